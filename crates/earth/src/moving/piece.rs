//! One piece of the planar model (docs/moving-features.md): the time between two
//! consecutive breakpoints (fix or keyframe times), where the mover and every vertex move
//! linearly — one paper-A case per ring (Narkawicz & Hagen §II, warping polygons §II.I)
//! — and what the certified engine (`polyguard::intervals`) says of its relations,
//! widened by the rounding of the case it is handed.
//!
//! # The stand-in and its distance δ from the model
//! The engine gets the f64 case: the mover's position A₀ at the piece's start and
//! velocity fl((A₁ − A₀)/h), each vertex likewise. Interpolated positions carry an error
//! `e` ([`lerp`]); the velocity's rounding moves the point by at most
//! |A₁ − A₀|·3.1u over the piece, and a time difference h that is not exact by u more.
//! So the stand-in point is within δ_p = Σ_c 2e₀ + 2e₁ + 5u|ΔA| of the model's, and each
//! stand-in vertex within δ_v of its model vertex (the same sum); δ = δ_p + δ_v.
//! Moving a point by δ_p and every vertex by δ_v changes the distance to the region by at
//! most δ, and (following the straight homotopy between the two polygons) cannot change
//! the winding number of a point farther than δ from the boundary. So, with the
//! engine's relations of the stand-in (near_D, breach_D):
//! - inside ⊆ near_δ, and fence_δ = ¬breach_δ ⊆ inside;
//! - near_D ⊆ near_{D+δ}, and near_{D−δ} ⊆ near_D (D > δ; else fence_{δ−D} ⊆ near_D);
//! - breach_D ⊆ breach_{D+δ}, and breach_{D−δ} ⊆ breach_D when D ≥ 2δ (a point outside
//!   the stand-in by more than δ is outside the model); else ¬near_δ ⊆ breach_D.
//!
//! Every D handed to the engine is rounded the safe way (up for an upper set, down for
//! a lower one).

use super::planar::{PlaneArea, PlaneFix, PlaneFrame, PlaneRings};
use super::prepared::{clip_ring, winding, Prepared};
use super::timeline::{Holds, Timeline};
use super::{next_down, next_up};
use polyguard::intervals::{intervals, Relation, Separation};
use polyguard::{End, Span, Vect2};

/// `a + f·(b − a)` with `f = (t − ta)/(tb − ta)`, rounded, and a bound on its distance from
/// the exact interpolation, per coordinate: the point of the linear motion from `a` at
/// `ta` to `b` at `tb`, at time `t` (docs/moving-features.md). Exact at `ta` and `tb`.
/// The bound: f has relative error ≤ 3u, the product ≤ 5.01u·|f(b − a)|, the sum u·|a + ·|,
/// so 8u(|a| + |b − a|) covers it (f ∈ [0, 1]).
fn lerp(a: [f64; 2], b: [f64; 2], ta: f64, tb: f64, t: f64) -> ([f64; 2], [f64; 2]) {
    if t == ta {
        return (a, [0.0; 2]);
    }
    if t == tb {
        return (b, [0.0; 2]);
    }
    let f = (t - ta) / (tb - ta);
    let mut p = [0.0; 2];
    let mut e = [0.0; 2];
    for c in 0..2 {
        let d = b[c] - a[c];
        p[c] = a[c] + f * d;
        e[c] = 8.0 * U * (a[c].abs() + d.abs());
    }
    (p, e)
}

/// The scalar [`lerp`] (heights): the value and its error bound.
fn lerp1(a: f64, b: f64, ta: f64, tb: f64, t: f64) -> (f64, f64) {
    let (p, e) = lerp([a, 0.0], [b, 0.0], ta, tb, t);
    (p[0], e[0])
}

