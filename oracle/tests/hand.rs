//! Hand-computed exact cases for every paper-A function of the oracle. Each
//! expected answer is derived in the comment above it.

use core::cmp::Ordering;

use polyguard_oracle::contain::{definitely_outside, near_edge, num_cross, perturb};
use polyguard_oracle::detect::{
    detect_3d, detect_diff_2d, detect_same_2d, dot_nn, dot_nn_lin, edge_detect, edge_detect_simp,
    slab_window, Interval,
    Sign::{Neg, Pos},
};
use polyguard_oracle::proximity::segments_close;
use polyguard_oracle::qfield::Alg;
use polyguard_oracle::quad::{quad_min_box_le_d, quad_min_le_d};
use polyguard_oracle::well_formed::{sharp_corner, well_formed};
use polyguard_oracle::{Arith, Decided, Exact, Q, V2};

/// An exact rational from "p/q" (test data is hard-coded and valid).
fn q(s: &str) -> Q {
    polyguard_oracle::convert::parse_rational(s).expect("valid test rational")
}

fn p(x: &str, y: &str) -> V2<Q> {
    V2::new(q(x), q(y))
}

fn poly(pts: &[(&str, &str)]) -> Vec<V2<Q>> {
    pts.iter().map(|(x, y)| p(x, y)).collect()
}

/// The interval's ends compared with rationals (lb, ub).
fn ends_are(iv: &Interval<Alg<Q>>, lb: &str, ub: &str) -> bool {
    match iv {
        Interval::Empty => false,
        Interval::Closed { lb: l, ub: u } => {
            l.cmp_rat(&q(lb)) == Ordering::Equal && u.cmp_rat(&q(ub)) == Ordering::Equal
        }
    }
}

#[test]
fn quad_min_le_d_parabola_with_known_minimum() {
    // (t − 1/2)² = t² − t + 1/4 has its minimum 0 at t = 1/2, and 1/4 at both ends.
    // Below 1/100: yes (step 2: b² − 4a(c − D) = 1 − 4(1/4 − 1/100) = 1/25 > 0).
    assert!(quad_min_le_d(&Exact, &q("1"), &q("-1"), &q("1/4"), &q("1/100")).decided());
    // Below 0: no — the discriminant b² − 4a(c − D) = 1 − 1 is exactly zero (strict test).
    assert!(!quad_min_le_d(&Exact, &q("1"), &q("-1"), &q("1/4"), &q("0")).decided());
    // (t − 2)² on [0, 1]: least value at t = 1, equal to 1: not < 1, but < 1 + 1/1000.
    assert!(!quad_min_le_d(&Exact, &q("1"), &q("-4"), &q("4"), &q("1")).decided());
    assert!(quad_min_le_d(&Exact, &q("1"), &q("-4"), &q("4"), &q("1001/1000")).decided());
    // Concave −t² + t: least values at the ends (0): not < 0.
    assert!(!quad_min_le_d(&Exact, &q("-1"), &q("1"), &q("0"), &q("0")).decided());
}

#[test]
fn quad_min_box_le_d_interior_minimum() {
    // (r − 1/2)² + (t − 1/2)² = r² + t² − r − t + 1/2: a = b = 1, c = 0, d = e = −1,
    // f = 1/2. On the sides the least value is 1/4; inside it is 0 at (1/2, 1/2):
    // disc = −4, mx = my = −2, mx·disc = 8 ∈ [0, 16], value·disc² = 0.
    let (a, b, c, d, e, f) = (q("1"), q("1"), q("0"), q("-1"), q("-1"), q("1/2"));
    assert!(quad_min_box_le_d(&Exact, &a, &b, &c, &d, &e, &f, &q("1/100")).decided());
    assert!(!quad_min_box_le_d(&Exact, &a, &b, &c, &d, &e, &f, &q("0")).decided());
    // Sides only: threshold 1/4 + 1/100 is met by the sides already.
    assert!(quad_min_box_le_d(&Exact, &a, &b, &c, &d, &e, &f, &q("26/100")).decided());
    // disc = c² − 4ab = 0: (r − t)² has its minimum 0 on the diagonal, which the
    // sides reach at the corners: not < 0, and the step-6 test reads 0 < 0.
    assert!(!quad_min_box_le_d(
        &Exact,
        &q("1"),
        &q("1"),
        &q("-2"),
        &q("0"),
        &q("0"),
        &q("0"),
        &q("0")
    )
    .decided());
}

