//! Real algebraic numbers: the exact ends of the sets of times a relation holds.
//!
//! Where a point meets, or comes within D of, a moving edge is a root of a polynomial in
//! t: the edge quadratics of paper A §II.C (the distance of a point to a segment), of
//! degree 2 for a statically shaped polygon and, squared against the moving edge's
//! length, of degree 4 for a warping one (§II.I); the slab of §III adds linear ones. A
//! [`RealAlg`] holds such a root exactly: an integer polynomial ([`Poly`]) and an
//! isolating interval with rational ends, or the rational number itself.
//!
//! Everything here is exact (integers and rationals; no square root is taken). The
//! rigorous float enclosure of a [`RealAlg`] (`to_f64_bounds`) lives with the other float
//! code in [`crate::kernel::interval`].
//!
//! Polynomials are over Q, kept as primitive integer polynomials: a result "over Q" is
//! returned as a positive rational multiple of itself, made primitive, which has the
//! same roots and the same signs. Roots are counted with Sturm sequences (the number of
//! distinct roots of a squarefree p in (a, b] is V(a) − V(b), V the sign variations of
//! the sequence), isolated by bisection, refined by bisection, and compared by refining
//! until the isolating intervals are disjoint, or by the greatest common divisor when
//! they share a root.

use core::cmp::Ordering;
use core::fmt;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::time::ExactTime;

/// A polynomial in t with integer coefficients, lowest degree first, without
/// trailing zero coefficients (the zero polynomial has none). Arithmetic "over Q"
/// returns primitive positive multiples (see the module doc).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Poly {
    c: Vec<BigInt>,
}

/// The sign of an integer as an order relative to 0 (every sign test of this module).
fn sign_of(x: &BigInt) -> Ordering {
    match x.sign() {
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
        Sign::Plus => Ordering::Greater,
    }
}

impl Poly {
    /// The polynomial Σ c_k·t^k (trailing zeros dropped).
    pub fn new(mut c: Vec<BigInt>) -> Self {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        Poly { c }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { c: Vec::new() }
    }

