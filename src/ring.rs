//! Is a polygon's ring simple, and which way does it run? Paper A §II takes P as a
//! simple polygon listed counterclockwise (its containment test §II.B–E counts ray
//! crossings, which mean nothing on a ring that crosses itself). These are the checks a
//! case's vertices pass before any paper function sees them; every sign is exact.
//!
//! Rounding: each orientation is first taken in floats with Shewchuk's static bound for
//! orient2d, |det − fl(det)| ≤ (3 + 16u)·u·(|l| + |r|) where l and r are the two rounded
//! products (u = 2⁻⁵³), used only where no product underflows; when the float value is
//! within that bound of zero (or tiny) the sign comes from an exact expansion (`crate::ball::exact`). The exact step declines (`None`)
//! only when a product over- or underflows; such a ring is then reported as not
//! checkable rather than guessed.

use crate::ball::exact;
use crate::vect2::Vect2;

/// Shewchuk's ccwerrboundA, (3 + 16u)·u, u = 2⁻⁵³.
const ORIENT_BOUND: f64 = (3.0 + 16.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);

/// The float filter is used only when |l| + |r| ≥ 10⁻²⁸⁸ (> 2⁻⁹⁶⁰): then any product
/// below the normal range adds at most 2⁻¹⁰⁷⁵ of absolute error, far inside the bound's
/// slack (ORIENT_BOUND·10⁻²⁸⁸ ≈ 2⁻¹⁰⁰⁸), and the others round relatively as the bound
/// assumes.
const MIN_RELATIVE: f64 = 1e-288;

/// The exact sign of (b − a) × (c − a): +1 when a, b, c turn left (counterclockwise),
/// −1 right, 0 collinear; `None` when an exact product would over- or underflow.
pub fn orient(a: Vect2, b: Vect2, c: Vect2) -> Option<i8> {
    let l = (b.x - a.x) * (c.y - a.y);
    let r = (b.y - a.y) * (c.x - a.x);
    let det = l - r;
    let size = l.abs() + r.abs();
    let bound = ORIENT_BOUND * size;
    // The bound holds for roundings relative to their results: not when a product falls
    // below the normal range, where its absolute error (up to 2⁻¹⁰⁷⁵) can exceed it. Such
    // sizes go to the exact step (found by tests/paper_a_ring_vs_oracle.rs).
    if size >= MIN_RELATIVE && det.is_finite() && bound.is_finite() && det.abs() > bound {
        return Some(if det > 0.0 { 1 } else { -1 });
    }
    exact::sign_cross(&[b.x, -a.x], &[b.y, -a.y], &[c.x, -a.x], &[c.y, -a.y])
}

/// The exact sign of (b − a)·(c − a); `None` as in [`orient`].
fn dot_sign(a: Vect2, b: Vect2, c: Vect2) -> Option<i8> {
    // (b − a)·(c − a) = (b − a) × ((c − a) turned left): x·x' + y·y' = x·y'' − y·x''
    // with (x'', y'') = (−(c − a)_y, (c − a)_x).
    exact::sign_cross(&[b.x, -a.x], &[b.y, -a.y], &[a.y, -c.y], &[c.x, -a.x])
}

/// Why a ring is not a simple polygon (vertex indices as given, from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingFault {
    /// Edges a0→a1 and b0→b1 share a point although they are not neighbours (or, when
    /// neighbours, overlap beyond their common vertex: a spike).
    Crossing {
        /// One edge, as (first vertex, second vertex).
        a: (usize, usize),
        /// The edge it meets.
        b: (usize, usize),
    },
    /// All vertices on one line, or on one point: the ring encloses nothing.
    ZeroArea,
    /// A coordinate so large or small that an exact product over- or underflows.
    NotCheckable,
}

/// Which way a ring runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Winding {
    /// Counterclockwise: the interior on the left, paper A's order.
    Counterclockwise,
    /// Clockwise.
    Clockwise,
}

/// Closed segments pq and rs share a point (exact); `None` as in [`orient`].
pub fn segments_meet(p: Vect2, q: Vect2, r: Vect2, s: Vect2) -> Option<bool> {
    // Bounding boxes first: disjoint boxes cannot meet (comparisons of inputs, exact).
    if p.x.max(q.x) < r.x.min(s.x)
        || r.x.max(s.x) < p.x.min(q.x)
        || p.y.max(q.y) < r.y.min(s.y)
        || r.y.max(s.y) < p.y.min(q.y)
    {
        return Some(false);
    }
    let (o1, o2) = (orient(p, q, r)?, orient(p, q, s)?);
    let (o3, o4) = (orient(r, s, p)?, orient(r, s, q)?);
    if o1 == 0 && o2 == 0 {
        // Collinear: the boxes overlap, so the segments do (on one line).
        return Some(true);
    }
    Some(o1 * o2 <= 0 && o3 * o4 <= 0)
}

