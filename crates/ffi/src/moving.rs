//! `pg_encounters`: whole flights against areas (docs/moving-features.md), the answer of
//! `polyguard encounters` as the same JSON Lines, in a text the library allocates and
//! `pg_free_text` frees.

use std::ffi::CString;
use std::os::raw::{c_char, c_int};

use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::moving::answer::encounter_json;
use polyguard_earth::moving::broad::{encounters_of, Areas};
use polyguard_earth::moving::encounter::Options;
use polyguard_earth::moving::model::{Area, Trajectory};
use polyguard_earth::moving::{fixes_csv, mfjson};

use crate::{
    guard, Failure, PG_ERR_BAD_PARAMETER, PG_ERR_INPUT, PG_ERR_NULL_POINTER, PG_ERR_UTF8,
    PG_PARTIAL,
};

/// `pg_encounter_options.geodesy`: the sphere of radius 3440.065 nm.
pub const PG_GEODESY_SPHERE: c_int = 0;
/// `pg_encounter_options.geodesy`: the WGS84 ellipsoid.
pub const PG_GEODESY_WGS84: c_int = 1;

/// What `pg_encounters` asks of every pair of mover and area (the options of
/// `polyguard encounters`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PgEncounterOptions {
    /// D, nautical miles (≥ 0): near means within D horizontally (0: near is inside).
    pub sep_nm: f64,
    /// H, feet (≥ 0): near also means within H of the area's floor–ceiling slab.
    pub sep_v_ft: f64,
    /// Fixes more than this many seconds apart are not joined (≥ 0; 60 by default).
    pub max_gap_s: f64,
    /// `PG_GEODESY_SPHERE` or `PG_GEODESY_WGS84`.
    pub geodesy: c_int,
}

/// Writes the defaults of `polyguard encounters` into `*out`: D = H = 0, gaps beyond
/// 60 s, the sphere. Returns `PG_OK`, or `PG_ERR_NULL_POINTER` when `out` is NULL.
///
/// # Safety
/// `out` is NULL or points to a writable `pg_encounter_options`.
#[no_mangle]
pub unsafe extern "C" fn pg_encounter_options_default(out: *mut PgEncounterOptions) -> c_int {
    guard(|| {
        if out.is_null() {
            return Err(Failure::new(PG_ERR_NULL_POINTER, "out: NULL".into()));
        }
        // SAFETY: `out` is non-NULL and writable (the caller's promise).
        unsafe {
            out.write(PgEncounterOptions {
                sep_nm: 0.0,
                sep_v_ft: 0.0,
                max_gap_s: 60.0,
                geodesy: PG_GEODESY_SPHERE,
            })
        };
        Ok(())
    })
}

/// The options checked as the CLI checks its flags.
fn options(o: &PgEncounterOptions) -> Result<Options, Failure> {
    for (name, x) in [
        ("sep_nm", o.sep_nm),
        ("sep_v_ft", o.sep_v_ft),
        ("max_gap_s", o.max_gap_s),
    ] {
        if !x.is_finite() || x < 0.0 {
            return Err(Failure::new(
                PG_ERR_BAD_PARAMETER,
                format!("{name}: {x}: must be a finite number ≥ 0"),
            ));
        }
    }
    let geodesy = match o.geodesy {
        PG_GEODESY_SPHERE => Geodesy::Sphere,
        PG_GEODESY_WGS84 => Geodesy::Wgs84,
        g => {
            return Err(Failure::new(
                PG_ERR_BAD_PARAMETER,
                format!("geodesy: {g}: PG_GEODESY_SPHERE or PG_GEODESY_WGS84 expected"),
            ))
        }
    };
    Ok(Options {
        sep_nm: o.sep_nm,
        sep_v_ft: o.sep_v_ft,
        max_gap_s: o.max_gap_s,
        geodesy,
    })
}

