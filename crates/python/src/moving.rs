//! `encounters`: whole flights against areas with certified spans of inside and near
//! (docs/moving-features.md), the answer of `polyguard encounters` as columns for a data
//! frame. The package's `polyguard.encounters` (python/polyguard/_moving.py) turns its
//! inputs (MF-JSON, GeoJSON, pandas and GeoPandas frames) into the two native entries
//! here: MF-JSON text, or the columns of a table of fixes.

use numpy::{PyArray1, PyReadonlyArray1};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::moving::broad::{encounters_of, Areas};
use polyguard_earth::moving::encounter::{Encounter, Options};
use polyguard_earth::moving::fixes_table::{self, FixColumns};
use polyguard_earth::moving::mfjson;
use polyguard_earth::moving::model::{Area, Trajectory};
use polyguard_earth::moving::time::from_nanos;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;

use crate::error;

/// The movers and areas read, and the messages of what was rejected and remarked, each
/// prefixed by its input's name as the CLI prefixes its file's.
#[derive(Default)]
struct Inputs {
    movers: Vec<Trajectory>,
    areas: Vec<Area>,
    errors: Vec<String>,
    warnings: Vec<String>,
}

/// One row per span: the columns of the answer.
#[derive(Default)]
struct Rows {
    mover: Vec<String>,
    callsign: Vec<Option<String>>,
    area: Vec<String>,
    relation: Vec<&'static str>,
    start_lo: Vec<f64>,
    start_hi: Vec<f64>,
    end_lo: Vec<f64>,
    end_hi: Vec<f64>,
    certain: Vec<bool>,
}

impl Rows {
    /// The rows of one encounter: its inside spans, then its near spans (the CLI line's
    /// order).
    fn push(&mut self, e: &Encounter) {
        for (relation, spans) in [("inside", &e.inside), ("near", &e.near)] {
            for s in spans {
                self.mover.push(e.mover.clone());
                self.callsign.push(e.callsign.clone());
                self.area.push(e.area.clone());
                self.relation.push(relation);
                self.start_lo.push(s.start[0]);
                self.start_hi.push(s.start[1]);
                self.end_lo.push(s.end[0]);
                self.end_hi.push(s.end[1]);
                self.certain.push(s.certain);
            }
        }
    }
}

/// The options of docs/moving-features.md from the Python arguments, or the
/// `polyguard.Error` naming the bad one.
fn options(py: Python<'_>, sep: f64, sep_v: f64, max_gap: f64, geodesy: &str) -> PyResult<Options> {
    for (name, x) in [("sep", sep), ("sep_v", sep_v), ("max_gap", max_gap)] {
        if !x.is_finite() || x < 0.0 {
            return Err(error(
                py,
                name,
                &format!("{name}: {x}, a finite number ≥ 0 expected"),
            ));
        }
    }
    let geodesy = match geodesy {
        "sphere" => Geodesy::Sphere,
        "wgs84" => Geodesy::Wgs84,
        other => {
            return Err(error(
                py,
                "geodesy",
                &format!("geodesy: {other:?}, \"sphere\" or \"wgs84\" expected"),
            ))
        }
    };
    Ok(Options {
        sep_nm: sep,
        sep_v_ft: sep_v,
        max_gap_s: max_gap,
        geodesy,
    })
}

/// Reads an MF-JSON / GeoJSON text named `name` into `inp`: movers when `want_movers`,
/// else areas (a feature of the other kind is an error naming it). The error is a text
/// that cannot be read at all.
fn read_json(text: &str, name: &str, want_movers: bool, inp: &mut Inputs) -> Result<(), String> {
    let r = mfjson::read(text).map_err(|e| format!("{name}: {e}"))?;
    inp.warnings
        .extend(r.warnings.iter().map(|w| format!("{name}: {w}")));
    for (i, item) in r.items.into_iter().enumerate() {
        match item {
            Ok(mfjson::Item::Mover(t)) if want_movers => inp.movers.push(t),
            Ok(mfjson::Item::Area(a)) if !want_movers => inp.areas.push(a),
            Ok(mfjson::Item::Mover(t)) => inp.errors.push(format!(
                "{name}: feature {i} ({}) is a mover, not an area",
                t.id
            )),
            Ok(mfjson::Item::Area(a)) => inp.errors.push(format!(
                "{name}: feature {i} ({}) is an area, not a mover",
                a.id
            )),
            Err(e) => inp.errors.push(format!("{name}: {e}")),
        }
    }
    Ok(())
}

/// Every mover against every area (as `polyguard encounters` answers them, in its
/// order), the movers in parallel; the errors of areas and movers that cannot be
/// answered join `inp.errors`.
fn answer(inp: &mut Inputs, opts: &Options) -> Rows {
    let (areas, area_errors) = Areas::new(&inp.areas, opts.geodesy);
    inp.errors
        .extend(area_errors.iter().map(|e| format!("area {e}")));
    let answers: Vec<_> = inp
        .movers
        .par_iter()
        .map(|t| encounters_of(t, &areas, opts))
        .collect();
    let mut rows = Rows::default();
    for (t, ans) in inp.movers.iter().zip(answers) {
        match ans {
            Ok(list) => list.iter().for_each(|e| rows.push(e)),
            Err(e) => inp.errors.push(format!("mover {} {e}", t.id)),
        }
    }
    rows
}

