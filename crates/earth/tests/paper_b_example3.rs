//! Paper B Section VI.C, Example 3 (Tables 3 and 4) on the paper's sphere model.

use polyguard_earth::conflict::{pipeline, stage3, Object};
use polyguard_earth::sphere::{track_legs, Leg, LonLat, RectDims};

const SQUARE10: RectDims = RectDims {
    front: 10.0,
    back: 10.0,
    side: 10.0,
};
/// The sphere model's published window (the paper's Example 3, two decimals), to be
/// reproduced within ±0.002 h.
const EXAMPLE3_TOL_H: f64 = 0.002;

fn blue() -> Leg {
    track_legs(
        &[
            LonLat::from_degrees(39.0, 29.0),
            LonLat::from_degrees(41.0, 31.0),
        ],
        15.0,
        0.0,
        SQUARE10,
    )
    .remove(0)
}
fn green() -> Leg {
    track_legs(
        &[
            LonLat::from_degrees(39.0, 30.0),
            LonLat::from_degrees(41.0, 30.0),
        ],
        15.0,
        0.0,
        SQUARE10,
    )
    .remove(0)
}

#[test]
fn track_ends() {
    assert!((blue().t1 - 10.59).abs() < 0.005, "{}", blue().t1);
    assert!((green().t1 - 6.93).abs() < 0.005, "{}", green().t1);
}

#[test]
fn pipeline_window() {
    let objs = vec![Object::leg(0, blue()), Object::leg(1, green())];
    let (c, stats) = pipeline::run(&objs, pipeline::Options::default());
    assert_eq!(stats.candidate_pairs, 1);
    assert_eq!(c.len(), 1);
    eprintln!("{:?} {:?}", (c[0].t_start, c[0].t_end), c[0].paper);
    assert!(
        (c[0].t_start - 4.1411).abs() < EXAMPLE3_TOL_H,
        "{}",
        c[0].t_start
    );
    assert!(
        (c[0].t_end - 4.6024).abs() < EXAMPLE3_TOL_H,
        "{}",
        c[0].t_end
    );
}

/// Paper B eq 7 as printed: the hull of the rectangle at `t0` and at `tf`.
fn paper_hull(l: &Leg) -> Vec<[f64; 2]> {
    let mut pts: Vec<[f64; 2]> = l.merc_vertices_at(l.t0).to_vec();
    pts.extend_from_slice(&l.merc_vertices_at(l.t1));
    polyguard_earth::conflict::geom::convex_hull(&pts)
}

#[test]
fn projection_windows() {
    let (b, g) = (blue(), green());
    let region = polyguard_earth::conflict::geom::clip_convex(&paper_hull(&b), &paper_hull(&g));
    let wb = stage3::paper_window(&b, &region).expect("blue window");
    let wg = stage3::paper_window(&g, &region).expect("green window");
    eprintln!("blue {wb:?} green {wg:?}");
    assert!((wb.0 - 3.17).abs() < 0.005, "{wb:?}");
    assert!((wg.0 - 1.33).abs() < 0.005, "{wg:?}");
    // the conservative windows contain the paper's
    let cb = stage3::conservative_window(&b, &region).unwrap();
    assert!(cb.0 <= wb.0 && cb.1 >= wb.1);
}

/// The shipped example through the `conflicts` command's code path.
#[test]
fn shipped_example_file() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/example3.geojson"
    ))
    .unwrap();
    let a = polyguard_earth::analysis::analyse(
        &text,
        polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H,
    )
    .unwrap();
    assert!(a.errors.is_empty());
    let v: serde_json::Value = serde_json::from_str(&a.answer).unwrap();
    let c = &v["conflicts"][0];
    assert_eq!(c["a"], "blue");
    assert_eq!(c["b"], "green");
    let (s, e) = (c["t_start"].as_f64().unwrap(), c["t_end"].as_f64().unwrap());
    assert!(
        (s - 4.1411).abs() < EXAMPLE3_TOL_H && (e - 4.6024).abs() < EXAMPLE3_TOL_H,
        "{s} {e}"
    );
    assert_eq!(v["stats"]["objects"], 2);
    assert_eq!(v["stats"]["candidate_pairs"], 1);
}
