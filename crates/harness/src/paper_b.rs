//! Hunting for paper B (`polyguard assure --paper b`): two-feature scenarios drawn at the
//! thresholds of the four-stage pipeline, answered by the pipeline as a user runs it
//! (GeoJSON text → parse → stages 1–4) and judged against the ground truth of
//! [`polyguard_earth::reference::truth`], which sees neither the stages nor their copies
//! across the antimeridian.
//!
//! Generator modes (each at a place: mid-latitudes, 80°–84.5° N or S, on the antimeridian, or
//! both):
//! - `touch_vertex`, `touch_edge`, `near_vertex`: two areas sharing a vertex exactly,
//!   sharing an edge exactly, or a vertex moved a signed gap of 10⁻¹³…10⁻² rad;
//! - `graze`: a track passing an area's apex at a signed lateral gap;
//! - `parallel`: two tracks on the same bearing, side by side at a signed gap;
//! - `east_west`: legs due east or west (eq 20's linear path), head-on or overtaking;
//! - `crossing`: two tracks crossing with a time offset;
//! - `ends`: an area touching a track's rectangle at its departure or arrival (windows
//!   that open at `t0` or close at a track's end), or an area whose own life ends
//!   mid-encounter.
//!
//! Classes (paper B's contract, docs/scenario.md: the reported window contains every
//! instant of meeting; at its ends the two are within `ε = (V_a + V_b)·tol`):
//! - `missed_conflict`: the truth finds a meeting, the pipeline reports none. A failure.
//! - `window_short`: a meeting instant lies outside the reported window. A failure.
//! - `end_far`: the pipeline reports a window, and at one of its ends the two are more
//!   than `2ε` plus the truth's slack apart (for two areas: apart by more than the
//!   slack). A failure (a false conflict or a window far too long).
//! - `bound_broken`: a body moved faster than its speed bound between two of the
//!   truth's evaluations. A failure (stage 4 relies on the same bound).
//! - `near_alarm`: a window reported for a pair that never meets, within the contract's
//!   band. By design.
//! - `undecided`: tangent within the truth's slack; not judged.
//! - `model_rounding` (with `--features rug`): at an instant the verdict rests on (the
//!   truth's first and last meetings, the window's ends), a leg's f64 rectangle
//!   (`merc_vertices_at`, which both the pipeline and the truth evaluate) lies farther
//!   than `2⁻⁴⁴·max(c, 4)` from its MPFR value (`reference::mpfr::leg_vertex_error`), the
//!   bound `position_slack` is built on. A failure: the truth's model is not the
//!   paper's geometry within the stated rounding.
//! - `agree`.

use std::collections::BTreeMap;

use polyguard_earth::conflict::{pipeline, DEFAULT_TIME_TOLERANCE_H};
use polyguard_earth::reference::truth::{self, Outcome};
use polyguard_earth::scenario::{self, Area, Feature, Kind, Scenario, Shape, Track};
use polyguard_earth::sphere::{self, Leg, LonLat, Merc, RectDims};
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::gen::Source;

/// The truth's time resolution: a sixty-fourth of the pipeline's tolerance.
pub const RESOLUTION_H: f64 = DEFAULT_TIME_TOLERANCE_H / 64.0;

/// A paper-B class.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ClassB {
    /// Truth and pipeline agree.
    Agree,
    /// A window for a pair that never meets, within the contract's band.
    NearAlarm,
    /// Tangent within the truth's slack: not judged.
    Undecided,
    /// A meeting the pipeline does not report.
    MissedConflict,
    /// A meeting instant outside the reported window.
    WindowShort,
    /// A window end far from contact.
    EndFar,
    /// A speed bound broken.
    BoundBroken,
    /// A leg's f64 rectangle farther from its MPFR value than the stated rounding bound.
    ModelRounding,
}

