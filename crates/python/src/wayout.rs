//! The way out (the engine's `polyguard::bands`, `polyguard::recovery` and
//! `polyguard::offset`, whose module docs give the definitions and certificates; paper
//! A §II's polygons, §II.G's proximity, §II–§III's motion): `course_bands`,
//! `speed_bands`, `vertical_speed_bands`, `recover`, `offset` and `inset`, on plain
//! Python values (lists of points, dicts of the case format's polygon fields), answering
//! plain Python values shaped as the CLI's answer lines.
//!
//! Bad input raises `polyguard.Error` (a `ValueError`) whose `field` names the
//! argument as the caller wrote it (`obstacles[1].vertices[2][0]`, `lookahead`, `sep`).

use polyguard::bands::{self, BandKind, Bands, BandsError, Height, Obstacle, Slab, Traffic};
use polyguard::offset::{self as offsets, Offset, OffsetError};
use polyguard::recovery::{self, Recovery, RecoveryError};
use polyguard::{Separation, Vect2};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::args::{number, numbers, pairs};

/// `polyguard.Error` for an argument-reading failure (the case format's error, its
/// field as the caller named the argument).
fn read_error(py: Python<'_>, e: &polyguard::error::CaseError) -> PyErr {
    crate::error(py, &e.field(), &e.to_string())
}

/// A point list as the engine's vectors.
fn vectors(points: &[[f64; 2]]) -> Vec<Vect2> {
    points.iter().map(|p| Vect2::new(p[0], p[1])).collect()
}

/// One obstacle as owned arrays: vertices, velocities (zeros when absent), slab.
struct Owned {
    p: Vec<Vect2>,
    vels: Vec<Vect2>,
    slab: Option<Slab>,
}

/// A mapping's optional member (`mapping.get(key)`; None when absent or None); an
/// object without `get` is `polyguard.Error` naming `field` (the obstacle).
fn member<'py>(
    obj: &Bound<'py, PyAny>,
    key: &str,
    field: &str,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    let v = obj.call_method1("get", (key,)).map_err(|_| {
        crate::error(
            obj.py(),
            field,
            &format!("{field}: not a mapping with `vertices` (a polygon object)"),
        )
    })?;
    Ok((!v.is_none()).then_some(v))
}

/// The obstacles: a sequence of mappings with the case format's polygon fields
/// (`vertices`, optional `velocities`, optional `bottom`, `top`, `vz` for a slab).
fn obstacles_of(py: Python<'_>, obj: &Bound<'_, PyAny>) -> PyResult<Vec<Owned>> {
    let mut out = Vec::new();
    let iter = obj
        .try_iter()
        .map_err(|_| crate::error(py, "obstacles", "obstacles: not a sequence of polygons"))?;
    for (i, item) in iter.enumerate() {
        let item = item?;
        let name = |f: &str| format!("obstacles[{i}].{f}");
        let whole = format!("obstacles[{i}]");
        let vertices = member(&item, "vertices", &whole)?.ok_or_else(|| {
            crate::error(
                py,
                &name("vertices"),
                &format!("{}: missing", name("vertices")),
            )
        })?;
        let p = pairs(&vertices, &name("vertices")).map_err(|e| read_error(py, &e))?;
        let vels = match member(&item, "velocities", &whole)? {
            Some(v) => pairs(&v, &name("velocities")).map_err(|e| read_error(py, &e))?,
            None => vec![[0.0, 0.0]; p.len()],
        };
        let slab = [
            member(&item, "bottom", &whole)?,
            member(&item, "top", &whole)?,
            member(&item, "vz", &whole)?,
        ];
        let slab = match slab {
            [None, None, None] => None,
            [Some(b), Some(t), Some(z)] => Some(Slab {
                bottom: number(&b, &name("bottom")).map_err(|e| read_error(py, &e))?,
                top: number(&t, &name("top")).map_err(|e| read_error(py, &e))?,
                vsp: number(&z, &name("vz")).map_err(|e| read_error(py, &e))?,
            }),
            _ => {
                return Err(crate::error(
                    py,
                    &name("bottom"),
                    &format!("{}: a slab needs bottom, top and vz", name("bottom")),
                ))
            }
        };
        out.push(Owned {
            p: vectors(&p),
            vels: vectors(&vels),
            slab,
        });
    }
    Ok(out)
}

