//! Paper B Algorithm 1 on a scenario GeoJSON (docs/scenario.md): the conflicts answer of
//! that spec, and an SVG drawing of the scenario and its conflicts.

use crate::conflict::{pipeline, stage4::Method, Object};
use crate::geodesy::Geodesy;
use crate::scenario::{self, Scenario, ScenarioError, ScenarioWarning};
use crate::sphere::Merc;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::time::Instant;

/// Told when the four stages start and end, which can take long on large scenarios; the
/// command-line tool draws a spinner. `()` ignores both.
pub trait Progress {
    /// The four stages start over `objects` objects.
    fn stages_start(&mut self, objects: usize) {
        let _ = objects;
    }
    /// The four stages are done.
    fn stages_end(&mut self) {}
}

impl Progress for () {}

/// A JSON number, or `null` for the unbounded ends of always-present areas.
fn num(out: &mut String, x: f64) {
    if x.is_finite() {
        let _ = write!(out, "{x}");
    } else {
        out.push_str("null");
    }
}

/// A JSON string literal with JSON's escapes (RFC 8259 §7) as `serde_json` writes them: `"` and `\\` escaped, the
/// control characters below U+0020 by their short escape or `\u00xx`, all else as it
/// is (a `Value` per id cost a tenth of writing a large answer).
fn string(out: &mut String, s: &str) {
    out.push('"');
    let mut start = 0;
    for (i, b) in s.bytes().enumerate() {
        let esc: &str = match b {
            b'"' => "\\\"",
            b'\\' => "\\\\",
            b'\n' => "\\n",
            b'\r' => "\\r",
            b'\t' => "\\t",
            0x08 => "\\b",
            0x0c => "\\f",
            0..=0x1f => "",
            _ => continue,
        };
        out.push_str(&s[start..i]);
        if esc.is_empty() {
            const HEX: &[u8; 16] = b"0123456789abcdef";
            out.push_str("\\u00");
            out.push(char::from(HEX[usize::from(b >> 4)]));
            out.push(char::from(HEX[usize::from(b & 15)]));
        } else {
            out.push_str(esc);
        }
        start = i + 1;
    }
    out.push_str(&s[start..]);
    out.push('"');
}

/// Region coordinates are written with this many decimals of a degree: 1e-7° ≈ 1.1 cm,
/// far below the stage tolerances, and a fixed-point writer is several times faster than
/// shortest round-trip formatting on the megabytes of a large answer.
const REGION_DECIMALS: u32 = 7;

/// A coordinate in units of the last printed decimal.
fn units(x: f64) -> i64 {
    (x * 10i64.pow(REGION_DECIMALS) as f64).round() as i64
}

fn coord_units(out: &mut String, v: i64) {
    let scale = 10i64.pow(REGION_DECIMALS);
    if v < 0 {
        out.push('-');
    }
    let a = v.unsigned_abs();
    let (int, frac) = (a / scale as u64, a % scale as u64);
    push_digits(out, int, 1);
    out.push('.');
    push_digits(out, frac, REGION_DECIMALS as usize);
}

/// n in decimal, left-padded with zeros to at least `width` digits (core::fmt's padding
/// machinery was a tenth of a large answer's run time).
fn push_digits(out: &mut String, mut n: u64, width: usize) {
    let mut buf = [b'0'; 20];
    let mut k = buf.len();
    while n > 0 {
        k -= 1;
        buf[k] = b'0' + (n % 10) as u8;
        n /= 10;
    }
    let start = k.min(buf.len() - width.min(buf.len()));
    for &d in &buf[start..] {
        out.push(char::from(d));
    }
}

/// A region's ring as printed: longitude and latitude in units of the last decimal,
/// with what rounding made of it repaired: repeated positions merged and spikes (a step
/// that turns straight back along itself) removed, so that the printed ring stays a
/// valid one. Empty when fewer than three positions are left.
fn printed_ring(ring: &[Merc], geo: Geodesy) -> Vec<[i64; 2]> {
    let mut r: Vec<[i64; 2]> = ring
        .iter()
        .map(|&m| {
            let (lon, lat) = geo.inverse_mercator(m).to_degrees();
            [units(lon), units(lat)]
        })
        .collect();
    loop {
        r.dedup();
        while r.len() > 1 && r.first() == r.last() {
            r.pop();
        }
        let n = r.len();
        if n < 3 {
            return Vec::new();
        }
        // b is a spike's tip when a, b, c lie on one line and c turns back towards a
        let spike = (0..n).find(|&i| {
            let (a, b, c) = (r[(i + n - 1) % n], r[i], r[(i + 1) % n]);
            let d1 = [i128::from(b[0] - a[0]), i128::from(b[1] - a[1])];
            let d2 = [i128::from(c[0] - b[0]), i128::from(c[1] - b[1])];
            d1[0] * d2[1] == d1[1] * d2[0] && d1[0] * d2[0] + d1[1] * d2[1] < 0
        });
        match spike {
            Some(i) => {
                r.remove(i);
            }
            None => return r,
        }
    }
}

