//! The benchmark workload, shared by benches/detect.rs (criterion),
//! crates/harness/examples/speed_ratio.rs and crates/harness/examples/uniform_workload.rs (the same cases as case lines,
//! for `polyguard detect`):
//! random star-shaped counterclockwise polygons of size ~1000, lookahead 300, BUFF 0.01,
//! F 1e-4, a point starting 1500 from the centre aimed within 800 of it, about half the
//! cases hitting. No threshold is sought: the uniform workload.

use super::gen::{Source, SplitMix};
use polyguard::Vect2;

/// `CASES` cases of one shape, as the engine's paper functions take them.
pub struct Workload {
    /// Each case's polygon, counterclockwise (a few raw polygons cross themselves; the
    /// case format refuses those, the paper functions take them).
    pub verts: Vec<Vec<Vect2>>,
    /// Each case's vertex velocities.
    pub vels: Vec<Vec<Vect2>>,
    /// Each case's point.
    pub s: Vec<Vect2>,
    /// Each case's point velocity.
    pub v: Vec<Vect2>,
    /// Each case's point height and vertical speed, for the 3D benches (slab 0 to 1000).
    pub z: Vec<(f64, f64)>,
}

/// T, the lookahead time.
pub const T: f64 = 300.0;
/// BUFF.
pub const BUFF: f64 = 0.01;
/// F.
pub const FAC: f64 = 1e-4;
/// Cases per workload.
pub const CASES: usize = 256;

/// The workload of `CASES` cases with `n`-gons, warping or not, from `seed`.
pub fn workload(n: usize, warping: bool, seed: u64) -> Workload {
    let mut rng = SplitMix(seed);
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
            .map(|_| rng.range(0.0, std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        let verts: Vec<Vect2> = angles
            .iter()
            .map(|&a| {
                let r = rng.range(250.0, 500.0);
                Vect2::new(r * a.cos(), r * a.sin())
            })
            .collect();
        let drift = Vect2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let vels = (0..n)
            .map(|_| {
                if warping {
                    drift + Vect2::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5))
                } else {
                    drift
                }
            })
            .collect();
        // Start 1500 from the centre, aim within 800 of it, cover ~2000 in T.
        let a = rng.range(0.0, std::f64::consts::TAU);
        let s = Vect2::new(1500.0 * a.cos(), 1500.0 * a.sin());
        let target = Vect2::new(rng.range(-800.0, 800.0), rng.range(-800.0, 800.0));
        let d = target - s;
        let v = d.scale(rng.range(5.0, 8.0) / d.sq().sqrt());
        w.verts.push(verts);
        w.vels.push(vels);
        w.s.push(s);
        w.v.push(v);
        w.z.push((rng.range(100.0, 1000.0), rng.range(-1.0, 1.0)));
    }
    w
}
