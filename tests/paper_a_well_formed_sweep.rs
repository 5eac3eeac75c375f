//! Paper A §II.J: `well_formed_fault` by the sweep (O(n log n), polygons of 48 vertices
//! or more) names exactly the fault that comparing every pair names, on polygons made to
//! be close to each rule's threshold: vertices and edges exactly 2·BUFF or BUFF apart
//! (ties decided the same way), BUFF an ulp either side of a pair's distance, needles
//! along either axis, snapped grids with many equal coordinates, and coordinates far
//! from the origin.
//!
//! Scale with `POLYGUARD_PROPTEST_CASES` (default 64).

use polyguard::vect2::Vect2;
use polyguard::well_formed::{well_formed_fault, well_formed_fault_pairwise};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64)
}

/// A star-shaped ring of `n` vertices: angles sorted, radii drawn, optionally squashed
/// into a needle along x or y, snapped to a grid and moved far from the origin.
fn ring() -> impl Strategy<Value = Vec<Vect2>> {
    (
        48usize..400,
        any::<u64>(),
        prop_oneof![Just(1.0), Just(1e-6), Just(1e6)],
        prop_oneof![Just(0.0), Just(1.0 / 64.0), Just(1.0 / 4.0)],
        prop_oneof![Just(0.0), Just(1e6), Just(-3.5e9)],
    )
        .prop_map(|(n, seed, squash, snap, offset)| {
            let mut s = seed | 1;
            let mut next = move || {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                (s >> 11) as f64 / (1u64 << 53) as f64
            };
            (0..n)
                .map(|k| {
                    let a = (k as f64 + 0.9 * next()) / n as f64 * std::f64::consts::TAU;
                    let r = 10.0 * (0.3 + next());
                    let (mut x, mut y) = (r * a.cos(), r * a.sin() * squash);
                    if snap > 0.0 {
                        x = (x / snap).round() * snap;
                        y = (y / snap).round() * snap;
                    }
                    Vect2::new(x + offset, y + offset)
                })
                .collect()
        })
}

/// BUFF: drawn, or a pair's distance (or half of it, rule 1's threshold) moved by an ulp.
fn buff_for(p: &[Vect2], pick: (usize, usize, u8, f64)) -> f64 {
    let (i, j, how, drawn) = pick;
    let n = p.len();
    let (i, j) = (i % n, j % n);
    let d = (p[i] - p[j]).sq().sqrt();
    let b = match how % 4 {
        0 => drawn,
        1 => 0.5 * d,
        2 => d,
        _ => 0.25 * d,
    };
    match how / 4 % 3 {
        0 => b,
        1 => f64::from_bits(b.to_bits() + 1),
        _ => f64::from_bits(b.to_bits().saturating_sub(1)),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() * 4))]

    #[test]
    fn the_sweep_names_the_pairwise_fault(
        p in ring(),
        pick in (any::<usize>(), any::<usize>(), any::<u8>(), prop_oneof![Just(1e-3), Just(0.05), Just(0.4), Just(3.0)]),
        cos_kappa in prop::sample::select(vec![-0.5, 0.0, 0.5, 0.9, 0.999]),
    ) {
        let buff = buff_for(&p, pick);
        prop_assert_eq!(
            well_formed_fault(&p[..], buff, cos_kappa),
            well_formed_fault_pairwise(&p[..], buff, cos_kappa),
            "BUFF = {:e}, n = {}", buff, p.len()
        );
    }
}

