//! Quadratic irrationals (p + q·√d)/r with rational p, q, d ≥ 0 and r > 0, and
//! their exact order by sign analysis (no square root is ever evaluated).
//!
//! The interval ends of dot_nn_lin (paper A §II.I) are roots of quadratics,
//! i.e. numbers of this form; edge_detect_simp only compares them.

use core::cmp::Ordering;

use crate::field::ExactField;

/// Paper A §II.I support: the sign of α + β·√d (d ≥ 0), exactly.
pub fn sign1<F: ExactField>(alpha: &F, beta: &F, d: &F) -> Ordering {
    let sa = alpha.sign();
    let sb = if d.is_zero_() {
        Ordering::Equal
    } else {
        beta.sign()
    };
    if sb == Ordering::Equal {
        return sa;
    }
    if sa == Ordering::Equal || sa == sb {
        return sb;
    }
    // Opposite signs: |α| vs |β|√d, compared through squares.
    let diff = alpha.sq().minus(&beta.sq().times(d));
    match diff.sign() {
        Ordering::Equal => Ordering::Equal,
        Ordering::Greater => sa,
        Ordering::Less => sb,
    }
}

/// Paper A §II.I support: the sign of α + β·√d1 + γ·√d2 (d1, d2 ≥ 0), exactly.
pub fn sign2<F: ExactField>(alpha: &F, beta: &F, d1: &F, gamma: &F, d2: &F) -> Ordering {
    if d1 == d2 {
        return sign1(alpha, &beta.plus(gamma), d1);
    }
    let su = sign1(alpha, beta, d1);
    let sw = if d2.is_zero_() {
        Ordering::Equal
    } else {
        gamma.sign()
    };
    if sw == Ordering::Equal {
        return su;
    }
    if su == Ordering::Equal || su == sw {
        return sw;
    }
    // u = α + β√d1 and w = γ√d2 have opposite signs: the sign of u + w is the
    // sign of the larger in magnitude, and u² − w² = (α² + β²d1 − γ²d2) + 2αβ√d1.
    let a2 = alpha
        .sq()
        .plus(&beta.sq().times(d1))
        .minus(&gamma.sq().times(d2));
    let b2 = alpha.times(beta).plus(&alpha.times(beta));
    match sign1(&a2, &b2, d1) {
        Ordering::Equal => Ordering::Equal,
        Ordering::Greater => su,
        Ordering::Less => sw,
    }
}

/// A real number (p + q·√d)/r with r > 0 and d ≥ 0 (q = 0 for a rational).
#[derive(Clone, Debug)]
pub struct Alg<F> {
    /// Rational part of the numerator.
    pub p: F,
    /// Coefficient of √d in the numerator.
    pub q: F,
    /// The radicand, ≥ 0.
    pub d: F,
    /// The denominator, > 0.
    pub r: F,
}

impl<F: ExactField> Alg<F> {
    /// The rational number x.
    pub fn rational(x: F) -> Self {
        Alg {
            p: x,
            q: F::zero(),
            d: F::zero(),
            r: F::one(),
        }
    }

    /// (p + q√d)/r for any nonzero r (normalised to r > 0); `None` if r = 0 or d < 0.
    pub fn new(p: F, q: F, d: F, r: F) -> Option<Self> {
        if d.is_neg() {
            return None;
        }
        match r.sign() {
            Ordering::Equal => None,
            Ordering::Greater => Some(Alg { p, q, d, r }),
            Ordering::Less => Some(Alg {
                p: p.negated(),
                q: q.negated(),
                d,
                r: r.negated(),
            }),
        }
    }

    /// Whether the number is written without a square root.
    pub fn is_rational(&self) -> bool {
        self.q.is_zero_() || self.d.is_zero_()
    }

    /// The sign of the number.
    pub fn sign(&self) -> Ordering {
        sign1(&self.p, &self.q, &self.d)
    }

    /// The exact order of two such numbers.
    pub fn cmp_alg(&self, o: &Self) -> Ordering {
        // sign(x − y) = sign(r2·p1 − r1·p2 + r2·q1·√d1 − r1·q2·√d2), as r1, r2 > 0.
        let x_rat = self.is_rational();
        let y_rat = o.is_rational();
        if x_rat && y_rat {
            return self.p.times(&o.r).cmp(&o.p.times(&self.r));
        }
        let alpha = self.p.times(&o.r).minus(&o.p.times(&self.r));
        if y_rat {
            return sign1(&alpha, &self.q.times(&o.r), &self.d);
        }
        if x_rat {
            return sign1(&alpha, &o.q.times(&self.r).negated(), &o.d);
        }
        sign2(
            &alpha,
            &self.q.times(&o.r),
            &self.d,
            &o.q.times(&self.r).negated(),
            &o.d,
        )
    }

    /// Compare with a rational number.
    pub fn cmp_rat(&self, x: &F) -> Ordering {
        if x.is_zero_() {
            return self.sign();
        }
        let alpha = self.p.minus(&x.times(&self.r));
        sign1(&alpha, &self.q, &self.d)
    }

