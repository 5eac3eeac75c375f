//! Certified offsets and insets of a polygon (paper A §II's simple counterclockwise
//! polygon P; the distance of §II.G's proximity tests, here to the whole polygon).
//!
//! # Definitions
//! For D ≥ 0 and ε > 0:
//! - the **offset** (buffer) of P by D is P ⊕ disc(D) = {x : dist(x, P) ≤ D}, where
//!   dist(x, P) = 0 inside the closed P. [`offset`] returns a set of polygons Q with
//!   **P ⊕ disc(D) ⊆ Q ⊆ P ⊕ disc(D·(1 + ε))**;
//! - the **inset** of P by D is {x ∈ P : dist(x, ∂P) ≥ D}. [`inset`] returns pieces Q
//!   with **Q ⊆ {x ∈ P : dist(x, ∂P) ≥ D}** and
//!   **Q ⊇ {x ∈ P : dist(x, ∂P) ≥ D·(1 + ε)}**; it may be several pieces, or none.
//!
//! A result is an [`Offset`]: regions, each an outer ring (counterclockwise) with holes
//! (clockwise); the rings are simple and pairwise disjoint.
//!
//! ```
//! use polyguard::offset::{inset, offset};
//! use polyguard::Vect2;
//!
//! let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
//! // Grown by 0.5 within 1 %: one region, its corners rounded by circumscribed arcs.
//! let grown = offset(&square, 0.5, 0.01)?;
//! assert_eq!(grown.regions.len(), 1);
//! assert!(grown.regions[0].outer.len() > 8);
//! // Shrunk by 1.5: no point of the square is 1.5 from its boundary.
//! assert!(inset(&square, 1.5, 0.01)?.regions.is_empty());
//! # Ok::<(), polyguard::offset::OffsetError>(())
//! ```
//!
//! # Construction
//! With D' = D·(1 + ε') and ε' = min(ε, [`EPS_CAP`])/4 ([`MARGIN_SHARE`]), the
//! construction region Q_K is
//! - offset: P ∪ the strips e ⊕ [0, D'·n_e] of the edges (n_e the outward unit normal)
//!   ∪ the fans at the convex vertices: the polygon v, v + D'·n_in, the vertices of the
//!   polygon circumscribed about the arc of radius D' (each at radius D'·sec(δ/2), arc
//!   pieces of angle δ with sec(δ/2) ≤ 1 + ε'), v + D'·n_out. Every x with
//!   dist(x, P) ≤ D' lies in P, in the strip of the edge holding its nearest point, or
//!   in the fan of the convex vertex that is its nearest point (a reflex vertex is never
//!   the nearest point of an outside point), so Q_K ⊇ P ⊕ disc(D'); and every point of
//!   Q_K is within D'·sec(δ/2) ≤ D·(1 + ε')² of P;
//! - inset: P minus the inward strips of the edges and the fans at the reflex vertices,
//!   by the same argument turned inside out.
//!
//! The boundary of Q_K lies on the shifted edges and the arcs' pieces (the raw
//! segments, module `raw`; where two shifted edges meet without a fan they are cut at
//! their mitre point, so that nearly parallel neighbours join at one node). Module `arrange` splits them at their crossings (exact
//! orientations), keeps each piece whose left side is in Q_K and right side is not (a
//! membership test of its midpoint against the pieces, exact orientations on the f64
//! points), and links the kept pieces into rings. Holes of the offset and the pieces of
//! the inset appear where Q_K has them. Cost: O((n + k)²) for n vertices and k arc
//! pieces (k ≤ n·⌈π/δ⌉), with bounding-box pruning; a few hundred vertices take
//! milliseconds.
//!
//! # Certificate
//! Before returning, module `certify` checks the rings with certified predicates (exact
//! orientations, and `ball`'s forward error bounds on squared distances; no
//! absolute epsilon):
//! - the rings are simple and pairwise disjoint (exact);
//! - every edge of Q is at distance ≥ D from every edge of P (certified lower bound of
//!   the squared distance, see `certify`): ∂Q misses the open D-neighbourhood of P (of
//!   ∂P for the inset);
//! - offset: a vertex of P is inside Q, and every ring of Q has a vertex outside P (a
//!   ring is at least D from ∂P, so it is wholly inside P or wholly outside). The
//!   D-neighbourhood of P is connected and ∂Q misses it, so it all lies in Q:
//!   **P ⊕ disc(D) ⊆ Q**. Inset: a vertex of P is
//!   outside Q (so the D-neighbourhood of ∂P is outside Q) and each outer ring has a
//!   vertex inside P (so each region, which meets no point of ∂P, is inside P):
//!   **Q ⊆ {x ∈ P : dist(x, ∂P) ≥ D}**;
//! - every edge of Q has both ends within D·(1 + ε) of one edge of P (certified upper
//!   bound); the distance to a segment is convex along a segment, so the whole edge is:
//!   **∂Q ⊆ P ⊕ disc(D(1 + ε))** (of ∂P for the inset). That Q has no extra region
//!   filling a hole of the true offset (or misses no piece of the inset) is the
//!   construction's argument above: Q_K is sandwiched between the two sets, and the
//!   rings bound it. The boundary cannot show a filled hole, but the construction
//!   cannot drop one quietly: each piece of a raw segment is kept or dropped by the
//!   exact location of its midpoint among the f64 pieces, so a hole's ring is dropped
//!   only where its midpoints truly lie inside Q_K, and a ring broken part way does not
//!   close (`Uncertified`). The exact oracle samples the interior in the tests.
//!
//! A result the certificate rejects is [`OffsetError::Uncertified`], never a silent wrong
//! polygon. A problem whose size lies beyond 2^±[`SCALE_RANGE`] is solved scaled by a
//! power of two (exactly, both ways; the properties are invariant under similarity). At time t ([`offset_at`], [`inset_at`]) the vertices p_i + t·V_i are
//! evaluated in f64 with an error radius r per vertex (`ball`); the certificate
//! then uses D + [`MOVE_SLACK`]·r for the containment and D·(1 + ε) − MOVE_SLACK·r for
//! the closeness, which covers the exact polygon at t. (With D = 0 and inexact vertices
//! the exact polygon itself is asked for, which f64 cannot hold: `Uncertified`.)
//!
//! # Error bounds
//! - [`MARGIN_SHARE`]: the share of ε the construction keeps for rounding: it builds at
//!   D·(1 + ε/4) with arcs of factor sec(δ/2) ≤ 1 + ε/4, so its points are within
//!   D·(1 + ε/4)² ≤ D·(1 + ε/2 + ε²/16) < D·(1 + ε) of P (ε ≤ [`EPS_CAP`]), leaving
//!   D·ε/4 on either side for the f64 rounding of its vertices, which the certificate
//!   then bounds exactly.
//! - The squared point-to-segment distance is evaluated on balls: each rounding adds
//!   2u·|value| to the radius (u = 2⁻⁵³), propagated by `ball::Ball`'s rules;
//!   decisions are taken only when the ball excludes the threshold.
//! - [`MOVE_SLACK`]: the distance between the exact and the f64 polygon at time t.
//! - [`ARC_ROOM`]: the share of each arc piece's angle left for the rounding of acos,
//!   cos and the circumscribed radius.
//! - [`SCALE_RANGE`]: the sizes solved as they are; others are scaled by 2^k exactly.
//! - [`MAX_PIECES_PER_TURN`] and [`EPS_CAP`]: the limits of the construction's size.

