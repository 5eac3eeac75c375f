//! Keep-in exit detection: does the point leave the fence at some t ∈ [0, T]? That is,
//! is breach_D(t) true for some t (the definitions of [`crate::intervals`]: fence_D(t)
//! is x(t) in P(t) at distance > D from ∂P(t), and in 3D bottom(t) + H < z(t) <
//! top(t) − H; paper A §II's motion and §III's slab).
//!
//! # The conditions
//! The point stays in the fence throughout [0, T] exactly when
//! 1. s is in the fence at t = 0 horizontally: inside P(0) (winding number odd; §II.B's
//!    crossing count, certified) — its distance to ∂P is covered by 2.;
//! 2. the point is at distance > D from every edge at every t (closed: a distance equal
//!    to D is an exit);
//! 3. in 3D, the height is strictly inside the shrunk slab at t = 0 and at t = T (the
//!    slab lines are linear in t).
//!
//! (⇐: by 2 the point never meets ∂P(t), so its winding number stays that of t = 0,
//! odd; at every t it is farther than D from each edge, hence from ∂P(t). ⇒: at each
//! t the point is inside at distance > D from ∂P(t), so from each edge.) This holds for
//! warping polygons too: the winding number changes only where the point is on an edge.
//!
//! # Statically shaped polygons: a closed form
//! When every V_i is the same V (paper A §II.F, §II.H), in the polygon's frame the
//! point moves along one segment, from s to s + T·(v − V) relative to P, and condition 2
//! is: that segment is at distance > D from every edge. The distance of two segments is
//! ≤ D exactly when they cross or one's end is within D of the other (paper A §II.G's
//! segments_close, closed): the engine's certified crossing test and a closed
//! point–segment test on balls, |a|² ≤ D², |b|² ≤ D², or the foot of the perpendicular
//! on the segment (h₁ ≥ 0, h₂ ≥ 0, |e|² > 0) with g² ≤ D²|e|². Two filters go first,
//! each certain: bounding boxes apart by more than D, and both ends of an edge beyond D
//! on one side of the path's line.
//!
//! # Warping polygons: each edge's halving
//! Condition 2 edge by edge, by the interval scan's machinery ([`crate::intervals`]):
//! [0, T] is halved while the edge is neither certainly farther than D on a piece nor
//! certainly within D on it (or certainly crossed), the edge the point heads for first.
//!
//! Condition 2 goes first (a point that leaves is usually settled there), the crossing
//! count of condition 1 after it.
//!
//! Certified both ways: `No` only when the point certainly stays in the fence, `Yes`
//! only when it certainly leaves; every decision is a `Ball` comparison (the error
//! analysis of `crate::ball`), never an epsilon.

use crate::ball::{mx, nonnegative, positive, up, Ball, BallV, Tri};
use crate::detect::statically_shaped;
use crate::intervals::{Heights, Parts, Relation, Scan, Separation};
use crate::motion::{winding, Frame, SlabLine, State};
use crate::predicates::{self as pr, PathLine};
use crate::vect2::Vect2;

/// Does the point leave the keep-in fence during [0, T] (breach_D at some t)? Never
/// `false` when it does (see [`detect_exit_tri`]; the module doc's definitions, paper A
/// §II–§III).
///
/// ```
/// use polyguard::fence::detect_exit;
/// use polyguard::{Separation, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(4.0, 0.0), Vect2::new(4.0, 4.0), Vect2::new(0.0, 4.0)];
/// let still = [Vect2::ZERO; 4];
/// let sep = Separation { d: 1.0, h: 0.0 };
/// // From the centre, east at 0.5: within 1 of the east edge from t = 2.
/// assert!(detect_exit(10.0, Vect2::new(2.0, 2.0), Vect2::new(0.5, 0.0), &square, &still, None, sep));
/// assert!(!detect_exit(1.5, Vect2::new(2.0, 2.0), Vect2::new(0.5, 0.0), &square, &still, None, sep));
/// ```
pub fn detect_exit(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    sep: Separation,
) -> bool {
    detect_exit_tri(t, s, v, p, vels, heights, sep).or_true()
}

