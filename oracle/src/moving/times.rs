//! Closed sets of times with real algebraic ends, as the exact truth of moving features
//! composes them (docs/moving-features.md, "The planar model"; paper A §II's sets of
//! times, pieced together): sorted lists of disjoint closed components [a, b] (a ≤ b,
//! a = b for an isolated time), and their exact ∨, ∧, closure of the complement within a
//! window, and move by a rational. Every comparison is [`RealAlg`]'s exact order.

use num_rational::BigRational;

use crate::algebraic::RealAlg;
use crate::intervals::Components;

/// The union of closed intervals given in any order: sorted by start, and merged where
/// one starts at or before the other's end (closed sets that touch are one component).
/// (The contract's components: closed, disjoint, sorted.)
pub fn union_all(mut parts: Vec<(RealAlg, RealAlg)>) -> Components {
    parts.sort_by(|a, b| a.0.cmp(&b.0));
    let mut out: Components = Vec::with_capacity(parts.len());
    for (a, b) in parts {
        if let Some(last) = out.last_mut() {
            if a <= last.1 {
                if b > last.1 {
                    last.1 = b;
                }
                continue;
            }
        }
        out.push((a, b));
    }
    out
}

/// a ∨ b: the times in either set.
/// (The truth's union over an area's parts and over pieces.)
pub fn union(a: &[(RealAlg, RealAlg)], b: &[(RealAlg, RealAlg)]) -> Components {
    union_all(a.iter().chain(b).cloned().collect())
}

/// a ∧ b: the times in both sets (two closed components that share one end meet in
/// that isolated time).
/// (The truth's conjunction of an outer ring with its holes and of the vertical condition.)
pub fn intersect(a: &[(RealAlg, RealAlg)], b: &[(RealAlg, RealAlg)]) -> Components {
    let mut out = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        let (x, y) = (&a[i], &b[j]);
        let lo = if x.0 < y.0 { &y.0 } else { &x.0 };
        let x_first = x.1 < y.1;
        let hi = if x_first { &x.1 } else { &y.1 };
        if lo <= hi {
            out.push((lo.clone(), hi.clone()));
        }
        if x_first {
            i += 1;
        } else {
            j += 1;
        }
    }
    out
}

/// The closure of the window [lo, hi] minus the set: the stretches of the window between
/// the set's components, each closed (an isolated time of the set splits nothing: the
/// two stretches around it touch there and are one component).
/// (The truth's negation of a relation within a domain, closed as every set here is.)
pub fn complement_in(set: &[(RealAlg, RealAlg)], lo: &RealAlg, hi: &RealAlg) -> Components {
    let inside = intersect(set, &[(lo.clone(), hi.clone())]);
    let mut gaps = Vec::with_capacity(inside.len() + 1);
    let mut from = lo.clone();
    for (a, b) in inside {
        if from < a {
            gaps.push((from, a));
        }
        from = b;
    }
    if &from < hi {
        gaps.push((from, hi.clone()));
    }
    union_all(gaps)
}

/// Every end moved by the rational c (a piece's times to global time).
/// (The truth's pieces, each worked on from its own start t_k.)
pub fn shift(set: &[(RealAlg, RealAlg)], c: &BigRational) -> Components {
    set.iter()
        .map(|(a, b)| (a.shifted_by(c), b.shifted_by(c)))
        .collect()
}