mod arrange;
mod certify;
mod raw;

pub(crate) use certify::{at_least, segments_at_least, within};
pub(crate) use raw::winding_number;

use core::fmt;
use std::vec::Vec;

use crate::ball::{Ball, U};
use crate::ring::{check, RingFault, Winding};
use crate::vect2::Vect2;

/// The share of ε the construction uses for its own enlargement (D' = D·(1 + ε/4)) and
/// for its arcs (sec(δ/2) ≤ 1 + ε/4): (1 + ε/4)² < 1 + ε for ε < 8, which leaves at least
/// D·ε/4 (minus D·ε²/16) between the construction and each of the two bounds for
/// rounding.
pub const MARGIN_SHARE: f64 = 0.25;

/// ε above this is used as this by the construction (its (1 + ε/4)² ≤ 1 + ε needs ε ≤ 8;
/// 4 keeps arcs of a quarter turn): the certificate still checks the caller's ε.
pub const EPS_CAP: f64 = 4.0;

/// The most arc pieces one full turn may take (an ε so small that sec(δ/2) ≤ 1 + ε/4
/// needs more is refused as [`OffsetError::TooFine`]: the result would be too large).
pub const MAX_PIECES_PER_TURN: usize = 4096;

/// The distance between a vertex p + t·V evaluated in f64 (each coordinate within r of
/// the exact one) and the exact vertex is ≤ √2·r; the regions bounded by the two rings
/// are then within 2√2·r < 3·r of each other (a point within √2·r of one boundary is
/// within 2√2·r of the other), so the certificate shifts its thresholds by 3·r.
pub const MOVE_SLACK: f64 = 3.0;

