//! Paper A §III: detection for 3D polygons, detect_3D: the window in which the point is
//! in the polygon's slab, with certified ends, then the 2D detector over that window.

use super::same::same_window;
use super::warping::diff_window;
use super::{dispatch, Method};
use crate::ball::{self, exact, round_down, round_up, Ball, Tri};
use crate::polygon::VertexSeq;
use crate::predicates as pr;
use crate::vect2::Vect2;

/// Paper A §III step 1: the exact sign of `z[0] + z[1]` + k·vz − k·vsp (k = σ·T, exact),
/// by expansion: the slab window's fallback when the static bound cannot tell. `None`
/// when it cannot be had (a product overflows, or is too small for an error-free
/// product).
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
#[doc(hidden)]
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
    let z0_at_t = sign_at_t([sz, -pmin], 1.0, t, vz, vsp); // sign of z0 + T·w
    let z1_at_t = sign_at_t([pmax, -sz], -1.0, t, vz, vsp); // sign of z1 − T·w
    let quotient = |x: Ball, y: Ball| quotient_in_window(x, y, t);
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
            quotient(float_diff(pmin, sz), float_diff(vz, vsp))
        };
        let b = match z1_at_t {
            Some(x) if x >= 0 => whole,
            Some(_) => quotient(float_diff(pmax, sz), float_diff(vz, vsp)),
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
            quotient(float_diff(sz, pmax), float_diff(vsp, vz))
        };
        let b = match z0_at_t {
            Some(x) if x >= 0 => whole,
            Some(_) => quotient(float_diff(sz, pmin), float_diff(vsp, vz)),
            None => unknown,
        };
        Some((a, b))
    }
}

/// Paper A §III step 1: the sign of `z[0] + z[1]` + σ·T·(vz − vsp), from floats with a
/// static bound first, by expansion ([`slab_sign_exact`]) when that cannot tell
/// (z0 + T·w = sz − pmin + T·vz − T·vsp, z1 − T·w likewise). `None` when neither can.
///
/// With a = fl(`z[0] + z[1]`) (error ≤ u|a|), w = fl(vz − vsp) (≤ u|w|) and
/// p = fl(σT·w) (≤ u|p| + T·u|w| ≤ 2u|p|(1 + u), plus an underflow of ≤ ETA), the sum
/// fl(a + p) adds ≤ u(|a| + |p|)(1 + 2u): 4u·(|a| + |p|) + ETA covers the whole, raised
/// by (1 + 16u) for its own roundings ([`ball::up`]).
#[inline(always)]
fn sign_at_t(z: [f64; 2], sigma: f64, t: f64, vz: f64, vsp: f64) -> Option<i8> {
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
}

/// Paper A §III step 1: a crossing time x/y of the slab's floor or ceiling, a quotient of
/// two float differences with x ≥ 0, y > 0, enclosed and clipped to [0, T]: exactly when
/// both are exact floats and the division is (q·y − x = 0 by two-product), else between
/// outward-rounded quotients of their ends (all of [0, T] when y's sign is not certain).
#[inline(always)]
fn quotient_in_window(x: Ball, y: Ball, t: f64) -> Ball {
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
}

/// Paper A §III step 1: the float difference p − q as a ball, exact when two-sum leaves
/// no error.
#[inline(always)]
fn float_diff(p: f64, q: f64) -> Ball {
    let (z, e) = exact::two_sum(p, -q);
    Ball { z, r: e.abs() }
}

/// Paper A §III step 1: the window [a, b] ⊆ [0, T] of the slab, as an outer enclosure
/// (a rounded down, b rounded up); `None` when there is certainly no such time.
#[inline]
pub fn slab_window(t: f64, sz: f64, vz: f64, pmin: f64, pmax: f64, vsp: f64) -> Option<(f64, f64)> {
    slab_window_balls(t, sz, vz, pmin, pmax, vsp).map(|(a, b)| (a.lo().max(0.0), b.hi().min(t)))
}

/// Paper A §III detect_3D: 2D detection (detect_same_2D when all vertex velocities are
/// equal, detect_diff_2D otherwise) from s + a·v and P + a·V over the lookahead b − a,
/// where [a, b] is the slab window of [`slab_window_balls`]. Certified.
///
/// ```
/// use polyguard::{detect_3d, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(4.0, 0.0), Vect2::new(4.0, 4.0), Vect2::new(0.0, 4.0)];
/// let rest = [Vect2::ZERO; 4];
/// let (s, east) = (Vect2::new(-2.0, 2.0), Vect2::new(1.0, 0.0));
/// // between heights 3 and 5: climbing at 1 from 0 it reaches the floor at t = 3, over
/// // the square; climbing at 0.2 it reaches it at t = 15, long after leaving the square
/// assert!(detect_3d(20.0, s, east, 0.0, 1.0, &square[..], &rest[..], 3.0, 5.0, 0.0, 0.01, 1e-4));
/// assert!(!detect_3d(20.0, s, east, 0.0, 0.2, &square[..], &rest[..], 3.0, 5.0, 0.0, 0.01, 1e-4));
/// ```
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
    use crate::detect::tests::v;

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
        use super::*;
        use crate::detect::tests::{exact, float};
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
}
