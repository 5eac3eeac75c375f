//! Paper A §II.H: detection for statically shaped polygons, detect_same_2D (and its
//! run over a slab window's part of the motion, which §III asks for).

use super::statically_shaped;
use crate::ball::{Ball, BallV, Tri};
use crate::contain::{definitely_outside_rel, AtTime, Shifted};
use crate::lanes::{self, Kernel, KernelFn};
use crate::polygon::VertexSeq;
use crate::predicates::{self as pr, PathLine, Terms};
use crate::proximity::segments_close_ordered;
use crate::vect2::Vect2;

/// Paper A §II.H detect_same_2D: does s + t·v come within BUFF of the statically shaped
/// polygon P + t·V (all v_i equal) for some t ∈ [0, T]?
///
/// Step 1: s not definitely outside P → true. Step 2: s + T·v not definitely outside
/// P + T·V → true. Step 3: some edge with segments_close(s, s + T·(v − v_i), p_i, p_j,
/// BUFF) → true. Certified: `false` only when the exact answer is false.
///
/// ```
/// use polyguard::{detect_same_2d, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// let east = [Vect2::new(1.0, 0.0); 4]; // the cell drifts east, rigidly
/// // an aircraft 3 south of the cell's path, flying north: it enters at t = 3
/// let (s, north) = (Vect2::new(5.0, -3.0), Vect2::new(0.0, 1.0));
/// assert!(detect_same_2d(10.0, s, north, &square[..], &east[..], 0.01));
/// assert!(!detect_same_2d(2.5, s, north, &square[..], &east[..], 0.01)); // T too short
/// ```
#[inline]
pub fn detect_same_2d<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64) -> bool
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_same_2d_tri(t, s, v, p, vels, buff).or_true()
}

/// Paper A §II.H detect_same_2D, three-valued (see [`detect_same_2d`]).
#[inline]
pub fn detect_same_2d_tri<P, V>(t: f64, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    detect_same_2d_tri_shaped(t, s, v, p, vels, buff, statically_shaped(vels))
}

/// Paper A §II.H detect_same_2D, three-valued, with [`statically_shaped`]`(vels)` given
/// as `stat` by a caller that has it at hand (the dispatch of §II.F checks it first).
#[inline]
pub(crate) fn detect_same_2d_tri_shaped<P, V>(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    buff: f64,
    stat: bool,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    same_window(Ball::exact(0.0), Ball::exact(t), s, v, p, vels, buff, stat)
}

/// detect_same_2D over the time window [ta, tb] of the original motion, which is what
/// paper A §III runs: detect_same_2D(tb − ta, s + ta·v, v, P + ta·V, V, BUFF). The
/// window's ends are balls (a slab window's ends are quotients).
///
/// In the point's frame (origin s, each velocity relative to v): step 1 is
/// definitely_outside of (p_i − s) + ta·(v_i − v), step 2 the same at tb, and step 3
/// translates segments_close by s + ta·v_i: the relative path runs from ta·(v − v_i) to
/// tb·(v − v_i), the edge from p_i − s to p_j − s + ta·(v_j − v_i). `stat` is
/// [`statically_shaped`]`(vels)`, which the caller has at hand. Inlined, so that the
/// window's exact ends from 0 fold into its ball arithmetic at detect_same_2D's call.
#[inline(always)]
pub(super) fn same_window<P, V>(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    buff: f64,
    stat: bool,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    if n == 0 {
        return Tri::No;
    }
    // Steps 3, 2 and 1, in that order: the answer is their disjunction (`Yes` from any,
    // else `Unsure` from any, else `No`) whatever the order. Step 3's side filter is
    // cheaper than a containment test at T, a miss pays all three anyway, and a point
    // that crosses an edge (the common hit) is settled without either containment test
    // (measured against the order 2, 3, 1: docs/performance.md, "The certified engine
    // against the plain transcription").
    let acc = match edges_close(ta, tb, s, v, p, vels, buff, stat) {
        Tri::Yes => return Tri::Yes,
        other => other,
    };
    let acc = match end_inside(tb, s, v, p, vels, buff, stat) {
        Tri::Yes => return Tri::Yes,
        Tri::Unsure => Tri::Unsure,
        Tri::No => acc,
    };
    match end_inside(ta, s, v, p, vels, buff, stat) {
        Tri::Yes => Tri::Yes,
        Tri::Unsure => Tri::Unsure,
        Tri::No => acc,
    }
}

