//! One case at a time: `detect` (paper A §II.H, §II.I, §III), `detect_time` (the f64
//! enclosure of the first-entry time) and `truth` (the exact oracle), each given the
//! case as arguments or, in their `*_case` forms, as a case object of docs/cases.md.

use polyguard::api::{self, Case};
use polyguard::entry::EntryTime as EngineEntry;
use polyguard_harness::case::RawCase;
use polyguard_harness::classify::Exact;
use pyo3::prelude::*;

use crate::args::{case_from_object, CaseArgs};

/// The answer of `detect` (paper A §II.F's dispatch, §II.J's well-formedness), the
/// fields of a `polyguard detect` answer line.
#[pyclass(frozen, get_all, eq, module = "polyguard")]
#[derive(Clone, Debug, PartialEq)]
pub struct Detection {
    /// The point comes within BUFF (or F's slack) of the polygon within [0, T], or a
    /// comparison on the way could not be decided in f64 (then `kind` is "conservative").
    pub detected: bool,
    /// "exact" (every comparison certified: paper A without rounding answers the same)
    /// or "conservative" (a yes taken on an undecided comparison; never a no).
    pub kind: &'static str,
    /// "detect_same_2d", "detect_diff_2d" or "detect_3d": which paper function decided.
    pub decided_by: &'static str,
    /// §II.J at t = 0, for information: a polygon that is not well formed is still
    /// checked, never answered no for that reason.
    pub well_formed: bool,
    /// Which §II.J rule fails when `well_formed` is false, else None.
    pub well_formed_reason: Option<String>,
}

#[pymethods]
impl Detection {
    /// The answer as `polyguard detect` writes it after `id` (docs/cases.md):
    /// `well_formed_reason` only when `well_formed` is false.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
        let d = pyo3::types::PyDict::new(py);
        d.set_item("detected", self.detected)?;
        d.set_item("kind", self.kind)?;
        d.set_item("decided_by", self.decided_by)?;
        d.set_item("well_formed", self.well_formed)?;
        if let Some(r) = &self.well_formed_reason {
            d.set_item("well_formed_reason", r)?;
        }
        Ok(d)
    }

    /// `bool(detection)` is `detection.detected` (paper A's answer).
    fn __bool__(&self) -> bool {
        self.detected
    }

    /// The Python repr of paper A's answer.
    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Detection(detected={}, kind={}, decided_by={}, well_formed={}{})",
            py_bool(self.detected),
            py_str(py, self.kind),
            py_str(py, self.decided_by),
            py_bool(self.well_formed),
            self.well_formed_reason
                .as_ref()
                .map_or(String::new(), |r| format!(
                    ", well_formed_reason={}",
                    py_str(py, r)
                ))
        )
    }
}

/// Python's repr of a str (quotes and escapes as Python writes them), for the reprs of
/// paper A's answers.
fn py_str(py: Python<'_>, s: &str) -> String {
    pyo3::types::PyString::new(py, s)
        .repr()
        .map_or_else(|_| format!("{s:?}"), |r| r.to_string())
}

/// Python's spelling of a bool, for the reprs of paper A's answers.
fn py_bool(b: bool) -> &'static str {
    if b {
        "True"
    } else {
        "False"
    }
}

/// The answer of `detect_time`: where the exact first-entry time t* lies (paper A
/// §II–III's "the point enters", timed; see the engine's `entry` module).
#[pyclass(frozen, get_all, eq, module = "polyguard")]
#[derive(Clone, Debug, PartialEq)]
pub struct EntryTime {
    /// "never" (certified: never in the closed polygon and slab on [0, T]), "enters"
    /// (certified: it enters, t* in [lo, hi]) or "possible" (not certified either way: no
    /// entry before lo; if it enters, t* in [lo, hi], hi = T).
    pub kind: &'static str,
    /// No entry before lo (None for "never").
    pub lo: Option<f64>,
    /// "enters": in the closed polygon at some time <= hi; "possible": T (None for "never").
    pub hi: Option<f64>,
}

#[pymethods]
impl EntryTime {
    /// `kind, lo, hi = detect_time(...)` unpacks it (the enclosure of paper A's entry time).
    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyIterator>> {
        (self.kind, self.lo, self.hi)
            .into_pyobject(py)?
            .into_any()
            .try_iter()
    }

    /// The Python repr of the entry-time enclosure (paper A §II–III, timed).
    fn __repr__(&self, py: Python<'_>) -> String {
        let f = |x: Option<f64>| x.map_or("None".to_string(), |v| format!("{v:?}"));
        format!(
            "EntryTime(kind={}, lo={}, hi={})",
            py_str(py, self.kind),
            f(self.lo),
            f(self.hi)
        )
    }
}

impl From<EngineEntry> for EntryTime {
    /// The engine's enclosure of the first-entry time (paper A §II–III, timed), for Python.
    fn from(e: EngineEntry) -> Self {
        let (lo, hi) = e.enclosure().unzip();
        EntryTime {
            kind: e.name(),
            lo,
            hi,
        }
    }
}

