//! The boundary of the construction region Q_K (paper A §II's polygon grown or shrunk,
//! see the parent module) from its raw segments: split at every crossing (exact
//! orientations), keep the pieces with Q_K on their left only, link them into rings,
//! and group the rings into regions (outer counterclockwise, holes clockwise).

use std::collections::HashMap;
use std::vec::Vec;

use super::raw::{locate, Loc, Raw};
use super::{OffsetError, Region, Side};
use crate::ring::{check, orient, Winding};
use crate::vect2::Vect2;

/// An error of this stage.
fn fail(reason: &'static str) -> OffsetError {
    OffsetError::Uncertified { reason }
}

/// The arrangement's points, each once (by its exact coordinates).
struct Nodes {
    pts: Vec<Vect2>,
    ids: HashMap<(u64, u64), usize>,
}

impl Nodes {
    fn id(&mut self, v: Vect2) -> usize {
        // + 0.0 turns −0 into +0, so that equal points share their key.
        let key = ((v.x + 0.0).to_bits(), (v.y + 0.0).to_bits());
        let next = self.pts.len();
        *self.ids.entry(key).or_insert_with(|| {
            self.pts.push(v);
            next
        })
    }
}

/// Lexicographic order of points (exact).
fn lex_lt(p: Vect2, q: Vect2) -> bool {
    p.x < q.x || (p.x == q.x && p.y < q.y)
}

/// c strictly between a and b, for c on the line ab (lexicographic order is monotone
/// along a line).
fn strictly_between(a: Vect2, b: Vect2, c: Vect2) -> bool {
    (lex_lt(a, c) && lex_lt(c, b)) || (lex_lt(b, c) && lex_lt(c, a))
}

/// The rings of Q_K's boundary (see the module doc), each a list of points.
/// Cost: O(m²) pairs of the m raw segments at worst, pruned by their x extents.
pub(crate) fn rings(raw: &Raw) -> Result<Vec<Vec<Vect2>>, OffsetError> {
    let segs = &raw.segs;
    let m = segs.len();
    let mut nodes = Nodes {
        pts: Vec::new(),
        ids: HashMap::new(),
    };
    let ends: Vec<(usize, usize)> = segs
        .iter()
        .map(|s| (nodes.id(s.a), nodes.id(s.b)))
        .collect();
    let mut splits: Vec<Vec<usize>> = std::vec![Vec::new(); m];
    let mut order: Vec<usize> = (0..m).collect();
    let min_x = |i: usize| segs[i].a.x.min(segs[i].b.x);
    order.sort_by(|&i, &j| min_x(i).total_cmp(&min_x(j)));
    for (k, &i) in order.iter().enumerate() {
        let (a, b) = (segs[i].a, segs[i].b);
        let max_x = a.x.max(b.x);
        for &j in &order[k + 1..] {
            if min_x(j) > max_x {
                break;
            }
            let (c, d) = (segs[j].a, segs[j].b);
            if a.y.max(b.y) < c.y.min(d.y) || c.y.max(d.y) < a.y.min(b.y) {
                continue;
            }
            let o = |p, q, r| orient(p, q, r).ok_or(fail("an orientation over- or underflows"));
            let (o1, o2, o3, o4) = (o(a, b, c)?, o(a, b, d)?, o(c, d, a)?, o(c, d, b)?);
            if o1 == 0 && o2 == 0 {
                if strictly_between(a, b, c)
                    || strictly_between(a, b, d)
                    || strictly_between(c, d, a)
                    || strictly_between(c, d, b)
                    || (a == c && b == d)
                    || (a == d && b == c)
                {
                    return Err(fail("two raw segments overlap on one line"));
                }
                continue;
            }
            if o1 * o2 < 0 && o3 * o4 < 0 {
                let (e, f) = (b - a, d - c);
                let t = (c - a).perp().dot(f) / e.perp().dot(f);
                let x = a + e.scale(t.clamp(0.0, 1.0));
                let id = nodes.id(x);
                splits[i].push(id);
                splits[j].push(id);
                continue;
            }
            for (on_line, s, q, seg) in [
                (o1 == 0, (a, b), c, i),
                (o2 == 0, (a, b), d, i),
                (o3 == 0, (c, d), a, j),
                (o4 == 0, (c, d), b, j),
            ] {
                if on_line && strictly_between(s.0, s.1, q) {
                    let id = nodes.id(q);
                    splits[seg].push(id);
                }
            }
        }
    }
    let kept = keep(raw, &nodes.pts, &ends, &mut splits)?;
    link(&nodes.pts, &kept)
}

