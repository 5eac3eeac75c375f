//! Every sign decision of the f64 engine, in one place.
//!
//! Each predicate names one comparison that paper A's algorithms make, takes the operands
//! the quantity is computed from, and returns the decision. The algorithms never compare
//! a computed f64 with zero or a threshold themselves: a later step can certify each
//! predicate here (a forward error bound, then an exact fallback when the bound straddles
//! the threshold) without touching the algorithms.
//!
//! NaN policy: a NaN can only come from overflow (inputs are validated finite). Where the
//! decision has a "safe" side (the one that leads towards a detection) the predicate is
//! written so that NaN lands there; the doc comment says which. That is why some tests
//! are written as negated comparisons, which clippy would otherwise rewrite.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::vect2::Vect2;

// ---------------------------------------------------------------- §I quadratics

/// §I step 1 of quad_min_le_D: a value of the quadratic at an end of [0, 1] is below D.
/// NaN → true (safe).
#[inline(always)]
pub fn value_below(value: f64, d: f64) -> bool {
    !(value >= d)
}

/// §I step 2 of quad_min_le_D: the parabola opens upwards (a > 0), its vertex −b/(2a)
/// lies in [0, 1] (b ≤ 0 and −b ≤ 2a), and its minimum c − b²/(4a) is below D, i.e.
/// b² − 4a(c − D) > 0 (the OCR'd text lost the minus signs). NaN → false.
#[inline(always)]
pub fn interior_min_below(a: f64, b: f64, c: f64, d: f64) -> bool {
    a > 0.0 && b <= 0.0 && -b <= 2.0 * a && b * b - 4.0 * a * (c - d) > 0.0
}

/// §I steps 5–6 of quad_min_box_le_D: the critical point (mx/disc, my/disc) of the
/// bivariate quadratic lies in the closed unit box and its value there is below D.
/// All tests are scaled by disc² so that no division is needed; disc = 0 fails the
/// last test (0 < 0). NaN → false.
#[inline(always)]
pub fn box_interior_min_below(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, dd: f64) -> bool {
    let disc = c * c - 4.0 * a * b;
    let mx = 2.0 * b * d - c * e;
    let my = 2.0 * a * e - c * d;
    let disc2 = disc * disc;
    let mxd = mx * disc;
    let myd = my * disc;
    if !(0.0 <= mxd && mxd <= disc2 && 0.0 <= myd && myd <= disc2) {
        return false;
    }
    // quad2D(a, b, c, d·disc, e·disc, f·disc²)(mx, my) < D·disc²
    let v = a * mx * mx + b * my * my + c * mx * my + d * disc * mx + e * disc * my + f * disc2;
    v < dd * disc2
}

// ---------------------------------------------------------------- §II.B–E containment

/// §II.B: vertex p is moved by the perturbation: p_y ≥ s_y − BUFF and |p_x − s_x| ≤ BUFF.
/// NaN → true (the vertex is moved, and both P and P*_BUFF are then checked).
#[inline(always)]
pub fn perturbs(p: Vect2, s: Vect2, buff: f64) -> bool {
    !(p.y < s.y - buff) && !((p.x - s.x).abs() > buff)
}

/// §II.C step 1: ‖s − p‖² < BUFF². NaN → true (safe: "near" means "not definitely outside").
#[inline(always)]
pub fn within_buff(p: Vect2, s: Vect2, buff: f64) -> bool {
    !((s - p).sq() >= buff * buff)
}

/// §II.C step 2: p_i ≠ p_j (the segment is not a single point).
#[inline(always)]
pub fn distinct(p: Vect2, q: Vect2) -> bool {
    p != q
}

/// §II.D: p_x ≥ s_x (the vertex is on the ray's side or right of it).
#[inline(always)]
pub fn at_or_right_of(p: Vect2, s: Vect2) -> bool {
    p.x >= s.x
}

/// §II.D: the edge p_i→p_j, whose ends straddle x = s_x, crosses the upward ray from s:
/// (p_jx − p_ix)·((s − p_i)·(p_j − p_i)⊥) ≥ 0. NaN → false.
#[inline(always)]
pub fn ray_crosses(pi: Vect2, pj: Vect2, s: Vect2) -> bool {
    let e = pj - pi;
    (e.x) * (s - pi).dot(e.perp()) >= 0.0
}

