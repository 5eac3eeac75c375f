//! The certificate of an offset or inset (the parent module's doc derives what it
//! proves): distances between the result's edges and paper A §II's polygon, bounded
//! with [`crate::ball`]'s certified arithmetic, and exact point locations.

use std::vec::Vec;

use super::raw::{winding_number, Loc};
use super::{OffsetError, Region, Side};
use crate::ball::{nonnegative, positive, round_down, Ball, BallV, Tri};
use crate::ring::segments_meet;
use crate::vect2::Vect2;

/// The two thresholds the certificate compares distances with.
pub(crate) struct Bounds {
    /// D + slack: every edge of Q is at least this far from every edge of P.
    pub clear: Ball,
    /// D·(1 + ε) − slack: every edge of Q is within this of one edge of P.
    pub close: Ball,
}

impl Bounds {
    /// The thresholds for `d`, `eps` and the moving polygon's `slack` (0 when the
    /// vertices are exact), as balls around their exact values.
    pub fn new(d: f64, eps: f64, slack: f64) -> Bounds {
        let d = Ball::exact(d);
        let slack = Ball::exact(slack);
        Bounds {
            clear: d.add(slack),
            close: d.mul(Ball::exact(1.0).add(Ball::exact(eps))).sub(slack),
        }
    }
}

fn fail(reason: &'static str) -> OffsetError {
    OffsetError::Uncertified { reason }
}

/// dist(q, [a, b]) ≥ th, certified. The squared distance is |q − a|² when the projection
/// falls before a, |q − b|² after b, and ((b − a) × (q − a))²/|b − a|² (the line's)
/// otherwise; the line's is a lower bound in every case, so it decides when the case
/// is not certain. Each is a ball; the comparison is certified when the ball of
/// (distance² − th²) is certainly ≥ 0.
pub(crate) fn at_least(q: Vect2, a: Vect2, b: Vect2, th: Ball) -> bool {
    let (w, e, wb) = (BallV::diff(q, a), BallV::diff(b, a), BallV::diff(q, b));
    let (dot, ee, th2) = (w.dot(e), e.sq(), th.sq());
    if nonnegative(dot.neg()) == Tri::Yes {
        return nonnegative(w.sq().sub(th2)) == Tri::Yes;
    }
    if nonnegative(dot.sub(ee)) == Tri::Yes {
        return nonnegative(wb.sq().sub(th2)) == Tri::Yes;
    }
    positive(ee) == Tri::Yes && nonnegative(e.cross(w).sq().sub(th2.mul(ee))) == Tri::Yes
}

/// dist(q, [a, b]) ≤ th, certified: the line's squared distance when the projection
/// certainly falls inside the segment, otherwise the nearer end's (an upper bound in
/// every case).
pub(crate) fn within(q: Vect2, a: Vect2, b: Vect2, th: Ball) -> bool {
    let (w, e, wb) = (BallV::diff(q, a), BallV::diff(b, a), BallV::diff(q, b));
    let (dot, ee, th2) = (w.dot(e), e.sq(), th.sq());
    if positive(dot) == Tri::Yes && positive(ee.sub(dot)) == Tri::Yes {
        return nonnegative(th2.mul(ee).sub(e.cross(w).sq())) == Tri::Yes;
    }
    nonnegative(th2.sub(w.sq())) == Tri::Yes || nonnegative(th2.sub(wb.sq())) == Tri::Yes
}

/// The distance between the boxes of [a, b] and [c, d] is certainly ≥ th (a float lower
/// bound of the gap along x or y).
fn boxes_apart(a: Vect2, b: Vect2, c: Vect2, d: Vect2, th: f64) -> bool {
    let gx = (c.x.min(d.x) - a.x.max(b.x)).max(a.x.min(b.x) - c.x.max(d.x));
    let gy = (c.y.min(d.y) - a.y.max(b.y)).max(a.y.min(b.y) - c.y.max(d.y));
    round_down(gx.max(gy)) >= th
}

/// dist([a, b], [c, d]) ≥ th, certified: the segments do not meet (exact) and each end
/// is ≥ th from the other segment (the minimum distance of two disjoint segments is
/// attained at an end of one of them).
pub(crate) fn segments_at_least(a: Vect2, b: Vect2, c: Vect2, d: Vect2, th: Ball) -> bool {
    segments_meet(a, b, c, d) == Some(false)
        && at_least(a, c, d, th)
        && at_least(b, c, d, th)
        && at_least(c, a, b, th)
        && at_least(d, a, b, th)
}

