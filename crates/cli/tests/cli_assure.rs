//! `polyguard assure` end to end: the report, the exit status, a reader that goes away.

use std::path::PathBuf;
use std::process::{Command, Stdio};

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// A small campaign writes report.json with every case counted, and exits 0 when it
/// finds no missed detection and no far false alarm (seed 1's first 300 cases have none).
#[test]
fn small_campaign_writes_its_report() {
    let dir = out_dir("assure-small");
    let out = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args([
            "assure", "--cases", "300", "--seed", "1", "--quiet", "--out",
        ])
        .arg(&dir)
        .output()
        .expect("run polyguard assure");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("detect_diff_2d") && stdout.contains("missed_detection"));
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).expect("report"))
            .expect("report.json is JSON");
    assert_eq!(report["cases"], 300);
    let counted: u64 = report["by_method"]
        .as_object()
        .expect("by_method")
        .values()
        .flat_map(|m| m.as_object().expect("classes").values())
        .map(|n| n.as_u64().expect("count"))
        .sum();
    assert_eq!(counted, 300);
}

/// `polyguard assure | head` used to lose the report: the summary was printed first and a
/// closed standard output panicked before report.json was written. The reader goes away
/// here before the campaign has printed anything.
#[test]
fn closed_stdout_still_writes_the_report() {
    let dir = out_dir("assure-closed-stdout");
    let mut child = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args([
            "assure", "--cases", "200", "--seed", "2", "--quiet", "--out",
        ])
        .arg(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn polyguard assure");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("wait");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(dir.join("report.json").is_file(), "{stderr}");
}
