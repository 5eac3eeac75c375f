//! Every sign decision of the f64 engine, in one place, each one certified.
//!
//! A predicate names one comparison that paper A's algorithms make, takes its operands
//! as [`Ball`]s or [`BallV`]s (the computed value and a rigorous error radius, see
//! [`crate::ball`]) and answers a [`Tri`]: `Yes` or `No` only when the exact comparison,
//! on the exact numbers the operands stand for, is certain to go that way; `Unsure`
//! otherwise. The forward error bound of each predicate is the radius its ball formula
//! carries: derived operation by operation by [`Ball`]'s arithmetic (2u·|result| per
//! rounding, propagated radii, rounded up by [`crate::ball::up`]). There is no absolute
//! epsilon anywhere.
//!
//! Where a small exact expansion can settle an `Unsure` (a sum of a few floats, a
//! 2×2 determinant of such sums) the predicate takes the exact terms of its operands
//! ([`Terms`]) and decides exactly; otherwise `Unsure` goes back to the algorithm,
//! which resolves it towards detection.
//!
//! The predicates are stated in the point's frame: the moving point is the origin and
//! the operands are polygon vertices relative to it (paper A's functions are
//! translation invariant, and differences are where the encounter's scale lives).

use crate::ball::{exact, nonnegative, positive, Ball, BallV, Tri};
use crate::vect2::Vect2;

// ---------------------------------------------------------------- exact terms

/// The coordinates of a point (relative to the moving point) as exact sums of floats:
/// x = Σ x[..n], y = Σ y[..n]. What the exact fallbacks evaluate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Terms {
    /// Terms of the x coordinate.
    pub x: [f64; 7],
    /// Terms of the y coordinate.
    pub y: [f64; 7],
    /// How many terms are in use.
    pub n: usize,
}

impl Terms {
    /// The origin (no terms).
    pub const ZERO: Terms = Terms {
        x: [0.0; 7],
        y: [0.0; 7],
        n: 0,
    };

    /// p − s for floats p and s.
    #[inline]
    pub fn diff(p: Vect2, s: Vect2) -> Terms {
        let mut t = Terms::ZERO;
        t.x[0] = p.x;
        t.x[1] = -s.x;
        t.y[0] = p.y;
        t.y[1] = -s.y;
        t.n = 2;
        t
    }

    /// self + k·w for floats k and w (k·w split exactly into two terms per coordinate);
    /// `None` when a product is not error-free or the terms run out.
    #[inline]
    pub fn plus_scaled(mut self, k: f64, w: Vect2) -> Option<Terms> {
        if self.n + 2 > 7 {
            return None;
        }
        let (px, ex) = exact::two_prod(k, w.x)?;
        let (py, ey) = exact::two_prod(k, w.y)?;
        let n = self.n;
        self.x[n] = px;
        self.x[n + 1] = ex;
        self.y[n] = py;
        self.y[n + 1] = ey;
        self.n += 2;
        Some(self)
    }

    /// self − o (the terms of o negated and appended); `None` when they run out.
    #[inline]
    pub fn minus(mut self, o: &Terms) -> Option<Terms> {
        if self.n + o.n > 7 {
            return None;
        }
        for k in 0..o.n {
            self.x[self.n + k] = -o.x[k];
            self.y[self.n + k] = -o.y[k];
        }
        self.n += o.n;
        Some(self)
    }

    /// self − (dx, 0) (one more term); `None` when the terms run out.
    #[inline]
    pub fn shift_x(mut self, dx: f64) -> Option<Terms> {
        if self.n + 1 > 7 {
            return None;
        }
        self.x[self.n] = dx;
        self.y[self.n] = 0.0;
        self.n += 1;
        Some(self)
    }

    /// The x coordinate, exactly.
    fn sx(&self) -> exact::Sum {
        exact::Sum::of(&self.x[..self.n])
    }

    /// The y coordinate, exactly.
    fn sy(&self) -> exact::Sum {
        exact::Sum::of(&self.y[..self.n])
    }

    /// The x terms with one more float appended (`None` when full).
    #[inline]
    fn x_with(&self, extra: f64) -> Option<([f64; 8], usize)> {
        let mut a = [0.0; 8];
        a[..self.n].copy_from_slice(&self.x[..self.n]);
        a[self.n] = extra;
        Some((a, self.n + 1))
    }
}

/// Exact sign of Σ terms + extra.
#[inline]
fn sign_terms(t: &[f64], extra: f64) -> Option<i8> {
    let mut s = exact::Sum::default();
    for &x in t {
        s.add(x);
    }
    s.add(extra);
    s.sign()
}

/// u·w and u × w of two exact vectors, as exact sums.
fn dot_cross(
    ux: &exact::Sum,
    uy: &exact::Sum,
    wx: &exact::Sum,
    wy: &exact::Sum,
) -> [exact::Sum; 2] {
    let mut dot = ux.mul(wx);
    dot.add_sum(&uy.mul(wy), 1.0);
    let mut cross = ux.mul(wy);
    cross.add_sum(&uy.mul(wx), -1.0);
    [dot, cross]
}

