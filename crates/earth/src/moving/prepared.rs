//! An area made ready for many pieces: for a static area, each ring's edges in an R-tree,
//! so that a piece far from every edge is decided by one exact point-in-ring test
//! instead of the engine (docs/moving-features.md, "How the answer is built").
//!
//! A piece's stand-in point sweeps the segment s + τ·v; when no edge's box meets the
//! segment's box grown by a reach r (the largest separation any of the piece's sets
//! uses, plus δ), every stand-in point is farther than r from the ring in the L∞ norm,
//! so also in the Euclidean one; the model's point is then farther than r − δ ≥ the
//! sets' separations from the model's ring, and its winding number is the stand-in's
//! (piece module doc). So the ring's sets are constant over the piece, and the winding
//! number at the piece's start, computed exactly ([`winding`]), decides them.

use super::{next_down, next_up};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

use super::planar::PlaneArea;

/// An edge's box, and its index in the ring.
type EdgeBox = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The edge trees of a static area: `rings[part][ring]` (ring 0 the outer, k the hole
/// k − 1). Empty for a keyframed area.
pub struct Prepared {
    rings: Vec<Vec<RTree<EdgeBox>>>,
    /// [xmin, ymin, xmax, ymax] of every vertex of every frame: a moving vertex stays in
    /// it (each moves linearly between two of its positions).
    bbox: [f64; 4],
}

impl Prepared {
    /// The trees of `area` when it is static (none when keyframed).
    pub fn new(area: &PlaneArea) -> Prepared {
        let rings = match area.frames.first() {
            Some(f) if area.is_static || area.frames.len() == 1 => f
                .parts
                .iter()
                .map(|p| {
                    core::iter::once(&p.outer)
                        .chain(&p.holes)
                        .map(|r| edge_tree(r))
                        .collect()
                })
                .collect(),
            _ => Vec::new(),
        };
        let mut bbox = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for f in &area.frames {
            for part in &f.parts {
                for p in core::iter::once(&part.outer).chain(&part.holes).flatten() {
                    bbox = [
                        bbox[0].min(p[0]),
                        bbox[1].min(p[1]),
                        bbox[2].max(p[0]),
                        bbox[3].max(p[1]),
                    ];
                }
            }
        }
        Prepared { rings, bbox }
    }

    /// The largest magnitude of a coordinate of the area.
    pub fn magnitude(&self) -> f64 {
        self.bbox.iter().fold(0.0f64, |m, x| m.max(x.abs()))
    }

    /// Whether the box of the segment from `a` to `b`, grown by `reach` (rounded outward),
    /// meets the area's box.
    pub fn box_meets(&self, a: [f64; 2], b: [f64; 2], reach: f64) -> bool {
        let lo = [a[0].min(b[0]) - reach, a[1].min(b[1]) - reach];
        let hi = [a[0].max(b[0]) + reach, a[1].max(b[1]) + reach];
        next_down(lo[0]) <= self.bbox[2]
            && self.bbox[0] <= next_up(hi[0])
            && next_down(lo[1]) <= self.bbox[3]
            && self.bbox[1] <= next_up(hi[1])
    }

    /// Whether ring `ring` of part `part` has no edge whose box meets the box of the
    /// segment from `a` to `b` grown by `reach` (rounded outward): `None` when the area
    /// is keyframed (the test does not apply).
    pub fn far_from(
        &self,
        part: usize,
        ring: usize,
        a: [f64; 2],
        b: [f64; 2],
        reach: f64,
    ) -> Option<bool> {
        let tree = self.rings.get(part)?.get(ring)?;
        let lo = [
            next_down(a[0].min(b[0]) - reach),
            next_down(a[1].min(b[1]) - reach),
        ];
        let hi = [
            next_up(a[0].max(b[0]) + reach),
            next_up(a[1].max(b[1]) + reach),
        ];
        let env = AABB::from_corners(lo, hi);
        Some(tree.locate_in_envelope_intersecting(&env).next().is_none())
    }
}

/// The R-tree of a ring's edge boxes.
fn edge_tree(ring: &[[f64; 2]]) -> RTree<EdgeBox> {
    let n = ring.len();
    let boxes = (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            GeomWithData::new(Rectangle::from_corners(a, b), i)
        })
        .collect();
    RTree::bulk_load(boxes)
}

