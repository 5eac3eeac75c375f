//! The answer format of `polyguard detect` (docs/cases.md, "Answers"): one valid case
//! answered by the certified f64 engine (paper A §II.F–§III), the plain transcription,
//! paper A in exact arithmetic, or the exact truth, as the JSON fields after `id`.

use serde_json::{Map, Value};

use polyguard::api::{self, Case};

use polyguard::intervals::{Relation, Separation, Span};
use polyguard_oracle::algebraic::RealAlg;
use polyguard_oracle::intervals::Relation as ORelation;

use crate::case::{CaseOptions, Fence, RawCase};
use crate::classify::Exact;

/// Which implementation answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// The certified f64 engine (paper A in floating point): the product.
    F64,
    /// The plain f64 transcription of paper A, without certificate: for comparison only
    /// (it misses true entries on long relative paths).
    Plain,
    /// Paper A's functions in exact rational arithmetic (the oracle).
    Exact,
    /// The exact ground truth: does the point really enter the closed polygon, and when?
    Truth,
}

/// The engine asked for, and what more than paper A's detection: the f64 entry-time
/// enclosure (`detect --time`), the intervals (`--intervals`), the keep-in exit
/// (`fence: "keep_in"`), with the separations they use.
#[derive(Clone, Copy, Debug)]
pub struct Ask {
    /// The engine.
    pub engine: Engine,
    /// Add `entry`, `entry_lo` and `entry_hi` (the f64 engine only).
    pub time: bool,
    /// Add `intervals`: the spans of inside, near_D and breach_D (docs/cases.md).
    pub intervals: bool,
    /// D ≥ 0, the horizontal separation of near_D and fence_D.
    pub sep: f64,
    /// H ≥ 0, the vertical separation (3D).
    pub sep_v: f64,
    /// Keep-in: add `fence`, `exits` (and `exit_kind` for f64).
    pub fence: Fence,
}

impl Ask {
    /// Paper A's detection by `engine`, nothing more.
    pub fn of(engine: Engine) -> Ask {
        Ask {
            engine,
            time: false,
            intervals: false,
            sep: 0.0,
            sep_v: 0.0,
            fence: Fence::KeepOut,
        }
    }

    /// This ask for a line with its own `sep`, `sep_v` and `fence` (the line's fields win
    /// over the command line's).
    pub fn for_line(self, o: &CaseOptions) -> Ask {
        Ask {
            sep: o.sep.unwrap_or(self.sep),
            sep_v: o.sep_v.unwrap_or(self.sep_v),
            fence: o.fence.unwrap_or(self.fence),
            ..self
        }
    }
}

/// One span as the answer writes it (f64 engine).
fn span_json(s: &Span) -> Value {
    serde_json::json!({
        "start": [s.start.lo, s.start.hi],
        "end": [s.end.lo, s.end.hi],
        "certain": s.certain,
    })
}

/// The f64 engine's `intervals` object: D, H, the spans of each relation, and the
/// enclosure of the time of loss of separation (near_D's first start; null if none).
fn engine_intervals(case: &Case, sep: Separation) -> Value {
    let mut m = Map::new();
    m.insert("sep".into(), sep.d.into());
    m.insert("sep_v".into(), sep.h.into());
    let mut loss = Value::Null;
    for r in [Relation::Inside, Relation::Near, Relation::Breach] {
        let spans = api::intervals(case, r, sep);
        if r == Relation::Near {
            if let Some(s) = spans.first() {
                loss = serde_json::json!([s.start.lo, s.start.hi]);
            }
        }
        m.insert(
            r.name().into(),
            Value::Array(spans.iter().map(span_json).collect()),
        );
    }
    m.insert("loss_of_separation".into(), loss);
    Value::Object(m)
}

