//! The scenario GeoJSON of shared/spec/scenario.md (Paper B's areas and tracks).
//!
//! Reading is forgiving per feature: a bad feature yields a [`ScenarioError`] naming its
//! id and field and is skipped, the others are still read. Only a file that is not a
//! GeoJSON FeatureCollection at all is a fatal error.

use crate::conflict::Object;
use crate::earth::{self, LonLat, RectDims};
use serde_json::{json, Map, Value};
use std::fmt;

/// Spec limit on |latitude| (degrees): the Mercator plane stretches without bound
/// towards the poles; 85° is the spec's validity limit.
pub const MAX_ABS_LAT_DEG: f64 = 85.0;

/// Largest |latitude| (degrees) a track's rectangle may reach: Table 2's steps from a
/// reference point at the spec's 85° limit stay clear of the pole for rectangles of up to
/// 240 nm (4°) of front/back + side.
pub const MAX_RECT_LAT_DEG: f64 = 89.0;

/// A static area (spec kind `area`).
#[derive(Clone, Debug, PartialEq)]
pub struct Area {
    /// Vertices (open ring, the closing repeat removed).
    pub ring: Vec<LonLat>,
    /// Start (h), `None` = always.
    pub t0: Option<f64>,
    /// End (h), `None` = always.
    pub tf: Option<f64>,
}

/// A moving rectangle along rhumb lines (spec kind `track`).
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// Waypoints (two or more).
    pub waypoints: Vec<LonLat>,
    /// Speed (kn), > 0.
    pub speed_kn: f64,
    /// Table 2 distances (nm).
    pub dims: RectDims,
    /// Departure time (h).
    pub t0: f64,
}

/// The two kinds of feature.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// `area`.
    Area(Area),
    /// `track`.
    Track(Track),
}

/// One feature of the scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Feature {
    /// `properties.id`, unique.
    pub id: String,
    /// What it is.
    pub kind: Kind,
}

/// A whole scenario (valid features only, in file order).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scenario {
    /// The features.
    pub features: Vec<Feature>,
}

/// What is wrong with a feature's field.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// The file is not JSON.
    Json(String),
    /// The field is missing.
    Missing,
    /// The field has the wrong JSON type or GeoJSON geometry type.
    WrongType(&'static str),
    /// A number is NaN/infinite or a position is not `[lon, lat]`.
    BadNumber,
    /// The polygon ring's last position differs from its first.
    UnclosedRing,
    /// Fewer than 3 distinct ring vertices (or 2 track waypoints).
    TooFewVertices(usize),
    /// |latitude| beyond [`MAX_ABS_LAT_DEG`].
    LatitudeOutOfRange(f64),
    /// A speed below zero.
    NegativeSpeed(f64),
    /// A speed of zero (the track would never end).
    ZeroSpeed,
    /// A distance below zero.
    NegativeDistance(f64),
    /// `properties.kind` is neither `area` nor `track`.
    UnknownKind(String),
    /// `properties.id` already used by an earlier feature.
    DuplicateId,
    /// `tf` before `t0`.
    EndBeforeStart,
    /// The rectangle's steps would carry a vertex past ±89° of latitude (the Mercator
    /// plane ends at the poles).
    RectangleTooLarge(f64),
}