#[test]
fn perturb_moves_exactly_the_vertices_within_buff_of_the_ray() {
    // s = (0, 0), BUFF = 1/10: (1/10, 5) has |dx| = BUFF (≤) → moved by −2/10;
    // (0, −1/10) has y = s_y − BUFF (≥) → moved; (0, −11/100) is too low and
    // (11/100, 3) too far right: unchanged.
    let s = p("0", "0");
    let pts = poly(&[
        ("1/10", "5"),
        ("0", "-1/10"),
        ("0", "-11/100"),
        ("11/100", "3"),
    ]);
    let star = |pts: &[V2<Q>], s: &V2<Q>, buff: &Q| -> Vec<V2<Q>> {
        pts.iter()
            .map(|v| perturb(&Exact, v, s, buff).decided())
            .collect()
    };
    let out = star(&pts, &s, &q("1/10"));
    assert_eq!(
        out,
        poly(&[
            ("-1/10", "5"),
            ("-2/10", "-1/10"),
            ("0", "-11/100"),
            ("11/100", "3")
        ])
    );
}

#[test]
fn near_edge_is_strict_at_exactly_buff() {
    let (a, b) = (p("0", "0"), p("10", "0"));
    let buff = q("1/10");
    // Exactly BUFF above the middle of the edge: distance² = 1/100 = BUFF², not <.
    assert!(!near_edge(&Exact, &a, &b, &p("5", "1/10"), &buff).decided());
    assert!(near_edge(&Exact, &a, &b, &p("5", "99/1000"), &buff).decided());
    // Exactly BUFF from an end point, beyond the edge: (−3/50, 8/100) has
    // distance² 36/10000 + 64/10000 = 1/100 from (0, 0).
    assert!(!near_edge(&Exact, &a, &b, &p("-3/50", "8/100"), &buff).decided());
    assert!(near_edge(&Exact, &a, &b, &p("-3/50", "79/1000"), &buff).decided());
    // Degenerate edge (p_i = p_j): only the end-point test.
    assert!(!near_edge(&Exact, &a, &a, &p("1/10", "0"), &buff).decided());
}

#[test]
fn ray_through_a_vertex_before_and_after_perturbation() {
    // Diamond (5,0), (10,5), (5,10), (0,5); the ray x = 5 from s passes exactly
    // through the vertices (5,0) and (5,10).
    let diamond = poly(&[("5", "0"), ("10", "5"), ("5", "10"), ("0", "5")]);
    let buff = q("1/10");
    // s = (5, −3) below: unperturbed, the half-open rule counts (5,10)→(0,5)
    // [dx = −5, (s − p_i)·(p_j − p_i)^⊥ = −65] and (0,5)→(5,0) [dx = 5, 15]: 2.
    let below = p("5", "-3");
    assert_eq!(num_cross(&Exact, &diamond, &below).decided(), 2);
    // Perturbed: (5,0) and (5,10) move to x = 4.8; the ray now crosses
    // (4.8,0)→(10,5) and (10,5)→(4.8,10) away from any vertex: still 2, outside.
    let star = |pts: &[V2<Q>], s: &V2<Q>| -> Vec<V2<Q>> {
        pts.iter()
            .map(|v| perturb(&Exact, v, s, &buff).decided())
            .collect()
    };
    let moved = star(&diamond, &below);
    assert_eq!(
        moved,
        poly(&[("24/5", "0"), ("10", "5"), ("24/5", "10"), ("0", "5")])
    );
    assert_eq!(num_cross(&Exact, &moved, &below).decided(), 2);
    assert!(definitely_outside(&Exact, &diamond, &below, &buff).decided());
    // s = (5, 3) inside: only (5,10) is perturbed (0 < 3 − BUFF for (5,0)); one crossing.
    let inside = p("5", "3");
    assert_eq!(num_cross(&Exact, &diamond, &inside).decided(), 1);
    let moved = star(&diamond, &inside);
    assert_eq!(num_cross(&Exact, &moved, &inside).decided(), 1);
    assert!(!definitely_outside(&Exact, &diamond, &inside, &buff).decided());
    // Exactly BUFF from the edge (0,5)→(5,0) but outside: not near (strict),
    // so definitely outside. The point (0,0) is at distance 5/√2 — use a point at
    // distance exactly BUFF from the line x + y = 5 with a rational offset:
    // (5/2 − 3/50, 5/2 − 4/50)… has distance (3 + 4)/(50√2), irrational; use
    // the horizontal edge of a square instead.
    let square = poly(&[("0", "0"), ("10", "0"), ("10", "10"), ("0", "10")]);
    assert!(definitely_outside(&Exact, &square, &p("5", "-1/10"), &buff).decided());
    assert!(!definitely_outside(&Exact, &square, &p("5", "-99/1000"), &buff).decided());
}

