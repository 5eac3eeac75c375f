//! What the reader reports: a typed error per rejected feature (or the file), and the
//! warnings, each naming the line, the feature and the field.

use crate::scenario::model::{MAX_ABS_LAT_DEG, MAX_RECT_LAT_DEG};
use std::fmt;

/// What is wrong with a feature's field.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// The file is not JSON.
    Json(String),
    /// The field is missing.
    Missing,
    /// The field has the wrong JSON type or GeoJSON geometry type.
    WrongType(&'static str),
    /// A number is NaN/infinite or a position is not `[lon, lat]`.
    BadNumber,
    /// `NaN`, `Infinity` or `-Infinity` written where a number belongs (not JSON).
    NotJsonNumber(&'static str),
    /// The polygon ring's last position differs from its first.
    UnclosedRing,
    /// Fewer than 3 distinct ring vertices (or 2 track waypoints).
    TooFewVertices(usize),
    /// |latitude| beyond [`MAX_ABS_LAT_DEG`].
    LatitudeOutOfRange(f64),
    /// A speed below zero.
    NegativeSpeed(f64),
    /// A speed of zero (the track would never end).
    ZeroSpeed,
    /// A distance below zero.
    NegativeDistance(f64),
    /// `properties.kind` is neither `area` nor `track`.
    UnknownKind(String),
    /// `properties.id` already used by an earlier feature.
    DuplicateId,
    /// `tf` before `t0`.
    EndBeforeStart,
    /// The rectangle's steps would carry a vertex past ±89° of latitude (the Mercator
    /// plane ends at the poles).
    RectangleTooLarge(f64),
    /// A member one or two letters from a defined one (a misspelling must not change the
    /// meaning silently), with that name: a `properties` member, or a member of the
    /// collection, a feature or a geometry that lacks the defined one.
    UnknownMember(Option<&'static str>),
    /// A member not allowed on this object (RFC 7946 §7.1, or a name the format defines
    /// on another object, where it would be ignored): where it belongs.
    Misplaced(&'static str),
    /// A defined property on the other kind of feature (`tf` on a track, `speed_kn` on an
    /// area): it would be ignored. Names the kind ("an area", "a track").
    NotForKind(&'static str),
    /// A key given twice in one object.
    DuplicateKey,
    /// The area's ring crosses itself: its edges from vertex a0 to a1 and b0 to b1 (indices
    /// into the ring as written, from 0) meet, on the Mercator plane where its edges are
    /// straight.
    SelfIntersecting((usize, usize), (usize, usize)),
    /// The area's vertices lie on one rhumb line (or one point): it encloses nothing.
    ZeroArea,
    /// `crs` names a system other than WGS 84 longitude/latitude.
    UnsupportedCrs(String),
    /// In a file of the unrolled plane ([`Longitudes::Unrolled`](crate::scenario::Longitudes::Unrolled)), positions k−1 and k
    /// differ by more than 180° of longitude (on the real Earth such a step is read the
    /// shorter way, across the antimeridian).
    CrossesAntimeridian(usize),
    /// Positions k−1 and k are exactly 180° of longitude apart: the rhumb line between
    /// them could run east or west.
    HalfTurnStep(usize),
    /// The ring, its positions joined the shorter way round, comes back to its first
    /// position a whole turn east or west: it circles a pole, and no ring on the
    /// Mercator plane bounds it.
    CirclesPole,
    /// The ring's longitudes span a whole turn or more (the span, degrees): it would
    /// overlap itself around the Earth.
    SpansWholeTurn(f64),
    /// The collection's `longitudes` member has a value other than `"earth"` or
    /// `"unrolled"`.
    UnknownLongitudes(String),
    /// Two rings of one polygon share a point: this ring's edge a0→a1 meets edge b0→b1
    /// of ring `ring` (0 the exterior, k ≥ 1 the k-th hole); indices into the rings as
    /// written, from 0.
    RingsMeet {
        /// The other ring (its index in the polygon's coordinates).
        ring: u32,
        /// This ring's edge.
        a: (u32, u32),
        /// The other ring's edge.
        b: (u32, u32),
    },
    /// A hole that does not lie inside its polygon's exterior ring.
    HoleOutside,
    /// A hole inside another hole (`k`, its index in the polygon's coordinates), or
    /// containing it.
    HoleInHole(usize),
}

/// A typed input error naming the line, the feature (index and id) and the field.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioError {
    /// The 1-based line of the file where the problem is (`None` only for a scenario
    /// built in memory).
    pub line: Option<usize>,
    /// Index of the feature in the file (`None` for file-level errors).
    pub index: Option<usize>,
    /// `properties.id` when known.
    pub id: Option<String>,
    /// JSON path of the field, e.g. `properties.speed_kn`.
    pub field: String,
    /// The problem.
    pub problem: Problem,
}

/// Something read that the reader wants the user to know: a member kept but not read (a
/// `properties` member the format does not define), a foreign member (RFC 7946 §6.1) of
/// the collection, a feature or a geometry, not read, or a longitude beyond ±180° read
/// modulo 360°.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioWarning {
    /// The 1-based line of the member or position.
    pub line: usize,
    /// Index of the feature in the file (`None` for a member of the FeatureCollection).
    pub index: Option<usize>,
    /// `properties.id` when known.
    pub id: Option<String>,
    /// JSON path of the member or position, e.g. `properties.colour`.
    pub field: String,
    /// What the warning is about.
    pub what: Warning,
}

/// The kinds of [`ScenarioWarning`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warning {
    /// A member of `properties` the format does not define, kept and written back, not
    /// read.
    Kept,
    /// A foreign member (RFC 7946 §6.1): a member of the collection, a feature or a
    /// geometry that neither RFC 7946 nor the format defines; not read, not kept.
    Foreign,
    /// A longitude beyond ±180° (as written) read on the real Earth as the place it
    /// names (the value in (−180, 180]); the first such position of the feature.
    Wrapped(f64, f64),
}

impl fmt::Display for ScenarioWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.index {
            Some(i) => write!(f, "line {}: feature {i}", self.line)?,
            None => write!(f, "line {}: the FeatureCollection", self.line)?,
        }
        if let Some(id) = &self.id {
            write!(f, " (id {id:?})")?;
        }
        match self.what {
            Warning::Kept => write!(
                f,
                ", {}: not defined by the scenario format; kept, not read",
                self.field
            ),
            Warning::Foreign => write!(
                f,
                ", {}: a foreign member (defined by neither RFC 7946 nor the scenario \
                 format); not read",
                self.field
            ),
            Warning::Wrapped(lon, read) => write!(
                f,
                ", {}: longitude {lon} is beyond ±180°; read as {read}, the same place on \
                 the Earth (a file of the unrolled plane says \"longitudes\": \"unrolled\")",
                self.field
            ),
        }
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(l) = self.line {
            write!(f, "line {l}: ")?;
        }
        match (&self.index, &self.id) {
            (Some(i), Some(id)) => write!(f, "feature {i} (id {id:?}), ")?,
            (Some(i), None) => write!(f, "feature {i}, ")?,
            _ => {}
        }
        write!(f, "{}: ", self.field)?;
        match &self.problem {
            Problem::Json(e) => write!(f, "not valid JSON: {e}"),
            Problem::Missing => write!(f, "missing"),
            Problem::WrongType(t) => write!(f, "expected {t}"),
            Problem::BadNumber => write!(f, "not a finite number / position"),
            Problem::NotJsonNumber(l) => {
                write!(f, "{l} is not a JSON number; finite numbers are needed")
            }
            Problem::UnclosedRing => write!(f, "ring not closed (last position ≠ first)"),
            Problem::TooFewVertices(n) => write!(f, "only {n} vertices"),
            Problem::LatitudeOutOfRange(l) => {
                write!(f, "latitude {l} beyond ±{MAX_ABS_LAT_DEG}°")
            }
            Problem::NegativeSpeed(s) => write!(f, "negative speed {s}"),
            Problem::ZeroSpeed => write!(f, "speed must be > 0"),
            Problem::NegativeDistance(d) => write!(f, "negative distance {d}"),
            Problem::UnknownKind(k) => write!(f, "unknown kind {k:?} (area or track)"),
            Problem::DuplicateId => write!(f, "duplicate id"),
            Problem::EndBeforeStart => write!(f, "tf before t0"),
            Problem::RectangleTooLarge(l) => write!(
                f,
                "the rectangle reaches latitude {l:.1}°, beyond ±{MAX_RECT_LAT_DEG}°"
            ),
            Problem::UnknownMember(s) => {
                write!(f, "unknown member")?;
                match s {
                    Some(s) => write!(f, "; did you mean {s}?"),
                    None => Ok(()),
                }
            }
            Problem::Misplaced(place) => {
                write!(f, "not a member of this object; it belongs in {place}")
            }
            Problem::NotForKind(k) => write!(f, "not a property of {k}"),
            Problem::DuplicateKey => write!(f, "given twice"),
            Problem::SelfIntersecting(a, b) => write!(
                f,
                "edges {}–{} and {}–{} cross (positions numbered from 0); \
                 the ring must not intersect itself",
                a.0, a.1, b.0, b.1
            ),
            Problem::ZeroArea => write!(f, "the vertices lie on one line; the area is empty"),
            Problem::CrossesAntimeridian(k) => write!(
                f,
                "positions {} and {k} are more than 180° of longitude apart, in a file of \
                 the unrolled plane (\"longitudes\": \"unrolled\"), where longitudes do not \
                 wrap; add positions between them",
                k - 1
            ),
            Problem::HalfTurnStep(k) => write!(
                f,
                "positions {} and {k} are exactly 180° of longitude apart: the line between \
                 them could run east or west; add a position between them",
                k - 1
            ),
            Problem::CirclesPole => write!(
                f,
                "the ring circles a pole (its positions, joined the shorter way round, end \
                 a whole turn of longitude from where they start); no ring on the Mercator \
                 plane bounds it"
            ),
            Problem::SpansWholeTurn(d) => write!(
                f,
                "the ring spans {d}° of longitude, a whole turn or more: it would overlap \
                 itself around the Earth"
            ),
            Problem::UnknownLongitudes(v) => {
                write!(f, "{v:?}: expected \"earth\" (the default) or \"unrolled\"")
            }
            Problem::RingsMeet { ring, a, b } => write!(
                f,
                "meets ring {ring} of the polygon: edge {}→{} of this ring and edge {}→{} of \
                 that one share a point (rings of a polygon must not touch or cross)",
                a.0, a.1, b.0, b.1
            ),
            Problem::HoleOutside => write!(
                f,
                "this hole does not lie inside the polygon's exterior ring (ring 0)"
            ),
            Problem::HoleInHole(k) => write!(
                f,
                "this hole and hole {k} of the polygon lie one inside the other"
            ),
            Problem::UnsupportedCrs(c) => write!(
                f,
                "{c:?} is not WGS 84 longitude/latitude (RFC 7946 positions are)"
            ),
        }
    }
}

