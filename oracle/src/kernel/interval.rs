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
use crate::convert::f64_to_exact;
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

/// A rigorous enclosure of an exact number: the point interval when it is a float
/// (recognised structurally by [`ExactField::as_dyadic`]), else end points near it
/// verified by exact comparison.
pub fn enclose<F: ExactField>(x: &F) -> Iv {
    if let Some((m, k)) = x.as_dyadic() {
        if m.unsigned_abs() < 1 << 53 && k <= 969 {
            return Iv::point(dyadic(m, k));
        }
    }
    let near = x.to_big().to_f64().unwrap_or(f64::NAN);
    if !near.is_finite() {
        return Iv::ENTIRE;
    }
    Iv::raw(checked_end(x, near, false), checked_end(x, near, true))
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
            let q = |x: f64| crate::convert::f64_to_exact::<Q>(x);
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
