//! The scenario GeoJSON of docs/scenario.md (paper B's areas and tracks).
//!
//! Reading is strict per feature and forgiving per file: a bad feature yields a
//! [`ScenarioError`] naming its line, index, id and field and is skipped, the others are
//! still read. Only a file that is not a GeoJSON FeatureCollection at all is a fatal
//! error.

use crate::conflict::Object;
use crate::json::{self, Json, Member, Node};
use crate::sphere::{self, LonLat, RectDims};
use serde_json::{json, Map, Value};
use std::fmt;

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
    /// properties are open) and written back by [`to_geojson`].
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

/// What [`parse`] read: the valid features, an error per rejected feature, and a
/// warning per member kept without being read.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Read {
    /// The valid features.
    pub scenario: Scenario,
    /// One per rejected feature (the first thing wrong with it).
    pub errors: Vec<ScenarioError>,
    /// Members of `properties` that the format does not define (kept, not read).
    pub warnings: Vec<ScenarioWarning>,
}

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
    /// A member the format does not define where GeoJSON allows none, or a `properties`
    /// member one or two letters from a defined one (a misspelling must not change the
    /// meaning silently), with that name.
    UnknownMember(Option<&'static str>),
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
    /// In a file of the unrolled plane ([`Longitudes::Unrolled`]), positions k−1 and k
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
/// `properties` member the format does not define), or a longitude beyond ±180° read
/// modulo 360°.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioWarning {
    /// The 1-based line of the member or position.
    pub line: usize,
    /// Index of the feature in the file.
    pub index: usize,
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
    /// A member the format does not define, kept and written back, not read.
    Kept,
    /// A longitude beyond ±180° (as written) read on the real Earth as the place it
    /// names (the value in (−180, 180]); the first such position of the feature.
    Wrapped(f64, f64),
}

impl fmt::Display for ScenarioWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: feature {}", self.line, self.index)?;
        if let Some(id) = &self.id {
            write!(f, " (id {id:?})")?;
        }
        match self.what {
            Warning::Kept => write!(
                f,
                ", {}: not defined by the scenario format; kept, not read",
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

struct Ctx<'a> {
    index: usize,
    id: Option<&'a str>,
    /// The line of the feature's start, for errors not tied to one field's position.
    line: Option<usize>,
}

impl Ctx<'_> {
    fn err(&self, field: impl Into<String>, problem: Problem) -> ScenarioError {
        ScenarioError {
            line: self.line,
            index: Some(self.index),
            id: self.id.map(str::to_owned),
            field: field.into(),
            problem,
        }
    }
}

fn file_err(line: Option<usize>, field: &str, problem: Problem) -> ScenarioError {
    ScenarioError {
        line,
        index: None,
        id: None,
        field: field.to_owned(),
        problem,
    }
}

/// A position checked for range: `[lon, lat]` degrees, |lat| ≤ [`MAX_ABS_LAT_DEG`].
fn checked(ctx: &Ctx, field: &str, k: usize, lon: f64, lat: f64) -> Result<LonLat, ScenarioError> {
    if !(lon.is_finite() && lat.is_finite()) {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::BadNumber));
    }
    if lat.abs() > MAX_ABS_LAT_DEG {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::LatitudeOutOfRange(lat)));
    }
    Ok(LonLat::from_degrees(lon, lat))
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

/// One line of positions (degrees as written: a ring, closing repeat included, or a
/// track's waypoints) laid out on the plane of `mode`; also the index of the first
/// position whose longitude lies beyond ±180° (it was wrapped, for a warning).
///
/// On the Earth the first longitude is taken modulo 360° into (−180, 180] and each next
/// one is the value of its own longitude (mod 360°) nearest the previous one, so every
/// step runs the shorter way round, across the antimeridian when that is shorter. The
/// way is decided on the steps between the exact values in (−180, 180] (one rounding,
/// which keeps the comparison with ±180 right except at a tie); a step of exactly 180°
/// could run either way and is an error. The longitude written is then ℓ + 360°·m for
/// the exact ℓ ∈ (−180, 180] and a whole m counted along the line: one rounding, none
/// accumulated. A ring must come back to its first position with m = 0 (else it
/// circles a pole) and span less than a turn. On the unrolled plane the longitudes are
/// kept as written, and a step longer than 180° is an error.
///
/// `start` (whole turns, 0 but for a hole) starts the count m there: a hole is laid out
/// in the same copy as its exterior ring.
fn lay_out(
    ctx: &Ctx,
    field: &str,
    pts: &[[f64; 2]],
    mode: Longitudes,
    ring: bool,
    start: f64,
) -> Result<(Vec<[f64; 2]>, Option<usize>), ScenarioError> {
    let at = |k: usize, p: Problem| ctx.err(format!("{field}[{k}]"), p);
    if mode == Longitudes::Unrolled {
        return match (1..pts.len()).find(|&k| (pts[k][0] - pts[k - 1][0]).abs() > 180.0) {
            Some(k) => Err(at(k, Problem::CrossesAntimeridian(k))),
            None => Ok((pts.to_vec(), None)),
        };
    }
    let mut out = Vec::with_capacity(pts.len());
    let mut wrapped = None;
    let (mut prev, mut turns) = (0.0, start);
    for (k, q) in pts.iter().enumerate() {
        let l = normal_lon(q[0]);
        if wrapped.is_none() && q[0].abs() > 180.0 {
            wrapped = Some(k);
        }
        if k > 0 {
            let step = l - prev;
            if step.abs() == 180.0 {
                return Err(at(k, Problem::HalfTurnStep(k)));
            }
            if step > 180.0 {
                turns -= 1.0;
            } else if step < -180.0 {
                turns += 1.0;
            }
        }
        prev = l;
        out.push([if turns == 0.0 { l } else { l + 360.0 * turns }, q[1]]);
    }
    if ring && pts.len() > 1 {
        let (first, last) = (pts[0], pts[pts.len() - 1]);
        let closed = normal_lon(first[0]) == normal_lon(last[0]) && first[1] == last[1];
        if closed && turns != start {
            return Err(ctx.err(field, Problem::CirclesPole));
        }
        let (lo, hi) = out
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[0]), hi.max(p[0]))
            });
        if hi - lo >= 360.0 {
            return Err(ctx.err(field, Problem::SpansWholeTurn(hi - lo)));
        }
    }
    Ok((out, wrapped))
}

/// The spec's rules for one ring already read (`field` names it): closed, ≥ 3 distinct
/// vertices, simple (on the Mercator plane, where paper B's rhumb-line edges are
/// straight; exact orientation tests on the f64 Mercator vertices the stages use).
/// Either winding is accepted (RFC 7946 §3.1.6); the ring is kept counterclockwise, or
/// clockwise for a `hole`.
fn ring_from(
    ctx: &Ctx,
    ring: Vec<LonLat>,
    field: &str,
    hole: bool,
) -> Result<Vec<LonLat>, ScenarioError> {
    ring_indexed(ctx, ring, field, hole).map(|(r, _)| r)
}

