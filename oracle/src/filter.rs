//! The floating filter in front of the exact oracle, as CGAL's filtered kernels
//! do it: every sign decision of [`crate::paper_detect`] and [`crate::truth()`] is
//! first tried in interval arithmetic on binary floats, and made exactly only when
//! the interval cannot certify it. The answers are those of the exact path
//! ([`crate::paper_detect_unfiltered`], [`crate::truth_unfiltered`]), bit for bit.
//!
//! This is the only module besides [`crate::convert`] that names a float type.
//! Floats never decide anything here: they only prove signs.
//!
//! # Why it is rigorous
//!
//! - **Enclosures.** An [`Iv`] `[lo, hi]` stands for one real number x that the
//!   exact path computes, with lo ≤ x ≤ hi. Inputs are enclosed by [`enclose`]: a
//!   dyadic rational that is a binary float exactly (every input that came from
//!   f64) becomes the point interval; any other rational gets end points that are
//!   *checked* exactly against it (lo, hi are converted back to rationals and
//!   compared; no float conversion routine is trusted).
//! - **Outward rounding.** Each operation computes the round-to-nearest result r
//!   of IEEE 754 (+, −, ×, ÷ and √ are correctly rounded), whose error is at most
//!   half an ulp; the end points are then moved outward by one ulp with
//!   [`next_down`] / [`next_up`] (bit steps), so the exact result lies in
//!   [next_down(r), next_up(r)] — also at binade boundaries, in the subnormal range
//!   and on overflow (next_down(+∞) = MAX is below any overflowed true value).
//!   Additions use Knuth's TwoSum instead, which yields the exact rounding error
//!   and therefore the tightest directed result (a difference of equal floats
//!   stays exactly 0); it is used only while no operand reaches 2^1000, where no
//!   intermediate can overflow. A product or quotient with an exactly-zero factor
//!   is exactly 0. Any NaN turns the interval into (−∞, +∞), and an operation on an
//!   infinite end point returns (−∞, +∞): such intervals certify nothing.
//! - **Decisions.** A sign is certain when the interval excludes 0 (lo > 0 or
//!   hi < 0), or is the point [0, 0]; a comparison x < y is certainly true when
//!   hi(x) < lo(y) and certainly false when lo(x) ≥ hi(y). Decisions are combined
//!   with Kleene's three-valued logic (`Option<bool>`, `None` = not certified), so
//!   a combined answer is certified only when every completion of the unknowns
//!   gives it. The filtered functions evaluate the *same* formulas as the exact
//!   ones, on enclosures of the same real numbers; a case split of the exact code
//!   (the sign of a leading coefficient, of a discriminant) is followed only when
//!   it is certified, else the filtered function answers `None`.
//! - **Fallback.** `None` sends that one paper function call (near_edge aside:
//!   one step of a detector, one edge_detect, one contact test of the truth) to
//!   the exact code with the exact inputs. Exact shortcuts of the exact code
//!   (far_from_edge, boxes_apart, the bounding-box exit of near_edge) are proven
//!   not to change answers, so the filter uses them only when certified.
//! - **Entry times.** The truth's first entry time is always produced by the exact
//!   code: the filter only certifies which root of which edge's contact quadratic
//!   comes first (and that earlier roots fail), and edges whose certified contact
//!   is certainly later than another certified contact are skipped; the exact
//!   root is then built by the same function the exact path uses, so even the
//!   representation of the algebraic number is the same.

use core::cmp::Ordering;

use num_rational::BigRational;
use num_traits::ToPrimitive;

use crate::case::{ExactCase, PaperAnswer};
use crate::convert::f64_to_exact;
use crate::detect::{all_equal, slab_interval};
use crate::field::{ExactField, V2};
use crate::qfield::Alg;
use crate::truth::{
    bad_lengths, contact_coeffs, contact_roots, crossing_at_start, in_closed_polygon, min_alg,
    segments_intersect, vertex_meets_edge, window, ExactTime, Truth,
};

// ---------------------------------------------------------------------------
// Directed rounding by one-ulp steps.

/// The least float greater than x (x for NaN and +∞; −MAX for −∞ is not needed).
#[inline]
pub fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    if x > 0.0 {
        f64::from_bits(b + 1)
    } else {
        f64::from_bits(b - 1)
    }
}

/// The greatest float less than x.
#[inline]
pub fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// 2^1000: below it, TwoSum's intermediates cannot overflow.
const TWO_SUM_LIMIT: f64 = 1.0715086071862673e301;

/// A float ≤ a + b (the exact sum), as tight as possible.
#[inline]
fn add_dn(a: f64, b: f64) -> f64 {
    let s = a + b;
    if a.abs() < TWO_SUM_LIMIT && b.abs() < TWO_SUM_LIMIT {
        let bb = s - a;
        let err = (a - (s - bb)) + (b - bb);
        if err < 0.0 {
            next_down(s)
        } else {
            s
        }
    } else {
        next_down(s)
    }
}

/// A float ≥ a + b (the exact sum), as tight as possible.
#[inline]
fn add_up(a: f64, b: f64) -> f64 {
    -add_dn(-a, -b)
}

/// A float ≤ a·b.
#[inline]
fn mul_dn(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        next_down(a * b)
    }
}

/// A float ≥ a·b.
#[inline]
fn mul_up(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        next_up(a * b)
    }
}

// ---------------------------------------------------------------------------
// Intervals.

/// A closed interval [lo, hi] of floats enclosing one real number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iv {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// Kleene's "and" of certified decisions.
#[inline]
fn and2(a: Option<bool>, b: Option<bool>) -> Option<bool> {
    match (a, b) {
        (Some(false), _) | (_, Some(false)) => Some(false),
        (Some(true), Some(true)) => Some(true),
        _ => None,
    }
}

/// Kleene's "or" of certified decisions.
#[inline]
fn or2(a: Option<bool>, b: Option<bool>) -> Option<bool> {
    match (a, b) {
        (Some(true), _) | (_, Some(true)) => Some(true),
        (Some(false), Some(false)) => Some(false),
        _ => None,
    }
}

/// Kleene's "and" over several decisions.
fn all(xs: &[Option<bool>]) -> Option<bool> {
    let mut acc = Some(true);
    for &x in xs {
        acc = and2(acc, x);
    }
    acc
}

/// Kleene's "or" over several decisions.
fn any(xs: &[Option<bool>]) -> Option<bool> {
    let mut acc = Some(false);
    for &x in xs {
        acc = or2(acc, x);
    }
    acc
}

