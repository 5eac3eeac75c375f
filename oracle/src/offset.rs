//! Offsets and insets of paper A §II's polygon, exactly: the true sets and the exact
//! check of a given binary-float result (the engine's `offset` module, mirrored by name).
//!
//! # Definitions
//! For a simple counterclockwise P (§II), D ≥ 0 and ε > 0, with L = D·(1 + ε):
//! - offset: B_D = P ⊕ disc(D) = {x : dist(x, P) ≤ D}; a result Q is correct when
//!   **B_D ⊆ Q ⊆ B_L**;
//! - inset: I_D = {x ∈ P : dist(x, ∂P) ≥ D}; Q is correct when **I_L ⊆ Q ⊆ I_D**.
//!
//! [`offset`], [`inset`] and their `_at` forms return a [`Buffer`]: P (at time t, exactly
//! p_i + t·V_i), D and ε as rationals. [`Buffer::check`] decides, in rationals, the parts
//! of correctness that a result's boundary determines, for rings given as binary floats
//! or text (any [`Input`], made exact at once):
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
//!
//! The point–segment tests and orientations behind these decisions first run in
//! rigorous intervals ([`crate::kernel::interval`]) and fall back to rationals only when
//! an enclosure cannot settle them, so every decision stays exact (`tests/offset.rs`
//! checks the filtered and the exact-only forms against each other).

use core::cmp::Ordering;

use crate::convert::Input;
use crate::error::OracleError;
use crate::field::{Arith, ExactField, Q, V2};
use crate::kernel::interval::{enclose, enclose2, Abstain, Iv};
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

/// A result to check: an outer ring and its holes, as points the oracle reads exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Region<I> {
    /// The outer ring (counterclockwise).
    pub outer: Vec<[I; 2]>,
    /// The holes (each clockwise).
    pub holes: Vec<Vec<[I; 2]>>,
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
pub fn offset<I: Input>(p: &[[I; 2]], d: I, eps: I) -> Result<Buffer, OracleError> {
    Buffer::new(
        exact_ring(p, "p")?,
        d.exact("d")?,
        eps.exact("eps")?,
        Side::Out,
    )
}

/// The exact problem of the inset of P by D (§II's polygon; see the module doc).
pub fn inset<I: Input>(p: &[[I; 2]], d: I, eps: I) -> Result<Buffer, OracleError> {
    Buffer::new(
        exact_ring(p, "p")?,
        d.exact("d")?,
        eps.exact("eps")?,
        Side::In,
    )
}

/// [`offset`] of the polygon p_i + t·V_i at time t, exactly (§II's moving polygon).
pub fn offset_at<I: Input>(
    p: &[[I; 2]],
    vels: &[[I; 2]],
    t: I,
    d: I,
    eps: I,
) -> Result<Buffer, OracleError> {
    let p = ring_at(p, vels, t)?;
    Buffer::new(p, d.exact("d")?, eps.exact("eps")?, Side::Out)
}

/// [`inset`] of the polygon p_i + t·V_i at time t, exactly (§II's moving polygon).
pub fn inset_at<I: Input>(
    p: &[[I; 2]],
    vels: &[[I; 2]],
    t: I,
    d: I,
    eps: I,
) -> Result<Buffer, OracleError> {
    let p = ring_at(p, vels, t)?;
    Buffer::new(p, d.exact("d")?, eps.exact("eps")?, Side::In)
}

fn exact_ring<I: Input>(p: &[[I; 2]], field: &'static str) -> Result<Vec<V2<Q>>, OracleError> {
    p.iter()
        .map(|v| Ok(V2::new(v[0].exact(field)?, v[1].exact(field)?)))
        .collect()
}

fn ring_at<I: Input>(p: &[[I; 2]], vels: &[[I; 2]], t: I) -> Result<Vec<V2<Q>>, OracleError> {
    if vels.len() != p.len() {
        return Err(OracleError::new("vels", "not one velocity per vertex"));
    }
    let t: Q = t.exact("t")?;
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
    segment_near(x, a, b, r2, false, true)
}

/// dist(x, [a, b])² < r2 (`strict`) or ≤ r2, exactly: first in intervals (when
/// `filter`), by the rationals of `point_segment_within` when an enclosure holds the
/// tie.
pub fn segment_near(x: &V2<Q>, a: &V2<Q>, b: &V2<Q>, r2: &Q, strict: bool, filter: bool) -> bool {
    if filter {
        if let Ok(v) = segment_near_iv(x, a, b, r2, strict) {
            return v;
        }
    }
    let cmp = |l: Q, r: &Q| if strict { l < *r } else { l <= *r };
    let (w, e) = (x.minus(a), b.minus(a));
    let (t, ee) = (w.dot(&e), e.sq());
    if !t.is_pos() {
        cmp(w.sq(), r2)
    } else if t >= ee {
        cmp(x.minus(b).sq(), r2)
    } else {
        cmp(w.sq() * &ee - &t * &t, &(r2 * &ee))
    }
}

