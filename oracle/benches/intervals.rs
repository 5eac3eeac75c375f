//! Cost of the exact sets of times (`intervals_of`) and of keep-in exit detection
//! (`detect_exit_of`) on a seeded workload of random star-shaped counterclockwise
//! polygons of size ~500 (n = 4, 8, 16), at rest, translating or warping, 2D or 3D
//! (a slab the point crosses about half the time), the point aimed at the centre or
//! off it, lookahead 300, D = 10, H = 5. Group `intervals`: cases/s per relation
//! ("elements" throughput).
//!
//! Before criterion runs, the binary prints the distribution of the time of one call
//! (each case timed alone, the best of 3 runs): the median per case is the figure a
//! campaign's budget is set against.

use std::time::{Duration, Instant};

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use polyguard_oracle::{
    detect_exit_of, intervals_of, CaseInput, ExactCase, ExactField, Relation, Separation, Q,
};

struct Rng(u64);
impl Rng {
    fn f(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn uni(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
}

/// How the polygon moves.
#[derive(Clone, Copy, Debug)]
enum Motion {
    Rest,
    Translating,
    Warping,
}

/// One random case (f64 inputs, made exact).
fn case<F: ExactField>(
    g: &mut Rng,
    n: usize,
    motion: Motion,
    three_d: bool,
) -> Option<ExactCase<F>> {
    let (cx, cy) = (g.uni(-2000.0, 2000.0), g.uni(-2000.0, 2000.0));
    let verts: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let a = (k as f64 + g.uni(0.1, 0.9)) * std::f64::consts::TAU / n as f64;
            let r = g.uni(250.0, 500.0);
            [cx + r * a.cos(), cy + r * a.sin()]
        })
        .collect();
    let base = match motion {
        Motion::Rest => [0.0, 0.0],
        _ => [g.uni(-2.0, 2.0), g.uni(-2.0, 2.0)],
    };
    let vels: Vec<[f64; 2]> = (0..n)
        .map(|_| match motion {
            Motion::Warping => [base[0] + g.uni(-0.5, 0.5), base[1] + g.uni(-0.5, 0.5)],
            _ => base,
        })
        .collect();
    let ang = g.uni(0.0, std::f64::consts::TAU);
    let dist = g.uni(1500.0, 2500.0);
    let pos = [cx + dist * ang.cos(), cy + dist * ang.sin()];
    let off = if g.f() < 0.5 {
        0.0
    } else {
        g.uni(600.0, 1500.0)
    };
    let aim = [cx + off * (ang + 1.0).cos(), cy + off * (ang + 1.0).sin()];
    let speed = g.uni(8.0, 12.0);
    let d = ((aim[0] - pos[0]).powi(2) + (aim[1] - pos[1]).powi(2)).sqrt();
    let vel2 = [
        speed * (aim[0] - pos[0]) / d + base[0],
        speed * (aim[1] - pos[1]) / d + base[1],
    ];
    let (pos3, vel3) = (
        [pos[0], pos[1], g.uni(-100.0, 100.0)],
        [vel2[0], vel2[1], g.uni(-1.0, 1.0)],
    );
    let slab = [g.uni(-200.0, -50.0), g.uni(50.0, 200.0), g.uni(-0.5, 0.5)];
    let (p, v): (&[f64], &[f64]) = if three_d {
        (&pos3, &vel3)
    } else {
        (&pos, &vel2)
    };
    ExactCase::new(&CaseInput {
        lookahead: 300.0,
        buff: 0.01,
        fac: 1e-4,
        pos: p,
        vel: v,
        vertices: &verts,
        velocities: &vels,
        slab: three_d.then_some(slab),
    })
    .ok()
}

/// `count` cases of n vertices, the motions and dimensions in turn.
fn workload<F: ExactField>(n: usize, count: usize, seed: u64) -> Vec<ExactCase<F>> {
    let mut g = Rng(seed | 1);
    let motions = [Motion::Rest, Motion::Translating, Motion::Warping];
    (0..count)
        .filter_map(|k| case(&mut g, n, motions[k % 3], k % 2 == 1))
        .collect()
}

fn separation() -> Separation<Q> {
    Separation {
        d: Q::from_integer(10.into()),
        h: Q::from_integer(5.into()),
    }
}

/// The per-case distribution of one call's time, printed (see the module doc).
fn distribution() {
    let sep = separation();
    for n in [4usize, 8, 16] {
        let cases: Vec<ExactCase<Q>> = workload(n, 600, 0xd157 + n as u64);
        for rel in [Relation::Inside, Relation::Near, Relation::Breach] {
            let mut times: Vec<Duration> = cases
                .iter()
                .map(|c| {
                    (0..3)
                        .map(|_| {
                            let t0 = Instant::now();
                            black_box(intervals_of(black_box(c), rel, &sep)).ok();
                            t0.elapsed()
                        })
                        .min()
                        .unwrap_or_default()
                })
                .collect();
            times.sort();
            let at = |q: f64| times[((times.len() - 1) as f64 * q) as usize];
            println!(
                "intervals_of {:6} n = {n:2}: median {:7.1?}  p90 {:7.1?}  p99 {:7.1?}  max {:7.1?}  ({} cases)",
                rel.name(),
                at(0.5),
                at(0.9),
                at(0.99),
                at(1.0),
                times.len()
            );
        }
    }
}

fn benches(c: &mut Criterion) {
    distribution();
    let sep = separation();
    let mut group = c.benchmark_group("intervals");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    for n in [4usize, 8, 16] {
        let cases: Vec<ExactCase<Q>> = workload(n, 96, 0x5eed + n as u64);
        group.throughput(Throughput::Elements(cases.len() as u64));
        for rel in [Relation::Inside, Relation::Near, Relation::Breach] {
            group.bench_with_input(BenchmarkId::new(rel.name(), n), &cases, |b, cs| {
                b.iter(|| {
                    cs.iter()
                        .filter(|c| {
                            black_box(intervals_of(c, rel, &sep)).is_ok_and(|s| !s.is_empty())
                        })
                        .count()
                })
            });
        }
        group.bench_with_input(BenchmarkId::new("detect_exit", n), &cases, |b, cs| {
            b.iter(|| {
                cs.iter()
                    .filter(|c| black_box(detect_exit_of(c, &sep)) == Ok(true))
                    .count()
            })
        });
    }
    group.finish();
}

criterion_group!(intervals, benches);
criterion_main!(intervals);
