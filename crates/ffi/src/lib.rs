//! The C interface of polyguard: paper A's detection (Narkawicz & Hagen, §II.H, §II.I,
//! §III), its entry time, the batch, and the certified intervals of inside, near_D and
//! breach_D with keep-in exit detection (docs/cases.md, "Separation and fences"), over
//! plain C arrays.
//!
//! The header is `include/polyguard.h`, generated from this file by cbindgen
//! (`cbindgen.toml`; `tests/header.rs` fails when the checked-in header is stale and
//! rewrites it with `UPDATE_HEADER=1`).
//!
//! Rules every entry point follows (they extend the engine's API, `polyguard::api` and
//! `polyguard::batch`, to C):
//!
//! - It returns an `int` status: `PG_OK` or a negative `PG_ERR_*` code, one per kind
//!   of bad input, and keeps a message naming the field (`polygon.vertices: clockwise
//!   order …`) for `pg_last_error_message`, per thread.
//! - It never unwinds into C: its body runs under `std::panic::catch_unwind`, and a
//!   panic becomes `PG_ERR_PANIC`.
//! - It reads the caller's arrays only during the call and never keeps a pointer; it
//!   never allocates memory the caller must free (the batch and `pg_intervals` write
//!   into the caller's array and say how many items the answer has), but for the text
//!   of `pg_encounters`, whose length only the answer knows, freed by `pg_free_text`.
//! - The way out ([`wayout`]): certified course, speed and vertical speed bands,
//!   recovery points, offsets and insets, into the caller's buffers.
//! - `pg_encounters` (whole flights against areas, docs/moving-features.md, in
//!   [`moving`]) may also return `PG_PARTIAL` (> 0): answered, some input rejected.
//! - On an error, the answer written for a single case is the most conservative one
//!   (detected; entry possible at any time; one possible span over all time), so that a
//!   caller who forgets the status still does not read "no".
#![deny(missing_docs)]

use std::cell::RefCell;
use std::os::raw::{c_char, c_int};
use std::panic::{catch_unwind, AssertUnwindSafe};

use polyguard::api::{self, Case, Detection, Kind, MovingPoint, MovingPolygon, Params};
use polyguard::batch;
use polyguard::entry::EntryTime;
use polyguard::error::CaseError;
use polyguard::well_formed::Fault;
use polyguard::{Method, Relation, Separation, Span, Vect2};

pub mod moving;
pub mod wayout;
pub use moving::{
    pg_encounter_options_default, pg_encounters, pg_free_text, PgEncounterOptions,
    PG_GEODESY_SPHERE, PG_GEODESY_WGS84,
};
pub use wayout::{
    pg_course_bands, pg_inset, pg_offset, pg_recovery, pg_speed_bands, pg_vertical_speed_bands,
    PgBand, PgBandsInfo, PgRecoveryPoint, PgRing, PgShapeInfo, PG_BAND_CLEAR, PG_BAND_CONFLICT,
    PG_BAND_UNKNOWN, PG_ERR_UNCERTIFIED, PG_FENCE_KEEP_IN, PG_FENCE_KEEP_OUT,
    PG_RECOVERY_IMPOSSIBLE, PG_RECOVERY_NONE, PG_RECOVERY_POINT,
};

/// Success.
pub const PG_OK: c_int = 0;
/// A pointer that must not be NULL is NULL (the message names it).
pub const PG_ERR_NULL_POINTER: c_int = -1;
/// A coordinate, speed or parameter is NaN or infinite (the message names it, down to
/// the coordinate: `polygon.vertices[2][1]`).
pub const PG_ERR_NOT_FINITE: c_int = -2;
/// A polygon has fewer than 3 vertices (paper A §II).
pub const PG_ERR_TOO_FEW_VERTICES: c_int = -3;
/// An array has the wrong length: batch offsets that do not start at 0 or decrease, or
/// a length too large to address.
pub const PG_ERR_WRONG_LENGTH: c_int = -4;
/// A polygon's vertices run clockwise; paper A §II lists them counterclockwise.
pub const PG_ERR_CLOCKWISE: c_int = -5;
/// A polygon's edges cross (paper A §II needs a simple polygon).
pub const PG_ERR_SELF_INTERSECTING: c_int = -6;
/// A polygon's vertices all lie on one line: it encloses nothing.
pub const PG_ERR_ZERO_AREA: c_int = -7;
/// 2D and 3D mixed: a point with a height (`has_z`) and a polygon without a slab, or
/// the reverse (paper A §III).
pub const PG_ERR_DIMENSION_MISMATCH: c_int = -8;
/// A parameter outside its domain: lookahead or buff not > 0, fac outside (0, 1),
/// kappa_deg outside (0, 180), a separation below 0, a relation that is not a
/// `PG_RELATION_*`.
pub const PG_ERR_BAD_PARAMETER: c_int = -9;
/// A slab's bottom lies above its top (paper A §III).
pub const PG_ERR_SLAB_INVERTED: c_int = -10;
/// The caller's buffer is too small: the batch's hits or `pg_intervals`' spans (the first
/// `cap` are written and the count of the whole answer is still written), or the error
/// message (truncated, still NUL-terminated).
pub const PG_ERR_CAPACITY: c_int = -11;
/// The engine panicked: a bug in polyguard, caught at the boundary (please report it
/// with the input).
pub const PG_ERR_PANIC: c_int = -12;
/// Any other invalid input: a pointer not aligned for its type (the message names it).
pub const PG_ERR_INVALID: c_int = -13;
/// A text that must be UTF-8 is not (`pg_encounters`; the message names it and the
/// first bad byte).
pub const PG_ERR_UTF8: c_int = -14;
/// An input text that cannot be read at all (`pg_encounters`: not JSON, a CSV without
/// its header line; the message says where).
pub const PG_ERR_INPUT: c_int = -15;
/// Not an error: the answer is written, but some of the input was rejected
/// (`pg_encounters`: features, rows, areas or movers; `pg_last_error_message` lists them,
/// one a line). The only status above 0.
pub const PG_PARTIAL: c_int = 1;

/// `pg_detection.kind` and `pg_hit.kind`: every comparison behind the answer was
/// certified; paper A computed without rounding answers the same.
pub const PG_KIND_EXACT: c_int = 0;
/// A "yes" taken on a comparison f64 could not decide; paper A without rounding may
/// answer no. Never a "no".
pub const PG_KIND_CONSERVATIVE: c_int = 1;

