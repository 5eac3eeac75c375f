use super::*;
use core::cmp::Ordering;
use polyguard_oracle::recovery as oracle;
use polyguard_oracle::Q as BigRational;
use proptest::prelude::*;

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}

fn square() -> Vec<Vect2> {
    vec![v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)]
}

/// The L-shape with its reflex vertex at (2, 2).
fn ell() -> Vec<Vect2> {
    vec![
        v(0.0, 0.0),
        v(4.0, 0.0),
        v(4.0, 2.0),
        v(2.0, 2.0),
        v(2.0, 4.0),
        v(0.0, 4.0),
    ]
}

fn arr(p: &[Vect2]) -> Vec<oracle::Point> {
    p.iter().map(|w| pt(*w)).collect()
}

fn pt(w: Vect2) -> oracle::Point {
    [q(w.x), q(w.y)]
}

fn q(x: f64) -> BigRational {
    polyguard_oracle::convert::q(x).expect("finite")
}

/// The scale S of the module doc.
fn scale(p: &[Vect2], s: Vect2, d: f64) -> f64 {
    let m = p.iter().fold(0.0f64, |m, w| {
        m.max((w.x - s.x).abs()).max((w.y - s.y).abs())
    });
    m.max(d).max(s.x.abs()).max(s.y.abs())
}

/// Checks an engine answer against the oracle: the condition exactly, the bounds
/// min_lo ≤ m ≤ |x − s| ≤ dist_hi, and the gap within the stated tolerance.
fn check(p: &[Vect2], vels: &[Vect2], t: f64, s: Vect2, d: f64, out: bool) {
    let (pa, va, sa, ta, da) = (arr(p), arr(vels), pt(s), q(t), q(d));
    let (got, exact) = match (out, vels.is_empty()) {
        (true, true) => (recovery_out(p, s, d), oracle::recovery_out(&pa, &sa, &da)),
        (false, true) => (recovery_in(p, s, d), oracle::recovery_in(&pa, &sa, &da)),
        (true, false) => (
            recovery_out_at(p, vels, t, s, d),
            oracle::recovery_out_at(&pa, &va, &ta, &sa, &da),
        ),
        (false, false) => (
            recovery_in_at(p, vels, t, s, d),
            oracle::recovery_in_at(&pa, &va, &ta, &sa, &da),
        ),
    };
    let exact = exact.expect("finite inputs");
    match (got, exact) {
        (
            Ok(Recovery::Point {
                x,
                dist_hi,
                min_lo,
                clear,
            }),
            oracle::ExactRecovery::Min(m),
        ) => {
            let ok = if out {
                oracle::satisfies_out(&pa, &va, &ta, &pt(x), &da)
            } else {
                oracle::satisfies_in(&pa, &va, &ta, &pt(x), &da)
            };
            assert!(ok, "x = {x:?} breaks the condition");
            assert_ne!(m.cmp_rational(&q(min_lo)), Ordering::Less, "min_lo above m");
            let (dx, dy) = (q(x.x) - q(s.x), q(x.y) - q(s.y));
            assert!(
                &dx * &dx + &dy * &dy <= q(dist_hi) * q(dist_hi),
                "|x − s| > dist_hi"
            );
            assert!(
                dist_hi - min_lo <= REL_TOL * scale(&at(p, vels, t), s, d),
                "gap {} at scale {}",
                dist_hi - min_lo,
                scale(p, s, d)
            );
            // clear is certified: s is then exactly feasible.
            assert!(!clear || m.zero);
        }
        (Ok(Recovery::Impossible { .. }), oracle::ExactRecovery::Impossible) => {}
        (g, e) => panic!("engine {g:?}, oracle {e:?}"),
    }
}

fn at(p: &[Vect2], vels: &[Vect2], t: f64) -> Vec<Vect2> {
    if vels.is_empty() {
        return p.to_vec();
    }
    p.iter().zip(vels).map(|(a, w)| a.at(*w, t)).collect()
}

fn point(r: Result<Recovery, RecoveryError>) -> (Vect2, f64, f64) {
    match r {
        Ok(Recovery::Point {
            x, dist_hi, min_lo, ..
        }) => (x, dist_hi, min_lo),
        other => panic!("{other:?}"),
    }
}

