//! Large polygons: the fast paths of the exact §II.J report and of the
//! truth give the answers of their references on polygons built to sit on their filters'
//! edges.
//!
//! - [`well_formed_fault`] (a sweep over outward-rounded boxes within 2·|BUFF| or |BUFF|,
//!   the interval kernel first, a line-side test in front of `segments_close`) names the
//!   same fault as [`well_formed_fault_pairwise`] (every pair, exact kernel only), on
//!   star polygons snapped to dyadic and non-dyadic grids and on grid clutter, edited so
//!   that vertices sit exactly 2·BUFF apart along an axis (rule 1's boundary: not close)
//!   or a grid step less, vertices lie exactly BUFF from another vertex's edges (rule 2's
//!   boundary), and vertices repeat.
//! - [`truth`] (the contact tests and the edge-collapse filter on enclosures first)
//!   equals [`truth_unfiltered`] (the exact kernel alone) on moving and warping 32- to
//!   48-vertex polygons with edges that shrink to a point exactly at 0, at T/2, at T and
//!   just after T, and point tracks through vertices.
//! - Canary: a sweep that leaves out the pairs of one edge is caught by the comparison.

use proptest::prelude::*;

use polyguard_oracle::well_formed::{
    well_formed_fault, well_formed_fault_pairwise, well_formed_fault_skipping, Fault,
};
use polyguard_oracle::{truth, truth_unfiltered, Arith, CaseInput, ExactCase, Q, V2};

/// n/d as an exact rational (d ≠ 0 in every call below).
fn q(n: i64, d: i64) -> Q {
    Q::from_i64(n)
        .quotient(&Q::from_i64(d))
        .expect("a nonzero denominator")
}

/// A small deterministic generator (xorshift), seeded by proptest.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
}

/// A §II.J test polygon: vertices, BUFF and cos κ, all exact.
#[derive(Debug)]
struct Poly {
    p: Vec<V2<Q>>,
    buff: Q,
    cos_kappa: Q,
}

/// A polygon of 32 to 48 vertices (the sweep's sizes) on the filters' edges (module doc).
fn gen_poly(seed: u64) -> Poly {
    let mut r = Rng(seed | 1);
    let n = r.range(32, 48) as usize;
    // Grid step 1/den: dyadic (point enclosures) or thirds (enclosures an ulp wide).
    let den = [1, 2, 3, 8][r.below(4) as usize];
    let buff = [q(1, 8), q(1, 3), q(1, 2), q(1, 1), q(3, 2)][r.below(5) as usize].clone();
    let mut p: Vec<V2<Q>> = if r.below(4) == 0 {
        // Clutter: any ring, crossings and close pairs everywhere.
        (0..n)
            .map(|_| V2::new(q(r.range(-12, 12), den), q(r.range(-12, 12), den)))
            .collect()
    } else {
        // A star: radii 16..24 around the origin, snapped to the grid.
        (0..n)
            .map(|k| {
                let a = (k as f64 + 0.3 * (r.below(100) as f64 / 100.0)) / n as f64
                    * std::f64::consts::TAU;
                let rad = r.range(16, 24) as f64;
                let snap = |x: f64| q((x * den as f64).round() as i64, den);
                V2::new(snap(rad * a.cos()), snap(rad * a.sin()))
            })
            .collect()
    };
    // Edits on the boundaries.
    for _ in 0..r.below(4) {
        let k = r.below(n as u64) as usize;
        let m = r.below(n as u64) as usize;
        let two_b = buff.twice();
        let step = q(1, den);
        if r.below(2) == 0 {
            // Vertex m near the middle of edge k (far from its ends): at BUFF, 3/4 of
            // it or just above half of it along an axis, so rule 2 is the first fault.
            let (a, b) = (&p[k], &p[(k + 1) % n]);
            let mid = a.plus(b).scale(&q(1, 2));
            let d = [buff.clone(), buff.times(&q(3, 4)), buff.times(&q(17, 32))]
                [r.below(3) as usize]
                .clone();
            let z = Q::from_i64(0);
            let off = match r.below(4) {
                0 => V2::new(d, z),
                1 => V2::new(d.negated(), z),
                2 => V2::new(z, d),
                _ => V2::new(z, d.negated()),
            };
            if m != k && m != (k + 1) % n {
                p[m] = mid.plus(&off);
            }
            continue;
        }
        let off = match r.below(6) {
            0 => V2::new(two_b.clone(), Q::from_i64(0)),
            1 => V2::new(Q::from_i64(0), two_b.negated()),
            2 => V2::new(two_b.minus(&step), Q::from_i64(0)),
            3 => V2::new(buff.clone(), Q::from_i64(0)),
            4 => V2::new(Q::from_i64(0), buff.negated()),
            _ => V2::new(Q::from_i64(0), Q::from_i64(0)),
        };
        p[m] = p[k].plus(&off);
    }
    let cos_kappa = [q(99619, 100000), q(0, 1), q(1, 2), q(-1, 2)][r.below(4) as usize].clone();
    Poly { p, buff, cos_kappa }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("POLYGUARD_PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(96)
    ))]

    /// The sweep names the pairwise loops' fault (or none), rule and indices alike.
    #[test]
    fn the_sweep_names_the_pairwise_fault(seed in any::<u64>()) {
        let g = gen_poly(seed);
        prop_assert_eq!(
            well_formed_fault(&g.p, &g.buff, &g.cos_kappa),
            well_formed_fault_pairwise(&g.p, &g.buff, &g.cos_kappa),
            "{:?}", g
        );
    }
}