/// The caller's bytes `(ptr, len)` named `name` as UTF-8 text.
///
/// # Safety
/// `ptr` is NULL or points to `len` readable bytes.
unsafe fn text<'a>(name: &str, ptr: *const c_char, len: usize) -> Result<&'a str, Failure> {
    if ptr.is_null() {
        return Err(Failure::new(PG_ERR_NULL_POINTER, format!("{name}: NULL")));
    }
    // SAFETY: `ptr` holds `len` readable bytes (the caller's promise), read during the
    // call only.
    let bytes = unsafe { std::slice::from_raw_parts(ptr.cast::<u8>(), len) };
    std::str::from_utf8(bytes).map_err(|e| {
        Failure::new(
            PG_ERR_UTF8,
            format!("{name}: not UTF-8 (byte {})", e.valid_up_to()),
        )
    })
}

/// The movers and areas read, and the messages of what was rejected.
#[derive(Default)]
struct Inputs {
    movers: Vec<Trajectory>,
    areas: Vec<Area>,
    errors: Vec<String>,
}

/// Reads the movers (CSV of fixes, or MF-JSON) and the areas (GeoJSON / MF-JSON) as the
/// CLI reads its two files; a text that cannot be read at all is `PG_ERR_INPUT`.
fn read(movers: &str, movers_is_csv: bool, areas: &str) -> Result<Inputs, Failure> {
    let fatal = |e: String| Failure::new(PG_ERR_INPUT, e);
    let mut inp = Inputs::default();
    if movers_is_csv {
        let r = fixes_csv::read(movers).map_err(|e| fatal(format!("movers: {e}")))?;
        inp.movers = r.trajectories;
        inp.errors
            .extend(r.errors.iter().map(|e| format!("movers: {e}")));
    } else {
        read_json(movers, "movers", true, &mut inp).map_err(fatal)?;
    }
    read_json(areas, "areas", false, &mut inp).map_err(fatal)?;
    Ok(inp)
}

/// One MF-JSON / GeoJSON text into `inp`: movers when `want_movers`, else areas (a
/// feature of the other kind is an error naming it).
fn read_json(text: &str, name: &str, want_movers: bool, inp: &mut Inputs) -> Result<(), String> {
    let r = mfjson::read(text).map_err(|e| format!("{name}: {e}"))?;
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

/// The JSON Lines of every mover against every area, in the CLI's order; rejected
/// areas and movers join `inp.errors`.
fn answer(inp: &mut Inputs, opts: &Options) -> String {
    let (areas, area_errors) = Areas::new(&inp.areas, opts.geodesy);
    inp.errors
        .extend(area_errors.iter().map(|e| format!("area {e}")));
    let mut out = String::new();
    for t in &inp.movers {
        match encounters_of(t, &areas, opts) {
            Ok(list) => {
                for e in &list {
                    out.push_str(&encounter_json(e).to_string());
                    out.push('\n');
                }
            }
            Err(e) => inp.errors.push(format!("mover {} {e}", t.id)),
        }
    }
    out
}

/// Every mover against every area (docs/moving-features.md): the JSON Lines that
/// `polyguard encounters MOVERS AREAS` writes for the same inputs and options, byte for
/// byte, one line per pair that meets.
///
/// - `movers`, `movers_len`: the movers' text, UTF-8 (not NUL-terminated; its length in
///   bytes): a CSV of fixes when `movers_is_csv` is non-zero, else MF-JSON.
/// - `areas`, `areas_len`: GeoJSON / MF-JSON areas, UTF-8.
/// - `opts`: the options; NULL takes the defaults (`pg_encounter_options_default`).
/// - `*out`, `*out_len`: on `PG_OK` and `PG_PARTIAL`, a NUL-terminated text the library
///   allocates (free it with `pg_free_text`) and its length without the NUL; on any
///   other status, NULL and 0.
///
/// Returns `PG_OK`; `PG_PARTIAL` when some features, rows, areas or movers were
/// rejected (the others are answered; `pg_last_error_message` lists the rejections, one
/// a line, as the CLI's standard error does); `PG_ERR_NULL_POINTER` (a NULL text, `out`
/// or `out_len`), `PG_ERR_UTF8` (a text that is not UTF-8), `PG_ERR_INPUT` (a text that
/// cannot be read at all: not JSON, a CSV without its header), `PG_ERR_BAD_PARAMETER`
/// (an option out of range).
///
/// # Safety
/// `movers` and `areas` are NULL or point to `movers_len` / `areas_len` readable bytes;
/// `opts` is NULL or points to a `pg_encounter_options`; `out` and `out_len` are NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn pg_encounters(
    movers: *const c_char,
    movers_len: usize,
    movers_is_csv: c_int,
    areas: *const c_char,
    areas_len: usize,
    opts: *const PgEncounterOptions,
    out: *mut *mut c_char,
    out_len: *mut usize,
) -> c_int {
    guard(|| {
        if out.is_null() || out_len.is_null() {
            let which = if out.is_null() { "out" } else { "out_len" };
            return Err(Failure::new(PG_ERR_NULL_POINTER, format!("{which}: NULL")));
        }
        // SAFETY: both are non-NULL and writable (the caller's promise).
        unsafe {
            out.write(core::ptr::null_mut());
            out_len.write(0);
        }
        let opts = if opts.is_null() {
            Options::default()
        } else {
            // SAFETY: non-NULL and readable (the caller's promise).
            options(unsafe { &*opts })?
        };
        // SAFETY: the texts' pointers and lengths are the caller's promise.
        let (m, a) = unsafe {
            (
                text("movers", movers, movers_len)?,
                text("areas", areas, areas_len)?,
            )
        };
        let mut inp = read(m, movers_is_csv != 0, a)?;
        let lines = answer(&mut inp, &opts);
        // serde_json escapes every control character: the lines hold no NUL byte.
        let c = CString::new(lines)
            .map_err(|_| Failure::new(crate::PG_ERR_INVALID, "a NUL byte in the answer".into()))?;
        let n = c.as_bytes().len();
        // SAFETY: both are non-NULL and writable (checked above).
        unsafe {
            out.write(c.into_raw());
            out_len.write(n);
        }
        if !inp.errors.is_empty() {
            // Not a failure: the answer stays written; the status and the message say
            // what was left out.
            return Err(Failure::new(PG_PARTIAL, inp.errors.join("\n")));
        }
        Ok(())
    })
}

