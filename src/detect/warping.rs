//! Paper A §II.I: detection for warping polygons, from dot_nn_lin and dot_nn through
//! edge_detect_simp and edge_detect to detect_diff_2D (and its run over a slab window's
//! part of the motion, which §III asks for).

use super::filter::lanes::{self, Kernel, KernelFn, LANES};
use super::filter::{never_collapses, swept_boxes_apart, Sweep};
use super::roots::{ball_set, below_zero_on};
use super::{Interval, Sign};
use crate::ball::{self, exact, nonnegative, Ball, BallV, Tri};
use crate::contain::{definitely_outside_rel, AtTime};
use crate::polygon::VertexSeq;
use crate::predicates as pr;
use crate::vect2::Vect2;

mod crossing;
use crossing::crossing_witness;
#[cfg(test)]
use crossing::{conditions_hold_at, crossing_times};

/// Coefficients (t², t, 1) of (ww + t·vv)·(aa + t·bb) as balls. `zero` says which of
/// ww, vv, aa, bb are known to be exactly 0 (from the inputs): the products they enter
/// are then exact 0s, not balls of radius ETA (which would blur a line into a parabola).
#[inline(always)]
fn dot_coeffs(ww: BallV, vv: BallV, aa: BallV, bb: BallV, zero: [bool; 4]) -> [Ball; 3] {
    let [w0, v0, a0, b0] = zero;
    let z = Ball::exact(0.0);
    let dot = |x: BallV, y: BallV, x0: bool, y0: bool| if x0 || y0 { None } else { Some(x.dot(y)) };
    let a = dot(vv, bb, v0, b0).unwrap_or(z);
    let b = match (dot(ww, bb, w0, b0), dot(vv, aa, v0, a0)) {
        (Some(p), Some(q)) => p.add(q),
        (Some(p), None) | (None, Some(p)) => p,
        (None, None) => z,
    };
    let c = dot(ww, aa, w0, a0).unwrap_or(z);
    [a, b, c]
}

/// Paper A §II.I dot_nn_lin (omitted in the paper; derived in docs/derivations.md): one of the
/// two intervals whose union is {t ∈ [0, T] : (ww + t·vv)·(aa + t·bb) ≥ 0}.
///
/// Certified as an outer enclosure: the returned interval contains the exact one.
///
/// ```
/// use polyguard::{dot_nn_lin, Sign, Vect2};
/// // (ww + t·vv)·aa = t − 1 with ww = (−1, 0), vv = (1, 0), aa = (1, 0), bb = 0:
/// // non-negative exactly on [1, T]
/// let (ww, vv, aa, bb) = (Vect2::new(-1.0, 0.0), Vect2::new(1.0, 0.0), Vect2::new(1.0, 0.0), Vect2::ZERO);
/// let both = [Sign::Neg, Sign::Pos].map(|sigma| dot_nn_lin(3.0, ww, vv, aa, bb, sigma));
/// let covers = |t: f64| both.iter().any(|i| !i.is_empty() && i.lb <= t && t <= i.ub);
/// assert!(covers(1.0) && covers(2.5) && covers(3.0));
/// assert!(!covers(0.5));
/// ```
#[inline]
pub fn dot_nn_lin(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, sigma: Sign) -> Interval {
    let e = BallV::exact;
    let zero = [ww, vv, aa, bb].map(|x| x == Vect2::ZERO);
    let [a, b, c] = dot_coeffs(e(ww), e(vv), e(aa), e(bb), zero);
    let set = ball_set(a, b, c, 0.0, t, true);
    match sigma {
        Sign::Neg => set[0],
        Sign::Pos => set[1],
    }
}

/// Paper A §II.I dot_nn: dot_nn_lin(T, F·aa + σ2·ww, F·bb + σ2·vv, aa, bb, σ1).
///
/// (F·aa + σ2·ww + t(F·bb + σ2·vv))·(aa + t·bb) = F·‖aa + t·bb‖² + σ2·(ww + t·vv)·(aa + t·bb),
/// so σ2 = +1 selects X ≥ −F·g² and σ2 = −1 selects X ≤ F·g²: together |X| ≤ F·g².
/// Certified as an outer enclosure, with F·aa + σ2·ww formed on balls.
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
    let e = BallV::exact;
    let k = Ball::exact(f);
    let s2 = Ball::exact(sigma2.value());
    let w2 = e(aa).scale(k).add(e(ww).scale(s2));
    let v2 = e(bb).scale(k).add(e(vv).scale(s2));
    let z = |x: Vect2| x == Vect2::ZERO;
    let zero = [z(aa) && z(ww), z(bb) && z(vv), z(aa), z(bb)];
    let [a, b, c] = dot_coeffs(w2, v2, e(aa), e(bb), zero);
    let set = ball_set(a, b, c, 0.0, t, true);
    match sigma1 {
        Sign::Neg => set[0],
        Sign::Pos => set[1],
    }
}

