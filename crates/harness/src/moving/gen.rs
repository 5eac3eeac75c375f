//! Scenarios for the hunt of moving features (docs/assurance.md, "Moving features"):
//! whole flights of timed fixes against static and keyframed areas, given as the planar
//! model's types (`polyguard_earth::moving::plane`), where the sets inside and near_{D,H}
//! are hard to place:
//! - multi-leg flights (3–20 fixes, speeds and heights changing at every fix) across
//!   polygons with holes, MultiPolygons (parts apart or touching), floors and ceilings;
//! - trajectories split by gaps longer than max_gap (judged segment by segment);
//! - keyframed cells (2–5 frames) that grow, shrink, rotate and translate (each frame a
//!   similar copy of one shape, so that every instant is simple), sweeping over a
//!   mover between two of its fixes;
//! - legs cutting a corner between fixes (both fixes outside);
//! - small integer scenarios where legs pass exactly through vertices, along edges, or
//!   at exactly D from a corner or an edge;
//! - areas and flights across the antimeridian, drawn in degrees, unwrapped onto one
//!   branch around the first fix and projected with Mercator, as the Earth layer hands
//!   them over.
//!
//! Coordinates are mostly Mercator radians (|x| ≤ π) and times epoch seconds near 1.6e9
//! (their rounding is exercised); the integer scenarios use small times and coordinates.

use polyguard_earth::moving::plane::{PlaneArea, PlaneFix, PlaneFrame, PlaneRings};
use polyguard_earth::rhumb::{mercator, LonLat};

use crate::gen::Source;

/// The default max_gap of the model (seconds).
pub const MAX_GAP: f64 = 60.0;

/// A scenario of the moving hunt: one trajectory (perhaps several segments), one area,
/// the separations of near, and how it was drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingScenario {
    /// The fixes, times strictly increasing.
    pub fixes: Vec<PlaneFix>,
    /// The area.
    pub area: PlaneArea,
    /// Fixes farther apart than this are not joined.
    pub max_gap: f64,
    /// D of near (plane units).
    pub d: f64,
    /// H of near (feet).
    pub h: f64,
    /// The generator's name ([`Kind::name`]).
    pub mode: &'static str,
}

/// The scenarios drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A multi-leg flight across a polygon (holes, floor, ceiling).
    Legs,
    /// A multi-leg flight across a MultiPolygon (parts apart or touching).
    Multi,
    /// A flight with gaps longer than max_gap.
    Gaps,
    /// A keyframed cell growing, shrinking, rotating and moving about a flight.
    Cell,
    /// A keyframed cell sweeping over a slow mover between two fixes.
    Sweep,
    /// A leg cutting a polygon's corner between two fixes outside it.
    CornerCut,
    /// Small integers: legs through vertices, along edges, at exactly D.
    Exact,
    /// An area and a flight across the antimeridian, projected.
    Antimeridian,
}

impl Kind {
    /// Every kind.
    pub const ALL: [Kind; 8] = [
        Kind::Legs,
        Kind::Multi,
        Kind::Gaps,
        Kind::Cell,
        Kind::Sweep,
        Kind::CornerCut,
        Kind::Exact,
        Kind::Antimeridian,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Legs => "legs",
            Kind::Multi => "multi",
            Kind::Gaps => "gaps",
            Kind::Cell => "cell",
            Kind::Sweep => "sweep",
            Kind::CornerCut => "corner_cut",
            Kind::Exact => "exact",
            Kind::Antimeridian => "antimeridian",
        }
    }
}

/// One scenario of the hunt, of a kind drawn uniformly.
pub fn moving_scenario<S: Source>(src: &mut S) -> MovingScenario {
    let kind = src.pick(&Kind::ALL);
    scenario_of(src, kind)
}

/// One scenario of the given kind.
pub fn scenario_of<S: Source>(src: &mut S, kind: Kind) -> MovingScenario {
    match kind {
        Kind::Legs => legs(src, 1, false),
        Kind::Multi => {
            let parts = 2 + src.below(2);
            legs(src, parts, false)
        }
        Kind::Gaps => legs(src, 1, true),
        Kind::Cell => cell(src, false),
        Kind::Sweep => cell(src, true),
        Kind::CornerCut => corner_cut(src),
        Kind::Exact => exact(src),
        Kind::Antimeridian => antimeridian(src),
    }
}

