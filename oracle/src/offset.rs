//! Offsets and insets of paper A §II's polygon, exactly: the true sets and the exact
//! check of a given f64 result (the engine's `offset` module, mirrored by name).
//!
//! # Definitions
//! For a simple counterclockwise P (§II), D ≥ 0 and ε > 0, with L = D·(1 + ε):
//! - offset: B_D = P ⊕ disc(D) = {x : dist(x, P) ≤ D}; a result Q is correct when
//!   **B_D ⊆ Q ⊆ B_L**;
//! - inset: I_D = {x ∈ P : dist(x, ∂P) ≥ D}; Q is correct when **I_L ⊆ Q ⊆ I_D**.
//!
//! [`offset`], [`inset`] and their `_at` forms return a [`Buffer`]: P (at time t, exactly
//! p_i + t·V_i), D and ε as rationals. [`Buffer::check`] decides, in rationals, the parts
//! of correctness that a result's boundary determines, for rings given as f64 points:
//! - `rings`: each ring simple, outer rings counterclockwise, holes clockwise inside
//!   their outer ring, rings pairwise disjoint;
//! - `clear`: every edge of Q at distance ≥ D from every edge of P (squared distances,
//!   exact), and the located vertex: a vertex of P inside Q (offset), or outside Q with
//!   each outer ring's first vertex inside P (inset). Given `rings`, this holds **if and
//!   only if** B_D ⊆ Q (offset) or Q ⊆ I_D (inset): B_D and the D-neighbourhood of ∂P
//!   are connected, so ∂Q misses them exactly when they lie on one side of it;
//! - `close`: every point of ∂Q within L of ∂P: each edge of Q is covered by the union
//!   of the capsules {dist(·, e) ≤ L} of P's edges, decided with interval ends in
//!   Q(√d) (module `qfield`), exactly. Given `rings`, Q ⊆ B_L then holds unless a
//!   bounded component of the complement of B_L lies in Q (a hole of the true offset
//!   filled; for the inset, a piece of I_L missed), which the boundary cannot show:
//!   [`Buffer::inside_truth`], [`Buffer::inside_limit`] and [`locate`] decide it point by
//!   point for sampling tests.

use core::cmp::Ordering;

use crate::convert::{f64_to_exact, to_float};
use crate::error::OracleError;
use crate::field::{Arith, ExactField, Q, V2};
use crate::qfield::{quad_roots, Alg};
use crate::ring::{check_simple, orient, segments_meet, winding, Winding};

/// Which set: the offset B_D or the inset I_D (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// B_D = P ⊕ disc(D).
    Out,
    /// I_D = {x ∈ P : dist(x, ∂P) ≥ D}.
    In,
}

/// The exact problem: P, D, ε and the side.
#[derive(Clone, Debug)]
pub struct Buffer {
    /// P's vertices, exactly (counterclockwise, simple).
    pub p: Vec<V2<Q>>,
    /// D.
    pub d: Q,
    /// ε.
    pub eps: Q,
    /// Offset or inset.
    pub side: Side,
}

/// A result to check: an outer ring and its holes, as f64 points.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// The outer ring (counterclockwise).
    pub outer: Vec<[f64; 2]>,
    /// The holes (each clockwise).
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// The exact verdict on a result (see the module doc for what each part decides).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// Rings simple, oriented, nested and disjoint.
    pub rings: bool,
    /// B_D ⊆ Q (offset) or Q ⊆ I_D (inset), given `rings`.
    pub clear: bool,
    /// ∂Q within L = D(1 + ε) of ∂P.
    pub close: bool,
}

impl Verdict {
    /// All three parts hold.
    pub fn holds(&self) -> bool {
        self.rings && self.clear && self.close
    }
}

/// The exact problem of the offset of P by D (§II's polygon; see the module doc).
pub fn offset(p: &[[f64; 2]], d: f64, eps: f64) -> Result<Buffer, OracleError> {
    Buffer::new(exact_ring(p, "p")?, d, eps, Side::Out)
}