/// The pieces of the split segments with Q_K on their left and not on their right, as
/// (from, to) node pairs.
fn keep(
    raw: &Raw,
    pts: &[Vect2],
    ends: &[(usize, usize)],
    splits: &mut [Vec<usize>],
) -> Result<Vec<(usize, usize)>, OffsetError> {
    let mut kept = Vec::new();
    for (i, seg) in raw.segs.iter().enumerate() {
        let e = seg.b - seg.a;
        let along = |id: usize| (pts[id] - seg.a).dot(e);
        let list = &mut splits[i];
        list.push(ends[i].0);
        list.push(ends[i].1);
        list.sort_by(|&x, &y| along(x).total_cmp(&along(y)));
        list.dedup();
        for w in list.windows(2) {
            let (from, to) = (w[0], w[1]);
            let mid = (pts[from] + pts[to]).scale(0.5);
            if on_boundary(raw, seg.piece, mid)? {
                kept.push((from, to));
            }
        }
    }
    Ok(kept)
}

/// Is the midpoint `x` of a piece of a raw segment of piece `own` on Q_K's boundary:
/// its right side outside Q_K? Out: x is in no other piece and not inside P. In: x is
/// inside P and in no other removed piece. (Exact orientations on the f64 points.)
fn on_boundary(raw: &Raw, own: usize, x: Vect2) -> Result<bool, OffsetError> {
    let undecided = || fail("a membership orientation over- or underflows");
    let in_p = locate(raw.p, x).ok_or_else(undecided)? == Loc::Inside;
    if in_p != (raw.side == Side::In) {
        return Ok(false);
    }
    for (k, piece) in raw.pieces.iter().enumerate() {
        if k != own && piece.strictly_contains(x).ok_or_else(undecided)? {
            return Ok(false);
        }
    }
    Ok(true)
}

/// The kept pieces linked into closed rings: at a node with several ways on, the one
/// turning most to the right (which keeps two regions touching at a point apart).
fn link(pts: &[Vect2], kept: &[(usize, usize)]) -> Result<Vec<Vec<Vect2>>, OffsetError> {
    let mut out: HashMap<usize, Vec<usize>> = HashMap::new();
    for (k, &(from, _)) in kept.iter().enumerate() {
        out.entry(from).or_default().push(k);
    }
    let mut used = std::vec![false; kept.len()];
    let mut rings = Vec::new();
    for start in 0..kept.len() {
        if used[start] {
            continue;
        }
        let mut ring = Vec::new();
        let mut cur = start;
        loop {
            used[cur] = true;
            let (from, to) = kept[cur];
            ring.push(pts[from]);
            let din = pts[to] - pts[from];
            let next = out
                .get(&to)
                .and_then(|c| {
                    c.iter().copied().min_by(|&x, &y| {
                        let turn = |k: usize| {
                            let dk = pts[kept[k].1] - pts[kept[k].0];
                            libm::atan2(-din.perp().dot(dk), din.dot(dk))
                        };
                        turn(x).total_cmp(&turn(y))
                    })
                })
                .ok_or(fail("a boundary chain does not close"))?;
            if next == start {
                break;
            }
            if used[next] {
                return Err(fail("boundary chains cross at a node"));
            }
            cur = next;
        }
        if ring.len() >= 3 {
            rings.push(ring);
        }
    }
    Ok(rings)
}

/// The shoelace area of a ring (f64; used only to choose among nested outer rings).
fn area(ring: &[Vect2]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            a.x * b.y - a.y * b.x
        })
        .sum::<f64>()
        * 0.5
}

/// The rings as regions: counterclockwise rings are outer rings, clockwise ones holes,
/// each hole given to the smallest outer ring around its first vertex (exact ring
/// checks and point locations).
pub(crate) fn regions(rings: Vec<Vec<Vect2>>) -> Result<Vec<Region>, OffsetError> {
    let mut regions = Vec::new();
    let mut holes = Vec::new();
    for ring in rings {
        match check(&ring) {
            Ok(Winding::Counterclockwise) => regions.push(Region {
                outer: ring,
                holes: Vec::new(),
            }),
            Ok(Winding::Clockwise) => holes.push(ring),
            Err(_) => return Err(fail("a boundary ring is not simple")),
        }
    }
    for hole in holes {
        let mut best: Option<(usize, f64)> = None;
        for (k, r) in regions.iter().enumerate() {
            let loc = locate(&r.outer, hole[0]).ok_or(fail("a hole cannot be located"))?;
            let a = area(&r.outer);
            if loc == Loc::Inside && best.map_or(true, |(_, b)| a < b) {
                best = Some((k, a));
            }
        }
        let (k, _) = best.ok_or(fail("a hole outside every outer ring"))?;
        regions[k].holes.push(hole);
    }
    Ok(regions)
}
