//! Whole flights against areas on the Earth (docs/moving-features.md): the model's
//! lon/lat fixes and rings laid on paper B's Mercator plane (§V, on the sphere or WGS84),
//! the planar core ([`super::plane`]) run on each segment, and its margins made to cover
//! what the plane does not see:
//!
//! - **the rhumb line at constant speed**: between two fixes the mover's model latitude u
//!   is linear in time, so its Mercator ordinate is Ψ(u(t)), not linear. Along the leg's
//!   line the position's fraction differs from the uniform one by at most
//!   Δu²·max|Ψ''|/(8·|ΔΨ|) ≤ |Δu|·max|Ψ''|/(8·min Ψ'), so the point is within
//!   |ΔP|·|Δu|·sec Φ tan Φ/(8·g_min) of the planar model's (Φ the leg's largest |latitude|,
//!   [`Geodesy::sec_tan_bound`], g = Ψ' ([`Geodesy::g_range`])); 0 on an east–west leg;
//! - **the projection's rounding**: each projected coordinate within
//!   [`position_slack`] of its exact value (paper B §V's stated bound, which also covers a
//!   whole-turn shift of longitude); on WGS84 also its series' model error;
//! - **distances in nautical miles**: a path of Earth length L from the mover has a
//!   Mercator image at most L·sec Φ_b/R long (Φ_b the largest latitude it can reach), and
//!   a Mercator segment of length m has an Earth image at most m·R·cos φ_low long (φ_low
//!   the smallest |latitude| it can reach); so near_D on the Earth lies between the
//!   planar near of `d_lo = D·sec φ_low/R` and of `d_hi = D·sec Φ_b/R` (on WGS84 with
//!   the radii of `aircraft_cell`'s module doc, and N cos φ ≤ a cos φ/√(1 − e²)).
//!
//! Longitudes: a segment's fixes are unwrapped each the shorter way from the one before
//! (the rhumb line joining two fixes is the shorter one), an area's rings each vertex the
//! shorter way from the previous (a keyframe's vertex the shorter way from the same vertex
//! in the keyframe before); where the segment's longitudes reach a copy of the area a
//! whole turn away, that copy is tested too.

use core::fmt;

use super::model::{Area, Fix, Rings, Shape, Trajectory};
use super::piece::Margins;
use super::plane::{
    timeline_with, PlaneArea, PlaneError, PlaneFix, PlaneFrame, PlaneRings, TimeSpan,
};
use super::prepared::Prepared;
use super::timeline::Timeline;
use crate::geodesy::{Geodesy, METRES_PER_NM, WGS84_A_M, WGS84_F};
use crate::rhumb::EARTH_RADIUS_NM;
use crate::sphere::{position_slack, BOUND_SAFETY};

/// The format's latitude limit (degrees), as the scenario format: Mercator's plane
/// stretches without bound towards the poles.
pub const MAX_LAT_DEG: f64 = 85.0;
/// The largest latitude (degrees) a path of D from a mover may reach: sec 89° ≈ 57 bounds
/// the Mercator scale in [`d_band`].
const MAX_REACH_LAT_DEG: f64 = 89.0;
/// On WGS84, the projection series' model error (radians), as `aircraft_cell`'s.
const WGS84_MODEL_RAD: f64 = 4e-10;
/// A whole turn of longitude, radians.
const TURN: f64 = 2.0 * core::f64::consts::PI;

/// What is asked of every pair of mover and area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// D, nautical miles (≥ 0): near means within D horizontally.
    pub sep_nm: f64,
    /// H, feet (≥ 0): near means within H of the floor–ceiling slab.
    pub sep_v_ft: f64,
    /// Fixes farther apart than this (seconds) are not joined: the trajectory splits.
    pub max_gap_s: f64,
    /// The model of the Earth.
    pub geodesy: Geodesy,
}

impl Default for Options {
    /// D = H = 0 (near is inside), gaps beyond 60 s, the sphere.
    fn default() -> Self {
        Options {
            sep_nm: 0.0,
            sep_v_ft: 0.0,
            max_gap_s: 60.0,
            geodesy: Geodesy::Sphere,
        }
    }
}