/// The Python argument a field of `polyguard::bands` stands for.
fn bands_field(engine: &str, unknown_max: &str) -> String {
    let fixed = match engine {
        "t" => Some("lookahead"),
        "s[0]" => Some("pos[0]"),
        "s[1]" => Some("pos[1]"),
        "v[0]" => Some("vel[0]"),
        "v[1]" => Some("vel[1]"),
        "height.sz" => Some("pos[2]"),
        "height.vz" | "height" => Some("vel[2]"),
        "course" => Some("course_deg"),
        "unknown_max" => Some(unknown_max),
        _ => None,
    };
    if let Some(f) = fixed {
        return f.into();
    }
    if let Some(obstacle) = engine.strip_suffix(".slab") {
        return format!("{obstacle}.bottom");
    }
    engine
        .replacen(".p", ".vertices", 1)
        .replacen(".vels", ".velocities", 1)
        .replacen(".slab.vsp", ".vz", 1)
        .replacen(".slab.", ".", 1)
}

/// `polyguard.Error` of a bands error, its field renamed for Python.
fn bands_error(py: Python<'_>, e: &BandsError, unknown_max: &str) -> PyErr {
    let (field, rest) = match e {
        BandsError::NotFinite { field } => (field, "not a finite number".to_string()),
        BandsError::OutOfRange {
            field,
            value,
            range,
        } => (field, format!("{value} is outside {range}")),
        BandsError::WrongLength {
            field,
            expected,
            found,
        } => (field, format!("length {found}, expected {expected}")),
        BandsError::DimensionMismatch { field } => (
            field,
            "a slab needs the point's height (pos with 3 numbers)".to_string(),
        ),
    };
    let f = bands_field(field, unknown_max);
    crate::error(py, &f, &format!("{f}: {rest}"))
}

/// The point's state: pos (2 or 3 numbers) and vel (as many).
struct PointState {
    s: Vect2,
    v: Vect2,
    height: Option<Height>,
}

/// Reads `pos` and `vel`: [x, y] and [vx, vy] in 2D, [x, y, z] and [vx, vy, vz] in 3D.
fn point_of(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
) -> PyResult<PointState> {
    let pos = numbers(pos, "pos").map_err(|e| read_error(py, &e))?;
    let vel = numbers(vel, "vel").map_err(|e| read_error(py, &e))?;
    if pos.len() != 2 && pos.len() != 3 {
        return Err(crate::error(
            py,
            "pos",
            &format!("pos: {} numbers, [x, y] or [x, y, z] expected", pos.len()),
        ));
    }
    if vel.len() != pos.len() {
        return Err(crate::error(
            py,
            "vel",
            &format!(
                "vel: {} numbers, {} expected (as many as pos)",
                vel.len(),
                pos.len()
            ),
        ));
    }
    Ok(PointState {
        s: Vect2::new(pos[0], pos[1]),
        v: Vect2::new(vel[0], vel[1]),
        height: (pos.len() == 3).then(|| Height {
            sz: pos[2],
            vz: vel[2],
        }),
    })
}

/// The name of a band kind, as the CLI's answers spell it.
fn kind_name(k: BandKind) -> &'static str {
    match k {
        BandKind::Clear => "clear",
        BandKind::Conflict => "conflict",
        BandKind::Unknown => "unknown",
    }
}

/// A band answer as a dict: `bands` a list of (lo, hi, kind), each end through `scale`
/// (degrees for courses), the Unknown total under `total_key`, and `met`.
fn bands_dict<'py>(
    py: Python<'py>,
    b: &Bands,
    scale: impl Fn(f64) -> f64,
    total_key: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let list = PyList::empty(py);
    for band in &b.bands {
        list.append((scale(band.lo), scale(band.hi), kind_name(band.kind)))?;
    }
    let d = PyDict::new(py);
    d.set_item("bands", list)?;
    d.set_item(total_key, scale(b.unknown_total))?;
    d.set_item("met", b.met)?;
    Ok(d)
}

/// Which band family a call asks for.
enum Family {
    Course { speed: f64 },
    Speed { course: f64, min: f64, max: f64 },
    Vertical { min: f64, max: f64 },
}

/// The arguments every band call shares: the point, the obstacles, the lookahead and
/// the separation (D, and H in 3D).
struct Encounter {
    point: PointState,
    obstacles: Vec<Owned>,
    lookahead: f64,
    sep: f64,
    sep_v: f64,
}

