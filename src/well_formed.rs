//! Paper A §II.J: is the polygon well formed?

use crate::polygon::VertexSeq;
use crate::predicates as pr;
use crate::proximity::segments_close;

/// Are edges i→i+1 and k→k+1 adjacent (sharing a vertex) in an n-gon?
#[inline(always)]
fn adjacent(i: usize, k: usize, n: usize) -> bool {
    i == k || (i + 1) % n == k || (k + 1) % n == i
}

/// Which rule of paper A §II.J a polygon breaks (vertex indices from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// Rule 1: vertices i and j are closer than 2·BUFF.
    CloseVertices(usize, usize),
    /// Rule 2: the edges starting at vertices i and k (not neighbours) come within BUFF.
    CloseEdges(usize, usize),
    /// Rule 3: the corner at vertex j is sharper than κ.
    SharpCorner(usize),
    /// Rule 4: the polygon turns right (or goes straight) at its extremal vertex m.
    TurnsRight(usize),
}

#[cfg(feature = "std")]
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

/// Paper A §II.J well_formed(P, BUFF) with the corner angle κ given as cos κ.
///
/// False when: (1) two vertices are closer than 2·BUFF; (2) two non-adjacent edges are
/// segments_close; (3) consecutive edges g, h make a corner sharper than κ,
/// g·h < −cos κ·‖g‖·‖h‖; (4) the polygon turns right (or goes straight) at its extremal
/// vertex. The printed extremal-vertex rule ("p_jx ≥ p_ix and p_jy > p_iy for every
/// other j") has no solution for most polygons; the lexicographic minimum (least x,
/// then least y) is meant: it is a vertex of the convex hull, where a counterclockwise
/// polygon turns left. Step 4's printed "(p_i − p_(i−1)*)·(p_(i+1)* − p_i)⊥ ≤ 0" uses
/// the right perpendicular: the cross product of the incoming and outgoing edges.
///
/// ```
/// use polyguard::{well_formed, Vect2};
/// let cos_kappa = 5f64.to_radians().cos();
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// assert!(well_formed(&square[..], 0.01, cos_kappa));
/// // BUFF so large that the vertices are closer than 2·BUFF (rule 1)
/// assert!(!well_formed(&square[..], 1.5, cos_kappa));
/// ```
pub fn well_formed<P: VertexSeq + ?Sized>(p: &P, buff: f64, cos_kappa: f64) -> bool {
    p.count() >= 3 && well_formed_fault(p, buff, cos_kappa).is_none()
}

/// Paper A §II.J: the first rule [`well_formed`] finds broken, in the paper's order
/// (`None`: well formed, or fewer than 3 vertices, which no rule speaks of).
pub fn well_formed_fault<P: VertexSeq + ?Sized>(p: &P, buff: f64, cos_kappa: f64) -> Option<Fault> {
    let n = p.count();
    if n < 3 {
        return None;
    }
    #[cfg(feature = "std")]
    if n >= SWEEP_MIN_VERTICES {
        if let Some(found) = sweep::close_pairs(p, buff) {
            return found.or_else(|| corner_and_turn(p, cos_kappa));
        }
    }
    well_formed_fault_pairwise(p, buff, cos_kappa)
}

/// [`well_formed_fault`] comparing every pair of vertices and of edges (rules 1 and 2 in
/// O(n²), as the paper states them): what the `no_std` build and polygons of fewer than
/// 48 vertices use, and the reference the sweep is tested against.
pub fn well_formed_fault_pairwise<P: VertexSeq + ?Sized>(
    p: &P,
    buff: f64,
    cos_kappa: f64,
) -> Option<Fault> {
    let n = p.count();
    if n < 3 {
        return None;
    }
    for i in 0..n {
        for j in (i + 1)..n {
            if pr::vertices_too_close(p.vertex(i), p.vertex(j), buff) {
                return Some(Fault::CloseVertices(i, j));
            }
        }
    }
    for i in 0..n {
        for k in (i + 1)..n {
            if adjacent(i, k, n) {
                continue;
            }
            let (a, b) = (p.vertex(i), p.vertex(p.next(i)));
            let (c, d) = (p.vertex(k), p.vertex(p.next(k)));
            if segments_close(a, b, c, d, buff) {
                return Some(Fault::CloseEdges(i, k));
            }
        }
    }
    corner_and_turn(p, cos_kappa)
}

/// Below this many vertices rules 1 and 2 compare every pair (the sweep's sorting costs
/// more than it saves).
#[cfg(feature = "std")]
const SWEEP_MIN_VERTICES: usize = 48;

