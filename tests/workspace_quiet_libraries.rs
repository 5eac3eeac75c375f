//! No library function prints or draws progress: the engine, the oracle, paper B and the
//! harness return what they found, and only the command-line tool's `commands` module
//! (and `main.rs`) write to the terminal. A library that prints corrupts the output of a
//! program that embeds it (a JSON Lines stream on standard output, for one).

use std::path::{Path, PathBuf};

/// The library sources: a file, or a directory read recursively.
const LIBRARY_SOURCES: [&str; 5] = [
    "src",
    "oracle/src",
    "crates/earth/src",
    "crates/cli/src/harness",
    "crates/cli/src/case.rs",
];

/// What printing looks like (built so that this file does not contain the macros).
fn printing() -> Vec<String> {
    vec![
        ["print", "ln!("].concat(),
        ["eprint", "ln!("].concat(),
        ["print", "!("].concat(),
        ["eprint", "!("].concat(),
        ["indi", "catif::"].concat(),
        ["std::io::std", "out()"].concat(),
        ["std::io::std", "err()"].concat(),
    ]
}

/// Lines of `text` outside its `#[cfg(test)]` module that print, as "line: text".
fn prints(text: &str) -> Vec<String> {
    let pats = printing();
    let mut out = Vec::new();
    for (no, line) in text.lines().enumerate() {
        // unit tests sit at the end of a file, after their cfg attribute
        if line.trim() == "#[cfg(test)]" {
            break;
        }
        let code = line.split("//").next().unwrap_or("");
        if pats.iter().any(|p| code.contains(p.as_str())) {
            out.push(format!("{}: {}", no + 1, line.trim()));
        }
    }
    out
}

fn rust_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_file() {
        out.push(path.to_path_buf());
        return;
    }
    let Ok(entries) = std::fs::read_dir(path) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().and_then(|x| x.to_str()) == Some("rs") {
            out.push(p);
        }
    }
}

#[test]
fn libraries_do_not_print() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for s in LIBRARY_SOURCES {
        rust_files(&root.join(s), &mut files);
    }
    assert!(files.len() > 50, "only {} library files found", files.len());
    let mut bad = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap_or_default();
        for hit in prints(&text) {
            bad.push(format!("{}:{hit}", f.display()));
        }
    }
    assert!(bad.is_empty(), "library code that prints: {bad:#?}");
}

/// The canary: a spinner or a println outside the unit tests is flagged; one inside them,
/// or in a comment, is not.
#[test]
fn canary_printing_is_flagged() {
    let spinner = ["let b = indi", "catif::ProgressBar::new_spinner();"].concat();
    let say = ["    eprint", "ln!(\"done\");"].concat();
    let text = format!(
        "fn f() {{\n    {spinner}\n}}\n// {say}\nfn g() {{\n{say}\n}}\n#[cfg(test)]\nmod tests {{\n{say}\n}}\n"
    );
    let hits = prints(&text);
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!(
        hits[0].starts_with("2: ") && hits[1].starts_with("6: "),
        "{hits:?}"
    );
}