/// Does some choice of one interval from each of the four pairs have a common point?
/// (edge_detect_simp step 2: max of the lower ends ≤ min of the upper ends.)
#[inline]
fn some_choice_meets(sets: &[[Interval; 2]; 4]) -> bool {
    first_meeting(sets).is_some()
}

/// Paper A §II.I edge_detect_simp step 2: the common part [lb, ub] of the first choice (one interval from each of the four
/// pairs) that has one, as in [`some_choice_meets`].
#[inline]
fn first_meeting(sets: &[[Interval; 2]; 4]) -> Option<(f64, f64)> {
    for i1 in &sets[0] {
        for i2 in &sets[1] {
            let (lb12, ub12) = (i1.lb.max(i2.lb), i1.ub.min(i2.ub));
            if lb12 > ub12 {
                continue;
            }
            for i3 in &sets[2] {
                for i4 in &sets[3] {
                    let (lb, ub) = (lb12.max(i3.lb).max(i4.lb), ub12.min(i3.ub).min(i4.ub));
                    if lb <= ub {
                        return Some((lb, ub));
                    }
                }
            }
        }
    }
    None
}

/// Paper A §II.I (edge_detect_simp): a quadratic with ball coefficients (t², t, 1) at an exact time t ≥ 0, by Horner's
/// rule on balls: the exact quadratic's value at t lies in the result.
#[inline(always)]
fn quad_at(c: &[Ball; 3], t: f64) -> Ball {
    c[0].scale(t).add(c[1]).scale(t).add(c[2])
}

/// Paper A §II.I edge_detect_simp: is there a t ∈ [0, T] with
/// |(ww + t·vv)·(aa + t·bb)| ≤ (1 + F)·‖aa + t·bb‖² and
/// |(ww + t·vv)·(aa⊥ + t·bb⊥)| ≤ F·‖aa⊥ + t·bb⊥‖²? Certified (see
/// [`edge_detect_simp_tri`]).
///
/// ```
/// use polyguard::{edge_detect_simp, Vect2};
/// // 2 left of an edge's midpoint, moving right at 1, against the half-edge (0, 1)
/// let (ww, aa, bb) = (Vect2::new(-2.0, 0.0), Vect2::new(0.0, 1.0), Vect2::ZERO);
/// assert!(edge_detect_simp(5.0, ww, Vect2::new(1.0, 0.0), aa, bb, 1e-4));
/// assert!(!edge_detect_simp(5.0, ww, Vect2::new(-1.0, 0.0), aa, bb, 1e-4)); // moving away
/// ```
#[inline]
pub fn edge_detect_simp(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2, f: f64) -> bool {
    let e = BallV::exact;
    let bb0 = bb == Vect2::ZERO;
    edge_detect_simp_tri(
        Ball::exact(0.0),
        Ball::exact(t),
        e(ww),
        e(vv),
        e(aa),
        e(bb),
        bb0,
        f,
    )
    .or_true()
}