impl ClassB {
    /// Every class, in report order.
    pub const ALL: [ClassB; 8] = [
        ClassB::Agree,
        ClassB::NearAlarm,
        ClassB::Undecided,
        ClassB::MissedConflict,
        ClassB::WindowShort,
        ClassB::EndFar,
        ClassB::BoundBroken,
        ClassB::ModelRounding,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            ClassB::Agree => "agree",
            ClassB::NearAlarm => "near_alarm",
            ClassB::Undecided => "undecided",
            ClassB::MissedConflict => "missed_conflict",
            ClassB::WindowShort => "window_short",
            ClassB::EndFar => "end_far",
            ClassB::BoundBroken => "bound_broken",
            ClassB::ModelRounding => "model_rounding",
        }
    }

    /// Is it a failure of the pipeline (or of the bound it shares with the truth)?
    pub fn is_failure(self) -> bool {
        matches!(
            self,
            ClassB::MissedConflict
                | ClassB::WindowShort
                | ClassB::EndFar
                | ClassB::BoundBroken
                | ClassB::ModelRounding
        )
    }
}

/// One drawn case: a two-feature scenario and its generator mode.
#[derive(Clone, Debug)]
pub struct CaseB {
    /// The scenario (features `a` and `b`).
    pub scenario: Scenario,
    /// `mode@place`.
    pub mode: String,
}

/// The verdict on one case.
#[derive(Clone, Debug, PartialEq)]
pub struct VerdictB {
    /// The class.
    pub class: ClassB,
    /// The pipeline's window for the pair (`None`: no conflict).
    pub engine: Option<(f64, f64)>,
    /// The truth.
    pub truth: Outcome,
    /// The largest f64-against-MPFR distance of a leg's rectangle at the verdict's
    /// instants, in units of its bound `2⁻⁴⁴·max(c, 4)`; `None` when not checked (built
    /// without `rug`, or no leg).
    pub model_error: Option<f64>,
}

// ---------------------------------------------------------------- generators

fn log_uniform(src: &mut impl Source, lo: f64, hi: f64) -> f64 {
    (src.range(lo.ln(), hi.ln())).exp()
}

/// A signed gap, magnitude log-uniform in `[lo, hi]`.
fn signed_gap(src: &mut impl Source, lo: f64, hi: f64) -> f64 {
    let g = log_uniform(src, lo, hi);
    if src.coin() {
        g
    } else {
        -g
    }
}

/// Where the encounter happens.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Place {
    Mid,
    Polar,
    Antimeridian,
    PolarAntimeridian,
}

impl Place {
    fn name(self) -> &'static str {
        match self {
            Place::Mid => "mid",
            Place::Polar => "polar",
            Place::Antimeridian => "antimeridian",
            Place::PolarAntimeridian => "polar+antimeridian",
        }
    }

    fn draw(self, src: &mut impl Source) -> LonLat {
        let polar = matches!(self, Place::Polar | Place::PolarAntimeridian);
        let am = matches!(self, Place::Antimeridian | Place::PolarAntimeridian);
        let lat = if polar {
            let l = src.range(80.0, 84.5);
            if src.coin() {
                l
            } else {
                -l
            }
        } else {
            src.range(-60.0, 60.0)
        };
        let lon = if am {
            180.0 + signed_gap(src, 1e-6, 0.3)
        } else {
            src.range(-170.0, 170.0)
        };
        LonLat::from_degrees(lon, lat)
    }
}

fn dims(src: &mut impl Source) -> RectDims {
    RectDims {
        front: log_uniform(src, 0.5, 30.0),
        back: log_uniform(src, 0.5, 30.0),
        side: log_uniform(src, 0.5, 20.0),
    }
}

/// A bearing: one of the four cardinal ones in a quarter of the draws (rhumb lines that
/// are meridians or parallels), else uniform.
fn bearing(src: &mut impl Source) -> f64 {
    if src.below(4) == 0 {
        src.below(4) as f64 * FRAC_PI_2
    } else {
        src.range(0.0, TAU)
    }
}

fn area(ring: Vec<LonLat>, t0: Option<f64>, tf: Option<f64>) -> Kind {
    Kind::Area(Area {
        shapes: vec![Shape::plain(ring)],
        multi: false,
        t0,
        tf,
    })
}

fn feature(id: &str, kind: Kind) -> Feature {
    Feature {
        id: id.into(),
        kind,
        extra: Default::default(),
    }
}

/// A counterclockwise ring of Mercator points, as longitudes and latitudes.
fn ring_from_merc(mut pts: Vec<Merc>) -> Vec<LonLat> {
    let a: f64 = (0..pts.len())
        .map(|i| {
            let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
            p[0] * q[1] - p[1] * q[0]
        })
        .sum();
    if a < 0.0 {
        pts.reverse();
    }
    pts.into_iter().map(sphere::inverse_mercator).collect()
}

