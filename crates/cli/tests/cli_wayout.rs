//! `polyguard bands`, `recover` and `offset` end to end on their examples
//! (examples/bands.jsonl, recover.jsonl, offset.jsonl; docs/way-out.md): what each answer
//! certifies is checked exactly through the harness's checkers (the oracle), and the
//! errors name their field and line.

mod common;

use serde_json::Value;

use polyguard::bands::{Band, BandKind, Bands};
use polyguard::offset::{Offset, Region};
use polyguard::Vect2;
use polyguard_harness::wayout::answer::{band_case, recovery_query, Ask};
use polyguard_harness::wayout::bands::{check, contradictions, Param};
use polyguard_harness::wayout::case::parse_way_line;
use polyguard_harness::wayout::offset as offset_check;
use polyguard_harness::wayout::recovery::{self as rec};

fn run(args: &[&str], input: &str) -> (Vec<Value>, String, i32) {
    let (out, err, code) = common::run(args, input.as_bytes());
    let lines = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect();
    (lines, err, code)
}

fn example(name: &str) -> String {
    std::fs::read_to_string(common::root().join("examples").join(name))
        .unwrap_or_else(|e| panic!("examples/{name}: {e}"))
}

/// The case line of `id` in `text`, read by the harness as the commands read it.
fn case_line<'a>(text: &'a str, id: &str) -> &'a str {
    text.lines()
        .find(|l| l.contains(&format!("\"id\":\"{id}\"")))
        .unwrap_or_else(|| panic!("no case {id}"))
}

fn kind(s: &str) -> BandKind {
    match s {
        "clear" => BandKind::Clear,
        "conflict" => BandKind::Conflict,
        "unknown" => BandKind::Unknown,
        other => panic!("kind {other}"),
    }
}

/// The answer's bands as the engine's, from the given end fields.
fn bands_of(v: &Value, lo: &str, hi: &str) -> Bands {
    let bands = v["bands"]
        .as_array()
        .expect("bands")
        .iter()
        .map(|b| Band {
            lo: b[lo].as_f64().expect("lo"),
            hi: b[hi].as_f64().expect("hi"),
            kind: kind(b["kind"].as_str().expect("kind")),
        })
        .collect();
    Bands {
        bands,
        unknown_total: 0.0,
        met: true,
    }
}

/// The aircraft facing a line of drifting cells: its current course (north) is in
/// conflict, the course bands tile [0°, 360°] without gaps, and values drawn in every
/// clear and conflict band (ends included) are exactly what the band says (the oracle's
/// conflict of their f64 velocities); so are the speed and vertical speed bands.
#[test]
fn bands_of_the_example_are_exactly_right() {
    let text = example("bands.jsonl");
    let (answers, err, code) = run(&["bands", "examples/bands.jsonl"], "");
    assert_eq!(code, 0, "{err}");
    assert_eq!(answers.len(), 3);
    for a in &answers {
        let id = a["id"].as_str().expect("id");
        assert_eq!(a["current"], "conflict", "{id}");
        assert_eq!(a["current_course_deg"], 0.0, "{id}");
        let course = &a["course"];
        assert_eq!(course["met"], true, "{id}");
        let bands = course["bands"].as_array().expect("bands");
        assert_eq!(bands[0]["from_deg"], 0.0);
        assert_eq!(
            bands[0]["kind"], "conflict",
            "{id}: north is in the cell ahead"
        );
        assert_eq!(
            bands.last().expect("a band")["to_deg"].as_f64(),
            Some(360.0)
        );
        for w in bands.windows(2) {
            assert_eq!(w[0]["to_rad"], w[1]["from_rad"], "{id}: a gap");
            assert_ne!(w[0]["kind"], w[1]["kind"], "{id}: unmerged bands");
        }
        let kinds: Vec<&str> = bands.iter().filter_map(|b| b["kind"].as_str()).collect();
        assert!(kinds.contains(&"clear"), "{id}: some way out");

        let case = parse_way_line(case_line(&text, id), 1)
            .case
            .expect("the example reads");
        let bc = band_case(&case, &Ask::default());
        let speed = course["speed"].as_f64().expect("speed");
        assert_eq!(speed, 450.0);
        let faults = check(
            &bc,
            Param::Course { speed },
            &bands_of(course, "from_rad", "to_rad"),
            1,
            0.0,
        );
        assert_eq!(contradictions(&faults), 0, "{id}: {faults:?}");
        assert!(faults.is_empty(), "{id}: undecided {faults:?}");
        if let Some(sp) = a.get("speed") {
            let faults = check(
                &bc,
                Param::Speed { course: 0.0 },
                &bands_of(sp, "from", "to"),
                1,
                0.0,
            );
            assert!(faults.is_empty(), "{id}: speed {faults:?}");
            // slow enough, the cells drift past before the aircraft arrives
            assert_eq!(sp["bands"][0]["kind"], "clear", "{id}");
        }
        if let Some(vs) = a.get("vertical_speed") {
            let v = case.v;
            let faults = check(
                &bc,
                Param::Vertical { v },
                &bands_of(vs, "from", "to"),
                1,
                0.0,
            );
            assert!(faults.is_empty(), "{id}: vertical {faults:?}");
            // a fast climb over the cells' tops is clear, level flight is not
            let last = vs["bands"]
                .as_array()
                .and_then(|b| b.last())
                .expect("a band");
            assert_eq!(last["kind"], "clear", "{id}");
        }
    }
    assert!(answers[1].get("speed").is_some() && answers[2].get("vertical_speed").is_some());
}

