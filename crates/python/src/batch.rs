//! `detect_batch`: N points against M polygons from numpy arrays (paper A §II.H, §II.I,
//! §III on many pairs, through the engine's `batch::detect_batch_with`: a certified broad
//! phase, then the paper functions per pair).
//!
//! Arrays of dtype float64 (and int64 offsets) are read in place, whatever their strides
//! (C-contiguous, Fortran order, sliced views): the engine's points and polygons are built
//! straight from the array memory. Anything else (lists, float32, int arrays) is first
//! converted by `numpy.asarray` to a new float64 array, one copy. The engine's validated
//! polygons own their vertices, so the vertices are copied once into them in any case
//! (O(total vertices), beside O(pairs) for the detection). The GIL is released for that
//! and for the detection; the arrays must not be changed by another thread meanwhile.

use numpy::ndarray::ArrayViewD;
use numpy::{PyArray1, PyReadonlyArrayDyn};
use polyguard::api::{Kind, MovingPoint, MovingPolygon, Params};
use polyguard::batch::{detect_batch_with, Options};
use polyguard::error::CaseError;
use polyguard::Vect2;
use pyo3::prelude::*;

/// The kind code of a hit whose every comparison was certified (paper A without rounding
/// says yes): `Kind::Exact`.
pub const KIND_EXACT: u8 = 0;
/// The kind code of a conservative hit (a yes taken on a comparison f64 could not
/// decide): `Kind::Conservative`.
pub const KIND_CONSERVATIVE: u8 = 1;

/// An error of the batch's input: the field and the whole message.
type Failure = (String, String);

/// A shape or layout error about argument `field` (not a paper rule: the arrays'
/// layout, extending paper A's one case to many).
fn shape_error(field: &str, what: String) -> Failure {
    (field.to_string(), format!("{field}: {what}"))
}

/// An engine error of item `index` (a point or a polygon), its field prefixed by the item:
/// `point.pos` becomes `points[3].pos`, `polygon.vertices[2][1]` becomes
/// `polygons[7].vertices[2][1]` (docs/cases.md's rules, per item).
fn item_error(e: &CaseError, index: usize) -> Failure {
    let field = e.field();
    let text = e.to_string();
    let rest = text
        .strip_prefix(&format!("{field}: "))
        .unwrap_or(text.as_str())
        .to_string();
    let renamed = if let Some(f) = field.strip_prefix("point.") {
        format!("points[{index}].{f}")
    } else if let Some(f) = field.strip_prefix("polygon.") {
        format!("polygons[{index}].{f}")
    } else {
        field.clone()
    };
    (renamed.clone(), format!("{renamed}: {rest}"))
}

/// A float64 array for `field` (the batch's inputs, extending paper A's one case to many):
/// the array itself when it is one (no copy), else
/// `numpy.asarray(obj, "float64")` (one copy).
fn f64_array<'py>(
    py: Python<'py>,
    obj: &Bound<'py, PyAny>,
    field: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArrayDyn<'py, f64>>() {
        return Ok(a);
    }
    let converted = py
        .import("numpy")?
        .call_method1("asarray", (obj, "float64"))
        .map_err(|e| {
            crate::case_error(
                py,
                field,
                &format!("{field}: cannot be read as an array of float64 ({e})"),
            )
        })?;
    converted.extract().map_err(|e: PyErr| {
        crate::case_error(
            py,
            field,
            &format!("{field}: cannot be read as an array of float64 ({e})"),
        )
    })
}

/// An int64 array for `field` (the polygons' offsets, extending paper A's one polygon to
/// many): the array itself when it is one,
/// else a conversion that refuses non-integer values (2.5 is not an offset).
fn i64_array<'py>(
    py: Python<'py>,
    obj: &Bound<'py, PyAny>,
    field: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, i64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArrayDyn<'py, i64>>() {
        return Ok(a);
    }
    let bad = |why: String| crate::case_error(py, field, &format!("{field}: {why}"));
    let arr = py
        .import("numpy")?
        .call_method1("asarray", (obj,))
        .map_err(|e| bad(format!("cannot be read as an array ({e})")))?;
    let kind: String = arr.getattr("dtype")?.getattr("kind")?.extract()?;
    if kind != "i" && kind != "u" && !(kind == "f" && arr.getattr("size")?.extract::<usize>()? == 0)
    {
        return Err(bad(format!(
            "must hold integers (numpy dtype kind {kind:?} given)"
        )));
    }
    arr.call_method1("astype", ("int64",))?
        .extract()
        .map_err(|e: PyErr| bad(format!("cannot be read as int64 ({e})")))
}

