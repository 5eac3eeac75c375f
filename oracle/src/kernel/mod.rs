//! Kernels: the numbers paper A's functions compute with and the sign decisions
//! they take. Every paper function of the oracle ([`crate::quad`],
//! [`crate::contain`], [`crate::proximity`], [`crate::detect`],
//! [`crate::truth`](mod@crate::truth)) is written once, generic over a [`Kernel`],
//! and runs in two of them:
//!
//! - [`Exact`]: exact rationals ([`ExactField`]) and exact algebraic roots
//!   ([`Alg`]); it never abstains (its `Abstain` is [`Infallible`]).
//! - [`Intervals`] ([`interval`]): rigorous enclosures on binary floats; it abstains
//!   whenever an enclosure cannot certify a decision.
//!
//! [`crate::paper_detect`] and [`crate::truth()`] run each paper-function call in
//! [`Intervals`] first and, only when it abstains, in [`Exact`] (the private module
//! `kernel/run.rs` says how); [`crate::paper_detect_unfiltered`] and
//! [`crate::truth_unfiltered`] run [`Exact`] alone. A certified decision is the
//! exact one, so both give the same answers.
//!
//! Decisions are `Result<bool, Abstain>` and are combined with Kleene's
//! three-valued logic ([`or`], [`and`], [`any`], [`all`]): a combination is decided
//! only when every way of deciding the abstentions gives the same answer. In the
//! exact kernel they are the plain short-circuit `||` and `&&`.

pub mod exact;
pub mod interval;
pub(crate) mod run;

use core::cmp::Ordering;
use core::convert::Infallible;
use core::fmt::Debug;
use std::borrow::Cow;

pub use exact::Exact;
pub use interval::{Abstain, Intervals, Iv};

use crate::field::Arith;
#[cfg(doc)]
use crate::{field::ExactField, qfield::Alg};

/// The numbers and decisions a paper function runs on. `N` is the kernel's number
/// type (an [`ExactField`] for [`Exact`], [`Iv`] for [`Intervals`]); `Root` is its
/// representation of the real roots of quadratics (the ends of paper A §II.I's
/// intervals, the truth's contact times). A decision either is the exact one or is
/// `Err(Self::Abstain)`; the value operations (`abs`, `hull`, roots, `root_max`,
/// `root_min`) never abstain: the interval kernel returns enclosures of the exact
/// results.
pub trait Kernel<N: Arith> {
    /// The real roots of quadratics: exact algebraic numbers or enclosures.
    type Root: Clone + Debug;
    /// Why a decision was not taken ([`Infallible`] for a kernel that always decides).
    type Abstain: Copy + Debug;

    /// a < b.
    fn lt(&self, a: &N, b: &N) -> Result<bool, Self::Abstain>;
    /// a ≤ b.
    fn le(&self, a: &N, b: &N) -> Result<bool, Self::Abstain>;
    /// a = b.
    fn eq(&self, a: &N, b: &N) -> Result<bool, Self::Abstain>;
    /// The sign of x, as its order relative to 0.
    fn sign(&self, x: &N) -> Result<Ordering, Self::Abstain>;
    /// x = 0.
    fn is_zero(&self, x: &N) -> Result<bool, Self::Abstain> {
        Ok(self.sign(x)? == Ordering::Equal)
    }
    /// x > 0.
    fn is_pos(&self, x: &N) -> Result<bool, Self::Abstain> {
        self.lt(&N::zero(), x)
    }
    /// x < 0.
    fn is_neg(&self, x: &N) -> Result<bool, Self::Abstain> {
        self.lt(x, &N::zero())
    }

    /// |x|.
    fn abs(&self, x: &N) -> N;
    /// The least and the greatest of `xs` (not empty; borrowed when they are among
    /// them).
    fn hull<'a>(&self, xs: &[&'a N]) -> (Cow<'a, N>, Cow<'a, N>);

    /// The number x as a root.
    fn root(&self, x: &N) -> Self::Root;
    /// The root n/d of d·t − n (d ≠ 0 has been decided); `None` when d = 0.
    fn linear_root(&self, n: N, d: N) -> Option<Self::Root>;
    /// The two roots of a·t² + b·t + c, in increasing order, from a (a ≠ 0 has been
    /// decided), b and the discriminant disc = b² − 4ac (disc > 0 has been decided);
    /// `None` when a = 0.
    fn two_roots(&self, a: &N, b: &N, disc: N) -> Option<[Self::Root; 2]>;
    /// max(r, x); x when they are equal.
    fn root_max(&self, r: Self::Root, x: &N) -> Self::Root;
    /// min(r, x); x when they are equal.
    fn root_min(&self, r: Self::Root, x: &N) -> Self::Root;
    /// a < b.
    fn root_lt(&self, a: &Self::Root, b: &Self::Root) -> Result<bool, Self::Abstain>;
    /// a ≤ b.
    fn root_le(&self, a: &Self::Root, b: &Self::Root) -> Result<bool, Self::Abstain>;
    /// a·r² + b·r + c < 0.
    fn quad_neg_at(&self, r: &Self::Root, a: &N, b: &N, c: &N) -> Result<bool, Self::Abstain>;
}