    /// The primitive integer polynomial that is a positive multiple of Σ c_k·t^k with
    /// rational coefficients (the denominators cleared, the content divided out).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn from_rationals(c: &[BigRational]) -> Self {
        let den = c.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
        let ints = c.iter().map(|x| x.numer() * (&den / x.denom())).collect();
        Poly::new(ints).primitive()
    }

    /// The polynomial with small integer coefficients, lowest degree first.
    pub fn from_i64s(c: &[i64]) -> Self {
        Poly::new(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    /// The coefficients, lowest degree first (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[BigInt] {
        &self.c
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// The leading coefficient (`None` for the zero polynomial).
    pub fn lead(&self) -> Option<&BigInt> {
        self.c.last()
    }

    /// self + o.
    pub fn add(&self, o: &Poly) -> Poly {
        let n = self.c.len().max(o.c.len());
        let zero = BigInt::zero();
        Poly::new(
            (0..n)
                .map(|k| self.c.get(k).unwrap_or(&zero) + o.c.get(k).unwrap_or(&zero))
                .collect(),
        )
    }

    /// −self.
    pub fn neg(&self) -> Poly {
        Poly {
            c: self.c.iter().map(|x| -x).collect(),
        }
    }

    /// self − o.
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.neg())
    }

    /// self · o.
    pub fn mul(&self, o: &Poly) -> Poly {
        if self.is_zero() || o.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![BigInt::zero(); self.c.len() + o.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            for (j, b) in o.c.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        Poly::new(c)
    }

    /// k · self.
    pub fn scale(&self, k: &BigInt) -> Poly {
        Poly::new(self.c.iter().map(|x| x * k).collect())
    }

    /// The derivative d/dt.
    pub fn derivative(&self) -> Poly {
        Poly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, x)| x * BigInt::from(k))
                .collect(),
        )
    }

    /// The gcd of the coefficients (0 for the zero polynomial), ≥ 0.
    pub fn content(&self) -> BigInt {
        let mut acc = BigInt::zero();
        for x in &self.c {
            acc = acc.gcd(x);
            if acc.is_one() {
                break;
            }
        }
        acc
    }

    /// self divided by its content: the primitive positive multiple.
    pub fn primitive(&self) -> Poly {
        let g = self.content();
        if g.is_zero() || g.is_one() {
            return self.clone();
        }
        Poly {
            c: self.c.iter().map(|x| x / &g).collect(),
        }
    }

    /// self divided by the largest power of two dividing every coefficient: a positive
    /// multiple found by shifts alone (inputs made of binary floats share large powers
    /// of two, and a full gcd of the coefficients costs far more).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn without_common_twos(&self) -> Poly {
        let k = self
            .c
            .iter()
            .filter_map(BigInt::trailing_zeros)
            .min()
            .unwrap_or(0);
        if k == 0 {
            return self.clone();
        }
        Poly {
            c: self.c.iter().map(|x| x >> k).collect(),
        }
    }

    /// The primitive multiple with a positive leading coefficient (a sign may change:
    /// the normal form of a gcd).
    fn normalized(&self) -> Poly {
        let p = self.primitive();
        if p.lead().is_some_and(Signed::is_negative) {
            p.neg()
        } else {
            p
        }
    }

    /// Pseudo-division by d ≠ 0: (q, r) with |lc(d)|^m · self = q·d + r and
    /// deg r < deg d; the factor is positive, so q and r are positive multiples of the
    /// quotient and the remainder over Q.
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    fn pseudo_div(&self, d: &Poly) -> (Poly, Poly) {
        let (Some(dd), Some(lc)) = (d.degree(), d.lead()) else {
            return (Poly::zero(), self.clone());
        };
        let (alc, slc) = (lc.abs(), sign_of(lc));
        let mut r = self.clone();
        let mut q = Poly::zero();
        while let Some(dr) = r.degree().filter(|&dr| dr >= dd) {
            let shift = dr - dd;
            let lr = r.c[dr].clone();
            let f = if slc == Ordering::Less { -lr } else { lr };
            let mut term = vec![BigInt::zero(); shift + 1];
            term[shift] = f;
            let term = Poly::new(term);
            r = r.scale(&alc).sub(&term.mul(d));
            q = q.scale(&alc).add(&term);
        }
        (q, r)
    }

    /// The remainder of self by d ≠ 0 over Q, as a primitive positive multiple (the
    /// Sturm sequence keeps its signs).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn rem(&self, d: &Poly) -> Poly {
        self.pseudo_div(d).1.primitive()
    }

    /// self / d over Q when d divides self (a primitive positive multiple of the
    /// quotient), `None` otherwise or when d = 0.
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn div_exact(&self, d: &Poly) -> Option<Poly> {
        if d.is_zero() {
            return None;
        }
        let (q, r) = self.pseudo_div(d);
        r.is_zero().then(|| q.primitive())
    }

    /// The greatest common divisor over Q, primitive with a positive leading
    /// coefficient (0 when both are 0).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn gcd(&self, o: &Poly) -> Poly {
        let (mut a, mut b) = (self.normalized(), o.normalized());
        while !b.is_zero() {
            let r = a.rem(&b);
            a = b;
            b = r;
        }
        a.normalized()
    }

    /// The squarefree part self / gcd(self, self′): the same roots, each simple
    /// (a primitive multiple; its sign may differ from self's).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn squarefree(&self) -> Poly {
        if self.degree().unwrap_or(0) <= 1 {
            return self.primitive();
        }
        let g = self.gcd(&self.derivative());
        if g.degree().unwrap_or(0) == 0 {
            return self.primitive();
        }
        self.div_exact(&g).unwrap_or_else(|| self.primitive())
    }

    /// A positive multiple of self(x + s) as a polynomial in s (a Taylor shift by the
    /// rational x = a/b): b^n·self(a/b + s) = P̃(a + b·s) with P̃(y) = b^n·self(y/b), an
    /// integer polynomial shifted by the integer a, then scaled.
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn shifted(&self, x: &BigRational) -> Poly {
        let Some(n) = self.degree() else {
            return Poly::zero();
        };
        let (a, b) = (x.numer(), x.denom());
        // P̃'s coefficients c_k·b^(n−k).
        let mut q: Vec<BigInt> = Vec::with_capacity(n + 1);
        let mut bp = BigInt::one();
        for k in (0..=n).rev() {
            q.push(&self.c[k] * &bp);
            bp *= b;
        }
        q.reverse();
        // Taylor shift by a (repeated synthetic division).
        for i in 0..n {
            for j in (i..n).rev() {
                let t = &q[j + 1] * a;
                q[j] += t;
            }
        }
        // y = a + b·s: coefficient k times b^k.
        let mut bp = BigInt::one();
        for c in q.iter_mut().skip(1) {
            bp *= b;
            *c *= &bp;
        }
        Poly::new(q).without_common_twos()
    }

    /// The exact value at a rational x.
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn eval(&self, x: &BigRational) -> BigRational {
        self.c.iter().rev().fold(BigRational::zero(), |acc, c| {
            acc * x + BigRational::from_integer(c.clone())
        })
    }

    /// The sign of self at a rational x = num/den, from the integer
    /// den^n · self(x) = Σ c_k · num^k · den^(n−k) (den > 0).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn sign_at(&self, x: &BigRational) -> Ordering {
        let Some(n) = self.degree() else {
            return Ordering::Equal;
        };
        let (num, den) = (x.numer(), x.denom());
        let mut acc = self.c[n].clone();
        let mut dpow = BigInt::one();
        for k in (0..n).rev() {
            dpow *= den;
            acc = acc * num + &self.c[k] * &dpow;
        }
        sign_of(&acc)
    }

    /// The Sturm sequence of a squarefree polynomial: p, p′, then the negated
    /// remainders (primitive positive multiples of them, which keep every sign).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn sturm(&self) -> Sturm {
        let mut seq = vec![self.clone()];
        let d = self.derivative();
        if !d.is_zero() {
            seq.push(d.primitive());
            loop {
                let n = seq.len();
                if seq[n - 1].degree().unwrap_or(0) == 0 {
                    break;
                }
                let r = seq[n - 2].rem(&seq[n - 1]);
                if r.is_zero() {
                    break;
                }
                seq.push(r.neg());
            }
        }
        Sturm { seq }
    }

    /// The distinct real roots of self (not the zero polynomial) in the closed interval
    /// [lo, hi], increasing: rational ones as rationals, the others with an isolating
    /// interval of self's squarefree part. Empty for the zero polynomial.
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn roots_in(&self, lo: &BigRational, hi: &BigRational) -> Vec<RealAlg> {
        let mut out = Vec::new();
        if self.is_zero() || lo > hi {
            return out;
        }
        if self.degree() == Some(2) {
            return quadratic_roots_in(self, lo, hi);
        }
        let sf = self.squarefree();
        match sf.degree() {
            None | Some(0) => return out,
            Some(1) => {
                let r = BigRational::new(-sf.c[0].clone(), sf.c[1].clone());
                if &r >= lo && &r <= hi {
                    out.push(RealAlg::rational(r));
                }
                return out;
            }
            Some(_) => {}
        }
        let st = sf.sturm();
        if sf.sign_at(lo) == Ordering::Equal {
            out.push(RealAlg::rational(lo.clone()));
        }
        let n = st.count(lo, hi);
        isolate(&sf, &st, lo.clone(), hi.clone(), n, &mut out);
        out
    }
}

