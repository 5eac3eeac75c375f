//! Tests of paper A §II.B–E (contain.rs): perturbation, near_edge, the ray crossings and
//! definitely_outside, on hand cases and against their definitions.

use super::*;

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}
const SQUARE: [Vect2; 4] = [
    Vect2::new(0.0, 0.0),
    Vect2::new(4.0, 0.0),
    Vect2::new(4.0, 4.0),
    Vect2::new(0.0, 4.0),
];

/// The shortcut "every vertex certainly above BUFF" (skip_margin) must not fire for a
/// point just below an edge within BUFF, nor for one just beside a side: in the
/// frame at t = 0 ([`AtTime`]) and in the shifted frame ([`Shifted`]). The margin
/// is BUFF plus the rounding bound, never less (a mutation-test survivor: a margin
/// of 0 or −1 passed every other test).
#[test]
fn the_all_above_shortcut_keeps_its_margin() {
    for (s, buff) in [
        (v(2.0, -0.5), 1.0),  // 0.5 below the bottom edge, BUFF 1
        (v(2.0, -0.25), 0.5), // likewise, BUFF 0.5
        (v(-0.5, 2.0), 1.0),  // 0.5 left of the left edge
        (v(4.75, 2.0), 1.0),  // 0.75 right of the right edge
        (v(2.0, 4.5), 1.0),   // 0.5 above the top edge: every vertex below the point
    ] {
        assert!(!definitely_outside(&SQUARE[..], s, buff), "{s:?}");
        let at = AtTime {
            p: &SQUARE[..],
            vels: &SQUARE[..],
            s,
            v: Vect2::ZERO,
            t: crate::ball::Ball::exact(0.0),
        };
        assert_eq!(definitely_outside_rel(&at, buff), Tri::No, "{s:?}");
        // The same point reached by a shift: the square moving right by 1 over t = 1,
        // the point too (the relative picture is the one above).
        let shifted = Shifted::new(
            &SQUARE[..],
            s,
            v(1.0, 0.0),
            v(1.0, 0.0),
            crate::ball::Ball::exact(1.0),
        );
        assert_eq!(definitely_outside_rel(&shifted, buff), Tri::No, "{s:?}");
    }
    // Beyond BUFF below (2 below, BUFF 1): certainly outside, in both frames.
    assert!(definitely_outside(&SQUARE[..], v(2.0, -2.0), 1.0));
    let far = Shifted::new(
        &SQUARE[..],
        v(2.0, -2.0),
        v(0.5, 0.0),
        v(0.5, 0.0),
        crate::ball::Ball::exact(3.0),
    );
    assert_eq!(definitely_outside_rel(&far, 1.0), Tri::Yes);
}

/// The frame at a time t ≠ 0 ([`AtTime`]) is P(t) seen from s(t), the same answer as
/// the polygon and point moved there by hand (exact dyadic motion); a frame that
/// forgot the motion (a mutation-test survivor) answers for t = 0 instead.
#[test]
fn the_frame_at_a_time_is_the_moved_scene() {
    let vels = [v(1.0, 0.0), v(1.0, 0.0), v(1.5, 0.5), v(1.0, 0.5)];
    let s = v(9.0, 2.0);
    let sv = v(-1.0, 0.0);
    for (t, inside) in [(0.0, false), (2.0, false), (3.0, true), (4.0, true)] {
        let at = AtTime {
            p: &SQUARE[..],
            vels: &vels[..],
            s,
            v: sv,
            t: crate::ball::Ball::exact(t),
        };
        let moved: Vec<Vect2> = SQUARE
            .iter()
            .zip(&vels)
            .map(|(&p, &w)| p + w.scale(t))
            .collect();
        let by_hand = definitely_outside(&moved[..], s + sv.scale(t), 0.25);
        assert_eq!(by_hand, !inside, "t = {t}");
        let want = if inside { Tri::No } else { Tri::Yes };
        assert_eq!(definitely_outside_rel(&at, 0.25), want, "t = {t}");
    }
}

