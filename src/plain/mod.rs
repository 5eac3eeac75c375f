//! The plain transcription of paper A in f64, as it reads without error analysis
//! (the engine before certification): every comparison is taken on the rounded value, with no error bound.
//!
//! Kept **for comparison only** (feature `plain`, `polyguard detect --engine plain`):
//! it misses true entries on relative paths long compared with the polygon, which is
//! what the hunting tools use it for, as a canary that a hunt must be able to catch.
//! Never use it to decide anything.
//!
//! Module for module it is the engine's layout: [`quad`] (§I), [`contain`] (§II.B–E),
//! [`proximity`] (§II.G), [`detect`] (§II.H, §II.I, §III), [`predicates`].
#![allow(missing_docs)]

pub mod contain;
pub mod detect;
pub mod predicates;
pub mod proximity;
pub mod quad;

pub use detect::{detect_3d, detect_diff_2d, detect_same_2d, statically_shaped};