#[test]
fn segments_close_cases() {
    let buff = q("1/10");
    // Parallel segments exactly BUFF apart: not close (strict); a hair closer: close.
    assert!(!segments_close(
        &Exact,
        &p("0", "0"),
        &p("10", "0"),
        &p("0", "1/10"),
        &p("10", "1/10"),
        &buff
    )
    .decided());
    assert!(segments_close(
        &Exact,
        &p("0", "0"),
        &p("10", "0"),
        &p("0", "99/1000"),
        &p("10", "99/1000"),
        &buff
    )
    .decided());
    // Crossing segments with every end point far away: only step 4 (the interior
    // minimum at r = t = 1/2, found with disc = −64, mx = my = −32) sees it.
    assert!(segments_close(
        &Exact,
        &p("0", "-1"),
        &p("0", "1"),
        &p("-1", "0"),
        &p("1", "0"),
        &q("1/100")
    )
    .decided());
    // Skew segments 1 apart at their closest points.
    assert!(!segments_close(
        &Exact,
        &p("0", "0"),
        &p("1", "0"),
        &p("2", "1"),
        &p("2", "5"),
        &q("1")
    )
    .decided());
}

/// dot_nn_lin's case analysis, one hand case for each shape of the quadratic: the sign
/// of A, the sign of the discriminant, and a linear or constant one.
#[test]
fn dot_nn_lin_every_shape_of_quadratic() {
    let t = q("3");
    let x = |a: &str| p(a, "0");
    // A > 0, two roots: (t − 1)(t − 2) ≥ 0 on [0, 1] ∪ [2, 3].
    let (ww, vv, aa, bb) = (x("-1"), x("1"), x("-2"), x("1"));
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Neg).decided(),
        "0",
        "1"
    ));
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Pos).decided(),
        "2",
        "3"
    ));
    // A > 0, discriminant exactly 0: (t − 1)² ≥ 0 everywhere.
    let (ww, vv, aa, bb) = (x("-1"), x("1"), x("-1"), x("1"));
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Neg).decided(),
        "0",
        "3"
    ));
    // A < 0, two roots: (t − 1)(2 − t) ≥ 0 on [1, 2].
    let (ww, vv, aa, bb) = (x("-1"), x("1"), x("2"), x("-1"));
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Neg).decided(),
        "1",
        "2"
    ));
    assert!(dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Pos)
        .decided()
        .is_empty());
    // A < 0, discriminant exactly 0: −(t − 1)² ≥ 0 only at t = 1.
    let (ww, vv, aa, bb) = (x("-1"), x("1"), x("1"), x("-1"));
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Neg).decided(),
        "1",
        "1"
    ));
    // A < 0, discriminant < 0: (t, 1)·(−t, −1) = −t² − 1 < 0: empty both.
    let (ww, vv, aa, bb) = (p("0", "1"), p("1", "0"), p("0", "-1"), p("-1", "0"));
    assert!(dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Neg)
        .decided()
        .is_empty());
    assert!(dot_nn_lin(&Exact, &t, &ww, &vv, &aa, &bb, Pos)
        .decided()
        .is_empty());
    // A = 0, linear: t − 1 ≥ 0 on [1, 3]; constant −1: empty; constant 0: [0, 3].
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &x("-1"), &x("1"), &x("1"), &x("0"), Neg).decided(),
        "1",
        "3"
    ));
    assert!(
        dot_nn_lin(&Exact, &t, &x("-1"), &x("0"), &x("1"), &x("0"), Neg)
            .decided()
            .is_empty()
    );
    assert!(ends_are(
        &dot_nn_lin(&Exact, &t, &x("0"), &x("0"), &x("1"), &x("0"), Neg).decided(),
        "0",
        "3"
    ));
}

