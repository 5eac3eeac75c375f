//! Paper A §II.H (statically shaped polygons), §II.I (warping polygons) and §III (3D).
//!
//! Every detector has a three-valued form (`*_tri`) that carries [`Tri`] through the
//! algorithm: `No` only when paper A computed without rounding answers no, `Yes` only
//! when it answers yes, `Unsure` when some comparison on the way could not be decided in
//! f64. The boolean form reads `Unsure` as a detection, so it never misses what paper A
//! in exact arithmetic detects.
//!
//! The detectors never form s + T·v or P + T·V in absolute coordinates: each decision
//! is taken on differences from the point (see [`crate::contain::RelPoly`]), so the
//! error bounds are on the scale of the encounter, whatever the offsets.

use crate::ball::{self, exact, nonnegative, positive, round_down, round_up, Ball, BallV, Tri};
use crate::contain::{definitely_outside_rel, AtTime, Shifted};
use crate::polygon::VertexSeq;
use crate::predicates::{self as pr, PathLine, Terms, SWEEP_ROUNDING};
use crate::proximity::segments_close_rel;
use crate::vect2::{sqrt, Vect2};

// ===================================================================== §II.H

/// Paper A §II.H detect_same_2D: does s + t·v come within BUFF of the statically shaped
/// polygon P + t·V (all v_i equal) for some t ∈ [0, T]?
///
/// Step 1: s not definitely outside P → true. Step 2: s + T·v not definitely outside
/// P + T·V → true. Step 3: some edge with segments_close(s, s + T·(v − v_i), p_i, p_j,
/// BUFF) → true. Certified: `false` only when the exact answer is false.
#[inline]
pub fn detect_same_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_same_2d_tri(t, s, v, p, vels, buff).or_true()
}

/// Paper A §II.H detect_same_2D, three-valued (see [`detect_same_2d`]).
#[inline]
pub fn detect_same_2d_tri<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    same_window(
        Ball::exact(0.0),
        Ball::exact(t),
        s,
        v,
        p,
        vels,
        buff,
        statically_shaped(vels),
    )
}

/// detect_same_2D over the time window [ta, tb] of the original motion, which is what
/// paper A §III runs: detect_same_2D(tb − ta, s + ta·v, v, P + ta·V, V, BUFF). The
/// window's ends are balls (a slab window's ends are quotients).
///
/// In the point's frame (origin s, each velocity relative to v): step 1 is
/// definitely_outside of (p_i − s) + ta·(v_i − v), step 2 the same at tb, and step 3
/// translates segments_close by s + ta·v_i: the relative path runs from ta·(v − v_i) to
/// tb·(v − v_i), the edge from p_i − s to p_j − s + ta·(v_j − v_i). `stat` is
/// [`statically_shaped`]`(vels)`, which the caller has at hand.
fn same_window<P, V>(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    buff: f64,
    stat: bool,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return Tri::No;
    }
    let mut acc = Tri::No;
    let v0 = vels.vertex(0);
    for t in [ta, tb] {
        let outside = if t.is_exact_zero() {
            definitely_outside_rel(&AtTime { p, vels, s, v, t }, buff)
        } else if stat {
            definitely_outside_rel(&Shifted::new(p, s, v, v0, t), buff)
        } else {
            definitely_outside_rel(&AtTime { p, vels, s, v, t }, buff)
        };
        match outside {
            Tri::No => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::Yes => {}
        }
    }
    // The relative path of the common velocity v_0, and each vertex's side of its line
    // (computed once, carried to the next edge): an edge with both ends certainly beyond
    // BUFF on one side is not close, the same certain test segments_close starts with.
    // From a window starting at 0 the line passes through the point exactly: a static
    // bound suffices ([`PathLine`]); otherwise the side is taken on balls.
    let rel0 = BallV::diff(v, v0);
    let from_zero = ta.is_exact_zero();
    // From 0 the path starts at the point exactly (and m0 is its end).
    let (pa0, pb0, m0) = if from_zero {
        let pb0 = rel0.scale(tb);
        (BallV::exact(Vect2::ZERO), pb0, pb0)
    } else {
        let (pa0, pb0) = (rel0.scale(ta), rel0.scale(tb));
        (pa0, pb0, pb0.sub(pa0))
    };
    let line = PathLine::new(m0, buff);
    // The side of vertex k: from the rounded difference alone when the line passes
    // through the point (the static bound of [`PathLine`]), else on its ball.
    let sides = PathSides {
        from_zero,
        line,
        pa: pa0,
        m: m0,
        buff,
    };
    let side = |k: usize| sides.of(p.vertex(k), s);
    let mut side_i = side(0);
    for i in 0..n {
        let j = p.next(i);
        let (vi, vj) = (vels.vertex(i), vels.vertex(j));
        let side_j = side(j);
        let same_i = stat || pr::same_velocity(vi, v0);
        let skip = side_i != 0 && side_i == side_j && same_i && (stat || pr::same_velocity(vj, vi));
        side_i = side_j;
        if skip {
            continue;
        }
        let (pa, pb) = if same_i {
            (pa0, pb0)
        } else {
            let rel = BallV::diff(v, vi);
            (rel.scale(ta), rel.scale(tb))
        };
        let qj = BallV::diff(p.vertex(j), s);
        let edge_j = if ta.is_exact_zero() || stat || pr::same_velocity(vj, vi) {
            qj
        } else {
            qj.add(BallV::diff(vj, vi).scale(ta))
        };
        let qi = BallV::diff(p.vertex(i), s);
        // Exact terms when both window ends are exact floats (always, but for a slab
        // window's quotients): the path from ta·(v − v_i) to tb·(v − v_i).
        let terms = || {
            if ta.r != 0.0 || tb.r != 0.0 {
                return None;
            }
            let path = |k: f64| Terms::ZERO.plus_scaled(k, v)?.plus_scaled(-k, vi);
            let ej = Terms::diff(p.vertex(j), s);
            let ej = if ta.is_exact_zero() || stat || pr::same_velocity(vj, vi) {
                ej
            } else {
                ej.plus_scaled(ta.z, vj)?.plus_scaled(-ta.z, vi)?
            };
            Some([path(ta.z)?, path(tb.z)?, Terms::diff(p.vertex(i), s), ej])
        };
        match segments_close_rel(pa, pb, qi, edge_j, buff, terms) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

/// Paper A §II.H step 3 (segments_close's filter): same_window's side test of a vertex against the relative path's line: from the
/// rounded difference alone when the window starts at 0 (the line passes through the
/// point: the static bound of [`PathLine`]), else on balls ([`pr::side_beyond`], out of
/// line so that the common test stays inlined in the loop).
struct PathSides {
    from_zero: bool,
    line: PathLine,
    pa: BallV,
    m: BallV,
    buff: f64,
}

impl PathSides {
    #[inline(always)]
    fn of(&self, p: Vect2, s: Vect2) -> i8 {
        if self.from_zero {
            self.line.side(p - s)
        } else {
            side_on_balls(self.pa, self.m, BallV::diff(p, s), self.buff)
        }
    }
}

/// See [`PathSides`].
#[inline(never)]
fn side_on_balls(pa: BallV, m: BallV, q: BallV, buff: f64) -> i8 {
    pr::side_beyond(pa, m, q, buff)
}

// ===================================================================== §II.I

/// The sign σ (or ε) = ±1 of paper A §II.I.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// σ = −1.
    Neg,
    /// σ = +1.
    Pos,
}

impl Sign {
    /// Both signs, −1 then +1.
    pub const BOTH: [Sign; 2] = [Sign::Neg, Sign::Pos];

    /// −1.0 or 1.0.
    #[inline(always)]
    pub fn value(self) -> f64 {
        match self {
            Sign::Neg => -1.0,
            Sign::Pos => 1.0,
        }
    }

    /// The other sign.
    #[inline(always)]
    pub fn flip(self) -> Sign {
        match self {
            Sign::Neg => Sign::Pos,
            Sign::Pos => Sign::Neg,
        }
    }
}

/// A closed time interval [lb, ub]; empty when lb > ub.
///
/// The paper writes the empty interval as (T, 0). That is not empty when T = 0, which
/// detect_3D produces when the slab window is a single instant, so the engine uses
/// (+∞, −∞) instead: it loses every max/min comparison, as (T, 0) does for T > 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower bound.
    pub lb: f64,
    /// The upper bound.
    pub ub: f64,
}

impl Interval {
    /// The empty interval.
    pub const EMPTY: Interval = Interval {
        lb: f64::INFINITY,
        ub: f64::NEG_INFINITY,
    };

    /// [lb, ub].
    #[inline(always)]
    pub const fn new(lb: f64, ub: f64) -> Interval {
        Interval { lb, ub }
    }

    /// Does the interval contain no time? (NaN ends count as non-empty: the safe side.)
    #[inline(always)]
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub fn is_empty(&self) -> bool {
        self.lb > self.ub
    }
}

/// Enclosures [lo, hi] of the smaller and the larger real root of a·t² + b·t + c
/// (floats, a ≠ 0) for every discriminant in the enclosure of b² − 4ac clipped at 0;
/// `None` when they are unbounded (q = 0 below).
///
/// Roots without cancellation: q = −(b + sgn(b)·√disc)/2, roots q/a and c/q. Each
/// operation is rounded outward ([`round_down`], [`round_up`]), so the enclosures hold.
fn root_bounds(a: f64, b: f64, c: f64, disc: Ball) -> Option<[(f64, f64); 2]> {
    // Outward rounding that keeps an overflowed quotient a sound bound: +∞ as a lower
    // bound reads "above f64::MAX", −∞ as an upper bound "below −f64::MAX".
    let rd = |x: f64| {
        if x == f64::INFINITY {
            f64::MAX
        } else {
            round_down(x)
        }
    };
    let ru = |x: f64| {
        if x == f64::NEG_INFINITY {
            -f64::MAX
        } else {
            round_up(x)
        }
    };
    // A bound that overflowed is still a bound on the right side once clamped: a lower
    // bound of +∞ means "above f64::MAX", an upper bound of −∞ "below −f64::MAX".
    let order = |x1: (f64, f64), x2: (f64, f64)| {
        let lo = |x: f64| if x == f64::INFINITY { f64::MAX } else { x };
        let hi = |x: f64| if x == f64::NEG_INFINITY { -f64::MAX } else { x };
        let (x1, x2) = ((lo(x1.0), hi(x1.1)), (lo(x2.0), hi(x2.1)));
        if x1.0.is_nan() || x1.1.is_nan() || x2.0.is_nan() || x2.1.is_nan() {
            return None;
        }
        Some([
            (fmin(x1.0, x2.0), fmin(x1.1, x2.1)),
            (fmax(x1.0, x2.0), fmax(x1.1, x2.1)),
        ])
    };
    if c == 0.0 {
        // Roots 0 and −b/a, the second exact when b = 0.
        let r = -b / a;
        let x2 = if b == 0.0 { (0.0, 0.0) } else { (rd(r), ru(r)) };
        return order((0.0, 0.0), x2);
    }
    if b != 0.0 && disc.z > 4.0 * disc.r {
        if let Some(r) = root_bounds_simple(a, b, c, disc) {
            return Some(r);
        }
    }
    let d_lo = disc.lo().max(0.0);
    let d_hi = disc.hi();
    let s_lo = rd(sqrt(d_lo)).max(0.0);
    let s_hi = ru(sqrt(d_hi));
    let (q_lo, q_hi) = if b >= 0.0 {
        (rd(-0.5 * ru(b + s_hi)), ru(-0.5 * rd(b + s_lo)))
    } else {
        (rd(0.5 * rd(s_lo - b)), ru(0.5 * ru(s_hi - b)))
    };
    if !(q_lo.is_finite() && q_hi.is_finite()) {
        return None;
    }
    let x1 = if a > 0.0 {
        (rd(q_lo / a), ru(q_hi / a))
    } else {
        (rd(q_hi / a), ru(q_lo / a))
    };
    if b == 0.0 {
        // Roots ±√disc/(2a): symmetric about 0.
        return order(x1, (-x1.1, -x1.0));
    }
    if q_lo <= 0.0 && q_hi >= 0.0 {
        return None;
    }
    let (y1, y2) = (c / q_lo, c / q_hi);
    order(x1, (rd(y1.min(y2)), ru(y1.max(y2))))
}

/// [`root_bounds`] for two well separated roots (disc > 4·its radius, b ≠ 0), in
/// midpoint-radius form with one square root and two reciprocals.
///
/// √d for d ∈ [z − r, z + r] lies within r/√z·(1/(1 + √(3/4))) < r/s·(1 + 2u) of √z,
/// and s = fl(√z) within u·√z: so within e = r·(1/s) + 2u·s (raised for rounding) of s.
/// q = −(b + sgn(b)·√d)/2 adds no cancellation: |q − q̃| ≤ (e + 2u|b ± s|)/2. Then
/// x1 = q/a and x2 = c/q from the reciprocals 1/a and 1/q̃: with |q̃| ≥ 2·q_r (checked),
/// |c/q − c/q̃| ≤ 2|c|·q_r/q̃², and each product and reciprocal adds ≤ 2u relative.
#[inline(always)]
fn root_bounds_simple(a: f64, b: f64, c: f64, disc: Ball) -> Option<[(f64, f64); 2]> {
    let s = sqrt(disc.z);
    let e = ball::up(disc.r * (1.0 / s) + 2.0 * ball::U * s);
    let bs = if b > 0.0 { b + s } else { b - s };
    let qz = -0.5 * bs;
    let qr = ball::up(0.5 * e + 2.0 * ball::U * bs.abs());
    // Also refuses a NaN: only a q̃ certainly twice its radius away from 0 passes.
    if qz.abs() <= 2.0 * qr || qz.is_nan() || qr.is_nan() {
        return None;
    }
    let ia = 1.0 / a;
    let iq = 1.0 / qz;
    let x1 = qz * ia;
    let x1r = ball::up(qr * ia.abs() + 6.0 * ball::U * x1.abs());
    let x2 = c * iq;
    let x2r = ball::up(2.0 * qr * iq.abs() * x2.abs() + 6.0 * ball::U * x2.abs());
    let (l1, h1) = (round_down(x1 - x1r), round_up(x1 + x1r));
    let (l2, h2) = (round_down(x2 - x2r), round_up(x2 + x2r));
    if !(l1.is_finite() && h1.is_finite() && l2.is_finite() && h2.is_finite()) {
        return None;
    }
    Some([(fmin(l1, l2), fmin(h1, h2)), (fmax(l1, l2), fmax(h1, h2))])
}

/// The set {t ∈ [lo, hi] : a·t² + b·t + c ≥ 0} for floats a, b, c, enclosed from
/// outside (`outer`: a superset) or from inside (a subset), as dot_nn_lin's two
/// intervals: [σ = −1, σ = +1].
///
/// The cases of dot_nn_lin (omitted in the paper) are derived in docs/derivations.md.
/// a is compared with zero exactly. An undecided discriminant makes the outer set
/// everything and the inner one the widest possible gap, so both enclosures hold
/// whatever it is.
fn float_set(a: f64, b: f64, c: f64, lo: f64, hi: f64, outer: bool) -> [Interval; 2] {
    let full = Interval::new(lo, hi);
    let none = Interval::EMPTY;
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return if outer { [none, full] } else { [none, none] };
    }
    // What an outer set falls back to when the roots cannot be had: everything, unless
    // the quadratic is certainly negative all over the window (checked only then: with
    // the roots in hand the clipped intervals say as much).
    let unknown = || {
        if outer && !below_zero_on(a, b, c, lo, hi) {
            [none, full]
        } else {
            [none, none]
        }
    };
    if a == 0.0 {
        if b == 0.0 {
            return if c >= 0.0 { [none, full] } else { [none, none] };
        }
        // An overflowed quotient is still a bound on its side once clamped (as in
        // [`root_bounds`]): +∞ as a lower bound reads "above f64::MAX".
        let root = -c / b;
        let rl = if root == f64::INFINITY {
            f64::MAX
        } else {
            round_down(root)
        };
        let rh = if root == f64::NEG_INFINITY {
            -f64::MAX
        } else {
            round_up(root)
        };
        return if b > 0.0 {
            [none, Interval::new(lo.max(if outer { rl } else { rh }), hi)]
        } else {
            [Interval::new(lo, hi.min(if outer { rh } else { rl })), none]
        };
    }
    let disc = Ball::exact(b)
        .sq()
        .sub(Ball::exact(a).mul(Ball::exact(c)).scale(4.0));
    let pos = positive(disc);
    if a > 0.0 {
        if pos == Tri::No {
            return [none, full];
        }
        if pos == Tri::Unsure && outer {
            return unknown();
        }
        let Some([r1, r2]) = root_bounds(a, b, c, disc) else {
            return unknown();
        };
        if outer {
            [
                Interval::new(lo, hi.min(r1.1)),
                Interval::new(lo.max(r2.0), hi),
            ]
        } else {
            [
                Interval::new(lo, hi.min(r1.0)),
                Interval::new(lo.max(r2.1), hi),
            ]
        }
    } else {
        if nonnegative(disc) == Tri::No || (!outer && pos != Tri::Yes) {
            return [none, none];
        }
        let Some([r1, r2]) = root_bounds(a, b, c, disc) else {
            return unknown();
        };
        if outer {
            [none, Interval::new(lo.max(r1.0), hi.min(r2.1))]
        } else {
            [none, Interval::new(lo.max(r1.1), hi.min(r2.0))]
        }
    }
}

