//! Random exact cases for the property tests: star-shaped counterclockwise
//! polygons on a 1/8 grid, boundary-biased points (aimed exactly at a vertex or
//! at a point of an edge at a chosen time), static or warping, 2D or 3D.

#![allow(dead_code)]

use polyguard_oracle::{CaseInput, ExactCase, ExactField, OracleError};

/// A small deterministic generator (xorshift64*), seeded by proptest.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed | 1)
    }
    pub fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo + 1) as u64;
        lo + (self.next() % span) as i64
    }
    pub fn coin(&mut self, num: u64, den: u64) -> bool {
        self.next() % den < num
    }
}

/// A rational p/q as a string.
fn r(p: i64, q: i64) -> String {
    format!("{p}/{q}")
}

/// A case written with rational strings (owned).
#[derive(Clone, Debug)]
pub struct GenCase {
    pub lookahead: String,
    pub buff: String,
    pub fac: String,
    pub pos: Vec<String>,
    pub vel: Vec<String>,
    pub vertices: Vec<[String; 2]>,
    pub velocities: Vec<[String; 2]>,
    pub slab: Option<[String; 3]>,
}

impl GenCase {
    pub fn exact<F: ExactField>(&self) -> Result<ExactCase<F>, OracleError> {
        let pos: Vec<&str> = self.pos.iter().map(String::as_str).collect();
        let vel: Vec<&str> = self.vel.iter().map(String::as_str).collect();
        let verts: Vec<[&str; 2]> = self
            .vertices
            .iter()
            .map(|[x, y]| [x.as_str(), y.as_str()])
            .collect();
        let vels: Vec<[&str; 2]> = self
            .velocities
            .iter()
            .map(|[x, y]| [x.as_str(), y.as_str()])
            .collect();
        let c = CaseInput {
            lookahead: self.lookahead.as_str(),
            buff: self.buff.as_str(),
            fac: self.fac.as_str(),
            pos: &pos,
            vel: &vel,
            vertices: &verts,
            velocities: &vels,
            slab: self
                .slab
                .as_ref()
                .map(|[a, b, c]| [a.as_str(), b.as_str(), c.as_str()]),
        };
        ExactCase::new(&c)
    }
}

/// Integer coordinates in units of 1/8.
const GRID: i64 = 8;

pub fn gen_case(seed: u64) -> GenCase {
    let mut g = Rng::new(seed);
    let n = g.range(3, 7) as usize;
    // Star-shaped CCW: increasing angles, radii 2..10 (in grid units ×8).
    let mut angles: Vec<f64> = (0..n)
        .map(|k| {
            (k as f64 + 0.15 + 0.7 * (g.range(0, 1000) as f64 / 1000.0)) * core::f64::consts::TAU
                / n as f64
        })
        .collect();
    angles.sort_by(|a, b| a.total_cmp(b));
    let verts: Vec<(i64, i64)> = angles
        .iter()
        .map(|a| {
            let rad = g.range(2 * GRID, 10 * GRID) as f64;
            (
                (rad * a.cos()).round() as i64,
                (rad * a.sin()).round() as i64,
            )
        })
        .collect();
    let mode = g.range(0, 2);
    let base = (g.range(-2 * GRID, 2 * GRID), g.range(-2 * GRID, 2 * GRID));
    let vels: Vec<(i64, i64)> = (0..n)
        .map(|_| match mode {
            0 => (0, 0),
            1 => base,
            _ => (base.0 + g.range(-GRID, GRID), base.1 + g.range(-GRID, GRID)),
        })
        .collect();
    // Lookahead in quarters.
    let t4 = g.range(1, 40);
    let vel = (g.range(-4 * GRID, 4 * GRID), g.range(-4 * GRID, 4 * GRID));
    let pos = if g.coin(2, 3) {
        // Aim exactly: the point is at a vertex, or at λ = k/4 along an edge,
        // at the time t_hit = h/4 ≤ T. Coordinates in 1/32 units.
        let h = g.range(0, t4);
        let i = g.range(0, n as i64 - 1) as usize;
        let j = (i + 1) % n;
        let k = if g.coin(1, 2) { 0 } else { g.range(0, 4) };
        // target·4 (in grid units) at time 0 and its velocity·4.
        let tx = verts[i].0 * (4 - k) + verts[j].0 * k;
        let ty = verts[i].1 * (4 - k) + verts[j].1 * k;
        let tvx = vels[i].0 * (4 - k) + vels[j].0 * k;
        let tvy = vels[i].1 * (4 - k) + vels[j].1 * k;
        // s = target + t_hit·(target velocity − v), ×16 in grid units.
        let sx = 4 * tx + h * (tvx - 4 * vel.0);
        let sy = 4 * ty + h * (tvy - 4 * vel.1);
        (sx, sy, 16 * GRID)
    } else {
        (
            g.range(-16 * GRID, 16 * GRID),
            g.range(-16 * GRID, 16 * GRID),
            GRID,
        )
    };
    let buff = [r(1, 100), r(1, 64), r(1, 1000)][g.range(0, 2) as usize].clone();
    let fac = [r(1, 10000), r(1, 64)][g.range(0, 1) as usize].clone();
    let three_d = g.coin(1, 4);
    let (posv, velv, slab) = if three_d {
        let sz = g.range(-20, 20);
        let vz = g.range(-4, 4);
        let bottom = g.range(-20, 10);
        let top = bottom + g.range(0, 20);
        let vsp = g.range(-2, 2);
        (
            vec![r(pos.0, pos.2), r(pos.1, pos.2), r(sz, 1)],
            vec![r(vel.0, GRID), r(vel.1, GRID), r(vz, 2)],
            Some([r(bottom, 1), r(top, 1), r(vsp, 2)]),
        )
    } else {
        (
            vec![r(pos.0, pos.2), r(pos.1, pos.2)],
            vec![r(vel.0, GRID), r(vel.1, GRID)],
            None,
        )
    };
    GenCase {
        lookahead: r(t4, 4),
        buff,
        fac,
        pos: posv,
        vel: velv,
        vertices: verts
            .iter()
            .map(|&(x, y)| [r(x, GRID), r(y, GRID)])
            .collect(),
        velocities: vels
            .iter()
            .map(|&(x, y)| [r(x, GRID), r(y, GRID)])
            .collect(),
        slab,
    }
}

/// The proptest case count: POLYGUARD_PROPTEST_CASES, or `default`.
pub fn cases(default: u32) -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}
