//! The polynomials in t whose signs decide the relations (paper A §II.C's edge
//! quadratics, of higher degree for §II.I's warping edges), written once over a
//! coefficient type and built twice: in float enclosures (always, to filter) and in
//! integers (only when an exact answer needs them).
//!
//! With q(t) = x(t) − a(t) (the point relative to an edge's start a) and
//! e(t) = b(t) − a(t) (the edge), both linear in t, per vertex and per edge:
//! - `Vertex(i)`: |x − p_i|² − D², a quadratic (paper A §II.C's end-point test);
//! - `Cross(i)`: g = q × e, the point's side of the edge's line (degree ≤ 2);
//! - `Ahead(i)`: h1 = q · e and `Behind(i)`: h2 = (e − q) · e, whether the point's
//!   projection falls beyond a or beyond b (degree ≤ 2);
//! - `Band(i)`: g² − D²·|e|², within D of the edge's line (degree ≤ 4; ≤ 2 when the
//!   edge does not warp, for then e is constant and g linear).
//!
//! The exact polynomials are in integers, in t: the inputs a polynomial involves (the
//! point, one or two vertices, D) are multiplied by their common denominator L, and
//! D² = num/den after the same scaling, so `Vertex` is den·|q|² − num and `Band`
//! den·g² − num·|e|², positive multiples of the true ones (the same roots and signs).
//! The float ones are enclosures of the true ones in s = t − τ for the start τ of the
//! window they are worked on, every length scaled by a power of two (again a positive
//! multiple): restarting the motions at τ before the products keeps a window far from
//! t = 0 clear of most cancellation between large terms.

use core::cell::OnceCell;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::algebraic::Poly;
use crate::field::{ExactField, V2};
use crate::kernel::interval::{enclose, magnitude_exponent, Iv};

/// Which polynomial of the scene (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// |x − p_i|² − D².
    Vertex(usize),
    /// g = (x − p_i) × (p_{i+1} − p_i).
    Cross(usize),
    /// h1 = (x − p_i) · (p_{i+1} − p_i).
    Ahead(usize),
    /// h2 = (p_{i+1} − x) · (p_{i+1} − p_i).
    Behind(usize),
    /// g² − D²·|p_{i+1} − p_i|².
    Band(usize),
}

impl Kind {
    /// The vertices the polynomial involves: (i, i + 1), or (i, i) for `Vertex(i)`.
    /// (Paper A §II.C: an edge's two ends, or one vertex.)
    fn ends(self, n: usize) -> (usize, usize) {
        match self {
            Kind::Vertex(i) => (i, i),
            Kind::Cross(i) | Kind::Ahead(i) | Kind::Behind(i) | Kind::Band(i) => (i, (i + 1) % n),
        }
    }
}

/// The ring operations the polynomials are written with (float enclosures or integers).
pub(crate) trait Coef: Clone {
    /// 0.
    fn zero() -> Self;
    /// self + o.
    fn add(&self, o: &Self) -> Self;
    /// self − o.
    fn sub(&self, o: &Self) -> Self;
    /// self · o.
    fn mul(&self, o: &Self) -> Self;
}

impl Coef for Iv {
    fn zero() -> Self {
        Iv::ZERO
    }
    fn add(&self, o: &Self) -> Self {
        Iv::add(*self, *o)
    }
    fn sub(&self, o: &Self) -> Self {
        Iv::sub(*self, *o)
    }
    fn mul(&self, o: &Self) -> Self {
        Iv::mul(*self, *o)
    }
}

impl Coef for BigInt {
    fn zero() -> Self {
        Zero::zero()
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
}

/// a · b for coefficient lists (lowest degree first).
/// (The products of paper A §II.C's quadratics.)
fn pmul<C: Coef>(a: &[C], b: &[C]) -> Vec<C> {
    let mut c = vec![C::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            c[i + j] = c[i + j].add(&x.mul(y));
        }
    }
    c
}

/// a − b for coefficient lists.
/// (The products of paper A §II.C's quadratics.)
fn psub<C: Coef>(a: &[C], b: &[C]) -> Vec<C> {
    (0..a.len().max(b.len()))
        .map(|k| {
            let z = C::zero();
            a.get(k).unwrap_or(&z).sub(b.get(k).unwrap_or(&z))
        })
        .collect()
}

