//! Paper A §II.J: is a 2D polygon well formed?

use core::cmp::Ordering;

use crate::field::{ExactField, V2};
use crate::proximity::segments_close;
use crate::qfield::sign1;

/// Paper A §II.J step 3: is the corner between edges g = p_j − p_i and
/// h = p_k − p_j sharper than κ, i.e. g·h < −cos κ·‖g‖·‖h‖ (exact: the sign of
/// g·h + cos κ·√(g²h²) by sign analysis, no square root taken)?
pub fn sharp_corner<F: ExactField>(g: &V2<F>, h: &V2<F>, cos_kappa: &F) -> bool {
    let gh = g.dot(h);
    let d = g.sq().times(&h.sq());
    sign1(&gh, cos_kappa, &d) == Ordering::Less
}

/// Paper A §II.J: the extremal vertex, the lexicographic minimum (least x, then
/// least y). The paper's "p_jx ≥ p_ix and p_jy > p_iy for every other j" need
/// not exist; the lexicographic minimum always does and is a convex-hull vertex.
pub fn extremal_vertex<F: ExactField>(poly: &[V2<F>]) -> Option<usize> {
    (0..poly.len()).min_by(|&i, &j| {
        poly[i]
            .x
            .cmp(&poly[j].x)
            .then_with(|| poly[i].y.cmp(&poly[j].y))
    })
}

/// Paper A §II.J: well_formed(P, BUFF) with the angle threshold given as cos κ.
pub fn well_formed<F: ExactField>(poly: &[V2<F>], buff: &F, cos_kappa: &F) -> bool {
    let n = poly.len();
    if n < 3 {
        return false;
    }
    // Step 1: vertices pairwise at least 2·BUFF apart.
    let four_b2 = F::from_i64(4).times(&buff.sq());
    for i in 0..n {
        for j in (i + 1)..n {
            if poly[i].minus(&poly[j]).sq() < four_b2 {
                return false;
            }
        }
    }
    // Step 2: non-adjacent edges farther than BUFF apart.
    for i in 0..n {
        for k in (i + 1)..n {
            let adjacent = k == i + 1 || (i == 0 && k == n - 1);
            if adjacent {
                continue;
            }
            let (pi, pj) = (&poly[i], &poly[(i + 1) % n]);
            let (pq, pk) = (&poly[k], &poly[(k + 1) % n]);
            if segments_close(pi, pj, pq, pk, buff) {
                return false;
            }
        }
    }
    // Step 3: no corner sharper than κ.
    for j in 0..n {
        let i = (j + n - 1) % n;
        let k = (j + 1) % n;
        let g = poly[j].minus(&poly[i]);
        let h = poly[k].minus(&poly[j]);
        if sharp_corner(&g, &h, cos_kappa) {
            return false;
        }
    }
    // Step 4: a left turn at the extremal vertex (counterclockwise order):
    // fail when (p_i − p_prev)·(p_next − p_i)^⊥ ≤ 0.
    let Some(i) = extremal_vertex(poly) else {
        return false;
    };
    let prev = &poly[(i + n - 1) % n];
    let next = &poly[(i + 1) % n];
    let turn = poly[i].minus(prev).cross(&next.minus(&poly[i]));
    turn.is_pos()
}
