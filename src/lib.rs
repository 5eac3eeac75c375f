//! polyguard: does a moving point enter a moving (possibly warping) polygon?
//!
//! The f64 engine of paper A (Narkawicz & Hagen): [`quad`] (§I), [`contain`] (§II.B–E),
//! [`proximity`] (§II.G), [`detect`] (§II.H, §II.I, §III), [`well_formed`](mod@well_formed)
//! (§II.J), every sign decision certified (a three-valued [`Tri`]). When, on paper A's
//! motion (§II–§III): [`intervals`] (every time the point is inside, within D, or out of
//! a keep-in fence, as certified spans) and [`fence`] (keep-in exits). The way out:
//! `offset` (certified offsets and insets of a polygon, with `std`). The high-level
//! entry points are `api::detect`, `api::detect_time`, `api::intervals`,
//! `api::detect_exit` and `batch::detect_batch`.
//!
//! ```
//! # #[cfg(feature = "std")] {
//! use polyguard::api::{detect, Case, MovingPoint, MovingPolygon, Params};
//! use polyguard::Vect2;
//!
//! // A 2 × 2 weather cell drifting east at 1 unit per time unit, counterclockwise.
//! let square = vec![Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
//! let cell = MovingPolygon::new(square, Some(vec![Vect2::new(1.0, 0.0); 4]))?;
//! // An aircraft south of it, flying north.
//! let aircraft = MovingPoint::new_2d(Vect2::new(5.0, -3.0), Vect2::new(0.0, 1.0))?;
//! // Lookahead T = 10, BUFF = 0.01 (F and κ at their defaults).
//! let case = Case::new(10.0, aircraft, cell, Params::new(0.01)?)?;
//! let answer = detect(&case);
//! assert!(answer.detected && answer.well_formed);
//! assert_eq!(answer.method.name(), "detect_same_2d");
//! # }
//! # Ok::<(), polyguard::error::CaseError>(())
//! ```
//!
//! # Features
//! - `std` (default): the `api` module (validated cases, owned `Vec`s), the error
//!   trait impls and the exact ring checks of `ring`. Without it the crate is `no_std`:
//!   the paper functions take slices (or any [`polygon::VertexSeq`]) and allocate nothing.
//! - `plain`: the uncertified f64 transcription of the paper (module `plain`), for
//!   comparison.
//! - `nalgebra`: conversions between [`Vect2`] and nalgebra's `Point2`/`Vector2`.
//! - `internals`: not part of the API. It makes the certification arithmetic (module
//!   `ball`: balls, error bounds) reachable for the crate's own tests, which check it
//!   against the exact oracle. The items hidden from this documentation (`ball`, the
//!   `*_rel` forms, `AtTime`, `Shifted`, `RelPoly`, `edge_detect_simp_tri`,
//!   `slab_window_balls`) carry no semver promise and may change in any release.
//! - `parallel`: `batch::detect_batch` (N points against M polygons) across cores with
//!   rayon; without it the same API runs on the calling thread.
//!
//! A plain dependency pulls `libm` and nothing else. Paper B, the command-line tool and
//! the exact oracle are other crates (`polyguard-earth`, `polyguard-cli`,
//! `polyguard-oracle`).
//!
//! # Conventions
//! - **Counterclockwise.** Vertices run counterclockwise (positive signed area); the API
//!   refuses clockwise, self-intersecting and collinear rings with a `CaseError`.
//! - **Units.** Any consistent units: positions in one length unit, velocities in that
//!   unit per time unit, the lookahead T in time units, BUFF in the length unit. F is a
//!   fraction of an edge's length (0 < F < 1: §II.I grows each edge of a warping polygon
//!   by F times its length), κ an angle in radians (the case format takes degrees).
//! - **BUFF and F.** The paper detects entry into the polygon grown by BUFF; for a
//!   warping polygon, §II.I's edge test also reaches F times each edge's length beyond
//!   it (along and across the edge). A "yes" for a point that passes within that band
//!   without entering is by design, not a false alarm.
//! - **Names.** Functions and parameters carry the paper's names (`t`, `s`, `v`, `p`,
//!   `vels`, `buff`, `f`), and the oracle uses the same ones.
//!
//! # The contract
//! For every case with finite f64 inputs, and at every public entry point (`api::detect`,
//! [`detect_same_2d`], [`detect_diff_2d`], [`detect_3d`] and the paper functions below
//! them): **if paper A computed without rounding answers yes, the engine answers yes.**
//! The exact oracle (`polyguard-oracle`) executes the PVS theorem that a point which
//! really enters is detected by paper A, so the engine never misses a true entry.
//!
//! Every comparison is certified ([`Tri`]): `No` and `Yes` hold for the exact
//! inputs. A comparison that f64 cannot decide is resolved towards detection, so an
//! engine "yes" where paper A says no happens only on an undecided comparison, within
//! rounding of one of paper A's thresholds; `api::Detection::kind` says when that was
//! the case (`Kind::Conservative`), and the `*_tri` forms return `Tri::Unsure`.
//!
//! Paper A takes BUFF > 0 (and a case must have it). The slice functions take any float:
//! a BUFF below 0 (or NaN) is outside the paper's domain, and the functions that take
//! one answer it undecided (`Tri::Unsure`: "yes", "near", "not definitely outside"),
//! so the contract holds there too, without a certain answer.
#![cfg_attr(not(feature = "std"), no_std)]
#![deny(missing_docs)]

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "std"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// docs/batch.md's library example, compiled and run as a doctest.
#[cfg(all(doctest, feature = "std"))]
#[doc = include_str!("../docs/batch.md")]
pub struct BatchDocDoctests;

#[cfg(feature = "std")]
pub mod api;
#[cfg(feature = "internals")]
#[doc(hidden)]
pub mod ball;
#[cfg(not(feature = "internals"))]
mod ball;
#[cfg(feature = "std")]
pub mod bands;
#[cfg(feature = "std")]
pub mod batch;
pub mod contain;
pub mod detect;
#[cfg(feature = "std")]
pub mod entry;
pub mod error;
pub mod fence;
pub mod intervals;
mod lanes;
mod motion;
#[cfg(feature = "std")]
pub mod offset;
#[cfg(feature = "plain")]
pub mod plain;
pub mod polygon;
mod predicates;
pub mod proximity;
pub mod quad;
#[cfg(feature = "std")]
pub mod recovery;
#[cfg(feature = "std")]
pub mod ring;
#[cfg(feature = "std")]
mod sweep;
pub mod vect2;
pub mod well_formed;

pub use ball::Tri;
pub use contain::{definitely_outside, near_edge, num_cross, perturb};
pub use detect::{
    detect_3d, detect_3d_tri, detect_diff_2d, detect_diff_2d_tri, detect_same_2d,
    detect_same_2d_tri, dispatch, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp, Interval,
    Method, Sign,
};
pub use intervals::{End, Relation, Separation, Span};
pub use proximity::segments_close;
pub use quad::{quad_min_box_le_d, quad_min_le_d};
pub use vect2::Vect2;
pub use well_formed::well_formed;