/// The exact problem of the inset of P by D (§II's polygon; see the module doc).
pub fn inset(p: &[[f64; 2]], d: f64, eps: f64) -> Result<Buffer, OracleError> {
    Buffer::new(exact_ring(p, "p")?, d, eps, Side::In)
}

/// [`offset`] of the polygon p_i + t·V_i at time t, exactly (§II's moving polygon).
pub fn offset_at(
    p: &[[f64; 2]],
    vels: &[[f64; 2]],
    t: f64,
    d: f64,
    eps: f64,
) -> Result<Buffer, OracleError> {
    Buffer::new(ring_at(p, vels, t)?, d, eps, Side::Out)
}

/// [`inset`] of the polygon p_i + t·V_i at time t, exactly (§II's moving polygon).
pub fn inset_at(
    p: &[[f64; 2]],
    vels: &[[f64; 2]],
    t: f64,
    d: f64,
    eps: f64,
) -> Result<Buffer, OracleError> {
    Buffer::new(ring_at(p, vels, t)?, d, eps, Side::In)
}

fn exact(x: f64, field: &'static str) -> Result<Q, OracleError> {
    f64_to_exact(x).ok_or_else(|| OracleError::new(field, "not finite"))
}

fn exact_ring(p: &[[f64; 2]], field: &'static str) -> Result<Vec<V2<Q>>, OracleError> {
    p.iter()
        .map(|v| Ok(V2::new(exact(v[0], field)?, exact(v[1], field)?)))
        .collect()
}

fn ring_at(p: &[[f64; 2]], vels: &[[f64; 2]], t: f64) -> Result<Vec<V2<Q>>, OracleError> {
    if vels.len() != p.len() {
        return Err(OracleError::new("vels", "not one velocity per vertex"));
    }
    let t = exact(t, "t")?;
    let (p, vels) = (exact_ring(p, "p")?, exact_ring(vels, "vels")?);
    Ok(p.iter().zip(&vels).map(|(pi, vi)| pi.at(vi, &t)).collect())
}

/// The squared distance from x to the segment [a, b], exactly: |x − a|² before a,
/// |x − b|² after b, the line's |x − a|² − ((x − a)·e)²/|e|² between.
pub fn point_segment_sq(x: &V2<Q>, a: &V2<Q>, b: &V2<Q>) -> Q {
    let (w, e) = (x.minus(a), b.minus(a));
    let (t, ee) = (w.dot(&e), e.sq());
    if !t.is_pos() {
        w.sq()
    } else if t >= ee {
        x.minus(b).sq()
    } else {
        w.sq() - &t * &t / ee
    }
}

/// dist(x, [a, b])² ≤ r2, exactly, without a division: the line's case compares
/// |w|²·|e|² − (w·e)² with r2·|e|².
fn point_segment_within(x: &V2<Q>, a: &V2<Q>, b: &V2<Q>, r2: &Q) -> bool {
    let (w, e) = (x.minus(a), b.minus(a));
    let (t, ee) = (w.dot(&e), e.sq());
    if !t.is_pos() {
        w.sq() <= *r2
    } else if t >= ee {
        x.minus(b).sq() <= *r2
    } else {
        w.sq() * &ee - &t * &t <= r2 * &ee
    }
}

/// The closed segments are at distance < r (r2 = r²): they meet, or an end of one is
/// closer than r to the other (the least distance of two disjoint segments is attained
/// at an end of one of them).
fn segments_closer(a: &V2<Q>, b: &V2<Q>, c: &V2<Q>, d: &V2<Q>, r2: &Q) -> bool {
    let closer = |x: &V2<Q>, p: &V2<Q>, q: &V2<Q>| {
        let (w, e) = (x.minus(p), q.minus(p));
        let (t, ee) = (w.dot(&e), e.sq());
        if !t.is_pos() {
            w.sq() < *r2
        } else if t >= ee {
            x.minus(q).sq() < *r2
        } else {
            w.sq() * &ee - &t * &t < r2 * &ee
        }
    };
    segments_meet(a, b, c, d)
        || closer(a, c, d)
        || closer(b, c, d)
        || closer(c, a, b)
        || closer(d, a, b)
}

