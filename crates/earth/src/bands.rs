//! Conflict-free bands on the Earth: which courses (degrees true) and which ground
//! speeds (knots) keep an aircraft BUFF nautical miles from a drifting cell over
//! `[0, T]`, certified between samples (paper A §II's detection through paper B §V's
//! rhumb motion and Mercator, as [`crate::aircraft_cell`]; the planar bands of
//! `polyguard::bands` on the Earth).
//!
//! # Definitions
//! An encounter of docs/earth-cases.md ([`EarthCase`]). The aircraft flies from its
//! position along the rhumb line of a course θ (degrees clockwise from true north) at a
//! ground speed σ (knots); the cell drifts as the case says. θ (or σ) is **in
//! conflict** when the aircraft comes within BUFF of the cell at some t ∈ [0, T]:
//! great-circle distance on the model sphere, geodesic distance on WGS84. A band answer
//! tiles [0°, 360°] (or [min, max] knots) into closed [`Band`]s, adjacent bands of one
//! kind merged:
//! - `Clear`: no value of the band is in conflict;
//! - `Conflict`: every value of the band is in conflict;
//! - `Unknown`: not decided; their total width is reported.
//!
//! # The certificate between samples
//! A cell [lo, hi] is sampled at its float midpoint m. For every value of the cell, the
//! aircraft's position at each t is within r nautical miles of the sample's:
//! - **speeds** at one course: both positions lie on one rhumb line, |σ − m|·t apart
//!   along it, so r = δ·T with δ the cell's half width (a path is never shorter than
//!   the distance between its ends, on either model);
//! - **courses** at one speed (the sphere): with L = σ·T, every position within the
//!   lookahead lies at most L/R of latitude from the start, |φ| ≤ Φ = |φ₀| + L/R. At a
//!   fixed distance d ≤ L along the rhumb line of course θ, φ = φ₀ + d·cos θ/R and
//!   λ = λ₀ + ∫₀^d sin θ / (R cos φ(u)) du, so the position's speed in θ has a north
//!   part d·|sin θ| and an east part R cos φ_d·|∂λ/∂θ|, at most the integral over
//!   [0, d] of (cos φ_d / cos φ(u))·(|cos θ| + (u/R)·sin²θ·tan Φ). With
//!   cos φ_d / cos φ(u) ≤ κ = 1 + L/(R cos Φ) (cos is 1-Lipschitz and
//!   |φ_d − φ(u)| ≤ (d − u)/R), the speed is at most κ·(1 + a)·L with
//!   a = L·tan Φ/(2R) (the sum of squares bounded with sin²θ + cos²θ = 1). Two courses
//!   |Δθ| apart are joined by the curve of positions over the courses between, never
//!   longer than |Δθ|·κ(1 + a)·L: r = δ·κ(1 + a)·L ([`course_spread_nm`]).
//!   Φ must stay below 85° (the format's limit): beyond, the lookahead's reach is refused.
//!
//! Both bounds grow with t: r(t) is the same with T replaced by t (L = σ·t), and on the
//! pieces [t_a, t_b] of detection ([`crate::aircraft_cell`]'s stand-ins, four times as
//! many) every time of a piece is within r(t_b). Then:
//! - **Clear**: every piece's grown stand-in for BUFF + r(t_b) (detection's certified
//!   buffer) has no span of near. Its near spans are certified (every time at which the
//!   aircraft is within BUFF + r(t_b) lies in one; they decide the distance itself,
//!   without paper A's detection margin), so the sample's aircraft is never within
//!   BUFF + r(t) of the cell, and by the triangle inequality (both distances are
//!   metrics, and a distance to a set is 1-Lipschitz) no value of the cell comes within
//!   BUFF.
//! - **Conflict**: in some piece with r(t_b) < BUFF, the shrunk stand-in below (target
//!   BUFF − r(t_b)) has a certain span of near: at that time the sample's aircraft is
//!   within BUFF − r(t_b) of the cell, so every value of the cell is within BUFF.
//!
//! # Conflict on the Earth: a certain approach
//! [`certain_within`] uses the pieces of [`crate::aircraft_cell`] with a shrunk buffer.
//! On the Mercator plane the distance element is ds = N cos φ·dm (N the prime-vertical
//! radius: R on the sphere, at most a/√(1 − e²) on WGS84), and along a straight
//! Mercator segment of length m the latitude changes by at most k·m (dφ/dψ = cos φ on the
//! sphere, at most 1/(1 − e²) on WGS84). So two points whose images are at most m apart,
//! one at |latitude| ≥ φ_lo, are at most N_max·cos(max(0, φ_lo − k·m))·m apart on the
//! Earth (the length of the rhumb line between them). For a target B, with
//! m₀ = B / (N_max cos φ_lo): the buffer is m = B / (N_max·cos(max(0, φ_lo − k₂·m₀))),
//! k₂ = k·cos(max(0, φ_lo − k·m₀)) (along a segment of length m ≤ m₀ the latitude stays
//! above φ_lo − k·m₀, where dφ/dψ ≤ k₂; m ≤ m₀ because the cosine used is at least
//! cos φ_lo). Then the latitude lost along the segment is at most k₂·m ≤ k₂·m₀ and
//! N_max·cos(max(0, φ_lo − k₂·m))·m ≤ B.
//! φ_lo is the lowest |latitude| of the aircraft in the piece. The stand-in point and
//! cell lie within the deviation and rounding terms of the true images (module doc of
//! [`crate::aircraft_cell`]); those are subtracted, and the rest divided by
//! [`BOUND_SAFETY`]. A certain span of near (docs/cases.md: near holds on all of
//! [start.hi, end.lo]) of that stand-in within the piece is a time at which the aircraft
//! is within B of the cell.
//!
//! # Rounding
//! The half width δ is rounded up (the next float above the larger difference of the
//! cell's ends from m), the course's conversion to radians adds 2⁻⁴⁷ rad (the model
//! converts m·π/180 with at most two roundings of an angle below 2π, under 2⁻⁴⁸ rad),
//! and r, BUFF + r and the shrunk buffers are multiplied or divided by [`BOUND_SAFETY`]
//! (1 + 10⁻⁹, far above the dozen roundings of each). No absolute tolerance enters.
//!
//! # Refinement
//! As `polyguard::bands` ([`refine`]): the fewest equal cells (a power of two, at most
//! [`FIRST_CELLS_MAX`]) whose r is below BUFF, then Unknown cells halved pass by pass
//! until the Unknown total is met. A sample the format refuses (a cell whose grown
//! buffer would reach past 89° of latitude, say) leaves its cell Unknown.