/// The batch's arrays, as views into the Python arrays.
struct Arrays<'a> {
    pos: ArrayViewD<'a, f64>,
    vel: ArrayViewD<'a, f64>,
    vertices: ArrayViewD<'a, f64>,
    offsets: Option<ArrayViewD<'a, i64>>,
    velocities: Option<ArrayViewD<'a, f64>>,
    slabs: Option<ArrayViewD<'a, f64>>,
}

/// The points: rows of `pos` and `vel`, (N, 2), or (N, 3) with the height (paper A §II's
/// s + t·v, §III's s_z + t·v_z).
fn read_points(a: &Arrays<'_>) -> Result<Vec<MovingPoint>, Failure> {
    let (pos, vel) = (&a.pos, &a.vel);
    if pos.ndim() != 2 || !(pos.shape()[1] == 2 || pos.shape()[1] == 3) {
        return Err(shape_error(
            "points_pos",
            format!("shape {:?}, (N, 2) or (N, 3) expected", pos.shape()),
        ));
    }
    if vel.shape() != pos.shape() {
        return Err(shape_error(
            "points_vel",
            format!(
                "shape {:?}, {:?} expected (as points_pos)",
                vel.shape(),
                pos.shape()
            ),
        ));
    }
    let mut points = Vec::with_capacity(pos.shape()[0]);
    for (i, (p, v)) in pos.outer_iter().zip(vel.outer_iter()).enumerate() {
        let point = if p.len() == 2 {
            MovingPoint::new_2d(Vect2::new(p[0], p[1]), Vect2::new(v[0], v[1]))
        } else {
            MovingPoint::new_3d([p[0], p[1], p[2]], [v[0], v[1], v[2]])
        };
        points.push(point.map_err(|e| item_error(&e, i))?);
    }
    Ok(points)
}

/// Where polygon j's vertices (paper A §II's P, one per polygon) lie: rows `ranges[j]` of the (V, 2) vertex array, or
/// `poly_vertices[j]` of an (M, n, 2) one.
fn polygon_ranges(a: &Arrays<'_>) -> Result<Vec<std::ops::Range<usize>>, Failure> {
    let v = &a.vertices;
    match (v.ndim(), &a.offsets) {
        (3, None) if v.shape()[2] == 2 => {
            let n = v.shape()[1];
            Ok((0..v.shape()[0]).map(|j| j * n..(j + 1) * n).collect())
        }
        (3, Some(_)) => Err(shape_error(
            "poly_offsets",
            "given with an (M, n, 2) poly_vertices; offsets go with a (V, 2) one".into(),
        )),
        (2, Some(off)) if v.shape()[1] == 2 => {
            if off.ndim() != 1 || off.is_empty() {
                return Err(shape_error(
                    "poly_offsets",
                    format!("shape {:?}, (M + 1,) expected", off.shape()),
                ));
            }
            let rows = v.shape()[0];
            if off[0] != 0 {
                return Err(shape_error(
                    "poly_offsets",
                    format!("starts at {}, 0 expected", off[0]),
                ));
            }
            let last = off[off.len() - 1];
            if usize::try_from(last).ok() != Some(rows) {
                return Err(shape_error(
                    "poly_offsets",
                    format!("ends at {last}, the number of vertex rows ({rows}) expected"),
                ));
            }
            let mut ranges = Vec::with_capacity(off.len() - 1);
            for j in 0..off.len() - 1 {
                let (s, e) = (off[j], off[j + 1]);
                if e < s {
                    return Err(shape_error(
                        &format!("poly_offsets[{}]", j + 1),
                        format!(
                            "{e} is below the offset before it ({s}); offsets must not decrease"
                        ),
                    ));
                }
                // 0 <= s <= e <= rows here: off[0] = 0, non-decreasing, ends at rows
                ranges.push(s as usize..e as usize);
            }
            Ok(ranges)
        }
        (2, None) => Err(shape_error(
            "poly_offsets",
            "missing: a (V, 2) poly_vertices needs the offsets of its polygons (M + 1 of them, \
             from 0 to V), or give an (M, n, 2) array"
                .into(),
        )),
        _ => Err(shape_error(
            "poly_vertices",
            format!(
                "shape {:?}, (M, n, 2) or (V, 2) with poly_offsets expected",
                v.shape()
            ),
        )),
    }
}

