//! The exact ground truth: does s + t·v lie in the closed polygon P + t·V (and,
//! in 3D, in the closed slab) for some t ∈ [0, T], and when first?
//!
//! Method. Restrict time to the window W = [t0, t1] (the slab window of paper A
//! §III in 3D, [0, T] in 2D) and shift the clock to t0. The polygon must stay
//! simple on W; then, by continuity, the point enters the closed polygon first
//! either at t0 (it is inside or on the boundary then) or at the earliest time it
//! lies on an edge. The point x(t) lies on the edge a(t) b(t) exactly when
//! g(t) = (x − a) × (b − a) = 0 (a quadratic in t) and
//! h1(t) = (x − a)·(b − a) ≥ 0 and h2(t) = (b − x)·(b − a) ≥ 0. The roots of g
//! are algebraic numbers (p + q√d)/r, the signs of h1, h2 at them are decided
//! exactly ([`crate::qfield`]); when g ≡ 0 (motion collinear with the edge's
//! line), the solution sets of h1 ≥ 0 and h2 ≥ 0 are exact unions of intervals
//! ([`crate::detect::dot_nn_lin`], which covers every degenerate case).
//!
//! Simplicity on W: checked at the start of W directly (no two non-adjacent
//! edges meet). Later, a simple polygon stops being simple only through a vertex
//! lying on a non-incident edge (two non-adjacent edges first touch at an end
//! point; folding adjacent edges put an end point on the other edge; a collapsing
//! edge puts its vertex on the next edge). So it is simple on all of W exactly
//! when it is at the start and no vertex ever meets a non-incident edge in W —
//! the same contact test as for the point.

use core::cmp::Ordering;
use core::fmt;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::case::ExactCase;
use crate::detect::{dot_nn_lin, slab_interval, Interval};
use crate::field::{ExactField, V2};
use crate::qfield::{quad_roots, Alg};

/// An exact time a + b·√d (a, b, d rational, d ≥ 0); b = 0 when it is rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactTime {
    a: BigRational,
    b: BigRational,
    d: BigRational,
}

fn big_isqrt(n: &BigInt) -> BigInt {
    if n.sign() != Sign::Plus {
        BigInt::zero()
    } else {
        n.sqrt()
    }
}

/// Whether n may be a perfect square: false is certain (squares have few
/// residues modulo 64 and 45045 = 5·7·9·11·13), true means "compute the root".
fn may_be_square(n: &BigInt) -> bool {
    let low = n.iter_u64_digits().next().unwrap_or(0);
    if (0x0202_0212_0203_0213u64 >> (low & 63)) & 1 == 0 {
        return false;
    }
    let r = (n % BigInt::from(45045u32)).to_u32().unwrap_or(0);
    [5u32, 7, 9, 11, 13].iter().all(|&m| {
        let x = r % m;
        (0..m).any(|y| y * y % m == x)
    })
}

fn rational_sqrt(x: &BigRational) -> Option<BigRational> {
    if x.is_negative() {
        return None;
    }
    if !may_be_square(x.numer()) || !may_be_square(x.denom()) {
        return None;
    }
    let n = big_isqrt(x.numer());
    let d = big_isqrt(x.denom());
    if &(&n * &n) == x.numer() && &(&d * &d) == x.denom() {
        Some(BigRational::new(n, d))
    } else {
        None
    }
}

fn floor_div(n: &BigRational) -> BigInt {
    n.floor().to_integer()
}

impl ExactTime {
    /// The rational time x.
    pub fn rational(x: BigRational) -> Self {
        ExactTime {
            a: x,
            b: <BigRational as Zero>::zero(),
            d: <BigRational as Zero>::zero(),
        }
    }

    /// The time a + b·√d (d ≥ 0), put in canonical form (rational when it is).
    pub fn new(a: BigRational, b: BigRational, d: BigRational) -> Self {
        if b.is_zero() || d.is_zero() || d.is_negative() {
            return ExactTime::rational(a);
        }
        if let Some(r) = rational_sqrt(&d) {
            return ExactTime::rational(a + b * r);
        }
        ExactTime { a, b, d }
    }