/// The winding number of a ring about x and whether x is on it (exact).
fn winding_about(ring: &[V2<Q>], x: &V2<Q>) -> (i32, bool) {
    let n = ring.len();
    let (mut w, mut on) = (0, false);
    for i in 0..n {
        let (a, b) = (&ring[i], &ring[(i + 1) % n]);
        let o = orient(a, b, x);
        if o == 0 && !x.minus(a).dot(&x.minus(b)).is_pos() {
            on = true;
        }
        if a.y <= x.y && x.y < b.y && o > 0 {
            w += 1;
        } else if b.y <= x.y && x.y < a.y && o < 0 {
            w -= 1;
        }
    }
    (w, on)
}

/// Whether x lies in the closed region of the result (rings given as f64 points):
/// on a ring, or with a non-zero sum of winding numbers. Exact.
pub fn locate(regions: &[Region], x: &V2<Q>) -> Result<bool, OracleError> {
    Ok(locate_in(&exact_rings(regions)?, x))
}

/// Every ring of the result (outer rings and holes), exactly.
pub fn exact_rings(regions: &[Region]) -> Result<Vec<Vec<V2<Q>>>, OracleError> {
    regions
        .iter()
        .flat_map(|r| core::iter::once(&r.outer).chain(&r.holes))
        .map(|ring| exact_ring(ring, "regions"))
        .collect()
}

/// [`locate`] on rings already made exact ([`exact_rings`]).
pub fn locate_in(rings: &[Vec<V2<Q>>], x: &V2<Q>) -> bool {
    let mut total = 0;
    for ring in rings {
        let (w, on) = winding_about(ring, x);
        if on {
            return true;
        }
        total += w;
    }
    total != 0
}

/// The interval {s ∈ [lo, hi] : a·s² + b·s + c ≤ 0} for a > 0, or `None` if empty.
fn quad_below(a: &Q, b: &Q, c: &Q) -> Option<(Alg<Q>, Alg<Q>)> {
    let roots = quad_roots(a, b, c);
    match roots.len() {
        2 => Some((roots[0].clone(), roots[1].clone())),
        1 => Some((roots[0].clone(), roots[0].clone())),
        _ => None,
    }
}

/// The intersection of two closed intervals (`None` if empty).
fn meet(x: Option<(Alg<Q>, Alg<Q>)>, y: Option<(Alg<Q>, Alg<Q>)>) -> Option<(Alg<Q>, Alg<Q>)> {
    let ((a, b), (c, d)) = (x?, y?);
    let lo = if a.cmp_alg(&c) == Ordering::Less {
        c
    } else {
        a
    };
    let hi = if b.cmp_alg(&d) == Ordering::Less {
        b
    } else {
        d
    };
    (lo.cmp_alg(&hi) != Ordering::Greater).then_some((lo, hi))
}

/// {s : α + β·s ∈ [lo, hi]} for rational α, β and ends that are Alg numbers, as an
/// interval (`None` if empty; `whole` when β = 0 and α lies in it).
fn linear_in(
    alpha: &Q,
    beta: &Q,
    lo: &Alg<Q>,
    hi: &Alg<Q>,
    whole: (Alg<Q>, Alg<Q>),
) -> Option<(Alg<Q>, Alg<Q>)> {
    if beta.is_zero_() {
        let inside = lo.cmp_rat(alpha) != Ordering::Greater && hi.cmp_rat(alpha) != Ordering::Less;
        return inside.then_some(whole);
    }
    // s = (end − α)/β, for end = (p + q√d)/r: (p − α r + q√d)/(r β).
    let at = |e: &Alg<Q>| Alg::new(&e.p - alpha * &e.r, e.q.clone(), e.d.clone(), &e.r * beta);
    let (s0, s1) = (at(lo)?, at(hi)?);
    Some(if beta.is_pos() { (s0, s1) } else { (s1, s0) })
}

