//! Real algebraic numbers (oracle/src/algebraic.rs): roots found are roots, root counts
//! match products of known linear factors, comparisons agree with floats where the
//! numbers are clearly apart and are exact where they are not (close roots, double
//! roots, rational roots), and the float enclosures and decimal digits are rigorous.

use core::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

use polyguard_oracle::algebraic::{Poly, RealAlg};
use polyguard_oracle::convert::f64_to_exact;
use polyguard_oracle::ExactTime;

fn rat(p: i64, q: i64) -> BigRational {
    BigRational::new(BigInt::from(p), BigInt::from(q))
}

/// The product of the factors (k·t − m).
fn product(factors: &[(i64, i64)]) -> Poly {
    factors.iter().fold(Poly::from_i64s(&[1]), |acc, &(k, m)| {
        acc.mul(&Poly::from_i64s(&[-m, k]))
    })
}

/// The exact value of a float.
fn exact(x: f64) -> BigRational {
    f64_to_exact(x).expect("finite")
}

/// lo ≤ x ≤ hi exactly for the floats of `to_f64_bounds`.
fn bounds_hold(x: &RealAlg) -> bool {
    let (lo, hi) = x.to_f64_bounds();
    lo <= hi
        && (lo == f64::NEG_INFINITY || x.cmp_rational(&exact(lo)) != Ordering::Less)
        && (hi == f64::INFINITY || x.cmp_rational(&exact(hi)) != Ordering::Greater)
}

fn sqrt2() -> RealAlg {
    RealAlg::from(&ExactTime::new(rat(0, 1), rat(1, 1), rat(2, 1)))
}

#[test]
fn square_root_of_two() {
    let r = sqrt2();
    assert!(!r.is_rational());
    assert_eq!(r.to_decimal_string(10), "1.4142135623");
    assert!(r.cmp_rational(&rat(141421, 100000)) == Ordering::Greater);
    assert!(r.cmp_rational(&rat(141422, 100000)) == Ordering::Less);
    let (lo, hi) = r.to_f64_bounds();
    assert!(lo <= 2f64.sqrt() && 2f64.sqrt() <= hi && hi - lo <= 16.0 * f64::EPSILON);
    assert!(bounds_hold(&r));
    assert!(
        r.exact_text().starts_with("root of t^2 − 2 in ("),
        "{}",
        r.exact_text()
    );
    // The roots of t² − 2 on [0, 2]: only √2, equal to the ExactTime's.
    let roots = RealAlg::roots_of(&Poly::from_i64s(&[-2, 0, 1]), &rat(0, 1), &rat(2, 1));
    assert_eq!(roots.len(), 1);
    assert_eq!(roots[0], r);
    // −√2 + 3 from an ExactTime with a negative surd coefficient.
    let s = RealAlg::from(&ExactTime::new(rat(3, 1), rat(-1, 1), rat(2, 1)));
    assert_eq!(s.to_decimal_string(6), "1.585786");
    assert!(s > r);
}

#[test]
fn rationals_print_and_compare() {
    let x = RealAlg::rational(rat(5, 2));
    assert_eq!(x.exact_text(), "5/2");
    assert_eq!(x.to_decimal_string(3), "2.500");
    assert_eq!(
        RealAlg::rational(rat(-1, 3)).to_decimal_string(4),
        "-0.3334"
    );
    assert_eq!(
        RealAlg::from(&ExactTime::rational(rat(6, 4))),
        RealAlg::rational(rat(3, 2))
    );
    // 4t² − 9 has the rational roots ±3/2, held as rationals once isolated.
    let p = Poly::from_i64s(&[-9, 0, 4]);
    let r = RealAlg::isolated(&p, rat(1, 1), rat(2, 1)).expect("one root in (1, 2)");
    assert!(r.is_rational());
    assert_eq!(r.exact_text(), "3/2");
    assert!(RealAlg::isolated(&p, rat(-2, 1), rat(2, 1)).is_none());
}

