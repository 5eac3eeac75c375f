//! The way out's checks: the engine's answers of offsets, recovery points and bands
//! held against the oracle's exact checks.

pub mod bands;
