//! The exact sets of times (oracle/src/intervals, oracle/src/fence.rs): hand-checked
//! answers (a crossing, a concave polygon entered twice, a corner at distance D, a
//! warping edge sweeping over the point twice, a 3D exit through the ceiling, a graze
//! at exactly D), agreement with the ground truth (`truth`: S of Inside is empty exactly
//! when the truth misses, and starts at its entry time), agreement with direct exact
//! evaluation of each relation at sampled times, and keep-in exit detection agreeing
//! with the breach set.

mod common;

use core::cmp::Ordering;

use num_bigint::BigInt;
use proptest::prelude::*;

use common::{cases, gen_case};
use polyguard_oracle::algebraic::{Poly, RealAlg};
use polyguard_oracle::truth::in_closed_polygon;
use polyguard_oracle::{
    detect_exit_of, intervals, intervals_of, truth, Arith, Decided, Exact, ExactCase, ExactTime,
    Heights, Relation, Separation, Truth, Q, V2,
};

fn q(p: i64, d: i64) -> Q {
    Q::new(BigInt::from(p), BigInt::from(d))
}

fn qi(p: i64) -> Q {
    Q::from_i64(p)
}

fn pt(x: i64, y: i64) -> V2<Q> {
    V2::new(qi(x), qi(y))
}

fn square() -> Vec<V2<Q>> {
    vec![pt(0, 0), pt(10, 0), pt(10, 10), pt(0, 10)]
}

fn still(n: usize) -> Vec<V2<Q>> {
    vec![pt(0, 0); n]
}

fn sep(d: Q, h: Q) -> Separation<Q> {
    Separation { d, h }
}

/// A component's ends as rationals (they must be rational).
fn rational_ends(c: &[(RealAlg, RealAlg)]) -> Vec<(String, String)> {
    c.iter()
        .map(|(a, b)| (a.exact_text(), b.exact_text()))
        .collect()
}

/// a + b·√d as a RealAlg.
fn surd(a: i64, b: i64, d: i64) -> RealAlg {
    RealAlg::from(&ExactTime::new(qi(a), qi(b), qi(d)))
}

#[test]
fn a_point_crossing_a_square() {
    let (s, v) = (pt(-5, 5), pt(1, 0));
    let p = square();
    let got = intervals(
        &qi(30),
        &s,
        &v,
        &p,
        &still(4),
        None,
        Relation::Inside,
        &Separation::none(),
    );
    let got = got.expect("defined");
    assert_eq!(rational_ends(&got), vec![("5/1".into(), "15/1".into())]);
    assert!(got[0].0.is_rational() && got[0].1.is_rational());
    // Breach with D = 1: outside, or within 1 of the boundary: everything but (6, 14).
    let b = intervals(
        &qi(30),
        &s,
        &v,
        &p,
        &still(4),
        None,
        Relation::Breach,
        &sep(qi(1), qi(0)),
    );
    assert_eq!(
        rational_ends(&b.expect("defined")),
        vec![("0/1".into(), "6/1".into()), ("14/1".into(), "30/1".into())]
    );
    // The same crossing seen from a polygon translating the other way: twice as fast.
    let vels = vec![pt(-1, 0); 4];
    let t = intervals(
        &qi(30),
        &s,
        &v,
        &p,
        &vels,
        None,
        Relation::Inside,
        &Separation::none(),
    );
    assert_eq!(
        rational_ends(&t.expect("defined")),
        vec![("5/2".into(), "15/2".into())]
    );
}

#[test]
fn a_concave_polygon_is_entered_twice() {
    // A U open upwards; the point crosses both arms at y = 5.
    let u = vec![
        pt(0, 0),
        pt(10, 0),
        pt(10, 10),
        pt(7, 10),
        pt(7, 3),
        pt(3, 3),
        pt(3, 10),
        pt(0, 10),
    ];
    let got = intervals(
        &qi(30),
        &pt(-5, 5),
        &pt(1, 0),
        &u,
        &still(8),
        None,
        Relation::Inside,
        &Separation::none(),
    );
    assert_eq!(
        rational_ends(&got.expect("defined")),
        vec![("5/1".into(), "8/1".into()), ("12/1".into(), "15/1".into())]
    );
    // Near with D = 2 joins them: the gap x ∈ (3, 7) is within 2 of an arm only
    // for x ≤ 5 or x ≥ 5, i.e. everywhere; it starts at x = −2 and ends at x = 12.
    let near = intervals(
        &qi(30),
        &pt(-5, 5),
        &pt(1, 0),
        &u,
        &still(8),
        None,
        Relation::Near,
        &sep(qi(2), qi(0)),
    );
    assert_eq!(
        rational_ends(&near.expect("defined")),
        vec![("3/1".into(), "17/1".into())]
    );
}

