//! The harness: the one place where the three answers meet (the f64 engine, paper A in
//! exact arithmetic, the exact ground truth). Tests, fuzz targets and `polyguard assure`
//! all call it.
//!
//! Cases are [`crate::case::RawCase`]s, the case format's fields.
//!
//! - [`gen`]: boundary-biased case generators over a seeded or byte-fed [`gen::Source`].
//! - [`classify`]: the verdict of one case (agree, float divergence, missed detection, …).
//! - [`report`]: counts per function, mode and class; shards merge exactly.
//! - [`minimise`]: a smaller case of the same class. [`svg`]: its picture.
//! - [`workload`]: the uniform benchmark workload (no threshold sought).
//! - [`batch`]: the seeded batch workload (N points, M polygons) of `detect-batch`.

pub mod batch;
pub mod classify;
pub mod gen;
pub mod minimise;
pub mod paper_b;
pub mod report;
pub mod svg;
pub mod workload;
