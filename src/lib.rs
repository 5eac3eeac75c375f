#![cfg_attr(not(feature = "std"), no_std)]

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
