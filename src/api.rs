//! The high-level API: validated cases and one [`detect`] call.
//!
//! ```
//! use polyguard::api::{detect, Case, MovingPoint, MovingPolygon, Params};
//! use polyguard::Vect2;
//!
//! // A 2×2 square drifting east at 1 unit/s; an aircraft climbing north through its path.
//! let cell = MovingPolygon::new(
//!     vec![[0.0, 0.0].into(), [2.0, 0.0].into(), [2.0, 2.0].into(), [0.0, 2.0].into()],
//!     Some(vec![Vect2::new(1.0, 0.0); 4]),
//! )?;
//! let aircraft = MovingPoint::new_2d(Vect2::new(5.0, -3.0), Vect2::new(0.0, 1.0))?;
//! let case = Case::new(10.0, aircraft, cell, Params::new(0.01)?)?;
//! let answer = detect(&case);
//! assert!(answer.detected && answer.well_formed);
//! # Ok::<(), polyguard::error::CaseError>(())
//! ```

use std::vec::Vec;

use crate::ball::Tri;
use crate::detect::{
    detect_3d_tri, detect_diff_2d_tri, detect_same_2d_tri_shaped, dispatch, statically_shaped,
    Method,
};
use crate::error::CaseError;
use crate::intervals::{Overflow, Relation, Separation, Span};
use crate::ring::{self, RingFault, Winding};
use crate::vect2::Vect2;
use crate::well_formed::{well_formed_fault, Fault};

/// The paper's slack parameters: BUFF (§II.A), F (§II.I) and the corner angle κ (§II.J).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params {
    buff: f64,
    fac: f64,
    kappa: f64,
    cos_kappa: f64,
}

impl Params {
    /// F when the case gives none: the paper's example value (§II.I, "e.g. 0.0001").
    pub const DEFAULT_FAC: f64 = 1e-4;
    /// κ when none is given: 5° in radians. The paper leaves κ to the user (§II.J); 5°
    /// flags slivers without flagging the ordinary corners of weather polygons.
    pub const DEFAULT_KAPPA: f64 = 5.0 * (core::f64::consts::PI / 180.0);

    /// BUFF > 0 (finite) with the default F and κ.
    pub fn new(buff: f64) -> Result<Self, CaseError> {
        check_positive("buff", buff)?;
        let kappa = Self::DEFAULT_KAPPA;
        Ok(Params {
            buff,
            fac: Self::DEFAULT_FAC,
            kappa,
            cos_kappa: kappa.cos(),
        })
    }

    /// F in the open interval (0, 1).
    pub fn with_fac(mut self, fac: f64) -> Result<Self, CaseError> {
        check_finite("fac", fac)?;
        if !(fac > 0.0 && fac < 1.0) {
            return Err(CaseError::OutOfRange {
                field: "fac",
                value: fac,
                range: "(0, 1)",
            });
        }
        self.fac = fac;
        Ok(self)
    }

    /// κ in radians, in the open interval (0, π).
    pub fn with_kappa(mut self, kappa: f64) -> Result<Self, CaseError> {
        check_finite("kappa", kappa)?;
        if !(kappa > 0.0 && kappa < core::f64::consts::PI) {
            return Err(CaseError::OutOfRange {
                field: "kappa",
                value: kappa,
                range: "(0, π)",
            });
        }
        self.kappa = kappa;
        self.cos_kappa = kappa.cos();
        Ok(self)
    }

    /// κ in degrees, in the open interval (0, 180): the case format's `kappa`.
    pub fn with_kappa_degrees(self, degrees: f64) -> Result<Self, CaseError> {
        check_finite("kappa", degrees)?;
        if !(degrees > 0.0 && degrees < 180.0) {
            return Err(CaseError::OutOfRange {
                field: "kappa",
                value: degrees,
                range: "(0, 180) degrees",
            });
        }
        self.with_kappa(degrees.to_radians())
    }