// Named methods rather than operator traits: each one is an outward-rounded
// enclosure, not the float operation its symbol would suggest.
#[allow(clippy::should_implement_trait)]
impl Iv {
    /// The point 0.
    pub const ZERO: Iv = Iv { lo: 0.0, hi: 0.0 };
    /// The point 1.
    pub const ONE: Iv = Iv { lo: 1.0, hi: 1.0 };
    /// Every real number (certifies nothing).
    pub const ENTIRE: Iv = Iv {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// [lo, hi]; (−∞, +∞) when an end is NaN.
    #[inline]
    fn raw(lo: f64, hi: f64) -> Iv {
        if lo.is_nan() || hi.is_nan() {
            Iv::ENTIRE
        } else {
            Iv { lo, hi }
        }
    }

    /// The point x (exact).
    #[inline]
    pub fn point(x: f64) -> Iv {
        // −0 and +0 are the same number; keep +0 so that "is exactly 0" is simple.
        let x = if x == 0.0 { 0.0 } else { x };
        Iv::raw(x, x)
    }

    #[inline]
    fn finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    #[inline]
    fn is_zero(self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }

    /// self + o.
    #[inline]
    pub fn add(self, o: Iv) -> Iv {
        Iv::raw(add_dn(self.lo, o.lo), add_up(self.hi, o.hi))
    }

    /// self − o.
    #[inline]
    pub fn sub(self, o: Iv) -> Iv {
        self.add(o.neg())
    }

    /// −self.
    #[inline]
    pub fn neg(self) -> Iv {
        Iv {
            lo: -self.hi,
            hi: -self.lo,
        }
    }

    /// self · o.
    #[inline]
    pub fn mul(self, o: Iv) -> Iv {
        if self.is_zero() || o.is_zero() {
            return Iv::ZERO;
        }
        if !(self.finite() && o.finite()) {
            return Iv::ENTIRE;
        }
        let (a, b, c, d) = (self.lo, self.hi, o.lo, o.hi);
        if a == b && c == d {
            return Iv::raw(mul_dn(a, c), mul_up(a, c));
        }
        // The classic sign cases: the extreme products are known in advance.
        let (lo, hi) = if a >= 0.0 {
            if c >= 0.0 {
                (mul_dn(a, c), mul_up(b, d))
            } else if d <= 0.0 {
                (mul_dn(b, c), mul_up(a, d))
            } else {
                (mul_dn(b, c), mul_up(b, d))
            }
        } else if b <= 0.0 {
            if c >= 0.0 {
                (mul_dn(a, d), mul_up(b, c))
            } else if d <= 0.0 {
                (mul_dn(b, d), mul_up(a, c))
            } else {
                (mul_dn(a, d), mul_up(a, c))
            }
        } else if c >= 0.0 {
            (mul_dn(a, d), mul_up(b, d))
        } else if d <= 0.0 {
            (mul_dn(b, c), mul_up(a, c))
        } else {
            (
                mul_dn(a, d).min(mul_dn(b, c)),
                mul_up(a, c).max(mul_up(b, d)),
            )
        };
        Iv::raw(lo, hi)
    }

    /// self² (tighter than self · self when the interval holds 0).
    #[inline]
    pub fn sq(self) -> Iv {
        if !self.finite() {
            return Iv::raw(0.0, f64::INFINITY);
        }
        if self.lo >= 0.0 {
            Iv::raw(mul_dn(self.lo, self.lo), mul_up(self.hi, self.hi))
        } else if self.hi <= 0.0 {
            Iv::raw(mul_dn(self.hi, self.hi), mul_up(self.lo, self.lo))
        } else {
            let m = self.lo.abs().max(self.hi);
            Iv::raw(0.0, mul_up(m, m))
        }
    }

    /// 2·self (exact unless it overflows).
    #[inline]
    pub fn twice(self) -> Iv {
        self.add(self)
    }

    /// self / 2.
    #[inline]
    pub fn half(self) -> Iv {
        self.mul(Iv::point(0.5))
    }

    /// self / o; (−∞, +∞) when o may be 0.
    pub fn div(self, o: Iv) -> Iv {
        if !(o.lo > 0.0 || o.hi < 0.0) || !(self.finite() && o.finite()) {
            return Iv::ENTIRE;
        }
        if self.is_zero() {
            return Iv::ZERO;
        }
        // A quotient is exactly 0 only when its dividend is; others move outward.
        let q_dn = |x: f64, y: f64| if x == 0.0 { 0.0 } else { next_down(x / y) };
        let q_up = |x: f64, y: f64| if x == 0.0 { 0.0 } else { next_up(x / y) };
        let (a, b, c, d) = (self.lo, self.hi, o.lo, o.hi);
        let lo = q_dn(a, c).min(q_dn(a, d)).min(q_dn(b, c)).min(q_dn(b, d));
        let hi = q_up(a, c).max(q_up(a, d)).max(q_up(b, c)).max(q_up(b, d));
        Iv::raw(lo, hi)
    }

    /// √self for self ≥ 0 (the part below 0 is ignored).
    pub fn sqrt(self) -> Iv {
        let lo = if self.lo > 0.0 {
            next_down(self.lo.sqrt()).max(0.0)
        } else {
            0.0
        };
        let hi = if self.hi > 0.0 {
            next_up(self.hi.sqrt())
        } else {
            0.0
        };
        Iv::raw(lo, hi)
    }

    /// |self|.
    #[inline]
    pub fn abs(self) -> Iv {
        if self.lo >= 0.0 {
            self
        } else if self.hi <= 0.0 {
            self.neg()
        } else {
            Iv::raw(0.0, self.hi.max(-self.lo))
        }
    }

    /// max(self, o) (the enclosure of the larger number).
    #[inline]
    pub fn max(self, o: Iv) -> Iv {
        Iv::raw(self.lo.max(o.lo), self.hi.max(o.hi))
    }

    /// min(self, o).
    #[inline]
    pub fn min(self, o: Iv) -> Iv {
        Iv::raw(self.lo.min(o.lo), self.hi.min(o.hi))
    }

    /// The certified sign, `None` when the interval cannot tell.
    #[inline]
    pub fn sign(self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.is_zero() {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// Certified self < o.
    #[inline]
    pub fn lt(self, o: Iv) -> Option<bool> {
        if self.hi < o.lo {
            Some(true)
        } else if self.lo >= o.hi {
            Some(false)
        } else {
            None
        }
    }

    /// Certified self ≤ o.
    #[inline]
    pub fn le(self, o: Iv) -> Option<bool> {
        if self.hi <= o.lo {
            Some(true)
        } else if self.lo > o.hi {
            Some(false)
        } else {
            None
        }
    }

    /// Certified self > 0.
    #[inline]
    fn pos(self) -> Option<bool> {
        Iv::ZERO.lt(self)
    }

    /// Certified self < 0.
    #[inline]
    fn neg0(self) -> Option<bool> {
        self.lt(Iv::ZERO)
    }

    /// Certified self = 0.
    #[inline]
    fn eq0(self) -> Option<bool> {
        self.sign().map(|s| s == Ordering::Equal)
    }

    /// Certified self = o for two point intervals or disjoint ones.
    fn eq(self, o: Iv) -> Option<bool> {
        if self.lo == self.hi && o.lo == o.hi {
            Some(self.lo == o.lo)
        } else if self.hi < o.lo || o.hi < self.lo {
            Some(false)
        } else {
            None
        }
    }
}

/// A 2D vector of intervals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IV2 {
    /// x component.
    pub x: Iv,
    /// y component.
    pub y: Iv,
}

impl IV2 {
    fn new(x: Iv, y: Iv) -> IV2 {
        IV2 { x, y }
    }
    #[inline]
    fn plus(self, o: IV2) -> IV2 {
        IV2::new(self.x.add(o.x), self.y.add(o.y))
    }
    #[inline]
    fn minus(self, o: IV2) -> IV2 {
        IV2::new(self.x.sub(o.x), self.y.sub(o.y))
    }
    #[inline]
    fn scale(self, k: Iv) -> IV2 {
        IV2::new(self.x.mul(k), self.y.mul(k))
    }
    fn half(self) -> IV2 {
        IV2::new(self.x.half(), self.y.half())
    }
    fn signed(self, sigma: i8) -> IV2 {
        if sigma < 0 {
            IV2::new(self.x.neg(), self.y.neg())
        } else {
            self
        }
    }
    #[inline]
    fn at(self, d: IV2, t: Iv) -> IV2 {
        self.plus(d.scale(t))
    }
    #[inline]
    fn dot(self, o: IV2) -> Iv {
        self.x.mul(o.x).add(self.y.mul(o.y))
    }
    fn sq(self) -> Iv {
        self.x.sq().add(self.y.sq())
    }
    #[inline]
    fn cross(self, o: IV2) -> Iv {
        self.x.mul(o.y).sub(self.y.mul(o.x))
    }
    fn perp(self) -> IV2 {
        IV2::new(self.y, self.x.neg())
    }
    fn eq(self, o: IV2) -> Option<bool> {
        and2(self.x.eq(o.x), self.y.eq(o.y))
    }
}

// ---------------------------------------------------------------------------
// Enclosing exact numbers.

/// What the filter needs from an exact backend. Nothing here is trusted for
/// rigor except [`Enclose::as_f64_exactly`], which must return `Some(x)` only when
/// the number equals x exactly (returning `None` is always allowed).
pub trait Enclose {
    /// The number as a binary float when it is one exactly (a structural test).
    fn as_f64_exactly(&self) -> Option<f64>;
    /// Some float near the number (no accuracy promised: [`enclose`] checks it).
    fn near_f64(&self) -> f64;
}

/// m · 2^−k for |m| < 2^53 and k ≤ 969: a normal float, computed exactly.
fn dyadic(m: i64, k: u64) -> f64 {
    // |m| < 2^53 converts exactly; 2^−k is a normal float; the product is ≥ 2^−969
    // in magnitude (or 0) and has at most 53 significant bits: exact.
    (m as f64) * f64::from_bits((1023 - k) << 52)
}

impl Enclose for BigRational {
    fn as_f64_exactly(&self) -> Option<f64> {
        let d = self.denom();
        let k = d.trailing_zeros()?;
        if d.bits() != k + 1 || k > 969 || self.numer().bits() > 53 {
            return None;
        }
        Some(dyadic(self.numer().to_i64()?, k))
    }
    fn near_f64(&self) -> f64 {
        self.to_f64().unwrap_or(f64::NAN)
    }
}

#[cfg(feature = "rug")]
impl Enclose for rug::Rational {
    fn as_f64_exactly(&self) -> Option<f64> {
        let d = self.denom();
        if !d.is_power_of_two() {
            return None;
        }
        let k = u64::from(d.significant_bits()).checked_sub(1)?;
        if k > 969 || self.numer().significant_bits() > 53 {
            return None;
        }
        Some(dyadic(self.numer().to_i64()?, k))
    }
    fn near_f64(&self) -> f64 {
        self.to_f64()
    }
}

/// A float ≤ x (or ≥ x when `above`), checked exactly; ∓∞ when the check fails.
fn checked_end<F: ExactField>(x: &F, start: f64, above: bool) -> f64 {
    let mut e = start;
    for _ in 0..4 {
        let ok = match f64_to_exact::<F>(e) {
            Some(r) if above => r >= *x,
            Some(r) => r <= *x,
            None => false,
        };
        if ok {
            return e;
        }
        e = if above { next_up(e) } else { next_down(e) };
    }
    if above {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// A rigorous enclosure of an exact number: the point interval when it is a
/// float, else end points verified by exact comparison.
pub fn enclose<F: ExactField>(x: &F) -> Iv {
    if let Some(v) = x.as_f64_exactly() {
        return Iv::point(v);
    }
    let m = x.near_f64();
    if !m.is_finite() {
        return Iv::ENTIRE;
    }
    Iv::raw(checked_end(x, m, false), checked_end(x, m, true))
}

fn enclose2<F: ExactField>(p: &V2<F>) -> IV2 {
    IV2::new(enclose(&p.x), enclose(&p.y))
}

fn enclose_all<F: ExactField>(ps: &[V2<F>]) -> Vec<IV2> {
    ps.iter().map(enclose2).collect()
}

// ---------------------------------------------------------------------------
// Paper A §I, §II.B–II.G in intervals (each mirrors the exact function of the
// same name; `None` = not certified).

/// Paper A §I: quad_min_le_D, certified.
pub fn quad_min_le_d_iv(a: Iv, b: Iv, c: Iv, d: Iv) -> Option<bool> {
    let ends = or2(c.lt(d), a.add(b).add(c).lt(d));
    if ends == Some(true) {
        return ends;
    }
    let four_a = a.twice().twice();
    let interior = all(&[
        a.pos(),
        b.pos().map(|x| !x),
        b.neg().le(a.twice()),
        b.sq().sub(four_a.mul(c.sub(d))).pos(),
    ]);
    or2(ends, interior)
}

/// Paper A §I: quad(a, b, c)(t) = (a·t + b)·t + c.
#[inline]
fn quad_iv(a: Iv, b: Iv, c: Iv, t: Iv) -> Iv {
    a.mul(t).add(b).mul(t).add(c)
}

/// Paper A §I: quad_min_box_le_D, certified.
#[allow(clippy::too_many_arguments)]
pub fn quad_min_box_le_d_iv(a: Iv, b: Iv, c: Iv, d: Iv, e: Iv, f: Iv, dd: Iv) -> Option<bool> {
    let one = Iv::ONE;
    let sides = [
        quad_min_le_d_iv(a, c.add(d), quad_iv(b, e, f, one), dd),
        quad_min_le_d_iv(a, d, f, dd),
        quad_min_le_d_iv(b, c.add(e), quad_iv(a, d, f, one), dd),
        quad_min_le_d_iv(b, e, f, dd),
    ];
    let sides = any(&sides);
    if sides == Some(true) {
        return sides;
    }
    let disc = c.sq().sub(a.twice().twice().mul(b));
    let mx = b.twice().mul(d).sub(c.mul(e));
    let my = a.twice().mul(e).sub(c.mul(d));
    let disc2 = disc.sq();
    let mxd = mx.mul(disc);
    let myd = my.mul(disc);
    let inside = all(&[
        Iv::ZERO.le(mxd),
        mxd.le(disc2),
        Iv::ZERO.le(myd),
        myd.le(disc2),
    ]);
    let crit = if inside == Some(false) {
        Some(false)
    } else {
        // quad2D(a, b, c, d·disc, e·disc, f·disc², mx, my).
        let v = a
            .mul(mx.sq())
            .add(b.mul(my.sq()))
            .add(c.mul(mx).mul(my))
            .add(d.mul(disc).mul(mx))
            .add(e.mul(disc).mul(my))
            .add(f.mul(disc2));
        and2(inside, v.lt(dd.mul(disc2)))
    };
    or2(sides, crit)
}

/// Paper A §II.B: the perturbed vertex and whether it moved, certified.
fn perturb_vertex_iv(p: IV2, s: IV2, buff: Iv) -> Option<(IV2, bool)> {
    let dx = p.x.sub(s.x);
    let near = all(&[dx.le(buff), dx.neg().le(buff), s.y.sub(buff).le(p.y)])?;
    if near {
        Some((IV2::new(p.x.sub(buff.twice()), p.y), true))
    } else {
        Some((p, false))
    }
}

/// Paper A §II.C: near_edge, certified (b2 = BUFF²).
pub fn near_edge_iv(pi: IV2, pj: IV2, s: IV2, buff: Iv, b2: Iv) -> Option<bool> {
    // The exact early "false" (s at least BUFF outside the edge's box), when certified.
    let outside = |a: Iv, b: Iv, x: Iv| or2(x.add(buff).le(a.min(b)), a.max(b).add(buff).le(x));
    if or2(outside(pi.x, pj.x, s.x), outside(pi.y, pj.y, s.y)) == Some(true) {
        return Some(false);
    }
    let ends = or2(s.minus(pi).sq().lt(b2), s.minus(pj).sq().lt(b2));
    if ends == Some(true) {
        return ends;
    }
    let distinct = pi.eq(pj).map(|x| !x);
    let inner = if distinct == Some(false) {
        Some(false)
    } else {
        let e = pj.minus(pi);
        let w = pi.minus(s);
        and2(
            distinct,
            quad_min_le_d_iv(e.sq(), w.dot(e).twice(), w.sq(), b2),
        )
    };
    or2(ends, inner)
}

/// Paper A §II.D: does the edge cross the upward ray from s, certified.
fn edge_crosses_ray_iv(pi: IV2, pj: IV2, s: IV2) -> Option<bool> {
    let i_right = s.x.le(pi.x)?;
    let j_right = s.x.le(pj.x)?;
    if i_right == j_right {
        return Some(false);
    }
    // Different sides: p_ix ≠ p_jx, and sign(dx·c) = sign(dx)·sign(c).
    let dx = pj.x.sub(pi.x).sign()?;
    let c = s.minus(pi).cross(pj.minus(pi)).sign()?;
    Some(c == Ordering::Equal || c == dx)
}

/// Paper A §II.E: definitely_outside, certified.
pub fn definitely_outside_iv(poly: &[IV2], s: IV2, buff: Iv) -> Option<bool> {
    let n = poly.len();
    let b2 = buff.sq();
    let mut pstar = Vec::with_capacity(n);
    for &p in poly {
        pstar.push(perturb_vertex_iv(p, s, buff)?);
    }
    let mut unsure = false;
    for i in 0..n {
        let j = (i + 1) % n;
        match near_edge_iv(poly[i], poly[j], s, buff, b2) {
            Some(true) => return Some(false),
            Some(false) => {}
            None => unsure = true,
        }
    }
    for i in 0..n {
        let j = (i + 1) % n;
        let ((qi, mi), (qj, mj)) = (pstar[i], pstar[j]);
        if !(mi || mj) {
            continue;
        }
        match near_edge_iv(qi, qj, s, buff, b2) {
            Some(true) => return Some(false),
            Some(false) => {}
            None => unsure = true,
        }
    }
    if unsure {
        return None;
    }
    let mut crossings = 0usize;
    for i in 0..n {
        let j = (i + 1) % n;
        if edge_crosses_ray_iv(pstar[i].0, pstar[j].0, s)? {
            crossings += 1;
        }
    }
    Some(crossings % 2 == 0)
}

/// Paper A §II.G: segments_close, certified.
pub fn segments_close_iv(c: IV2, d: IV2, e: IV2, f: IV2, buff: Iv) -> Option<bool> {
    let b2 = buff.sq();
    let ends = any(&[
        near_edge_iv(e, f, c, buff, b2),
        near_edge_iv(e, f, d, buff, b2),
        near_edge_iv(c, d, e, buff, b2),
        near_edge_iv(c, d, f, buff, b2),
    ]);
    if ends == Some(true) {
        return ends;
    }
    let q = c.minus(e);
    let u = d.minus(c);
    let w = f.minus(e);
    let box_ = quad_min_box_le_d_iv(
        u.sq(),
        w.sq(),
        u.dot(w).twice().neg(),
        q.dot(u).twice(),
        q.dot(w).twice().neg(),
        q.sq(),
        b2,
    );
    or2(ends, box_)
}

// ---------------------------------------------------------------------------
// Paper A §II.I in intervals.

/// An enclosure of dot_nn_lin's interval: empty, or [lb, ub] with enclosed ends.
#[derive(Clone, Copy, Debug)]
enum IvSet {
    Empty,
    Closed(Iv, Iv),
}

/// Interval::clip, certified: [max(lo, 0), min(hi, T)], empty when lb > ub.
fn clip_iv(t: Iv, lo: Option<Iv>, hi: Option<Iv>) -> Option<IvSet> {
    let lb = lo.map_or(Iv::ZERO, |x| x.max(Iv::ZERO));
    let ub = hi.map_or(t, |x| x.min(t));
    if ub.lt(lb)? {
        Some(IvSet::Empty)
    } else {
        Some(IvSet::Closed(lb, ub))
    }
}

/// The two roots of a·x² + b·x + c (a ≠ 0, disc > 0), in quad_roots' order.
fn two_roots(a: Iv, b: Iv, disc: Iv) -> [Iv; 2] {
    let two_a = a.twice();
    let r = disc.sqrt();
    let mb = b.neg();
    // lo_sign = −1 when a > 0 (callers have certified the sign of a).
    let (lo, hi) = if a.lo > 0.0 {
        (mb.sub(r), mb.add(r))
    } else {
        (mb.add(r), mb.sub(r))
    };
    [lo.div(two_a), hi.div(two_a)]
}

/// Paper A §II.I: dot_nn_lin, certified (mirrors crate::detect::dot_nn_lin).
fn dot_nn_lin_iv(t: Iv, ww: IV2, vv: IV2, aa: IV2, bb: IV2, sigma: i8) -> Option<IvSet> {
    let a = vv.dot(bb);
    let b = ww.dot(bb).add(vv.dot(aa));
    let c = ww.dot(aa);
    let left = sigma < 0;
    match a.sign()? {
        Ordering::Equal => {
            if !left {
                return Some(IvSet::Empty);
            }
            match b.sign()? {
                Ordering::Equal => {
                    if c.neg0()? {
                        Some(IvSet::Empty)
                    } else {
                        clip_iv(t, None, None)
                    }
                }
                Ordering::Greater => clip_iv(t, Some(c.neg().div(b)), None),
                Ordering::Less => clip_iv(t, None, Some(c.neg().div(b))),
            }
        }
        Ordering::Greater => {
            let disc = b.sq().sub(a.twice().twice().mul(c));
            if !disc.pos()? {
                return if left {
                    clip_iv(t, None, None)
                } else {
                    Some(IvSet::Empty)
                };
            }
            let [r1, r2] = two_roots(a, b, disc);
            if left {
                clip_iv(t, None, Some(r1))
            } else {
                clip_iv(t, Some(r2), None)
            }
        }
        Ordering::Less => {
            if !left {
                return Some(IvSet::Empty);
            }
            let disc = b.sq().sub(a.twice().twice().mul(c));
            match disc.sign()? {
                Ordering::Less => Some(IvSet::Empty),
                Ordering::Equal => {
                    let r = b.neg().div(a.twice());
                    clip_iv(t, Some(r), Some(r))
                }
                Ordering::Greater => {
                    let [r1, r2] = two_roots(a, b, disc);
                    clip_iv(t, Some(r1), Some(r2))
                }
            }
        }
    }
}

/// Paper A §II.I support: far_from_edge, `true` only when certified.
fn far_from_edge_iv(t: Iv, ww: IV2, vv: IV2, aa: IV2, bb: IV2, fac: Iv) -> bool {
    if aa.cross(bb).eq0() != Some(false) {
        return false;
    }
    let u_t = aa.at(bb, t);
    let m0 = aa.x.abs().add(aa.y.abs());
    let m1 = u_t.x.abs().add(u_t.y.abs());
    let m = m0.max(m1);
    let r = m.add(m.mul(fac.twice()));
    let w_t = ww.at(vv, t);
    let nr = r.neg();
    let beyond = |a: Iv, b: Iv| or2(and2(r.lt(a), r.lt(b)), and2(a.lt(nr), b.lt(nr))) == Some(true);
    beyond(ww.x, w_t.x) || beyond(ww.y, w_t.y)
}

/// Paper A §II.I: edge_detect_simp, certified.
pub fn edge_detect_simp_iv(t: Iv, ww: IV2, vv: IV2, aa: IV2, bb: IV2, fac: Iv) -> Option<bool> {
    if far_from_edge_iv(t, ww, vv, aa, bb, fac) {
        return Some(false);
    }
    let f1 = Iv::ONE.add(fac);
    let groups = [(aa, bb, f1), (aa.perp(), bb.perp(), fac)];
    let mut ivs = [IvSet::Empty; 8];
    for (g, (x, y, k)) in groups.into_iter().enumerate() {
        for (i1, s1) in [-1i8, 1].into_iter().enumerate() {
            for (i2, s2) in [-1i8, 1].into_iter().enumerate() {
                // dot_nn(T, ww, vv, x, y, σ1, σ2, k).
                let w2 = x.scale(k).plus(ww.signed(s2));
                let v2 = y.scale(k).plus(vv.signed(s2));
                ivs[4 * g + 2 * i1 + i2] = dot_nn_lin_iv(t, w2, v2, x, y, s1)?;
            }
        }
        let col_empty =
            |s2: usize| (0..2).all(|s1| matches!(ivs[4 * g + 2 * s1 + s2], IvSet::Empty));
        if col_empty(0) || col_empty(1) {
            return Some(false);
        }
    }
    let mut le = [[None; 8]; 8];
    for (i, row) in le.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = match (ivs[i], ivs[j]) {
                (IvSet::Closed(lb, _), IvSet::Closed(_, ub)) => {
                    if i == j {
                        Some(true)
                    } else {
                        lb.le(ub)
                    }
                }
                _ => Some(false),
            };
        }
    }
    let si = |s: i8| usize::from(s > 0);
    let mut unsure = false;
    for e2 in [-1i8, 1] {
        for s2 in [-1i8, 1] {
            for e1 in [-1i8, 1] {
                for e3 in [-1i8, 1] {
                    for s1 in [-1i8, 1] {
                        for s3 in [-1i8, 1] {
                            let idx = [
                                2 * si(e1) + si(e2),
                                2 * si(e3) + si(-e2),
                                4 + 2 * si(s1) + si(s2),
                                4 + 2 * si(s3) + si(-s2),
                            ];
                            let mut meet = Some(true);
                            for &i in &idx {
                                for &j in &idx {
                                    meet = and2(meet, le[i][j]);
                                }
                            }
                            match meet {
                                Some(true) => return Some(true),
                                Some(false) => {}
                                None => unsure = true,
                            }
                        }
                    }
                }
            }
        }
    }
    if unsure {
        None
    } else {
        Some(false)
    }
}

/// Paper A §II.I: edge_detect (the midpoint frame), certified.
#[allow(clippy::too_many_arguments)]
pub fn edge_detect_iv(
    t: Iv,
    s: IV2,
    v: IV2,
    pi: IV2,
    pj: IV2,
    vi: IV2,
    vj: IV2,
    fac: Iv,
) -> Option<bool> {
    let ww = s.minus(pj.half().plus(pi.half()));
    let vv = v.minus(vj.half().plus(vi.half()));
    let aa = pj.half().minus(pi.half());
    let bb = vj.half().minus(vi.half());
    edge_detect_simp_iv(t, ww, vv, aa, bb, fac)
}

// ---------------------------------------------------------------------------
// The filtered detectors: same signatures and answers as crate::detect's.

/// The exact inputs of a 2D detector and their enclosures.
struct Inputs<'a, F> {
    t: &'a F,
    s: &'a V2<F>,
    v: &'a V2<F>,
    poly: &'a [V2<F>],
    vels: &'a [V2<F>],
    buff: &'a F,
    fac: &'a F,
    ti: Iv,
    si: IV2,
    vi: IV2,
    polyi: Vec<IV2>,
    velsi: Vec<IV2>,
    buffi: Iv,
    faci: Iv,
}

impl<'a, F: ExactField> Inputs<'a, F> {
    #[allow(clippy::too_many_arguments)]
    fn new(
        t: &'a F,
        s: &'a V2<F>,
        v: &'a V2<F>,
        poly: &'a [V2<F>],
        vels: &'a [V2<F>],
        buff: &'a F,
        fac: &'a F,
    ) -> Self {
        Inputs {
            t,
            s,
            v,
            poly,
            vels,
            buff,
            fac,
            ti: enclose(t),
            si: enclose2(s),
            vi: enclose2(v),
            polyi: enclose_all(poly),
            velsi: enclose_all(vels),
            buffi: enclose(buff),
            faci: enclose(fac),
        }
    }
}

fn same_2d<F: ExactField>(x: &Inputs<'_, F>) -> bool {
    let n = x.poly.len();
    if n == 0 || x.vels.len() != n || x.polyi.len() != n || x.velsi.len() != n {
        return false;
    }
    // Step 1: s at time 0.
    let outside0 = definitely_outside_iv(&x.polyi, x.si, x.buffi)
        .unwrap_or_else(|| crate::contain::definitely_outside(x.poly, x.s, x.buff));
    if !outside0 {
        return true;
    }
    // Step 2: s + T·v against P + T·V.
    let moved: Vec<IV2> = x
        .polyi
        .iter()
        .zip(&x.velsi)
        .map(|(&p, &w)| p.at(w, x.ti))
        .collect();
    let outside1 =
        definitely_outside_iv(&moved, x.si.at(x.vi, x.ti), x.buffi).unwrap_or_else(|| {
            let moved: Vec<V2<F>> = x
                .poly
                .iter()
                .zip(x.vels)
                .map(|(p, w)| p.at(w, x.t))
                .collect();
            crate::contain::definitely_outside(&moved, &x.s.at(x.v, x.t), x.buff)
        });
    if !outside1 {
        return true;
    }
    // Step 3: the relative path against each static edge.
    (0..n).any(|i| {
        let j = (i + 1) % n;
        let end = x.si.at(x.vi.minus(x.velsi[i]), x.ti);
        segments_close_iv(x.si, end, x.polyi[i], x.polyi[j], x.buffi).unwrap_or_else(|| {
            let end = x.s.at(&x.v.minus(&x.vels[i]), x.t);
            crate::proximity::segments_close(x.s, &end, &x.poly[i], &x.poly[j], x.buff)
        })
    })
}

fn diff_2d<F: ExactField>(x: &Inputs<'_, F>) -> bool {
    let n = x.poly.len();
    if n == 0 || x.vels.len() != n || x.polyi.len() != n || x.velsi.len() != n {
        return false;
    }
    let outside0 = definitely_outside_iv(&x.polyi, x.si, x.buffi)
        .unwrap_or_else(|| crate::contain::definitely_outside(x.poly, x.s, x.buff));
    if !outside0 {
        return true;
    }
    (0..n).any(|i| {
        let j = (i + 1) % n;
        edge_detect_iv(
            x.ti, x.si, x.vi, x.polyi[i], x.polyi[j], x.velsi[i], x.velsi[j], x.faci,
        )
        .unwrap_or_else(|| {
            crate::detect::edge_detect(
                x.t, x.s, x.v, &x.poly[i], &x.poly[j], &x.vels[i], &x.vels[j], x.fac,
            )
        })
    })
}

/// Paper A §II.H: detect_same_2D, filtered (the answer of
/// [`crate::detect::detect_same_2d`]).
pub fn detect_same_2d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    poly: &[V2<F>],
    vels: &[V2<F>],
    buff: &F,
) -> bool {
    // fac is not used by detect_same_2D; any enclosed number will do.
    let fac = F::zero();
    same_2d(&Inputs::new(t, s, v, poly, vels, buff, &fac))
}

