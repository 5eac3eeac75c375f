//! `polyguard detect --intervals` and keep-in fences end to end, on the worked examples of
//! docs/intervals.md (examples/intervals.jsonl): the exact truth gives the ends computed
//! by hand there, the f64 engine encloses each of them, and the errors name their field.

mod common;

use serde_json::Value;

fn run(args: &[&str], input: &str) -> (String, String, i32) {
    common::run(args, input.as_bytes())
}

fn examples() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/intervals.jsonl"
    );
    std::fs::read_to_string(path).expect("examples/intervals.jsonl")
}

fn json_lines(s: &str) -> Vec<Value> {
    s.lines()
        .map(|l| serde_json::from_str(l).expect("answer is JSON"))
        .collect()
}

/// The hand-computed ends of docs/intervals.md, per example and relation, as the exact
/// rationals the truth prints and their values.
/// One exact component: its start and end, each as the truth's text and its value.
type Component = (&'static str, f64, &'static str, f64);

const HAND: [(&str, &str, &[Component]); 5] = [
    (
        "cell-entered-twice",
        "inside",
        &[
            ("2/27", 2.0 / 27.0, "11/108", 11.0 / 108.0),
            ("17/108", 17.0 / 108.0, "5/27", 5.0 / 27.0),
        ],
    ),
    (
        "cell-entered-twice",
        "near",
        &[
            ("7/108", 7.0 / 108.0, "1/9", 1.0 / 9.0),
            ("4/27", 4.0 / 27.0, "7/36", 7.0 / 36.0),
        ],
    ),
    (
        "drone-leaves-through-ceiling",
        "inside",
        &[("0/1", 0.0, "10/1", 10.0)],
    ),
    (
        "drone-leaves-through-ceiling",
        "near",
        &[("0/1", 0.0, "15/1", 15.0)],
    ),
    (
        "drone-leaves-through-ceiling",
        "breach",
        &[("5/1", 5.0, "60/1", 60.0)],
    ),
];

fn by_id<'a>(lines: &'a [Value], id: &str) -> &'a Value {
    lines
        .iter()
        .find(|l| l["id"] == id)
        .unwrap_or_else(|| panic!("no answer for {id}"))
}

#[test]
fn the_truth_gives_the_hand_computed_ends() {
    let (out, err, code) = run(&["detect", "--engine", "truth", "--intervals"], &examples());
    assert_eq!(code, 0, "{err}");
    let lines = json_lines(&out);
    for (id, relation, comps) in HAND {
        let got = by_id(&lines, id)["intervals"][relation]
            .as_array()
            .unwrap_or_else(|| panic!("{id} {relation}: {out}"));
        assert_eq!(got.len(), comps.len(), "{id} {relation}: {got:?}");
        for (g, (a, av, b, bv)) in got.iter().zip(comps) {
            assert_eq!(g["start_exact"], *a, "{id} {relation}");
            assert_eq!(g["end_exact"], *b, "{id} {relation}");
            // the numbers are the nearest f64 (p / q in f64 is correctly rounded)
            assert_eq!(g["start"].as_f64(), Some(*av), "{id} {relation}");
            assert_eq!(g["end"].as_f64(), Some(*bv), "{id} {relation}");
        }
    }
    assert_eq!(
        by_id(&lines, "cell-entered-twice")["intervals"]["loss_of_separation"]["time_exact"],
        "7/108"
    );
    assert_eq!(by_id(&lines, "drone-leaves-through-ceiling")["exits"], true);
}

#[test]
fn the_engine_encloses_every_hand_computed_end() {
    let (out, err, code) = run(&["detect", "--intervals"], &examples());
    assert_eq!(code, 0, "{err}");
    let lines = json_lines(&out);
    for (id, relation, comps) in HAND {
        let spans = by_id(&lines, id)["intervals"][relation]
            .as_array()
            .unwrap_or_else(|| panic!("{id} {relation}: {out}"));
        assert_eq!(spans.len(), comps.len(), "{id} {relation}: {spans:?}");
        for (s, (_, a, _, b)) in spans.iter().zip(comps) {
            let lo_hi = |k: &str| -> (f64, f64) {
                (
                    s[k][0].as_f64().unwrap_or(f64::NAN),
                    s[k][1].as_f64().unwrap_or(f64::NAN),
                )
            };
            let (sl, sh) = lo_hi("start");
            let (el, eh) = lo_hi("end");
            // the enclosures are thousands of ulps wide around the exact end, so the
            // nearest f64 of the hand-computed rational lies in them too
            assert!(
                sl <= *a && *a <= sh,
                "{id} {relation}: start {a} not in [{sl}, {sh}]"
            );
            assert!(
                el <= *b && *b <= eh,
                "{id} {relation}: end {b} not in [{el}, {eh}]"
            );
            assert_eq!(s["certain"], true, "{id} {relation}");
            // narrow: a crossing's enclosure is a few T·2⁻³⁶ wide
            assert!(sh - sl <= 1e-9 * 60.0 && eh - el <= 1e-9 * 60.0, "{s}");
        }
    }
    let drone = by_id(&lines, "drone-leaves-through-ceiling");
    assert_eq!(drone["fence"], "keep_in");
    assert_eq!(drone["exits"], true);
    assert_eq!(drone["exit_kind"], "exact");
}

#[test]
fn a_fence_kept_is_not_left() {
    // the drone of the example, with a ceiling high enough and a short lookahead
    let line = r#"{"id":"stays","lookahead":2,"buff":1,"sep":10,"sep_v":10,"fence":"keep_in","point":{"pos":[50,50,100],"vel":[1,0,2]},"polygon":{"vertices":[[0,0],[100,0],[100,100],[0,100]],"bottom":0,"top":120,"vz":0}}"#;
    for engine in ["f64", "truth"] {
        let (out, err, code) = run(&["detect", "--engine", engine], line);
        assert_eq!(code, 0, "{err}");
        let a = &json_lines(&out)[0];
        assert_eq!(a["exits"], false, "{engine}: {a}");
    }
}

#[test]
fn separations_are_checked_and_named() {
    let neg = r#"{"id":"neg","lookahead":1,"buff":1,"sep":-1,"point":{"pos":[0,0],"vel":[1,0]},"polygon":{"vertices":[[0,0],[1,0],[0,1]]}}"#;
    let (out, _, code) = run(&["detect", "--intervals"], neg);
    assert_eq!(code, 1);
    let a = &json_lines(&out)[0];
    assert_eq!(a["id"], "neg");
    assert!(
        a["error"].as_str().is_some_and(|e| e.starts_with("sep:")),
        "{a}"
    );
    let typo = r#"{"id":"typo","lookahead":1,"buff":1,"fence":"keepin","point":{"pos":[0,0],"vel":[1,0]},"polygon":{"vertices":[[0,0],[1,0],[0,1]]}}"#;
    let (out, _, _) = run(&["detect"], typo);
    let a = &json_lines(&out)[0];
    assert!(
        a["error"].as_str().is_some_and(|e| e.starts_with("fence:")),
        "{a}"
    );
    let (_, err, code) = run(&["detect", "--sep", "-2"], "");
    assert_eq!(code, 2, "{err}");
    let (_, err, code) = run(&["detect", "--intervals", "--engine", "exact"], "");
    assert_eq!(code, 2, "{err}");
}