/// One region of a result: an outer ring and its holes.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// The outer ring, counterclockwise.
    pub outer: Vec<Vect2>,
    /// The holes, each clockwise, inside `outer`.
    pub holes: Vec<Vec<Vect2>>,
}

/// A certified offset or inset: its regions (none for an empty inset).
#[derive(Clone, Debug, PartialEq)]
pub struct Offset {
    /// The regions, with pairwise disjoint boundaries.
    pub regions: Vec<Region>,
}

/// Why an offset or inset was not returned.
#[derive(Clone, Debug, PartialEq)]
pub enum OffsetError {
    /// An argument outside its domain, naming its field (`p`, `vels`, `t`, `d`, `eps`).
    Invalid {
        /// The argument.
        field: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The polygon `p` (at time t for the `_at` forms) is not simple and
    /// counterclockwise.
    Polygon {
        /// The ring check's finding.
        fault: RingFault,
    },
    /// ε so small that the arcs would need more than [`MAX_PIECES_PER_TURN`] pieces per
    /// turn.
    TooFine {
        /// The pieces one turn would need.
        pieces_per_turn: f64,
    },
    /// The construction's result failed its certificate (rounding too coarse for D·ε at
    /// this scale, or a degenerate arrangement): no polygon is returned.
    Uncertified {
        /// Which check failed.
        reason: &'static str,
    },
}

impl fmt::Display for OffsetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OffsetError::Invalid { field, reason } => write!(f, "{field}: {reason}"),
            OffsetError::Polygon { fault } => {
                write!(f, "p: not a simple counterclockwise polygon ({fault:?})")
            }
            OffsetError::TooFine { pieces_per_turn } => write!(
                f,
                "eps: too small, arcs would need {pieces_per_turn:.0} pieces per turn \
                 (at most {MAX_PIECES_PER_TURN})"
            ),
            OffsetError::Uncertified { reason } => write!(f, "not certified: {reason}"),
        }
    }
}

impl std::error::Error for OffsetError {}

/// Which of the two sets is built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Side {
    /// P ⊕ disc(D).
    Out,
    /// {x ∈ P : dist(x, ∂P) ≥ D}.
    In,
}

/// The offset of P by D (see the module doc): Q with P ⊕ disc(D) ⊆ Q ⊆ P ⊕ disc(D(1 + ε)),
/// certified. `p` simple and counterclockwise, `d` ≥ 0 finite, `eps` > 0 finite.
/// (Paper A §II's polygon; the offset of the module doc.)
pub fn offset(p: &[Vect2], d: f64, eps: f64) -> Result<Offset, OffsetError> {
    build(p, &[], d, eps, Side::Out)
}

/// The inset of P by D (see the module doc): pieces inside {x ∈ P : dist(x, ∂P) ≥ D}
/// that contain {x ∈ P : dist(x, ∂P) ≥ D(1 + ε)}, certified; no region when P has no
/// such point (an answer, not an error). (Paper A §II's polygon; the module doc's inset.)
pub fn inset(p: &[Vect2], d: f64, eps: f64) -> Result<Offset, OffsetError> {
    build(p, &[], d, eps, Side::In)
}

/// [`offset`] of the moving polygon with vertices p_i + t·V_i at time `t` (paper A §II's
/// motion), certified for the exact polygon at t.
pub fn offset_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    d: f64,
    eps: f64,
) -> Result<Offset, OffsetError> {
    let (at, r) = at_time(p, vels, t)?;
    build(&at, &r, d, eps, Side::Out)
}

/// [`inset`] of the moving polygon with vertices p_i + t·V_i at time `t` (paper A §II's
/// motion), certified for the exact polygon at t.
pub fn inset_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    d: f64,
    eps: f64,
) -> Result<Offset, OffsetError> {
    let (at, r) = at_time(p, vels, t)?;
    build(&at, &r, d, eps, Side::In)
}