#[test]
fn perturb_moves_only_vertices_near_the_ray() {
    let s = v(1.0, 1.0);
    // |0 − 1| ≤ 1 and 4 ≥ 1 − 1: moved to (0 − 2, 4).
    assert_eq!(perturb(v(0.0, 4.0), s, 1.0), v(-2.0, 4.0));
    // Exactly at both thresholds (|x − s_x| = BUFF, y = s_y − BUFF): moved.
    assert_eq!(perturb(v(2.0, 0.0), s, 1.0), v(0.0, 0.0));
    // Below s_y − BUFF: stays.
    assert_eq!(perturb(v(1.0, -0.5), s, 1.0), v(1.0, -0.5));
    // Farther than BUFF in x: stays.
    assert_eq!(perturb(v(2.5, 9.0), s, 1.0), v(2.5, 9.0));
}

#[test]
fn near_edge_is_strict_at_exactly_buff() {
    // s = (2, 1) is exactly 1 from the edge (0,0)-(4,0): not nearer than BUFF = 1.
    assert_eq!(
        near_edge_tri(v(0.0, 0.0), v(4.0, 0.0), v(2.0, 1.0), 1.0),
        Tri::No
    );
    assert!(near_edge(v(0.0, 0.0), v(4.0, 0.0), v(2.0, 0.75), 1.0));
    // Beyond the end: distance to (4,0) from (4.5, 0.5) is √0.5 ≈ 0.707.
    assert!(near_edge(v(0.0, 0.0), v(4.0, 0.0), v(4.5, 0.5), 0.75));
    assert!(!near_edge(v(0.0, 0.0), v(4.0, 0.0), v(4.5, 0.5), 0.5));
    // Degenerate segment p_i = p_j: only the end test applies.
    assert!(!near_edge(v(1.0, 1.0), v(1.0, 1.0), v(1.0, 2.0), 1.0));
    assert!(near_edge(v(1.0, 1.0), v(1.0, 1.0), v(1.0, 1.5), 1.0));
}

#[test]
fn near_edge_on_a_long_segment_keeps_its_precision() {
    // A segment 10⁶ long and a point 1e-7 + 2⁻³⁰ beside its middle, BUFF = 1e-7.
    // The paper's quadratic in f64 cancels 10¹² against 10¹² and cannot see 1e-14;
    // the certified form measures the distance to the line directly.
    let (a, b) = (v(-5e5, 0.0), v(5e5, 0.0));
    let buff = 1e-7;
    assert_eq!(near_edge_tri(a, b, v(3.0, buff - 1e-15), buff), Tri::Yes);
    assert_eq!(near_edge_tri(a, b, v(3.0, buff + 1e-15), buff), Tri::No);
}

#[test]
fn ray_through_a_vertex_before_and_after_perturbation() {
    // Triangle with apex (2, 4) straight above s = (2, 1): the ray passes exactly
    // through the apex. Unperturbed: one crossing ((2,4)→(0,0)); perturbed (BUFF
    // 0.1) the apex moves to (1.8, 4) and (4,0)→(1.8,4) crosses instead: again one.
    let tri = [v(0.0, 0.0), v(4.0, 0.0), v(2.0, 4.0)];
    let s = v(2.0, 1.0);
    assert_eq!(num_cross(&tri[..], s), 1);
    let star = Perturbed {
        poly: &tri[..],
        s,
        buff: 0.1,
    };
    assert_eq!(star.vertex(2), v(1.8, 4.0));
    assert_eq!(num_cross(&star, s), 1);
    assert!(!definitely_outside(&tri[..], s, 0.1)); // inside: odd count
    assert!(definitely_outside(&tri[..], v(2.0, 5.0), 0.1));
}

#[test]
fn outside_pentagon_whose_vertex_0_is_on_the_ray() {
    // tests/regressions/assure-seed7.jsonl, false_alarm_far-2861536 (an LLVM 22
    // miscompile read vertex 0 as (0.73, 0) on the last edge): s is outside.
    let p = [
        v(0.73, 0.2),
        v(-0.3, -0.5),
        v(0.04, -0.7),
        v(0.3, -0.5),
        v(0.5, -0.3),
    ];
    let s = v(0.73, 0.005);
    assert!(definitely_outside(&p[..], s, 0.01));
    assert!(!near_edge(p[4], p[0], s, 0.01));
    assert!(near_edge(p[4], v(0.73, 0.0), s, 0.01));
    assert!(!definitely_outside(&p[..], v(0.6, 0.05), 0.01));
}

