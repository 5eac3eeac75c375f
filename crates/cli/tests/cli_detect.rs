//! `polyguard detect` end to end: good and bad lines, order, exit status, engines.

mod common;

fn run(args: &[&str], input: &str) -> (String, String, i32) {
    common::run(args, input.as_bytes())
}

fn json_lines(s: &str) -> Vec<serde_json::Value> {
    s.lines()
        .map(|l| serde_json::from_str(l).expect("answer is JSON"))
        .collect()
}

const HIT: &str = r#"{"id":"hit","lookahead":10,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]}}"#;
const MISS: &str = r#"{"lookahead":2.5,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]}}"#;

#[test]
fn good_and_bad_lines_in_order() {
    let bad_vertices = r#"{"id":"few","lookahead":1,"buff":0.1,"point":{"pos":[0,0],"vel":[0,0]},"polygon":{"vertices":[[0,0],[1,0]]}}"#;
    let input = format!("{HIT}\n\nnot json\n{bad_vertices}\n{MISS}\n");
    let (out, err, code) = run(&["detect"], &input);
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 4, "{out}");
    assert_eq!(lines[0]["id"], "hit");
    assert_eq!(lines[0]["detected"], true);
    // "not json" is physical line 3 (the blank line 2 gets no answer).
    assert_eq!(lines[1]["id"], 3);
    assert_eq!(lines[1]["line"], 3);
    assert!(lines[1]["error"]
        .as_str()
        .is_some_and(|e| e.starts_with("line:")));
    assert_eq!(lines[2]["id"], "few");
    assert_eq!(
        lines[2]["error"],
        "polygon.vertices: 2 points, at least 3 are needed"
    );
    assert_eq!(lines[3]["id"], 5);
    assert_eq!(lines[3]["detected"], false);
    assert_eq!(code, 1, "exit status with failed lines");
    assert!(err.contains("2 line(s)"), "{err}");
    // The answer's first key is the id, as in the spec's example.
    assert!(out.starts_with(r#"{"id":"hit""#), "{out}");
}

#[test]
fn all_good_exits_zero_and_engines_agree_here() {
    let input = format!("{HIT}\n{MISS}\n");
    for engine in ["f64", "exact", "truth"] {
        let (out, _, code) = run(&["detect", "--engine", engine], &input);
        assert_eq!(code, 0, "{engine}");
        let lines = json_lines(&out);
        assert_eq!(lines[0]["detected"], true, "{engine}");
        assert_eq!(lines[1]["detected"], false, "{engine}");
    }
    // The truth gives the entry time: the point (5, −3 + t) reaches y = 0 at t = 3, when
    // the square (drifting east at 1) spans x ∈ [3, 5]: it enters at the corner (5, 0).
    let (out, _, _) = run(&["detect", "--engine", "truth"], HIT);
    assert_eq!(json_lines(&out)[0]["entry_time_exact"], "3/1");
}

#[test]
fn timing_reports_groups_on_stderr() {
    let (out, err, code) = run(
        &["detect", "--repeat", "50", "--timing"],
        &format!("{HIT}\n{MISS}\n"),
    );
    assert_eq!(code, 0);
    assert_eq!(json_lines(&out).len(), 2);
    assert!(err.contains("ns/call"), "{err}");
    assert!(
        err.lines()
            .any(|l| l.starts_with("2D") && l.contains("static") && l.contains(" 100 ")),
        "{err}"
    );
}

#[test]
fn missing_file_is_a_clear_error() {
    let (_, err, code) = run(&["detect", "/nonexistent/cases.jsonl"], "");
    assert_eq!(code, 2);
    assert!(err.contains("cannot read"), "{err}");
}

/// `--case-timeout`: a case that takes longer is answered by an error line naming the
/// option, and the lines after it are answered as usual; exit 1. Without the option every
/// case waits. The slow case: the exact truth's §II.J report on a 64k-vertex circle with
/// a BUFF larger than the circle, where every pair of vertices is within rule 1's reach
/// (2·10⁹ pairs visited by the sweep, seconds even in a release build).
#[test]
fn a_case_timeout_answers_the_slow_case_and_goes_on() {
    let n = 65_536;
    let verts: Vec<String> = (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            format!("[{}, {}]", 1e4 * a.cos(), 1e4 * a.sin())
        })
        .collect();
    let big = format!(
        r#"{{"id": "circle-64k", "lookahead": 10.0, "buff": 100000.0, "point": {{"pos": [-20000.0, 0.5], "vel": [1000.0, 0.0]}}, "polygon": {{"vertices": [{}]}}}}"#,
        verts.join(", ")
    );
    let small = r#"{"id": "square", "lookahead": 10.0, "buff": 0.01, "point": {"pos": [1.0, -3.0], "vel": [0.0, 1.0]}, "polygon": {"vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}}"#;
    let input = format!("{big}\n{small}\n{{oops\n{small}\n");
    let (out, err, code) = common::run(
        &["detect", "--engine", "truth", "--case-timeout", "0.5"],
        input.as_bytes(),
    );
    assert_eq!(code, 1, "{err}");
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("each answer is JSON"))
        .collect();
    assert_eq!(lines.len(), 4, "{out}");
    assert_eq!(lines[0]["id"], "circle-64k");
    assert_eq!(lines[0]["line"], 1);
    let e = lines[0]["error"].as_str().expect("an error");
    assert!(
        e.starts_with("case: no answer within 0.5 s (--case-timeout)"),
        "{e}"
    );
    for k in [1, 3] {
        assert_eq!(lines[k]["id"], "square");
        assert_eq!(lines[k]["detected"], true, "{}", lines[k]);
        assert!(lines[k]["entry_time"].is_number(), "{}", lines[k]);
    }
    assert!(lines[2]["error"]
        .as_str()
        .is_some_and(|e| e.starts_with("line:")));
    // a timeout that is not a positive number of seconds is refused before any line
    for bad in ["0", "-1", "NaN", "soon"] {
        let opt = format!("--case-timeout={bad}");
        let (_, err, code) = common::run(&["detect", &opt], small.as_bytes());
        assert_eq!(code, 2, "{bad}: {err}");
        assert!(err.contains("case-timeout"), "{err}");
    }
}

