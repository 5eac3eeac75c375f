//! Paper A §II.B–§II.E: is the point s definitely outside the polygon P?
//!
//! The certified forms work in the point's frame: [`RelPoly`] hands out each vertex
//! minus the point as a ball (and, where it can, as exact terms), so that the same code
//! serves P at time 0, P + T·V at the lookahead and P + a·V at a slab window's start,
//! and every radius is on the scale of the encounter rather than of the coordinates.

use crate::ball::{mx, BallV, Tri};
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
    let mut acc = Tri::Yes;
    let mut odd = false;
    let mut parity_known = true;
    // Each vertex is carried to the next edge; vertex 0 is computed afresh for the last
    // edge rather than kept alive across the loop: at opt-level 3 LLVM 22 (rustc 1.95,
    // 1.97-nightly) once reloaded a vertex 0 kept in a vector register across a
    // vectorised loop from a 64-bit spill slot, its y read as 0 on the last edge
    // (tests/regressions/*.jsonl).
    let fixed = p.skip_margin(buff);
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
        let (ta, tb) = (|| p.terms(i), || p.terms(j));
        match near_edge_rel(a, b, buff, || Some((ta()?, tb()?))) {
            Tri::Yes => return Tri::No,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
        let pa = pr::perturbs(a, ta, buff);
        let pb = pr::perturbs(b, tb, buff);
        if pa == Tri::Unsure || pb == Tri::Unsure {
            acc = Tri::Unsure;
            parity_known = false;
            continue;
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
                Tri::Yes => return Tri::No,
                Tri::Unsure => acc = Tri::Unsure,
                Tri::No => {}
            }
        }
        match pr::crosses_ray(a_star, b_star, pa, pb, ta, tb, buff) {
            Tri::Yes => odd = !odd,
            Tri::No => {}
            Tri::Unsure => parity_known = false,
        }
    }
    let even = if parity_known {
        Tri::from_bool(!odd)
    } else {
        Tri::Unsure
    };
    acc.and(even)
}