/// Paper A §II.I: detect_diff_2D, filtered (the answer of
/// [`crate::detect::detect_diff_2d`]).
#[allow(clippy::too_many_arguments)]
pub fn detect_diff_2d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    poly: &[V2<F>],
    vels: &[V2<F>],
    fac: &F,
    buff: &F,
) -> bool {
    diff_2d(&Inputs::new(t, s, v, poly, vels, buff, fac))
}

/// Paper A §III: detect_3D, filtered (the answer of [`crate::detect::detect_3d`]).
#[allow(clippy::too_many_arguments)]
pub fn detect_3d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    sz: &F,
    vz: &F,
    poly: &[V2<F>],
    vels: &[V2<F>],
    pmin: &F,
    pmax: &F,
    vsp: &F,
    buff: &F,
    fac: &F,
) -> bool {
    let Some((a, b)) = slab_interval(t, sz, vz, pmin, pmax, vsp) else {
        return false;
    };
    let s2 = s.at(v, &a);
    let p2: Vec<V2<F>> = poly.iter().zip(vels).map(|(p, w)| p.at(w, &a)).collect();
    let t2 = b.minus(&a);
    if all_equal(vels) {
        detect_same_2d(&t2, &s2, v, &p2, vels, buff)
    } else {
        detect_diff_2d(&t2, &s2, v, &p2, vels, fac, buff)
    }
}

