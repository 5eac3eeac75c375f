//! The way out in C: certified course, speed and vertical speed bands among moving
//! polygons, recovery points and certified offsets and insets (the engine's
//! `polyguard::bands`, `polyguard::recovery` and `polyguard::offset`, whose module docs
//! state the definitions; paper A §II's polygons, §II.G's proximity, §II–§III's motion).
//!
//! Every function follows the crate's rules (status codes, a message naming the field,
//! no unwinding, the caller owns every array). Answers of unknown size go into the
//! caller's buffers with `PG_ERR_CAPACITY` and the needed counts when they are too
//! small, as `pg_detect_batch` and `pg_intervals` do.

use std::os::raw::c_int;

use polyguard::bands::{self, Band, BandKind, Bands, BandsError, Height, Obstacle, Slab, Traffic};
use polyguard::offset::{self, Offset, OffsetError};
use polyguard::recovery::{self, Recovery, RecoveryError};
use polyguard::ring::RingFault;
use polyguard::{Separation, Vect2};

use crate::{
    buffer_ok, capacity_failure, deref, flat_polygons, guard, out_of, polygon_slices, vects,
    Failure, PgPoint, PgPolygon, PgPolygons, PgSeparation, PgVec2, PG_ERR_BAD_PARAMETER,
    PG_ERR_CLOCKWISE, PG_ERR_DIMENSION_MISMATCH, PG_ERR_NOT_FINITE, PG_ERR_SELF_INTERSECTING,
    PG_ERR_TOO_FEW_VERTICES, PG_ERR_WRONG_LENGTH, PG_ERR_ZERO_AREA,
};

/// The engine could not certify an answer (a near-degenerate input within rounding, or
/// an offset's rounding too coarse for D·ε at this scale): no answer is given rather
/// than an uncertified one.
pub const PG_ERR_UNCERTIFIED: c_int = -16;

/// `pg_band.kind`: no value of the band is in conflict (certified).
pub const PG_BAND_CLEAR: c_int = 0;
/// `pg_band.kind`: every value of the band is in conflict (certified).
pub const PG_BAND_CONFLICT: c_int = 1;
/// `pg_band.kind`: not decided.
pub const PG_BAND_UNKNOWN: c_int = 2;

/// `pg_recovery`'s fence: out of the polygon's D-neighbourhood (recovery_out).
pub const PG_FENCE_KEEP_OUT: c_int = 0;
/// `pg_recovery`'s fence: into the polygon's D-core (recovery_in).
pub const PG_FENCE_KEEP_IN: c_int = 1;

/// `pg_recovery_point.kind`: no answer (written on an error).
pub const PG_RECOVERY_NONE: c_int = -1;
/// `pg_recovery_point.kind`: a certified recovery point.
pub const PG_RECOVERY_POINT: c_int = 0;
/// `pg_recovery_point.kind`: no point of the polygon is D from its boundary (its
/// inradius is below D; keep-in only), certified.
pub const PG_RECOVERY_IMPOSSIBLE: c_int = 1;

/// One closed band [lo, hi] of a band answer (course in radians clockwise from +y,
/// speed, or vertical speed) and what is certified on it.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgBand {
    /// The low end.
    pub lo: f64,
    /// The high end.
    pub hi: f64,
    /// `PG_BAND_CLEAR`, `PG_BAND_CONFLICT` or `PG_BAND_UNKNOWN`.
    pub kind: c_int,
}

/// The summary of a band answer.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgBandsInfo {
    /// The number of bands of the whole answer (written even when the buffer is too
    /// small).
    pub count: usize,
    /// The total width of the Unknown bands.
    pub unknown_total: f64,
    /// 1 when `unknown_total ≤ unknown_max` was reached, else 0.
    pub met: c_int,
}

/// The answer of `pg_recovery`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgRecoveryPoint {
    /// `PG_RECOVERY_POINT`, `PG_RECOVERY_IMPOSSIBLE` or `PG_RECOVERY_NONE` (an error).
    pub kind: c_int,
    /// The point: it satisfies its condition for the exact inputs (NaN otherwise).
    pub x: PgVec2,
    /// A certified upper bound of |x − s|.
    pub dist_hi: f64,
    /// A certified lower bound of the exact minimum distance.
    pub min_lo: f64,
    /// 1 when s itself satisfies the condition (then x = s).
    pub clear: c_int,
}