#[test]
fn definitely_outside_square() {
    let sq = &SQUARE[..];
    assert!(!definitely_outside(sq, v(2.0, 2.0), 0.1)); // inside
    assert!(definitely_outside(sq, v(6.0, 2.0), 0.1)); // outside
    assert!(definitely_outside(sq, v(2.0, -1.0), 0.1)); // below: ray crosses twice
    assert!(!definitely_outside(sq, v(4.05, 2.0), 0.1)); // within BUFF of the edge
    assert!(definitely_outside(sq, v(4.5, 2.0), 0.5)); // exactly BUFF away
    assert!(!definitely_outside(sq, v(4.25, 2.0), 0.5));
}

/// A frame that counts its ball computations ([`RelPoly::rel`]): the work that
/// §II.E's shortcuts are there to save.
struct Counting<'a, R> {
    inner: &'a R,
    rels: core::cell::Cell<usize>,
}

impl<'a, R: RelPoly> Counting<'a, R> {
    fn new(inner: &'a R) -> Self {
        Counting {
            inner,
            rels: core::cell::Cell::new(0),
        }
    }
}

impl<R: RelPoly> RelPoly for Counting<'_, R> {
    fn count(&self) -> usize {
        self.inner.count()
    }
    fn rel(&self, i: usize) -> BallV {
        self.rels.set(self.rels.get() + 1);
        self.inner.rel(i)
    }
    fn terms(&self, i: usize) -> Option<Terms> {
        self.inner.terms(i)
    }
    fn at(&self, i: usize) -> Vect2 {
        self.inner.at(i)
    }
    fn skip_margin(&self, buff: f64) -> Option<f64> {
        self.inner.skip_margin(buff)
    }
}

/// §II.E's shortcuts do their work: a point 1.5·BUFF or 10⁶ beyond a side of the
/// polygon's bounding box, on any of the four sides, is answered `Yes` without a
/// single ball computation, in the frame at t = 0 and in the shifted frame. 1.5·BUFF
/// lies between the margins BUFF·(1 + 4u) (or BUFF + the shift's slack) and BUFF + 1
/// or 5·BUFF, so a margin off by a term or a factor shows; a frame whose `at` or
/// `skip_margin` stopped answering shows too. (Mutation-test survivors: each of these
/// left every answer unchanged, only slower.)
#[test]
fn the_shortcuts_skip_what_is_far() {
    for d in [1.5, 1e6] {
        for (s, side) in [
            (v(-d, 2.0), "left: every edge skipped"),
            (v(4.0 + d, 2.0), "right: every edge skipped"),
            (v(2.0, 4.0 + d), "above: every edge skipped"),
            (v(2.0, -d), "below: the all-above shortcut"),
        ] {
            let at = AtTime {
                p: &SQUARE[..],
                vels: &SQUARE[..],
                s,
                v: Vect2::ZERO,
                t: crate::ball::Ball::exact(0.0),
            };
            let counted = Counting::new(&at);
            assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::Yes, "{side}");
            assert_eq!(counted.rels.get(), 0, "t = 0, {side}, d = {d}");
            // The square and the point both moving right by 1 over t = 1.
            let shifted = Shifted::new(
                &SQUARE[..],
                s,
                v(1.0, 0.0),
                v(1.0, 0.0),
                crate::ball::Ball::exact(1.0),
            );
            let counted = Counting::new(&shifted);
            assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::Yes, "{side}");
            assert_eq!(counted.rels.get(), 0, "shifted, {side}, d = {d}");
        }
    }
    // Within BUFF the edges are computed: the shortcut is not a blanket.
    let at = AtTime {
        p: &SQUARE[..],
        vels: &SQUARE[..],
        s: v(-0.5, 2.0),
        v: Vect2::ZERO,
        t: crate::ball::Ball::exact(0.0),
    };
    let counted = Counting::new(&at);
    assert_eq!(definitely_outside_rel(&counted, 1.0), Tri::No);
    assert!(counted.rels.get() > 0);
}

