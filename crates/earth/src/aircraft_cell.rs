//! Paper A (Narkawicz & Hagen) on the Earth: does an aircraft come within BUFF nautical
//! miles of a drifting weather cell during `[0, T]`?
//!
//! Paper A's `detect_same_2D` (§II.H) works on a plane, with linear motion `s + t·v` and
//! vertices `p_i + t·V`. This module takes the Earth's own quantities (positions in
//! degrees, courses, ground speeds in knots, BUFF in nautical miles), projects them with
//! paper B's Mercator (§V, eqs 25–26: [`crate::sphere`], [`crate::geodesy`]) and makes the
//! engine's "no" a certain statement about the Earth:
//!
//! > **If [`detect_earth`] answers no, the aircraft is never within `buff_nm` nautical
//! > miles (great-circle distance on the model sphere; geodesic distance on WGS84 with
//! > [`Geodesy::Wgs84`]) of the cell at any time of `[0, T]`.**
//!
//! # The model (docs/earth-cases.md)
//! The aircraft starts at `pos` and flies a rhumb line (constant course) at constant
//! ground speed. The cell is a ring of vertices whose edges are rhumb lines (straight on
//! the Mercator plane, as in docs/scenario.md); it drifts: every vertex moves along its
//! own rhumb line with the cell's course and speed. At each instant the cell is the
//! region those edges bound.
//!
//! # Why the Mercator plane is not paper A's plane, and what is added
//! Mercator is conformal but not isometric: near latitude φ a distance `d` on the sphere
//! is `d·sec φ / R` on the plane (paper B §V). And constant-speed motion along a rhumb line
//! is straight there but not uniform: the ordinate is `Ψ(u(t))` with the model latitude `u`
//! linear in t, and `Ψ` is not linear. So the case handed to the engine is a stand-in
//! with a grown buffer, on pieces `[t_a, t_b]` of `[0, T]`:
//!
//! - **the point** `s + τ·v` interpolates the aircraft's projected positions at `t_a` and
//!   `t_b`. It moves along the same Mercator line as the aircraft; the distance between
//!   them is `|f(t) − lin(t)| / |cos θ|` with `f = Ψ∘u`, `f'' = Ψ''(u)·u'²`,
//!   `u' = s cos θ / R_u` and `|Ψ''| ≤ sec Φ tan Φ` at the largest |latitude| Φ of the
//!   piece ([`Geodesy::sec_tan_bound`]): at most `h²/8 · (s/R_u)² · |cos θ| · sec Φ tan Φ`
//!   ([`rhumb_deviation`]);
//! - **the cell** is made statically shaped (one velocity `V̄` for every vertex), because
//!   only `detect_same_2D` answers yes for every approach within BUFF (§II.G–H;
//!   `detect_diff_2D` of §II.I detects edge crossings, its BUFF acts at t = 0 only). Each
//!   vertex's own interpolation (displacement `D_i` over the piece) deviates from its
//!   motion as the point's does; the common displacement `D̄` is the mid-range of the
//!   `D_i`, and the stand-in vertex starts at `R_i(t_a) + (D_i − D̄)/2`, so it lies within
//!   `|D_i − D̄|/2` of the vertex's interpolation throughout the piece. A polygon whose
//!   vertices all lie within δ of another's (the second simple) has every point of its
//!   closed region within δ of the other's region (follow `P + σ(P' − P)`, σ from 0 to 1:
//!   a point inside P and outside P' is on the boundary of some intermediate polygon,
//!   within δ of the boundary of P'), so the cell moves by at most that much;
//! - **the buffer**: a great-circle path of length `L < BUFF` from the aircraft reaches at
//!   most `BUFF/R` of latitude beyond the aircraft's, so its image on the plane is at most
//!   `L · sec Φ_b / R` long with `Φ_b = max |φ_aircraft| + BUFF/R` over the piece (sec grows
//!   with |φ|: the largest is the conservative one). On WGS84 the Mercator scale is
//!   `1/(N cos φ) ≤ sec φ / a` and a path of length L changes latitude by at most
//!   `L / (a(1 − e²))` (the smallest meridian radius);
//! - **rounding**: each projected position is within [`position_slack`] of its exact value
//!   (paper B §V's stated bound), and the stand-in's few operations add far less; four
//!   slacks are added (plus, on WGS84, 4·10⁻¹⁰ rad for Helmert's series, 0.1 mm).
//!
//! The buffer handed to the engine is the sum, times [`BOUND_SAFETY`]:
//! `BUFF_merc = BUFF sec Φ_b / R + dev_point + max_i (dev_i + |D_i − D̄|/2) + rounding`.
//! If the aircraft is within BUFF of the cell at some t, the stand-in point is within
//! less than `BUFF_merc` of the stand-in cell at the same τ = t − t_a, paper A answers yes
//! (§II.H: `segments_close` holds, or the point is not `definitely_outside` at τ = 0) and
//! the certified engine answers yes whenever paper A without rounding does (the engine's
//! contract). Pieces are chosen so that the deviation terms stay small next to BUFF and
//! the aircraft's latitude changes by at most a quarter degree in each ([`Pieces::Auto`]).
//!
//! The price is false alarms: an approach up to about `BUFF_merc · R cos φ` nm at the
//! aircraft's latitude φ alarms ([`EarthAnswer::effective_buff_nm`]); measured in
//! docs/earth-cases.md.
//!
//! # The antimeridian and the poles
//! Longitudes are unwrapped onto one branch around the aircraft's start: the first
//! vertex within 180° of it, each next vertex the shorter way from the previous one (two
//! exactly 180° apart are an error, as in docs/scenario.md), and the motion continues
//! without wrapping. The whole encounter (the aircraft and every vertex at 0 and T) must
//! span less than 180° of longitude, so no other copy of the cell (a whole turn away) can
//! come near the aircraft. Latitudes are within ±85° at t = 0 and at T (the format's limit,
//! [`MAX_LAT_DEG`]; a rhumb line's latitude is monotone in t, so also in between) and
//! `Φ_b` must stay below [`MAX_BUFF_LAT_DEG`]. A path shorter than BUFF moves at most
//! `BUFF sec Φ_b / R` in x, and that reach plus the span must stay below 180°, so such a
//! path from the aircraft meets no copy of the cell a whole turn away.

use core::fmt;