/// The mover's position (and height) at time `t` within its fixes, with error bounds.
fn mover_at(fixes: &[PlaneFix], t: f64) -> ([f64; 2], [f64; 2], Option<(f64, f64)>) {
    let j = match fixes.binary_search_by(|f| f.t.total_cmp(&t)) {
        Ok(j) => {
            let f = fixes[j];
            return ([f.x, f.y], [0.0; 2], f.z.map(|z| (z, 0.0)));
        }
        Err(j) => j.clamp(1, fixes.len() - 1) - 1,
    };
    let (a, b) = (fixes[j], fixes[j + 1]);
    let (p, e) = lerp([a.x, a.y], [b.x, b.y], a.t, b.t, t);
    let z = match (a.z, b.z) {
        (Some(za), Some(zb)) => Some(lerp1(za, zb, a.t, b.t, t)),
        _ => None,
    };
    (p, e, z)
}

/// Ring `ring` (0 the outer, k the hole k − 1) of part `part` of frame `f`.
fn ring_of(f: &PlaneFrame, part: usize, ring: usize) -> &[[f64; 2]] {
    let r = &f.parts[part];
    if ring == 0 {
        &r.outer
    } else {
        &r.holes[ring - 1]
    }
}

/// One ring's vertices at time `t` (the frame pair around it), with the largest error
/// bound (L1) of a vertex.
fn ring_at(area: &PlaneArea, part: usize, ring: usize, t: f64) -> (Vec<[f64; 2]>, f64) {
    let fr = &area.frames;
    if area.is_static || fr.len() == 1 {
        return (ring_of(&fr[0], part, ring).to_vec(), 0.0);
    }
    let k = match fr.binary_search_by(|f| f.t.total_cmp(&t)) {
        Ok(k) => return (ring_of(&fr[k], part, ring).to_vec(), 0.0),
        Err(k) => k.clamp(1, fr.len() - 1) - 1,
    };
    let (a, b) = (ring_of(&fr[k], part, ring), ring_of(&fr[k + 1], part, ring));
    let mut err: f64 = 0.0;
    let pts = a
        .iter()
        .zip(b)
        .map(|(p, q)| {
            let (v, e) = lerp(*p, *q, fr[k].t, fr[k + 1].t, t);
            err = err.max(e[0] + e[1]);
            v
        })
        .collect();
    (pts, err)
}

/// The area's polygons at time `t` (interpolated between keyframes), and the largest
/// error bound (L1) of a vertex.
pub(super) fn frame_at(area: &PlaneArea, t: f64) -> (PlaneFrame, f64) {
    let mut err: f64 = 0.0;
    let parts = area.frames[0]
        .parts
        .iter()
        .enumerate()
        .map(|(k, part)| {
            let mut ring = |r: usize| {
                let (v, e) = ring_at(area, k, r, t);
                err = err.max(e);
                v
            };
            let outer = ring(0);
            let holes = (1..=part.holes.len()).map(&mut ring).collect();
            PlaneRings { outer, holes }
        })
        .collect();
    (PlaneFrame { t, parts }, err)
}

/// The unit roundoff of f64, 2⁻⁵³.
const U: f64 = f64::EPSILON / 2.0;

/// `b − a` and whether it is exact (Knuth's two-sum).
fn diff_exact(b: f64, a: f64) -> (f64, bool) {
    let s = b - a;
    let bb = s - b;
    let err = (b - (s - bb)) + (-a - bb);
    (s, err == 0.0)
}

/// Which horizontal set of one ring (the module doc's sandwiches).
#[derive(Clone, Copy, Debug)]
enum RingSet {
    /// The outer ring: near within D (`d_lo`, `d_hi` as in `PlaneRelation::Near`);
    /// `d_hi` = 0 is inside.
    Outer { d_lo: f64, d_hi: f64 },
    /// A hole: breach_D (not deep inside the hole), 0 for "not in its open interior".
    Hole { d_lo: f64, d_hi: f64 },
}

/// A stand-in ring on one piece: vertices at its start, velocities, and δ_v.
struct StandIn {
    p: Vec<Vect2>,
    vels: Vec<Vect2>,
}

/// The engine's timeline of `relation` at separation `d` for the stand-in point `(s, v)`
/// and ring over [0, look].
fn engine(look: f64, s: Vect2, v: Vect2, r: &StandIn, relation: Relation, d: f64) -> Timeline {
    let sep = Separation {
        d: d.max(0.0),
        h: 0.0,
    };
    let spans = intervals(look, s, v, &r.p, &r.vels, None, relation, sep);
    Timeline::from_spans(look, &spans)
}