/// At a time t ≠ 0 the vertex's computed position carries the rounding of t·(v_i − v),
/// up to half an ulp of the product: no margin of the t = 0 kind holds, and the
/// per-edge skip must widen BUFF by the balls' radii. Crafted: x = 2⁵³ + 2 +
/// t·W with W = −(2⁵³ − 1), t = 1 + 2⁻⁵², so exactly x = 1 + 2⁻⁵², while fl(t·W) = −2⁵³
/// and the computed x is 2. With BUFF 1.5 the square's left side is within BUFF of the
/// point (exactly), yet computed beyond 1.5·(1 + 4u). (Mutation-test survivors: a
/// t = 0 margin for every exact time, and BUFF − radius for BUFF + radius.)
#[test]
fn a_moved_frame_keeps_its_rounding_in_the_skip() {
    let left = 9_007_199_254_740_994.0; // 2⁵³ + 2
    let (side, half) = (1_048_576.0, 524_288.0); // 2²⁰, 2¹⁹
    let p = [
        v(left, -half),
        v(left + side, -half),
        v(left + side, half),
        v(left, half),
    ];
    let w = v(-9_007_199_254_740_991.0, 0.0); // −(2⁵³ − 1)
    let vels = [w; 4];
    let t = 1.0 + f64::EPSILON;
    assert_eq!(
        w.x * t,
        -9_007_199_254_740_992.0,
        "the product rounds as designed"
    );
    let at = AtTime {
        p: &p[..],
        vels: &vels[..],
        s: Vect2::ZERO,
        v: Vect2::ZERO,
        t: crate::ball::Ball::exact(t),
    };
    assert_eq!(at.at(0).x, 2.0, "the computed left side");
    assert_ne!(definitely_outside_rel(&at, 1.5), Tri::Yes);
}

/// §II.C's filter decides what the ball tests cannot: two balls of radius 4 with their
/// centres BUFF + 4 beyond BUFF's box on one side, or exactly at the filter's bound (a
/// tie: every point of the segment is then at distance ≥ BUFF, and near_edge is
/// strict), are `No` on each of the four sides, while the end and interior tests on
/// the same balls are `Unsure`. (Mutation-test survivors: a filter weakened to `==`,
/// `&&` or a strict comparison changed no answer the other tests saw.)
#[test]
fn the_near_edge_filter_decides_far_balls() {
    let (buff, r) = (1.0, 4.0);
    let bound = crate::ball::up(buff + r);
    for x in [bound, 10.0] {
        for (a, b) in [
            (v(x, -3.0), v(x, 1e3)),   // both right of the point
            (v(-x, -3.0), v(-x, 1e3)), // left
            (v(-3.0, x), v(1e3, x)),   // above
            (v(-3.0, -x), v(1e3, -x)), // below
        ] {
            let (a, b) = (BallV { v: a, r }, BallV { v: b, r });
            assert_eq!(near_edge_rel(a, b, buff, || None), Tri::No, "{a:?} {b:?}");
            let ends = pr::closer_than(a, buff, || None).or(pr::closer_than(b, buff, || None));
            let unfiltered = ends.or(pr::interior_closer_than(a, b, buff, || None));
            assert_eq!(unfiltered, Tri::Unsure, "the filter is what decides {a:?}");
        }
    }
    // One end on the near side of the bound: the filter does not fire.
    let (a, b) = (
        BallV {
            v: v(bound, -3.0),
            r,
        },
        BallV {
            v: v(bound * (1.0 - f64::EPSILON), 1e3),
            r,
        },
    );
    assert_eq!(near_edge_rel(a, b, buff, || None), Tri::Unsure);
}

/// The margins are closed: vertices exactly at the margin M (computed as the frame
/// computes it) are skipped, in the all-above shortcut and in the per-edge skip, with
/// no ball computed; M is strict on its own (see [`RelPoly::skip_margin`]).
#[test]
fn the_shortcut_margins_are_closed() {
    let buff = 1.0;
    let zero = crate::ball::Ball::exact(0.0);
    let probe = AtTime {
        p: &SQUARE[..],
        vels: &SQUARE[..],
        s: Vect2::ZERO,
        v: Vect2::ZERO,
        t: zero,
    };
    let m = probe.skip_margin(buff).expect("t = 0 has a margin");
    assert!(m > buff);
    // A square [m, m + 4] × [−2, 2] right of the point, and one [−2, 2] × [m, m + 4]
    // above the point (every vertex above: the all-above shortcut).
    let right: Vec<Vect2> = SQUARE.iter().map(|q| v(q.x + m, q.y - 2.0)).collect();
    let above: Vec<Vect2> = SQUARE.iter().map(|q| v(q.x - 2.0, q.y + m)).collect();
    for (poly, what) in [(&right, "per-edge skip"), (&above, "all-above shortcut")] {
        let at = AtTime {
            p: &poly[..],
            vels: &poly[..],
            s: Vect2::ZERO,
            v: Vect2::ZERO,
            t: zero,
        };
        let q = at.at(0); // (m, −2) or (−2, m): the tie is exact
        assert!(q.x == m || q.y == m, "{q:?}");
        let counted = Counting::new(&at);
        assert_eq!(definitely_outside_rel(&counted, buff), Tri::Yes, "{what}");
        assert_eq!(
            counted.rels.get(),
            0,
            "{what}: a vertex exactly at M is skipped"
        );
    }
}