/// dot_nn_lin beyond the case analysis: an irrational root, a leading coefficient far
/// below any epsilon, and a lookahead of 0.
#[test]
fn dot_nn_lin_irrational_root_tiny_coefficient_and_one_instant() {
    let t = q("3");
    let x = |a: &str| p(a, "0");
    // Irrational roots: (1, t)·(−2, t) = t² − 2 ≥ 0 on [√2, 3]; 141/100 < √2 < 142/100.
    let iv = dot_nn_lin(
        &Exact,
        &t,
        &p("1", "0"),
        &p("0", "1"),
        &p("-2", "0"),
        &p("0", "1"),
        Pos,
    )
    .decided();
    match &iv {
        Interval::Closed { lb, ub } => {
            assert_eq!(lb.cmp_rat(&q("141/100")), Ordering::Greater);
            assert_eq!(lb.cmp_rat(&q("142/100")), Ordering::Less);
            assert_eq!(ub.cmp_rat(&t), Ordering::Equal);
        }
        Interval::Empty => panic!("expected [√2, 3]"),
    }
    assert!(dot_nn_lin(
        &Exact,
        &t,
        &p("1", "0"),
        &p("0", "1"),
        &p("-2", "0"),
        &p("0", "1"),
        Neg
    )
    .decided()
    .is_empty());
    // A tiny but nonzero leading coefficient (PolyCARP zeroes |A| < 1e-8):
    // (1, t/10¹⁰)·(−1, t) = t²/10¹⁰ − 1 ≥ 0 from t = 10⁵; lookahead 2·10⁵.
    let big_t = q("200000");
    let iv = dot_nn_lin(
        &Exact,
        &big_t,
        &p("1", "0"),
        &p("0", "1/10000000000"),
        &p("-1", "0"),
        &p("0", "1"),
        Pos,
    )
    .decided();
    assert!(ends_are(&iv, "100000", "200000"));
    // Lookahead 0 (detect_3D with a one-instant window): [0, 0] or empty, never the
    // paper's sentinel (T, 0) = (0, 0) standing for "empty".
    let z = q("0");
    assert!(ends_are(
        &dot_nn_lin(&Exact, &z, &x("0"), &x("0"), &x("1"), &x("0"), Neg).decided(),
        "0",
        "0"
    ));
    assert!(
        dot_nn_lin(&Exact, &z, &x("-1"), &x("0"), &x("1"), &x("0"), Neg)
            .decided()
            .is_empty()
    );
}

