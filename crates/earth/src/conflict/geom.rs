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

/// The exact sign of [`orient`] (Shewchuk's adaptive predicate: exact on f64 inputs).
fn orient_exact(a: Merc, b: Merc, c: Merc) -> f64 {
    let k = |p: Merc| robust::Coord { x: p[0], y: p[1] };
    robust::orient2d(k(a), k(b), k(c))
}

/// Paper B eq 9 for a simple counter-clockwise `subject` without holes and a convex
/// counter-clockwise `clipper`: [`clip_convex`]'s ring when it is the boundary of
/// `subject ∩ clipper`, `None` when that is not shown (then the caller takes the general
/// boolean operations).
///
/// Why the ring is the boundary when `Some`: clipping a closed curve by a half-plane `H`
/// replaces each excursion outside `H` by a chord on `H`'s line; an excursion and its
/// chord form a closed curve in the closed complement of `H`, which winds 0 times around
/// any point inside `H`, and the clipped curve lies in `H`. So the clip winds once around
/// the points of `subject ∩ clipper` and 0 times around the others (off the curve), and
/// the curve is that set's boundary except where it runs along a part of the clipper's
/// boundary twice, in opposite directions (the zero-width bridges of an intersection of
/// several pieces, or a spike). Only chords lie on the clipper's lines: every subject
/// vertex is off every clipper line (exact orientation, else `None`), so no subject edge
/// lies on one. Each point of the clip is tagged with the clipper lines it was made on
/// (a point cut from an edge also keeps the lines both ends share); two edges on one line
/// whose spans along it overlap are a bridge (`None`). Last the ring must be simple and
/// counter-clockwise ([`simple_ccw`], exact), which also rejects pieces that touch at a
/// point. The float classification `orient ≥ 0` may differ from the exact sign only for
/// points within rounding of a line; a point whose float orientation is 0 is tagged with
/// the line, so a chord that starts at it is seen as one.
pub fn clip_convex_exact(subject: &[Merc], clipper: &[Merc]) -> Option<Vec<Merc>> {
    let m = clipper.len();
    if !(3..=64).contains(&m) || subject.len() < 3 {
        return None;
    }
    for i in 0..m {
        let (e0, e1) = (clipper[i], clipper[(i + 1) % m]);
        // strictly convex: two collinear edges would be one line with two tags
        if orient_exact(e0, e1, clipper[(i + 2) % m]) <= 0.0 {
            return None;
        }
        if subject.iter().any(|&v| orient_exact(e0, e1, v) == 0.0) {
            return None;
        }
    }
    // the same arithmetic as clip_convex, each point with its lines (bit i: line i)
    let mut out: Vec<(Merc, u64)> = subject.iter().map(|&p| (p, 0)).collect();
    let mut buf: Vec<(Merc, u64)> = Vec::with_capacity(subject.len() + m);
    for i in 0..m {
        if out.is_empty() {
            break;
        }
        let (e0, e1) = (clipper[i], clipper[(i + 1) % m]);
        let bit = 1u64 << i;
        buf.clear();
        let n = out.len();
        for j in 0..n {
            let ((p, tp), (q, tq)) = (out[j], out[(j + 1) % n]);
            let (op, oq) = (orient(e0, e1, p), orient(e0, e1, q));
            if op >= 0.0 {
                buf.push((p, if op == 0.0 { tp | bit } else { tp }));
            }
            if (op > 0.0 && oq < 0.0) || (op < 0.0 && oq > 0.0) {
                let s = op / (op - oq);
                let x = [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
                buf.push((x, (tp & tq) | bit));
            }
        }
        core::mem::swap(&mut out, &mut buf);
    }
    let n = out.len();
    for i in 0..m {
        let bit = 1u64 << i;
        let (e0, e1) = (clipper[i], clipper[(i + 1) % m]);
        let d = [e1[0] - e0[0], e1[1] - e0[1]];
        let t = |p: Merc| (p[0] - e0[0]) * d[0] + (p[1] - e0[1]) * d[1];
        let spans: Vec<(f64, f64)> = (0..n)
            .filter(|&j| out[j].1 & out[(j + 1) % n].1 & bit != 0)
            .map(|j| {
                let (a, b) = (t(out[j].0), t(out[(j + 1) % n].0));
                (a.min(b), a.max(b))
            })
            .collect();
        for (k, x) in spans.iter().enumerate() {
            if spans[k + 1..].iter().any(|y| x.0.max(y.0) < x.1.min(y.1)) {
                return None;
            }
        }
    }
    let ring: Vec<Merc> = out.into_iter().map(|(p, _)| p).collect();
    simple_ccw(&ring).then_some(ring)
}

/// Paper B eq 9 for two simple counter-clockwise rings without holes, `a` and `b`:
/// `a ∩ b` as [`clip_convex_exact`]'s clip of `a` by the convex hull of `b`, when `a`
/// meets none of `b`'s pockets; `None` when that is not shown.
///
/// Why: the hull `H` of a simple polygon `b` is `b` together with its pockets (each
/// bounded by a hull edge, its lid, and the stretch of `b` between the lid's ends), so
/// `a ∩ H = (a ∩ b) ∪ (a ∩ pockets) = a ∩ b` when `a` meets no pocket. Every decision is
/// exact: `H` is taken from `b`'s vertices and must be strictly convex, hold every vertex
/// of `b` and meet `b`'s ring in its vertices in `b`'s order; a pocket's stretch must lie
/// strictly inside its lid; `a` and a pocket are disjoint closed sets when no edge of one
/// meets an edge of the other (`polyguard::ring::segments_meet`, exact) and neither has a
/// vertex inside the other (winding number by exact orientations).
pub fn clip_by_hull_exact(a: &[Merc], b: &[Merc]) -> Option<Vec<Merc>> {
    let n = b.len();
    let hull = convex_hull(b);
    let h = hull.len();
    if h < 3 || n < 3 {
        return None;
    }
    // the hull's vertices in b, in b's order from the first
    let idx: Vec<usize> = hull
        .iter()
        .map(|v| b.iter().position(|w| w == v))
        .collect::<Option<Vec<usize>>>()?;
    let k0 = idx.iter().enumerate().min_by_key(|&(_, &i)| i)?.0;
    let order: Vec<usize> = (0..h).map(|k| idx[(k0 + k) % h]).collect();
    if order.windows(2).any(|w| w[0] >= w[1]) {
        return None;
    }
    for k in 0..h {
        let (e0, e1) = (hull[k], hull[(k + 1) % h]);
        if b.iter().any(|&v| orient_exact(e0, e1, v) < 0.0) {
            return None;
        }
    }
    let v2 = |p: Merc| polyguard::Vect2::new(p[0], p[1]);
    let disjoint = |p: &[Merc], q: &[Merc]| -> bool {
        let (np, nq) = (p.len(), q.len());
        for i in 0..np {
            for j in 0..nq {
                let m = polyguard::ring::segments_meet(
                    v2(p[i]),
                    v2(p[(i + 1) % np]),
                    v2(q[j]),
                    v2(q[(j + 1) % nq]),
                );
                if m != Some(false) {
                    return false;
                }
            }
        }
        // boundaries apart: each lies inside the other or outside it as a whole
        crate::moving::prepared::winding(q, p[0]) == 0
            && crate::moving::prepared::winding(p, q[0]) == 0
    };
    for k in 0..h {
        let (i, j) = (order[k], order[(k + 1) % h]);
        let end = if j > i { j } else { j + n };
        if end - i < 2 {
            continue; // the lid is an edge of b: no pocket
        }
        // the pocket: b's stretch from i to j, closed by the lid from j back to i
        let pocket: Vec<Merc> = (i..=end).map(|t| b[t % n]).collect();
        let (l0, l1) = (b[i], b[end % n]);
        if pocket[1..pocket.len() - 1]
            .iter()
            .any(|&v| orient_exact(l0, l1, v) <= 0.0)
        {
            return None;
        }
        if !disjoint(a, &pocket) {
            return None;
        }
    }
    clip_convex_exact(a, &hull)
}

/// Is the ring simple (no two edges meet but neighbours at their common vertex; repeated
/// consecutive vertices count once) and counter-clockwise? Decided exactly by the
/// engine's ring check (`polyguard::ring::check`: Shewchuk's filtered orientation with
/// an exact fallback), so no rounding bound enters; a ring too extreme to check exactly
/// counts as not simple.
pub fn simple_ccw(ring: &[Merc]) -> bool {
    let v: Vec<polyguard::Vect2> = ring
        .iter()
        .map(|p| polyguard::Vect2::new(p[0], p[1]))
        .collect();
    polyguard::ring::simple_ccw(&v)
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

/// Do the two rings (as closed curves) share a point? Pairs of edges whose bounding boxes
/// are disjoint are skipped: closed segments meet only where their boxes do, and the
/// boxes compare input coordinates, without rounding.
pub fn boundaries_meet(a: &[Merc], b: &[Merc]) -> bool {
    let (n, m) = (a.len(), b.len());
    let boxes: Vec<[f64; 4]> = (0..m)
        .map(|j| {
            let (p, q) = (b[j], b[(j + 1) % m]);
            [
                p[0].min(q[0]),
                p[1].min(q[1]),
                p[0].max(q[0]),
                p[1].max(q[1]),
            ]
        })
        .collect();
    (0..n).any(|i| {
        let (p, q) = (a[i], a[(i + 1) % n]);
        let ba = [
            p[0].min(q[0]),
            p[1].min(q[1]),
            p[0].max(q[0]),
            p[1].max(q[1]),
        ];
        (0..m).any(|j| {
            let bb = &boxes[j];
            ba[0] <= bb[2]
                && bb[0] <= ba[2]
                && ba[1] <= bb[3]
                && bb[1] <= ba[3]
                && segments_meet(p, q, b[j], b[(j + 1) % m])
        })
    })
}

/// Paper B eq 9 as a predicate: do the closed polygons bounded by two simple rings meet?
pub fn rings_intersect(a: &[Merc], b: &[Merc]) -> bool {
    let (n, m) = (a.len(), b.len());
    boundaries_meet(a, b) || (n > 0 && point_in_ring(a[0], b)) || (m > 0 && point_in_ring(b[0], a))
}

/// Is the closed polygon bounded by ring `c` inside the open hole `h`: no common point,
/// and a point of `c` inside `h` (a connected set that does not meet `h`'s boundary lies
/// on one side of it)?
pub fn inside_hole(c: &[Merc], h: &[Merc]) -> bool {
    !c.is_empty() && !boundaries_meet(c, h) && point_in_ring(c[0], h)
}

/// Paper B eq 9 with holes: do the closed areas `a` minus the open holes `ha` and `b`
/// minus `hb` meet? Each area is connected, so it misses the other exactly when it lies
/// outside the other's exterior ring or inside one of its open holes: they meet when the
/// exterior rings do and neither exterior ring lies inside a hole of the other.
pub fn areas_meet(a: &[Merc], ha: &[Vec<Merc>], b: &[Merc], hb: &[Vec<Merc>]) -> bool {
    rings_intersect(a, b)
        && !hb.iter().any(|h| inside_hole(a, h))
        && !ha.iter().any(|h| inside_hole(b, h))
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
    boundary_closest(a, b)
}

/// [`closest`] for areas with holes (`ha`, `hb`; at most one of the two has any): when
/// one lies inside a hole of the other, their distance is that of its ring to the hole's.
pub fn closest_holed(
    a: &[Merc],
    ha: &[Vec<Merc>],
    b: &[Merc],
    hb: &[Vec<Merc>],
    convex: bool,
) -> Option<(f64, Merc)> {
    if ha.is_empty() && hb.is_empty() {
        return closest(a, b, convex);
    }
    if !rings_intersect(a, b) {
        return boundary_closest(a, b);
    }
    if let Some(h) = hb.iter().find(|h| inside_hole(a, h)) {
        return boundary_closest(a, h);
    }
    if let Some(h) = ha.iter().find(|h| inside_hole(b, h)) {
        return boundary_closest(h, b);
    }
    None
}

/// The distance between two rings that do not meet, and the unit vector from the
/// closest point of `a` to that of `b` (attained between a vertex of one and an edge of
/// the other); `None` when it is 0 or not finite.
fn boundary_closest(a: &[Merc], b: &[Merc]) -> Option<(f64, Merc)> {
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

/// A region's rings as polygons: each counter-clockwise ring starts one, the clockwise
/// rings after it are its holes (the order stage 2 writes them in).
pub fn polygons(rings: &[Vec<Merc>]) -> Vec<(Vec<Merc>, Vec<Vec<Merc>>)> {
    let mut out: Vec<(Vec<Merc>, Vec<Vec<Merc>>)> = Vec::new();
    for r in rings {
        let a = signed_area(r);
        if r.len() < 3 || a == 0.0 || !a.is_finite() {
            continue;
        }
        match out.last_mut() {
            Some((_, holes)) if a < 0.0 => holes.push(r.clone()),
            _ if a < 0.0 => {} // a hole of nothing
            _ => out.push((r.clone(), Vec::new())),
        }
    }
    out
}

fn geo_ring(r: &[Merc], dx: f64) -> geo::LineString<f64> {
    let mut v: Vec<(f64, f64)> = r.iter().map(|p| (p[0] + dx, p[1])).collect();
    if let Some(&first) = v.first() {
        v.push(first);
    }
    geo::LineString::from(v)
}

/// Consecutive repeats removed, the ring open.
fn open_ring(l: &geo::LineString<f64>) -> Vec<Merc> {
    let mut r: Vec<Merc> = l.coords().map(|c| [c.x, c.y]).collect();
    r.dedup();
    while r.len() > 1 && r.first() == r.last() {
        r.pop();
    }
    r
}

/// The region of a conflict as the answer reports it (`region`): the union of its pieces
/// (stage 2's rings of each object pair, see [`polygons`]; pieces of several legs
/// overlap, and a non-convex area's clip may carry zero-width bridges) as valid
/// polygons, each a counter-clockwise exterior followed by its clockwise holes. On the
/// Earth (`earth`) each piece is first moved by whole turns so that its least x lies in
/// [−π, π), and the union is cut at x = π (RFC 7946 §3.1.9), the part east of it moved a
/// turn west: every x in [−π, π]. One ring within [−π, π] that is convex or simple and
/// counter-clockwise (the common case) is returned as it is; the rest goes through
/// `geo`'s boolean operations ([`united`]), which compute on a grid finer than the
/// answer's 7 decimals of a degree. Only reported: stages 3 and 4 use stage 2's rings.
pub fn region(rings: Vec<Vec<Merc>>, earth: bool) -> Vec<Vec<Merc>> {
    use std::f64::consts::{PI, TAU};
    let pieces = polygons(&rings);
    let turn = |r: &[Merc]| {
        let b = bbox(r);
        if earth && b[0].is_finite() {
            -TAU * ((b[0] + PI) / TAU).floor()
        } else {
            0.0
        }
    };
    // one ring that is already a valid polygon (convex, or simple and counter-clockwise,
    // decided exactly by [`simple_ccw`]) and within [−π, π]: the union of one polygon is
    // itself
    if let [(ring, holes)] = pieces.as_slice() {
        let dx = turn(ring);
        let b = bbox(ring);
        if holes.is_empty() && (!earth || b[2] + dx <= PI) && (is_convex(ring) || simple_ccw(ring))
        {
            let mut r: Vec<Merc> = ring.iter().map(|p| [p[0] + dx, p[1]]).collect();
            r.dedup();
            while r.len() > 1 && r.first() == r.last() {
                r.pop();
            }
            return if r.len() >= 3 { vec![r] } else { Vec::new() };
        }
    }
    united(&pieces, earth)
}

/// [`region`] by `geo`'s boolean operations, whatever the pieces: their union (each piece
/// first moved by whole turns on the Earth), cut at x = π. `pieces` as [`polygons`]
/// gives them.
pub fn united(pieces: &[(Vec<Merc>, Vec<Vec<Merc>>)], earth: bool) -> Vec<Vec<Merc>> {
    use geo::BooleanOps;
    use std::f64::consts::{PI, TAU};
    let turn = |r: &[Merc]| {
        let b = bbox(r);
        if earth && b[0].is_finite() {
            -TAU * ((b[0] + PI) / TAU).floor()
        } else {
            0.0
        }
    };
    let mut acc = geo::MultiPolygon::<f64>(Vec::new());
    for (ring, holes) in pieces {
        let dx = turn(ring);
        let p = geo::Polygon::new(
            geo_ring(ring, dx),
            holes.iter().map(|h| geo_ring(h, dx)).collect(),
        );
        acc = acc.union(&p);
    }
    let mut parts: Vec<(geo::Polygon<f64>, f64)> = Vec::new();
    let all: Vec<Merc> = acc
        .0
        .iter()
        .flat_map(|p| p.exterior().coords().map(|c| [c.x, c.y]))
        .collect();
    let b = bbox(&all);
    if earth && b[2] > PI {
        let strip = |lo: f64, hi: f64| {
            geo::Polygon::new(
                // tight around the region: geo computes on a grid of its operands' extent
                geo_ring(&[[lo, b[1]], [hi, b[1]], [hi, b[3]], [lo, b[3]]], 0.0),
                Vec::new(),
            )
        };
        for (lo, hi, shift) in [(b[0], PI, 0.0), (PI, b[2], -TAU)] {
            for p in acc.intersection(&strip(lo, hi)).0 {
                parts.push((p, shift));
            }
        }
    } else {
        parts.extend(acc.0.into_iter().map(|p| (p, 0.0)));
    }
    // geo's grid step is about 2⁻³¹ of the operands' extent; a vertex within ten steps of
    // the cut is put on it, exactly at ±π
    let snap = 10.0 * ((b[2] - b[0]) + (b[3] - b[1])) * 2f64.powi(-31);
    let mut out = Vec::new();
    for (p, shift) in parts {
        let mv = |r: Vec<Merc>| -> Vec<Merc> {
            r.into_iter()
                .map(|q| {
                    let x = q[0] + shift;
                    let x = if earth && (x.abs() - PI).abs() <= snap {
                        PI.copysign(x)
                    } else {
                        x
                    };
                    [if earth { x.clamp(-PI, PI) } else { x }, q[1]]
                })
                .collect()
        };
        let ext = ccw(mv(open_ring(p.exterior())));
        if ext.len() < 3 || signed_area(&ext) == 0.0 {
            continue;
        }
        out.push(ext);
        for h in p.interiors() {
            let mut h = ccw(mv(open_ring(h)));
            h.reverse();
            if h.len() >= 3 && signed_area(&h) != 0.0 {
                out.push(h);
            }
        }
    }
    out
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
        let out = region(vec![across.clone(), sq(PI - 0.05 - TAU)], true);
        assert_eq!(out.len(), 2, "{out:?}");
        let total: f64 = out.iter().map(|r| signed_area(r)).sum();
        // geo's grid: far below the answer's 7 decimals of a degree
        assert!(
            (total - signed_area(&across)).abs() < 1e-8 * signed_area(&across),
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
        assert_eq!(region(vec![inside.clone()], true), vec![inside]);
        // a turn east: moved back
        let moved = region(vec![sq(1.0 + TAU)], true);
        assert!((moved[0][0][0] - 1.0).abs() < 1e-15, "{moved:?}");
    }

    /// The reported region is valid: the pieces of two legs that overlap become one
    /// ring; a clip with a zero-width bridge becomes its two pieces; a hole stays a hole
    /// (clockwise, after its exterior).
    #[test]
    fn regions_are_united_into_valid_polygons() {
        let sq =
            |x0: f64, y0: f64, s: f64| vec![[x0, y0], [x0 + s, y0], [x0 + s, y0 + s], [x0, y0 + s]];
        let out = region(vec![sq(0.0, 0.0, 1.0), sq(0.5, 0.0, 1.0)], false);
        assert_eq!(out.len(), 1, "{out:?}");
        assert!((signed_area(&out[0]) - 1.5).abs() < 1e-9);
        // two unit squares joined along y = 0 by a zero-width bridge x ∈ [1, 2]
        let bridged = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
        ];
        let out = region(vec![bridged], false);
        assert_eq!(out.len(), 2, "{out:?}");
        for r in &out {
            assert!((signed_area(r) - 1.0).abs() < 1e-9, "{r:?}");
            assert_eq!(r.len(), 4, "{r:?}");
        }
        // a square with a hole
        let mut hole = sq(1.0, 1.0, 1.0);
        hole.reverse();
        let out = region(vec![sq(0.0, 0.0, 3.0), hole], false);
        assert_eq!(out.len(), 2, "{out:?}");
        assert!((signed_area(&out[0]) - 9.0).abs() < 1e-9);
        assert!((signed_area(&out[1]) + 1.0).abs() < 1e-9);
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