/// Canary: a broad phase that loses the pairs of one edge (or vertex) is caught by the
/// comparison above on the generated polygons, in most of those where that edge
/// (vertex) makes the first fault.
#[test]
fn a_sweep_losing_one_edge_is_caught() {
    let (mut faults, mut caught) = (0, 0);
    for seed in 1..=60u64 {
        let g = gen_poly(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        let want = well_formed_fault_pairwise(&g.p, &g.buff, &g.cos_kappa);
        let lost = match want {
            Some(Fault::CloseVertices(i, _)) => (1, i),
            Some(Fault::CloseEdges(i, _)) => (2, i),
            _ => continue,
        };
        faults += 1;
        let skip = |rule: u8, i: usize, j: usize| rule == lost.0 && (i == lost.1 || j == lost.1);
        let got = well_formed_fault_skipping(&g.p, &g.buff, &g.cos_kappa, &skip);
        if got != want {
            caught += 1;
        }
        // The unbroken sweep agrees on the same polygon.
        assert_eq!(
            well_formed_fault_skipping(&g.p, &g.buff, &g.cos_kappa, &|_, _, _| false),
            want
        );
    }
    assert!(
        faults >= 20,
        "only {faults} polygons with a rule 1 or 2 fault"
    );
    assert_eq!(caught, faults, "{caught} of {faults} caught");
}

/// T, the point's position and velocity, the vertices and their velocities.
type MovingCase = (f64, Vec<f64>, Vec<f64>, Vec<[f64; 2]>, Vec<[f64; 2]>);

/// A moving 32- to 48-vertex case on the truth's filter edges (module doc), as f64 inputs
/// (every number a small dyadic, so exact).
fn gen_case(seed: u64) -> MovingCase {
    let mut r = Rng(seed | 1);
    let n = r.range(32, 48) as usize;
    let t = [1.0, 2.0, 8.0][r.below(3) as usize];
    let verts: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            let rad = r.range(16, 24) as f64;
            [
                (rad * a.cos() * 4.0).round() / 4.0,
                (rad * a.sin() * 4.0).round() / 4.0,
            ]
        })
        .collect();
    let common = [r.range(-4, 4) as f64, r.range(-4, 4) as f64];
    let mut vels: Vec<[f64; 2]> = match r.below(3) {
        0 => vec![[0.0, 0.0]; n],
        1 => vec![common; n],
        _ => verts
            .iter()
            .map(|v| [common[0] + v[0] / 8.0, common[1] + v[1] / 8.0])
            .collect(),
    };
    // An edge k → k + 1 that shrinks to a point at time tc: vertex k + 1 moves onto
    // vertex k's track (tc = 0 repeats the vertex; tc just after T keeps it whole).
    for _ in 0..r.below(3) {
        let k = r.below(n as u64) as usize;
        let j = (k + 1) % n;
        let tc = [t, t / 2.0, t * 1.0625, t * 2.0][r.below(4) as usize];
        vels[j] = [
            vels[k][0] - (verts[j][0] - verts[k][0]) / tc,
            vels[k][1] - (verts[j][1] - verts[k][1]) / tc,
        ];
    }
    // The point: aimed at a vertex (reached at T/2), or across the middle.
    let target = verts[r.below(n as u64) as usize];
    let (pos, vel) = if r.below(2) == 0 {
        let tv = vels[r.below(n as u64) as usize];
        let s = [-64.0, r.range(-20, 20) as f64];
        let half = t / 2.0;
        let at = [target[0] + half * tv[0], target[1] + half * tv[1]];
        (
            s.to_vec(),
            vec![(at[0] - s[0]) / half, (at[1] - s[1]) / half],
        )
    } else {
        (vec![-64.0, 0.5], vec![64.0 / t, 0.0])
    };
    (t, pos, vel, verts, vels)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("POLYGUARD_PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(64)
    ))]

    /// The truth with its interval filters equals the exact kernel's alone.
    #[test]
    fn the_filtered_truth_is_the_exact_one(seed in any::<u64>()) {
        let (t, pos, vel, verts, vels) = gen_case(seed);
        let c = CaseInput {
            lookahead: t,
            buff: 0.125,
            fac: 1e-4,
            pos: &pos,
            vel: &vel,
            vertices: &verts,
            velocities: &vels,
            slab: None,
        };
        let Ok(exact) = ExactCase::<Q>::new(&c) else { return Ok(()) };
        prop_assert_eq!(truth(&exact), truth_unfiltered(&exact), "{:?}", (t, &pos, &vel));
    }
}

