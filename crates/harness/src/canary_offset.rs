//! A canary for the offset check: a PolyCARP-style bisector expansion of paper A §II's
//! polygon (each vertex moved along a bisector of its corner until it reaches the
//! incoming edge's line shifted by D), written here from the idea of NASA PolyCARP's
//! `expand_polygon_2D`. It is not an offset: a vertex whose move is nearly parallel to
//! the incoming edge (a very sharp corner) is left where it is, and the buffer beyond it
//! is missed; a sharp corner that is moved ends far beyond D(1 + ε). The oracle's check
//! (`polyguard_oracle::offset`) must catch both.

use polyguard::Vect2;

/// The unit vector of v (v itself when it is zero).
fn hat(v: Vect2) -> Vect2 {
    let n = v.x.hypot(v.y);
    if n > 0.0 {
        v.scale(1.0 / n)
    } else {
        v
    }
}

/// The direction a vertex v (between u and w) moves along: the sum of the two edges'
/// outward normals for a turn of at most 90°, else the sum of the two edges' unit
/// vectors pointing out of the corner; PolyCARP's fixed (1, 1) when an edge is shorter
/// than `buff`. Outward is the right side for our counterclockwise polygons.
fn corner_direction(u: Vect2, v: Vect2, w: Vect2, buff: f64) -> Vect2 {
    let (a, b) = (v - u, w - v);
    if a.x.hypot(a.y) <= buff || b.x.hypot(b.y) <= buff {
        return Vect2::new(1.0, 1.0);
    }
    if a.dot(b) >= 0.0 {
        return hat(a.perp()) + hat(b.perp());
    }
    // det(b, a) = b × a ≤ 0: a left (convex) turn, the corner points away from both
    // neighbours.
    if b.x * a.y - b.y * a.x <= 0.0 {
        hat(a) + hat(v - w)
    } else {
        hat(u - v) + hat(b)
    }
}

/// The bisector expansion of P by `d`, with PolyCARP's tolerance `buff` (a move whose
/// component along the incoming edge's outward normal is at most buff/100 is dropped).
pub fn bisector_expansion(p: &[Vect2], buff: f64, d: f64) -> Vec<Vect2> {
    let n = p.len();
    (0..n)
        .map(|i| {
            let (u, v, w) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
            let dir = corner_direction(u, v, w, buff);
            let normal = hat((v - u).perp());
            let along = dir.dot(normal);
            let t = if along.abs() <= buff / 100.0 {
                0.0
            } else {
                d / along
            };
            v + dir.scale(t)
        })
        .collect()
}
