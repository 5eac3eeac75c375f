//! Paper B failures found by `polyguard assure --paper b`, each kept as the scenario file
//! the hunt wrote (its `assure` answers removed) and replayed here against the ground
//! truth (`reference::truth`): the pipeline's window must contain every meeting instant
//! the truth finds.

use polyguard_earth::conflict::pipeline;
use polyguard_earth::reference::truth::{self, Outcome};
use polyguard_earth::scenario;

/// Reads `tests/regressions/NAME`, runs the pipeline, and checks the pair's window
/// against the truth (resolution 1/64 of the default tolerance, as the hunt uses).
fn replay(name: &str) -> (Option<(f64, f64)>, Outcome) {
    let path = format!("{}/tests/regressions/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let read = scenario::parse(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    assert!(read.errors.is_empty(), "{path}: {:?}", read.errors);
    let sc = read.scenario;
    let objs = scenario::objects(&sc);
    let (conflicts, _) = pipeline::run(&objs, pipeline::Options::default());
    let window = conflicts.first().map(|c| (c.t_start, c.t_end));
    let res = polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H / 64.0;
    let t = truth::pair(&sc.features[0], &sc.features[1], res).expect("modelled");
    (window, t)
}

fn assert_contains(name: &str) {
    let (w, t) = replay(name);
    match (&t, w) {
        (Outcome::Meets { first, last, .. }, Some((s, e))) => assert!(
            s <= *first && *last <= e,
            "{name}: window [{s:e}, {e:e}] leaves out meetings of [{first:e}, {last:e}]"
        ),
        (Outcome::Meets { .. }, None) => panic!("{name}: missed conflict, truth {t:?}"),
        _ => panic!("{name}: the truth no longer meets ({t:?}); the regression proves nothing"),
    }
}

/// assure --paper b, seed 1, case 15865 (east_west@mid): two east–west legs still
/// touching when the second leg ends at t₁ = 1.8679605954503866 h. Eq 20's linear window
/// came back from its relative time as `(t₁ − t_ref) + t_ref`, one ulp short of t₁, so
/// the contact at t₁ itself was outside the window.
#[test]
fn east_west_window_keeps_the_leg_end_exactly() {
    assert_contains("b-east-west-end-ulp.geojson");
}
