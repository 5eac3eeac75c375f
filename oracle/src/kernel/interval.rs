//! The interval kernel: rigorous enclosures on binary floats, in front of the
//! exact kernel as CGAL's filtered kernels do it. [`Intervals`] takes a decision
//! only when the enclosures certify it, and abstains otherwise; the runner
//! (`kernel/run.rs`) then runs that one paper-function call in the exact kernel.
//! Floats never decide anything here: they only prove signs, so every answer is the
//! exact one.
//!
//! It also holds the truth's broad phase (`VertexBox`): outward-rounded boxes whose
//! being apart proves that two exact objects never meet.
//!
//! This is the only module besides [`crate::convert`] that names a float type.
//!
//! Why it is rigorous (enclosures, outward rounding, decisions, roots):
//! docs/derivations.md, "The oracle's interval kernel".

use core::cmp::Ordering;
use std::borrow::Cow;

use num_traits::ToPrimitive;

use super::Kernel;
use crate::algebraic::RealAlg;
use crate::field::{Arith, ExactField, V2};

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

/// The exact value of a finite f64 (`None` for NaN and ±∞): the dyadic rational its
/// bits denote. The interval kernel makes its ends exact with it; [`crate::convert`],
/// which reads the inputs, re-exports it.
pub fn f64_to_exact<F: ExactField>(x: f64) -> Option<F> {
    if !x.is_finite() {
        return None;
    }
    let bits = x.to_bits();
    let neg = (bits >> 63) == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, exp) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), biased - 1075)
    };
    Some(F::from_dyadic(neg, mant, exp))
}

/// A closed interval [lo, hi] of floats enclosing one real number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iv {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
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
        // Halving is exact unless it lands below the normal range and drops a bit.
        let (lo, hi) = (self.lo * 0.5, self.hi * 0.5);
        if lo * 2.0 == self.lo && hi * 2.0 == self.hi {
            Iv::raw(lo, hi)
        } else {
            self.mul(Iv::point(0.5))
        }
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

    /// The certified sign.
    #[inline]
    pub fn sign(self) -> Result<Ordering, Abstain> {
        if self.lo > 0.0 {
            Ok(Ordering::Greater)
        } else if self.hi < 0.0 {
            Ok(Ordering::Less)
        } else if self.is_zero() {
            Ok(Ordering::Equal)
        } else {
            Err(Abstain)
        }
    }

    /// Certified self < o.
    #[inline]
    pub fn lt(self, o: Iv) -> Result<bool, Abstain> {
        if self.hi < o.lo {
            Ok(true)
        } else if self.lo >= o.hi {
            Ok(false)
        } else {
            Err(Abstain)
        }
    }

    /// Certified self ≤ o.
    #[inline]
    pub fn le(self, o: Iv) -> Result<bool, Abstain> {
        if self.hi <= o.lo {
            Ok(true)
        } else if self.lo > o.hi {
            Ok(false)
        } else {
            Err(Abstain)
        }
    }

    /// Certified self = o: two equal points, or two disjoint intervals.
    #[inline]
    pub fn equals(self, o: Iv) -> Result<bool, Abstain> {
        if self.lo == self.hi && o.lo == o.hi {
            Ok(self.lo == o.lo)
        } else if self.hi < o.lo || o.hi < self.lo {
            Ok(false)
        } else {
            Err(Abstain)
        }
    }
}

/// An interval decision that cannot be certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Abstain;

impl Arith for Iv {
    fn zero() -> Self {
        Iv::ZERO
    }
    fn one() -> Self {
        Iv::ONE
    }
    fn from_i64(v: i64) -> Self {
        // Exact below 2^53 in magnitude; otherwise one ulp either way holds v.
        let x = v as f64;
        if x.abs() < 9007199254740992.0 {
            Iv::point(x)
        } else {
            Iv::raw(next_down(x), next_up(x))
        }
    }
    fn plus(&self, o: &Self) -> Self {
        self.add(*o)
    }
    fn minus(&self, o: &Self) -> Self {
        self.sub(*o)
    }
    fn times(&self, o: &Self) -> Self {
        self.mul(*o)
    }
    fn negated(&self) -> Self {
        self.neg()
    }
    fn quotient(&self, o: &Self) -> Option<Self> {
        if o.lo > 0.0 || o.hi < 0.0 {
            Some(self.div(*o))
        } else {
            None
        }
    }
    fn half(&self) -> Self {
        Iv::half(*self)
    }
    fn sq(&self) -> Self {
        Iv::sq(*self)
    }
    fn twice(&self) -> Self {
        Iv::twice(*self)
    }
}

/// The interval kernel (see the [module doc](self)): numbers and roots are [`Iv`]
/// enclosures; a decision the enclosures cannot certify is `Err(Abstain)`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Intervals;

impl Kernel<Iv> for Intervals {
    type Root = Iv;
    type Abstain = Abstain;

    fn lt(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        a.lt(*b)
    }
    fn le(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        a.le(*b)
    }
    fn eq(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        a.equals(*b)
    }
    fn sign(&self, x: &Iv) -> Result<Ordering, Abstain> {
        x.sign()
    }

    fn abs(&self, x: &Iv) -> Iv {
        x.abs()
    }
    fn hull<'a>(&self, xs: &[&'a Iv]) -> (Cow<'a, Iv>, Cow<'a, Iv>) {
        let (mut lo, mut hi) = (*xs[0], *xs[0]);
        for &&x in &xs[1..] {
            lo = lo.min(x);
            hi = hi.max(x);
        }
        (Cow::Owned(lo), Cow::Owned(hi))
    }

    fn root(&self, x: &Iv) -> Iv {
        *x
    }
    fn linear_root(&self, n: Iv, d: Iv) -> Option<Iv> {
        Some(n.div(d))
    }
    fn two_roots(&self, a: &Iv, b: &Iv, disc: Iv) -> Option<[Iv; 2]> {
        let two_a = a.twice();
        let r = disc.sqrt();
        let mb = b.neg();
        // The smaller root takes −√disc when a > 0 (a ≠ 0 has been certified).
        let (lo, hi) = if a.lo > 0.0 {
            (mb.sub(r), mb.add(r))
        } else {
            (mb.add(r), mb.sub(r))
        };
        Some([lo.div(two_a), hi.div(two_a)])
    }
    fn root_max(&self, r: Iv, x: &Iv) -> Iv {
        r.max(*x)
    }
    fn root_min(&self, r: Iv, x: &Iv) -> Iv {
        r.min(*x)
    }
    fn root_lt(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        a.lt(*b)
    }
    fn root_le(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        a.le(*b)
    }
    fn quad_neg_at(&self, r: &Iv, a: &Iv, b: &Iv, c: &Iv) -> Result<bool, Abstain> {
        a.mul(*r).add(*b).mul(*r).add(*c).lt(Iv::ZERO)
    }
}

