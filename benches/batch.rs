//! Criterion bench of batch detection (`polyguard::batch`), group `batch`:
//! 10⁴ points against 10³ polygons of 8 vertices at the harness's density
//! (`polyguard_harness::batch`: polygons about 1 across, one per 1000 square units
//! in a 1000 × 1000 square, a quarter warping; points at 2 to 5 units per time unit for
//! T = 10, a tenth of them aimed at a polygon's vertex), seed 1.
//!
//! - `grid_parallel`: the default (the grid broad phase, rayon's threads with the feature
//!   `parallel`; one thread without it, when it measures the same as `grid_sequential`);
//! - `grid_sequential`: the grid on one thread;
//! - `all_pairs_parallel`: every pair's boxes tested instead of the grid (10⁷ box tests),
//!   the broad phase the grid replaces.
//!
//!
//! Group `batch_dense`: the dense workload of crates/python/bench/bench_batch.py
//! (`polyguard_harness::batch::dense_workload`, 10³ points × 10³ polygons, seed 1: every
//! pair a candidate, 140,203 hits), `dense_parallel` and `dense_sequential`.
//!
//! `cargo bench --bench batch --features parallel` measures all five in one run.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use polyguard::api::Params;
use polyguard::batch::{detect_batch_with, Broad, Options};
use polyguard_harness::batch::{batch_workload, dense_workload, Mix, BUFF, FAC, T};

fn batch(c: &mut Criterion) {
    let w = batch_workload(10_000, 1_000, 1, Mix::BENCH);
    let params = Params::new(BUFF).and_then(|p| p.with_fac(FAC)).unwrap();
    let mut g = c.benchmark_group("batch");
    g.sample_size(10);
    for (name, broad, parallel) in [
        ("grid_parallel", Broad::Grid, true),
        ("grid_sequential", Broad::Grid, false),
        ("all_pairs_parallel", Broad::AllPairs, true),
    ] {
        let opts = Options {
            broad,
            parallel,
            ..Options::default()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                detect_batch_with(T, black_box(&w.points), &w.polygons, &params, &opts)
                    .map(|r| r.hits.len())
            })
        });
    }
    g.finish();
    let w = dense_workload(1_000, 1_000, 1);
    let mut g = c.benchmark_group("batch_dense");
    g.sample_size(10);
    for (name, parallel) in [("dense_parallel", true), ("dense_sequential", false)] {
        let opts = Options {
            parallel,
            ..Options::default()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                detect_batch_with(T, black_box(&w.points), &w.polygons, &params, &opts)
                    .map(|r| r.hits.len())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, batch);
criterion_main!(benches);
