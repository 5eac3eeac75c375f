//! `polyguard detect-earth [FILE]`: paper A's detection on lon/lat input, one JSON line
//! per encounter (docs/earth-cases.md), answered by `polyguard_earth::paper_a`.

use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use serde_json::{json, Map, Value};

use crate::commands::conflicts::GeodesyArg;
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::{detect_earth, EarthCase, Motion};
use polyguard_harness::case::Strict;

/// Arguments of `polyguard detect-earth`.
#[derive(Debug, clap::Args)]
pub struct DetectEarthArgs {
    /// The encounter file (JSON Lines, docs/earth-cases.md); standard input when absent
    /// or "-".
    pub file: Option<PathBuf>,
    /// The model of the Earth: `sphere` (radius 3440.065 nm, the default; BUFF is a
    /// great-circle distance) or `wgs84` (motion, Mercator and BUFF on the ellipsoid).
    #[arg(long, value_enum, default_value_t = GeodesyArg::Sphere)]
    pub geodesy: GeodesyArg,
}

/// A line that cannot be answered: the field (a path such as `cell.vertices[2][1]`, or
/// `line` for the line as a whole) and what is wrong.
#[derive(Clone, Debug, PartialEq)]
pub struct LineError {
    /// The field.
    pub field: String,
    /// The message, which starts with the field.
    pub message: String,
}

impl LineError {
    pub(crate) fn new(field: impl Into<String>, what: impl std::fmt::Display) -> Self {
        let field = field.into();
        LineError {
            message: format!("{field}: {what}"),
            field,
        }
    }
}

/// The top-level fields; `bands` is read by `polyguard bands --earth` (crate
/// `commands::bands_earth`) and ignored here.
const TOP_KEYS: [&str; 7] = [
    "id",
    "lookahead_h",
    "buff_nm",
    "aircraft",
    "cell",
    "bands",
    "meta",
];
const AIRCRAFT_KEYS: [&str; 3] = ["pos", "course_deg", "speed_kn"];
const CELL_KEYS: [&str; 3] = ["vertices", "course_deg", "speed_kn"];

/// The first key of `obj` not in `known`, as an error naming its path and the nearest
/// known name (as the case format does: docs/cases.md).
pub(crate) fn only_known(
    obj: &Map<String, Value>,
    known: &[&'static str],
    prefix: &str,
) -> Result<(), LineError> {
    match obj.keys().find(|k| !known.contains(&k.as_str())) {
        None => Ok(()),
        Some(key) => {
            let hint = polyguard_earth::json::suggest(key, known)
                .map(|s| format!("; did you mean {s}?"))
                .unwrap_or_default();
            Err(LineError::new(
                format!("{prefix}{key}"),
                format!("unknown field{hint}"),
            ))
        }
    }
}

pub(crate) fn get<'a>(
    obj: &'a Map<String, Value>,
    key: &str,
    field: &str,
) -> Result<&'a Value, LineError> {
    match obj.get(key) {
        None | Some(Value::Null) => Err(LineError::new(field, "missing")),
        Some(v) => Ok(v),
    }
}

pub(crate) fn number(v: &Value, field: &str) -> Result<f64, LineError> {
    v.as_f64()
        .ok_or_else(|| LineError::new(field, "must be a number"))
}

pub(crate) fn object<'a>(v: &'a Value, field: &str) -> Result<&'a Map<String, Value>, LineError> {
    v.as_object()
        .ok_or_else(|| LineError::new(field, "must be an object"))
}

fn lon_lat(v: &Value, field: &str) -> Result<[f64; 2], LineError> {
    let a = v
        .as_array()
        .ok_or_else(|| LineError::new(field, "must be an array [longitude, latitude]"))?;
    if a.len() != 2 {
        return Err(LineError::new(
            field,
            format!(
                "{} numbers, 2 expected ([longitude, latitude] in degrees)",
                a.len()
            ),
        ));
    }
    Ok([
        number(&a[0], &format!("{field}[0]"))?,
        number(&a[1], &format!("{field}[1]"))?,
    ])
}

