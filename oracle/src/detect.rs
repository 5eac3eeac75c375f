//! Paper A §II.H, §II.I and §III: detection for statically shaped polygons,
//! warping polygons (dot_nn_lin … detect_diff_2D) and 3D polygons.

use core::cmp::Ordering;

use crate::contain::definitely_outside;
use crate::field::{ExactField, V2};
use crate::proximity::segments_close;
use crate::qfield::{quad_roots, Alg};

/// Paper A §II.I: an interval of times returned by dot_nn_lin / dot_nn.
///
/// The paper encodes "empty" as the pair (T, 0). That is only empty when T > 0:
/// detect_3D calls the 2D functions with lookahead b − a, which is 0 when the
/// slab window is a single instant, and then (T, 0) = (0, 0) would read as the
/// non-empty interval [0, 0]. Emptiness is therefore explicit here.
#[derive(Clone, Debug)]
pub enum Interval<F> {
    /// No time.
    Empty,
    /// The closed interval [lb, ub] with lb ≤ ub, both in [0, T].
    Closed {
        /// Lower end.
        lb: Alg<F>,
        /// Upper end.
        ub: Alg<F>,
    },
}

impl<F: ExactField> Interval<F> {
    /// Paper A §II.I support: whether the interval holds no time.
    pub fn is_empty(&self) -> bool {
        matches!(self, Interval::Empty)
    }

    /// Paper A §II.I support: whether the rational time t lies in the interval.
    pub fn contains_rat(&self, t: &F) -> bool {
        match self {
            Interval::Empty => false,
            Interval::Closed { lb, ub } => {
                lb.cmp_rat(t) != Ordering::Greater && ub.cmp_rat(t) != Ordering::Less
            }
        }
    }

    /// Paper A §II.I support: the interval {t ∈ [0, T] : lo ≤ t ≤ hi}, where a
    /// missing end is unbounded.
    pub fn clip(t: &F, lo: Option<Alg<F>>, hi: Option<Alg<F>>) -> Self {
        let lb = match lo {
            Some(x) if x.sign() == Ordering::Greater => x,
            _ => Alg::rational(F::zero()),
        };
        let ub = match hi {
            Some(x) if x.cmp_rat(t) == Ordering::Less => x,
            _ => Alg::rational(t.clone()),
        };
        if lb.cmp_alg(&ub) == Ordering::Greater {
            Interval::Empty
        } else {
            Interval::Closed { lb, ub }
        }
    }
}

/// Paper A §II.I (omitted by the paper, derived here): dot_nn_lin(T, ww, vv, aa, bb, σ).
///
/// With f(t) = (ww + t·vv)·(aa + t·bb) = A·t² + B·t + C, A = vv·bb,
/// B = ww·bb + vv·aa, C = ww·aa, the two intervals for σ = −1 and σ = +1 have
/// union exactly {t ∈ [0, T] : f(t) ≥ 0}. σ = −1 gives the left (or only)
/// component, σ = +1 the right component when there are two:
/// - A = 0, B = 0: [0, T] when C ≥ 0, else empty;
/// - A = 0, B ≠ 0: t ≥ −C/B (B > 0) or t ≤ −C/B (B < 0), clipped to [0, T];
/// - A > 0, disc = B² − 4AC ≤ 0: f ≥ 0 everywhere, [0, T];
/// - A > 0, disc > 0: t ≤ r1 (σ = −1) or t ≥ r2 (σ = +1), roots r1 < r2;
/// - A < 0, disc < 0: empty; disc = 0: the single time r = −B/(2A); disc > 0: [r1, r2].
///
/// No epsilon: a leading coefficient is zero only when it is exactly zero.
pub fn dot_nn_lin<F: ExactField>(
    t: &F,
    ww: &V2<F>,
    vv: &V2<F>,
    aa: &V2<F>,
    bb: &V2<F>,
    sigma: i8,
) -> Interval<F> {
    let a = vv.dot(bb);
    let b = ww.dot(bb).plus(&vv.dot(aa));
    let c = ww.dot(aa);
    let left = sigma < 0;
    match a.sign() {
        Ordering::Equal => {
            if !left {
                return Interval::Empty;
            }
            match b.sign() {
                Ordering::Equal => {
                    if c.is_neg() {
                        Interval::Empty
                    } else {
                        Interval::clip(t, None, None)
                    }
                }
                sb => {
                    let root = Alg::new(c.negated(), F::zero(), F::zero(), b);
                    match (root, sb) {
                        (Some(r), Ordering::Greater) => Interval::clip(t, Some(r), None),
                        (Some(r), _) => Interval::clip(t, None, Some(r)),
                        (None, _) => Interval::Empty,
                    }
                }
            }
        }
        Ordering::Greater => {
            let mut roots = quad_roots(&a, &b, &c);
            if roots.len() < 2 {
                // f = A(t − r)² ≥ 0 or f > 0 everywhere.
                return if left {
                    Interval::clip(t, None, None)
                } else {
                    Interval::Empty
                };
            }
            let r2 = roots.pop();
            let r1 = roots.pop();
            if left {
                Interval::clip(t, None, r1)
            } else {
                Interval::clip(t, r2, None)
            }
        }
        Ordering::Less => {
            if !left {
                return Interval::Empty;
            }
            let mut roots = quad_roots(&a, &b, &c);
            match roots.len() {
                0 => Interval::Empty,
                1 => {
                    let r = roots.pop();
                    Interval::clip(t, r.clone(), r)
                }
                _ => {
                    let r2 = roots.pop();
                    let r1 = roots.pop();
                    Interval::clip(t, r1, r2)
                }
            }
        }
    }
}

