//! Which members each GeoJSON object of a scenario may have (RFC 7946 §3, §6.1, §7.1 and
//! docs/scenario.md, "Strict reading").
//!
//! A member of the FeatureCollection, a Feature or a geometry object is one of four
//! things:
//! - **defined**: a member of RFC 7946 at that level (`type`, `bbox`, a Feature's `id`…),
//!   one the format reads there (`longitudes`, `crs`), or the collection's `name` that
//!   GDAL and QGIS write;
//! - **misplaced**, an error: a member RFC 7946 §7.1 forbids at that level (`coordinates`
//!   on a Feature) or a name the format defines elsewhere (`t0` beside `properties`
//!   instead of in it, `longitudes` on a Feature): it would be ignored where it is;
//! - **misspelt**, an error: within a few letters of a defined member that the object
//!   lacks and whose absence changes the reading (`geometyr` for `geometry`, `longitude`
//!   for `longitudes`): a misspelling must not change the meaning silently;
//! - **foreign** (RFC 7946 §6.1): any other member, such as `generator` or `title`
//!   written by another tool. It is not read, and the reader warns of it by name.

use crate::json::{self, Member};

/// The three levels of GeoJSON object a scenario has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Level {
    /// The FeatureCollection.
    Collection,
    /// A Feature.
    Feature,
    /// A Feature's geometry object.
    Geometry,
}

/// What a member is at its level (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Verdict {
    /// Defined at this level.
    Defined,
    /// Not allowed at this level: where it belongs.
    Misplaced(&'static str),
    /// Most likely a misspelling of this defined member, which the object lacks.
    Misspelt(&'static str),
    /// A foreign member (RFC 7946 §6.1): not read.
    Foreign,
}

/// The properties the format defines (docs/scenario.md, "Features"), but `id`, which RFC
/// 7946 defines on a Feature and which is foreign elsewhere.
const PROPERTIES: [&str; 7] = [
    "kind", "t0", "tf", "speed_kn", "front_nm", "back_nm", "side_nm",
];

impl Level {
    /// The members defined at this level: RFC 7946's, and those the format reads or
    /// GDAL and QGIS write (the collection's `name`; `crs`, checked to name WGS 84, at
    /// every level, as GeoJSON of 2008 allowed).
    pub(super) fn defined(self) -> &'static [&'static str] {
        match self {
            Level::Collection => &["type", "features", "bbox", "name", "crs", "longitudes"],
            Level::Feature => &["type", "properties", "geometry", "id", "bbox", "crs"],
            Level::Geometry => &["type", "coordinates", "bbox", "crs"],
        }
    }

    /// The defined members whose absence changes the reading: a near miss of one of them
    /// that the object lacks is taken for a misspelling. (`bbox`, `name` and a Feature's
    /// `id` are not read; a near miss of them is foreign.)
    fn read(self) -> &'static [&'static str] {
        match self {
            Level::Collection => &["type", "features", "crs", "longitudes"],
            Level::Feature => &["type", "properties", "geometry", "crs"],
            Level::Geometry => &["type", "coordinates", "crs"],
        }
    }

    /// Where `key` belongs when this level may not have it: RFC 7946 §7.1's members of
    /// other kinds of object, and the format's names of another level.
    fn misplaced(self, key: &str) -> Option<&'static str> {
        const GEOMETRY: &str = "a geometry object (RFC 7946 §7.1)";
        const COLLECTION: &str = "the FeatureCollection (RFC 7946 §7.1)";
        const FEATURE: &str = "a Feature (RFC 7946 §7.1)";
        match (self, key) {
            (Level::Collection | Level::Feature, "coordinates") => Some(GEOMETRY),
            (Level::Collection | Level::Feature, "geometries") => {
                Some("a GeometryCollection (RFC 7946 §7.1)")
            }
            (Level::Collection | Level::Geometry, "geometry" | "properties") => Some(FEATURE),
            (Level::Feature | Level::Geometry, "features") => Some(COLLECTION),
            (Level::Feature | Level::Geometry, "longitudes") => {
                Some("the FeatureCollection (docs/scenario.md)")
            }
            (_, k) if PROPERTIES.contains(&k) => Some("a Feature's properties (docs/scenario.md)"),
            _ => None,
        }
    }
}

