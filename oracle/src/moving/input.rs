//! The inputs of the moving truth (docs/moving-features.md, "The planar model"): the
//! planar types as the engine's `moving::plane` gives them, with f64 numbers, and
//! their exact form (every f64 is the rational it denotes: the model's exact points,
//! paper A §II's exact case inputs). The one file of the moving truth that names the
//! float type: the numbers are made exact here and nowhere else.

use core::ops::Range;

use num_rational::BigRational;
use num_traits::Signed;

use crate::convert::q;
use crate::field::V2;
use crate::intervals::Undefined;

/// One fix on the plane: at time `t` the mover is at `(x, y)`, height `z` when known
/// (the engine's `moving::plane::PlaneFix`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneFix {
    /// Time (seconds).
    pub t: f64,
    /// Abscissa.
    pub x: f64,
    /// Ordinate.
    pub y: f64,
    /// Height (feet), absent when unknown.
    pub z: Option<f64>,
}

/// One polygon on the plane: an outer ring and holes, not closed, either winding.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneRings {
    /// The outer ring.
    pub outer: Vec<[f64; 2]>,
    /// The holes.
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// An area's polygons at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneFrame {
    /// Time (seconds).
    pub t: f64,
    /// The parts (their union is the region).
    pub parts: Vec<PlaneRings>,
}

/// An area on the plane: static (its first frame, at all times) or keyframed (frames
/// strictly increasing in time, the same structure in each, vertices linear in time
/// between them; existing from the first frame to the last).
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneArea {
    /// The frames.
    pub frames: Vec<PlaneFrame>,
    /// One frame valid at all times.
    pub is_static: bool,
    /// The floor (absent: unbounded below).
    pub floor: Option<f64>,
    /// The ceiling (absent: unbounded above).
    pub ceiling: Option<f64>,
}

/// Which set of times: inside, or near within D (plane units) and H (feet).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlaneRelation {
    /// inside(t): in the region, between floor and ceiling.
    Inside,
    /// near(t): within D of the region, within H of the floor–ceiling slab.
    Near {
        /// D ≥ 0.
        d: f64,
        /// H ≥ 0.
        h: f64,
    },
}

/// A fix made exact.
pub(super) struct Fix {
    pub t: BigRational,
    pub p: V2<BigRational>,
    pub z: Option<BigRational>,
}

/// A frame made exact: parts, each its rings (the outer first), each its vertices.
pub(super) struct Frame {
    pub t: BigRational,
    pub parts: Vec<Vec<Vec<V2<BigRational>>>>,
}

/// The refusal of an input that breaks the model.
pub(super) fn bad<T>(why: impl Into<String>) -> Result<T, Undefined> {
    Err(Undefined { reason: why.into() })
}

/// An f64 as its exact rational, refused when not finite.
/// (The planar model: every input is the exact rational it denotes.)
fn exact(x: f64, what: &str) -> Result<BigRational, Undefined> {
    match q(x) {
        Some(r) => Ok(r),
        None => bad(format!("{what} is not finite")),
    }
}

/// A point made exact.
/// (The planar model: every input is the exact rational it denotes.)
fn point(p: [f64; 2], what: &str) -> Result<V2<BigRational>, Undefined> {
    Ok(V2::new(exact(p[0], what)?, exact(p[1], what)?))
}

/// The fixes made exact; times strictly increasing, at least one fix.
/// (The model's mover: fixes with t strictly increasing.)
pub(super) fn exact_fixes(fixes: &[PlaneFix]) -> Result<Vec<Fix>, Undefined> {
    let mut out: Vec<Fix> = Vec::with_capacity(fixes.len());
    for (i, f) in fixes.iter().enumerate() {
        let t = exact(f.t, "a fix's time")?;
        if out.last().is_some_and(|l| l.t >= t) {
            return bad(format!("fix {i}: times must increase strictly"));
        }
        let z = match f.z {
            Some(z) => Some(exact(z, "a fix's height")?),
            None => None,
        };
        out.push(Fix {
            t,
            p: point([f.x, f.y], "a fix's position")?,
            z,
        });
    }
    if out.is_empty() {
        return bad("a segment needs at least one fix");
    }
    Ok(out)
}

