//! Paper B with GeoJSON polygons as they are:
//! holes are not part of an area, and a MultiPolygon is the union of its parts. The times
//! are checked against a truth sampled independently of the stages: at each of many
//! instants, does the track's rectangle meet the area (exterior minus holes), by `geo`'s
//! closed-set `Intersects` on the Mercator polygons?

use geo::{Intersects, LineString, Polygon};
use polyguard_earth::analysis::{analyse, Analysis};
use polyguard_earth::conflict::{Object, DEFAULT_TIME_TOLERANCE_H as TOL};
use polyguard_earth::scenario::objects;
use polyguard_earth::sphere::Merc;

/// A ring as GeoJSON positions, closed.
fn ring(r: &[(f64, f64)]) -> String {
    let mut pts: Vec<String> = r.iter().map(|(x, y)| format!("[{x},{y}]")).collect();
    pts.push(pts[0].clone());
    format!("[{}]", pts.join(","))
}

fn square(lon: (f64, f64), lat: (f64, f64)) -> Vec<(f64, f64)> {
    vec![
        (lon.0, lat.0),
        (lon.1, lat.0),
        (lon.1, lat.1),
        (lon.0, lat.1),
    ]
}

/// An area: a Polygon of the given rings (the first the exterior).
fn polygon(id: &str, rings: &[Vec<(f64, f64)>]) -> String {
    let rs: Vec<String> = rings.iter().map(|r| ring(r)).collect();
    format!(
        r#"{{"type":"Feature","properties":{{"id":"{id}","kind":"area"}},"geometry":{{"type":"Polygon","coordinates":[{}]}}}}"#,
        rs.join(",")
    )
}

/// An area: a MultiPolygon of the given polygons.
fn multi(id: &str, parts: &[Vec<Vec<(f64, f64)>>]) -> String {
    let ps: Vec<String> = parts
        .iter()
        .map(|p| {
            let rs: Vec<String> = p.iter().map(|r| ring(r)).collect();
            format!("[{}]", rs.join(","))
        })
        .collect();
    format!(
        r#"{{"type":"Feature","properties":{{"id":"{id}","kind":"area"}},"geometry":{{"type":"MultiPolygon","coordinates":[{}]}}}}"#,
        ps.join(",")
    )
}

/// A track at 15 kn with a rectangle 5 nm each way, from t = 0.
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

/// The conflicts as (id, id, t_start, t_end).
fn pairs(a: &Analysis) -> Vec<(String, String, f64, f64)> {
    a.conflicts
        .iter()
        .map(|c| {
            let id = |k: u32| a.scenario.features[k as usize].id.clone();
            (id(c.a), id(c.b), c.t_start, c.t_end)
        })
        .collect()
}

fn closed(r: &[Merc]) -> LineString<f64> {
    let mut v: Vec<(f64, f64)> = r.iter().map(|p| (p[0], p[1])).collect();
    v.push(v[0]);
    LineString::from(v)
}

/// The area objects of feature `owner` as `geo` polygons with their holes.
fn area_polygons(objs: &[Object], owner: u32) -> Vec<Polygon<f64>> {
    objs.iter()
        .filter(|o| o.owner == owner && !o.is_moving())
        .map(|o| {
            Polygon::new(
                closed(&o.sweep),
                o.holes().iter().map(|h| closed(h)).collect(),
            )
        })
        .collect()
}

/// The sampled truth: the first and last of `n + 1` instants of the track's life at which
/// its rectangle meets the area, and the sampling step.
fn sampled(a: &Analysis, track_id: &str, area_id: &str, n: usize) -> (Option<(f64, f64)>, f64) {
    let objs = objects(&a.scenario);
    let find = |id: &str| {
        a.scenario
            .features
            .iter()
            .position(|f| f.id == id)
            .expect("feature") as u32
    };
    let legs: Vec<&Object> = objs
        .iter()
        .filter(|o| o.owner == find(track_id) && o.copy == 0)
        .collect();
    let area = area_polygons(&objs, find(area_id));
    let (t0, t1) = (legs[0].t0, legs[legs.len() - 1].t1);
    let step = (t1 - t0) / n as f64;
    let mut seen: Option<(f64, f64)> = None;
    let mut v = Vec::new();
    for k in 0..=n {
        let t = t0 + step * k as f64;
        let leg = legs
            .iter()
            .find(|l| t >= l.t0 && t <= l.t1)
            .expect("a leg at t");
        leg.vertices_at(t, &mut v);
        let rect = Polygon::new(closed(&v), vec![]);
        if area.iter().any(|p| p.intersects(&rect)) {
            seen = Some(seen.map_or((t, t), |(s, _)| (s, t)));
        }
    }
    (seen, step)
}

/// The reported window contains every sampled meeting and ends within the tolerance of
/// the sampled ones (plus one sampling step).
fn agrees(a: &Analysis, track_id: &str, area_id: &str) {
    let (truth, step) = sampled(a, track_id, area_id, 20_000);
    let got = pairs(a)
        .into_iter()
        .find(|(x, y, _, _)| (x == track_id && y == area_id) || (x == area_id && y == track_id));
    match (truth, got) {
        (None, None) => {}
        (Some((s, e)), Some((_, _, ts, te))) => {
            assert!(
                ts <= s && te >= e,
                "{track_id}/{area_id}: [{ts}, {te}] misses [{s}, {e}]"
            );
            let slack = 2.0 * TOL + step;
            assert!(
                s - ts <= slack && te - e <= slack,
                "{track_id}/{area_id}: [{ts}, {te}] is wider than [{s}, {e}]"
            );
        }
        (t, g) => panic!("{track_id}/{area_id}: truth {t:?}, reported {g:?}"),
    }
}

