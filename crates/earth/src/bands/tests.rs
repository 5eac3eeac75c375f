use super::*;
use crate::reference::approach::{closest_approach, distance_nm, encounter, position, Mix};

/// The largest sampled distance (nm) between the positions at equal times on courses
/// θ and θ' ∈ [θ − δ, θ + δ] (degrees), over [0, T].
fn sampled_spread(start: [f64; 2], course: f64, delta_deg: f64, speed: f64, t_end: f64) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..=8 {
        let t = t_end * i as f64 / 8.0;
        let a = position(Geodesy::Sphere, start, course, speed, t);
        for k in [-1.0, -0.5, 0.5, 1.0] {
            let b = position(Geodesy::Sphere, start, course + k * delta_deg, speed, t);
            worst = worst.max(distance_nm(Geodesy::Sphere, a, b));
        }
    }
    worst
}

/// r for courses bounds the sampled spread at every latitude up to the reach's limit,
/// every course and cell width; and the planar bound L·2 sin(δ/2) alone (the canary) is
/// exceeded at high latitude, where rhumb lines of nearby courses fan out faster.
#[test]
fn the_course_spread_bounds_rhumb_positions_and_the_planar_bound_does_not() {
    let mut rng = Mix(30);
    let mut planar_exceeded = 0;
    for case in 0..400 {
        let lat = rng.uniform(-80.0, 80.0);
        let course = rng.uniform(0.0, 360.0);
        let speed = rng.uniform(60.0, 600.0);
        let t_end = rng.uniform(0.1, 1.0);
        let delta_deg = 10f64.powf(rng.uniform(-3.0, 1.0));
        let start = [rng.uniform(-170.0, 170.0), lat];
        let Some(r) = course_spread_nm(speed, t_end, lat.to_radians(), delta_deg.to_radians())
        else {
            continue;
        };
        let got = sampled_spread(start, course, delta_deg, speed, t_end);
        assert!(got <= r, "case {case}: sampled {got} nm above r = {r} nm");
        let planar = speed * t_end * 2.0 * (delta_deg.to_radians() / 2.0).sin();
        if got > planar * (1.0 + 1e-6) {
            planar_exceeded += 1;
        }
    }
    assert!(
        planar_exceeded > 10,
        "the planar bound held in all but {planar_exceeded}"
    );
}

/// A reach past 85° of latitude is refused, naming the lookahead.
#[test]
fn a_reach_past_the_latitude_limit_is_refused() {
    assert!(course_spread_nm(600.0, 1.0, 80f64.to_radians(), 0.01).is_none());
    let mut case = encounter(7, 82.0);
    case.aircraft.speed_kn = 600.0;
    case.lookahead_h = 1.0;
    case.aircraft.course_deg = 90.0;
    case.buff_nm = 5.0;
    match course_bands(&case, Geodesy::Sphere, 0.5) {
        Err(e) => assert_eq!(e.field, "lookahead_h", "{e}"),
        Ok(b) => panic!("answered {b:?}"),
    }
}

/// Course bands refuse WGS84 and a non-positive unknown_max, naming the field.
#[test]
fn course_bands_name_the_fields_they_refuse() {
    let case = encounter(3, 40.0);
    let e = course_bands(&case, Geodesy::Wgs84, 0.1).expect_err("wgs84");
    assert_eq!(e.field, "geodesy");
    let e = course_bands(&case, Geodesy::Sphere, 0.0).expect_err("zero");
    assert_eq!(e.field, "unknown_max_deg");
    let e = speed_bands(&case, Geodesy::Sphere, 300.0, 200.0, 1.0).expect_err("order");
    assert_eq!(e.field, "speeds_kn[1]");
}

