//! Reading a scenario: a typed fast path for clean files, and the general path that names
//! the line, feature and field of every problem; both apply the format's rules
//! ([`rules`]) and agree wherever the fast path answers.

mod errors;
mod fast;
mod general;
mod members;
mod rules;
#[cfg(test)]
pub(super) mod testkit;

pub use errors::{Problem, ScenarioError, ScenarioWarning, Warning};
pub use fast::fast_parse;
pub use general::parse_general;

use super::model::Scenario;

/// What [`parse`] read: the valid features, an error per rejected feature, and the
/// warnings (nothing here prints: the caller shows them).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Read {
    /// The valid features.
    pub scenario: Scenario,
    /// One per rejected feature (the first thing wrong with it).
    pub errors: Vec<ScenarioError>,
    /// One per member not read (a foreign member of the collection, a feature or a
    /// geometry, or a `properties` member the format does not define, kept) and per
    /// feature with a longitude beyond ±180° read modulo 360°; of the valid features and
    /// the collection only.
    pub warnings: Vec<ScenarioWarning>,
}

/// Reads a scenario. `Err` only when the text is not a GeoJSON FeatureCollection; a bad
/// feature is reported (its line, index, id and field) and skipped, the others are read.
/// A byte-order mark in front is skipped.
pub fn parse(text: &str) -> Result<Read, ScenarioError> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some(r) = fast_parse(body) {
        return Ok(r);
    }
    parse_general(text)
}