/// §II.J rules 3 and 4 (linear in n), after rules 1 and 2 found nothing.
fn corner_and_turn<P: VertexSeq + ?Sized>(p: &P, cos_kappa: f64) -> Option<Fault> {
    let n = p.count();
    for j in 0..n {
        let i = if j == 0 { n - 1 } else { j - 1 };
        let k = p.next(j);
        let g = p.vertex(j) - p.vertex(i);
        let h = p.vertex(k) - p.vertex(j);
        if pr::corner_too_sharp(g, h, cos_kappa) {
            return Some(Fault::SharpCorner(j));
        }
    }
    let mut m = 0;
    for i in 1..n {
        if pr::lex_less(p.vertex(i), p.vertex(m)) {
            m = i;
        }
    }
    let prev = p.vertex(if m == 0 { n - 1 } else { m - 1 });
    pr::turns_right_or_straight(prev, p.vertex(m), p.vertex(p.next(m)))
        .then_some(Fault::TurnsRight(m))
}

/// §II.J rules 1 and 2 in O(n log n + k) for k nearby pairs (a quadratic
/// comparison of every pair takes seconds at 64k vertices): the same predicates
/// on the pairs a sweep along the polygon's longer axis finds near, and the same fault,
/// the first in the paper's order (the least pair `(i, j)` of the first rule broken).
///
/// **Nothing is missed.** Rule 1's predicate is f64 `‖p − q‖² < 4·BUFF²`: when it holds,
/// `|Δx| ≤ 2·|BUFF|·(1 + 4u)` along either axis (the sum of two rounded squares is at
/// least either one rounded, each within `u` relative). Rule 2's `segments_close` says
/// yes only when the segments are closer than BUFF or within its certificate's rounding
/// of it, a few dozen units of `u` times the coordinates' magnitude. So a pair is left
/// out only when its boxes are more than `2·|BUFF|·(1 + 2⁻⁴⁰) + 2⁻⁴⁰·S` apart along the
/// sweep axis (rule 2: `|BUFF|` in place of `2·|BUFF|`), `S` the largest coordinate
/// magnitude: far beyond both. Non-finite coordinates, and BUFF below 0 or not finite,
/// fall back to every pair.
#[cfg(feature = "std")]
mod sweep {
    extern crate std;
    use super::{adjacent, Fault};
    use crate::polygon::VertexSeq;
    use crate::predicates as pr;
    use crate::proximity::segments_close;
    use crate::sweep::{along_x, near_pairs, Item};
    use std::vec::Vec;

