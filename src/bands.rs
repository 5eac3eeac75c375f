//! Conflict-free bands of course, speed and vertical speed for a point among moving
//! polygons over [0, T], certified between samples (paper A §II–§III's motion, §II.G's
//! proximity: the near_D relation of [`crate::intervals`]).
//!
//! # Definitions
//! The point starts at s (in 3D at height sz, climbing at vz); each obstacle is a moving
//! polygon P(t) with vertices p_i + t·V_i, in 3D with an optional slab bottom + t·vsp ≤
//! z ≤ top + t·vsp (an obstacle without a slab has no vertical extent limit). A
//! velocity w (horizontal) is **in conflict** when near_D (the intervals module's
//! definition, with H in 3D) holds at some t ∈ [0, T] against some obstacle for the
//! point s + t·w. The course θ is in radians clockwise from +y ("north"):
//! v(θ) = speed·(sin θ, cos θ).
//!
//! A band answer tiles the parameter range without gaps ([0, 2π) for courses, given
//! as [0, fl(2π)], the last band also covering the courses between fl(2π) and 2π) into
//! [`Band`]s, adjacent bands of one kind merged:
//! - `Clear`: **every** parameter value in the closed band is free of conflict, for
//!   the exact velocity and for the f64 velocity [`velocity`] computes from it;
//! - `Conflict`: every value in the closed band is in conflict (both velocities);
//! - `Unknown`: not decided; their total width is reported, with whether it met the
//!   requested `unknown_max`.
//!
//! # The certificate between samples
//! A cell [lo, hi] of the parameter is sampled at its float midpoint m, where the scan
//! runs with the f64 velocity w_m. For every value θ of the cell and each velocity w_θ
//! of θ (exact or f64), the points differ by |x_θ(t) − x_m(t)| = t·|w_θ − w_m| ≤ r for
//! all t ∈ [0, T], where (δ the cell's half width, rounded up):
//! - course: |v(θ) − v(m)| = speed·2·sin(|θ − m|/2) ≤ speed·2·sin(min(δ, π)/2), and
//!   |w − v| ≤ 2⁻⁵¹·speed for w_m and for w_θ (below), so
//!   r = T·speed·(2·sin(min(δ, π)/2) + 2⁻⁴⁹) (a factor 2 of room in the slack);
//! - speed at a fixed course c: |v(σ) − v(m)| = |σ − m| ≤ δ, and the same slack with
//!   the cell's top speed: r = T·(δ + 2⁻⁴⁹·hi);
//! - vertical speed: the horizontal motion is one exact f64 velocity; the heights
//!   differ by |Δvz|·t ≤ r_z = T·δ.
//!
//! Then, for each obstacle:
//! - **Clear**: the certified spans of near_{D+r} (with H + r_z in 3D) at m are empty
//!   (every piece of the scan fails). By G1 near_{D+r} never holds at m; a point within
//!   r (and r_z) of x_m(t) that were within D (and H) of P(t) would put x_m(t) within
//!   D + r (H + r_z), so near_D never holds for any value of the cell.
//! - **Conflict** when r ≤ D: some piece where near_{D−r} certainly holds at m, with
//!   the slab shifted inward by r_z − H (grown by H − r_z when that is positive; its
//!   bottom rounded up, its top rounded down, H then 0). At such a t, x_m(t) is within
//!   D − r of P(t) and its height in [bottom − H + r_z, top + H − r_z]; every x_θ(t)
//!   is within r of x_m(t), its height within r_z: within D and H.
//! - **Conflict** when r > D: some piece where breach_{r−D} certainly fails at m (the
//!   fence holds: x_m(t) inside P(t) deeper than r − D, and strictly inside the same
//!   shifted slab). A point displaced by ≤ r is inside P(t), or leaves it across ∂P(t)
//!   at a distance > r − D from x_m(t), ending within r − (r − D) = D of it.
//!
//! A cell is Conflict when some obstacle is, Clear when every obstacle is; otherwise
//! Unknown. A parent's verdict for an obstacle holds on every child (its certificate
//! covers the whole parent), so children test only the obstacles left open.
//!
//! # Rounding analysis of r
//! No absolute tolerance enters. `libm`'s sin and cos are within 1 ulp (≤ 2⁻⁵²·|y|)
//! of the exact value; [`velocity`] multiplies by the speed (one rounding, 2⁻⁵³), so
//! each component is within |speed·sin θ|·(2⁻⁵² + 2⁻⁵³ + 2⁻¹⁰⁵) < 2⁻⁵¹·|speed·sin θ|
//! (cos alike), and |w − v(θ)| ≤ 2⁻⁵¹·speed. The half width δ = max(m − lo, hi − m)
//! is rounded up (`round_up` bounds the exact result of one operation), the last course
//! cell's δ grows by 2⁻⁵¹ ≥ 2π − fl(2π) (half an ulp of 2π), 2·sin(δ/2) is rounded up
//! (1 ulp of libm, within `round_up`'s 2⁻⁵¹ relative), and every sum and product of r
//! is rounded up. D + r and H + r_z are rounded up, D − r and r − D rounded toward the
//! safe side, the shifted slab's ends rounded inward. The scan itself certifies the
//! f64 case it is given exactly (the intervals module's error analysis).
//!
//! # Prefilter and early exit
//! [0, T] is cut into 8 slices at float times. In each, an obstacle's swept box (every
//! vertex moves along a segment: the box of its positions at the slice's ends, rounded
//! outward) and the box of x_m's piece of segment are compared along x and along y; a
//! gap (rounded down) beyond D + r in every slice makes the obstacle Clear for the cell
//! without a scan. The two scans stop at their first deciding piece (the scan's
//! consumer asks it to stop; no change to the scan was needed): the Clear test at the
//! first piece that does not fail, the Conflict test at the first certain one. When
//! r > D and every slice's box is narrower than 2(r − D) along x or y, no point can be
//! r − D deep inside the obstacle, and the breach scan is skipped.
//!
//! # Fast path for translating polygons
//! An obstacle without a slab whose vertex velocities are all one f64 vector V (static:
//! V = 0) moves rigidly: P(t) = P(0) + t·V. For the sample's f64 velocity w, the point
//! relative to the polygon is y(t) = x_m(t) − t·V = s + t·(w − V), and
//! dist(x_m(t), P(t)) = dist(y(t), P(0)) exactly. Over [0, T], y runs along the segment
//! σ from s to e = s + T·(w − V), y(t) = s + (t/T)·(e − s); P(0)'s vertices are the
//! exact input floats.
//!
//! **Rounding of σ.** e is computed with `ball::Ball` arithmetic
//! per coordinate (w − V, times T, plus s): the float ẽ has each coordinate within ρ of
//! e's (the larger of the two balls' radii), so |e − ẽ| ≤ √2·ρ, and the float segment
//! σ̃ = [s, ẽ] satisfies |y(t) − ỹ(t)| = (t/T)·|e − ẽ| ≤ √2·ρ ≤ 2ρ for ỹ(t) = s +
//! (t/T)(ẽ − s). A witness point y(t*) at a float time t* = fl(λ·T) ∈ [0, T] (λ ∈ [0, 1],
//! so the rounded product stays in [0, T]) is computed with balls from s, t* and
//! w − V: its float ỹ has each coordinate within ρ_y of y(t*), |y − ỹ| ≤ 2ρ_y.
//! Distances between exact floats are certified by the offset certificate's tests
//! (`at_least`, `within`: squared distances as balls, no absolute epsilon); inside is an
//! exact crossing count of the float point (not on ∂P, odd; the winding number has
//! the crossing count's parity).
//!
//! Then, with reach = D + r rounded up (strictly above D + r):
//! - **Prefilter** (replacing the sliced boxes for these obstacles): every coordinate
//!   of a point of σ lies between s's and e's, and e's within ρ ≤ 2ρ of ẽ's; when the
//!   box of s and ẽ grown by 2ρ (rounded outward) and P's vertex box are more than
//!   reach apart along x or y (the gap rounded down), every t is farther than reach:
//!   Clear.
//! - **Clear**: s is outside P (exact) and every edge of P is at least reach + 2ρ from
//!   σ̃ (the segments do not meet, exact orientations, and the four end-to-segment
//!   distances are certified, as the offset certificate's `segments_at_least`; a box
//!   gap rounded down, or both ends of the edge certainly on one side of σ̃'s line and
//!   at least that far from it ((ẽ − s) × (a − s) of one certain sign and squared at
//!   least th²·|ẽ − s|², as balls), may settle an edge first: the distance to a line
//!   is affine along an edge on one side of it). Every point of σ is then at least
//!   reach + 2ρ − √2ρ ≥ reach from ∂P, and σ, connected and starting outside P, never
//!   enters it: dist(y(t), P) ≥ reach > D + r for every t (`round_up` lands at least
//!   `ball::ETA`/2 above the exact sum), so near_{D+r} never holds at
//!   the sample, which is the Clear certificate above.
//! - **Conflict, r ≤ D**: with near = D − r rounded down (≥ 0): some t* where ỹ is
//!   within near − 2ρ_y of an edge (certified, near − 2ρ_y certainly > 0), so
//!   dist(y(t*), P) ≤ near ≤ D − r; or ỹ inside P (exact) and at least 2ρ_y from every
//!   edge, so y(t*) is inside P too (dist 0). Either is the r ≤ D Conflict certificate.
//!   The candidate t* is σ̃'s float nearest approach to ∂P (ends against edges,
//!   vertices against σ̃, crossings), then the deepest of a few float points of σ̃ inside P.
//! - **Conflict, r > D**: with deep = r − D rounded up (strictly above): ỹ inside P and
//!   at least deep + 2ρ_y from every edge, so y(t*) is inside P and at least deep > r − D
//!   from ∂P: the r > D Conflict certificate. Candidates: the deepest of 7 evenly spaced
//!   float points in each stretch of σ̃ between its float crossings of ∂P.
//! - Otherwise the scans decide, except those that certainly cannot: the Clear scan
//!   (all pieces of near_{reach} fail) when some y(t*) is certified within reach of P
//!   as above (near_{reach} then holds at t*, and the scan is certified), the near_{D−r}
//!   scan when s is outside P and every edge is at least fl↑(near + 2ρ) from σ̃
//!   (so every point of σ is farther than near from P: near_{near} never holds). A
//!   skipped scan could only have returned Unknown, so the fast path never loses a
//!   decision, and every decision it makes is certified.
//!
//! # Refinement
//! The range starts as the fewest equal cells (a power of two, at most 256) whose r
//! is at most D (r_z at most H): coarser cells could be decided only far from every
//! obstacle, which the prefilter does anyway. Then, pass by pass, every Unknown cell
//! is halved, while the Unknown total is above `unknown_max` and some Unknown cell can
//! still be split (its float midpoint strictly inside), within a budget of
//! [`MAX_CELLS`] cell tests, and until four passes in a row each left more than 90 %
//! of the Unknown total: halving every cell roughly halves a sliver around a boundary
//! once the cells are narrower than it, while a stretch that does not shrink is one the
//! certificate cannot decide (the point starting on an obstacle's boundary with D = 0,
//! moving out of it: in conflict at t = 0, never deeper inside, never clear). `met`
//! says whether the total came under `unknown_max`.

