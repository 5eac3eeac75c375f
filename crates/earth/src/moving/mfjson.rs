//! OGC Moving Features JSON (OGC 19-045r3) and GeoJSON areas (RFC 7946), read from text
//! into the model (docs/moving-features.md, "Formats").
//!
//! The input is a FeatureCollection, a single Feature, or JSON Lines (one Feature a line,
//! blank lines skipped). Each feature gives an [`Item`] or a [`MovingError`] naming where;
//! a bad feature does not stop the others. Forms read:
//! - a mover as MF-JSON's trajectory form: geometry `LineString`, `properties.datetimes`;
//! - a mover as a `temporalGeometry` of type `MovingPoint` (interpolation `Linear` or
//!   absent), with an optional `altitude` temporal property;
//! - a keyframed area as a `temporalGeometry` of type `MovingPolygon` (interpolation
//!   `Linear`), one polygon per instant, the same rings and vertex counts at each;
//! - a static area as a geometry `Polygon` or `MultiPolygon`.

use super::error::{ErrorKind, Location, MovingError, MovingWarning, WarningKind};
use super::geojson::{multi_polygon, polygon, position, Ctx};
use super::model::{Area, Fix, Keyframe, Rings, Shape, Trajectory};
use super::time;
use crate::json::{self, Json, Lines, Member, Node};

/// Feet per metre: 1 ft = 0.3048 m exactly (the international foot).
pub const M_PER_FT: f64 = 0.3048;

/// The members MF-JSON and GeoJSON define on a FeatureCollection.
const COLLECTION_MEMBERS: [&str; 8] = [
    "type",
    "features",
    "crs",
    "trs",
    "bbox",
    "time",
    "stBoundedBy",
    "label",
];
/// The members MF-JSON and GeoJSON define on a Feature.
const FEATURE_MEMBERS: [&str; 10] = [
    "type",
    "id",
    "geometry",
    "properties",
    "temporalGeometry",
    "temporalProperties",
    "crs",
    "trs",
    "time",
    "bbox",
];
/// The members of a GeoJSON geometry.
const GEOMETRY_MEMBERS: [&str; 3] = ["type", "coordinates", "bbox"];
/// The members MF-JSON defines on a temporal primitive geometry (OGC 19-045r3 §7.2.1);
/// any other member there is an error.
const TEMPORAL_GEOMETRY_MEMBERS: [&str; 8] = [
    "type",
    "datetimes",
    "coordinates",
    "interpolation",
    "base",
    "orientations",
    "crs",
    "trs",
];
/// The CRS names that mean RFC 7946's own (WGS 84 longitude, latitude in degrees).
const WGS84_NAMES: [&str; 4] = [
    "urn:ogc:def:crs:OGC:1.3:CRS84",
    "urn:ogc:def:crs:OGC::CRS84",
    "EPSG:4326",
    "urn:ogc:def:crs:EPSG::4326",
];
/// The area properties this format defines.
const AREA_PROPS: [&str; 2] = ["floor_ft", "ceiling_ft"];

/// One feature read.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A mover (trajectory form or MovingPoint).
    Mover(Trajectory),
    /// An area (Polygon, MultiPolygon or MovingPolygon).
    Area(Area),
}

/// What a text gave: every feature in order, and the warnings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MfRead {
    /// Each feature's item or its error, in input order.
    pub items: Vec<Result<Item, MovingError>>,
    /// Remarks that did not stop a feature being read.
    pub warnings: Vec<MovingWarning>,
}

/// Reads a FeatureCollection, a Feature or JSON Lines of Features. The error is for a
/// text that is none of them (not JSON, or JSON of another kind); problems of single
/// features are in [`MfRead::items`].
pub fn read(text: &str) -> Result<MfRead, MovingError> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let lines = Lines::new(text);
    match json::parse(text) {
        Ok(root) => {
            let mut out = MfRead::default();
            let ctx = Ctx {
                lines: &lines,
                line_base: 0,
                feature: None,
                id: None,
            };
            document(&ctx, &root, &mut out)?;
            Ok(out)
        }
        // one value and then more: JSON Lines
        Err(e) if e.message.contains("after the JSON value") => Ok(json_lines(body)),
        Err(e) => Err(MovingError::new(
            Location {
                line: Some(lines.line(e.at)),
                ..Location::default()
            },
            ErrorKind::Syntax,
            e.message,
        )),
    }
}

