//! Moving features: whole flights (timed fixes) against static or keyframed areas, with
//! certified intervals of inside and of loss of separation (docs/moving-features.md).
//!
//! - [`model`]: the fixes, trajectories and areas the readers give and the engine takes.
//! - [`time`]: RFC 3339 date-times to epoch seconds and back (rounded in a direction).
//! - [`error`]: the readers' errors and warnings, each naming line, feature and member.
//! - [`mfjson`]: OGC Moving Features JSON (trajectories, MovingPoint, MovingPolygon) and
//!   GeoJSON areas, as a FeatureCollection, one Feature or JSON Lines.
//! - [`geojson`]: GeoJSON positions, rings and polygons, checked, with their locations.
//! - [`fixes_csv`]: a CSV of fixes (traffic and OpenSky columns), grouped into
//!   trajectories.
//! - [`plane`]: the planar model and its certified spans over one segment.
//! - [`timeline`]: three-valued timelines, the algebra that composes the spans.
//! - [`prepared`]: an area made ready for many pieces (edge trees, exact winding).
//! - [`encounter`]: whole flights against areas on the Earth, the answer of
//!   `polyguard encounters`.
//! - [`broad`]: many movers against many areas: the broad phase.

pub mod broad;
pub mod encounter;
pub mod error;
pub mod fixes_csv;
pub mod geojson;
pub mod mfjson;
pub mod model;
mod piece;
pub mod plane;
pub mod prepared;
pub mod time;
pub mod timeline;
