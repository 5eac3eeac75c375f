//! Paper A §II.B–§II.E: is the point s definitely outside the polygon P?
//!
//! The certified forms work in the point's frame: [`RelPoly`] hands out each vertex
//! minus the point as a ball (and, where it can, as exact terms), so that the same code
//! serves P at time 0, P + T·V at the lookahead and P + a·V at a slab window's start,
//! and every radius is on the scale of the encounter rather than of the coordinates.

use crate::ball::{mx, BallV, Tri};
use crate::lanes::{self, Frame, Kernel, KernelFn};
use crate::polygon::VertexSeq;
use crate::predicates::{self as pr, Terms};
use crate::vect2::Vect2;

/// Paper A §II.B: vertex i of P*_BUFF. A vertex with p_y ≥ s_y − BUFF and
/// |p_x − s_x| ≤ BUFF moves to p − (2·BUFF, 0); any other stays.
///
/// The OCR'd text lost both minus signs ("s_y BUFF", "p(i) (2BUFF, 0)"). Moving left by
/// 2·BUFF puts the vertex at x ≤ s_x − BUFF < s_x, off the upward ray, as §II.D needs.
/// The decision is exact (a sum of three floats); the moved x is rounded once.
#[inline]
///
/// ```
/// use polyguard::{perturb, Vect2};
/// let s = Vect2::new(0.0, 0.0);
/// // a vertex just above s, within BUFF of the upward ray, moves 2·BUFF left
/// assert_eq!(perturb(Vect2::new(0.05, 3.0), s, 0.1), Vect2::new(0.05 - 0.2, 3.0));
/// // a vertex below s stays
/// assert_eq!(perturb(Vect2::new(0.05, -3.0), s, 0.1), Vect2::new(0.05, -3.0));
/// ```
pub fn perturb(p: Vect2, s: Vect2, buff: f64) -> Vect2 {
    let q = BallV::diff(p, s);
    if pr::perturbs(q, || Some(Terms::diff(p, s)), buff) == Tri::Yes {
        Vect2::new(p.x - 2.0 * buff, p.y)
    } else {
        p
    }
}

/// Paper A §II.B: the perturbed polygon P*_BUFF, computed vertex by vertex on access.
#[derive(Clone, Copy, Debug)]
pub struct Perturbed<P> {
    /// The polygon P.
    pub poly: P,
    /// The point s it is seen from.
    pub s: Vect2,
    /// BUFF.
    pub buff: f64,
}

impl<P: VertexSeq> VertexSeq for Perturbed<P> {
    #[inline(always)]
    fn count(&self) -> usize {
        self.poly.count()
    }
    #[inline(always)]
    fn vertex(&self, i: usize) -> Vect2 {
        perturb(self.poly.vertex(i), self.s, self.buff)
    }
}

/// A polygon seen from the moving point: vertex i minus the point, as a ball, and as
/// exact terms when the vertex is a simple enough expression of the inputs.
#[doc(hidden)]
pub trait RelPoly {
    /// Number of vertices.
    fn count(&self) -> usize;
    /// Vertex i relative to the point.
    fn rel(&self, i: usize) -> BallV;
    /// Vertex i relative to the point as exact sums of floats, if it is one.
    fn terms(&self, i: usize) -> Option<Terms>;
    /// The computed value of [`RelPoly::rel`] alone (each frame computes it its own,
    /// cheaper way: no default, so that none is left unused and untested).
    fn at(&self, i: usize) -> Vect2;
    /// A margin M, the same for every vertex, such that a coordinate computed by
    /// [`RelPoly::at`] at or above M (at or below −M) is certainly above BUFF (below
    /// −BUFF) exactly, strictly; `None` when the error is not bounded that way.
    fn skip_margin(&self, buff: f64) -> Option<f64>;
    /// The vertices and the frame's translation, when [`RelPoly::at`] is fl(p_i − s)
    /// (+ a shift common to all vertices) of contiguously stored vertices p_i: the skip
    /// filter then tests several vertices at once ([`crate::lanes`]). `None` otherwise.
    #[inline(always)]
    fn frame(&self) -> Option<Frame<'_>> {
        None
    }
    /// The vertex after i, cyclically.
    #[inline(always)]
    fn next(&self, i: usize) -> usize {
        if i + 1 == self.count() {
            0
        } else {
            i + 1
        }
    }
}

