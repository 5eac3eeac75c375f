//! Batch detection: N moving points against M moving polygons in one call (extends paper
//! A §II.H, §II.I and §III from one pair to many).
//!
//! Two phases:
//!
//! 1. **Broad phase** (not in the paper): each point gets the box swept by its positions
//!    over [0, T], each polygon the box swept by its vertices, grown by the polygon's
//!    *reach*, the farthest (in the max norm) that paper A computed without rounding can
//!    answer "yes" from (the private `reach`: BUFF; F times the longest edge for a
//!    warping polygon when that is more; unbounded when an edge may shrink to a point;
//!    docs/batch.md). Boxes are rounded outward, so a pair whose boxes
//!    are disjoint is one that paper A certainly answers "no": the broad phase never drops
//!    a pair paper A (or the engine) detects. Pairs are found through a uniform grid over
//!    the polygons' boxes (`Broad::Grid`); `Broad::AllPairs` tests every pair's boxes,
//!    the reference the grid is measured and tested against.
//! 2. **Narrow phase**: the certified paper functions on the slices, as
//!    [`api::decide`](crate::api::decide) calls them ([`detect_same_2d_tri`](crate::detect::detect_same_2d_tri),
//!    [`detect_diff_2d_tri`](crate::detect::detect_diff_2d_tri), [`detect_3d_tri`](crate::detect::detect_3d_tri)), with no allocation per pair.
//!
//! With the feature `parallel` the points are answered in chunks across rayon's threads;
//! without it the same code runs on the calling thread. The answer is the same either
//! way, sorted by (point, polygon).
//!
//! ```
//! use polyguard::api::{MovingPoint, MovingPolygon, Params};
//! use polyguard::batch::detect_batch;
//! use polyguard::Vect2;
//!
//! let square = |x: f64| {
//!     let v = vec![[x, 0.0].into(), [x + 1.0, 0.0].into(), [x + 1.0, 1.0].into(), [x, 1.0].into()];
//!     MovingPolygon::new(v, None)
//! };
//! let polygons = vec![square(0.0)?, square(10.0)?];
//! let points = vec![
//!     MovingPoint::new_2d(Vect2::new(0.5, -2.0), Vect2::new(0.0, 1.0))?, // into square 0
//!     MovingPoint::new_2d(Vect2::new(5.0, -2.0), Vect2::new(0.0, 1.0))?, // between them
//! ];
//! let hits = detect_batch(10.0, &points, &polygons, &Params::new(0.01)?)?;
//! assert_eq!(hits.len(), 1);
//! assert_eq!((hits[0].point, hits[0].polygon), (0, 0));
//! # Ok::<(), polyguard::error::CaseError>(())
//! ```

use std::vec::Vec;

use crate::api::{decide_pair, Kind, MovingPoint, MovingPolygon, Params};
use crate::ball::{self, round_down, round_up, Ball, Tri};
use crate::detect::{dispatch, never_collapses, Method};
use crate::error::CaseError;

/// One detected pair: point `point` (its index in the points given) may enter polygon
/// `polygon` (its index) within [0, T] (paper A §II.H, §II.I, §III).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Hit {
    /// The point's index.
    pub point: usize,
    /// The polygon's index.
    pub polygon: usize,
    /// `Exact`: every comparison behind the "yes" was certified; `Conservative`: a "yes"
    /// taken on a comparison f64 could not decide (see [`Kind`]).
    pub kind: Kind,
    /// Which paper function decided (detect_same_2D, detect_diff_2D or detect_3D).
    pub method: Method,
}

/// How pairs are found (a tuning and test knob; the answer does not depend on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Broad {
    /// A uniform grid over the polygons' grown boxes (the default).
    Grid,
    /// Every pair's boxes tested: O(N·M), the reference for the grid.
    AllPairs,
}

/// Options of [`detect_batch_with`]. `Default` is what [`detect_batch`] uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// How pairs are found.
    pub broad: Broad,
    /// Use rayon's threads (only with the feature `parallel`; ignored without it).
    pub parallel: bool,
    /// Added to every polygon's reach. 0 in any real use: a negative value makes the
    /// broad phase unsound, on purpose, for the tests that must see it drop pairs (the
    /// canary).
    pub reach_offset: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            broad: Broad::Grid,
            parallel: true,
            reach_offset: 0.0,
        }
    }
}

