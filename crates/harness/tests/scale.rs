//! The case format's scaling (`RawCase::times_pow2`) against the oracle: the homogeneity
//! that `RawCase::exact` relies on, on generated cases.

/// The homogeneity `RawCase::exact` relies on: generated cases moved by 2⁻¹⁰⁰⁰
/// and by 2⁹⁰⁰ (exactly), handed to the oracle as they are, get paper A's answer,
/// the truth and the entry time of the case at its own scale.
#[test]
fn the_oracle_answers_alike_at_every_scale() {
    use polyguard_harness::classify::Exact;
    use polyguard_harness::gen::{any_case, SplitMix};
    use polyguard_oracle::{paper_detect, truth, ExactCase};
    // the entry time as a value (a + b·√d is written in more than one way)
    let answers = |c: &ExactCase<Exact>| {
        let t = match truth(c) {
            polyguard_oracle::Truth::Enters { entry_time } => {
                Some(Some(entry_time.to_decimal_string(40)))
            }
            polyguard_oracle::Truth::Misses => Some(None),
            polyguard_oracle::Truth::Undefined { .. } => None,
        };
        (paper_detect(c).detected, t)
    };
    let mut src = SplitMix(5);
    let mut moved = 0;
    for _ in 0..40 {
        let raw = any_case(&mut src).raw;
        let want = answers(&raw.exact().expect("a generated case is valid"));
        for s in [-1000, 900] {
            let c = raw.times_pow2(s);
            if c.times_pow2(-s) != raw {
                continue; // the move rounded: not the same case
            }
            moved += 1;
            let got = answers(&c.exact_as_is().expect("moved exactly"));
            assert_eq!(got, want, "moved by 2^{s}: {c:?}");
        }
    }
    assert!(moved >= 40, "only {moved} of 80 moves were exact");
}
