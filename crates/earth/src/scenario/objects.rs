//! The scenario's objects for paper B's four stages (Sections III and V).

use super::model::{Kind, Longitudes, Scenario};
use crate::conflict::Object;
use crate::sphere::{self, LonLat};

/// Paper B Sections III and V: the scenario's objects in the Mercator plane, one per area
/// and one per track leg, `owner` = feature index in `scenario.features`. On the Earth an
/// object that reaches past ±180° comes with its copies a turn away
/// ([`Object::on_earth`]), so that stage 1 finds its meetings across the antimeridian.
pub fn objects(scenario: &Scenario) -> Vec<Object> {
    use rayon::prelude::*;
    let earth = scenario.longitudes == Longitudes::Earth;
    let geo = scenario.geodesy;
    scenario
        .features
        .par_iter()
        .enumerate()
        .flat_map_iter(|(k, f)| {
            let owner = k as u32;
            let merc =
                |r: &[LonLat]| -> Vec<[f64; 2]> { r.iter().map(|&p| geo.mercator(p)).collect() };
            let v: Vec<Object> = match &f.kind {
                Kind::Area(a) => a
                    .shapes
                    .iter()
                    .map(|sh| {
                        Object::area_with_holes(
                            owner,
                            merc(&sh.ring),
                            sh.holes.iter().map(|h| merc(h)).collect(),
                            a.t0.unwrap_or(f64::NEG_INFINITY),
                            a.tf.unwrap_or(f64::INFINITY),
                        )
                    })
                    .collect(),
                Kind::Track(t) => {
                    sphere::track_legs_in(geo, &t.waypoints, t.speed_kn, t.t0, t.dims)
                        .into_iter()
                        .map(|leg| Object::leg(owner, leg))
                        .collect()
                }
            };
            v.into_iter().flat_map(move |o| {
                if earth {
                    o.on_earth()
                } else {
                    vec![o.on_plane()]
                }
            })
        })
        .collect()
}
