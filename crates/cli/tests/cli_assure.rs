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
    assert!(stdout.contains("coverage (all modes)"), "{stdout}");
    assert!(
        stdout
            .lines()
            .last()
            .is_some_and(|l| l.starts_with("PASS: 0 missed detections")),
        "{stdout}"
    );
    // The coverage of one mode, as the rate of a class; an unknown mode names the known.
    let cov = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_polyguard"))
            .args(["assure", "coverage"])
            .arg(dir.join("report.json"))
            .args(args)
            .output()
            .expect("run polyguard assure coverage")
    };
    let view = cov(&["--mode", "free", "--class", "agree"]);
    assert_eq!(view.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&view.stdout).contains("coverage (modes free*): % agree"));
    let none = cov(&["--mode", "nosuchmode"]);
    assert_eq!(none.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&none.stderr).contains("the report has: along_edge"));
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

fn assure(args: &[&str], out: &std::path::Path) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .arg("assure")
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .expect("run polyguard assure");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn merge(
    reports: &[&std::path::Path],
    extra: &[&str],
    out: &std::path::Path,
) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args(["assure", "merge"])
        .args(reports.iter().map(|d| d.join("report.json")))
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .expect("run polyguard assure merge");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Two shards merge into exactly the unsharded run's counts, with every kept case's
/// files beside the merged report; merges that would lie (a shard missing or given twice,
/// shards of other campaigns) are refused with exit 2, and a partial one needs --partial
/// and says PARTIAL.
#[test]
fn merges_are_exact_or_refused() {
    let (whole, s0, s1, s0_other) = (
        out_dir("merge-whole"),
        out_dir("merge-s0"),
        out_dir("merge-s1"),
        out_dir("merge-s0-other-size"),
    );
    let base = ["--cases", "400", "--seed", "3", "--quiet"];
    for (dir, shard) in [(&whole, None), (&s0, Some("0/2")), (&s1, Some("1/2"))] {
        let mut args = base.to_vec();
        if let Some(s) = shard {
            args.extend(["--shard", s]);
        }
        let (code, out, err) = assure(&args, dir);
        assert!(code == 0 || code == 1, "{out}{err}");
    }
    let merged = out_dir("merge-out");
    let (code, out, err) = merge(&[&s0, &s1], &[], &merged);
    assert!(code == 0 || code == 1, "{out}{err}");
    let read = |d: &std::path::Path| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(d.join("report.json")).expect("report"))
            .expect("JSON")
    };
    let (m, w) = (read(&merged), read(&whole));
    for key in [
        "cases",
        "campaign_cases",
        "by_method",
        "by_mode",
        "contract",
        "by_bucket",
        "space",
        "kept",
    ] {
        assert_eq!(m[key], w[key], "{key}");
    }
    for k in m["kept"].as_array().expect("kept") {
        for f in ["case_file", "svg_file"] {
            let name = k[f].as_str().expect("file name");
            assert!(
                merged.join(name).is_file(),
                "{name} did not travel with the merge"
            );
        }
    }
    // Pictures left behind (as evidence/ files shards without them) are drawn again
    // from their case files, the same as the unsharded run's, byte for byte.
    let mut dropped = 0;
    for dir in [&s0, &s1] {
        for e in std::fs::read_dir(dir.join("counterexamples")).expect("kept cases") {
            let path = e.expect("entry").path();
            if path.extension().is_some_and(|x| x == "svg") {
                std::fs::remove_file(&path).expect("remove a picture");
                dropped += 1;
            }
        }
    }
    assert!(dropped > 0, "the shards kept no picture to drop");
    let redrawn = out_dir("merge-redrawn");
    let (code, out, err) = merge(&[&s0, &s1], &[], &redrawn);
    assert!(code == 0 || code == 1, "{out}{err}");
    for k in m["kept"].as_array().expect("kept") {
        let name = k["svg_file"].as_str().expect("file name");
        let again = std::fs::read(redrawn.join(name)).expect("a picture drawn again");
        let first = std::fs::read(whole.join(name)).expect("the unsharded picture");
        assert!(again == first, "{name} drawn again differs");
    }
    // one shard alone; a shard twice; a shard of another campaign size
    let (code, _, err) = merge(&[&s0], &[], &out_dir("merge-bad-1"));
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("shard 1 of 2 (1 shard) of the campaign are missing"),
        "{err}"
    );
    let (code, _, err) = merge(&[&s0, &s0], &[], &out_dir("merge-bad-2"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("count twice"), "{err}");
    let (code, _, err) = merge(&[&whole, &s1], &[], &out_dir("merge-bad-3"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("split"), "{err}");
    let (code, out, err) = assure(
        &["--cases", "500", "--seed", "3", "--quiet", "--shard", "0/2"],
        &s0_other,
    );
    assert!(code == 0 || code == 1, "{out}{err}");
    let (code, _, err) = merge(&[&s0_other, &s1], &[], &out_dir("merge-bad-4"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("500"), "{err}");
    // a partial merge is allowed when asked for, and says so
    let (code, out, err) = merge(&[&s0], &["--partial"], &out_dir("merge-partial"));
    assert!(code == 0 || code == 1, "{out}{err}");
    assert!(
        out.contains("PARTIAL: shard 1 of 2 (1 shard) of this"),
        "{out}"
    );
}

/// The hunt's canary: on the same cases, judging the plain transcription finds
/// missed detections (exit 1, kept and minimised), while the certified engine has none
/// (exit 0). A hunt that found nothing against the plain engine would be blind.
#[test]
fn the_plain_engine_is_caught_and_the_certified_one_is_not() {
    let args = ["--cases", "1000", "--seed", "1", "--quiet"];
    let (plain, certified) = (out_dir("hunt-plain"), out_dir("hunt-certified"));
    let mut with_plain = args.to_vec();
    with_plain.extend(["--engine", "plain"]);
    let (code, out, err) = assure(&with_plain, &plain);
    assert_eq!(code, 1, "{out}{err}");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(plain.join("report.json")).expect("report"))
            .expect("JSON");
    assert_eq!(report["engine"], "plain");
    let missed: u64 = report["by_method"]
        .as_object()
        .expect("by_method")
        .values()
        .filter_map(|m| m["missed_detection"].as_u64())
        .sum();
    assert!(missed >= 1, "{out}");
    let kept = report["kept"].as_array().expect("kept");
    assert!(
        kept.iter().any(|k| k["class"] == "missed_detection"),
        "{out}"
    );
    let (code, out, err) = assure(&args, &certified);
    assert_eq!(code, 0, "{out}{err}");
    // a merge keeps the verdict: the plain engine's misses still exit 1
    let (code, _, err) = merge(&[&plain], &[], &out_dir("hunt-merge"));
    assert_eq!(code, 1, "{err}");
    // and the two engines' shards cannot be merged as one campaign
    let mut shard_plain = with_plain.clone();
    shard_plain.extend(["--shard", "0/2"]);
    let (sp, sc) = (out_dir("hunt-plain-0"), out_dir("hunt-cert-1"));
    let _ = assure(&shard_plain, &sp);
    let mut shard_cert = args.to_vec();
    shard_cert.extend(["--shard", "1/2"]);
    let _ = assure(&shard_cert, &sc);
    let (code, _, err) = merge(&[&sp, &sc], &[], &out_dir("hunt-merge-mixed"));
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("plain engine") || err.contains("f64 engine"),
        "{err}"
    );
}

