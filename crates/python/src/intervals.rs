//! Every time a relation holds, and keep-in exits (docs/cases.md, "Separation and
//! fences"; paper A §II–§III's motion, timed): `intervals` gives the engine's certified
//! spans of inside, near_D and breach_D, `detect_exit` whether the point leaves a
//! keep-in fence. Both take a case object of docs/cases.md, as `detect_case` does, and
//! answer as `polyguard detect --intervals` and `--fence keep-in` do.

use polyguard::api::{self, Case};
use polyguard::{Relation, Separation, Span};
use polyguard_harness::case::CaseOptions;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::args::{case_and_options, number};
use crate::single::detect_large_without_gil;

/// The separations D and H of one call: the case's own `sep` and `sep_v` where it gives
/// them, else the arguments, as `polyguard detect` takes a line's fields over its
/// `--sep` and `--sep-v` (the definitions of near_D and fence_D: finite and ≥ 0). The
/// arguments are checked either way, each error naming `sep` or `sep_v`.
fn separation(
    py: Python<'_>,
    sep: Option<&Bound<'_, PyAny>>,
    sep_v: Option<&Bound<'_, PyAny>>,
    own: &CaseOptions,
) -> PyResult<Separation> {
    let read = |x: Option<&Bound<'_, PyAny>>, field: &str| match x {
        None => Ok(0.0),
        Some(x) => number(x, field),
    };
    let given = read(sep, "sep")
        .and_then(|d| Ok((d, read(sep_v, "sep_v")?)))
        .and_then(|(d, h)| Separation::new(d, h))
        .map_err(|e| crate::engine_error(py, &e, str::to_owned))?;
    Separation::new(own.sep.unwrap_or(given.d), own.sep_v.unwrap_or(given.h))
        .map_err(|e| crate::engine_error(py, &e, str::to_owned))
}

/// `intervals`' `relation`: one of the sets of docs/cases.md's definitions by its name,
/// or all three (Python's None).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    /// "inside", "near" or "breach".
    One(Relation),
    /// None: the three, as the CLI's `intervals` object.
    All,
}

impl<'a, 'py> FromPyObject<'a, 'py> for Which {
    type Error = PyErr;

    /// The relation of a name: "inside", "near" or "breach", or None for all three;
    /// anything else is `polyguard.Error` naming `relation` (docs/cases.md's definitions).
    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if obj.is_none() {
            return Ok(Which::All);
        }
        let name = obj.cast::<PyString>().ok().map(|s| s.to_string());
        let found = name
            .as_deref()
            .and_then(|n| Relation::ALL.into_iter().find(|r| r.name() == n));
        match found {
            Some(r) => Ok(Which::One(r)),
            None => {
                let shown = obj
                    .repr()
                    .map_or_else(|_| "the value".to_string(), |r| r.to_string());
                Err(crate::error(
                    obj.py(),
                    "relation",
                    &format!(
                        "relation: {shown} is not \"inside\", \"near\", \"breach\" \
                         (or None for all three)"
                    ),
                ))
            }
        }
    }
}

/// One span as Python sees it: `{"start": (lo, hi), "end": (lo, hi), "certain": bool}`
/// (the enclosures of the ends of a component of the relation's set, src/intervals.rs).
fn span_dict<'py>(py: Python<'py>, s: &Span) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("start", (s.start.lo, s.start.hi))?;
    d.set_item("end", (s.end.lo, s.end.hi))?;
    d.set_item("certain", s.certain)?;
    Ok(d)
}

/// A list of spans as Python's list of dicts (see [`span_dict`]).
fn span_list<'py>(py: Python<'py>, spans: &[Span]) -> PyResult<Bound<'py, PyList>> {
    let items = spans
        .iter()
        .map(|s| span_dict(py, s))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, items)
}

/// The spans of the relations asked for, computed without the GIL for a polygon of 64
/// vertices or more (the engine's `api::intervals`).
fn spans_of(
    py: Python<'_>,
    case: &Case,
    relations: &[Relation],
    sep: Separation,
) -> Vec<Vec<Span>> {
    detect_large_without_gil(py, case, |c| {
        relations
            .iter()
            .map(|&r| api::intervals(c, r, sep))
            .collect()
    })
}

