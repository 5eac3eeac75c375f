//! Hand-computed ground truths (entry times derived in the comments).

use polyguard_oracle::truth::{earliest_contact, simple_on_window, RootId};
use polyguard_oracle::{truth, CaseInput, Decided, Exact, ExactCase, Truth, Q, V2};

fn q(s: &str) -> Q {
    polyguard_oracle::convert::parse_rational(s).expect("valid test rational")
}

fn p(x: &str, y: &str) -> V2<Q> {
    V2::new(q(x), q(y))
}

const SQUARE: [[&str; 2]; 4] = [["0", "0"], ["10", "0"], ["10", "10"], ["0", "10"]];

fn case2d(
    t: &str,
    pos: [&str; 2],
    vel: [&str; 2],
    verts: &[[&str; 2]],
    vels: &[[&str; 2]],
) -> ExactCase<Q> {
    let c = CaseInput {
        lookahead: t,
        buff: "1/100",
        fac: "1/10000",
        pos: &pos,
        vel: &vel,
        vertices: verts,
        velocities: vels,
        slab: None,
    };
    ExactCase::new(&c).expect("valid test case")
}

fn entry(t: &Truth) -> Option<String> {
    match t {
        Truth::Enters { entry_time } => entry_time.as_rational_string(),
        _ => None,
    }
}

#[test]
fn static_square_entries() {
    // (−5, 5) moving right at 1 reaches x = 0 at t = 5.
    assert_eq!(
        entry(&truth(&case2d("10", ["-5", "5"], ["1", "0"], &SQUARE, &[]))).as_deref(),
        Some("5/1")
    );
    // Exactly at t = T = 5 (closed interval), and missed with T = 49/10.
    assert_eq!(
        entry(&truth(&case2d("5", ["-5", "5"], ["1", "0"], &SQUARE, &[]))).as_deref(),
        Some("5/1")
    );
    assert_eq!(
        truth(&case2d("49/10", ["-5", "5"], ["1", "0"], &SQUARE, &[])),
        Truth::Misses
    );
    // Starting on the boundary: t = 0. Inside: t = 0.
    assert_eq!(
        entry(&truth(&case2d("1", ["0", "5"], ["-1", "0"], &SQUARE, &[]))).as_deref(),
        Some("0/1")
    );
    assert_eq!(
        entry(&truth(&case2d("1", ["3", "3"], ["0", "0"], &SQUARE, &[]))).as_deref(),
        Some("0/1")
    );
    // Sliding along the bottom edge's line (motion collinear with the edge): at t = 5.
    assert_eq!(
        entry(&truth(&case2d("10", ["-5", "0"], ["1", "0"], &SQUARE, &[]))).as_deref(),
        Some("5/1")
    );
    // Through the corner only: (−1, 1) moving (1, −1) touches (0, 0) at t = 1.
    assert_eq!(
        entry(&truth(&case2d("3", ["-1", "1"], ["1", "-1"], &SQUARE, &[]))).as_deref(),
        Some("1/1")
    );
    // Passing 1/1000 below the square: never.
    assert_eq!(
        truth(&case2d("30", ["-5", "-1/1000"], ["1", "0"], &SQUARE, &[])),
        Truth::Misses
    );
    // The square moving left at 1 to a point at rest at (12, 5): right side x = 10 − t, t = −2? no:
    // the point is outside to the right and the square moves away: never.
    let left = [["-1", "0"]; 4];
    assert_eq!(
        truth(&case2d("10", ["12", "5"], ["0", "0"], &SQUARE, &left)),
        Truth::Misses
    );
    // Moving right instead: x = 10 + t reaches 12 at t = 2.
    let right = [["1", "0"]; 4];
    assert_eq!(
        entry(&truth(&case2d(
            "10",
            ["12", "5"],
            ["0", "0"],
            &SQUARE,
            &right
        )))
        .as_deref(),
        Some("2/1")
    );
}