/// Runs `polyguard assure --paper b` with `args`; (exit code, stdout, report.json).
fn assure_b(args: &[&str], dir: &std::path::Path) -> (Option<i32>, String, serde_json::Value) {
    let out = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args(["assure", "--paper", "b", "--quiet", "--out"])
        .arg(dir)
        .args(args)
        .output()
        .expect("run polyguard assure --paper b");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let report = std::fs::read_to_string(dir.join("report.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or(serde_json::Value::Null);
    (out.status.code(), stdout, report)
}

/// Paper B's hunt: every case counted in one class, every generator mode drawn, the
/// shipped pipeline passes (exit 0, a PASS line), and the canary that samples once a
/// minute is caught (exit 1, failure cases kept with their scenario and picture).
#[test]
fn paper_b_hunt_passes_the_pipeline_and_catches_its_canary() {
    let dir = out_dir("assure-b");
    let (code, stdout, report) = assure_b(&["--cases", "1500", "--seed", "3"], &dir);
    assert_eq!(code, Some(0), "{stdout}");
    assert_eq!(report["paper"], "b");
    assert_eq!(report["cases"], 1500);
    let modes = report["by_mode"].as_object().expect("by_mode");
    let counted: u64 = modes
        .values()
        .flat_map(|m| m.as_object().expect("classes").values())
        .map(|n| n.as_u64().expect("count"))
        .sum();
    assert_eq!(counted, 1500);
    for m in [
        "touch_vertex",
        "touch_edge",
        "near_vertex",
        "graze",
        "parallel",
        "east_west",
        "crossing",
        "ends",
    ] {
        for place in ["mid", "polar", "antimeridian", "polar+antimeridian"] {
            let key = format!("{m}@{place}");
            assert!(modes.contains_key(&key), "mode {key} never drawn");
        }
    }
    assert!(
        stdout
            .lines()
            .last()
            .is_some_and(|l| l.starts_with("PASS: paper B, 1500 cases: 0 missed conflicts")),
        "{stdout}"
    );

    let canary = out_dir("assure-b-sampled");
    let (code, stdout, report) = assure_b(
        &["--cases", "1500", "--seed", "3", "--engine", "sampled"],
        &canary,
    );
    assert_eq!(code, Some(1), "{stdout}");
    assert_eq!(report["engine"], "sampled");
    let kept = report["kept"].as_array().expect("kept");
    let failing: Vec<&serde_json::Value> = kept
        .iter()
        .filter(|k| k["class"] == "window_short" || k["class"] == "missed_conflict")
        .collect();
    assert!(!failing.is_empty(), "{stdout}");
    for k in failing {
        // the kept scenario reads back as a scenario, with the verdict in its properties
        let file = canary.join(k["case_file"].as_str().expect("case_file"));
        let text = std::fs::read_to_string(&file).expect("case file");
        let read = polyguard_earth::scenario::parse(&text).expect("a scenario");
        assert!(read.errors.is_empty(), "{:?}", read.errors);
        assert_eq!(read.scenario.features.len(), 2);
        assert!(text.contains("\"assure\""));
        assert!(canary.join(k["svg_file"].as_str().expect("svg")).exists());
    }
    assert!(stdout
        .lines()
        .last()
        .is_some_and(|l| l.starts_with("FAIL: paper B")));
}

/// Paper-B shards merge into exactly the unsharded run's counts and kept cases; a missing
/// shard, a paper-A report among paper-B ones, or another seed is refused (exit 2).
#[test]
fn paper_b_shards_merge_exactly() {
    let whole = out_dir("assure-b-whole");
    let (code, _, full) = assure_b(
        &["--cases", "600", "--seed", "4", "--engine", "sampled"],
        &whole,
    );
    assert_eq!(code, Some(1));
    let mut parts = Vec::new();
    for i in 0..3 {
        let d = out_dir(&format!("assure-b-shard{i}"));
        let shard = format!("{i}/3");
        let (code, _, _) = assure_b(
            &[
                "--cases", "600", "--seed", "4", "--engine", "sampled", "--shard", &shard,
            ],
            &d,
        );
        assert!(matches!(code, Some(0 | 1)));
        parts.push(d.join("report.json"));
    }
    let merge = |reports: &[&std::path::PathBuf], extra: &[&str], out: &std::path::Path| {
        Command::new(env!("CARGO_BIN_EXE_polyguard"))
            .args(["assure", "merge"])
            .args(reports)
            .args(extra)
            .arg("--out")
            .arg(out)
            .output()
            .expect("run polyguard assure merge")
    };
    let m = out_dir("assure-b-merged");
    let r = merge(&parts.iter().collect::<Vec<_>>(), &[], &m);
    assert_eq!(
        r.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&r.stderr)
    );
    let merged: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(m.join("report.json")).expect("merged"))
            .expect("JSON");
    assert_eq!(merged["by_mode"], full["by_mode"]);
    assert_eq!(merged["cases"], full["cases"]);
    assert_eq!(merged["kept"], full["kept"]);
    for k in merged["kept"].as_array().expect("kept") {
        assert!(m.join(k["case_file"].as_str().expect("file")).exists());
    }
    // refused: a missing shard, another seed, a paper-A report
    let r = merge(&[&parts[0], &parts[1]], &[], &out_dir("assure-b-missing"));
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("2/3 are missing"));
    let other = out_dir("assure-b-other-seed");
    let _ = assure_b(&["--cases", "600", "--seed", "5", "--shard", "2/3"], &other);
    let r = merge(
        &[&parts[0], &parts[1], &other.join("report.json")],
        &[],
        &out_dir("assure-b-mixed-seed"),
    );
    assert_eq!(r.status.code(), Some(2));
    let a = out_dir("assure-a-for-b");
    let _ = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args(["assure", "--cases", "50", "--quiet", "--out"])
        .arg(&a)
        .output()
        .expect("run");
    let r = merge(
        &[&parts[0], &a.join("report.json")],
        &[],
        &out_dir("assure-b-mixed-paper"),
    );
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("paper B's and the rest paper A's"));
}

