//! Nothing the project ships may point outside the repository: the formats live in
//! `docs/`, the papers are cited, not linked by path (a clone has no sibling folders).

use std::path::{Path, PathBuf};

/// The patterns, built so that this file does not contain them.
fn outside_patterns() -> Vec<String> {
    vec![
        ["..", "/shared"].concat(),
        ["shared", "/spec/"].concat(),
        ["shared", "/papers"].concat(),
        ["shared", "/design.md"].concat(),
    ]
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            // build output, fuzzing state and git internals are not shipped
            if !["target", ".git", "corpus", "artifacts", "coverage"].contains(&name.as_str()) {
                files(&p, out);
            }
        } else if [".rs", ".md", ".toml", ".sh", ".json", ".jsonl", ".geojson"]
            .iter()
            .any(|x| name.ends_with(x))
            || name == "run"
        {
            out.push(p);
        }
    }
}

/// The offending lines of `text`.
fn pointers(text: &str) -> Vec<usize> {
    let pats = outside_patterns();
    text.lines()
        .enumerate()
        .filter(|(_, l)| pats.iter().any(|p| l.contains(p.as_str())))
        .map(|(i, _)| i + 1)
        .collect()
}

#[test]
fn no_shipped_file_points_outside_the_repository() {
    // the canary: the check sees a pointer when there is one
    assert_eq!(
        pointers(&format!("see {}/spec/cases.md", ["..", "/shared"].concat())),
        [1]
    );
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    files(root, &mut all);
    assert!(all.len() > 50, "only {} files found", all.len());
    let bad: Vec<String> = all
        .iter()
        .flat_map(|p| {
            let text = std::fs::read_to_string(p).unwrap_or_default();
            pointers(&text)
                .into_iter()
                .map(move |l| format!("{}:{l}", p.display()))
        })
        .collect();
    assert!(bad.is_empty(), "pointers outside the repository: {bad:?}");
}

#[test]
fn the_format_docs_are_in_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for doc in ["docs/cases.md", "docs/scenario.md"] {
        let text = std::fs::read_to_string(root.join(doc)).unwrap_or_default();
        assert!(text.len() > 2000, "{doc} is missing or short");
    }
}
