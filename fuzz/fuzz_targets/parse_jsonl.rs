//! Arbitrary bytes into the case parser and `polyguard detect`'s line loop: never a panic.
//! A case that parses must also survive the round trip through the case format bit for bit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_harness::case::parse_line;
use polyguard_cli::commands::detect::{process, DetectArgs, Engine};
use polyguard_harness::case::RawCase;

/// Lines handed to `process` at most (each runs the engine once).
const MAX_LINES: usize = 8;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    for (k, line) in text.lines().enumerate().take(MAX_LINES) {
        let parsed = parse_line(line, k + 1);
        if let Ok(case) = parsed.case {
            let raw = RawCase::from_api(&case);
            let again = parse_line(&raw.to_json_line("round-trip", &[]), 1);
            match again.case {
                Ok(back) => assert_eq!(back, case, "the case format does not round-trip"),
                Err(e) => panic!("a valid case, written back, does not parse: {e}"),
            }
        }
    }
    // The raw bytes (not UTF-8 cleaned) through the streaming loop with the f64 engine.
    let end = data
        .iter()
        .enumerate()
        .filter(|(_, &b)| b == b'\n')
        .nth(MAX_LINES - 1)
        .map_or(data.len(), |(i, _)| i);
    let args = DetectArgs {
        file: None,
        engine: Engine::F64,
        repeat: 1,
        timing: false,
        kappa: polyguard_harness::case::DEFAULT_KAPPA_DEG,
        case_timeout: None,
        time: false,
    };
    let mut out = Vec::new();
    if let Err(e) = process(&data[..end], &mut out, &args) {
        panic!("process failed on an in-memory reader: {e}");
    }
});