/// One ring of `pg_offset` / `pg_inset`: `n` vertices from `vertices[first]`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgRing {
    /// The index of its first vertex in the vertex buffer.
    pub first: usize,
    /// Its number of vertices.
    pub n: usize,
    /// The region it belongs to (0, 1, …).
    pub region: usize,
    /// 0: the region's outer ring (counterclockwise); 1: a hole (clockwise).
    pub hole: c_int,
}

/// The sizes of an offset or inset answer (written even when a buffer is too small).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgShapeInfo {
    /// The regions (0 for an empty inset).
    pub regions: usize,
    /// The rings: each region's outer ring then its holes.
    pub rings: usize,
    /// The vertices of all rings.
    pub vertices: usize,
}

/// The C field of an engine field of `polyguard::bands` (its names are the traffic
/// struct's; C's are the arguments').
fn bands_field(engine: &str) -> String {
    let fixed = match engine {
        "t" => Some("lookahead"),
        "s[0]" => Some("point.pos.x"),
        "s[1]" => Some("point.pos.y"),
        "v[0]" => Some("point.vel.x"),
        "v[1]" => Some("point.vel.y"),
        "height.sz" => Some("point.z"),
        "height.vz" => Some("point.vz"),
        "height" => Some("point.has_z"),
        "sep" => Some("sep.d"),
        "sep_v" => Some("sep.h"),
        _ => None,
    };
    if let Some(f) = fixed {
        return f.into();
    }
    engine
        .replacen(".p", ".vertices", 1)
        .replacen(".vels", ".velocities", 1)
}

/// The status and message of a bands error, its field in C's names.
fn bands_failure(e: &BandsError) -> Failure {
    match e {
        BandsError::NotFinite { field } => Failure::new(
            PG_ERR_NOT_FINITE,
            format!("{}: not a finite number", bands_field(field)),
        ),
        BandsError::OutOfRange {
            field,
            value,
            range,
        } => Failure::new(
            PG_ERR_BAD_PARAMETER,
            format!("{}: {value} is outside {range}", bands_field(field)),
        ),
        BandsError::WrongLength {
            field,
            expected,
            found,
        } => {
            let code = if field.ends_with(".p") {
                PG_ERR_TOO_FEW_VERTICES
            } else {
                PG_ERR_WRONG_LENGTH
            };
            Failure::new(
                code,
                format!(
                    "{}: length {found}, expected {expected}",
                    bands_field(field)
                ),
            )
        }
        BandsError::DimensionMismatch { field } => Failure::new(
            PG_ERR_DIMENSION_MISMATCH,
            format!(
                "{}: a slab needs the point's height (point.has_z)",
                bands_field(field)
            ),
        ),
    }
}

/// The obstacles of `pg_polygons` (the batch's flat arrays) as owned vertex lists.
struct Owned {
    p: Vec<Vec<Vect2>>,
    vels: Vec<Vec<Vect2>>,
    slabs: Vec<Option<Slab>>,
}

/// Reads the flat arrays of `pg_polygons`, as `pg_detect_batch` does (offsets from 0,
/// never decreasing; velocities NULL: at rest; slabs NULL: 2D).
///
/// # Safety
/// As `pg_detect_batch`'s `polygons`.
unsafe fn obstacles_of(polygons: *const PgPolygons) -> Result<Owned, Failure> {
    // SAFETY (this function): the caller's promise of valid pointers and lengths.
    let polys = unsafe { deref(polygons, "obstacles") }?;
    let flat = unsafe { flat_polygons(polys, "obstacles") }?;
    let mut owned = Owned {
        p: Vec::with_capacity(polys.count),
        vels: Vec::with_capacity(polys.count),
        slabs: Vec::with_capacity(polys.count),
    };
    for i in 0..polys.count {
        let r = flat.offsets[i]..flat.offsets[i + 1];
        owned.p.push(vects(&flat.vertices[r.clone()]));
        owned.vels.push(match flat.velocities {
            Some(v) => vects(&v[r]),
            None => vec![Vect2::new(0.0, 0.0); r.len()],
        });
        owned.slabs.push(flat.slabs.map(|s| Slab {
            bottom: s[i].bottom,
            top: s[i].top,
            vsp: s[i].vz,
        }));
    }
    Ok(owned)
}