/// Paper A §II.F and §III: the filtered [`crate::paper_detect`].
pub fn paper_detect<F: ExactField>(c: &ExactCase<F>) -> PaperAnswer {
    if let Some(z) = &c.vertical {
        let detected = detect_3d(
            &c.lookahead,
            &c.s,
            &c.v,
            &z.sz,
            &z.vz,
            &c.vertices,
            &c.velocities,
            &z.bottom,
            &z.top,
            &z.vsp,
            &c.buff,
            &c.fac,
        );
        return PaperAnswer {
            detected,
            decided_by: "detect_3d",
        };
    }
    if c.is_static() {
        PaperAnswer {
            detected: detect_same_2d(
                &c.lookahead,
                &c.s,
                &c.v,
                &c.vertices,
                &c.velocities,
                &c.buff,
            ),
            decided_by: "detect_same_2d",
        }
    } else {
        PaperAnswer {
            detected: detect_diff_2d(
                &c.lookahead,
                &c.s,
                &c.v,
                &c.vertices,
                &c.velocities,
                &c.fac,
                &c.buff,
            ),
            decided_by: "detect_diff_2d",
        }
    }
}

/// Paper A §II.E: definitely_outside, filtered (the answer of
/// [`crate::contain::definitely_outside`]).
pub fn definitely_outside<F: ExactField>(poly: &[V2<F>], s: &V2<F>, buff: &F) -> bool {
    definitely_outside_iv(&enclose_all(poly), enclose2(s), enclose(buff))
        .unwrap_or_else(|| crate::contain::definitely_outside(poly, s, buff))
}

