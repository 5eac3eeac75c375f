//! Text labels placed without overlap: a greedy placement over candidate positions.
//!
//! Each label has an anchor (the point it names) and a box estimated from its text (a
//! mean glyph width of 0.62 em, which sans-serif digits and lower-case letters stay
//! under). In the order asked, each label takes the first candidate position whose box
//! lies inside its panel's plot and overlaps no label placed before (nor a mark kept
//! clear, such as an arrowhead): on the anchor or
//! beside it (as the label prefers), then around it at growing distances. A label set
//! away from its anchor gets a leader line back to it. A label with no free position is
//! left out and counted; its text stays in the drawing's tooltip.

use super::esc;
use std::fmt::Write as _;

/// Mean glyph width, in em, for a label's box.
const GLYPH_EM: f64 = 0.62;
/// Space kept around a label's text (pixels).
const PAD: f64 = 1.5;
/// Distances (pixels) from the anchor at which a label is tried, nearest first.
const RINGS: [f64; 6] = [3.0, 10.0, 20.0, 34.0, 52.0, 76.0];
/// A label whose box is farther than this (pixels) from its anchor gets a leader line.
const LEADER_FROM: f64 = 8.0;
/// The side (pixels) of the cells that index the labels placed, so that a candidate is
/// compared with the labels near it only.
const CELL: f64 = 48.0;

/// Where a label would rather be, tried first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Prefer {
    /// Centred on the anchor (an area's name inside it).
    Centre,
    /// Above the anchor (a track's name at its start).
    Above,
    /// Below the anchor (a time at a leg's end).
    Below,
    /// Up and right of the anchor (a conflict's window at its region's corner).
    UpRight,
}

/// The kinds of label, counted apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Class {
    /// A feature's id.
    Feature = 0,
    /// A conflict's window.
    Window = 1,
    /// A time along a track.
    Time = 2,
}

/// A label asked for.
#[derive(Clone, Debug)]
pub(super) struct Request {
    /// The text (not escaped).
    pub text: String,
    /// The point it names (pixels).
    pub anchor: (f64, f64),
    /// The plot it must stay inside (pixels, `[x0, y0, x1, y1]`).
    pub frame: [f64; 4],
    /// Its colour.
    pub colour: &'static str,
    /// Its font size (pixels).
    pub size: f64,
    /// Where it would rather be.
    pub prefer: Prefer,
    /// What it names.
    pub class: Class,
}

/// One label placed: its box (pixels, `[x0, y0, x1, y1]`, its padding included) and the
/// plot it lies in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// The label's box.
    pub bbox: [f64; 4],
    /// The plot it lies in.
    pub frame: [f64; 4],
}

/// The labels placed so far, and how many of each [`Class`] were asked for and placed.
#[derive(Default)]
pub(super) struct Placer {
    /// The labels placed.
    pub placed: Vec<Placed>,
    /// Per class: asked for, placed.
    pub counts: [(usize, usize); 3],
    /// The boxes no label may cover: the labels placed, and the marks reserved.
    taken: Vec<[f64; 4]>,
    /// The boxes taken (their indices) in each cell they reach.
    cells: std::collections::HashMap<(i64, i64), Vec<usize>>,
    leaders: String,
    texts: String,
}

/// The cells (of side [`CELL`]) a box reaches.
fn cells(b: [f64; 4]) -> impl Iterator<Item = (i64, i64)> {
    let c = |v: f64| (v / CELL).floor() as i64;
    let (i0, i1, j0, j1) = (c(b[0]), c(b[2]), c(b[1]), c(b[3]));
    (i0..=i1).flat_map(move |i| (j0..=j1).map(move |j| (i, j)))
}