use crate::geodesy::{Geodesy, METRES_PER_NM, WGS84_A_M, WGS84_F};
use crate::sphere::{position_slack, LonLat, Merc, BOUND_SAFETY, EARTH_RADIUS_NM};
use polyguard::api::{self, Case, Kind, MovingPoint, MovingPolygon, Params};
use polyguard::ring::{self, RingFault, Winding};
use polyguard::{Tri, Vect2};

/// The format's latitude limit (degrees), as docs/scenario.md: the Mercator plane
/// stretches without bound towards the poles.
pub const MAX_LAT_DEG: f64 = 85.0;
/// The limit (degrees) of `Φ_b`, the largest latitude a path shorter than BUFF from the
/// aircraft can reach; sec Φ_b is 57 there.
pub const MAX_BUFF_LAT_DEG: f64 = 89.0;
/// The most pieces [`Pieces::Auto`] cuts `[0, T]` into.
pub const MAX_PIECES: usize = 4096;
/// [`Pieces::Auto`]: the deviation terms are kept below this fraction of `BUFF / R`.
const AUTO_DEVIATION_SHARE: f64 = 0.05;
/// [`Pieces::Auto`]: the aircraft's latitude changes by at most this much (radians,
/// a quarter degree) within a piece, so that sec Φ_b is taken near the encounter.
const AUTO_PIECE_DLAT: f64 = 0.25 * core::f64::consts::PI / 180.0;
/// On WGS84, the rhumb motion's model error (Helmert's series to n⁴: 0.1 mm of meridian
/// distance, 1.6·10⁻¹¹ rad of latitude, times g ≤ sec 85° ≈ 11.5 on the ordinate) with room.
const WGS84_MODEL_RAD: f64 = 4e-10;

/// A constant course and ground speed: motion along a rhumb line (paper B §V, eqs 23–24).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Course, degrees clockwise from true north (any finite value; taken modulo 360).
    pub course_deg: f64,
    /// Ground speed, knots (≥ 0).
    pub speed_kn: f64,
}

/// One encounter on the Earth (docs/earth-cases.md): paper A's T, BUFF, point and
/// polygon (§II) in degrees, nautical miles, knots and hours.
#[derive(Clone, Debug, PartialEq)]
pub struct EarthCase {
    /// T, hours (> 0).
    pub lookahead_h: f64,
    /// BUFF, nautical miles (> 0).
    pub buff_nm: f64,
    /// The aircraft at t = 0: `[longitude, latitude]`, degrees.
    pub aircraft_pos: [f64; 2],
    /// The aircraft's course and ground speed.
    pub aircraft: Motion,
    /// The cell's ring at t = 0, `[longitude, latitude]` degrees, either winding, not
    /// closed (the first vertex is not repeated); edges are rhumb lines.
    pub cell_vertices: Vec<[f64; 2]>,
    /// The cell's drift: every vertex moves with this course and speed.
    pub cell: Motion,
}

/// How the buffer handed to the engine is made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Buffer {
    /// The certified buffer of the module doc (the product).
    #[default]
    Certified,
    /// The canary: `BUFF / R` alone, without sec Φ, the deviations or the rounding. It
    /// misses approaches at high latitude; the tests show that their check sees it.
    Unscaled,
}

/// How `[0, T]` is cut into pieces, each its own paper-A case.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Pieces {
    /// As many as keep the deviations under 5 % of `BUFF/R` and the aircraft's latitude
    /// change under 0.25° per piece, at most [`MAX_PIECES`].
    #[default]
    Auto,
    /// Exactly this many (≥ 1).
    Fixed(usize),
}

/// Options of [`detect_earth_with`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// The model of the Earth (motion, Mercator, distances).
    pub geodesy: Geodesy,
    /// The buffer (certified, or the canary).
    pub buffer: Buffer,
    /// How `[0, T]` is cut.
    pub pieces: Pieces,
}

/// The answer of [`detect_earth`].
#[derive(Clone, Debug, PartialEq)]
pub struct EarthAnswer {
    /// The aircraft may come within BUFF of the cell (certainly not, when false).
    pub detected: bool,
    /// `Exact` when every comparison behind the answer was certified, `Conservative` for
    /// a yes taken on an undecided one (the engine's [`Kind`]).
    pub kind: Kind,
    /// The first of `separation_windows_h`: when the aircraft may first be within BUFF.
    pub alarm_window_h: Option<[f64; 2]>,
    /// Certified windows of loss of separation (hours, sorted, disjoint): at every time
    /// at which the aircraft is within BUFF of the cell it is in one of them. Each is the
    /// hull of the engine's near spans (docs/cases.md) of a piece's stand-in case, whose
    /// grown buffer makes it a little wider than the exact interval on the Earth.
    pub separation_windows_h: Vec<[f64; 2]>,
    /// How many pieces `[0, T]` was cut into.
    pub pieces: usize,
    /// The largest buffer handed to the engine (Mercator radians).
    pub buff_merc_max: f64,
    /// The largest, over the pieces, of that buffer in nautical miles at the lowest
    /// latitude the aircraft reaches in the piece (`BUFF_merc · R cos φ`): roughly how far
    /// away a cell can be and still raise an alarm. At least `buff_nm`.
    pub effective_buff_nm: f64,
    /// The cell was given clockwise and was read in the reverse order.
    pub reversed: bool,
}

/// What is wrong with an [`EarthCase`].
#[derive(Clone, Debug, PartialEq)]
pub enum EarthErrorKind {
    /// NaN or ±∞.
    NotFinite,
    /// Must be > 0.
    NotPositive {
        /// The value given.
        value: f64,
    },
    /// Must be ≥ 0.
    Negative {
        /// The value given.
        value: f64,
    },
    /// Outside its range.
    OutOfRange {
        /// The value given.
        value: f64,
        /// The range, for the message.
        range: &'static str,
    },
    /// A ring of fewer than 3 vertices.
    TooFewVertices {
        /// How many there are.
        found: usize,
    },
    /// Two consecutive vertices exactly 180° of longitude apart: the edge could run
    /// either way round.
    HalfTurnApart {
        /// The first vertex's index.
        a: usize,
        /// The second's.
        b: usize,
    },
    /// Joined the shorter way, the ring does not close within 180° of longitude (it
    /// circles a pole or spans half the Earth).
    CirclesPole,
    /// A mover reaches beyond [`MAX_LAT_DEG`] by t = T.
    LeavesLatitudeLimit {
        /// Its latitude at T, degrees.
        lat_deg: f64,
    },
    /// A path shorter than BUFF from the aircraft could reach beyond [`MAX_BUFF_LAT_DEG`].
    BufferTooLarge {
        /// That latitude, degrees.
        lat_deg: f64,
    },
    /// The encounter spans 180° of longitude or more (unwrapped, with the reach of BUFF
    /// on the Mercator plane, `BUFF sec Φ_b / R`).
    TooWide {
        /// Its span, degrees.
        span_deg: f64,
    },
    /// The projected ring is not simple: edges `a` and `b` (vertex indices as given).
    Crossing {
        /// One edge.
        a: (usize, usize),
        /// The edge it meets.
        b: (usize, usize),
    },
    /// All vertices on one rhumb line.
    ZeroArea,
    /// The ring is too extreme for the exact checks.
    NotCheckable,
    /// Course bands (`crate::bands`): some course reaches beyond [`MAX_LAT_DEG`] within
    /// the lookahead (|latitude| + speed·T/R).
    CoursesReach {
        /// That latitude, degrees.
        lat_deg: f64,
    },
    /// Certified on the sphere model only (course bands: `crate::bands`).
    SphereOnly {
        /// What is asked.
        what: &'static str,
    },
    /// The projected cell stops being a simple polygon during the lookahead.
    NotSimpleAt {
        /// The start of the piece where it fails (hours).
        t_h: f64,
    },
}

