//! The cases of the way-out hunt (`polyguard assure --paper wayout`), drawn from a
//! [`Source`]: band cases (a point among 1–10 moving polygons of paper A §II–§III, 2D or
//! 3D with slabs), recovery cases (a point and one polygon, static or at a time t) and
//! offset or inset cases (one polygon, small or large D).
//!
//! Polygons are star-shaped about a centre (angles increasing, so simple and
//! counterclockwise before rounding; redrawn when the rounded ring is not, decided
//! exactly by [`polyguard::ring::simple_ccw`]), a star with one sharp spike, a C whose
//! mouth a large D closes, or a thin rectangle (whose D-core is empty when D exceeds
//! half its width). A moving polygon translates, or warps as a homothety about its
//! centre plus a translation (p_i + t·(u + k·(p_i − c))), which keeps it similar to
//! itself, hence simple, while 1 + t·k > 0 (up to the rounding of the velocities; a
//! case the oracle finds not simple is counted `undefined`, not judged).
//!
//! Band cases aim at the certificate's weak spots: a thin conflict (a small obstacle far
//! away, its conflict band narrower than a sampling step) and a tangency (a square whose
//! side lies exactly D from the course due north).

use core::f64::consts::TAU;

use polyguard::bands::{Height, Slab};
use polyguard::{Separation, Vect2};

use super::bands::{BandCase, Param, Polygon};
use super::recovery::{Query, Side as RecoverySide};
use crate::gen::Source;
use polyguard_oracle::offset::Side as OffsetSide;

/// The most vertices of a recovery case's star (the exact minimum's candidates are
/// O(n²), each checked against n edges in towers of square roots).
pub const RECOVERY_MOST: usize = 10;

/// One case of the hunt.
#[derive(Clone, Debug)]
pub enum WayoutCase {
    /// Bands of one parameter, with the unknown total asked for.
    Bands {
        /// The situation.
        case: BandCase,
        /// The parameter varied, and the others fixed.
        param: Param,
        /// The range of the parameter (courses: [0, 2π)).
        range: (f64, f64),
        /// The unknown total asked for.
        unknown_max: f64,
    },
    /// A recovery point.
    Recovery(Query),
    /// An offset or inset.
    Offset(OffsetCase),
}

/// An offset or inset case.
#[derive(Clone, Debug)]
pub struct OffsetCase {
    /// The vertices at t = 0.
    pub p: Vec<Vect2>,
    /// Their velocities (empty: static).
    pub vels: Vec<Vect2>,
    /// The time.
    pub t: f64,
    /// D.
    pub d: f64,
    /// ε.
    pub eps: f64,
    /// Offset or inset.
    pub side: OffsetSide,
}

/// A drawn case and the name of the generator mode that drew it.
#[derive(Clone, Debug)]
pub struct Drawn {
    /// The case.
    pub case: WayoutCase,
    /// The mode (kind, shape and motion), for the report.
    pub mode: String,
}

/// 10^x for x uniform in [lo, hi).
fn decade<S: Source>(src: &mut S, lo: f64, hi: f64) -> f64 {
    10f64.powf(src.range(lo, hi))
}