/// One pair of mover and area that meet: the certified spans of inside and of near
/// (docs/moving-features.md, "The contract"), in seconds since 1970-01-01T00:00:00Z.
#[derive(Clone, Debug, PartialEq)]
pub struct Encounter {
    /// The mover's id.
    pub mover: String,
    /// The mover's callsign, when known.
    pub callsign: Option<String>,
    /// The area's id.
    pub area: String,
    /// When the mover is inside the area (and between its floor and ceiling).
    pub inside: Vec<TimeSpan>,
    /// When it is within D nm and H ft of it.
    pub near: Vec<TimeSpan>,
    /// The trajectory's gaps longer than the maximum: [last fix before, first fix after].
    pub gaps: Vec<[f64; 2]>,
}

impl Encounter {
    /// The first loss of separation: the first near span's start enclosure.
    pub fn loss_of_separation(&self) -> Option<[f64; 2]> {
        self.near.first().map(|s| s.start)
    }
}

/// Why a mover or an area cannot be answered.
#[derive(Clone, Debug, PartialEq)]
pub struct EncounterError {
    /// The mover's or the area's id.
    pub id: String,
    /// The member (`fixes[3].lat`, `parts[0].outer[2]`, …).
    pub member: String,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for EncounterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.id, self.member, self.message)
    }
}

impl std::error::Error for EncounterError {}

/// `lon + 360·k` for the integer k that brings it within 180° of `reference` (degrees).
pub(crate) fn unwrap_near(lon: f64, reference: f64) -> f64 {
    let k = ((reference - lon) / 360.0).round();
    lon + 360.0 * k
}

/// The checks every position passes: finite, longitude in [−180, 180], latitude within
/// ±[`MAX_LAT_DEG`].
fn check_position(id: &str, member: &str, p: [f64; 2]) -> Result<(), EncounterError> {
    let err = |message: String| EncounterError {
        id: id.into(),
        member: member.into(),
        message,
    };
    if !p[0].is_finite() || !p[1].is_finite() {
        return Err(err("not a finite number".into()));
    }
    if !(-180.0..=180.0).contains(&p[0]) {
        return Err(err(format!("longitude {} is outside [-180, 180]", p[0])));
    }
    if !(-MAX_LAT_DEG..=MAX_LAT_DEG).contains(&p[1]) {
        return Err(err(format!("latitude {} is outside [-85, 85]", p[1])));
    }
    Ok(())
}

/// A position in degrees (longitude already unwrapped) on the Mercator plane.
fn project(geo: Geodesy, lon_deg: f64, lat_deg: f64) -> [f64; 2] {
    [lon_deg.to_radians(), geo.mercator_y(lat_deg.to_radians())]
}

/// An area laid on the Mercator plane, ready for many movers.
pub struct PreparedArea {
    /// The area's id.
    pub id: String,
    plane: PlaneArea,
    prepared: Prepared,
    /// [xmin, ymin, xmax, ymax] over every frame (radians).
    pub bbox: [f64; 4],
    slack: f64,
}

/// One ring unwrapped, checked and projected: each vertex the shorter way from the same
/// vertex of the keyframe `before` when there is one, else from the previous vertex.
fn ring_on_plane(
    geo: Geodesy,
    id: &str,
    member: &str,
    ring: &[[f64; 2]],
    before: Option<&[[f64; 2]]>,
) -> Result<Vec<[f64; 2]>, EncounterError> {
    if ring.len() < 3 {
        return Err(EncounterError {
            id: id.into(),
            member: member.into(),
            message: format!("{} vertices, at least 3 are needed", ring.len()),
        });
    }
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(ring.len());
    for (i, p) in ring.iter().enumerate() {
        check_position(id, &format!("{member}[{i}]"), *p)?;
        let reference = match (before, out.last()) {
            (Some(b), _) => b[i][0].to_degrees(),
            (None, Some(q)) => q[0].to_degrees(),
            (None, None) => p[0],
        };
        out.push(project(geo, unwrap_near(p[0], reference), p[1]));
    }
    Ok(out)
}