/// [`ring_from`], with the index as written of each vertex kept.
fn ring_indexed(
    ctx: &Ctx,
    mut ring: Vec<LonLat>,
    field: &str,
    hole: bool,
) -> Result<(Vec<LonLat>, Vec<usize>), ScenarioError> {
    use polyguard::ring::{check, collinear, RingFault, Winding};
    if ring.len() < 2 || ring.first() != ring.last() {
        if ring.len() < 3 {
            return Err(ctx.err(field, Problem::TooFewVertices(ring.len())));
        }
        return Err(ctx.err(field, Problem::UnclosedRing));
    }
    ring.pop();
    let distinct = {
        let mut d = ring.clone();
        d.dedup();
        d.len() - usize::from(d.len() > 1 && d.first() == d.last())
    };
    if distinct < 3 {
        return Err(ctx.err(field, Problem::TooFewVertices(distinct)));
    }
    let plane = merc_ring(&ring);
    let want = if hole {
        Winding::Clockwise
    } else {
        Winding::Counterclockwise
    };
    let mut index: Vec<usize> = (0..ring.len()).collect();
    match check(&plane) {
        Ok(w) if w == want => {}
        Ok(_) => {
            ring.reverse();
            index.reverse();
        }
        Err(RingFault::Crossing { .. }) if collinear(&plane) => {
            return Err(ctx.err(field, Problem::ZeroArea))
        }
        Err(RingFault::Crossing { a, b }) => {
            return Err(ctx.err(field, Problem::SelfIntersecting(a, b)))
        }
        Err(RingFault::ZeroArea) => return Err(ctx.err(field, Problem::ZeroArea)),
        // beyond the exact check's range (no real position gets there): kept as given
        Err(RingFault::NotCheckable) => {}
    }
    let mut kept: Vec<(LonLat, usize)> = ring.into_iter().zip(index).collect();
    kept.dedup_by(|b, a| a.0 == b.0);
    if kept.len() > 1 && kept.first().map(|p| p.0) == kept.last().map(|p| p.0) {
        kept.pop();
    }
    Ok(kept.into_iter().unzip())
}

/// A ring's vertices on the Mercator plane, as the stages see them.
fn merc_ring(ring: &[LonLat]) -> Vec<polyguard::vect2::Vect2> {
    ring.iter()
        .map(|&p| {
            let [x, y] = sphere::mercator(p);
            polyguard::vect2::Vect2::new(x, y)
        })
        .collect()
}

/// Is `p` strictly inside the ring? Exact crossing number (the orientation of each edge
/// that straddles p's height); `p` must not lie on the ring. `None` when an exact
/// product would over- or underflow.
fn strictly_inside(p: polyguard::vect2::Vect2, ring: &[polyguard::vect2::Vect2]) -> Option<bool> {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            // the edge crosses the horizontal line through p right of p exactly when p
            // is left of the edge taken upward
            let o = polyguard::ring::orient(a, b, p)?;
            if (o > 0) == (b.y > a.y) {
                inside = !inside;
            }
        }
    }
    Some(inside)
}

/// The rules between the rings of one polygon (each already checked by [`ring_from`]):
/// no two share a point, every hole lies inside the exterior ring and outside the other
/// holes. `Err((k, problem))` names the ring k at fault (a hole); the checks are exact on
/// the Mercator vertices. O(n²) edge pairs, pruned by bounding boxes. `written` gives
/// each ring's vertex indices as written (for the edges an error names).
fn check_rings(
    ring: &[LonLat],
    holes: &[Vec<LonLat>],
    written: &[Vec<usize>],
) -> Result<(), (usize, Problem)> {
    use polyguard::ring::segments_meet;
    use polyguard::vect2::Vect2;
    let rings: Vec<Vec<Vect2>> = std::iter::once(ring)
        .chain(holes.iter().map(|h| h.as_slice()))
        .map(merc_ring)
        .collect();
    let boxes: Vec<[f64; 4]> = rings
        .iter()
        .map(|r| {
            r.iter().fold(
                [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ],
                |b, p| [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)],
            )
        })
        .collect();
    let apart = |a: [f64; 4], b: [f64; 4]| a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1];
    for k in 1..rings.len() {
        for j in 0..k {
            if apart(boxes[j], boxes[k]) {
                continue;
            }
            let (r, q) = (&rings[k], &rings[j]);
            for a in 0..r.len() {
                let (a0, a1) = (r[a], r[(a + 1) % r.len()]);
                for b in 0..q.len() {
                    let (b0, b1) = (q[b], q[(b + 1) % q.len()]);
                    // beyond the exact range (no real position gets there): not a meeting
                    if segments_meet(a0, a1, b0, b1) == Some(true) {
                        // each edge named in the direction it is written
                        let edge = |w: &[usize], i: usize| {
                            let (x, y) = (w[i], w[(i + 1) % w.len()]);
                            if w.len() > 1 && w[0] > w[1] {
                                (y, x)
                            } else {
                                (x, y)
                            }
                        };
                        let (a, b) = (edge(&written[k], a), edge(&written[j], b));
                        let n = |x: usize| u32::try_from(x).unwrap_or(u32::MAX);
                        return Err((
                            k,
                            Problem::RingsMeet {
                                ring: n(j),
                                a: (n(a.0), n(a.1)),
                                b: (n(b.0), n(b.1)),
                            },
                        ));
                    }
                }
            }
        }
        // No ring meets another: a ring's first vertex tells on which side of another
        // ring the whole of it lies.
        if strictly_inside(rings[k][0], &rings[0]) == Some(false) {
            return Err((k, Problem::HoleOutside));
        }
        for j in 1..k {
            if strictly_inside(rings[k][0], &rings[j]) == Some(true)
                || strictly_inside(rings[j][0], &rings[k]) == Some(true)
            {
                return Err((k, Problem::HoleInHole(j)));
            }
        }
    }
    Ok(())
}

/// The spec's area rules for a Polygon of one ring (the fast path's areas): the ring's
/// rules ([`ring_from`]) and `tf ≥ t0`.
fn area_from(
    ctx: &Ctx,
    ring: Vec<LonLat>,
    t0: Option<f64>,
    tf: Option<f64>,
) -> Result<Area, ScenarioError> {
    let ring = ring_from(ctx, ring, "geometry.coordinates[0]", false)?;
    times_ok(ctx, t0, tf)?;
    Ok(Area {
        shapes: vec![Shape::plain(ring)],
        multi: false,
        t0,
        tf,
    })
}

/// An area's `tf ≥ t0`.
fn times_ok(ctx: &Ctx, t0: Option<f64>, tf: Option<f64>) -> Result<(), ScenarioError> {
    if let (Some(a), Some(b)) = (t0, tf) {
        if b < a {
            return Err(ctx.err("properties.tf", Problem::EndBeforeStart));
        }
    }
    Ok(())
}

/// The spec's track rules on values already read: ≥ 2 waypoints, speed > 0, distances
/// ≥ 0 (`None` = missing).
fn track_from(
    ctx: &Ctx,
    waypoints: Vec<LonLat>,
    speed_kn: Option<f64>,
    dists: [Option<f64>; 3],
    t0: Option<f64>,
) -> Result<Track, ScenarioError> {
    if waypoints.len() < 2 {
        return Err(ctx.err(
            "geometry.coordinates",
            Problem::TooFewVertices(waypoints.len()),
        ));
    }
    let speed_kn = speed_kn.ok_or_else(|| ctx.err("properties.speed_kn", Problem::Missing))?;
    if speed_kn < 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::NegativeSpeed(speed_kn)));
    }
    if speed_kn == 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::ZeroSpeed));
    }
    let mut d = [0.0; 3];
    for (k, key) in ["front_nm", "back_nm", "side_nm"].iter().enumerate() {
        d[k] = dists[k].ok_or_else(|| ctx.err(format!("properties.{key}"), Problem::Missing))?;
        if d[k] < 0.0 {
            return Err(ctx.err(format!("properties.{key}"), Problem::NegativeDistance(d[k])));
        }
    }
    let reach = (d[0].max(d[1]) + d[2]) / sphere::EARTH_RADIUS_NM;
    let top = waypoints.iter().fold(0f64, |m, p| m.max(p.lat.abs())) + reach;
    if top.to_degrees() > MAX_RECT_LAT_DEG {
        return Err(ctx.err(
            "properties.front_nm",
            Problem::RectangleTooLarge(top.to_degrees()),
        ));
    }
    Ok(Track {
        waypoints,
        speed_kn,
        dims: RectDims {
            front: d[0],
            back: d[1],
            side: d[2],
        },
        t0: t0.unwrap_or(0.0),
    })
}