#[test]
fn near_a_corner_ends_at_a_vertex_distance_root() {
    // Along y = −1, D = 2: within 2 of the corner (0, 0) from x = −√3, of the corner
    // (10, 0) up to x = 10 + √3: t from 5 − √3 to 15 + √3.
    let got = intervals(
        &qi(30),
        &pt(-5, -1),
        &pt(1, 0),
        &square(),
        &still(4),
        None,
        Relation::Near,
        &sep(qi(2), qi(0)),
    )
    .expect("defined");
    assert_eq!(got.len(), 1);
    assert_eq!(got[0].0, surd(5, -1, 3));
    assert_eq!(got[0].1, surd(15, 1, 3));
    assert!(
        got[0].0.exact_text().starts_with("root of t^2 − 10t + 22"),
        "{}",
        got[0].0
    );
    assert_eq!(got[0].0.to_decimal_string(6), "3.267949");
    // It never is inside; and the polygon is not entered.
    let inside = intervals(
        &qi(30),
        &pt(-5, -1),
        &pt(1, 0),
        &square(),
        &still(4),
        None,
        Relation::Inside,
        &Separation::none(),
    );
    assert_eq!(inside, Ok(vec![]));
}

/// The triangle a(t) = (−2 + t, −1), b(t) = (2 − 2t, −1 + 2t), c = (−20, 13) and the
/// point at rest at the origin: g = (x − a) × (b − a) = −2t² + 7t − 4, so the edge ab
/// sweeps over the point at (7 ∓ √17)/4 ≈ 0.72, 2.78 (out, then in again).
fn sweeping_triangle() -> (Vec<V2<Q>>, Vec<V2<Q>>) {
    (
        vec![pt(-2, -1), pt(2, -1), pt(-20, 13)],
        vec![pt(1, 0), pt(-2, 2), pt(0, 0)],
    )
}

#[test]
fn a_warping_edge_sweeps_over_the_point_twice() {
    let (p, vels) = sweeping_triangle();
    let origin = pt(0, 0);
    let inside = intervals(
        &qi(3),
        &origin,
        &origin,
        &p,
        &vels,
        None,
        Relation::Inside,
        &Separation::none(),
    )
    .expect("defined");
    assert_eq!(inside.len(), 2);
    assert_eq!(inside[0].0, RealAlg::from_i64(0));
    assert_eq!(
        inside[0].1,
        RealAlg::from(&ExactTime::new(q(7, 4), q(-1, 4), qi(17)))
    );
    assert_eq!(
        inside[1].0,
        RealAlg::from(&ExactTime::new(q(7, 4), q(1, 4), qi(17)))
    );
    assert_eq!(inside[1].1, RealAlg::from_i64(3));
    // Near with D = 1/10: the inner ends move outward to the roots of the quartic
    // g² − D²·|b − a|², with b − a = (4 − 3t, 2t).
    let d = q(1, 10);
    let near = intervals(
        &qi(3),
        &origin,
        &origin,
        &p,
        &vels,
        None,
        Relation::Near,
        &sep(d, qi(0)),
    )
    .expect("defined");
    assert_eq!(near.len(), 2);
    let g = Poly::from_i64s(&[-4, 7, -2]);
    let e2 = Poly::from_i64s(&[16, -24, 13]); // (4 − 3t)² + (2t)²
    let quartic = g.mul(&g).scale(&BigInt::from(100)).sub(&e2);
    for end in [&near[0].1, &near[1].0] {
        assert_eq!(end.sign_of(&quartic), Ordering::Equal, "{end}");
        assert!(end.exact_text().contains("t^4"), "{end}");
    }
    assert!(near[0].1 > inside[0].1 && near[1].0 < inside[1].0);
    // Breach with D = 1/10 is the complement of the strictly-inside-by-more-than-D
    // times: from the first quartic root to the second.
    let breach = intervals(
        &qi(3),
        &origin,
        &origin,
        &p,
        &vels,
        None,
        Relation::Breach,
        &sep(q(1, 10), qi(0)),
    )
    .expect("defined");
    assert_eq!(breach.len(), 1);
    assert!(breach[0].0 < inside[0].1 && breach[0].1 > inside[1].0);
    assert_eq!(breach[0].0.sign_of(&quartic), Ordering::Equal);
}