// ---------------------------------------------------------------- §II.I intervals

/// The sign of a computed coefficient or discriminant (dot_nn_lin's case split).
/// NaN is reported as zero.
#[inline(always)]
pub fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// Discriminant B² − 4AC of dot_nn_lin's quadratic, and its sign.
#[inline(always)]
pub fn discriminant(a: f64, b: f64, c: f64) -> (f64, i8) {
    let disc = b * b - 4.0 * a * c;
    (disc, sign(disc))
}

/// §II.I edge_detect_simp step 2: max of lower bounds ≤ min of upper bounds.
/// NaN → true (safe).
#[inline(always)]
pub fn intervals_meet(max_lb: f64, min_ub: f64) -> bool {
    !(max_lb > min_ub)
}

// ---------------------------------------------------------------- §III slab

/// §III step 1: a linear height difference z0 + t·w is ≥ 0 at t = 0 (w = 0 case).
#[inline(always)]
pub fn nonnegative(x: f64) -> bool {
    x >= 0.0
}

/// §III step 1: lower end a ≤ upper end b of the slab window. NaN → true (safe).
#[inline(always)]
pub fn window_nonempty(a: f64, b: f64) -> bool {
    !(a > b)
}

pub use crate::predicates::same_velocity;

// ---------------------------------------------------------------- filters

/// §II.E filter, one vertex: hi − lo > 2·m (the same rigorous margin as
/// [`ranges_apart`], which this is with one-point ranges). NaN → false (no filtering).
#[inline(always)]
pub fn gap_exceeds(lo: f64, hi: f64, twice_margin: f64) -> bool {
    hi - lo > twice_margin
}

/// A cheap, rigorous "far apart" test: the x-ranges [a_lo, a_hi] and [b_lo, b_hi] are
/// separated by more than `margin`, judged from one rounded subtraction each.
///
/// fl(b_lo − a_hi) has relative error ≤ 2⁻⁵³, so fl(b_lo − a_hi) > 2·m implies
/// b_lo − a_hi > 2m/(1 + 2⁻⁵³) > m: callers pass twice the distance they need to exceed.
#[inline(always)]
pub fn ranges_apart(a_lo: f64, a_hi: f64, b_lo: f64, b_hi: f64, twice_margin: f64) -> bool {
    b_lo - a_hi > twice_margin || a_lo - b_hi > twice_margin
}

/// Relative size of the rounding allowance in the swept-box filter of edge_detect:
/// forming p + T·v and a box gap takes ≤ 4 roundings of ≤ 2⁻⁵³ of the largest magnitude
/// M involved; 2⁻⁴⁰·M covers them with a factor 2¹¹ to spare.
pub const SWEEP_ROUNDING: f64 = 1.0 / ((1u64 << 40) as f64);

/// Unit roundoff of f64, 2⁻⁵³.
const U: f64 = 1.0 / ((1u64 << 53) as f64);

/// Rigorous side test: +1 when p is farther than `dist` from the line through a and b on
/// its left (a→b), −1 when farther on its right, 0 when unsure.
///
/// orient = (b − a) × (p − a) is computed in f64; Shewchuk's bound
/// |fl(orient) − orient| ≤ (3u + 16u²)·(|b_x − a_x|·|p_y − a_y| + |b_y − a_y|·|p_x − a_x|)
/// is taken as 8u·(…) to cover the rounding of the bound itself. A side is reported when
/// |fl(orient)| − bound > 2·dist·‖b − a‖₁, so the exact |orient| exceeds
/// dist·‖b − a‖₁ ≥ dist·‖b − a‖₂: the exact distance to the line exceeds `dist`.
#[inline(always)]
pub fn line_side(a: Vect2, b: Vect2, p: Vect2, dist: f64) -> i8 {
    let d = b - a;
    let w = p - a;
    let l = d.x * w.y;
    let r = d.y * w.x;
    let orient = l - r;
    let need = 8.0 * U * (l.abs() + r.abs()) + 2.0 * dist * (d.x.abs() + d.y.abs());
    if orient > need {
        1
    } else if -orient > need {
        -1
    } else {
        0
    }
}