/// The module doc's sandwich of one ring's set over [0, look], δ the stand-in's
/// distance from the model.
fn ring_timeline(look: f64, s: Vect2, v: Vect2, r: &StandIn, set: RingSet, delta: f64) -> Timeline {
    let e = |rel, d: f64| engine(look, s, v, r, rel, d);
    match set {
        RingSet::Outer { d_lo, d_hi } => {
            let upper = e(Relation::Near, next_up(d_hi + delta));
            let lower = if d_lo > delta {
                e(Relation::Near, next_down(d_lo - delta))
            } else {
                e(Relation::Breach, next_up(delta - d_lo)).complement()
            };
            Timeline::sandwich(&lower, &upper)
        }
        RingSet::Hole { d_lo, d_hi } => {
            let upper = e(Relation::Breach, next_up(d_hi + delta));
            let lower = if d_lo > 0.0 && d_lo >= 2.0 * delta {
                e(Relation::Breach, next_down(d_lo - delta))
            } else {
                e(Relation::Near, next_up(delta)).complement()
            };
            Timeline::sandwich(&lower, &upper)
        }
    }
}

/// The timeline of g(τ) ≥ 0 over [0, look] for g linear in time on [0, h] with
/// g(0) ∈ `g0` and g(h) ∈ `g1` (intervals that enclose the model's values): `Yes` where
/// the lower line is ≥ 0, `No` where the upper one is < 0. A line's root s·h, s =
/// a/(a − b) with a, b of opposite signs, has relative error ≤ 3.02u; it is enclosed in
/// [τ(1 − 5u), τ(1 + 5u)] (5u also covers h's own rounding).
fn linear_ge(g0: [f64; 2], g1: [f64; 2], h: f64, look: f64) -> Timeline {
    // The set where the line through (0, a) and (h, b) is ≥ 0, as [lo, hi] with the
    // ends' enclosures, or None.
    let region = |a: f64, b: f64| -> Option<([f64; 2], [f64; 2])> {
        let root = || {
            let tau = a / (a - b) * h;
            [
                (tau * (1.0 - 5.0 * U)).max(0.0),
                (tau * (1.0 + 5.0 * U)).min(look),
            ]
        };
        match (a >= 0.0, b >= 0.0) {
            (true, true) => Some(([0.0, 0.0], [look, look])),
            (true, false) => Some(([0.0, 0.0], root())),
            (false, true) => Some((root(), [look, look])),
            (false, false) => None,
        }
    };
    let certain = region(g0[0], g1[0]);
    let possible = region(g0[1], g1[1]);
    let span = match (certain, possible) {
        (Some((cs, ce)), Some((ps, pe))) if cs[1] <= ce[0] => Span {
            start: End {
                lo: ps[0],
                hi: cs[1],
            },
            end: End {
                lo: ce[0],
                hi: pe[1],
            },
            certain: true,
        },
        (_, Some((ps, pe))) => Span {
            start: End {
                lo: ps[0],
                hi: pe[1],
            },
            end: End {
                lo: ps[0],
                hi: pe[1],
            },
            certain: false,
        },
        (_, None) => return Timeline::constant(0.0, look, Holds::No),
    };
    Timeline::from_spans(look, &[span])
}

