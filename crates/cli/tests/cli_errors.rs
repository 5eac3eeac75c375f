//! Every kind of bad input the formats name, end to end through the binary: the error
//! names the field and the line, keeps the id when it could be read, and the lines or
//! features after it are still answered (docs/cases.md, docs/scenario.md).

use serde_json::Value;

mod common;

fn run(args: &[&str], input: &str) -> (String, String, i32) {
    common::run(args, input.as_bytes())
}

const GOOD: &str = r#"{"id":"wx","lookahead":10,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]}}"#;

/// `bad` between two good lines: its answer (line 2) and proof that line 3 was answered.
fn second_line(bad: &str, code_wanted: i32) -> Value {
    let after = GOOD.replace(r#""id":"wx""#, r#""id":"after""#);
    let input = format!("{GOOD}\n{bad}\n{after}\n");
    let (out, err, code) = run(&["detect"], &input);
    assert_eq!(
        code, code_wanted,
        "a failed line makes the exit status 1: {err}"
    );
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("every answer line is JSON"))
        .collect();
    assert_eq!(lines.len(), 3, "{out}");
    assert_eq!(lines[0]["detected"], Value::Bool(true));
    assert_eq!(lines[2]["id"], "after");
    assert_eq!(
        lines[2]["detected"],
        Value::Bool(true),
        "the line after is answered"
    );
    if code_wanted == 1 {
        assert_eq!(lines[1]["line"], 2);
    }
    lines[1].clone()
}

