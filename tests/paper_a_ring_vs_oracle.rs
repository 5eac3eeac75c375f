//! Paper A §II takes the polygon P simple and listed counterclockwise. The engine checks
//! both with float orientations backed by an exact fallback (`polyguard::ring`); the
//! oracle (`polyguard_oracle::ring`) decides them in exact rationals. Here the two must
//! give the same answer, fault for fault: the same first pair of edges, named by the same
//! vertex indices, and the same winding.
//!
//! The rings are drawn to be adversarial: 3–9 vertices on a 6 × 6 integer grid, so that
//! collinear vertices, vertices on other edges, repeated vertices and spikes (neighbouring
//! edges folding back along one line) are frequent; in raw order (mostly crossing) or
//! sorted by angle around the grid's centre (often simple, either way round). The grid is
//! then scaled by a power of two and shifted (by 0, by half the grid, by 10⁶ or by ±2³⁰),
//! and up to two coordinates are moved by one ulp, which turns exact collinearities and
//! touchings into near-degenerate ones that the float orientation alone gets wrong
//! (`the_rings_are_adversarial` checks that such rings are drawn). Rounding in the
//! shift only moves vertices: both sides read the same floats, the oracle converts them
//! exactly.
//!
//! A ring the engine reports as not checkable (an exact product over- or underflows) is
//! skipped: the oracle has no such answer.
#![cfg(feature = "std")]

use std::f64::consts::PI;

use polyguard::ring::{self, RingFault, Winding};
use polyguard::Vect2;
use polyguard_oracle::convert::f64_to_exact;
use polyguard_oracle::kernel::interval::{next_down, next_up};
use polyguard_oracle::ring as oring;
use polyguard_oracle::{Q, V2};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4096)
}

// ------------------------------------------------------------------ conversions

fn exact(p: &[Vect2]) -> Vec<V2<Q>> {
    p.iter()
        .map(|v| {
            V2::new(
                f64_to_exact(v.x).expect("finite"),
                f64_to_exact(v.y).expect("finite"),
            )
        })
        .collect()
}

/// The engine's fault as the oracle names it; `None` for NotCheckable.
fn as_oracle(f: RingFault) -> Option<oring::RingFault> {
    match f {
        RingFault::Crossing { a, b } => Some(oring::RingFault::Crossing { a, b }),
        RingFault::ZeroArea => Some(oring::RingFault::ZeroArea),
        RingFault::NotCheckable => None,
    }
}

fn as_oracle_winding(w: Winding) -> oring::Winding {
    match w {
        Winding::Counterclockwise => oring::Winding::Counterclockwise,
        Winding::Clockwise => oring::Winding::Clockwise,
    }
}

/// The engine's answer in the oracle's terms; `None` when the engine cannot check.
fn engine_check(p: &[Vect2]) -> Option<Result<(), oring::RingFault>> {
    match ring::check_simple(p) {
        Ok(()) => Some(Ok(())),
        Err(f) => as_oracle(f).map(Err),
    }
}

fn engine_winding(p: &[Vect2]) -> Option<Result<oring::Winding, oring::RingFault>> {
    match ring::winding(p) {
        Ok(w) => Some(Ok(as_oracle_winding(w))),
        Err(f) => as_oracle(f).map(Err),
    }
}

// ------------------------------------------------------------------ the rings

/// How the grid points are put in order.
#[derive(Clone, Copy, Debug)]
enum Order {
    /// As drawn: mostly self-crossing.
    Raw,
    /// By angle around the grid's centre (2.5, 2.5): often simple, counterclockwise.
    Around,
    /// By angle, clockwise.
    AroundReversed,
}

/// A one-ulp move of one coordinate: (vertex, the y coordinate?, upwards?).
type Nudge = (usize, bool, bool);