/// No method: the call failed.
pub const PG_METHOD_NONE: c_int = 0;
/// Paper A §II.H detect_same_2D: all vertex velocities equal (statically shaped).
pub const PG_METHOD_SAME_2D: c_int = 1;
/// Paper A §II.I detect_diff_2D: a warping polygon.
pub const PG_METHOD_DIFF_2D: c_int = 2;
/// Paper A §III detect_3D: a point with a height and a polygon with a slab.
pub const PG_METHOD_3D: c_int = 3;

/// `PgEntryTime::kind`: certified, the point never enters during [0, T].
pub const PG_ENTRY_NEVER: c_int = 0;
/// Certified: the point enters, first at a time in [lo, hi].
pub const PG_ENTRY_ENTERS: c_int = 1;
/// Not certified either way: no entry before lo; if the point enters, it is first at a
/// time in [lo, hi] (hi is then T).
pub const PG_ENTRY_POSSIBLE: c_int = 2;

/// `pg_intervals`' relation inside(t): the point is in the closed polygon P(t) (and, in
/// 3D, in the closed slab). Definitions: docs/cases.md, "Separation and fences".
pub const PG_RELATION_INSIDE: c_int = 0;
/// near_D(t): the point is within D horizontally of the closed P(t) (and, in 3D, within
/// H of the slab): the first span's start is the time of loss of separation.
pub const PG_RELATION_NEAR: c_int = 1;
/// breach_D(t), for a keep-in fence: the point is not inside P(t) at a distance > D from
/// its boundary (or, in 3D, not more than H inside the slab's bottom and top).
pub const PG_RELATION_BREACH: c_int = 2;

/// A 2D vector or point (paper A §I); the same layout as two `double`s.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgVec2 {
    /// The first coordinate.
    pub x: f64,
    /// The second coordinate.
    pub y: f64,
}

/// The moving point s + t·v (paper A §II), with height z + t·vz when `has_z` is non-zero
/// (§III; `z` and `vz` are ignored otherwise).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgPoint {
    /// s, the horizontal position at t = 0.
    pub pos: PgVec2,
    /// v, the horizontal velocity.
    pub vel: PgVec2,
    /// Non-zero for a 3D point.
    pub has_z: c_int,
    /// The height at t = 0 (3D only).
    pub z: f64,
    /// The vertical speed (3D only).
    pub vz: f64,
}

/// The vertical extent of a 3D polygon (paper A §III): bottom + t·vz ≤ z ≤ top + t·vz.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgSlab {
    /// pmin, the bottom at t = 0.
    pub bottom: f64,
    /// pmax, the top at t = 0 (not below the bottom).
    pub top: f64,
    /// vsp, the slab's vertical speed.
    pub vz: f64,
}

/// A moving polygon P + t·V (paper A §II): `n` ≥ 3 vertices in counterclockwise order,
/// simple; `velocities` NULL for a polygon at rest, else `n` velocities, one per vertex;
/// with a slab (§III) when `has_slab` is non-zero. The arrays are the caller's, read
/// during the call only.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct PgPolygon {
    /// P: `n` vertices.
    pub vertices: *const PgVec2,
    /// V: `n` velocities, or NULL (all zero).
    pub velocities: *const PgVec2,
    /// The number of vertices.
    pub n: usize,
    /// Non-zero for a 3D polygon.
    pub has_slab: c_int,
    /// The slab (3D only).
    pub slab: PgSlab,
}

/// Many moving polygons in flat arrays, for `pg_detect_batch`: polygon i has the
/// vertices `vertices[offsets[i]] … vertices[offsets[i + 1] - 1]` (and the velocities at
/// the same indices, or all at rest when `velocities` is NULL); `offsets` holds
/// `count + 1` entries, `offsets[0] == 0`, never decreasing. `slabs` is NULL for 2D
/// polygons, else `count` slabs (paper A §III).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct PgPolygons {
    /// All vertices, polygon after polygon: `offsets[count]` of them.
    pub vertices: *const PgVec2,
    /// As many velocities, or NULL.
    pub velocities: *const PgVec2,
    /// `count + 1` offsets into `vertices`.
    pub offsets: *const usize,
    /// The number of polygons.
    pub count: usize,
    /// `count` slabs, or NULL for 2D polygons.
    pub slabs: *const PgSlab,
}

/// The case's parameters: the lookahead T (> 0), BUFF (> 0, paper A §II.A), F (in
/// (0, 1), §II.I) and the corner angle κ in degrees (in (0, 180), §II.J).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgParams {
    /// T, the lookahead time.
    pub lookahead: f64,
    /// BUFF, the distance that counts as contact.
    pub buff: f64,
    /// F, the relative slack of detect_diff_2D and detect_3D.
    pub fac: f64,
    /// κ in degrees, for the well-formedness check only.
    pub kappa_deg: f64,
}

/// The answer of `pg_detect` (paper A §II.H, §II.I, §III; §II.J for `well_formed`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgDetection {
    /// 1 when the point comes within BUFF (or the F slack) of the polygon during
    /// [0, T], or when a comparison on the way could not be decided; else 0.
    pub detected: c_int,
    /// `PG_KIND_EXACT` or `PG_KIND_CONSERVATIVE`.
    pub kind: c_int,
    /// `PG_METHOD_*`: which paper function decided.
    pub method: c_int,
    /// 1 when the polygon is well formed at t = 0 (§II.J), for information only: a
    /// polygon that is not is still checked.
    pub well_formed: c_int,
    /// 0 when well formed, else the first §II.J rule that fails (1 to 4).
    pub well_formed_rule: c_int,
    /// The vertex the failing rule names (rule 1: the first of two close vertices;
    /// rule 2: the start of the first of two close edges; rules 3, 4: the corner).
    pub well_formed_a: usize,
    /// The second vertex rules 1 and 2 name (the start of the second edge for rule 2);
    /// equal to `well_formed_a` for rules 3 and 4.
    pub well_formed_b: usize,
}

/// The answer of `pg_detect_time`: where the first time the point is in the closed
/// polygon (and slab) lies.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgEntryTime {
    /// `PG_ENTRY_NEVER`, `PG_ENTRY_ENTERS` or `PG_ENTRY_POSSIBLE`.
    pub kind: c_int,
    /// No entry before lo (NaN for `PG_ENTRY_NEVER`).
    pub lo: f64,
    /// Entered by hi (`PG_ENTRY_ENTERS`), or T (`PG_ENTRY_POSSIBLE`); NaN for
    /// `PG_ENTRY_NEVER`.
    pub hi: f64,
}

