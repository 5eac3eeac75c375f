//! `polyguard bands --earth` end to end (docs/earth-cases.md, "Bands on the Earth"): the
//! example file's bands tile their ranges, agree with the ground truth at drawn courses
//! and speeds, and with detect-earth on the aircraft's own course; bad lines name their
//! field while good ones are answered; the options it refuses.

mod common;

use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::{EarthCase, Motion};
use polyguard_earth::reference::approach::{closest_approach, Mix};

const EXAMPLE: &str = include_str!("../../../examples/earth-bands.jsonl");

fn json_lines(s: &str) -> Vec<serde_json::Value> {
    s.lines()
        .map(|l| serde_json::from_str(l).expect("answer is JSON"))
        .collect()
}

/// The encounter of an example line, read by the detect-earth reader.
fn encounter(line: &str) -> EarthCase {
    let v: serde_json::Value = serde_json::from_str(line).expect("JSON");
    let obj = v.as_object().expect("object");
    polyguard_cli::commands::detect_earth::encounter_from_object(obj).expect("a good encounter")
}

/// (lo, hi, kind) of each band under `unit`.
fn bands(v: &serde_json::Value, unit: &str) -> Vec<(f64, f64, String)> {
    v["bands"]
        .as_array()
        .expect("bands")
        .iter()
        .map(|b| {
            (
                b[format!("from_{unit}")].as_f64().expect("from"),
                b[format!("to_{unit}")].as_f64().expect("to"),
                b["kind"].as_str().expect("kind").to_owned(),
            )
        })
        .collect()
}

/// The truth at a drawn value: a clear value's closest approach (a real distance, never
/// below the least) must exceed BUFF, a conflict value's must not.
fn agrees(case: &EarthCase, kind: &str) -> Result<(), String> {
    let (d, _) = closest_approach(case, Geodesy::Sphere, 400);
    match kind {
        "clear" if d <= case.buff_nm => Err(format!("clear at {d} nm")),
        "conflict" if d > case.buff_nm => Err(format!("conflict at {d} nm")),
        _ => Ok(()),
    }
}

#[test]
fn the_example_bands_tile_and_agree_with_the_truth() {
    let (out, err, code) = common::run(&["bands", "--earth", "-"], EXAMPLE.as_bytes());
    assert_eq!(code, 0, "{err}");
    let answers = json_lines(&out);
    let lines: Vec<&str> = EXAMPLE.lines().collect();
    assert_eq!(answers.len(), lines.len());
    let mut rng = Mix(29);
    let mut drawn = 0;
    for (a, line) in answers.iter().zip(&lines) {
        let case = encounter(line);
        let course = bands(&a["course"], "deg");
        assert_eq!(course.first().map(|b| b.0), Some(0.0));
        assert_eq!(course.last().map(|b| b.1), Some(360.0));
        for w in course.windows(2) {
            assert_eq!(w[0].1, w[1].0, "{}: bands in order", a["id"]);
            assert_ne!(w[0].2, w[1].2, "{}: merged", a["id"]);
        }
        assert!(a["course"]["met"].as_bool().expect("met"), "{}", a["id"]);
        for (lo, hi, kind) in &course {
            for _ in 0..4 {
                let x = rng.uniform(*lo, *hi);
                let flown = EarthCase {
                    aircraft: Motion {
                        course_deg: x,
                        ..case.aircraft
                    },
                    ..case.clone()
                };
                agrees(&flown, kind)
                    .map_err(|e| format!("{} course {x}: {e}", a["id"]))
                    .unwrap();
                drawn += 1;
            }
        }
        if let Some(speed) = a.get("speed") {
            for (lo, hi, kind) in bands(speed, "kn") {
                let x = rng.uniform(lo, hi);
                let flown = EarthCase {
                    aircraft: Motion {
                        speed_kn: x,
                        ..case.aircraft
                    },
                    ..case.clone()
                };
                agrees(&flown, &kind)
                    .map_err(|e| format!("{} speed {x}: {e}", a["id"]))
                    .unwrap();
            }
        }
        // the aircraft's own course: conflict means detect-earth detects it
        let (det, _, _) = common::run(&["detect-earth", "-"], line.as_bytes());
        let det: serde_json::Value = serde_json::from_str(det.trim()).expect("JSON");
        if a["current"] == "conflict" {
            assert_eq!(det["detected"], true, "{}", a["id"]);
        }
        if a["current"] == "clear" {
            assert_eq!(
                det["separation_windows_h"],
                serde_json::json!([]),
                "{}",
                a["id"]
            );
        }
    }
    assert!(drawn >= 40, "{drawn} draws");
}

#[test]
fn bad_lines_name_their_field_and_good_lines_are_answered() {
    let good = EXAMPLE.lines().nth(1).expect("a second line");
    let cases = [
        (
            good.replace(r#""meta":"#, r#""bands":{"unknown_max_dg":1},"meta":"#),
            "bands.unknown_max_dg",
        ),
        (
            good.replace(r#""meta":"#, r#""bands":{"speeds_kn":[300,200]},"meta":"#),
            "bands.speeds_kn[1]",
        ),
        (
            good.replace(r#""meta":"#, r#""bands":{"speeds_kn":[-1,200]},"meta":"#),
            "bands.speeds_kn[0]",
        ),
        (
            good.replace(r#""meta":"#, r#""bands":{"unknown_max_deg":0},"meta":"#),
            "bands.unknown_max_deg",
        ),
        (
            good.replace(r#""meta":"#, r#""bands":[1],"meta":"#),
            "bands",
        ),
        (good.replace(r#""buff_nm":5"#, r#""buff_nm":-5"#), "buff_nm"),
        ("{".to_owned(), "line"),
    ];
    let mut input = String::new();
    for (line, _) in &cases {
        input.push_str(line);
        input.push('\n');
    }
    input.push_str(good);
    input.push('\n');
    let (out, _, code) = common::run(&["bands", "--earth", "-"], input.as_bytes());
    assert_eq!(code, 1);
    let answers = json_lines(&out);
    assert_eq!(answers.len(), cases.len() + 1);
    for (a, (_, field)) in answers.iter().zip(&cases) {
        assert_eq!(a["field"], *field, "{a}");
        assert!(
            a["error"].as_str().expect("error").starts_with(field),
            "{a}"
        );
    }
    assert!(
        answers[cases.len()].get("course").is_some(),
        "the good line is answered"
    );
}

#[test]
fn the_options_it_refuses() {
    let good = EXAMPLE.lines().next().expect("a line");
    // course bands are certified on the sphere; WGS84 names the model
    let (out, _, code) = common::run(
        &["bands", "--earth", "--geodesy", "wgs84", "-"],
        good.as_bytes(),
    );
    assert_eq!(code, 1);
    let a: serde_json::Value = serde_json::from_str(out.trim()).expect("JSON");
    assert_eq!(a["field"], "geodesy");
    // no picture of Earth bands
    let (_, err, code) = common::run(
        &["bands", "--earth", "--svg", "/tmp/never.svg", "-"],
        good.as_bytes(),
    );
    assert_eq!(code, 2);
    assert!(err.contains("--earth"), "{err}");
    // detect-earth reads the same lines (bands is ignored there)
    let (_, err, code) = common::run(&["detect-earth", "-"], EXAMPLE.as_bytes());
    assert_eq!(code, 0, "{err}");
}
