//! Criterion benches of paper B's pipeline on the generator's scenarios (§VI.D):
//! `end_to_end_800` (parse + four stages + answer JSON, per mix), `stages_800_mixed`
//! (each stage alone on its real input) and `scaling` (10³, 10⁴ objects, mixed, at the
//! paper's density with `--density-box`). The 10⁵ and 10⁶ rows come from the CLI
//! (`polyguard generate … --density-box | polyguard conflicts -`), as docs/performance.md says.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use polyguard_earth::analysis::analyse;
use polyguard_earth::conflict::{
    pipeline, stage1, stage2, stage3, stage4, DEFAULT_TIME_TOLERANCE_H,
};
use polyguard_earth::generate::Mix;
use polyguard_earth::scenario;
use polyguard_harness::paper_b::seeded;

fn text(n: usize, mix: Mix, density_box: bool) -> String {
    scenario::to_geojson(&seeded(n, mix, 1, density_box)).to_string()
}

fn end_to_end(c: &mut Criterion) {
    let mut g = c.benchmark_group("end_to_end_800");
    for (name, mix) in [
        ("static", Mix::Static),
        ("mixed", Mix::Mixed),
        ("tracks", Mix::Tracks),
    ] {
        let t = text(800, mix, false);
        g.bench_function(name, |b| {
            b.iter(|| analyse(black_box(&t), DEFAULT_TIME_TOLERANCE_H).map(|a| a.answer.len()))
        });
    }
    g.finish();
}

fn stages(c: &mut Criterion) {
    let sc = seeded(800, Mix::Mixed, 1, false);
    let objs = scenario::objects(&sc);
    let cands = stage1::candidates(&objs);
    let regions = stage2::regions(&objs, &cands, true);
    let windows = stage3::windows(&objs, regions.clone(), true);
    let mut g = c.benchmark_group("stages_800_mixed");
    g.bench_function("objects", |b| {
        b.iter(|| scenario::objects(black_box(&sc)).len())
    });
    g.bench_function("stage1", |b| {
        b.iter(|| stage1::candidates(black_box(&objs)).pairs.len())
    });
    g.bench_function("stage2", |b| {
        b.iter(|| {
            stage2::regions(&objs, black_box(&cands), true)
                .regions
                .len()
        })
    });
    g.bench_function("stage3", |b| {
        b.iter(|| {
            stage3::windows(&objs, black_box(regions.clone()), true)
                .windows
                .len()
        })
    });
    g.bench_function("stage4", |b| {
        b.iter(|| {
            stage4::intervals(&objs, black_box(windows.clone()), DEFAULT_TIME_TOLERANCE_H)
                .intervals
                .len()
        })
    });
    g.finish();
}

fn scaling(c: &mut Criterion) {
    let mut g = c.benchmark_group("scaling");
    g.sample_size(10);
    for n in [1_000usize, 10_000] {
        let objs = scenario::objects(&seeded(n, Mix::Mixed, 1, true));
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::new("mixed_density_box", n), &objs, |b, o| {
            b.iter(|| {
                pipeline::run(black_box(o), pipeline::Options::default())
                    .0
                    .len()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, end_to_end, stages, scaling);
criterion_main!(benches);
