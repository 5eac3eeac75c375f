//! Paper A §II.H, §II.I and §III: detection for statically shaped polygons,
//! warping polygons (dot_nn_lin … detect_diff_2D) and 3D polygons, and the choice
//! between them (§II.F).

use core::cmp::Ordering;

use crate::contain::definitely_outside;
use crate::field::{Arith, V2};
use crate::kernel::run::{Runner, Scene, Single, Unit};
use crate::kernel::{all, and, any, any_of, certainly, eq2, not, or, Kernel};
use crate::proximity::segments_close;

/// Paper A §II.I: the sign σ (or ε) = ±1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// −1.
    Neg,
    /// +1.
    Pos,
}

impl Sign {
    /// Paper A §II.I: both signs, −1 then +1.
    pub const BOTH: [Sign; 2] = [Sign::Neg, Sign::Pos];

    /// Paper A §II.I: the other sign.
    pub fn flip(self) -> Sign {
        match self {
            Sign::Neg => Sign::Pos,
            Sign::Pos => Sign::Neg,
        }
    }
}

/// Paper A §II.F and §III: the detector that decides a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// §II.H, statically shaped polygon.
    DetectSame2d,
    /// §II.I, warping polygon.
    DetectDiff2d,
    /// §III, with a slab.
    Detect3d,
}

impl Method {
    /// Paper A §II.F and §III: the paper's name in snake case.
    pub fn name(self) -> &'static str {
        match self {
            Method::DetectSame2d => "detect_same_2d",
            Method::DetectDiff2d => "detect_diff_2d",
            Method::Detect3d => "detect_3d",
        }
    }
}

/// Paper A §II.I: an interval of times returned by dot_nn_lin / dot_nn, with ends
/// of a kernel's root type (exact algebraic numbers, or enclosures).
///
/// The paper encodes "empty" as the pair (T, 0). That is only empty when T > 0:
/// detect_3D calls the 2D functions with lookahead b − a, which is 0 when the
/// slab window is a single instant, and then (T, 0) = (0, 0) would read as the
/// non-empty interval [0, 0]. Emptiness is therefore explicit here.
#[derive(Clone, Debug)]
pub enum Interval<R> {
    /// No time.
    Empty,
    /// The closed interval [lb, ub] with lb ≤ ub, both in [0, T].
    Closed {
        /// Lower end.
        lb: R,
        /// Upper end.
        ub: R,
    },
}

impl<R> Interval<R> {
    /// Paper A §II.I support: whether the interval holds no time.
    pub fn is_empty(&self) -> bool {
        matches!(self, Interval::Empty)
    }
}

/// Paper A §II.I support: the interval {t ∈ [0, T] : lo ≤ t ≤ hi}, where a missing
/// end is unbounded.
fn clip<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    lo: Option<K::Root>,
    hi: Option<K::Root>,
) -> Result<Interval<K::Root>, K::Abstain> {
    let zero = N::zero();
    let lb = match lo {
        Some(x) => k.root_max(x, &zero),
        None => k.root(&zero),
    };
    let ub = match hi {
        Some(x) => k.root_min(x, t),
        None => k.root(t),
    };
    Ok(if k.root_lt(&ub, &lb)? {
        Interval::Empty
    } else {
        Interval::Closed { lb, ub }
    })
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
pub fn dot_nn_lin<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    sigma: Sign,
) -> Result<Interval<K::Root>, K::Abstain> {
    let [left, right] = dot_nn_lin_both(k, t, ww, vv, aa, bb)?;
    Ok(match sigma {
        Sign::Neg => left,
        Sign::Pos => right,
    })
}

