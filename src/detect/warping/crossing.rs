//! Paper A §II.I edge_detect_simp's certain yes at the point's crossings of the edge's
//! line: candidate times in plain floats, each checked on balls against the four
//! conditions. The engine's fast path in front of the root sets of
//! [`simp_window`](super::simp_window); the oracle decides the same conditions exactly and
//! needs no witness.

use crate::ball::{self, mx, nonnegative, up, Ball, BallV, Tri};
use crate::vect2::{sqrt, Vect2};

/// Paper A §II.I edge_detect_simp at the times the point crosses the edge's line: the
/// first of them in the inner window [ilo, ihi] at which all four conditions certainly
/// hold ([`conditions_hold_at`]), a witness of a certain yes.
///
/// The candidate times are [`crossing_times`], in plain floats. They need no error
/// bound: any float time of the inner window is a valid witness, and what decides is
/// the certified check at that time.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn crossing_witness(
    ilo: f64,
    ihi: f64,
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    k1: Ball,
    f: f64,
) -> Option<f64> {
    let [r1, r2] = crossing_times(ww.v, vv.v, aa.v, bb.v, ilo);
    let sure = |b: Ball| nonnegative(b) == Tri::Yes;
    // NaN fails the window test.
    let holds = |t: f64| ilo <= t && t <= ihi && conditions_hold_at(t, ww, vv, aa, bb, k1, f, sure);
    if holds(r1) {
        Some(r1)
    } else if holds(r2) {
        Some(r2)
    } else {
        None
    }
}

/// The times at which w(t) × a(t) = 0 (w = ww + t·vv, a = aa + t·bb: the point on the
/// edge's line, paper A §II.I), in plain floats, smaller first (NaN where there is
/// none): the roots of y₂t² + y₁t + y₀ by the cancellation-free pair q / y₂, y₀ / q, or
/// the vertex −y₁ / 2y₂ where they are complex (the point passes the line's side
/// without crossing it: where |w × a| is least). Where y₂ = y₁ = 0, w × a is the same
/// at every time, and the candidate is `t0`. Candidates only: see [`crossing_witness`].
#[inline(always)]
pub(super) fn crossing_times(w: Vect2, v: Vect2, a: Vect2, b: Vect2, t0: f64) -> [f64; 2] {
    let cross = |x: Vect2, y: Vect2| x.dot(y.perp());
    let (y2, y1, y0) = (cross(v, b), cross(w, b) + cross(v, a), cross(w, a));
    if y2 == 0.0 {
        return [if y1 == 0.0 { t0 } else { -y0 / y1 }, f64::NAN];
    }
    let disc = y1 * y1 - 4.0 * y2 * y0;
    if disc > 0.0 {
        let q = -0.5 * (y1 + sqrt(disc).copysign(y1));
        let (p, r) = (q / y2, y0 / q);
        [p.min(r), p.max(r)]
    } else {
        [-0.5 * y1 / y2, f64::NAN]
    }
}

/// Paper A §II.I edge_detect_simp's four conditions at one exact time t:
/// (1 + F)·‖a‖² ∓ w·a ≥ 0 and F·‖a‖² ∓ w × a ≥ 0 (w = ww + t·vv, a = aa + t·bb), each
/// pair as (1 + F)·‖a‖² − |w·a| ≥ 0 and F·‖a‖² − |w × a| ≥ 0, decided by `sure` on a
/// ball that holds the exact value for every exact input within ww, vv, aa, bb (radii
/// per coordinate) and k1 ∋ 1 + F. One static bound per step, in floats (u the unit
/// roundoff; each sum of non-negative terms raised by [`up`], which absorbs its own
/// roundings and an underflow):
///
/// - w̃ = fl(ww̃ + fl(t·vṽ)) is within ρ_w = r_ww + |t|·r_vv + u·(‖fl(t·vṽ)‖∞ + ‖w̃‖∞) of
///   the exact w in each coordinate (each rounding errs by at most u times its result);
///   ã within ρ_a likewise;
/// - ‖a‖², w·a and w × a from the rounded vectors are within e_g = 2ρ_a‖ã‖₁ + 2ρ_a² +
///   3u‖ã‖₁² and e_x = ‖w̃‖₁ρ_a + ‖ã‖₁ρ_w + 2ρ_wρ_a + 3u‖w̃‖₁‖ã‖₁ of the exact ones (the
///   products' differences, then two products and a sum rounded, ≤ 2u(1 + 2u) of the sum
///   of their magnitudes);
/// - with k = 1 + F known within r_k, k ≥ r_k and F ≥ 0 (else no witness is claimed),
///   K·‖a‖² − |w·a| ≥ k·g̃ − |x̃| − (k·e_g + r_k·(g̃ + e_g) + e_x); its computed value
///   p − |x̃|, p = fl(k·g̃), errs by at most u·(p + |result|). F·‖a‖² − |w × a| likewise.
///
/// The one test per pair answers as the two signs would: the exact k·g − |x| is the
/// smaller of k·g ∓ x. The engine passes [`nonnegative`]`(·) == Yes` (an infinite radius,
/// as after an overflow, is never sure); the tests pass a comparison that ignores the
/// radius, as a canary.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn conditions_hold_at(
    t: f64,
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    k1: Ball,
    f: f64,
    sure: impl Fn(Ball) -> bool,
) -> bool {
    if !(k1.z >= k1.r && f >= 0.0) {
        return false;
    }
    let u = ball::U;
    let n1 = |v: Vect2| v.x.abs() + v.y.abs();
    let big = |v: Vect2| mx(v.x.abs(), v.y.abs());
    let ta = t.abs();
    let (tv, tb) = (vv.v.scale(t), bb.v.scale(t));
    let (w, a) = (ww.v + tv, aa.v + tb);
    let rho_w = up(ww.r + ta * vv.r + u * (big(tv) + big(w)));
    let rho_a = up(aa.r + ta * bb.r + u * (big(tb) + big(a)));
    let (nw, na) = (n1(w), n1(a));
    let g = a.dot(a);
    let eg = up(2.0 * rho_a * na + 2.0 * rho_a * rho_a + 3.0 * u * na * na);
    let ex = up(nw * rho_a + na * rho_w + 2.0 * rho_w * rho_a + 3.0 * u * nw * na);
    // The along condition first: at a crossing, it is the one that fails when the point
    // passes beside the edge.
    let p = k1.z * g;
    let along = p - w.dot(a).abs();
    let r_along = up(k1.z * eg + k1.r * (g + eg) + ex + u * (p + along.abs()));
    if !sure(Ball {
        z: along,
        r: r_along,
    }) {
        return false;
    }
    let q = f * g;
    let perp = q - w.dot(a.perp()).abs();
    sure(Ball {
        z: perp,
        r: up(f * eg + ex + u * (q + perp.abs())),
    })
}
