//! The point's motion against a moving polygon over time, certified: the machinery that
//! the time scans of [`crate::entry`] and [`crate::intervals`] share (paper A §II.C's
//! edge quadratics without the BUFF band, §II.B's crossing count, §III's slab).
//!
//! - [`Edge`]: one edge a(t) b(t) in the point's frame, with its quadratics
//!   g = (x − a) × (b − a), h₁ = (x − a)·(b − a), h₂ = (b − x)·(b − a) and the squared
//!   lengths |b − a|², |x − a|², |x − b|², each as a [`Taylor`] form at a float time.
//! - [`range`]: the rigorous enclosure of a quadratic over |t − m| ≤ h.
//! - [`bracket`]: a certified bracket of the one root of a monotone function.
//! - [`winding`]: the point's certified winding number about P(τ).
//! - [`Frame`]: the exact change of length unit (a power of two) that keeps every
//!   product of the scans away from overflow and underflow.
//! - [`SlabLine`]: the two linear functions whose signs say where the point's height is
//!   against the slab.
//!
//! # Error analysis
//! Every quantity is a [`Ball`] computed by `crate::ball`'s arithmetic (one rounding per
//! operation, each bounded by 2u·|result|, radii rounded up by [`up`]), at an exact float
//! time m. A quadratic f(t) = f(m) + f′(m)(t − m) + (f″/2)(t − m)² is then enclosed over
//! |t − m| ≤ h by f(m) ± (|f′(m)|·h + |f″/2|·h²): the Taylor form of a quadratic is
//! exact, so the radius only adds the enclosures of the three coefficients and the
//! rounding of its own terms. No absolute epsilon enters.

use crate::ball::{mx, up, Ball, BallV};
use crate::vect2::Vect2;

/// The slab of paper A §III, for the time scans: the point's height sz + t·vz, the
/// slab's ends bottom + t·vsp and top + t·vsp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heights {
    /// The point's height at t = 0.
    pub sz: f64,
    /// The point's vertical speed.
    pub vz: f64,
    /// The slab's bottom at t = 0.
    pub bottom: f64,
    /// The slab's top at t = 0.
    pub top: f64,
    /// The slab's vertical speed.
    pub vsp: f64,
}

/// The finest interval the scans halve: T·2⁻³⁶ (an enclosure's typical width is one
/// or two of them, below 10⁻¹⁰·T).
pub const RESOLUTION: f64 = 1.0 / (1u64 << 36) as f64;

/// The most intervals one scan visits before answering from where it stands.
pub const VISIT_BUDGET: usize = 20_000;

/// The point's state about P(t) while it is on no edge (§II.B's crossing count: zero
/// outside, odd inside; even and non-zero only for a polygon that is not simple, where
/// inside is undefined).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum State {
    Outside,
    Inside,
    /// The winding number is certainly even and not 0.
    Undefined,
    /// Not certified.
    Unknown,
}

/// The enclosure of f over |t − m| ≤ h from f(m), f′(m) and f″/2 (a quadratic's
/// Taylor form, exact: the radius only adds the rounding of its own terms, which
/// [`up`] covers).
#[inline]
pub(crate) fn range(f0: Ball, f1: Ball, f2: Ball, h: f64) -> Ball {
    let a1 = f1.z.abs() + f1.r;
    let a2 = f2.z.abs() + f2.r;
    Ball {
        z: f0.z,
        r: up(f0.r + a1 * h + a2 * h * h),
    }
}

/// A quadratic in t at the float time m: f(m), f′(m) and f″/2, each a ball (the module
/// doc's Taylor form).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Taylor {
    pub f0: Ball,
    pub f1: Ball,
    pub f2: Ball,
}

impl Taylor {
    /// The enclosure of f over |t − m| ≤ h ([`range`]).
    #[inline]
    pub(crate) fn range(&self, h: f64) -> Ball {
        range(self.f0, self.f1, self.f2, h)
    }

    /// The enclosure of f′(t) = f′(m) + 2·(f″/2)·(t − m) over |t − m| ≤ h.
    #[inline]
    pub(crate) fn slope(&self, h: f64) -> Ball {
        Ball {
            z: self.f1.z,
            r: up(self.f1.r + 2.0 * (self.f2.z.abs() + self.f2.r) * h),
        }
    }
}

