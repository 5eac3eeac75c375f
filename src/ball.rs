//! Certified arithmetic for the engine's decisions: three-valued answers ([`Tri`]),
//! numbers with a rigorous error radius ([`Ball`], [`BallV`]) and exact signs of small
//! sums and products of floats ([`exact`]).
//!
//! # The rounding model
//! Every f64 operation ∘ ∈ {+, −, ×, ÷, √} returns fl(x ∘ y) with
//! |fl(x ∘ y) − x ∘ y| ≤ u·|x ∘ y| (u = 2⁻⁵³) when the result is normal, and an absolute
//! error ≤ 2⁻¹⁰⁷⁵ when it is subnormal (additions are then exact). An overflow gives ±∞
//! and ∞ − ∞ gives NaN; every decision below checks that its operands are finite and
//! answers [`Tri::Unsure`] otherwise.
//!
//! # Balls
//! A [`Ball`] (z, r) says: the exact real number the engine stands for lies in
//! [z − r, z + r]. The operations propagate that promise: the new radius is the
//! propagated one plus 2u·|z| (one rounding, with (1 + 2u) to spare because |z| is the
//! rounded value), computed with [`up`], which turns a radius computed with at most
//! [`UP_OPS`] roundings of non-negative numbers into an upper bound of the exact one.
//! A sign is decided when |z| > r, by an exact float comparison. This is the forward
//! error bound of every predicate of the engine: each one evaluates its formula on balls,
//! so the bound is the formula's own, derived operation by operation, never an epsilon.

use crate::vect2::Vect2;

/// The unit roundoff of f64, 2⁻⁵³.
pub const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// An absolute floor for radii: 2⁻¹⁰⁶⁵, which covers the at most 2⁻¹⁰⁷⁵ error of each
/// subnormal product or quotient among the roundings one radius carries (at most 2¹⁰).
pub const ETA: f64 = f64::MIN_POSITIVE / 8_796_093_022_208.0; // 2⁻¹⁰²² / 2⁴³

/// How many roundings of non-negative numbers [`up`] absorbs: their computed value is at
/// least the exact one times (1 − u)^UP_OPS ≥ 1 − 14u; ×(1 + 16u) (itself rounded, −u)
/// brings it back above 1 + u − O(u²) > 1. (The error analysis names it; no code reads it.)
#[allow(dead_code)]
pub const UP_OPS: u32 = 14;

/// max of two non-negative magnitudes by one comparison. A NaN argument may be dropped:
/// that is harmless, because a NaN radius only ever comes with a NaN or infinite value,
/// which every decision already treats as undecided.
#[inline(always)]
pub fn mx(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// An upper bound of the exact value of a non-negative quantity whose computed value is
/// `x` after at most [`UP_OPS`] roundings (see the module doc). NaN and ∞ stay.
///
/// Branch-free on purpose (it is on every hot path): the ETA floor is added even to an
/// exact 0. Exact zeros that matter (a coefficient that is exactly 0) are settled by
/// the exact fallbacks, or tolerated by the interval enclosures, which treat a
/// coefficient in [−ETA, ETA] as the tiny parabola it might be.
#[inline(always)]
pub fn up(x: f64) -> f64 {
    x * (1.0 + 16.0 * U) + ETA
}

/// The rounding error bound of a product p = fl(x·y): 2u·|p| in the normal range; the
/// at most 2⁻¹⁰⁷⁵ of an underflowing product is in the [`ETA`] that [`up`] adds.
/// Additions need no such term: they are exact when subnormal.
#[inline(always)]
fn prod_err(p: f64, _x: f64, _y: f64) -> f64 {
    2.0 * U * p.abs()
}

/// A float ≥ the exact result of the one operation that produced `x` (round toward +∞).
///
/// |fl − exact| ≤ u·|exact| ≤ u(1 + 2u)|x| for a normal x, ≤ 2⁻¹⁰⁷⁵ for a subnormal one;
/// x + (4u|x| + ETA) is itself rounded to nearest but stays ≥ x + 3u|x| + ETA/2.
#[inline(always)]
pub fn round_up(x: f64) -> f64 {
    x + (4.0 * U * x.abs() + ETA)
}

/// A float ≤ the exact result of the one operation that produced `x` (see [`round_up`]).
#[inline(always)]
pub fn round_down(x: f64) -> f64 {
    x - (4.0 * U * x.abs() + ETA)
}

// ================================================================ Tri

/// A decision that may be certified either way, or not certified at all.
///
/// The engine's algorithms carry it through every step; wherever it leads to the final
/// answer, `Unsure` is resolved towards detection, so a `false` is only ever returned
/// when every comparison behind it was certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Tri {
    /// Certainly false (for the exact inputs).
    No,
    /// Certainly true.
    Yes,
    /// The float computation could not decide it.
    Unsure,
}