/// Paper A §II's polygon: the first pair of edges that make the ring not simple, or
/// `Ok(())`. Repeated consecutive vertices are one vertex here (a zero-length edge
/// crosses nothing). Rings of 48 edges or more are swept (O(n log n + k), `swept`);
/// smaller ones compare every pair, each pruned by its bounding boxes.
pub fn check_simple(p: &[Vect2]) -> Result<(), RingFault> {
    check_simple_with(p, true)
}

/// [`check_simple`] comparing every pair of edges, whatever the ring's size: the
/// reference the sweep is tested against.
pub fn check_simple_pairwise(p: &[Vect2]) -> Result<(), RingFault> {
    check_simple_with(p, false)
}

fn check_simple_with(p: &[Vect2], sweep: bool) -> Result<(), RingFault> {
    // The ring without repeats: indices into p of each distinct consecutive vertex.
    let mut idx: Vec<usize> = Vec::with_capacity(p.len());
    for (i, &v) in p.iter().enumerate() {
        if idx.last().map(|&j| p[j]) != Some(v) {
            idx.push(i);
        }
    }
    while idx.len() > 1 && p[idx[0]] == p[idx[idx.len() - 1]] {
        idx.pop();
    }
    let n = idx.len();
    if n < 3 {
        return Err(RingFault::ZeroArea);
    }
    let vtx = |k: usize| p[idx[k % n]];
    // the edge k of the reduced ring, named by the given indices of its ends
    let name = |k: usize| (idx[k % n], idx[(k + 1) % n]);
    if sweep && n >= SWEEP_MIN_EDGES && p.iter().all(|v| v.x.is_finite() && v.y.is_finite()) {
        return swept(n, &vtx, &name);
    }
    for i in 0..n {
        // neighbours share one vertex: they overlap only by folding back on a line
        let (a, b, c) = (vtx(i), vtx(i + 1), vtx(i + 2));
        if orient(a, b, c).ok_or(RingFault::NotCheckable)? == 0
            && dot_sign(b, a, c).ok_or(RingFault::NotCheckable)? > 0
        {
            return Err(RingFault::Crossing {
                a: name(i),
                b: name(i + 1),
            });
        }
        for k in (i + 2)..n {
            if i == 0 && k == n - 1 {
                continue; // the last edge and the first are neighbours
            }
            if segments_meet(vtx(i), vtx(i + 1), vtx(k), vtx(k + 1))
                .ok_or(RingFault::NotCheckable)?
            {
                return Err(RingFault::Crossing {
                    a: name(i),
                    b: name(k),
                });
            }
        }
    }
    Ok(())
}

/// Below this many edges [`check_simple`] compares every pair.
const SWEEP_MIN_EDGES: usize = 48;

/// [`check_simple`] on the `n` edges of the reduced ring by a sweep ([`crate::sweep`]):
/// only edges whose closed boxes meet can meet, and [`segments_meet`] answers `Some(false)`
/// for every other pair without computing anything, so the pairs the sweep finds hold
/// every outcome the pairwise loop can meet. The answer is the first of them in the
/// loop's order (edge `i`'s fold-back test, then its pairs `(i, k)` by `k`): the same
/// fault, or the same `NotCheckable`.
fn swept(
    n: usize,
    vtx: &dyn Fn(usize) -> Vect2,
    name: &dyn Fn(usize) -> (usize, usize),
) -> Result<(), RingFault> {
    use crate::sweep::{along_x, near_pairs, Item};
    // (i, k, fault) with k = i + 1 for a fold-back; the least (i, k) is the loop's first
    let mut first: Option<(usize, usize, RingFault)> = None;
    let mut see = |i: usize, k: usize, f: RingFault| {
        if first.as_ref().map_or(true, |(a, b, _)| (i, k) < (*a, *b)) {
            first = Some((i, k, f));
        }
    };
    for i in 0..n {
        let (a, b, c) = (vtx(i), vtx(i + 1), vtx(i + 2));
        let fold = match (orient(a, b, c), dot_sign(b, a, c)) {
            (None, _) => Some(RingFault::NotCheckable),
            (Some(0), None) => Some(RingFault::NotCheckable),
            (Some(0), Some(d)) if d > 0 => Some(RingFault::Crossing {
                a: name(i),
                b: name(i + 1),
            }),
            _ => None,
        };
        if let Some(f) = fold {
            see(i, i + 1, f);
        }
    }
    let x = along_x((0..n).map(vtx));
    let items: Vec<Item> = (0..n).map(|i| Item::of(vtx(i), vtx(i + 1), i, x)).collect();
    near_pairs(items, 0.0, |i, k| {
        if k < i + 2 || (i == 0 && k == n - 1) {
            return;
        }
        match segments_meet(vtx(i), vtx(i + 1), vtx(k), vtx(k + 1)) {
            None => see(i, k, RingFault::NotCheckable),
            Some(true) => see(
                i,
                k,
                RingFault::Crossing {
                    a: name(i),
                    b: name(k),
                },
            ),
            Some(false) => {}
        }
    });
    match first {
        Some((_, _, f)) => Err(f),
        None => Ok(()),
    }
}