impl PreparedArea {
    /// `area` on the Mercator plane of `geo`: rings unwrapped and projected, checked
    /// (finite, in range, ≥ 3 vertices, keyframes with one structure and increasing
    /// times, floor ≤ ceiling).
    pub fn new(area: &Area, geo: Geodesy) -> Result<PreparedArea, EncounterError> {
        let id = area.id.as_str();
        let err = |member: &str, message: String| EncounterError {
            id: id.into(),
            member: member.into(),
            message,
        };
        let (frames, is_static): (Vec<(f64, &Vec<Rings>)>, bool) = match &area.shape {
            Shape::Static(parts) => (vec![(0.0, parts)], true),
            Shape::Keyframed(k) => (k.iter().map(|f| (f.t, &f.parts)).collect(), false),
        };
        if frames.is_empty() || frames[0].1.is_empty() {
            return Err(err("parts", "no polygon".into()));
        }
        let mut plane_frames: Vec<PlaneFrame> = Vec::with_capacity(frames.len());
        for (k, (t, parts)) in frames.iter().enumerate() {
            if !t.is_finite() || (k > 0 && *t <= frames[k - 1].0) {
                return Err(err(
                    &format!("keyframes[{k}].t"),
                    "times must increase".into(),
                ));
            }
            let frame = frame_on_plane(geo, id, k, *t, parts, plane_frames.last())?;
            plane_frames.push(frame);
        }
        for (name, x) in [("floor_ft", area.floor_ft), ("ceiling_ft", area.ceiling_ft)] {
            if x.is_some_and(|x| !x.is_finite()) {
                return Err(err(name, "not a finite number".into()));
            }
        }
        if let (Some(f), Some(c)) = (area.floor_ft, area.ceiling_ft) {
            if f > c {
                return Err(err("floor_ft", format!("{f} is above ceiling_ft {c}")));
            }
        }
        let bbox = frames_box(&plane_frames);
        let plane = PlaneArea {
            frames: plane_frames,
            is_static,
            floor: area.floor_ft,
            ceiling: area.ceiling_ft,
        };
        let prepared = Prepared::new(&plane);
        let c = bbox.iter().fold(0.0f64, |m, x| m.max(x.abs())) + TURN;
        let slack = 2.0 * position_slack(c) + model_rad(geo);
        Ok(PreparedArea {
            id: area.id.clone(),
            plane,
            prepared,
            bbox,
            slack,
        })
    }
}

/// Keyframe `k` (time `t`, `parts`) on the plane: each ring laid out by
/// [`ring_on_plane`], checked to have the structure of the keyframe `before`.
fn frame_on_plane(
    geo: Geodesy,
    id: &str,
    k: usize,
    t: f64,
    parts: &[Rings],
    before: Option<&PlaneFrame>,
) -> Result<PlaneFrame, EncounterError> {
    let err = |member: String, message: String| EncounterError {
        id: id.into(),
        member,
        message,
    };
    if let Some(pf) = before {
        if pf.parts.len() != parts.len()
            || pf
                .parts
                .iter()
                .zip(parts)
                .any(|(a, b)| a.holes.len() != b.holes.len())
        {
            return Err(err(
                format!("keyframes[{k}].parts"),
                "the parts or holes differ from the keyframe before".into(),
            ));
        }
    }
    let mut pparts = Vec::with_capacity(parts.len());
    for (j, part) in parts.iter().enumerate() {
        let mut rings_out = Vec::new();
        for (r, ring) in core::iter::once(&part.outer).chain(&part.holes).enumerate() {
            let member = if r == 0 {
                format!("keyframes[{k}].parts[{j}].outer")
            } else {
                format!("keyframes[{k}].parts[{j}].holes[{}]", r - 1)
            };
            let prev: Option<&[[f64; 2]]> = before.and_then(|f| {
                let p = &f.parts[j];
                if r == 0 {
                    Some(&p.outer[..])
                } else {
                    p.holes.get(r - 1).map(|h| &h[..])
                }
            });
            if let Some(b) = prev {
                if b.len() != ring.len() {
                    return Err(err(
                        member,
                        format!(
                            "{} vertices where the keyframe before has {} (linear \
                             interpolation needs the same count)",
                            ring.len(),
                            b.len()
                        ),
                    ));
                }
            }
            rings_out.push(ring_on_plane(geo, id, &member, ring, prev)?);
        }
        let outer = rings_out.remove(0);
        pparts.push(PlaneRings {
            outer,
            holes: rings_out,
        });
    }
    Ok(PlaneFrame { t, parts: pparts })
}

/// [xmin, ymin, xmax, ymax] of every vertex of `frames`.
fn frames_box(frames: &[PlaneFrame]) -> [f64; 4] {
    let mut bbox = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for f in frames {
        for part in &f.parts {
            for p in core::iter::once(&part.outer).chain(&part.holes).flatten() {
                bbox = [
                    bbox[0].min(p[0]),
                    bbox[1].min(p[1]),
                    bbox[2].max(p[0]),
                    bbox[3].max(p[1]),
                ];
            }
        }
    }
    bbox
}