#[test]
fn dot_nn_bounds_the_normalised_projection() {
    // ww = (1, 0), vv = 0, aa = (2, 0), bb = 0: f = 2, ‖aa‖² = 4, F = 1/2:
    // |f| ≤ F‖aa‖² = 2 holds (with equality) at every t: f ≤ 2 is dot_nn(σ2 = −1)
    // and −f ≤ 2 is dot_nn(σ2 = +1), each [0, T].
    let t = q("1");
    let (ww, vv, aa, bb) = (p("1", "0"), p("0", "0"), p("2", "0"), p("0", "0"));
    let f = q("1/2");
    assert!(ends_are(
        &dot_nn(&Exact, &t, &ww, &vv, &aa, &bb, Neg, Neg, &f).decided(),
        "0",
        "1"
    ));
    assert!(ends_are(
        &dot_nn(&Exact, &t, &ww, &vv, &aa, &bb, Neg, Pos, &f).decided(),
        "0",
        "1"
    ));
    // F = 1/4: f ≤ 1 fails everywhere.
    let f = q("1/4");
    assert!(dot_nn(&Exact, &t, &ww, &vv, &aa, &bb, Neg, Neg, &f)
        .decided()
        .is_empty());
    assert!(dot_nn(&Exact, &t, &ww, &vv, &aa, &bb, Pos, Neg, &f)
        .decided()
        .is_empty());
}

#[test]
fn edge_detect_static_edge() {
    // Edge (0,0)→(10,0) at rest; s = (5, −1) moving up at speed 1 meets it at t = 1.
    let (a, b, z) = (p("0", "0"), p("10", "0"), p("0", "0"));
    let f = q("1/10000");
    assert!(edge_detect(
        &Exact,
        &q("2"),
        &p("5", "-1"),
        &p("0", "1"),
        &a,
        &b,
        &z,
        &z,
        &f
    )
    .decided());
    // Stopping at t = 1/2, half a unit short: no.
    assert!(!edge_detect(
        &Exact,
        &q("1/2"),
        &p("5", "-1"),
        &p("0", "1"),
        &a,
        &b,
        &z,
        &z,
        &f
    )
    .decided());
    // Beside the edge (x = 11 > 10(1 + F)): no.
    assert!(!edge_detect(
        &Exact,
        &q("2"),
        &p("11", "-1"),
        &p("0", "1"),
        &a,
        &b,
        &z,
        &z,
        &f
    )
    .decided());
    // edge_detect_simp directly: the midpoint frame of the same edge.
    assert!(edge_detect_simp(
        &Exact,
        &q("2"),
        &p("0", "-1"),
        &p("0", "1"),
        &p("5", "0"),
        &p("0", "0"),
        &f
    )
    .decided());
}

/// Paper A Figure 2: a warping edge met twice. A = (0,0) at rest,
/// B(t) = (2, 2 − 2t); the edge lies on y = (1 − t)·x. The point
/// (t, 2/9) meets it when 2/9 = (1 − t)·t, i.e. t = 1/3 and t = 2/3
/// (x = 1/3 and 2/3, inside [0, 2]).
#[test]
fn figure_2_warping_edge_met_twice() {
    let (a, va) = (p("0", "0"), p("0", "0"));
    let (b, vb) = (p("2", "2"), p("0", "-2"));
    let (s, v) = (p("0", "2/9"), p("1", "0"));
    let f = q("1/10000");
    assert!(edge_detect(&Exact, &q("1"), &s, &v, &a, &b, &va, &vb, &f).decided());
    // Until t = 1/4 the point stays ≥ 0.02 from the edge: no.
    assert!(!edge_detect(&Exact, &q("1/4"), &s, &v, &a, &b, &va, &vb, &f).decided());
    // The second meeting alone: start the clock at t = 1/2 (s + v/2, B + vB/2),
    // lookahead 1/2: met at 1/6 (absolute 2/3).
    let s2 = s.at(&v, &q("1/2"));
    let b2 = b.at(&vb, &q("1/2"));
    assert!(edge_detect(&Exact, &q("1/2"), &s2, &v, &a, &b2, &va, &vb, &f).decided());
    assert!(!edge_detect(&Exact, &q("1/7"), &s2, &v, &a, &b2, &va, &vb, &f).decided());
    // The warping triangle A, D = (3, −1), B(t) is simple and CCW on [0, 1]; the
    // point starts outside it and enters at t = 1/3.
    let tri = vec![a.clone(), p("3", "-1"), b.clone()];
    let vels = vec![va.clone(), p("0", "0"), vb.clone()];
    let buff = q("1/100");
    assert!(detect_diff_2d(&Exact, &q("1"), &s, &v, &tri, &vels, &f, &buff).decided());
    assert!(!detect_diff_2d(&Exact, &q("1/4"), &s, &v, &tri, &vels, &f, &buff).decided());
}