/// JSON Lines: each non-blank line one Feature, parsed alone.
fn json_lines(body: &str) -> MfRead {
    let mut out = MfRead::default();
    for (k, line) in body.split('\n').enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let index = out.items.len();
        let lines = Lines::new(line);
        let ctx = Ctx {
            lines: &lines,
            line_base: k,
            feature: Some(index),
            id: None,
        };
        let item = match json::parse(line) {
            Ok(node) => feature(&ctx, &node, &mut out.warnings),
            Err(e) => Err(ctx.err(e.at, "", ErrorKind::Syntax, e.message)),
        };
        out.items.push(item);
    }
    out
}

/// A whole JSON document: a FeatureCollection or one Feature.
fn document(ctx: &Ctx, root: &Node, out: &mut MfRead) -> Result<(), MovingError> {
    let members = root
        .members()
        .ok_or_else(|| ctx.wrong(root, "", "a FeatureCollection or a Feature object"))?;
    match root.get("type").and_then(Node::as_str) {
        Some("FeatureCollection") => {}
        Some("Feature") => {
            let c = Ctx {
                feature: Some(0),
                ..ctx.clone()
            };
            out.items.push(feature(&c, root, &mut out.warnings));
            return Ok(());
        }
        Some(other) => {
            return Err(ctx.err(
                root.at,
                "type",
                ErrorKind::Unsupported,
                format!("expected FeatureCollection or Feature, found {other:?}"),
            ))
        }
        None => return Err(ctx.err(root.at, "type", ErrorKind::Missing, "no \"type\"")),
    }
    no_repeats(ctx, members, "")?;
    foreign(ctx, members, &COLLECTION_MEMBERS, "", &mut out.warnings);
    if let Some(c) = root.get("crs") {
        crs(ctx, c, "crs")?;
    }
    let features = root
        .get("features")
        .ok_or_else(|| ctx.err(root.at, "features", ErrorKind::Missing, "no \"features\""))?;
    let features = ctx.array(features, "features")?;
    for (k, f) in features.iter().enumerate() {
        let c = Ctx {
            feature: Some(k),
            ..ctx.clone()
        };
        out.items.push(feature(&c, f, &mut out.warnings));
    }
    Ok(())
}

/// The first member given twice in `members`, as an error.
fn no_repeats(ctx: &Ctx, members: &[Member], prefix: &str) -> Result<(), MovingError> {
    let mut seen = std::collections::HashSet::with_capacity(members.len());
    match members.iter().find(|m| !seen.insert(m.key.as_str())) {
        Some(m) => Err(ctx.err(
            m.at,
            &join(prefix, &m.key),
            ErrorKind::DuplicateMember,
            format!("{:?} appears more than once in one object", m.key),
        )),
        None => Ok(()),
    }
}

/// `prefix.key`, or `key` at the top.
fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_owned()
    } else {
        format!("{prefix}.{key}")
    }
}

/// Warnings naming the members outside `known` (RFC 7946 §6.1 foreign members).
fn foreign(
    ctx: &Ctx,
    members: &[Member],
    known: &[&str],
    prefix: &str,
    warnings: &mut Vec<MovingWarning>,
) {
    for m in members.iter().filter(|m| !known.contains(&m.key.as_str())) {
        warnings.push(MovingWarning::new(
            ctx.loc(m.at, &join(prefix, &m.key)),
            WarningKind::ForeignMember,
            format!("foreign member {:?} ignored", m.key),
        ));
    }
}

/// A `crs` member: absent, null, or a name meaning WGS 84 longitude/latitude degrees;
/// any other CRS would misread the positions.
fn crs(ctx: &Ctx, n: &Node, member: &str) -> Result<(), MovingError> {
    if n.value == Json::Null {
        return Ok(());
    }
    let name = n
        .get("properties")
        .and_then(|p| p.get("name"))
        .and_then(Node::as_str);
    match name {
        Some(name) if WGS84_NAMES.contains(&name) => Ok(()),
        Some(name) => Err(ctx.err(
            n.at,
            member,
            ErrorKind::Unsupported,
            format!("CRS {name:?}: positions must be WGS 84 longitude, latitude degrees"),
        )),
        None => Err(ctx.err(
            n.at,
            member,
            ErrorKind::Unsupported,
            "only a named CRS (urn:ogc:def:crs:OGC:1.3:CRS84) is read",
        )),
    }
}

