//! Paper B Section IV-D, eqs 11–13 and Algorithm 3: projection of the conflict region
//! onto a track, giving a time window.
//!
//! Paper defects fixed here:
//! * Algorithm 3 ends the window at `ρ_max − ρ_f` (the *front* reaching the last conflict
//!   vertex). The rectangle covers fractions `[ρ + ρ_b, ρ + ρ_f]` (ρ_b < 0, eq 13), so it
//!   still touches `ρ_max` until its *back* leaves it: the end is `ρ_max − ρ_b`, and the
//!   start `ρ_min − ρ_f` (the printed `ρ_min + ρ_b` is the same only for ρ_f = −ρ_b).
//! * The end test `1 − ρ_b ≤ ρ_max ≤ 1 + ρ_f` is empty for a symmetric rectangle; both
//!   ends are simply clamped to `[0, 1]`.
//! * `ρ_f`, `ρ_b` are measured at `t0` while the rectangle's Mercator size scales with
//!   `sec φ`, so the paper's window is not conservative. [`conservative_window`] bounds
//!   them over the whole leg (with [`crate::sphere::Leg::offset_boxes`]); stage 4 searches
//!   that window, and the paper's window is kept for reporting only.

use super::{stage2::Regions, Motion, Object};
use crate::sphere::{Leg, Merc};
use rayon::prelude::*;

/// Widening (h) of conservative windows against the rounding of `track_time`: its result
/// (≤ 1e4 h in any scenario we read) carries a few ulps, ≲ 1e-11 h; 1e-9 h is far above
/// that and far below the stage 4 tolerance (1 s ≈ 2.8e-4 h).
pub const WINDOW_PAD_H: f64 = 1e-9;

/// Stage 3's output for one pair.
#[derive(Clone, Debug, PartialEq)]
pub struct Window {
    /// Object indices `(i, j)`.
    pub pair: (u32, u32),
    /// Conservative search window `[lo, hi]` (h): every conflict time lies inside.
    pub lo: f64,
    /// See `lo`.
    pub hi: f64,
    /// The paper's window (fixed Algorithm 3) for each object that moves.
    pub paper: [Option<(f64, f64)>; 2],
    /// Rings of the stage 2 region (for the answer's `region`).
    pub rings: Vec<Vec<Merc>>,
}

/// All surviving pairs of stage 3.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Windows {
    /// The windows.
    pub windows: Vec<Window>,
}

/// Paper B eqs 11–13: the constants of a leg's projections, computed once per leg.
#[derive(Clone, Debug, PartialEq)]
pub struct Projection {
    /// `c_m(t0)`.
    pub c0: Merc,
    /// `c_m(tf) − c_m(t0)`.
    pub dir: Merc,
    /// `|dir|²`.
    pub n2: f64,
    /// `ρ_f` and `ρ_b` at `t0` (eqs 12–13 as printed).
    pub front_back_t0: (f64, f64),
    /// Bounds on `ρ_f` (max) and `ρ_b` (min) over the whole leg.
    pub front_back_bounds: (f64, f64),
}

impl Projection {
    /// Paper B eqs 11–13 for `leg`.
    pub fn new(leg: &Leg) -> Projection {
        Projection::with_boxes(leg, &leg.offset_boxes())
    }

    /// As [`Projection::new`] with the leg's [`Leg::offset_boxes`] already at hand.
    pub fn with_boxes(leg: &Leg, boxes: &[[f64; 4]; 4]) -> Projection {
        let (dir, n2, c0) = axis(leg);
        Projection {
            c0,
            dir,
            n2,
            front_back_t0: rho_front_back_t0(leg),
            front_back_bounds: front_back_from_boxes(dir, n2, boxes),
        }
    }

    /// Paper B eq 11: `(ρ_min, ρ_max)` over `pts`.
    pub fn range(&self, pts: &[Merc]) -> Option<(f64, f64)> {
        if pts.is_empty() || self.n2 == 0.0 {
            return None;
        }
        let (d, c0) = (self.dir, self.c0);
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for p in pts {
            let r = (d[0] * (p[0] - c0[0]) + d[1] * (p[1] - c0[1])) / self.n2;
            lo = lo.min(r);
            hi = hi.max(r);
        }
        Some((lo, hi))
    }
}

/// Algorithm 3 (fixed) from the fractions: `[max(0, ρ_min − ρ_f), min(1, ρ_max − ρ_b)]`.
fn fractions(range: (f64, f64), front_back: (f64, f64)) -> Option<(f64, f64)> {
    let lo = (range.0 - front_back.0).max(0.0);
    let hi = (range.1 - front_back.1).min(1.0);
    (lo <= hi).then_some((lo, hi))
}

/// Paper B eq 11: projection fractions of points onto the leg's Mercator segment.
/// Returns `(dir, |dir|², c0)`.
fn axis(leg: &Leg) -> (Merc, f64, Merc) {
    let [c0, c1] = leg.merc;
    let d = [c1[0] - c0[0], c1[1] - c0[1]];
    (d, d[0] * d[0] + d[1] * d[1], c0)
}

/// Paper B eq 11: `ρ_min`, `ρ_max` over the region's vertices `a^{ij}(k)`.
pub fn rho_range(leg: &Leg, pts: &[Merc]) -> Option<(f64, f64)> {
    let (d, n2, c0) = axis(leg);
    if pts.is_empty() || n2 == 0.0 {
        return None;
    }
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for p in pts {
        let r = (d[0] * (p[0] - c0[0]) + d[1] * (p[1] - c0[1])) / n2;
        lo = lo.min(r);
        hi = hi.max(r);
    }
    Some((lo, hi))
}

