//! polyguard: does a moving point enter a moving (possibly warping) polygon?
//!
//! The f64 engine of paper A (Narkawicz & Hagen): [`quad`] (§I), [`contain`] (§II.B–E),
//! [`proximity`] (§II.G), [`detect`] (§II.H, §II.I, §III), [`well_formed`](mod@well_formed) (§II.J), every
//! sign decision in [`predicates`], certified by the arithmetic of [`ball`]. The
//! high-level entry point is `api::detect`.
//!
//! # The contract
//! For every case with finite f64 inputs, and at every public entry point (`api::detect`,
//! [`detect_same_2d`], [`detect_diff_2d`], [`detect_3d`] and the paper functions below
//! them): **if paper A computed without rounding answers yes, the engine answers yes.**
//! The exact oracle (`polyguard-oracle`) executes the PVS theorem that a point which
//! really enters is detected by paper A, so the engine never misses a true entry.
//!
//! Every comparison is certified ([`ball::Tri`]): `No` and `Yes` hold for the exact
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

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "std"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

#[cfg(feature = "std")]
pub mod api;
pub mod ball;
pub mod contain;
pub mod detect;
pub mod error;
#[cfg(feature = "plain")]
pub mod plain;
pub mod polygon;
pub mod predicates;
pub mod proximity;
pub mod quad;
#[cfg(feature = "std")]
pub mod ring;
pub mod vect2;
pub mod well_formed;

pub use ball::Tri;
pub use contain::{definitely_outside, near_edge, num_cross, perturb};
pub use detect::{
    detect_3d, detect_3d_tri, detect_diff_2d, detect_diff_2d_tri, detect_same_2d,
    detect_same_2d_tri, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp, Interval, Sign,
};
pub use proximity::segments_close;
pub use quad::{quad_min_box_le_d, quad_min_le_d};
pub use vect2::Vect2;
pub use well_formed::well_formed;