// Enclosing exact numbers.

/// m · 2^−k for |m| < 2^53 and k ≤ 969: a normal float, computed exactly.
fn dyadic(m: i64, k: u64) -> f64 {
    // |m| < 2^53 converts exactly; 2^−k is a normal float; the product is ≥ 2^−969
    // in magnitude (or 0) and has at most 53 significant bits: exact.
    (m as f64) * f64::from_bits((1023 - k) << 52)
}

/// A rigorous enclosure of an exact number: the point interval when it is a float
/// (recognised structurally by [`ExactField::as_dyadic`]), else the leading bits of
/// its numerator over its power-of-two denominator, or of ⌊n·2^k / d⌋, rounded
/// outward (an ulp or two wide).
pub fn enclose<F: ExactField>(x: &F) -> Iv {
    if let Some((m, k)) = x.as_dyadic() {
        if m.unsigned_abs() < 1 << 53 && k <= 969 {
            return Iv::point(dyadic(m, k));
        }
    }
    let big = x.to_big();
    if let Some(k) = power_of_two(big.denom()) {
        return enclose_scaled_int(big.numer(), -i64::try_from(k).unwrap_or(i64::MAX));
    }
    // n/d = q·2^−k + a remainder below 2^−k, with q = ⌊n·2^k / d⌋ of about 64 bits.
    use num_integer::Integer;
    let (n, d) = (big.numer(), big.denom());
    let k = 64 + i64::try_from(d.bits()).unwrap_or(0) - i64::try_from(n.bits()).unwrap_or(0);
    let (num, den) = if k >= 0 {
        (n << k.unsigned_abs(), d.clone())
    } else {
        (n.clone(), d << k.unsigned_abs())
    };
    let (q, r) = num.div_mod_floor(&den);
    let lo = enclose_scaled_int(&q, -k).lo;
    let hi = if r.bits() == 0 {
        enclose_scaled_int(&q, -k).hi
    } else {
        enclose_scaled_int(&(q + 1u8), -k).hi
    };
    Iv::raw(lo, hi)
}

/// k when the positive integer x is 2^k.
fn power_of_two(x: &num_bigint::BigInt) -> Option<u64> {
    let k = x.trailing_zeros()?;
    (x.bits() == k + 1).then_some(k)
}

/// A rigorous enclosure of m·2^e for an integer m of any size: its leading 60 bits
/// rounded outward (an ulp or two wide), then scaled (outward beyond the normal range).
/// (Enclosing the exact numbers of paper A §II–III.)
pub fn enclose_scaled_int(m: &num_bigint::BigInt, e: i64) -> Iv {
    use num_bigint::Sign;
    let mag = m.magnitude();
    let bits = mag.bits();
    if bits == 0 {
        return Iv::ZERO;
    }
    let (lo, hi, shift) = if bits <= 53 {
        let v = mag.to_u64().map_or(f64::NAN, |v| v as f64);
        (v, v, 0i64)
    } else {
        // 54 … 60 bits fit a u64 whole (s = 0): rounded to f64 below
        let s = bits.saturating_sub(60);
        let h = (mag >> s).to_u64().unwrap_or(u64::MAX);
        let exact = mag.trailing_zeros().is_some_and(|z| z >= s);
        let down = |v: u64| {
            let f = v as f64;
            if f as u64 > v {
                next_down(f)
            } else {
                f
            }
        };
        let up = |v: u64| {
            let f = v as f64;
            if (f as u64) < v {
                next_up(f)
            } else {
                f
            }
        };
        let top = if exact { h } else { h + 1 };
        (down(h), up(top), i64::try_from(s).unwrap_or(i64::MAX))
    };
    let k = e.saturating_add(shift).clamp(-4000, 4000) as i32;
    let r = Iv::raw(lo, hi).scaled_pow2(k);
    if m.sign() == Sign::Minus {
        r.neg()
    } else {
        r
    }
}

/// The enclosure of a vector.
pub fn enclose2<F: ExactField>(p: &V2<F>) -> V2<Iv> {
    V2::new(enclose(&p.x), enclose(&p.y))
}

// ------------------------------------------------ the truth's broad phase

/// An axis-aligned box of floats, [lo₀, hi₀] × [lo₁, hi₁], enclosing where a vertex
/// (or an edge) can be: the broad phase of the truth's simplicity tests (paper A §II's
/// premise that P(t) is simple, checked pair by pair). Boxes only ever rule contacts
/// out: two boxes apart prove that the exact objects never meet, and meeting boxes
/// send the pair to the exact test.
#[derive(Clone, Copy, Debug)]
pub(crate) struct VertexBox {
    lo: [f64; 2],
    hi: [f64; 2],
}

impl VertexBox {
    /// The box of an interval vector.
    fn of(p: &V2<Iv>) -> VertexBox {
        VertexBox {
            lo: [p.x.lo, p.y.lo],
            hi: [p.x.hi, p.y.hi],
        }
    }

    /// The smallest box holding both.
    fn hull(self, o: VertexBox) -> VertexBox {
        VertexBox {
            lo: [self.lo[0].min(o.lo[0]), self.lo[1].min(o.lo[1])],
            hi: [self.hi[0].max(o.hi[0]), self.hi[1].max(o.hi[1])],
        }
    }

    /// Whether the closed boxes share a point. No rounding: the ends are compared as
    /// they are, and an infinite end (an enclosure that certifies nothing) meets
    /// everything on its side.
    fn meets(self, o: VertexBox) -> bool {
        (0..2).all(|k| self.lo[k] <= o.hi[k] && o.lo[k] <= self.hi[k])
    }
}

