//! The per-vertex filters of paper A §II.E (definitely_outside's skip of far edges) and
//! §II.H step 3 (detect_same_2D's side of the relative path's line), several vertices at
//! once: each vertex's certain tests become bits of a mask, and an edge's skip is the
//! AND of its two ends' bits, so that the loops visit only the edges that survive.
//!
//! Every lane evaluates the scalar formula of [`RelPoly::at`](crate::contain::RelPoly::at)
//! or [`PathLine::side`] with the same operations in the same order (Rust does not
//! contract a·b + c into a fused multiply-add, and the intrinsics below are separate
//! multiplies and adds), so each bit is the scalar comparison's result, NaN included
//! (ordered comparisons: false). The masks therefore skip exactly the edges the scalar
//! loops skip, and the detectors' answers do not depend on the kernel.
//!
//! Kernels: a portable one ([`Portable`]), and on x86-64 one on 256-bit AVX registers
//! ([`Avx`], two vertices a register for the margins, four for the sides), chosen once
//! per call by [`with_kernel`]: at compile time when the target has AVX (e.g.
//! `-C target-cpu=native`), else at run time with the `std` feature, else portable.

use crate::predicates::PathLine;
use crate::vect2::Vect2;

/// Vertices of one polygon in a frame where vertex k is fl(p_k − s) (+ fl(·) `shift`
/// when there is one): the vertices of [`crate::contain::AtTime`] at t = 0 and of
/// [`crate::contain::Shifted`] as their `at` computes them.
#[derive(Clone, Copy, Debug)]
pub struct Frame<'a> {
    /// The polygon's vertices, contiguous.
    pub verts: &'a [Vect2],
    /// The point s.
    pub s: Vect2,
    /// The common shift added after the difference, if any.
    pub shift: Option<Vect2>,
}

impl Frame<'_> {
    /// Vertex k in the frame, as [`crate::contain::RelPoly::at`] computes it.
    #[inline(always)]
    pub fn at(&self, k: usize) -> Vect2 {
        let d = self.verts[k] - self.s;
        match self.shift {
            Some(h) => d + h,
            None => d,
        }
    }
}

/// Per-vertex filter bits for up to [`MARGIN_CHUNK`] (margins) or [`SIDE_CHUNK`] (sides)
/// consecutive vertices.
pub trait Kernel: Copy {
    /// §II.E's margin bits of `f.verts[lo..hi]` (hi − lo ≤ [`MARGIN_CHUNK`]): bit 2k of
    /// `.0` is x_k ≥ m and bit 2k + 1 is y_k ≥ m; bits 2k, 2k + 1 of `.1` are x_k ≤ −m and
    /// y_k ≤ −m (k counted from lo; x_k, y_k the coordinates of [`Frame::at`]).
    fn margin_bits(self, f: &Frame<'_>, lo: usize, hi: usize, m: f64) -> (u64, u64);
    /// §II.H step 3's side bits of `verts[lo..hi] − s` (hi − lo ≤ [`SIDE_CHUNK`]): bit k
    /// of `.0` is set when [`PathLine::side`] is +1, of `.1` when it is −1.
    fn side_bits(
        self,
        line: &PathLine,
        verts: &[Vect2],
        s: Vect2,
        lo: usize,
        hi: usize,
    ) -> (u64, u64);
}

/// The fewest vertices for which the masks pay: below, setting them up (the kernel's
/// call, the chunk's bookkeeping) costs more than the per-edge tests they replace, and
/// the loops test one edge at a time (measured: docs/performance.md, "SIMD across
/// edges").
pub const MIN_VERTICES: usize = 16;

/// Vertices a margin mask holds (two bits each).
pub const MARGIN_CHUNK: usize = 32;
/// Vertices a side mask holds (one bit each).
pub const SIDE_CHUNK: usize = 64;

/// The bits of one vertex at (x, y) against ±m: (x ≥ m, y ≥ m) and (x ≤ −m, y ≤ −m), as
/// bits 0 and 1 — the comparisons of `definitely_outside_rel`'s skip.
#[inline(always)]
pub fn vertex_margin_bits(q: Vect2, m: f64) -> (u64, u64) {
    let ge = (q.x >= m) as u64 | ((q.y >= m) as u64) << 1;
    let le = (q.x <= -m) as u64 | ((q.y <= -m) as u64) << 1;
    (ge, le)
}

/// The portable kernel: one vertex at a time, branch-free.
#[derive(Clone, Copy, Debug)]
pub struct Portable;

impl Kernel for Portable {
    #[inline(always)]
    fn margin_bits(self, f: &Frame<'_>, lo: usize, hi: usize, m: f64) -> (u64, u64) {
        let (mut ge, mut le) = (0u64, 0u64);
        for k in lo..hi {
            let (g, l) = vertex_margin_bits(f.at(k), m);
            ge |= g << (2 * (k - lo));
            le |= l << (2 * (k - lo));
        }
        (ge, le)
    }