/// Each recovery point meets its condition exactly, its distance bounds enclose the
/// exact minimum, and the truth engine's minimum is the hand-computed one: 3 nm below
/// the square's buffer, 7 nm from the triangle drifted for 6 minutes, √8 to the keep-in
/// square's 3-deep core; a strip 4 wide has no point 3 from its boundary.
#[test]
fn recovery_points_meet_their_condition_at_the_exact_minimum() {
    let text = example("recover.jsonl");
    let (answers, err, code) = run(
        &["recover", "--engine", "truth", "examples/recover.jsonl"],
        "",
    );
    assert_eq!(code, 0, "{err}");
    let want = [
        ("inside-buffer", "3", true),
        ("already-clear", "0", false),
        ("drifting-cell-at-6-min", "7", true),
        ("keep-in-near-the-edge", "√(8)", true),
    ];
    for (id, exact, moved) in want {
        let a = answers.iter().find(|a| a["id"] == id).expect("answered");
        let r = &a["recovery"];
        assert_eq!(r["min_exact"], exact, "{id}");
        assert_eq!(r["moved"], moved, "{id}");
        assert_eq!(r["meets"], true, "{id}");
        let (lo, hi, m) = (
            r["min_lo"].as_f64().expect("min_lo"),
            r["distance"].as_f64().expect("distance"),
            r["min"].as_f64().expect("min"),
        );
        assert!(lo <= m && m <= hi, "{id}: {lo} {m} {hi}");
        // the point, checked again by the oracle from the answer's numbers
        let case = parse_way_line(case_line(&text, id), 1).case.expect("reads");
        let qy = recovery_query(&case, &Ask::default()).expect("one polygon");
        let x = r["point"].as_array().expect("point");
        let x = Vect2::new(x[0].as_f64().expect("x"), x[1].as_f64().expect("y"));
        assert!(rec::meets(&qy, x), "{id}: {x:?}");
        let d = (x - case.s).x.hypot((x - case.s).y);
        assert!(d <= hi, "{id}");
    }
    let thin = answers
        .iter()
        .find(|a| a["id"] == "keep-in-too-thin")
        .expect("answered");
    assert!(thin["recovery"]["impossible"]
        .as_str()
        .is_some_and(|s| s.contains("inradius")));
    assert_eq!(thin["recovery"]["impossible_exact"], true);
}

fn ring(v: &Value) -> Vec<Vect2> {
    v.as_array()
        .expect("ring")
        .iter()
        .map(|p| Vect2::new(p[0].as_f64().expect("x"), p[1].as_f64().expect("y")))
        .collect()
}