/// A time near 1.6e9 s with a random fraction of a second.
fn epoch<S: Source>(src: &mut S) -> f64 {
    1.6e9 + src.range(0.0, 1e8)
}

/// A shape of unit size around the origin: (outer ring, holes), counterclockwise or
/// not, convex with a hole, or not convex.
fn shape<S: Source>(src: &mut S) -> (Vec<[f64; 2]>, Vec<Vec<[f64; 2]>>) {
    let n = 3 + src.below(6);
    let phase = src.range(0.0, std::f64::consts::TAU);
    let regular: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let a = phase + std::f64::consts::TAU * k as f64 / n as f64;
            [a.cos(), a.sin()]
        })
        .collect();
    let (mut outer, convex) = match src.below(4) {
        // a comb: teeth along x, open upwards (not convex)
        0 => {
            let teeth = 2 + src.below(3);
            let w = 2.0 / (2 * teeth - 1) as f64;
            let mut r = vec![[-1.0, -1.0], [1.0, -1.0]];
            for k in (0..teeth).rev() {
                let x1 = -1.0 + (2 * k + 1) as f64 * w;
                let x0 = x1 - w;
                r.push([x1, 1.0]);
                r.push([x0, 1.0]);
                if k > 0 {
                    r.push([x0, 0.0]);
                    r.push([x0 - w, 0.0]);
                }
            }
            (r, false)
        }
        1 => (
            vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]],
            true,
        ),
        _ => (regular, true),
    };
    let mut holes = Vec::new();
    if convex && src.below(3) == 0 {
        let s = src.range(0.2, 0.5);
        let c = [src.range(-0.1, 0.1), src.range(-0.1, 0.1)];
        holes.push(vec![
            [c[0] - s, c[1] - s],
            [c[0] + s, c[1] - s],
            [c[0] + s, c[1] + s],
            [c[0] - s, c[1] + s],
        ]);
    }
    if src.coin() {
        outer.reverse();
    }
    (outer, holes)
}

/// The shape moved to `c`, scaled by `s` and turned by `a`.
fn placed(ring: &[[f64; 2]], c: [f64; 2], s: f64, a: f64) -> Vec<[f64; 2]> {
    let (sn, cs) = a.sin_cos();
    ring.iter()
        .map(|p| {
            [
                c[0] + s * (cs * p[0] - sn * p[1]),
                c[1] + s * (sn * p[0] + cs * p[1]),
            ]
        })
        .collect()
}

/// A slab for an area (each of floor and ceiling present or not), in feet.
fn slab<S: Source>(src: &mut S) -> (Option<f64>, Option<f64>) {
    match src.below(4) {
        0 => (None, None),
        1 => (Some(src.range(0.0, 20_000.0).round()), None),
        2 => (None, Some(src.range(5_000.0, 40_000.0).round())),
        _ => {
            let f = src.range(0.0, 20_000.0).round();
            (Some(f), Some(f + src.range(1_000.0, 20_000.0).round()))
        }
    }
}

/// Heights for n fixes about a slab (a climb or a descent through it at times), or none
/// (one flight in eight).
fn heights<S: Source>(src: &mut S, n: usize, slab: (Option<f64>, Option<f64>)) -> Vec<Option<f64>> {
    if src.below(8) == 0 {
        return vec![None; n];
    }
    let lo = slab.0.unwrap_or(5_000.0) - 3_000.0;
    let hi = slab.1.unwrap_or(lo + 20_000.0) + 3_000.0;
    let mut z = src.range(lo, hi);
    (0..n)
        .map(|_| {
            z = (z + src.range(-4_000.0, 4_000.0)).clamp(lo, hi);
            Some(z)
        })
        .collect()
}

