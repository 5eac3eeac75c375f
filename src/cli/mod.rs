//! The command-line tool's subcommands, one module each.
pub mod assure;
#[cfg(feature = "earth")]
pub mod conflicts;
pub mod detect;
#[cfg(feature = "earth")]
pub mod generate;
