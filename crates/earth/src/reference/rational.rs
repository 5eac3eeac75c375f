//! Paper B Section IV in exact rational arithmetic: convex hull (eq 7), convex
//! intersection (eq 9), projection onto a track (eq 11) and the linear-motion time window
//! (eq 20). Every decision is exact; floats enter only through [`q`] (exact conversion).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// A rational point.
pub type P = [BigRational; 2];

/// The exact value of a finite f64 (`None` for NaN and ±∞).
pub fn q(x: f64) -> Option<BigRational> {
    BigRational::from_float(x)
}

/// A rational rounded to the nearest f64, for reports and tolerance comparisons only
/// (never for a decision).
pub fn to_f64(x: &BigRational) -> f64 {
    num_traits::ToPrimitive::to_f64(x).unwrap_or(f64::NAN)
}

/// The exact point of an f64 pair (`None` if a coordinate is not finite).
pub fn point(p: [f64; 2]) -> Option<P> {
    Some([q(p[0])?, q(p[1])?])
}

/// Exact points of an f64 ring (`None` if any coordinate is not finite).
pub fn points(ring: &[[f64; 2]]) -> Option<Vec<P>> {
    ring.iter().map(|&p| point(p)).collect()
}

/// Paper B eq 9: twice the signed area of `abc`.
pub fn orient(a: &P, b: &P, c: &P) -> BigRational {
    (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])
}

/// Paper B eq 9: signed area of a ring.
pub fn signed_area(ring: &[P]) -> BigRational {
    let n = ring.len();
    let mut s = BigRational::zero();
    for i in 0..n {
        let (a, b) = (&ring[i], &ring[(i + 1) % n]);
        s += &a[0] * &b[1] - &a[1] * &b[0];
    }
    s / BigRational::from_integer(BigInt::from(2))
}

/// Paper B eq 7: exact convex hull, counter-clockwise, collinear points dropped.
pub fn convex_hull(pts: &[P]) -> Vec<P> {
    let mut p: Vec<P> = pts.to_vec();
    p.sort_by(|a, b| a[0].cmp(&b[0]).then(a[1].cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut h: Vec<P> = Vec::with_capacity(2 * p.len());
    for x in p.iter() {
        while h.len() >= 2 && !orient(&h[h.len() - 2], &h[h.len() - 1], x).is_positive() {
            h.pop();
        }
        h.push(x.clone());
    }
    let lower = h.len() + 1;
    for x in p.iter().rev().skip(1) {
        while h.len() >= lower && !orient(&h[h.len() - 2], &h[h.len() - 1], x).is_positive() {
            h.pop();
        }
        h.push(x.clone());
    }
    h.pop();
    h
}

/// Paper B eq 9: exact intersection of convex `a` with convex counter-clockwise `b`
/// (Sutherland–Hodgman; intersection points are exact rationals).
pub fn clip_convex(a: &[P], b: &[P]) -> Vec<P> {
    let mut out: Vec<P> = a.to_vec();
    let m = b.len();
    for i in 0..m {
        if out.is_empty() {
            break;
        }
        let (e0, e1) = (&b[i], &b[(i + 1) % m]);
        let n = out.len();
        let mut next = Vec::with_capacity(n + 1);
        for j in 0..n {
            let (p, r) = (&out[j], &out[(j + 1) % n]);
            let (op, or) = (orient(e0, e1, p), orient(e0, e1, r));
            if !op.is_negative() {
                next.push(p.clone());
            }
            if (op.is_positive() && or.is_negative()) || (op.is_negative() && or.is_positive()) {
                let s = &op / (&op - &or);
                next.push([&p[0] + &s * (&r[0] - &p[0]), &p[1] + &s * (&r[1] - &p[1])]);
            }
        }
        out = next;
    }
    out
}

fn between(p: &P, q: &P, r: &P) -> bool {
    let inside = |k: usize| {
        let (lo, hi) = if p[k] <= q[k] {
            (&p[k], &q[k])
        } else {
            (&q[k], &p[k])
        };
        &r[k] >= lo && &r[k] <= hi
    };
    inside(0) && inside(1)
}

/// Do the closed segments `ab` and `cd` meet? (exact)
pub fn segments_meet(a: &P, b: &P, c: &P, d: &P) -> bool {
    let s = |x: BigRational| match x.cmp(&BigRational::zero()) {
        Ordering::Less => -1,
        Ordering::Equal => 0,
        Ordering::Greater => 1,
    };
    let (o1, o2) = (s(orient(a, b, c)), s(orient(a, b, d)));
    let (o3, o4) = (s(orient(c, d, a)), s(orient(c, d, b)));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && between(a, b, c))
        || (o2 == 0 && between(a, b, d))
        || (o3 == 0 && between(c, d, a))
        || (o4 == 0 && between(c, d, b))
}

/// Is `p` inside or on the simple ring? (exact crossing number)
pub fn point_in_ring(p: &P, ring: &[P]) -> bool {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (&ring[i], &ring[(i + 1) % n]);
        if orient(a, b, p).is_zero() && between(a, b, p) {
            return true;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            // p is left of the upward-oriented edge ⇔ the crossing lies right of p
            let o = orient(a, b, p);
            let left = if b[1] > a[1] {
                o.is_positive()
            } else {
                o.is_negative()
            };
            if left {
                inside = !inside;
            }
        }
    }
    inside
}

