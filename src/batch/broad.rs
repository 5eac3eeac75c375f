//! Batch detection's broad phase (not in paper A; extends its §II.H, §II.I and §III to
//! many pairs): each point's swept box, each polygon's swept box grown by its reach, and
//! the uniform grid that finds the pairs whose boxes meet (see the parent module).

use std::vec::Vec;

use crate::api::{MovingPoint, MovingPolygon, Params};
use crate::ball::{self, round_down, round_up, Ball};
use crate::detect::{dispatch, never_collapses, Method};

/// A box [lo, hi] in x, y and z (z is (−∞, ∞) for a 2D item). Its ends are floats that
/// bound the exact quantities they stand for from outside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Aabb {
    pub(super) lo: [f64; 3],
    pub(super) hi: [f64; 3],
}

impl Aabb {
    /// Broad phase (extends paper A §II.H, §II.I, §III): the boxes share a point. Exact
    /// float comparisons of ends that bound the exact boxes from outside: `false` proves
    /// the exact boxes disjoint. (A NaN end, which finite inputs never give, compares
    /// false both ways and keeps the pair.)
    #[inline(always)]
    pub(super) fn meets(&self, o: &Aabb) -> bool {
        !(self.hi[0] < o.lo[0]
            || o.hi[0] < self.lo[0]
            || self.hi[1] < o.lo[1]
            || o.hi[1] < self.lo[1]
            || self.hi[2] < o.lo[2]
            || o.hi[2] < self.lo[2])
    }
}

/// Broad phase (extends paper A §II): the range of c + t·w over t ∈ [0, T], as floats
/// that enclose the exact range: c exactly at t = 0, and at T the ends of the ball
/// c + T·w of [`ball`] (the product and the sum each rounded, their error bounded by
/// the ball's radius, the ends rounded outward by [`Ball::lo`] and [`Ball::hi`]).
#[inline]
fn swept(c: f64, w: f64, t: f64) -> (f64, f64) {
    let end = Ball::exact(c).add(Ball::exact(w).scale(t));
    (c.min(end.lo()), c.max(end.hi()))
}

/// Broad phase (extends paper A §II, §III): the box swept by s + t·v (and its height)
/// over [0, T], enclosing the exact one.
pub(super) fn point_box(t: f64, p: &MovingPoint) -> Aabb {
    let (x0, x1) = swept(p.pos.x, p.vel.x, t);
    let (y0, y1) = swept(p.pos.y, p.vel.y, t);
    let (z0, z1) = match p.z {
        Some((sz, vz)) => swept(sz, vz, t),
        None => (f64::NEG_INFINITY, f64::INFINITY),
    };
    Aabb {
        lo: [x0, y0, z0],
        hi: [x1, y1, z1],
    }
}

