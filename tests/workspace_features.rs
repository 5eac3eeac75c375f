//! Every `feature = "…"` named in a `cfg` of a package's sources is a feature that package
//! declares. A cfg on a feature the package does not have is silently false: when the
//! crates were split, `#![cfg(feature = "cli")]` on a test file would have compiled it to
//! nothing, and the test would have "passed" without running.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The workspace's packages (and the fuzz crate): directory, and the directories below it
/// that belong to another package.
const PACKAGES: [(&str, &[&str]); 5] = [
    (".", &["oracle", "crates", "fuzz", "target", ".git"]),
    ("oracle", &["target"]),
    ("crates/earth", &["target"]),
    ("crates/cli", &["target"]),
    ("fuzz", &["target", "corpus", "artifacts", "coverage"]),
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The feature names a Cargo.toml declares in its `[features]` table.
fn declared(manifest: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut in_features = false;
    for line in manifest.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            in_features = line == "[features]";
            continue;
        }
        if in_features && !line.starts_with('#') {
            if let Some((name, _)) = line.split_once('=') {
                out.insert(name.trim().to_owned());
            }
        }
    }
    out
}

/// Every `feature = "NAME"` in the text, with its line number; `target_feature = "…"`
/// names a CPU feature, not a package's, and is left out.
fn used(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (no, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(at) = rest.find("feature = \"") {
            let cpu = rest[..at].ends_with("target_");
            rest = &rest[at + "feature = \"".len()..];
            if let Some(end) = rest.find('"') {
                if !cpu {
                    out.push((no + 1, rest[..end].to_owned()));
                }
                rest = &rest[end..];
            }
        }
    }
    out
}

fn rust_files(dir: &Path, skip: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if !skip.contains(&name.as_str()) {
                rust_files(&p, &[], out);
            }
        } else if name.ends_with(".rs") {
            out.push(p);
        }
    }
}

/// The cfg features of `text` that `features` lacks, as "path:line: feature".
fn undeclared(path: &str, text: &str, features: &BTreeSet<String>) -> Vec<String> {
    used(text)
        .into_iter()
        .filter(|(_, f)| !features.contains(f))
        .map(|(no, f)| format!("{path}:{no}: feature \"{f}\""))
        .collect()
}

#[test]
fn every_cfg_feature_is_declared_by_its_package() {
    let mut bad = Vec::new();
    let mut files_read = 0;
    for (dir, skip) in PACKAGES {
        let pkg = root().join(dir);
        let manifest = std::fs::read_to_string(pkg.join("Cargo.toml"))
            .unwrap_or_else(|e| panic!("{dir}/Cargo.toml: {e}"));
        let features = declared(&manifest);
        let mut files = Vec::new();
        rust_files(&pkg, skip, &mut files);
        for f in files {
            // this file names features in its own text and canary
            if f.ends_with("tests/workspace_features.rs") {
                continue;
            }
            let text = std::fs::read_to_string(&f).unwrap_or_default();
            files_read += 1;
            bad.extend(undeclared(&f.display().to_string(), &text, &features));
        }
    }
    assert!(files_read > 100, "only {files_read} source files read");
    assert!(
        bad.is_empty(),
        "cfg on features the package lacks: {bad:#?}"
    );
}

/// The canary: the check flags a cfg on a feature that is not declared, and passes one
/// that is.
#[test]
fn canary_a_missing_feature_is_flagged() {
    let features =
        declared("[features]\ndefault = [\"std\"]\nstd = []\n[dependencies]\nx = \"1\"\n");
    assert_eq!(
        features,
        BTreeSet::from(["default".to_owned(), "std".to_owned()])
    );
    let text = "#![cfg(feature = \"std\")]\n#[cfg(all(feature = \"cli\", feature = \"std\"))]\n\
                #[cfg(all(target_feature = \"avx\", feature = \"avx\"))]\n";
    assert_eq!(
        undeclared("t.rs", text, &features),
        vec![
            "t.rs:2: feature \"cli\"".to_owned(),
            "t.rs:3: feature \"avx\"".to_owned()
        ]
    );
}