/// What the member `key` of an object at `level` is (module doc); `members` are all the
/// object's members, for the defined ones it lacks.
pub(super) fn judge(level: Level, key: &str, members: &[Member]) -> Verdict {
    if level.defined().contains(&key) {
        return Verdict::Defined;
    }
    if let Some(place) = level.misplaced(key) {
        return Verdict::Misplaced(place);
    }
    let lacking: Vec<&'static str> = level
        .read()
        .iter()
        .copied()
        .filter(|d| !members.iter().any(|m| m.key == *d))
        .collect();
    match json::suggest(key, &lacking) {
        Some(d) => Verdict::Misspelt(d),
        None => Verdict::Foreign,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::{Json, Node};

    /// An object's members with these keys (the values do not matter here).
    fn members(keys: &[&str]) -> Vec<Member> {
        keys.iter()
            .map(|k| Member {
                key: (*k).to_owned(),
                at: 0,
                value: Node {
                    at: 0,
                    value: Json::Null,
                },
            })
            .collect()
    }

    /// Each kind of member at each level, as the module doc sorts them.
    #[test]
    fn each_member_is_defined_misplaced_misspelt_or_foreign() {
        use Level::{Collection, Feature, Geometry};
        use Verdict::{Defined, Foreign, Misplaced, Misspelt};
        let feature = members(&["type", "properties", "geometry"]);
        let collection = members(&["type", "features"]);
        let geometry = members(&["type", "coordinates"]);
        let cases = [
            (Collection, "name", &collection, Defined),
            (Collection, "longitudes", &collection, Defined),
            (Collection, "generator", &collection, Foreign),
            (Collection, "title", &collection, Foreign),
            (Collection, "metadata", &collection, Foreign),
            (Collection, "longitude", &collection, Misspelt("longitudes")),
            (
                Collection,
                "feature",
                &members(&["type"]),
                Misspelt("features"),
            ),
            // with `features` there, a near miss is another member
            (Collection, "feature", &collection, Foreign),
            (
                Collection,
                "properties",
                &collection,
                Misplaced("a Feature (RFC 7946 §7.1)"),
            ),
            (
                Collection,
                "kind",
                &collection,
                Misplaced("a Feature's properties (docs/scenario.md)"),
            ),
            (Feature, "id", &feature, Defined),
            (Feature, "crs", &feature, Defined),
            (Feature, "style", &feature, Foreign),
            (Feature, "title", &feature, Foreign),
            (
                Feature,
                "geometyr",
                &members(&["type", "properties"]),
                Misspelt("geometry"),
            ),
            (
                Feature,
                "coordinates",
                &feature,
                Misplaced("a geometry object (RFC 7946 §7.1)"),
            ),
            (
                Feature,
                "features",
                &feature,
                Misplaced("the FeatureCollection (RFC 7946 §7.1)"),
            ),
            (
                Feature,
                "t0",
                &feature,
                Misplaced("a Feature's properties (docs/scenario.md)"),
            ),
            (
                Feature,
                "longitudes",
                &feature,
                Misplaced("the FeatureCollection (docs/scenario.md)"),
            ),
            (Geometry, "bbox", &geometry, Defined),
            (Geometry, "style", &geometry, Foreign),
            (Geometry, "coords", &geometry, Foreign),
            (
                Geometry,
                "coordinate",
                &members(&["type"]),
                Misspelt("coordinates"),
            ),
            (
                Geometry,
                "properties",
                &geometry,
                Misplaced("a Feature (RFC 7946 §7.1)"),
            ),
            (
                Geometry,
                "speed_kn",
                &geometry,
                Misplaced("a Feature's properties (docs/scenario.md)"),
            ),
        ];
        for (level, key, present, want) in cases {
            assert_eq!(judge(level, key, present), want, "{level:?} {key}");
        }
    }
}