mod cell;
pub mod refine;
mod rigid;

use core::fmt;
use std::string::String;
use std::vec::Vec;

pub use crate::ball::Tri;
use crate::intervals::Separation;
use crate::vect2::Vect2;
use cell::{Family, Tester};

/// How many cells one band answer may test before it stops refining (a cell test is at
/// most two scans per open obstacle).
pub const MAX_CELLS: usize = 1 << 16;

/// The point's vertical state in 3D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Height {
    /// sz, the height at t = 0.
    pub sz: f64,
    /// vz, the vertical speed (ignored by [`vertical_speed_bands`], which varies it).
    pub vz: f64,
}

/// An obstacle's slab in 3D: bottom + t·vsp ≤ z ≤ top + t·vsp (paper A §III).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slab {
    /// The bottom at t = 0.
    pub bottom: f64,
    /// The top at t = 0.
    pub top: f64,
    /// The vertical speed of both.
    pub vsp: f64,
}

/// One moving polygon: vertices `p[i] + t·vels[i]`, counterclockwise, with an optional
/// slab (3D).
#[derive(Clone, Copy, Debug)]
pub struct Obstacle<'a> {
    /// The vertices at t = 0.
    pub p: &'a [Vect2],
    /// Their velocities (as many as vertices).
    pub vels: &'a [Vect2],
    /// The slab, in 3D; `None`: no vertical limit.
    pub slab: Option<Slab>,
}