fn unit(v: Merc) -> Merc {
    let n = v[0].hypot(v[1]);
    [v[0] / n, v[1] / n]
}

fn rot(v: Merc, a: f64) -> Merc {
    let (s, c) = a.sin_cos();
    [v[0] * c - v[1] * s, v[0] * s + v[1] * c]
}

fn add(p: Merc, v: Merc, k: f64) -> Merc {
    [p[0] + k * v[0], p[1] + k * v[1]]
}

/// A convex polygon of 3–7 vertices around `c` (Mercator), radius `r`.
fn convex_around(src: &mut impl Source, c: Merc, r: f64) -> Vec<Merc> {
    let n = 3 + src.below(5);
    // one vertex in each of n equal sectors, at least a fifth of a sector apart
    let turn = src.range(0.0, TAU);
    let angles: Vec<f64> = (0..n)
        .map(|i| turn + (i as f64 + 0.8 * src.unit()) * TAU / n as f64)
        .collect();
    angles
        .iter()
        .map(|&a| add(c, [a.cos(), a.sin()], r))
        .collect()
}

/// A track from `before` nm behind `e` to `after` nm ahead on bearing `th`.
fn track_through(e: LonLat, th: f64, before: f64, after: f64) -> (LonLat, LonLat) {
    (
        sphere::rhumb_destination(e, th + PI, before),
        sphere::rhumb_destination(e, th, after),
    )
}

fn track(w: Vec<LonLat>, speed_kn: f64, t0: f64, d: RectDims) -> Kind {
    Kind::Track(Track {
        waypoints: w,
        speed_kn,
        dims: d,
        t0,
    })
}

const MODES: [&str; 8] = [
    "touch_vertex",
    "touch_edge",
    "near_vertex",
    "graze",
    "parallel",
    "east_west",
    "crossing",
    "ends",
];

const PLACES: [Place; 4] = [
    Place::Mid,
    Place::Polar,
    Place::Antimeridian,
    Place::PolarAntimeridian,
];

/// A case drawn from `src`.
pub fn draw(src: &mut impl Source) -> CaseB {
    // near the poles a drawn area or track may reach past the format's ±85° (about 6 in
    // 10⁵ cases): such a draw is replaced by the next one (the reader would refuse it)
    let mut case = draw_once(src);
    for _ in 0..8 {
        if within_format(&case.scenario) {
            break;
        }
        case = draw_once(src);
    }
    case
}

/// Every position within the scenario format's ±85° of latitude.
fn within_format(sc: &Scenario) -> bool {
    let limit = 85f64.to_radians();
    let ok = |ps: &[LonLat]| ps.iter().all(|p| p.lat.abs() <= limit);
    sc.features.iter().all(|f| match &f.kind {
        Kind::Area(a) => a
            .shapes
            .iter()
            .all(|s| ok(&s.ring) && s.holes.iter().all(|h| ok(h))),
        Kind::Track(t) => ok(&t.waypoints),
    })
}

/// One draw of [`draw`]: a mode, a place, and the pair of features of that mode there.
fn draw_once(src: &mut impl Source) -> CaseB {
    let mode = src.pick(&MODES);
    let place = src.pick(&PLACES);
    let e = place.draw(src);
    // near the poles tracks stay short, within the format's ±85°
    let far = if matches!(place, Place::Polar | Place::PolarAntimeridian) {
        20.0
    } else {
        300.0
    };
    let (ka, kb) = match mode {
        "touch_vertex" | "touch_edge" | "near_vertex" => touching(src, mode, e),
        "graze" | "ends" => grazing(src, mode, e, far),
        "parallel" => parallel(src, e, far),
        "east_west" => east_west(src, e),
        _ => crossing(src, e, far),
    };
    CaseB {
        scenario: Scenario {
            features: vec![feature("a", ka), feature("b", kb)],
            longitudes: scenario::Longitudes::Earth,
            geodesy: Default::default(),
        },
        mode: format!("{mode}@{}", place.name()),
    }
}