#[test]
fn figure_2_truth_rational_and_irrational() {
    // Triangle A = (0,0), D = (3,−1) at rest, B(t) = (2, 2 − 2t); the point
    // (t, y0) meets AB when y0 = (1 − t)t. y0 = 2/9: t = 1/3 (then 2/3).
    let tri = [["0", "0"], ["3", "-1"], ["2", "2"]];
    let vels = [["0", "0"], ["0", "0"], ["0", "-2"]];
    let c = case2d("1", ["0", "2/9"], ["1", "0"], &tri, &vels);
    assert_eq!(entry(&truth(&c)).as_deref(), Some("1/3"));
    // y0 = 1/5: t² − t + 1/5 = 0, t = 1/2 − √5/10 = 0.27639320225002…
    let c = case2d("1", ["0", "1/5"], ["1", "0"], &tri, &vels);
    match truth(&c) {
        Truth::Enters { entry_time } => {
            assert_eq!(entry_time.as_rational_string(), None);
            assert_eq!(entry_time.to_decimal_string(6), "0.276393");
            assert_eq!(entry_time.to_decimal_string(14), "0.27639320225002");
        }
        other => panic!("expected an irrational entry, got {other:?}"),
    }
    // y0 = 1/4: the double root t = 1/2 (discriminant exactly zero): the point
    // touches the edge at (1/2, 1/4) and leaves: still an entry of the closed polygon.
    let c = case2d("1", ["0", "1/4"], ["1", "0"], &tri, &vels);
    assert_eq!(entry(&truth(&c)).as_deref(), Some("1/2"));
    // y0 = 1/4 + 1/1000: never meets it (t(1 − t) ≤ 1/4).
    let c = case2d("1", ["0", "251/1000"], ["1", "0"], &tri, &vels);
    assert_eq!(truth(&c), Truth::Misses);
    // The second meeting via earliest_contact on [1/2, 1]: 1/6 after the restart.
    let (s, v) = (p("1/2", "2/9"), p("1", "0"));
    let tc = earliest_contact(
        &Exact,
        &q("1/2"),
        &s,
        &v,
        &p("0", "0"),
        &p("0", "0"),
        &p("2", "1"),
        &p("0", "-2"),
    )
    .decided();
    let tc = tc.expect("met at 1/6");
    assert_eq!(tc.root, RootId::Index(1));
    assert_eq!(tc.time.cmp_rat(&q("1/6")), core::cmp::Ordering::Equal);
}

#[test]
fn polygons_that_are_not_simple_are_answered_where_no_fill_rule_matters() {
    // A bow tie at rest: lobes (0,0),(5,5),(0,10) and (5,5),(10,10),(10,0), each of
    // winding number ±1, inside by the nonzero and the even-odd rule alike.
    let bow = [["0", "0"], ["10", "10"], ["10", "0"], ["0", "10"]];
    assert_eq!(
        truth(&case2d("1", ["20", "20"], ["0", "0"], &bow, &[])),
        Truth::Misses
    );
    for inside in [["8", "5"], ["2", "5"]] {
        assert_eq!(
            entry(&truth(&case2d("1", inside, ["0", "0"], &bow, &[]))).as_deref(),
            Some("0/1")
        );
    }
    // From (20, 5) at −10 along x, the right lobe's edge x = 10 is touched at t = 1.
    assert_eq!(
        entry(&truth(&case2d("2", ["20", "5"], ["-10", "0"], &bow, &[]))).as_deref(),
        Some("1/1")
    );
    // Between the lobes' far ends (5, 1) lies outside both: winding 0, a miss at rest.
    assert_eq!(
        truth(&case2d("1", ["5", "1"], ["0", "0"], &bow, &[])),
        Truth::Misses
    );
    // A pentagram winds twice around its centre: inside by the nonzero rule, outside
    // by the even-odd rule. Only there does the truth refuse, naming two crossing edges.
    let star = [
        ["0", "10"],
        ["-6", "-8"],
        ["10", "3"],
        ["-10", "3"],
        ["6", "-8"],
    ];
    match truth(&case2d("1", ["0", "0"], ["0", "0"], &star, &[])) {
        Truth::Undefined { reason } => {
            assert!(reason.contains("winding number is 2"), "{reason}");
            assert!(reason.contains("cross"), "{reason}");
        }
        other => panic!("the pentagram's centre depends on the fill rule: {other:?}"),
    }
    // Its points (winding 1) are inside by both rules.
    assert_eq!(
        entry(&truth(&case2d("1", ["0", "8"], ["0", "0"], &star, &[]))).as_deref(),
        Some("0/1")
    );
}