/// Frees a text that `pg_encounters` allocated; NULL is ignored. (Extends this
/// interface's ownership rule: the one kind of memory the library hands out.)
///
/// # Safety
/// `text` is NULL or a pointer `pg_encounters` wrote into `*out`, not yet freed.
#[no_mangle]
pub unsafe extern "C" fn pg_free_text(text: *mut c_char) {
    if !text.is_null() {
        // SAFETY: made by CString::into_raw in pg_encounters, freed once (the caller's
        // promise).
        drop(unsafe { CString::from_raw(text) });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PG_OK;

    #[test]
    fn null_pointers_and_bad_utf8_are_statuses() {
        let areas = br#"{"type":"FeatureCollection","features":[]}"#;
        let (mut out, mut len) = (core::ptr::null_mut(), 0usize);
        // SAFETY: every pointer is NULL or valid for its length.
        unsafe {
            let rc = pg_encounters(
                core::ptr::null(),
                0,
                0,
                areas.as_ptr().cast(),
                areas.len(),
                core::ptr::null(),
                &mut out,
                &mut len,
            );
            assert_eq!(rc, PG_ERR_NULL_POINTER);
            assert!(out.is_null());
            let bad = [0xffu8, 0xfe];
            let rc = pg_encounters(
                bad.as_ptr().cast(),
                bad.len(),
                0,
                areas.as_ptr().cast(),
                areas.len(),
                core::ptr::null(),
                &mut out,
                &mut len,
            );
            assert_eq!(rc, PG_ERR_UTF8);
            let rc = pg_encounters(
                areas.as_ptr().cast(),
                areas.len(),
                0,
                areas.as_ptr().cast(),
                areas.len(),
                core::ptr::null(),
                &mut out,
                core::ptr::null_mut(),
            );
            assert_eq!(rc, PG_ERR_NULL_POINTER);
            let rc = pg_encounters(
                areas.as_ptr().cast(),
                areas.len(),
                0,
                areas.as_ptr().cast(),
                areas.len(),
                core::ptr::null(),
                &mut out,
                &mut len,
            );
            assert_eq!((rc, len), (PG_OK, 0));
            pg_free_text(out);
        }
    }
}
