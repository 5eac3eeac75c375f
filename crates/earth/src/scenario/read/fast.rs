//! The fast path: clean files deserialize straight into typed structures (no tree), and
//! anything else goes to the general path. The collection is split into its features'
//! raw text in one pass, and the features are read on every core.

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
    use serde_json::value::RawValue;
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Collection<'a> {
        #[serde(rename = "type")]
        pub ty: String,
        #[serde(borrow)]
        pub features: Vec<&'a RawValue>,
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

/// Features read by one task: a small collection (the assurance hunt's two-feature
/// scenarios) is read on one core, without handing work between threads.
const FEATURES_PER_TASK: usize = 16;

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
    let features: Vec<typed::Feature> = {
        use rayon::prelude::*;
        fc.features
            .par_iter()
            .with_min_len(FEATURES_PER_TASK)
            .map(|raw| serde_json::from_str::<typed::Feature>(raw.get()).ok())
            .collect::<Option<Vec<_>>>()?
    };
    // ids are unique: a repeated one is the general path's to report
    let mut seen = std::collections::HashSet::with_capacity(features.len());
    if !features
        .iter()
        .all(|f| seen.insert(f.properties.id.as_str()))
    {
        return None;
    }
    drop(seen);
    let features: Vec<Feature> = {
        use rayon::prelude::*;
        features
            .into_par_iter()
            .with_min_len(FEATURES_PER_TASK)
            .enumerate()
            .map(|(index, f)| feature(index, f, longitudes))
            .collect::<Option<Vec<_>>>()?
    };
    let out = Scenario {
        features,
        longitudes,
        geodesy: Default::default(),
    };
    Some(Read {
        scenario: out,
        ..Read::default()
    })
}

/// One feature of a clean file, read by the format's rules: `None` (to the general path)
/// for anything to report, a warning included.
fn feature(index: usize, f: typed::Feature, longitudes: Longitudes) -> Option<Feature> {
    let p = f.properties;
    if f.ty != "Feature" {
        return None;
    }
    let ctx = Ctx {
        index,
        id: Some(&p.id),
        line: None,
    };
    // None (to the general path) for a warning: a longitude wrapped
    let pts =
        |field: &str, v: &[[f64; 2]], ring: bool| -> Option<Result<Vec<LonLat>, ScenarioError>> {
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
    let kind = kind.ok()?;
    Some(Feature {
        id: p.id,
        kind,
        extra: Map::new(),
    })
}