/// Rigorous boxes of exact vertices p moving with velocities `vels`: where vertex k
/// is at time 0 (`swept` false), or anywhere in [0, T] (`swept` true; each
/// coordinate is linear in t, so the box of the two end positions holds the whole
/// motion). Each end is an outward-rounded enclosure of the exact position, so the
/// exact vertex is in its box; the boxes only ever rule contacts out.
///
/// The motion is taken relative to vertex 0's velocity: whether a vertex meets an
/// edge does not change when one velocity is subtracted from every vertex (both
/// positions shift by the same vector at every time), and without the common
/// translation a polygon's swept boxes stay as small as its warp.
/// (Paper A §II's premise (P(t) simple): the broad phase's boxes.)
pub(crate) fn vertex_boxes<F: ExactField>(
    p: &[V2<F>],
    vels: &[V2<F>],
    t: &F,
    swept: bool,
) -> Vec<VertexBox> {
    let t = enclose(t);
    let common = vels.first().map_or(V2::new(Iv::ZERO, Iv::ZERO), enclose2);
    p.iter()
        .zip(vels.iter())
        .map(|(p, v)| {
            let p0 = enclose2(p);
            let at0 = VertexBox::of(&p0);
            if !swept {
                return at0;
            }
            let v = enclose2(v);
            let (vx, vy) = (v.x.sub(common.x), v.y.sub(common.y));
            let p1 = V2::new(p0.x.add(t.mul(vx)), p0.y.add(t.mul(vy)));
            at0.hull(VertexBox::of(&p1))
        })
        .collect()
}

/// The boxes of the edges (edge i from vertex i to i + 1) from their ends' boxes.
/// (Paper A §II's premise (P(t) simple): the broad phase's boxes.)
pub(crate) fn edge_boxes(vertex: &[VertexBox]) -> Vec<VertexBox> {
    let n = vertex.len();
    (0..n)
        .map(|i| vertex[i].hull(vertex[(i + 1) % n]))
        .collect()
}

/// Every pair (i, m) with a[i] meeting b[m], in increasing order: a sort and sweep
/// along the first axis, O((|a| + |b|) log + the pairs overlapping on that axis),
/// in place of the |a|·|b| pairs (256² for the generators' largest outlines).
/// (Paper A §II's premise (P(t) simple): the broad phase's pairs.)
pub(crate) fn meeting_pairs(a: &[VertexBox], b: &[VertexBox]) -> Vec<(usize, usize)> {
    // Events: every box by its low end on axis 0, the a's first on ties (either order
    // finds the pair; this one is deterministic).
    let mut order: Vec<(bool, usize)> = (0..a.len())
        .map(|i| (false, i))
        .chain((0..b.len()).map(|m| (true, m)))
        .collect();
    let of = |(in_b, i): (bool, usize)| if in_b { b[i] } else { a[i] };
    order.sort_by(|&x, &y| {
        of(x).lo[0]
            .total_cmp(&of(y).lo[0])
            .then(x.0.cmp(&y.0))
            .then(x.1.cmp(&y.1))
    });
    let (mut open_a, mut open_b): (Vec<usize>, Vec<usize>) = (Vec::new(), Vec::new());
    let mut pairs = Vec::new();
    for (in_b, i) in order {
        let bx = of((in_b, i));
        // Boxes of the other set that end before this one starts meet nothing from here
        // on (every later box starts at or after this one).
        let (mine, other, other_boxes) = if in_b {
            (&mut open_b, &mut open_a, a)
        } else {
            (&mut open_a, &mut open_b, b)
        };
        other.retain(|&j| other_boxes[j].hi[0] >= bx.lo[0]);
        for &j in other.iter() {
            if bx.meets(other_boxes[j]) {
                pairs.push(if in_b { (j, i) } else { (i, j) });
            }
        }
        mine.push(i);
    }
    pairs.sort_unstable();
    pairs
}

/// Rigorous boxes of exact points (a point box when the number is a float): §II.J's
/// rules 1 and 2 ask about the polygon at one time, so its vertices do not move.
/// (Paper A §II.J: the broad phase of its pairwise rules.)
pub(crate) fn point_boxes<F: ExactField>(p: &[V2<F>]) -> Vec<VertexBox> {
    p.iter().map(|v| VertexBox::of(&enclose2(v))).collect()
}

/// Calls `visit(i, j)`, `i < j`, once for every pair of boxes that come within `reach`
/// of each other on both axes (in no particular order): a sort along the axis where the boxes spread the
/// most and a forward scan while the next box starts within reach, O(n log n + the
/// pairs met on the way) in place of n²/2 (what makes §II.J's rules 1 and 2 of a
/// 16k-vertex polygon cost milliseconds instead of minutes; it extends paper A §II.J,
/// which compares every pair).
///
/// **No pair within reach is left out.** Each box grows on its high side by
/// r ≥ |reach| (|reach| enclosed, r its upper end) rounded upward, and the grown boxes
/// are compared exactly as floats. A pair left out thus has, on one axis, a box
/// starting above the other's grown end: the exact gap there exceeds r ≥ |reach|, and
/// so does the gap between any two points of the boxes, in particular the exact
/// objects they hold.
pub(crate) fn near_pairs<F: ExactField>(
    boxes: &[VertexBox],
    reach: &F,
    mut visit: impl FnMut(usize, usize),
) {
    let r = enclose(reach).abs().hi;
    let grown: Vec<VertexBox> = boxes
        .iter()
        .map(|b| VertexBox {
            lo: b.lo,
            hi: [add_up(b.hi[0], r), add_up(b.hi[1], r)],
        })
        .collect();
    // The axis of the larger spread (a needle along y would make an x sweep quadratic).
    let spread = |k: usize| {
        let lo = boxes.iter().map(|b| b.lo[k]).fold(f64::INFINITY, f64::min);
        let hi = boxes
            .iter()
            .map(|b| b.hi[k])
            .fold(f64::NEG_INFINITY, f64::max);
        hi - lo
    };
    let ax = if spread(0) >= spread(1) { 0 } else { 1 };
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_unstable_by(|&i, &j| grown[i].lo[ax].total_cmp(&grown[j].lo[ax]).then(i.cmp(&j)));
    for (k, &i) in order.iter().enumerate() {
        let a = grown[i];
        for &j in &order[k + 1..] {
            let b = grown[j];
            // Every later box starts at or after this one: none of them is in reach.
            if b.lo[ax] > a.hi[ax] {
                break;
            }
            if a.meets(b) {
                visit(i.min(j), i.max(j));
            }
        }
    }
}