/// A typed input error naming the feature (index and id) and the field.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioError {
    /// Index of the feature in the file (`None` for file-level errors).
    pub index: Option<usize>,
    /// `properties.id` when known.
    pub id: Option<String>,
    /// JSON path of the field, e.g. `properties.speed_kn`.
    pub field: String,
    /// The problem.
    pub problem: Problem,
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.index, &self.id) {
            (Some(i), Some(id)) => write!(f, "feature {i} (id {id:?}), ")?,
            (Some(i), None) => write!(f, "feature {i}, ")?,
            _ => {}
        }
        write!(f, "{}: ", self.field)?;
        match &self.problem {
            Problem::Json(e) => write!(f, "not valid JSON: {e}"),
            Problem::Missing => write!(f, "missing"),
            Problem::WrongType(t) => write!(f, "expected {t}"),
            Problem::BadNumber => write!(f, "not a finite number / position"),
            Problem::UnclosedRing => write!(f, "ring not closed (last position ≠ first)"),
            Problem::TooFewVertices(n) => write!(f, "only {n} vertices"),
            Problem::LatitudeOutOfRange(l) => {
                write!(f, "latitude {l} beyond ±{MAX_ABS_LAT_DEG}°")
            }
            Problem::NegativeSpeed(s) => write!(f, "negative speed {s}"),
            Problem::ZeroSpeed => write!(f, "speed must be > 0"),
            Problem::NegativeDistance(d) => write!(f, "negative distance {d}"),
            Problem::UnknownKind(k) => write!(f, "unknown kind {k:?} (area or track)"),
            Problem::DuplicateId => write!(f, "duplicate id"),
            Problem::EndBeforeStart => write!(f, "tf before t0"),
            Problem::RectangleTooLarge(l) => write!(
                f,
                "the rectangle reaches latitude {l:.1}°, beyond ±{MAX_RECT_LAT_DEG}°"
            ),
        }
    }
}

impl std::error::Error for ScenarioError {}

struct Ctx<'a> {
    index: usize,
    id: Option<&'a str>,
}

impl Ctx<'_> {
    fn err(&self, field: impl Into<String>, problem: Problem) -> ScenarioError {
        ScenarioError {
            index: Some(self.index),
            id: self.id.map(str::to_owned),
            field: field.into(),
            problem,
        }
    }
}

fn file_err(field: &str, problem: Problem) -> ScenarioError {
    ScenarioError {
        index: None,
        id: None,
        field: field.to_owned(),
        problem,
    }
}

fn position(ctx: &Ctx, field: &str, k: usize, v: &Value) -> Result<LonLat, ScenarioError> {
    // the field name is built only on error: positions are most of a scenario's numbers
    let name = || format!("{field}[{k}]");
    let arr = v
        .as_array()
        .filter(|a| a.len() >= 2)
        .ok_or_else(|| ctx.err(name(), Problem::BadNumber))?;
    match (arr[0].as_f64(), arr[1].as_f64()) {
        (Some(lon), Some(lat)) => checked(ctx, field, k, lon, lat),
        _ => Err(ctx.err(name(), Problem::BadNumber)),
    }
}

fn positions(ctx: &Ctx, field: &str, v: &Value) -> Result<Vec<LonLat>, ScenarioError> {
    let arr = v
        .as_array()
        .ok_or_else(|| ctx.err(field, Problem::WrongType("array of positions")))?;
    arr.iter()
        .enumerate()
        .map(|(k, p)| position(ctx, field, k, p))
        .collect()
}

fn number(ctx: &Ctx, props: &Map<String, Value>, key: &str) -> Result<Option<f64>, ScenarioError> {
    match props.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(v) => match v.as_f64() {
            Some(x) if x.is_finite() => Ok(Some(x)),
            Some(_) => Err(ctx.err(format!("properties.{key}"), Problem::BadNumber)),
            None => Err(ctx.err(format!("properties.{key}"), Problem::WrongType("number"))),
        },
    }
}

fn geometry<'a>(ctx: &Ctx, f: &'a Value, ty: &'static str) -> Result<&'a Value, ScenarioError> {
    let g = f
        .get("geometry")
        .filter(|g| !g.is_null())
        .ok_or_else(|| ctx.err("geometry", Problem::Missing))?;
    if g.get("type").and_then(Value::as_str) != Some(ty) {
        return Err(ctx.err("geometry.type", Problem::WrongType(ty)));
    }
    g.get("coordinates")
        .ok_or_else(|| ctx.err("geometry.coordinates", Problem::Missing))
}