#[test]
fn square_from_the_centre_goes_out_by_one_and_a_half() {
    let (x, hi, lo) = point(recovery_out(&square(), v(1.0, 1.0), 0.5));
    assert!(lo <= 1.5 && 1.5 <= hi && hi - lo <= REL_TOL * scale(&square(), v(1.0, 1.0), 0.5));
    // One of the four sides' points at 1/2 beyond the middle of an edge.
    assert!((x - v(1.0, 1.0)).sq() >= 2.25);
    check(&square(), &[], 0.0, v(1.0, 1.0), 0.5, true);
}

#[test]
fn points_already_clear_stay() {
    let r = recovery_out(&square(), v(5.0, 5.0), 0.5);
    assert_eq!(
        r,
        Ok(Recovery::Point {
            x: v(5.0, 5.0),
            dist_hi: 0.0,
            min_lo: 0.0,
            clear: true
        })
    );
    let r = recovery_in(&square(), v(1.0, 1.0), 0.5);
    assert!(matches!(r, Ok(Recovery::Point { clear: true, .. })));
}

#[test]
fn outside_near_an_edge_and_near_a_corner() {
    // Beside the right edge: straight out to x = 2.5.
    let (x, hi, _) = point(recovery_out(&square(), v(2.2, 1.0), 0.5));
    assert!((x - v(2.5, 1.0)).sq().sqrt() <= REL_TOL * 2.5 && hi >= 0.3);
    check(&square(), &[], 0.0, v(2.2, 1.0), 0.5, true);
    // Beside the corner (2, 2): along the diagonal to the circle of radius 1.
    check(&square(), &[], 0.0, v(2.1, 2.1), 1.0, true);
    check(&square(), &[], 0.0, v(2.1, 2.3), 1.0, true);
}

#[test]
fn into_the_core_from_outside_goes_to_its_corner() {
    let (x, _, _) = point(recovery_in(&square(), v(-1.0, -1.0), 0.5));
    assert!((x - v(0.5, 0.5)).sq().sqrt() <= REL_TOL * 3.0);
    check(&square(), &[], 0.0, v(-1.0, -1.0), 0.5, false);
    check(&square(), &[], 0.0, v(1.9, 0.3), 0.5, false);
}

#[test]
fn concave_corner_is_where_two_shifted_edges_meet() {
    // Near the reflex vertex (2, 2) of the L: the circle's point (2.71, 2.71) is 0.71
    // from the edge x = 2, so the nearest clear point is (3, 3), where the edges
    // y = 2 and x = 2 shifted by 1 meet: 0.9·√2 away.
    let (x, hi, lo) = point(recovery_out(&ell(), v(2.1, 2.1), 1.0));
    assert!((x - v(3.0, 3.0)).sq().sqrt() <= REL_TOL * 4.0, "{x:?}");
    let want = 0.9 * 2f64.sqrt();
    // want is rounded twice: within 4 ulps of 0.9·√2.
    let ulps = 1.0 + 4.0 * f64::EPSILON;
    assert!(lo <= want * ulps && want <= hi * ulps);
    check(&ell(), &[], 0.0, v(2.1, 2.1), 1.0, true);
    check(&ell(), &[], 0.0, v(2.5, 2.5), 1.0, true);
    // Into the L's 1/2-core from beyond its reflex corner.
    check(&ell(), &[], 0.0, v(3.0, 3.0), 0.5, false);
}

#[test]
fn thin_polygon_has_no_core() {
    let thin = vec![v(0.0, 0.0), v(10.0, 0.0), v(10.0, 0.5), v(0.0, 0.5)];
    assert!(matches!(
        recovery_in(&thin, v(5.0, 0.25), 0.3),
        Ok(Recovery::Impossible { .. })
    ));
    check(&thin, &[], 0.0, v(5.0, 0.25), 0.3, false);
    // 0.25 is its inradius: the core is the segment y = 0.25, x ∈ [0.25, 9.75]. A point
    // on it is clear, exactly; from beside it, the rounded candidate cannot be certified
    // on a core of zero width, and the engine says so rather than guess.
    check(&thin, &[], 0.0, v(5.0, 0.25), 0.25, false);
    assert_eq!(
        recovery_in(&thin, v(5.0, 0.1), 0.25),
        Err(RecoveryError::Uncertified)
    );
}