/// The offsets and insets of the examples pass the oracle's exact check (B_D ⊆ Q ⊆
/// B_{D(1+ε)}, rings simple and nested), the moving cell at its `time`; the C whose
/// mouth closes has a hole.
#[test]
fn offsets_pass_the_exact_check() {
    let text = example("offset.jsonl");
    for inset in [false, true] {
        let mut args = vec!["offset", "examples/offset.jsonl"];
        if inset {
            args.push("--inset");
        }
        let (answers, err, code) = run(&args, "");
        assert_eq!(code, 0, "{err}");
        assert_eq!(answers.len(), text.lines().count());
        for a in &answers {
            let id = a["id"].as_str().expect("id");
            let case = parse_way_line(case_line(&text, id), 1).case.expect("reads");
            let regions = a["offset"]
                .as_array()
                .expect("regions")
                .iter()
                .map(|r| Region {
                    outer: ring(&r["outer"]),
                    holes: r["holes"]
                        .as_array()
                        .expect("holes")
                        .iter()
                        .map(ring)
                        .collect(),
                })
                .collect();
            let result = Offset { regions };
            let poly = &case.polygons[0];
            let side = if inset {
                polyguard_oracle::offset::Side::In
            } else {
                polyguard_oracle::offset::Side::Out
            };
            let (d, eps) = (a["d"].as_f64().expect("d"), a["eps"].as_f64().expect("eps"));
            let t = a["time"].as_f64().expect("time");
            let problem = offset_check::problem_at(&poly.p, &poly.vels, t, d, eps, side)
                .expect("exact problem");
            let verdict = problem
                .check(&offset_check::regions_of(&result))
                .expect("checked");
            assert!(verdict.holds(), "{id} inset={inset}: {verdict:?}");
            if id == "c-shape-mouth-closes" && !inset {
                assert_eq!(result.regions.len(), 1);
                assert_eq!(
                    result.regions[0].holes.len(),
                    1,
                    "the closed mouth leaves a hole"
                );
            }
        }
    }
}