/// Keep-in exit detection, three-valued: `Yes` only when the point certainly leaves the
/// fence during [0, T], `No` only when it certainly stays, `Unsure` otherwise (also for
/// a case outside the domain: T negative or not finite, fewer than 3 vertices, a
/// coordinate that is not finite, D or H (3D) negative or not finite). Closed form for
/// statically shaped polygons, the breach scan for warping ones (module doc; paper A
/// §II.F's dispatch).
pub fn detect_exit_tri(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    sep: Separation,
) -> Tri {
    let n = p.len().min(vels.len());
    if n < 3 {
        return Tri::Unsure;
    }
    let (p, vels) = (&p[..n], &vels[..n]);
    exit(t, s, v, p, vels, heights, sep, statically_shaped(vels))
}

/// Keep-in exit detection (the module doc): the height against the shrunk slab and the
/// start (conditions 3 and 1), then the edges (condition 2): the closed form when
/// `closed` (the polygon is statically shaped), else each edge's halving of [0, T].
#[allow(clippy::too_many_arguments)]
fn exit(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    sep: Separation,
    closed: bool,
) -> Tri {
    let h = if heights.is_some() { sep.h } else { 0.0 };
    let finite = |a: &Vect2| a.is_finite();
    let ok = t >= 0.0
        && t.is_finite()
        && finite(&s)
        && finite(&v)
        && p.iter().all(finite)
        && vels.iter().all(finite)
        && sep.d >= 0.0
        && sep.d.is_finite()
        && h >= 0.0
        && h.is_finite();
    if !ok {
        return Tri::Unsure;
    }
    let frame = Frame::new(t, s, v, p, vels, heights, &[sep.d, h], true);
    // 3. The height against the shrunk slab, at t = 0 and t = T.
    let mut acc = match heights {
        Some(z) => slab_exit(SlabLine::pair(frame.heights(z), -frame.len(h)), t),
        None => Tri::No,
    };
    if acc == Tri::Yes {
        return Tri::Yes;
    }
    // 2. Within D of an edge at some time, first for a statically shaped polygon (a
    // point that leaves is usually settled there, before the O(n) crossing count);
    // for a warping one, a quick look at the edge the point heads for.
    let d = frame.len(sep.d);
    // Each warping edge is halved on its own: no stored edges or candidates are needed.
    let ws = Parts {
        edges: &mut [],
        reach: &mut [],
        cands: &mut [],
    };
    let mut warping = match closed {
        true => None,
        false => Scan::new(t, s, v, p, vels, heights, Relation::Breach, sep, ws),
    };
    let (edges, first) = match &warping {
        _ if closed => (static_edges(&frame, t, s, v, p, vels[0], d), 0),
        Some(scan) => match scan.heads_for() {
            (_, true) => return Tri::Yes,
            (first, false) => (Tri::Unsure, first),
        },
        None => (Tri::Unsure, 0),
    };
    if edges == Tri::Yes {
        return Tri::Yes;
    }
    // 1. Inside P at t = 0.
    let at_start = |i: usize| (frame.pt(p[i]), Vect2::ZERO);
    match winding(p.len(), at_start, frame.pt(s), Vect2::ZERO, 0.0) {
        State::Outside => return Tri::Yes,
        State::Unknown | State::Undefined => acc = Tri::Unsure,
        State::Inside => {}
    }
    match warping.as_mut() {
        Some(scan) => acc.or(scan.comes_within(first)),
        None => acc.or(edges),
    }
}

/// Condition 2 for a statically shaped polygon (all velocities `vel`): the relative
/// path 0 → T·(v − V) against every edge (a point when v = V or T = 0), in the frame
/// (`d` is D there).
fn static_edges(frame: &Frame, t: f64, s: Vect2, v: Vect2, p: &[Vect2], vel: Vect2, d: f64) -> Tri {
    let (s, v, vel) = (frame.pt(s), frame.pt(v), frame.pt(vel));
    let still = t == 0.0 || vel == v;
    let path = BallV::diff(v, vel).scale(Ball::exact(t));
    let line = PathLine::new(path, d);
    let rel = |i: usize| {
        let q = BallV::diff(frame.pt(p[i]), s);
        (q, line.side(q.v))
    };
    let n = p.len();
    let first = rel(0);
    let (mut a, mut side_a) = first;
    let mut acc = Tri::No;
    for i in 0..n {
        let j = if i + 1 == n { 0 } else { i + 1 };
        let (b, side_b) = if j == 0 { first } else { rel(j) };
        // Both ends beyond D on one side of the path's line: the edge is farther than D
        // from the path. A repeated vertex is no edge (its neighbours cover it).
        let far = side_a != 0 && side_a == side_b;
        if !far && p[i] != p[j] {
            match path_within(path, still, a, b, d) {
                Tri::Yes => return Tri::Yes,
                Tri::Unsure => acc = Tri::Unsure,
                Tri::No => {}
            }
        }
        (a, side_a) = (b, side_b);
    }
    acc
}