/// One detected pair of `pg_detect_batch`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgHit {
    /// The point's index in the points given.
    pub point: usize,
    /// The polygon's index in the polygons given.
    pub polygon: usize,
    /// `PG_KIND_EXACT` or `PG_KIND_CONSERVATIVE`.
    pub kind: c_int,
    /// `PG_METHOD_*`.
    pub method: c_int,
}

/// The separations of near_D and breach_D (docs/cases.md, "Separation and fences"):
/// D horizontally, H vertically (3D only); each finite and ≥ 0.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgSeparation {
    /// D ≥ 0, a length (the case format's `sep`).
    pub d: f64,
    /// H ≥ 0, a height (the case format's `sep_v`; ignored in 2D).
    pub h: f64,
}

/// One span of `pg_intervals`: the relation starts in [start_lo, start_hi] and stops in
/// [end_lo, end_hi] (start_lo ≤ start_hi ≤ end_lo ≤ end_hi, all in [0, T]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgSpan {
    /// The start enclosure's lower end.
    pub start_lo: f64,
    /// The start enclosure's upper end.
    pub start_hi: f64,
    /// The end enclosure's lower end.
    pub end_lo: f64,
    /// The end enclosure's upper end.
    pub end_hi: f64,
    /// 1: the relation holds throughout [start_hi, end_lo]; 0 (possible): f64 could not
    /// settle the stretch, the relation may hold there or not.
    pub certain: c_int,
}

impl From<&Span> for PgSpan {
    /// The engine's span (src/intervals.rs, G1–G3), field for field.
    fn from(s: &Span) -> Self {
        PgSpan {
            start_lo: s.start.lo,
            start_hi: s.start.hi,
            end_lo: s.end.lo,
            end_hi: s.end.hi,
            certain: c_int::from(s.certain),
        }
    }
}

/// A failed call: its status and its message.
struct Failure {
    code: c_int,
    message: String,
}

impl Failure {
    /// A failure with its status and message.
    fn new(code: c_int, message: String) -> Self {
        Failure { code, message }
    }

    /// `field` is NULL where a pointer is required.
    fn null(field: &str) -> Self {
        Failure::new(PG_ERR_NULL_POINTER, format!("{field}: NULL pointer"))
    }

    /// `field` is not aligned for its type.
    fn misaligned(field: &str) -> Self {
        Failure::new(
            PG_ERR_INVALID,
            format!("{field}: misaligned pointer (not a pointer to this type)"),
        )
    }

    /// An engine error, its message with the field renamed (`point.` to `points[3].`
    /// in a batch).
    fn case(e: CaseError, rename: Option<(&str, String)>) -> Self {
        let mut message = e.to_string();
        if let Some((from, to)) = rename {
            if let Some(rest) = message.strip_prefix(from) {
                message = format!("{to}{rest}");
            }
        }
        Failure::new(status_of(&e), message)
    }
}

/// The status code of an engine error (extends polyguard::error::CaseError to C).
fn status_of(e: &CaseError) -> c_int {
    match e {
        CaseError::NotFinite { .. } | CaseError::NotJsonNumber { .. } => PG_ERR_NOT_FINITE,
        CaseError::TooFewVertices { .. } => PG_ERR_TOO_FEW_VERTICES,
        CaseError::WrongLength { .. } | CaseError::PointLength { .. } => PG_ERR_WRONG_LENGTH,
        CaseError::Clockwise { .. } => PG_ERR_CLOCKWISE,
        CaseError::SelfIntersecting { .. } => PG_ERR_SELF_INTERSECTING,
        CaseError::ZeroArea => PG_ERR_ZERO_AREA,
        CaseError::DimensionMismatch { .. } => PG_ERR_DIMENSION_MISMATCH,
        CaseError::NotPositive { .. } | CaseError::OutOfRange { .. } => PG_ERR_BAD_PARAMETER,
        CaseError::SlabInverted { .. } => PG_ERR_SLAB_INVERTED,
        CaseError::Syntax { .. }
        | CaseError::Missing { .. }
        | CaseError::WrongType { .. }
        | CaseError::UnknownField { .. } => PG_ERR_INVALID,
    }
}

thread_local! {
    /// The message of this thread's last failed call ("" after a successful one).
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Keeps `message` as this thread's last error (for `pg_last_error_message`).
fn set_last_error(message: String) {
    LAST_ERROR.with(|m| *m.borrow_mut() = message);
}

/// Runs an entry point's body: clears the thread's message, catches a panic (never
/// unwinds into C), records a failure's message and returns its status.
fn guard<F: FnOnce() -> Result<(), Failure>>(body: F) -> c_int {
    set_last_error(String::new());
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => PG_OK,
        Ok(Err(f)) => {
            set_last_error(f.message);
            f.code
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| String::from(*s))
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| String::from("no message"));
            set_last_error(format!(
                "internal error: polyguard panicked ({what}); please report it with the input"
            ));
            PG_ERR_PANIC
        }
    }
}

/// A C array as a slice: NULL only when empty (then an empty slice); a length whose
/// bytes exceed isize::MAX is refused.
///
/// # Safety
/// A non-NULL `ptr` must point to `len` valid, initialised `T`s that stay unchanged
/// during the call.
unsafe fn slice_of<'a, T>(ptr: *const T, len: usize, field: &str) -> Result<&'a [T], Failure> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(Failure::null(field));
    }
    if !ptr.is_aligned() {
        return Err(Failure::misaligned(field));
    }
    if len > isize::MAX as usize / core::mem::size_of::<T>().max(1) {
        return Err(Failure::new(
            PG_ERR_WRONG_LENGTH,
            format!("{field}: {len} elements are more than memory can hold"),
        ));
    }
    // SAFETY: non-null, the caller's promise of `len` valid elements, size checked.
    Ok(unsafe { core::slice::from_raw_parts(ptr, len) })
}

/// A reference to a caller's struct, or the NULL-pointer failure naming it.
///
/// # Safety
/// A non-NULL `ptr` must point to a valid `T`.
unsafe fn deref<'a, T>(ptr: *const T, field: &str) -> Result<&'a T, Failure> {
    if !ptr.is_aligned() {
        return Err(Failure::misaligned(field));
    }
    // SAFETY: aligned, and the caller's promise.
    unsafe { ptr.as_ref() }.ok_or_else(|| Failure::null(field))
}

/// The caller's struct an entry point writes its answer into, or the failure naming
/// it (misaligned or NULL); checked before `guard` so the answer's default can be
/// written first.
///
/// # Safety
/// A non-NULL `ptr` must point to a writable `T`.
unsafe fn out_of<'a, T>(ptr: *mut T, field: &str) -> Result<&'a mut T, Failure> {
    if !ptr.is_aligned() {
        return Err(Failure::misaligned(field));
    }
    // SAFETY: aligned, and the caller's promise.
    unsafe { ptr.as_mut() }.ok_or_else(|| Failure::null(field))
}

