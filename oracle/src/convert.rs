//! How the oracle reads numbers: exact conversion of finite f64 values to rationals, the
//! parsing of exact rationals written as strings ("p/q", "p", "-1.25"), the [`Input`]
//! of a case (either kind, made exact), and the f64 nearest to an exact time for
//! printing. Besides the interval kernel, the one module of the oracle that names binary
//! floating point.
//!
//! Every finite f64 is a dyadic rational m·2^e, so the conversion loses nothing.

use crate::error::OracleError;
use crate::field::ExactField;
use crate::time::ExactTime;
use core::cmp::Ordering;
use num_bigint::BigInt;
use num_rational::BigRational;

/// The exact value of a finite f64 (the interval kernel's, where it is defined).
pub use crate::kernel::interval::f64_to_exact;

/// A number the oracle reads exactly: a finite binary float is the dyadic rational it
/// denotes, text is "p/q", an integer or a decimal.
pub trait Input: Copy {
    /// The exact value, or what is wrong with `field`.
    fn exact<F: ExactField>(self, field: &'static str) -> Result<F, OracleError>;
}

impl Input for &str {
    fn exact<F: ExactField>(self, field: &'static str) -> Result<F, OracleError> {
        parse_rational(self).ok_or_else(|| {
            OracleError::new(
                field,
                format!("{self:?} is not an exact rational (p/q, integer or decimal)"),
            )
        })
    }
}

impl Input for f64 {
    fn exact<F: ExactField>(self, field: &'static str) -> Result<F, OracleError> {
        f64_to_exact(self).ok_or_else(|| OracleError::new(field, "not a finite number"))
    }
}

fn all_digits(s: &str) -> bool {
    !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit())
}