/// P + t·V seen from s + t·v, for an exact float time t (t = 0: P seen from s).
#[derive(Clone, Copy, Debug)]
#[doc(hidden)]
pub struct AtTime<'a, P: ?Sized, V: ?Sized> {
    /// The vertices P at t = 0.
    pub p: &'a P,
    /// Their velocities V.
    pub vels: &'a V,
    /// The point s at t = 0.
    pub s: Vect2,
    /// Its velocity v.
    pub v: Vect2,
    /// The time, as a ball (an exact float when its radius is 0).
    pub t: crate::ball::Ball,
}

impl<P: VertexSeq + ?Sized, V: VertexSeq + ?Sized> RelPoly for AtTime<'_, P, V> {
    #[inline(always)]
    fn count(&self) -> usize {
        self.p.count()
    }
    /// (p_i − s) + t·(v_i − v).
    #[inline(always)]
    fn rel(&self, i: usize) -> BallV {
        let d = BallV::diff(self.p.vertex(i), self.s);
        if self.t.z == 0.0 && self.t.r == 0.0 {
            return d;
        }
        let w = BallV::diff(self.vels.vertex(i), self.v);
        d.add(w.scale(self.t))
    }
    /// At t = 0 the only error is the rounding of p_i − s: |x̃ − x| ≤ u|x| for a normal
    /// x̃, none for a subnormal one (subnormal differences are exact). The margin must
    /// be strictly above BUFF, since a vertex exactly BUFF to the side is perturbed:
    /// for a normal BUFF, BUFF·(1 + 4u) rounds to at least BUFF(1 + 3u), and x̃ ≥ that
    /// gives x ≥ BUFF·(1 + 3u)/(1 + u) > BUFF; for a subnormal BUFF the product rounds
    /// back to BUFF, and + ETA (2⁻¹⁰⁶⁵, added exactly) keeps it strictly above.
    #[inline(always)]
    fn skip_margin(&self, buff: f64) -> Option<f64> {
        if self.t.z == 0.0 && self.t.r == 0.0 {
            Some(buff * (1.0 + 4.0 * crate::ball::U) + crate::ball::ETA)
        } else {
            None
        }
    }
    #[inline(always)]
    fn at(&self, i: usize) -> Vect2 {
        if self.t.z == 0.0 && self.t.r == 0.0 {
            self.p.vertex(i) - self.s
        } else {
            self.rel(i).v
        }
    }
    /// At t = 0, P seen from s: fl(p_i − s), as [`RelPoly::at`] computes it.
    #[inline(always)]
    fn frame(&self) -> Option<Frame<'_>> {
        if self.t.z == 0.0 && self.t.r == 0.0 {
            Some(Frame {
                verts: self.p.as_slice()?,
                s: self.s,
                shift: None,
            })
        } else {
            None
        }
    }
    #[inline(always)]
    fn terms(&self, i: usize) -> Option<Terms> {
        let t = Terms::diff(self.p.vertex(i), self.s);
        if self.t.z == 0.0 && self.t.r == 0.0 {
            return Some(t);
        }
        if self.t.r != 0.0 {
            return None;
        }
        t.plus_scaled(self.t.z, self.vels.vertex(i))?
            .plus_scaled(-self.t.z, self.v)
    }
}