/// k · a for a coefficient list.
/// (The products of paper A §II.C's quadratics.)
fn pscale<C: Coef>(a: &[C], k: &C) -> Vec<C> {
    a.iter().map(|x| x.mul(k)).collect()
}

/// A 2-vector moving linearly, c0 + t·c1 (the paper's s + t·v, p_i + t·v_i).
#[derive(Clone, Debug)]
pub(crate) struct Moving<C> {
    /// At t = 0.
    pub c0: [C; 2],
    /// Per unit time.
    pub c1: [C; 2],
}

impl<C: Coef> Moving<C> {
    /// self − o.
    /// (The products of paper A §II.C's quadratics.)
    fn minus(&self, o: &Self) -> Self {
        Moving {
            c0: [self.c0[0].sub(&o.c0[0]), self.c0[1].sub(&o.c0[1])],
            c1: [self.c1[0].sub(&o.c1[0]), self.c1[1].sub(&o.c1[1])],
        }
    }

    /// self · o as a polynomial in t (degree ≤ 2).
    /// (The products of paper A §II.C's quadratics.)
    fn dot(&self, o: &Self) -> Vec<C> {
        let d = |a: &[C; 2], b: &[C; 2]| a[0].mul(&b[0]).add(&a[1].mul(&b[1]));
        vec![
            d(&self.c0, &o.c0),
            d(&self.c0, &o.c1).add(&d(&self.c1, &o.c0)),
            d(&self.c1, &o.c1),
        ]
    }

    /// self × o as a polynomial in t (degree ≤ 2).
    /// (The products of paper A §II.C's quadratics.)
    fn cross(&self, o: &Self) -> Vec<C> {
        let x = |a: &[C; 2], b: &[C; 2]| a[0].mul(&b[1]).sub(&a[1].mul(&b[0]));
        vec![
            x(&self.c0, &o.c0),
            x(&self.c0, &o.c1).add(&x(&self.c1, &o.c0)),
            x(&self.c1, &o.c1),
        ]
    }
}

impl Moving<Iv> {
    /// The same motion with the clock started at τ (enclosed): c0 + τ·c1 and c1.
    /// (Paper A §III's restart of a scene at a window's start.)
    fn restarted_at(&self, tau: Iv) -> Moving<Iv> {
        Moving {
            c0: [
                self.c0[0].add(tau.mul(self.c1[0])),
                self.c0[1].add(tau.mul(self.c1[1])),
            ],
            c1: self.c1,
        }
    }
}

/// The polynomial `kind` (see the module doc) of the point x and the vertices a, b
/// (b = a for `Vertex`), with D² = d2_num / d2_den, lowest degree first.
/// (Paper A §II.C's quadratics for a moving point and edge, §II.I's warping edge.)
fn poly_of<C: Coef>(
    kind: Kind,
    x: &Moving<C>,
    a: &Moving<C>,
    b: &Moving<C>,
    d2_num: &C,
    d2_den: &C,
) -> Vec<C> {
    let q = x.minus(a);
    let e = b.minus(a);
    match kind {
        Kind::Vertex(_) => {
            let mut r = pscale(&q.dot(&q), d2_den);
            r[0] = r[0].sub(d2_num);
            r
        }
        Kind::Cross(_) => q.cross(&e),
        Kind::Ahead(_) => q.dot(&e),
        Kind::Behind(_) => e.minus(&q).dot(&e),
        Kind::Band(_) => {
            let g = q.cross(&e);
            psub(&pscale(&pmul(&g, &g), d2_den), &pscale(&e.dot(&e), d2_num))
        }
    }
}

/// A scene in one coefficient type: the point and the vertices.
#[derive(Clone, Debug)]
pub(crate) struct Layout<C> {
    /// The point, s + t·v.
    pub x: Moving<C>,
    /// The vertices, p_i + t·v_i.
    pub p: Vec<Moving<C>>,
}

/// The power of two a positive integer is, if it is one.
/// (Making paper A §II–III's inputs integers.)
fn power_of_two(x: &BigInt) -> Option<u64> {
    let k = x.trailing_zeros()?;
    (x.bits() == k + 1).then_some(k)
}