/// `PG_BAND_*` of a band kind.
fn band_code(k: BandKind) -> c_int {
    match k {
        BandKind::Clear => PG_BAND_CLEAR,
        BandKind::Conflict => PG_BAND_CONFLICT,
        BandKind::Unknown => PG_BAND_UNKNOWN,
    }
}

/// Which band family a call asks for, with its parameters.
enum Family {
    /// Courses at a speed.
    Course { speed: f64 },
    /// Speeds in [min, max] at a course.
    Speed { course: f64, min: f64, max: f64 },
    /// Vertical speeds in [min, max] at the point's horizontal velocity.
    Vertical { min: f64, max: f64 },
}

impl Family {
    /// The range the conservative answer covers on an error.
    fn range(&self) -> (f64, f64) {
        match *self {
            Family::Course { .. } => (0.0, core::f64::consts::TAU),
            Family::Speed { min, max, .. } | Family::Vertical { min, max } => (min, max),
        }
    }
}

/// The body shared by the three band functions: the traffic from the C arguments, the
/// engine's answer into the caller's buffer (module doc; `polyguard::bands`).
///
/// # Safety
/// As `pg_course_bands`.
#[allow(clippy::too_many_arguments)]
unsafe fn bands_call(
    point: *const PgPoint,
    obstacles: *const PgPolygons,
    lookahead: f64,
    sep: *const PgSeparation,
    family: Family,
    unknown_max: f64,
    out: *mut PgBand,
    cap: usize,
    info: *mut PgBandsInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    let info = match unsafe { out_of(info, "info") } {
        Ok(i) => i,
        Err(f) => return guard(|| Err(f)),
    };
    let (lo, hi) = family.range();
    let width = hi - lo;
    *info = PgBandsInfo {
        count: 1,
        unknown_total: if width.is_finite() {
            width
        } else {
            f64::INFINITY
        },
        met: 0,
    };
    guard(|| {
        buffer_ok(out, cap, "out")?;
        if cap > 0 {
            // SAFETY: non-NULL, aligned, room for cap ≥ 1 bands (the caller's promise).
            unsafe {
                out.write(PgBand {
                    lo,
                    hi,
                    kind: PG_BAND_UNKNOWN,
                })
            };
        }
        // SAFETY (three): the caller's promise.
        let point = unsafe { deref(point, "point") }?;
        let sep = unsafe { deref(sep, "sep") }?;
        let owned = unsafe { obstacles_of(obstacles) }?;
        let answer = engine_bands(point, sep, &owned, lookahead, family, unknown_max)?;
        write_bands(&answer.bands, out, cap);
        *info = PgBandsInfo {
            count: answer.bands.len(),
            unknown_total: answer.unknown_total,
            met: c_int::from(answer.met),
        };
        if answer.bands.len() > cap {
            return Err(capacity_failure("out", "bands", answer.bands.len(), cap));
        }
        Ok(())
    })
}

/// The engine's bands (`polyguard::bands`) for the C point, separation and obstacles.
fn engine_bands(
    point: &PgPoint,
    sep: &PgSeparation,
    owned: &Owned,
    lookahead: f64,
    family: Family,
    unknown_max: f64,
) -> Result<Bands, Failure> {
    let list: Vec<Obstacle> = (0..owned.p.len())
        .map(|i| Obstacle {
            p: &owned.p[i],
            vels: &owned.vels[i],
            slab: owned.slabs[i],
        })
        .collect();
    let traffic = Traffic {
        t: lookahead,
        s: Vect2::new(point.pos.x, point.pos.y),
        height: (point.has_z != 0).then_some(Height {
            sz: point.z,
            vz: point.vz,
        }),
        obstacles: &list,
        sep: Separation { d: sep.d, h: sep.h },
    };
    let answer: Result<Bands, BandsError> = match family {
        Family::Course { speed } => bands::course_bands(&traffic, speed, unknown_max),
        Family::Speed { course, min, max } => {
            bands::speed_bands(&traffic, course, min, max, unknown_max)
        }
        Family::Vertical { min, max } => bands::vertical_speed_bands(
            &traffic,
            Vect2::new(point.vel.x, point.vel.y),
            min,
            max,
            unknown_max,
        ),
    };
    answer.map_err(|e| bands_failure(&e))
}