    /// BUFF.
    pub fn buff(&self) -> f64 {
        self.buff
    }
    /// F.
    pub fn fac(&self) -> f64 {
        self.fac
    }
    /// κ in radians.
    pub fn kappa(&self) -> f64 {
        self.kappa
    }
    /// cos κ, as well_formed takes it.
    pub fn cos_kappa(&self) -> f64 {
        self.cos_kappa
    }
}

fn check_finite(field: &'static str, x: f64) -> Result<(), CaseError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(CaseError::NotFinite {
            field: field.into(),
        })
    }
}

fn check_positive(field: &'static str, x: f64) -> Result<(), CaseError> {
    check_finite(field, x)?;
    if x > 0.0 {
        Ok(())
    } else {
        Err(CaseError::NotPositive { field, value: x })
    }
}

fn check_points(field: &str, pts: &[Vect2]) -> Result<(), CaseError> {
    for (i, p) in pts.iter().enumerate() {
        for (k, c) in [p.x, p.y].into_iter().enumerate() {
            if !c.is_finite() {
                return Err(CaseError::NotFinite {
                    field: format!("{field}[{i}][{k}]"),
                });
            }
        }
    }
    Ok(())
}

/// Twice the signed area of P (shoelace, relative to p_0 to limit cancellation).
pub fn signed_area2(p: &[Vect2]) -> f64 {
    let Some(&o) = p.first() else { return 0.0 };
    let mut sum = 0.0;
    for k in 1..p.len().saturating_sub(1) {
        let a = p[k] - o;
        let b = p[k + 1] - o;
        sum += a.x * b.y - a.y * b.x;
    }
    sum
}

/// The vertical extent of a 3D polygon (§III): pmin + t·vsp ≤ z ≤ pmax + t·vsp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slab {
    /// pmin, the bottom at t = 0.
    pub bottom: f64,
    /// pmax, the top at t = 0.
    pub top: f64,
    /// vsp, the vertical speed of the slab.
    pub vz: f64,
}

/// A polygon P with one velocity per vertex V (§II), optionally with a slab (§III).
/// Validated: ≥ 3 finite vertices in counterclockwise order, as many finite velocities.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingPolygon {
    vertices: Vec<Vect2>,
    velocities: Vec<Vect2>,
    slab: Option<Slab>,
}

impl MovingPolygon {
    /// P and V (`None`: a polygon at rest).
    pub fn new(vertices: Vec<Vect2>, velocities: Option<Vec<Vect2>>) -> Result<Self, CaseError> {
        if vertices.len() < 3 {
            return Err(CaseError::TooFewVertices {
                found: vertices.len(),
            });
        }
        check_points("polygon.vertices", &vertices)?;
        let velocities = match velocities {
            Some(v) => {
                if v.len() != vertices.len() {
                    return Err(CaseError::WrongLength {
                        field: "polygon.velocities".into(),
                        expected: vertices.len(),
                        found: v.len(),
                        what: "velocities (one per vertex)",
                    });
                }
                check_points("polygon.velocities", &v)?;
                v
            }
            None => vec![Vect2::ZERO; vertices.len()],
        };
        // §II: a simple ring, counterclockwise. A crossing is its own error (a bow tie
        // has no winding); a ring whose exact check would overflow (coordinates beyond
        // about 1e150) keeps the float area's sign, as before the check existed.
        match ring::check(&vertices) {
            Ok(Winding::Counterclockwise) => {}
            Ok(Winding::Clockwise) => {
                return Err(CaseError::Clockwise {
                    signed_area: signed_area2(&vertices) / 2.0,
                })
            }
            Err(RingFault::Crossing { .. }) if ring::collinear(&vertices) => {
                return Err(CaseError::ZeroArea)
            }
            Err(RingFault::Crossing { a, b }) => {
                return Err(CaseError::SelfIntersecting { a, b });
            }
            Err(RingFault::ZeroArea) => return Err(CaseError::ZeroArea),
            Err(RingFault::NotCheckable) => {
                let area2 = signed_area2(&vertices);
                if area2 < 0.0 {
                    return Err(CaseError::Clockwise {
                        signed_area: area2 / 2.0,
                    });
                }
            }
        }
        Ok(MovingPolygon {
            vertices,
            velocities,
            slab: None,
        })
    }

