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
//! The exact polynomials are in integers: every length is multiplied by the common
//! denominator L of the horizontal inputs, and D² = num/den after the same scaling,
//! so `Vertex` is den·|q|² − num and `Band` den·g² − num·|e|², positive multiples of the
//! true ones (the same roots and signs). The float ones are enclosures of the true
//! ones with every length scaled by a power of two (again a positive multiple).

use core::cell::OnceCell;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::algebraic::Poly;
use crate::field::{ExactField, V2};
use crate::kernel::interval::{balancing_exponent, enclose, Iv};

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
fn psub<C: Coef>(a: &[C], b: &[C]) -> Vec<C> {
    (0..a.len().max(b.len()))
        .map(|k| {
            let z = C::zero();
            a.get(k).unwrap_or(&z).sub(b.get(k).unwrap_or(&z))
        })
        .collect()
}

/// k · a for a coefficient list.
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
    fn minus(&self, o: &Self) -> Self {
        Moving {
            c0: [self.c0[0].sub(&o.c0[0]), self.c0[1].sub(&o.c0[1])],
            c1: [self.c1[0].sub(&o.c1[0]), self.c1[1].sub(&o.c1[1])],
        }
    }

    /// self · o as a polynomial in t (degree ≤ 2).
    fn dot(&self, o: &Self) -> Vec<C> {
        let d = |a: &[C; 2], b: &[C; 2]| a[0].mul(&b[0]).add(&a[1].mul(&b[1]));
        vec![
            d(&self.c0, &o.c0),
            d(&self.c0, &o.c1).add(&d(&self.c1, &o.c0)),
            d(&self.c1, &o.c1),
        ]
    }

    /// self × o as a polynomial in t (degree ≤ 2).
    fn cross(&self, o: &Self) -> Vec<C> {
        let x = |a: &[C; 2], b: &[C; 2]| a[0].mul(&b[1]).sub(&a[1].mul(&b[0]));
        vec![
            x(&self.c0, &o.c0),
            x(&self.c0, &o.c1).add(&x(&self.c1, &o.c0)),
            x(&self.c1, &o.c1),
        ]
    }
}

/// A scene in one coefficient type: the point, the vertices, D² = num/den.
#[derive(Clone, Debug)]
pub(crate) struct Layout<C> {
    /// The point, s + t·v.
    pub x: Moving<C>,
    /// The vertices, p_i + t·v_i.
    pub p: Vec<Moving<C>>,
    /// D² = d2_num / d2_den (d2_den > 0).
    pub d2_num: C,
    /// See `d2_num`.
    pub d2_den: C,
}

impl<C: Coef> Layout<C> {
    /// The polynomial `kind` (see the module doc), lowest degree first.
    /// (Paper A §II.C's quadratics for a moving point and edge, §II.I's warping edge.)
    pub fn poly(&self, kind: Kind) -> Vec<C> {
        let n = self.p.len();
        let edge = |i: usize| {
            (
                self.x.minus(&self.p[i]),
                self.p[(i + 1) % n].minus(&self.p[i]),
            )
        };
        match kind {
            Kind::Vertex(i) => {
                let q = self.x.minus(&self.p[i]);
                let mut r = pscale(&q.dot(&q), &self.d2_den);
                r[0] = r[0].sub(&self.d2_num);
                r
            }
            Kind::Cross(i) => {
                let (q, e) = edge(i);
                q.cross(&e)
            }
            Kind::Ahead(i) => {
                let (q, e) = edge(i);
                q.dot(&e)
            }
            Kind::Behind(i) => {
                let (q, e) = edge(i);
                e.minus(&q).dot(&e)
            }
            Kind::Band(i) => {
                let (q, e) = edge(i);
                let g = q.cross(&e);
                psub(
                    &pscale(&pmul(&g, &g), &self.d2_den),
                    &pscale(&e.dot(&e), &self.d2_num),
                )
            }
        }
    }

    /// Where the point and the vertices are at time τ (a coefficient).
    pub fn at(&self, tau: &C) -> (V2Of<C>, Vec<V2Of<C>>) {
        let pos = |m: &Moving<C>| {
            [
                m.c0[0].add(&m.c1[0].mul(tau)),
                m.c0[1].add(&m.c1[1].mul(tau)),
            ]
        };
        (pos(&self.x), self.p.iter().map(pos).collect())
    }
}

/// A position as two coefficients.
pub(crate) type V2Of<C> = [C; 2];

/// The power of two a positive integer is, if it is one.
fn power_of_two(x: &BigInt) -> Option<u64> {
    let k = x.trailing_zeros()?;
    (x.bits() == k + 1).then_some(k)
}

/// lcm(a, b) of positive integers, by a comparison when both are powers of two (the
/// denominators of binary floats).
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
    /// D, times the same 2^k.
    pub d_fl: Iv,
    exact: OnceCell<Layout<BigInt>>,
}

impl<'a, F: ExactField> Scene<'a, F> {
    /// The scene of s + t·v and P + t·V (n = |p| = |vels| vertices) at separation D,
    /// over the lookahead t (for the float scaling only).
    pub fn new(
        t: &F,
        s: &'a V2<F>,
        v: &'a V2<F>,
        p: &'a [V2<F>],
        vels: &'a [V2<F>],
        d: &'a F,
    ) -> Self {
        let tt = enclose(t);
        let e2 = |a: &V2<F>| [enclose(&a.x), enclose(&a.y)];
        let (s_iv, v_iv) = (e2(s), e2(v));
        let p_iv: Vec<[Iv; 2]> = p.iter().map(e2).collect();
        let w_iv: Vec<[Iv; 2]> = vels.iter().map(e2).collect();
        let d_iv = enclose(d);
        let mags = s_iv
            .iter()
            .copied()
            .chain(v_iv.iter().map(|&c| Iv::mul(c, tt)))
            .chain(p_iv.iter().flatten().copied())
            .chain(w_iv.iter().flatten().map(|&c| Iv::mul(c, tt)))
            .chain([d_iv]);
        let k = balancing_exponent(mags);
        let sc = |a: [Iv; 2]| [a[0].scaled_pow2(k), a[1].scaled_pow2(k)];
        let mv = |a: [Iv; 2], b: [Iv; 2]| Moving {
            c0: sc(a),
            c1: sc(b),
        };
        let ds = d_iv.scaled_pow2(k);
        let fl = Layout {
            x: mv(s_iv, v_iv),
            p: p_iv.into_iter().zip(w_iv).map(|(a, b)| mv(a, b)).collect(),
            d2_num: ds.sq(),
            d2_den: Iv::ONE,
        };
        Scene {
            s,
            v,
            p,
            vels,
            d,
            fl,
            d_fl: ds,
            exact: OnceCell::new(),
        }
    }

    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.p.len()
    }

    /// Whether D = 0 (the contacts of the truth instead of bands).
    pub fn d_is_zero(&self) -> bool {
        self.d.is_zero_()
    }

    /// The integer layout (built on first use): every horizontal length times the
    /// common denominator L of the inputs, D² = (L·D)² as num/den.
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
            let ld = big(self.d) * BigRational::from_integer(l.clone());
            let ld2 = &ld * &ld;
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
                d2_num: ld2.numer().clone(),
                d2_den: ld2.denom().clone(),
            }
        })
    }

    /// The exact polynomial `kind` (common powers of two divided out).
    pub fn exact_poly(&self, kind: Kind) -> Poly {
        Poly::new(self.exact().poly(kind)).without_common_twos()
    }

    /// The exact point and vertices at the rational time τ = num/den, all times den·L
    /// (a positive factor: the same winding number).
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