/// A caller's output buffer of `cap` elements: NULL or misaligned is refused unless
/// `cap` is 0.
fn buffer_ok<T>(ptr: *mut T, cap: usize, field: &str) -> Result<(), Failure> {
    if cap > 0 && ptr.is_null() {
        return Err(Failure::null(field));
    }
    if cap > 0 && !ptr.is_aligned() {
        return Err(Failure::misaligned(field));
    }
    Ok(())
}

/// The `PG_ERR_CAPACITY` failure of a buffer `field` with room for `cap` of the
/// `found` answers (`what` names them): the first `cap` are written.
fn capacity_failure(field: &str, what: &str, found: usize, cap: usize) -> Failure {
    Failure::new(
        PG_ERR_CAPACITY,
        format!(
            "{field}: {found} {what}, room for {cap}; the first {cap} are written, call again \
             with cap >= {found}"
        ),
    )
}

/// The checked arrays of a `pg_polygons` (offsets from 0, never decreasing; each
/// array of the length the offsets say).
struct FlatPolygons<'a> {
    /// `count + 1` offsets into `vertices`.
    offsets: &'a [usize],
    /// All vertices, polygon after polygon.
    vertices: &'a [PgVec2],
    /// As many velocities, or None (at rest).
    velocities: Option<&'a [PgVec2]>,
    /// `count` slabs, or None (2D).
    slabs: Option<&'a [PgSlab]>,
}

/// Reads the flat arrays of `polys`, their fields named `{name}.offsets` and so on
/// (the layout `pg_detect_batch` documents).
///
/// # Safety
/// As `pg_detect_batch`'s `polygons`.
unsafe fn flat_polygons<'a>(polys: &PgPolygons, name: &str) -> Result<FlatPolygons<'a>, Failure> {
    let offsets_len = polys
        .count
        .checked_add(1)
        .ok_or_else(|| Failure::new(PG_ERR_WRONG_LENGTH, format!("{name}.count: too large")))?;
    // SAFETY (this function): the caller's promise of valid pointers and lengths.
    let offsets = unsafe { slice_of(polys.offsets, offsets_len, &format!("{name}.offsets")) }?;
    if offsets[0] != 0 {
        return Err(Failure::new(
            PG_ERR_WRONG_LENGTH,
            format!("{name}.offsets[0]: {}, 0 expected", offsets[0]),
        ));
    }
    if let Some(i) = (1..offsets.len()).find(|&i| offsets[i] < offsets[i - 1]) {
        return Err(Failure::new(
            PG_ERR_WRONG_LENGTH,
            format!(
                "{name}.offsets[{i}]: {} is less than offsets[{}] = {}",
                offsets[i],
                i - 1,
                offsets[i - 1]
            ),
        ));
    }
    let total = offsets[polys.count];
    let vertices = unsafe { slice_of(polys.vertices, total, &format!("{name}.vertices")) }?;
    let velocities = if polys.velocities.is_null() {
        None
    } else {
        Some(unsafe { slice_of(polys.velocities, total, &format!("{name}.velocities")) }?)
    };
    let slabs = if polys.slabs.is_null() {
        None
    } else {
        Some(unsafe { slice_of(polys.slabs, polys.count, &format!("{name}.slabs")) }?)
    };
    Ok(FlatPolygons {
        offsets,
        vertices,
        velocities,
        slabs,
    })
}

/// A polygon's vertex array and, unless NULL, its velocity array (`polygon->n` each).
///
/// # Safety
/// As `pg_detect`'s `polygon`.
unsafe fn polygon_slices<'a>(
    polygon: &PgPolygon,
) -> Result<(&'a [PgVec2], Option<&'a [PgVec2]>), Failure> {
    // SAFETY (this function): the caller's promise about the polygon's arrays.
    let vertices = unsafe { slice_of(polygon.vertices, polygon.n, "polygon.vertices") }?;
    let velocities = if polygon.velocities.is_null() {
        None
    } else {
        Some(unsafe { slice_of(polygon.velocities, polygon.n, "polygon.velocities") }?)
    };
    Ok((vertices, velocities))
}

/// The engine's vectors from C's (paper A §I's points and velocities).
fn vects(v: &[PgVec2]) -> Vec<Vect2> {
    v.iter().map(|p| Vect2::new(p.x, p.y)).collect()
}

/// The engine's parameters from the C ones (paper A §II.A, §II.I, §II.J).
fn params_of(p: &PgParams) -> Result<Params, Failure> {
    Params::new(p.buff)
        .and_then(|q| q.with_fac(p.fac))
        .and_then(|q| q.with_kappa_degrees(p.kappa_deg))
        .map_err(|e| Failure::case(e, None))
}

/// The engine's moving point from the C one (paper A §II, §III).
fn point_of(p: &PgPoint) -> Result<MovingPoint, CaseError> {
    if p.has_z != 0 {
        MovingPoint::new_3d([p.pos.x, p.pos.y, p.z], [p.vel.x, p.vel.y, p.vz])
    } else {
        MovingPoint::new_2d(Vect2::new(p.pos.x, p.pos.y), Vect2::new(p.vel.x, p.vel.y))
    }
}

/// The engine's validated polygon from vertex and velocity slices (paper A §II, §III).
fn polygon_of(
    vertices: &[PgVec2],
    velocities: Option<&[PgVec2]>,
    slab: Option<&PgSlab>,
) -> Result<MovingPolygon, CaseError> {
    let poly = MovingPolygon::new(vects(vertices), velocities.map(vects))?;
    match slab {
        Some(s) => poly.with_slab(s.bottom, s.top, s.vz),
        None => Ok(poly),
    }
}

/// The validated case behind `pg_detect` and `pg_detect_time` (paper A §II, §III).
///
/// # Safety
/// As `pg_detect`.
unsafe fn case_of(
    params: *const PgParams,
    point: *const PgPoint,
    polygon: *const PgPolygon,
) -> Result<Case, Failure> {
    // SAFETY (all three): the caller's promise of valid pointers or NULL.
    let params = unsafe { deref(params, "params") }?;
    let point = unsafe { deref(point, "point") }?;
    let polygon = unsafe { deref(polygon, "polygon") }?;
    let p = params_of(params)?;
    let pt = point_of(point).map_err(|e| Failure::case(e, None))?;
    // SAFETY: the caller's promise about the polygon's arrays.
    let (vertices, velocities) = unsafe { polygon_slices(polygon) }?;
    let slab = (polygon.has_slab != 0).then_some(&polygon.slab);
    let poly = polygon_of(vertices, velocities, slab).map_err(|e| Failure::case(e, None))?;
    Case::new(params.lookahead, pt, poly, p).map_err(|e| Failure::case(e, None))
}

