//! Towers of square roots: the numbers Q(√b₀)(√b₁)…(√b_{K−1}), each radicand b_k ≥ 0 an
//! element of the levels below it, with exact signs (no square root is evaluated).
//!
//! Where a recovery point lies (paper A §II's polygon grown or shrunk by D: shifted edges
//! at distance D, circles of radius D about vertices, and where two of them meet) is a
//! point whose coordinates need one or two nested square roots: the length of an edge
//! (√|e|²) and the discriminant of a quadratic whose coefficients already hold one.
//! [`qfield`](crate::qfield) orders numbers with one root over Q; this module takes the
//! same sign analysis up a tower of them.
//!
//! An element of level k is a vector of 2^k rationals: its first half u and second half
//! w (each of level k − 1) stand for u + w·√b_{k−1}. The sign of u + w·√b: if u and w
//! (w·√b read as 0 when b = 0) have the same sign or one is 0, that sign; otherwise the
//! sign of the larger in magnitude, told by the sign of u² − w²·b (a level k − 1 number).
//!
//! In front of that analysis stands an interval filter (the house pattern of
//! [`crate::kernel::interval`]): each root keeps a rigorous enclosure of √b_k, an element
//! is enclosed level by level as enclose(u) + enclose(w)·enclose(√b), and a sign is read
//! off the enclosure when it excludes 0. Only when it does not does the exact analysis
//! run, so every sign is still exact; [`Tower::unfiltered`] turns the filter off, and the
//! tests check that both give the same signs.

use core::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::kernel::interval::{enclose, Iv};

/// A tower of square roots: the radicands b_0 … b_{K−1} (b_k of level k, ≥ 0).
#[derive(Clone, Debug)]
pub struct Tower {
    rads: Vec<Elem>,
    /// Rigorous enclosures of √b_0 … √b_{K−1}.
    roots: Vec<Iv>,
    /// Signs are first read off enclosures (module doc).
    filter: bool,
}

impl Default for Tower {
    fn default() -> Tower {
        Tower::new()
    }
}

/// An element of a tower, as 2^k rational coefficients (k its level).
#[derive(Clone, Debug, PartialEq)]
pub struct Elem(pub Vec<BigRational>);

impl Elem {
    /// The rational x, at level 0.
    pub fn rat(x: BigRational) -> Elem {
        Elem(vec![x])
    }

    /// The level (log₂ of the length).
    pub fn level(&self) -> usize {
        self.0.len().trailing_zeros() as usize
    }

    /// The same number at level k ≥ its own (zeros for the higher roots).
    pub fn lift(&self, k: usize) -> Elem {
        let mut c = self.0.clone();
        c.resize(1 << k, BigRational::zero());
        Elem(c)
    }

    /// self · x for a rational x.
    pub fn scale(&self, x: &BigRational) -> Elem {
        Elem(self.0.iter().map(|c| c * x).collect())
    }
}

impl Tower {
    /// The empty tower: the rationals, with the interval filter in front of every sign.
    pub fn new() -> Tower {
        Tower {
            rads: Vec::new(),
            roots: Vec::new(),
            filter: true,
        }
    }

    /// The empty tower without the interval filter: every sign by the exact analysis
    /// alone (the reference the filter is tested against).
    pub fn unfiltered() -> Tower {
        Tower {
            filter: false,
            ..Tower::new()
        }
    }

    /// Whether signs are first read off enclosures.
    pub fn filtered(&self) -> bool {
        self.filter
    }

    /// A rigorous enclosure of a: enclose(u) + enclose(w)·enclose(√b) level by level
    /// (the ends of each operation rounded outward).
    pub fn enclose(&self, a: &Elem) -> Iv {
        let a = self.top(a);
        self.enclose_at(a.level(), &a.0)
    }

    fn enclose_at(&self, k: usize, a: &[BigRational]) -> Iv {
        if k == 0 {
            return enclose(&a[0]);
        }
        let h = 1 << (k - 1);
        let (u, w) = a.split_at(h);
        let wi = self.enclose_at(k - 1, w);
        if wi == Iv::ZERO {
            return self.enclose_at(k - 1, u);
        }
        self.enclose_at(k - 1, u).add(wi.mul(self.roots[k - 1]))
    }

    /// The number of roots adjoined.
    pub fn height(&self) -> usize {
        self.rads.len()
    }