    #[inline(always)]
    fn side_bits(
        self,
        line: &PathLine,
        verts: &[Vect2],
        s: Vect2,
        lo: usize,
        hi: usize,
    ) -> (u64, u64) {
        let (mut pos, mut neg) = (0u64, 0u64);
        for (k, &p) in verts[lo..hi].iter().enumerate() {
            let side = line.side(p - s);
            pos |= ((side > 0) as u64) << k;
            neg |= ((side < 0) as u64) << k;
        }
        (pos, neg)
    }
}

/// The AVX kernel (x86-64): only constructed where AVX is known to be present.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx(());

#[cfg(target_arch = "x86_64")]
impl Avx {
    /// The kernel, when the CPU has AVX (at compile time, or detected with `std`).
    #[inline(always)]
    pub fn new() -> Option<Avx> {
        #[cfg(target_feature = "avx")]
        {
            Some(Avx(()))
        }
        #[cfg(all(not(target_feature = "avx"), feature = "std"))]
        {
            if std::is_x86_feature_detected!("avx") {
                Some(Avx(()))
            } else {
                None
            }
        }
        #[cfg(all(not(target_feature = "avx"), not(feature = "std")))]
        {
            None
        }
    }
}

#[cfg(target_arch = "x86_64")]
impl Kernel for Avx {
    #[inline(always)]
    fn margin_bits(self, f: &Frame<'_>, lo: usize, hi: usize, m: f64) -> (u64, u64) {
        let verts = &f.verts[lo..hi];
        // SAFETY: an `Avx` exists only where the CPU has AVX (`Avx::new`).
        unsafe {
            match f.shift {
                Some(h) => avx::margin_bits::<true>(verts, f.s, h, m),
                None => avx::margin_bits::<false>(verts, f.s, Vect2::ZERO, m),
            }
        }
    }

    #[inline(always)]
    fn side_bits(
        self,
        line: &PathLine,
        verts: &[Vect2],
        s: Vect2,
        lo: usize,
        hi: usize,
    ) -> (u64, u64) {
        // SAFETY: as above.
        unsafe { avx::side_bits(line, &verts[lo..hi], s) }
    }
}

/// A computation generic over the kernel (a closure cannot be generic).
pub trait KernelFn<T> {
    /// Runs with kernel `k`.
    fn call<K: Kernel>(self, k: K) -> T;
}

/// Runs `f` with the fastest kernel this CPU has (see the module's documentation).
#[inline(always)]
pub fn with_kernel<T>(f: impl KernelFn<T>) -> T {
    #[cfg(target_arch = "x86_64")]
    if let Some(k) = Avx::new() {
        return f.call(k);
    }
    f.call(Portable)
}

#[cfg(target_arch = "x86_64")]
mod avx {
    use crate::predicates::PathLine;
    use crate::vect2::Vect2;
    use core::arch::x86_64::*;

