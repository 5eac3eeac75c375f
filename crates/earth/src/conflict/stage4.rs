//! Paper B Section IV-E, eqs 14–20, replaced: certified first and last times at which two
//! polygons meet.
//!
//! The paper solves eqs 14–19 with SLSQP, a local method that may miss a conflict and is
//! slowest on false alarms. Here:
//!
//! * **Linear motion (eq 20)** — static areas and east–west legs translate at constant
//!   Mercator velocity. `A(t) ∩ B(t) ≠ ∅ ⇔ (v_a − v_b) t ∈ B* ⊖ A*` (the Minkowski
//!   difference of the polygons at time 0): the window is the clip of a line by a convex
//!   polygon, exact up to f64 rounding, no tolerance.
//! * **General motion** — conservative advancement: the Hausdorff distance between a
//!   polygon at two times is at most `V·|Δt|` ([`crate::sphere::Leg::merc_speed_bound`]),
//!   so polygons at distance `d` cannot meet within `d / (V_a + V_b)`. Stepping by that
//!   from the window's start (for the first time) and from its end (for the last time)
//!   certifies every skipped instant. The search stops at the first instant where the
//!   distance is at most `ε = (V_a + V_b)·tol`, the distance the pair can close within
//!   the tolerance `tol`.
//!
//! Contract: every instant at which the polygons meet lies in `[t_start, t_end]`; at both
//! ends the polygons are within `ε` of each other (they meet at the ends when the approach
//! is not tangential, within `tol` of the reported times). A pair that never comes within
//! `ε` is reported as no conflict; a pair that comes within `ε` without touching is
//! reported (a near miss of at most `ε`, ≈ 20 m for two 15 kn tracks at 1 s).

use super::{geom, stage3::Windows, Object};
use crate::sphere::Merc;
use rayon::prelude::*;

/// How stage 4 decided an interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Two static areas: the overlap of their lives (stage 2 decides).
    AreaOverlap,
    /// Exact linear-motion window (eq 20).
    Linear,
    /// Certified conservative advancement.
    Advancement,
}

/// Stage 4's output for one pair.
#[derive(Clone, Debug, PartialEq)]
pub struct Interval {
    /// Object indices.
    pub pair: (u32, u32),
    /// First conflict time (h).
    pub t_start: f64,
    /// Last conflict time (h).
    pub t_end: f64,
    /// How it was decided.
    pub method: Method,
    /// The stage 2 region.
    pub rings: Vec<Vec<Merc>>,
    /// The paper's stage 3 windows (reporting only).
    pub paper: [Option<(f64, f64)>; 2],
}

/// All conflicts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Intervals {
    /// The intervals.
    pub intervals: Vec<Interval>,
}

