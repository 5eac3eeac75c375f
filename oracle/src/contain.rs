//! Paper A §II.B–II.E: perturbation, proximity to an edge, ray crossings and
//! "definitely outside".

use crate::field::{ExactField, V2};
use crate::quad::quad_min_le_d;

/// Paper A §II.B: the i-th vertex of P*_BUFF — moved by (−2·BUFF, 0) when
/// p_iy ≥ s_y − BUFF and |p_ix − s_x| ≤ BUFF, else unchanged.
pub fn perturb_vertex<F: ExactField>(p: &V2<F>, s: &V2<F>, buff: &F) -> V2<F> {
    let dx = p.x.minus(&s.x);
    let near_x = dx <= *buff && dx.negated() <= *buff;
    if near_x && p.y >= s.y.minus(buff) {
        V2::new(p.x.minus(&buff.plus(buff)), p.y.clone())
    } else {
        p.clone()
    }
}

/// Paper A §II.B: the perturbed polygon P*_BUFF.
pub fn perturb<F: ExactField>(poly: &[V2<F>], s: &V2<F>, buff: &F) -> Vec<V2<F>> {
    poly.iter().map(|p| perturb_vertex(p, s, buff)).collect()
}

/// Paper A §II.C: near_edge — is s at distance < BUFF from the segment p_i p_j?
pub fn near_edge<F: ExactField>(pi: &V2<F>, pj: &V2<F>, s: &V2<F>, buff: &F) -> bool {
    // Exact early "false": s at least BUFF outside the edge's bounding box in
    // one coordinate is at distance ≥ BUFF from every point of the edge.
    let outside = |a: &F, b: &F, x: &F| {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        x.plus(buff) <= *lo || *x >= hi.plus(buff)
    };
    if outside(&pi.x, &pj.x, &s.x) || outside(&pi.y, &pj.y, &s.y) {
        return false;
    }
    let b2 = buff.sq();
    // Step 1: the end points.
    if s.minus(pi).sq() < b2 || s.minus(pj).sq() < b2 {
        return true;
    }
    // Step 2: the quadratic ‖p_i + r(p_j − p_i) − s‖² on r ∈ [0, 1].
    if pi != pj {
        let e = pj.minus(pi);
        let w = pi.minus(s);
        let a = e.sq();
        let b = w.dot(&e);
        let b = b.plus(&b);
        let c = w.sq();
        if quad_min_le_d(&a, &b, &c, &b2) {
            return true;
        }
    }
    false
}

/// Paper A §II.D: does the edge p_i → p_j cross the upward ray from s?
pub fn edge_crosses_ray<F: ExactField>(pi: &V2<F>, pj: &V2<F>, s: &V2<F>) -> bool {
    let i_right = pi.x >= s.x;
    let j_right = pj.x >= s.x;
    // Both on the same side of the vertical line through s (this also covers
    // p_ix = p_jx).
    if i_right == j_right || pi.x == pj.x {
        return false;
    }
    // (p_jx − p_ix)·((s − p_i)·(p_j − p_i)^⊥) ≥ 0 with the right perpendicular.
    let dx = pj.x.minus(&pi.x);
    let c = s.minus(pi).cross(&pj.minus(pi));
    !dx.times(&c).is_neg()
}

/// Paper A §II.D: num_cross — the number of edges of P crossing the upward ray from s.
pub fn num_cross<F: ExactField>(poly: &[V2<F>], s: &V2<F>) -> usize {
    let n = poly.len();
    (0..n)
        .filter(|&i| edge_crosses_ray(&poly[i], &poly[(i + 1) % n], s))
        .count()
}

/// Paper A §II.E: definitely_outside — s is farther than BUFF from every edge of
/// P and of P*_BUFF, and the ray from s crosses P*_BUFF an even number of times.
pub fn definitely_outside<F: ExactField>(poly: &[V2<F>], s: &V2<F>, buff: &F) -> bool {
    let n = poly.len();
    let pstar = perturb(poly, s, buff);
    for i in 0..n {
        let j = (i + 1) % n;
        if near_edge(&poly[i], &poly[j], s, buff) {
            return false;
        }
    }
    for i in 0..n {
        let j = (i + 1) % n;
        // An edge that the perturbation left in place was checked just above.
        let unchanged = pstar[i] == poly[i] && pstar[j] == poly[j];
        if !unchanged && near_edge(&pstar[i], &pstar[j], s, buff) {
            return false;
        }
    }
    num_cross(&pstar, s) % 2 == 0
}
