//! The moving-features model (docs/moving-features.md): timed fixes of a mover, and
//! areas that are static or keyframed, as the readers give them and the encounter
//! engine takes them. Positions are degrees `[longitude, latitude]`, times seconds since
//! 1970-01-01T00:00:00Z (UTC without leap seconds, as POSIX time), heights feet.

/// One timed position of a mover: between two fixes it flies the rhumb line joining them
/// at constant ground speed, its altitude linear in time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fix {
    /// Seconds since 1970-01-01T00:00:00Z.
    pub t: f64,
    /// Longitude, degrees in [-180, 180].
    pub lon: f64,
    /// Latitude, degrees in [-85, 85] (the Mercator plane's limit, as the scenario format).
    pub lat: f64,
    /// Altitude, feet (absent when the source has none).
    pub alt_ft: Option<f64>,
}

/// A mover: its identifier and its fixes, strictly increasing in time.
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory {
    /// The identifier (MF-JSON `id`, or the fixes' `icao24`).
    pub id: String,
    /// The callsign, when the source gives one.
    pub callsign: Option<String>,
    /// The fixes, strictly increasing in `t`.
    pub fixes: Vec<Fix>,
}

/// One polygon: an outer ring and its holes, each ring `[lon, lat]` degrees, not closed
/// (the repeated first position of GeoJSON is removed), in either winding; edges are
/// rhumb lines.
#[derive(Clone, Debug, PartialEq)]
pub struct Rings {
    /// The outer ring (≥ 3 vertices).
    pub outer: Vec<[f64; 2]>,
    /// The holes (each ≥ 3 vertices), inside the outer ring.
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// The area's polygons at one instant (a keyframe).
#[derive(Clone, Debug, PartialEq)]
pub struct Keyframe {
    /// Seconds since 1970-01-01T00:00:00Z.
    pub t: f64,
    /// The polygons (a MultiPolygon's parts; one for a Polygon).
    pub parts: Vec<Rings>,
}

/// How an area's shape depends on time.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// The same polygons at every time.
    Static(Vec<Rings>),
    /// Polygons at instants, strictly increasing, with the same structure at each (parts,
    /// holes and vertex counts); between two keyframes every vertex moves linearly on the
    /// Mercator plane. The area exists from the first keyframe to the last.
    Keyframed(Vec<Keyframe>),
}

/// An area: an airspace, a fence or a weather cell, with an optional vertical extent.
#[derive(Clone, Debug, PartialEq)]
pub struct Area {
    /// The identifier (`id` of the feature, or a name property the reader chose).
    pub id: String,
    /// A human name, when the source gives one.
    pub name: Option<String>,
    /// Its shape over time.
    pub shape: Shape,
    /// The floor, feet (absent: unbounded below).
    pub floor_ft: Option<f64>,
    /// The ceiling, feet (absent: unbounded above).
    pub ceiling_ft: Option<f64>,
}
