//! `conflicts`: paper B's Algorithm 1 (the four stages, §IV) on a scenario GeoJSON
//! (docs/scenario.md), answering what `polyguard conflicts` writes.

use polyguard_earth::analysis::analyse_into;
use polyguard_earth::geodesy::Geodesy;
use pyo3::prelude::*;

use crate::ScenarioError;

/// A [`ScenarioError`] with `field`, `line` (None when unknown) and the message: a
/// scenario of docs/scenario.md (paper B's input) that cannot be read.
fn scenario_error(py: Python<'_>, field: &str, line: Option<usize>, message: &str) -> PyErr {
    let err = ScenarioError::new_err(message.to_string());
    let v = err.value(py);
    let _ = v.setattr("field", field);
    let _ = v.setattr("line", line);
    err
}

/// Which areas and tracks of a scenario conflict, and when: paper B's four stages
/// (§IV.A bounding boxes, §IV.B swept regions, §IV.C projection onto the tracks, §IV.D
/// times of intersection) on a scenario GeoJSON text (docs/scenario.md). Returns the
/// answer object of `polyguard conflicts` (docs/scenario.md, docs/schema/): `conflicts`,
/// `stats`, and the rejected features under `errors` (a bad feature does not stop the
/// others), unread members under `warnings`.
///
/// - geodesy: "sphere" (the paper's) or "wgs84" (rhumb lines on the ellipsoid).
/// - tolerance_s: stage 4's time tolerance in seconds (> 0).
/// - regions: False leaves the conflict regions and projection windows out.
///
/// Raises ScenarioError (a ValueError, with `field` and `line`) when the text cannot be
/// read at all (not JSON, not a FeatureCollection) or an option is out of range.
/// Runs without the GIL.
#[pyfunction]
#[pyo3(signature = (geojson, geodesy="sphere", *, tolerance_s=1.0, regions=true))]
pub fn conflicts<'py>(
    py: Python<'py>,
    geojson: String,
    geodesy: &str,
    tolerance_s: f64,
    regions: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let geodesy = match geodesy {
        "sphere" => Geodesy::Sphere,
        "wgs84" => Geodesy::Wgs84,
        other => {
            return Err(scenario_error(
                py,
                "geodesy",
                None,
                &format!("geodesy: {other:?}, \"sphere\" or \"wgs84\" expected"),
            ))
        }
    };
    if !(tolerance_s.is_finite() && tolerance_s > 0.0) {
        return Err(scenario_error(
            py,
            "tolerance_s",
            None,
            &format!("tolerance_s: {tolerance_s}, a positive number of seconds expected"),
        ));
    }
    let answer = py.detach(move || {
        let mut out = Vec::new();
        analyse_into(
            geojson,
            tolerance_s / 3600.0,
            regions,
            geodesy,
            &mut out,
            &mut (),
        )
        .map(|written| written.map(|_| out))
    });
    let text = match answer {
        Ok(Ok(bytes)) => bytes,
        // writing into memory does not fail but for memory
        Ok(Err(e)) => return Err(pyo3::exceptions::PyMemoryError::new_err(e.to_string())),
        Err(e) => {
            return Err(scenario_error(py, &e.field, e.line, &e.to_string()));
        }
    };
    let text = String::from_utf8(text)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}
