//! Reading a case's fields from Python values (the case format of docs/cases.md, whose
//! fields are paper A §II's T, BUFF, F, s, v, P, V and §III's slab; not a paper function).
//!
//! Every failure is a [`polyguard::error::CaseError`] naming the field as the case format
//! spells it (`polygon.vertices[2]`), so that Python sees the same field names and
//! messages as `polyguard detect`.

use numpy::{PyArrayDyn, PyArrayMethods};
use polyguard::api::{Case, Params};
use polyguard::error::CaseError;
use polyguard_harness::case::{CaseOptions, RawCase};
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyList, PyString, PyTuple};

/// A number for `field` (docs/cases.md's number fields): a Python float or int, or
/// anything with `__float__` (a numpy scalar). Not finiteness: the engine checks that,
/// naming the field down to the coordinate.
pub fn number(obj: &Bound<'_, PyAny>, field: &str) -> Result<f64, CaseError> {
    to_f64(obj).ok_or_else(|| CaseError::WrongType {
        field: field.into(),
        expected: "a number",
    })
}

/// The value of a Python number (a float first, without a lookup), or `None` for a str
/// or anything without `__float__` (the case format's numbers, docs/cases.md, from Python).
fn to_f64(obj: &Bound<'_, PyAny>) -> Option<f64> {
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Some(f.value());
    }
    if obj.is_instance_of::<PyString>() {
        return None;
    }
    obj.extract::<f64>().ok()
}

/// A list of numbers for `field` (a point's `pos` or `vel`: paper A §II's s and v): any iterable of numbers but a
/// string (a list, a tuple, a 1-D numpy array).
pub fn numbers(obj: &Bound<'_, PyAny>, field: &str) -> Result<Vec<f64>, CaseError> {
    numbers_named(obj, &|| field.to_string())
}

/// [`numbers`] with the field's name made only when there is an error (the names of
/// vertices are not built for every vertex read; docs/cases.md's field paths).
fn numbers_named(
    obj: &Bound<'_, PyAny>,
    field: &dyn Fn() -> String,
) -> Result<Vec<f64>, CaseError> {
    let item = |k: usize, x: &Bound<'_, PyAny>| {
        to_f64(x).ok_or_else(|| CaseError::WrongType {
            field: format!("{}[{k}]", field()),
            expected: "a number",
        })
    };
    // Lists and tuples by index (the common case, without an iterator object).
    if let Ok(list) = obj.cast::<PyList>() {
        return list.iter().enumerate().map(|(k, x)| item(k, &x)).collect();
    }
    if let Ok(tuple) = obj.cast::<PyTuple>() {
        return tuple.iter().enumerate().map(|(k, x)| item(k, &x)).collect();
    }
    let wrong = || CaseError::WrongType {
        field: field(),
        expected: "a list of numbers",
    };
    if obj.is_instance_of::<PyString>() {
        return Err(wrong());
    }
    // A 1-D float64 array is read in place.
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        if let Ok(ro) = a.try_readonly() {
            let v = ro.as_array();
            if v.ndim() == 1 {
                return Ok(v.iter().copied().collect());
            }
        }
    }
    let mut out = Vec::new();
    for (k, x) in obj.try_iter().map_err(|_| wrong())?.enumerate() {
        out.push(item(k, &x.map_err(|_| wrong())?)?);
    }
    Ok(out)
}

/// A list of points [x, y] for `field` (a polygon's `vertices` or `velocities`: paper A
/// §II's P and V): an
/// iterable of pairs (a list of lists, an (n, 2) numpy array).
pub fn pairs(obj: &Bound<'_, PyAny>, field: &str) -> Result<Vec<[f64; 2]>, CaseError> {
    let wrong = || CaseError::WrongType {
        field: field.into(),
        expected: "a list of [x, y] points",
    };
    if obj.is_instance_of::<PyString>() {
        return Err(wrong());
    }
    // An (n, 2) float64 array is read in place (any strides), not element by element.
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        if let Ok(ro) = a.try_readonly() {
            let v = ro.as_array();
            if v.ndim() == 2 && v.shape()[1] == 2 {
                return Ok(v.outer_iter().map(|r| [r[0], r[1]]).collect());
            }
        }
    }
    let mut out = Vec::new();
    let mut push = |i: usize, item: &Bound<'_, PyAny>| {
        let name = || format!("{field}[{i}]");
        let xy = numbers_named(item, &name)?;
        if xy.len() != 2 {
            return Err(CaseError::WrongLength {
                field: name(),
                expected: 2,
                found: xy.len(),
                what: "numbers (a point is [x, y])",
            });
        }
        out.push([xy[0], xy[1]]);
        Ok(())
    };
    if let Ok(list) = obj.cast::<PyList>() {
        for (i, item) in list.iter().enumerate() {
            push(i, &item)?;
        }
    } else {
        for (i, item) in obj.try_iter().map_err(|_| wrong())?.enumerate() {
            push(i, &item.map_err(|_| wrong())?)?;
        }
    }
    Ok(out)
}

