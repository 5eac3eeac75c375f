//! Helpers of the reading tests: a feature read between good ones, its one error.

use super::{fast_parse, parse, parse_general, ScenarioError};
use crate::scenario::model::Scenario;
use crate::scenario::testdata::{file, AREA, TRACK};

/// The scenario and errors of `feature` read after a good area.
pub fn one(feature: &str) -> (Scenario, Vec<ScenarioError>) {
    let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
        "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
    let r = parse(&format!(
        r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#
    ))
    .expect("collection");
    (r.scenario, r.errors)
}

/// The one error of `feature` read after a good area (the good one still read), the
/// typed fast path agreeing with the general path when it applies.
pub fn problem(feature: &str) -> ScenarioError {
    let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
        "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
    let text = format!(r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#);
    // the typed fast path, when it applies, agrees with the general path
    if let Some(fast) = fast_parse(&text) {
        assert_eq!(Ok(fast), parse_general(&text));
    }
    let (s, e) = one(feature);
    assert_eq!(s.features.len(), 1, "the good feature is still read");
    assert_eq!(e.len(), 1, "{e:?}");
    e[0].clone()
}

/// The error of the middle feature (line 3) between two good ones, whose reading is
/// checked too.
pub fn middle(bad: &str) -> ScenarioError {
    let good2 = TRACK.replace(r#""id":"t""#, r#""id":"t2""#);
    let r = parse(&file(&[AREA, bad, &good2])).expect("a collection");
    let ids: Vec<&str> = r.scenario.features.iter().map(|f| f.id.as_str()).collect();
    assert_eq!(ids, ["a", "t2"], "the good features are still read: {bad}");
    assert_eq!(r.errors.len(), 1, "{:?}", r.errors);
    r.errors[0].clone()
}
