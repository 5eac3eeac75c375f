//! Engine against the exact oracle on boundary-biased cases: the safety property
//! "truth enters ⇒ the engine detects" (a failure is a missed detection), the paper's
//! own theorem in exact arithmetic "truth enters ⇒ paper-exact detects", and the engine's
//! certificate both ways: a certified yes or no is paper A's answer.
//!
//! The cases are the harness's (`polyguard_harness::gen::any_case`, the generator
//! `polyguard assure` and the fuzz targets draw from): the point exactly at, or a few
//! ulps / a relative 10⁻¹⁵…10⁻³ inside or outside of, the BUFF band around an edge or a
//! vertex, through vertices, along edges, first contact at t = 0 or t = T, over the whole
//! scale space (relative paths of 10⁻³ … 10⁷ polygon sizes, BUFF of 10⁻¹² … 1 of it,
//! offsets to 10⁹, lookaheads of 10⁻⁶ … 10⁹, needles, short edges, up to 256 vertices).

use polyguard::api::{decide, detected};
use polyguard::Tri;
use polyguard_harness::classify::Exact;
use polyguard_harness::gen::{any_case, SplitMix};
use polyguard_oracle::{paper_detect, truth, Truth};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(128)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn truth_enters_implies_engine_and_paper_detect(seed in any::<u64>()) {
        let drawn = any_case(&mut SplitMix(seed));
        let (raw, mode) = (&drawn.raw, drawn.name());
        // the generator makes valid cases; one the engine refuses has nothing to check
        let Ok(case) = raw.to_api() else { return Ok(()) };
        let got = detected(&case);
        let tri = decide(&case);
        let exact = raw.exact::<Exact>();
        prop_assert!(exact.is_ok(), "seed {seed} ({mode}): the oracle refuses a case the engine takes");
        let Ok(exact) = exact else { return Ok(()) };
        let paper = paper_detect(&exact).detected;
        // The certificate, both ways: a decided answer is paper A's answer.
        prop_assert!(tri == Tri::Unsure || (tri == Tri::Yes) == paper, "seed {seed} ({mode}): the engine certifies {tri:?}, paper-exact says {paper}");
        if let Truth::Enters { entry_time } = truth(&exact) {
            prop_assert!(paper, "seed {seed} ({mode}): paper gap: truth enters at {} but paper-exact says no", entry_time.to_decimal_string(20));
            prop_assert!(got, "seed {seed} ({mode}): missed detection: truth enters at {} but the engine says no", entry_time.to_decimal_string(20));
        }
    }
}
