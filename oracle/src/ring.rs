//! Paper A §II: the polygon P is simple and listed counterclockwise. Is a ring simple,
//! and which way does it run? Decided exactly: every sign is the sign of a rational.
//!
//! The engine's `ring` module, mirrored: the same faults, found in the same order and
//! named by the same vertex indices, so that the two can be compared answer for answer.
//! There is no "not checkable" here; exact arithmetic decides every ring.

use core::cmp::Ordering;

use crate::field::{ExactField, V2};

/// Paper A §II (P simple, counterclockwise): the sign of (b − a) × (c − a): +1 when a, b,
/// c turn left (counterclockwise), −1 right, 0 collinear.
pub fn orient<F: ExactField>(a: &V2<F>, b: &V2<F>, c: &V2<F>) -> i8 {
    match b.minus(a).cross(&c.minus(a)).sign() {
        Ordering::Greater => 1,
        Ordering::Less => -1,
        Ordering::Equal => 0,
    }
}

/// Paper A §II (P simple): why a ring is not a simple polygon (vertex indices as
/// given, from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingFault {
    /// Edges a0→a1 and b0→b1 share a point although they are not neighbours (or, when
    /// neighbours, overlap beyond their common vertex: a spike).
    Crossing {
        /// The first edge, by the indices of its ends.
        a: (usize, usize),
        /// The second edge, by the indices of its ends.
        b: (usize, usize),
    },
    /// All vertices on one line, or on one point: the ring encloses nothing.
    ZeroArea,
}

/// Paper A §II (P listed counterclockwise): which way a ring runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Winding {
    /// Counterclockwise: the interior on the left, paper A's order.
    Counterclockwise,
    /// Clockwise.
    Clockwise,
}

/// Paper A §II (P simple): does point r of the line through p and q lie on the closed
/// segment pq? (r − p)·(r − q) ≤ 0.
fn on_segment<F: ExactField>(p: &V2<F>, q: &V2<F>, r: &V2<F>) -> bool {
    !r.minus(p).dot(&r.minus(q)).is_pos()
}

/// Paper A §II (P simple): do the closed segments pq and rs share a point? Written
/// without the engine's bounding-box pruning: a proper crossing, or an end of one
/// segment on the other.
pub fn segments_meet<F: ExactField>(p: &V2<F>, q: &V2<F>, r: &V2<F>, s: &V2<F>) -> bool {
    let (o1, o2) = (orient(p, q, r), orient(p, q, s));
    let (o3, o4) = (orient(r, s, p), orient(r, s, q));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && on_segment(p, q, r))
        || (o2 == 0 && on_segment(p, q, s))
        || (o3 == 0 && on_segment(r, s, p))
        || (o4 == 0 && on_segment(r, s, q))
}

/// Paper A §II (P simple): the first pair of edges that make the ring not simple, or
/// `Ok(())`. Repeated consecutive vertices (also across the end of the list) are one
/// vertex. For each edge i of that reduced ring, in order: first whether edges i and
/// i + 1 fold back over each other (a spike), then edge i against every later edge that
/// is not its neighbour. Edges are named by the given indices of their ends.
pub fn check_simple<F: ExactField>(p: &[V2<F>]) -> Result<(), RingFault> {
    // The given index of each distinct consecutive vertex.
    let mut idx: Vec<usize> = Vec::with_capacity(p.len());
    for (i, v) in p.iter().enumerate() {
        if idx.last().map(|&j| &p[j]) != Some(v) {
            idx.push(i);
        }
    }
    while idx.len() > 1 && p[idx[0]] == p[idx[idx.len() - 1]] {
        idx.pop();
    }
    let n = idx.len();
    if n < 3 {
        return Err(RingFault::ZeroArea);
    }
    let vtx = |k: usize| &p[idx[k % n]];
    let name = |k: usize| (idx[k % n], idx[(k + 1) % n]);
    for i in 0..n {
        // Neighbours a→b and b→c share b; they share more only when c lies on the
        // line ab on a's side of b: (a − b)·(c − b) > 0.
        let (a, b, c) = (vtx(i), vtx(i + 1), vtx(i + 2));
        if orient(a, b, c) == 0 && a.minus(b).dot(&c.minus(b)).is_pos() {
            return Err(RingFault::Crossing {
                a: name(i),
                b: name(i + 1),
            });
        }
        for k in (i + 2)..n {
            if i == 0 && k == n - 1 {
                continue; // the last edge and the first are neighbours
            }
            if segments_meet(vtx(i), vtx(i + 1), vtx(k), vtx(k + 1)) {
                return Err(RingFault::Crossing {
                    a: name(i),
                    b: name(k),
                });
            }
        }
    }
    Ok(())
}

