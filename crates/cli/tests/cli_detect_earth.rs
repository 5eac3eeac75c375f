//! `polyguard detect-earth` end to end: the example file's expected reading
//! (docs/earth-cases.md) against the ground truth, bad lines answered with their field
//! while good ones are still answered, and the exit status.

mod common;

use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::{detect_earth_with, Buffer, Options, Pieces};
use polyguard_earth::reference::approach::closest_approach;

fn json_lines(s: &str) -> Vec<serde_json::Value> {
    s.lines()
        .map(|l| serde_json::from_str(l).expect("answer is JSON"))
        .collect()
}

const EXAMPLE: &str = include_str!("../../../examples/earth-aircraft-cell.jsonl");

/// The example's reading: the aircraft flies through the cell near 45° N and across the
/// antimeridian (the truth's closest approach is 0: it enters), passes 6 nm from a cell
/// at 80° N with BUFF 10 nm (detected; the unscaled buffer misses it), and stays 30 nm
/// from one (not detected), on both models.
#[test]
fn the_example_reads_as_documented() {
    let want = [
        ("cell-45n", true),
        ("antimeridian", true),
        ("high-lat-near", true),
        ("high-lat-miss", false),
    ];
    for geodesy in ["sphere", "wgs84"] {
        let (out, err, code) = common::run(
            &["detect-earth", "--geodesy", geodesy, "-"],
            EXAMPLE.as_bytes(),
        );
        assert_eq!(code, 0, "{err}");
        let lines = json_lines(&out);
        assert_eq!(lines.len(), want.len());
        for (line, (id, detected)) in lines.iter().zip(want) {
            assert_eq!(line["id"], id);
            assert_eq!(line["detected"], detected, "{geodesy}: {line}");
            assert_eq!(line["geodesy"], geodesy);
            let eff = line["effective_buff_nm"].as_f64().expect("a number");
            let buff = if id.starts_with("high") { 10.0 } else { 5.0 };
            assert!(eff >= buff && eff < 1.1 * buff, "{line}");
        }
    }
    // the truth behind that reading, on the sphere
    let cases: Vec<_> = EXAMPLE
        .lines()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).expect("JSON");
            polyguard_cli::commands::detect_earth::encounter_from_object(
                v.as_object().expect("an object"),
            )
            .expect("valid")
        })
        .collect();
    let truth: Vec<f64> = cases
        .iter()
        .map(|c| closest_approach(c, Geodesy::Sphere, 400).0)
        .collect();
    assert_eq!(truth[0], 0.0, "the aircraft enters the cell at 45° N");
    assert_eq!(truth[1], 0.0, "and across the antimeridian");
    assert!((truth[2] - 6.0).abs() < 0.1, "{}", truth[2]);
    assert!((truth[3] - 30.0).abs() < 0.1, "{}", truth[3]);
    // the canary misses the near pass at 80° N: sec 80° is 5.8
    let unscaled = Options {
        geodesy: Geodesy::Sphere,
        buffer: Buffer::Unscaled,
        pieces: Pieces::Fixed(1),
    };
    assert!(
        !detect_earth_with(&cases[2], unscaled)
            .expect("valid")
            .detected
    );
}

#[test]
fn bad_lines_name_their_field_and_good_lines_are_answered() {
    let good = EXAMPLE.lines().next().expect("a line");
    let bad_lat = good.replace("[1.7,45.2]", "[1.7,86.0]");
    let typo = good.replace("\"speed_kn\":25", "\"speed_kts\":25");
    let twice = good.replace("\"buff_nm\":5,", "\"buff_nm\":5,\"buff_nm\":50,");
    let clockwise = good.replace(
        "[[1.0,44.8],[1.6,44.85],[1.7,45.2],[1.2,45.35],[0.9,45.1]]",
        "[[0.9,45.1],[1.2,45.35],[1.7,45.2],[1.6,44.85],[1.0,44.8]]",
    );
    let pole = good.replace(
        "\"course_deg\":90,\"speed_kn\":420",
        "\"course_deg\":0,\"speed_kn\":4000",
    );
    let input = format!("{bad_lat}\n\nnot json\n{typo}\n{good}\n{twice}\n{clockwise}\n{pole}\n");
    let (out, err, code) = common::run(&["detect-earth"], input.as_bytes());
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 7, "{out}");
    assert_eq!(lines[0]["id"], "cell-45n");
    assert_eq!(lines[0]["line"], 1);
    assert_eq!(lines[0]["field"], "cell.vertices[2][1]");
    assert_eq!(
        lines[0]["error"],
        "cell.vertices[2][1]: 86 is outside [-85, 85] degrees of latitude"
    );
    assert_eq!(lines[1]["id"], 3);
    assert_eq!(lines[1]["field"], "line");
    assert_eq!(
        lines[2]["error"],
        "cell.speed_kts: unknown field; did you mean speed_kn?"
    );
    assert_eq!(lines[3]["detected"], true);
    assert!(lines[4]["error"]
        .as_str()
        .is_some_and(|e| e.contains("duplicate key `buff_nm`")));
    assert_eq!(lines[5]["detected"], true, "clockwise is read reversed");
    assert_eq!(lines[6]["field"], "aircraft");
    assert_eq!(code, 1);
    assert!(err.contains("5 line(s)"), "{err}");
}