/// Broad phase: how far (in the max norm, in the plane) from the polygon's swept box the
/// swept box of a point can be when paper A, computed without rounding, answers "yes"
/// (paper A §II.E, §II.H, §II.I). An upper bound, rounded up:
///
/// - **BUFF** for every polygon. definitely_outside (§II.E) is false only within BUFF of
///   P's box: a point more than BUFF left or right of the box perturbs no vertex
///   (|p_x − s_x| > BUFF) and sees no edge straddle its vertical; more than BUFF above,
///   it perturbs none and every edge lies below it; more than BUFF below, the perturbed
///   vertices move to x ≤ s_x − BUFF, no vertex of P*_BUFF lies on its vertical, so the
///   closed ring crosses the whole vertical (all of it above the point) an even number
///   of times. The near_edge tests are Euclidean distances ≤ BUFF, which bound the max
///   norm. segments_close (§II.H step 3) is a distance ≤ BUFF between the point and an
///   edge at one time t, both inside their swept boxes.
/// - **F·L** for a warping polygon (§II.I), L = the longest edge at 0 or T (‖·‖₁, an
///   upper bound of ‖·‖₂; an edge's length is convex in t, so its largest over [0, T]
///   is at an end). edge_detect accepts a point within (1 + F)·‖a‖ of the edge's
///   midpoint along it and F·‖a‖ across (a the half edge, ‖a‖ ≤ L/2): at most
///   √2·F·L/2 < F·L from the edge at that time.
/// - **∞** when an edge may shrink to a point within [0, T] (not provably
///   [`never_collapses`]): inequalities (1) of §II.I read 0 ≤ 0 there and accept any
///   point. Such a polygon meets every point in the plane (`unbounded`).
///
/// In 3D (§III) the slab window is the exact time set where the height is in the slab,
/// with no BUFF: the reach in z is 0.
fn reach(t: f64, q: &MovingPolygon, params: &Params) -> f64 {
    let (p, vels) = (q.vertices(), q.velocities());
    let buff = params.buff();
    if dispatch(false, vels) == Method::DetectSame2d {
        return buff;
    }
    let n = p.len();
    let mut longest = 0.0f64;
    for i in 0..n {
        let j = if i + 1 == n { 0 } else { i + 1 };
        let (pi, pj, vi, vj) = (p[i], p[j], vels[i], vels[j]);
        if !never_collapses(0.0, t, pi, pj, vi, vj) {
            return f64::INFINITY;
        }
        // At 0: two rounded differences and their sum (3 roundings, within ball::up).
        let l0 = ball::up((pj.x - pi.x).abs() + (pj.y - pi.y).abs());
        // At T: the ends as balls, their difference's magnitude plus its radius.
        let at = |c: f64, w: f64| Ball::exact(c).add(Ball::exact(w).scale(t));
        let dx = at(pj.x, vj.x).sub(at(pi.x, vi.x));
        let dy = at(pj.y, vj.y).sub(at(pi.y, vi.y));
        let l1 = ball::up(dx.z.abs() + dx.r + dy.z.abs() + dy.r);
        longest = longest.max(l0).max(l1);
    }
    // One product rounding, within up.
    buff.max(ball::up(params.fac() * longest))
}

/// A polygon made ready for the broad phase: its grown box, and whether it is unbounded.
#[derive(Clone, Copy, Debug)]
pub(super) struct Prepared {
    pub(super) bx: Aabb,
    /// The grown box in the plane for the mid phase, [lo x, lo y, hi x, hi y]: `bx`'s
    /// (but for the mid phase's canary).
    pub(super) mid: [f64; 4],
    pub(super) unbounded: bool,
}

impl Prepared {
    /// Broad phase (extends paper A §II, §III): the box swept by the vertices over
    /// [0, T] (each vertex moves on a segment, the polygon at every t lies in the convex
    /// hull of its vertices), grown by [`reach`] in x and y (plus `offset`, 0 but for the
    /// canary), rounded outward; in z the slab's swept range, reach 0. The mid phase's
    /// box is the same in the plane, grown by `mid_offset` more (0 but for its canary).
    pub(super) fn new(
        t: f64,
        q: &MovingPolygon,
        params: &Params,
        offset: f64,
        mid_offset: f64,
    ) -> Prepared {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for (p, v) in q.vertices().iter().zip(q.velocities()) {
            let (x0, x1) = swept(p.x, v.x, t);
            let (y0, y1) = swept(p.y, v.y, t);
            lo[0] = lo[0].min(x0);
            hi[0] = hi[0].max(x1);
            lo[1] = lo[1].min(y0);
            hi[1] = hi[1].max(y1);
        }
        let r = reach(t, q, params) + offset;
        let unbounded = !r.is_finite();
        for k in 0..2 {
            // one subtraction (addition) each, rounded outward
            lo[k] = round_down(lo[k] - r);
            hi[k] = round_up(hi[k] + r);
        }
        match q.slab() {
            Some(s) => {
                let (b0, b1) = swept(s.bottom, s.vz, t);
                let (t0, t1) = swept(s.top, s.vz, t);
                lo[2] = b0.min(t0);
                hi[2] = b1.max(t1);
            }
            None => {
                lo[2] = f64::NEG_INFINITY;
                hi[2] = f64::INFINITY;
            }
        }
        // mid_offset is 0 but for the canary: the same floats then (x − 0 = x)
        let mid = [
            lo[0] - mid_offset,
            lo[1] - mid_offset,
            hi[0] + mid_offset,
            hi[1] + mid_offset,
        ];
        Prepared {
            bx: Aabb { lo, hi },
            mid,
            unbounded: unbounded
                || !(lo[0].is_finite() && lo[1].is_finite())
                || !(hi[0].is_finite() && hi[1].is_finite()),
        }
    }
}