/// Paper A §II.H step 3 over the window [ta, tb] (see [`same_window`]): `Yes` at the
/// first edge whose segments_close certainly holds, else `Unsure` if some edge is
/// undecided, else `No`.
#[inline(always)]
fn edges_close<P, V>(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    p: &P,
    vels: &V,
    buff: f64,
    stat: bool,
) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let n = p.count();
    let v0 = vels.vertex(0);
    let mut acc = Tri::No;
    // Each vertex's side of the relative path's line of the common velocity v_0, computed
    // once and carried to the next edge: an edge with both ends certainly beyond BUFF on
    // one side is not close, the same certain test segments_close starts with.
    let (path0, sides) = PathSides::new(ta, tb, v, v0, buff);
    // From a window starting at 0 with every velocity v_0 and the vertices stored
    // contiguously, the sides are taken several vertices at a time ([`same_masked`]):
    // the same tests, hence the same edges tested in full, in the same order.
    if stat && sides.from_zero && n >= lanes::MIN_VERTICES {
        if let Some(verts) = p.as_slice().filter(|q| q.len() == n) {
            let masked = SameMasked {
                ta,
                tb,
                s,
                v,
                verts,
                vels,
                buff,
                path0,
                line: sides.line,
            };
            return lanes::with_kernel(masked);
        }
    }
    let side = |k: usize| sides.of(p.vertex(k), s);
    let mut side_i = side(0);
    for i in 0..n {
        let j = p.next(i);
        let (vi, vj) = (vels.vertex(i), vels.vertex(j));
        let side_j = side(j);
        let same_i = stat || pr::same_velocity(vi, v0);
        let skip = side_i != 0 && side_i == side_j && same_i && (stat || pr::same_velocity(vj, vi));
        side_i = side_j;
        if skip {
            continue;
        }
        let path = if same_i { Some(path0) } else { None };
        let (pi, pj) = (p.vertex(i), p.vertex(j));
        match edge_close(ta, tb, s, v, pi, pj, vi, vj, buff, stat, path) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

/// [`same_window`]'s step 3 for a statically shaped polygon from a window starting at 0,
/// on side masks ([`crate::lanes`]), for [`lanes::with_kernel`].
struct SameMasked<'a, V: ?Sized> {
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    verts: &'a [Vect2],
    vels: &'a V,
    buff: f64,
    path0: (BallV, BallV),
    line: PathLine,
}

impl<V: VertexSeq + ?Sized> KernelFn<Tri> for SameMasked<'_, V> {
    #[inline(always)]
    fn call<K: Kernel>(self, k: K) -> Tri {
        same_masked(self, k)
    }
}

/// Paper A §II.H step 3 on side masks: edge i is skipped when both its ends are
/// certainly beyond BUFF on the same side of the relative path's line ([`PathLine::side`]
/// +1 at both, or −1 at both), as [`same_window`]'s loop does; the edges left go through
/// [`edge_close`] in increasing order. Chunks of [`lanes::SIDE_CHUNK`] edges; the end of
/// a chunk's last edge (vertex 0 after the last chunk) is computed afresh.
#[inline(always)]
fn same_masked<V: VertexSeq + ?Sized, K: Kernel>(w: SameMasked<'_, V>, k: K) -> Tri {
    let n = w.verts.len();
    const C: usize = lanes::SIDE_CHUNK;
    let mut acc = Tri::No;
    let mut lo = 0;
    while lo < n {
        let hi = (lo + C).min(n);
        let len = hi - lo;
        let (pos, neg) = k.side_bits(&w.line, w.verts, w.s, lo, hi);
        let next = w.line.side(w.verts[if hi == n { 0 } else { hi }] - w.s);
        // Each edge's far end at its near end's bit.
        let pos_far = (pos >> 1) | (((next > 0) as u64) << (len - 1));
        let neg_far = (neg >> 1) | (((next < 0) as u64) << (len - 1));
        let skip = (pos & pos_far) | (neg & neg_far);
        let all = if len == 64 {
            u64::MAX
        } else {
            (1u64 << len) - 1
        };
        let mut live = !skip & all;
        while live != 0 {
            let i = lo + live.trailing_zeros() as usize;
            live &= live - 1;
            let j = if i + 1 == n { 0 } else { i + 1 };
            let (vi, vj) = (w.vels.vertex(i), w.vels.vertex(j));
            let (pi, pj) = (w.verts[i], w.verts[j]);
            let (ta, tb, path) = (w.ta, w.tb, Some(w.path0));
            match edge_close(ta, tb, w.s, w.v, pi, pj, vi, vj, w.buff, true, path) {
                Tri::Yes => return Tri::Yes,
                Tri::Unsure => acc = Tri::Unsure,
                Tri::No => {}
            }
        }
        lo = hi;
    }
    acc
}

