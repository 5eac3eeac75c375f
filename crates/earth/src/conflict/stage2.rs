//! Paper B Section IV-C, eqs 7–10: intersection of the regions `Γ` two objects can occupy.

use super::{geom, stage1::Candidates, Object};
use crate::sphere::Merc;
use geo::{BooleanOps, LineString, Polygon};
use rayon::prelude::*;

/// Stage 2's output for one surviving pair: `A^{ij} = Γ^i ∩ Γ^j` (eq 9) as rings whose
/// vertices are the `a^{ij}(k)` of eq 10. `rings` may be empty when the closed regions
/// only touch (a conflict of zero area).
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// Object indices `(i, j)`, `i < j`.
    pub pair: (u32, u32),
    /// The intersection's rings (counter-clockwise, not closed).
    pub rings: Vec<Vec<Merc>>,
}

/// All surviving pairs of stage 2.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Regions {
    /// The regions, in candidate order.
    pub regions: Vec<Region>,
}

fn line(ring: &[Merc]) -> LineString<f64> {
    let mut pts: Vec<(f64, f64)> = ring.iter().map(|p| (p[0], p[1])).collect();
    if let Some(&first) = pts.first() {
        pts.push(first);
    }
    LineString::from(pts)
}

fn to_geo(ring: &[Merc], holes: &[Vec<Merc>]) -> Polygon<f64> {
    Polygon::new(line(ring), holes.iter().map(|h| line(h)).collect())
}

/// Paper B eq 9 for one pair: `None` when the closed regions are disjoint. Convex–convex
/// (rectangle sweeps, convex areas) uses clipping; two non-convex static areas the clip by
/// a hull where [`geom::clip_by_hull_exact`] shows it exact, otherwise `geo`'s boolean
/// operations (the paper's Shapely), their closed-set test deciding ([`geom::areas_meet`]).
/// `static_region`: compute the region of two static areas (only reported, never used by
/// later stages); when false such pairs are decided and get no rings.
pub fn region(a: &Object, b: &Object, static_region: bool) -> Option<Vec<Vec<Merc>>> {
    let (ba, bb) = (a.aabb, b.aabb);
    if ba[0] > bb[2] || bb[0] > ba[2] || ba[1] > bb[3] || bb[1] > ba[3] {
        return None;
    }
    let both_static = !a.is_moving() && !b.is_moving();
    if a.is_convex() && b.is_convex() {
        if !geom::convex_intersect(&a.sweep, &b.sweep) {
            return None;
        }
        if both_static && !static_region {
            return Some(Vec::new());
        }
        let c = geom::clip_convex(&a.sweep, &b.sweep);
        let rings = if c.len() >= 3 { vec![c] } else { vec![] };
        return Some(rings);
    }
    // A non-convex area (perhaps with holes) against a convex region: Sutherland–Hodgman
    // with the convex one as clipper, on the exterior ring and on each hole. The output
    // ring may contain zero-width bridges along the clipper's edges where the true
    // intersection has several pieces; its vertices include every vertex of the true
    // intersection (plus, possibly, clipper corners on a bridge, inside the convex
    // region), so stage 3's projections (eq 10) stay conservative. The clipped holes
    // follow as clockwise rings.
    if a.is_convex() || b.is_convex() {
        let (subject, clipper) = if b.is_convex() { (a, b) } else { (b, a) };
        if !geom::areas_meet(&subject.sweep, subject.holes(), &clipper.sweep, &[]) {
            return None;
        }
        if both_static && !static_region {
            return Some(Vec::new());
        }
        let c = geom::clip_convex(&subject.sweep, &clipper.sweep);
        let mut rings = if c.len() >= 3 { vec![c] } else { vec![] };
        if !rings.is_empty() {
            rings.extend(
                subject
                    .holes()
                    .iter()
                    .map(|h| geom::clip_convex(h, &clipper.sweep))
                    .filter(|h| h.len() >= 3),
            );
        }
        return Some(rings);
    }
    if !geom::areas_meet(&a.sweep, a.holes(), &b.sweep, b.holes()) {
        return None;
    }
    if !static_region {
        return Some(Vec::new());
    }
    // one of the two meets none of the other's pockets: the clip by the other's hull
    if a.holes().is_empty() && b.holes().is_empty() {
        let clip = geom::clip_by_hull_exact(&a.sweep, &b.sweep)
            .or_else(|| geom::clip_by_hull_exact(&b.sweep, &a.sweep));
        if let Some(r) = clip {
            return Some(if r.len() >= 3 { vec![r] } else { Vec::new() });
        }
    }
    Some(exact_rings(a, b))
}

/// Paper B eq 9 by `geo`'s boolean operations: `Γ^i ∩ Γ^j`, holes included, as
/// counter-clockwise exteriors each followed by its clockwise holes. For the answer's
/// region where an object is not convex (the Sutherland–Hodgman clip stage 3 uses may
/// carry zero-width bridges, which no union removes once rounding has given them a
/// width); also stage 2's region of two non-convex static areas.
pub fn exact_rings(a: &Object, b: &Object) -> Vec<Vec<Merc>> {
    let (pa, pb) = (to_geo(&a.sweep, a.holes()), to_geo(&b.sweep, b.holes()));
    let mp = pa.intersection(&pb);
    let open = |l: &LineString<f64>| {
        let mut r: Vec<Merc> = l.coords().map(|c| [c.x, c.y]).collect();
        if r.len() > 1 && r.first() == r.last() {
            r.pop();
        }
        r
    };
    let mut rings = Vec::new();
    for p in &mp.0 {
        let r = geom::ccw(open(p.exterior()));
        if r.len() < 3 {
            continue;
        }
        rings.push(r);
        for h in p.interiors() {
            let mut h = geom::ccw(open(h));
            h.reverse();
            if h.len() >= 3 {
                rings.push(h);
            }
        }
    }
    rings
}

/// Paper B eq 9, the answer's region of a pair where exactly one object is convex: the
/// clip of the other by it when [`geom::clip_convex_exact`] shows the clip to be the
/// intersection's boundary (the other has no holes), otherwise [`exact_rings`].
pub fn answer_rings(a: &Object, b: &Object) -> Vec<Vec<Merc>> {
    let (subject, clipper) = if b.is_convex() { (a, b) } else { (b, a) };
    if subject.holes().is_empty() && clipper.holes().is_empty() {
        if let Some(r) = geom::clip_convex_exact(&subject.sweep, &clipper.sweep) {
            return if r.len() >= 3 { vec![r] } else { Vec::new() };
        }
    }
    exact_rings(a, b)
}

/// Paper B Section IV-C over all candidates, in parallel (rayon). `static_regions`: see
/// [`region`].
pub fn regions(objects: &[Object], cands: &Candidates, static_regions: bool) -> Regions {
    let regions = cands
        .pairs
        .par_iter()
        .filter_map(|&(i, j)| {
            region(&objects[i as usize], &objects[j as usize], static_regions).map(|rings| Region {
                pair: (i, j),
                rings,
            })
        })
        .collect();
    Regions { regions }
}
