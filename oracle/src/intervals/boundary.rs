//! The horizontal part of the relations over a time window: the set B where the point
//! is within D of the polygon's boundary (paper A §II.C's distance to an edge, made a
//! set of times; §II.I for warping edges), the winding number on the gaps of B
//! (§II.D's ray crossings, exact and signed), and what makes the answer undefined
//! (the truth's rules: an edge shrinking to a point, an even non-zero winding number).

use core::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::scene::{Kind, Scene};
use super::set::{roots_in, sign_at_end, sign_set, End, Lazy, Sample, Set, Window};
use super::{Relation, Undefined};
use crate::field::{ExactField, V2};
use crate::kernel::interval::Iv;
use crate::kernel::{Decided, Exact, Intervals};
use crate::truth::winding_number;

/// Per edge, whether it is one repeated vertex throughout the window (it is then that
/// vertex, which its neighbours' edges cover, as in the truth). Undefined when an edge
/// shrinks to a point at one time of the window, or when every edge is a point.
/// (Paper A §II's premise: edges of positive length.)
pub(crate) fn point_edges<F: ExactField>(
    sc: &Scene<'_, F>,
    w: &Window,
) -> Result<Vec<bool>, Undefined> {
    let n = sc.len();
    let mut out = vec![false; n];
    for (i, point) in out.iter_mut().enumerate() {
        let j = (i + 1) % n;
        let (a, b) = (&sc.fl.p[i], &sc.fl.p[j]);
        // e = b − a is linear in t: one coordinate of one strict sign at both ends of
        // the window keeps it away from 0 throughout.
        let at = |tau: Iv, k: usize| b.c0[k].sub(a.c0[k]).add(b.c1[k].sub(a.c1[k]).mul(tau));
        let strict = |x: Iv, y: Iv| {
            matches!(
                (x.sign(), y.sign()),
                (Ok(Ordering::Less), Ok(Ordering::Less))
                    | (Ok(Ordering::Greater), Ok(Ordering::Greater))
            )
        };
        if (0..2).any(|k| strict(at(w.lo_end.iv, k), at(w.hi_end.iv, k))) {
            continue;
        }
        let e = sc.exact();
        let d0: Vec<BigInt> = (0..2).map(|k| &e.p[j].c0[k] - &e.p[i].c0[k]).collect();
        let d1: Vec<BigInt> = (0..2).map(|k| &e.p[j].c1[k] - &e.p[i].c1[k]).collect();
        let Some(k) = (0..2).find(|&k| !d1[k].is_zero()) else {
            *point = d0.iter().all(Zero::is_zero);
            continue;
        };
        let tc = BigRational::new(-d0[k].clone(), d1[k].clone());
        let zero_at = (0..2).all(|m| {
            (BigRational::from_integer(d0[m].clone())
                + BigRational::from_integer(d1[m].clone()) * &tc)
                .is_zero()
        });
        if zero_at && tc >= w.lo && tc <= w.hi {
            return Err(Undefined {
                reason: format!(
                    "edge {i}-{j} shrinks to a point at t = {} (the polygon is not simple then)",
                    crate::algebraic::RealAlg::rational(tc).to_decimal_string(9)
                ),
            });
        }
    }
    if out.iter().all(|&p| p) {
        return Err(Undefined {
            reason: "every vertex is the same point".into(),
        });
    }
    Ok(out)
}

/// An outer float range of {t ∈ w : c0 + t·c1 ∈ band} (one coordinate moving linearly
/// against a fixed band), `None` when certainly empty: the constraint solved for t in
/// enclosures, each bound taken outward.
/// (A cheap exclusion in front of paper A §II.C's quadratics.)
fn clip(c0: Iv, c1: Iv, band: Iv, w: Iv) -> Option<Iv> {
    let (lo, hi) = (Iv::point(band.lo), Iv::point(band.hi));
    let (from, to) = match c1.sign() {
        Ok(Ordering::Equal) => {
            return (c0.hi >= band.lo && c0.lo <= band.hi).then_some(w);
        }
        Ok(Ordering::Greater) => (lo.sub(c0).div(c1).lo, hi.sub(c0).div(c1).hi),
        Ok(Ordering::Less) => (hi.sub(c0).div(c1).lo, lo.sub(c0).div(c1).hi),
        Err(_) => return Some(w),
    };
    let r = Iv {
        lo: from.max(w.lo),
        hi: to.min(w.hi),
    };
    (r.lo <= r.hi).then_some(r)
}