/// Reads the shared band arguments in the order the errors name them: `pos`, `vel`,
/// `obstacles`, `lookahead`, `sep`, `sep_v` (0 when absent).
fn encounter_of(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    obstacles: &Bound<'_, PyAny>,
    lookahead: &Bound<'_, PyAny>,
    sep: &Bound<'_, PyAny>,
    sep_v: Option<&Bound<'_, PyAny>>,
) -> PyResult<Encounter> {
    Ok(Encounter {
        point: point_of(py, pos, vel)?,
        obstacles: obstacles_of(py, obstacles)?,
        lookahead: arg(py, lookahead, "lookahead")?,
        sep: arg(py, sep, "sep")?,
        sep_v: sep_v.map_or(Ok(0.0), |x| arg(py, x, "sep_v"))?,
    })
}

/// The engine's bands for the point among the obstacles, without the GIL
/// (`polyguard::bands`), as the answer dict of `bands_dict`; an error names
/// `unknown_max` as the caller's `um_name`.
fn bands_answer<'py>(
    py: Python<'py>,
    e: &Encounter,
    family: Family,
    unknown_max: f64,
    um_name: &str,
    scale: impl Fn(f64) -> f64,
    total_key: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let list: Vec<Obstacle> = e
        .obstacles
        .iter()
        .map(|o| Obstacle {
            p: &o.p,
            vels: &o.vels,
            slab: o.slab,
        })
        .collect();
    let traffic = Traffic {
        t: e.lookahead,
        s: e.point.s,
        height: e.point.height,
        obstacles: &list,
        sep: Separation {
            d: e.sep,
            h: e.sep_v,
        },
    };
    let v = e.point.v;
    let b = py
        .detach(|| match family {
            Family::Course { speed } => bands::course_bands(&traffic, speed, unknown_max),
            Family::Speed { course, min, max } => {
                bands::speed_bands(&traffic, course, min, max, unknown_max)
            }
            Family::Vertical { min, max } => {
                bands::vertical_speed_bands(&traffic, v, min, max, unknown_max)
            }
        })
        .map_err(|err| bands_error(py, &err, um_name))?;
    bands_dict(py, &b, scale, total_key)
}

/// The `unknown_max` argument, or `default_unknown_max` of the range when absent.
fn unknown_max_of(
    py: Python<'_>,
    unknown_max: Option<&Bound<'_, PyAny>>,
    min: f64,
    max: f64,
) -> PyResult<f64> {
    match unknown_max {
        Some(x) => arg(py, x, "unknown_max"),
        None => Ok(default_unknown_max(min, max)),
    }
}

/// A number argument, or `polyguard.Error` naming it.
fn arg(py: Python<'_>, x: &Bound<'_, PyAny>, field: &str) -> PyResult<f64> {
    number(x, field).map_err(|e| read_error(py, &e))
}

/// The current course of a horizontal velocity, in degrees clockwise from +y in
/// [0, 360) (the definition of `polyguard::bands`: v = speed·(sin θ, cos θ)).
fn course_deg_of(v: Vect2) -> f64 {
    let deg = v.x.atan2(v.y).to_degrees();
    if deg < 0.0 {
        deg + 360.0
    } else {
        deg
    }
}

/// Course bands over [0°, 360°] for the point at `pos` (3 numbers: with its height,
/// 3D) moving at `speed` (default |vel|'s horizontal part; vel's third number is the
/// vertical speed in 3D) among the moving `obstacles` over [0, lookahead], with
/// separation `sep` (D) and `sep_v` (H, 3D): the engine's
/// `polyguard::bands::course_bands` (its module doc: a course is in conflict when
/// near_D holds at some time against some obstacle; clear bands are certified free of
/// conflict for every course in them, conflict bands certified in conflict for every
/// course). Courses in degrees clockwise from +y ("north"); the ends are the engine's
/// radians converted to degrees (one rounding).
///
/// Each obstacle is a mapping with the case format's polygon fields: `vertices`
/// (counterclockwise), optional `velocities`, optional slab `bottom`, `top`, `vz` (3D).
/// Returns `{"bands": [(from_deg, to_deg, "clear" | "conflict" | "unknown"), ...],
/// "unknown_total_deg": float, "met": bool}`. Raises `polyguard.Error` naming the
/// field.
#[pyfunction]
#[pyo3(signature = (pos, vel, obstacles, *, lookahead, sep, sep_v=None, speed=None, unknown_max_deg=None),
    text_signature = "(pos, vel, obstacles, *, lookahead, sep, sep_v=0.0, speed=None, unknown_max_deg=0.1)")]