/// Paper A §II.I: dot_nn(T, ww, vv, aa, bb, σ1, σ2, F) =
/// dot_nn_lin(T, F·aa + σ2·ww, F·bb + σ2·vv, aa, bb, σ1).
#[allow(clippy::too_many_arguments)]
pub fn dot_nn<F: ExactField>(
    t: &F,
    ww: &V2<F>,
    vv: &V2<F>,
    aa: &V2<F>,
    bb: &V2<F>,
    sigma1: i8,
    sigma2: i8,
    fac: &F,
) -> Interval<F> {
    let w2 = aa.scale(fac).plus(&ww.signed(sigma2));
    let v2 = bb.scale(fac).plus(&vv.signed(sigma2));
    dot_nn_lin(t, &w2, &v2, aa, bb, sigma1)
}

fn sign_index(s: i8) -> usize {
    usize::from(s > 0)
}

fn abs<F: ExactField>(x: &F) -> F {
    if x.is_neg() {
        x.negated()
    } else {
        x.clone()
    }
}

/// Paper A §II.I support: an exact, proven-sound early "false" for
/// edge_detect_simp (it never changes the answer, it only skips work).
///
/// Proof. Let u = aa + t·bb, w = ww + t·vv. If u ≠ 0 and both inequalities (1)
/// hold, then writing w in the orthogonal basis u, u^⊥ gives
/// ‖w‖² = ((w·u)² + (w·u^⊥)²)/‖u‖² ≤ ((1 + F)² + F²)‖u‖² ≤ (1 + 2F)²‖u‖².
/// When aa × bb ≠ 0, u is never 0. ‖u‖ ≤ |u_x| + |u_y|, a convex function of t,
/// so ‖u‖ ≤ M = max over t ∈ {0, T} of |u_x| + |u_y|. If one coordinate of w
/// (linear in t) exceeds (1 + 2F)·M in absolute value, with the same sign, at
/// t = 0 and at t = T, then ‖w‖ > (1 + 2F)‖u‖ on all of [0, T]: no t satisfies (1).
pub fn far_from_edge<F: ExactField>(
    t: &F,
    ww: &V2<F>,
    vv: &V2<F>,
    aa: &V2<F>,
    bb: &V2<F>,
    fac: &F,
) -> bool {
    if aa.cross(bb).is_zero_() {
        return false;
    }
    let u_t = aa.at(bb, t);
    let m0 = abs(&aa.x).plus(&abs(&aa.y));
    let m1 = abs(&u_t.x).plus(&abs(&u_t.y));
    let m = if m0 > m1 { m0 } else { m1 };
    let two_f = fac.plus(fac);
    let r = m.plus(&m.times(&two_f));
    let w_t = ww.at(vv, t);
    let beyond = |a: &F, b: &F| {
        let nr = r.negated();
        (*a > r && *b > r) || (*a < nr && *b < nr)
    };
    beyond(&ww.x, &w_t.x) || beyond(&ww.y, &w_t.y)
}

