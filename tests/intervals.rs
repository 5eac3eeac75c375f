//! The certified intervals (`api::intervals`, module `intervals`) and keep-in exit
//! detection (`api::detect_exit`, module `fence`) against what is known exactly, on the
//! harness's boundary-biased cases (the generator of `polyguard assure`) and on the
//! uniform workload of the benches:
//! - inside against the exact truth (`polyguard_oracle::truth`): when the truth misses
//!   no span is certain; when it enters at t*, t* lies in a span's enclosure (G3), no
//!   certain stretch starts before it, and the first span starts no later (G1);
//! - inside against `first_entry`: the first span, when certain, starts inside
//!   first_entry's enclosure;
//! - detect_exit against the spans of breach_D: a certain exit has a span, a certain
//!   breach stretch is never a certain "no exit".

use polyguard::api::{detect_exit, detect_time, intervals, Case, Kind, MovingPoint, MovingPolygon};
use polyguard::entry::{first_entry, EntryTime, Heights};
use polyguard::{Relation, Separation, Span};
use polyguard_harness::classify::Exact;
use polyguard_harness::gen::{any_case, SplitMix};
use polyguard_harness::workload::{workload, BUFF, T};
use polyguard_oracle::convert::q;
use polyguard_oracle::{truth, Truth};
use proptest::prelude::*;
use std::cmp::Ordering;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(256)
}

