//! Throughput of the oracle: ground truth and paper-exact detection (detect_diff_2D,
//! the workload's polygons warp) on a seeded workload of random star-shaped
//! counterclockwise warping polygons of size ~1000, lookahead 300, BUFF 0.01,
//! F 1e-4, n = 4, 8, 16 (cases/s is the "elements" throughput criterion prints).
//! Each is measured "filtered", the interval kernel in front of the exact one (the
//! default `paper_detect`, `truth`), and "unfiltered", the exact kernel alone
//! (`paper_detect_unfiltered`, `truth_unfiltered`), and "both" is paper_detect + truth
//! together, what one differential comparison costs the oracle.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use polyguard_oracle::{
    paper_detect, paper_detect_unfiltered, truth, truth_unfiltered, CaseInput, ExactCase,
    ExactField, PaperAnswer, Truth,
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

struct OwnedCase {
    pos: [f64; 2],
    vel: [f64; 2],
    verts: Vec<[f64; 2]>,
    vels: Vec<[f64; 2]>,
}

fn workload(n: usize, count: usize, seed: u64) -> Vec<OwnedCase> {
    let mut g = Rng(seed);
    (0..count)
        .map(|_| {
            let (cx, cy) = (g.uni(-2000.0, 2000.0), g.uni(-2000.0, 2000.0));
            let verts: Vec<[f64; 2]> = (0..n)
                .map(|k| {
                    let a = (k as f64 + g.uni(0.1, 0.9)) * std::f64::consts::TAU / n as f64;
                    let r = g.uni(250.0, 500.0);
                    [cx + r * a.cos(), cy + r * a.sin()]
                })
                .collect();
            let base = [g.uni(-2.0, 2.0), g.uni(-2.0, 2.0)];
            let vels: Vec<[f64; 2]> = (0..n)
                .map(|_| [base[0] + g.uni(-0.5, 0.5), base[1] + g.uni(-0.5, 0.5)])
                .collect();
            // Start 1500–2500 away; aim at the centre (about half hit) or off it.
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
            let vel = [
                speed * (aim[0] - pos[0]) / d + base[0],
                speed * (aim[1] - pos[1]) / d + base[1],
            ];
            OwnedCase {
                pos,
                vel,
                verts,
                vels,
            }
        })
        .collect()
}

fn exact<F: ExactField>(cases: &[OwnedCase]) -> Vec<ExactCase<F>> {
    cases
        .iter()
        .filter_map(|c| {
            ExactCase::new(&CaseInput {
                lookahead: 300.0,
                buff: 0.01,
                fac: 1e-4,
                pos: &c.pos,
                vel: &c.vel,
                vertices: &c.verts,
                velocities: &c.vels,
                slab: None,
            })
            .ok()
        })
        .collect()
}

fn run_backend<F: ExactField>(c: &mut Criterion, name: &str) {
    let mut group = c.benchmark_group(format!("oracle/{name}"));
    group.sample_size(10);
    group.warm_up_time(std::time::Duration::from_millis(500));
    group.measurement_time(std::time::Duration::from_secs(3));
    for n in [4usize, 8, 16] {
        let cases: Vec<ExactCase<F>> = exact(&workload(n, 64, 0x5eed_0000 + n as u64));
        group.throughput(Throughput::Elements(cases.len() as u64));
        type Paper<F> = fn(&ExactCase<F>) -> PaperAnswer;
        type Ground<F> = fn(&ExactCase<F>) -> Truth;
        let variants: [(&str, Paper<F>, Ground<F>); 2] = [
            ("filtered", paper_detect, truth),
            ("unfiltered", paper_detect_unfiltered, truth_unfiltered),
        ];
        for (label, paper, ground) in variants {
            group.bench_with_input(
                BenchmarkId::new(format!("paper_detect/{label}"), n),
                &cases,
                |b, cs| b.iter(|| cs.iter().filter(|c| black_box(paper(c)).detected).count()),
            );
            group.bench_with_input(
                BenchmarkId::new(format!("truth/{label}"), n),
                &cases,
                |b, cs| {
                    b.iter(|| {
                        cs.iter()
                            .filter(|c| matches!(black_box(ground(c)), Truth::Enters { .. }))
                            .count()
                    })
                },
            );
            if label == "filtered" {
                group.bench_with_input(
                    BenchmarkId::new(format!("both/{label}"), n),
                    &cases,
                    |b, cs| {
                        b.iter(|| {
                            cs.iter()
                                .filter(|c| {
                                    let detected = black_box(paper(c)).detected;
                                    let enters =
                                        matches!(black_box(ground(c)), Truth::Enters { .. });
                                    detected == enters
                                })
                                .count()
                        })
                    },
                );
            }
        }
    }
    group.finish();
}

fn benches(c: &mut Criterion) {
    run_backend::<polyguard_oracle::Q>(c, "num");
    #[cfg(feature = "rug")]
    run_backend::<polyguard_oracle::R>(c, "rug");
}

criterion_group!(oracle, benches);
criterion_main!(oracle);
