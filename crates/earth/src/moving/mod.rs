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
//! - [`fixes_table`]: the same fixes held in columns (a data frame's arrays).
//! - [`planar`]: the planar model's data (fixes, keyframed areas, relations, spans).
//! - [`plane`]: the planar model's certified spans over one segment.
//! - [`timeline`]: three-valued timelines, the algebra that composes the spans.
//! - [`prepared`]: an area made ready for many pieces (edge trees, exact winding).
//! - [`encounter`]: whole flights against areas on the Earth, the answer of
//!   `polyguard encounters`.
//! - [`broad`]: many movers against many areas: the broad phase.
//! - [`answer`]: the answer as JSON, one object per pair that meets.

pub mod answer;
pub mod broad;
pub mod encounter;
pub mod error;
pub mod fixes_csv;
pub mod fixes_table;
pub mod geojson;
pub mod mfjson;
pub mod model;
mod piece;
pub mod planar;
pub mod plane;
pub mod prepared;
pub mod time;
pub mod timeline;

/// The next f64 above `x` (`f64::next_up`, which the minimum Rust version lacks); NaN
/// and +∞ stay.
pub(crate) fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    f64::from_bits(if x > 0.0 { b + 1 } else { b - 1 })
}

/// The next f64 below `x`.
pub(crate) fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

#[cfg(test)]
mod tests {
    use super::{next_down, next_up};

    #[test]
    fn next_up_and_down_step_one_ulp_either_side() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1.5e300,
            -2.5e-310,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            let (u, d) = (next_up(x), next_down(x));
            assert!(u > x && d < x, "{x}");
            assert!(next_down(u) == x && next_up(d) == x, "{x}");
        }
        assert_eq!(next_up(f64::MAX), f64::INFINITY);
    }
}
