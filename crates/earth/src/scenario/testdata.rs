//! Scenario texts the reading and writing tests share.

/// A scenario of one line per feature after a header line: feature k is on line k + 2.
pub fn file(features: &[&str]) -> String {
    let mut t = String::from("{\"type\":\"FeatureCollection\",\"features\":[\n");
    t.push_str(&features.join(",\n"));
    t.push_str("\n]}\n");
    t
}

/// An area present from 1 h to 2 h.
pub const AREA: &str = r#"{"type":"Feature","properties":{"id":"a","kind":"area","t0":1,"tf":2},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
/// A track of one leg, 10 kn.
pub const TRACK: &str = r#"{"type":"Feature","properties":{"id":"t","kind":"track","speed_kn":10,"front_nm":1,"back_nm":1,"side_nm":1},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#;