/// A printed polygon: its exterior ring and its holes ([`printed_ring`]).
type PrintedPolygon = (Vec<[i64; 2]>, Vec<Vec<[i64; 2]>>);

fn ring_lonlat(out: &mut String, ring: &[[i64; 2]]) {
    out.push('[');
    for (k, p) in ring.iter().chain(ring.first()).enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push('[');
        coord_units(out, p[0]);
        out.push(',');
        coord_units(out, p[1]);
        out.push(']');
    }
    out.push(']');
}

/// The answer JSON of the spec for a pipeline result, written directly (the answer of a
/// large scenario holds megabytes of region coordinates; building a `serde_json::Value`
/// first costs more than the four stages).
pub fn answer(
    scenario: &Scenario,
    conflicts: &[pipeline::Conflict],
    stats: &pipeline::Stats,
    errors: &[ScenarioError],
    warnings: &[ScenarioWarning],
    extra_ms: (f64, f64, f64),
    regions: bool,
) -> String {
    let per = if regions { 640 } else { 200 };
    let mut out = String::with_capacity(1024 + conflicts.len() * per);
    out.push_str(ANSWER_HEAD);
    for (k, c) in conflicts.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        conflict_json(
            &mut out,
            &|k| &scenario.features[k].id,
            c,
            regions,
            scenario.geodesy,
        );
    }
    answer_tail(
        &mut out,
        scenario.features.len(),
        conflicts.len(),
        stats,
        errors,
        warnings,
        extra_ms,
        scenario.geodesy,
    );
    out
}

/// How the answer starts.
const ANSWER_HEAD: &str = "{\"conflicts\":[";

/// One conflict of the answer, on a line of its own (the comma before it is the caller's).
fn conflict_json<'a>(
    out: &mut String,
    id: &dyn Fn(usize) -> &'a str,
    c: &pipeline::Conflict,
    regions: bool,
    geo: Geodesy,
) {
    let (decided_by, method) = match c.method {
        Method::AreaOverlap => ("area_overlap", "area_overlap"),
        Method::Linear => ("time_of_intersection", "exact_linear"),
        Method::Advancement => ("time_of_intersection", "certified_advancement"),
    };
    out.push_str("\n{\"a\":");
    string(out, id(c.a as usize));
    out.push_str(",\"b\":");
    string(out, id(c.b as usize));
    out.push_str(",\"t_start\":");
    num(out, c.t_start);
    out.push_str(",\"t_end\":");
    num(out, c.t_end);
    out.push_str(",\"decided_by\":\"");
    out.push_str(decided_by);
    out.push_str("\",\"method\":\"");
    out.push_str(method);
    out.push_str("\",\"projection_windows\":");
    // not computed with --no-regions: null, not a pair of "no window"s
    if !regions {
        out.push_str("null");
    } else {
        out.push('[');
    }
    for (i, w) in c.paper.iter().enumerate().filter(|_| regions) {
        if i > 0 {
            out.push(',');
        }
        match w {
            Some((a, b)) => {
                out.push('[');
                num(out, *a);
                out.push(',');
                num(out, *b);
                out.push(']');
            }
            None => out.push_str("null"),
        }
    }
    if regions {
        out.push(']');
    }
    // --no-regions: no region member at all (the answer of a dense scenario is
    // gigabytes of `"region": null` otherwise)
    if !regions {
        out.push('}');
        return;
    }
    out.push_str(",\"region\":");
    // each counterclockwise ring starts a polygon, the clockwise ones after it are
    // its holes (crate::conflict::geom::region)
    let polys: Vec<PrintedPolygon> = crate::conflict::geom::polygons(&c.rings)
        .iter()
        .map(|(ext, holes)| {
            let holes = holes.iter().map(|h| printed_ring(h, geo));
            (
                printed_ring(ext, geo),
                holes.filter(|h| !h.is_empty()).collect(),
            )
        })
        .filter(|(ext, _)| !ext.is_empty())
        .collect();
    let polygon = |out: &mut String, (ext, holes): &PrintedPolygon| {
        out.push('[');
        ring_lonlat(out, ext);
        for h in holes {
            out.push(',');
            ring_lonlat(out, h);
        }
        out.push(']');
    };
    match polys.as_slice() {
        [] => out.push_str("null"),
        [one] => {
            out.push_str("{\"type\":\"Polygon\",\"coordinates\":");
            polygon(out, one);
            out.push('}');
        }
        many => {
            out.push_str("{\"type\":\"MultiPolygon\",\"coordinates\":[");
            for (i, p) in many.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                polygon(out, p);
            }
            out.push_str("]}");
        }
    }
    out.push('}');
}