/// A certain sign: `Some(true)` when the exact value is > 0, `Some(false)` when < 0.
#[inline]
pub(crate) fn sign(x: Ball) -> Option<bool> {
    if x.lo() > 0.0 {
        Some(true)
    } else if x.hi() < 0.0 {
        Some(false)
    } else {
        None
    }
}

/// One edge i → j, in the point's frame: q(t) = x − a = q0 + t·q1, e(t) = b − a =
/// e0 + t·e1, w(t) = b − x = e − q (paper A §II.C's relative motion).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge {
    pub q0: BallV,
    pub q1: BallV,
    pub e0: BallV,
    pub e1: BallV,
    pub w1: BallV,
    /// g″/2, h₁″/2, h₂″/2: constant.
    pub g2: Ball,
    pub h12: Ball,
    pub h22: Ball,
    /// |e|″/2, |q|″/2, |w|″/2 (the squared lengths' second coefficients): constant.
    pub e22: Ball,
    pub q22: Ball,
    pub w22: Ball,
    /// Which of q1, e1, w1 are exactly 0, when the edge was formed by [`Edge::lean`]
    /// (else all `false`): their terms are then left out of every sum, exactly.
    zero: [bool; 3],
}

/// a + b where either may be absent (an exact 0).
#[inline]
fn plus(a: Option<Ball>, b: Option<Ball>) -> Ball {
    match (a, b) {
        (Some(a), Some(b)) => a.add(b),
        (Some(a), None) | (None, Some(a)) => a,
        (None, None) => Ball::exact(0.0),
    }
}

/// f(), unless `absent` (an exact 0).
#[inline]
fn term(absent: bool, f: impl FnOnce() -> Ball) -> Option<Ball> {
    if absent {
        None
    } else {
        Some(f())
    }
}

impl Edge {
    /// The edge's relative motion (paper A §II.C).
    pub(crate) fn new(s: Vect2, v: Vect2, a: Vect2, va: Vect2, b: Vect2, vb: Vect2) -> Edge {
        let q1 = BallV::diff(v, va);
        let e1 = BallV::diff(vb, va);
        let w1 = e1.sub(q1);
        // A velocity difference that is exactly 0 (a rigidly moving edge, a point moving
        // with a vertex) makes its products exactly 0: kept exact rather than given the
        // radius floor, which would put subnormal numbers (slow on most processors) into
        // every range of the scan.
        let zero = |x: BallV| x.v == Vect2::ZERO && x.r == 0.0;
        let prod = |x: BallV, y: BallV, f: fn(BallV, BallV) -> Ball| {
            if zero(x) || zero(y) {
                Ball::exact(0.0)
            } else {
                f(x, y)
            }
        };
        Edge {
            q0: BallV::diff(s, a),
            q1,
            e0: BallV::diff(b, a),
            e1,
            w1,
            g2: prod(q1, e1, BallV::cross),
            h12: prod(q1, e1, BallV::dot),
            h22: prod(w1, e1, BallV::dot),
            e22: prod(e1, e1, BallV::dot),
            q22: prod(q1, q1, BallV::dot),
            w22: prod(w1, w1, BallV::dot),
            zero: [false; 3],
        }
    }

    /// [`Edge::new`], with the terms of a velocity difference that is exactly 0 left out
    /// of the Taylor forms (exact: they are 0; the radii are smaller and no subnormal
    /// radius floor enters the hot sums). The interval scan's form.
    pub(crate) fn lean(s: Vect2, v: Vect2, a: Vect2, va: Vect2, b: Vect2, vb: Vect2) -> Edge {
        let mut e = Edge::new(s, v, a, va, b, vb);
        let zero = |x: BallV| x.v == Vect2::ZERO && x.r == 0.0;
        e.zero = [zero(e.q1), zero(e.e1), zero(e.w1)];
        e
    }

    /// q(m), e(m), w(m) at the float time m.
    #[inline]
    pub(crate) fn at(&self, m: f64) -> (BallV, BallV, BallV) {
        let mb = Ball::exact(m);
        let [zq, ze, _] = self.zero;
        let q = if zq {
            self.q0
        } else {
            self.q0.add(self.q1.scale(mb))
        };
        let e = if ze {
            self.e0
        } else {
            self.e0.add(self.e1.scale(mb))
        };
        (q, e, e.sub(q))
    }