/// An [`EarthErrorKind`] and the field it is about (a path of docs/earth-cases.md, such
/// as `cell.vertices[2][1]`).
#[derive(Clone, Debug, PartialEq)]
pub struct EarthError {
    /// The field.
    pub field: String,
    /// What is wrong.
    pub kind: EarthErrorKind,
}

impl EarthError {
    /// An error of `kind` about `field`.
    pub(crate) fn new(field: impl Into<String>, kind: EarthErrorKind) -> Self {
        EarthError {
            field: field.into(),
            kind,
        }
    }
}

impl fmt::Display for EarthError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.field)?;
        match &self.kind {
            EarthErrorKind::NotFinite => write!(f, "not a finite number"),
            EarthErrorKind::CoursesReach { lat_deg } => write!(
                f,
                "a course of the bands reaches latitude {lat_deg:.4}° within the lookahead \
                 (|latitude| + speed·T/R), beyond the format's ±{MAX_LAT_DEG}°"
            ),
            EarthErrorKind::SphereOnly { what } => write!(
                f,
                "{what} are certified on the sphere model only (--geodesy sphere)"
            ),
            EarthErrorKind::NotPositive { value } => write!(f, "{value} is not > 0"),
            EarthErrorKind::Negative { value } => write!(f, "{value} is negative"),
            EarthErrorKind::OutOfRange { value, range } => write!(f, "{value} is outside {range}"),
            EarthErrorKind::TooFewVertices { found } => {
                write!(f, "{found} vertices, at least 3 are needed")
            }
            EarthErrorKind::HalfTurnApart { a, b } => write!(
                f,
                "vertices {a} and {b} are exactly 180° of longitude apart (the edge could run \
                 either way round): add a vertex between them"
            ),
            EarthErrorKind::CirclesPole => write!(
                f,
                "joined the shorter way round, the ring does not close: it circles a pole or \
                 spans 180° of longitude or more"
            ),
            EarthErrorKind::LeavesLatitudeLimit { lat_deg } => write!(
                f,
                "reaches latitude {lat_deg:.4}° by t = lookahead_h, beyond the format's \
                 ±{MAX_LAT_DEG}°"
            ),
            EarthErrorKind::BufferTooLarge { lat_deg } => write!(
                f,
                "a path of buff_nm from the aircraft could reach latitude {lat_deg:.4}°, beyond \
                 ±{MAX_BUFF_LAT_DEG}°"
            ),
            EarthErrorKind::TooWide { span_deg } => write!(
                f,
                "the encounter (aircraft and cell at 0 and T, and BUFF around the aircraft) \
                 spans {span_deg:.3}° of longitude; less than 180° is needed"
            ),
            EarthErrorKind::Crossing { a, b } => write!(
                f,
                "edges {}–{} and {}–{} meet (vertices numbered from 0); the cell must not \
                 touch or cross itself",
                a.0, a.1, b.0, b.1
            ),
            EarthErrorKind::ZeroArea => write!(f, "all vertices lie on one rhumb line"),
            EarthErrorKind::NotCheckable => {
                write!(f, "the ring is too extreme to check exactly")
            }
            EarthErrorKind::NotSimpleAt { t_h } => write!(
                f,
                "the drifting cell is not a simple polygon on the Mercator plane near \
                 t = {t_h} h"
            ),
        }
    }
}

impl std::error::Error for EarthError {}

/// The radii a model's bounds use (nautical miles): `R_u` of the motion, `R_s` of the
/// Mercator scale (`scale ≤ sec φ / R_s`) and `R_φ`, the smallest meridian radius
/// (a path of length L changes latitude by at most `L / R_φ`).
#[derive(Clone, Copy, Debug)]
struct Radii {
    motion: f64,
    scale: f64,
    lat: f64,
}

/// The radii of the model `geo` ([`Radii`]).
fn radii(geo: Geodesy) -> Radii {
    match geo {
        Geodesy::Sphere => Radii {
            motion: EARTH_RADIUS_NM,
            scale: EARTH_RADIUS_NM,
            lat: EARTH_RADIUS_NM,
        },
        Geodesy::Wgs84 => {
            let a = WGS84_A_M / METRES_PER_NM;
            let e2 = WGS84_F * (2.0 - WGS84_F);
            Radii {
                motion: geo.radius_nm(),
                scale: a,
                // rounded down a relative 1e-12: a smaller radius is the safe side
                lat: a * (1.0 - e2) * (1.0 - 1e-12),
            }
        }
    }
}

/// A mover of the encounter: a start (radians, longitude unwrapped) and a rhumb motion
/// (paper B §V, eqs 23–24).
#[derive(Clone, Copy, Debug)]
struct Mover {
    start: LonLat,
    course: f64,
    speed_kn: f64,
}

impl Mover {
    /// Paper B eqs 23–24 on the model: the position at time `t` (hours).
    fn at(&self, geo: Geodesy, t: f64) -> LonLat {
        if t == 0.0 {
            return self.start;
        }
        geo.rhumb_destination(self.start, self.course, self.speed_kn * t)
    }
}

