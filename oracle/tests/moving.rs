//! Hand cases of the moving truth (polyguard_oracle::moving), each answer worked out on paper (rationals, or a
//! surd given to 9 digits).

use core::ops::Range;

use polyguard_oracle::moving::{
    components_text, plane_truth, split_segments, PlaneArea, PlaneFix, PlaneFrame, PlaneRelation,
    PlaneRings,
};

fn fix(t: f64, x: f64, y: f64) -> PlaneFix {
    PlaneFix { t, x, y, z: None }
}

fn fixz(t: f64, x: f64, y: f64, z: f64) -> PlaneFix {
    PlaneFix {
        t,
        x,
        y,
        z: Some(z),
    }
}

fn square(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn still(parts: Vec<PlaneRings>) -> PlaneArea {
    PlaneArea {
        frames: vec![PlaneFrame { t: 0.0, parts }],
        is_static: true,
        floor: None,
        ceiling: None,
    }
}

fn rings(outer: Vec<[f64; 2]>) -> PlaneRings {
    PlaneRings {
        outer,
        holes: Vec::new(),
    }
}

fn keyed(frames: Vec<(f64, Vec<[f64; 2]>)>) -> PlaneArea {
    PlaneArea {
        frames: frames
            .into_iter()
            .map(|(t, r)| PlaneFrame {
                t,
                parts: vec![rings(r)],
            })
            .collect(),
        is_static: false,
        floor: None,
        ceiling: None,
    }
}

fn near(d: f64, h: f64) -> PlaneRelation {
    PlaneRelation::Near { d, h }
}

/// The components as decimal text.
fn answer(fixes: &[PlaneFix], area: &PlaneArea, r: PlaneRelation) -> String {
    match plane_truth(fixes, area, r) {
        Ok(t) => components_text(&t.components),
        Err(u) => format!("undefined: {u}"),
    }
}

#[test]
fn moving_two_legs_cross_a_square() {
    let area = still(vec![rings(square(0.0, 0.0, 10.0, 10.0))]);
    let fixes = [
        fix(0.0, -5.0, 5.0),
        fix(10.0, 5.0, 5.0),
        fix(20.0, 5.0, 15.0),
    ];
    // in through x = 0 at t = 5 on the first leg, out through y = 10 at t = 15
    assert_eq!(
        answer(&fixes, &area, PlaneRelation::Inside),
        "[5.000000000, 15.000000000]"
    );
    // within 1: x = −1 at t = 4, y = 11 at t = 16; the legs' union merges at t = 10
    assert_eq!(
        answer(&fixes, &area, near(1.0, 0.0)),
        "[4.000000000, 16.000000000]"
    );
    // clockwise given: made counterclockwise, the same answer
    let mut cw = square(0.0, 0.0, 10.0, 10.0);
    cw.reverse();
    let area = still(vec![rings(cw)]);
    assert_eq!(
        answer(&fixes, &area, PlaneRelation::Inside),
        "[5.000000000, 15.000000000]"
    );
}

#[test]
fn moving_times_of_epoch_size_stay_exact() {
    let t0 = 1.6e9;
    let area = still(vec![rings(square(0.0, 0.0, 10.0, 10.0))]);
    let fixes = [
        fix(t0, -5.0, 5.0),
        fix(t0 + 10.0, 5.0, 5.0),
        fix(t0 + 20.0, 5.0, 15.0),
    ];
    let t = plane_truth(&fixes, &area, PlaneRelation::Inside).expect("defined");
    let c = &t.components;
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].0.exact_text(), "1600000005/1");
    assert_eq!(c[0].1.exact_text(), "1600000015/1");
}

