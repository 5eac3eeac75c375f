//! Where the picture shows what: the whole turn each object is drawn in on the Earth, and
//! the panels.
//!
//! Objects far apart (two ships 150° of longitude apart) drawn in one frame would be
//! specks in an empty picture. The picture is cut where nothing lies instead: the objects'
//! boxes are split at the widest empty band, across longitude or latitude, while that
//! band is more than half the group's extent (at most [`MAX_PANELS`] panels), and each
//! group is drawn in a panel of its own, side by side or one above the other, all at one
//! scale (so that sizes compare), the band left out between them. A conflict region lies
//! inside both its objects' boxes, so always inside one panel.

use super::frame::Frame;
use crate::conflict::Object;
use std::f64::consts::TAU;

/// At most this many panels.
pub(super) const MAX_PANELS: usize = 6;
/// An empty band is cut out when it is wider than this share of its group's extent.
const CUT_SHARE: f64 = 0.5;
/// A panel's margins around its plot (pixels: left, top, right, bottom): the latitudes
/// are written on the left, the longitudes below.
const MARGIN: [f64; 4] = [62.0, 8.0, 10.0, 24.0];
/// A plot is at least this wide and high (pixels), with room for labels.
const MIN_PLOT: f64 = 160.0;
/// The space between two panels (pixels), where the band left out is named.
pub(super) const BREAK_GAP: f64 = 36.0;
/// The panels together fit in this many pixels (width, height) when they can.
const MAX_SIZE: (f64, f64) = (960.0, 900.0);
/// The plot's margin around the objects, a share of their extent.
const PAD_SHARE: f64 = 0.04;

/// The whole turn each object is drawn in: on the Earth every object and region is moved
/// by whole turns to lie within half a turn of the scenario's circular mean longitude, so
/// that objects meeting across the antimeridian are drawn side by side.
pub(super) struct Turns {
    centre: f64,
    earth: bool,
}

/// The middle longitude (Mercator x) of a box.
pub(super) fn mid(r: [f64; 4]) -> f64 {
    0.5 * (r[0] + r[2])
}

impl Turns {
    /// The turns of `objects`' drawing (`earth`: the plane wraps).
    pub fn new(objects: &[&Object], earth: bool) -> Turns {
        let (sin, cos) = objects.iter().fold((0.0, 0.0), |(s, c), o| {
            (s + mid(o.aabb).sin(), c + mid(o.aabb).cos())
        });
        Turns {
            centre: sin.atan2(cos),
            earth,
        }
    }

    /// The shift (radians, whole turns) of something whose middle longitude is `x`.
    pub fn dx(&self, x: f64) -> f64 {
        let k = ((x - self.centre) / TAU).round();
        if self.earth && k.is_finite() {
            -TAU * k
        } else {
            0.0
        }
    }
}

/// A band left out between two panels: across longitude (`across_x`, the panels side by
/// side) or latitude (one above the other), from Mercator `from` to `to`, named at the
/// pixel `at`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Break {
    /// The band is one of longitude.
    pub across_x: bool,
    /// Its Mercator ends (x or y, radians), `from < to`.
    pub from: f64,
    /// See `from`.
    pub to: f64,
    /// Where its name is written (pixels).
    pub at: (f64, f64),
}

/// The panels and the bands left out between them.
pub(super) struct Layout {
    /// One frame a panel.
    pub frames: Vec<Frame>,
    /// The bands left out.
    pub breaks: Vec<Break>,
    /// The panels' extent (pixels), from the origin given.
    pub size: (f64, f64),
}

impl Layout {
    /// The panel that shows the Mercator point (`x`, `y`): the one whose bounds hold it,
    /// or the nearest.
    pub fn panel_of(&self, x: f64, y: f64) -> usize {
        let mut best = (f64::INFINITY, 0);
        for (i, f) in self.frames.iter().enumerate() {
            let d = f.distance(x, y);
            if d < best.0 {
                best = (d, i);
            }
        }
        best.1
    }
}

