//! Reading one detection case from a JSON line (docs/cases.md).

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use polyguard::api::{Case, MovingPoint, MovingPolygon, Params};
use polyguard::error::CaseError;
use polyguard::vect2::Vect2;

/// One line of the case file: the id to echo back and the case (or what is wrong with it).
pub struct ParsedLine {
    /// The case's `id`, or the 1-based line number when it has none (or the line is not
    /// an object).
    pub id: Value,
    /// The engine's validated case, or the first thing wrong with the line.
    pub case: Result<Case, CaseError>,
    /// The line's separation and fence fields (their defaults when the line has none, or
    /// when it could not be read: then `case` says why).
    pub options: CaseOptions,
}

/// What kind of area the polygon is (the case format's `fence`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Fence {
    /// Keep out (the default): the question is whether the point comes in.
    #[default]
    KeepOut,
    /// Keep in: the question is whether the point leaves (breach_D, docs/cases.md).
    KeepIn,
}

impl Fence {
    /// The format's name: "keep_out" or "keep_in".
    pub fn name(self) -> &'static str {
        match self {
            Fence::KeepOut => "keep_out",
            Fence::KeepIn => "keep_in",
        }
    }

    /// The fence of a name ("keep_in", "keep_out"; the command line's "keep-in" too).
    pub fn from_name(name: &str) -> Option<Fence> {
        match name {
            "keep_out" | "keep-out" => Some(Fence::KeepOut),
            "keep_in" | "keep-in" => Some(Fence::KeepIn),
            _ => None,
        }
    }
}

/// The case format's optional fields for intervals and fences (docs/cases.md,
/// "Separation and fences"): the horizontal separation D (`sep`), the vertical
/// separation H (`sep_v`), and the fence kind. `None` where the line gives none, so that
/// a command-line default can apply.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CaseOptions {
    /// D ≥ 0, in the case's length unit.
    pub sep: Option<f64>,
    /// H ≥ 0, in the case's height unit (3D cases).
    pub sep_v: Option<f64>,
    /// `fence`, when given.
    pub fence: Option<Fence>,
}

/// A separation field: finite and ≥ 0 (the definitions of near_D and fence_D).
fn separation(v: &Value, field: &'static str) -> Result<f64, CaseError> {
    let x = number(v, field)?;
    if x >= 0.0 {
        Ok(x)
    } else {
        Err(CaseError::OutOfRange {
            field,
            value: x,
            range: "[0, ∞) (a distance)",
        })
    }
}

/// The case format's `sep`, `sep_v` and `fence` of a case object (docs/cases.md).
pub fn case_options(obj: &Map<String, Value>) -> Result<CaseOptions, CaseError> {
    let present = |k: &str| obj.get(k).filter(|v| !v.is_null());
    let sep = present("sep").map(|v| separation(v, "sep")).transpose()?;
    let sep_v = present("sep_v")
        .map(|v| separation(v, "sep_v"))
        .transpose()?;
    let fence = match present("fence") {
        None => None,
        Some(Value::String(s)) => Some(match s.as_str() {
            "keep_in" => Fence::KeepIn,
            "keep_out" => Fence::KeepOut,
            _ => {
                return Err(CaseError::WrongType {
                    field: "fence".into(),
                    expected: "\"keep_in\" or \"keep_out\"",
                })
            }
        }),
        Some(_) => {
            return Err(CaseError::WrongType {
                field: "fence".into(),
                expected: "\"keep_in\" or \"keep_out\"",
            })
        }
    };
    Ok(CaseOptions { sep, sep_v, fence })
}

/// The case format (not a paper function): a JSON value read strictly: an object that gives a key twice is an error naming the
/// key (serde_json alone keeps the last value, silently).
pub struct Strict(pub Value);

impl<'de> serde::Deserialize<'de> for Strict {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(StrictVisitor).map(Strict)
    }
}

struct StrictVisitor;

impl<'de> serde::de::Visitor<'de> for StrictVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, b: bool) -> Result<Value, E> {
        Ok(Value::Bool(b))
    }
    fn visit_i64<E>(self, x: i64) -> Result<Value, E> {
        Ok(Value::from(x))
    }
    fn visit_u64<E>(self, x: u64) -> Result<Value, E> {
        Ok(Value::from(x))
    }
    fn visit_f64<E>(self, x: f64) -> Result<Value, E> {
        Ok(Value::from(x))
    }
    fn visit_str<E>(self, s: &str) -> Result<Value, E> {
        Ok(Value::from(s))
    }
    fn visit_string<E>(self, s: String) -> Result<Value, E> {
        Ok(Value::String(s))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_some<D: serde::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        serde::Deserialize::deserialize(d).map(|Strict(v)| v)
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(Strict(v)) = seq.next_element()? {
            out.push(v);
        }
        Ok(Value::Array(out))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if out.contains_key(&key) {
                return Err(serde::de::Error::custom(format_args!(
                    "duplicate key `{key}`"
                )));
            }
            let Strict(v) = map.next_value()?;
            out.insert(key, v);
        }
        Ok(Value::Object(out))
    }
}