/// The frames made exact (a static area: its first frame alone); keyframe times
/// strictly increasing, every frame of the first one's structure, rings of ≥ 3 vertices.
/// (The model's area: the same structure at every instant.)
pub(super) fn exact_frames(area: &PlaneArea) -> Result<Vec<Frame>, Undefined> {
    let frames = if area.is_static {
        area.frames.get(..1).unwrap_or(&[])
    } else {
        &area.frames[..]
    };
    let Some(first) = frames.first() else {
        return bad("an area needs at least one frame");
    };
    let shape = |f: &PlaneFrame| -> Vec<Vec<usize>> {
        f.parts
            .iter()
            .map(|p| {
                core::iter::once(p.outer.len())
                    .chain(p.holes.iter().map(Vec::len))
                    .collect()
            })
            .collect()
    };
    let want = shape(first);
    if want.is_empty() || want.iter().flatten().any(|&n| n < 3) {
        return bad("every ring needs at least 3 vertices, and an area at least one part");
    }
    let mut out: Vec<Frame> = Vec::with_capacity(frames.len());
    for (k, f) in frames.iter().enumerate() {
        if shape(f) != want {
            return bad(format!(
                "keyframe {k} has another structure than keyframe 0"
            ));
        }
        let t = exact(f.t, "a keyframe's time")?;
        if out.last().is_some_and(|l| l.t >= t) {
            return bad(format!("keyframe {k}: times must increase strictly"));
        }
        let mut parts = Vec::with_capacity(f.parts.len());
        for p in &f.parts {
            let mut rings = Vec::with_capacity(1 + p.holes.len());
            for ring in core::iter::once(&p.outer).chain(&p.holes) {
                let r: Result<Vec<_>, _> = ring.iter().map(|&v| point(v, "a vertex")).collect();
                rings.push(r?);
            }
            parts.push(rings);
        }
        out.push(Frame { t, parts });
    }
    Ok(out)
}

/// D and H of a near relation made exact (`None` for inside); both ≥ 0.
/// (The contract's separations D ≥ 0, H ≥ 0.)
pub(super) fn separations(
    relation: PlaneRelation,
) -> Result<Option<(BigRational, BigRational)>, Undefined> {
    match relation {
        PlaneRelation::Inside => Ok(None),
        PlaneRelation::Near { d, h } => {
            let (d, h) = (exact(d, "D")?, exact(h, "H")?);
            if d.is_negative() || h.is_negative() {
                return bad("the separations D and H must be ≥ 0");
            }
            Ok(Some((d, h)))
        }
    }
}

/// The floor and the ceiling made exact (absent: unbounded).
/// (The model's area: optional floor ≤ ceiling, constant in time.)
pub(super) fn slab(
    area: &PlaneArea,
) -> Result<(Option<BigRational>, Option<BigRational>), Undefined> {
    let floor = area.floor.map(|f| exact(f, "the floor")).transpose()?;
    let ceiling = area.ceiling.map(|c| exact(c, "the ceiling")).transpose()?;
    Ok((floor, ceiling))
}

/// The segments of a trajectory: maximal runs of fixes whose consecutive times are at
/// most `max_gap` apart (exactly), as index ranges.
/// (The model's mover: fixes more than max_gap apart are not joined.)
pub fn split_segments(fixes: &[PlaneFix], max_gap: f64) -> Vec<Range<usize>> {
    let gap = q(max_gap);
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..fixes.len() {
        let joined = match (q(fixes[i - 1].t), q(fixes[i].t), &gap) {
            (Some(a), Some(b), Some(g)) => &(b - a) <= g,
            // an infinite max_gap joins everything; a time that is not finite nothing
            (_, _, None) => max_gap > 0.0,
            _ => false,
        };
        if !joined {
            out.push(start..i);
            start = i;
        }
    }
    if !fixes.is_empty() {
        out.push(start..fixes.len());
    }
    out
}