fn ring_of(
    pts: &[(i32, i32)],
    order: Order,
    dup: Option<usize>,
    close: bool,
    scale_exp: i32,
    offset: u8,
    nudges: &[Nudge],
) -> Vec<Vect2> {
    let mut pts = pts.to_vec();
    if !matches!(order, Order::Raw) {
        let key = |&(x, y): &(i32, i32)| {
            let (dx, dy) = (f64::from(x) - 2.5, f64::from(y) - 2.5);
            (dy.atan2(dx) + PI, dx * dx + dy * dy)
        };
        pts.sort_by(|p, q| {
            let (a, b) = (key(p), key(q));
            a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1))
        });
        if matches!(order, Order::AroundReversed) {
            pts.reverse();
        }
    }
    if let Some(i) = dup {
        let i = i % pts.len();
        pts.insert(i, pts[i]);
    }
    if close {
        pts.push(pts[0]);
    }
    let s = 2f64.powi(scale_exp);
    let off = match offset {
        0 => 0.0,
        1 => -3.0 * s,
        2 => 1e6,
        3 => 1_073_741_824.0,
        _ => -1_073_741_824.0,
    };
    let mut p: Vec<Vect2> = pts
        .iter()
        .map(|&(x, y)| Vect2::new(off + f64::from(x) * s, off + f64::from(y) * s))
        .collect();
    for &(i, on_y, up) in nudges {
        let v = &mut p[i % pts.len()];
        let c = if on_y { &mut v.y } else { &mut v.x };
        *c = if up { next_up(*c) } else { next_down(*c) };
    }
    p
}

fn rings() -> impl Strategy<Value = Vec<Vect2>> {
    let order = prop_oneof![
        2 => Just(Order::Raw),
        2 => Just(Order::Around),
        1 => Just(Order::AroundReversed),
    ];
    let scale = prop_oneof![2 => Just(0), 3 => -40..=40i32];
    let nudge = (0..10usize, any::<bool>(), any::<bool>());
    (
        prop::collection::vec((0..6i32, 0..6i32), 3..=9),
        order,
        prop::option::weighted(0.2, 0..10usize),
        prop::bool::weighted(0.15),
        scale,
        0..5u8,
        prop::collection::vec(nudge, 0..=2),
    )
        .prop_map(|(pts, order, dup, close, e, off, nudges)| {
            ring_of(&pts, order, dup, close, e, off, &nudges)
        })
}

// ------------------------------------------------------------------ the comparison

/// What the oracle said of a ring (for the coverage count).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Outcome {
    Skipped,
    SimpleCcw,
    SimpleCw,
    Spike,
    Crossing,
    ZeroArea,
}

/// Engine and oracle agree on `ring` (check_simple, then winding and simple_ccw when
/// simple, and collinear); the oracle's answer.
fn compare(p: &[Vect2]) -> Result<Outcome, TestCaseError> {
    let Some(engine) = engine_check(p) else {
        return Ok(Outcome::Skipped);
    };
    let q = exact(p);
    let oracle = oring::check_simple(&q);
    prop_assert_eq!(engine, oracle, "check_simple of {:?}", p);
    let outcome = match oracle {
        Ok(()) => {
            let Some(w) = engine_winding(p) else {
                return Ok(Outcome::Skipped);
            };
            let ow = oring::winding(&q);
            prop_assert_eq!(w, ow, "winding of the simple ring {:?}", p);
            prop_assert_eq!(
                ring::simple_ccw(p),
                oring::simple_ccw(&q),
                "simple_ccw of {:?}",
                p
            );
            match ow {
                Ok(oring::Winding::Counterclockwise) => Outcome::SimpleCcw,
                Ok(oring::Winding::Clockwise) => Outcome::SimpleCw,
                Err(_) => Outcome::ZeroArea,
            }
        }
        Err(oring::RingFault::ZeroArea) => Outcome::ZeroArea,
        Err(oring::RingFault::Crossing { a, b }) if a.1 == b.0 => Outcome::Spike,
        Err(oring::RingFault::Crossing { .. }) => Outcome::Crossing,
    };
    // The engine's collinear says false when a sign cannot be decided.
    let decidable = p
        .iter()
        .all(|&c| p.iter().all(|&b| ring::orient(p[0], b, c).is_some()));
    if decidable {
        prop_assert_eq!(
            ring::collinear(p),
            oring::collinear(&q),
            "collinear of {:?}",
            p
        );
    }
    Ok(outcome)
}

