//! Arbitrary bytes into the scenario reader (docs/scenario.md): never a panic, every
//! error's line inside the text, and the typed fast path, whenever it accepts a file,
//! reads it exactly as the general path that names lines and fields.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_earth::scenario::{fast_parse, parse, parse_general};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    // a text of k newlines has k + 1 lines (the end of "\n" is on line 2)
    let lines = text.matches('\n').count() + 1;
    match parse(&text) {
        Ok(read) => {
            for e in &read.errors {
                let line = e.line.unwrap_or_else(|| panic!("an error without a line: {e}"));
                assert!((1..=lines).contains(&line), "line {line} of {lines}: {e}");
            }
            for w in &read.warnings {
                assert!((1..=lines).contains(&w.line), "line {} of {lines}: {w}", w.line);
            }
        }
        Err(e) => {
            let line = e.line.unwrap_or_else(|| panic!("a file error without a line: {e}"));
            assert!((1..=lines).contains(&line), "line {line} of {lines}: {e}");
        }
    }
    let body = text.strip_prefix('\u{feff}').unwrap_or(&text);
    if let Some(fast) = fast_parse(body) {
        assert!(fast.errors.is_empty() && fast.warnings.is_empty());
        assert_eq!(Ok(fast), parse_general(&text), "the fast path reads differently");
    }
});