#[test]
fn close_and_double_roots_of_a_quartic() {
    // (1000t − 1001)(1000t − 1002)(t² − 2): roots 1.001, 1.002 and ±√2.
    let p = product(&[(1000, 1001), (1000, 1002)]).mul(&Poly::from_i64s(&[-2, 0, 1]));
    let roots = RealAlg::roots_of(&p, &rat(-10, 1), &rat(10, 1));
    assert_eq!(roots.len(), 4);
    assert!(roots.windows(2).all(|w| w[0] < w[1]));
    assert_eq!(roots[1], RealAlg::rational(rat(1001, 1000)));
    assert_eq!(roots[2], RealAlg::rational(rat(1002, 1000)));
    assert_eq!(roots[3], sqrt2());
    // (3t − 1)²(t² − 3): the double root counts once.
    let q = product(&[(3, 1), (3, 1)]).mul(&Poly::from_i64s(&[-3, 0, 1]));
    assert_eq!(q.squarefree().degree(), Some(3));
    let roots = RealAlg::roots_of(&q, &rat(-2, 1), &rat(2, 1));
    assert_eq!(roots.len(), 3);
    assert_eq!(roots[1], RealAlg::rational(rat(1, 3)));
    // The sign of a polynomial at a shared root is 0, at another root its sign.
    let s2 = sqrt2();
    assert_eq!(
        s2.sign_of(&Poly::from_i64s(&[-2, 0, 1]).mul(&Poly::from_i64s(&[5, 1]))),
        Ordering::Equal
    );
    assert_eq!(s2.sign_of(&Poly::from_i64s(&[-1, 1])), Ordering::Greater);
    assert_eq!(s2.sign_of(&Poly::from_i64s(&[-3, 0, 1])), Ordering::Less);
}

