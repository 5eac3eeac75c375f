//! Paper B Section V on two models of the Earth: the paper's sphere (the default) and the
//! WGS84 ellipsoid (`polyguard conflicts --geodesy wgs84`).
//!
//! Section V needs four things of the Earth: the Mercator projection (rhumb lines are
//! straight in it), rhumb lines of a given length, the motion of a point along one at a
//! constant speed, and Table 2's rectangle built from rhumb steps. On both models they
//! share one form, which [`crate::sphere::Leg`] evaluates once for either:
//!
//! - a *model latitude* `u` that changes linearly with the distance `d` along a rhumb line
//!   of bearing `θ`: `Δu = d cos θ / R_u`. On the sphere `u = φ` and `R_u = R`; on the
//!   ellipsoid `u = μ`, the rectifying latitude (`A·μ` is the meridian distance), and
//!   `R_u = A`, the rectifying radius;
//! - the Mercator ordinate as a function of it, `y = Ψ(u)`, with derivative `g(u) =
//!   dΨ/du`: `sec φ` on the sphere, `A / (N cos φ)` on the ellipsoid (`N` the prime
//!   vertical radius of curvature);
//! - along the line, `Δλ = tan θ · ΔΨ = (d sin θ / R_u) · M(u, Δu)`, with `M` the mean of
//!   `g` over the step (eq 24 read as a mean; its limit `g(u)` on east–west lines).
//!
//! **Bounds** (for stage 3's offset boxes and stage 4's speeds). On the ellipsoid `g` is
//! even and convex in `μ`, like `sec`, and `g ≤ (A/a) sec φ ≤ sec φ`,
//! `g' = (A/a)² sin φ (1 − e² sin² φ) / cos² φ ≤ sec φ tan φ` at the geodetic latitude
//! `φ(μ)`, which is at least `|μ|` in magnitude. So the sphere's bounds, taken with
//! `R_u = A` and with `sec`, `tan` at the geodetic latitude, hold on the ellipsoid.
//! (`d/dφ [sin φ (1 − e² sin² φ)/cos² φ] = (1 + (1 − 3e²) sin² φ + e² sin⁴ φ)/cos³ φ > 0`:
//! `g'` grows with `|φ|`, and `φ` with `μ`, so `g` is convex.)

use crate::rhumb::{self, LonLat, Merc, EARTH_RADIUS_NM};

/// The model of the Earth.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Geodesy {
    /// The paper's sphere of radius [`EARTH_RADIUS_NM`] (the default).
    #[default]
    Sphere,
    /// The WGS84 ellipsoid: rhumb lines, Mercator and distances on it.
    Wgs84,
}

/// WGS84 semi-major axis (m).
pub const WGS84_A_M: f64 = 6_378_137.0;
/// WGS84 flattening.
pub const WGS84_F: f64 = 1.0 / 298.257_223_563;
/// Metres in a nautical mile.
pub const METRES_PER_NM: f64 = 1852.0;

const E2: f64 = WGS84_F * (2.0 - WGS84_F);
/// Third flattening `n = f / (2 − f)`.
const N3: f64 = WGS84_F / (2.0 - WGS84_F);

/// `e`, the first eccentricity.
fn ecc() -> f64 {
    E2.sqrt()
}

/// The rectifying radius `A = a/(1+n) · (1 + n²/4 + n⁴/64)` (m): the meridian distance
/// from the equator is `A·μ`.
fn rectifying_radius_m() -> f64 {
    let n2 = N3 * N3;
    WGS84_A_M / (1.0 + N3) * (1.0 + n2 / 4.0 + n2 * n2 / 64.0)
}

/// The coefficients `h_j` of `μ = φ + Σ h_j sin 2jφ` (Helmert's series in `n`, to `n⁴`:
/// the meridian distance within `n⁵·A ≈ 0.1 mm`).
fn mu_coeffs() -> [f64; 4] {
    let n = N3;
    let (n2, n3, n4) = (n * n, n * n * n, n * n * n * n);
    [
        -1.5 * n + 9.0 / 16.0 * n3,
        15.0 / 16.0 * n2 - 15.0 / 32.0 * n4,
        -35.0 / 48.0 * n3,
        315.0 / 512.0 * n4,
    ]
}

