//! The construction region Q_K of an offset or inset (paper A §II's polygon, grown or
//! shrunk by D'): its convex pieces (the strips of the edges and the fans of the
//! vertices, see the parent module's doc) and the raw segments its boundary lies on
//! (the shifted edges and the circumscribed arcs), each oriented with Q_K's side on its
//! left.

use std::vec::Vec;

use super::Side;
use crate::ring::orient;
use crate::vect2::Vect2;

/// A raw segment a → b, Q_K's side on its left.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Seg {
    pub a: Vect2,
    pub b: Vect2,
    /// The piece whose boundary it is (its own piece, skipped by the membership test).
    pub piece: usize,
}

/// A convex piece, counterclockwise, with its bounding box.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    pub verts: Vec<Vect2>,
    pub lo: Vect2,
    pub hi: Vect2,
}

impl Piece {
    fn new(verts: Vec<Vect2>) -> Piece {
        let mut lo = Vect2::new(f64::INFINITY, f64::INFINITY);
        let mut hi = Vect2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        for v in &verts {
            lo = Vect2::new(lo.x.min(v.x), lo.y.min(v.y));
            hi = Vect2::new(hi.x.max(v.x), hi.y.max(v.y));
        }
        Piece { verts, lo, hi }
    }

    /// x strictly inside (exact orientations on the f64 vertices; repeated vertices
    /// skipped). `None` when an orientation cannot be decided exactly.
    pub fn strictly_contains(&self, x: Vect2) -> Option<bool> {
        if x.x <= self.lo.x || x.x >= self.hi.x || x.y <= self.lo.y || x.y >= self.hi.y {
            return Some(false);
        }
        let n = self.verts.len();
        for i in 0..n {
            let (a, b) = (self.verts[i], self.verts[(i + 1) % n]);
            if a == b {
                continue;
            }
            if orient(a, b, x)? <= 0 {
                return Some(false);
            }
        }
        Some(true)
    }
}

/// Q_K of the parent module's doc: P, its pieces and the raw segments.
pub(crate) struct Raw<'a> {
    pub p: &'a [Vect2],
    pub side: Side,
    pub pieces: Vec<Piece>,
    pub segs: Vec<Seg>,
}

/// The unit normal of the edge a → b on the side that is grown: the right (outward
/// for a counterclockwise P) for the offset, the left (inward) for the inset.
fn normal(a: Vect2, b: Vect2, side: Side) -> Vect2 {
    let e = b - a;
    let len = libm::hypot(e.x, e.y);
    let n = e.perp().scale(1.0 / len);
    match side {
        Side::Out => n,
        Side::In => -n,
    }
}