/// Modes `touch_vertex`, `touch_edge`, `near_vertex`: two areas near `e`, the second
/// touching the first at a vertex, along an edge, or a signed gap from a vertex.
fn touching(src: &mut impl Source, mode: &str, e: LonLat) -> (Kind, Kind) {
    let em = sphere::mercator(e);
    let r = log_uniform(src, 1e-5, 0.05);
    let a = convex_around(src, em, r);
    let n = a.len();
    let i = src.below(n);
    let ring_a = ring_from_merc(a.clone());
    // ring_from_merc keeps the order (the angles are sorted: counterclockwise)
    let (prev, v, next) = (a[(i + n - 1) % n], a[i], a[(i + 1) % n]);
    let w = unit(add(
        unit([v[0] - prev[0], v[1] - prev[1]]),
        unit([v[0] - next[0], v[1] - next[1]]),
        1.0,
    ));
    let rb = r * log_uniform(src, 0.1, 3.0);
    let b = match mode {
        "touch_edge" => {
            // the edge v → next, shared exactly, with an apex outside it
            let mid = add(v, [next[0] - v[0], next[1] - v[1]], 0.5);
            let out = unit([next[1] - v[1], v[0] - next[0]]);
            let apex = sphere::inverse_mercator(add(mid, out, rb));
            vec![ring_a[(i + 1) % n], ring_a[i], apex]
        }
        _ => {
            let alpha = src.range(0.05, 0.5);
            let (u1, u2) = (rot(w, alpha), rot(w, -alpha));
            let (p1, p2) = (add(v, u2, rb), add(v, u1, rb));
            let shared = if mode == "near_vertex" {
                sphere::inverse_mercator(add(v, w, signed_gap(src, 1e-13, 1e-2) * r))
            } else {
                ring_a[i]
            };
            vec![
                shared,
                sphere::inverse_mercator(p1),
                sphere::inverse_mercator(p2),
            ]
        }
    };
    let mut life = || {
        if src.below(3) == 0 {
            let t0 = src.range(-5.0, 5.0);
            (Some(t0), Some(t0 + src.range(0.0, 10.0)))
        } else {
            (None, None)
        }
    };
    let (t0a, tfa) = life();
    let (t0b, tfb) = life();
    (area(ring_a, t0a, tfa), area(b, t0b, tfb))
}

/// Modes `graze` and `ends`: a track through `e` and an area whose apex comes a signed
/// gap from the track's rectangle, beside it (`graze`) or at its start or end (`ends`,
/// where the area's own life may also end or start mid-encounter).
fn grazing(src: &mut impl Source, mode: &str, e: LonLat, far: f64) -> (Kind, Kind) {
    let th = bearing(src);
    let (before, after) = (log_uniform(src, 1.0, far), log_uniform(src, 1.0, far));
    let (s0, s1) = track_through(e, th, before, after);
    let (d, speed, t0) = (
        dims(src),
        log_uniform(src, 2.0, 600.0),
        src.range(-10.0, 10.0),
    );
    let leg = Leg::new(s0, s1, speed, t0, d);
    let dir = unit([
        leg.merc[1][0] - leg.merc[0][0],
        leg.merc[1][1] - leg.merc[0][1],
    ]);
    // where and in which direction the area's apex approaches the rectangle
    let (t_star, push) = if mode == "graze" {
        let side = if src.coin() { 1.0 } else { -1.0 };
        (src.range(leg.t0, leg.t1), [-dir[1] * side, dir[0] * side])
    } else if src.coin() {
        (leg.t0, [-dir[0], -dir[1]])
    } else {
        (leg.t1, dir)
    };
    let verts = leg.merc_vertices_at(t_star);
    let k = (0..4)
        .max_by(|&i, &j| {
            let f = |p: Merc| p[0] * push[0] + p[1] * push[1];
            f(verts[i]).total_cmp(&f(verts[j]))
        })
        .unwrap_or(0);
    let scale = (leg.dims.side / sphere::EARTH_RADIUS_NM) / e.lat.cos();
    let apex = add(
        verts[k],
        push,
        signed_gap(src, 1e-8, 1e-2) * scale.max(1e-9),
    );
    let rb = scale * log_uniform(src, 0.1, if far < 300.0 { 1.0 } else { 10.0 });
    let alpha = src.range(0.1, 1.2);
    let ring = vec![
        apex,
        add(apex, rot(push, alpha), rb),
        add(apex, rot(push, -alpha), rb),
    ];
    let (ta0, taf) = if mode == "ends" && src.below(3) == 0 {
        // the area's own life ends (or starts) mid-encounter
        let t = src.range(leg.t0, leg.t1);
        if src.coin() {
            (None, Some(t))
        } else {
            (Some(t), None)
        }
    } else {
        (None, None)
    };
    (
        track(vec![s0, s1], speed, t0, d),
        area(ring_from_merc(ring), ta0, taf),
    )
}

