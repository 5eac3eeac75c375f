//! The planar model of docs/moving-features.md: fixes and keyframed polygons already on a
//! plane (the Earth layer gives Mercator coordinates), the exact interpolation between
//! them, and the relations' certified spans over one segment of a trajectory. This is
//! what the exact truth (`polyguard_oracle::moving`) checks.

use super::piece::{piece_timeline, FarCache, Margins};
pub use super::planar::{
    PlaneArea, PlaneError, PlaneFix, PlaneFrame, PlaneRelation, PlaneRings, TimeSpan,
};
use super::prepared::Prepared;
use super::timeline::Timeline;

/// The segments of a trajectory: maximal runs of fixes in which consecutive fixes are at
/// most `max_gap` apart (docs/moving-features.md: longer gaps are not joined).
pub fn split_segments(fixes: &[PlaneFix], max_gap: f64) -> Vec<core::ops::Range<usize>> {
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..=fixes.len() {
        if i == fixes.len() || fixes[i].t - fixes[i - 1].t > max_gap {
            if i > start {
                out.push(start..i);
            }
            start = i;
        }
    }
    out
}

/// `x` when finite.
fn finite(what: impl FnOnce() -> String, x: f64) -> Result<(), PlaneError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(PlaneError::NotFinite { what: what() })
    }
}

/// The planar model's rules (docs/moving-features.md) on one segment and one area.
fn validate(fixes: &[PlaneFix], area: &PlaneArea) -> Result<(), PlaneError> {
    for (i, f) in fixes.iter().enumerate() {
        for (name, x) in [
            ("t", f.t),
            ("x", f.x),
            ("y", f.y),
            ("z", f.z.unwrap_or(0.0)),
        ] {
            finite(|| format!("fixes[{i}].{name}"), x)?;
        }
        if i > 0 && f.t <= fixes[i - 1].t {
            return Err(PlaneError::NotIncreasing {
                what: "fixes".into(),
            });
        }
    }
    let Some(first) = area.frames.first() else {
        return Err(PlaneError::Degenerate {
            what: "area.frames".into(),
        });
    };
    for (k, f) in area.frames.iter().enumerate() {
        finite(|| format!("frames[{k}].t"), f.t)?;
        if k > 0 && !area.is_static && f.t <= area.frames[k - 1].t {
            return Err(PlaneError::NotIncreasing {
                what: "frames".into(),
            });
        }
        let same = f.parts.len() == first.parts.len()
            && f.parts.iter().zip(&first.parts).all(|(a, b)| {
                a.outer.len() == b.outer.len()
                    && a.holes.len() == b.holes.len()
                    && a.holes
                        .iter()
                        .zip(&b.holes)
                        .all(|(x, y)| x.len() == y.len())
            });
        if !same {
            return Err(PlaneError::StructureChanges { frame: k });
        }
        for (j, part) in f.parts.iter().enumerate() {
            for (r, ring) in core::iter::once(&part.outer).chain(&part.holes).enumerate() {
                if ring.len() < 3 {
                    return Err(PlaneError::Degenerate {
                        what: format!("frames[{k}].parts[{j}] ring {r}"),
                    });
                }
                for (i, p) in ring.iter().enumerate() {
                    for (c, x) in p.iter().enumerate() {
                        finite(|| format!("frames[{k}].parts[{j}] ring {r}[{i}][{c}]"), *x)?;
                    }
                }
            }
        }
    }
    if first.parts.is_empty() {
        return Err(PlaneError::Degenerate {
            what: "area.frames[0].parts".into(),
        });
    }
    for (name, x) in [("floor", area.floor), ("ceiling", area.ceiling)] {
        if let Some(x) = x {
            finite(|| name.into(), x)?;
        }
    }
    Ok(())
}