/// A flight of n fixes from `t0` over points drawn around `c` within `reach`, legs of
/// 5–55 s (or, with `gaps`, some of 61–600 s), heights from `z`.
fn flight<S: Source>(
    src: &mut S,
    n: usize,
    t0: f64,
    c: [f64; 2],
    reach: f64,
    z: &[Option<f64>],
    gaps: bool,
) -> Vec<PlaneFix> {
    let mut t = t0;
    (0..n)
        .map(|k| {
            if k > 0 {
                t += if gaps && src.below(4) == 0 {
                    src.range(MAX_GAP + 1.0, 600.0)
                } else {
                    src.range(5.0, 55.0)
                };
            }
            PlaneFix {
                t,
                x: c[0] + src.range(-reach, reach),
                y: c[1] + src.range(-reach, reach),
                z: z.get(k).copied().flatten(),
            }
        })
        .collect()
}

/// A size in Mercator radians (about 6 km to 60 km) and a centre within |x| ≤ 3, |y| ≤ 1.5.
fn place<S: Source>(src: &mut S) -> ([f64; 2], f64) {
    let size = 10f64.powf(src.range(-3.0, -2.0));
    ([src.range(-3.0, 3.0), src.range(-1.5, 1.5)], size)
}

/// D of near: 0 (one in eight) or 10⁻³ to 1 sizes; H: 0 to 2000 ft.
fn separations<S: Source>(src: &mut S, size: f64) -> (f64, f64) {
    let d = if src.below(8) == 0 {
        0.0
    } else {
        size * 10f64.powf(src.range(-3.0, 0.0))
    };
    (d, src.range(0.0, 2_000.0).round())
}

/// A static polygon (or `parts` of them, apart or touching) and a multi-leg flight.
fn legs<S: Source>(src: &mut S, parts: usize, gaps: bool) -> MovingScenario {
    let (c, size) = place(src);
    let touching = parts > 1 && src.coin();
    let mut rings = Vec::with_capacity(parts);
    for k in 0..parts {
        let (outer, holes) = shape(src);
        let (cc, s, a) = if touching {
            // unit squares side by side share an edge
            let sq = vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
            let cc = [c[0] + 2.0 * size * k as f64, c[1]];
            rings.push(PlaneRings {
                outer: placed(&sq, cc, size, 0.0),
                holes: Vec::new(),
            });
            continue;
        } else {
            let cc = [c[0] + 3.0 * size * k as f64, c[1] + src.range(-size, size)];
            (cc, size, src.range(0.0, 6.3))
        };
        rings.push(PlaneRings {
            outer: placed(&outer, cc, s, a),
            holes: holes.iter().map(|h| placed(h, cc, s, a)).collect(),
        });
    }
    let (floor, ceiling) = slab(src);
    let n = 3 + src.below(18);
    let z = heights(src, n, (floor, ceiling));
    let mid = [c[0] + 1.5 * size * (parts - 1) as f64, c[1]];
    let reach = size * (1.5 + 1.5 * parts as f64);
    let t0 = epoch(src);
    let fixes = flight(src, n, t0, mid, reach, &z, gaps);
    let (d, h) = separations(src, size);
    MovingScenario {
        fixes,
        area: PlaneArea {
            frames: vec![PlaneFrame {
                t: 0.0,
                parts: rings,
            }],
            is_static: true,
            floor,
            ceiling,
        },
        max_gap: MAX_GAP,
        d,
        h,
        mode: if gaps {
            Kind::Gaps.name()
        } else if parts > 1 {
            Kind::Multi.name()
        } else {
            Kind::Legs.name()
        },
    }
}

