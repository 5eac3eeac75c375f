//! Recovery points: the nearest way out of a polygon's D-neighbourhood, or into its
//! D-core (paper A §II's polygons, §II.G's proximity as the distance to a segment, and
//! §II–§III's motion for the `_at` forms).
//!
//! # Definitions
//! P is a simple counterclockwise polygon (closed, with its interior), s a point, D ≥ 0,
//! dist the Euclidean distance in the plane (dist(x, P) = 0 inside P) and ∂P the boundary.
//! - [`recovery_out`]: the nearest x to s with **dist(x, P) ≥ D** (s itself when it is).
//! - [`recovery_in`]: the nearest x to s with **x ∈ P and dist(x, ∂P) ≥ D**; when no point
//!   of P is that deep, [`Recovery::Impossible`].
//! - [`recovery_out_at`], [`recovery_in_at`]: the same for the exact polygon
//!   P(t) = (p_i + t·V_i) of a moving polygon at time t. Each vertex is taken as a ball
//!   about its f64 evaluation, which covers the rounding, and as the exact terms
//!   p_i − x + t·V_i (t·V_i split without error) where a predicate falls back to exact
//!   signs.
//!
//! # Method
//! The minimum m = min {|x − s| : x feasible} is attained on the boundary of the feasible
//! set, made of pieces of *features*: each edge shifted by D along its normal (outward for
//! `out`, inward for `in`) and each circle of radius D around a vertex. The nearest point
//! is either a local minimum of the distance to s along one feature (the clamped
//! projection of s on a shifted edge, the point of a circle on the ray from its centre
//! through s) or an end of a piece, where two features meet (pairwise intersections).
//! Every candidate is computed on balls (see `crate::ball`): the exact candidate lies
//! in its ball. A candidate whose ball certainly breaks the condition (some vertex or
//! edge certainly closer than D, or the point certainly on the wrong side of ∂P) cannot
//! be the minimiser; the lower end of the distance of every other candidate bounds m from
//! below: that is **min_lo** (0 when s itself is not certainly infeasible). The nearest candidate not certainly infeasible is then
//! pushed off its features (along the sum of their normals) by a bounded amount δ and the
//! resulting f64 point x is certified with the predicates of `crate::predicates` (on
//! balls, with their exact fallbacks): every vertex and edge at least D away, and the
//! crossing parity of §II.D deciding the side. **dist_hi** is a certified upper bound of
//! |x − s|. A point certified in this way satisfies its condition for the exact inputs.
//!
//! D = 0: every point is out of P's 0-neighbourhood (s is returned), and the 0-core is P
//! itself: its candidates are the nearest points of the edges and the vertices (pushed
//! into P along the inward bisector); no side test applies on ∂P, so none is dropped by
//! one. A shifted edge meets the circles about its own ends at its two ends, which are
//! taken as they are rather than as the double root of a quadratic.
//!
//! # Guarantees and tolerance
//! For a returned [`Recovery::Point`]: x satisfies its condition exactly, and
//! min_lo ≤ m ≤ |x − s| ≤ dist_hi. With the scale S = max(|s|∞, maxᵢ |vᵢ − s|∞, D), the
//! push δ is 0 first (a candidate may be exact), then S·2⁻⁵⁰·4ᵏ for k = 0, …, 9, the first
//! that certifies (so δ ≤ S·2⁻³²); the next candidate is tried when none does. And
//! when the certified candidate is the nearest one not certainly infeasible the gap is
//!
//! **dist_hi − min_lo ≤ δ + 2ρ + 8u·|x − s| ≤ [`REL_TOL`]·S = 2⁻³⁰·S**,
//!
//! where ρ is the candidate's ball radius (a few u·S for well-conditioned features) and
//! u = 2⁻⁵³. Near-degenerate inputs (a candidate within rounding of the condition that
//! cannot be certified, nearly parallel shifted edges whose intersection is undecided)
//! can widen the gap; the bounds stay certified.
//!
//! [`Recovery::Impossible`] for `recovery_in` is certified too: s and every candidate
//! certainly break the condition, and if the feasible set were not empty its nearest
//! point to s would be one of them and satisfy it.
//!
//! The candidates are O(n²) and each is checked against n edges: O(n³) for n vertices,
//! meant for polygons of tens of vertices.

use std::vec::Vec;

use crate::ball::{exact, mx, round_down, round_up, Ball, BallV, Tri};
use crate::predicates::{closer_than, crosses_ray, interior_closer_than, Terms};
use crate::vect2::Vect2;