// ------------------------------------------- polynomials and their real roots

/// Small float helpers the exact layers need without naming a float type: points,
/// scaling by powers of two, a float between two enclosures.
impl Iv {
    /// Whether the enclosure is one float (the exact number is that float).
    #[inline]
    pub fn is_point(self) -> bool {
        self.lo == self.hi
    }

    /// Whether both ends are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.finite()
    }

    /// The exact value of the lower end (`None` when it is infinite).
    pub fn lo_exact<F: ExactField>(self) -> Option<F> {
        f64_to_exact(self.lo)
    }

    /// The exact value of the upper end (`None` when it is infinite).
    pub fn hi_exact<F: ExactField>(self) -> Option<F> {
        f64_to_exact(self.hi)
    }

    /// self · 2^k, exactly when the ends stay normal floats, else outward rounded.
    pub fn scaled_pow2(self, k: i32) -> Iv {
        let k = k.clamp(-2000, 2000);
        let (mut lo, mut hi) = (self.lo, self.hi);
        // In steps whose factor is a normal float; each step exact unless the result
        // leaves the normal range, when it is widened by an ulp.
        let mut left = k;
        while left != 0 {
            let step = left.clamp(-1000, 1000);
            let f = f64::from_bits(((1023 + step) as u64) << 52);
            let exact = |x: f64| {
                let y = x * f;
                y == 0.0 && x == 0.0 || (y.is_finite() && y.abs() >= f64::MIN_POSITIVE)
            };
            lo = if exact(lo) { lo * f } else { mul_dn(lo, f) };
            hi = if exact(hi) { hi * f } else { mul_up(hi, f) };
            left -= step;
        }
        Iv::raw(lo, hi)
    }

    /// A float strictly above `a` and strictly below `b`, as a point, near their
    /// midpoint; `None` when there is none (the enclosures meet or touch).
    pub fn point_between(a: Iv, b: Iv) -> Option<Iv> {
        let (x, y) = (a.hi, b.lo);
        // NaN never occurs in an Iv; infinite ends have no float beyond them.
        if x >= y || !x.is_finite() || !y.is_finite() {
            return None;
        }
        let m = x / 2.0 + y / 2.0;
        let m = if m > x && m < y { m } else { next_up(x) };
        (m > x && m < y).then(|| Iv::point(m))
    }

    /// The hull of two enclosures.
    #[inline]
    pub fn hull(self, o: Iv) -> Iv {
        Iv::raw(self.lo.min(o.lo), self.hi.max(o.hi))
    }
}

/// The binary exponent e of an enclosure's magnitude, 2^(e−1) ≤ max|x| < 2^e
/// (`None` for 0 or when an end is infinite): how the oracle scales a case into the
/// float range without ever forming a product that could overflow.
/// (Scaling a case of paper A §II–III into the float range.)
pub fn magnitude_exponent(x: Iv) -> Option<i32> {
    if !x.finite() {
        return None;
    }
    let m = x.lo.abs().max(x.hi.abs());
    if m == 0.0 {
        return None;
    }
    // A normal float's exponent field; the subnormals are first brought up by 2^64.
    let (m, extra) = if m < f64::MIN_POSITIVE {
        (m * 18446744073709551616.0, 64)
    } else {
        (m, 0)
    };
    Some(((m.to_bits() >> 52) & 0x7ff) as i32 - 1022 - extra)
}

/// Σ c_k·t^k by Horner's rule, enclosed (c lowest degree first).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
pub fn poly_eval(c: &[Iv], t: Iv) -> Iv {
    c.iter().rev().fold(Iv::ZERO, |acc, &x| acc.mul(t).add(x))
}

/// Enclosures of an integer polynomial's coefficients, all divided by one power of two
/// (a positive factor: the same roots and signs) so that the largest is about 2^900
/// at most.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
pub fn enclose_poly(p: &crate::algebraic::Poly) -> Vec<Iv> {
    let bits = p.coeffs().iter().map(|c| c.bits()).max().unwrap_or(0);
    let shift = i64::try_from(bits.saturating_sub(900)).unwrap_or(i64::MAX);
    p.coeffs()
        .iter()
        .map(|c| enclose_scaled_int(c, -shift))
        .collect()
}

/// One stretch of a window after [`isolate_roots`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RootPiece {
    /// Exactly one root, a simple one, strictly between `at.lo` and `at.hi`: the
    /// polynomial's signs there are certified, nonzero and opposite; `rising` when it
    /// is negative at `at.lo`.
    Root {
        /// The isolating interval (float ends, lo < hi).
        at: Iv,
        /// Negative at at.lo, positive at at.hi.
        rising: bool,
    },
    /// A stretch where floats cannot tell how many roots there are (a multiple root,
    /// roots closer than the enclosures, or no certified sign): exact arithmetic must.
    Unsure(Iv),
}

/// The most Bernstein subdivisions one isolation spends before it leaves the rest to
/// exact arithmetic.
const SPLIT_BUDGET: usize = 64;

/// The deepest a Bernstein subdivision goes (a piece 2⁻⁴⁰ of the window).
const MAX_DEPTH: u32 = 40;

