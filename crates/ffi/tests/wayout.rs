//! `pg_course_bands`, `pg_speed_bands`, `pg_vertical_speed_bands`, `pg_recovery`,
//! `pg_offset` and `pg_inset` against the engine's answers on the same inputs
//! (`polyguard::bands`, `polyguard::recovery`, `polyguard::offset`: the definitions of
//! their module docs), bit for bit; their buffer protocols and their errors naming the C
//! field.

use std::ptr;

use polyguard::bands::{self, BandKind, Height, Obstacle, Slab, Traffic};
use polyguard::offset;
use polyguard::recovery::{self, Recovery};
use polyguard::{Separation, Vect2};
use polyguard_ffi::*;

mod common;
use common::{message, polygon, v};

/// The engine's vectors of C's.
fn vect(p: &[PgVec2]) -> Vec<Vect2> {
    p.iter().map(|q| Vect2::new(q.x, q.y)).collect()
}

/// The engine's obstacles: vertices, velocities and slabs of each.
type EngineScene = (Vec<Vec<Vect2>>, Vec<Vec<Vect2>>, Vec<Option<Slab>>);

/// A square [3, 5] × [-1, 1] drifting west at 0.1, and a triangle north of the point at
/// rest: flat arrays as `pg_detect_batch` takes them.
struct Scene {
    vertices: Vec<PgVec2>,
    velocities: Vec<PgVec2>,
    offsets: Vec<usize>,
    slabs: Vec<PgSlab>,
}

/// The scene's arrays.
fn scene() -> Scene {
    Scene {
        vertices: vec![
            v(3.0, -1.0),
            v(5.0, -1.0),
            v(5.0, 1.0),
            v(3.0, 1.0),
            v(-1.0, 4.0),
            v(1.0, 4.0),
            v(0.0, 6.0),
        ],
        velocities: vec![
            v(-0.1, 0.0),
            v(-0.1, 0.0),
            v(-0.1, 0.0),
            v(-0.1, 0.0),
            v(0.0, 0.0),
            v(0.0, 0.0),
            v(0.0, 0.0),
        ],
        offsets: vec![0, 4, 7],
        slabs: vec![
            PgSlab {
                bottom: 0.0,
                top: 10.0,
                vz: 0.0,
            },
            PgSlab {
                bottom: 20.0,
                top: 30.0,
                vz: 0.0,
            },
        ],
    }
}

impl Scene {
    /// The scene as `pg_polygons` (with its slabs, 3D, or without, 2D).
    fn polygons(&self, slabs: bool) -> PgPolygons {
        PgPolygons {
            vertices: self.vertices.as_ptr(),
            velocities: self.velocities.as_ptr(),
            offsets: self.offsets.as_ptr(),
            count: self.offsets.len() - 1,
            slabs: if slabs {
                self.slabs.as_ptr()
            } else {
                ptr::null()
            },
        }
    }

    /// The engine's view of the same scene.
    fn engine(&self, slabs: bool) -> EngineScene {
        let n = self.offsets.len() - 1;
        let p = (0..n)
            .map(|i| vect(&self.vertices[self.offsets[i]..self.offsets[i + 1]]))
            .collect();
        let vels = (0..n)
            .map(|i| vect(&self.velocities[self.offsets[i]..self.offsets[i + 1]]))
            .collect();
        let s = (0..n)
            .map(|i| {
                slabs.then_some(Slab {
                    bottom: self.slabs[i].bottom,
                    top: self.slabs[i].top,
                    vsp: self.slabs[i].vz,
                })
            })
            .collect();
        (p, vels, s)
    }
}

/// `PG_BAND_*` of a band kind.
fn kind(k: BandKind) -> i32 {
    match k {
        BandKind::Clear => PG_BAND_CLEAR,
        BandKind::Conflict => PG_BAND_CONFLICT,
        BandKind::Unknown => PG_BAND_UNKNOWN,
    }
}

/// The engine's bands as C's.
fn c_bands(b: &bands::Bands) -> (Vec<PgBand>, PgBandsInfo) {
    (
        b.bands
            .iter()
            .map(|x| PgBand {
                lo: x.lo,
                hi: x.hi,
                kind: kind(x.kind),
            })
            .collect(),
        PgBandsInfo {
            count: b.bands.len(),
            unknown_total: b.unknown_total,
            met: i32::from(b.met),
        },
    )
}