/// Writes the first `cap` bands into `out`.
fn write_bands(bands: &[Band], out: *mut PgBand, cap: usize) {
    for (k, b) in bands.iter().take(cap).enumerate() {
        // SAFETY: k < cap, and `out` holds `cap` bands (non-NULL as cap > 0).
        unsafe {
            out.add(k).write(PgBand {
                lo: b.lo,
                hi: b.hi,
                kind: band_code(b.kind),
            })
        };
    }
}

/// Course bands over [0, 2π) at `speed` for the point `point->pos` (in 3D with
/// `point->z`, `point->vz` when `point->has_z`) among the moving polygons `obstacles`
/// (`pg_detect_batch`'s flat arrays; a polygon needs no particular order here, and a
/// slab only with a 3D point) over [0, `lookahead`], separation D = `sep->d` (and
/// H = `sep->h` in 3D). The engine's `polyguard::bands::course_bands` (definitions and
/// certificate in its module doc; paper A §II–§III's motion and near_D): courses in
/// radians clockwise from +y ("north"), velocity speed·(sin θ, cos θ); the bands tile
/// [0, fl(2π)] in order, each `PG_BAND_CLEAR` (no course in it loses separation),
/// `PG_BAND_CONFLICT` (every course does) or `PG_BAND_UNKNOWN`, whose total width is
/// refined towards `unknown_max` (> 0); `point->vel` is not used.
///
/// The buffer: at most `cap` bands are written to `out` (NULL allowed when `cap` is 0);
/// `info` receives the number of bands of the whole answer, the Unknown total and
/// `met`. When the count exceeds `cap`, the first `cap` bands are written and the status
/// is `PG_ERR_CAPACITY`: call again with `cap >= info->count`.
///
/// Returns `PG_OK`, `PG_ERR_CAPACITY`, or another `PG_ERR_*` code with a message naming
/// the field (`lookahead`, `speed`, `unknown_max`, `sep.d`,
/// `obstacles[1].vertices[2][0]`, `obstacles.offsets[2]`); on those `info->count` is 1
/// and `out[0]` (when `cap` ≥ 1) is one Unknown band over the whole range, so that an
/// unchecked status never reads "clear".
///
/// # Safety
/// Each pointer is NULL or valid for the call; `obstacles`' arrays as for
/// `pg_detect_batch`; `out` has room for `cap` bands. Nothing is kept.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_course_bands(
    point: *const PgPoint,
    obstacles: *const PgPolygons,
    lookahead: f64,
    sep: *const PgSeparation,
    speed: f64,
    unknown_max: f64,
    out: *mut PgBand,
    cap: usize,
    info: *mut PgBandsInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    unsafe {
        bands_call(
            point,
            obstacles,
            lookahead,
            sep,
            Family::Course { speed },
            unknown_max,
            out,
            cap,
            info,
        )
    }
}

/// Speed bands over [`min`, `max`] (0 ≤ min ≤ max) at the fixed `course` (radians
/// clockwise from +y): `pg_course_bands` with the speed varied (the engine's
/// `polyguard::bands::speed_bands`); the same buffer protocol, statuses and
/// conservative answer (one Unknown band [min, max]).
///
/// # Safety
/// As `pg_course_bands`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_speed_bands(
    point: *const PgPoint,
    obstacles: *const PgPolygons,
    lookahead: f64,
    sep: *const PgSeparation,
    course: f64,
    min: f64,
    max: f64,
    unknown_max: f64,
    out: *mut PgBand,
    cap: usize,
    info: *mut PgBandsInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    unsafe {
        bands_call(
            point,
            obstacles,
            lookahead,
            sep,
            Family::Speed { course, min, max },
            unknown_max,
            out,
            cap,
            info,
        )
    }
}

/// Vertical speed bands over [`min`, `max`] with the horizontal velocity `point->vel`
/// fixed (3D: `point->has_z` is required; the engine's
/// `polyguard::bands::vertical_speed_bands`); the same buffer protocol, statuses and
/// conservative answer as `pg_course_bands`.
///
/// # Safety
/// As `pg_course_bands`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_vertical_speed_bands(
    point: *const PgPoint,
    obstacles: *const PgPolygons,
    lookahead: f64,
    sep: *const PgSeparation,
    min: f64,
    max: f64,
    unknown_max: f64,
    out: *mut PgBand,
    cap: usize,
    info: *mut PgBandsInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    unsafe {
        bands_call(
            point,
            obstacles,
            lookahead,
            sep,
            Family::Vertical { min, max },
            unknown_max,
            out,
            cap,
            info,
        )
    }
}