/// Paper A §II.G: segments_close, filtered (the answer of
/// [`crate::proximity::segments_close`]).
pub fn segments_close<F: ExactField>(c: &V2<F>, d: &V2<F>, e: &V2<F>, f: &V2<F>, buff: &F) -> bool {
    segments_close_iv(
        enclose2(c),
        enclose2(d),
        enclose2(e),
        enclose2(f),
        enclose(buff),
    )
    .unwrap_or_else(|| crate::proximity::segments_close(c, d, e, f, buff))
}

/// Paper A §II.I: edge_detect, filtered (the answer of [`crate::detect::edge_detect`]).
#[allow(clippy::too_many_arguments)]
pub fn edge_detect<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    pi: &V2<F>,
    pj: &V2<F>,
    vi: &V2<F>,
    vj: &V2<F>,
    fac: &F,
) -> bool {
    edge_detect_iv(
        enclose(t),
        enclose2(s),
        enclose2(v),
        enclose2(pi),
        enclose2(pj),
        enclose2(vi),
        enclose2(vj),
        enclose(fac),
    )
    .unwrap_or_else(|| crate::detect::edge_detect(t, s, v, pi, pj, vi, vj, fac))
}

// ---------------------------------------------------------------------------
// The ground truth, filtered.

/// Whether the closed segments meet, certified (mirrors truth::segments_intersect).
fn segments_intersect_iv(a: IV2, b: IV2, c: IV2, d: IV2) -> Option<bool> {
    // Disjoint bounding boxes: certainly apart (a consequence of the exact tests).
    let apart = |p: Iv, q: Iv, r: Iv, s: Iv| or2(p.max(q).lt(r.min(s)), r.max(s).lt(p.min(q)));
    if or2(apart(a.x, b.x, c.x, d.x), apart(a.y, b.y, c.y, d.y)) == Some(true) {
        return Some(false);
    }
    let on = |p: IV2, q: IV2, x: IV2| {
        let e = q.minus(p);
        all(&[
            e.cross(x.minus(p)).eq0(),
            x.minus(p).dot(e).neg0().map(|v| !v),
            q.minus(x).dot(e).neg0().map(|v| !v),
        ])
    };
    let o1 = b.minus(a).cross(c.minus(a)).sign();
    let o2 = b.minus(a).cross(d.minus(a)).sign();
    let o3 = d.minus(c).cross(a.minus(c)).sign();
    let o4 = d.minus(c).cross(b.minus(c)).sign();
    let proper = |x: Option<Ordering>, y: Option<Ordering>| match (x, y) {
        (Some(Ordering::Equal), _) | (_, Some(Ordering::Equal)) => Some(false),
        (Some(x), Some(y)) => Some(x != y),
        _ => None,
    };
    any(&[
        and2(proper(o1, o2), proper(o3, o4)),
        on(a, b, c),
        on(a, b, d),
        on(c, d, a),
        on(c, d, b),
    ])
}