/// What a batch found and how much work the broad phase left (for reports).
#[derive(Clone, Debug, PartialEq)]
pub struct Batch {
    /// The hits, sorted by (point, polygon).
    pub hits: Vec<Hit>,
    /// Pairs the broad phase kept, each answered by a paper function.
    pub candidates: u64,
    /// Polygons that meet every point's box in the plane (an edge that may shrink to a
    /// point within [0, T]: paper A's edge_detect accepts anywhere then, §II.I).
    pub unbounded_polygons: usize,
}

/// Paper A for every point against every polygon: the hits, sorted by (point, polygon),
/// the pairs for which [`api::detected`](crate::api::detected) says yes for
/// `Case::new(lookahead, point, polygon, params)`, with the same kind and method.
///
/// Every pair that paper A computed without rounding detects is among them (the broad
/// phase drops a pair only when its grown boxes prove paper A's "no"). The one way the
/// batch can differ from the pairwise engine is in its favour: a pair whose boxes are
/// that far apart, which the pairwise engine would still answer with a conservative
/// "yes" because some comparison could not be decided in f64 (magnitudes near overflow,
/// or an edge that nearly shrinks to a point), is left out, as paper A certainly says no
/// there. tests/batch.rs checks exactly that against the oracle (a proptest found such a
/// pair: `a_conservative_pairwise_yes_that_paper_a_denies_may_be_spared`); on the bench's
/// workloads (crates/harness/examples/batch_vs_pairwise.rs) the two are equal pair for pair.
///
/// Errors: `lookahead` not finite or not > 0 (field `lookahead`); a 3D point (with a
/// height) in the same batch as a 2D polygon (without a slab), or the reverse (field
/// `point.pos` or `polygon.bottom`, as [`Case::new`](crate::api::Case::new)): a batch is
/// all 2D or all 3D. Empty lists give no hits and no error.
pub fn detect_batch(
    lookahead: f64,
    points: &[MovingPoint],
    polygons: &[MovingPolygon],
    params: &Params,
) -> Result<Vec<Hit>, CaseError> {
    detect_batch_with(lookahead, points, polygons, params, &Options::default()).map(|b| b.hits)
}

/// [`detect_batch`] with [`Options`], and the broad phase's counts.
pub fn detect_batch_with(
    lookahead: f64,
    points: &[MovingPoint],
    polygons: &[MovingPolygon],
    params: &Params,
    options: &Options,
) -> Result<Batch, CaseError> {
    if !lookahead.is_finite() {
        return Err(CaseError::NotFinite {
            field: "lookahead".into(),
        });
    }
    // finite here: not > 0 is ≤ 0
    if lookahead <= 0.0 {
        return Err(CaseError::NotPositive {
            field: "lookahead",
            value: lookahead,
        });
    }
    if points.is_empty() || polygons.is_empty() {
        return Ok(Batch {
            hits: Vec::new(),
            candidates: 0,
            unbounded_polygons: 0,
        });
    }
    let three_d = points[0].z.is_some();
    if points.iter().any(|p| p.z.is_some() != three_d) {
        return Err(CaseError::DimensionMismatch {
            field: "point.pos",
            detail: "some points have a height and others not; a batch is all 2D or all 3D",
        });
    }
    if let Some(_q) = polygons.iter().find(|q| q.slab().is_some() != three_d) {
        return Err(if three_d {
            CaseError::DimensionMismatch {
                field: "polygon.bottom",
                detail: "the points have a height but a polygon has no bottom/top/vz",
            }
        } else {
            CaseError::DimensionMismatch {
                field: "point.pos",
                detail: "a polygon has bottom/top/vz but the points have no height",
            }
        });
    }
    let t = lookahead;
    let prepared: Vec<Prepared> = polygons
        .iter()
        .map(|q| Prepared::new(t, q, params, options.reach_offset))
        .collect();
    let point_boxes: Vec<Aabb> = points.iter().map(|p| point_box(t, p)).collect();
    let index = match options.broad {
        Broad::Grid => Index::Grid(Grid::new(&prepared)),
        Broad::AllPairs => Index::All,
    };
    let ctx = Ctx {
        t,
        points,
        polygons,
        params,
        prepared: &prepared,
        point_boxes: &point_boxes,
        index: &index,
    };
    let chunks = chunk_results(&ctx, options.parallel);
    let mut hits = Vec::with_capacity(chunks.iter().map(|c| c.hits.len()).sum());
    let mut candidates = 0;
    for c in chunks {
        hits.extend_from_slice(&c.hits);
        candidates += c.candidates;
    }
    Ok(Batch {
        hits,
        candidates,
        unbounded_polygons: prepared.iter().filter(|p| p.unbounded).count(),
    })
}