/// A keyframed cell: 2–5 frames, each the shape placed at a centre, scale and angle
/// (turns under a quarter between frames: every instant is a similar copy, so simple).
/// With `sweep`, the mover is slow with fixes far apart and the cell crosses it between
/// two of them; else a flight goes about a cell that grows, shrinks, turns and moves.
fn cell<S: Source>(src: &mut S, sweep: bool) -> MovingScenario {
    let (c, size) = place(src);
    let (outer, holes) = shape(src);
    let frames_n = 2 + src.below(4);
    let t0 = epoch(src);
    let span = src.range(60.0, 400.0);
    let fixes_n = if sweep {
        2 + src.below(2)
    } else {
        3 + src.below(10)
    };
    let (floor, ceiling) = if sweep { (None, None) } else { slab(src) };
    let z = heights(src, fixes_n, (floor, ceiling));
    let fixes = if sweep {
        // a slow mover: fixes at the ends of the span (and one near an end)
        let mut times = vec![t0, t0 + span];
        if fixes_n == 3 {
            times.insert(1, t0 + span * src.range(0.02, 0.1));
        }
        let drift = size * 0.2;
        times
            .iter()
            .enumerate()
            .map(|(k, &t)| PlaneFix {
                t,
                x: c[0] + src.range(-drift, drift),
                y: c[1] + src.range(-drift, drift),
                z: z[k],
            })
            .collect()
    } else {
        flight(src, fixes_n, t0, c, size * 3.0, &z, false)
    };
    let first_t = fixes[0].t;
    let last_t = fixes[fixes.len() - 1].t;
    let (from, to) = if sweep || src.below(3) != 0 {
        (
            first_t - src.range(0.0, 30.0),
            last_t + src.range(0.0, 30.0),
        )
    } else {
        // existence inside the flight's time
        let a = first_t + (last_t - first_t) * src.range(0.0, 0.4);
        (a, a + (last_t - a) * src.range(0.3, 1.0))
    };
    let mut angle = src.range(0.0, 6.3);
    let frames: Vec<PlaneFrame> = (0..frames_n)
        .map(|k| {
            let u = k as f64 / (frames_n - 1) as f64;
            let t = from + (to - from) * u;
            let centre = if sweep {
                // from 3 sizes left of the mover to 3 sizes right, through it mid-span
                [
                    c[0] + size * 3.0 * (2.0 * u - 1.0),
                    c[1] + src.range(-0.3, 0.3) * size,
                ]
            } else {
                [c[0] + src.range(-size, size), c[1] + src.range(-size, size)]
            };
            let s = size * src.range(0.4, 1.6);
            angle += src.range(-1.2, 1.2);
            PlaneFrame {
                t,
                parts: vec![PlaneRings {
                    outer: placed(&outer, centre, s, angle),
                    holes: holes.iter().map(|h| placed(h, centre, s, angle)).collect(),
                }],
            }
        })
        .collect();
    let (d, h) = separations(src, size);
    MovingScenario {
        fixes,
        area: PlaneArea {
            frames,
            is_static: false,
            floor,
            ceiling,
        },
        max_gap: if sweep { 1e4 } else { MAX_GAP },
        d,
        h,
        mode: if sweep {
            Kind::Sweep.name()
        } else {
            Kind::Cell.name()
        },
    }
}

/// A square and a leg from outside one side of a corner to outside the other, cutting
/// the corner in between, with fixes before and after, all outside.
fn corner_cut<S: Source>(src: &mut S) -> MovingScenario {
    let (c, size) = place(src);
    let sq = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let angle = src.range(0.0, 6.3);
    let outer = placed(&sq, c, size, angle);
    // in the square's own frame: corner (1, 1); A above the top edge, B right of the
    // right edge; their midpoint is inside
    let depth = src.range(0.05, 0.4);
    let a = [1.0 - 2.0 * depth - 0.1, 1.0 + src.range(0.02, 0.2)];
    let b = [1.0 + src.range(0.02, 0.2), 1.0 - 2.0 * depth - 0.1];
    let before = [-0.5, 3.0];
    let after = [3.0, -0.5];
    let pts = placed(&[before, a, b, after], c, size, angle);
    let mut t = epoch(src);
    let fixes = pts
        .iter()
        .map(|p| {
            t += src.range(5.0, 55.0);
            PlaneFix {
                t,
                x: p[0],
                y: p[1],
                z: None,
            }
        })
        .collect();
    let (d, h) = separations(src, size);
    MovingScenario {
        fixes,
        area: PlaneArea {
            frames: vec![PlaneFrame {
                t: 0.0,
                parts: vec![PlaneRings {
                    outer,
                    holes: Vec::new(),
                }],
            }],
            is_static: true,
            floor: None,
            ceiling: None,
        },
        max_gap: MAX_GAP,
        d: d.min(size * 0.01),
        h,
        mode: Kind::CornerCut.name(),
    }
}

