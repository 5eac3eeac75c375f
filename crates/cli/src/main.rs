//! The `polyguard` command-line tool.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// mimalloc serves the many small allocations of reading large inputs faster than the
/// system allocator (measured in docs/performance.md).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[derive(Parser)]
#[command(
    name = "polyguard",
    version,
    about = "Does a moving point enter a moving polygon? (paper A) Which moving areas conflict, and when? (paper B)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Answer detection cases (JSON Lines, docs/cases.md), one line per case.
    Detect(polyguard_cli::commands::detect::DetectArgs),
    /// Every point of one JSON Lines file against every polygon of another (docs/batch.md).
    DetectBatch(polyguard_cli::commands::detect_batch::DetectBatchArgs),
    /// Paper A on the Earth: does an aircraft come within BUFF nm of a drifting cell?
    /// (JSON Lines in degrees, nm, knots, hours: docs/earth-cases.md)
    DetectEarth(polyguard_cli::commands::detect_earth::DetectEarthArgs),
    /// A seeded safety-assurance run: engine vs paper-exact vs truth on boundary cases.
    Assure(polyguard_cli::commands::assure::AssureArgs),
    /// Which areas and tracks of a scenario GeoJSON conflict, and when (paper B).
    Conflicts(polyguard_cli::commands::conflicts::ConflictsArgs),
    /// Whole flights (timed fixes, CSV or MF-JSON) against areas (GeoJSON, MF-JSON
    /// moving polygons): certified intervals inside and within separation, one JSON line
    /// per pair met (docs/moving-features.md).
    Encounters(polyguard_cli::commands::encounters::EncountersArgs),
    /// A random scenario as in paper B, Section VI.D.
    Generate(polyguard_cli::commands::generate::GenerateArgs),
    /// Conflict-free course (and speed) bands for the point of each case among its
    /// moving polygons: clear, conflict or unknown, certified (docs/way-out.md).
    Bands(polyguard_cli::commands::bands::BandsArgs),
    /// The nearest point out of each case's polygon grown by D (or, keep-in, into it
    /// shrunk by D), certified (docs/way-out.md).
    Recover(polyguard_cli::commands::recover::RecoverArgs),
    /// Each case's polygon grown (or, --inset, shrunk) by D, certified within D·(1 + ε)
    /// (docs/way-out.md).
    Offset(polyguard_cli::commands::offset::OffsetArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match &cli.command {
        Command::Detect(a) => polyguard_cli::commands::detect::run(a),
        Command::DetectBatch(a) => polyguard_cli::commands::detect_batch::run(a),
        Command::DetectEarth(a) => polyguard_cli::commands::detect_earth::run(a),
        Command::Assure(a) => polyguard_cli::commands::assure::run(a),
        Command::Conflicts(a) => polyguard_cli::commands::conflicts::run(a),
        Command::Encounters(a) => polyguard_cli::commands::encounters::run(a),
        Command::Generate(a) => polyguard_cli::commands::generate::run(a),
        Command::Bands(a) => polyguard_cli::commands::bands::run(a),
        Command::Recover(a) => polyguard_cli::commands::recover::run(a),
        Command::Offset(a) => polyguard_cli::commands::offset::run(a),
    }
}