/// Whether s lies in the closed polygon, certified (mirrors truth::in_closed_polygon).
fn in_closed_polygon_iv(poly: &[IV2], s: IV2) -> Option<bool> {
    let n = poly.len();
    let mut winding: i64 = 0;
    for i in 0..n {
        let a = poly[i];
        let b = poly[(i + 1) % n];
        let e = b.minus(a);
        let q = s.minus(a);
        let o = e.cross(q);
        let on = all(&[
            o.eq0(),
            q.dot(e).neg0().map(|v| !v),
            b.minus(s).dot(e).neg0().map(|v| !v),
        ])?;
        if on {
            return Some(true);
        }
        if a.y.le(s.y)? {
            if s.y.lt(b.y)? && o.pos()? {
                winding += 1;
            }
        } else if b.y.le(s.y)? && o.neg0()? {
            winding -= 1;
        }
    }
    Some(winding != 0)
}

/// The filtered verdict on one contact test.
#[derive(Clone, Copy, Debug)]
enum Contact {
    /// Certainly no contact in [0, T].
    No,
    /// Certainly the root of index k (in contact_roots' order) is the earliest
    /// contact; it lies in the interval.
    Root(usize, Iv),
    /// Not certified.
    Unknown,
}

/// earliest_contact, certified (mirrors truth::earliest_contact).
fn contact_iv(t: Iv, x0: IV2, xv: IV2, a0: IV2, av: IV2, b0: IV2, bv: IV2) -> Contact {
    // boxes_apart, certified.
    let x1 = x0.at(xv, t);
    let a1 = a0.at(av, t);
    let b1 = b0.at(bv, t);
    let apart = |p: [Iv; 2], e: [Iv; 4]| {
        let plo = p[0].min(p[1]);
        let phi = p[0].max(p[1]);
        let elo = e[0].min(e[1]).min(e[2]).min(e[3]);
        let ehi = e[0].max(e[1]).max(e[2]).max(e[3]);
        or2(phi.lt(elo), ehi.lt(plo))
    };
    if or2(
        apart([x0.x, x1.x], [a0.x, a1.x, b0.x, b1.x]),
        apart([x0.y, x1.y], [a0.y, a1.y, b0.y, b1.y]),
    ) == Some(true)
    {
        return Contact::No;
    }
    let q0 = x0.minus(a0);
    let q1 = xv.minus(av);
    let e0 = b0.minus(a0);
    let e1 = bv.minus(av);
    let g2 = q1.cross(e1);
    let g1 = q0.cross(e1).add(q1.cross(e0));
    let g0 = q0.cross(e0);
    // g keeps one strict sign on [0, T] when its Bernstein coefficients there,
    // g(0), g(0) + g'(0)·T/2 and g(T), share it: no root, no contact (certified).
    let bern = [g0, g0.add(g1.mul(t).half()), quad_iv(g2, g1, g0, t)];
    if bern.iter().all(|b| b.lo > 0.0) || bern.iter().all(|b| b.hi < 0.0) {
        return Contact::No;
    }
    let mut roots = [Iv::ZERO; 2];
    let count = match g2.sign() {
        None => return Contact::Unknown,
        Some(Ordering::Equal) => match g1.sign() {
            None => return Contact::Unknown,
            Some(Ordering::Equal) => {
                // Not identically zero (certified): no root; identically zero
                // (collinear motion) or unknown: the exact code decides.
                return if g0.eq0() == Some(false) {
                    Contact::No
                } else {
                    Contact::Unknown
                };
            }
            Some(_) => {
                roots[0] = g0.neg().div(g1);
                1
            }
        },
        Some(_) => {
            let disc = g1.sq().sub(g2.twice().twice().mul(g0));
            match disc.sign() {
                None => return Contact::Unknown,
                Some(Ordering::Less) => return Contact::No,
                Some(Ordering::Equal) => {
                    roots[0] = g1.neg().div(g2.twice());
                    1
                }
                Some(Ordering::Greater) => {
                    roots = two_roots(g2, g1, disc);
                    2
                }
            }
        }
    };
    let r0 = e0.minus(q0);
    let r1 = e1.minus(q1);
    let h = |w: IV2, v: IV2, r: Iv| {
        let a = v.dot(e1);
        let b = w.dot(e1).add(v.dot(e0));
        let c = w.dot(e0);
        quad_iv(a, b, c, r)
    };
    for (k, &r) in roots.iter().enumerate().take(count) {
        let ok = all(&[
            r.neg0().map(|v| !v),
            r.le(t),
            h(q0, q1, r).neg0().map(|v| !v),
            h(r0, r1, r).neg0().map(|v| !v),
        ]);
        match ok {
            Some(true) => return Contact::Root(k, r),
            Some(false) => {}
            None => return Contact::Unknown,
        }
    }
    Contact::No
}

