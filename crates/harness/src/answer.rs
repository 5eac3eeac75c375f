//! The answer format of `polyguard detect` (docs/cases.md, "Answers"): one valid case
//! answered by the certified f64 engine (paper A §II.F–§III), the plain transcription,
//! paper A in exact arithmetic, or the exact truth, as the JSON fields after `id`.

use serde_json::{Map, Value};

use polyguard::api::{self, Case};

use crate::case::RawCase;
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

/// The engine asked for, and whether the f64 entry-time enclosure was (`detect --time`).
#[derive(Clone, Copy, Debug)]
pub struct Ask {
    /// The engine.
    pub engine: Engine,
    /// Add `entry`, `entry_lo` and `entry_hi` (the f64 engine only).
    pub time: bool,
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
    Ok(())
}
