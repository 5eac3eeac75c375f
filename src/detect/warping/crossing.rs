//! Paper A §II.I edge_detect_simp's certain yes at the point's crossings of the edge's
//! line: candidate times in plain floats, each checked on balls against the four
//! conditions. The engine's fast path in front of the root sets of
//! [`simp_window`](super::simp_window); the oracle decides the same conditions exactly and
//! needs no witness.

use crate::ball::{nonnegative, Ball, BallV, Tri};
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
/// ball that holds the exact value for every exact input within ww, vv, aa, bb and
/// k1 ∋ 1 + F: w and a are formed on balls, then ‖a‖², w·a and w × a ([`BallV::sq`],
/// [`BallV::dot`], [`BallV::cross`]), each step's bound being its ball operation's; the
/// exact |x| lies in the ball (|x̃|, r) when x lies in (x̃, r). The one test per pair
/// answers as the two signs would: k·g − |x̃| is the smaller of k·g ∓ x̃, and the larger
/// one's radius exceeds it by at most 2u(1 + 16u)·2|x̃| while its centre exceeds it by
/// 2|x̃| less two roundings (≤ 2u·|centre| each), far more. The engine passes
/// [`nonnegative`]`(·) == Yes`; the tests pass a comparison that ignores the radius, as
/// a canary.
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
    let abs = |b: Ball| Ball {
        z: b.z.abs(),
        r: b.r,
    };
    let tt = Ball::exact(t);
    let (wt, at) = (ww.add(vv.scale(tt)), aa.add(bb.scale(tt)));
    let (g, x) = (at.sq(), wt.dot(at));
    // The along condition first: at a crossing, it is the one that fails when the point
    // passes beside the edge.
    if !sure(g.mul(k1).sub(abs(x))) {
        return false;
    }
    sure(g.scale(f).sub(abs(wt.cross(at))))
}