/// The answer after its conflicts: stats, errors, warnings.
fn answer_tail(
    out: &mut String,
    features: usize,
    conflicts: usize,
    stats: &pipeline::Stats,
    errors: &[ScenarioError],
    warnings: &[ScenarioWarning],
    extra_ms: (f64, f64, f64),
    geo: Geodesy,
) {
    let (parse_ms, objects_ms, total_ms) = extra_ms;
    let stats_v = json!({
        "geodesy": geo.name(),
        "objects": features,
        "stage_objects": stats.objects,
        "candidate_pairs": stats.candidate_pairs,
        "region_pairs": stats.region_pairs,
        "window_pairs": stats.window_pairs,
        "interval_pairs": stats.interval_pairs,
        "exact_linear_pairs": stats.linear_pairs,
        "advancement_pairs": stats.advancement_pairs,
        "conflicts": conflicts,
        "rejected_features": errors.len(),
        "timings_ms": {
            "parse": parse_ms,
            "objects": objects_ms,
            "stage1": stats.stage1_ms,
            "stage2": stats.stage2_ms,
            "stage3": stats.stage3_ms,
            "stage4": stats.stage4_ms,
            "total": total_ms,
        }
    });
    let errors_v: Vec<Value> = errors
        .iter()
        .map(|e| {
            json!({"line": e.line, "index": e.index, "id": e.id, "field": e.field,
                   "message": e.to_string()})
        })
        .collect();
    let warnings_v: Vec<Value> = warnings
        .iter()
        .map(|w| {
            json!({"line": w.line, "index": w.index, "id": w.id, "field": w.field,
                   "message": w.to_string()})
        })
        .collect();
    let _ = write!(
        out,
        "],\n\"stats\":{stats_v},\n\"errors\":{},\n\"warnings\":{}}}",
        Value::from(errors_v),
        Value::from(warnings_v)
    );
}

/// What [`analyse_into`] gives back: everything but the conflicts, which went to the
/// writer.
#[derive(Debug)]
pub struct Summary {
    /// Rejected features.
    pub errors: Vec<ScenarioError>,
    /// What the reader warns of: members not read (foreign, or kept in `properties`),
    /// longitudes read modulo 360°.
    pub warnings: Vec<ScenarioWarning>,
    /// How many conflicts were written.
    pub conflicts: usize,
    /// The pipeline's counts and timings.
    pub stats: pipeline::Stats,
}

/// Conflicts whose answer text one task of [`analyse_into`] writes.
const OUTPUT_CHUNK: usize = 256;

/// The bytes of one conflict's answer text reserved ahead (with its region).
const CONFLICT_BYTES: usize = 512;

/// [`analyse_with`], the answer written to `out` as each block of features is done
/// ([`pipeline::run_blocks`]): memory holds one block's conflicts, never the whole answer
/// (any density, in bounded memory). The text written is the answer
/// [`analyse_with`] gives, timings apart. `Err` when the text is not a collection
/// (nothing is written then); the inner `Err` when writing fails (the answer is cut).
pub fn analyse_into(
    text: String,
    tolerance_h: f64,
    regions: bool,
    geodesy: Geodesy,
    out: &mut dyn std::io::Write,
    progress: &mut dyn Progress,
) -> Result<std::io::Result<Summary>, ScenarioError> {
    let t_all = Instant::now();
    let scenario::Read {
        scenario: mut sc,
        errors,
        warnings,
    } = scenario::parse(&text)?;
    sc.geodesy = geodesy;
    let geo = geodesy;
    // the text and, once the objects are built, the features' geometry are not needed
    // again: a 10⁶-object scenario's text is hundreds of MB
    drop(text);
    let parse_ms = t_all.elapsed().as_secs_f64() * 1e3;
    let t_obj = Instant::now();
    let objects = scenario::objects(&sc);
    let ids: Vec<String> = sc.features.into_iter().map(|f| f.id).collect();
    let objects_ms = t_obj.elapsed().as_secs_f64() * 1e3;
    progress.stages_start(objects.len());
    let mut failed: Option<std::io::Error> = None;
    let mut count = 0usize;
    if let Err(e) = out.write_all(ANSWER_HEAD.as_bytes()) {
        return Ok(Err(e));
    }
    let stats = pipeline::run_blocks(
        &objects,
        pipeline::Options {
            tolerance_h,
            details: regions,
            ..pipeline::Options::default()
        },
        &mut |block| {
            if failed.is_some() {
                return;
            }
            // the conflicts' text in parallel, a chunk per task (with regions, writing the
            // coordinates costs as much as a stage), written in order
            use rayon::prelude::*;
            let texts: Vec<String> = block
                .par_chunks(OUTPUT_CHUNK)
                .map(|chunk| {
                    // room for a conflict with a region of a dozen vertices: few regrowths
                    let mut s = String::with_capacity(chunk.len() * CONFLICT_BYTES);
                    for (k, c) in chunk.iter().enumerate() {
                        if k > 0 {
                            s.push(',');
                        }
                        conflict_json(&mut s, &|k| &ids[k], c, regions, geo);
                    }
                    s
                })
                .collect();
            for (i, t) in texts.iter().enumerate() {
                let sep: &[u8] = if count > 0 || i > 0 { b"," } else { b"" };
                if let Err(e) = out
                    .write_all(sep)
                    .and_then(|()| out.write_all(t.as_bytes()))
                {
                    failed = Some(e);
                    return;
                }
            }
            count += block.len();
        },
    );
    progress.stages_end();
    if let Some(e) = failed {
        return Ok(Err(e));
    }
    let total_ms = t_all.elapsed().as_secs_f64() * 1e3;
    let mut buf = String::new();
    answer_tail(
        &mut buf,
        ids.len(),
        count,
        &stats,
        &errors,
        &warnings,
        (parse_ms, objects_ms, total_ms),
        geo,
    );
    buf.push('\n');
    Ok(out
        .write_all(buf.as_bytes())
        .and_then(|()| out.flush())
        .map(|()| Summary {
            errors,
            warnings,
            conflicts: count,
            stats,
        }))
}