/// The four quadratics of edge_detect_simp (§II.I), F·‖a‖² + w×a, F·‖a‖² − w×a,
/// K·‖a‖² + w·a and K·‖a‖² − w·a (K = 1 + F, a = aa + t·bb, w = ww + t·vv), as balls of
/// coefficients (t², t, 1): each coefficient is computed in floats, and its radius is a
/// static bound on the distance to the exact coefficient, for every exact input within
/// the balls ww, vv, aa, bb and k1 ∋ 1 + F.
///
/// Derivation. For vectors x, y known within r_x, r_y per coordinate, with
/// n_x = |x̃₁| + |x̃₂|, the exact x·y (or x × y) lies within
/// n_x·r_y + n_y·r_x + 2·r_x·r_y of x̃·ỹ (each of the two products moves by at most
/// |x̃ᵢ|·r_y + |ỹᵢ|·r_x + r_x·r_y), and fl(fl(x̃₁ỹ₁) ± fl(x̃₂ỹ₂)) within
/// u·(|x̃₁ỹ₁| + |x̃₂ỹ₂|)·(2 + u) ≤ 3u·n_x·n_y of x̃·ỹ: that is [`pair_err`]. A sum of two
/// such products adds u·|sum|. A coefficient c = K·g ± h (g of ‖a‖², h of w·a or w × a)
/// with K within r_K of k̃ is within |k̃|·E_g + r_K·(|g̃| + E_g) + E_h of k̃·g̃ ± h̃, and its
/// two roundings add u·|fl(k̃g̃)| + u·|c̃| ≤ 2u·|fl(k̃g̃)| + u·(1 + u)·|h̃|, so one bound
/// serves both signs. Every bound is a sum of products of non-negative floats at most
/// [`ball::UP_OPS`] roundings deep, raised by [`ball::up`] (which also covers underflow).
/// When bb is exactly 0 (`bb0`) the t² coefficients are exact zeros.
///
/// The detector forms the two pairs apart ([`SimpTerms::pair`]), the along pair only
/// when the perpendicular one leaves a chance; this composition of both is what the
/// contract tests check in exact arithmetic.
#[cfg_attr(not(test), allow(dead_code))]
fn simp_quadratics(
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    bb0: bool,
    k1: Ball,
    f: f64,
) -> [[Ball; 3]; 4] {
    let terms = SimpTerms::new(ww, vv, aa, bb, bb0);
    let [p_pos, p_neg] = terms.pair(Ball::exact(f), true);
    let [a_pos, a_neg] = terms.pair(k1, false);
    [p_pos, p_neg, a_pos, a_neg]
}

/// What the pairs of [`simp_quadratics`] share: the centres, ‖a‖²'s coefficients g and
/// their bounds eg, and the four product bounds of h's coefficients.
#[derive(Clone, Copy)]
struct SimpTerms {
    w: Vect2,
    v: Vect2,
    a: Vect2,
    b: Vect2,
    bb0: bool,
    g: [f64; 3],
    eg: [f64; 3],
    /// [`pair_err`] of v·b, w·b, v·a and w·a (the same for the cross products).
    e: [f64; 4],
}

impl SimpTerms {
    /// Paper A §II.I (edge_detect_simp): the shared terms of [`simp_quadratics`].
    #[inline(always)]
    fn new(ww: BallV, vv: BallV, aa: BallV, bb: BallV, bb0: bool) -> SimpTerms {
        let n = |x: BallV| x.v.x.abs() + x.v.y.abs();
        let (nw, nv, na, nb) = (n(ww), n(vv), n(aa), n(bb));
        let (rw, rv, ra, rb) = (ww.r, vv.r, aa.r, bb.r);
        let (a, b) = (aa.v, bb.v);
        SimpTerms {
            w: ww.v,
            v: vv.v,
            a,
            b,
            bb0,
            g: [b.dot(b), 2.0 * a.dot(b), a.dot(a)],
            eg: [
                pair_err(nb, rb, nb, rb),
                2.0 * pair_err(na, ra, nb, rb),
                pair_err(na, ra, na, ra),
            ],
            e: [
                pair_err(nv, rv, nb, rb),
                pair_err(nw, rw, nb, rb),
                pair_err(nv, rv, na, ra),
                pair_err(nw, rw, na, ra),
            ],
        }
    }

    /// Paper A §II.I (edge_detect_simp): one pair of [`simp_quadratics`], k·‖a‖² + h and
    /// k·‖a‖² − h with h = w × a (`perp`, k = F exactly) or h = w·a (k = k1), by the
    /// bounds derived there. Formed apart so that the along pair is computed only when
    /// the perpendicular one leaves a chance.
    #[inline(always)]
    fn pair(&self, k: Ball, perp: bool) -> [[Ball; 3]; 2] {
        let (w, v, a, b) = (self.w, self.v, self.a, self.b);
        let (g, eg) = (self.g, self.eg);
        // h = h2·t² + h1·t + h0 of w·a or w × a.
        let prod = |x: Vect2, y: Vect2| if perp { x.dot(y.perp()) } else { x.dot(y) };
        let h = [prod(v, b), prod(w, b) + prod(v, a), prod(w, a)];
        let [e_vb, e_wb, e_va, e_wa] = self.e;
        let e = [e_vb, e_wb + e_va + ball::U * h[1].abs(), e_wa];
        // The values of both signs and their shared radii.
        let kg = [k.z * g[0], k.z * g[1], k.z * g[2]];
        let r = |i: usize| {
            ball::up(
                k.z.abs() * eg[i]
                    + k.r * (g[i].abs() + eg[i])
                    + e[i]
                    + 2.0 * ball::U * kg[i].abs()
                    + 2.0 * ball::U * h[i].abs(),
            )
        };
        let rs = [r(0), r(1), r(2)];
        let c = |i: usize, sigma: f64| {
            if self.bb0 && i == 0 {
                Ball::exact(0.0)
            } else {
                Ball {
                    z: if sigma > 0.0 {
                        kg[i] + h[i]
                    } else {
                        kg[i] - h[i]
                    },
                    r: rs[i],
                }
            }
        };
        [
            [c(0, 1.0), c(1, 1.0), c(2, 1.0)],
            [c(0, -1.0), c(1, -1.0), c(2, -1.0)],
        ]
    }
}