/// Paper A §II.I: dot_nn_lin for σ = −1 and σ = +1 at once (one case analysis, one
/// pair of roots; see [`dot_nn_lin`]).
fn dot_nn_lin_both<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
) -> Result<[Interval<K::Root>; 2], K::Abstain> {
    let a = vv.dot(bb);
    let b = ww.dot(bb).plus(&vv.dot(aa));
    let c = ww.dot(aa);
    let disc = || b.sq().minus(&a.twice().twice().times(&c));
    let (left, right) = match k.sign(&a)? {
        Ordering::Equal => {
            let left = match k.sign(&b)? {
                Ordering::Equal if k.is_neg(&c)? => Interval::Empty,
                Ordering::Equal => clip(k, t, None, None)?,
                sb => match k.linear_root(c.negated(), b.clone()) {
                    Some(r) if sb == Ordering::Greater => clip(k, t, Some(r), None)?,
                    Some(r) => clip(k, t, None, Some(r))?,
                    None => Interval::Empty,
                },
            };
            (left, Interval::Empty)
        }
        Ordering::Greater => {
            let d = disc();
            let roots = if k.is_pos(&d)? {
                k.two_roots(&a, &b, d)
            } else {
                None
            };
            match roots {
                // f = A(t − r)² ≥ 0 or f > 0 everywhere.
                None => (clip(k, t, None, None)?, Interval::Empty),
                Some([r1, r2]) => (clip(k, t, None, Some(r1))?, clip(k, t, Some(r2), None)?),
            }
        }
        Ordering::Less => {
            let d = disc();
            let left = match k.sign(&d)? {
                Ordering::Less => Interval::Empty,
                Ordering::Equal => match k.linear_root(b.negated(), a.twice()) {
                    Some(r) => clip(k, t, Some(r.clone()), Some(r))?,
                    None => Interval::Empty,
                },
                Ordering::Greater => match k.two_roots(&a, &b, d) {
                    Some([r1, r2]) => clip(k, t, Some(r1), Some(r2))?,
                    None => Interval::Empty,
                },
            };
            (left, Interval::Empty)
        }
    };
    Ok([left, right])
}

/// Paper A §II.I support: σ · x.
fn signed<N: Arith>(x: &V2<N>, sigma: Sign) -> V2<N> {
    match sigma {
        Sign::Neg => x.negated(),
        Sign::Pos => x.clone(),
    }
}

/// Paper A §II.I: the vectors dot_nn hands to dot_nn_lin, F·aa + σ2·ww and F·bb + σ2·vv.
fn dot_nn_args<N: Arith>(
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    sigma2: Sign,
    f: &N,
) -> [V2<N>; 2] {
    [
        aa.scale(f).plus(&signed(ww, sigma2)),
        bb.scale(f).plus(&signed(vv, sigma2)),
    ]
}

/// Paper A §II.I: dot_nn(T, ww, vv, aa, bb, σ1, σ2, F) =
/// dot_nn_lin(T, F·aa + σ2·ww, F·bb + σ2·vv, aa, bb, σ1).
pub fn dot_nn<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    sigma1: Sign,
    sigma2: Sign,
    f: &N,
) -> Result<Interval<K::Root>, K::Abstain> {
    let [w2, v2] = dot_nn_args(ww, vv, aa, bb, sigma2, f);
    dot_nn_lin(k, t, &w2, &v2, aa, bb, sigma1)
}

/// Paper A §II.I support: a proven-sound early "false" for edge_detect_simp (it
/// never changes the answer, it only skips work; taken only when decided).
///
/// Proof. Let u = aa + t·bb, w = ww + t·vv. If u ≠ 0 and both inequalities (1)
/// hold, then writing w in the orthogonal basis u, u^⊥ gives
/// ‖w‖² = ((w·u)² + (w·u^⊥)²)/‖u‖² ≤ ((1 + F)² + F²)‖u‖² ≤ (1 + 2F)²‖u‖².
/// When aa × bb ≠ 0, u is never 0. ‖u‖ ≤ |u_x| + |u_y|, a convex function of t,
/// so ‖u‖ ≤ M = max over t ∈ {0, T} of |u_x| + |u_y|. If one coordinate of w
/// (linear in t) exceeds (1 + 2F)·M in absolute value, with the same sign, at
/// t = 0 and at t = T, then ‖w‖ > (1 + 2F)‖u‖ on all of [0, T]: no t satisfies (1).
pub fn far_from_edge<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    f: &N,
) -> Result<bool, K::Abstain> {
    if k.sign(&aa.cross(bb))? == Ordering::Equal {
        return Ok(false);
    }
    let u_t = aa.at(bb, t);
    let m0 = k.abs(&aa.x).plus(&k.abs(&aa.y));
    let m1 = k.abs(&u_t.x).plus(&k.abs(&u_t.y));
    let (_, m) = k.hull(&[&m0, &m1]);
    let r = m.plus(&m.times(&f.twice()));
    let nr = r.negated();
    let w_t = ww.at(vv, t);
    let beyond = |a: &N, b: &N| {
        or(and(k.lt(&r, a), || k.lt(&r, b)), || {
            and(k.lt(a, &nr), || k.lt(b, &nr))
        })
    };
    or(beyond(&ww.x, &w_t.x), || beyond(&ww.y, &w_t.y))
}