impl<'a> Raw<'a> {
    /// The pieces and raw segments of P grown (`Side::Out`) or shrunk (`Side::In`) by
    /// `d` (D' of the parent module), arcs in pieces of at most `delta` radians.
    pub fn new(p: &'a [Vect2], d: f64, delta: f64, side: Side) -> Raw<'a> {
        let n = p.len();
        let mut raw = Raw {
            p,
            side,
            pieces: Vec::new(),
            segs: Vec::new(),
        };
        let normals: Vec<Vect2> = (0..n).map(|i| normal(p[i], p[(i + 1) % n], side)).collect();
        let fans: Vec<bool> = (0..n)
            .map(|j| {
                let turn = orient(p[(j + n - 1) % n], p[j], p[(j + 1) % n]);
                match (side, turn) {
                    (Side::Out, Some(t)) => t >= 0,
                    (Side::In, Some(t)) => t <= 0,
                    (_, None) => true,
                }
            })
            .collect();
        let mitres = mitres(p, &normals, &fans, d);
        // The strips: edge i's shifted copy, the strip on its left for Out (the edge is
        // on its left) and on its right for In (the strip lies between it and the edge).
        // The raw segment is the shifted copy cut at the mitre points of its ends.
        for i in 0..n {
            let j = (i + 1) % n;
            let (a, b) = (p[i], p[j]);
            let off = normals[i].scale(d);
            let (sa, sb) = (a + off, b + off);
            let verts = match side {
                Side::Out => std::vec![a, sa, sb, b],
                Side::In => std::vec![a, b, sb, sa],
            };
            raw.segs.push(Seg {
                a: mitres[i].unwrap_or(sa),
                b: mitres[j].unwrap_or(sb),
                piece: raw.pieces.len(),
            });
            raw.pieces.push(Piece::new(verts));
        }
        // The fans: at the vertices where the grown side turns outward (convex vertices
        // for Out, reflex ones for In), and at straight ones, whose two shifted edges
        // may end an ulp apart.
        for j in 0..n {
            if fans[j] {
                raw.fan(p[j], normals[(j + n - 1) % n], normals[j], d, delta);
            }
        }
        raw
    }

    /// The fan at v from normal `n0` to normal `n1` (turning less than a half turn):
    /// v + d·n0, the circumscribed arc's vertices at radius d·sec(δ/2), v + d·n1.
    fn fan(&mut self, v: Vect2, n0: Vect2, n1: Vect2, d: f64, delta: f64) {
        if n0 == n1 {
            // A straight vertex whose shifted edges meet exactly: nothing to fill.
            return;
        }
        let sweep = libm::atan2(n0.x * n1.y - n0.y * n1.x, n0.dot(n1));
        let k = libm::ceil(sweep.abs() / delta).max(1.0);
        let step = sweep / k;
        let radius = d / libm::cos(0.5 * step);
        let a0 = libm::atan2(n0.y, n0.x);
        let mut arc = std::vec![v + n0.scale(d)];
        for m in 0..k as usize {
            let a = a0 + (m as f64 + 0.5) * step;
            arc.push(v + Vect2::new(libm::cos(a), libm::sin(a)).scale(radius));
        }
        arc.push(v + n1.scale(d));
        // Out: the arc runs counterclockwise about v, the fan on its left. In: it runs
        // clockwise, the fan on its right, Q_K's side on its left.
        let piece = self.pieces.len();
        for w in arc.windows(2) {
            if w[0] != w[1] {
                self.segs.push(Seg {
                    a: w[0],
                    b: w[1],
                    piece,
                });
            }
        }
        let mut verts = std::vec![v];
        verts.extend_from_slice(&arc);
        if self.side == Side::In {
            verts.reverse();
        }
        self.pieces.push(Piece::new(verts));
    }
}

/// At each vertex without a fan, the point where the two shifted edges' lines cross
/// (the mitre point v + d·(n₀ + n₁)/(1 + n₀·n₁)), when it lies within both edges'
/// spans and the edges' two cuts keep their order. Cutting there joins the two raw
/// segments at one node: their crossing, for nearly parallel edges, is a point that the
/// general intersection places poorly, and the tips beyond it lie inside the
/// neighbour's strip anyway. (A float choice: the certificate checks the outcome.)
fn mitres(p: &[Vect2], normals: &[Vect2], fans: &[bool], d: f64) -> Vec<Option<Vect2>> {
    let n = p.len();
    let along = |i: usize, m: Vect2| {
        let e = p[(i + 1) % n] - p[i];
        (m - p[i]).dot(e) / e.sq()
    };
    let mut out: Vec<Option<Vect2>> = (0..n)
        .map(|j| {
            if fans[j] {
                return None;
            }
            let i = (j + n - 1) % n;
            let (n0, n1) = (normals[i], normals[j]);
            let m = p[j] + (n0 + n1).scale(d / (1.0 + n0.dot(n1)));
            let (ti, tj) = (along(i, m), along(j, m));
            (m.is_finite() && ti > 0.0 && ti < 1.0 && tj > 0.0 && tj < 1.0).then_some(m)
        })
        .collect();
    for i in 0..n {
        let j = (i + 1) % n;
        if let (Some(a), Some(b)) = (out[i], out[j]) {
            if along(i, b) <= along(i, a) {
                out[i] = None;
                out[j] = None;
            }
        }
    }
    out
}

/// Where a point lies with respect to a ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Loc {
    /// Winding number ≠ 0.
    Inside,
    /// Winding number 0, not on the ring.
    Outside,
    /// On one of the ring's edges.
    Boundary,
}

/// The winding number of `ring` about x (exact orientations on the f64 points: the
/// crossing rule of paper A §II.D, counted with signs), or `None` when an orientation
/// cannot be decided exactly (a product over- or underflows).
pub(crate) fn winding_number(ring: &[Vect2], x: Vect2) -> Option<(i32, bool)> {
    let n = ring.len();
    let mut w = 0i32;
    let mut on = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let lo = (a.x.min(b.x), a.y.min(b.y));
        let hi = (a.x.max(b.x), a.y.max(b.y));
        let in_box = lo.0 <= x.x && x.x <= hi.0 && lo.1 <= x.y && x.y <= hi.1;
        if !in_box && ((a.y > x.y) == (b.y > x.y) || x.x > hi.0) {
            continue;
        }
        let o = orient(a, b, x)?;
        if o == 0 && in_box {
            on = true;
        }
        if a.y <= x.y && x.y < b.y && o > 0 {
            w += 1;
        } else if b.y <= x.y && x.y < a.y && o < 0 {
            w -= 1;
        }
    }
    Some((w, on))
}

/// [`winding_number`] as a [`Loc`].
pub(crate) fn locate(ring: &[Vect2], x: Vect2) -> Option<Loc> {
    let (w, on) = winding_number(ring, x)?;
    Some(if on {
        Loc::Boundary
    } else if w != 0 {
        Loc::Inside
    } else {
        Loc::Outside
    })
}
