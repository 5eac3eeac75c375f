//! Paper B Section V on the sphere: points in longitude and latitude, the Mercator plane
//! (eqs 25–26 and Algorithm 4's inverse) and rhumb lines (eqs 23–24), in radians and
//! nautical miles.
//!
//! The bottom layer of the Earth's geometry: [`crate::geodesy`] chooses the model of the
//! Earth from these and the ellipsoid's, and [`crate::sphere`] (which re-exports them)
//! moves the tracks' rectangles on the model chosen.

/// Paper B eqs 23–24, R: the mean Earth radius 6371.0088 km expressed in nautical miles
/// (1 nm = 1.852 km exactly), the sphere of the paper's own model.
pub const EARTH_RADIUS_NM: f64 = 3440.065;

/// Below this latitude difference (radians) `Δψ` is evaluated by the atanh difference
/// formula instead of `ψ(φ2) − ψ(φ1)`: 0.1 rad keeps the atanh argument below
/// `sin 0.1 / (…)`, far from 1 where atanh loses accuracy, while above it the plain
/// difference loses at most one bit to cancellation.
const DPSI_SMALL_DPHI: f64 = 0.1;

/// A point on the sphere, radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LonLat {
    /// Longitude λ, radians (not wrapped).
    pub lon: f64,
    /// Latitude φ, radians.
    pub lat: f64,
}

impl LonLat {
    /// A point from degrees `(lon, lat)`.
    pub fn from_degrees(lon: f64, lat: f64) -> Self {
        LonLat {
            lon: lon.to_radians(),
            lat: lat.to_radians(),
        }
    }
    /// `(lon, lat)` in degrees.
    pub fn to_degrees(self) -> (f64, f64) {
        (self.lon.to_degrees(), self.lat.to_degrees())
    }
}

/// A point of the Mercator plane (radians): `[x, y]`.
pub type Merc = [f64; 2];

/// Paper B eq 26: `ψ(φ) = ln tan(π/4 + φ/2)`, evaluated as `asinh(tan φ)` (the same
/// function, without the cancellation of `ln` near the equator).
pub fn mercator_y(lat: f64) -> f64 {
    lat.tan().asinh()
}

/// Paper B eqs 25–26: Mercator forward, `x = λ`, `y = ψ(φ)` (radians).
pub fn mercator(p: LonLat) -> Merc {
    [p.lon, mercator_y(p.lat)]
}

/// Paper B Algorithm 4 (inverse Mercator): `φ = 2 atan(tanh(y/2))`, evaluated as the
/// equivalent `atan(sinh y)` (inverse Gudermannian).
pub fn mercator_lat(y: f64) -> f64 {
    y.sinh().atan()
}

/// Paper B Algorithm 4: inverse Mercator, `λ = x`, `φ = gd(y)`.
pub fn inverse_mercator(m: Merc) -> LonLat {
    LonLat {
        lon: m[0],
        lat: mercator_lat(m[1]),
    }
}

/// Paper B eq 24 / Algorithm 4: `Δψ = ψ(φ2) − ψ(φ1)`. For small `Δφ` it uses
/// `atanh((sin φ2 − sin φ1)/(1 − sin φ1 sin φ2))` with both numerator and denominator
/// written without cancellation, so `Δψ` keeps full relative accuracy as `Δφ → 0`.
pub fn delta_psi(lat1: f64, lat2: f64) -> f64 {
    let dphi = lat2 - lat1;
    if dphi.abs() < DPSI_SMALL_DPHI {
        let half = 0.5 * dphi;
        let sh = half.sin();
        let num = 2.0 * (lat1 + half).cos() * sh;
        let den = 2.0 * sh * sh + lat1.cos() * lat2.cos();
        (num / den).atanh()
    } else {
        mercator_y(lat2) - mercator_y(lat1)
    }
}

/// Paper B Algorithm 4, `w`: the ratio `Δφ/Δψ` (the mean of `cos` in the sense of
/// eq 24), with its east–west limit `cos φ1` when `Δφ = 0`. Paper defect: eqs 24, 27 and
/// 29 write `tan θ · Δψ`, which is `∞ · 0` on east–west bearings; this ratio is the limit.
pub fn rhumb_q(lat1: f64, lat2: f64) -> f64 {
    let dphi = lat2 - lat1;
    if dphi == 0.0 {
        lat1.cos()
    } else {
        dphi / delta_psi(lat1, lat2)
    }
}