/// Paper A §II.I: edge_detect_simp — is there t ∈ [0, T] with
/// |(ww + t·vv)·(aa + t·bb)| ≤ (1 + F)‖aa + t·bb‖² and
/// |(ww + t·vv)·(aa^⊥ + t·bb^⊥)| ≤ F‖aa^⊥ + t·bb^⊥‖²?
pub fn edge_detect_simp<F: ExactField>(
    t: &F,
    ww: &V2<F>,
    vv: &V2<F>,
    aa: &V2<F>,
    bb: &V2<F>,
    fac: &F,
) -> bool {
    !far_from_edge(t, ww, vv, aa, bb, fac) && edge_detect_simp_unfiltered(t, ww, vv, aa, bb, fac)
}

/// Paper A §II.I: edge_detect_simp exactly as the paper defines it, without the
/// [`far_from_edge`] shortcut (kept public so tests can check the shortcut).
pub fn edge_detect_simp_unfiltered<F: ExactField>(
    t: &F,
    ww: &V2<F>,
    vv: &V2<F>,
    aa: &V2<F>,
    bb: &V2<F>,
    fac: &F,
) -> bool {
    let f1 = F::one().plus(fac);
    let aap = aa.perp();
    let bbp = bb.perp();
    // The paper's 64 sign choices use only 8 distinct dot_nn intervals:
    // ivs[2·i1 + i2] = dot_nn(.., aa, bb, σ1, σ2, 1 + F) and
    // ivs[4 + 2·i1 + i2] = dot_nn(.., aa^⊥, bb^⊥, σ1, σ2, F), i = 1 for σ = +1.
    let mut ivs: Vec<Interval<F>> = Vec::with_capacity(8);
    for (g, (x, y, k)) in [(aa, bb, &f1), (&aap, &bbp, fac)].into_iter().enumerate() {
        for s1 in [-1i8, 1] {
            for s2 in [-1i8, 1] {
                ivs.push(dot_nn(t, ww, vv, x, y, s1, s2, k));
            }
        }
        // Every sign choice takes one interval with σ2 = −1 and one with σ2 = +1
        // from each group: if either column is all empty, no choice succeeds.
        let col_empty = |s2: usize| (0..2).all(|s1| ivs[4 * g + 2 * s1 + s2].is_empty());
        if col_empty(0) || col_empty(1) {
            return false;
        }
    }
    // le[i][j] caches lb_i ≤ ub_j; a set of intervals meets (max of lbs ≤ min of
    // ubs) exactly when every interval is non-empty and lb_i ≤ ub_j for all i, j.
    let mut le: [[Option<bool>; 8]; 8] = [[None; 8]; 8];
    let mut lb_le_ub = |i: usize, j: usize| -> bool {
        if let Some(v) = le[i][j] {
            return v;
        }
        let v = match (&ivs[i], &ivs[j]) {
            (Interval::Closed { lb, .. }, Interval::Closed { ub, .. }) => {
                i == j || lb.cmp_alg(ub) != Ordering::Greater
            }
            _ => false,
        };
        le[i][j] = Some(v);
        v
    };
    for e2 in [-1i8, 1] {
        for s2 in [-1i8, 1] {
            for e1 in [-1i8, 1] {
                for e3 in [-1i8, 1] {
                    for s1 in [-1i8, 1] {
                        for s3 in [-1i8, 1] {
                            let idx = [
                                2 * sign_index(e1) + sign_index(e2),
                                2 * sign_index(e3) + sign_index(-e2),
                                4 + 2 * sign_index(s1) + sign_index(s2),
                                4 + 2 * sign_index(s3) + sign_index(-s2),
                            ];
                            let meet = idx.iter().all(|&i| idx.iter().all(|&j| lb_le_ub(i, j)));
                            if meet {
                                return true;
                            }
                        }
                    }
                }
            }
        }
    }
    false
}

/// Paper A §II.I: edge_detect — edge_detect_simp on the edge's midpoint frame (equation 2).
#[allow(clippy::too_many_arguments)]
pub fn edge_detect<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    pi: &V2<F>,
    pj: &V2<F>,
    vi: &V2<F>,
    vj: &V2<F>,
    fac: &F,
) -> bool {
    let ww = s.minus(&pj.half().plus(&pi.half()));
    let vv = v.minus(&vj.half().plus(&vi.half()));
    let aa = pj.half().minus(&pi.half());
    let bb = vj.half().minus(&vi.half());
    edge_detect_simp(t, &ww, &vv, &aa, &bb, fac)
}