#[test]
fn moving_square_at_time_t() {
    let vels = vec![v(0.1, 0.0); 4];
    // At t = 3 the square is [0.3, 2.3] × [0, 2] (rounded vertices covered).
    check(&square(), &vels, 3.0, v(2.4, 1.0), 0.5, true);
    check(&square(), &vels, 3.0, v(0.2, 1.0), 0.5, false);
    let warping = vec![v(0.1, 0.0), v(0.3, -0.1), v(0.0, 0.7), v(-0.2, 0.1)];
    check(&square(), &warping, 1.7, v(1.1, 0.9), 0.4, true);
    check(&square(), &warping, 1.7, v(3.1, 0.9), 0.4, false);
}

#[test]
fn bad_inputs_name_their_field() {
    let e = recovery_out(&square(), v(1.0, 1.0), -1.0).unwrap_err();
    assert_eq!(e.field(), "sep");
    let e = recovery_in(&square(), v(f64::NAN, 1.0), 1.0).unwrap_err();
    assert_eq!(e.field(), "s");
    let e = recovery_out(&square(), v(1.0, 1.0), f64::INFINITY).unwrap_err();
    assert_eq!(e.field(), "sep");
    let vels = vec![v(0.0, 0.0); 4];
    let e = recovery_out_at(&square(), &vels, f64::NAN, v(1.0, 1.0), 1.0).unwrap_err();
    assert_eq!(e.field(), "t");
    let e = recovery_out_at(&square(), &vels[..3], 1.0, v(1.0, 1.0), 1.0).unwrap_err();
    assert_eq!(e.field(), "vels");
    let mut cw = square();
    cw.reverse();
    assert_eq!(
        recovery_out(&cw, v(1.0, 1.0), 1.0),
        Err(RecoveryError::NotCounterclockwise)
    );
    assert!(recovery_out(&square()[..2], v(1.0, 1.0), 1.0).is_err());
}

