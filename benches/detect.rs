//! Criterion benches of paper A's detectors on a seeded workload: random star-shaped
//! counterclockwise polygons of size ~1000, lookahead 300, BUFF 0.01, F 1e-4, about half
//! the cases hitting. Groups: detect_same_2d, detect_diff_2d (n = 4 … 64) and detect_3d
//! (n = 8, static and warping).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use polyguard::detect::{detect_3d, detect_diff_2d, detect_same_2d};
use polyguard::Vect2;

/// SplitMix64: a tiny seeded generator, so the workload is the same on every run.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }
}

struct Workload {
    verts: Vec<Vec<Vect2>>,
    vels: Vec<Vec<Vect2>>,
    s: Vec<Vect2>,
    v: Vec<Vect2>,
    z: Vec<(f64, f64)>,
}

const T: f64 = 300.0;
const BUFF: f64 = 0.01;
const FAC: f64 = 1e-4;
const CASES: usize = 256;

fn workload(n: usize, warping: bool, seed: u64) -> Workload {
    let mut rng = Rng(seed);
    let mut w = Workload {
        verts: vec![],
        vels: vec![],
        s: vec![],
        v: vec![],
        z: vec![],
    };
    for _ in 0..CASES {
        // Star-shaped around the origin: sorted angles, radii 250…500 (size ~1000).
        let mut angles: Vec<f64> = (0..n)
            .map(|_| rng.uniform(0.0, std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        let verts: Vec<Vect2> = angles
            .iter()
            .map(|&a| {
                let r = rng.uniform(250.0, 500.0);
                Vect2::new(r * a.cos(), r * a.sin())
            })
            .collect();
        let drift = Vect2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        let vels = (0..n)
            .map(|_| {
                if warping {
                    drift + Vect2::new(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5))
                } else {
                    drift
                }
            })
            .collect();
        // Start 1500 from the centre, aim within 800 of it, cover ~2000 in T.
        let a = rng.uniform(0.0, std::f64::consts::TAU);
        let s = Vect2::new(1500.0 * a.cos(), 1500.0 * a.sin());
        let target = Vect2::new(rng.uniform(-800.0, 800.0), rng.uniform(-800.0, 800.0));
        let d = target - s;
        let v = d.scale(rng.uniform(5.0, 8.0) / d.sq().sqrt());
        w.verts.push(verts);
        w.vels.push(vels);
        w.s.push(s);
        w.v.push(v);
        w.z.push((rng.uniform(100.0, 1000.0), rng.uniform(-1.0, 1.0)));
    }
    w
}

fn hits(w: &Workload, f: impl Fn(&Workload, usize) -> bool) -> usize {
    (0..CASES).filter(|&i| f(w, i)).count()
}

fn same(w: &Workload, i: usize) -> bool {
    detect_same_2d(T, w.s[i], w.v[i], &w.verts[i][..], &w.vels[i][..], BUFF)
}
fn diff(w: &Workload, i: usize) -> bool {
    detect_diff_2d(
        T,
        w.s[i],
        w.v[i],
        &w.verts[i][..],
        &w.vels[i][..],
        FAC,
        BUFF,
    )
}
fn three(w: &Workload, i: usize) -> bool {
    let (sz, vz) = w.z[i];
    detect_3d(
        T,
        w.s[i],
        w.v[i],
        sz,
        vz,
        &w.verts[i][..],
        &w.vels[i][..],
        0.0,
        1000.0,
        0.0,
        BUFF,
        FAC,
    )
}

fn bench(c: &mut Criterion) {
    for (name, warping, f) in [
        (
            "detect_same_2d",
            false,
            same as fn(&Workload, usize) -> bool,
        ),
        ("detect_diff_2d", true, diff),
    ] {
        let mut g = c.benchmark_group(name);
        g.throughput(Throughput::Elements(CASES as u64));
        for n in [4usize, 8, 16, 32, 64] {
            let w = workload(n, warping, 42 + n as u64);
            eprintln!("{name} n={n}: {} of {CASES} cases hit", hits(&w, f));
            g.bench_with_input(BenchmarkId::from_parameter(n), &w, |b, w| {
                b.iter(|| {
                    (0..CASES)
                        .filter(|&i| black_box(f(black_box(w), i)))
                        .count()
                })
            });
        }
        g.finish();
    }
    let mut g = c.benchmark_group("detect_3d");
    g.throughput(Throughput::Elements(CASES as u64));
    for (label, warping) in [("static/8", false), ("warping/8", true)] {
        let w = workload(8, warping, 7);
        eprintln!(
            "detect_3d {label}: {} of {CASES} cases hit",
            hits(&w, three)
        );
        g.bench_with_input(BenchmarkId::from_parameter(label), &w, |b, w| {
            b.iter(|| {
                (0..CASES)
                    .filter(|&i| black_box(three(black_box(w), i)))
                    .count()
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench
}
criterion_main!(benches);
