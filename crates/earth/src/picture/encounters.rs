//! The picture of `polyguard encounters --svg` (docs/moving-features.md): one mover and
//! every area it meets, or one area and every mover that meets it. Above, a map on the
//! Mercator plane (the frame, graticule, labels and legend of the scenario pictures):
//! areas, tracks, the stretches inside drawn thick and the stretches near as a halo,
//! possible stretches dashed, fixes as dots, gaps dotted, the first loss of separation
//! ringed in red. Below, a timeline with one row per pair met ([`super::timeline`]).

use super::frame::Frame;
use super::labels::{Class, Placer, Prefer, Request};
use super::legend::{self, Sample};
use super::timeline::{self, Axis, Row, LABEL_W};
use super::track_map::{bbox_of, line, rings_path, Outline, Track};
use super::{esc, grid};
use crate::moving::encounter::{Encounter, Options};
use crate::moving::model::{Area, Trajectory};
use crate::moving::time::{format, Round};
use std::fmt::Write as _;

/// One pair met, seen from the side drawn: the other side (an area, or a mover) and the
/// encounter's spans.
#[derive(Debug)]
pub struct Met<'a, T> {
    /// The area or the mover met.
    pub other: &'a T,
    /// The pair's spans and the mover's gaps.
    pub encounter: &'a Encounter,
}

// two references: copied whatever `T` is (a derive would ask `T: Copy`)
impl<T> Clone for Met<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for Met<'_, T> {}

/// Colours of the pairs met, in turn (the scenario pictures' four first); red is kept
/// for the loss of separation, grey for gaps.
const COLOURS: [&str; 8] = [
    "#1f4fd8", "#1a8a3a", "#7b2fa8", "#d2691e", "#008b8b", "#b8860b", "#c71585", "#556b2f",
];
/// The map's largest plot (pixels).
const MAP_W: f64 = 760.0;
const MAP_H: f64 = 480.0;
/// The map's top-left corner (pixels): the title above, the latitudes to the left.
const MAP_AT: (f64, f64) = (70.0, 44.0);
/// The timeline shows at most this many rows, and counts the rest.
pub const MAX_ROWS: usize = 40;
/// Keyframes drawn faint at most (evenly chosen among those in the time shown).
const MAX_KEYFRAMES: usize = 12;
/// Fixes are dotted when they are at least this far apart on average (pixels).
const DOT_SPACING_PX: f64 = 4.0;

/// The frame that shows the Mercator box `b` (grown by a margin) at one scale within
/// [`MAP_W`] × [`MAP_H`].
fn frame_for(b: [f64; 4]) -> Frame {
    let least = 1e-5;
    let (cx, cy) = ((b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0);
    let w = (b[2] - b[0]).max(least) * 1.1;
    let h = (b[3] - b[1]).max(least) * 1.1;
    let k = (MAP_W / w).min(MAP_H / h);
    Frame {
        b: [cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0],
        k,
        left: MAP_AT.0,
        top: MAP_AT.1,
    }
}

/// The union of two boxes.
fn union(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0].min(b[0]),
        a[1].min(b[1]),
        a[2].max(b[2]),
        a[3].max(b[3]),
    ]
}

/// A stroke dashed when the span is only possible.
fn dash(certain: bool, pattern: &str) -> String {
    if certain {
        String::new()
    } else {
        format!(" stroke-dasharray=\"{pattern}\"")
    }
}

