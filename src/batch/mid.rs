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
//! by [`PathSide::side`] with its stated rounding bound; an undecided corner keeps the
//! pair, and so does a polygon whose reach is unbounded.

use crate::api::MovingPoint;
use crate::ball::U;
use crate::vect2::Vect2;

use super::broad::{Aabb, Prepared};

/// A point's path line for the mid phase: the line through s along v.
pub(super) struct PathSide {
    s: Vect2,
    v: Vect2,
}

impl PathSide {
    /// The constant of [`PathSide::side`]'s bound: 6u raised by (1 + 16u).
    const K: f64 = 6.0 * U * (1.0 + 16.0 * U);

    /// The line through the point's s along its v (both exact floats).
    #[inline]
    pub(super) fn new(p: &MovingPoint) -> PathSide {
        PathSide { s: p.pos, v: p.vel }
    }

    /// Mid phase: +1 when the corner c is certainly strictly left of the path line
    /// (v × (c − s) > 0), −1 certainly right, 0 when not certain.
    ///
    /// q = fl(c − s) is within 2u·|q| of c − s per coordinate (one rounding; exact when
    /// it underflows); l = fl(v_x·q_y) and r = fl(v_y·q_x) are each within
    /// 3u(1 + 2u)·|l| (|r|) of v_x·(c_y − s_y) (v_y·(c_x − s_x)), plus 2⁻¹⁰⁷⁴ when the
    /// product underflows (its 2⁻¹⁰⁷⁵ and the rest); their difference is rounded once
    /// more (u·(|l| + |r|); exact when it underflows). The exact cross product is then
    /// within 4u(1 + 2u)·(|l| + |r|) + 2⁻¹⁰⁷² of fl(l − r). The bound K·(|l| + |r|) + 2⁻¹⁰²² (the smallest normal float, so that
    /// no operation here meets a subnormal, which many processors slow down for) covers
    /// that with its own three roundings (a product that underflows there errs by
    /// 2⁻¹⁰⁷⁵, far below the floor): K·(1 − u)³ > 6u > 4u(1 + 2u). A side
    /// is reported when the computed cross product clears the bound: the exact one then
    /// has its sign. A NaN or infinite cross product never clears it (the comparison is
    /// false, or the bound infinite).
    #[inline(always)]
    fn side(&self, q: Vect2) -> i8 {
        let l = self.v.x * q.y;
        let r = self.v.y * q.x;
        let c = l - r;
        let bound = Self::K * (l.abs() + r.abs()) + f64::MIN_POSITIVE;
        (c > bound) as i8 - (-c > bound) as i8
    }

    /// Mid phase: `true` when the polygon's grown box lies certainly on one side of the
    /// path line (paper A then certainly says no; see the module doc), `false` when the
    /// pair must be decided.
    #[inline(always)]
    pub(super) fn apart(&self, q: &Prepared) -> bool {
        if q.unbounded {
            return false;
        }
        let [lx, ly, hx, hy] = q.mid;
        self.apart_box(lx, ly, hx, hy)
    }

    /// [`PathSide::apart`] on the box [lx, hx] × [ly, hy]: its four corners, each entering
    /// [`PathSide::side`] as fl(c − s), one rounding per coordinate.
    #[inline(always)]
    fn apart_box(&self, lx: f64, ly: f64, hx: f64, hy: f64) -> bool {
        let (x0, x1) = (lx - self.s.x, hx - self.s.x);
        let (y0, y1) = (ly - self.s.y, hy - self.s.y);
        let sides = self.side(Vect2::new(x0, y0))
            + self.side(Vect2::new(x1, y0))
            + self.side(Vect2::new(x1, y1))
            + self.side(Vect2::new(x0, y1));
        // each side is −1, 0 or +1: ±4 only when all four are certain and alike
        sides == 4 || sides == -4
    }
}

/// The polygons' boxes as columns (one array per end), for the scan of a point whose box
/// spans most of the grid: the broad phase's box test and the mid phase's side test on
/// every polygon in turn, without a branch per polygon.
pub(super) struct Columns {
    /// The grown boxes' ends: lo x, lo y, lo z, hi x, hi y, hi z.
    bx: [Vec<f64>; 6],
    /// The mid phase's boxes: lo x, lo y, hi x, hi y.
    mid: [Vec<f64>; 4],
}

impl Columns {
    /// The columns of the prepared polygons' boxes.
    pub(super) fn new(prepared: &[Prepared]) -> Columns {
        let col = |f: &dyn Fn(&Prepared) -> f64| prepared.iter().map(f).collect::<Vec<f64>>();
        Columns {
            bx: [
                col(&|q| q.bx.lo[0]),
                col(&|q| q.bx.lo[1]),
                col(&|q| q.bx.lo[2]),
                col(&|q| q.bx.hi[0]),
                col(&|q| q.bx.hi[1]),
                col(&|q| q.bx.hi[2]),
            ],
            mid: [
                col(&|q| q.mid[0]),
                col(&|q| q.mid[1]),
                col(&|q| q.mid[2]),
                col(&|q| q.mid[3]),
            ],
        }
    }