/// Which broad phase a batch uses.
pub(super) enum Index {
    Grid(Grid),
    All,
}

/// A uniform grid over the bounded polygons' boxes in the plane (broad phase, extending
/// paper A to many pairs): cell lists in one array (CSR), plus the unbounded polygons,
/// which every point meets in the plane.
///
/// A box covers the cells from `cell(lo)` to `cell(hi)` on each axis. `cell` is a
/// composition of correctly rounded, hence monotone, operations (a subtraction, a
/// product by a positive constant, floor and clamping), so two boxes that meet have cell
/// ranges that meet; a pair is then looked at only in the one cell where both ranges
/// start (the larger of the two starts on each axis), so it is never seen twice, and the
/// boxes themselves are compared before the pair is kept.
pub(super) struct Grid {
    x0: f64,
    y0: f64,
    inv_x: f64,
    inv_y: f64,
    nx: usize,
    ny: usize,
    starts: Vec<u32>,
    items: Vec<u32>,
    unbounded: Vec<u32>,
    /// Each polygon's first cell (x, y): where its range starts (0 for an unbounded one).
    first: Vec<(u32, u32)>,
}

impl Grid {
    /// Broad phase: about as many cells as √M on a side, up to twice that, and no
    /// smaller than the mean box, so that a polygon sits in a few cells.
    pub(super) fn new(prepared: &[Prepared]) -> Grid {
        let mut unbounded = Vec::new();
        let (mut x0, mut y0) = (f64::INFINITY, f64::INFINITY);
        let (mut x1, mut y1) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        let (mut sw, mut sh, mut m) = (0.0, 0.0, 0usize);
        for (j, p) in prepared.iter().enumerate() {
            if p.unbounded {
                unbounded.push(j as u32);
                continue;
            }
            x0 = x0.min(p.bx.lo[0]);
            y0 = y0.min(p.bx.lo[1]);
            x1 = x1.max(p.bx.hi[0]);
            y1 = y1.max(p.bx.hi[1]);
            sw += p.bx.hi[0] - p.bx.lo[0];
            sh += p.bx.hi[1] - p.bx.lo[1];
            m += 1;
        }
        let side = ((m as f64).sqrt().ceil() * 2.0).max(1.0);
        let cells = |extent: f64, mean: f64| -> usize {
            let by_size = if mean > 0.0 { extent / mean } else { side };
            let n = by_size.min(side).ceil();
            if n.is_finite() && n >= 1.0 {
                n as usize
            } else {
                1
            }
        };
        let (mf, ex, ey) = (m.max(1) as f64, x1 - x0, y1 - y0);
        let nx = if m == 0 { 1 } else { cells(ex, sw / mf) };
        let ny = if m == 0 { 1 } else { cells(ey, sh / mf) };
        let inv = |n: usize, e: f64| {
            let k = n as f64 / e;
            if n > 1 && k.is_finite() && k > 0.0 {
                k
            } else {
                0.0
            }
        };
        let mut g = Grid {
            x0,
            y0,
            inv_x: inv(nx, ex),
            inv_y: inv(ny, ey),
            nx: if inv(nx, ex) > 0.0 { nx } else { 1 },
            ny: if inv(ny, ey) > 0.0 { ny } else { 1 },
            starts: Vec::new(),
            items: Vec::new(),
            unbounded,
            first: vec![(0, 0); prepared.len()],
        };
        let mut counts = vec![0u32; g.nx * g.ny + 1];
        let bounded = || prepared.iter().enumerate().filter(|(_, p)| !p.unbounded);
        for (_, p) in bounded() {
            let (cx0, cx1, cy0, cy1) = g.range(&p.bx);
            for cy in cy0..=cy1 {
                for cx in cx0..=cx1 {
                    counts[cy * g.nx + cx + 1] += 1;
                }
            }
        }
        for k in 1..counts.len() {
            counts[k] += counts[k - 1];
        }
        let mut fill = counts.clone();
        g.items = vec![0; counts[counts.len() - 1] as usize];
        for (j, p) in bounded() {
            let (cx0, cx1, cy0, cy1) = g.range(&p.bx);
            for cy in cy0..=cy1 {
                for cx in cx0..=cx1 {
                    let c = cy * g.nx + cx;
                    g.items[fill[c] as usize] = j as u32;
                    fill[c] += 1;
                }
            }
        }
        g.starts = counts;
        for (j, p) in bounded() {
            let (cx0, _, cy0, _) = g.range(&p.bx);
            // cell indices are below nx, ny, which count cells holding u32 entries
            g.first[j] = (cx0 as u32, cy0 as u32);
        }
        g
    }