/// Points per chunk of work: large enough that a chunk's buffers and rayon's hand-off
/// cost little per point, small enough to balance two to dozens of threads.
const CHUNK: usize = 256;

/// One chunk's answer.
struct ChunkResult {
    hits: Vec<Hit>,
    candidates: u64,
}

/// Everything a chunk reads.
struct Ctx<'a> {
    t: f64,
    points: &'a [MovingPoint],
    polygons: &'a [MovingPolygon],
    params: &'a Params,
    prepared: &'a [Prepared],
    point_boxes: &'a [Aabb],
    index: &'a Index,
}

/// The chunks' answers, in order: across rayon's threads with `parallel`, else here.
#[cfg(feature = "parallel")]
fn chunk_results(ctx: &Ctx<'_>, parallel: bool) -> Vec<ChunkResult> {
    use rayon::prelude::*;
    let n = ctx.points.len();
    let starts: Vec<usize> = (0..n).step_by(CHUNK).collect();
    if parallel {
        starts
            .par_iter()
            .map_init(Vec::new, |scratch, &s| {
                run_chunk(ctx, s, (s + CHUNK).min(n), scratch)
            })
            .collect()
    } else {
        let mut scratch = Vec::new();
        starts
            .iter()
            .map(|&s| run_chunk(ctx, s, (s + CHUNK).min(n), &mut scratch))
            .collect()
    }
}

/// The chunks' answers, in order, on this thread (without the feature `parallel`).
#[cfg(not(feature = "parallel"))]
fn chunk_results(ctx: &Ctx<'_>, _parallel: bool) -> Vec<ChunkResult> {
    let n = ctx.points.len();
    let mut scratch = Vec::new();
    (0..n)
        .step_by(CHUNK)
        .map(|s| run_chunk(ctx, s, (s + CHUNK).min(n), &mut scratch))
        .collect()
}

/// Points `start..end`: each one's candidates (into `scratch`, reused), sorted, then
/// answered by the paper function for the pair (paper A §II.F's dispatch).
fn run_chunk(ctx: &Ctx<'_>, start: usize, end: usize, scratch: &mut Vec<u32>) -> ChunkResult {
    let mut out = ChunkResult {
        hits: Vec::new(),
        candidates: 0,
    };
    for i in start..end {
        scratch.clear();
        let b = &ctx.point_boxes[i];
        match ctx.index {
            Index::Grid(g) => g.candidates(b, ctx.prepared, scratch),
            Index::All => scratch.extend(
                (0..ctx.prepared.len() as u32).filter(|&j| b.meets(&ctx.prepared[j as usize].bx)),
            ),
        }
        scratch.sort_unstable();
        out.candidates += scratch.len() as u64;
        let p = &ctx.points[i];
        for &j in scratch.iter() {
            let j = j as usize;
            let (method, tri) = decide_pair(ctx.t, p, &ctx.polygons[j], ctx.params);
            let kind = match tri {
                Tri::No => continue,
                Tri::Yes => Kind::Exact,
                Tri::Unsure => Kind::Conservative,
            };
            out.hits.push(Hit {
                point: i,
                polygon: j,
                kind,
                method,
            });
        }
    }
    out
}

// ============================================================== the broad phase

