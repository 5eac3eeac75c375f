//! Whole flights on the Earth (docs/moving-features.md) whose answers are known exactly:
//! along a parallel or a meridian at constant speed, longitude or latitude is linear in
//! time, so the times of entry and exit of a lon/lat box are rational.

use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::moving::encounter::{encounter, Options, PreparedArea};
use polyguard_earth::moving::model::{Area, Fix, Rings, Shape, Trajectory};

const T0: f64 = 1_633_611_625.0;

fn flight(fixes: &[(f64, f64, f64)]) -> Trajectory {
    Trajectory {
        id: "f".into(),
        callsign: None,
        fixes: fixes
            .iter()
            .map(|&(t, lon, lat)| Fix {
                t: T0 + t,
                lon,
                lat,
                alt_ft: Some(30000.0),
            })
            .collect(),
    }
}

fn boxed(lon0: f64, lat0: f64, lon1: f64, lat1: f64) -> Area {
    Area {
        id: "a".into(),
        name: None,
        shape: Shape::Static(vec![Rings {
            outer: vec![[lon0, lat0], [lon1, lat0], [lon1, lat1], [lon0, lat1]],
            holes: vec![],
        }]),
        floor_ft: None,
        ceiling_ft: None,
    }
}

/// One certain inside span enclosing [T0 + a, T0 + b] to within a millisecond's width.
fn assert_inside(f: &Trajectory, area: &Area, geo: Geodesy, a: f64, b: f64) {
    let opts = Options {
        max_gap_s: 1e9,
        geodesy: geo,
        ..Options::default()
    };
    let pa = PreparedArea::new(area, geo).unwrap();
    let e = encounter(f, &pa, &opts).unwrap().expect("they meet");
    assert_eq!(e.inside.len(), 1, "{:?}", e.inside);
    let s = e.inside[0];
    assert!(s.certain);
    assert!(
        s.start[0] <= T0 + a && T0 + a <= s.start[1],
        "{:?} vs {}",
        s.start,
        T0 + a
    );
    assert!(
        s.end[0] <= T0 + b && T0 + b <= s.end[1],
        "{:?} vs {}",
        s.end,
        T0 + b
    );
    assert!(
        s.start[1] - s.start[0] < 1e-3 && s.end[1] - s.end[0] < 1e-3,
        "{s:?}"
    );
}

#[test]
fn east_along_a_parallel_through_a_box() {
    let f = flight(&[(0.0, 0.0, 49.0), (7200.0, 2.0, 49.0)]);
    for geo in [Geodesy::Sphere, Geodesy::Wgs84] {
        assert_inside(&f, &boxed(0.5, 48.5, 1.5, 49.5), geo, 1800.0, 5400.0);
    }
}

#[test]
fn north_along_a_meridian_where_the_rhumb_line_is_not_uniform_on_the_plane() {
    // Latitude linear in time at constant speed; its Mercator ordinate is not.
    let f = flight(&[(0.0, 1.0, 48.0), (7200.0, 1.0, 50.0)]);
    assert_inside(
        &f,
        &boxed(0.5, 48.5, 1.5, 49.5),
        Geodesy::Sphere,
        1800.0,
        5400.0,
    );
}

#[test]
fn across_the_antimeridian() {
    let f = flight(&[(0.0, 179.0, 49.0), (7200.0, -179.0, 49.0)]);
    assert_inside(
        &f,
        &boxed(179.5, 48.5, -179.5, 49.5),
        Geodesy::Sphere,
        1800.0,
        5400.0,
    );
    // The area given on the other side of the line: the same answer.
    assert_inside(
        &f,
        &boxed(-180.5 + 360.0, 48.5, 180.5 - 360.0, 49.5),
        Geodesy::Sphere,
        1800.0,
        5400.0,
    );
}

#[test]
fn near_starts_before_inside_and_ends_after() {
    let f = flight(&[(0.0, 0.0, 49.0), (7200.0, 2.0, 49.0)]);
    let opts = Options {
        sep_nm: 5.0,
        max_gap_s: 1e9,
        ..Options::default()
    };
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    let e = encounter(&f, &pa, &opts).unwrap().unwrap();
    assert_eq!(e.near.len(), 1);
    // 2° of longitude at 49° in 7200 s: 78.7 nm/h; 5 nm is about 229 s.
    let speed = 2.0 * 60.0 * 49f64.to_radians().cos() / 7200.0;
    let lead = 5.0 / speed;
    let start = e.loss_of_separation().unwrap();
    assert!(
        (start[0] - (T0 + 1800.0 - lead)).abs() < 0.01 * lead,
        "{start:?}"
    );
    assert!(e.near[0].end[1] > e.inside[0].end[1]);
}

