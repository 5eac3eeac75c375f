//! The ground truth of [`crate::aircraft_cell`]: how close does the aircraft really come to the
//! cell during `[0, T]`, in nautical miles on the Earth? Written without the module's
//! shortcut (no linear stand-in, no grown buffer, no piece): positions from the rhumb
//! motion itself, distances on the Earth itself.
//!
//! - On the sphere the motion is the closed form of paper B §V, written here again
//!   (`φ(t) = φ0 + s t cos θ / R`, `λ(t) = λ0 + tan θ (ψ(φ(t)) − ψ(φ0))` with
//!   `ψ = ln tan(π/4 + φ/2)`, or `s t sin θ / (R cos φ0)` due east or west), and
//!   distances are great-circle distances (haversine) on the sphere of radius
//!   [`EARTH_RADIUS_NM`].
//! - On WGS84 the motion is [`Geodesy::rhumb_destination`] (the model's definition) and
//!   distances are Karney's geodesics (`geo::Geodesic`).
//!
//! The cell at time t is the region its rhumb-line edges bound; a point is inside when
//! the ray cast on the Mercator plane (where those edges are straight) crosses them an
//! odd number of times. Otherwise its distance to the cell is the least distance to a
//! point of an edge, sampled along the edge and refined by ternary search. Every distance
//! returned is the distance between two real points of the model (the aircraft and a
//! point of the cell), so it is never below the true least distance: an engine "no" with
//! BUFF above it is a missed detection.

use crate::aircraft_cell::{EarthCase, Motion};
use crate::geodesy::Geodesy;
use crate::sphere::{rhumb_destination, LonLat, EARTH_RADIUS_NM};
use geo::{Distance, Geodesic, Point};

/// Paper B §V, eqs 23–24, written again from the closed form (module doc): the position
/// (radians, longitude unwrapped) after `t` hours from `start` (degrees).
pub fn position(
    geo: Geodesy,
    start_deg: [f64; 2],
    course_deg: f64,
    speed_kn: f64,
    t: f64,
) -> LonLat {
    let p0 = LonLat::from_degrees(start_deg[0], start_deg[1]);
    let th = course_deg.to_radians();
    let d = speed_kn * t;
    match geo {
        Geodesy::Wgs84 => geo.rhumb_destination(p0, th, d),
        Geodesy::Sphere => {
            let lat = p0.lat + d * th.cos() / EARTH_RADIUS_NM;
            let psi = |phi: f64| (core::f64::consts::FRAC_PI_4 + 0.5 * phi).tan().ln();
            let dpsi = psi(lat) - psi(p0.lat);
            let dlat = lat - p0.lat;
            // due east or west (or too close to it for the quotient): the parallel's scale
            let lon = if dlat.abs() < 1e-12 {
                p0.lon + d * th.sin() / (EARTH_RADIUS_NM * p0.lat.cos())
            } else {
                p0.lon + th.tan() * dpsi
            };
            LonLat { lon, lat }
        }
    }
}

/// The distance (nm) between two points on the model: haversine on the sphere, Karney's
/// geodesic on WGS84.
pub fn distance_nm(geo: Geodesy, a: LonLat, b: LonLat) -> f64 {
    match geo {
        Geodesy::Sphere => {
            let h = ((b.lat - a.lat) / 2.0).sin().powi(2)
                + a.lat.cos() * b.lat.cos() * ((b.lon - a.lon) / 2.0).sin().powi(2);
            2.0 * EARTH_RADIUS_NM * h.sqrt().min(1.0).asin()
        }
        Geodesy::Wgs84 => {
            let (pa, pb) = (
                Point::new(a.lon.to_degrees(), a.lat.to_degrees()),
                Point::new(b.lon.to_degrees(), b.lat.to_degrees()),
            );
            Geodesic::distance(pa, pb) / crate::geodesy::METRES_PER_NM
        }
    }
}

/// `x` moved by whole turns to within π of `reference`.
fn near(x: f64, reference: f64) -> f64 {
    let tau = core::f64::consts::TAU;
    x + tau * ((reference - x) / tau).round()
}