    /// The cell of coordinate `x` on an axis starting at `origin` with `inv` cells per
    /// unit and `n` cells: monotone in `x` (see [`Grid`]).
    #[inline(always)]
    fn cell(x: f64, origin: f64, inv: f64, n: usize) -> usize {
        if n == 1 {
            return 0;
        }
        let k = ((x - origin) * inv).floor();
        if k >= (n - 1) as f64 {
            n - 1
        } else if k >= 0.0 {
            k as usize
        } else {
            // below the grid, and NaN (which finite inputs never give): the first cell
            0
        }
    }

    /// The cells a box covers: (x from, x to, y from, y to), inclusive.
    #[inline(always)]
    fn range(&self, b: &Aabb) -> (usize, usize, usize, usize) {
        (
            Self::cell(b.lo[0], self.x0, self.inv_x, self.nx),
            Self::cell(b.hi[0], self.x0, self.inv_x, self.nx),
            Self::cell(b.lo[1], self.y0, self.inv_y, self.ny),
            Self::cell(b.hi[1], self.y0, self.inv_y, self.ny),
        )
    }

    /// Whether the cells `b` covers hold at least half as many entries as there are
    /// polygons (`m`): a point whose box spans most of the grid, for which comparing
    /// every polygon's box in turn costs less than visiting the cells and sorting.
    pub(super) fn spans_most(&self, b: &Aabb, m: usize) -> bool {
        let (cx0, cx1, cy0, cy1) = self.range(b);
        // a row's cells cx0..=cx1 hold contiguous entries
        let covered: usize = (cy0..=cy1)
            .map(|cy| {
                (self.starts[cy * self.nx + cx1 + 1] - self.starts[cy * self.nx + cx0]) as usize
            })
            .sum();
        2 * covered >= m
    }

