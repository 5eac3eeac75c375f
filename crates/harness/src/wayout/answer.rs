//! The answers of `polyguard bands`, `recover` and `offset` (docs/way-out.md): one case
//! line in, one answer object out, shared by the command line and the bindings. The
//! engine's `bands` (course, speed and vertical speed bands of paper A §II–§III's motion
//! against §II.G's near_D), `recovery` (the nearest point out of a polygon's
//! D-neighbourhood or into its D-core, §II's polygon) and `offset` (P ⊕ disc(D) and the
//! inset, certified within D(1 + ε)), with the oracle's exact minimum for
//! `recover --engine truth`.

use std::cmp::Ordering;
use std::f64::consts::TAU;

use serde_json::{json, Map, Value};

use polyguard::bands::{
    conflict, course_bands, speed_bands, vertical_speed_bands, BandKind, Bands, BandsError,
};
use polyguard::offset::{inset_at, offset_at, Offset, OffsetError};
use polyguard::recovery::{Recovery, RecoveryError};
use polyguard::{Separation, Tri, Vect2};
use polyguard_oracle::convert::q;
use polyguard_oracle::recovery::{ExactMin, ExactRecovery};
use polyguard_oracle::Q;

use super::bands::BandCase;
use super::case::{parse_way_line, FieldError, WayCase};
use super::recovery::{self as rec, Query, Side};
use crate::case::Fence;

/// Which command answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// `polyguard bands`: course (and speed, vertical speed) bands.
    Bands,
    /// `polyguard recover`: the recovery point.
    Recover,
    /// `polyguard offset`: the offset or inset polygons.
    Offset,
}

/// The command line's values for what a case line does not give (the line's own fields
/// win), and the command's switches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ask {
    /// D ≥ 0 (`--sep`).
    pub sep: f64,
    /// H ≥ 0 (`--sep-v`).
    pub sep_v: f64,
    /// The Unknown total aimed at, degrees (`--unknown-max-deg`).
    pub unknown_max_deg: f64,
    /// ε of the offset (`--eps`).
    pub eps: f64,
    /// keep-out: recovery out of the D-neighbourhood; keep-in: into the D-core.
    pub fence: Fence,
    /// The inset instead of the offset (`offset --inset`).
    pub inset: bool,
    /// Add the oracle's exact minimum distance (`recover --engine truth`).
    pub truth: bool,
    /// Add PolyCARP's recovery point beside the engine's, judged exactly (`recover
    /// --polycarp`).
    pub polycarp: bool,
}

/// The format's defaults (docs/way-out.md).
impl Default for Ask {
    fn default() -> Ask {
        Ask {
            sep: 0.0,
            sep_v: 0.0,
            unknown_max_deg: DEFAULT_UNKNOWN_MAX_DEG,
            eps: DEFAULT_EPS,
            fence: Fence::KeepOut,
            inset: false,
            truth: false,
            polycarp: false,
        }
    }
}

/// `bands.unknown_max_deg` when neither the line nor the command line gives one.
pub const DEFAULT_UNKNOWN_MAX_DEG: f64 = 0.1;
/// `eps` when neither the line nor the command line gives one.
pub const DEFAULT_EPS: f64 = 0.01;

/// One line answered: the answer object (`id` first) and whether it is an error line.
pub fn answer_line(cmd: Command, line: &str, line_no: usize, ask: &Ask) -> (Value, bool) {
    let parsed = parse_way_line(line, line_no);
    let mut obj = Map::new();
    obj.insert("id".into(), parsed.id);
    match parsed.case.and_then(|c| answer(cmd, &c, ask)) {
        Ok(fields) => {
            obj.extend(fields);
            (Value::Object(obj), true)
        }
        Err(e) => {
            obj.insert("error".into(), error_json(&e, line_no));
            (Value::Object(obj), false)
        }
    }
}

/// The error object of an error line: `{"field", "line", "message"}`.
pub fn error_json(e: &FieldError, line_no: usize) -> Value {
    json!({"field": e.field, "line": line_no, "message": e.message})
}

/// A valid case answered by `cmd`: the fields after `id`.
pub fn answer(cmd: Command, case: &WayCase, ask: &Ask) -> Result<Map<String, Value>, FieldError> {
    match cmd {
        Command::Bands => bands_answer(case, ask),
        Command::Recover => recover_answer(case, ask),
        Command::Offset => offset_answer(case, ask),
    }
}