/// A position checked for range: `[lon, lat]` degrees, |lat| ≤ [`MAX_ABS_LAT_DEG`].
fn checked(ctx: &Ctx, field: &str, k: usize, lon: f64, lat: f64) -> Result<LonLat, ScenarioError> {
    if !(lon.is_finite() && lat.is_finite()) {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::BadNumber));
    }
    if lat.abs() > MAX_ABS_LAT_DEG {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::LatitudeOutOfRange(lat)));
    }
    Ok(LonLat::from_degrees(lon, lat))
}

/// The spec's area rules on a ring already read: closed, ≥ 3 distinct vertices,
/// `tf ≥ t0`.
fn area_from(
    ctx: &Ctx,
    mut ring: Vec<LonLat>,
    t0: Option<f64>,
    tf: Option<f64>,
) -> Result<Area, ScenarioError> {
    const FIELD: &str = "geometry.coordinates[0]";
    if ring.len() < 2 || ring.first() != ring.last() {
        if ring.len() < 3 {
            return Err(ctx.err(FIELD, Problem::TooFewVertices(ring.len())));
        }
        return Err(ctx.err(FIELD, Problem::UnclosedRing));
    }
    ring.pop();
    ring.dedup();
    if ring.len() < 3 {
        return Err(ctx.err(FIELD, Problem::TooFewVertices(ring.len())));
    }
    if let (Some(a), Some(b)) = (t0, tf) {
        if b < a {
            return Err(ctx.err("properties.tf", Problem::EndBeforeStart));
        }
    }
    Ok(Area { ring, t0, tf })
}

/// The spec's track rules on values already read: ≥ 2 waypoints, speed > 0, distances
/// ≥ 0 (`None` = missing).
fn track_from(
    ctx: &Ctx,
    waypoints: Vec<LonLat>,
    speed_kn: Option<f64>,
    dists: [Option<f64>; 3],
    t0: Option<f64>,
) -> Result<Track, ScenarioError> {
    if waypoints.len() < 2 {
        return Err(ctx.err(
            "geometry.coordinates",
            Problem::TooFewVertices(waypoints.len()),
        ));
    }
    let speed_kn = speed_kn.ok_or_else(|| ctx.err("properties.speed_kn", Problem::Missing))?;
    if speed_kn < 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::NegativeSpeed(speed_kn)));
    }
    if speed_kn == 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::ZeroSpeed));
    }
    let mut d = [0.0; 3];
    for (k, key) in ["front_nm", "back_nm", "side_nm"].iter().enumerate() {
        d[k] = dists[k].ok_or_else(|| ctx.err(format!("properties.{key}"), Problem::Missing))?;
        if d[k] < 0.0 {
            return Err(ctx.err(format!("properties.{key}"), Problem::NegativeDistance(d[k])));
        }
    }
    let reach = (d[0].max(d[1]) + d[2]) / earth::EARTH_RADIUS_NM;
    let top = waypoints.iter().fold(0f64, |m, p| m.max(p.lat.abs())) + reach;
    if top.to_degrees() > MAX_RECT_LAT_DEG {
        return Err(ctx.err(
            "properties.front_nm",
            Problem::RectangleTooLarge(top.to_degrees()),
        ));
    }
    Ok(Track {
        waypoints,
        speed_kn,
        dims: RectDims {
            front: d[0],
            back: d[1],
            side: d[2],
        },
        t0: t0.unwrap_or(0.0),
    })
}

fn area(ctx: &Ctx, f: &Value, props: &Map<String, Value>) -> Result<Area, ScenarioError> {
    let coords = geometry(ctx, f, "Polygon")?;
    let ring_v = coords
        .as_array()
        .and_then(|r| r.first())
        .ok_or_else(|| ctx.err("geometry.coordinates[0]", Problem::Missing))?;
    let ring = positions(ctx, "geometry.coordinates[0]", ring_v)?;
    let t0 = number(ctx, props, "t0")?;
    let tf = number(ctx, props, "tf")?;
    area_from(ctx, ring, t0, tf)
}

