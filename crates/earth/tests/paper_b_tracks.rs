//! Paper B Sections III and V: tracks of several waypoints (one straight Mercator segment
//! per leg) and the exact linear case (eq 20) against a hand derivation.

use polyguard_earth::conflict::{pipeline, stage4::Method, Object};
use polyguard_earth::sphere::{mercator, track_legs, LonLat, RectDims, EARTH_RADIUS_NM};

const DIMS: RectDims = RectDims {
    front: 5.0,
    back: 5.0,
    side: 5.0,
};

fn square(owner: u32, lon: (f64, f64), lat: (f64, f64)) -> Object {
    let ring = [
        (lon.0, lat.0),
        (lon.1, lat.0),
        (lon.1, lat.1),
        (lon.0, lat.1),
    ]
    .iter()
    .map(|&(x, y)| mercator(LonLat::from_degrees(x, y)))
    .collect();
    Object::area(owner, ring, f64::NEG_INFINITY, f64::INFINITY)
}

#[test]
fn conflict_on_the_second_leg_only() {
    let legs = track_legs(
        &[
            LonLat::from_degrees(-40.0, 10.0),
            LonLat::from_degrees(-39.0, 10.0),
            LonLat::from_degrees(-39.0, 11.0),
        ],
        15.0,
        0.0,
        DIMS,
    );
    assert_eq!(legs.len(), 2);
    assert_eq!(legs[1].t0, legs[0].t1, "legs are back to back");
    let first_end = legs[0].t1;
    let mut objs = vec![square(0, (-39.2, -38.8), (10.4, 10.6))];
    objs.extend(legs.into_iter().map(|l| Object::leg(1, l)));
    let (c, _) = pipeline::run(&objs, pipeline::Options::default());
    assert_eq!(c.len(), 1, "one feature pair, legs merged");
    assert!(c[0].t_start > first_end && c[0].t_end > c[0].t_start);
    // the second leg's front (5 nm ahead) reaches lat 10.4° after (0.4° · 60 − 5) nm
    let want = first_end + (0.4 * 60.0 * (EARTH_RADIUS_NM * 1f64.to_radians() / 60.0) - 5.0) / 15.0;
    assert!(
        (c[0].t_start - want).abs() < 2.0 * polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H,
        "{} vs {want}",
        c[0].t_start
    );
}

#[test]
fn east_west_track_through_a_square_is_exact() {
    let leg = track_legs(
        &[
            LonLat::from_degrees(-40.0, 10.5),
            LonLat::from_degrees(-38.0, 10.5),
        ],
        15.0,
        0.0,
        DIMS,
    )
    .remove(0);
    let x0 = leg.start.lon;
    let v = leg.linear_velocity().expect("east-west leg is linear")[0];
    // front offset in x of the east–west rectangle: d_f / (R cos φ) (the limit of eq 24)
    let front = 5.0 / (EARTH_RADIUS_NM * leg.start.lat.cos());
    let (west, east) = ((-39.2f64).to_radians(), (-38.8f64).to_radians());
    let objs = vec![square(0, (-39.2, -38.8), (10.4, 10.6)), Object::leg(1, leg)];
    let (c, _) = pipeline::run(&objs, pipeline::Options::default());
    assert_eq!(c[0].method, Method::Linear);
    // the window contains the exact one and exceeds it by at most its certified
    // relaxation: twice the position slack (coordinates ≤ |x| + 2π) over the speed, a
    // few µs (the `want`s carry ~1e-15 h of rounding of their own)
    let (want_s, want_e) = ((west - front - x0) / v, (east + front - x0) / v);
    let pad = 4.0 * polyguard_earth::sphere::position_slack(1.0 + std::f64::consts::TAU) / v;
    assert!(pad < 1e-8, "{pad}");
    let (s, e) = (c[0].t_start, c[0].t_end);
    assert!(s <= want_s + 1e-12 && s >= want_s - pad, "{s} vs {want_s}");
    assert!(e >= want_e - 1e-12 && e <= want_e + pad, "{e} vs {want_e}");
}