/// Everything `conflicts` computes for one scenario.
pub struct Analysis {
    /// The answer JSON text.
    pub answer: String,
    /// Rejected features.
    pub errors: Vec<ScenarioError>,
    /// What the reader warns of: members not read (foreign, or kept in `properties`),
    /// longitudes read modulo 360°.
    pub warnings: Vec<ScenarioWarning>,
    /// The valid features.
    pub scenario: Scenario,
    /// Their stage objects.
    pub objects: Vec<Object>,
    /// The conflicts.
    pub conflicts: Vec<pipeline::Conflict>,
}

/// Paper B Algorithm 1 on scenario text.
pub fn analyse(text: &str, tolerance_h: f64) -> Result<Analysis, ScenarioError> {
    analyse_with(text, tolerance_h, true, Geodesy::Sphere, &mut ())
}

/// [`analyse`], optionally without the regions in the answer, telling `progress` when the
/// four stages start and end.
pub fn analyse_with(
    text: &str,
    tolerance_h: f64,
    regions: bool,
    geodesy: Geodesy,
    progress: &mut dyn Progress,
) -> Result<Analysis, ScenarioError> {
    let t_all = Instant::now();
    let scenario::Read {
        scenario: mut sc,
        errors,
        warnings,
    } = scenario::parse(text)?;
    sc.geodesy = geodesy;
    let parse_ms = t_all.elapsed().as_secs_f64() * 1e3;
    let t_obj = Instant::now();
    let objects = scenario::objects(&sc);
    let objects_ms = t_obj.elapsed().as_secs_f64() * 1e3;
    progress.stages_start(objects.len());
    let (conflicts, stats) = pipeline::run(
        &objects,
        pipeline::Options {
            tolerance_h,
            details: regions,
            ..pipeline::Options::default()
        },
    );
    progress.stages_end();
    let total_ms = t_all.elapsed().as_secs_f64() * 1e3;
    let answer = answer(
        &sc,
        &conflicts,
        &stats,
        &errors,
        &warnings,
        (parse_ms, objects_ms, total_ms),
        regions,
    );
    Ok(Analysis {
        answer,
        errors,
        warnings,
        scenario: sc,
        objects,
        conflicts,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ids are written as serde_json writes them: every control character, quotes,
    /// backslashes, non-ASCII text.
    #[test]
    fn strings_are_escaped_as_serde_json_escapes_them() {
        let mut cases: Vec<String> = (0u8..0x20)
            .map(|b| format!("a{}b", char::from(b)))
            .collect();
        cases.extend(
            [
                "",
                "plain",
                "q\"uote",
                "back\\slash",
                "\u{7f}",
                "é – ü 飛",
                "\"\\\n",
            ]
            .map(String::from),
        );
        for c in &cases {
            let mut s = String::new();
            string(&mut s, c);
            assert_eq!(s, Value::from(c.as_str()).to_string(), "{c:?}");
        }
    }

    #[test]
    fn coord_is_fixed_point_with_seven_decimals() {
        for &(x, want) in &[
            (0.0, "0.0000000"),
            (-0.0, "0.0000000"),
            (39.5, "39.5000000"),
            (-45.123456789, "-45.1234568"),
            (179.99999999, "180.0000000"),
            (-0.00000004, "0.0000000"),
            (-0.00000006, "-0.0000001"),
            (1.0000001, "1.0000001"),
        ] {
            let mut s = String::new();
            coord_units(&mut s, units(x));
            assert_eq!(s, want, "{x}");
        }
    }
}
