//! The exact sets of times of three relations between a moving point and a moving
//! (possibly warping) polygon, in 2D or with a slab in 3D (paper A §II, §II.I, §III),
//! over [0, T]: their closed components [a, b] with real algebraic ends
//! ([`RealAlg`]), sorted and disjoint (a = b for an isolated touch). The first start of
//! [`Relation::Near`] is the time of loss of separation; [`Relation::Breach`] is the
//! keep-in fence's breach ([`crate::fence`]).
//!
//! # Definitions (the shared contract of the engine and the oracle)
//! A case: T > 0, the point x(t) = s + t·v (3D: height z(t) = sz + t·vz), the polygon
//! P(t) with vertices p_i + t·v_i, in 3D the slab bottom + t·vsp ≤ z ≤ top + t·vsp;
//! separations D ≥ 0, H ≥ 0.
//! - inside(t): x(t) in the closed polygon P(t) (and bottom(t) ≤ z(t) ≤ top(t) in 3D);
//! - near_D(t): the horizontal distance from x(t) to the closed P(t) is ≤ D (0 when
//!   inside), and in 3D bottom(t) − H ≤ z(t) ≤ top(t) + H;
//! - fence_D(t): x(t) in P(t) at distance > D from its boundary ∂P(t), and in 3D
//!   bottom(t) + H < z(t) < top(t) − H; breach_D(t) := not fence_D(t).
//!
//! "In the closed polygon" is as in the truth ([`crate::truth`](mod@crate::truth)): on an edge, or of
//! non-zero winding number; where the winding number is even and non-zero (a polygon
//! that is not simple) the relation depends on the fill rule and the answer is
//! [`Undefined`], as it is when an edge shrinks to a point during the window.
//!
//! # Method, and why it is exact
//! Let d(t) be the distance from x(t) to ∂P(t) and W a closed window of time.
//!
//! 1. B = {t ∈ W : d(t) ≤ D} is a finite union of closed intervals with algebraic ends.
//!    The distance to a segment [a, b] is the distance to an end, or to the foot of
//!    the perpendicular when the foot falls on the segment, that is when
//!    h1 = (x − a)·(b − a) ≥ 0 and h2 = (b − x)·(b − a) ≥ 0, and then its square is
//!    g²/|b − a|² with g = (x − a) × (b − a) (paper A §II.C's quadratic in r, minimised).
//!    So d ≤ D ⇔ some vertex has |x − p_i|² ≤ D², or some edge has h1 ≥ 0, h2 ≥ 0 and
//!    g² ≤ D²·|b − a|². Each of these is a polynomial in t (degree 2; g² − D²|e|² has
//!    degree 4 for a warping edge, §II.I), so each condition holds on a set of times
//!    whose ends are roots of that polynomial or ends of W; those sets are computed
//!    exactly (the roots, and the polynomial's sign between consecutive roots), and B
//!    is their union. With D = 0 the vertex sets lie in the edge sets (a vertex is on
//!    its edges), and the edge sets are the contacts: roots of g at which h1, h2 ≥ 0,
//!    or, where the point slides along the edge's line (g ≡ 0), {h1 ≥ 0} ∩ {h2 ≥ 0}.
//! 2. On each gap of W outside B, d > D ≥ 0: the point is on no edge, so its winding
//!    number about P(t) (an integer, continuous in t while the point is off the closed
//!    curve P(t), which moves continuously) is constant there. It is taken at one
//!    rational time of the gap (§II.D's crossings, exact and signed). In other words:
//!    every relation is a boolean function of the signs of finitely many polynomials
//!    in t (the ones above, and the linear y-comparisons and g of the crossing test),
//!    and it can only change where the point is at distance exactly D from an edge or
//!    a vertex, or (D = 0) on the boundary — at the ends of the sets of step 1.
//! 3. In W: near = B ∪ {gaps of odd winding number}; inside = the same with D = 0;
//!    breach = B ∪ {gaps of winding number 0}. Each set is closed, so a gap that
//!    belongs to it brings its ends (ends of B's components, or of W) along; adjacent
//!    pieces merge into the components, whose ends are thus roots or ends of W.
//! 4. In 3D the vertical conditions are linear in t (§III's slab window): inside and
//!    near are the horizontal set over the closed window where the vertical part
//!    holds; breach is {z ≤ bottom + H} ∪ {z ≥ top − H} (rational ends) together with
//!    the horizontal breach over the closed window where bottom + H ≤ z ≤ top − H.
//!    In 2D, W = [0, T].
//!
//! # Speed: floats first
//! Every polynomial exists first as float enclosures of its coefficients; its roots are
//! isolated in floats ([`crate::kernel::interval::isolate_roots`]), the sign between two
//! roots is taken at a float sample, and two ends are compared by their enclosures when
//! these are apart. Exact integers and algebraic numbers are built only where floats
//! cannot decide (ties, multiple roots, a root at a window's end) and for the ends that
//! are returned. A vertex or edge whose box over the window is farther than D from the
//! point's contributes nothing and costs no root at all. Every float decision is
//! certified by outward rounding, so the answer is the exact one.