/// The certified spans of `relation` over one segment (fixes without a gap, ≥ 1), against
/// `area` (docs/moving-features.md, "The contract"): over the domain [first fix, last
/// fix] ∩ the area's existence, G1–G3 hold with global times. Each piece between
/// consecutive breakpoints (fix and keyframe times) is one paper-A case per ring
/// (module `piece`); their timelines are joined and turned into spans
/// (`timeline::Timeline::to_spans`).
pub fn plane_spans(
    fixes: &[PlaneFix],
    area: &PlaneArea,
    relation: PlaneRelation,
) -> Result<Vec<TimeSpan>, PlaneError> {
    validate(fixes, area)?;
    let prepared = Prepared::new(area);
    let (h, m) = match relation {
        PlaneRelation::Inside => (
            0.0,
            Margins {
                d_lo: 0.0,
                d_hi: 0.0,
                extra_point: 0.0,
                extra_area: 0.0,
                extra_z: 0.0,
            },
        ),
        PlaneRelation::Near { d_lo, d_hi, h } => (
            h,
            Margins {
                d_lo,
                d_hi,
                extra_point: 0.0,
                extra_area: 0.0,
                extra_z: 0.0,
            },
        ),
    };
    Ok(timeline_with(fixes, area, &prepared, h, &|_, _| m)
        .map(|t| t.closed().to_spans())
        .unwrap_or_default())
}

/// The timeline under [`plane_spans`], on validated input, with `margins` of each piece
/// [t0, t1] (the Earth layer's) and the vertical separation `h_sep` (0 for inside); `None`
/// when the domain is empty.
pub(crate) fn timeline_with(
    fixes: &[PlaneFix],
    area: &PlaneArea,
    prepared: &Prepared,
    h_sep: f64,
    margins: &dyn Fn(f64, f64) -> Margins,
) -> Option<Timeline> {
    let (Some(first), Some(last)) = (fixes.first(), fixes.last()) else {
        return None;
    };
    let (mut a, mut b) = (first.t, last.t);
    if !area.is_static {
        a = a.max(area.frames[0].t);
        b = b.min(area.frames[area.frames.len() - 1].t);
    }
    if a > b {
        return None;
    }
    if a == b {
        return Some(instant(fixes, area, h_sep, margins(a, b), a));
    }
    let mut cuts: Vec<f64> = vec![a, b];
    cuts.extend(fixes.iter().map(|f| f.t).filter(|&t| t > a && t < b));
    if !area.is_static {
        cuts.extend(area.frames.iter().map(|f| f.t).filter(|&t| t > a && t < b));
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut tl: Option<Timeline> = None;
    let mut cache = FarCache::default();
    for w in cuts.windows(2) {
        let p = piece_timeline(
            &mut cache,
            fixes,
            area,
            prepared,
            h_sep,
            margins(w[0], w[1]),
            w[0],
            w[1],
        );
        tl = Some(match tl {
            None => p,
            Some(t) => t.then(&p),
        });
    }
    tl
}

/// The timeline of a domain that is one instant `a`: the engine needs a duration, so the
/// mover and the area are frozen as they are at `a` over a piece of length 1, on which
/// every set is constant; its value at the start is the answer.
fn instant(fixes: &[PlaneFix], area: &PlaneArea, h_sep: f64, m: Margins, a: f64) -> Timeline {
    let (frame, err) = super::piece::frame_at(area, a);
    let m = Margins {
        extra_area: m.extra_area + 2.0 * err,
        ..m
    };
    let frozen = PlaneArea {
        frames: vec![PlaneFrame { t: 0.0, ..frame }],
        is_static: true,
        floor: area.floor,
        ceiling: area.ceiling,
    };
    let p = fixes.iter().find(|f| f.t == a).copied().unwrap_or(fixes[0]);
    let still = [PlaneFix { t: 0.0, ..p }, PlaneFix { t: 1.0, ..p }];
    let tl = piece_timeline(
        &mut FarCache::default(),
        &still,
        &frozen,
        &Prepared::new(&frozen),
        h_sep,
        m,
        0.0,
        1.0,
    );
    Timeline::constant(a, a, tl.value_at(0.0))
}