/// Does the height leave the shrunk slab (breach lines c0 + t·c1 > 0 for the fence, H
/// already subtracted) at t = 0 or t = T? Linear lines: their least values over [0, T]
/// are at the ends (paper A §III's slab).
fn slab_exit(lines: [SlabLine; 2], t: f64) -> Tri {
    let mut acc = Tri::No;
    for line in lines {
        for tau in [0.0, t] {
            let (x, _) = line.at(tau);
            match positive(x) {
                Tri::No => return Tri::Yes,
                Tri::Unsure => acc = Tri::Unsure,
                Tri::Yes => {}
            }
        }
    }
    acc
}

/// Is the segment 0 → `path` (the point's relative motion; the point 0 alone when
/// `still`) within distance D (closed) of the segment a b? (Paper A §II.G's
/// segments_close with ≤ D; the module doc.)
fn path_within(path: BallV, still: bool, a: BallV, b: BallV, d: f64) -> Tri {
    // Bounding boxes apart by more than D: fl(x − y) > 2(D + 2r) puts the exact gap
    // above D (as segments_close's filter argues).
    let r = mx(path.r, mx(a.r, b.r));
    let gap = up(2.0 * (d + 2.0 * r));
    let apart = |p1: f64, a1: f64, b1: f64| {
        let (p0, p1) = (0.0, p1);
        (a1 - p0 > gap && a1 - p1 > gap && b1 - p0 > gap && b1 - p1 > gap)
            || (p0 - a1 > gap && p1 - a1 > gap && p0 - b1 > gap && p1 - b1 > gap)
    };
    if apart(path.v.x, a.v.x, b.v.x) || apart(path.v.y, a.v.y, b.v.y) {
        return Tri::No;
    }
    let o = BallV::ZERO;
    let d2 = Ball::exact(d).sq();
    if still {
        return point_within(a, b, d2);
    }
    let cross = pr::segments_cross(o, path, a, b, || None);
    if cross == Tri::Yes {
        return Tri::Yes;
    }
    let mut acc = cross;
    // Each end against the other segment, in that end's frame.
    for (x, e, f) in [(o, a, b), (path, a, b), (a, o, path), (b, o, path)] {
        match point_within(e.sub(x), f.sub(x), d2) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

/// Is the origin within distance D (closed; `d2` = D²) of the segment a b? |a|² ≤ D²,
/// |b|² ≤ D², or the foot of the perpendicular on the segment (h₁ = −a·e ≥ 0,
/// h₂ = b·e ≥ 0, |e|² > 0 for e = b − a) with (a × b)² ≤ D²|e|² (paper A §II.C's
/// near_edge, closed). `No` only when each disjunct certainly fails; each failure then
/// puts the distance above D (an end, or the line, is farther).
fn point_within(a: BallV, b: BallV, d2: Ball) -> Tri {
    let ends = nonnegative(d2.sub(a.sq())).or(nonnegative(d2.sub(b.sq())));
    if ends == Tri::Yes {
        return Tri::Yes;
    }
    let e = b.sub(a);
    let len2 = e.sq();
    let foot = nonnegative(a.dot(e).neg())
        .and(nonnegative(b.dot(e)))
        .and(positive(len2));
    if foot == Tri::No {
        return ends;
    }
    let band = nonnegative(d2.mul(len2).sub(a.cross(b).sq()));
    ends.or(foot.and(band))
}

#[cfg(test)]
mod tests;
