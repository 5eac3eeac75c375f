//! The exact field behind every oracle computation, its two backends, and the
//! small 2D vector type the paper's formulas are written with.
//!
//! Generic code sees only [`ExactField`]; the default backend is
//! [`num_rational::BigRational`] (pure Rust), and `rug::Rational` (GMP) is the
//! faster one behind the crate feature `rug`.

use core::cmp::Ordering;
use core::fmt::Debug;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// The default exact number type: an arbitrary-precision rational.
pub type Q = BigRational;

/// The GMP exact number type (feature `rug`).
#[cfg(feature = "rug")]
pub type R = rug::Rational;

/// An exact ordered field (rationals). Every sign decision of the oracle is a
/// comparison of such numbers, or of numbers built from them in [`crate::qfield`].
///
/// The supertrait [`crate::filter::Enclose`] lets the floating filter enclose a
/// value in an interval; it never decides anything by itself.
pub trait ExactField:
    Clone + Ord + Eq + Debug + Send + Sync + 'static + crate::filter::Enclose
{
    /// The number 0.
    fn zero() -> Self;
    /// The number 1.
    fn one() -> Self;
    /// A small integer.
    fn from_i64(v: i64) -> Self;
    /// The dyadic number (−1)^neg · mant · 2^exp (how a finite binary float is built).
    fn from_dyadic(neg: bool, mant: u64, exp: i32) -> Self;
    /// num/den from decimal digit strings (num may start with '-'; den is positive);
    /// `None` when a string is not an integer or den is 0.
    fn from_int_strs(num: &str, den: &str) -> Option<Self>;
    /// self + o.
    fn plus(&self, o: &Self) -> Self;
    /// self − o.
    fn minus(&self, o: &Self) -> Self;
    /// self · o.
    fn times(&self, o: &Self) -> Self;
    /// −self.
    fn negated(&self) -> Self;
    /// self / o, `None` when o = 0.
    fn quotient(&self, o: &Self) -> Option<Self>;
    /// self / 2.
    fn half(&self) -> Self;
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
    /// self², the square.
    fn sq(&self) -> Self {
        self.times(self)
    }
    /// σ·self for a sign σ = ±1.
    fn signed(&self, sigma: i8) -> Self {
        if sigma < 0 {
            self.negated()
        } else {
            self.clone()
        }
    }
}

impl ExactField for BigRational {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn from_i64(v: i64) -> Self {
        BigRational::from_integer(BigInt::from(v))
    }
    fn from_dyadic(neg: bool, mant: u64, exp: i32) -> Self {
        let mut m = BigInt::from(mant);
        if neg {
            m = -m;
        }
        if exp >= 0 {
            BigRational::from_integer(m << exp.unsigned_abs())
        } else {
            BigRational::new(m, BigInt::one() << exp.unsigned_abs())
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
    use super::ExactField;
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

    impl ExactField for Rational {
        fn zero() -> Self {
            Rational::new()
        }
        fn one() -> Self {
            Rational::from(1)
        }
        fn from_i64(v: i64) -> Self {
            Rational::from(v)
        }
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

/// A 2D vector of exact numbers (the paper's bold-face letters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct V2<F> {
    /// x component.
    pub x: F,
    /// y component.
    pub y: F,
}

impl<F: ExactField> V2<F> {
    /// The vector (x, y).
    pub fn new(x: F, y: F) -> Self {
        V2 { x, y }
    }
    /// The zero vector **0**.
    pub fn zero() -> Self {
        V2::new(F::zero(), F::zero())
    }
    /// self + o.
    pub fn plus(&self, o: &Self) -> Self {
        V2::new(self.x.plus(&o.x), self.y.plus(&o.y))
    }
    /// self − o.
    pub fn minus(&self, o: &Self) -> Self {
        V2::new(self.x.minus(&o.x), self.y.minus(&o.y))
    }
    /// k · self.
    pub fn scale(&self, k: &F) -> Self {
        V2::new(self.x.times(k), self.y.times(k))
    }
    /// self / 2.
    pub fn half(&self) -> Self {
        V2::new(self.x.half(), self.y.half())
    }
    /// σ · self, σ = ±1.
    pub fn signed(&self, sigma: i8) -> Self {
        V2::new(self.x.signed(sigma), self.y.signed(sigma))
    }
    /// self + t · d (a position after time t at velocity d).
    pub fn at(&self, d: &Self, t: &F) -> Self {
        self.plus(&d.scale(t))
    }
    /// The dot product self · o.
    pub fn dot(&self, o: &Self) -> F {
        self.x.times(&o.x).plus(&self.y.times(&o.y))
    }
    /// The square self · self.
    pub fn sq(&self) -> F {
        self.dot(self)
    }
    /// The 2D cross product self_x·o_y − self_y·o_x, equal to self · o^⊥.
    pub fn cross(&self, o: &Self) -> F {
        self.x.times(&o.y).minus(&self.y.times(&o.x))
    }
    /// The right perpendicular self^⊥ = (self_y, −self_x) of paper A §I.
    pub fn perp(&self) -> Self {
        V2::new(self.y.clone(), self.x.negated())
    }
    /// self = **0**.
    pub fn is_zero(&self) -> bool {
        self.x.is_zero_() && self.y.is_zero_()
    }
}