use polyguard::api;
use polyguard::bands::refine::{refine, CellTest};
use polyguard::bands::{BandKind, Bands};
use polyguard::{Relation, Separation};

use crate::aircraft_cell::{
    self, piece_ends, prepare, EarthCase, EarthError, EarthErrorKind, Motion, Pieces, Role,
};
use crate::geodesy::Geodesy;
use crate::sphere::{BOUND_SAFETY, EARTH_RADIUS_NM};

pub use polyguard::bands::{Band, BandKind as Kind};

/// The most cells a band answer starts with.
pub const FIRST_CELLS_MAX: usize = 1024;

/// The samples of a band answer cut `[0, T]` into this many times the pieces of
/// detection: the deviation terms, which widen the Unknown slivers, fall 16-fold.
const PIECE_FACTOR: usize = 4;

/// The format's latitude limit on the lookahead's reach (degrees).
const REACH_LAT_DEG: f64 = aircraft_cell::MAX_LAT_DEG;

/// 2⁻⁴⁷ rad: the model's conversion of a course in degrees to radians is within this of
/// the exact angle (module doc, "Rounding").
const COURSE_RAD_SLACK: f64 = 1.0 / 140_737_488_355_328.0;

/// r for courses on the sphere (module doc): the largest distance (nm) over `[0, t_h]`
/// between the aircraft on two courses at most `half_width_rad` apart, at `speed_kn`,
/// from latitude `lat0_rad`; `None` when the lookahead's reach passes 85° of latitude.
pub fn course_spread_nm(
    speed_kn: f64,
    t_h: f64,
    lat0_rad: f64,
    half_width_rad: f64,
) -> Option<f64> {
    let r = EARTH_RADIUS_NM;
    let l = speed_kn * t_h * BOUND_SAFETY;
    let phi = (lat0_rad.abs() + l / r) * BOUND_SAFETY;
    if phi.is_nan() || phi.to_degrees() > REACH_LAT_DEG {
        return None;
    }
    let kappa = 1.0 + l / (r * phi.cos()) * BOUND_SAFETY;
    let a = l * phi.tan() / (2.0 * r) * BOUND_SAFETY;
    Some(half_width_rad * kappa * (1.0 + a) * l * BOUND_SAFETY)
}