/// Paper A §II.I (edge_detect_simp): the bound of [`simp_quadratics`] on |x·y − fl(x̃·ỹ)| (or the cross product) for
/// vectors known within r_x and r_y per coordinate, n_x = ‖x̃‖₁, n_y = ‖ỹ‖₁:
/// n_x·r_y + n_y·r_x + 2·r_x·r_y + 3u·n_x·n_y, raised by [`ball::up`].
#[inline(always)]
fn pair_err(nx: f64, rx: f64, ny: f64, ry: f64) -> f64 {
    ball::up(nx * ry + ny * rx + 2.0 * rx * ry + 3.0 * ball::U * (nx * ny))
}

/// Paper A §II.I edge_detect_simp over the time window [ta, tb], three-valued, on balls.
///
/// The paper loops over six signs and intersects four dot_nn intervals per choice. A
/// choice meets exactly when some t lies in all four unions, i.e. when the four
/// quadratics (1 + F)‖a‖² ∓ w·a and F‖a‖² ∓ w×a (a = aa + t·bb, w = ww + t·vv; w·a⊥ =
/// w × a) are all ≥ 0 at one t. Their coefficients share nine dot and cross products,
/// formed once, with static error bounds (`simp_quadratics`). Each quadratic's set is
/// enclosed from outside and from inside (`ball_set`): no meeting of the outer sets is
/// a certain `No`; a time at which all four are certainly ≥ 0 (`quad_at`), or a
/// meeting of the inner sets, a certain `Yes`; anything between is `Unsure`. The
/// perpendicular conditions go first: they fail for most edges, and where they hold
/// (short intervals) the along conditions are usually settled by one evaluation, without
/// their roots. `bb0` says that bb is exactly 0 (a translating edge, v_i = v_j): the t²
/// coefficients are then exact zeros, and the quadratics lines.
#[doc(hidden)]
pub fn edge_detect_simp_tri(
    ta: Ball,
    tb: Ball,
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    bb0: bool,
    f: f64,
) -> Tri {
    simp_window(ta, tb, ww, vv, aa, bb, bb0, f)
}