/// A string or number id as text (an integral number without a fraction).
fn id_text(n: &Node) -> Option<String> {
    match &n.value {
        Json::String(s) => Some(s.clone()),
        Json::Number(x) if x.fract() == 0.0 && x.abs() < 9.0e15 => Some(format!("{}", *x as i64)),
        Json::Number(x) => Some(x.to_string()),
        _ => None,
    }
}

/// The feature's id: its `id`, else `properties.id`, else `properties.traj_id` (what
/// MovingPandas writes), else `properties.flight_id` (traffic's), else its index.
fn feature_id(f: &Node, index: usize) -> String {
    let props = f.get("properties");
    f.get("id")
        .and_then(id_text)
        .or_else(|| {
            ["id", "traj_id", "flight_id"]
                .iter()
                .find_map(|k| props.and_then(|p| p.get(k)).and_then(id_text))
        })
        .unwrap_or_else(|| index.to_string())
}

/// One Feature: a mover or an area, or the error that makes it unusable.
fn feature(ctx: &Ctx, f: &Node, warnings: &mut Vec<MovingWarning>) -> Result<Item, MovingError> {
    let members = f
        .members()
        .ok_or_else(|| ctx.wrong(f, "", "a Feature object"))?;
    let index = ctx.feature.unwrap_or(0);
    let ctx = &Ctx {
        id: Some(feature_id(f, index)),
        ..ctx.clone()
    };
    if let Some((path, at)) = json::repeated_key(f) {
        return Err(ctx.err(
            at,
            &path,
            ErrorKind::DuplicateMember,
            "a member appears more than once in one object",
        ));
    }
    match f.get("type").and_then(Node::as_str) {
        Some("Feature") => {}
        Some(other) => {
            return Err(ctx.err(
                f.at,
                "type",
                ErrorKind::Unsupported,
                format!("expected \"Feature\", found {other:?}"),
            ))
        }
        None => return Err(ctx.err(f.at, "type", ErrorKind::Missing, "no \"type\": \"Feature\"")),
    }
    foreign(ctx, members, &FEATURE_MEMBERS, "", warnings);
    if let Some(c) = f.get("crs") {
        crs(ctx, c, "crs")?;
    }
    let props = match f.get("properties") {
        None => None,
        Some(p) if p.value == Json::Null => None,
        Some(p) => {
            p.members()
                .ok_or_else(|| ctx.wrong(p, "properties", "an object or null"))?;
            Some(p)
        }
    };
    let id = ctx.id.clone().unwrap_or_default();
    if let Some(tg) = f.get("temporalGeometry") {
        return temporal(ctx, f, tg, props, id, warnings);
    }
    let g = f
        .get("geometry")
        .filter(|g| g.value != Json::Null)
        .ok_or_else(|| {
            ctx.err(
                f.at,
                "geometry",
                ErrorKind::Missing,
                "a feature needs a geometry (LineString, Polygon, MultiPolygon) or a temporalGeometry",
            )
        })?;
    let gm = g
        .members()
        .ok_or_else(|| ctx.wrong(g, "geometry", "an object"))?;
    foreign(ctx, gm, &GEOMETRY_MEMBERS, "geometry", warnings);
    let coords = g.get("coordinates").ok_or_else(|| {
        ctx.err(
            g.at,
            "geometry.coordinates",
            ErrorKind::Missing,
            "no coordinates",
        )
    })?;
    let member = "geometry.coordinates";
    match g.get("type").and_then(Node::as_str) {
        Some("LineString") => {
            let times = props.and_then(|p| p.get("datetimes")).ok_or_else(|| {
                ctx.err(
                    f.at,
                    "properties.datetimes",
                    ErrorKind::Missing,
                    "a LineString mover needs properties.datetimes, one per position",
                )
            })?;
            let (t, no_offset) = datetimes(ctx, times, "properties.datetimes")?;
            note_offset(ctx, times, "properties.datetimes", no_offset, warnings);
            mover(ctx, id, props, coords, member, times, &t, None).map(Item::Mover)
        }
        Some("Polygon") => {
            let rings = polygon(ctx, coords, member)?;
            area(ctx, id, props, Shape::Static(vec![rings])).map(Item::Area)
        }
        Some("MultiPolygon") => {
            let parts = multi_polygon(ctx, coords, member)?;
            area(ctx, id, props, Shape::Static(parts)).map(Item::Area)
        }
        Some(other) => Err(ctx.err(
            g.at,
            "geometry.type",
            ErrorKind::Unsupported,
            format!(
                "geometry {other:?}: a mover is a LineString, an area a Polygon or MultiPolygon"
            ),
        )),
        None => Err(ctx.err(
            g.at,
            "geometry.type",
            ErrorKind::Missing,
            "no geometry type",
        )),
    }
}