    /// [`super::Kernel::margin_bits`] two vertices a register: lanes (x, y, x, y) of
    /// fl(fl(p − s) + shift) (the shift when `SHIFT`) compared with ±m. The bit order of
    /// `_mm256_movemask_pd` is the lane order, which is the interleaved order of the
    /// masks.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[target_feature(enable = "avx")]
    pub unsafe fn margin_bits<const SHIFT: bool>(
        verts: &[Vect2],
        s: Vect2,
        shift: Vect2,
        m: f64,
    ) -> (u64, u64) {
        let sv = _mm256_setr_pd(s.x, s.y, s.x, s.y);
        let hv = _mm256_setr_pd(shift.x, shift.y, shift.x, shift.y);
        let (pm, nm) = (_mm256_set1_pd(m), _mm256_set1_pd(-m));
        let (mut ge, mut le) = (0u64, 0u64);
        let pairs = verts.len() / 2;
        // `Vect2` is `#[repr(C)]` (x, y): the slice is 2·len contiguous f64.
        let base = verts.as_ptr() as *const f64;
        for k in 0..pairs {
            let p = _mm256_loadu_pd(base.add(4 * k));
            let mut q = _mm256_sub_pd(p, sv);
            if SHIFT {
                q = _mm256_add_pd(q, hv);
            }
            let g = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GE_OQ>(q, pm)) as u64;
            let l = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(q, nm)) as u64;
            ge |= g << (4 * k);
            le |= l << (4 * k);
        }
        if verts.len() % 2 == 1 {
            let k = verts.len() - 1;
            let d = verts[k] - s;
            let q = if SHIFT { d + shift } else { d };
            let (g, l) = super::vertex_margin_bits(q, m);
            ge |= g << (2 * k);
            le |= l << (2 * k);
        }
        (ge, le)
    }

    /// [`super::Kernel::side_bits`] four vertices a register: x and y of fl(p − s) in
    /// separate registers (vertices 0, 2 in the low halves, 1, 3 in the high, so that the
    /// unpacks give lanes in vertex order), then [`PathLine::side`]'s formula lane by
    /// lane.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[target_feature(enable = "avx")]
    pub unsafe fn side_bits(line: &PathLine, verts: &[Vect2], s: Vect2) -> (u64, u64) {
        let (d, rd, need) = line.parts();
        let (dx, dy) = (_mm256_set1_pd(d.x), _mm256_set1_pd(d.y));
        let (k1, rdv, needv) = (
            _mm256_set1_pd(PathLine::K1),
            _mm256_set1_pd(rd),
            _mm256_set1_pd(need),
        );
        let sv = _mm256_setr_pd(s.x, s.y, s.x, s.y);
        let abs = _mm256_castsi256_pd(_mm256_set1_epi64x(i64::MAX));
        let sign = _mm256_set1_pd(-0.0);
        let (mut pos, mut neg) = (0u64, 0u64);
        let quads = verts.len() / 4;
        let base = verts.as_ptr() as *const f64;
        for k in 0..quads {
            let at = base.add(8 * k);
            // (x0, y0 | x2, y2) and (x1, y1 | x3, y3)
            let a = _mm256_loadu2_m128d(at.add(4), at);
            let b = _mm256_loadu2_m128d(at.add(6), at.add(2));
            let (a, b) = (_mm256_sub_pd(a, sv), _mm256_sub_pd(b, sv));
            let qx = _mm256_unpacklo_pd(a, b);
            let qy = _mm256_unpackhi_pd(a, b);
            let l = _mm256_mul_pd(dx, qy);
            let r = _mm256_mul_pd(dy, qx);
            let c = _mm256_sub_pd(l, r);
            let lr = _mm256_add_pd(_mm256_and_pd(l, abs), _mm256_and_pd(r, abs));
            let qq = _mm256_add_pd(_mm256_and_pd(qx, abs), _mm256_and_pd(qy, abs));
            let bound = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(k1, lr), _mm256_mul_pd(rdv, qq)),
                needv,
            );
            let p = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(c, bound)) as u64;
            let nc = _mm256_xor_pd(c, sign);
            let n = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(nc, bound)) as u64;
            pos |= p << (4 * k);
            // −1 only where the side is not +1, as `PathLine::side` tests +1 first.
            neg |= (n & !p) << (4 * k);
        }
        for (k, &p) in verts.iter().enumerate().skip(4 * quads) {
            let side = line.side(p - s);
            pos |= ((side > 0) as u64) << k;
            neg |= ((side < 0) as u64) << k;
        }
        (pos, neg)
    }
}

#[cfg(test)]
pub(crate) mod tests;