#[test]
fn detect_same_2d_square() {
    // Square [0,10]², at rest; s = (−5, 5) moving right at speed 1 reaches x = 0 at t = 5.
    let sq = poly(&[("0", "0"), ("10", "0"), ("10", "10"), ("0", "10")]);
    let vels = vec![p("0", "0"); 4];
    let (s, v) = (p("-5", "5"), p("1", "0"));
    let buff = q("1/100");
    assert!(detect_same_2d(&Exact, &q("10"), &s, &v, &sq, &vels, &buff).decided());
    // At T = 4.99 the path ends at (−1/100, 5), exactly BUFF from the left edge.
    // Yet detect_same_2D says true: P*_BUFF (taken around s + T·v) moves (0, 10)
    // to (−2/100, 10), and the perturbed edge (−2/100, 10)→(0, 0) passes through
    // (−1/100, 5) itself, so near_edge on P*_BUFF fires (a false alarm made by
    // the perturbation, allowed by the paper: it only errs on the safe side).
    assert!(detect_same_2d(&Exact, &q("499/100"), &s, &v, &sq, &vels, &buff).decided());
    // From below, no vertex is within BUFF of the ray: s = (5, −5) moving up ends
    // at (5, −1/100), exactly BUFF below the bottom edge: not close (strict).
    let (s, v) = (p("5", "-5"), p("0", "1"));
    assert!(!detect_same_2d(&Exact, &q("499/100"), &s, &v, &sq, &vels, &buff).decided());
    assert!(detect_same_2d(&Exact, &q("4991/1000"), &s, &v, &sq, &vels, &buff).decided());
    // The square moving down at speed 1 instead, the point at rest: same meeting.
    let moving = vec![p("0", "-1"); 4];
    assert!(detect_same_2d(&Exact, &q("5"), &s, &p("0", "0"), &sq, &moving, &buff).decided());
    assert!(
        !detect_same_2d(&Exact, &q("499/100"), &s, &p("0", "0"), &sq, &moving, &buff).decided()
    );
}

#[test]
fn detect_3d_slab_windows() {
    // Square [0,10]² at rest; s = (−5, 5) moving right at speed 1 (inside the
    // square for t ∈ [5, 15]); height z = t.
    let sq = poly(&[("0", "0"), ("10", "0"), ("10", "10"), ("0", "10")]);
    let vels = vec![p("0", "0"); 4];
    let (s, v) = (p("-5", "5"), p("1", "0"));
    let (sz, vz, zero) = (q("0"), q("1"), q("0"));
    let (buff, f, t) = (q("1/100"), q("1/10000"), q("30"));
    let d3 = |bottom: &str, top: &str, vsp: &str| {
        detect_3d(
            &Exact,
            &t,
            &s,
            &v,
            &sz,
            &vz,
            &sq,
            &vels,
            &q(bottom),
            &q(top),
            &q(vsp),
            &buff,
            &f,
        )
        .decided()
    };
    // Slab [10, 20]: window t ∈ [10, 20], x ∈ [5, 15]: inside at t = 10.
    assert_eq!(
        slab_window(&Exact, &t, &sz, &vz, &q("10"), &q("20"), &zero).decided(),
        Some((q("10"), q("20")))
    );
    assert!(d3("10", "20", "0"));
    // Slab [20, 30]: window [20, 30], x ∈ [15, 25]: always 5 or more outside.
    assert!(!d3("20", "30", "0"));
    // One-instant windows (lookahead b − a = 0): at t = 10 (x = 5, inside), at
    // t = 16 (x = 11, one unit outside).
    assert!(d3("10", "10", "0"));
    assert!(!d3("16", "16", "0"));
    // No window at all within [0, 30]: false (not a 2D run with lookahead −T).
    assert_eq!(
        slab_window(&Exact, &t, &sz, &vz, &q("100"), &q("200"), &zero).decided(),
        None
    );
    assert!(!d3("100", "200", "0"));
    // A sinking slab [40 − 2t, 50 − 2t] and a level point at z = 0: t ∈ [20, 25].
    assert_eq!(
        slab_window(&Exact, &t, &zero, &zero, &q("40"), &q("50"), &q("-2")).decided(),
        Some((q("20"), q("25")))
    );
    // A warping polygon in 3D goes through detect_diff_2D: the square's right
    // side stretching, window [10, 20].
    let warp = vec![p("0", "0"), p("1", "0"), p("1", "0"), p("0", "0")];
    assert!(detect_3d(
        &Exact,
        &t,
        &s,
        &v,
        &sz,
        &vz,
        &sq,
        &warp,
        &q("10"),
        &q("20"),
        &zero,
        &buff,
        &f
    )
    .decided());
}