/// The donut: a 4° square with a 2° square hole in its middle.
fn donut(id: &str, at: f64) -> String {
    polygon(
        id,
        &[
            square((at, at + 4.0), (-2.0, 2.0)),
            square((at + 1.0, at + 3.0), (-1.0, 1.0)),
        ],
    )
}

/// An area inside a donut's hole does not overlap the donut; one
/// across the hole's edge does, and so does one on the ring.
#[test]
fn an_area_in_the_hole_is_not_in_the_donut() {
    let a = run(&[
        donut("donut", 0.0),
        polygon("in_hole", &[square((1.6, 2.4), (-0.4, 0.4))]),
        polygon("across_edge", &[square((2.6, 3.5), (-0.5, 0.5))]),
        polygon("on_ring", &[square((0.2, 0.8), (-0.5, 0.5))]),
        // touching the hole's boundary from inside: the boundary is part of the area
        polygon("touching", &[square((1.0, 1.5), (-0.5, 0.5))]),
    ]);
    let got: Vec<(String, String)> = pairs(&a).into_iter().map(|(x, y, _, _)| (x, y)).collect();
    for other in ["across_edge", "on_ring", "touching"] {
        assert!(
            got.contains(&("donut".into(), other.into())),
            "{other}: {got:?}"
        );
    }
    assert!(
        !got.iter().any(|(x, y)| x == "in_hole" || y == "in_hole"),
        "{got:?}"
    );
    // the region of donut ∩ across_edge is the part outside the hole: lon 3 to 3.5
    let c = a
        .conflicts
        .iter()
        .find(|c| a.scenario.features[c.b as usize].id == "across_edge")
        .expect("a conflict");
    let lon = |x: f64| x.to_degrees();
    for r in &c.rings {
        for p in r {
            // (to within the printed 7 decimals: geo computes the union on a grid)
            assert!(lon(p[0]) >= 3.0 - 1e-7, "{r:?}");
        }
    }
}

/// Tracks through a donut: one inside the hole all its life (no conflict), one leaving
/// the hole, one crossing ring, hole and ring; times as the sampled truth has them.
#[test]
fn tracks_and_holes_meet_when_the_truth_says() {
    let a = run(&[
        donut("donut", 0.0),
        track("inside", (1.5, 0.0), (2.5, 0.0)),
        track("leaving", (2.0, 0.3), (3.5, 0.3)),
        track("through", (-1.0, 0.2), (5.0, -0.2)),
        track("above", (1.5, 1.5), (2.5, 1.5)),
    ]);
    for t in ["inside", "leaving", "through", "above"] {
        agrees(&a, t, "donut");
    }
    let got: Vec<String> = pairs(&a).into_iter().map(|(_, y, _, _)| y).collect();
    assert!(!got.contains(&"inside".to_owned()), "{got:?}");
    assert!(got.contains(&"leaving".to_owned()) && got.contains(&"above".to_owned()));
}

/// A MultiPolygon is the union of its parts: a track over both parts conflicts once, from
/// entering the first to leaving the second; a part's hole is honoured.
#[test]
fn a_multipolygon_is_its_parts() {
    let a = run(&[
        multi(
            "islands",
            &[
                vec![square((10.0, 11.0), (0.0, 1.0))],
                vec![
                    square((12.0, 16.0), (-2.0, 2.0)),
                    square((13.0, 15.0), (-1.0, 1.0)),
                ],
            ],
        ),
        track("over", (9.5, 0.5), (12.5, 0.5)),
        track("in_the_hole", (13.5, 0.0), (14.5, 0.0)),
        polygon("between", &[square((11.2, 11.8), (-1.0, -0.5))]),
    ]);
    agrees(&a, "over", "islands");
    agrees(&a, "in_the_hole", "islands");
    let got: Vec<(String, String)> = pairs(&a).into_iter().map(|(x, y, _, _)| (x, y)).collect();
    assert_eq!(got, vec![("islands".to_owned(), "over".to_owned())]);
}

/// A donut across the antimeridian, its hole written from the other side (starting at
/// −179): the hole is laid out with its exterior, and holds a box without meeting it.
#[test]
fn a_hole_across_the_antimeridian() {
    let hole = vec![(-179.0, -1.0), (-179.0, 1.0), (179.0, 1.0), (179.0, -1.0)];
    let a = run(&[
        polygon("donut", &[square((178.0, 182.0), (-2.0, 2.0)), hole]),
        polygon("in_hole", &[square((179.5, -179.5), (-0.5, 0.5))]),
        polygon("east", &[square((-178.5, -177.5), (-0.5, 0.5))]),
        track("through", (177.0, 0.0), (-177.0, 0.0)),
    ]);
    let got: Vec<(String, String)> = pairs(&a).into_iter().map(|(x, y, _, _)| (x, y)).collect();
    assert!(got.contains(&("donut".into(), "east".into())), "{got:?}");
    assert!(
        !got.contains(&("donut".into(), "in_hole".into())),
        "{got:?}"
    );
    assert!(got.contains(&("donut".into(), "through".into())), "{got:?}");
}