fn track(ctx: &Ctx, f: &Value, props: &Map<String, Value>) -> Result<Track, ScenarioError> {
    let coords = geometry(ctx, f, "LineString")?;
    let waypoints = positions(ctx, "geometry.coordinates", coords)?;
    let speed = number(ctx, props, "speed_kn")?;
    let dists = [
        number(ctx, props, "front_nm")?,
        number(ctx, props, "back_nm")?,
        number(ctx, props, "side_nm")?,
    ];
    let t0 = number(ctx, props, "t0")?;
    track_from(ctx, waypoints, speed, dists, t0)
}

/// The fast path's view of a scenario: well-typed files deserialize straight into these
/// (no `Value` tree); anything else falls back to the `Value` path, which names fields.
mod fast {
    #[derive(serde::Deserialize)]
    pub struct Collection {
        #[serde(rename = "type")]
        pub ty: String,
        pub features: Vec<Feature>,
    }
    #[derive(serde::Deserialize)]
    pub struct Feature {
        pub properties: Props,
        pub geometry: Geometry,
    }
    #[derive(serde::Deserialize)]
    pub struct Props {
        pub id: String,
        pub kind: String,
        pub t0: Option<f64>,
        pub tf: Option<f64>,
        pub speed_kn: Option<f64>,
        pub front_nm: Option<f64>,
        pub back_nm: Option<f64>,
        pub side_nm: Option<f64>,
    }
    #[derive(serde::Deserialize)]
    #[serde(tag = "type", content = "coordinates")]
    pub enum Geometry {
        Polygon(Vec<Vec<[f64; 2]>>),
        LineString(Vec<[f64; 2]>),
    }
}

fn fast_parse(text: &str) -> Option<(Scenario, Vec<ScenarioError>)> {
    let fc: fast::Collection = serde_json::from_str(text).ok()?;
    if fc.ty != "FeatureCollection" {
        return None;
    }
    let mut out = Scenario::default();
    let mut errors = Vec::new();
    let mut seen = std::collections::HashSet::with_capacity(fc.features.len());
    for (index, f) in fc.features.into_iter().enumerate() {
        let p = f.properties;
        let ctx = Ctx {
            index,
            id: Some(&p.id),
        };
        if !seen.insert(p.id.clone()) {
            errors.push(ctx.err("properties.id", Problem::DuplicateId));
            continue;
        }
        let pts = |field: &str, v: &[[f64; 2]]| -> Result<Vec<LonLat>, ScenarioError> {
            v.iter()
                .enumerate()
                .map(|(k, q)| checked(&ctx, field, k, q[0], q[1]))
                .collect()
        };
        let kind = match (p.kind.as_str(), &f.geometry) {
            ("area", fast::Geometry::Polygon(rings)) => match rings.first() {
                None => Err(ctx.err("geometry.coordinates[0]", Problem::Missing)),
                Some(r) => pts("geometry.coordinates[0]", r)
                    .and_then(|ring| area_from(&ctx, ring, p.t0, p.tf))
                    .map(Kind::Area),
            },
            ("area", _) => Err(ctx.err("geometry.type", Problem::WrongType("Polygon"))),
            ("track", fast::Geometry::LineString(line)) => pts("geometry.coordinates", line)
                .and_then(|w| {
                    track_from(
                        &ctx,
                        w,
                        p.speed_kn,
                        [p.front_nm, p.back_nm, p.side_nm],
                        p.t0,
                    )
                })
                .map(Kind::Track),
            ("track", _) => Err(ctx.err("geometry.type", Problem::WrongType("LineString"))),
            (k, _) => Err(ctx.err("properties.kind", Problem::UnknownKind(k.to_owned()))),
        };
        match kind {
            Ok(kind) => out.features.push(Feature {
                id: p.id.clone(),
                kind,
            }),
            Err(e) => errors.push(e),
        }
    }
    Some((out, errors))
}

