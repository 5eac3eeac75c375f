//! Paper B on the WGS84 ellipsoid (`conflicts --geodesy wgs84`): Example 3's printed
//! numbers, the certified bounds stage 3 and stage 4 rely on (checked on samples of
//! ellipsoidal legs), and the window against a sampled truth built another way (the
//! rectangle's vertices by successive rhumb steps instead of the closed forms).

use polyguard_earth::analysis::analyse_with;
use polyguard_earth::conflict::{geom, pipeline, Object};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::sphere::{track_legs_in, Leg, LonLat, Merc, RectDims};

const SQUARE10: RectDims = RectDims {
    front: 10.0,
    back: 10.0,
    side: 10.0,
};

/// The tolerance on the paper's printed numbers (they have two decimals, and the paper's
/// own model is not the ellipsoid).
const TOL_H: f64 = 0.006;

fn leg(geo: Geodesy, a: (f64, f64), b: (f64, f64), dims: RectDims) -> Leg {
    track_legs_in(
        geo,
        &[
            LonLat::from_degrees(a.0, a.1),
            LonLat::from_degrees(b.0, b.1),
        ],
        15.0,
        0.0,
        dims,
    )
    .remove(0)
}

fn blue(geo: Geodesy) -> Leg {
    leg(geo, (39.0, 29.0), (41.0, 31.0), SQUARE10)
}

fn green(geo: Geodesy) -> Leg {
    leg(geo, (39.0, 30.0), (41.0, 30.0), SQUARE10)
}

fn near(x: f64, want: f64) -> bool {
    (x - want).abs() <= TOL_H
}

/// Section VI.C: "3.16 to 10.58 hours" on the blue track, "1.33 to 6.95" on the green,
/// conflict "between 4.12 hours and 4.63 hours". On the ellipsoid the window, the
/// projection windows' starts and the tracks' ends (10.58 h and 6.95 h, where the
/// paper's projection windows end) come within 0.006 h of them; on the sphere the
/// tracks' ends do not.
#[test]
fn example3_reproduces_the_printed_numbers_on_wgs84() {
    let (b, g) = (blue(Geodesy::Wgs84), green(Geodesy::Wgs84));
    assert!(near(b.t1, 10.58), "{}", b.t1);
    assert!(near(g.t1, 6.95), "{}", g.t1);
    let objs = vec![Object::leg(0, b), Object::leg(1, g)];
    let (c, _) = pipeline::run(&objs, pipeline::Options::default());
    assert_eq!(c.len(), 1);
    assert!(near(c[0].t_start, 4.12), "{}", c[0].t_start);
    assert!(near(c[0].t_end, 4.63), "{}", c[0].t_end);
    let [pb, pg] = c[0].paper;
    let (pb, pg) = (pb.expect("blue's window"), pg.expect("green's window"));
    assert!(near(pb.0, 3.16), "{pb:?}");
    assert!(near(pg.0, 1.33), "{pg:?}");
    // the model matters: the sphere's tracks end outside the tolerance
    assert!(!near(blue(Geodesy::Sphere).t1, 10.58) && !near(green(Geodesy::Sphere).t1, 6.95));
}

/// The same through the scenario file and `analyse_with` (what `conflicts --geodesy
/// wgs84` runs): the window, the region in degrees, and the model named in the stats.
#[test]
fn example3_file_on_wgs84() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/example3.geojson"
    ))
    .expect("examples/example3.geojson");
    let a = analyse_with(&text, 1.0 / 3600.0, true, Geodesy::Wgs84, &mut ()).expect("reads");
    let v: serde_json::Value = serde_json::from_str(&a.answer).expect("JSON");
    let c = &v["conflicts"][0];
    assert!(near(c["t_start"].as_f64().unwrap_or(0.0), 4.12), "{c}");
    assert!(near(c["t_end"].as_f64().unwrap_or(0.0), 4.63), "{c}");
    assert_eq!(v["stats"]["geodesy"], "wgs84");
    // the region lies around 40° E 30° N, as on the sphere
    let ring = &c["region"]["coordinates"][0];
    for p in ring.as_array().expect("ring") {
        let (lon, lat) = (p[0].as_f64().unwrap_or(0.0), p[1].as_f64().unwrap_or(0.0));
        assert!(
            (39.5..40.5).contains(&lon) && (29.8..30.2).contains(&lat),
            "{p}"
        );
    }
    let s = analyse_with(&text, 1.0 / 3600.0, true, Geodesy::Sphere, &mut ()).expect("reads");
    let v: serde_json::Value = serde_json::from_str(&s.answer).expect("JSON");
    assert_eq!(v["stats"]["geodesy"], "sphere");
    assert!(!near(
        v["conflicts"][0]["t_start"].as_f64().unwrap_or(0.0),
        4.12
    ));
}

/// Legs on the ellipsoid where the bounds are tested: mid-latitudes, across the equator,
/// near 80°, due east, due south, long and short rectangles.
fn legs() -> Vec<Leg> {
    let g = Geodesy::Wgs84;
    let d = |f: f64, b: f64, s: f64| RectDims {
        front: f,
        back: b,
        side: s,
    };
    vec![
        leg(g, (-40.0, 2.0), (-39.0, 28.0), d(20.0, 20.0, 20.0)),
        leg(g, (-40.0, -1.0), (-39.0, 1.5), d(20.0, 15.0, 30.0)),
        leg(g, (10.0, 78.0), (30.0, 80.5), d(5.0, 30.0, 8.0)),
        leg(g, (10.0, -45.0), (14.0, -45.0), d(10.0, 10.0, 10.0)),
        leg(g, (120.0, 60.0), (120.0, 20.0), d(40.0, 1.0, 2.0)),
        leg(g, (-170.0, 33.0), (-169.9, 33.05), d(0.5, 0.5, 0.5)),
    ]
}