/// Paper B eq 20: the window `[t_lo, t_hi] ∩ {t : A(t) ∩ B(t) ≠ ∅}` for convex polygons
/// translating at constant velocities `va`, `vb`; `a_ref`, `b_ref` are their vertices at
/// time `t_ref`. `None` when the Minkowski difference is degenerate (zero area),
/// `Some(None)` when the polygons never meet in the window.
///
/// **Rounding.** The window is certified to contain every instant at which the polygons
/// as the f64 model evaluates them ([`crate::sphere::Leg::merc_vertices_at`] at that
/// instant, as the ground truth does) meet:
/// - each vertex at `t` lies within `D = position_slack(c)` of `p(t_ref) + v·(t − t_ref)`
///   ([`crate::sphere::position_slack`]; `c` bounds every coordinate over the window),
///   so the Minkowski difference at `t` lies within `2D` of the one used here, and the
///   difference's half-planes are relaxed by `2D` (a convex set grown by `2D` lies in
///   each of its half-planes shifted by `2D`);
/// - the differences `b − a`, the hull (non-robust orientations drop only points within
///   `≈ 16u·c` of an edge) and each edge's `c0`, `c1` carry rounding bounded by
///   `64u·c·|e|` and `4u` of the products' magnitudes; they are added to the relaxation;
/// - a constraint whose `c1` is within its own error of 0 does not narrow the window
///   (its sign is uncertain); it empties it only when violated for every `s` in reach;
/// - each quotient is moved outwards by `4u` of its magnitude (two roundings), and each
///   end `t_ref + s` by `2u` of its own (one more);
/// - an end that no constraint moved is `t_lo` or `t_hi` exactly (not
///   `(t_hi − t_ref) + t_ref`, which may differ by an ulp).
///
/// The ends stay near contact: at each, the relative position violates no half-plane by
/// more than its relaxation (`≈ 2D` in distance), far within stage 4's `ε`.
pub fn linear_window(
    a_ref: &[Merc],
    va: Merc,
    b_ref: &[Merc],
    vb: Merc,
    t_ref: f64,
    t_lo: f64,
    t_hi: f64,
) -> Option<Option<(f64, f64)>> {
    const U: f64 = f64::EPSILON / 2.0;
    // Relative motion about t_ref: (va − vb) s ∈ B − A, s = t − t_ref.
    let mut diff = Vec::with_capacity(a_ref.len() * b_ref.len());
    for b in b_ref {
        for a in a_ref {
            diff.push([b[0] - a[0], b[1] - a[1]]);
        }
    }
    let m = geom::convex_hull(&diff);
    if m.len() < 3 {
        // Degenerate difference (a segment or a point): leave it to the general method.
        return None;
    }
    let w = [va[0] - vb[0], va[1] - vb[1]];
    let (s_lo, s_hi) = (t_lo - t_ref, t_hi - t_ref);
    let s_max = s_lo.abs().max(s_hi.abs());
    // every coordinate any vertex takes over the window (plus a turn: copies across the
    // antimeridian), and every coordinate of the differences
    let coord = a_ref
        .iter()
        .chain(b_ref)
        .fold(0f64, |c, p| c.max(p[0].abs()).max(p[1].abs()));
    let speed = va[0]
        .abs()
        .max(va[1].abs())
        .max(vb[0].abs())
        .max(vb[1].abs());
    let c = coord + speed * s_max + std::f64::consts::TAU;
    let relax = 2.0 * crate::sphere::position_slack(c) + 64.0 * U * c;
    let (mut lo, mut hi) = (s_lo, s_hi);
    let (mut moved_lo, mut moved_hi) = (false, false);
    let n = m.len();
    for k in 0..n {
        let (e0, e1) = (m[k], m[(k + 1) % n]);
        let e = [e1[0] - e0[0], e1[1] - e0[1]];
        // inside ⇔ cross(e, w s − e0) ≥ 0 ⇔ c0 + c1 s ≥ 0; relaxed: ≥ −pad
        let c0 = -(e[0] * e0[1] - e[1] * e0[0]);
        let c1 = e[0] * w[1] - e[1] * w[0];
        let c1_err = 4.0 * U * ((e[0] * w[1]).abs() + (e[1] * w[0]).abs())
            + 4.0 * U * e[0].abs().max(e[1].abs()) * w[0].abs().max(w[1].abs());
        let pad = e[0].hypot(e[1]) * relax
            + 4.0 * U * ((e[0] * e0[1]).abs() + (e[1] * e0[0]).abs())
            + c1_err * s_max;
        if !(pad.is_finite() && c0.is_finite() && c1.is_finite()) {
            // beyond the f64 range: no certified narrowing
            continue;
        }
        if c1.abs() <= c1_err {
            // the sign of c1 is uncertain: only a constraint violated at every s in reach
            // decides (no meeting); otherwise it does not narrow the window
            if c0 + pad + c1.abs() * s_max < 0.0 {
                return Some(None);
            }
            continue;
        }
        // the root of c0 + pad + c1 s = 0, moved outwards by its two roundings
        let q = -(c0 + pad) / c1;
        if c1 > 0.0 {
            let b = q - 4.0 * U * q.abs();
            if b > lo {
                lo = b;
                moved_lo = true;
            }
        } else {
            let b = q + 4.0 * U * q.abs();
            if b < hi {
                hi = b;
                moved_hi = true;
            }
        }
        if lo > hi {
            return Some(None);
        }
    }
    let start = if moved_lo {
        let t = t_ref + lo;
        (t - 2.0 * U * t.abs()).max(t_lo)
    } else {
        t_lo
    };
    let end = if moved_hi {
        let t = t_ref + hi;
        (t + 2.0 * U * t.abs()).min(t_hi)
    } else {
        t_hi
    };
    Some(Some((start, end)))
}

/// An object's velocity envelope ([`Object::velocity_envelope`]): `(e, σ_lo, σ_hi, deform)`.
type Envelope = (Merc, f64, f64, f64);

/// Bound on how fast the gap between the two polygons can shrink, measured along the
/// unit direction `n`, or in any direction when `n` is `None`. Every vertex velocity is
/// `σ e + w` (see [`Object::velocity_envelope`], here `a` and `b` for the two objects);
/// the common part cancels in the gap, so the bound is
/// `max_{σ_a, σ_b ∈ ends} |n·(σ_b e_b − σ_a e_a)| + deform_a + deform_b`
/// (a convex function of `(σ_a, σ_b)`, maximal at a corner of their box).
fn closing_rate(a: &Envelope, b: &Envelope, n: Option<Merc>) -> f64 {
    let &(ea, la, ha, wa) = a;
    let &(eb, lb, hb, wb) = b;
    let mut m: f64 = 0.0;
    for sa in [la, ha] {
        for sb in [lb, hb] {
            let r = [sb * eb[0] - sa * ea[0], sb * eb[1] - sa * ea[1]];
            let v = match n {
                Some(n) => (n[0] * r[0] + n[1] * r[1]).abs(),
                None => r[0].hypot(r[1]),
            };
            m = m.max(v);
        }
    }
    (m + wa + wb) * crate::sphere::BOUND_SAFETY
}