/// The engine's band case of a way-out case, with D and H (the line's, else `ask`'s).
pub fn band_case(case: &WayCase, ask: &Ask) -> BandCase {
    BandCase {
        t: case.lookahead,
        s: case.s,
        height: case.height,
        polygons: case.polygons.clone(),
        sep: Separation {
            d: case.sep.unwrap_or(ask.sep),
            h: case.sep_v.unwrap_or(ask.sep_v),
        },
    }
}

/// The current course of the velocity v: degrees-style radians clockwise from +y, in
/// [0, 2π) (0 for a point at rest).
pub fn course_of(v: Vect2) -> f64 {
    let c = v.x.atan2(v.y);
    if c < 0.0 {
        c + TAU
    } else {
        c
    }
}

fn kind_name(k: BandKind) -> &'static str {
    match k {
        BandKind::Clear => "clear",
        BandKind::Conflict => "conflict",
        BandKind::Unknown => "unknown",
    }
}

/// A band error in the case's terms (`obstacles[i]` is `polygons[i]`).
fn band_error(e: &BandsError) -> FieldError {
    let text = e.to_string();
    let (field, message) = text.split_once(": ").unwrap_or(("case", &text));
    let field = field
        .replace("obstacles", "polygons")
        .replace(".p[", ".vertices[")
        .replace(".vels[", ".velocities[");
    FieldError::new(field, message)
}

/// Bands over a linear parameter (speeds, vertical speeds) as the answer writes them.
fn linear_json(b: &Bands) -> Value {
    let bands: Vec<Value> = b
        .bands
        .iter()
        .map(|x| json!({"from": x.lo, "to": x.hi, "kind": kind_name(x.kind)}))
        .collect();
    json!({"bands": bands, "unknown_total": b.unknown_total, "met": b.met})
}

/// The Unknown total aimed at over [min, max]: the share of the range that
/// `unknown_max_deg` is of a full turn (the range itself when it is a single value, whose
/// Unknown total is 0 anyway).
fn linear_unknown_max(r: [f64; 2], deg: f64) -> f64 {
    let w = (r[1] - r[0]) * (deg / 360.0);
    if w > 0.0 {
        w
    } else {
        f64::MIN_POSITIVE
    }
}

/// `polyguard bands` (docs/way-out.md, the definitions of the engine's `bands` module):
/// course bands at the current speed |v|, the current velocity's own verdict, and the
/// speed and vertical speed bands the line asks for.
pub fn bands_answer(case: &WayCase, ask: &Ask) -> Result<Map<String, Value>, FieldError> {
    if case.fence == Some(Fence::KeepIn) {
        return Err(FieldError::new(
            "fence",
            "bands treat every polygon as an area to stay out of (keep_out); \
             keep_in is for recover",
        ));
    }
    let bc = band_case(case, ask);
    let deg = case.bands.unknown_max_deg.unwrap_or(ask.unknown_max_deg);
    if !(deg.is_finite() && deg > 0.0) {
        return Err(FieldError::new(
            "bands.unknown_max_deg",
            format!("{deg} is not > 0"),
        ));
    }
    let speed = case.v.x.hypot(case.v.y);
    let course = course_of(case.v);
    bc.with_traffic(|traffic| {
        let cb = course_bands(traffic, speed, deg.to_radians()).map_err(|e| band_error(&e))?;
        let current = conflict(traffic, case.v).map_err(|e| band_error(&e))?;
        let bands: Vec<Value> = cb
            .bands
            .iter()
            .map(|b| {
                json!({
                    "from_deg": b.lo.to_degrees(),
                    "to_deg": b.hi.to_degrees(),
                    "from_rad": b.lo,
                    "to_rad": b.hi,
                    "kind": kind_name(b.kind),
                })
            })
            .collect();
        let mut out = Map::new();
        out.insert(
            "course".into(),
            json!({
                "speed": speed,
                "bands": bands,
                "unknown_total_deg": cb.unknown_total.to_degrees(),
                "met": cb.met,
            }),
        );
        out.insert("current_course_deg".into(), course.to_degrees().into());
        let current = match current {
            Tri::Yes => "conflict",
            Tri::No => "clear",
            Tri::Unsure => "unknown",
        };
        out.insert("current".into(), current.into());
        if let Some(r) = case.bands.speeds {
            let sb = speed_bands(traffic, course, r[0], r[1], linear_unknown_max(r, deg))
                .map_err(|e| band_error(&e))?;
            out.insert("speed".into(), linear_json(&sb));
        }
        if let Some(r) = case.bands.vertical_speeds {
            let vb = vertical_speed_bands(traffic, case.v, r[0], r[1], linear_unknown_max(r, deg))
                .map_err(|e| band_error(&e))?;
            out.insert("vertical_speed".into(), linear_json(&vb));
        }
        out.insert("sep".into(), bc.sep.d.into());
        if case.height.is_some() {
            out.insert("sep_v".into(), bc.sep.h.into());
        }
        Ok(out)
    })
}