impl Tri {
    /// A certified bool.
    #[inline(always)]
    pub fn from_bool(b: bool) -> Tri {
        if b {
            Tri::Yes
        } else {
            Tri::No
        }
    }

    /// Logical or: Yes if either is Yes, No if both are No.
    #[inline(always)]
    pub fn or(self, o: Tri) -> Tri {
        match (self, o) {
            (Tri::Yes, _) | (_, Tri::Yes) => Tri::Yes,
            (Tri::No, Tri::No) => Tri::No,
            _ => Tri::Unsure,
        }
    }

    /// Logical and: No if either is No, Yes if both are Yes.
    #[inline(always)]
    pub fn and(self, o: Tri) -> Tri {
        match (self, o) {
            (Tri::No, _) | (_, Tri::No) => Tri::No,
            (Tri::Yes, Tri::Yes) => Tri::Yes,
            _ => Tri::Unsure,
        }
    }

    /// Logical not (Unsure stays Unsure).
    #[inline(always)]
    #[allow(clippy::should_implement_trait)]
    pub fn not(self) -> Tri {
        match self {
            Tri::No => Tri::Yes,
            Tri::Yes => Tri::No,
            Tri::Unsure => Tri::Unsure,
        }
    }

    /// The answer when `Yes` is the safe side (a detection): Unsure reads as true.
    #[inline(always)]
    pub fn or_true(self) -> bool {
        self != Tri::No
    }

    /// The decision is certified (Yes or No).
    #[inline(always)]
    pub fn is_certain(self) -> bool {
        self != Tri::Unsure
    }
}

/// Is the radius finite? Every ball operation adds 2u·|value| to the radius, so an
/// infinite or NaN value always comes with an infinite or NaN radius: this one
/// comparison is the finiteness guard of the decisions.
#[inline(always)]
fn bounded(b: Ball) -> bool {
    b.r < f64::INFINITY
}

/// exact > 0, certified.
#[inline(always)]
pub fn positive(b: Ball) -> Tri {
    if !bounded(b) {
        Tri::Unsure
    } else if b.z > b.r {
        Tri::Yes
    } else if b.z <= -b.r {
        Tri::No
    } else {
        Tri::Unsure
    }
}

/// exact ≥ 0, certified.
#[inline(always)]
pub fn nonnegative(b: Ball) -> Tri {
    if !bounded(b) {
        Tri::Unsure
    } else if b.z >= b.r {
        Tri::Yes
    } else if -b.z > b.r {
        Tri::No
    } else {
        Tri::Unsure
    }
}

// ================================================================ balls

/// A real number known to lie in [z − r, z + r].
///
/// Invariant: r ≥ 0. A non-finite z or r makes every decision on it Unsure (the
/// comparisons with NaN or ∞ in [`positive`] and [`nonnegative`] fail both ways).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// The computed value.
    pub z: f64,
    /// The error radius.
    pub r: f64,
}