/// The mover's track in `colour`, with the pair's spans on it: near as a wide pale halo,
/// inside as a thick line, possible ones dashed; the first loss of separation ringed.
/// `under` draws the halos (before the tracks), else the rest; the ring's box (pixels),
/// which labels must leave clear.
fn pair_on_map(
    out: &mut String,
    f: &Frame,
    track: &Track,
    e: &Encounter,
    colour: &str,
    under: bool,
) -> Option<[f64; 4]> {
    if under {
        for s in &e.near {
            for pts in track.stretch(s.start[0], s.end[1]) {
                let style = format!(
                    "stroke=\"{colour}\" stroke-opacity=\"0.3\" stroke-width=\"11\"{}",
                    dash(s.certain, "10 6")
                );
                line(out, f, &pts, &style, &span_title(&e.area, "near", s));
            }
        }
        return None;
    }
    for s in &e.inside {
        for pts in track.stretch(s.start[0], s.end[1]) {
            let style = format!(
                "stroke=\"{colour}\" stroke-width=\"4.5\"{}",
                dash(s.certain, "7 5")
            );
            line(out, f, &pts, &style, &span_title(&e.area, "inside", s));
        }
    }
    let p = e.loss_of_separation().and_then(|t| track.point(t[0]))?;
    {
        let (x, y) = f.pt(p, 0.0);
        let _ = writeln!(
            out,
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"6\" fill=\"none\" stroke=\"red\" \
             stroke-width=\"2\"><title>{} – {}: first loss of separation {}</title></circle>",
            esc(&e.mover),
            esc(&e.area),
            format(e.near[0].start[0], Round::Floor).unwrap_or_default()
        );
        Some([x - 7.0, y - 7.0, x + 7.0, y + 7.0])
    }
}

/// A span's tooltip: what, the area, and its outer ends in UTC.
fn span_title(area: &str, what: &str, s: &crate::moving::plane::TimeSpan) -> String {
    format!(
        "{what} {area}{}: {} – {}",
        if s.certain { "" } else { " (possible)" },
        format(s.start[0], Round::Floor).unwrap_or_default(),
        format(s.end[1], Round::Ceil).unwrap_or_default()
    )
}

/// A track's line, its gaps dotted, and its fixes dotted when they are far enough apart
/// to be seen (the count of tracks too dense to dot goes to `dense`).
fn track_line(
    out: &mut String,
    f: &Frame,
    track: &Track,
    colour: &str,
    name: &str,
    dense: &mut usize,
) {
    for s in &track.segments {
        let pts = &track.p[s.clone()];
        line(
            out,
            f,
            pts,
            &format!("stroke=\"{colour}\" stroke-width=\"1.2\""),
            name,
        );
    }
    // the whole track's length on the map, gaps included (a fix alone between two gaps
    // is seen by its dot only)
    let length: f64 = track
        .p
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]) * f.k)
        .sum();
    for [a, b] in track.gaps() {
        line(
            out,
            f,
            &[a, b],
            "stroke=\"#777\" stroke-width=\"1.5\" stroke-dasharray=\"1 4\"",
            &format!("{name}: gap, no fixes"),
        );
    }
    if length >= DOT_SPACING_PX * track.p.len() as f64 {
        let mut d = String::new();
        for &p in &track.p {
            let (x, y) = f.pt(p, 0.0);
            let _ = write!(d, "M{x:.2},{y:.2}h0");
        }
        let _ = writeln!(
            out,
            "<path d=\"{d}\" stroke=\"{colour}\" stroke-width=\"3.5\" stroke-linecap=\"round\"/>"
        );
    } else {
        *dense += 1;
    }
}

/// The keyframes of `o` within [a, b], at most [`MAX_KEYFRAMES`] evenly chosen, drawn
/// faint in `colour`.
fn keyframes(out: &mut String, f: &Frame, o: &Outline, [a, b]: [f64; 2], colour: &str) {
    if o.is_static {
        return;
    }
    let within: Vec<&(f64, Vec<Vec<[f64; 2]>>)> =
        o.frames.iter().filter(|k| a <= k.0 && k.0 <= b).collect();
    let every = within.len().div_ceil(MAX_KEYFRAMES).max(1);
    for k in within.iter().step_by(every) {
        rings_path(
            out,
            f,
            &k.1,
            &format!(
                "fill=\"none\" stroke=\"{colour}\" stroke-opacity=\"0.35\" stroke-width=\"0.8\""
            ),
        );
    }
}

/// When a pair's mover enters: the start of each inside span, or of each near span when
/// it is never inside.
fn entries(e: &Encounter) -> Vec<f64> {
    let spans = if e.inside.is_empty() {
        &e.near
    } else {
        &e.inside
    };
    spans.iter().map(|s| s.start[0]).collect()
}

