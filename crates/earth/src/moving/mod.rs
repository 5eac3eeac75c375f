//! Moving features: whole flights (timed fixes) against static or keyframed areas, with
//! certified intervals of inside and of loss of separation (docs/moving-features.md).
//!
//! - [`model`]: the fixes, trajectories and areas the readers give and the engine takes.
//! - [`plane`]: the planar model and its certified spans over one segment.

pub mod model;
pub mod plane;
