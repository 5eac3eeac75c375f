//! Batch detection (`polyguard::batch`) against the pairwise engine: on seeded
//! workloads with touching and nearly touching pairs, 2D and 3D, rigid, warping and
//! collapsing polygons, `detect_batch` returns the pairs for which `api::detected` says
//! yes, with the same kind and method, but for conservative pairwise yeses that paper A
//! computed without rounding denies (checked with the oracle), which the broad phase may
//! spare; a broad phase with boxes shrunk by BUFF (the canary) is caught dropping pairs.

use polyguard::api::{decide, Case, Kind, MovingPoint, MovingPolygon, Params};
use polyguard::batch::{
    detect_batch, detect_batch_counted, detect_batch_mid_offset, detect_batch_with, Broad, Hit,
    Options,
};
use polyguard::{Tri, Vect2};
use polyguard_harness::batch::{batch_workload, dense_workload, Mix, BUFF, T};
use polyguard_harness::case::RawCase;
use polyguard_harness::classify::Exact;
use polyguard_oracle::paper_detect;
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(32)
}

/// The pairwise engine's answer for every pair, as hits, in (point, polygon) order.
fn pairwise(points: &[MovingPoint], polygons: &[MovingPolygon], params: &Params) -> Vec<Hit> {
    let mut out = Vec::new();
    for (i, p) in points.iter().enumerate() {
        for (j, q) in polygons.iter().enumerate() {
            let case = Case::new(T, *p, q.clone(), *params).expect("a valid pair");
            let tri = decide(&case);
            assert_eq!(
                polyguard::api::detected(&case),
                tri != Tri::No,
                "pair ({i}, {j})"
            );
            let kind = match tri {
                Tri::No => continue,
                Tri::Yes => Kind::Exact,
                Tri::Unsure => Kind::Conservative,
            };
            out.push(Hit {
                point: i,
                polygon: j,
                kind,
                method: case.method(),
            });
        }
    }
    out
}

fn params(fac: f64) -> Params {
    Params::new(BUFF).and_then(|p| p.with_fac(fac)).unwrap()
}

fn mix(three_d: bool, fac: f64) -> Mix {
    Mix {
        three_d,
        warping: 0.4,
        aimed: 0.4,
        collapsing: 0.02,
        fac,
    }
}

/// The batch against the pairwise engine under the batch's contract: every batch hit is
/// a pairwise hit with the same kind and method; every pairwise hit is a batch hit,
/// except a conservative one whose pair paper A computed without rounding does not
/// detect (the broad phase proved it apart where the pairwise engine could not decide a
/// comparison in f64). `Err` names the first breach.
fn agrees(
    got: &[Hit],
    want: &[Hit],
    points: &[MovingPoint],
    polygons: &[MovingPolygon],
    params: &Params,
) -> Result<usize, String> {
    if let Some(h) = got.iter().find(|h| !want.contains(h)) {
        return Err(format!("a batch hit the pairwise engine lacks: {h:?}"));
    }
    let mut spared = 0;
    for h in want.iter().filter(|h| !got.contains(h)) {
        if h.kind == Kind::Exact {
            return Err(format!("a certified pairwise hit the batch dropped: {h:?}"));
        }
        let case = Case::new(T, points[h.point], polygons[h.polygon].clone(), *params)
            .expect("a valid pair");
        let exact = RawCase::from_api(&case)
            .exact::<Exact>()
            .map_err(|e| format!("{h:?}: the oracle refuses it: {e}"))?;
        if paper_detect(&exact).detected {
            return Err(format!("the batch dropped a pair paper A detects: {h:?}"));
        }
        spared += 1;
    }
    Ok(spared)
}

/// The first pair on which two answers differ, for the message.
fn first_difference(a: &[Hit], b: &[Hit]) -> String {
    let k = a
        .iter()
        .zip(b)
        .position(|(x, y)| x != y)
        .unwrap_or(a.len().min(b.len()));
    format!(
        "{} against {} hits; first difference at {k}: {:?} / {:?}",
        a.len(),
        b.len(),
        a.get(k),
        b.get(k)
    )
}

