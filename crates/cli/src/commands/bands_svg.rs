//! `polyguard bands --svg FILE`: the compass-rose picture of one case's course bands
//! (docs/way-out.md, "The picture"), drawn by the harness's `wayout::picture`.

use std::path::Path;

use serde_json::Value;

use polyguard::bands::course_bands;
use polyguard::offset::offset;
use polyguard::recovery::{recovery_out, Recovery};
use polyguard::Vect2;
use polyguard_harness::wayout::answer::{band_case, Ask};
use polyguard_harness::wayout::case::{parse_way_line, WayCase};
use polyguard_harness::wayout::picture::{compass_svg, Compass};

/// The relative tolerance of the offsets drawn (a picture needs no finer).
const PICTURE_EPS: f64 = 0.01;

/// Does the line's id match the one asked for (a string id as written, any other id as
/// its JSON text)?
fn id_matches(id: &Value, want: &str) -> bool {
    match id {
        Value::String(s) => s == want,
        other => serde_json::to_string(other).is_ok_and(|text| text == want),
    }
}

/// The case to draw: the first valid one, or the one whose id is `want`.
fn pick(text: &str, want: Option<&str>) -> Result<(String, WayCase), String> {
    let lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    for (i, line) in lines {
        let parsed = parse_way_line(line, i + 1);
        if want.is_some_and(|w| !id_matches(&parsed.id, w)) {
            continue;
        }
        let title = match &parsed.id {
            Value::String(s) => s.clone(),
            other => other.to_string(),
        };
        match parsed.case {
            Ok(case) => return Ok((title, case)),
            Err(e) if want.is_some() => return Err(format!("line {}: {e}", i + 1)),
            Err(_) => {}
        }
    }
    Err(match want {
        Some(w) => format!("no case with id {w:?}"),
        None => "no valid case to draw".into(),
    })
}

/// The recovery point out of the nearest polygon's D-neighbourhood at t = 0, when the
/// point is within D of some polygon.
fn recovery(case: &WayCase, d: f64) -> Option<Vect2> {
    let mut best: Option<(f64, Vect2)> = None;
    for poly in &case.polygons {
        if let Ok(Recovery::Point {
            x,
            dist_hi,
            clear: false,
            ..
        }) = recovery_out(&poly.p, case.s, d)
        {
            if best.map_or(true, |(b, _)| dist_hi < b) {
                best = Some((dist_hi, x));
            }
        }
    }
    best.map(|(_, x)| x)
}

/// Draws the case `want` (or the first valid one) of `file` into `out`.
pub fn write(file: &Path, want: Option<&str>, ask: &Ask, out: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let (title, case) = pick(&text, want)?;
    let bc = band_case(&case, ask);
    let deg = case.bands.unknown_max_deg.unwrap_or(ask.unknown_max_deg);
    let speed = case.v.x.hypot(case.v.y);
    let bands = bc
        .with_traffic(|traffic| course_bands(traffic, speed, deg.to_radians()))
        .map_err(|e| e.to_string())?;
    let t = case.lookahead;
    let polygons: Vec<(Vec<Vect2>, Vec<Vect2>)> = case
        .polygons
        .iter()
        .map(|p| {
            let at_t = p.p.iter().zip(&p.vels).map(|(a, v)| a.at(*v, t)).collect();
            (p.p.clone(), at_t)
        })
        .collect();
    let d = bc.sep.d;
    let offsets: Vec<_> = if d > 0.0 {
        case.polygons
            .iter()
            .filter_map(|p| offset(&p.p, d, PICTURE_EPS).ok())
            .collect()
    } else {
        Vec::new()
    };
    let picture = Compass {
        title: &title,
        s: case.s,
        v: case.v,
        t,
        sep: d,
        polygons: &polygons,
        offsets: &offsets,
        bands: &bands,
        recovery: recovery(&case, d),
        units: "case units",
    };
    std::fs::write(out, compass_svg(&picture)).map_err(|e| format!("{}: {e}", out.display()))
}