/// The cuts: a group drawn in one panel, or two parts across a band left out (the west
/// or north part first).
enum Tree {
    Leaf([f64; 4]),
    Split {
        across_x: bool,
        parts: Box<[Tree; 2]>,
    },
}

/// The bounds of boxes.
fn bounds(boxes: &[[f64; 4]]) -> [f64; 4] {
    boxes.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, r| {
            [
                b[0].min(r[0]),
                b[1].min(r[1]),
                b[2].max(r[2]),
                b[3].max(r[3]),
            ]
        },
    )
}

/// The widest band along `axis` (0: x, 1: y) that no box reaches into: its width and
/// middle.
fn widest_gap(boxes: &[[f64; 4]], axis: usize) -> Option<(f64, f64)> {
    let mut spans: Vec<(f64, f64)> = boxes.iter().map(|b| (b[axis], b[axis + 2])).collect();
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut reach = spans.first()?.1;
    let mut best: Option<(f64, f64)> = None;
    for &(lo, hi) in &spans[1..] {
        if lo > reach && best.map_or(true, |(g, _)| lo - reach > g) {
            best = Some((lo - reach, 0.5 * (lo + reach)));
        }
        reach = reach.max(hi);
    }
    best
}

/// The module doc's cuts of `boxes`; `panels` counts the panels made so far.
fn cut(boxes: Vec<[f64; 4]>, panels: &mut usize) -> Tree {
    let b = bounds(&boxes);
    let span = (b[2] - b[0]).max(b[3] - b[1]);
    let best = [0, 1]
        .into_iter()
        .filter_map(|axis| widest_gap(&boxes, axis).map(|(g, at)| (g, at, axis)))
        .max_by(|a, c| a.0.total_cmp(&c.0));
    match best {
        Some((gap, at, axis)) if *panels < MAX_PANELS && gap > CUT_SHARE * span => {
            *panels += 1;
            let (low, high): (Vec<[f64; 4]>, Vec<[f64; 4]>) =
                boxes.into_iter().partition(|r| r[axis] < at);
            // west before east, north (the larger y) before south
            let (first, second) = if axis == 0 { (low, high) } else { (high, low) };
            let first = cut(first, panels);
            let second = cut(second, panels);
            Tree::Split {
                across_x: axis == 0,
                parts: Box::new([first, second]),
            }
        }
        _ => Tree::Leaf(b),
    }
}

/// Two panels side by side that show about the same latitudes show the same ones (or,
/// stacked, the same longitudes), so that they read as one axis broken: when the union
/// of their ranges is at most twice the larger range.
fn align(t: &mut Tree) {
    let Tree::Split { across_x, parts } = t else {
        return;
    };
    let axis = if *across_x { 1 } else { 0 };
    match &mut **parts {
        [Tree::Leaf(a), Tree::Leaf(b)] => {
            let (lo, hi) = (a[axis].min(b[axis]), a[axis + 2].max(b[axis + 2]));
            let larger = (a[axis + 2] - a[axis]).max(b[axis + 2] - b[axis]);
            if hi - lo <= 2.0 * larger {
                for r in [a, b] {
                    r[axis] = lo;
                    r[axis + 2] = hi;
                }
            }
        }
        [first, second] => {
            align(first);
            align(second);
        }
    }
}

/// Each group's bounds with the margin around its objects.
fn pad(t: &mut Tree) {
    match t {
        Tree::Leaf(b) => {
            let p = PAD_SHARE * (b[2] - b[0]).max(b[3] - b[1]).max(1e-6);
            *b = [b[0] - p, b[1] - p, b[2] + p, b[3] + p];
        }
        Tree::Split { parts, .. } => parts.iter_mut().for_each(pad),
    }
}

/// A group's plot at `k` pixels a radian: its width and height (pixels).
fn plot(b: [f64; 4], k: f64) -> (f64, f64) {
    (
        ((b[2] - b[0]) * k).max(MIN_PLOT),
        ((b[3] - b[1]) * k).max(MIN_PLOT),
    )
}