/// The one polygon `recover` and `offset` take.
fn single(case: &WayCase, what: &str) -> Result<usize, FieldError> {
    if case.polygons.len() == 1 {
        Ok(0)
    } else {
        Err(FieldError::new(
            "polygons",
            format!(
                "{} polygons: {what} takes one polygon (give each its own case line)",
                case.polygons.len()
            ),
        ))
    }
}

/// A recovery error in the case's terms.
fn recovery_error(e: &RecoveryError) -> FieldError {
    let field = match e.field() {
        "p" => "polygon.vertices",
        "vels" => "polygon.velocities",
        "s" => "point.pos",
        "t" => "time",
        other => other,
    };
    let text = e.to_string();
    let message = text.split_once(": ").map_or(text.as_str(), |(_, m)| m);
    FieldError::new(field, message)
}

/// The recovery query of a case: its polygon at `time`, s, D, the fence's condition.
pub fn recovery_query(case: &WayCase, ask: &Ask) -> Result<Query, FieldError> {
    let k = single(case, "recover")?;
    let poly = &case.polygons[k];
    let t = case.time.unwrap_or(0.0);
    let moving = t != 0.0 && poly.vels.iter().any(|v| v.x != 0.0 || v.y != 0.0);
    Ok(Query {
        p: poly.p.clone(),
        vels: if moving { poly.vels.clone() } else { vec![] },
        t,
        s: case.s,
        d: case.sep.unwrap_or(ask.sep),
        side: match case.fence.unwrap_or(ask.fence) {
            Fence::KeepOut => Side::Out,
            Fence::KeepIn => Side::In,
        },
    })
}

/// `polyguard recover` (docs/way-out.md, the engine's `recovery` module): the certified
/// recovery point, or why there is none; with `ask.truth` the exact minimum distance.
pub fn recover_answer(case: &WayCase, ask: &Ask) -> Result<Map<String, Value>, FieldError> {
    let qy = recovery_query(case, ask)?;
    let got = rec::engine(&qy).map_err(|e| recovery_error(&e))?;
    let mut recovery = Map::new();
    match got {
        Recovery::Point {
            x,
            dist_hi,
            min_lo,
            clear,
        } => {
            recovery.insert("point".into(), json!([x.x, x.y]));
            recovery.insert("distance".into(), dist_hi.into());
            recovery.insert("min_lo".into(), min_lo.into());
            recovery.insert("moved".into(), (!clear).into());
        }
        Recovery::Impossible { reason } => {
            recovery.insert("impossible".into(), reason.into());
        }
    }
    if ask.truth {
        match (rec::exact(&qy), &got) {
            (Some(ExactRecovery::Min(m)), Recovery::Point { x, .. }) => {
                let (near, text) = exact_min(&m);
                recovery.insert("min".into(), near.into());
                recovery.insert("min_exact".into(), text.into());
                recovery.insert("meets".into(), rec::meets(&qy, *x).into());
            }
            (Some(ExactRecovery::Impossible), Recovery::Impossible { .. }) => {
                recovery.insert("impossible_exact".into(), true.into());
            }
            (Some(_), _) => {
                return Err(FieldError::new(
                    "case",
                    "the exact oracle contradicts the engine (please report this case)",
                ))
            }
            (None, _) => {
                return Err(FieldError::new(
                    "case",
                    "the exact oracle cannot read the case",
                ))
            }
        }
    }
    let mut out = Map::new();
    out.insert("recovery".into(), Value::Object(recovery));
    if ask.polycarp {
        out.insert("polycarp".into(), polycarp_json(&qy));
    }
    out.insert("sep".into(), qy.d.into());
    out.insert(
        "fence".into(),
        case.fence.unwrap_or(ask.fence).name().into(),
    );
    out.insert("time".into(), qy.t.into());
    Ok(out)
}

