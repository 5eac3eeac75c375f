//! Paper B Section VI.A, Example 1: two static polygons. The paper draws them (Fig. 2)
//! but does not list their vertices, so these tests use polygons of the same kind: the
//! AABBs overlap (stage 1 keeps the pair), stage 2 finds the conflict area and decides.

use polyguard_earth::conflict::{geom, pipeline, stage4::Method, Object};
use polyguard_earth::sphere::{mercator, LonLat};

fn area(owner: u32, deg: &[(f64, f64)]) -> Object {
    let ring = deg
        .iter()
        .map(|&(x, y)| mercator(LonLat::from_degrees(x, y)))
        .collect();
    Object::area(owner, ring, f64::NEG_INFINITY, f64::INFINITY)
}

/// Relative accuracy of a reported region's area: a region of several pieces is made
/// valid by `geo`'s boolean operations, on a grid of about 2⁻³¹ of its extent (each vertex
/// within ~5·10⁻¹⁰ of the extent; the area within a few 10⁻⁹ of itself).
const AREA_REL: f64 = 1e-8;

#[test]
fn overlapping_static_polygons_conflict_with_their_common_area() {
    // a non-convex "L" and a convex quadrilateral
    let a = area(
        0,
        &[
            (0.0, 0.0),
            (4.0, 0.0),
            (4.0, 1.0),
            (1.0, 1.0),
            (1.0, 4.0),
            (0.0, 4.0),
        ],
    );
    let b = area(1, &[(0.5, 0.5), (3.0, 0.5), (3.0, 3.0), (0.5, 3.0)]);
    let (c, stats) = pipeline::run(&[a.clone(), b.clone()], pipeline::Options::default());
    assert_eq!(stats.candidate_pairs, 1);
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].method, Method::AreaOverlap);
    assert!(c[0].t_start == f64::NEG_INFINITY && c[0].t_end == f64::INFINITY);
    // the conflict area: the L's two arms inside the square (in the Mercator plane)
    let got: f64 = c[0].rings.iter().map(|r| geom::signed_area(r).abs()).sum();
    let whole_b = geom::signed_area(&b.sweep);
    let hole = geom::signed_area(&area(2, &[(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)]).sweep);
    let want = whole_b - hole;
    assert!((got - want).abs() <= AREA_REL * want, "{got} vs {want}");
}

#[test]
fn overlapping_boxes_but_disjoint_polygons_are_rejected_by_stage2() {
    // the L's notch holds a small square: AABBs overlap, polygons do not
    let a = area(
        0,
        &[
            (0.0, 0.0),
            (4.0, 0.0),
            (4.0, 1.0),
            (1.0, 1.0),
            (1.0, 4.0),
            (0.0, 4.0),
        ],
    );
    let b = area(1, &[(2.0, 2.0), (3.0, 2.0), (3.0, 3.0), (2.0, 3.0)]);
    let (c, stats) = pipeline::run(&[a, b], pipeline::Options::default());
    assert_eq!(stats.candidate_pairs, 1);
    assert_eq!(stats.region_pairs, 0);
    assert!(c.is_empty());
}

#[test]
fn time_windows_of_static_areas_overlap() {
    let ring = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)];
    let mk = |o, t0, t1| {
        let r = ring
            .iter()
            .map(|&(x, y)| mercator(LonLat::from_degrees(x + o as f64, y)))
            .collect();
        Object::area(o, r, t0, t1)
    };
    let (c, _) = pipeline::run(
        &[mk(0, 0.0, 5.0), mk(1, 3.0, 9.0)],
        pipeline::Options::default(),
    );
    assert_eq!((c[0].t_start, c[0].t_end), (3.0, 5.0));
    let (c, s) = pipeline::run(
        &[mk(0, 0.0, 2.0), mk(1, 3.0, 9.0)],
        pipeline::Options::default(),
    );
    assert!(c.is_empty() && s.candidate_pairs == 0);
}
