//! Paper B Section V in MPFR (rug) at [`PREC`] bits: the reference for the engine's
//! Mercator (eqs 25–26), rhumb motion (eqs 23–24, 27–28) and `track_time` (Algorithm 4).
//!
//! Inputs are f64 values taken exactly; the sphere radius is the f64 nearest to
//! 3440.065 nm, the same constant the engine uses, so a comparison measures the engine's
//! rounding alone. Written from the paper's equations, independent of the engine.

use rug::float::Constant;
pub use rug::Float;

/// Working precision (bits): at least 200 for a reference; 256 leaves ~200 bits after the
/// worst cancellation met here (`ψ(φ2) − ψ(φ1)` for latitudes 1e-15 rad apart).
pub const PREC: u32 = 256;

/// Paper B eqs 23–24, R (nm): the f64 the engine uses.
pub const EARTH_RADIUS_NM: f64 = 3440.065;

fn f(x: f64) -> Float {
    Float::with_val(PREC, x)
}

/// Paper B eq 26: `ψ(φ) = ln tan(π/4 + φ/2)`, evaluated as written.
pub fn mercator_y(lat: f64) -> Float {
    let pi4 = Float::with_val(PREC, Constant::Pi) / 4u32;
    let half = f(lat) / 2u32;
    let arg = Float::with_val(PREC, &pi4 + &half).tan();
    arg.ln()
}

/// Paper B Algorithm 4: inverse Mercator `φ = 2 atan(tanh(y/2))`, evaluated as written.
pub fn mercator_lat(y: f64) -> Float {
    let h = (f(y) / 2u32).tanh();
    h.atan() * 2u32
}

fn psi(lat: &Float) -> Float {
    let pi4 = Float::with_val(PREC, Constant::Pi) / 4u32;
    let half = Float::with_val(PREC, lat / 2u32);
    Float::with_val(PREC, &pi4 + &half).tan().ln()
}

/// Paper B eqs 23–24: rhumb destination `(λ, φ)` from `(lon, lat)` at `bearing` (radians)
/// after `dist_nm`, with the east–west limit `Δλ = d sin θ / (R cos φ)` when `Δφ = 0`.
pub fn rhumb_destination(lon: f64, lat: f64, bearing: f64, dist_nm: f64) -> (Float, Float) {
    let r = f(EARTH_RADIUS_NM);
    let d = f(dist_nm);
    let b = f(bearing);
    let dlat = Float::with_val(PREC, &d * &b.clone().cos()) / &r;
    let lat1 = f(lat);
    let lat2 = Float::with_val(PREC, &lat1 + &dlat);
    let dlon = if dlat.is_zero() {
        let cos = lat1.clone().cos();
        Float::with_val(PREC, &d * &b.sin()) / (r * cos)
    } else {
        // tan θ · Δψ = (d sin θ / R) · Δψ / Δφ
        let dpsi = psi(&lat2) - psi(&lat1);
        Float::with_val(PREC, &d * &b.sin()) / r * dpsi / dlat
    };
    (Float::with_val(PREC, f(lon) + dlon), lat2)
}

/// Paper B Algorithm 4's distance and eq 24's bearing: rhumb distance (nm) and bearing
/// from `a = (lon, lat)` to `b`.
pub fn rhumb_inverse(a: (f64, f64), b: (f64, f64)) -> (Float, Float) {
    let (la, pa) = (f(a.0), f(a.1));
    let (lb, pb) = (f(b.0), f(b.1));
    let dlat = Float::with_val(PREC, &pb - &pa);
    let dlon = Float::with_val(PREC, &lb - &la);
    let dpsi = psi(&pb) - psi(&pa);
    let w = if dlat.is_zero() {
        pa.cos()
    } else {
        Float::with_val(PREC, &dlat / &dpsi)
    };
    let wl = Float::with_val(PREC, &w * &dlon);
    let dist = dlat.hypot(&wl) * f(EARTH_RADIUS_NM);
    let bearing = dlon.atan2(&dpsi);
    (dist, bearing)
}

/// Paper B Algorithm 4 with `R` and `t0` restored: the time at which the reference point of
/// a leg from `start` to `end` (lon, lat radians), leaving at `t0` with `speed_kn`, is at
/// fraction `rho` of its Mercator segment.
pub fn track_time(start: (f64, f64), end: (f64, f64), speed_kn: f64, t0: f64, rho: f64) -> Float {
    let y0 = psi(&f(start.1));
    let y1 = psi(&f(end.1));
    let rho_f = f(rho);
    let qx = f(start.0) + Float::with_val(PREC, &rho_f * &(f(end.0) - f(start.0)));
    let qy = Float::with_val(PREC, &y0 + &Float::with_val(PREC, &rho_f * &(y1 - &y0)));
    // inverse Mercator of q, exactly as Algorithm 4 writes it
    let qlat = (qy / 2u32).tanh().atan() * 2u32;
    let (la, pa) = (f(start.0), f(start.1));
    let dlat = Float::with_val(PREC, &qlat - &pa);
    let dlon = Float::with_val(PREC, &qx - &la);
    let dpsi = psi(&qlat) - psi(&pa);
    // East–west legs: `q_y = y0` exactly, but `gd(q_y)` carries the 2⁻²⁵⁶-level rounding
    // of this precision, so `Δφ`, `Δψ` are rounding noise; below 2⁻²⁰⁰ take the limit.
    let w = if dlat.is_zero()
        || dpsi.is_zero()
        || dlat.clone().abs() < Float::with_val(PREC, Float::i_exp(1, -200))
    {
        pa.cos()
    } else {
        Float::with_val(PREC, &dlat / &dpsi)
    };
    let wl = Float::with_val(PREC, &w * &dlon);
    let d = dlat.hypot(&wl) * f(EARTH_RADIUS_NM);
    let signed = if rho < 0.0 { -d } else { d };
    f(t0) + signed / f(speed_kn)
}

