//! How a detector or the truth runs its paper-function calls: all in one kernel
//! ([`Single`]), or each in the interval kernel first and, when that one call
//! abstains, in the exact kernel ([`Filtered`]).
//!
//! The grain of the fallback is a [`Unit`]: one paper-function call (one
//! definitely_outside, one segments_close, one edge_detect, one contact test of the
//! truth, …) with the computation of its inputs from the scene. A unit is written
//! once, generic over the kernel; the detectors and the truth are written once,
//! generic over the [`Runner`].
//!
//! The truth's entry time is always built by the exact kernel. A contact found by
//! the interval kernel is reported as an enclosure together with *which* root it
//! is (the k-th root of the contact quadratic, see [`crate::truth::Contact`]);
//! contacts certainly later than another one are dropped, and the exact kernel
//! builds the rest by the same function the exact-only path uses, so even the
//! representation of the algebraic number is the same.

use core::convert::Infallible;
use std::borrow::Cow;

use super::interval::{enclose, enclose2, Iv};
use super::{certainly, Decided, Exact, Kernel};
use crate::field::{Arith, ExactField, V2};
use crate::qfield::Alg;

/// The inputs of a detector (paper A's T, s, v, P, V, BUFF, F), or of the truth on
/// its window, in one kernel's numbers: borrowed from the case, or computed.
#[derive(Clone, Debug)]
pub(crate) struct Scene<'a, N: Clone> {
    /// T, the lookahead.
    pub(crate) t: Cow<'a, N>,
    /// s, the point.
    pub(crate) s: Cow<'a, V2<N>>,
    /// v, its velocity.
    pub(crate) v: Cow<'a, V2<N>>,
    /// P, the vertices.
    pub(crate) p: Cow<'a, [V2<N>]>,
    /// V, their velocities.
    pub(crate) vels: Cow<'a, [V2<N>]>,
    /// BUFF.
    pub(crate) buff: Cow<'a, N>,
    /// F.
    pub(crate) f: Cow<'a, N>,
}

impl<'a, N: Arith> Scene<'a, N> {
    /// The scene of borrowed inputs.
    pub(crate) fn new(
        t: &'a N,
        s: &'a V2<N>,
        v: &'a V2<N>,
        p: &'a [V2<N>],
        vels: &'a [V2<N>],
        buff: &'a N,
        f: &'a N,
    ) -> Self {
        Scene {
            t: Cow::Borrowed(t),
            s: Cow::Borrowed(s),
            v: Cow::Borrowed(v),
            p: Cow::Borrowed(p),
            vels: Cow::Borrowed(vels),
            buff: Cow::Borrowed(buff),
            f: Cow::Borrowed(f),
        }
    }

    /// The same motion seen from time t0 on, over the lookahead t: the point at
    /// s + t0·v and the polygon at P + t0·V (paper A §III's restart at the slab
    /// window's start).
    pub(crate) fn shifted(&self, t0: &N, t: N) -> Self {
        let p: Vec<V2<N>> = self
            .p
            .iter()
            .zip(self.vels.iter())
            .map(|(p, w)| p.at(w, t0))
            .collect();
        Scene {
            t: Cow::Owned(t),
            s: Cow::Owned(self.s.at(&self.v, t0)),
            p: Cow::Owned(p),
            ..self.clone()
        }
    }

    /// The number of vertices; 0 when P and V differ in length (nothing to detect).
    pub(crate) fn count(&self) -> usize {
        if self.p.len() == self.vels.len() {
            self.p.len()
        } else {
            0
        }
    }
}

impl<F: ExactField> Scene<'_, F> {
    /// The enclosures of the scene's numbers.
    pub(crate) fn enclosed(&self) -> Scene<'static, Iv> {
        Scene {
            t: Cow::Owned(enclose(&*self.t)),
            s: Cow::Owned(enclose2(&self.s)),
            v: Cow::Owned(enclose2(&self.v)),
            p: Cow::Owned(self.p.iter().map(enclose2).collect()),
            vels: Cow::Owned(self.vels.iter().map(enclose2).collect()),
            buff: Cow::Owned(enclose(&*self.buff)),
            f: Cow::Owned(enclose(&*self.f)),
        }
    }
}

/// One paper-function call on a scene, written once for every kernel: the grain
/// of the fallback. Its answer may hold roots of the kernel (`Out<K::Root>`).
pub(crate) trait Unit {
    /// The answer, with roots of type R.
    type Out<R>;
    /// The call in kernel `k` on the scene in its numbers.
    fn run<N: Arith, K: Kernel<N>>(
        &self,
        k: &K,
        sc: &Scene<'_, N>,
    ) -> Result<Self::Out<K::Root>, K::Abstain>;
    /// The answer with its roots turned into another type.
    fn map_root<A, B>(out: Self::Out<A>, f: impl FnMut(A) -> B) -> Self::Out<B>;
}

/// Runs units: the one way the detectors and the truth reach a kernel.
pub(crate) trait Runner {
    /// The roots in the answers.
    type Root;
    /// Why a unit was not decided.
    type Abstain: Copy;
    /// The unit's answer.
    fn run<U: Unit>(&self, u: &U) -> Result<U::Out<Self::Root>, Self::Abstain>;
    /// The number of vertices of the scene; 0 when P and V differ in length.
    fn count(&self) -> usize;
}

/// Every unit in one kernel (the exact-only path, or a whole call in intervals).
pub(crate) struct Single<'a, N: Clone, K> {
    k: &'a K,
    sc: Scene<'a, N>,
}