/// The contract on four seeded workloads (2D and 3D, F = 10⁻⁴ where BUFF is the reach
/// and F = 0.5 where F times an edge is): the batch is the pairwise engine, pair for
/// pair, and the workloads are not trivial (hits at the boundary, misses near it).
#[test]
fn batch_is_the_pairwise_engine_on_seeded_workloads() {
    for (seed, three_d, fac) in [
        (1, false, 1e-4),
        (2, false, 0.5),
        (3, true, 1e-4),
        (4, true, 0.5),
    ] {
        let w = batch_workload(600, 120, seed, mix(three_d, fac));
        let p = params(fac);
        let want = pairwise(&w.points, &w.polygons, &p);
        let got = detect_batch(T, &w.points, &w.polygons, &p).unwrap();
        let verdict = agrees(&got, &want, &w.points, &w.polygons, &p);
        assert!(
            verdict.is_ok(),
            "seed {seed}: {verdict:?}; {}",
            first_difference(&got, &want)
        );
        // not trivial: hits, several methods, and far fewer candidates than pairs
        assert!(want.len() > 60, "seed {seed}: {} hits", want.len());
        let (b, decided) =
            detect_batch_counted(T, &w.points, &w.polygons, &p, &Options::default()).unwrap();
        assert!(b.candidates < 600 * 120 / 10, "{} candidates", b.candidates);
        assert!(
            b.unbounded_polygons > 0,
            "seed {seed}: no collapsing polygon"
        );
        // every pair with an unbounded polygon is a candidate, and detected (an edge
        // that collapses accepts any point that is in the slab then)
        if !three_d {
            assert!(b.candidates >= (b.unbounded_polygons * 600) as u64);
        }
        // the all-pairs box test and the sequential run give the same answer
        for opts in [
            Options {
                broad: Broad::AllPairs,
                ..Options::default()
            },
            Options {
                parallel: false,
                ..Options::default()
            },
        ] {
            let (other, other_decided) =
                detect_batch_counted(T, &w.points, &w.polygons, &p, &opts).unwrap();
            assert_eq!(other.hits, got, "{opts:?}");
            assert_eq!(other.candidates, b.candidates, "{opts:?}");
            assert_eq!(other_decided, decided, "{opts:?}");
        }
    }
}

/// The canary: the same comparison with every polygon's box shrunk by BUFF (its reach
/// lowered by 2·BUFF) must fail: the workloads hold pairs that only the full reach
/// keeps, so the comparison above can see a dropped pair.
#[test]
fn a_broad_phase_with_boxes_shrunk_by_buff_is_caught() {
    for (seed, three_d) in [(1, false), (3, true)] {
        let w = batch_workload(600, 120, seed, mix(three_d, 1e-4));
        let p = params(1e-4);
        let want = pairwise(&w.points, &w.polygons, &p);
        let shrunk = Options {
            reach_offset: -2.0 * BUFF,
            ..Options::default()
        };
        let got = detect_batch_with(T, &w.points, &w.polygons, &p, &shrunk).unwrap();
        assert!(
            agrees(&got.hits, &want, &w.points, &w.polygons, &p).is_err(),
            "seed {seed}: the shrunk broad phase passed the comparison"
        );
        // and shrinking by only a hundredth of BUFF is caught too on the aimed pairs
        let slightly = Options {
            reach_offset: -0.02 * BUFF,
            ..Options::default()
        };
        let got = detect_batch_with(T, &w.points, &w.polygons, &p, &slightly).unwrap();
        assert!(
            agrees(&got.hits, &want, &w.points, &w.polygons, &p).is_err(),
            "seed {seed}: shrinking by BUFF/100 went unseen"
        );
    }
}

