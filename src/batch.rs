//! Batch detection: N moving points against M moving polygons in one call (extends paper
//! A §II.H, §II.I and §III from one pair to many).
//!
//! Three phases:
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
//! 2. **Mid phase** (not in the paper): a pair is dropped when the polygon's grown box lies
//!    certainly on one side of the point's path line (the line through s along v), all
//!    four corners' sides decided with a stated rounding bound: the point is on that line
//!    at every t, so it never comes within the reach of the polygon, and paper A
//!    certainly answers "no" (the private `mid` module says why step by step).
//! 3. **Narrow phase**: the certified paper functions on the slices, as
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
use crate::ball::Tri;
use crate::detect::Method;
use crate::error::CaseError;

mod broad;
mod mid;

use broad::{point_box, Aabb, Grid, Index, Prepared};
use mid::{Columns, PathSide};

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
    /// Pairs the broad phase kept.
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
    detect_batch_counted(lookahead, points, polygons, params, options).map(|(b, _)| b)
}

/// [`detect_batch_with`], and how many of the pairs the broad phase kept its mid phase
/// left to a paper function (the others lie wholly on one side of the point's path
/// line: paper A certainly says no), for reports.
pub fn detect_batch_counted(
    lookahead: f64,
    points: &[MovingPoint],
    polygons: &[MovingPolygon],
    params: &Params,
    options: &Options,
) -> Result<(Batch, u64), CaseError> {
    detect_batch_mid_offset(lookahead, points, polygons, params, options, 0.0)
}

/// [`detect_batch_counted`] with `mid_offset` added to every polygon's reach in the mid
/// phase only (the broad phase keeps [`Options::reach_offset`]'s boxes). 0 in any real
/// use: a negative value makes the mid phase unsound, on purpose, for the tests that
/// must see it drop pairs (its canary).
#[doc(hidden)]
pub fn detect_batch_mid_offset(
    lookahead: f64,
    points: &[MovingPoint],
    polygons: &[MovingPolygon],
    params: &Params,
    options: &Options,
    mid_offset: f64,
) -> Result<(Batch, u64), CaseError> {
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
        return Ok((
            Batch {
                hits: Vec::new(),
                candidates: 0,
                unbounded_polygons: 0,
            },
            0,
        ));
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
        .map(|q| Prepared::new(t, q, params, options.reach_offset, mid_offset))
        .collect();
    let point_boxes: Vec<Aabb> = points.iter().map(|p| point_box(t, p)).collect();
    let columns = Columns::new(&prepared);
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
        columns: &columns,
    };
    let chunks = chunk_results(&ctx, options.parallel);
    let mut hits = Vec::with_capacity(chunks.iter().map(|c| c.hits.len()).sum());
    let (mut candidates, mut decided) = (0, 0);
    for c in chunks {
        hits.extend_from_slice(&c.hits);
        candidates += c.candidates;
        decided += c.decided;
    }
    Ok((
        Batch {
            hits,
            candidates,
            unbounded_polygons: prepared.iter().filter(|p| p.unbounded).count(),
        },
        decided,
    ))
}

/// Points per chunk of work at most: large enough that a chunk's buffers and rayon's
/// hand-off cost little per point.
const CHUNK: usize = 256;

/// Points per chunk of work at least (see [`chunk_len`]).
#[cfg(feature = "parallel")]
const MIN_CHUNK: usize = 16;

/// Points per chunk for `n` points on `threads` threads: [`CHUNK`], or fewer so that
/// each thread gets about eight chunks (a thread that draws slow points is not left
/// alone at the end: 1000 points on two threads make 16 chunks, not 4), but no fewer
/// than [`MIN_CHUNK`].
#[cfg(feature = "parallel")]
fn chunk_len(n: usize, threads: usize) -> usize {
    (n / (8 * threads.max(1))).clamp(MIN_CHUNK, CHUNK)
}

/// One chunk's answer.
struct ChunkResult {
    hits: Vec<Hit>,
    candidates: u64,
    decided: u64,
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
    columns: &'a Columns,
}

/// The chunks' answers, in order: across rayon's threads with `parallel`, else here.
#[cfg(feature = "parallel")]
fn chunk_results(ctx: &Ctx<'_>, parallel: bool) -> Vec<ChunkResult> {
    use rayon::prelude::*;
    let n = ctx.points.len();
    if parallel {
        let len = chunk_len(n, rayon::current_num_threads());
        let starts: Vec<usize> = (0..n).step_by(len).collect();
        starts
            .par_iter()
            .map_init(Vec::new, |scratch, &s| {
                run_chunk(ctx, s, (s + len).min(n), scratch)
            })
            .collect()
    } else {
        let mut scratch = Vec::new();
        (0..n)
            .step_by(CHUNK)
            .map(|s| run_chunk(ctx, s, (s + CHUNK).min(n), &mut scratch))
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

/// Points `start..end`: each one's candidates (into `scratch`, reused), sorted, those the
/// mid phase keeps answered by the paper function for the pair (paper A §II.F's dispatch).
fn run_chunk(ctx: &Ctx<'_>, start: usize, end: usize, scratch: &mut Vec<u32>) -> ChunkResult {
    let mut out = ChunkResult {
        hits: Vec::new(),
        candidates: 0,
        decided: 0,
    };
    for i in start..end {
        scratch.clear();
        let b = &ctx.point_boxes[i];
        let p = &ctx.points[i];
        let line = PathSide::new(p);
        let prepared = ctx.prepared;
        match ctx.index {
            Index::Grid(g) if g.spans_most(b, prepared.len()) => {
                out.candidates += ctx.columns.scan(b, &line, scratch);
            }
            Index::Grid(g) => {
                g.candidates(b, prepared, scratch);
                scratch.sort_unstable();
                out.candidates += scratch.len() as u64;
                scratch.retain(|&j| !line.apart(&prepared[j as usize]));
            }
            Index::All => {
                scratch.extend(
                    (0..prepared.len() as u32).filter(|&j| b.meets(&prepared[j as usize].bx)),
                );
                out.candidates += scratch.len() as u64;
                scratch.retain(|&j| !line.apart(&prepared[j as usize]));
            }
        }
        out.decided += scratch.len() as u64;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vect2::Vect2;

    /// The unit square with its lower-left corner at (x, y), translating at `vel` (also
    /// the broad phase's tests' polygon).
    pub(super) fn square(x: f64, y: f64, vel: Vect2) -> MovingPolygon {
        let v = vec![
            Vect2::new(x, y),
            Vect2::new(x + 1.0, y),
            Vect2::new(x + 1.0, y + 1.0),
            Vect2::new(x, y + 1.0),
        ];
        MovingPolygon::new(v, Some(vec![vel; 4])).unwrap()
    }

    /// Chunks: about eight per thread, between MIN_CHUNK and CHUNK points.
    #[cfg(feature = "parallel")]
    #[test]
    fn chunks_give_every_thread_several() {
        assert_eq!(chunk_len(1000, 2), 62);
        assert_eq!(chunk_len(100_000, 2), CHUNK);
        assert_eq!(chunk_len(100, 8), MIN_CHUNK);
        assert_eq!(chunk_len(0, 0), MIN_CHUNK);
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