/// A statically shaped P + t·V (all v_i = v_0) seen from s + t·v: P seen from s,
/// shifted by one vector t·(v_0 − v), formed once (its exact terms only on demand).
#[derive(Clone, Copy, Debug)]
#[doc(hidden)]
pub struct Shifted<'a, P: ?Sized> {
    /// The vertices P at t = 0.
    pub p: &'a P,
    /// The point s at t = 0.
    pub s: Vect2,
    /// Its velocity v.
    pub v: Vect2,
    /// The common vertex velocity v_0.
    pub v0: Vect2,
    /// The time, as a ball.
    pub t: crate::ball::Ball,
    /// t·(v_0 − v) as a ball.
    pub shift: BallV,
    /// A constant error margin for [`RelPoly::skip_margin`]: 3u·‖shift‖∞ + r_shift.
    slack: f64,
}

impl<'a, P: VertexSeq + ?Sized> Shifted<'a, P> {
    /// P + t·V seen from s + t·v, for V all equal to v0.
    pub fn new(p: &'a P, s: Vect2, v: Vect2, v0: Vect2, t: crate::ball::Ball) -> Self {
        let shift = BallV::diff(v0, v).scale(t);
        let slack =
            crate::ball::up(3.0 * crate::ball::U * mx(shift.v.x.abs(), shift.v.y.abs()) + shift.r);
        Shifted {
            p,
            s,
            v,
            v0,
            t,
            shift,
            slack,
        }
    }
}

impl<P: VertexSeq + ?Sized> RelPoly for Shifted<'_, P> {
    #[inline(always)]
    fn count(&self) -> usize {
        self.p.count()
    }
    #[inline(always)]
    fn rel(&self, i: usize) -> BallV {
        BallV::diff(self.p.vertex(i), self.s).add(self.shift)
    }
    #[inline(always)]
    fn at(&self, i: usize) -> Vect2 {
        (self.p.vertex(i) - self.s) + self.shift.v
    }
    /// fl(fl(p_i − s) + sh̃), as [`RelPoly::at`] computes it.
    #[inline(always)]
    fn frame(&self) -> Option<Frame<'_>> {
        Some(Frame {
            verts: self.p.as_slice()?,
            s: self.s,
            shift: Some(self.shift.v),
        })
    }
    /// x̃ = fl(fl(p − s) + sh̃): |x̃ − x| ≤ u|x̃|(1 + 2u) (the sum) + 2u|fl(p − s)| (the
    /// difference, |fl(p − s)| ≤ (|x̃| + |sh̃|)(1 + 2u)) + r_sh ≤ 5u|x̃| + C with
    /// C = 3u·|sh̃| + r_sh. So x̃ > (BUFF + C)/(1 − 5u) gives x > BUFF; [`crate::ball::up`]
    /// of BUFF + C is larger than that, so x̃ ≥ it suffices.
    #[inline(always)]
    fn skip_margin(&self, buff: f64) -> Option<f64> {
        Some(crate::ball::up(buff + self.slack))
    }
    #[inline(always)]
    fn terms(&self, i: usize) -> Option<Terms> {
        if self.t.r != 0.0 {
            return None;
        }
        Terms::diff(self.p.vertex(i), self.s)
            .plus_scaled(self.t.z, self.v0)?
            .plus_scaled(-self.t.z, self.v)
    }
}

