//! Paper B's figures (Figs 2–5) for a scenario and its conflicts, as SVG: areas, tracks
//! with their swept hulls, rectangles at each leg's ends and direction, conflict regions
//! with their windows, a longitude–latitude graticule on the Mercator plane, and a
//! legend. With `detail`, also stage 1's bounding boxes (eqs 3–6) and stage 3's
//! projections of each region's vertices onto the track (eqs 10–11, Fig 4).

use crate::conflict::{geom, pipeline, Motion, Object};
use crate::scenario::{Longitudes, Scenario};
use crate::sphere::{LonLat, Merc};
use std::f64::consts::TAU;
use std::fmt::Write as _;

/// What to draw beyond the scene itself.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Stage 1's bounding boxes and stage 3's projection lines (the paper's Figs 2–5).
    pub detail: bool,
}

/// Features take turns in the paper's colours (blue, green) and two more.
const PALETTE: [&str; 4] = ["#1f4fd8", "#1a8a3a", "#7b2fa8", "#d2691e"];

/// Above this many conflicts the windows are tooltips only (labels would cover the map).
const LABELLED_CONFLICTS: usize = 60;
/// Above this many features the ids are tooltips only.
const LABELLED_FEATURES: usize = 120;

/// The plot's frame: Mercator x, y to picture coordinates.
struct Frame {
    b: [f64; 4],
    k: f64,
    left: f64,
    top: f64,
}

impl Frame {
    fn pt(&self, p: Merc, dx: f64) -> (f64, f64) {
        (
            self.left + (p[0] + dx - self.b[0]) * self.k,
            self.top + (self.b[3] - p[1]) * self.k,
        )
    }

    fn path(&self, ring: &[Merc], dx: f64, close: bool) -> String {
        let mut s = String::new();
        for (i, &p) in ring.iter().enumerate() {
            let (x, y) = self.pt(p, dx);
            let _ = write!(s, "{}{x:.2},{y:.2} ", if i == 0 { "M" } else { "L" });
        }
        if close {
            s.push('Z');
        }
        s
    }

    fn width(&self) -> f64 {
        (self.b[2] - self.b[0]) * self.k
    }

    fn height(&self) -> f64 {
        (self.b[3] - self.b[1]) * self.k
    }
}

/// Text labels, written last (on top), each moved up or down by whole lines until it
/// covers no label placed before it (greedy; at most a few lines away).
struct Labels {
    placed: Vec<[f64; 4]>,
    svg: String,
    /// The plot's left and right ends: a label is moved along x to stay between them.
    x_range: (f64, f64),
}

impl Labels {
    /// A label at (x, y) (its baseline; centred on x when `middle`).
    fn add(&mut self, x: f64, y: f64, middle: bool, colour: &str, size: f64, text: &str) {
        // the text's box, from a mean glyph width of 0.6 em
        let w = 0.6 * size * text.chars().count() as f64;
        let x0 = if middle { x - 0.5 * w } else { x };
        let x0 = x0.min(self.x_range.1 - w).max(self.x_range.0);
        let x = if middle { x0 + 0.5 * w } else { x0 };
        let free = |y: f64, placed: &[[f64; 4]]| {
            let b = [x0, y - size, x0 + w, y + 2.0];
            !placed
                .iter()
                .any(|p| b[0] < p[2] && p[0] < b[2] && b[1] < p[3] && p[1] < b[3])
        };
        let y = [0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 4.0, -4.0]
            .iter()
            .map(|k| y + k * (size + 2.0))
            .find(|&y| free(y, &self.placed))
            .unwrap_or(y);
        self.placed.push([x0, y - size, x0 + w, y + 2.0]);
        let anchor = if middle {
            " text-anchor=\"middle\""
        } else {
            ""
        };
        let _ = writeln!(
            self.svg,
            "<text x=\"{x:.2}\" y=\"{y:.2}\"{anchor} fill=\"{colour}\" font-size=\"{size}\" \
             paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">{text}</text>"
        );
    }
}

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

/// A step of the graticule (degrees) that gives a few lines over `span` degrees.
fn grid_step(span: f64) -> f64 {
    const STEPS: [f64; 16] = [
        0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0,
    ];
    STEPS
        .iter()
        .copied()
        .find(|&s| span / s <= 8.0)
        .unwrap_or(90.0)
}

/// A longitude label, wrapped into (−180, 180].
fn lon_label(deg: f64) -> String {
    let l = crate::scenario::normal_lon(deg);
    let a = (l.abs() * 100.0).round() / 100.0;
    if a == 0.0 || a == 180.0 {
        format!("{a}°")
    } else if l > 0.0 {
        format!("{a}°E")
    } else {
        format!("{a}°W")
    }
}

