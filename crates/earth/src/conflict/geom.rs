//! Planar helpers of Paper B Section IV (f64, Mercator plane): convex hull (eq 7),
//! convex–convex intersection (eq 9, fast path), closed-set intersection tests and the
//! Euclidean distance between polygons (stage 4's safe time steps).

use crate::sphere::Merc;

/// Paper B eq 9: twice the signed area of triangle `abc` (> 0 counter-clockwise).
#[inline]
pub fn orient(a: Merc, b: Merc, c: Merc) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Paper B eq 9: signed area of a ring (> 0 counter-clockwise).
pub fn signed_area(ring: &[Merc]) -> f64 {
    let n = ring.len();
    let mut s = 0.0;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        s += a[0] * b[1] - a[1] * b[0];
    }
    0.5 * s
}

/// Paper B eq 7: convex hull (Andrew's monotone chain), counter-clockwise, collinear
/// points dropped. Returns fewer than 3 points for degenerate input.
pub fn convex_hull(points: &[Merc]) -> Vec<Merc> {
    let mut p: Vec<Merc> = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut h: Vec<Merc> = Vec::with_capacity(2 * p.len());
    for &q in p.iter() {
        while h.len() >= 2 && orient(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
            h.pop();
        }
        h.push(q);
    }
    let lower = h.len() + 1;
    for &q in p.iter().rev().skip(1) {
        while h.len() >= lower && orient(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
            h.pop();
        }
        h.push(q);
    }
    h.pop();
    h
}

/// Paper B eq 8: is the ring convex (all turns of one sign, zero turns allowed)?
pub fn is_convex(ring: &[Merc]) -> bool {
    let n = ring.len();
    if n < 3 {
        return false;
    }
    let (mut pos, mut neg) = (false, false);
    for i in 0..n {
        let o = orient(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
        pos |= o > 0.0;
        neg |= o < 0.0;
    }
    !(pos && neg)
}

/// The ring in counter-clockwise order.
pub fn ccw(mut ring: Vec<Merc>) -> Vec<Merc> {
    if signed_area(&ring) < 0.0 {
        ring.reverse();
    }
    ring
}

/// Paper B eq 9, fast convex–convex path: Sutherland–Hodgman clipping of convex `a` by
/// convex counter-clockwise `b`. Returns the (possibly empty or degenerate) intersection.
pub fn clip_convex(a: &[Merc], b: &[Merc]) -> Vec<Merc> {
    let mut out: Vec<Merc> = a.to_vec();
    let m = b.len();
    let mut buf = Vec::with_capacity(a.len() + m);
    for i in 0..m {
        if out.is_empty() {
            break;
        }
        let (e0, e1) = (b[i], b[(i + 1) % m]);
        buf.clear();
        let n = out.len();
        for j in 0..n {
            let (p, q) = (out[j], out[(j + 1) % n]);
            let (op, oq) = (orient(e0, e1, p), orient(e0, e1, q));
            if op >= 0.0 {
                buf.push(p);
            }
            if (op > 0.0 && oq < 0.0) || (op < 0.0 && oq > 0.0) {
                let s = op / (op - oq);
                buf.push([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
            }
        }
        core::mem::swap(&mut out, &mut buf);
    }
    out
}

/// Paper B eq 9 for convex polygons (both counter-clockwise): do the closed polygons
/// meet? Separating-axis test over the edge normals: they are disjoint iff some edge of
/// one has every vertex of the other strictly outside.
pub fn convex_intersect(a: &[Merc], b: &[Merc]) -> bool {
    fn separates(p: &[Merc], q: &[Merc]) -> bool {
        let n = p.len();
        (0..n).any(|i| {
            let (e0, e1) = (p[i], p[(i + 1) % n]);
            q.iter().all(|&v| orient(e0, e1, v) < 0.0)
        })
    }
    if a.len() < 3 || b.len() < 3 {
        return rings_intersect(a, b);
    }
    !(separates(a, b) || separates(b, a))
}

/// Do the closed segments `ab` and `cd` meet?
pub fn segments_meet(a: Merc, b: Merc, c: Merc, d: Merc) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
        && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0))
    {
        return true;
    }
    let on = |p: Merc, q: Merc, r: Merc| {
        r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    (o1 == 0.0 && on(a, b, c))
        || (o2 == 0.0 && on(a, b, d))
        || (o3 == 0.0 && on(c, d, a))
        || (o4 == 0.0 && on(c, d, b))
}

/// Is `p` inside or on the (simple, any orientation) ring? Crossing number with boundary
/// points counted inside.
pub fn point_in_ring(p: Merc, ring: &[Merc]) -> bool {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if orient(a, b, p) == 0.0
            && p[0] >= a[0].min(b[0])
            && p[0] <= a[0].max(b[0])
            && p[1] >= a[1].min(b[1])
            && p[1] <= a[1].max(b[1])
        {
            return true;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Paper B eq 9 as a predicate: do the closed polygons bounded by two simple rings meet?
pub fn rings_intersect(a: &[Merc], b: &[Merc]) -> bool {
    let (n, m) = (a.len(), b.len());
    for i in 0..n {
        for j in 0..m {
            if segments_meet(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m]) {
                return true;
            }
        }
    }
    (n > 0 && point_in_ring(a[0], b)) || (m > 0 && point_in_ring(b[0], a))
}

fn point_segment_dist(p: Merc, a: Merc, b: Merc) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let s = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - s * dx).hypot(p[1] - a[1] - s * dy)
}