/// The distinct roots of a quadratic p = c + b·t + a·t² (a ≠ 0) in [lo, hi], by its
/// exact discriminant: none, a double root −b/2a, two rational roots when it is a
/// perfect square, else one on each side of the vertex −b/2a, where p is monotone, so
/// that a sign change between the window's end and the vertex isolates it.
/// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
fn quadratic_roots_in(p: &Poly, lo: &BigRational, hi: &BigRational) -> Vec<RealAlg> {
    let (c, b, a) = (&p.c[0], &p.c[1], &p.c[2]);
    let disc = b * b - BigInt::from(4) * a * c;
    let two_a = a * BigInt::from(2);
    let inside = |r: &BigRational| r >= lo && r <= hi;
    let rational = |num: BigInt| {
        let r = BigRational::new(num, two_a.clone());
        inside(&r).then(|| RealAlg::rational(r))
    };
    match sign_of(&disc) {
        Ordering::Less => return Vec::new(),
        Ordering::Equal => return rational(-b).into_iter().collect(),
        Ordering::Greater => {}
    }
    if let Some(s) = exact_sqrt(&disc) {
        let mut r: Vec<RealAlg> = [rational(-b - &s), rational(-b + &s)]
            .into_iter()
            .flatten()
            .collect();
        r.sort();
        return r;
    }
    // Irrational roots: neither is a rational end, so signs there are nonzero.
    let v = BigRational::new(-b.clone(), two_a.clone());
    let mut out = Vec::new();
    let mut side = |from: &BigRational, to: &BigRational| {
        if from >= to {
            return;
        }
        let (sf, st) = (p.sign_at(from), p.sign_at(to));
        if sf != st && sf != Ordering::Equal && st != Ordering::Equal {
            out.push(RealAlg(Repr::Root(Root {
                p: p.clone(),
                lo: from.clone(),
                hi: to.clone(),
                lo_sign: sf,
            })));
        }
    };
    // Left of the vertex, then right of it.
    side(lo, if &v < hi { &v } else { hi });
    side(if &v > lo { &v } else { lo }, hi);
    out
}