/// Mode `parallel`: two tracks on parallel rhumb lines, their rectangles a signed gap
/// apart side by side.
fn parallel(src: &mut impl Source, e: LonLat, far: f64) -> (Kind, Kind) {
    let th = bearing(src);
    let (da, db) = (dims(src), dims(src));
    let (s0, s1) = track_through(
        e,
        th,
        log_uniform(src, 1.0, far),
        log_uniform(src, 1.0, far),
    );
    let side = if src.coin() { FRAC_PI_2 } else { -FRAC_PI_2 };
    let lateral = da.side + db.side + signed_gap(src, 1e-9, 1.0);
    let along = src.range(-far, far) / 3.0;
    let b0 =
        sphere::rhumb_destination(sphere::rhumb_destination(s0, th + side, lateral), th, along);
    let b1 = sphere::rhumb_destination(b0, th, log_uniform(src, 1.0, far));
    let (va, vb) = (log_uniform(src, 2.0, 600.0), log_uniform(src, 2.0, 600.0));
    let (t0a, t0b) = (src.range(-5.0, 5.0), src.range(-5.0, 5.0));
    (
        track(vec![s0, s1], va, t0a, da),
        track(vec![b0, b1], vb, t0b, db),
    )
}

/// Mode `east_west`: two tracks along parallels of latitude (rhumb lines due east or
/// west), a signed gap apart in latitude, the same way or head-on.
fn east_west(src: &mut impl Source, e: LonLat) -> (Kind, Kind) {
    let (da, db) = (dims(src), dims(src));
    let la = log_uniform(src, 0.02, 3.0).to_radians();
    let lb = log_uniform(src, 0.02, 3.0).to_radians();
    let a0 = LonLat {
        lon: e.lon - 0.5 * la,
        lat: e.lat,
    };
    let a1 = LonLat {
        lon: e.lon + 0.5 * la,
        lat: e.lat,
    };
    let dlat = (da.side + db.side) / sphere::EARTH_RADIUS_NM + signed_gap(src, 1e-12, 1e-3);
    let latb = e.lat + if src.coin() { dlat } else { -dlat };
    let (b0, b1) = if src.coin() {
        // head-on
        (
            LonLat {
                lon: e.lon + 0.5 * lb,
                lat: latb,
            },
            LonLat {
                lon: e.lon - 0.5 * lb,
                lat: latb,
            },
        )
    } else {
        (
            LonLat {
                lon: e.lon - 0.5 * lb,
                lat: latb,
            },
            LonLat {
                lon: e.lon + 0.5 * lb,
                lat: latb,
            },
        )
    };
    let (va, vb) = (log_uniform(src, 2.0, 600.0), log_uniform(src, 2.0, 600.0));
    let (t0a, t0b) = (src.range(-2.0, 2.0), src.range(-2.0, 2.0));
    (
        track(vec![a0, a1], va, t0a, da),
        track(vec![b0, b1], vb, t0b, db),
    )
}