/// Paper A §II.I edge_detect_simp over [ta, tb]: [`edge_detect_simp_tri`], inlined into
/// the detectors' edge loops so that the window's ends, exact floats from 0 there, fold
/// into its interval arithmetic.
// Long because its stages (the crossing, the perpendicular sets, their meetings, the
// along sets) share the window, the quadratics and the sets: the perpendicular sets in a
// function of their own cost 0.8–1.5 % more instructions on the hot path (measured).
#[inline(always)]
fn simp_window(
    ta: Ball,
    tb: Ball,
    ww: BallV,
    vv: BallV,
    aa: BallV,
    bb: BallV,
    bb0: bool,
    f: f64,
) -> Tri {
    let (one_f, err) = exact::two_sum(1.0, f);
    let k1 = Ball {
        z: one_f,
        r: err.abs(),
    };
    let (lo, hi) = (ta.lo().max(0.0), tb.hi());
    if !(lo.is_finite() && hi.is_finite()) {
        return Tri::Unsure;
    }
    // The inner window: times that lie in [ta, tb] for every exact ta and tb.
    let (ilo, ihi) = (ta.hi().max(0.0), tb.lo());
    // Most edges met are met where the point crosses the edge's line: a certain yes
    // there costs no coefficient radii and no root sets.
    if crossing_witness(ilo, ihi, ww, vv, aa, bb, k1, f).is_some() {
        return Tri::Yes;
    }
    let terms = SimpTerms::new(ww, vv, aa, bb, bb0);
    let [q0, q1] = terms.pair(Ball::exact(f), true);
    let empty = |s: &[Interval; 2]| s[0].is_empty() && s[1].is_empty();
    let outer = |c: &[Ball; 3]| ball_set(c[0], c[1], c[2], lo, hi, true);
    // Either set empty is a certain no. Where w × a is positive at the window's middle
    // (in floats: a guess, which decides nothing) F·‖a‖² − w × a is the likelier to be
    // negative all along, so its set is formed first; the sets are the same either way.
    let mid = 0.5 * lo + 0.5 * hi;
    let y_mid = ((q0[0].z - q1[0].z) * mid + (q0[1].z - q1[1].z)) * mid + (q0[2].z - q1[2].z);
    let (p_pos, p_neg) = if y_mid > 0.0 {
        let p_neg = outer(&q1);
        if empty(&p_neg) {
            return Tri::No;
        }
        (outer(&q0), p_neg)
    } else {
        let p_pos = outer(&q0);
        if empty(&p_pos) {
            return Tri::No;
        }
        (p_pos, outer(&q1))
    };
    if empty(&p_pos) || empty(&p_neg) {
        return Tri::No;
    }
    let [q2, q3] = terms.pair(k1, false);
    let q = [q0, q1, q2, q3];
    let yes_at = |t: f64| {
        let t = t.max(ilo).min(ihi);
        // The along conditions first: where the perpendicular ones meet, they are the
        // ones that fail when the edge is missed.
        ilo <= ihi
            && [2, 3, 0, 1]
                .iter()
                .all(|&k| nonnegative(quad_at(&q[k], t)) == Tri::Yes)
    };
    // The perpendicular conditions hold only on the meetings J of their two outer sets,
    // short intervals around the times the point crosses the edge's line. On each J,
    // either an along quadratic is certainly negative all over J ([`below_zero_on`], on
    // the coefficients' upper ends, which bound the exact quadratic for t ≥ 0): J holds
    // no solution; or one time (its middle) certainly satisfies all four quadratics — a
    // certain yes. Only when some J is settled neither way are the along
    // quadratics' sets formed (below).
    let mut settled = true;
    let below =
        |c: &[Ball; 3], l: f64, h: f64| below_zero_on(c[0].hi(), c[1].hi(), c[2].hi(), l, h);
    for i1 in &p_pos {
        for i2 in &p_neg {
            let (jl, ju) = (i1.lb.max(i2.lb), i1.ub.min(i2.ub));
            if jl > ju {
                continue;
            }
            // The cheap test first: an along quadratic below zero all over J rules out a
            // certain yes at J's middle, so the order changes no answer.
            if below(&q[2], jl, ju) || below(&q[3], jl, ju) {
                continue;
            }
            if yes_at(0.5 * jl + 0.5 * ju) {
                return Tri::Yes;
            }
            settled = false;
        }
    }
    if settled {
        return Tri::No;
    }
    let a_pos = outer(&q[2]);
    if empty(&a_pos) {
        return Tri::No;
    }
    let a_neg = outer(&q[3]);
    let Some((lb, ub)) = first_meeting(&[p_pos, p_neg, a_pos, a_neg]) else {
        return Tri::No;
    };
    // A certain yes from the middle of the outer sets' meeting, as above.
    if yes_at(0.5 * lb + 0.5 * ub) {
        return Tri::Yes;
    }
    let inner = q.map(|c| ball_set(c[0], c[1], c[2], ilo, ihi, false));
    if some_choice_meets(&inner) {
        Tri::Yes
    } else {
        Tri::Unsure
    }
}

/// Paper A §II.I eq (2) edge_detect: does s + t·v meet the moving segment
/// (p_i + t·v_i, p_j + t·v_j) for some t ∈ [0, T] (within the F slack)?
///
/// edge_detect_simp(T, s − (½p_j + ½p_i), v − (½v_j + ½v_i), ½p_j − ½p_i, ½v_j − ½v_i, F):
/// positions relative to the edge's midpoint, against the half-edge vector. Certified.
///
/// ```
/// use polyguard::{edge_detect, Vect2};
/// let (pi, pj, rest) = (Vect2::new(2.0, -1.0), Vect2::new(2.0, 1.0), Vect2::ZERO);
/// let s = Vect2::ZERO;
/// // moving right, the point crosses the edge x = 2 at t = 2
/// assert!(edge_detect(5.0, s, Vect2::new(1.0, 0.0), pi, pj, rest, rest, 1e-4));
/// assert!(!edge_detect(5.0, s, Vect2::new(-1.0, 0.0), pi, pj, rest, rest, 1e-4));
/// ```
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
    let sweep = Sweep::new(0.0, t, s, v);
    edge_detect_window(
        &sweep,
        Ball::exact(0.0),
        Ball::exact(t),
        s,
        v,
        pi,
        pj,
        vi,
        vj,
        f,
    )
    .or_true()
}