/// The next f64 above a finite x.
fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// The f64 nearest the algebraic number a (ties to even): its rigorous f64 enclosure
/// narrowed until it is one float or two neighbours, then the exact comparison with
/// their midpoint.
fn near_f64(a: &RealAlg) -> f64 {
    use polyguard_oracle::convert::q;
    let mut x = a.clone();
    for _ in 0..400 {
        let (lo, hi) = x.to_f64_bounds();
        if lo == hi {
            return lo;
        }
        if next_up(lo) == hi {
            let (Some(l), Some(h), Some(two)) = (q(lo), q(hi), q(2.0)) else {
                break;
            };
            return match x.cmp_rational(&((l + h) / two)) {
                std::cmp::Ordering::Less => lo,
                std::cmp::Ordering::Greater => hi,
                std::cmp::Ordering::Equal if lo.to_bits() % 2 == 0 => lo,
                std::cmp::Ordering::Equal => hi,
            };
        }
        x.refine();
    }
    let (lo, hi) = x.to_f64_bounds();
    lo + 0.5 * (hi - lo)
}

/// One exact end as the answer writes it: the nearest f64 and the exact form.
fn end_json(out: &mut Map<String, Value>, key: &str, a: &RealAlg) {
    out.insert(key.into(), near_f64(a).into());
    out.insert(format!("{key}_exact"), a.exact_text().into());
}

/// The truth engine's `intervals` object: the exact components of each relation, every
/// end as the nearest f64 and exactly, and the exact time of loss of separation.
fn truth_intervals(case: &Case, sep: Separation) -> Result<Value, String> {
    let (exact, lengths) = RawCase::from_api(case)
        .exact_with_lengths::<Exact>(&[sep.d, sep.h])
        .map_err(|e| e.to_string())?;
    let [d, h]: [Exact; 2] = lengths
        .try_into()
        .map_err(|_| "sep: two lengths expected".to_string())?;
    let osep = polyguard_oracle::intervals::Separation { d, h };
    let mut m = Map::new();
    m.insert("sep".into(), sep.d.into());
    m.insert("sep_v".into(), sep.h.into());
    let mut loss = Value::Null;
    for (r, o) in [
        (Relation::Inside, ORelation::Inside),
        (Relation::Near, ORelation::Near),
        (Relation::Breach, ORelation::Breach),
    ] {
        let comps = polyguard_oracle::intervals::intervals_of(&exact, o, &osep)
            .map_err(|e| format!("truth undefined: {e}"))?;
        let list: Vec<Value> = comps
            .iter()
            .map(|(a, b)| {
                let mut c = Map::new();
                end_json(&mut c, "start", a);
                end_json(&mut c, "end", b);
                Value::Object(c)
            })
            .collect();
        if r == Relation::Near {
            if let Some((a, _)) = comps.first() {
                let mut c = Map::new();
                end_json(&mut c, "time", a);
                loss = Value::Object(c);
            }
        }
        m.insert(r.name().into(), Value::Array(list));
    }
    m.insert("loss_of_separation".into(), loss);
    Ok(Value::Object(m))
}

/// `fence`, `exits` and (f64) `exit_kind`: does the point leave the keep-in fence?
fn exit_fields(out: &mut Map<String, Value>, case: &Case, ask: Ask) -> Result<(), String> {
    out.insert("fence".into(), ask.fence.name().into());
    let sep = Separation {
        d: ask.sep,
        h: ask.sep_v,
    };
    match ask.engine {
        Engine::F64 => {
            let d = api::detect_exit(case, sep);
            out.insert("exits".into(), d.detected.into());
            out.insert("exit_kind".into(), d.kind.name().into());
        }
        Engine::Truth => {
            let (exact, lengths) = RawCase::from_api(case)
                .exact_with_lengths::<Exact>(&[sep.d, sep.h])
                .map_err(|e| e.to_string())?;
            let [d, h]: [Exact; 2] = lengths
                .try_into()
                .map_err(|_| "sep: two lengths expected".to_string())?;
            let osep = polyguard_oracle::intervals::Separation { d, h };
            let comps =
                polyguard_oracle::intervals::intervals_of(&exact, ORelation::Breach, &osep)
                    .map_err(|e| format!("truth undefined: {e}"))?;
            out.insert("exits".into(), (!comps.is_empty()).into());
        }
        Engine::Plain | Engine::Exact => {
            return Err(
                "fence: keep_in is answered by the f64 and truth engines (paper A has no exit detection)"
                    .into(),
            )
        }
    }
    Ok(())
}

/// The exact case the oracle reads: the rationals the f64 inputs denote.
fn exact_case(case: &Case) -> Result<polyguard_oracle::ExactCase<Exact>, String> {
    RawCase::from_api(case)
        .exact::<Exact>()
        .map_err(|e| e.to_string())
}