/// Mode `crossing`: two tracks crossing at `e`, the second passing it about the time to
/// clear the rectangles before or after the first.
fn crossing(src: &mut impl Source, e: LonLat, far: f64) -> (Kind, Kind) {
    // a passes e at ta, b at ta + Δ
    let (tha, thb) = (bearing(src), bearing(src));
    let (da, db) = (dims(src), dims(src));
    let (va, vb) = (log_uniform(src, 2.0, 600.0), log_uniform(src, 2.0, 600.0));
    let (ba, aa) = (log_uniform(src, 1.0, far), log_uniform(src, 1.0, far));
    let (bb, ab) = (log_uniform(src, 1.0, far), log_uniform(src, 1.0, far));
    let (a0, a1) = track_through(e, tha, ba, aa);
    let (b0, b1) = track_through(e, thb, bb, ab);
    let t0a = src.range(-2.0, 2.0);
    let ta = t0a + ba / va;
    // a time offset of about the time to clear the rectangles, moved a little
    let clear = (da.front + da.back + db.front + db.back) / va.min(vb);
    let dt = clear * log_uniform(src, 0.05, 2.0) * if src.coin() { 1.0 } else { -1.0 };
    let t0b = ta + dt - bb / vb;
    (
        track(vec![a0, a1], va, t0a, da),
        track(vec![b0, b1], vb, t0b, db),
    )
}

// ---------------------------------------------------------------- judging

/// The pipeline as a user runs it, on the scenario's GeoJSON text: the window of the pair
/// (features 0 and 1), or `None`; `Err` when the text is refused.
pub fn engine(text: &str) -> Result<Option<(f64, f64)>, String> {
    let read = scenario::parse(text).map_err(|e| e.to_string())?;
    if let Some(e) = read.errors.first() {
        return Err(e.to_string());
    }
    if read.scenario.features.len() != 2 {
        return Err(format!(
            "{} features read, 2 expected",
            read.scenario.features.len()
        ));
    }
    let objs = scenario::objects(&read.scenario);
    let (conflicts, _) = pipeline::run(&objs, pipeline::Options::default());
    Ok(conflicts
        .iter()
        .find(|c| (c.a.min(c.b), c.a.max(c.b)) == (0, 1))
        .map(|c| (c.t_start, c.t_end)))
}

/// Judges the case: the scenario is written as GeoJSON text, read back (the case is what
/// was read), answered by the pipeline and by the truth.
pub fn judge(case: &CaseB) -> Result<(VerdictB, Scenario, String), String> {
    let text = scenario::to_geojson(&case.scenario).to_string();
    let read = scenario::parse(&text).map_err(|e| e.to_string())?;
    if let Some(e) = read.errors.first() {
        return Err(e.to_string());
    }
    let sc = read.scenario;
    let eng = engine(&text)?;
    let verdict = judge_read(&sc, eng).ok_or("a feature the truth does not model")?;
    Ok((verdict, sc, text))
}

/// Judges the pipeline's answer `eng` for a scenario as read.
pub fn judge_read(sc: &Scenario, eng: Option<(f64, f64)>) -> Option<VerdictB> {
    let (fa, fb) = (&sc.features[0], &sc.features[1]);
    let t = truth::pair(fa, fb, RESOLUTION_H)?;
    let eps = (truth::speed_bound(fa) + truth::speed_bound(fb)) * DEFAULT_TIME_TOLERANCE_H;
    // at a reported end, farther than the contract allows (twice ε, plus the slack)?
    let end_far = |s: f64, e: f64| {
        [s, e]
            .iter()
            .any(|&x| truth::distance_at(fa, fb, x).is_some_and(|(d, sl)| d > 2.0 * eps + 2.0 * sl))
    };
    let class = match (&t, eng) {
        (Outcome::BoundBroken { .. }, _) => ClassB::BoundBroken,
        (Outcome::Undecided, _) => ClassB::Undecided,
        (Outcome::Meets { .. }, None) => ClassB::MissedConflict,
        (Outcome::Meets { first, last, .. }, Some((s, e))) => {
            if *first < s || *last > e {
                ClassB::WindowShort
            } else if end_far(s, e) {
                ClassB::EndFar
            } else {
                ClassB::Agree
            }
        }
        (Outcome::Apart { .. }, None) => ClassB::Agree,
        (Outcome::Apart { min_distance }, Some((s, e))) => {
            let both_static = eps == 0.0;
            let far = if both_static {
                *min_distance > 2.0 * truth::slack(4.0 + TAU)
            } else {
                end_far(s, e)
            };
            if far {
                ClassB::EndFar
            } else {
                ClassB::NearAlarm
            }
        }
    };
    let mut instants = Vec::new();
    if let Outcome::Meets { first, last, .. } = t {
        instants.extend([first, last]);
    }
    if let Some((s, e)) = eng {
        instants.extend([s, e]);
    }
    let model_error = model_error(sc, &instants);
    let class = match model_error {
        Some(r) if r > 1.0 && !class.is_failure() => ClassB::ModelRounding,
        _ => class,
    };
    Some(VerdictB {
        class,
        engine: eng,
        truth: t,
        model_error,
    })
}