    /// The exact value of (p + q√d)/r.
    pub fn from_alg<F: ExactField>(x: &Alg<F>) -> Self {
        let r = x.r.to_big();
        if r.is_zero() {
            return ExactTime::rational(<BigRational as Zero>::zero());
        }
        // Divide in the backend (GMP is faster than num-bigint), then convert.
        match (x.p.quotient(&x.r), x.q.quotient(&x.r)) {
            (Some(a), Some(b)) => ExactTime::new(a.to_big(), b.to_big(), x.d.to_big()),
            _ => ExactTime::new(x.p.to_big() / &r, x.q.to_big() / &r, x.d.to_big()),
        }
    }

    /// The rational part a.
    pub fn rational_part(&self) -> &BigRational {
        &self.a
    }

    /// The coefficient b of √d (0 for a rational time).
    pub fn surd_coefficient(&self) -> &BigRational {
        &self.b
    }

    /// The radicand d (0 for a rational time).
    pub fn radicand(&self) -> &BigRational {
        &self.d
    }

    /// Whether the time is rational.
    pub fn is_rational(&self) -> bool {
        self.b.is_zero()
    }

    /// "p/q" (lowest terms, q ≥ 1) when the time is rational.
    pub fn as_rational_string(&self) -> Option<String> {
        if self.is_rational() {
            Some(format!("{}/{}", self.a.numer(), self.a.denom()))
        } else {
            None
        }
    }

    /// The order of this time and a rational number, exactly.
    pub fn cmp_rational(&self, x: &BigRational) -> Ordering {
        let alpha = &self.a - x;
        crate::qfield::sign1(&alpha, &self.b, &self.d)
    }

    /// The exact value as text: "p/q" when rational, else "a + b·√d" with a, b, d in
    /// lowest terms.
    pub fn exact_text(&self) -> String {
        match self.as_rational_string() {
            Some(r) => r,
            None => self.to_string(),
        }
    }

    /// The decimal expansion with `digits` digits after the point, rounded
    /// toward −∞ (exact: no digit is ever wrong).
    pub fn to_decimal_string(&self, digits: usize) -> String {
        let scale = BigInt::from(10u32).pow(u32::try_from(digits).unwrap_or(u32::MAX));
        let sr = BigRational::from_integer(scale.clone());
        let floor = if self.is_rational() {
            floor_div(&(&self.a * &sr))
        } else {
            // x·S = a·S + c·√N with N = dn·dd, c = b·S/dd; c·√N = ±√(cn²·N)/cd.
            let a_s = &self.a * &sr;
            let n = self.d.numer() * self.d.denom();
            let c = &self.b * &sr / BigRational::from_integer(self.d.denom().clone());
            let m = c.numer() * c.numer() * &n;
            let cd = c.denom().clone();
            let neg = c.is_negative();
            let mut k: u32 = 0;
            loop {
                // isqrt(m·4^k) / 2^k ≤ √m < (isqrt(m·4^k) + 1) / 2^k.
                let mk = &m << (2 * k as usize);
                let root = big_isqrt(&mk);
                let den = BigRational::from_integer(&cd << (k as usize));
                let lo_abs = BigRational::from_integer(root.clone()) / &den;
                let hi_abs = BigRational::from_integer(root + BigInt::one()) / &den;
                let (lo, hi) = if neg {
                    (&a_s - hi_abs, &a_s - lo_abs)
                } else {
                    (&a_s + lo_abs, &a_s + hi_abs)
                };
                let fl = floor_div(&lo);
                if fl == floor_div(&hi) || k > 4096 {
                    break fl;
                }
                k += 8;
            }
        };
        let neg = floor.is_negative();
        let abs = floor.abs();
        let (int_part, frac_part) = abs.div_rem(&scale);
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
}

impl fmt::Display for ExactTime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_rational() {
            write!(f, "{}", self.a)
        } else {
            write!(f, "{} + ({})·√({})", self.a, self.b, self.d)
        }
    }
}