/// The real roots of a polynomial in a window, isolated in floats: `p` (lowest degree
/// first) encloses the coefficients of a positive multiple of an exact polynomial;
/// every root of it in `window` lies in exactly one returned piece, and none lies in
/// the window outside them (a piece may reach a little beyond the window). Sorted.
/// A polynomial that may be identically 0 gives one `Unsure` window.
///
/// Degree 1 and 2 (leading coefficient certified nonzero) by the closed forms, the
/// others by subdivision in the Bernstein basis on the window: Bernstein coefficients
/// of one strict sign exclude a root, exactly one sign change isolates one (Descartes'
/// rule for the Bernstein basis). Root brackets are then narrowed to a few ulps.
/// (The roots of paper A §II.C's and §II.I's edge polynomials, certified in floats.)
pub fn isolate_roots(p: &[Iv], window: Iv) -> Vec<RootPiece> {
    let mut n = p.len();
    while n > 0 && p[n - 1].is_zero() {
        n -= 1;
    }
    let p = &p[..n];
    if !window.finite() || window.lo > window.hi || p.iter().any(|c| !c.finite()) {
        return vec![RootPiece::Unsure(window)];
    }
    let certain_sign = |x: Iv| matches!(x.sign(), Ok(Ordering::Less | Ordering::Greater));
    if n == 0 {
        return vec![RootPiece::Unsure(window)];
    }
    if window.lo == window.hi {
        return if certain_sign(poly_eval(p, window)) {
            Vec::new()
        } else {
            vec![RootPiece::Unsure(window)]
        };
    }
    let pieces = match n {
        1 if certain_sign(p[0]) => Vec::new(),
        2 if certain_sign(p[1]) => {
            let r = p[0].neg().div(p[1]);
            vec![bracket_or_unsure(p, r)]
        }
        3 if certain_sign(p[2]) => quadratic_pieces(p),
        _ => bernstein_pieces(p, window),
    };
    pieces
        .into_iter()
        .filter(|piece| {
            let at = match *piece {
                RootPiece::Root { at, .. } | RootPiece::Unsure(at) => at,
            };
            at.hi >= window.lo && at.lo <= window.hi
        })
        .map(|piece| match piece {
            RootPiece::Root { at, rising } => RootPiece::Root {
                at: tighten(p, at, rising),
                rising,
            },
            other => other,
        })
        .collect()
}

/// The certified sign of p at the float x (`None` when not certified nonzero).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn sign_at(p: &[Iv], x: f64) -> Option<Ordering> {
    match poly_eval(p, Iv::point(x)).sign() {
        Ok(Ordering::Equal) | Err(_) => None,
        Ok(s) => Some(s),
    }
}

/// A root piece for a root known to lie in the enclosure r, of a polynomial of degree
/// ≤ 2: r widened until the signs at its ends are certified opposite (then it holds
/// exactly one root: a second one would make the signs agree), doubling the widening
/// from an ulp; `Unsure` when that does not happen.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn bracket_or_unsure(p: &[Iv], r: Iv) -> RootPiece {
    if !r.finite() {
        return RootPiece::Unsure(r);
    }
    let scale = r.lo.abs().max(r.hi.abs());
    let mut delta = (scale * f64::EPSILON).max(f64::MIN_POSITIVE);
    for _ in 0..48 {
        let (l, h) = (next_down(r.lo - delta), next_up(r.hi + delta));
        match (sign_at(p, l), sign_at(p, h)) {
            (Some(sl), Some(sh)) if sl != sh => {
                return RootPiece::Root {
                    at: Iv::raw(l, h),
                    rising: sl == Ordering::Less,
                }
            }
            // Certified equal signs: the enclosure was right, so both roots are in it.
            (Some(_), Some(_)) => break,
            _ => delta *= 2.0,
        }
    }
    RootPiece::Unsure(r)
}

/// The pieces of a quadratic c + b·t + a·t² with a certified nonzero: no real root
/// (discriminant certified negative), two enclosed roots (certified positive, by the
/// cancellation-free formulas q = −(b ± √disc)/2, roots q/a and c/q), or one stretch
/// that holds every real root when the discriminant may be 0.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn quadratic_pieces(p: &[Iv]) -> Vec<RootPiece> {
    let (c, b, a) = (p[0], p[1], p[2]);
    let disc = b.sq().sub(Iv::from_i64(4).mul(a).mul(c));
    if disc.hi < 0.0 {
        return Vec::new();
    }
    let two_a = a.twice();
    if disc.lo <= 0.0 {
        // Every real root is −b/(2a) ± √disc/(2|a|) with disc ∈ [0, disc.hi].
        let centre = b.neg().div(two_a);
        let radius = Iv::point(disc.hi).sqrt().div(two_a.abs());
        let lo = centre.sub(radius).lo;
        let hi = centre.add(radius).hi;
        return vec![RootPiece::Unsure(Iv::raw(lo, hi))];
    }
    let sq = disc.sqrt();
    let (r1, r2) = if b.lo >= 0.0 {
        let q = b.add(sq).half().neg();
        (q.div(a), c.div(q))
    } else if b.hi <= 0.0 {
        let q = sq.sub(b).half();
        (q.div(a), c.div(q))
    } else {
        (b.neg().sub(sq).div(two_a), b.neg().add(sq).div(two_a))
    };
    let (r1, r2) = if r1.lo <= r2.lo { (r1, r2) } else { (r2, r1) };
    if r1.hi >= r2.lo {
        return vec![RootPiece::Unsure(r1.hull(r2))];
    }
    vec![bracket_or_unsure(p, r1), bracket_or_unsure(p, r2)]
}

/// The Bernstein coefficients on [l, h] of the polynomial p (enclosed): those of
/// p(l + (h − l)·u) on u ∈ [0, 1] (a Taylor shift, a scaling, the basis change
/// b_i = Σ_{j ≤ i} C(i, j)/C(n, j) · q_j).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn bernstein(p: &[Iv], l: f64, h: f64) -> Vec<Iv> {
    let n = p.len() - 1;
    let mut q = p.to_vec();
    let li = Iv::point(l);
    for i in 0..n {
        for j in (i..n).rev() {
            q[j] = q[j].add(li.mul(q[j + 1]));
        }
    }
    let w = Iv::point(h).sub(li);
    let mut wp = Iv::ONE;
    for x in q.iter_mut().skip(1) {
        wp = wp.mul(w);
        *x = x.mul(wp);
    }
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    };
    (0..=n)
        .map(|i| {
            (0..=i).fold(Iv::ZERO, |acc, j| {
                let f = Iv::point(binom(i, j)).div(Iv::point(binom(n, j)));
                acc.add(f.mul(q[j]))
            })
        })
        .collect()
}