fn motion(obj: &Map<String, Value>, prefix: &str) -> Result<Motion, LineError> {
    let f = |k: &str| format!("{prefix}.{k}");
    Ok(Motion {
        course_deg: number(get(obj, "course_deg", &f("course_deg"))?, &f("course_deg"))?,
        speed_kn: number(get(obj, "speed_kn", &f("speed_kn"))?, &f("speed_kn"))?,
    })
}

/// Reads one encounter object (docs/earth-cases.md) strictly: every field of the format,
/// no other (a misspelt field is an error, never read as absent).
pub fn encounter_from_object(obj: &Map<String, Value>) -> Result<EarthCase, LineError> {
    only_known(obj, &TOP_KEYS, "")?;
    if let Some(m) = obj.get("meta") {
        object(m, "meta")?;
    }
    let lookahead_h = number(get(obj, "lookahead_h", "lookahead_h")?, "lookahead_h")?;
    let buff_nm = number(get(obj, "buff_nm", "buff_nm")?, "buff_nm")?;
    let air = object(get(obj, "aircraft", "aircraft")?, "aircraft")?;
    only_known(air, &AIRCRAFT_KEYS, "aircraft.")?;
    let aircraft_pos = lon_lat(get(air, "pos", "aircraft.pos")?, "aircraft.pos")?;
    let aircraft = motion(air, "aircraft")?;
    let cell = object(get(obj, "cell", "cell")?, "cell")?;
    only_known(cell, &CELL_KEYS, "cell.")?;
    let verts = get(cell, "vertices", "cell.vertices")?
        .as_array()
        .ok_or_else(|| {
            LineError::new("cell.vertices", "must be an array of [longitude, latitude]")
        })?;
    let cell_vertices = verts
        .iter()
        .enumerate()
        .map(|(i, v)| lon_lat(v, &format!("cell.vertices[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(EarthCase {
        lookahead_h,
        buff_nm,
        aircraft_pos,
        aircraft,
        cell_vertices,
        cell: motion(cell, "cell")?,
    })
}

/// One line read as a JSON object (a leading BOM and the line end dropped), with its
/// id: the line's `id`, or the line number when it has none or cannot be read.
pub(crate) fn object_line(
    text: &str,
    line_no: usize,
) -> Result<(Value, Map<String, Value>), (Value, LineError)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let text = text.trim_end_matches(['\n', '\r']);
    let value = match serde_json::from_str::<Strict>(text) {
        Ok(Strict(v)) => v,
        Err(e) => {
            let msg = e.to_string();
            let msg = match msg.find(" at line ") {
                Some(i) => format!("{} at column {}", &msg[..i], e.column()),
                None => msg,
            };
            return Err((
                Value::from(line_no),
                LineError::new("line", format!("not a JSON object: {msg}")),
            ));
        }
    };
    let Value::Object(obj) = value else {
        return Err((
            Value::from(line_no),
            LineError::new("line", "the line is JSON but not an object"),
        ));
    };
    let id = obj
        .get("id")
        .cloned()
        .unwrap_or_else(|| Value::from(line_no));
    Ok((id, obj))
}

/// An engine error as a line error (its field and message).
pub(crate) fn earth_error(e: polyguard_earth::paper_a::EarthError) -> LineError {
    LineError {
        message: e.to_string(),
        field: e.field.clone(),
    }
}

/// Answers one line: the fields after `id`, or the error. The id is the line's `id`, or
/// the line number when it has none or cannot be read.
pub fn answer_line(
    text: &str,
    line_no: usize,
    geo: Geodesy,
) -> (Value, Result<Map<String, Value>, LineError>) {
    let (id, obj) = match object_line(text, line_no) {
        Ok(x) => x,
        Err((id, e)) => return (id, Err(e)),
    };
    let result = encounter_from_object(&obj).and_then(|case| {
        let a = detect_earth(&case, geo).map_err(earth_error)?;
        let mut out = Map::new();
        out.insert("detected".into(), a.detected.into());
        out.insert("kind".into(), a.kind.name().into());
        if let Some(w) = a.alarm_window_h {
            out.insert("alarm_window_h".into(), json!(w));
        }
        out.insert("separation_windows_h".into(), json!(a.separation_windows_h));
        out.insert("pieces".into(), a.pieces.into());
        out.insert("effective_buff_nm".into(), a.effective_buff_nm.into());
        out.insert("geodesy".into(), geo.name().into());
        Ok(out)
    });
    (id, result)
}