/// An empty vertex list: definitely outside, with no vertex read (the shortcuts must
/// not look at a vertex 0 that is not there).
#[test]
fn an_empty_polygon_is_outside_and_reads_no_vertex() {
    let none: [Vect2; 0] = [];
    assert!(definitely_outside(&none[..], v(1.0, 2.0), 1.0));
}

/// A time known only as a ball around 0 (a slab window's start that underflowed to 0,
/// with its error radius r) still carries the motion: every position at a time in
/// [−r, r] is in the vertex's ball. Crafted with exact dyadics: velocity 2⁹⁰⁰, r =
/// 2⁻⁹⁰⁰, so the vertex (1, 1) can be anywhere in x ∈ [0, 2]. (A mutation-test
/// survivor returned the t = 0 position for such a ball.)
#[test]
fn a_time_ball_around_zero_carries_the_motion() {
    let big = 2f64.powi(900);
    let p = [v(1.0, 1.0), v(3.0, 1.0), v(3.0, 3.0)];
    let vels = [v(big, 0.0); 3];
    let t = crate::ball::Ball {
        z: 0.0,
        r: 1.0 / big,
    };
    let at = AtTime {
        p: &p[..],
        vels: &vels[..],
        s: Vect2::ZERO,
        v: Vect2::ZERO,
        t,
    };
    for (i, q) in p.iter().enumerate() {
        let b = at.rel(i);
        for x in [q.x - 1.0, q.x + 1.0] {
            // the position at t = ∓r, exactly
            assert!((b.v.x - x).abs() <= b.r, "vertex {i}: {b:?} misses x = {x}");
        }
    }
    // Such a frame has no exact terms (its time is not a float), so it cannot claim
    // "definitely outside" from the t = 0 picture: the triangle 3 beyond the point at
    // t = 0 (BUFF 1) sweeps x by ±4 within the ball and covers the point at t = −r.
    let far = [v(3.0, -1.0), v(5.0, -1.0), v(5.0, 1.0)];
    let vels = [v(4.0 * big, 0.0); 3];
    let at = AtTime {
        p: &far[..],
        vels: &vels[..],
        s: Vect2::ZERO,
        v: Vect2::ZERO,
        t,
    };
    assert!(at.terms(0).is_none());
    assert_ne!(definitely_outside_rel(&at, 1.0), Tri::Yes);
}

/// §II.B–C: a perturbed vertex keeps its exact terms. The triangle (0, −20),
/// (4, −2), (0, −5) seen from the point, BUFF 4:
/// - (4, −2) lies in the perturbation strip (|4| ≤ 4, −2 ≥ −4) and moves to (−4, −2);
/// - the perturbed edge to (0, −5) is then exactly BUFF from the point
///   (|(−4, −2) × (4, −3)| / 5 = 4, its foot inside the edge), as is the unperturbed
///   edge from (4, −2);
/// - every other edge is farther, and the triangle stays below the point, so the
///   ray crosses nothing.
///
/// The balls cannot tell the ties; exactly, near_edge is strict, so the point is
/// definitely outside. Terms shifted by −2/BUFF instead of −2·BUFF put the vertex at
/// (3.5, −2), whose edge passes within BUFF. That shift is the same when BUFF = 1,
/// so it survived mutation testing.
#[test]
fn a_perturbed_vertex_keeps_its_exact_terms() {
    let s = v(0.5, 0.25);
    let tri: Vec<Vect2> = [v(0.0, -20.0), v(4.0, -2.0), v(0.0, -5.0)]
        .iter()
        .map(|&q| q + s)
        .collect();
    assert!(definitely_outside(&tri[..], s, 4.0));
}

