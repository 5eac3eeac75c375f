//! Batch detection's mid phase (not in paper A; extends its §II.H, §II.I and §III to many
//! pairs): a pair the broad phase kept is dropped when the polygon's grown box lies
//! certainly on one side of the point's path line, a test of four corners, far cheaper
//! than the paper function it spares.
//!
//! **Why it is sound.** Paper A computed without rounding answers "yes" for a pair only
//! when at some time t ∈ [0, T] (in 3D, t in the slab window, a part of [0, T]) the point
//! s + t·v lies within the polygon's reach, in the max norm, of the polygon at t (the
//! broad phase's `reach`, step by step: definitely_outside at t = 0 and t = T, and
//! segments_close and edge_detect at the time they find), hence inside the polygon's
//! grown box: its box swept over [0, T] grown by the reach, whose float ends enclose the
//! exact one. s + t·v lies on the line through s along v. When all four corners of the
//! grown box lie strictly on one side of that line, so does the box (their convex hull),
//! and no point of the line is in it: paper A says no. The side of each corner is decided
//! by [`PathLine::side`] with its stated rounding bound; an undecided corner keeps the
//! pair, and so does a polygon whose reach is unbounded.

use crate::api::MovingPoint;
use crate::ball::BallV;
use crate::predicates::PathLine;
use crate::vect2::Vect2;

use super::broad::Prepared;

/// A point's path line for the mid phase: the line through s along v.
pub(super) struct PathSide {
    line: PathLine,
    s: Vect2,
}

impl PathSide {
    /// The line through the point's s along its v (exact floats: a ball of radius 0),
    /// sides taken strictly beyond it (distance 0).
    #[inline]
    pub(super) fn new(p: &MovingPoint) -> PathSide {
        PathSide {
            line: PathLine::new(BallV::exact(p.vel), 0.0),
            s: p.pos,
        }
    }

    /// Mid phase: `true` when the polygon's grown box lies certainly on one side of the
    /// path line (paper A then certainly says no; see the module doc), `false` when the
    /// pair must be decided.
    ///
    /// Each corner c enters as q = fl(c − s), one rounding per coordinate, which is what
    /// [`PathLine::side`] bounds. With d = v exact (r_d = 0) its bound is
    /// 6u(1 + 16u)·(|l| + |r|), l and r the two products of the cross product v × q
    /// (q's roundings, the products and the difference: PathLine's derivation), plus
    /// its constant term, here up(up(0)) ≈ 2⁻¹⁰⁶⁴ ([`crate::ball::up`]), which covers
    /// the at most 2⁻¹⁰⁷⁵ absolute error of each product that underflows (a subtraction
    /// that underflows is exact). A side is reported only when the computed cross
    /// product clears that bound, and the exact one then has its sign. A NaN or infinite
    /// cross product never clears it (the comparison is false).
    #[inline(always)]
    pub(super) fn apart(&self, q: &Prepared) -> bool {
        if q.unbounded {
            return false;
        }
        let [lx, ly, hx, hy] = q.mid;
        let (x0, x1) = (lx - self.s.x, hx - self.s.x);
        let (y0, y1) = (ly - self.s.y, hy - self.s.y);
        let sides = self.line.side(Vect2::new(x0, y0))
            + self.line.side(Vect2::new(x1, y0))
            + self.line.side(Vect2::new(x1, y1))
            + self.line.side(Vect2::new(x0, y1));
        // each side is −1, 0 or +1: ±4 only when all four are certain and alike
        sides == 4 || sides == -4
    }
}