/// A `datetimes` array: each an RFC 3339 string or epoch seconds as a number. Also says
/// whether some string had no UTC offset (read as UTC).
fn datetimes(ctx: &Ctx, n: &Node, member: &str) -> Result<(Vec<f64>, bool), MovingError> {
    let e = ctx.array(n, member)?;
    let mut out = Vec::with_capacity(e.len());
    let mut no_offset = false;
    for (k, x) in e.iter().enumerate() {
        let m = format!("{member}[{k}]");
        let t = match &x.value {
            Json::String(s) => {
                let p = time::parse(s).map_err(|why| {
                    ctx.err(x.at, &m, ErrorKind::BadTime, format!("{s:?}: {why}"))
                })?;
                no_offset |= !p.has_offset;
                p.t
            }
            Json::Number(_) | Json::NotJson(_) => {
                let v = ctx.number(x, &m)?;
                time::epoch_seconds(v)
                    .map_err(|why| ctx.err(x.at, &m, ErrorKind::OutOfRange, why))?
            }
            _ => return Err(ctx.wrong(x, &m, "an RFC 3339 string or epoch seconds")),
        };
        if let Some(&prev) = out.last() {
            if t <= prev {
                return Err(ctx.err(
                    x.at,
                    &m,
                    ErrorKind::TimesNotIncreasing,
                    format!(
                        "{} is not after the previous instant {}",
                        shown_time(t),
                        shown_time(prev)
                    ),
                ));
            }
        }
        out.push(t);
    }
    Ok((out, no_offset))
}

/// An instant for a message: RFC 3339 when printable, else seconds.
fn shown_time(t: f64) -> String {
    time::format(t, time::Round::Floor).unwrap_or_else(|| format!("{t} s"))
}

/// One warning for a feature whose date-times lacked a UTC offset.
fn note_offset(ctx: &Ctx, n: &Node, member: &str, no_offset: bool, w: &mut Vec<MovingWarning>) {
    if no_offset {
        w.push(MovingWarning::new(
            ctx.loc(n.at, member),
            WarningKind::NoOffset,
            "date-times without a UTC offset (as MovingPandas writes them) read as UTC",
        ));
    }
}

/// A string property, when present and a string.
fn text_prop(props: Option<&Node>, key: &str) -> Option<String> {
    props?.get(key)?.as_str().map(str::to_owned)
}