/// [`segment_near`] in rigorous intervals, the same branches; `Err` when one cannot
/// be told.
fn segment_near_iv(x: &V2<Q>, a: &V2<Q>, b: &V2<Q>, r2: &Q, strict: bool) -> Result<bool, Abstain> {
    let (xi, ai, bi, r2i) = (enclose2(x), enclose2(a), enclose2(b), enclose(r2));
    let cmp = |l: Iv, r: Iv| if strict { l.lt(r) } else { l.le(r) };
    let (w, e) = (xi.minus(&ai), bi.minus(&ai));
    let (t, ee) = (w.dot(&e), e.sq());
    if t.sign()? != Ordering::Greater {
        cmp(w.sq(), r2i)
    } else if t.sub(ee).sign()? != Ordering::Less {
        cmp(xi.minus(&bi).sq(), r2i)
    } else {
        cmp(w.sq().mul(ee).sub(t.sq()), r2i.mul(ee))
    }
}

/// orient(a, b, c), read off an enclosure of the cross product when it excludes 0,
/// else exactly.
fn orient_f(a: &V2<Q>, b: &V2<Q>, c: &V2<Q>) -> i8 {
    let (ai, bi, ci) = (enclose2(a), enclose2(b), enclose2(c));
    match bi.minus(&ai).cross(&ci.minus(&ai)).sign() {
        Ok(Ordering::Greater) => 1,
        Ok(Ordering::Less) => -1,
        _ => orient(a, b, c),
    }
}

/// The closed segments meet: a proper crossing told by filtered orientations, every
/// other case by [`segments_meet`].
fn segments_meet_f(a: &V2<Q>, b: &V2<Q>, c: &V2<Q>, d: &V2<Q>) -> bool {
    let (o1, o2) = (orient_f(a, b, c), orient_f(a, b, d));
    let (o3, o4) = (orient_f(c, d, a), orient_f(c, d, b));
    if o1 * o2 > 0 || o3 * o4 > 0 {
        return false;
    }
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    segments_meet(a, b, c, d)
}

/// The closed segments are at distance < r (r2 = r²): they meet, or an end of one is
/// closer than r to the other (the least distance of two disjoint segments is attained
/// at an end of one of them).
fn segments_closer(a: &V2<Q>, b: &V2<Q>, c: &V2<Q>, d: &V2<Q>, r2: &Q) -> bool {
    segments_meet_f(a, b, c, d)
        || segment_near(a, c, d, r2, true, true)
        || segment_near(b, c, d, r2, true, true)
        || segment_near(c, a, b, r2, true, true)
        || segment_near(d, a, b, r2, true, true)
}