/// The situation the bands answer for: lookahead T, the point's start (and height),
/// the obstacles, the separations.
#[derive(Clone, Copy, Debug)]
pub struct Traffic<'a> {
    /// T > 0.
    pub t: f64,
    /// The point at t = 0.
    pub s: Vect2,
    /// Its height and vertical speed (3D), or `None` (2D).
    pub height: Option<Height>,
    /// The moving polygons.
    pub obstacles: &'a [Obstacle<'a>],
    /// D (and H in 3D).
    pub sep: Separation,
}

/// What a band certifies (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BandKind {
    /// No value in the band is in conflict.
    Clear,
    /// Every value in the band is in conflict.
    Conflict,
    /// Not decided.
    Unknown,
}

/// A closed band [lo, hi] of the parameter (course, speed or vertical speed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// The band's low end.
    pub lo: f64,
    /// Its high end.
    pub hi: f64,
    /// What is certified on it.
    pub kind: BandKind,
}

/// A band answer: the range tiled in order (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Bands {
    /// The bands, in increasing order, each starting where the previous ends.
    pub bands: Vec<Band>,
    /// The total width of the Unknown bands.
    pub unknown_total: f64,
    /// Whether `unknown_total ≤ unknown_max` was reached.
    pub met: bool,
}

/// An input the bands refuse, naming its field.
#[derive(Clone, Debug, PartialEq)]
pub enum BandsError {
    /// NaN or ±∞.
    NotFinite {
        /// The field (`t`, `speed`, `obstacles[2].p[1]`, ...).
        field: String,
    },
    /// A number outside its range.
    OutOfRange {
        /// The field.
        field: String,
        /// Its value.
        value: f64,
        /// The range it must lie in.
        range: &'static str,
    },
    /// A polygon with fewer than 3 vertices, or velocities not matching its vertices.
    WrongLength {
        /// The field.
        field: String,
        /// The length it must have (at least, for vertices).
        expected: usize,
        /// The length it has.
        found: usize,
    },
    /// A slab without the point's height.
    DimensionMismatch {
        /// The field.
        field: String,
    },
}