/// The vertices p_i + t·V_i in f64 and each one's error radius (per coordinate), from
/// `Ball`'s rules: t·V rounded once, the sum rounded once.
fn at_time(p: &[Vect2], vels: &[Vect2], t: f64) -> Result<(Vec<Vect2>, Vec<f64>), OffsetError> {
    if !t.is_finite() {
        return Err(OffsetError::Invalid {
            field: "t",
            reason: "not finite",
        });
    }
    if vels.len() != p.len() {
        return Err(OffsetError::Invalid {
            field: "vels",
            reason: "not one velocity per vertex",
        });
    }
    if vels.iter().any(|v| !v.is_finite()) {
        return Err(OffsetError::Invalid {
            field: "vels",
            reason: "not finite",
        });
    }
    let mut at = Vec::with_capacity(p.len());
    let mut r = Vec::with_capacity(p.len());
    for (&pi, &vi) in p.iter().zip(vels) {
        let x = Ball::exact(pi.x).add(Ball::exact(vi.x).scale(t));
        let y = Ball::exact(pi.y).add(Ball::exact(vi.y).scale(t));
        at.push(Vect2::new(x.z, y.z));
        r.push(x.r.max(y.r));
    }
    Ok((at, r))
}

/// Checks the arguments, builds, certifies. `radii` (empty: exact vertices) are the
/// vertices' error radii.
fn build(p: &[Vect2], radii: &[f64], d: f64, eps: f64, side: Side) -> Result<Offset, OffsetError> {
    if p.len() < 3 {
        return Err(OffsetError::Invalid {
            field: "p",
            reason: "fewer than 3 vertices",
        });
    }
    if p.iter().any(|v| !v.is_finite()) || radii.iter().any(|r| !r.is_finite()) {
        return Err(OffsetError::Invalid {
            field: "p",
            reason: "not finite",
        });
    }
    if !(d.is_finite() && d >= 0.0) {
        return Err(OffsetError::Invalid {
            field: "d",
            reason: "not a finite number ≥ 0",
        });
    }
    if !(eps.is_finite() && eps > 0.0) {
        return Err(OffsetError::Invalid {
            field: "eps",
            reason: "not a finite number > 0",
        });
    }
    match check(p) {
        Ok(Winding::Counterclockwise) => {}
        Ok(Winding::Clockwise) => {
            return Err(OffsetError::Invalid {
                field: "p",
                reason: "clockwise",
            })
        }
        Err(fault) => return Err(OffsetError::Polygon { fault }),
    }
    // Repeated consecutive vertices are one vertex (as for the ring check).
    let n = p.len();
    let keep: Vec<usize> = (0..n).filter(|&i| p[i] != p[(i + 1) % n]).collect();
    let p: Vec<Vect2> = keep.iter().map(|&i| p[i]).collect();
    let p = p.as_slice();
    let slack = MOVE_SLACK * radii.iter().fold(0.0f64, |m, &r| m.max(r));
    if d == 0.0 && slack == 0.0 {
        // P ⊕ disc(0) = P and {x ∈ P : dist(x, ∂P) ≥ 0} = P, exactly.
        return Ok(Offset {
            regions: std::vec![Region {
                outer: p.to_vec(),
                holes: Vec::new(),
            }],
        });
    }
    let e = eps.min(EPS_CAP) * MARGIN_SHARE;
    let pieces_per_turn = core::f64::consts::TAU / max_arc_angle(e);
    let fits = pieces_per_turn.partial_cmp(&(MAX_PIECES_PER_TURN as f64));
    if !matches!(
        fits,
        Some(core::cmp::Ordering::Less | core::cmp::Ordering::Equal)
    ) {
        return Err(OffsetError::TooFine { pieces_per_turn });
    }
    let k = scale_exponent(p, d + slack);
    if k == 0 {
        return construct(p, d, eps, slack, side);
    }
    // Far from 1 in scale (exact products would over- or underflow): the similar
    // problem scaled by 2^k, exactly, and its answer scaled back, exactly.
    let scaled: Vec<Vect2> = p.iter().map(|&v| times_pow2(v, k)).collect();
    let exact = |a: Vect2, b: Vect2| times_pow2(b, -k) == a && b.is_finite();
    let ds = times_pow2(Vect2::new(d, slack), k);
    if !(p.iter().zip(&scaled).all(|(&a, &b)| exact(a, b)) && exact(Vect2::new(d, slack), ds)) {
        return Err(OffsetError::Uncertified {
            reason: "coordinates and D too far apart in scale to scale exactly",
        });
    }
    let mut out = construct(&scaled, ds.x, eps, ds.y, side)?;
    for ring in out
        .regions
        .iter_mut()
        .flat_map(|r| core::iter::once(&mut r.outer).chain(r.holes.iter_mut()))
    {
        for v in ring.iter_mut() {
            let back = times_pow2(*v, -k);
            if times_pow2(back, k) != *v {
                return Err(OffsetError::Uncertified {
                    reason: "the result does not scale back exactly",
                });
            }
            *v = back;
        }
    }
    Ok(out)
}

