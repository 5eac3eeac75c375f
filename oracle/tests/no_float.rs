//! No binary floating point in any decision: every source file of the oracle
//! (src/ and all its subdirectories) except the three listed below must be free of
//! the tokens for the two float types.
//!
//! The exceptions are listed, not silently skipped:
//! - src/moving/input.rs, the planar model's inputs as the engine gives them (f64
//!   fields), made exact there at once; the moving truth decides on rationals only.
//! - src/convert.rs, the exact conversion of f64 inputs to rationals (and of exact
//!   times back to the nearest f64 for printing): f64 is its interface.
//! - src/kernel/interval.rs, the interval kernel in front of the exact one. Its
//!   floats only *certify* signs with rigorous interval arithmetic (outward rounding
//!   on every operation, enclosures of the inputs checked exactly); whenever an
//!   interval cannot certify a sign, it abstains and the exact kernel decides. Every
//!   decision thus remains exact, and tests/kernels.rs checks that interval-then-exact
//!   and exact-only answers are identical.

use std::path::{Path, PathBuf};

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

/// Files allowed to name the float types (see the module doc), relative to src/.
const EXEMPT: [&str; 3] = ["convert.rs", "kernel/interval.rs", "moving/input.rs"];

/// Every .rs file below `dir`, with its path relative to `root` ('/'-separated).
fn sources(root: &Path, dir: &Path, out: &mut Vec<(String, PathBuf)>) {
    let entries = std::fs::read_dir(dir).expect("source directory is readable");
    for e in entries.flatten() {
        let path = e.path();
        if path.is_dir() {
            sources(root, &path, out);
        } else if path.extension().and_then(|x| x.to_str()) == Some("rs") {
            let rel = path.strip_prefix(root).unwrap_or(&path);
            let rel: Vec<_> = rel.iter().filter_map(|c| c.to_str()).collect();
            out.push((rel.join("/"), path));
        }
    }
}

#[test]
fn no_float_outside_convert_and_the_interval_kernel() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &src, &mut files);
    let mut checked = Vec::new();
    let mut bad = Vec::new();
    for (rel, path) in &files {
        if EXEMPT.contains(&rel.as_str()) {
            continue;
        }
        let text = std::fs::read_to_string(path).expect("source is readable");
        checked.push(rel.clone());
        for line in float_tokens(&text) {
            bad.push(format!("{rel}:{line}"));
        }
    }
    // The exemptions exist (a renamed file must not leave a stale, silent entry),
    // and the subdirectories are scanned.
    for e in EXEMPT {
        assert!(files.iter().any(|(rel, _)| rel == e), "{e} is not in src/");
    }
    assert!(
        checked.iter().any(|rel| rel.starts_with("kernel/")),
        "src/kernel/ was not scanned: {checked:?}"
    );
    assert!(checked.len() >= 12, "only {} files checked", checked.len());
    assert!(
        bad.is_empty(),
        "float types outside convert.rs, kernel/interval.rs and moving/input.rs: {bad:?}"
    );
}

#[test]
fn the_check_catches_floats() {
    let probe = ["let x: ", "f", "64", " = 1.0;"].concat();
    assert_eq!(float_tokens(&probe), vec![1]);
    assert!(float_tokens("fn from_f64(c: &CaseF64) {}").is_empty());
}