#[test]
fn a_gap_splits_the_flight_and_is_reported() {
    let f = flight(&[
        (0.0, 0.0, 49.0),
        (30.0, 0.001, 49.0),
        (3600.0, 0.9, 49.0),
        (3630.0, 0.9001, 49.0),
    ]);
    let opts = Options::default();
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    let e = encounter(&f, &pa, &opts).unwrap().unwrap();
    assert_eq!(e.gaps, vec![[T0 + 30.0, T0 + 3600.0]]);
    // Only the second segment is inside: the flight is nowhere during the gap.
    assert_eq!(e.inside.len(), 1);
    assert_eq!(e.inside[0].start, [T0 + 3600.0, T0 + 3600.0]);
}

#[test]
fn a_flight_that_stays_away_meets_nothing() {
    let f = flight(&[(0.0, 10.0, 40.0), (600.0, 10.5, 40.0)]);
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    assert_eq!(
        encounter(
            &f,
            &pa,
            &Options {
                sep_nm: 50.0,
                ..Options::default()
            }
        )
        .unwrap(),
        None
    );
}

#[test]
fn bad_positions_are_named() {
    let f = flight(&[(0.0, 0.0, 49.0), (60.0, 0.0, 88.0)]);
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    let e = encounter(&f, &pa, &Options::default()).unwrap_err();
    assert_eq!(e.member, "fixes[1]");
    assert!(e.to_string().contains("latitude 88"), "{e}");
    let mut a = boxed(0.5, 48.5, 1.5, 49.5);
    a.floor_ft = Some(10.0);
    a.ceiling_ft = Some(5.0);
    assert_eq!(
        PreparedArea::new(&a, Geodesy::Sphere).err().unwrap().member,
        "floor_ft"
    );
}

#[test]
fn a_fix_without_altitude_takes_the_line_between_its_neighbours() {
    // Climbing 0 → 2000 ft over 200 s through a ceiling of 1000 ft, the middle fix without
    // altitude: the model's altitude there is 1000 ft, so inside ends at t = 100 s.
    let mut f = flight(&[(0.0, 0.0, 49.0), (100.0, 0.001, 49.0), (200.0, 0.002, 49.0)]);
    f.fixes[0].alt_ft = Some(0.0);
    f.fixes[1].alt_ft = None;
    f.fixes[2].alt_ft = Some(2000.0);
    let mut a = boxed(-0.5, 48.5, 1.5, 49.5);
    a.ceiling_ft = Some(1000.0);
    let pa = PreparedArea::new(&a, Geodesy::Sphere).unwrap();
    let e = encounter(
        &f,
        &pa,
        &Options {
            max_gap_s: 1e9,
            ..Options::default()
        },
    )
    .unwrap()
    .unwrap();
    assert_eq!(e.inside.len(), 1, "{:?}", e.inside);
    let s = e.inside[0];
    assert!(
        s.certain && s.end[0] <= T0 + 100.0 && T0 + 100.0 <= s.end[1],
        "{s:?}"
    );
    assert!(s.end[1] - s.end[0] < 1e-3, "{s:?}");
}

#[test]
fn a_separation_that_could_reach_the_pole_is_refused() {
    let f = flight(&[(0.0, 0.0, 84.0), (60.0, 0.1, 84.0)]);
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    let opts = Options {
        sep_nm: 400.0,
        ..Options::default()
    };
    let e = encounter(&f, &pa, &opts).unwrap_err();
    assert_eq!(e.member, "fixes[0].lat");
    assert!(encounter(
        &f,
        &pa,
        &Options {
            sep_nm: 40.0,
            ..Options::default()
        }
    )
    .is_ok());
}

#[test]
fn near_ends_enclose_the_great_circle_distance_to_a_meridian_edge() {
    // From (λ, 49°) the distance to the meridian λ₀ is asin(sin|λ − λ₀|·cos 49°)·R; at 5 nm
    // from the box's west and east edges the flight (1° an hour) is near.
    let f = flight(&[(0.0, 0.0, 49.0), (7200.0, 2.0, 49.0)]);
    let opts = Options {
        sep_nm: 5.0,
        max_gap_s: 1e9,
        ..Options::default()
    };
    let pa = PreparedArea::new(&boxed(0.5, 48.5, 1.5, 49.5), Geodesy::Sphere).unwrap();
    let e = encounter(&f, &pa, &opts).unwrap().unwrap();
    let r = polyguard_earth::rhumb::EARTH_RADIUS_NM;
    let dl = ((5.0 / r).sin() / 49f64.to_radians().cos())
        .asin()
        .to_degrees();
    let (a, b) = (T0 + (0.5 - dl) * 3600.0, T0 + (1.5 + dl) * 3600.0);
    let s = e.near[0];
    assert!(s.start[0] <= a && a <= s.start[1], "{:?} vs {a}", s.start);
    assert!(s.end[0] <= b && b <= s.end[1], "{:?} vs {b}", s.end);
    // The band between d_lo and d_hi is a few tenths of a percent of D: seconds here.
    assert!(
        s.start[1] - s.start[0] < 5.0 && s.end[1] - s.end[0] < 5.0,
        "{s:?}"
    );
}