/// The status and message of a recovery error, its field in C's names.
fn recovery_failure(e: &RecoveryError) -> Failure {
    let code = match e {
        RecoveryError::NotFinite { .. } => PG_ERR_NOT_FINITE,
        RecoveryError::NegativeSep { .. } => PG_ERR_BAD_PARAMETER,
        RecoveryError::TooFewVertices { .. } => PG_ERR_TOO_FEW_VERTICES,
        RecoveryError::VelsLength { .. } => PG_ERR_WRONG_LENGTH,
        RecoveryError::NotCounterclockwise => PG_ERR_CLOCKWISE,
        RecoveryError::Uncertified => PG_ERR_UNCERTIFIED,
    };
    let text = e.to_string();
    let field = e.field();
    let rest = text
        .strip_prefix(&format!("{field}: "))
        .unwrap_or(text.as_str());
    Failure::new(code, format!("{}: {rest}", polygon_field(field)))
}

/// The C field of an engine field of `polyguard::recovery` or `polyguard::offset` (the
/// polygon's `p` and `vels` are `pg_polygon`'s arrays; the others keep their names).
fn polygon_field(engine: &str) -> &str {
    match engine {
        "p" => "polygon.vertices",
        "vels" => "polygon.velocities",
        other => other,
    }
}

/// The polygon's vertices and, unless NULL, velocities.
///
/// # Safety
/// As `pg_detect`'s `polygon`.
unsafe fn polygon_arrays(
    polygon: *const PgPolygon,
) -> Result<(Vec<Vect2>, Option<Vec<Vect2>>), Failure> {
    // SAFETY (both): the caller's promise.
    let polygon = unsafe { deref(polygon, "polygon") }?;
    let (vertices, velocities) = unsafe { polygon_slices(polygon) }?;
    Ok((vects(vertices), velocities.map(vects)))
}

/// The recovery point of `s` for the polygon `polygon` at time `t` (its slab is not
/// used): with `fence == PG_FENCE_KEEP_OUT` the nearest x with dist(x, P(t)) ≥ `sep`,
/// with `PG_FENCE_KEEP_IN` the nearest x ∈ P(t) with dist(x, ∂P(t)) ≥ `sep` (the
/// engine's `polyguard::recovery::recovery_out` / `recovery_in`, their `_at` forms when
/// `polygon->velocities` is not NULL; paper A §II's polygon, §II.G's distance, §II–§III's
/// motion).
///
/// `out->kind` is `PG_RECOVERY_POINT` with x certified to satisfy its condition,
/// min_lo ≤ (the exact minimum) ≤ |x − s| ≤ dist_hi (the gap within the engine's
/// `REL_TOL` times the problem's scale), and `clear` 1 when s itself satisfies it (then
/// x = s); or `PG_RECOVERY_IMPOSSIBLE` (keep-in only, certified: the polygon's inradius
/// is below `sep`), an answer, not an error.
///
/// Returns `PG_OK`, or a `PG_ERR_*` code with a message naming the field
/// (`polygon.vertices`, `s`, `t`, `sep`, `fence`); `PG_ERR_CLOCKWISE` when the vertices
/// are not certainly counterclockwise, `PG_ERR_UNCERTIFIED` when no candidate could be
/// certified. On those `*out` has kind `PG_RECOVERY_NONE` and NaN numbers.
///
/// # Safety
/// `polygon` as for `pg_detect`; `out` NULL or valid. Nothing is kept.
#[no_mangle]
pub unsafe extern "C" fn pg_recovery(
    polygon: *const PgPolygon,
    t: f64,
    s: PgVec2,
    sep: f64,
    fence: c_int,
    out: *mut PgRecoveryPoint,
) -> c_int {
    // SAFETY: the caller's promise.
    let out = match unsafe { out_of(out, "out") } {
        Ok(o) => o,
        Err(f) => return guard(|| Err(f)),
    };
    *out = PgRecoveryPoint {
        kind: PG_RECOVERY_NONE,
        x: PgVec2 {
            x: f64::NAN,
            y: f64::NAN,
        },
        dist_hi: f64::NAN,
        min_lo: f64::NAN,
        clear: 0,
    };
    guard(|| {
        let keep_in = match fence {
            PG_FENCE_KEEP_OUT => false,
            PG_FENCE_KEEP_IN => true,
            other => {
                return Err(Failure::new(
                    PG_ERR_BAD_PARAMETER,
                    format!("fence: {other} is not PG_FENCE_KEEP_OUT (0) or PG_FENCE_KEEP_IN (1)"),
                ))
            }
        };
        // SAFETY: the caller's promise.
        let (p, vels) = unsafe { polygon_arrays(polygon) }?;
        let s = Vect2::new(s.x, s.y);
        let answer = match (&vels, keep_in) {
            (Some(v), false) => recovery::recovery_out_at(&p, v, t, s, sep),
            (Some(v), true) => recovery::recovery_in_at(&p, v, t, s, sep),
            (None, _) if !t.is_finite() => Err(RecoveryError::NotFinite { field: "t" }),
            (None, false) => recovery::recovery_out(&p, s, sep),
            (None, true) => recovery::recovery_in(&p, s, sep),
        };
        *out = match answer.map_err(|e| recovery_failure(&e))? {
            Recovery::Point {
                x,
                dist_hi,
                min_lo,
                clear,
            } => PgRecoveryPoint {
                kind: PG_RECOVERY_POINT,
                x: PgVec2 { x: x.x, y: x.y },
                dist_hi,
                min_lo,
                clear: c_int::from(clear),
            },
            Recovery::Impossible { .. } => PgRecoveryPoint {
                kind: PG_RECOVERY_IMPOSSIBLE,
                ..*out
            },
        };
        Ok(())
    })
}