/// Paper A §II.C near_edge in the point's frame: is the origin closer than BUFF to the
/// segment a b? Step 1 tests the ends, step 2 the interior minimum of the quadratic
/// (see [`pr::interior_closer_than`] for why that is quad_min_le_D's step 2).
///
/// A filter goes first: the origin farther than BUFF from the segment's bounding box
/// (enlarged by the radii) is certainly not near it.
///
/// `terms` gives the ends' exact terms (relative to the point) for the comparisons the
/// balls cannot settle; it is called only then.
#[inline]
#[doc(hidden)]
pub fn near_edge_rel(
    a: BallV,
    b: BallV,
    buff: f64,
    terms: impl Fn() -> Option<(Terms, Terms)>,
) -> Tri {
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    // A non-finite coordinate comes with an infinite radius (see ball::bounded), so t is
    // then +∞ and nothing is filtered. Closed comparisons: with both balls in x ≥ BUFF
    // (t ≥ BUFF + radius), every point of the segment is at distance ≥ BUFF, and
    // "closer than BUFF" is strict, so a tie is decided too.
    let t = crate::ball::up(buff + mx(a.r, b.r));
    if (a.v.x >= t && b.v.x >= t)
        || (a.v.x <= -t && b.v.x <= -t)
        || (a.v.y >= t && b.v.y >= t)
        || (a.v.y <= -t && b.v.y <= -t)
    {
        return Tri::No;
    }
    let ends =
        pr::closer_than(a, buff, || terms().map(|t| t.0))
            .or(pr::closer_than(b, buff, || terms().map(|t| t.1)));
    if ends == Tri::Yes {
        return Tri::Yes;
    }
    ends.or(pr::interior_closer_than(a, b, buff, terms))
}

/// Paper A §II.C near_edge: is s closer than BUFF to some point of the segment p_i p_j?
///
/// Certified: `false` only when the exact answer is false; `true` when it is true or
/// when a comparison could not be decided in f64 (see [`near_edge_tri`]).
#[inline]
///
/// ```
/// use polyguard::{near_edge, Vect2};
/// let (a, b) = (Vect2::new(0.0, 0.0), Vect2::new(4.0, 0.0));
/// assert!(near_edge(a, b, Vect2::new(2.0, 0.5), 1.0)); // 0.5 from the edge's middle
/// assert!(!near_edge(a, b, Vect2::new(6.0, 0.0), 1.0)); // 2 beyond its end
/// ```
pub fn near_edge(pi: Vect2, pj: Vect2, s: Vect2, buff: f64) -> bool {
    near_edge_tri(pi, pj, s, buff).or_true()
}

/// Paper A §II.C near_edge, three-valued (see [`near_edge`]).
#[inline]
pub fn near_edge_tri(pi: Vect2, pj: Vect2, s: Vect2, buff: f64) -> Tri {
    near_edge_rel(BallV::diff(pi, s), BallV::diff(pj, s), buff, || {
        Some((Terms::diff(pi, s), Terms::diff(pj, s)))
    })
}

/// Paper A §II.D: does edge p_i→p_j cross the upward ray {(s_x, s_y + z) : z ≥ 0}?
///
/// The printed rules read "p_ix ≥ s_x and p_ix ≥ s_x" (the j was lost): an edge whose
/// ends are both at or right of s_x, or both left of it, does not cross. Otherwise the
/// ends straddle x = s_x (so p_jx ≠ p_ix) and the crossing height z ≥ 0 is
/// (p_jx − p_ix)·((s − p_i)·(p_j − p_i)⊥) ≥ 0. Decided exactly (an orientation of three
/// float points, by expansion when the ball cannot tell); `true` also when it overflows.
#[inline]
pub fn edge_crosses_ray(pi: Vect2, pj: Vect2, s: Vect2) -> bool {
    pr::crosses_ray(
        BallV::diff(pi, s),
        BallV::diff(pj, s),
        false,
        false,
        || Some(Terms::diff(pi, s)),
        || Some(Terms::diff(pj, s)),
        0.0,
    )
    .or_true()
}

/// Paper A §II.D num_cross: how many edges of P cross the upward ray from s.
/// P is assumed perturbed (no vertex on the ray), as the paper requires.
#[inline]
///
/// ```
/// use polyguard::{num_cross, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// assert_eq!(num_cross(&square[..], Vect2::new(1.0, 1.0)), 1); // inside: odd
/// assert_eq!(num_cross(&square[..], Vect2::new(1.0, -1.0)), 2); // below it: even
/// ```
pub fn num_cross<P: VertexSeq + ?Sized>(p: &P, s: Vect2) -> usize {
    let n = p.count();
    (0..n)
        .filter(|&i| edge_crosses_ray(p.vertex(i), p.vertex(p.next(i)), s))
        .count()
}