/// A star-shaped polygon about (cx, cy): sorted angles, random radii (simple, ccw,
/// with reflex vertices where a radius dips). Consecutive angles are less than π apart
/// (for a triangle too), so the centre is inside and the ring runs counterclockwise.
fn star() -> impl Strategy<Value = Vec<Vect2>> {
    (
        prop::collection::vec((0.0f64..1.0, 0.3f64..3.0), 3..8),
        -2.0f64..2.0,
        -2.0f64..2.0,
    )
        .prop_map(|(raw, cx, cy)| {
            let n = raw.len();
            let spread = if n == 3 { 0.3 } else { 0.8 };
            raw.iter()
                .enumerate()
                .map(|(i, &(a, r))| {
                    let ang = (i as f64 + (1.0 - spread) / 2.0 + spread * a)
                        * core::f64::consts::TAU
                        / n as f64;
                    v(cx + r * ang.cos(), cy + r * ang.sin())
                })
                .collect()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn random_polygons_agree_with_the_oracle(
        p in star(),
        sx in -4.0f64..4.0,
        sy in -4.0f64..4.0,
        d in 0.0f64..1.5,
    ) {
        let s = v(sx, sy);
        check(&p, &[], 0.0, s, d, true);
        check(&p, &[], 0.0, s, d, false);
    }
}

#[test]
fn zero_separation_is_containment() {
    // Out with D = 0: every point is clear. In with D = 0: the nearest point of P.
    let r = recovery_out(&square(), v(1.0, 1.0), 0.0);
    assert!(matches!(r, Ok(Recovery::Point { clear: true, .. })));
    check(&square(), &[], 0.0, v(-1.0, 0.5), 0.0, false);
    // From far below a triangle, into it: the nearest point of P is its vertex C, which
    // must be pushed into P (along the inward bisector) to be certified.
    let tri = vec![
        v(-0.9245876690546373, 0.8156091667960288),
        v(-1.8513649712107147, -1.6368068874980566),
        v(-0.17514818540671184, -3.069559486709352),
    ];
    check(
        &tri,
        &[],
        0.0,
        v(-0.0004396781031328345, -5.49200035913006),
        0.0,
        false,
    );
    let quad = vec![v(0.0, 0.0), v(3.0, 0.5), v(2.5, 2.0), v(0.2, 1.5)];
    check(&quad, &[], 0.0, v(4.0, 3.0), 0.0, false);
    check(&quad, &[], 0.0, v(1.0, -1.0), 0.0, false);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20))]

    /// Moving (warping) polygons at a time t (half of them at t = 0, static), and points
    /// on or near a vertex or an edge.
    #[test]
    fn moving_polygons_and_near_points_agree_with_the_oracle(
        p in star(),
        vel in prop::collection::vec((-0.3f64..0.3, -0.3f64..0.3), 8),
        t in prop_oneof![Just(0.0), 0.0f64..3.0],
        k in 0usize..8,
        along in prop::sample::select(vec![0.0, 0.5, 0.25]),
        off in prop::sample::select(vec![0.0, 0.3, -0.3, 1e-9]),
        d in prop::sample::select(vec![0.1, 0.5, 1.0]),
    ) {
        let n = p.len();
        // Small shears only, so that the polygon stays simple and counterclockwise.
        let vels: Vec<Vect2> = vel[..n].iter().map(|&(x, y)| v(x * 0.1, y * 0.1)).collect();
        // Twice the signed area at t, in f64: the shears keep it well above 0.
        let q = at(&p, &vels, t);
        let area: f64 = (0..n).map(|i| q[i].x * q[(i + 1) % n].y - q[i].y * q[(i + 1) % n].x).sum();
        prop_assume!(area > 0.01);
        let (a, b) = (p[k % n], p[(k + 1) % n]);
        let e = b - a;
        let s = a + e.scale(along) + e.perp().scale(off);
        check(&p, &vels, t, s, d, true);
        check(&p, &vels, t, s, d, false);
    }
}

#[test]
fn far_from_the_origin_and_small_separations() {
    // The L moved to (10⁶, −3·10⁵), with D a millionth of its size and s near its reflex
    // corner: candidates and certificates work in coordinates relative to s.
    let off = v(1.0e6, -3.0e5);
    let p: Vec<Vect2> = ell().iter().map(|&w| w + off).collect();
    for d in [1e-6, 0.25] {
        let s = v(2.0, 2.0) + off + v(d / 3.0, d / 5.0);
        check(&p, &[], 0.0, s, d, true);
        check(&p, &[], 0.0, s, d, false);
    }
    // s exactly on a vertex, and exactly D from an edge.
    check(&ell(), &[], 0.0, v(2.0, 2.0), 0.5, true);
    check(&ell(), &[], 0.0, v(2.0, 2.0), 0.5, false);
    check(&square(), &[], 0.0, v(2.5, 1.0), 0.5, true);
    check(&square(), &[], 0.0, v(1.5, 1.0), 0.5, false);
}

/// A 16 × 16 square 1.1·10¹¹ from s (the regression corpus's `slab-end-rounds-up`,
/// tests/regressions/crafted.jsonl): its orientation is exact in f64, but twice its area
/// about s (about 512) is lost in products near 10²² of the coordinates relative to s,
/// which refused it as not counterclockwise. At rest and moving, it is answered: s is
/// already clear.
#[test]
fn a_small_polygon_far_from_s_is_counterclockwise() {
    let p = vec![
        v(109_951_162_778.6, -8.0),
        v(109_951_162_794.6, -8.0),
        v(109_951_162_794.6, 8.0),
        v(109_951_162_778.6, 8.0),
    ];
    let s = v(0.0, 0.0);
    for r in [
        recovery_out(&p, s, 0.5),
        recovery_out_at(&p, &[v(0.0, 0.0); 4], 1.0, s, 0.5),
        recovery_out_at(&p, &[v(1.0, 0.5); 4], 2.0, s, 0.5),
    ] {
        assert!(
            matches!(r, Ok(Recovery::Point { clear: true, .. })),
            "{r:?}"
        );
    }
}
