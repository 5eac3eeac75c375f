//! `polyguard conflicts` end to end on paper B's Example 3 (examples/example3.geojson).

mod common;

/// The sphere model's published window, to be reproduced within ±0.002 h
/// (the same tolerance as crates/earth/tests/paper_b_example3.rs).
const EXAMPLE3_TOL_H: f64 = 0.002;

/// The binary answers the shipped example with paper B's window (4.1411 h onwards).
#[test]
fn binary_on_shipped_example() {
    let (out, err, code) = common::run(&["conflicts", "examples/example3.geojson"], b"");
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("the answer is JSON");
    let s = v["conflicts"][0]["t_start"]
        .as_f64()
        .expect("one conflict with a start time");
    assert!((s - 4.1411).abs() < EXAMPLE3_TOL_H, "{s}");
}

/// `--geodesy wgs84` answers with the window paper B prints for Example 3 (4.12–4.63 h,
/// within ±0.006 h), names the model in the stats, and a model that does not exist is
/// refused before anything is read.
#[test]
fn binary_on_shipped_example_on_wgs84() {
    let (out, err, code) = common::run(
        &[
            "conflicts",
            "examples/example3.geojson",
            "--geodesy",
            "wgs84",
        ],
        b"",
    );
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("the answer is JSON");
    let c = &v["conflicts"][0];
    let (s, e) = (
        c["t_start"].as_f64().expect("a start"),
        c["t_end"].as_f64().expect("an end"),
    );
    assert!(
        (s - 4.12).abs() <= 0.006 && (e - 4.63).abs() <= 0.006,
        "{s} {e}"
    );
    assert_eq!(v["stats"]["geodesy"], "wgs84");
    let (_, err, code) = common::run(
        &[
            "conflicts",
            "examples/example3.geojson",
            "--geodesy",
            "grs80",
        ],
        b"",
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("geodesy"), "{err}");
}

/// RFC 7946 §6.1: foreign members that another tool writes, on the collection, a feature
/// and a geometry, leave the answer's conflicts as they are; each is a warning on standard
/// error naming it and where it is, and in the answer's `warnings`. A misspelt property
/// is still an error naming the field.
#[test]
fn foreign_members_are_warnings_and_change_no_conflict() {
    let plain = std::fs::read_to_string(common::root().join("examples/example3.geojson"))
        .expect("the example");
    let foreign = plain
        .replacen(
            r#"{"type": "FeatureCollection", "#,
            r#"{"type": "FeatureCollection", "generator": "qgis", "#,
            1,
        )
        .replacen(
            r#"{"type": "Feature","#,
            r#"{"type": "Feature", "title": "the blue ship","#,
            1,
        )
        .replacen(
            r#""type": "LineString", "#,
            r#""type": "LineString", "style": {"stroke": "blue"}, "#,
            1,
        );
    assert_eq!(foreign.matches("qgis").count(), 1);
    assert_eq!(foreign.matches("the blue ship").count(), 1);
    assert_eq!(foreign.matches("\"style\"").count(), 1);
    let answer = |text: &str| {
        let (out, err, code) = common::run(&["conflicts", "--quiet", "-"], text.as_bytes());
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).expect("the answer is JSON");
        (v, err)
    };
    let (a, a_err) = answer(&plain);
    let (b, b_err) = answer(&foreign);
    assert_eq!(a["conflicts"], b["conflicts"]);
    assert!(a_err.is_empty(), "{a_err}");
    let warned: Vec<&str> = b_err.lines().filter(|l| l.contains("warning: ")).collect();
    assert_eq!(warned.len(), 3, "{b_err}");
    for (line, place) in [
        (
            "the FeatureCollection, generator: a foreign member",
            "line 1",
        ),
        ("feature 0 (id \"blue\"), title: a foreign member", "line 2"),
        (
            "feature 0 (id \"blue\"), geometry.style: a foreign member",
            "line 4",
        ),
    ] {
        assert!(
            warned
                .iter()
                .any(|w| w.contains(&format!("warning: {place}: {line}"))),
            "{line}: {b_err}"
        );
    }
    let w = b["warnings"].as_array().expect("warnings");
    assert_eq!(w.len(), 3, "{b}");
    assert!(
        w[0]["index"].is_null() && w[0]["field"] == "generator",
        "{b}"
    );
    // a misspelt property stays an error naming it
    let typo = plain.replacen(r#""speed_kn": 15"#, r#""speed_knots": 15"#, 1);
    let (_, err, code) = common::run(&["conflicts", "--quiet", "-"], typo.as_bytes());
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("properties.speed_knots: unknown member; did you mean speed_kn?"),
        "{err}"
    );
}