/// The share of D that PolyCARP's BUFF is given beside `recover --polycarp` (its
/// ResolBUFF is D).
pub const POLYCARP_BUFF_SHARE: f64 = 0.01;

/// PolyCARP's recovery point for the query (NASA PolyCARP's `recovery_point`, ported in
/// `wayout::polycarp`; BUFF = D/100, ResolBUFF = D), on the polygon at the query's time
/// evaluated in f64: the point, |x − s|, whether it meets the condition (exactly, on
/// that polygon) and how much farther than the exact minimum it is (`null` when no
/// point meets the condition).
fn polycarp_json(qy: &Query) -> Value {
    let p: Vec<Vect2> = if qy.vels.is_empty() {
        qy.p.clone()
    } else {
        qy.p.iter()
            .zip(&qy.vels)
            .map(|(a, v)| a.at(*v, qy.t))
            .collect()
    };
    let at = Query {
        p,
        vels: Vec::new(),
        t: 0.0,
        ..qy.clone()
    };
    let r = rec::polycarp_report(&at, POLYCARP_BUFF_SHARE * qy.d);
    json!({
        "point": [r.x.x, r.x.y],
        "distance": r.dist,
        "meets": r.meets,
        "excess": r.excess(),
    })
}

/// The order of m and the f64 x ≥ 0, exactly.
fn cmp_f64(m: &ExactMin, x: f64) -> Ordering {
    match q(x) {
        Some(r) => m.cmp_rational(&r),
        None => Ordering::Less,
    }
}

