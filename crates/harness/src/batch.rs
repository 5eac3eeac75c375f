//! The seeded batch workload (batch detection; extends paper A's single case to
//! N points and M polygons): the one generator behind benches/batch.rs, the batch tests
//! and `polyguard detect-batch --generate`.
//!
//! **Density.** M polygons of 8 vertices, each about 1 across (star-shaped, radii 0.3 to
//! 0.6 around its centre), their centres uniform in a square of side 31.6·√M (1000 for
//! M = 1000: one polygon per 1000 square units), drifting at up to 1 unit per time
//! unit. N points uniform in the same square, moving at 5 to 15 units per time unit for
//! T = 10: a path of 50 to 150 units, whose swept box meets the grown boxes of 3.6
//! polygons on average (2,000 points and 200 polygons of seed 1: 7,135 pairs of 400,000,
//! 293 hits). BUFF = 0.05, F = 10⁻⁴.
//!
//! **Boundary pairs.** A share of the points ([`Mix::aimed`]) is aimed at a vertex of a
//! random polygon, arriving at 0, ½, 1, 1 + 2⁻²⁰ or 2 times BUFF (or F times the edge
//! from it, for a warping polygon, when that is more) from it: half of them at a random
//! time, outwards from the opposite vertex; half past the vertex that is extreme along
//! an axis, at the end of [0, T] where the polygon's swept box reaches farthest that
//! way, on a path that stays beyond it (so that the two swept boxes are just apart, or
//! just touch); in 3D at a height exactly at the slab's top or bottom then, or just
//! beyond, or inside: pairs that touch, nearly touch and just miss.

use super::gen::{Source, SplitMix};
use polyguard::api::{MovingPoint, MovingPolygon};
use polyguard::Vect2;

/// T of the workload.
pub const T: f64 = 10.0;
/// BUFF of the workload.
pub const BUFF: f64 = 0.05;
/// F of the workload.
pub const FAC: f64 = 1e-4;

/// What the workload holds besides uniform points and rigid polygons.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mix {
    /// 3D: every point has a height, every polygon a slab.
    pub three_d: bool,
    /// The share of polygons that warp (each vertex's velocity its own).
    pub warping: f64,
    /// The share of points aimed at a polygon's vertex (boundary pairs).
    pub aimed: f64,
    /// The share of polygons with an edge that shrinks to a point within [0, T] (paper A
    /// accepts any point then: the broad phase must keep every pair).
    pub collapsing: f64,
    /// The F the batch will be run with: points aimed at a warping polygon arrive at
    /// multiples of max(BUFF, F·edge) from the vertex.
    pub fac: f64,
}

impl Mix {
    /// The bench's mix: 2D, a quarter warping, a tenth of the points aimed, none
    /// collapsing.
    pub const BENCH: Mix = Mix {
        three_d: false,
        warping: 0.25,
        aimed: 0.1,
        collapsing: 0.0,
        fac: FAC,
    };
}

/// The batch's items (T, BUFF and F are the constants above).
pub struct BatchWorkload {
    /// The points.
    pub points: Vec<MovingPoint>,
    /// The polygons.
    pub polygons: Vec<MovingPolygon>,
}

/// The square's side for `m` polygons (see the module doc).
pub fn side(m: usize) -> f64 {
    31.6 * (m.max(1) as f64).sqrt()
}

/// `n` points and `m` polygons of 8 vertices from `seed` (see the module doc).
pub fn batch_workload(n: usize, m: usize, seed: u64, mix: Mix) -> BatchWorkload {
    let mut rng = SplitMix(seed);
    let side = side(m);
    let mut polygons = Vec::with_capacity(m);
    while polygons.len() < m {
        if let Some(q) = polygon(&mut rng, side, mix) {
            polygons.push(q);
        }
    }
    let points = (0..n)
        .map(|_| point(&mut rng, side, mix, &polygons))
        .collect();
    BatchWorkload { points, polygons }
}

/// One 8-vertex star-shaped polygon, counterclockwise, about 1 across; `None` when the
/// draw is refused by the API (never seen; the caller draws again).
fn polygon(rng: &mut SplitMix, side: f64, mix: Mix) -> Option<MovingPolygon> {
    let c = Vect2::new(rng.range(0.0, side), rng.range(0.0, side));
    let mut angles: Vec<f64> = (0..8)
        .map(|k| (k as f64 + rng.range(0.1, 0.9)) * std::f64::consts::TAU / 8.0)
        .collect();
    angles.sort_by(f64::total_cmp);
    let verts: Vec<Vect2> = angles
        .iter()
        .map(|&a| {
            let r = rng.range(0.3, 0.6);
            Vect2::new(c.x + r * a.cos(), c.y + r * a.sin())
        })
        .collect();
    let drift = Vect2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
    let mut vels = vec![drift; 8];
    if rng.unit() < mix.warping {
        for v in &mut vels {
            *v = drift + Vect2::new(rng.range(-0.02, 0.02), rng.range(-0.02, 0.02));
        }
    }
    if rng.unit() < mix.collapsing {
        // vertex k runs onto vertex k + 1 at a time tc of [0, T]
        let k = rng.below(8);
        let tc = rng.range(0.5, T);
        let d = verts[(k + 1) % 8] - verts[k];
        vels[k] = vels[(k + 1) % 8] + d.scale(1.0 / tc);
    }
    let mut q = MovingPolygon::new(verts, Some(vels)).ok()?;
    if mix.three_d {
        let bottom = rng.range(0.0, 1000.0);
        let top = bottom + rng.range(50.0, 300.0);
        q = q.with_slab(bottom, top, rng.range(-5.0, 5.0)).ok()?;
    }
    Some(q)
}