/// The case format (not a paper function): one non-blank line read strictly as a JSON
/// object, with the id to echo (the case's `id`, else the 1-based line number; kept from
/// a line with a NaN or a repeated key too). A byte-order mark in front is skipped.
pub fn read_case_object(
    line: &str,
    line_no: usize,
) -> (Value, Result<Map<String, Value>, CaseError>) {
    let line = line.strip_prefix('\u{feff}').unwrap_or(line);
    // the line ending is not part of the case (an error at the end says its column)
    let line = line.trim_end_matches(['\n', '\r']);
    let value: Value = match serde_json::from_str::<Strict>(line) {
        Ok(Strict(v)) => v,
        Err(e) => {
            // A line that is JSON but for a repeated key still gives its id back.
            let (error, lenient) = syntax_failure(line, &e);
            let id = lenient
                .as_ref()
                .and_then(|v| v.get("id").cloned())
                .filter(|v| !is_marked(v))
                .unwrap_or_else(|| Value::from(line_no));
            return (id, Err(error));
        }
    };
    let Value::Object(obj) = value else {
        return (
            Value::from(line_no),
            Err(CaseError::Syntax {
                message: "the line is JSON but not an object".into(),
            }),
        );
    };
    let id = obj
        .get("id")
        .cloned()
        .unwrap_or_else(|| Value::from(line_no));
    (id, Ok(obj))
}

/// Reads one non-blank line of the case format. A byte-order mark in front (the first
/// line of a file saved by some editors) is skipped.
pub fn parse_line(line: &str, line_no: usize) -> ParsedLine {
    parse_line_with(line, line_no, DEFAULT_KAPPA_DEG)
}

/// [`parse_line`] with the κ (degrees) that a case without `kappa` gets.
pub fn parse_line_with(line: &str, line_no: usize, default_kappa_deg: f64) -> ParsedLine {
    let (id, obj) = match read_case_object(line, line_no) {
        (id, Ok(obj)) => (id, obj),
        (id, Err(e)) => {
            return ParsedLine {
                id,
                case: Err(e),
                options: CaseOptions::default(),
            }
        }
    };
    let case = case_from_object_with(&obj, default_kappa_deg);
    let (case, options) = match (case, case_options(&obj)) {
        (Ok(c), Ok(o)) => (Ok(c), o),
        (Err(e), _) | (Ok(_), Err(e)) => (Err(e), CaseOptions::default()),
    };
    ParsedLine { id, case, options }
}

/// The case format (not a paper function): the error of a line that strict JSON reading
/// refused, and the line read leniently (NaN and ±Infinity as marked strings) when that
/// works, for its id.
fn syntax_failure(line: &str, e: &serde_json::Error) -> (CaseError, Option<Value>) {
    // serde_json places the error "at line 1 column C" of this one line: say "at column
    // C" (the file's line is in the answer).
    let text = e.to_string();
    let message = match text.find(" at line ") {
        Some(i) => format!("{} at column {}", &text[..i], e.column()),
        None => text,
    };
    // NaN and ±Infinity (which Python's json writes) are not JSON, and a number beyond
    // f64's range fails the whole parse: read them as marked strings to name their field.
    let lenient = serde_json::from_str::<Value>(&mark_unreadable_numbers(line)).ok();
    let marked = lenient
        .as_ref()
        .and_then(|v| first_marked(v, String::new()))
        .filter(|(field, _)| !field.is_empty());
    let error = match marked {
        Some((field, literal)) if NON_JSON_NUMBERS.contains(&literal.as_str()) => {
            CaseError::NotJsonNumber { field, literal }
        }
        // a JSON number whose nearest f64 is infinite (1e400)
        Some((field, _)) => CaseError::NotFinite { field },
        None => CaseError::Syntax { message },
    };
    (error, lenient)
}

/// The case format's point and polygon objects, one per line, for batch detection
/// (docs/batch.md; extends the case format of docs/cases.md): a line's JSON object read
/// strictly (no key twice), a byte-order mark in front skipped. `prefix` ("point." or
/// "polygon.") puts a NaN's field in the case's terms, as every other error of the line.
fn read_object(line: &str, prefix: &str) -> Result<Map<String, Value>, CaseError> {
    let line = line.strip_prefix('\u{feff}').unwrap_or(line);
    let line = line.trim_end_matches(['\n', '\r']);
    match serde_json::from_str::<Strict>(line) {
        Ok(Strict(Value::Object(obj))) => Ok(obj),
        Ok(Strict(_)) => Err(CaseError::Syntax {
            message: "the line is JSON but not an object".into(),
        }),
        Err(e) => Err(match syntax_failure(line, &e).0 {
            CaseError::NotJsonNumber { field, literal } => CaseError::NotJsonNumber {
                field: format!("{prefix}{field}"),
                literal,
            },
            CaseError::NotFinite { field } => CaseError::NotFinite {
                field: format!("{prefix}{field}"),
            },
            other => other,
        }),
    }
}

/// A batch's point line (docs/batch.md): the case format's `point` object, `pos` and
/// `vel` of two numbers each (three with a height), errors named `point.…` as in a case.
pub fn point_from_line(line: &str) -> Result<MovingPoint, CaseError> {
    let obj = read_object(line, "point.")?;
    let (pos, vel) = point_fields(&obj)?;
    moving_point(&pos, &vel)
}

/// A batch's polygon line (docs/batch.md): the case format's `polygon` object
/// (`vertices`, optional `velocities`, and `bottom`, `top`, `vz` for a slab), errors
/// named `polygon.…` as in a case.
pub fn polygon_from_line(line: &str) -> Result<MovingPolygon, CaseError> {
    let obj = read_object(line, "polygon.")?;
    let (vertices, velocities, slab) = polygon_fields(&obj)?;
    moving_polygon(&vertices, &velocities, slab)
}

