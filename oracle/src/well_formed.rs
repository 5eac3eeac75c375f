//! Paper A §II.J: is a 2D polygon well formed?

use core::cmp::Ordering;

use crate::field::{Arith, ExactField, V2};
use crate::kernel::interval::{edge_boxes, enclose, enclose2, near_pairs, point_boxes};
use crate::kernel::{and, certainly, Decided, Exact, Intervals, Iv, Kernel};
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
/// fewer than 3 vertices); the same fault as [`well_formed_fault_pairwise`], found in
/// O(n log n + k) for the k pairs a sweep finds near (it extends §II.J, which compares
/// every pair).
///
/// Rules 1 and 2 are asked only of the pairs a box sweep finds within reach (2·|BUFF|
/// for vertices, |BUFF| for edges), in increasing order, the first failure winning as in
/// the pairwise loops. Nothing is missed: both rules say "too close" only with a witness,
/// two points of the pair closer than 2·|BUFF| (rule 1: ‖p − q‖² < 4·BUFF²) or than
/// |BUFF| (rule 2: every yes of `segments_close`, its end-point tests and its
/// quadratics alike, is a point pair at distance² below BUFF²), and such points are
/// within that reach on both axes, so their boxes are too. Each test of rules 1–3 runs
/// in the interval kernel first and in the exact kernel when that one abstains, so
/// every decision is the exact one.
pub fn well_formed_fault<F: ExactField>(p: &[V2<F>], buff: &F, cos_kappa: &F) -> Option<Fault> {
    if p.len() < SWEEP_MIN_VERTICES {
        return well_formed_fault_pairwise(p, buff, cos_kappa);
    }
    well_formed_fault_skipping(p, buff, cos_kappa, &|_, _, _| false)
}

/// [`well_formed_fault`]'s sweep at any size, leaving out the candidate pairs for which
/// `skip(rule, i, j)` holds (rule 1 or 2): the hook of the tests' canary, which shows
/// that a broad phase wrong by one pair is caught by the comparison with
/// [`well_formed_fault_pairwise`]. `&|_, _, _| false` is the sweep itself.
/// (Paper A §II.J, extended as [`well_formed_fault`] says.)
#[doc(hidden)]
pub fn well_formed_fault_skipping<F: ExactField>(
    p: &[V2<F>],
    buff: &F,
    cos_kappa: &F,
    skip: &dyn Fn(u8, usize, usize) -> bool,
) -> Option<Fault> {
    let n = p.len();
    if n < 3 {
        return None;
    }
    let ip: Vec<V2<Iv>> = p.iter().map(enclose2).collect();
    let ib = enclose(buff);
    let boxes = point_boxes(p);
    // Step 1: vertices pairwise at least 2·BUFF apart. The least failing pair is the
    // pairwise loop's first; pairs above one found need no test.
    let four_b2 = F::from_i64(4).times(&buff.sq());
    let four_b2_iv = Iv::from_i64(4).times(&ib.sq());
    let mut first: Option<(usize, usize)> = None;
    near_pairs(&boxes, &buff.twice(), |i, j| {
        if first.is_some_and(|f| f <= (i, j)) || skip(1, i, j) {
            return;
        }
        let close = match Intervals.lt(&ip[i].minus(&ip[j]).sq(), &four_b2_iv) {
            Ok(c) => c,
            Err(_) => p[i].minus(&p[j]).sq() < four_b2,
        };
        if close {
            first = Some((i, j));
        }
    });
    if let Some((i, j)) = first {
        return Some(Fault::CloseVertices(i, j));
    }
    // Step 2: non-adjacent edges farther than BUFF apart.
    let next = |i: usize| (i + 1) % n;
    let lines: Vec<EdgeLine<Iv>> = (0..n)
        .map(|i| EdgeLine::new(&ip[i], &ip[next(i)], &ib))
        .collect();
    near_pairs(&edge_boxes(&boxes), buff, |i, k| {
        let adjacent = k == i + 1 || (i == 0 && k == n - 1);
        if adjacent || first.is_some_and(|f| f <= (i, k)) || skip(2, i, k) {
            return;
        }
        let (a, b, c, d) = (&ip[i], &ip[next(i)], &ip[k], &ip[next(k)]);
        if certainly(beyond_line(&Intervals, &lines[i], c, d))
            || certainly(beyond_line(&Intervals, &lines[k], a, b))
        {
            return;
        }
        let close = match segments_close(&Intervals, a, b, c, d, &ib) {
            Ok(c) => c,
            Err(_) => {
                segments_close(&Exact, &p[i], &p[next(i)], &p[k], &p[next(k)], buff).decided()
            }
        };
        if close {
            first = Some((i, k));
        }
    });
    if let Some((i, k)) = first {
        return Some(Fault::CloseEdges(i, k));
    }
    // Step 3: no corner sharper than κ.
    let ck = enclose(cos_kappa);
    for j in 0..n {
        let i = (j + n - 1) % n;
        let k = next(j);
        let (g, h) = (ip[j].minus(&ip[i]), ip[k].minus(&ip[j]));
        // g·h + cos κ·√(g²h²) < 0, certified on the enclosures, else exactly.
        let sharp = match g.dot(&h).add(ck.mul(g.sq().mul(h.sq()).sqrt())).sign() {
            Ok(o) => o == Ordering::Less,
            Err(_) => sharp_corner(&p[j].minus(&p[i]), &p[k].minus(&p[j]), cos_kappa),
        };
        if sharp {
            return Some(Fault::SharpCorner(j));
        }
    }
    turns_right(p)
}