// Named methods rather than operator traits: each one is a rounding step whose bound is
// spelled out beside it.
#[allow(clippy::should_implement_trait)]
impl Ball {
    /// An exact float (radius 0).
    #[inline(always)]
    pub const fn exact(z: f64) -> Ball {
        Ball { z, r: 0.0 }
    }

    /// z with the error of one rounding: the exact value is within 2u·|z| (+ ETA).
    #[inline(always)]
    pub fn rounded(z: f64) -> Ball {
        Ball {
            z,
            r: 2.0 * U * z.abs() + ETA,
        }
    }

    /// self + o.
    #[inline(always)]
    pub fn add(self, o: Ball) -> Ball {
        let z = self.z + o.z;
        Ball {
            z,
            r: up(self.r + o.r + 2.0 * U * z.abs()),
        }
    }

    /// self − o.
    #[inline(always)]
    pub fn sub(self, o: Ball) -> Ball {
        let z = self.z - o.z;
        Ball {
            z,
            r: up(self.r + o.r + 2.0 * U * z.abs()),
        }
    }

    /// self · o: |xy − x̃ỹ| ≤ |x̃|·r_y + |ỹ|·r_x + r_x·r_y, plus the product's rounding.
    #[inline(always)]
    pub fn mul(self, o: Ball) -> Ball {
        let z = self.z * o.z;
        Ball {
            z,
            r: up(self.z.abs() * o.r
                + o.z.abs() * self.r
                + self.r * o.r
                + prod_err(z, self.z, o.z)),
        }
    }

    /// self · k for an exact float k.
    #[inline(always)]
    pub fn scale(self, k: f64) -> Ball {
        let z = self.z * k;
        Ball {
            z,
            r: up(self.r * k.abs() + prod_err(z, self.z, k)),
        }
    }

    /// self / 2 (exact unless subnormal, which `prod_err` covers).
    #[inline(always)]
    pub fn half(self) -> Ball {
        let z = 0.5 * self.z;
        Ball {
            z,
            r: up(0.5 * self.r + prod_err(z, self.z, 0.5)),
        }
    }

    /// −self.
    #[inline(always)]
    pub fn neg(self) -> Ball {
        Ball {
            z: -self.z,
            r: self.r,
        }
    }

    /// self², using |x + e|² − x̃² = 2x̃e + e².
    #[inline(always)]
    pub fn sq(self) -> Ball {
        let z = self.z * self.z;
        Ball {
            z,
            r: up(2.0 * self.z.abs() * self.r + self.r * self.r + prod_err(z, self.z, self.z)),
        }
    }

    /// The lower end of the enclosure, rounded down (z itself for an exact float).
    #[inline(always)]
    pub fn lo(self) -> f64 {
        if self.r == 0.0 {
            self.z
        } else {
            round_down(self.z - self.r)
        }
    }

    /// The upper end of the enclosure, rounded up (z itself for an exact float).
    #[inline(always)]
    pub fn hi(self) -> f64 {
        if self.r == 0.0 {
            self.z
        } else {
            round_up(self.z + self.r)
        }
    }

    /// Is this exactly the float 0?
    #[inline(always)]
    pub fn is_exact_zero(self) -> bool {
        self.z == 0.0 && self.r == 0.0
    }

    /// The ball of the float interval [lo, hi] (lo ≤ hi).
    #[inline(always)]
    pub fn from_interval(lo: f64, hi: f64) -> Ball {
        let z = 0.5 * lo + 0.5 * hi;
        Ball {
            z,
            r: up(mx(hi - z, z - lo)),
        }
    }

    /// Both ends finite.
    #[inline(always)]
    pub fn is_finite(self) -> bool {
        self.z.is_finite() && self.r.is_finite()
    }
}

/// A 2D point or vector whose exact coordinates are each within r of (v.x, v.y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallV {
    /// The computed coordinates.
    pub v: Vect2,
    /// One error radius for both coordinates.
    pub r: f64,
}

