//! The way out: harness code for the engine's offsets, recovery points and bands, beside
//! the baselines they are measured against.

pub mod polycarp;
pub mod recovery;