/// The construction and its certificate (the module doc), for a deduplicated P.
fn construct(p: &[Vect2], d: f64, eps: f64, slack: f64, side: Side) -> Result<Offset, OffsetError> {
    let e = eps.min(EPS_CAP) * MARGIN_SHARE;
    // D' covers the slack of a moving polygon too: the construction stays D'·ε/4 clear.
    let d_build = (d + slack) * (1.0 + e) * BUILD_ROUNDING;
    let raw = raw::Raw::new(p, d_build, max_arc_angle(e), side);
    let rings = arrange::rings(&raw)?;
    let regions = arrange::regions(rings)?;
    let bounds = certify::Bounds::new(d, eps, slack);
    certify::certify(p, &regions, &bounds, side)?;
    Ok(Offset { regions })
}

/// The power of two that brings the largest of P's coordinates and D near 1, or 0 when
/// they already lie within 2^±[`SCALE_RANGE`] (where no exact product of the
/// construction's orientations over- or underflows).
fn scale_exponent(p: &[Vect2], d: f64) -> i32 {
    let m = p
        .iter()
        .fold(d.abs(), |m, v| m.max(v.x.abs()).max(v.y.abs()));
    let e = if m > 0.0 {
        libm::log2(m).floor() as i32
    } else {
        0
    };
    if e.abs() <= SCALE_RANGE {
        0
    } else {
        -e
    }
}

/// The largest |log₂| of the problem's size kept as it is: squared differences of
/// coordinates up to 2^±300 stay far inside the f64 range (2^±1022).
pub const SCALE_RANGE: i32 = 300;

/// v·2^k, exactly when the result is normal (steps of at most 2^500, each exact
/// unless it under- or overflows; callers check the round trip).
fn times_pow2(v: Vect2, k: i32) -> Vect2 {
    let (mut x, mut y, mut k) = (v.x, v.y, k);
    while k != 0 {
        let step = k.clamp(-500, 500);
        // 2^step, built from its bits (step ∈ [−500, 500]: a normal float).
        let f = f64::from_bits(((1023 + step) as u64) << 52);
        x *= f;
        y *= f;
        k -= step;
    }
    Vect2::new(x, y)
}

/// The share of the arc angle given up for rounding: δ = 2·acos(1/(1 + e))·(1 − 2⁻²⁰).
/// acos, the quotient and cos in the construction each err by a few ulps (≈ 2⁻⁵⁰
/// relative); giving up 2⁻²⁰ of the angle lowers sec(δ/2) − 1 by about 2⁻¹⁹ of itself,
/// far more than those errors move it, so the arcs' factor stays ≤ 1 + e.
pub const ARC_ROOM: f64 = 1.0 / 1_048_576.0;

/// The rounding allowance on D' = (D + slack)·(1 + e): three roundings, each at most u,
/// so ×(1 + 4u) keeps the computed D' at or above the exact product.
const BUILD_ROUNDING: f64 = 1.0 + 4.0 * U;

/// The largest arc piece δ with sec(δ/2) ≤ 1 + e, less [`ARC_ROOM`] for rounding, at
/// most a quarter turn.
fn max_arc_angle(e: f64) -> f64 {
    let half = libm::acos(1.0 / (1.0 + e));
    (2.0 * half * (1.0 - ARC_ROOM)).min(core::f64::consts::FRAC_PI_2)
}

#[cfg(test)]
mod tests;