/// [`rhumb_destination`] from a point given in MPFR.
fn destination(lon: &Float, lat: &Float, bearing: f64, dist_nm: f64) -> (Float, Float) {
    let r = f(EARTH_RADIUS_NM);
    let d = f(dist_nm);
    let b = f(bearing);
    let dlat = Float::with_val(PREC, &d * &b.clone().cos()) / &r;
    let lat2 = Float::with_val(PREC, lat + &dlat);
    let dlon = if dlat.is_zero() {
        Float::with_val(PREC, &d * &b.sin()) / (r * lat.clone().cos())
    } else {
        let dpsi = psi(&lat2) - psi(lat);
        Float::with_val(PREC, &d * &b.sin()) / r * dpsi / dlat
    };
    (Float::with_val(PREC, lon + &dlon), lat2)
}

/// Paper B eqs 23–30 and Table 2 in MPFR on the sphere: the Mercator vertices (ring
/// order) of a leg's rectangle at `t` (clamped to the leg's life), from the leg's f64
/// parameters taken exactly: its start, bearing, speed, `t0` and Table 2 steps. The
/// reference point is `speed·(t − t0)` along the rhumb line from the start; each vertex
/// two rhumb steps from it. `None` for a leg on another model than the sphere.
pub fn leg_merc_vertices(leg: &crate::sphere::Leg, t: f64) -> Option<[(Float, Float); 4]> {
    if leg.geo != crate::geodesy::Geodesy::Sphere {
        return None;
    }
    let t = t.clamp(leg.t0, leg.t1);
    let dist = Float::with_val(PREC, f(t) - f(leg.t0)) * f(leg.speed_kn);
    // the distance is exact in MPFR; `destination` takes it as an f64, so the reference
    // point is reached in two steps whose sum is that distance exactly
    let d_hi = dist.to_f64();
    let d_lo = Float::with_val(PREC, &dist - d_hi).to_f64();
    let (lon, lat) = destination(&f(leg.start.lon), &f(leg.start.lat), leg.bearing, d_hi);
    let (lon, lat) = destination(&lon, &lat, leg.bearing, d_lo);
    Some(leg.steps.map(|steps| {
        let (mut x, mut y) = (lon.clone(), lat.clone());
        for (d, b) in steps {
            let (x2, y2) = destination(&x, &y, b, d);
            x = x2;
            y = y2;
        }
        let py = psi(&y);
        (x, py)
    }))
}

/// The largest distance (Mercator radians) between [`crate::sphere::Leg::merc_vertices_at`]
/// and [`leg_merc_vertices`] at `t`: the f64 model's rounding, which
/// [`crate::sphere::position_slack`] claims below `2⁻⁴⁴·max(c, 4)` per evaluation.
pub fn leg_vertex_error(leg: &crate::sphere::Leg, t: f64) -> Option<f64> {
    let exact = leg_merc_vertices(leg, t)?;
    let got = leg.merc_vertices_at(t);
    Some(
        got.iter()
            .zip(exact.iter())
            .map(|(g, (x, y))| {
                let dx = Float::with_val(PREC, g[0] - x).to_f64();
                let dy = Float::with_val(PREC, g[1] - y).to_f64();
                dx.hypot(dy)
            })
            .fold(0f64, f64::max),
    )
}

/// The spacing of f64 values at `|x|` (2⁻¹⁰⁷⁴ below the normal range).
pub fn ulp(x: f64) -> f64 {
    let x = x.abs();
    if x < f64::MIN_POSITIVE {
        return f64::from_bits(1);
    }
    // exponent from the bits: exact, unlike log2
    let e = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(e - 52)
}

/// Error of an f64 `engine` value against `reference`, in ulps of
/// `max(|reference|, scale)` (`scale` for results that may cancel to near zero).
pub fn error_ulps(engine: f64, reference: &Float, scale: f64) -> f64 {
    let diff = Float::with_val(PREC, engine - reference);
    diff.abs().to_f64() / ulp(reference.to_f64().abs().max(scale))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mercator_round_trip() {
        let y = mercator_y(0.5);
        let back = mercator_lat(y.to_f64());
        assert!((back.to_f64() - 0.5).abs() < 1e-15);
    }

    #[test]
    fn east_west_limit() {
        let (lon, lat) = rhumb_destination(0.0, 0.5, core::f64::consts::FRAC_PI_2, 60.0);
        let want = 60.0 / (EARTH_RADIUS_NM * 0.5f64.cos());
        assert!((lon.to_f64() - want).abs() < 1e-15);
        assert!((lat.to_f64() - 0.5).abs() < 1e-15);
    }
}