/// Paper A §II (P listed counterclockwise): the winding of a simple ring
/// ([`check_simple`] passed), the turn at its lexicographically least vertex (least x,
/// then least y; a convex-hull vertex, where a simple ring turns the way it runs), taken
/// between the nearest vertices on each side that differ from it. `Err(ZeroArea)` when
/// there is no such vertex or the turn is straight.
pub fn winding<F: ExactField>(p: &[V2<F>]) -> Result<Winding, RingFault> {
    let n = p.len();
    let m = crate::well_formed::extremal_vertex(p).ok_or(RingFault::ZeroArea)?;
    let prev = (1..n)
        .map(|k| &p[(m + n - k) % n])
        .find(|&q| q != &p[m])
        .ok_or(RingFault::ZeroArea)?;
    let next = (1..n)
        .map(|k| &p[(m + k) % n])
        .find(|&q| q != &p[m])
        .ok_or(RingFault::ZeroArea)?;
    match orient(prev, &p[m], next) {
        1 => Ok(Winding::Counterclockwise),
        -1 => Ok(Winding::Clockwise),
        _ => Err(RingFault::ZeroArea),
    }
}

/// Paper A §II (P simple encloses something): do all vertices lie on one line (true
/// for no vertices or one point)?
pub fn collinear<F: ExactField>(p: &[V2<F>]) -> bool {
    let Some(a) = p.first() else { return true };
    let Some(b) = p.iter().find(|&q| q != a) else {
        return true;
    };
    p.iter().all(|c| orient(a, b, c) == 0)
}

/// Paper A §II: is the ring a polygon as the paper takes it, simple and listed
/// counterclockwise?
pub fn simple_ccw<F: ExactField>(p: &[V2<F>]) -> bool {
    check_simple(p).and_then(|()| winding(p)) == Ok(Winding::Counterclockwise)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Arith, Q};

    fn ring(xy: &[(i64, i64)]) -> Vec<V2<Q>> {
        xy.iter()
            .map(|&(x, y)| V2::new(Q::from_i64(x), Q::from_i64(y)))
            .collect()
    }

    #[test]
    fn square_both_ways() {
        let ccw = ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        assert_eq!(check_simple(&ccw), Ok(()));
        assert_eq!(winding(&ccw), Ok(Winding::Counterclockwise));
        assert!(simple_ccw(&ccw));
        let cw: Vec<V2<Q>> = ccw.iter().rev().cloned().collect();
        assert_eq!(check_simple(&cw), Ok(()));
        assert_eq!(winding(&cw), Ok(Winding::Clockwise));
        assert!(!simple_ccw(&cw));
    }

    #[test]
    fn faults_are_named() {
        let bow = ring(&[(0, 0), (4, 4), (4, 0), (0, 4)]);
        assert_eq!(
            check_simple(&bow),
            Err(RingFault::Crossing {
                a: (0, 1),
                b: (2, 3)
            })
        );
        // vertex 3 on edge 0–1: edges 0–1 and 2–3 meet first
        let touch = ring(&[(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)]);
        assert_eq!(
            check_simple(&touch),
            Err(RingFault::Crossing {
                a: (0, 1),
                b: (2, 3)
            })
        );
        // 1 → 2 goes out and 2 → 3 comes back: the spike at vertex 2
        let spike = ring(&[(0, 0), (4, 0), (6, 0), (5, 0), (4, 4)]);
        assert_eq!(
            check_simple(&spike),
            Err(RingFault::Crossing {
                a: (1, 2),
                b: (2, 3)
            })
        );
        let line = ring(&[(0, 0), (1, 1), (2, 2)]);
        assert!(collinear(&line));
        assert!(check_simple(&line).is_err());
        assert_eq!(
            check_simple(&ring(&[(1, 1), (1, 1), (2, 2)])),
            Err(RingFault::ZeroArea)
        );
    }

    #[test]
    fn repeats_are_one_vertex() {
        let rep = ring(&[(0, 0), (4, 0), (4, 0), (4, 4), (0, 0)]);
        assert_eq!(check_simple(&rep), Ok(()));
        assert_eq!(winding(&rep), Ok(Winding::Counterclockwise));
    }
}
