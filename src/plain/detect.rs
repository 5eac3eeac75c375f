//! Paper A §II.H (statically shaped polygons), §II.I (warping polygons) and §III (3D).

use super::contain::definitely_outside;
use super::predicates as pr;
use super::proximity::segments_close;
use crate::polygon::{Moved, VertexSeq};
use crate::vect2::{sqrt, Vect2};

// ===================================================================== §II.H

/// Paper A §II.H detect_same_2D: does s + t·v come within BUFF of the statically shaped
/// polygon P + t·V (all v_i equal) for some t ∈ [0, T]?
///
/// Step 1: s not definitely outside P → true. Step 2: s + T·v not definitely outside
/// P + T·V → true. Step 3: some edge with segments_close(s, s + T·(v − v_i), p_i, p_j,
/// BUFF) → true.
#[inline]
pub fn detect_same_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return false;
    }
    if !definitely_outside(p, s, buff) {
        return true;
    }
    let at_t = Moved { p, v: vels, t };
    if !definitely_outside(&at_t, s.at(v, t), buff) {
        return true;
    }
    // Each vertex's side of the relative path's line is computed once and carried to the
    // next edge: an edge with both ends beyond BUFF on one side is not close (the same
    // rigorous test segments_close starts with, done n instead of 2n times).
    let v0 = vels.vertex(0);
    let path_end = s.at(v - v0, t);
    let mut side_i = pr::line_side(s, path_end, p.vertex(0), buff);
    for i in 0..n {
        let j = p.next(i);
        let side_j = pr::line_side(s, path_end, p.vertex(j), buff);
        let vi = vels.vertex(i);
        let skip = side_i != 0 && side_i == side_j && pr::same_velocity(vi, v0);
        side_i = side_j;
        if skip {
            continue;
        }
        let rel_end = s.at(v - vi, t);
        if segments_close(s, rel_end, p.vertex(i), p.vertex(j), buff) {
            return true;
        }
    }
    false
}

// ===================================================================== §II.I

// The sign σ and the interval type are the engine's (crate::detect).
pub use crate::detect::{Interval, Sign};

/// Roots r1 ≤ r2 of A·t² + B·t + C (A ≠ 0, disc = B² − 4AC > 0), computed without
/// cancellation: q = −(B + sgn(B)·√disc)/2, roots q/A and C/q.
#[inline(always)]
fn roots(a: f64, b: f64, c: f64, disc: f64) -> (f64, f64) {
    let sq = sqrt(disc);
    let q = if b >= 0.0 {
        -0.5 * (b + sq)
    } else {
        -0.5 * (b - sq)
    };
    let x1 = q / a;
    let x2 = c / q;
    if x1 <= x2 {
        (x1, x2)
    } else {
        (x2, x1)
    }
}

/// Paper A §II.I dot_nn_lin (omitted in the paper; derived in docs/derivations.md): one of the two
/// intervals whose union is {t ∈ [0, T] : (ww + t·vv)·(aa + t·bb) ≥ 0}.
///
/// The case analysis, with A = vv·bb, B = ww·bb + vv·aa, C = ww·aa: docs/derivations.md.
#[inline]
pub fn dot_nn_lin(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, sigma: Sign) -> Interval {
    let a = vv.dot(bb);
    let b = ww.dot(bb) + vv.dot(aa);
    let c = ww.dot(aa);
    match pr::sign(a) {
        0 => match (pr::sign(b), sigma) {
            (0, Sign::Pos) if pr::nonnegative(c) => Interval::new(0.0, t),
            (1, Sign::Pos) => Interval::new((-c / b).max(0.0), t),
            (-1, Sign::Neg) => Interval::new(0.0, (-c / b).min(t)),
            _ => Interval::EMPTY,
        },
        1 => {
            let (disc, ds) = pr::discriminant(a, b, c);
            if ds <= 0 {
                match sigma {
                    Sign::Pos => Interval::new(0.0, t),
                    Sign::Neg => Interval::EMPTY,
                }
            } else {
                let (r1, r2) = roots(a, b, c, disc);
                match sigma {
                    Sign::Neg => Interval::new(0.0, r1.min(t)),
                    Sign::Pos => Interval::new(r2.max(0.0), t),
                }
            }
        }
        _ => {
            if sigma == Sign::Neg {
                return Interval::EMPTY;
            }
            let (disc, ds) = pr::discriminant(a, b, c);
            match ds {
                0 => {
                    let r = -b / (2.0 * a);
                    Interval::new(r.max(0.0), r.min(t))
                }
                1 => {
                    let (r1, r2) = roots(a, b, c, disc);
                    Interval::new(r1.max(0.0), r2.min(t))
                }
                _ => Interval::EMPTY,
            }
        }
    }
}