#[test]
fn leaving_through_the_ceiling() {
    // At (5, 5) inside the square, rising from z = 0 at 1 per second; slab [−10, 10].
    let z = Heights {
        sz: qi(0),
        vz: qi(1),
        bottom: qi(-10),
        top: qi(10),
        vsp: qi(0),
    };
    let run = |rel, d: i64, h: i64| {
        intervals(
            &qi(30),
            &pt(5, 5),
            &pt(0, 0),
            &square(),
            &still(4),
            Some(&z),
            rel,
            &sep(qi(d), qi(h)),
        )
        .expect("defined")
    };
    assert_eq!(
        rational_ends(&run(Relation::Inside, 0, 0)),
        vec![("0/1".into(), "10/1".into())]
    );
    assert_eq!(
        rational_ends(&run(Relation::Near, 0, 2)),
        vec![("0/1".into(), "12/1".into())]
    );
    // Breach with H = 2: from z = top − H = 8 on (the point stays 5 from the edges).
    assert_eq!(
        rational_ends(&run(Relation::Breach, 1, 2)),
        vec![("8/1".into(), "30/1".into())]
    );
    // With D = 5 the point is at distance exactly D from the edges: breached from 0.
    assert_eq!(
        rational_ends(&run(Relation::Breach, 5, 2)),
        vec![("0/1".into(), "30/1".into())]
    );
    // A slab sinking at 1/2 per second under a point at rest at z = 0: the ceiling
    // 10 − t/2 meets z + H = 2 at t = 16.
    let sinking = Heights {
        sz: qi(0),
        vz: qi(0),
        bottom: qi(-10),
        top: qi(10),
        vsp: q(-1, 2),
    };
    let b = intervals(
        &qi(30),
        &pt(5, 5),
        &pt(0, 0),
        &square(),
        &still(4),
        Some(&sinking),
        Relation::Breach,
        &sep(qi(1), qi(2)),
    )
    .expect("defined");
    assert_eq!(rational_ends(&b), vec![("16/1".into(), "30/1".into())]);
}

#[test]
fn a_graze_at_exactly_d_is_one_point() {
    // The line 3x + 4y = −25 is 5 from the corner (0, 0) and farther from the rest of
    // the square; the point runs along it and is closest at t = 5, at (−3, −4).
    let (s, v) = (pt(-23, 11), pt(4, -3));
    let near = intervals(
        &qi(10),
        &s,
        &v,
        &square(),
        &still(4),
        None,
        Relation::Near,
        &sep(qi(5), qi(0)),
    )
    .expect("defined");
    assert_eq!(rational_ends(&near), vec![("5/1".into(), "5/1".into())]);
    // Just less than 5: nothing; just more: an interval around 5.
    let less = intervals(
        &qi(10),
        &s,
        &v,
        &square(),
        &still(4),
        None,
        Relation::Near,
        &sep(q(4999, 1000), qi(0)),
    );
    assert_eq!(less, Ok(vec![]));
    let more = intervals(
        &qi(10),
        &s,
        &v,
        &square(),
        &still(4),
        None,
        Relation::Near,
        &sep(q(5001, 1000), qi(0)),
    )
    .expect("defined");
    assert_eq!(more.len(), 1);
    assert!(more[0].0 < RealAlg::from_i64(5) && more[0].1 > RealAlg::from_i64(5));
    // D = 0: a graze of a vertex is an isolated contact too.
    let touch = intervals(
        &qi(10),
        &pt(-5, 5),
        &pt(1, -1),
        &square(),
        &still(4),
        None,
        Relation::Inside,
        &Separation::none(),
    )
    .expect("defined");
    assert_eq!(rational_ends(&touch), vec![("5/1".into(), "5/1".into())]);
}

