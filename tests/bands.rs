//! The certified bands (module `bands`) against the exact conflict of single velocities
//! (`polyguard_oracle::bands::conflict`, through the harness's `wayout::bands::check`):
//! on random scenes of one to three moving polygons (star-shaped, some drifting or
//! warping), 2D and 3D, every value drawn inside a Clear band is exactly free of
//! conflict and every value drawn inside a Conflict band exactly loses separation; the
//! bands tile the range in order, and the Unknown total is what the answer reports.

use polyguard::bands::{
    course_bands, speed_bands, vertical_speed_bands, BandKind, Bands, Height, Slab,
};
use polyguard::{Separation, Vect2};
use polyguard_harness::wayout::bands::{check, contradictions, BandCase, Param, Polygon};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .map_or(24, |n: u32| n.min(64))
}

/// A star-shaped counterclockwise polygon of n vertices around c, radii in [0.4r, r]
/// from `radii` (fractions), with a drift and (when `warp`) a vertex-wise wobble.
fn polygon(c: Vect2, r: f64, radii: &[f64], drift: Vect2, warp: f64) -> Vec<(Vect2, Vect2)> {
    let n = radii.len();
    radii
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            let rr = r * (0.4 + 0.6 * f);
            let p = Vect2::new(c.x + rr * a.cos(), c.y + rr * a.sin());
            let w = Vect2::new(drift.x + warp * a.cos(), drift.y + warp * a.sin());
            (p, w)
        })
        .collect()
}

prop_compose! {
    fn scene()(
        k in 1usize..=3,
        centres in prop::collection::vec((-60.0..60.0f64, -60.0..60.0f64, 3.0..15.0f64), 3),
        radii in prop::collection::vec(prop::collection::vec(0.0..1.0f64, 3..7), 3),
        drifts in prop::collection::vec((-2.0..2.0f64, -2.0..2.0f64, prop::bool::ANY), 3),
        d in prop_oneof![Just(0.0), 0.5..6.0f64],
        slabs in prop::collection::vec((0.0..40.0f64, 5.0..40.0f64, -1.0..1.0f64), 3),
        height in prop::option::of((0.0..60.0f64, -3.0..3.0f64)),
        h in 0.0..8.0f64,
    ) -> BandCase {
        let polygons = (0..k).map(|i| {
            let (cx, cy, r) = centres[i];
            let (dx, dy, warping) = drifts[i];
            let pv = polygon(Vect2::new(cx, cy), r, &radii[i], Vect2::new(dx, dy), if warping { 0.3 } else { 0.0 });
            let (bottom, thick, vsp) = slabs[i];
            Polygon {
                p: pv.iter().map(|x| x.0).collect(),
                vels: pv.iter().map(|x| x.1).collect(),
                slab: height.map(|_| Slab { bottom, top: bottom + thick, vsp }),
            }
        }).collect();
        BandCase {
            t: 10.0,
            s: Vect2::ZERO,
            height: height.map(|(sz, vz)| Height { sz, vz }),
            polygons,
            sep: Separation { d, h },
        }
    }
}

/// The bands tile [lo, hi] in order without gaps, adjacent kinds differ, the Unknown
/// total is the sum of the Unknown widths and `met` says whether it is within `max`.
fn tiles(b: &Bands, lo: f64, hi: f64, max: f64) -> bool {
    let ordered = b
        .bands
        .windows(2)
        .all(|w| w[0].hi == w[1].lo && w[0].kind != w[1].kind);
    let u: f64 = b
        .bands
        .iter()
        .filter(|x| x.kind == BandKind::Unknown)
        .map(|x| x.hi - x.lo)
        .sum();
    b.bands.first().map(|x| x.lo) == Some(lo)
        && b.bands.last().map(|x| x.hi) == Some(hi)
        && ordered
        && b.bands.iter().all(|x| x.lo <= x.hi)
        && (u - b.unknown_total).abs() <= 1e-9 * (1.0 + u)
        && b.met == (b.unknown_total <= max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn course_bands_agree_with_the_exact_conflict(case in scene(), speed in 1.0..12.0f64) {
        let max = 1f64.to_radians();
        let b = case.with_traffic(|t| course_bands(t, speed, max)).expect("valid");
        prop_assert!(tiles(&b, 0.0, std::f64::consts::TAU, max), "{b:?}");
        let faults = check(&case, Param::Course { speed }, &b, 3, 0.0);
        prop_assert_eq!(contradictions(&faults), 0, "{:?}", faults);
    }

    #[test]
    fn speed_bands_agree_with_the_exact_conflict(case in scene(), course in 0.0..std::f64::consts::TAU) {
        let b = case.with_traffic(|t| speed_bands(t, course, 0.0, 12.0, 0.1)).expect("valid");
        prop_assert!(tiles(&b, 0.0, 12.0, 0.1), "{b:?}");
        let faults = check(&case, Param::Speed { course }, &b, 3, 0.0);
        prop_assert_eq!(contradictions(&faults), 0, "{:?}", faults);
    }

    #[test]
    fn vertical_speed_bands_agree_with_the_exact_conflict(
        case in scene(),
        vx in -6.0..6.0f64,
        vy in -6.0..6.0f64,
    ) {
        prop_assume!(case.height.is_some());
        let v = Vect2::new(vx, vy);
        let b = case
            .with_traffic(|t| vertical_speed_bands(t, v, -5.0, 5.0, 0.05))
            .expect("valid");
        prop_assert!(tiles(&b, -5.0, 5.0, 0.05), "{b:?}");
        let faults = check(&case, Param::Vertical { v }, &b, 3, 0.0);
        prop_assert_eq!(contradictions(&faults), 0, "{:?}", faults);
    }
}
