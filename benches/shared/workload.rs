//! The benchmark workload, shared by benches/detect.rs (criterion) and
//! examples/uniform_workload.rs (the same cases as case lines, for `polyguard detect`):
//! random star-shaped counterclockwise polygons of size ~1000, lookahead 300, BUFF 0.01,
//! F 1e-4, a point starting 1500 from the centre aimed within 800 of it, about half the
//! cases hitting. No threshold is sought: the uniform workload.
#![allow(dead_code)]

use polyguard::Vect2;

/// SplitMix64: a tiny seeded generator, so the workload is the same on every run.
pub struct Rng(pub u64);
impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }
}

pub struct Workload {
    pub verts: Vec<Vec<Vect2>>,
    pub vels: Vec<Vec<Vect2>>,
    pub s: Vec<Vect2>,
    pub v: Vec<Vect2>,
    pub z: Vec<(f64, f64)>,
}

pub const T: f64 = 300.0;
pub const BUFF: f64 = 0.01;
pub const FAC: f64 = 1e-4;
pub const CASES: usize = 256;

pub fn workload(n: usize, warping: bool, seed: u64) -> Workload {
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