#[test]
fn undefined_when_the_fill_rule_decides() {
    // A doubly wound square (the outline run twice): winding number 2 inside.
    let twice: Vec<V2<Q>> = square().into_iter().cycle().take(8).collect();
    let got = intervals(
        &qi(30),
        &pt(-5, 5),
        &pt(1, 0),
        &twice,
        &still(8),
        None,
        Relation::Inside,
        &Separation::none(),
    );
    assert!(got.is_err(), "{got:?}");
    // Bad inputs.
    let bad = intervals(
        &qi(0),
        &pt(-5, 5),
        &pt(1, 0),
        &square(),
        &still(4),
        None,
        Relation::Inside,
        &Separation::none(),
    );
    assert!(bad.is_err());
    let bad = intervals(
        &qi(1),
        &pt(-5, 5),
        &pt(1, 0),
        &square(),
        &still(4),
        None,
        Relation::Near,
        &sep(qi(-1), qi(0)),
    );
    assert!(bad.is_err());
}

// ------------------------------------------------------------ generated cases

/// Whether the rational τ lies in one of the components.
fn member(c: &[(RealAlg, RealAlg)], tau: &Q) -> bool {
    c.iter().any(|(a, b)| {
        a.cmp_rational(tau) != Ordering::Greater && b.cmp_rational(tau) != Ordering::Less
    })
}

/// The exact squared distance from x to the segment a b.
fn seg_dist2(x: &V2<Q>, a: &V2<Q>, b: &V2<Q>) -> Q {
    let e = b.minus(a);
    let qv = x.minus(a);
    let e2 = e.sq();
    if e2 == qi(0) {
        return qv.sq();
    }
    let r = qv.dot(&e) / &e2;
    let r = if r < qi(0) {
        qi(0)
    } else if r > qi(1) {
        qi(1)
    } else {
        r
    };
    qv.minus(&e.scale(&r)).sq()
}

/// Each relation at the rational time τ, evaluated directly and exactly.
fn relation_at(c: &ExactCase<Q>, rel: Relation, s: &Separation<Q>, tau: &Q) -> bool {
    let poly: Vec<V2<Q>> = c
        .vertices
        .iter()
        .zip(&c.velocities)
        .map(|(p, w)| p.at(w, tau))
        .collect();
    let x = c.s.at(&c.v, tau);
    let n = poly.len();
    let inside = in_closed_polygon(&Exact, &poly, &x).decided();
    let dist2 = (0..n)
        .map(|i| seg_dist2(&x, &poly[i], &poly[(i + 1) % n]))
        .min()
        .unwrap_or_else(|| qi(0));
    let d2 = s.d.sq();
    let (lo, hi) = match &c.vertical {
        None => (true, true),
        Some(z) => {
            // u = z − bottom, w = top − z, against 0, −H or H.
            let h = z.sz.plus(&z.vz.times(tau));
            let u = h.minus(&z.bottom.plus(&z.vsp.times(tau)));
            let w = z.top.plus(&z.vsp.times(tau)).minus(&h);
            match rel {
                Relation::Inside => (u >= qi(0), w >= qi(0)),
                Relation::Near => (&u + &s.h >= qi(0), &w + &s.h >= qi(0)),
                Relation::Breach => (u > s.h, w > s.h),
            }
        }
    };
    match rel {
        Relation::Inside => inside && lo && hi,
        Relation::Near => (inside || dist2 <= d2) && lo && hi,
        Relation::Breach => !(inside && dist2 > d2 && lo && hi),
    }
}

/// A rational strictly between two different algebraic numbers a < b.
fn between(a: &RealAlg, b: &RealAlg) -> Q {
    let (mut a, mut b) = (a.clone(), b.clone());
    while a.bounds().1 >= b.bounds().0 {
        a.refine();
        b.refine();
    }
    (a.bounds().1 + b.bounds().0) / qi(2)
}

fn separations(seed: u64) -> Separation<Q> {
    let d = [qi(0), q(1, 8), q(1, 2), qi(2)][(seed % 4) as usize].clone();
    let h = [qi(0), qi(1), qi(3)][((seed / 4) % 3) as usize].clone();
    sep(d, h)
}