/// Paper A §II.H: detect_same_2D for a statically shaped polygon (v_i of each edge used).
pub fn detect_same_2d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    poly: &[V2<F>],
    vels: &[V2<F>],
    buff: &F,
) -> bool {
    let n = poly.len();
    if n == 0 || vels.len() != n {
        return false;
    }
    // Step 1: s at time 0.
    if !definitely_outside(poly, s, buff) {
        return true;
    }
    // Step 2: s + T·v against P + T·V.
    let moved: Vec<V2<F>> = poly.iter().zip(vels).map(|(p, w)| p.at(w, t)).collect();
    if !definitely_outside(&moved, &s.at(v, t), buff) {
        return true;
    }
    // Step 3: the relative path s → s + T(v − v_i) against each static edge.
    for i in 0..n {
        let j = (i + 1) % n;
        let end = s.at(&v.minus(&vels[i]), t);
        if segments_close(s, &end, &poly[i], &poly[j], buff) {
            return true;
        }
    }
    false
}

/// Paper A §II.I: detect_diff_2D for a warping polygon.
#[allow(clippy::too_many_arguments)]
pub fn detect_diff_2d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    poly: &[V2<F>],
    vels: &[V2<F>],
    fac: &F,
    buff: &F,
) -> bool {
    let n = poly.len();
    if n == 0 || vels.len() != n {
        return false;
    }
    if !definitely_outside(poly, s, buff) {
        return true;
    }
    (0..n).any(|i| {
        let j = (i + 1) % n;
        edge_detect(t, s, v, &poly[i], &poly[j], &vels[i], &vels[j], fac)
    })
}

/// Paper A §III step 1: the exact window [a, b] ⊆ [0, T] where
/// pmin + t·vsp ≤ s_z + t·v_z ≤ pmax + t·vsp, or `None` when there is no such t.
pub fn slab_interval<F: ExactField>(
    t: &F,
    sz: &F,
    vz: &F,
    pmin: &F,
    pmax: &F,
    vsp: &F,
) -> Option<(F, F)> {
    if pmin > pmax {
        return None;
    }
    let w = vz.minus(vsp);
    let zero = F::zero();
    if w.is_zero_() {
        return if pmin <= sz && sz <= pmax {
            Some((zero, t.clone()))
        } else {
            None
        };
    }
    let t1 = pmin.minus(sz).quotient(&w)?;
    let t2 = pmax.minus(sz).quotient(&w)?;
    let (lo, hi) = if t1 <= t2 { (t1, t2) } else { (t2, t1) };
    let a = if lo > zero { lo } else { zero };
    let b = if hi < *t { hi } else { t.clone() };
    if a <= b {
        Some((a, b))
    } else {
        None
    }
}

/// Whether all vertex velocities are equal (a statically shaped polygon, §II.F).
pub fn all_equal<F: ExactField>(vels: &[V2<F>]) -> bool {
    vels.windows(2).all(|w| w[0] == w[1])
}

/// Paper A §III: detect_3D — the slab window [a, b], then 2D detection from
/// s + a·v and P + a·V over lookahead b − a (detect_same_2D when all vertex
/// velocities are equal, detect_diff_2D otherwise). An empty window returns
/// false (the paper's text would run the 2D function with lookahead 0 − T).
#[allow(clippy::too_many_arguments)]
pub fn detect_3d<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    sz: &F,
    vz: &F,
    poly: &[V2<F>],
    vels: &[V2<F>],
    pmin: &F,
    pmax: &F,
    vsp: &F,
    buff: &F,
    fac: &F,
) -> bool {
    let Some((a, b)) = slab_interval(t, sz, vz, pmin, pmax, vsp) else {
        return false;
    };
    let s2 = s.at(v, &a);
    let p2: Vec<V2<F>> = poly.iter().zip(vels).map(|(p, w)| p.at(w, &a)).collect();
    let t2 = b.minus(&a);
    if all_equal(vels) {
        detect_same_2d(&t2, &s2, v, &p2, vels, buff)
    } else {
        detect_diff_2d(&t2, &s2, v, &p2, vels, fac, buff)
    }
}