/// The area `o` drawn in `colour`: a static one filled; a keyframed one faint at its
/// keyframes within `shown` and filled at the times `enter`. Its label's anchor (pixels).
fn area_on_map(
    out: &mut String,
    f: &Frame,
    o: &Outline,
    shown: [f64; 2],
    enter: &[f64],
    colour: &str,
) -> Option<(f64, f64)> {
    keyframes(out, f, o, shown, colour);
    let style =
        format!("fill=\"{colour}\" fill-opacity=\"0.08\" stroke=\"{colour}\" stroke-width=\"1.5\"");
    let mut anchor = None;
    let times: Vec<f64> = if o.is_static {
        vec![0.0]
    } else {
        enter.to_vec()
    };
    for t in times {
        if let Some(r) = o.at(t) {
            rings_path(out, f, &r, &style);
            let b = bbox_of(r.iter().flatten());
            anchor.get_or_insert(f.pt([(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0], 0.0));
        }
    }
    anchor
}

/// The map's drawing opened in a group clipped to the plot of `f` (closed by the caller).
fn clip(f: &Frame) -> String {
    format!(
        "<defs><clipPath id=\"plot\"><rect x=\"{:.2}\" y=\"{:.2}\" width=\"{:.2}\" \
         height=\"{:.2}\"/></clipPath></defs>\n<g clip-path=\"url(#plot)\">\n",
        f.left,
        f.top,
        f.width(),
        f.height()
    )
}

/// The part of the plane a mover's map shows: the track and the areas it meets, but no
/// farther from the track than 0.6 of its size (an airspace much larger than the flight
/// is cut, so that the flight stays large enough to read).
fn near_track(track: &Track, outlines: &[Outline]) -> [f64; 4] {
    let t = bbox_of(track.p.iter());
    let all = outlines.iter().fold(t, |b, o| union(b, o.bbox()));
    let g = 0.6 * (t[2] - t[0]).max(t[3] - t[1]);
    [
        all[0].max(t[0] - g),
        all[1].max(t[1] - g),
        all[2].min(t[2] + g),
        all[3].min(t[3] + g),
    ]
}

/// What the picture draws, whichever side it is of.
struct Sheet<'a> {
    title: String,
    frame: Frame,
    body: String,
    rows: Vec<Row<'a>>,
    shown: [f64; 2],
    notes: Vec<String>,
    keyframed: bool,
    /// One mover: its gaps shaded across every row.
    shared_gaps: bool,
    geo: crate::geodesy::Geodesy,
}

/// A mover's name: its id, and its callsign when it has one.
fn mover_name(id: &str, callsign: Option<&str>) -> String {
    match callsign {
        Some(c) if !c.is_empty() && c != id => format!("{id} ({c})"),
        _ => id.to_owned(),
    }
}

/// The pairs in the order of their first loss of separation (the timeline reads down
/// in time), ties in the order given.
fn by_first_loss<'a, T>(met: &[Met<'a, T>]) -> Vec<Met<'a, T>> {
    let mut out = met.to_vec();
    let first = |m: &Met<T>| {
        m.encounter
            .loss_of_separation()
            .map_or(f64::INFINITY, |s| s[0])
    };
    out.sort_by(|a, b| first(a).total_cmp(&first(b)));
    out
}

/// The timeline's rows of `met`: each named by `label`, coloured by the palette index
/// `colour` gives its place.
fn rows_of<'a, T>(
    met: &[Met<'a, T>],
    label: impl Fn(&T) -> String,
    colour: impl Fn(usize) -> usize,
) -> Vec<Row<'a>> {
    met.iter()
        .enumerate()
        .map(|(i, m)| Row {
            label: label(m.other),
            colour: (COLOURS[colour(i)], colour(i)),
            inside: &m.encounter.inside,
            near: &m.encounter.near,
            gaps: &m.encounter.gaps,
        })
        .collect()
}

/// The options in words, for the title.
fn options_text(opts: &Options) -> String {
    format!(
        "--sep {} nm, --sep-v {} ft, --max-gap {} s",
        opts.sep_nm, opts.sep_v_ft, opts.max_gap_s
    )
}