/// Reads a scenario. `Err` only when the text is not a GeoJSON FeatureCollection; bad
/// features are reported in the second element and skipped.
pub fn parse(text: &str) -> Result<(Scenario, Vec<ScenarioError>), ScenarioError> {
    if let Some(r) = fast_parse(text) {
        return Ok(r);
    }
    parse_value(text)
}

/// [`parse`]'s general path through a `serde_json::Value` tree: any JSON, every field
/// checked by name.
fn parse_value(text: &str) -> Result<(Scenario, Vec<ScenarioError>), ScenarioError> {
    let v: Value =
        serde_json::from_str(text).map_err(|e| file_err("(file)", Problem::Json(e.to_string())))?;
    if v.get("type").and_then(Value::as_str) != Some("FeatureCollection") {
        return Err(file_err("type", Problem::WrongType("FeatureCollection")));
    }
    let feats = v
        .get("features")
        .and_then(Value::as_array)
        .ok_or_else(|| file_err("features", Problem::WrongType("array")))?;
    let mut out = Scenario::default();
    let mut errors = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for (index, f) in feats.iter().enumerate() {
        let props = f.get("properties").and_then(Value::as_object);
        let id = props.and_then(|p| p.get("id")).and_then(Value::as_str);
        let ctx = Ctx { index, id };
        let Some(props) = props else {
            errors.push(ctx.err("properties", Problem::Missing));
            continue;
        };
        let Some(id) = id else {
            let p = if props.contains_key("id") {
                Problem::WrongType("string")
            } else {
                Problem::Missing
            };
            errors.push(ctx.err("properties.id", p));
            continue;
        };
        if !seen.insert(id.to_owned()) {
            errors.push(ctx.err("properties.id", Problem::DuplicateId));
            continue;
        }
        let kind = match props.get("kind").and_then(Value::as_str) {
            Some("area") => area(&ctx, f, props).map(Kind::Area),
            Some("track") => track(&ctx, f, props).map(Kind::Track),
            Some(k) => Err(ctx.err("properties.kind", Problem::UnknownKind(k.to_owned()))),
            None => Err(ctx.err("properties.kind", Problem::Missing)),
        };
        match kind {
            Ok(kind) => out.features.push(Feature {
                id: id.to_owned(),
                kind,
            }),
            Err(e) => errors.push(e),
        }
    }
    Ok((out, errors))
}

/// Paper B Sections III and V: the scenario's objects in the Mercator plane, one per area
/// and one per track leg, `owner` = feature index in `scenario.features`.
pub fn objects(scenario: &Scenario) -> Vec<Object> {
    use rayon::prelude::*;
    scenario
        .features
        .par_iter()
        .enumerate()
        .flat_map_iter(|(k, f)| {
            let owner = k as u32;
            let v: Vec<Object> = match &f.kind {
                Kind::Area(a) => vec![Object::area(
                    owner,
                    a.ring.iter().map(|&p| earth::mercator(p)).collect(),
                    a.t0.unwrap_or(f64::NEG_INFINITY),
                    a.tf.unwrap_or(f64::INFINITY),
                )],
                Kind::Track(t) => earth::track_legs(&t.waypoints, t.speed_kn, t.t0, t.dims)
                    .into_iter()
                    .map(|leg| Object::leg(owner, leg))
                    .collect(),
            };
            v
        })
        .collect()
}

fn pos(p: LonLat) -> Value {
    let (lon, lat) = p.to_degrees();
    json!([lon, lat])
}

