//! The exact truth of moving features on the plane (docs/moving-features.md, "The
//! planar model"): the sets of times a mover,
//! flying straight at constant speed between timed fixes, is inside an area (static, or
//! keyframed with vertices linear in time between keyframes) or near it within D
//! horizontally and H vertically, over one segment of its trajectory.
//!
//! # Method
//! Every input float is the exact rational it denotes (`input`). The
//! breakpoints are the segment's fix times and the area's keyframe times, cut to the
//! domain (the segment's [first fix, last fix] ∩ the area's existence). Between two
//! consecutive breakpoints t_k < t_{k+1} (h = t_{k+1} − t_k) everything moves linearly:
//! the piece is paper A's case of a point s + τ·v and a polygon p_i + τ·v_i over
//! τ ∈ [0, h] (§II for a rigid translation, §II.I for a warping polygon), with s, p_i
//! the exact positions at t_k and v, v_i the exact differences to t_{k+1} over h. On
//! each ring the oracle's [`crate::intervals::intervals`] gives the exact
//! components in 2D: the outer ring with inside (D = 0) or near_D, each hole with
//! breach_D (breach_0: not in the hole's open interior), so that
//! - region(τ) = ∨_parts [outer ∧ ∧_holes breach(hole)] (the closed outer minus the open
//!   holes, grown by D);
//! - vertical(τ) = floor − H ≤ z(τ) ≤ ceiling + H, z linear on the piece (a missing
//!   floor or ceiling bounds nothing; a fix without height makes the condition hold,
//!   and the truth says so: [`MovingTruth::vertical_unknown`]);
//! - the piece's set = region ∧ vertical, moved by t_k; the pieces' sets are unioned
//!   (components that meet at a breakpoint are one).
//!
//! A domain of one instant is judged at that instant. A ring that is not simple on a
//! piece (the fill rule would decide, an edge shrinks to a point) makes the truth
//! [`Undefined`], as does an input that breaks the model (times not increasing,
//! keyframes of different structures, a number that is not finite).

mod input;
pub mod times;

use core::cmp::Ordering;

use num_rational::BigRational;
use num_traits::Zero;

use crate::algebraic::RealAlg;
use crate::field::V2;
use crate::intervals::{at_least, intervals, meet, Components, Relation, Separation, Undefined};
use input::{bad, exact_fixes, exact_frames, Fix, Frame};
pub use input::{split_segments, PlaneArea, PlaneFix, PlaneFrame, PlaneRelation, PlaneRings};

/// The exact truth over one segment.
#[derive(Clone, Debug)]
pub struct MovingTruth {
    /// The domain [lo, hi]: the segment's fix times ∩ the area's existence (`None`:
    /// they do not meet, and there is no answer to give).
    pub domain: Option<(BigRational, BigRational)>,
    /// The relation's set of times in the domain: sorted, disjoint, closed.
    pub components: Components,
    /// A fix has no height and the area has a floor or a ceiling: the vertical
    /// condition is unknown, taken as holding here (the set is an upper bound, and no
    /// time of it is certain).
    pub vertical_unknown: bool,
}

/// Where t falls among increasing times (t within [first, last]): (i, λ) with the value
/// at t = value_i + λ·(value_{i+1} − value_i) (λ = 0 and i the last index at the last
/// time, or with one time).
/// (The model: positions linear in time between fixes and between keyframes.)
fn locate(times: &[&BigRational], t: &BigRational) -> (usize, BigRational) {
    let after = times.partition_point(|x| *x <= t);
    let i = after.saturating_sub(1);
    if i + 1 >= times.len() {
        return (i, BigRational::zero());
    }
    let lambda = (t - times[i]) / (times[i + 1] - times[i]);
    (i, lambda)
}

/// a + λ·(b − a).
/// (The model's exact linear interpolation.)
fn lerp(a: &BigRational, b: &BigRational, lambda: &BigRational) -> BigRational {
    a + (b - a) * lambda
}

/// The mover's position and height (when both ends have one) at t in its segment.
/// (The model's mover: straight at constant speed, height linear, between fixes.)
fn mover_at(fixes: &[Fix], t: &BigRational) -> (V2<BigRational>, Option<BigRational>) {
    let times: Vec<&BigRational> = fixes.iter().map(|f| &f.t).collect();
    let (i, lambda) = locate(&times, t);
    let a = &fixes[i];
    let Some(b) = fixes.get(i + 1) else {
        return (a.p.clone(), a.z.clone());
    };
    let p = V2::new(lerp(&a.p.x, &b.p.x, &lambda), lerp(&a.p.y, &b.p.y, &lambda));
    let z = match (&a.z, &b.z) {
        (Some(za), Some(zb)) => Some(lerp(za, zb, &lambda)),
        _ => None,
    };
    (p, z)
}