#[test]
fn simplicity_on_the_lookahead_is_decided_exactly() {
    // The square's corner (10,10) moving by (−20, −20) reaches the opposite corner
    // (0, 0) at t = 1/2: not simple over T = 1, simple over T = 1/4 ((10,10) → (5,5)).
    let vels = [["0", "0"], ["0", "0"], ["-20", "-20"], ["0", "0"]];
    let long = case2d("1", ["20", "20"], ["0", "0"], &SQUARE, &vels);
    let why = simple_on_window(&long).expect_err("the corner crosses the square");
    assert!(why.contains("vertex 2 meets edge"), "{why}");
    assert!(simple_on_window(&case2d("1/4", ["20", "20"], ["0", "0"], &SQUARE, &vels)).is_ok());
    // The truth needs no simplicity: the point at (20, 20) is never touched.
    assert_eq!(truth(&long), Truth::Misses);
    // A bow tie fails at t = 0, naming the crossing edges.
    let bow = [["0", "0"], ["10", "10"], ["10", "0"], ["0", "10"]];
    let why = simple_on_window(&case2d("1", ["20", "20"], ["0", "0"], &bow, &[]))
        .expect_err("a bow tie is not simple");
    assert!(why.contains("edges 0-1 and 2-3 cross"), "{why}");
    // The square at rest or translated is simple throughout.
    assert!(simple_on_window(&case2d("1", ["20", "20"], ["0", "0"], &SQUARE, &[])).is_ok());
}

#[test]
fn truth_3d_windows() {
    // Square at rest; s = (−5, 5, 0) moving (1, 0, 1); slab [10, 20]: window
    // [10, 20]; the point is inside from t = 5 on, so the entry is at t = 10.
    let mk = |bottom: &str, top: &str, vsp: &str| {
        let c = CaseInput {
            lookahead: "30",
            buff: "1/100",
            fac: "1/10000",
            pos: &["-5", "5", "0"],
            vel: &["1", "0", "1"],
            vertices: &SQUARE,
            velocities: &[],
            slab: Some([bottom, top, vsp]),
        };
        truth(&ExactCase::<Q>::new(&c).expect("valid"))
    };
    assert_eq!(entry(&mk("10", "20", "0")).as_deref(), Some("10/1"));
    assert_eq!(entry(&mk("0", "20", "0")).as_deref(), Some("5/1"));
    assert_eq!(mk("20", "30", "0"), Truth::Misses);
    assert_eq!(entry(&mk("15", "15", "0")).as_deref(), Some("15/1"));
    assert_eq!(mk("16", "16", "0"), Truth::Misses);
    assert_eq!(mk("100", "200", "0"), Truth::Misses);
    // Rising slab [−10 + t/2, −5 + t/2] against z = t: t ∈ [−20, −10]: never.
    assert_eq!(mk("-10", "-5", "1/2"), Truth::Misses);
}

