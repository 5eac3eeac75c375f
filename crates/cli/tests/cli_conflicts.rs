//! `polyguard conflicts` end to end on paper B's Example 3 (examples/example3.geojson).

mod common;

/// Issue 5: the sphere model's published window, to be reproduced within ±0.002 h
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