    /// Adds the slab bottom ≤ z ≤ top moving vertically at vz (§III).
    pub fn with_slab(mut self, bottom: f64, top: f64, vz: f64) -> Result<Self, CaseError> {
        check_finite("polygon.bottom", bottom)?;
        check_finite("polygon.top", top)?;
        check_finite("polygon.vz", vz)?;
        if bottom > top {
            return Err(CaseError::SlabInverted { bottom, top });
        }
        self.slab = Some(Slab { bottom, top, vz });
        Ok(self)
    }

    /// P.
    pub fn vertices(&self) -> &[Vect2] {
        &self.vertices
    }
    /// V.
    pub fn velocities(&self) -> &[Vect2] {
        &self.velocities
    }
    /// The slab, for a 3D polygon.
    pub fn slab(&self) -> Option<Slab> {
        self.slab
    }
    /// All vertex velocities equal: statically shaped (§II.F).
    pub fn statically_shaped(&self) -> bool {
        statically_shaped(&self.velocities[..])
    }
}

/// The moving point s + t·v (§II), with height s_z + t·v_z in 3D (§III).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MovingPoint {
    /// s, the horizontal position at t = 0.
    pub pos: Vect2,
    /// v, the horizontal velocity.
    pub vel: Vect2,
    /// (s_z, v_z) for a 3D point.
    pub z: Option<(f64, f64)>,
}

impl MovingPoint {
    /// A 2D point s moving at v.
    pub fn new_2d(pos: Vect2, vel: Vect2) -> Result<Self, CaseError> {
        check_points("point.pos", &[pos]).map_err(|_| CaseError::NotFinite {
            field: "point.pos".into(),
        })?;
        check_points("point.vel", &[vel]).map_err(|_| CaseError::NotFinite {
            field: "point.vel".into(),
        })?;
        Ok(MovingPoint { pos, vel, z: None })
    }

    /// A 3D point: pos = (x, y, z), vel = (vx, vy, vz).
    pub fn new_3d(pos: [f64; 3], vel: [f64; 3]) -> Result<Self, CaseError> {
        for (field, arr) in [("point.pos", pos), ("point.vel", vel)] {
            for (k, c) in arr.iter().enumerate() {
                if !c.is_finite() {
                    return Err(CaseError::NotFinite {
                        field: format!("{field}[{k}]"),
                    });
                }
            }
        }
        Ok(MovingPoint {
            pos: Vect2::new(pos[0], pos[1]),
            vel: Vect2::new(vel[0], vel[1]),
            z: Some((pos[2], vel[2])),
        })
    }
}

/// A validated detection case: lookahead T, the point, the polygon, the parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    lookahead: f64,
    point: MovingPoint,
    polygon: MovingPolygon,
    params: Params,
}

impl Case {
    /// T > 0; point and polygon both 2D or both 3D.
    pub fn new(
        lookahead: f64,
        point: MovingPoint,
        polygon: MovingPolygon,
        params: Params,
    ) -> Result<Self, CaseError> {
        check_positive("lookahead", lookahead)?;
        match (point.z.is_some(), polygon.slab.is_some()) {
            (true, false) => {
                return Err(CaseError::DimensionMismatch {
                    field: "polygon.bottom",
                    detail: "the point has a height but the polygon has no bottom/top/vz",
                })
            }
            (false, true) => {
                return Err(CaseError::DimensionMismatch {
                    field: "point.pos",
                    detail: "the polygon has bottom/top/vz but the point has no height",
                })
            }
            _ => {}
        }
        Ok(Case {
            lookahead,
            point,
            polygon,
            params,
        })
    }

    /// T.
    pub fn lookahead(&self) -> f64 {
        self.lookahead
    }
    /// The moving point.
    pub fn point(&self) -> &MovingPoint {
        &self.point
    }
    /// The moving polygon.
    pub fn polygon(&self) -> &MovingPolygon {
        &self.polygon
    }
    /// BUFF, F, κ.
    pub fn params(&self) -> &Params {
        &self.params
    }
    /// Which paper function decides this case.
    pub fn method(&self) -> Method {
        dispatch(
            self.point.z.is_some() && self.polygon.slab.is_some(),
            &self.polygon.velocities[..],
        )
    }
}