mod boundary;
pub(crate) mod scene;
pub(crate) mod set;

use core::fmt;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::algebraic::RealAlg;
use crate::case::{ExactCase, Vertical};
use crate::field::{ExactField, V2};
use boundary::horizontal;
pub(crate) use boundary::{near_boundary, outside_throughout, point_edges};
use scene::Scene;
use set::{End, Set, Window};

/// The slab of a 3D case (sz, vz, bottom, top, vsp): the engine's `entry::Heights`.
pub type Heights<F> = Vertical<F>;

/// Which set of times [`intervals`] computes (see the module doc's definitions).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Relation {
    /// x(t) in the closed polygon (and the closed slab).
    Inside,
    /// Within D of the closed polygon (and within H of the slab).
    Near,
    /// Not in the keep-in fence: not inside at distance > D from the boundary (and
    /// not strictly inside the slab shrunk by H).
    Breach,
}

impl Relation {
    /// "inside", "near" or "breach".
    /// (The contract's relations.)
    pub fn name(self) -> &'static str {
        match self {
            Relation::Inside => "inside",
            Relation::Near => "near",
            Relation::Breach => "breach",
        }
    }
}

/// The separations: D horizontal, H vertical (both ≥ 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Separation<F> {
    /// D, the horizontal separation.
    pub d: F,
    /// H, the vertical separation.
    pub h: F,
}

impl<F: ExactField> Separation<F> {
    /// D = H = 0.
    /// (The contract's separations.)
    pub fn none() -> Self {
        Separation {
            d: F::zero(),
            h: F::zero(),
        }
    }
}

/// Why a set of times has no answer: the fill rule would decide it (an even, non-zero
/// winding number), an edge shrinks to a point, or the input breaks the contract.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Undefined {
    /// Why.
    pub reason: String,
}

impl fmt::Display for Undefined {
    /// The reason. (The contract's undefined cases.)
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.reason)
    }
}

impl std::error::Error for Undefined {}

/// The exact components of a relation's set of times, each (a, b) with a ≤ b.
pub type Components = Vec<(RealAlg, RealAlg)>;

/// The inputs' rules (T > 0, D, H ≥ 0, at least 3 vertices; `p` and `vels` have
/// equal lengths, the shorter is used, as the engine does): the number of vertices.
/// (The contract's definitions, and paper A §II's polygon of at least three vertices.)
pub(crate) fn check<F: ExactField>(
    t: &F,
    p: &[V2<F>],
    vels: &[V2<F>],
    sep: &Separation<F>,
) -> Result<usize, Undefined> {
    let n = p.len().min(vels.len());
    let bad = |why: &str| {
        Err(Undefined {
            reason: why.to_string(),
        })
    };
    if !t.is_pos() {
        return bad("the lookahead T must be > 0");
    }
    if sep.d.is_neg() || sep.h.is_neg() {
        return bad("the separations D and H must be ≥ 0");
    }
    if n < 3 {
        return bad("fewer than 3 vertices (or velocities)");
    }
    Ok(n)
}

/// {t ∈ [0, T] : c0 + c1·t ≥ 0}, a closed interval with rational ends or empty.
/// (Paper A §III step 1: where a height is above a moving plane.)
pub(crate) fn at_least(
    c0: &BigRational,
    c1: &BigRational,
    t: &BigRational,
) -> Option<(BigRational, BigRational)> {
    let zero = BigRational::zero();
    if c1.is_zero() {
        return (!c0.is_negative()).then(|| (zero, t.clone()));
    }
    let r = -c0 / c1;
    if c1.is_positive() {
        (&r <= t).then(|| (if r > zero { r } else { zero }, t.clone()))
    } else {
        (r >= zero).then(|| (zero, if &r < t { r } else { t.clone() }))
    }
}