/// The n roots of the squarefree sf in (a, b], isolated by bisection and appended in
/// increasing order (Sturm counts on each half).
/// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
fn isolate(
    sf: &Poly,
    st: &Sturm,
    a: BigRational,
    b: BigRational,
    n: usize,
    out: &mut Vec<RealAlg>,
) {
    if n == 0 {
        return;
    }
    if n == 1 {
        if sf.sign_at(&b) == Ordering::Equal {
            out.push(RealAlg::rational(b));
            return;
        }
        let sa = sf.sign_at(&a);
        if sa != Ordering::Equal {
            out.push(RealAlg(Repr::Root(Root {
                p: sf.clone(),
                lo: a,
                hi: b,
                lo_sign: sa,
            })));
            return;
        }
        // a is a root of sf (counted in the piece before): move the left end right
        // until it is not, keeping the one root of (a, b].
    }
    let m = midpoint(&a, &b);
    let left = st.count(&a, &m);
    isolate(sf, st, a, m.clone(), left, out);
    isolate(sf, st, m, b, n - left, out);
}

/// A Sturm sequence (of a squarefree polynomial): [`Sturm::count`] counts its
/// distinct real roots in a half-open interval.
#[derive(Clone, Debug)]
pub struct Sturm {
    seq: Vec<Poly>,
}

impl Sturm {
    /// The number of sign changes of the sequence at x, zeros skipped.
    fn variations(&self, x: &BigRational) -> usize {
        let mut last = Ordering::Equal;
        let mut v = 0;
        for p in &self.seq {
            let s = p.sign_at(x);
            if s == Ordering::Equal {
                continue;
            }
            if last != Ordering::Equal && s != last {
                v += 1;
            }
            last = s;
        }
        v
    }

    /// The number of distinct real roots in (a, b] (0 when a ≥ b): V(a) − V(b).
    /// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
    pub fn count(&self, a: &BigRational, b: &BigRational) -> usize {
        if a >= b {
            return 0;
        }
        self.variations(a).saturating_sub(self.variations(b))
    }
}

/// One term c·t^k of a polynomial's text, with its sign (" − " or " + " between
/// terms, a leading "−" for the first). (How [`RealAlg::exact_text`] prints paper
/// A §II.C/§II.I's polynomials.)
fn fmt_coeff_term(out: &mut String, c: &BigInt, k: usize, first: bool) {
    let neg = c.is_negative();
    let a = c.abs();
    if first {
        if neg {
            out.push('−');
        }
    } else {
        out.push_str(if neg { " − " } else { " + " });
    }
    if !a.is_one() || k == 0 {
        out.push_str(&a.to_string());
    }
    match k {
        0 => {}
        1 => out.push('t'),
        _ => {
            out.push_str("t^");
            out.push_str(&k.to_string());
        }
    }
}

impl fmt::Display for Poly {
    /// Highest degree first, in t: "3t^4 − 2t + 1".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        let mut out = String::new();
        for (k, c) in self.c.iter().enumerate().rev() {
            if c.is_zero() {
                continue;
            }
            let first = out.is_empty();
            fmt_coeff_term(&mut out, c, k, first);
        }
        f.write_str(&out)
    }
}

/// A real algebraic number: an exact rational, or the one root of an integer
/// polynomial p in an open interval (lo, hi) with rational ends, where p changes sign
/// (p(lo), p(hi) ≠ 0 of opposite signs; the root is simple). The polynomials this
/// module builds ([`Poly::roots_in`], [`RealAlg::isolated`]) are squarefree; a caller
/// that certified a simple root by other means (the oracle's float filter) may keep a
/// polynomial that is squarefree only near it, and [`RealAlg::exact_text`] prints the
/// squarefree part.
///
/// Comparisons are exact ([`Ord`]); refinement narrows the interval by bisection.
#[derive(Clone, Debug)]
pub struct RealAlg(Repr);