/// Paper B §V differentiated twice (this module's extension): a bound on the distance,
/// on the Mercator plane, between a mover on a rhumb line over a piece of `h` hours and
/// the uniform motion between its projected ends, `h²/8 · (s/R_u)² · |cos θ| · sec Φ tan Φ`,
/// with Φ the geodetic latitude of `u_abs_max`, the largest |model latitude| of the piece
/// (module doc). Zero on an east–west course, where the motion is uniform.
pub fn rhumb_deviation(geo: Geodesy, speed_kn: f64, course: f64, u_abs_max: f64, h: f64) -> f64 {
    let (sec, tan) = geo.sec_tan_bound(u_abs_max);
    let w = speed_kn / radii(geo).motion;
    h * h / 8.0 * w * w * course.cos().abs() * sec * tan.abs() * BOUND_SAFETY
}

/// The shrunk buffer (Mercator radians, before the deviation and rounding terms) that
/// certifies an approach within `target_nm` for an aircraft at |latitude| ≥ `lat_lo`
/// (`crate::bands`, "Conflict on the Earth").
pub(crate) fn certain_buffer(geo: Geodesy, target_nm: f64, lat_lo: f64) -> f64 {
    let (n_max, k) = match geo {
        Geodesy::Sphere => (EARTH_RADIUS_NM, 1.0),
        Geodesy::Wgs84 => {
            let a = WGS84_A_M / METRES_PER_NM;
            let e2 = WGS84_F * (2.0 - WGS84_F);
            (
                a / (1.0 - e2).sqrt() * BOUND_SAFETY,
                1.0 / (1.0 - e2) * BOUND_SAFETY,
            )
        }
    };
    let m0 = target_nm / (n_max * lat_lo.cos()) * BOUND_SAFETY;
    // along the segment |φ| ≥ φ_lo − k·m₀, so dφ/dψ ≤ k·cos(φ_lo − k·m₀): a second,
    // tighter bound on the latitude lost
    let k2 = k * (lat_lo - k * m0).max(0.0).cos() * BOUND_SAFETY;
    let low = (lat_lo - k2 * m0).max(0.0);
    target_nm / (n_max * low.cos()) / BOUND_SAFETY / BOUND_SAFETY
}

/// `x`, when finite (docs/earth-cases.md).
fn finite(field: &str, x: f64) -> Result<f64, EarthError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(EarthError::new(field, EarthErrorKind::NotFinite))
    }
}

/// A position `[lon, lat]` within the format's ranges (docs/earth-cases.md).
fn position(field: &str, p: [f64; 2]) -> Result<(), EarthError> {
    let lon = finite(&format!("{field}[0]"), p[0])?;
    let lat = finite(&format!("{field}[1]"), p[1])?;
    if !(-180.0..=180.0).contains(&lon) {
        return Err(EarthError::new(
            format!("{field}[0]"),
            EarthErrorKind::OutOfRange {
                value: lon,
                range: "[-180, 180] degrees of longitude",
            },
        ));
    }
    if !(-MAX_LAT_DEG..=MAX_LAT_DEG).contains(&lat) {
        return Err(EarthError::new(
            format!("{field}[1]"),
            EarthErrorKind::OutOfRange {
                value: lat,
                range: "[-85, 85] degrees of latitude",
            },
        ));
    }
    Ok(())
}

/// A course and a ground speed: finite, the speed not negative (docs/earth-cases.md).
fn motion(field: &str, m: Motion) -> Result<(), EarthError> {
    finite(&format!("{field}.course_deg"), m.course_deg)?;
    let s = finite(&format!("{field}.speed_kn"), m.speed_kn)?;
    if s < 0.0 {
        return Err(EarthError::new(
            format!("{field}.speed_kn"),
            EarthErrorKind::Negative { value: s },
        ));
    }
    Ok(())
}

/// The format's rules on one case (docs/earth-cases.md), each error naming its field.
fn validate(case: &EarthCase) -> Result<(), EarthError> {
    let t = finite("lookahead_h", case.lookahead_h)?;
    if t <= 0.0 {
        return Err(EarthError::new(
            "lookahead_h",
            EarthErrorKind::NotPositive { value: t },
        ));
    }
    let b = finite("buff_nm", case.buff_nm)?;
    if b <= 0.0 {
        return Err(EarthError::new(
            "buff_nm",
            EarthErrorKind::NotPositive { value: b },
        ));
    }
    position("aircraft.pos", case.aircraft_pos)?;
    motion("aircraft", case.aircraft)?;
    if case.cell_vertices.len() < 3 {
        return Err(EarthError::new(
            "cell.vertices",
            EarthErrorKind::TooFewVertices {
                found: case.cell_vertices.len(),
            },
        ));
    }
    for (i, p) in case.cell_vertices.iter().enumerate() {
        position(&format!("cell.vertices[{i}]"), *p)?;
    }
    motion("cell", case.cell)
}

/// `lon + 360·k` for the integer k that brings it within `[reference − 180, reference + 180)`.
fn unwrap_near(lon: f64, reference: f64) -> f64 {
    let k = ((reference - lon) / 360.0).round();
    let mut x = lon + 360.0 * k;
    if x - reference >= 180.0 {
        x -= 360.0;
    } else if x - reference < -180.0 {
        x += 360.0;
    }
    x
}

/// The cell's longitudes on the aircraft's branch: the first vertex within 180° of the
/// aircraft, each next the shorter way from the previous (docs/scenario.md's rule).
fn unwrap_ring(vertices: &[[f64; 2]], reference: f64) -> Result<Vec<f64>, EarthError> {
    let mut out: Vec<f64> = Vec::with_capacity(vertices.len());
    for (i, p) in vertices.iter().enumerate() {
        let x = match out.last() {
            None => unwrap_near(p[0], reference),
            Some(&prev) => {
                let x = unwrap_near(p[0], prev);
                if (x - prev).abs() == 180.0 {
                    return Err(EarthError::new(
                        "cell.vertices",
                        EarthErrorKind::HalfTurnApart { a: i - 1, b: i },
                    ));
                }
                x
            }
        };
        out.push(x);
    }
    let n = out.len();
    let closing = out[n - 1] - out[0];
    if closing.abs() == 180.0 {
        return Err(EarthError::new(
            "cell.vertices",
            EarthErrorKind::HalfTurnApart { a: n - 1, b: 0 },
        ));
    }
    if closing.abs() > 180.0 {
        return Err(EarthError::new(
            "cell.vertices",
            EarthErrorKind::CirclesPole,
        ));
    }
    Ok(out)
}

/// The cell's error for the exact ring check's fault.
fn ring_error(fault: RingFault) -> EarthError {
    let kind = match fault {
        RingFault::Crossing { a, b } => EarthErrorKind::Crossing { a, b },
        RingFault::ZeroArea => EarthErrorKind::ZeroArea,
        RingFault::NotCheckable => EarthErrorKind::NotCheckable,
    };
    EarthError::new("cell.vertices", kind)
}