/// Paper B eqs 12–13: `(ρ_f, ρ_b)` of the rectangle at `t0`, as the paper measures them.
pub fn rho_front_back_t0(leg: &Leg) -> (f64, f64) {
    let (d, n2, _) = axis(leg);
    let c = leg.reference_merc_at(leg.t0);
    let mut f = f64::NEG_INFINITY;
    let mut b = f64::INFINITY;
    for v in leg.merc_vertices_at(leg.t0) {
        let r = (d[0] * (v[0] - c[0]) + d[1] * (v[1] - c[1])) / n2;
        f = f.max(r);
        b = b.min(r);
    }
    (f, b)
}

/// Paper B eqs 12–13 made conservative: bounds `(ρ_f_max, ρ_b_min)` over the whole leg,
/// from the offset boxes of every vertex.
pub fn rho_front_back_bounds(leg: &Leg) -> (f64, f64) {
    let (d, n2, _) = axis(leg);
    front_back_from_boxes(d, n2, &leg.offset_boxes())
}

fn front_back_from_boxes(d: Merc, n2: f64, boxes: &[[f64; 4]; 4]) -> (f64, f64) {
    let mut f = f64::NEG_INFINITY;
    let mut b = f64::INFINITY;
    for bx in boxes {
        let (x0, x1) = (d[0] * bx[0], d[0] * bx[1]);
        let (y0, y1) = (d[1] * bx[2], d[1] * bx[3]);
        f = f.max((x0.max(x1) + y0.max(y1)) / n2);
        b = b.min((x0.min(x1) + y0.min(y1)) / n2);
    }
    (f, b)
}

/// Paper B Algorithm 3 (fixed): the window `[track_time(max(0, ρ_min − ρ_f)),
/// track_time(min(1, ρ_max − ρ_b))]` with `ρ_f`, `ρ_b` at `t0`; `None` when empty.
pub fn paper_window(leg: &Leg, pts: &[Merc]) -> Option<(f64, f64)> {
    paper_window_with(leg, &Projection::new(leg), pts)
}

fn paper_window_with(leg: &Leg, pr: &Projection, pts: &[Merc]) -> Option<(f64, f64)> {
    let (lo, hi) = fractions(pr.range(pts)?, pr.front_back_t0)?;
    Some((leg.track_time(lo), leg.track_time(hi)))
}

/// Paper B Algorithm 3 made conservative: as [`paper_window`] with `ρ_f`, `ρ_b` bounded
/// over the leg, widened by [`WINDOW_PAD_H`]. `None` proves the pair never meets.
pub fn conservative_window(leg: &Leg, pts: &[Merc]) -> Option<(f64, f64)> {
    conservative_window_with(leg, &Projection::new(leg), pts)
}

fn conservative_window_with(leg: &Leg, pr: &Projection, pts: &[Merc]) -> Option<(f64, f64)> {
    let Some(range) = pr.range(pts) else {
        return Some((leg.t0, leg.t1));
    };
    let (lo, hi) = fractions(range, pr.front_back_bounds)?;
    Some((
        (leg.track_time(lo) - WINDOW_PAD_H).max(leg.t0),
        (leg.track_time(hi) + WINDOW_PAD_H).min(leg.t1),
    ))
}

/// Paper B Section IV-D for one pair: the most restrictive of the objects' windows and
/// their common life (for two static areas: the common life only).
/// `paper`: also compute the paper's windows (reporting only).
pub fn window(
    a: &Object,
    b: &Object,
    pair: (u32, u32),
    rings: Vec<Vec<Merc>>,
    paper: bool,
) -> Option<Window> {
    let want_paper = paper;
    let mut lo = a.t0.max(b.t0);
    let mut hi = a.t1.min(b.t1);
    let pts: Vec<Merc> = rings.iter().flatten().copied().collect();
    let mut paper = [None, None];
    // The paper's windows use eq 7 as printed (hulls at t0 and tf) when both are convex.
    let paper_pts = if !want_paper {
        Vec::new()
    } else if a.is_convex() && b.is_convex() {
        let pa = if a.is_moving() {
            &a.paper_sweep
        } else {
            &a.sweep
        };
        let pb = if b.is_moving() {
            &b.paper_sweep
        } else {
            &b.sweep
        };
        super::geom::clip_convex(pa, pb)
    } else {
        pts.clone()
    };
    for (k, o) in [a, b].into_iter().enumerate() {
        if let (Motion::Moving(leg), Some(pr)) = (&o.motion, &o.projection) {
            let (wl, wh) = conservative_window_with(leg, pr, &pts)?;
            lo = lo.max(wl);
            hi = hi.min(wh);
            if want_paper {
                paper[k] = paper_window_with(leg, pr, &paper_pts);
            }
        }
    }
    (lo <= hi).then_some(Window {
        pair,
        lo,
        hi,
        paper,
        rings,
    })
}

/// Paper B Section IV-D over all stage 2 survivors, in parallel.
pub fn windows(objects: &[Object], regions: Regions, paper: bool) -> Windows {
    let windows = regions
        .regions
        .into_par_iter()
        .filter_map(|r| {
            let (i, j) = r.pair;
            window(
                &objects[i as usize],
                &objects[j as usize],
                r.pair,
                r.rings,
                paper,
            )
        })
        .collect();
    Windows { windows }
}