/// The exact root of index k of the contact quadratic (what earliest_contact
/// returns when the filter certified that root).
#[allow(clippy::too_many_arguments)]
fn exact_root<F: ExactField>(
    k: usize,
    t: &F,
    x0: &V2<F>,
    xv: &V2<F>,
    a0: &V2<F>,
    av: &V2<F>,
    b0: &V2<F>,
    bv: &V2<F>,
) -> Option<Alg<F>> {
    let q0 = x0.minus(a0);
    let q1 = xv.minus(av);
    let e0 = b0.minus(a0);
    let e1 = bv.minus(av);
    let [g2, g1, g0] = contact_coeffs(&q0, &q1, &e0, &e1);
    match contact_roots(&g2, &g1, &g0).into_iter().nth(k) {
        Some(r) => Some(r),
        // Cannot happen (the filter certified the root count); stay exact anyway.
        None => crate::truth::earliest_contact(t, x0, xv, a0, av, b0, bv),
    }
}

/// The earliest contact of a moving point and a moving segment, filtered: the
/// same exact number, in the same representation, as
/// [`crate::truth::earliest_contact`].
pub fn earliest_contact<F: ExactField>(
    t: &F,
    x0: &V2<F>,
    xv: &V2<F>,
    a0: &V2<F>,
    av: &V2<F>,
    b0: &V2<F>,
    bv: &V2<F>,
) -> Option<Alg<F>> {
    let ct = contact_iv(
        enclose(t),
        enclose2(x0),
        enclose2(xv),
        enclose2(a0),
        enclose2(av),
        enclose2(b0),
        enclose2(bv),
    );
    match ct {
        Contact::No => None,
        Contact::Root(k, _) => exact_root(k, t, x0, xv, a0, av, b0, bv),
        Contact::Unknown => crate::truth::earliest_contact(t, x0, xv, a0, av, b0, bv),
    }
}

