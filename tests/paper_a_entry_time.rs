//! The f64 time of first entry (`api::detect_time`, module `entry`) against the exact
//! truth's entry time, on the harness's boundary-biased cases (the generator of
//! `polyguard assure`): a certified `never` is the truth's "misses", a certified `enters`
//! is its "enters", and whenever the truth enters, its exact time lies in the enclosure.
//! A canary shows the comparison sees an enclosure moved by two resolution steps (the
//! same shift as `polyguard assure --engine shifted-time`).

use polyguard::api::{detect_time, detected};
use polyguard::entry::EntryTime;
use polyguard_harness::classify::{shifted, time_failure as judge, Exact, TIME_CANARY_STEPS};
use polyguard_harness::gen::{any_case, SplitMix};
use polyguard_oracle::{truth, Truth};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(256)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn the_truths_entry_time_lies_in_the_enclosure(seed in any::<u64>()) {
        let drawn = any_case(&mut SplitMix(seed));
        let (raw, mode) = (&drawn.raw, drawn.name());
        let Ok(case) = raw.to_api() else { return Ok(()) };
        let Ok(exact) = raw.exact::<Exact>() else { return Ok(()) };
        let answer = detect_time(&case);
        let truth = truth(&exact);
        prop_assert!(judge(answer, &truth).is_none(), "seed {seed} ({mode}): {answer:?}: {}", judge(answer, &truth).unwrap_or_default());
        // A certain entry is a true entry, which paper A (and so the engine) detects.
        if let EntryTime::Enters { lo, hi } = answer {
            prop_assert!(lo <= hi && detected(&case), "seed {seed} ({mode}): {answer:?} but detected = {}", detected(&case));
        }
    }
}

/// The canary: the same judge on enclosures moved right by one resolution step (the true
/// entry then lies just before lo) must fail on crossing entries; a judge that passes
/// them cannot see a wrong enclosure.
#[test]
fn the_judge_catches_an_enclosure_moved_by_one_step() {
    let mut caught = 0;
    let mut entering = 0;
    for seed in 0..400u64 {
        let drawn = any_case(&mut SplitMix(seed));
        let raw = &drawn.raw;
        let (Ok(case), Ok(exact)) = (raw.to_api(), raw.exact::<Exact>()) else {
            continue;
        };
        let truth = truth(&exact);
        if let (EntryTime::Enters { lo, hi }, Truth::Enters { .. }) = (detect_time(&case), &truth) {
            entering += 1;
            let moved = shifted(
                EntryTime::Enters { lo, hi },
                raw.lookahead,
                TIME_CANARY_STEPS,
            );
            if judge(moved, &truth).is_some() {
                caught += 1;
            }
        }
    }
    assert!(
        entering >= 50,
        "only {entering} certified entries in 400 cases"
    );
    assert!(
        caught * 10 >= entering * 9,
        "the judge caught {caught} of {entering} shifted enclosures"
    );
}