/// A Tri from an exact sign: `test` says which signs make it true.
#[inline]
fn tri_of(sign: Option<i8>, test: impl FnOnce(i8) -> bool) -> Tri {
    match sign {
        Some(s) => Tri::from_bool(test(s)),
        None => Tri::Unsure,
    }
}

// ---------------------------------------------------------------- §II.C near_edge

/// §II.C step 1 (and quad_min_le_D step 1 on near_edge's quadratic): the point (the
/// origin) is closer than BUFF to q: ‖q‖² < BUFF², i.e. BUFF² − ‖q‖² > 0 on balls,
/// and exactly on q's terms when the ball cannot tell.
#[inline]
pub fn closer_than(q: BallV, buff: f64, terms: impl FnOnce() -> Option<Terms>) -> Tri {
    match positive(Ball::exact(buff).sq().sub(q.sq())) {
        Tri::Unsure => closer_than_exact(terms(), buff),
        d => d,
    }
}

#[cold]
#[inline(never)]
fn closer_than_exact(t: Option<Terms>, buff: f64) -> Tri {
    let Some(t) = t else { return Tri::Unsure };
    let (x, y) = (t.sx(), t.sy());
    let mut s = exact::Sum::default();
    s.add_prod(buff, buff);
    s.add_sum(&x.mul(&x), -1.0);
    s.add_sum(&y.mul(&y), -1.0);
    tri_of(s.sign(), |v| v > 0)
}

/// §II.C step 2: the interior minimum of near_edge's quadratic
/// ‖a + r(b − a)‖² = e²r² + 2(a·e)r + a² (e = b − a, the point at the origin) lies in
/// (0, 1) and is below BUFF².
///
/// quad_min_le_D step 2 reads a > 0, b ≤ 0, −b ≤ 2a, b² − 4a(c − D) > 0 with a = e²,
/// b = 2a·e, c = a². By Lagrange's identity (a·e)² − a²e² = −(a × e)², so the last test
/// is e²·BUFF² − (a × e)² > 0 (the distance to the line is below BUFF), and
/// a × e = a × b. The middle tests are a·e ≤ 0 and b·e ≥ 0 (the foot of the
/// perpendicular lies on the segment). This form has no cancellation of squared lengths,
/// so its error bound is on the scale of the distances themselves; it is the same real
/// number test, and tests/paper_a_functions_vs_oracle.rs checks it against the exact paper form.
/// Undecided parts are settled exactly on the ends' terms when there are any.
#[inline]
pub fn interior_closer_than(
    a: BallV,
    b: BallV,
    buff: f64,
    terms: impl FnOnce() -> Option<(Terms, Terms)>,
) -> Tri {
    let e = b.sub(a);
    let foot_a = nonnegative(a.dot(e).neg());
    if foot_a == Tri::No {
        return Tri::No;
    }
    let foot_b = nonnegative(b.dot(e));
    if foot_b == Tri::No {
        return Tri::No;
    }
    let line = positive(e.sq().mul(Ball::exact(buff).sq()).sub(a.cross(b).sq()));
    match foot_a.and(foot_b).and(line) {
        Tri::Unsure => interior_exact(terms(), buff),
        d => d,
    }
}

#[cold]
#[inline(never)]
fn interior_exact(t: Option<(Terms, Terms)>, buff: f64) -> Tri {
    let Some((ta, tb)) = t else {
        return Tri::Unsure;
    };
    let (ax, ay, bx, by) = (ta.sx(), ta.sy(), tb.sx(), tb.sy());
    let mut ex = bx.clone();
    ex.add_sum(&ax, -1.0);
    let mut ey = by.clone();
    ey.add_sum(&ay, -1.0);
    let [ae, _] = dot_cross(&ax, &ay, &ex, &ey);
    let [be, _] = dot_cross(&bx, &by, &ex, &ey);
    let [_, axb] = dot_cross(&ax, &ay, &bx, &by);
    let foot = tri_of(ae.sign(), |s| s <= 0).and(tri_of(be.sign(), |s| s >= 0));
    if foot == Tri::No {
        return Tri::No;
    }
    let [e2, _] = dot_cross(&ex, &ey, &ex, &ey);
    let mut bb = exact::Sum::default();
    bb.add_prod(buff, buff);
    let mut line = e2.mul(&bb);
    line.add_sum(&axb.mul(&axb), -1.0);
    foot.and(tri_of(line.sign(), |s| s > 0))
}

// ---------------------------------------------------------------- §II.B perturbation

