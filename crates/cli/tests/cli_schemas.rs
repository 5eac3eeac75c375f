//! The JSON Schemas of `docs/schema/` (draft 2020-12) checked against what the project
//! really reads and writes: every example and regression case line, every answer line of
//! `polyguard detect` with each engine, the example and generated scenarios and the
//! `polyguard conflicts` answers for them, and the JSON examples of docs/cases.md and
//! docs/scenario.md. Canaries check the other direction: inputs the readers reject must be
//! rejected by the schemas too (and each canary is first confirmed to be rejected by the
//! reader, so the schema and the code are compared, not the schema and a guess).

mod common;

use std::fs;
use std::path::{Path, PathBuf};

use common::root;
use jsonschema::Validator;
use serde_json::{json, Value};

const DRAFT_2020_12: &str = "https://json-schema.org/draft/2020-12/schema";

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// `docs/schema/NAME`, checked against the draft 2020-12 meta-schema and compiled.
fn schema(name: &str) -> Validator {
    let path = root().join("docs/schema").join(name);
    let value: Value = serde_json::from_str(&read(&path))
        .unwrap_or_else(|e| panic!("{}: not JSON: {e}", path.display()));
    assert_eq!(
        value["$schema"], DRAFT_2020_12,
        "{name}: $schema must name draft 2020-12"
    );
    if let Err(e) = jsonschema::draft202012::meta::validate(&value) {
        panic!("{name}: not a valid draft 2020-12 schema: {e}");
    }
    jsonschema::draft202012::new(&value).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The schema's complaints about `instance`, one per line, with their paths.
fn complaints(v: &Validator, instance: &Value) -> Vec<String> {
    v.iter_errors(instance)
        .map(|e| format!("  at {:?}: {e}", e.instance_path.as_str()))
        .collect()
}

/// `instance` as text, cut short (a generated scenario is tens of kilobytes).
fn shown(instance: &Value) -> String {
    let text = instance.to_string();
    match text.char_indices().nth(2000) {
        Some((cut, _)) => format!("{} …", &text[..cut]),
        None => text,
    }
}

#[track_caller]
fn assert_valid(v: &Validator, what: &str, instance: &Value) {
    let c = complaints(v, instance);
    assert!(
        c.is_empty(),
        "{what} does not validate:\n{}\n{}",
        c.join("\n"),
        shown(instance)
    );
}

#[track_caller]
fn assert_invalid(v: &Validator, what: &str, instance: &Value) {
    assert!(
        !v.is_valid(instance),
        "{what} validates but must not (canary):\n{}",
        shown(instance)
    );
}

fn parse(what: &str, text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{what}: not JSON: {e}\n{text}"))
}

/// The non-blank lines of a JSON Lines file, with their 1-based numbers.
fn jsonl(path: &Path) -> Vec<(usize, String)> {
    read(path)
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(k, l)| (k + 1, l.to_owned()))
        .collect()
}

/// tests/regressions/*.jsonl, as tests/paper_a_regressions.rs finds them.
fn regression_files() -> Vec<PathBuf> {
    let dir = root().join("tests/regressions");
    let mut files: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
        .collect();
    files.sort();
    files
}

/// Runs the built binary with `input` on standard input: (stdout, exit code).
fn polyguard(args: &[&str], input: &[u8]) -> (String, i32) {
    let (out, _, code) = common::run(args, input);
    (out, code)
}

// ---------------------------------------------------------------------------------------
// The case line

/// A good 2D case (crates/cli/src/case.rs's unit tests use the same).
const GOOD: &str = r#"{"id":"a","lookahead":10,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]}}"#;
/// A good 3D case.
const GOOD_3D: &str = r#"{"id":"z","lookahead":10,"buff":0.01,"point":{"pos":[-3,1,20],"vel":[1,0,-2]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"bottom":0,"top":10,"vz":0}}"#;

/// `base` with its first `from` replaced by `to` (which must be there).
fn edit(base: &str, from: &str, to: &str) -> String {
    let line = base.replacen(from, to, 1);
    assert_ne!(line, base, "{from:?} is not in the base line");
    line
}

fn reader_accepts(line: &str) -> Result<(), String> {
    polyguard_harness::case::parse_line(line, 1)
        .case
        .map(|_| ())
        .map_err(|e| e.to_string())
}

#[test]
fn every_example_and_regression_case_line_validates() {
    let v = schema("case.schema.json");
    let mut files = vec![root().join("examples/cases.jsonl")];
    files.extend(regression_files());
    let mut count = 0;
    for file in &files {
        for (n, line) in jsonl(file) {
            let what = format!("{}:{n}", file.display());
            assert_valid(&v, &what, &parse(&what, &line));
            count += 1;
        }
    }
    assert!(count >= 7, "only {count} case lines found");
    println!(
        "case.schema.json: {count} case lines of {} files validate",
        files.len()
    );
}