/// The exact first-entry time of the point into the closed polygon (and slab), from the
/// oracle (paper A's ground truth: what the PVS theorem says detection must flag).
#[pyclass(frozen, get_all, eq, module = "polyguard")]
#[derive(Clone, Debug, PartialEq)]
pub struct Truth {
    /// The f64 nearest to the exact time.
    pub entry_time: f64,
    /// The exact time: a rational `p/q`, or `a + (b)·√(d)`.
    pub entry_time_exact: String,
}

#[pymethods]
impl Truth {
    /// The Python repr of the oracle's exact entry time.
    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Truth(entry_time={:?}, entry_time_exact={})",
            self.entry_time,
            py_str(py, &self.entry_time_exact)
        )
    }
}

/// Paper A end to end on a validated case (§II.F's dispatch to detect_same_2D,
/// detect_diff_2D or detect_3D, and §II.J's well-formedness), as `polyguard detect`
/// answers it.
pub fn detection(case: &Case) -> Detection {
    let d = api::detect(case);
    Detection {
        detected: d.detected,
        kind: d.kind.name(),
        decided_by: d.method.name(),
        well_formed: d.well_formed,
        well_formed_reason: d.well_formed_fault.map(|f| f.to_string()),
    }
}

/// Polygons of at least this many vertices are answered without the GIL: their time
/// (tens of µs and up) is worth the hand-over (well under a µs); a small one is answered
/// faster holding it.
pub const GIL_FREE_VERTICES: usize = 64;

/// `answer(case)` (paper A's detection or entry time), without the GIL for a polygon of
/// [`GIL_FREE_VERTICES`] or more.
pub(crate) fn detect_large_without_gil<T: Send>(
    py: Python<'_>,
    case: &Case,
    answer: impl Fn(&Case) -> T + Send + Sync,
) -> T {
    if case.polygon().vertices().len() >= GIL_FREE_VERTICES {
        py.detach(|| answer(case))
    } else {
        answer(case)
    }
}

/// The oracle's exact truth on a validated case (paper A's ground truth), without the
/// GIL: `None` when the point never enters.
fn exact_truth(py: Python<'_>, case: Case) -> PyResult<Option<Truth>> {
    let answer = py.detach(move || {
        let exact = RawCase::from_api(&case)
            .exact::<Exact>()
            .map_err(|e| ("case".to_string(), e.to_string()))?;
        match polyguard_oracle::truth(&exact) {
            polyguard_oracle::Truth::Enters { entry_time } => Ok(Some(Truth {
                entry_time: polyguard_oracle::convert::time_to_f64(&entry_time),
                entry_time_exact: entry_time.exact_text(),
            })),
            polyguard_oracle::Truth::Misses => Ok(None),
            polyguard_oracle::Truth::Undefined { reason } => Err((
                "polygon.vertices".to_string(),
                format!("polygon.vertices: truth undefined: {reason}"),
            )),
        }
    });
    answer.map_err(|(field, message)| crate::case_error(py, &field, &message))
}

/// The case from `detect`'s arguments (docs/cases.md's fields), or the CaseError.
#[allow(clippy::too_many_arguments)]
fn case_of<'py>(
    py: Python<'py>,
    lookahead: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    vertices: &Bound<'py, PyAny>,
    velocities: Option<&Bound<'py, PyAny>>,
    buff: &Bound<'py, PyAny>,
    fac: Option<&Bound<'py, PyAny>>,
    kappa_deg: Option<&Bound<'py, PyAny>>,
    slab: [Option<&Bound<'py, PyAny>>; 3],
) -> PyResult<Case> {
    CaseArgs {
        lookahead,
        pos,
        vel,
        vertices,
        velocities,
        buff,
        fac,
        kappa_deg,
        slab,
    }
    .case()
    .map_err(|e| crate::engine_error(py, &e, str::to_owned))
}

/// Does the point s + t·v come within BUFF of the polygon P + t·V for some t in
/// [0, lookahead]? Paper A: detect_same_2D (§II.H) when all vertex velocities are equal,
/// detect_diff_2D (§II.I) otherwise, detect_3D (§III) when the point has a height
/// (`pos`, `vel` of 3 numbers) and the polygon a slab (`bottom`, `top`, `vz`). Every
/// comparison is certified: a "no" is always paper A's exact "no". Polygons of 64
/// vertices or more are answered without the GIL.
///
/// Raises CaseError (a ValueError) naming the field, e.g. `polygon.vertices[2][1]`.
#[pyfunction]
#[pyo3(signature = (lookahead, pos, vel, vertices, velocities=None, *, buff, fac=None,
    kappa_deg=None, bottom=None, top=None, vz=None),
    text_signature = "(lookahead, pos, vel, vertices, velocities=None, *, buff, fac=0.0001, \
    kappa_deg=5.0, bottom=None, top=None, vz=None)")]