/// The set as the closed interval [lo, hi] with rational ends, or empty.
/// (The truth's vertical condition on a piece: one interval with rational ends.)
pub fn interval(lo: BigRational, hi: BigRational) -> Components {
    if lo <= hi {
        vec![(RealAlg::rational(lo), RealAlg::rational(hi))]
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebraic::Poly;
    use core::cmp::Ordering;
    use num_bigint::BigInt;

    fn r(n: i64) -> RealAlg {
        RealAlg::from_i64(n)
    }

    fn set(c: &[(i64, i64)]) -> Components {
        c.iter().map(|&(a, b)| (r(a), r(b))).collect()
    }

    fn ints(c: &Components) -> Vec<(String, String)> {
        c.iter()
            .map(|(a, b)| (a.exact_text(), b.exact_text()))
            .collect()
    }

    fn same(a: &Components, b: &[(i64, i64)]) {
        assert_eq!(ints(a), ints(&set(b)));
    }

    #[test]
    fn touching_intervals_merge_in_a_union() {
        same(&union(&set(&[(0, 2)]), &set(&[(2, 5)])), &[(0, 5)]);
        same(
            &union(&set(&[(0, 2), (6, 7)]), &set(&[(3, 5)])),
            &[(0, 2), (3, 5), (6, 7)],
        );
        same(&union(&set(&[(3, 3)]), &set(&[(1, 3)])), &[(1, 3)]);
        same(
            &union_all(set(&[(4, 9), (0, 1), (1, 1), (5, 6)])),
            &[(0, 1), (4, 9)],
        );
    }

    #[test]
    fn intersections_keep_isolated_points_and_equal_ends() {
        same(&intersect(&set(&[(0, 2)]), &set(&[(2, 5)])), &[(2, 2)]);
        same(
            &intersect(&set(&[(0, 10)]), &set(&[(1, 2), (4, 4), (9, 12)])),
            &[(1, 2), (4, 4), (9, 10)],
        );
        same(&intersect(&set(&[(0, 1)]), &set(&[(2, 3)])), &[]);
        same(&intersect(&set(&[(0, 5)]), &set(&[(0, 5)])), &[(0, 5)]);
        same(
            &intersect(&set(&[(0, 3), (5, 8)]), &set(&[(3, 5)])),
            &[(3, 3), (5, 5)],
        );
    }

    #[test]
    fn the_complement_is_closed_and_an_isolated_point_splits_nothing() {
        let (lo, hi) = (r(0), r(10));
        same(
            &complement_in(&set(&[(2, 3), (5, 5)]), &lo, &hi),
            &[(0, 2), (3, 10)],
        );
        same(&complement_in(&set(&[(0, 4)]), &lo, &hi), &[(4, 10)]);
        same(&complement_in(&set(&[(0, 10)]), &lo, &hi), &[]);
        same(&complement_in(&set(&[]), &lo, &hi), &[(0, 10)]);
        same(
            &complement_in(&set(&[(-3, 1), (9, 12)]), &lo, &hi),
            &[(1, 9)],
        );
    }

    #[test]
    fn a_shift_moves_irrational_ends_exactly() {
        // √2 (root of t² − 2 in (1, 2)) moved by 3/2 is a root of (t − 3/2)² − 2.
        let p = Poly::from_i64s(&[-2, 0, 1]);
        let two = BigRational::from_integer(BigInt::from(2));
        let root = RealAlg::roots_of(&p, &BigRational::from_integer(BigInt::from(1)), &two)
            .pop()
            .expect("√2 is in [1, 2]");
        let c = BigRational::new(BigInt::from(3), BigInt::from(2));
        let moved = shift(&[(r(0), root.clone())], &c);
        assert_eq!(moved[0].0.exact_text(), "3/2");
        assert_eq!(moved[0].1.to_decimal_string(9), "2.914213562");
        // exactly √2 + 3/2: (t − 3/2)² − 2 is 0 there, and the order with rationals holds
        let q = Poly::from_rationals(&[
            BigRational::new(BigInt::from(1), BigInt::from(4)),
            BigRational::from_integer(BigInt::from(-3)),
            BigRational::from_integer(BigInt::from(1)),
        ]);
        assert_eq!(moved[0].1.sign_of(&q), Ordering::Equal);
        assert_eq!(
            moved[0]
                .1
                .cmp_rational(&BigRational::new(BigInt::from(2914), BigInt::from(1000))),
            Ordering::Greater
        );
        // and back
        assert_eq!(moved[0].1.shifted_by(&-c), root);
    }
}