/// Rectifying latitude `μ(φ)` (radians).
pub fn rectifying_lat(phi: f64) -> f64 {
    let h = mu_coeffs();
    phi + h
        .iter()
        .enumerate()
        .map(|(j, c)| c * (2.0 * (j + 1) as f64 * phi).sin())
        .sum::<f64>()
}

/// `μ(φ2) − μ(φ1)` without cancellation: `Δφ + Σ h_j · 2 cos(j(φ1+φ2)) sin(jΔφ)`.
pub fn delta_rectifying(phi1: f64, phi2: f64) -> f64 {
    let d = phi2 - phi1;
    let s = phi1 + phi2;
    let h = mu_coeffs();
    d + h
        .iter()
        .enumerate()
        .map(|(j, c)| {
            let j = (j + 1) as f64;
            c * 2.0 * (j * s).cos() * (j * d).sin()
        })
        .sum::<f64>()
}

/// Geodetic latitude of rectifying latitude `mu` (Newton on [`rectifying_lat`], from
/// the series' inverse's first term): `rectifying_lat(geodetic_of_rectifying(μ)) = μ` to
/// an ulp or two.
pub fn geodetic_of_rectifying(mu: f64) -> f64 {
    let mut phi = mu + 1.5 * N3 * (2.0 * mu).sin();
    for _ in 0..8 {
        // dμ/dφ = (1 − e²)/(1 − e² sin² φ)^{3/2} · a/A
        let s = phi.sin();
        let w = 1.0 - E2 * s * s;
        let deriv = (1.0 - E2) / (w * w.sqrt()) * (WGS84_A_M / rectifying_radius_m());
        let step = (rectifying_lat(phi) - mu) / deriv;
        phi -= step;
        if step.abs() <= 1e-17 * phi.abs().max(1e-300) {
            break;
        }
    }
    phi
}

/// Ellipsoidal isometric latitude (Mercator ordinate) `ψ(φ) = asinh(tan φ) − e·atanh(e sin φ)`.
pub fn isometric_lat(phi: f64) -> f64 {
    let e = ecc();
    phi.tan().asinh() - e * (e * phi.sin()).atanh()
}

/// Geodetic latitude of the isometric latitude `y` (fixed point `φ = atan(sinh(y +
/// e·atanh(e sin φ)))`, a contraction by about `e² ≈ 0.0067`).
pub fn geodetic_of_isometric(y: f64) -> f64 {
    let e = ecc();
    let mut phi = y.sinh().atan();
    for _ in 0..20 {
        let next = (y + e * (e * phi.sin()).atanh()).sinh().atan();
        if next == phi {
            break;
        }
        phi = next;
    }
    phi
}

/// `ψ(φ2) − ψ(φ1)` on the ellipsoid without cancellation for close latitudes.
fn delta_isometric(phi1: f64, phi2: f64) -> f64 {
    let e = ecc();
    let sphere = rhumb::delta_psi(phi1, phi2);
    // atanh(x2) − atanh(x1) = atanh((x2 − x1)/(1 − x1 x2)), x = e sin φ
    let half = 0.5 * (phi2 - phi1);
    let dsin = 2.0 * (phi1 + half).cos() * half.sin();
    let (x1, x2) = (e * phi1.sin(), e * phi2.sin());
    sphere - e * (e * dsin / (1.0 - x1 * x2)).atanh()
}

/// Steps at least this long (in `u`) take `M` as the plain quotient of differences (as
/// on the sphere: `crate::sphere`'s `FAST_MEAN_SEC_MIN_H`).
const FAST_MEAN_MIN_H: f64 = 1e-3;