/// The progress lines of a campaign whose standard error is a pipe (no terminal: no bar):
/// one at every tenth of the cases, counts rising to the 100 % line, and none with
/// `--quiet`; for either paper. The canary's failures are counted as they come.
#[test]
fn a_piped_run_prints_progress_lines_unless_quiet() {
    let progress = |err: &str| -> Vec<(u64, u64, u64)> {
        err.lines()
            .filter_map(|l| {
                // polyguard assure: 60/200 cases (30 %), 0 s, 0 failures so far
                let rest = l.strip_prefix("polyguard assure: ")?;
                let (done, rest) = rest.split_once('/')?;
                let (total, rest) = rest.split_once(" cases (")?;
                let (_, rest) = rest.split_once(" %), ")?;
                let (_, rest) = rest.split_once(" s, ")?;
                let failures = rest.strip_suffix(" failures so far")?;
                Some((
                    done.parse().ok()?,
                    total.parse().ok()?,
                    failures.parse().ok()?,
                ))
            })
            .collect()
    };
    for (paper, engine, cases) in [("a", "plain", 400), ("b", "pipeline", 60)] {
        let n = cases.to_string();
        let args = [
            "--paper", paper, "--engine", engine, "--cases", &n, "--seed", "1",
        ];
        let (_, _, err) = assure(&args, &out_dir(&format!("assure-progress-{paper}")));
        let lines = progress(&err);
        assert!(lines.len() >= 10, "paper {paper}: {err}");
        assert_eq!(
            lines.last().map(|l| (l.0, l.1)),
            Some((cases, cases)),
            "{err}"
        );
        assert!(
            lines
                .windows(2)
                .all(|w| w[0].0 < w[1].0 && w[0].2 <= w[1].2),
            "{err}"
        );
        assert!(lines.iter().all(|l| l.1 == cases), "{err}");
        if paper == "a" {
            assert!(
                lines[lines.len() - 1].2 > 0,
                "the plain engine fails: {err}"
            );
        }
        let quiet = [&args[..], &["--quiet"]].concat();
        let (_, _, err) = assure(&quiet, &out_dir(&format!("assure-progress-{paper}-q")));
        assert!(progress(&err).is_empty(), "--quiet: {err}");
        assert!(!err.contains("cases ("), "--quiet: {err}");
    }
}

