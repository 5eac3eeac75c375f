//! The way out: the exact checks of the engine's offsets (paper A §II's polygon grown
//! and shrunk), recovery points and bands against the oracle, beside the baselines they
//! are measured against.

pub mod answer;
pub mod bands;
pub mod case;
pub mod offset;
pub mod picture;
pub mod polycarp;
pub mod recovery;