impl Buffer {
    fn new(p: Vec<V2<Q>>, d: f64, eps: f64, side: Side) -> Result<Buffer, OracleError> {
        if p.len() < 3 || check_simple(&p).is_err() || winding(&p) != Ok(Winding::Counterclockwise)
        {
            return Err(OracleError::new(
                "p",
                "not a simple counterclockwise polygon",
            ));
        }
        let d = exact(d, "d")?;
        let eps = exact(eps, "eps")?;
        if d.is_neg() {
            return Err(OracleError::new("d", "negative"));
        }
        if !eps.is_pos() {
            return Err(OracleError::new("eps", "not positive"));
        }
        Ok(Buffer { p, d, eps, side })
    }

    /// L = D·(1 + ε).
    pub fn limit(&self) -> Q {
        &self.d * (Q::one() + &self.eps)
    }

    fn edges(&self) -> impl Iterator<Item = (&V2<Q>, &V2<Q>)> {
        let n = self.p.len();
        (0..n).map(move |i| (&self.p[i], &self.p[(i + 1) % n]))
    }

    /// dist(x, ∂P)², exactly.
    pub fn boundary_sq(&self, x: &V2<Q>) -> Q {
        self.edges()
            .map(|(a, b)| point_segment_sq(x, a, b))
            .min()
            .unwrap_or_else(Q::zero)
    }

    /// x ∈ P (closed), exactly.
    pub fn in_p(&self, x: &V2<Q>) -> bool {
        let (w, on) = winding_about(&self.p, x);
        on || w != 0
    }

    /// x lies in the true set at D: B_D (offset) or I_D (inset).
    pub fn inside_truth(&self, x: &V2<Q>) -> bool {
        self.inside_at(x, &self.d)
    }

    /// x lies in the true set at L = D(1 + ε): B_L (offset) or I_L (inset).
    pub fn inside_limit(&self, x: &V2<Q>) -> bool {
        self.inside_at(x, &self.limit())
    }

    fn inside_at(&self, x: &V2<Q>, r: &Q) -> bool {
        let r2 = r * r;
        let near = |strict: bool| {
            self.edges().any(|(a, b)| {
                let within = point_segment_within(x, a, b, &r2);
                // dist < r: within r and not exactly at r (dist² ≤ r² but not ≥ r²).
                within && (!strict || !point_segment_sq(x, a, b).ge(&r2))
            })
        };
        match self.side {
            Side::Out => self.in_p(x) || near(false),
            Side::In => self.in_p(x) && !near(true),
        }
    }

    /// The exact verdict on a result (see the module doc).
    pub fn check(&self, regions: &[Region]) -> Result<Verdict, OracleError> {
        let mut rings = Vec::new();
        for r in regions {
            rings.push((true, exact_ring(&r.outer, "regions")?));
            for h in &r.holes {
                rings.push((false, exact_ring(h, "regions")?));
            }
        }
        let all: Vec<Vec<V2<Q>>> = rings.iter().map(|(_, r)| r.clone()).collect();
        Ok(Verdict {
            rings: self.rings_valid(regions, &rings),
            clear: self.clear(regions, &all)?,
            close: {
                let pf = floats(&self.p);
                all.iter().all(|r| self.ring_close(r, &pf))
            },
        })
    }

    fn rings_valid(&self, regions: &[Region], rings: &[(bool, Vec<V2<Q>>)]) -> bool {
        let all: Vec<Vec<V2<Q>>> = rings.iter().map(|(_, r)| r.clone()).collect();
        let fl: Vec<Vec<[f64; 2]>> = all.iter().map(|r| floats(r)).collect();
        if rings.iter().any(|(_, r)| r.len() < 3) || !rings_disjoint(&all, &fl) {
            return false;
        }
        let oriented = rings.iter().all(|(outer, r)| {
            let want = if *outer {
                Winding::Counterclockwise
            } else {
                Winding::Clockwise
            };
            winding(r) == Ok(want)
        });
        if !oriented {
            return false;
        }
        let mut k = 0;
        for reg in regions {
            let outer = &rings[k].1;
            k += 1;
            for _ in &reg.holes {
                if winding_about(outer, &rings[k].1[0]) != (1, false) {
                    return false;
                }
                k += 1;
            }
        }
        true
    }