/// A mover from its positions (`coords`, member `member`) and instants `t` (from
/// `times`), with altitudes from a temporal property (feet) or else from the positions'
/// heights (metres, converted to feet).
#[allow(clippy::too_many_arguments)]
fn mover(
    ctx: &Ctx,
    id: String,
    props: Option<&Node>,
    coords: &Node,
    member: &str,
    times: &Node,
    t: &[f64],
    alt_ft: Option<Vec<Option<f64>>>,
) -> Result<Trajectory, MovingError> {
    let e = ctx.array(coords, member)?;
    if e.len() != t.len() {
        return Err(ctx.err(
            times.at,
            member,
            ErrorKind::LengthMismatch,
            format!("{} positions but {} date-times", e.len(), t.len()),
        ));
    }
    if e.len() < 2 {
        return Err(ctx.err(
            coords.at,
            member,
            ErrorKind::TooFewFixes,
            format!("a mover needs at least 2 fixes, found {}", e.len()),
        ));
    }
    let mut fixes = Vec::with_capacity(e.len());
    for (k, p) in e.iter().enumerate() {
        let m = format!("{member}[{k}]");
        let ([lon, lat], h) = position(ctx, p, &m)?;
        if h.is_some() && alt_ft.is_some() {
            return Err(ctx.err(
                p.at,
                &m,
                ErrorKind::Unsupported,
                "two altitudes: a height in the position and an altitude temporal property",
            ));
        }
        let alt = match &alt_ft {
            Some(a) => a[k],
            None => h.map(|m| m / M_PER_FT),
        };
        fixes.push(Fix {
            t: t[k],
            lon,
            lat,
            alt_ft: alt,
        });
    }
    Ok(Trajectory {
        id,
        callsign: text_prop(props, "callsign"),
        fixes,
    })
}

/// An area from its shape and its properties: `floor_ft` ≤ `ceiling_ft` when given, a
/// misspelling of either an error.
fn area(ctx: &Ctx, id: String, props: Option<&Node>, shape: Shape) -> Result<Area, MovingError> {
    let mut floor_ceiling = [None, None];
    if let Some(p) = props {
        for m in p.members().unwrap_or_default() {
            let member = format!("properties.{}", m.key);
            if let Some(k) = AREA_PROPS.iter().position(|&a| a == m.key) {
                floor_ceiling[k] = Some(ctx.number(&m.value, &member)?);
            } else if let Some(meant) = misspelt(&m.key) {
                return Err(ctx.err(
                    m.at,
                    &member,
                    ErrorKind::UnknownMember,
                    format!("{:?} is not read; did you mean {meant:?} (feet)?", m.key),
                ));
            }
        }
    }
    let [floor_ft, ceiling_ft] = floor_ceiling;
    if let (Some(f), Some(c)) = (floor_ft, ceiling_ft) {
        if f > c {
            let at = p_at(props, "floor_ft");
            return Err(ctx.err(
                at,
                "properties.floor_ft",
                ErrorKind::FloorAboveCeiling,
                format!("floor_ft {f} is above ceiling_ft {c}"),
            ));
        }
    }
    Ok(Area {
        id,
        name: text_prop(props, "name"),
        shape,
        floor_ft,
        ceiling_ft,
    })
}

/// The offset of property `key` (or of the properties) for a location.
fn p_at(props: Option<&Node>, key: &str) -> usize {
    props
        .and_then(|p| p.members())
        .and_then(|m| m.iter().find(|m| m.key == key))
        .map_or(0, |m| m.at)
}

/// The area property a key most likely misspells: one starting with `floor` or
/// `ceiling` (any case), or within 2 edits of `floor_ft` or `ceiling_ft`, but not
/// exactly either.
pub fn misspelt(key: &str) -> Option<&'static str> {
    if AREA_PROPS.contains(&key) {
        return None;
    }
    let lower = key.to_lowercase();
    if lower.starts_with("floor") {
        return Some("floor_ft");
    }
    if lower.starts_with("ceil") {
        return Some("ceiling_ft");
    }
    AREA_PROPS
        .iter()
        .map(|&a| (json::edit_distance(&lower, a), a))
        .filter(|&(d, _)| d <= 2)
        .min_by_key(|&(d, _)| d)
        .map(|(_, a)| a)
}

