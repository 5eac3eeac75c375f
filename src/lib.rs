//! polyguard: does a moving point enter a moving (possibly warping) polygon?
//!
//! The f64 engine of paper A (Narkawicz & Hagen): [`quad`] (§I), [`contain`] (§II.B–E),
//! [`proximity`] (§II.G), [`detect`] (§II.H, §II.I, §III), [`well_formed`] (§II.J), every
//! sign decision in [`predicates`]. The high-level entry point is `api::detect`.
#![cfg_attr(not(feature = "std"), no_std)]

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "std"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

#[cfg(feature = "earth")]
pub mod conflict;
#[cfg(feature = "earth")]
pub mod earth;
#[cfg(feature = "earth")]
pub mod scenario;

#[cfg(feature = "cli")]
pub mod case;
#[cfg(feature = "cli")]
pub mod cli;
#[cfg(feature = "cli")]
pub mod harness;

#[cfg(feature = "std")]
pub mod api;
pub mod contain;
pub mod detect;
pub mod error;
pub mod polygon;
pub mod predicates;
pub mod proximity;
pub mod quad;
pub mod vect2;
pub mod well_formed;

pub use contain::{definitely_outside, near_edge, num_cross, perturb};
pub use detect::{
    detect_3d, detect_diff_2d, detect_same_2d, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp,
    Interval, Sign,
};
pub use proximity::segments_close;
pub use quad::{quad_min_box_le_d, quad_min_le_d};
pub use vect2::Vect2;
pub use well_formed::well_formed;
