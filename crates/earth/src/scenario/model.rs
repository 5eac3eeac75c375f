//! The scenario's model: areas and tracks (paper B Section III) with their times, in
//! radians of longitude and latitude, and how the file's longitudes are read.

use crate::sphere::{LonLat, RectDims};
use serde_json::{Map, Value};

/// Spec limit on |latitude| (degrees): the Mercator plane stretches without bound
/// towards the poles; 85° is the spec's validity limit.
pub const MAX_ABS_LAT_DEG: f64 = 85.0;

/// Largest |latitude| (degrees) a track's rectangle may reach: Table 2's steps from a
/// reference point at the spec's 85° limit stay clear of the pole for rectangles of up to
/// 240 nm (4°) of front/back + side.
pub const MAX_RECT_LAT_DEG: f64 = 89.0;

/// One polygon of an area: its boundary and its holes, each an open ring (the closing
/// repeat removed) whose edges are rhumb lines (straight on the Mercator plane).
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    /// The exterior ring, counterclockwise (RFC 7946 §3.1.6).
    pub ring: Vec<LonLat>,
    /// The holes (interior rings), clockwise: places inside `ring` that are not part of
    /// the area (their boundaries are). Each lies inside `ring`, outside the others, and
    /// no two rings of the shape share a point.
    pub holes: Vec<Vec<LonLat>>,
}

impl Shape {
    /// A shape without holes.
    pub fn plain(ring: Vec<LonLat>) -> Shape {
        Shape {
            ring,
            holes: Vec::new(),
        }
    }
}

/// A static area (spec kind `area`): a GeoJSON Polygon (one shape) or MultiPolygon (one
/// or more shapes, which may touch or overlap: the area is their union).
#[derive(Clone, Debug, PartialEq)]
pub struct Area {
    /// The shapes.
    pub shapes: Vec<Shape>,
    /// Written as a MultiPolygon (kept when the scenario is written back).
    pub multi: bool,
    /// Start (h), `None` = always.
    pub t0: Option<f64>,
    /// End (h), `None` = always.
    pub tf: Option<f64>,
}

/// A moving rectangle along rhumb lines (spec kind `track`).
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// Waypoints (two or more).
    pub waypoints: Vec<LonLat>,
    /// Speed (kn), > 0.
    pub speed_kn: f64,
    /// Table 2 distances (nm).
    pub dims: RectDims,
    /// Departure time (h).
    pub t0: f64,
}

/// The two kinds of feature.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// `area`.
    Area(Area),
    /// `track`.
    Track(Track),
}

/// One feature of the scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Feature {
    /// `properties.id`, unique.
    pub id: String,
    /// What it is.
    pub kind: Kind,
    /// Members of `properties` that the format does not define, kept as read (GeoJSON's
    /// properties are open) and written back by [`to_geojson`](crate::scenario::to_geojson).
    pub extra: Map<String, Value>,
}

/// How a scenario's longitudes are read: the collection member `longitudes`
/// (docs/scenario.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Longitudes {
    /// `"earth"`, the default: the real Earth. A longitude is taken modulo 360° (190 is
    /// the place −170 names), consecutive positions are joined the shorter way round (a
    /// step from 179.5 to −179.5 crosses the antimeridian, 1° long), and objects meet
    /// across ±180°.
    #[default]
    Earth,
    /// `"unrolled"`: the unrolled Mercator strip that `generate --density-box` writes for
    /// more objects than the Earth holds at the paper's density. Longitudes are not
    /// wrapped (190 is 10° east of 180 and not the place −170 names), so the strip is as
    /// long as the file needs; a step longer than 180° is an error there.
    Unrolled,
}

impl Longitudes {
    /// The member's value as written.
    pub fn name(self) -> &'static str {
        match self {
            Longitudes::Earth => "earth",
            Longitudes::Unrolled => "unrolled",
        }
    }
}

/// A whole scenario (valid features only, in file order).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scenario {
    /// The features.
    pub features: Vec<Feature>,
    /// How its longitudes were read (and are to be understood).
    pub longitudes: Longitudes,
    /// The model of the Earth its rhumb lines, Mercator plane and distances are taken on
    /// (not read from the file: `polyguard conflicts --geodesy`; the sphere by default).
    pub geodesy: crate::geodesy::Geodesy,
}

/// A longitude (degrees) taken modulo 360° into (−180, 180], exactly: `%` is exact, and
/// the one subtraction or addition of 360 that may follow is exact by Sterbenz's lemma
/// (the remainder's magnitude is then within [180, 360)).
pub fn normal_lon(lon: f64) -> f64 {
    let r = lon % 360.0;
    if r > 180.0 {
        r - 360.0
    } else if r <= -180.0 {
        r + 360.0
    } else {
        r
    }
}