#[test]
fn moving_a_hole_splits_inside_and_a_deep_hole_splits_near() {
    let area = still(vec![PlaneRings {
        outer: square(0.0, 0.0, 10.0, 10.0),
        holes: vec![square(4.0, 4.0, 6.0, 6.0)],
    }]);
    let fixes = [fix(0.0, -5.0, 5.0), fix(20.0, 15.0, 5.0)];
    // x = −5 + t: inside for x in [0, 4] ∪ [6, 10] (the hole's edges belong to the region)
    assert_eq!(
        answer(&fixes, &area, PlaneRelation::Inside),
        "[5.000000000, 9.000000000] [11.000000000, 15.000000000]"
    );
    // D = 1/2: the hole is deeper than D for x in (4.5, 5.5)
    assert_eq!(
        answer(&fixes, &area, near(0.5, 0.0)),
        "[4.500000000, 9.500000000] [10.500000000, 15.500000000]"
    );
    // D = 1: no point of the hole is farther than 1 from its edges
    assert_eq!(
        answer(&fixes, &area, near(1.0, 0.0)),
        "[4.000000000, 16.000000000]"
    );
}

#[test]
fn moving_parts_of_a_multipolygon_union_and_touching_parts_merge() {
    let fixes = [fix(0.0, -1.0, 1.0), fix(8.0, 7.0, 1.0)];
    let apart = still(vec![
        rings(square(0.0, 0.0, 2.0, 2.0)),
        rings(square(4.0, 0.0, 6.0, 2.0)),
    ]);
    assert_eq!(
        answer(&fixes, &apart, PlaneRelation::Inside),
        "[1.000000000, 3.000000000] [5.000000000, 7.000000000]"
    );
    let touching = still(vec![
        rings(square(0.0, 0.0, 2.0, 2.0)),
        rings(square(2.0, 0.0, 4.0, 2.0)),
    ]);
    assert_eq!(
        answer(&fixes, &touching, PlaneRelation::Inside),
        "[1.000000000, 5.000000000]"
    );
}

#[test]
fn moving_a_keyframed_square_grows_over_a_still_point() {
    // [0, 2]² at t = 0 to [0, 10]² at t = 10: [0, 2 + 0.8·t]² holds (5, 5) from t = 3.75
    let area = keyed(vec![
        (0.0, square(0.0, 0.0, 2.0, 2.0)),
        (10.0, square(0.0, 0.0, 10.0, 10.0)),
    ]);
    let fixes = [fix(0.0, 5.0, 5.0), fix(4.0, 5.0, 5.0), fix(10.0, 5.0, 5.0)];
    assert_eq!(
        answer(&fixes, &area, PlaneRelation::Inside),
        "[3.750000000, 10.000000000]"
    );
    // fixes beyond the area's existence: the domain is cut to [0, 10]
    let longer = [fix(-5.0, 5.0, 5.0), fix(15.0, 5.0, 5.0)];
    let t = plane_truth(&longer, &area, PlaneRelation::Inside).expect("defined");
    assert_eq!(
        components_text(&t.components),
        "[3.750000000, 10.000000000]"
    );
    let (lo, hi) = t.domain.expect("they meet");
    assert_eq!((lo.to_string(), hi.to_string()), ("0".into(), "10".into()));
}

#[test]
fn moving_a_cell_sweeps_over_the_mover_between_fixes() {
    // x in [10 − 2.2·t, 12 − 2.2·t] holds x = 0 for t in [50/11, 60/11]
    let area = keyed(vec![
        (0.0, square(10.0, 0.0, 12.0, 2.0)),
        (10.0, square(-12.0, 0.0, -10.0, 2.0)),
    ]);
    let fixes = [fix(0.0, 0.0, 1.0), fix(10.0, 0.0, 1.0)];
    let t = plane_truth(&fixes, &area, PlaneRelation::Inside).expect("defined");
    let c = &t.components;
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].0.exact_text(), "50/11");
    assert_eq!(c[0].1.exact_text(), "60/11");
}

#[test]
fn moving_a_corner_passed_within_d_has_a_surd_end() {
    // y = −1/2, x = −2 + t: within 1 of the corner (0, 0) from x = −√3/2
    let area = still(vec![rings(square(0.0, 0.0, 10.0, 10.0))]);
    let fixes = [fix(0.0, -2.0, -0.5), fix(4.0, 2.0, -0.5)];
    assert_eq!(
        answer(&fixes, &area, near(1.0, 0.0)),
        "[1.133974596, 4.000000000]"
    );
    // inside: never (the path stays below the square)
    assert_eq!(answer(&fixes, &area, PlaneRelation::Inside), "");
}

