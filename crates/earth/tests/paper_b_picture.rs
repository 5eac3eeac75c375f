//! The `--svg` picture: what a reader of paper B's Figs 2–5 looks for is there, every
//! feature stays visible and named where there is room, and no label covers another.
//! Rendered and looked at by hand too (rsvg-convert).

use polyguard_earth::analysis::{analyse, Analysis};
use polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H as TOL;
use polyguard_earth::generate::{generate, Mix};
use polyguard_earth::picture::{draw, svg, Options, Picture};
use polyguard_earth::scenario::to_geojson;

fn example3() -> polyguard_earth::analysis::Analysis {
    let text = include_str!("../../../examples/example3.geojson");
    analyse(text, TOL).expect("a collection")
}

/// Example 3: the ids, each track's start and end times, the conflict's window beside its
/// region, a graticule labelled in degrees, and a legend; the detail adds stage 1's boxes
/// and stage 3's projection lines, which the plain picture leaves out.
#[test]
fn the_picture_names_what_it_draws() {
    let a = example3();
    let plain = svg(&a.scenario, &a.objects, &a.conflicts, Options::default());
    for want in [
        ">blue 0.00 h<",
        ">green 0.00 h<",
        ">10.59 h<",
        ">6.93 h<",
        ">blue × green: 4.14 h to 4.60 h<",
        ">40°E<",
        ">30°N<",
        ">track, direction of travel<",
        ">conflict region, window (h)<",
        "marker-end=\"url(#arrow)\"",
        ">2 features, 1 conflict (Mercator plane)<",
    ] {
        assert!(plain.contains(want), "{want} is missing");
    }
    assert!(!plain.contains("bounding box (eqs 3–6)"));
    let detail = svg(
        &a.scenario,
        &a.objects,
        &a.conflicts,
        Options { detail: true },
    );
    assert!(detail.contains(">bounding box (eqs 3–6)<"));
    assert!(detail.contains(">projection on a track (eq 10)<"));
    // one projection line per region vertex and track: more lines than the plain picture
    let lines = |s: &str| s.matches("<line ").count();
    assert!(
        lines(&detail) >= lines(&plain) + 4,
        "{} against {}",
        lines(&detail),
        lines(&plain)
    );
    // every element opened is closed (the picture is one well-formed document)
    for tag in ["svg", "text", "title", "path", "line", "marker", "defs"] {
        let open =
            plain.matches(&format!("<{tag} ")).count() + plain.matches(&format!("<{tag}>")).count();
        let closed = plain.matches(&format!("</{tag}>")).count();
        let selfclosed = plain
            .split(&format!("<{tag} "))
            .skip(1)
            .filter(|rest| rest.find('>').is_some_and(|k| rest[..k].ends_with('/')))
            .count();
        assert_eq!(open, closed + selfclosed, "<{tag}>");
    }
}

/// The picture of scenario text.
fn picture(text: &str) -> (Analysis, Picture) {
    let a = analyse(text, TOL).expect("a collection");
    assert!(a.errors.is_empty(), "{:?}", a.errors);
    let p = draw(&a.scenario, &a.objects, &a.conflicts, Options::default());
    (a, p)
}

/// No two labels overlap, and each lies inside its panel's plot, which is one of the
/// picture's panels; no two panels overlap.
#[track_caller]
fn labels_are_clear(p: &Picture) {
    let overlap =
        |a: [f64; 4], b: [f64; 4]| a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
    for (i, a) in p.labels.iter().enumerate() {
        let (b, f) = (a.bbox, a.frame);
        assert!(p.panels.contains(&f), "{f:?}");
        assert!(
            b[0] >= f[0] && b[1] >= f[1] && b[2] <= f[2] && b[3] <= f[3],
            "{b:?} outside {f:?}"
        );
        for c in &p.labels[i + 1..] {
            assert!(!overlap(b, c.bbox), "{b:?} and {:?}", c.bbox);
        }
    }
    for (i, a) in p.panels.iter().enumerate() {
        for b in &p.panels[i + 1..] {
            assert!(!overlap(*a, *b), "{a:?} and {b:?}");
        }
    }
}

