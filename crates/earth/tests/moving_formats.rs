//! The moving-features readers (docs/moving-features.md, "Formats"): every error kind
//! with its location, the forms MF-JSON, GeoJSON and CSV take, real exports of the
//! `traffic` library and MovingPandas, round trips of random trajectories and areas
//! through text, and garbage that must never panic.

use polyguard_earth::moving::error::{ErrorKind, MovingError, WarningKind};
use polyguard_earth::moving::fixes_csv::{self, CsvRead};
use polyguard_earth::moving::mfjson::{self, Item, MfRead, M_PER_FT};
use polyguard_earth::moving::model::{Area, Fix, Keyframe, Rings, Shape, Trajectory};
use polyguard_earth::moving::time::{self, Round};
use proptest::prelude::*;

fn mf(text: &str) -> MfRead {
    mfjson::read(text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn only_error(text: &str) -> MovingError {
    let r = mf(text);
    assert_eq!(r.items.len(), 1, "{r:?}");
    match &r.items[0] {
        Err(e) => e.clone(),
        Ok(item) => panic!("read {item:?} from\n{text}"),
    }
}

fn only_item(text: &str) -> Item {
    let r = mf(text);
    assert_eq!(r.items.len(), 1, "{r:?}");
    r.items[0].clone().unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// A MovingPoint feature with `extra` members inside `temporalGeometry` and the given
/// datetimes and coordinates.
fn moving_point(times: &str, coords: &str, extra: &str) -> String {
    format!(
        r#"{{"type": "Feature", "id": "AFR12",
 "properties": {{"callsign": "AFR12"}},
 "temporalGeometry": {{"type": "MovingPoint",
  "datetimes": {times},
  "coordinates": {coords}{extra}}}}}"#
    )
}

const TIMES3: &str = r#"["2021-10-07T13:00:25Z", "2021-10-07T13:00:26Z", "2021-10-07T13:00:27Z"]"#;
const COORDS3: &str = "[[2.0, 48.0], [2.01, 48.0], [2.02, 48.01]]";

#[test]
fn a_moving_point_reads_as_a_mover() {
    let Item::Mover(t) = only_item(&moving_point(
        TIMES3,
        COORDS3,
        r#", "interpolation": "Linear""#,
    )) else {
        panic!("not a mover")
    };
    assert_eq!(t.id, "AFR12");
    assert_eq!(t.callsign.as_deref(), Some("AFR12"));
    let ts: Vec<f64> = t.fixes.iter().map(|f| f.t).collect();
    assert_eq!(ts, [1_633_611_625.0, 1_633_611_626.0, 1_633_611_627.0]);
    assert_eq!(t.fixes[2].lon, 2.02);
    assert!(t.fixes.iter().all(|f| f.alt_ft.is_none()));
}

#[test]
fn heights_in_positions_are_metres_and_altitude_properties_take_their_unit() {
    let coords = "[[2.0, 48.0, 304.8], [2.01, 48.0, 0], [2.02, 48.01, 3048]]";
    let Item::Mover(t) = only_item(&moving_point(TIMES3, coords, "")) else {
        panic!("not a mover")
    };
    let alts: Vec<Option<f64>> = t.fixes.iter().map(|f| f.alt_ft).collect();
    assert_eq!(
        alts,
        [Some(304.8 / M_PER_FT), Some(0.0), Some(3048.0 / M_PER_FT)]
    );
    assert!((alts[0].expect("alt") - 1000.0).abs() <= 1000.0 * 4.0 * f64::EPSILON);

    for (form, factor) in [
        ("\"[ft_i]\"", 1.0),
        ("\"FOT\"", 1.0),
        ("\"MTR\"", 1.0 / M_PER_FT),
    ] {
        let text = moving_point(TIMES3, COORDS3, "").replacen(
            r#""temporalGeometry""#,
            &format!(
                r#""temporalProperties": [{{"datetimes": {TIMES3},
  "altitude": {{"type": "Measure", "form": {form}, "values": [1000, null, NaN]}}}}],
 "temporalGeometry""#
            ),
            1,
        );
        let Item::Mover(t) = only_item(&text) else {
            panic!("not a mover")
        };
        let alts: Vec<Option<f64>> = t.fixes.iter().map(|f| f.alt_ft).collect();
        assert_eq!(alts, [Some(1000.0 * factor), None, None], "{form}");
    }
}

