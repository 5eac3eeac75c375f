//! The answer of `polyguard encounters` as JSON (docs/moving-features.md, "The
//! answer"): one object per pair of mover and area that meet, the same for the CLI's
//! lines, the C interface's and any other writer of them.

use super::encounter::Encounter;
use super::plane::TimeSpan;
use super::time::{format, Round};
use serde_json::{json, Value};

/// An epoch time as RFC 3339 rounded `r` (or `null` beyond years 0–9999).
fn utc(t: f64, r: Round) -> Value {
    format(t, r).map_or(Value::Null, Value::String)
}

/// One span of the answer: epoch-second enclosures, and the UTC text of its outer ends
/// (the start's lower end rounded down, the end's upper end rounded up).
fn span_json(s: &TimeSpan) -> Value {
    json!({
        "start": s.start,
        "end": s.end,
        "certain": s.certain,
        "start_utc": utc(s.start[0], Round::Floor),
        "end_utc": utc(s.end[1], Round::Ceil),
    })
}

/// One line of the answer: the pair, its inside and near spans, the first loss of
/// separation, and the mover's gaps.
pub fn encounter_json(e: &Encounter) -> Value {
    json!({
        "mover": e.mover,
        "callsign": e.callsign,
        "area": e.area,
        "inside": e.inside.iter().map(span_json).collect::<Vec<_>>(),
        "near": e.near.iter().map(span_json).collect::<Vec<_>>(),
        "loss_of_separation": e.loss_of_separation(),
        "loss_of_separation_utc": e.loss_of_separation().map(|s| utc(s[0], Round::Floor)),
        "gaps": e.gaps,
    })
}