    /// Adjoins √b for b ≥ 0 in this tower; `None` when b < 0. Returns the element √b.
    pub fn adjoin(&mut self, b: &Elem) -> Option<Elem> {
        let k = self.height();
        let b = b.lift(k);
        if self.sign(&b) == Ordering::Less {
            return None;
        }
        self.roots.push(self.enclose(&b).sqrt());
        self.rads.push(b);
        let mut c = vec![BigRational::zero(); 1 << (k + 1)];
        c[1 << k] = BigRational::from_integer(1.into());
        Some(Elem(c))
    }

    /// x at the tower's top level.
    pub fn top(&self, x: &Elem) -> Elem {
        x.lift(self.height().max(x.level()))
    }

    /// The rational x at the top level.
    pub fn rat(&self, x: &BigRational) -> Elem {
        Elem::rat(x.clone()).lift(self.height())
    }

    /// a + b.
    pub fn add(&self, a: &Elem, b: &Elem) -> Elem {
        let (a, b) = (self.top(a), self.top(b));
        Elem(a.0.iter().zip(&b.0).map(|(x, y)| x + y).collect())
    }

    /// a − b.
    pub fn sub(&self, a: &Elem, b: &Elem) -> Elem {
        let (a, b) = (self.top(a), self.top(b));
        Elem(a.0.iter().zip(&b.0).map(|(x, y)| x - y).collect())
    }

    /// a · b.
    pub fn mul(&self, a: &Elem, b: &Elem) -> Elem {
        let k = self.height();
        Elem(self.mul_at(k, &self.top(a).0, &self.top(b).0))
    }

    /// a².
    pub fn sq(&self, a: &Elem) -> Elem {
        self.mul(a, a)
    }

    fn mul_at(&self, k: usize, a: &[BigRational], b: &[BigRational]) -> Vec<BigRational> {
        if k == 0 {
            return vec![&a[0] * &b[0]];
        }
        let h = 1 << (k - 1);
        let (u1, w1) = a.split_at(h);
        let (u2, w2) = b.split_at(h);
        let rad = &self.rads[k - 1].0[..h];
        let ww = self.mul_at(k - 1, w1, w2);
        let lo = add_v(&self.mul_at(k - 1, u1, u2), &self.mul_at(k - 1, &ww, rad));
        let hi = add_v(&self.mul_at(k - 1, u1, w2), &self.mul_at(k - 1, w1, u2));
        let mut out = lo;
        out.extend(hi);
        out
    }

    /// The exact sign of a.
    pub fn sign(&self, a: &Elem) -> Ordering {
        let a = self.top(a);
        if self.filter {
            if let Ok(o) = self.enclose_at(a.level(), &a.0).sign() {
                return o;
            }
        }
        self.sign_at(a.level(), &a.0)
    }

    fn sign_at(&self, k: usize, a: &[BigRational]) -> Ordering {
        if k == 0 {
            return sign_q(&a[0]);
        }
        let h = 1 << (k - 1);
        let (u, w) = a.split_at(h);
        let rad = &self.rads[k - 1].0[..h];
        let su = self.sign_at(k - 1, u);
        let sw = if self.sign_at(k - 1, rad) == Ordering::Equal {
            Ordering::Equal
        } else {
            self.sign_at(k - 1, w)
        };
        if sw == Ordering::Equal {
            return su;
        }
        if su == Ordering::Equal || su == sw {
            return sw;
        }
        let uu = self.mul_at(k - 1, u, u);
        let ww = self.mul_at(k - 1, w, w);
        let wwb = self.mul_at(k - 1, &ww, rad);
        let diff: Vec<BigRational> = uu.iter().zip(&wwb).map(|(x, y)| x - y).collect();
        match self.sign_at(k - 1, &diff) {
            Ordering::Equal => Ordering::Equal,
            Ordering::Greater => su,
            Ordering::Less => sw,
        }
    }

    /// a written exactly: rationals `p/q` (`p` when q = 1), a level above as
    /// `u + (w)·√(b)` with u, w and b written the same way, a zero coefficient left out.
    pub fn text(&self, a: &Elem) -> String {
        let a = self.top(a);
        self.text_at(a.level(), &a.0)
    }

    /// √a written exactly (a ≥ 0): the rational root when a is the square of a
    /// rational, else `√(…)` around [`Tower::text`].
    pub fn sqrt_text(&self, a: &Elem) -> String {
        let a = self.top(a);
        let inner = self.text(&a);
        match inner
            .parse::<BigRational>()
            .ok()
            .and_then(|x| rational_sqrt(&x))
        {
            Some(r) => r.to_string(),
            None => format!("√({inner})"),
        }
    }