/// The picture of one mover `traj` and every area it meets (`met`), with the options
/// the encounters were answered with, as an SVG document.
pub fn mover_svg(traj: &Trajectory, met: &[Met<Area>], opts: &Options) -> String {
    let met = &by_first_loss(met);
    let geo = opts.geodesy;
    let reference = traj.fixes.first().map_or(0.0, |f| f.lon);
    let track = Track::new(traj, geo, opts.max_gap_s, reference);
    let shown = [
        track.t.first().copied().unwrap_or(0.0),
        track.t.last().copied().unwrap_or(0.0),
    ];
    let outlines: Vec<Outline> = met
        .iter()
        .map(|m| Outline::new(m.other, geo, reference))
        .collect();
    let f = frame_for(near_track(&track, &outlines));
    let mut body = clip(&f);
    let mut placer = Placer::default();
    let mut labels = Vec::new();
    for (i, (m, o)) in met.iter().zip(&outlines).enumerate() {
        let c = COLOURS[i % COLOURS.len()];
        let enter = entries(m.encounter);
        area_on_map(&mut body, &f, o, shown, &enter, c);
        // an area is named where the track enters it: its centre may lie off the map
        if let Some(p) = enter.first().and_then(|&t| track.point(t)) {
            labels.push((m.other.id.clone(), f.pt(p, 0.0), c, Prefer::Below));
        }
    }
    for (i, m) in met.iter().enumerate() {
        pair_on_map(
            &mut body,
            &f,
            &track,
            m.encounter,
            COLOURS[i % COLOURS.len()],
            true,
        );
    }
    let name = mover_name(&traj.id, traj.callsign.as_deref());
    let mut dense = 0;
    track_line(&mut body, &f, &track, "#333", &name, &mut dense);
    for (i, m) in met.iter().enumerate() {
        let ring = pair_on_map(
            &mut body,
            &f,
            &track,
            m.encounter,
            COLOURS[i % COLOURS.len()],
            false,
        );
        if let Some(b) = ring {
            placer.reserve(b);
        }
    }
    body.push_str("</g>\n");
    if let Some(&p) = track.p.first() {
        labels.insert(0, (name.clone(), f.pt(p, 0.0), "#333", Prefer::Above));
    }
    place_labels(&mut body, &mut placer, &f, &labels);
    let rows = rows_of(met, |a| a.id.clone(), |i| i % COLOURS.len());
    let mut notes = vec!["colours: areas met in turn".to_owned()];
    if dense > 0 {
        notes.push("fixes too dense to dot at this scale".to_owned());
    }
    let n = met.len();
    draw(Sheet {
        title: format!(
            "{name}: {n} area{} met ({})",
            if n == 1 { "" } else { "s" },
            options_text(opts)
        ),
        frame: f,
        body,
        rows,
        shown,
        notes,
        keyframed: outlines.iter().any(|o| !o.is_static),
        shared_gaps: true,
        geo,
    })
}