/// Which kind of answer a [`Detection`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Every comparison behind the answer was certified: paper A computed without
    /// rounding gives the same answer.
    Exact,
    /// A "yes" taken on a comparison that f64 could not decide (within rounding of one
    /// of paper A's thresholds); paper A without rounding may answer no. Never a "no".
    Conservative,
}

impl Kind {
    /// "exact" or "conservative".
    pub fn name(self) -> &'static str {
        match self {
            Kind::Exact => "exact",
            Kind::Conservative => "conservative",
        }
    }
}

/// The answer of [`detect`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Detection {
    /// The point comes within BUFF (or the F slack) of the polygon within [0, T], or a
    /// comparison on the way could not be decided (then `kind` is `Conservative`).
    pub detected: bool,
    /// Certified, or a conservative "yes".
    pub kind: Kind,
    /// Which paper function decided.
    pub method: Method,
    /// §II.J at t = 0, for information only: a polygon that is not well formed is still
    /// checked, never answered "no detection" for that reason.
    pub well_formed: bool,
    /// Which §II.J rule fails when `well_formed` is false (the first, in the paper's
    /// order).
    pub well_formed_fault: Option<Fault>,
}

/// Paper A §II.F and §III for one point and one polygon, on the polygon's own slices
/// (no case is built, nothing is cloned): which detector decides, and its three-valued
/// answer. Shared by [`decide`] and the batch. A point and polygon of different
/// dimensions (which `Case::new` refuses) are decided in 2D.
#[inline]
pub(crate) fn decide_pair(
    t: f64,
    pt: &MovingPoint,
    q: &MovingPolygon,
    params: &Params,
) -> (Method, Tri) {
    let (p, vels) = (&q.vertices[..], &q.velocities[..]);
    let (s, v) = (pt.pos, pt.vel);
    let (buff, fac) = (params.buff, params.fac);
    match (pt.z, q.slab) {
        (Some((sz, vz)), Some(slab)) => (
            Method::Detect3d,
            detect_3d_tri(
                t,
                s,
                v,
                sz,
                vz,
                p,
                vels,
                slab.bottom,
                slab.top,
                slab.vz,
                buff,
                fac,
            ),
        ),
        _ => match dispatch(false, vels) {
            // The dispatch found the velocities equal: detect_same_2D need not look again.
            Method::DetectSame2d => (
                Method::DetectSame2d,
                detect_same_2d_tri_shaped(t, s, v, p, vels, buff, true),
            ),
            _ => (
                Method::DetectDiff2d,
                detect_diff_2d_tri(t, s, v, p, vels, fac, buff),
            ),
        },
    }
}

/// The three-valued decision: `Yes`/`No` certified, `Unsure` when a comparison could
/// not be decided. The paper's functions see the case's own coordinates: every decision
/// is taken on differences from the point, so no rounded translation is needed.
pub fn decide(case: &Case) -> Tri {
    decide_pair(case.lookahead, &case.point, &case.polygon, &case.params).1
}

/// The decision alone (no well_formed check): the engine's hot path. Never `false` when
/// paper A without rounding says yes.
pub fn detected(case: &Case) -> bool {
    decide(case).or_true()
}

/// Paper A end to end: detect_3D for a 3D case, else detect_same_2D when all vertex
/// velocities are equal, else detect_diff_2D; plus well_formed (§II.J) for information.
pub fn detect(case: &Case) -> Detection {
    detection(case, decide(case))
}

/// The [`Detection`] of a three-valued answer for the case: `Unsure` is a conservative
/// yes; the method and §II.J's well_formed (at t = 0, for information) are the case's.
fn detection(case: &Case, tri: Tri) -> Detection {
    let fault = well_formed_fault(
        &case.polygon.vertices[..],
        case.params.buff,
        case.params.cos_kappa,
    );
    Detection {
        detected: tri.or_true(),
        kind: if tri == Tri::Unsure {
            Kind::Conservative
        } else {
            Kind::Exact
        },
        method: case.method(),
        well_formed: fault.is_none(),
        well_formed_fault: fault,
    }
}

