//! What the picture shows of the scenario, each in its panel: areas, tracks (paper B's
//! Figs 2–5: swept hulls, rectangles at each leg's ends, the direction of travel),
//! conflict regions, and with detail stage 1's boxes (eqs 3–6) and stage 3's projections
//! (eqs 10–11, Fig 4); the labels asked for each; and a ring around a feature too small
//! to see at the picture's scale.

use super::labels::{Class, Prefer, Request};
use super::layout::{mid, Layout, Turns};
use super::{esc, hours, PALETTE};
use crate::conflict::{geom, pipeline, Motion, Object};
use crate::scenario::Scenario;
use crate::sphere::Merc;
use std::fmt::Write as _;

/// A region's polygon: its exterior ring and holes (Mercator).
type Polygon = (Vec<Merc>, Vec<Vec<Merc>>);

/// Up to this many features, tracks are labelled with their times as well as their ids.
pub(super) const TIMED_FEATURES: usize = 40;
/// Up to this many conflicts, each region is labelled with its window.
pub(super) const LABELLED_CONFLICTS: usize = 60;
/// A feature drawn smaller than this (pixels, its larger side) gets a ring around it.
const SPECK_PX: f64 = 6.0;
/// The radius of that ring (pixels).
const SPECK_RING_PX: f64 = 10.0;

/// The scenario, its objects (each once) and conflicts, laid out.
pub(super) struct Scene<'a> {
    pub sc: &'a Scenario,
    pub objects: &'a [&'a Object],
    pub conflicts: &'a [pipeline::Conflict],
    pub turns: &'a Turns,
    pub layout: &'a Layout,
}

/// The labels asked for, in the order they are placed: features' ids first, then the
/// conflicts' windows, then the tracks' times.
#[derive(Default)]
pub(super) struct Asked {
    pub features: Vec<Request>,
    pub windows: Vec<Request>,
    pub times: Vec<Request>,
    /// Marks labels must leave clear (pixels): the arrowheads at the tracks' ends.
    pub marks: Vec<[f64; 4]>,
}

/// Half the side (pixels) of the box kept clear of labels around an arrowhead.
const ARROW_PX: f64 = 6.0;