/// edge_detect over the window [ta, tb] of the original motion, three-valued: the
/// paper's edge_detect(tb − ta, s + ta·v, v, p_i + ta·v_i, …) asks for a time of
/// [ta, tb] at which the same four quadratics of t hold.
///
/// ww = −((p_i − s) + (p_j − s))/2, vv = −((v_i − v) + (v_j − v))/2, aa = (p_j − p_i)/2,
/// bb = (v_j − v_i)/2, each on balls.
#[inline(always)]
fn edge_detect_window(
    sweep: &Sweep,
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    f: f64,
) -> Tri {
    if swept_boxes_apart(sweep, pi, pj, vi, vj, f)
        && never_collapses(sweep.t0, sweep.t1, pi, pj, vi, vj)
    {
        return Tri::No;
    }
    edge_detect_simp_window(ta, tb, s, v, pi, pj, vi, vj, f)
}

/// edge_detect over the window [ta, tb] past its filter (see [`edge_detect_window`]):
/// edge_detect_simp on the edge's ww, vv, aa, bb, each formed with one static error bound
/// ([`BallV::mid_offset`], [`BallV::half_diff`]) rather than a ball per operation.
#[inline(always)]
fn edge_detect_simp_window(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    f: f64,
) -> Tri {
    let ww = BallV::mid_offset(pi, pj, s);
    let vv = BallV::mid_offset(vi, vj, v);
    let aa = BallV::half_diff(pj, pi);
    let bb = BallV::half_diff(vj, vi);
    simp_window(ta, tb, ww, vv, aa, bb, vi == vj, f)
}

/// Paper A §II.I detect_diff_2D: s not definitely outside P, or some moving edge met by
/// s + t·v within [0, T] (edge_detect). Certified: `false` only when the exact answer is.
///
/// ```
/// use polyguard::{detect_diff_2d, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// // drifting east at 1 while each side moves out at 0.1: a warping polygon
/// let vels = [Vect2::new(0.9, -0.1), Vect2::new(1.1, -0.1), Vect2::new(1.1, 0.1), Vect2::new(0.9, 0.1)];
/// // from (5, −4) north at 1, the point meets the south side at t = 40/11 ≈ 3.64
/// let (s, north) = (Vect2::new(5.0, -4.0), Vect2::new(0.0, 1.0));
/// assert!(detect_diff_2d(10.0, s, north, &square[..], &vels[..], 1e-4, 0.01));
/// assert!(!detect_diff_2d(3.0, s, north, &square[..], &vels[..], 1e-4, 0.01));
/// ```
#[inline]
pub fn detect_diff_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, f: f64, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_diff_2d_tri(t, s, v, p, vels, f, buff).or_true()
}

/// Paper A §II.I detect_diff_2D, three-valued (see [`detect_diff_2d`]).
#[inline]
pub fn detect_diff_2d_tri<P, V>(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    f: f64,
    buff: f64,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    diff_window(Ball::exact(0.0), Ball::exact(t), s, v, p, vels, f, buff)
}

/// detect_diff_2D over the window [ta, tb] of the original motion (see
/// [`same_window`](super::same::same_window)); inlined for the same reason.
#[inline(always)]
pub(super) fn diff_window<P, V>(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    f: f64,
    buff: f64,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return Tri::No;
    }
    // The edges first, then the start's containment: the answer is their disjunction
    // whatever the order, and a point that crosses an edge is settled without the
    // containment test.
    match diff_edges(ta, tb, s, v, p, vels, f) {
        Tri::Yes => Tri::Yes,
        acc => match definitely_outside_rel(
            &AtTime {
                p,
                vels,
                s,
                v,
                t: ta,
            },
            buff,
        ) {
            Tri::No => Tri::Yes,
            Tri::Unsure => Tri::Unsure,
            Tri::Yes => acc,
        },
    }
}