/// The sign of (b − a) × (c − a) in floats alone (no error bound, no fallback), and
/// whether it may be wrong: its rounding error is below 2⁻⁵⁰·(|l| + |r|) (l, r the two
/// products), so beyond 2⁻⁴⁰ of that it is right.
fn float_orient(a: Vect2, b: Vect2, c: Vect2) -> (i8, bool) {
    let l = (b.x - a.x) * (c.y - a.y);
    let r = (b.y - a.y) * (c.x - a.x);
    let det = l - r;
    let doubtful = det.abs() <= (l.abs() + r.abs()) / 1_099_511_627_776.0;
    let sign = if det > 0.0 {
        1
    } else if det < 0.0 {
        -1
    } else {
        0
    };
    (sign, doubtful)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Paper A §II (P simple, counterclockwise): the engine's check_simple names the same
    /// first fault as the exact oracle, and a simple ring winds the same way.
    #[test]
    fn check_simple_and_winding_match_the_oracle(p in rings()) {
        compare(&p)?;
    }

    /// The orientation every check is built on: the engine's filtered sign is the exact one,
    /// for each edge (p_i, p_i+1) against every vertex (the triples check_simple asks about).
    #[test]
    fn orient_matches_the_oracle(p in rings()) {
        let q = exact(&p);
        let n = p.len();
        for i in 0..n {
            let j = (i + 1) % n;
            for k in 0..n {
                if let Some(s) = ring::orient(p[i], p[j], p[k]) {
                    prop_assert_eq!(
                        s,
                        oring::orient(&q[i], &q[j], &q[k]),
                        "orient({:?}, {:?}, {:?})", p[i], p[j], p[k]
                    );
                }
            }
        }
    }
}

/// The strategy draws every kind of answer, and rings on which the float orientation
/// alone takes a wrong sign: the comparison above is not vacuous.
#[test]
fn the_rings_are_adversarial() {
    let mut runner = TestRunner::deterministic();
    let strategy = rings();
    let mut counts = std::collections::BTreeMap::new();
    let mut float_wrong = 0;
    let total = 2000;
    for _ in 0..total {
        let p = strategy.new_tree(&mut runner).expect("a ring").current();
        let outcome = compare(&p).expect("engine and oracle agree");
        *counts.entry(format!("{outcome:?}")).or_insert(0) += 1;
        let q = exact(&p);
        let n = p.len();
        let wrong = (0..n).any(|i| {
            (0..n).any(|j| {
                (0..n).any(|k| {
                    let (sign, doubtful) = float_orient(p[i], p[j], p[k]);
                    doubtful && sign != oring::orient(&q[i], &q[j], &q[k])
                })
            })
        });
        float_wrong += usize::from(wrong);
    }
    eprintln!("{total} rings: {counts:?}; float orientation wrong in {float_wrong}");
    for kind in ["SimpleCcw", "SimpleCw", "Spike", "Crossing", "ZeroArea"] {
        assert!(
            counts.get(kind).copied().unwrap_or(0) >= 20,
            "too few {kind}: {counts:?}"
        );
    }
    assert!(
        float_wrong >= 20,
        "float orientation wrong in only {float_wrong}"
    );
}

// ------------------------------------------------------------------ hand-made rings

fn ring_xy(xy: &[(f64, f64)]) -> Vec<Vect2> {
    xy.iter().map(|&(x, y)| Vect2::new(x, y)).collect()
}

/// Both sides give `want`.
fn both(p: &[Vect2], want: Result<(), oring::RingFault>) {
    assert_eq!(engine_check(p), Some(want), "engine on {p:?}");
    assert_eq!(oring::check_simple(&exact(p)), want, "oracle on {p:?}");
}

fn crossing(a: (usize, usize), b: (usize, usize)) -> Result<(), oring::RingFault> {
    Err(oring::RingFault::Crossing { a, b })
}

#[test]
fn square_both_ways() {
    let ccw = ring_xy(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]);
    let cw: Vec<Vect2> = ccw.iter().rev().copied().collect();
    for (p, w) in [
        (&ccw, oring::Winding::Counterclockwise),
        (&cw, oring::Winding::Clockwise),
    ] {
        both(p, Ok(()));
        assert_eq!(engine_winding(p), Some(Ok(w)));
        assert_eq!(oring::winding(&exact(p)), Ok(w));
    }
    assert!(ring::simple_ccw(&ccw) && oring::simple_ccw(&exact(&ccw)));
    assert!(!ring::simple_ccw(&cw) && !oring::simple_ccw(&exact(&cw)));
}

#[test]
fn bow_tie() {
    let bow = ring_xy(&[(0.0, 0.0), (4.0, 4.0), (4.0, 0.0), (0.0, 4.0)]);
    both(&bow, crossing((0, 1), (2, 3)));
}

#[test]
fn spike() {
    // 1 → 2 goes out along y = 0 and 2 → 3 comes back over it
    let spike = ring_xy(&[(0.0, 0.0), (4.0, 0.0), (6.0, 0.0), (5.0, 0.0), (4.0, 4.0)]);
    both(&spike, crossing((1, 2), (2, 3)));
    // a repeated vertex is named by the first index of its run; a closing repeat of
    // vertex 0 is vertex 0
    let rep = ring_xy(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (6.0, 0.0),
        (6.0, 0.0),
        (5.0, 0.0),
        (4.0, 4.0),
        (0.0, 0.0),
    ]);
    both(&rep, crossing((1, 2), (2, 4)));
}

