//! polyguard-harness: the one place where the three answers meet (the f64 engine, paper A
//! in exact arithmetic, the exact ground truth), and the case format's reader. The engine's
//! tests, benches and fuzz targets, the Python package and the command-line tool
//! (`polyguard assure`, `detect`, `detect-batch`) all call it. It prints nothing.
//!
//! The layers, each using only those above it:
//! - [`case`]: the case JSON Lines format (docs/cases.md): a line to a [`case::RawCase`],
//!   to the engine's `polyguard::api::Case`, to the oracle's exact case.
//! - [`gen`]: boundary-biased case generators over a seeded or byte-fed [`gen::Source`];
//!   [`workload`]: the uniform benchmark workload (no threshold sought); [`batch`]: the
//!   seeded batch workload (N points, M polygons) of `detect-batch`.
//! - [`answer`]: one case answered as the answer format says (docs/cases.md).
//! - [`classify`]: the verdict of one case (agree, float divergence, missed detection, …).
//! - [`report`]: counts per function, mode and class; shards merge exactly.
//! - [`minimise`]: a smaller case of the same class. [`svg`]: its picture.
//! - [`paper_b`]: paper B's hunt (scenario generator, judge, pictures).
//! - [`intervals`]: the hunt of certified intervals; [`moving`]: the hunt of moving
//!   features (flights against static and keyframed areas).
//! - [`wayout`]: the way out checked exactly ([`wayout::offset`]: one engine offset or
//!   inset against the oracle; [`wayout::recovery`]: recovery points and PolyCARP's;
//!   [`wayout::bands`]: values drawn in each band against the exact conflict of their
//!   velocities); [`canary_offset`]: a bisector expansion it must catch;
//!   [`wayout::case`] and [`wayout::answer`]: a case line read for `bands`, `recover`
//!   and `offset`, and answered as docs/way-out.md says; [`wayout::gen`],
//!   [`wayout::judge`]: the hunt of all three (`assure --paper wayout`).
//! - [`hunt`]: a report shape hunts share (classes per case and mode, costs, the worst
//!   case of each failing class); shards merge exactly.
#![deny(missing_docs)]

pub mod answer;
pub mod batch;
pub mod canary_offset;
pub mod case;
pub mod classify;
pub mod gen;
pub mod hunt;
pub mod intervals;
pub mod minimise;
pub mod moving;
pub mod paper_b;
pub mod report;
pub mod svg;
pub mod wayout;
pub mod workload;