/// Is a·t² + b·t + c certainly negative on all of [lo, hi] (0 ≤ lo ≤ hi)? Then its set
/// is empty, and no root is needed. Decided when the quadratic takes its maximum over the
/// window at an end: always for a ≥ 0 (convex or linear), and for a < 0 when its slope
/// 2a·t + b is certainly ≤ 0 at lo (falling all along) or ≥ 0 at hi (rising all along).
/// Each evaluation is rounded upward step by step ([`round_up`]; t ≥ 0 keeps every step
/// monotone), so a negative result is certain.
#[inline(always)]
fn below_zero_on(a: f64, b: f64, c: f64, lo: f64, hi: f64) -> bool {
    let g_up = |t: f64| round_up(round_up(round_up(round_up(a * t) + b) * t) + c);
    if !(g_up(lo) < 0.0 && g_up(hi) < 0.0) {
        return false;
    }
    if a >= 0.0 {
        return true;
    }
    let slope_up = |t: f64| round_up(round_up(2.0 * a * t) + b);
    let slope_down = |t: f64| round_down(round_down(2.0 * a * t) + b);
    slope_up(lo) <= 0.0 || slope_down(hi) >= 0.0
}

/// The set {t ∈ [lo, hi] : A·t² + B·t + C ≥ 0} for ball coefficients (lo ≥ 0):
/// the outer enclosure uses the upper ends of the coefficients (for t ≥ 0 the exact
/// quadratic is at most A⁺t² + B⁺t + C⁺), the inner one the lower ends.
#[inline]
fn ball_set(a: Ball, b: Ball, c: Ball, lo: f64, hi: f64, outer: bool) -> [Interval; 2] {
    // An empty (or NaN) window: nothing.
    if lo > hi || lo.is_nan() || hi.is_nan() {
        return [Interval::EMPTY; 2];
    }
    if outer {
        float_set(a.hi(), b.hi(), c.hi(), lo, hi, true)
    } else {
        float_set(a.lo(), b.lo(), c.lo(), lo, hi, false)
    }
}

/// Coefficients (t², t, 1) of (ww + t·vv)·(aa + t·bb) as balls. `zero` says which of
/// ww, vv, aa, bb are known to be exactly 0 (from the inputs): the products they enter
/// are then exact 0s, not balls of radius ETA (which would blur a line into a parabola).
#[inline(always)]
fn dot_coeffs(ww: BallV, vv: BallV, aa: BallV, bb: BallV, zero: [bool; 4]) -> [Ball; 3] {
    let [w0, v0, a0, b0] = zero;
    let z = Ball::exact(0.0);
    let dot = |x: BallV, y: BallV, x0: bool, y0: bool| if x0 || y0 { None } else { Some(x.dot(y)) };
    let a = dot(vv, bb, v0, b0).unwrap_or(z);
    let b = match (dot(ww, bb, w0, b0), dot(vv, aa, v0, a0)) {
        (Some(p), Some(q)) => p.add(q),
        (Some(p), None) | (None, Some(p)) => p,
        (None, None) => z,
    };
    let c = dot(ww, aa, w0, a0).unwrap_or(z);
    [a, b, c]
}

/// Paper A §II.I dot_nn_lin (omitted in the paper; derived in docs/derivations.md): one of the
/// two intervals whose union is {t ∈ [0, T] : (ww + t·vv)·(aa + t·bb) ≥ 0}.
///
/// Certified as an outer enclosure: the returned interval contains the exact one.
#[inline]
pub fn dot_nn_lin(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, sigma: Sign) -> Interval {
    let e = BallV::exact;
    let zero = [ww, vv, aa, bb].map(|x| x == Vect2::ZERO);
    let [a, b, c] = dot_coeffs(e(ww), e(vv), e(aa), e(bb), zero);
    let set = ball_set(a, b, c, 0.0, t, true);
    match sigma {
        Sign::Neg => set[0],
        Sign::Pos => set[1],
    }
}

/// Paper A §II.I dot_nn: dot_nn_lin(T, F·aa + σ2·ww, F·bb + σ2·vv, aa, bb, σ1).
///
/// (F·aa + σ2·ww + t(F·bb + σ2·vv))·(aa + t·bb) = F·‖aa + t·bb‖² + σ2·(ww + t·vv)·(aa + t·bb),
/// so σ2 = +1 selects X ≥ −F·g² and σ2 = −1 selects X ≤ F·g²: together |X| ≤ F·g².
/// Certified as an outer enclosure, with F·aa + σ2·ww formed on balls.
#[inline]
pub fn dot_nn(
    t: f64,
    ww: Vect2,
    vv: Vect2,
    aa: Vect2,
    bb: Vect2,
    sigma1: Sign,
    sigma2: Sign,
    f: f64,
) -> Interval {
    let e = BallV::exact;
    let k = Ball::exact(f);
    let s2 = Ball::exact(sigma2.value());
    let w2 = e(aa).scale(k).add(e(ww).scale(s2));
    let v2 = e(bb).scale(k).add(e(vv).scale(s2));
    let z = |x: Vect2| x == Vect2::ZERO;
    let zero = [z(aa) && z(ww), z(bb) && z(vv), z(aa), z(bb)];
    let [a, b, c] = dot_coeffs(w2, v2, e(aa), e(bb), zero);
    let set = ball_set(a, b, c, 0.0, t, true);
    match sigma1 {
        Sign::Neg => set[0],
        Sign::Pos => set[1],
    }
}

/// Does some choice of one interval from each of the four pairs have a common point?
/// (edge_detect_simp step 2: max of the lower ends ≤ min of the upper ends.)
#[inline]
fn some_choice_meets(sets: &[[Interval; 2]; 4]) -> bool {
    first_meeting(sets).is_some()
}

/// Paper A §II.I edge_detect_simp step 2: the common part [lb, ub] of the first choice (one interval from each of the four
/// pairs) that has one, as in [`some_choice_meets`].
#[inline]
fn first_meeting(sets: &[[Interval; 2]; 4]) -> Option<(f64, f64)> {
    for i1 in &sets[0] {
        for i2 in &sets[1] {
            let (lb12, ub12) = (i1.lb.max(i2.lb), i1.ub.min(i2.ub));
            if lb12 > ub12 {
                continue;
            }
            for i3 in &sets[2] {
                for i4 in &sets[3] {
                    let (lb, ub) = (lb12.max(i3.lb).max(i4.lb), ub12.min(i3.ub).min(i4.ub));
                    if lb <= ub {
                        return Some((lb, ub));
                    }
                }
            }
        }
    }
    None
}

/// Paper A §II.I (edge_detect_simp): a quadratic with ball coefficients (t², t, 1) at an exact time t ≥ 0, by Horner's
/// rule on balls: the exact quadratic's value at t lies in the result.
#[inline(always)]
fn quad_at(c: &[Ball; 3], t: f64) -> Ball {
    c[0].scale(t).add(c[1]).scale(t).add(c[2])
}

/// Paper A §II.I edge_detect_simp: is there a t ∈ [0, T] with
/// |(ww + t·vv)·(aa + t·bb)| ≤ (1 + F)·‖aa + t·bb‖² and
/// |(ww + t·vv)·(aa⊥ + t·bb⊥)| ≤ F·‖aa⊥ + t·bb⊥‖²? Certified (see
/// [`edge_detect_simp_tri`]).
#[inline]
pub fn edge_detect_simp(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, f: f64) -> bool {
    let e = BallV::exact;
    let bb0 = bb == Vect2::ZERO;
    edge_detect_simp_tri(
        Ball::exact(0.0),
        Ball::exact(t),
        e(ww),
        e(vv),
        e(aa),
        e(bb),
        bb0,
        f,
    )
    .or_true()
}

/// The four quadratics of edge_detect_simp (§II.I), F·‖a‖² + w×a, F·‖a‖² − w×a,
/// K·‖a‖² + w·a and K·‖a‖² − w·a (K = 1 + F, a = aa + t·bb, w = ww + t·vv), as balls of
/// coefficients (t², t, 1): each coefficient is computed in floats, and its radius is a
/// static bound on the distance to the exact coefficient, for every exact input within
/// the balls ww, vv, aa, bb and k1 ∋ 1 + F.
///
/// Derivation. For vectors x, y known within r_x, r_y per coordinate, with
/// n_x = |x̃₁| + |x̃₂|, the exact x·y (or x × y) lies within
/// n_x·r_y + n_y·r_x + 2·r_x·r_y of x̃·ỹ (each of the two products moves by at most
/// |x̃ᵢ|·r_y + |ỹᵢ|·r_x + r_x·r_y), and fl(fl(x̃₁ỹ₁) ± fl(x̃₂ỹ₂)) within
/// u·(|x̃₁ỹ₁| + |x̃₂ỹ₂|)·(2 + u) ≤ 3u·n_x·n_y of x̃·ỹ: that is [`pair_err`]. A sum of two
/// such products adds u·|sum|. A coefficient c = K·g ± h (g of ‖a‖², h of w·a or w × a)
/// with K within r_K of k̃ is within |k̃|·E_g + r_K·(|g̃| + E_g) + E_h of k̃·g̃ ± h̃, and its
/// two roundings add u·|fl(k̃g̃)| + u·|c̃| ≤ 2u·|fl(k̃g̃)| + u·(1 + u)·|h̃|, so one bound
/// serves both signs. Every bound is a sum of products of non-negative floats at most
/// [`ball::UP_OPS`] roundings deep, raised by [`ball::up`] (which also covers underflow).
/// When bb is exactly 0 (`bb0`) the t² coefficients are exact zeros.
#[inline(always)]
fn simp_quadratics(
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    bb0: bool,
    k1: Ball,
    f: f64,
) -> [[Ball; 3]; 4] {
    let n = |x: BallV| x.v.x.abs() + x.v.y.abs();
    let (nw, nv, na, nb) = (n(ww), n(vv), n(aa), n(bb));
    let (rw, rv, ra, rb) = (ww.r, vv.r, aa.r, bb.r);
    let (w, v, a, b) = (ww.v, vv.v, aa.v, bb.v);
    // Values: ‖a‖² = g2·t² + g1·t + g0, w·a = x2·t² + x1·t + x0, w × a likewise (y).
    let cross = |x: Vect2, y: Vect2| x.dot(y.perp());
    let (ab, wb, va) = (a.dot(b), w.dot(b), v.dot(a));
    let (wbx, vax) = (cross(w, b), cross(v, a));
    let g = [b.dot(b), 2.0 * ab, a.dot(a)];
    let x = [v.dot(b), wb + va, w.dot(a)];
    let y = [cross(v, b), wbx + vax, cross(w, a)];
    let eg = [
        pair_err(nb, rb, nb, rb),
        2.0 * pair_err(na, ra, nb, rb),
        pair_err(na, ra, na, ra),
    ];
    let (e_vb, e_wb, e_va, e_wa) = (
        pair_err(nv, rv, nb, rb),
        pair_err(nw, rw, nb, rb),
        pair_err(nv, rv, na, ra),
        pair_err(nw, rw, na, ra),
    );
    let eh = |h: &[f64; 3]| [e_vb, e_wb + e_va + ball::U * h[1].abs(), e_wa];
    let (ex, ey) = (eh(&x), eh(&y));
    // One K·‖a‖² ± h pair: values of both signs and their shared radii.
    let pair = |k: Ball, h: &[f64; 3], e: &[f64; 3]| {
        let kg = [k.z * g[0], k.z * g[1], k.z * g[2]];
        let r = |i: usize| {
            ball::up(
                k.z.abs() * eg[i]
                    + k.r * (g[i].abs() + eg[i])
                    + e[i]
                    + 2.0 * ball::U * kg[i].abs()
                    + 2.0 * ball::U * h[i].abs(),
            )
        };
        let rs = [r(0), r(1), r(2)];
        let c = |i: usize, sigma: f64| {
            if bb0 && i == 0 {
                Ball::exact(0.0)
            } else {
                Ball {
                    z: if sigma > 0.0 {
                        kg[i] + h[i]
                    } else {
                        kg[i] - h[i]
                    },
                    r: rs[i],
                }
            }
        };
        (
            [c(0, 1.0), c(1, 1.0), c(2, 1.0)],
            [c(0, -1.0), c(1, -1.0), c(2, -1.0)],
        )
    };
    let (p_pos, p_neg) = pair(Ball::exact(f), &y, &ey);
    let (a_pos, a_neg) = pair(k1, &x, &ex);
    [p_pos, p_neg, a_pos, a_neg]
}

/// Paper A §II.I (edge_detect_simp): the bound of [`simp_quadratics`] on |x·y − fl(x̃·ỹ)| (or the cross product) for
/// vectors known within r_x and r_y per coordinate, n_x = ‖x̃‖₁, n_y = ‖ỹ‖₁:
/// n_x·r_y + n_y·r_x + 2·r_x·r_y + 3u·n_x·n_y, raised by [`ball::up`].
#[inline(always)]
fn pair_err(nx: f64, rx: f64, ny: f64, ry: f64) -> f64 {
    ball::up(nx * ry + ny * rx + 2.0 * rx * ry + 3.0 * ball::U * (nx * ny))
}