#[test]
fn vertex_on_a_non_adjacent_edge() {
    // vertex 3 lies on edge 0–1
    let touch = ring_xy(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 0.0), (0.0, 4.0)]);
    both(&touch, crossing((0, 1), (2, 3)));
    // an ulp below it, near 2³⁰: both edges at vertex 3 dip through edge 0–1
    let big = 1_073_741_824.0;
    let dip = ring_xy(&[
        (big, big),
        (big + 4.0, big),
        (big + 4.0, big + 4.0),
        (big + 2.0, next_down(big)),
        (big, big + 4.0),
    ]);
    both(&dip, crossing((0, 1), (2, 3)));
    let clear = ring_xy(&[
        (big, big),
        (big + 4.0, big),
        (big + 4.0, big + 4.0),
        (big + 2.0, next_up(big)),
        (big, big + 4.0),
    ]);
    both(&clear, Ok(()));
}

#[test]
fn degenerate_rings_enclose_nothing() {
    both(
        &ring_xy(&[(1.0, 1.0), (1.0, 1.0), (2.0, 2.0)]),
        Err(oring::RingFault::ZeroArea),
    );
    both(&ring_xy(&[(1.0, 1.0); 4]), Err(oring::RingFault::ZeroArea));
    let line = ring_xy(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]);
    assert!(ring::collinear(&line) && oring::collinear(&exact(&line)));
    // a line folds back at its ends: a spike, the first one found
    both(&line, crossing((1, 2), (2, 0)));
}

/// A found engine defect, now a regression test: `polyguard::ring::orient`'s float
/// filter used Shewchuk's relative error bound also where the products are subnormal
/// (their rounding error is then absolute, up to 2⁻¹⁰⁷⁵). Here, for the triple
/// (v0, v1, v2), the two products are (K + ½)·2⁻¹⁰⁷⁴ and (K + ½ − 2⁻⁵²)·2⁻¹⁰⁷⁴ with K
/// odd, rounded to (K + 1) and K units: the float determinant is +2⁻¹⁰⁷⁴, above the bound
/// (≈ 0.7·2⁻¹⁰⁷⁴), while the exact one is ≈ −1.1·10⁻¹⁶·2⁻¹⁰⁷⁴. The engine took v2 on the
/// wrong side of edge v0→v1, missed that edge v2→v3 crosses it, and accepted the ring as
/// simple and counterclockwise; it is self-crossing. Fixed: the filter is used only for
/// products in the normal range, and a tiny ring is checked scaled by 2⁶⁰⁰.
#[test]
fn subnormal_products_defeat_the_float_filter() {
    let p = [
        Vect2::new(f64::from_bits(0xbc9f_fffe_0000_0000), 0.0), // −(2²⁰ − 1)·2⁻⁷³
        Vect2::new(
            f64::from_bits(0xbff4_aaaa_aaaa_aaab), // −5817149518686891·2⁻⁵²
            f64::from_bits(0x0002_0000_0000_0000), // 2⁴⁹·2⁻¹⁰⁷⁴ = 2⁻¹⁰²⁵
        ),
        Vect2::new(
            f64::from_bits(0xbff4_aaaa_aaaa_aa8c), // −5817149518686860·2⁻⁵²
            f64::from_bits(0x0001_ffff_ffff_fffd), // (2⁴⁹ − 3)·2⁻¹⁰⁷⁴
        ),
        Vect2::new(-0.5, -1.0),
    ];
    let q = exact(&p);
    assert_eq!(oring::orient(&q[0], &q[1], &q[2]), -1);
    assert_eq!(
        oring::check_simple(&q),
        Err(oring::RingFault::Crossing {
            a: (0, 1),
            b: (2, 3)
        })
    );
    assert_eq!(oring::winding(&q), Ok(oring::Winding::Clockwise));
    // The engine may decline (None, NotCheckable) but must not answer wrongly.
    assert_ne!(ring::orient(p[0], p[1], p[2]), Some(1));
    assert_ne!(engine_check(&p), Some(Ok(())));
    assert!(!ring::simple_ccw(&p));
    assert!(
        matches!(ring::check(&p), Err(ring::RingFault::Crossing { .. })),
        "{:?} {:?}",
        ring::check(&p),
        ring::check_simple(&p)
    );
}
