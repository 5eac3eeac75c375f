//! Paper A §II.B–§II.E: is the point s definitely outside the polygon P?

use super::predicates as pr;
use super::quad::quad_min_le_d;
use crate::polygon::VertexSeq;
use crate::vect2::Vect2;

/// Paper A §II.B: vertex i of P*_BUFF. A vertex with p_y ≥ s_y − BUFF and
/// |p_x − s_x| ≤ BUFF moves to p − (2·BUFF, 0); any other stays.
///
/// The OCR'd text lost both minus signs ("s_y BUFF", "p(i) (2BUFF, 0)"). Moving left by
/// 2·BUFF puts the vertex at x ≤ s_x − BUFF < s_x, off the upward ray, as §II.D needs.
#[inline(always)]
pub fn perturb(p: Vect2, s: Vect2, buff: f64) -> Vect2 {
    if pr::perturbs(p, s, buff) {
        Vect2::new(p.x - 2.0 * buff, p.y)
    } else {
        p
    }
}

/// Paper A §II.B: the perturbed polygon P*_BUFF, computed vertex by vertex on access.
#[derive(Clone, Copy, Debug)]
pub struct Perturbed<P> {
    pub poly: P,
    pub s: Vect2,
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

/// Paper A §II.C near_edge: is s closer than BUFF to some point of the segment p_i p_j?
///
/// ‖p_i + r(p_j − p_i) − s‖² = (p_j − p_i)²·r² + 2(p_i − s)·(p_j − p_i)·r + (p_i − s)²,
/// a quadratic in r handed to quad_min_le_D with D = BUFF².
#[inline]
pub fn near_edge(pi: Vect2, pj: Vect2, s: Vect2, buff: f64) -> bool {
    // Filter: s farther than BUFF from the segment's bounding box in x or y (exact
    // answer false; the paper's formulas, rounded, could only add a false alarm here).
    let twice = 2.0 * buff;
    if pr::ranges_apart(pi.x.min(pj.x), pi.x.max(pj.x), s.x, s.x, twice)
        || pr::ranges_apart(pi.y.min(pj.y), pi.y.max(pj.y), s.y, s.y, twice)
    {
        return false;
    }
    if pr::within_buff(pi, s, buff) || pr::within_buff(pj, s, buff) {
        return true;
    }
    if pr::distinct(pi, pj) {
        let e = pj - pi;
        let w = pi - s;
        return quad_min_le_d(e.sq(), 2.0 * w.dot(e), w.sq(), buff * buff);
    }
    false
}

/// Paper A §II.D: does edge p_i→p_j cross the upward ray {(s_x, s_y + z) : z ≥ 0}?
///
/// The printed rules read "p_ix ≥ s_x and p_ix ≥ s_x" (the j was lost): an edge whose
/// ends are both at or right of s_x, or both left of it, does not cross. Otherwise the
/// ends straddle x = s_x (so p_jx ≠ p_ix) and the crossing height z ≥ 0 is
/// (p_jx − p_ix)·((s − p_i)·(p_j − p_i)⊥) ≥ 0.
#[inline(always)]
pub fn edge_crosses_ray(pi: Vect2, pj: Vect2, s: Vect2) -> bool {
    let ri = pr::at_or_right_of(pi, s);
    let rj = pr::at_or_right_of(pj, s);
    ri != rj && pr::ray_crosses(pi, pj, s)
}

/// Paper A §II.D num_cross: how many edges of P cross the upward ray from s.
/// P is assumed perturbed (no vertex on the ray), as the paper requires.
#[inline]
pub fn num_cross<P: VertexSeq + ?Sized>(p: &P, s: Vect2) -> usize {
    let n = p.count();
    let mut count = 0;
    for i in 0..n {
        if edge_crosses_ray(p.vertex(i), p.vertex(p.next(i)), s) {
            count += 1;
        }
    }
    count
}

/// Paper A §II.E definitely_outside: s is farther than BUFF from every edge of P and of
/// P*_BUFF, and the ray from s crosses P*_BUFF an even number of times.
///
/// One pass does steps 2–4: an edge of P*_BUFF whose two ends were not perturbed is the
/// same edge of P, so its near_edge test is not repeated. Each edge reads and perturbs its
/// two ends afresh.
#[inline]
pub fn definitely_outside<P: VertexSeq + ?Sized>(p: &P, s: Vect2, buff: f64) -> bool {
    if beyond_bounding_box(p, s, buff) {
        return true;
    }
    let n = p.count();
    let mut crossings = 0usize;
    for i in 0..n {
        let a = p.vertex(i);
        let b = p.vertex(p.next(i));
        if near_edge(a, b, s, buff) {
            return false;
        }
        let (a_star, b_star) = (perturb(a, s, buff), perturb(b, s, buff));
        if (a_star != a || b_star != b) && near_edge(a_star, b_star, s, buff) {
            return false;
        }
        if edge_crosses_ray(a_star, b_star, s) {
            crossings += 1;
        }
    }
    crossings % 2 == 0
}

/// Filter in front of definitely_outside: every vertex is more than 2·BUFF beyond s on
/// one side, in x or in y (the exact answer is then "outside").
///
/// Then s is farther than BUFF from every edge of P; no vertex is perturbed except, when
/// s is below P, ones whose y stays above s_y + BUFF, so P*_BUFF's edges are far too; and
/// the upward ray misses P or crosses the whole closed curve, an even number of times.
/// fl(s_x − q_x) is monotone in q_x, so the test per vertex equals the bounding-box test.
///
/// Written as a loop that leaves as soon as no side is left, not as a min/max reduction
/// over the vertices followed by the edge loop: at opt-level 3 LLVM 22 (rustc 1.95,
/// 1.97-nightly) vectorised that reduction and reloaded vertex 0, kept in a vector
/// register across it, from a 64-bit spill slot, so its y read as 0 on the last edge:
/// far false alarms in release builds and missed detections in fuzzing builds
/// (tests/regressions/*.jsonl). Nothing here stays alive across the loop but s and BUFF.
#[inline]
fn beyond_bounding_box<P: VertexSeq + ?Sized>(p: &P, s: Vect2, buff: f64) -> bool {
    let twice = 2.0 * buff;
    // Bits: all left, all right, all below, all above (by more than 2·BUFF).
    let mut sides = 0b1111u8;
    for i in 0..p.count() {
        let q = p.vertex(i);
        sides &= u8::from(pr::gap_exceeds(q.x, s.x, twice))
            | u8::from(pr::gap_exceeds(s.x, q.x, twice)) << 1
            | u8::from(pr::gap_exceeds(q.y, s.y, twice)) << 2
            | u8::from(pr::gap_exceeds(s.y, q.y, twice)) << 3;
        if sides == 0 {
            return false;
        }
    }
    sides != 0 && p.count() > 0
}