/// The components are sorted, disjoint, in [0, T], and each relation holds at a
/// sampled time exactly when it holds by direct evaluation: at a grid of times,
/// strictly inside each component and strictly between components.
fn check_against_direct(c: &ExactCase<Q>, rel: Relation, s: &Separation<Q>) -> Result<(), String> {
    let Ok(got) = intervals_of(c, rel, s) else {
        return Ok(());
    };
    for (a, b) in &got {
        if a > b
            || a.cmp_rational(&qi(0)) == Ordering::Less
            || b.cmp_rational(&c.lookahead) == Ordering::Greater
        {
            return Err(format!("bad component {a} .. {b}"));
        }
    }
    if got.windows(2).any(|w| w[0].1 >= w[1].0) {
        return Err(format!("not disjoint: {got:?}"));
    }
    let steps = 24i64;
    let mut times: Vec<Q> = (0..=steps).map(|k| &c.lookahead * q(k, steps)).collect();
    times.extend(
        got.iter()
            .filter(|(a, b)| a < b)
            .map(|(a, b)| between(a, b)),
    );
    times.extend(got.windows(2).map(|w| between(&w[0].1, &w[1].0)));
    for tau in &times {
        if member(&got, tau) != relation_at(c, rel, s, tau) {
            return Err(format!("{} at {tau}: {got:?}", rel.name()));
        }
    }
    Ok(())
}