/// A box [lo, hi] in x, y and z (z is (−∞, ∞) for a 2D item). Its ends are floats that
/// bound the exact quantities they stand for from outside.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Aabb {
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Aabb {
    /// Broad phase (extends paper A §II.H, §II.I, §III): the boxes share a point. Exact
    /// float comparisons of ends that bound the exact boxes from outside: `false` proves
    /// the exact boxes disjoint. (A NaN end, which finite inputs never give, compares
    /// false both ways and keeps the pair.)
    #[inline(always)]
    fn meets(&self, o: &Aabb) -> bool {
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
fn point_box(t: f64, p: &MovingPoint) -> Aabb {
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
struct Prepared {
    bx: Aabb,
    unbounded: bool,
}

impl Prepared {
    /// Broad phase (extends paper A §II, §III): the box swept by the vertices over
    /// [0, T] (each vertex moves on a segment, the polygon at every t lies in the convex
    /// hull of its vertices), grown by [`reach`] in x and y (plus `offset`, 0 but for the
    /// canary), rounded outward; in z the slab's swept range, reach 0.
    fn new(t: f64, q: &MovingPolygon, params: &Params, offset: f64) -> Prepared {
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
        Prepared {
            bx: Aabb { lo, hi },
            unbounded: unbounded
                || !(lo[0].is_finite() && lo[1].is_finite())
                || !(hi[0].is_finite() && hi[1].is_finite()),
        }
    }
}

/// Which broad phase a batch uses.
enum Index {
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
struct Grid {
    x0: f64,
    y0: f64,
    inv_x: f64,
    inv_y: f64,
    nx: usize,
    ny: usize,
    starts: Vec<u32>,
    items: Vec<u32>,
    unbounded: Vec<u32>,
}

impl Grid {
    /// Broad phase: about as many cells as √M on a side, up to twice that, and no
    /// smaller than the mean box, so that a polygon sits in a few cells.
    fn new(prepared: &[Prepared]) -> Grid {
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

    /// The polygons whose grown boxes meet `b`, each once, appended to `out`.
    fn candidates(&self, b: &Aabb, prepared: &[Prepared], out: &mut Vec<u32>) {
        let (cx0, cx1, cy0, cy1) = self.range(b);
        for cy in cy0..=cy1 {
            for cx in cx0..=cx1 {
                let c = cy * self.nx + cx;
                let (s, e) = (self.starts[c] as usize, self.starts[c + 1] as usize);
                for &j in &self.items[s..e] {
                    let q = &prepared[j as usize].bx;
                    // the cell where both ranges start: the pair is looked at there only
                    let (qx, _, qy, _) = self.range(q);
                    if cx == cx0.max(qx) && cy == cy0.max(qy) && b.meets(q) {
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
    use crate::vect2::Vect2;

    fn square(x: f64, y: f64, vel: Vect2) -> MovingPolygon {
        let v = vec![
            Vect2::new(x, y),
            Vect2::new(x + 1.0, y),
            Vect2::new(x + 1.0, y + 1.0),
            Vect2::new(x, y + 1.0),
        ];
        MovingPolygon::new(v, Some(vec![vel; 4])).unwrap()
    }

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
    /// whose boxes straddle cells, and nothing twice.
    #[test]
    fn grid_finds_the_pairs_every_pair_test_finds() {
        let params = Params::new(0.01).unwrap();
        let polys: Vec<_> = (0..40)
            .map(|k| square(3.0 * (k % 8) as f64, 3.0 * (k / 8) as f64, Vect2::ZERO))
            .collect();
        let prepared: Vec<_> = polys
            .iter()
            .map(|q| Prepared::new(1.0, q, &params, 0.0))
            .collect();
        let g = Grid::new(&prepared);
        assert!(g.nx > 1 && g.ny > 1);
        for k in 0..200 {
            let s = Vect2::new(-2.0 + 0.13 * k as f64, -1.0 + 0.07 * k as f64);
            let p = MovingPoint::new_2d(s, Vect2::new(2.0, 1.0)).unwrap();
            let b = point_box(1.0, &p);
            let mut got = Vec::new();
            g.candidates(&b, &prepared, &mut got);
            got.sort_unstable();
            let want: Vec<u32> = (0..40)
                .filter(|&j| b.meets(&prepared[j as usize].bx))
                .collect();
            assert_eq!(got, want, "point {k}");
        }
    }

    #[test]
    fn mixed_dimensions_and_bad_lookahead_are_errors() {
        let params = Params::new(0.01).unwrap();
        let q2 = square(0.0, 0.0, Vect2::ZERO);
        let q3 = q2.clone().with_slab(0.0, 1.0, 0.0).unwrap();
        let p2 = MovingPoint::new_2d(Vect2::ZERO, Vect2::ZERO).unwrap();
        let p3 = MovingPoint::new_3d([0.0; 3], [0.0; 3]).unwrap();
        let e = detect_batch(1.0, &[p3], std::slice::from_ref(&q2), &params).unwrap_err();
        assert_eq!(e.field(), "polygon.bottom");
        let e = detect_batch(1.0, &[p2], std::slice::from_ref(&q3), &params).unwrap_err();
        assert_eq!(e.field(), "point.pos");
        let e = detect_batch(1.0, &[p2, p3], std::slice::from_ref(&q2), &params).unwrap_err();
        assert_eq!(e.field(), "point.pos");
        assert_eq!(
            detect_batch(0.0, &[p2], std::slice::from_ref(&q2), &params)
                .unwrap_err()
                .field(),
            "lookahead"
        );
        assert_eq!(
            detect_batch(f64::NAN, &[p2], &[q2], &params)
                .unwrap_err()
                .field(),
            "lookahead"
        );
        assert_eq!(detect_batch(1.0, &[p3], &[q3], &params).unwrap().len(), 1);
    }
}