impl Geodesy {
    /// The name in answers and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Geodesy::Sphere => "sphere",
            Geodesy::Wgs84 => "wgs84",
        }
    }

    /// `R_u` (nm): the sphere's radius, or the ellipsoid's rectifying radius `A`.
    pub fn radius_nm(self) -> f64 {
        match self {
            Geodesy::Sphere => EARTH_RADIUS_NM,
            Geodesy::Wgs84 => rectifying_radius_m() / METRES_PER_NM,
        }
    }

    /// The model latitude `u` of the geodetic latitude `lat`.
    pub fn u_of_lat(self, lat: f64) -> f64 {
        match self {
            Geodesy::Sphere => lat,
            Geodesy::Wgs84 => rectifying_lat(lat),
        }
    }

    /// The geodetic latitude of the model latitude `u`.
    pub fn lat_of_u(self, u: f64) -> f64 {
        match self {
            Geodesy::Sphere => u,
            Geodesy::Wgs84 => geodetic_of_rectifying(u),
        }
    }

    /// Mercator ordinate `y` of the geodetic latitude `lat` (paper B eq 26 on this model).
    pub fn mercator_y(self, lat: f64) -> f64 {
        match self {
            Geodesy::Sphere => rhumb::mercator_y(lat),
            Geodesy::Wgs84 => isometric_lat(lat),
        }
    }

    /// Paper B eqs 25–26 on this model.
    pub fn mercator(self, p: LonLat) -> Merc {
        [p.lon, self.mercator_y(p.lat)]
    }

    /// Paper B Algorithm 4's inverse Mercator on this model.
    pub fn inverse_mercator(self, m: Merc) -> LonLat {
        LonLat {
            lon: m[0],
            lat: match self {
                Geodesy::Sphere => rhumb::mercator_lat(m[1]),
                Geodesy::Wgs84 => geodetic_of_isometric(m[1]),
            },
        }
    }

    /// `Ψ(u)`: the Mercator ordinate of the point at model latitude `u`.
    pub fn psi_of_u(self, u: f64) -> f64 {
        self.mercator_y(self.lat_of_u(u))
    }

    /// `g(u) = dΨ/du`: `sec φ`, or `A/(N cos φ) = (A/a)·√(1 − e² sin² φ)/cos φ`.
    pub fn g(self, u: f64) -> f64 {
        match self {
            Geodesy::Sphere => 1.0 / u.cos(),
            Geodesy::Wgs84 => {
                let phi = geodetic_of_rectifying(u);
                let s = phi.sin();
                rectifying_radius_m() / WGS84_A_M * (1.0 - E2 * s * s).sqrt() / phi.cos()
            }
        }
    }

    /// `M(u, h)`: the mean of `g` over `[u, u + h]` (over the step actually taken between
    /// the two f64 model latitudes; `g(u)` when it is 0), without cancellation for short
    /// steps. On the sphere, [`rhumb::mean_sec`].
    pub fn mean_g(self, u: f64, h: f64) -> f64 {
        match self {
            Geodesy::Sphere => rhumb::mean_sec(u, h),
            Geodesy::Wgs84 => {
                let u2 = u + h;
                let du = u2 - u;
                if du == 0.0 {
                    return self.g(u);
                }
                let (p1, p2) = (geodetic_of_rectifying(u), geodetic_of_rectifying(u2));
                if du.abs() >= FAST_MEAN_MIN_H {
                    (isometric_lat(p2) - isometric_lat(p1)) / du
                } else {
                    delta_isometric(p1, p2) / delta_rectifying(p1, p2)
                }
            }
        }
    }

    /// `(sec Φ, tan Φ)` at the geodetic latitude `Φ` of the model latitude `|u|`: bounds on
    /// `g` and `g'` wherever the model latitude is at most `|u|` in magnitude (module doc).
    pub fn sec_tan_bound(self, u_abs: f64) -> (f64, f64) {
        let phi = self.lat_of_u(u_abs.abs());
        (1.0 / phi.cos(), phi.tan())
    }

    /// The range of `g` over model latitudes in `[lo, hi]` (`g` is even and grows with
    /// `|u|`): its value at the latitude nearest the equator and at the farthest.
    pub fn g_range(self, lo: f64, hi: f64) -> (f64, f64) {
        let far = lo.abs().max(hi.abs());
        let near = if lo <= 0.0 && hi >= 0.0 {
            0.0
        } else {
            lo.abs().min(hi.abs())
        };
        (self.g(near), self.g(far))
    }

    /// `Ψ(φ2) − Ψ(φ1)` of geodetic latitudes, without cancellation for close ones.
    pub fn delta_psi(self, lat1: f64, lat2: f64) -> f64 {
        match self {
            Geodesy::Sphere => rhumb::delta_psi(lat1, lat2),
            Geodesy::Wgs84 => delta_isometric(lat1, lat2),
        }
    }

    /// Paper B eqs 23–24 on this model: the point reached from `p` along a rhumb line of
    /// bearing `bearing` (radians from north, clockwise) and length `dist_nm`.
    pub fn rhumb_destination(self, p: LonLat, bearing: f64, dist_nm: f64) -> LonLat {
        match self {
            Geodesy::Sphere => rhumb::rhumb_destination(p, bearing, dist_nm),
            Geodesy::Wgs84 => {
                let r = self.radius_nm();
                let u1 = rectifying_lat(p.lat);
                let h = dist_nm * bearing.cos() / r;
                let u2 = u1 + h;
                let lat2 = if u2 == u1 {
                    p.lat
                } else {
                    geodetic_of_rectifying(u2)
                };
                LonLat {
                    lon: p.lon + dist_nm * bearing.sin() / r * self.mean_g(u1, h),
                    lat: lat2,
                }
            }
        }
    }

    /// Rhumb-line distance (nm) and bearing (radians) from `a` to `b` on this model:
    /// `θ = atan2(Δλ, ΔΨ)`, `d = R_u·√(Δu² + (Δλ/M)²)` with `M = ΔΨ/Δu` (`g(u)` on
    /// east–west lines).
    pub fn rhumb_inverse(self, a: LonLat, b: LonLat) -> (f64, f64) {
        match self {
            Geodesy::Sphere => rhumb::rhumb_inverse(a, b),
            Geodesy::Wgs84 => {
                let dlon = b.lon - a.lon;
                let dpsi = delta_isometric(a.lat, b.lat);
                let du = if a.lat == b.lat {
                    0.0
                } else {
                    delta_rectifying(a.lat, b.lat)
                };
                let m = if du == 0.0 {
                    self.g(rectifying_lat(a.lat))
                } else {
                    dpsi / du
                };
                (self.radius_nm() * du.hypot(dlon / m), dlon.atan2(dpsi))
            }
        }
    }

    /// The rhumb-line distance (nm) from `a` to `b` on this model.
    pub fn rhumb_distance(self, a: LonLat, b: LonLat) -> f64 {
        self.rhumb_inverse(a, b).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The meridian distance by Simpson's rule on `a(1 − e²)/(1 − e² sin² φ)^{3/2}`.
    fn meridian_simpson(phi: f64) -> f64 {
        let n = 20_000;
        let h = phi / n as f64;
        let f = |x: f64| {
            let s = x.sin();
            WGS84_A_M * (1.0 - E2) / (1.0 - E2 * s * s).powf(1.5)
        };
        let mut sum = f(0.0) + f(phi);
        for i in 1..n {
            sum += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        sum * h / 3.0
    }

    #[test]
    fn rectifying_latitude_is_the_meridian_distance() {
        for d in [1.0f64, 15.0, 29.0, 45.0, 60.0, 80.0, 89.0] {
            let phi = d.to_radians();
            let m = rectifying_radius_m() * rectifying_lat(phi);
            // 0.1 mm: the series' truncation (n⁵·A) and Simpson's error
            assert!((m - meridian_simpson(phi)).abs() < 1e-4, "{d}°: {m}");
        }
        // the quarter meridian, a known value (m)
        let q = rectifying_radius_m() * std::f64::consts::FRAC_PI_2;
        assert!((q - 10_001_965.729).abs() < 1e-3, "{q}");
    }

    #[test]
    fn inverses_round_trip() {
        for d in [-84.0f64, -30.0, -1e-7, 0.0, 1e-9, 29.0, 60.0, 84.9] {
            let phi = d.to_radians();
            let back = geodetic_of_rectifying(rectifying_lat(phi));
            assert!((back - phi).abs() <= 4.0 * f64::EPSILON * phi.abs().max(1e-300));
            let back = geodetic_of_isometric(isometric_lat(phi));
            assert!((back - phi).abs() <= 4.0 * f64::EPSILON * phi.abs().max(1e-300));
        }
    }

    #[test]
    fn differences_agree_with_plain_ones() {
        for (a, b) in [(0.1, 0.3), (0.5, 0.5000001), (-0.2, 0.25), (1.0, 1.05)] {
            let plain = rectifying_lat(b) - rectifying_lat(a);
            assert!((delta_rectifying(a, b) - plain).abs() <= 8.0 * f64::EPSILON);
            let plain = isometric_lat(b) - isometric_lat(a);
            assert!((delta_isometric(a, b) - plain).abs() <= 16.0 * f64::EPSILON);
        }
    }

    #[test]
    fn mean_g_is_the_mean_of_g() {
        let geo = Geodesy::Wgs84;
        for u in [-1.2f64, -0.3, 0.0, 0.2, 0.9, 1.3] {
            for h in [1e-9f64, 1e-5, 2e-3, -0.05, 0.1] {
                // Simpson on g over the step
                let n = 2000;
                let mut s = geo.g(u) + geo.g(u + h);
                for i in 1..n {
                    s += geo.g(u + h * i as f64 / n as f64) * if i % 2 == 1 { 4.0 } else { 2.0 };
                }
                let want = s / (3.0 * n as f64);
                let got = geo.mean_g(u, h);
                assert!(
                    (got - want).abs() <= 1e-10 * want,
                    "u {u} h {h}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn the_ellipsoid_bounds_g_and_its_derivative_by_the_sphere_s() {
        let geo = Geodesy::Wgs84;
        for i in 0..=170 {
            let u = (i as f64 * 0.5f64).to_radians().min(1.5);
            let (sec, tan) = geo.sec_tan_bound(u);
            assert!(geo.g(u) <= sec && geo.g(-u) <= sec);
            let h = 1e-6;
            let dg = (geo.g(u + h) - geo.g(u - h)) / (2.0 * h);
            assert!(
                dg <= sec * tan * (1.0 + 1e-6) + 1e-9,
                "{u}: {dg} vs {}",
                sec * tan
            );
            assert!(dg >= -1e-9, "g grows with |u|");
        }
    }

    #[test]
    fn rhumb_lines_round_trip_and_match_the_sphere_s_shape() {
        let geo = Geodesy::Wgs84;
        let p = LonLat::from_degrees(39.0, 29.0);
        for (b, d) in [
            (0.3f64, 120.0),
            (1.2, 80.0),
            (std::f64::consts::FRAC_PI_2, 60.0),
            (3.0, 500.0),
            (-2.0, 5.0),
        ] {
            let q = geo.rhumb_destination(p, b, d);
            let (d2, b2) = geo.rhumb_inverse(p, q);
            assert!((d2 - d).abs() < 1e-9 * d, "{d} vs {d2}");
            let db = (b2 - b).rem_euclid(std::f64::consts::TAU);
            assert!(db.min(std::f64::consts::TAU - db) < 1e-12, "{b} vs {b2}");
            // the same line on the sphere is within 0.7 % of it (the models' radii)
            let (ds, _) = rhumb::rhumb_inverse(p, q);
            assert!((ds / d - 1.0).abs() < 7e-3, "{ds} vs {d}");
        }
        // a meridian: the length is the meridian distance
        let q = LonLat::from_degrees(39.0, 31.0);
        let (d, b) = geo.rhumb_inverse(p, q);
        let want = (meridian_simpson(q.lat) - meridian_simpson(p.lat)) / METRES_PER_NM;
        assert!((d - want).abs() < 1e-6 && b.abs() < 1e-15, "{d} vs {want}");
    }
}