/// The answer written on an error by `pg_detect` and `pg_detect_exit`: detected,
/// conservative, no method, not well formed (so an unchecked status never reads "no").
const CONSERVATIVE_DETECTION: PgDetection = PgDetection {
    detected: 1,
    kind: PG_KIND_CONSERVATIVE,
    method: PG_METHOD_NONE,
    well_formed: 0,
    well_formed_rule: 0,
    well_formed_a: 0,
    well_formed_b: 0,
};

/// The engine's answer (`api::detect` or `api::detect_exit`) for C: the §II.J fault as
/// its rule number (1 to 4, paper A's order) and the vertices it names.
fn detection_of(d: &Detection) -> PgDetection {
    let (rule, a, b) = match d.well_formed_fault {
        None => (0, 0, 0),
        Some(Fault::CloseVertices(i, j)) => (1, i, j),
        Some(Fault::CloseEdges(i, k)) => (2, i, k),
        Some(Fault::SharpCorner(j)) => (3, j, j),
        Some(Fault::TurnsRight(m)) => (4, m, m),
    };
    PgDetection {
        detected: c_int::from(d.detected),
        kind: kind_code(d.kind),
        method: method_code(d.method),
        well_formed: c_int::from(d.well_formed),
        well_formed_rule: rule,
        well_formed_a: a,
        well_formed_b: b,
    }
}

/// `PG_KIND_*` of the engine's kind of answer (exact, or a conservative yes).
fn kind_code(k: Kind) -> c_int {
    match k {
        Kind::Exact => PG_KIND_EXACT,
        Kind::Conservative => PG_KIND_CONSERVATIVE,
    }
}

/// `PG_METHOD_*` of the paper function that decided (paper A §II.F's dispatch, §III).
fn method_code(m: Method) -> c_int {
    match m {
        Method::DetectSame2d => PG_METHOD_SAME_2D,
        Method::DetectDiff2d => PG_METHOD_DIFF_2D,
        Method::Detect3d => PG_METHOD_3D,
    }
}

/// The parameters' defaults: F = 0.0001 (paper A §II.I's example) and κ = 5° (§II.J);
/// `lookahead` and `buff` are 0, which every call refuses (`PG_ERR_BAD_PARAMETER`)
/// until the caller sets them, as the paper gives them no default.
///
/// Returns `PG_OK`, or `PG_ERR_NULL_POINTER` when `out` is NULL.
///
/// # Safety
/// `out` is NULL or points to a writable `pg_params`.
#[no_mangle]
pub unsafe extern "C" fn pg_params_default(out: *mut PgParams) -> c_int {
    guard(|| {
        if !out.is_aligned() {
            return Err(Failure::misaligned("out"));
        }
        // SAFETY: aligned, and the caller's promise.
        let out = unsafe { out.as_mut() }.ok_or_else(|| Failure::null("out"))?;
        *out = PgParams {
            lookahead: 0.0,
            buff: 0.0,
            fac: Params::DEFAULT_FAC,
            kappa_deg: 5.0,
        };
        Ok(())
    })
}

/// Does the point come within BUFF of the polygon during [0, T]? Paper A end to end:
/// detect_3D (§III) when the point has a height and the polygon a slab, else
/// detect_same_2D (§II.H) when all vertex velocities are equal, else detect_diff_2D
/// (§II.I); plus the well-formedness check of §II.J at t = 0, for information.
///
/// The contract: if paper A computed without rounding says yes, `out->detected` is 1.
/// A 1 taken on a comparison f64 could not decide has `kind == PG_KIND_CONSERVATIVE`.
///
/// Returns `PG_OK`, or a `PG_ERR_*` code with a message naming the field (see
/// `pg_last_error_message`); on an error `*out` (when `out` is not NULL) holds the
/// conservative answer: detected 1, kind conservative, method `PG_METHOD_NONE`,
/// well_formed 0.
///
/// # Safety
/// Each pointer is NULL or valid for the call; `polygon->vertices` (and
/// `polygon->velocities` unless NULL) point to `polygon->n` elements. Nothing is kept.
#[no_mangle]
pub unsafe extern "C" fn pg_detect(
    params: *const PgParams,
    point: *const PgPoint,
    polygon: *const PgPolygon,
    out: *mut PgDetection,
) -> c_int {
    // SAFETY: the caller's promise.
    let out = match unsafe { out_of(out, "out") } {
        Ok(o) => o,
        Err(f) => return guard(|| Err(f)),
    };
    *out = CONSERVATIVE_DETECTION;
    guard(|| {
        // SAFETY: the caller's promise.
        let case = unsafe { case_of(params, point, polygon) }?;
        *out = detection_of(&api::detect(&case));
        Ok(())
    })
}

/// When does the point first lie in the closed polygon (and, in 3D, the slab) during
/// [0, T]? The moment paper A's detection (§II.H, §II.I, §III) guarantees to flag,
/// without BUFF: an f64 enclosure [lo, hi] of the exact first-entry time, by a certified
/// branch and bound over each edge's contact quadratics (§II.C's, without the BUFF
/// band). `PG_ENTRY_NEVER` is certified; `PG_ENTRY_ENTERS` certifies the entry and its
/// enclosure; `PG_ENTRY_POSSIBLE` says f64 could not tell (tangent contacts): no entry
/// before lo, and any entry is by hi = T.
///
/// BUFF, F and κ are not used, but `params` is validated as for `pg_detect`.
///
/// Returns `PG_OK` or a `PG_ERR_*` code (message: `pg_last_error_message`); on an error
/// `*out` (when `out` is not NULL) is `PG_ENTRY_POSSIBLE` on [0, +∞].
///
/// # Safety
/// As `pg_detect`.
#[no_mangle]
pub unsafe extern "C" fn pg_detect_time(
    params: *const PgParams,
    point: *const PgPoint,
    polygon: *const PgPolygon,
    out: *mut PgEntryTime,
) -> c_int {
    // SAFETY: the caller's promise.
    let out = match unsafe { out_of(out, "out") } {
        Ok(o) => o,
        Err(f) => return guard(|| Err(f)),
    };
    *out = PgEntryTime {
        kind: PG_ENTRY_POSSIBLE,
        lo: 0.0,
        hi: f64::INFINITY,
    };
    guard(|| {
        // SAFETY: the caller's promise.
        let case = unsafe { case_of(params, point, polygon) }?;
        *out = match api::detect_time(&case) {
            EntryTime::Never => PgEntryTime {
                kind: PG_ENTRY_NEVER,
                lo: f64::NAN,
                hi: f64::NAN,
            },
            EntryTime::Enters { lo, hi } => PgEntryTime {
                kind: PG_ENTRY_ENTERS,
                lo,
                hi,
            },
            EntryTime::Possible { lo, hi } => PgEntryTime {
                kind: PG_ENTRY_POSSIBLE,
                lo,
                hi,
            },
        };
        Ok(())
    })
}