/// Conservative advancement from `from` towards `to` (either direction). At each instant
/// with polygons at distance `d`, closest direction `n` and gap `g` along `n` (the
/// separating-axis margin), no contact can happen within
/// `max(d / rate_any, g / rate_n)`; that span is skipped. Returns the first instant where
/// the skip would be shorter than `tol` (the polygons then meet or are within
/// `rate · tol`), or `None` when `to` is reached first.
fn advance(a: &Object, b: &Object, from: f64, to: f64, tol: f64) -> Option<f64> {
    // the envelopes are constants of the objects: formed once, not at every step
    let (env_a, env_b) = (a.velocity_envelope(), b.velocity_envelope());
    let rate_any = closing_rate(&env_a, &env_b, None);
    let convex = a.is_convex() && b.is_convex();
    let dir = if to >= from { 1.0 } else { -1.0 };
    let (mut va, mut vb) = (Vec::with_capacity(16), Vec::with_capacity(16));
    let mut t = from;
    loop {
        a.vertices_at(t, &mut va);
        b.vertices_at(t, &mut vb);
        let Some((d, n)) = geom::closest_holed(&va, a.holes(), &vb, b.holes(), convex) else {
            return Some(t);
        };
        let mut step = d / rate_any;
        let amax = va
            .iter()
            .map(|p| n[0] * p[0] + n[1] * p[1])
            .fold(f64::NEG_INFINITY, f64::max);
        let bmin = vb
            .iter()
            .map(|p| n[0] * p[0] + n[1] * p[1])
            .fold(f64::INFINITY, f64::min);
        let g = bmin - amax;
        if g > 0.0 {
            step = step.max(g / closing_rate(&env_a, &env_b, Some(n)));
        }
        if step < tol {
            return Some(t);
        }
        if t == to {
            return None;
        }
        let next = t + dir * step;
        t = if (next - to) * dir >= 0.0 { to } else { next };
    }
}

/// Paper B Section IV-E (replaced) for one pair with at least one moving object: the
/// certified first and last conflict times within `[lo, hi]`.
pub fn interval(a: &Object, b: &Object, lo: f64, hi: f64, tol: f64) -> Option<(f64, f64, Method)> {
    if let (Some(va), Some(vb), true, true) = (
        a.linear_velocity(),
        b.linear_velocity(),
        a.is_convex(),
        b.is_convex(),
    ) {
        let (mut pa, mut pb) = (Vec::new(), Vec::new());
        a.vertices_at(lo, &mut pa);
        b.vertices_at(lo, &mut pb);
        if let Some(w) = linear_window(&pa, va, &pb, vb, lo, lo, hi) {
            return w.map(|(s, e)| (s, e, Method::Linear));
        }
    }
    advancement_interval(a, b, lo, hi, tol).map(|(s, e)| (s, e, Method::Advancement))
}

/// The certified advancement alone (no linear shortcut): first and last instants in
/// `[lo, hi]` at which the pair is within the stopping distance, `None` if never.
pub fn advancement_interval(
    a: &Object,
    b: &Object,
    lo: f64,
    hi: f64,
    tol: f64,
) -> Option<(f64, f64)> {
    let s = advance(a, b, lo, hi, tol)?;
    let e = advance(a, b, hi, s, tol).unwrap_or(s);
    Some((s, e))
}

/// Paper B Section IV-E (replaced) over all stage 3 survivors, in parallel. Static–static
/// pairs keep the overlap of their lives.
pub fn intervals(objects: &[Object], windows: Windows, tol: f64) -> Intervals {
    let intervals = windows
        .windows
        .into_par_iter()
        .filter_map(|w| {
            let (a, b) = (&objects[w.pair.0 as usize], &objects[w.pair.1 as usize]);
            let (t_start, t_end, method) = if !a.is_moving() && !b.is_moving() {
                (w.lo, w.hi, Method::AreaOverlap)
            } else {
                interval(a, b, w.lo, w.hi, tol)?
            };
            Some(Interval {
                pair: w.pair,
                t_start,
                t_end,
                method,
                rings: w.rings,
                paper: w.paper,
            })
        })
        .collect();
    Intervals { intervals }
}