/// The extent of a tree's panels (pixels) at `k` pixels a radian.
fn size(t: &Tree, k: f64) -> (f64, f64) {
    match t {
        Tree::Leaf(b) => {
            let (w, h) = plot(*b, k);
            (w + MARGIN[0] + MARGIN[2], h + MARGIN[1] + MARGIN[3])
        }
        Tree::Split { across_x, parts } => {
            let (a, c) = (size(&parts[0], k), size(&parts[1], k));
            if *across_x {
                (a.0 + BREAK_GAP + c.0, a.1.max(c.1))
            } else {
                (a.0.max(c.0), a.1 + BREAK_GAP + c.1)
            }
        }
    }
}

/// The panels of a tree at `k` pixels a radian, from the pixel (`x`, `y`).
fn place(t: &Tree, k: f64, (x, y): (f64, f64), out: &mut Layout) {
    match t {
        Tree::Leaf(p) => {
            let (w, h) = plot(*p, k);
            let (cx, cy) = (0.5 * (p[0] + p[2]), 0.5 * (p[1] + p[3]));
            let (hw, hh) = (0.5 * w / k, 0.5 * h / k);
            out.frames.push(Frame {
                b: [cx - hw, cy - hh, cx + hw, cy + hh],
                k,
                left: x + MARGIN[0],
                top: y + MARGIN[1],
            });
        }
        Tree::Split { across_x, parts } => {
            let a = size(&parts[0], k);
            let whole = size(t, k);
            let n = out.frames.len();
            place(&parts[0], k, (x, y), out);
            let m = out.frames.len();
            let next = if *across_x {
                (x + a.0 + BREAK_GAP, y)
            } else {
                (x, y + a.1 + BREAK_GAP)
            };
            place(&parts[1], k, next, out);
            let (first, second) = (&out.frames[n..m], &out.frames[m..]);
            let (from, to, at) = if *across_x {
                (
                    first
                        .iter()
                        .map(|f| f.b[2])
                        .fold(f64::NEG_INFINITY, f64::max),
                    second.iter().map(|f| f.b[0]).fold(f64::INFINITY, f64::min),
                    (x + a.0 + 0.5 * BREAK_GAP, y + 0.5 * whole.1),
                )
            } else {
                (
                    second
                        .iter()
                        .map(|f| f.b[3])
                        .fold(f64::NEG_INFINITY, f64::max),
                    first.iter().map(|f| f.b[1]).fold(f64::INFINITY, f64::min),
                    (x + 0.5 * whole.0, y + a.1 + 0.5 * BREAK_GAP),
                )
            };
            out.breaks.push(Break {
                across_x: *across_x,
                from,
                to,
                at,
            });
        }
    }
}