/// `pg_course_bands` at lookahead 10 into all of `out` (cap `out.len()`).
fn course_into(
    point: &PgPoint,
    polys: &PgPolygons,
    sep: &PgSeparation,
    speed: f64,
    unknown_max: f64,
    out: &mut [PgBand],
    info: &mut PgBandsInfo,
) -> i32 {
    // SAFETY: valid pointers, `out` holds `out.len()` bands.
    unsafe {
        pg_course_bands(
            point,
            polys,
            10.0,
            sep,
            speed,
            unknown_max,
            out.as_mut_ptr(),
            out.len(),
            info,
        )
    }
}

/// Course, speed and vertical speed bands equal the engine's, in 2D and 3D.
#[test]
fn bands_equal_the_engines() {
    let sc = scene();
    for three_d in [false, true] {
        let point = PgPoint {
            pos: v(0.0, 0.0),
            vel: v(0.6, 0.8),
            has_z: i32::from(three_d),
            z: 5.0,
            vz: 0.5,
        };
        let sep = PgSeparation { d: 0.5, h: 1.0 };
        let polys = sc.polygons(three_d);
        let (p, vels, slabs) = sc.engine(three_d);
        let list: Vec<Obstacle> = (0..p.len())
            .map(|i| Obstacle {
                p: &p[i],
                vels: &vels[i],
                slab: slabs[i],
            })
            .collect();
        let traffic = Traffic {
            t: 10.0,
            s: Vect2::new(0.0, 0.0),
            height: three_d.then_some(Height { sz: 5.0, vz: 0.5 }),
            obstacles: &list,
            sep: Separation { d: 0.5, h: 1.0 },
        };
        let um = 0.01;
        let mut out = vec![PgBand::default(); 256];
        let mut info = PgBandsInfo::default();
        let rc = course_into(&point, &polys, &sep, 1.0, um, &mut out, &mut info);
        assert_eq!(rc, PG_OK, "{}", message());
        let (want, want_info) = c_bands(&bands::course_bands(&traffic, 1.0, um).unwrap());
        assert_eq!(info, want_info);
        assert_eq!(&out[..info.count], &want[..]);
        assert!(want.iter().any(|b| b.kind == PG_BAND_CLEAR));
        assert!(want.iter().any(|b| b.kind == PG_BAND_CONFLICT));

        // SAFETY: as above.
        let rc = unsafe {
            pg_speed_bands(
                &point,
                &polys,
                10.0,
                &sep,
                0.0,
                0.0,
                2.0,
                um,
                out.as_mut_ptr(),
                256,
                &mut info,
            )
        };
        assert_eq!(rc, PG_OK, "{}", message());
        let (want, want_info) = c_bands(&bands::speed_bands(&traffic, 0.0, 0.0, 2.0, um).unwrap());
        assert_eq!(info, want_info);
        assert_eq!(&out[..info.count], &want[..]);

        if three_d {
            // SAFETY: as above.
            let rc = unsafe {
                pg_vertical_speed_bands(
                    &point,
                    &polys,
                    10.0,
                    &sep,
                    -3.0,
                    3.0,
                    um,
                    out.as_mut_ptr(),
                    256,
                    &mut info,
                )
            };
            assert_eq!(rc, PG_OK, "{}", message());
            let w = Vect2::new(0.6, 0.8);
            let (want, want_info) =
                c_bands(&bands::vertical_speed_bands(&traffic, w, -3.0, 3.0, um).unwrap());
            assert_eq!(info, want_info);
            assert_eq!(&out[..info.count], &want[..]);
        }
    }
}

/// A buffer too small: the first `cap` bands, the whole count, `PG_ERR_CAPACITY`; cap 0
/// with a NULL buffer asks for the count alone.
#[test]
fn a_small_band_buffer_is_a_capacity_error() {
    let sc = scene();
    let polys = sc.polygons(false);
    let point = PgPoint::default();
    let sep = PgSeparation { d: 0.5, h: 0.0 };
    let mut full = vec![PgBand::default(); 256];
    let mut info = PgBandsInfo::default();
    let rc = course_into(&point, &polys, &sep, 1.0, 0.01, &mut full, &mut info);
    assert_eq!(rc, PG_OK);
    let n = info.count;
    assert!(n >= 3);
    let mut small = vec![PgBand::default(); 2];
    let rc = course_into(&point, &polys, &sep, 1.0, 0.01, &mut small, &mut info);
    assert_eq!(rc, PG_ERR_CAPACITY);
    assert_eq!(info.count, n);
    assert_eq!(&small[..], &full[..2]);
    assert!(message().starts_with("out:"), "{}", message());
    // SAFETY: cap 0, NULL out allowed.
    let rc = unsafe {
        pg_course_bands(
            &point,
            &polys,
            10.0,
            &sep,
            1.0,
            0.01,
            ptr::null_mut(),
            0,
            &mut info,
        )
    };
    assert_eq!(rc, PG_ERR_CAPACITY);
    assert_eq!(info.count, n);
}

