//! Arbitrary bytes into the case parser and the answer format: never a panic. A case that
//! parses must survive the round trip through the case format bit for bit, and get an
//! answer from the f64 engine with its entry-time enclosure (docs/cases.md, "Answers").
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_harness::answer::{answer, Ask, Engine};
use polyguard_harness::case::{parse_line, RawCase};
use serde_json::Map;

/// Lines read at most (each runs the engine once).
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
            let ask = Ask {
                time: true,
                ..Ask::of(Engine::F64)
            }
            .for_line(&parsed.options);
            let mut out = Map::new();
            if let Err(e) = answer(&case, ask, &mut out) {
                panic!("the f64 engine gave no answer to a valid case: {e}");
            }
            assert!(out.contains_key("detected") && out.contains_key("entry"));
        }
    }
});
