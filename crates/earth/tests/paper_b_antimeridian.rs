//! Paper B on the real Earth, across the antimeridian:
//! longitudes are read modulo 360°, steps run the shorter way, and objects meet
//! across ±180°. The strongest check is an invariance: turning a whole scenario about the
//! Earth's axis (every longitude plus a constant) changes no conflict, whether or not the
//! turned scenario straddles the antimeridian.

use polyguard_earth::analysis::{analyse, Analysis};
use polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H as TOL;
use polyguard_earth::generate::{generate, Mix};
use polyguard_earth::scenario::{to_geojson, Kind, Scenario};
use polyguard_earth::sphere::LonLat;

fn area(id: &str, ring: &[(f64, f64)]) -> String {
    let mut pts: Vec<String> = ring.iter().map(|(x, y)| format!("[{x},{y}]")).collect();
    pts.push(pts[0].clone());
    format!(
        r#"{{"type":"Feature","properties":{{"id":"{id}","kind":"area"}},"geometry":{{"type":"Polygon","coordinates":[[{}]]}}}}"#,
        pts.join(",")
    )
}

fn boxed(id: &str, lon: (f64, f64), lat: (f64, f64)) -> String {
    area(
        id,
        &[
            (lon.0, lat.0),
            (lon.1, lat.0),
            (lon.1, lat.1),
            (lon.0, lat.1),
        ],
    )
}

fn track(id: &str, from: (f64, f64), to: (f64, f64)) -> String {
    format!(
        r#"{{"type":"Feature","properties":{{"id":"{id}","kind":"track","speed_kn":15,"front_nm":5,"back_nm":5,"side_nm":5,"t0":0}},"geometry":{{"type":"LineString","coordinates":[[{},{}],[{},{}]]}}}}"#,
        from.0, from.1, to.0, to.1
    )
}

fn run(features: &[String]) -> Analysis {
    let text = format!(
        "{{\"type\":\"FeatureCollection\",\"features\":[\n{}\n]}}",
        features.join(",\n")
    );
    let a = analyse(&text, TOL).expect("a collection");
    assert!(a.errors.is_empty(), "{:?}", a.errors);
    a
}

/// The conflicts as (a, b, t_start, t_end), ids in file order.
fn pairs(a: &Analysis) -> Vec<(String, String, f64, f64)> {
    a.conflicts
        .iter()
        .map(|c| {
            let id = |k: u32| a.scenario.features[k as usize].id.clone();
            (id(c.a), id(c.b), c.t_start, c.t_end)
        })
        .collect()
}

fn ids(a: &Analysis) -> Vec<(String, String)> {
    pairs(a).into_iter().map(|(x, y, _, _)| (x, y)).collect()
}

/// A box from 179.5 to −179.5 is 1° wide, across the antimeridian.
/// It meets a box just east of it (written in negative longitudes), one written beyond
/// 180, and one west of it, but not one at longitude 10 (which a 359°-wide box would).
#[test]
fn a_box_across_the_antimeridian_is_one_degree_wide() {
    let a = run(&[
        boxed("across", (179.5, -179.5), (0.0, 1.0)),
        boxed("east", (-179.8, -179.6), (0.2, 0.8)),
        boxed("beyond", (180.2, 180.3), (0.2, 0.8)),
        boxed("west", (179.0, 179.6), (0.2, 0.8)),
        boxed("ten", (10.0, 11.0), (0.2, 0.8)),
    ]);
    let got = ids(&a);
    for other in ["east", "beyond", "west"] {
        assert!(
            got.contains(&("across".to_owned(), other.to_owned())),
            "{other}: {got:?}"
        );
    }
    assert!(
        !got.iter().any(|(x, y)| x == "ten" || y == "ten"),
        "{got:?}"
    );
    // east and beyond are the same strip of longitude (180.2 is −179.8)
    assert!(
        got.contains(&("east".to_owned(), "beyond".to_owned())),
        "{got:?}"
    );
    // the region of across ∩ east lies in [−180, 180], west of −179.5
    let c = a
        .conflicts
        .iter()
        .find(|c| a.scenario.features[c.b as usize].id == "east")
        .expect("across meets east");
    assert!(!c.rings.is_empty());
    for r in &c.rings {
        for p in r {
            assert!(p[0] >= -std::f64::consts::PI && p[0] <= std::f64::consts::PI);
        }
    }
}

/// Longitude 190 is the place −170 names: two boxes written so meet.
#[test]
fn longitude_190_is_minus_170() {
    let a = run(&[
        boxed("written_east", (189.5, 190.5), (10.0, 11.0)),
        boxed("written_west", (-170.2, -169.8), (10.2, 10.8)),
    ]);
    assert_eq!(ids(&a).len(), 1);
    assert_eq!(a.warnings.len(), 1, "the wrapped longitude is named");
}