#[test]
fn validation_names_fields() {
    let sq = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
    let base = CaseInput {
        lookahead: 10.0,
        buff: 0.01,
        fac: 1e-4,
        pos: &[0.0, 0.0],
        vel: &[0.0, 0.0],
        vertices: &sq,
        velocities: &[],
        slab: None,
    };
    let err = |c: CaseInput<'_, f64>| ExactCase::<Q>::new(&c).err().map(|e| e.field);
    assert_eq!(err(base), None);
    assert_eq!(
        err(CaseInput {
            lookahead: 0.0,
            ..base
        }),
        Some("lookahead")
    );
    assert_eq!(
        err(CaseInput {
            lookahead: f64::NAN,
            ..base
        }),
        Some("lookahead")
    );
    assert_eq!(err(CaseInput { buff: -1.0, ..base }), Some("buff"));
    assert_eq!(err(CaseInput { fac: 1.0, ..base }), Some("fac"));
    assert_eq!(err(CaseInput { fac: 0.0, ..base }), Some("fac"));
    assert_eq!(
        err(CaseInput {
            pos: &[f64::INFINITY, 0.0],
            ..base
        }),
        Some("point.pos")
    );
    assert_eq!(
        err(CaseInput {
            vel: &[0.0, 0.0, 0.0],
            ..base
        }),
        Some("point.vel")
    );
    assert_eq!(
        err(CaseInput {
            vertices: &sq[..2],
            ..base
        }),
        Some("polygon.vertices")
    );
    assert_eq!(
        err(CaseInput {
            velocities: &sq[..3],
            ..base
        }),
        Some("polygon.velocities")
    );
    assert_eq!(
        err(CaseInput {
            slab: Some([0.0, 1.0, 0.0]),
            ..base
        }),
        Some("point.pos")
    );
    assert_eq!(
        err(CaseInput {
            pos: &[0.0, 0.0, 0.0],
            vel: &[0.0, 0.0, 0.0],
            ..base
        }),
        Some("polygon.bottom")
    );
    assert_eq!(
        err(CaseInput {
            slab: Some([0.0, f64::NAN, 0.0]),
            pos: &[0.0, 0.0, 0.0],
            vel: &[0.0, 0.0, 0.0],
            ..base
        }),
        Some("polygon.top")
    );
    let msg = ExactCase::<Q>::new(&CaseInput {
        vertices: &sq[..2],
        ..base
    })
    .err()
    .map(|e| e.to_string());
    assert_eq!(
        msg.as_deref(),
        Some("polygon.vertices: 2 points, at least 3 are needed")
    );
}

#[test]
fn repeated_vertices_and_collapsing_edges() {
    // The square with its corner (10, 0) given twice: the same point set. A point far
    // outside misses (a zero-length edge is not a line through it), a point coming in
    // enters where it would without the repeat, and the repeated corner itself is on
    // the boundary.
    let twice = [
        ["0", "0"],
        ["10", "0"],
        ["10", "0"],
        ["10", "10"],
        ["0", "10"],
    ];
    assert_eq!(
        truth(&case2d("1", ["20", "0"], ["0", "0"], &twice, &[])),
        Truth::Misses
    );
    assert_eq!(
        truth(&case2d("1", ["10", "-5"], ["0", "0"], &twice, &[])),
        Truth::Misses
    );
    assert_eq!(
        entry(&truth(&case2d("10", ["-5", "5"], ["1", "0"], &twice, &[]))).as_deref(),
        Some("5/1")
    );
    assert_eq!(
        entry(&truth(&case2d("1", ["10", "0"], ["0", "0"], &twice, &[]))).as_deref(),
        Some("0/1")
    );
    // Edge (10,0)-(10,10) shrinking to the point (10, 0) at t = 1 (its upper end moving
    // down at 10): undefined from T = 1 on, a miss of a far point before.
    let vels = [["0", "0"], ["0", "0"], ["0", "-10"], ["0", "0"]];
    match truth(&case2d("2", ["30", "30"], ["0", "0"], &SQUARE, &vels)) {
        Truth::Undefined { reason } => assert!(reason.contains("edge 1-2 shrinks"), "{reason}"),
        other => panic!("a collapsing edge: {other:?}"),
    }
    assert_eq!(
        truth(&case2d("1/2", ["30", "30"], ["0", "0"], &SQUARE, &vels)),
        Truth::Misses
    );
}