/// The members each level may have. GeoJSON (RFC 7946) defines `type`, `bbox` and a
/// Feature's `id`; `name` and `crs` are what GDAL/QGIS write on a collection.
const COLLECTION_KEYS: [&str; 6] = ["type", "features", "bbox", "name", "crs", "longitudes"];
const FEATURE_KEYS: [&str; 5] = ["type", "properties", "geometry", "id", "bbox"];
const GEOMETRY_KEYS: [&str; 3] = ["type", "coordinates", "bbox"];
/// The properties this format defines, and which kind each belongs to.
const AREA_PROPS: [&str; 4] = ["id", "kind", "t0", "tf"];
const TRACK_PROPS: [&str; 7] = [
    "id", "kind", "speed_kn", "front_nm", "back_nm", "side_nm", "t0",
];
const ALL_PROPS: [&str; 8] = [
    "id", "kind", "t0", "tf", "speed_kn", "front_nm", "back_nm", "side_nm",
];

/// The CRS names that mean RFC 7946's own (WGS 84 longitude, latitude in degrees).
const WGS84_NAMES: [&str; 4] = [
    "urn:ogc:def:crs:OGC:1.3:CRS84",
    "urn:ogc:def:crs:OGC::CRS84",
    "EPSG:4326",
    "urn:ogc:def:crs:EPSG::4326",
];

/// The reader of the general path: every member checked by name, every error with its
/// line.
struct Reader<'t> {
    lines: json::Lines,
    /// The collection's `longitudes`.
    longitudes: Longitudes,
    _text: std::marker::PhantomData<&'t str>,
}