/// Paper A §II.I edge_detect_simp over the time window [ta, tb], three-valued, on balls.
///
/// The paper loops over six signs and intersects four dot_nn intervals per choice. A
/// choice meets exactly when some t lies in all four unions, i.e. when the four
/// quadratics (1 + F)‖a‖² ∓ w·a and F‖a‖² ∓ w×a (a = aa + t·bb, w = ww + t·vv; w·a⊥ =
/// w × a) are all ≥ 0 at one t. Their coefficients share nine dot and cross products,
/// formed once, with static error bounds (`simp_quadratics`). Each quadratic's set is
/// enclosed from outside and from inside (`ball_set`): no meeting of the outer sets is
/// a certain `No`; a time at which all four are certainly ≥ 0 (`quad_at`), or a
/// meeting of the inner sets, a certain `Yes`; anything between is `Unsure`. The
/// perpendicular conditions go first: they fail for most edges, and where they hold
/// (short intervals) the along conditions are usually settled by one evaluation, without
/// their roots. `bb0` says that bb is exactly 0 (a translating edge, v_i = v_j): the t²
/// coefficients are then exact zeros, and the quadratics lines.
pub fn edge_detect_simp_tri(
    ta: Ball,
    tb: Ball,
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    bb0: bool,
    f: f64,
) -> Tri {
    let (one_f, err) = exact::two_sum(1.0, f);
    let q = simp_quadratics(
        ww,
        vv,
        aa,
        bb,
        bb0,
        Ball {
            z: one_f,
            r: err.abs(),
        },
        f,
    );
    let (lo, hi) = (ta.lo().max(0.0), tb.hi());
    if !(lo.is_finite() && hi.is_finite()) {
        return Tri::Unsure;
    }
    let empty = |s: &[Interval; 2]| s[0].is_empty() && s[1].is_empty();
    let outer = |c: &[Ball; 3]| ball_set(c[0], c[1], c[2], lo, hi, true);
    let p_pos = outer(&q[0]);
    if empty(&p_pos) {
        return Tri::No;
    }
    let p_neg = outer(&q[1]);
    if empty(&p_neg) {
        return Tri::No;
    }
    // The inner window: times that lie in [ta, tb] for every exact ta and tb.
    let (ilo, ihi) = (ta.hi().max(0.0), tb.lo());
    let yes_at = |t: f64| {
        let t = t.max(ilo).min(ihi);
        // The along conditions first: where the perpendicular ones meet, they are the
        // ones that fail when the edge is missed.
        ilo <= ihi
            && [2, 3, 0, 1]
                .iter()
                .all(|&k| nonnegative(quad_at(&q[k], t)) == Tri::Yes)
    };
    // The perpendicular conditions hold only on the meetings J of their two outer sets,
    // short intervals around the times the point crosses the edge's line. On each J,
    // either one time (its middle) certainly satisfies all four quadratics — a certain
    // yes — or an along quadratic is certainly negative all over J ([`below_zero_on`],
    // on the coefficients' upper ends, which bound the exact quadratic for t ≥ 0): J
    // holds no solution. Only when some J is settled neither way are the along
    // quadratics' sets formed (below).
    let mut settled = true;
    let below =
        |c: &[Ball; 3], l: f64, h: f64| below_zero_on(c[0].hi(), c[1].hi(), c[2].hi(), l, h);
    for i1 in &p_pos {
        for i2 in &p_neg {
            let (jl, ju) = (i1.lb.max(i2.lb), i1.ub.min(i2.ub));
            if jl > ju {
                continue;
            }
            if yes_at(0.5 * jl + 0.5 * ju) {
                return Tri::Yes;
            }
            if !(below(&q[2], jl, ju) || below(&q[3], jl, ju)) {
                settled = false;
            }
        }
    }
    if settled {
        return Tri::No;
    }
    let a_pos = outer(&q[2]);
    if empty(&a_pos) {
        return Tri::No;
    }
    let a_neg = outer(&q[3]);
    let Some((lb, ub)) = first_meeting(&[p_pos, p_neg, a_pos, a_neg]) else {
        return Tri::No;
    };
    // A certain yes from the middle of the outer sets' meeting, as above.
    if yes_at(0.5 * lb + 0.5 * ub) {
        return Tri::Yes;
    }
    let inner = q.map(|c| ball_set(c[0], c[1], c[2], ilo, ihi, false));
    if some_choice_meets(&inner) {
        Tri::Yes
    } else {
        Tri::Unsure
    }
}

/// min for the filters' corner coordinates, which are never NaN (finite inputs: a sum
/// p + t·v overflows to ±∞ at worst), so the NaN handling of f64::min is not needed.
#[inline(always)]
fn fmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// max, as [`fmin`].
#[inline(always)]
fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// The point's part of the swept-box filter over a window [t0, t1], shared by every
/// edge of the polygon: its positions at t0 and t1, their box, the largest magnitude
/// involved, and its path line.
#[derive(Clone, Copy, Debug)]
struct Sweep {
    t0: f64,
    t1: f64,
    lo: Vect2,
    hi: Vect2,
    m: f64,
    s0: Vect2,
    dir: Vect2,
    moving: bool,
}

impl Sweep {
    fn new(t0: f64, t1: f64, s: Vect2, v: Vect2) -> Sweep {
        let (s0, s1) = (s.at(v, t0), s.at(v, t1));
        let big = |q: Vect2| fmax(q.x.abs(), q.y.abs());
        Sweep {
            t0,
            t1,
            lo: Vect2::new(fmin(s0.x, s1.x), fmin(s0.y, s1.y)),
            hi: Vect2::new(fmax(s0.x, s1.x), fmax(s0.y, s1.y)),
            m: fmax(fmax(big(s0), big(s1)), big(s)),
            s0,
            dir: s1 - s0,
            moving: s0 != s1,
        }
    }
}

/// Filter in front of edge_detect: over the window [t0, t1], the boxes swept by the point
/// and by the edge are farther apart than any time edge_detect_simp could accept.
///
/// The edge at time t lies in the box of its ends at t0 and t1 (each end moves on a
/// segment, the edge is their convex combination), the point in the box of its positions.
/// A time accepted by edge_detect_simp puts the point within (1 + F)·‖aa‖ of the midpoint
/// along the edge and F·‖aa‖ across it, so within 2F·‖aa(t)‖ ≤ 2F·L of the edge, with
/// L = max of ‖edge‖₁ at t0 and t1 (a norm is convex in t; ‖·‖₁ ≥ ‖·‖₂). The margin is
/// doubled for [`pr::ranges_apart`] and widened by [`SWEEP_ROUNDING`]·M: forming p + t·v
/// and a gap takes ≤ 4 roundings of ≤ u·(|p| + |t·v|) ≤ 3u·M each when M bounds |p| and
/// |p + t·v| (|t·v| ≤ |p| + |p + t·v|), and 2⁻⁴⁰ leaves a factor 2⁹ to spare.
///
/// The one exception is an edge that collapses to a point at some t of the window:
/// inequalities (1) read 0 ≤ 0 there, so paper A accepts wherever the point is. The
/// filter therefore only rejects an edge that provably never collapses
/// ([`never_collapses`]).
#[inline(always)]
fn swept_boxes_apart(w: &Sweep, pi: Vect2, pj: Vect2, vi: Vect2, vj: Vect2, f: f64) -> bool {
    let (t0, t1) = (w.t0, w.t1);
    let (ai, bi, aj, bj) = (pi.at(vi, t0), pi.at(vi, t1), pj.at(vj, t0), pj.at(vj, t1));
    let l0 = (aj.x - ai.x).abs() + (aj.y - ai.y).abs();
    let l1 = (bj.x - bi.x).abs() + (bj.y - bi.y).abs();
    let ex_lo = fmin(fmin(ai.x, aj.x), fmin(bi.x, bj.x));
    let ex_hi = fmax(fmax(ai.x, aj.x), fmax(bi.x, bj.x));
    let ey_lo = fmin(fmin(ai.y, aj.y), fmin(bi.y, bj.y));
    let ey_hi = fmax(fmax(ai.y, aj.y), fmax(bi.y, bj.y));
    let big = |q: Vect2| fmax(q.x.abs(), q.y.abs());
    let mut m = fmax(
        w.m,
        fmax(
            fmax(ex_lo.abs(), ex_hi.abs()),
            fmax(ey_lo.abs(), ey_hi.abs()),
        ),
    );
    if t0 != 0.0 {
        m = fmax(m, fmax(big(pi), big(pj)));
    }
    let slack = 2.0 * f * fmax(l0, l1) + SWEEP_ROUNDING * m;
    let twice = 2.0 * slack;
    if pr::ranges_apart(ex_lo, ex_hi, w.lo.x, w.hi.x, twice)
        || pr::ranges_apart(ey_lo, ey_hi, w.lo.y, w.hi.y, twice)
    {
        return true;
    }
    // The four swept corners certainly on one side of the point's path line, beyond the
    // slack: the edge (in their convex hull at every t) never comes near the path. The
    // computed corners and path ends are within SWEEP_ROUNDING·M of the exact ones.
    if w.moving {
        let line = pr::FuzzyLine::new(w.s0, w.dir, SWEEP_ROUNDING * m, slack);
        let side = line.side(ai);
        return side != 0
            && side == line.side(aj)
            && side == line.side(bi)
            && side == line.side(bj);
    }
    false
}

/// The edge e(t) = p_j − p_i + t·(v_j − v_i) is certainly non-zero on [t0, t1]:
/// e(0) × (v_j − v_i) ≠ 0 (then e(t) is never parallel to, let alone equal to, 0 — the
/// oracle's test), or ‖e(0)‖∞ > t1·‖v_j − v_i‖∞ (it cannot shrink to 0 in time), or one
/// coordinate has the same strict sign at t0 and t1 (it is linear in t).
///
/// The first two are decided on rounded differences with a static bound: each
/// difference has relative error ≤ u, so the cross product's computed value is within
/// 6u·(|e_x·w_y| + |e_y·w_x|) of the exact one (8u leaves room for its own roundings),
/// and the norms within 2u relative (8u on the comparison).
#[inline(always)]
pub(crate) fn never_collapses(
    t0: f64,
    t1: f64,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
) -> bool {
    let e = pj - pi;
    let w = vj - vi;
    let (p, q) = (e.x * w.y, e.y * w.x);
    let c = p - q;
    if c.abs() > 8.0 * ball::U * (p.abs() + q.abs()) + ball::ETA {
        return true;
    }
    let big = |x: Vect2| fmax(x.x.abs(), x.y.abs());
    if big(e) * (1.0 - 8.0 * ball::U) > t1 * big(w) * (1.0 + 8.0 * ball::U) + ball::ETA {
        return true;
    }
    let e = BallV::diff(pj, pi);
    let w = BallV::diff(vj, vi);
    let (e0, e1) = (
        e.add(w.scale(Ball::exact(t0))),
        e.add(w.scale(Ball::exact(t1))),
    );
    let strict = |x0: Ball, x1: Ball| {
        (positive(x0) == Tri::Yes && positive(x1) == Tri::Yes)
            || (positive(x0.neg()) == Tri::Yes && positive(x1.neg()) == Tri::Yes)
    };
    strict(e0.x(), e1.x()) || strict(e0.y(), e1.y())
}

/// Paper A §II.I eq (2) edge_detect: does s + t·v meet the moving segment
/// (p_i + t·v_i, p_j + t·v_j) for some t ∈ [0, T] (within the F slack)?
///
/// edge_detect_simp(T, s − (½p_j + ½p_i), v − (½v_j + ½v_i), ½p_j − ½p_i, ½v_j − ½v_i, F):
/// positions relative to the edge's midpoint, against the half-edge vector. Certified.
#[inline]
pub fn edge_detect(
    t: f64,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    f: f64,
) -> bool {
    let sweep = Sweep::new(0.0, t, s, v);
    edge_detect_window(
        &sweep,
        Ball::exact(0.0),
        Ball::exact(t),
        s,
        v,
        pi,
        pj,
        vi,
        vj,
        f,
    )
    .or_true()
}

/// edge_detect over the window [ta, tb] of the original motion, three-valued: the
/// paper's edge_detect(tb − ta, s + ta·v, v, p_i + ta·v_i, …) asks for a time of
/// [ta, tb] at which the same four quadratics of t hold.
///
/// ww = −((p_i − s) + (p_j − s))/2, vv = −((v_i − v) + (v_j − v))/2, aa = (p_j − p_i)/2,
/// bb = (v_j − v_i)/2, each on balls.
#[inline(always)]
fn edge_detect_window(
    sweep: &Sweep,
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    f: f64,
) -> Tri {
    if swept_boxes_apart(sweep, pi, pj, vi, vj, f)
        && never_collapses(sweep.t0, sweep.t1, pi, pj, vi, vj)
    {
        return Tri::No;
    }
    let (qi, qj) = (BallV::diff(pi, s), BallV::diff(pj, s));
    let (ui, uj) = (BallV::diff(vi, v), BallV::diff(vj, v));
    let ww = qi.add(qj).half().neg();
    let vv = ui.add(uj).half().neg();
    let aa = BallV::diff(pj, pi).half();
    let bb = BallV::diff(vj, vi).half();
    edge_detect_simp_tri(ta, tb, ww, vv, aa, bb, vi == vj, f)
}

/// Paper A §II.I detect_diff_2D: s not definitely outside P, or some moving edge met by
/// s + t·v within [0, T] (edge_detect). Certified: `false` only when the exact answer is.
#[inline]
pub fn detect_diff_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, f: f64, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_diff_2d_tri(t, s, v, p, vels, f, buff).or_true()
}

/// Paper A §II.I detect_diff_2D, three-valued (see [`detect_diff_2d`]).
#[inline]
pub fn detect_diff_2d_tri<P, V>(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    f: f64,
    buff: f64,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    diff_window(Ball::exact(0.0), Ball::exact(t), s, v, p, vels, f, buff)
}

