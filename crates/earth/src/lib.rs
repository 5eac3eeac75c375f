//! polyguard-earth: paper B (A. Bienkowski, D. Sidoti and K. R. Pattipati, *Interference
//! Identification for Time-Varying Polyhedra*, IEEE Access 9, 2021) on the Earth.
//!
//! - [`rhumb`]: Section V on the sphere: points, the Mercator plane and rhumb lines.
//! - [`geodesy`]: Section V on the model of the Earth chosen, the sphere or the WGS84
//!   ellipsoid.
//! - [`sphere`]: Section V, Table 2's rectangles moving along rhumb lines (and
//!   [`rhumb`]'s functions, re-exported).
//! - [`conflict`]: Section IV, the four stages of interference identification
//!   ([`conflict::pipeline`] runs them, Algorithm 1).
//! - [`scenario`]: the scenario GeoJSON (`docs/scenario.md`), read strictly with
//!   positions ([`json`]) and written back.
//! - [`moving`]: whole flights (timed fixes) against static or keyframed areas: the
//!   moving-features formats (MF-JSON, GeoJSON areas, CSV fixes) and certified intervals.
//! - [`analysis`]: Algorithm 1 on scenario text, the conflicts answer and its drawing.
//! - [`generate`]: random scenarios as in Section VI.D.
//! - [`aircraft_cell`]: paper A's detection (Narkawicz & Hagen §II.H) of an aircraft on a
//!   rhumb line against a drifting weather cell, on lon/lat input through Section V's
//!   Mercator, with a buffer grown so that its "no" holds on the Earth ([`paper_a`] is the
//!   same module under the paper's name).
//! - [`reference`](mod@reference): the exact references the tests hold the f64 code to: Section IV in
//!   rationals, and (feature `rug`) Section V in 256-bit MPFR.
//!
//! Nothing here prints: progress is reported through [`analysis::Progress`], which the
//! command-line tool draws.
#![deny(missing_docs)]

pub mod aircraft_cell;
pub mod analysis;
pub mod bands;
pub mod conflict;
pub mod generate;
pub mod geodesy;
pub mod json;
pub mod moving;
pub mod picture;
pub mod reference;
pub mod rhumb;
pub mod scenario;
pub mod sphere;

/// [`aircraft_cell`] under the name of its paper (Narkawicz & Hagen's paper A on the
/// Earth), the path `polyguard_earth::paper_a::detect_earth` that callers use.
pub use aircraft_cell as paper_a;