/// Paper A §II.H step 1 (t = ta) or step 2 (t = tb): is the point not definitely outside
/// the polygon at t? `Yes` when it certainly is not (definitely_outside says `No`), `No`
/// when it certainly is, `Unsure` otherwise. From t = 0 the polygon is P itself; for a
/// statically shaped polygon (`stat`) the vertices at t are P shifted by t·(v_0 − v)
/// ([`Shifted`]), else each moves by its own velocity ([`AtTime`]).
#[inline(always)]
fn end_inside<P, V>(t: Ball, s: Vect2, v: Vect2, p: &P, vels: &V, buff: f64, stat: bool) -> Tri
where
    P: VertexSeq + ?Sized,
    V: VertexSeq + ?Sized,
{
    let outside = if t.is_exact_zero() {
        definitely_outside_rel(&AtTime { p, vels, s, v, t }, buff)
    } else if stat {
        definitely_outside_rel(&Shifted::new(p, s, v, vels.vertex(0), t), buff)
    } else {
        definitely_outside_rel(&AtTime { p, vels, s, v, t }, buff)
    };
    match outside {
        Tri::No => Tri::Yes,
        Tri::Unsure => Tri::Unsure,
        Tri::Yes => Tri::No,
    }
}

/// Paper A §II.H step 3 for the edge p_i p_j over the window [ta, tb], in the point's
/// frame: segments_close of the relative path, from ta·(v − v_i) to tb·(v − v_i), and
/// the edge, from p_i − s to p_j − s + ta·(v_j − v_i). `path` is the relative path of the
/// common velocity v_0 when v_i = v_0 (computed once for the polygon), `None` otherwise.
#[inline(always)]
fn edge_close(
    ta: Ball,
    tb: Ball,
    s: Vect2,
    v: Vect2,
    pi: Vect2,
    pj: Vect2,
    vi: Vect2,
    vj: Vect2,
    buff: f64,
    stat: bool,
    path: Option<(BallV, BallV)>,
) -> Tri {
    let (pa, pb) = match path {
        Some(ends) => ends,
        None => {
            let rel = BallV::diff(v, vi);
            (rel.scale(ta), rel.scale(tb))
        }
    };
    let qj = BallV::diff(pj, s);
    let edge_j = if ta.is_exact_zero() || stat || pr::same_velocity(vj, vi) {
        qj
    } else {
        qj.add(BallV::diff(vj, vi).scale(ta))
    };
    let qi = BallV::diff(pi, s);
    // Exact terms when both window ends are exact floats (always, but for a slab
    // window's quotients): the path from ta·(v − v_i) to tb·(v − v_i).
    let terms = || {
        if ta.r != 0.0 || tb.r != 0.0 {
            return None;
        }
        let path = |k: f64| Terms::ZERO.plus_scaled(k, v)?.plus_scaled(-k, vi);
        let ej = Terms::diff(pj, s);
        let ej = if ta.is_exact_zero() || stat || pr::same_velocity(vj, vi) {
            ej
        } else {
            ej.plus_scaled(ta.z, vj)?.plus_scaled(-ta.z, vi)?
        };
        Some([path(ta.z)?, path(tb.z)?, Terms::diff(pi, s), ej])
    };
    segments_close_ordered(pa, pb, qi, edge_j, buff, terms, true)
}

