//! Engine vs exact oracle on boundary-biased Warping cases decoded from the input;
//! aborts on missed_detection, false_alarm_far and time_outside (see fuzz/README.md).
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_harness::gen::Shape;

fuzz_target!(|data: &[u8]| {
    polyguard_fuzz::differential(data, Shape::Warping);
});