#[derive(Clone, Debug)]
enum Repr {
    Rational(BigRational),
    Root(Root),
}

#[derive(Clone, Debug)]
struct Root {
    p: Poly,
    lo: BigRational,
    hi: BigRational,
    /// The sign of p at lo (never Equal).
    lo_sign: Ordering,
}

/// √n when the integer n ≥ 0 is a perfect square (squares have few residues modulo
/// 64 and 63·65·11: most non-squares are rejected before the root is taken).
/// (The ends of paper A §II.C's and §II.I's sets of times are roots of such polynomials.)
fn exact_sqrt(n: &BigInt) -> Option<BigInt> {
    if n.is_negative() {
        return None;
    }
    let low = n.iter_u64_digits().next().unwrap_or(0);
    if (0x0202_0212_0203_0213u64 >> (low & 63)) & 1 == 0 {
        return None;
    }
    let r = (n % BigInt::from(45045u32)).to_u32().unwrap_or(0);
    if ![5u32, 7, 9, 11, 13].iter().all(|&m| {
        let x = r % m;
        (0..m).any(|y| y * y % m == x)
    }) {
        return None;
    }
    let s = n.sqrt();
    (&s * &s == *n).then_some(s)
}

impl RealAlg {
    /// The rational number x.
    pub fn rational(x: BigRational) -> Self {
        RealAlg(Repr::Rational(x))
    }

    /// The integer n.
    pub fn from_i64(n: i64) -> Self {
        RealAlg::rational(BigRational::from_integer(BigInt::from(n)))
    }

    /// The number plus the rational c: a rational moves by c; a root of p in (lo, hi)
    /// becomes the root of p(t − c) ([`Poly::shifted`] by −c, a positive multiple, so
    /// the sign at the lower end is kept) in (lo + c, hi + c).
    /// (The exact truth of moving features: a piece's times moved to global time.)
    pub fn shifted_by(&self, c: &BigRational) -> RealAlg {
        match &self.0 {
            Repr::Rational(x) => RealAlg::rational(x + c),
            Repr::Root(r) => RealAlg(Repr::Root(Root {
                p: r.p.shifted(&-c),
                lo: &r.lo + c,
                hi: &r.hi + c,
                lo_sign: r.lo_sign,
            })),
        }
    }

