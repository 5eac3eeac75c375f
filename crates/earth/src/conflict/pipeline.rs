//! Paper B Algorithm 1: the four stages composed (candidates → regions → windows →
//! intervals), timed, and the legs' answers merged per feature pair.

use super::{stage1, stage2, stage3, stage4, Object};
use crate::sphere::Merc;
use rayon::prelude::*;
use std::time::Instant;

/// Options of the pipeline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Stage 4 time tolerance (h).
    pub tolerance_h: f64,
    /// Compute what is only reported: the regions (`Conflict::rings`, empty without) and
    /// the paper's stage 3 windows.
    pub details: bool,
    /// Objects per block of [`run_blocks`] at most (a block ends with a feature).
    pub block_objects: usize,
    /// Candidate pairs per block of [`run_blocks`], about ([`BLOCK_PAIRS`]).
    pub block_pairs: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tolerance_h: super::DEFAULT_TIME_TOLERANCE_H,
            details: true,
            block_objects: BLOCK_OBJECTS,
            block_pairs: BLOCK_PAIRS,
        }
    }
}

/// Per-stage counts and timings (Paper B Section VI.D's measurements).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stats {
    /// Objects fed to stage 1 (one per static area, one per track leg).
    pub objects: usize,
    /// Stage 1 output: object pairs with meeting AABBs and overlapping lives.
    pub candidate_pairs: usize,
    /// Stage 2 output: pairs whose regions meet.
    pub region_pairs: usize,
    /// Stage 3 output: pairs with a non-empty conservative window.
    pub window_pairs: usize,
    /// Stage 4 output: object pairs in conflict.
    pub interval_pairs: usize,
    /// Of those, decided by the exact linear solution (eq 20).
    pub linear_pairs: usize,
    /// Of those, decided by certified advancement.
    pub advancement_pairs: usize,
    /// Stage timings (ms).
    pub stage1_ms: f64,
    /// See `stage1_ms`.
    pub stage2_ms: f64,
    /// See `stage1_ms`.
    pub stage3_ms: f64,
    /// See `stage1_ms`.
    pub stage4_ms: f64,
}

