//! Paper A §II.F: the choice of detector for a case ([`dispatch`]), and the detectors, one
//! module per section of the paper: `same` (§II.H, statically shaped polygons),
//! `warping` (§II.I, warping polygons) with the root enclosures of its quadratics
//! (`roots`) and the sweep filter in front of edge_detect (`filter`), and `slab` (§III,
//! 3D). Every public item is re-exported here, so its path is `detect::name`.
//!
//! Every detector has a three-valued form (`*_tri`) that carries [`Tri`] through the
//! algorithm: `No` only when paper A computed without rounding answers no, `Yes` only
//! when it answers yes, `Unsure` when some comparison on the way could not be decided in
//! f64. The boolean form reads `Unsure` as a detection, so it never misses what paper A
//! in exact arithmetic detects.
//!
//! The detectors never form s + T·v or P + T·V in absolute coordinates: each decision
//! is taken on differences from the point (see [`crate::contain::RelPoly`]), so the
//! error bounds are on the scale of the encounter, whatever the offsets.

mod filter;
mod roots;
mod same;
mod slab;
mod warping;

#[cfg(feature = "std")]
pub(crate) use filter::never_collapses;
#[cfg(feature = "std")]
pub(crate) use same::detect_same_2d_tri_shaped;
pub use same::{detect_same_2d, detect_same_2d_tri};
#[doc(hidden)]
pub use slab::slab_window_balls;
pub use slab::{detect_3d, detect_3d_tri, slab_window};
pub use warping::{
    detect_diff_2d, detect_diff_2d_tri, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp,
    edge_detect_simp_tri,
};

use crate::polygon::VertexSeq;
use crate::predicates as pr;
#[cfg(doc)]
use crate::Tri;

/// The sign σ (or ε) = ±1 of paper A §II.I.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// σ = −1.
    Neg,
    /// σ = +1.
    Pos,
}

impl Sign {
    /// Both signs, −1 then +1.
    pub const BOTH: [Sign; 2] = [Sign::Neg, Sign::Pos];

    /// −1.0 or 1.0.
    #[inline(always)]
    pub fn value(self) -> f64 {
        match self {
            Sign::Neg => -1.0,
            Sign::Pos => 1.0,
        }
    }

    /// The other sign.
    #[inline(always)]
    pub fn flip(self) -> Sign {
        match self {
            Sign::Neg => Sign::Pos,
            Sign::Pos => Sign::Neg,
        }
    }
}

/// A closed time interval [lb, ub]; empty when lb > ub.
///
/// The paper writes the empty interval as (T, 0). That is not empty when T = 0, which
/// detect_3D produces when the slab window is a single instant, so the engine uses
/// (+∞, −∞) instead: it loses every max/min comparison, as (T, 0) does for T > 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower bound.
    pub lb: f64,
    /// The upper bound.
    pub ub: f64,
}

impl Interval {
    /// The empty interval.
    pub const EMPTY: Interval = Interval {
        lb: f64::INFINITY,
        ub: f64::NEG_INFINITY,
    };

    /// [lb, ub].
    #[inline(always)]
    pub const fn new(lb: f64, ub: f64) -> Interval {
        Interval { lb, ub }
    }

    /// Does the interval contain no time? (NaN ends count as non-empty: the safe side.)
    #[inline(always)]
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub fn is_empty(&self) -> bool {
        self.lb > self.ub
    }
}

/// min for values that are never NaN, so the NaN handling of f64::min is not needed: the
/// sweep filter's corner coordinates (finite inputs: a sum p + t·v overflows to ±∞ at
/// worst) and the root enclosures' ends (checked for NaN first).
#[inline(always)]
fn fmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// max, as [`fmin`].
#[inline(always)]
fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// Are all vertex velocities equal (a statically shaped polygon, §II.F)?
#[inline]
pub fn statically_shaped<V: VertexSeq + ?Sized>(vels: &V) -> bool {
    let n = vels.count();
    if n == 0 {
        return true;
    }
    let v0 = vels.vertex(0);
    // On a slice: the second vertex first (a warping polygon's velocities usually differ
    // there already), then every comparison made and the results ANDed, without an exit
    // per vertex, which the compiler takes several vertices at a time. The same answer.
    if let Some(vs) = vels.as_slice() {
        return vs.get(1).map_or(true, |&w| pr::same_velocity(w, v0))
            && vs.iter().fold(true, |ok, &w| ok & pr::same_velocity(w, v0));
    }
    (1..n).all(|i| pr::same_velocity(vels.vertex(i), v0))
}

/// Paper A §II.F and §III: the detector that decides a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// §II.H, statically shaped polygon.
    DetectSame2d,
    /// §II.I, warping polygon.
    DetectDiff2d,
    /// §III, with a slab.
    Detect3d,
}

impl Method {
    /// The paper's name in snake case.
    pub fn name(self) -> &'static str {
        match self {
            Method::DetectSame2d => "detect_same_2d",
            Method::DetectDiff2d => "detect_diff_2d",
            Method::Detect3d => "detect_3d",
        }
    }
}

/// Paper A §II.F and §III: the detector for a case. detect_3D when the point has a
/// height and the polygon a slab (`vertical`), else detect_same_2D when every vertex
/// velocity is the same ([`statically_shaped`]), else detect_diff_2D. The one place the
/// choice is made: `api` and [`detect_3d`] (for its 2D part) both ask here.
///
/// ```
/// use polyguard::{dispatch, Method, Vect2};
/// let rigid = [Vect2::new(1.0, 0.0); 3];
/// let warping = [Vect2::ZERO, Vect2::new(0.1, 0.0), Vect2::ZERO];
/// assert_eq!(dispatch(false, &rigid[..]), Method::DetectSame2d);
/// assert_eq!(dispatch(false, &warping[..]), Method::DetectDiff2d);
/// assert_eq!(dispatch(true, &rigid[..]), Method::Detect3d);
/// ```
pub fn dispatch<V: VertexSeq + ?Sized>(vertical: bool, vels: &V) -> Method {
    if vertical {
        Method::Detect3d
    } else if statically_shaped(vels) {
        Method::DetectSame2d
    } else {
        Method::DetectDiff2d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vect2::Vect2;
    use polyguard_oracle::convert::q;
    use polyguard_oracle::Q;

    /// The exact value of a finite float.
    pub(super) fn exact(x: f64) -> Q {
        q(x).expect("a finite float")
    }

    /// ±m·2^e.
    pub(super) fn float(neg: bool, m: f64, e: i32) -> f64 {
        let x = m * 2f64.powi(e);
        if neg {
            -x
        } else {
            x
        }
    }

    /// (x, y).
    pub(super) fn v(x: f64, y: f64) -> Vect2 {
        Vect2::new(x, y)
    }

    /// `decided_by` in the detect answer is [`Method::name`]: every method's name is one the
    /// answer's schema (docs/schema/detect-answer.schema.json) allows, and each method has
    /// its own.
    #[test]
    fn method_names_are_the_answer_schemas() {
        let schema = include_str!("../../docs/schema/detect-answer.schema.json");
        let names =
            [Method::DetectSame2d, Method::DetectDiff2d, Method::Detect3d].map(Method::name);
        for n in names {
            assert!(
                !n.is_empty() && schema.contains(&format!("\"{n}\"")),
                "{n:?}"
            );
        }
        assert!(names[0] != names[1] && names[1] != names[2] && names[0] != names[2]);
    }
}