/// The ground truth for a case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Truth {
    /// The point is in the closed polygon (and slab) at some time in [0, T];
    /// `entry_time` is the first such time.
    Enters {
        /// The first time in [0, T] at which the point is in the closed polygon.
        entry_time: ExactTime,
    },
    /// It never is.
    Misses,
    /// The question has no answer: the polygon is not simple at some time of the window.
    Undefined {
        /// Why.
        reason: String,
    },
}

/// Exact early "no contact": over [0, T] the point stays in the box spanned by
/// its two end positions and the moving segment in the box spanned by the four
/// end positions of its ends (each coordinate is linear in t); disjoint boxes
/// mean no contact.
#[allow(clippy::too_many_arguments)]
fn boxes_apart<F: ExactField>(
    t: &F,
    x0: &V2<F>,
    xv: &V2<F>,
    a0: &V2<F>,
    av: &V2<F>,
    b0: &V2<F>,
    bv: &V2<F>,
) -> bool {
    let x1 = x0.at(xv, t);
    let a1 = a0.at(av, t);
    let b1 = b0.at(bv, t);
    let apart = |px: [&F; 2], ex: [&F; 4]| {
        let (plo, phi) = if px[0] <= px[1] {
            (px[0], px[1])
        } else {
            (px[1], px[0])
        };
        let elo = ex.iter().copied().min();
        let ehi = ex.iter().copied().max();
        match (elo, ehi) {
            (Some(lo), Some(hi)) => phi < lo || plo > hi,
            _ => false,
        }
    };
    apart([&x0.x, &x1.x], [&a0.x, &a1.x, &b0.x, &b1.x])
        || apart([&x0.y, &x1.y], [&a0.y, &a1.y, &b0.y, &b1.y])
}

/// g(t) = (q0 + t·q1) × (e0 + t·e1) = g2·t² + g1·t + g0, as [g2, g1, g0]
/// (q = x − a, the point relative to the edge's start; e = b − a, the edge).
pub(crate) fn contact_coeffs<F: ExactField>(
    q0: &V2<F>,
    q1: &V2<F>,
    e0: &V2<F>,
    e1: &V2<F>,
) -> [F; 3] {
    let g2 = q1.cross(e1);
    let g1 = q0.cross(e1).plus(&q1.cross(e0));
    let g0 = q0.cross(e0);
    [g2, g1, g0]
}

/// The real roots of g2·t² + g1·t + g0, not identically zero, in increasing
/// order (the candidates of [`earliest_contact`]; the filter picks one by index).
pub(crate) fn contact_roots<F: ExactField>(g2: &F, g1: &F, g0: &F) -> Vec<Alg<F>> {
    if g2.is_zero_() {
        if g1.is_zero_() {
            Vec::new()
        } else {
            Alg::new(g0.negated(), F::zero(), F::zero(), g1.clone())
                .into_iter()
                .collect()
        }
    } else {
        quad_roots(g2, g1, g0)
    }
}