/// Small integers: the square [0, 8]² (or a keyframed one moving by whole units per
/// second) against legs through its vertices, along its edges, touching a corner, or
/// at exactly D = 1 or 2 from an edge or a corner; times are small integers.
fn exact<S: Source>(src: &mut S) -> MovingScenario {
    let paths: [&[[f64; 2]]; 6] = [
        // the diagonal through (0, 0) and (8, 8)
        &[[-4.0, -4.0], [12.0, 12.0]],
        // along the bottom edge, then up the right one
        &[[-4.0, 0.0], [8.0, 0.0], [8.0, 12.0]],
        // touching the corner (8, 8) alone
        &[[4.0, 12.0], [12.0, 4.0]],
        // at y = 10, exactly 2 above the top edge; then down through (10, 0)
        &[[-4.0, 10.0], [10.0, 10.0], [10.0, 0.0]],
        // passing the corner (0, 0) at distance 1 along y = −1, then turning in
        &[[-6.0, -1.0], [0.0, -1.0], [4.0, 4.0]],
        // in and out through a vertex, a leg ending on an edge
        &[[-2.0, 4.0], [0.0, 8.0], [4.0, 8.0], [4.0, 4.0]],
    ];
    let path = src.pick(&paths);
    let off = [src.below(5) as f64 - 2.0, src.below(5) as f64 - 2.0];
    let mut t = src.below(10) as f64;
    let fixes: Vec<PlaneFix> = path
        .iter()
        .map(|p| {
            t += 1.0 + src.below(8) as f64;
            PlaneFix {
                t,
                x: p[0] + off[0],
                y: p[1] + off[1],
                z: None,
            }
        })
        .collect();
    let sq = vec![[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]];
    let area = if src.coin() {
        PlaneArea {
            frames: vec![PlaneFrame {
                t: 0.0,
                parts: vec![PlaneRings {
                    outer: sq,
                    holes: Vec::new(),
                }],
            }],
            is_static: true,
            floor: None,
            ceiling: None,
        }
    } else {
        // keyframed: moved by whole units at whole times, first frame at the first fix
        let t0 = fixes[0].t;
        let frames = (0..2 + src.below(3))
            .map(|k| {
                let shift = [src.below(5) as f64 - 2.0, src.below(5) as f64 - 2.0];
                PlaneFrame {
                    t: t0 + 4.0 * k as f64,
                    parts: vec![PlaneRings {
                        outer: sq
                            .iter()
                            .map(|p| [p[0] + shift[0], p[1] + shift[1]])
                            .collect(),
                        holes: Vec::new(),
                    }],
                }
            })
            .collect();
        PlaneArea {
            frames,
            is_static: false,
            floor: None,
            ceiling: None,
        }
    };
    MovingScenario {
        fixes,
        area,
        max_gap: MAX_GAP,
        d: src.pick(&[0.0, 1.0, 2.0]),
        h: 0.0,
        mode: Kind::Exact.name(),
    }
}

/// Longitude `lon` (degrees) moved by whole turns to within 180° of `reference`.
fn unwrap(lon: f64, reference: f64) -> f64 {
    let mut l = lon;
    while l - reference > 180.0 {
        l -= 360.0;
    }
    while l - reference < -180.0 {
        l += 360.0;
    }
    l
}

/// A longitude in degrees wrapped into [−180, 180).
fn wrap(lon: f64) -> f64 {
    (lon + 180.0).rem_euclid(360.0) - 180.0
}

/// Mercator of (lon, lat) in degrees.
fn project(lon: f64, lat: f64) -> [f64; 2] {
    mercator(LonLat::from_degrees(lon, lat))
}

