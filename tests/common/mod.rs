//! What the paper-A tests share: the exact value of the engine's inputs, and exact
//! distances, to place cases at exact ties.

use polyguard::Vect2;
use polyguard_oracle::convert::f64_to_exact;
use polyguard_oracle::{Arith, Decided, Exact, ExactField, Q, V2};

/// The exact value of a finite f64 (the tests draw finite inputs only).
pub fn q(x: f64) -> Q {
    f64_to_exact(x).expect("test inputs are finite")
}

/// The exact value of a point.
pub fn qv(p: Vect2) -> V2<Q> {
    V2::new(q(p.x), q(p.y))
}

/// The exact values of a polygon's points.
pub fn qpoly(ps: &[Vect2]) -> Vec<V2<Q>> {
    ps.iter().map(|&p| qv(p)).collect()
}

/// Exact squared distance from s to the segment a b.
pub fn dist2_point_segment(s: &V2<Q>, a: &V2<Q>, b: &V2<Q>) -> Q {
    let e = b.minus(a);
    let w = s.minus(a);
    let Some(r) = w.dot(&e).quotient(&e.sq()) else {
        return w.sq();
    };
    let r = if r.is_neg() {
        <Q as Arith>::zero()
    } else if r > <Q as Arith>::one() {
        <Q as Arith>::one()
    } else {
        r
    };
    w.minus(&e.scale(&r)).sq()
}

/// Exact squared distance between the segments a b and c d (attained at an end of one of
/// them unless they meet).
pub fn dist2_segments(a: &V2<Q>, b: &V2<Q>, c: &V2<Q>, d: &V2<Q>) -> Q {
    if polyguard_oracle::truth::segments_intersect(&Exact, a, b, c, d).decided() {
        return <Q as Arith>::zero();
    }
    [
        dist2_point_segment(a, c, d),
        dist2_point_segment(b, c, d),
        dist2_point_segment(c, a, b),
        dist2_point_segment(d, a, b),
    ]
    .into_iter()
    .min()
    .expect("four distances")
}
