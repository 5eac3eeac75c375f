//! The kernels' bits are [`swept_boxes_apart`]'s answers, edge by edge: on random and
//! adversarial edges and sweeps (NaN, ±∞, subnormals, huge values, ties among the
//! coordinates, windows from 0 and from later, still and moving points, F of every
//! sign), with each group of four edges starting anywhere in polygons of 1 to 70
//! vertices. The cases also serve detect_diff_2D's comparison of its masked and scalar
//! loops (`detect::warping`'s tests), which this module does not import.

use super::*;
use crate::lanes::tests::check_cases;
use proptest::prelude::*;

/// A coordinate: mostly from a few small values (so that box ends and corners tie),
/// ordinary otherwise, sometimes non-finite, subnormal or huge.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => prop_oneof![Just(0.0), Just(-0.0), Just(1.0), Just(-1.0), Just(0.5), Just(2.0)],
        4 => -6.0f64..6.0,
        1 => prop_oneof![
            Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY),
            Just(f64::MIN_POSITIVE / 3.0), Just(-5e-324), Just(1e300), Just(-1e300),
            Just(f64::MAX), Just(1e-300),
        ],
    ]
}

fn point() -> impl Strategy<Value = Vect2> {
    (coord(), coord()).prop_map(|(x, y)| Vect2::new(x, y))
}

/// A velocity: often zero (a still vertex or point), else as a point.
fn velocity() -> impl Strategy<Value = Vect2> {
    prop_oneof![1 => Just(Vect2::ZERO), 3 => point()]
}

/// A warping case: the vertices (1 to 70) and their velocities, the point and its
/// velocity, the window's ends [t0, t1] (t0 = 0 often, later otherwise, now and then
/// non-finite), F and BUFF.
pub(in crate::detect) type Case = (Vec<Vect2>, Vec<Vect2>, Vect2, Vect2, (f64, f64), f64, f64);

pub(in crate::detect) fn case() -> impl Strategy<Value = Case> {
    (1usize..=70).prop_flat_map(|n| {
        (
            proptest::collection::vec(point(), n),
            proptest::collection::vec(velocity(), n),
            prop_oneof![Just(Vect2::ZERO), point()],
            velocity(),
            (
                prop_oneof![4 => Just(0.0), 4 => 0.0f64..3.0, 1 => Just(1.0), 1 => Just(f64::INFINITY)],
                prop_oneof![4 => 0.0f64..10.0, 1 => Just(1.0), 1 => Just(0.0), 1 => Just(f64::INFINITY), 1 => Just(f64::NAN)],
            ),
            prop_oneof![
                Just(0.5), Just(1e-4), 0.0f64..1.0, Just(0.0), Just(-0.5), Just(f64::NAN),
                Just(5e-324),
            ],
            prop_oneof![Just(0.01), Just(1.0), 0.0f64..2.0],
        )
    })
}

/// Vertices i, i + 1, i + 2, i + 3 of `p`, cyclically.
fn cyc(p: &[Vect2], i: usize) -> Four {
    core::array::from_fn(|l| p[(i + l) % p.len()])
}

/// Every kernel gives [`swept_boxes_apart`]'s bits for four consecutive edges (cyclically)
/// starting at every vertex.
#[test]
fn the_kernels_give_the_scalar_bits() {
    check_cases(case(), kernel_bits);
}

fn kernel_bits((p, vels, s, v, (t0, t1), f, _): Case) -> Result<(), TestCaseError> {
    let n = p.len();
    let w = Sweep::new(t0, t1, s, v);
    for i in 0..n {
        let (q, v4) = (cyc(&p, i), p[(i + LANES) % n]);
        let (u, u4) = (cyc(&vels, i), vels[(i + LANES) % n]);
        let mut scalar = 0u32;
        for l in 0..LANES {
            let (e, j) = ((i + l) % n, (i + l + 1) % n);
            scalar |= (swept_boxes_apart(&w, p[e], p[j], vels[e], vels[j], f) as u32) << l;
        }
        prop_assert_eq!(
            Portable.apart(&w, &q, v4, &u, u4, f),
            scalar,
            "portable, from {}",
            i
        );
        #[cfg(target_arch = "x86_64")]
        if let Some(k) = crate::lanes::Avx::new() {
            let avx = Avx(k).apart(&w, &q, v4, &u, u4, f);
            prop_assert_eq!(avx, scalar, "AVX, edges from {}: sweep {:?}, F {}", i, w, f);
        }
    }
    Ok(())
}

/// The filter does fire in these cases, through the box test and through the side test,
/// and also does not (or the comparison above would compare only zeros or only ones).
#[test]
fn the_cases_reach_both_answers_of_both_tests() {
    let still = Vect2::ZERO;
    let (pi, pj) = (Vect2::new(0.0, 0.0), Vect2::new(1.0, 0.0));
    let (edge, still4) = ([pi, pj, pi, pj], [still; LANES]);
    // far to the right: the boxes apart
    let far = Sweep::new(0.0, 1.0, Vect2::new(10.0, 0.0), still);
    // moving diagonally past the edge's box corner, above the edge: the boxes' y ranges
    // [0, 0] and [0.5, 4.5] are 0.5 apart, not more than twice the slack 2F·1 = 0.25, so
    // only the side test fires
    let past = Sweep::new(0.0, 1.0, Vect2::new(-1.0, 0.5), Vect2::new(4.0, 4.0));
    // through the edge
    let through = Sweep::new(0.0, 1.0, Vect2::new(0.5, -1.0), Vect2::new(0.0, 2.0));
    for (w, want) in [(far, true), (past, true), (through, false)] {
        assert_eq!(swept_boxes_apart(&w, pi, pj, still, still, 0.125), want);
        // the edge there and back, twice
        let bits = if want { 0b1111 } else { 0 };
        assert_eq!(Portable.apart(&w, &edge, pi, &still4, still, 0.125), bits);
        #[cfg(target_arch = "x86_64")]
        if let Some(k) = crate::lanes::Avx::new() {
            assert_eq!(Avx(k).apart(&w, &edge, pi, &still4, still, 0.125), bits);
        }
    }
}