/// A perturbed vertex moves by exactly 2·BUFF, in its ball and in its exact terms.
/// With BUFF = 3/4, (0.75, −0.5) moves to (−0.75, −0.5), and its perturbed edge to
/// (2.25, −1.75) touches the circle of radius BUFF (the foot of the perpendicular
/// inside the edge): exactly BUFF from the point, a tie that only the exact terms
/// decide, so the point is still definitely outside (the other edges stay farther).
/// Terms moved by −2 + BUFF instead (a mutation-test survivor, the same as −2·BUFF
/// at BUFF = 2, as −2/BUFF is at BUFF = 1) put the vertex at (−0.5, −0.5), and that
/// edge's interior within BUFF.
#[test]
fn a_perturbed_vertex_moves_by_two_buff() {
    let s = v(0.5, 0.25);
    let tri: Vec<Vect2> = [v(3.0, -6.0), v(2.25, -1.75), v(0.75, -0.5)]
        .iter()
        .map(|&q| q + s)
        .collect();
    assert!(definitely_outside(&tri[..], s, 0.75));
    // At t = 3, polygon and point moving alike: the same scene, with the frame's
    // vertices as balls (p + 3·v − s − 3·v carries a rounding bound).
    let vels = [v(1.0, 0.0); 3];
    let at = AtTime {
        p: &tri[..],
        vels: &vels[..],
        s,
        v: v(1.0, 0.0),
        t: crate::ball::Ball::exact(3.0),
    };
    assert!(at.rel(2).r > 0.0, "a ball, not an exact vertex");
    assert_eq!(definitely_outside_rel(&at, 0.75), Tri::Yes);
}

#[test]
fn a_perturbed_edge_within_an_ulp_of_buff_is_decided_on_the_moved_vertex() {
    // BUFF = 1/2 and the point at the origin. a = (1/4, y0) with y0 = −(1/2 − 2⁻⁵⁴)
    // is moved by §II.B (|a_x| ≤ BUFF, a_y ≥ −BUFF) to a* = (−3/4, y0); the edge
    // a* b, along y = y0, passes 1/2 − 2⁻⁵⁴ < BUFF below the point, so s is not
    // definitely outside. The unmoved edge a b keeps its distance ‖a‖ > 0.55. The gap
    // 2⁻⁵⁴ is below the balls' resolution: only the exact terms of a*, with their
    // −2·BUFF term, see it.
    let y0 = -(0.5 - 2f64.powi(-54));
    let tri = [v(0.25, y0), v(2.0, y0), v(1.0, -3.0)];
    assert!(!definitely_outside(&tri[..], v(0.0, 0.0), 0.5));
    // One ulp of y0 further down the edge is exactly BUFF away: not closer, and the
    // point is outside (the ray from it meets no edge).
    assert!(definitely_outside(
        &[v(0.25, -0.5), v(2.0, -0.5), v(1.0, -3.0)][..],
        v(0.0, 0.0),
        0.5
    ));
}

/// A frame of given balls and no exact terms: what a frame at an inexact time looks
/// like to §II.E.
struct Balls(Vec<BallV>);

impl RelPoly for Balls {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn rel(&self, i: usize) -> BallV {
        self.0[i]
    }
    fn terms(&self, _: usize) -> Option<Terms> {
        None
    }
    fn at(&self, i: usize) -> Vect2 {
        self.0[i].v
    }
    fn skip_margin(&self, _: f64) -> Option<f64> {
        None
    }
}

/// §II.B–E: an undecided perturbation leaves P*_BUFF unknown, so the answer cannot be
/// "definitely outside". The triangle (0.9, −1 ± 0.01), (5, 3), (3, −6) seen from the
/// point, BUFF 1:
/// - every edge of P is certainly farther than BUFF (1.34, 4.2, 1.35);
/// - vertex 0 is perturbed exactly when its y ≥ −1, which the ball cannot tell, and
///   its perturbed edge to (5, 3) passes 0.23 from the point.
///
/// So for some exact inputs in the balls the point is not definitely outside: `No` or
/// `Unsure`, never `Yes`. Reading "one end undecided" as "not perturbed" (a
/// mutation-test survivor: `||` → `&&`) answered `Yes`.
#[test]
fn an_undecided_perturbation_is_not_outside() {
    let tri = Balls(vec![
        BallV {
            v: v(0.9, -1.0),
            r: 0.01,
        },
        BallV::exact(v(5.0, 3.0)),
        BallV::exact(v(3.0, -6.0)),
    ]);
    assert_eq!(pr::perturbs(tri.rel(0), || None, 1.0), Tri::Unsure);
    assert_ne!(definitely_outside_rel(&tri, 1.0), Tri::Yes);
}