#[allow(clippy::should_implement_trait)]
impl BallV {
    /// An exact point.
    #[inline(always)]
    pub const fn exact(v: Vect2) -> BallV {
        BallV { v, r: 0.0 }
    }

    /// The origin, exactly.
    pub const ZERO: BallV = BallV::exact(Vect2::ZERO);

    /// p − q for exact floats p, q: each coordinate rounded once.
    #[inline(always)]
    pub fn diff(p: Vect2, q: Vect2) -> BallV {
        let v = p - q;
        BallV {
            v,
            r: 2.0 * U * mx(v.x.abs(), v.y.abs()),
        }
    }

    /// The x coordinate as a ball.
    #[inline(always)]
    pub fn x(self) -> Ball {
        Ball {
            z: self.v.x,
            r: self.r,
        }
    }

    /// The y coordinate as a ball.
    #[inline(always)]
    pub fn y(self) -> Ball {
        Ball {
            z: self.v.y,
            r: self.r,
        }
    }

    /// self + o.
    #[inline(always)]
    pub fn add(self, o: BallV) -> BallV {
        let v = self.v + o.v;
        BallV {
            v,
            r: up(self.r + o.r + 2.0 * U * mx(v.x.abs(), v.y.abs())),
        }
    }

    /// self − o.
    #[inline(always)]
    pub fn sub(self, o: BallV) -> BallV {
        let v = self.v - o.v;
        BallV {
            v,
            r: up(self.r + o.r + 2.0 * U * mx(v.x.abs(), v.y.abs())),
        }
    }

    /// k·self for a ball k.
    #[inline(always)]
    pub fn scale(self, k: Ball) -> BallV {
        let v = self.v.scale(k.z);
        let m = mx(self.v.x.abs(), self.v.y.abs());
        let e = mx(prod_err(v.x, self.v.x, k.z), prod_err(v.y, self.v.y, k.z));
        BallV {
            v,
            r: up(k.z.abs() * self.r + m * k.r + self.r * k.r + e),
        }
    }

    /// self / 2.
    #[inline(always)]
    pub fn half(self) -> BallV {
        let v = self.v.scale(0.5);
        let e = mx(prod_err(v.x, self.v.x, 0.5), prod_err(v.y, self.v.y, 0.5));
        BallV {
            v,
            r: up(0.5 * self.r + e),
        }
    }

    /// `s − (p + q)/2` for exact floats p, q, s (the offset of a segment's midpoint, paper
    /// A §II.I's `w`), with one static error bound instead of a ball per operation. Per
    /// coordinate the two differences `d = fl(p − s)`, `e = fl(q − s)` and their sum
    /// `σ = fl(d + e)` are each within `u` of their computed value's magnitude (round to
    /// nearest; a subnormal difference is exact), and the halving loses at most 2⁻¹⁰⁷⁵
    /// (underflow only): the error is at most `u(|d| + |e| + |σ|)/2` plus that, which
    /// [`up`] covers together with the radius's own two roundings.
    #[inline(always)]
    pub fn mid_offset(p: Vect2, q: Vect2, s: Vect2) -> BallV {
        let (d, e) = (p - s, q - s);
        let sum = d + e;
        let m = |a: Vect2| mx(a.x.abs(), a.y.abs());
        BallV {
            v: sum.scale(-0.5),
            r: up(0.5 * U * (m(d) + m(e) + m(sum))),
        }
    }

    /// `(p − q)/2` for exact floats p, q (paper A §II.I's half edge `a`), with one static
    /// error bound: the difference is within `u` of its computed magnitude and the halving
    /// loses at most 2⁻¹⁰⁷⁵ (underflow only), which [`up`] covers.
    #[inline(always)]
    pub fn half_diff(p: Vect2, q: Vect2) -> BallV {
        let d = p - q;
        BallV {
            v: d.scale(0.5),
            r: up(0.5 * U * mx(d.x.abs(), d.y.abs())),
        }
    }