/// Stage 4 helper: Euclidean distance between the closed polygons bounded by two simple
/// rings (0 when they meet). For disjoint polygons the distance is attained between a
/// vertex of one and an edge of the other.
pub fn ring_distance(a: &[Merc], b: &[Merc]) -> f64 {
    if rings_intersect(a, b) {
        return 0.0;
    }
    let mut d = f64::INFINITY;
    let (n, m) = (a.len(), b.len());
    for j in 0..m {
        let (b0, b1) = (b[j], b[(j + 1) % m]);
        for &p in a {
            d = d.min(point_segment_dist(p, b0, b1));
        }
    }
    for i in 0..n {
        let (a0, a1) = (a[i], a[(i + 1) % n]);
        for &p in b {
            d = d.min(point_segment_dist(p, a0, a1));
        }
    }
    d
}

/// Stage 4 helper: `None` when the closed polygons meet, else their distance `d` and the
/// unit vector `n` from the closest point of `a` to the closest point of `b`. `convex`:
/// both rings are convex and counter-clockwise (enables the separating-axis test).
pub fn closest(a: &[Merc], b: &[Merc], convex: bool) -> Option<(f64, Merc)> {
    let meet = if convex {
        convex_intersect(a, b)
    } else {
        rings_intersect(a, b)
    };
    if meet {
        return None;
    }
    let mut best = (f64::INFINITY, [0.0, 0.0]);
    let mut consider = |p: Merc, s0: Merc, s1: Merc, flip: bool| {
        let (dx, dy) = (s1[0] - s0[0], s1[1] - s0[1]);
        let len2 = dx * dx + dy * dy;
        let s = if len2 > 0.0 {
            (((p[0] - s0[0]) * dx + (p[1] - s0[1]) * dy) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = [s0[0] + s * dx, s0[1] + s * dy];
        let v = if flip {
            [p[0] - q[0], p[1] - q[1]]
        } else {
            [q[0] - p[0], q[1] - p[1]]
        };
        let d2 = v[0] * v[0] + v[1] * v[1];
        if d2 < best.0 {
            best = (d2, v);
        }
    };
    let (n, m) = (a.len(), b.len());
    for j in 0..m {
        for &p in a {
            consider(p, b[j], b[(j + 1) % m], false);
        }
    }
    for i in 0..n {
        for &p in b {
            consider(p, a[i], a[(i + 1) % n], true);
        }
    }
    let (d2, v) = best;
    let d = d2.sqrt();
    (d > 0.0 && d.is_finite()).then(|| (d, [v[0] / d, v[1] / d]))
}

/// Axis-aligned bounding box `[xmin, ymin, xmax, ymax]` (eqs 3–6).
pub fn bbox(points: &[Merc]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        b[0] = b[0].min(p[0]);
        b[1] = b[1].min(p[1]);
        b[2] = b[2].max(p[0]);
        b[3] = b[3].max(p[1]);
    }
    b
}

/// Sutherland–Hodgman against one half-plane, x ≤ c (`west`) or x ≥ c: the part of the
/// ring on that side, crossings placed on x = c exactly (their y one interpolation from
/// exact). For a ring that crosses the line more than twice (a non-convex region) the
/// parts are joined by zero-width stretches along the line.
fn half_plane(ring: &[Merc], c: f64, west: bool) -> Vec<Merc> {
    let inside = |p: Merc| if west { p[0] <= c } else { p[0] >= c };
    let mut out = Vec::with_capacity(ring.len() + 2);
    for (j, &p) in ring.iter().enumerate() {
        let q = ring[(j + 1) % ring.len()];
        if inside(p) {
            out.push(p);
        }
        if (p[0] < c && q[0] > c) || (p[0] > c && q[0] < c) {
            let s = (c - p[0]) / (q[0] - p[0]);
            out.push([c, p[1] + s * (q[1] - p[1])]);
        }
    }
    out
}

/// The rings of a region on the Earth, each within the strip [−π, π] of longitude, as
/// RFC 7946 §3.1.9 asks of a geometry that crosses the antimeridian ("cut in two"). A
/// ring is moved by whole turns (2π) so that its least x lies in [−π, π); a part beyond
/// x = π is cut off along that line (Sutherland–Hodgman against the half-plane, the
/// crossings placed on x = π exactly) and moved a turn west. Exact
/// repeats (a pair found in two copies, within [`super::stage1::WRAP_MARGIN`] of ±π) are
/// dropped.
pub fn earth_rings(rings: Vec<Vec<Merc>>) -> Vec<Vec<Merc>> {
    use std::f64::consts::{PI, TAU};
    let mut out: Vec<Vec<Merc>> = Vec::with_capacity(rings.len());
    for ring in rings {
        let b = bbox(&ring);
        if !(b[0].is_finite() && b[2].is_finite()) {
            out.push(ring);
            continue;
        }
        let k = ((b[0] + PI) / TAU).floor();
        let dx = -TAU * k;
        let ring: Vec<Merc> = if k == 0.0 {
            ring
        } else {
            ring.iter().map(|p| [p[0] + dx, p[1]]).collect()
        };
        if b[2] + dx <= PI {
            out.push(ring);
            continue;
        }
        for (west, shift) in [(true, 0.0), (false, -TAU)] {
            let r: Vec<Merc> = half_plane(&ring, PI, west)
                .into_iter()
                .map(|p| [p[0] + shift, p[1]])
                .collect();
            if r.len() >= 3 && signed_area(&r) != 0.0 {
                out.push(r);
            }
        }
    }
    let mut kept: Vec<Vec<Merc>> = Vec::with_capacity(out.len());
    for r in out {
        if !kept.contains(&r) {
            kept.push(r);
        }
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A region across the antimeridian comes out as two rings within [−π, π] whose areas
    /// add up to the region's; one found in a copy a turn away comes out once.
    #[test]
    fn regions_on_the_earth_are_cut_at_the_antimeridian() {
        use std::f64::consts::{PI, TAU};
        let sq = |x0: f64| vec![[x0, 0.0], [x0 + 0.2, 0.0], [x0 + 0.2, 0.1], [x0, 0.1]];
        let across = sq(PI - 0.05);
        let out = earth_rings(vec![across.clone(), sq(PI - 0.05 - TAU)]);
        assert_eq!(out.len(), 2, "{out:?}");
        let total: f64 = out.iter().map(|r| signed_area(r)).sum();
        assert!(
            (total - signed_area(&across)).abs() < 1e-12 * signed_area(&across),
            "{total} {} {out:?}",
            signed_area(&across)
        );
        for r in &out {
            let b = bbox(r);
            assert!(b[0] >= -PI && b[2] <= PI, "{r:?}");
            assert!(signed_area(r) > 0.0);
        }
        // within the strip: unchanged
        let inside = sq(1.0);
        assert_eq!(earth_rings(vec![inside.clone()]), vec![inside]);
        // a turn east: moved back
        let moved = earth_rings(vec![sq(1.0 + TAU)]);
        assert!((moved[0][0][0] - 1.0).abs() < 1e-15, "{moved:?}");
    }

    #[test]
    fn hull_of_square_with_inner_point() {
        let h = convex_hull(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.], [0.5, 0.5]]);
        assert_eq!(h.len(), 4);
        assert!(signed_area(&h) > 0.0);
    }

    #[test]
    fn clip_and_distance() {
        let a = vec![[0., 0.], [2., 0.], [2., 2.], [0., 2.]];
        let b = vec![[1., 1.], [3., 1.], [3., 3.], [1., 3.]];
        let c = clip_convex(&a, &b);
        assert!((signed_area(&c) - 1.0).abs() < 1e-12);
        let far = vec![[5., 0.], [6., 0.], [6., 1.]];
        assert!((ring_distance(&a, &far) - 3.0).abs() < 1e-12);
        assert_eq!(ring_distance(&a, &b), 0.0);
        let inner = vec![[0.5, 0.5], [0.6, 0.5], [0.6, 0.6]];
        assert_eq!(ring_distance(&a, &inner), 0.0);
    }
}