impl Reader<'_> {
    fn line(&self, at: usize) -> Option<usize> {
        Some(self.lines.line(at))
    }

    fn at(&self, ctx: &Ctx, node_at: usize, field: impl Into<String>, p: Problem) -> ScenarioError {
        let mut e = ctx.err(field, p);
        e.line = self.line(node_at);
        e
    }

    /// The first repeated key of an object, as an error for `prefix.key`.
    fn no_repeats(&self, ctx: &Ctx, members: &[Member], prefix: &str) -> Result<(), ScenarioError> {
        let mut seen = std::collections::HashSet::with_capacity(members.len());
        match members.iter().find(|m| !seen.insert(m.key.as_str())) {
            Some(m) => Err(self.at(ctx, m.at, join(prefix, &m.key), Problem::DuplicateKey)),
            None => Ok(()),
        }
    }

    /// Members outside `known` are errors (GeoJSON's own levels).
    fn only_known(
        &self,
        ctx: &Ctx,
        members: &[Member],
        known: &[&'static str],
        prefix: &str,
    ) -> Result<(), ScenarioError> {
        self.no_repeats(ctx, members, prefix)?;
        match members.iter().find(|m| !known.contains(&m.key.as_str())) {
            Some(m) => Err(self.at(
                ctx,
                m.at,
                join(prefix, &m.key),
                Problem::UnknownMember(json::suggest(&m.key, known)),
            )),
            None => Ok(()),
        }
    }

    fn number(
        &self,
        ctx: &Ctx,
        node: Option<&Node>,
        field: &str,
    ) -> Result<Option<f64>, ScenarioError> {
        match node.map(|n| (n.at, &n.value)) {
            None | Some((_, Json::Null)) => Ok(None),
            Some((_, Json::Number(x))) if x.is_finite() => Ok(Some(*x)),
            Some((at, Json::Number(_))) => Err(self.at(ctx, at, field, Problem::BadNumber)),
            Some((at, Json::NotJson(l))) => Err(self.at(ctx, at, field, Problem::NotJsonNumber(l))),
            Some((at, _)) => Err(self.at(ctx, at, field, Problem::WrongType("number"))),
        }
    }

    fn positions(
        &self,
        ctx: &Ctx,
        node: &Node,
        field: &str,
        ring: bool,
        start: f64,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Vec<LonLat>, ScenarioError> {
        let arr = node.elements().ok_or_else(|| {
            self.at(
                ctx,
                node.at,
                field,
                Problem::WrongType("array of positions"),
            )
        })?;
        arr.iter()
            .enumerate()
            .map(|(k, p)| {
                let name = || format!("{field}[{k}]");
                let xy = p
                    .elements()
                    .filter(|a| a.len() >= 2)
                    .ok_or_else(|| self.at(ctx, p.at, name(), Problem::BadNumber))?;
                let mut c = [0.0; 2];
                for (j, n) in xy.iter().take(2).enumerate() {
                    c[j] = match n.value {
                        Json::Number(x) => x,
                        Json::NotJson(l) => {
                            return Err(self.at(ctx, n.at, name(), Problem::NotJsonNumber(l)))
                        }
                        _ => return Err(self.at(ctx, n.at, name(), Problem::BadNumber)),
                    };
                }
                checked(ctx, field, k, c[0], c[1])
                    .map(|q| (q, c))
                    .map_err(|mut e| {
                        e.line = self.line(p.at);
                        e
                    })
            })
            .collect::<Result<Vec<_>, _>>()
            .and_then(|read| {
                let raw: Vec<[f64; 2]> = read.iter().map(|&(_, c)| c).collect();
                let (laid, wrapped) = lay_out(ctx, field, &raw, self.longitudes, ring, start)
                    .map_err(|mut e| {
                        e.line = match e.problem {
                            Problem::CrossesAntimeridian(k) | Problem::HalfTurnStep(k) => {
                                self.line(arr[k].at)
                            }
                            _ => self.line(node.at),
                        };
                        e
                    })?;
                if let Some(k) = wrapped {
                    warnings.push(ScenarioWarning {
                        line: self.lines.line(arr[k].at),
                        index: ctx.index,
                        id: ctx.id.map(str::to_owned),
                        field: format!("{field}[{k}]"),
                        what: Warning::Wrapped(raw[k][0], normal_lon(raw[k][0])),
                    });
                }
                Ok(laid
                    .into_iter()
                    .map(|[lon, lat]| LonLat::from_degrees(lon, lat))
                    .collect())
            })
    }

    /// One polygon of an area (`prefix` names its array of rings): its exterior ring and
    /// holes, each checked ([`ring_from`]), and the rules between them ([`check_rings`]).
    /// On the Earth each hole is laid out in the copy of its exterior ring (the one whose
    /// longitudes are nearest the ring's middle).
    fn shape(
        &self,
        ctx: &Ctx,
        node: &Node,
        prefix: &str,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Shape, ScenarioError> {
        let rings = node
            .elements()
            .ok_or_else(|| self.at(ctx, node.at, prefix, Problem::WrongType("array of rings")))?;
        let first = rings
            .first()
            .ok_or_else(|| self.at(ctx, node.at, format!("{prefix}[0]"), Problem::Missing))?;
        let at_ring = |n: &Node| Ctx {
            line: self.line(n.at),
            ..*ctx
        };
        let field = format!("{prefix}[0]");
        let ring = self.positions(ctx, first, &field, true, 0.0, warnings)?;
        let (ring, w0) = ring_indexed(&at_ring(first), ring, &field, false)?;
        let mut written = vec![w0];
        let mid = {
            let (lo, hi) = ring
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
                    (lo.min(q.lon), hi.max(q.lon))
                });
            (0.5 * (lo + hi)).to_degrees()
        };
        let mut holes = Vec::with_capacity(rings.len() - 1);
        for (k, h) in rings.iter().enumerate().skip(1) {
            let field = format!("{prefix}[{k}]");
            let mut read = Vec::new();
            let mut laid = self.positions(ctx, h, &field, true, 0.0, &mut read)?;
            if self.longitudes == Longitudes::Earth {
                if let Some(q) = laid.first() {
                    let turns = ((mid - q.lon.to_degrees()) / 360.0).round();
                    if turns != 0.0 {
                        laid = self.positions(ctx, h, &field, true, turns, &mut Vec::new())?;
                    }
                }
            }
            warnings.extend(read);
            let (hole, w) = ring_indexed(&at_ring(h), laid, &field, true)?;
            holes.push(hole);
            written.push(w);
        }
        check_rings(&ring, &holes, &written)
            .map_err(|(k, problem)| self.at(ctx, rings[k].at, format!("{prefix}[{k}]"), problem))?;
        Ok(Shape { ring, holes })
    }

    /// An area's geometry: a Polygon or a MultiPolygon (`true`), its coordinates.
    fn area_geometry<'n>(&self, ctx: &Ctx, f: &'n Node) -> Result<(&'n Node, bool), ScenarioError> {
        let multi = f
            .get("geometry")
            .and_then(|g| g.get("type"))
            .and_then(|t| t.as_str())
            == Some("MultiPolygon");
        let ty = if multi { "MultiPolygon" } else { "Polygon" };
        match self.geometry(ctx, f, ty) {
            Ok(c) => Ok((c, multi)),
            Err(mut e) => {
                if e.problem == Problem::WrongType("Polygon") {
                    e.problem = Problem::WrongType("Polygon or MultiPolygon");
                }
                Err(e)
            }
        }
    }

    /// The geometry's coordinates, its type checked.
    fn geometry<'n>(
        &self,
        ctx: &Ctx,
        f: &'n Node,
        ty: &'static str,
    ) -> Result<&'n Node, ScenarioError> {
        let g = f
            .get("geometry")
            .filter(|g| g.value != Json::Null)
            .ok_or_else(|| ctx.err("geometry", Problem::Missing))?;
        let members = g
            .members()
            .ok_or_else(|| self.at(ctx, g.at, "geometry", Problem::WrongType("an object")))?;
        self.only_known(ctx, members, &GEOMETRY_KEYS, "geometry")?;
        match g.get("type") {
            Some(t) if t.as_str() == Some(ty) => {}
            Some(t) => return Err(self.at(ctx, t.at, "geometry.type", Problem::WrongType(ty))),
            None => return Err(self.at(ctx, g.at, "geometry.type", Problem::Missing)),
        }
        g.get("coordinates")
            .ok_or_else(|| self.at(ctx, g.at, "geometry.coordinates", Problem::Missing))
    }

    /// One feature: its kind's rules, its properties checked by name.
    fn feature(
        &self,
        ctx: &Ctx,
        f: &Node,
        props: &[Member],
        kind: &str,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<(Kind, Map<String, Value>), ScenarioError> {
        let (own, this): (&[&str], &'static str) = match kind {
            "area" => (&AREA_PROPS, "an area"),
            "track" => (&TRACK_PROPS, "a track"),
            k => {
                let at = f
                    .get("properties")
                    .and_then(|p| p.get("kind"))
                    .map_or(f.at, |n| n.at);
                return Err(self.at(
                    ctx,
                    at,
                    "properties.kind",
                    Problem::UnknownKind(k.to_owned()),
                ));
            }
        };
        let mut extra = Map::new();
        let mut kept = Vec::new();
        for m in props {
            let field = join("properties", &m.key);
            if own.contains(&m.key.as_str()) {
                continue;
            }
            if ALL_PROPS.contains(&m.key.as_str()) {
                // null is absent, as for the kind's own properties
                if m.value.value == Json::Null {
                    continue;
                }
                return Err(self.at(ctx, m.at, field, Problem::NotForKind(this)));
            }
            if let Some(s) = json::suggest(&m.key, own) {
                return Err(self.at(ctx, m.at, field, Problem::UnknownMember(Some(s))));
            }
            if let Json::NotJson(l) = m.value.value {
                return Err(self.at(ctx, m.value.at, field, Problem::NotJsonNumber(l)));
            }
            extra.insert(m.key.clone(), json::to_value(&m.value));
            kept.push(ScenarioWarning {
                line: self.lines.line(m.at),
                index: ctx.index,
                id: ctx.id.map(str::to_owned),
                field,
                what: Warning::Kept,
            });
        }
        let p = |k: &str| props.iter().find(|m| m.key == k).map(|m| &m.value);
        let t0 = self.number(ctx, p("t0"), "properties.t0")?;
        let kind = if kind == "area" {
            let (coords, multi) = self.area_geometry(ctx, f)?;
            let tf = self.number(ctx, p("tf"), "properties.tf")?;
            let polygons: Vec<(&Node, String)> = if multi {
                let parts = coords.elements().ok_or_else(|| {
                    self.at(
                        ctx,
                        coords.at,
                        "geometry.coordinates",
                        Problem::WrongType("array of polygons"),
                    )
                })?;
                if parts.is_empty() {
                    return Err(self.at(
                        ctx,
                        coords.at,
                        "geometry.coordinates[0]",
                        Problem::Missing,
                    ));
                }
                parts
                    .iter()
                    .enumerate()
                    .map(|(k, n)| (n, format!("geometry.coordinates[{k}]")))
                    .collect()
            } else {
                vec![(coords, "geometry.coordinates".to_owned())]
            };
            let mut shapes = Vec::with_capacity(polygons.len());
            for (node, prefix) in polygons {
                shapes.push(self.shape(ctx, node, &prefix, warnings)?);
            }
            times_ok(ctx, t0, tf).map_err(|mut e| {
                e.line = p("tf").and_then(|n| self.line(n.at));
                e
            })?;
            Kind::Area(Area {
                shapes,
                multi,
                t0,
                tf,
            })
        } else {
            let coords = self.geometry(ctx, f, "LineString")?;
            let waypoints =
                self.positions(ctx, coords, "geometry.coordinates", false, 0.0, warnings)?;
            let speed = self.number(ctx, p("speed_kn"), "properties.speed_kn")?;
            let dists = [
                self.number(ctx, p("front_nm"), "properties.front_nm")?,
                self.number(ctx, p("back_nm"), "properties.back_nm")?,
                self.number(ctx, p("side_nm"), "properties.side_nm")?,
            ];
            Kind::Track(
                track_from(ctx, waypoints, speed, dists, t0).map_err(|mut e| {
                    // a value's own line when the error is about one property
                    let key = e.field.strip_prefix("properties.").unwrap_or("");
                    if let Some(n) = p(key) {
                        e.line = self.line(n.at);
                    } else if e.field == "geometry.coordinates" {
                        e.line = self.line(coords.at);
                    }
                    e
                })?,
            )
        };
        warnings.extend(kept);
        Ok((kind, extra))
    }
}

fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_owned()
    } else {
        format!("{prefix}.{key}")
    }
}

/// The fast path's view of a scenario: clean files deserialize straight into these (no
/// tree); anything else (an unknown or repeated member, a wrong type, a rule broken)
/// goes to the general path, which names fields and lines.
mod fast {
    use serde::de::IgnoredAny;
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Collection {
        #[serde(rename = "type")]
        pub ty: String,
        pub features: Vec<Feature>,
        #[allow(dead_code)]
        pub bbox: Option<IgnoredAny>,
        #[allow(dead_code)]
        pub name: Option<IgnoredAny>,
        pub longitudes: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Feature {
        #[serde(rename = "type")]
        pub ty: String,
        pub properties: Props,
        pub geometry: Geometry,
        #[allow(dead_code)]
        pub id: Option<IgnoredAny>,
        #[allow(dead_code)]
        pub bbox: Option<IgnoredAny>,
    }
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Props {
        pub id: String,
        pub kind: String,
        pub t0: Option<f64>,
        pub tf: Option<f64>,
        pub speed_kn: Option<f64>,
        pub front_nm: Option<f64>,
        pub back_nm: Option<f64>,
        pub side_nm: Option<f64>,
    }
    #[derive(serde::Deserialize)]
    #[serde(tag = "type", content = "coordinates", deny_unknown_fields)]
    pub enum Geometry {
        Polygon(Vec<Vec<[f64; 2]>>),
        LineString(Vec<[f64; 2]>),
    }
}

/// The fast path: `Some` only for a file with nothing to report (no error, no warning),
/// which then reads exactly as the general path reads it (public for the differential
/// fuzz target; [`parse`] is the reader to use).
pub fn fast_parse(text: &str) -> Option<Read> {
    let fc: fast::Collection = serde_json::from_str(text).ok()?;
    if fc.ty != "FeatureCollection" {
        return None;
    }
    let longitudes = match fc.longitudes.as_deref() {
        None | Some("earth") => Longitudes::Earth,
        Some("unrolled") => Longitudes::Unrolled,
        Some(_) => return None,
    };
    let mut out = Scenario {
        features: Vec::new(),
        longitudes,
        geodesy: Default::default(),
    };
    let mut seen = std::collections::HashSet::with_capacity(fc.features.len());
    for (index, f) in fc.features.into_iter().enumerate() {
        let p = f.properties;
        if f.ty != "Feature" || !seen.insert(p.id.clone()) {
            return None;
        }
        let ctx = Ctx {
            index,
            id: Some(&p.id),
            line: None,
        };
        // None (to the general path) for a warning: a longitude wrapped
        let pts = |field: &str,
                   v: &[[f64; 2]],
                   ring: bool|
         -> Option<Result<Vec<LonLat>, ScenarioError>> {
            for (k, q) in v.iter().enumerate() {
                if let Err(e) = checked(&ctx, field, k, q[0], q[1]) {
                    return Some(Err(e));
                }
            }
            match lay_out(&ctx, field, v, longitudes, ring, 0.0) {
                Ok((_, Some(_))) => None,
                Ok((laid, None)) => Some(Ok(laid
                    .into_iter()
                    .map(|[lon, lat]| LonLat::from_degrees(lon, lat))
                    .collect())),
                Err(e) => Some(Err(e)),
            }
        };
        let kind = match (p.kind.as_str(), &f.geometry) {
            ("area", fast::Geometry::Polygon(rings))
                if rings.len() == 1
                    && p.speed_kn.is_none()
                    && p.front_nm.is_none()
                    && p.back_nm.is_none()
                    && p.side_nm.is_none() =>
            {
                let r = rings.first()?;
                pts("geometry.coordinates[0]", r, true)?
                    .and_then(|ring| area_from(&ctx, ring, p.t0, p.tf))
                    .map(Kind::Area)
            }
            ("track", fast::Geometry::LineString(line)) if p.tf.is_none() => {
                pts("geometry.coordinates", line, false)?
                    .and_then(|w| {
                        track_from(
                            &ctx,
                            w,
                            p.speed_kn,
                            [p.front_nm, p.back_nm, p.side_nm],
                            p.t0,
                        )
                    })
                    .map(Kind::Track)
            }
            _ => return None,
        };
        out.features.push(Feature {
            id: p.id,
            kind: kind.ok()?,
            extra: Map::new(),
        });
    }
    Some(Read {
        scenario: out,
        ..Read::default()
    })
}

/// Reads a scenario. `Err` only when the text is not a GeoJSON FeatureCollection; a bad
/// feature is reported (its line, index, id and field) and skipped, the others are read.
/// A byte-order mark in front is skipped.
pub fn parse(text: &str) -> Result<Read, ScenarioError> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some(r) = fast_parse(body) {
        return Ok(r);
    }
    parse_general(text)
}