/// The case format's `point` object: `pos` and `vel`, unvalidated but for `pos`'s length.
pub(crate) fn point_fields(point: &Map<String, Value>) -> Result<(Vec<f64>, Vec<f64>), CaseError> {
    only_known(point, &POINT_KEYS, "point.")?;
    let pos = numbers(get(point, "pos", "point.pos")?, "point.pos")?;
    let vel = numbers(get(point, "vel", "point.vel")?, "point.vel")?;
    if pos.len() != 2 && pos.len() != 3 {
        return Err(CaseError::PointLength { found: pos.len() });
    }
    Ok((pos, vel))
}

/// The fields of the case format's `polygon` object: vertices, velocities (empty when
/// absent), and the slab.
pub(crate) type PolygonFields = (Vec<[f64; 2]>, Vec<[f64; 2]>, Option<[f64; 3]>);

/// The case format's `polygon` object, unvalidated but for the lengths.
pub(crate) fn polygon_fields(poly: &Map<String, Value>) -> Result<PolygonFields, CaseError> {
    only_known(poly, &POLYGON_KEYS, "polygon.")?;
    let vertices = points(
        get(poly, "vertices", "polygon.vertices")?,
        "polygon.vertices",
    )?;
    let velocities = match poly.get("velocities") {
        None | Some(Value::Null) => vec![],
        Some(v) => {
            // given, it must have one per vertex: `[]` is not read as "at rest" (too few
            // vertices is the first thing wrong when it applies, as RawCase::to_api says)
            let vels = points(v, "polygon.velocities")?;
            if vels.len() != vertices.len() && vertices.len() >= 3 {
                return Err(CaseError::WrongLength {
                    field: "polygon.velocities".into(),
                    expected: vertices.len(),
                    found: vels.len(),
                    what: "velocities (one per vertex)",
                });
            }
            vels
        }
    };
    let slab_fields = ["bottom", "top", "vz"].map(|k| poly.get(k).filter(|v| !v.is_null()));
    let slab = match slab_fields {
        [None, None, None] => None,
        [Some(b), Some(t), Some(z)] => Some([
            number(b, "polygon.bottom")?,
            number(t, "polygon.top")?,
            number(z, "polygon.vz")?,
        ]),
        _ => {
            let missing = ["bottom", "top", "vz"]
                .iter()
                .zip(slab_fields.iter())
                .find(|(_, v)| v.is_none())
                .map(|(k, _)| *k)
                .unwrap_or("bottom");
            return Err(CaseError::Missing {
                field: format!("polygon.{missing}"),
            });
        }
    };
    Ok((vertices, velocities, slab))
}

/// The literals some writers put where JSON wants a number.
const NON_JSON_NUMBERS: [&str; 4] = ["-Infinity", "Infinity", "NaN", "+Infinity"];
/// A marked literal, as a string no JSON writer produces (a NUL character).
const MARK: char = '\u{0}';

/// `line` with every NaN/Infinity literal outside strings, and every JSON number whose
/// nearest f64 is infinite (`1e400`), turned into the string "\u0000NaN" (etc.), so that
/// a JSON reader can place it.
fn mark_unreadable_numbers(line: &str) -> String {
    let mut out = String::with_capacity(line.len() + 16);
    let mut in_string = false;
    let mut escaped = false;
    let mut rest = line;
    while let Some(c) = rest.chars().next() {
        if in_string {
            in_string = c != '"' || escaped;
            escaped = c == '\\' && !escaped;
        } else if c == '"' {
            in_string = true;
        } else if let Some(lit) = NON_JSON_NUMBERS.iter().find(|l| rest.starts_with(**l)) {
            out.push_str(&format!("\"\\u0000{lit}\""));
            rest = &rest[lit.len()..];
            continue;
        } else if c == '-' || c.is_ascii_digit() {
            // a number token: JSON's grammar has only these characters in one
            let len = rest
                .find(|d: char| !(d.is_ascii_digit() || "+-.eE".contains(d)))
                .unwrap_or(rest.len());
            let token = &rest[..len];
            if token.parse::<f64>().is_ok_and(f64::is_infinite) {
                out.push_str(&format!("\"\\u0000{token}\""));
            } else {
                out.push_str(token);
            }
            rest = &rest[len..];
            continue;
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

fn is_marked(v: &Value) -> bool {
    v.as_str().is_some_and(|s| s.starts_with(MARK))
}

/// The path and literal of the first marked value in `v` (depth first, keys in order).
fn first_marked(v: &Value, path: String) -> Option<(String, String)> {
    match v {
        Value::String(s) if is_marked(v) => Some((path, s.trim_start_matches(MARK).to_owned())),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(k, x)| first_marked(x, format!("{path}[{k}]"))),
        Value::Object(o) => o.iter().find_map(|(k, x)| {
            let p = if path.is_empty() {
                k.clone()
            } else {
                format!("{path}.{k}")
            };
            first_marked(x, p)
        }),
        _ => None,
    }
}

pub(crate) fn number(v: &Value, field: &str) -> Result<f64, CaseError> {
    match v.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        Some(_) => Err(CaseError::NotFinite {
            field: field.into(),
        }),
        None => Err(CaseError::WrongType {
            field: field.into(),
            expected: "a number",
        }),
    }
}

pub(crate) fn get<'a>(
    obj: &'a Map<String, Value>,
    key: &str,
    field: &str,
) -> Result<&'a Value, CaseError> {
    match obj.get(key) {
        Some(Value::Null) | None => Err(CaseError::Missing {
            field: field.into(),
        }),
        Some(v) => Ok(v),
    }
}

pub(crate) fn object<'a>(v: &'a Value, field: &str) -> Result<&'a Map<String, Value>, CaseError> {
    v.as_object().ok_or_else(|| CaseError::WrongType {
        field: field.into(),
        expected: "an object",
    })
}

