//! The way out: the exact checks of the engine's offsets (paper A §II's polygon grown
//! and shrunk), recovery points and bands against the oracle, beside the baselines they
//! are measured against; and the hunt that draws cases for them ([`gen`], [`judge`]:
//! `polyguard assure --paper wayout`).

pub mod answer;
pub mod bands;
pub mod case;
pub mod gen;
pub mod judge;
pub mod offset;
pub mod picture;
pub mod polycarp;
pub mod recovery;