/// Bad input: the status, the C field in the message, and the conservative answer (one
/// Unknown band over the whole range).
#[test]
fn band_errors_name_the_field() {
    let mut sc = scene();
    let point = PgPoint::default();
    let sep = PgSeparation { d: 0.5, h: 0.0 };
    let mut out = [PgBand::default(); 4];
    let mut info = PgBandsInfo::default();
    let call = |sc: &Scene, speed: f64, slabs: bool, out: &mut [PgBand], info: &mut PgBandsInfo| {
        course_into(&point, &sc.polygons(slabs), &sep, speed, 0.01, out, info)
    };
    assert_eq!(
        call(&sc, -1.0, false, &mut out, &mut info),
        PG_ERR_BAD_PARAMETER
    );
    assert!(message().starts_with("speed:"), "{}", message());
    assert_eq!(info.count, 1);
    assert_eq!(out[0].kind, PG_BAND_UNKNOWN);
    assert_eq!((out[0].lo, out[0].hi), (0.0, std::f64::consts::TAU));
    assert_eq!(
        call(&sc, 1.0, true, &mut out, &mut info),
        PG_ERR_DIMENSION_MISMATCH
    );
    assert!(message().starts_with("obstacles[0].slab"), "{}", message());
    sc.vertices[5].y = f64::NAN;
    assert_eq!(
        call(&sc, 1.0, false, &mut out, &mut info),
        PG_ERR_NOT_FINITE
    );
    assert_eq!(
        message(),
        "obstacles[1].vertices[1][1]: not a finite number"
    );
    sc.vertices[5].y = 4.0;
    sc.offsets = vec![0, 5, 4];
    assert_eq!(
        call(&sc, 1.0, false, &mut out, &mut info),
        PG_ERR_WRONG_LENGTH
    );
    assert!(
        message().starts_with("obstacles.offsets[2]"),
        "{}",
        message()
    );
    sc.offsets = vec![0, 2, 7];
    assert_eq!(
        call(&sc, 1.0, false, &mut out, &mut info),
        PG_ERR_TOO_FEW_VERTICES
    );
    assert!(
        message().starts_with("obstacles[0].vertices"),
        "{}",
        message()
    );
}

/// The square [0, 2]², counterclockwise.
const SQUARE: [PgVec2; 4] = [
    PgVec2 { x: 0.0, y: 0.0 },
    PgVec2 { x: 2.0, y: 0.0 },
    PgVec2 { x: 2.0, y: 2.0 },
    PgVec2 { x: 0.0, y: 2.0 },
];

/// `pg_recovery`'s status and answer.
fn recover(poly: &PgPolygon, t: f64, s: PgVec2, sep: f64, fence: i32) -> (i32, PgRecoveryPoint) {
    let mut out = PgRecoveryPoint::default();
    // SAFETY: valid pointers.
    let rc = unsafe { pg_recovery(poly, t, s, sep, fence, &mut out) };
    (rc, out)
}

fn c_recovery(r: Recovery) -> PgRecoveryPoint {
    match r {
        Recovery::Point {
            x,
            dist_hi,
            min_lo,
            clear,
        } => PgRecoveryPoint {
            kind: PG_RECOVERY_POINT,
            x: v(x.x, x.y),
            dist_hi,
            min_lo,
            clear: i32::from(clear),
        },
        Recovery::Impossible { .. } => panic!("not a point"),
    }
}