/// §II.B: vertex q (relative to the point) is moved by the perturbation:
/// q_y ≥ −BUFF and |q_x| ≤ BUFF. Undecided ball tests fall back to the exact terms.
#[inline]
pub fn perturbs(q: BallV, terms: impl Fn() -> Option<Terms>, buff: f64) -> Tri {
    // Fast path: |q_x| certainly above BUFF (the computed |q_x| exceeds an upper bound of
    // BUFF + r, and the exact one is within r of it). Most vertices leave here.
    if q.v.x.abs() > crate::ball::up(buff + q.r) {
        return Tri::No;
    }
    let b = Ball::exact(buff);
    // sign·coord + BUFF ≥ 0, exactly.
    let exact_ge0 = |coord: usize, sign: f64| -> Tri {
        let Some(t) = terms() else { return Tri::Unsure };
        let mut v = [0.0f64; 7];
        let src = if coord == 0 { &t.x } else { &t.y };
        for (d, &s) in v.iter_mut().zip(&src[..t.n]) {
            *d = sign * s;
        }
        tri_of(sign_terms(&v[..t.n], buff), |s| s >= 0)
    };
    let mut y = nonnegative(q.y().add(b));
    if y == Tri::Unsure {
        y = exact_ge0(1, 1.0);
    }
    if y == Tri::No {
        return Tri::No;
    }
    let mut xr = nonnegative(b.sub(q.x()));
    if xr == Tri::Unsure {
        xr = exact_ge0(0, -1.0);
    }
    if xr == Tri::No {
        return Tri::No;
    }
    let mut xl = nonnegative(b.add(q.x()));
    if xl == Tri::Unsure {
        xl = exact_ge0(0, 1.0);
    }
    y.and(xr).and(xl)
}

// ---------------------------------------------------------------- §II.D ray crossing

/// §II.D: vertex q is at or right of the ray's line, q_x ≥ 0. A perturbed vertex is
/// certainly left of it: §II.B moves only vertices with q_x ≤ BUFF, to q_x − 2·BUFF ≤
/// −BUFF < 0. Undecided ball tests fall back to the exact terms.
#[inline]
pub fn at_or_right_of(q: BallV, perturbed: bool, terms: impl FnOnce() -> Option<Terms>) -> Tri {
    if perturbed {
        return Tri::No;
    }
    match nonnegative(q.x()) {
        Tri::Unsure => tri_of(terms().and_then(|t| sign_terms(&t.x[..t.n], 0.0)), |s| {
            s >= 0
        }),
        d => d,
    }
}

/// §II.D: the edge a→b of P*_BUFF crosses the upward ray from the point (the origin):
/// its ends straddle x = 0 and (b_x − a_x)·((0 − a)·(b − a)⊥) ≥ 0.
///
/// (0 − a)·(b − a)⊥ = (b − a) × a = b × a. When both ends are certainly below the
/// point no crossing height can be ≥ 0, and when both are certainly above, every
/// straddling edge crosses above it: both shortcuts are the paper's formula's value.
/// `pa`, `pb` say whether the ends were perturbed (their x is then q_x − 2·BUFF, which
/// the exact terms get as one more term).
#[inline]
pub fn crosses_ray(
    a: BallV,
    b: BallV,
    pa: bool,
    pb: bool,
    ta: impl Fn() -> Option<Terms>,
    tb: impl Fn() -> Option<Terms>,
    buff: f64,
) -> Tri {
    let below = |q: BallV| positive(q.y().neg());
    if below(a) == Tri::Yes && below(b) == Tri::Yes {
        return Tri::No;
    }
    let ra = at_or_right_of(a, pa, &ta);
    let rb = at_or_right_of(b, pb, &tb);
    let straddle = match (ra, rb) {
        (Tri::Unsure, _) | (_, Tri::Unsure) => Tri::Unsure,
        (x, y) => Tri::from_bool(x != y),
    };
    if straddle == Tri::No {
        return Tri::No;
    }
    if positive(a.y()) == Tri::Yes && positive(b.y()) == Tri::Yes {
        return straddle;
    }
    if straddle == Tri::Unsure {
        return Tri::Unsure;
    }
    // a left and b right: b_x − a_x > 0, so the test is b × a ≥ 0; otherwise a × b ≥ 0.
    let b_right = rb == Tri::Yes;
    let (l, r) = if b_right { (b, a) } else { (a, b) };
    match nonnegative(l.cross(r)) {
        Tri::Unsure => {
            let (Some(t_a), Some(t_b)) = (ta(), tb()) else {
                return Tri::Unsure;
            };
            let (tl, tr, pl, pr_) = if b_right {
                (t_b, t_a, pb, pa)
            } else {
                (t_a, t_b, pa, pb)
            };
            let shift = |t: &Terms, p: bool| t.x_with(if p { -2.0 * buff } else { 0.0 });
            let (Some((lx, ln)), Some((rx, rn))) = (shift(&tl, pl), shift(&tr, pr_)) else {
                return Tri::Unsure;
            };
            tri_of(
                exact::sign_cross(&lx[..ln], &tl.y[..tl.n], &rx[..rn], &tr.y[..tr.n]),
                |s| s >= 0,
            )
        }
        d => d,
    }
}

// ---------------------------------------------------------------- §II.G segments

