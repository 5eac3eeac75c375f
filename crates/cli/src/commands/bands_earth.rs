//! `polyguard bands --earth [FILE]`: course bands in degrees true and speed bands in
//! knots for the aircraft of each encounter of docs/earth-cases.md, against its drifting
//! cell (`polyguard_earth::bands`; docs/earth-cases.md, "Bands").

use std::path::PathBuf;
use std::process::ExitCode;

use serde_json::{json, Map, Value};

use super::detect_earth::{
    earth_error, encounter_from_object, get, number, object, object_line, only_known, run_lines,
    LineError,
};
use polyguard_earth::bands::{course_bands, current, speed_bands, Band, Kind};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::EarthCase;

/// The fields of an encounter's `bands` object.
const BANDS_KEYS: [&str; 3] = ["unknown_max_deg", "speeds_kn", "unknown_max_kn"];

/// What one encounter asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EarthAsk {
    /// The unknown course total aimed at, degrees.
    pub unknown_max_deg: f64,
    /// Speed bands over [min, max] knots, when asked.
    pub speeds_kn: Option<[f64; 2]>,
    /// The unknown speed total aimed at, knots; `None`: the same share of the speed
    /// range as `unknown_max_deg` is of 360°.
    pub unknown_max_kn: Option<f64>,
}

/// The encounter's `bands` object (docs/earth-cases.md, "Bands"), strictly, over the
/// defaults `ask` (from the command line).
fn read_ask(obj: &Map<String, Value>, ask: EarthAsk) -> Result<EarthAsk, LineError> {
    let Some(b) = obj.get("bands") else {
        return Ok(ask);
    };
    let b = object(b, "bands")?;
    only_known(b, &BANDS_KEYS, "bands.")?;
    let mut out = ask;
    if b.contains_key("unknown_max_deg") {
        out.unknown_max_deg = number(
            get(b, "unknown_max_deg", "bands.unknown_max_deg")?,
            "bands.unknown_max_deg",
        )?;
    }
    if b.contains_key("unknown_max_kn") {
        out.unknown_max_kn = Some(number(
            get(b, "unknown_max_kn", "bands.unknown_max_kn")?,
            "bands.unknown_max_kn",
        )?);
    }
    if b.contains_key("speeds_kn") {
        let v = get(b, "speeds_kn", "bands.speeds_kn")?;
        let a = v
            .as_array()
            .filter(|a| a.len() == 2)
            .ok_or_else(|| LineError::new("bands.speeds_kn", "must be [min, max] in knots"))?;
        out.speeds_kn = Some([
            number(&a[0], "bands.speeds_kn[0]")?,
            number(&a[1], "bands.speeds_kn[1]")?,
        ]);
    }
    Ok(out)
}

/// The bands as JSON, the ends under `from_{unit}` and `to_{unit}`.
fn bands_json(bands: &[Band], unit: &str) -> Value {
    Value::Array(
        bands
            .iter()
            .map(|b| {
                let mut m = Map::new();
                m.insert(format!("from_{unit}"), b.lo.into());
                m.insert(format!("to_{unit}"), b.hi.into());
                m.insert("kind".into(), kind_name(b.kind).into());
                Value::Object(m)
            })
            .collect(),
    )
}

/// The answer's name of a band kind.
fn kind_name(k: Kind) -> &'static str {
    match k {
        Kind::Clear => "clear",
        Kind::Conflict => "conflict",
        Kind::Unknown => "unknown",
    }
}

/// Renames an engine error's field into the `bands` object where it belongs there.
fn in_bands(mut e: LineError) -> LineError {
    if e.field.starts_with("unknown_max") || e.field.starts_with("speeds_kn") {
        e.message = format!("bands.{}", e.message);
        e.field = format!("bands.{}", e.field);
    }
    e
}

/// The answer to one encounter (docs/earth-cases.md, "Bands").
pub fn answer(
    case: &EarthCase,
    ask: EarthAsk,
    geo: Geodesy,
) -> Result<Map<String, Value>, LineError> {
    let courses = course_bands(case, geo, ask.unknown_max_deg)
        .map_err(earth_error)
        .map_err(in_bands)?;
    let mut out = Map::new();
    out.insert(
        "course".into(),
        json!({
            "speed_kn": case.aircraft.speed_kn,
            "bands": bands_json(&courses.bands, "deg"),
            "unknown_total_deg": courses.unknown_total,
            "met": courses.met,
        }),
    );
    if let Some([lo, hi]) = ask.speeds_kn {
        let share = ask.unknown_max_deg / 360.0 * (hi - lo);
        let unknown_max = ask.unknown_max_kn.unwrap_or(if share > 0.0 {
            share
        } else {
            f64::MIN_POSITIVE
        });
        let s = speed_bands(case, geo, lo, hi, unknown_max)
            .map_err(earth_error)
            .map_err(in_bands)?;
        out.insert(
            "speed".into(),
            json!({
                "course_deg": case.aircraft.course_deg,
                "bands": bands_json(&s.bands, "kn"),
                "unknown_total_kn": s.unknown_total,
                "met": s.met,
            }),
        );
    }
    out.insert("current_course_deg".into(), case.aircraft.course_deg.into());
    let now = current(case, geo).map_err(earth_error)?;
    out.insert("current".into(), kind_name(now).into());
    out.insert("buff_nm".into(), case.buff_nm.into());
    out.insert("geodesy".into(), geo.name().into());
    Ok(out)
}

/// Answers one line of an encounter file: its id, and its fields or its error.
pub fn answer_line(
    text: &str,
    line_no: usize,
    ask: EarthAsk,
    geo: Geodesy,
) -> (Value, Result<Map<String, Value>, LineError>) {
    let (id, obj) = match object_line(text, line_no) {
        Ok(x) => x,
        Err((id, e)) => return (id, Err(e)),
    };
    let result = encounter_from_object(&obj)
        .and_then(|case| Ok((case, read_ask(&obj, ask)?)))
        .and_then(|(case, ask)| answer(&case, ask, geo));
    (id, result)
}

/// Runs `polyguard bands --earth`.
pub fn run(file: &Option<PathBuf>, ask: EarthAsk, geo: Geodesy) -> ExitCode {
    run_lines("bands", file, |t, n| answer_line(t, n, ask, geo))
}
