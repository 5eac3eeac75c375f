//! The exact kernel: numbers of an [`ExactField`], roots as exact algebraic numbers
//! ([`Alg`]), every decision taken exactly (it never abstains).

use core::cmp::Ordering;
use core::convert::Infallible;
use std::borrow::Cow;

use super::Kernel;
use crate::field::ExactField;
use crate::qfield::Alg;

/// The exact kernel over any [`ExactField`] (see the [module doc](self)).
#[derive(Clone, Copy, Debug, Default)]
pub struct Exact;

impl<F: ExactField> Kernel<F> for Exact {
    type Root = Alg<F>;
    type Abstain = Infallible;

    fn lt(&self, a: &F, b: &F) -> Result<bool, Infallible> {
        Ok(a < b)
    }
    fn le(&self, a: &F, b: &F) -> Result<bool, Infallible> {
        Ok(a <= b)
    }
    fn eq(&self, a: &F, b: &F) -> Result<bool, Infallible> {
        Ok(a == b)
    }
    fn sign(&self, x: &F) -> Result<Ordering, Infallible> {
        Ok(x.sign())
    }
    fn is_zero(&self, x: &F) -> Result<bool, Infallible> {
        Ok(x.is_zero_())
    }
    fn is_pos(&self, x: &F) -> Result<bool, Infallible> {
        Ok(x.is_pos())
    }
    fn is_neg(&self, x: &F) -> Result<bool, Infallible> {
        Ok(x.is_neg())
    }

    fn abs(&self, x: &F) -> F {
        if x.is_neg() {
            x.negated()
        } else {
            x.clone()
        }
    }
    fn hull<'a>(&self, xs: &[&'a F]) -> (Cow<'a, F>, Cow<'a, F>) {
        let (mut lo, mut hi) = (xs[0], xs[0]);
        for &x in &xs[1..] {
            if x < lo {
                lo = x;
            } else if x > hi {
                hi = x;
            }
        }
        (Cow::Borrowed(lo), Cow::Borrowed(hi))
    }

    fn root(&self, x: &F) -> Alg<F> {
        Alg::rational(x.clone())
    }
    fn linear_root(&self, n: F, d: F) -> Option<Alg<F>> {
        Alg::new(n, F::zero(), F::zero(), d)
    }
    fn two_roots(&self, a: &F, b: &F, disc: F) -> Option<[Alg<F>; 2]> {
        crate::qfield::simple_roots(a, b, disc)
    }
    fn root_max(&self, r: Alg<F>, x: &F) -> Alg<F> {
        if r.cmp_rat(x) == Ordering::Greater {
            r
        } else {
            Alg::rational(x.clone())
        }
    }
    fn root_min(&self, r: Alg<F>, x: &F) -> Alg<F> {
        if r.cmp_rat(x) == Ordering::Less {
            r
        } else {
            Alg::rational(x.clone())
        }
    }
    fn root_lt(&self, a: &Alg<F>, b: &Alg<F>) -> Result<bool, Infallible> {
        Ok(a.cmp_alg(b) == Ordering::Less)
    }
    fn root_le(&self, a: &Alg<F>, b: &Alg<F>) -> Result<bool, Infallible> {
        Ok(a.cmp_alg(b) != Ordering::Greater)
    }
    fn quad_neg_at(&self, r: &Alg<F>, a: &F, b: &F, c: &F) -> Result<bool, Infallible> {
        Ok(r.quad_sign(a, b, c) == Ordering::Less)
    }
}