#[allow(clippy::too_many_arguments)]
pub fn course_bands<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    obstacles: &Bound<'py, PyAny>,
    lookahead: &Bound<'py, PyAny>,
    sep: &Bound<'py, PyAny>,
    sep_v: Option<&Bound<'py, PyAny>>,
    speed: Option<&Bound<'py, PyAny>>,
    unknown_max_deg: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = encounter_of(py, pos, vel, obstacles, lookahead, sep, sep_v)?;
    let speed = match speed {
        Some(x) => arg(py, x, "speed")?,
        None => e.point.v.x.hypot(e.point.v.y),
    };
    let um = unknown_max_deg.map_or(Ok(0.1), |x| arg(py, x, "unknown_max_deg"))?;
    bands_answer(
        py,
        &e,
        Family::Course { speed },
        um.to_radians(),
        "unknown_max_deg",
        f64::to_degrees,
        "unknown_total_deg",
    )
}

/// Speed bands over [`min`, `max`] at the fixed `course_deg` (default: the current
/// course of `vel`), the rest as `course_bands` (the engine's
/// `polyguard::bands::speed_bands`). `unknown_max` defaults to (max − min)/1000 (1 when
/// max = min). Returns `{"bands": [(from, to, kind), ...], "unknown_total": float,
/// "met": bool}`.
#[pyfunction]
#[pyo3(signature = (pos, vel, obstacles, *, lookahead, sep, min, max, sep_v=None, course_deg=None, unknown_max=None),
    text_signature = "(pos, vel, obstacles, *, lookahead, sep, min, max, sep_v=0.0, course_deg=None, unknown_max=None)")]
#[allow(clippy::too_many_arguments)]
pub fn speed_bands<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    obstacles: &Bound<'py, PyAny>,
    lookahead: &Bound<'py, PyAny>,
    sep: &Bound<'py, PyAny>,
    min: &Bound<'py, PyAny>,
    max: &Bound<'py, PyAny>,
    sep_v: Option<&Bound<'py, PyAny>>,
    course_deg: Option<&Bound<'py, PyAny>>,
    unknown_max: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = encounter_of(py, pos, vel, obstacles, lookahead, sep, sep_v)?;
    let (min, max) = (arg(py, min, "min")?, arg(py, max, "max")?);
    let course = match course_deg {
        Some(x) => arg(py, x, "course_deg")?,
        None => course_deg_of(e.point.v),
    };
    let um = unknown_max_of(py, unknown_max, min, max)?;
    bands_answer(
        py,
        &e,
        Family::Speed {
            course: course.to_radians(),
            min,
            max,
        },
        um,
        "unknown_max",
        |x| x,
        "unknown_total",
    )
}

/// (max − min)/1000, or 1 for an empty or invalid range (the engine then names the bad
/// bound).
fn default_unknown_max(min: f64, max: f64) -> f64 {
    let w = (max - min) / 1000.0;
    if w.is_finite() && w > 0.0 {
        w
    } else {
        1.0
    }
}

/// Vertical speed bands over [`min`, `max`] with the horizontal velocity `vel[:2]`
/// fixed (3D: `pos` and `vel` of 3 numbers), the rest as `speed_bands` (the engine's
/// `polyguard::bands::vertical_speed_bands`).
#[pyfunction]
#[pyo3(signature = (pos, vel, obstacles, *, lookahead, sep, sep_v, min, max, unknown_max=None),
    text_signature = "(pos, vel, obstacles, *, lookahead, sep, sep_v, min, max, unknown_max=None)")]
#[allow(clippy::too_many_arguments)]
pub fn vertical_speed_bands<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    obstacles: &Bound<'py, PyAny>,
    lookahead: &Bound<'py, PyAny>,
    sep: &Bound<'py, PyAny>,
    sep_v: &Bound<'py, PyAny>,
    min: &Bound<'py, PyAny>,
    max: &Bound<'py, PyAny>,
    unknown_max: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = encounter_of(py, pos, vel, obstacles, lookahead, sep, Some(sep_v))?;
    let (min, max) = (arg(py, min, "min")?, arg(py, max, "max")?);
    let um = unknown_max_of(py, unknown_max, min, max)?;
    if e.point.height.is_none() {
        return Err(crate::error(
            py,
            "pos",
            "pos: vertical speed bands need the point's height ([x, y, z])",
        ));
    }
    bands_answer(
        py,
        &e,
        Family::Vertical { min, max },
        um,
        "unknown_max",
        |x| x,
        "unknown_total",
    )
}