mod masks {
    //! definitely_outside (§II.E) answers on masks ([`crate::lanes`]) as one edge at a
    //! time, with every kernel, at t = 0 and in the shifted frame.
    use super::*;
    use crate::ball::Ball;
    use crate::lanes::tests::{case, check_cases, Case};
    #[cfg(target_arch = "x86_64")]
    use crate::lanes::Avx;
    use crate::lanes::{Kernel, Portable};
    use proptest::prelude::*;

    /// A frame without [`RelPoly::frame`]: definitely_outside_rel runs its scalar loop.
    struct NoFrame<'a, R>(&'a R);

    impl<R: RelPoly> RelPoly for NoFrame<'_, R> {
        fn count(&self) -> usize {
            self.0.count()
        }
        fn rel(&self, i: usize) -> BallV {
            self.0.rel(i)
        }
        fn terms(&self, i: usize) -> Option<Terms> {
            self.0.terms(i)
        }
        fn at(&self, i: usize) -> Vect2 {
            self.0.at(i)
        }
        fn skip_margin(&self, buff: f64) -> Option<f64> {
            self.0.skip_margin(buff)
        }
    }

    /// definitely_outside_rel on masks with kernel `k`, as the masked path calls it.
    fn masked<R: RelPoly, K: Kernel>(p: &R, buff: f64, k: K) -> Option<Tri> {
        let (m, f) = (p.skip_margin(buff)?, p.frame()?);
        Some(outside_masked(p, &f, m, buff, k))
    }

    /// definitely_outside (§II.E) on masks, with each kernel, answers as the scalar loop,
    /// at t = 0 and in the shifted frame at T.
    #[test]
    fn definitely_outside_on_masks_is_the_scalar_answer() {
        check_cases(case(), outside_same);
    }

    fn outside_same((b, verts, s, v, v0, t): Case) -> Result<(), TestCaseError> {
        let at0 = AtTime {
            p: &verts[..],
            vels: &verts[..],
            s,
            v,
            t: Ball::exact(0.0),
        };
        let shifted = Shifted::new(&verts[..], s, v, v0, Ball::exact(t));
        for (scalar, dispatched, portable, k) in [
            (
                definitely_outside_rel(&NoFrame(&at0), b),
                definitely_outside_rel(&at0, b),
                masked(&at0, b, Portable),
                0,
            ),
            (
                definitely_outside_rel(&NoFrame(&shifted), b),
                definitely_outside_rel(&shifted, b),
                masked(&shifted, b, Portable),
                1,
            ),
        ] {
            prop_assert_eq!(dispatched, scalar, "frame {}", k);
            prop_assert_eq!(portable, Some(scalar), "frame {}", k);
        }
        #[cfg(target_arch = "x86_64")]
        if let Some(avx) = Avx::new() {
            prop_assert_eq!(
                masked(&at0, b, avx),
                Some(definitely_outside_rel(&NoFrame(&at0), b))
            );
            prop_assert_eq!(
                masked(&shifted, b, avx),
                Some(definitely_outside_rel(&NoFrame(&shifted), b))
            );
        }
        Ok(())
    }
}

/// The frames' [`RelPoly::frame`] computes what their [`RelPoly::at`] does, bit for bit.
#[test]
fn a_frame_is_its_at() {
    let verts = [v(0.1, 0.7), v(3.3, -1e-310), v(-2.9, 1e300)];
    let (s, vel, v0) = (v(0.3, 0.2), v(0.7, -0.1), v(-0.3, 1.1));
    let t0 = crate::ball::Ball::exact(0.0);
    let at0 = AtTime {
        p: &verts[..],
        vels: &verts[..],
        s,
        v: vel,
        t: t0,
    };
    let shifted = Shifted::new(&verts[..], s, vel, v0, crate::ball::Ball::exact(0.7));
    let bits = |q: Vect2| (q.x.to_bits(), q.y.to_bits());
    for k in 0..3 {
        assert_eq!(at0.frame().map(|f| bits(f.at(k))), Some(bits(at0.at(k))));
        assert_eq!(
            shifted.frame().map(|f| bits(f.at(k))),
            Some(bits(shifted.at(k)))
        );
    }
    // At a time other than 0 each vertex moves by its own velocity: no frame.
    let t1 = crate::ball::Ball::exact(1.0);
    assert!(AtTime {
        p: &verts[..],
        vels: &verts[..],
        s,
        v: vel,
        t: t1
    }
    .frame()
    .is_none());
}
