//! Paper A §II.B–II.E: perturbation, proximity to an edge, ray crossings and
//! "definitely outside".

use core::cmp::Ordering;

use crate::field::{Arith, V2};
use crate::kernel::{all_of, and, certainly, eq2, not, or, Kernel};
use crate::quad::quad_min_le_d;

/// Paper A §II.B: the perturbed vertex and whether it moved — by (−2·BUFF, 0) when
/// p_y ≥ s_y − BUFF and |p_x − s_x| ≤ BUFF.
fn perturb_moved<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &V2<N>,
    s: &V2<N>,
    buff: &N,
) -> Result<(V2<N>, bool), K::Abstain> {
    let dx = p.x.minus(&s.x);
    let near = all_of!(
        k.le(&dx, buff),
        k.le(&dx.negated(), buff),
        k.le(&s.y.minus(buff), &p.y),
    )?;
    Ok(if near {
        (V2::new(p.x.minus(&buff.twice()), p.y.clone()), true)
    } else {
        (p.clone(), false)
    })
}

/// Paper A §II.B: the vertex p of P*_BUFF — moved by (−2·BUFF, 0) when
/// p_y ≥ s_y − BUFF and |p_x − s_x| ≤ BUFF, else unchanged.
pub fn perturb<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &V2<N>,
    s: &V2<N>,
    buff: &N,
) -> Result<V2<N>, K::Abstain> {
    perturb_moved(k, p, s, buff).map(|(q, _)| q)
}

/// Paper A §II.C: near_edge — is s at distance < BUFF from the segment p_i p_j?
pub fn near_edge<N: Arith, K: Kernel<N>>(
    k: &K,
    pi: &V2<N>,
    pj: &V2<N>,
    s: &V2<N>,
    buff: &N,
) -> Result<bool, K::Abstain> {
    // Early "false": s at least BUFF outside the edge's bounding box in one
    // coordinate is at distance ≥ BUFF from every point of the edge.
    let outside = |a: &N, b: &N, x: &N| {
        let (lo, hi) = k.hull(&[a, b]);
        or(k.le(&x.plus(buff), &lo), || k.le(&hi.plus(buff), x))
    };
    if certainly(or(outside(&pi.x, &pj.x, &s.x), || {
        outside(&pi.y, &pj.y, &s.y)
    })) {
        return Ok(false);
    }
    let b2 = buff.sq();
    // Step 1: the end points.
    let ends = or(k.lt(&s.minus(pi).sq(), &b2), || {
        k.lt(&s.minus(pj).sq(), &b2)
    });
    if certainly(ends) {
        return ends;
    }
    // Step 2: the quadratic ‖p_i + r(p_j − p_i) − s‖² on r ∈ [0, 1].
    or(ends, || {
        and(not(eq2(k, pi, pj)), || {
            let e = pj.minus(pi);
            let w = pi.minus(s);
            quad_min_le_d(k, &e.sq(), &w.dot(&e).twice(), &w.sq(), &b2)
        })
    })
}

/// Paper A §II.D: does the edge p_i → p_j cross the upward ray from s?
pub fn edge_crosses_ray<N: Arith, K: Kernel<N>>(
    k: &K,
    pi: &V2<N>,
    pj: &V2<N>,
    s: &V2<N>,
) -> Result<bool, K::Abstain> {
    // Both on the same side of the vertical line through s (this also covers
    // p_ix = p_jx).
    if k.le(&s.x, &pi.x)? == k.le(&s.x, &pj.x)? {
        return Ok(false);
    }
    // (p_jx − p_ix)·((s − p_i)·(p_j − p_i)^⊥) ≥ 0 with the right perpendicular,
    // where p_jx − p_ix ≠ 0: the sign of the product is the product of the signs.
    let dx = k.sign(&pj.x.minus(&pi.x))?;
    let c = k.sign(&s.minus(pi).cross(&pj.minus(pi)))?;
    Ok(c == Ordering::Equal || c == dx)
}

/// Paper A §II.D: num_cross — the number of edges of P crossing the upward ray from s.
pub fn num_cross<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &[V2<N>],
    s: &V2<N>,
) -> Result<usize, K::Abstain> {
    let n = p.len();
    let mut count = 0;
    for i in 0..n {
        if edge_crosses_ray(k, &p[i], &p[(i + 1) % n], s)? {
            count += 1;
        }
    }
    Ok(count)
}

/// Paper A §II.E: definitely_outside — s is farther than BUFF from every edge of
/// P and of P*_BUFF, and the ray from s crosses P*_BUFF an even number of times.
pub fn definitely_outside<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &[V2<N>],
    s: &V2<N>,
    buff: &N,
) -> Result<bool, K::Abstain> {
    let n = p.len();
    let mut pstar = Vec::with_capacity(n);
    let mut moved = Vec::with_capacity(n);
    for q in p {
        let (q, m) = perturb_moved(k, q, s, buff)?;
        pstar.push(q);
        moved.push(m);
    }
    // Near an edge of P, or of P*_BUFF (an edge that the perturbation left in place
    // is an edge of P).
    let mut near = Ok(false);
    for i in 0..n {
        let j = (i + 1) % n;
        near = or(near, || near_edge(k, &p[i], &p[j], s, buff));
        if certainly(near) {
            return Ok(false);
        }
    }
    for i in 0..n {
        let j = (i + 1) % n;
        if moved[i] || moved[j] {
            near = or(near, || near_edge(k, &pstar[i], &pstar[j], s, buff));
            if certainly(near) {
                return Ok(false);
            }
        }
    }
    // An abstention on any edge leaves the answer open.
    near?;
    Ok(num_cross(k, &pstar, s)? % 2 == 0)
}