/// On WGS84, the projection series' model error; 0 on the sphere.
fn model_rad(geo: Geodesy) -> f64 {
    match geo {
        Geodesy::Sphere => 0.0,
        Geodesy::Wgs84 => WGS84_MODEL_RAD,
    }
}

/// The radii (nm) the distance bounds use: the Mercator scale's `R_s` (scale ≤ sec φ/R_s),
/// `R_φ` (a path of length L changes latitude by at most L/R_φ) and `R_up` (a Mercator
/// segment of length m has an Earth image at most m·R_up·cos φ_low long).
fn radii(geo: Geodesy) -> (f64, f64, f64) {
    match geo {
        Geodesy::Sphere => (EARTH_RADIUS_NM, EARTH_RADIUS_NM, EARTH_RADIUS_NM),
        Geodesy::Wgs84 => {
            let a = WGS84_A_M / METRES_PER_NM;
            let e2 = WGS84_F * (2.0 - WGS84_F);
            (
                a,
                a * (1.0 - e2) * (1.0 - 1e-12),
                a / (1.0 - e2).sqrt() * (1.0 + 1e-12),
            )
        }
    }
}

/// A leg's rhumb deviation (module doc) is kept below this many radians (2⁻³⁰, about
/// 6 mm on the Earth) by cutting the leg at points of the model's own motion.
const RHUMB_RESOLUTION: f64 = 1.0 / (1u64 << 30) as f64;
/// The most sub-legs one leg is cut into.
const MAX_SUBLEGS: f64 = 4096.0;
/// The unit roundoff of f64, 2⁻⁵³.
const U: f64 = f64::EPSILON / 2.0;

/// One segment of a mover on the plane, with what each leg adds to the margins.
struct Segment {
    fixes: Vec<PlaneFix>,
    /// Per leg (fixes i, i + 1): the latitudes' range [min |φ|, max |φ|] (radians; min 0
    /// across the equator), the extra distance of the model's point from the plane's, and
    /// the extra error of the heights.
    legs: Vec<([f64; 2], f64, f64)>,
}

/// A projected fix with its latitude (radians) and its errors (position, height).
#[derive(Clone, Copy)]
struct Placed {
    fix: PlaneFix,
    lat: f64,
    err: f64,
    err_z: f64,
}

/// The rhumb deviation bound of the module doc between two placed fixes, and |ΔP|₁.
fn rhumb_dev(geo: Geodesy, a: &Placed, b: &Placed) -> (f64, f64) {
    let (u0, u1) = (geo.u_of_lat(a.lat), geo.u_of_lat(b.lat));
    let (sec, tan) = geo.sec_tan_bound(u0.abs().max(u1.abs()));
    let (g_min, _) = geo.g_range(u0.min(u1), u0.max(u1));
    let dp = (b.fix.x - a.fix.x).abs() + (b.fix.y - a.fix.y).abs();
    (
        dp * (u1 - u0).abs() * sec * tan.abs() / (8.0 * g_min) * BOUND_SAFETY,
        dp,
    )
}

/// The points that cut the leg from `a` to `b` into `k` sub-legs, on the model's motion
/// (model latitude linear in time, x linear in y along the rhumb line), each with its
/// error: the projection's slack, and the rounding of its fraction of the leg (≤ 3u,
/// moving u by 3u|Δu| and the point by at most 8u·|ΔP|₁·g_max/g_min).
fn cut_leg(geo: Geodesy, a: &Placed, b: &Placed, k: usize, slack: f64) -> Vec<Placed> {
    let (u0, u1) = (geo.u_of_lat(a.lat), geo.u_of_lat(b.lat));
    let (g_min, g_max) = geo.g_range(u0.min(u1), u0.max(u1));
    let dp = (b.fix.x - a.fix.x).abs() + (b.fix.y - a.fix.y).abs();
    let err = slack + 8.0 * U * dp * g_max / g_min * BOUND_SAFETY;
    let (ta, tb) = (a.fix.t, b.fix.t);
    let mut out: Vec<Placed> = Vec::with_capacity(k);
    for j in 1..k {
        let t = ta + (tb - ta) * (j as f64 / k as f64);
        if t <= out.last().map_or(ta, |p| p.fix.t) || t >= tb {
            continue;
        }
        let sigma = (t - ta) / (tb - ta);
        let lat = geo.lat_of_u(u0 + sigma * (u1 - u0));
        let y = geo.mercator_y(lat);
        let x = if b.fix.y != a.fix.y {
            a.fix.x + (y - a.fix.y) / (b.fix.y - a.fix.y) * (b.fix.x - a.fix.x)
        } else {
            a.fix.x + sigma * (b.fix.x - a.fix.x)
        };
        let (z, err_z) = match (a.fix.z, b.fix.z) {
            (Some(za), Some(zb)) => (
                Some(za + sigma * (zb - za)),
                8.0 * U * (za.abs() + (zb - za).abs()),
            ),
            _ => (None, 0.0),
        };
        out.push(Placed {
            fix: PlaneFix { t, x, y, z },
            lat,
            err,
            err_z,
        });
    }
    out
}