/// The tolerance factor of the gap dist_hi − min_lo, relative to the scale S of the
/// module doc: the largest push 2⁻³²·S, plus twice the candidate's radius and the
/// rounding of dist_hi (each far below 2⁻³²·S), with room: 2⁻³⁰.
pub const REL_TOL: f64 = 1.0 / 1_073_741_824.0;

/// How many times the push is multiplied by 4 before a candidate is given up:
/// δ runs over S·2⁻⁵⁰ … S·2⁻³².
const PUSH_STEPS: i32 = 10;

/// The answer of a recovery query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Recovery {
    /// A certified recovery point.
    Point {
        /// The point (it satisfies its condition for the exact inputs).
        x: Vect2,
        /// A certified upper bound of |x − s|.
        dist_hi: f64,
        /// A certified lower bound of the exact minimum distance m.
        min_lo: f64,
        /// s itself is certified to satisfy the condition (then x = s). False when it
        /// does not, or when that could not be certified (a point of ∂P with D = 0).
        clear: bool,
    },
    /// The feasible set is empty (certified).
    Impossible {
        /// Why, in words.
        reason: &'static str,
    },
}

/// What a recovery query refuses, each naming its field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RecoveryError {
    /// NaN or ±∞ in a field (`p`, `vels`, `s`, `t`, `sep`).
    NotFinite {
        /// The field.
        field: &'static str,
    },
    /// The separation D is negative.
    NegativeSep {
        /// Its value.
        value: f64,
    },
    /// Fewer than 3 vertices.
    TooFewVertices {
        /// How many there are.
        found: usize,
    },
    /// `vels` and `p` differ in length.
    VelsLength {
        /// The number of vertices.
        expected: usize,
        /// The number of velocities.
        found: usize,
    },
    /// The polygon is not certainly counterclockwise (signed area not certainly > 0).
    NotCounterclockwise,
    /// No candidate could be certified (a near-degenerate input within rounding).
    Uncertified,
}

impl RecoveryError {
    /// The field the error is about.
    pub fn field(&self) -> &'static str {
        match self {
            RecoveryError::NotFinite { field } => field,
            RecoveryError::NegativeSep { .. } => "sep",
            RecoveryError::TooFewVertices { .. } | RecoveryError::NotCounterclockwise => "p",
            RecoveryError::VelsLength { .. } => "vels",
            RecoveryError::Uncertified => "p",
        }
    }
}

impl core::fmt::Display for RecoveryError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            RecoveryError::NotFinite { field } => write!(f, "{field}: not finite"),
            RecoveryError::NegativeSep { value } => write!(f, "sep: {value} is negative"),
            RecoveryError::TooFewVertices { found } => {
                write!(f, "p: {found} vertices, at least 3 needed")
            }
            RecoveryError::VelsLength { expected, found } => {
                write!(f, "vels: {found} velocities for {expected} vertices")
            }
            RecoveryError::NotCounterclockwise => {
                write!(f, "p: not certainly counterclockwise")
            }
            RecoveryError::Uncertified => {
                write!(
                    f,
                    "p: no recovery point could be certified (near-degenerate input)"
                )
            }
        }
    }
}

impl std::error::Error for RecoveryError {}

/// Out of P's D-neighbourhood: the nearest x with dist(x, P) ≥ D (module doc).
pub fn recovery_out(p: &[Vect2], s: Vect2, d: f64) -> Result<Recovery, RecoveryError> {
    Shape::new(p, None, s, d)?.solve(Side::Out)
}

/// Into P's D-core: the nearest x ∈ P with dist(x, ∂P) ≥ D, or `Impossible` (module doc).
pub fn recovery_in(p: &[Vect2], s: Vect2, d: f64) -> Result<Recovery, RecoveryError> {
    Shape::new(p, None, s, d)?.solve(Side::In)
}

/// [`recovery_out`] for the exact polygon (p_i + t·V_i) at time t (§II–§III motion).
pub fn recovery_out_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    s: Vect2,
    d: f64,
) -> Result<Recovery, RecoveryError> {
    Shape::new(p, Some((vels, t)), s, d)?.solve(Side::Out)
}

/// [`recovery_in`] for the exact polygon (p_i + t·V_i) at time t (§II–§III motion).
pub fn recovery_in_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    s: Vect2,
    d: f64,
) -> Result<Recovery, RecoveryError> {
    Shape::new(p, Some((vels, t)), s, d)?.solve(Side::In)
}

