//! Keep-in exits, one edge at a time (the conditions of `crate::fence`; paper A §II.C's
//! edge quadratics): does the point come within D of an edge at some t ∈ [0, T]? The
//! scan's ranges of the edge's functions decide each piece of a halving of [0, T]: a
//! piece on which the edge is farther than D is done, one on which it is within D
//! throughout, or is crossed, answers yes.

use super::{centre, close, live, next, sign, Fun, Scan, Tri, VISIT_BUDGET};
use crate::vect2::Vect2;

/// The pending pieces of one edge's halving ([`Scan::comes_within`]): at most one per
/// level, and the resolution is reached within 40 levels.
const DEPTH: usize = 64;

impl Scan<'_> {
    /// The edge the point heads for (a float estimate, for the order of the edges only)
    /// and whether the point is certainly within D of it at the estimated time of the
    /// crossing: a quick `true` for [`Scan::comes_within`], which then starts from that
    /// edge.
    pub(crate) fn heads_for(&self) -> (usize, bool) {
        let n = self.p.len();
        let (when, first) = (0..n)
            .filter(|&i| live(self.p, self.vels, i))
            .map(|i| (self.heading(i as u32), i))
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .unwrap_or((f64::INFINITY, 0));
        (first, when <= self.t && self.close_at(first as u32, when))
    }

    /// Does the point come within D of some edge at some t ∈ [0, T] (the horizontal
    /// part of a keep-in exit, `crate::fence`)? `Yes` certainly (at some instant), `No`
    /// certainly not, `Unsure` otherwise. Each edge on its own, from edge `first` on
    /// (see [`Scan::heads_for`]), by halving [0, T]: a piece on which the edge is farther
    /// than D is done, one on which it is within D throughout (or is crossed: g changes
    /// sign while h₁, h₂ > 0) answers `Yes`.
    pub(crate) fn comes_within(&mut self, first: usize) -> Tri {
        let n = self.p.len();
        let mut acc = Tri::No;
        for k in 0..n {
            let i = (first + k) % n;
            if live(self.p, self.vels, i) {
                match self.edge_within(i as u32) {
                    Tri::Yes => return Tri::Yes,
                    Tri::Unsure => acc = Tri::Unsure,
                    Tri::No => {}
                }
            }
        }
        acc
    }

    /// Edge i certainly within D of the point at the float time t (the closeness test
    /// of [`Scan::edge_within`] on the one-point piece [t, t]).
    fn close_at(&self, i: u32, t: f64) -> bool {
        self.ranges(i, t, 0.0, &[]).is_some_and(|r| close(&r))
    }

    /// When the point, moving as at t = 0 against the edge as it is at t = 0, crosses
    /// edge i's segment (+∞ if it does not): a float estimate that orders the edges in
    /// [`Scan::comes_within`], never a decision.
    fn heading(&self, i: u32) -> f64 {
        let f = &self.frame;
        let (i, j) = (i as usize, next(self.p.len(), i as usize));
        let (a, va) = (f.pt(self.p[i]), f.pt(self.vels[i]));
        let (q0, q1, e0) = (self.s - a, self.v - va, f.pt(self.p[j]) - a);
        let cross = |a: Vect2, b: Vect2| a.x * b.y - a.y * b.x;
        let t = -cross(q0, e0) / cross(q1, e0);
        let along = (q0 + q1.scale(t)).dot(e0) / e0.sq();
        if t >= 0.0 && (0.0..=1.0).contains(&along) {
            t
        } else {
            f64::INFINITY
        }
    }

    /// [`Scan::comes_within`] for edge i: a depth-first halving of [0, T] with its
    /// pending pieces on a stack (one per level, so [`DEPTH`] suffices).
    fn edge_within(&mut self, i: u32) -> Tri {
        let mut slot = None;
        let edge = *self.edge(i, &mut slot);
        let mut stack = [(0.0, 0.0); DEPTH];
        stack[0] = (0.0, self.t);
        let mut top = 1;
        let mut acc = Tri::No;
        while top > 0 {
            top -= 1;
            let (a, b) = stack[top];
            self.visits += 1;
            if self.visits > VISIT_BUDGET {
                return Tri::Unsure;
            }
            let (m, h) = centre(a, b);
            let Some(r) = self.ranges_of(i, &edge, m, h, &[]) else {
                continue;
            };
            if (r.h1.hi() < 0.0 && r.head.lo() > 0.0) || (r.h2.hi() < 0.0 && r.tail.lo() > 0.0) {
                continue;
            }
            let crossed = r.h1.lo() > 0.0 && r.h2.lo() > 0.0 && {
                let g = |t: f64| self.eval(Fun::Cross(i), t).0;
                let (ga, gb) = (sign(g(a)), sign(g(b)));
                ga.is_some() && gb.is_some() && ga != gb
            };
            if close(&r) || crossed {
                return Tri::Yes;
            }
            if b - a <= self.eps || m <= a || m >= b || top + 2 > DEPTH {
                acc = Tri::Unsure;
                continue;
            }
            stack[top] = (m, b);
            stack[top + 1] = (a, m);
            top += 2;
        }
        acc
    }
}