/// The earliest t ∈ [0, T] at which the point x0 + t·xv lies on the closed
/// segment from a0 + t·av to b0 + t·bv, if any (exact; see the module doc).
#[allow(clippy::too_many_arguments)]
pub fn earliest_contact<F: ExactField>(
    t: &F,
    x0: &V2<F>,
    xv: &V2<F>,
    a0: &V2<F>,
    av: &V2<F>,
    b0: &V2<F>,
    bv: &V2<F>,
) -> Option<Alg<F>> {
    if boxes_apart(t, x0, xv, a0, av, b0, bv) {
        return None;
    }
    let q0 = x0.minus(a0);
    let q1 = xv.minus(av);
    let e0 = b0.minus(a0);
    let e1 = bv.minus(av);
    let [g2, g1, g0] = contact_coeffs(&q0, &q1, &e0, &e1);
    let r0 = e0.minus(&q0);
    let r1 = e1.minus(&q1);
    if g2.is_zero_() && g1.is_zero_() && g0.is_zero_() {
        // Always on the edge's line: {h1 ≥ 0} ∩ {h2 ≥ 0}, each an exact union
        // of two intervals of [0, T]; the answer is the least common point.
        let s1 = [-1i8, 1].map(|sg| dot_nn_lin(t, &q0, &q1, &e0, &e1, sg));
        let s2 = [-1i8, 1].map(|sg| dot_nn_lin(t, &r0, &r1, &e0, &e1, sg));
        let mut best: Option<Alg<F>> = None;
        for i in &s1 {
            for j in &s2 {
                if let (Interval::Closed { lb: l1, ub: u1 }, Interval::Closed { lb: l2, ub: u2 }) =
                    (i, j)
                {
                    let lb = if l1.cmp_alg(l2) == Ordering::Less {
                        l2
                    } else {
                        l1
                    };
                    let ub = if u1.cmp_alg(u2) == Ordering::Less {
                        u1
                    } else {
                        u2
                    };
                    if lb.cmp_alg(ub) != Ordering::Greater {
                        let better = match &best {
                            None => true,
                            Some(b) => lb.cmp_alg(b) == Ordering::Less,
                        };
                        if better {
                            best = Some(lb.clone());
                        }
                    }
                }
            }
        }
        return best;
    }
    let roots = contact_roots(&g2, &g1, &g0);
    // h1 = (q0 + t q1)·(e0 + t e1) and h2 = (r0 + t r1)·(e0 + t e1) as quadratics.
    let h = |w: &V2<F>, v: &V2<F>| {
        let a = v.dot(&e1);
        let b = w.dot(&e1).plus(&v.dot(&e0));
        let c = w.dot(&e0);
        (a, b, c)
    };
    let (a1, b1, c1) = h(&q0, &q1);
    let (a2, b2, c2) = h(&r0, &r1);
    roots.into_iter().find(|r| {
        r.sign() != Ordering::Less
            && r.cmp_rat(t) != Ordering::Greater
            && r.quad_sign(&a1, &b1, &c1) != Ordering::Less
            && r.quad_sign(&a2, &b2, &c2) != Ordering::Less
    })
}

/// Whether the closed segments a b and c d meet (exact orientation tests).
pub fn segments_intersect<F: ExactField>(a: &V2<F>, b: &V2<F>, c: &V2<F>, d: &V2<F>) -> bool {
    let on = |p: &V2<F>, q: &V2<F>, x: &V2<F>| {
        let e = q.minus(p);
        e.cross(&x.minus(p)).is_zero_()
            && !x.minus(p).dot(&e).is_neg()
            && !q.minus(x).dot(&e).is_neg()
    };
    let o1 = b.minus(a).cross(&c.minus(a)).sign();
    let o2 = b.minus(a).cross(&d.minus(a)).sign();
    let o3 = d.minus(c).cross(&a.minus(c)).sign();
    let o4 = d.minus(c).cross(&b.minus(c)).sign();
    let proper = |x: Ordering, y: Ordering| {
        (x == Ordering::Greater && y == Ordering::Less)
            || (x == Ordering::Less && y == Ordering::Greater)
    };
    (proper(o1, o2) && proper(o3, o4)) || on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b)
}

/// Whether s lies in the closed polygon P (on an edge, or winding number ≠ 0).
pub fn in_closed_polygon<F: ExactField>(poly: &[V2<F>], s: &V2<F>) -> bool {
    let n = poly.len();
    let mut winding: i64 = 0;
    for i in 0..n {
        let a = &poly[i];
        let b = &poly[(i + 1) % n];
        let e = b.minus(a);
        let q = s.minus(a);
        let o = e.cross(&q);
        if o.is_zero_() && !q.dot(&e).is_neg() && !b.minus(s).dot(&e).is_neg() {
            return true;
        }
        if a.y <= s.y {
            if b.y > s.y && o.is_pos() {
                winding += 1;
            }
        } else if b.y <= s.y && o.is_neg() {
            winding -= 1;
        }
    }
    winding != 0
}

pub(crate) fn min_alg<F: ExactField>(best: Option<Alg<F>>, x: Alg<F>) -> Option<Alg<F>> {
    match best {
        Some(b) if b.cmp_alg(&x) != Ordering::Greater => Some(b),
        _ => Some(x),
    }
}