/// The Bernstein coefficients of the two halves [l, m] and [m, h] of a piece from its
/// own, by de Casteljau's scheme at u = (m − l)/(h − l) (enclosed; the exact 1/2 when
/// m is the exact midpoint, then every step is a sum and a halving).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn de_casteljau(b: &[Iv], u: Iv) -> (Vec<Iv>, Vec<Iv>) {
    let n = b.len() - 1;
    let half = u.lo == 0.5 && u.hi == 0.5;
    let v = Iv::ONE.sub(u);
    let mut work = b.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = Vec::with_capacity(n + 1);
    left.push(work[0]);
    right.push(work[n]);
    for r in 1..=n {
        for i in 0..=n - r {
            work[i] = if half {
                work[i].add(work[i + 1]).half()
            } else {
                work[i].mul(v).add(work[i + 1].mul(u))
            };
        }
        left.push(work[0]);
        right.push(work[n - r]);
    }
    right.reverse();
    (left, right)
}

/// What the Bernstein coefficients of a piece say about the roots in it.
enum Verdict {
    /// None: the coefficients have one strict sign.
    NoRoot,
    /// Exactly one, simple: one sign change, the ends' signs certified and nonzero
    /// (Descartes' rule for the Bernstein basis); `true` when the polynomial rises.
    OneRoot(bool),
    /// Nothing certain.
    Unknown,
}

/// The verdict of a piece's Bernstein coefficients (see [`Verdict`]).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn verdict(b: &[Iv]) -> Verdict {
    let mut last = Ordering::Equal;
    let mut first = Ordering::Equal;
    let mut changes = 0;
    for x in b {
        match x.sign() {
            Err(_) => return Verdict::Unknown,
            Ok(Ordering::Equal) => continue,
            Ok(s) => {
                if first == Ordering::Equal {
                    first = s;
                } else if s != last {
                    changes += 1;
                }
                last = s;
            }
        }
    }
    let ends = |x: Option<&Iv>| {
        matches!(
            x.map(|x| x.sign()),
            Some(Ok(Ordering::Less | Ordering::Greater))
        )
    };
    if !(ends(b.first()) && ends(b.last())) {
        return Verdict::Unknown;
    }
    match changes {
        0 => Verdict::NoRoot,
        1 => Verdict::OneRoot(first == Ordering::Less),
        _ => Verdict::Unknown,
    }
}

/// Subdivision in the Bernstein basis (see [`isolate_roots`]): pieces of the window
/// with one strict sign are dropped, pieces with exactly one sign change are roots,
/// the rest are halved (de Casteljau) until the budget or the depth runs out.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn bernstein_pieces(p: &[Iv], window: Iv) -> Vec<RootPiece> {
    let mut out = Vec::new();
    let mut stack = vec![(
        window.lo,
        window.hi,
        0u32,
        bernstein(p, window.lo, window.hi),
    )];
    let mut splits = 0usize;
    while let Some((l, h, depth, b)) = stack.pop() {
        match verdict(&b) {
            Verdict::NoRoot => continue,
            Verdict::OneRoot(rising) => {
                out.push(RootPiece::Root {
                    at: Iv::raw(l, h),
                    rising,
                });
                continue;
            }
            Verdict::Unknown => {}
        }
        match Iv::point_between(Iv::point(l), Iv::point(h)) {
            Some(m) if depth < MAX_DEPTH && splits < SPLIT_BUDGET => {
                splits += 1;
                let m = m.lo;
                // u = (m − l)/(h − l), exactly 1/2 when m is the exact midpoint.
                let u = if m - l == h - m {
                    Iv::point(0.5)
                } else {
                    Iv::point(m)
                        .sub(Iv::point(l))
                        .div(Iv::point(h).sub(Iv::point(l)))
                };
                let (bl, br) = de_casteljau(&b, u);
                // Right half first onto the stack, so that the left one comes out first.
                stack.push((m, h, depth + 1, br));
                stack.push((l, m, depth + 1, bl));
            }
            _ => out.push(RootPiece::Unsure(Iv::raw(l, h))),
        }
    }
    // Adjacent unsure pieces are one stretch.
    let mut merged: Vec<RootPiece> = Vec::with_capacity(out.len());
    for piece in out {
        if let (Some(RootPiece::Unsure(last)), RootPiece::Unsure(x)) = (merged.last_mut(), piece) {
            if last.hi >= x.lo {
                *last = last.hull(x);
                continue;
            }
        }
        merged.push(piece);
    }
    merged
}

/// The midpoints of the coefficients' enclosures: the plain polynomial whose root a
/// float search approximates (only ever a guess; certification is by enclosures).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn midpoints(p: &[Iv]) -> Vec<f64> {
    p.iter().map(|c| c.lo / 2.0 + c.hi / 2.0).collect()
}

/// An approximate root in (l, h) of the plain polynomial c that is negative at l when
/// `rising` (positive otherwise): Newton's method kept inside a shrinking bracket,
/// bisecting when a step leaves it.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn approx_root(c: &[f64], l: f64, h: f64, rising: bool) -> f64 {
    let eval = |t: f64| {
        c.iter()
            .rev()
            .fold((0.0, 0.0), |(v, d), &x| (v * t + x, d * t + v))
    };
    let (mut a, mut b) = (l, h);
    let mut x = a / 2.0 + b / 2.0;
    for _ in 0..100 {
        let (v, d) = eval(x);
        if v == 0.0 || !v.is_finite() {
            return x;
        }
        if (v < 0.0) == rising {
            a = x;
        } else {
            b = x;
        }
        let mid = a / 2.0 + b / 2.0;
        if !(mid > a && mid < b) {
            break;
        }
        let step = x - v / d;
        if step == x {
            return x;
        }
        x = if step > a && step < b { step } else { mid };
    }
    x
}

