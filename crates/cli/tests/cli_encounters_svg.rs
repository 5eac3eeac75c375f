//! `polyguard encounters --svg`: the picture of one mover or one area is one well-formed
//! document that names what it draws and has its timeline; an id that does not exist is
//! refused with the ids that do; the picture in docs/img is the command's output.

mod common;

use std::path::PathBuf;

/// The worked example of docs/moving-features.md: one flight, a static box and a
/// drifting cell.
const EXAMPLE: [&str; 5] = [
    "encounters",
    "examples/moving/flight.csv",
    "examples/moving/areas.geojson",
    "--max-gap",
    "900",
];

/// The picture in the documents, drawn by [`EXAMPLE`] with `--svg` (and made a PNG by
/// scripts/docs-images).
const DOCS_SVG: &str = "docs/img/encounters-flight.svg";

/// A file in this test's scratch directory.
fn scratch(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-encounters-svg-{name}"))
}

/// `polyguard` on [`EXAMPLE`] and `more`: the picture it drew, and its standard error.
fn draw(name: &str, more: &[&str]) -> (String, String) {
    let path = scratch(name);
    let p = path.to_str().expect("a UTF-8 path");
    let mut args: Vec<&str> = EXAMPLE.to_vec();
    args.extend(["--quiet", "-o", "/dev/null", "--svg", p]);
    args.extend(more);
    let (_, err, code) = common::run(&args, b"");
    assert_eq!(code, 0, "{err}");
    (std::fs::read_to_string(&path).expect("the picture"), err)
}

/// Checks that `svg` is well-formed XML: every tag closed in order, attributes quoted,
/// `&` only in entities; returns the element names seen.
fn well_formed(svg: &str) -> Vec<String> {
    let mut open: Vec<String> = Vec::new();
    let mut seen = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        check_text(&rest[..i]);
        let tail = &rest[i..];
        let j = tail.find('>').expect("a tag is closed by '>'");
        let tag = &tail[1..j];
        rest = &tail[j + 1..];
        assert_eq!(
            tag.matches('"').count() % 2,
            0,
            "unquoted attribute in <{tag}>"
        );
        check_text(tag);
        if let Some(name) = tag.strip_prefix('/') {
            let top = open.pop().expect("a closing tag closes an open one");
            assert_eq!(top, name.trim(), "</{name}> closes <{top}>");
            continue;
        }
        let name: String = tag
            .chars()
            .take_while(|c| !c.is_whitespace() && *c != '/')
            .collect();
        assert!(!name.is_empty(), "<{tag}>");
        seen.push(name.clone());
        if !tag.ends_with('/') {
            open.push(name);
        }
    }
    check_text(rest);
    assert!(open.is_empty(), "left open: {open:?}");
    assert_eq!(seen.first().map(String::as_str), Some("svg"));
    seen
}

/// Text and attributes hold `&` only as one of XML's entities.
fn check_text(s: &str) {
    for (k, _) in s.match_indices('&') {
        let after = &s[k + 1..];
        assert!(
            ["amp;", "lt;", "gt;", "quot;", "apos;", "#"]
                .iter()
                .any(|e| after.starts_with(e)),
            "a bare & in {s:?}"
        );
    }
}

/// Without an id the first mover that meets an area is drawn: its track, both areas,
/// a timeline row each in UTC clock times, the first loss of separation, the options.
#[test]
fn a_flight_is_drawn_with_every_area_it_meets_and_a_timeline() {
    let (svg, _) = draw("flight.svg", &[]);
    let names = well_formed(&svg);
    for n in ["path", "text", "rect", "circle", "pattern"] {
        assert!(names.iter().any(|x| x == n), "no <{n}>");
    }
    for s in [
        "3c6444 (DLH4AB)",
        ">BOX<",
        ">CELL<",
        "time, UTC (2021-10-07)",
        ">12:30<",
        "first loss of separation",
        "--sep 0 nm, --sep-v 0 ft, --max-gap 900 s",
    ] {
        assert!(svg.contains(s), "{s} is missing");
    }
    // the same picture when the mover is named, by id or by callsign
    assert_eq!(draw("by-id.svg", &["--svg-mover", "3c6444"]).0, svg);
    assert_eq!(draw("by-callsign.svg", &["--svg-mover", "DLH4AB"]).0, svg);
}

/// `--svg-area` draws the area and the movers that meet it, one row each.
#[test]
fn an_area_is_drawn_with_every_mover_that_meets_it() {
    let (svg, _) = draw("area.svg", &["--svg-area", "CELL"]);
    well_formed(&svg);
    for s in ["CELL", "1 mover met", "3c6444 (DLH4AB)", "time, UTC"] {
        assert!(svg.contains(s), "{s} is missing");
    }
    assert!(!svg.contains(">BOX<"), "another area drawn");
}

/// An id that no mover or area has is refused (exit 2) before any answer, naming
/// the ids there are; so are both flags at once, and either without --svg.
#[test]
fn unknown_ids_are_refused_with_the_ids_there_are() {
    let out = scratch("never.svg");
    let p = out.to_str().expect("a UTF-8 path");
    for (flag, id, listed) in [
        ("--svg-mover", "NOPE", "3c6444"),
        ("--svg-area", "NOWHERE", "BOX, CELL"),
    ] {
        let mut args = EXAMPLE.to_vec();
        args.extend(["--svg", p, flag, id]);
        let (stdout, err, code) = common::run(&args, b"");
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(&format!("{flag} {id}")), "{err}");
        assert!(err.contains(listed), "{err}");
        assert!(stdout.is_empty(), "answered anyway: {stdout}");
        assert!(!out.exists(), "a picture was written");
    }
    let mut both = EXAMPLE.to_vec();
    both.extend(["--svg", p, "--svg-mover", "3c6444", "--svg-area", "BOX"]);
    assert_eq!(common::run(&both, b"").2, 2);
    let mut bare = EXAMPLE.to_vec();
    bare.extend(["--svg-area", "BOX"]);
    assert_eq!(common::run(&bare, b"").2, 2);
}

/// The picture in docs/img is what the command draws today (scripts/docs-images draws
/// it again, and its PNG).
#[test]
fn the_documents_picture_is_the_commands_output() {
    let (svg, _) = draw("docs.svg", &[]);
    let kept = std::fs::read_to_string(common::root().join(DOCS_SVG)).expect("the docs picture");
    assert!(
        kept == svg,
        "{DOCS_SVG} differs from the command's output: run scripts/docs-images"
    );
}
