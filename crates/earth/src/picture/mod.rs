//! Paper B's figures (Figs 2–5) for a scenario and its conflicts, as SVG: areas, tracks
//! with their swept hulls, rectangles at each leg's ends and direction, conflict regions
//! with their windows, a longitude–latitude graticule on the Mercator plane, and a
//! legend. With `detail`, also stage 1's bounding boxes (eqs 3–6) and stage 3's
//! projections of each region's vertices onto the track (eqs 10–11, Fig 4).
//!
//! - `layout`: on the Earth each object in the whole turn nearest the others, and the
//!   panels: far-apart groups drawn in panels of their own at one scale;
//! - `frame`: a panel's Mercator plane to pixels;
//! - `grid`: the graticule, and the bands left out between panels;
//! - `scene`: the areas, tracks and conflicts, and the labels they ask for;
//! - `labels`: the labels placed without overlap, inside their panel;
//! - `legend`: what each thing drawn is, and what the picture leaves out.

mod encounters;
mod frame;
mod grid;
mod labels;
mod layout;
mod legend;
mod scene;
mod timeline;
mod track_map;

pub use encounters::{area_svg, mover_svg, Met};
pub use labels::Placed;

use crate::conflict::{pipeline, Object};
use crate::scenario::{Longitudes, Scenario};
use labels::{Class, Placer};
use layout::{lay_out, mid, Layout, Turns};
use scene::{Asked, Scene, LABELLED_CONFLICTS, TIMED_FEATURES};
use std::fmt::Write as _;

/// What to draw beyond the scene itself.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Stage 1's bounding boxes and stage 3's projection lines (the paper's Figs 2–5).
    pub detail: bool,
}

/// A picture drawn: its SVG, and where its panels and labels are.
#[derive(Clone, Debug)]
pub struct Picture {
    /// The SVG document.
    pub svg: String,
    /// Each panel's plot (pixels, `[x0, y0, x1, y1]`).
    pub panels: Vec<[f64; 4]>,
    /// The labels placed.
    pub labels: Vec<Placed>,
    /// Labels asked for and placed: features' names, conflicts' windows, tracks' times.
    pub label_counts: [(usize, usize); 3],
}

/// Features take turns in the paper's colours (blue, green) and two more.
const PALETTE: [&str; 4] = ["#1f4fd8", "#1a8a3a", "#7b2fa8", "#d2691e"];

/// The panels' top-left corner (pixels): the title above, the first plot's left edge at
/// 70 pixels.
const ORIGIN: (f64, f64) = (8.0, 32.0);

/// XML text escaped.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A time (h) for a label.
fn hours(t: f64) -> String {
    if t.is_finite() {
        format!("{t:.2} h")
    } else if t > 0.0 {
        "+∞".to_owned()
    } else {
        "−∞".to_owned()
    }
}

/// Paper B's figures for `sc` (its stage objects and conflicts), as SVG text.
pub fn svg(
    sc: &Scenario,
    objects: &[Object],
    conflicts: &[pipeline::Conflict],
    opts: Options,
) -> String {
    draw(sc, objects, conflicts, opts).svg
}

/// [`svg`], with where the picture put its panels and labels.
pub fn draw(
    sc: &Scenario,
    objects: &[Object],
    conflicts: &[pipeline::Conflict],
    opts: Options,
) -> Picture {
    // each object once: its first copy on the Earth (Object::on_earth)
    let objects: Vec<&Object> = objects.iter().filter(|o| o.copy == 0).collect();
    let turns = Turns::new(&objects, sc.longitudes == Longitudes::Earth);
    let boxes: Vec<[f64; 4]> = objects
        .iter()
        .map(|o| {
            let dx = turns.dx(mid(o.aabb));
            [o.aabb[0] + dx, o.aabb[1], o.aabb[2] + dx, o.aabb[3]]
        })
        .collect();
    let layout = lay_out(&boxes, ORIGIN);
    let scene = Scene {
        sc,
        objects: &objects,
        conflicts,
        turns: &turns,
        layout: &layout,
    };
    let mut body = String::new();
    let step = grid::step(layout.frames[0].k);
    for f in &layout.frames {
        grid::graticule(&mut body, f, sc.geodesy, step);
    }
    for b in &layout.breaks {
        grid::band(&mut body, b, sc.geodesy);
    }
    if opts.detail {
        scene.boxes(&mut body);
    }
    let mut asked = Asked::default();
    scene.features(&mut body, &mut asked);
    scene.conflicts(&mut body, opts.detail, &mut asked);
    let specks = scene.specks(&mut body);
    let mut placer = Placer::default();
    for &m in &asked.marks {
        placer.reserve(m);
    }
    for r in asked
        .features
        .iter()
        .chain(&asked.windows)
        .chain(&asked.times)
    {
        placer.add(r);
    }
    body.push_str(&placer.svg());
    let notes = notes(sc, conflicts.len(), &placer, &layout, specks);
    Picture {
        svg: page(sc, conflicts.len(), &layout, &body, opts.detail, &notes),
        panels: layout.frames.iter().map(|f| f.rect()).collect(),
        labels: placer.placed,
        label_counts: placer.counts,
    }
}

