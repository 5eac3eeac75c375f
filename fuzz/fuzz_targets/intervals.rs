//! The certified intervals and keep-in exit detection against the oracle's exact algebraic
//! truth, on cases decoded from the input by the interval hunt's generator (the one
//! `polyguard assure --intervals` uses); aborts on every failing class (interval_missed,
//! end_outside, interval_false, span_malformed, exit_missed, exit_false) with the case as
//! a line of the case format, `sep` and `sep_v` included.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_harness::gen::{Bytes, Space};
use polyguard_harness::intervals::gen::interval_case;
use polyguard_harness::intervals::judge::{judge, IntervalEngine};

fuzz_target!(|data: &[u8]| {
    let mut src = Bytes::new(data);
    let ic = interval_case(&mut src, &Space::FULL);
    let Ok(v) = judge(&ic, IntervalEngine::Certified) else {
        return;
    };
    if v.class.is_failure() {
        let why: Vec<String> = v.relations.iter().filter_map(|r| r.why.clone()).collect();
        panic!(
            "{} ({}; exit truth {:?}, engine {:?}): {}\n{}",
            v.class.name(),
            ic.mode,
            v.exit_truth,
            v.exit_engine,
            why.join("; "),
            ic.to_json_line("fuzz-intervals", &[])
        );
    }
});