/// The model's altitude at fixes that carry none: linear in time between the nearest
/// fixes before and after that carry one (docs/moving-features.md), with its rounding
/// (8u(|z_a| + |Δz|), as an interpolation); fixes before the first or after the last
/// altitude of the segment keep none.
fn fill_altitudes(raw: &mut [Placed]) {
    let known: Vec<usize> = (0..raw.len()).filter(|&i| raw[i].fix.z.is_some()).collect();
    for w in known.windows(2) {
        let (a, b) = (raw[w[0]], raw[w[1]]);
        let (Some(za), Some(zb)) = (a.fix.z, b.fix.z) else {
            continue;
        };
        for p in &mut raw[w[0] + 1..w[1]] {
            let f = (p.fix.t - a.fix.t) / (b.fix.t - a.fix.t);
            p.fix.z = Some(za + f * (zb - za));
            p.err_z = 8.0 * U * (za.abs() + (zb - za).abs());
        }
    }
}

/// The mover's fixes `f` (one segment) unwrapped, checked and projected; legs whose
/// rhumb deviation exceeds [`RHUMB_RESOLUTION`] cut at points of the model's motion.
fn segment_on_plane(
    geo: Geodesy,
    id: &str,
    f: &[Fix],
    first: usize,
) -> Result<Segment, EncounterError> {
    let mut raw: Vec<Placed> = Vec::with_capacity(f.len());
    let mut prev_lon: Option<f64> = None;
    for (i, x) in f.iter().enumerate() {
        let member = format!("fixes[{}]", first + i);
        check_position(id, &member, [x.lon, x.lat])?;
        if !x.t.is_finite() || x.alt_ft.is_some_and(|z| !z.is_finite()) {
            return Err(EncounterError {
                id: id.into(),
                member,
                message: "not a finite number".into(),
            });
        }
        if let Some(p) = raw.last() {
            if x.t <= p.fix.t {
                return Err(EncounterError {
                    id: id.into(),
                    member: format!("{member}.t"),
                    message: "times must strictly increase".into(),
                });
            }
        }
        let lon = match prev_lon {
            None => x.lon,
            Some(p) => unwrap_near(x.lon, p),
        };
        prev_lon = Some(lon);
        let m = project(geo, lon, x.lat);
        let fix = PlaneFix {
            t: x.t,
            x: m[0],
            y: m[1],
            z: x.alt_ft,
        };
        raw.push(Placed {
            fix,
            lat: x.lat.to_radians(),
            err: 0.0,
            err_z: 0.0,
        });
    }
    fill_altitudes(&mut raw);
    let c = raw
        .iter()
        .fold(0.0f64, |m, p| m.max(p.fix.x.abs()).max(p.fix.y.abs()))
        + TURN;
    let slack = 2.0 * position_slack(c) + model_rad(geo);
    for p in &mut raw {
        p.err = slack;
    }
    let mut placed: Vec<Placed> = Vec::with_capacity(raw.len());
    for (i, p) in raw.iter().enumerate() {
        if let Some(prev) = i.checked_sub(1).map(|j| raw[j]) {
            let (dev, _) = rhumb_dev(geo, &prev, p);
            if dev > RHUMB_RESOLUTION {
                let k = (dev / RHUMB_RESOLUTION).sqrt().ceil().min(MAX_SUBLEGS) as usize;
                placed.extend(cut_leg(geo, &prev, p, k, slack));
            }
        }
        placed.push(*p);
    }
    let mut legs: Vec<([f64; 2], f64, f64)> = placed
        .windows(2)
        .map(|w| {
            let (l0, l1) = (w[0].lat, w[1].lat);
            let lo = if l0 * l1 <= 0.0 {
                0.0
            } else {
                l0.abs().min(l1.abs())
            };
            let hi = l0.abs().max(l1.abs());
            let (dev, _) = rhumb_dev(geo, &w[0], &w[1]);
            (
                [lo, hi],
                w[0].err.max(w[1].err) + dev,
                w[0].err_z.max(w[1].err_z),
            )
        })
        .collect();
    if let [only] = placed[..] {
        // One fix: an instant, with the fix's own errors.
        legs.push(([only.lat.abs(), only.lat.abs()], only.err, 0.0));
    }
    Ok(Segment {
        fixes: placed.iter().map(|p| p.fix).collect(),
        legs,
    })
}