/// Paper B eq 24 read as a mean: `M(φ, h) = (ψ(φ+h) − ψ(φ))/h`, the mean of `sec` over
/// `[φ, φ+h]` (`sec φ` when `h = 0`); `1/rhumb_q`.
pub fn mean_sec(lat: f64, h: f64) -> f64 {
    // the step actually taken between the two f64 latitudes (a tiny `h` may vanish)
    let lat2 = lat + h;
    let dphi = lat2 - lat;
    if dphi == 0.0 {
        1.0 / lat.cos()
    } else {
        delta_psi(lat, lat2) / dphi
    }
}

/// Paper B eqs 23–24 (with the east–west limit): the point reached from `p` by a rhumb
/// line of bearing `bearing` (radians, clockwise from north) and length `dist_nm`.
/// `φ2 = φ1 + d cos θ / R`, `λ2 = λ1 + d sin θ / (R · Δφ/Δψ)`.
pub fn rhumb_destination(p: LonLat, bearing: f64, dist_nm: f64) -> LonLat {
    let dlat = dist_nm * bearing.cos() / EARTH_RADIUS_NM;
    let lat2 = p.lat + dlat;
    let q = rhumb_q(p.lat, lat2);
    LonLat {
        lon: p.lon + dist_nm * bearing.sin() / (EARTH_RADIUS_NM * q),
        lat: lat2,
    }
}

/// Paper B Algorithm 4 (distance part) and eq 24 inverted: rhumb-line distance (nm) and
/// bearing (radians) from `a` to `b`: `θ = atan2(Δλ, Δψ)`,
/// `d = R √(Δφ² + w² Δλ²)` with `w = Δφ/Δψ` (`cos φ` on east–west lines).
pub fn rhumb_inverse(a: LonLat, b: LonLat) -> (f64, f64) {
    let dlat = b.lat - a.lat;
    let dlon = b.lon - a.lon;
    let dpsi = delta_psi(a.lat, b.lat);
    let q = if dlat == 0.0 {
        a.lat.cos()
    } else {
        dlat / dpsi
    };
    (EARTH_RADIUS_NM * dlat.hypot(q * dlon), dlon.atan2(dpsi))
}

/// Paper B Algorithm 4 (distance part): the rhumb-line distance (nm) from `a` to `b`,
/// `R √(Δφ² + w² Δλ²)` with `w = Δφ/Δψ` (`cos φ` on east–west lines).
pub fn rhumb_distance(a: LonLat, b: LonLat) -> f64 {
    let dlat = b.lat - a.lat;
    let q = rhumb_q(a.lat, b.lat);
    EARTH_RADIUS_NM * dlat.hypot(q * (b.lon - a.lon))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::FRAC_PI_2;

    #[test]
    fn mercator_round_trip() {
        for d in [-84.0f64, -30.0, 0.0, 1e-9, 29.0, 60.0, 84.9] {
            let lat = d.to_radians();
            let back = mercator_lat(mercator_y(lat));
            assert!((back - lat).abs() <= 4.0 * f64::EPSILON * lat.abs().max(1e-300));
        }
    }

    #[test]
    fn delta_psi_agrees_with_difference() {
        for (a, b) in [(0.1, 0.3), (0.5, 0.5000001), (-0.2, 0.25), (1.0, 1.05)] {
            // the plain difference carries the absolute rounding error of ψ itself
            let direct = mercator_y(b) - mercator_y(a);
            let scale = mercator_y(a).abs().max(mercator_y(b).abs()).max(1.0);
            assert!((delta_psi(a, b) - direct).abs() <= 8.0 * f64::EPSILON * scale);
        }
    }

    #[test]
    fn east_west_destination_uses_the_limit() {
        let p = LonLat::from_degrees(39.0, 30.0);
        let q = rhumb_destination(p, FRAC_PI_2, 60.0);
        // 60 nm along a parallel at 30°: Δλ = 60 / (R cos 30°)
        let want = 60.0 / (EARTH_RADIUS_NM * 30f64.to_radians().cos());
        assert!((q.lon - p.lon - want).abs() < 1e-15);
        assert!((q.lat - p.lat).abs() < 1e-15);
    }

    #[test]
    fn rhumb_inverse_inverts_destination() {
        let p = LonLat::from_degrees(-30.0, 10.0);
        for b in [0.3f64, 1.2, 2.0, -2.5, FRAC_PI_2, -FRAC_PI_2] {
            let q = rhumb_destination(p, b, 75.0);
            let (d, th) = rhumb_inverse(p, q);
            assert!((d - 75.0).abs() < 1e-9, "{d}");
            assert!((th - b).abs() < 1e-9, "{th} {b}");
        }
    }
}
