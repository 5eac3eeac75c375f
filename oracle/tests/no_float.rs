//! No binary floating point in any decision: every source file of the oracle
//! except src/convert.rs must be free of the tokens for the two float types.
//!
//! Two exceptions are listed, not silently skipped:
//! - src/filter.rs, the floating filter in front of the exact path. Its floats
//!   only *certify* signs with rigorous interval arithmetic (outward rounding on
//!   every operation, enclosures of the inputs checked exactly); whenever an
//!   interval cannot certify a sign, the exact code decides. Every decision thus
//!   remains exact, and tests/filtered.rs checks that the filtered and unfiltered
//!   oracles give identical answers.
//! - src/earth_ref.rs, paper B's MPFR reference for Mercator and rhumb lines
//!   (feature rug). It takes the engine's f64 inputs and measures the engine's f64
//!   outputs in ulps against 256-bit MPFR values: f64 is its interface, and it
//!   takes no decision of paper A. (Paper B's exact geometry, geom.rs, reads floats
//!   only through convert.rs.)

use std::path::Path;

fn float_tokens(text: &str) -> Vec<usize> {
    let forbidden = [["f", "32"].concat(), ["f", "64"].concat()];
    let mut hits = Vec::new();
    for (no, line) in text.lines().enumerate() {
        let found = line
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|tok| forbidden.iter().any(|f| f == tok));
        if found {
            hits.push(no + 1);
        }
    }
    hits
}

/// Files allowed to name the float types (see the module doc).
const EXEMPT: [&str; 3] = ["convert.rs", "filter.rs", "earth_ref.rs"];

#[test]
fn no_float_outside_convert() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut checked = 0;
    let mut bad = Vec::new();
    let entries = std::fs::read_dir(&src).expect("oracle/src is readable");
    for e in entries.flatten() {
        let path = e.path();
        if path.extension().and_then(|x| x.to_str()) != Some("rs") {
            continue;
        }
        let name = path.file_name().and_then(|x| x.to_str()).unwrap_or("");
        if EXEMPT.contains(&name) {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("source is readable");
        checked += 1;
        for line in float_tokens(&text) {
            bad.push(format!("{}:{line}", path.display()));
        }
    }
    assert!(checked >= 9, "only {checked} files checked");
    assert!(
        bad.is_empty(),
        "float types outside convert.rs, filter.rs and earth_ref.rs: {bad:?}"
    );
}

#[test]
fn the_check_catches_floats() {
    let probe = ["let x: ", "f", "64", " = 1.0;"].concat();
    assert_eq!(float_tokens(&probe), vec![1]);
    assert!(float_tokens("fn from_f64(c: &CaseF64) {}").is_empty());
}