/// detect_diff_2D over the window [ta, tb] of the original motion (see [`same_window`]).
fn diff_window<P, V>(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    f: f64,
    buff: f64,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return Tri::No;
    }
    let mut acc = match definitely_outside_rel(
        &AtTime {
            p,
            vels,
            s,
            v,
            t: ta,
        },
        buff,
    ) {
        Tri::No => return Tri::Yes,
        Tri::Unsure => Tri::Unsure,
        Tri::Yes => Tri::No,
    };
    let sweep = Sweep::new(ta.lo().max(0.0), tb.hi(), s, v);
    for i in 0..n {
        let j = p.next(i);
        let (pi, pj) = (p.vertex(i), p.vertex(j));
        let (vi, vj) = (vels.vertex(i), vels.vertex(j));
        match edge_detect_window(&sweep, ta, tb, s, v, pi, pj, vi, vj, f) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

// ===================================================================== §III

/// Paper A §III step 1: the exact sign of z[0] + z[1] + k·vz − k·vsp (k = σ·T, exact), by expansion: the
/// slab window's fallback when the static bound cannot tell. `None` when it cannot be had
/// (a product overflows, or is too small for an error-free product).
///
/// Heights and speeds all below 2⁻⁵⁰⁰ (down to subnormals, whose products with k the
/// error-free product refuses) are first scaled up by 2⁵⁰⁰ until the largest is at least
/// 2⁻⁵⁰⁰: scaling up by a power of two is exact for every float (subnormals included)
/// while the results stay below 1, and a positive factor keeps the sign.
#[inline(never)]
fn slab_sign_exact(z: [f64; 2], k: f64, vz: f64, vsp: f64) -> Option<i8> {
    let (low, up500) = (f64::from_bits(523 << 52), f64::from_bits(1523 << 52)); // 2⁻⁵⁰⁰, 2⁵⁰⁰
    let mut x = [z[0], z[1], vz, vsp];
    loop {
        let largest = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if !(largest > 0.0 && largest < low) {
            break;
        }
        x = x.map(|v| v * up500);
    }
    let mut sum = exact::Sum::default();
    sum.add(x[0]);
    sum.add(x[1]);
    sum.add_prod(k, x[2]);
    sum.add_prod(-k, x[3]);
    sum.sign()
}

/// Paper A §III step 1 with certified ends: the window [a, b] ⊆ [0, T] in which the
/// height s_z + t·v_z lies in [pmin + t·vsp, pmax + t·vsp], as two balls, or `None`
/// when there is certainly no such time.
///
/// With w = v_z − vsp, z0 = s_z − pmin, z1 = pmax − s_z the conditions are z0 + t·w ≥ 0
/// and z1 − t·w ≥ 0. Every decision is exact: the signs of w, z0 and z1 are signs of
/// float differences, and the comparisons of the crossing times with T are signs of
/// sums of a few floats and products (z0 + T·w and z1 − T·w, by expansion). Only the
/// crossing times themselves, quotients, are enclosed in balls.
pub fn slab_window_balls(
    t: f64,
    sz: f64,
    vz: f64,
    pmin: f64,
    pmax: f64,
    vsp: f64,
) -> Option<(Ball, Ball)> {
    if pmin > pmax {
        return None;
    }
    let zero = Ball::exact(0.0);
    let whole = Ball::exact(t);
    // An end that a comparison could not decide: a ball over all of [0, T], so that the
    // outer window [a.lo, b.hi] still holds the true one and the inner window
    // [a.hi, b.lo] claims no time the point may spend outside the slab.
    let unknown = Ball::from_interval(0.0, t);
    if vz == vsp {
        return (sz >= pmin && sz <= pmax).then_some((zero, whole));
    }
    // The sign of z[0] + z[1] + σ·T·(vz − vsp): from floats with a static bound first,
    // by expansion when that cannot tell (z0 + T·w = sz − pmin + T·vz − T·vsp, z1 − T·w
    // likewise). With a = fl(z[0] + z[1]) (error ≤ u|a|), w = fl(vz − vsp) (≤ u|w|) and
    // p = fl(σT·w) (≤ u|p| + T·u|w| ≤ 2u|p|(1 + u), plus an underflow of ≤ ETA), the
    // sum fl(a + p) adds ≤ u(|a| + |p|)(1 + 2u): 4u·(|a| + |p|) + ETA covers the whole,
    // raised by (1 + 16u) for its own roundings ([`ball::up`]).
    let sign_at_t = |z: [f64; 2], sigma: f64| -> Option<i8> {
        let a = z[0] + z[1];
        let p = (sigma * t) * (vz - vsp);
        let val = a + p;
        let bound = ball::up(4.0 * ball::U * (a.abs() + p.abs()) + ball::ETA);
        if val > bound {
            return Some(1);
        }
        if -val > bound {
            return Some(-1);
        }
        slab_sign_exact(z, sigma * t, vz, vsp)
    };
    let z0_at_t = sign_at_t([sz, -pmin], 1.0); // sign of z0 + T·w
    let z1_at_t = sign_at_t([pmax, -sz], -1.0); // sign of z1 − T·w
                                                // A quotient x/y of two float differences with x ≥ 0, y > 0, enclosed (exactly,
                                                // when both are exact floats and the division is: q·y − x = 0 by two-product).
    let quotient = |x: Ball, y: Ball| {
        if x.r == 0.0 && y.r == 0.0 {
            let q = x.z / y.z;
            if exact::two_prod(q, y.z) == Some((x.z, 0.0)) {
                return Ball::exact(q.min(t));
            }
        }
        let (x_lo, x_hi, y_lo, y_hi) = (x.lo().max(0.0), x.hi(), y.lo(), y.hi());
        if y_lo <= 0.0 || y_lo.is_nan() {
            return Ball::from_interval(0.0, t);
        }
        let lo = round_down(x_lo / y_hi).max(0.0);
        let hi = round_up(x_hi / y_lo).min(t);
        if lo <= hi {
            Ball::from_interval(lo, hi)
        } else {
            Ball::exact(lo.min(t))
        }
    };
    // A float difference: exact when two-sum leaves no error.
    let d = |p: f64, q: f64| {
        let (z, e) = exact::two_sum(p, -q);
        Ball { z, r: e.abs() }
    };
    if vz > vsp {
        // Enters at −z0/w, leaves at z1/w.
        let Some(s0) = z0_at_t else {
            return Some((unknown, unknown));
        };
        if pmax < sz || s0 < 0 {
            return None;
        }
        let a = if sz >= pmin {
            zero
        } else {
            quotient(d(pmin, sz), d(vz, vsp))
        };
        let b = match z1_at_t {
            Some(x) if x >= 0 => whole,
            Some(_) => quotient(d(pmax, sz), d(vz, vsp)),
            None => unknown,
        };
        Some((a, b))
    } else {
        // w < 0: enters at z1/w = (sz − pmax)/(vsp − vz), leaves at −z0/w.
        let Some(s1) = z1_at_t else {
            return Some((unknown, unknown));
        };
        if sz < pmin || s1 < 0 {
            return None;
        }
        let a = if sz <= pmax {
            zero
        } else {
            quotient(d(sz, pmax), d(vsp, vz))
        };
        let b = match z0_at_t {
            Some(x) if x >= 0 => whole,
            Some(_) => quotient(d(sz, pmin), d(vsp, vz)),
            None => unknown,
        };
        Some((a, b))
    }
}

/// Paper A §III step 1: the window [a, b] ⊆ [0, T] of the slab, as an outer enclosure
/// (a rounded down, b rounded up); `None` when there is certainly no such time.
#[inline]
pub fn slab_window(t: f64, sz: f64, vz: f64, pmin: f64, pmax: f64, vsp: f64) -> Option<(f64, f64)> {
    slab_window_balls(t, sz, vz, pmin, pmax, vsp).map(|(a, b)| (a.lo().max(0.0), b.hi().min(t)))
}

/// Are all vertex velocities equal (a statically shaped polygon, §II.F)?
#[inline]
pub fn statically_shaped<V: VertexSeq + ?Sized>(vels: &V) -> bool {
    let n = vels.count();
    if n == 0 {
        return true;
    }
    let v0 = vels.vertex(0);
    (1..n).all(|i| pr::same_velocity(vels.vertex(i), v0))
}

/// Paper A §II.F and §III: the detector that decides a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// §II.H, statically shaped polygon.
    DetectSame2d,
    /// §II.I, warping polygon.
    DetectDiff2d,
    /// §III, with a slab.
    Detect3d,
}

impl Method {
    /// The paper's name in snake case.
    pub fn name(self) -> &'static str {
        match self {
            Method::DetectSame2d => "detect_same_2d",
            Method::DetectDiff2d => "detect_diff_2d",
            Method::Detect3d => "detect_3d",
        }
    }
}

/// Paper A §II.F and §III: the detector for a case. detect_3D when the point has a
/// height and the polygon a slab (`vertical`), else detect_same_2D when every vertex
/// velocity is the same ([`statically_shaped`]), else detect_diff_2D. The one place the
/// choice is made: `api` and [`detect_3d`] (for its 2D part) both ask here.
pub fn dispatch<V: VertexSeq + ?Sized>(vertical: bool, vels: &V) -> Method {
    if vertical {
        Method::Detect3d
    } else if statically_shaped(vels) {
        Method::DetectSame2d
    } else {
        Method::DetectDiff2d
    }
}

/// Paper A §III detect_3D: 2D detection (detect_same_2D when all vertex velocities are
/// equal, detect_diff_2D otherwise) from s + a·v and P + a·V over the lookahead b − a,
/// where [a, b] is the slab window of [`slab_window_balls`]. Certified.
#[inline]
pub fn detect_3d<P, V>(
    t: f64,
    s: Vect2,
    v: Vect2,
    sz: f64,
    vz: f64,
    p: &P,
    vels: &V,
    pmin: f64,
    pmax: f64,
    vsp: f64,
    buff: f64,
    f: f64,
) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_3d_tri(t, s, v, sz, vz, p, vels, pmin, pmax, vsp, buff, f).or_true()
}