/// The interval hunt: a small run passes; two shards merge into exactly the unsharded
/// run's counts (kept cases with them); a shard given twice, a missing one without
/// --partial, and an interval report beside a paper-A one are refused; the drop-second
/// canary is caught keeping `interval_missed` cases.
#[test]
fn interval_hunts_pass_merge_exactly_and_catch_their_canary() {
    let dirs: Vec<PathBuf> = ["iv-0", "iv-1", "iv-all", "iv-merged", "iv-a", "iv-drop"]
        .iter()
        .map(|n| out_dir(n))
        .collect();
    let base = ["--intervals", "--cases", "80", "--seed", "7", "--quiet"];
    for (i, d) in dirs[..2].iter().enumerate() {
        let shard = format!("{i}/2");
        let (code, out, err) = assure(&[&base[..], &["--shard", &shard]].concat(), d);
        assert_eq!(code, 0, "{out}{err}");
    }
    let (code, out, err) = assure(&base, &dirs[2]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("PASS: 80 cases"), "{out}");
    let (code, out, err) = merge(&[&dirs[0], &dirs[1]], &[], &dirs[3]);
    assert_eq!(code, 0, "{out}{err}");
    let read = |d: &PathBuf| -> serde_json::Value {
        let text = std::fs::read_to_string(d.join("report.json")).expect("report.json");
        serde_json::from_str(&text).expect("JSON")
    };
    let (whole, merged) = (read(&dirs[2]), read(&dirs[3]));
    for key in ["cases", "classes", "relations", "modes", "exits"] {
        assert_eq!(whole[key], merged[key], "{key}");
    }
    let (code, _, err) = merge(&[&dirs[0], &dirs[0]], &[], &dirs[3]);
    assert_eq!(code, 2, "{err}");
    let (code, _, err) = merge(&[&dirs[0]], &[], &dirs[3]);
    assert_eq!(code, 2, "{err}");
    let (code, _, _) = assure(&["--cases", "20", "--quiet"], &dirs[4]);
    assert_eq!(code, 0);
    let (code, _, err) = merge(&[&dirs[0], &dirs[4]], &[], &dirs[3]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("interval hunts"), "{err}");
    let (code, out, err) = assure(
        &[
            "--intervals",
            "--engine",
            "drop-second",
            "--cases",
            "80",
            "--seed",
            "7",
            "--quiet",
        ],
        &dirs[5],
    );
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.lines().any(|l| l.starts_with("kept interval_missed ")),
        "{out}"
    );
}