/// The result handed to Python: (columns, errors, warnings); or `polyguard.Error` when
/// nothing could be read (no mover or no area, and errors that say why).
fn finish<'py>(
    py: Python<'py>,
    inp: Inputs,
    rows: Rows,
) -> PyResult<(Bound<'py, PyDict>, Vec<String>, Vec<String>)> {
    if !inp.errors.is_empty() && (inp.movers.is_empty() || inp.areas.is_empty()) {
        let what = if inp.movers.is_empty() {
            "movers"
        } else {
            "areas"
        };
        return Err(error(
            py,
            what,
            &format!("no {what} could be read:\n{}", inp.errors.join("\n")),
        ));
    }
    let d = PyDict::new(py);
    d.set_item("mover", PyList::new(py, rows.mover)?)?;
    d.set_item("callsign", PyList::new(py, rows.callsign)?)?;
    d.set_item("area", PyList::new(py, rows.area)?)?;
    d.set_item("relation", PyList::new(py, rows.relation)?)?;
    d.set_item("start_lo", PyArray1::from_vec(py, rows.start_lo))?;
    d.set_item("start_hi", PyArray1::from_vec(py, rows.start_hi))?;
    d.set_item("end_lo", PyArray1::from_vec(py, rows.end_lo))?;
    d.set_item("end_hi", PyArray1::from_vec(py, rows.end_hi))?;
    d.set_item("certain", PyArray1::from_vec(py, rows.certain))?;
    Ok((d, inp.errors, inp.warnings))
}

/// The encounters of MF-JSON movers (a FeatureCollection, a Feature or JSON Lines of
/// trajectories / MovingPoints) with GeoJSON / MF-JSON areas, as `polyguard encounters
/// MOVERS AREAS` answers them (docs/moving-features.md). Returns (columns, errors,
/// warnings): one entry per span in the columns `mover`, `callsign`, `area`, `relation`,
/// `start_lo`, `start_hi`, `end_lo`, `end_hi`, `certain`. Raises `polyguard.Error` when an
/// option is bad or nothing can be read. Runs without the GIL.
#[pyfunction]
#[pyo3(signature = (movers, areas, *, sep=0.0, sep_v=0.0, max_gap=60.0, geodesy="sphere"))]
pub fn _encounters_json<'py>(
    py: Python<'py>,
    movers: String,
    areas: String,
    sep: f64,
    sep_v: f64,
    max_gap: f64,
    geodesy: &str,
) -> PyResult<(Bound<'py, PyDict>, Vec<String>, Vec<String>)> {
    let opts = options(py, sep, sep_v, max_gap, geodesy)?;
    let done = py.detach(move || {
        let mut inp = Inputs::default();
        read_json(&movers, "movers", true, &mut inp)?;
        read_json(&areas, "areas", false, &mut inp)?;
        let rows = answer(&mut inp, &opts);
        Ok::<_, String>((inp, rows))
    });
    let (inp, rows) = done.map_err(|e| error(py, "input", &e))?;
    finish(py, inp, rows)
}

/// The columns of a table of fixes held as arrays.
type Texts = Vec<Option<String>>;

/// [`_encounters_json`] for movers given as the columns of a table of fixes (a pandas
/// frame of `traffic` or MovingPandas): `t_ns` nanoseconds since the epoch (numpy
/// `datetime64[ns]` as int64; its NaT is a missing time), `lon`, `lat`, `alt` (feet, NaN:
/// none; None: no column) and the texts `icao24`, `callsign`, `flight_id` (None: no
/// column), grouped into trajectories as the CSV of fixes is (docs/moving-features.md,
/// "CSV of fixes").
#[pyfunction]
#[pyo3(signature = (t_ns, lon, lat, alt, icao24, callsign, flight_id, areas, *, sep=0.0,
    sep_v=0.0, max_gap=60.0, geodesy="sphere"))]
#[allow(clippy::too_many_arguments)] // the columns of a table, each its own argument
pub fn _encounters_columns<'py>(
    py: Python<'py>,
    t_ns: PyReadonlyArray1<'py, i64>,
    lon: PyReadonlyArray1<'py, f64>,
    lat: PyReadonlyArray1<'py, f64>,
    alt: Option<PyReadonlyArray1<'py, f64>>,
    icao24: Texts,
    callsign: Option<Texts>,
    flight_id: Option<Texts>,
    areas: String,
    sep: f64,
    sep_v: f64,
    max_gap: f64,
    geodesy: &str,
) -> PyResult<(Bound<'py, PyDict>, Vec<String>, Vec<String>)> {
    let opts = options(py, sep, sep_v, max_gap, geodesy)?;
    // NaT (the least int64) is no time: NaN, refused by the row's check.
    let t: Vec<f64> = t_ns
        .as_array()
        .iter()
        .map(|&ns| {
            if ns == i64::MIN {
                f64::NAN
            } else {
                from_nanos(ns)
            }
        })
        .collect();
    let lon = lon.as_array().to_vec();
    let lat = lat.as_array().to_vec();
    let alt = alt.map(|a| a.as_array().to_vec());
    let done = py.detach(move || {
        let cols = FixColumns {
            t: &t,
            lon: &lon,
            lat: &lat,
            alt_ft: alt.as_deref(),
            icao24: &icao24,
            callsign: callsign.as_deref(),
            flight_id: flight_id.as_deref(),
        };
        let r = fixes_table::read(&cols).map_err(|e| format!("movers: {e}"))?;
        let mut inp = Inputs {
            movers: r.trajectories,
            errors: r.errors.iter().map(|e| format!("movers: {e}")).collect(),
            warnings: r.warnings.iter().map(|w| format!("movers: {w}")).collect(),
            ..Inputs::default()
        };
        read_json(&areas, "areas", false, &mut inp)?;
        let rows = answer(&mut inp, &opts);
        Ok::<_, String>((inp, rows))
    });
    let (inp, rows) = done.map_err(|e| error(py, "input", &e))?;
    finish(py, inp, rows)
}