pub(crate) fn array<'a>(v: &'a Value, field: &str) -> Result<&'a Vec<Value>, CaseError> {
    v.as_array().ok_or_else(|| CaseError::WrongType {
        field: field.into(),
        expected: "an array",
    })
}

pub(crate) fn numbers(v: &Value, field: &str) -> Result<Vec<f64>, CaseError> {
    array(v, field)?
        .iter()
        .enumerate()
        .map(|(k, x)| number(x, &format!("{field}[{k}]")))
        .collect()
}

pub(crate) fn points(v: &Value, field: &str) -> Result<Vec<[f64; 2]>, CaseError> {
    let arr = array(v, field)?;
    let mut out = Vec::with_capacity(arr.len());
    for (i, p) in arr.iter().enumerate() {
        let f = format!("{field}[{i}]");
        let xy = numbers(p, &f)?;
        if xy.len() != 2 {
            return Err(CaseError::WrongLength {
                field: f,
                expected: 2,
                found: xy.len(),
                what: "numbers (a point is [x, y])",
            });
        }
        out.push([xy[0], xy[1]]);
    }
    Ok(out)
}

/// The keys each level of a case line may have (docs: the case format). `meta` holds
/// annotations for people and tools (a kept counterexample's class, why a regression
/// case is there); detection never reads it.
pub(crate) const TOP_KEYS: [&str; 15] = [
    "id",
    "sep",
    "sep_v",
    "fence",
    "lookahead",
    "buff",
    "fac",
    "kappa",
    "point",
    "polygon",
    "meta",
    "polygons",
    "time",
    "bands",
    "eps",
];
const POINT_KEYS: [&str; 2] = ["pos", "vel"];
pub(crate) const POLYGON_KEYS: [&str; 5] = ["vertices", "velocities", "bottom", "top", "vz"];

/// The first key of `obj` that is not in `known`, as an error naming its path (`prefix`
/// is "" or "point." …) and the nearest known key when it is close: the same letters in
/// another case, or at most three edits away (and fewer than half its letters).
pub(crate) fn only_known(
    obj: &Map<String, Value>,
    known: &[&'static str],
    prefix: &str,
) -> Result<(), CaseError> {
    let Some(key) = obj.keys().find(|k| !known.contains(&k.as_str())) else {
        return Ok(());
    };
    let suggestion = polyguard_earth::json::suggest(key, known);
    Err(CaseError::UnknownField {
        field: format!("{prefix}{key}"),
        suggestion,
    })
}

/// Builds and validates a case from its JSON object, κ at the format's default when the
/// case gives none.
pub fn case_from_object(obj: &Map<String, Value>) -> Result<Case, CaseError> {
    case_from_object_with(obj, DEFAULT_KAPPA_DEG)
}

/// κ in degrees when neither the case nor the command line gives one (§II.J leaves it to
/// the user).
pub const DEFAULT_KAPPA_DEG: f64 = 5.0;

/// [`case_from_object`] with the κ (degrees) that a case without `kappa` gets.
pub fn case_from_object_with(
    obj: &Map<String, Value>,
    default_kappa_deg: f64,
) -> Result<Case, CaseError> {
    only_known(obj, &TOP_KEYS, "")?;
    if let Some(m) = obj.get("meta") {
        object(m, "meta")?;
    }
    let lookahead = number(get(obj, "lookahead", "lookahead")?, "lookahead")?;
    let buff = number(get(obj, "buff", "buff")?, "buff")?;
    let fac = match obj.get("fac") {
        None | Some(Value::Null) => Params::DEFAULT_FAC,
        Some(f) => number(f, "fac")?,
    };
    let kappa_deg = match obj.get("kappa") {
        None | Some(Value::Null) => default_kappa_deg,
        Some(k) => number(k, "kappa")?,
    };

    if obj.get("polygons").is_some_and(|v| !v.is_null()) {
        return Err(CaseError::WrongType {
            field: "polygons".into(),
            expected: "absent for detect: detect takes one polygon (`polygon`); \
                       `bands` takes several",
        });
    }
    let point = object(get(obj, "point", "point")?, "point")?;
    let (pos, vel) = point_fields(point)?;
    let poly = object(get(obj, "polygon", "polygon")?, "polygon")?;
    let (vertices, velocities, slab) = polygon_fields(poly)?;
    RawCase {
        lookahead,
        buff,
        fac,
        pos,
        vel,
        vertices,
        velocities,
        slab,
    }
    .to_api_with(kappa_deg)
}

/// The case format's point fields as the engine's validated point (2 or 3 numbers each).
pub(crate) fn moving_point(pos: &[f64], vel: &[f64]) -> Result<MovingPoint, CaseError> {
    match (pos, vel) {
        ([x, y], [vx, vy]) => MovingPoint::new_2d(Vect2::new(*x, *y), Vect2::new(*vx, *vy)),
        ([x, y, z], [vx, vy, vz]) => MovingPoint::new_3d([*x, *y, *z], [*vx, *vy, *vz]),
        _ => Err(CaseError::WrongLength {
            field: "point.vel".into(),
            expected: pos.len(),
            found: vel.len(),
            what: "numbers (as many as point.pos)",
        }),
    }
}

/// The case format's polygon fields as the engine's validated polygon (no velocities: at
/// rest).
pub(crate) fn moving_polygon(
    vertices: &[[f64; 2]],
    velocities: &[[f64; 2]],
    slab: Option<[f64; 3]>,
) -> Result<MovingPolygon, CaseError> {
    let velocities =
        (!velocities.is_empty()).then(|| velocities.iter().map(|&p| p.into()).collect());
    let poly = MovingPolygon::new(vertices.iter().map(|&p| p.into()).collect(), velocities)?;
    match slab {
        Some([b, t, z]) => poly.with_slab(b, t, z),
        None => Ok(poly),
    }
}

/// A case of docs/cases.md as its fields, unvalidated: the one case type of the I/O
/// layer. The reader fills it from a line ([`parse_line`]), the generators of the harness
/// draw it, [`RawCase::to_json_line`] writes it, and [`RawCase::to_api`] and
/// [`RawCase::exact`] make the engine's and the oracle's case of it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RawCase {
    /// T, the lookahead time.
    pub lookahead: f64,
    /// BUFF, the distance threshold.
    pub buff: f64,
    /// F, the fraction of BUFF for warping polygons.
    pub fac: f64,
    /// 2 numbers, or 3 with the height.
    pub pos: Vec<f64>,
    /// As many as `pos`.
    pub vel: Vec<f64>,
    /// The polygon, counterclockwise.
    pub vertices: Vec<[f64; 2]>,
    /// One velocity per vertex (empty: all still).
    pub velocities: Vec<[f64; 2]>,
    /// bottom, top, vz for a 3D case.
    pub slab: Option<[f64; 3]>,
}