/// The vertical condition floor − H ≤ z ≤ ceiling + H over the piece, the heights
/// `z0`, `z1` at its ends with their error bounds (None: unknown).
fn vertical(
    area: &PlaneArea,
    h_sep: f64,
    z0: Option<(f64, f64)>,
    z1: Option<(f64, f64)>,
    h: f64,
    look: f64,
) -> Timeline {
    if area.floor.is_none() && area.ceiling.is_none() {
        return Timeline::constant(0.0, look, Holds::Yes);
    }
    let (Some((z0, e0)), Some((z1, e1))) = (z0, z1) else {
        return Timeline::constant(0.0, look, Holds::Maybe);
    };
    // g = sign·(z − c) with c = bound ∓ H rounded; each value enclosed with its errors.
    let ge = |c: f64, sign: f64| {
        let ec = U * c.abs();
        let at = |z: f64, e: f64| {
            let v = sign * (z - c);
            let r = e + ec + 2.0 * U * v.abs();
            [v - r, v + r]
        };
        linear_ge(at(z0, e0), at(z1, e1), h, look)
    };
    let mut tl = Timeline::constant(0.0, look, Holds::Yes);
    if let Some(f) = area.floor {
        tl = tl.and(&ge(f - h_sep, 1.0));
    }
    if let Some(c) = area.ceiling {
        tl = tl.and(&ge(c + h_sep, -1.0));
    }
    tl
}

/// The stand-in of ring `ring` of part `part` over [t0, t1] (duration h), counterclockwise,
/// and its δ_v (module doc).
fn stand_in(
    area: &PlaneArea,
    part: usize,
    ring: usize,
    t0: f64,
    t1: f64,
    h: f64,
) -> (StandIn, f64) {
    let (p0, e0) = ring_at(area, part, ring, t0);
    let (p1, e1) = ring_at(area, part, ring, t1);
    let mut dv: f64 = 0.0;
    let mut p: Vec<Vect2> = Vec::with_capacity(p0.len());
    let mut vels: Vec<Vect2> = Vec::with_capacity(p0.len());
    for (a, b) in p0.iter().zip(&p1) {
        let d = [b[0] - a[0], b[1] - a[1]];
        dv = dv.max(2.0 * e0 + 2.0 * e1 + 5.0 * U * (d[0].abs() + d[1].abs()));
        p.push(Vect2::new(a[0], a[1]));
        vels.push(Vect2::new(d[0] / h, d[1] / h));
    }
    if polyguard::api::signed_area2(&p) < 0.0 {
        p.reverse();
        vels.reverse();
    }
    (StandIn { p, vels }, dv)
}

/// What the Earth layer adds to a piece (zero on the plane): D's sandwich in plane units
/// (`PlaneRelation::Near`) and extra distances of the mover's and the vertices' model
/// from what is projected.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Margins {
    /// A distance certainly within D.
    pub d_lo: f64,
    /// A distance beyond which the distance certainly exceeds D.
    pub d_hi: f64,
    /// Added to δ_p.
    pub extra_point: f64,
    /// Added to δ_v.
    pub extra_area: f64,
    /// Added to the heights' error bounds at the piece's ends (feet).
    pub extra_z: f64,
}

/// The value over a piece of a ring's set when the piece is far from the ring
/// ([`Prepared::far_from`]): from the exact winding number at the stand-in's start (odd:
/// inside, 0: outside, even and not 0: a ring that is not simple, unknown).
fn far_value(area: &PlaneArea, part: usize, ring: usize, s: [f64; 2], hole: bool) -> Holds {
    let w = winding(ring_of(&area.frames[0], part, ring), s);
    let inside = match w {
        w if w % 2 != 0 => Holds::Yes,
        0 => Holds::No,
        _ => Holds::Maybe,
    };
    if hole {
        inside.negated()
    } else {
        inside
    }
}