/// The arguments of `detect`, `detect_time` and `truth`, as Python gave them.
pub struct CaseArgs<'a, 'py> {
    /// T.
    pub lookahead: &'a Bound<'py, PyAny>,
    /// s (2 numbers, 3 with the height).
    pub pos: &'a Bound<'py, PyAny>,
    /// v (as many as s).
    pub vel: &'a Bound<'py, PyAny>,
    /// P.
    pub vertices: &'a Bound<'py, PyAny>,
    /// V, or none: the polygon at rest.
    pub velocities: Option<&'a Bound<'py, PyAny>>,
    /// BUFF.
    pub buff: &'a Bound<'py, PyAny>,
    /// F (none: the default 10⁻⁴, §II.I's example).
    pub fac: Option<&'a Bound<'py, PyAny>>,
    /// κ in degrees (none: 5°, the case format's default).
    pub kappa_deg: Option<&'a Bound<'py, PyAny>>,
    /// The slab's bottom, top and vertical speed (§III): all three or none.
    pub slab: [Option<&'a Bound<'py, PyAny>>; 3],
}

impl CaseArgs<'_, '_> {
    /// The engine's validated case (paper A §II, §III), through the one path the case
    /// format takes ([`RawCase::to_api_with`]): the same rules, fields and messages.
    pub fn case(&self) -> Result<Case, CaseError> {
        let lookahead = number(self.lookahead, "lookahead")?;
        let buff = number(self.buff, "buff")?;
        let fac = match self.fac {
            Some(f) => number(f, "fac")?,
            None => Params::DEFAULT_FAC,
        };
        let kappa_deg = match self.kappa_deg {
            Some(k) => number(k, "kappa")?,
            None => polyguard_harness::case::DEFAULT_KAPPA_DEG,
        };
        let pos = numbers(self.pos, "point.pos")?;
        if pos.len() != 2 && pos.len() != 3 {
            return Err(CaseError::PointLength { found: pos.len() });
        }
        let vel = numbers(self.vel, "point.vel")?;
        let vertices = pairs(self.vertices, "polygon.vertices")?;
        let velocities = match self.velocities {
            None => Vec::new(),
            Some(v) => {
                let v = pairs(v, "polygon.velocities")?;
                // An explicit list is one velocity per vertex; only `None` means at rest.
                if v.len() != vertices.len() {
                    return Err(CaseError::WrongLength {
                        field: "polygon.velocities".into(),
                        expected: vertices.len(),
                        found: v.len(),
                        what: "velocities (one per vertex)",
                    });
                }
                v
            }
        };
        let names = ["polygon.bottom", "polygon.top", "polygon.vz"];
        let slab = match self.slab {
            [None, None, None] => None,
            [Some(b), Some(t), Some(z)] => Some([
                number(b, names[0])?,
                number(t, names[1])?,
                number(z, names[2])?,
            ]),
            given => {
                let k = given.iter().position(Option::is_none).unwrap_or(0);
                return Err(CaseError::Missing {
                    field: names[k].into(),
                });
            }
        };
        RawCase {
            lookahead,
            buff,
            fac,
            pos,
            vel,
            vertices,
            velocities,
            slab,
        }
        .to_api_with(kappa_deg)
    }
}

/// A case object of docs/cases.md (a dict, or one JSON line as a str), read by the case
/// format's own reader (unknown keys, repeated keys, NaN literals are errors naming the
/// field). A dict is written as JSON by Python's `json.dumps` first (NaN and infinities
/// as the literals the reader reports).
pub fn case_from_object(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<Case> {
    case_and_options(py, case).map(|(case, _)| case)
}

/// [`case_from_object`] with the case's own `sep`, `sep_v` and `fence` (docs/cases.md,
/// "Separation and fences"), read and checked by the same reader.
pub fn case_and_options(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<(Case, CaseOptions)> {
    let text: String = if let Ok(s) = case.cast::<PyString>() {
        s.to_str()?.to_owned()
    } else {
        py.import("json")?
            .call_method1("dumps", (case,))?
            .extract()?
    };
    let parsed = polyguard_harness::case::parse_line(&text, 1);
    let case = parsed
        .case
        .map_err(|e| crate::engine_error(py, &e, str::to_owned))?;
    Ok((case, parsed.options))
}