/// Paper A §II.E definitely_outside(P, s, BUFF): s is farther than BUFF from every edge
/// of P and of P*_BUFF, and the ray from s crosses P*_BUFF an even number of times.
///
/// Certified: `true` only when the exact answer is true (see [`definitely_outside_rel`]).
#[inline]
///
/// ```
/// use polyguard::{definitely_outside, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// assert!(definitely_outside(&square[..], Vect2::new(5.0, 1.0), 0.1));
/// assert!(!definitely_outside(&square[..], Vect2::new(2.05, 1.0), 0.1)); // within BUFF
/// assert!(!definitely_outside(&square[..], Vect2::new(1.0, 1.0), 0.1)); // inside
/// ```
pub fn definitely_outside<P: VertexSeq + ?Sized>(p: &P, s: Vect2, buff: f64) -> bool {
    let rel = AtTime {
        p,
        vels: p,
        s,
        v: Vect2::ZERO,
        t: crate::ball::Ball::exact(0.0),
    };
    definitely_outside_rel(&rel, buff) == Tri::Yes
}

/// Paper A §II.E definitely_outside in the point's frame, three-valued: `Yes` when s is
/// certainly definitely outside, `No` when certainly not, `Unsure` otherwise (which the
/// detectors read as "not outside", towards detection).
///
/// One pass does steps 2–4: an edge of P*_BUFF whose two ends were not perturbed is the
/// same edge of P, so its near_edge test is not repeated. An undecided perturbation
/// leaves P*_BUFF unknown, and the answer can then only be `No` or `Unsure`.
#[doc(hidden)]
pub fn definitely_outside_rel<R: RelPoly + ?Sized>(p: &R, buff: f64) -> Tri {
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    let n = p.count();
    let fixed = p.skip_margin(buff);
    // With a margin common to all vertices and the vertices stored contiguously, the
    // skip below is taken several vertices at a time ([`outside_masked`]): the same
    // comparisons, hence the same edges tested in full, in the same order.
    if let (Some(m), Some(f)) = (fixed, p.frame()) {
        if n >= lanes::MIN_VERTICES && f.verts.len() == n {
            return lanes::with_kernel(Masked { p, f, m, buff });
        }
    }
    // Each vertex is carried to the next edge; vertex 0 is computed afresh for the last
    // edge rather than kept alive across the loop: at opt-level 3 LLVM 22 (rustc 1.95,
    // 1.97-nightly) once reloaded a vertex 0 kept in a vector register across a
    // vectorised loop from a 64-bit spill slot, its y read as 0 on the last edge
    // (tests/regressions/*.jsonl).
    //
    // Every vertex certainly above BUFF (the point below the polygon's bounding box):
    // no edge of P or of P*_BUFF (perturbing moves vertices sideways only) comes within
    // BUFF, and every edge whose ends straddle the ray's line crosses it above the
    // point, so the crossings are the sign changes of x around a closed cycle: an even
    // number. The per-edge test below cannot see this (an edge above the point may
    // cross the ray), so it goes first, vertex by vertex, stopping at the first miss.
    if let Some(m) = fixed {
        if n > 0 && (0..n).all(|i| p.at(i).y >= m) {
            return Tri::Yes;
        }
    }
    let mut pass = Pass::new();
    let mut bv = if n > 0 { p.at(0) } else { Vect2::ZERO };
    for i in 0..n {
        let j = p.next(i);
        let av = bv;
        bv = p.at(j);
        // Both ends certainly beyond BUFF on the same side of the ray's line x = 0, or
        // both certainly below y = −BUFF: neither end is perturbed (§II.B), the edge
        // neither straddles the ray nor crosses it above the point (§II.D), and the
        // point is farther than BUFF from its bounding box (§II.C): nothing to count.
        // (A point outside the polygon's bounding box skips every edge this way.) With a
        // margin common to all vertices the test needs no radius; otherwise the two
        // radii give it (x̃ ≥ up(BUFF + r) > BUFF + r gives x > BUFF). Closed
        // comparisons: either margin is strict on its own.
        let skip = |m: f64| {
            (av.x >= m && bv.x >= m) || (av.x <= -m && bv.x <= -m) || (av.y <= -m && bv.y <= -m)
        };
        if let Some(m) = fixed {
            if skip(m) {
                continue;
            }
        }
        let (a, b) = (p.rel(i), p.rel(j));
        if fixed.is_none() && skip(crate::ball::up(buff + mx(a.r, b.r))) {
            continue;
        }
        if !pass.edge(p, i, j, a, b, buff) {
            return Tri::No;
        }
    }
    pass.end()
}

