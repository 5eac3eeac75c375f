//! The Python package `polyguard` (its native part, `polyguard._native`): paper A's
//! certified detection (Narkawicz & Hagen), its entry time and exact truth, paper A on
//! many pairs from numpy arrays, and paper B's conflicts (Bienkowski et al.).
//!
//! - [`single`]: `detect`, `detect_time`, `truth` on one case, given as arguments or as a
//!   case object of docs/cases.md.
//! - [`batch`]: `detect_batch` on numpy arrays.
//! - [`intervals`]: `intervals` (the certified spans of inside, near_D and breach_D) and
//!   `detect_exit` (keep-in exits) on a case object (docs/cases.md, "Separation and
//!   fences").
//! - [`earth`]: `conflicts` on a scenario GeoJSON (docs/scenario.md).
//! - [`moving`]: `encounters` of whole flights with areas (docs/moving-features.md).
//! - [`wayout`]: the way out: `course_bands`, `speed_bands`, `vertical_speed_bands`,
//!   `recover`, `offset`, `inset` (certified bands, recovery points and offsets).
//!
//! Bad input raises `polyguard.CaseError` (or `polyguard.ScenarioError`), a `ValueError`
//! whose `field` names the field as the case format spells it.
#![deny(missing_docs)]

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pub mod args;
pub mod batch;
pub mod earth;
pub mod intervals;
pub mod moving;
pub mod single;
pub mod wayout;

create_exception!(
    polyguard,
    Error,
    PyValueError,
    "Bad input to polyguard: `field` names what is wrong (a path such as \
     `polygon.vertices[2][1]`), the message says why."
);
create_exception!(
    polyguard,
    CaseError,
    Error,
    "A detection case (paper A) that breaks a rule of docs/cases.md: `field` is the \
     case format's path of the field (`lookahead`, `point.pos`, `polygon.vertices[2][1]`, \
     or `polygons[7].vertices` in a batch)."
);
create_exception!(
    polyguard,
    ScenarioError,
    Error,
    "A scenario GeoJSON (paper B) that cannot be read at all: `field` names the member, \
     `line` the 1-based line when known (None otherwise)."
);

/// `polyguard.Error` (a ValueError) whose `field` is `field`, for bad input that is not
/// a field of a case (an option such as `relation`); `message` starts with the field.
pub fn error(py: Python<'_>, field: &str, message: &str) -> PyErr {
    let err = Error::new_err(message.to_string());
    // As in `case_error`: setting the attribute cannot fail but for memory.
    let _ = err.value(py).setattr("field", field);
    err
}

/// The Python exception for an engine error (paper A's input rules, docs/cases.md): a
/// [`CaseError`] whose `field` is `field` and whose message is `message` (which starts
/// with the field, as the CLI's error lines do).
pub fn case_error(py: Python<'_>, field: &str, message: &str) -> PyErr {
    let err = CaseError::new_err(message.to_string());
    // Setting an attribute on a fresh exception instance cannot fail but for memory; the
    // message is raised either way.
    let _ = err.value(py).setattr("field", field);
    err
}

/// [`case_error`] for an engine [`polyguard::error::CaseError`] (docs/cases.md's rules),
/// its field renamed by `rename` (a batch prefixes the item: `polygons[7].vertices`).
pub fn engine_error(
    py: Python<'_>,
    e: &polyguard::error::CaseError,
    rename: impl Fn(&str) -> String,
) -> PyErr {
    let field = e.field();
    let text = e.to_string();
    let rest = text
        .strip_prefix(&format!("{field}: "))
        .unwrap_or(text.as_str());
    let new_field = rename(&field);
    case_error(py, &new_field, &format!("{new_field}: {rest}"))
}

/// The native module (extends paper A and paper B's Rust API to Python).
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("Error", py.get_type::<Error>())?;
    m.add("CaseError", py.get_type::<CaseError>())?;
    m.add("ScenarioError", py.get_type::<ScenarioError>())?;
    m.add("KIND_EXACT", batch::KIND_EXACT)?;
    m.add("KIND_CONSERVATIVE", batch::KIND_CONSERVATIVE)?;
    m.add_class::<single::Detection>()?;
    m.add_class::<single::EntryTime>()?;
    m.add_class::<single::Truth>()?;
    m.add_function(wrap_pyfunction!(single::detect, m)?)?;
    m.add_function(wrap_pyfunction!(single::detect_case, m)?)?;
    m.add_function(wrap_pyfunction!(single::detect_time, m)?)?;
    m.add_function(wrap_pyfunction!(single::detect_time_case, m)?)?;
    m.add_function(wrap_pyfunction!(single::truth, m)?)?;
    m.add_function(wrap_pyfunction!(single::truth_case, m)?)?;
    m.add_function(wrap_pyfunction!(intervals::intervals, m)?)?;
    m.add_function(wrap_pyfunction!(intervals::detect_exit, m)?)?;
    m.add_function(wrap_pyfunction!(batch::detect_batch, m)?)?;
    m.add_function(wrap_pyfunction!(earth::conflicts, m)?)?;
    m.add_function(wrap_pyfunction!(moving::_encounters_json, m)?)?;
    m.add_function(wrap_pyfunction!(moving::_encounters_columns, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::course_bands, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::speed_bands, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::vertical_speed_bands, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::recover, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::offset, m)?)?;
    m.add_function(wrap_pyfunction!(wayout::inset, m)?)?;
    Ok(())
}