/// A bracket [g − δ, g + δ] inside (l, h), with certified opposite signs, around the
/// float guess g: δ from an ulp of g up, fourfold each try. `None` when none
/// certifies.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn certify_near(p: &[Iv], g: f64, l: f64, h: f64, rising: bool) -> Option<Iv> {
    let want_lo = if rising {
        Ordering::Less
    } else {
        Ordering::Greater
    };
    // The first width: the evaluation's own uncertainty at g over the slope there
    // (below it no sign can be certified), at least an ulp of g.
    let noise = poly_eval(p, Iv::point(g));
    let c = midpoints(p);
    let slope = c
        .iter()
        .enumerate()
        .skip(1)
        .rev()
        .fold(0.0, |acc, (k, &x)| acc * g + k as f64 * x)
        .abs();
    let ulp = (g.abs() * f64::EPSILON).max(f64::MIN_POSITIVE);
    let guess = (noise.hi - noise.lo) / slope;
    let mut delta = if guess.is_finite() && guess > ulp {
        guess
    } else {
        ulp
    };
    for _ in 0..14 {
        let (a, b) = (g - delta, g + delta);
        if a > l && b < h && a < b {
            if let (Some(sa), Some(sb)) = (sign_at(p, a), sign_at(p, b)) {
                if sa == want_lo && sb == want_lo.reverse() {
                    return Some(Iv::raw(a, b));
                }
            }
        }
        delta *= 4.0;
    }
    None
}

/// A root bracket narrowed to a few ulps where the enclosures allow it (else as it
/// was): the signs at its new ends are certified, so it still isolates the root.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn tighten(p: &[Iv], at: Iv, rising: bool) -> Iv {
    let scale = at.lo.abs().max(at.hi.abs());
    if at.hi - at.lo <= scale * (64.0 * f64::EPSILON) {
        return at;
    }
    let g = approx_root(&midpoints(p), at.lo, at.hi, rising);
    certify_near(p, g, at.lo, at.hi, rising).unwrap_or(at)
}

/// Whether an enclosure is at most four ulps wide.
/// (Paper A §II.C/§II.I's roots, certified in floats.)
fn is_tight(x: Iv) -> bool {
    if !x.finite() {
        return false;
    }
    let mut e = x.lo;
    for _ in 0..4 {
        e = next_up(e);
    }
    x.hi <= e
}

/// A rigorous enclosure of a real algebraic number, as tight as a few float steps
/// make it; the number's isolating interval is narrowed to the certified float
/// bracket on the way (so later exact work starts from it). A rational is enclosed
/// directly. (The float side of paper A §II.C/§II.I's exact roots.)
pub fn tighten_alg(x: &mut RealAlg) -> Iv {
    if let Some(q) = x.as_rational() {
        return enclose(q);
    }
    let (lo, hi) = x.bounds();
    let (elo, ehi) = (enclose(lo), enclose(hi));
    let outer = Iv::raw(elo.lo, ehi.hi);
    if is_tight(outer) {
        return outer;
    }
    let rising = x.lo_sign() == Some(Ordering::Less);
    let c = enclose_poly(&x.poly());
    // Floats inside [lo, hi]: between them the root can be bracketed in floats.
    let (a, b) = (elo.hi, ehi.lo);
    if a < b && c.iter().all(|v| v.finite()) {
        let g = approx_root(&midpoints(&c), a, b, rising);
        if let Some(br) = certify_near(&c, g, a, b, rising) {
            if let (Some(l), Some(h)) = (br.lo_exact(), br.hi_exact()) {
                x.narrow_to(l, h);
                return br;
            }
        }
    }
    // Floats again with the origin of time moved to lo exactly.
    if narrow_alg(x) {
        let (lo, hi) = x.bounds();
        return Iv::raw(enclose(lo).lo, enclose(hi).hi);
    }
    // Exact bisection: as many halvings as bring the width to a few ulps of the
    // number (at most 200), the enclosure taken once at the end.
    let width = outer.hi - outer.lo;
    let target = (outer.lo.abs().max(outer.hi.abs()) * (4.0 * f64::EPSILON)).max(f64::MIN_POSITIVE);
    let steps = if width.is_finite() && width > target {
        ((width / target).log2().ceil() as usize).min(200)
    } else {
        64
    };
    for _ in 0..steps {
        x.refine();
        if let Some(q) = x.as_rational() {
            return enclose(q);
        }
    }
    let (lo, hi) = x.bounds();
    Iv::raw(enclose(lo).lo, enclose(hi).hi)
}

/// Narrow a real algebraic number's isolating interval (lo, hi) in floats relative to
/// its own width, far below the float resolution at the number: the polynomial is
/// moved to the origin s = t − lo exactly (its coefficients exact, so nothing cancels
/// between large terms) and the root bracketed in s with certified signs. Whether it
/// narrowed (a rational, or floats that cannot certify, leave it as it was).
/// (Paper A §II.C/§II.I's roots, told apart where they nearly coincide.)
pub fn narrow_alg(x: &mut RealAlg) -> bool {
    let Some(sign) = x.lo_sign() else {
        return false;
    };
    let rising = sign == Ordering::Less;
    let (lo, hi) = {
        let (l, h) = x.bounds();
        (l.clone(), h.clone())
    };
    let c = enclose_poly(&x.poly().shifted(&lo));
    let b = enclose(&(&hi - &lo)).lo;
    if !(b > 0.0 && c.iter().all(|v| v.finite())) {
        return false;
    }
    let g = approx_root(&midpoints(&c), 0.0, b, rising);
    let Some(br) = certify_near(&c, g, 0.0, b, rising) else {
        return false;
    };
    let (Some(l), Some(h)) = (
        br.lo_exact::<num_rational::BigRational>(),
        br.hi_exact::<num_rational::BigRational>(),
    ) else {
        return false;
    };
    x.narrow_to(&lo + l, &lo + h);
    true
}

/// A rigorous enclosure of a real algebraic number ([`tighten_alg`] on a copy).
/// (Paper A §II.C/§II.I's roots, certified in floats.)
pub fn enclose_alg(x: &RealAlg) -> Iv {
    tighten_alg(&mut x.clone())
}

impl RealAlg {
    /// Floats lo ≤ x ≤ hi, rounded outward (rigorous), a few ulps apart where the float
    /// range allows (±∞ beyond it).
    /// (Paper A §II.C/§II.I's roots, certified in floats.)
    pub fn to_f64_bounds(&self) -> (f64, f64) {
        let e = enclose_alg(self);
        (e.lo, e.hi)
    }
}