/// Every point against every polygon (paper A §II.H, §II.I, §III per pair, behind a
/// broad phase that never drops a pair paper A detects; across threads): exactly the
/// pairs `pg_detect` answers detected, sorted by (point, polygon). A batch is all 2D or
/// all 3D (`points[i].has_z` all zero and `polygons->slabs` NULL, or the reverse).
///
/// Ownership: the library allocates nothing the caller frees. It writes at most `cap`
/// hits into the caller's `hits` (NULL allowed when `cap` is 0) and the total number of
/// hits into `*n_hits`. When the total exceeds `cap`, the first `cap` hits (in order) are
/// written and the status is `PG_ERR_CAPACITY`: call again with `cap >= *n_hits` (at
/// most `n_points * polygons->count` hits exist). So a truncated answer is never a
/// `PG_OK`.
///
/// Returns `PG_OK`, `PG_ERR_CAPACITY`, or another `PG_ERR_*` code with a message naming
/// the element (`polygons[2].vertices: clockwise order …`, `points[0].pos: …`); on
/// those `*n_hits` is 0.
///
/// # Safety
/// Each pointer is NULL or valid for the call: `points` holds `n_points` points,
/// `polygons->offsets` `polygons->count + 1` offsets, `polygons->vertices` (and
/// `velocities` unless NULL) `offsets[count]` elements, `polygons->slabs` (unless
/// NULL) `count` slabs, `hits` room for `cap` hits. Nothing is kept.
#[no_mangle]
pub unsafe extern "C" fn pg_detect_batch(
    params: *const PgParams,
    points: *const PgPoint,
    n_points: usize,
    polygons: *const PgPolygons,
    hits: *mut PgHit,
    cap: usize,
    n_hits: *mut usize,
) -> c_int {
    // SAFETY: the caller's promise.
    let n_hits = match unsafe { out_of(n_hits, "n_hits") } {
        Ok(n) => n,
        Err(f) => return guard(|| Err(f)),
    };
    *n_hits = 0;
    guard(|| {
        // SAFETY (this block): the caller's promise of valid pointers and lengths.
        let params = unsafe { deref(params, "params") }?;
        let polys = unsafe { deref(polygons, "polygons") }?;
        let points = unsafe { slice_of(points, n_points, "points") }?;
        buffer_ok(hits, cap, "hits")?;
        let flat = unsafe { flat_polygons(polys, "polygons") }?;
        let p = params_of(params)?;
        let pts = points
            .iter()
            .enumerate()
            .map(|(i, q)| {
                point_of(q).map_err(|e| Failure::case(e, Some(("point.", format!("points[{i}].")))))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut polygons = Vec::with_capacity(polys.count);
        for i in 0..polys.count {
            let r = flat.offsets[i]..flat.offsets[i + 1];
            let poly = polygon_of(
                &flat.vertices[r.clone()],
                flat.velocities.map(|v| &v[r]),
                flat.slabs.map(|s| &s[i]),
            )
            .map_err(|e| Failure::case(e, Some(("polygon.", format!("polygons[{i}].")))))?;
            polygons.push(poly);
        }
        let found = batch::detect_batch(params.lookahead, &pts, &polygons, &p)
            .map_err(|e| Failure::case(e, None))?;
        let written = found.len().min(cap);
        for (k, h) in found.iter().take(written).enumerate() {
            // SAFETY: k < cap, and `hits` holds `cap` elements (non-NULL as cap > 0).
            unsafe {
                hits.add(k).write(PgHit {
                    point: h.point,
                    polygon: h.polygon,
                    kind: kind_code(h.kind),
                    method: method_code(h.method),
                })
            };
        }
        *n_hits = found.len();
        if found.len() > cap {
            return Err(capacity_failure("hits", "hits", found.len(), cap));
        }
        Ok(())
    })
}

/// `pg_intervals`' relation from its `PG_RELATION_*` code (docs/cases.md's
/// definitions of inside, near_D and breach_D).
fn relation_of(code: c_int) -> Result<Relation, Failure> {
    match code {
        PG_RELATION_INSIDE => Ok(Relation::Inside),
        PG_RELATION_NEAR => Ok(Relation::Near),
        PG_RELATION_BREACH => Ok(Relation::Breach),
        other => Err(Failure::new(
            PG_ERR_BAD_PARAMETER,
            format!(
                "relation: {other} is not PG_RELATION_INSIDE (0), PG_RELATION_NEAR (1) \
                 or PG_RELATION_BREACH (2)"
            ),
        )),
    }
}

/// The engine's separation from the caller's (D and H of near_D and fence_D), validated
/// by `Separation::new`: its message names the C field, `sep.d` or `sep.h`.
///
/// # Safety
/// `sep` is NULL or points to a valid `pg_separation`.
unsafe fn separation_of(sep: *const PgSeparation) -> Result<Separation, Failure> {
    // SAFETY: the caller's promise.
    let s = unsafe { deref(sep, "sep") }?;
    Separation::new(s.d, s.h).map_err(|e| {
        let rename = match &*e.field() {
            "sep" => Some(("sep", "sep.d".to_string())),
            "sep_v" => Some(("sep_v", "sep.h".to_string())),
            _ => None,
        };
        Failure::case(e, rename)
    })
}

/// The span `pg_intervals` writes first on an error: possible, from 0 to +∞ (the
/// relation may hold at any time), so that an unchecked status never reads "never".
const POSSIBLE_ALWAYS: PgSpan = PgSpan {
    start_lo: 0.0,
    start_hi: f64::INFINITY,
    end_lo: 0.0,
    end_hi: f64::INFINITY,
    certain: 0,
};

/// Every time during [0, T] that the relation holds, as certified spans: inside(t)
/// (`PG_RELATION_INSIDE`), near_D(t) (`PG_RELATION_NEAR`) or breach_D(t)
/// (`PG_RELATION_BREACH`), with D = `sep->d` and H = `sep->h` (docs/cases.md,
/// "Separation and fences"; paper A §II–§III's motion, timed). The spans are the
/// engine's (`polyguard::api::intervals`), bit for bit those of `polyguard detect
/// --intervals`. For the exact set S of times:
///
/// - the spans are sorted: start_lo ≤ start_hi ≤ end_lo ≤ end_hi, all in [0, T], and
///   each span's end_hi ≤ the next one's start_lo;
/// - nothing is missed: S lies in the union of the spans' [start_lo, end_hi];
/// - every end of a component of S (0 and T included) lies in some span's start or end
///   enclosure;
/// - `certain == 1`: S holds throughout [start_hi, end_lo]; `certain == 0` (possible):
///   f64 could not settle the stretch (a tangency, say), S may hold there or not.
///
/// The first span of near_D starts at the time of loss of separation. BUFF, F and κ play
/// no part, but `params` is validated as for `pg_detect`.
///
/// The buffer: at most `cap` spans are written to `out` (NULL allowed when `cap` is 0)
/// and the number of spans of the answer to `*n_out`. When it exceeds `cap`, the first
/// `cap` spans are written and the status is `PG_ERR_CAPACITY`: call again with
/// `cap >= *n_out` (`cap = 0` asks for the count alone). A truncated answer is never
/// `PG_OK`.
///
/// Returns `PG_OK`, `PG_ERR_CAPACITY`, or another `PG_ERR_*` code with a message
/// naming the field (`sep.d: …`, `relation: …`, `polygon.vertices: …`); on those
/// `*n_out` is 1 and `out[0]` (when `cap` ≥ 1 and `out` is valid) is the possible span
/// [0, +∞], [0, +∞], so that an unchecked status never reads "never".
///
/// # Safety
/// As `pg_detect`; `sep` is NULL or valid, `out` is NULL or has room for `cap` spans,
/// `n_out` is NULL or valid. Nothing is kept.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_intervals(
    params: *const PgParams,
    point: *const PgPoint,
    polygon: *const PgPolygon,
    relation: c_int,
    sep: *const PgSeparation,
    out: *mut PgSpan,
    cap: usize,
    n_out: *mut usize,
) -> c_int {
    // SAFETY: the caller's promise.
    let n_out = match unsafe { out_of(n_out, "n_out") } {
        Ok(n) => n,
        Err(f) => return guard(|| Err(f)),
    };
    *n_out = 1;
    guard(|| {
        buffer_ok(out, cap, "out")?;
        if cap > 0 {
            // SAFETY: non-NULL, aligned, room for cap ≥ 1 spans (the caller's promise).
            unsafe { out.write(POSSIBLE_ALWAYS) };
        }
        // SAFETY (both): the caller's promise.
        let case = unsafe { case_of(params, point, polygon) }?;
        let relation = relation_of(relation)?;
        let sep = unsafe { separation_of(sep) }?;
        let spans = api::intervals(&case, relation, sep);
        for (k, s) in spans.iter().take(cap).enumerate() {
            // SAFETY: k < cap, and `out` holds `cap` spans (non-NULL as cap > 0).
            unsafe { out.add(k).write(PgSpan::from(s)) };
        }
        *n_out = spans.len();
        if spans.len() > cap {
            return Err(capacity_failure("out", "spans", spans.len(), cap));
        }
        Ok(())
    })
}

/// Keep-in exit detection: does the point leave the fence, that is, does breach_D hold
/// at some t in [0, T] (docs/cases.md, "Separation and fences"; paper A §II–§III's motion
/// and slab, for a polygon the point must stay in)? D = `sep->d` from the polygon's
/// boundary, H = `sep->h` from the slab's bottom and top (3D).
///
/// `out->detected` is 1 when the point leaves, never 0 when it does: the engine's
/// `polyguard::api::detect_exit`, the `exits` of `polyguard detect --fence keep-in`.
/// `kind` is `PG_KIND_EXACT` when certified, `PG_KIND_CONSERVATIVE` for a 1 f64 could
/// not certify; `method` and the well-formedness fields are those of `pg_detect`. BUFF
/// and F play no part, but `params` is validated as for `pg_detect`.
///
/// Returns `PG_OK`, or a `PG_ERR_*` code with a message naming the field (`sep.h: …`);
/// on an error `*out` (when `out` is not NULL) holds the conservative answer, as
/// `pg_detect`'s: detected 1, kind conservative, method `PG_METHOD_NONE`.
///
/// # Safety
/// As `pg_detect`; `sep` is NULL or valid. Nothing is kept.
#[no_mangle]
pub unsafe extern "C" fn pg_detect_exit(
    params: *const PgParams,
    point: *const PgPoint,
    polygon: *const PgPolygon,
    sep: *const PgSeparation,
    out: *mut PgDetection,
) -> c_int {
    // SAFETY: the caller's promise.
    let out = match unsafe { out_of(out, "out") } {
        Ok(o) => o,
        Err(f) => return guard(|| Err(f)),
    };
    *out = CONSERVATIVE_DETECTION;
    guard(|| {
        // SAFETY (both): the caller's promise.
        let case = unsafe { case_of(params, point, polygon) }?;
        let sep = unsafe { separation_of(sep) }?;
        *out = detection_of(&api::detect_exit(&case, sep));
        Ok(())
    })
}

/// Copies this thread's message about its last failed call (empty after a successful
/// one) into `buf` as a NUL-terminated UTF-8 string: the field first, as in the case
/// format of docs/cases.md (`polygon.vertices: clockwise order …`). (Extends the
/// engine's typed errors, polyguard::error, to C.)
///
/// Returns `PG_OK`; `PG_ERR_CAPACITY` when the message was cut to fit `len` bytes (at
/// a character boundary, still NUL-terminated when `len > 0`); `PG_ERR_NULL_POINTER`
/// when `buf` is NULL and `len > 0`. It does not change the message itself.
///
/// # Safety
/// `buf` is NULL or points to `len` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn pg_last_error_message(buf: *mut c_char, len: usize) -> c_int {
    let caught = catch_unwind(AssertUnwindSafe(|| {
        LAST_ERROR.with(|m| {
            let m = m.borrow();
            if len == 0 {
                return if m.is_empty() { PG_OK } else { PG_ERR_CAPACITY };
            }
            if buf.is_null() {
                return PG_ERR_NULL_POINTER;
            }
            let mut n = m.len().min(len - 1);
            while !m.is_char_boundary(n) {
                n -= 1;
            }
            // SAFETY: `buf` holds `len` > n bytes (the caller's promise).
            unsafe {
                core::ptr::copy_nonoverlapping(m.as_ptr(), buf.cast::<u8>(), n);
                buf.add(n).write(0);
            }
            if n < m.len() {
                PG_ERR_CAPACITY
            } else {
                PG_OK
            }
        })
    }));
    caught.unwrap_or(PG_ERR_PANIC)
}