/// The case's heights for the time scans (paper A §III's point height and slab), or
/// `None` in 2D.
fn heights(case: &Case) -> Option<crate::entry::Heights> {
    match (case.point.z, case.polygon.slab) {
        (Some((sz, vz)), Some(slab)) => Some(crate::entry::Heights {
            sz,
            vz,
            bottom: slab.bottom,
            top: slab.top,
            vsp: slab.vz,
        }),
        _ => None,
    }
}

/// When the point first enters the closed polygon (and slab), enclosed in f64: see
/// [`crate::entry`]. No BUFF: the time the exact truth computes, which paper A's
/// detection guarantees to flag. (Paper A §II–III's "the point enters", timed.)
pub fn detect_time(case: &Case) -> crate::entry::EntryTime {
    crate::entry::first_entry(
        case.lookahead,
        case.point.pos,
        case.point.vel,
        &case.polygon.vertices,
        &case.polygon.velocities,
        heights(case),
    )
}

/// Every time the relation holds during [0, T], as certified spans: see
/// [`crate::intervals`] (its definitions of inside, near_D and breach_D, and what the
/// spans certify, G1–G3). BUFF, F and κ play no part. Build `sep` with
/// [`Separation::new`], which refuses a negative or non-finite D or H; a `Separation`
/// written by hand with such a value gets the uncertain answer (one possible span over
/// [0, T]). (Paper A §II–§III's motion, timed.)
///
/// ```
/// use polyguard::api::{intervals, Case, MovingPoint, MovingPolygon, Params};
/// use polyguard::{Relation, Separation, Vect2};
///
/// let square = MovingPolygon::new(
///     vec![[0.0, 0.0].into(), [2.0, 0.0].into(), [2.0, 2.0].into(), [0.0, 2.0].into()],
///     None,
/// )?;
/// // (1, −2) moving north at 1: inside the square from t = 2 to t = 4.
/// let point = MovingPoint::new_2d(Vect2::new(1.0, -2.0), Vect2::new(0.0, 1.0))?;
/// let case = Case::new(10.0, point, square, Params::new(0.01)?)?;
/// let spans = intervals(&case, Relation::Inside, Separation::NONE);
/// assert_eq!(spans.len(), 1);
/// let (start, end) = (spans[0].start, spans[0].end);
/// assert!(spans[0].certain);
/// assert!(start.lo <= 2.0 && 2.0 <= start.hi && start.hi - start.lo < 1e-8);
/// assert!(end.lo <= 4.0 && 4.0 <= end.hi && end.hi - end.lo < 1e-8);
/// // Within D = 0.5: from t = 1.5 to t = 4.5 (the loss of separation at 1.5).
/// let near = intervals(&case, Relation::Near, Separation::new(0.5, 0.0)?);
/// assert!(near[0].start.lo <= 1.5 && 1.5 <= near[0].start.hi);
/// # Ok::<(), polyguard::error::CaseError>(())
/// ```
pub fn intervals(case: &Case, relation: Relation, sep: Separation) -> Vec<Span> {
    crate::intervals::intervals(
        case.lookahead,
        case.point.pos,
        case.point.vel,
        &case.polygon.vertices,
        &case.polygon.velocities,
        heights(case),
        relation,
        sep,
    )
}