    fn clear(&self, regions: &[Region], rings: &[Vec<V2<Q>>]) -> Result<bool, OracleError> {
        let d2 = &self.d * &self.d;
        let d_float = to_float(&self.d);
        let pf = floats(&self.p);
        let n = pf.len();
        for r in rings {
            let rf = floats(r);
            for i in 0..r.len() {
                let i1 = (i + 1) % r.len();
                let (a, b) = (&r[i], &r[i1]);
                for (j, (c, d)) in self.edges().enumerate() {
                    if !far_apart(rf[i], rf[i1], pf[j], pf[(j + 1) % n], d_float)
                        && segments_closer(a, b, c, d, &d2)
                    {
                        return Ok(false);
                    }
                }
            }
        }
        let p0_in = locate(regions, &self.p[0])?;
        Ok(match self.side {
            Side::Out => p0_in,
            Side::In => {
                !p0_in
                    && rings
                        .iter()
                        .zip(regions.iter().flat_map(|g| {
                            core::iter::once(true).chain(g.holes.iter().map(|_| false))
                        }))
                        .filter(|(_, outer)| *outer)
                        .all(|(r, _)| self.in_p(&r[0]))
            }
        })
    }

    /// Every edge of the ring is covered by the capsules of P's edges at L.
    fn ring_close(&self, r: &[V2<Q>], pf: &[[f64; 2]]) -> bool {
        let rf = floats(r);
        let n = r.len();
        (0..n).all(|i| self.segment_close(&r[i], &r[(i + 1) % n], (rf[i], rf[(i + 1) % n]), pf))
    }

    /// [a, b] ⊆ ⋃ {dist(·, e) ≤ L} over P's edges e: the parameters s ∈ [0, 1] of
    /// a + s·(b − a) within L of each vertex (a quadratic's roots) and of each edge's
    /// band (linear ends, one with √(L²|e|²)), swept in exact order.
    fn segment_close(
        &self,
        a: &V2<Q>,
        b: &V2<Q>,
        ab: ([f64; 2], [f64; 2]),
        pf: &[[f64; 2]],
    ) -> bool {
        let l = self.limit();
        let l2 = &l * &l;
        let l_float = to_float(&l);
        let e = b.minus(a);
        let ee = e.sq();
        let zero = Alg::rational(Q::zero());
        let one = Alg::rational(Q::one());
        let unit = (zero.clone(), one.clone());
        if ee.is_zero_() {
            return self.boundary_sq(a) <= l2;
        }
        let n = pf.len();
        // Enough (the distance to one segment is convex along [a, b]): both ends
        // within L of one edge.
        let near = |j: usize, c: &V2<Q>, d: &V2<Q>| {
            !far_apart(ab.0, ab.1, pf[j], pf[(j + 1) % n], l_float)
                && point_segment_within(a, c, d, &l2)
                && point_segment_within(b, c, d, &l2)
        };
        if self.edges().enumerate().any(|(j, (c, d))| near(j, c, d)) {
            return true;
        }
        let mut spans: Vec<(Alg<Q>, Alg<Q>)> = Vec::new();
        for (j, (c, d)) in self.edges().enumerate() {
            if far_apart(ab.0, ab.1, pf[j], pf[(j + 1) % n], l_float) {
                continue;
            }
            // The disc about c: |a − c + s·e|² ≤ L².
            let w = a.minus(c);
            let disc = quad_below(&ee, &(w.dot(&e) * Q::from_i64(2)), &(w.sq() - &l2));
            spans.extend(meet(disc, Some(unit.clone())));
            // The band of [c, d]: 0 ≤ (w + s·e)·E ≤ |E|² and |E × (w + s·e)| ≤ L·|E|.
            let big_e = d.minus(c);
            let eq = big_e.sq();
            if eq.is_zero_() {
                continue;
            }
            let along = linear_in(
                &w.dot(&big_e),
                &e.dot(&big_e),
                &zero,
                &Alg::rational(eq.clone()),
                unit.clone(),
            );
            let le = &l2 * &eq;
            let lo = Alg::new(Q::zero(), -Q::one(), le.clone(), Q::one());
            let hi = Alg::new(Q::zero(), Q::one(), le, Q::one());
            let (Some(lo), Some(hi)) = (lo, hi) else {
                continue;
            };
            let across = linear_in(&big_e.cross(&w), &big_e.cross(&e), &lo, &hi, unit.clone());
            spans.extend(meet(meet(along, across), Some(unit.clone())));
        }
        spans.sort_by(|x, y| x.0.cmp_alg(&y.0));
        let mut reach = zero;
        for (lo, hi) in spans {
            if lo.cmp_alg(&reach) == Ordering::Greater {
                return false;
            }
            if hi.cmp_alg(&reach) == Ordering::Greater {
                reach = hi;
            }
        }
        reach.cmp_alg(&one) != Ordering::Less
    }
}