/// `well_formed` and, when false, `well_formed_reason`: which §II.J rule failed.
fn well_formed_fields(out: &mut Map<String, Value>, fault: Option<impl std::fmt::Display>) {
    out.insert("well_formed".into(), fault.is_none().into());
    if let Some(f) = fault {
        out.insert("well_formed_reason".into(), f.to_string().into());
    }
}

/// §II.J decided exactly (the exact and truth engines): κ enters as the f64 cos κ that
/// the f64 engine uses, read as the rational it denotes.
fn exact_well_formed(
    case: &Case,
    exact: &polyguard_oracle::ExactCase<Exact>,
) -> Result<Option<polyguard_oracle::well_formed::Fault>, String> {
    let cos_kappa = polyguard_oracle::convert::f64_to_exact::<Exact>(case.params().cos_kappa())
        .ok_or("kappa: cos κ is not finite")?;
    Ok(polyguard_oracle::well_formed::well_formed_fault(
        &exact.vertices,
        &exact.buff,
        &cos_kappa,
    ))
}

/// `entry`, and `entry_lo`, `entry_hi` unless it is "never": the f64 enclosure of the
/// first-entry time (`--time`).
fn entry_fields(out: &mut Map<String, Value>, e: polyguard::entry::EntryTime) {
    out.insert("entry".into(), e.name().into());
    if let Some((lo, hi)) = e.enclosure() {
        out.insert("entry_lo".into(), lo.into());
        out.insert("entry_hi".into(), hi.into());
    }
}

/// The answer format (docs/cases.md, "Answers") for one valid case, by the chosen engine:
/// the fields after `id`, or the error an answer line then carries.
pub fn answer(case: &Case, ask: Ask, out: &mut Map<String, Value>) -> Result<(), String> {
    match ask.engine {
        Engine::F64 => {
            let d = api::detect(case);
            out.insert("detected".into(), d.detected.into());
            out.insert("kind".into(), d.kind.name().into());
            out.insert("decided_by".into(), d.method.name().into());
            well_formed_fields(out, d.well_formed_fault);
            if ask.time {
                entry_fields(out, api::detect_time(case));
            }
        }
        Engine::Plain => {
            out.insert("detected".into(), api::detected_plain(case).into());
            out.insert("decided_by".into(), case.method().name().into());
            well_formed_fields(out, api::detect(case).well_formed_fault);
        }
        Engine::Exact => {
            let exact = exact_case(case)?;
            let a = polyguard_oracle::paper_detect(&exact);
            out.insert("detected".into(), a.detected.into());
            out.insert("decided_by".into(), a.method.name().into());
            well_formed_fields(out, exact_well_formed(case, &exact)?);
        }
        Engine::Truth => {
            let exact = exact_case(case)?;
            match polyguard_oracle::truth(&exact) {
                polyguard_oracle::Truth::Enters { entry_time } => {
                    out.insert("detected".into(), true.into());
                    out.insert(
                        "entry_time".into(),
                        polyguard_oracle::convert::time_to_f64(&entry_time).into(),
                    );
                    out.insert("entry_time_exact".into(), entry_time.exact_text().into());
                }
                polyguard_oracle::Truth::Misses => {
                    out.insert("detected".into(), false.into());
                }
                polyguard_oracle::Truth::Undefined { reason } => {
                    return Err(format!("truth undefined: {reason}"));
                }
            }
            out.insert("decided_by".into(), "truth".into());
            well_formed_fields(out, exact_well_formed(case, &exact)?);
        }
    }
    let sep = Separation {
        d: ask.sep,
        h: ask.sep_v,
    };
    if ask.intervals {
        match ask.engine {
            Engine::F64 => {
                out.insert("intervals".into(), engine_intervals(case, sep));
            }
            Engine::Truth => {
                out.insert("intervals".into(), truth_intervals(case, sep)?);
            }
            Engine::Plain | Engine::Exact => return Err(
                "--intervals is answered by the f64 and truth engines (paper A has no intervals)"
                    .into(),
            ),
        }
    }
    if ask.fence == Fence::KeepIn {
        exit_fields(out, case, ask)?;
    }
    Ok(())
}