/// The common part of two closed intervals. (Paper A §III: a slab window.)
pub(crate) fn meet(
    a: Option<(BigRational, BigRational)>,
    b: Option<(BigRational, BigRational)>,
) -> Option<(BigRational, BigRational)> {
    let ((a0, a1), (b0, b1)) = (a?, b?);
    let lo = if a0 > b0 { a0 } else { b0 };
    let hi = if a1 < b1 { a1 } else { b1 };
    (lo <= hi).then_some((lo, hi))
}

/// The vertical part of a 3D case as the heights above the slab's bottom and below its
/// top, u(t) = z − bottom and w(t) = top − z, each c0 + c1·t.
/// (Paper A §III: the point's height against the moving slab.)
pub(crate) fn heights_of<F: ExactField>(z: &Heights<F>) -> [(BigRational, BigRational); 2] {
    let b = |x: &F| x.to_big();
    let (sz, vz, bot, top, vsp) = (b(&z.sz), b(&z.vz), b(&z.bottom), b(&z.top), b(&z.vsp));
    [(&sz - &bot, &vz - &vsp), (&top - &sz, &vsp - &vz)]
}

/// The set of times of `relation` in the scene (see the module doc, steps 1–4).
/// (The contract's inside / near_D / breach_D, paper A §II–III.)
fn set_of<F: ExactField>(
    sc: &Scene<'_, F>,
    t: &BigRational,
    heights: Option<&Heights<F>>,
    relation: Relation,
    h: &BigRational,
) -> Result<Set, Undefined> {
    let zero = BigRational::zero();
    let Some(z) = heights else {
        return horizontal(sc, &Window::new(zero, t.clone()), relation);
    };
    let [(u0, u1), (w0, w1)] = heights_of(z);
    // {u + m ≥ 0} ∩ {w + m ≥ 0}: the slab grown by m (shrunk when m < 0).
    let window = |m: &BigRational| meet(at_least(&(&u0 + m), &u1, t), at_least(&(&w0 + m), &w1, t));
    match relation {
        Relation::Inside | Relation::Near => {
            let grow = if relation == Relation::Inside {
                zero
            } else {
                h.clone()
            };
            match window(&grow) {
                None => Ok(Set::empty()),
                Some((a, b)) => horizontal(sc, &Window::new(a, b), relation),
            }
        }
        Relation::Breach => {
            // {u ≤ H} ∪ {w ≤ H}, then the horizontal breach where u ≥ H and w ≥ H.
            let mut parts: Vec<(End, End)> = [(&u0, &u1), (&w0, &w1)]
                .into_iter()
                .filter_map(|(c0, c1)| at_least(&(h - c0), &-c1, t))
                .map(|(a, b)| (End::rational(a), End::rational(b)))
                .collect();
            if let Some((a, b)) = window(&-h) {
                parts.extend(horizontal(sc, &Window::new(a, b), relation)?.comps);
            }
            Ok(Set::union_of(sc, parts))
        }
    }
}

/// The exact components of the set of times t ∈ [0, T] at which `relation` holds for
/// the point s + t·v (3D: with `heights`) and the polygon P + t·V, at separation `sep`
/// (D for Near and Breach, H in 3D; Inside uses neither): sorted, disjoint, closed,
/// (a, a) for an isolated touch. `Undefined` when the fill rule would decide or the
/// polygon degenerates (see the module doc), or when the input breaks the contract.
/// (The contract's inside / near_D / breach_D over paper A §II–III's cases.)
#[allow(clippy::too_many_arguments)]
pub fn intervals<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    p: &[V2<F>],
    vels: &[V2<F>],
    heights: Option<&Heights<F>>,
    relation: Relation,
    sep: &Separation<F>,
) -> Result<Components, Undefined> {
    let n = check(t, p, vels, sep)?;
    let zero = F::zero();
    let d = if relation == Relation::Inside {
        &zero
    } else {
        &sep.d
    };
    let sc = Scene::new(t, s, v, &p[..n], &vels[..n], d);
    let set = set_of(&sc, &t.to_big(), heights, relation, &sep.h.to_big())?;
    Ok(set
        .comps
        .into_iter()
        .map(|(a, b)| (a.into_alg(&sc), b.into_alg(&sc)))
        .collect())
}

/// [`intervals`] of a validated case (its T, point, polygon and slab).
/// (The contract's inside / near_D / breach_D over paper A §II–III's cases.)
pub fn intervals_of<F: ExactField>(
    case: &ExactCase<F>,
    relation: Relation,
    sep: &Separation<F>,
) -> Result<Components, Undefined> {
    intervals(
        &case.lookahead,
        &case.s,
        &case.v,
        &case.vertices,
        &case.velocities,
        case.vertical.as_ref(),
        relation,
        sep,
    )
}