/// [`parse`]'s general path over a tree that knows where each value starts: any JSON,
/// every member checked by name (public for the differential fuzz target).
pub fn parse_general(text: &str) -> Result<Read, ScenarioError> {
    let mut r = Reader {
        lines: json::Lines::new(text),
        longitudes: Longitudes::Earth,
        _text: std::marker::PhantomData,
    };
    let root = json::parse(text).map_err(|e| {
        let (line, col) = r.lines.line_col(e.at);
        file_err(
            Some(line),
            "(file)",
            Problem::Json(format!("{} at column {col}", e.message)),
        )
    })?;
    let top = Ctx {
        index: 0,
        id: None,
        line: r.line(root.at),
    };
    let fatal = |e: ScenarioError| ScenarioError {
        index: None,
        id: None,
        ..e
    };
    let members = root.members().ok_or_else(|| {
        file_err(
            r.line(root.at),
            "(file)",
            Problem::WrongType("a GeoJSON object"),
        )
    })?;
    r.only_known(&top, members, &COLLECTION_KEYS, "")
        .map_err(fatal)?;
    match root.get("type") {
        Some(t) if t.as_str() == Some("FeatureCollection") => {}
        Some(t) => {
            return Err(file_err(
                r.line(t.at),
                "type",
                Problem::WrongType("FeatureCollection"),
            ))
        }
        None => return Err(file_err(r.line(root.at), "type", Problem::Missing)),
    }
    if let Some(crs) = root.get("crs") {
        let name = crs
            .get("properties")
            .and_then(|p| p.get("name"))
            .and_then(Node::as_str);
        match name {
            Some(n) if WGS84_NAMES.contains(&n) => {}
            Some(n) => {
                return Err(file_err(
                    r.line(crs.at),
                    "crs",
                    Problem::UnsupportedCrs(n.to_owned()),
                ))
            }
            None => {
                return Err(file_err(
                    r.line(crs.at),
                    "crs.properties.name",
                    Problem::Missing,
                ))
            }
        }
    }
    if let Some(l) = root.get("longitudes") {
        r.longitudes = match l.as_str() {
            Some("earth") => Longitudes::Earth,
            Some("unrolled") => Longitudes::Unrolled,
            Some(v) => {
                return Err(file_err(
                    r.line(l.at),
                    "longitudes",
                    Problem::UnknownLongitudes(v.to_owned()),
                ))
            }
            None => {
                return Err(file_err(
                    r.line(l.at),
                    "longitudes",
                    Problem::WrongType("a string, \"earth\" or \"unrolled\""),
                ))
            }
        };
    }
    let feats = root
        .get("features")
        .ok_or_else(|| file_err(r.line(root.at), "features", Problem::Missing))?;
    let feats = feats
        .elements()
        .ok_or_else(|| file_err(r.line(feats.at), "features", Problem::WrongType("an array")))?;
    let mut out = Read::default();
    out.scenario.longitudes = r.longitudes;
    let mut seen = std::collections::HashSet::new();
    for (index, f) in feats.iter().enumerate() {
        let props_node = f.get("properties");
        let props = props_node.and_then(Node::members);
        let id_node = props.and_then(|p| p.iter().find(|m| m.key == "id"));
        let id = id_node.and_then(|m| m.value.as_str());
        let ctx = Ctx {
            index,
            id,
            line: r.line(f.at),
        };
        let result = (|| {
            let members = f.members().ok_or_else(|| {
                r.at(
                    &ctx,
                    f.at,
                    "(feature)",
                    Problem::WrongType("a GeoJSON Feature object"),
                )
            })?;
            r.only_known(&ctx, members, &FEATURE_KEYS, "")?;
            match f.get("type") {
                Some(t) if t.as_str() == Some("Feature") => {}
                Some(t) => return Err(r.at(&ctx, t.at, "type", Problem::WrongType("Feature"))),
                None => return Err(r.at(&ctx, f.at, "type", Problem::Missing)),
            }
            let props_node = props_node
                .filter(|p| p.value != Json::Null)
                .ok_or_else(|| ctx.err("properties", Problem::Missing))?;
            let props = props.ok_or_else(|| {
                r.at(
                    &ctx,
                    props_node.at,
                    "properties",
                    Problem::WrongType("an object"),
                )
            })?;
            r.no_repeats(&ctx, props, "properties")?;
            let Some(id) = id else {
                return Err(match id_node {
                    Some(m) => r.at(
                        &ctx,
                        m.value.at,
                        "properties.id",
                        Problem::WrongType("a string"),
                    ),
                    None => r.at(&ctx, props_node.at, "properties.id", Problem::Missing),
                });
            };
            if !seen.insert(id.to_owned()) {
                let at = id_node.map_or(f.at, |m| m.value.at);
                return Err(r.at(&ctx, at, "properties.id", Problem::DuplicateId));
            }
            let kind = match props_node.get("kind") {
                Some(k) => k.as_str().ok_or_else(|| {
                    r.at(
                        &ctx,
                        k.at,
                        "properties.kind",
                        Problem::WrongType("a string"),
                    )
                })?,
                None => return Err(r.at(&ctx, props_node.at, "properties.kind", Problem::Missing)),
            };
            let mut warnings = Vec::new();
            let (kind, extra) = r.feature(&ctx, f, props, kind, &mut warnings)?;
            Ok((
                Feature {
                    id: id.to_owned(),
                    kind,
                    extra,
                },
                warnings,
            ))
        })();
        match result {
            Ok((feature, warnings)) => {
                out.scenario.features.push(feature);
                out.warnings.extend(warnings);
            }
            Err(e) => out.errors.push(e),
        }
    }
    Ok(out)
}

/// Paper B Sections III and V: the scenario's objects in the Mercator plane, one per area
/// and one per track leg, `owner` = feature index in `scenario.features`. On the Earth an
/// object that reaches past ±180° comes with its copies a turn away
/// ([`Object::on_earth`]), so that stage 1 finds its meetings across the antimeridian.
pub fn objects(scenario: &Scenario) -> Vec<Object> {
    use rayon::prelude::*;
    let earth = scenario.longitudes == Longitudes::Earth;
    let geo = scenario.geodesy;
    scenario
        .features
        .par_iter()
        .enumerate()
        .flat_map_iter(|(k, f)| {
            let owner = k as u32;
            let merc =
                |r: &[LonLat]| -> Vec<[f64; 2]> { r.iter().map(|&p| geo.mercator(p)).collect() };
            let v: Vec<Object> = match &f.kind {
                Kind::Area(a) => a
                    .shapes
                    .iter()
                    .map(|sh| {
                        Object::area_with_holes(
                            owner,
                            merc(&sh.ring),
                            sh.holes.iter().map(|h| merc(h)).collect(),
                            a.t0.unwrap_or(f64::NEG_INFINITY),
                            a.tf.unwrap_or(f64::INFINITY),
                        )
                    })
                    .collect(),
                Kind::Track(t) => {
                    sphere::track_legs_in(geo, &t.waypoints, t.speed_kn, t.t0, t.dims)
                        .into_iter()
                        .map(|leg| Object::leg(owner, leg))
                        .collect()
                }
            };
            v.into_iter().flat_map(move |o| {
                if earth {
                    o.on_earth()
                } else {
                    vec![o.on_plane()]
                }
            })
        })
        .collect()
}

/// A position as written: on the Earth its longitude in (−180, 180] (RFC 7946), on the
/// unrolled plane as it lies there.
fn pos(p: LonLat, mode: Longitudes) -> Value {
    let (lon, lat) = p.to_degrees();
    match mode {
        Longitudes::Earth => json!([normal_lon(lon), lat]),
        Longitudes::Unrolled => json!([lon, lat]),
    }
}

/// The kept members after the defined ones.
fn extend(props: &mut Value, extra: &Map<String, Value>) {
    if let Some(m) = props.as_object_mut() {
        for (k, v) in extra {
            m.insert(k.clone(), v.clone());
        }
    }
}

/// Writes a scenario as the format's GeoJSON (areas counterclockwise, as read).
pub fn to_geojson(scenario: &Scenario) -> Value {
    let feats: Vec<Value> = scenario
        .features
        .iter()
        .map(|f| feature_geojson(f, scenario.longitudes))
        .collect();
    match scenario.longitudes {
        Longitudes::Earth => json!({"type": "FeatureCollection", "features": feats}),
        Longitudes::Unrolled => json!({"type": "FeatureCollection", "longitudes": "unrolled",
                                       "features": feats}),
    }
}