/// §II.G step 4 (quad_min_box_le_D steps 5–6 on segments_close's quadratic): the
/// critical point of ‖(c + r·u) − (e + t·w)‖² lies in the closed unit box and the value
/// there is below BUFF².
///
/// With X = u × w: disc = −4X², mx = 4(q × w)X and my = 4(q × u)X (Lagrange's
/// identity), so the box tests say r* = −(q × w)/X and t* = −(q × u)/X lie in [0, 1],
/// and the value at (r*, t*) is 0 (two non-parallel lines in the plane meet), below
/// BUFF²·disc² exactly when disc ≠ 0. Together: the segments cross, X ≠ 0. Certified
/// here as: c and d on opposite sides of line e f (or on it), e and f on opposite sides
/// of line c d (or on it), and X ≠ 0; exactly on the terms when the balls cannot tell.
#[inline]
pub fn segments_cross(
    c: BallV,
    d: BallV,
    e: BallV,
    f: BallV,
    terms: impl FnOnce() -> Option<[Terms; 4]>,
) -> Tri {
    let w = f.sub(e);
    let u = d.sub(c);
    // r* ∈ [0, 1] ⟺ (w × (c − e))·(w × (d − e)) ≤ 0, and likewise for t*.
    let opposite = |x: Ball, y: Ball| {
        let (xp, xn, yp, yn) = (
            positive(x),
            positive(x.neg()),
            positive(y),
            positive(y.neg()),
        );
        if (xp == Tri::Yes && yp == Tri::Yes) || (xn == Tri::Yes && yn == Tri::Yes) {
            Tri::No
        } else if (xp == Tri::Yes && yn == Tri::Yes) || (xn == Tri::Yes && yp == Tri::Yes) {
            Tri::Yes
        } else {
            Tri::Unsure
        }
    };
    let cd = opposite(w.cross(c.sub(e)), w.cross(d.sub(e)));
    if cd == Tri::No {
        return Tri::No;
    }
    let ef = opposite(u.cross(e.sub(c)), u.cross(f.sub(c)));
    if ef == Tri::No {
        return Tri::No;
    }
    let x = u.cross(w);
    let nonzero = positive(x).or(positive(x.neg()));
    match cd.and(ef).and(nonzero) {
        Tri::Unsure => segments_cross_exact(terms()),
        r => r,
    }
}

#[cold]
#[inline(never)]
fn segments_cross_exact(t: Option<[Terms; 4]>) -> Tri {
    let Some([c, d, e, f]) = t else {
        return Tri::Unsure;
    };
    let sub = |p: &Terms, q: &Terms| {
        let mut x = p.sx();
        x.add_sum(&q.sx(), -1.0);
        let mut y = p.sy();
        y.add_sum(&q.sy(), -1.0);
        (x, y)
    };
    let cross = |a: &(exact::Sum, exact::Sum), b: &(exact::Sum, exact::Sum)| {
        let [_, c] = dot_cross(&a.0, &a.1, &b.0, &b.1);
        c.sign()
    };
    let (w, u) = (sub(&f, &e), sub(&d, &c));
    let side = |s1: Option<i8>, s2: Option<i8>| match (s1, s2) {
        (Some(a), Some(b)) => Tri::from_bool(i16::from(a) * i16::from(b) <= 0),
        _ => Tri::Unsure,
    };
    let cd = side(cross(&w, &sub(&c, &e)), cross(&w, &sub(&d, &e)));
    let ef = side(cross(&u, &sub(&e, &c)), cross(&u, &sub(&f, &c)));
    let x = tri_of(cross(&u, &w), |s| s != 0);
    cd.and(ef).and(x)
}

/// Which side of the line through a (along direction m) q lies on, beyond `dist`:
/// +1 left, −1 right, 0 not certain. |m × (q − a)| > dist·‖m‖ is certified with
/// ‖m‖₂ ≤ ‖m‖₁ (an upper bound, [`BallV::norm1_hi`]). A filter: 0 only means "test".
#[inline]
pub fn side_beyond(a: BallV, m: BallV, q: BallV, dist: f64) -> i8 {
    let c = m.cross(q.sub(a));
    let need = crate::ball::up(dist * m.norm1_hi());
    let need = Ball {
        z: 0.0,
        r: crate::ball::up(c.r + need),
    };
    if c.z > need.r {
        1
    } else if -c.z > need.r {
        -1
    } else {
        0
    }
}

/// The relative path's line through the point (the origin) along d, and a static error
/// bound for the side of a vertex q = fl(p − s) (one rounding per coordinate): the
/// filter of detect_same_2D step 3, per vertex.
///
/// With d̃ known to ±r_d and q̃ to ±2u·|q̃_c| per coordinate, the exact d × q differs
/// from fl(d̃_x·q̃_y − d̃_y·q̃_x) by at most r_d·‖q̃‖₁·(1 + 4u) + 2u(|l| + |r|) (the
/// error of q̃) + 2u(|l| + |r|)(1 + 2u) (the two products and the difference), l and r
/// the two products; 6u(|l| + |r|) covers the last two. A side is reported when the
/// computed cross product clears that bound plus dist·(‖d̃‖₁ + 2r_d) ≥ dist·‖d‖₂, all
/// rounded up by [`crate::ball::up`].
#[derive(Clone, Copy, Debug)]
pub struct PathLine {
    d: Vect2,
    rd: f64,
    need: f64,
}

impl PathLine {
    /// The constant K1 of [`PathLine::side`]'s bound: 6u raised by (1 + 16u).
    pub const K1: f64 = 6.0 * crate::ball::U * (1.0 + 16.0 * crate::ball::U);

    /// The line's direction d̃, its radius term r_d·(1 + 4u) and the constant part of
    /// the bound, for [`crate::lanes`], which evaluates [`PathLine::side`] on several
    /// vertices at once.
    #[inline(always)]
    pub fn parts(&self) -> (Vect2, f64, f64) {
        (self.d, self.rd, self.need)
    }