/// Is the aircraft certainly within BUFF of the cell at some time of `[0, T]`? A time
/// (hours, rounded) at which it is, or `None` when no piece certifies one (module doc,
/// "Conflict on the Earth"). The same errors as [`aircraft_cell::detect_earth`].
pub fn certain_within(case: &EarthCase, geo: Geodesy) -> Result<Option<f64>, EarthError> {
    let buff = case.buff_nm;
    certain_within_by(case, geo, 1, |_| buff)
}

/// The number of pieces: `factor` times detection's automatic number (at most
/// [`aircraft_cell::MAX_PIECES`]); the deviation terms shrink with the square of the
/// pieces' length.
fn pieces_of(auto: usize, factor: usize) -> usize {
    (auto * factor).min(aircraft_cell::MAX_PIECES)
}

/// [`certain_within`] with `factor` times the automatic pieces and, in the piece ending
/// at t_b, the target `target(t_b)` nm in place of BUFF (a piece whose target is not > 0
/// certifies nothing).
fn certain_within_by(
    case: &EarthCase,
    geo: Geodesy,
    factor: usize,
    target: impl Fn(f64) -> f64,
) -> Result<Option<f64>, EarthError> {
    let (layout, auto, _) = prepare(case, geo, Pieces::Auto)?;
    let n = pieces_of(auto, factor);
    for j in 0..n {
        let (ta, tb) = piece_ends(case.lookahead_h, j, n);
        let target_nm = target(tb);
        if target_nm.is_nan() || target_nm <= 0.0 {
            continue;
        }
        // the piece's exact length is within 2⁻⁵³ of tb − ta: a time below h·(1 − 2⁻⁵¹)
        // lies within it
        let h_in = (tb - ta) * (1.0 - 4.0 * f64::EPSILON);
        for mid_shape in [true, false] {
            let piece = layout.piece(ta, tb, Role::Certain { target_nm }, mid_shape);
            let Some(pcase) = piece.case else { continue };
            let sep = Separation {
                d: piece.buff_merc,
                h: 0.0,
            };
            let found = api::intervals(&pcase, Relation::Near, sep)
                .into_iter()
                .find(|s| s.certain && s.start.hi <= s.end.lo && s.start.hi <= h_in);
            if let Some(s) = found {
                return Ok(Some(ta + s.start.hi));
            }
            break;
        }
    }
    Ok(None)
}

/// Does the aircraft certainly stay farther than `buff(t_b)` nm from the cell in each
/// piece (ending at t_b) of `factor` times the automatic pieces? The grown stand-ins of
/// detection ([`Role::Grown`]) have no span of near: their near spans are certified
/// (every time within the buffer lies in one), so none means never within. `case`
/// carries the largest buffer, for the format's limits.
fn clear_by(case: &EarthCase, geo: Geodesy, factor: usize, buff: impl Fn(f64) -> f64) -> bool {
    let Ok((layout, auto, _)) = prepare(case, geo, Pieces::Auto) else {
        return false;
    };
    let n = pieces_of(auto, factor);
    (0..n).all(|j| {
        let (ta, tb) = piece_ends(case.lookahead_h, j, n);
        let role = Role::Grown { buff_nm: buff(tb) };
        let mut piece = layout.piece(ta, tb, role, true);
        if piece.case.is_none() {
            piece = layout.piece(ta, tb, role, false);
        }
        let Some(pcase) = piece.case else {
            return false;
        };
        let sep = Separation {
            d: piece.buff_merc,
            h: 0.0,
        };
        api::intervals(&pcase, Relation::Near, sep).is_empty()
    })
}