impl fmt::Display for BandsError {
    /// The error with its field.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BandsError::NotFinite { field } => write!(f, "{field}: not a finite number"),
            BandsError::OutOfRange {
                field,
                value,
                range,
            } => write!(f, "{field}: {value} is outside {range}"),
            BandsError::WrongLength {
                field,
                expected,
                found,
            } => write!(f, "{field}: length {found}, expected {expected}"),
            BandsError::DimensionMismatch { field } => {
                write!(f, "{field}: a slab needs the point's height (3D)")
            }
        }
    }
}

impl std::error::Error for BandsError {}

/// A finite number, else the typed error naming `field`.
fn finite(field: &str, x: f64) -> Result<f64, BandsError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(BandsError::NotFinite {
            field: field.into(),
        })
    }
}

/// A finite number ≥ 0 (> 0 when `positive`), else the typed error naming `field`.
fn at_least_zero(field: &str, x: f64, positive: bool) -> Result<f64, BandsError> {
    finite(field, x)?;
    if x < 0.0 || (positive && x == 0.0) {
        return Err(BandsError::OutOfRange {
            field: field.into(),
            value: x,
            range: if positive { "(0, ∞)" } else { "[0, ∞)" },
        });
    }
    Ok(x)
}

/// The definitions' rules for a traffic situation: T > 0, D, H ≥ 0, finite
/// coordinates, at least 3 vertices with as many velocities, slabs only in 3D.
fn validate(traffic: &Traffic) -> Result<(), BandsError> {
    at_least_zero("t", traffic.t, true)?;
    finite("s[0]", traffic.s.x)?;
    finite("s[1]", traffic.s.y)?;
    if let Some(z) = traffic.height {
        finite("height.sz", z.sz)?;
        finite("height.vz", z.vz)?;
    }
    at_least_zero("sep", traffic.sep.d, false)?;
    at_least_zero("sep_v", traffic.sep.h, false)?;
    for (i, o) in traffic.obstacles.iter().enumerate() {
        if o.p.len() < 3 {
            return Err(BandsError::WrongLength {
                field: format!("obstacles[{i}].p"),
                expected: 3,
                found: o.p.len(),
            });
        }
        if o.vels.len() != o.p.len() {
            return Err(BandsError::WrongLength {
                field: format!("obstacles[{i}].vels"),
                expected: o.p.len(),
                found: o.vels.len(),
            });
        }
        for (name, list) in [("p", o.p), ("vels", o.vels)] {
            for (k, a) in list.iter().enumerate() {
                finite(&format!("obstacles[{i}].{name}[{k}][0]"), a.x)?;
                finite(&format!("obstacles[{i}].{name}[{k}][1]"), a.y)?;
            }
        }
        if let Some(slab) = o.slab {
            if traffic.height.is_none() {
                return Err(BandsError::DimensionMismatch {
                    field: format!("obstacles[{i}].slab"),
                });
            }
            for (name, x) in [
                ("bottom", slab.bottom),
                ("top", slab.top),
                ("vsp", slab.vsp),
            ] {
                finite(&format!("obstacles[{i}].slab.{name}"), x)?;
            }
        }
    }
    Ok(())
}

