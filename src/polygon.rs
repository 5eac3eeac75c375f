//! Polygons as the paper's functions see them (§II): a sequence of vertices p_0 … p_n,
//! read through a view so that P + t·V and the perturbed P*_BUFF are never copied.

use crate::vect2::Vect2;

/// A read-only sequence of vertices (or of velocities): paper A §II's P = {p_0, …, p_n}.
///
/// Implemented for slices and for the lazily computed polygons the algorithms need
/// ([`Moved`] for P + t·V, [`crate::contain::Perturbed`] for P*_BUFF), so no paper
/// function allocates.
pub trait VertexSeq {
    /// Number of vertices n + 1.
    fn count(&self) -> usize;
    /// Vertex i (0 ≤ i < count).
    fn vertex(&self, i: usize) -> Vect2;
    /// The vertex after i, cyclically: edges run from i to `next(i)` (§II.D).
    #[inline(always)]
    fn next(&self, i: usize) -> usize {
        if i + 1 == self.count() {
            0
        } else {
            i + 1
        }
    }
    /// The vertices as one contiguous slice, when they are stored that way (vertex i is
    /// element i): the per-edge filters then test several vertices at once (the
    /// engine's lanes, docs/performance.md). `None` for computed views.
    #[inline(always)]
    fn as_slice(&self) -> Option<&[Vect2]> {
        None
    }
}

impl VertexSeq for [Vect2] {
    #[inline(always)]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline(always)]
    fn vertex(&self, i: usize) -> Vect2 {
        self[i]
    }
    #[inline(always)]
    fn as_slice(&self) -> Option<&[Vect2]> {
        Some(self)
    }
}

impl<const N: usize> VertexSeq for [Vect2; N] {
    #[inline(always)]
    fn count(&self) -> usize {
        N
    }
    #[inline(always)]
    fn vertex(&self, i: usize) -> Vect2 {
        self[i]
    }
    #[inline(always)]
    fn as_slice(&self) -> Option<&[Vect2]> {
        Some(&self[..])
    }
}

impl<T: VertexSeq + ?Sized> VertexSeq for &T {
    #[inline(always)]
    fn count(&self) -> usize {
        (**self).count()
    }
    #[inline(always)]
    fn vertex(&self, i: usize) -> Vect2 {
        (**self).vertex(i)
    }
    #[inline(always)]
    fn as_slice(&self) -> Option<&[Vect2]> {
        (**self).as_slice()
    }
}

/// The polygon P + t·V of §II (vertex i is p_i + t·v_i), computed on access.
#[derive(Clone, Copy, Debug)]
pub struct Moved<P, V> {
    /// The vertices P at t = 0.
    pub p: P,
    /// Their velocities V.
    pub v: V,
    /// The time t.
    pub t: f64,
}

impl<P: VertexSeq, V: VertexSeq> VertexSeq for Moved<P, V> {
    #[inline(always)]
    fn count(&self) -> usize {
        self.p.count()
    }
    #[inline(always)]
    fn vertex(&self, i: usize) -> Vect2 {
        self.p.vertex(i).at(self.v.vertex(i), self.t)
    }
}