    /// g(m) = (x − a) × (b − a) at the float time m.
    #[cfg(feature = "std")]
    pub(crate) fn g_at(&self, m: f64) -> Ball {
        let (q, e, _) = self.at(m);
        q.cross(e)
    }

    /// g, h₁, h₂ as Taylor forms at m, from q(m), e(m), w(m) (§II.C's quadratics).
    #[inline]
    #[cfg(feature = "std")]
    pub(crate) fn taylor3(&self, q: BallV, e: BallV, w: BallV) -> [Taylor; 3] {
        [self.g(q, e), self.h1(q, e), self.h2(w, e)]
    }

    /// g = q × e as a Taylor form at m, from q(m), e(m).
    #[inline]
    pub(crate) fn g(&self, q: BallV, e: BallV) -> Taylor {
        let [zq, ze, _] = self.zero;
        Taylor {
            f0: q.cross(e),
            f1: plus(term(zq, || self.q1.cross(e)), term(ze, || q.cross(self.e1))),
            f2: self.g2,
        }
    }

    /// h₁ = q·e as a Taylor form at m.
    #[inline]
    pub(crate) fn h1(&self, q: BallV, e: BallV) -> Taylor {
        let [zq, ze, _] = self.zero;
        Taylor {
            f0: q.dot(e),
            f1: plus(term(zq, || self.q1.dot(e)), term(ze, || q.dot(self.e1))),
            f2: self.h12,
        }
    }

    /// h₂ = w·e as a Taylor form at m.
    #[inline]
    pub(crate) fn h2(&self, w: BallV, e: BallV) -> Taylor {
        let [_, ze, zw] = self.zero;
        Taylor {
            f0: w.dot(e),
            f1: plus(term(zw, || self.w1.dot(e)), term(ze, || w.dot(self.e1))),
            f2: self.h22,
        }
    }

    /// The edge is rigid: e1 is exactly 0 (known only for an edge formed by
    /// [`Edge::lean`]).
    #[inline]
    pub(crate) fn rigid(&self) -> bool {
        self.zero[1]
    }

    /// One squared length as a Taylor form at m: of q(m) (k = 0), e(m) (k = 1) or w(m)
    /// (k = 2), whose velocity is q1, e1 or w1.
    #[inline]
    pub(crate) fn length(&self, k: usize, x: BallV) -> Taylor {
        let (x1, f2) = match k {
            0 => (self.q1, self.q22),
            1 => (self.e1, self.e22),
            _ => (self.w1, self.w22),
        };
        Taylor {
            f0: x.sq(),
            f1: plus(term(self.zero[k], || x.dot(x1).scale(2.0)), None),
            f2,
        }
    }

    /// The ranges of g, h₁, h₂ over |t − m| ≤ h.
    #[inline]
    #[cfg(feature = "std")]
    pub(crate) fn ranges(&self, m: f64, h: f64) -> [Ball; 3] {
        let (q, e, w) = self.at(m);
        let [g, h1, h2] = self.taylor3(q, e, w);
        [g.range(h), h1.range(h), h2.range(h)]
    }

    /// A crossing of this edge alone, resolved without halving (the scan's shortcut):
    /// over [a, b] (centre m, half width h) h₁ > 0 and h₂ > 0 throughout and g′ ≠ 0
    /// throughout, so the point meets the edge exactly where g = 0, at most once. `None`
    /// when those conditions or the signs of g at a and b are not certain. `Some(None)`:
    /// g has the same sign at a and b, so no contact on [a, b]. `Some(Some((t1, t2)))`:
    /// a ≤ t1 < t2 ≤ b, no contact on [a, t1] (g monotone with one sign at a and t1), and
    /// a contact in (t1, t2) (g changes sign there with h₁, h₂ > 0).
    #[cfg(feature = "std")]
    pub(crate) fn lone_crossing(
        &self,
        a: f64,
        b: f64,
        m: f64,
        h: f64,
        eps: f64,
    ) -> Option<Option<(f64, f64)>> {
        let (q, e, w) = self.at(m);
        let [g, h1, h2] = self.taylor3(q, e, w);
        let (h1, h2) = (h1.range(h), h2.range(h));
        let slope = g.slope(h);
        if !(h1.lo() > 0.0 && h2.lo() > 0.0 && (slope.lo() > 0.0 || slope.hi() < 0.0)) {
            return None;
        }
        let (sa, sb) = (sign(self.g_at(a))?, sign(self.g_at(b))?);
        if sa == sb {
            return Some(None);
        }
        bracket(|t| self.g_with_slope(t), a, b, m, eps, 0.0, sa, sb)
            .map(|(t1, t2, _, _)| Some((t1, t2)))
    }