/// A random case in binary floats, every horizontal length (and D, returned) times
/// 2^k: a star-shaped counterclockwise polygon of 3 to 16 vertices at rest,
/// translating or warping, the point aimed at its centre, at a vertex or off it, in 2D
/// or with a slab.
fn float_case(seed: u64, k: i32) -> (ExactCase<Q>, Q) {
    let mut g = common::Rng::new(seed);
    let mut u = |lo: f64, hi: f64| lo + (hi - lo) * (g.next() >> 11) as f64 / (1u64 << 53) as f64;
    let s2 = 2f64.powi(k);
    let n = 3 + (u(0.0, 14.0) as usize);
    let size = 10f64.powf(u(-3.0, 3.0));
    let (cx, cy) = (u(-1e3, 1e3) * size, u(-1e3, 1e3) * size);
    let verts: Vec<[f64; 2]> = (0..n)
        .map(|j| {
            let a = (j as f64 + u(0.1, 0.9)) * std::f64::consts::TAU / n as f64;
            let r = size * u(0.5, 1.0);
            [cx + r * a.cos(), cy + r * a.sin()]
        })
        .collect();
    let t = 10f64.powf(u(-2.0, 3.0));
    let motion = u(0.0, 3.0) as u32;
    let base = [u(-1.0, 1.0) * size / t, u(-1.0, 1.0) * size / t];
    let vels: Vec<[f64; 2]> = (0..n)
        .map(|_| match motion {
            0 => [0.0, 0.0],
            1 => base,
            _ => [
                base[0] + u(-0.2, 0.2) * size / t,
                base[1] + u(-0.2, 0.2) * size / t,
            ],
        })
        .collect();
    let ang = u(0.0, std::f64::consts::TAU);
    let start = [cx + 3.0 * size * ang.cos(), cy + 3.0 * size * ang.sin()];
    let aim = match u(0.0, 3.0) as u32 {
        0 => [cx, cy],
        1 => verts[0],
        _ => [
            cx + 2.0 * size * (ang + 1.0).cos(),
            cy + 2.0 * size * (ang + 1.0).sin(),
        ],
    };
    let hit = t * u(0.1, 0.9);
    let vel = [
        (aim[0] - start[0]) / hit + base[0],
        (aim[1] - start[1]) / hit + base[1],
    ];
    let d = [0.0, size * 1e-3, size * 0.1, size][u(0.0, 4.0) as usize];
    let slab = (u(0.0, 1.0) < 0.3).then(|| [u(-10.0, 0.0), u(0.0, 10.0), u(-1.0, 1.0) / t]);
    let sc = |p: [f64; 2]| [p[0] * s2, p[1] * s2];
    let verts: Vec<[f64; 2]> = verts.into_iter().map(sc).collect();
    let vels: Vec<[f64; 2]> = vels.into_iter().map(sc).collect();
    let (pos, velv) = (sc(start), sc(vel));
    let (pos3, vel3) = (
        [pos[0], pos[1], u(-10.0, 10.0)],
        [velv[0], velv[1], u(-1.0, 1.0) / t],
    );
    let (p, v): (&[f64], &[f64]) = if slab.is_some() {
        (&pos3, &vel3)
    } else {
        (&pos, &velv)
    };
    let c = ExactCase::new(&polyguard_oracle::CaseInput {
        lookahead: t,
        buff: 0.01,
        fac: 1e-4,
        pos: p,
        vel: v,
        vertices: &verts,
        velocities: &vels,
        slab,
    })
    .expect("a valid case");
    let d = polyguard_oracle::convert::f64_to_exact::<Q>(d * s2).expect("finite");
    (c, d)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(400)))]

    // Inside's set is empty exactly when the truth misses, and starts at its entry time.
    #[test]
    fn inside_agrees_with_the_truth(seed in any::<u64>()) {
        let g = gen_case(seed);
        let Ok(c) = g.exact::<Q>() else { return Ok(()) };
        let got = intervals_of(&c, Relation::Inside, &Separation::none());
        match (truth(&c), got) {
            (Truth::Undefined { .. }, got) => prop_assert!(got.is_err(), "truth undefined, intervals {got:?}: {g:?}"),
            (_, Err(_)) => {}
            (Truth::Misses, Ok(s)) => prop_assert!(s.is_empty(), "{s:?}: {g:?}"),
            (Truth::Enters { entry_time }, Ok(s)) => {
                prop_assert!(!s.is_empty(), "empty, truth enters at {entry_time}: {g:?}");
                prop_assert_eq!(&s[0].0, &RealAlg::from(&entry_time), "{:?}", g);
            }
        }
    }

    // Each relation's set holds at a sampled time exactly when the relation, evaluated
    // directly, does (cases on a grid of rationals, many exact ties).
    #[test]
    fn sets_agree_with_direct_evaluation(seed in any::<u64>(), which in 0u64..36) {
        let g = gen_case(seed);
        let Ok(c) = g.exact::<Q>() else { return Ok(()) };
        let s = separations(which);
        let rel = [Relation::Inside, Relation::Near, Relation::Breach][(which % 3) as usize];
        check_against_direct(&c, rel, &s).map_err(|e| TestCaseError::fail(format!("{e}: {g:?}")))?;
    }

    // The same on cases in binary floats over many scales.
    #[test]
    fn float_sets_agree_with_direct_evaluation(seed in any::<u64>(), which in 0u64..36) {
        let (c, d) = float_case(seed, 0);
        let s = sep(d, [qi(0), qi(1), qi(3)][((which / 4) % 3) as usize].clone());
        let rel = [Relation::Inside, Relation::Near, Relation::Breach][(which % 3) as usize];
        check_against_direct(&c, rel, &s).map_err(|e| TestCaseError::fail(format!("{e}: seed {seed}")))?;
    }

    // Scaling every horizontal length (and D) by a power of two changes no time: the
    // components are exactly the same, far into the float range's ends.
    #[test]
    fn components_do_not_depend_on_the_horizontal_scale(seed in any::<u64>(), which in 0u64..12) {
        let rel = [Relation::Inside, Relation::Near, Relation::Breach][(which % 3) as usize];
        let (c, d) = float_case(seed, 0);
        let s = sep(d.clone(), qi(1));
        let base = intervals_of(&c, rel, &s);
        for k in [-900i32, -40, 40, 900] {
            let (ck, dk) = float_case(seed, k);
            let got = intervals_of(&ck, rel, &sep(dk, qi(1)));
            prop_assert_eq!(&got, &base, "2^{} ({})", k, rel.name());
        }
    }

    // Keep-in exit detection says yes exactly when the breach set is not empty.
    #[test]
    fn exit_detection_agrees_with_the_breach_set(seed in any::<u64>(), which in 0u64..12) {
        let g = gen_case(seed);
        let Ok(c) = g.exact::<Q>() else { return Ok(()) };
        let s = separations(which);
        if let Ok(set) = intervals_of(&c, Relation::Breach, &s) {
            prop_assert_eq!(detect_exit_of(&c, &s), Ok(!set.is_empty()), "{:?}", g);
        }
    }
}
