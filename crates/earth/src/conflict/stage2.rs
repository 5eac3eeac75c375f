//! Paper B Section IV-C, eqs 7–10: intersection of the regions `Γ` two objects can occupy.

use super::{geom, stage1::Candidates, Object};
use crate::sphere::Merc;
use geo::{BooleanOps, Intersects, LineString, Polygon};
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

fn to_geo(ring: &[Merc]) -> Polygon<f64> {
    let mut pts: Vec<(f64, f64)> = ring.iter().map(|p| (p[0], p[1])).collect();
    if let Some(&first) = pts.first() {
        pts.push(first);
    }
    Polygon::new(LineString::from(pts), vec![])
}

/// Paper B eq 9 for one pair: `None` when the closed regions are disjoint. Convex–convex
/// (rectangle sweeps, convex areas) uses clipping; a non-convex static area goes through
/// `geo`'s boolean operations (the paper's Shapely), its closed-set `Intersects` deciding.
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
    // A non-convex area against a convex region: Sutherland–Hodgman with the convex one
    // as clipper. The output ring may contain zero-width bridges along the clipper's
    // edges where the true intersection has several pieces; its vertices include every
    // vertex of the true intersection (plus, possibly, clipper corners on a bridge, inside
    // the convex region), so stage 3's projections (eq 10) stay conservative.
    if a.is_convex() || b.is_convex() {
        let (subject, clipper) = if b.is_convex() { (a, b) } else { (b, a) };
        if !geom::rings_intersect(&subject.sweep, &clipper.sweep) {
            return None;
        }
        if both_static && !static_region {
            return Some(Vec::new());
        }
        let c = geom::clip_convex(&subject.sweep, &clipper.sweep);
        let rings = if c.len() >= 3 { vec![c] } else { vec![] };
        return Some(rings);
    }
    if !static_region {
        return geom::rings_intersect(&a.sweep, &b.sweep).then(Vec::new);
    }
    let (pa, pb) = (to_geo(&a.sweep), to_geo(&b.sweep));
    if !pa.intersects(&pb) {
        return None;
    }
    let mp = pa.intersection(&pb);
    let rings =
        mp.0.iter()
            .map(|p| {
                let mut r: Vec<Merc> = p.exterior().coords().map(|c| [c.x, c.y]).collect();
                if r.len() > 1 && r.first() == r.last() {
                    r.pop();
                }
                geom::ccw(r)
            })
            .filter(|r| r.len() >= 3)
            .collect();
    Some(rings)
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