/// One feature of [`to_geojson`]'s collection on the plane `longitudes`.
pub fn feature_geojson(f: &Feature, longitudes: Longitudes) -> Value {
    match &f.kind {
        Kind::Area(a) => {
            let ring = |r: &[LonLat]| {
                let mut v: Vec<Value> = r.iter().map(|&p| pos(p, longitudes)).collect();
                if let Some(first) = v.first().cloned() {
                    v.push(first);
                }
                Value::Array(v)
            };
            let polygon = |sh: &Shape| {
                Value::Array(
                    std::iter::once(ring(&sh.ring))
                        .chain(sh.holes.iter().map(|h| ring(h)))
                        .collect(),
                )
            };
            let geometry = if a.multi {
                json!({"type": "MultiPolygon",
                       "coordinates": a.shapes.iter().map(polygon).collect::<Vec<_>>()})
            } else {
                json!({"type": "Polygon",
                       "coordinates": a.shapes.first().map(polygon).unwrap_or(json!([]))})
            };
            let mut props = json!({"id": f.id, "kind": "area"});
            extend(&mut props, &f.extra);
            if let Some(t0) = a.t0 {
                props["t0"] = json!(t0);
            }
            if let Some(tf) = a.tf {
                props["tf"] = json!(tf);
            }
            json!({"type": "Feature", "properties": props, "geometry": geometry})
        }
        Kind::Track(t) => {
            let line: Vec<Value> = t.waypoints.iter().map(|&p| pos(p, longitudes)).collect();
            let mut props = json!({"id": f.id, "kind": "track", "speed_kn": t.speed_kn,
                                   "front_nm": t.dims.front, "back_nm": t.dims.back,
                                   "side_nm": t.dims.side, "t0": t.t0});
            extend(&mut props, &f.extra);
            json!({"type": "Feature", "properties": props,
                   "geometry": {"type": "LineString", "coordinates": line}})
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(feature: &str) -> (Scenario, Vec<ScenarioError>) {
        let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
        let r = parse(&format!(
            r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#
        ))
        .expect("collection");
        (r.scenario, r.errors)
    }

    fn problem(feature: &str) -> ScenarioError {
        let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
        let text = format!(r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#);
        // the typed fast path, when it applies, agrees with the general path
        if let Some(fast) = fast_parse(&text) {
            assert_eq!(Ok(fast), parse_general(&text));
        }
        let (s, e) = one(feature);
        assert_eq!(s.features.len(), 1, "the good feature is still read");
        assert_eq!(e.len(), 1, "{e:?}");
        e[0].clone()
    }

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

    #[test]
    fn round_trip() {
        let (s, e) = one(
            r#"{"type":"Feature","properties":{"id":"t","kind":"track","speed_kn":15,
            "front_nm":10,"back_nm":10,"side_nm":10},
            "geometry":{"type":"LineString","coordinates":[[39,29],[41,31]]}}"#,
        );
        assert!(e.is_empty());
        let text = to_geojson(&s).to_string();
        let r = parse(&text).expect("parse");
        assert!(r.errors.is_empty());
        let s2 = r.scenario;
        assert_eq!(s2.features.len(), 2);
        assert_eq!(objects(&s2).len(), 2);
    }

    #[test]
    fn rectangle_past_the_pole_is_rejected() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"big","kind":"track","speed_kn":10,
            "front_nm":400,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,84],[1,84]]}}"#,
        );
        assert!(matches!(e.problem, Problem::RectangleTooLarge(_)));
    }

    #[test]
    fn wrong_types_fall_back_to_named_fields() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"s","kind":"track","speed_kn":"fast",
            "front_nm":1,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.field, "properties.speed_kn");
        assert_eq!(e.problem, Problem::WrongType("number"));
    }

    #[test]
    fn not_json_is_fatal() {
        assert!(matches!(parse("{").unwrap_err().problem, Problem::Json(_)));
    }

    /// A scenario of one line per feature after a header line: feature k is on line k + 2.
    fn file(features: &[&str]) -> String {
        let mut t = String::from("{\"type\":\"FeatureCollection\",\"features\":[\n");
        t.push_str(&features.join(",\n"));
        t.push_str("\n]}\n");
        t
    }

    const AREA: &str = r#"{"type":"Feature","properties":{"id":"a","kind":"area","t0":1,"tf":2},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
    const TRACK: &str = r#"{"type":"Feature","properties":{"id":"t","kind":"track","speed_kn":10,"front_nm":1,"back_nm":1,"side_nm":1},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#;

    /// The error of the middle feature (line 3) between two good ones, whose reading is
    /// checked too.
    fn middle(bad: &str) -> ScenarioError {
        let good2 = TRACK.replace(r#""id":"t""#, r#""id":"t2""#);
        let r = parse(&file(&[AREA, bad, &good2])).expect("a collection");
        let ids: Vec<&str> = r.scenario.features.iter().map(|f| f.id.as_str()).collect();
        assert_eq!(ids, ["a", "t2"], "the good features are still read: {bad}");
        assert_eq!(r.errors.len(), 1, "{:?}", r.errors);
        r.errors[0].clone()
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
                AREA.replace(r#""type":"Polygon","#, r#""type":"Polygon","coords":1,"#)
                    .replace(r#""id":"a""#, r#""id":"x""#),
                "geometry.coords",
                "unknown member",
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

    /// GeoJSON's properties are open: a member the format does not define is kept (and
    /// written back), listed as a warning with its line, and changes nothing.
    #[test]
    fn open_properties_are_kept_with_a_warning() {
        let coloured = AREA.replace(r#""tf":2"#, r#""tf":2,"colour":"red""#);
        let r = parse(&file(&[&coloured, TRACK])).expect("collection");
        assert!(r.errors.is_empty(), "{:?}", r.errors);
        assert_eq!(r.warnings.len(), 1);
        assert_eq!(
            r.warnings[0].to_string(),
            "line 2: feature 0 (id \"a\"), properties.colour: not defined by the scenario \
             format; kept, not read"
        );
        assert_eq!(
            r.scenario.features[0].extra.get("colour"),
            Some(&Value::from("red"))
        );
        let plain = parse(&file(&[AREA, TRACK])).expect("collection");
        assert_eq!(plain.scenario.features[0].kind, r.scenario.features[0].kind);
        let again = parse(&to_geojson(&r.scenario).to_string()).expect("collection");
        assert_eq!(again.scenario, r.scenario);
    }

    /// Either winding is read (RFC 7946) and kept counterclockwise, by both paths.
    #[test]
    fn either_winding_reads_counterclockwise() {
        let ccw = parse(&file(&[AREA])).expect("collection");
        let cw_text =
            file(&[&AREA.replace("[[0,0],[1,0],[1,1],[0,0]]", "[[0,0],[1,1],[1,0],[0,0]]")]);
        let cw = parse(&cw_text).expect("collection");
        assert!(cw.errors.is_empty() && ccw.errors.is_empty());
        let (Kind::Area(a), Kind::Area(b)) = (
            &ccw.scenario.features[0].kind,
            &cw.scenario.features[0].kind,
        ) else {
            panic!("areas");
        };
        let turn = |r: &[LonLat]| {
            let p: Vec<polyguard::vect2::Vect2> = r
                .iter()
                .map(|q| polyguard::vect2::Vect2::new(q.lon, q.lat))
                .collect();
            polyguard::ring::winding(&p)
        };
        assert_eq!(
            turn(&a.shapes[0].ring),
            Ok(polyguard::ring::Winding::Counterclockwise)
        );
        assert_eq!(
            turn(&b.shapes[0].ring),
            Ok(polyguard::ring::Winding::Counterclockwise)
        );
        assert_eq!(
            fast_parse(&cw_text),
            Some(parse_general(&cw_text).expect("collection"))
        );
    }

    /// `null` is absent everywhere, also for the other kind's properties, on both paths
    /// (the fast path read `"tf": null` on a track, the general one refused it; found by
    /// comparing the JSON Schema with the reader).
    #[test]
    fn null_is_absent_on_both_paths() {
        let track = TRACK.replace(r#""side_nm":1"#, r#""side_nm":1,"tf":null"#);
        let area = AREA.replace(r#""tf":2"#, r#""tf":2,"speed_kn":null"#);
        for text in [file(&[&track]), file(&[&area])] {
            let general = parse_general(&text).expect("collection");
            assert!(general.errors.is_empty(), "{:?}", general.errors);
            assert_eq!(fast_parse(&text), Some(general));
        }
    }

    /// File-level problems: the line, and a clear reason.
    #[test]
    fn file_level_errors_say_where() {
        let e = parse("{\"type\":\"FeatureCollection\",\n\"features\":[1,]}").expect_err("syntax");
        assert_eq!(e.line, Some(2));
        assert!(
            e.to_string()
                .starts_with("line 2: (file): not valid JSON: expected a value"),
            "{e}"
        );
        let e = parse("{\"type\":\"FeatureCollection\",\"feature\":[]}").expect_err("typo");
        assert_eq!(
            e.to_string(),
            "line 1: feature: unknown member; did you mean features?"
        );
        let mercator = "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\
            \"properties\":{\"name\":\"EPSG:3857\"}},\"features\":[]}";
        assert!(matches!(
            parse(mercator).expect_err("crs").problem,
            Problem::UnsupportedCrs(_)
        ));
        let crs84 = mercator.replace("EPSG:3857", "urn:ogc:def:crs:OGC:1.3:CRS84");
        assert!(parse(&crs84).is_ok());
        // a byte-order mark is not part of the text
        let bom = format!("\u{feff}{}", file(&[AREA]));
        let r = parse(&bom).expect("collection");
        assert_eq!(r.scenario.features.len(), 1);
        let bad_bom = format!("\u{feff}{}", file(&[AREA, "{\"type\":\"Feature\"}"]));
        let r = parse(&bad_bom).expect("collection");
        assert_eq!(r.errors[0].line, Some(3));
    }

    /// What cannot be read one way only is an error, never a silent misreading: a step of
    /// exactly 180° of longitude (east or west?), a ring that circles a pole or spans a
    /// whole turn, a step longer than 180° on the unrolled plane (where longitudes do not
    /// wrap), holes (not modelled yet).
    #[test]
    fn what_is_ambiguous_or_not_modelled_is_refused() {
        let cases = [
            (
                TRACK.replace("[[0,0],[1,1]]", "[[179.5,0],[-0.5,1]]"),
                "geometry.coordinates[1]",
                "positions 0 and 1 are exactly 180° of longitude apart",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,60],[120,60],[-120,60],[0,60]]]",
                ),
                "geometry.coordinates[0]",
                "the ring circles a pole",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[170,0],[340,0],[20,1],[-150,2],[40,3],[0,3],[0,0]]]",
                ),
                "geometry.coordinates[0]",
                "spans 380° of longitude, a whole turn or more",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[1,1],[4,1],[4,2],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "meets ring 0 of the polygon: edge 0→1 of this ring and edge 1→2",
            ),
            (
                // a hole touching the exterior at one point is refused too
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[1,1],[3,2],[1,2],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "meets ring 0 of the polygon",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[4,1],[5,1],[5,2],[4,1]]]",
                ),
                "geometry.coordinates[1]",
                "does not lie inside the polygon's exterior ring",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[9,0],[9,9],[0,9],[0,0]],[[1,1],[1,8],[8,8],[8,1],[1,1]],\
                     [[2,2],[2,3],[3,3],[2,2]]]",
                ),
                "geometry.coordinates[2]",
                "this hole and hole 1 of the polygon lie one inside the other",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[9,0],[9,9],[0,9],[0,0]],[[1,1],[3,3],[3,1],[1,3],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "edges 0–1 and 2–3 cross",
            ),
            (
                AREA.replace(r#""type":"Polygon""#, r#""type":"MultiPolygon""#)
                    .replace(
                        "[[[0,0],[1,0],[1,1],[0,0]]]",
                        "[[[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6]]]]",
                    ),
                "geometry.coordinates[1][0]",
                "ring not closed",
            ),
            (
                AREA.replace(r#""type":"Polygon""#, r#""type":"Point""#),
                "geometry.type",
                "expected Polygon or MultiPolygon",
            ),
        ];
        for (bad, field, message) in cases {
            let bad = bad
                .replace(r#""id":"a""#, r#""id":"x""#)
                .replace(r#""id":"t""#, r#""id":"x""#);
            let e = middle(&bad);
            assert_eq!((e.line, e.field.as_str()), (Some(3), field), "{bad}");
            assert!(e.to_string().contains(message), "{e}");
        }
        // the unrolled plane: a long step is an error, the file's other features are read
        let unrolled = |feats: &[&str]| {
            file(feats).replacen(
                "\"type\":\"FeatureCollection\",",
                "\"type\":\"FeatureCollection\",\"longitudes\":\"unrolled\",",
                1,
            )
        };
        let long = TRACK
            .replace("[[0,0],[1,1]]", "[[179.5,0],[-179.5,0]]")
            .replace(r#""id":"t""#, r#""id":"x""#);
        let r = parse(&unrolled(&[AREA, &long])).expect("a collection");
        assert_eq!(r.scenario.longitudes, Longitudes::Unrolled);
        assert_eq!(r.scenario.features.len(), 1);
        assert!(
            r.errors[0]
                .to_string()
                .contains("more than 180° of longitude apart"),
            "{}",
            r.errors[0]
        );
        // an unknown value is a file error naming the member
        let bad = file(&[AREA]).replacen(
            "\"type\":\"FeatureCollection\",",
            "\"type\":\"FeatureCollection\",\"longitudes\":\"flat\",",
            1,
        );
        let e = parse(&bad).expect_err("a file error");
        assert_eq!(e.field, "longitudes");
        assert!(
            e.to_string()
                .contains("\"earth\" (the default) or \"unrolled\""),
            "{e}"
        );
    }

    /// On the Earth a step across the antimeridian is read the shorter way (1°, not 359°),
    /// east-bound or west-bound; a longitude beyond ±180° names the same place as its
    /// value in (−180, 180], with a warning naming the position; and the scenario is
    /// written back with longitudes in (−180, 180] that read the same.
    #[test]
    fn longitudes_on_the_earth() {
        let track = |coords: &str| {
            TRACK
                .replace("[[0,0],[1,1]]", coords)
                .replace(r#""id":"t""#, r#""id":"x""#)
        };
        for (coords, lons) in [
            ("[[179.5,0],[-179.5,0]]", [179.5, 180.5]),
            ("[[-179.5,0],[179.5,0]]", [-179.5, -180.5]),
            ("[[-180,0],[179,0]]", [180.0, 179.0]),
            ("[[540.5,0],[-178.5,0]]", [-179.5, -178.5]),
        ] {
            let r = parse(&file(&[&track(coords)])).expect("a collection");
            assert!(r.errors.is_empty(), "{coords}: {:?}", r.errors);
            let Kind::Track(t) = &r.scenario.features[0].kind else {
                panic!("a track")
            };
            let got: Vec<f64> = t.waypoints.iter().map(|p| p.to_degrees().0).collect();
            assert_eq!(got, lons, "{coords}");
            // the leg is 1° of longitude long, on the equator
            let legs = sphere::track_legs(&t.waypoints, t.speed_kn, t.t0, t.dims);
            assert_eq!(legs.len(), 1, "{coords}: {:?}", t.waypoints);
            let nm = legs[0].length_nm;
            assert!((nm - 60.04).abs() < 0.01, "{coords}: {nm} nm");
        }
        let r = parse(&file(&[&track("[[190,0],[191,1]]")])).expect("a collection");
        assert_eq!(r.warnings.len(), 1, "{:?}", r.warnings);
        let w = r.warnings[0].to_string();
        assert!(
            w.contains("geometry.coordinates[0]: longitude 190 is beyond ±180°; read as -170"),
            "{w}"
        );
        let Kind::Track(t) = &r.scenario.features[0].kind else {
            panic!("a track")
        };
        assert_eq!(t.waypoints[0].to_degrees().0, -170.0);
        // written back in (−180, 180], read back the same
        let across = parse(&file(&[&track("[[179.5,0],[-179.5,0]]")])).expect("a collection");
        let text = to_geojson(&across.scenario).to_string();
        assert!(text.contains("[-179.5,0.0]"), "{text}");
        let again = parse(&text).expect("a collection");
        assert_eq!(again.scenario, across.scenario);
    }
}
