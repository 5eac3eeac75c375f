//! The exact truth on large polygons (the goal: the truth at 16k vertices within 1 s):
//! what `polyguard detect --engine truth` computes after reading a case, the exact case
//! built from the f64 inputs, `truth` and the exact §II.J report (`well_formed_fault`),
//! on circles (convex) and 64-lobed stars (not convex) of 4k and 16k vertices of radius
//! 10⁴: at rest with a point track that enters, translating, warping (growing 1 %/s)
//! with a track that misses, and 3D (a slab met from t = 5 to 15). Group `truth_large`;
//! `reference/…/128` is the pairwise §II.J report it replaced, on a 128-vertex circle
//! (it is quadratic in exact `segments_close` tests: minutes at 4k), next to the sweep.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use polyguard_oracle::well_formed::{well_formed_fault, well_formed_fault_pairwise};
use polyguard_oracle::{convert::f64_to_exact, truth, CaseInput, ExactCase, Q};

fn circle(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            [1e4 * a.cos(), 1e4 * a.sin()]
        })
        .collect()
}

fn star(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            let r = 1e4 * (1.0 + 0.3 * (64.0 * a).sin());
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// One case's inputs: vertices, velocities, point position and velocity, slab.
struct Raw {
    verts: Vec<[f64; 2]>,
    vels: Vec<[f64; 2]>,
    pos: Vec<f64>,
    vel: Vec<f64>,
    slab: Option<[f64; 3]>,
}

fn cases(n: usize) -> Vec<(&'static str, Raw)> {
    let grow = |v: &[[f64; 2]]| v.iter().map(|p| [0.01 * p[0], 0.01 * p[1]]).collect();
    let (c, s) = (circle(n), star(n));
    vec![
        (
            "circle-rest-enter",
            Raw {
                vels: vec![],
                verts: c.clone(),
                pos: vec![-2e4, 0.5],
                vel: vec![1e3, 0.0],
                slab: None,
            },
        ),
        (
            "circle-moving-enter",
            Raw {
                vels: vec![[-300.0, 10.0]; n],
                verts: c.clone(),
                pos: vec![-2e4, 0.5],
                vel: vec![700.0, 0.0],
                slab: None,
            },
        ),
        (
            "star-warp-miss",
            Raw {
                vels: grow(&s),
                verts: s.clone(),
                pos: vec![-2e4, 1.7e4],
                vel: vec![800.0, 0.0],
                slab: None,
            },
        ),
        (
            "star-3d-warp",
            Raw {
                vels: grow(&s),
                verts: s,
                pos: vec![-2e4, 0.5, 0.0],
                vel: vec![1e3, 0.0, 1.0],
                slab: Some([5.0, 15.0, 0.0]),
            },
        ),
    ]
}

/// The work of one `detect --engine truth` answer after parsing.
fn answer(r: &Raw, cos_kappa: &Q) -> bool {
    let c = CaseInput {
        lookahead: 20.0,
        buff: 0.1,
        fac: 1e-4,
        pos: &r.pos,
        vel: &r.vel,
        vertices: &r.verts,
        velocities: &r.vels,
        slab: r.slab,
    };
    let Ok(exact) = ExactCase::<Q>::new(&c) else {
        return false;
    };
    let t = truth(&exact);
    let wf = well_formed_fault(&exact.vertices, &exact.buff, cos_kappa);
    black_box(&t);
    wf.is_none()
}

fn benches(c: &mut Criterion) {
    let cos_kappa = f64_to_exact::<Q>(5f64.to_radians().cos()).expect("finite");
    let mut group = c.benchmark_group("truth_large");
    group.sample_size(10);
    group.warm_up_time(std::time::Duration::from_millis(500));
    group.measurement_time(std::time::Duration::from_secs(3));
    for n in [4096usize, 16384] {
        for (name, raw) in cases(n) {
            group.bench_with_input(BenchmarkId::new(name, n), &raw, |b, r| {
                b.iter(|| answer(r, &cos_kappa))
            });
        }
    }
    // The reference it replaced: the pairwise §II.J report on 128 vertices.
    let p: Vec<_> = circle(128)
        .iter()
        .map(|v| {
            polyguard_oracle::V2::new(
                f64_to_exact::<Q>(v[0]).expect("finite"),
                f64_to_exact::<Q>(v[1]).expect("finite"),
            )
        })
        .collect();
    let buff = f64_to_exact::<Q>(0.1).expect("finite");
    group.sample_size(10);
    group.bench_function("reference/well_formed_fault_pairwise/128", |b| {
        b.iter(|| well_formed_fault_pairwise(black_box(&p), &buff, &cos_kappa))
    });
    group.bench_function("well_formed_fault/128", |b| {
        b.iter(|| well_formed_fault(black_box(&p), &buff, &cos_kappa))
    });
    group.finish();
}

criterion_group!(truth_large, benches);
criterion_main!(truth_large);
