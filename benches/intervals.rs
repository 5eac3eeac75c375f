//! Criterion benches of the certified intervals and of keep-in exit detection, each
//! beside the detector it extends, in one run, on the seeded uniform workload of
//! benches/detect.rs (random star-shaped counterclockwise polygons of size ~1000,
//! lookahead 300, a point starting 1500 from the centre).
//!
//! Group `intervals`: per workload (n = 8 and 32, static and warping), the first-entry
//! enclosure (`first_entry`, what `api::detect_time` runs), the spans of inside and the
//! spans of near_D with D = 10 (`intervals_into`, no heap).
//!
//! Group `exit`: `api::detect` against `api::detect_exit` (D = 10) on the same cases as
//! validated `Case`s (the few raw polygons that cross themselves are left out), on the
//! uniform workload (the point starts outside the fence: an exit at t = 0) and on its
//! keep-in variant (the point starts at the polygon's centre, inside).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use polyguard::api::{detect, detect_exit, Case, MovingPoint, MovingPolygon, Params};
use polyguard::entry::{first_entry, EntryTime};
use polyguard::intervals::{intervals_into, End, Relation, Separation, Span};
use polyguard::Vect2;
use polyguard_harness::workload::{workload, Workload, BUFF, CASES, T};

/// D for near_D and the fence: 1 % of the polygons' size.
const D: f64 = 10.0;

/// The workloads: label, n, warping.
const SHAPES: [(&str, usize, bool); 4] = [
    ("static/8", 8, false),
    ("warping/8", 8, true),
    ("static/32", 32, false),
    ("warping/32", 32, true),
];

/// The number of spans of case i (a stack buffer; an overflow counts what it needs).
fn spans(w: &Workload, i: usize, relation: Relation) -> usize {
    let blank = Span {
        start: End::at(0.0),
        end: End::at(0.0),
        certain: false,
    };
    let mut out = [blank; 16];
    let sep = Separation { d: D, h: 0.0 };
    let (s, v, p, vels) = (w.s[i], w.v[i], &w.verts[i][..], &w.vels[i][..]);
    match intervals_into(T, s, v, p, vels, None, relation, sep, &mut out) {
        Ok(n) => n,
        Err(o) => o.needed_at_least,
    }
}

fn intervals(c: &mut Criterion) {
    let mut g = c.benchmark_group("intervals");
    g.throughput(Throughput::Elements(CASES as u64));
    for (label, n, warping) in SHAPES {
        let w = workload(n, warping, 42 + n as u64);
        let time =
            |w: &Workload, i: usize| first_entry(T, w.s[i], w.v[i], &w.verts[i], &w.vels[i], None);
        let inside: usize = (0..CASES).map(|i| spans(&w, i, Relation::Inside)).sum();
        let near: usize = (0..CASES).map(|i| spans(&w, i, Relation::Near)).sum();
        eprintln!("intervals {label}: {inside} spans of inside, {near} of near_D in {CASES} cases");
        g.bench_with_input(BenchmarkId::new("first_entry", label), &w, |b, w| {
            b.iter(|| {
                (0..CASES)
                    .filter(|&i| black_box(time(black_box(w), i)) != EntryTime::Never)
                    .count()
            })
        });
        for (name, rel) in [("inside", Relation::Inside), ("near", Relation::Near)] {
            g.bench_with_input(BenchmarkId::new(name, label), &w, |b, w| {
                b.iter(|| {
                    (0..CASES)
                        .map(|i| spans(black_box(w), i, rel))
                        .sum::<usize>()
                })
            });
        }
    }
    g.finish();
}

/// The workload's cases as validated `Case`s (the point at the polygon's centre when
/// `keep_in`).
fn cases(w: &Workload, keep_in: bool) -> Vec<Case> {
    (0..CASES)
        .filter_map(|i| {
            let poly = MovingPolygon::new(w.verts[i].clone(), Some(w.vels[i].clone())).ok()?;
            let s = if keep_in { Vect2::ZERO } else { w.s[i] };
            let point = MovingPoint::new_2d(s, w.v[i]).ok()?;
            Case::new(T, point, poly, Params::new(BUFF).ok()?).ok()
        })
        .collect()
}

fn exit(c: &mut Criterion) {
    let mut g = c.benchmark_group("exit");
    let sep = Separation { d: D, h: 0.0 };
    for (label, n, warping) in SHAPES {
        let w = workload(n, warping, 42 + n as u64);
        for (start, keep_in) in [("uniform", false), ("keep_in", true)] {
            let cs = cases(&w, keep_in);
            g.throughput(Throughput::Elements(cs.len() as u64));
            let exits = cs.iter().filter(|c| detect_exit(c, sep).detected).count();
            eprintln!("exit {start}/{label}: {exits} of {} cases exit", cs.len());
            let id = format!("{start}/{label}");
            g.bench_with_input(BenchmarkId::new("detect", &id), &cs, |b, cs| {
                b.iter(|| cs.iter().filter(|c| detect(black_box(c)).detected).count())
            });
            g.bench_with_input(BenchmarkId::new("detect_exit", &id), &cs, |b, cs| {
                b.iter(|| {
                    cs.iter()
                        .filter(|c| detect_exit(black_box(c), sep).detected)
                        .count()
                })
            });
        }
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = intervals, exit
}
criterion_main!(benches);