/// A `temporalGeometry` (OGC 19-045r3 §7.2.1): MovingPoint → mover, MovingPolygon →
/// keyframed area; other types unsupported.
fn temporal(
    ctx: &Ctx,
    f: &Node,
    tg: &Node,
    props: Option<&Node>,
    id: String,
    warnings: &mut Vec<MovingWarning>,
) -> Result<Item, MovingError> {
    let tm = tg
        .members()
        .ok_or_else(|| ctx.wrong(tg, "temporalGeometry", "an object"))?;
    for m in tm {
        if !TEMPORAL_GEOMETRY_MEMBERS.contains(&m.key.as_str()) {
            let hint = json::suggest(&m.key, &TEMPORAL_GEOMETRY_MEMBERS)
                .map(|s| format!("; did you mean {s:?}?"))
                .unwrap_or_default();
            return Err(ctx.err(
                m.at,
                &format!("temporalGeometry.{}", m.key),
                ErrorKind::UnknownMember,
                format!(
                    "{:?} is not a member of an MF-JSON temporal geometry{hint}",
                    m.key
                ),
            ));
        }
    }
    if let Some(c) = tg.get("crs") {
        crs(ctx, c, "temporalGeometry.crs")?;
    }
    let kind = tg.get("type").and_then(Node::as_str);
    let interp = tg.get("interpolation");
    let interp_text = interp.map(|n| {
        n.as_str()
            .ok_or_else(|| ctx.wrong(n, "temporalGeometry.interpolation", "a string"))
    });
    let interp_text = interp_text.transpose()?;
    let linear_needed = |required: bool| -> Result<(), MovingError> {
        match interp_text {
            Some("Linear") => Ok(()),
            None if !required => Ok(()),
            other => Err(ctx.err(
                interp.map_or(tg.at, |n| n.at),
                "temporalGeometry.interpolation",
                if other.is_none() {
                    ErrorKind::Missing
                } else {
                    ErrorKind::Unsupported
                },
                format!(
                    "{}: only \"Linear\" motion between instants is read",
                    other.map_or("absent".to_owned(), |o| format!("{o:?}"))
                ),
            )),
        }
    };
    let times = tg.get("datetimes").ok_or_else(|| {
        ctx.err(
            tg.at,
            "temporalGeometry.datetimes",
            ErrorKind::Missing,
            "no datetimes",
        )
    })?;
    let coords = tg.get("coordinates").ok_or_else(|| {
        ctx.err(
            tg.at,
            "temporalGeometry.coordinates",
            ErrorKind::Missing,
            "no coordinates",
        )
    })?;
    match kind {
        Some("MovingPoint") => {
            linear_needed(false)?;
            let (t, no_offset) = datetimes(ctx, times, "temporalGeometry.datetimes")?;
            note_offset(
                ctx,
                times,
                "temporalGeometry.datetimes",
                no_offset,
                warnings,
            );
            let alt = match f.get("temporalProperties") {
                Some(tp) => altitude(ctx, tp, &t, warnings)?,
                None => None,
            };
            mover(
                ctx,
                id,
                props,
                coords,
                "temporalGeometry.coordinates",
                times,
                &t,
                alt,
            )
            .map(Item::Mover)
        }
        Some("MovingPolygon") => {
            linear_needed(true)?;
            let (t, no_offset) = datetimes(ctx, times, "temporalGeometry.datetimes")?;
            note_offset(
                ctx,
                times,
                "temporalGeometry.datetimes",
                no_offset,
                warnings,
            );
            let frames = keyframes(ctx, coords, times, &t)?;
            area(ctx, id, props, Shape::Keyframed(frames)).map(Item::Area)
        }
        Some(other) => Err(ctx.err(
            tg.at,
            "temporalGeometry.type",
            ErrorKind::Unsupported,
            format!("{other:?}: only MovingPoint and MovingPolygon are read"),
        )),
        None => Err(ctx.err(
            tg.at,
            "temporalGeometry.type",
            ErrorKind::Missing,
            "no type",
        )),
    }
}