/// Whether the stand-in point's segment from `a` to `b`, grown by `reach`, misses the box
/// swept by every edge of the moving stand-in ring over [0, look] (each vertex moves
/// linearly, so an edge stays in the box of its four end positions; those at `look` are
/// rounded, by at most 2u of the coordinates' size, which the growth covers). Then the
/// stand-in point is farther than `reach` from the ring throughout, and the ring's sets
/// are constant over the piece (the `prepared` module doc's argument).
fn swept_far(r: &StandIn, look: f64, a: [f64; 2], b: [f64; 2], reach: f64) -> bool {
    let n = r.p.len();
    let end: Vec<Vect2> = (0..n)
        .map(|i| Vect2::new(r.p[i].x + look * r.vels[i].x, r.p[i].y + look * r.vels[i].y))
        .collect();
    let c = r.p.iter().chain(&end).fold(
        a[0].abs().max(a[1].abs()).max(b[0].abs()).max(b[1].abs()),
        |m, q| m.max(q.x.abs()).max(q.y.abs()),
    );
    let g = next_up(reach + 8.0 * U * c);
    let lo = [a[0].min(b[0]) - g, a[1].min(b[1]) - g];
    let hi = [a[0].max(b[0]) + g, a[1].max(b[1]) + g];
    (0..n).all(|i| {
        let j = (i + 1) % n;
        let xs = [r.p[i].x, r.p[j].x, end[i].x, end[j].x];
        let ys = [r.p[i].y, r.p[j].y, end[i].y, end[j].y];
        let (x0, x1) = (
            xs.iter().fold(f64::INFINITY, |m, &x| m.min(x)),
            xs.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x)),
        );
        let (y0, y1) = (
            ys.iter().fold(f64::INFINITY, |m, &y| m.min(y)),
            ys.iter().fold(f64::NEG_INFINITY, |m, &y| m.max(y)),
        );
        x1 < lo[0] || x0 > hi[0] || y1 < lo[1] || y0 > hi[1]
    })
}

/// The value of inside for the exact winding number of the ring `p` around `a`: odd
/// inside, 0 outside, even and not 0 unknown (a ring that is not simple).
fn winding_of(p: &[Vect2], a: [f64; 2]) -> Holds {
    let ring: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
    let w = winding(&ring, a);
    if w % 2 != 0 {
        Holds::Yes
    } else if w == 0 {
        Holds::No
    } else {
        Holds::Maybe
    }
}

/// The values of the rings' far pieces ([`far_value`]) carried from one piece to the
/// next: a piece far from a ring that starts where the previous far piece of that ring
/// ended has the same value, as the mover has not met the ring in between (both pieces'
/// stand-ins are farther than the reach from it, and they join at the shared fix).
#[derive(Default)]
pub(super) struct FarCache {
    /// Per (part, ring): the end time of the last far piece and its value.
    last: Vec<Vec<Option<(f64, Holds)>>>,
    /// Per (part, ring) of a static ring: the last clip box and the ring clipped to it,
    /// counterclockwise ([`clip_ring`]).
    clips: Vec<Vec<Option<Clip>>>,
}

/// A static ring clipped to a box (the `prepared` module's `clip_ring`), as a stand-in's
/// vertices.
struct Clip {
    lo: [f64; 2],
    hi: [f64; 2],
    p: std::rc::Rc<Vec<Vect2>>,
}

/// Static rings with more vertices than this are clipped to a box around each piece
/// before the engine sees them (a FIR has thousands).
const CLIP_MIN_VERTICES: usize = 32;

impl FarCache {
    /// The static ring `ring` of part `k` clipped to a box around the piece's segment
    /// from `a` to `b` that holds the segment's box grown by `2·reach`: the last clip when
    /// it does, else a new one grown by `2·reach` plus eight times the segment's extent (so
    /// that the next pieces reuse it). Counterclockwise.
    fn clip(
        &mut self,
        area: &PlaneArea,
        k: usize,
        ring: usize,
        a: [f64; 2],
        b: [f64; 2],
        reach: f64,
    ) -> std::rc::Rc<Vec<Vect2>> {
        if self.clips.len() <= k {
            self.clips.resize_with(k + 1, Vec::new);
        }
        if self.clips[k].len() <= ring {
            self.clips[k].resize_with(ring + 1, || None);
        }
        let g = next_up(2.0 * reach);
        let need_lo = [next_down(a[0].min(b[0]) - g), next_down(a[1].min(b[1]) - g)];
        let need_hi = [next_up(a[0].max(b[0]) + g), next_up(a[1].max(b[1]) + g)];
        if let Some(c) = &self.clips[k][ring] {
            if c.lo[0] <= need_lo[0]
                && c.lo[1] <= need_lo[1]
                && c.hi[0] >= need_hi[0]
                && c.hi[1] >= need_hi[1]
            {
                return c.p.clone();
            }
        }
        let ext = 8.0 * (a[0] - b[0]).abs().max((a[1] - b[1]).abs());
        let lo = [need_lo[0] - ext, need_lo[1] - ext];
        let hi = [need_hi[0] + ext, need_hi[1] + ext];
        let clipped = clip_ring(ring_of(&area.frames[0], k, ring), lo, hi);
        let mut p: Vec<Vect2> = clipped.iter().map(|q| Vect2::new(q[0], q[1])).collect();
        if polyguard::api::signed_area2(&p) < 0.0 {
            p.reverse();
        }
        let p = std::rc::Rc::new(p);
        self.clips[k][ring] = Some(Clip {
            lo,
            hi,
            p: p.clone(),
        });
        p
    }
}