/// Paper A §II.I: edge_detect_simp — is there t ∈ [0, T] with
/// |(ww + t·vv)·(aa + t·bb)| ≤ (1 + F)‖aa + t·bb‖² and
/// |(ww + t·vv)·(aa^⊥ + t·bb^⊥)| ≤ F‖aa^⊥ + t·bb^⊥‖²?
pub fn edge_detect_simp<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    f: &N,
) -> Result<bool, K::Abstain> {
    if certainly(far_from_edge(k, t, ww, vv, aa, bb, f)) {
        return Ok(false);
    }
    edge_detect_simp_without_shortcut(k, t, ww, vv, aa, bb, f)
}

/// Paper A §II.I: edge_detect_simp exactly as the paper defines it, without the
/// [`far_from_edge`] shortcut (kept public so tests can check the shortcut).
pub fn edge_detect_simp_without_shortcut<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    ww: &V2<N>,
    vv: &V2<N>,
    aa: &V2<N>,
    bb: &V2<N>,
    f: &N,
) -> Result<bool, K::Abstain> {
    let f1 = N::one().plus(f);
    let aap = aa.perp();
    let bbp = bb.perp();
    // The paper's 64 sign choices use only 8 distinct dot_nn intervals:
    // ivs[2·i1 + i2] = dot_nn(.., aa, bb, σ1, σ2, 1 + F) and
    // ivs[4 + 2·i1 + i2] = dot_nn(.., aa^⊥, bb^⊥, σ1, σ2, F), i = 1 for σ = +1.
    // dot_nn for σ1 = −1 and +1 shares its dot_nn_lin arguments: one case analysis
    // (dot_nn_lin_both) gives both.
    let mut ivs: Vec<Interval<K::Root>> = vec![Interval::Empty; 8];
    for (g, (x, y, kf)) in [(aa, bb, &f1), (&aap, &bbp, f)].into_iter().enumerate() {
        for (i2, s2) in Sign::BOTH.into_iter().enumerate() {
            let [w2, v2] = dot_nn_args(ww, vv, x, y, s2, kf);
            let [left, right] = dot_nn_lin_both(k, t, &w2, &v2, x, y)?;
            ivs[4 * g + i2] = left;
            ivs[4 * g + 2 + i2] = right;
        }
        // Every sign choice takes one interval with σ2 = −1 and one with σ2 = +1
        // from each group: if either column is all empty, no choice succeeds.
        let col_empty = |i2: usize| (0..2).all(|i1| ivs[4 * g + 2 * i1 + i2].is_empty());
        if col_empty(0) || col_empty(1) {
            return Ok(false);
        }
    }
    // le[i][j] caches lb_i ≤ ub_j; a set of intervals meets (max of lbs ≤ min of
    // ubs) exactly when every interval is non-empty and lb_i ≤ ub_j for all i, j.
    let mut le = [[None; 8]; 8];
    let mut lb_le_ub = |i: usize, j: usize| {
        *le[i][j].get_or_insert_with(|| match (&ivs[i], &ivs[j]) {
            (Interval::Closed { .. }, Interval::Closed { .. }) if i == j => Ok(true),
            (Interval::Closed { lb, .. }, Interval::Closed { ub, .. }) => k.root_le(lb, ub),
            _ => Ok(false),
        })
    };
    let si = |s: Sign| usize::from(s == Sign::Pos);
    let mut acc = Ok(false);
    for e2 in Sign::BOTH {
        for s2 in Sign::BOTH {
            for e1 in Sign::BOTH {
                for e3 in Sign::BOTH {
                    for s1 in Sign::BOTH {
                        for s3 in Sign::BOTH {
                            let idx = [
                                2 * si(e1) + si(e2),
                                2 * si(e3) + si(e2.flip()),
                                4 + 2 * si(s1) + si(s2),
                                4 + 2 * si(s3) + si(s2.flip()),
                            ];
                            let pairs = idx.iter().flat_map(|&i| idx.iter().map(move |&j| (i, j)));
                            acc = or(acc, || all(pairs.map(|(i, j)| lb_le_ub(i, j))));
                            if certainly(acc) {
                                return acc;
                            }
                        }
                    }
                }
            }
        }
    }
    acc
}