impl RawCase {
    /// The engine's validated case, κ at the format's default ([`DEFAULT_KAPPA_DEG`]).
    pub fn to_api(&self) -> Result<Case, CaseError> {
        self.to_api_with(DEFAULT_KAPPA_DEG)
    }

    /// The engine's validated case with κ in degrees: the one path from the format's
    /// fields to a [`Case`], for case lines and generated cases alike.
    pub fn to_api_with(&self, kappa_deg: f64) -> Result<Case, CaseError> {
        let params = Params::new(self.buff)?
            .with_fac(self.fac)?
            .with_kappa_degrees(kappa_deg)?;
        let pt = moving_point(&self.pos, &self.vel)?;
        let poly = moving_polygon(&self.vertices, &self.velocities, self.slab)?;
        Case::new(self.lookahead, pt, poly, params)
    }

    /// The raw fields of a validated case.
    pub fn from_api(case: &Case) -> RawCase {
        let pt = case.point();
        let (pos, vel) = match pt.z {
            Some((sz, vz)) => (vec![pt.pos.x, pt.pos.y, sz], vec![pt.vel.x, pt.vel.y, vz]),
            None => (vec![pt.pos.x, pt.pos.y], vec![pt.vel.x, pt.vel.y]),
        };
        RawCase {
            lookahead: case.lookahead(),
            buff: case.params().buff(),
            fac: case.params().fac(),
            pos,
            vel,
            vertices: case
                .polygon()
                .vertices()
                .iter()
                .map(|&p| p.into())
                .collect(),
            velocities: case
                .polygon()
                .velocities()
                .iter()
                .map(|&p| p.into())
                .collect(),
            slab: case.polygon().slab().map(|s| [s.bottom, s.top, s.vz]),
        }
    }

    /// The oracle's exact case: the rationals these f64 denote.
    ///
    /// A case far from unit scale (its largest number beyond 2^±64) is handed to the
    /// oracle moved by a power of two to unit scale, when every number moves exactly.
    /// Lengths, heights and velocities move, T and F do not: every decision of paper A
    /// and of the truth compares quantities of one degree in length, so the answers and
    /// the first entry time are the same. The oracle's float filter then decides as it
    /// does at unit scale instead of failing on overflow or underflow, and its exact
    /// numbers stay short (at 2⁻¹⁰⁷⁰ a case took 60 ms with num-rational).
    pub fn exact<F: polyguard_oracle::ExactField>(
        &self,
    ) -> Result<polyguard_oracle::ExactCase<F>, polyguard_oracle::OracleError> {
        let unit = self.at_unit_scale();
        unit.as_ref().unwrap_or(self).exact_as_is()
    }

    /// The exact case of exactly these numbers, at whatever scale (see [`Self::exact`]).
    pub fn exact_as_is<F: polyguard_oracle::ExactField>(
        &self,
    ) -> Result<polyguard_oracle::ExactCase<F>, polyguard_oracle::OracleError> {
        polyguard_oracle::ExactCase::new(&polyguard_oracle::CaseInput {
            lookahead: self.lookahead,
            buff: self.buff,
            fac: self.fac,
            pos: &self.pos,
            vel: &self.vel,
            vertices: &self.vertices,
            velocities: &self.velocities,
            slab: self.slab,
        })
    }

    /// The case moved by 2^s to unit scale (its largest magnitude in [1, 2)), or `None`
    /// when it is near unit scale already (|s| ≤ 64) or some number would not move
    /// exactly (it would round, overflow or underflow).
    fn at_unit_scale(&self) -> Option<RawCase> {
        self.unit_scale_exponent().map(|s| self.times_pow2(s))
    }

