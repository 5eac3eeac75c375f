//! Paper A on the Earth (`polyguard_earth::aircraft_cell`) against the ground truth of
//! `reference::approach`: whenever the aircraft really comes within BUFF nautical miles
//! of the cell during [0, T], the answer is yes. Random encounters at every latitude up to
//! the format's limit and across the antimeridian; the canary (the unscaled buffer) must
//! be caught missing at high latitude.

use polyguard_earth::aircraft_cell::{
    detect_earth, detect_earth_with, Buffer, EarthCase, Options, Pieces,
};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::reference::approach::{closest_approach, encounter};
use proptest::prelude::*;

/// The truth's closest approach `d` over [0, T] and the case with BUFF just above it
/// (so the aircraft really comes within BUFF), or None when the case is outside the
/// format (a mover leaves ±85°, …).
fn at_the_truth(mut case: EarthCase, geo: Geodesy, samples: usize) -> Option<(EarthCase, f64)> {
    detect_earth(&case, geo).ok()?;
    let (d, _) = closest_approach(&case, geo, samples);
    case.buff_nm = if d == 0.0 { 0.01 } else { d * (1.0 + 1e-9) };
    detect_earth(&case, geo).ok()?;
    Some((case, d))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, max_global_rejects: 4096, ..ProptestConfig::default() })]

    /// On the sphere, latitudes from the equator to 84°, either hemisphere.
    #[test]
    fn within_buff_is_always_detected_on_the_sphere(seed in any::<u64>(), lat in -84.0f64..84.0) {
        let found = at_the_truth(encounter(seed, lat), Geodesy::Sphere, 200);
        prop_assume!(found.is_some());
        let (case, d) = found.unwrap_or_else(|| unreachable!());
        let a = detect_earth(&case, Geodesy::Sphere).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(a.detected, "missed: truth {d} nm < BUFF {} nm: {case:?} {a:?}", case.buff_nm);
        prop_assert!(a.effective_buff_nm >= case.buff_nm);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, max_global_rejects: 1024, ..ProptestConfig::default() })]

    /// On WGS84 (geodesic distances by Karney's method), fewer cases: each is slower.
    #[test]
    fn within_buff_is_always_detected_on_wgs84(seed in any::<u64>(), lat in -84.0f64..84.0) {
        let found = at_the_truth(encounter(seed, lat), Geodesy::Wgs84, 50);
        prop_assume!(found.is_some());
        let (case, d) = found.unwrap_or_else(|| unreachable!());
        let a = detect_earth(&case, Geodesy::Wgs84).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(a.detected, "missed: truth {d} nm < BUFF {} nm: {case:?} {a:?}", case.buff_nm);
    }
}

/// The canary: handed `BUFF / R` alone (no sec φ, no deviation, one piece), the engine
/// misses approaches within BUFF at high latitude, and the check above sees them; the
/// certified buffer on the same cases misses none. Also counts what the cases covered.
#[test]
fn the_unscaled_buffer_is_caught_missing_at_high_latitude() {
    let unscaled = Options {
        geodesy: Geodesy::Sphere,
        buffer: Buffer::Unscaled,
        pieces: Pieces::Fixed(1),
    };
    let (mut valid, mut canary_missed, mut crossing) = (0, 0, 0);
    for seed in 0..60u64 {
        let lat = if seed % 2 == 0 { 75.0 } else { -80.0 };
        let Some((case, _)) = at_the_truth(encounter(seed, lat), Geodesy::Sphere, 200) else {
            continue;
        };
        valid += 1;
        let lons = case.cell_vertices.iter().map(|v| v[0]);
        if lons.clone().any(|x| x > 170.0) && lons.clone().any(|x| x < -170.0) {
            crossing += 1;
        }
        let certified = detect_earth(&case, Geodesy::Sphere).expect("valid");
        assert!(certified.detected, "certified missed {case:?}");
        if !detect_earth_with(&case, unscaled).expect("valid").detected {
            canary_missed += 1;
        }
    }
    assert!(valid >= 40, "only {valid} of 60 encounters in the format");
    assert!(
        crossing >= 5,
        "only {crossing} cells across the antimeridian"
    );
    // at 75-80° sec φ is 3.9-5.8: nearly every boundary approach is missed unscaled
    assert!(
        canary_missed * 2 >= valid,
        "the canary missed only {canary_missed} of {valid}: the check is blind"
    );
}