/// Which condition: out of the D-neighbourhood or into the D-core.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Side {
    Out,
    In,
}

/// The polygon at time t, the point and D, validated.
struct Shape<'a> {
    p: &'a [Vect2],
    vels: Option<(&'a [Vect2], f64)>,
    s: Vect2,
    d: f64,
    /// The vertices relative to s, as balls.
    q: Vec<BallV>,
}

/// A shifted edge (see `Shape::line`).
struct Line {
    e: BallV,
    big_e: Ball,
    p0: Option<BallV>,
    c: Ball,
    nn: Vect2,
}

/// One candidate: its ball (relative to s) or none, a certified lower bound of its
/// distance to s, and the direction to push it off its features.
struct Cand {
    c: Option<BallV>,
    lo: f64,
    dir: Vect2,
}

/// √ of a ball, as an interval (the lower end clamped at 0); a NaN ball if it is
/// certainly negative or unbounded. Each √ is one correctly rounded operation.
fn sqrt_ball(b: Ball) -> Ball {
    let (lo, hi) = (b.lo().max(0.0), b.hi());
    if !(hi >= 0.0 && hi.is_finite()) {
        return Ball {
            z: f64::NAN,
            r: f64::INFINITY,
        };
    }
    Ball::from_interval(round_down(lo.sqrt()).max(0.0), round_up(hi.sqrt()))
}

/// a / b when b is certainly non-zero, as the interval of the four corner quotients
/// (each one rounding); `None` otherwise.
fn div_ball(a: Ball, b: Ball) -> Option<Ball> {
    let (bl, bh) = (b.lo(), b.hi());
    if !(bl.is_finite() && bh.is_finite()) || (bl <= 0.0 && bh >= 0.0) {
        return None;
    }
    let (al, ah) = (a.lo(), a.hi());
    let qs = [al / bl, al / bh, ah / bl, ah / bh];
    let lo = qs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = qs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    Some(Ball::from_interval(round_down(lo), round_up(hi)))
}

/// The ball clamped to [0, 1] (clamping is monotone, so the ends clamp).
fn clamp01(b: Ball) -> Ball {
    let lo = b.lo().clamp(0.0, 1.0);
    let hi = b.hi().clamp(0.0, 1.0);
    if lo == hi {
        Ball::exact(lo)
    } else {
        Ball::from_interval(lo, hi)
    }
}

/// A point from two coordinate balls.
fn pt(x: Ball, y: Ball) -> BallV {
    BallV {
        v: Vect2::new(x.z, y.z),
        r: mx(x.r, y.r),
    }
}

/// A unit-ish direction (f64, uncertified: only the push uses it).
fn unit(v: Vect2) -> Vect2 {
    let n = v.sq().sqrt();
    if n > 0.0 && n.is_finite() {
        v.scale(1.0 / n)
    } else {
        Vect2::ZERO
    }
}

impl<'a> Shape<'a> {
    /// Validates the inputs and computes the vertices relative to s.
    fn new(
        p: &'a [Vect2],
        vels: Option<(&'a [Vect2], f64)>,
        s: Vect2,
        d: f64,
    ) -> Result<Shape<'a>, RecoveryError> {
        if p.len() < 3 {
            return Err(RecoveryError::TooFewVertices { found: p.len() });
        }
        let bad = |field| Err(RecoveryError::NotFinite { field });
        if !p.iter().all(|v| v.is_finite()) {
            return bad("p");
        }
        if !s.is_finite() {
            return bad("s");
        }
        if !d.is_finite() {
            return bad("sep");
        }
        if d < 0.0 {
            return Err(RecoveryError::NegativeSep { value: d });
        }
        if let Some((v, t)) = vels {
            if !t.is_finite() {
                return bad("t");
            }
            if v.len() != p.len() {
                return Err(RecoveryError::VelsLength {
                    expected: p.len(),
                    found: v.len(),
                });
            }
            if !v.iter().all(|w| w.is_finite()) {
                return bad("vels");
            }
        }
        let mut sh = Shape {
            p,
            vels,
            s,
            d,
            q: Vec::new(),
        };
        sh.q = (0..p.len()).map(|i| sh.rel(i, s)).collect();
        if !sh.q.iter().all(|b| b.is_finite()) {
            return bad("p");
        }
        // Counterclockwise: at rest, the exact orientation of the ring (`ring::winding`,
        // the turn at its lexicographically least vertex, as the case format checks it);
        // moving, twice the signed area about the first vertex, Σ (qᵢ − q₀) × (qᵢ₊₁ − q₀)
        // > 0, certified on balls (about the first vertex rather than about s, so that a
        // small polygon far from s is not lost in the rounding of |p − s|).
        let ccw = match vels {
            None => crate::ring::winding(p) == Ok(crate::ring::Winding::Counterclockwise),
            Some(_) => {
                let mut area = Ball::exact(0.0);
                let q0 = sh.q[0];
                for i in 1..sh.n() - 1 {
                    area = area.add(sh.q[i].sub(q0).cross(sh.q[i + 1].sub(q0)));
                }
                crate::ball::positive(area) == Tri::Yes
            }
        };
        if !ccw {
            return Err(RecoveryError::NotCounterclockwise);
        }
        Ok(sh)
    }