/// Paper A §II.I detect_diff_2D's loop over the edges (see [`diff_window`]): `Yes` at the
/// first edge that edge_detect certainly meets, `Unsure` if some edge is undecided, else
/// `No`.
#[inline(always)]
fn diff_edges<P, V>(ta: Ball, tb: Ball, s: Vect2, v: Vect2, p: &P, vels: &V, f: f64) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    let mut acc = Tri::No;
    let sweep = Sweep::new(ta.lo().max(0.0), tb.hi(), s, v);
    // With the vertices and velocities stored contiguously, the filter takes four edges
    // at a time ([`diff_masked`]): the same tests, hence the same edges tested in full,
    // in the same order.
    if let (Some(ps), Some(vs)) = (p.as_slice(), vels.as_slice()) {
        if ps.len() == n && vs.len() == n {
            let masked = DiffMasked {
                ta,
                tb,
                s,
                v,
                ps,
                vs,
                f,
                sweep,
                acc,
            };
            return lanes::with_kernel(masked);
        }
    }
    for i in 0..n {
        let j = p.next(i);
        let (pi, pj) = (p.vertex(i), p.vertex(j));
        let (vi, vj) = (vels.vertex(i), vels.vertex(j));
        match edge_detect_window(&sweep, ta, tb, s, v, pi, pj, vi, vj, f) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

/// [`diff_window`]'s edge loop on contiguously stored vertices and velocities, for
/// [`lanes::with_kernel`].
struct DiffMasked<'a> {
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    ps: &'a [Vect2],
    vs: &'a [Vect2],
    f: f64,
    sweep: Sweep,
    /// definitely_outside's answer (`No` or `Unsure`).
    acc: Tri,
}

impl KernelFn<Tri> for DiffMasked<'_> {
    #[inline(always)]
    fn call<K: Kernel>(self, k: K) -> Tri {
        diff_masked(self, k)
    }
}

/// Paper A §II.I detect_diff_2D's edge loop with edge_detect's filter four edges at a
/// time: edge i is left out when its [`swept_boxes_apart`] bit is set and it
/// [`never_collapses`], as [`edge_detect_window`] leaves it out; the edges left go
/// through edge_detect_simp in increasing order, the first certain yes answering.
/// Groups of [`LANES`] edges from [`LANES`] consecutive vertices; the last group of a
/// polygon whose size is not a multiple of [`LANES`] is the last [`LANES`] edges, of
/// which only those not yet visited are read (below [`LANES`] vertices, the edges repeat
/// cyclically).
#[inline(always)]
fn diff_masked<K: Kernel>(d: DiffMasked<'_>, k: K) -> Tri {
    let (ps, vs, w) = (d.ps, d.vs, &d.sweep);
    let n = ps.len();
    let mut acc = d.acc;
    let mut i = 0;
    while i < n {
        let g = i.min(n.saturating_sub(LANES));
        // The vertex after the group: g + LANES ≤ n once n ≥ LANES, so only a polygon of
        // fewer than LANES vertices needs the remainder (a division).
        let j = if g + LANES < n {
            g + LANES
        } else if n >= LANES {
            0
        } else {
            (g + LANES) % n
        };
        let bits = match (
            ps[g..].first_chunk::<LANES>(),
            vs[g..].first_chunk::<LANES>(),
        ) {
            (Some(p), Some(v)) => k.apart(w, p, ps[j], v, vs[j], d.f),
            _ => {
                let cyc = |s: &[Vect2]| core::array::from_fn(|l| s[(g + l) % n]);
                k.apart(w, &cyc(ps), ps[j], &cyc(vs), vs[j], d.f)
            }
        } >> (i - g);
        for e in i..(g + LANES).min(n) {
            let j = if e + 1 == n { 0 } else { e + 1 };
            let (pi, pj, vi, vj) = (ps[e], ps[j], vs[e], vs[j]);
            if (bits >> (e - i)) & 1 == 1 && never_collapses(w.t0, w.t1, pi, pj, vi, vj) {
                continue;
            }
            match edge_detect_simp_window(d.ta, d.tb, d.s, d.v, pi, pj, vi, vj, d.f) {
                Tri::Yes => return Tri::Yes,
                Tri::Unsure => acc = Tri::Unsure,
                Tri::No => {}
            }
        }
        i = g + LANES;
    }
    acc
}

#[cfg(test)]
mod tests;