/// Every edge of a set of rings, as (ring, a, b).
fn edges(rings: &[&[Vect2]]) -> Vec<(usize, Vect2, Vect2)> {
    let mut out = Vec::new();
    for (k, r) in rings.iter().enumerate() {
        for i in 0..r.len() {
            out.push((k, r[i], r[(i + 1) % r.len()]));
        }
    }
    out
}

/// The rings' edges of different rings never meet (exact; each ring itself was checked
/// simple when the regions were formed). Swept by x extents.
fn disjoint(rings: &[&[Vect2]]) -> Result<(), OffsetError> {
    let mut es = edges(rings);
    let lo = |e: &(usize, Vect2, Vect2)| e.1.x.min(e.2.x);
    es.sort_by(|x, y| lo(x).total_cmp(&lo(y)));
    for (k, &(ri, a, b)) in es.iter().enumerate() {
        let hi = a.x.max(b.x);
        for &(rj, c, d) in &es[k + 1..] {
            if lo(&(rj, c, d)) > hi {
                break;
            }
            if ri != rj && segments_meet(a, b, c, d) != Some(false) {
                return Err(fail("two rings of the result meet"));
            }
        }
    }
    Ok(())
}

/// The sum of the winding numbers of all rings about x: 1 inside the result, 0 outside
/// (the rings are simple and disjoint, holes clockwise inside their outer ring).
fn membership(rings: &[&[Vect2]], x: Vect2) -> Result<Loc, OffsetError> {
    let mut total = 0;
    for r in rings {
        let (w, on) = winding_number(r, x).ok_or(fail("a location over- or underflows"))?;
        if on {
            return Ok(Loc::Boundary);
        }
        total += w;
    }
    Ok(if total != 0 {
        Loc::Inside
    } else {
        Loc::Outside
    })
}

/// Checks the result against P (see the parent module's doc): rings disjoint, every
/// edge of Q at least `bounds.clear` from P's edges and within `bounds.close` of one of
/// them, and the locations that place P (Out) or ∂P (In) on the right side, and every
/// ring outside P (Out) or every region inside P (In).
/// Cost: O(|Q|·n) distance checks (pruned by boxes) and O(|Q|²) at worst for
/// disjointness (swept by x).
pub(crate) fn certify(
    p: &[Vect2],
    regions: &[Region],
    bounds: &Bounds,
    side: Side,
) -> Result<(), OffsetError> {
    let mut rings: Vec<&[Vect2]> = Vec::new();
    for r in regions {
        rings.push(&r.outer);
        rings.extend(r.holes.iter().map(Vec::as_slice));
    }
    if side == Side::Out && rings.is_empty() {
        return Err(fail("an offset without a region"));
    }
    disjoint(&rings)?;
    let clear_hi = bounds.clear.hi();
    if bounds.close.lo().partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return Err(fail("D·(1 + ε) is not above the moving polygon's rounding"));
    }
    let close_hi = bounds.close.hi();
    let n = p.len();
    let p_edges = || (0..n).map(|j| (p[j], p[(j + 1) % n]));
    for (_, a, b) in edges(&rings) {
        for (c, d) in p_edges() {
            if !boxes_apart(a, b, c, d, clear_hi) && !segments_at_least(a, b, c, d, bounds.clear) {
                return Err(fail("an edge of the result is closer than D to P"));
            }
        }
        let close = p_edges().any(|(c, d)| {
            !boxes_apart(a, b, c, d, close_hi)
                && within(a, c, d, bounds.close)
                && within(b, c, d, bounds.close)
        });
        if !close {
            return Err(fail(
                "an edge of the result is farther than D·(1 + ε) from P",
            ));
        }
    }
    let at_vertex = membership(&rings, p[0])?;
    match side {
        Side::Out if at_vertex != Loc::Inside => Err(fail("P is not inside the offset")),
        Side::In if at_vertex != Loc::Outside => Err(fail("∂P is not outside the inset")),
        Side::In => {
            for r in regions {
                let inside =
                    winding_number(p, r.outer[0]).ok_or(fail("a location over- or underflows"))?;
                if inside != (1, false) {
                    return Err(fail("a region of the inset is outside P"));
                }
            }
            Ok(())
        }
        Side::Out => {
            // A ring is at least D from every edge of P, so it lies wholly inside P or
            // wholly outside: one vertex tells which. A ring inside P (a hole cut out of
            // P where P is about 2·D wide) would pass every distance test above.
            for ring in &rings {
                let at =
                    winding_number(p, ring[0]).ok_or(fail("a location over- or underflows"))?;
                if at != (0, false) {
                    return Err(fail("a ring of the offset lies inside P"));
                }
            }
            Ok(())
        }
    }
}