/// The module doc's `d_lo` and `d_hi` for D = `sep_nm` over latitudes `lat` = [min |φ|,
/// max |φ|] of the mover.
fn d_band(geo: Geodesy, sep_nm: f64, lat: [f64; 2]) -> (f64, f64) {
    if sep_nm == 0.0 {
        return (0.0, 0.0);
    }
    let (r_s, r_phi, r_up) = radii(geo);
    // Below 89° (checked by `encounter`).
    let phi_b = lat[1] + sep_nm / r_phi;
    let d_hi = sep_nm / (phi_b.cos() * r_s) * BOUND_SAFETY;
    // A Mercator segment of length m changes latitude by at most m (dφ/dy = cos φ ≤ 1).
    // First with m ≤ 12·D/R_s (sec 85° < 12), then with the d_lo that gives: that d_lo
    // is no larger, so the latitudes it reaches stay above the φ_low it used.
    let d_lo_at = |phi_low: f64| sep_nm / (phi_low.cos() * r_up) / BOUND_SAFETY;
    let first = d_lo_at((lat[0] - 12.0 * sep_nm / r_s).max(0.0));
    let d_lo = d_lo_at((lat[0] - first * BOUND_SAFETY).max(0.0));
    (d_lo, d_hi)
}

/// How far (plane units) anything within D nm of a mover whose |latitude| stays below
/// `max_lat` (radians) can be: [`d_band`]'s `d_hi` there, and room for every margin δ (all
/// below 10⁻⁹ of a turn: paper B's slack is 2⁻⁴⁰ of the coordinates, the rhumb deviation
/// is kept below 2⁻³⁰ rad).
pub(crate) fn reach(geo: Geodesy, sep_nm: f64, max_lat: f64) -> f64 {
    d_band(geo, sep_nm, [0.0, max_lat]).1 + 1e-9 * TURN
}

/// The spans of one segment against one area (every copy a whole turn away that its
/// longitudes reach): inside (`near` false) or near.
fn segment_spans(seg: &Segment, area: &PreparedArea, opts: &Options, near: bool) -> Vec<TimeSpan> {
    let (xmin, xmax) = seg
        .fixes
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.x), b.max(p.x))
        });
    let max_lat = seg.legs.iter().fold(0.0f64, |m, l| m.max(l.0[1]));
    let reach = reach(opts.geodesy, opts.sep_nm, max_lat);
    let ks = (((xmin - reach - area.bbox[2]) / TURN).ceil() as i64)
        ..=(((xmax + reach - area.bbox[0]) / TURN).floor() as i64);
    let mut total: Option<Timeline> = None;
    for k in ks {
        let shift = k as f64 * TURN;
        let fixes: Vec<PlaneFix> = seg
            .fixes
            .iter()
            .map(|p| PlaneFix {
                x: p.x - shift,
                ..*p
            })
            .collect();
        let margins = |t0: f64, _t1: f64| {
            let j = match fixes.binary_search_by(|f| f.t.total_cmp(&t0)) {
                Ok(j) => j,
                Err(j) => j.saturating_sub(1),
            }
            .min(seg.legs.len().saturating_sub(1));
            let (lat, extra, extra_z) = seg.legs.get(j).copied().unwrap_or(([0.0, 0.0], 0.0, 0.0));
            let (d_lo, d_hi) = if near {
                d_band(opts.geodesy, opts.sep_nm, lat)
            } else {
                (0.0, 0.0)
            };
            Margins {
                d_lo,
                d_hi,
                extra_point: extra,
                extra_area: area.slack,
                extra_z,
            }
        };
        let h = if near { opts.sep_v_ft } else { 0.0 };
        let tl = timeline_with(&fixes, &area.plane, &area.prepared, h, &margins);
        total = match (total, tl) {
            (None, t) | (t, None) => t,
            (Some(a), Some(b)) => Some(a.or(&b)),
        };
    }
    total.map(|t| t.closed().to_spans()).unwrap_or_default()
}