/// The name of a status code (`"PG_OK"`, `"PG_ERR_CLOCKWISE"`, …; `"unknown"` for any
/// other value), as a NUL-terminated string in static storage: never freed, never NULL.
/// For logs beside `pg_last_error_message`. (Extends this interface's status codes;
/// no paper section.)
#[no_mangle]
pub extern "C" fn pg_status_name(status: c_int) -> *const c_char {
    let s: &'static [u8] = match status {
        PG_OK => b"PG_OK\0",
        PG_ERR_NULL_POINTER => b"PG_ERR_NULL_POINTER\0",
        PG_ERR_NOT_FINITE => b"PG_ERR_NOT_FINITE\0",
        PG_ERR_TOO_FEW_VERTICES => b"PG_ERR_TOO_FEW_VERTICES\0",
        PG_ERR_WRONG_LENGTH => b"PG_ERR_WRONG_LENGTH\0",
        PG_ERR_CLOCKWISE => b"PG_ERR_CLOCKWISE\0",
        PG_ERR_SELF_INTERSECTING => b"PG_ERR_SELF_INTERSECTING\0",
        PG_ERR_ZERO_AREA => b"PG_ERR_ZERO_AREA\0",
        PG_ERR_DIMENSION_MISMATCH => b"PG_ERR_DIMENSION_MISMATCH\0",
        PG_ERR_BAD_PARAMETER => b"PG_ERR_BAD_PARAMETER\0",
        PG_ERR_SLAB_INVERTED => b"PG_ERR_SLAB_INVERTED\0",
        PG_ERR_CAPACITY => b"PG_ERR_CAPACITY\0",
        PG_ERR_PANIC => b"PG_ERR_PANIC\0",
        PG_ERR_INVALID => b"PG_ERR_INVALID\0",
        PG_ERR_UTF8 => b"PG_ERR_UTF8\0",
        PG_ERR_INPUT => b"PG_ERR_INPUT\0",
        PG_ERR_UNCERTIFIED => b"PG_ERR_UNCERTIFIED\0",
        PG_PARTIAL => b"PG_PARTIAL\0",
        _ => b"unknown\0",
    };
    s.as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message() -> String {
        let mut buf = [0 as c_char; 256];
        // SAFETY: buf holds 256 bytes.
        let rc = unsafe { pg_last_error_message(buf.as_mut_ptr(), buf.len()) };
        assert_eq!(rc, PG_OK);
        // SAFETY: NUL-terminated by pg_last_error_message.
        unsafe { std::ffi::CStr::from_ptr(buf.as_ptr()) }
            .to_str()
            .unwrap()
            .to_owned()
    }

    /// A panic inside an entry point's body comes back as PG_ERR_PANIC with its message,
    /// not as an unwind (no input reaches a panic today, so the guard is tested alone).
    #[test]
    fn a_panic_becomes_a_status() {
        let rc = guard(|| panic!("boom {}", 7));
        assert_eq!(rc, PG_ERR_PANIC);
        let m = message();
        assert!(
            m.contains("boom 7") && m.starts_with("internal error"),
            "{m}"
        );
        let rc = guard(|| std::panic::panic_any(42u8));
        assert_eq!(rc, PG_ERR_PANIC);
        assert!(message().contains("no message"));
        // and the next successful call clears it
        assert_eq!(guard(|| Ok(())), PG_OK);
        assert_eq!(message(), "");
    }

    /// The message is per thread: a failure on one thread leaves another's message as
    /// it was (the header promises it).
    #[test]
    fn the_message_is_per_thread() {
        // SAFETY: NULL `out` is allowed; it is the failure under test.
        assert_eq!(
            unsafe { pg_params_default(core::ptr::null_mut()) },
            PG_ERR_NULL_POINTER
        );
        assert_eq!(message(), "out: NULL pointer");
        let other = std::thread::spawn(|| {
            let before = message();
            let mut p = PgParams::default();
            // SAFETY: a valid `out`.
            let rc = unsafe { pg_params_default(&mut p) };
            (before, rc, message())
        })
        .join()
        .unwrap();
        assert_eq!(other, (String::new(), PG_OK, String::new()));
        assert_eq!(message(), "out: NULL pointer");
    }

    /// A misaligned pointer is refused with its name, never read.
    #[test]
    fn a_misaligned_pointer_is_refused() {
        let bytes = [0u8; 64];
        let params = bytes.as_ptr().wrapping_add(1).cast::<PgParams>();
        let mut out = PgDetection::default();
        // SAFETY: the misaligned pointer is checked before any read.
        let rc = unsafe { pg_detect(params, core::ptr::null(), core::ptr::null(), &mut out) };
        assert_eq!(rc, PG_ERR_INVALID);
        assert!(
            message().starts_with("params: misaligned pointer"),
            "{}",
            message()
        );
        assert_eq!(out.detected, 1);
    }

    /// Every status has its own name (no two codes share one, none is "unknown").
    #[test]
    fn status_names_are_distinct() {
        let codes = [
            PG_OK,
            PG_ERR_NULL_POINTER,
            PG_ERR_NOT_FINITE,
            PG_ERR_TOO_FEW_VERTICES,
            PG_ERR_WRONG_LENGTH,
            PG_ERR_CLOCKWISE,
            PG_ERR_SELF_INTERSECTING,
            PG_ERR_ZERO_AREA,
            PG_ERR_DIMENSION_MISMATCH,
            PG_ERR_BAD_PARAMETER,
            PG_ERR_SLAB_INVERTED,
            PG_ERR_CAPACITY,
            PG_ERR_PANIC,
            PG_ERR_INVALID,
            PG_ERR_UTF8,
            PG_ERR_INPUT,
            PG_ERR_UNCERTIFIED,
        ];
        let names: std::collections::HashSet<String> = codes
            .iter()
            .map(|&c| {
                // SAFETY: static NUL-terminated strings.
                unsafe { std::ffi::CStr::from_ptr(pg_status_name(c)) }
                    .to_str()
                    .unwrap()
                    .to_owned()
            })
            .collect();
        assert_eq!(names.len(), codes.len());
        assert!(!names.contains("unknown"));
    }
}
