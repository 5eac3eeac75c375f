//! The regression corpus `tests/regressions/*.jsonl`, replayed on every test run.
//!
//! Each line is a case of docs/cases.md with two annotations in its `meta` object:
//! `class`, the class `harness::classify` gave it when it was recorded, and `why`, why it
//! is there. The
//! replay parses the line with the CLI's parser, runs engine, paper-exact and truth
//! (`classify::compare`) and checks that the class still holds and that no certified
//! answer (yes or no) contradicts paper-exact. A recorded failure
//! (`missed_detection`, `false_alarm_far`) that now comes out better is reported as fixed:
//! update the line's class (and say so in its `why`), never delete it.

use std::fs;
use std::path::{Path, PathBuf};

use polyguard_harness::case::parse_line;
use polyguard_harness::case::RawCase;
use polyguard_harness::classify::{compare, Class};
use serde_json::Value;

fn corpus_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions");
    let mut files: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
        .collect();
    files.sort();
    files
}

/// One replayed line: where it is, and what went wrong (None when it still holds).
fn replay(file: &Path, line_no: usize, line: &str) -> Result<Class, String> {
    let at = format!("{}:{line_no}", file.display());
    let value: Value = serde_json::from_str(line).map_err(|e| format!("{at}: not JSON: {e}"))?;
    let meta = value.get("meta").cloned().unwrap_or(Value::Null);
    let recorded: Class = meta
        .get("class")
        .cloned()
        .ok_or_else(|| format!("{at}: no \"meta.class\" field"))
        .and_then(|c| serde_json::from_value(c).map_err(|e| format!("{at}: class: {e}")))?;
    match meta.get("why") {
        Some(Value::String(w)) if !w.trim().is_empty() => {}
        _ => {
            return Err(format!(
                "{at}: no \"meta.why\" field saying why the case is here"
            ))
        }
    }
    let id = value.get("id").cloned().unwrap_or(Value::Null);
    let case = parse_line(line, line_no)
        .case
        .map_err(|e| format!("{at} ({id}): the case does not parse: {e}"))?;
    let verdict = compare(&RawCase::from_api(&case))
        .map_err(|e| format!("{at} ({id}): cannot be compared: {e:?}"))?;
    let now = verdict.class;
    if verdict.certificate_breach {
        return Err(format!(
            "{at} ({id}): the engine certifies {} but paper-exact says {}: a certificate breach",
            verdict.engine, verdict.paper
        ));
    }
    if now == recorded {
        return Ok(now);
    }
    let answers = format!(
        "engine {}, paper-exact {}, truth {:?}, entry {:?}",
        verdict.engine, verdict.paper, verdict.truth, verdict.entry_time
    );
    if recorded.is_failure() && !now.is_failure() {
        Err(format!(
            "{at} ({id}): recorded {} now comes out {} ({answers}): it was fixed, update the \
             line's class to \"{}\" and say so in its why",
            recorded.name(),
            now.name(),
            now.name()
        ))
    } else {
        Err(format!(
            "{at} ({id}): recorded {}, now {} ({answers})",
            recorded.name(),
            now.name()
        ))
    }
}

#[test]
fn every_recorded_case_keeps_its_class() {
    let files = corpus_files();
    assert!(!files.is_empty(), "no tests/regressions/*.jsonl");
    let mut problems = Vec::new();
    let mut counts = std::collections::BTreeMap::<Class, usize>::new();
    for file in &files {
        let text = fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for (k, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            match replay(file, k + 1, line) {
                Ok(class) => *counts.entry(class).or_default() += 1,
                Err(p) => problems.push(p),
            }
        }
    }
    let total: usize = counts.values().sum();
    let summary: Vec<String> = counts
        .iter()
        .map(|(c, n)| format!("{} {n}", c.name()))
        .collect();
    println!(
        "regression corpus: {total} cases hold ({})",
        summary.join(", ")
    );
    assert!(
        problems.is_empty(),
        "{} regression line(s) changed class:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The canary of the corpus: the plain f64 transcription still misses every true entry of
/// `plain-canary.jsonl` (which the certified engine detects, checked above). If it stops
/// missing them, the cases no longer show what the certificate is for.
#[test]
fn the_plain_transcription_still_misses_the_canary_cases() {
    use polyguard_harness::classify::{compare_as, Hunted};
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions/plain-canary.jsonl");
    let text = fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let mut n = 0;
    for (k, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let case = parse_line(line, k + 1)
            .case
            .unwrap_or_else(|e| panic!("line {}: {e}", k + 1));
        let v = compare_as(&RawCase::from_api(&case), Hunted::Plain)
            .unwrap_or_else(|e| panic!("line {}: {e:?}", k + 1));
        assert_eq!(v.class, Class::MissedDetection, "line {}", k + 1);
        n += 1;
    }
    assert!(n >= 3, "only {n} canary cases");
}
