//! Keep-in exit detection, exactly: does the point breach the fence — leave the
//! polygon, come within D of its boundary, or (3D) come within H of the slab's bottom
//! or top — at some t ∈ [0, T]? (The contract's breach_D ≠ ∅ on [0, T], over paper A
//! §II–III's cases; [`crate::intervals`](mod@crate::intervals) computes the whole set.)
//!
//! It stops at the first evidence: a time where the height is within H of the slab's
//! ends (3D, rational windows of §III), a vertex or an edge the point comes within D of
//! (§II.C's tests as sets of times, floats first), or else the point's side of the
//! boundary, constant over the whole window, taken at one time (§II.D's crossings).

use num_rational::BigRational;

use crate::case::ExactCase;
use crate::field::{ExactField, V2};
use crate::intervals::scene::Scene;
use crate::intervals::set::Window;
use crate::intervals::{
    at_least, check, heights_of, near_boundary, outside_throughout, point_edges, Heights,
    Separation, Undefined,
};

/// Whether breach_D holds at some t ∈ [0, T] (see the module doc): `Ok(true)` exactly
/// when [`crate::intervals::intervals`] of `Relation::Breach` is not empty, and defined
/// wherever that is (also in some cases where it is not: a breach near the boundary
/// needs no fill rule). `Undefined` as there otherwise.
/// (The contract's keep-in exit over paper A §II–III's cases.)
pub fn detect_exit<F: ExactField>(
    t: &F,
    s: &V2<F>,
    v: &V2<F>,
    p: &[V2<F>],
    vels: &[V2<F>],
    heights: Option<&Heights<F>>,
    sep: &Separation<F>,
) -> Result<bool, Undefined> {
    let n = check(t, p, vels, sep)?;
    let tq = t.to_big();
    if let Some(z) = heights {
        // {u ≤ H} ∪ {w ≤ H} on [0, T]: the height comes within H of an end of the slab.
        let h = sep.h.to_big();
        let near_end = heights_of(z)
            .iter()
            .any(|(c0, c1)| at_least(&(&h - c0), &-c1, &tq).is_some());
        if near_end {
            return Ok(true);
        }
    }
    // Otherwise bottom + H < z < top − H throughout: the horizontal part decides.
    let sc = Scene::new(t, s, v, &p[..n], &vels[..n], &sep.d);
    let w = Window::new(BigRational::from_integer(0.into()), tq);
    let point_edge = point_edges(&sc, &w)?;
    if !near_boundary(&sc, &w, &point_edge, true).is_empty() {
        return Ok(true);
    }
    outside_throughout(&sc, &w)
}

/// [`detect_exit`] of a validated case (its T, point, polygon and slab).
/// (The contract's keep-in exit over paper A §II–III's cases.)
pub fn detect_exit_of<F: ExactField>(
    case: &ExactCase<F>,
    sep: &Separation<F>,
) -> Result<bool, Undefined> {
    detect_exit(
        &case.lookahead,
        &case.s,
        &case.v,
        &case.vertices,
        &case.velocities,
        case.vertical.as_ref(),
        sep,
    )
}