impl FarCache {
    /// The cached value of ring `ring` of part `k` for a far piece starting at `t0`, or
    /// `compute`'s, which is remembered with the piece's end `t1`.
    fn value(
        &mut self,
        k: usize,
        ring: usize,
        t0: f64,
        t1: f64,
        compute: impl FnOnce() -> Holds,
    ) -> Holds {
        if self.last.len() <= k {
            self.last.resize(k + 1, Vec::new());
        }
        if self.last[k].len() <= ring {
            self.last[k].resize(ring + 1, None);
        }
        let v = match self.last[k][ring] {
            Some((end, v)) if end == t0 => v,
            _ => compute(),
        };
        self.last[k][ring] = Some((t1, v));
        v
    }

    /// Forgets ring `ring` of part `k` (a piece near it broke the run).
    fn forget(&mut self, k: usize, ring: usize) {
        if let Some(slot) = self.last.get_mut(k).and_then(|r| r.get_mut(ring)) {
            *slot = None;
        }
    }
}

/// One piece's data, as [`piece_timeline`] works it out for its rings.
struct Piece {
    t0: f64,
    t1: f64,
    h: f64,
    look: f64,
    s: Vect2,
    v: Vect2,
    a0: [f64; 2],
    a1: [f64; 2],
    dp: f64,
    c: f64,
    m: Margins,
}

/// Ring `ring` of part `k` over the piece: constant from its exact winding number when the
/// piece is far from it (static rings: the edge tree; moving ones: their swept boxes),
/// else the module doc's sandwich by the engine on the ring (clipped to a box around
/// the piece when it is large and static).
fn ring_piece(
    pc: &Piece,
    cache: &mut FarCache,
    area: &PlaneArea,
    prepared: &Prepared,
    k: usize,
    ring: usize,
) -> Timeline {
    let frame0 = &area.frames[0];
    let hole = ring > 0;
    let (d_lo, d_hi) = (pc.m.d_lo, pc.m.d_hi);
    let set = if hole {
        RingSet::Hole { d_lo, d_hi }
    } else {
        RingSet::Outer { d_lo, d_hi }
    };
    // Static rings: δ_v is the projection's alone; the reach covers every set.
    let reach = next_up(d_hi.max(0.0) + (pc.dp + pc.m.extra_area) * (1.0 + 8.0 * U));
    match prepared.far_from(k, ring, pc.a0, pc.a1, reach) {
        Some(true) => {
            let val = cache.value(k, ring, pc.t0, pc.t1, || {
                far_value(area, k, ring, pc.a0, hole)
            });
            Timeline::constant(0.0, pc.look, val)
        }
        Some(false) if ring_of(frame0, k, ring).len() > CLIP_MIN_VERTICES => {
            cache.forget(k, ring);
            // A clipped vertex lies within 8u·c of its edge (`clip_ring`); twice that.
            let dv = 16.0 * U * pc.c;
            let delta = (pc.dp + dv + pc.m.extra_area) * (1.0 + 8.0 * U);
            let reach = next_up(d_hi.max(0.0) + delta);
            let p = cache.clip(area, k, ring, pc.a0, pc.a1, reach);
            if p.len() < 3 {
                // Nothing of the ring within twice the reach: constant, as far.
                let val = far_value(area, k, ring, pc.a0, hole);
                Timeline::constant(0.0, pc.look, val)
            } else {
                let r = StandIn {
                    p: (*p).clone(),
                    vels: vec![Vect2::new(0.0, 0.0); p.len()],
                };
                ring_timeline(pc.look, pc.s, pc.v, &r, set, delta)
            }
        }
        _ => {
            cache.forget(k, ring);
            let (r, dv) = stand_in(area, k, ring, pc.t0, pc.t1, pc.h);
            // δ summed in f64 (a few terms): relative rounding below 1e-15, covered.
            let delta = (pc.dp + dv + pc.m.extra_area) * (1.0 + 8.0 * U);
            let reach = next_up(d_hi.max(0.0) + delta);
            if swept_far(&r, pc.look, pc.a0, pc.a1, reach) {
                let w = winding_of(&r.p, pc.a0);
                Timeline::constant(0.0, pc.look, if hole { w.negated() } else { w })
            } else {
                ring_timeline(pc.look, pc.s, pc.v, &r, set, delta)
            }
        }
    }
}

