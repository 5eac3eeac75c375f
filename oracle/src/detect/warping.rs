//! Paper A §II.I: detection for warping polygons, from dot_nn_lin and dot_nn through
//! edge_detect_simp and edge_detect to detect_diff_2D.

use core::cmp::Ordering;

use super::filter::far_from_edge;
use super::{Interval, Sign, Step};
use crate::field::{Arith, V2};
use crate::kernel::run::{Runner, Scene, Single};
use crate::kernel::{all, any, certainly, or, Kernel};

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

/// Paper A §II.I: detect_diff_2D's steps, each run by `r`.
pub(super) fn diff_2d<R: Runner>(r: &R) -> Result<bool, R::Abstain> {
    let n = r.count();
    if n == 0 {
        return Ok(false);
    }
    or(r.run(&Step::Inside0), || {
        any((0..n).map(|i| r.run(&Step::Edge(i))))
    })
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