/// Paper B eq 9 as a predicate: do the closed polygons bounded by two simple rings meet?
pub fn rings_intersect(a: &[P], b: &[P]) -> bool {
    let (n, m) = (a.len(), b.len());
    for i in 0..n {
        for j in 0..m {
            if segments_meet(&a[i], &a[(i + 1) % n], &b[j], &b[(j + 1) % m]) {
                return true;
            }
        }
    }
    (n > 0 && point_in_ring(&a[0], b)) || (m > 0 && point_in_ring(&b[0], a))
}

/// Paper B eq 11: exact projection fractions of `pts` onto the segment `c0 → c1`
/// (`None` when the segment is a point).
pub fn projection(c0: &P, c1: &P, pts: &[P]) -> Option<Vec<BigRational>> {
    let d = [&c1[0] - &c0[0], &c1[1] - &c0[1]];
    let n2 = &d[0] * &d[0] + &d[1] * &d[1];
    if n2.is_zero() {
        return None;
    }
    Some(
        pts.iter()
            .map(|p| (&d[0] * (&p[0] - &c0[0]) + &d[1] * (&p[1] - &c0[1])) / &n2)
            .collect(),
    )
}

/// Paper B eq 20, exact: for convex polygons with vertices `a_ref`, `b_ref` at `t_ref`
/// translating with velocities `va`, `vb`, the window `[lo, hi] ∩ {t : A(t) ∩ B(t) ≠ ∅}`.
/// `None` when the Minkowski difference has no area (degenerate input),
/// `Some(None)` when they never meet in `[lo, hi]`.
pub fn linear_window(
    a_ref: &[P],
    va: &P,
    b_ref: &[P],
    vb: &P,
    t_ref: &BigRational,
    lo: &BigRational,
    hi: &BigRational,
) -> Option<Option<(BigRational, BigRational)>> {
    let mut diff = Vec::with_capacity(a_ref.len() * b_ref.len());
    for b in b_ref {
        for a in a_ref {
            diff.push([&b[0] - &a[0], &b[1] - &a[1]]);
        }
    }
    let m = convex_hull(&diff);
    if m.len() < 3 {
        return None;
    }
    let w = [&va[0] - &vb[0], &va[1] - &vb[1]];
    let mut l = lo - t_ref;
    let mut h = hi - t_ref;
    let n = m.len();
    for k in 0..n {
        let (e0, e1) = (&m[k], &m[(k + 1) % n]);
        let e = [&e1[0] - &e0[0], &e1[1] - &e0[1]];
        let c0 = -(&e[0] * &e0[1] - &e[1] * &e0[0]);
        let c1 = &e[0] * &w[1] - &e[1] * &w[0];
        if c1.is_zero() {
            if c0.is_negative() {
                return Some(None);
            }
        } else {
            let root = -(&c0 / &c1);
            if c1.is_positive() {
                if root > l {
                    l = root;
                }
            } else if root < h {
                h = root;
            }
        }
        if l > h {
            return Some(None);
        }
    }
    Some(Some((l + t_ref, h + t_ref)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The square [x0, x0 + s] × [y0, y0 + s], exactly.
    fn sq(x0: (i64, i64), y0: (i64, i64), s: i64) -> Vec<P> {
        let r = |(n, d): (i64, i64)| BigRational::new(n.into(), d.into());
        let (x, y, s) = (r(x0), r(y0), BigRational::from_integer(s.into()));
        vec![
            [x.clone(), y.clone()],
            [&x + &s, y.clone()],
            [&x + &s, &y + &s],
            [x, y + s],
        ]
    }

    #[test]
    fn clip_area_exact() {
        let c = clip_convex(&sq((0, 1), (0, 1), 2), &sq((1, 1), (1, 1), 2));
        assert_eq!(signed_area(&c), q(1.0).unwrap());
    }

    #[test]
    fn touching_squares_meet() {
        assert!(rings_intersect(
            &sq((0, 1), (0, 1), 1),
            &sq((1, 1), (0, 1), 1)
        ));
        assert!(!rings_intersect(
            &sq((0, 1), (0, 1), 1),
            &sq((3, 2), (0, 1), 1)
        ));
    }

    #[test]
    fn linear_window_of_sliding_squares() {
        // a moves right at 1/h from x = -3, b fixed at [0, 1]²: meet for t in [2, 4]
        let w = linear_window(
            &sq((-3, 1), (0, 1), 1),
            &point([1.0, 0.0]).unwrap(),
            &sq((0, 1), (0, 1), 1),
            &point([0.0, 0.0]).unwrap(),
            &q(0.0).unwrap(),
            &q(0.0).unwrap(),
            &q(10.0).unwrap(),
        );
        assert_eq!(w, Some(Some((q(2.0).unwrap(), q(4.0).unwrap()))));
    }
}