/// The polygons of a MovingPolygon, one per instant, each with the rings and vertex
/// counts of the first (the model's keyframes; OGC 19-045r3 requires it for Linear).
fn keyframes(
    ctx: &Ctx,
    coords: &Node,
    times: &Node,
    t: &[f64],
) -> Result<Vec<Keyframe>, MovingError> {
    let member = "temporalGeometry.coordinates";
    let e = ctx.array(coords, member)?;
    if e.len() != t.len() {
        return Err(ctx.err(
            times.at,
            member,
            ErrorKind::LengthMismatch,
            format!("{} polygons but {} date-times", e.len(), t.len()),
        ));
    }
    if e.len() < 2 {
        return Err(ctx.err(
            coords.at,
            member,
            ErrorKind::TooFewFixes,
            format!(
                "a MovingPolygon needs at least 2 instants, found {}",
                e.len()
            ),
        ));
    }
    let mut frames: Vec<Keyframe> = Vec::with_capacity(e.len());
    for (k, p) in e.iter().enumerate() {
        let m = format!("{member}[{k}]");
        let rings = polygon(ctx, p, &m)?;
        if let Some(first) = frames.first() {
            let shape = |r: &Rings| {
                std::iter::once(r.outer.len())
                    .chain(r.holes.iter().map(Vec::len))
                    .collect::<Vec<_>>()
            };
            let (a, b) = (shape(&first.parts[0]), shape(&rings));
            if a != b {
                return Err(ctx.err(
                    p.at,
                    &m,
                    ErrorKind::VertexCountChanges,
                    format!(
                        "instant {k} has rings of {b:?} vertices, instant 0 of {a:?} (the same at every instant)"
                    ),
                ));
            }
        }
        frames.push(Keyframe {
            t: t[k],
            parts: vec![rings],
        });
    }
    Ok(frames)
}

/// The unit factor to feet of an altitude's `form` (UCUM or UN/ECE Rec. 20 codes).
fn feet_per_unit(form: &str) -> Option<f64> {
    match form {
        "[ft_i]" | "FOT" | "ft" => Some(1.0),
        "m" | "MTR" => Some(1.0 / M_PER_FT),
        _ => None,
    }
}

/// The `altitude` temporal property (OGC 19-045r3 §7.2.2), when a group has one: its
/// values in feet (`null` or `NaN`: no altitude at that instant), at the very instants
/// of the positions.
fn altitude(
    ctx: &Ctx,
    tp: &Node,
    t: &[f64],
    warnings: &mut Vec<MovingWarning>,
) -> Result<Option<Vec<Option<f64>>>, MovingError> {
    let groups = ctx.array(tp, "temporalProperties")?;
    for (g, group) in groups.iter().enumerate() {
        let Some(alt) = group.get("altitude") else {
            continue;
        };
        let base = format!("temporalProperties[{g}]");
        let gt = group.get("datetimes").ok_or_else(|| {
            ctx.err(
                group.at,
                &format!("{base}.datetimes"),
                ErrorKind::Missing,
                "no datetimes",
            )
        })?;
        let (at, _) = datetimes(ctx, gt, &format!("{base}.datetimes"))?;
        if at != t {
            return Err(ctx.err(
                gt.at,
                &format!("{base}.datetimes"),
                ErrorKind::Unsupported,
                "the altitude must be given at the instants of the positions",
            ));
        }
        let am = format!("{base}.altitude");
        let factor = match alt.get("form") {
            Some(f) => {
                let form = f
                    .as_str()
                    .ok_or_else(|| ctx.wrong(f, &format!("{am}.form"), "a unit code"))?;
                feet_per_unit(form).ok_or_else(|| {
                    ctx.err(
                        f.at,
                        &format!("{am}.form"),
                        ErrorKind::Unsupported,
                        format!("unit {form:?}: feet are [ft_i], FOT or ft; metres m or MTR"),
                    )
                })?
            }
            None => {
                warnings.push(MovingWarning::new(
                    ctx.loc(alt.at, &am),
                    WarningKind::UnitAssumed,
                    "altitude without a form (unit) read as feet",
                ));
                1.0
            }
        };
        let values = alt.get("values").ok_or_else(|| {
            ctx.err(
                alt.at,
                &format!("{am}.values"),
                ErrorKind::Missing,
                "no values",
            )
        })?;
        let v = ctx.array(values, &format!("{am}.values"))?;
        if v.len() != t.len() {
            return Err(ctx.err(
                values.at,
                &format!("{am}.values"),
                ErrorKind::LengthMismatch,
                format!("{} values but {} date-times", v.len(), t.len()),
            ));
        }
        let mut out = Vec::with_capacity(v.len());
        for (k, x) in v.iter().enumerate() {
            out.push(match x.value {
                Json::Null | Json::NotJson("NaN") => None,
                _ => Some(ctx.number(x, &format!("{am}.values[{k}]"))? * factor),
            });
        }
        return Ok(Some(out));
    }
    Ok(None)
}