#[test]
fn well_formed_cases() {
    let cos_k = q("9/10"); // κ ≈ 25.8°
    let buff = q("1/100");
    let sq = poly(&[("0", "0"), ("10", "0"), ("10", "10"), ("0", "10")]);
    assert!(well_formed(&sq, &buff, &cos_k));
    // Clockwise: the lexicographic minimum (0,0) turns right.
    let cw: Vec<V2<Q>> = sq.iter().rev().cloned().collect();
    assert!(!well_formed(&cw, &buff, &cos_k));
    // A spike: the corner at (100, 0) is atan(1/100) ≈ 0.57° < κ.
    assert!(!well_formed(
        &poly(&[("0", "0"), ("100", "0"), ("0", "1")]),
        &buff,
        &cos_k
    ));
    // Two vertices 1/100 apart (< 2·BUFF).
    let close = poly(&[
        ("0", "0"),
        ("10", "0"),
        ("10", "10"),
        ("1/100", "10"),
        ("0", "10"),
    ]);
    assert!(!well_formed(&close, &buff, &cos_k));
    // A vertex 1/200 above the non-adjacent bottom edge: not well formed with
    // BUFF = 1/100, well formed with BUFF = 1/1000 (corners ≥ 26.6° > κ).
    let dent = poly(&[
        ("0", "0"),
        ("10", "0"),
        ("10", "10"),
        ("5", "1/200"),
        ("0", "10"),
    ]);
    assert!(!well_formed(&dent, &buff, &cos_k));
    assert!(well_formed(&dent, &q("1/1000"), &cos_k));
    // A right angle is not sharper than κ = 90° (cos κ = 0): 0 < 0 is false;
    // a 45° corner is sharper than κ = 60° (cos κ = 1/2), not than κ = 30°.
    assert!(!sharp_corner(&p("1", "0"), &p("0", "1"), &q("0")));
    assert!(sharp_corner(&p("1", "0"), &p("-1", "1"), &q("1/2")));
    assert!(!sharp_corner(&p("1", "0"), &p("-1", "1"), &q("866/1000")));
    // Exactly 45° with cos κ = cos 45° is impossible to write rationally; the
    // squared comparison 1/2 vs (cos κ)² is exact either side: 7071/10000 < √2/2.
    assert!(sharp_corner(&p("1", "0"), &p("-1", "1"), &q("7071/10000")));
    assert!(!sharp_corner(&p("1", "0"), &p("-1", "1"), &q("7072/10000")));
}

#[test]
fn field_helpers() {
    assert_eq!(Q::from_i64(3).half(), q("3/2"));
    assert_eq!(q("1/3").quotient(&q("0")), None);
}
