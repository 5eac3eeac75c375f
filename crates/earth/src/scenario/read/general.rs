//! The general path: any JSON read into a tree that knows where each value starts, every
//! member checked by name, every error with its line.

use super::errors::{file_err, Ctx, Problem, ScenarioError, ScenarioWarning, Warning};
use super::members::{judge, Level, Verdict};
use super::rules::{check_rings, checked, lay_out, ring_indexed, times_ok, track_from};
use super::Read;
use crate::json::{self, Json, Member, Node};
use crate::scenario::model::{normal_lon, Area, Feature, Kind, Longitudes, Shape};
use crate::sphere::LonLat;
use serde_json::{Map, Value};

/// The properties this format defines, and which kind each belongs to.
const AREA_PROPS: [&str; 4] = ["id", "kind", "t0", "tf"];
const TRACK_PROPS: [&str; 7] = [
    "id", "kind", "speed_kn", "front_nm", "back_nm", "side_nm", "t0",
];
const ALL_PROPS: [&str; 8] = [
    "id", "kind", "t0", "tf", "speed_kn", "front_nm", "back_nm", "side_nm",
];

/// The CRS names that mean RFC 7946's own (WGS 84 longitude, latitude in degrees).
const WGS84_NAMES: [&str; 4] = [
    "urn:ogc:def:crs:OGC:1.3:CRS84",
    "urn:ogc:def:crs:OGC::CRS84",
    "EPSG:4326",
    "urn:ogc:def:crs:EPSG::4326",
];

/// The reader of the general path: every member checked by name, every error with its
/// line.
struct Reader<'t> {
    lines: json::Lines,
    /// The collection's `longitudes`.
    longitudes: Longitudes,
    _text: std::marker::PhantomData<&'t str>,
}