#[test]
fn movingpandas_output_reads_with_one_warning_for_naive_times() {
    // What Trajectory.to_mf_json() writes (movingpandas io.gdf_to_mf_json): the id in
    // properties.traj_id, date-times as "%Y-%m-%d %H:%M:%S" without an offset, an
    // altitude temporal column without a unit.
    let text = r#"{"type": "FeatureCollection", "features": [{"type": "Feature",
 "properties": {"traj_id": 7, "icao24": "4ca1b2", "altitude": 1225},
 "temporalGeometry": {"type": "MovingPoint",
   "coordinates": [[2.61, 48.99], [2.62, 48.99]],
   "datetimes": ["2021-10-07 13:27:47", "2021-10-07 13:27:48"]},
 "temporalProperties": [{"datetimes": ["2021-10-07 13:27:47", "2021-10-07 13:27:48"],
   "altitude": {"values": [1225.0, NaN]}}]}]}"#;
    let r = mf(text);
    let Ok(Item::Mover(t)) = &r.items[0] else {
        panic!("{r:?}")
    };
    assert_eq!(t.id, "7");
    assert_eq!(t.fixes[0].t, 1_633_613_267.0);
    assert_eq!(t.fixes[0].alt_ft, Some(1225.0));
    assert_eq!(t.fixes[1].alt_ft, None);
    let kinds: Vec<WarningKind> = r.warnings.iter().map(|w| w.kind).collect();
    assert_eq!(
        kinds,
        [WarningKind::NoOffset, WarningKind::UnitAssumed],
        "{r:?}"
    );
}

#[test]
fn the_trajectory_form_reads_as_a_mover() {
    let text = r#"{"type": "Feature", "geometry": {"type": "LineString",
 "coordinates": [[2.0, 48.0], [2.1, 48.1]]},
 "properties": {"id": "x", "datetimes": [1633611625, "2021-10-07T13:00:26.5+00:00"]}}"#;
    let Item::Mover(t) = only_item(text) else {
        panic!("not a mover")
    };
    assert_eq!(t.id, "x");
    assert_eq!(t.fixes[1].t, 1_633_611_626.5);
}