/// Paper A §II.E definitely_outside's pass over the edges that the skip leaves (steps
/// 2–4 on one edge at a time): what is known so far.
struct Pass {
    /// `Unsure` once a near_edge or a perturbation was undecided, else `Yes`.
    acc: Tri,
    /// The parity of the crossings counted so far.
    odd: bool,
    /// No crossing or perturbation was undecided.
    parity_known: bool,
}

impl Pass {
    /// Before the first edge.
    #[inline(always)]
    fn new() -> Pass {
        Pass {
            acc: Tri::Yes,
            odd: false,
            parity_known: true,
        }
    }

    /// Paper A §II.E steps 2–4 on edge i→j (ends a, b relative to the point): near_edge
    /// on P and, when an end is perturbed, on P*_BUFF, and the edge's crossing of the
    /// ray (§II.D). `false` when the point is certainly within BUFF of the edge (then
    /// definitely_outside is certainly false). Out of line: it runs only on the edges
    /// the skip leaves, and one copy serves the scalar and the masked loops (inlined in
    /// both, its callees were left out of line instead).
    #[inline(never)]
    fn edge<R: RelPoly + ?Sized>(
        &mut self,
        p: &R,
        i: usize,
        j: usize,
        a: BallV,
        b: BallV,
        buff: f64,
    ) -> bool {
        let (ta, tb) = (|| p.terms(i), || p.terms(j));
        match near_edge_rel(a, b, buff, || Some((ta()?, tb()?))) {
            Tri::Yes => return false,
            Tri::Unsure => self.acc = Tri::Unsure,
            Tri::No => {}
        }
        let pa = pr::perturbs(a, ta, buff);
        let pb = pr::perturbs(b, tb, buff);
        if pa == Tri::Unsure || pb == Tri::Unsure {
            self.acc = Tri::Unsure;
            self.parity_known = false;
            return true;
        }
        let (pa, pb) = (pa == Tri::Yes, pb == Tri::Yes);
        let a_star = if pa { shift_left(a, buff) } else { a };
        let b_star = if pb { shift_left(b, buff) } else { b };
        let star = |t: Option<Terms>, moved: bool| {
            if moved {
                t?.shift_x(-2.0 * buff)
            } else {
                t
            }
        };
        if pa || pb {
            let terms = || Some((star(ta(), pa)?, star(tb(), pb)?));
            match near_edge_rel(a_star, b_star, buff, terms) {
                Tri::Yes => return false,
                Tri::Unsure => self.acc = Tri::Unsure,
                Tri::No => {}
            }
        }
        match pr::crosses_ray(a_star, b_star, pa, pb, ta, tb, buff) {
            Tri::Yes => self.odd = !self.odd,
            Tri::No => {}
            Tri::Unsure => self.parity_known = false,
        }
        true
    }

    /// Paper A §II.E's answer after the last edge: `acc` and an even count.
    #[inline(always)]
    fn end(self) -> Tri {
        let even = if self.parity_known {
            Tri::from_bool(!self.odd)
        } else {
            Tri::Unsure
        };
        self.acc.and(even)
    }
}