impl std::error::Error for ScenarioError {}

pub(super) struct Ctx<'a> {
    pub(super) index: usize,
    pub(super) id: Option<&'a str>,
    /// The line of the feature's start, for errors not tied to one field's position.
    pub(super) line: Option<usize>,
}

impl Ctx<'_> {
    /// An error of this feature about `field`, on the feature's line.
    pub(super) fn err(&self, field: impl Into<String>, problem: Problem) -> ScenarioError {
        ScenarioError {
            line: self.line,
            index: Some(self.index),
            id: self.id.map(str::to_owned),
            field: field.into(),
            problem,
        }
    }
}

/// An error of the file (no feature) about `field`.
pub(super) fn file_err(line: Option<usize>, field: &str, problem: Problem) -> ScenarioError {
    ScenarioError {
        line,
        index: None,
        id: None,
        field: field.to_owned(),
        problem,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::read::testkit::{middle, problem};
    use crate::scenario::testdata::{AREA, TRACK};

    #[test]
    fn typed_errors_name_id_and_field() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"u","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1]]]}}"#,
        );
        assert_eq!(e.problem, Problem::UnclosedRing);
        assert_eq!(e.id.as_deref(), Some("u"));
        assert_eq!(e.field, "geometry.coordinates[0]");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"few","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,0]]]}}"#,
        );
        assert!(matches!(e.problem, Problem::TooFewVertices(_)));
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"lat","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,86],[1,1],[0,0]]]}}"#,
        );
        assert_eq!(e.problem, Problem::LatitudeOutOfRange(86.0));
        assert_eq!(e.field, "geometry.coordinates[0][1]");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"neg","kind":"track","speed_kn":-1,
            "front_nm":1,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.problem, Problem::NegativeSpeed(-1.0));
        assert_eq!(e.field, "properties.speed_kn");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"k","kind":"blob"},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.problem, Problem::UnknownKind("blob".into()));
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#,
        );
        assert_eq!(e.problem, Problem::DuplicateId);
        assert!(e.to_string().contains("\"ok\""));
    }

    /// Every kind of error names the line, the feature's index and id, and the field.
    #[test]
    fn each_error_names_line_id_and_field() {
        let cases: [(String, &str, &str); 10] = [
            (
                AREA.replace(r#""tf":2"#, r#""t_f":2"#).replace(r#""id":"a""#, r#""id":"x""#),
                "properties.t_f",
                "unknown member; did you mean tf?",
            ),
            (
                TRACK.replace(r#""side_nm":1"#, r#""side_nm":1,"tf":4"#).replace(r#""id":"t""#, r#""id":"x""#),
                "properties.tf",
                "not a property of a track",
            ),
            (
                AREA.replace(r#""tf":2"#, r#""tf":2,"tf":3"#).replace(r#""id":"a""#, r#""id":"x""#),
                "properties.tf",
                "given twice",
            ),
            (
                AREA.replace(r#""tf":2"#, r#""tf":NaN"#).replace(r#""id":"a""#, r#""id":"x""#),
                "properties.tf",
                "NaN is not a JSON number; finite numbers are needed",
            ),
            (
                AREA.replace("[[[0,0],[1,0],[1,1],[0,0]]]", "[[[0,0],[1,1],[1,0],[0,1],[0,0]]]")
                    .replace(r#""id":"a""#, r#""id":"x""#),
                "geometry.coordinates[0]",
                "edges 0–1 and 2–3 cross (positions numbered from 0); the ring must not intersect itself",
            ),
            (
                AREA.replace(r#""geometry":{"#, r#""geometyr":{"#).replace(r#""id":"a""#, r#""id":"x""#),
                "geometyr",
                "unknown member; did you mean geometry?",
            ),
            (
                AREA.replace(r#""geometry":{"#, r#""t0":1,"geometry":{"#)
                    .replace(r#""id":"a""#, r#""id":"x""#),
                "t0",
                "not a member of this object; it belongs in a Feature's properties (docs/scenario.md)",
            ),
            (
                TRACK.replace(r#""speed_kn":10"#, r#""speed_kn":-1"#).replace(r#""id":"t""#, r#""id":"x""#),
                "properties.speed_kn",
                "negative speed -1",
            ),
            (
                AREA.replace("[1,1],[0,0]", "[1,1],[0,0.5]").replace(r#""id":"a""#, r#""id":"x""#),
                "geometry.coordinates[0]",
                "ring not closed (last position ≠ first)",
            ),
            (
                AREA.replace("[[[0,0],[1,0],[1,1],[0,0]]]", "[[[0,1],[1,1],[2,1],[0,1]]]")
                    .replace(r#""id":"a""#, r#""id":"x""#),
                "geometry.coordinates[0]",
                "the vertices lie on one line; the area is empty",
            ),
        ];
        for (bad, field, message) in cases {
            let e = middle(&bad);
            assert_eq!(e.line, Some(3), "{bad}: {e}");
            assert_eq!(e.index, Some(1), "{bad}");
            assert_eq!(e.id.as_deref(), Some("x"), "{bad}");
            assert_eq!(e.field, field, "{bad}");
            assert_eq!(
                e.to_string(),
                format!("line 3: feature 1 (id \"x\"), {field}: {message}")
            );
        }
    }
}