/// lcm(a, b) of positive integers, by a comparison when both are powers of two (the
/// denominators of binary floats).
/// (Making paper A §II–III's inputs integers.)
fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    match (power_of_two(a), power_of_two(b)) {
        (Some(x), Some(y)) => {
            if x >= y {
                a.clone()
            } else {
                b.clone()
            }
        }
        _ => a.lcm(b),
    }
}

/// a / b for a positive b dividing a, by a shift when b is a power of two.
/// (Making paper A §II–III's inputs integers.)
fn quotient(a: &BigInt, b: &BigInt) -> BigInt {
    match power_of_two(b) {
        Some(k) => a >> k,
        None => a / b,
    }
}

/// The inputs of a case, the float layout built at once, the integer one on demand.
pub(crate) struct Scene<'a, F> {
    s: &'a V2<F>,
    v: &'a V2<F>,
    p: &'a [V2<F>],
    vels: &'a [V2<F>],
    d: &'a F,
    /// Enclosures of the true scene, every length times 2^k.
    pub fl: Layout<Iv>,
    /// D², times 2^2k.
    d2_fl: Iv,
    /// D, times 2^k.
    pub d_fl: Iv,
    exact: OnceCell<Layout<BigInt>>,
}

impl<'a, F: ExactField> Scene<'a, F> {
    /// The scene of s + t·v and P + t·V (n = |p| = |vels| vertices) at separation D,
    /// over the lookahead t (for the float scaling only).
    /// (The contract's case: paper A §II–III's moving point and polygon.)
    pub fn new(
        t: &F,
        s: &'a V2<F>,
        v: &'a V2<F>,
        p: &'a [V2<F>],
        vels: &'a [V2<F>],
        d: &'a F,
    ) -> Self {
        let e2 = |a: &V2<F>| [enclose(&a.x), enclose(&a.y)];
        let (s_iv, v_iv) = (e2(s), e2(v));
        let p_iv: Vec<[Iv; 2]> = p.iter().map(e2).collect();
        let w_iv: Vec<[Iv; 2]> = vels.iter().map(e2).collect();
        let d_iv = enclose(d);
        // Lengths times 2^k with k the negated largest exponent among the positions,
        // the distances moved over T (the exponent of T plus that of a speed) and D:
        // exponents, so that no product can overflow on the way.
        let et = magnitude_exponent(enclose(t)).unwrap_or(0);
        let k = -s_iv
            .iter()
            .chain(p_iv.iter().flatten())
            .filter_map(|&x| magnitude_exponent(x))
            .chain(
                v_iv.iter()
                    .chain(w_iv.iter().flatten())
                    .filter_map(|&x| magnitude_exponent(x).map(|m| m + et)),
            )
            .chain(magnitude_exponent(d_iv))
            .max()
            .unwrap_or(0);
        let sc = |a: [Iv; 2]| [a[0].scaled_pow2(k), a[1].scaled_pow2(k)];
        let mv = |a: [Iv; 2], b: [Iv; 2]| Moving {
            c0: sc(a),
            c1: sc(b),
        };
        let ds = d_iv.scaled_pow2(k);
        let fl = Layout {
            x: mv(s_iv, v_iv),
            p: p_iv.into_iter().zip(w_iv).map(|(a, b)| mv(a, b)).collect(),
        };
        Scene {
            s,
            v,
            p,
            vels,
            d,
            fl,
            d2_fl: ds.sq(),
            d_fl: ds,
            exact: OnceCell::new(),
        }
    }

    /// The number of vertices.
    /// (The contract's case: paper A §II–III's moving point and polygon.)
    pub fn len(&self) -> usize {
        self.p.len()
    }

    /// Whether D = 0 (the contacts of the truth instead of bands).
    /// (The contract's case: paper A §II–III's moving point and polygon.)
    pub fn d_is_zero(&self) -> bool {
        self.d.is_zero_()
    }