/// The segments of `traj` (fixes at most `max_gap_s` apart) and the gaps between them.
fn segments(traj: &Trajectory, max_gap_s: f64) -> (Vec<core::ops::Range<usize>>, Vec<[f64; 2]>) {
    let fixes: Vec<PlaneFix> = traj
        .fixes
        .iter()
        .map(|f| PlaneFix {
            t: f.t,
            x: 0.0,
            y: 0.0,
            z: None,
        })
        .collect();
    let segs = super::plane::split_segments(&fixes, max_gap_s);
    let gaps = segs
        .windows(2)
        .map(|w| [traj.fixes[w[0].end - 1].t, traj.fixes[w[1].start].t])
        .collect();
    (segs, gaps)
}

/// The mover's rules (docs/moving-features.md): finite times strictly increasing,
/// positions in range, and a path of D nm from any fix staying below 89° of latitude
/// ([`d_band`]'s Φ_b). Checked before the broad phase, so that a bad mover is reported
/// whether or not it comes near an area.
pub(crate) fn check_mover(traj: &Trajectory, opts: &Options) -> Result<(), EncounterError> {
    let (_, r_phi, _) = radii(opts.geodesy);
    let reach_deg = (opts.sep_nm / r_phi).to_degrees();
    for (i, f) in traj.fixes.iter().enumerate() {
        let member = format!("fixes[{i}]");
        check_position(&traj.id, &member, [f.lon, f.lat])?;
        let err = |member: String, message: String| EncounterError {
            id: traj.id.clone(),
            member,
            message,
        };
        if !f.t.is_finite() || f.alt_ft.is_some_and(|z| !z.is_finite()) {
            return Err(err(member, "not a finite number".into()));
        }
        if i > 0 && f.t <= traj.fixes[i - 1].t {
            return Err(err(
                format!("{member}.t"),
                "times must strictly increase".into(),
            ));
        }
        if f.lat.abs() + reach_deg >= MAX_REACH_LAT_DEG {
            return Err(err(
                format!("{member}.lat"),
                format!(
                    "a path of {} nm from latitude {} could reach beyond {MAX_REACH_LAT_DEG}°",
                    opts.sep_nm, f.lat
                ),
            ));
        }
    }
    Ok(())
}

/// The mover `traj` against the prepared area: `None` when they never meet (no near span,
/// so no inside span either), else the [`Encounter`] (docs/moving-features.md).
pub fn encounter(
    traj: &Trajectory,
    area: &PreparedArea,
    opts: &Options,
) -> Result<Option<Encounter>, EncounterError> {
    let (segs, gaps) = segments(traj, opts.max_gap_s);
    check_mover(traj, opts)?;
    let mut inside = Vec::new();
    let mut near = Vec::new();
    for r in segs {
        let seg = segment_on_plane(opts.geodesy, &traj.id, &traj.fixes[r.clone()], r.start)?;
        let n = segment_spans(&seg, area, opts, true);
        if n.is_empty() {
            continue;
        }
        if opts.sep_nm == 0.0 && opts.sep_v_ft == 0.0 {
            // near with D = H = 0 is inside.
            inside.extend(n.iter().copied());
        } else {
            inside.extend(segment_spans(&seg, area, opts, false));
        }
        near.extend(n);
    }
    if near.is_empty() {
        return Ok(None);
    }
    Ok(Some(Encounter {
        mover: traj.id.clone(),
        callsign: traj.callsign.clone(),
        area: area.id.clone(),
        inside,
        near,
        gaps,
    }))
}

/// A [`PlaneError`] as an encounter error of `id`.
impl From<(String, PlaneError)> for EncounterError {
    fn from((id, e): (String, PlaneError)) -> Self {
        EncounterError {
            id,
            member: String::new(),
            message: e.to_string(),
        }
    }
}