/// Every time during [0, lookahead] that the relation holds, as certified spans (the
/// engine's; `polyguard detect --intervals` gives the same numbers): "inside" (in the
/// closed polygon and slab), "near" (within `sep` of the polygon, and `sep_v` of the
/// slab: the first span's start is the loss of separation) or "breach" (not deeper than
/// `sep` inside a keep-in fence, or than `sep_v` inside its slab). Definitions:
/// docs/cases.md, "Separation and fences".
///
/// `case` is a case object of docs/cases.md (a dict, or one JSON line), as for
/// `detect_case`. Its own `sep` and `sep_v` win over the arguments, as a line's do over
/// `polyguard detect --sep --sep-v`. Returns a list of spans `{"start": (lo, hi),
/// "end": (lo, hi), "certain": bool}`, sorted: nothing is missed (the set lies within
/// the spans' `[start[0], end[1]]`), every end of the set lies in a span's start or
/// end, and a certain span holds throughout `[start[1], end[0]]`; a possible one
/// (certain False) is a stretch f64 could not settle. With `relation=None`, a dict of the three
/// lists keyed "inside", "near", "breach", with "loss_of_separation" (near's first
/// start, or None) and the "sep" and "sep_v" used: the CLI's `intervals` object.
///
/// Raises CaseError naming the field (`sep`, `polygon.vertices[2][1]`), or Error naming
/// `relation`.
#[pyfunction]
#[pyo3(signature = (case, relation=Which::One(Relation::Near), sep=None, sep_v=None),
    text_signature = "(case, relation='near', sep=0.0, sep_v=0.0)")]
pub fn intervals<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    relation: Which,
    sep: Option<&Bound<'py, PyAny>>,
    sep_v: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (case, own) = case_and_options(py, case)?;
    let sep = separation(py, sep, sep_v, &own)?;
    match relation {
        Which::One(r) => {
            let spans = spans_of(py, &case, &[r], sep);
            Ok(span_list(py, spans.first().map_or(&[][..], Vec::as_slice))?.into_any())
        }
        Which::All => {
            let all = spans_of(py, &case, &Relation::ALL, sep);
            let d = PyDict::new(py);
            for (r, spans) in Relation::ALL.iter().zip(&all) {
                d.set_item(r.name(), span_list(py, spans)?)?;
            }
            let near = Relation::ALL.iter().position(|&r| r == Relation::Near);
            let loss = near
                .and_then(|k| all.get(k))
                .and_then(|spans| spans.first())
                .map(|s| (s.start.lo, s.start.hi));
            d.set_item("loss_of_separation", loss)?;
            d.set_item("sep", sep.d)?;
            d.set_item("sep_v", sep.h)?;
            Ok(d.into_any())
        }
    }
}

/// Keep-in exit detection: does the point leave the polygon taken as a keep-in fence,
/// that is, does breach_D hold at some time in [0, lookahead] (it comes within `sep` of
/// the polygon's boundary or is outside, or within `sep_v` of the slab's floor or
/// ceiling)? The engine's `api::detect_exit`, as `polyguard detect --fence keep-in`
/// answers `exits` and `exit_kind`: never False when the point leaves.
///
/// `case` is a case object of docs/cases.md (its `fence`, if any, is not consulted); its
/// own `sep` and `sep_v` win over the arguments, as in `intervals`. Returns
/// `{"exits": bool, "kind": "exact" | "conservative"}` ("conservative": a True f64 could
/// not certify). Raises CaseError naming the field.
#[pyfunction]
#[pyo3(signature = (case, sep=None, sep_v=None),
    text_signature = "(case, sep=0.0, sep_v=0.0)")]
pub fn detect_exit<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    sep: Option<&Bound<'py, PyAny>>,
    sep_v: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (case, own) = case_and_options(py, case)?;
    let sep = separation(py, sep, sep_v, &own)?;
    let d = detect_large_without_gil(py, &case, |c| api::detect_exit(c, sep));
    let out = PyDict::new(py);
    out.set_item("exits", d.detected)?;
    out.set_item("kind", d.kind.name())?;
    Ok(out)
}