/// `a − b` on the Mercator plane.
fn sub(a: Merc, b: Merc) -> Merc {
    [a[0] - b[0], a[1] - b[1]]
}

/// The length of `a` on the Mercator plane.
fn norm(a: Merc) -> f64 {
    a[0].hypot(a[1])
}

/// One piece's paper-A case and its buffer.
pub(crate) struct Piece {
    pub(crate) case: Option<Case>,
    pub(crate) buff_merc: f64,
    effective_nm: f64,
}

/// What a piece's buffer is for.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Role {
    /// Detection (module doc): grown, so that the stand-in's "no" is certain.
    Alarm(Buffer),
    /// The certified grown buffer of detection for another BUFF (`buff_nm`, > 0): a
    /// piece whose stand-in never comes within it keeps the aircraft `buff_nm` from the
    /// cell (crate::bands, a radius growing with time).
    Grown {
        /// The BUFF of this piece, nautical miles.
        buff_nm: f64,
    },
    /// A certain approach within `target_nm` (> 0): shrunk, so that the stand-in point
    /// certainly within the buffer of the stand-in cell puts the aircraft within
    /// `target_nm` of the cell (crate::bands, "Conflict on the Earth").
    Certain {
        /// The distance to certify, nautical miles.
        target_nm: f64,
    },
}

/// The encounter laid out on the unwrapped Mercator plane.
pub(crate) struct Layout {
    geo: Geodesy,
    radii: Radii,
    buff_nm: f64,
    aircraft: Mover,
    vertices: Vec<Mover>,
}

impl Layout {
    /// The largest geodetic |latitude| and the largest |model latitude| of a mover over
    /// `[ta, tb]` (u is linear in t and φ monotone in u: the ends).
    fn lat_extent(&self, a: LonLat, b: LonLat) -> (f64, f64) {
        let (ua, ub) = (self.geo.u_of_lat(a.lat), self.geo.u_of_lat(b.lat));
        (a.lat.abs().max(b.lat.abs()), ua.abs().max(ub.abs()))
    }

    /// `Φ_b`: the largest latitude a path shorter than BUFF from the aircraft reaches
    /// while the aircraft is between latitudes `a` and `b`.
    fn buffer_lat(&self, a: LonLat, b: LonLat) -> f64 {
        self.buffer_lat_of(a, b, self.buff_nm)
    }

    /// `Φ_b` for a BUFF of `buff_nm`.
    fn buffer_lat_of(&self, a: LonLat, b: LonLat, buff_nm: f64) -> f64 {
        a.lat.abs().max(b.lat.abs()) + buff_nm / self.radii.lat
    }

    /// The stand-in's buffer for `role` (module doc; `crate::bands` for `Certain`), the
    /// aircraft between `pa` and `pb`, at |latitude| ≥ `lo`, with `terms` the point's
    /// deviation, the cell's and the rounding (added in that order).
    fn buffer(&self, role: Role, pa: LonLat, pb: LonLat, lo: f64, terms: [f64; 3]) -> f64 {
        let [dev_air, cell_dev, rounding] = terms;
        let slack = dev_air + cell_dev + rounding;
        let grown = |buff_nm: f64| {
            let phi_b = self.buffer_lat_of(pa, pb, buff_nm);
            (buff_nm / (phi_b.cos() * self.radii.scale) + dev_air + cell_dev + rounding)
                * BOUND_SAFETY
        };
        match role {
            Role::Alarm(Buffer::Certified) => grown(self.buff_nm),
            Role::Grown { buff_nm } => grown(buff_nm),
            Role::Alarm(Buffer::Unscaled) => self.buff_nm / self.radii.scale,
            Role::Certain { target_nm } => {
                certain_buffer(self.geo, target_nm, lo) - slack * BOUND_SAFETY
            }
        }
    }

    /// Paper A §II.H's case for the piece `[ta, tb]` (module doc); the case is `None`
    /// when the stand-in cell is not a simple polygon (the caller falls back or fails).
    pub(crate) fn piece(&self, ta: f64, tb: f64, role: Role, mid_shape: bool) -> Piece {
        let geo = self.geo;
        let h = tb - ta;
        // The point: the aircraft's projected ends and their interpolation.
        let (pa, pb) = (self.aircraft.at(geo, ta), self.aircraft.at(geo, tb));
        let (sa, sb) = (geo.mercator(pa), geo.mercator(pb));
        let (_, u_air) = self.lat_extent(pa, pb);
        let dev_air = rhumb_deviation(geo, self.aircraft.speed_kn, self.aircraft.course, u_air, h);
        // The cell: each vertex's projected ends, displacements D_i, and their mid-range.
        let mut ra = Vec::with_capacity(self.vertices.len());
        let mut disp = Vec::with_capacity(self.vertices.len());
        let mut dev_v = Vec::with_capacity(self.vertices.len());
        let mut c = sa[0]
            .abs()
            .max(sa[1].abs())
            .max(sb[0].abs())
            .max(sb[1].abs());
        for v in &self.vertices {
            let (a, b) = (v.at(geo, ta), v.at(geo, tb));
            let (ma, mb) = (geo.mercator(a), geo.mercator(b));
            let (_, u) = self.lat_extent(a, b);
            dev_v.push(rhumb_deviation(geo, v.speed_kn, v.course, u, h));
            c = c
                .max(ma[0].abs())
                .max(ma[1].abs())
                .max(mb[0].abs())
                .max(mb[1].abs());
            ra.push(ma);
            disp.push(sub(mb, ma));
        }
        let mid = |k: usize| {
            let lo = disp.iter().map(|d| d[k]).fold(f64::INFINITY, f64::min);
            let hi = disp.iter().map(|d| d[k]).fold(f64::NEG_INFINITY, f64::max);
            0.5 * (lo + hi)
        };
        let dbar = [mid(0), mid(1)];
        // Stand-in vertices: at the mid-shape (within |D_i − D̄|/2 of each vertex's
        // interpolation), or at the shape at t_a (within |D_i − D̄|).
        let share = if mid_shape { 0.5 } else { 1.0 };
        let mut cell_dev: f64 = 0.0;
        let mut verts = Vec::with_capacity(ra.len());
        for ((r, d), dv) in ra.iter().zip(&disp).zip(&dev_v) {
            let off = sub(*d, dbar);
            cell_dev = cell_dev.max(dv + share * norm(off));
            let p = if mid_shape {
                [r[0] + 0.5 * off[0], r[1] + 0.5 * off[1]]
            } else {
                *r
            };
            c = c.max(p[0].abs()).max(p[1].abs());
            verts.push(Vect2::new(p[0], p[1]));
        }
        let rounding = 4.0 * position_slack(c)
            + match geo {
                Geodesy::Sphere => 0.0,
                Geodesy::Wgs84 => WGS84_MODEL_RAD,
            };
        // the lowest |latitude| of the aircraft in the piece (a rhumb line's latitude is
        // monotone in t)
        let lo = if pa.lat.signum() != pb.lat.signum() {
            0.0
        } else {
            pa.lat.abs().min(pb.lat.abs())
        };
        let buff_merc = self.buffer(role, pa, pb, lo, [dev_air, cell_dev, rounding]);
        if buff_merc.is_nan() || buff_merc <= 0.0 {
            return Piece {
                case: None,
                buff_merc: 0.0,
                effective_nm: 0.0,
            };
        }
        // nm per Mercator radian at the lowest |latitude| of the aircraft in the piece
        let effective_nm = buff_merc * self.radii.scale * lo.cos();
        // The engine covers [0, h'] with h' ≥ the exact t_b − t_a (h is within 2⁻⁵³ of it).
        let lookahead = h * (1.0 + 4.0 * f64::EPSILON);
        let vel = |d: Merc| Vect2::new(d[0] / h, d[1] / h);
        let case = MovingPoint::new_2d(Vect2::new(sa[0], sa[1]), vel(sub(sb, sa)))
            .and_then(|point| {
                let n = verts.len();
                let poly = MovingPolygon::new(verts, Some(vec![vel(dbar); n]))?;
                Case::new(lookahead, point, poly, Params::new(buff_merc)?)
            })
            .ok();
        Piece {
            case,
            buff_merc,
            effective_nm,
        }
    }
}

