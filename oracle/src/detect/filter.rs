//! Paper A §II.I: the filter in front of edge_detect_simp, an early "no" that is proven
//! sound (it never changes the answer, it only skips work).

use core::cmp::Ordering;

use crate::field::{Arith, V2};
use crate::kernel::{and, or, Kernel};

/// Paper A §II.I support: a proven-sound early "false" for edge_detect_simp (it
/// never changes the answer, it only skips work; taken only when decided).
///
/// Proof. Let u = aa + t·bb, w = ww + t·vv. If u ≠ 0 and both inequalities (1)
/// hold, then writing w in the orthogonal basis u, u^⊥ gives
/// ‖w‖² = ((w·u)² + (w·u^⊥)²)/‖u‖² ≤ ((1 + F)² + F²)‖u‖² ≤ (1 + 2F)²‖u‖².
/// When aa × bb ≠ 0, u is never 0. ‖u‖ ≤ |u_x| + |u_y|, a convex function of t,
/// so ‖u‖ ≤ M = max over t ∈ {0, T} of |u_x| + |u_y|. If one coordinate of w
/// (linear in t) exceeds (1 + 2F)·M in absolute value, with the same sign, at
/// t = 0 and at t = T, then ‖w‖ > (1 + 2F)‖u‖ on all of [0, T]: no t satisfies (1).
pub fn far_from_edge<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    f: &N,
) -> Result<bool, K::Abstain> {
    if k.sign(&aa.cross(bb))? == Ordering::Equal {
        return Ok(false);
    }
    let u_t = aa.at(bb, t);
    let m0 = k.abs(&aa.x).plus(&k.abs(&aa.y));
    let m1 = k.abs(&u_t.x).plus(&k.abs(&u_t.y));
    let (_, m) = k.hull(&[&m0, &m1]);
    let r = m.plus(&m.times(&f.twice()));
    let nr = r.negated();
    let w_t = ww.at(vv, t);
    let beyond = |a: &N, b: &N| {
        or(and(k.lt(&r, a), || k.lt(&r, b)), || {
            and(k.lt(a, &nr), || k.lt(b, &nr))
        })
    };
    or(beyond(&ww.x, &w_t.x), || beyond(&ww.y, &w_t.y))
}