/// Streams encounters from `reader` to `out`; returns the number of lines that failed.
pub fn process<R: BufRead, W: Write>(reader: R, out: &mut W, geo: Geodesy) -> io::Result<u64> {
    process_with(reader, out, |t, n| answer_line(t, n, geo))
}

/// Streams lines from `reader` to `out`, each answered by `answer` (its id, and its
/// fields or its error); blank lines are skipped. Returns the number of lines that
/// failed.
pub(crate) fn process_with<R: BufRead, W: Write>(
    mut reader: R,
    out: &mut W,
    mut answer: impl FnMut(&str, usize) -> (Value, Result<Map<String, Value>, LineError>),
) -> io::Result<u64> {
    let mut buf = Vec::new();
    let (mut line_no, mut failed) = (0usize, 0u64);
    loop {
        buf.clear();
        if reader.read_until(b'\n', &mut buf)? == 0 {
            break;
        }
        line_no += 1;
        let (id, result) = match std::str::from_utf8(&buf) {
            Ok(t) if t.trim().is_empty() => continue,
            Ok(t) => answer(t, line_no),
            Err(_) => (
                Value::from(line_no),
                Err(LineError::new("line", "not UTF-8")),
            ),
        };
        let mut obj = Map::new();
        obj.insert("id".into(), id);
        match result {
            Ok(fields) => obj.extend(fields),
            Err(e) => {
                failed += 1;
                obj.insert("line".into(), line_no.into());
                obj.insert("field".into(), e.field.into());
                obj.insert("error".into(), e.message.into());
            }
        }
        writeln!(out, "{}", Value::Object(obj))?;
    }
    Ok(failed)
}

/// Runs `polyguard detect-earth`: one answer line per non-blank input line, in order;
/// exit 0, 1 when some line could not be answered, 2 when the input cannot be read.
pub fn run(args: &DetectEarthArgs) -> ExitCode {
    let geo: Geodesy = args.geodesy.into();
    run_lines("detect-earth", &args.file, |t, n| answer_line(t, n, geo))
}

/// Runs a command that answers the encounter file `file` (standard input when absent or
/// "-") line by line with `answer`: exit 0, 1 when some line could not be answered, 2
/// when the input cannot be read.
pub(crate) fn run_lines(
    cmd: &str,
    file: &Option<PathBuf>,
    answer: impl FnMut(&str, usize) -> (Value, Result<Map<String, Value>, LineError>),
) -> ExitCode {
    let name = file
        .as_ref()
        .map_or_else(|| "standard input".into(), |p| p.display().to_string());
    let reader: Box<dyn BufRead> = match file {
        Some(p) if p.is_dir() => {
            eprintln!("polyguard {cmd}: cannot read {name}: is a directory");
            return ExitCode::from(2);
        }
        Some(p) if p.as_os_str() != "-" => match File::open(p) {
            Ok(f) => Box::new(BufReader::new(f)),
            Err(e) => {
                eprintln!("polyguard {cmd}: cannot read {name}: {e}");
                return ExitCode::from(2);
            }
        },
        _ => Box::new(BufReader::new(io::stdin().lock())),
    };
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    match process_with(reader, &mut out, answer).and_then(|f| out.flush().map(|()| f)) {
        Ok(0) => ExitCode::SUCCESS,
        Ok(failed) => {
            eprintln!("polyguard {cmd}: {failed} line(s) could not be answered");
            ExitCode::from(1)
        }
        Err(e) => {
            eprintln!("polyguard {cmd}: reading {name}: {e}");
            ExitCode::from(2)
        }
    }
}