    /// Broad and mid phase for one point on every polygon, in order: the polygons whose
    /// grown boxes meet `b` ([`Aabb::meets`], the same comparisons) and that
    /// [`PathSide::apart`] does not drop (the same side tests), appended to `out`;
    /// returns how many boxes meet `b` (the broad phase's count).
    ///
    /// An unbounded polygon needs no test of its own here: its grown box has an infinite
    /// or NaN end in the plane, so two of its corners have such a coordinate, whose
    /// cross product with v is infinite or NaN and never clears [`PathSide::side`]'s
    /// bound (an infinite or NaN bound, or a NaN comparison): those sides are 0, kept.
    pub(super) fn scan(&self, b: &Aabb, line: &PathSide, out: &mut Vec<u32>) -> u64 {
        let [lx, ly, lz, hx, hy, hz] = &self.bx;
        let [mlx, mly, mhx, mhy] = &self.mid;
        let m = lx.len();
        let mut met = 0u64;
        // 64 polygons at a time: a mask of those kept, then their indices in order
        let mut base = 0;
        while base < m {
            let end = (base + 64).min(m);
            let (mut keep, mut meet) = (0u64, 0u64);
            for (bit, j) in (base..end).enumerate() {
                // Aabb::meets, with | for || (the same comparisons, no branch)
                let meets = !((b.hi[0] < lx[j])
                    | (hx[j] < b.lo[0])
                    | (b.hi[1] < ly[j])
                    | (hy[j] < b.lo[1])
                    | (b.hi[2] < lz[j])
                    | (hz[j] < b.lo[2]));
                let apart = line.apart_box(mlx[j], mly[j], mhx[j], mhy[j]);
                meet |= (meets as u64) << bit;
                keep |= ((meets & !apart) as u64) << bit;
            }
            met += u64::from(meet.count_ones());
            while keep != 0 {
                out.push((base + keep.trailing_zeros() as usize) as u32);
                keep &= keep - 1;
            }
            base = end;
        }
        met
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::api::{MovingPolygon, Params};

    fn line(s: (f64, f64), v: (f64, f64)) -> PathSide {
        let p = MovingPoint::new_2d(Vect2::new(s.0, s.1), Vect2::new(v.0, v.1)).unwrap();
        PathSide::new(&p)
    }

    /// The side of a corner: certain only beyond the bound, 0 on the line, on a
    /// difference lost to rounding, for a standing point and for infinite coordinates.
    #[test]
    fn a_side_is_reported_only_when_certain() {
        let east = line((0.0, 0.0), (1.0, 0.0));
        assert_eq!(east.side(Vect2::new(5.0, 1e-300)), 1);
        assert_eq!(east.side(Vect2::new(5.0, -1e-300)), -1);
        assert_eq!(east.side(Vect2::new(5.0, 0.0)), 0);
        // below the floor 2⁻¹⁰²²: not certain, though the exact side is clear
        assert_eq!(east.side(Vect2::new(5.0, 1e-310)), 0);
        // a cross product that cancels: v × q = −ε·10¹⁶ ≈ −2.2, below the bound
        // 6u·2·10¹⁶ ≈ 13 (r = fl((1 + ε)·10¹⁶) is 10¹⁶ + 2): not certain
        let diag = line((0.0, 0.0), (1.0, 1.0 + f64::EPSILON));
        assert_eq!(diag.side(Vect2::new(1e16, 1e16)), 0);
        assert_eq!(diag.side(Vect2::new(1.0, 1.0)), 0);
        assert_eq!(diag.side(Vect2::new(1.0, 2.0)), 1);
        assert_eq!(line((0.0, 0.0), (0.0, 0.0)).side(Vect2::new(1.0, 2.0)), 0);
        assert_eq!(east.side(Vect2::new(f64::INFINITY, 1.0)), 0);
        assert_eq!(east.side(Vect2::new(1.0, f64::INFINITY)), 0);
        assert_eq!(east.side(Vect2::new(f64::NAN, 1.0)), 0);
    }

    /// A box wholly above or below the path line is apart; one the line touches (a grown
    /// edge at exactly the line) or crosses is not, nor is an unbounded polygon's.
    #[test]
    fn a_box_is_apart_only_wholly_on_one_side() {
        let params = Params::new(0.5).unwrap();
        let square = |y: f64| {
            let v = vec![
                Vect2::new(0.0, y),
                Vect2::new(1.0, y),
                Vect2::new(1.0, y + 1.0),
                Vect2::new(0.0, y + 1.0),
            ];
            MovingPolygon::new(v, None).unwrap()
        };
        let prep = |q: &MovingPolygon| Prepared::new(1.0, q, &params, 0.0, 0.0);
        let east = line((-10.0, 0.0), (1.0, 0.0));
        // grown by BUFF = 0.5 (rounded outward): from y − 0.5 to y + 1.5
        assert!(east.apart(&prep(&square(1.0))));
        assert!(east.apart(&prep(&square(-3.0))));
        assert!(!east.apart(&prep(&square(0.25))));
        assert!(!east.apart(&prep(&square(-1.5))));
        // the line at the grown box's lower edge, y − 0.5 = 0 before the outward rounding
        assert!(!east.apart(&prep(&square(0.5))));
        // a collapsing edge: unbounded, never apart
        let v = vec![
            Vect2::new(0.0, 5.0),
            Vect2::new(1.0, 5.0),
            Vect2::new(1.0, 6.0),
            Vect2::new(0.0, 6.0),
        ];
        let vels = vec![Vect2::ZERO, Vect2::ZERO, Vect2::ZERO, Vect2::new(1.0, 0.0)];
        let collapsing = MovingPolygon::new(v, Some(vels)).unwrap();
        let p = prep(&collapsing);
        assert!(p.unbounded && !east.apart(&p));
    }
}