/// The f64 velocity of a course: speed·(sin θ, cos θ), θ clockwise from +y (the module
/// doc's definition). Each component is within 2⁻⁵¹·speed of the exact one (the
/// rounding analysis).
pub fn velocity(speed: f64, course: f64) -> Vect2 {
    Vect2::new(speed * libm::sin(course), speed * libm::cos(course))
}

/// Is the velocity `v` in conflict (the module doc's definition; 3D with
/// `traffic.height`'s vz)? `Yes` and `No` are certified (G1 and G2 of the scan over
/// each obstacle, paper A §II–§III), `Unsure` when a scan cannot tell. Allocates only
/// the scan's workspace.
pub fn conflict(traffic: &Traffic, v: Vect2) -> Result<Tri, BandsError> {
    validate(traffic)?;
    finite("v[0]", v.x)?;
    finite("v[1]", v.y)?;
    let mut tester = Tester::new(traffic, Family::Fixed { v });
    Ok(tester.at_velocity(v))
}

/// The unknown_max rule: finite and > 0.
fn check_unknown_max(unknown_max: f64) -> Result<(), BandsError> {
    at_least_zero("unknown_max", unknown_max, true).map(|_| ())
}

/// Course bands over [0, 2π) at `speed` (module doc: definitions, certificate,
/// refinement). The last band ends at fl(2π) and covers the courses up to 2π.
pub fn course_bands(traffic: &Traffic, speed: f64, unknown_max: f64) -> Result<Bands, BandsError> {
    validate(traffic)?;
    at_least_zero("speed", speed, false)?;
    check_unknown_max(unknown_max)?;
    let tester = Tester::new(traffic, Family::Course { speed });
    Ok(tester.bands(0.0, core::f64::consts::TAU, unknown_max))
}

/// Speed bands over [min, max] at a fixed `course` (radians clockwise from +y; module
/// doc).
pub fn speed_bands(
    traffic: &Traffic,
    course: f64,
    min: f64,
    max: f64,
    unknown_max: f64,
) -> Result<Bands, BandsError> {
    validate(traffic)?;
    finite("course", course)?;
    at_least_zero("min", min, false)?;
    at_least_zero("max", max, false)?;
    if max < min {
        return Err(BandsError::OutOfRange {
            field: "max".into(),
            value: max,
            range: "[min, ∞)",
        });
    }
    check_unknown_max(unknown_max)?;
    let tester = Tester::new(traffic, Family::Speed { course });
    Ok(tester.bands(min, max, unknown_max))
}

/// Vertical speed bands over [min, max] with the horizontal velocity `v` fixed (3D:
/// `traffic.height` is required, its vz is the varied parameter; module doc).
pub fn vertical_speed_bands(
    traffic: &Traffic,
    v: Vect2,
    min: f64,
    max: f64,
    unknown_max: f64,
) -> Result<Bands, BandsError> {
    validate(traffic)?;
    if traffic.height.is_none() {
        return Err(BandsError::DimensionMismatch {
            field: "height".into(),
        });
    }
    finite("v[0]", v.x)?;
    finite("v[1]", v.y)?;
    finite("min", min)?;
    finite("max", max)?;
    if max < min {
        return Err(BandsError::OutOfRange {
            field: "max".into(),
            value: max,
            range: "[min, ∞)",
        });
    }
    check_unknown_max(unknown_max)?;
    let tester = Tester::new(traffic, Family::Vertical { v });
    Ok(tester.bands(min, max, unknown_max))
}

#[cfg(test)]
mod tests;