/// The winding of a simple ring ([`check_simple`] passed): the turn at its
/// lexicographically least vertex, a vertex of the convex hull, where a simple ring
/// turns the way it runs. `Err(ZeroArea)` when that turn is straight (the ring is then
/// degenerate).
pub fn winding(p: &[Vect2]) -> Result<Winding, RingFault> {
    let n = p.len();
    let Some(m) = (0..n).min_by(|&i, &j| {
        p[i].x
            .total_cmp(&p[j].x)
            .then_with(|| p[i].y.total_cmp(&p[j].y))
    }) else {
        return Err(RingFault::ZeroArea);
    };
    // the nearest distinct neighbours on each side
    let prev = (1..n)
        .map(|k| p[(m + n - k) % n])
        .find(|&q| q != p[m])
        .ok_or(RingFault::ZeroArea)?;
    let next = (1..n)
        .map(|k| p[(m + k) % n])
        .find(|&q| q != p[m])
        .ok_or(RingFault::ZeroArea)?;
    match orient(prev, p[m], next).ok_or(RingFault::NotCheckable)? {
        1 => Ok(Winding::Counterclockwise),
        -1 => Ok(Winding::Clockwise),
        _ => Err(RingFault::ZeroArea),
    }
}

/// Do all vertices lie on one line (exact; `false` when that cannot be decided)? A
/// ring that does encloses nothing: callers report it as such rather than as the
/// folding edges [`check_simple`] finds first.
pub fn collinear(p: &[Vect2]) -> bool {
    let Some(&a) = p.first() else { return true };
    let Some(&b) = p.iter().find(|&&q| q != a) else {
        return true;
    };
    p.iter().all(|&c| orient(a, b, c) == Some(0))
}

/// x·2^k, exactly when the result is a normal float (steps of at most 2⁵⁰⁰, each a
/// power of two: exact unless it under- or overflows).
fn times_pow2(mut x: f64, mut k: i32) -> f64 {
    while k != 0 {
        let step = k.clamp(-500, 500);
        x *= 2f64.powi(step);
        k -= step;
    }
    x
}

/// The exponents that bring the largest |x| and the largest |y| of a ring near 2⁵⁰⁰.
fn axis_scales(p: &[Vect2]) -> (i32, i32) {
    let e = |m: f64| if m > 0.0 { m.log2().floor() as i32 } else { 0 };
    let mx = p.iter().fold(0f64, |m, v| m.max(v.x.abs()));
    let my = p.iter().fold(0f64, |m, v| m.max(v.y.abs()));
    (500 - e(mx), 500 - e(my))
}

/// Paper A §II's polygon: [`check_simple`], then [`winding`]. A ring whose exact
/// products would under- or overflow is checked again with x and y each scaled by a
/// power of two (largest coordinate near 2⁵⁰⁰): a positive diagonal map, which keeps
/// every orientation, every crossing and the direction of collinear edges, and is exact
/// (checked: every coordinate scales back to itself). Only a ring whose coordinates
/// differ too much within one axis (about 10⁻¹⁵⁰ and 10¹⁵⁰ of each other) stays
/// `NotCheckable`.
pub fn check(p: &[Vect2]) -> Result<Winding, RingFault> {
    match check_simple(p).and_then(|()| winding(p)) {
        Err(RingFault::NotCheckable) => {
            let (kx, ky) = axis_scales(p);
            let scaled: Vec<Vect2> = p
                .iter()
                .map(|v| Vect2::new(times_pow2(v.x, kx), times_pow2(v.y, ky)))
                .collect();
            let exact = p.iter().zip(&scaled).all(|(v, w)| {
                times_pow2(w.x, -kx) == v.x && times_pow2(w.y, -ky) == v.y && w.x.is_finite()
            });
            if !exact {
                return Err(RingFault::NotCheckable);
            }
            check_simple(&scaled).and_then(|()| winding(&scaled))
        }
        r => r,
    }
}

