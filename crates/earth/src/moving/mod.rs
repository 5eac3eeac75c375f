//! Moving features: whole flights (timed fixes) against static or keyframed areas, with
//! certified intervals of inside and of loss of separation (docs/moving-features.md).
//!
//! - [`model`]: the fixes, trajectories and areas the readers give and the engine takes.
//! - [`plane`]: the planar model and its certified spans over one segment.
//! - [`timeline`]: three-valued timelines, the algebra that composes the spans.
//! - [`prepared`]: an area made ready for many pieces (edge trees, exact winding).

pub mod model;
mod piece;
pub mod plane;
pub mod prepared;
pub mod timeline;