#[test]
fn moving_a_ceiling_cuts_a_climb() {
    let mut area = still(vec![rings(square(0.0, 0.0, 10.0, 10.0))]);
    area.floor = Some(0.0);
    area.ceiling = Some(1000.0);
    // inside horizontally throughout, z = 500 + 100·t
    let fixes = [fixz(0.0, 5.0, 5.0, 500.0), fixz(10.0, 5.0, 5.0, 1500.0)];
    assert_eq!(
        answer(&fixes, &area, PlaneRelation::Inside),
        "[0.000000000, 5.000000000]"
    );
    // H = 100: up to z = 1100
    assert_eq!(
        answer(&fixes, &area, near(0.0, 100.0)),
        "[0.000000000, 6.000000000]"
    );
    // no heights: the vertical condition is unknown, taken as holding
    let flat = [fix(0.0, 5.0, 5.0), fix(10.0, 5.0, 5.0)];
    let t = plane_truth(&flat, &area, PlaneRelation::Inside).expect("defined");
    assert!(t.vertical_unknown);
    assert_eq!(
        components_text(&t.components),
        "[0.000000000, 10.000000000]"
    );
    // heights known: not unknown
    let t = plane_truth(&fixes, &area, PlaneRelation::Inside).expect("defined");
    assert!(!t.vertical_unknown);
}

#[test]
fn moving_one_instant_and_no_overlap() {
    let area = still(vec![rings(square(0.0, 0.0, 10.0, 10.0))]);
    assert_eq!(
        answer(&[fix(3.0, 5.0, 5.0)], &area, PlaneRelation::Inside),
        "[3.000000000, 3.000000000]"
    );
    assert_eq!(
        answer(&[fix(3.0, 50.0, 5.0)], &area, PlaneRelation::Inside),
        ""
    );
    // a keyframed area after the fixes: no domain
    let later = keyed(vec![
        (100.0, square(0.0, 0.0, 10.0, 10.0)),
        (110.0, square(0.0, 0.0, 10.0, 10.0)),
    ]);
    let fixes = [fix(0.0, 5.0, 5.0), fix(10.0, 5.0, 5.0)];
    let t = plane_truth(&fixes, &later, PlaneRelation::Inside).expect("defined");
    assert!(t.domain.is_none() && t.components.is_empty());
    // meeting at one instant: the last fix at the first keyframe
    let fixes = [fix(90.0, 5.0, 5.0), fix(100.0, 5.0, 5.0)];
    assert_eq!(
        answer(&fixes, &later, PlaneRelation::Inside),
        "[100.000000000, 100.000000000]"
    );
}

#[test]
fn moving_a_bow_tie_is_undefined_and_bad_input_refused() {
    let area = still(vec![rings(vec![
        [0.0, 0.0],
        [2.0, 2.0],
        [2.0, 0.0],
        [0.0, 2.0],
    ])]);
    let fixes = [fix(0.0, -1.0, 1.0), fix(4.0, 3.0, 1.0)];
    assert!(plane_truth(&fixes, &area, PlaneRelation::Inside).is_err());
    let sq = still(vec![rings(square(0.0, 0.0, 1.0, 1.0))]);
    let backwards = [fix(1.0, 0.0, 0.0), fix(1.0, 1.0, 0.0)];
    assert!(plane_truth(&backwards, &sq, PlaneRelation::Inside).is_err());
    assert!(plane_truth(&fixes, &sq, near(-1.0, 0.0)).is_err());
    assert!(plane_truth(&[fix(f64::NAN, 0.0, 0.0)], &sq, PlaneRelation::Inside).is_err());
}

#[test]
fn moving_segments_split_at_gaps_longer_than_max_gap() {
    let f = |t: f64| fix(t, 0.0, 0.0);
    let fixes = [f(0.0), f(10.0), f(100.0), f(160.0), f(221.0)];
    // 10 → 100 is 90 > 60; 100 → 160 is exactly 60 (joined); 160 → 221 is 61
    assert_eq!(split_segments(&fixes, 60.0), vec![0..2, 2..4, 4..5]);
    assert_eq!(split_segments(&[], 60.0), Vec::<Range<usize>>::new());
    assert_eq!(split_segments(&fixes, f64::INFINITY), vec![0..5]);
}