    /// The polygons whose grown boxes meet `b`, each once, appended to `out` (in no
    /// particular order).
    pub(super) fn candidates(&self, b: &Aabb, prepared: &[Prepared], out: &mut Vec<u32>) {
        let (cx0, cx1, cy0, cy1) = self.range(b);
        for cy in cy0..=cy1 {
            for cx in cx0..=cx1 {
                let c = cy * self.nx + cx;
                let (s, e) = (self.starts[c] as usize, self.starts[c + 1] as usize);
                for &j in &self.items[s..e] {
                    let (qx, qy) = self.first[j as usize];
                    // the cell where both ranges start: the pair is looked at there only
                    if cx == cx0.max(qx as usize)
                        && cy == cy0.max(qy as usize)
                        && b.meets(&prepared[j as usize].bx)
                    {
                        out.push(j);
                    }
                }
            }
        }
        for &j in &self.unbounded {
            if b.meets(&prepared[j as usize].bx) {
                out.push(j);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::tests::square;
    use crate::vect2::Vect2;

    /// The swept range encloses the exact c + T·w at both ends, also where the product
    /// and the sum round (1e16 + 0.3·3 is not a float).
    #[test]
    fn swept_encloses_the_rounded_end() {
        let (lo, hi) = swept(1e16, 0.3, 3.0);
        assert!(lo <= 1e16 && hi > 1e16 + 0.5, "{lo} {hi}");
        let (lo, hi) = swept(0.1, -0.7, 3.0);
        // exact end 0.1 − 2.1 = −2.0 (for the decimals; the floats are within 1e-15)
        assert!(
            lo < -2.0 + 1e-14 && lo > -2.0 - 1e-14 && hi == 0.1,
            "{lo} {hi}"
        );
    }

    /// A statically shaped polygon reaches BUFF; a warping one F times its longest
    /// edge (at 0 or T) when that is more; one whose edge shrinks to a point, everywhere.
    #[test]
    fn reach_is_buff_or_f_times_the_longest_edge_or_unbounded() {
        let params = Params::new(0.01).unwrap().with_fac(0.5).unwrap();
        let still = square(0.0, 0.0, Vect2::ZERO);
        assert_eq!(reach(10.0, &still, &params), 0.01);
        // The top edge stretches to length 1 + 10·0.1 = 2 at T = 10 (‖·‖₁ = 2).
        let v = vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(1.0, 0.0),
            Vect2::new(1.0, 1.0),
            Vect2::new(0.0, 1.0),
        ];
        let vels = vec![Vect2::ZERO, Vect2::ZERO, Vect2::ZERO, Vect2::new(-0.1, 0.0)];
        let warping = MovingPolygon::new(v.clone(), Some(vels)).unwrap();
        let r = reach(10.0, &warping, &params);
        assert!((1.0..1.0 + 1e-12).contains(&r), "{r}");
        // Vertex 3 runs onto vertex 2 at t = 1 (the top edge collapses).
        let vels = vec![Vect2::ZERO, Vect2::ZERO, Vect2::ZERO, Vect2::new(1.0, 0.0)];
        let collapsing = MovingPolygon::new(v, Some(vels)).unwrap();
        assert_eq!(reach(10.0, &collapsing, &params), f64::INFINITY);
        // Before the collapse (T = 0.5) the longest edge is 3–0, from (0.5, 1) to (0, 0):
        // ‖·‖₁ = 1.5, reach 0.75.
        let r = reach(0.5, &collapsing, &params);
        assert!((0.75..0.75 + 1e-12).contains(&r), "{r}");
    }

    /// The grid finds what testing every pair finds, on polygons in a row and points
    /// whose boxes straddle cells, and nothing twice; points whose boxes span most of the
    /// grid (velocities up to 20 over T = 1 across a 24 × 15 grid) are told apart (the
    /// batch scans every polygon's box for them).
    #[test]
    fn grid_finds_the_pairs_every_pair_test_finds() {
        let params = Params::new(0.01).unwrap();
        let polys: Vec<_> = (0..40)
            .map(|k| square(3.0 * (k % 8) as f64, 3.0 * (k / 8) as f64, Vect2::ZERO))
            .collect();
        let prepared: Vec<_> = polys
            .iter()
            .map(|q| Prepared::new(1.0, q, &params, 0.0, 0.0))
            .collect();
        let g = Grid::new(&prepared);
        assert!(g.nx > 1 && g.ny > 1);
        let (mut scanned, mut visited) = (0, 0);
        for k in 0..400 {
            let s = Vect2::new(
                -2.0 + 0.13 * (k % 200) as f64,
                -1.0 + 0.07 * (k % 200) as f64,
            );
            let speed = if k < 200 { 1.0 } else { 0.1 * (k - 200) as f64 };
            let p = MovingPoint::new_2d(s, Vect2::new(2.0 * speed, speed)).unwrap();
            let b = point_box(1.0, &p);
            let mut got = Vec::new();
            if g.spans_most(&b, 40) {
                scanned += 1;
            } else {
                visited += 1;
            }
            g.candidates(&b, &prepared, &mut got);
            got.sort_unstable();
            let want: Vec<u32> = (0..40)
                .filter(|&j| b.meets(&prepared[j as usize].bx))
                .collect();
            assert_eq!(got, want, "point {k}");
        }
        assert!(
            scanned > 50 && visited > 200,
            "{scanned} scanned, {visited} visited"
        );
    }
}