/// Writes a scenario as the spec's GeoJSON.
pub fn to_geojson(scenario: &Scenario) -> Value {
    let feats: Vec<Value> = scenario
        .features
        .iter()
        .map(|f| match &f.kind {
            Kind::Area(a) => {
                let mut ring: Vec<Value> = a.ring.iter().map(|&p| pos(p)).collect();
                if let Some(first) = ring.first().cloned() {
                    ring.push(first);
                }
                let mut props = json!({"id": f.id, "kind": "area"});
                if let Some(t0) = a.t0 {
                    props["t0"] = json!(t0);
                }
                if let Some(tf) = a.tf {
                    props["tf"] = json!(tf);
                }
                json!({"type": "Feature", "properties": props,
                       "geometry": {"type": "Polygon", "coordinates": [ring]}})
            }
            Kind::Track(t) => {
                let line: Vec<Value> = t.waypoints.iter().map(|&p| pos(p)).collect();
                json!({"type": "Feature",
                       "properties": {"id": f.id, "kind": "track", "speed_kn": t.speed_kn,
                                      "front_nm": t.dims.front, "back_nm": t.dims.back,
                                      "side_nm": t.dims.side, "t0": t.t0},
                       "geometry": {"type": "LineString", "coordinates": line}})
            }
        })
        .collect();
    json!({"type": "FeatureCollection", "features": feats})
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(feature: &str) -> (Scenario, Vec<ScenarioError>) {
        let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
        parse(&format!(
            r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#
        ))
        .expect("collection")
    }

    fn problem(feature: &str) -> ScenarioError {
        let ok = r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
        let text = format!(r#"{{"type":"FeatureCollection","features":[{ok},{feature}]}}"#);
        // the typed fast path, when it applies, agrees with the general path
        if let Some(fast) = fast_parse(&text) {
            assert_eq!(Ok(fast), parse_value(&text));
        }
        let (s, e) = one(feature);
        assert_eq!(s.features.len(), 1, "the good feature is still read");
        assert_eq!(e.len(), 1, "{e:?}");
        e[0].clone()
    }

    #[test]
    fn typed_errors_name_id_and_field() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"u","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1]]]}}"#,
        );
        assert_eq!(e.problem, Problem::UnclosedRing);
        assert_eq!(e.id.as_deref(), Some("u"));
        assert_eq!(e.field, "geometry.coordinates[0]");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"few","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,0]]]}}"#,
        );
        assert!(matches!(e.problem, Problem::TooFewVertices(_)));
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"lat","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,86],[1,1],[0,0]]]}}"#,
        );
        assert_eq!(e.problem, Problem::LatitudeOutOfRange(86.0));
        assert_eq!(e.field, "geometry.coordinates[0][1]");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"neg","kind":"track","speed_kn":-1,
            "front_nm":1,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.problem, Problem::NegativeSpeed(-1.0));
        assert_eq!(e.field, "properties.speed_kn");
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"k","kind":"blob"},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.problem, Problem::UnknownKind("blob".into()));
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"ok","kind":"area"},
            "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#,
        );
        assert_eq!(e.problem, Problem::DuplicateId);
        assert!(e.to_string().contains("\"ok\""));
    }

    #[test]
    fn round_trip() {
        let (s, e) = one(
            r#"{"type":"Feature","properties":{"id":"t","kind":"track","speed_kn":15,
            "front_nm":10,"back_nm":10,"side_nm":10},
            "geometry":{"type":"LineString","coordinates":[[39,29],[41,31]]}}"#,
        );
        assert!(e.is_empty());
        let text = to_geojson(&s).to_string();
        let (s2, e2) = parse(&text).expect("parse");
        assert!(e2.is_empty());
        assert_eq!(s2.features.len(), 2);
        assert_eq!(objects(&s2).len(), 2);
    }

    #[test]
    fn rectangle_past_the_pole_is_rejected() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"big","kind":"track","speed_kn":10,
            "front_nm":400,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,84],[1,84]]}}"#,
        );
        assert!(matches!(e.problem, Problem::RectangleTooLarge(_)));
    }

    #[test]
    fn wrong_types_fall_back_to_named_fields() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"s","kind":"track","speed_kn":"fast",
            "front_nm":1,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}"#,
        );
        assert_eq!(e.field, "properties.speed_kn");
        assert_eq!(e.problem, Problem::WrongType("number"));
    }

    #[test]
    fn not_json_is_fatal() {
        assert!(matches!(parse("{").unwrap_err().problem, Problem::Json(_)));
    }
}