impl Reader<'_> {
    /// The 1-based line of the byte offset `at`.
    fn line(&self, at: usize) -> Option<usize> {
        Some(self.lines.line(at))
    }

    /// An error of the feature `ctx` about `field`, on the line of the value at `node_at`.
    fn at(&self, ctx: &Ctx, node_at: usize, field: impl Into<String>, p: Problem) -> ScenarioError {
        let mut e = ctx.err(field, p);
        e.line = self.line(node_at);
        e
    }

    /// The first repeated key of an object, as an error for `prefix.key`.
    fn no_repeats(&self, ctx: &Ctx, members: &[Member], prefix: &str) -> Result<(), ScenarioError> {
        let mut seen = std::collections::HashSet::with_capacity(members.len());
        match members.iter().find(|m| !seen.insert(m.key.as_str())) {
            Some(m) => Err(self.at(ctx, m.at, join(prefix, &m.key), Problem::DuplicateKey)),
            None => Ok(()),
        }
    }

    /// The members of a GeoJSON object at `level` (`prefix` names it in fields): none
    /// given twice, none misplaced or misspelt ([`judge`]), and a warning for each foreign
    /// member (RFC 7946 §6.1), of the feature `index` (`None` for the collection).
    fn members(
        &self,
        ctx: &Ctx,
        index: Option<usize>,
        members: &[Member],
        (level, prefix): (Level, &str),
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<(), ScenarioError> {
        self.no_repeats(ctx, members, prefix)?;
        for m in members {
            let field = join(prefix, &m.key);
            match judge(level, &m.key, members) {
                Verdict::Defined => {}
                Verdict::Misplaced(place) => {
                    return Err(self.at(ctx, m.at, field, Problem::Misplaced(place)))
                }
                Verdict::Misspelt(name) => {
                    return Err(self.at(ctx, m.at, field, Problem::UnknownMember(Some(name))))
                }
                Verdict::Foreign => {
                    if let Json::NotJson(l) = m.value.value {
                        return Err(self.at(ctx, m.value.at, field, Problem::NotJsonNumber(l)));
                    }
                    warnings.push(ScenarioWarning {
                        line: self.lines.line(m.at),
                        index,
                        id: ctx.id.map(str::to_owned),
                        field,
                        what: Warning::Foreign,
                    });
                }
            }
        }
        Ok(())
    }

    /// A number property: finite, or absent (`null` too).
    fn number(
        &self,
        ctx: &Ctx,
        node: Option<&Node>,
        field: &str,
    ) -> Result<Option<f64>, ScenarioError> {
        match node.map(|n| (n.at, &n.value)) {
            None | Some((_, Json::Null)) => Ok(None),
            Some((_, Json::Number(x))) if x.is_finite() => Ok(Some(*x)),
            Some((at, Json::Number(_))) => Err(self.at(ctx, at, field, Problem::BadNumber)),
            Some((at, Json::NotJson(l))) => Err(self.at(ctx, at, field, Problem::NotJsonNumber(l))),
            Some((at, _)) => Err(self.at(ctx, at, field, Problem::WrongType("number"))),
        }
    }

    /// An array of positions `[lon, lat]` (`field` names it): each in range, laid out on
    /// the plane of the file's `longitudes` from `start` whole turns ([`lay_out`]; a
    /// `ring` must close without circling a pole); a warning for a longitude wrapped.
    fn positions(
        &self,
        ctx: &Ctx,
        node: &Node,
        field: &str,
        ring: bool,
        start: f64,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Vec<LonLat>, ScenarioError> {
        let arr = node.elements().ok_or_else(|| {
            self.at(
                ctx,
                node.at,
                field,
                Problem::WrongType("array of positions"),
            )
        })?;
        arr.iter()
            .enumerate()
            .map(|(k, p)| {
                let name = || format!("{field}[{k}]");
                let xy = p
                    .elements()
                    .filter(|a| a.len() >= 2)
                    .ok_or_else(|| self.at(ctx, p.at, name(), Problem::BadNumber))?;
                let mut c = [0.0; 2];
                for (j, n) in xy.iter().take(2).enumerate() {
                    c[j] = match n.value {
                        Json::Number(x) => x,
                        Json::NotJson(l) => {
                            return Err(self.at(ctx, n.at, name(), Problem::NotJsonNumber(l)))
                        }
                        _ => return Err(self.at(ctx, n.at, name(), Problem::BadNumber)),
                    };
                }
                checked(ctx, field, k, c[0], c[1])
                    .map(|q| (q, c))
                    .map_err(|mut e| {
                        e.line = self.line(p.at);
                        e
                    })
            })
            .collect::<Result<Vec<_>, _>>()
            .and_then(|read| {
                let raw: Vec<[f64; 2]> = read.iter().map(|&(_, c)| c).collect();
                let (laid, wrapped) = lay_out(ctx, field, &raw, self.longitudes, ring, start)
                    .map_err(|mut e| {
                        e.line = match e.problem {
                            Problem::CrossesAntimeridian(k) | Problem::HalfTurnStep(k) => {
                                self.line(arr[k].at)
                            }
                            _ => self.line(node.at),
                        };
                        e
                    })?;
                if let Some(k) = wrapped {
                    warnings.push(ScenarioWarning {
                        line: self.lines.line(arr[k].at),
                        index: Some(ctx.index),
                        id: ctx.id.map(str::to_owned),
                        field: format!("{field}[{k}]"),
                        what: Warning::Wrapped(raw[k][0], normal_lon(raw[k][0])),
                    });
                }
                Ok(laid
                    .into_iter()
                    .map(|[lon, lat]| LonLat::from_degrees(lon, lat))
                    .collect())
            })
    }

    /// One polygon of an area (`prefix` names its array of rings): its exterior ring and
    /// holes, each checked ([`ring_from`]), and the rules between them ([`check_rings`]).
    /// On the Earth each hole is laid out in the copy of its exterior ring (the one whose
    /// longitudes are nearest the ring's middle).
    fn shape(
        &self,
        ctx: &Ctx,
        node: &Node,
        prefix: &str,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Shape, ScenarioError> {
        let rings = node
            .elements()
            .ok_or_else(|| self.at(ctx, node.at, prefix, Problem::WrongType("array of rings")))?;
        let first = rings
            .first()
            .ok_or_else(|| self.at(ctx, node.at, format!("{prefix}[0]"), Problem::Missing))?;
        let at_ring = |n: &Node| Ctx {
            line: self.line(n.at),
            ..*ctx
        };
        let field = format!("{prefix}[0]");
        let ring = self.positions(ctx, first, &field, true, 0.0, warnings)?;
        let (ring, w0) = ring_indexed(&at_ring(first), ring, &field, false)?;
        let mut written = vec![w0];
        let mid = {
            let (lo, hi) = ring
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
                    (lo.min(q.lon), hi.max(q.lon))
                });
            (0.5 * (lo + hi)).to_degrees()
        };
        let mut holes = Vec::with_capacity(rings.len() - 1);
        for (k, h) in rings.iter().enumerate().skip(1) {
            let field = format!("{prefix}[{k}]");
            let mut read = Vec::new();
            let mut laid = self.positions(ctx, h, &field, true, 0.0, &mut read)?;
            if self.longitudes == Longitudes::Earth {
                if let Some(q) = laid.first() {
                    let turns = ((mid - q.lon.to_degrees()) / 360.0).round();
                    if turns != 0.0 {
                        laid = self.positions(ctx, h, &field, true, turns, &mut Vec::new())?;
                    }
                }
            }
            warnings.extend(read);
            let (hole, w) = ring_indexed(&at_ring(h), laid, &field, true)?;
            holes.push(hole);
            written.push(w);
        }
        check_rings(&ring, &holes, &written)
            .map_err(|(k, problem)| self.at(ctx, rings[k].at, format!("{prefix}[{k}]"), problem))?;
        Ok(Shape { ring, holes })
    }

    /// An area's geometry: a Polygon or a MultiPolygon (`true`), its coordinates.
    fn area_geometry<'n>(
        &self,
        ctx: &Ctx,
        f: &'n Node,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<(&'n Node, bool), ScenarioError> {
        let multi = f
            .get("geometry")
            .and_then(|g| g.get("type"))
            .and_then(|t| t.as_str())
            == Some("MultiPolygon");
        let ty = if multi { "MultiPolygon" } else { "Polygon" };
        match self.geometry(ctx, f, ty, warnings) {
            Ok(c) => Ok((c, multi)),
            Err(mut e) => {
                if e.problem == Problem::WrongType("Polygon") {
                    e.problem = Problem::WrongType("Polygon or MultiPolygon");
                }
                Err(e)
            }
        }
    }

    /// The geometry's coordinates, its members and type checked (a warning for each
    /// foreign member).
    fn geometry<'n>(
        &self,
        ctx: &Ctx,
        f: &'n Node,
        ty: &'static str,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<&'n Node, ScenarioError> {
        let g = f
            .get("geometry")
            .filter(|g| g.value != Json::Null)
            .ok_or_else(|| ctx.err("geometry", Problem::Missing))?;
        let members = g
            .members()
            .ok_or_else(|| self.at(ctx, g.at, "geometry", Problem::WrongType("an object")))?;
        let level = (Level::Geometry, "geometry");
        self.members(ctx, Some(ctx.index), members, level, warnings)?;
        if let Some(crs) = g.get("crs") {
            self.crs(ctx, crs, "geometry")?;
        }
        match g.get("type") {
            Some(t) if t.as_str() == Some(ty) => {}
            Some(t) => return Err(self.at(ctx, t.at, "geometry.type", Problem::WrongType(ty))),
            None => return Err(self.at(ctx, g.at, "geometry.type", Problem::Missing)),
        }
        g.get("coordinates")
            .ok_or_else(|| self.at(ctx, g.at, "geometry.coordinates", Problem::Missing))
    }

    /// One feature: its kind's rules, its properties checked by name.
    fn feature(
        &self,
        ctx: &Ctx,
        f: &Node,
        props: &[Member],
        kind: &str,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<(Kind, Map<String, Value>), ScenarioError> {
        let (own, this): (&[&str], &'static str) = match kind {
            "area" => (&AREA_PROPS, "an area"),
            "track" => (&TRACK_PROPS, "a track"),
            k => {
                let at = f
                    .get("properties")
                    .and_then(|p| p.get("kind"))
                    .map_or(f.at, |n| n.at);
                return Err(self.at(
                    ctx,
                    at,
                    "properties.kind",
                    Problem::UnknownKind(k.to_owned()),
                ));
            }
        };
        let (extra, kept) = self.open_properties(ctx, props, own, this)?;
        let kind = if kind == "area" {
            self.area(ctx, f, props, warnings)?
        } else {
            self.track(ctx, f, props, warnings)?
        };
        warnings.extend(kept);
        Ok((kind, extra))
    }

    /// The members of `properties` that the format does not define for this kind (`own`,
    /// `this` naming it), kept with a warning each: GeoJSON's properties are open. A
    /// defined property of the other kind (unless null), a misspelling of one of `own`,
    /// or a value that is not JSON is an error.
    fn open_properties(
        &self,
        ctx: &Ctx,
        props: &[Member],
        own: &[&'static str],
        this: &'static str,
    ) -> Result<(Map<String, Value>, Vec<ScenarioWarning>), ScenarioError> {
        let mut extra = Map::new();
        let mut kept = Vec::new();
        for m in props {
            let field = join("properties", &m.key);
            if own.contains(&m.key.as_str()) {
                continue;
            }
            if ALL_PROPS.contains(&m.key.as_str()) {
                // null is absent, as for the kind's own properties
                if m.value.value == Json::Null {
                    continue;
                }
                return Err(self.at(ctx, m.at, field, Problem::NotForKind(this)));
            }
            if let Some(s) = json::suggest(&m.key, own) {
                return Err(self.at(ctx, m.at, field, Problem::UnknownMember(Some(s))));
            }
            if let Json::NotJson(l) = m.value.value {
                return Err(self.at(ctx, m.value.at, field, Problem::NotJsonNumber(l)));
            }
            extra.insert(m.key.clone(), json::to_value(&m.value));
            kept.push(ScenarioWarning {
                line: self.lines.line(m.at),
                index: Some(ctx.index),
                id: ctx.id.map(str::to_owned),
                field,
                what: Warning::Kept,
            });
        }
        Ok((extra, kept))
    }

    /// An area (spec kind `area`): its Polygon or MultiPolygon, each polygon's rings
    /// ([`Reader::shape`]), and its times.
    fn area(
        &self,
        ctx: &Ctx,
        f: &Node,
        props: &[Member],
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Kind, ScenarioError> {
        let p = |k: &str| props.iter().find(|m| m.key == k).map(|m| &m.value);
        let t0 = self.number(ctx, p("t0"), "properties.t0")?;
        let (coords, multi) = self.area_geometry(ctx, f, warnings)?;
        let tf = self.number(ctx, p("tf"), "properties.tf")?;
        let polygons: Vec<(&Node, String)> = if multi {
            let parts = coords.elements().ok_or_else(|| {
                self.at(
                    ctx,
                    coords.at,
                    "geometry.coordinates",
                    Problem::WrongType("array of polygons"),
                )
            })?;
            if parts.is_empty() {
                return Err(self.at(ctx, coords.at, "geometry.coordinates[0]", Problem::Missing));
            }
            parts
                .iter()
                .enumerate()
                .map(|(k, n)| (n, format!("geometry.coordinates[{k}]")))
                .collect()
        } else {
            vec![(coords, "geometry.coordinates".to_owned())]
        };
        let mut shapes = Vec::with_capacity(polygons.len());
        for (node, prefix) in polygons {
            shapes.push(self.shape(ctx, node, &prefix, warnings)?);
        }
        times_ok(ctx, t0, tf).map_err(|mut e| {
            e.line = p("tf").and_then(|n| self.line(n.at));
            e
        })?;
        Ok(Kind::Area(Area {
            shapes,
            multi,
            t0,
            tf,
        }))
    }

    /// A track (spec kind `track`): its LineString's waypoints, speed and rectangle
    /// ([`track_from`]), each error on the line of the value it is about.
    fn track(
        &self,
        ctx: &Ctx,
        f: &Node,
        props: &[Member],
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<Kind, ScenarioError> {
        let p = |k: &str| props.iter().find(|m| m.key == k).map(|m| &m.value);
        let t0 = self.number(ctx, p("t0"), "properties.t0")?;
        let coords = self.geometry(ctx, f, "LineString", warnings)?;
        let waypoints =
            self.positions(ctx, coords, "geometry.coordinates", false, 0.0, warnings)?;
        let speed = self.number(ctx, p("speed_kn"), "properties.speed_kn")?;
        let dists = [
            self.number(ctx, p("front_nm"), "properties.front_nm")?,
            self.number(ctx, p("back_nm"), "properties.back_nm")?,
            self.number(ctx, p("side_nm"), "properties.side_nm")?,
        ];
        let track = track_from(ctx, waypoints, speed, dists, t0).map_err(|mut e| {
            // a value's own line when the error is about one property
            let key = e.field.strip_prefix("properties.").unwrap_or("");
            if let Some(n) = p(key) {
                e.line = self.line(n.at);
            } else if e.field == "geometry.coordinates" {
                e.line = self.line(coords.at);
            }
            e
        })?;
        Ok(Kind::Track(track))
    }
}

/// The JSON path of `key` in the object `prefix` names.
fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_owned()
    } else {
        format!("{prefix}.{key}")
    }
}

/// [`parse`](crate::scenario::parse)'s general path over a tree that knows where each
/// value starts: any JSON, every member checked by name (public for the differential fuzz
/// target).
pub fn parse_general(text: &str) -> Result<Read, ScenarioError> {
    let mut r = Reader {
        lines: json::Lines::new(text),
        longitudes: Longitudes::Earth,
        _text: std::marker::PhantomData,
    };
    let root = json::parse(text).map_err(|e| {
        let (line, col) = r.lines.line_col(e.at);
        file_err(
            Some(line),
            "(file)",
            Problem::Json(format!("{} at column {col}", e.message)),
        )
    })?;
    let mut out = Read::default();
    let feats = r.collection(&root, &mut out.warnings)?;
    out.scenario.longitudes = r.longitudes;
    let mut seen = std::collections::HashSet::new();
    for (index, f) in feats.iter().enumerate() {
        match r.read_feature(index, f, &mut seen) {
            Ok((feature, warnings)) => {
                out.scenario.features.push(feature);
                out.warnings.extend(warnings);
            }
            Err(e) => out.errors.push(e),
        }
    }
    Ok(out)
}

impl Reader<'_> {
    /// The FeatureCollection around the features (docs/scenario.md): its members (a
    /// warning for each foreign one), its `type`, a `crs` that names WGS 84, its
    /// `longitudes` (kept in `self`); its features. Every error here is fatal.
    fn collection<'n>(
        &mut self,
        root: &'n Node,
        warnings: &mut Vec<ScenarioWarning>,
    ) -> Result<&'n [Node], ScenarioError> {
        let top = Ctx {
            index: 0,
            id: None,
            line: self.line(root.at),
        };
        let fatal = |e: ScenarioError| ScenarioError {
            index: None,
            id: None,
            ..e
        };
        let members = root.members().ok_or_else(|| {
            file_err(
                self.line(root.at),
                "(file)",
                Problem::WrongType("a GeoJSON object"),
            )
        })?;
        self.members(&top, None, members, (Level::Collection, ""), warnings)
            .map_err(fatal)?;
        match root.get("type") {
            Some(t) if t.as_str() == Some("FeatureCollection") => {}
            Some(t) => {
                return Err(file_err(
                    self.line(t.at),
                    "type",
                    Problem::WrongType("FeatureCollection"),
                ))
            }
            None => return Err(file_err(self.line(root.at), "type", Problem::Missing)),
        }
        if let Some(crs) = root.get("crs") {
            self.crs(&top, crs, "").map_err(fatal)?;
        }
        if let Some(l) = root.get("longitudes") {
            self.longitudes = self.longitudes_member(l)?;
        }
        let feats = root
            .get("features")
            .ok_or_else(|| file_err(self.line(root.at), "features", Problem::Missing))?;
        feats.elements().ok_or_else(|| {
            file_err(
                self.line(feats.at),
                "features",
                Problem::WrongType("an array"),
            )
        })
    }

    /// A `crs` member of the object `prefix` names: it must name WGS 84
    /// longitude/latitude ([`WGS84_NAMES`]), or the positions would be misread.
    fn crs(&self, ctx: &Ctx, crs: &Node, prefix: &str) -> Result<(), ScenarioError> {
        let name = crs
            .get("properties")
            .and_then(|p| p.get("name"))
            .and_then(Node::as_str);
        match name {
            Some(n) if WGS84_NAMES.contains(&n) => Ok(()),
            Some(n) => Err(self.at(
                ctx,
                crs.at,
                join(prefix, "crs"),
                Problem::UnsupportedCrs(n.to_owned()),
            )),
            None => Err(self.at(
                ctx,
                crs.at,
                join(prefix, "crs.properties.name"),
                Problem::Missing,
            )),
        }
    }

    /// The collection's `longitudes`: `"earth"` or `"unrolled"`.
    fn longitudes_member(&self, l: &Node) -> Result<Longitudes, ScenarioError> {
        match l.as_str() {
            Some("earth") => Ok(Longitudes::Earth),
            Some("unrolled") => Ok(Longitudes::Unrolled),
            Some(v) => Err(file_err(
                self.line(l.at),
                "longitudes",
                Problem::UnknownLongitudes(v.to_owned()),
            )),
            None => Err(file_err(
                self.line(l.at),
                "longitudes",
                Problem::WrongType("a string, \"earth\" or \"unrolled\""),
            )),
        }
    }

    /// Feature `index` of the collection: a Feature object with `properties`, a string
    /// `properties.id` not used before (`seen` holds the ids read so far), a `kind`, and
    /// its kind's rules ([`Reader::feature`]); its warnings.
    fn read_feature(
        &self,
        index: usize,
        f: &Node,
        seen: &mut std::collections::HashSet<String>,
    ) -> Result<(Feature, Vec<ScenarioWarning>), ScenarioError> {
        let props_node = f.get("properties");
        let props = props_node.and_then(Node::members);
        let id_node = props.and_then(|p| p.iter().find(|m| m.key == "id"));
        let id = id_node.and_then(|m| m.value.as_str());
        let ctx = Ctx {
            index,
            id,
            line: self.line(f.at),
        };
        let members = f.members().ok_or_else(|| {
            self.at(
                &ctx,
                f.at,
                "(feature)",
                Problem::WrongType("a GeoJSON Feature object"),
            )
        })?;
        let mut warnings = Vec::new();
        self.members(
            &ctx,
            Some(index),
            members,
            (Level::Feature, ""),
            &mut warnings,
        )?;
        if let Some(crs) = f.get("crs") {
            self.crs(&ctx, crs, "")?;
        }
        match f.get("type") {
            Some(t) if t.as_str() == Some("Feature") => {}
            Some(t) => return Err(self.at(&ctx, t.at, "type", Problem::WrongType("Feature"))),
            None => return Err(self.at(&ctx, f.at, "type", Problem::Missing)),
        }
        let props_node = props_node
            .filter(|p| p.value != Json::Null)
            .ok_or_else(|| ctx.err("properties", Problem::Missing))?;
        let props = props.ok_or_else(|| {
            self.at(
                &ctx,
                props_node.at,
                "properties",
                Problem::WrongType("an object"),
            )
        })?;
        self.no_repeats(&ctx, props, "properties")?;
        let Some(id) = id else {
            return Err(match id_node {
                Some(m) => self.at(
                    &ctx,
                    m.value.at,
                    "properties.id",
                    Problem::WrongType("a string"),
                ),
                None => self.at(&ctx, props_node.at, "properties.id", Problem::Missing),
            });
        };
        if !seen.insert(id.to_owned()) {
            let at = id_node.map_or(f.at, |m| m.value.at);
            return Err(self.at(&ctx, at, "properties.id", Problem::DuplicateId));
        }
        let kind = match props_node.get("kind") {
            Some(k) => k.as_str().ok_or_else(|| {
                self.at(
                    &ctx,
                    k.at,
                    "properties.kind",
                    Problem::WrongType("a string"),
                )
            })?,
            None => return Err(self.at(&ctx, props_node.at, "properties.kind", Problem::Missing)),
        };
        let (kind, extra) = self.feature(&ctx, f, props, kind, &mut warnings)?;
        let feature = Feature {
            id: id.to_owned(),
            kind,
            extra,
        };
        Ok((feature, warnings))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::read::testkit::problem;
    use crate::scenario::read::{fast_parse, parse};
    use crate::scenario::testdata::{file, AREA, TRACK};

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

    /// `null` is absent everywhere, also for the other kind's properties, on both paths
    /// (the fast path read `"tf": null` on a track, the general one refused it; found by
    /// comparing the JSON Schema with the reader).
    #[test]
    fn null_is_absent_on_both_paths() {
        let track = TRACK.replace(r#""side_nm":1"#, r#""side_nm":1,"tf":null"#);
        let area = AREA.replace(r#""tf":2"#, r#""tf":2,"speed_kn":null"#);
        for text in [file(&[&track]), file(&[&area])] {
            let general = parse_general(&text).expect("collection");
            assert!(general.errors.is_empty(), "{:?}", general.errors);
            assert_eq!(fast_parse(&text), Some(general));
        }
    }

    /// File-level problems: the line, and a clear reason.
    #[test]
    fn file_level_errors_say_where() {
        let e = parse("{\"type\":\"FeatureCollection\",\n\"features\":[1,]}").expect_err("syntax");
        assert_eq!(e.line, Some(2));
        assert!(
            e.to_string()
                .starts_with("line 2: (file): not valid JSON: expected a value"),
            "{e}"
        );
        let e = parse("{\"type\":\"FeatureCollection\",\"feature\":[]}").expect_err("typo");
        assert_eq!(
            e.to_string(),
            "line 1: feature: unknown member; did you mean features?"
        );
        let mercator = "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\
            \"properties\":{\"name\":\"EPSG:3857\"}},\"features\":[]}";
        assert!(matches!(
            parse(mercator).expect_err("crs").problem,
            Problem::UnsupportedCrs(_)
        ));
        let crs84 = mercator.replace("EPSG:3857", "urn:ogc:def:crs:OGC:1.3:CRS84");
        assert!(parse(&crs84).is_ok());
        // a byte-order mark is not part of the text
        let bom = format!("\u{feff}{}", file(&[AREA]));
        let r = parse(&bom).expect("collection");
        assert_eq!(r.scenario.features.len(), 1);
        let bad_bom = format!("\u{feff}{}", file(&[AREA, "{\"type\":\"Feature\"}"]));
        let r = parse(&bad_bom).expect("collection");
        assert_eq!(r.errors[0].line, Some(3));
    }

    /// RFC 7946 §6.1: members another tool writes (`generator`, `title`, `style`…) on the
    /// collection, a feature or a geometry are read past: the scenario is the one without
    /// them, and each has a warning naming it and where it is (line, feature index and id,
    /// or the collection).
    #[test]
    fn foreign_members_are_read_past_with_a_warning_each() {
        let plain = file(&[AREA, TRACK]);
        let foreign = plain
            .replacen(
                "\"type\":\"FeatureCollection\",",
                "\"type\":\"FeatureCollection\",\"generator\":\"qgis\",\"metadata\":{\"v\":[1,2]},",
                1,
            )
            .replace(
                r#""type":"Feature","properties":{"id":"a""#,
                r#""type":"Feature","title":"storm","properties":{"id":"a""#,
            )
            .replace(
                r#""type":"LineString","#,
                r#""type":"LineString","style":{"stroke":"red"},"#,
            );
        let (a, b) = (parse(&plain), parse(&foreign));
        let (a, b) = (a.expect("a collection"), b.expect("a collection"));
        assert!(a.errors.is_empty() && b.errors.is_empty(), "{:?}", b.errors);
        assert_eq!(a.scenario, b.scenario);
        assert!(a.warnings.is_empty());
        let said: Vec<String> = b.warnings.iter().map(|w| w.to_string()).collect();
        let tail = ": a foreign member (defined by neither RFC 7946 nor the scenario format); \
                    not read";
        assert_eq!(
            said,
            [
                format!("line 1: the FeatureCollection, generator{tail}"),
                format!("line 1: the FeatureCollection, metadata{tail}"),
                format!("line 2: feature 0 (id \"a\"), title{tail}"),
                format!("line 3: feature 1 (id \"t\"), geometry.style{tail}"),
            ]
        );
        assert_eq!(b.warnings[0].index, None);
        assert_eq!(b.warnings[3].index, Some(1));
        assert!(b.warnings.iter().all(|w| w.what == Warning::Foreign));
    }

    /// What a foreign member may not be: a misspelling of a member the format reads that
    /// the object lacks, a member RFC 7946 §7.1 forbids there, a name the format defines
    /// on another object, a `crs` other than WGS 84 on a feature or a geometry. Each is an
    /// error naming the field; inside `properties`, a misspelling is one too.
    #[test]
    fn what_may_not_be_foreign_is_an_error() {
        let e = parse(&file(&[AREA]).replacen(
            "\"type\":\"FeatureCollection\",",
            "\"type\":\"FeatureCollection\",\"longitude\":\"unrolled\",",
            1,
        ))
        .expect_err("a file error");
        assert_eq!(
            e.to_string(),
            "line 1: longitude: unknown member; did you mean longitudes?"
        );
        for (bad, field, message) in [
            (
                AREA.replace(r#""geometry":{"#, r#""coordinates":[],"geometry":{"#),
                "coordinates",
                "it belongs in a geometry object (RFC 7946 §7.1)",
            ),
            (
                TRACK.replace(r#""geometry":{"#, r#""longitudes":"unrolled","geometry":{"#),
                "longitudes",
                "it belongs in the FeatureCollection (docs/scenario.md)",
            ),
            (
                TRACK.replace(r#""type":"LineString","#, r#""type":"LineString","kind":"track","#),
                "geometry.kind",
                "it belongs in a Feature's properties (docs/scenario.md)",
            ),
            (
                TRACK.replace(
                    r#""type":"LineString","#,
                    r#""type":"LineString","crs":{"type":"name","properties":{"name":"EPSG:3857"}},"#,
                ),
                "geometry.crs",
                "\"EPSG:3857\" is not WGS 84 longitude/latitude",
            ),
            (
                AREA.replace(r#""tf":2"#, r#""t_f":2"#),
                "properties.t_f",
                "unknown member; did you mean tf?",
            ),
        ] {
            let r = parse(&file(&[&bad])).expect("a collection");
            assert!(r.scenario.features.is_empty(), "{bad}");
            let e = &r.errors[0];
            assert_eq!(e.field, field, "{bad}");
            assert!(e.to_string().contains(message), "{e}");
        }
    }
}