/// The dense workload (every pair a candidate; paths across the whole square of polygons,
/// many of them grazing a polygon): the batch is the pairwise engine, pair for pair, and
/// the mid phase drops most pairs but leaves every hit.
#[test]
fn batch_is_the_pairwise_engine_on_the_dense_workload() {
    let w = dense_workload(200, 150, 1);
    let p = params(1e-4);
    let want = pairwise(&w.points, &w.polygons, &p);
    let (b, decided) =
        detect_batch_counted(T, &w.points, &w.polygons, &p, &Options::default()).unwrap();
    assert_eq!(b.hits, want, "{}", first_difference(&b.hits, &want));
    assert_eq!(b.candidates, 200 * 150);
    assert!(decided < b.candidates / 3, "{decided} decided");
    assert!(want.len() > 200 * 150 / 10, "{} hits", want.len());
    // the scan of every polygon's columns (each point's box spans the grid) and the
    // reference loop over every pair's boxes keep and decide the same pairs
    let all = Options {
        broad: Broad::AllPairs,
        parallel: false,
        ..Options::default()
    };
    let (other, other_decided) = detect_batch_counted(T, &w.points, &w.polygons, &p, &all).unwrap();
    assert_eq!(
        (other.hits, other.candidates, other_decided),
        (b.hits, b.candidates, decided)
    );
}

/// Unit squares in three rows (still, or drifting along x) and axis-aligned paths along
/// their edges at 0, ½, 1, 1 + 2⁻²⁰ and 2 times BUFF outside them: the paths at BUFF
/// graze the squares (paper A says yes, at distance BUFF) and run along their grown
/// boxes' edges, the tightest pairs for the mid phase's side test.
fn grazing() -> (Vec<MovingPoint>, Vec<MovingPolygon>) {
    let square = |k: usize| {
        let (x, y) = (3.0 * k as f64, 3.0 * (k % 3) as f64);
        let v = vec![
            Vect2::new(x, y),
            Vect2::new(x + 1.0, y),
            Vect2::new(x + 1.0, y + 1.0),
            Vect2::new(x, y + 1.0),
        ];
        let drift = Vect2::new(if k % 2 == 0 { 0.0 } else { 0.3 }, 0.0);
        MovingPolygon::new(v, Some(vec![drift; 4])).expect("a square")
    };
    let polygons: Vec<_> = (0..12).map(square).collect();
    let mut points = Vec::new();
    for f in [0.0, 0.5, 1.0, 1.0 + 1.0 / 1048576.0, 2.0] {
        let d = f * BUFF;
        for r in 0..3 {
            let y = 3.0 * r as f64;
            for y in [y - d, y + 1.0 + d] {
                let p = MovingPoint::new_2d(Vect2::new(-5.0, y), Vect2::new(4.0, 0.0));
                points.push(p.expect("a point"));
            }
        }
        // vertical paths beside the still squares only (a drifting one moves across them)
        for k in (0..12).step_by(2) {
            let x = 3.0 * k as f64;
            for x in [x - d, x + 1.0 + d] {
                let p = MovingPoint::new_2d(Vect2::new(x, -5.0), Vect2::new(0.0, 2.0));
                points.push(p.expect("a point"));
            }
        }
    }
    (points, polygons)
}

/// The grazing pairs: the batch is the pairwise engine, pair for pair.
#[test]
fn batch_is_the_pairwise_engine_on_grazing_paths() {
    let (points, polygons) = grazing();
    let p = params(1e-4);
    let want = pairwise(&points, &polygons, &p);
    let b = detect_batch_with(T, &points, &polygons, &p, &Options::default()).unwrap();
    let verdict = agrees(&b.hits, &want, &points, &polygons, &p);
    assert!(
        verdict.is_ok(),
        "{verdict:?}; {}",
        first_difference(&b.hits, &want)
    );
    assert!(want.len() > 40, "{} hits", want.len());
}

