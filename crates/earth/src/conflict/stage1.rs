//! Paper B Section IV-B, Algorithm 2: AABBs (eqs 3–6) in an R-tree.

use super::Object;
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::RTree;

/// Stage 1's output: pairs `(i, j)`, `i < j`, of object indices whose AABBs meet and
/// whose lives overlap.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Candidates {
    /// The pairs, in spatial order (by the AABB centre's x of the pair's first object in
    /// that order), so that later stages touch objects with good memory locality.
    pub pairs: Vec<(u32, u32)>,
}

impl Candidates {
    /// The pairs sorted by index (for comparisons).
    pub fn sorted(mut self) -> Candidates {
        self.pairs.sort_unstable();
        self
    }
}

type Entry = GeomWithData<Rectangle<[f64; 2]>, u32>;

/// The margin (radians of x) by which an object's copies on the Earth reach past the
/// strip [−π, π] ([`Object::on_earth`]) and by which [`wanted`] widens it: far above
/// the rounding of a copy's coordinates (a few units of 2⁻⁵¹, from adding 2π·k), far
/// below any geometry (10⁻⁹ rad is 6 mm on the Earth).
pub const WRAP_MARGIN: f64 = 1e-9;

/// Whether stage 1 keeps a pair whose boxes meet: different features, overlapping lives,
/// and on the Earth the one copy of the pair whose boxes' common x-range starts in the
/// strip [−π, π) (widened by [`WRAP_MARGIN`]). The copies of a pair moved together by a
/// whole turn have common ranges 2π apart, so the widened strip holds the start of at
/// least one (rounding moves them by far less than the margin) and of two only when it
/// falls within the margin of ±π; [`Object::on_earth`] made every copy whose range
/// reaches the strip, so the one kept exists.
pub fn wanted(a: &Object, b: &Object) -> bool {
    use std::f64::consts::PI;
    if a.owner == b.owner || a.t0.max(b.t0) > a.t1.min(b.t1) {
        return false;
    }
    if !(a.earth && b.earth) {
        return true;
    }
    let start = a.aabb[0].max(b.aabb[0]);
    (-PI - WRAP_MARGIN..PI + WRAP_MARGIN).contains(&start) || !start.is_finite()
}

/// Slabs per worker thread: a few more joins than threads balance the load.
const SLABS_PER_THREAD: usize = 2;
/// Below this many objects per slab one tree is cheaper than the extra joins.
const MIN_SLAB_OBJECTS: usize = 4096;

/// Paper B Algorithm 2: bulk-load every object's AABB (eqs 3–6) into R-trees, find every
/// pair of meeting AABBs, keep pairs whose time windows overlap (`max(t0) ≤ min(tf)`) and
/// that do not belong to the same feature (legs of one track), and on the Earth each pair
/// in one copy ([`wanted`]). The printed algorithm's
/// insert-then-query loop finds the same pairs (tested against brute force).
pub fn candidates(objects: &[Object]) -> Candidates {
    // Objects go to SLABS_PER_THREAD × threads slabs by the x of their AABB centre, each
    // slab in its own bulk-loaded R-tree. Every pair of slabs (and each slab with itself) is
    // joined by rstar's simultaneous descent of the two trees, the joins in parallel.
    // Cross-slab joins whose root boxes are disjoint end at once. Pairs come out in tree
    // order, i.e. spatially coherent: later stages then touch objects with good locality.
    let slabs = (rayon::current_num_threads() * SLABS_PER_THREAD)
        .min(objects.len() / MIN_SLAB_OBJECTS)
        .max(1);
    let mut order: Vec<u32> = (0..objects.len() as u32).collect();
    order.sort_unstable_by(|&a, &b| {
        let (ba, bb) = (objects[a as usize].aabb, objects[b as usize].aabb);
        (ba[0] + ba[2]).total_cmp(&(bb[0] + bb[2])).then(a.cmp(&b))
    });
    let per = order.len().div_ceil(slabs).max(1);
    let trees: Vec<RTree<Entry>> = order
        .par_chunks(per)
        .map(|chunk| {
            RTree::bulk_load(
                chunk
                    .iter()
                    .map(|&i| {
                        let b = objects[i as usize].aabb;
                        GeomWithData::new(Rectangle::from_corners([b[0], b[1]], [b[2], b[3]]), i)
                    })
                    .collect(),
            )
        })
        .collect();
    let jobs: Vec<(usize, usize)> = (0..trees.len())
        .flat_map(|s| (s..trees.len()).map(move |t| (s, t)))
        .collect();
    let pairs: Vec<(u32, u32)> = jobs
        .par_iter()
        .flat_map_iter(|&(s, t)| {
            let same = s == t;
            trees[s]
                .intersection_candidates_with_other_tree(&trees[t])
                .filter_map(move |(ea, eb)| {
                    let (i, j) = (ea.data, eb.data);
                    if same && i >= j {
                        return None;
                    }
                    wanted(&objects[i as usize], &objects[j as usize])
                        .then_some((i.min(j), i.max(j)))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    Candidates { pairs }
}

/// Stage 1 over a block of objects (any density, in bounded memory): one R-tree of
/// every object's AABB, asked for the partners of the objects of a block, so that the
/// pipeline holds the candidates of one block at a time.
pub struct Index {
    tree: RTree<Entry>,
}

impl Index {
    /// The R-tree of the objects' AABBs (eqs 3–6).
    pub fn new(objects: &[Object]) -> Index {
        Index {
            tree: RTree::bulk_load(
                objects
                    .iter()
                    .enumerate()
                    .map(|(i, o)| {
                        let b = o.aabb;
                        GeomWithData::new(
                            Rectangle::from_corners([b[0], b[1]], [b[2], b[3]]),
                            i as u32,
                        )
                    })
                    .collect(),
            ),
        }
    }

    /// Algorithm 2 for the objects `block`: the pairs (i, j), i in the block and j > i,
    /// whose AABBs meet (closed boxes) and which [`wanted`] keeps. Together over blocks
    /// that cover the objects, the pairs of [`candidates`] (in another order).
    pub fn candidates(&self, objects: &[Object], block: std::ops::Range<usize>) -> Candidates {
        let pairs = block
            .into_par_iter()
            .flat_map_iter(|i| {
                let b = objects[i].aabb;
                let env = rstar::AABB::from_corners([b[0], b[1]], [b[2], b[3]]);
                let i = i as u32;
                self.tree
                    .locate_in_envelope_intersecting(&env)
                    .filter_map(move |e| {
                        let j = e.data;
                        (j > i && wanted(&objects[i as usize], &objects[j as usize]))
                            .then_some((i, j))
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        Candidates { pairs }
    }
}

/// Paper B Algorithm 2 by brute force (all pairs), the reference for tests.
pub fn candidates_brute(objects: &[Object]) -> Candidates {
    let mut pairs = Vec::new();
    for i in 0..objects.len() {
        for j in i + 1..objects.len() {
            let (a, b) = (&objects[i], &objects[j]);
            let boxes = a.aabb[0] <= b.aabb[2]
                && b.aabb[0] <= a.aabb[2]
                && a.aabb[1] <= b.aabb[3]
                && b.aabb[1] <= a.aabb[3];
            if boxes && wanted(a, b) {
                pairs.push((i as u32, j as u32));
            }
        }
    }
    Candidates { pairs }
}