    fn n(&self) -> usize {
        self.p.len()
    }

    fn next(&self, i: usize) -> usize {
        (i + 1) % self.n()
    }

    /// Vertex i at time t minus x, as a ball: p_i − x (+ t·V_i).
    fn rel(&self, i: usize, x: Vect2) -> BallV {
        let b = BallV::diff(self.p[i], x);
        match self.vels {
            None => b,
            Some((v, t)) => b.add(BallV::exact(v[i]).scale(Ball::exact(t))),
        }
    }

    /// Vertex i at time t minus x, as exact terms.
    fn terms(&self, i: usize, x: Vect2) -> Option<Terms> {
        let tm = Terms::diff(self.p[i], x);
        match self.vels {
            None => Some(tm),
            Some((v, t)) => tm.plus_scaled(t, v[i]),
        }
    }

    /// The scale S of the module doc.
    fn scale(&self) -> f64 {
        let m = self
            .q
            .iter()
            .fold(0.0f64, |m, b| mx(m, mx(b.v.x.abs(), b.v.y.abs()) + b.r));
        mx(mx(m, self.d), mx(self.s.x.abs(), self.s.y.abs()))
    }

    /// Solves one side (module doc: candidates, filter, push, certify).
    fn solve(&self, side: Side) -> Result<Recovery, RecoveryError> {
        if side == Side::Out && self.d == 0.0 {
            return Ok(self.clear());
        }
        let s_tri = self.certify(side, self.s);
        if s_tri == Tri::Yes {
            return Ok(self.clear());
        }
        let mut cands: Vec<Cand> = self.candidates(side);
        cands.retain(|c| self.possible(side, c) != Tri::No);
        let mut min_lo = cands.iter().fold(f64::INFINITY, |m, c| m.min(c.lo));
        if s_tri == Tri::Unsure {
            min_lo = 0.0;
        }
        if cands.is_empty() && s_tri == Tri::Unsure {
            // s may be feasible itself: nothing certain either way.
            return Err(RecoveryError::Uncertified);
        }
        if cands.is_empty() {
            return Ok(Recovery::Impossible {
                reason: "no point of P is D from its boundary: its inradius is below D",
            });
        }
        cands.sort_by(|a, b| a.lo.total_cmp(&b.lo));
        let scale = self.scale();
        for c in cands.iter() {
            let Some(ball) = c.c else { continue };
            for k in 0..=PUSH_STEPS {
                // First unpushed (a candidate may be exact), then δ = S·2⁻⁵⁰·4ᵏ⁻¹.
                let delta = if k == 0 {
                    0.0
                } else {
                    scale * (2f64).powi(-52 + 2 * k)
                };
                let rel = ball.v + c.dir.scale(delta);
                let x = self.s + rel;
                if self.certify(side, x) == Tri::Yes {
                    let dx = BallV::diff(x, self.s);
                    let dist_hi = sqrt_ball(dx.sq()).hi();
                    return Ok(Recovery::Point {
                        x,
                        dist_hi,
                        min_lo: min_lo.min(dist_hi),
                        clear: false,
                    });
                }
            }
        }
        Err(RecoveryError::Uncertified)
    }

    /// s itself, already clear.
    fn clear(&self) -> Recovery {
        Recovery::Point {
            x: self.s,
            dist_hi: 0.0,
            min_lo: 0.0,
            clear: true,
        }
    }