/// One point: uniform, or aimed at a polygon's vertex (see the module doc).
fn point(rng: &mut SplitMix, side: f64, mix: Mix, polygons: &[MovingPolygon]) -> MovingPoint {
    let speed = rng.range(5.0, 15.0);
    let a = rng.range(0.0, std::f64::consts::TAU);
    let v = Vect2::new(speed * a.cos(), speed * a.sin());
    let vz = rng.range(-10.0, 10.0);
    if polygons.is_empty() || rng.unit() >= mix.aimed {
        let s = Vect2::new(rng.range(0.0, side), rng.range(0.0, side));
        return make_point(s, v, mix.three_d.then(|| (rng.range(0.0, 1300.0), vz)));
    }
    let q = &polygons[rng.below(polygons.len())];
    let mut v = v;
    let (k, t_star, out) = if rng.unit() < 0.5 {
        // Through a vertex at a random time, outwards from the opposite vertex.
        let k = rng.below(8);
        let t_star = rng.range(0.0, T);
        let at = |i: usize| q.vertices()[i] + q.velocities()[i].scale(t_star);
        let out = at(k) - at((k + 4) % 8);
        (k, t_star, out.scale(1.0 / out.sq().sqrt()))
    } else {
        // Past the polygon's extreme vertex along an axis, at the end of [0, T] where
        // the swept box reaches farthest that way, on a path that stays beyond it: the
        // point's box lies just outside the polygon's (the pairs a broad phase with too
        // little margin drops).
        let axis = rng.pick(&[
            Vect2::new(1.0, 0.0),
            Vect2::new(-1.0, 0.0),
            Vect2::new(0.0, 1.0),
            Vect2::new(0.0, -1.0),
        ]);
        let t_star = if q.velocities()[0].dot(axis) > 0.0 {
            T
        } else {
            0.0
        };
        let at = |i: usize| q.vertices()[i] + q.velocities()[i].scale(t_star);
        let k = (0..8)
            .max_by(|&a, &b| at(a).dot(axis).total_cmp(&at(b).dot(axis)))
            .unwrap_or(0);
        // moving away from the box after 0, towards it before T
        let along = v.dot(axis);
        if (t_star == 0.0) == (along < 0.0) {
            v = v - axis.scale(2.0 * along);
        }
        (k, t_star, axis)
    };
    let (p, vel) = (q.vertices()[k], q.velocities()[k]);
    let at = p + vel.scale(t_star);
    let unit = if q.statically_shaped() {
        BUFF
    } else {
        let e = q.vertices()[(k + 1) % 8] - p;
        BUFF.max(mix.fac * e.sq().sqrt())
    };
    let d = unit * rng.pick(&[0.0, 0.5, 1.0, 1.0 + 1.0 / 1048576.0, 2.0]);
    let target = at + out.scale(d);
    let s = target - v.scale(t_star);
    let z = mix.three_d.then(|| {
        let slab = q.slab().unwrap_or(polyguard::api::Slab {
            bottom: 0.0,
            top: 0.0,
            vz: 0.0,
        });
        let (b, t) = (slab.bottom + slab.vz * t_star, slab.top + slab.vz * t_star);
        let h = rng.pick(&[b, t, b - 1e-9, t + 1e-9, 0.5 * (b + t)]);
        (h - vz * t_star, vz)
    });
    make_point(s, v, z)
}

fn make_point(s: Vect2, v: Vect2, z: Option<(f64, f64)>) -> MovingPoint {
    // finite by construction (no constructor check needed)
    MovingPoint { pos: s, vel: v, z }
}

/// The dense workload of crates/python/bench/bench_batch.py, drawn here with [`SplitMix`]
/// (the same distribution, not the same numbers): `m` star-shaped polygons of 8
/// vertices (radii 0.3 to 0.6) centred uniformly in a 10 × 10 square, nearly still
/// (drifts up to 0.01 per time unit, a quarter warping by up to 2·10⁻⁴ more per vertex),
/// and `n` points whose paths cross the whole square diagonally within T = 10, from
/// (−5, −5) + U(0, 1)² to (15, 15) + U(0, 1)², so that the broad phase keeps every one of
/// the N·M pairs and paper A's functions decide each one. Run with BUFF = 0.05 and F the
/// default ([`polyguard::api::Params::DEFAULT_FAC`]).
pub fn dense_workload(n: usize, m: usize, seed: u64) -> BatchWorkload {
    let mut rng = SplitMix(seed);
    let mut polygons = Vec::with_capacity(m);
    while polygons.len() < m {
        let c = Vect2::new(rng.range(0.0, 10.0), rng.range(0.0, 10.0));
        let verts: Vec<Vect2> = (0..8)
            .map(|k| {
                let a = (k as f64 + rng.range(0.1, 0.9)) * std::f64::consts::TAU / 8.0;
                let r = rng.range(0.3, 0.6);
                Vect2::new(c.x + r * a.cos(), c.y + r * a.sin())
            })
            .collect();
        let drift = Vect2::new(rng.range(-0.01, 0.01), rng.range(-0.01, 0.01));
        let mut vels = vec![drift; 8];
        if rng.unit() < 0.25 {
            for v in &mut vels {
                *v = drift + Vect2::new(rng.range(-2e-4, 2e-4), rng.range(-2e-4, 2e-4));
            }
        }
        if let Ok(q) = MovingPolygon::new(verts, Some(vels)) {
            polygons.push(q);
        }
    }
    let points = (0..n)
        .map(|_| {
            let s = Vect2::new(-5.0 + rng.unit(), -5.0 + rng.unit());
            let e = Vect2::new(15.0 + rng.unit(), 15.0 + rng.unit());
            make_point(s, (e - s).scale(1.0 / T), None)
        })
        .collect();
    BatchWorkload { points, polygons }
}
