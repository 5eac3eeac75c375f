//! The command-line tool's subcommands, one module each.
pub mod assure;
pub mod assure_b;
pub mod assure_common;
pub mod assure_intervals;
pub mod assure_moving;
pub mod bands;
pub mod conflicts;
pub mod detect;
pub mod detect_batch;
pub mod detect_earth;
pub mod encounters;
pub mod encounters_svg;
pub mod generate;
pub mod offset;
pub mod recover;
pub mod wayout_common;
pub mod wayout_svg;