/// The verdict on the case's own course and speed: `Clear` when detection finds no
/// window of loss of separation,
/// `Conflict` when an approach within BUFF is certain, else `Unknown`.
pub fn current(case: &EarthCase, geo: Geodesy) -> Result<BandKind, EarthError> {
    if aircraft_cell::detect_earth(case, geo)?
        .separation_windows_h
        .is_empty()
    {
        return Ok(BandKind::Clear);
    }
    Ok(match certain_within(case, geo)? {
        Some(_) => BandKind::Conflict,
        None => BandKind::Unknown,
    })
}

/// The varied parameter.
#[derive(Clone, Copy, Debug)]
enum Family {
    /// Courses in degrees, at the case's speed.
    Course,
    /// Speeds in knots, at the case's course.
    Speed,
}

/// The Earth's cell certificate for [`refine`].
struct EarthCells<'a> {
    case: &'a EarthCase,
    geo: Geodesy,
    family: Family,
}

impl EarthCells<'_> {
    /// r of the cell [lo, hi] around its sample m over [0, T] (module doc), `None` when
    /// it cannot be bounded.
    fn spread(&self, lo: f64, hi: f64, m: f64) -> Option<f64> {
        self.spread_until(lo, hi, m, self.case.lookahead_h)
    }

    /// r over [0, t] (the bounds grow with t).
    fn spread_until(&self, lo: f64, hi: f64, m: f64, t: f64) -> Option<f64> {
        let d = (m - lo).max(hi - m);
        let delta = f64::from_bits(d.to_bits() + 1);
        match self.family {
            Family::Speed => Some(delta * t * BOUND_SAFETY),
            Family::Course => course_spread_nm(
                self.case.aircraft.speed_kn,
                t,
                self.case.aircraft_pos[1].to_radians(),
                delta.to_radians() * BOUND_SAFETY + COURSE_RAD_SLACK,
            ),
        }
    }

    /// The case flown at the sample m with BUFF `buff_nm`.
    fn sample(&self, m: f64, buff_nm: f64) -> EarthCase {
        let aircraft = match self.family {
            Family::Course => Motion {
                course_deg: m,
                ..self.case.aircraft
            },
            Family::Speed => Motion {
                speed_kn: m,
                ..self.case.aircraft
            },
        };
        EarthCase {
            aircraft,
            buff_nm,
            ..self.case.clone()
        }
    }

    /// The fewest equal cells (a power of two, at most [`FIRST_CELLS_MAX`]) whose r is
    /// below BUFF.
    fn first_cells(&self, lo: f64, hi: f64) -> usize {
        let mut n = 1;
        while n < FIRST_CELLS_MAX {
            let b = lo + (hi - lo) / n as f64;
            let m = lo + (b - lo) * 0.5;
            if self.spread(lo, b, m).is_some_and(|r| r < self.case.buff_nm) {
                break;
            }
            n *= 2;
        }
        n
    }
}

impl CellTest for EarthCells<'_> {
    type Open = ();

    fn everything(&self) {}

    fn test(&mut self, lo: f64, hi: f64, _open: &()) -> (BandKind, ()) {
        let m = lo + (hi - lo) * 0.5;
        let Some(r) = self.spread(lo, hi, m) else {
            return (BandKind::Unknown, ());
        };
        let buff = self.case.buff_nm;
        // the radius at the end of each piece: every time of the piece is within it
        let r_at = |tb: f64| self.spread_until(lo, hi, m, tb).unwrap_or(r);
        let largest = self.sample(m, (buff + r) * BOUND_SAFETY);
        if clear_by(&largest, self.geo, PIECE_FACTOR, |tb| {
            (buff + r_at(tb)) * BOUND_SAFETY
        }) {
            return (BandKind::Clear, ());
        }
        // pieces whose radius is below BUFF may certify an approach, however wide r
        // is by T
        let flown = self.sample(m, buff);
        let target = |tb: f64| (buff - r_at(tb) * BOUND_SAFETY) / BOUND_SAFETY;
        if let Ok(Some(_)) = certain_within_by(&flown, self.geo, PIECE_FACTOR, target) {
            return (BandKind::Conflict, ());
        }
        (BandKind::Unknown, ())
    }
}

