//! Paper B's four stages against the ground truth on generated two-feature scenarios;
//! aborts on a missed conflict, a short window, a far window end or a broken speed bound
//! (see fuzz/README.md).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    polyguard_fuzz::paper_b(data);
});