    /// Is the exact f64 point x certainly feasible? Every vertex and every edge at least
    /// D from x (the §II.C tests `closer_than`, `interior_closer_than` certainly false),
    /// and the crossing parity (§II.D) certainly on the right side. `No` only when x is
    /// certainly infeasible.
    fn certify(&self, side: Side, x: Vect2) -> Tri {
        let n = self.n();
        let rel: Vec<BallV> = (0..n).map(|i| self.rel(i, x)).collect();
        let mut far = Tri::Yes;
        for j in 0..n {
            let k = self.next(j);
            let near = closer_than(rel[j], self.d, || self.terms(j, x)).or(interior_closer_than(
                rel[j],
                rel[k],
                self.d,
                || Some((self.terms(j, x)?, self.terms(k, x)?)),
            ));
            far = far.and(near.not());
            if far == Tri::No {
                return Tri::No;
            }
        }
        let inside = self.parity(&rel, |i| self.terms(i, x));
        let side_ok = match side {
            Side::Out => inside.not(),
            // With D = 0 a point of ∂P is feasible, and the parity of a point on ∂P says
            // nothing: an even parity proves x outside P only with x on no edge. (With
            // D > 0 a point on ∂P is infeasible either way.)
            Side::In if self.d == 0.0 && inside == Tri::No => match self.off_boundary(&rel, x) {
                Tri::Yes => Tri::No,
                _ => Tri::Unsure,
            },
            Side::In => inside,
        };
        far.and(side_ok)
    }

    /// Is x on no edge of P? Per edge a b (vertices minus x): on it exactly when
    /// a × b = 0 and a·b ≤ 0; decided on balls, else exactly on the terms.
    fn off_boundary(&self, rel: &[BallV], x: Vect2) -> Tri {
        let mut off = Tri::Yes;
        for j in 0..self.n() {
            let k = self.next(j);
            let (a, b) = (rel[j], rel[k]);
            let cross = a.cross(b);
            let ball_off = crate::ball::positive(cross)
                .or(crate::ball::positive(cross.neg()))
                .or(crate::ball::positive(a.dot(b)));
            let edge_off = match ball_off {
                Tri::Yes => Tri::Yes,
                _ => self.off_edge_exact(j, k, x),
            };
            off = off.and(edge_off);
            if off == Tri::No {
                return off;
            }
        }
        off
    }

    /// [`Shape::off_boundary`]'s test of one edge, on the exact terms.
    fn off_edge_exact(&self, j: usize, k: usize, x: Vect2) -> Tri {
        let (Some(ta), Some(tb)) = (self.terms(j, x), self.terms(k, x)) else {
            return Tri::Unsure;
        };
        let sum = |t: &[f64]| exact::Sum::of(t);
        let (ax, ay) = (sum(&ta.x[..ta.n]), sum(&ta.y[..ta.n]));
        let (bx, by) = (sum(&tb.x[..tb.n]), sum(&tb.y[..tb.n]));
        let mut cross = ax.mul(&by);
        cross.add_sum(&ay.mul(&bx), -1.0);
        let mut dot = ax.mul(&bx);
        dot.add_sum(&ay.mul(&by), 1.0);
        match (cross.sign(), dot.sign()) {
            (Some(0), Some(d)) => Tri::from_bool(d > 0),
            (Some(_), _) => Tri::Yes,
            _ => Tri::Unsure,
        }
    }

    /// The crossing parity of the upward ray from the point whose vertex offsets are
    /// `rel` (§II.D's test per edge): Yes for odd (inside, or on ∂P).
    fn parity(&self, rel: &[BallV], terms: impl Fn(usize) -> Option<Terms>) -> Tri {
        let mut odd = false;
        for j in 0..self.n() {
            let k = self.next(j);
            match crosses_ray(rel[j], rel[k], false, false, || terms(j), || terms(k), 0.0) {
                Tri::Yes => odd = !odd,
                Tri::No => {}
                Tri::Unsure => return Tri::Unsure,
            }
        }
        Tri::from_bool(odd)
    }