impl Scene<'_> {
    /// The panel (its index) and whole-turn shift of something whose box is `b`.
    fn place(&self, b: [f64; 4]) -> (usize, f64) {
        let dx = self.turns.dx(mid(b));
        (self.layout.panel_of(mid(b) + dx, 0.5 * (b[1] + b[3])), dx)
    }

    /// Stage 1's bounding boxes (eqs 3–6).
    pub fn boxes(&self, out: &mut String) {
        for o in self.objects {
            let (p, dx) = self.place(o.aabb);
            let a = o.aabb;
            let ring = [[a[0], a[1]], [a[2], a[1]], [a[2], a[3]], [a[0], a[3]]];
            let _ = writeln!(
                out,
                "<path d=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.7\" \
                 stroke-dasharray=\"1 3\"/>",
                self.layout.frames[p].path(&ring, dx, true)
            );
        }
    }

    /// The areas and tracks, and the labels they ask for: each feature's id, and with
    /// few features the tracks' times (each leg's end, the first leg's start with the id).
    pub fn features(&self, out: &mut String, asked: &mut Asked) {
        let timed = self.sc.features.len() <= TIMED_FEATURES;
        let mut named = vec![false; self.sc.features.len()];
        for o in self.objects {
            let owner = o.owner as usize;
            let id = &self.sc.features[owner].id;
            let colour = PALETTE[owner % PALETTE.len()];
            let (p, dx) = self.place(o.aabb);
            let f = &self.layout.frames[p];
            let label = |text: String, at: (f64, f64), prefer: Prefer, class: Class| Request {
                text,
                anchor: at,
                frame: f.rect(),
                colour,
                size: 12.0,
                prefer,
                class,
            };
            let first = !named[owner];
            named[owner] = true;
            match &o.motion {
                Motion::Static { ring, holes, .. } => {
                    let mut d = f.path(ring, dx, true);
                    for hole in holes {
                        d.push(' ');
                        d.push_str(&f.path(hole, dx, true));
                    }
                    let _ = writeln!(
                        out,
                        "<path d=\"{d}\" fill=\"{colour}\" fill-opacity=\"0.08\" \
                         fill-rule=\"evenodd\" stroke=\"{colour}\" stroke-width=\"1.5\">\
                         <title>area {}</title></path>",
                        esc(id)
                    );
                    if first {
                        let n = ring.len().max(1) as f64;
                        let c = ring
                            .iter()
                            .fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n]);
                        let at = f.pt(c, dx);
                        asked
                            .features
                            .push(label(id.clone(), at, Prefer::Centre, Class::Feature));
                    }
                }
                Motion::Moving(leg) => {
                    let (start, end) = track(out, f, o, leg, dx, colour, id);
                    let (x, y) = end;
                    asked
                        .marks
                        .push([x - ARROW_PX, y - ARROW_PX, x + ARROW_PX, y + ARROW_PX]);
                    if first {
                        let text = if timed {
                            format!("{id} {}", hours(leg.t0))
                        } else {
                            id.clone()
                        };
                        asked
                            .features
                            .push(label(text, start, Prefer::Above, Class::Feature));
                    }
                    if timed {
                        let text = hours(leg.t1);
                        asked
                            .times
                            .push(label(text, end, Prefer::Below, Class::Time));
                    }
                }
            }
        }
    }

    /// The conflict regions with their windows (labels asked for when there are few), and
    /// with `detail` stage 3's projections of each region's vertices onto the tracks.
    pub fn conflicts(&self, out: &mut String, detail: bool, asked: &mut Asked) {
        let labelled = self.conflicts.len() <= LABELLED_CONFLICTS;
        for c in self.conflicts {
            let (ia, ib) = (
                &self.sc.features[c.a as usize].id,
                &self.sc.features[c.b as usize].id,
            );
            let window = if c.t_start.is_finite() || c.t_end.is_finite() {
                format!("{ia} × {ib}: {} to {}", hours(c.t_start), hours(c.t_end))
            } else {
                format!("{ia} × {ib}: always")
            };
            let polys = geom::polygons(&c.rings);
            for (ext, holes) in &polys {
                let (p, dx) = self.place(geom::bbox(ext));
                let f = &self.layout.frames[p];
                let mut d = f.path(ext, dx, true);
                for hole in holes {
                    d.push(' ');
                    d.push_str(&f.path(hole, dx, true));
                }
                let _ = writeln!(
                    out,
                    "<path d=\"{d}\" fill=\"red\" fill-opacity=\"0.35\" fill-rule=\"evenodd\" \
                     stroke=\"red\" stroke-dasharray=\"2 2\"><title>{}</title></path>",
                    esc(&window)
                );
            }
            if detail {
                self.projections(out, c, &polys);
            }
            if let (true, Some((ext, _))) = (labelled, polys.first()) {
                let bb = geom::bbox(ext);
                let (p, dx) = self.place(bb);
                let f = &self.layout.frames[p];
                asked.windows.push(Request {
                    text: window,
                    anchor: f.pt([bb[2], bb[3]], dx),
                    frame: f.rect(),
                    colour: "#b00000",
                    size: 11.0,
                    prefer: Prefer::UpRight,
                    class: Class::Window,
                });
            }
        }
    }

    /// Stage 3 (eqs 10–11): each vertex of the conflict's regions projected onto the line
    /// of each leg of its two tracks.
    fn projections(&self, out: &mut String, c: &pipeline::Conflict, polys: &[Polygon]) {
        for o in self
            .objects
            .iter()
            .filter(|o| o.owner == c.a || o.owner == c.b)
        {
            let Motion::Moving(leg) = &o.motion else {
                continue;
            };
            let (p, dx) = self.place(o.aabb);
            let f = &self.layout.frames[p];
            let (p0, p1) = (leg.merc[0], leg.merc[1]);
            let d = [p1[0] - p0[0], p1[1] - p0[1]];
            let n2 = d[0] * d[0] + d[1] * d[1];
            for (ext, _) in polys {
                let rdx = self.turns.dx(mid(geom::bbox(ext)));
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
                        "<line x1=\"{xa:.2}\" y1=\"{ya:.2}\" x2=\"{xb:.2}\" y2=\"{yb:.2}\" \
                         stroke=\"red\" stroke-width=\"0.5\" stroke-opacity=\"0.6\"/>"
                    );
                }
            }
        }
    }

    /// A dashed ring around each feature drawn smaller than [`SPECK_PX`], so that it stays
    /// visible; how many there are.
    pub fn specks(&self, out: &mut String) -> usize {
        let n = self.sc.features.len();
        let mut extent: Vec<Option<(usize, [f64; 4])>> = vec![None; n];
        for o in self.objects {
            let (p, dx) = self.place(o.aabb);
            let f = &self.layout.frames[p];
            let (x0, y0) = f.pt([o.aabb[0], o.aabb[3]], dx);
            let (x1, y1) = f.pt([o.aabb[2], o.aabb[1]], dx);
            let e = &mut extent[o.owner as usize];
            *e = Some(match *e {
                None => (p, [x0, y0, x1, y1]),
                Some((q, b)) => (q, [b[0].min(x0), b[1].min(y0), b[2].max(x1), b[3].max(y1)]),
            });
        }
        let mut count = 0;
        for (owner, e) in extent.iter().enumerate() {
            let Some((_, b)) = e else { continue };
            if (b[2] - b[0]).max(b[3] - b[1]) >= SPECK_PX {
                continue;
            }
            count += 1;
            let _ = writeln!(
                out,
                "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{SPECK_RING_PX}\" fill=\"none\" \
                 stroke=\"{}\" stroke-width=\"1.2\" stroke-dasharray=\"3 2\"/>",
                0.5 * (b[0] + b[2]),
                0.5 * (b[1] + b[3]),
                PALETTE[owner % PALETTE.len()]
            );
        }
        count
    }
}

/// One leg of a track: its swept hull (eq 7), its rectangle at both ends, and its line
/// with the direction of travel; the pixels of its start and end.
fn track(
    out: &mut String,
    f: &super::frame::Frame,
    o: &Object,
    leg: &crate::sphere::Leg,
    dx: f64,
    colour: &str,
    id: &str,
) -> ((f64, f64), (f64, f64)) {
    let id = esc(id);
    let _ = writeln!(
        out,
        "<path d=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-dasharray=\"5 3\">\
         <title>track {id}: swept hull of a leg</title></path>",
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
         stroke-width=\"1.5\" marker-end=\"url(#arrow)\"><title>track {id}: {} to {}</title>\
         </line>",
        hours(leg.t0),
        hours(leg.t1)
    );
    ((x0, y0), (x1, y1))
}