/// What the legend tells beyond its samples: labels left out for want of room (their
/// text stays in the drawing's tooltip), the bands left out between panels, the rings
/// around features too small to see.
fn notes(
    sc: &Scenario,
    conflicts: usize,
    placer: &Placer,
    layout: &Layout,
    specks: usize,
) -> Vec<String> {
    let mut out = Vec::new();
    let counted = |class: Class, what: &str| {
        let (asked, placed) = placer.counts[class as usize];
        (placed < asked).then(|| {
            format!(
                "{} of {asked} {what} left out for want of room (see the tooltips)",
                asked - placed
            )
        })
    };
    out.extend(counted(Class::Feature, "feature names"));
    if conflicts > LABELLED_CONFLICTS {
        out.push(format!(
            "windows of the {conflicts} conflicts in the tooltips of their regions"
        ));
    } else {
        out.extend(counted(Class::Window, "conflict windows"));
    }
    let tracks = sc
        .features
        .iter()
        .any(|f| matches!(f.kind, crate::scenario::Kind::Track(_)));
    if tracks && sc.features.len() > TIMED_FEATURES {
        out.push("tracks' times in the tooltips of their lines".to_owned());
    } else {
        out.extend(counted(Class::Time, "track times"));
    }
    if !layout.breaks.is_empty() {
        out.push(format!(
            "{} panels at one scale: the picture is cut where nothing lies (the bands left \
             out are named between the panels)",
            layout.frames.len()
        ));
    }
    if specks > 0 {
        out.push(format!(
            "dashed ring: {specks} feature{} too small to see at this scale",
            if specks == 1 { "" } else { "s" }
        ));
    }
    out
}

/// The SVG document: its header, title, the drawing `body`, and the legend right of the
/// panels.
fn page(
    sc: &Scenario,
    conflicts: usize,
    layout: &Layout,
    body: &str,
    detail: bool,
    notes: &[String],
) -> String {
    let legend_at = (ORIGIN.0 + layout.size.0 + 12.0, 40.0);
    let mut legend = String::new();
    let entries: Vec<(legend::Sample, String)> = legend::entries(detail)
        .into_iter()
        .map(|(s, t)| (s, t.to_owned()))
        .collect();
    let notes: Vec<String> = std::iter::once("colours: features in turn".to_owned())
        .chain(notes.iter().cloned())
        .collect();
    let legend_h = legend::legend(&mut legend, legend_at, &entries, &notes);
    let total_w = legend_at.0 + legend::WIDTH;
    let total_h = (ORIGIN.1 + layout.size.1 + 16.0).max(legend_at.1 + legend_h + 16.0);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{total_w:.0}\" height=\"{total_h:.0}\" \
         viewBox=\"0 0 {total_w:.0} {total_h:.0}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"8\" \
         markerHeight=\"8\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" \
         fill=\"context-stroke\"/></marker></defs>\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let n = sc.features.len();
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"22\" font-size=\"15\">{n} feature{}, {conflicts} conflict{} \
         (Mercator plane)</text>",
        layout.frames[0].left,
        if n == 1 { "" } else { "s" },
        if conflicts == 1 { "" } else { "s" }
    );
    out.push_str(body);
    out.push_str(&legend);
    out.push_str("</svg>\n");
    out
}