    /// The exact case of [`Self::exact`] and the exact values of `lengths` (separations
    /// in the case's units) moved by the same power of two, so that they keep their
    /// meaning in the moved case. A length that would not move exactly is refused with
    /// the case (as `exact` refuses nothing: then the case is taken as it is).
    pub fn exact_with_lengths<F: polyguard_oracle::ExactField>(
        &self,
        lengths: &[f64],
    ) -> Result<(polyguard_oracle::ExactCase<F>, Vec<F>), polyguard_oracle::OracleError> {
        let s = self
            .unit_scale_exponent()
            .filter(|&s| {
                lengths.iter().all(|&x| {
                    let m = x * 2f64.powi(s / 2) * 2f64.powi(s - s / 2);
                    m * 2f64.powi(-s / 2) * 2f64.powi(-s - (-s / 2)) == x
                })
            })
            .unwrap_or(0);
        let moved = if s == 0 {
            self.clone()
        } else {
            self.times_pow2(s)
        };
        let case = moved.exact_as_is()?;
        let exact = lengths
            .iter()
            .map(|&x| {
                let m = x * 2f64.powi(s / 2) * 2f64.powi(s - s / 2);
                polyguard_oracle::convert::f64_to_exact::<F>(m).ok_or(
                    polyguard_oracle::OracleError {
                        field: "sep",
                        message: "not a finite number".into(),
                    },
                )
            })
            .collect::<Result<Vec<F>, _>>()?;
        Ok((case, exact))
    }

    /// The power of two 2^s that moves the case to unit scale (see
    /// [`Self::at_unit_scale`]).
    fn unit_scale_exponent(&self) -> Option<i32> {
        let mut all = self
            .pos
            .iter()
            .chain(&self.vel)
            .chain(self.vertices.iter().flatten())
            .chain(self.velocities.iter().flatten())
            .chain(self.slab.iter().flatten())
            .chain(std::iter::once(&self.buff));
        let largest = all.try_fold(0.0f64, |m, &x| x.is_finite().then(|| m.max(x.abs())))?;
        if largest == 0.0 {
            return None;
        }
        let s = -(largest.log2().floor() as i32);
        if s.abs() <= 64 {
            return None;
        }
        let c = self.times_pow2(s);
        // a round trip checks that every number moved exactly
        (c.times_pow2(-s) == *self).then_some(s)
    }

    /// The case with its lengths, heights and velocities multiplied by 2^s (T and F as
    /// they are), in two factors so that no factor under- or overflows; a number rounds
    /// only where the product does.
    pub fn times_pow2(&self, s: i32) -> RawCase {
        let by = |x: &mut f64| *x = *x * 2f64.powi(s / 2) * 2f64.powi(s - s / 2);
        let mut c = self.clone();
        by(&mut c.buff);
        c.pos.iter_mut().for_each(by);
        c.vel.iter_mut().for_each(by);
        c.vertices.iter_mut().flatten().for_each(by);
        c.velocities.iter_mut().flatten().for_each(by);
        c.slab.iter_mut().flatten().for_each(by);
        c
    }

    /// The same case with BUFF and F multiplied by k (the "wide band" of classify).
    pub fn widened(&self, k: f64) -> RawCase {
        RawCase {
            buff: self.buff * k,
            fac: (self.fac * k).min(0.5),
            ..self.clone()
        }
    }

