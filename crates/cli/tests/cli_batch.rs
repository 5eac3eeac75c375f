//! `polyguard detect-batch` end to end: the example files and a generated workload
//! against `polyguard detect` on every pair as a case line (the pairwise engine), bad
//! lines, option errors.

mod common;

use serde_json::{json, Value};
use std::collections::BTreeSet;

fn json_lines(s: &str) -> Vec<Value> {
    s.lines()
        .map(|l| serde_json::from_str(l).expect("output is JSON"))
        .collect()
}

fn file_lines(path: &std::path::Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .expect("readable")
        .lines()
        .map(str::to_owned)
        .collect()
}

/// (point, polygon, kind, method) of every pair that `polyguard detect` detects, the
/// pairs built as case lines from the two files' lines (all good) with T and BUFF.
fn pairwise(points: &[String], polygons: &[String], t: f64, buff: f64) -> BTreeSet<Hit> {
    let mut input = String::new();
    let mut pairs = Vec::new();
    for (i, p) in points.iter().enumerate() {
        for (j, q) in polygons.iter().enumerate() {
            let p: Value = serde_json::from_str(p).unwrap();
            let q: Value = serde_json::from_str(q).unwrap();
            let case = json!({"lookahead": t, "buff": buff, "point": p, "polygon": q});
            input.push_str(&format!("{case}\n"));
            pairs.push((i, j));
        }
    }
    // through a file: thousands of cases on standard input would fill the pipes both ways
    let file = std::env::temp_dir().join(format!(
        "polyguard-cli-batch-pairs-{}-{}.jsonl",
        std::process::id(),
        pairs.len()
    ));
    std::fs::write(&file, &input).unwrap();
    let (out, err, code) = common::run(&["detect", file.to_str().unwrap()], b"");
    let _ = std::fs::remove_file(&file);
    assert_eq!(code, 0, "{err}");
    let answers = json_lines(&out);
    assert_eq!(answers.len(), pairs.len());
    pairs
        .iter()
        .zip(&answers)
        .filter(|(_, a)| a["detected"] == true)
        .map(|(&(i, j), a)| {
            (
                i as u64,
                j as u64,
                a["kind"].as_str().unwrap().to_owned(),
                a["decided_by"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

type Hit = (u64, u64, String, String);

fn hits(out: &str) -> BTreeSet<Hit> {
    json_lines(out)
        .iter()
        .map(|h| {
            (
                h["point"].as_u64().unwrap(),
                h["polygon"].as_u64().unwrap(),
                h["kind"].as_str().unwrap().to_owned(),
                h["method"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

/// The example of docs/batch.md: its hits are the pairwise engine's, and they are the
/// ones the example was written for (a crossing, a pass within BUFF, a warping polygon,
/// a polygon drifting over a point at rest; a pass 0.5 off and a far point miss).
#[test]
fn the_example_is_the_pairwise_engine() {
    let root = common::root();
    let (points, polygons) = (
        file_lines(&root.join("examples/batch-points.jsonl")),
        file_lines(&root.join("examples/batch-polygons.jsonl")),
    );
    let (out, err, code) = common::run(
        &[
            "detect-batch",
            "examples/batch-points.jsonl",
            "examples/batch-polygons.jsonl",
            "--lookahead",
            "10",
            "--buff",
            "0.1",
        ],
        b"",
    );
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("4 hits"), "{err}");
    let got = hits(&out);
    assert_eq!(got, pairwise(&points, &polygons, 10.0, 0.1));
    let pairs: Vec<(u64, u64)> = got.iter().map(|h| (h.0, h.1)).collect();
    assert_eq!(pairs, [(0, 0), (1, 0), (3, 1), (4, 2)]);
    // output order: by point, then polygon
    let lines = json_lines(&out);
    let order: Vec<(u64, u64)> = lines
        .iter()
        .map(|h| (h["point"].as_u64().unwrap(), h["polygon"].as_u64().unwrap()))
        .collect();
    assert_eq!(order, pairs);
}

/// A generated workload (2D and 3D): detect-batch's hits are detect's on every pair.
#[test]
fn a_generated_workload_is_the_pairwise_engine() {
    let dir = std::env::temp_dir().join(format!("polyguard-cli-batch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for three_d in [false, true] {
        let (p, q) = (dir.join("p.jsonl"), dir.join("q.jsonl"));
        let (ps, qs) = (p.to_str().unwrap(), q.to_str().unwrap());
        let mut gen = vec![
            "detect-batch",
            "--generate",
            "150",
            "40",
            "--seed",
            "5",
            ps,
            qs,
        ];
        if three_d {
            gen.push("--three-d");
        }
        let (_, err, code) = common::run(&gen, b"");
        assert_eq!(code, 0, "{err}");
        assert!(err.contains("--lookahead 10 --buff 0.05"), "{err}");
        let (out, err, code) = common::run(
            &[
                "detect-batch",
                ps,
                qs,
                "--lookahead",
                "10",
                "--buff",
                "0.05",
            ],
            b"",
        );
        assert_eq!(code, 0, "{err}");
        let got = hits(&out);
        assert!(got.len() > 5, "{three_d}: {} hits", got.len());
        assert_eq!(got, pairwise(&file_lines(&p), &file_lines(&q), 10.0, 0.05));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Bad lines: each named by file, line and field, skipped; the good ones answered with
/// their own line indexes; exit status 1. Unknown fields and mixed dimensions are bad
/// lines.
#[test]
fn bad_lines_are_named_and_skipped() {
    let dir = std::env::temp_dir().join(format!("polyguard-cli-batch-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (p, q) = (dir.join("p.jsonl"), dir.join("q.jsonl"));
    std::fs::write(
        &p,
        concat!(
            "{\"pos\": [5, -5], \"vel\": [0, NaN]}\n",
            "{\"pos\": [1, -5], \"vel\": [0, 1]}\n",
            "\n",
            "{\"pos\": [1, -5], \"vell\": [0, 1]}\n",
            "{\"pos\": [1, -5, 3], \"vel\": [0, 1, 0]}\n",
            "[1, 2]\n",
            "{\"pos\": [1, 9], \"vel\": [0, -1]}\n",
        ),
    )
    .unwrap();
    std::fs::write(
        &q,
        concat!(
            "{\"vertices\": [[0, 0], [0, 2], [2, 2], [2, 0]]}\n",
            "{\"vertices\": [[0, 0], [2, 0], [2, 2], [0, 2]]}\n",
            "{\"vertices\": [[0, 0], [2, 0], [2, 2]], \"velocities\": [[0, 0]]}\n",
        ),
    )
    .unwrap();
    let (ps, qs) = (p.to_str().unwrap(), q.to_str().unwrap());
    let (out, err, code) = common::run(
        &["detect-batch", ps, qs, "--lookahead", "10", "--buff", "0.1"],
        b"",
    );
    assert_eq!(code, 1, "{err}");
    let lines = json_lines(&out);
    let errors: Vec<(String, u64, String)> = lines
        .iter()
        .filter(|l| l.get("error").is_some())
        .map(|l| {
            (
                l["file"].as_str().unwrap().to_owned(),
                l["line"].as_u64().unwrap(),
                l["error"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    let at = |file: &str, line: u64| {
        errors
            .iter()
            .find(|e| e.0 == file && e.1 == line)
            .map(|e| e.2.clone())
            .unwrap_or_else(|| panic!("no error for {file} line {line}: {errors:?}"))
    };
    assert_eq!(errors.len(), 6, "{errors:?}");
    assert!(
        at(ps, 1).starts_with("point.vel[1]: NaN is not a JSON number"),
        "{errors:?}"
    );
    assert_eq!(at(ps, 4), "point.vell: unknown field; did you mean vel?");
    assert!(at(ps, 5).starts_with("2D and 3D mixed"), "{errors:?}");
    assert!(
        at(ps, 6).starts_with("line: not a JSON object"),
        "{errors:?}"
    );
    assert!(
        at(qs, 1).starts_with("polygon.vertices: clockwise"),
        "{errors:?}"
    );
    assert!(
        at(qs, 3).starts_with("polygon.velocities: 1 velocity"),
        "{errors:?}"
    );
    // the good lines: points at lines 2 and 7 (indexes 1 and 6), the polygon at line 2
    let got: Vec<(u64, u64)> = hits(
        &lines
            .iter()
            .filter(|l| l.get("error").is_none())
            .map(|l| format!("{l}\n"))
            .collect::<String>(),
    )
    .iter()
    .map(|h| (h.0, h.1))
    .collect();
    assert_eq!(got, [(1, 1), (6, 1)]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Options out of range are refused before any file is read (exit 2), naming the option.
#[test]
fn bad_options_are_refused() {
    let ex = [
        "examples/batch-points.jsonl",
        "examples/batch-polygons.jsonl",
    ];
    for (opts, needle) in [
        (vec!["--lookahead", "0", "--buff", "0.1"], "--lookahead"),
        (vec!["--lookahead", "1", "--buff=-1"], "--buff"),
        // a negative number after a space is the option's value, not another option
        (
            vec!["--lookahead", "-1", "--buff", "0.1"],
            "--lookahead: -1",
        ),
        (
            vec!["--lookahead", "1", "--buff", "-0.1"],
            "--buff: buff: -0.1",
        ),
        (
            vec!["--lookahead", "1", "--buff", "0.1", "--fac", "1"],
            "--fac",
        ),
        (
            vec!["--lookahead", "1", "--buff", "0.1", "--kappa", "180"],
            "--kappa",
        ),
    ] {
        let mut args = vec!["detect-batch", ex[0], ex[1]];
        args.extend(opts);
        let (out, err, code) = common::run(&args, b"");
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty() && err.contains(needle), "{args:?}: {err}");
    }
    let (_, err, code) = common::run(
        &[
            "detect-batch",
            ex[0],
            "no-such-file.jsonl",
            "--lookahead",
            "1",
            "--buff",
            "1",
        ],
        b"",
    );
    assert_eq!(code, 2);
    assert!(err.contains("no-such-file.jsonl"), "{err}");
}