/// The line through an edge c d, for [`beyond_line`]: c, u = d − c and BUFF²·‖u‖²,
/// computed once per edge (an edge's box may meet thousands of others).
struct EdgeLine<N> {
    c: V2<N>,
    u: V2<N>,
    reach: N,
}

impl<N: Arith> EdgeLine<N> {
    /// The line of the edge c d at distance BUFF (paper A §II.G's reach).
    fn new(c: &V2<N>, d: &V2<N>, buff: &N) -> Self {
        let u = d.minus(c);
        let reach = buff.sq().times(&u.sq());
        EdgeLine {
            c: c.clone(),
            u,
            reach,
        }
    }
}

/// Whether the segment e f lies on one side of the line of an edge c d, every point of
/// it farther than |BUFF| from that line, so farther than |BUFF| from the segment c d:
/// then `segments_close` (paper A §II.G), whose every yes is a pair of points closer than
/// |BUFF|, says no. With s(x) = (d − c) × (x − c), affine in x and |BUFF|·‖d − c‖ away
/// from 0 exactly at distance |BUFF| from the line: s(e)·s(f) > 0 and both
/// s² > BUFF²·‖d − c‖² (a point c = d passes neither). A cheap test in front of
/// §II.G's quadratics, for long edges whose boxes meet many (it extends paper A §II.J's
/// rule 2).
fn beyond_line<N: Arith, K: Kernel<N>>(
    k: &K,
    line: &EdgeLine<N>,
    e: &V2<N>,
    f: &V2<N>,
) -> Result<bool, K::Abstain> {
    let se = line.u.cross(&e.minus(&line.c));
    let sf = line.u.cross(&f.minus(&line.c));
    and(k.is_pos(&se.times(&sf)), || {
        and(k.lt(&line.reach, &se.sq()), || k.lt(&line.reach, &sf.sq()))
    })
}

/// Below this many vertices rules 1 and 2 compare every pair (the sweep's sorting and
/// enclosures cost more than they save).
const SWEEP_MIN_VERTICES: usize = 32;

/// Paper A §II.J step 4: a left turn at the extremal vertex (counterclockwise order):
/// the fault when (p_i − p_prev)·(p_next − p_i)^⊥ ≤ 0.
fn turns_right<F: ExactField>(p: &[V2<F>]) -> Option<Fault> {
    let n = p.len();
    let i = extremal_vertex(p)?;
    let prev = &p[(i + n - 1) % n];
    let next = &p[(i + 1) % n];
    let turn = p[i].minus(prev).cross(&next.minus(&p[i]));
    (!turn.is_pos()).then_some(Fault::TurnsRight(i))
}

/// Paper A §II.J: the first rule broken, in the paper's order (`None`: well formed, or
/// fewer than 3 vertices), comparing every pair of vertices and of edges (rules 1 and 2
/// in O(n²) exact tests, as the paper states them): the reference that
/// [`well_formed_fault`]'s sweep is tested against.
pub fn well_formed_fault_pairwise<F: ExactField>(
    p: &[V2<F>],
    buff: &F,
    cos_kappa: &F,
) -> Option<Fault> {
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
    turns_right(p)
}
