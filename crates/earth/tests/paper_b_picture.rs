//! The `--svg` picture (issue "paper B on the real Earth", item 6): what a reader of the
//! paper's Figs 2–5 looks for is there. Rendered and looked at by hand too (rsvg-convert).

use polyguard_earth::analysis::analyse;
use polyguard_earth::conflict::DEFAULT_TIME_TOLERANCE_H as TOL;
use polyguard_earth::picture::{svg, Options};

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
