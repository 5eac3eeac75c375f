//! Paper B Algorithm 1 on a scenario GeoJSON (docs/scenario.md): the conflicts answer of
//! that spec, and an SVG drawing of the scenario and its conflicts.

use crate::conflict::{pipeline, stage4::Method, Object};
use crate::geodesy::Geodesy;
use crate::scenario::{self, Scenario, ScenarioError, ScenarioWarning};
use crate::sphere::Merc;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::time::Instant;
use text::{num, ring_lonlat, string, units};

mod text;

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
    let mut out = Vec::with_capacity(1024 + conflicts.len() * per);
    out.extend_from_slice(ANSWER_HEAD.as_bytes());
    for (k, c) in conflicts.iter().enumerate() {
        if k > 0 {
            out.push(b',');
        }
        conflict_json(
            &mut out,
            &|k| &scenario.features[k].id,
            c,
            regions,
            scenario.geodesy,
        );
    }
    let mut tail = String::new();
    answer_tail(
        &mut tail,
        scenario.features.len(),
        conflicts.len(),
        stats,
        errors,
        warnings,
        extra_ms,
        scenario.geodesy,
    );
    out.extend_from_slice(tail.as_bytes());
    // every byte written is ASCII or comes from a &str (an id): UTF-8 throughout
    String::from_utf8(out).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// How the answer starts.
const ANSWER_HEAD: &str = "{\"conflicts\":[";

/// One conflict of the answer, on a line of its own (the comma before it is the caller's).
fn conflict_json<'a>(
    out: &mut Vec<u8>,
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
    out.extend_from_slice(b"\n{\"a\":");
    string(out, id(c.a as usize));
    out.extend_from_slice(b",\"b\":");
    string(out, id(c.b as usize));
    out.extend_from_slice(b",\"t_start\":");
    num(out, c.t_start);
    out.extend_from_slice(b",\"t_end\":");
    num(out, c.t_end);
    out.extend_from_slice(b",\"decided_by\":\"");
    out.extend_from_slice(decided_by.as_bytes());
    out.extend_from_slice(b"\",\"method\":\"");
    out.extend_from_slice(method.as_bytes());
    out.extend_from_slice(b"\",\"projection_windows\":");
    // not computed with --no-regions: null, not a pair of "no window"s
    if !regions {
        out.extend_from_slice(b"null");
    } else {
        out.push(b'[');
    }
    for (i, w) in c.paper.iter().enumerate().filter(|_| regions) {
        if i > 0 {
            out.push(b',');
        }
        match w {
            Some((a, b)) => {
                out.push(b'[');
                num(out, *a);
                out.push(b',');
                num(out, *b);
                out.push(b']');
            }
            None => out.extend_from_slice(b"null"),
        }
    }
    if regions {
        out.push(b']');
    }
    // --no-regions: no region member at all (the answer of a dense scenario is
    // gigabytes of `"region": null` otherwise)
    if !regions {
        out.push(b'}');
        return;
    }
    out.extend_from_slice(b",\"region\":");
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
    let polygon = |out: &mut Vec<u8>, (ext, holes): &PrintedPolygon| {
        out.push(b'[');
        ring_lonlat(out, ext);
        for h in holes {
            out.push(b',');
            ring_lonlat(out, h);
        }
        out.push(b']');
    };
    match polys.as_slice() {
        [] => out.extend_from_slice(b"null"),
        [one] => {
            out.extend_from_slice(b"{\"type\":\"Polygon\",\"coordinates\":");
            polygon(out, one);
            out.push(b'}');
        }
        many => {
            out.extend_from_slice(b"{\"type\":\"MultiPolygon\",\"coordinates\":[");
            for (i, p) in many.iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                polygon(out, p);
            }
            out.extend_from_slice(b"]}");
        }
    }
    out.push(b'}');
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
            let texts: Vec<Vec<u8>> = block
                .par_chunks(OUTPUT_CHUNK)
                .map(|chunk| {
                    // room for a conflict with a region of a dozen vertices: few regrowths
                    let mut s = Vec::with_capacity(chunk.len() * CONFLICT_BYTES);
                    for (k, c) in chunk.iter().enumerate() {
                        if k > 0 {
                            s.push(b',');
                        }
                        conflict_json(&mut s, &|k| &ids[k], c, regions, geo);
                    }
                    s
                })
                .collect();
            for (i, t) in texts.iter().enumerate() {
                let sep: &[u8] = if count > 0 || i > 0 { b"," } else { b"" };
                if let Err(e) = out.write_all(sep).and_then(|()| out.write_all(t)) {
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