    /// One line of the case format (shortest round-trip numbers), with an `id` and any
    /// annotations (a kept counterexample's class, …) in its `meta` object.
    pub fn to_json_line(&self, id: &str, extra: &[(&str, serde_json::Value)]) -> String {
        let mut point = serde_json::Map::new();
        point.insert("pos".into(), serde_json::json!(self.pos));
        point.insert("vel".into(), serde_json::json!(self.vel));
        let mut poly = serde_json::Map::new();
        poly.insert("vertices".into(), serde_json::json!(self.vertices));
        poly.insert("velocities".into(), serde_json::json!(self.velocities));
        if let Some([b, t, z]) = self.slab {
            poly.insert("bottom".into(), b.into());
            poly.insert("top".into(), t.into());
            poly.insert("vz".into(), z.into());
        }
        let mut obj = serde_json::Map::new();
        obj.insert("id".into(), id.into());
        obj.insert("lookahead".into(), self.lookahead.into());
        obj.insert("buff".into(), self.buff.into());
        obj.insert("fac".into(), self.fac.into());
        obj.insert("point".into(), serde_json::Value::Object(point));
        obj.insert("polygon".into(), serde_json::Value::Object(poly));
        if !extra.is_empty() {
            let meta: serde_json::Map<String, serde_json::Value> = extra
                .iter()
                .map(|(k, v)| ((*k).to_string(), v.clone()))
                .collect();
            obj.insert("meta".into(), serde_json::Value::Object(meta));
        }
        serde_json::Value::Object(obj).to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(line: &str) -> String {
        match parse_line(line, 7).case {
            Err(e) => e.to_string(),
            Ok(_) => String::from("ok"),
        }
    }

    /// Each (from, to, error): GOOD with `from` replaced by `to` gives that error.
    fn edits_give(cases: &[(&str, &str, &str)]) {
        for &(from, to, want) in cases {
            let line = GOOD.replacen(from, to, 1);
            assert_ne!(line, GOOD, "{from}");
            assert_eq!(err(&line), want, "{line}");
        }
    }

    const GOOD: &str = r#"{"id":"a","lookahead":10,"buff":0.01,"point":{"pos":[5,-3],"vel":[0,1]},"polygon":{"vertices":[[0,0],[2,0],[2,2],[0,2]],"velocities":[[1,0],[1,0],[1,0],[1,0]]}}"#;

    #[test]
    fn good_line_reads() {
        let p = parse_line(GOOD, 1);
        assert_eq!(p.id, Value::from("a"));
        let c = p.case.expect("valid");
        assert_eq!(c.lookahead(), 10.0);
        assert_eq!(c.params().fac(), Params::DEFAULT_FAC);
        assert!(c.polygon().statically_shaped());
    }

    #[test]
    fn each_bad_field_is_named() {
        assert_eq!(err("not json").split(':').next(), Some("line"));
        assert_eq!(err("[1,2]").split(':').next(), Some("line"));
        let cases = [
            (
                r#""lookahead":10,"#,
                r#""lookahead":-1,"#,
                "lookahead: -1 is not > 0",
            ),
            (r#""lookahead":10,"#, r#""#, "lookahead: missing"),
            (r#""buff":0.01,"#, r#""buff":0,"#, "buff: 0 is not > 0"),
            (
                r#""buff":0.01,"#,
                r#""buff":0.01,"fac":1.5,"#,
                "fac: 1.5 is outside (0, 1)",
            ),
            (
                r#""buff":0.01,"#,
                r#""buff":"x","#,
                "buff: must be a number",
            ),
            (
                r#""vel":[0,1]"#,
                r#""vel":[0,1,2]"#,
                "point.vel: 3 numbers (as many as point.pos), 2 expected",
            ),
            (
                r#"[[0,0],[2,0],[2,2],[0,2]]"#,
                r#"[[0,0],[2,0]]"#,
                "polygon.vertices: 2 points, at least 3 are needed",
            ),
            (
                r#"[[0,0],[2,0],[2,2],[0,2]]"#,
                r#"[[0,0],[2,0],[2,2,1],[0,2]]"#,
                "polygon.vertices[2]: 3 numbers (a point is [x, y]), 2 expected",
            ),
            (
                r#","velocities":[[1,0],[1,0],[1,0],[1,0]]"#,
                r#","velocities":[[1,0],[1,0]]"#,
                "polygon.velocities: 2 velocities (one per vertex), 4 expected",
            ),
            (
                r#""pos":[5,-3]"#,
                r#""pos":[5,-3,1]"#,
                "point.vel: 2 numbers (as many as point.pos), 3 expected",
            ),
        ];
        edits_give(&cases);
        // 3D point without a slab, slab without all three fields.
        let line3 = GOOD.replace(
            r#""pos":[5,-3],"vel":[0,1]"#,
            r#""pos":[5,-3,1],"vel":[0,1,0]"#,
        );
        assert!(err(&line3).starts_with("polygon.bottom: 2D and 3D mixed"));
        let partial = GOOD.replace(r#""velocities""#, r#""bottom":0,"top":5,"velocities""#);
        assert_eq!(err(&partial), "polygon.vz: missing");
        let slab2d = GOOD.replace(
            r#""velocities""#,
            r#""bottom":0,"top":5,"vz":0,"velocities""#,
        );
        assert!(err(&slab2d).starts_with("point.pos: 2D and 3D mixed"));
    }

    /// A JSON number too large for an f64 fails serde_json's whole parse ("number out of
    /// range", no field): the error names its field, nested ones too, and the id is kept.
    #[test]
    fn numbers_beyond_f64_name_their_field_and_keep_the_id() {
        let cases = [
            (r#""lookahead":10"#, r#""lookahead":1e400"#, "lookahead"),
            (r#""buff":0.01"#, r#""buff":-2.5E+309"#, "buff"),
            (r#""pos":[5,-3]"#, r#""pos":[5,-1e999]"#, "point.pos[1]"),
            (
                r#""vertices":[[0,0],[2,0]"#,
                r#""vertices":[[0,0],[2,1e400]"#,
                "polygon.vertices[1][1]",
            ),
            (
                r#""velocities":[[1,0],[1,0],[1,0]"#,
                r#""velocities":[[1,0],[1,0],[1e400,0]"#,
                "polygon.velocities[2][0]",
            ),
        ];
        for (from, to, field) in cases {
            let line = GOOD.replacen(from, to, 1);
            assert_ne!(line, GOOD, "{from}");
            let p = parse_line(&line, 3);
            assert_eq!(p.id, Value::from("a"), "{line}");
            assert_eq!(
                p.case.err().map(|e| e.to_string()),
                Some(format!("{field}: not a finite number")),
                "{line}"
            );
        }
        // a huge number inside a string is text; one that underflows reads as 0
        let named = GOOD.replace(r#""id":"a""#, r#""id":"1e400""#);
        assert_eq!(parse_line(&named, 3).id, Value::from("1e400"));
        assert_eq!(err(&named), "ok");
        let tiny = GOOD.replace("[5,-3]", "[5,-1e-400]");
        assert_eq!(err(&tiny), "ok");
        // a batch's point line names the field in the case's terms
        let e = point_from_line(r#"{"pos":[1e400,0],"vel":[0,0]}"#).err();
        assert_eq!(
            e.map(|e| e.to_string()),
            Some("point.pos[0]: not a finite number".into())
        );
        // a line that is a bare number is not an object: no field to name
        assert!(
            err("1e400").starts_with("line: not a JSON object"),
            "{}",
            err("1e400")
        );
    }

    /// A typo must never turn a hit into a miss: the misspelt `velocity` was read as a
    /// polygon at rest. Every unknown key, at every level, is an error naming its path,
    /// with the nearest known name when one is close.
    #[test]
    fn unknown_fields_are_errors() {
        let cases = [
            (
                r#""velocities""#,
                r#""velocity""#,
                "polygon.velocity: unknown field; did you mean velocities?",
            ),
            (
                r#""lookahead""#,
                r#""look_ahead""#,
                "look_ahead: unknown field; did you mean lookahead?",
            ),
            (
                r#""vel""#,
                r#""velo""#,
                "point.velo: unknown field; did you mean vel?",
            ),
            (
                r#""buff":0.01,"#,
                r#""buff":0.01,"colour":"red","#,
                "colour: unknown field",
            ),
            (
                r#""vertices""#,
                r#""Vertices""#,
                "polygon.Vertices: unknown field; did you mean vertices?",
            ),
        ];
        edits_give(&cases);
        // Annotations for people and tools go in `meta`, which detection never reads.
        let meta = GOOD.replace(
            r#""id":"a","#,
            r#""id":"a","meta":{"class":"agree","why":"x"},"#,
        );
        assert_eq!(err(&meta), "ok");
        let bad_meta = GOOD.replace(r#""id":"a","#, r#""id":"a","meta":3,"#);
        assert_eq!(err(&bad_meta), "meta: must be an object");
    }

    /// A key given twice would silently keep its last value: an error naming the key.
    /// A byte-order mark before the first line is not part of the case.
    #[test]
    fn duplicate_keys_are_errors_and_a_bom_is_skipped() {
        let twice = GOOD.replace(r#""buff":0.01,"#, r#""buff":0.01,"buff":5,"#);
        assert!(
            err(&twice).starts_with("line: not a JSON object: duplicate key `buff`"),
            "{}",
            err(&twice)
        );
        let nested = GOOD.replace(r#""vel":[0,1]"#, r#""vel":[0,1],"vel":[1,0]"#);
        assert!(
            err(&nested).contains("duplicate key `vel`"),
            "{}",
            err(&nested)
        );
        let bom = format!("\u{feff}{GOOD}");
        assert_eq!(err(&bom), "ok");
        assert_eq!(parse_line(&bom, 1).id, Value::from("a"));
    }

    /// Python's json writes NaN and Infinity, which JSON lacks: the error names the field
    /// and the id is kept (it said "expected value at line 1 column 64" and lost both).
    #[test]
    fn non_json_numbers_name_their_field_and_keep_the_id() {
        for (lit, field) in [("NaN", "point.pos[0]"), ("-Infinity", "point.pos[0]")] {
            let line = GOOD.replace(r#""pos":[5,-3]"#, &format!(r#""pos":[{lit},-3]"#));
            let p = parse_line(&line, 3);
            assert_eq!(p.id, Value::from("a"));
            assert_eq!(
                p.case.err().map(|e| e.to_string()),
                Some(format!(
                    "{field}: {lit} is not a JSON number; a case needs finite numbers"
                ))
            );
        }
        // inside a string it is text, not a number
        let named = GOOD.replace(r#""id":"a""#, r#""id":"NaN run""#);
        assert_eq!(parse_line(&named, 3).id, Value::from("NaN run"));
        assert_eq!(err(&named), "ok");
    }

    /// A point of one number: 2 or 3 are allowed, and the message says both.
    #[test]
    fn a_point_of_one_number_says_two_or_three() {
        let line = GOOD.replace(r#""pos":[5,-3]"#, r#""pos":[5]"#);
        assert_eq!(
            err(&line),
            "point.pos: 1 number, 2 (x, y) or 3 (x, y, z) expected"
        );
    }

    /// κ per case, in degrees, in (0, 180).
    #[test]
    fn kappa_is_read_in_degrees() {
        let with =
            |k: &str| GOOD.replace(r#""buff":0.01,"#, &format!(r#""buff":0.01,"kappa":{k},"#));
        let c = parse_line(&with("30"), 1).case.expect("valid");
        assert_eq!(c.params().kappa(), 30f64.to_radians());
        assert_eq!(err(&with("180")), "kappa: 180 is outside (0, 180) degrees");
        assert_eq!(err(&with("0")), "kappa: 0 is outside (0, 180) degrees");
        let d = parse_line(GOOD, 1).case.expect("valid");
        assert_eq!(d.params().kappa(), Params::DEFAULT_KAPPA);
        let e = parse_line_with(GOOD, 1, 12.5).case.expect("valid");
        assert_eq!(e.params().kappa(), 12.5f64.to_radians());
    }

    /// A bow tie is its own error naming the crossing edges, not "clockwise".
    #[test]
    fn a_bow_tie_names_its_edges() {
        let line = GOOD.replace("[[0,0],[2,0],[2,2],[0,2]]", "[[0,0],[2,0],[0,2],[2,2]]");
        assert_eq!(
            err(&line),
            "polygon.vertices: edges 1–2 and 3–0 cross (vertices numbered from 0); \
             the polygon must not intersect itself"
        );
        let cw = GOOD.replace("[[0,0],[2,0],[2,2],[0,2]]", "[[0,0],[0,2],[2,2],[2,0]]");
        assert!(err(&cw).starts_with("polygon.vertices: clockwise order"));
    }

    #[test]
    fn missing_id_uses_line_number() {
        let line = GOOD.replace(r#""id":"a","#, "");
        assert_eq!(parse_line(&line, 7).id, Value::from(7));
    }
}

#[cfg(test)]
mod raw_case_tests {
    use super::*;

    #[test]
    fn json_round_trip_is_bit_exact() {
        let raw = RawCase {
            lookahead: 300.0,
            buff: 0.1 + 0.2,
            fac: 1e-4,
            pos: vec![1.0 / 3.0, -2.5e-300, 7.0],
            vel: vec![0.1, f64::MIN_POSITIVE, -1.0],
            vertices: vec![[0.0, 0.0], [1e7 + 0.1, 0.0], [0.5, 1.0]],
            velocities: vec![[0.0, 0.0]; 3],
            slab: Some([0.0, 10.0, -0.25]),
        };
        let line = raw.to_json_line("x", &[]);
        let back = parse_line(&line, 1).case.expect("valid");
        assert_eq!(RawCase::from_api(&back), raw);
    }
}