/// Paper A §III detect_3D, three-valued (see [`detect_3d`]). The 2D detector runs over
/// the window [a, b] of the original motion, never on P + a·V formed in absolute
/// coordinates.
#[inline]
pub fn detect_3d_tri<P, V>(
    t: f64,
    s: Vect2,
    v: Vect2,
    sz: f64,
    vz: f64,
    p: &P,
    vels: &V,
    pmin: f64,
    pmax: f64,
    vsp: f64,
    buff: f64,
    f: f64,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    let Some((a, b)) = slab_window_balls(t, sz, vz, pmin, pmax, vsp) else {
        return Tri::No;
    };
    match dispatch(false, vels) {
        Method::DetectSame2d => same_window(a, b, s, v, p, vels, buff, true),
        _ => diff_window(a, b, s, v, p, vels, f, buff),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn v(x: f64, y: f64) -> Vect2 {
        Vect2::new(x, y)
    }

    /// The interval encloses [lb, ub] from outside, tightly (a few ulps).
    fn assert_encl(i: Interval, lb: f64, ub: f64) {
        let tight = |a: f64, b: f64| (a - b).abs() <= 1e-14 * (1.0 + b.abs());
        assert!(
            i.lb <= lb && i.ub >= ub && tight(i.lb, lb) && tight(i.ub, ub),
            "{i:?} does not tightly enclose [{lb}, {ub}]"
        );
    }

    /// The union of the two dot_nn_lin intervals, sampled, equals {t : f(t) ≥ 0}.
    fn check_union(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2) {
        let lo = dot_nn_lin(t, ww, vv, aa, bb, Sign::Neg);
        let hi = dot_nn_lin(t, ww, vv, aa, bb, Sign::Pos);
        for k in 0..=64 {
            let tk = t * k as f64 / 64.0;
            let fk = (ww + vv.scale(tk)).dot(aa + bb.scale(tk));
            let inside = |i: &Interval| i.lb <= tk && tk <= i.ub;
            // Skip samples within rounding of a root.
            if fk.abs() < 1e-9 {
                continue;
            }
            assert_eq!(
                fk >= 0.0,
                inside(&lo) || inside(&hi),
                "t = {tk}, f = {fk}, {lo:?} {hi:?}"
            );
        }
    }

    /// Paper A §II.I edge_detect accepts a crossing of the edge's line beyond the edge's
    /// end by an F-dependent stretch: for the bottom edge (0,0)-(2,0) of this warping
    /// triangle with F = 1/2, crossings up to x = 3 are detected and x = 3.1 is not
    /// (paper A in exact arithmetic, `polyguard detect --engine exact`, says the same),
    /// all of them far beyond BUFF = 0.01 from the polygon. The filter in front of
    /// edge_detect (swept_boxes_apart, margin 2F·L doubled) must keep the edge for every
    /// detected crossing: a mutant that shrinks the margin below 1 (the gap from the
    /// edge's box to x = 3) rejects it.
    #[test]
    fn the_sweep_filter_keeps_the_extended_edge() {
        let p = [v(0.0, 0.0), v(2.0, 0.0), v(1.0, 3.0)];
        // Warping (detect_diff_2d): the apex drifts up slowly, the bottom edge stays.
        let vels = [v(0.0, 0.0), v(0.0, 0.0), v(0.0, 1.0 / 64.0)];
        let (t, buff, vel) = (1.0, 0.01, v(0.0, 2.0));
        for (x, f, want) in [
            (2.4, 0.5, true),
            (2.9, 0.5, true),
            (3.0, 0.5, true),
            (3.1, 0.5, false),
            (3.5, 0.5, false),
            (2.0001, 1e-4, true),
            (2.01, 1e-4, false),
        ] {
            let s = v(x, -1.0);
            assert_eq!(
                detect_diff_2d(t, s, vel, &p[..], &vels[..], f, buff),
                want,
                "crossing y = 0 at x = {x}, F = {f}"
            );
        }
    }

    /// `decided_by` in the detect answer is [`Method::name`]: every method's name is one the
    /// answer's schema (docs/schema/detect-answer.schema.json) allows, and each method has
    /// its own.
    #[test]
    fn method_names_are_the_answer_schemas() {
        let schema = include_str!("../docs/schema/detect-answer.schema.json");
        let names =
            [Method::DetectSame2d, Method::DetectDiff2d, Method::Detect3d].map(Method::name);
        for n in names {
            assert!(
                !n.is_empty() && schema.contains(&format!("\"{n}\"")),
                "{n:?}"
            );
        }
        assert!(names[0] != names[1] && names[1] != names[2] && names[0] != names[2]);
    }

    /// Paper A §II.I at a window of one instant (T = 0): edge_detect accepts a point on
    /// the bottom edge's line up to (1 + F)·‖aa‖ = 1.5 from its midpoint (aa the half
    /// edge): x = 2.5, on the boundary, included; far outside the polygon's BUFF, so
    /// detect_diff_2D says yes there (or leaves the boundary to exact arithmetic) and no
    /// beyond. Every set the edge test forms is the single time 0, or empty.
    #[test]
    fn a_window_of_one_instant_is_walked() {
        // A thin bar (its short sides reach 0.05 beyond the corners), warping slowly.
        let p = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 0.2), v(0.0, 0.2)];
        let vels = [
            v(0.0, 0.0),
            v(0.0, 0.0),
            v(0.0, 1.0 / 64.0),
            v(0.0, 1.0 / 64.0),
        ];
        let at =
            |x: f64| detect_diff_2d_tri(0.0, v(x, 0.0), v(0.0, 2.0), &p[..], &vels[..], 0.5, 0.01);
        assert_eq!(at(2.4), Tri::Yes);
        // on the boundary: a yes, or undecided (then the exact fallback decides), never a no
        assert_ne!(at(2.5), Tri::No);
        assert_eq!(at(2.6), Tri::No);
        assert_eq!(at(3.5), Tri::No);
    }

    /// The sweep filter's contract (§II.I, in front of edge_detect): when
    /// [`swept_boxes_apart`] says the boxes swept over [t0, t1] are apart and
    /// [`never_collapses`] says the edge keeps a length (the filter as edge_detect applies
    /// it), paper A's edge_detect over that window (in exact arithmetic) accepts no time.
    /// Checked on points passing near edges (across and beyond their ends, within a few
    /// F·‖edge‖), moving and warping, from t0 = 0 or later, and on edges that grow or
    /// shrink many times over the window, where a margin too small would filter an edge
    /// that paper A accepts. And the filter is as sharp as documented.
    mod sweep_filter_contract {
        use super::root_bounds_contract::exact;
        use super::*;
        use polyguard_oracle::{detect as od, Arith, Decided, Exact, V2};
        use proptest::prelude::*;

        /// Paper A's edge_detect over [t0, t1], exactly: the scene moved to t0.
        #[allow(clippy::too_many_arguments)]
        fn paper(
            t0: f64,
            t1: f64,
            s: Vect2,
            v: Vect2,
            pi: Vect2,
            pj: Vect2,
            vi: Vect2,
            vj: Vect2,
            f: f64,
        ) -> bool {
            let t = exact(t0);
            let at = |p: Vect2, w: Vect2| {
                V2::new(
                    exact(p.x).plus(&t.times(&exact(w.x))),
                    exact(p.y).plus(&t.times(&exact(w.y))),
                )
            };
            let q = |p: Vect2| V2::new(exact(p.x), exact(p.y));
            od::edge_detect(
                &Exact,
                &exact(t1).minus(&t),
                &at(s, v),
                &q(v),
                &at(pi, vi),
                &at(pj, vj),
                &q(vi),
                &q(vj),
                &exact(f),
            )
            .decided()
        }

        /// The filter as edge_detect applies it: the swept boxes apart, and the edge never
        /// collapses in the window (where it does, paper A accepts wherever the point is).
        fn filtered(w: &Sweep, pi: Vect2, pj: Vect2, vi: Vect2, vj: Vect2, f: f64) -> bool {
            swept_boxes_apart(w, pi, pj, vi, vj, f) && never_collapses(w.t0, w.t1, pi, pj, vi, vj)
        }

        /// The contract on one scene: if the filter drops the edge over [t0, t1], paper A
        /// accepts no time there.
        #[allow(clippy::too_many_arguments)]
        fn contract_holds(
            t0: f64,
            t1: f64,
            s: Vect2,
            v: Vect2,
            pi: Vect2,
            pj: Vect2,
            vi: Vect2,
            vj: Vect2,
            f: f64,
        ) -> Result<(), TestCaseError> {
            if filtered(&Sweep::new(t0, t1, s, v), pi, pj, vi, vj, f) {
                prop_assert!(
                    !paper(t0, t1, s, v, pi, pj, vi, vj, f),
                    "filtered, but paper A accepts: window [{}, {}], s {:?} v {:?}, edge {:?} {:?} moving {:?} {:?}, F {}",
                    t0, t1, s, v, pi, pj, vi, vj, f
                );
            }
            Ok(())
        }

        /// An edge, a window, and a point near the edge at some time of the window.
        #[allow(clippy::type_complexity)]
        fn scene(
        ) -> impl Strategy<Value = (f64, f64, Vect2, Vect2, Vect2, Vect2, Vect2, Vect2, f64)>
        {
            let small = || (-4i32..=4).prop_map(|k| k as f64 / 2.0);
            let vec = move || (small(), small()).prop_map(|(x, y)| v(x, y));
            // velocities zero half of the time, slow otherwise: swept boxes that stay small
            let vel = move || prop_oneof![Just(v(0.0, 0.0)), vec().prop_map(|w| w.scale(0.125))];
            (
                (vec(), vec(), vel(), vel(), vel()),
                (
                    prop_oneof![Just(0.0), 0.0..2.0f64],
                    0.25..3.0f64,
                    0.0..1.0f64,
                ),
                (
                    -0.8..1.8f64,
                    -2.0..2.0f64,
                    prop_oneof![Just(0.125), Just(0.25), Just(0.5)],
                ),
            )
                .prop_map(
                    |((pi, pj, vi, vj, v), (t0, len, at), (along, across, f))| {
                        let t1 = t0 + len;
                        let tc = t0 + at * len;
                        let (a, b) = (pi.at(vi, tc), pj.at(vj, tc));
                        let e = b - a;
                        let n = e.perp();
                        // a point `along` the edge (0 and 1 its ends) and `across` it, in units
                        // of F·‖e‖ (paper A reaches about 1 across and F beyond the ends)
                        let p = a + e.scale(along) + n.scale(across * f);
                        (t0, t1, p - v.scale(tc), v, pi, pj, vi, vj, f)
                    },
                )
        }

        /// An edge that grows or shrinks many times over the window (its length at one end
        /// of the window a small part of its length at the other), straddling the origin or
        /// not, axis-parallel or diagonal, from length 1 to 2¹², with F up to 0.9; and a
        /// point near it (beyond its ends or across it) at a time near the window's end
        /// where the edge is long. The margin is L = the longer of the edge's two ends; a
        /// margin taken from the wrong end, or from a wrong norm or factor, is smaller
        /// than paper A's reach there. With `growth` below −1 the edge shrinks through zero
        /// inside the window: paper A accepts at that instant wherever the point is, so
        /// the filter must not claim the edge never collapses.
        #[allow(clippy::type_complexity)]
        fn stretching_scene(
            growth: std::ops::Range<f64>,
        ) -> impl Strategy<Value = (f64, f64, Vect2, Vect2, Vect2, Vect2, Vect2, Vect2, f64)>
        {
            let angle = prop_oneof![
                Just(0.0),
                Just(std::f64::consts::FRAC_PI_2),
                Just(std::f64::consts::FRAC_PI_4),
                Just(3.0 * std::f64::consts::FRAC_PI_4),
                0.0..std::f64::consts::TAU,
            ];
            let centre = prop_oneof![Just(0.0), -0.02..0.02f64, -1.0..1.0f64];
            (
                (0i32..=12, angle, (centre.clone(), centre), growth),
                (
                    prop_oneof![Just(0.0), 0.0..2.0f64],
                    0.25..3.0f64,
                    prop_oneof![Just(0.0), Just(1.0), 0.0..1.0f64],
                ),
                (
                    prop_oneof![-0.9..0.1f64, 0.9..1.9f64, 0.0..1.0f64],
                    -1.5..1.5f64,
                    prop_oneof![Just(0.125), Just(0.5), Just(0.75), Just(0.9)],
                    (-1.0..1.0f64, -1.0..1.0f64),
                ),
            )
                .prop_map(
                    |((k, th, (cx, cy), g), (t0, len, at), (along, across, f, (ux, uy)))| {
                        let l = 2f64.powi(k);
                        let h = v(th.cos(), th.sin()).scale(l / 2.0);
                        let c = v(cx, cy).scale(l);
                        // e(t) = 2h·(1 + g·(t − t0)/len): ends moving apart (g > 0) or together
                        let (vi, vj) = (h.scale(-g / len), h.scale(g / len));
                        let (pi, pj) = ((c - h) - vi.scale(t0), (c + h) - vj.scale(t0));
                        let t1 = t0 + len;
                        // the time the point is placed: where the edge is long, mostly
                        let at = if g > 0.0 { 1.0 - 0.2 * at } else { 0.2 * at };
                        let tc = t0 + at * len;
                        let (a, b) = (pi.at(vi, tc), pj.at(vj, tc));
                        let e = b - a;
                        let p = a + e.scale(along) + e.perp().scale(across * f);
                        let u = v(ux, uy).scale(l / len);
                        (t0, t1, p - u.scale(tc), u, pi, pj, vi, vj, f)
                    },
                )
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(16384))]

            #[test]
            fn the_filter_keeps_a_stretching_edge_paper_a_accepts(
                (t0, t1, s, v, pi, pj, vi, vj, f) in stretching_scene(-0.95..6.0)
            ) {
                prop_assume!(pi != pj);
                contract_holds(t0, t1, s, v, pi, pj, vi, vj, f)?;
            }

            /// The filter is as sharp as documented: a still point beyond the edge's swept
            /// box by 1 % more than 4F·L (the margin 2F·L, L the longer ‖edge‖₁ of the
            /// window's ends, doubled by `ranges_apart` to absorb the gap's rounding) is
            /// filtered. A wider margin would still be safe, only slower; this checks the
            /// filter does the work it claims.
            #[test]
            fn the_filter_fires_just_beyond_its_margin(
                (pi, pj, vi, vj) in (
                    (-8i32..=8, -8i32..=8), (-8i32..=8, -8i32..=8),
                    (-4i32..=4, -4i32..=4), (-4i32..=4, -4i32..=4),
                ).prop_map(|(a, b, c, d)| {
                    let h = |(x, y): (i32, i32), k: f64| v(x as f64 * k, y as f64 * k);
                    (h(a, 0.5), h(b, 0.5), h(c, 0.125), h(d, 0.125))
                }),
                (t0, len) in (prop_oneof![Just(0.0), Just(1.0)], prop_oneof![Just(1.0), Just(2.0)]),
                f in prop_oneof![Just(0.125), Just(0.25), Just(0.5), Just(0.9)],
                (side, y) in (0usize..4, 0.0..1.0f64),
            ) {
                prop_assume!(pi != pj);
                let t1 = t0 + len;
                let ends = [pi.at(vi, t0), pj.at(vj, t0), pi.at(vi, t1), pj.at(vj, t1)];
                let l1 = |a: Vect2, b: Vect2| (b.x - a.x).abs() + (b.y - a.y).abs();
                let l = fmax(l1(ends[0], ends[1]), l1(ends[2], ends[3]));
                let gap = 1.01 * 4.0 * f * l;
                let (lo, hi) = ends.iter().fold((ends[0], ends[0]), |(lo, hi), e| {
                    (v(fmin(lo.x, e.x), fmin(lo.y, e.y)), v(fmax(hi.x, e.x), fmax(hi.y, e.y)))
                });
                let (across_x, across_y) = (lo.x + y * (hi.x - lo.x), lo.y + y * (hi.y - lo.y));
                let s = match side {
                    0 => v(hi.x + gap, across_y),
                    1 => v(lo.x - gap, across_y),
                    2 => v(across_x, hi.y + gap),
                    _ => v(across_x, lo.y - gap),
                };
                let w = Sweep::new(t0, t1, s, v(0.0, 0.0));
                prop_assert!(
                    swept_boxes_apart(&w, pi, pj, vi, vj, f),
                    "not filtered at 1.01·4F·L beyond the box: s {:?}, edge {:?} {:?} moving {:?} {:?}, F {}",
                    s, pi, pj, vi, vj, f
                );
            }

            #[test]
            fn the_filter_drops_no_edge_paper_a_accepts(
                (t0, t1, s, v, pi, pj, vi, vj, f) in scene()
            ) {
                prop_assume!(pi != pj);
                contract_holds(t0, t1, s, v, pi, pj, vi, vj, f)?;
            }
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(256))]

            /// An edge that shrinks through zero inside the window (paper A accepts there,
            /// wherever the point is) is never filtered; 256 cases, each slow in exact
            /// arithmetic at the collapse.
            #[test]
            fn the_filter_keeps_a_collapsing_edge(
                (t0, t1, s, v, pi, pj, vi, vj, f) in stretching_scene(-3.0..-1.0)
            ) {
                prop_assume!(pi != pj);
                contract_holds(t0, t1, s, v, pi, pj, vi, vj, f)?;
            }
        }

        /// The filter does fire in that space (or the test above would test nothing):
        /// a point far beyond an edge's end is filtered, one within F·‖edge‖ across it
        /// (which paper A accepts) is not.
        #[test]
        fn the_filter_fires_far_from_the_edge() {
            let still = v(0.0, 0.0);
            let (pi, pj, f) = (v(0.0, 0.0), v(2.0, 0.0), 0.25);
            let w = Sweep::new(0.0, 1.0, v(10.0, 0.5), still);
            assert!(swept_boxes_apart(&w, pi, pj, still, still, f));
            let near = v(1.0, 0.25);
            assert!(paper(0.0, 1.0, near, still, pi, pj, still, still, f));
            let w = Sweep::new(0.0, 1.0, near, still);
            assert!(!swept_boxes_apart(&w, pi, pj, still, still, f));
        }
    }

    /// §II.I dot_nn_lin when vv = 0: (ww)·(aa + t·bb) is a line, its t² coefficient an
    /// exact 0 (not a ball of radius ETA, which would make it a parabola with a second
    /// root near |b|/ETA). Here the line is 2⁻⁷⁰·(5 − t), over a window reaching 2¹⁰⁰⁰:
    /// the set where it is ≥ 0 is [0, 5], and no time near 2⁹⁹⁵, where the line is about
    /// −2⁹²⁵, may be in either interval.
    #[test]
    fn a_line_stays_a_line_over_a_long_window() {
        let k = 2f64.powi(-35);
        let (ww, vv, aa, bb) = (v(k, 0.0), v(0.0, 0.0), v(5.0 * k, 0.0), v(-k, 0.0));
        let t = 2f64.powi(1000);
        let neg = dot_nn_lin(t, ww, vv, aa, bb, Sign::Neg);
        let pos = dot_nn_lin(t, ww, vv, aa, bb, Sign::Pos);
        assert!(
            neg.lb <= 0.0 && neg.ub >= 5.0 && neg.ub < 5.0 + 1e-9,
            "{neg:?}"
        );
        assert!(pos.is_empty(), "{pos:?}");
    }

    #[test]
    fn dot_nn_lin_cases() {
        // A = 0, B = 0: f = C.
        check_union(2.0, v(1.0, 0.0), v(0.0, 0.0), v(1.0, 0.0), v(0.0, 0.0)); // C = 1
        assert!(dot_nn_lin(
            2.0,
            v(-1.0, 0.0),
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(0.0, 0.0),
            Sign::Pos
        )
        .is_empty());
        // A = 0, B > 0: f = t − 1 ≥ 0 on [1, 2].
        let i = dot_nn_lin(
            2.0,
            v(-1.0, 0.0),
            v(1.0, 0.0),
            v(1.0, 0.0),
            v(0.0, 0.0),
            Sign::Pos,
        );
        assert_encl(i, 1.0, 2.0);
        // A = 0, B < 0: f = 1 − t ≥ 0 on [0, 1].
        let i = dot_nn_lin(
            2.0,
            v(1.0, 0.0),
            v(-1.0, 0.0),
            v(1.0, 0.0),
            v(0.0, 0.0),
            Sign::Neg,
        );
        assert_encl(i, 0.0, 1.0);
        // A > 0, two roots: (t − 1)(t − 3) = t² − 4t + 3 with ww = (−1,0), vv = (1,0),
        // aa = (−3,0), bb = (1,0): f = (t − 1)(t − 3).
        let (ww, vv, aa, bb) = (v(-1.0, 0.0), v(1.0, 0.0), v(-3.0, 0.0), v(1.0, 0.0));
        assert_encl(dot_nn_lin(4.0, ww, vv, aa, bb, Sign::Neg), 0.0, 1.0);
        assert_encl(dot_nn_lin(4.0, ww, vv, aa, bb, Sign::Pos), 3.0, 4.0);
        check_union(4.0, ww, vv, aa, bb);
        // A < 0: −(t − 1)(t − 3) ≥ 0 between the roots.
        let aa2 = v(3.0, 0.0);
        let bb2 = v(-1.0, 0.0);
        assert_encl(dot_nn_lin(4.0, ww, vv, aa2, bb2, Sign::Pos), 1.0, 3.0);
        assert!(dot_nn_lin(4.0, ww, vv, aa2, bb2, Sign::Neg).is_empty());
        // A < 0, double root: −(t − 2)², ww = (−2,0), vv = (1,0), aa = (2,0), bb = (−1,0).
        let i = dot_nn_lin(
            4.0,
            v(-2.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 0.0),
            v(-1.0, 0.0),
            Sign::Pos,
        );
        // A double root: its enclosure widens to about √u of the coefficients' scale
        // (the discriminant, 0, is known to ±u·B²), around the exact time 2.
        assert!(i.lb <= 2.0 && i.ub >= 2.0 && i.ub - i.lb < 1e-6, "{i:?}");
        // A > 0, double root: (t − 2)² ≥ 0 everywhere.
        let i = dot_nn_lin(
            4.0,
            v(-2.0, 0.0),
            v(1.0, 0.0),
            v(-2.0, 0.0),
            v(1.0, 0.0),
            Sign::Pos,
        );
        assert_encl(i, 0.0, 4.0);
    }

    /// Found by paper_a_functions_vs_oracle: (ww + t·vv)·(aa + t·bb) = −1/16 for all t (ww·bb = 0
    /// exactly, but its ball has a tiny radius, so the line's slope is a tiny float and
    /// −c/b overflows). Rounding +∞ down gave NaN, and the set became everything.
    #[test]
    fn overflowing_linear_root_is_clamped() {
        let (ww, vv, aa, bb) = (v(0.25, 0.0), v(0.0, 0.0), v(-0.25, 0.0), v(0.0, -0.25));
        for s in Sign::BOTH {
            assert!(dot_nn_lin(0.125, ww, vv, aa, bb, s).is_empty(), "{s:?}");
        }
    }

    #[test]
    fn tiny_leading_coefficient_is_not_zero() {
        // f(t) = 1e-9·(t − 1)(t − 1000): A = 1e-9 (PolyCARP would call it a line,
        // B·t + C = −1.001e-6·t + 1e-6, losing the root at 1000). Over T = 2000, f ≥ 0 on
        // [0, 1] ∪ [1000, 2000].
        let (ww, vv, aa, bb) = (v(-1.0, 0.0), v(1.0, 0.0), v(-1000e-9, 0.0), v(1e-9, 0.0));
        let lo = dot_nn_lin(2000.0, ww, vv, aa, bb, Sign::Neg);
        let hi = dot_nn_lin(2000.0, ww, vv, aa, bb, Sign::Pos);
        assert!((lo.ub - 1.0).abs() < 1e-12 && lo.lb == 0.0);
        assert!((hi.lb - 1000.0).abs() < 1e-9 && hi.ub == 2000.0);
    }

    /// Paper A Figure 2: a warping edge met twice. A(t) = (−2, 0) fixed, B(t) = (2, 2 − 2t),
    /// s(t) = (t, 7/4 − 7t/4). cross(B − A, s − A) = 2t² − 5t + 3 = 2(t − 1)(t − 3/2):
    /// the point is on the segment at t = 1 (s = (1, 0), B = (2, 0)) and at t = 3/2
    /// (s = (3/2, −7/8) on the segment to B = (2, −1)), on the other side in between.
    #[test]
    fn warping_edge_met_twice() {
        let (a, va) = (v(-2.0, 0.0), v(0.0, 0.0));
        let (b, vb) = (v(2.0, 2.0), v(0.0, -2.0));
        let (s, vs) = (v(0.0, 1.75), v(1.0, -1.75));
        let f = 1e-4;
        assert!(edge_detect(1.2, s, vs, a, b, va, vb, f));
        assert!(!edge_detect(0.9, s, vs, a, b, va, vb, f));
        // From t0 = 1.1 (between the crossings) only the second crossing can be found.
        let t0 = 1.1;
        let (s1, a1, b1) = (s.at(vs, t0), a.at(va, t0), b.at(vb, t0));
        assert!(!edge_detect(0.3, s1, vs, a1, b1, va, vb, f));
        assert!(edge_detect(0.5, s1, vs, a1, b1, va, vb, f));
        // Either crossing alone is found in a window around it.
        assert!(edge_detect(
            0.2,
            s.at(vs, 0.9),
            vs,
            a.at(va, 0.9),
            b.at(vb, 0.9),
            va,
            vb,
            f
        ));
    }

    #[test]
    fn detect_diff_and_same_agree_on_a_translating_square() {
        // A unit-speed square moving right; a point moving up through its path.
        let sq = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)];
        let vel_same = [v(1.0, 0.0); 4];
        let s = v(5.0, -3.0);
        let vs = v(0.0, 1.0);
        // At t = 4 the square spans x ∈ [4, 6], y ∈ [0, 2] and s = (5, 1): inside.
        for (t, expect) in [(10.0, true), (2.5, false)] {
            assert_eq!(
                detect_same_2d(t, s, vs, &sq[..], &vel_same[..], 0.01),
                expect,
                "T={t}"
            );
            assert_eq!(
                detect_diff_2d(t, s, vs, &sq[..], &vel_same[..], 1e-4, 0.01),
                expect,
                "T={t}"
            );
        }
    }

    #[test]
    fn slab_window_cases() {
        // Level flight inside the slab: whole lookahead.
        assert_eq!(
            slab_window(10.0, 5.0, 0.0, 0.0, 10.0, 0.0),
            Some((0.0, 10.0))
        );
        // Above the slab, level: never.
        assert_eq!(slab_window(10.0, 15.0, 0.0, 0.0, 10.0, 0.0), None);
        // Climbing from −4 at 2 per unit: enters at 2, leaves at 7.
        assert_eq!(
            slab_window(10.0, -4.0, 2.0, 0.0, 10.0, 0.0),
            Some((2.0, 7.0))
        );
        // Descending from 14 at −2: enters at 2, leaves at 7; lookahead 5 clips it.
        assert_eq!(
            slab_window(5.0, 14.0, -2.0, 0.0, 10.0, 0.0),
            Some((2.0, 5.0))
        );
        // The slab rises with the point: relative speed 0.
        assert_eq!(slab_window(5.0, 1.0, 3.0, 0.0, 10.0, 3.0), Some((0.0, 5.0)));
        // Touching only at t = T exactly: a one-instant window.
        assert_eq!(
            slab_window(2.0, -4.0, 2.0, 0.0, 10.0, 0.0),
            Some((2.0, 2.0))
        );
        assert_eq!(slab_window(1.5, -4.0, 2.0, 0.0, 10.0, 0.0), None);
    }

    /// §III step 1 among subnormals (the campaign's shard 7/100 of seed 1): the point
    /// sinks from −142 units of 2⁻¹⁰⁷⁴ at 4 units per unit time toward a slab whose top
    /// is at −607 units, reaching it at t = 465/4 = 116.25. Within T = 100 there is no
    /// window (z1 − T·w is −65 units); within T = 200 the window is [116.25, 200]. (The static bound's ETA exceeds
    /// those 65 units, so only the exact sum, scaled out of the subnormals, can tell.)
    #[test]
    fn a_subnormal_slab_window_is_decided() {
        let unit = f64::from_bits(1);
        let (sz, vz, pmin, pmax) = (-142.0 * unit, -4.0 * unit, -6072.0 * unit, -607.0 * unit);
        assert_eq!(slab_window_balls(100.0, sz, vz, pmin, pmax, 0.0), None);
        let (a, b) = slab_window(200.0, sz, vz, pmin, pmax, 0.0).expect("a window");
        // the entry, a quotient of subnormals, is enclosed from below within an ulp or two
        assert!(
            a <= 116.25 && 116.25 - a < 1e-12 && b == 200.0,
            "[{a}, {b}]"
        );
        // the same, climbing
        assert_eq!(slab_window_balls(100.0, -sz, -vz, -pmax, -pmin, 0.0), None);
        let (a, b) = slab_window(200.0, -sz, -vz, -pmax, -pmin, 0.0).expect("a window");
        // the entry, a quotient of subnormals, is enclosed from below within an ulp or two
        assert!(
            a <= 116.25 && 116.25 - a < 1e-12 && b == 200.0,
            "[{a}, {b}]"
        );
    }

    /// §III step 1 with a height difference that is not a float: from 2⁻⁶⁰ below the
    /// slab [1, 2] (pmin − sz = 1 − 2⁻⁶⁰ rounds to 1) climbing at 1, the point enters at
    /// 1 − 2⁻⁶⁰ and leaves at 2 − 2⁻⁶⁰. The balls must hold those ends: the exact quotient
    /// of the rounded differences (1/1) is not the entry, and a rounded quotient is not
    /// an exact end.
    #[test]
    fn an_inexact_height_difference_is_not_claimed_exact() {
        let tiny = 2f64.powi(-60);
        for (sz, vz, pmin, pmax) in [(tiny, 1.0, 1.0, 2.0), (-tiny, -1.0, -2.0, -1.0)] {
            let (a, b) = slab_window_balls(10.0, sz, vz, pmin, pmax, 0.0).expect("a window");
            // 1 − 2⁻⁶⁰ lies strictly between the floats 1 − 2⁻⁵³ and 1; 2 − 2⁻⁶⁰ below 2
            assert!(
                a.lo() < 1.0 && a.hi() >= 1.0 - 2f64.powi(-53),
                "entry {a:?}"
            );
            assert!(b.lo() < 2.0 && b.hi() >= 2.0, "exit {b:?}");
        }
    }

    /// A point resting on the slab's floor or ceiling (no vertical speed relative to the
    /// slab): in the slab the whole time, the window exactly [0, T].
    #[test]
    fn a_point_resting_on_the_slab_floor_is_decided() {
        let (a, b) = slab_window_balls(3.0, 0.0, 0.0, 0.0, 1.0, 0.0).expect("a window");
        assert_eq!((a, b), (Ball::exact(0.0), Ball::exact(3.0)));
        let (a, b) = slab_window_balls(3.0, 1.0, 0.5, 0.0, 1.0, 0.5).expect("a window");
        assert_eq!((a, b), (Ball::exact(0.0), Ball::exact(3.0)));
    }

    /// When the comparisons of §III step 1 cannot be decided (here T·w overflows), the
    /// window's balls still enclose its ends: the outer window [a.lo, b.hi] holds the
    /// true one, and the inner window [a.hi, b.lo] (times in the window whatever the
    /// exact ends) lies inside it. Claiming the whole [0, T] exactly would let the 2D
    /// detector certify a contact after the point has left the slab.
    #[test]
    fn an_undecided_slab_window_claims_nothing() {
        // From height 0 at ±1e300 per unit, the slab [−1, 1] is left at t = 1e-300.
        for vz in [1e300, -1e300] {
            let (a, b) = slab_window_balls(1e300, 0.0, vz, -1.0, 1.0, 0.0).expect("a window");
            assert!(
                a.lo() <= 0.0 && b.hi() >= 1e-300,
                "outer [{}, {}]",
                a.lo(),
                b.hi()
            );
            assert!(
                a.hi() > b.lo() || (a.hi() >= 0.0 && b.lo() <= 1e-300),
                "inner [{}, {}] outside [0, 1e-300]",
                a.hi(),
                b.lo()
            );
        }
    }

    /// Exact checks of [`slab_window_balls`]' contract (§III step 1) at every scale, from
    /// subnormals to 2¹⁰⁰⁰: with W the exact set of t ∈ [0, T] where the height lies in
    /// the slab, `None` only when W is empty; otherwise the outer window [a.lo, b.hi]
    /// holds W and the inner window [a.hi, b.lo], when not empty, lies in W.
    mod slab_window_contract {
        use super::root_bounds_contract::{exact, float};
        use super::*;
        use polyguard_oracle::{Arith, ExactField, Q};
        use proptest::prelude::*;

        /// W = [lo, hi] exactly, or None when empty.
        fn exact_window(
            t: f64,
            sz: f64,
            vz: f64,
            pmin: f64,
            pmax: f64,
            vsp: f64,
        ) -> Option<(Q, Q)> {
            let (t, sz) = (exact(t), exact(sz));
            let w = exact(vz).minus(&exact(vsp));
            let z0 = sz.minus(&exact(pmin)); // z0 + t·w ≥ 0
            let z1 = exact(pmax).minus(&sz); // z1 − t·w ≥ 0
            let (mut lo, mut hi) = (Q::zero(), t);
            if w.is_zero_() {
                if z0.is_neg() || z1.is_neg() {
                    return None;
                }
            } else {
                let from0 = z0.negated().quotient(&w).expect("w ≠ 0"); // −z0/w
                let from1 = z1.quotient(&w).expect("w ≠ 0"); // z1/w
                let (enter, leave) = if w.is_pos() {
                    (from0, from1)
                } else {
                    (from1, from0)
                };
                lo = lo.max(enter);
                hi = hi.min(leave);
            }
            (lo <= hi).then_some((lo, hi))
        }

        fn breach(t: f64, sz: f64, vz: f64, pmin: f64, pmax: f64, vsp: f64) -> Option<String> {
            let got = slab_window_balls(t, sz, vz, pmin, pmax, vsp);
            let want = exact_window(t, sz, vz, pmin, pmax, vsp);
            match (got, want) {
                (None, None) => None,
                (None, Some((lo, hi))) => Some(format!("None, but W = [{lo}, {hi}]")),
                (Some((a, b)), want) => {
                    let (al, ah, bl, bh) = (a.lo(), a.hi(), b.lo(), b.hi());
                    if [al, ah, bl, bh].iter().any(|x| x.is_nan()) {
                        return Some(format!("NaN in {a:?}, {b:?}"));
                    }
                    let q = |x: f64| {
                        if x.is_finite() {
                            exact(x)
                        } else if x > 0.0 {
                            exact(f64::MAX).twice()
                        } else {
                            exact(f64::MAX).twice().negated()
                        }
                    };
                    let inner = (ah <= bl).then(|| (q(ah), q(bl)));
                    match (want, inner) {
                        (None, Some((il, ih))) => {
                            Some(format!("W is empty, but the inner window is [{il}, {ih}]"))
                        }
                        (Some((lo, hi)), inner) => {
                            if q(al) > lo || q(bh) < hi {
                                return Some(format!(
                                    "outer [{al:e}, {bh:e}] misses W = [{lo}, {hi}]"
                                ));
                            }
                            match inner {
                                Some((il, ih)) if il < lo || ih > hi => {
                                    Some(format!("inner [{ah:e}, {bl:e}] leaves W = [{lo}, {hi}]"))
                                }
                                _ => None,
                            }
                        }
                        (None, None) => None,
                    }
                }
            }
        }

        /// A height or speed at scale 2^e: zero one time in six, else ±m·2^(e + k), k small.
        fn at_scale(e: i32) -> impl Strategy<Value = f64> {
            prop_oneof![
                1 => Just(0.0),
                5 => (any::<bool>(), 1.0..2.0f64, -12..12i32)
                    .prop_map(move |(n, m, k)| float(n, m, (e + k).clamp(-1074, 1000))),
            ]
        }

        /// Heights and speeds at one scale (subnormal, small, unit, large, near overflow),
        /// the lookahead from 2⁻²⁰ to 2⁶⁰; the slab's ends sorted.
        fn slab() -> impl Strategy<Value = (f64, f64, f64, f64, f64, f64)> {
            (
                prop_oneof![
                    Just(-1074),
                    Just(-1060),
                    Just(-1040),
                    Just(-600),
                    Just(0),
                    Just(600),
                    Just(980)
                ],
                (1.0..2.0f64, -20..60i32),
            )
                .prop_flat_map(|(e, (tm, te))| {
                    (
                        Just(float(false, tm, te)),
                        at_scale(e),
                        at_scale(e),
                        at_scale(e),
                        at_scale(e),
                        at_scale(e),
                    )
                })
                .prop_map(|(t, sz, vz, p1, p2, vsp)| (t, sz, vz, p1.min(p2), p1.max(p2), vsp))
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(2048))]

            #[test]
            fn the_window_balls_enclose_the_exact_window((t, sz, vz, pmin, pmax, vsp) in slab()) {
                prop_assume!([t, sz, vz, pmin, pmax, vsp].iter().all(|x| x.is_finite()));
                if let Some(why) = breach(t, sz, vz, pmin, pmax, vsp) {
                    prop_assert!(
                        false,
                        "T {t:e}, sz {sz:e}, vz {vz:e}, slab [{pmin:e}, {pmax:e}], vsp {vsp:e}: {why}"
                    );
                }
            }
        }

        /// The campaign's case itself, and the undecided one.
        #[test]
        fn the_known_cases_keep_the_contract() {
            let unit = f64::from_bits(1);
            let (sz, vz, pmin, pmax) = (-142.0 * unit, -4.0 * unit, -6072.0 * unit, -607.0 * unit);
            for t in [100.0, 116.25, 200.0] {
                assert_eq!(breach(t, sz, vz, pmin, pmax, 0.0), None, "T = {t}");
            }
            assert_eq!(breach(1e300, 0.0, 1e300, -1.0, 1.0, 0.0), None);
        }
    }

    #[test]
    fn detect_3d_needs_both_horizontal_and_vertical_overlap() {
        let sq = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)];
        let still = [v(0.0, 0.0); 4];
        // Horizontally the point (from (−3, 1), speed 1 in x) is over the square for
        // t ∈ [3, 5]. Vertically it descends from 20 at −2 into the slab [0, 10] at t = 5.
        let s = v(-3.0, 1.0);
        let vs = v(1.0, 0.0);
        assert!(detect_3d(
            10.0,
            s,
            vs,
            20.0,
            -2.0,
            &sq[..],
            &still[..],
            0.0,
            10.0,
            0.0,
            0.01,
            1e-4
        ));
        // Descending slower (−1): enters the slab at t = 10, long after leaving the square.
        assert!(!detect_3d(
            10.0,
            s,
            vs,
            20.0,
            -1.0,
            &sq[..],
            &still[..],
            0.0,
            10.0,
            0.0,
            0.01,
            1e-4
        ));
        // A one-instant slab window (T = 5, descending at −2) at the moment the point is at
        // the square's right edge x = 2: within BUFF of it, so detected (a boundary case
        // the paper's (T, 0) sentinel would mishandle only when b − a = 0 is empty).
        assert!(detect_3d(
            5.0,
            s,
            vs,
            20.0,
            -2.0,
            &sq[..],
            &still[..],
            0.0,
            10.0,
            0.0,
            0.01,
            1e-4
        ));
        // Warping polygon: the right side moves away, the point still enters.
        let warp = [v(0.0, 0.0), v(0.5, 0.0), v(0.5, 0.0), v(0.0, 0.0)];
        assert!(detect_3d(
            10.0,
            s,
            vs,
            20.0,
            -2.0,
            &sq[..],
            &warp[..],
            0.0,
            10.0,
            0.0,
            0.01,
            1e-4
        ));
    }

    /// A window of one instant (t = 1) at which the point lies exactly on the boundary
    /// of edge_detect_simp's perpendicular condition (|w × a| = F·‖a‖², the along one
    /// holding with room): paper A says yes, so the engine must not certify "no". The
    /// outer sets of the four quadratics then all shrink to the point [1, 1], and a
    /// meeting of one point is still a meeting (first_meeting's `lb > ub` is strict).
    #[test]
    fn a_one_instant_window_on_the_boundary_is_not_missed() {
        let e = BallV::exact;
        for side in [0.5, -0.5] {
            let tri = edge_detect_simp_tri(
                Ball::exact(1.0),
                Ball::exact(1.0),
                e(v(-0.5, side)),
                e(v(1.0, 0.0)),
                e(v(1.0, 0.0)),
                e(v(0.0, 0.0)),
                true,
                0.5,
            );
            assert_ne!(tri, Tri::No, "w(1) = (0.5, {side})");
        }
    }

    /// §II.I over a window whose ends are balls that overlap (ta, tb ∈ [0.75, 1.25]):
    /// for ta = 1.25 and tb = 0.75 the window is empty, so no answer may be a certain
    /// yes, even for a point sitting on the edge's midpoint all the time (every t meets
    /// inequalities (1)). Looking for a certain time in an empty inner window (a mutation
    /// survivor: `ilo <= ihi` → `>`) certified it.
    #[test]
    fn an_empty_inner_window_certifies_nothing() {
        let (zero, a) = (BallV::exact(v(0.0, 0.0)), BallV::exact(v(1.0, 0.0)));
        let over =
            |ta: Ball, tb: Ball| edge_detect_simp_tri(ta, tb, zero, zero, a, zero, true, 0.5);
        let end = Ball { z: 1.0, r: 0.25 };
        assert_ne!(over(end, end), Tri::Yes);
        // the same scene over a window that is certainly not empty: a certain yes
        assert_eq!(over(Ball::exact(0.5), Ball::exact(1.5)), Tri::Yes);
    }

    /// §II.I with F = 0: the perpendicular conditions |w × a| ≤ 0 hold only at the one
    /// instant t = 1 when the point crosses the edge's line (w = (−1 + t)·(0, 1) against
    /// a = (2, 0)), inside the edge (w·a = 0), so paper A says yes, and the engine must
    /// not settle the crossing's short meeting J as a certain no.
    #[test]
    fn a_one_point_crossing_is_not_settled_as_no() {
        let e = BallV::exact;
        let tri = edge_detect_simp_tri(
            Ball::exact(0.0),
            Ball::exact(2.0),
            e(v(0.0, -1.0)),
            e(v(0.0, 1.0)),
            e(v(2.0, 0.0)),
            e(v(0.0, 0.0)),
            true,
            0.0,
        );
        assert_ne!(tri, Tri::No);
        assert!(edge_detect_simp(
            2.0,
            v(0.0, -1.0),
            v(0.0, 1.0),
            v(2.0, 0.0),
            v(0.0, 0.0),
            0.0
        ));
    }

    /// Exact checks of [`root_bounds`]' contract: for float a ≠ 0, b, c with real roots
    /// and any ball `disc` that holds b² − 4ac, each enclosure holds its exact root.
    mod root_bounds_contract {
        use super::*;
        use polyguard_oracle::convert::q;
        use polyguard_oracle::{Arith, ExactField, Q};
        use proptest::prelude::*;
        use std::cmp::Ordering;

        pub(super) fn exact(x: f64) -> Q {
            q(x).expect("a finite float")
        }

        /// The order of x against the root (−b + s·√d)/(2a) (s = ±1, d ≥ 0), decided
        /// exactly: with y = 2a·x + b, x ≤ root ⇔ y ≤ s·√d when a > 0, ⇔ y ≥ s·√d when
        /// a < 0; y is compared with ±√d through its sign and y² against d.
        fn cmp_root(x: &Q, a: &Q, b: &Q, d: &Q, s: i8) -> Ordering {
            let y = a.twice().times(x).plus(b);
            // y against s·√d
            let y_vs = match (s > 0, y.sign()) {
                (true, Ordering::Less) => Ordering::Less,
                (true, _) => y.sq().cmp(d),
                (false, Ordering::Greater) => Ordering::Greater,
                (false, _) => d.cmp(&y.sq()),
            };
            if a.is_pos() {
                y_vs
            } else {
                y_vs.reverse()
            }
        }

        /// Some(reason) when the enclosures miss a root of a·t² + b·t + c.
        fn breach(a: f64, b: f64, c: f64, disc: Ball) -> Option<String> {
            let (qa, qb, qc) = (exact(a), exact(b), exact(c));
            let d = qb.sq().minus(&Q::from_i64(4).times(&qa).times(&qc));
            if d.is_neg() {
                return None;
            }
            let [r1, r2] = root_bounds(a, b, c, disc)?;
            // the smaller root takes −√d when a > 0, +√d when a < 0
            let small = if a > 0.0 { -1 } else { 1 };
            for (i, ((lo, hi), s)) in [(r1, small), (r2, -small)].into_iter().enumerate() {
                let below = cmp_root(&exact(lo), &qa, &qb, &d, s) == Ordering::Greater;
                let above = cmp_root(&exact(hi), &qa, &qb, &d, s) == Ordering::Less;
                if below || above || lo.is_nan() || hi.is_nan() {
                    return Some(format!("root {} not in [{lo:e}, {hi:e}]", i + 1));
                }
            }
            None
        }

        /// The discriminant ball float_set computes, with its radius raised to `k`
        /// times its own (k ≥ 1) or to |z|/m (m > 0: z/r = m, so m ≤ 4 leaves the fast
        /// path and m ≤ 1 reaches below 0), and its centre shifted by j·(the radius
        /// added)/2: a ball that holds b² − 4ac when the exact check says so (the
        /// caller skips it otherwise).
        fn disc_ball(a: f64, b: f64, c: f64, k: f64, m: f64, j: f64) -> Option<Ball> {
            let d = Ball::exact(b)
                .sq()
                .sub(Ball::exact(a).mul(Ball::exact(c)).scale(4.0));
            let r = if m > 0.0 {
                d.r.max(d.z.abs() / m)
            } else {
                ball::up(d.r * k + f64::MIN_POSITIVE)
            };
            let z = d.z + j * (r - d.r) * 0.5;
            let ball = Ball { z, r };
            let (qa, qb, qc) = (exact(a), exact(b), exact(c));
            let exact_d = qb.sq().minus(&Q::from_i64(4).times(&qa).times(&qc));
            let (lo, hi) = (exact(z).minus(&exact(r)), exact(z).plus(&exact(r)));
            (z.is_finite() && r.is_finite() && lo <= exact_d && exact_d <= hi).then_some(ball)
        }

        /// The roots over the disc, in floats (good to a few ulps), in the form
        /// root_bounds uses: q = −(b + sgn(b)·√d)/2, roots q/a and c/q, for d = max(0,
        /// disc.lo) and disc.hi (each is monotone in d, so these bound it over the disc;
        /// at d = b² − 4ac they are the roots).
        fn float_roots(a: f64, b: f64, c: f64, disc: Ball) -> [[f64; 2]; 2] {
            let roots = |d: f64| {
                let s = d.sqrt();
                let q = -0.5 * (b + if b >= 0.0 { s } else { -s });
                let (x1, x2) = (q / a, c / q);
                (x1.min(x2), x1.max(x2))
            };
            let (l, h) = (roots(disc.lo().max(0.0)), roots(disc.hi()));
            [[l.0, h.0], [l.1, h.1]]
        }

        /// Some(reason) when an enclosure is more than 6 times as wide as the roots'
        /// own spread over the disc, beyond rounding (the fast path of well separated
        /// roots is up to 4 times as wide: √d to r/s, and c/q doubles that).
        fn too_wide(a: f64, b: f64, c: f64, disc: Ball) -> Option<String> {
            let [r1, r2] = root_bounds(a, b, c, disc)?;
            let ideal = float_roots(a, b, c, disc);
            for (i, ((lo, hi), [x, y])) in [(r1, ideal[0]), (r2, ideal[1])].into_iter().enumerate()
            {
                let spread = (x - y).abs();
                let scale = x.abs().max(y.abs());
                let allowed = 6.0 * spread + 64.0 * ball::U * scale + 1e3 * f64::MIN_POSITIVE;
                if !(allowed.is_finite() && (hi - lo).is_finite()) {
                    continue;
                }
                if hi - lo > allowed {
                    return Some(format!(
                        "root {}: [{lo:e}, {hi:e}] is {:e} wide, its spread {spread:e}",
                        i + 1,
                        hi - lo
                    ));
                }
            }
            None
        }

        /// ±m·2^e.
        pub(super) fn float(neg: bool, m: f64, e: i32) -> f64 {
            let x = m * 2f64.powi(e);
            if neg {
                -x
            } else {
                x
            }
        }

        /// a, b, c drawn three ways: independent (any magnitudes), from two close
        /// roots (a double root up to rounding, where the discriminant cancels), and
        /// with b = 0 or c = 0.
        fn quadratic() -> impl Strategy<Value = (f64, f64, f64)> {
            let part = || (any::<bool>(), 1.0..2.0f64, -200..200i32);
            let free = (part(), part(), part()).prop_map(|(a, b, c)| {
                (
                    float(a.0, a.1, a.2),
                    float(b.0, b.1, b.2),
                    float(c.0, c.1, c.2),
                )
            });
            let close = (part(), part(), -52..0i32, any::<bool>()).prop_map(|(a, r, gap, far)| {
                let a = float(a.0, a.1, a.2 / 4);
                let r1 = float(r.0, r.1, r.2 / 4);
                let r2 = r1 * (1.0 + if far { 2f64.powi(gap) } else { 0.0 });
                (a, -a * (r1 + r2), a * r1 * r2)
            });
            let zeros = (part(), part(), any::<bool>()).prop_map(|(a, x, b_zero)| {
                let (a, x) = (float(a.0, a.1, a.2 / 4), float(x.0, x.1, x.2 / 4));
                if b_zero {
                    (a, 0.0, -a.abs() * x.abs() * a.signum())
                } else {
                    (a, x, 0.0)
                }
            });
            prop_oneof![free, close, zeros]
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(4096))]

            #[test]
            fn each_enclosure_holds_its_root(
                (a, b, c) in quadratic(),
                k in prop_oneof![Just(1.0), 1.0..4.0f64, 1e3..1e12f64],
                m in prop_oneof![Just(0.0), 3.8..4.0f64, 1e-6..4.0f64],
                j in -1.0..1.0f64,
            ) {
                prop_assume!(a != 0.0 && a.is_finite() && b.is_finite() && c.is_finite());
                let disc = disc_ball(a, b, c, k, m, j);
                prop_assume!(disc.is_some());
                let disc = disc.expect("checked");
                if let Some(why) = breach(a, b, c, disc) {
                    prop_assert!(false, "a = {a:e}, b = {b:e}, c = {c:e}, disc {disc:?}: {why}");
                }
                let d = b * b - 4.0 * a * c;
                // tightness where the roots exist and are not a cancelled b² − 4ac
                // (where q/a and c/q need not be the roots' order: checked above only)
                if let Some(why) = too_wide(a, b, c, disc).filter(|_| d > 0.0) {
                    prop_assert!(false, "a = {a:e}, b = {b:e}, c = {c:e}, disc {disc:?}: {why}");
                }
            }
        }
    }

    /// Exact checks of [`float_set`]'s contract on [lo, hi] (0 ≤ lo ≤ hi): the inner
    /// set holds only times where a·t² + b·t + c ≥ 0, the outer one every such time.
    /// Checked at the window's ends, at each interval's ends and their neighbours, and
    /// at interior points, with the quadratic evaluated exactly (BigRational).
    mod float_set_contract {
        use super::root_bounds_contract::{exact, float};
        use super::*;
        use polyguard_oracle::{Arith, ExactField, Q};
        use proptest::prelude::*;

        fn nonneg_at(a: f64, b: f64, c: f64, t: f64) -> bool {
            let t = exact(t);
            !exact(a)
                .times(&t)
                .plus(&exact(b))
                .times(&t)
                .plus(&exact(c))
                .is_neg()
        }

        fn inside(set: &[Interval; 2], t: f64) -> bool {
            set.iter().any(|i| i.lb <= t && t <= i.ub)
        }

        /// Some(reason) when a sample breaks the contract.
        fn breach(a: f64, b: f64, c: f64, lo: f64, hi: f64) -> Option<String> {
            let outer = float_set(a, b, c, lo, hi, true);
            let inner = float_set(a, b, c, lo, hi, false);
            let mut ts = vec![lo, hi];
            for k in 1..16 {
                ts.push(lo + (hi - lo) * (k as f64 / 16.0));
            }
            for i in outer.iter().chain(&inner) {
                for e in [i.lb, i.ub] {
                    if e.is_finite() {
                        ts.extend([e, e.next_up(), e.next_down()]);
                    }
                }
            }
            for t in ts.into_iter().filter(|t| (lo..=hi).contains(t)) {
                let ok = nonneg_at(a, b, c, t);
                if inside(&inner, t) && !ok {
                    return Some(format!(
                        "t = {t:e}: in the inner set {inner:?}, but negative"
                    ));
                }
                if ok && !inside(&outer, t) {
                    return Some(format!(
                        "t = {t:e}: ≥ 0, but not in the outer set {outer:?}"
                    ));
                }
            }
            None
        }

        /// Coefficients of any magnitude up to overflow, with roots inside the window
        /// (a from two roots in [lo, hi]), b or c zero, and a = 0.
        fn coefficients() -> impl Strategy<Value = (f64, f64, f64, f64, f64)> {
            let part = || (any::<bool>(), 1.0..2.0f64, -1074..1024i32);
            let window = (0.0..1.0f64, 0.0..4.0f64, -60..60i32)
                .prop_map(|(l, w, e)| (l * 2f64.powi(e), (l + w) * 2f64.powi(e)));
            let free = (part(), part(), part(), window.clone()).prop_map(|(a, b, c, (lo, hi))| {
                (
                    float(a.0, a.1, a.2),
                    float(b.0, b.1, b.2),
                    float(c.0, c.1, c.2),
                    lo,
                    hi,
                )
            });
            let rooted = (part(), 0.0..1.0f64, 0.0..1.0f64, window.clone()).prop_map(
                |(a, u1, u2, (lo, hi))| {
                    let a = float(a.0, a.1, a.2 / 2);
                    let (r1, r2) = (lo + u1 * (hi - lo), lo + u2 * (hi - lo));
                    (a, -a * (r1 + r2), a * r1 * r2, lo, hi)
                },
            );
            let linear = (part(), part(), window).prop_map(|(b, c, (lo, hi))| {
                (0.0, float(b.0, b.1, b.2), float(c.0, c.1, c.2), lo, hi)
            });
            prop_oneof![free, rooted, linear]
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(512))]

            #[test]
            fn the_sets_enclose_the_nonnegative_times((a, b, c, lo, hi) in coefficients()) {
                prop_assume!(a.is_finite() && b.is_finite() && c.is_finite());
                prop_assume!(0.0 <= lo && lo <= hi && hi.is_finite());
                if let Some(why) = breach(a, b, c, lo, hi) {
                    prop_assert!(false, "a = {a:e}, b = {b:e}, c = {c:e}, [{lo:e}, {hi:e}]: {why}");
                }
            }
        }

        /// [`below_zero_on`] answers true only when the quadratic is negative all over
        /// [lo, hi] (its largest value there, at an end or at the vertex, is checked
        /// exactly), and does answer true when the quadratic is negative at both ends
        /// with room to spare and its largest value is at an end.
        fn below_zero_breach(a: f64, b: f64, c: f64, lo: f64, hi: f64) -> Option<String> {
            let got = below_zero_on(a, b, c, lo, hi);
            let (qa, qb, qc) = (exact(a), exact(b), exact(c));
            let value = |t: &Q| qa.times(t).plus(&qb).times(t).plus(&qc);
            let (l, h) = (exact(lo), exact(hi));
            let mut largest = vec![value(&l), value(&h)];
            // the vertex −b/(2a), when a < 0 puts it inside
            if a < 0.0 {
                if let Some(v) = qb.negated().quotient(&qa.twice()) {
                    if l <= v && v <= h {
                        largest.push(value(&v));
                    }
                }
            }
            let max = largest.into_iter().max().expect("two values at least");
            if got && !max.is_neg() {
                return Some(format!("true, but the quadratic reaches {max:?} ≥ 0"));
            }
            None
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(512))]

            #[test]
            fn below_zero_is_certain((a, b, c, lo, hi) in coefficients()) {
                prop_assume!(a.is_finite() && b.is_finite() && c.is_finite());
                prop_assume!(0.0 <= lo && lo <= hi && hi.is_finite());
                if let Some(why) = below_zero_breach(a, b, c, lo, hi) {
                    prop_assert!(false, "a = {a:e}, b = {b:e}, c = {c:e}, [{lo:e}, {hi:e}]: {why}");
                }
            }

            /// Concave quadratics negative at both ends, with the vertex anywhere: the
            /// answer is true exactly when the vertex is outside the window (the largest
            /// value at an end); inside, the slopes at the ends cannot tell, and the
            /// answer is false (cases within 10⁻⁹ of a boundary are skipped).
            #[test]
            fn below_zero_sees_concave_quadratics(
                vx in -2.0..3.0f64,
                top in -1.0..1.0f64,
                curv in 0.1..10.0f64,
            ) {
                // −curv·(t − vx)² + top on [0, 1]
                let (a, b, c) = (-curv, 2.0 * curv * vx, top - curv * vx * vx);
                let at = |t: f64| a * t * t + b * t + c;
                prop_assume!(at(0.0) < -1e-9 && at(1.0) < -1e-9);
                let max = if (0.0..=1.0).contains(&vx) { top } else { at(0.0).max(at(1.0)) };
                prop_assume!(max.abs() > 1e-9 && vx.abs() > 1e-9 && (vx - 1.0).abs() > 1e-9);
                // decidable from the slopes at the ends: the vertex outside the window
                let want = !(0.0..=1.0).contains(&vx);
                prop_assert_eq!(below_zero_on(a, b, c, 0.0, 1.0), want, "vertex {} top {}", vx, top);
                if let Some(why) = below_zero_breach(a, b, c, 0.0, 1.0) {
                    prop_assert!(false, "{why}");
                }
            }
        }

        /// Clear cases: convex and negative at both ends; concave with its largest value
        /// at an end (decreasing from lo, or increasing up to hi).
        #[test]
        fn below_zero_decides_clear_cases() {
            assert!(below_zero_on(1.0, 0.0, -4.0, 0.0, 1.0), "t² − 4");
            assert!(
                below_zero_on(-1.0, -0.5, -1.0, 0.0, 1.0),
                "−t² − t/2 − 1, largest at 0"
            );
            assert!(
                below_zero_on(-1.0, 4.0, -10.0, 0.0, 1.0),
                "−t² + 4t − 10, largest at 1"
            );
            assert!(
                !below_zero_on(-1.0, 2.0, -0.5, 0.0, 2.0),
                "−t² + 2t − 0.5 reaches 0.5"
            );
            assert!(!below_zero_on(1.0, 0.0, -4.0, 0.0, 3.0), "t² − 4 reaches 5");
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(512))]

            /// The sets decide what is clear: two roots well apart (a tenth of the window
            /// or more) inside the window, at moderate magnitudes. Where the quadratic is
            /// clearly positive (between the roots when a < 0, outside them when a > 0)
            /// the inner set holds the point; where it is clearly negative the outer set
            /// does not.
            #[test]
            fn the_sets_decide_what_is_clear(
                neg in any::<bool>(),
                am in 1.0..2.0f64,
                ae in -100..100i32,
                u1 in 0.1..0.4f64,
                u2 in 0.6..0.9f64,
                (lo, w) in (0.0..1.0f64, 0.5..4.0f64),
                we in -30..30i32,
            ) {
                let (lo, hi) = (lo * 2f64.powi(we), (lo + w) * 2f64.powi(we));
                let a = float(neg, am, ae);
                let (r1, r2) = (lo + u1 * (hi - lo), lo + u2 * (hi - lo));
                let (b, c) = (-a * (r1 + r2), a * r1 * r2);
                let outer = float_set(a, b, c, lo, hi, true);
                let inner = float_set(a, b, c, lo, hi, false);
                let mid = 0.5 * (r1 + r2);
                if a < 0.0 {
                    prop_assert!(inside(&inner, mid), "inner {:?} misses {:e}", inner, mid);
                    prop_assert!(!inside(&outer, lo) && !inside(&outer, hi), "outer {:?}", outer);
                } else {
                    prop_assert!(inside(&inner, lo) && inside(&inner, hi), "inner {:?}", inner);
                    prop_assert!(!inside(&outer, mid), "outer {:?} holds {:e}", outer, mid);
                }
            }
        }

        /// A coefficient that is not finite tells nothing: the outer set is the whole
        /// window, the inner one is empty.
        #[test]
        fn a_coefficient_not_finite_tells_nothing() {
            let bad = [f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
            for &x in &bad {
                for &y in &[1.0, -1.0, 0.0] {
                    for (a, b, c) in [(x, y, y), (y, x, y), (y, y, x), (x, x, y), (y, x, x)] {
                        let outer = float_set(a, b, c, 0.0, 1.0, true);
                        let inner = float_set(a, b, c, 0.0, 1.0, false);
                        assert!(
                            inside(&outer, 0.0) && inside(&outer, 1.0),
                            "({a}, {b}, {c}): outer {outer:?}"
                        );
                        assert!(
                            inner.iter().all(Interval::is_empty),
                            "({a}, {b}, {c}): inner {inner:?}"
                        );
                    }
                }
            }
        }

        /// A linear function whose root overflows lies on one side of every window:
        /// 10⁻³⁰⁰·t + 10³⁰⁰ (root below −f64::MAX) is ≥ 0 on all of [0, 1], and the
        /// inner set says so; −10⁻³⁰⁰·t − 10³⁰⁰ is negative there, and the outer set is
        /// empty.
        #[test]
        fn an_overflowed_linear_root_keeps_its_side() {
            let inner = float_set(0.0, 1e-300, 1e300, 0.0, 1.0, false);
            assert!(
                inside(&inner, 0.0) && inside(&inner, 1.0),
                "inner {inner:?}"
            );
            let outer = float_set(0.0, -1e-300, -1e300, 0.0, 1.0, true);
            assert!(outer.iter().all(Interval::is_empty), "outer {outer:?}");
            // and the root above f64::MAX: 10⁻³⁰⁰·t − 10³⁰⁰ is negative on [0, 1]
            let outer = float_set(0.0, 1e-300, -1e300, 0.0, 1.0, true);
            assert!(outer.iter().all(Interval::is_empty), "outer {outer:?}");
            let inner = float_set(0.0, -1e-300, 1e300, 0.0, 1.0, false);
            assert!(
                inside(&inner, 0.0) && inside(&inner, 1.0),
                "inner {inner:?}"
            );
        }
    }

    /// Exact checks of [`simp_quadratics`]' contract (§II.I): for every exact w, v, a, b
    /// within the balls ww, vv, aa, bb (each coordinate within its radius of the centre)
    /// and every k within k1, the exact coefficients of F·‖a‖² ± w × a and
    /// k·‖a‖² ± w·a (a = aa + t·bb, w = ww + t·vv) lie in the balls it returns. The
    /// inputs are taken at corners of their boxes, where a product's deviation reaches the
    /// bound's input terms exactly (n_x·r_y + n_y·r_x + 2·r_x·r_y), the corner chosen to
    /// push each coefficient up and down in turn, and on exact inputs whose roundings are
    /// as large as they get (mantissas just above a power of two, vectors on one axis, so
    /// that ‖·‖₁² is no looser than the product it bounds).
    mod simp_quadratics_contract {
        use super::root_bounds_contract::{exact, float};
        use super::*;
        use polyguard_oracle::{Arith, ExactField, Q};
        use proptest::prelude::*;

        /// One call's arguments.
        #[derive(Clone, Copy, Debug)]
        struct Args {
            /// ww, vv, aa, bb.
            vecs: [BallV; 4],
            k1: Ball,
            f: f64,
        }

        impl Args {
            /// The four centres as one array (w.x, w.y, v.x, v.y, a.x, a.y, b.x, b.y).
            fn centres(&self) -> [f64; 8] {
                core::array::from_fn(|m| {
                    let v = self.vecs[m / 2].v;
                    if m % 2 == 0 {
                        v.x
                    } else {
                        v.y
                    }
                })
            }

            /// bb is exactly zero: the caller's `bb0`.
            fn bb0(&self) -> bool {
                self.vecs[3].v == Vect2::ZERO && self.vecs[3].r == 0.0
            }
        }

        const W: usize = 0;
        const V: usize = 2;
        const A: usize = 4;
        const B: usize = 6;

        fn dot(c: &[Q; 8], p: usize, q: usize) -> Q {
            c[p].times(&c[q]).plus(&c[p + 1].times(&c[q + 1]))
        }

        fn cross(c: &[Q; 8], p: usize, q: usize) -> Q {
            c[p].times(&c[q + 1]).minus(&c[p + 1].times(&c[q]))
        }

        /// The exact coefficients (t², t, 1) of the four quadratics, in simp_quadratics'
        /// order (F·g + y, F·g − y, k·g + x, k·g − x), at the exact inputs `c` and `k`.
        fn exact_coefficients(c: &[Q; 8], k: &Q, f: &Q) -> [[Q; 3]; 4] {
            let g = [dot(c, B, B), dot(c, A, B).twice(), dot(c, A, A)];
            let x = [dot(c, V, B), dot(c, W, B).plus(&dot(c, V, A)), dot(c, W, A)];
            let y = [
                cross(c, V, B),
                cross(c, W, B).plus(&cross(c, V, A)),
                cross(c, W, A),
            ];
            let quad = |kk: &Q, h: &[Q; 3], plus: bool| -> [Q; 3] {
                core::array::from_fn(|i| {
                    let kg = kk.times(&g[i]);
                    if plus {
                        kg.plus(&h[i])
                    } else {
                        kg.minus(&h[i])
                    }
                })
            };
            [
                quad(f, &y, true),
                quad(f, &y, false),
                quad(k, &x, true),
                quad(k, &x, false),
            ]
        }

        /// Adds α·∇(p·q) (or α·∇(p × q)) at the centres `c` to `g`.
        fn add_grad(g: &mut [f64; 9], c: &[f64; 8], alpha: f64, p: usize, q: usize, cross: bool) {
            if cross {
                g[p] += alpha * c[q + 1];
                g[p + 1] -= alpha * c[q];
                g[q] -= alpha * c[p + 1];
                g[q + 1] += alpha * c[p];
            } else {
                g[p] += alpha * c[q];
                g[p + 1] += alpha * c[q + 1];
                g[q] += alpha * c[p];
                g[q + 1] += alpha * c[p + 1];
            }
        }

        /// The gradient of coefficient i of quadratic j at the centres, over the eight
        /// coordinates and k (a guide to the corner that pushes it furthest).
        fn gradient(args: &Args, j: usize, i: usize) -> [f64; 9] {
            let c = args.centres();
            let mut g = [0.0; 9];
            let (kappa, sigma, is_cross) = match j {
                0 => (args.f, 1.0, true),
                1 => (args.f, -1.0, true),
                2 => (args.k1.z, 1.0, false),
                _ => (args.k1.z, -1.0, false),
            };
            match i {
                0 => add_grad(&mut g, &c, kappa, B, B, false),
                1 => add_grad(&mut g, &c, 2.0 * kappa, A, B, false),
                _ => add_grad(&mut g, &c, kappa, A, A, false),
            }
            match i {
                0 => add_grad(&mut g, &c, sigma, V, B, is_cross),
                1 => {
                    add_grad(&mut g, &c, sigma, W, B, is_cross);
                    add_grad(&mut g, &c, sigma, V, A, is_cross);
                }
                _ => add_grad(&mut g, &c, sigma, W, A, is_cross),
            }
            if j >= 2 {
                let d = |p: usize, q: usize| c[p] * c[q] + c[p + 1] * c[q + 1];
                g[8] = [d(B, B), 2.0 * d(A, B), d(A, A)][i];
            }
            g
        }

        /// The exact input at a corner: each coordinate (and k) at its centre minus, at,
        /// or plus its radius (sign −1, 0, 1).
        fn corner(args: &Args, s: &[i8; 9]) -> ([Q; 8], Q) {
            let shift = |z: f64, r: f64, s: i8| match s {
                1 => exact(z).plus(&exact(r)),
                -1 => exact(z).minus(&exact(r)),
                _ => exact(z),
            };
            let c = args.centres();
            let coords = core::array::from_fn(|m| shift(c[m], args.vecs[m / 2].r, s[m]));
            (coords, shift(args.k1.z, args.k1.r, s[8]))
        }

        /// The corners tried: the centre, each coefficient pushed up and down along its
        /// gradient's signs (a zero component taking either sign), and all coordinates
        /// at +r or −r together.
        fn corners(args: &Args) -> Vec<[i8; 9]> {
            let mut all = vec![[0; 9], [1; 9], [-1; 9]];
            for j in 0..4 {
                for i in 0..3 {
                    let g = gradient(args, j, i);
                    for dir in [1.0, -1.0] {
                        for zero in [1, -1] {
                            all.push(core::array::from_fn(|m| {
                                let d = dir * g[m];
                                if d > 0.0 {
                                    1
                                } else if d < 0.0 {
                                    -1
                                } else {
                                    zero
                                }
                            }));
                        }
                    }
                }
            }
            all.sort_unstable();
            all.dedup();
            all
        }

        /// Some(reason) when an exact coefficient at some corner lies outside its ball.
        fn breach(args: &Args) -> Option<String> {
            let [ww, vv, aa, bb] = args.vecs;
            let got = simp_quadratics(ww, vv, aa, bb, args.bb0(), args.k1, args.f);
            let f = exact(args.f);
            for s in corners(args) {
                let (c, k) = corner(args, &s);
                let want = exact_coefficients(&c, &k, &f);
                for (j, (balls, exact_c)) in got.iter().zip(&want).enumerate() {
                    for (i, (ball, e)) in balls.iter().zip(exact_c).enumerate() {
                        if !(ball.z.is_finite() && ball.r >= 0.0 && ball.r.is_finite()) {
                            return Some(format!("quadratic {j} coefficient {i}: {ball:?}"));
                        }
                        let d = e.minus(&exact(ball.z));
                        let d = if d.is_neg() { d.negated() } else { d };
                        if d > exact(ball.r) {
                            return Some(format!(
                                "quadratic {j} coefficient {i} at corner {s:?}: {:e} off the \
                                 centre {:e}, radius {:e}",
                                polyguard_oracle::convert::to_float(&d),
                                ball.z,
                                ball.r
                            ));
                        }
                    }
                }
            }
            None
        }

        /// A coordinate: zero one time in four, else ±m·2^e.
        fn coordinate(e: core::ops::Range<i32>) -> impl Strategy<Value = f64> {
            prop_oneof![
                1 => Just(0.0),
                3 => (any::<bool>(), 1.0..2.0f64, e).prop_map(|(n, m, e)| float(n, m, e)),
            ]
        }

        /// A ball vector: its radius exact zero one time in three, else 2^e from far below
        /// the centre to above it.
        fn ball_vector() -> impl Strategy<Value = BallV> {
            (
                coordinate(-20..20),
                coordinate(-20..20),
                prop_oneof![1 => Just(0.0), 2 => (-70..24i32).prop_map(|e| 2f64.powi(e))],
            )
                .prop_map(|(x, y, r)| BallV { v: v(x, y), r })
        }

        /// F ≥ 0, and k1 either as edge_detect_simp_tri makes it (1 + F and its rounding
        /// error) or any ball of positive centre, whose radius may be as large as half
        /// of it (the contract holds for every ball).
        fn k_and_f() -> impl Strategy<Value = (Ball, f64)> {
            (
                prop_oneof![
                    Just(0.0),
                    (1.0..2.0f64, -60..4i32).prop_map(|(m, e)| float(false, m, e))
                ],
                prop_oneof![
                    Just(None),
                    (1.0..4.0f64, 1..60i32).prop_map(|(z, e)| Some(Ball {
                        z,
                        r: z * 2f64.powi(-e)
                    })),
                ],
            )
                .prop_map(|(f, k)| {
                    let k1 = k.unwrap_or_else(|| {
                        let (z, err) = crate::ball::exact::two_sum(1.0, f);
                        Ball { z, r: err.abs() }
                    });
                    (k1, f)
                })
        }

        /// A coordinate whose products round by nearly half an ulp: ±2^e·(1 + m·2⁻²⁷),
        /// so that the product of two is 2^e'·(1 + … + m·m'·2⁻⁵⁴) with the last term
        /// anywhere in an ulp.
        fn rounding_coordinate() -> impl Strategy<Value = f64> {
            (any::<bool>(), 1.0..2.0f64, -8..8i32)
                .prop_map(|(n, m, e)| float(n, 1.0 + m * 2f64.powi(-27), e))
        }

        /// An exact vector on one axis (‖·‖₁ is then its length, the bound's tightest case).
        fn rounding_vector() -> impl Strategy<Value = BallV> {
            (any::<bool>(), rounding_coordinate())
                .prop_map(|(on_x, z)| BallV::exact(if on_x { v(z, 0.0) } else { v(0.0, z) }))
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(256))]

            #[test]
            fn the_balls_hold_the_exact_coefficients(
                vecs in [ball_vector(), ball_vector(), ball_vector(), ball_vector()],
                (k1, f) in k_and_f(),
            ) {
                let args = Args { vecs, k1, f };
                if let Some(why) = breach(&args) {
                    prop_assert!(false, "{:?}: {}", args, why);
                }
            }

            #[test]
            fn the_balls_hold_the_exact_coefficients_of_exact_inputs(
                vecs in [rounding_vector(), rounding_vector(), rounding_vector(), rounding_vector()],
                f in prop_oneof![Just(0.0), rounding_coordinate().prop_map(f64::abs)],
            ) {
                let (z, err) = crate::ball::exact::two_sum(1.0, f);
                let args = Args { vecs, k1: Ball { z, r: err.abs() }, f };
                if let Some(why) = breach(&args) {
                    prop_assert!(false, "{:?}: {}", args, why);
                }
            }
        }
    }
}