/// Paper A §II's polygon as a case must give it: simple and counterclockwise (a ring
/// too extreme to check exactly counts as not).
pub fn simple_ccw(p: &[Vect2]) -> bool {
    check(p) == Ok(Winding::Counterclockwise)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(xy: &[(f64, f64)]) -> Vec<Vect2> {
        xy.iter().map(|&(x, y)| Vect2::new(x, y)).collect()
    }

    #[test]
    fn powers_of_two_scale_exactly() {
        assert_eq!(times_pow2(1.5, 1100), 1.5 * 2f64.powi(550) * 2f64.powi(550));
        assert_eq!(times_pow2(times_pow2(5e-324, 1500), -1500), 5e-324);
        assert_eq!(axis_scales(&ring(&[(1.0, 4.0), (-2.0, 0.0)])), (499, 498));
    }

    /// A ring of subnormal size is checked exactly after scaling, not left unchecked.
    #[test]
    fn a_tiny_bow_tie_is_still_found() {
        let t = 1e-310;
        let bow = ring(&[
            (0.0, 0.0),
            (4.0 * t, 4.0 * t),
            (4.0 * t, 0.0),
            (0.0, 4.0 * t),
        ]);
        assert_eq!(check_simple(&bow), Err(RingFault::NotCheckable));
        assert!(matches!(check(&bow), Err(RingFault::Crossing { .. })));
        let sq = ring(&[
            (0.0, 0.0),
            (4.0 * t, 0.0),
            (4.0 * t, 4.0 * t),
            (0.0, 4.0 * t),
        ]);
        assert_eq!(check(&sq), Ok(Winding::Counterclockwise));
    }

    #[test]
    fn square_is_simple_both_ways() {
        let ccw = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]);
        assert_eq!(check_simple(&ccw), Ok(()));
        assert_eq!(winding(&ccw), Ok(Winding::Counterclockwise));
        let cw: Vec<Vect2> = ccw.iter().rev().copied().collect();
        assert_eq!(check_simple(&cw), Ok(()));
        assert_eq!(winding(&cw), Ok(Winding::Clockwise));
    }

    #[test]
    fn bow_tie_names_its_crossing_edges() {
        let bow = ring(&[(0.0, 0.0), (4.0, 4.0), (4.0, 0.0), (0.0, 4.0)]);
        assert_eq!(
            check_simple(&bow),
            Err(RingFault::Crossing {
                a: (0, 1),
                b: (2, 3)
            })
        );
    }

    #[test]
    fn touching_vertex_spike_and_line_are_faults() {
        // vertex 3 lies on edge 0–1
        let touch = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 0.0), (0.0, 4.0)]);
        assert!(matches!(
            check_simple(&touch),
            Err(RingFault::Crossing { .. })
        ));
        // a spike: 1 → 2 goes out and 2 → 3 comes back along the same line
        let spike = ring(&[(0.0, 0.0), (4.0, 0.0), (6.0, 0.0), (5.0, 0.0), (4.0, 4.0)]);
        assert!(matches!(
            check_simple(&spike),
            Err(RingFault::Crossing { .. })
        ));
        let line = ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]);
        assert!(check_simple(&line).is_err());
    }

    #[test]
    fn repeated_vertices_are_one_vertex() {
        let rep = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 0.0)]);
        assert_eq!(check_simple(&rep), Ok(()));
        assert_eq!(winding(&rep), Ok(Winding::Counterclockwise));
    }

    /// A crossing by one ulp: the float orientation alone cannot see it.
    #[test]
    fn a_crossing_an_ulp_deep_is_found() {
        let e = f64::EPSILON;
        // vertex 3 at (2, 1ulp below 0): edge 2–3 and edge 3–4 dip through edge 0–1
        let dip = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, -e), (0.0, 4.0)]);
        assert!(matches!(
            check_simple(&dip),
            Err(RingFault::Crossing { .. })
        ));
        let clear = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, e), (0.0, 4.0)]);
        assert_eq!(check_simple(&clear), Ok(()));
    }
}
