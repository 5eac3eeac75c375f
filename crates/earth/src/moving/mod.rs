//! Moving features: whole flights (timed fixes) against static or keyframed areas, with
//! certified intervals of inside and of loss of separation (docs/moving-features.md).
//!
//! - [`broad`]: many movers against many areas: the broad phase.
//! - [`encounter`]: whole flights against areas on the Earth, the answer of `polyguard encounters`.
//! - [`model`]: the fixes, trajectories and areas the readers give and the engine takes.
//! - [`plane`]: the planar model and its certified spans over one segment.
//! - [`timeline`]: three-valued timelines, the algebra that composes the spans.
//! - [`prepared`]: an area made ready for many pieces (edge trees, exact winding).

pub mod broad;
pub mod encounter;
pub mod model;
mod piece;
pub mod plane;
pub mod prepared;
pub mod timeline;
