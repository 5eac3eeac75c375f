//! The GeoJSON pieces of the moving-features formats (RFC 7946 §3.1): numbers, positions
//! `[lon, lat]` or `[lon, lat, height]`, closed linear rings and polygons, each checked
//! and each error naming its feature, member path and line (docs/moving-features.md,
//! "Formats").

use super::error::{ErrorKind, Location, MovingError};
use super::model::Rings;
use crate::json::{Json, Lines, Node};

/// The latitude limit of positions, degrees: the Mercator plane's (as the model's
/// [`super::model::Fix::lat`]).
pub const MAX_LAT: f64 = 85.0;

/// Where a reader is: the text's lines and the feature being read, to make locations.
#[derive(Clone, Debug)]
pub struct Ctx<'a> {
    /// The line table of the parsed text.
    pub lines: &'a Lines,
    /// Lines before the parsed text (a JSON Lines record is parsed alone).
    pub line_base: usize,
    /// The feature's index, counting from 0.
    pub feature: Option<usize>,
    /// The feature's id, once known.
    pub id: Option<String>,
}

impl Ctx<'_> {
    /// The location of the value starting at byte `at`, member `member`.
    pub fn loc(&self, at: usize, member: &str) -> Location {
        Location {
            line: Some(self.line_base + self.lines.line(at)),
            feature: self.feature,
            id: self.id.clone(),
            member: (!member.is_empty()).then(|| member.to_owned()),
        }
    }

    /// An error of `kind` about the value at `at`, member `member`.
    pub fn err(
        &self,
        at: usize,
        member: &str,
        kind: ErrorKind,
        detail: impl Into<String>,
    ) -> MovingError {
        MovingError::new(self.loc(at, member), kind, detail)
    }

    /// The error for a value of the wrong type.
    pub fn wrong(&self, n: &Node, member: &str, expected: &str) -> MovingError {
        self.err(
            n.at,
            member,
            ErrorKind::WrongType,
            format!("expected {expected}, found {}", n.value.kind()),
        )
    }

    /// A finite number (RFC 8259 has no others; `NaN`, `Infinity` and a literal beyond
    /// the f64 range are errors of their member).
    pub fn number(&self, n: &Node, member: &str) -> Result<f64, MovingError> {
        match n.value {
            Json::Number(x) if x.is_finite() => Ok(x),
            Json::Number(x) => Err(self.err(
                n.at,
                member,
                ErrorKind::NotFinite,
                format!("{x} (beyond the f64 range)"),
            )),
            Json::NotJson(w) => Err(self.err(n.at, member, ErrorKind::NotFinite, w)),
            _ => Err(self.wrong(n, member, "a number")),
        }
    }

    /// The elements of an array member.
    pub fn array<'n>(&self, n: &'n Node, member: &str) -> Result<&'n [Node], MovingError> {
        n.elements()
            .ok_or_else(|| self.wrong(n, member, "an array"))
    }
}

/// A position (RFC 7946 §3.1.1): longitude in [-180, 180], latitude in [-85, 85], and
/// an optional third element, the height in the CRS's unit (metres).
pub fn position(ctx: &Ctx, n: &Node, member: &str) -> Result<([f64; 2], Option<f64>), MovingError> {
    let e = ctx.array(n, member)?;
    if e.len() < 2 {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::WrongType,
            format!(
                "a position is [longitude, latitude], found {} numbers",
                e.len()
            ),
        ));
    }
    if e.len() > 3 {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::Unsupported,
            "a position has at most 3 numbers (longitude, latitude, height)",
        ));
    }
    let lon = ctx.number(&e[0], &format!("{member}[0]"))?;
    let lat = ctx.number(&e[1], &format!("{member}[1]"))?;
    if !(-180.0..=180.0).contains(&lon) {
        return Err(ctx.err(
            e[0].at,
            &format!("{member}[0]"),
            ErrorKind::OutOfRange,
            format!("longitude {lon} is not in [-180, 180]"),
        ));
    }
    if !(-MAX_LAT..=MAX_LAT).contains(&lat) {
        return Err(ctx.err(
            e[1].at,
            &format!("{member}[1]"),
            ErrorKind::OutOfRange,
            format!("latitude {lat} is not in [-85, 85] (the Mercator plane's limit)"),
        ));
    }
    let h = match e.get(2) {
        Some(z) => Some(ctx.number(z, &format!("{member}[2]"))?),
        None => None,
    };
    Ok(([lon, lat], h))
}

/// A linear ring (RFC 7946 §3.1.6): closed (its last position repeats its first), the
/// repeat dropped; at least 3 distinct vertices. Heights are not part of an area (its
/// vertical extent is `floor_ft`/`ceiling_ft`) and are read and dropped.
pub fn ring(ctx: &Ctx, n: &Node, member: &str) -> Result<Vec<[f64; 2]>, MovingError> {
    let e = ctx.array(n, member)?;
    let mut v = Vec::with_capacity(e.len());
    for (k, p) in e.iter().enumerate() {
        v.push(position(ctx, p, &format!("{member}[{k}]"))?.0);
    }
    if v.len() < 2 || v.first() != v.last() {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::WrongType,
            "a ring must end with its first position (GeoJSON linear ring)",
        ));
    }
    v.pop();
    let mut distinct = v.clone();
    distinct.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    distinct.dedup();
    if distinct.len() < 3 {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::TooFewVertices,
            format!(
                "a ring needs at least 3 distinct vertices, found {}",
                distinct.len()
            ),
        ));
    }
    Ok(v)
}

/// A Polygon's coordinates (RFC 7946 §3.1.6): the outer ring then the holes.
pub fn polygon(ctx: &Ctx, n: &Node, member: &str) -> Result<Rings, MovingError> {
    let e = ctx.array(n, member)?;
    if e.is_empty() {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::Missing,
            "a polygon needs its outer ring",
        ));
    }
    let mut rings = Vec::with_capacity(e.len());
    for (k, r) in e.iter().enumerate() {
        rings.push(ring(ctx, r, &format!("{member}[{k}]"))?);
    }
    let outer = rings.remove(0);
    Ok(Rings {
        outer,
        holes: rings,
    })
}

/// A MultiPolygon's coordinates (RFC 7946 §3.1.7): its polygons (at least one).
pub fn multi_polygon(ctx: &Ctx, n: &Node, member: &str) -> Result<Vec<Rings>, MovingError> {
    let e = ctx.array(n, member)?;
    if e.is_empty() {
        return Err(ctx.err(
            n.at,
            member,
            ErrorKind::Missing,
            "a MultiPolygon needs at least one polygon",
        ));
    }
    e.iter()
        .enumerate()
        .map(|(k, p)| polygon(ctx, p, &format!("{member}[{k}]")))
        .collect()
}