/// A float prefilter that never drops a pair within `r` of each other: the boxes are
/// more than 2r + 2⁻⁵⁰·m apart along x or y in floats, m the largest |coordinate|.
/// Each float coordinate is within u·m of its exact value (u = 2⁻⁵³; exact for the
/// result's own points), the gap's subtraction adds at most u·2m, so the exact gap
/// exceeds the float one less 4u·m; and r, the nearest float to the exact bound, is at
/// least half of it.
fn far_apart(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2], r: f64) -> bool {
    let gx = (c[0].min(d[0]) - a[0].max(b[0])).max(a[0].min(b[0]) - c[0].max(d[0]));
    let gy = (c[1].min(d[1]) - a[1].max(b[1])).max(a[1].min(b[1]) - c[1].max(d[1]));
    let gap = gx.max(gy);
    let m = [a, b, c, d]
        .iter()
        .fold(0.0f64, |m, v| m.max(v[0].abs()).max(v[1].abs()));
    let rounding = m / 1_125_899_906_842_624.0; // 2⁻⁵⁰·m
    gap.is_finite() && gap > 2.0 * r + rounding
}

/// The nearest floats of exact points (for prefilters only).
fn floats(p: &[V2<Q>]) -> Vec<[f64; 2]> {
    p.iter().map(|v| [to_float(&v.x), to_float(&v.y)]).collect()
}

/// No two edges of the rings meet, except neighbours of one ring at their common
/// vertex (without folding back over each other). Pairs are pruned by their boxes
/// (exact comparisons of the f64 coordinates), swept along x; each remaining pair is
/// decided exactly.
fn rings_disjoint(rings: &[Vec<V2<Q>>], floats: &[Vec<[f64; 2]>]) -> bool {
    // (ring, index, min x, max x, min y, max y)
    let mut es = Vec::new();
    for (k, r) in floats.iter().enumerate() {
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            es.push((
                k,
                i,
                a[0].min(b[0]),
                a[0].max(b[0]),
                a[1].min(b[1]),
                a[1].max(b[1]),
            ));
        }
    }
    es.sort_by(|x, y| x.2.total_cmp(&y.2));
    for (m, &(k, i, _, hx, ly, hy)) in es.iter().enumerate() {
        for &(l, j, lx2, _, ly2, hy2) in &es[m + 1..] {
            if lx2 > hx {
                break;
            }
            if ly2 > hy || ly > hy2 {
                continue;
            }
            let (ri, rj) = (&rings[k], &rings[l]);
            let (p, q) = (&ri[i], &ri[(i + 1) % ri.len()]);
            let (r, s) = (&rj[j], &rj[(j + 1) % rj.len()]);
            let n = ri.len();
            let neighbours = k == l && ((i + 1) % n == j || (j + 1) % n == i);
            if neighbours {
                // Sharing one vertex: they meet elsewhere only when they fold back.
                let (shared, x, y) = if (i + 1) % n == j {
                    (q, p, s)
                } else {
                    (p, q, r)
                };
                if orient(x, shared, y) == 0 && x.minus(shared).dot(&y.minus(shared)).is_pos() {
                    return false;
                }
            } else if segments_meet(p, q, r, s) {
                return false;
            }
        }
    }
    true
}