/// [`definitely_outside_rel`] with a common margin m and a [`Frame`], for
/// [`lanes::with_kernel`].
struct Masked<'a, R: ?Sized> {
    p: &'a R,
    f: Frame<'a>,
    m: f64,
    buff: f64,
}

impl<R: RelPoly + ?Sized> KernelFn<Tri> for Masked<'_, R> {
    #[inline(always)]
    fn call<K: Kernel>(self, k: K) -> Tri {
        outside_masked(self.p, &self.f, self.m, self.buff, k)
    }
}

/// Bits 0, 2, 4, …: the x bits of a margin mask (one per vertex, or per edge).
const EVEN: u64 = 0x5555_5555_5555_5555;

/// The even bits of the first `len` vertices (1 ≤ len ≤ [`lanes::MARGIN_CHUNK`]).
#[inline(always)]
fn even_bits(len: usize) -> u64 {
    if len >= lanes::MARGIN_CHUNK {
        EVEN
    } else {
        EVEN & ((1u64 << (2 * len)) - 1)
    }
}

/// Paper A §II.E definitely_outside_rel's skip and shortcut on margin masks (see
/// [`crate::lanes`]): the "every vertex certainly above" shortcut is the AND of the
/// y ≥ m bits; edge k is skipped when the x ≥ m, the x ≤ −m or the y ≤ −m bits of both
/// its ends are set, exactly the scalar loop's test; the edges left go through
/// [`Pass::edge`] in increasing order, as in the scalar loop. Chunks of
/// [`lanes::MARGIN_CHUNK`] edges; the end of a chunk's last edge (vertex 0 after the
/// last chunk) is computed afresh, not carried.
#[inline(always)]
pub(crate) fn outside_masked<R: RelPoly + ?Sized, K: Kernel>(
    p: &R,
    f: &Frame<'_>,
    m: f64,
    buff: f64,
    k: K,
) -> Tri {
    let n = f.verts.len();
    const C: usize = lanes::MARGIN_CHUNK;
    let y_above = |bits: (u64, u64), len: usize| (bits.0 >> 1) & even_bits(len) == even_bits(len);
    let first = k.margin_bits(f, 0, n.min(C), m);
    if y_above(first, n.min(C))
        && (C..n).step_by(C).all(|lo| {
            let hi = (lo + C).min(n);
            y_above(k.margin_bits(f, lo, hi, m), hi - lo)
        })
    {
        return Tri::Yes;
    }
    let mut pass = Pass::new();
    let mut lo = 0;
    while lo < n {
        let hi = (lo + C).min(n);
        let len = hi - lo;
        let (ge, le) = if lo == 0 {
            first
        } else {
            k.margin_bits(f, lo, hi, m)
        };
        let (ge_next, le_next) = lanes::vertex_margin_bits(f.at(if hi == n { 0 } else { hi }), m);
        // The bits of each edge's far end at its near end's place.
        let ge_far = (ge >> 2) | (ge_next << (2 * (len - 1)));
        let le_far = (le >> 2) | (le_next << (2 * (len - 1)));
        let le_both = le & le_far;
        let skip = (ge & ge_far) | le_both | (le_both >> 1);
        let mut live = !skip & even_bits(len);
        while live != 0 {
            let i = lo + live.trailing_zeros() as usize / 2;
            live &= live - 1;
            let j = p.next(i);
            if !pass.edge(p, i, j, p.rel(i), p.rel(j), buff) {
                return Tri::No;
            }
        }
        lo = hi;
    }
    pass.end()
}

/// q − (2·BUFF, 0), the perturbed vertex of §II.B, as a ball.
#[inline(always)]
fn shift_left(q: BallV, buff: f64) -> BallV {
    q.sub(BallV::exact(Vect2::new(2.0 * buff, 0.0)))
}

#[cfg(test)]
mod tests;