    /// The number plus a rational shift t0.
    pub fn shifted(&self, t0: &F) -> Self {
        Alg {
            p: self.p.plus(&t0.times(&self.r)),
            q: self.q.clone(),
            d: self.d.clone(),
            r: self.r.clone(),
        }
    }

    /// The sign of the quadratic a·x² + b·x + c at this number x, exactly.
    pub fn quad_sign(&self, a: &F, b: &F, c: &F) -> Ordering {
        // With x = (p + q√d)/r: r²·(a x² + b x + c)
        //   = a(p² + q²d) + b·p·r + c·r² + (2a·p·q + b·q·r)·√d, and r² > 0.
        let (p, q, d, r) = (&self.p, &self.q, &self.d, &self.r);
        let rat = a
            .times(&p.sq().plus(&q.sq().times(d)))
            .plus(&b.times(p).times(r))
            .plus(&c.times(&r.sq()));
        let apq = a.times(p).times(q);
        let irr = apq.plus(&apq).plus(&b.times(q).times(r));
        sign1(&rat, &irr, d)
    }
}

/// The real roots of a·x² + b·x + c with a ≠ 0, in increasing order:
/// none (discriminant < 0), one double root, or two simple roots.
pub fn quad_roots<F: ExactField>(a: &F, b: &F, c: &F) -> Vec<Alg<F>> {
    let four = F::from_i64(4);
    let disc = b.sq().minus(&four.times(a).times(c));
    match disc.sign() {
        Ordering::Less => Vec::new(),
        Ordering::Equal => Alg::new(b.negated(), F::zero(), F::zero(), a.twice())
            .into_iter()
            .collect(),
        Ordering::Greater => simple_roots(a, b, disc).into_iter().flatten().collect(),
    }
}

/// The two roots (−b ∓ √disc)/(2a) of a·x² + b·x + c, in increasing order, from
/// disc = b² − 4ac > 0; `None` when a = 0.
pub fn simple_roots<F: ExactField>(a: &F, b: &F, disc: F) -> Option<[Alg<F>; 2]> {
    let lo_sign = if a.is_pos() { -1 } else { 1 };
    let two_a = a.twice();
    let mb = b.negated();
    let lo = Alg::new(
        mb.clone(),
        F::from_i64(lo_sign),
        disc.clone(),
        two_a.clone(),
    )?;
    let hi = Alg::new(mb, F::from_i64(-lo_sign), disc, two_a)?;
    Some([lo, hi])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Arith, Q};

    fn q(n: i64) -> Q {
        Q::from_i64(n)
    }

    #[test]
    fn sign1_cases() {
        // 3 − √9 = 0, 3 − √8 > 0, 3 − √10 < 0, −1 + √2 > 0.
        assert_eq!(sign1(&q(3), &q(-1), &q(9)), Ordering::Equal);
        assert_eq!(sign1(&q(3), &q(-1), &q(8)), Ordering::Greater);
        assert_eq!(sign1(&q(3), &q(-1), &q(10)), Ordering::Less);
        assert_eq!(sign1(&q(-1), &q(1), &q(2)), Ordering::Greater);
        assert_eq!(sign1(&q(0), &q(-5), &q(0)), Ordering::Equal);
    }

    #[test]
    fn sign2_cases() {
        // √2 + √3 − √(5 + 2√6) = 0 cannot be written here; use √2 − √3 < 0,
        // 1 + √2 − √3 > 0 (2.414 > 1.732), √8 − 2√2 = 0 (d1 ≠ d2 but equal values).
        assert_eq!(sign2(&q(0), &q(1), &q(2), &q(-1), &q(3)), Ordering::Less);
        assert_eq!(sign2(&q(1), &q(1), &q(2), &q(-1), &q(3)), Ordering::Greater);
        assert_eq!(sign2(&q(0), &q(1), &q(8), &q(-2), &q(2)), Ordering::Equal);
        // 5 − √2 − √3 > 0 (5 > 3.15), 3 − √2 − √3 < 0 (3 < 3.146).
        assert_eq!(
            sign2(&q(5), &q(-1), &q(2), &q(-1), &q(3)),
            Ordering::Greater
        );
        assert_eq!(sign2(&q(3), &q(-1), &q(2), &q(-1), &q(3)), Ordering::Less);
    }

    #[test]
    fn roots_ordered() {
        // x² − 3x + 2 = (x − 1)(x − 2); −x² + 3x − 2 has the same roots.
        for s in [1, -1] {
            let r = quad_roots(&q(s), &q(-3 * s), &q(2 * s));
            assert_eq!(r.len(), 2);
            assert_eq!(r[0].cmp_rat(&q(1)), Ordering::Equal);
            assert_eq!(r[1].cmp_rat(&q(2)), Ordering::Equal);
        }
        // x² − 2x + 1: double root 1 (discriminant exactly 0).
        let r = quad_roots(&q(1), &q(-2), &q(1));
        assert_eq!(r.len(), 1);
        assert_eq!(r[0].cmp_rat(&q(1)), Ordering::Equal);
        assert!(quad_roots(&q(1), &q(0), &q(1)).is_empty());
    }
}
