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

/// Paper B eq 20: the exact window `[t_lo, t_hi] ∩ {t : A(t) ∩ B(t) ≠ ∅}` for convex
/// polygons translating at constant velocities `va`, `vb`; `a_ref`, `b_ref` are their
/// vertices at time `t_ref`. `None` when the Minkowski difference is degenerate (zero
/// area), `Some(None)` when the polygons never meet in the window.
pub fn linear_window(
    a_ref: &[Merc],
    va: Merc,
    b_ref: &[Merc],
    vb: Merc,
    t_ref: f64,
    t_lo: f64,
    t_hi: f64,
) -> Option<Option<(f64, f64)>> {
    // Relative motion about t_ref: (va − vb) s ∈ B − A, s = t − t_ref.
    let mut diff = Vec::with_capacity(a_ref.len() * b_ref.len());
    for b in b_ref {
        for a in a_ref {
            diff.push([b[0] - a[0], b[1] - a[1]]);
        }
    }
    let m = geom::convex_hull(&diff);
    let w = [va[0] - vb[0], va[1] - vb[1]];
    let (mut lo, mut hi) = (t_lo - t_ref, t_hi - t_ref);
    if m.len() < 3 {
        // Degenerate difference (a segment or a point): leave it to the general method.
        return None;
    }
    let n = m.len();
    for k in 0..n {
        let (e0, e1) = (m[k], m[(k + 1) % n]);
        let e = [e1[0] - e0[0], e1[1] - e0[1]];
        // inside ⇔ cross(e, w s − e0) ≥ 0 ⇔ c0 + c1 s ≥ 0
        let c0 = -(e[0] * e0[1] - e[1] * e0[0]);
        let c1 = e[0] * w[1] - e[1] * w[0];
        if c1 == 0.0 {
            if c0 < 0.0 {
                return Some(None);
            }
        } else if c1 > 0.0 {
            lo = lo.max(-c0 / c1);
        } else {
            hi = hi.min(-c0 / c1);
        }
        if lo > hi {
            return Some(None);
        }
    }
    Some(Some((lo + t_ref, hi + t_ref)))
}

/// Bound on how fast the gap between the two polygons can shrink, measured along the
/// unit direction `n`, or in any direction when `n` is `None`. Every vertex velocity is
/// `σ e + w` (see [`Object::velocity_envelope`]); the common part cancels in the gap, so
/// the bound is `max_{σ_a, σ_b ∈ ends} |n·(σ_b e_b − σ_a e_a)| + deform_a + deform_b`
/// (a convex function of `(σ_a, σ_b)`, maximal at a corner of their box).
fn closing_rate(a: &Object, b: &Object, n: Option<Merc>) -> f64 {
    let (ea, la, ha, wa) = a.velocity_envelope();
    let (eb, lb, hb, wb) = b.velocity_envelope();
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
    let rate_any = closing_rate(a, b, None);
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
            step = step.max(g / closing_rate(a, b, Some(n)));
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