    /// −self.
    #[inline(always)]
    pub fn neg(self) -> BallV {
        BallV {
            v: -self.v,
            r: self.r,
        }
    }

    /// The right perpendicular (v_y, −v_x) (§I), exactly.
    #[inline(always)]
    pub fn perp(self) -> BallV {
        BallV {
            v: self.v.perp(),
            r: self.r,
        }
    }

    /// self · o: each of the two products as in [`Ball::mul`], then their sum.
    #[inline(always)]
    pub fn dot(self, o: BallV) -> Ball {
        let (a, b) = (self.v, o.v);
        let p = a.x * b.x;
        let q = a.y * b.y;
        let z = p + q;
        let prop =
            (a.x.abs() + a.y.abs()) * o.r + (b.x.abs() + b.y.abs()) * self.r + 2.0 * self.r * o.r;
        Ball {
            z,
            r: up(prop + prod_err(p, a.x, b.x) + prod_err(q, a.y, b.y) + 2.0 * U * z.abs()),
        }
    }

    /// self × o = self_x·o_y − self_y·o_x (equal to self · o⊥).
    #[inline(always)]
    pub fn cross(self, o: BallV) -> Ball {
        let (a, b) = (self.v, o.v);
        let p = a.x * b.y;
        let q = a.y * b.x;
        let z = p - q;
        let prop =
            (a.x.abs() + a.y.abs()) * o.r + (b.x.abs() + b.y.abs()) * self.r + 2.0 * self.r * o.r;
        Ball {
            z,
            r: up(prop + prod_err(p, a.x, b.y) + prod_err(q, a.y, b.x) + 2.0 * U * z.abs()),
        }
    }

    /// ‖self‖², as [`BallV::dot`] with itself.
    #[inline(always)]
    pub fn sq(self) -> Ball {
        self.dot(self)
    }

    /// An upper bound of ‖exact‖₁.
    #[inline(always)]
    pub fn norm1_hi(self) -> f64 {
        up(self.v.x.abs() + self.v.y.abs() + 2.0 * self.r)
    }

    /// Both coordinates and the radius finite.
    #[inline(always)]
    pub fn is_finite(self) -> bool {
        self.v.is_finite() && self.r.is_finite()
    }
}

// ================================================================ exact signs

/// Exact signs of sums and products of a few floats, by error-free transformations
/// (two-sum, two-product) into a non-overlapping expansion on the stack.
///
/// The sign of an expansion is the sign of its largest non-zero component (Shewchuk,
/// "Adaptive precision floating-point arithmetic", 1997). Each routine returns `None`
/// when an intermediate overflows or a product is so small that its error term may be
/// subnormal (then the transformations are not error-free): the caller stays Unsure.
pub mod exact {
    /// Products below this magnitude may have an inexact error term (2⁻⁹⁶⁰ leaves room).
    const TINY: f64 = f64::MIN_POSITIVE * 4_611_686_018_427_387_904.0; // 2⁻¹⁰²² · 2⁶²