    /// g(t) as a ball and g′(t) as a float estimate (for Newton's method).
    #[inline]
    #[cfg(feature = "std")]
    pub(crate) fn g_with_slope(&self, t: f64) -> (Ball, f64) {
        let (q, e, w) = self.at(t);
        let [g, ..] = self.taylor3(q, e, w);
        (g.f0, g.f1.z)
    }

    /// Can the point be on this edge at some time of |t − m| ≤ h? `false` is certain.
    /// A NaN range compares false both ways, so it is "may touch".
    #[inline]
    #[cfg(feature = "std")]
    pub(crate) fn may_touch(&self, m: f64, h: f64) -> bool {
        let [g, h1, h2] = self.ranges(m, h);
        touch_possible(g, h1, h2)
    }

    /// Certainly on the edge's interior at some time of [a, b] (m, h its centre and
    /// half width): g changes sign between a and b while h₁ > 0 and h₂ > 0 throughout.
    #[cfg(feature = "std")]
    pub(crate) fn surely_crossed(&self, a: f64, b: f64, m: f64, h: f64) -> bool {
        let [_, h1, h2] = self.ranges(m, h);
        if !(h1.lo() > 0.0 && h2.lo() > 0.0) {
            return false;
        }
        let (ga, gb) = (self.g_at(a), self.g_at(b));
        (ga.lo() > 0.0 && gb.hi() < 0.0) || (ga.hi() < 0.0 && gb.lo() > 0.0)
    }
}

/// From the ranges of g, h₁, h₂: can the point be on the edge (g = 0, h₁ ≥ 0, h₂ ≥ 0,
/// §II.C's contact without BUFF)? `false` is certain; NaN reads as "may".
#[inline]
pub(crate) fn touch_possible(g: Ball, h1: Ball, h2: Ball) -> bool {
    !(g.lo() > 0.0 || g.hi() < 0.0 || h1.hi() < 0.0 || h2.hi() < 0.0)
}

/// The one root of f on [a, b], bracketed: f is monotone on [a, b] and certainly of sign
/// `sa` at a and `sb` ≠ `sa` at b (the caller's certificates). `f(t)` gives f(t) as a
/// ball and f′(t) as a float estimate. Newton's method on the float centres gives an
/// estimate r (any estimate in [a, b] will do: what follows certifies the bracket around
/// it; the iteration stops early at a fixed point, or once a step is at most `tol`);
/// floats t1 = r − δ and t2 = r + δ at which f has the certain signs `sa` and `sb` then
/// bound the root, δ growing from `eps`/16. `Some((t1, t2, f(t1), f(t2)))`:
/// a ≤ t1 < t2 ≤ b with f of sign `sa` on [a, t1] and `sb` on [t2, b] (monotone), the
/// root in (t1, t2).
#[allow(clippy::too_many_arguments)]
pub(crate) fn bracket(
    f: impl Fn(f64) -> (Ball, f64),
    a: f64,
    b: f64,
    m: f64,
    eps: f64,
    tol: f64,
    sa: bool,
    sb: bool,
) -> Option<(f64, f64, Ball, Ball)> {
    let mut r = m;
    for _ in 0..6 {
        let (y, d) = f(r);
        let step = y.z / d;
        if !step.is_finite() {
            break;
        }
        let next = (r - step).clamp(a, b);
        let done = next == r || step.abs() <= tol;
        r = next;
        if done {
            break;
        }
    }
    let mut delta = eps * (1.0 / 16.0);
    for _ in 0..80 {
        let t1 = if r - delta > a { r - delta } else { a };
        let t2 = if r + delta < b { r + delta } else { b };
        if t1 < t2 {
            let f1 = f(t1).0;
            if sign(f1) == Some(sa) {
                let f2 = f(t2).0;
                if sign(f2) == Some(sb) {
                    return Some((t1, t2, f1, f2));
                }
            }
        }
        delta *= 2.0;
    }
    None
}