    /// The one root of p in (lo, hi), checked exactly: `None` unless p(lo) and p(hi)
    /// have opposite signs and p's squarefree part has exactly one root there. A root
    /// of a linear or quadratic p that is rational comes back as a rational.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn isolated(p: &Poly, lo: BigRational, hi: BigRational) -> Option<Self> {
        let (sl, sh) = (p.sign_at(&lo), p.sign_at(&hi));
        if lo >= hi || sl == Ordering::Equal || sh == Ordering::Equal || sl == sh {
            return None;
        }
        let sf = p.squarefree();
        if sf.sturm().count(&lo, &hi) != 1 {
            return None;
        }
        let s = sf.sign_at(&lo);
        Some(RealAlg::certified(sf, lo, hi, s))
    }

    /// The one root of p in (lo, hi) when the caller has proved that p(lo) has the
    /// sign `lo_sign` (not Equal), p(hi) the opposite one, and that p has exactly one
    /// root there (then simple). A linear or quadratic p with a rational root gives the
    /// rational. (Debug builds check the claim.)
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub(crate) fn certified(p: Poly, lo: BigRational, hi: BigRational, lo_sign: Ordering) -> Self {
        debug_assert!(lo < hi && lo_sign != Ordering::Equal);
        debug_assert_eq!(p.sign_at(&lo), lo_sign);
        debug_assert_eq!(p.sign_at(&hi), lo_sign.reverse());
        match p.degree() {
            Some(1) => return RealAlg::rational(BigRational::new(-p.c[0].clone(), p.c[1].clone())),
            Some(2) => {
                let (c, b, a) = (&p.c[0], &p.c[1], &p.c[2]);
                let disc = b * b - BigInt::from(4) * a * c;
                if let Some(s) = exact_sqrt(&disc) {
                    let two_a = a * BigInt::from(2);
                    for r in [
                        BigRational::new(-b - &s, two_a.clone()),
                        BigRational::new(-b + &s, two_a),
                    ] {
                        if r > lo && r < hi {
                            return RealAlg::rational(r);
                        }
                    }
                }
            }
            _ => {}
        }
        RealAlg(Repr::Root(Root { p, lo, hi, lo_sign }))
    }

    /// The distinct real roots of p in [lo, hi], increasing ([`Poly::roots_in`]).
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn roots_of(p: &Poly, lo: &BigRational, hi: &BigRational) -> Vec<RealAlg> {
        p.roots_in(lo, hi)
    }

    /// Whether the number is held as a rational (a root of a polynomial of degree ≥ 3
    /// may be rational and still be held as a root: [`RealAlg::exact_text`] then prints
    /// the root form).
    pub fn is_rational(&self) -> bool {
        matches!(self.0, Repr::Rational(_))
    }

    /// The rational value when the number is held as a rational.
    pub fn as_rational(&self) -> Option<&BigRational> {
        match &self.0 {
            Repr::Rational(x) => Some(x),
            Repr::Root(_) => None,
        }
    }

    /// A polynomial of which the number is a root (den·t − num for a rational).
    pub fn poly(&self) -> Poly {
        match &self.0 {
            Repr::Rational(x) => Poly::new(vec![-x.numer().clone(), x.denom().clone()]),
            Repr::Root(r) => r.p.clone(),
        }
    }

    /// The isolating interval (lo, hi), or (x, x) for a rational x: lo ≤ x ≤ hi.
    pub fn bounds(&self) -> (&BigRational, &BigRational) {
        match &self.0 {
            Repr::Rational(x) => (x, x),
            Repr::Root(r) => (&r.lo, &r.hi),
        }
    }

    /// The sign of p at lo, for a root (how the interval tells its halves apart).
    pub(crate) fn lo_sign(&self) -> Option<Ordering> {
        match &self.0 {
            Repr::Rational(_) => None,
            Repr::Root(r) => Some(r.lo_sign),
        }
    }

    /// Replace the isolating interval by a narrower one (lo′, hi′) ⊆ (lo, hi) that the
    /// caller has proved to hold the root (p(lo′) has the sign of p(lo), p(hi′) the
    /// other). No effect on a rational.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub(crate) fn narrow_to(&mut self, lo: BigRational, hi: BigRational) {
        if let Repr::Root(r) = &mut self.0 {
            debug_assert!(r.lo <= lo && lo < hi && hi <= r.hi);
            debug_assert_eq!(r.p.sign_at(&lo), r.lo_sign);
            debug_assert_eq!(r.p.sign_at(&hi), r.lo_sign.reverse());
            r.lo = lo;
            r.hi = hi;
        }
    }

    /// Halve the isolating interval (exact bisection); the number becomes a rational
    /// when the midpoint is the root.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn refine(&mut self) {
        let Repr::Root(r) = &mut self.0 else {
            return;
        };
        let m = midpoint(&r.lo, &r.hi);
        match r.p.sign_at(&m) {
            Ordering::Equal => self.0 = Repr::Rational(m),
            s if s == r.lo_sign => r.lo = m,
            _ => r.hi = m,
        }
    }

    /// Refine until the isolating interval is no wider than `width` (> 0).
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn refine_to(&mut self, width: &BigRational) {
        if !width.is_positive() {
            return;
        }
        while let Repr::Root(r) = &self.0 {
            if &(&r.hi - &r.lo) <= width {
                return;
            }
            self.refine();
        }
    }

    /// The order of the number and a rational x, exactly.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn cmp_rational(&self, x: &BigRational) -> Ordering {
        match &self.0 {
            Repr::Rational(a) => a.cmp(x),
            Repr::Root(r) => {
                if x <= &r.lo {
                    Ordering::Greater
                } else if x >= &r.hi {
                    Ordering::Less
                } else {
                    match r.p.sign_at(x) {
                        Ordering::Equal => Ordering::Equal,
                        // x lies between lo and the root.
                        s if s == r.lo_sign => Ordering::Greater,
                        _ => Ordering::Less,
                    }
                }
            }
        }
    }

    /// The sign of f at the number, exactly: 0 when f and p share the root (their gcd
    /// changes sign on the interval), else the sign of f at the interval's upper end
    /// once the interval holds no root of f (Sturm count of f's squarefree part).
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn sign_of(&self, f: &Poly) -> Ordering {
        if f.is_zero() {
            return Ordering::Equal;
        }
        let mut x = self.clone();
        let r = match &x.0 {
            Repr::Rational(a) => return f.sign_at(a),
            Repr::Root(r) => r,
        };
        let g = f.gcd(&r.p);
        if g.degree().unwrap_or(0) >= 1 {
            let (gl, gh) = (g.sign_at(&r.lo), g.sign_at(&r.hi));
            if gl != gh && gl != Ordering::Equal && gh != Ordering::Equal {
                return Ordering::Equal;
            }
        }
        let st = f.squarefree().sturm();
        loop {
            match &x.0 {
                Repr::Rational(a) => return f.sign_at(a),
                Repr::Root(r) => {
                    if st.count(&r.lo, &r.hi) == 0 {
                        return f.sign_at(&r.hi);
                    }
                }
            }
            x.refine();
        }
    }

    /// The exact order of two real algebraic numbers.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    fn cmp_alg(&self, o: &RealAlg) -> Ordering {
        let (a, b) = match (&self.0, &o.0) {
            (Repr::Rational(x), _) => return o.cmp_rational(x).reverse(),
            (_, Repr::Rational(y)) => return self.cmp_rational(y),
            (Repr::Root(a), Repr::Root(b)) => (a, b),
        };
        if a.hi <= b.lo {
            return Ordering::Less;
        }
        if b.hi <= a.lo {
            return Ordering::Greater;
        }
        // The intervals overlap. Equal exactly when gcd(p, q) has a root in the overlap
        // (it would be the one root of p there and the one root of q): its ends are ends
        // of one of the intervals, where p or q is not 0, so neither is the gcd, and the
        // gcd has at most one root there, a simple one: a sign change tells.
        let g = a.p.gcd(&b.p);
        if g.degree().unwrap_or(0) >= 1 {
            let l = if a.lo > b.lo { &a.lo } else { &b.lo };
            let h = if a.hi < b.hi { &a.hi } else { &b.hi };
            if g.sign_at(l) != g.sign_at(h) {
                return Ordering::Equal;
            }
        }
        // Different numbers: refine both until the intervals are apart.
        let (mut x, mut y) = (self.clone(), o.clone());
        loop {
            x.refine();
            y.refine();
            match (&x.0, &y.0) {
                (Repr::Root(a), Repr::Root(b)) => {
                    if a.hi <= b.lo {
                        return Ordering::Less;
                    }
                    if b.hi <= a.lo {
                        return Ordering::Greater;
                    }
                }
                _ => return x.cmp_alg(&y),
            }
        }
    }

    /// The decimal expansion with `digits` digits after the point, rounded toward −∞
    /// (exact: no digit is ever wrong), as [`ExactTime::to_decimal_string`] prints.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn to_decimal_string(&self, digits: usize) -> String {
        let scale = BigInt::from(10u32).pow(u32::try_from(digits).unwrap_or(u32::MAX));
        let sr = BigRational::from_integer(scale.clone());
        let mut x = self.clone();
        let floor = loop {
            match &x.0 {
                Repr::Rational(a) => break (a * &sr).floor().to_integer(),
                Repr::Root(r) => {
                    let fl = (&r.lo * &sr).floor().to_integer();
                    let fh = (&r.hi * &sr).floor().to_integer();
                    if fl == fh {
                        break fl;
                    }
                    // A root exactly on a digit boundary N/10^digits would keep the two
                    // floors apart for ever: test it.
                    let n = BigRational::new(fh, scale.clone());
                    if n > r.lo && r.p.sign_at(&n) == Ordering::Equal {
                        x = RealAlg::rational(n);
                        continue;
                    }
                }
            }
            x.refine();
        };
        decimal_of_floor(&floor, &scale, digits)
    }

    /// The exact value as text: "p/q" for a rational (lowest terms, q ≥ 1, as
    /// [`ExactTime::exact_text`]), else "root of P in (lo, hi)" with P the squarefree
    /// polynomial in t and lo, hi rationals.
    /// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
    pub fn exact_text(&self) -> String {
        match &self.0 {
            Repr::Rational(x) => format!("{}/{}", x.numer(), x.denom()),
            Repr::Root(r) => format!(
                "root of {} in ({}/{}, {}/{})",
                r.p.squarefree().normalized(),
                r.lo.numer(),
                r.lo.denom(),
                r.hi.numer(),
                r.hi.denom()
            ),
        }
    }
}