/// The ground truth of a case: `Enters` with the exact first entry time,
/// `Misses`, or `Undefined` when the polygon is not simple during the window.
///
/// Every sign decision is first tried in interval arithmetic ([`crate::filter`])
/// and made exactly only when the interval cannot certify it; the answer is
/// identical to [`truth_unfiltered`]'s (tests/filtered.rs checks it).
pub fn truth<F: ExactField>(c: &ExactCase<F>) -> Truth {
    crate::filter::truth(c)
}

/// The window [t0, t1] of a case (the slab window of paper A §III in 3D,
/// [0, T] in 2D), `None` when the point never is in the slab.
pub(crate) fn window<F: ExactField>(c: &ExactCase<F>) -> Option<(F, F)> {
    match &c.vertical {
        None => Some((F::zero(), c.lookahead.clone())),
        Some(z) => slab_interval(&c.lookahead, &z.sz, &z.vz, &z.bottom, &z.top, &z.vsp),
    }
}

/// The answer for a case whose sizes are wrong.
pub(crate) fn bad_lengths() -> Truth {
    Truth::Undefined {
        reason: "fewer than 3 vertices or velocities of the wrong length".to_string(),
    }
}

/// The answer when edges i-(i+1) and k-(k+1) meet at the window's start.
pub(crate) fn crossing_at_start(n: usize, i: usize, k: usize) -> Truth {
    Truth::Undefined {
        reason: format!(
            "the polygon is not simple: edges {i}-{} and {k}-{} cross at the window's start",
            (i + 1) % n,
            (k + 1) % n
        ),
    }
}

/// The answer when vertex k meets edge i-j at the shifted time tc + t0.
pub(crate) fn vertex_meets_edge<F: ExactField>(
    k: usize,
    i: usize,
    j: usize,
    tc: &Alg<F>,
    t0: &F,
) -> Truth {
    let when = ExactTime::from_alg(&tc.shifted(t0));
    Truth::Undefined {
        reason: format!(
            "the polygon is not simple: vertex {k} meets edge {i}-{j} at t = {}",
            when.to_decimal_string(9)
        ),
    }
}

/// The ground truth computed with exact arithmetic only (no floating filter).
pub fn truth_unfiltered<F: ExactField>(c: &ExactCase<F>) -> Truth {
    let Some((t0, t1)) = window(c) else {
        return Truth::Misses;
    };
    let tw = t1.minus(&t0);
    let s = c.s.at(&c.v, &t0);
    let poly: Vec<V2<F>> = c
        .vertices
        .iter()
        .zip(&c.velocities)
        .map(|(p, w)| p.at(w, &t0))
        .collect();
    let vels = &c.velocities;
    let n = poly.len();
    if n < 3 || vels.len() != n {
        return bad_lengths();
    }
    // Simplicity at the window's start: non-adjacent edges do not meet
    // (vertices on non-incident edges are caught by the contact test below).
    for i in 0..n {
        for k in (i + 2)..n {
            if i == 0 && k == n - 1 {
                continue;
            }
            if segments_intersect(&poly[i], &poly[(i + 1) % n], &poly[k], &poly[(k + 1) % n]) {
                return crossing_at_start(n, i, k);
            }
        }
    }
    // Simplicity on the window: no vertex ever meets a non-incident edge.
    for i in 0..n {
        let j = (i + 1) % n;
        for k in 0..n {
            if k == i || k == j {
                continue;
            }
            if let Some(tc) = earliest_contact(
                &tw, &poly[k], &vels[k], &poly[i], &vels[i], &poly[j], &vels[j],
            ) {
                return vertex_meets_edge(k, i, j, &tc, &t0);
            }
        }
    }
    if in_closed_polygon(&poly, &s) {
        return Truth::Enters {
            entry_time: ExactTime::rational(t0.to_big()),
        };
    }
    let mut best: Option<Alg<F>> = None;
    for i in 0..n {
        let j = (i + 1) % n;
        if let Some(tc) = earliest_contact(&tw, &s, &c.v, &poly[i], &vels[i], &poly[j], &vels[j]) {
            best = min_alg(best, tc);
        }
    }
    match best {
        Some(tc) => Truth::Enters {
            entry_time: ExactTime::from_alg(&tc.shifted(&t0)),
        },
        None => Truth::Misses,
    }
}
