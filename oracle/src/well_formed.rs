//! Paper A §II.J: is a 2D polygon well formed?

use core::cmp::Ordering;

use crate::field::{ExactField, V2};
use crate::kernel::{Decided, Exact};
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
pub fn extremal_vertex<F: ExactField>(p: &[V2<F>]) -> Option<usize> {
    (0..p.len()).min_by(|&i, &j| p[i].x.cmp(&p[j].x).then_with(|| p[i].y.cmp(&p[j].y)))
}

/// Which rule of paper A §II.J a polygon breaks (vertex indices from 0); the engine's
/// `well_formed::Fault`, decided exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// Rule 1: vertices i and j are closer than 2·BUFF.
    CloseVertices(usize, usize),
    /// Rule 2: the edges starting at vertices i and k (not neighbours) come within BUFF.
    CloseEdges(usize, usize),
    /// Rule 3: the corner at vertex j is sharper than κ.
    SharpCorner(usize),
    /// Rule 4: no left turn at the extremal vertex m.
    TurnsRight(usize),
}

impl core::fmt::Display for Fault {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            Fault::CloseVertices(i, j) => {
                write!(
                    f,
                    "§II.J rule 1: vertices {i} and {j} are closer than 2·BUFF"
                )
            }
            Fault::CloseEdges(i, k) => write!(
                f,
                "§II.J rule 2: the edges from vertex {i} and from vertex {k} come within BUFF"
            ),
            Fault::SharpCorner(j) => {
                write!(
                    f,
                    "§II.J rule 3: the corner at vertex {j} is sharper than κ"
                )
            }
            Fault::TurnsRight(m) => write!(
                f,
                "§II.J rule 4: the polygon does not turn left at its extremal vertex {m}"
            ),
        }
    }
}

/// Paper A §II.J: well_formed(P, BUFF) with the angle threshold given as cos κ.
pub fn well_formed<F: ExactField>(p: &[V2<F>], buff: &F, cos_kappa: &F) -> bool {
    p.len() >= 3 && well_formed_fault(p, buff, cos_kappa).is_none()
}

/// Paper A §II.J: the first rule broken, in the paper's order (`None`: well formed, or
/// fewer than 3 vertices).
pub fn well_formed_fault<F: ExactField>(p: &[V2<F>], buff: &F, cos_kappa: &F) -> Option<Fault> {
    let n = p.len();
    if n < 3 {
        return None;
    }
    // Step 1: vertices pairwise at least 2·BUFF apart.
    let four_b2 = F::from_i64(4).times(&buff.sq());
    for i in 0..n {
        for j in (i + 1)..n {
            if p[i].minus(&p[j]).sq() < four_b2 {
                return Some(Fault::CloseVertices(i, j));
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
            let (pi, pj) = (&p[i], &p[(i + 1) % n]);
            let (pq, pk) = (&p[k], &p[(k + 1) % n]);
            if segments_close(&Exact, pi, pj, pq, pk, buff).decided() {
                return Some(Fault::CloseEdges(i, k));
            }
        }
    }
    // Step 3: no corner sharper than κ.
    for j in 0..n {
        let i = (j + n - 1) % n;
        let k = (j + 1) % n;
        let g = p[j].minus(&p[i]);
        let h = p[k].minus(&p[j]);
        if sharp_corner(&g, &h, cos_kappa) {
            return Some(Fault::SharpCorner(j));
        }
    }
    // Step 4: a left turn at the extremal vertex (counterclockwise order):
    // fail when (p_i − p_prev)·(p_next − p_i)^⊥ ≤ 0.
    let i = extremal_vertex(p)?;
    let prev = &p[(i + n - 1) % n];
    let next = &p[(i + 1) % n];
    let turn = p[i].minus(prev).cross(&next.minus(&p[i]));
    (!turn.is_pos()).then_some(Fault::TurnsRight(i))
}
