//! The fast path: clean files deserialize straight into typed structures (no tree), and
//! anything else goes to the general path.

use super::errors::{Ctx, ScenarioError};
use super::rules::{area_from, checked, lay_out, track_from};
use super::Read;
use crate::scenario::model::{Feature, Kind, Longitudes, Scenario};
use crate::sphere::LonLat;
use serde_json::Map;

/// The fast path's view of a scenario: clean files deserialize straight into these (no
/// tree); anything else (an unknown or repeated member, a wrong type, a rule broken)
/// goes to the general path, which names fields and lines.
mod typed {
    use serde::de::IgnoredAny;
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Collection {
        #[serde(rename = "type")]
        pub ty: String,
        pub features: Vec<Feature>,
        #[allow(dead_code)]
        pub bbox: Option<IgnoredAny>,
        #[allow(dead_code)]
        pub name: Option<IgnoredAny>,
        pub longitudes: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Feature {
        #[serde(rename = "type")]
        pub ty: String,
        pub properties: Props,
        pub geometry: Geometry,
        #[allow(dead_code)]
        pub id: Option<IgnoredAny>,
        #[allow(dead_code)]
        pub bbox: Option<IgnoredAny>,
    }
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
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
    #[serde(tag = "type", content = "coordinates", deny_unknown_fields)]
    pub enum Geometry {
        Polygon(Vec<Vec<[f64; 2]>>),
        LineString(Vec<[f64; 2]>),
    }
}

/// The fast path: `Some` only for a file with nothing to report (no error, no warning),
/// which then reads exactly as the general path reads it (public for the differential
/// fuzz target; [`parse`](crate::scenario::parse) is the reader to use).
pub fn fast_parse(text: &str) -> Option<Read> {
    let fc: typed::Collection = serde_json::from_str(text).ok()?;
    if fc.ty != "FeatureCollection" {
        return None;
    }
    let longitudes = match fc.longitudes.as_deref() {
        None | Some("earth") => Longitudes::Earth,
        Some("unrolled") => Longitudes::Unrolled,
        Some(_) => return None,
    };
    let mut out = Scenario {
        features: Vec::new(),
        longitudes,
        geodesy: Default::default(),
    };
    let mut seen = std::collections::HashSet::with_capacity(fc.features.len());
    for (index, f) in fc.features.into_iter().enumerate() {
        let p = f.properties;
        if f.ty != "Feature" || !seen.insert(p.id.clone()) {
            return None;
        }
        let ctx = Ctx {
            index,
            id: Some(&p.id),
            line: None,
        };
        // None (to the general path) for a warning: a longitude wrapped
        let pts = |field: &str,
                   v: &[[f64; 2]],
                   ring: bool|
         -> Option<Result<Vec<LonLat>, ScenarioError>> {
            for (k, q) in v.iter().enumerate() {
                if let Err(e) = checked(&ctx, field, k, q[0], q[1]) {
                    return Some(Err(e));
                }
            }
            match lay_out(&ctx, field, v, longitudes, ring, 0.0) {
                Ok((_, Some(_))) => None,
                Ok((laid, None)) => Some(Ok(laid
                    .into_iter()
                    .map(|[lon, lat]| LonLat::from_degrees(lon, lat))
                    .collect())),
                Err(e) => Some(Err(e)),
            }
        };
        let kind = match (p.kind.as_str(), &f.geometry) {
            ("area", typed::Geometry::Polygon(rings))
                if rings.len() == 1
                    && p.speed_kn.is_none()
                    && p.front_nm.is_none()
                    && p.back_nm.is_none()
                    && p.side_nm.is_none() =>
            {
                let r = rings.first()?;
                pts("geometry.coordinates[0]", r, true)?
                    .and_then(|ring| area_from(&ctx, ring, p.t0, p.tf))
                    .map(Kind::Area)
            }
            ("track", typed::Geometry::LineString(line)) if p.tf.is_none() => {
                pts("geometry.coordinates", line, false)?
                    .and_then(|w| {
                        track_from(
                            &ctx,
                            w,
                            p.speed_kn,
                            [p.front_nm, p.back_nm, p.side_nm],
                            p.t0,
                        )
                    })
                    .map(Kind::Track)
            }
            _ => return None,
        };
        out.features.push(Feature {
            id: p.id,
            kind: kind.ok()?,
            extra: Map::new(),
        });
    }
    Some(Read {
        scenario: out,
        ..Read::default()
    })
}