/// The moving hunt: a small run passes; two shards merge into exactly the unsharded
/// run's counts; a moving report beside an interval one is refused; the fixes-only canary
/// is caught (exit 1) keeping `moving_missed` scenarios; `--canary` without
/// `--paper moving` is refused (exit 2).
#[test]
fn moving_hunts_pass_merge_exactly_and_catch_their_canary() {
    let dirs: Vec<PathBuf> = ["mv-0", "mv-1", "mv-all", "mv-merged", "mv-iv", "mv-canary"]
        .iter()
        .map(|n| out_dir(n))
        .collect();
    let base = [
        "--paper", "moving", "--cases", "40", "--seed", "5", "--quiet",
    ];
    for (i, d) in dirs[..2].iter().enumerate() {
        let shard = format!("{i}/2");
        let (code, out, err) = assure(&[&base[..], &["--shard", &shard]].concat(), d);
        assert_eq!(code, 0, "{out}{err}");
    }
    let (code, out, err) = assure(&base, &dirs[2]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("PASS: 40 scenarios"), "{out}");
    let (code, out, err) = merge(&[&dirs[0], &dirs[1]], &[], &dirs[3]);
    assert_eq!(code, 0, "{out}{err}");
    let read = |d: &PathBuf| -> serde_json::Value {
        let text = std::fs::read_to_string(d.join("report.json")).expect("report.json");
        serde_json::from_str(&text).expect("JSON")
    };
    let (whole, merged) = (read(&dirs[2]), read(&dirs[3]));
    assert_eq!(whole["hunt"], "moving");
    for key in ["cases", "segments", "classes", "relations", "modes"] {
        assert_eq!(whole[key], merged[key], "{key}");
    }
    let (code, _, _) = assure(&["--intervals", "--cases", "10", "--quiet"], &dirs[4]);
    assert_eq!(code, 0);
    let (code, _, err) = merge(&[&dirs[0], &dirs[4]], &[], &dirs[3]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("moving hunts"), "{err}");
    let canary = [&base[..], &["--canary", "fixes-only"]].concat();
    let (code, out, err) = assure(&canary, &dirs[5]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("FAIL: 40 scenarios"), "{out}");
    assert!(
        out.lines().any(|l| l.starts_with("kept moving_missed ")),
        "{out}"
    );
    let (code, _, err) = assure(&["--canary", "fixes-only", "--cases", "5"], &dirs[5]);
    assert_eq!(code, 2, "{err}");
}