/// Paper A §II.I dot_nn: dot_nn_lin(T, F·aa + σ2·ww, F·bb + σ2·vv, aa, bb, σ1).
///
/// (F·aa + σ2·ww + t(F·bb + σ2·vv))·(aa + t·bb) = F·‖aa + t·bb‖² + σ2·(ww + t·vv)·(aa + t·bb),
/// so σ2 = +1 selects X ≥ −F·g² and σ2 = −1 selects X ≤ F·g²: together |X| ≤ F·g².
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
    let s2 = sigma2.value();
    dot_nn_lin(
        t,
        aa.scale(f) + ww.scale(s2),
        bb.scale(f) + vv.scale(s2),
        aa,
        bb,
        sigma1,
    )
}

/// Both dot_nn intervals of one side σ2: their union is where σ2·X ≥ −F·g².
#[inline(always)]
fn side(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, sigma2: Sign, f: f64) -> [Interval; 2] {
    [
        dot_nn(t, ww, vv, aa, bb, Sign::Neg, sigma2, f),
        dot_nn(t, ww, vv, aa, bb, Sign::Pos, sigma2, f),
    ]
}

/// Paper A §II.I edge_detect_simp: is there a t ∈ [0, T] with
/// |(ww + t·vv)·(aa + t·bb)| ≤ (1 + F)·‖aa + t·bb‖² and
/// |(ww + t·vv)·(aa⊥ + t·bb⊥)| ≤ F·‖aa⊥ + t·bb⊥‖²?
///
/// The paper loops over six signs ε1, ε2, ε3, σ1, σ2, σ3; the combinations with ε2 = −1
/// (σ2 = −1) repeat those with ε2 = +1 (σ2 = +1) with the two intervals swapped, so only
/// ε2 = σ2 = +1 is enumerated: 2⁴ interval intersections over 8 dot_nn intervals.
#[inline]
pub fn edge_detect_simp(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, f: f64) -> bool {
    let (aap, bbp) = (aa.perp(), bb.perp());
    // The perpendicular conditions first: they fail for most edges.
    let p_pos = side(t, ww, vv, aap, bbp, Sign::Pos, f);
    if p_pos[0].is_empty() && p_pos[1].is_empty() {
        return false;
    }
    let p_neg = side(t, ww, vv, aap, bbp, Sign::Neg, f);
    if p_neg[0].is_empty() && p_neg[1].is_empty() {
        return false;
    }
    let f1 = 1.0 + f;
    let a_pos = side(t, ww, vv, aa, bb, Sign::Pos, f1);
    if a_pos[0].is_empty() && a_pos[1].is_empty() {
        return false;
    }
    let a_neg = side(t, ww, vv, aa, bb, Sign::Neg, f1);
    for i1 in &p_pos {
        for i2 in &p_neg {
            let lb12 = i1.lb.max(i2.lb);
            let ub12 = i1.ub.min(i2.ub);
            if !pr::intervals_meet(lb12, ub12) {
                continue;
            }
            for i3 in &a_pos {
                for i4 in &a_neg {
                    let lb = lb12.max(i3.lb).max(i4.lb);
                    let ub = ub12.min(i3.ub).min(i4.ub);
                    if pr::intervals_meet(lb, ub) {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// Filter in front of edge_detect: the boxes swept by the point over [0, T] and by the
/// edge over [0, T] are farther apart than any time edge_detect_simp could accept.
///
/// The edge at time t lies in the box of p_i, p_j, p_i + T·v_i, p_j + T·v_j (each end moves
/// on a segment, the edge is their convex combination), the point in the box of s and
/// s + T·v. A time accepted by edge_detect_simp puts the point within (1 + F)·‖aa‖ of the
/// midpoint along the edge and F·‖aa‖ across it, so within 2F·‖aa(t)‖ ≤ 2F·L of the edge,
/// with L = max(‖aa(0)‖₁, ‖aa(T)‖₁) (a norm is convex in t; ‖·‖₁ ≥ ‖·‖₂). The margin is
/// doubled for [`pr::ranges_apart`] and widened by [`pr::SWEEP_ROUNDING`] for rounding.
///
/// The one exception is an edge that collapses to a point at some t ∈ [0, T] (a repeated
/// vertex, or p_j − p_i + t·(v_j − v_i) = 0): inequalities (1) read 0 ≤ 0 there, so the
/// paper's edge_detect_simp accepts wherever the point is, and this filter rejects when the
/// point is far. That acceptance is a false alarm of the paper on an edge that is not an
/// edge (such a polygon is not well formed, §II.J step 1); a point that really enters
/// crosses a proper edge or the collapsed point, which the neighbouring edges contain.
/// tests/paper_a_functions_vs_oracle.rs checks that this is the only difference.
#[inline(always)]
fn swept_boxes_apart(
    t: f64,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    f: f64,
) -> bool {
    let (qi, qj, st) = (pi.at(vi, t), pj.at(vj, t), s.at(v, t));
    let l0 = (pj.x - pi.x).abs() + (pj.y - pi.y).abs();
    let l1 = (qj.x - qi.x).abs() + (qj.y - qi.y).abs();
    let ex_lo = pi.x.min(pj.x).min(qi.x.min(qj.x));
    let ex_hi = pi.x.max(pj.x).max(qi.x.max(qj.x));
    let ey_lo = pi.y.min(pj.y).min(qi.y.min(qj.y));
    let ey_hi = pi.y.max(pj.y).max(qi.y.max(qj.y));
    let (sx_lo, sx_hi) = (s.x.min(st.x), s.x.max(st.x));
    let (sy_lo, sy_hi) = (s.y.min(st.y), s.y.max(st.y));
    let m = ex_lo
        .abs()
        .max(ex_hi.abs())
        .max(ey_lo.abs().max(ey_hi.abs()))
        .max(
            sx_lo
                .abs()
                .max(sx_hi.abs())
                .max(sy_lo.abs().max(sy_hi.abs())),
        );
    let twice = 2.0 * (2.0 * f * l0.max(l1)) + pr::SWEEP_ROUNDING * m;
    if pr::ranges_apart(ex_lo, ex_hi, sx_lo, sx_hi, twice)
        || pr::ranges_apart(ey_lo, ey_hi, sy_lo, sy_hi, twice)
    {
        return true;
    }
    // The four swept corners on one side of the point's path line, beyond 2F·L: the
    // edge (in their convex hull at every t) never comes within the F slack of the path.
    // The rounded corners and path end are within a few 2⁻⁵³·M of the exact ones, which
    // SWEEP_ROUNDING·M covers.
    if s != st {
        let slack = 2.0 * f * l0.max(l1) + pr::SWEEP_ROUNDING * m;
        let side = pr::line_side(s, st, pi, slack);
        return side != 0
            && side == pr::line_side(s, st, pj, slack)
            && side == pr::line_side(s, st, qi, slack)
            && side == pr::line_side(s, st, qj, slack);
    }
    false
}

/// Paper A §II.I eq (2) edge_detect: does s + t·v meet the moving segment
/// (p_i + t·v_i, p_j + t·v_j) for some t ∈ [0, T] (within the F slack)?
///
/// edge_detect_simp(T, s − (½p_j + ½p_i), v − (½v_j + ½v_i), ½p_j − ½p_i, ½v_j − ½v_i, F):
/// positions relative to the edge's midpoint, against the half-edge vector.
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
    if swept_boxes_apart(t, s, v, pi, pj, vi, vj, f) {
        return false;
    }
    let ww = s - (pj.scale(0.5) + pi.scale(0.5));
    let vv = v - (vj.scale(0.5) + vi.scale(0.5));
    let aa = pj.scale(0.5) - pi.scale(0.5);
    let bb = vj.scale(0.5) - vi.scale(0.5);
    edge_detect_simp(t, ww, vv, aa, bb, f)
}

/// Paper A §II.I detect_diff_2D: s not definitely outside P, or some moving edge met by
/// s + t·v within [0, T] (edge_detect).
#[inline]
pub fn detect_diff_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, f: f64, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return false;
    }
    if !definitely_outside(p, s, buff) {
        return true;
    }
    for i in 0..n {
        let j = p.next(i);
        if edge_detect(
            t,
            s,
            v,
            p.vertex(i),
            p.vertex(j),
            vels.vertex(i),
            vels.vertex(j),
            f,
        ) {
            return true;
        }
    }
    false
}

// ===================================================================== §III

/// Paper A §III step 1: the exact window [a, b] ⊆ [0, T] in which the height s_z + t·v_z
/// lies in [pmin + t·vsp, pmax + t·vsp]; `None` when there is no such time.
///
/// With w = v_z − vsp, z0 = s_z − pmin, z1 = pmax − s_z the conditions are z0 + t·w ≥ 0
/// and z1 − t·w ≥ 0: for w = 0 both must hold at once; for w > 0,
/// t ∈ [−z0/w, z1/w]; for w < 0, t ∈ [z1/w, −z0/w].
#[inline]
pub fn slab_window(t: f64, sz: f64, vz: f64, pmin: f64, pmax: f64, vsp: f64) -> Option<(f64, f64)> {
    let w = vz - vsp;
    let z0 = sz - pmin;
    let z1 = pmax - sz;
    let (a, b) = match pr::sign(w) {
        0 => {
            if pr::nonnegative(z0) && pr::nonnegative(z1) {
                (0.0, t)
            } else {
                return None;
            }
        }
        1 => ((-z0 / w).max(0.0), (z1 / w).min(t)),
        _ => ((z1 / w).max(0.0), (-z0 / w).min(t)),
    };
    if pr::window_nonempty(a, b) {
        Some((a, b))
    } else {
        None
    }
}

pub use crate::detect::statically_shaped;

/// Paper A §III detect_3D: 2D detection (detect_same_2D when all vertex velocities are
/// equal, detect_diff_2D otherwise) from s + a·v and P + a·V over the lookahead b − a,
/// where [a, b] is the slab window of [`slab_window`].
///
/// When a = 0 the inputs are used unshifted, so no rounding is added.
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
    let Some((a, b)) = slab_window(t, sz, vz, pmin, pmax, vsp) else {
        return false;
    };
    let same = crate::detect::dispatch(false, vels) == crate::detect::Method::DetectSame2d;
    if a == 0.0 {
        if same {
            detect_same_2d(b, s, v, p, vels, buff)
        } else {
            detect_diff_2d(b, s, v, p, vels, f, buff)
        }
    } else {
        let sa = s.at(v, a);
        let n = p.count();
        if n <= SHIFT_BUFFER {
            // P + a·V once, on the stack (no heap), instead of on every vertex access.
            let mut buf = [Vect2::ZERO; SHIFT_BUFFER];
            for (i, q) in buf.iter_mut().enumerate().take(n) {
                *q = p.vertex(i).at(vels.vertex(i), a);
            }
            let pa = &buf[..n];
            if same {
                detect_same_2d(b - a, sa, v, pa, vels, buff)
            } else {
                detect_diff_2d(b - a, sa, v, pa, vels, f, buff)
            }
        } else {
            let pa = Moved { p, v: vels, t: a };
            if same {
                detect_same_2d(b - a, sa, v, &pa, vels, buff)
            } else {
                detect_diff_2d(b - a, sa, v, &pa, vels, f, buff)
            }
        }
    }
}

/// Polygons up to this many vertices are shifted to the slab window's start in a stack
/// buffer by detect_3d (1 KiB); larger ones are read through a [`Moved`] view.
pub const SHIFT_BUFFER: usize = 64;