/// Bands tile their range in order, and agree with the reference's closest approach:
/// a course (or speed) drawn in a clear band never comes within BUFF, one in a conflict
/// band does (the reference's distance is between two real points, so a clear value it
/// finds within BUFF is a real failure; a conflict value is checked against BUFF with
/// the reference's sampling). Encounters of the detection tests, BUFF 5 nm.
fn check_bands(bands: &Bands, lo: f64, hi: f64) {
    assert_eq!(bands.bands.first().map(|b| b.lo), Some(lo));
    assert_eq!(bands.bands.last().map(|b| b.hi), Some(hi));
    for w in bands.bands.windows(2) {
        assert_eq!(w[0].hi, w[1].lo);
        assert_ne!(w[0].kind, w[1].kind);
    }
}

fn judge(case: &EarthCase, kind: BandKind, what: &str) -> (usize, usize) {
    let (d, _) = closest_approach(case, Geodesy::Sphere, 200);
    match kind {
        BandKind::Clear => {
            assert!(
                d > case.buff_nm,
                "{what}: clear, yet {d} nm ≤ BUFF {}",
                case.buff_nm
            );
            (1, 0)
        }
        BandKind::Conflict => {
            assert!(
                d <= case.buff_nm,
                "{what}: conflict, yet {d} nm > BUFF {}",
                case.buff_nm
            );
            (0, 1)
        }
        BandKind::Unknown => (0, 0),
    }
}

#[test]
fn drawn_courses_and_speeds_agree_with_the_reference() {
    let mut rng = Mix(31);
    let (mut clear, mut conflict) = (0, 0);
    for seed in 0..6u64 {
        let lat = [0.0, 30.0, 55.0, 70.0, -45.0, 10.0][seed as usize];
        let mut case = encounter(1000 + seed, lat);
        case.buff_nm = 5.0;
        case.lookahead_h = case.lookahead_h.min(0.5);
        let bands = course_bands(&case, Geodesy::Sphere, 0.5).expect("answered");
        check_bands(&bands, 0.0, 360.0);
        assert!(bands.bands.iter().any(|b| b.kind == BandKind::Clear));
        for b in &bands.bands {
            for _ in 0..3 {
                let x = rng.uniform(b.lo, b.hi);
                let flown = EarthCase {
                    aircraft: Motion {
                        course_deg: x,
                        ..case.aircraft
                    },
                    ..case.clone()
                };
                let (a, c) = judge(&flown, b.kind, &format!("seed {seed} course {x}"));
                clear += a;
                conflict += c;
            }
        }
        let speeds = speed_bands(&case, Geodesy::Sphere, 0.0, 600.0, 1.0).expect("answered");
        check_bands(&speeds, 0.0, 600.0);
        for b in &speeds.bands {
            let x = rng.uniform(b.lo, b.hi);
            let flown = EarthCase {
                aircraft: Motion {
                    speed_kn: x,
                    ..case.aircraft
                },
                ..case.clone()
            };
            let (a, c) = judge(&flown, b.kind, &format!("seed {seed} speed {x}"));
            clear += a;
            conflict += c;
        }
    }
    assert!(
        clear > 20 && conflict > 5,
        "{clear} clear and {conflict} conflict draws"
    );
}

/// A certain approach is one: the time returned is one at which the reference puts the
/// aircraft within BUFF; and when the reference's closest approach is comfortably
/// inside BUFF, one is found.
#[test]
fn certain_within_is_within_buff_at_its_time() {
    let mut found = 0;
    for seed in 0..40u64 {
        let lat = -75.0 + 150.0 * (seed as f64 / 39.0);
        let mut case = encounter(2000 + seed, lat);
        let (d, _) = closest_approach(&case, Geodesy::Sphere, 200);
        case.buff_nm = d + 2.0;
        if let Some(t) = certain_within(&case, Geodesy::Sphere).expect("answered") {
            let at = crate::reference::approach::distance_at(&case, Geodesy::Sphere, t);
            assert!(at <= case.buff_nm, "seed {seed}: {at} nm at t = {t}");
            found += 1;
        }
    }
    assert!(found >= 30, "found {found} of 40");
}