/// The area's rings at t in its existence: parts, rings, vertices.
/// (The model's keyframed area: each vertex linear in time between keyframes.)
fn area_at(frames: &[Frame], t: &BigRational) -> Vec<Vec<Vec<V2<BigRational>>>> {
    let times: Vec<&BigRational> = frames.iter().map(|f| &f.t).collect();
    let (i, lambda) = locate(&times, t);
    let a = &frames[i];
    let Some(b) = frames.get(i + 1) else {
        return a.parts.clone();
    };
    a.parts
        .iter()
        .zip(&b.parts)
        .map(|(pa, pb)| {
            pa.iter()
                .zip(pb)
                .map(|(ra, rb)| {
                    ra.iter()
                        .zip(rb)
                        .map(|(u, w)| V2::new(lerp(&u.x, &w.x, &lambda), lerp(&u.y, &w.y, &lambda)))
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// Twice the signed area of a ring (positive: counterclockwise).
/// (Paper A §II: the polygon is simple and counterclockwise.)
fn signed_area2(ring: &[V2<BigRational>]) -> BigRational {
    let n = ring.len();
    (0..n).fold(BigRational::zero(), |acc, i| {
        acc + ring[i].cross(&ring[(i + 1) % n])
    })
}

/// Which relation each ring is asked and the separations: (outer's, holes', D, H).
/// (The contract: near_D(area) = ∨ parts [near_D(outer) ∧ ∧ breach_D(hole)].)
fn rings_relations(
    relation: PlaneRelation,
) -> Result<(Relation, Relation, BigRational, BigRational), Undefined> {
    Ok(match input::separations(relation)? {
        None => (
            Relation::Inside,
            Relation::Breach,
            BigRational::zero(),
            BigRational::zero(),
        ),
        Some((d, h)) => (Relation::Near, Relation::Breach, d, h),
    })
}

/// What a piece is asked: the relations and separations, the floor and ceiling.
struct Ask {
    outer: Relation,
    hole: Relation,
    d: BigRational,
    h: BigRational,
    floor: Option<BigRational>,
    ceiling: Option<BigRational>,
}

/// The horizontal set over τ ∈ [0, h] of the point s + τ·v against the rings moving from
/// `from` to `to` over h (each ring made counterclockwise exactly at τ = 0).
/// (The contract: ∨ parts [outer ∧ ∧ holes], each ring by paper A §II/§II.I.)
fn region_set(
    ask: &Ask,
    h: &BigRational,
    s: &V2<BigRational>,
    v: &V2<BigRational>,
    from: &[Vec<Vec<V2<BigRational>>>],
    to: &[Vec<Vec<V2<BigRational>>>],
) -> Result<Components, Undefined> {
    let sep = Separation {
        d: ask.d.clone(),
        h: BigRational::zero(),
    };
    let mut region: Components = Vec::new();
    for (pa, pb) in from.iter().zip(to) {
        let mut part: Option<Components> = None;
        for (k, (ra, rb)) in pa.iter().zip(pb).enumerate() {
            let mut p = ra.clone();
            let mut vels: Vec<V2<BigRational>> = ra
                .iter()
                .zip(rb)
                .map(|(u, w)| V2::new((&w.x - &u.x) / h, (&w.y - &u.y) / h))
                .collect();
            match signed_area2(&p).cmp(&BigRational::zero()) {
                Ordering::Less => {
                    p.reverse();
                    vels.reverse();
                }
                Ordering::Equal => return bad("a ring has no area (it is not simple)"),
                Ordering::Greater => {}
            }
            let rel = if k == 0 { ask.outer } else { ask.hole };
            let set = intervals(h, s, v, &p, &vels, None, rel, &sep)?;
            part = Some(match part {
                None => set,
                Some(acc) => times::intersect(&acc, &set),
            });
            if part.as_ref().is_some_and(Vec::is_empty) {
                break;
            }
        }
        region = times::union(&region, &part.unwrap_or_default());
    }
    Ok(region)
}

/// The vertical condition floor − H ≤ z ≤ ceiling + H over τ ∈ [0, h], z from za to zb
/// (no height: the whole piece).
/// (The model's vertical relation: z linear in time, paper A §III's slab window.)
fn vertical_set(
    ask: &Ask,
    h: &BigRational,
    za: Option<&BigRational>,
    zb: Option<&BigRational>,
) -> Components {
    let (Some(za), Some(zb)) = (za, zb) else {
        return times::interval(BigRational::zero(), h.clone());
    };
    let vz = (zb - za) / h;
    let all = Some((BigRational::zero(), h.clone()));
    // z − (floor − H) ≥ 0 and (ceiling + H) − z ≥ 0, each c0 + c1·τ ≥ 0.
    let above = match &ask.floor {
        Some(f) => at_least(&(za - f + &ask.h), &vz, h),
        None => all.clone(),
    };
    let below = match &ask.ceiling {
        Some(c) => at_least(&(c + &ask.h - za), &-&vz, h),
        None => all,
    };
    match meet(above, below) {
        Some((a, b)) => times::interval(a, b),
        None => Vec::new(),
    }
}

/// The set of one piece [a, b] (a < b), in global time.
/// (The contract's exact truth: one paper-A case per piece, composed, moved by t_k.)
fn piece(
    ask: &Ask,
    fixes: &[Fix],
    frames: &[Frame],
    a: &BigRational,
    b: &BigRational,
) -> Result<Components, Undefined> {
    let h = b - a;
    let (pa, za) = mover_at(fixes, a);
    let (pb, zb) = mover_at(fixes, b);
    let v = V2::new((&pb.x - &pa.x) / &h, (&pb.y - &pa.y) / &h);
    let vertical = vertical_set(ask, &h, za.as_ref(), zb.as_ref());
    if vertical.is_empty() {
        return Ok(Vec::new());
    }
    let region = region_set(ask, &h, &pa, &v, &area_at(frames, a), &area_at(frames, b))?;
    Ok(times::shift(&times::intersect(&region, &vertical), a))
}

/// The relation at the one instant t: the piece of a still scene over [0, 1] (constant
/// in time, so all or nothing), kept at t alone.
/// (The contract's exact truth on a domain of one instant.)
fn instant(
    ask: &Ask,
    fixes: &[Fix],
    frames: &[Frame],
    t: &BigRational,
) -> Result<Components, Undefined> {
    let (p, z) = mover_at(fixes, t);
    let one = BigRational::from_integer(1.into());
    let rings = area_at(frames, t);
    let still = V2::new(BigRational::zero(), BigRational::zero());
    let vertical = vertical_set(ask, &one, z.as_ref(), z.as_ref());
    let region = region_set(ask, &one, &p, &still, &rings, &rings)?;
    let holds = !vertical.is_empty() && !region.is_empty();
    Ok(if holds {
        times::interval(t.clone(), t.clone())
    } else {
        Vec::new()
    })
}

/// The exact set of times of `relation` between the mover of one segment (`fixes`, no
/// gap) and `area`, over the domain (see the module doc).
/// (The contract's "exact truth": the planar model's inside and near_{D,H}.)
pub fn plane_truth(
    fixes: &[PlaneFix],
    area: &PlaneArea,
    relation: PlaneRelation,
) -> Result<MovingTruth, Undefined> {
    let fx = exact_fixes(fixes)?;
    let frames = exact_frames(area)?;
    let (outer, hole, d, h) = rings_relations(relation)?;
    let (floor, ceiling) = input::slab(area)?;
    let vertical_unknown =
        (floor.is_some() || ceiling.is_some()) && fx.iter().any(|f| f.z.is_none());
    let ask = Ask {
        outer,
        hole,
        d,
        h,
        floor,
        ceiling,
    };
    let (mut lo, mut hi) = (fx[0].t.clone(), fx[fx.len() - 1].t.clone());
    if !area.is_static {
        lo = lo.max(frames[0].t.clone());
        hi = hi.min(frames[frames.len() - 1].t.clone());
    }
    let mut truth = MovingTruth {
        domain: None,
        components: Vec::new(),
        vertical_unknown,
    };
    if lo > hi {
        return Ok(truth);
    }
    let mut cuts: Vec<BigRational> = fx
        .iter()
        .map(|f| &f.t)
        .chain(frames.iter().map(|f| &f.t).filter(|_| !area.is_static))
        .filter(|t| **t > lo && **t < hi)
        .cloned()
        .chain([lo.clone(), hi.clone()])
        .collect();
    cuts.sort();
    cuts.dedup();
    let mut parts = Vec::new();
    if cuts.len() == 1 {
        parts = instant(&ask, &fx, &frames, &lo)?;
    } else {
        for w in cuts.windows(2) {
            parts.extend(piece(&ask, &fx, &frames, &w[0], &w[1])?);
        }
    }
    truth.components = times::union_all(parts);
    truth.domain = Some((lo, hi));
    Ok(truth)
}

/// The components as decimal text (9 digits, toward −∞), for messages and tests.
/// (The contract's components, printed.)
pub fn components_text(c: &[(RealAlg, RealAlg)]) -> String {
    let parts: Vec<String> = c
        .iter()
        .map(|(a, b)| format!("[{}, {}]", a.to_decimal_string(9), b.to_decimal_string(9)))
        .collect();
    parts.join(" ")
}