/// The largest distance between a leg's f64 rectangle and its MPFR value at `instants`
/// (each clamped into the leg's life; finite ones only), in units of `2⁻⁴⁴·max(c, 4)`.
#[cfg(feature = "rug")]
fn model_error(sc: &Scenario, instants: &[f64]) -> Option<f64> {
    use polyguard_earth::reference::mpfr;
    let mut worst: Option<f64> = None;
    for f in &sc.features {
        let Kind::Track(t) = &f.kind else { continue };
        for leg in sphere::track_legs_in(sc.geodesy, &t.waypoints, t.speed_kn, t.t0, t.dims) {
            for &x in instants.iter().filter(|x| x.is_finite()) {
                let x = x.clamp(leg.t0, leg.t1);
                let c = leg
                    .merc_vertices_at(x)
                    .iter()
                    .fold(4f64, |c, p| c.max(p[0].abs()).max(p[1].abs()));
                if let Some(e) = mpfr::leg_vertex_error(&leg, x) {
                    let r = e / (c * 2f64.powi(-44));
                    worst = Some(worst.map_or(r, |w: f64| w.max(r)));
                }
            }
        }
    }
    worst
}

/// Without `rug` the model is not checked.
#[cfg(not(feature = "rug"))]
fn model_error(_: &Scenario, _: &[f64]) -> Option<f64> {
    None
}

// ---------------------------------------------------------------- report

/// A kept case of a paper-B run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeptB {
    /// The case's index (with the seed, it regenerates the case).
    pub index: u64,
    /// Its class.
    pub class: ClassB,
    /// Its generator mode.
    pub mode: String,
    /// The scenario file (relative to the run's directory), with the answers in each
    /// feature's properties' `assure` member, and its picture.
    pub case_file: String,
    /// See `case_file`.
    pub svg_file: String,
}

/// The report of a paper-B run (`report.json` with `"paper": "b"`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReportB {
    /// Always "b".
    pub paper: String,
    /// The run's seed.
    pub seed: u64,
    /// Shards included, as "i/N".
    pub shards: Vec<String>,
    /// The campaign's size (`--cases`).
    pub campaign_cases: u64,
    /// The pipeline judged: "pipeline" (as shipped) or "sampled" (the canary).
    pub engine: String,
    /// Shards absent from a merge made with `--partial`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub missing_shards: Vec<String>,
    /// Cases judged.
    pub cases: u64,
    /// Cases refused by the reader or not modelled by the truth (should be 0).
    pub rejected: u64,
    /// mode@place → class → count.
    pub by_mode: BTreeMap<String, BTreeMap<ClassB, u64>>,
    /// Total ns in the pipeline (parse and stages) and in the truth.
    pub nanos: [u64; 2],
    /// Wall-clock seconds (summed over shards when merged).
    pub wall_seconds: f64,
    /// The cases kept (up to five per class but agreement and near alarms).
    pub kept: Vec<KeptB>,
    /// Cases whose legs' rectangles were checked against MPFR (built with `rug`), and the
    /// largest distance found, in units of its bound `2⁻⁴⁴·max(c, 4)`.
    #[serde(default)]
    pub model_checked: u64,
    /// See `model_checked`.
    #[serde(default)]
    pub model_error_max: f64,
}

impl ReportB {
    /// Counts per class over all modes.
    pub fn totals(&self) -> BTreeMap<ClassB, u64> {
        let mut t = BTreeMap::new();
        for m in self.by_mode.values() {
            for (c, n) in m {
                *t.entry(*c).or_insert(0) += n;
            }
        }
        t
    }

    /// Failures (missed conflicts, short windows, far ends, broken bounds).
    pub fn failures(&self) -> u64 {
        self.totals()
            .iter()
            .filter(|(c, _)| c.is_failure())
            .map(|(_, n)| n)
            .sum()
    }

