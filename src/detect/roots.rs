//! Paper A §II.I, dot_nn_lin's case analysis (omitted in the paper, derived in
//! docs/derivations.md): the set where a quadratic a·t² + b·t + c is ≥ 0 on a window,
//! enclosed from outside and from inside, from enclosures of its real roots.

use super::{fmax, fmin, Interval};
use crate::ball::{self, nonnegative, positive, round_down, round_up, Ball, Tri};
use crate::vect2::sqrt;

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
pub(super) fn below_zero_on(a: f64, b: f64, c: f64, lo: f64, hi: f64) -> bool {
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
pub(super) fn ball_set(a: Ball, b: Ball, c: Ball, lo: f64, hi: f64, outer: bool) -> [Interval; 2] {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact checks of [`root_bounds`]' contract: for float a ≠ 0, b, c with real roots
    /// and any ball `disc` that holds b² − 4ac, each enclosure holds its exact root.
    mod root_bounds_contract {
        use super::*;
        use crate::detect::tests::{exact, float};
        use polyguard_oracle::{Arith, ExactField, Q};
        use proptest::prelude::*;
        use std::cmp::Ordering;

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
        use super::*;
        use crate::detect::tests::{exact, float};
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
}