    /// a + b = s + e exactly (Knuth's two-sum).
    #[inline(always)]
    pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        let bb = s - a;
        let e = (a - (s - bb)) + (b - bb);
        (s, e)
    }

    /// a·b = p + e exactly, by a fused multiply-add, or `None` when it may not be.
    #[inline(always)]
    pub fn two_prod(a: f64, b: f64) -> Option<(f64, f64)> {
        let p = a * b;
        if !p.is_finite() || (p != 0.0 && p.abs() < TINY) || (p == 0.0 && a != 0.0 && b != 0.0) {
            return None;
        }
        Some((p, fma(a, b, -p)))
    }

    #[inline(always)]
    fn fma(a: f64, b: f64, c: f64) -> f64 {
        #[cfg(feature = "std")]
        {
            a.mul_add(b, c)
        }
        #[cfg(not(feature = "std"))]
        {
            libm::fma(a, b, c)
        }
    }

    /// Up to this many terms in one sum.
    pub const CAP: usize = 128;

    /// A sum of floats kept exactly, as a non-overlapping expansion (Shewchuk's
    /// Grow-Expansion, components in increasing magnitude).
    #[derive(Clone)]
    pub struct Sum {
        e: [f64; CAP],
        n: usize,
        ok: bool,
    }

    impl Default for Sum {
        fn default() -> Self {
            Sum {
                e: [0.0; CAP],
                n: 0,
                ok: true,
            }
        }
    }

    impl Sum {
        /// Adds one float exactly.
        pub fn add(&mut self, x: f64) {
            if !x.is_finite() || self.n >= CAP {
                self.ok = false;
                return;
            }
            let mut q = x;
            let mut k = 0;
            for i in 0..self.n {
                let (s, h) = two_sum(q, self.e[i]);
                q = s;
                if h != 0.0 {
                    self.e[k] = h;
                    k += 1;
                }
            }
            if !q.is_finite() {
                self.ok = false;
                return;
            }
            if q != 0.0 {
                self.e[k] = q;
                k += 1;
            }
            self.n = k;
        }

        /// Adds a·b exactly.
        pub fn add_prod(&mut self, a: f64, b: f64) {
            match two_prod(a, b) {
                Some((p, e)) => {
                    self.add(p);
                    self.add(e);
                }
                None => self.ok = false,
            }
        }

        /// Adds (Σ xs)·(Σ ys) exactly.
        pub fn add_prods(&mut self, xs: &[f64], ys: &[f64]) {
            for &x in xs {
                for &y in ys {
                    self.add_prod(x, y);
                }
            }
        }

        /// Σ xs, exactly.
        pub fn of(xs: &[f64]) -> Sum {
            let mut s = Sum::default();
            for &x in xs {
                s.add(x);
            }
            s
        }

        /// The components (their sum is the value).
        pub fn comps(&self) -> &[f64] {
            &self.e[..self.n]
        }

        /// self + k·o for k = ±1, exactly.
        pub fn add_sum(&mut self, o: &Sum, k: f64) {
            if !o.ok {
                self.ok = false;
            }
            for &c in o.comps() {
                self.add(k * c);
            }
        }

        /// self · o, exactly.
        pub fn mul(&self, o: &Sum) -> Sum {
            let mut r = Sum {
                ok: self.ok && o.ok,
                ..Default::default()
            };
            r.add_prods(self.comps(), o.comps());
            r
        }

        /// The exact sign of the sum, or `None` when it could not be kept exactly.
        pub fn sign(&self) -> Option<i8> {
            if !self.ok {
                return None;
            }
            // Zero-eliminated: the last component is the largest and non-zero.
            match self.n {
                0 => Some(0),
                n if self.e[n - 1] > 0.0 => Some(1),
                _ => Some(-1),
            }
        }
    }

    /// The exact sign of Σ xs.
    #[cfg(test)]
    pub fn sign_sum(xs: &[f64]) -> Option<i8> {
        let mut s = Sum::default();
        for &x in xs {
            s.add(x);
        }
        s.sign()
    }

    /// The exact sign of (Σax)(Σby) − (Σay)(Σbx): the cross product a × b of two
    /// vectors whose coordinates are exact sums of floats.
    pub fn sign_cross(ax: &[f64], ay: &[f64], bx: &[f64], by: &[f64]) -> Option<i8> {
        let mut s = Sum::default();
        s.add_prods(ax, by);
        let mut nay = [0.0f64; 8];
        let k = ay.len().min(8);
        if ay.len() > 8 {
            return None;
        }
        for (d, &y) in nay.iter_mut().zip(ay) {
            *d = -y;
        }
        s.add_prods(&nay[..k], bx);
        s.sign()
    }
}

#[cfg(test)]
mod tests;