/// The shape of every answer: finite, in [0, T], each span in order (or one cluster),
/// the spans in order or sharing one cluster.
fn well_shaped(spans: &[Span], t: f64) -> bool {
    let mut last: Option<polyguard::End> = None;
    spans.iter().all(|sp| {
        let e = [sp.start.lo, sp.start.hi, sp.end.lo, sp.end.hi];
        let ordered = e[0] <= e[1]
            && e[2] <= e[3]
            && (e[1] <= e[2] || (sp.start == sp.end && !sp.certain))
            && 0.0 <= e[0]
            && e[3] <= t
            && e.iter().all(|x| x.is_finite());
        let after = last.map_or(true, |l| l.hi <= sp.start.lo || l == sp.start);
        last = Some(sp.end);
        ordered && after
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn inside_agrees_with_the_exact_truth(seed in any::<u64>()) {
        let drawn = any_case(&mut SplitMix(seed));
        let (raw, mode) = (&drawn.raw, drawn.name());
        let Ok(case) = raw.to_api() else { return Ok(()) };
        let Ok(exact) = raw.exact::<Exact>() else { return Ok(()) };
        let spans = intervals(&case, Relation::Inside, Separation::NONE);
        prop_assert!(well_shaped(&spans, case.lookahead()), "seed {seed} ({mode}): {spans:?}");
        match truth(&exact) {
            Truth::Misses => {
                prop_assert!(spans.iter().all(|sp| !sp.certain), "seed {seed} ({mode}): misses, but {spans:?}");
            }
            Truth::Enters { entry_time } => {
                // t* ≥ x and t* ≤ x, exactly (a float that is not a rational is never
                // one of the engine's ends).
                let at_least = |x: f64| q(x).is_some_and(|r| entry_time.cmp_rational(&r) != Ordering::Less);
                let at_most = |x: f64| q(x).is_some_and(|r| entry_time.cmp_rational(&r) != Ordering::Greater);
                let enclosed = spans.iter().any(|sp| {
                    [sp.start, sp.end].iter().any(|e| at_least(e.lo) && at_most(e.hi))
                });
                let t = entry_time.to_decimal_string(20);
                prop_assert!(enclosed, "seed {seed} ({mode}): enters at {t}, not enclosed: {spans:?}");
                prop_assert!(spans.iter().all(|sp| !sp.certain || at_most(sp.start.hi)), "seed {seed} ({mode}): certain before {t}: {spans:?}");
                prop_assert!(at_least(spans[0].start.lo), "seed {seed} ({mode}): first span after {t}: {spans:?}");
            }
            Truth::Undefined { .. } => {}
        }
    }

    #[test]
    fn exits_agree_with_the_spans_of_breach(seed in any::<u64>(), d in 0.0f64..2.0) {
        let drawn = any_case(&mut SplitMix(seed));
        let Ok(case) = drawn.raw.to_api() else { return Ok(()) };
        let sep = Separation { d: d * case.params().buff() * 100.0, h: d };
        let exit = detect_exit(&case, sep);
        let spans = intervals(&case, Relation::Breach, sep);
        prop_assert!(well_shaped(&spans, case.lookahead()), "seed {seed}: {spans:?}");
        let certain_exit = exit.detected && exit.kind == Kind::Exact;
        let certain_stay = !exit.detected;
        prop_assert!(!certain_exit || !spans.is_empty(), "seed {seed}: a certain exit, no span");
        prop_assert!(!certain_stay || spans.iter().all(|sp| !sp.certain), "seed {seed}: stays, but {spans:?}");
    }
}

/// The workload's case i as the paper functions take it, with a slab in 3D.
fn workload_cases(n: usize, warping: bool, seed: u64) -> Vec<Case> {
    let w = workload(n, warping, seed);
    (0..w.s.len())
        .filter_map(|i| {
            let poly = MovingPolygon::new(w.verts[i].clone(), Some(w.vels[i].clone())).ok()?;
            let (s, v) = (w.s[i], w.v[i]);
            let (point, poly) = if i % 2 == 0 {
                (MovingPoint::new_2d(s, v).ok()?, poly)
            } else {
                let (sz, vz) = w.z[i];
                let point = MovingPoint::new_3d([s.x, s.y, sz], [v.x, v.y, vz]).ok()?;
                (point, poly.with_slab(0.0, 1000.0, 0.0).ok()?)
            };
            Case::new(T, point, poly, polyguard::api::Params::new(BUFF).ok()?).ok()
        })
        .collect()
}

#[test]
fn the_first_certain_span_starts_in_first_entrys_enclosure() {
    let mut compared = 0;
    for (n, warping) in [(8, false), (8, true), (32, false), (32, true)] {
        for case in workload_cases(n, warping, 7 + n as u64) {
            let spans = intervals(&case, Relation::Inside, Separation::NONE);
            assert!(well_shaped(&spans, T), "{spans:?}");
            let entry = detect_time(&case);
            match entry {
                EntryTime::Never => assert!(spans.iter().all(|sp| !sp.certain), "{spans:?}"),
                EntryTime::Enters { lo, hi } | EntryTime::Possible { lo, hi } => {
                    // Nothing certain before lo; something in [0, hi] when it enters.
                    assert!(spans.iter().all(|sp| !sp.certain || lo <= sp.start.hi));
                    if matches!(entry, EntryTime::Enters { .. }) {
                        assert!(spans[0].start.lo <= hi, "{entry:?}: {spans:?}");
                        if spans[0].certain {
                            let s = spans[0].start;
                            assert!(s.lo <= hi && lo <= s.hi, "{entry:?}: {spans:?}");
                            compared += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(compared > 100, "only {compared} certain entries compared");
}

#[test]
fn first_entry_and_the_slice_form_agree_on_heights() {
    // The same 3D crossing through the slice functions: entering the square [0, 2]² at
    // t = 2 below a ceiling it reaches at t = 3.
    let sq = [
        polyguard::Vect2::new(0.0, 0.0),
        polyguard::Vect2::new(2.0, 0.0),
        polyguard::Vect2::new(2.0, 2.0),
        polyguard::Vect2::new(0.0, 2.0),
    ];
    let still = [polyguard::Vect2::ZERO; 4];
    let z = Heights {
        sz: 1.0,
        vz: 1.0,
        bottom: 0.0,
        top: 4.0,
        vsp: 0.0,
    };
    let (s, v) = (
        polyguard::Vect2::new(1.0, -2.0),
        polyguard::Vect2::new(0.0, 1.0),
    );
    let spans = polyguard::intervals::intervals(
        10.0,
        s,
        v,
        &sq,
        &still,
        Some(z),
        Relation::Inside,
        Separation::NONE,
    );
    let EntryTime::Enters { lo, hi } = first_entry(10.0, s, v, &sq, &still, Some(z)) else {
        panic!("enters at 2");
    };
    assert_eq!(spans.len(), 1, "{spans:?}");
    assert!(spans[0].start.lo <= hi && lo <= spans[0].start.hi);
    // Inside from t = 2 (the square) to t = 3 (z = 4, the ceiling).
    assert!(
        spans[0].end.lo <= 3.0 && 3.0 <= spans[0].end.hi,
        "{spans:?}"
    );
}