#[test]
fn each_case_error_names_field_line_and_id() {
    let with = |from: &str, to: &str| {
        let s = GOOD.replacen(from, to, 1);
        assert_ne!(s, GOOD, "{from}");
        s
    };
    let cases: Vec<(String, Value, &str)> = vec![
        (
            with(r#""velocities""#, r#""velocity""#),
            "wx".into(),
            "polygon.velocity: unknown field; did you mean velocities?",
        ),
        (
            with(r#""buff":0.01,"#, r#""buff":0.01,"buff":5,"#),
            "wx".into(),
            "line: not a JSON object: duplicate key `buff` at column 44",
        ),
        (
            with(r#""pos":[5,-3]"#, r#""pos":[NaN,-3]"#),
            "wx".into(),
            "point.pos[0]: NaN is not a JSON number; a case needs finite numbers",
        ),
        (
            with(r#""pos":[5,-3]"#, r#""pos":[5]"#),
            "wx".into(),
            "point.pos: 1 number, 2 (x, y) or 3 (x, y, z) expected",
        ),
        (
            with("[[0,0],[2,0],[2,2],[0,2]]", "[[0,0],[2,0],[0,2],[2,2]]"),
            "wx".into(),
            "polygon.vertices: edges 1–2 and 3–0 cross (vertices numbered from 0); \
             the polygon must not intersect itself",
        ),
        (
            with("[[0,0],[2,0],[2,2],[0,2]]", "[[0,0],[0,2],[2,2],[2,0]]"),
            "wx".into(),
            "polygon.vertices: clockwise order (signed area -4); list the vertices \
             counterclockwise",
        ),
        (
            with(r#""buff":0.01,"#, r#""buff":0.01,"kappa":200,"#),
            "wx".into(),
            "kappa: 200 is outside (0, 180) degrees",
        ),
        (
            with(r#""lookahead":10"#, r#""lookahead":-1"#),
            "wx".into(),
            "lookahead: -1 is not > 0",
        ),
        // a JSON number beyond f64's range fails serde_json's whole parse: the reader
        // finds its field, nested ones too, and keeps the id
        (
            with(r#""lookahead":10"#, r#""lookahead":1e400"#),
            "wx".into(),
            "lookahead: not a finite number",
        ),
        (
            with(
                r#""vertices":[[0,0],[2,0]"#,
                r#""vertices":[[0,0],[-2e400,0]"#,
            ),
            "wx".into(),
            "polygon.vertices[1][0]: not a finite number",
        ),
        (
            with(r#""vel":[0,1]"#, r#""vel":[0,1e309]"#),
            "wx".into(),
            "point.vel[1]: not a finite number",
        ),
        (
            "{\"id\":\"cut\",\"lookahead\":".into(),
            2.into(),
            "line: not a JSON object: EOF while parsing a value at column 24",
        ),
        ("\u{feff}".to_owned() + GOOD, "wx".into(), ""),
    ];
    for (bad, id, message) in cases {
        let a = second_line(&bad, if message.is_empty() { 0 } else { 1 });
        assert_eq!(a["id"], id, "{bad}");
        if message.is_empty() {
            // a byte-order mark is not an error
            assert_eq!(a["detected"], Value::Bool(true), "{a}");
            continue;
        }
        assert_eq!(a["error"], message, "{bad}");
    }
}

/// Every engine's answer carries `well_formed`, and the reason when it is false; the
/// truth engine's entry time is a number, with the exact value beside it.
#[test]
fn answers_carry_typed_values_for_every_engine() {
    // a sliver: its corner at (10, 0) is 5.7°, sharper than κ = 10°
    let sliver = r#"{"id":"s","lookahead":4,"buff":0.01,"kappa":10,"point":{"pos":[-2,0.25],"vel":[1,0]},"polygon":{"vertices":[[0,0],[10,0],[0,1]]}}"#;
    for engine in ["f64", "plain", "exact", "truth"] {
        let (out, err, code) = run(&["detect", "--engine", engine], &format!("{sliver}\n"));
        assert_eq!(code, 0, "{engine}: {err}");
        let a: Value = serde_json::from_str(out.trim()).expect("JSON");
        assert_eq!(a["well_formed"], Value::Bool(false), "{engine}: {a}");
        assert_eq!(
            a["well_formed_reason"], "§II.J rule 3: the corner at vertex 1 is sharper than κ",
            "{engine}"
        );
        assert_eq!(a["detected"], Value::Bool(true), "{engine}");
        if engine == "truth" {
            // enters at x = 0: t = 2 exactly
            assert_eq!(a["entry_time"], Value::from(2.0));
            assert_eq!(a["entry_time_exact"], "2/1");
        }
    }
    // the same case with κ = 5° (from the command line, the case's own kappa removed)
    let five = sliver.replace(r#""kappa":10,"#, "");
    let (out, _, _) = run(&["detect", "--kappa", "5"], &format!("{five}\n"));
    assert!(out.contains(r#""well_formed":true"#), "{out}");
    let (_, err, code) = run(&["detect", "--kappa", "0"], "");
    assert_eq!(code, 2);
    assert!(
        err.contains("--kappa: kappa: 0 is outside (0, 180) degrees"),
        "{err}"
    );
}

/// A run that cannot start exits 2 and names the path.
#[test]
fn a_run_that_cannot_start_names_the_path() {
    for sub in ["detect", "conflicts"] {
        let (_, err, code) = run(&[sub, "src"], "");
        assert_eq!(code, 2, "{sub}");
        assert!(err.contains("src"), "{sub}: {err}");
        let (_, err, code) = run(&[sub, "no/such/file.txt"], "");
        assert_eq!(code, 2, "{sub}");
        assert!(err.contains("no/such/file.txt"), "{sub}: {err}");
    }
}

/// The scenario of mistakes: every bad feature named by line, id and field; the good
/// ones still answered; unknown properties kept with a warning.
#[test]
fn each_scenario_error_names_field_line_and_id() {
    let path = "tests/scenarios/mistakes.geojson";
    let (out, err, code) = run(&["conflicts", path, "--no-regions", "--quiet"], "");
    assert_eq!(code, 1, "{err}");
    let a: Value = serde_json::from_str(&out).expect("the answer is JSON");
    let errors: Vec<(u64, &str, &str)> = a["errors"]
        .as_array()
        .expect("errors")
        .iter()
        .map(|e| {
            (
                e["line"].as_u64().unwrap_or(0),
                e["id"].as_str().unwrap_or(""),
                e["field"].as_str().unwrap_or(""),
            )
        })
        .collect();
    assert_eq!(
        errors,
        [
            (4, "typo", "properties.t_f"),
            (7, "bow-tie", "geometry.coordinates[0]"),
            (8, "twice", "properties.speed_kn"),
            (11, "nan", "properties.speed_kn"),
            (15, "end-on-a-track", "properties.tf"),
            (19, "pacific", "geometry.coordinates[1]"),
        ]
    );
    assert!(
        err.contains(
            "line 4: feature 1 (id \"typo\"), properties.t_f: unknown member; did you mean tf?"
        ),
        "{err}"
    );
    let warnings = a["warnings"].as_array().expect("warnings");
    assert_eq!(warnings.len(), 1);
    assert_eq!(warnings[0]["field"], "properties.colour");
    assert_eq!(warnings[0]["line"], 20);
    // the good features (one of them written clockwise) are answered
    let pairs: Vec<(String, String)> = a["conflicts"]
        .as_array()
        .expect("conflicts")
        .iter()
        .map(|c| (c["a"].to_string(), c["b"].to_string()))
        .collect();
    assert_eq!(pairs.len(), 3, "{pairs:?}");
    assert_eq!(a["stats"]["rejected_features"], 6);
}

/// `assure merge` reads reports strictly.
#[test]
fn a_report_with_a_typo_is_refused_by_merge() {
    let dir = std::env::temp_dir().join(format!("polyguard-merge-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join("report.json");
    std::fs::write(&p, r#"{"seed": 1, "shards": ["0/1"], "casse": 3}"#).expect("write");
    let ps = p.to_string_lossy().into_owned();
    let (_, err, code) = run(
        &["assure", "merge", &ps, "--out", &dir.to_string_lossy()],
        "",
    );
    assert_eq!(code, 2);
    assert!(
        err.contains("unknown field `casse`") && err.contains(&ps),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