/// Parse an exact rational: "p/q" (q ≠ 0), an integer "p", or a plain decimal
/// "-12.5" (read exactly as 125/10). Surrounding spaces are ignored. `None`
/// for anything else.
pub fn parse_rational<F: ExactField>(s: &str) -> Option<F> {
    let s = s.trim();
    if let Some((n, d)) = s.split_once('/') {
        let n = n.trim();
        let d = d.trim();
        let nd = n.strip_prefix(['-', '+']).unwrap_or(n);
        let (dneg, dd) = match d.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, d.strip_prefix('+').unwrap_or(d)),
        };
        if !all_digits(nd) || !all_digits(dd) {
            return None;
        }
        let nneg = n.starts_with('-');
        let num = if nneg != dneg {
            format!("-{nd}")
        } else {
            nd.to_string()
        };
        return F::from_int_strs(&num, dd);
    }
    let (neg, body) = match s.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    let (int_part, frac_part) = match body.split_once('.') {
        Some((i, f)) => (i, f),
        None => (body, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !(int_part.is_empty() || all_digits(int_part))
        || !(frac_part.is_empty() || all_digits(frac_part))
    {
        return None;
    }
    let mut num = String::with_capacity(body.len() + 1);
    if neg {
        num.push('-');
    }
    num.push_str(if int_part.is_empty() { "0" } else { int_part });
    num.push_str(frac_part);
    let mut den = String::with_capacity(frac_part.len() + 1);
    den.push('1');
    for _ in 0..frac_part.len() {
        den.push('0');
    }
    F::from_int_strs(&num, &den)
}

/// The exact value of a finite f64 as a BigRational (`None` for NaN/∞): paper B's exact
/// geometry (geom.rs) reads the engine's coordinates through this.
pub fn q(x: f64) -> Option<num_rational::BigRational> {
    num_rational::BigRational::from_float(x)
}

/// A rational rounded to the nearest f64, for reports and tolerance comparisons only
/// (never for a decision).
pub fn to_float(x: &num_rational::BigRational) -> f64 {
    num_traits::ToPrimitive::to_f64(x).unwrap_or(f64::NAN)
}

/// A tower number rounded to about the nearest f64, for reports only (never for a
/// decision): each level's u + w·√b evaluated in floats.
pub fn tower_to_f64(t: &crate::tower::Tower, a: &crate::tower::Elem) -> f64 {
    fn at(t: &crate::tower::Tower, k: usize, a: &[num_rational::BigRational]) -> f64 {
        if k == 0 {
            return to_float(&a[0]);
        }
        let h = 1 << (k - 1);
        let (u, w) = a.split_at(h);
        let rad = at(t, k - 1, &t.radicand(k - 1).0[..h]).max(0.0);
        at(t, k - 1, u) + at(t, k - 1, w) * rad.sqrt()
    }
    let a = t.top(a);
    at(t, a.level(), &a.0)
}

/// The exact point of an f64 pair (`None` if a coordinate is not finite).
pub fn exact_point(p: [f64; 2]) -> Option<[num_rational::BigRational; 2]> {
    Some([q(p[0])?, q(p[1])?])
}

/// Exact points of an f64 ring (`None` if any coordinate is not finite).
pub fn exact_points(ring: &[[f64; 2]]) -> Option<Vec<[num_rational::BigRational; 2]>> {
    ring.iter().map(|&p| exact_point(p)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Arith, Q};
    use num_bigint::BigInt;

    #[test]
    fn f64_exact() {
        // 0.1 = 3602879701896397 / 2^55 exactly.
        let x: Q = f64_to_exact(0.1).expect("finite");
        assert_eq!(*x.numer(), BigInt::from(3602879701896397u64));
        assert_eq!(*x.denom(), BigInt::from(1u64 << 55));
        let y: Q = f64_to_exact(-2.5).expect("finite");
        assert_eq!(y, Q::new(BigInt::from(-5), BigInt::from(2)));
        let tiny: Q = f64_to_exact(f64::from_bits(1)).expect("finite");
        assert_eq!(tiny, Q::new(BigInt::from(1), BigInt::from(2).pow(1074)));
        assert!(f64_to_exact::<Q>(f64::NAN).is_none());
        assert!(f64_to_exact::<Q>(f64::INFINITY).is_none());
        let z: Q = f64_to_exact(-0.0).expect("finite");
        assert_eq!(z, Q::from_i64(0));
    }

    #[test]
    fn strings() {
        let h = |s: &str| parse_rational::<Q>(s);
        assert_eq!(h("3/4"), Some(Q::new(BigInt::from(3), BigInt::from(4))));
        assert_eq!(h("-3/-4"), Some(Q::new(BigInt::from(3), BigInt::from(4))));
        assert_eq!(h("3/-4"), Some(Q::new(BigInt::from(-3), BigInt::from(4))));
        assert_eq!(h("-1.25"), Some(Q::new(BigInt::from(-5), BigInt::from(4))));
        assert_eq!(h(".5"), Some(Q::new(BigInt::from(1), BigInt::from(2))));
        assert_eq!(h("7"), Some(Q::from_i64(7)));
        for bad in ["", "1/0", "a", "1/", "/2", "1.2.3", "-", ".", "1e3", "--1"] {
            assert_eq!(h(bad), None, "{bad}");
        }
    }
}

/// The f64 nearest to an exact time (a tie may go either way), found by bisection over
/// the ordered floats with exact comparisons only: the number an answer line prints,
/// next to the exact text.
pub fn time_to_f64(t: &ExactTime) -> f64 {
    // floats in order: the bit pattern as an i64, negatives' magnitude bits flipped
    // (i128 so that hi − lo cannot overflow)
    let key = |x: f64| {
        let k = x.to_bits() as i64;
        i128::from(if k < 0 { k ^ i64::MAX } else { k })
    };
    let float = |k: i128| {
        let k = k as i64;
        f64::from_bits((if k < 0 { k ^ i64::MAX } else { k }) as u64)
    };
    let exact = |x: f64| BigRational::from_float(x).unwrap_or_default();
    let (mut lo, mut hi) = (key(-f64::MAX), key(f64::MAX));
    if t.cmp_rational(&exact(float(lo))) == Ordering::Less {
        return f64::NEG_INFINITY;
    }
    if t.cmp_rational(&exact(float(hi))) == Ordering::Greater {
        return f64::INFINITY;
    }
    // invariant: float(lo) ≤ self < float(hi), or self = float(hi) at the top
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if t.cmp_rational(&exact(float(mid))) == Ordering::Less {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let (a, b) = (float(lo), float(hi));
    let half = (exact(a) + exact(b)) / BigRational::from_integer(BigInt::from(2));
    if t.cmp_rational(&half) == Ordering::Greater {
        b
    } else {
        a
    }
}

#[cfg(test)]
mod time_tests {
    use super::*;

    fn rat(p: i64, q: i64) -> BigRational {
        BigRational::new(BigInt::from(p), BigInt::from(q))
    }

    /// The printed float is the nearest: no float lies strictly closer to the exact time
    /// (checked exactly against both neighbours).
    fn nearest(t: &ExactTime) -> f64 {
        let f = time_to_f64(t);
        let q = |x: f64| BigRational::from_float(x).expect("finite");
        for g in [f.next_down(), f.next_up()] {
            // g closer than f would put t beyond the midpoint of f and g
            let mid = (q(f) + q(g)) / rat(2, 1);
            let beyond = t.cmp_rational(&mid);
            let toward_g = if g > f {
                Ordering::Greater
            } else {
                Ordering::Less
            };
            assert_ne!(beyond, toward_g, "{t}: {g} is closer than {f}");
        }
        f
    }

    #[test]
    fn time_to_f64_is_the_nearest_float() {
        assert_eq!(nearest(&ExactTime::rational(rat(1, 3))), 1.0 / 3.0);
        assert_eq!(nearest(&ExactTime::rational(rat(0, 1))), 0.0);
        assert_eq!(nearest(&ExactTime::rational(rat(-7, 2))), -3.5);
        let sqrt2 = ExactTime::new(rat(0, 1), rat(1, 1), rat(2, 1));
        assert!(!sqrt2.is_rational());
        assert_eq!(nearest(&sqrt2), 2f64.sqrt());
        let tiny = ExactTime::new(rat(0, 1), rat(1, 1), rat(1, 7) * rat(1, 1 << 40));
        nearest(&tiny);
        let shifted = ExactTime::new(rat(3, 1), rat(-1, 5), rat(11, 1));
        nearest(&shifted);
        assert_eq!(sqrt2.exact_text(), sqrt2.to_string());
        assert_eq!(ExactTime::rational(rat(6, 4)).exact_text(), "3/2");
    }
}
