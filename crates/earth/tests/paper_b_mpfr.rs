//! Paper B Section V: the engine's Mercator, rhumb and `track_time` against the MPFR
//! reference (`polyguard_earth::reference::mpfr`, 256 bits), in ulps.
//!
//! Run with `cargo test -p polyguard-earth --features rug --test paper_b_mpfr`; scale the number of random
//! inputs with `POLYGUARD_PROPTEST_CASES` (default 2000 per function).
//!
//! Stated bounds: the measured maxima over 10⁵ inputs each (mercator_y 1.99,
//! mercator_lat 1.93, destination lat 2.62 / lon 8.25, inverse distance 7.19 / bearing
//! 4.84, track_time 2.87 in its units), doubled and rounded up to a power of two. The ulp is
//! that of the reference value, or of the named scale when the result can cancel to near
//! zero (a longitude or latitude after a step: the ulp of the larger of start and result).
#![cfg(feature = "rug")]

use polyguard_earth::reference::mpfr as mp;
use polyguard_earth::sphere::{self, LonLat, RectDims};

/// Mercator forward `ψ(φ) = asinh(tan φ)` vs `ln tan(π/4 + φ/2)`.
const MERCATOR_Y_ULPS: f64 = 4.0;
/// Mercator inverse `atan(sinh y)` vs `2 atan(tanh(y/2))`.
const MERCATOR_LAT_ULPS: f64 = 4.0;
/// Rhumb destination, latitude and longitude.
const DESTINATION_ULPS: f64 = 16.0;
/// Rhumb inverse: distance and bearing.
const INVERSE_ULPS: f64 = 16.0;
/// `track_time` (Algorithm 4, fixed). The algorithm is conditioned by its own first step:
/// the point `q_m = c_m(t0) + ρ Δc_m` is rounded to ulp(|c_m|), which moves the time by up
/// to `ulp(|c_m|) · (tf − t0) / |Δc_m|`. The bound is this many such units plus this many
/// ulps of `t`.
const TRACK_TIME_ULPS: f64 = 8.0;

fn cases() -> usize {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000)
}

use mp::error_ulps as ulps;
use polyguard_harness::gen::{Source, SplitMix};