/// The way-out hunt: a small run passes (seed 1's first 8 cases: bands, a recovery, an
/// inset); two shards of a canary run merge into exactly the unsharded run's counts and
/// worst cases; each canary is caught (exit 1) with its class kept as a regression line;
/// a way-out report beside a moving one is refused; a canary of the other hunt is
/// refused (exit 2).
#[test]
fn wayout_hunts_pass_merge_exactly_and_catch_their_canaries() {
    let dirs: Vec<PathBuf> = [
        "wo-real",
        "wo-0",
        "wo-1",
        "wo-all",
        "wo-merged",
        "wo-bands",
        "wo-mv",
    ]
    .iter()
    .map(|n| out_dir(n))
    .collect();
    let (code, out, err) = assure(
        &[
            "--paper", "wayout", "--cases", "8", "--seed", "1", "--quiet",
        ],
        &dirs[0],
    );
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("PASS: 8 cases"), "{out}");
    let offsets = [
        "--paper",
        "wayout",
        "--canary",
        "bisector-offset",
        "--cases",
        "6",
        "--seed",
        "1",
        "--quiet",
    ];
    for (i, d) in dirs[1..3].iter().enumerate() {
        let shard = format!("{i}/2");
        let (code, out, err) = assure(&[&offsets[..], &["--shard", &shard]].concat(), d);
        assert!(code == 0 || code == 1, "{out}{err}");
    }
    let (code, out, err) = assure(&offsets, &dirs[3]);
    assert_eq!(code, 1, "{out}{err}");
    let kept = out
        .lines()
        .find(|l| l.starts_with("kept offset_misses_buffer "))
        .unwrap_or_else(|| panic!("{out}"));
    let file = kept.rsplit(' ').next().unwrap_or_default();
    let line = std::fs::read_to_string(dirs[3].join(file)).expect("the regression line");
    let case: serde_json::Value = serde_json::from_str(line.trim()).expect("one JSON line");
    assert_eq!(case["meta"]["class"], "offset_misses_buffer");
    assert_eq!(case["kind"], "offset");
    let (code, out, err) = merge(&[&dirs[1], &dirs[2]], &[], &dirs[4]);
    assert_eq!(code, 1, "{out}{err}");
    let read = |d: &PathBuf| -> serde_json::Value {
        let text = std::fs::read_to_string(d.join("report.json")).expect("report.json");
        serde_json::from_str(&text).expect("JSON")
    };
    let (whole, merged) = (read(&dirs[3]), read(&dirs[4]));
    assert_eq!(whole["hunt"], "wayout");
    for key in [
        "cases",
        "failed_cases",
        "classes",
        "modes",
        "mode_cases",
        "kept",
    ] {
        assert_eq!(whole[key], merged[key], "{key}");
    }
    assert!(dirs[4].join(file).exists());
    wayout_refusals_and_the_bands_canary(&dirs[1], &dirs[4], &dirs[5], &dirs[6]);
}

/// The sampled-bands canary is caught; a way-out report beside a moving one is
/// refused; a canary of the other hunt is refused (exit 2).
fn wayout_refusals_and_the_bands_canary(
    shard: &std::path::Path,
    merged: &std::path::Path,
    bands: &std::path::Path,
    moving: &std::path::Path,
) {
    let (code, out, err) = assure(
        &[
            "--paper",
            "wayout",
            "--canary",
            "sampled-bands",
            "--cases",
            "10",
            "--seed",
            "1",
            "--quiet",
        ],
        bands,
    );
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.lines().any(|l| l.starts_with("kept wrong_clear ")),
        "{out}"
    );
    let (code, _, _) = assure(&["--paper", "moving", "--cases", "4", "--quiet"], moving);
    assert_eq!(code, 0);
    let (code, _, err) = merge(&[shard, moving], &[], merged);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("way-out hunts"), "{err}");
    let (code, _, err) = assure(
        &[
            "--paper",
            "wayout",
            "--canary",
            "fixes-only",
            "--cases",
            "2",
        ],
        moving,
    );
    assert_eq!(code, 2, "{err}");
}