/// The answer of a kernel that never abstains.
pub trait Decided<T> {
    /// The decided value (there is no other case).
    fn decided(self) -> T;
}

impl<T> Decided<T> for Result<T, Infallible> {
    fn decided(self) -> T {
        match self {
            Ok(x) => x,
            Err(never) => match never {},
        }
    }
}

/// Kleene's "or": decided true when either side is, decided false when both are;
/// `b` is evaluated only when `a` is not decided true.
pub fn or<E>(a: Result<bool, E>, b: impl FnOnce() -> Result<bool, E>) -> Result<bool, E> {
    match a {
        Ok(true) => Ok(true),
        Ok(false) => b(),
        Err(e) => match b() {
            Ok(true) => Ok(true),
            _ => Err(e),
        },
    }
}

/// Kleene's "and": decided false when either side is, decided true when both are;
/// `b` is evaluated only when `a` is not decided false.
pub fn and<E>(a: Result<bool, E>, b: impl FnOnce() -> Result<bool, E>) -> Result<bool, E> {
    match a {
        Ok(false) => Ok(false),
        Ok(true) => b(),
        Err(e) => match b() {
            Ok(false) => Ok(false),
            _ => Err(e),
        },
    }
}

/// Kleene's "not".
pub fn not<E>(a: Result<bool, E>) -> Result<bool, E> {
    a.map(|x| !x)
}

/// Kleene's "or" over decisions taken in turn, up to the first decided true.
pub fn any<E>(xs: impl IntoIterator<Item = Result<bool, E>>) -> Result<bool, E> {
    let mut acc = Ok(false);
    for x in xs {
        match x {
            Ok(true) => return Ok(true),
            Ok(false) => {}
            Err(e) => acc = Err(e),
        }
    }
    acc
}

/// Kleene's "and" over decisions taken in turn, up to the first decided false.
pub fn all<E>(xs: impl IntoIterator<Item = Result<bool, E>>) -> Result<bool, E> {
    not(any(xs.into_iter().map(not)))
}

/// Kleene's "or" of several decisions, each evaluated only while none is decided true.
macro_rules! any_of {
    ($a:expr $(, $b:expr)+ $(,)?) => {{
        let acc = $a;
        $(let acc = $crate::kernel::or(acc, || $b);)+
        acc
    }};
}

/// Kleene's "and" of several decisions, each evaluated only while none is decided false.
macro_rules! all_of {
    ($a:expr $(, $b:expr)+ $(,)?) => {{
        let acc = $a;
        $(let acc = $crate::kernel::and(acc, || $b);)+
        acc
    }};
}

pub(crate) use {all_of, any_of};

/// Whether a decision came out true (an abstention counts as no: for shortcuts that
/// may only be taken when they are certain).
pub fn certainly<E>(x: Result<bool, E>) -> bool {
    matches!(x, Ok(true))
}

/// a = b for two vectors.
pub fn eq2<N: Arith, K: Kernel<N>>(
    k: &K,
    a: &crate::field::V2<N>,
    b: &crate::field::V2<N>,
) -> Result<bool, K::Abstain> {
    and(k.eq(&a.x, &b.x), || k.eq(&a.y, &b.y))
}

#[cfg(test)]
mod tests {
    use super::*;

    type D = Result<bool, ()>;
    const T: D = Ok(true);
    const F: D = Ok(false);
    const U: D = Err(());

    #[test]
    fn kleene_tables() {
        for (a, b, o, n) in [
            (T, T, T, T),
            (T, F, T, F),
            (T, U, T, U),
            (F, F, F, F),
            (F, U, U, F),
            (U, U, U, U),
            (U, T, T, U),
            (U, F, U, F),
        ] {
            assert_eq!(or(a, || b), o, "{a:?} or {b:?}");
            assert_eq!(and(a, || b), n, "{a:?} and {b:?}");
        }
        assert_eq!(any([F, U, T]), T);
        assert_eq!(any([F, U, F]), U);
        assert_eq!(all([T, U, F]), F);
        assert_eq!(all([T, U, T]), U);
        assert_eq!(all_of!(T, T, T), T);
        assert_eq!(any_of!(F, U, F), U);
    }

    #[test]
    fn short_circuits() {
        let mut evaluated = false;
        assert_eq!(
            or(T, || {
                evaluated = true;
                F
            }),
            T
        );
        assert!(!evaluated);
        assert_eq!(
            and(F, || {
                evaluated = true;
                T
            }),
            F
        );
        assert!(!evaluated);
    }
}