#[test]
fn polynomial_arithmetic() {
    let a = product(&[(1, 1), (2, 3)]); // (t − 1)(2t − 3)
    let b = product(&[(1, 1), (1, -4)]); // (t − 1)(t + 4)
    assert_eq!(a.gcd(&b), Poly::from_i64s(&[-1, 1]));
    assert_eq!(a.mul(&b).div_exact(&b), Some(a.clone()));
    // rem is a positive multiple of the remainder over Q: a − 2b = −11t + 11, made primitive:
    // −t + 1.
    assert_eq!(a.rem(&b), Poly::from_i64s(&[1, -1]));
    assert_eq!(a.derivative(), Poly::from_i64s(&[-5, 4]));
    assert_eq!(a.add(&b).sub(&b), a);
    assert_eq!(
        format!("{}", Poly::from_i64s(&[1, -2, 0, 0, 3])),
        "3t^4 − 2t + 1"
    );
    assert_eq!(
        Poly::from_rationals(&[rat(1, 2), rat(-1, 3)]),
        Poly::from_i64s(&[3, -2])
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    // Products of known linear factors: as many distinct roots in [lo, hi] as distinct
    // values m/k there, each equal to one of them, in increasing order.
    #[test]
    fn roots_of_products_of_linear_factors(
        factors in proptest::collection::vec((1i64..40, -200i64..200), 1..6),
        lo in -8i64..0, hi in 0i64..8,
    ) {
        let p = product(&factors);
        let (lo, hi) = (rat(lo, 1), rat(hi, 1));
        let mut want: Vec<BigRational> = factors.iter().map(|&(k, m)| rat(m, k)).filter(|r| r >= &lo && r <= &hi).collect();
        want.sort();
        want.dedup();
        let got = RealAlg::roots_of(&p, &lo, &hi);
        prop_assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(&want) {
            prop_assert_eq!(g.cmp_rational(w), Ordering::Equal);
        }
    }

    // Roots found are roots: the polynomial changes sign across each isolating
    // interval, also after refining it; the enclosures are rigorous; and the order of
    // two roots agrees with the floats where their enclosures are apart.
    #[test]
    fn roots_are_roots_and_order_like_floats(
        c in proptest::collection::vec(-50i64..50, 2..6),
        d in proptest::collection::vec(-50i64..50, 2..6),
    ) {
        let (p, q) = (Poly::from_i64s(&c), Poly::from_i64s(&d));
        let (lo, hi) = (rat(-60, 1), rat(60, 1));
        let rp = RealAlg::roots_of(&p, &lo, &hi);
        let rq = RealAlg::roots_of(&q, &lo, &hi);
        for r in rp.iter() {
            prop_assert_eq!(r.sign_of(&p), Ordering::Equal);
            let mut s = r.clone();
            s.refine_to(&rat(1, 1 << 40));
            let (a, b) = s.bounds();
            prop_assert!(b - a <= rat(1, 1 << 40));
            if !s.is_rational() {
                let sf = p.squarefree();
                prop_assert_ne!(sf.sign_at(a), sf.sign_at(b));
                prop_assert_ne!(sf.sign_at(a), Ordering::Equal);
            }
            prop_assert!(bounds_hold(r));
            prop_assert_eq!(&s, r);
        }
        for x in &rp {
            for y in &rq {
                let (xl, xh) = x.to_f64_bounds();
                let (yl, yh) = y.to_f64_bounds();
                if xh < yl {
                    prop_assert_eq!(x.cmp(y), Ordering::Less);
                } else if yh < xl {
                    prop_assert_eq!(x.cmp(y), Ordering::Greater);
                }
                // Exactly equal roots of the two: a common root of the gcd.
                if x == y {
                    prop_assert_eq!(x.sign_of(&p.gcd(&q)), Ordering::Equal);
                }
            }
        }
    }

    // Two roots within 1/N² of each other (quartics with close roots) are told apart
    // exactly, in the right order.
    #[test]
    fn close_roots_are_told_apart(a in 1i64..1000, n in 1000i64..100_000, s in -3i64..4) {
        // (n t − a)(n t − a − 1) · (t² − 2 − s²): the first two differ by 1/n.
        let p = product(&[(n, a), (n, a + 1)]);
        let quartic = p.mul(&Poly::from_i64s(&[-2 - s * s, 0, 1]));
        let roots = RealAlg::roots_of(&quartic, &rat(-10, 1), &rat(10, 1));
        prop_assert_eq!(roots.len(), 4);
        prop_assert!(roots.windows(2).all(|w| w[0] < w[1]));
        let first = roots.iter().position(|r| r.cmp_rational(&rat(a, n)) == Ordering::Equal);
        let second = roots.iter().position(|r| r.cmp_rational(&rat(a + 1, n)) == Ordering::Equal);
        prop_assert!(matches!((first, second), (Some(i), Some(j)) if j == i + 1));
    }

    // Decimal digits are the floor of x·10^d: the value lies in [digits, digits + 10^-d).
    #[test]
    fn decimal_digits_bracket_the_value(c in proptest::collection::vec(-30i64..30, 3..6), digits in 0usize..12) {
        let p = Poly::from_i64s(&c);
        for r in RealAlg::roots_of(&p, &rat(-40, 1), &rat(40, 1)) {
            let text = r.to_decimal_string(digits);
            let (neg, body) = text.strip_prefix('-').map_or((false, text.as_str()), |b| (true, b));
            let plain: String = body.chars().filter(|&ch| ch != '.').collect();
            let mut n: BigInt = plain.parse().expect("digits");
            if neg { n = -n; }
            let scale = BigInt::from(10u32).pow(digits as u32);
            let low = BigRational::new(n.clone(), scale.clone());
            let high = BigRational::new(n + 1, scale);
            prop_assert!(r.cmp_rational(&low) != Ordering::Less);
            prop_assert!(r.cmp_rational(&high) == Ordering::Less);
        }
    }
}