/// Paper A §II.H step 3 (segments_close's filter): same_window's side test of a vertex
/// against the relative path's line: from the rounded difference alone when the window
/// starts at 0 (the line passes through the point: the static bound of [`PathLine`]),
/// else on balls ([`pr::side_beyond`], out of line so that the common test stays inlined
/// in the loop).
struct PathSides {
    from_zero: bool,
    line: PathLine,
    pa: BallV,
    m: BallV,
    buff: f64,
}

impl PathSides {
    /// Paper A §II.H step 3: the relative path of the common velocity v_0 over [ta, tb],
    /// as its two ends, and the side test against its line. From a window starting at 0
    /// the path starts at the point exactly (and its direction m is its end): the line
    /// passes through the point, and the static bound of [`PathLine`] suffices;
    /// otherwise the side is taken on balls.
    #[inline(always)]
    fn new(ta: Ball, tb: Ball, v: Vect2, v0: Vect2, buff: f64) -> ((BallV, BallV), PathSides) {
        let rel0 = BallV::diff(v, v0);
        let from_zero = ta.is_exact_zero();
        let (pa0, pb0, m0) = if from_zero {
            let pb0 = rel0.scale(tb);
            (BallV::exact(Vect2::ZERO), pb0, pb0)
        } else {
            let (pa0, pb0) = (rel0.scale(ta), rel0.scale(tb));
            (pa0, pb0, pb0.sub(pa0))
        };
        let sides = PathSides {
            from_zero,
            line: PathLine::new(m0, buff),
            pa: pa0,
            m: m0,
            buff,
        };
        ((pa0, pb0), sides)
    }

    /// The side of vertex p (−1, 0 or +1; 0 when not certainly beyond BUFF).
    #[inline(always)]
    fn of(&self, p: Vect2, s: Vect2) -> i8 {
        if self.from_zero {
            self.line.side(p - s)
        } else {
            side_on_balls(self.pa, self.m, BallV::diff(p, s), self.buff)
        }
    }
}

/// See [`PathSides`].
#[inline(never)]
fn side_on_balls(pa: BallV, m: BallV, q: BallV, buff: f64) -> i8 {
    pr::side_beyond(pa, m, q, buff)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detect::detect_diff_2d;
    use crate::detect::tests::v;

    mod masks {
        //! detect_same_2D (§II.H) answers on masks ([`crate::lanes`]) as one edge at a
        //! time.
        use super::*;
        use crate::lanes::tests::{case, check_cases, Case, NotSlice};
        use proptest::prelude::*;

        /// detect_same_2D (§II.H) on slices (masks from 16 vertices on) answers as on
        /// vertices that are not a slice (one edge at a time).
        #[test]
        fn detect_same_on_masks_is_the_scalar_answer() {
            check_cases(case(), detect_same);
        }

        fn detect_same((b, verts, s, v, v0, t): Case) -> Result<(), TestCaseError> {
            let vels = vec![v0; verts.len()];
            prop_assert_eq!(
                detect_same_2d_tri(t, s, v, &verts[..], &vels[..], b),
                detect_same_2d_tri(t, s, v, &NotSlice(&verts), &vels[..], b)
            );
            Ok(())
        }
    }

    #[test]
    fn detect_diff_and_same_agree_on_a_translating_square() {
        // A unit-speed square moving right; a point moving up through its path.
        let sq = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)];
        let vel_same = [v(1.0, 0.0); 4];
        let s = v(5.0, -3.0);
        let vs = v(0.0, 1.0);
        // At t = 4 the square spans x ∈ [4, 6], y ∈ [0, 2] and s = (5, 1): inside.
        for (t, expect) in [(10.0, true), (2.5, false)] {
            assert_eq!(
                detect_same_2d(t, s, vs, &sq[..], &vel_same[..], 0.01),
                expect,
                "T={t}"
            );
            assert_eq!(
                detect_diff_2d(t, s, vs, &sq[..], &vel_same[..], 1e-4, 0.01),
                expect,
                "T={t}"
            );
        }
    }
}
