//! NASA PolyCARP's recovery points, ported as a comparison baseline (not as a reference:
//! nothing here is certified).
//!
//! PolyCARP (`PolycarpResolution`) answers "where should the aircraft go to be clear" for
//! a point s and a polygon P with two distances: BUFF, a small numerical buffer of its
//! containment tests, and ResolBUFF, the resolution distance (our D). Its recovery point:
//! 1. s itself when it already passes the side test (definitely outside, resp. inside,
//!    with the BUFF of §II.B–D) and is near no edge within ResolBUFF;
//! 2. else the *test point*: the point of the nearest edge closest to s, moved along that
//!    edge's right normal (outward for a counterclockwise P) by ±(ResolBUFF + BUFF/2),
//!    when it passes the same tests;
//! 3. else a point built at the nearer end of that edge: the vertex moved along the
//!    direction `proj_vect` of its two edges, scaled to reach ResolBUFF off the incoming
//!    edge's line (or along the normalised direction by ResolBUFF at a turn of the wrong
//!    hand), when it passes the side test alone;
//! 4. else s.
//!
//! PolyCARP's polygons run counterclockwise too (its `PerpR` normal of an edge points out
//! of a counterclockwise ring), so the port keeps its signs. Its `definitely_outside` is
//! paper A's, which the engine has; its `definitely_inside` (with the polygon "fixed"
//! about s) is replaced here by the plain crossing parity with no edge within BUFF, the
//! same test on the simple polygons this harness draws.

use polyguard::contain::{definitely_outside, near_edge, num_cross};
use polyguard::Vect2;

/// x/|x| (PolyCARP's `Hat`; the zero vector stays zero).
fn hat(x: Vect2) -> Vect2 {
    let n = x.sq().sqrt();
    if n > 0.0 {
        x.scale(1.0 / n)
    } else {
        x
    }
}

/// a × b = a_x·b_y − a_y·b_x (PolyCARP's `det`).
fn det(a: Vect2, b: Vect2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The direction along which PolyCARP moves vertex v between u (before) and w (after):
/// the sum of the two edges' unit right normals at a convex-or-straight turn, else the
/// sum of the unit edge directions pointing away from v on the turn's outer side.
pub fn proj_vect(u: Vect2, v: Vect2, w: Vect2, buff: f64) -> Vect2 {
    let (a, b) = (v - u, w - v);
    if a.sq().sqrt() <= buff || b.sq().sqrt() <= buff {
        return Vect2::new(1.0, 1.0);
    }
    if a.dot(b) >= 0.0 {
        return hat(a.perp()) + hat(b.perp());
    }
    if det(b, a) <= 0.0 {
        return hat(a) + hat(-b);
    }
    hat(-a) + hat(b)
}

/// The point of segment a b closest to s (PolyCARP's, with its BUFF short-edge rule).
pub fn closest_point(a: Vect2, b: Vect2, s: Vect2, buff: f64) -> Vect2 {
    let e = b - a;
    if e.sq().sqrt() <= buff || (s - a).dot(e) <= 0.0 {
        return a;
    }
    if (s - b).dot(a - b) <= 0.0 {
        return b;
    }
    let dir = hat(e);
    s + dir.perp().scale(det(a - s, dir))
}

/// The index of the edge nearest to s (the first of the nearest, by float distances).
pub fn closest_edge(p: &[Vect2], buff: f64, s: Vect2) -> usize {
    let n = p.len();
    let dist = |i: usize| {
        (s - closest_point(p[i], p[(i + 1) % n], s, buff))
            .sq()
            .sqrt()
    };
    let mut best = 0;
    for i in 0..n {
        if dist(i) < dist(best) {
            best = i;
        }
    }
    best
}

/// Some edge of P is within `buff` of s (paper A's near_edge).
fn near_any_edge(p: &[Vect2], s: Vect2, buff: f64) -> bool {
    (0..p.len()).any(|i| near_edge(p[i], p[(i + 1) % p.len()], s, buff))
}

/// Inside by crossing parity, with no edge within BUFF (see the module doc).
fn definitely_inside(p: &[Vect2], s: Vect2, buff: f64) -> bool {
    num_cross(p, s) % 2 == 1 && !near_any_edge(p, s, buff)
}

/// PolyCARP's recovery point: `side` = 1 out of P, −1 into P (the module doc's steps).
pub fn recovery_point(buff: f64, resol_buff: f64, p: &[Vect2], s: Vect2, side: i32) -> Vect2 {
    let n = p.len();
    let sg = f64::from(side);
    let passes = |x: Vect2| {
        if side == 1 {
            definitely_outside(p, x, buff)
        } else {
            definitely_inside(p, x, buff)
        }
    };
    if passes(s) && !near_any_edge(p, s, resol_buff) {
        return s;
    }
    let i = closest_edge(p, buff, s);
    let ni = (i + 1) % n;
    let foot = closest_point(p[i], p[ni], s, buff);
    let test = foot + hat((p[ni] - p[i]).perp()).scale(sg * (resol_buff + buff / 2.0));
    if passes(test) && !near_any_edge(p, test, resol_buff) {
        return test;
    }
    // The nearer end of the edge, and its neighbours.
    let k = if (s - p[i]).sq() <= (s - p[ni]).sq() {
        i
    } else {
        ni
    };
    let (prev, next) = ((k + n - 1) % n, (k + 1) % n);
    let (v1, v2) = (p[k] - p[prev], p[next] - p[k]);
    let left_turn = det(v2, v1) <= 0.0;
    let pv = proj_vect(p[prev], p[k], p[next], buff);
    let r = hat(v1.perp());
    let q = p[k] + r.scale(sg * resol_buff);
    let along = pv.dot(r);
    let tt = if along.abs() <= buff / 100.0 {
        0.0
    } else {
        (q - p[i]).dot(r) / along
    };
    let mut ans = p[k] + pv.scale(tt);
    if (side == 1 && left_turn) || (side == -1 && !left_turn) {
        ans = p[k] + hat(pv).scale(sg * resol_buff);
    }
    if passes(ans) {
        return ans;
    }
    s
}

/// PolyCARP's `outside_recovery_point`.
pub fn outside_recovery_point(buff: f64, resol_buff: f64, p: &[Vect2], s: Vect2) -> Vect2 {
    recovery_point(buff, resol_buff, p, s, 1)
}

/// PolyCARP's `inside_recovery_point`.
pub fn inside_recovery_point(buff: f64, resol_buff: f64, p: &[Vect2], s: Vect2) -> Vect2 {
    recovery_point(buff, resol_buff, p, s, -1)
}