/// Non-finite inputs take the pairwise path, and answer as it does.
#[test]
fn non_finite_inputs_answer_as_pairwise() {
    let mut p: Vec<Vect2> = (0..60)
        .map(|k| {
            let a = k as f64 / 60.0 * std::f64::consts::TAU;
            Vect2::new(10.0 * a.cos(), 10.0 * a.sin())
        })
        .collect();
    for buff in [f64::NAN, f64::INFINITY, -0.5, 0.0] {
        assert_eq!(
            well_formed_fault(&p[..], buff, 0.5),
            well_formed_fault_pairwise(&p[..], buff, 0.5),
            "{buff}"
        );
    }
    p[7] = Vect2::new(f64::NAN, 1.0);
    assert_eq!(
        well_formed_fault(&p[..], 0.1, 0.5),
        well_formed_fault_pairwise(&p[..], 0.1, 0.5)
    );
}

/// A circle of 64k vertices, well formed, is judged so (the sweep's reason to be: the
/// pairwise rules took seconds there); one vertex moved next to another is found.
#[test]
fn a_large_circle_is_judged_and_a_close_pair_found() {
    let n = 65_536;
    let r = 1e4;
    let mut p: Vec<Vect2> = (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect();
    // neighbours are 2πr/n ≈ 0.96 apart: BUFF 0.1 is well formed
    assert_eq!(well_formed_fault(&p[..], 0.1, 0.9), None);
    // vertex 40,000 moved to 0.05 from vertex 10 (across the circle from it otherwise)
    p[40_000] = p[10] + Vect2::new(0.05, 0.0);
    assert_eq!(
        well_formed_fault(&p[..], 0.1, 0.9),
        Some(polyguard::well_formed::Fault::CloseVertices(10, 40_000))
    );
}

/// A ring with `n` vertices that crosses itself, folds back or touches, or not: a star
/// with one or two vertices moved onto others' edges, across the ring, or back along
/// their own edge, snapped to a grid so that touches are exact.
fn messy_ring() -> impl Strategy<Value = Vec<Vect2>> {
    (ring(), any::<u64>(), 0u8..6).prop_map(|(mut p, seed, how)| {
        let n = p.len();
        let (i, j) = (
            (seed % n as u64) as usize,
            ((seed >> 20) % n as u64) as usize,
        );
        match how {
            // a vertex onto another vertex
            0 => p[i] = p[j],
            // a vertex onto the middle of another edge (exact on the snapped grids)
            1 => p[i] = (p[j] + p[(j + 1) % n]).scale(0.5),
            // across the ring: the star's vertex pulled through the centre
            2 => p[i] = -p[i],
            // back along its own edge (a fold)
            3 => p[(i + 1) % n] = p[i] + (p[i] - p[(i + n - 1) % n]).scale(-0.5),
            // a repeated vertex (a zero-length edge: not a fault)
            4 => p.insert(i, p[i]),
            _ => {}
        }
        p
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() * 4))]

    /// §II's simplicity check by the sweep names the same crossing (or the same "not
    /// checkable") as comparing every pair of edges.
    #[test]
    fn the_sweep_finds_the_pairwise_crossing(p in messy_ring()) {
        prop_assert_eq!(
            polyguard::ring::check_simple(&p),
            polyguard::ring::check_simple_pairwise(&p),
            "n = {}", p.len()
        );
    }
}

/// The 64k-vertex circle is simple and counterclockwise; with one vertex pulled across
/// the centre it crosses itself, at the same pair of edges as the pairwise check says.
#[test]
fn a_large_circle_is_simple_and_a_crossing_found() {
    let n = 65_536;
    let mut p: Vec<Vect2> = (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            Vect2::new(1e4 * a.cos(), 1e4 * a.sin())
        })
        .collect();
    assert_eq!(
        polyguard::ring::check(&p),
        Ok(polyguard::ring::Winding::Counterclockwise)
    );
    p[30_000] = -p[30_000];
    let got = polyguard::ring::check_simple(&p);
    assert!(
        matches!(got, Err(polyguard::ring::RingFault::Crossing { .. })),
        "{got:?}"
    );
    // the pairwise check on the same ring (a few seconds in debug builds: in release)
    if !cfg!(debug_assertions) {
        assert_eq!(got, polyguard::ring::check_simple_pairwise(&p));
    }
}