/// The part of the window in which the point can be within D of the segment from
/// vertex i to vertex j (or of vertex i alone, j = i): in the frame of vertex i the
/// segment lies in the box spanned by 0 and e(t) = p_j(t) − p_i(t) over the window,
/// and the point, q(t) = x(t) − p_i(t), moves linearly; the times at which q is within
/// D of that box on both axes, as a sub-window with rational ends (`None`: never).
/// (A cheap exclusion in front of paper A §II.C's quadratics.)
fn reach<F: ExactField>(sc: &Scene<'_, F>, w: &Window, i: usize, j: usize) -> Option<Window> {
    let (x, a, b) = (&sc.fl.x, &sc.fl.p[i], &sc.fl.p[j]);
    let tw = w.iv();
    let d = sc.d_fl.hi;
    let mut range = tw;
    for k in 0..2 {
        let e = b.c0[k].sub(a.c0[k]).add(b.c1[k].sub(a.c1[k]).mul(tw));
        // [min(e, 0), max(e, 0)] grown by D on both sides, rounded outward.
        let band = e.hull(Iv::ZERO).add(Iv { lo: -d, hi: d });
        let q0 = x.c0[k].sub(a.c0[k]);
        let q1 = x.c1[k].sub(a.c1[k]);
        range = clip(q0, q1, band, range)?;
    }
    if range.lo <= w.lo_end.iv.lo && range.hi >= w.hi_end.iv.hi {
        return Some(w.clone());
    }
    let lo = match range.lo_exact::<BigRational>() {
        Some(l) if l > w.lo => l,
        _ => w.lo.clone(),
    };
    let hi = match range.hi_exact::<BigRational>() {
        Some(h) if h < w.hi => h,
        _ => w.hi.clone(),
    };
    (lo <= hi).then(|| Window::new(lo, hi))
}

/// B over the window: the times at which the point is within D of the boundary,
/// a union of per-vertex and per-edge sets (see the module doc of
/// [`crate::intervals`](mod@crate::intervals)). With `early`, it stops at the first nonempty part (enough to
/// know whether B is empty).
/// (Paper A §II.C: near_edge's two tests, its end points and its quadratic, as sets of
/// times; with D = 0 the contacts of the truth.)
pub(crate) fn near_boundary<F: ExactField>(
    sc: &Scene<'_, F>,
    w: &Window,
    point_edge: &[bool],
    early: bool,
) -> Set {
    let n = sc.len();
    let d_zero = sc.d_is_zero();
    let mut parts: Vec<(End, End)> = Vec::new();
    if !d_zero {
        for i in 0..n {
            let Some(wi) = reach(sc, w, i, i) else {
                continue;
            };
            let s = sign_set(
                sc,
                &Lazy::new(sc, Kind::Vertex(i), &wi),
                &wi,
                Ordering::Less,
            );
            parts.extend(s.comps);
            if early && !parts.is_empty() {
                return Set::union_of(sc, parts);
            }
        }
    }
    for i in (0..n).filter(|&i| !point_edge[i]) {
        let Some(wi) = reach(sc, w, i, (i + 1) % n) else {
            continue;
        };
        let strip = if d_zero {
            contacts(sc, &wi, i)
        } else {
            band(sc, &wi, i)
        };
        parts.extend(strip.comps);
        if early && !parts.is_empty() {
            break;
        }
    }
    Set::union_of(sc, parts)
}

/// {h1 ≥ 0} ∩ {h2 ≥ 0} ∩ {g² ≤ D²·|e|²} for edge i: where the foot of the
/// perpendicular from the point falls on the edge and the point is within D of the
/// edge's line (paper A §II.C's quadratic in r has its minimum inside [0, 1] and
/// below BUFF², as times).
fn band<F: ExactField>(sc: &Scene<'_, F>, w: &Window, i: usize) -> Set {
    let k = sign_set(sc, &Lazy::new(sc, Kind::Band(i), w), w, Ordering::Less);
    if k.is_empty() {
        return k;
    }
    let a = sign_set(sc, &Lazy::new(sc, Kind::Ahead(i), w), w, Ordering::Greater);
    let r = k.intersect(sc, &a);
    if r.is_empty() {
        return r;
    }
    let b = sign_set(sc, &Lazy::new(sc, Kind::Behind(i), w), w, Ordering::Greater);
    r.intersect(sc, &b)
}