/// An area and a flight across ±180°, drawn in degrees (longitudes wrapped as a file
/// gives them), unwrapped onto one branch around the first fix (each next longitude
/// the shorter way from the previous one) and projected.
fn antimeridian<S: Source>(src: &mut S) -> MovingScenario {
    let lat0 = src.range(-60.0, 60.0);
    let lon0 = 180.0 + src.range(-0.3, 0.3);
    let size_deg = 10f64.powf(src.range(-1.5, -0.5));
    let (outer, holes) = shape(src);
    let angle = src.range(0.0, 6.3);
    let ring_deg = |r: &[[f64; 2]]| -> Vec<[f64; 2]> {
        placed(r, [lon0, lat0], size_deg, angle)
            .into_iter()
            .map(|p| [wrap(p[0]), p[1]])
            .collect()
    };
    let n = 3 + src.below(10);
    let mut t = epoch(src);
    let fixes_deg: Vec<(f64, [f64; 2])> = (0..n)
        .map(|k| {
            if k > 0 {
                t += src.range(5.0, 55.0);
            }
            let p = [
                lon0 + src.range(-3.0, 3.0) * size_deg,
                lat0 + src.range(-3.0, 3.0) * size_deg,
            ];
            (t, [wrap(p[0]), p[1]])
        })
        .collect();
    // one branch: the first fix's longitude, then each the shorter way from the last
    let mut last = fixes_deg[0].1[0];
    let mut along = |lon: f64| {
        last = unwrap(lon, last);
        last
    };
    let fixes: Vec<PlaneFix> = fixes_deg
        .iter()
        .map(|(t, p)| {
            let m = project(along(p[0]), p[1]);
            PlaneFix {
                t: *t,
                x: m[0],
                y: m[1],
                z: None,
            }
        })
        .collect();
    let reference = fixes_deg[0].1[0];
    let on_branch = |r: Vec<[f64; 2]>| -> Vec<[f64; 2]> {
        let mut prev = unwrap(r[0][0], reference);
        r.iter()
            .map(|p| {
                prev = unwrap(p[0], prev);
                project(prev, p[1])
            })
            .collect()
    };
    let rings = PlaneRings {
        outer: on_branch(ring_deg(&outer)),
        holes: holes.iter().map(|h| on_branch(ring_deg(h))).collect(),
    };
    let size = size_deg.to_radians();
    let (d, h) = separations(src, size);
    MovingScenario {
        fixes,
        area: PlaneArea {
            frames: vec![PlaneFrame {
                t: 0.0,
                parts: vec![rings],
            }],
            is_static: true,
            floor: None,
            ceiling: None,
        },
        max_gap: MAX_GAP,
        d,
        h,
        mode: Kind::Antimeridian.name(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::SplitMix;

    #[test]
    fn moving_scenarios_keep_the_model_rules() {
        for seed in 0..400u64 {
            let s = moving_scenario(&mut SplitMix(seed));
            assert!(s.fixes.windows(2).all(|w| w[0].t < w[1].t), "{seed}");
            assert!(s.fixes.iter().all(|f| f.x.is_finite() && f.y.is_finite()));
            let first = &s.area.frames[0];
            for f in &s.area.frames {
                assert_eq!(f.parts.len(), first.parts.len());
            }
            if !s.area.is_static {
                assert!(s.area.frames.len() >= 2);
                assert!(s.area.frames.windows(2).all(|w| w[0].t < w[1].t), "{seed}");
            }
            assert!(s.d >= 0.0 && s.h >= 0.0);
        }
    }

    #[test]
    fn moving_antimeridian_scenarios_stay_on_one_branch() {
        for seed in 0..200u64 {
            let s = scenario_of(&mut SplitMix(seed), Kind::Antimeridian);
            let xs = s
                .fixes
                .iter()
                .map(|f| f.x)
                .chain(s.area.frames[0].parts[0].outer.iter().map(|p| p[0]));
            let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
            // within a few degrees of each other, around ±π
            assert!(hi - lo < 0.5, "{seed}: {lo} .. {hi}");
            assert!(lo.abs() > 2.5, "{seed}: {lo}");
        }
    }
}