/// A star about `c`: n vertices at increasing angles, radii in [0.35, 1]·size.
fn star<S: Source>(src: &mut S, n: usize, size: f64, c: Vect2) -> Vec<Vect2> {
    let phase = src.range(0.0, TAU);
    (0..n)
        .map(|i| {
            let a = phase + TAU * (i as f64 + src.range(0.1, 0.9)) / n as f64;
            let r = size * src.range(0.35, 1.0);
            c + Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

/// A star with one spike: vertex 0 pushed out to 3–30 sizes between two close
/// neighbours, so its corner is sharp (a few degrees).
fn spike<S: Source>(src: &mut S, n: usize, size: f64, c: Vect2) -> Vec<Vect2> {
    let mut p = star(src, n.max(4), size, c);
    let a = src.range(0.0, TAU);
    let far = size * src.range(3.0, 30.0);
    let k = p.len();
    p[0] = c + Vect2::new(far * a.cos(), far * a.sin());
    // the neighbours close to the spike's direction, on either side
    let w = src.range(0.02, 0.2);
    p[1] = c + Vect2::new(0.5 * size * (a + w).cos(), 0.5 * size * (a + w).sin());
    p[k - 1] = c + Vect2::new(0.5 * size * (a - w).cos(), 0.5 * size * (a - w).sin());
    // the others stay on the star, away from the spike: re-spread them over the rest
    let rest = k - 3;
    for j in 0..rest {
        let b = a + w + (TAU - 2.0 * w) * (j as f64 + 1.0) / (rest as f64 + 1.0);
        let r = size * src.range(0.35, 1.0);
        p[2 + j] = c + Vect2::new(r * b.cos(), r * b.sin());
    }
    p
}

/// A C (a square ring of side `size` cut open on the right by a mouth of `mouth`
/// sizes), counterclockwise.
fn c_shape(size: f64, mouth: f64, c: Vect2) -> Vec<Vect2> {
    let h = 0.5 * mouth;
    [
        (0.0, 0.0),
        (1.0, 0.0),
        (1.0, 0.5 - h),
        (0.8, 0.5 - h),
        (0.8, 0.2),
        (0.2, 0.2),
        (0.2, 0.8),
        (0.8, 0.8),
        (0.8, 0.5 + h),
        (1.0, 0.5 + h),
        (1.0, 1.0),
        (0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y)| c + Vect2::new((x - 0.5) * size, (y - 0.5) * size))
    .collect()
}

/// A thin rectangle of length `size` and width `size·thin`, turned by `a`.
fn thin_rect(size: f64, thin: f64, a: f64, c: Vect2) -> Vec<Vect2> {
    let (u, v) = (Vect2::new(a.cos(), a.sin()), Vect2::new(-a.sin(), a.cos()));
    [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
        .iter()
        .map(|&(x, y)| c + u.scale(x * size) + v.scale(y * size * thin))
        .collect()
}

/// A shape by name, redrawn as a star until the rounded ring is simple and
/// counterclockwise (exactly).
fn shape<S: Source>(src: &mut S, name: &str, size: f64, c: Vect2, most: usize) -> Vec<Vect2> {
    let n = 3 + src.below(most - 2);
    let mut p = match name {
        "spike" => spike(src, n, size, c),
        "c" => c_shape(size, src.range(0.05, 0.4), c),
        "thin" => thin_rect(size, decade(src, -3.0, -1.0), src.range(0.0, TAU), c),
        _ => star(src, n, size, c),
    };
    for _ in 0..16 {
        if polyguard::ring::simple_ccw(&p) {
            return p;
        }
        let n = 3 + src.below(most - 2);
        p = star(src, n, size, c);
    }
    // a triangle about c: simple at every scale the hunt draws
    let s = size;
    vec![c, c + Vect2::new(s, 0.0), c + Vect2::new(0.0, s)]
}

/// The motion of a polygon: `static` (no velocities), `translating` (one velocity u) or
/// `warping` (u + k·(p_i − c), with |k|·T ≤ 1/2).
fn motion<S: Source>(
    src: &mut S,
    p: &[Vect2],
    c: Vect2,
    speed: f64,
    horizon: f64,
) -> (&'static str, Vec<Vect2>) {
    let a = src.range(0.0, TAU);
    let u = Vect2::new(speed * a.cos(), speed * a.sin());
    match src.below(3) {
        0 => ("static", vec![Vect2::ZERO; p.len()]),
        1 => ("translating", vec![u; p.len()]),
        _ => {
            let k = src.range(-0.5, 0.5) / horizon;
            ("warping", p.iter().map(|&q| u + (q - c).scale(k)).collect())
        }
    }
}

/// Draws one case: bands (2 in 5), recovery (3 in 10) or offset (3 in 10).
pub fn wayout_case<S: Source>(src: &mut S) -> Drawn {
    match src.below(10) {
        0..=3 => band_case(src),
        4..=6 => recovery_case(src),
        _ => offset_case(src),
    }
}

/// A band case: the point at the origin at `speed`, over [0, T]; 1–10 polygons of 3–16
/// vertices around it, some aimed at thin conflicts and tangencies.
pub fn band_case<S: Source>(src: &mut S) -> Drawn {
    let t = decade(src, 0.0, 2.0);
    let speed = decade(src, 0.0, 2.0);
    let reach = speed * t;
    let aim = src.below(4);
    // a thin conflict needs a small D too, or its band is wide
    let d = if aim == 0 {
        reach * decade(src, -3.5, -2.5)
    } else {
        reach * decade(src, -2.5, -0.7)
    };
    let three_d = src.coin();
    let h = if three_d { decade(src, 0.0, 2.0) } else { 0.0 };
    let sz = src.range(-100.0, 100.0);
    let vz = src.range(-10.0, 10.0);
    let count = 1 + src.below(10);
    let mut polygons = Vec::with_capacity(count);
    for j in 0..count {
        let bearing = src.range(0.0, TAU);
        let at = |r: f64| Vect2::new(r * bearing.sin(), r * bearing.cos());
        let (p, c) = if j == 0 && aim == 0 {
            // a thin conflict: a small obstacle far out, its band a fraction of a degree
            let c = at(reach * src.range(0.6, 0.95));
            let size = (reach * decade(src, -3.5, -2.0)).max(d * 0.01);
            (shape(src, "star", size, c, 16), c)
        } else if j == 0 && aim == 1 {
            // a tangency: a square whose left side lies exactly D east of the course 0
            let a = reach * src.range(0.05, 0.3);
            let y0 = reach * src.range(0.1, 0.6);
            let p = vec![
                Vect2::new(d, y0),
                Vect2::new(d + a, y0),
                Vect2::new(d + a, y0 + a),
                Vect2::new(d, y0 + a),
            ];
            (p, Vect2::new(d + 0.5 * a, y0 + 0.5 * a))
        } else {
            let c = at(reach * src.range(0.1, 1.3));
            let size = reach * decade(src, -2.0, -0.5);
            let name = if src.below(4) == 0 { "spike" } else { "star" };
            (shape(src, name, size, c, 16), c)
        };
        let vels = if j == 0 && aim == 1 {
            vec![Vect2::ZERO; p.len()]
        } else {
            let drift = speed * src.range(0.0, 0.8);
            motion(src, &p, c, drift, t).1
        };
        let slab = (three_d && src.below(4) != 0).then(|| {
            let bottom = sz + src.range(-300.0, 100.0);
            Slab {
                bottom,
                top: bottom + decade(src, 0.0, 2.5),
                vsp: src.range(-10.0, 10.0),
            }
        });
        polygons.push(Polygon { p, vels, slab });
    }
    let case = BandCase {
        t,
        s: Vect2::ZERO,
        height: three_d.then_some(Height { sz, vz }),
        polygons,
        sep: Separation { d, h },
    };
    let (param, range, unknown_max, pname) = band_param(src, speed, three_d);
    let aimed = ["thin", "tangent", "plain", "plain"][aim];
    Drawn {
        mode: format!(
            "bands/{pname}/{}/{aimed}",
            if three_d { "3d" } else { "2d" }
        ),
        case: WayoutCase::Bands {
            case,
            param,
            range,
            unknown_max,
        },
    }
}

/// The parameter a band case varies (courses 7 in 10, speeds 2 in 10, vertical speeds
/// 1 in 10 in 3D), its range, the unknown total asked for, and its name.
fn band_param<S: Source>(
    src: &mut S,
    speed: f64,
    three_d: bool,
) -> (Param, (f64, f64), f64, &'static str) {
    match src.below(10) {
        0..=6 => (
            Param::Course { speed },
            (0.0, TAU),
            0.1f64.to_radians(),
            "course",
        ),
        7 | 8 => (
            Param::Speed {
                course: src.range(0.0, TAU),
            },
            (0.0, 2.0 * speed),
            speed / 500.0,
            "speed",
        ),
        _ if three_d => (
            Param::Vertical {
                v: polyguard::bands::velocity(speed, src.range(0.0, TAU)),
            },
            (-20.0, 20.0),
            0.1,
            "vertical",
        ),
        _ => (
            Param::Course { speed },
            (0.0, TAU),
            0.1f64.to_radians(),
            "course",
        ),
    }
}

/// A recovery case: one polygon (star, spike, C or thin), static or at a time t; s
/// inside, outside, or near a corner; keep-out or keep-in (impossible when a thin
/// polygon's half width is below D).
pub fn recovery_case<S: Source>(src: &mut S) -> Drawn {
    let size = decade(src, -2.0, 3.0);
    let c = Vect2::new(size * src.range(-3.0, 3.0), size * src.range(-3.0, 3.0));
    let name = ["star", "star", "spike", "c", "thin"][src.below(5)];
    let p = shape(src, name, size, c, RECOVERY_MOST);
    let side = if src.coin() {
        RecoverySide::Out
    } else {
        RecoverySide::In
    };
    let d = size * decade(src, -3.0, -0.3);
    let drift = size * src.range(0.0, 1.0);
    let (kind, vels) = motion(src, &p, c, drift, 1.0);
    let (kind, vels, t) = if kind == "static" {
        (kind, Vec::new(), 0.0)
    } else {
        (kind, vels, src.range(0.0, 1.0))
    };
    let n = p.len();
    let (place, s) = match src.below(4) {
        0 => (
            "inside",
            c + (p[src.below(n)] - c).scale(src.range(0.0, 0.3)),
        ),
        1 => {
            let a = src.range(0.0, TAU);
            let r = size * src.range(0.5, 3.0);
            ("outside", c + Vect2::new(r * a.cos(), r * a.sin()))
        }
        2 => {
            let a = src.range(0.0, TAU);
            let r = d * decade(src, -12.0, 0.3);
            let v = p[src.below(n)];
            ("corner", v + Vect2::new(r * a.cos(), r * a.sin()))
        }
        _ => {
            let i = src.below(n);
            let (a, b) = (p[i], p[(i + 1) % n]);
            ("edge", a + (b - a).scale(src.range(0.0, 1.0)))
        }
    };
    // s is placed about the polygon at t = 0; at time t the polygon has moved, which
    // only changes which of the places s is in
    let side_name = match side {
        RecoverySide::Out => "out",
        RecoverySide::In => "in",
    };
    Drawn {
        mode: format!(
            "recovery/{side_name}/{place}/{}",
            if kind == "static" { "static" } else { "at_t" }
        ),
        case: WayoutCase::Recovery(Query {
            p,
            vels,
            t,
            s,
            d,
            side,
        }),
    }
}

/// An offset or inset case: a star, a spike or a C, static or at a time t, with a small
/// D (10⁻³…10⁻¹ of its size) or a large one (0.2…2 sizes; a C's mouth closes).
pub fn offset_case<S: Source>(src: &mut S) -> Drawn {
    let size = decade(src, -2.0, 3.0);
    let c = Vect2::new(size * src.range(-3.0, 3.0), size * src.range(-3.0, 3.0));
    let name = ["star", "spike", "spike", "c"][src.below(4)];
    let p = shape(src, name, size, c, 16);
    let large = src.coin();
    let d = if large {
        size * src.range(0.2, 2.0)
    } else {
        size * decade(src, -3.0, -1.0)
    };
    let eps = [0.01, 0.05, 0.2][src.below(3)];
    let side = if src.below(5) < 3 {
        OffsetSide::Out
    } else {
        OffsetSide::In
    };
    let drift = size * src.range(0.0, 1.0);
    let (kind, vels) = motion(src, &p, c, drift, 1.0);
    let (kind, vels, t) = if kind == "static" {
        (kind, Vec::new(), 0.0)
    } else {
        (kind, vels, src.range(0.0, 1.0))
    };
    Drawn {
        mode: format!(
            "{}/{name}/{}/{}",
            if side == OffsetSide::Out {
                "offset"
            } else {
                "inset"
            },
            if large { "large_d" } else { "small_d" },
            if kind == "static" { "static" } else { "at_t" }
        ),
        case: WayoutCase::Offset(OffsetCase {
            p,
            vels,
            t,
            d,
            eps,
            side,
        }),
    }
}

/// Points as JSON pairs (f64 written to round-trip exactly).
fn pts(p: &[Vect2]) -> serde_json::Value {
    p.iter().map(|v| serde_json::json!([v.x, v.y])).collect()
}

impl WayoutCase {
    /// The case as one JSON object (the regression line of a kept case; every number an
    /// f64 that reads back exactly).
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::json;
        match self {
            WayoutCase::Bands {
                case,
                param,
                range,
                unknown_max,
            } => {
                let polygons: Vec<serde_json::Value> = case
                    .polygons
                    .iter()
                    .map(|o| {
                        json!({
                            "vertices": pts(&o.p),
                            "velocities": pts(&o.vels),
                            "slab": o.slab.map(|z| json!({"bottom": z.bottom, "top": z.top, "vsp": z.vsp})),
                        })
                    })
                    .collect();
                let param = match param {
                    Param::Course { speed } => json!({"course_bands": {"speed": speed}}),
                    Param::Speed { course } => json!({"speed_bands": {"course": course}}),
                    Param::Vertical { v } => json!({"vertical_speed_bands": {"v": [v.x, v.y]}}),
                };
                json!({
                    "kind": "bands",
                    "lookahead": case.t,
                    "s": [case.s.x, case.s.y],
                    "height": case.height.map(|z| json!({"sz": z.sz, "vz": z.vz})),
                    "sep": case.sep.d,
                    "sep_v": case.sep.h,
                    "polygons": polygons,
                    "param": param,
                    "range": [range.0, range.1],
                    "unknown_max": unknown_max,
                })
            }
            WayoutCase::Recovery(q) => json!({
                "kind": "recovery",
                "fence": if q.side == RecoverySide::Out { "keep_out" } else { "keep_in" },
                "vertices": pts(&q.p),
                "velocities": pts(&q.vels),
                "time": q.t,
                "s": [q.s.x, q.s.y],
                "sep": q.d,
            }),
            WayoutCase::Offset(o) => json!({
                "kind": if o.side == OffsetSide::Out { "offset" } else { "inset" },
                "vertices": pts(&o.p),
                "velocities": pts(&o.vels),
                "time": o.t,
                "sep": o.d,
                "eps": o.eps,
            }),
        }
    }
}