    /// The float polynomial `kind` in s = t − τ (τ enclosed by `tau`): the motions
    /// restarted at τ in enclosures before the products, so that a window far from
    /// t = 0 loses little to cancellation. A positive multiple of the true polynomial
    /// in s. (Where it still cannot settle a root, the exact polynomial is shifted
    /// exactly: `intervals::set`'s shifted roots.)
    /// (Paper A §II.C/§II.I's polynomials, in floats.)
    pub fn fl_poly(&self, kind: Kind, tau: Iv) -> Vec<Iv> {
        let (i, j) = kind.ends(self.p.len());
        let fl = &self.fl;
        poly_of(
            kind,
            &fl.x.restarted_at(tau),
            &fl.p[i].restarted_at(tau),
            &fl.p[j].restarted_at(tau),
            &self.d2_fl,
            &Iv::ONE,
        )
    }

    /// The inputs polynomial `kind` involves, made integers by their common
    /// denominator L: the point and vertices i and j (see [`Kind::ends`]) as integer
    /// motions, and (L·D)².
    /// (Making paper A §II–III's inputs integers.)
    fn local(&self, kind: Kind) -> ([Moving<BigInt>; 3], BigRational) {
        let (i, j) = kind.ends(self.p.len());
        let big = |x: &F| x.to_big();
        let all: Vec<BigRational> = [
            self.s,
            self.v,
            &self.p[i],
            &self.vels[i],
            &self.p[j],
            &self.vels[j],
        ]
        .into_iter()
        .flat_map(|a| [big(&a.x), big(&a.y)])
        .collect();
        let l = all
            .iter()
            .fold(BigInt::one(), |acc, x| lcm(&acc, x.denom()));
        let int = |x: &BigRational| x.numer() * quotient(&l, x.denom());
        let mv = |k: usize| Moving {
            c0: [int(&all[4 * k]), int(&all[4 * k + 1])],
            c1: [int(&all[4 * k + 2]), int(&all[4 * k + 3])],
        };
        let ld = big(self.d) * BigRational::from_integer(l.clone());
        ([mv(0), mv(1), mv(2)], &ld * &ld)
    }

    /// The exact polynomial `kind` in t (common powers of two divided out).
    /// (Paper A §II.C/§II.I's polynomials, exactly.)
    pub fn exact_poly(&self, kind: Kind) -> Poly {
        let ([x, a, b], ld2) = self.local(kind);
        let c = poly_of(kind, &x, &a, &b, ld2.numer(), ld2.denom());
        Poly::new(c).without_common_twos()
    }

    /// The integer layout of the whole scene (built on first use): every horizontal
    /// length times the common denominator L of the inputs.
    /// (Making paper A §II–III's inputs integers.)
    pub fn exact(&self) -> &Layout<BigInt> {
        self.exact.get_or_init(|| {
            let big = |x: &F| x.to_big();
            let all: Vec<BigRational> = [self.s, self.v]
                .into_iter()
                .chain(self.p.iter())
                .chain(self.vels.iter())
                .flat_map(|a| [big(&a.x), big(&a.y)])
                .collect();
            let l = all
                .iter()
                .fold(BigInt::one(), |acc, x| lcm(&acc, x.denom()));
            let int = |x: &BigRational| x.numer() * quotient(&l, x.denom());
            let at = |i: usize| [int(&all[2 * i]), int(&all[2 * i + 1])];
            let n = self.p.len();
            Layout {
                x: Moving {
                    c0: at(0),
                    c1: at(1),
                },
                p: (0..n)
                    .map(|i| Moving {
                        c0: at(2 + i),
                        c1: at(2 + n + i),
                    })
                    .collect(),
            }
        })
    }

    /// The exact point and vertices at the rational time τ = num/den, all times den·L
    /// (a positive factor: the same winding number).
    /// (Paper A §II.D's crossings at one time, exactly.)
    pub fn exact_at(&self, tau: &BigRational) -> (V2<BigRational>, Vec<V2<BigRational>>) {
        let e = self.exact();
        let (num, den) = (tau.numer(), tau.denom());
        let pos = |m: &Moving<BigInt>| {
            let c = |k: usize| BigRational::from_integer(&m.c0[k] * den + &m.c1[k] * num);
            V2::new(c(0), c(1))
        };
        (pos(&e.x), e.p.iter().map(pos).collect())
    }
}