/// Recovery points out and in, static and moving, equal the engine's; an impossible
/// keep-in is an answer; bad input names the field.
#[test]
fn recovery_equals_the_engines() {
    let sq = vect(&SQUARE);
    let poly = polygon(&SQUARE, None);
    let s = v(1.0, 0.5);
    let (rc, got) = recover(&poly, 0.0, s, 0.5, PG_FENCE_KEEP_OUT);
    assert_eq!(rc, PG_OK, "{}", message());
    let want = recovery::recovery_out(&sq, Vect2::new(1.0, 0.5), 0.5).unwrap();
    assert_eq!(got, c_recovery(want));
    assert!(got.x.y < -0.5 + 1e-9 && got.clear == 0);
    let (rc, got) = recover(&poly, 0.0, v(-1.0, 1.0), 0.5, PG_FENCE_KEEP_IN);
    assert_eq!(rc, PG_OK);
    let want = recovery::recovery_in(&sq, Vect2::new(-1.0, 1.0), 0.5).unwrap();
    assert_eq!(got, c_recovery(want));

    let vels = [v(1.0, 0.0); 4];
    let moving = polygon(&SQUARE, Some(&vels));
    let (rc, got) = recover(&moving, 2.0, s, 0.5, PG_FENCE_KEEP_OUT);
    assert_eq!(rc, PG_OK);
    let want =
        recovery::recovery_out_at(&sq, &vect(&vels), 2.0, Vect2::new(1.0, 0.5), 0.5).unwrap();
    assert_eq!(got, c_recovery(want));

    let (rc, got) = recover(&poly, 0.0, s, 1.5, PG_FENCE_KEEP_IN);
    assert_eq!(rc, PG_OK);
    assert_eq!(got.kind, PG_RECOVERY_IMPOSSIBLE);

    let (rc, got) = recover(&poly, 0.0, s, 0.5, 7);
    assert_eq!(rc, PG_ERR_BAD_PARAMETER);
    assert!(message().starts_with("fence:"), "{}", message());
    assert_eq!(got.kind, PG_RECOVERY_NONE);
    let (rc, _) = recover(&poly, 0.0, s, -1.0, PG_FENCE_KEEP_OUT);
    assert_eq!(rc, PG_ERR_BAD_PARAMETER);
    assert!(message().starts_with("sep:"), "{}", message());
    let cw = [SQUARE[3], SQUARE[2], SQUARE[1], SQUARE[0]];
    let (rc, _) = recover(&polygon(&cw, None), 0.0, s, 0.5, PG_FENCE_KEEP_OUT);
    assert_eq!(rc, PG_ERR_CLOCKWISE);
    assert!(message().starts_with("polygon.vertices:"), "{}", message());
    let (rc, _) = recover(&poly, f64::NAN, s, 0.5, PG_FENCE_KEEP_OUT);
    assert_eq!(rc, PG_ERR_NOT_FINITE);
    assert!(message().starts_with("t:"), "{}", message());
}

/// The rings of `pg_offset` / `pg_inset` read back into the engine's regions.
fn shape(poly: &PgPolygon, t: f64, d: f64, inset: bool) -> (i32, offset::Offset, PgShapeInfo) {
    let mut info = PgShapeInfo::default();
    let f = if inset { pg_inset } else { pg_offset };
    // SAFETY: caps 0 with NULL buffers ask for the sizes.
    let rc = unsafe {
        f(
            poly,
            t,
            d,
            0.01,
            ptr::null_mut(),
            0,
            ptr::null_mut(),
            0,
            &mut info,
        )
    };
    if rc != PG_ERR_CAPACITY {
        return (rc, offset::Offset { regions: vec![] }, info);
    }
    let mut rings = vec![PgRing::default(); info.rings];
    let mut vertices = vec![PgVec2::default(); info.vertices];
    // SAFETY: buffers of exactly the sizes asked for.
    let rc = unsafe {
        f(
            poly,
            t,
            d,
            0.01,
            rings.as_mut_ptr(),
            rings.len(),
            vertices.as_mut_ptr(),
            vertices.len(),
            &mut info,
        )
    };
    let mut regions: Vec<offset::Region> = Vec::new();
    for r in &rings {
        let ring = vect(&vertices[r.first..r.first + r.n]);
        if r.hole == 0 {
            assert_eq!(r.region, regions.len());
            regions.push(offset::Region {
                outer: ring,
                holes: vec![],
            });
        } else {
            regions[r.region].holes.push(ring);
        }
    }
    (rc, offset::Offset { regions }, info)
}