/// The exact minimum m as its nearest f64 (ties to even) and as exact text: `0`, a
/// rational, `√(X)` with X the squared distance of the candidate attaining it (X
/// rational or in nested square roots, `Tower::sqrt_text`), or `min(√(X), √(Y), …)` when several
/// candidates lie within one ulp of m and the f64 bracket does not tell them apart.
pub fn exact_min(m: &ExactMin) -> (f64, String) {
    if m.zero {
        return (0.0, "0".into());
    }
    // Non-negative f64 are ordered as their bit patterns: bisect for lo ≤ m < hi.
    let (mut lo, mut hi) = (0u64, f64::MAX.to_bits());
    if cmp_f64(m, f64::MAX) != Ordering::Less {
        return (f64::MAX, "beyond the largest f64".into());
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if cmp_f64(m, f64::from_bits(mid)) == Ordering::Less {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let (a, b) = (f64::from_bits(lo), f64::from_bits(hi));
    let near = match (q(a), q(b), q(0.5)) {
        _ if cmp_f64(m, a) == Ordering::Equal => a,
        (Some(ra), Some(rb), Some(half)) => match m.cmp_rational(&((ra + rb) * half)) {
            Ordering::Less => a,
            Ordering::Greater => b,
            Ordering::Equal if lo % 2 == 0 => a,
            Ordering::Equal => b,
        },
        _ => a,
    };
    // The candidates with d² ≤ b² hold the minimiser; the others exceed m.
    let bound = q(b).map(|r| &r * &r);
    let mut texts: Vec<String> = Vec::new();
    for (t, d2) in &m.cands {
        let within = bound.as_ref().map_or(true, |b2: &Q| {
            t.sign(&t.sub(d2, &t.rat(b2))) != Ordering::Greater
        });
        if within {
            let text = t.sqrt_text(d2);
            if !texts.contains(&text) {
                texts.push(text);
            }
        }
    }
    let text = match texts.len() {
        1 => texts.remove(0),
        _ => format!("min({})", texts.join(", ")),
    };
    (near, text)
}

/// An offset error in the case's terms.
fn offset_error(e: &OffsetError) -> FieldError {
    let text = e.to_string();
    match e {
        OffsetError::Invalid { field, reason } => {
            let field = match *field {
                "p" => "polygon.vertices",
                "vels" => "polygon.velocities",
                "t" => "time",
                "d" => "sep",
                other => other,
            };
            FieldError::new(field, *reason)
        }
        OffsetError::Polygon { .. } => FieldError::new(
            "polygon.vertices",
            text.split_once(": ").map_or(text.as_str(), |(_, m)| m),
        ),
        OffsetError::TooFine { .. } => FieldError::new(
            "eps",
            text.split_once(": ").map_or(text.as_str(), |(_, m)| m),
        ),
        OffsetError::Uncertified { .. } => FieldError::new("case", text),
    }
}

fn ring_json(r: &[Vect2]) -> Value {
    Value::Array(r.iter().map(|v| json!([v.x, v.y])).collect())
}

/// The regions of an offset as the answer writes them.
pub fn regions_json(o: &Offset) -> Value {
    Value::Array(
        o.regions
            .iter()
            .map(|r| {
                json!({
                    "outer": ring_json(&r.outer),
                    "holes": r.holes.iter().map(|h| ring_json(h)).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}

/// `polyguard offset` (docs/way-out.md, the engine's `offset` module): the certified
/// offset (or inset) by D of the case's polygon at `time`, within D(1 + ε).
pub fn offset_answer(case: &WayCase, ask: &Ask) -> Result<Map<String, Value>, FieldError> {
    let k = single(case, "offset")?;
    let poly = &case.polygons[k];
    let d = case.sep.unwrap_or(ask.sep);
    let eps = case.eps.unwrap_or(ask.eps);
    let t = case.time.unwrap_or(0.0);
    let built = if ask.inset {
        inset_at(&poly.p, &poly.vels, t, d, eps)
    } else {
        offset_at(&poly.p, &poly.vels, t, d, eps)
    }
    .map_err(|e| offset_error(&e))?;
    let mut out = Map::new();
    out.insert("offset".into(), regions_json(&built));
    out.insert("d".into(), d.into());
    out.insert("eps".into(), eps.into());
    out.insert("inset".into(), ask.inset.into());
    out.insert("time".into(), t.into());
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const KEEP_IN: &str = r#"{"id":"k","lookahead":1,"sep":3,"fence":"keep_in","point":{"pos":[19,1],"vel":[0,0]},"polygon":{"vertices":[[0,0],[20,0],[20,20],[0,20]]}}"#;

    /// The exact minimum to the keep-in square's core is √8 (from (19, 1) to (17, 3)):
    /// its nearest f64 is the correctly rounded √8, and its text says it exactly.
    #[test]
    fn the_exact_minimum_is_rounded_to_nearest() {
        let ask = Ask {
            truth: true,
            ..Ask::default()
        };
        let (a, ok) = answer_line(Command::Recover, KEEP_IN, 1, &ask);
        assert!(ok, "{a}");
        let r = &a["recovery"];
        assert_eq!(r["min"].as_f64(), Some(8f64.sqrt()));
        assert_eq!(r["min_exact"], "√(8)");
        assert_eq!(r["meets"], true);
        assert!(r["min_lo"].as_f64() <= Some(8f64.sqrt()));
    }

    /// Course bands tile [0°, 360°]; the current velocity's verdict is its own.
    #[test]
    fn course_bands_tile_the_circle() {
        let line = r#"{"id":"b","lookahead":1,"sep":0.5,"point":{"pos":[0,-3],"vel":[0,5]},"polygon":{"vertices":[[-1,0],[1,0],[0,1]]}}"#;
        let (a, ok) = answer_line(Command::Bands, line, 1, &Ask::default());
        assert!(ok, "{a}");
        assert_eq!(a["current"], "conflict");
        let bands = a["course"]["bands"].as_array().expect("bands");
        assert_eq!(bands[0]["from_deg"], 0.0);
        assert_eq!(bands[bands.len() - 1]["to_rad"], TAU);
        assert!(bands.iter().any(|b| b["kind"] == "clear"));
        assert_eq!(course_of(Vect2::new(-1.0, 0.0)).to_degrees(), 270.0);
        // every polygon of the bands is an area to stay out of
        let keep_in = line.replace(r#""sep":0.5,"#, r#""sep":0.5,"fence":"keep_in","#);
        let (a, ok) = answer_line(Command::Bands, &keep_in, 3, &Ask::default());
        assert!(!ok);
        assert_eq!(
            (&a["error"]["field"], &a["error"]["line"]),
            (&"fence".into(), &3.into())
        );
    }
}