    /// Rules 1 and 2 by the sweep: `Some(fault or None)`, or `None` when the inputs are
    /// not finite or BUFF is below 0 (the caller then compares every pair).
    pub(super) fn close_pairs<P: VertexSeq + ?Sized>(p: &P, buff: f64) -> Option<Option<Fault>> {
        let n = p.count();
        let mut scale: f64 = 0.0;
        for i in 0..n {
            let v = p.vertex(i);
            if !(v.x.is_finite() && v.y.is_finite()) {
                return None;
            }
            scale = scale.max(v.x.abs()).max(v.y.abs());
        }
        // BUFF below 0 (outside paper A's domain) makes segments_close undecided, so yes,
        // for every pair: only the pairwise rules say which pair is first
        if !(buff >= 0.0 && buff.is_finite()) {
            return None;
        }
        let x = along_x((0..n).map(|i| p.vertex(i)));
        let slack = scale * 2f64.powi(-40);
        let grow = 1.0 + 2f64.powi(-40);
        // rule 1
        let verts: Vec<Item> = (0..n)
            .map(|i| Item::of(p.vertex(i), p.vertex(i), i, x))
            .collect();
        let mut first: Option<(usize, usize)> = None;
        near_pairs(verts, 2.0 * buff * grow + slack, |i, j| {
            if first.is_some_and(|f| f <= (i, j)) {
                return;
            }
            if pr::vertices_too_close(p.vertex(i), p.vertex(j), buff) {
                first = Some((i, j));
            }
        });
        if let Some((i, j)) = first {
            return Some(Some(Fault::CloseVertices(i, j)));
        }
        // rule 2
        let edges: Vec<Item> = (0..n)
            .map(|i| Item::of(p.vertex(i), p.vertex(p.next(i)), i, x))
            .collect();
        near_pairs(edges, buff * grow + slack, |i, k| {
            if adjacent(i, k, n) || first.is_some_and(|f| f <= (i, k)) {
                return;
            }
            let (a, c) = (p.vertex(i), p.vertex(p.next(i)));
            let (d, e) = (p.vertex(k), p.vertex(p.next(k)));
            if segments_close(a, c, d, e, buff) {
                first = Some((i, k));
            }
        });
        Some(first.map(|(i, k)| Fault::CloseEdges(i, k)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vect2::Vect2;
    fn v(x: f64, y: f64) -> Vect2 {
        Vect2::new(x, y)
    }
    const COS_10_DEG: f64 = 0.984_807_753_012_208;

    /// A fault names its rule of §II.J and the vertices or edges, as the CLI prints it.
    #[cfg(feature = "std")]
    #[test]
    fn faults_name_their_rule_and_indices() {
        let text = |f: Fault| format!("{f}");
        assert!(text(Fault::CloseVertices(0, 2)).contains("rule 1: vertices 0 and 2"));
        assert!(text(Fault::CloseEdges(1, 3)).contains("rule 2"));
        assert!(text(Fault::SharpCorner(4)).contains("rule 3"));
        assert!(text(Fault::TurnsRight(5)).contains("rule 4"));
    }

    #[test]
    fn square_is_well_formed_clockwise_is_not() {
        let ccw = [v(0.0, 0.0), v(4.0, 0.0), v(4.0, 4.0), v(0.0, 4.0)];
        assert!(well_formed(&ccw[..], 0.1, COS_10_DEG));
        let cw = [v(0.0, 0.0), v(0.0, 4.0), v(4.0, 4.0), v(4.0, 0.0)];
        assert!(!well_formed(&cw[..], 0.1, COS_10_DEG));
    }

    /// §II.J step 4 takes the turn at the lexicographically least vertex (least x, then
    /// least y): with several vertices at the least x, the others may be straight (a
    /// vertex in the middle of the left edge) or not extreme at all.
    #[test]
    fn the_extreme_vertex_is_lexicographically_least() {
        // a vertex in the middle of the left edge, before and after the least one in the
        // ring's order, and the least one first or last
        for ring in [
            [
                v(0.0, 0.0),
                v(4.0, 0.0),
                v(4.0, 4.0),
                v(0.0, 4.0),
                v(0.0, 2.0),
            ],
            [
                v(0.0, 2.0),
                v(0.0, 0.0),
                v(4.0, 0.0),
                v(4.0, 4.0),
                v(0.0, 4.0),
            ],
            [
                v(4.0, 0.0),
                v(4.0, 4.0),
                v(0.0, 4.0),
                v(0.0, 2.0),
                v(0.0, 0.0),
            ],
        ] {
            assert_eq!(
                well_formed_fault(&ring[..], 0.1, COS_10_DEG),
                None,
                "{ring:?}"
            );
        }
        // a chevron, counterclockwise, its reflex vertex (2, 1) lower than the first
        // vertex (0, 4) and right of the least one (0, 0): only the least one tells
        let chevron = [
            v(0.0, 4.0),
            v(0.0, 0.0),
            v(4.0, 0.0),
            v(4.0, 4.0),
            v(2.0, 1.0),
        ];
        assert_eq!(well_formed_fault(&chevron[..], 0.1, COS_10_DEG), None);
        // clockwise, with the least x shared: still found to turn right
        let cw = [
            v(0.0, 2.0),
            v(0.0, 4.0),
            v(4.0, 4.0),
            v(4.0, 0.0),
            v(0.0, 0.0),
        ];
        assert!(matches!(
            well_formed_fault(&cw[..], 0.1, COS_10_DEG),
            Some(Fault::TurnsRight(_))
        ));
    }

    #[test]
    fn bow_tie_and_close_vertices_are_not() {
        // Edges (0,0)-(4,0) ... the bow tie (0,0),(4,4),(4,0),(0,4) has crossing
        // non-adjacent edges (0,0)-(4,4) and (4,0)-(0,4).
        let bow = [v(0.0, 0.0), v(4.0, 4.0), v(4.0, 0.0), v(0.0, 4.0)];
        assert!(!well_formed(&bow[..], 0.1, COS_10_DEG));
        // Two vertices 0.15 apart with BUFF 0.1 (< 2·BUFF).
        let close = [v(0.0, 0.0), v(4.0, 0.0), v(4.0, 0.15), v(4.0, 4.0)];
        assert!(!well_formed(&close[..], 0.1, COS_10_DEG));
    }

    #[test]
    fn sharp_corner_is_not() {
        // A sliver triangle with a 2.86° apex at (10, 0.5)... corner at (0,0)/(10,0)/(0,1):
        // the angle at (10,0) is atan(1/10) ≈ 5.7° < 10°.
        let sliver = [v(0.0, 0.0), v(10.0, 0.0), v(0.0, 1.0)];
        assert!(!well_formed(&sliver[..], 0.01, COS_10_DEG));
        // With κ = 1° (cos = 0.99985) the same triangle passes.
        assert!(well_formed(&sliver[..], 0.01, 0.999_847_695_156_391));
    }
}