/// Rows `range` of the vertex (or velocity) array as points: row i of a (V, 2) array, or
/// `[j, k]` with i = j·n + k of an (M, n, 2) one (the layout of paper A §II's P and V
/// per polygon).
fn rows2(v: &ArrayViewD<'_, f64>, range: std::ops::Range<usize>) -> Vec<Vect2> {
    if v.ndim() == 3 {
        let n = v.shape()[1];
        range
            .map(|i| Vect2::new(v[[i / n, i % n, 0]], v[[i / n, i % n, 1]]))
            .collect()
    } else {
        range.map(|i| Vect2::new(v[[i, 0]], v[[i, 1]])).collect()
    }
}

/// The polygons (paper A §II's P + t·V, with §III's slab): validated as the case format's
/// polygons are, each error naming `polygons[j]`.
fn read_polygons(a: &Arrays<'_>, three_d: bool) -> Result<Vec<MovingPolygon>, Failure> {
    let ranges = polygon_ranges(a)?;
    let m = ranges.len();
    let vshape = a.vertices.shape().to_vec();
    // velocities: None (at rest), per vertex (the vertices' shape), or one drift per
    // polygon (M, 2)
    enum Vel {
        Rest,
        PerVertex,
        Drift,
    }
    let vel_kind = match &a.velocities {
        None => Vel::Rest,
        Some(v) if v.shape() == vshape.as_slice() => Vel::PerVertex,
        Some(v) if v.shape() == [m, 2] => Vel::Drift,
        Some(v) => {
            return Err(shape_error(
                "poly_velocities",
                format!(
                    "shape {:?}: one velocity per vertex ({vshape:?}, as poly_vertices) or \
                     one per polygon ({:?}) expected",
                    v.shape(),
                    [m, 2]
                ),
            ))
        }
    };
    match (&a.slabs, three_d) {
        (Some(s), true) if s.shape() != [m, 3] => {
            return Err(shape_error(
                "poly_slabs",
                format!(
                    "shape {:?}, (M, 3) = {:?} expected (bottom, top, vz per polygon)",
                    s.shape(),
                    [m, 3]
                ),
            ))
        }
        (None, true) => {
            return Err(shape_error(
                "poly_slabs",
                "missing: the points have a height (3 columns), so every polygon needs a \
                 slab (bottom, top, vz)"
                    .into(),
            ))
        }
        (Some(_), false) => {
            return Err(shape_error(
                "points_pos",
                "2 columns, but poly_slabs is given: a 3-D batch needs (N, 3) points".into(),
            ))
        }
        _ => {}
    }
    let mut polygons = Vec::with_capacity(m);
    for (j, r) in ranges.into_iter().enumerate() {
        let vertices = rows2(&a.vertices, r.clone());
        let velocities = match (&vel_kind, &a.velocities) {
            (Vel::PerVertex, Some(v)) => Some(rows2(v, r.clone())),
            (Vel::Drift, Some(v)) => Some(vec![Vect2::new(v[[j, 0]], v[[j, 1]]); r.len()]),
            _ => None,
        };
        let mut q = MovingPolygon::new(vertices, velocities).map_err(|e| item_error(&e, j))?;
        if let Some(s) = &a.slabs {
            q = q
                .with_slab(s[[j, 0]], s[[j, 1]], s[[j, 2]])
                .map_err(|e| item_error(&e, j))?;
        }
        polygons.push(q);
    }
    Ok(polygons)
}

/// The hits, without the GIL's help: points, polygons, then the engine's batch (paper A
/// §II.H, §II.I, §III on every kept pair).
fn run(
    a: &Arrays<'_>,
    lookahead: f64,
    params: Params,
    parallel: bool,
) -> Result<Vec<polyguard::batch::Hit>, Failure> {
    let points = read_points(a)?;
    let three_d = a.pos.shape()[1] == 3;
    let polygons = read_polygons(a, three_d)?;
    let options = Options {
        parallel,
        ..Options::default()
    };
    detect_batch_with(lookahead, &points, &polygons, &params, &options)
        .map(|b| b.hits)
        .map_err(|e| (e.field(), e.to_string()))
}

/// The three answer arrays: point indices, polygon indices (int64), kind codes (uint8).
type Answer<'py> = (
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<u8>>,
);