/// Offsets and insets equal the engine's, static, moving, and with a hole (a cavity
/// whose mouth closes).
#[test]
fn offsets_equal_the_engines() {
    let sq = vect(&SQUARE);
    let poly = polygon(&SQUARE, None);
    let (rc, got, info) = shape(&poly, 0.0, 0.5, false);
    assert_eq!(rc, PG_OK, "{}", message());
    assert_eq!(got, offset::offset(&sq, 0.5, 0.01).unwrap());
    assert_eq!(info.regions, 1);
    let (rc, got, _) = shape(&poly, 0.0, 0.5, true);
    assert_eq!(rc, PG_OK);
    assert_eq!(got, offset::inset(&sq, 0.5, 0.01).unwrap());

    // a square cavity [1, 3]² with a mouth 0.4 wide to the east: grown by 0.5 the
    // mouth closes and the cavity's middle is a hole
    let c = [
        v(0.0, 0.0),
        v(4.0, 0.0),
        v(4.0, 1.8),
        v(3.0, 1.8),
        v(3.0, 1.0),
        v(1.0, 1.0),
        v(1.0, 3.0),
        v(3.0, 3.0),
        v(3.0, 2.2),
        v(4.0, 2.2),
        v(4.0, 4.0),
        v(0.0, 4.0),
    ];
    let (rc, got, info) = shape(&polygon(&c, None), 0.0, 0.5, false);
    assert_eq!(rc, PG_OK, "{}", message());
    assert_eq!(got, offset::offset(&vect(&c), 0.5, 0.01).unwrap());
    assert_eq!((info.regions, info.rings), (1, 2));
    assert_eq!(got.regions[0].holes.len(), 1);

    let vels = [v(0.5, -0.25); 4];
    let moving = polygon(&SQUARE, Some(&vels));
    let (rc, got, _) = shape(&moving, 3.0, 0.5, false);
    assert_eq!(rc, PG_OK);
    assert_eq!(
        got,
        offset::offset_at(&sq, &vect(&vels), 3.0, 0.5, 0.01).unwrap()
    );
}

/// `pg_offset` (or `pg_inset`) at t = 0 into all of `rings` and `vertices`.
fn shape_into(
    poly: &PgPolygon,
    d: f64,
    eps: f64,
    inset: bool,
    rings: &mut [PgRing],
    vertices: &mut [PgVec2],
    info: &mut PgShapeInfo,
) -> i32 {
    let f = if inset { pg_inset } else { pg_offset };
    // SAFETY: valid pointers, buffers of the sizes given.
    unsafe {
        f(
            poly,
            0.0,
            d,
            eps,
            rings.as_mut_ptr(),
            rings.len(),
            vertices.as_mut_ptr(),
            vertices.len(),
            info,
        )
    }
}

/// An empty inset is an answer; a buffer too small writes nothing but the sizes; bad
/// input names the field.
#[test]
fn shape_buffers_and_errors() {
    let poly = polygon(&SQUARE, None);
    let (rc, got, info) = shape(&poly, 0.0, 1.5, true);
    assert_eq!(rc, PG_OK);
    assert!(got.regions.is_empty());
    assert_eq!(info, PgShapeInfo::default());

    let mut rings = [PgRing::default(); 1];
    let mut vertices = [PgVec2::default(); 4];
    let mut info = PgShapeInfo::default();
    let rc = shape_into(
        &poly,
        0.5,
        0.01,
        false,
        &mut rings,
        &mut vertices,
        &mut info,
    );
    assert_eq!(rc, PG_ERR_CAPACITY);
    assert!(info.vertices > 4 && info.rings == 1);
    assert_eq!(vertices, [PgVec2::default(); 4], "nothing written");

    let rc = shape_into(
        &poly,
        -1.0,
        0.01,
        false,
        &mut rings,
        &mut vertices,
        &mut info,
    );
    assert_eq!(rc, PG_ERR_BAD_PARAMETER);
    assert!(message().starts_with("d:"), "{}", message());
    let rc = shape_into(&poly, 0.5, 0.0, false, &mut rings, &mut vertices, &mut info);
    assert_eq!(rc, PG_ERR_BAD_PARAMETER);
    assert!(message().starts_with("eps:"), "{}", message());
    let cw = [SQUARE[3], SQUARE[2], SQUARE[1], SQUARE[0]];
    let rc = shape_into(
        &polygon(&cw, None),
        0.5,
        0.01,
        true,
        &mut rings,
        &mut vertices,
        &mut info,
    );
    assert_eq!(rc, PG_ERR_CLOCKWISE);
    assert!(
        message().starts_with("polygon.vertices: clockwise"),
        "{}",
        message()
    );
}