/// A track that crosses the antimeridian east-bound, and one west-bound, meet an area
/// beyond it at the times the same encounter has 10° west of the antimeridian.
#[test]
fn tracks_cross_the_antimeridian_both_ways() {
    for (from, to, area_lon) in [
        ((179.0, 0.0), (-179.0, 0.0), (-179.6, -179.4)),
        ((-179.0, 0.0), (179.0, 0.0), (179.4, 179.6)),
        ((179.5, -0.5), (-179.5, 0.5), (179.9, -179.9)),
    ] {
        let here = run(&[track("t", from, to), boxed("a", area_lon, (-0.5, 0.5))]);
        let turn = |x: f64| if x > 0.0 { x - 190.0 } else { x + 170.0 };
        let west = run(&[
            track("t", (turn(from.0), from.1), (turn(to.0), to.1)),
            boxed("a", (turn(area_lon.0), turn(area_lon.1)), (-0.5, 0.5)),
        ]);
        let (p, q) = (pairs(&here), pairs(&west));
        assert_eq!(p.len(), 1, "{from:?} → {to:?}: {p:?}");
        assert_eq!(q.len(), 1, "{q:?}");
        assert!(p[0].2 > 0.0 && p[0].3 < 10.0, "{p:?}");
        assert!(
            (p[0].2 - q[0].2).abs() <= 2.0 * TOL && (p[0].3 - q[0].3).abs() <= 2.0 * TOL,
            "{from:?} → {to:?}: {p:?} against {q:?}"
        );
    }
}

/// SplitMix64, the generator's randomness for these tests.
fn rng(seed: u64) -> impl FnMut() -> u64 {
    let mut s = seed;
    move || {
        s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}

/// Every longitude of the scenario plus `deg`.
fn turned(sc: &Scenario, deg: f64) -> Scenario {
    let mv = |p: &LonLat| {
        let (lon, lat) = p.to_degrees();
        LonLat::from_degrees(lon + deg, lat)
    };
    let mut out = sc.clone();
    for f in &mut out.features {
        match &mut f.kind {
            Kind::Area(a) => {
                for sh in &mut a.shapes {
                    sh.ring = sh.ring.iter().map(mv).collect();
                    for h in &mut sh.holes {
                        *h = h.iter().map(mv).collect();
                    }
                }
            }
            Kind::Track(t) => t.waypoints = t.waypoints.iter().map(mv).collect(),
        }
    }
    out
}

/// Paper B §VI.D scenarios (areas and tracks in 30° of longitude) turned so that they
/// straddle the antimeridian, from the east and from the west, and turned a whole turn
/// and more: the same conflicts (pairs, and times within twice the tolerance) as the
/// scenario where the paper draws it.
#[test]
fn turning_the_earth_changes_no_conflict() {
    for seed in 1..=3u64 {
        let mut bits = rng(seed);
        let sc = generate(300, Mix::Mixed, false, &mut bits);
        let at = |s: &Scenario| {
            let text = to_geojson(s).to_string();
            let a = analyse(&text, TOL).expect("a collection");
            assert!(a.errors.is_empty(), "{:?}", a.errors);
            pairs(&a)
        };
        let base = at(&sc);
        assert!(base.len() > 20, "a scenario with conflicts: {}", base.len());
        for deg in [210.0, -150.0, 195.0, -165.0, 360.0 + 210.0, -720.0] {
            let got = at(&turned(&sc, deg));
            assert_eq!(
                got.len(),
                base.len(),
                "seed {seed}, turned {deg}°: {} conflicts, {} unturned",
                got.len(),
                base.len()
            );
            for (g, b) in got.iter().zip(&base) {
                assert_eq!((&g.0, &g.1), (&b.0, &b.1), "seed {seed}, turned {deg}°");
                // areas without a start or end conflict from −∞ to +∞
                let close = |x: f64, y: f64| x == y || (x - y).abs() <= 2.0 * TOL;
                assert!(
                    close(g.2, b.2) && close(g.3, b.3),
                    "seed {seed}, turned {deg}°: {g:?} against {b:?}"
                );
            }
        }
    }
}

/// The pipeline in blocks of a few features gives the conflicts of one block, in the
/// same order (feature pairs), on a scenario that straddles the antimeridian (copies of
/// objects a turn away belong to their feature's block).
#[test]
fn blocks_change_no_conflict() {
    use polyguard_earth::conflict::pipeline::{run, Options};
    let sc = turned(&generate(300, Mix::Mixed, false, &mut rng(7)), 195.0);
    let objects = polyguard_earth::scenario::objects(&sc);
    let whole = Options {
        block_objects: usize::MAX,
        block_pairs: usize::MAX,
        ..Options::default()
    };
    let (one, s1) = run(&objects, whole);
    assert!(one.len() > 20, "{} conflicts", one.len());
    // blocks of a few objects, and blocks cut where their pairs reach a few dozen
    for (block_objects, block_pairs) in [
        (1, usize::MAX),
        (7, usize::MAX),
        (64, usize::MAX),
        (usize::MAX, 40),
    ] {
        let (got, s) = run(
            &objects,
            Options {
                block_objects,
                block_pairs,
                ..whole
            },
        );
        assert_eq!(
            got, one,
            "blocks of {block_objects} objects, {block_pairs} pairs"
        );
        assert_eq!(
            (s.candidate_pairs, s.region_pairs, s.interval_pairs),
            (s1.candidate_pairs, s1.region_pairs, s1.interval_pairs)
        );
    }
}