/// The exact ground truth with the floating filter (the answer of
/// [`crate::truth_unfiltered`]; see the module doc).
pub fn truth<F: ExactField>(c: &ExactCase<F>) -> Truth {
    let Some((t0, t1)) = window(c) else {
        return Truth::Misses;
    };
    let tw = t1.minus(&t0);
    let shifted = !t0.is_zero_();
    // In 2D the window starts at 0: the shifted data are the data themselves.
    let (s_own, poly_own) = if shifted {
        let p: Vec<V2<F>> = c
            .vertices
            .iter()
            .zip(&c.velocities)
            .map(|(p, w)| p.at(w, &t0))
            .collect();
        (Some(c.s.at(&c.v, &t0)), Some(p))
    } else {
        (None, None)
    };
    let s = s_own.as_ref().unwrap_or(&c.s);
    let poly: &[V2<F>] = poly_own.as_deref().unwrap_or(&c.vertices);
    let vels = &c.velocities;
    let n = poly.len();
    if n < 3 || vels.len() != n {
        return bad_lengths();
    }
    let twi = enclose(&tw);
    let vi = enclose2(&c.v);
    let velsi = enclose_all(vels);
    let (si, polyi) = if shifted {
        let t0i = enclose(&t0);
        let si = enclose2(&c.s).at(vi, t0i);
        let pi: Vec<IV2> = c
            .vertices
            .iter()
            .zip(&velsi)
            .map(|(p, &w)| enclose2(p).at(w, t0i))
            .collect();
        (si, pi)
    } else {
        (enclose2(s), enclose_all(poly))
    };
    // Simplicity at the window's start.
    for i in 0..n {
        for k in (i + 2)..n {
            if i == 0 && k == n - 1 {
                continue;
            }
            let (j, l) = ((i + 1) % n, (k + 1) % n);
            let meet = segments_intersect_iv(polyi[i], polyi[j], polyi[k], polyi[l])
                .unwrap_or_else(|| segments_intersect(&poly[i], &poly[j], &poly[k], &poly[l]));
            if meet {
                return crossing_at_start(n, i, k);
            }
        }
    }
    // Simplicity on the window: no vertex ever meets a non-incident edge.
    for i in 0..n {
        let j = (i + 1) % n;
        for k in 0..n {
            if k == i || k == j {
                continue;
            }
            let ct = contact_iv(
                twi, polyi[k], velsi[k], polyi[i], velsi[i], polyi[j], velsi[j],
            );
            if matches!(ct, Contact::No) {
                continue;
            }
            if let Some(tc) = crate::truth::earliest_contact(
                &tw, &poly[k], &vels[k], &poly[i], &vels[i], &poly[j], &vels[j],
            ) {
                return vertex_meets_edge(k, i, j, &tc, &t0);
            }
        }
    }
    let inside = in_closed_polygon_iv(&polyi, si).unwrap_or_else(|| in_closed_polygon(poly, s));
    if inside {
        return Truth::Enters {
            entry_time: ExactTime::rational(t0.to_big()),
        };
    }
    let contacts: Vec<Contact> = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            contact_iv(twi, si, vi, polyi[i], velsi[i], polyi[j], velsi[j])
        })
        .collect();
    // A certified contact certainly later than another certified one cannot be
    // the earliest, nor tie with it.
    let bound = contacts.iter().fold(f64::INFINITY, |m, ct| match ct {
        Contact::Root(_, r) => m.min(r.hi),
        _ => m,
    });
    let mut best: Option<Alg<F>> = None;
    for (i, ct) in contacts.iter().enumerate() {
        let j = (i + 1) % n;
        let tc = match *ct {
            Contact::No => None,
            Contact::Root(_, r) if r.lo > bound => None,
            Contact::Root(k, _) => {
                exact_root(k, &tw, s, &c.v, &poly[i], &vels[i], &poly[j], &vels[j])
            }
            Contact::Unknown => {
                crate::truth::earliest_contact(&tw, s, &c.v, &poly[i], &vels[i], &poly[j], &vels[j])
            }
        };
        if let Some(tc) = tc {
            best = min_alg(best, tc);
        }
    }
    match best {
        Some(tc) => Truth::Enters {
            entry_time: ExactTime::from_alg(&tc.shifted(&t0)),
        },
        None => Truth::Misses,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;

    #[test]
    fn steps_and_sums() {
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(next_up(0.0), f64::from_bits(1));
        assert_eq!(next_down(0.0), -f64::from_bits(1));
        assert_eq!(next_down(f64::INFINITY), f64::MAX);
        // 1 + 2^−60 is not a float: the directed sums bracket it tightly.
        let tiny = 2f64.powi(-60);
        assert_eq!(add_dn(1.0, tiny), 1.0);
        assert_eq!(add_up(1.0, tiny), next_up(1.0));
        assert_eq!(add_dn(0.1, -0.1), 0.0);
        assert_eq!(add_up(0.1, -0.1), 0.0);
    }

    #[test]
    fn enclosures_hold_the_number() {
        let third = Q::from_i64(1)
            .quotient(&Q::from_i64(3))
            .unwrap_or_else(Q::zero);
        let e = enclose(&third);
        assert!(e.lo < e.hi);
        assert!(f64_to_exact::<Q>(e.lo).is_some_and(|x| x < third));
        assert!(f64_to_exact::<Q>(e.hi).is_some_and(|x| x > third));
        let x = f64_to_exact::<Q>(0.1).unwrap_or_else(Q::zero);
        assert_eq!(enclose(&x), Iv::point(0.1));
        // A product of two floats is enclosed, and its sign decided.
        let p = Iv::point(0.1).mul(Iv::point(0.3));
        let exact = x.times(&f64_to_exact::<Q>(0.3).unwrap_or_else(Q::zero));
        assert!(f64_to_exact::<Q>(p.lo).is_some_and(|l| l <= exact));
        assert!(f64_to_exact::<Q>(p.hi).is_some_and(|h| h >= exact));
        assert_eq!(
            Iv::point(3.0).sub(Iv::point(3.0)).sign(),
            Some(Ordering::Equal)
        );
        assert_eq!(Iv { lo: -1.0, hi: 1.0 }.sign(), None);
        assert_eq!(Iv::ENTIRE.mul(Iv::point(0.0)), Iv::ZERO);
        assert_eq!(Iv::ENTIRE.add(Iv::point(1.0)).sign(), None);
    }
}
