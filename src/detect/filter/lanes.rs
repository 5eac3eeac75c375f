//! Paper A §II.I, the filter in front of edge_detect, four edges at once: the bits of
//! [`swept_boxes_apart`] for the four edges from four consecutive vertices p_0 … p_3
//! (with velocities v_0 … v_3) to their successors p_1, p_2, p_3 and p_4, against one
//! [`Sweep`] of the point.
//!
//! The AVX kernel evaluates the scalar formula lane by lane with the same operations in
//! the same order (Rust does not contract a·b + c into a fused multiply-add, and the
//! intrinsics below are separate multiplies and adds), so each bit is the scalar
//! function's answer, NaN included: `_mm256_min_pd(a, b)` is `if a < b { a } else { b }`
//! and `_mm256_max_pd(a, b)` is `if a > b { a } else { b }` (the second operand when
//! either is NaN or both are equal), which is what `detect`'s `fmin` and `fmax`
//! compute; the comparisons are ordered (false on NaN), as Rust's
//! are. The portable kernel is the scalar function itself. The choice of kernel follows
//! [`crate::lanes::with_kernel`].

use super::{swept_boxes_apart, Sweep};
use crate::vect2::Vect2;

/// Edges a call to [`Kernel::apart`] decides.
pub(in crate::detect) const LANES: usize = 4;

/// Four consecutive vertices (or velocities), lane l being edge l's start.
pub(in crate::detect) type Four = [Vect2; LANES];

/// [`swept_boxes_apart`] for [`LANES`] edges.
pub(in crate::detect) trait Kernel: Copy {
    /// Bit l is `swept_boxes_apart(w, p[l], p[l + 1], v[l], v[l + 1], f)` (paper A §II.I,
    /// the filter in front of edge_detect), where p[4] is `p4` and v[4] is `v4`.
    fn apart(self, w: &Sweep, p: &Four, p4: Vect2, v: &Four, v4: Vect2, f: f64) -> u32;
}

/// The ends of edge l of [`Kernel::apart`]: (p[l], p[l + 1]).
#[inline(always)]
fn ends(p: &Four, p4: Vect2, l: usize) -> (Vect2, Vect2) {
    (p[l], if l + 1 == LANES { p4 } else { p[l + 1] })
}

/// The portable kernel: the scalar filter, one edge at a time.
#[derive(Clone, Copy, Debug)]
pub(in crate::detect) struct Portable;

impl Kernel for Portable {
    #[inline(always)]
    fn apart(self, w: &Sweep, p: &Four, p4: Vect2, v: &Four, v4: Vect2, f: f64) -> u32 {
        let mut bits = 0;
        for l in 0..LANES {
            let ((pi, pj), (vi, vj)) = (ends(p, p4, l), ends(v, v4, l));
            bits |= (swept_boxes_apart(w, pi, pj, vi, vj, f) as u32) << l;
        }
        bits
    }
}

/// The AVX kernel (x86-64), four edges a 256-bit register: only constructed where
/// [`crate::lanes::Avx::new`] finds AVX.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(in crate::detect) struct Avx(crate::lanes::Avx);

#[cfg(target_arch = "x86_64")]
impl Kernel for Avx {
    #[inline(always)]
    fn apart(self, w: &Sweep, p: &Four, p4: Vect2, v: &Four, v4: Vect2, f: f64) -> u32 {
        // SAFETY: an `Avx` holds a `crate::lanes::Avx`, which exists only where the CPU
        // has AVX.
        unsafe { avx::apart(w, p, p4, v, v4, f) }
    }
}

/// A computation generic over the kernel (a closure cannot be generic).
pub(in crate::detect) trait KernelFn<T> {
    /// Runs with kernel `k`.
    fn call<K: Kernel>(self, k: K) -> T;
}

/// Runs `f` with the fastest kernel this CPU has, chosen as [`crate::lanes::with_kernel`]
/// chooses (paper A §II.I, the filter in front of edge_detect).
#[inline(always)]
pub(in crate::detect) fn with_kernel<T>(f: impl KernelFn<T>) -> T {
    #[cfg(target_arch = "x86_64")]
    if let Some(k) = crate::lanes::Avx::new() {
        return f.call(Avx(k));
    }
    f.call(Portable)
}

#[cfg(target_arch = "x86_64")]
mod avx {
    use super::super::Sweep;
    use super::Four;
    use crate::ball::{mx, ETA, U};
    use crate::predicates::{FuzzyLine, SWEEP_ROUNDING};
    use core::arch::x86_64::*;

    /// The factor of [`crate::ball::up`].
    const UP: f64 = 1.0 + 16.0 * U;