/// [`detect_earth_with`] with the default options on the model `geo`: the certified
/// buffer and automatic pieces.
pub fn detect_earth(case: &EarthCase, geo: Geodesy) -> Result<EarthAnswer, EarthError> {
    detect_earth_with(
        case,
        Options {
            geodesy: geo,
            ..Options::default()
        },
    )
}

/// Paper A §II.H (`detect_same_2D`) on the Earth through paper B §V's Mercator, with the
/// buffer grown so that "no" is certain (module doc).
pub fn detect_earth_with(case: &EarthCase, opts: Options) -> Result<EarthAnswer, EarthError> {
    let (layout, n, reversed) = prepare(case, opts.geodesy, opts.pieces)?;
    let mut answer = EarthAnswer {
        detected: false,
        kind: Kind::Exact,
        alarm_window_h: None,
        separation_windows_h: Vec::new(),
        pieces: n,
        buff_merc_max: 0.0,
        effective_buff_nm: 0.0,
        reversed,
    };
    decide_pieces(&layout, case.lookahead_h, opts.buffer, &mut answer)?;
    Ok(answer)
}

/// A case checked against the format's rules and limits and laid out (module doc), with
/// its number of pieces and whether the ring was reversed.
pub(crate) fn prepare(
    case: &EarthCase,
    geo: Geodesy,
    pieces: Pieces,
) -> Result<(Layout, usize, bool), EarthError> {
    validate(case)?;
    let (layout, order, reversed) = lay_out(case, geo)?;
    let air_end = within_reach(case, &layout, &order)?;
    let n = match pieces {
        Pieces::Fixed(n) => n.max(1),
        Pieces::Auto => auto_pieces(&layout, air_end, case.lookahead_h),
    };
    Ok((layout, n, reversed))
}

/// The ends of piece `j` of `n` of `[0, t_end]` (float times; the last ends at t_end).
pub(crate) fn piece_ends(t_end: f64, j: usize, n: usize) -> (f64, f64) {
    let ta = t_end * j as f64 / n as f64;
    let tb = if j + 1 == n {
        t_end
    } else {
        t_end * (j + 1) as f64 / n as f64
    };
    (ta, tb)
}

/// The module doc's layout: the movers on one branch of longitude around the aircraft's
/// start, and the ring at t = 0 checked exactly on the Mercator plane (simple) and made
/// counterclockwise. Also each mover's vertex index as given, and whether the ring was
/// reversed.
fn lay_out(case: &EarthCase, geo: Geodesy) -> Result<(Layout, Vec<usize>, bool), EarthError> {
    let ref_lon = case.aircraft_pos[0];
    let lons = unwrap_ring(&case.cell_vertices, ref_lon)?;
    let mut order: Vec<usize> = (0..lons.len()).collect();
    let course = |m: Motion| m.course_deg.rem_euclid(360.0).to_radians();
    let aircraft = Mover {
        start: LonLat::from_degrees(ref_lon, case.aircraft_pos[1]),
        course: course(case.aircraft),
        speed_kn: case.aircraft.speed_kn,
    };
    let mut vertices: Vec<Mover> = lons
        .iter()
        .zip(&case.cell_vertices)
        .map(|(&lon, p)| Mover {
            start: LonLat::from_degrees(lon, p[1]),
            course: course(case.cell),
            speed_kn: case.cell.speed_kn,
        })
        .collect();
    let ring0: Vec<Vect2> = vertices
        .iter()
        .map(|v| {
            let m = geo.mercator(v.start);
            Vect2::new(m[0], m[1])
        })
        .collect();
    let reversed = match ring::check(&ring0).map_err(ring_error)? {
        Winding::Counterclockwise => false,
        Winding::Clockwise => {
            vertices.reverse();
            order.reverse();
            true
        }
    };
    let layout = Layout {
        geo,
        radii: radii(geo),
        buff_nm: case.buff_nm,
        aircraft,
        vertices,
    };
    Ok((layout, order, reversed))
}