/// The least distance found (nm) between the aircraft and the cell at time `t`, 0 when
/// the aircraft is inside it.
pub fn distance_at(case: &EarthCase, geo: Geodesy, t: f64) -> f64 {
    let a = position(
        geo,
        case.aircraft_pos,
        case.aircraft.course_deg,
        case.aircraft.speed_kn,
        t,
    );
    // the ring on the aircraft's branch, joined the shorter way
    let mut ring: Vec<LonLat> = Vec::with_capacity(case.cell_vertices.len());
    for v in &case.cell_vertices {
        let mut p = position(geo, *v, case.cell.course_deg, case.cell.speed_kn, t);
        p.lon = near(p.lon, ring.last().map_or(a.lon, |q| q.lon));
        ring.push(p);
    }
    let merc: Vec<[f64; 2]> = ring.iter().map(|p| geo.mercator(*p)).collect();
    let s = geo.mercator(a);
    // ray cast upwards on the Mercator plane
    let n = merc.len();
    let mut inside = false;
    for i in 0..n {
        let (p, q) = (merc[i], merc[(i + 1) % n]);
        if (p[0] > s[0]) != (q[0] > s[0]) {
            let y = p[1] + (s[0] - p[0]) / (q[0] - p[0]) * (q[1] - p[1]);
            if y > s[1] {
                inside = !inside;
            }
        }
    }
    if inside {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (p, q) = (merc[i], merc[(i + 1) % n]);
        let at = |r: f64| {
            let m = [p[0] + r * (q[0] - p[0]), p[1] + r * (q[1] - p[1])];
            distance_nm(geo, a, geo.inverse_mercator(m))
        };
        let k = 16;
        let (mut r_best, mut d_best) = (0.0, f64::INFINITY);
        for j in 0..=k {
            let r = j as f64 / k as f64;
            let d = at(r);
            if d < d_best {
                (r_best, d_best) = (r, d);
            }
        }
        let (mut lo, mut hi) = (
            (r_best - 1.0 / k as f64).max(0.0),
            (r_best + 1.0 / k as f64).min(1.0),
        );
        for _ in 0..40 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if at(m1) < at(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        best = best.min(d_best).min(at(0.5 * (lo + hi)));
    }
    best
}

/// The least distance found (nm) between the aircraft and the cell over `[0, T]`, and
/// when: `samples + 1` instants, then a ternary search around the best.
pub fn closest_approach(case: &EarthCase, geo: Geodesy, samples: usize) -> (f64, f64) {
    let t_end = case.lookahead_h;
    let k = samples.max(1);
    let (mut t_best, mut d_best) = (0.0, f64::INFINITY);
    for j in 0..=k {
        let t = t_end * j as f64 / k as f64;
        let d = distance_at(case, geo, t);
        if d < d_best {
            (t_best, d_best) = (t, d);
        }
    }
    let step = t_end / k as f64;
    let (mut lo, mut hi) = ((t_best - step).max(0.0), (t_best + step).min(t_end));
    for _ in 0..40 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if distance_at(case, geo, m1) < distance_at(case, geo, m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    let t = 0.5 * (lo + hi);
    let d = distance_at(case, geo, t);
    if d < d_best {
        (d, t)
    } else {
        (d_best, t_best)
    }
}

/// A small seeded generator (SplitMix64).
pub struct Mix(pub u64);

impl Mix {
    /// The next 64 random bits.
    pub fn bits(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn wrap(lon_deg: f64) -> f64 {
    (lon_deg + 180.0).rem_euclid(360.0) - 180.0
}

fn degrees(p: LonLat) -> [f64; 2] {
    let (lon, lat) = p.to_degrees();
    [wrap(lon), lat]
}

/// An encounter near latitude `lat` (degrees): a star-shaped cell of 3 to 8 vertices,
/// 3 to 40 nm across, drifting at up to 40 kn; an aircraft at 60 to 600 kn whose track
/// passes the cell's centre at a random offset at a random time of [0, T]. One in three
/// is placed on the antimeridian. BUFF is 1 nm (callers set their own). The generator of
/// the tests (tests/paper_a_earth.rs) and of the measurement (crates/harness/examples/earth_false_alarms.rs).
pub fn encounter(seed: u64, lat: f64) -> EarthCase {
    let mut r = Mix(seed);
    let lon = if r.bits() % 3 == 0 {
        180.0 + r.uniform(-1.0, 1.0)
    } else {
        r.uniform(-180.0, 180.0)
    };
    let centre = LonLat::from_degrees(lon, lat);
    let radius = r.uniform(3.0, 40.0);
    let n = 3 + (r.bits() % 6) as usize;
    let mut angles: Vec<f64> = (0..n).map(|_| r.uniform(0.0, 360.0)).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup_by(|a, b| (*a - *b).abs() < 5.0);
    while angles.len() < 3 {
        let a = angles.last().copied().unwrap_or(0.0) + 100.0;
        angles.push(a);
    }
    let vertices: Vec<[f64; 2]> = angles
        .iter()
        .map(|a| {
            let d = radius * r.uniform(0.5, 1.0);
            degrees(rhumb_destination(centre, a.to_radians(), d))
        })
        .collect();
    let cell = Motion {
        course_deg: r.uniform(0.0, 360.0),
        speed_kn: r.uniform(0.0, 40.0),
    };
    let aircraft = Motion {
        course_deg: r.uniform(0.0, 360.0),
        speed_kn: r.uniform(60.0, 600.0),
    };
    let lookahead_h = r.uniform(0.1, 1.5);
    let t_mid = lookahead_h * r.uniform(0.0, 1.0);
    let offset = r.uniform(-radius, 2.0 * radius + 30.0);
    let drifted = rhumb_destination(centre, cell.course_deg.to_radians(), cell.speed_kn * t_mid);
    let th = aircraft.course_deg.to_radians();
    let abeam = rhumb_destination(drifted, th + core::f64::consts::FRAC_PI_2, offset);
    let start = rhumb_destination(abeam, th + core::f64::consts::PI, aircraft.speed_kn * t_mid);
    EarthCase {
        lookahead_h,
        buff_nm: 1.0,
        aircraft_pos: degrees(start),
        aircraft,
        cell_vertices: vertices,
        cell,
    }
}
