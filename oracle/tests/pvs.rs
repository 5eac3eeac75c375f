//! Paper A's correctness theorem (proved in PVS), executable: for well-formed
//! polygons, if the point really enters the polygon (truth), the paper's
//! algorithm evaluated exactly detects it.

mod common;

use proptest::prelude::*;

use common::{cases, gen_case, GenCase};
use polyguard_oracle::well_formed::well_formed;
use polyguard_oracle::{paper_detect, truth, Arith, Decided, Exact, Truth, Q};

/// κ ≈ 8.1°: cos κ = 99/100.
fn cos_kappa() -> Q {
    Q::from_i64(99)
        .quotient(&Q::from_i64(100))
        .unwrap_or_else(<Q as Arith>::one)
}

/// None when the case is outside the theorem's hypotheses; Some(message) on a counterexample.
fn check(g: &GenCase) -> Option<String> {
    let c = g.exact::<Q>().ok()?;
    if !well_formed(&c.vertices, &c.buff, &cos_kappa()) {
        return None;
    }
    let t = truth(&c);
    if let Truth::Enters { entry_time } = &t {
        let ans = paper_detect(&c);
        if !ans.detected {
            return Some(format!(
                "truth enters at {} but {} says no: {g:?}",
                entry_time.to_decimal_string(12),
                ans.method.name()
            ));
        }
    }
    None
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(256)))]

    #[test]
    fn truth_implies_paper_detect(seed in any::<u64>()) {
        let g = gen_case(seed);
        if let Some(msg) = check(&g) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// The generator does reach the interesting region: many well-formed cases,
/// many true entries, some misses.
#[test]
fn generator_covers_hits_and_misses() {
    let (mut wf, mut enters, mut misses) = (0, 0, 0);
    for seed in 1..200u64 {
        let g = gen_case(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15));
        let Ok(c) = g.exact::<Q>() else { continue };
        if !well_formed(&c.vertices, &c.buff, &cos_kappa()) {
            continue;
        }
        wf += 1;
        match truth(&c) {
            Truth::Enters { .. } => enters += 1,
            Truth::Misses => misses += 1,
            Truth::Undefined { .. } => {}
        }
    }
    assert!(wf > 100, "well formed: {wf}");
    assert!(
        enters > 30 && misses > 10,
        "enters {enters}, misses {misses}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(512)))]

    /// The exact shortcut in front of edge_detect_simp never changes its answer.
    #[test]
    fn far_from_edge_shortcut_is_sound(c in proptest::collection::vec(-40i64..40, 9), f in 1i64..64) {
        use polyguard_oracle::detect::{edge_detect_simp, edge_detect_simp_without_shortcut};
        use polyguard_oracle::V2;
        let v = |i: usize| V2::new(Q::from_i64(c[i]), Q::from_i64(c[i + 1]).quotient(&Q::from_i64(4)).unwrap_or_default());
        let t = Q::from_i64(c[8].abs() + 1);
        let fac = Q::from_i64(1).quotient(&Q::from_i64(f + 1)).unwrap_or_default();
        prop_assert_eq!(
            edge_detect_simp(&Exact, &t, &v(0), &v(2), &v(4), &v(6), &fac).decided(),
            edge_detect_simp_without_shortcut(&Exact, &t, &v(0), &v(2), &v(4), &v(6), &fac).decided()
        );
    }
}
