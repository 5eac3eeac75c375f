//! What the C interface costs over the Rust API on one case (paper A §II.H, §II.I):
//! `pg_detect` copies and validates the polygon (§II's counterclockwise simple ring) on
//! every call, as a C caller holds no validated object; `api::detect` on a `Case` built
//! once does not. Also `pg_detect` against `api::detect` with the `Case` built inside the
//! loop, which is the same work: the difference is the boundary itself.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use polyguard::api::{self, Case, MovingPoint, MovingPolygon, Params};
use polyguard::Vect2;
use polyguard_ffi::{pg_detect, PgDetection, PgParams, PgPoint, PgPolygon, PgSlab, PgVec2, PG_OK};

/// A regular n-gon of radius 10, counterclockwise, drifting (same velocities) or
/// warping (growing about its centre).
fn ngon(n: usize, warp: bool) -> (Vec<PgVec2>, Vec<PgVec2>) {
    let vs: Vec<PgVec2> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            PgVec2 {
                x: 10.0 * a.cos(),
                y: 10.0 * a.sin(),
            }
        })
        .collect();
    let vel = vs
        .iter()
        .map(|p| {
            if warp {
                PgVec2 {
                    x: 0.01 * p.x,
                    y: 0.01 * p.y,
                }
            } else {
                PgVec2 { x: 0.3, y: 0.1 }
            }
        })
        .collect();
    (vs, vel)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("ffi");
    for &(n, warp) in &[(8, false), (8, true), (64, false), (64, true)] {
        let (vs, vel) = ngon(n, warp);
        let label = format!("{n}{}", if warp { "_warping" } else { "_rigid" });
        // a point that crosses the polygon: every call answers yes
        let point = PgPoint {
            pos: PgVec2 { x: -30.0, y: 1.0 },
            vel: PgVec2 { x: 1.0, y: 0.0 },
            ..PgPoint::default()
        };
        let params = PgParams {
            lookahead: 60.0,
            buff: 0.01,
            fac: 1e-4,
            kappa_deg: 5.0,
        };
        let poly = PgPolygon {
            vertices: vs.as_ptr(),
            velocities: vel.as_ptr(),
            n,
            has_slab: 0,
            slab: PgSlab::default(),
        };
        let to_v = |v: &[PgVec2]| v.iter().map(|p| Vect2::new(p.x, p.y)).collect::<Vec<_>>();
        let build = || {
            Case::new(
                60.0,
                MovingPoint::new_2d(Vect2::new(-30.0, 1.0), Vect2::new(1.0, 0.0)).unwrap(),
                MovingPolygon::new(to_v(&vs), Some(to_v(&vel))).unwrap(),
                Params::new(0.01).unwrap(),
            )
            .unwrap()
        };
        let case = build();
        assert!(api::detect(&case).detected);
        g.bench_function(BenchmarkId::new("pg_detect", &label), |b| {
            b.iter(|| {
                let mut out = PgDetection::default();
                // SAFETY: every pointer is valid for the call.
                let rc = unsafe { pg_detect(&params, &point, black_box(&poly), &mut out) };
                assert_eq!(rc, PG_OK);
                out.detected
            })
        });
        g.bench_function(BenchmarkId::new("rust_case_built_each_call", &label), |b| {
            b.iter(|| api::detect(&black_box(build())).detected)
        });
        g.bench_function(BenchmarkId::new("rust_case_built_once", &label), |b| {
            b.iter(|| api::detect(black_box(&case)).detected)
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