/// Every sampled time at which the aircraft is within BUFF of the cell (the reference's
/// distance, BUFF set just above the closest approach) lies in a certified separation
/// window, and the windows are sorted and disjoint inside [0, T].
fn windows_cover(case: &EarthCase, geo: Geodesy, samples: usize) -> Result<usize, String> {
    let a = detect_earth(case, geo).map_err(|e| e.to_string())?;
    windows_hold(case, geo, samples, &a)
}

/// [`windows_cover`]'s check of the answer `a`.
fn windows_hold(
    case: &EarthCase,
    geo: Geodesy,
    samples: usize,
    a: &polyguard_earth::aircraft_cell::EarthAnswer,
) -> Result<usize, String> {
    let w = &a.separation_windows_h;
    for pair in w.windows(2) {
        if pair[0][1] >= pair[1][0] {
            return Err(format!("windows overlap: {w:?}"));
        }
    }
    if a.alarm_window_h != w.first().copied() {
        return Err(format!("alarm_window_h is not the first window: {a:?}"));
    }
    let mut within = 0;
    for k in 0..=samples {
        let t = case.lookahead_h * k as f64 / samples as f64;
        let d = polyguard_earth::reference::approach::distance_at(case, geo, t);
        if d <= case.buff_nm {
            within += 1;
            if !w.iter().any(|&[lo, hi]| lo <= t && t <= hi) {
                return Err(format!(
                    "at t = {t} h the aircraft is {d} nm from the cell (BUFF {}), outside every window {w:?}",
                    case.buff_nm
                ));
            }
        }
    }
    Ok(within)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, max_global_rejects: 4096, ..ProptestConfig::default() })]

    /// The separation windows miss no sampled time within BUFF, at every latitude.
    #[test]
    fn separation_windows_hold_every_time_within_buff(seed in any::<u64>(), lat in -84.0f64..84.0) {
        let found = at_the_truth(encounter(seed, lat), Geodesy::Sphere, 200);
        prop_assume!(found.is_some());
        let (mut case, d) = found.unwrap_or_else(|| unreachable!());
        // a buffer a little above the closest approach: the aircraft is within it for a
        // stretch of time, which the samples see
        case.buff_nm = d * 1.05 + 0.05;
        windows_cover(&case, Geodesy::Sphere, 400).map_err(TestCaseError::fail)?;
    }
}

/// Encounters at 45°: the windows hold every sampled time within BUFF and, for most, are
/// much narrower than the lookahead (the alarm window of a one-piece answer was the whole
/// of [0, T]).
#[test]
fn separation_windows_are_narrower_than_the_lookahead() {
    let (mut narrower, mut seen) = (0, 0);
    for seed in 0..40u64 {
        let Some((mut case, d)) = at_the_truth(encounter(seed, 45.0), Geodesy::Sphere, 200) else {
            continue;
        };
        case.buff_nm = d * 1.05 + 0.05;
        let within = windows_cover(&case, Geodesy::Sphere, 400).unwrap_or_else(|e| panic!("{e}"));
        let a = detect_earth(&case, Geodesy::Sphere).expect("valid");
        let total: f64 = a.separation_windows_h.iter().map(|w| w[1] - w[0]).sum();
        seen += usize::from(within > 0);
        if total < 0.9 * case.lookahead_h {
            narrower += 1;
        }
    }
    assert!(seen >= 10, "too few encounters within BUFF: {seen}");
    assert!(
        narrower * 2 >= seen,
        "windows barely narrower than T: {narrower} of {seen}"
    );
}

/// The check's canary: the windows of the unscaled buffer (no sec φ, one piece) at high
/// latitude are too narrow, and the sampled check catches times within BUFF outside them.
#[test]
fn the_windows_check_catches_the_unscaled_buffer() {
    let unscaled = Options {
        geodesy: Geodesy::Sphere,
        buffer: Buffer::Unscaled,
        pieces: Pieces::Fixed(1),
    };
    let mut caught = 0;
    for seed in 0..40u64 {
        let Some((mut case, d)) = at_the_truth(encounter(seed, 78.0), Geodesy::Sphere, 200) else {
            continue;
        };
        case.buff_nm = d * 1.05 + 0.05;
        let a = detect_earth_with(&case, unscaled).expect("valid");
        if windows_hold(&case, Geodesy::Sphere, 400, &a).is_err() {
            caught += 1;
        }
    }
    assert!(
        caught > 0,
        "the unscaled buffer's windows were never caught short"
    );
}
