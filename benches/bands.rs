//! Criterion bench of the certified course bands: one aircraft against 10 convective
//! cells of 16 vertices (half of them drifting), lookahead 10 min, D = 5 nm, speed
//! 8 nm/min (480 kt), Unknown total at most 0.1° (the wayout contract's target: ≤ 1 ms
//! per call). Lengths in nautical miles, times in minutes. The cells are star-shaped
//! 16-gons of radius 3 to 9 nm, centred 15 to 75 nm from the aircraft on a seeded
//! generator, so that some are out of reach and some overlap the reachable disc.
//!
//! Group `bands`: `course_bands` (the scene above) and `speed_bands` at course 0 over
//! [4, 10] nm/min with Unknown ≤ 0.01 nm/min.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use polyguard::bands::{course_bands, speed_bands, Obstacle, Traffic};
use polyguard::{Separation, Vect2};

/// 0.1° in radians.
const TENTH_DEGREE: f64 = std::f64::consts::PI / 1800.0;

/// A small seeded generator (64-bit LCG, top 53 bits as a fraction of 1).
struct Lcg(u64);

impl Lcg {
    /// The next number in [0, 1).
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The 10 cells: (vertices, velocities).
fn cells(seed: u64) -> Vec<(Vec<Vect2>, Vec<Vect2>)> {
    let mut g = Lcg(seed);
    (0..10)
        .map(|k| {
            let (dist, bearing) = (15.0 + 60.0 * g.next(), std::f64::consts::TAU * g.next());
            let c = Vect2::new(dist * bearing.sin(), dist * bearing.cos());
            let radius = 3.0 + 6.0 * g.next();
            let p: Vec<Vect2> = (0..16)
                .map(|i| {
                    let a = std::f64::consts::TAU * (i as f64) / 16.0;
                    let r = radius * (0.7 + 0.3 * g.next());
                    Vect2::new(c.x + r * a.cos(), c.y + r * a.sin())
                })
                .collect();
            let drift = if k % 2 == 0 {
                let a = std::f64::consts::TAU * g.next();
                Vect2::new(0.5 * a.cos(), 0.5 * a.sin())
            } else {
                Vect2::ZERO
            };
            (p, vec![drift; 16])
        })
        .collect()
}

fn bands(c: &mut Criterion) {
    let cells = cells(7);
    let obstacles: Vec<Obstacle> = cells
        .iter()
        .map(|(p, vels)| Obstacle {
            p,
            vels,
            slab: None,
        })
        .collect();
    let traffic = Traffic {
        t: 10.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: Separation { d: 5.0, h: 0.0 },
    };
    let answer = course_bands(&traffic, 8.0, TENTH_DEGREE).expect("valid");
    eprintln!(
        "bands: {} course bands, Unknown total {:.3e} rad ({:.4}°), met {}",
        answer.bands.len(),
        answer.unknown_total,
        answer.unknown_total.to_degrees(),
        answer.met
    );
    let speeds = speed_bands(&traffic, 0.0, 4.0, 10.0, 0.01).expect("valid");
    eprintln!(
        "bands: {} speed bands, Unknown total {:.3e}, met {}",
        speeds.bands.len(),
        speeds.unknown_total,
        speeds.met
    );
    let mut g = c.benchmark_group("bands");
    g.bench_function("course_bands/10x16", |b| {
        b.iter(|| course_bands(black_box(&traffic), 8.0, TENTH_DEGREE))
    });
    g.bench_function("speed_bands/10x16", |b| {
        b.iter(|| speed_bands(black_box(&traffic), 0.0, 4.0, 10.0, 0.01))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = bands
}
criterion_main!(benches);