/// Two features 150° of longitude apart: each drawn in a panel of its own at one scale
/// (at least 100 pixels across, not a speck), named, the band between them named.
#[test]
fn features_far_apart_are_drawn_large_in_panels_of_their_own() {
    let text = r#"{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"id": "west", "kind": "area"},
  "geometry": {"type": "Polygon", "coordinates": [[[-75, 10], [-74, 10], [-74, 11], [-75, 11], [-75, 10]]]}},
 {"type": "Feature", "properties": {"id": "east", "kind": "track", "speed_kn": 15, "front_nm": 10, "back_nm": 10, "side_nm": 10},
  "geometry": {"type": "LineString", "coordinates": [[75, 10.5], [76, 10.5]]}}
]}"#;
    let (_, p) = picture(text);
    assert_eq!(p.panels.len(), 2);
    for f in &p.panels {
        assert!(f[2] - f[0] >= 150.0 && f[3] - f[1] >= 150.0, "{f:?}");
    }
    assert_eq!(p.label_counts[0], (2, 2), "both features are named");
    assert!(p.svg.contains("≈ 149° of longitude left out"));
    assert!(p.svg.contains(">west<") && p.svg.contains(">east 0.00 h<"));
    labels_are_clear(&p);
}

/// 200 generated features (`polyguard generate --objects 200`): every one named, no
/// label over another, all in one panel.
#[test]
fn two_hundred_generated_features_are_all_named() {
    let mut s = 7u64;
    let mut bits = move || {
        s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let sc = generate(200, Mix::Mixed, false, &mut bits);
    let (a, p) = picture(&to_geojson(&sc).to_string());
    assert_eq!(a.scenario.features.len(), 200);
    assert_eq!(p.panels.len(), 1);
    assert_eq!(p.label_counts[0], (200, 200), "every feature is named");
    labels_are_clear(&p);
    // too many conflicts to label: their windows are in the tooltips, and the legend says so
    assert!(a.conflicts.len() > 60);
    assert!(p
        .svg
        .contains(&format!("windows of the {} conflicts", a.conflicts.len())));
}

/// 1,000 generated features: the labels that fit are placed clear of each other, and the
/// legend says how many names were left out.
#[test]
fn a_crowd_is_named_where_there_is_room_and_the_rest_counted() {
    let mut s = 11u64;
    let mut bits = move || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        s
    };
    let sc = generate(1000, Mix::Mixed, false, &mut bits);
    let (_, p) = picture(&to_geojson(&sc).to_string());
    let (asked, placed) = p.label_counts[0];
    assert_eq!(asked, 1000);
    assert!(placed > 300 && placed < 1000, "{placed}");
    let note = format!("{} of 1000 feature names left out", 1000 - placed);
    assert!(p.svg.contains(&note), "{note}");
    labels_are_clear(&p);
}

/// Across the antimeridian: one panel, the objects drawn side by side (a box from 179°E
/// to 179°W is 2° wide, not 358°), every label clear.
#[test]
fn across_the_antimeridian_objects_are_drawn_side_by_side() {
    let text = r#"{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"id": "dateline-box", "kind": "area"},
  "geometry": {"type": "Polygon", "coordinates": [[[179, -1], [-179, -1], [-179, 1], [179, 1], [179, -1]]]}},
 {"type": "Feature", "properties": {"id": "eastbound", "kind": "track", "speed_kn": 20, "front_nm": 10, "back_nm": 10, "side_nm": 10},
  "geometry": {"type": "LineString", "coordinates": [[178, 0.2], [-178, 0.5]]}},
 {"type": "Feature", "properties": {"id": "westbound", "kind": "track", "speed_kn": 20, "front_nm": 10, "back_nm": 10, "side_nm": 10},
  "geometry": {"type": "LineString", "coordinates": [[-177.5, -0.5], [179.5, 0.3], [177.5, 0.0]]}}
]}"#;
    let (a, p) = picture(text);
    assert_eq!(a.conflicts.len(), 3);
    assert_eq!(p.panels.len(), 1);
    assert!(p.svg.contains(">180°<") && p.svg.contains(">179°W<"));
    assert_eq!(p.label_counts[0], (3, 3));
    // a leg's end that is the next leg's start is timed once
    assert_eq!(p.svg.matches(">9.32 h<").count(), 1);
    labels_are_clear(&p);
}