/// A file with bad lines still answers its good ones; each error names its field and
/// line; exit status 1 (2 for a file that cannot be read). `detect` refuses `polygons`.
#[test]
fn errors_name_field_and_line_and_good_lines_are_answered() {
    let good = r#"{"id":"ok","lookahead":1,"sep":0.5,"point":{"pos":[0,-5],"vel":[0,6]},"polygons":[{"vertices":[[0,0],[1,0],[0,1]]}]}"#;
    let input = [
        good.to_owned(),
        good.replace(r#""vertices""#, r#""vertexes""#)
            .replace(r#""ok""#, r#""typo""#),
        String::new(),
        good.replace(r#""sep":0.5,"#, r#""sep":0.5,"bands":{"speeds":[2,1]},"#)
            .replace(r#""ok""#, r#""range""#),
        good.replace(r#""lookahead":1,"#, r#""lookahead":1,"time":3,"#)
            .replace(r#""ok""#, r#""late""#),
        "{not json".to_owned(),
        good.to_owned(),
    ]
    .join("\n");
    let (answers, err, code) = run(&["bands", "-"], &input);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("4 line(s)"), "{err}");
    assert_eq!(answers.len(), 6);
    let errors: Vec<(&str, u64)> = answers
        .iter()
        .filter_map(|a| {
            let e = a.get("error")?;
            Some((e["field"].as_str()?, e["line"].as_u64()?))
        })
        .collect();
    assert_eq!(
        errors,
        [
            ("polygons[0].vertexes", 2),
            ("bands.speeds[1]", 4),
            ("time", 5),
            ("line", 6)
        ]
    );
    assert_eq!(
        answers[1]["error"]["message"],
        "unknown field; did you mean vertices?"
    );
    assert_eq!(answers[0]["current"], "conflict");
    assert_eq!(answers[5]["id"], "ok");
    // recover and offset take one polygon
    let two = good.replace("]}]}", "]},{\"vertices\":[[5,5],[6,5],[5,6]]}]}");
    let (a, _, code) = run(&["recover", "-"], &two);
    assert_eq!(
        (code, &a[0]["error"]["field"]),
        (1, &Value::from("polygons"))
    );
    // detect keeps taking one `polygon`
    let detect = good.replace(r#""lookahead":1,"#, r#""lookahead":1,"buff":0.1,"#);
    let (out, _, code) = common::run(&["detect", "-"], detect.as_bytes());
    assert_eq!(code, 1);
    assert!(out.contains("polygons: must be absent for detect"), "{out}");
    // a file that cannot be read
    let (_, err, code) = common::run(&["offset", "no/such/file.jsonl"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("no/such/file.jsonl"), "{err}");
}

/// Each command's help cites the page that defines it, and that page exists.
#[test]
fn help_cites_the_way_out_page() {
    assert!(common::root().join("docs/way-out.md").exists());
    for cmd in ["bands", "recover", "offset"] {
        let (out, _, code) = common::run(&[cmd, "--help"], b"");
        assert_eq!(code, 0);
        assert!(out.contains("docs/way-out.md"), "{cmd}: {out}");
    }
}

/// `--svg` draws the chosen case's bands as a compass rose: its title is the case id, a
/// wedge is drawn in the colour of each kind the answer has, and without a FILE (standard
/// input) or with an unknown id it refuses with exit 2.
#[test]
fn svg_draws_the_chosen_cases_rose() {
    let dir = std::env::temp_dir().join(format!("pg-bands-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join("rose.svg");
    let file = common::root().join("examples/bands.jsonl");
    let (f, o) = (file.to_string_lossy(), out.to_string_lossy());
    let (lines, _, code) = run(
        &["bands", &f, "--svg", &o, "--svg-case", "line-of-cells"],
        "",
    );
    assert_eq!(code, 0);
    let svg = std::fs::read_to_string(&out).expect("svg written");
    assert!(svg.contains(">line-of-cells<"));
    let first = &lines[0]["course"]["bands"];
    for (name, colour) in [("clear", "#2e9d46"), ("conflict", "#d7301f")] {
        let has = first
            .as_array()
            .is_some_and(|b| b.iter().any(|x| x["kind"] == name));
        assert!(has, "the example has {name} bands");
        assert!(svg.contains(&format!("fill=\"{colour}\" fill-opacity=\"0.85\"")));
    }
    let (_, err, code) = run(&["bands", "--svg", &o], "");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--svg needs a case FILE"), "{err}");
    let (_, err, code) = run(&["bands", &f, "--svg", &o, "--svg-case", "nope"], "");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no case with id \"nope\""), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `offset --svg` draws the certified offset beside a bisector expansion: on the example
/// with a 0.02-long edge (shorter than the expansion's BUFF), the expansion moves two
/// vertices along PolyCARP's fixed (1, 1) and leaves points within D of P out, which the
/// picture counts; the certified offset is drawn as one region.
#[test]
fn offset_svg_shows_what_the_bisector_expansion_misses() {
    let dir = std::env::temp_dir().join(format!("pg-offset-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join("offset.svg");
    let file = common::root().join("examples/offset.jsonl");
    let (f, o) = (file.to_string_lossy(), out.to_string_lossy());
    let args = [
        "offset",
        &f,
        "--svg",
        &o,
        "--svg-case",
        "cell-with-a-short-edge",
    ];
    let (_, err, code) = run(&args, "");
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(&out).expect("svg written");
    let missed: usize = svg
        .split("red: ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|n| n.parse().ok())
        .expect("the missed count");
    assert!(missed > 0);
    assert_eq!(svg.matches("r=\"2.5\"").count(), missed);
    assert_eq!(svg.matches("fill=\"#4a7fc1\"").count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `recover --polycarp` judges PolyCARP's point exactly beside the engine's: in the V
/// notch it breaks the condition while the engine's meets it; on the thin strip it
/// returns a point where the engine (and the oracle) say none exists; where it meets the
/// condition its excess over the exact minimum is never negative.
#[test]
fn polycarp_recovery_is_judged_beside_the_engines() {
    let (answers, err, code) = run(
        &[
            "recover",
            "--engine",
            "truth",
            "--polycarp",
            "examples/recover-vs-polycarp.jsonl",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    let by_id = |id: &str| {
        answers
            .iter()
            .find(|a| a["id"] == id)
            .unwrap_or_else(|| panic!("no answer {id}"))
    };
    let notch = by_id("v-notch");
    assert_eq!(notch["recovery"]["meets"], true);
    assert_eq!(notch["polycarp"]["meets"], false);
    let strip = by_id("thin-strip-keep-in");
    assert_eq!(strip["recovery"]["impossible_exact"], true);
    assert_eq!(strip["polycarp"]["meets"], false);
    assert!(strip["polycarp"]["excess"].is_null());
    for a in &answers {
        if a["polycarp"]["meets"] == true {
            let excess = a["polycarp"]["excess"].as_f64().expect("excess");
            assert!(excess >= 0.0, "{a}");
        }
        assert!(a["recovery"]["meets"] != false, "{a}");
    }
}
