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
    /// Answer detection cases (JSON Lines, shared/spec/cases.md), one line per case.
    Detect(polyguard::cli::detect::DetectArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match &cli.command {
        Command::Detect(a) => polyguard::cli::detect::run(a),
    }
}