#[cfg(test)]
mod broad_phase_tests {
    use super::*;
    use crate::field::Q;
    use proptest::prelude::*;

    fn fbox() -> impl Strategy<Value = VertexBox> {
        // Small integer grids make touching and shared ends common; an infinite end
        // stands for an enclosure that certifies nothing.
        let end = prop_oneof![8 => (-6i32..6).prop_map(f64::from), 1 => Just(f64::INFINITY)];
        (end.clone(), end.clone(), 0i32..5, 0i32..5).prop_map(|(x, y, w, h)| VertexBox {
            lo: [-x, -y],
            hi: [
                if x.is_finite() { -x + f64::from(w) } else { x },
                -y + f64::from(h),
            ],
        })
    }

    proptest! {
        // §II broad phase: the sweep finds exactly the pairs the |a|·|b| test finds.
        #[test]
        fn the_sweep_finds_every_meeting_pair(
            a in proptest::collection::vec(fbox(), 0..12),
            b in proptest::collection::vec(fbox(), 0..12),
        ) {
            let mut brute = Vec::new();
            for (i, x) in a.iter().enumerate() {
                for (m, y) in b.iter().enumerate() {
                    if x.meets(*y) {
                        brute.push((i, m));
                    }
                }
            }
            prop_assert_eq!(meeting_pairs(&a, &b), brute);
        }

        // The swept boxes hold the exact vertex, in the frame of vertex 0, at every
        // sampled time of [0, T].
        #[test]
        fn swept_boxes_hold_the_exact_motion(
            p in proptest::collection::vec((-1e9f64..1e9, -1e9f64..1e9, -1e3f64..1e3, -1e3f64..1e3), 3..6),
            t in 1e-6f64..1e9,
            k in 0u32..=16,
        ) {
            let q = |x: f64| f64_to_exact::<Q>(x);
            let q_ = |x: f64| q(x).expect("finite");
            let pos: Vec<V2<Q>> = p.iter().map(|&(x, y, _, _)| V2::new(q_(x), q_(y))).collect();
            let vel: Vec<V2<Q>> = p.iter().map(|&(_, _, u, v)| V2::new(q_(u), q_(v))).collect();
            let tq = q_(t);
            let at = tq.times(&<Q as Arith>::from_i64(i64::from(k))).quotient(&<Q as Arith>::from_i64(16)).expect("16 ≠ 0");
            for (b, (p0, v)) in vertex_boxes(&pos, &vel, &tq, true).iter().zip(pos.iter().zip(vel.iter())) {
                // In the frame that moves with vertex 0.
                let x = p0.at(&v.minus(&vel[0]), &at);
                for (c, axis) in [(&x.x, 0), (&x.y, 1)] {
                    // Exact comparisons with the box's ends (an infinite end holds all).
                    let above = |end: f64| q(end).is_none_or(|e| c.minus(&e).sign() != Ordering::Less);
                    let below = |end: f64| q(end).is_none_or(|e| c.minus(&e).sign() != Ordering::Greater);
                    prop_assert!(above(b.lo[axis]) && below(b.hi[axis]), "{:?} outside {:?}", x, b);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;

    /// Integers of 54 to 60 bits (more than an f64 holds, fewer than the 60 leading bits
    /// kept) are enclosed, not an overflow: found by the paper-A end-to-end tests.
    #[test]
    fn integers_of_54_to_60_bits_are_enclosed() {
        for bits in 54..=64u32 {
            for m in [(1u128 << (bits - 1)) + 1, (1u128 << bits) - 1] {
                let big = num_bigint::BigInt::from(m);
                for e in [-3i64, 0, 5] {
                    let iv = enclose_scaled_int(&big, e);
                    let exact = m as f64 * 2f64.powi(e as i32);
                    // the f64 nearest m·2^e is within an ulp of the true value, which the
                    // enclosure holds: so the enclosure meets [exact − ulp, exact + ulp]
                    let ulp = exact * f64::EPSILON;
                    assert!(
                        iv.lo <= exact + ulp && exact - ulp <= iv.hi,
                        "{bits} bits, e {e}: {iv:?}"
                    );
                    assert!(iv.hi - iv.lo <= 4.0 * ulp, "{bits} bits: {iv:?} too wide");
                    let neg = enclose_scaled_int(&(-&big), e);
                    assert_eq!((neg.lo, neg.hi), (-iv.hi, -iv.lo));
                }
            }
        }
    }

    #[test]
    fn decisions_abstain_on_overlap() {
        let k = Intervals;
        let (a, b) = (Iv { lo: 1.0, hi: 2.0 }, Iv { lo: 2.0, hi: 2.0 });
        assert_eq!(k.le(&a, &b), Ok(true));
        assert_eq!(k.lt(&a, &b), Err(Abstain));
        assert_eq!(k.lt(&b, &a), Ok(false));
        assert_eq!(k.eq(&Iv::point(2.0), &b), Ok(true));
        assert_eq!(k.eq(&a, &Iv::point(3.0)), Ok(false));
        assert_eq!(k.eq(&a, &b), Err(Abstain));
        assert_eq!(k.is_pos(&Iv { lo: 0.0, hi: 1.0 }), Err(Abstain));
        assert_eq!(k.is_neg(&Iv { lo: 0.0, hi: 1.0 }), Ok(false));
    }

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
            Ok(Ordering::Equal)
        );
        assert_eq!(Iv { lo: -1.0, hi: 1.0 }.sign(), Err(Abstain));
        assert_eq!(Iv::ENTIRE.mul(Iv::point(0.0)), Iv::ZERO);
        assert_eq!(Iv::ENTIRE.add(Iv::point(1.0)).sign(), Err(Abstain));
        // Integers beyond 2^53 are enclosed, not rounded.
        let big = (1i64 << 60) + 1;
        let e = Iv::from_i64(big);
        assert!(f64_to_exact::<Q>(e.lo).is_some_and(|l| l <= Q::from_i64(big)));
        assert!(f64_to_exact::<Q>(e.hi).is_some_and(|h| h >= Q::from_i64(big)));
    }
}
