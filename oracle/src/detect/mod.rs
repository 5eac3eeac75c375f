//! Paper A §II.F: the choice of detector for a case ([`dispatch`]) and the steps the 2D
//! detectors are made of, and the detectors, one module per section of the paper, as
//! in the engine: `same` (§II.H, statically shaped polygons), `warping` (§II.I, warping
//! polygons) with the filter in front of edge_detect_simp (`filter`), and `slab` (§III,
//! 3D). Every public item is re-exported here, so its path is `detect::name`.

mod filter;
mod same;
mod slab;
mod warping;

pub use filter::far_from_edge;
pub use same::detect_same_2d;
pub(crate) use slab::slab_scene;
pub use slab::{detect_3d, slab_window};
pub use warping::{
    detect_diff_2d, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp,
    edge_detect_simp_without_shortcut,
};

use same::same_2d;
use warping::diff_2d;

use crate::contain::definitely_outside;
use crate::field::{Arith, V2};
use crate::kernel::run::{Runner, Scene, Unit};
use crate::kernel::{all, eq2, not, Kernel};
use crate::proximity::segments_close;

/// Paper A §II.I: the sign σ (or ε) = ±1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// −1.
    Neg,
    /// +1.
    Pos,
}

impl Sign {
    /// Paper A §II.I: both signs, −1 then +1.
    pub const BOTH: [Sign; 2] = [Sign::Neg, Sign::Pos];

    /// Paper A §II.I: the other sign.
    pub fn flip(self) -> Sign {
        match self {
            Sign::Neg => Sign::Pos,
            Sign::Pos => Sign::Neg,
        }
    }
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
    /// Paper A §II.F and §III: the paper's name in snake case.
    pub fn name(self) -> &'static str {
        match self {
            Method::DetectSame2d => "detect_same_2d",
            Method::DetectDiff2d => "detect_diff_2d",
            Method::Detect3d => "detect_3d",
        }
    }
}

/// Paper A §II.I: an interval of times returned by dot_nn_lin / dot_nn, with ends
/// of a kernel's root type (exact algebraic numbers, or enclosures).
///
/// The paper encodes "empty" as the pair (T, 0). That is only empty when T > 0:
/// detect_3D calls the 2D functions with lookahead b − a, which is 0 when the
/// slab window is a single instant, and then (T, 0) = (0, 0) would read as the
/// non-empty interval [0, 0]. Emptiness is therefore explicit here.
#[derive(Clone, Debug)]
pub enum Interval<R> {
    /// No time.
    Empty,
    /// The closed interval [lb, ub] with lb ≤ ub, both in [0, T].
    Closed {
        /// Lower end.
        lb: R,
        /// Upper end.
        ub: R,
    },
}

impl<R> Interval<R> {
    /// Paper A §II.I support: whether the interval holds no time.
    pub fn is_empty(&self) -> bool {
        matches!(self, Interval::Empty)
    }
}

/// Paper A §II.H and §II.I: one step of detect_same_2D or detect_diff_2D, each one
/// paper-function call (the grain at which a filtered run falls back to exact).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Step {
    /// Step 1 of both: s not definitely outside P.
    Inside0,
    /// detect_same_2D step 2: s + T·v not definitely outside P + T·V.
    InsideT,
    /// detect_same_2D step 3: segments_close(s, s + T·(v − v_i), p_i, p_{i+1}, BUFF).
    PathClose(usize),
    /// detect_diff_2D: edge_detect on the edge p_i p_{i+1}.
    Edge(usize),
}

impl Unit for Step {
    type Out<R> = bool;

    fn run<N: Arith, K: Kernel<N>>(&self, k: &K, sc: &Scene<'_, N>) -> Result<bool, K::Abstain> {
        let next = |i: usize| (i + 1) % sc.p.len();
        match *self {
            Step::Inside0 => not(definitely_outside(k, &sc.p, &sc.s, &sc.buff)),
            Step::InsideT => {
                let moved: Vec<V2<N>> =
                    sc.p.iter()
                        .zip(sc.vels.iter())
                        .map(|(p, w)| p.at(w, &sc.t))
                        .collect();
                not(definitely_outside(
                    k,
                    &moved,
                    &sc.s.at(&sc.v, &sc.t),
                    &sc.buff,
                ))
            }
            Step::PathClose(i) => {
                let end = sc.s.at(&sc.v.minus(&sc.vels[i]), &sc.t);
                segments_close(k, &sc.s, &end, &sc.p[i], &sc.p[next(i)], &sc.buff)
            }
            Step::Edge(i) => {
                let (p, w, j) = (&sc.p, &sc.vels, next(i));
                edge_detect(k, &sc.t, &sc.s, &sc.v, &p[i], &p[j], &w[i], &w[j], &sc.f)
            }
        }
    }

    fn map_root<A, B>(out: bool, _: impl FnMut(A) -> B) -> bool {
        out
    }
}

/// Paper A §II.H / §II.I: the 2D detector of `method` (detect_same_2D for
/// [`Method::DetectSame2d`], detect_diff_2D otherwise), its steps run by `r`.
pub(crate) fn detect_2d<R: Runner>(r: &R, method: Method) -> Result<bool, R::Abstain> {
    match method {
        Method::DetectSame2d => same_2d(r),
        _ => diff_2d(r),
    }
}

/// Paper A §II.F: whether all vertex velocities are equal (a statically shaped polygon).
pub fn statically_shaped<N: Arith, K: Kernel<N>>(
    k: &K,
    vels: &[V2<N>],
) -> Result<bool, K::Abstain> {
    all(vels.windows(2).map(|w| eq2(k, &w[0], &w[1])))
}

/// Paper A §II.F and §III: the detector for a case — detect_3D when the point has a
/// height and the polygon a slab (`vertical`), else detect_same_2D when every vertex
/// velocity is the same ([`statically_shaped`]), else detect_diff_2D. The one place
/// the choice is made: [`crate::paper_detect`] and [`detect_3d`] (for its 2D part)
/// both ask here.
pub fn dispatch<N: Arith, K: Kernel<N>>(
    k: &K,
    vertical: bool,
    vels: &[V2<N>],
) -> Result<Method, K::Abstain> {
    Ok(if vertical {
        Method::Detect3d
    } else if statically_shaped(k, vels)? {
        Method::DetectSame2d
    } else {
        Method::DetectDiff2d
    })
}