/// The module doc's limits on the whole encounter ("The antimeridian and the poles"):
/// every mover within [`MAX_LAT_DEG`] at T, `Φ_b` within [`MAX_BUFF_LAT_DEG`], and the
/// span of longitude with the reach of BUFF short of half a turn. `order` names each
/// vertex as given. The aircraft's position at T.
fn within_reach(case: &EarthCase, layout: &Layout, order: &[usize]) -> Result<LonLat, EarthError> {
    let (geo, t_end) = (layout.geo, case.lookahead_h);
    let check_end = |field: String, m: &Mover| -> Result<LonLat, EarthError> {
        let e = m.at(geo, t_end);
        let lat_deg = e.lat.to_degrees();
        if !lat_deg.is_finite() || lat_deg.abs() > MAX_LAT_DEG {
            return Err(EarthError::new(
                field,
                EarthErrorKind::LeavesLatitudeLimit { lat_deg },
            ));
        }
        Ok(e)
    };
    let aircraft = layout.aircraft;
    let air_end = check_end("aircraft".into(), &aircraft)?;
    let mut xs = vec![aircraft.start.lon, air_end.lon];
    for (k, v) in layout.vertices.iter().enumerate() {
        let e = check_end(format!("cell.vertices[{}]", order[k]), v)?;
        xs.push(v.start.lon);
        xs.push(e.lon);
    }
    let span = xs.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x))
        - xs.iter().fold(f64::INFINITY, |m, &x| m.min(x));
    if span.to_degrees() >= 180.0 {
        return Err(EarthError::new(
            "lookahead_h",
            EarthErrorKind::TooWide {
                span_deg: span.to_degrees(),
            },
        ));
    }
    let phi_b = layout.buffer_lat(aircraft.start, air_end);
    if phi_b.to_degrees() > MAX_BUFF_LAT_DEG {
        return Err(EarthError::new(
            "buff_nm",
            EarthErrorKind::BufferTooLarge {
                lat_deg: phi_b.to_degrees(),
            },
        ));
    }
    // A path shorter than BUFF moves at most BUFF sec Φ_b / R_s in x: with the span, it
    // must stay short of a whole turn's copy of the cell (module doc).
    let reach = case.buff_nm / (phi_b.cos() * layout.radii.scale);
    if span + reach >= core::f64::consts::PI {
        let field = if reach >= core::f64::consts::FRAC_PI_2 {
            "buff_nm"
        } else {
            "lookahead_h"
        };
        return Err(EarthError::new(
            field,
            EarthErrorKind::TooWide {
                span_deg: (span + reach).to_degrees(),
            },
        ));
    }
    Ok(air_end)
}

/// Paper A §II.H on each of the `answer.pieces` pieces of `[0, t_end]` (module doc): the
/// first yes sets the alarm; every piece's buffer is measured (the answer's largest).
fn decide_pieces(
    layout: &Layout,
    t_end: f64,
    buffer: Buffer,
    answer: &mut EarthAnswer,
) -> Result<(), EarthError> {
    let n = answer.pieces;
    for j in 0..n {
        let (ta, tb) = piece_ends(t_end, j, n);
        let mut piece = layout.piece(ta, tb, Role::Alarm(buffer), true);
        if piece.case.is_none() {
            piece = layout.piece(ta, tb, Role::Alarm(buffer), false);
        }
        let Some(pcase) = piece.case else {
            return Err(EarthError::new(
                "cell.vertices",
                EarthErrorKind::NotSimpleAt { t_h: ta },
            ));
        };
        answer.buff_merc_max = answer.buff_merc_max.max(piece.buff_merc);
        answer.effective_buff_nm = answer.effective_buff_nm.max(piece.effective_nm);
        add_windows(
            &pcase,
            ta,
            piece.buff_merc,
            &mut answer.separation_windows_h,
        );
        if answer.detected {
            continue;
        }
        let tri = api::decide(&pcase);
        if tri != Tri::No {
            answer.detected = true;
            answer.kind = if tri == Tri::Unsure {
                Kind::Conservative
            } else {
                Kind::Exact
            };
        }
    }
    answer.alarm_window_h = answer.separation_windows_h.first().copied();
    Ok(())
}

/// The next f64 below a time x ≥ 0 (0 stays 0).
fn below(x: f64) -> f64 {
    if x > 0.0 && x.is_finite() {
        f64::from_bits(x.to_bits() - 1)
    } else {
        x.max(0.0)
    }
}

/// The next f64 above a finite time x ≥ 0.
fn above(x: f64) -> f64 {
    if x.is_finite() && x >= 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        x
    }
}

/// The windows of loss of separation of one piece starting at `ta` (hours): the hulls
/// [start.lo, end.hi] of the engine's near spans (docs/cases.md) of the stand-in case
/// with D = its grown buffer, moved to the piece's start with outward rounding and merged
/// into `windows`. Certified: an aircraft within BUFF of the cell at t puts the stand-in
/// point within the buffer of the stand-in cell at τ = t − t_a (module doc), and the
/// spans miss no time of that set.
fn add_windows(pcase: &api::Case, ta: f64, buff_merc: f64, windows: &mut Vec<[f64; 2]>) {
    let sep = polyguard::Separation {
        d: buff_merc,
        h: 0.0,
    };
    for s in api::intervals(pcase, polyguard::Relation::Near, sep) {
        let w = [below(ta + s.start.lo), above(ta + s.end.hi)];
        match windows.last_mut() {
            Some(last) if w[0] <= last[1] => last[1] = last[1].max(w[1]),
            _ => windows.push(w),
        }
    }
}