/// The times at which the point lies on edge i: the roots of g with h1, h2 ≥ 0 there
/// (signs at the roots in floats first, exactly when they cannot tell), or where the
/// point slides along the edge's line (g ≡ 0), {h1 ≥ 0} ∩ {h2 ≥ 0}.
/// (Paper A §II.C with BUFF = 0, the truth's contact test, as a set of times.)
fn contacts<F: ExactField>(sc: &Scene<'_, F>, w: &Window, i: usize) -> Set {
    let g = Lazy::new(sc, Kind::Cross(i), w);
    let ahead = Lazy::new(sc, Kind::Ahead(i), w);
    let behind = Lazy::new(sc, Kind::Behind(i), w);
    match roots_in(sc, &g, w) {
        None => {
            let a = sign_set(sc, &ahead, w, Ordering::Greater);
            a.intersect(sc, &sign_set(sc, &behind, w, Ordering::Greater))
        }
        Some(roots) => {
            let on = |r: &End| {
                sign_at_end(sc, &ahead, r) != Ordering::Less
                    && sign_at_end(sc, &behind, r) != Ordering::Less
            };
            let comps = roots
                .into_iter()
                .map(|(r, _)| r)
                .filter(on)
                .map(|r| (r.clone(), r))
                .collect();
            Set { comps }
        }
    }
}

/// The winding number of P around the point at the sample time (not on the boundary),
/// in the point's frame: the vertices relative to the point, q_i(τ) = (p_i − s) +
/// τ·(v_i − v), winding around the origin (the differences are taken before the motion,
/// so a polygon far from the origin loses no precision). In floats when they certify
/// it, else exactly. `None` if the point is on an edge.
/// (Paper A §II.D's ray crossings, exact and signed, at one time.)
pub(crate) fn winding_at<F: ExactField>(sc: &Scene<'_, F>, at: &Sample) -> Option<i64> {
    let x = &sc.fl.x;
    let poly: Vec<V2<Iv>> = sc
        .fl
        .p
        .iter()
        .map(|m| {
            let c = |k: usize| {
                let q0 = m.c0[k].sub(x.c0[k]);
                let q1 = m.c1[k].sub(x.c1[k]);
                q0.add(q1.mul(at.iv))
            };
            V2::new(c(0), c(1))
        })
        .collect();
    if let Ok(Some(w)) = winding_number(&Intervals, &poly, &V2::new(Iv::ZERO, Iv::ZERO)) {
        return Some(w);
    }
    let (x, ps) = sc.exact_at(at.exact());
    winding_number(&Exact, &ps, &x).decided()
}

/// The horizontal relation over the window: B, and each gap of B whose winding number
/// puts it in the relation (odd: inside; 0: outside); `Undefined` for an even, non-zero
/// winding number or a degenerate edge (see [`point_edges`]).
/// (The contract's inside / near_D / breach_D over a window, paper A §II: the method
/// of [`crate::intervals`](mod@crate::intervals), steps 1–3.)
pub(crate) fn horizontal<F: ExactField>(
    sc: &Scene<'_, F>,
    w: &Window,
    relation: Relation,
) -> Result<Set, Undefined> {
    let point_edge = point_edges(sc, w)?;
    let b = near_boundary(sc, w, &point_edge, false);
    let mut parts = b.comps.clone();
    for (lo, hi, at) in b.gaps(sc, w) {
        let inside = match winding_at(sc, &at) {
            None => true,
            Some(k) if k % 2 != 0 => true,
            Some(0) => false,
            Some(k) => {
                return Err(Undefined {
                    reason: format!(
                        "at t ≈ {} the point's winding number is {k}: inside by the nonzero rule, outside by the even-odd rule (the polygon is not simple)",
                        at.exact_text()
                    ),
                })
            }
        };
        let wanted = match relation {
            Relation::Inside | Relation::Near => inside,
            Relation::Breach => !inside,
        };
        if wanted {
            parts.push((lo, hi));
        }
    }
    Ok(Set::union_of(sc, parts))
}

/// The one gap of an empty B (the whole window): whether the point is outside there.
/// (Paper A §II.D at one time of the window: the keep-in fence's side.)
pub(crate) fn outside_throughout<F: ExactField>(
    sc: &Scene<'_, F>,
    w: &Window,
) -> Result<bool, Undefined> {
    let at = if w.is_point() {
        Sample::rational(w.lo.clone())
    } else {
        Sample::between(sc, &w.lo_end, &w.hi_end)
    };
    match winding_at(sc, &at) {
        Some(0) => Ok(true),
        None => Ok(false),
        Some(k) if k % 2 != 0 => Ok(false),
        Some(k) => Err(Undefined {
            reason: format!(
                "the point's winding number is {k}: inside by the nonzero rule, outside by the even-odd rule (the polygon is not simple)"
            ),
        }),
    }
}