    /// The line through the origin along the ball d; sides beyond `dist`.
    #[inline]
    pub fn new(d: BallV, dist: f64) -> PathLine {
        let n1 = d.v.x.abs() + d.v.y.abs();
        PathLine {
            d: d.v,
            rd: crate::ball::up(d.r * (1.0 + 4.0 * crate::ball::U)),
            need: crate::ball::up(crate::ball::up(dist * (n1 + 2.0 * d.r))),
        }
    }

    /// +1 when q = fl(p − s) is certainly beyond `dist` on the left of the line, −1 on
    /// the right, 0 when not certain (then the caller tests the edge in full).
    ///
    /// The bound K1·(|l| + |r|) + K2·‖q̃‖₁ + need has its constants raised by (1 + 16u)
    /// beforehand, which covers the four roundings of its own evaluation (all terms are
    /// non-negative) and keeps the dependency chain short.
    #[inline(always)]
    pub fn side(&self, q: Vect2) -> i8 {
        let l = self.d.x * q.y;
        let r = self.d.y * q.x;
        let c = l - r;
        let bound = Self::K1 * (l.abs() + r.abs()) + self.rd * (q.x.abs() + q.y.abs()) + self.need;
        if c > bound {
            1
        } else if -c > bound {
            -1
        } else {
            0
        }
    }
}

/// The side of points q with respect to the line through o along d, where o, q and the
/// line's far end are each known to within ρ per coordinate (the swept-box filter of
/// edge_detect: rounded corners p + t·v and path ends s + t·v), with a static bound.
///
/// d̃ = fl(s1 − s0) is within r_d = 2ρ + 2u‖d̃‖∞ of the exact direction, and
/// w̃ = fl(q − o) within 2ρ + 2u‖w̃‖∞ ≤ 2ρ + 2u‖w̃‖₁ of q − o. The exact d × w then
/// differs from fl(d̃_x·w̃_y − d̃_y·w̃_x) by at most 6u(|l| + |r|) (the products and the
/// difference, l and r the products) + (r_d + 2u‖d̃‖₁)·‖w̃‖₁ + 2ρ‖d̃‖₁ + 2r_d(2ρ + 2u‖w̃‖₁),
/// and |d × w| > dist·(‖d̃‖₁ + 2r_d) puts q farther than dist from the line. The
/// constants are raised by (1 + 16u) beforehand to cover the bound's own roundings.
#[derive(Clone, Copy, Debug)]
pub struct FuzzyLine {
    o: Vect2,
    d: Vect2,
    k2: f64,
    c: f64,
}

impl FuzzyLine {
    /// The constant K1 of [`FuzzyLine::side`]'s bound: 6u raised by (1 + 16u).
    pub const K1: f64 = 6.0 * crate::ball::U * (1.0 + 16.0 * crate::ball::U);

    /// The line through o along d (o and the far end each within ρ); sides beyond `dist`.
    #[inline(always)]
    pub fn new(o: Vect2, d: Vect2, rho: f64, dist: f64) -> FuzzyLine {
        use crate::ball::{mx, up, U};
        let n1 = d.x.abs() + d.y.abs();
        let rd = up(2.0 * rho + 2.0 * U * mx(d.x.abs(), d.y.abs()));
        FuzzyLine {
            o,
            d,
            k2: up(up(rd + 2.0 * U * n1) + 4.0 * U * rd),
            c: up(up(dist * (n1 + 2.0 * rd)) + 2.0 * rho * n1 + 4.0 * rd * rho),
        }
    }

    /// +1 when q is certainly beyond `dist` on the left of the line, −1 on the right,
    /// 0 when not certain.
    #[inline(always)]
    pub fn side(&self, q: Vect2) -> i8 {
        let w = q - self.o;
        let l = self.d.x * w.y;
        let r = self.d.y * w.x;
        let c = l - r;
        let bound = Self::K1 * (l.abs() + r.abs()) + self.k2 * (w.x.abs() + w.y.abs()) + self.c;
        if c > bound {
            1
        } else if -c > bound {
            -1
        } else {
            0
        }
    }
}

// ---------------------------------------------------------------- filters

/// A cheap, rigorous "far apart" test for exact floats: the ranges [a_lo, a_hi] and
/// [b_lo, b_hi] are separated by more than `twice_margin`/2.
///
/// fl(b_lo − a_hi) has relative error ≤ 2⁻⁵³, so fl(b_lo − a_hi) > 2·m implies
/// b_lo − a_hi > 2m/(1 + 2⁻⁵³) > m: callers pass twice the distance they need to exceed.
#[inline(always)]
pub fn ranges_apart(a_lo: f64, a_hi: f64, b_lo: f64, b_hi: f64, twice_margin: f64) -> bool {
    b_lo - a_hi > twice_margin || a_lo - b_hi > twice_margin
}

/// Relative size of the rounding allowance in the swept-box filter of edge_detect:
/// forming p + t·v and a box gap takes ≤ 4 roundings of ≤ 2⁻⁵³ of the largest magnitude
/// M involved; 2⁻⁴⁰·M covers them with a factor 2¹¹ to spare.
pub const SWEEP_ROUNDING: f64 = 1.0 / ((1u64 << 40) as f64);