/// The panels for objects whose (turned) boxes are `boxes`, from the pixel `origin`: the
/// module doc's cuts, at the largest scale that fits [`MAX_SIZE`] (or the smallest
/// panels, when even they do not).
pub(super) fn lay_out(boxes: &[[f64; 4]], origin: (f64, f64)) -> Layout {
    let mut boxes: Vec<[f64; 4]> = boxes
        .iter()
        .copied()
        .filter(|b| b.iter().all(|v| v.is_finite()))
        .collect();
    if boxes.is_empty() {
        boxes.push([-0.01, -0.01, 0.01, 0.01]);
    }
    let mut panels = 1;
    let mut tree = cut(boxes, &mut panels);
    pad(&mut tree);
    align(&mut tree);
    let least = size(&tree, 0.0);
    let most = (MAX_SIZE.0.max(least.0), MAX_SIZE.1.max(least.1));
    // the largest k that fits, by bisection on ln k (the extent grows with k)
    let (mut lo, mut hi) = (-12.0f64, 40.0f64);
    for _ in 0..80 {
        let m = 0.5 * (lo + hi);
        let (w, h) = size(&tree, m.exp());
        if w <= most.0 && h <= most.1 {
            lo = m;
        } else {
            hi = m;
        }
    }
    let k = lo.exp();
    let mut out = Layout {
        frames: Vec::new(),
        breaks: Vec::new(),
        size: size(&tree, k),
    };
    place(&tree, k, origin, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box of `w` × `h` radians around (`x`, `y`).
    fn around(x: f64, y: f64, w: f64, h: f64) -> [f64; 4] {
        [x - 0.5 * w, y - 0.5 * h, x + 0.5 * w, y + 0.5 * h]
    }

    /// Do two pixel boxes overlap (more than touch)?
    fn overlap(a: [f64; 4], b: [f64; 4]) -> bool {
        a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
    }

    /// Two groups 150° of longitude apart get a panel each, side by side at one scale,
    /// the band between them left out; each object is drawn large, inside its panel.
    #[test]
    fn far_apart_groups_get_panels_of_their_own() {
        let d = 1f64.to_radians();
        let boxes = [
            around(-75f64.to_radians(), 0.2, 2.0 * d, d),
            around(-74f64.to_radians(), 0.2, d, d),
            around(75f64.to_radians(), 0.2, d, d),
        ];
        let l = lay_out(&boxes, (0.0, 0.0));
        assert_eq!(l.frames.len(), 2);
        assert_eq!(l.breaks.len(), 1);
        let b = &l.breaks[0];
        assert!(b.across_x && (b.to - b.from).to_degrees() > 140.0, "{b:?}");
        assert_eq!(l.frames[0].k, l.frames[1].k);
        assert!(l.frames[0].rect()[2] < l.frames[1].rect()[0]);
        for r in boxes {
            let f = &l.frames[l.panel_of(mid(r), 0.2)];
            let (x0, y0) = f.pt([r[0], r[3]], 0.0);
            let (x1, y1) = f.pt([r[2], r[1]], 0.0);
            assert!(x1 - x0 > 100.0 && y1 - y0 > 100.0, "{r:?} drawn {x0} {x1}");
            let p = f.rect();
            assert!(x0 >= p[0] && x1 <= p[2] && y0 >= p[1] && y1 <= p[3]);
        }
        assert!(l.size.0 <= MAX_SIZE.0 + 1e-9 && l.size.1 <= MAX_SIZE.1 + 1e-9);
        assert!(!overlap(l.frames[0].rect(), l.frames[1].rect()));
    }

    /// Groups apart in latitude are stacked, north on top; objects close together stay in
    /// one panel; and never more than MAX_PANELS panels, none overlapping another.
    #[test]
    fn panels_stack_north_on_top_and_are_few() {
        let north = around(0.0, 1.0, 0.02, 0.02);
        let south = around(0.0, -0.5, 0.02, 0.02);
        let l = lay_out(&[south, north], (0.0, 0.0));
        assert_eq!(l.frames.len(), 2);
        assert!(!l.breaks[0].across_x);
        assert!(l.frames[0].b[1] > 0.5 && l.frames[0].top < l.frames[1].top);
        let near = lay_out(
            &[around(0.0, 0.0, 0.1, 0.1), around(0.12, 0.0, 0.1, 0.1)],
            (0.0, 0.0),
        );
        assert_eq!(near.frames.len(), 1);
        let scattered: Vec<[f64; 4]> = (0..20)
            .map(|i| around(0.3 * i as f64, 0.1 * (i % 3) as f64, 0.001, 0.001))
            .collect();
        let l = lay_out(&scattered, (0.0, 0.0));
        assert!(l.frames.len() <= MAX_PANELS);
        for (i, a) in l.frames.iter().enumerate() {
            for b in &l.frames[i + 1..] {
                assert!(!overlap(a.rect(), b.rect()));
            }
        }
        for r in &scattered {
            let f = &l.frames[l.panel_of(mid(*r), r[1])];
            assert_eq!(f.distance(mid(*r), r[1]), 0.0);
        }
    }
}