/// Places the map's labels (text, anchor, colour, side) inside the plot.
fn place_labels(
    body: &mut String,
    placer: &mut Placer,
    f: &Frame,
    labels: &[(String, (f64, f64), &'static str, Prefer)],
) {
    for (text, anchor, colour, prefer) in labels {
        placer.add(&Request {
            text: text.clone(),
            anchor: *anchor,
            frame: f.rect(),
            colour,
            size: 11.0,
            prefer: *prefer,
            class: Class::Feature,
        });
    }
    body.push_str(&placer.svg());
}

/// The times an area's timeline shows: every near span of `met`, and 5 % more either
/// side (at least 5 minutes).
fn near_times(met: &[Met<Trajectory>]) -> [f64; 2] {
    let near = met.iter().flat_map(|m| &m.encounter.near);
    let lo = near
        .clone()
        .map(|s| s.start[0])
        .fold(f64::INFINITY, f64::min);
    let hi = near.map(|s| s.end[1]).fold(f64::NEG_INFINITY, f64::max);
    let pad = ((hi - lo) * 0.05).max(300.0);
    if lo <= hi {
        [lo - pad, hi + pad]
    } else {
        [0.0, 1.0]
    }
}

/// The frame of an area's map: the area, a quarter of its size around it, and at least
/// twice D (at the area's latitude, where D nm span D/R·sec(lat) radians of the plane).
fn around(outline: &Outline, opts: &Options) -> Frame {
    let geo = opts.geodesy;
    let ab = outline.bbox();
    let lat = geo.inverse_mercator([0.0, (ab[1] + ab[3]) / 2.0]).lat;
    let d = 2.0 * opts.sep_nm / geo.radius_nm() / lat.cos().max(0.05);
    let grow = ((ab[2] - ab[0]).max(ab[3] - ab[1]) * 0.25).max(d);
    frame_for([ab[0] - grow, ab[1] - grow, ab[2] + grow, ab[3] + grow])
}

/// The picture of one area and every mover that meets it (`met`; the timeline shows the
/// first `MAX_ROWS`, 40), with the options the encounters were answered with, as an SVG
/// document. The map shows the area and the movers near it.
pub fn area_svg(area: &Area, met: &[Met<Trajectory>], opts: &Options) -> String {
    let met = &by_first_loss(met);
    let geo = opts.geodesy;
    let probe = Outline::new(area, geo, 0.0);
    let reference = probe
        .frames
        .first()
        .and_then(|f| f.1.first())
        .and_then(|r| r.first())
        .map_or(0.0, |p| p[0].to_degrees());
    let outline = Outline::new(area, geo, reference);
    let shown = near_times(met);
    let f = around(&outline, opts);
    let mut body = clip(&f);
    let area_colour = COLOURS[0];
    let mut all_entries: Vec<f64> = met
        .iter()
        .take(8)
        .flat_map(|m| entries(m.encounter))
        .collect();
    all_entries.truncate(8);
    let mut labels = Vec::new();
    if let Some(at) = area_on_map(&mut body, &f, &outline, shown, &all_entries, area_colour) {
        labels.push((area.id.clone(), at, area_colour, Prefer::Centre));
    }
    let tracks: Vec<Track> = met
        .iter()
        .map(|m| Track::new(m.other, geo, opts.max_gap_s, reference))
        .collect();
    let colour = |i: usize| 1 + i % (COLOURS.len() - 1);
    for (i, (m, t)) in met.iter().zip(&tracks).enumerate() {
        pair_on_map(&mut body, &f, t, m.encounter, COLOURS[colour(i)], true);
    }
    let mut dense = 0;
    let mut placer = Placer::default();
    for (i, (m, t)) in met.iter().zip(&tracks).enumerate() {
        let name = mover_name(&m.other.id, m.other.callsign.as_deref());
        track_line(&mut body, &f, t, COLOURS[colour(i)], &name, &mut dense);
        if let Some(b) = pair_on_map(&mut body, &f, t, m.encounter, COLOURS[colour(i)], false) {
            placer.reserve(b);
        }
        if i < MAX_ROWS {
            if let Some(p) = entries(m.encounter).first().and_then(|&s| t.point(s)) {
                labels.push((
                    m.other.id.clone(),
                    f.pt(p, 0.0),
                    COLOURS[colour(i)],
                    Prefer::Above,
                ));
            }
        }
    }
    // the area's outline again over the tracks, which may hide it
    let first = if outline.is_static {
        Some(0.0)
    } else {
        all_entries.first().copied()
    };
    if let Some(r) = first.and_then(|t| outline.at(t)) {
        let style = format!("fill=\"none\" stroke=\"{area_colour}\" stroke-width=\"1.5\"");
        rings_path(&mut body, &f, &r, &style);
    }
    body.push_str("</g>\n");
    place_labels(&mut body, &mut placer, &f, &labels);
    let rows = rows_of(met, |t| mover_name(&t.id, t.callsign.as_deref()), colour);
    let mut notes = vec!["colours: movers in turn; the area in blue".to_owned()];
    if dense > 0 {
        notes.push(format!(
            "fixes of {dense} track{} too dense to dot at this scale",
            if dense == 1 { "" } else { "s" }
        ));
    }
    if !outline.is_static && met.len() > 8 {
        notes.push("the area filled at the first 8 movers' entries".to_owned());
    }
    let n = met.len();
    let name = area
        .name
        .as_deref()
        .filter(|s| *s != area.id)
        .map_or(area.id.clone(), |s| format!("{} ({s})", area.id));
    draw(Sheet {
        title: format!(
            "{name}: {n} mover{} met ({})",
            if n == 1 { "" } else { "s" },
            options_text(opts)
        ),
        frame: f,
        body,
        rows,
        shown,
        notes,
        keyframed: !outline.is_static,
        shared_gaps: false,
        geo,
    })
}

/// The legend's samples for an encounters picture (a keyframed area's faint outline when
/// there is one).
fn samples(keyframed: bool) -> Vec<(Sample, String)> {
    let c = COLOURS[0];
    let mut out = vec![(
        Sample::Boxed(format!(
            "fill=\"{c}\" fill-opacity=\"0.08\" stroke=\"{c}\" stroke-width=\"1.5\""
        )),
        if keyframed {
            "area (moving: as entered)"
        } else {
            "area (holes unfilled)"
        },
    )];
    if keyframed {
        out.push((
            Sample::Boxed(format!(
                "fill=\"none\" stroke=\"{c}\" stroke-opacity=\"0.35\""
            )),
            "moving area at a keyframe",
        ));
    }
    out.extend([
        (Sample::Lined("stroke=\"#333\" stroke-width=\"1.2\"".to_owned()), "track, fixes (dots)"),
        (Sample::Lined("stroke=\"#777\" stroke-width=\"1.5\" stroke-dasharray=\"1 4\"".to_owned()), "gap: no fixes"),
        (Sample::Lined(format!("stroke=\"{c}\" stroke-width=\"4.5\"")), "inside"),
        (Sample::Lined(format!("stroke=\"{c}\" stroke-width=\"4.5\" stroke-dasharray=\"7 5\"")), "possibly inside"),
        (Sample::Lined(format!("stroke=\"{c}\" stroke-opacity=\"0.3\" stroke-width=\"11\"")), "near"),
        (Sample::Lined(format!("stroke=\"{c}\" stroke-opacity=\"0.3\" stroke-width=\"11\" stroke-dasharray=\"10 6\"")), "possibly near"),
        (Sample::Lined("stroke=\"red\" stroke-width=\"2\"".to_owned()), "first loss of separation"),
        (Sample::Boxed(format!("fill=\"{c}\" fill-opacity=\"0.3\"")), "timeline: near"),
        (Sample::Boxed("fill=\"url(#hatch0)\"".to_owned()), "timeline: possibly near"),
        (Sample::Boxed(format!("fill=\"{c}\"")), "timeline: inside"),
        (Sample::Boxed("fill=\"#888\" fill-opacity=\"0.25\"".to_owned()), "timeline: gap"),
    ]);
    out.into_iter().map(|(s, t)| (s, t.to_owned())).collect()
}

/// The SVG document of `s`: title, map with its graticule, timeline below, legend right.
fn draw(s: Sheet) -> String {
    let f = &s.frame;
    let mut map = String::new();
    grid::graticule(&mut map, f, s.geo, grid::step(f.k));
    let [_, _, map_right, map_bottom] = f.rect();
    let axis = Axis {
        left: 8.0,
        top: map_bottom + 50.0,
        width: (map_right - 8.0 - LABEL_W).max(560.0),
        t: s.shown,
    };
    let mut tl = String::new();
    let tl_h = timeline::timeline(&mut tl, &axis, &s.rows, MAX_ROWS, s.shared_gaps);
    let right = (axis.left + LABEL_W + axis.width).max(map_right) + 16.0;
    let mut legend_svg = String::new();
    let legend_h = legend::legend(
        &mut legend_svg,
        (right, MAP_AT.1),
        &samples(s.keyframed),
        &s.notes,
    );
    let w = right + legend::WIDTH;
    let h = (axis.top + tl_h + 16.0).max(MAP_AT.1 + legend_h + 16.0);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w:.0}\" height=\"{h:.0}\" \
         viewBox=\"0 0 {w:.0} {h:.0}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    timeline::hatches(&mut out, &COLOURS);
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"24\" font-size=\"15\">{}</text>",
        8.0,
        esc(&s.title)
    );
    out.push_str(&map);
    out.push_str(&s.body);
    out.push_str(&tl);
    out.push_str(&legend_svg);
    out.push_str("</svg>\n");
    out
}