    /// Adds another (shard's) report's counts.
    pub fn absorb(&mut self, o: &ReportB) {
        self.cases += o.cases;
        self.rejected += o.rejected;
        for (m, cs) in &o.by_mode {
            let e = self.by_mode.entry(m.clone()).or_default();
            for (c, n) in cs {
                *e.entry(*c).or_insert(0) += n;
            }
        }
        self.nanos[0] += o.nanos[0];
        self.nanos[1] += o.nanos[1];
        self.wall_seconds += o.wall_seconds;
        self.model_checked += o.model_checked;
        self.model_error_max = self.model_error_max.max(o.model_error_max);
    }

    /// Counts a verdict's MPFR check.
    pub fn see_model(&mut self, v: &VerdictB) {
        if let Some(r) = v.model_error {
            self.model_checked += 1;
            self.model_error_max = self.model_error_max.max(r);
        }
    }

    /// The printed summary: a table of modes × classes, the legend and one verdict line.
    pub fn summary(&self) -> String {
        use std::fmt::Write as _;
        let mut s = String::new();
        let short = [
            "agree", "near", "undec", "MISSED", "SHORT", "ENDFAR", "BOUND", "ROUND",
        ];
        let _ = write!(s, "{:<30}", "paper B mode@place");
        for h in short {
            let _ = write!(s, "{h:>8}");
        }
        s.push('\n');
        for (m, cs) in &self.by_mode {
            let _ = write!(s, "{m:<30}");
            for c in ClassB::ALL {
                let _ = write!(s, "{:>8}", cs.get(&c).copied().unwrap_or(0));
            }
            s.push('\n');
        }
        let t = self.totals();
        let _ = write!(s, "{:<30}", "all");
        for c in ClassB::ALL {
            let _ = write!(s, "{:>8}", t.get(&c).copied().unwrap_or(0));
        }
        s.push('\n');
        s.push_str(
            "classes: agree; near = a window for a pair that never meets, within 2ε (by design);\n  \
             undec = tangent within the truth's slack (not judged); MISSED = a meeting not \
             reported;\n  SHORT = a meeting outside the window; ENDFAR = a window end > 2ε \
             from contact;\n  BOUND = a speed bound broken; ROUND = a leg's f64 rectangle \
             beyond its rounding bound (MPFR)\n  (MISSED, SHORT, ENDFAR, BOUND and ROUND are \
             failures)\n",
        );
        let per = |i: usize| {
            if self.cases > 0 {
                self.nanos[i] as f64 / self.cases as f64 / 1e3
            } else {
                0.0
            }
        };
        let _ = writeln!(
            s,
            "{} cases, {} rejected, {:.1} µs pipeline and {:.1} µs truth per case, {:.1} s",
            self.cases,
            self.rejected,
            per(0),
            per(1),
            self.wall_seconds
        );
        if self.model_checked > 0 {
            let _ = writeln!(
                s,
                "model rounding (MPFR): {} cases checked, largest error {:.4} of its bound",
                self.model_checked, self.model_error_max
            );
        } else {
            s.push_str("model rounding (MPFR): not checked (build with --features rug)\n");
        }
        let g = |c: ClassB| t.get(&c).copied().unwrap_or(0);
        let _ = writeln!(
            s,
            "{}: paper B, {} cases: {} missed conflicts, {} short windows, {} far ends, {} broken bounds, {} model roundings ({} undecided, {} near alarms)",
            if self.failures() == 0 && self.rejected == 0 { "PASS" } else { "FAIL" },
            self.cases,
            g(ClassB::MissedConflict),
            g(ClassB::WindowShort),
            g(ClassB::EndFar),
            g(ClassB::BoundBroken),
            g(ClassB::ModelRounding),
            g(ClassB::Undecided),
            g(ClassB::NearAlarm),
        );
        s
    }
}

/// Paper B §VI.D: a random scenario of `n` objects from `seed` (the same scenario for the
/// same arguments on every machine), drawn by [`polyguard_earth::generate::generate`] from
/// the harness's SplitMix64.
pub fn seeded(
    n: usize,
    mix: polyguard_earth::generate::Mix,
    seed: u64,
    density_box: bool,
) -> polyguard_earth::scenario::Scenario {
    let mut rng = crate::gen::SplitMix(seed);
    polyguard_earth::generate::generate(n, mix, density_box, &mut || rng.next_u64())
}