#[allow(clippy::too_many_arguments)]
pub fn detect<'py>(
    py: Python<'py>,
    lookahead: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    vertices: &Bound<'py, PyAny>,
    velocities: Option<&Bound<'py, PyAny>>,
    buff: &Bound<'py, PyAny>,
    fac: Option<&Bound<'py, PyAny>>,
    kappa_deg: Option<&Bound<'py, PyAny>>,
    bottom: Option<&Bound<'py, PyAny>>,
    top: Option<&Bound<'py, PyAny>>,
    vz: Option<&Bound<'py, PyAny>>,
) -> PyResult<Detection> {
    let case = case_of(
        py,
        lookahead,
        pos,
        vel,
        vertices,
        velocities,
        buff,
        fac,
        kappa_deg,
        [bottom, top, vz],
    )?;
    Ok(detect_large_without_gil(py, &case, detection))
}

/// `detect` on a case object of docs/cases.md (a dict, or one JSON line as a str), read
/// by the case format's own reader: unknown keys are errors (paper A §II.H, §II.I, §III).
/// A dict is written by `json.dumps` first: its values must be JSON-serialisable (lists,
/// not numpy arrays; a TypeError otherwise).
#[pyfunction]
pub fn detect_case(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<Detection> {
    let case = case_from_object(py, case)?;
    Ok(detect_large_without_gil(py, &case, detection))
}

/// When the point first enters the closed polygon (and slab), enclosed in f64: kind
/// "never", "enters" (t* in [lo, hi]) or "possible" (undecided in f64; no entry before
/// lo). No BUFF: the time the exact truth computes, which paper A's detection (§II–III)
/// is guaranteed to flag. `buff`, `fac` and `kappa_deg` are validated as for `detect`.
#[pyfunction]
#[pyo3(signature = (lookahead, pos, vel, vertices, velocities=None, *, buff, fac=None,
    kappa_deg=None, bottom=None, top=None, vz=None),
    text_signature = "(lookahead, pos, vel, vertices, velocities=None, *, buff, fac=0.0001, \
    kappa_deg=5.0, bottom=None, top=None, vz=None)")]
#[allow(clippy::too_many_arguments)]
pub fn detect_time<'py>(
    py: Python<'py>,
    lookahead: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    vertices: &Bound<'py, PyAny>,
    velocities: Option<&Bound<'py, PyAny>>,
    buff: &Bound<'py, PyAny>,
    fac: Option<&Bound<'py, PyAny>>,
    kappa_deg: Option<&Bound<'py, PyAny>>,
    bottom: Option<&Bound<'py, PyAny>>,
    top: Option<&Bound<'py, PyAny>>,
    vz: Option<&Bound<'py, PyAny>>,
) -> PyResult<EntryTime> {
    let case = case_of(
        py,
        lookahead,
        pos,
        vel,
        vertices,
        velocities,
        buff,
        fac,
        kappa_deg,
        [bottom, top, vz],
    )?;
    Ok(detect_large_without_gil(py, &case, |c| {
        api::detect_time(c).into()
    }))
}

/// `detect_time` on a case object of docs/cases.md (paper A §II–III's entry, timed).
#[pyfunction]
pub fn detect_time_case(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<EntryTime> {
    let case = case_from_object(py, case)?;
    Ok(detect_large_without_gil(py, &case, |c| {
        api::detect_time(c).into()
    }))
}

/// The exact ground truth (the oracle, in rational arithmetic): the exact time the
/// point first enters the closed polygon (and slab) within [0, lookahead], or None when
/// it never does. What paper A's theorem (§II–III) says detection must flag. Runs
/// without the GIL; it can take milliseconds on large polygons.
#[pyfunction]
#[pyo3(signature = (lookahead, pos, vel, vertices, velocities=None, *, buff, fac=None,
    kappa_deg=None, bottom=None, top=None, vz=None),
    text_signature = "(lookahead, pos, vel, vertices, velocities=None, *, buff, fac=0.0001, \
    kappa_deg=5.0, bottom=None, top=None, vz=None)")]
#[allow(clippy::too_many_arguments)]
pub fn truth<'py>(
    py: Python<'py>,
    lookahead: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    vertices: &Bound<'py, PyAny>,
    velocities: Option<&Bound<'py, PyAny>>,
    buff: &Bound<'py, PyAny>,
    fac: Option<&Bound<'py, PyAny>>,
    kappa_deg: Option<&Bound<'py, PyAny>>,
    bottom: Option<&Bound<'py, PyAny>>,
    top: Option<&Bound<'py, PyAny>>,
    vz: Option<&Bound<'py, PyAny>>,
) -> PyResult<Option<Truth>> {
    let case = case_of(
        py,
        lookahead,
        pos,
        vel,
        vertices,
        velocities,
        buff,
        fac,
        kappa_deg,
        [bottom, top, vz],
    )?;
    exact_truth(py, case)
}

/// `truth` on a case object of docs/cases.md (paper A's exact ground truth).
#[pyfunction]
pub fn truth_case(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<Option<Truth>> {
    let case = case_from_object(py, case)?;
    exact_truth(py, case)
}