#[test]
fn time_encloses_the_truths_entry_time_on_the_examples() {
    let input = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/cases.jsonl"
    ))
    .expect("examples/cases.jsonl");
    let (timed, _, code) = run(&["detect", "--time"], &input);
    assert_eq!(code, 0, "{timed}");
    let (truth, _, _) = run(&["detect", "--engine", "truth"], &input);
    let (timed, truth) = (json_lines(&timed), json_lines(&truth));
    assert_eq!(timed.len(), truth.len());
    let mut kinds = std::collections::BTreeSet::new();
    for (a, t) in timed.iter().zip(&truth) {
        let entry = a["entry"].as_str().expect("entry with --time");
        kinds.insert(entry.to_string());
        match t["entry_time"].as_f64() {
            None => assert_ne!(entry, "enters", "{a} but the truth misses"),
            Some(time) => {
                assert_ne!(entry, "never", "{a} but the truth enters at {time}");
                let (lo, hi) = (a["entry_lo"].as_f64(), a["entry_hi"].as_f64());
                let (Some(lo), Some(hi)) = (lo, hi) else {
                    panic!("{a}: no enclosure")
                };
                assert!(lo <= time && time <= hi, "{a}: truth {time}");
                if entry == "enters" {
                    // the typical width: about T·2⁻³⁶
                    let t_end = 100.0;
                    assert!(hi - lo <= 1e-9 * t_end, "{a}: wide");
                }
            }
        }
    }
    assert_eq!(
        kinds.len(),
        3,
        "the examples show never, enters and possible: {kinds:?}"
    );
    // --time is the f64 engine's: asked of another, the run does not start.
    let (_, err, code) = run(&["detect", "--time", "--engine", "truth"], HIT);
    assert_eq!(code, 2);
    assert!(err.contains("--time"), "{err}");
}