/// [a, b]'s centre m and an upper bound h of |t − m| over [a, b] (both differences are
/// rounded once, [`up`] covers it).
#[inline]
pub(crate) fn centre(a: f64, b: f64) -> (f64, f64) {
    let m = 0.5 * a + 0.5 * b;
    (m, up(mx(b - m, m - a)))
}

/// One of the slab's two lines (paper A §III): c0 + t·c1, which is ≥ 0 where the
/// point's height is on the slab's side of that end (c0, c1 balls of the exact values).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SlabLine {
    pub c0: Ball,
    pub c1: Ball,
}

impl SlabLine {
    /// The lines (sz − bottom + off) + t·(vz − vsp) and (top − sz + off) + t·(vsp − vz):
    /// both ≥ 0 exactly when bottom − off ≤ z ≤ top + off (off = 0: the slab of §III).
    pub(crate) fn pair(z: Heights, off: f64) -> [SlabLine; 2] {
        let shift = |c: Ball| {
            if off == 0.0 {
                c
            } else {
                c.add(Ball::exact(off))
            }
        };
        [
            SlabLine {
                c0: shift(Ball::rounded(z.sz - z.bottom)),
                c1: Ball::rounded(z.vz - z.vsp),
            },
            SlabLine {
                c0: shift(Ball::rounded(z.top - z.sz)),
                c1: Ball::rounded(z.vsp - z.vz),
            },
        ]
    }

    /// The line's range over |t − m| ≤ h.
    #[inline]
    pub(crate) fn range(&self, m: f64, h: f64) -> Ball {
        range(
            self.c0.add(self.c1.mul(Ball::exact(m))),
            self.c1,
            Ball::exact(0.0),
            h,
        )
    }

    /// The line's value at the float time t (a ball) and its slope.
    #[inline]
    pub(crate) fn at(&self, t: f64) -> (Ball, f64) {
        (self.c0.add(self.c1.mul(Ball::exact(t))), self.c1.z)
    }
}

/// The magnitudes 2^−LAZY … 2^LAZY that a lazy [`Frame`] leaves unscaled.
pub(crate) const LAZY: i32 = 300;

/// An exact change of length unit: every length times 2^k (paper A §II's question is
/// invariant under it), chosen so that the largest magnitude of a case is about 1, so
/// that the scans' products neither overflow nor underflow. Only an exact scaling is
/// used: when some coordinate would lose bits, k is 0.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    k: i32,
    /// 2^k when it is a normal float (then x·2^k is the exact scalbn), else 0.
    factor: f64,
}

