//! The JSON Schemas of the moving-features formats (docs/schema/mf-json.schema.json and
//! moving-area.schema.json, draft 2020-12) checked against what the readers really read:
//! the real exports in tests/data/moving/, the JSON examples of docs/moving-features.md;
//! and canaries the other way: inputs the reader rejects (each first confirmed rejected
//! by the reader) must be rejected by the schema too.

use jsonschema::Validator;
use polyguard_earth::moving::mfjson;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// `docs/schema/NAME`, checked against the draft 2020-12 meta-schema and compiled.
fn schema(name: &str) -> Validator {
    let path = root().join("docs/schema").join(name);
    let value: Value = serde_json::from_str(&read(&path)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(
        value["$schema"],
        "https://json-schema.org/draft/2020-12/schema"
    );
    if let Err(e) = jsonschema::draft202012::meta::validate(&value) {
        panic!("{name}: not a valid draft 2020-12 schema: {e}");
    }
    jsonschema::draft202012::new(&value).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[track_caller]
fn assert_valid(v: &Validator, what: &str, text: &str) {
    let instance: Value = serde_json::from_str(text).unwrap_or_else(|e| panic!("{what}: {e}"));
    let errors: Vec<String> = v
        .iter_errors(&instance)
        .map(|e| format!("  at {}: {e}", e.instance_path.as_str()))
        .take(5)
        .collect();
    assert!(
        errors.is_empty(),
        "{what} does not validate:\n{}",
        errors.join("\n")
    );
}

/// Reads `text` and says whether every feature was read without error.
fn reader_accepts(text: &str) -> bool {
    mfjson::read(text).is_ok_and(|r| r.items.iter().all(Result::is_ok))
}

fn data_files(ends: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/moving");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(ends))
        .collect();
    files.sort();
    files
}

#[test]
fn the_real_exports_validate() {
    let mf = schema("mf-json.schema.json");
    let area = schema("moving-area.schema.json");
    let mut n = 0;
    for path in data_files(".mf.json")
        .into_iter()
        .chain(data_files(".geojson"))
    {
        let text = read(&path);
        assert!(reader_accepts(&text), "{}", path.display());
        assert_valid(&mf, &path.display().to_string(), &text);
        n += 1;
    }
    for path in data_files(".geojson") {
        assert_valid(&area, &path.display().to_string(), &read(&path));
    }
    assert!(n >= 4, "only {n} files");
}

/// The ```json blocks of docs/moving-features.md.
fn page_examples() -> Vec<String> {
    let page = read(&root().join("docs/moving-features.md"));
    page.split("```json\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap_or_default().to_owned())
        .collect()
}

#[test]
fn the_pages_examples_read_and_validate() {
    let mf = schema("mf-json.schema.json");
    let examples = page_examples();
    assert!(examples.len() >= 3);
    for text in &examples {
        assert!(
            reader_accepts(text),
            "the reader rejects the page's example\n{text}"
        );
        assert_valid(&mf, "an example of docs/moving-features.md", text);
    }
    // What the page says of its MovingPandas example.
    let r = mfjson::read(&examples[0]).expect("read");
    let Ok(mfjson::Item::Mover(t)) = &r.items[0] else {
        panic!("{r:?}")
    };
    assert_eq!(
        (t.id.as_str(), t.callsign.as_deref()),
        ("ABR471_198", Some("ABR471"))
    );
    let fixes: Vec<(f64, Option<f64>)> = t.fixes.iter().map(|f| (f.t, f.alt_ft)).collect();
    assert_eq!(
        fixes,
        [
            (1_633_613_267.0, Some(1225.0)),
            (1_633_613_268.0, Some(1275.0))
        ]
    );
    assert_eq!(r.warnings.len(), 2, "{:?}", r.warnings);
}

/// A good MovingPoint, a good MovingPolygon and a good area, to be spoiled.
const POINT: &str = r#"{"type": "Feature", "id": "a", "temporalGeometry": {"type": "MovingPoint", "interpolation": "Linear", "datetimes": ["2021-10-07T13:00:25Z", "2021-10-07T13:00:26Z"], "coordinates": [[2, 48], [2.1, 48]]}}"#;
const CELL: &str = r#"{"type": "Feature", "id": "c", "properties": {"ceiling_ft": 100}, "temporalGeometry": {"type": "MovingPolygon", "interpolation": "Linear", "datetimes": [0, 60], "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]], [[0, 1], [1, 1], [1, 2], [0, 1]]]}}"#;
const AREA: &str = r#"{"type": "Feature", "id": "z", "properties": {"floor_ft": 0, "other": 1}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}}"#;

fn edit(base: &str, from: &str, to: &str) -> String {
    let s = base.replacen(from, to, 1);
    assert_ne!(s, base, "{from:?} not in the base");
    s
}

#[test]
fn the_bases_read_and_validate() {
    let mf = schema("mf-json.schema.json");
    for text in [POINT, CELL, AREA] {
        assert!(reader_accepts(text), "{text}");
        assert_valid(&mf, "a base", text);
    }
    assert_valid(&schema("moving-area.schema.json"), "the area", AREA);
}

#[test]
fn the_schemas_reject_the_canaries() {
    let mf = schema("mf-json.schema.json");
    let area = schema("moving-area.schema.json");
    let canaries = [
        edit(POINT, "\"Linear\"", "\"Step\""),
        edit(POINT, "\"interpolation\"", "\"interpolations\""),
        edit(POINT, "[2.1, 48]", "[2.1, 86]"),
        edit(POINT, "[2.1, 48]", "[181, 48]"),
        edit(POINT, "[2.1, 48]", "[2.1, 48, 0, 0]"),
        edit(POINT, "\"2021-10-07T13:00:26Z\"", "\"2021/10/07 13:00:26\""),
        edit(POINT, "\"2021-10-07T13:00:26Z\"", "1633611626000"),
        edit(POINT, "MovingPoint", "MovingGeometryCollection"),
        edit(
            POINT,
            "\"id\": \"a\",",
            "\"crs\": {\"type\": \"name\", \"properties\": {\"name\": \"EPSG:3857\"}},",
        ),
        edit(POINT, ", [2.1, 48]]", "]"),
        edit(CELL, "\"interpolation\": \"Linear\", ", ""),
        edit(CELL, "\"ceiling_ft\"", "\"ceiling\""),
        edit(
            CELL,
            "[[0, 1], [1, 1], [1, 2], [0, 1]]",
            "[[0, 1], [1, 1], [0, 1]]",
        ),
        edit(AREA, "\"floor_ft\"", "\"Floor_m\""),
        edit(AREA, "0, \"other\"", "\"0\", \"other\""),
        edit(AREA, "\"Polygon\"", "\"LineString\""),
        edit(AREA, "[[[0, 0], [1, 0], [1, 1], [0, 0]]]", "[]"),
    ];
    for text in &canaries {
        assert!(
            !reader_accepts(text),
            "the reader accepts a canary:\n{text}"
        );
        let instance: Value = serde_json::from_str(text).expect("canaries are JSON");
        assert!(
            !mf.is_valid(&instance),
            "mf-json.schema.json accepts a canary:\n{text}"
        );
        if text.contains("\"geometry\"") {
            assert!(
                !area.is_valid(&instance),
                "moving-area.schema.json accepts:\n{text}"
            );
        }
    }
}