    /// Could the candidate be feasible? `No` when its ball certainly breaks the condition.
    fn possible(&self, side: Side, c: &Cand) -> Tri {
        let Some(b) = c.c else { return Tri::Unsure };
        let rel: Vec<BallV> = self.q.iter().map(|q| q.sub(b)).collect();
        let n = self.n();
        for j in 0..n {
            let k = self.next(j);
            let near = closer_than(rel[j], self.d, || None).or(interior_closer_than(
                rel[j],
                rel[k],
                self.d,
                || None,
            ));
            if near == Tri::Yes {
                return Tri::No;
            }
        }
        if self.d == 0.0 {
            // The feasible candidates lie on ∂P, where the parity says nothing.
            return Tri::Unsure;
        }
        let wrong_side = matches!(
            (side, self.parity(&rel, |_| None)),
            (Side::Out, Tri::Yes) | (Side::In, Tri::No)
        );
        if wrong_side {
            Tri::No
        } else {
            Tri::Unsure
        }
    }

    /// A candidate from its ball (relative to s) and push direction.
    fn cand(c: BallV, dir: Vect2) -> Cand {
        let lo = sqrt_ball(c.sq()).lo().max(0.0);
        Cand {
            c: Some(c),
            lo: if lo.is_finite() { lo } else { 0.0 },
            dir: unit(dir),
        }
    }

    /// A candidate whose place is undecided: it only bounds min_lo, by `lo`.
    fn unplaced(lo: f64) -> Cand {
        Cand {
            c: None,
            lo: lo.max(0.0),
            dir: Vect2::ZERO,
        }
    }

    /// Shifted edge i: e, N = e⊥ (outward for ccw), E = |e|², the shifted start
    /// p0 = q + N·σD/√E, the line N·x = N·q + σD√E, and the push direction σN̂.
    fn line(&self, i: usize, sig: f64) -> Line {
        let sd = Ball::exact(sig * self.d);
        let q = self.q[i];
        let e = self.q[self.next(i)].sub(q);
        let big_e = e.sq();
        let root = sqrt_ball(big_e);
        let nvec = e.perp();
        Line {
            e,
            big_e,
            p0: div_ball(sd, root).map(|k| q.add(nvec.scale(k))),
            c: nvec.dot(q).add(sd.mul(root)),
            nn: unit(e.v.perp()).scale(sig),
        }
    }

    /// Every candidate of the module doc, relative to s.
    fn candidates(&self, side: Side) -> Vec<Cand> {
        let n = self.n();
        let sig = if side == Side::Out { 1.0 } else { -1.0 };
        let lines: Vec<Line> = (0..n).map(|i| self.line(i, sig)).collect();
        let mut out = Vec::new();
        for l in &lines {
            // The clamped projection of s (the origin) on the shifted edge.
            let tau =
                l.p0.and_then(|p0| Some((p0, div_ball(p0.neg().dot(l.e), l.big_e)?)));
            out.push(match tau {
                Some((p0, tau)) => Self::cand(p0.add(l.e.scale(clamp01(tau))), l.nn),
                None => Self::unplaced(0.0),
            });
        }
        for (i, q) in self.q.iter().enumerate() {
            // The point of the circle on the ray from its centre through s, pushed away
            // from the centre; with D = 0 (only `in` gets here) the circle is the vertex,
            // pushed into P along the inward bisector (the sum of the two edges' push
            // directions σN̂, inward for `in`).
            let w = q.neg();
            let len = sqrt_ball(w.sq());
            let dir = if self.d == 0.0 {
                lines[(i + n - 1) % n].nn + lines[i].nn
            } else {
                w.v
            };
            out.push(match div_ball(Ball::exact(self.d), len) {
                Some(k) => Self::cand(q.add(w.scale(k)), dir),
                // s is the vertex, exactly: every point of the circle is D away, and the
                // ends of its feasible arcs are meetings with other features.
                None if self.at_vertex(i) => continue,
                // s within rounding of the vertex: the circle is about D away.
                None => Self::unplaced(self.d - len.hi()),
            });
        }
        for i in 0..n {
            for j in 0..n {
                // With D = 0 the shifted edges are the edges: where they meet on P is a
                // vertex (a circle of radius 0 here); their lines' other meetings lie
                // off ∂P and would only loosen min_lo, as no side test can drop them.
                if j > i && self.d > 0.0 {
                    self.line_line(&lines[i], &lines[j], i, j, &mut out);
                    self.circle_circle(i, j, &mut out);
                }
                self.line_circle(&lines[i], i, j, &mut out);
            }
        }
        out
    }