impl Frame {
    /// The frame of a case: k = −ilogb of the largest of |s|, T·|v|, |p_i|, T·|V_i|, the
    /// heights (and T times their speeds) and the `extra` lengths; k = 0 unless every
    /// one of those values (and v, V_i, the vertical speeds) scales exactly. With
    /// `lazy`, also k = 0 when that largest magnitude is within 2^±[`LAZY`]: the scans'
    /// products of two lengths then stay far from overflow and underflow as they are.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        t: f64,
        s: Vect2,
        v: Vect2,
        p: &[Vect2],
        vels: &[Vect2],
        heights: Option<Heights>,
        extra: &[f64],
        lazy: bool,
    ) -> Frame {
        let mut mag = s.x.abs().max(s.y.abs()).max(t * v.x.abs().max(v.y.abs()));
        for (pi, vi) in p.iter().zip(vels) {
            mag = mag
                .max(pi.x.abs().max(pi.y.abs()))
                .max(t * vi.x.abs().max(vi.y.abs()));
        }
        if let Some(z) = heights {
            for x in [z.sz, z.bottom, z.top, t * z.vz, t * z.vsp] {
                mag = mag.max(x.abs());
            }
        }
        for &x in extra {
            mag = mag.max(x.abs());
        }
        let k = if mag.is_finite() && mag > 0.0 {
            -libm::ilogb(mag)
        } else {
            0
        };
        if lazy && k.abs() <= LAZY {
            return Frame::of(0);
        }
        let frame = Frame::of(k);
        if k == 0 {
            return frame;
        }
        // x scales exactly when scaling back gives x again. With 2^k and 2^−k both
        // normal floats, x·2^k and y·2^−k are the correctly rounded scalbn(x, k) and
        // scalbn(y, −k): the same test, by two multiplications.
        let back = Frame::of(-k);
        let exact = |x: f64| back.len(frame.len(x)) == x;
        let pt = |a: &Vect2| exact(a.x) && exact(a.y);
        let all = pt(&s)
            && pt(&v)
            && p.iter().all(pt)
            && vels.iter().all(pt)
            && heights.map_or(true, |z| {
                [z.sz, z.vz, z.bottom, z.top, z.vsp].into_iter().all(exact)
            })
            && extra.iter().all(|&x| exact(x));
        if all {
            frame
        } else {
            Frame::of(0)
        }
    }

    /// The frame of 2^k.
    fn of(k: i32) -> Frame {
        let factor = if (-1022..=1023).contains(&k) {
            f64::from_bits(((k + 1023) as u64) << 52)
        } else {
            0.0
        };
        Frame { k, factor }
    }

    /// x·2^k (exact for every value [`Frame::new`] checked).
    #[inline]
    pub(crate) fn len(&self, x: f64) -> f64 {
        if self.k == 0 {
            x
        } else if self.factor != 0.0 {
            x * self.factor
        } else {
            libm::scalbn(x, self.k)
        }
    }

    /// a·2^k.
    #[inline]
    pub(crate) fn pt(&self, a: Vect2) -> Vect2 {
        Vect2::new(self.len(a.x), self.len(a.y))
    }

    /// The heights times 2^k.
    pub(crate) fn heights(&self, z: Heights) -> Heights {
        Heights {
            sz: self.len(z.sz),
            vz: self.len(z.vz),
            bottom: self.len(z.bottom),
            top: self.len(z.top),
            vsp: self.len(z.vsp),
        }
    }
}

/// The point's winding number about P(τ), certified, with a ray along +x, +y, −x or −y
/// (the first whose every sign is decided): 0 outside, odd inside, even and not 0
/// undefined, unknown when no ray decides (paper A §II.B's crossing count, on balls). `vertex(i)` gives p_i and V_i (in the scan's
/// frame), s and v the point.
pub(crate) fn winding(
    n: usize,
    vertex: impl Fn(usize) -> (Vect2, Vect2),
    s: Vect2,
    v: Vect2,
    tau: f64,
) -> State {
    let tb = Ball::exact(tau);
    let rel = |i: usize| {
        let (pi, vi) = vertex(i);
        BallV::diff(pi, s).add(BallV::diff(vi, v).scale(tb))
    };
    // Rotations by quarter turns are exact (swaps and negations).
    let turns: [fn(BallV) -> BallV; 4] = [
        |a| a,
        |a| BallV {
            v: Vect2::new(a.v.y, -a.v.x),
            r: a.r,
        },
        |a| a.neg(),
        |a| BallV {
            v: Vect2::new(-a.v.y, a.v.x),
            r: a.r,
        },
    ];
    let below = |y: Ball| -> Option<bool> {
        if y.hi() <= 0.0 {
            Some(true)
        } else if y.lo() > 0.0 {
            Some(false)
        } else {
            None
        }
    };
    if n == 0 {
        return State::Outside;
    }
    let first = rel(0);
    'ray: for turn in turns {
        let mut w: i64 = 0;
        let mut cur = first;
        for i in 0..n {
            let next = if i + 1 == n { first } else { rel(i + 1) };
            let (a, b) = (turn(cur), turn(next));
            cur = next;
            let (Some(a_below), Some(b_below)) = (below(a.y()), below(b.y())) else {
                continue 'ray;
            };
            if a_below == b_below {
                continue;
            }
            let c = a.cross(b);
            let side = if c.lo() > 0.0 {
                1
            } else if c.hi() < 0.0 {
                -1
            } else {
                continue 'ray;
            };
            if a_below && side > 0 {
                w += 1;
            } else if !a_below && side < 0 {
                w -= 1;
            }
        }
        return match w {
            0 => State::Outside,
            w if w % 2 != 0 => State::Inside,
            _ => State::Undefined,
        };
    }
    State::Unknown
}
