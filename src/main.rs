//! The `polyguard` command-line tool.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

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
    Detect(polyguard::cli::detect::DetectArgs),
    /// A seeded safety-assurance run: engine vs paper-exact vs truth on boundary cases.
    Assure(polyguard::cli::assure::AssureArgs),
    /// Which areas and tracks of a scenario GeoJSON conflict, and when (paper B).
    #[cfg(feature = "earth")]
    Conflicts(polyguard::cli::conflicts::ConflictsArgs),
    /// A random scenario as in paper B, Section VI.D.
    #[cfg(feature = "earth")]
    Generate(polyguard::cli::generate::GenerateArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match &cli.command {
        Command::Detect(a) => polyguard::cli::detect::run(a),
        Command::Assure(a) => polyguard::cli::assure::run(a),
        #[cfg(feature = "earth")]
        Command::Conflicts(a) => polyguard::cli::conflicts::run(a),
        #[cfg(feature = "earth")]
        Command::Generate(a) => polyguard::cli::generate::run(a),
    }
}