/// Paper A §II.I: edge_detect — edge_detect_simp on the edge's midpoint frame (equation 2).
pub fn edge_detect<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    pi: &V2<N>,
    pj: &V2<N>,
    vi: &V2<N>,
    vj: &V2<N>,
    f: &N,
) -> Result<bool, K::Abstain> {
    let (pi, pj, vi, vj) = (pi.half(), pj.half(), vi.half(), vj.half());
    let ww = s.minus(&pj.plus(&pi));
    let vv = v.minus(&vj.plus(&vi));
    let aa = pj.minus(&pi);
    let bb = vj.minus(&vi);
    edge_detect_simp(k, t, &ww, &vv, &aa, &bb, f)
}

/// Paper A §II.H and §II.I: one step of detect_same_2D or detect_diff_2D, each one
/// paper-function call (the grain at which a filtered run falls back to exact).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Step {
    /// Step 1 of both: s not definitely outside P.
    Inside0,
    /// detect_same_2D step 2: s + T·v not definitely outside P + T·V.
    InsideT,
    /// detect_same_2D step 3: segments_close(s, s + T·(v − v_i), p_i, p_{i+1}, BUFF).
    PathClose(usize),
    /// detect_diff_2D: edge_detect on the edge p_i p_{i+1}.
    Edge(usize),
}

impl Unit for Step {
    type Out<R> = bool;

    fn run<N: Arith, K: Kernel<N>>(&self, k: &K, sc: &Scene<'_, N>) -> Result<bool, K::Abstain> {
        let next = |i: usize| (i + 1) % sc.p.len();
        match *self {
            Step::Inside0 => not(definitely_outside(k, &sc.p, &sc.s, &sc.buff)),
            Step::InsideT => {
                let moved: Vec<V2<N>> =
                    sc.p.iter()
                        .zip(sc.vels.iter())
                        .map(|(p, w)| p.at(w, &sc.t))
                        .collect();
                not(definitely_outside(
                    k,
                    &moved,
                    &sc.s.at(&sc.v, &sc.t),
                    &sc.buff,
                ))
            }
            Step::PathClose(i) => {
                let end = sc.s.at(&sc.v.minus(&sc.vels[i]), &sc.t);
                segments_close(k, &sc.s, &end, &sc.p[i], &sc.p[next(i)], &sc.buff)
            }
            Step::Edge(i) => {
                let (p, w, j) = (&sc.p, &sc.vels, next(i));
                edge_detect(k, &sc.t, &sc.s, &sc.v, &p[i], &p[j], &w[i], &w[j], &sc.f)
            }
        }
    }

    fn map_root<A, B>(out: bool, _: impl FnMut(A) -> B) -> bool {
        out
    }
}

/// Paper A §II.H: detect_same_2D's steps, each run by `r`.
fn same_2d<R: Runner>(r: &R) -> Result<bool, R::Abstain> {
    let n = r.count();
    if n == 0 {
        return Ok(false);
    }
    any_of!(
        r.run(&Step::Inside0),
        r.run(&Step::InsideT),
        any((0..n).map(|i| r.run(&Step::PathClose(i)))),
    )
}

/// Paper A §II.I: detect_diff_2D's steps, each run by `r`.
fn diff_2d<R: Runner>(r: &R) -> Result<bool, R::Abstain> {
    let n = r.count();
    if n == 0 {
        return Ok(false);
    }
    or(r.run(&Step::Inside0), || {
        any((0..n).map(|i| r.run(&Step::Edge(i))))
    })
}

/// Paper A §II.H / §II.I: the 2D detector of `method` (detect_same_2D for
/// [`Method::DetectSame2d`], detect_diff_2D otherwise), its steps run by `r`.
pub(crate) fn detect_2d<R: Runner>(r: &R, method: Method) -> Result<bool, R::Abstain> {
    match method {
        Method::DetectSame2d => same_2d(r),
        _ => diff_2d(r),
    }
}

/// Paper A §II.H: detect_same_2D for a statically shaped polygon (v_i of each edge used).
pub fn detect_same_2d<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    p: &[V2<N>],
    vels: &[V2<N>],
    buff: &N,
) -> Result<bool, K::Abstain> {
    // detect_same_2D has no F: the scene's F (here BUFF) is never read.
    same_2d(&Single::new(k, Scene::new(t, s, v, p, vels, buff, buff)))
}