/// Do two boxes overlap (more than touch)?
pub(super) fn overlap(a: [f64; 4], b: [f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Does box `a` lie inside box `outer`?
pub(super) fn inside(a: [f64; 4], outer: [f64; 4]) -> bool {
    a[0] >= outer[0] && a[1] >= outer[1] && a[2] <= outer[2] && a[3] <= outer[3]
}

/// The top-left corners (pixels) of a `w` × `h` box to try around (`x`, `y`), the
/// preferred side first.
fn candidates((x, y): (f64, f64), w: f64, h: f64, prefer: Prefer) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(1 + 8 * RINGS.len());
    let centre = (x - 0.5 * w, y - 0.5 * h);
    let around = |d: f64| {
        let e = std::f64::consts::FRAC_1_SQRT_2 * d;
        [
            (x + e, y - e - h),       // up right
            (x - 0.5 * w, y - d - h), // above
            (x - 0.5 * w, y + d),     // below
            (x + d, y - 0.5 * h),     // right
            (x - d - w, y - 0.5 * h), // left
            (x - e - w, y - e - h),   // up left
            (x + e, y + e),           // down right
            (x - e - w, y + e),       // down left
        ]
    };
    let first = RINGS[0];
    match prefer {
        Prefer::Centre => out.push(centre),
        Prefer::Above => out.push(around(first)[1]),
        Prefer::Below => out.push(around(first)[2]),
        Prefer::UpRight => out.push(around(first)[0]),
    }
    for d in RINGS {
        out.extend(around(d));
    }
    if prefer != Prefer::Centre {
        out.push(centre);
    }
    out
}

/// The point of box `b` nearest (`x`, `y`).
fn nearest(b: [f64; 4], (x, y): (f64, f64)) -> (f64, f64) {
    (x.clamp(b[0], b[2]), y.clamp(b[1], b[3]))
}

impl Placer {
    /// Places `r` at its first free candidate (module doc); false when none is free.
    pub fn add(&mut self, r: &Request) -> bool {
        self.counts[r.class as usize].0 += 1;
        let w = GLYPH_EM * r.size * r.text.chars().count() as f64 + 2.0 * PAD;
        let h = 1.2 * r.size + 2.0 * PAD;
        let free = candidates(r.anchor, w, h, r.prefer)
            .into_iter()
            .map(|(x, y)| [x, y, x + w, y + h])
            .find(|b| inside(*b, r.frame) && self.free(*b));
        let Some(b) = free else {
            return false;
        };
        self.counts[r.class as usize].1 += 1;
        self.take(b);
        self.placed.push(Placed {
            bbox: b,
            frame: r.frame,
        });
        let (nx, ny) = nearest(b, r.anchor);
        let (ax, ay) = r.anchor;
        if (nx - ax).hypot(ny - ay) > LEADER_FROM {
            let _ = writeln!(
                self.leaders,
                "<line x1=\"{ax:.2}\" y1=\"{ay:.2}\" x2=\"{nx:.2}\" y2=\"{ny:.2}\" stroke=\"{}\" \
                 stroke-width=\"0.8\" stroke-opacity=\"0.8\"/>",
                r.colour
            );
        }
        let _ = writeln!(
            self.texts,
            "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"{}\" font-size=\"{}\" paint-order=\"stroke\" \
             stroke=\"white\" stroke-width=\"3\">{}</text>",
            b[0] + PAD,
            b[3] - PAD - 0.25 * r.size,
            r.colour,
            r.size,
            esc(&r.text)
        );
        true
    }

    /// Keeps labels off the box `b` (a mark drawn there, such as an arrowhead).
    pub fn reserve(&mut self, b: [f64; 4]) {
        self.take(b);
    }

    /// Marks box `b` taken.
    fn take(&mut self, b: [f64; 4]) {
        for cell in cells(b) {
            self.cells.entry(cell).or_default().push(self.taken.len());
        }
        self.taken.push(b);
    }

    /// Does box `b` overlap no box taken?
    fn free(&self, b: [f64; 4]) -> bool {
        cells(b).all(|cell| {
            self.cells.get(&cell).map_or(true, |near| {
                near.iter().all(|&k| !overlap(b, self.taken[k]))
            })
        })
    }

    /// The labels' SVG: the leader lines, then the texts over them.
    pub fn svg(&self) -> String {
        format!("{}{}", self.leaders, self.texts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic stream in [0, 1) (a linear congruential generator).
    fn stream(mut s: u64) -> impl FnMut() -> f64 {
        move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// A 12-pixel feature label of `text` at `anchor` in `frame`.
    fn request(text: String, anchor: (f64, f64), frame: [f64; 4], prefer: Prefer) -> Request {
        Request {
            text,
            anchor,
            frame,
            colour: "#000",
            size: 12.0,
            prefer,
            class: Class::Feature,
        }
    }

    /// However crowded: no two labels' boxes overlap, every box lies inside its plot,
    /// and a label is left out only when asked for in a crowd; two panels' labels each
    /// stay in their own panel.
    #[test]
    fn labels_never_overlap_and_stay_inside_their_plot() {
        let frames = [[70.0, 40.0, 470.0, 440.0], [520.0, 40.0, 820.0, 300.0]];
        for (seed, n) in [(1u64, 10usize), (2, 60), (3, 200), (4, 1000)] {
            let mut u = stream(seed);
            let mut p = Placer::default();
            let prefers = [
                Prefer::Centre,
                Prefer::Above,
                Prefer::Below,
                Prefer::UpRight,
            ];
            for i in 0..n {
                let f = frames[i % 2];
                // anchors anywhere in the plot, edges and corners included
                let a = (f[0] + u() * (f[2] - f[0]), f[1] + u() * (f[3] - f[1]));
                let text = format!("t{i} {:.2} h", 10.0 * u());
                p.add(&request(text, a, f, prefers[i % 4]));
            }
            let (asked, placed) = p.counts[Class::Feature as usize];
            assert_eq!((asked, placed), (n, p.placed.len()));
            if n <= 10 {
                assert_eq!(placed, n, "few labels all find room");
            }
            for (i, a) in p.placed.iter().enumerate() {
                assert!(inside(a.bbox, a.frame), "{a:?}");
                assert!(frames.contains(&a.frame));
                for b in &p.placed[i + 1..] {
                    assert!(!overlap(a.bbox, b.bbox), "{a:?} and {b:?}");
                }
            }
        }
    }

    /// A label goes where it prefers when that is free, and is moved (with a leader line)
    /// when it is not; one that cannot fit its plot at all is left out and counted.
    #[test]
    fn a_label_moves_only_when_it_must() {
        let f = [0.0, 0.0, 400.0, 400.0];
        let mut p = Placer::default();
        assert!(p.add(&request("storm".into(), (200.0, 200.0), f, Prefer::Centre)));
        let b = p.placed[0].bbox;
        assert!(
            (0.5 * (b[0] + b[2]) - 200.0).abs() < 1e-9
                && (0.5 * (b[1] + b[3]) - 200.0).abs() < 1e-9
        );
        assert!(!p.svg().contains("<line"));
        // the same place again: moved beside the first, with a leader when far
        assert!(p.add(&request("storm2".into(), (200.0, 200.0), f, Prefer::Centre)));
        assert!(!overlap(p.placed[0].bbox, p.placed[1].bbox));
        // a label wider than its plot has no place
        let long = "x".repeat(80);
        assert!(!p.add(&request(long, (200.0, 200.0), f, Prefer::Centre)));
        assert_eq!(p.counts[Class::Feature as usize], (3, 2));
        assert_eq!(p.svg().matches("<text ").count(), 2);
    }

    /// A mark kept clear (an arrowhead) is covered by no label.
    #[test]
    fn a_reserved_mark_is_left_clear() {
        let f = [0.0, 0.0, 400.0, 400.0];
        let mut p = Placer::default();
        let mark = [194.0, 194.0, 206.0, 206.0];
        p.reserve(mark);
        for prefer in [
            Prefer::Centre,
            Prefer::Above,
            Prefer::Below,
            Prefer::UpRight,
        ] {
            assert!(p.add(&request("10.59 h".into(), (200.0, 200.0), f, prefer)));
        }
        assert!(p.placed.iter().all(|l| !overlap(l.bbox, mark)));
        assert_eq!(p.placed.len(), 4);
    }
}