/// Paper A (§II.H, §II.I, §III) for every point against every polygon: exactly the pairs
/// for which `detect` says detected, sorted by (point, polygon). A certified broad phase
/// (swept boxes grown by what paper A can reach, rounded outward) and mid phase (such a
/// box wholly on one side of the point's path line) skip only pairs paper A answers no.
///
/// - points_pos, points_vel: (N, 2), or (N, 3) with the height (then every polygon needs
///   a slab).
/// - poly_vertices: (M, n, 2) for polygons of n vertices each, or (V, 2) with
///   poly_offsets (M + 1 integers from 0 to V: polygon j is rows `offsets[j]..offsets[j+1]`).
///   Counterclockwise, as in docs/cases.md.
/// - poly_velocities: None (at rest), one per vertex (poly_vertices' shape), or one drift
///   per polygon (M, 2).
/// - poly_slabs: (M, 3) of bottom, top, vz (paper A §III).
/// - parallel: use the engine's threads (rayon); the answer is the same either way.
///
/// Returns numpy arrays of equal length: point indices and polygon indices (int64), and
/// kind codes (uint8: KIND_EXACT = 0, KIND_CONSERVATIVE = 1). Raises CaseError naming
/// the array (`poly_offsets`) or the item (`polygons[7].vertices`).
#[pyfunction]
#[pyo3(signature = (lookahead, points_pos, points_vel, poly_vertices, poly_offsets=None,
    poly_velocities=None, *, buff, fac=None, poly_slabs=None, parallel=true),
    text_signature = "(lookahead, points_pos, points_vel, poly_vertices, poly_offsets=None, \
    poly_velocities=None, *, buff, fac=0.0001, poly_slabs=None, parallel=True)")]
#[allow(clippy::too_many_arguments)]
pub fn detect_batch<'py>(
    py: Python<'py>,
    lookahead: &Bound<'py, PyAny>,
    points_pos: &Bound<'py, PyAny>,
    points_vel: &Bound<'py, PyAny>,
    poly_vertices: &Bound<'py, PyAny>,
    poly_offsets: Option<&Bound<'py, PyAny>>,
    poly_velocities: Option<&Bound<'py, PyAny>>,
    buff: &Bound<'py, PyAny>,
    fac: Option<&Bound<'py, PyAny>>,
    poly_slabs: Option<&Bound<'py, PyAny>>,
    parallel: bool,
) -> PyResult<Answer<'py>> {
    let err = |e: CaseError| crate::engine_error(py, &e, str::to_owned);
    let lookahead = crate::args::number(lookahead, "lookahead").map_err(err)?;
    let buff = crate::args::number(buff, "buff").map_err(err)?;
    let fac = match fac {
        Some(f) => crate::args::number(f, "fac").map_err(err)?,
        None => Params::DEFAULT_FAC,
    };
    let params = Params::new(buff)
        .and_then(|p| p.with_fac(fac))
        .map_err(err)?;
    let pos = f64_array(py, points_pos, "points_pos")?;
    let vel = f64_array(py, points_vel, "points_vel")?;
    let vertices = f64_array(py, poly_vertices, "poly_vertices")?;
    let offsets = poly_offsets
        .map(|o| i64_array(py, o, "poly_offsets"))
        .transpose()?;
    let velocities = poly_velocities
        .map(|v| f64_array(py, v, "poly_velocities"))
        .transpose()?;
    let slabs = poly_slabs
        .map(|s| f64_array(py, s, "poly_slabs"))
        .transpose()?;
    let arrays = Arrays {
        pos: pos.as_array(),
        vel: vel.as_array(),
        vertices: vertices.as_array(),
        offsets: offsets.as_ref().map(|o| o.as_array()),
        velocities: velocities.as_ref().map(|v| v.as_array()),
        slabs: slabs.as_ref().map(|s| s.as_array()),
    };
    let hits = py
        .detach(|| run(&arrays, lookahead, params, parallel))
        .map_err(|(field, message)| crate::case_error(py, &field, &message))?;
    let mut pi = Vec::with_capacity(hits.len());
    let mut qi = Vec::with_capacity(hits.len());
    let mut kind = Vec::with_capacity(hits.len());
    for h in &hits {
        // indices fit in i64: they index arrays in memory
        pi.push(h.point as i64);
        qi.push(h.polygon as i64);
        kind.push(match h.kind {
            Kind::Exact => KIND_EXACT,
            Kind::Conservative => KIND_CONSERVATIVE,
        });
    }
    Ok((
        PyArray1::from_vec(py, pi),
        PyArray1::from_vec(py, qi),
        PyArray1::from_vec(py, kind),
    ))
}
