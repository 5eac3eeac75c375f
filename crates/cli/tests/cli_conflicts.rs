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