/// The timeline of `relation` over the piece [t0, t1] (t0 < t1), in global time: each
/// ring's sandwich (or its constant value when the piece is far from it), the region ∨
/// over parts of (outer ∧ holes), ∧ the vertical condition, moved to t0 with outward
/// rounding and cut to [t0, t1].
#[allow(clippy::too_many_arguments)]
pub(super) fn piece_timeline(
    cache: &mut FarCache,
    fixes: &[PlaneFix],
    area: &PlaneArea,
    prepared: &Prepared,
    h_sep: f64,
    m: Margins,
    t0: f64,
    t1: f64,
) -> Timeline {
    let (h, exact) = diff_exact(t1, t0);
    let look = if exact { h } else { next_up(h) };
    let (a0, e0, z0) = mover_at(fixes, t0);
    let (a1, e1, z1) = mover_at(fixes, t1);
    let da = [a1[0] - a0[0], a1[1] - a0[1]];
    let dp: f64 = (0..2)
        .map(|c| 2.0 * e0[c] + 2.0 * e1[c] + 5.0 * U * da[c].abs())
        .sum::<f64>()
        + m.extra_point;
    let s = Vect2::new(a0[0], a0[1]);
    let v = Vect2::new(da[0] / h, da[1] / h);
    let frame0 = &area.frames[0];
    let mut region = Timeline::constant(0.0, look, Holds::No);
    // Far from the area's box: outside every ring by more than every set's reach. A
    // keyframed vertex's interpolation error is below 80u times the coordinates' size.
    let c = prepared
        .magnitude()
        .max(a0[0].abs())
        .max(a0[1].abs())
        .max(a1[0].abs())
        .max(a1[1].abs());
    let reach_box =
        next_up((m.d_hi.max(0.0) + dp + m.extra_area) * (1.0 + 8.0 * U) + 128.0 * U * c);
    let parts = if prepared.box_meets(a0, a1, reach_box) {
        &frame0.parts[..]
    } else {
        &[]
    };
    let pc = Piece {
        t0,
        t1,
        h,
        look,
        s,
        v,
        a0,
        a1,
        dp,
        c,
        m,
    };
    for (k, part) in parts.iter().enumerate() {
        let mut tl: Option<Timeline> = None;
        for ring in 0..=part.holes.len() {
            let r_tl = ring_piece(&pc, cache, area, prepared, k, ring);
            tl = Some(match tl {
                None => r_tl,
                Some(t) => t.and(&r_tl),
            });
        }
        if let Some(t) = tl {
            region = region.or(&t);
        }
    }
    let widen = |z: Option<(f64, f64)>| z.map(|(z, e)| (z, e + m.extra_z));
    let vert = vertical(area, h_sep, widen(z0), widen(z1), h, look);
    let both = region.and(&vert);
    match both.as_constant() {
        // A constant needs no shift: its window is [t0, t1] exactly.
        Some(v) => Timeline::constant(t0, t1, v),
        None => both.shifted(t0).clipped(t0, t1),
    }
}