/// A polygon's vertices and optional velocities from Python.
fn polygon_of(
    py: Python<'_>,
    vertices: &Bound<'_, PyAny>,
    velocities: Option<&Bound<'_, PyAny>>,
) -> PyResult<(Vec<Vect2>, Option<Vec<Vect2>>)> {
    let p = pairs(vertices, "vertices").map_err(|e| read_error(py, &e))?;
    let v = match velocities {
        Some(v) => Some(vectors(
            &pairs(v, "velocities").map_err(|e| read_error(py, &e))?,
        )),
        None => None,
    };
    Ok((vectors(&p), v))
}

/// `polyguard.Error` of a recovery error, its field in Python's names.
fn recovery_error(py: Python<'_>, e: &RecoveryError) -> PyErr {
    let text = e.to_string();
    let field = e.field();
    let rest = text
        .strip_prefix(&format!("{field}: "))
        .unwrap_or(text.as_str());
    polygon_error(py, field, rest)
}

/// The recovery point of `s` for the polygon `vertices` (counterclockwise; at time `t`
/// with `velocities`): `fence="keep_out"` the nearest x with dist(x, P) ≥ `sep`,
/// `"keep_in"` the nearest x in P with dist(x, ∂P) ≥ `sep` (the engine's
/// `polyguard::recovery`: x is certified to satisfy its condition, and the exact
/// minimum distance lies in [min_lo, distance]). Returns `{"point": (x, y),
/// "distance": float, "min_lo": float, "moved": bool}`, or `{"impossible": reason}`
/// when no point of P is `sep` from its boundary (keep_in). Raises `polyguard.Error`
/// naming the field (`vertices`, `s`, `sep`, `t`, `fence`).
#[pyfunction]
#[pyo3(signature = (vertices, s, sep, *, fence="keep_out", velocities=None, t=None),
    text_signature = "(vertices, s, sep, *, fence='keep_out', velocities=None, t=0.0)")]
pub fn recover<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    s: &Bound<'py, PyAny>,
    sep: &Bound<'py, PyAny>,
    fence: &str,
    velocities: Option<&Bound<'py, PyAny>>,
    t: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let keep_in = match fence {
        "keep_out" => false,
        "keep_in" => true,
        other => {
            return Err(crate::error(
                py,
                "fence",
                &format!("fence: {other:?} is not \"keep_out\" or \"keep_in\""),
            ))
        }
    };
    let (p, vels) = polygon_of(py, vertices, velocities)?;
    let xy = numbers(s, "s").map_err(|e| read_error(py, &e))?;
    if xy.len() != 2 {
        return Err(crate::error(
            py,
            "s",
            &format!("s: {} numbers, [x, y] expected", xy.len()),
        ));
    }
    let s = Vect2::new(xy[0], xy[1]);
    let d = arg(py, sep, "sep")?;
    let t = t.map_or(Ok(0.0), |x| arg(py, x, "t"))?;
    let answer = py.detach(|| match (&vels, keep_in) {
        (Some(v), false) => recovery::recovery_out_at(&p, v, t, s, d),
        (Some(v), true) => recovery::recovery_in_at(&p, v, t, s, d),
        (None, _) if !t.is_finite() => Err(RecoveryError::NotFinite { field: "t" }),
        (None, false) => recovery::recovery_out(&p, s, d),
        (None, true) => recovery::recovery_in(&p, s, d),
    });
    let out = PyDict::new(py);
    match answer.map_err(|e| recovery_error(py, &e))? {
        Recovery::Point {
            x,
            dist_hi,
            min_lo,
            clear,
        } => {
            out.set_item("point", (x.x, x.y))?;
            out.set_item("distance", dist_hi)?;
            out.set_item("min_lo", min_lo)?;
            out.set_item("moved", !clear)?;
        }
        Recovery::Impossible { reason } => out.set_item("impossible", reason)?,
    }
    Ok(out)
}

/// `polyguard.Error` of an offset error, its field in Python's names.
fn offset_error(py: Python<'_>, e: &OffsetError) -> PyErr {
    let (field, rest) = match e {
        OffsetError::Invalid { field, reason } => (*field, (*reason).to_string()),
        OffsetError::Polygon { fault } => ("p", format!("not a simple polygon ({fault:?})")),
        OffsetError::TooFine { .. } => {
            let text = e.to_string();
            let rest = text.strip_prefix("eps: ").unwrap_or(&text).to_string();
            ("eps", rest)
        }
        OffsetError::Uncertified { .. } => ("p", e.to_string()),
    };
    polygon_error(py, field, &rest)
}