/// A positive, finite `unknown_max`, else the error naming `field`.
fn positive(field: &str, x: f64) -> Result<f64, EarthError> {
    if !x.is_finite() {
        return Err(EarthError::new(field, EarthErrorKind::NotFinite));
    }
    if x <= 0.0 {
        return Err(EarthError::new(
            field,
            EarthErrorKind::NotPositive { value: x },
        ));
    }
    Ok(x)
}

/// Course bands over [0°, 360°] at the case's speed, on the sphere (module doc). Errors:
/// the case's own ([`aircraft_cell::detect_earth`]), `unknown_max_deg` not > 0, WGS84
/// (`geodesy`: course bands are certified on the sphere), and a lookahead whose reach
/// passes 85° of latitude (`lookahead_h`).
pub fn course_bands(
    case: &EarthCase,
    geo: Geodesy,
    unknown_max_deg: f64,
) -> Result<Bands, EarthError> {
    positive("unknown_max_deg", unknown_max_deg)?;
    if geo != Geodesy::Sphere {
        return Err(EarthError::new(
            "geodesy",
            EarthErrorKind::SphereOnly {
                what: "course bands",
            },
        ));
    }
    prepare(case, geo, Pieces::Auto)?;
    let reach = case.aircraft_pos[1].abs()
        + (case.aircraft.speed_kn * case.lookahead_h / EARTH_RADIUS_NM).to_degrees();
    if course_spread_nm(
        case.aircraft.speed_kn,
        case.lookahead_h,
        case.aircraft_pos[1].to_radians(),
        0.0,
    )
    .is_none()
    {
        return Err(EarthError::new(
            "lookahead_h",
            EarthErrorKind::CoursesReach { lat_deg: reach },
        ));
    }
    let mut cells = EarthCells {
        case,
        geo,
        family: Family::Course,
    };
    let n = cells.first_cells(0.0, 360.0);
    Ok(refine(&mut cells, 0.0, 360.0, n, unknown_max_deg))
}

/// Speed bands over [min_kn, max_kn] at the case's course (module doc), on either model.
/// Errors: the case's own, min_kn < 0, max_kn < min_kn, `unknown_max_kn` not > 0.
pub fn speed_bands(
    case: &EarthCase,
    geo: Geodesy,
    min_kn: f64,
    max_kn: f64,
    unknown_max_kn: f64,
) -> Result<Bands, EarthError> {
    positive("unknown_max_kn", unknown_max_kn)?;
    for (field, x) in [("speeds_kn[0]", min_kn), ("speeds_kn[1]", max_kn)] {
        if !x.is_finite() {
            return Err(EarthError::new(field, EarthErrorKind::NotFinite));
        }
        if x < 0.0 {
            return Err(EarthError::new(
                field,
                EarthErrorKind::Negative { value: x },
            ));
        }
    }
    if max_kn < min_kn {
        return Err(EarthError::new(
            "speeds_kn[1]",
            EarthErrorKind::OutOfRange {
                value: max_kn,
                range: "[min, ∞) knots",
            },
        ));
    }
    prepare(case, geo, Pieces::Auto)?;
    // every speed of the range must be one the format accepts (poleward flights end
    // within 85° of latitude): the fastest is checked, the others reach less far
    prepare(
        &EarthCase {
            aircraft: Motion {
                speed_kn: max_kn,
                ..case.aircraft
            },
            ..case.clone()
        },
        geo,
        Pieces::Auto,
    )
    .map_err(|e| EarthError::new("speeds_kn[1]", e.kind))?;
    let mut cells = EarthCells {
        case,
        geo,
        family: Family::Speed,
    };
    let n = cells.first_cells(min_kn, max_kn);
    Ok(refine(&mut cells, min_kn, max_kn, n, unknown_max_kn))
}

/// Whether a course in degrees lies in a band list tiling [0, 360] (for tests and
/// pictures): the kind of the band holding it, the first one at a shared end.
pub fn kind_at(bands: &Bands, x: f64) -> Option<BandKind> {
    bands
        .bands
        .iter()
        .find(|b| b.lo <= x && x <= b.hi)
        .map(|b| b.kind)
}

#[cfg(test)]
mod tests;