fn lat_label(deg: f64) -> String {
    let a = (deg.abs() * 100.0).round() / 100.0;
    if a == 0.0 {
        "0°".to_owned()
    } else if deg > 0.0 {
        format!("{a}°N")
    } else {
        format!("{a}°S")
    }
}

/// Paper B's figures for `sc` (its stage objects and conflicts), as SVG text.
pub fn svg(
    sc: &Scenario,
    objects: &[Object],
    conflicts: &[pipeline::Conflict],
    opts: Options,
) -> String {
    // each object once: its first copy on the Earth (Object::on_earth)
    let objects: Vec<&Object> = objects.iter().filter(|o| o.copy == 0).collect();
    // On the Earth every object and region is drawn moved by whole turns to lie within
    // half a turn of the scenario's mean longitude (its circular mean), so that objects
    // meeting across the antimeridian are drawn side by side.
    let mid = |r: [f64; 4]| 0.5 * (r[0] + r[2]);
    let (sin, cos) = objects.iter().fold((0.0, 0.0), |(s, c), o| {
        (s + mid(o.aabb).sin(), c + mid(o.aabb).cos())
    });
    let centre = sin.atan2(cos);
    let earth = sc.longitudes == Longitudes::Earth;
    let turn = |x: f64| {
        let k = ((x - centre) / TAU).round();
        if earth && k.is_finite() {
            -TAU * k
        } else {
            0.0
        }
    };
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for o in &objects {
        let dx = turn(mid(o.aabb));
        b[0] = b[0].min(o.aabb[0] + dx);
        b[1] = b[1].min(o.aabb[1]);
        b[2] = b[2].max(o.aabb[2] + dx);
        b[3] = b[3].max(o.aabb[3]);
    }
    if !b.iter().all(|v| v.is_finite()) {
        b = [-0.01, -0.01, 0.01, 0.01];
    }
    // a margin of 4 % around the objects
    let pad = 0.04 * (b[2] - b[0]).max(b[3] - b[1]).max(1e-6);
    b = [b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad];
    let size = 900.0;
    let span = (b[2] - b[0]).max(b[3] - b[1]);
    let f = Frame {
        b,
        k: size / span,
        left: 70.0,
        top: 40.0,
    };
    let (w, h) = (f.width(), f.height());
    let legend_w = 250.0;
    let total_w = f.left + w + 20.0 + legend_w;
    let total_h = (f.top + h + 50.0).max(330.0);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{total_w:.0}\" height=\"{total_h:.0}\" \
         viewBox=\"0 0 {total_w:.0} {total_h:.0}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"8\" \
         markerHeight=\"8\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" \
         fill=\"context-stroke\"/></marker></defs>\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"22\" font-size=\"15\">{} feature{}, {} conflict{} (Mercator plane)</text>",
        f.left,
        sc.features.len(),
        if sc.features.len() == 1 { "" } else { "s" },
        conflicts.len(),
        if conflicts.len() == 1 { "" } else { "s" }
    );
    // The graticule: meridians and parallels at a round step, labelled on the frame.
    let lon0 = b[0].to_degrees();
    let lon1 = b[2].to_degrees();
    let geo = sc.geodesy;
    let lat0 = geo.inverse_mercator([0.0, b[1]]).lat.to_degrees();
    let lat1 = geo.inverse_mercator([0.0, b[3]]).lat.to_degrees();
    let step = grid_step((lon1 - lon0).max(lat1 - lat0));
    let _ = writeln!(
        out,
        "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"{w:.2}\" height=\"{h:.2}\" fill=\"none\" stroke=\"#888\"/>",
        f.left, f.top
    );
    let mut g = (lon0 / step).ceil() * step;
    while g <= lon1 {
        let (x, _) = f.pt([g.to_radians(), 0.0], 0.0);
        let _ = writeln!(
            out,
            "<line x1=\"{x:.2}\" y1=\"{:.2}\" x2=\"{x:.2}\" y2=\"{:.2}\" stroke=\"#ddd\"/>\
             <text x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#555\">{}</text>",
            f.top,
            f.top + h,
            f.top + h + 16.0,
            lon_label(g)
        );
        g += step;
    }
    let mut g = (lat0 / step).ceil() * step;
    while g <= lat1 {
        let y = geo.mercator(LonLat::from_degrees(0.0, g))[1];
        let (_, py) = f.pt([0.0, y], 0.0);
        let _ = writeln!(
            out,
            "<line x1=\"{:.2}\" y1=\"{py:.2}\" x2=\"{:.2}\" y2=\"{py:.2}\" stroke=\"#ddd\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#555\">{}</text>",
            f.left,
            f.left + w,
            f.left - 6.0,
            py + 4.0,
            lat_label(g)
        );
        g += step;
    }
    let label_features = sc.features.len() <= LABELLED_FEATURES;
    if opts.detail {
        // stage 1's boxes (eqs 3–6)
        for o in &objects {
            let dx = turn(mid(o.aabb));
            let a = o.aabb;
            let ring = [[a[0], a[1]], [a[2], a[1]], [a[2], a[3]], [a[0], a[3]]];
            let _ = writeln!(
                out,
                "<path d=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.7\" stroke-dasharray=\"1 3\"/>",
                f.path(&ring, dx, true)
            );
        }
    }
    let mut named = vec![false; sc.features.len()];
    let mut labels = Labels {
        placed: Vec::new(),
        svg: String::new(),
        x_range: (f.left, f.left + w),
    };
    for o in &objects {
        let owner = o.owner as usize;
        let id = esc(&sc.features[owner].id);
        let colour = PALETTE[owner % PALETTE.len()];
        let dx = turn(mid(o.aabb));
        match &o.motion {
            Motion::Static { ring, holes, .. } => {
                let mut d = f.path(ring, dx, true);
                for hole in holes {
                    d.push(' ');
                    d.push_str(&f.path(hole, dx, true));
                }
                let _ = writeln!(
                    out,
                    "<path d=\"{d}\" fill=\"{colour}\" fill-opacity=\"0.08\" fill-rule=\"evenodd\" \
                     stroke=\"{colour}\" stroke-width=\"1.5\"><title>area {id}</title></path>"
                );
                if label_features && !named[owner] {
                    named[owner] = true;
                    let n = ring.len().max(1) as f64;
                    let c = ring
                        .iter()
                        .fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n]);
                    let (x, y) = f.pt(c, dx);
                    labels.add(x, y, true, colour, 12.0, &id);
                }
            }
            Motion::Moving(leg) => {
                let _ = writeln!(
                    out,
                    "<path d=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-dasharray=\"5 3\"><title>track {id}: swept hull of a leg</title></path>",
                    f.path(&o.sweep, dx, true)
                );
                for t in [leg.t0, leg.t1] {
                    let _ = writeln!(
                        out,
                        "<path d=\"{}\" fill=\"{colour}\" fill-opacity=\"0.15\" stroke=\"{colour}\"/>",
                        f.path(&leg.merc_vertices_at(t), dx, true)
                    );
                }
                let (x0, y0) = f.pt(leg.merc[0], dx);
                let (x1, y1) = f.pt(leg.merc[1], dx);
                let _ = writeln!(
                    out,
                    "<line x1=\"{x0:.2}\" y1=\"{y0:.2}\" x2=\"{x1:.2}\" y2=\"{y1:.2}\" stroke=\"{colour}\" \
                     stroke-width=\"1.5\" marker-end=\"url(#arrow)\"><title>track {id}: {} to {}</title></line>",
                    hours(leg.t0),
                    hours(leg.t1)
                );
                if label_features {
                    let first = !named[owner];
                    named[owner] = true;
                    let name = if first {
                        format!("{id} ")
                    } else {
                        String::new()
                    };
                    let start = format!("{name}{}", hours(leg.t0));
                    labels.add(x0, y0 - 8.0, true, colour, 12.0, &start);
                    labels.add(x1, y1 + 16.0, true, colour, 12.0, &hours(leg.t1));
                }
            }
        }
    }
    let label_conflicts = conflicts.len() <= LABELLED_CONFLICTS;
    for c in conflicts {
        let (ia, ib) = (
            esc(&sc.features[c.a as usize].id),
            esc(&sc.features[c.b as usize].id),
        );
        let window = if c.t_start.is_finite() || c.t_end.is_finite() {
            format!("{ia} × {ib}: {} to {}", hours(c.t_start), hours(c.t_end))
        } else {
            format!("{ia} × {ib}: always")
        };
        let polys = geom::polygons(&c.rings);
        for (ext, holes) in &polys {
            let dx = turn(mid(geom::bbox(ext)));
            let mut d = f.path(ext, dx, true);
            for hole in holes {
                d.push(' ');
                d.push_str(&f.path(hole, dx, true));
            }
            let _ = writeln!(
                out,
                "<path d=\"{d}\" fill=\"red\" fill-opacity=\"0.35\" fill-rule=\"evenodd\" stroke=\"red\" \
                 stroke-dasharray=\"2 2\"><title>{window}</title></path>"
            );
        }
        if opts.detail {
            // stage 3: each region vertex projected onto the track's line (eqs 10–11)
            for o in objects.iter().filter(|o| o.owner == c.a || o.owner == c.b) {
                let Motion::Moving(leg) = &o.motion else {
                    continue;
                };
                let dx = turn(mid(o.aabb));
                let (p0, p1) = (leg.merc[0], leg.merc[1]);
                let d = [p1[0] - p0[0], p1[1] - p0[1]];
                let n2 = d[0] * d[0] + d[1] * d[1];
                for (ext, _) in &polys {
                    let rdx = turn(mid(geom::bbox(ext)));
                    for &v in ext {
                        let v = [v[0] + rdx - dx, v[1]];
                        let s = if n2 > 0.0 {
                            (((v[0] - p0[0]) * d[0] + (v[1] - p0[1]) * d[1]) / n2).clamp(0.0, 1.0)
                        } else {
                            0.0
                        };
                        let foot = [p0[0] + s * d[0], p0[1] + s * d[1]];
                        let (xa, ya) = f.pt(v, dx);
                        let (xb, yb) = f.pt(foot, dx);
                        let _ = writeln!(
                            out,
                            "<line x1=\"{xa:.2}\" y1=\"{ya:.2}\" x2=\"{xb:.2}\" y2=\"{yb:.2}\" stroke=\"red\" stroke-width=\"0.5\" stroke-opacity=\"0.6\"/>"
                        );
                    }
                }
            }
        }
        if label_conflicts {
            if let Some((ext, _)) = polys.first() {
                let bb = geom::bbox(ext);
                let dx = turn(mid(bb));
                let (x, y) = f.pt([bb[2], bb[3]], dx);
                labels.add(x + 3.0, y - 3.0, false, "#b00000", 11.0, &window);
            }
        }
    }
    out.push_str(&labels.svg);
    // The legend.
    let lx = f.left + w + 20.0;
    let mut ly = f.top;
    let _ = writeln!(
        out,
        "<rect x=\"{lx:.2}\" y=\"{ly:.2}\" width=\"{:.2}\" height=\"{}\" fill=\"white\" stroke=\"#888\"/>",
        legend_w - 10.0,
        if opts.detail { 255 } else { 195 }
    );
    ly += 22.0;
    let c0 = PALETTE[0];
    let sx = lx + 10.0;
    let boxed = |y: f64, style: &str| {
        format!(
            "<rect x=\"{sx:.2}\" y=\"{:.2}\" width=\"28\" height=\"14\" {style}/>",
            y - 7.0
        )
    };
    let lined = |y: f64, style: &str| {
        format!(
            "<line x1=\"{sx:.2}\" y1=\"{y:.2}\" x2=\"{:.2}\" y2=\"{y:.2}\" {style}/>",
            sx + 28.0
        )
    };
    let mut entries: Vec<(String, &str)> = vec![
        (
            boxed(
                ly,
                &format!(
                    "fill=\"{c0}\" fill-opacity=\"0.08\" stroke=\"{c0}\" stroke-width=\"1.5\""
                ),
            ),
            "area (holes unfilled)",
        ),
        (
            lined(
                ly + 30.0,
                &format!("stroke=\"{c0}\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\""),
            ),
            "track, direction of travel",
        ),
        (
            boxed(
                ly + 60.0,
                &format!("fill=\"{c0}\" fill-opacity=\"0.15\" stroke=\"{c0}\""),
            ),
            "rectangle at a leg's start, end",
        ),
        (
            boxed(
                ly + 90.0,
                &format!("fill=\"none\" stroke=\"{c0}\" stroke-dasharray=\"5 3\""),
            ),
            "swept hull of a leg (eq 7)",
        ),
        (
            boxed(
                ly + 120.0,
                "fill=\"red\" fill-opacity=\"0.35\" stroke=\"red\" stroke-dasharray=\"2 2\"",
            ),
            "conflict region, window (h)",
        ),
    ];
    if opts.detail {
        entries.push((
            boxed(
                ly + 150.0,
                "fill=\"none\" stroke=\"#999\" stroke-dasharray=\"1 3\"",
            ),
            "bounding box (eqs 3–6)",
        ));
        entries.push((
            lined(ly + 180.0, "stroke=\"red\" stroke-width=\"0.5\""),
            "projection on a track (eq 10)",
        ));
    }
    for (sample, text) in &entries {
        let _ = writeln!(
            out,
            "{sample}<text x=\"{:.2}\" y=\"{:.2}\">{text}</text>",
            lx + 48.0,
            ly + 4.0
        );
        ly += 30.0;
    }
    let _ = writeln!(
        out,
        "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#555\" font-size=\"11\">colours: features in turn</text>",
        sx,
        ly + 4.0
    );
    out.push_str("</svg>\n");
    out
}