// ---------------------------------------------------------------- §I quadratics

/// §I quad_min_le_D on balls: is there a t ∈ [0, 1] with a·t² + b·t + c < D?
/// Step 1: c < D or a + b + c < D; step 2: a > 0, b ≤ 0, −b ≤ 2a, b² − 4a(c − D) > 0.
#[inline]
pub fn quad_min_below(a: Ball, b: Ball, c: Ball, d: Ball) -> Tri {
    let ends = positive(d.sub(c)).or(positive(d.sub(a.add(b).add(c))));
    if ends == Tri::Yes {
        return Tri::Yes;
    }
    let interior = positive(a)
        .and(nonnegative(b.neg()))
        .and(nonnegative(a.scale(2.0).add(b)))
        .and(positive(b.sq().sub(a.mul(c.sub(d)).scale(4.0))));
    ends.or(interior)
}

/// §I quad_min_le_D for exact floats, decided exactly (see [`quad_min_below_sums`]).
pub fn quad_min_below_exact(a: f64, b: f64, c: f64, d: f64) -> Option<bool> {
    let x = |v: f64| exact::Sum::of(&[v]);
    quad_min_below_sums(&x(a), &x(b), &x(c), &x(d))
}

/// §I quad_min_le_D for coefficients that are exact sums of floats, decided exactly:
/// every test is the sign of a polynomial in them, evaluated as an expansion. `None`
/// only on overflow or underflow.
pub fn quad_min_below_sums(
    a: &exact::Sum,
    b: &exact::Sum,
    c: &exact::Sum,
    d: &exact::Sum,
) -> Option<bool> {
    let lin = |terms: &[(&exact::Sum, f64)]| {
        let mut s = exact::Sum::default();
        for (t, k) in terms {
            s.add_sum(t, *k);
        }
        s
    };
    if lin(&[(c, 1.0), (d, -1.0)]).sign()? < 0 {
        return Some(true);
    }
    if lin(&[(a, 1.0), (b, 1.0), (c, 1.0), (d, -1.0)]).sign()? < 0 {
        return Some(true);
    }
    if !(a.sign()? > 0 && b.sign()? <= 0) {
        return Some(false);
    }
    // −b ≤ 2a ⟺ 2a + b ≥ 0.
    if lin(&[(a, 1.0), (a, 1.0), (b, 1.0)]).sign()? < 0 {
        return Some(false);
    }
    // b² − 4a(c − D) > 0.
    let mut disc = b.mul(b);
    let four_a = lin(&[(a, 4.0)]);
    disc.add_sum(&four_a.mul(&lin(&[(c, 1.0), (d, -1.0)])), -1.0);
    Some(disc.sign()? > 0)
}

/// §I quad_min_box_le_D steps 5–6 for exact floats, decided exactly as expansions
/// (degree 5 in the coefficients). `None` only on overflow or underflow.
pub fn box_interior_min_below_exact(
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: f64,
    f: f64,
    dd: f64,
) -> Option<bool> {
    let x = |v: f64| exact::Sum::of(&[v]);
    let two = |p: f64, q: f64, r: f64, s_: f64| {
        let mut s = exact::Sum::default();
        s.add_prod(p, q);
        s.add_prod(r, s_);
        s
    };
    let disc = two(c, c, -4.0 * a, b);
    let mx = two(2.0 * b, d, -c, e);
    let my = two(2.0 * a, e, -c, d);
    let disc2 = disc.mul(&disc);
    let mxd = mx.mul(&disc);
    let myd = my.mul(&disc);
    let diff = |p: &exact::Sum, q: &exact::Sum| {
        let mut s = p.clone();
        s.add_sum(q, -1.0);
        s
    };
    let in_box = mxd.sign()? >= 0
        && diff(&disc2, &mxd).sign()? >= 0
        && myd.sign()? >= 0
        && diff(&disc2, &myd).sign()? >= 0;
    if !in_box {
        return Some(false);
    }
    let mut v = x(a).mul(&mx.mul(&mx));
    v.add_sum(&x(b).mul(&my.mul(&my)), 1.0);
    v.add_sum(&x(c).mul(&mx.mul(&my)), 1.0);
    v.add_sum(&x(d).mul(&disc.mul(&mx)), 1.0);
    v.add_sum(&x(e).mul(&disc.mul(&my)), 1.0);
    v.add_sum(&x(f).mul(&disc2), 1.0);
    Some(diff(&x(dd).mul(&disc2), &v).sign()? > 0)
}

/// §I quad_min_box_le_D steps 5–6 on balls: the critical point (mx/disc, my/disc) lies
/// in the closed unit box and the value there, scaled by disc², is below D·disc².
#[inline]
pub fn box_interior_min_below(
    a: Ball,
    b: Ball,
    c: Ball,
    d: Ball,
    e: Ball,
    f: Ball,
    dd: Ball,
) -> Tri {
    let disc = c.sq().sub(a.mul(b).scale(4.0));
    let mx = b.mul(d).scale(2.0).sub(c.mul(e));
    let my = a.mul(e).scale(2.0).sub(c.mul(d));
    let disc2 = disc.sq();
    let mxd = mx.mul(disc);
    let myd = my.mul(disc);
    let in_box = nonnegative(mxd)
        .and(nonnegative(disc2.sub(mxd)))
        .and(nonnegative(myd))
        .and(nonnegative(disc2.sub(myd)));
    if in_box == Tri::No {
        return Tri::No;
    }
    let v = a
        .mul(mx.sq())
        .add(b.mul(my.sq()))
        .add(c.mul(mx).mul(my))
        .add(d.mul(disc).mul(mx))
        .add(e.mul(disc).mul(my))
        .add(f.mul(disc2));
    in_box.and(positive(dd.mul(disc2).sub(v)))
}