/// k when the positive integer x is 2^k.
fn power_of_two(x: &BigInt) -> Option<u64> {
    let k = x.trailing_zeros()?;
    (x.bits() == k + 1).then_some(k)
}

/// The dyadic n/2^k in lowest terms.
fn dyadic(n: BigInt, k: u64) -> BigRational {
    let z = n.trailing_zeros().unwrap_or(k).min(k);
    BigRational::new_raw(n >> z, BigInt::one() << (k - z))
}

/// A dyadic rational within a quarter of the width of (a + b)/2, for a < b: the exact
/// midpoint by shifts when both are dyadic, else the midpoint rounded down to a
/// multiple of 2^−j ≤ (b − a)/4. Bisection points stay dyadic, so no gcd reduction is
/// ever needed (it would dominate the cost).
/// (Paper A §II.C/§II.I: the exact ends of the sets of times.)
fn midpoint(a: &BigRational, b: &BigRational) -> BigRational {
    if let (Some(ka), Some(kb)) = (power_of_two(a.denom()), power_of_two(b.denom())) {
        let k = ka.max(kb);
        let sum = (a.numer() << (k - ka)) + (b.numer() << (k - kb));
        return dyadic(sum, k + 1);
    }
    // (a + b)/2 = num/den; 2^−j ≤ (b − a)/4 holds for j ≥ 2 + log2 of
    // (ad·bd)/(bn·ad − an·bd), bounded by bit lengths.
    let (an, ad, bn, bd) = (a.numer(), a.denom(), b.numer(), b.denom());
    let num = an * bd + bn * ad;
    let den = ad * bd * BigInt::from(2);
    let gap = bn * ad - an * bd;
    let j = (den.bits() + 3).saturating_sub(gap.bits());
    let k = (num << j).div_floor(&den);
    dyadic(k, j)
}