/// The winding number of a ring about x and whether x is on it (exact).
fn winding_about(ring: &[V2<Q>], x: &V2<Q>) -> (i32, bool) {
    let n = ring.len();
    let (mut w, mut on) = (0, false);
    for i in 0..n {
        let (a, b) = (&ring[i], &ring[(i + 1) % n]);
        let o = orient_f(a, b, x);
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

/// Whether x lies in the closed region of the result: on a ring, or with a non-zero
/// sum of winding numbers. Exact.
pub fn locate<I: Input>(regions: &[Region<I>], x: &V2<Q>) -> Result<bool, OracleError> {
    Ok(locate_in(&exact_rings(regions)?, x))
}

/// Every ring of the result (outer rings and holes), exactly.
pub fn exact_rings<I: Input>(regions: &[Region<I>]) -> Result<Vec<Vec<V2<Q>>>, OracleError> {
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
    fn new(p: Vec<V2<Q>>, d: Q, eps: Q, side: Side) -> Result<Buffer, OracleError> {
        if p.len() < 3 || check_simple(&p).is_err() || winding(&p) != Ok(Winding::Counterclockwise)
        {
            return Err(OracleError::new(
                "p",
                "not a simple counterclockwise polygon",
            ));
        }
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
            self.edges()
                .any(|(a, b)| segment_near(x, a, b, &r2, strict, true))
        };
        match self.side {
            Side::Out => self.in_p(x) || near(false),
            Side::In => self.in_p(x) && !near(true),
        }
    }

    /// The exact verdict on a result (see the module doc).
    pub fn check<I: Input>(&self, regions: &[Region<I>]) -> Result<Verdict, OracleError> {
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
                let pb = boxes(&self.p);
                all.iter().all(|r| self.ring_close(r, &pb))
            },
        })
    }

    fn rings_valid<I>(&self, regions: &[Region<I>], rings: &[(bool, Vec<V2<Q>>)]) -> bool {
        let all: Vec<Vec<V2<Q>>> = rings.iter().map(|(_, r)| r.clone()).collect();
        if rings.iter().any(|(_, r)| r.len() < 3) || !rings_disjoint(&all) {
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

    fn clear<I>(&self, regions: &[Region<I>], rings: &[Vec<V2<Q>>]) -> Result<bool, OracleError> {
        let d2 = &self.d * &self.d;
        let pb = boxes(&self.p);
        for r in rings {
            for (i, rb) in boxes(r).iter().enumerate() {
                let (a, b) = (&r[i], &r[(i + 1) % r.len()]);
                let grown = rb.grown(&self.d);
                for ((c, d), qb) in self.edges().zip(&pb) {
                    if !grown.apart(qb) && segments_closer(a, b, c, d, &d2) {
                        return Ok(false);
                    }
                }
            }
        }
        let p0_in = locate_in(rings, &self.p[0]);
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
    fn ring_close(&self, r: &[V2<Q>], pb: &[Bx]) -> bool {
        let n = r.len();
        let l = self.limit();
        boxes(r)
            .iter()
            .enumerate()
            .all(|(i, rb)| self.segment_close(&r[i], &r[(i + 1) % n], &rb.grown(&l), pb))
    }

    /// [a, b] ⊆ ⋃ {dist(·, e) ≤ L} over P's edges e: the parameters s ∈ [0, 1] of
    /// a + s·(b − a) within L of each vertex (a quadratic's roots) and of each edge's
    /// band (linear ends, one with √(L²|e|²)), swept in exact order.
    fn segment_close(&self, a: &V2<Q>, b: &V2<Q>, grown: &Bx, pb: &[Bx]) -> bool {
        let l = self.limit();
        let l2 = &l * &l;
        let e = b.minus(a);
        let ee = e.sq();
        let zero = Alg::rational(Q::zero());
        let one = Alg::rational(Q::one());
        let unit = (zero.clone(), one.clone());
        if ee.is_zero_() {
            return self.boundary_sq(a) <= l2;
        }
        // Enough (the distance to one segment is convex along [a, b]): both ends
        // within L of one edge.
        let near = |j: usize, c: &V2<Q>, d: &V2<Q>| {
            !grown.apart(&pb[j])
                && point_segment_within(a, c, d, &l2)
                && point_segment_within(b, c, d, &l2)
        };
        if self.edges().enumerate().any(|(j, (c, d))| near(j, c, d)) {
            return true;
        }
        let mut spans: Vec<(Alg<Q>, Alg<Q>)> = Vec::new();
        for (j, (c, d)) in self.edges().enumerate() {
            if grown.apart(&pb[j]) {
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

/// The closed box of a segment, exactly.
#[derive(Clone, Debug)]
struct Bx {
    lo: V2<Q>,
    hi: V2<Q>,
}

impl Bx {
    fn of(a: &V2<Q>, b: &V2<Q>) -> Bx {
        let mn = |x: &Q, y: &Q| if x < y { x.clone() } else { y.clone() };
        let mx = |x: &Q, y: &Q| if x > y { x.clone() } else { y.clone() };
        Bx {
            lo: V2::new(mn(&a.x, &b.x), mn(&a.y, &b.y)),
            hi: V2::new(mx(&a.x, &b.x), mx(&a.y, &b.y)),
        }
    }

    /// The box grown by r on every side.
    fn grown(&self, r: &Q) -> Bx {
        Bx {
            lo: V2::new(&self.lo.x - r, &self.lo.y - r),
            hi: V2::new(&self.hi.x + r, &self.hi.y + r),
        }
    }

    /// The boxes share no point (then the segments of a box grown by r and of the
    /// other are more than r apart).
    fn apart(&self, o: &Bx) -> bool {
        o.lo.x > self.hi.x || o.hi.x < self.lo.x || o.lo.y > self.hi.y || o.hi.y < self.lo.y
    }
}

/// The boxes of a ring's edges, edge i from vertex i to i + 1.
fn boxes(r: &[V2<Q>]) -> Vec<Bx> {
    (0..r.len())
        .map(|i| Bx::of(&r[i], &r[(i + 1) % r.len()]))
        .collect()
}

/// No two edges of the rings meet, except neighbours of one ring at their common
/// vertex (without folding back over each other). Pairs are pruned by their boxes,
/// swept along x; each remaining pair is decided exactly.
fn rings_disjoint(rings: &[Vec<V2<Q>>]) -> bool {
    let mut es = Vec::new();
    for (k, r) in rings.iter().enumerate() {
        for (i, b) in boxes(r).into_iter().enumerate() {
            es.push((k, i, b));
        }
    }
    es.sort_by(|x, y| x.2.lo.x.cmp(&y.2.lo.x));
    for (m, (k, i, bi)) in es.iter().enumerate() {
        let (k, i) = (*k, *i);
        for (l, j, bj) in &es[m + 1..] {
            if bj.lo.x > bi.hi.x {
                break;
            }
            if bi.apart(bj) {
                continue;
            }
            let (l, j) = (*l, *j);
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

/// The exact point of a pair the oracle reads, for sampling.
pub fn exact_point<I: Input>(x: [I; 2]) -> Result<V2<Q>, OracleError> {
    Ok(V2::new(x[0].exact("x")?, x[1].exact("x")?))
}