// ---------------------------------------------------------------- §II.J well formed

// well_formed (§II.J) is information only: a polygon that is not well formed is still
// checked, never answered "no detection" for that reason. Its comparisons are the
// paper's, in f64, with no certificate; tests/paper_a_functions_vs_oracle.rs compares them with
// the exact oracle on dyadic grids.

/// §II.J step 1: ‖p − q‖ < 2·BUFF, as ‖p − q‖² < 4·BUFF² (information only).
#[inline(always)]
pub fn vertices_too_close(p: Vect2, q: Vect2, buff: f64) -> bool {
    (p - q).sq() < 4.0 * buff * buff
}

/// §II.J step 3: the corner between consecutive edges g and h is sharper than κ:
/// g·h < −cos κ·‖g‖·‖h‖ (information only).
#[inline(always)]
pub fn corner_too_sharp(g: Vect2, h: Vect2, cos_kappa: f64) -> bool {
    g.dot(h) < -cos_kappa * crate::vect2::sqrt(g.sq() * h.sq())
}

/// §II.J step 4: the polygon does not turn left at the extremal vertex:
/// (p_i − p_prev)·(p_next − p_i)⊥ ≤ 0 (information only).
#[inline(always)]
pub fn turns_right_or_straight(prev: Vect2, cur: Vect2, next: Vect2) -> bool {
    (cur - prev).dot((next - cur).perp()) <= 0.0
}

/// §II.J step 4: p is lexicographically below q (exact float comparisons).
#[inline(always)]
pub fn lex_less(p: Vect2, q: Vect2) -> bool {
    p.x < q.x || (p.x == q.x && p.y < q.y)
}

/// Paper A §II (BUFF > 0 throughout): BUFF outside the paper's domain (below 0, or NaN): the slice functions that take it
/// answer undecided (see the crate docs' contract). −0 is in the domain, as 0.
#[inline(always)]
pub fn buff_outside_domain(buff: f64) -> bool {
    buff.is_nan() || buff < 0.0
}