struct Max(&'static str, f64);
impl Max {
    fn see(&mut self, e: f64, ctx: impl FnOnce() -> String, bound: f64) {
        assert!(e <= bound, "{}: {e} ulps > {bound} at {}", self.0, ctx());
        self.1 = self.1.max(e);
    }
}
impl Drop for Max {
    fn drop(&mut self) {
        eprintln!("{}: max {} ulps", self.0, self.1);
    }
}

#[test]
fn mercator_forward_and_inverse() {
    let mut r = SplitMix(1);
    let (mut fy, mut fl) = (Max("mercator_y", 0.0), Max("mercator_lat", 0.0));
    for _ in 0..cases() {
        let lat = r.range(-85.0, 85.0).to_radians();
        fy.see(
            ulps(sphere::mercator_y(lat), &mp::mercator_y(lat), 0.0),
            || format!("{lat}"),
            MERCATOR_Y_ULPS,
        );
        let y = r.range(-3.1, 3.1);
        fl.see(
            ulps(sphere::mercator_lat(y), &mp::mercator_lat(y), 0.0),
            || format!("{y}"),
            MERCATOR_LAT_ULPS,
        );
    }
}

#[test]
fn rhumb_destination_and_inverse() {
    let mut r = SplitMix(2);
    let (mut dlat, mut dlon) = (Max("destination lat", 0.0), Max("destination lon", 0.0));
    let (mut idist, mut ibrg) = (Max("inverse distance", 0.0), Max("inverse bearing", 0.0));
    for k in 0..cases() {
        let p = LonLat::from_degrees(r.range(-60.0, 60.0), r.range(-70.0, 70.0));
        // every 8th bearing exactly east or west (the limit of eqs 24/27/29)
        let b = match k % 8 {
            0 => core::f64::consts::FRAC_PI_2,
            4 => -core::f64::consts::FRAC_PI_2,
            _ => r.range(-core::f64::consts::PI, core::f64::consts::PI),
        };
        let d = r.range(0.5, 300.0);
        let q = sphere::rhumb_destination(p, b, d);
        let (mlon, mlat) = mp::rhumb_destination(p.lon, p.lat, b, d);
        let ctx = || format!("{p:?} {b} {d}");
        dlat.see(ulps(q.lat, &mlat, p.lat.abs()), ctx, DESTINATION_ULPS);
        dlon.see(ulps(q.lon, &mlon, p.lon.abs()), ctx, DESTINATION_ULPS);
        let (dist, brg) = sphere::rhumb_inverse(p, q);
        let (mdist, mbrg) = mp::rhumb_inverse((p.lon, p.lat), (q.lon, q.lat));
        idist.see(ulps(dist, &mdist, 0.0), ctx, INVERSE_ULPS);
        ibrg.see(ulps(brg, &mbrg, 0.0), ctx, INVERSE_ULPS);
    }
}

#[test]
fn track_time_algorithm4() {
    let mut r = SplitMix(3);
    let mut m = Max("track_time", 0.0);
    let dims = RectDims {
        front: 10.0,
        back: 10.0,
        side: 10.0,
    };
    for k in 0..cases() {
        let a = LonLat::from_degrees(r.range(-60.0, 60.0), r.range(-70.0, 70.0));
        let b = if k % 8 == 0 {
            LonLat {
                lon: a.lon + r.range(0.01, 0.05),
                lat: a.lat,
            }
        } else {
            sphere::rhumb_destination(
                a,
                r.range(-core::f64::consts::PI, core::f64::consts::PI),
                r.range(20.0, 200.0),
            )
        };
        let leg = sphere::Leg::new(a, b, 15.0, 0.0, dims);
        let rho = r.range(0.05, 1.0);
        let t = leg.track_time(rho);
        let mt = mp::track_time((a.lon, a.lat), (b.lon, b.lat), 15.0, 0.0, rho);
        let [c0, c1] = leg.merc;
        let cmax = c0.iter().chain(c1.iter()).fold(0f64, |m, v| m.max(v.abs()));
        let dc = (c1[0] - c0[0]).hypot(c1[1] - c0[1]);
        let unit = mp::ulp(cmax) * (leg.t1 - leg.t0) / dc + mp::ulp(t);
        let err = ulps(t, &mt, 0.0) * mp::ulp(mt.to_f64());
        m.see(err / unit, || format!("{a:?} {b:?} {rho}"), TRACK_TIME_ULPS);
    }
}

/// `position_slack`'s claim: one f64 evaluation of a leg's rectangle
/// (`merc_vertices_at`) lies within 2⁻⁴⁴·max(c, 4) of the MPFR one (c the largest
/// coordinate), on legs at latitudes up to 84°, every bearing (a quarter cardinal),
/// rectangles of 0.01–50 nm, at nine instants each. In units of that bound.
#[test]
fn leg_vertices_within_the_position_slack() {
    use polyguard_earth::sphere::Leg;
    let mut worst = Max("merc_vertices_at vs MPFR (units of 2^-44 max(c, 4))", 0.0);
    let mut g = SplitMix(0x2545_f491_4f6c_dd1d);
    let mut n = 0;
    while n < cases() / 4 {
        let start = LonLat::from_degrees(g.range(-179.0, 179.0), g.range(-80.0, 80.0));
        let bearing = if g.below(4) == 0 {
            g.below(4) as f64 * std::f64::consts::FRAC_PI_2
        } else {
            g.range(0.0, std::f64::consts::TAU)
        };
        let end = sphere::rhumb_destination(start, bearing, 10f64.powf(g.range(0.0, 3.0)));
        if end.lat.abs() > 84f64.to_radians() {
            continue;
        }
        n += 1;
        let mut size = || 10f64.powf(g.range(-2.0, 1.7));
        let dims = RectDims {
            front: size(),
            back: size(),
            side: size(),
        };
        let leg = Leg::new(start, end, g.range(1.0, 500.0), g.range(-5.0, 5.0), dims);
        for i in 0..=8 {
            let t = leg.t0 + (leg.t1 - leg.t0) * i as f64 / 8.0;
            let c = leg
                .merc_vertices_at(t)
                .iter()
                .fold(4f64, |c, p| c.max(p[0].abs()).max(p[1].abs()));
            let err = mp::leg_vertex_error(&leg, t).expect("a sphere leg");
            worst.see(err / (c * 2f64.powi(-44)), || format!("{leg:?} t {t}"), 1.0);
        }
    }
}