/// [`Pieces::Auto`]: from the whole lookahead's deviation terms (quadratic in the piece's
/// length for the rhumb deviations, linear for the cell's spread of displacements) the
/// fewest pieces that keep them under 5 % of `BUFF/R`, and enough that the aircraft's
/// latitude changes by at most 0.25° in each.
fn auto_pieces(layout: &Layout, air_end: LonLat, t_end: f64) -> usize {
    let geo = layout.geo;
    let (_, u_air) = layout.lat_extent(layout.aircraft.start, air_end);
    let mut quad = rhumb_deviation(
        geo,
        layout.aircraft.speed_kn,
        layout.aircraft.course,
        u_air,
        t_end,
    );
    let mut lin: f64 = 0.0;
    let ends: Vec<(Merc, Merc, f64)> = layout
        .vertices
        .iter()
        .map(|v| {
            let (a, b) = (v.at(geo, 0.0), v.at(geo, t_end));
            let (_, u) = layout.lat_extent(a, b);
            (
                geo.mercator(a),
                geo.mercator(b),
                rhumb_deviation(geo, v.speed_kn, v.course, u, t_end),
            )
        })
        .collect();
    let dev_max = ends.iter().map(|e| e.2).fold(0.0, f64::max);
    quad += dev_max;
    let disp: Vec<Merc> = ends.iter().map(|(a, b, _)| sub(*b, *a)).collect();
    for k in 0..2 {
        let lo = disp.iter().map(|d| d[k]).fold(f64::INFINITY, f64::min);
        let hi = disp.iter().map(|d| d[k]).fold(f64::NEG_INFINITY, f64::max);
        lin = lin.hypot(0.5 * (hi - lo));
    }
    let target = AUTO_DEVIATION_SHARE * layout.buff_nm / layout.radii.scale;
    // smallest n with quad/n² + lin/n ≤ target
    let n_dev = (lin + (lin * lin + 4.0 * target * quad).sqrt()) / (2.0 * target);
    let dlat = (air_end.lat - layout.aircraft.start.lat).abs();
    let n_lat = dlat / AUTO_PIECE_DLAT;
    let n = n_dev.max(n_lat).ceil();
    if n.is_finite() {
        (n as usize).clamp(1, MAX_PIECES)
    } else {
        MAX_PIECES
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An aircraft flying east at `lat` towards a square cell 1° ahead, drifting north-east.
    fn square_case(lat: f64) -> EarthCase {
        EarthCase {
            lookahead_h: 1.0,
            buff_nm: 5.0,
            aircraft_pos: [-1.0, lat],
            aircraft: Motion {
                course_deg: 90.0,
                speed_kn: 240.0,
            },
            cell_vertices: vec![
                [0.0, lat - 0.2],
                [0.4, lat - 0.2],
                [0.4, lat + 0.2],
                [0.0, lat + 0.2],
            ],
            cell: Motion {
                course_deg: 45.0,
                speed_kn: 20.0,
            },
        }
    }

    #[test]
    fn unwrapping_takes_the_shorter_way() {
        let lons = unwrap_ring(&[[179.5, 0.0], [-179.5, 0.0], [-179.5, 1.0]], 170.0)
            .expect("a ring across the antimeridian");
        assert_eq!(lons, vec![179.5, 180.5, 180.5]);
        let lons = unwrap_ring(&[[179.5, 0.0], [-179.5, 0.0], [-179.5, 1.0]], -170.0)
            .expect("the same ring seen from the west");
        assert_eq!(lons, vec![-180.5, -179.5, -179.5]);
        let half = unwrap_ring(&[[0.0, 0.0], [180.0, 0.0], [90.0, 10.0]], 0.0);
        assert_eq!(
            half.map_err(|e| e.kind),
            Err(EarthErrorKind::HalfTurnApart { a: 0, b: 1 })
        );
        // around the pole: three steps of 120° each close a whole turn
        let pole = unwrap_ring(&[[0.0, 80.0], [120.0, 80.0], [-120.0, 80.0]], 0.0);
        assert_eq!(pole.map_err(|e| e.kind), Err(EarthErrorKind::CirclesPole));
    }

    #[test]
    fn the_deviation_bounds_sampled_rhumb_motion() {
        for geo in [Geodesy::Sphere, Geodesy::Wgs84] {
            for (lat, course) in [(0.0, 10.0), (45.0, 30.0), (70.0, 170.0), (-80.0, 200.0)] {
                let m = Mover {
                    start: LonLat::from_degrees(3.0, lat),
                    course: f64::to_radians(course),
                    speed_kn: 480.0,
                };
                let h = 0.5;
                let (a, b) = (m.at(geo, 0.0), m.at(geo, h));
                let (ma, mb) = (geo.mercator(a), geo.mercator(b));
                let u = geo.u_of_lat(a.lat).abs().max(geo.u_of_lat(b.lat).abs());
                let bound = rhumb_deviation(geo, m.speed_kn, m.course, u, h);
                let mut worst: f64 = 0.0;
                for i in 0..=200 {
                    let t = h * i as f64 / 200.0;
                    let r = geo.mercator(m.at(geo, t));
                    let l = [
                        ma[0] + (mb[0] - ma[0]) * t / h,
                        ma[1] + (mb[1] - ma[1]) * t / h,
                    ];
                    worst = worst.max(norm(sub(r, l)));
                }
                assert!(worst <= bound, "{geo:?} {lat} {course}: {worst} > {bound}");
                // and it is a bound of the right size, not a vacuous one
                assert!(
                    worst >= 0.5 * bound,
                    "{geo:?} {lat} {course}: {worst} ≪ {bound}"
                );
            }
        }
    }

    #[test]
    fn a_cell_ahead_is_detected_and_one_far_north_is_not() {
        let hit = detect_earth(&square_case(45.0), Geodesy::Sphere).expect("valid");
        assert!(hit.detected);
        let mut miss = square_case(45.0);
        for v in &mut miss.cell_vertices {
            v[1] += 1.0; // 60 nm north of the track
        }
        let a = detect_earth(&miss, Geodesy::Sphere).expect("valid");
        assert!(!a.detected, "{a:?}");
        assert!(a.effective_buff_nm >= 5.0);
    }

    #[test]
    fn each_rule_names_its_field() {
        let err = |f: &dyn Fn(&mut EarthCase)| {
            let mut c = square_case(45.0);
            f(&mut c);
            detect_earth(&c, Geodesy::Sphere)
                .map(|_| String::from("ok"))
                .unwrap_or_else(|e| e.to_string())
        };
        assert_eq!(err(&|c| c.lookahead_h = 0.0), "lookahead_h: 0 is not > 0");
        assert_eq!(
            err(&|c| c.buff_nm = f64::NAN),
            "buff_nm: not a finite number"
        );
        assert_eq!(
            err(&|c| c.cell_vertices[2][1] = 86.0),
            "cell.vertices[2][1]: 86 is outside [-85, 85] degrees of latitude"
        );
        assert_eq!(
            err(&|c| c.aircraft.speed_kn = -1.0),
            "aircraft.speed_kn: -1 is negative"
        );
        assert!(err(&|c| c.cell_vertices.swap(1, 2)).starts_with("cell.vertices: edges"));
        assert!(err(&|c| {
            c.aircraft_pos[1] = 84.0;
            c.aircraft.course_deg = 0.0;
        })
        .starts_with("aircraft: reaches latitude"));
        assert!(err(&|c| c.lookahead_h = 40.0).starts_with("lookahead_h: the encounter"));
        assert!(err(&|c| c.buff_nm = 3000.0).starts_with("buff_nm: a path"));
        assert!(err(&|c| c.buff_nm = 2500.0).starts_with("buff_nm: the encounter"));
        // clockwise is read reversed, with the same answer
        let mut cw = square_case(45.0);
        cw.cell_vertices.reverse();
        let a = detect_earth(&cw, Geodesy::Sphere).expect("clockwise is accepted");
        assert!(a.reversed && a.detected);
    }
}