/// q − (2·BUFF, 0), the perturbed vertex of §II.B, as a ball.
#[inline(always)]
fn shift_left(q: BallV, buff: f64) -> BallV {
    q.sub(BallV::exact(Vect2::new(2.0 * buff, 0.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vect2 {
        Vect2::new(x, y)
    }
    const SQUARE: [Vect2; 4] = [
        Vect2::new(0.0, 0.0),
        Vect2::new(4.0, 0.0),
        Vect2::new(4.0, 4.0),
        Vect2::new(0.0, 4.0),
    ];

    /// The shortcut "every vertex certainly above BUFF" (skip_margin) must not fire for a
    /// point just below an edge within BUFF, nor for one just beside a side: in the
    /// frame at t = 0 ([`AtTime`]) and in the shifted frame ([`Shifted`]). The margin
    /// is BUFF plus the rounding bound, never less (a mutation-test survivor: a margin
    /// of 0 or −1 passed every other test).
    #[test]
    fn the_all_above_shortcut_keeps_its_margin() {
        for (s, buff) in [
            (v(2.0, -0.5), 1.0),  // 0.5 below the bottom edge, BUFF 1
            (v(2.0, -0.25), 0.5), // likewise, BUFF 0.5
            (v(-0.5, 2.0), 1.0),  // 0.5 left of the left edge
            (v(4.75, 2.0), 1.0),  // 0.75 right of the right edge
            (v(2.0, 4.5), 1.0),   // 0.5 above the top edge: every vertex below the point
        ] {
            assert!(!definitely_outside(&SQUARE[..], s, buff), "{s:?}");
            let at = AtTime {
                p: &SQUARE[..],
                vels: &SQUARE[..],
                s,
                v: Vect2::ZERO,
                t: crate::ball::Ball::exact(0.0),
            };
            assert_eq!(definitely_outside_rel(&at, buff), Tri::No, "{s:?}");
            // The same point reached by a shift: the square moving right by 1 over t = 1,
            // the point too (the relative picture is the one above).
            let shifted = Shifted::new(
                &SQUARE[..],
                s,
                v(1.0, 0.0),
                v(1.0, 0.0),
                crate::ball::Ball::exact(1.0),
            );
            assert_eq!(definitely_outside_rel(&shifted, buff), Tri::No, "{s:?}");
        }
        // Beyond BUFF below (2 below, BUFF 1): certainly outside, in both frames.
        assert!(definitely_outside(&SQUARE[..], v(2.0, -2.0), 1.0));
        let far = Shifted::new(
            &SQUARE[..],
            v(2.0, -2.0),
            v(0.5, 0.0),
            v(0.5, 0.0),
            crate::ball::Ball::exact(3.0),
        );
        assert_eq!(definitely_outside_rel(&far, 1.0), Tri::Yes);
    }

    /// The frame at a time t ≠ 0 ([`AtTime`]) is P(t) seen from s(t), the same answer as
    /// the polygon and point moved there by hand (exact dyadic motion); a frame that
    /// forgot the motion (a mutation-test survivor) answers for t = 0 instead.
    #[test]
    fn the_frame_at_a_time_is_the_moved_scene() {
        let vels = [v(1.0, 0.0), v(1.0, 0.0), v(1.5, 0.5), v(1.0, 0.5)];
        let s = v(9.0, 2.0);
        let sv = v(-1.0, 0.0);
        for (t, inside) in [(0.0, false), (2.0, false), (3.0, true), (4.0, true)] {
            let at = AtTime {
                p: &SQUARE[..],
                vels: &vels[..],
                s,
                v: sv,
                t: crate::ball::Ball::exact(t),
            };
            let moved: Vec<Vect2> = SQUARE
                .iter()
                .zip(&vels)
                .map(|(&p, &w)| p + w.scale(t))
                .collect();
            let by_hand = definitely_outside(&moved[..], s + sv.scale(t), 0.25);
            assert_eq!(by_hand, !inside, "t = {t}");
            let want = if inside { Tri::No } else { Tri::Yes };
            assert_eq!(definitely_outside_rel(&at, 0.25), want, "t = {t}");
        }
    }

    #[test]
    fn perturb_moves_only_vertices_near_the_ray() {
        let s = v(1.0, 1.0);
        // |0 − 1| ≤ 1 and 4 ≥ 1 − 1: moved to (0 − 2, 4).
        assert_eq!(perturb(v(0.0, 4.0), s, 1.0), v(-2.0, 4.0));
        // Exactly at both thresholds (|x − s_x| = BUFF, y = s_y − BUFF): moved.
        assert_eq!(perturb(v(2.0, 0.0), s, 1.0), v(0.0, 0.0));
        // Below s_y − BUFF: stays.
        assert_eq!(perturb(v(1.0, -0.5), s, 1.0), v(1.0, -0.5));
        // Farther than BUFF in x: stays.
        assert_eq!(perturb(v(2.5, 9.0), s, 1.0), v(2.5, 9.0));
    }

    #[test]
    fn near_edge_is_strict_at_exactly_buff() {
        // s = (2, 1) is exactly 1 from the edge (0,0)-(4,0): not nearer than BUFF = 1.
        assert_eq!(
            near_edge_tri(v(0.0, 0.0), v(4.0, 0.0), v(2.0, 1.0), 1.0),
            Tri::No
        );
        assert!(near_edge(v(0.0, 0.0), v(4.0, 0.0), v(2.0, 0.75), 1.0));
        // Beyond the end: distance to (4,0) from (4.5, 0.5) is √0.5 ≈ 0.707.
        assert!(near_edge(v(0.0, 0.0), v(4.0, 0.0), v(4.5, 0.5), 0.75));
        assert!(!near_edge(v(0.0, 0.0), v(4.0, 0.0), v(4.5, 0.5), 0.5));
        // Degenerate segment p_i = p_j: only the end test applies.
        assert!(!near_edge(v(1.0, 1.0), v(1.0, 1.0), v(1.0, 2.0), 1.0));
        assert!(near_edge(v(1.0, 1.0), v(1.0, 1.0), v(1.0, 1.5), 1.0));
    }

    #[test]
    fn near_edge_on_a_long_segment_keeps_its_precision() {
        // A segment 10⁶ long and a point 1e-7 + 2⁻³⁰ beside its middle, BUFF = 1e-7.
        // The paper's quadratic in f64 cancels 10¹² against 10¹² and cannot see 1e-14;
        // the certified form measures the distance to the line directly.
        let (a, b) = (v(-5e5, 0.0), v(5e5, 0.0));
        let buff = 1e-7;
        assert_eq!(near_edge_tri(a, b, v(3.0, buff - 1e-15), buff), Tri::Yes);
        assert_eq!(near_edge_tri(a, b, v(3.0, buff + 1e-15), buff), Tri::No);
    }

    #[test]
    fn ray_through_a_vertex_before_and_after_perturbation() {
        // Triangle with apex (2, 4) straight above s = (2, 1): the ray passes exactly
        // through the apex. Unperturbed: one crossing ((2,4)→(0,0)); perturbed (BUFF
        // 0.1) the apex moves to (1.8, 4) and (4,0)→(1.8,4) crosses instead: again one.
        let tri = [v(0.0, 0.0), v(4.0, 0.0), v(2.0, 4.0)];
        let s = v(2.0, 1.0);
        assert_eq!(num_cross(&tri[..], s), 1);
        let star = Perturbed {
            poly: &tri[..],
            s,
            buff: 0.1,
        };
        assert_eq!(star.vertex(2), v(1.8, 4.0));
        assert_eq!(num_cross(&star, s), 1);
        assert!(!definitely_outside(&tri[..], s, 0.1)); // inside: odd count
        assert!(definitely_outside(&tri[..], v(2.0, 5.0), 0.1));
    }

    #[test]
    fn outside_pentagon_whose_vertex_0_is_on_the_ray() {
        // tests/regressions/assure-seed7.jsonl, false_alarm_far-2861536 (an LLVM 22
        // miscompile read vertex 0 as (0.73, 0) on the last edge): s is outside.
        let p = [
            v(0.73, 0.2),
            v(-0.3, -0.5),
            v(0.04, -0.7),
            v(0.3, -0.5),
            v(0.5, -0.3),
        ];
        let s = v(0.73, 0.005);
        assert!(definitely_outside(&p[..], s, 0.01));
        assert!(!near_edge(p[4], p[0], s, 0.01));
        assert!(near_edge(p[4], v(0.73, 0.0), s, 0.01));
        assert!(!definitely_outside(&p[..], v(0.6, 0.05), 0.01));
    }

    #[test]
    fn definitely_outside_square() {
        let sq = &SQUARE[..];
        assert!(!definitely_outside(sq, v(2.0, 2.0), 0.1)); // inside
        assert!(definitely_outside(sq, v(6.0, 2.0), 0.1)); // outside
        assert!(definitely_outside(sq, v(2.0, -1.0), 0.1)); // below: ray crosses twice
        assert!(!definitely_outside(sq, v(4.05, 2.0), 0.1)); // within BUFF of the edge
        assert!(definitely_outside(sq, v(4.5, 2.0), 0.5)); // exactly BUFF away
        assert!(!definitely_outside(sq, v(4.25, 2.0), 0.5));
    }

    /// A frame that counts its ball computations ([`RelPoly::rel`]): the work that
    /// §II.E's shortcuts are there to save.
    struct Counting<'a, R> {
        inner: &'a R,
        rels: core::cell::Cell<usize>,
    }

    impl<'a, R: RelPoly> Counting<'a, R> {
        fn new(inner: &'a R) -> Self {
            Counting {
                inner,
                rels: core::cell::Cell::new(0),
            }
        }
    }

    impl<R: RelPoly> RelPoly for Counting<'_, R> {
        fn count(&self) -> usize {
            self.inner.count()
        }
        fn rel(&self, i: usize) -> BallV {
            self.rels.set(self.rels.get() + 1);
            self.inner.rel(i)
        }
        fn terms(&self, i: usize) -> Option<Terms> {
            self.inner.terms(i)
        }
        fn at(&self, i: usize) -> Vect2 {
            self.inner.at(i)
        }
        fn skip_margin(&self, buff: f64) -> Option<f64> {
            self.inner.skip_margin(buff)
        }
    }

    /// §II.E's shortcuts do their work: a point 1.5·BUFF or 10⁶ beyond a side of the
    /// polygon's bounding box, on any of the four sides, is answered `Yes` without a
    /// single ball computation, in the frame at t = 0 and in the shifted frame. 1.5·BUFF
    /// lies between the margins BUFF·(1 + 4u) (or BUFF + the shift's slack) and BUFF + 1
    /// or 5·BUFF, so a margin off by a term or a factor shows; a frame whose `at` or
    /// `skip_margin` stopped answering shows too. (Mutation-test survivors: each of these
    /// left every answer unchanged, only slower.)
    #[test]
    fn the_shortcuts_skip_what_is_far() {
        for d in [1.5, 1e6] {
            for (s, side) in [
                (v(-d, 2.0), "left: every edge skipped"),
                (v(4.0 + d, 2.0), "right: every edge skipped"),
                (v(2.0, 4.0 + d), "above: every edge skipped"),
                (v(2.0, -d), "below: the all-above shortcut"),
            ] {
                let at = AtTime {
                    p: &SQUARE[..],
                    vels: &SQUARE[..],
                    s,
                    v: Vect2::ZERO,
                    t: crate::ball::Ball::exact(0.0),
                };
                let counted = Counting::new(&at);
                assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::Yes, "{side}");
                assert_eq!(counted.rels.get(), 0, "t = 0, {side}, d = {d}");
                // The square and the point both moving right by 1 over t = 1.
                let shifted = Shifted::new(
                    &SQUARE[..],
                    s,
                    v(1.0, 0.0),
                    v(1.0, 0.0),
                    crate::ball::Ball::exact(1.0),
                );
                let counted = Counting::new(&shifted);
                assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::Yes, "{side}");
                assert_eq!(counted.rels.get(), 0, "shifted, {side}, d = {d}");
            }
        }
        // Within BUFF the edges are computed: the shortcut is not a blanket.
        let at = AtTime {
            p: &SQUARE[..],
            vels: &SQUARE[..],
            s: v(-0.5, 2.0),
            v: Vect2::ZERO,
            t: crate::ball::Ball::exact(0.0),
        };
        let counted = Counting::new(&at);
        assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::No);
        assert!(counted.rels.get() > 0);
    }

    /// At a time t ≠ 0 the vertex's computed position carries the rounding of t·(v_i − v),
    /// up to half an ulp of the product: no margin of the t = 0 kind holds, and the
    /// per-edge skip must widen BUFF by the balls' radii. Crafted: x = 2⁵³ + 2 +
    /// t·W with W = −(2⁵³ − 1), t = 1 + 2⁻⁵², so exactly x = 1 + 2⁻⁵², while fl(t·W) = −2⁵³
    /// and the computed x is 2. With BUFF 1.5 the square's left side is within BUFF of the
    /// point (exactly), yet computed beyond 1.5·(1 + 4u). (Mutation-test survivors: a
    /// t = 0 margin for every exact time, and BUFF − radius for BUFF + radius.)
    #[test]
    fn a_moved_frame_keeps_its_rounding_in_the_skip() {
        let left = 9_007_199_254_740_994.0; // 2⁵³ + 2
        let (side, half) = (1_048_576.0, 524_288.0); // 2²⁰, 2¹⁹
        let p = [
            v(left, -half),
            v(left + side, -half),
            v(left + side, half),
            v(left, half),
        ];
        let w = v(-9_007_199_254_740_991.0, 0.0); // −(2⁵³ − 1)
        let vels = [w; 4];
        let t = 1.0 + f64::EPSILON;
        assert_eq!(
            w.x * t,
            -9_007_199_254_740_992.0,
            "the product rounds as designed"
        );
        let at = AtTime {
            p: &p[..],
            vels: &vels[..],
            s: Vect2::ZERO,
            v: Vect2::ZERO,
            t: crate::ball::Ball::exact(t),
        };
        assert_eq!(at.at(0).x, 2.0, "the computed left side");
        assert_ne!(definitely_outside_rel(&at, 1.5), Tri::Yes);
    }

    /// §II.C's filter decides what the ball tests cannot: two balls of radius 4 with their
    /// centres BUFF + 4 beyond BUFF's box on one side, or exactly at the filter's bound (a
    /// tie: every point of the segment is then at distance ≥ BUFF, and near_edge is
    /// strict), are `No` on each of the four sides, while the end and interior tests on
    /// the same balls are `Unsure`. (Mutation-test survivors: a filter weakened to `==`,
    /// `&&` or a strict comparison changed no answer the other tests saw.)
    #[test]
    fn the_near_edge_filter_decides_far_balls() {
        let (buff, r) = (1.0, 4.0);
        let bound = crate::ball::up(buff + r);
        for x in [bound, 10.0] {
            for (a, b) in [
                (v(x, -3.0), v(x, 1e3)),   // both right of the point
                (v(-x, -3.0), v(-x, 1e3)), // left
                (v(-3.0, x), v(1e3, x)),   // above
                (v(-3.0, -x), v(1e3, -x)), // below
            ] {
                let (a, b) = (BallV { v: a, r }, BallV { v: b, r });
                assert_eq!(near_edge_rel(a, b, buff, || None), Tri::No, "{a:?} {b:?}");
                let ends = pr::closer_than(a, buff, || None).or(pr::closer_than(b, buff, || None));
                let unfiltered = ends.or(pr::interior_closer_than(a, b, buff, || None));
                assert_eq!(unfiltered, Tri::Unsure, "the filter is what decides {a:?}");
            }
        }
        // One end on the near side of the bound: the filter does not fire.
        let (a, b) = (
            BallV {
                v: v(bound, -3.0),
                r,
            },
            BallV {
                v: v(bound * (1.0 - f64::EPSILON), 1e3),
                r,
            },
        );
        assert_eq!(near_edge_rel(a, b, buff, || None), Tri::Unsure);
    }

    /// The margins are closed: vertices exactly at the margin M (computed as the frame
    /// computes it) are skipped, in the all-above shortcut and in the per-edge skip, with
    /// no ball computed; M is strict on its own (see [`RelPoly::skip_margin`]).
    #[test]
    fn the_shortcut_margins_are_closed() {
        let buff = 1.0;
        let zero = crate::ball::Ball::exact(0.0);
        let probe = AtTime {
            p: &SQUARE[..],
            vels: &SQUARE[..],
            s: Vect2::ZERO,
            v: Vect2::ZERO,
            t: zero,
        };
        let m = probe.skip_margin(buff).expect("t = 0 has a margin");
        assert!(m > buff);
        // A square [m, m + 4] × [−2, 2] right of the point, and one [−2, 2] × [m, m + 4]
        // above the point (every vertex above: the all-above shortcut).
        let right: Vec<Vect2> = SQUARE.iter().map(|q| v(q.x + m, q.y - 2.0)).collect();
        let above: Vec<Vect2> = SQUARE.iter().map(|q| v(q.x - 2.0, q.y + m)).collect();
        for (poly, what) in [(&right, "per-edge skip"), (&above, "all-above shortcut")] {
            let at = AtTime {
                p: &poly[..],
                vels: &poly[..],
                s: Vect2::ZERO,
                v: Vect2::ZERO,
                t: zero,
            };
            let q = at.at(0); // (m, −2) or (−2, m): the tie is exact
            assert!(q.x == m || q.y == m, "{q:?}");
            let counted = Counting::new(&at);
            assert_eq!(definitely_outside_rel(&counted, buff), Tri::Yes, "{what}");
            assert_eq!(
                counted.rels.get(),
                0,
                "{what}: a vertex exactly at M is skipped"
            );
        }
    }

    /// An empty vertex list: definitely outside, with no vertex read (the shortcuts must
    /// not look at a vertex 0 that is not there).
    #[test]
    fn an_empty_polygon_is_outside_and_reads_no_vertex() {
        let none: [Vect2; 0] = [];
        assert!(definitely_outside(&none[..], v(1.0, 2.0), 1.0));
    }

    /// A time known only as a ball around 0 (a slab window's start that underflowed to 0,
    /// with its error radius r) still carries the motion: every position at a time in
    /// [−r, r] is in the vertex's ball. Crafted with exact dyadics: velocity 2⁹⁰⁰, r =
    /// 2⁻⁹⁰⁰, so the vertex (1, 1) can be anywhere in x ∈ [0, 2]. (A mutation-test
    /// survivor returned the t = 0 position for such a ball.)
    #[test]
    fn a_time_ball_around_zero_carries_the_motion() {
        let big = 2f64.powi(900);
        let p = [v(1.0, 1.0), v(3.0, 1.0), v(3.0, 3.0)];
        let vels = [v(big, 0.0); 3];
        let t = crate::ball::Ball {
            z: 0.0,
            r: 1.0 / big,
        };
        let at = AtTime {
            p: &p[..],
            vels: &vels[..],
            s: Vect2::ZERO,
            v: Vect2::ZERO,
            t,
        };
        for (i, q) in p.iter().enumerate() {
            let b = at.rel(i);
            for x in [q.x - 1.0, q.x + 1.0] {
                // the position at t = ∓r, exactly
                assert!((b.v.x - x).abs() <= b.r, "vertex {i}: {b:?} misses x = {x}");
            }
        }
        // Such a frame has no exact terms (its time is not a float), so it cannot claim
        // "definitely outside" from the t = 0 picture: the triangle 3 beyond the point at
        // t = 0 (BUFF 1) sweeps x by ±4 within the ball and covers the point at t = −r.
        let far = [v(3.0, -1.0), v(5.0, -1.0), v(5.0, 1.0)];
        let vels = [v(4.0 * big, 0.0); 3];
        let at = AtTime {
            p: &far[..],
            vels: &vels[..],
            s: Vect2::ZERO,
            v: Vect2::ZERO,
            t,
        };
        assert!(at.terms(0).is_none());
        assert_ne!(definitely_outside_rel(&at, 1.0), Tri::Yes);
    }

    /// §II.B–C: a perturbed vertex keeps its exact terms. The triangle (0, −20),
    /// (4, −2), (0, −5) seen from the point, BUFF 4:
    /// - (4, −2) lies in the perturbation strip (|4| ≤ 4, −2 ≥ −4) and moves to (−4, −2);
    /// - the perturbed edge to (0, −5) is then exactly BUFF from the point
    ///   (|(−4, −2) × (4, −3)| / 5 = 4, its foot inside the edge), as is the unperturbed
    ///   edge from (4, −2);
    /// - every other edge is farther, and the triangle stays below the point, so the
    ///   ray crosses nothing.
    ///
    /// The balls cannot tell the ties; exactly, near_edge is strict, so the point is
    /// definitely outside. Terms shifted by −2/BUFF instead of −2·BUFF put the vertex at
    /// (3.5, −2), whose edge passes within BUFF. That shift is the same when BUFF = 1,
    /// so it survived mutation testing.
    #[test]
    fn a_perturbed_vertex_keeps_its_exact_terms() {
        let s = v(0.5, 0.25);
        let tri: Vec<Vect2> = [v(0.0, -20.0), v(4.0, -2.0), v(0.0, -5.0)]
            .iter()
            .map(|&q| q + s)
            .collect();
        assert!(definitely_outside(&tri[..], s, 4.0));
    }

    /// A perturbed vertex moves by exactly 2·BUFF, in its ball and in its exact terms.
    /// With BUFF = 3/4, (0.75, −0.5) moves to (−0.75, −0.5), and its perturbed edge to
    /// (2.25, −1.75) touches the circle of radius BUFF (the foot of the perpendicular
    /// inside the edge): exactly BUFF from the point, a tie that only the exact terms
    /// decide, so the point is still definitely outside (the other edges stay farther).
    /// Terms moved by −2 + BUFF instead (a mutation-test survivor, the same as −2·BUFF
    /// at BUFF = 2, as −2/BUFF is at BUFF = 1) put the vertex at (−0.5, −0.5), and that
    /// edge's interior within BUFF.
    #[test]
    fn a_perturbed_vertex_moves_by_two_buff() {
        let s = v(0.5, 0.25);
        let tri: Vec<Vect2> = [v(3.0, -6.0), v(2.25, -1.75), v(0.75, -0.5)]
            .iter()
            .map(|&q| q + s)
            .collect();
        assert!(definitely_outside(&tri[..], s, 0.75));
        // At t = 3, polygon and point moving alike: the same scene, with the frame's
        // vertices as balls (p + 3·v − s − 3·v carries a rounding bound).
        let vels = [v(1.0, 0.0); 3];
        let at = AtTime {
            p: &tri[..],
            vels: &vels[..],
            s,
            v: v(1.0, 0.0),
            t: crate::ball::Ball::exact(3.0),
        };
        assert!(at.rel(2).r > 0.0, "a ball, not an exact vertex");
        assert_eq!(definitely_outside_rel(&at, 0.75), Tri::Yes);
    }

    #[test]
    fn a_perturbed_edge_within_an_ulp_of_buff_is_decided_on_the_moved_vertex() {
        // BUFF = 1/2 and the point at the origin. a = (1/4, y0) with y0 = −(1/2 − 2⁻⁵⁴)
        // is moved by §II.B (|a_x| ≤ BUFF, a_y ≥ −BUFF) to a* = (−3/4, y0); the edge
        // a* b, along y = y0, passes 1/2 − 2⁻⁵⁴ < BUFF below the point, so s is not
        // definitely outside. The unmoved edge a b keeps its distance ‖a‖ > 0.55. The gap
        // 2⁻⁵⁴ is below the balls' resolution: only the exact terms of a*, with their
        // −2·BUFF term, see it.
        let y0 = -(0.5 - 2f64.powi(-54));
        let tri = [v(0.25, y0), v(2.0, y0), v(1.0, -3.0)];
        assert!(!definitely_outside(&tri[..], v(0.0, 0.0), 0.5));
        // One ulp of y0 further down the edge is exactly BUFF away: not closer, and the
        // point is outside (the ray from it meets no edge).
        assert!(definitely_outside(
            &[v(0.25, -0.5), v(2.0, -0.5), v(1.0, -3.0)][..],
            v(0.0, 0.0),
            0.5
        ));
    }

    /// A frame of given balls and no exact terms: what a frame at an inexact time looks
    /// like to §II.E.
    struct Balls(Vec<BallV>);

    impl RelPoly for Balls {
        fn count(&self) -> usize {
            self.0.len()
        }
        fn rel(&self, i: usize) -> BallV {
            self.0[i]
        }
        fn terms(&self, _: usize) -> Option<Terms> {
            None
        }
        fn at(&self, i: usize) -> Vect2 {
            self.0[i].v
        }
        fn skip_margin(&self, _: f64) -> Option<f64> {
            None
        }
    }

    /// §II.B–E: an undecided perturbation leaves P*_BUFF unknown, so the answer cannot be
    /// "definitely outside". The triangle (0.9, −1 ± 0.01), (5, 3), (3, −6) seen from the
    /// point, BUFF 1:
    /// - every edge of P is certainly farther than BUFF (1.34, 4.2, 1.35);
    /// - vertex 0 is perturbed exactly when its y ≥ −1, which the ball cannot tell, and
    ///   its perturbed edge to (5, 3) passes 0.23 from the point.
    ///
    /// So for some exact inputs in the balls the point is not definitely outside: `No` or
    /// `Unsure`, never `Yes`. Reading "one end undecided" as "not perturbed" (a
    /// mutation-test survivor: `||` → `&&`) answered `Yes`.
    #[test]
    fn an_undecided_perturbation_is_not_outside() {
        let tri = Balls(vec![
            BallV {
                v: v(0.9, -1.0),
                r: 0.01,
            },
            BallV::exact(v(5.0, 3.0)),
            BallV::exact(v(3.0, -6.0)),
        ]);
        assert_eq!(pr::perturbs(tri.rel(0), || None, 1.0), Tri::Unsure);
        assert_ne!(definitely_outside_rel(&tri, 1.0), Tri::Yes);
    }
}