/// Paper A §II.I: detect_diff_2D for a warping polygon.
pub fn detect_diff_2d<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    p: &[V2<N>],
    vels: &[V2<N>],
    f: &N,
    buff: &N,
) -> Result<bool, K::Abstain> {
    diff_2d(&Single::new(k, Scene::new(t, s, v, p, vels, buff, f)))
}

/// Paper A §III step 1: the window [a, b] ⊆ [0, T] where
/// pmin + t·vsp ≤ s_z + t·v_z ≤ pmax + t·vsp, or `None` when there is no such t.
pub fn slab_window<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    sz: &N,
    vz: &N,
    pmin: &N,
    pmax: &N,
    vsp: &N,
) -> Result<Option<(N, N)>, K::Abstain> {
    if k.lt(pmax, pmin)? {
        return Ok(None);
    }
    let w = vz.minus(vsp);
    let zero = N::zero();
    if k.sign(&w)? == Ordering::Equal {
        let inside = and(k.le(pmin, sz), || k.le(sz, pmax))?;
        return Ok(inside.then(|| (zero, t.clone())));
    }
    let (Some(t1), Some(t2)) = (pmin.minus(sz).quotient(&w), pmax.minus(sz).quotient(&w)) else {
        return Ok(None);
    };
    let (lo, hi) = if k.le(&t1, &t2)? { (t1, t2) } else { (t2, t1) };
    let a = if k.lt(&zero, &lo)? { lo } else { zero };
    let b = if k.lt(&hi, t)? { hi } else { t.clone() };
    Ok(if k.le(&a, &b)? { Some((a, b)) } else { None })
}

/// Paper A §II.F: whether all vertex velocities are equal (a statically shaped polygon).
pub fn statically_shaped<N: Arith, K: Kernel<N>>(
    k: &K,
    vels: &[V2<N>],
) -> Result<bool, K::Abstain> {
    all(vels.windows(2).map(|w| eq2(k, &w[0], &w[1])))
}

/// Paper A §II.F and §III: the detector for a case — detect_3D when the point has a
/// height and the polygon a slab (`vertical`), else detect_same_2D when every vertex
/// velocity is the same ([`statically_shaped`]), else detect_diff_2D. The one place
/// the choice is made: [`crate::paper_detect`] and [`detect_3d`] (for its 2D part)
/// both ask here.
pub fn dispatch<N: Arith, K: Kernel<N>>(
    k: &K,
    vertical: bool,
    vels: &[V2<N>],
) -> Result<Method, K::Abstain> {
    Ok(if vertical {
        Method::Detect3d
    } else if statically_shaped(k, vels)? {
        Method::DetectSame2d
    } else {
        Method::DetectDiff2d
    })
}

/// Paper A §III steps 1–2: the scene restarted at the slab window [a, b] (the point
/// at s + a·v, the polygon at P + a·V, lookahead b − a), `None` when the window is
/// empty.
pub(crate) fn slab_scene<'a, N: Arith, K: Kernel<N>>(
    k: &K,
    sc: &Scene<'a, N>,
    sz: &N,
    vz: &N,
    pmin: &N,
    pmax: &N,
    vsp: &N,
) -> Result<Option<Scene<'a, N>>, K::Abstain> {
    let window = slab_window(k, &sc.t, sz, vz, pmin, pmax, vsp)?;
    Ok(window.map(|(a, b)| sc.shifted(&a, b.minus(&a))))
}

/// Paper A §III: detect_3D — the slab window [a, b], then 2D detection from
/// s + a·v and P + a·V over lookahead b − a (detect_same_2D when all vertex
/// velocities are equal, detect_diff_2D otherwise). An empty window returns
/// false (the paper's text would run the 2D function with lookahead 0 − T).
pub fn detect_3d<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    sz: &N,
    vz: &N,
    p: &[V2<N>],
    vels: &[V2<N>],
    pmin: &N,
    pmax: &N,
    vsp: &N,
    buff: &N,
    f: &N,
) -> Result<bool, K::Abstain> {
    let sc = Scene::new(t, s, v, p, vels, buff, f);
    match slab_scene(k, &sc, sz, vz, pmin, pmax, vsp)? {
        None => Ok(false),
        Some(window) => detect_2d(&Single::new(k, window), dispatch(k, false, vels)?),
    }
}
