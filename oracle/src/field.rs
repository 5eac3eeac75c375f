//! The number layer: the arithmetic paper A's formulas are written with
//! ([`Arith`]), the exact field behind every exact decision ([`ExactField`]) with its
//! two backends, and the small 2D vector type ([`V2`]).
//!
//! The default exact backend is [`num_rational::BigRational`] (pure Rust), and
//! `rug::Rational` (GMP) is the faster one behind the crate feature `rug`. This
//! module decides nothing about enclosures: the kernels ([`crate::kernel`]) build on
//! it, never the other way round.

use core::cmp::Ordering;
use core::fmt::Debug;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The default exact number type: an arbitrary-precision rational.
pub type Q = BigRational;

/// The GMP exact number type (feature `rug`).
#[cfg(feature = "rug")]
pub type R = rug::Rational;

/// The arithmetic paper A's formulas are written with: what exact numbers and the
/// interval kernel's enclosures ([`crate::kernel::interval::Iv`]) both provide.
/// Nothing here decides a sign; decisions belong to a [`crate::kernel::Kernel`].
pub trait Arith: Clone + Debug {
    /// The number 0.
    fn zero() -> Self;
    /// The number 1.
    fn one() -> Self;
    /// A small integer.
    fn from_i64(v: i64) -> Self;
    /// self + o.
    fn plus(&self, o: &Self) -> Self;
    /// self − o.
    fn minus(&self, o: &Self) -> Self;
    /// self · o.
    fn times(&self, o: &Self) -> Self;
    /// −self.
    fn negated(&self) -> Self;
    /// self / o, `None` when o is 0 (for an enclosure: when it may be 0).
    fn quotient(&self, o: &Self) -> Option<Self>;
    /// self / 2.
    fn half(&self) -> Self;
    /// self², the square.
    fn sq(&self) -> Self {
        self.times(self)
    }
    /// 2·self.
    fn twice(&self) -> Self {
        self.plus(self)
    }
}

/// An exact ordered field (rationals). Every sign decision of the exact kernel
/// ([`crate::kernel::Exact`]) is a comparison of such numbers, or of numbers built
/// from them in [`crate::qfield`].
pub trait ExactField: Arith + Ord + Eq + Send + Sync + 'static {
    /// The dyadic number (−1)^neg · mant · 2^exp (how a finite binary float is built).
    fn from_dyadic(neg: bool, mant: u64, exp: i32) -> Self;
    /// num/den from decimal digit strings (num may start with '-'; den is positive);
    /// `None` when a string is not an integer or den is 0.
    fn from_int_strs(num: &str, den: &str) -> Option<Self>;
    /// (m, k) with self = m / 2^k, when the denominator is a power of two and the
    /// numerator fits an i64 (a structural test: how the interval kernel recognises
    /// the numbers it can hold exactly; `None` is always allowed).
    fn as_dyadic(&self) -> Option<(i64, u64)>;
    /// The sign of self, as its order relative to 0.
    fn sign(&self) -> Ordering;
    /// The same number as a `BigRational` (for answers that leave the oracle).
    fn to_big(&self) -> BigRational;

    /// self = 0.
    fn is_zero_(&self) -> bool {
        self.sign() == Ordering::Equal
    }
    /// self > 0.
    fn is_pos(&self) -> bool {
        self.sign() == Ordering::Greater
    }
    /// self < 0.
    fn is_neg(&self) -> bool {
        self.sign() == Ordering::Less
    }
}

impl Arith for BigRational {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn from_i64(v: i64) -> Self {
        BigRational::from_integer(BigInt::from(v))
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn negated(&self) -> Self {
        -self
    }
    fn quotient(&self, o: &Self) -> Option<Self> {
        if o.is_zero() {
            None
        } else {
            Some(self / o)
        }
    }
    fn half(&self) -> Self {
        self / BigInt::from(2)
    }
}

impl ExactField for BigRational {
    fn from_dyadic(neg: bool, mant: u64, exp: i32) -> Self {
        let mut m = BigInt::from(mant);
        if neg {
            m = -m;
        }
        if exp >= 0 {
            BigRational::from_integer(m << exp.unsigned_abs())
        } else {
            // Lowest terms by shifts: the denominator is a power of two, so the common
            // factor is the power of two dividing the mantissa.
            let k = u64::from(mant.trailing_zeros()).min(u64::from(exp.unsigned_abs()));
            let den_exp = u64::from(exp.unsigned_abs()) - k;
            if mant == 0 {
                return BigRational::from_integer(BigInt::zero());
            }
            BigRational::new_raw(m >> k, BigInt::one() << den_exp)
        }
    }
    fn from_int_strs(num: &str, den: &str) -> Option<Self> {
        let n: BigInt = num.parse().ok()?;
        let d: BigInt = den.parse().ok()?;
        if d.is_zero() {
            return None;
        }
        Some(BigRational::new(n, d))
    }
    fn as_dyadic(&self) -> Option<(i64, u64)> {
        let d = self.denom();
        let k = d.trailing_zeros()?;
        if d.bits() != k + 1 {
            return None;
        }
        Some((self.numer().to_i64()?, k))
    }
    fn sign(&self) -> Ordering {
        if self.is_positive() {
            Ordering::Greater
        } else if self.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
    fn to_big(&self) -> BigRational {
        self.clone()
    }
}

#[cfg(feature = "rug")]
mod rug_backend {
    use super::{Arith, ExactField};
    use core::cmp::Ordering;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use rug::{Integer, Rational};