/// The exact point of an f64 pair (`None` if not finite), for sampling.
pub fn exact_point(x: [f64; 2]) -> Option<V2<Q>> {
    Some(V2::new(f64_to_exact(x[0])?, f64_to_exact(x[1])?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn region(outer: &[[f64; 2]]) -> Region {
        Region {
            outer: outer.to_vec(),
            holes: Vec::new(),
        }
    }

    const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];

    #[test]
    fn the_mitred_square_contains_the_buffer_but_reaches_too_far() {
        let b = offset(&SQUARE, 1.0, 0.01).expect("valid");
        let mitred = region(&[[-1.0, -1.0], [3.0, -1.0], [3.0, 3.0], [-1.0, 3.0]]);
        let v = b.check(&[mitred]).expect("finite");
        assert!(v.rings && v.clear && !v.close, "{v:?}");
        // With ε = 1, L = 2 reaches the mitred corners (√2 from the square's).
        let wide = offset(&SQUARE, 1.0, 1.0).expect("valid");
        let mitred = region(&[[-1.0, -1.0], [3.0, -1.0], [3.0, 3.0], [-1.0, 3.0]]);
        assert!(wide.check(&[mitred]).expect("finite").holds());
    }

    #[test]
    fn a_square_cut_at_its_corners_misses_the_buffer() {
        let b = offset(&SQUARE, 1.0, 0.01).expect("valid");
        // The octagon through the edges' shifted copies, its corners cut at distance
        // 1/√2 < 1 from the square's corners.
        let cut = region(&[
            [0.0, -1.0],
            [2.0, -1.0],
            [3.0, 0.0],
            [3.0, 2.0],
            [2.0, 3.0],
            [0.0, 3.0],
            [-1.0, 2.0],
            [-1.0, 0.0],
        ]);
        let v = b.check(&[cut]).expect("finite");
        assert!(v.rings && !v.clear && v.close, "{v:?}");
    }

    #[test]
    fn the_inset_square_is_exact_and_the_wrong_way_round_is_not_a_ring() {
        let b = inset(&SQUARE, 0.5, 0.01).expect("valid");
        let inner = region(&[[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]);
        assert!(b
            .check(std::slice::from_ref(&inner))
            .expect("finite")
            .holds());
        let mut cw = inner.clone();
        cw.outer.reverse();
        assert!(!b.check(&[cw]).expect("finite").rings);
        // Too deep: closer than D to the boundary.
        let fat = region(&[[0.4, 0.4], [1.6, 0.4], [1.6, 1.6], [0.4, 1.6]]);
        assert!(!b.check(&[fat]).expect("finite").clear);
        // Points: the centre is in I_D, a point 0.3 from the boundary is not.
        let centre = exact_point([1.0, 1.0]).expect("finite");
        assert!(b.inside_truth(&centre) && b.inside_limit(&centre));
        assert!(!b.inside_truth(&exact_point([0.3, 1.0]).expect("finite")));
    }

    #[test]
    fn arguments_name_their_field() {
        assert_eq!(offset(&SQUARE, -1.0, 0.1).unwrap_err().field, "d");
        assert_eq!(inset(&SQUARE, 1.0, 0.0).unwrap_err().field, "eps");
        let mut cw = SQUARE;
        cw.reverse();
        assert_eq!(offset(&cw, 1.0, 0.1).unwrap_err().field, "p");
        assert_eq!(
            offset_at(&SQUARE, &[[0.0, 0.0]; 3], 1.0, 1.0, 0.1)
                .unwrap_err()
                .field,
            "vels"
        );
        let moved = offset_at(&SQUARE, &[[1.0, 0.0]; 4], 2.0, 1.0, 0.1).expect("valid");
        assert_eq!(moved.p[0], exact_point([2.0, 0.0]).expect("finite"));
    }
}
