//! The planar model's certified spans (docs/moving-features.md) on cases whose answers
//! are known by hand: each exact end must lie in its enclosure, and certain spans must
//! cover the known interior.

use polyguard_earth::moving::plane::{
    plane_spans, split_segments, PlaneArea, PlaneFix, PlaneFrame, PlaneRelation, PlaneRings,
    TimeSpan,
};

fn fix(t: f64, x: f64, y: f64) -> PlaneFix {
    PlaneFix { t, x, y, z: None }
}

fn square(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn stat(parts: Vec<PlaneRings>) -> PlaneArea {
    PlaneArea {
        frames: vec![PlaneFrame { t: 0.0, parts }],
        is_static: true,
        floor: None,
        ceiling: None,
    }
}

fn rings(outer: Vec<[f64; 2]>, holes: Vec<Vec<[f64; 2]>>) -> PlaneRings {
    PlaneRings { outer, holes }
}

/// The spans enclose `truth` (components [a, b]) exactly: one certain span each, each
/// end in its enclosure, enclosures narrow (relative to the times' size).
fn assert_encloses(spans: &[TimeSpan], truth: &[(f64, f64)]) {
    assert_eq!(
        spans.len(),
        truth.len(),
        "spans {spans:?} against {truth:?}"
    );
    for (s, &(a, b)) in spans.iter().zip(truth) {
        assert!(s.certain, "{s:?}");
        assert!(
            s.start[0] <= a && a <= s.start[1],
            "start {a} not in {:?}",
            s.start
        );
        assert!(s.end[0] <= b && b <= s.end[1], "end {b} not in {:?}", s.end);
        let scale = a.abs().max(b.abs()).max(1.0);
        assert!(s.start[1] - s.start[0] <= 1e-9 * scale, "{s:?} too wide");
        assert!(s.end[1] - s.end[0] <= 1e-9 * scale, "{s:?} too wide");
    }
}

#[test]
fn a_two_leg_flight_through_a_square() {
    // North at 1 then 1: inside while 0 ≤ y ≤ 2, that is t ∈ [2, 4].
    let fixes = [fix(0.0, 1.0, -2.0), fix(3.0, 1.0, 1.0), fix(8.0, 1.0, 6.0)];
    let area = stat(vec![rings(square(0.0, 0.0, 2.0, 2.0), vec![])]);
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_encloses(&spans, &[(2.0, 4.0)]);
    // Within D = 0.5: y ∈ [-0.5, 2.5], t ∈ [1.5, 4.5].
    let near = PlaneRelation::Near {
        d_lo: 0.5,
        d_hi: 0.5,
        h: 0.0,
    };
    assert_encloses(&plane_spans(&fixes, &area, near).unwrap(), &[(1.5, 4.5)]);
}

#[test]
fn epoch_times_are_kept_to_their_ulp() {
    let t0 = 1_633_611_625.0;
    let fixes = [
        fix(t0, 1.0, -2.0),
        fix(t0 + 3.0, 1.0, 1.0),
        fix(t0 + 8.0, 1.0, 6.0),
    ];
    let area = stat(vec![rings(square(0.0, 0.0, 2.0, 2.0), vec![])]);
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_encloses(&spans, &[(t0 + 2.0, t0 + 4.0)]);
}

#[test]
fn a_hole_splits_the_interval_and_its_edge_belongs_to_the_area() {
    // East along y = 2 at 1 from x = -1: the area is [0, 4]² less the open (1, 3)².
    let fixes = [fix(0.0, -1.0, 2.0), fix(6.0, 5.0, 2.0)];
    let area = stat(vec![rings(
        square(0.0, 0.0, 4.0, 4.0),
        vec![square(1.0, 1.0, 3.0, 3.0)],
    )]);
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_encloses(&spans, &[(1.0, 2.0), (4.0, 5.0)]);
    // Within 0.5 the hole's deep part is x ∈ (1.5, 2.5): near on [0.5, 2.5] and [3.5, 5.5].
    let near = PlaneRelation::Near {
        d_lo: 0.5,
        d_hi: 0.5,
        h: 0.0,
    };
    assert_encloses(
        &plane_spans(&fixes, &area, near).unwrap(),
        &[(0.5, 2.5), (3.5, 5.5)],
    );
}

#[test]
fn a_multipolygon_is_the_union_of_its_parts() {
    let fixes = [fix(0.0, -1.0, 0.5), fix(10.0, 9.0, 0.5)];
    let area = stat(vec![
        rings(square(0.0, 0.0, 2.0, 1.0), vec![]),
        rings(square(2.0, 0.0, 3.0, 1.0), vec![]),
        rings(square(5.0, 0.0, 6.0, 1.0), vec![]),
    ]);
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    // [1, 3] and [3, 4] touch at x = 2: one component [1, 4] (reported as two certain
    // spans that share the enclosure around 3, as G1–G3 allow), then [6, 7].
    assert_contract(&spans, &[(1.0, 4.0), (6.0, 7.0)]);
}

/// G1–G3 of docs/moving-features.md against exact components.
fn assert_contract(spans: &[TimeSpan], truth: &[(f64, f64)]) {
    for &(a, b) in truth {
        // G1 at the ends and the middle, G3 for both ends.
        for x in [a, (a + b) / 2.0, b] {
            assert!(
                spans.iter().any(|s| s.start[0] <= x && x <= s.end[1]),
                "{x} missed"
            );
        }
        for x in [a, b] {
            let enclosed = spans
                .iter()
                .any(|s| (s.start[0] <= x && x <= s.start[1]) || (s.end[0] <= x && x <= s.end[1]));
            assert!(enclosed, "end {x} not enclosed in {spans:?}");
        }
    }
    for s in spans.iter().filter(|s| s.certain) {
        // G2: the certain core lies in one component.
        assert!(
            truth.iter().any(|&(a, b)| a <= s.start[1] && s.end[0] <= b),
            "{s:?}"
        );
    }
}

#[test]
fn a_cell_that_sweeps_over_a_still_mover_between_two_keyframes() {
    // The mover sits at (5, 0.5) with fixes at 0 and 10 only; the cell [0, 1] × [0, 1]
    // moves to [9, 10] × [0, 1] between keyframes at 0 and 10: x ∈ [5 − 1, 5] ⇔ 0.9t ∈ [4, 5].
    let fixes = [fix(0.0, 5.0, 0.5), fix(10.0, 5.0, 0.5)];
    let area = PlaneArea {
        frames: vec![
            PlaneFrame {
                t: 0.0,
                parts: vec![rings(square(0.0, 0.0, 1.0, 1.0), vec![])],
            },
            PlaneFrame {
                t: 10.0,
                parts: vec![rings(square(9.0, 0.0, 10.0, 1.0), vec![])],
            },
        ],
        is_static: false,
        floor: None,
        ceiling: None,
    };
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_encloses(&spans, &[(40.0 / 9.0, 50.0 / 9.0)]);
}

#[test]
fn a_keyframed_cell_exists_only_between_its_keyframes() {
    let fixes = [fix(0.0, 0.5, 0.5), fix(10.0, 0.5, 0.5)];
    let sq = vec![rings(square(0.0, 0.0, 1.0, 1.0), vec![])];
    let area = PlaneArea {
        frames: vec![
            PlaneFrame {
                t: 2.0,
                parts: sq.clone(),
            },
            PlaneFrame { t: 5.0, parts: sq },
        ],
        is_static: false,
        floor: None,
        ceiling: None,
    };
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_encloses(&spans, &[(2.0, 5.0)]);
}

#[test]
fn a_climb_through_the_ceiling() {
    // Inside horizontally throughout; z from 0 to 1000 over 10: ceiling 400 ⇒ t ≤ 4; with
    // H = 100, t ≤ 5.
    let fixes = [
        PlaneFix {
            t: 0.0,
            x: 0.5,
            y: 0.5,
            z: Some(0.0),
        },
        PlaneFix {
            t: 10.0,
            x: 0.5,
            y: 0.5,
            z: Some(1000.0),
        },
    ];
    let mut area = stat(vec![rings(square(0.0, 0.0, 1.0, 1.0), vec![])]);
    area.ceiling = Some(400.0);
    area.floor = Some(-50.0);
    assert_encloses(
        &plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap(),
        &[(0.0, 4.0)],
    );
    let near = PlaneRelation::Near {
        d_lo: 0.0,
        d_hi: 0.0,
        h: 100.0,
    };
    assert_encloses(&plane_spans(&fixes, &area, near).unwrap(), &[(0.0, 5.0)]);
}

#[test]
fn without_altitude_a_vertical_limit_makes_every_span_possible() {
    let fixes = [fix(0.0, 0.5, 0.5), fix(10.0, 0.5, 0.5)];
    let mut area = stat(vec![rings(square(0.0, 0.0, 1.0, 1.0), vec![])]);
    area.ceiling = Some(400.0);
    let spans = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap();
    assert_eq!(spans.len(), 1);
    assert!(!spans[0].certain);
    assert_eq!((spans[0].start[0], spans[0].end[1]), (0.0, 10.0));
}

#[test]
fn gaps_split_the_segments() {
    let f = [
        fix(0.0, 0.0, 0.0),
        fix(1.0, 0.0, 0.0),
        fix(100.0, 0.0, 0.0),
        fix(101.0, 0.0, 0.0),
    ];
    assert_eq!(split_segments(&f, 60.0), vec![0..2, 2..4]);
    assert_eq!(split_segments(&f, 99.0), vec![0..4]);
    assert_eq!(split_segments(&f[..1], 60.0), vec![0..1]);
}

#[test]
fn bad_input_is_named() {
    let fixes = [fix(0.0, 0.0, 0.0), fix(0.0, 1.0, 0.0)];
    let area = stat(vec![rings(square(0.0, 0.0, 1.0, 1.0), vec![])]);
    let e = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap_err();
    assert!(e.to_string().contains("fixes"), "{e}");
    let fixes = [fix(0.0, f64::NAN, 0.0), fix(1.0, 1.0, 0.0)];
    let e = plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap_err();
    assert!(e.to_string().contains("fixes[0].x"), "{e}");
}

/// A comb of 40 teeth (162 vertices: large rings are clipped to a box around each piece
/// before the engine sees them, and the clip is reused by the next pieces), crossed along
/// y = 5 at unit speed from x = −1 with a fix every half time unit: inside each tooth
/// [2i, 2i + 1] at t ∈ [2i + 1, 2i + 2]; within 0.25, [2i + 0.75, 2i + 2.25].
#[test]
fn a_large_ring_is_answered_through_its_clips() {
    let mut comb = vec![[0.0, -1.0], [80.0, -1.0]];
    for i in (0..40).rev() {
        let x = 2.0 * i as f64;
        comb.extend([[x + 1.0, 0.0], [x + 1.0, 10.0], [x, 10.0], [x, 0.0]]);
    }
    comb.truncate(comb.len() - 1); // the last tooth's foot is the first vertex's column
    comb.push([0.0, 0.0]);
    let comb: Vec<[f64; 2]> = comb.into_iter().rev().collect();
    assert!(comb.len() > 100);
    let fixes: Vec<PlaneFix> = (0..=170)
        .map(|k| fix(k as f64 * 0.5, -1.0 + k as f64 * 0.5, 5.0))
        .collect();
    let area = stat(vec![rings(comb, vec![])]);
    let inside: Vec<(f64, f64)> = (0..40)
        .map(|i| (2.0 * i as f64 + 1.0, 2.0 * i as f64 + 2.0))
        .collect();
    assert_contract(
        &plane_spans(&fixes, &area, PlaneRelation::Inside).unwrap(),
        &inside,
    );
    let near = PlaneRelation::Near {
        d_lo: 0.25,
        d_hi: 0.25,
        h: 0.0,
    };
    let within: Vec<(f64, f64)> = (0..40)
        .map(|i| (2.0 * i as f64 + 0.75, 2.0 * i as f64 + 2.25))
        .collect();
    assert_contract(&plane_spans(&fixes, &area, near).unwrap(), &within);
}
