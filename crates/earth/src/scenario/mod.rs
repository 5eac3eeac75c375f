//! The scenario GeoJSON of docs/scenario.md (paper B's areas and tracks).
//!
//! - the model ([`Scenario`], [`Feature`], [`Area`], [`Track`]…): what a scenario is, in
//!   radians on the sphere's longitude and latitude;
//! - reading ([`parse`]): strict per feature and forgiving per file: a bad feature yields
//!   a [`ScenarioError`] naming its line, index, id and field and is skipped, the others
//!   are still read. Only a file that is not a GeoJSON FeatureCollection at all is a
//!   fatal error;
//! - writing ([`to_geojson`]): the format's GeoJSON, which reads back the same;
//! - [`objects`]: the scenario's objects for paper B's four stages.

mod model;
mod objects;
mod read;
#[cfg(test)]
mod testdata;
mod write;

pub use model::{
    normal_lon, Area, Feature, Kind, Longitudes, Scenario, Shape, Track, MAX_ABS_LAT_DEG,
    MAX_RECT_LAT_DEG,
};
pub use objects::objects;
pub use read::{
    fast_parse, parse, parse_general, Problem, Read, ScenarioError, ScenarioWarning, Warning,
};
pub use write::{feature_geojson, to_geojson};