/// §II.H/§II.I dispatch: two input velocities are identical (exact float comparison).
#[inline(always)]
pub fn same_velocity(a: Vect2, b: Vect2) -> bool {
    a == b
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bv(x: f64, y: f64) -> BallV {
        BallV::exact(Vect2::new(x, y))
    }

    #[test]
    fn closer_than_is_strict_and_certified() {
        let t = |x: f64, y: f64| move || Some(Terms::diff(Vect2::new(x, y), Vect2::ZERO));
        // Exactly BUFF away: the ball cannot tell, the exact terms can.
        assert_eq!(closer_than(bv(3.0, 4.0), 5.0, || None), Tri::Unsure);
        assert_eq!(closer_than(bv(3.0, 4.0), 5.0, t(3.0, 4.0)), Tri::No);
        assert_eq!(closer_than(bv(3.0, 4.0), 5.0 + 1e-9, || None), Tri::Yes);
        assert_eq!(closer_than(bv(3.0, 4.0), 5.0 - 1e-9, || None), Tri::No);
        // A vertex exactly BUFF away but known only to within 1e-12: undecided.
        let fuzzy = BallV {
            v: Vect2::new(3.0, 4.0),
            r: 1e-12,
        };
        assert_eq!(closer_than(fuzzy, 5.0, || None), Tri::Unsure);
    }

    #[test]
    fn perturbation_thresholds_are_exact_with_terms() {
        // p_x − s_x = 1.1 − 1 is exact (Sterbenz); with BUFF equal to it the test
        // |p_x − s_x| ≤ BUFF is an equality, decided on the exact terms.
        let s = Vect2::new(1.0, 1.0);
        let p = Vect2::new(1.1, 5.0);
        let buff = 1.1 - 1.0; // exactly p_x − s_x (Sterbenz)
        let q = BallV::diff(p, s);
        let t = Terms::diff(p, s);
        assert_eq!(perturbs(q, || Some(t), buff), Tri::Yes);
        // One ulp less BUFF: certainly not moved.
        let smaller = f64::from_bits(buff.to_bits() - 1);
        assert_eq!(perturbs(q, || Some(t), smaller), Tri::No);
    }

    #[test]
    fn a_ray_crossing_at_a_tie_is_decided_on_the_moved_vertex() {
        // BUFF = 1/2 and the point at the origin; a is moved by §II.B to a* = a − (1, 0).
        // Each edge a* b runs exactly through the point (b × a* = 0): the crossing
        // height is 0, on the ray, so the edge crosses. The balls see only a zero with
        // an error bound; the exact terms decide, and must carry a's −2·BUFF term.
        let buff = 0.5;
        let t = |q: Vect2| move || Some(Terms::diff(q, Vect2::ZERO));
        let shifted = |q: Vect2| bv(q.x - 2.0 * buff, q.y);
        for (a, b) in [
            // a below the point: unmoved, or moved right instead, b × a < 0.
            (Vect2::new(0.5, -0.25), Vect2::new(1.0, 0.5)),
            // a above it: moved further left (by 3/2 or by 4), b × a < 0.
            (Vect2::new(0.5, 0.25), Vect2::new(1.0, -0.5)),
        ] {
            let (a_star, b_ball) = (shifted(a), bv(b.x, b.y));
            assert_eq!(b.x * a_star.v.y - b.y * a_star.v.x, 0.0);
            assert_eq!(
                crosses_ray(a_star, b_ball, true, false, t(a), t(b), buff),
                Tri::Yes,
                "a = {a:?}, b = {b:?}"
            );
            // Without exact terms the tie is undecided.
            assert_eq!(
                crosses_ray(a_star, b_ball, true, false, || None, || None, buff),
                Tri::Unsure
            );
        }
    }

    #[test]
    fn segments_at_a_tie_are_decided_on_the_exact_terms() {
        // d lies on segment e f: the orientation of d against e f is an exact zero,
        // which the balls cannot sign. r* = 1 and t* = 1/2 lie in the closed box and the
        // lines are not parallel: the segments cross (they meet at d).
        let (c, d, e, f) = (
            Vect2::new(0.0, -1.0),
            Vect2::new(0.0, 0.0),
            Vect2::new(-1.0, 0.0),
            Vect2::new(1.0, 0.0),
        );
        let terms = || Some([c, d, e, f].map(|p| Terms::diff(p, c)));
        let balls = [c, d, e, f].map(|p| BallV::diff(p, c));
        let [bc, bd, be, bf] = balls;
        assert_eq!(segments_cross(bc, bd, be, bf, || None), Tri::Unsure);
        assert_eq!(segments_cross(bc, bd, be, bf, terms), Tri::Yes);
        // d one step short of the line (−1/4 below it): certainly no crossing.
        let d2 = Vect2::new(0.0, -0.25);
        let terms2 = || Some([c, d2, e, f].map(|p| Terms::diff(p, c)));
        let bd2 = BallV::diff(d2, c);
        assert_eq!(segments_cross(bc, bd2, be, bf, terms2), Tri::No);
        // d = (3, 3 − 2⁻⁵¹) just short of the line y = x through e f, on c's side: the
        // orientation −6·2⁻⁵¹ is below the balls' resolution, and e, f are on opposite
        // sides of line c d. The exact terms say c and d are on one side: no crossing,
        // whichever way round the segments run.
        let (d, e, f) = (
            Vect2::new(3.0, 3.0 - 2f64.powi(-51)),
            Vect2::new(-1.0, -1.0),
            Vect2::new(5.0, 5.0),
        );
        for (c, d, e, f) in [(c, d, e, f), (c, d, f, e), (d, c, e, f), (d, c, f, e)] {
            let terms = || Some([c, d, e, f].map(|p| Terms::diff(p, c)));
            let [bc, bd, be, bf] = [c, d, e, f].map(|p| BallV::diff(p, c));
            assert_eq!(segments_cross(bc, bd, be, bf, || None), Tri::Unsure);
            assert_eq!(segments_cross(bc, bd, be, bf, terms), Tri::No);
        }
    }

    #[test]
    fn exact_box_minimum_agrees_with_hand_cases() {
        // (x − 1/2)² + (y − 1/2)² + 1: its minimum 1 at the box's centre.
        let f = |dd: f64| box_interior_min_below_exact(1.0, 1.0, 0.0, -1.0, -1.0, 1.5, dd);
        assert_eq!(f(1.0), Some(false));
        assert_eq!(f(1.0 + 2f64.powi(-52)), Some(true));
        // x² + y² + xy − x − y + 1: minimum 2/3 at (1/3, 1/3) (a cross term).
        let g = |dd: f64| box_interior_min_below_exact(1.0, 1.0, 1.0, -1.0, -1.0, 1.0, dd);
        assert_eq!(g(0.7), Some(true));
        assert_eq!(g(0.6), Some(false));
        // the minimum (3/2, 1/2) outside the box: no interior minimum
        let h = box_interior_min_below_exact(1.0, 1.0, 0.0, -3.0, -1.0, 10.0, 100.0);
        assert_eq!(h, Some(false));
    }

    #[test]
    fn exact_quad_agrees_with_hand_cases() {
        // (t − 1/2)² + 1: minimum 1.
        assert_eq!(quad_min_below_exact(1.0, -1.0, 1.25, 1.0), Some(false));
        assert_eq!(
            quad_min_below_exact(1.0, -1.0, 1.25, 1.0 + 2f64.powi(-52)),
            Some(true)
        );
        // Ends: 2 − t < 1.5 near t = 1.
        assert_eq!(quad_min_below_exact(0.0, -1.0, 2.0, 1.5), Some(true));
        // (2t − 1)²: minimum exactly 0, not below 0.
        assert_eq!(quad_min_below_exact(4.0, -4.0, 1.0, 0.0), Some(false));
    }
}