    fn big_of(i: &Integer) -> BigInt {
        // The 32-bit digits, least significant first, are an exact interchange format.
        let sign = match i.cmp0() {
            Ordering::Less => num_bigint::Sign::Minus,
            Ordering::Equal => num_bigint::Sign::NoSign,
            Ordering::Greater => num_bigint::Sign::Plus,
        };
        let mut digits = vec![0u32; i.significant_digits::<u32>()];
        i.write_digits(&mut digits, rug::integer::Order::Lsf);
        BigInt::from_slice(sign, &digits)
    }

    impl Arith for Rational {
        fn zero() -> Self {
            Rational::new()
        }
        fn one() -> Self {
            Rational::from(1)
        }
        fn from_i64(v: i64) -> Self {
            Rational::from(v)
        }
        fn plus(&self, o: &Self) -> Self {
            Rational::from(self + o)
        }
        fn minus(&self, o: &Self) -> Self {
            Rational::from(self - o)
        }
        fn times(&self, o: &Self) -> Self {
            Rational::from(self * o)
        }
        fn negated(&self) -> Self {
            Rational::from(-self)
        }
        fn quotient(&self, o: &Self) -> Option<Self> {
            if o.cmp0() == Ordering::Equal {
                None
            } else {
                Some(Rational::from(self / o))
            }
        }
        fn half(&self) -> Self {
            Rational::from(self >> 1u32)
        }
    }

    impl ExactField for Rational {
        fn from_dyadic(neg: bool, mant: u64, exp: i32) -> Self {
            let mut r = Rational::from(mant);
            if neg {
                r = -r;
            }
            r << exp
        }
        fn from_int_strs(num: &str, den: &str) -> Option<Self> {
            let n = Integer::from_str_radix(num, 10).ok()?;
            let d = Integer::from_str_radix(den, 10).ok()?;
            if d == 0 {
                return None;
            }
            Some(Rational::from((n, d)))
        }
        fn as_dyadic(&self) -> Option<(i64, u64)> {
            let d = self.denom();
            if !d.is_power_of_two() {
                return None;
            }
            let k = u64::from(d.significant_bits()).checked_sub(1)?;
            Some((self.numer().to_i64()?, k))
        }
        fn sign(&self) -> Ordering {
            self.cmp0()
        }
        fn to_big(&self) -> BigRational {
            // A rug rational is canonical (lowest terms, positive denominator),
            // as a BigRational must be: no reduction needed.
            BigRational::new_raw(big_of(self.numer()), big_of(self.denom()))
        }
    }
}

/// A 2D vector (the paper's bold-face letters), of exact numbers or of enclosures.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct V2<F> {
    /// x component.
    pub x: F,
    /// y component.
    pub y: F,
}

impl<N: Arith> V2<N> {
    /// The vector (x, y).
    pub fn new(x: N, y: N) -> Self {
        V2 { x, y }
    }
    /// The zero vector **0**.
    pub fn zero() -> Self {
        V2::new(N::zero(), N::zero())
    }
    /// self + o.
    pub fn plus(&self, o: &Self) -> Self {
        V2::new(self.x.plus(&o.x), self.y.plus(&o.y))
    }
    /// self − o.
    pub fn minus(&self, o: &Self) -> Self {
        V2::new(self.x.minus(&o.x), self.y.minus(&o.y))
    }
    /// −self.
    pub fn negated(&self) -> Self {
        V2::new(self.x.negated(), self.y.negated())
    }
    /// k · self.
    pub fn scale(&self, k: &N) -> Self {
        V2::new(self.x.times(k), self.y.times(k))
    }
    /// self / 2.
    pub fn half(&self) -> Self {
        V2::new(self.x.half(), self.y.half())
    }
    /// self + t · d (a position after time t at velocity d).
    pub fn at(&self, d: &Self, t: &N) -> Self {
        self.plus(&d.scale(t))
    }
    /// The dot product self · o.
    pub fn dot(&self, o: &Self) -> N {
        self.x.times(&o.x).plus(&self.y.times(&o.y))
    }
    /// The square self · self.
    pub fn sq(&self) -> N {
        self.x.sq().plus(&self.y.sq())
    }
    /// The 2D cross product self_x·o_y − self_y·o_x, equal to self · o^⊥.
    pub fn cross(&self, o: &Self) -> N {
        self.x.times(&o.y).minus(&self.y.times(&o.x))
    }
    /// The right perpendicular self^⊥ = (self_y, −self_x) of paper A §I.
    pub fn perp(&self) -> Self {
        V2::new(self.y.clone(), self.x.negated())
    }
}

impl<F: ExactField> V2<F> {
    /// self = **0**.
    pub fn is_zero(&self) -> bool {
        self.x.is_zero_() && self.y.is_zero_()
    }
}