/// [`intervals`] into a slice, allocating nothing: the number of spans, or
/// [`Overflow`] with the number needed when `out` is too short (the spans that fit are
/// written). (Paper A §II–§III's motion, timed; see [`crate::intervals`].)
///
/// ```
/// use polyguard::api::{intervals_into, Case, MovingPoint, MovingPolygon, Params};
/// use polyguard::{End, Relation, Separation, Span, Vect2};
///
/// let square = MovingPolygon::new(
///     vec![[0.0, 0.0].into(), [2.0, 0.0].into(), [2.0, 2.0].into(), [0.0, 2.0].into()],
///     None,
/// )?;
/// let point = MovingPoint::new_2d(Vect2::new(1.0, -2.0), Vect2::new(0.0, 1.0))?;
/// let case = Case::new(10.0, point, square, Params::new(0.01)?)?;
/// let mut out = [Span { start: End::at(0.0), end: End::at(0.0), certain: false }; 2];
/// assert_eq!(intervals_into(&case, Relation::Inside, Separation::NONE, &mut out), Ok(1));
/// assert!(out[0].start.lo <= 2.0 && 2.0 <= out[0].start.hi);
/// assert!(out[0].end.lo <= 4.0 && 4.0 <= out[0].end.hi);
/// # Ok::<(), polyguard::error::CaseError>(())
/// ```
pub fn intervals_into(
    case: &Case,
    relation: Relation,
    sep: Separation,
    out: &mut [Span],
) -> Result<usize, Overflow> {
    crate::intervals::intervals_into(
        case.lookahead,
        case.point.pos,
        case.point.vel,
        &case.polygon.vertices,
        &case.polygon.velocities,
        heights(case),
        relation,
        sep,
        out,
    )
}

/// Keep-in exit detection: does the point leave the fence (breach_D at some t ∈ [0, T],
/// see [`crate::fence`])? `detected` is never false when it does; `kind` is `Exact` when
/// the answer is certified, `Conservative` for a "yes" f64 could not certify. `method`
/// and the §II.J well_formed fields are those of [`detect`]. BUFF and F play no part.
/// Build `sep` with [`Separation::new`] (a hand-written negative or non-finite one gets
/// a conservative yes). (Paper A §II–§III's motion and slab, for a keep-in polygon.)
///
/// ```
/// use polyguard::api::{detect_exit, Case, Kind, MovingPoint, MovingPolygon, Params};
/// use polyguard::{Separation, Vect2};
///
/// let fence = MovingPolygon::new(
///     vec![[0.0, 0.0].into(), [4.0, 0.0].into(), [4.0, 4.0].into(), [0.0, 4.0].into()],
///     None,
/// )?;
/// // From the centre, east at 0.5: within D = 1 of the east edge from t = 2.
/// let point = MovingPoint::new_2d(Vect2::new(2.0, 2.0), Vect2::new(0.5, 0.0))?;
/// let case = Case::new(10.0, point, fence.clone(), Params::new(0.01)?)?;
/// let exit = detect_exit(&case, Separation::new(1.0, 0.0)?);
/// assert!(exit.detected && exit.kind == Kind::Exact);
/// let case = Case::new(1.5, point, fence, Params::new(0.01)?)?;
/// assert!(!detect_exit(&case, Separation::new(1.0, 0.0)?).detected);
/// # Ok::<(), polyguard::error::CaseError>(())
/// ```
pub fn detect_exit(case: &Case, sep: Separation) -> Detection {
    let tri = crate::fence::detect_exit_tri(
        case.lookahead,
        case.point.pos,
        case.point.vel,
        &case.polygon.vertices,
        &case.polygon.velocities,
        heights(case),
        sep,
    );
    detection(case, tri)
}