fn sample_times(l: &Leg, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|i| l.t0 + (l.t1 - l.t0) * i as f64 / n as f64)
        .collect()
}

fn dist(a: Merc, b: Merc) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Stage 4's bound: no vertex moves faster in the Mercator plane than
/// `merc_speed_bound`, and none faster relative to the reference point than
/// `deformation_speed_bound`.
#[test]
fn speed_bounds_hold_on_wgs84_legs() {
    for l in legs() {
        let (v, w) = (l.merc_speed_bound(), l.deformation_speed_bound());
        let ts = sample_times(&l, 400);
        for p in ts.windows(2) {
            let (a, b) = (l.merc_vertices_at(p[0]), l.merc_vertices_at(p[1]));
            let (ca, cb) = (l.reference_merc_at(p[0]), l.reference_merc_at(p[1]));
            let h = p[1] - p[0];
            for k in 0..4 {
                let slack = 1e-13;
                assert!(dist(a[k], b[k]) <= v * h + slack, "{l:?}: vertex {k}");
                let rel = [
                    b[k][0] - cb[0] - (a[k][0] - ca[0]),
                    b[k][1] - cb[1] - (a[k][1] - ca[1]),
                ];
                assert!(
                    rel[0].hypot(rel[1]) <= w * h + slack,
                    "{l:?}: vertex {k} deforms"
                );
            }
        }
    }
}

/// Stage 4's envelope: the reference point's Mercator velocity is `σ·e` with `σ` within
/// `reference_velocity_envelope`'s range (finite differences, whose error is far below
/// the check's 10⁻⁶).
#[test]
fn reference_velocity_stays_in_its_envelope_on_wgs84_legs() {
    for l in legs() {
        let (e, lo, hi) = l.reference_velocity_envelope();
        let n = e[0].hypot(e[1]);
        let ts = sample_times(&l, 200);
        for p in ts.windows(2) {
            let (a, b) = (l.reference_merc_at(p[0]), l.reference_merc_at(p[1]));
            let v = dist(a, b) / (p[1] - p[0]);
            let sigma = v / n;
            assert!(
                sigma >= lo * (1.0 - 1e-6) && sigma <= hi * (1.0 + 1e-6),
                "{l:?}: {sigma} not in [{lo}, {hi}]"
            );
        }
    }
}

/// Stage 3's offset boxes contain every vertex's offset from the reference point.
#[test]
fn offset_boxes_contain_sampled_offsets_on_wgs84_legs() {
    for l in legs() {
        let boxes = l.offset_boxes();
        for t in sample_times(&l, 300) {
            let c = l.reference_merc_at(t);
            for (k, v) in l.merc_vertices_at(t).iter().enumerate() {
                let (dx, dy) = (v[0] - c[0], v[1] - c[1]);
                let b = boxes[k];
                let slack = 1e-15;
                assert!(
                    dx >= b[0] - slack && dx <= b[1] + slack,
                    "{l:?}: x {k} {dx} {b:?}"
                );
                assert!(
                    dy >= b[2] - slack && dy <= b[3] + slack,
                    "{l:?}: y {k} {dy} {b:?}"
                );
            }
        }
    }
}

/// The closed forms (`merc_vertices_at`) are the rectangle built step by step with rhumb
/// destinations on the ellipsoid (`vertices_at`), projected.
#[test]
fn closed_forms_are_the_rhumb_steps_on_wgs84() {
    for l in legs() {
        for t in sample_times(&l, 50) {
            let a = l.merc_vertices_at(t);
            let b = l.vertices_at(t).map(|p| Geodesy::Wgs84.mercator(p));
            for k in 0..4 {
                assert!(
                    dist(a[k], b[k]) < 1e-12,
                    "{l:?} t {t}: {:?} vs {:?}",
                    a[k],
                    b[k]
                );
            }
        }
    }
}

/// Example 3's window contains every instant at which the rectangles, built step by step
/// on the ellipsoid and sampled every 0.36 s, meet; and it is no wider than the sampling
/// and the tolerance (1 s) allow.
#[test]
fn example3_window_contains_the_sampled_meetings() {
    let (b, g) = (blue(Geodesy::Wgs84), green(Geodesy::Wgs84));
    let objs = vec![Object::leg(0, b.clone()), Object::leg(1, g.clone())];
    let (c, _) = pipeline::run(&objs, pipeline::Options::default());
    let (s, e) = (c[0].t_start, c[0].t_end);
    let geo = Geodesy::Wgs84;
    let ring = |l: &Leg, t: f64| l.vertices_at(t).map(|p| geo.mercator(p)).to_vec();
    let step = 1e-4;
    let met: Vec<f64> = (0..10_000)
        .map(|i| 3.9 + i as f64 * step)
        .filter(|&t| geom::rings_intersect(&ring(&b, t), &ring(&g, t)))
        .collect();
    let (first, last) = (met[0], met[met.len() - 1]);
    assert!(
        s <= first && last <= e,
        "[{s}, {e}] vs sampled [{first}, {last}]"
    );
    let tol = 1.0 / 3600.0;
    assert!(
        first - s <= step + tol && e - last <= step + tol,
        "[{s}, {e}] vs [{first}, {last}]"
    );
}