/// The status and message of an offset error, its field in C's names.
fn offset_failure(e: &OffsetError) -> Failure {
    match e {
        OffsetError::Invalid { field, reason } => {
            let code = if *reason == "not finite" {
                PG_ERR_NOT_FINITE
            } else if *reason == "clockwise" {
                PG_ERR_CLOCKWISE
            } else if *reason == "fewer than 3 vertices" {
                PG_ERR_TOO_FEW_VERTICES
            } else if *field == "vels" {
                PG_ERR_WRONG_LENGTH
            } else {
                PG_ERR_BAD_PARAMETER
            };
            Failure::new(code, format!("{}: {reason}", polygon_field(field)))
        }
        OffsetError::Polygon { fault } => {
            let code = match fault {
                RingFault::Crossing { .. } => PG_ERR_SELF_INTERSECTING,
                RingFault::ZeroArea => PG_ERR_ZERO_AREA,
                RingFault::NotCheckable => PG_ERR_BAD_PARAMETER,
            };
            Failure::new(
                code,
                format!("polygon.vertices: not a simple polygon ({fault:?})"),
            )
        }
        OffsetError::TooFine { .. } => {
            let text = e.to_string();
            Failure::new(PG_ERR_BAD_PARAMETER, text)
        }
        OffsetError::Uncertified { .. } => Failure::new(PG_ERR_UNCERTIFIED, e.to_string()),
    }
}

/// The body of `pg_offset` and `pg_inset`.
///
/// # Safety
/// As `pg_offset`.
#[allow(clippy::too_many_arguments)]
unsafe fn shape_call(
    polygon: *const PgPolygon,
    t: f64,
    d: f64,
    eps: f64,
    inset: bool,
    rings: *mut PgRing,
    ring_cap: usize,
    vertices: *mut PgVec2,
    vertex_cap: usize,
    info: *mut PgShapeInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    let info = match unsafe { out_of(info, "info") } {
        Ok(i) => i,
        Err(f) => return guard(|| Err(f)),
    };
    *info = PgShapeInfo::default();
    guard(|| {
        buffer_ok(rings, ring_cap, "rings")?;
        buffer_ok(vertices, vertex_cap, "vertices")?;
        // SAFETY: the caller's promise.
        let (p, vels) = unsafe { polygon_arrays(polygon) }?;
        let answer: Result<Offset, OffsetError> = match (&vels, inset) {
            (Some(v), false) => offset::offset_at(&p, v, t, d, eps),
            (Some(v), true) => offset::inset_at(&p, v, t, d, eps),
            (None, _) if !t.is_finite() => Err(OffsetError::Invalid {
                field: "t",
                reason: "not finite",
            }),
            (None, false) => offset::offset(&p, d, eps),
            (None, true) => offset::inset(&p, d, eps),
        };
        let answer = answer.map_err(|e| offset_failure(&e))?;
        let mut list: Vec<(&[Vect2], usize, bool)> = Vec::new();
        for (k, r) in answer.regions.iter().enumerate() {
            list.push((&r.outer, k, false));
            for h in &r.holes {
                list.push((h, k, true));
            }
        }
        let n_vertices: usize = list.iter().map(|(ring, _, _)| ring.len()).sum();
        *info = PgShapeInfo {
            regions: answer.regions.len(),
            rings: list.len(),
            vertices: n_vertices,
        };
        if list.len() > ring_cap || n_vertices > vertex_cap {
            return Err(Failure::new(
                crate::PG_ERR_CAPACITY,
                format!(
                    "rings, vertices: the answer has {} rings of {n_vertices} vertices, room \
                     for {ring_cap} and {vertex_cap}; nothing is written, call again with \
                     ring_cap >= {} and vertex_cap >= {n_vertices}",
                    list.len(),
                    list.len()
                ),
            ));
        }
        let mut first = 0;
        for (k, (ring, region, hole)) in list.iter().enumerate() {
            // SAFETY: k < rings count ≤ ring_cap, first + ring.len() ≤ n_vertices ≤
            // vertex_cap, both buffers non-NULL and aligned when their cap is > 0.
            unsafe {
                rings.add(k).write(PgRing {
                    first,
                    n: ring.len(),
                    region: *region,
                    hole: c_int::from(*hole),
                });
                for (j, v) in ring.iter().enumerate() {
                    vertices.add(first + j).write(PgVec2 { x: v.x, y: v.y });
                }
            }
            first += ring.len();
        }
        Ok(())
    })
}

