//! The exact time of an answer (the truth's first entry), a + b·√d: a time at which a
//! point meets a moving edge is a root of a quadratic (paper A §II.I), and one at which
//! it meets a moving slab a rational (§III). In the form in which it is printed and
//! compared: rational when it is, in lowest terms.

use core::cmp::Ordering;
use core::fmt;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::field::ExactField;
use crate::qfield::Alg;

/// An exact time a + b·√d (a, b, d rational, d ≥ 0); b = 0 when it is rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactTime {
    a: BigRational,
    b: BigRational,
    d: BigRational,
}

/// ⌊√n⌋, 0 for n ≤ 0 (paper A §II: entry times are roots of quadratics).
fn big_isqrt(n: &BigInt) -> BigInt {
    if n.sign() != Sign::Plus {
        BigInt::zero()
    } else {
        n.sqrt()
    }
}

/// Whether n may be a perfect square: false is certain (squares have few
/// residues modulo 64 and 45045 = 5·7·9·11·13), true means "compute the root".
/// (Paper A §II (entry times are roots of quadratics).)
fn may_be_square(n: &BigInt) -> bool {
    let low = n.iter_u64_digits().next().unwrap_or(0);
    if (0x0202_0212_0203_0213u64 >> (low & 63)) & 1 == 0 {
        return false;
    }
    let r = (n % BigInt::from(45045u32)).to_u32().unwrap_or(0);
    [5u32, 7, 9, 11, 13].iter().all(|&m| {
        let x = r % m;
        (0..m).any(|y| y * y % m == x)
    })
}

/// √x when it is rational (paper A §II: entry times are roots of quadratics).
fn rational_sqrt(x: &BigRational) -> Option<BigRational> {
    if x.is_negative() {
        return None;
    }
    if !may_be_square(x.numer()) || !may_be_square(x.denom()) {
        return None;
    }
    let n = big_isqrt(x.numer());
    let d = big_isqrt(x.denom());
    if &(&n * &n) == x.numer() && &(&d * &d) == x.denom() {
        Some(BigRational::new(n, d))
    } else {
        None
    }
}

/// ⌊n⌋ (paper A §II: entry times, printed in decimal).
fn floor_div(n: &BigRational) -> BigInt {
    n.floor().to_integer()
}

impl ExactTime {
    /// The rational time x.
    pub fn rational(x: BigRational) -> Self {
        ExactTime {
            a: x,
            b: <BigRational as Zero>::zero(),
            d: <BigRational as Zero>::zero(),
        }
    }

    /// The time a + b·√d (d ≥ 0), put in canonical form (rational when it is).
    pub fn new(a: BigRational, b: BigRational, d: BigRational) -> Self {
        if b.is_zero() || d.is_zero() || d.is_negative() {
            return ExactTime::rational(a);
        }
        if let Some(r) = rational_sqrt(&d) {
            return ExactTime::rational(a + b * r);
        }
        ExactTime { a, b, d }
    }

    /// The exact value of (p + q√d)/r.
    pub fn from_alg<F: ExactField>(x: &Alg<F>) -> Self {
        let r = x.r.to_big();
        if r.is_zero() {
            return ExactTime::rational(<BigRational as Zero>::zero());
        }
        // Divide in the backend (GMP is faster than num-bigint), then convert.
        match (x.p.quotient(&x.r), x.q.quotient(&x.r)) {
            (Some(a), Some(b)) => ExactTime::new(a.to_big(), b.to_big(), x.d.to_big()),
            _ => ExactTime::new(x.p.to_big() / &r, x.q.to_big() / &r, x.d.to_big()),
        }
    }

    /// The rational part a.
    pub fn rational_part(&self) -> &BigRational {
        &self.a
    }

    /// The coefficient b of √d (0 for a rational time).
    pub fn surd_coefficient(&self) -> &BigRational {
        &self.b
    }

    /// The radicand d (0 for a rational time).
    pub fn radicand(&self) -> &BigRational {
        &self.d
    }

    /// Whether the time is rational.
    pub fn is_rational(&self) -> bool {
        self.b.is_zero()
    }

    /// "p/q" (lowest terms, q ≥ 1) when the time is rational.
    pub fn as_rational_string(&self) -> Option<String> {
        if self.is_rational() {
            Some(format!("{}/{}", self.a.numer(), self.a.denom()))
        } else {
            None
        }
    }

    /// The order of this time and a rational number, exactly.
    pub fn cmp_rational(&self, x: &BigRational) -> Ordering {
        let alpha = &self.a - x;
        crate::qfield::sign1(&alpha, &self.b, &self.d)
    }

    /// The exact value as text: "p/q" when rational, else "a + b·√d" with a, b, d in
    /// lowest terms.
    pub fn exact_text(&self) -> String {
        match self.as_rational_string() {
            Some(r) => r,
            None => self.to_string(),
        }
    }

    /// The decimal expansion with `digits` digits after the point, rounded
    /// toward −∞ (exact: no digit is ever wrong).
    pub fn to_decimal_string(&self, digits: usize) -> String {
        let scale = BigInt::from(10u32).pow(u32::try_from(digits).unwrap_or(u32::MAX));
        let sr = BigRational::from_integer(scale.clone());
        let floor = if self.is_rational() {
            floor_div(&(&self.a * &sr))
        } else {
            // x·S = a·S + c·√N with N = dn·dd, c = b·S/dd; c·√N = ±√(cn²·N)/cd.
            let a_s = &self.a * &sr;
            let n = self.d.numer() * self.d.denom();
            let c = &self.b * &sr / BigRational::from_integer(self.d.denom().clone());
            let m = c.numer() * c.numer() * &n;
            let cd = c.denom().clone();
            let neg = c.is_negative();
            let mut k: u32 = 0;
            loop {
                // isqrt(m·4^k) / 2^k ≤ √m < (isqrt(m·4^k) + 1) / 2^k.
                let mk = &m << (2 * k as usize);
                let root = big_isqrt(&mk);
                let den = BigRational::from_integer(&cd << (k as usize));
                let lo_abs = BigRational::from_integer(root.clone()) / &den;
                let hi_abs = BigRational::from_integer(root + BigInt::one()) / &den;
                let (lo, hi) = if neg {
                    (&a_s - hi_abs, &a_s - lo_abs)
                } else {
                    (&a_s + lo_abs, &a_s + hi_abs)
                };
                let fl = floor_div(&lo);
                if fl == floor_div(&hi) || k > 4096 {
                    break fl;
                }
                k += 8;
            }
        };
        let neg = floor.is_negative();
        let abs = floor.abs();
        let (int_part, frac_part) = abs.div_rem(&scale);
        let mut out = String::new();
        if neg {
            out.push('-');
        }
        out.push_str(&int_part.to_string());
        if digits > 0 {
            let f = frac_part.to_string();
            out.push('.');
            for _ in f.len()..digits {
                out.push('0');
            }
            out.push_str(&f);
        }
        out
    }
}

impl fmt::Display for ExactTime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_rational() {
            write!(f, "{}", self.a)
        } else {
            write!(f, "{} + ({})·√({})", self.a, self.b, self.d)
        }
    }
}