/// The winding number of the ring around `p`, exactly (orientations by
/// `robust::orient2d`, exact on f64 inputs; the crossing rule counts an edge when it
/// crosses the horizontal through `p` upward with `p` on its left, downward with `p` on
/// its right). `p` must not lie on the ring (the callers know it is far from it).
pub fn winding(ring: &[[f64; 2]], p: [f64; 2]) -> i64 {
    let c = |q: [f64; 2]| robust::Coord { x: q[0], y: q[1] };
    let n = ring.len();
    let mut w = 0;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if a[1] <= p[1] {
            if b[1] > p[1] && robust::orient2d(c(a), c(b), c(p)) > 0.0 {
                w += 1;
            }
        } else if b[1] <= p[1] && robust::orient2d(c(a), c(b), c(p)) < 0.0 {
            w -= 1;
        }
    }
    w
}

/// The ring clipped to the box [lo, hi] (Sutherland and Hodgman's algorithm, one side of
/// the box at a time): a ring whose winding number around every point strictly inside
/// the box is the ring's (the parts outside are moved onto the box's sides, which no
/// such point crosses), with new edges only on the box's sides. Each vertex made on a
/// side lies within 8u·c of the ring's edge it cuts (c the coordinates' largest size:
/// one subtraction, one division, one product and one sum on the cut coordinate, the
/// other coordinate exact), so every edge kept near the box's middle is within that of
/// the ring's.
pub fn clip_ring(ring: &[[f64; 2]], lo: [f64; 2], hi: [f64; 2]) -> Vec<[f64; 2]> {
    let mut cur: Vec<[f64; 2]> = ring.to_vec();
    // (axis, bound, keep the side ≥ bound)
    for (axis, bound, ge) in [
        (0, lo[0], true),
        (0, hi[0], false),
        (1, lo[1], true),
        (1, hi[1], false),
    ] {
        if cur.is_empty() {
            break;
        }
        let inside = |p: &[f64; 2]| {
            if ge {
                p[axis] >= bound
            } else {
                p[axis] <= bound
            }
        };
        let cut = |p: [f64; 2], q: [f64; 2]| {
            let o = 1 - axis;
            let f = (bound - p[axis]) / (q[axis] - p[axis]);
            let mut r = [0.0; 2];
            r[axis] = bound;
            r[o] = p[o] + f * (q[o] - p[o]);
            r
        };
        let n = cur.len();
        let mut out = Vec::with_capacity(n + 4);
        for i in 0..n {
            let (p, q) = (cur[i], cur[(i + 1) % n]);
            match (inside(&p), inside(&q)) {
                (true, true) => out.push(q),
                (true, false) => out.push(cut(p, q)),
                (false, true) => {
                    out.push(cut(p, q));
                    out.push(q);
                }
                (false, false) => {}
            }
        }
        cur = out;
    }
    cur
}

#[cfg(test)]
mod tests {
    use super::{clip_ring, winding};

    #[test]
    fn clipping_keeps_the_winding_number_inside_the_box() {
        // A U shape clipped by a box that cuts both arms: points inside the box keep
        // their winding numbers.
        let u = [
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 3.0],
            [2.0, 3.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ];
        let c = clip_ring(&u, [0.5, 0.5], [2.5, 2.0]);
        for p in [
            [0.75, 1.5],
            [1.5, 1.5],
            [2.25, 1.5],
            [1.5, 0.75],
            [0.6, 1.9],
        ] {
            assert_eq!(winding(&c, p), winding(&u, p), "{p:?}");
        }
        assert!(clip_ring(&u, [10.0, 10.0], [11.0, 11.0]).is_empty());
    }
}