/// One conflict between two features (owners), `a < b` in file order.
#[derive(Clone, Debug, PartialEq)]
pub struct Conflict {
    /// Feature index of the first object.
    pub a: u32,
    /// Feature index of the second object.
    pub b: u32,
    /// First conflict time (h); `-∞` for two areas without a start.
    pub t_start: f64,
    /// Last conflict time (h); `+∞` for two areas without an end.
    pub t_end: f64,
    /// How the interval was decided (the weakest method among merged legs).
    pub method: stage4::Method,
    /// Stage 2 regions of the merged object pairs.
    pub rings: Vec<Vec<Merc>>,
    /// The paper's stage 3 windows of the first merged pair (`a`'s, `b`'s).
    pub paper: [Option<(f64, f64)>; 2],
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Objects per block of [`run_blocks`] at most (whole features: a block ends at a
/// feature's last object).
pub const BLOCK_OBJECTS: usize = 8192;

/// Candidate pairs per block of [`run_blocks`], about: a block ends (with a feature) once
/// its objects' pairs reach this many. Each pair costs a few hundred bytes through stages
/// 2–4, so a block stays within some 100 MB however dense the scenario.
pub const BLOCK_PAIRS: usize = 250_000;

/// Objects whose partners [`run_blocks`] asks the R-tree for at once while it fills a
/// block, at most: a block's pairs pass [`BLOCK_PAIRS`] by at most one chunk's, and the
/// chunks shrink as the block fills (by the pairs per object seen so far).
const BLOCK_CHUNK: usize = 512;
/// The first chunk of a block.
const BLOCK_FIRST_CHUNK: usize = 64;

/// Paper B Algorithm 1 over `objects`: the conflicts in one vector, ordered by feature
/// pair ([`run_blocks`] collected).
pub fn run(objects: &[Object], opts: Options) -> (Vec<Conflict>, Stats) {
    let mut all = Vec::new();
    let stats = run_blocks(objects, opts, &mut |c| all.extend(c));
    (all, stats)
}

/// Paper B Algorithm 1 over `objects`, a block of whole features at a time: stage 1 finds
/// the pairs whose first object lies in the block ([`stage1::Index`]), stages 2–4 and the
/// merge per feature pair follow, and `sink` gets the block's conflicts, ordered by
/// feature pair. Memory holds one block's pairs and conflicts, whatever their total
/// (any density, in bounded memory). The objects of a feature must be
/// consecutive and in feature order, as [`crate::scenario::objects`] makes them (a
/// feature pair's object pairs then all start in the block of its first feature);
/// otherwise the whole is one block.
pub fn run_blocks(objects: &[Object], opts: Options, sink: &mut dyn FnMut(Vec<Conflict>)) -> Stats {
    let mut stats = Stats {
        objects: objects.len(),
        ..Stats::default()
    };
    let t = Instant::now();
    let index = stage1::Index::new(objects);
    stats.stage1_ms += ms(t);
    let grouped = objects.windows(2).all(|w| w[0].owner <= w[1].owner);
    let earth = objects.iter().any(|o| o.earth);
    let n = objects.len();
    let mut start = 0;
    while start < n {
        // stage 1 for the block: its objects' partners, a chunk of objects at a time,
        // until the block holds block_pairs pairs or block_objects objects; then on to
        // the end of the last feature (each object is asked once: counting the pairs
        // first asked the R-tree twice, half of stage 1's time on 10⁶ objects)
        let t = Instant::now();
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        let mut end = start;
        if grouped {
            let limit = start.saturating_add(opts.block_objects.max(1)).min(n);
            while end < limit && pairs.len() < opts.block_pairs {
                // a small first chunk, then as many objects as the pairs per object seen
                // so far leave room for (a dense scenario has hundreds per object)
                let chunk = match pairs.len().checked_div(end - start) {
                    None => BLOCK_FIRST_CHUNK,
                    Some(0) => BLOCK_CHUNK,
                    Some(per) => ((opts.block_pairs - pairs.len()) / per).clamp(1, BLOCK_CHUNK),
                };
                let next = end.saturating_add(chunk).min(limit);
                pairs.extend(index.candidates(objects, end..next).pairs);
                end = next;
            }
            let mut feature_end = end;
            while feature_end < n && objects[feature_end].owner == objects[feature_end - 1].owner {
                feature_end += 1;
            }
            pairs.extend(index.candidates(objects, end..feature_end).pairs);
            end = feature_end;
        } else {
            pairs = index.candidates(objects, 0..n).pairs;
            end = n;
        }
        stats.stage1_ms += ms(t);
        let cands = stage1::Candidates { pairs };
        sink(block(objects, cands, opts, earth, &mut stats));
        start = end;
    }
    stats
}

/// Stages 2–4 and the merge for a block's candidate pairs (stage 1's).
fn block(
    objects: &[Object],
    cands: stage1::Candidates,
    opts: Options,
    earth: bool,
    stats: &mut Stats,
) -> Vec<Conflict> {
    stats.candidate_pairs += cands.pairs.len();

    let t = Instant::now();
    let regions = stage2::regions(objects, &cands, opts.details);
    drop(cands);
    stats.stage2_ms += ms(t);
    stats.region_pairs += regions.regions.len();

    let t = Instant::now();
    let windows = stage3::windows(objects, regions, opts.details);
    stats.stage3_ms += ms(t);
    stats.window_pairs += windows.windows.len();

    let t = Instant::now();
    let intervals = stage4::intervals(objects, windows, opts.tolerance_h);
    stats.stage4_ms += ms(t);
    stats.interval_pairs += intervals.intervals.len();
    for iv in &intervals.intervals {
        match iv.method {
            stage4::Method::Linear => stats.linear_pairs += 1,
            stage4::Method::Advancement => stats.advancement_pairs += 1,
            stage4::Method::AreaOverlap => {}
        }
    }
    // without details (--no-regions) no region is printed: the answer's rings are
    // dropped rather than made exact and valid (a third of the blocks' time on a dense
    // 10⁶-object scenario)
    let mut intervals = intervals;
    if !opts.details {
        for iv in &mut intervals.intervals {
            iv.rings = Vec::new();
        }
    }
    // the answer's regions where an object is not convex: the clip stage 3 used when it
    // is shown to be the intersection's boundary, exact pieces otherwise
    // (stage2::answer_rings)
    intervals.intervals.par_iter_mut().for_each(|iv| {
        let (a, b) = (&objects[iv.pair.0 as usize], &objects[iv.pair.1 as usize]);
        if !iv.rings.is_empty() && a.is_convex() != b.is_convex() {
            iv.rings = stage2::answer_rings(a, b);
        }
    });
    let mut conflicts = merge(objects, intervals);
    // the reported regions valid: pieces united; on the Earth every region within
    // [−π, π] of longitude, cut at the antimeridian
    conflicts.par_iter_mut().for_each(|c| {
        if !c.rings.is_empty() {
            c.rings = super::geom::region(std::mem::take(&mut c.rings), earth);
        }
    });
    conflicts
}

/// Merges object-pair intervals into feature-pair conflicts (legs of multi-waypoint
/// tracks): the union's first and last times.
pub fn merge(objects: &[Object], intervals: stage4::Intervals) -> Vec<Conflict> {
    let mut out: Vec<Conflict> = Vec::with_capacity(intervals.intervals.len());
    let mut keyed: Vec<((u32, u32), stage4::Interval)> = intervals
        .intervals
        .into_iter()
        .map(|iv| {
            let (oa, ob) = (
                objects[iv.pair.0 as usize].owner,
                objects[iv.pair.1 as usize].owner,
            );
            if oa <= ob {
                ((oa, ob), iv)
            } else {
                let mut iv = iv;
                iv.paper.swap(0, 1);
                ((ob, oa), iv)
            }
        })
        .collect();
    keyed.sort_by(|x, y| {
        x.0.cmp(&y.0)
            .then(x.1.t_start.total_cmp(&y.1.t_start))
            .then(x.1.pair.cmp(&y.1.pair))
    });
    for ((a, b), iv) in keyed {
        match out.last_mut() {
            Some(c) if c.a == a && c.b == b => {
                c.t_start = c.t_start.min(iv.t_start);
                c.t_end = c.t_end.max(iv.t_end);
                c.rings.extend(iv.rings);
                if iv.method == stage4::Method::Advancement {
                    c.method = iv.method;
                }
            }
            _ => out.push(Conflict {
                a,
                b,
                t_start: iv.t_start,
                t_end: iv.t_end,
                method: iv.method,
                rings: iv.rings,
                paper: iv.paper,
            }),
        }
    }
    out
}