/// Lines the reader accepts and the schema must accept: nulls for optional fields, the
/// 3D form, meta, ids, kappa.
#[test]
fn the_readers_optional_forms_validate() {
    let v = schema("case.schema.json");
    let accepted = [
        GOOD.to_owned(),
        GOOD_3D.to_owned(),
        edit(GOOD, r#""id":"a","#, ""),
        edit(GOOD, r#""id":"a""#, r#""id":17"#),
        edit(
            GOOD,
            r#""buff":0.01,"#,
            r#""buff":0.01,"fac":null,"kappa":null,"#,
        ),
        edit(
            GOOD,
            r#""buff":0.01,"#,
            r#""buff":0.01,"fac":0.5,"kappa":179.9,"#,
        ),
        edit(
            GOOD,
            r#""id":"a","#,
            r#""id":"a","meta":{"class":"agree","n":[1]},"#,
        ),
        edit(
            GOOD,
            r#""velocities":[[1,0],[1,0],[1,0],[1,0]]"#,
            r#""velocities":null,"bottom":null,"top":null,"vz":null"#,
        ),
        edit(
            GOOD,
            r#","velocities":[[1,0],[1,0],[1,0],[1,0]]"#,
            r#","bottom":null"#,
        ),
        edit(GOOD_3D, r#""vz":0"#, r#""vz":-1.5,"velocities":null"#),
    ];
    for line in &accepted {
        reader_accepts(line).unwrap_or_else(|e| panic!("the reader rejects {line}: {e}"));
        assert_valid(&v, "an accepted case", &parse("case", line));
    }
    println!(
        "case.schema.json: {} optional-form lines validate",
        accepted.len()
    );
}

/// Lines the reader rejects: the schema must reject them too.
#[test]
fn the_case_schema_rejects_the_canaries() {
    let v = schema("case.schema.json");
    let canaries = [
        // the typo that once read a moving polygon as one at rest
        edit(GOOD, r#""velocities""#, r#""velocity""#),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":0.01,"fac":1.5,"#),
        edit(GOOD, r#""pos":[5,-3]"#, r#""pos":[5]"#),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":0.01,"kappa":180,"#),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":0.01,"fac":0,"#),
        edit(GOOD, r#""lookahead":10,"#, r#""lookahead":0,"#),
        edit(GOOD, r#""lookahead":10,"#, r#""lookahead":null,"#),
        edit(GOOD, r#""lookahead":10,"#, ""),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":-1,"#),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":"0.01","#),
        edit(GOOD, r#""buff":0.01,"#, r#""buff":0.01,"colour":"red","#),
        edit(GOOD, r#""vel":[0,1]"#, r#""vel":[0,1,2]"#),
        edit(GOOD, r#""vel":[0,1]"#, r#""velo":[0,1]"#),
        edit(GOOD, r#""pos":[5,-3]"#, r#""pos":[5,-3,1,2]"#),
        edit(GOOD, r#""pos":[5,-3]"#, r#""pos":[5,"-3"]"#),
        edit(GOOD, r#"[[0,0],[2,0],[2,2],[0,2]]"#, r#"[[0,0],[2,0]]"#),
        edit(
            GOOD,
            r#"[[0,0],[2,0],[2,2],[0,2]]"#,
            r#"[[0,0],[2,0],[2,2,1],[0,2]]"#,
        ),
        edit(GOOD, r#""vertices""#, r#""Vertices""#),
        edit(GOOD, r#""id":"a","#, r#""id":"a","meta":3,"#),
        edit(GOOD, r#""id":"a","#, r#""id":"a","meta":null,"#),
        // 2D and 3D mixed, in both directions
        edit(
            GOOD,
            r#""pos":[5,-3],"vel":[0,1]"#,
            r#""pos":[5,-3,1],"vel":[0,1,0]"#,
        ),
        edit(
            GOOD,
            r#""velocities""#,
            r#""bottom":0,"top":5,"vz":0,"velocities""#,
        ),
        // a slab of two fields, and one whose null field makes it two
        edit(GOOD_3D, r#","vz":0"#, ""),
        edit(GOOD_3D, r#""bottom":0"#, r#""bottom":null"#),
        edit(GOOD_3D, r#""top":10"#, r#""top":"10""#),
    ];
    for line in &canaries {
        assert!(
            reader_accepts(line).is_err(),
            "the reader accepts the canary {line}"
        );
        assert_invalid(&v, "a case the reader rejects", &parse("canary", line));
    }
    // What the schema cannot say (its $comment lists these): the reader alone rejects.
    let beyond = [
        edit(
            GOOD,
            r#"[[0,0],[2,0],[2,2],[0,2]]"#,
            r#"[[0,0],[0,2],[2,2],[2,0]]"#,
        ),
        edit(
            GOOD,
            r#"[[0,0],[2,0],[2,2],[0,2]]"#,
            r#"[[0,0],[2,0],[0,2],[2,2]]"#,
        ),
        edit(
            GOOD,
            r#"[[1,0],[1,0],[1,0],[1,0]]"#,
            r#"[[1,0],[1,0],[1,0]]"#,
        ),
        edit(GOOD_3D, r#""bottom":0,"top":10"#, r#""bottom":5,"top":1"#),
    ];
    for line in &beyond {
        assert!(reader_accepts(line).is_err(), "the reader accepts {line}");
        assert_valid(&v, "a rule beyond JSON Schema", &parse("case", line));
    }
    println!(
        "case.schema.json: {} canaries rejected, {} reader-only rules confirmed",
        canaries.len(),
        beyond.len()
    );
}

// ---------------------------------------------------------------------------------------
// The detect answer line

/// Lines that exercise every shape of answer: a case that is not well formed, an
/// irrational entry time, a case without id, one the truth engine cannot answer (the
/// polygon stops being simple), and bad lines of every sort (a non-UTF-8 line included).
fn detect_input() -> Vec<u8> {
    let mut input = read(&root().join("examples/cases.jsonl")).into_bytes();
    let extra = [
        r#"{"id":"sliver","lookahead":1,"buff":0.01,"kappa":10,"point":{"pos":[1,0.5],"vel":[0,0]},"polygon":{"vertices":[[0,0],[10,0],[0,1]]}}"#,
        r#"{"id":"irrational","lookahead":3,"buff":0.01,"point":{"pos":[1,-1],"vel":[0.0625,1]},"polygon":{"vertices":[[0,0],[2,0],[2,4],[0,4]],"velocities":[[0,0],[0,1],[0,0],[0,0]]}}"#,
        r#"{"id":"not-simple-later","lookahead":10,"buff":0.01,"point":{"pos":[1,-1],"vel":[0.0625,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[0,0],[0,1],[0,0],[0,0]]}}"#,
        r#"{"lookahead":2.5,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]]}}"#,
        "",
        "not json",
        "[1,2]",
        r#"{"id":"few","lookahead":1,"buff":0.1,"point":{"pos":[0,0],"vel":[0,0]},"polygon":{"vertices":[[0,0],[1,0]]}}"#,
        r#"{"id":"nan","lookahead":1,"buff":0.1,"point":{"pos":[NaN,0],"vel":[0,0]},"polygon":{"vertices":[[0,0],[1,0],[0,1]]}}"#,
        r#"{"id":"twice","lookahead":1,"buff":0.1,"buff":0.2,"point":{"pos":[0,0],"vel":[0,0]},"polygon":{"vertices":[[0,0],[1,0],[0,1]]}}"#,
        r#"{"id":{"odd":"id"},"lookahead":1,"buff":0.1,"point":{"pos":[0,0],"vel":[0,0]},"polygon":{"velocity":[],"vertices":[[0,0],[1,0],[0,1]]}}"#,
    ];
    for line in extra {
        input.extend_from_slice(line.as_bytes());
        input.push(b'\n');
    }
    input.extend_from_slice(b"{\"id\":\"\xff\"}\n");
    input
}

#[test]
fn every_detect_answer_line_validates_for_every_engine() {
    let v = schema("detect-answer.schema.json");
    let input = detect_input();
    let expected = input
        .split(|&b| b == b'\n')
        .filter(|l| !l.iter().all(u8::is_ascii_whitespace))
        .count();
    let mut count = 0;
    let mut seen = std::collections::BTreeSet::new();
    for engine in ["f64", "plain", "exact", "truth", "f64 --time"] {
        let mut argv = vec!["detect", "--engine"];
        argv.extend(engine.split(' '));
        let (out, code) = polyguard(&argv, &input);
        assert_eq!(code, 1, "{engine}: the bad lines make the exit status 1");
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(
            lines.len(),
            expected,
            "{engine}: one answer per line\n{out}"
        );
        for (k, line) in lines.iter().enumerate() {
            let value = parse(engine, line);
            assert_valid(&v, &format!("{engine} answer {}", k + 1), &value);
            let obj = value.as_object().expect("an object");
            for key in obj.keys() {
                seen.insert(key.clone());
            }
            if obj.get("well_formed") == Some(&Value::Bool(false)) {
                seen.insert("<not well formed>".into());
            }
            if let Some(Value::String(e)) = obj.get("entry") {
                seen.insert(format!("<entry {e}>"));
            }
            if obj
                .get("entry_time_exact")
                .and_then(Value::as_str)
                .is_some_and(|s| s.contains('√'))
            {
                seen.insert("<irrational entry time>".into());
            }
            count += 1;
        }
    }
    // the input must exercise every field of the schema
    for field in [
        "id",
        "detected",
        "kind",
        "decided_by",
        "well_formed",
        "well_formed_reason",
        "entry_time",
        "entry_time_exact",
        "line",
        "error",
        "<not well formed>",
        "<irrational entry time>",
        "entry_lo",
        "entry_hi",
        "<entry never>",
        "<entry enters>",
        "<entry possible>",
    ] {
        assert!(seen.contains(field), "no answer line had {field}");
    }
    println!(
        "detect-answer.schema.json: {count} answer lines of 4 engines (and f64 --time) validate"
    );
}

#[test]
fn the_detect_answer_schema_rejects_the_canaries() {
    let v = schema("detect-answer.schema.json");
    let good = json!({"id": "a", "detected": true, "kind": "exact",
                      "decided_by": "detect_same_2d", "well_formed": true});
    assert_valid(&v, "a good answer", &good);
    let truth = json!({"id": "a", "detected": true, "entry_time": 3.0,
                       "entry_time_exact": "3/1", "decided_by": "truth", "well_formed": true});
    assert_valid(&v, "a good truth answer", &truth);
    let error = json!({"id": 3, "line": 3, "error": "line: not a JSON object"});
    assert_valid(&v, "a good error line", &error);
    let timed = json!({"id": "a", "detected": true, "kind": "exact",
                       "decided_by": "detect_same_2d", "well_formed": true,
                       "entry": "enters", "entry_lo": 2.9, "entry_hi": 3.1});
    assert_valid(&v, "a good answer with --time", &timed);
    let with = |base: &Value, key: &str, value: Value| {
        let mut x = base.clone();
        x[key] = value;
        x
    };
    let without = |base: &Value, key: &str| {
        let mut x = base.clone();
        x.as_object_mut().expect("object").remove(key);
        x
    };
    let canaries = [
        with(&good, "detected", json!("yes")),
        with(&good, "kind", json!("approximate")),
        with(&good, "decided_by", json!("detect_2d")),
        with(&good, "well_formed", json!(false)),
        with(&good, "well_formed_reason", json!("§II.J rule 1: …")),
        with(&good, "entry_time", json!(3.0)),
        with(&good, "colour", json!("red")),
        with(&good, "line", json!(1)),
        with(
            &with(&good, "detected", json!(false)),
            "kind",
            json!("conservative"),
        ),
        without(&good, "decided_by"),
        without(&truth, "entry_time_exact"),
        with(&truth, "kind", json!("exact")),
        with(&truth, "entry_time_exact", json!("3.0")),
        with(&truth, "entry_time", json!(-1.0)),
        with(
            &with(&good, "entry", json!("never")),
            "entry_lo",
            json!(1.0),
        ),
        with(&good, "entry", json!("enters")),
        with(
            &with(&good, "entry", json!("sometime")),
            "entry_lo",
            json!(1.0),
        ),
        with(
            &with(
                &with(&good, "entry", json!("enters")),
                "entry_lo",
                json!(1.0),
            ),
            "entry_hi",
            json!(-2.0),
        ),
        with(
            &with(
                &with(
                    &with(&good, "entry", json!("enters")),
                    "entry_lo",
                    json!(1.0),
                ),
                "entry_hi",
                json!(2.0),
            ),
            "detected",
            json!(false),
        ),
        with(&truth, "entry", json!("never")),
        with(&error, "line", json!(0)),
        with(&error, "line", json!("3")),
        without(&error, "id"),
        with(&error, "detected", json!(true)),
    ];
    for c in &canaries {
        assert_invalid(&v, "a broken answer line", c);
    }
    println!(
        "detect-answer.schema.json: {} canaries rejected",
        canaries.len()
    );
}

// ---------------------------------------------------------------------------------------
// The scenario and the conflicts answer

/// The scenarios checked: the example, generated ones (both kinds, and static areas whose
/// overlaps include a MultiPolygon region), and a hand-written one with a properties
/// member the format does not define and foreign members on the collection and a feature
/// (warnings in the answer, one with a null index).
fn scenarios() -> Vec<(String, String)> {
    let mut out = vec![(
        "examples/example3.geojson".to_owned(),
        read(&root().join("examples/example3.geojson")),
    )];
    for (mix, n, seed) in [
        ("mixed", "120", "1"),
        ("static", "120", "1"),
        ("tracks", "40", "7"),
    ] {
        let (text, code) = polyguard(
            &["generate", "--objects", n, "--mix", mix, "--seed", seed],
            b"",
        );
        assert_eq!(code, 0, "generate --mix {mix}");
        out.push((
            format!("generate --objects {n} --mix {mix} --seed {seed}"),
            text,
        ));
    }
    out.push((
        "a scenario with an extra property and foreign members".to_owned(),
        r#"{"type": "FeatureCollection", "name": "extra", "bbox": [0, 0, 2, 2], "generator": "qgis",
            "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:OGC:1.3:CRS84"}},
            "features": [
             {"type": "Feature", "id": 7, "title": "a storm",
              "properties": {"id": "storm", "kind": "area", "t0": 1.5, "tf": null, "colour": "red"},
              "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}},
             {"type": "Feature",
              "properties": {"id": "ship", "kind": "track", "speed_kn": 15, "front_nm": 10,
                             "back_nm": 10, "side_nm": 0, "t0": null},
              "geometry": {"type": "LineString", "coordinates": [[-1, 0.5, 100], [2, 0.5, 100]]}}
            ]}"#
        .to_owned(),
    ));
    out
}

#[test]
fn scenarios_and_their_conflicts_answers_validate() {
    let scenario = schema("scenario.schema.json");
    let answer = schema("conflicts-answer.schema.json");
    let mut regions = std::collections::BTreeSet::new();
    let (mut n_scenarios, mut n_answers, mut n_conflicts) = (0, 0, 0);
    for (what, text) in scenarios() {
        assert_valid(&scenario, &what, &parse(&what, &text));
        n_scenarios += 1;
        for extra in [&[][..], &["--no-regions"][..]] {
            let mut args = vec!["conflicts", "--quiet", "-"];
            args.extend_from_slice(extra);
            let (out, code) = polyguard(&args, text.as_bytes());
            assert_eq!(code, 0, "conflicts {extra:?} on {what}\n{out}");
            let value = parse(&what, &out);
            assert_valid(&answer, &format!("the answer for {what} {extra:?}"), &value);
            n_answers += 1;
            for c in value["conflicts"].as_array().expect("conflicts") {
                // --no-regions drops the member; otherwise it is always there
                let has = c.as_object().is_some_and(|o| o.contains_key("region"));
                assert_eq!(has, extra.is_empty(), "{what} {extra:?}: {c}");
                n_conflicts += 1;
                regions.insert(c["region"]["type"].as_str().unwrap_or("null").to_owned());
            }
        }
    }
    for kind in ["Polygon", "MultiPolygon", "null"] {
        assert!(regions.contains(kind), "no conflict region of type {kind}");
    }
    println!(
        "scenario.schema.json: {n_scenarios} scenarios validate; \
         conflicts-answer.schema.json: {n_answers} answers ({n_conflicts} conflicts) validate"
    );
}

/// A scenario of bad features: the reader lists them in `errors`, and that answer
/// validates (with warnings too).
#[test]
fn an_answer_with_errors_and_warnings_validates() {
    let answer = schema("conflicts-answer.schema.json");
    let text = r#"{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"id": "ok", "kind": "area", "note": "x"},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}},
 {"type": "Feature", "properties": {"id": "typo", "kind": "area", "t_f": 3},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}},
 {"type": "Feature", "properties": {"id": "slow", "kind": "track", "front_nm": 1, "back_nm": 1, "side_nm": 1},
  "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}},
 {"type": "Feature", "properties": {"kind": "area"},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}}
]}"#;
    let (out, code) = polyguard(&["conflicts", "--quiet", "-"], text.as_bytes());
    assert_eq!(code, 1, "rejected features make the exit status 1");
    let value = parse("answer", &out);
    assert_valid(&answer, "an answer with errors", &value);
    assert_eq!(value["errors"].as_array().map(Vec::len), Some(3), "{out}");
    assert_eq!(value["warnings"].as_array().map(Vec::len), Some(1), "{out}");
    assert!(value["errors"][2]["id"].is_null(), "{out}");
}

/// One area and one track, for the canaries to break.
const SCENARIO: &str = r#"{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"id": "storm", "kind": "area", "t0": 1, "tf": 4},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}},
 {"type": "Feature", "properties": {"id": "ship", "kind": "track", "speed_kn": 15, "front_nm": 10, "back_nm": 10, "side_nm": 10, "t0": 0},
  "geometry": {"type": "LineString", "coordinates": [[-1, 0.5], [2, 0.5]]}}
]}"#;

/// The strict reader's verdict (crates/earth/src/scenario/read/general.rs, which names every error):
/// `Err` when the file or any feature is rejected.
fn scenario_reader_accepts(text: &str) -> Result<(), String> {
    match polyguard_earth::scenario::parse_general(text) {
        Err(e) => Err(e.to_string()),
        Ok(r) if !r.errors.is_empty() => Err(r.errors[0].to_string()),
        Ok(_) => Ok(()),
    }
}

/// The base scenario, a hole, and a MultiPolygon of two parts (one with a hole): all
/// read, all valid.
#[test]
fn the_scenario_schema_accepts_what_the_reader_reads() {
    let v = schema("scenario.schema.json");
    scenario_reader_accepts(SCENARIO).expect("the base scenario reads");
    assert_valid(&v, "the base scenario", &parse("scenario", SCENARIO));
    let square = r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#;
    let holed = r#"[[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], [[0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.2, 0.2]]]"#;
    for good in [
        edit(SCENARIO, square, holed),
        edit(
            SCENARIO,
            &format!(r#"{{"type": "Polygon", "coordinates": {square}}}"#),
            &format!(
                r#"{{"type": "MultiPolygon", "coordinates": [{square}, {}]}}"#,
                holed
                    .replace(
                        "[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]",
                        "[3, 0], [4, 0], [4, 1], [3, 1], [3, 0]"
                    )
                    .replace(
                        "0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.2, 0.2",
                        "3.2, 0.2], [3.2, 0.4], [3.4, 0.4], [3.2, 0.2"
                    )
            ),
        ),
    ] {
        scenario_reader_accepts(&good).expect("a hole or a MultiPolygon reads");
        assert_valid(&v, "a hole or a MultiPolygon", &parse("scenario", &good));
    }
    // foreign members (RFC 7946 §6.1) at each level: both read them past
    for good in [
        edit(SCENARIO, r#""geometry""#, r#""style": {}, "geometry""#),
        edit(
            SCENARIO,
            r#""features""#,
            r#""title": "x", "generator": "qgis", "features""#,
        ),
        edit(
            SCENARIO,
            r#""type": "LineString", "#,
            r#""type": "LineString", "style": {"stroke": "red"}, "#,
        ),
    ] {
        scenario_reader_accepts(&good).expect("a foreign member reads");
        assert_valid(&v, "a foreign member", &parse("scenario", &good));
    }
}

/// Scenarios that break a rule JSON Schema can state: the reader and the schema both
/// reject each.
#[test]
fn the_scenario_schema_rejects_the_canaries() {
    let v = schema("scenario.schema.json");
    let canaries = [
        // a misspelt member, or a member not allowed where it is: RFC 7946 §7.1's, or the
        // format's names on another object
        edit(SCENARIO, r#""geometry""#, r#""geometyr""#),
        edit(
            SCENARIO,
            r#""geometry""#,
            r#""coordinates": [], "geometry""#,
        ),
        edit(SCENARIO, r#""geometry""#, r#""t0": 1, "geometry""#),
        edit(
            SCENARIO,
            r#""geometry""#,
            r#""longitudes": "unrolled", "geometry""#,
        ),
        edit(SCENARIO, r#""features""#, r#""properties": {}, "features""#),
        edit(
            SCENARIO,
            r#""type": "LineString", "#,
            r#""type": "LineString", "speed_kn": 3, "#,
        ),
        edit(
            SCENARIO,
            r#""type": "LineString", "#,
            r#""type": "LineString", "crs": {"type": "name", "properties": {"name": "EPSG:3857"}}, "#,
        ),
        // a track without its speed, or with a null one
        edit(SCENARIO, r#""speed_kn": 15, "#, ""),
        edit(SCENARIO, r#""speed_kn": 15"#, r#""speed_kn": null"#),
        edit(SCENARIO, r#""speed_kn": 15"#, r#""speed_kn": 0"#),
        edit(SCENARIO, r#""side_nm": 10"#, r#""side_nm": -1"#),
        // a property of the other kind (null would be absent, as everywhere)
        edit(SCENARIO, r#""tf": 4"#, r#""tf": 4, "speed_kn": 3"#),
        edit(SCENARIO, r#""t0": 0}"#, r#""t0": 0, "tf": 2}"#),
        edit(SCENARIO, r#""kind": "area""#, r#""kind": "zone""#),
        edit(SCENARIO, r#""id": "storm", "#, ""),
        edit(SCENARIO, r#""id": "storm""#, r#""id": 5"#),
        edit(SCENARIO, r#""tf": 4"#, r#""tf": "4""#),
        edit(SCENARIO, r#"[1, 1], [0, 0]]]"#, r#"[1, 86], [0, 0]]]"#),
        edit(
            SCENARIO,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#,
            r#"[[[0, 0], [1, 0], [0, 0]]]"#,
        ),
        // a hole of two positions; a MultiPolygon of nothing
        edit(
            SCENARIO,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]], [[0.5, 0.2], [0.5, 0.2]]]"#,
        ),
        edit(
            SCENARIO,
            r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}"#,
            r#"{"type": "MultiPolygon", "coordinates": []}"#,
        ),
        edit(SCENARIO, r#"[[-1, 0.5], [2, 0.5]]"#, r#"[[-1, 0.5]]"#),
        edit(SCENARIO, r#"[[-1, 0.5], [2, 0.5]]"#, r#"[[-1, 0.5], [2]]"#),
        edit(SCENARIO, r#""type": "LineString""#, r#""type": "Polygon""#),
        edit(
            SCENARIO,
            r#""type": "LineString", "#,
            r#""type": "LineString", "crs": {}, "#,
        ),
        edit(
            SCENARIO,
            r#""geometry": {"type": "Polygon""#,
            r#""geometry": null, "g": {"type": "Polygon""#,
        ),
        edit(
            SCENARIO,
            r#""features""#,
            r#""crs": {"type": "name", "properties": {"name": "EPSG:3857"}}, "features""#,
        ),
        edit(SCENARIO, r#""FeatureCollection""#, r#""Feature""#),
    ];
    for text in &canaries {
        assert!(
            scenario_reader_accepts(text).is_err(),
            "the reader accepts the canary {text}"
        );
        assert_invalid(&v, "a scenario the reader rejects", &parse("canary", text));
    }
    println!("scenario.schema.json: {} canaries rejected", canaries.len());
}

/// What the schema cannot say (its $comment lists these): the reader alone rejects each,
/// and the schema finds it valid.
#[test]
fn the_scenario_schema_leaves_some_rules_to_the_reader() {
    let v = schema("scenario.schema.json");
    let beyond = [
        edit(SCENARIO, r#"[1, 1], [0, 0]]]"#, r#"[1, 1], [0, 1]]]"#),
        edit(SCENARIO, r#""id": "ship""#, r#""id": "storm""#),
        edit(SCENARIO, r#""tf": 4"#, r#""tf": 0.5"#),
        edit(SCENARIO, r#""tf": 4"#, r#""t_f": 4"#),
        // a misspelling of a member the object lacks: of the collection's longitudes
        edit(
            SCENARIO,
            r#""features""#,
            r#""longitude": "unrolled", "features""#,
        ),
        // exactly 180° of longitude apart: east or west? (200° apart reads as 160° across
        // the antimeridian, which the reader accepts)
        edit(
            SCENARIO,
            r#"[[-1, 0.5], [2, 0.5]]"#,
            r#"[[-100, 0.5], [80, 0.5]]"#,
        ),
        // a ring around the pole
        edit(
            SCENARIO,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#,
            r#"[[[0, 60], [120, 60], [-120, 60], [0, 60]]]"#,
        ),
        // a hole outside its exterior ring, and one that crosses it
        edit(
            SCENARIO,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]], [[2, 0.2], [2.1, 0.2], [2.1, 0.3], [2, 0.2]]]"#,
        ),
        edit(
            SCENARIO,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]]]"#,
            r#"[[[0, 0], [1, 0], [1, 1], [0, 0]], [[0.5, 0.2], [1.5, 0.2], [1.5, 0.3], [0.5, 0.2]]]"#,
        ),
    ];
    for text in &beyond {
        assert!(
            scenario_reader_accepts(text).is_err(),
            "the reader accepts {text}"
        );
        assert_valid(&v, "a rule beyond JSON Schema", &parse("scenario", text));
    }
    println!(
        "scenario.schema.json: {} reader-only rules confirmed",
        beyond.len()
    );
}

#[test]
fn the_conflicts_answer_schema_rejects_the_canaries() {
    let v = schema("conflicts-answer.schema.json");
    let (out, _) = polyguard(
        &["conflicts", "--quiet", "-"],
        read(&root().join("examples/example3.geojson")).as_bytes(),
    );
    let good = parse("answer", &out);
    assert_valid(&v, "the Example 3 answer", &good);
    let edited = |f: &dyn Fn(&mut Value)| {
        let mut x = good.clone();
        f(&mut x);
        x
    };
    let canaries = [
        edited(&|x| x["conflicts"][0]["t_start"] = json!("4.1")),
        edited(&|x| x["conflicts"][0]["t_start"] = Value::Null),
        edited(&|x| x["conflicts"][0]["method"] = json!("area_overlap")),
        edited(&|x| x["conflicts"][0]["decided_by"] = json!("stage4")),
        edited(&|x| x["conflicts"][0]["projection_windows"] = json!([[1.0, 2.0]])),
        edited(&|x| x["conflicts"][0]["region"]["type"] = json!("LineString")),
        edited(&|x| x["conflicts"][0]["region"]["coordinates"][0] = json!([[0, 0], [1, 1]])),
        edited(&|x| x["conflicts"][0]["colour"] = json!("red")),
        edited(&|x| {
            x["conflicts"][0]
                .as_object_mut()
                .expect("conflict")
                .remove("b");
        }),
        edited(&|x| x["stats"]["conflicts"] = json!(-1)),
        edited(&|x| {
            x["stats"]
                .as_object_mut()
                .expect("stats")
                .remove("timings_ms");
        }),
        edited(&|x| x["errors"] = json!([{"line": 1, "index": 0, "id": "a", "field": "x"}])),
        edited(&|x| {
            x["warnings"] =
                json!([{"line": 0, "index": 0, "id": "a", "field": "properties.x", "message": "m"}])
        }),
        edited(&|x| {
            x.as_object_mut().expect("answer").remove("warnings");
        }),
    ];
    for c in &canaries {
        assert_invalid(&v, "a broken conflicts answer", c);
    }
    println!(
        "conflicts-answer.schema.json: {} canaries rejected",
        canaries.len()
    );
}

// ---------------------------------------------------------------------------------------
// The examples of the format docs

/// The ```json blocks of a Markdown file: each block whole when it is one JSON value,
/// else each of its lines that is (a block of JSON Lines).
fn json_blocks(markdown: &str) -> Vec<Value> {
    let mut out = Vec::new();
    let mut block: Option<Vec<&str>> = None;
    for line in markdown.lines() {
        let fence = line.trim_start();
        match &mut block {
            None if fence.starts_with("```") && fence[3..].trim() == "json" => {
                block = Some(Vec::new());
            }
            Some(lines) if fence.starts_with("```") => {
                let text = lines.join("\n");
                match serde_json::from_str::<Value>(&text) {
                    Ok(v) => out.push(v),
                    Err(_) => out.extend(
                        lines
                            .iter()
                            .filter_map(|l| serde_json::from_str::<Value>(l).ok()),
                    ),
                }
                block = None;
            }
            Some(lines) => lines.push(line),
            None => {}
        }
    }
    out
}

#[test]
fn the_docs_examples_validate() {
    let case = schema("case.schema.json");
    let scenario = schema("scenario.schema.json");
    for (doc, key) in [
        ("docs/cases.md", "case"),
        ("docs/way-out.md", "case"),
        ("docs/scenario.md", "scenario"),
    ] {
        let path = root().join(doc);
        if !path.exists() {
            println!("note: {doc} does not exist yet; its examples are not checked");
            continue;
        }
        let mut count = 0;
        for value in json_blocks(&read(&path)) {
            if key == "case" && value.get("lookahead").is_some() {
                assert_valid(&case, &format!("a case example of {doc}"), &value);
                count += 1;
            }
            if key == "scenario" && value.get("type") == Some(&json!("FeatureCollection")) {
                assert_valid(&scenario, &format!("a scenario example of {doc}"), &value);
                count += 1;
            }
        }
        println!("{doc}: {count} {key} examples validate");
    }
}

/// Every answer line of `polyguard encounters` on the worked example and on real flights
/// (the `traffic` package's quickstart excerpt against two French FIRs, and drifting
/// cells) validates, and the worked example's lines are checked for sortedness, which
/// the schema cannot say.
#[test]
fn encounters_answers_validate() {
    let answer = schema("encounters-answer.schema.json");
    let ex = root().join("examples/moving");
    let data = root().join("crates/earth/tests/data/moving");
    let runs: Vec<Vec<String>> = vec![
        vec![ex.join("flight.csv"), ex.join("areas.geojson")]
            .into_iter()
            .map(|p| p.display().to_string())
            .chain(["--max-gap".into(), "900".into(), "--sep".into(), "5".into()])
            .collect(),
        vec![data.join("quickstart-3.csv"), data.join("fir-LFFF.geojson")]
            .into_iter()
            .map(|p| p.display().to_string())
            .collect(),
        vec![
            data.join("quickstart-3.mf.json"),
            data.join("cells-2.mf.json"),
        ]
        .into_iter()
        .map(|p| p.display().to_string())
        .chain(["--sep".into(), "20".into(), "--sep-v".into(), "1000".into()])
        .collect(),
    ];
    let mut n = 0;
    for run in runs {
        let mut args = vec!["encounters", "--quiet"];
        args.extend(run.iter().map(String::as_str));
        let (out, code) = polyguard(&args, b"");
        assert_eq!(code, 0, "{args:?}\n{out}");
        for line in out.lines() {
            let v = parse(&format!("{args:?}"), line);
            assert_valid(&answer, line, &v);
            for rel in ["inside", "near"] {
                let mut last = f64::NEG_INFINITY;
                for s in v[rel].as_array().expect("spans") {
                    let e: Vec<f64> = ["start", "end"]
                        .iter()
                        .flat_map(|k| s[k].as_array().expect("enclosure").iter())
                        .map(|x| x.as_f64().expect("number"))
                        .collect();
                    assert!(last <= e[0] && e.windows(2).all(|w| w[0] <= w[1]), "{line}");
                    last = e[3];
                }
            }
            n += 1;
        }
    }
    assert!(n >= 3, "only {n} answer lines");
    println!("encounters-answer.schema.json: {n} answer lines validate");
}

// ---------------------------------------------------------------------------------------
// The way out: the case's new fields and the answers of bands, recover and offset

/// The way-out examples (docs/way-out.md).
const WAYOUT_EXAMPLES: [&str; 3] = [
    "examples/bands.jsonl",
    "examples/recover.jsonl",
    "examples/offset.jsonl",
];

fn way_reader_accepts(line: &str) -> Result<(), String> {
    polyguard_harness::wayout::case::parse_way_line(line, 1)
        .case
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// A good way-out case of two polygons with every new field.
const GOOD_WAY: &str = r#"{"id":"w","lookahead":1,"sep":0.5,"time":0.5,"eps":0.1,"bands":{"unknown_max_deg":1,"speeds":[0,2]},"point":{"pos":[5,-3],"vel":[0,1]},"polygons":[{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]},{"vertices":[[4,0],[6,0],[5,1]]}]}"#;
/// Its 3D form, with vertical speed bands.
const GOOD_WAY_3D: &str = r#"{"id":"w3","lookahead":1,"sep":0.5,"sep_v":1,"bands":{"vertical_speeds":[-5,5]},"point":{"pos":[5,-3,2],"vel":[0,1,0]},"polygons":[{"vertices":[[0,0],[2,0],[2,2],[0,2]],"bottom":0,"top":3,"vz":0}]}"#;

/// The way-out examples and the reader's optional forms validate; lines the way-out
/// reader rejects are rejected by the schema too, except the rules its $comment leaves
/// to the reader.
#[test]
fn the_case_schema_takes_the_way_out_fields() {
    let v = schema("case.schema.json");
    let mut count = 0;
    for file in WAYOUT_EXAMPLES {
        for (n, line) in jsonl(&root().join(file)) {
            let what = format!("{file}:{n}");
            way_reader_accepts(&line).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_valid(&v, &what, &parse(&what, &line));
            count += 1;
        }
    }
    let accepted = [
        GOOD_WAY.to_owned(),
        GOOD_WAY_3D.to_owned(),
        edit(
            GOOD_WAY,
            r#""time":0.5,"eps":0.1,"#,
            r#""time":null,"eps":null,"#,
        ),
        edit(GOOD_WAY, r#""speeds":[0,2]"#, r#""speeds":null"#),
        edit(
            GOOD_WAY,
            r#""id":"w","#,
            r#""id":"w","buff":0.1,"polygon":null,"#,
        ),
    ];
    for line in &accepted[..4] {
        way_reader_accepts(line).unwrap_or_else(|e| panic!("{line}: {e}"));
        assert_valid(&v, "an accepted way-out case", &parse("case", line));
        count += 1;
    }
    // the reader reads a null polygon as absent; the schema wants an object ($comment)
    way_reader_accepts(&accepted[4]).expect("null polygon beside polygons");
    let canaries = [
        edit(
            GOOD_WAY,
            r#""id":"w","#,
            r#""id":"w","polygon":{"vertices":[[0,0],[1,0],[0,1]]},"#,
        ),
        edit(GOOD_WAY, r#""eps":0.1"#, r#""eps":1"#),
        edit(GOOD_WAY, r#""unknown_max_deg":1"#, r#""unknown_max":1"#),
        edit(GOOD_WAY, r#""unknown_max_deg":1"#, r#""unknown_max_deg":0"#),
        edit(GOOD_WAY, r#""speeds":[0,2]"#, r#""speeds":[-1,2]"#),
        edit(GOOD_WAY, r#""speeds":[0,2]"#, r#""speeds":[0,2,3]"#),
        edit(GOOD_WAY, r#""speeds":[0,2]"#, r#""vertical_speeds":[0,2]"#),
        edit(GOOD_WAY, r#""time":0.5"#, r#""time":-1"#),
        edit(GOOD_WAY, r#""velocities""#, r#""velocity""#),
        edit(GOOD_WAY_3D, r#","bottom":0,"top":3,"vz":0"#, ""),
        edit(
            GOOD_WAY_3D,
            r#""polygons":[{"vertices":[[0,0],[2,0],[2,2],[0,2]],"bottom":0,"top":3,"vz":0}]"#,
            r#""polygons":[]"#,
        ),
    ];
    for line in &canaries {
        assert!(
            way_reader_accepts(line).is_err(),
            "the reader accepts {line}"
        );
        assert_invalid(
            &v,
            "a way-out case the reader rejects",
            &parse("canary", line),
        );
    }
    let beyond = [
        edit(GOOD_WAY, r#""time":0.5"#, r#""time":2"#),
        edit(GOOD_WAY, r#""speeds":[0,2]"#, r#""speeds":[2,0]"#),
    ];
    for line in &beyond {
        assert!(
            way_reader_accepts(line).is_err(),
            "the reader accepts {line}"
        );
        assert_valid(
            &v,
            "a way-out rule beyond JSON Schema",
            &parse("case", line),
        );
    }
    // detect refuses polygons, which the format allows
    let detect = edit(GOOD_WAY, r#""id":"w","#, r#""id":"w","buff":0.1,"#);
    assert!(reader_accepts(&detect).is_err_and(|e| e.starts_with("polygons:")));
    println!(
        "case.schema.json: {count} way-out lines validate, {} canaries rejected",
        canaries.len()
    );
}

/// Every answer line of bands, recover (both engines) and offset (and --inset) on the
/// examples and on bad lines validates against its schema; the schemas reject answers
/// of the other commands.
#[test]
fn the_way_out_answers_validate() {
    let bad = [
        "not json",
        r#"{"id":"x","lookahead":1,"point":{"pos":[0,0],"vel":[0,1]},"polygons":[{"vertices":[[0,0],[0,1],[1,0]]}]}"#,
    ]
    .join("\n");
    let runs: [(&str, &[&str], &str); 6] = [
        ("bands-answer.schema.json", &["bands"], WAYOUT_EXAMPLES[0]),
        (
            "recover-answer.schema.json",
            &["recover"],
            WAYOUT_EXAMPLES[1],
        ),
        (
            "recover-answer.schema.json",
            &["recover", "--engine", "truth"],
            WAYOUT_EXAMPLES[1],
        ),
        ("offset-answer.schema.json", &["offset"], WAYOUT_EXAMPLES[2]),
        (
            "offset-answer.schema.json",
            &["offset", "--inset"],
            WAYOUT_EXAMPLES[2],
        ),
        ("bands-answer.schema.json", &["bands"], ""),
    ];
    let mut answers: Vec<(String, Value)> = Vec::new();
    for (name, args, file) in runs {
        let v = schema(name);
        let input = if file.is_empty() {
            bad.clone()
        } else {
            format!("{}\n{bad}\n", read(&root().join(file)))
        };
        let mut all = args.to_vec();
        all.push("-");
        let (out, code) = polyguard(&all, input.as_bytes());
        assert_eq!(code, 1, "{args:?}: the bad lines give exit 1\n{out}");
        let lines: Vec<&str> = out.lines().collect();
        assert!(lines.len() >= 2, "{args:?}");
        for line in lines {
            let value = parse(name, line);
            assert_valid(&v, &format!("{args:?}"), &value);
            if value.get("error").is_none() {
                answers.push((name.to_owned(), value));
            }
        }
    }
    for name in [
        "bands-answer.schema.json",
        "recover-answer.schema.json",
        "offset-answer.schema.json",
    ] {
        let v = schema(name);
        for (other, value) in answers.iter().filter(|(n, _)| n != name) {
            assert_invalid(&v, &format!("a {other} answer under {name}"), value);
        }
    }
    println!("way-out answers: {} lines validate", answers.len());
}

/// Every answer line of `bands --earth` on its example (with and without speed bands)
/// and on bad lines validates against bands-earth-answer.schema.json; the schema
/// rejects a plane `bands` answer, and an Earth answer whose band ends lost their unit
/// or whose kind is misspelt (the canaries).
#[test]
fn the_earth_bands_answers_validate() {
    let v = schema("bands-earth-answer.schema.json");
    let example = read(&root().join("examples/earth-bands.jsonl"));
    let input = format!("{example}not json\n{{\"id\":\"x\",\"buff_nm\":5}}\n");
    let (out, code) = polyguard(&["bands", "--earth", "-"], input.as_bytes());
    assert_eq!(code, 1, "the bad lines give exit 1\n{out}");
    let mut answers = Vec::new();
    for line in out.lines() {
        let value = parse("bands --earth", line);
        assert_valid(&v, "bands --earth", &value);
        if value.get("error").is_none() {
            answers.push(value);
        }
    }
    assert_eq!(answers.len(), example.lines().count());
    assert!(answers.iter().any(|a| a.get("speed").is_some()));
    let a = &answers[0];
    let unitless =
        serde_json::from_str::<Value>(&a.to_string().replace("\"from_deg\"", "\"from\""))
            .expect("JSON");
    assert_invalid(&v, "course bands without their unit", &unitless);
    let misspelt = serde_json::from_str::<Value>(&a.to_string().replacen(
        "\"kind\":\"clear\"",
        "\"kind\":\"free\"",
        1,
    ))
    .expect("JSON");
    assert_invalid(&v, "a kind that is not one", &misspelt);
    let plane = read(&root().join(WAYOUT_EXAMPLES[0]));
    let (out, _) = polyguard(&["bands", "-"], plane.as_bytes());
    let first = out.lines().next().expect("a plane answer");
    assert_invalid(&v, "a plane bands answer", &parse("bands", first));
    println!(
        "bands-earth-answer.schema.json: {} answers validate",
        answers.len()
    );
}