/// The plain f64 transcription's answer (feature `plain`), for comparison only: it
/// can miss true entries (see [`crate::plain`]).
#[cfg(feature = "plain")]
pub fn detected_plain(case: &Case) -> bool {
    use crate::plain::detect as pd;
    let p = &case.polygon.vertices[..];
    let vels = &case.polygon.velocities[..];
    let (s, v, t) = (case.point.pos, case.point.vel, case.lookahead);
    let (buff, fac) = (case.params.buff, case.params.fac);
    match (case.method(), case.point.z, case.polygon.slab) {
        (Method::Detect3d, Some((sz, vz)), Some(slab)) => pd::detect_3d(
            t,
            s,
            v,
            sz,
            vz,
            p,
            vels,
            slab.bottom,
            slab.top,
            slab.vz,
            buff,
            fac,
        ),
        (Method::DetectSame2d, ..) => pd::detect_same_2d(t, s, v, p, vels, buff),
        _ => pd::detect_diff_2d(t, s, v, p, vels, fac, buff),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<Vect2> {
        vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(2.0, 0.0),
            Vect2::new(2.0, 2.0),
            Vect2::new(0.0, 2.0),
        ]
    }

    #[test]
    fn every_rule_is_a_typed_error_naming_its_field() {
        let e = MovingPolygon::new(square()[..2].to_vec(), None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "polygon.vertices: 2 points, at least 3 are needed"
        );
        let mut bad = square();
        bad[2].y = f64::NAN;
        assert_eq!(
            MovingPolygon::new(bad, None).unwrap_err().field(),
            "polygon.vertices[2][1]"
        );
        let e = MovingPolygon::new(square(), Some(vec![Vect2::ZERO; 3])).unwrap_err();
        assert_eq!(e.field(), "polygon.velocities");
        let mut cw = square();
        cw.reverse();
        assert!(matches!(
            MovingPolygon::new(cw, None),
            Err(CaseError::Clockwise { .. })
        ));
        assert_eq!(Params::new(0.0).unwrap_err().field(), "buff");
        assert_eq!(Params::new(f64::INFINITY).unwrap_err().field(), "buff");
        let p = Params::new(0.1).unwrap();
        assert_eq!(p.with_fac(1.0).unwrap_err().field(), "fac");
        assert_eq!(p.with_fac(0.0).unwrap_err().field(), "fac");
        let poly = MovingPolygon::new(square(), None).unwrap();
        let pt = MovingPoint::new_2d(Vect2::ZERO, Vect2::ZERO).unwrap();
        let e = Case::new(-1.0, pt, poly.clone(), p).unwrap_err();
        assert_eq!(e.field(), "lookahead");
        let pt3 = MovingPoint::new_3d([0.0; 3], [0.0; 3]).unwrap();
        assert!(matches!(
            Case::new(1.0, pt3, poly.clone(), p),
            Err(CaseError::DimensionMismatch { .. })
        ));
        let poly3 = poly.clone().with_slab(0.0, 1.0, 0.0).unwrap();
        assert_eq!(
            Case::new(1.0, pt, poly3, p).unwrap_err().field(),
            "point.pos"
        );
        assert_eq!(
            poly.with_slab(2.0, 1.0, 0.0).unwrap_err().field(),
            "polygon.top"
        );
        assert_eq!(
            MovingPoint::new_3d([0.0, 0.0, f64::NAN], [0.0; 3])
                .unwrap_err()
                .field(),
            "point.pos[2]"
        );
    }

    #[test]
    fn not_well_formed_still_detects() {
        // A sliver with a 5.7° corner at (10, 0), sharper than κ = 10°: not well formed
        // (§II.J rule 3), still answered. The point starts inside.
        let sliver = vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(10.0, 0.0),
            Vect2::new(0.0, 1.0),
        ];
        let poly = MovingPolygon::new(sliver, None).unwrap();
        let pt = MovingPoint::new_2d(Vect2::new(1.0, 0.5), Vect2::ZERO).unwrap();
        let params = Params::new(0.01)
            .and_then(|p| p.with_kappa(10f64.to_radians()))
            .unwrap();
        let c = Case::new(1.0, pt, poly, params).unwrap();
        let d = detect(&c);
        assert!(!d.well_formed);
        assert_eq!(d.well_formed_fault, Some(Fault::SharpCorner(1)));
        assert!(d.detected);
        assert_eq!(d.method, Method::DetectSame2d);
    }

    /// A bow tie has no inside for §II's ray count and no winding: its own error, naming
    /// the edges that cross (it used to pass, its shoelace area 0 counting as not
    /// clockwise).
    #[test]
    fn a_self_intersecting_polygon_is_an_error() {
        let bow = vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(4.0, 4.0),
            Vect2::new(4.0, 0.0),
            Vect2::new(0.0, 4.0),
        ];
        let e = MovingPolygon::new(bow, None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "polygon.vertices: edges 0–1 and 2–3 cross (vertices numbered from 0); \
             the polygon must not intersect itself"
        );
        let line = vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(1.0, 1.0),
            Vect2::new(3.0, 3.0),
        ];
        assert!(MovingPolygon::new(line, None).is_err());
    }
}