/// The mid phase's canary: the comparisons with the mid phase's boxes shrunk by BUFF/100
/// (`detect_batch_mid_offset`, the broad phase intact) must fail on the grazing paths (whose pairs at
/// BUFF only the full box keeps), and with them shrunk by 2·BUFF on the dense workload
/// (the max-norm box reaches farther than paper A's Euclidean BUFF from a polygon, so
/// only a deeper cut drops hits there): the comparisons can see a mid phase that drops
/// too much.
#[test]
fn a_mid_phase_with_boxes_shrunk_is_caught() {
    let shrunk = |points: &[MovingPoint], polygons: &[MovingPolygon], p: &Params, by: f64| {
        detect_batch_mid_offset(T, points, polygons, p, &Options::default(), -by)
            .map(|(b, _)| b)
            .unwrap()
    };
    let p = params(1e-4);
    let (points, polygons) = grazing();
    let want = pairwise(&points, &polygons, &p);
    let got = shrunk(&points, &polygons, &p, 0.01 * BUFF);
    assert!(
        agrees(&got.hits, &want, &points, &polygons, &p).is_err(),
        "grazing paths: a mid phase shrunk by BUFF/100 passed the comparison"
    );
    let w = dense_workload(200, 150, 1);
    let want = pairwise(&w.points, &w.polygons, &p);
    let got = shrunk(&w.points, &w.polygons, &p, 2.0 * BUFF);
    assert!(
        agrees(&got.hits, &want, &w.points, &w.polygons, &p).is_err(),
        "the dense workload: a mid phase shrunk by 2·BUFF passed the comparison"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Small random workloads of every mix: the batch is the pairwise engine.
    #[test]
    fn batch_is_the_pairwise_engine_on_small_workloads(
        seed in any::<u64>(),
        n in 0usize..40,
        m in 0usize..12,
        three_d in any::<bool>(),
        warping in 0.0f64..1.0,
        aimed in 0.0f64..1.0,
        collapsing in 0.0f64..0.3,
        big_f in any::<bool>(),
    ) {
        let fac = if big_f { 0.5 } else { 1e-4 };
        let mix = Mix { three_d, warping, aimed, collapsing, fac };
        let w = batch_workload(n, m, seed, mix);
        let p = params(fac);
        let want = pairwise(&w.points, &w.polygons, &p);
        let got = detect_batch(T, &w.points, &w.polygons, &p).unwrap();
        let verdict = agrees(&got, &want, &w.points, &w.polygons, &p);
        prop_assert!(verdict.is_ok(), "{:?}; {}", verdict, first_difference(&got, &want));
    }
}

/// Found by the proptest above (CI, seed 6737143454489738953): a warping polygon whose
/// edge 7–0 nearly shrinks to a point near t = 7.9, and a point 4 units to its right
/// moving away. The pairwise engine cannot decide a comparison on the nearly collapsed
/// edge and answers a conservative yes; the broad phase proves the pair apart, and paper
/// A computed without rounding (and the truth) say no. The batch leaves it out: allowed,
/// and the only difference from the pairwise engine.
#[test]
fn a_conservative_pairwise_yes_that_paper_a_denies_may_be_spared() {
    let mix = Mix {
        three_d: false,
        warping: 0.6613917772484683,
        aimed: 0.8867079174161251,
        collapsing: 0.2842482836771003,
        fac: 0.5,
    };
    let w = batch_workload(11, 10, 6737143454489738953, mix);
    let p = params(0.5);
    let want = pairwise(&w.points, &w.polygons, &p);
    let got = detect_batch(T, &w.points, &w.polygons, &p).unwrap();
    let pair = (10, 9);
    assert!(want
        .iter()
        .any(|h| (h.point, h.polygon) == pair && h.kind == Kind::Conservative));
    assert!(!got.iter().any(|h| (h.point, h.polygon) == pair));
    assert_eq!(agrees(&got, &want, &w.points, &w.polygons, &p), Ok(1));
}
