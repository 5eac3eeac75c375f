//! The engine's three-valued answers on N generated cases, as counts and one digest:
//! two builds that print the same digest gave the same answer (yes, no or unsure) on
//! every case. Used to sort mutation-test survivors (`scripts/mutants.sh`): a mutant
//! whose digest differs from the unmutated engine's changed an answer, so a test can
//! be written for it; one whose digest is the same on 10⁶ cases of the scale-space
//! generators is a candidate for "equivalent" (then argued in docs/mutation.md).
//!
//!   cargo run --release -p polyguard-harness --example decisions_digest -- [N] [FIRST_SEED]

use std::hash::{DefaultHasher, Hash, Hasher};

use polyguard::api::decide;
use polyguard::Tri;
use polyguard_harness::gen::{any_case, SplitMix};

fn main() {
    let mut args = std::env::args().skip(1);
    let n: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(200_000);
    let first: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(0);
    let mut counts = [0u64; 4];
    let mut digest = DefaultHasher::new();
    for seed in first..first + n {
        let drawn = any_case(&mut SplitMix(seed));
        let code = match drawn.raw.to_api() {
            Ok(case) => match decide(&case) {
                Tri::Yes => 0u8,
                Tri::No => 1,
                Tri::Unsure => 2,
            },
            Err(_) => 3,
        };
        counts[usize::from(code)] += 1;
        (seed, code).hash(&mut digest);
    }
    println!(
        "{n} cases from seed {first}: yes {}, no {}, unsure {}, refused {}; digest {:016x}",
        counts[0],
        counts[1],
        counts[2],
        counts[3],
        digest.finish()
    );
}