/// "int.frac" from ⌊x·10^digits⌋ (the digits of [`RealAlg::to_decimal_string`]).
fn decimal_of_floor(floor: &BigInt, scale: &BigInt, digits: usize) -> String {
    let neg = floor.is_negative();
    let (int_part, frac_part) = floor.abs().div_rem(scale);
    let mut out = String::new();
    if neg {
        out.push('-');
    }
    out.push_str(&int_part.to_string());
    if digits > 0 {
        let f = frac_part.to_string();
        out.push('.');
        for _ in f.len()..digits {
            out.push('0');
        }
        out.push_str(&f);
    }
    out
}

impl PartialEq for RealAlg {
    fn eq(&self, o: &Self) -> bool {
        self.cmp_alg(o) == Ordering::Equal
    }
}

impl Eq for RealAlg {}

impl PartialOrd for RealAlg {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for RealAlg {
    fn cmp(&self, o: &Self) -> Ordering {
        self.cmp_alg(o)
    }
}

impl fmt::Display for RealAlg {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.exact_text())
    }
}

impl From<&ExactTime> for RealAlg {
    /// The time a + b·√d (paper A §II.I's root of a quadratic) as a root of
    /// (t − a)² − b²·d, isolated in (a, a + |b|·(d + 1)) or (a − |b|·(d + 1), a), since
    /// 0 < √d < d + 1.
    fn from(x: &ExactTime) -> Self {
        let (a, b, d) = (x.rational_part(), x.surd_coefficient(), x.radicand());
        if x.is_rational() {
            return RealAlg::rational(a.clone());
        }
        let two = BigRational::from_integer(BigInt::from(2));
        let p = Poly::from_rationals(&[a * a - b * b * d, -(&two * a), BigRational::one()]);
        let reach = b.abs() * (d + BigRational::one());
        let (lo, hi) = if b.is_positive() {
            (a.clone(), a + reach)
        } else {
            (a - reach, a.clone())
        };
        let s = p.sign_at(&lo);
        RealAlg::certified(p, lo, hi, s)
    }
}

impl From<ExactTime> for RealAlg {
    fn from(x: ExactTime) -> Self {
        RealAlg::from(&x)
    }
}