    fn text_at(&self, k: usize, a: &[BigRational]) -> String {
        if k == 0 {
            return a[0].to_string();
        }
        let h = 1 << (k - 1);
        let (u, w) = a.split_at(h);
        let zero = |x: &[BigRational]| x.iter().all(Zero::is_zero);
        if zero(w) {
            return self.text_at(k - 1, u);
        }
        // a rational radicand that is a square: u + w·r, one level down
        let rad = &self.rads[k - 1].0[..h];
        if zero(&rad[1..]) {
            if let Some(r) = rational_sqrt(&rad[0]) {
                let folded: Vec<BigRational> = u.iter().zip(w).map(|(x, y)| x + y * &r).collect();
                return self.text_at(k - 1, &folded);
            }
        }
        let root = format!(
            "({})·√({})",
            self.text_at(k - 1, w),
            self.text_at(k - 1, &self.rads[k - 1].0[..h])
        );
        if zero(u) {
            root
        } else {
            format!("{} + {root}", self.text_at(k - 1, u))
        }
    }

    /// The radicand b_k (an element of level k).
    pub fn radicand(&self, k: usize) -> &Elem {
        &self.rads[k]
    }
}

/// √x when the rational x ≥ 0 is the square of a rational (numerator and denominator,
/// in lowest terms, both squares).
fn rational_sqrt(x: &BigRational) -> Option<BigRational> {
    if x.is_negative() {
        return None;
    }
    let root = |n: &num_bigint::BigInt| {
        let s = num_integer::Roots::sqrt(n);
        (&s * &s == *n).then_some(s)
    };
    Some(BigRational::new(root(x.numer())?, root(x.denom())?))
}

fn add_v(a: &[BigRational], b: &[BigRational]) -> Vec<BigRational> {
    a.iter().zip(b).map(|(x, y)| x + y).collect()
}

/// The sign of a rational.
pub fn sign_q(x: &BigRational) -> Ordering {
    if x.is_zero() {
        Ordering::Equal
    } else if x.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    #[test]
    fn nested_roots_have_exact_signs() {
        // √2 + √3 vs √(5 + 2√6) (equal): tower Q(√6)(√(5 + 2√6)).
        let mut t = Tower::new();
        let r6 = t.adjoin(&Elem::rat(q(6))).unwrap();
        let b = t.add(&t.rat(&q(5)), &t.mul(&t.rat(&q(2)), &r6));
        let r = t.adjoin(&b).unwrap();
        // r² − (5 + 2√6) = 0.
        assert_eq!(t.sign(&t.sub(&t.sq(&r), &b)), Ordering::Equal);
        // r − 3.147 < 0 < r − 3.14 (√2 + √3 = 3.1462…).
        let frac = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        assert_eq!(
            t.sign(&t.sub(&r, &t.rat(&frac(3147, 1000)))),
            Ordering::Less
        );
        assert_eq!(
            t.sign(&t.sub(&r, &t.rat(&frac(314, 100)))),
            Ordering::Greater
        );
        // A negative radicand is refused.
        assert!(t.clone().adjoin(&t.sub(&r6, &t.rat(&q(3)))).is_none());
    }
}

#[cfg(test)]
mod text_tests {
    use super::*;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// The exact text of tower numbers: rationals as p/q, roots nested, square
    /// radicands folded, zero parts left out.
    #[test]
    fn tower_numbers_are_written_exactly() {
        let mut tw = Tower::new();
        let two = tw.adjoin(&Elem::rat(r(2, 1))).expect("2 ≥ 0");
        let x = tw.add(&tw.rat(&r(1, 3)), &tw.mul(&two, &tw.rat(&r(-5, 2))));
        assert_eq!(tw.text(&x), "1/3 + (-5/2)·√(2)");
        assert_eq!(tw.text(&two), "(1)·√(2)");
        assert_eq!(tw.sqrt_text(&tw.rat(&r(9, 4))), "3/2");
        assert_eq!(tw.sqrt_text(&tw.rat(&r(8, 1))), "√(8)");
        let mut sq = Tower::new();
        let four = sq.adjoin(&Elem::rat(r(400, 1))).expect("400 ≥ 0");
        let y = sq.sub(&sq.rat(&r(29, 1)), &four);
        assert_eq!(sq.text(&y), "9");
        assert_eq!(sq.sqrt_text(&y), "3");
    }
}