impl<'a, N: Arith, K: Kernel<N>> Single<'a, N, K> {
    /// Units of kernel `k` on the scene.
    pub(crate) fn new(k: &'a K, sc: Scene<'a, N>) -> Self {
        Single { k, sc }
    }
}

impl<N: Arith, K: Kernel<N>> Runner for Single<'_, N, K> {
    type Root = K::Root;
    type Abstain = K::Abstain;
    fn run<U: Unit>(&self, u: &U) -> Result<U::Out<K::Root>, K::Abstain> {
        u.run(self.k, &self.sc)
    }
    fn count(&self) -> usize {
        self.sc.count()
    }
}

/// A root found by [`Filtered`]: an enclosure certified by the first kernel, or an
/// exact root when the unit fell back to the exact kernel.
#[derive(Clone, Debug)]
pub(crate) enum Found<R, F> {
    /// Certified by the first kernel (an enclosure; the unit says which root).
    Enclosed(R),
    /// Computed by the exact kernel.
    Exact(Alg<F>),
}

/// Each unit in the first kernel (normally [`super::Intervals`]) on the enclosed
/// scene, and in [`Exact`] on the exact scene when the first abstains.
pub(crate) struct Filtered<'a, F: ExactField, K> {
    first: &'a K,
    iv: Scene<'static, Iv>,
    ex: Scene<'a, F>,
}

impl<'a, F: ExactField, K: Kernel<Iv>> Filtered<'a, F, K> {
    /// The first kernel on the enclosures of the exact scene `ex`.
    pub(crate) fn new(first: &'a K, ex: Scene<'a, F>) -> Self {
        let iv = ex.enclosed();
        Filtered { first, iv, ex }
    }

    /// The first kernel on `iv`, which must enclose the numbers of `ex`.
    pub(crate) fn with_enclosures(first: &'a K, ex: Scene<'a, F>, iv: Scene<'static, Iv>) -> Self {
        Filtered { first, iv, ex }
    }
}

impl<F: ExactField, K: Kernel<Iv>> Runner for Filtered<'_, F, K> {
    type Root = Found<K::Root, F>;
    type Abstain = Infallible;
    fn run<U: Unit>(&self, u: &U) -> Result<U::Out<Self::Root>, Infallible> {
        Ok(match u.run(self.first, &self.iv) {
            Ok(out) => U::map_root(out, Found::Enclosed),
            Err(_) => U::map_root(u.run(&Exact, &self.ex).decided(), Found::Exact),
        })
    }
    fn count(&self) -> usize {
        self.ex.count()
    }
}

/// What the truth needs beyond [`Runner`]: its roots ordered and made exact.
pub(crate) trait Resolve<F: ExactField>: Runner<Abstain = Infallible> {
    /// The exact scene.
    fn exact_scene(&self) -> &Scene<'_, F>;
    /// The root, when it is exact already.
    fn as_exact<'r>(&self, r: &'r Self::Root) -> Option<&'r Alg<F>>;
    /// Whether a < b is certain (false when it is not decided).
    fn certainly_before(&self, a: &Self::Root, b: &Self::Root) -> bool;
    /// Whether `test` is certain on the scene in the first kernel (false when the runner
    /// has none, or the kernel abstains): the truth's O(n) filters in front of exact
    /// passes.
    fn certainly_first(&self, test: impl Fn(&dyn FirstKernel, &Scene<'_, Iv>) -> bool) -> bool;
}

/// A first kernel seen through a trait object: the tests the truth's filters run.
pub(crate) trait FirstKernel {
    /// x > 0 certified (false when not certain).
    fn pos(&self, x: &Iv) -> bool;
    /// x < 0 certified (false when not certain).
    fn neg(&self, x: &Iv) -> bool;
}

impl<K: Kernel<Iv>> FirstKernel for K {
    fn pos(&self, x: &Iv) -> bool {
        certainly(self.is_pos(x))
    }
    fn neg(&self, x: &Iv) -> bool {
        certainly(self.is_neg(x))
    }
}

impl<F: ExactField> Resolve<F> for Single<'_, F, Exact> {
    fn exact_scene(&self) -> &Scene<'_, F> {
        &self.sc
    }
    fn as_exact<'r>(&self, r: &'r Alg<F>) -> Option<&'r Alg<F>> {
        Some(r)
    }
    fn certainly_before(&self, a: &Alg<F>, b: &Alg<F>) -> bool {
        certainly(Exact.root_lt(a, b))
    }
    fn certainly_first(&self, _: impl Fn(&dyn FirstKernel, &Scene<'_, Iv>) -> bool) -> bool {
        false
    }
}

impl<F: ExactField, K: Kernel<Iv>> Resolve<F> for Filtered<'_, F, K> {
    fn exact_scene(&self) -> &Scene<'_, F> {
        &self.ex
    }
    fn as_exact<'r>(&self, r: &'r Self::Root) -> Option<&'r Alg<F>> {
        match r {
            Found::Exact(a) => Some(a),
            Found::Enclosed(_) => None,
        }
    }
    fn certainly_before(&self, a: &Self::Root, b: &Self::Root) -> bool {
        match (a, b) {
            (Found::Enclosed(a), Found::Enclosed(b)) => certainly(self.first.root_lt(a, b)),
            _ => false,
        }
    }
    fn certainly_first(&self, test: impl Fn(&dyn FirstKernel, &Scene<'_, Iv>) -> bool) -> bool {
        test(self.first, &self.iv)
    }
}