/// Rule 2 at its reach: a vertex δ to the left of a vertical edge's middle (so δ from
/// it, and more than 2·BUFF from every vertex), for δ at BUFF (not close: the rule is
/// strict), just below it and down to half of it. The sweep names the pairwise fault, and
/// below BUFF that fault is edge 0 against the edge ending at the moved vertex.
#[test]
fn a_vertex_at_the_edge_reach() {
    let n = 40;
    for buff in [q(1, 8), q(1, 3), q(1, 2)] {
        for delta in [
            buff.clone(),
            buff.minus(&q(1, 1 << 20)),
            buff.times(&q(3, 4)),
            buff.times(&q(17, 32)),
            buff.plus(&q(1, 1 << 20)),
        ] {
            let mut p: Vec<V2<Q>> = (0..n)
                .map(|k| {
                    let a = k as f64 / n as f64 * std::f64::consts::TAU;
                    let snap = |x: f64| q((x * 8.0).round() as i64, 8);
                    V2::new(snap(20.0 * a.cos()), snap(20.0 * a.sin()))
                })
                .collect();
            p[0] = V2::new(q(20, 1), q(0, 1));
            p[1] = V2::new(q(20, 1), q(3, 1));
            p[n / 2] = V2::new(q(20, 1).minus(&delta), q(3, 2));
            let cos_kappa = q(99619, 100000);
            let want = well_formed_fault_pairwise(&p, &buff, &cos_kappa);
            assert_eq!(
                well_formed_fault(&p, &buff, &cos_kappa),
                want,
                "δ = {delta}"
            );
            if delta < buff {
                assert_eq!(want, Some(Fault::CloseEdges(0, n / 2 - 1)), "δ = {delta}");
            } else {
                assert!(
                    !matches!(want, Some(Fault::CloseEdges(0, _))),
                    "δ = {delta}: {want:?}"
                );
            }
        }
    }
}
