//! A scenario written as the format's GeoJSON (docs/scenario.md), which reads back the
//! same.

use super::model::{normal_lon, Feature, Kind, Longitudes, Scenario, Shape};
use crate::sphere::LonLat;
use serde_json::{json, Map, Value};

/// A position as written: on the Earth its longitude in (−180, 180] (RFC 7946), on the
/// unrolled plane as it lies there.
fn pos(p: LonLat, mode: Longitudes) -> Value {
    let (lon, lat) = p.to_degrees();
    match mode {
        Longitudes::Earth => json!([normal_lon(lon), lat]),
        Longitudes::Unrolled => json!([lon, lat]),
    }
}

/// The kept members after the defined ones.
fn extend(props: &mut Value, extra: &Map<String, Value>) {
    if let Some(m) = props.as_object_mut() {
        for (k, v) in extra {
            m.insert(k.clone(), v.clone());
        }
    }
}

/// Writes a scenario as the format's GeoJSON (areas counterclockwise, as read).
pub fn to_geojson(scenario: &Scenario) -> Value {
    let feats: Vec<Value> = scenario
        .features
        .iter()
        .map(|f| feature_geojson(f, scenario.longitudes))
        .collect();
    match scenario.longitudes {
        Longitudes::Earth => json!({"type": "FeatureCollection", "features": feats}),
        Longitudes::Unrolled => json!({"type": "FeatureCollection", "longitudes": "unrolled",
                                       "features": feats}),
    }
}

/// One feature of [`to_geojson`]'s collection on the plane `longitudes`.
pub fn feature_geojson(f: &Feature, longitudes: Longitudes) -> Value {
    match &f.kind {
        Kind::Area(a) => {
            let ring = |r: &[LonLat]| {
                let mut v: Vec<Value> = r.iter().map(|&p| pos(p, longitudes)).collect();
                if let Some(first) = v.first().cloned() {
                    v.push(first);
                }
                Value::Array(v)
            };
            let polygon = |sh: &Shape| {
                Value::Array(
                    std::iter::once(ring(&sh.ring))
                        .chain(sh.holes.iter().map(|h| ring(h)))
                        .collect(),
                )
            };
            let geometry = if a.multi {
                json!({"type": "MultiPolygon",
                       "coordinates": a.shapes.iter().map(polygon).collect::<Vec<_>>()})
            } else {
                json!({"type": "Polygon",
                       "coordinates": a.shapes.first().map(polygon).unwrap_or(json!([]))})
            };
            let mut props = json!({"id": f.id, "kind": "area"});
            extend(&mut props, &f.extra);
            if let Some(t0) = a.t0 {
                props["t0"] = json!(t0);
            }
            if let Some(tf) = a.tf {
                props["tf"] = json!(tf);
            }
            json!({"type": "Feature", "properties": props, "geometry": geometry})
        }
        Kind::Track(t) => {
            let line: Vec<Value> = t.waypoints.iter().map(|&p| pos(p, longitudes)).collect();
            let mut props = json!({"id": f.id, "kind": "track", "speed_kn": t.speed_kn,
                                   "front_nm": t.dims.front, "back_nm": t.dims.back,
                                   "side_nm": t.dims.side, "t0": t.t0});
            extend(&mut props, &f.extra);
            json!({"type": "Feature", "properties": props,
                   "geometry": {"type": "LineString", "coordinates": line}})
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::objects;
    use crate::scenario::read::parse;
    use crate::scenario::read::testkit::one;
    use crate::scenario::testdata::{file, AREA, TRACK};

    #[test]
    fn round_trip() {
        let (s, e) = one(
            r#"{"type":"Feature","properties":{"id":"t","kind":"track","speed_kn":15,
            "front_nm":10,"back_nm":10,"side_nm":10},
            "geometry":{"type":"LineString","coordinates":[[39,29],[41,31]]}}"#,
        );
        assert!(e.is_empty());
        let text = to_geojson(&s).to_string();
        let r = parse(&text).expect("parse");
        assert!(r.errors.is_empty());
        let s2 = r.scenario;
        assert_eq!(s2.features.len(), 2);
        assert_eq!(objects(&s2).len(), 2);
    }

    /// GeoJSON's properties are open: a member the format does not define is kept (and
    /// written back), listed as a warning with its line, and changes nothing.
    #[test]
    fn open_properties_are_kept_with_a_warning() {
        let coloured = AREA.replace(r#""tf":2"#, r#""tf":2,"colour":"red""#);
        let r = parse(&file(&[&coloured, TRACK])).expect("collection");
        assert!(r.errors.is_empty(), "{:?}", r.errors);
        assert_eq!(r.warnings.len(), 1);
        assert_eq!(
            r.warnings[0].to_string(),
            "line 2: feature 0 (id \"a\"), properties.colour: not defined by the scenario \
             format; kept, not read"
        );
        assert_eq!(
            r.scenario.features[0].extra.get("colour"),
            Some(&Value::from("red"))
        );
        let plain = parse(&file(&[AREA, TRACK])).expect("collection");
        assert_eq!(plain.scenario.features[0].kind, r.scenario.features[0].kind);
        let again = parse(&to_geojson(&r.scenario).to_string()).expect("collection");
        assert_eq!(again.scenario, r.scenario);
    }

    /// On the Earth a scenario is written back with longitudes in (−180, 180] (RFC 7946),
    /// which read the same: a track across the antimeridian stays one 1° step.
    #[test]
    fn longitudes_are_written_back_on_the_earth() {
        let track = TRACK
            .replace("[[0,0],[1,1]]", "[[179.5,0],[-179.5,0]]")
            .replace(r#""id":"t""#, r#""id":"x""#);
        let across = parse(&file(&[&track])).expect("a collection");
        let text = to_geojson(&across.scenario).to_string();
        assert!(text.contains("[-179.5,0.0]"), "{text}");
        let again = parse(&text).expect("a collection");
        assert_eq!(again.scenario, across.scenario);
    }
}