/// The certified offset of the polygon at time `t` by `d` within relative tolerance
/// `eps`: regions Q with P ⊕ disc(d) ⊆ Q ⊆ P ⊕ disc(d·(1 + eps)) (the engine's
/// `polyguard::offset::offset`, `offset_at` when `polygon->velocities` is not NULL;
/// paper A §II's polygon; definitions in its module doc). The slab is not used.
///
/// The answer: `info` receives the numbers of regions, rings and vertices. Ring k is
/// `rings[k]`: its vertices `vertices[rings[k].first] … [first + n − 1]`, its region,
/// and whether it is the region's outer ring (counterclockwise, listed first) or a hole
/// (clockwise). When `ring_cap` or `vertex_cap` is too small, nothing is written but
/// `info`, and the status is `PG_ERR_CAPACITY`: call again with `ring_cap >=
/// info->rings` and `vertex_cap >= info->vertices` (caps of 0 ask for the sizes alone).
///
/// Returns `PG_OK`, `PG_ERR_CAPACITY`, or another `PG_ERR_*` code with a message naming
/// the field (`polygon.vertices`, `t`, `d`, `eps`); `PG_ERR_UNCERTIFIED` when the
/// result failed its certificate (no polygon rather than a wrong one). On those `info`
/// is all zeros.
///
/// # Safety
/// `polygon` as for `pg_detect`; `rings`, `vertices` have room for their caps; `info`
/// NULL or valid. Nothing is kept.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_offset(
    polygon: *const PgPolygon,
    t: f64,
    d: f64,
    eps: f64,
    rings: *mut PgRing,
    ring_cap: usize,
    vertices: *mut PgVec2,
    vertex_cap: usize,
    info: *mut PgShapeInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    unsafe {
        shape_call(
            polygon, t, d, eps, false, rings, ring_cap, vertices, vertex_cap, info,
        )
    }
}

/// The certified inset of the polygon at time `t` by `d`: pieces Q with
/// Q ⊆ {x ∈ P : dist(x, ∂P) ≥ d} and Q ⊇ {x ∈ P : dist(x, ∂P) ≥ d·(1 + eps)}, maybe
/// several regions, maybe none (`info->regions` 0: an answer, not an error). The
/// engine's `polyguard::offset::inset` (`inset_at` with velocities); the buffers,
/// statuses and fields as `pg_offset`.
///
/// # Safety
/// As `pg_offset`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pg_inset(
    polygon: *const PgPolygon,
    t: f64,
    d: f64,
    eps: f64,
    rings: *mut PgRing,
    ring_cap: usize,
    vertices: *mut PgVec2,
    vertex_cap: usize,
    info: *mut PgShapeInfo,
) -> c_int {
    // SAFETY: the caller's promise.
    unsafe {
        shape_call(
            polygon, t, d, eps, true, rings, ring_cap, vertices, vertex_cap, info,
        )
    }
}