    /// x and y of four vertices in two registers, lanes in vertex order: (x0, y0 | x2, y2)
    /// and (x1, y1 | x3, y3) unpacked.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn xy(p: &Four) -> (__m256d, __m256d) {
        // `Vect2` is `#[repr(C)]` (x, y): the array is 8 contiguous f64.
        let at = p.as_ptr() as *const f64;
        let a = _mm256_loadu2_m128d(at.add(4), at);
        let b = _mm256_loadu2_m128d(at.add(6), at.add(2));
        (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b))
    }

    /// The lanes moved down by one, `x4` in the last: (x1, x2, x3, x4) from
    /// (x0, x1, x2, x3), the edges' far ends from their near ends.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn next(x: __m256d, x4: f64) -> __m256d {
        // (x2, x3, x0, x1), then (x1, x2 | x3, x0)
        let halves = _mm256_permute2f128_pd::<0x01>(x, x);
        let down = _mm256_shuffle_pd::<0b0101>(x, halves);
        _mm256_blend_pd::<0b1000>(down, _mm256_set1_pd(x4))
    }

    /// |x|, as `f64::abs`: the sign bit cleared.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn abs(x: __m256d) -> __m256d {
        _mm256_and_pd(x, _mm256_castsi256_pd(_mm256_set1_epi64x(i64::MAX)))
    }

    /// [`crate::ball::up`] lane by lane: x·(1 + 16u) + ETA.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn up(x: __m256d) -> __m256d {
        _mm256_add_pd(_mm256_mul_pd(x, _mm256_set1_pd(UP)), _mm256_set1_pd(ETA))
    }

    /// a > b lane by lane (ordered: false on NaN).
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn gt(a: __m256d, b: __m256d) -> __m256d {
        _mm256_cmp_pd::<_CMP_GT_OQ>(a, b)
    }

    /// The lanes where [`FuzzyLine::side`] is +1 and where it is −1, for the line of
    /// [`FuzzyLine::new`]`(o, d, ρ, dist)` with ρ and dist per lane; `n1` = ‖d‖₁ and
    /// `dmx2` = 2u·‖d‖∞ as the constructor forms them.
    #[derive(Clone, Copy)]
    struct Line {
        o: (__m256d, __m256d),
        d: (__m256d, __m256d),
        k2: __m256d,
        c: __m256d,
    }

    impl Line {
        /// [`FuzzyLine::new`] lane by lane.
        ///
        /// # Safety
        /// The CPU must have AVX.
        #[inline]
        #[target_feature(enable = "avx")]
        unsafe fn new(
            o: crate::vect2::Vect2,
            d: crate::vect2::Vect2,
            rho: __m256d,
            dist: __m256d,
        ) -> Line {
            let n1 = d.x.abs() + d.y.abs();
            let two = _mm256_set1_pd(2.0);
            let rd = up(_mm256_add_pd(
                _mm256_mul_pd(two, rho),
                _mm256_set1_pd(2.0 * U * mx(d.x.abs(), d.y.abs())),
            ));
            let k2 = up(_mm256_add_pd(
                up(_mm256_add_pd(rd, _mm256_set1_pd(2.0 * U * n1))),
                _mm256_mul_pd(_mm256_set1_pd(4.0 * U), rd),
            ));
            let n1v = _mm256_set1_pd(n1);
            let c = up(_mm256_add_pd(
                _mm256_add_pd(
                    up(_mm256_mul_pd(
                        dist,
                        _mm256_add_pd(n1v, _mm256_mul_pd(two, rd)),
                    )),
                    _mm256_mul_pd(_mm256_mul_pd(two, rho), n1v),
                ),
                _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(4.0), rd), rho),
            ));
            Line {
                o: (_mm256_set1_pd(o.x), _mm256_set1_pd(o.y)),
                d: (_mm256_set1_pd(d.x), _mm256_set1_pd(d.y)),
                k2,
                c,
            }
        }

        /// [`FuzzyLine::side`] lane by lane: the bits where it is +1 and where it is −1.
        ///
        /// # Safety
        /// The CPU must have AVX.
        #[inline]
        #[target_feature(enable = "avx")]
        unsafe fn side(&self, qx: __m256d, qy: __m256d) -> (i32, i32) {
            let wx = _mm256_sub_pd(qx, self.o.0);
            let wy = _mm256_sub_pd(qy, self.o.1);
            let l = _mm256_mul_pd(self.d.0, wy);
            let r = _mm256_mul_pd(self.d.1, wx);
            let c = _mm256_sub_pd(l, r);
            let bound = _mm256_add_pd(
                _mm256_add_pd(
                    _mm256_mul_pd(_mm256_set1_pd(FuzzyLine::K1), _mm256_add_pd(abs(l), abs(r))),
                    _mm256_mul_pd(self.k2, _mm256_add_pd(abs(wx), abs(wy))),
                ),
                self.c,
            );
            let pos = _mm256_movemask_pd(gt(c, bound));
            let nc = _mm256_xor_pd(c, _mm256_set1_pd(-0.0));
            let neg = _mm256_movemask_pd(gt(nc, bound));
            // −1 only where the side is not +1, as `FuzzyLine::side` tests +1 first.
            (pos, neg & !pos)
        }
    }

    /// [`super::Kernel::apart`]: [`super::swept_boxes_apart`]'s formula lane by lane, in
    /// its order (the corners, l0 and l1, the edges' box, M, the slack, the ranges apart,
    /// then the four corners' side of the path line when the point moves).
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[target_feature(enable = "avx")]
    pub(super) unsafe fn apart(
        w: &Sweep,
        p: &Four,
        p4: crate::vect2::Vect2,
        v: &Four,
        v4: crate::vect2::Vect2,
        f: f64,
    ) -> u32 {
        let ((pix, piy), (vix, viy)) = (xy(p), xy(v));
        let (pjx, pjy) = (next(pix, p4.x), next(piy, p4.y));
        let (vjx, vjy) = (next(vix, v4.x), next(viy, v4.y));
        let (t0, t1) = (_mm256_set1_pd(w.t0), _mm256_set1_pd(w.t1));
        // p + t·v, as `Vect2::at`
        let at = |p: __m256d, v: __m256d, t: __m256d| _mm256_add_pd(p, _mm256_mul_pd(t, v));
        let (aix, aiy, bix, biy) = (
            at(pix, vix, t0),
            at(piy, viy, t0),
            at(pix, vix, t1),
            at(piy, viy, t1),
        );
        let (ajx, ajy, bjx, bjy) = (
            at(pjx, vjx, t0),
            at(pjy, vjy, t0),
            at(pjx, vjx, t1),
            at(pjy, vjy, t1),
        );
        let l0 = _mm256_add_pd(abs(_mm256_sub_pd(ajx, aix)), abs(_mm256_sub_pd(ajy, aiy)));
        let l1 = _mm256_add_pd(abs(_mm256_sub_pd(bjx, bix)), abs(_mm256_sub_pd(bjy, biy)));
        let (min, max) = (
            |a: __m256d, b: __m256d| _mm256_min_pd(a, b),
            |a: __m256d, b: __m256d| _mm256_max_pd(a, b),
        );
        let ex_lo = min(min(aix, ajx), min(bix, bjx));
        let ex_hi = max(max(aix, ajx), max(bix, bjx));
        let ey_lo = min(min(aiy, ajy), min(biy, bjy));
        let ey_hi = max(max(aiy, ajy), max(biy, bjy));
        let mut m = max(
            _mm256_set1_pd(w.m),
            max(max(abs(ex_lo), abs(ex_hi)), max(abs(ey_lo), abs(ey_hi))),
        );
        if w.t0 != 0.0 {
            let (big_i, big_j) = (max(abs(pix), abs(piy)), max(abs(pjx), abs(pjy)));
            m = max(m, max(big_i, big_j));
        }
        let slack = _mm256_add_pd(
            _mm256_mul_pd(_mm256_set1_pd(2.0 * f), max(l0, l1)),
            _mm256_mul_pd(_mm256_set1_pd(SWEEP_ROUNDING), m),
        );
        let twice = _mm256_mul_pd(_mm256_set1_pd(2.0), slack);
        // `ranges_apart` on x, then on y
        let apart = |lo: __m256d, hi: __m256d, b_lo: f64, b_hi: f64| {
            _mm256_or_pd(
                gt(_mm256_sub_pd(_mm256_set1_pd(b_lo), hi), twice),
                gt(_mm256_sub_pd(lo, _mm256_set1_pd(b_hi)), twice),
            )
        };
        let boxes = _mm256_or_pd(
            apart(ex_lo, ex_hi, w.lo.x, w.hi.x),
            apart(ey_lo, ey_hi, w.lo.y, w.hi.y),
        );
        let bits = _mm256_movemask_pd(boxes);
        if !w.moving || bits == 0b1111 {
            return bits as u32;
        }
        let rho = _mm256_mul_pd(_mm256_set1_pd(SWEEP_ROUNDING), m);
        let line = Line::new(w.s0, w.dir, rho, slack);
        let (p0, n0) = line.side(aix, aiy);
        let (p1, n1) = line.side(ajx, ajy);
        let (p2, n2) = line.side(bix, biy);
        let (p3, n3) = line.side(bjx, bjy);
        (bits | (p0 & p1 & p2 & p3) | (n0 & n1 & n2 & n3)) as u32
    }
}

#[cfg(test)]
pub(in crate::detect) mod tests;