    /// The intersection of two shifted edge lines N_i·x = c_i, N_j·x = c_j (Cramer).
    fn line_line(&self, li: &Line, lj: &Line, i: usize, j: usize, out: &mut Vec<Cand>) {
        let (ni, nj) = (li.e.perp(), lj.e.perp());
        let det = ni.cross(nj);
        let undecided = crate::ball::positive(det) == Tri::Unsure
            && crate::ball::positive(det.neg()) == Tri::Unsure;
        if undecided && self.parallel_exactly(i, j) {
            return;
        }
        let (ci, cj) = (li.c, lj.c);
        let xn = ci.mul(nj.y()).sub(cj.mul(ni.y()));
        let yn = ni.x().mul(cj).sub(ci.mul(nj.x()));
        out.push(match (div_ball(xn, det), div_ball(yn, det)) {
            (Some(x), Some(y)) => Self::cand(pt(x, y), li.nn + lj.nn),
            _ => Self::unplaced(0.0),
        });
    }

    /// Is s exactly vertex i (at time t)?
    fn at_vertex(&self, i: usize) -> bool {
        self.terms(i, self.s).is_some_and(|t| {
            exact::Sum::of(&t.x[..t.n]).sign() == Some(0)
                && exact::Sum::of(&t.y[..t.n]).sign() == Some(0)
        })
    }

    /// Are edges i and j exactly parallel (e_i × e_j = 0 on the exact vertices)?
    fn parallel_exactly(&self, i: usize, j: usize) -> bool {
        let comp = |k: usize, y: bool| -> exact::Sum {
            let mut s = exact::Sum::default();
            for (idx, sign) in [(self.next(k), 1.0), (k, -1.0)] {
                let c = |w: Vect2| if y { w.y } else { w.x };
                s.add(sign * c(self.p[idx]));
                if let Some((v, t)) = self.vels {
                    s.add_prod(sign * t, c(v[idx]));
                }
            }
            s
        };
        let mut c = comp(i, false).mul(&comp(j, true));
        c.add_sum(&comp(i, true).mul(&comp(j, false)), -1.0);
        c.sign() == Some(0)
    }

    /// The intersections of the shifted edge p0 + τe with the circle of radius D about
    /// vertex j: E τ² + 2Bτ + C = 0, B = e·(p0 − q_j), C = |p0 − q_j|² − D².
    ///
    /// The circles about the edge's own ends touch it at its ends, p0 and p0 + e (a double
    /// root, which the quadratic would only give to √u): those are taken as they are.
    fn line_circle(&self, l: &Line, i: usize, j: usize, out: &mut Vec<Cand>) {
        let Some(p0) = l.p0 else {
            out.push(Self::unplaced(0.0));
            return;
        };
        if j == i {
            out.push(Self::cand(p0, l.nn));
            return;
        }
        if j == self.next(i) {
            out.push(Self::cand(p0.add(l.e), l.nn));
            return;
        }
        let w = p0.sub(self.q[j]);
        let b = l.e.dot(w);
        let c = w.sq().sub(Ball::exact(self.d).sq());
        let disc = b.sq().sub(l.big_e.mul(c));
        if crate::ball::positive(disc.neg()) == Tri::Yes {
            return;
        }
        let root = sqrt_ball(disc);
        for sgn in [1.0, -1.0] {
            let num = b.neg().add(root.scale(sgn));
            out.push(match div_ball(num, l.big_e) {
                Some(tau) => {
                    let x = p0.add(l.e.scale(tau));
                    Self::cand(x, l.nn + unit(x.sub(self.q[j]).v))
                }
                None => Self::unplaced(0.0),
            });
        }
    }

    /// The intersections of the circles of radius D about vertices i and j: the midpoint
    /// m ± (q_j − q_i)⊥·h with h² = (D² − L/4)/L, L = |q_j − q_i|².
    fn circle_circle(&self, i: usize, j: usize, out: &mut Vec<Cand>) {
        let (a, b) = (self.q[i], self.q[j]);
        let w = b.sub(a);
        let l = w.sq();
        let h2n = Ball::exact(self.d).sq().sub(l.scale(0.25));
        if crate::ball::positive(h2n.neg()) == Tri::Yes {
            return;
        }
        let Some(h2) = div_ball(h2n, l) else {
            out.push(Self::unplaced(0.0));
            return;
        };
        let h = sqrt_ball(h2);
        let m = a.add(b).half();
        for sgn in [1.0, -1.0] {
            let x = m.add(w.perp().scale(h.scale(sgn)));
            let dir = unit(x.sub(a).v) + unit(x.sub(b).v);
            out.push(Self::cand(x, dir));
        }
    }
}

#[cfg(test)]
mod tests;
