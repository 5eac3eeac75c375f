//! Paper B stages, engine (f64) against the exact rational oracle, stage by stage, and the
//! dense exact check that the pipeline misses no conflict.
//!
//! Scale with `POLYGUARD_PROPTEST_CASES` (default 64) and `POLYGUARD_DENSE_PAIRS`
//! (default 300; an acceptance run uses 10000).

use polyguard_earth::conflict::{geom, pipeline, stage1, stage3, stage4, Object};
use polyguard_earth::generate::Mix;
use polyguard_earth::reference::rational as ex;
use polyguard_earth::scenario;
use polyguard_earth::sphere::{LonLat, RectDims};
use polyguard_harness::paper_b::seeded;
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64)
}

fn dense_pairs() -> usize {
    std::env::var("POLYGUARD_DENSE_PAIRS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

/// Relative agreement expected of short f64 formulas (a few roundings of values of
/// order 1): 1e-9 leaves ~6 decimal digits of margin over 2⁻⁵³-level errors, while a
/// wrong formula is off by far more.
const REL_AGREEMENT: f64 = 1e-9;

fn pt() -> impl Strategy<Value = [f64; 2]> {
    (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| [x, y])
}

fn cloud() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec(pt(), 3..12)
}

fn exact(ring: &[[f64; 2]]) -> Vec<ex::P> {
    ex::points(ring).expect("finite")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Stage 2, eq 7: the engine's hull has the oracle hull's vertices.
    #[test]
    fn hull_matches_oracle(p in cloud()) {
        let h = geom::convex_hull(&p);
        let o = ex::convex_hull(&exact(&p));
        let back: Vec<[f64; 2]> = o.iter().map(|v| [ex::to_f64(&v[0]), ex::to_f64(&v[1])]).collect();
        prop_assert_eq!(h, back);
    }

    /// Stage 2, eq 9: convex clip area and emptiness agree with the exact clip.
    #[test]
    fn clip_matches_oracle(a in cloud(), b in cloud(), shift in pt()) {
        let ha = geom::convex_hull(&a);
        let hb: Vec<[f64; 2]> = geom::convex_hull(&b).iter().map(|p| [p[0] + shift[0], p[1] + shift[1]]).collect();
        prop_assume!(ha.len() >= 3 && hb.len() >= 3);
        let c = geom::clip_convex(&ha, &hb);
        let e = ex::clip_convex(&exact(&ha), &exact(&hb));
        let area_e = if e.len() >= 3 { ex::to_f64(&ex::signed_area(&e)) } else { 0.0 };
        let area_c = if c.len() >= 3 { geom::signed_area(&c) } else { 0.0 };
        prop_assert!((area_e - area_c).abs() <= REL_AGREEMENT * (1.0 + area_e.abs()), "{area_e} vs {area_c}");
        prop_assert_eq!(geom::rings_intersect(&ha, &hb), ex::rings_intersect(&exact(&ha), &exact(&hb)));
    }

    /// Stage 3, eq 11: projection fractions agree with the exact ones.
    #[test]
    fn projection_matches_oracle(lon in -40.0f64..-20.0, lat in 1.0f64..28.0, brg in 0.0f64..std::f64::consts::TAU, pts in cloud()) {
        let leg = polyguard_earth::sphere::Leg::new(
            LonLat::from_degrees(lon, lat),
            polyguard_earth::sphere::rhumb_destination(LonLat::from_degrees(lon, lat), brg, 80.0),
            15.0, 0.0, RectDims { front: 10.0, back: 10.0, side: 10.0 });
        let c0 = polyguard_earth::sphere::mercator(leg.start);
        let c1 = polyguard_earth::sphere::mercator(leg.end);
        let pts: Vec<[f64; 2]> = pts.iter().map(|p| [c0[0] + 0.02 * p[0], c0[1] + 0.02 * p[1]]).collect();
        let (lo, hi) = stage3::rho_range(&leg, &pts).unwrap();
        let r = ex::projection(&ex::point(c0).unwrap(), &ex::point(c1).unwrap(), &exact(&pts)).unwrap();
        let elo = ex::to_f64(r.iter().min().unwrap());
        let ehi = ex::to_f64(r.iter().max().unwrap());
        prop_assert!((lo - elo).abs() <= REL_AGREEMENT * (1.0 + elo.abs()));
        prop_assert!((hi - ehi).abs() <= REL_AGREEMENT * (1.0 + ehi.abs()));
    }

    /// Stage 4, eq 20: the f64 linear window contains the oracle's exact one (it is
    /// certified: a window left out, or a "never" for a pair that meets, is a missed
    /// conflict) and exceeds it by little: ends within 1e-6 h where the window is well
    /// conditioned.
    #[test]
    fn linear_window_matches_oracle(a in cloud(), b in cloud(), va in pt(), vb in pt()) {
        let ha = geom::convex_hull(&a);
        let hb: Vec<[f64; 2]> = geom::convex_hull(&b).iter().map(|p| [p[0] + 3.0, p[1]]).collect();
        prop_assume!(ha.len() >= 3 && hb.len() >= 3);
        let w = stage4::linear_window(&ha, va, &hb, vb, 0.0, 0.0, 10.0);
        let z = ex::q(0.0).unwrap();
        let e = ex::linear_window(&exact(&ha), &ex::point(va).unwrap(), &exact(&hb), &ex::point(vb).unwrap(), &z, &z, &ex::q(10.0).unwrap());
        match (w, e) {
            (Some(Some((s, t))), Some(Some((es, et)))) => {
                let (es_f, et_f) = (ex::to_f64(&es), ex::to_f64(&et));
                prop_assert!(ex::q(s).unwrap() <= es && ex::q(t).unwrap() >= et, "[{s}, {t}] leaves out part of [{es_f}, {et_f}]");
                let tol = 1e-6 * (1.0 + es_f.abs().max(et_f.abs()));
                prop_assert!(es_f - s <= tol && t - et_f <= tol, "[{s}, {t}] vs [{es_f}, {et_f}]");
            }
            (Some(None), Some(Some((es, et)))) => {
                prop_assert!(false, "the f64 window says never; the exact one is [{}, {}]", ex::to_f64(&es), ex::to_f64(&et));
            }
            // a window where the exact one is empty: a near alarm, allowed only for a
            // grazing pass (length ~0)
            (Some(Some((s, t))), Some(None)) => prop_assert!((t - s).abs() < 1e-6, "[{s}, {t}] vs never"),
            _ => {}
        }
    }
}

/// Stage 1: the R-tree finds exactly the brute-force pairs.
#[test]
fn stage1_rtree_equals_brute_force() {
    for (mix, seed) in [(Mix::Static, 1), (Mix::Mixed, 2), (Mix::Tracks, 3)] {
        let sc = seeded(400, mix, seed, false);
        let objs = scenario::objects(&sc);
        assert_eq!(
            stage1::candidates(&objs).sorted(),
            stage1::candidates_brute(&objs)
        );
    }
}

/// f64 distance above which two polygons are certainly disjoint: the Mercator
/// coordinates are ≤ 4 in magnitude, so the engine's distance carries an absolute error
/// of a few 1e-16; 1e-10 rad (≈ 0.6 mm) is a safe margin before the exact test.
const CERTAINLY_APART: f64 = 1e-10;

/// Dense exact check: for stage-1 candidate pairs of random scenarios, sample time
/// finely; at every sample outside the interval the pipeline reports for the pair (or at
/// every sample, when it rejects the pair), the polygons must not meet — decided exactly by
/// the oracle whenever the f64 distance is not clearly positive.
#[test]
fn dense_exact_check_no_missed_conflict() {
    let want = dense_pairs();
    let tol = polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H;
    let step = 0.02; // h: 72 s between samples (≈ 0.3 nm of motion at 15 kn)
    let mut checked = 0usize;
    let mut covered = 0usize;
    let mut exact_tests = 0usize;
    let mut exact_meetings_near_ends = 0usize;
    let mut seed = 100;
    while checked < want {
        let mix = if seed % 2 == 0 {
            Mix::Tracks
        } else {
            Mix::Mixed
        };
        let sc = seeded(300, mix, seed, false);
        seed += 1;
        let objs: Vec<Object> = scenario::objects(&sc);
        let (conflicts, _) = pipeline::run(&objs, pipeline::Options::default());
        let reported: std::collections::HashMap<(u32, u32), (f64, f64)> = conflicts
            .iter()
            .map(|c| ((c.a, c.b), (c.t_start, c.t_end)))
            .collect();
        let cands = stage1::candidates(&objs);
        let (mut va, mut vb) = (Vec::new(), Vec::new());
        for &(i, j) in cands.pairs.iter() {
            if checked >= want {
                break;
            }
            let (a, b) = (&objs[i as usize], &objs[j as usize]);
            if !a.is_moving() && !b.is_moving() {
                continue;
            }
            checked += 1;
            let lo = a.t0.max(b.t0);
            let hi = a.t1.min(b.t1);
            let key = (a.owner.min(b.owner), a.owner.max(b.owner));
            let n = ((hi - lo) / step).ceil() as usize;
            for k in 0..=n {
                let t = (lo + k as f64 * step).min(hi);
                if let Some(&(s, e)) = reported.get(&key) {
                    if t >= s - tol && t <= e + tol {
                        covered += 1;
                        // near the reported ends, confirm with the exact oracle that the
                        // polygons do meet there (the interval is not needlessly wide)
                        if (t - s).abs() <= 2.0 * step || (e - t).abs() <= 2.0 * step {
                            a.vertices_at(t, &mut va);
                            b.vertices_at(t, &mut vb);
                            if ex::rings_intersect(&exact(&va), &exact(&vb)) {
                                exact_meetings_near_ends += 1;
                            }
                        }
                        continue;
                    }
                }
                a.vertices_at(t, &mut va);
                b.vertices_at(t, &mut vb);
                if geom::ring_distance(&va, &vb) > CERTAINLY_APART {
                    continue;
                }
                exact_tests += 1;
                assert!(
                    !ex::rings_intersect(&exact(&va), &exact(&vb)),
                    "missed conflict: {} and {} meet at t = {t} (reported: {:?})",
                    sc.features[key.0 as usize].id,
                    sc.features[key.1 as usize].id,
                    reported.get(&key)
                );
            }
        }
    }
    eprintln!(
        "dense check: {checked} candidate pairs, {covered} samples inside reported intervals \
         ({exact_meetings_near_ends} exact meetings within 2 samples of their ends), \
         {exact_tests} exact tests outside them, no miss"
    );
    assert!(
        exact_meetings_near_ends > 0,
        "the check must exercise real conflicts"
    );
}

/// Stage 4: on east–west legs (eq 20 applies) the exact linear window and the certified
/// advancement agree within the tolerance.
#[test]
fn linear_and_advancement_agree_on_east_west_legs() {
    let tol = polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H;
    let dims = RectDims {
        front: 10.0,
        back: 8.0,
        side: 6.0,
    };
    let mut checked = 0;
    for k in 0..40 {
        let lat = 5.0 + k as f64 * 0.6;
        let dy = (k % 5) as f64 * 0.1; // second leg 0–0.4° north: some pairs miss
        let a = polyguard_earth::sphere::track_legs(
            &[
                LonLat::from_degrees(-40.0, lat),
                LonLat::from_degrees(-37.0, lat),
            ],
            15.0,
            0.0,
            dims,
        )
        .remove(0);
        let b = polyguard_earth::sphere::track_legs(
            &[
                LonLat::from_degrees(-36.0, lat + dy),
                LonLat::from_degrees(-39.0, lat + dy),
            ],
            9.0 + k as f64 * 0.3,
            1.0,
            dims,
        )
        .remove(0);
        let (oa, ob) = (Object::leg(0, a), Object::leg(1, b));
        let (lo, hi) = (oa.t0.max(ob.t0), oa.t1.min(ob.t1));
        let lin = stage4::interval(&oa, &ob, lo, hi, tol);
        let adv = stage4::advancement_interval(&oa, &ob, lo, hi, tol);
        match (lin, adv) {
            (Some((s, e, m)), Some((s2, e2))) => {
                assert_eq!(m, stage4::Method::Linear);
                assert!(s2 <= s + 1e-12 && s - s2 <= tol, "start {s} vs {s2}");
                assert!(e2 >= e - 1e-12 && e2 - e <= tol, "end {e} vs {e2}");
                checked += 1;
            }
            (None, None) => {}
            (x, y) => panic!("linear {x:?} vs advancement {y:?}"),
        }
    }
    assert!(checked > 10);
}

/// Stage 4's contract at the ends: for reported moving pairs, the polygons at `t_start`
/// and `t_end` are within the stopping distance (at most the two speed bounds times the
/// tolerance, doubled for the bound's slack).
#[test]
fn reported_ends_are_near_contact() {
    let tol = polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H;
    let sc = seeded(300, Mix::Tracks, 9, false);
    let objs = scenario::objects(&sc);
    let cands = stage1::candidates(&objs);
    let regions = polyguard_earth::conflict::stage2::regions(&objs, &cands, false);
    let windows = stage3::windows(&objs, regions, false);
    let ivs = stage4::intervals(&objs, windows, tol);
    let (mut va, mut vb) = (Vec::new(), Vec::new());
    assert!(!ivs.intervals.is_empty());
    for iv in &ivs.intervals {
        let (a, b) = (&objs[iv.pair.0 as usize], &objs[iv.pair.1 as usize]);
        let eps = 2.0 * (a.speed_bound() + b.speed_bound()) * tol;
        for t in [iv.t_start, iv.t_end] {
            a.vertices_at(t, &mut va);
            b.vertices_at(t, &mut vb);
            let d = geom::ring_distance(&va, &vb);
            assert!(d <= eps, "distance {d} > {eps} at {t}");
        }
    }
}