#[test]
fn static_and_keyframed_areas() {
    let text = r#"{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "CTR", "properties": {"name": "Paris CTR", "floor_ft": 0, "ceiling_ft": 3500, "UPPERLIMIT": "35"},
  "geometry": {"type": "Polygon", "coordinates": [
    [[2, 48], [3, 48], [3, 49], [2, 49], [2, 48]],
    [[2.4, 48.4], [2.6, 48.4], [2.5, 48.6], [2.4, 48.4]]]}},
 {"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [
    [[[0, 0], [1, 0], [1, 1], [0, 0]]], [[[5, 5], [6, 5], [6, 6], [5, 5]]]]}},
 {"type": "Feature", "id": "cell", "properties": {"ceiling_ft": 30000},
  "temporalGeometry": {"type": "MovingPolygon", "interpolation": "Linear",
   "datetimes": ["2021-10-07T12:00:00Z", "2021-10-07T12:15:00Z"],
   "coordinates": [[[3, 47], [3.1, 47], [3.1, 47.1], [3, 47]],
                   [[3.2, 47], [3.3, 47], [3.3, 47.1], [3.2, 47]]]}},
 {"type": "Feature", "id": "holed-cell",
  "temporalGeometry": {"type": "MovingPolygon", "interpolation": "Linear",
   "datetimes": [0, 60],
   "coordinates": [[[[0, 0], [4, 0], [4, 4], [0, 0]], [[1, 0.5], [2, 0.5], [2, 1], [1, 0.5]]],
                   [[[1, 0], [5, 0], [5, 4], [1, 0]], [[2, 0.5], [3, 0.5], [3, 1], [2, 0.5]]]]}}
]}"#;
    let r = mf(text);
    let areas: Vec<Area> = r
        .items
        .iter()
        .map(|i| match i {
            Ok(Item::Area(a)) => a.clone(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(areas[0].id, "CTR");
    assert_eq!(areas[0].name.as_deref(), Some("Paris CTR"));
    assert_eq!(
        (areas[0].floor_ft, areas[0].ceiling_ft),
        (Some(0.0), Some(3500.0))
    );
    let Shape::Static(parts) = &areas[0].shape else {
        panic!("static")
    };
    assert_eq!(
        parts[0].outer,
        [[2.0, 48.0], [3.0, 48.0], [3.0, 49.0], [2.0, 49.0]]
    );
    assert_eq!(parts[0].holes.len(), 1);
    assert_eq!(areas[1].id, "1");
    assert!(matches!(&areas[1].shape, Shape::Static(p) if p.len() == 2));
    let Shape::Keyframed(k) = &areas[2].shape else {
        panic!("keyframed")
    };
    assert_eq!((k.len(), k[1].t - k[0].t), (2, 900.0));
    assert_eq!(
        (areas[2].floor_ft, areas[2].ceiling_ft),
        (None, Some(30000.0))
    );
    let Shape::Keyframed(k) = &areas[3].shape else {
        panic!("keyframed")
    };
    assert_eq!(k[1].parts[0].holes[0][0], [2.0, 0.5]);
}

#[test]
fn json_lines_read_feature_by_feature() {
    let good = moving_point(TIMES3, COORDS3, "").replace('\n', " ");
    let text = format!("{good}\n\n{{\"type\": \"Feature\", oops}}\n{good}\n");
    let r = mf(&text);
    assert_eq!(r.items.len(), 3);
    assert!(r.items[0].is_ok() && r.items[2].is_ok());
    let e = r.items[1].clone().expect_err("bad line");
    assert_eq!(
        (e.kind, e.at.line, e.at.feature),
        (ErrorKind::Syntax, Some(3), Some(1))
    );
}

#[test]
fn a_document_that_is_not_json_is_one_error_with_its_line() {
    let e = mfjson::read("{\"type\": \"FeatureCollection\",\n \"features\": [}").expect_err("bad");
    assert_eq!((e.kind, e.at.line), (ErrorKind::Syntax, Some(2)));
    let e = mfjson::read("[1, 2]").expect_err("array");
    assert_eq!(e.kind, ErrorKind::WrongType);
}

/// Each error kind of MF-JSON: the text, the kind, its line, the member.
#[test]
fn every_mfjson_error_names_its_kind_line_and_member() {
    let mp = |t: &str, c: &str, x: &str| moving_point(t, c, x);
    let cases: Vec<(String, ErrorKind, usize, &str)> = vec![
        (mp(TIMES3, "[[2.0, 48.0], [NaN, 48.0], [2.02, 48.01]]", ""), ErrorKind::NotFinite, 5, "temporalGeometry.coordinates[1][0]"),
        (mp(TIMES3, "[[2.0, 48.0], [2.0, 1e999], [2.02, 48.01]]", ""), ErrorKind::NotFinite, 5, "temporalGeometry.coordinates[1][1]"),
        (mp(TIMES3, "[[2.0, 48.0], [2.0, 86], [2.02, 48.01]]", ""), ErrorKind::OutOfRange, 5, "temporalGeometry.coordinates[1][1]"),
        (mp(TIMES3, "[[2.0, 48.0], [181, 48], [2.02, 48.01]]", ""), ErrorKind::OutOfRange, 5, "temporalGeometry.coordinates[1][0]"),
        (mp(r#"["2021-10-07T13:00:25Z", "2021-10-07T13:00:25Z", "2021-10-07T13:00:27Z"]"#, COORDS3, ""), ErrorKind::TimesNotIncreasing, 4, "temporalGeometry.datetimes[1]"),
        (mp(r#"["2021-10-07T13:00:25Z", "2021-10-07T13:00:60Z", "2021-10-07T13:00:27Z"]"#, COORDS3, ""), ErrorKind::BadTime, 4, "temporalGeometry.datetimes[1]"),
        (mp(r#"[1633611625, 1633611626000, 1633611627]"#, COORDS3, ""), ErrorKind::OutOfRange, 4, "temporalGeometry.datetimes[1]"),
        (mp(r#"[1633611625, true, 1633611627]"#, COORDS3, ""), ErrorKind::WrongType, 4, "temporalGeometry.datetimes[1]"),
        (mp(TIMES3, COORDS3, ",\n \"interpolations\": \"Linear\""), ErrorKind::UnknownMember, 6, "temporalGeometry.interpolations"),
        (mp(TIMES3, COORDS3, ",\n \"interpolation\": \"Step\""), ErrorKind::Unsupported, 6, "temporalGeometry.interpolation"),
        (mp(TIMES3, COORDS3, ",\n \"datetimes\": []"), ErrorKind::DuplicateMember, 6, "temporalGeometry.datetimes"),
        (mp(TIMES3, "[[2.0, 48.0], [2.01, 48.0]]", ""), ErrorKind::LengthMismatch, 4, "temporalGeometry.coordinates"),
        (mp(r#"["2021-10-07T13:00:25Z"]"#, "[[2.0, 48.0]]", ""), ErrorKind::TooFewFixes, 5, "temporalGeometry.coordinates"),
        (
            mp(TIMES3, COORDS3, "").replace("MovingPoint", "MovingGeometryCollection"),
            ErrorKind::Unsupported,
            3,
            "temporalGeometry.type",
        ),
        (
            mp(TIMES3, COORDS3, "").replace(r#""id": "AFR12","#, r#""crs": {"type": "Name", "properties": {"name": "EPSG:3857"}},"#),
            ErrorKind::Unsupported,
            1,
            "crs",
        ),
        (
            "{\"type\": \"Feature\", \"properties\": {}}".to_owned(),
            ErrorKind::Missing,
            1,
            "geometry",
        ),
        (
            "{\"type\": \"Feature\",\n \"geometry\": {\"type\": \"Polygon\", \"coordinates\":\n [[[0, 0], [1, 0], [0, 0]]]}}".to_owned(),
            ErrorKind::TooFewVertices,
            3,
            "geometry.coordinates[0]",
        ),
        (
            "{\"type\": \"Feature\",\n \"geometry\": {\"type\": \"Polygon\", \"coordinates\":\n [[[0, 0], [1, 0], [1, 1], [0, 1]]]}}".to_owned(),
            ErrorKind::WrongType,
            3,
            "geometry.coordinates[0]",
        ),
        (
            "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]},\n \"properties\": {\"floor_ft\": 500,\n \"ceiling_ft\": 100}}".to_owned(),
            ErrorKind::FloorAboveCeiling,
            2,
            "properties.floor_ft",
        ),
        (
            "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]},\n \"properties\": {\"ceilling_ft\": 100}}".to_owned(),
            ErrorKind::UnknownMember,
            2,
            "properties.ceilling_ft",
        ),
        (
            "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]},\n \"properties\": {\"floor_ft\": \"100\"}}".to_owned(),
            ErrorKind::WrongType,
            2,
            "properties.floor_ft",
        ),
        (
            "{\"type\": \"Feature\", \"id\": \"c\", \"temporalGeometry\": {\"type\": \"MovingPolygon\", \"interpolation\": \"Linear\",\n \"datetimes\": [0, 60],\n \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]],\n [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]]}}".to_owned(),
            ErrorKind::VertexCountChanges,
            4,
            "temporalGeometry.coordinates[1]",
        ),
        (
            "{\"type\": \"Feature\", \"id\": \"c\", \"temporalGeometry\": {\"type\": \"MovingPolygon\",\n \"datetimes\": [0, 60],\n \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]],\n [[0, 0], [1, 0], [1, 1], [0, 0]]]}}".to_owned(),
            ErrorKind::Missing,
            1,
            "temporalGeometry.interpolation",
        ),
    ];
    for (text, kind, line, member) in cases {
        let e = only_error(&text);
        assert_eq!(
            (e.kind, e.at.line, e.at.member.as_deref(), e.at.feature),
            (kind, Some(line), Some(member), Some(0)),
            "{e}\n{text}"
        );
        let shown = e.to_string();
        assert!(
            shown.contains(member) && shown.contains(&format!("line {line}")),
            "{shown}"
        );
    }
}

#[test]
fn errors_name_the_feature_and_its_id_and_do_not_stop_the_others() {
    let good = moving_point(TIMES3, COORDS3, "");
    let bad = moving_point(TIMES3, "[[2.0, 48.0], [2.0, 86], [2.02, 48.01]]", "")
        .replace("AFR12", "BAD1");
    let text =
        format!("{{\"type\": \"FeatureCollection\", \"features\": [{good}, {bad}, {good}]}}");
    let r = mf(&text);
    assert!(r.items[0].is_ok() && r.items[2].is_ok());
    let e = r.items[1].clone().expect_err("bad");
    assert_eq!((e.at.feature, e.at.id.as_deref()), (Some(1), Some("BAD1")));
    assert!(e.to_string().contains("feature 1 (id \"BAD1\")"), "{e}");
}

#[test]
fn foreign_members_are_warnings_naming_them() {
    let text = r#"{"type": "FeatureCollection", "name": "export", "features": [
{"type": "Feature", "title": "t", "geometry": {"type": "Polygon", "extra": 1,
 "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}, "properties": {"anything": [1, NaN]}}]}"#;
    let r = mf(text);
    assert!(r.items[0].is_ok(), "{r:?}");
    let named: Vec<(WarningKind, Option<String>)> = r
        .warnings
        .iter()
        .map(|w| (w.kind, w.at.member.clone()))
        .collect();
    assert_eq!(
        named,
        [
            (WarningKind::ForeignMember, Some("name".into())),
            (WarningKind::ForeignMember, Some("title".into())),
            (WarningKind::ForeignMember, Some("geometry.extra".into())),
        ]
    );
}

#[test]
fn misspelt_area_properties_name_the_one_meant() {
    for (key, meant) in [
        ("floor", "floor_ft"),
        ("Floor_m", "floor_ft"),
        ("ceiling", "ceiling_ft"),
        ("ceil_ft", "ceiling_ft"),
        ("flor_ft", "floor_ft"),
        ("celing_ft", "ceiling_ft"),
    ] {
        assert_eq!(mfjson::misspelt(key), Some(meant), "{key}");
    }
    for key in [
        "floor_ft",
        "ceiling_ft",
        "name",
        "LOWERLIMIT",
        "UPPERUNIT",
        "flow",
    ] {
        assert_eq!(mfjson::misspelt(key), None, "{key}");
    }
}

// ---------------------------------------------------------------------------------------
// CSV

const CSV_HEAD: &str =
    "flight_id,timestamp,icao24,callsign,latitude,longitude,altitude,groundspeed\n";

fn csv(text: &str) -> CsvRead {
    fixes_csv::read(text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

#[test]
fn a_traffic_csv_groups_by_flight_id() {
    let text = format!(
        "{CSV_HEAD}ABR471_198,2021-10-07 13:27:47+00:00,4ca1b2,ABR471,48.99,2.61,1225,150\n\
         ABR471_198,2021-10-07 13:27:48+00:00,4ca1b2,ABR471,48.99,2.62,,150\n\
         X_1,1633611625,3c6444,\"DLH,1\",48.0,2.0,30000,400\n\
         ABR471_198,2021-10-07 13:27:49+00:00,4ca1b2,ABR471,,,,\n\
         X_1,1633611626.5,3c6444,\"DLH,1\",48.0,2.01,30000,400\n"
    );
    let r = csv(&text);
    assert!(r.errors.is_empty(), "{:?}", r.errors);
    assert_eq!(r.trajectories.len(), 2);
    let t = &r.trajectories[0];
    assert_eq!(
        (t.id.as_str(), t.callsign.as_deref()),
        ("ABR471_198", Some("ABR471"))
    );
    assert_eq!(t.fixes[0].t, 1_633_613_267.0);
    assert_eq!((t.fixes[0].alt_ft, t.fixes[1].alt_ft), (Some(1225.0), None));
    assert_eq!(r.trajectories[1].callsign.as_deref(), Some("DLH,1"));
    assert_eq!(r.trajectories[1].fixes[1].t, 1_633_611_626.5);
    let kinds: Vec<WarningKind> = r.warnings.iter().map(|w| w.kind).collect();
    assert_eq!(
        kinds,
        [WarningKind::UnknownColumns, WarningKind::NoPosition]
    );
    assert!(r.warnings[0].detail.contains("groundspeed"));
    assert_eq!(r.warnings[1].at.line, Some(5));
}

#[test]
fn without_flight_id_rows_group_by_aircraft_and_callsign() {
    let text = "timestamp,icao24,callsign,latitude,longitude\n\
        2021-10-07T13:00:00Z,aaa111,AF1,48,2\n\
        2021-10-07T13:00:00Z,aaa111,AF2,48,2\n\
        2021-10-07T13:00:01Z,aaa111,AF1,48,2.1\n\
        2021-10-07T13:00:01Z,aaa111,AF2,48,2.1\n\
        2021-10-07T13:00:00Z,bbb222,,48,2\n\
        2021-10-07T13:00:01Z,bbb222,,48,2.1\n";
    let ids: Vec<String> = csv(text).trajectories.into_iter().map(|t| t.id).collect();
    assert_eq!(ids, ["aaa111/AF1", "aaa111/AF2", "bbb222"]);
}

#[test]
fn every_csv_row_error_names_line_and_column_and_is_skipped() {
    let text = format!(
        "{CSV_HEAD}F,2021-10-07T13:00:00Z,a1,C,48,2,0,0\n\
         F,2021-10-07T13:00:01Z,a1,C,86,2,0,0\n\
         F,2021-10-07T13:00:02Z,a1,C,48,x,0,0\n\
         F,2021-10-07T13:00:00Z,a1,C,48,2,0,0\n\
         F,2021-10-07T13:00:60Z,a1,C,48,2,0,0\n\
         F,2021-10-07T13:00:03Z,a1,C,48,2,inf,0\n\
         F,2021-10-07T13:00:04Z,,C,48,2,0,0\n\
         F,2021-10-07T13:00:05Z,a1,C,48,2\n\
         F,2021-10-07T13:00:06Z,a1,C,48,2.5,,0\n\
         G,2021-10-07T13:00:06Z,a1,C,48,2.5,,0\n"
    );
    let r = csv(&text);
    let got: Vec<(ErrorKind, Option<usize>, Option<String>)> = r
        .errors
        .iter()
        .map(|e| (e.kind, e.at.line, e.at.member.clone()))
        .collect();
    let col = |c: &str| Some(format!("column {c}"));
    assert_eq!(
        got,
        [
            (ErrorKind::OutOfRange, Some(3), col("latitude")),
            (ErrorKind::WrongType, Some(4), col("longitude")),
            (ErrorKind::TimesNotIncreasing, Some(5), col("timestamp")),
            (ErrorKind::BadTime, Some(6), col("timestamp")),
            (ErrorKind::NotFinite, Some(7), col("altitude")),
            (ErrorKind::Missing, Some(8), col("icao24")),
            (ErrorKind::Syntax, Some(9), None),
            (ErrorKind::TooFewFixes, Some(11), None),
        ]
    );
    assert_eq!(r.trajectories.len(), 1);
    assert_eq!(r.trajectories[0].fixes.len(), 2);
    assert_eq!(r.errors[7].at.id.as_deref(), Some("G"));
}

#[test]
fn a_csv_without_a_required_column_is_one_error() {
    let e = fixes_csv::read("timestamp,icao24,lat,lon\n").expect_err("columns");
    assert_eq!(
        (e.kind, e.at.member.as_deref()),
        (ErrorKind::Missing, Some("column latitude"))
    );
    assert_eq!(
        fixes_csv::read("").expect_err("empty").kind,
        ErrorKind::Missing
    );
}

// ---------------------------------------------------------------------------------------
// Real exports: a few flights of traffic's `quickstart` (CSV and MovingPandas MF-JSON),
// two FIRs of Europe as GeoJSON, and keyframed cells (tests/data/moving/, a small
// excerpt of what the export in the repository's data helper wrote).

fn data(name: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/moving")
        .join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn real_traffic_csv_and_movingpandas_json_read_alike() {
    let c = csv(&data("quickstart-3.csv"));
    assert!(c.errors.is_empty(), "{:?}", c.errors);
    assert_eq!(c.trajectories.len(), 3);
    let m = mf(&data("quickstart-3.mf.json"));
    let movers: Vec<Trajectory> = m
        .items
        .into_iter()
        .map(|i| match i {
            Ok(Item::Mover(t)) => t,
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(movers.len(), 3);
    // MovingPandas keeps the flight_id as its trajectory id column and writes naive
    // times: the same instants, positions and altitudes as the CSV.
    for (a, b) in c.trajectories.iter().zip(&movers) {
        assert_eq!(a.id, b.id);
        assert_eq!(a.fixes.len(), b.fixes.len(), "{}", a.id);
        for (x, y) in a.fixes.iter().zip(&b.fixes) {
            assert_eq!(x, y, "{}", a.id);
        }
    }
}

#[test]
fn real_firs_and_cells_read() {
    for name in ["fir-LFFF.geojson", "fir-LFRR.geojson", "cells-2.mf.json"] {
        let r = mf(&data(name));
        assert!(!r.items.is_empty(), "{name}");
        for item in &r.items {
            let Ok(Item::Area(a)) = item else {
                panic!("{name}: {item:?}")
            };
            assert!(
                a.floor_ft.is_some() || a.ceiling_ft.is_some(),
                "{name}: {}",
                a.id
            );
        }
    }
}

/// The whole exports, when a directory of them is named in `MOVING_REAL_DIR` (not in
/// the repository: tens of megabytes).
#[test]
#[ignore = "needs MOVING_REAL_DIR with the full exports"]
fn whole_real_exports_read_without_error() {
    let Ok(dir) = std::env::var("MOVING_REAL_DIR") else {
        return;
    };
    for entry in std::fs::read_dir(&dir).expect("dir") {
        let path = entry.expect("entry").path();
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let name = path.display().to_string();
        if name.ends_with(".csv") {
            let r = csv(&text);
            assert!(
                r.errors.is_empty(),
                "{name}: {:?}",
                &r.errors[..r.errors.len().min(5)]
            );
            println!(
                "{name}: {} trajectories, {} warnings",
                r.trajectories.len(),
                r.warnings.len()
            );
        } else if name.ends_with(".mf.json") || name.ends_with(".geojson") {
            let r = mf(&text);
            let errors: Vec<String> = r
                .items
                .iter()
                .filter_map(|i| i.as_ref().err().map(ToString::to_string))
                .collect();
            assert!(
                errors.is_empty(),
                "{name}: {:?}",
                &errors[..errors.len().min(5)]
            );
            println!(
                "{name}: {} features, {} warnings",
                r.items.len(),
                r.warnings.len()
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Round trips: a small writer of MF-JSON and CSV, then the readers give back the model.

/// Numbers as JSON text: Rust's shortest round-trip form.
fn num(x: f64) -> String {
    format!("{x:?}")
}

fn positions(ring: &[[f64; 2]]) -> String {
    let mut v: Vec<String> = ring
        .iter()
        .map(|p| format!("[{}, {}]", num(p[0]), num(p[1])))
        .collect();
    v.push(v[0].clone()); // GeoJSON rings are closed
    format!("[{}]", v.join(", "))
}

fn polygon_text(r: &Rings) -> String {
    let rings: Vec<String> = std::iter::once(&r.outer)
        .chain(&r.holes)
        .map(|x| positions(x))
        .collect();
    format!("[{}]", rings.join(", "))
}

fn time_text(t: f64) -> String {
    format!("{:?}", time::format(t, Round::Nearest).expect("in range"))
}

/// A mover as an MF-JSON MovingPoint, altitudes as a temporal property in feet.
fn write_mover(t: &Trajectory) -> String {
    let times: Vec<String> = t.fixes.iter().map(|f| time_text(f.t)).collect();
    let coords: Vec<String> = t
        .fixes
        .iter()
        .map(|f| format!("[{}, {}]", num(f.lon), num(f.lat)))
        .collect();
    let alts: Vec<String> = t
        .fixes
        .iter()
        .map(|f| f.alt_ft.map_or("null".into(), num))
        .collect();
    let cs = t
        .callsign
        .as_ref()
        .map_or(String::new(), |c| format!(r#""callsign": {c:?}"#));
    format!(
        r#"{{"type": "Feature", "id": {:?}, "properties": {{{cs}}},
 "temporalGeometry": {{"type": "MovingPoint", "interpolation": "Linear", "datetimes": [{}], "coordinates": [{}]}},
 "temporalProperties": [{{"datetimes": [{}], "altitude": {{"type": "Measure", "form": "[ft_i]", "values": [{}]}}}}]}}"#,
        t.id,
        times.join(", "),
        coords.join(", "),
        times.join(", "),
        alts.join(", ")
    )
}

fn write_area(a: &Area) -> String {
    let mut props = Vec::new();
    if let Some(f) = a.floor_ft {
        props.push(format!(r#""floor_ft": {}"#, num(f)));
    }
    if let Some(c) = a.ceiling_ft {
        props.push(format!(r#""ceiling_ft": {}"#, num(c)));
    }
    let head = format!(
        r#"{{"type": "Feature", "id": {:?}, "properties": {{{}}}, "#,
        a.id,
        props.join(", ")
    );
    match &a.shape {
        Shape::Static(parts) if parts.len() == 1 => format!(
            r#"{head}"geometry": {{"type": "Polygon", "coordinates": {}}}}}"#,
            polygon_text(&parts[0])
        ),
        Shape::Static(parts) => {
            let p: Vec<String> = parts.iter().map(polygon_text).collect();
            format!(
                r#"{head}"geometry": {{"type": "MultiPolygon", "coordinates": [{}]}}}}"#,
                p.join(", ")
            )
        }
        Shape::Keyframed(k) => {
            let times: Vec<String> = k.iter().map(|f| time_text(f.t)).collect();
            let p: Vec<String> = k.iter().map(|f| polygon_text(&f.parts[0])).collect();
            format!(
                r#"{head}"temporalGeometry": {{"type": "MovingPolygon", "interpolation": "Linear", "datetimes": [{}], "coordinates": [{}]}}}}"#,
                times.join(", "),
                p.join(", ")
            )
        }
    }
}

/// Fixes as a CSV with a flight_id column, quoting the callsign (RFC 4180), times as
/// epoch seconds or RFC 3339 by turns.
fn write_csv(ts: &[Trajectory]) -> String {
    let mut out =
        String::from("flight_id,timestamp,icao24,callsign,latitude,longitude,altitude,track\n");
    for t in ts {
        for (k, f) in t.fixes.iter().enumerate() {
            let when = if k % 2 == 0 {
                num(f.t)
            } else {
                time::format(f.t, Round::Nearest).expect("time")
            };
            let cs = t
                .callsign
                .as_ref()
                .map_or(String::new(), |c| format!("\"{}\"", c.replace('"', "\"\"")));
            let alt = f.alt_ft.map_or(String::new(), num);
            out.push_str(&format!(
                "{},{when},abc123,{cs},{},{},{alt},90\n",
                t.id,
                num(f.lat),
                num(f.lon)
            ));
        }
    }
    out
}

/// Times: whole milliseconds of 2000 to 2040 (exact through RFC 3339 text), increasing.
fn times(n: usize) -> impl Strategy<Value = Vec<f64>> {
    (
        946_684_800_000i64..2_208_988_800_000,
        prop::collection::vec(1i64..600_000, n),
    )
        .prop_map(|(start, steps)| {
            let mut ms = start;
            steps
                .iter()
                .map(|s| {
                    ms += s;
                    ms as f64 / 1000.0
                })
                .collect()
        })
}

fn trajectory() -> impl Strategy<Value = Trajectory> {
    (2usize..12).prop_flat_map(|n| {
        (
            "[A-Z]{3}[0-9]{1,4}",
            prop::option::of("[A-Z0-9 ,\"]{1,8}"),
            times(n),
            prop::collection::vec(
                (
                    -180.0f64..=180.0,
                    -85.0f64..=85.0,
                    prop::option::of(-2000.0f64..60000.0),
                ),
                n,
            ),
        )
            .prop_map(|(id, callsign, ts, pos)| Trajectory {
                id,
                callsign: callsign
                    .map(|c| c.trim().to_owned())
                    .filter(|c| !c.is_empty()),
                fixes: ts
                    .into_iter()
                    .zip(pos)
                    .map(|(t, (lon, lat, alt_ft))| Fix {
                        t,
                        lon,
                        lat,
                        alt_ft,
                    })
                    .collect(),
            })
    })
}

fn ring(n: usize) -> impl Strategy<Value = Vec<[f64; 2]>> {
    // distinct vertices: a random polygon around a centre, by increasing angle
    (
        -170.0f64..170.0,
        -80.0f64..80.0,
        prop::collection::vec(0.1f64..4.0, n),
    )
        .prop_map(|(cx, cy, radii)| {
            let n = radii.len();
            radii
                .iter()
                .enumerate()
                .map(|(k, r)| {
                    let a = std::f64::consts::TAU * k as f64 / n as f64;
                    [cx + r * a.cos(), cy + r * a.sin()]
                })
                .collect()
        })
}

fn area() -> impl Strategy<Value = Area> {
    let bounds = prop::option::of(0.0f64..20000.0).prop_flat_map(|f| {
        (
            Just(f),
            prop::option::of(f.unwrap_or(0.0)..f.unwrap_or(0.0) + 40000.0),
        )
    });
    let static_shape = prop::collection::vec(
        (3usize..9).prop_flat_map(ring).prop_map(|outer| Rings {
            outer,
            holes: vec![],
        }),
        1..3,
    )
    .prop_map(Shape::Static);
    let keyframed = (3usize..9, 2usize..5).prop_flat_map(|(n, k)| {
        (prop::collection::vec(ring(n), k), times(k)).prop_map(|(rings, ts)| {
            Shape::Keyframed(
                rings
                    .into_iter()
                    .zip(ts)
                    .map(|(outer, t)| Keyframe {
                        t,
                        parts: vec![Rings {
                            outer,
                            holes: vec![],
                        }],
                    })
                    .collect(),
            )
        })
    });
    ("[a-z]{1,6}", prop_oneof![static_shape, keyframed], bounds).prop_map(
        |(id, shape, (floor_ft, ceiling_ft))| Area {
            id,
            name: None,
            shape,
            floor_ft,
            ceiling_ft,
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// A trajectory written as MF-JSON reads back equal (times whole milliseconds, so
    /// exact through RFC 3339; altitudes in feet, exact).
    #[test]
    fn movers_round_trip_through_mfjson(ts in prop::collection::vec(trajectory(), 1..4)) {
        let body: Vec<String> = ts.iter().map(write_mover).collect();
        let text = format!("{{\"type\": \"FeatureCollection\", \"features\": [{}]}}", body.join(",\n"));
        let r = mf(&text);
        prop_assert!(r.warnings.is_empty(), "{:?}", r.warnings);
        let back: Vec<Item> = r.items.into_iter().map(|i| i.expect("read")).collect();
        let want: Vec<Item> = ts.into_iter().map(Item::Mover).collect();
        prop_assert_eq!(back, want);
    }

    /// The same as JSON Lines, one feature a line.
    #[test]
    fn movers_round_trip_through_json_lines(ts in prop::collection::vec(trajectory(), 2..4)) {
        let text: Vec<String> = ts.iter().map(|t| write_mover(t).replace('\n', " ")).collect();
        let r = mf(&text.join("\n"));
        let back: Vec<Item> = r.items.into_iter().map(|i| i.expect("read")).collect();
        prop_assert_eq!(back, ts.into_iter().map(Item::Mover).collect::<Vec<_>>());
    }

    /// Heights in positions are metres: back in feet within a few ulps (two roundings).
    #[test]
    fn heights_in_metres_come_back_in_feet(t in trajectory()) {
        let times: Vec<String> = t.fixes.iter().map(|f| time_text(f.t)).collect();
        let coords: Vec<String> = t.fixes.iter().map(|f| match f.alt_ft {
            Some(a) => format!("[{}, {}, {}]", num(f.lon), num(f.lat), num(a * M_PER_FT)),
            None => format!("[{}, {}]", num(f.lon), num(f.lat)),
        }).collect();
        let text = format!(r#"{{"type": "Feature", "temporalGeometry": {{"type": "MovingPoint", "datetimes": [{}], "coordinates": [{}]}}}}"#, times.join(","), coords.join(","));
        let Item::Mover(back) = only_item(&text) else { panic!("not a mover") };
        for (a, b) in t.fixes.iter().zip(&back.fixes) {
            prop_assert_eq!((a.t, a.lon, a.lat), (b.t, b.lon, b.lat));
            match (a.alt_ft, b.alt_ft) {
                (Some(x), Some(y)) => prop_assert!((x - y).abs() <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE), "{} {}", x, y),
                (x, y) => prop_assert_eq!(x, y),
            }
        }
    }

    /// An area written as GeoJSON or MF-JSON reads back equal.
    #[test]
    fn areas_round_trip(areas in prop::collection::vec(area(), 1..4)) {
        let body: Vec<String> = areas.iter().map(write_area).collect();
        let text = format!("{{\"type\": \"FeatureCollection\", \"features\": [{}]}}", body.join(",\n"));
        let r = mf(&text);
        let back: Vec<Item> = r.items.into_iter().map(|i| i.unwrap_or_else(|e| panic!("{e}\n{text}"))).collect();
        prop_assert_eq!(back, areas.into_iter().map(Item::Area).collect::<Vec<_>>());
    }

    /// Trajectories written as a CSV read back equal (ids are the flight_id column).
    #[test]
    fn movers_round_trip_through_csv(ts in prop::collection::vec(trajectory(), 1..4)) {
        let mut ts = ts;
        for (k, t) in ts.iter_mut().enumerate() {
            t.id = format!("{}_{k}", t.id); // distinct flights
        }
        let r = csv(&write_csv(&ts));
        prop_assert!(r.errors.is_empty(), "{:?}", r.errors);
        prop_assert_eq!(r.trajectories, ts);
    }

    /// Mutated valid input and garbage never panic, and every error's line is in the text.
    #[test]
    fn mutated_input_never_panics(
        t in trajectory(),
        a in area(),
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
        garbage in ".{0,200}",
    ) {
        let texts = [
            format!("{{\"type\": \"FeatureCollection\", \"features\": [{},\n{}]}}", write_mover(&t), write_area(&a)),
            write_csv(std::slice::from_ref(&t)),
        ];
        for base in texts {
            let mut bytes = base.into_bytes();
            for (at, b, op) in &edits {
                let i = at.index(bytes.len().max(1)).min(bytes.len());
                match op {
                    0 if i < bytes.len() => bytes[i] = *b,
                    1 => bytes.insert(i, *b),
                    _ if i < bytes.len() => { bytes.remove(i); }
                    _ => {}
                }
            }
            let text = String::from_utf8_lossy(&bytes).into_owned();
            for input in [text.as_str(), garbage.as_str()] {
                let lines = input.matches('\n').count() + 1;
                let check = |e: &MovingError| {
                    if let Some(l) = e.at.line {
                        assert!((1..=lines).contains(&l), "line {l} of {lines}: {e}");
                    }
                    let _ = e.to_string();
                };
                match mfjson::read(input) {
                    Ok(r) => r.items.iter().filter_map(|i| i.as_ref().err()).for_each(check),
                    Err(e) => check(&e),
                }
                match fixes_csv::read(input) {
                    Ok(r) => r.errors.iter().for_each(check),
                    Err(e) => check(&e),
                }
            }
        }
    }
}
