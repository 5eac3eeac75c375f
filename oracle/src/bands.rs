//! The exact truth behind the bands: is one velocity in conflict? (Paper A §II–§III's
//! motion and §II.G's proximity, through the exact near_D sets of
//! [`crate::intervals`](mod@crate::intervals).)
//!
//! # Definition (the engine's `bands` module doc)
//! The point starts at s (in 3D at height sz with vertical speed vz) and moves at the
//! horizontal velocity w; each obstacle is a moving polygon P(t) with vertices
//! p_i + t·V_i, in 3D with an optional slab bottom + t·vsp ≤ z ≤ top + t·vsp (none:
//! no vertical limit). The velocity is **in conflict** when near_D (with H in 3D)
//! holds at some t ∈ [0, T] against some obstacle.
//!
//! # What the oracle offers, and why not bands
//! A band's ends are where a conflict starts for a course θ, with the velocity
//! speed·(sin θ, cos θ): transcendental in θ, so an exact band construction would
//! need more than the rational and algebraic numbers here. The oracle instead
//! decides single velocities exactly: a binary floating-point velocity (the engine's
//! `velocity` of a course, or any other), converted exactly by the caller, and
//! [`conflict`] answers for it with the exact components of near_D. A band answer is
//! checked by drawing values inside each Clear and Conflict band, forming their
//! floating-point velocities, and asking [`conflict`] (the harness's `wayout::bands`
//! check). The engine certifies its bands for those velocities as well as for the
//! exact ones.

use crate::case::Vertical;
use crate::field::{ExactField, V2};
use crate::intervals::{intervals, Relation, Separation, Undefined};

/// The point's vertical state in 3D (the engine's `bands::Height`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Height<F> {
    /// sz, the height at t = 0.
    pub sz: F,
    /// vz, the vertical speed.
    pub vz: F,
}

/// An obstacle's slab (paper A §III; the engine's `bands::Slab`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Slab<F> {
    /// The bottom at t = 0.
    pub bottom: F,
    /// The top at t = 0.
    pub top: F,
    /// Their vertical speed.
    pub vsp: F,
}

/// One moving polygon (the engine's `bands::Obstacle`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Obstacle<F> {
    /// The vertices at t = 0, counterclockwise.
    pub p: Vec<V2<F>>,
    /// Their velocities.
    pub vels: Vec<V2<F>>,
    /// The slab, in 3D.
    pub slab: Option<Slab<F>>,
}

/// The situation (the engine's `bands::Traffic`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Traffic<F> {
    /// T > 0.
    pub t: F,
    /// The point at t = 0.
    pub s: V2<F>,
    /// Its height and vertical speed (3D).
    pub height: Option<Height<F>>,
    /// The moving polygons.
    pub obstacles: Vec<Obstacle<F>>,
    /// D and H.
    pub sep: Separation<F>,
}

/// Is the velocity `v` in conflict (the module doc's definition)? Exact: near_D's exact
/// components against each obstacle, non-empty for some. `Undefined` as
/// [`intervals`] is (a polygon that is not simple, bad inputs).
/// (The contract's conflict of a velocity; paper A §II–§III's motion.)
pub fn conflict<F: ExactField>(traffic: &Traffic<F>, v: &V2<F>) -> Result<bool, Undefined> {
    for o in &traffic.obstacles {
        let heights = match (&traffic.height, &o.slab) {
            (Some(z), Some(slab)) => Some(Vertical {
                sz: z.sz.clone(),
                vz: z.vz.clone(),
                bottom: slab.bottom.clone(),
                top: slab.top.clone(),
                vsp: slab.vsp.clone(),
            }),
            _ => None,
        };
        let comps = intervals(
            &traffic.t,
            &traffic.s,
            v,
            &o.p,
            &o.vels,
            heights.as_ref(),
            Relation::Near,
            &traffic.sep,
        )?;
        if !comps.is_empty() {
            return Ok(true);
        }
    }
    Ok(false)
}
