//! The exact references of paper B, next to the f64 code they check: the f64 stages and
//! projection must agree with them within stated bounds (tests/paper_b_*.rs).
//!
//! - [`rational`]: Section IV (convex hull, convex intersection, projection, linear time
//!   window) in exact rational arithmetic.
//! - `mpfr` (feature `rug`): Section V (Mercator, rhumb motion, `track_time`) in 256-bit
//!   MPFR, to measure the f64 code in ulps.
//! - [`truth`]: whether and when two features really meet (`assure --paper b`).
//! - [`approach`]: how close an aircraft really comes to a drifting cell (the ground truth
//!   of [`crate::aircraft_cell`]).

pub mod approach;
#[cfg(feature = "rug")]
pub mod mpfr;
pub mod rational;
pub mod truth;