/// `polyguard.Error` of a recovery or offset error's field and text, the engine's
/// `p` and `vels` named as Python's `vertices` and `velocities`.
fn polygon_error(py: Python<'_>, field: &str, rest: &str) -> PyErr {
    let f = match field {
        "p" => "vertices",
        "vels" => "velocities",
        other => other,
    };
    crate::error(py, f, &format!("{f}: {rest}"))
}

/// The regions as `[{"outer": [(x, y), ...], "holes": [[(x, y), ...], ...]}, ...]`.
fn regions_list<'py>(py: Python<'py>, o: &Offset) -> PyResult<Bound<'py, PyList>> {
    let ring = |r: &[Vect2]| PyList::new(py, r.iter().map(|v| (v.x, v.y)));
    let list = PyList::empty(py);
    for region in &o.regions {
        let d = PyDict::new(py);
        d.set_item("outer", ring(&region.outer)?)?;
        let holes = PyList::empty(py);
        for h in &region.holes {
            holes.append(ring(h)?)?;
        }
        d.set_item("holes", holes)?;
        list.append(d)?;
    }
    Ok(list)
}

/// The body of `offset` and `inset`.
fn shape<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    d: &Bound<'py, PyAny>,
    eps: Option<&Bound<'py, PyAny>>,
    velocities: Option<&Bound<'py, PyAny>>,
    t: Option<&Bound<'py, PyAny>>,
    inset: bool,
) -> PyResult<Bound<'py, PyList>> {
    let (p, vels) = polygon_of(py, vertices, velocities)?;
    let d = arg(py, d, "d")?;
    let eps = eps.map_or(Ok(0.01), |x| arg(py, x, "eps"))?;
    let t = t.map_or(Ok(0.0), |x| arg(py, x, "t"))?;
    let answer = py.detach(|| match (&vels, inset) {
        (Some(v), false) => offsets::offset_at(&p, v, t, d, eps),
        (Some(v), true) => offsets::inset_at(&p, v, t, d, eps),
        (None, _) if !t.is_finite() => Err(OffsetError::Invalid {
            field: "t",
            reason: "not finite",
        }),
        (None, false) => offsets::offset(&p, d, eps),
        (None, true) => offsets::inset(&p, d, eps),
    });
    regions_list(py, &answer.map_err(|e| offset_error(py, &e))?)
}

/// The certified offset of the polygon `vertices` (counterclockwise; at time `t` with
/// `velocities`) by `d` within relative tolerance `eps`: regions Q with
/// P ⊕ disc(d) ⊆ Q ⊆ P ⊕ disc(d·(1 + eps)) (the engine's `polyguard::offset::offset`).
/// Returns `[{"outer": [(x, y), ...] (counterclockwise), "holes": [[(x, y), ...],
/// ...] (clockwise)}, ...]`. Raises `polyguard.Error` naming the field (`vertices`,
/// `d`, `eps`, `t`; `vertices` also when the result could not be certified).
#[pyfunction]
#[pyo3(signature = (vertices, d, eps=None, *, velocities=None, t=None),
    text_signature = "(vertices, d, eps=0.01, *, velocities=None, t=0.0)")]
pub fn offset<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    d: &Bound<'py, PyAny>,
    eps: Option<&Bound<'py, PyAny>>,
    velocities: Option<&Bound<'py, PyAny>>,
    t: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    shape(py, vertices, d, eps, velocities, t, false)
}

/// The certified inset: pieces Q with Q ⊆ {x ∈ P : dist(x, ∂P) ≥ d} and
/// Q ⊇ {x ∈ P : dist(x, ∂P) ≥ d·(1 + eps)}; maybe several, maybe none (`[]`). The
/// engine's `polyguard::offset::inset`; arguments and answer as `offset`.
#[pyfunction]
#[pyo3(signature = (vertices, d, eps=None, *, velocities=None, t=None),
    text_signature = "(vertices, d, eps=0.01, *, velocities=None, t=0.0)")]
pub fn inset<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    d: &Bound<'py, PyAny>,
    eps: Option<&Bound<'py, PyAny>>,
    velocities: Option<&Bound<'py, PyAny>>,
    t: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    shape(py, vertices, d, eps, velocities, t, true)
}
