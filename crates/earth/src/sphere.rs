//! Paper B, Section V: a track's rectangle of Table 2 moving along rhumb lines, on the
//! model of the Earth [`crate::geodesy::Geodesy`] names (the paper's sphere by default).
//!
//! Conventions (all internal quantities):
//! * longitudes/latitudes in **radians** ([`LonLat`]); the scenario file speaks degrees;
//! * the Mercator plane in radians: `x = λ`, `y = ψ(φ)` (eqs 25–26). Paper defect: a
//!   Mercator plane with `x` in degrees and `y` in radians is not conformal, rhumb lines
//!   are still straight but the rectangles are distorted and true conflicts are rejected;
//! * distances in nautical miles, speeds in knots, times in hours;
//! * the sphere's points, Mercator plane and rhumb lines are [`crate::rhumb`]'s,
//!   re-exported here.
//!
//! Longitudes are not wrapped: the Mercator plane is the unrolled strip, so a track may
//! run past ±180° (the scaling generator relies on this; see `cli::generate`).

use crate::geodesy::Geodesy;
pub use crate::rhumb::{
    delta_psi, inverse_mercator, mean_sec, mercator, mercator_lat, mercator_y, rhumb_destination,
    rhumb_distance, rhumb_inverse, rhumb_q, LonLat, Merc, EARTH_RADIUS_NM,
};
use core::f64::consts::{FRAC_PI_2, PI};

/// Smallest latitude step (radians) for which [`Leg::merc_vertices_at`] takes the mean of
/// sec as the plain quotient `(ψ(φ+h) − ψ(φ))/h`: with |ψ| ≤ 3.2 (|φ| ≤ 85°) the
/// difference carries ≤ 2 ulp(3.2) ≈ 9e-16 absolute error, ≤ 1e-12 relative for
/// |h| ≥ 1e-3, i.e. ≤ 1e-14 rad on a vertex offset of ≤ 0.01 rad (≈ 60 nm). Smaller steps
/// use the cancellation-free [`mean_sec`].
const FAST_MEAN_SEC_MIN_H: f64 = 1e-3;

/// Relative safety factor applied to derived speed bounds so that the rounding of the
/// few f64 operations that evaluate them (a dozen, each ≤ 2⁻⁵³ relative) can never make a
/// bound too small: 1e-9 ≫ 12 · 2⁻⁵³ ≈ 1.3e-15.
pub const BOUND_SAFETY: f64 = 1.0 + 1e-9;

/// Paper B Section V, eqs 23–30 in f64: a bound on how far two evaluations of one vertex
/// may lie apart in the Mercator plane, for coordinates of magnitude at most `c`:
/// `2⁻⁴⁰·max(c, 4)` (≈ 3.6e-12 rad, 2 cm on the Earth, for |x| ≤ 4).
///
/// [`Leg::merc_vertices_at`] is a chain of about 20 operations whose rounding is
/// amplified at most by `sec φ ≤ 57` (latitudes ≤ 89°, the rectangles' limit): ≤ 2⁻⁴⁴·c
/// per evaluation. Two evaluations at one instant (the truth's and the pipeline's), or an
/// evaluation and the linear extrapolation `p(t_ref) + v·(t − t_ref)` of an east–west leg
/// (whose exact motion is linear; `v·s` carries ≤ 2⁻⁵²·|Δlon| ≤ 2⁻⁵¹·c), differ by less
/// than 2⁻⁴³·c; the bound leaves 8× over it, and also covers a whole-turn shift (one
/// addition, ≤ 2⁻⁵³·c) and the f64 vertex–edge distance's rounding (≤ 2⁻⁴⁸·c).
pub fn position_slack(c: f64) -> f64 {
    c.max(4.0) * 2f64.powi(-40)
}

/// Paper B Table 2: front, back and side distances (nm) of a track's rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RectDims {
    /// `d_f`: reference point to the front edge.
    pub front: f64,
    /// `d_b`: reference point to the back edge.
    pub back: f64,
    /// `d_s`: reference point to each side edge.
    pub side: f64,
}

/// Paper B Table 2: the two rhumb steps `(d, ψ)` to each vertex, in **ring order**
/// 1-2-4-3. Paper defect: taking the table's rows 1-2-3-4 as a ring gives a bow-tie
/// (1 and 2 are the front corners, 3 and 4 the back ones, both listed right then left).
pub fn table2_steps(dims: RectDims, bearing: f64) -> [[(f64, f64); 2]; 4] {
    let right = (dims.side, bearing + FRAC_PI_2);
    let left = (dims.side, bearing - FRAC_PI_2);
    let front = (dims.front, bearing);
    let back = (dims.back, bearing + PI);
    [
        [front, right], // vertex 1
        [front, left],  // vertex 2
        [back, left],   // vertex 4
        [back, right],  // vertex 3
    ]
}

/// Paper B eqs 29–30: a vertex reached from the reference point `c` (at the *current*
/// time: the paper's eq 29 writes `c_x(t0)`, a typo for `c_x(t)`) by successive rhumb steps.
pub fn vertex_by_steps(c: LonLat, steps: &[(f64, f64)]) -> LonLat {
    steps
        .iter()
        .fold(c, |p, &(d, psi)| rhumb_destination(p, psi, d))
}

/// Paper B Section V, eqs 23–30 and Algorithm 4: one straight Mercator segment of a track,
/// the rectangle's reference point moving at constant speed along one rhumb line.
#[derive(Clone, Debug, PartialEq)]
pub struct Leg {
    /// Reference point at `t0`.
    pub start: LonLat,
    /// Reference point at `t1`.
    pub end: LonLat,
    /// Rhumb bearing θ (radians).
    pub bearing: f64,
    /// Rhumb length (nm).
    pub length_nm: f64,
    /// Speed `s` (knots), > 0.
    pub speed_kn: f64,
    /// Time the reference point is at `start` (h).
    pub t0: f64,
    /// Time the reference point reaches `end` (h): `t0 + length/speed`.
    pub t1: f64,
    /// Rectangle of Table 2.
    pub dims: RectDims,
    /// Table 2 steps, ring order.
    pub steps: [[(f64, f64); 2]; 4],
    /// `c_m(t0)`, `c_m(tf)`: the ends in the Mercator plane (eqs 25–26).
    pub merc: [Merc; 2],
    /// The model of the Earth the leg moves on.
    pub geo: Geodesy,
    /// The model latitudes `u` of `start` and `end` ([`Geodesy::u_of_lat`]: the latitude
    /// itself on the sphere, the rectifying latitude on the ellipsoid); `u` is linear in t.
    pub u: [f64; 2],
    /// `(cos θ, sin θ)`.
    cos_sin: [f64; 2],
    /// Per vertex (ring order), the constants of eqs 29–30:
    /// `[a, b, d1 sin ψ1 / R, d2 sin ψ2 / R]` with `a = d1 cos ψ1 / R`, `b = d2 cos ψ2 / R`
    /// (`R` the model's [`Geodesy::radius_nm`]; `a`, `b` steps of the model latitude).
    step_consts: [[f64; 4]; 4],
}

impl Leg {
    /// Paper B Section V: a leg from `start` to `end` leaving at `t0` with speed `speed_kn`,
    /// on the paper's sphere.
    pub fn new(start: LonLat, end: LonLat, speed_kn: f64, t0: f64, dims: RectDims) -> Leg {
        Leg::new_in(Geodesy::Sphere, start, end, speed_kn, t0, dims)
    }

    /// Paper B Section V on the model `geo` (the sphere, or the WGS84 ellipsoid).
    pub fn new_in(
        geo: Geodesy,
        start: LonLat,
        end: LonLat,
        speed_kn: f64,
        t0: f64,
        dims: RectDims,
    ) -> Leg {
        let (length_nm, bearing) = geo.rhumb_inverse(start, end);
        let steps = table2_steps(dims, bearing);
        let r = geo.radius_nm();
        let step_consts = steps.map(|[(d1, p1), (d2, p2)]| {
            [
                d1 * p1.cos() / r,
                d2 * p2.cos() / r,
                d1 * p1.sin() / r,
                d2 * p2.sin() / r,
            ]
        });
        Leg {
            start,
            end,
            bearing,
            length_nm,
            speed_kn,
            t0,
            t1: t0 + length_nm / speed_kn,
            dims,
            steps,
            step_consts,
            merc: [geo.mercator(start), geo.mercator(end)],
            geo,
            u: [geo.u_of_lat(start.lat), geo.u_of_lat(end.lat)],
            cos_sin: [bearing.cos(), bearing.sin()],
        }
    }

    /// The same leg moved `dx` radians east (a whole turn, 2π·k, for the copies of an
    /// object on the Earth's unrolled plane): its bearing, length, times and rectangle are
    /// those of `self`, which depend on longitude differences only; only the ends' (and
    /// so every point's) longitudes move, each by one rounding of `dx`'s sum.
    pub fn shifted(&self, dx: f64) -> Leg {
        let mv = |p: LonLat| LonLat {
            lon: p.lon + dx,
            lat: p.lat,
        };
        let (start, end) = (mv(self.start), mv(self.end));
        Leg {
            start,
            end,
            merc: [self.geo.mercator(start), self.geo.mercator(end)],
            ..self.clone()
        }
    }

    /// Paper B eqs 23–24: the reference point `c_s(t)` (t clamped to the leg's life).
    pub fn reference_at(&self, t: f64) -> LonLat {
        self.reference_with_psi(t).0
    }

    /// The model's radius `R` ([`Geodesy::radius_nm`]).
    fn radius(&self) -> f64 {
        self.geo.radius_nm()
    }

    /// Paper B eqs 23–24 and 26: `c_s(t)`, its model latitude `u` and `Ψ(u)`, with the
    /// bearing's cosine and sine and `Ψ(u(t0))` precomputed (the same formula as
    /// [`Geodesy::rhumb_destination`]).
    fn reference_with_psi(&self, t: f64) -> (LonLat, f64, f64) {
        let t = t.clamp(self.t0, self.t1);
        if t == self.t1 {
            return (self.end, self.u[1], self.merc[1][1]);
        }
        let d = self.speed_kn * (t - self.t0);
        let r = self.radius();
        let u = self.u[0] + d * self.cos_sin[0] / r;
        let psi = self.geo.psi_of_u(u);
        let du = u - self.u[0];
        let m = if du.abs() >= FAST_MEAN_SEC_MIN_H {
            (psi - self.merc[0][1]) / du
        } else {
            self.geo.mean_g(self.u[0], du)
        };
        let lon = self.start.lon + d * self.cos_sin[1] / r * m;
        let lat = self.geo.lat_of_u(u);
        (LonLat { lon, lat }, u, psi)
    }

    /// Paper B eqs 27–28: the reference point in the Mercator plane.
    pub fn reference_merc_at(&self, t: f64) -> Merc {
        let (c, _, psi) = self.reference_with_psi(t);
        [c.lon, psi]
    }

    /// Paper B eqs 29–30 and Table 2: the rectangle's vertices at time `t`, ring order 1-2-4-3.
    pub fn vertices_at(&self, t: f64) -> [LonLat; 4] {
        let c = self.reference_at(t);
        self.steps.map(|s| {
            s.iter()
                .fold(c, |p, &(d, psi)| self.geo.rhumb_destination(p, psi, d))
        })
    }

    /// Paper B eqs 29–30 in the Mercator plane (eqs 25–26), evaluated with the step
    /// constants precomputed: vertex `k` is `x = λ_c + s1·M(u, a) + s2·M(u+a, b)`,
    /// `y = ψ(u + a + b)` with `u = φ_c(t)` (the same formulas as [`Leg::vertices_at`]
    /// followed by [`mercator`], sharing the front and back steps' means).
    pub fn merc_vertices_at(&self, t: f64) -> [Merc; 4] {
        let (c, u, psi_u) = self.reference_with_psi(t);
        // M(φ, h) from ψ values already at hand when h is large enough for the plain
        // difference (see FAST_MEAN_SEC_MIN_H), else the cancellation-free form.
        let mean = |lat: f64, psi_lat: f64, h: f64, psi_end: f64| {
            let dphi = (lat + h) - lat;
            if dphi.abs() >= FAST_MEAN_SEC_MIN_H {
                (psi_end - psi_lat) / dphi
            } else {
                self.geo.mean_g(lat, h)
            }
        };
        let (af, ab) = (self.step_consts[0][0], self.step_consts[2][0]);
        let (psi_f, psi_b) = (self.geo.psi_of_u(u + af), self.geo.psi_of_u(u + ab));
        let front = mean(u, psi_u, af, psi_f);
        let back = mean(u, psi_u, ab, psi_b);
        let mut out = [[0.0; 2]; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let [a, b, s1, s2] = self.step_consts[k];
            let (m1, psi_mid) = if k < 2 { (front, psi_f) } else { (back, psi_b) };
            let mid = u + a;
            let y = self.geo.psi_of_u(mid + b);
            *o = [c.lon + s1 * m1 + s2 * mean(mid, psi_mid, b, y), y];
        }
        out
    }

    /// Paper B Section V: a leg is *linear* (eq 20 applies) when it runs due east or west:
    /// the latitude is constant, so every vertex translates along x at a constant rate.
    pub fn is_east_west(&self) -> bool {
        self.start.lat == self.end.lat
    }

    /// Paper B eq 20: for an east–west leg, the constant Mercator velocity of every vertex
    /// (radians of x per hour); `None` otherwise.
    pub fn linear_velocity(&self) -> Option<Merc> {
        if !self.is_east_west() || self.t1 <= self.t0 {
            return None;
        }
        Some([(self.end.lon - self.start.lon) / (self.t1 - self.t0), 0.0])
    }

    /// Latitude offsets of the two steps of vertex `k`: `(a, a + b)` with
    /// `a = d1 cos ψ1 / R`, `b = d2 cos ψ2 / R` (eq 30), independent of time: the stored
    /// `step_consts`, formed by the same expressions.
    fn lat_offsets(&self, k: usize) -> (f64, f64) {
        let [a, b, _, _] = self.step_consts[k];
        (a, a + b)
    }

    /// Largest |latitude| reached by the reference point, the step points and the vertices
    /// during the leg (latitudes are `u + const` with `u` linear in t, so the extremes are
    /// at the ends).
    pub fn max_abs_lat(&self) -> f64 {
        let mut m: f64 = 0.0;
        for u in self.u {
            m = m.max(u.abs());
            for k in 0..4 {
                let (a, ab) = self.lat_offsets(k);
                m = m.max((u + a).abs()).max((u + ab).abs());
            }
        }
        m
    }

    /// Paper B eqs 27–30 differentiated: an upper bound on the Mercator speed (radians/h)
    /// of every vertex during the leg. With `u = φ_c(t)`, `u' = s cos θ / R`:
    /// `x_c' = s sin θ sec u / R`; vertex `y_k = ψ(u + a + b)`, `y_k' = sec(u+a+b) u'`;
    /// `x_k = x_c + (d1 sin ψ1/R) M(u, a) + (d2 sin ψ2/R) M(u+a, b)` with
    /// `|∂M/∂u| ≤ sec Φ tan Φ` (M is the mean of sec, its derivative the mean of sec·tan).
    pub fn merc_speed_bound(&self) -> f64 {
        let (sec, tan) = self.geo.sec_tan_bound(self.max_abs_lat());
        let s = self.speed_kn / self.radius();
        let (st, ct) = (self.bearing.sin().abs(), self.bearing.cos().abs());
        let steps = (self.dims.front.max(self.dims.back) + self.dims.side) / self.radius();
        let vx = s * (st * sec + ct * steps * sec * tan);
        let vy = s * ct * sec;
        vx.hypot(vy) * BOUND_SAFETY
    }

    /// Paper B eqs 27–28 differentiated: the reference point's Mercator velocity is
    /// `sec φ_c(t) · e` with the constant `e = (s/R)(sin θ, cos θ)`. Returns `e` and the
    /// range `[sec_min, sec_max]` of `sec φ_c` over the leg (φ_c is linear in t).
    pub fn reference_velocity_envelope(&self) -> (Merc, f64, f64) {
        let s = self.speed_kn / self.radius();
        let e = [s * self.bearing.sin(), s * self.bearing.cos()];
        let [a, b] = self.u;
        let (lo, hi) = self.geo.g_range(a.min(b), a.max(b));
        (e, lo / BOUND_SAFETY, hi * BOUND_SAFETY)
    }

    /// Paper B eqs 29–30 differentiated: a bound on `|v_k(t) − v_c(t)|`, the speed of any
    /// vertex relative to the reference point. From [`Leg::merc_speed_bound`]'s terms:
    /// the x part is `u' Σ (d_m sin ψ_m / R) ∂M/∂u` and the y part `u'(sec(u+δ) − sec u)`,
    /// each at most `|u'| sec Φ tan Φ · (Σ d_m)/R`.
    pub fn deformation_speed_bound(&self) -> f64 {
        let (sec, tan) = self.geo.sec_tan_bound(self.max_abs_lat());
        let steps = (self.dims.front.max(self.dims.back) + self.dims.side) / self.radius();
        let du = self.speed_kn / self.radius() * self.bearing.cos().abs();
        2.0 * du * steps * tan * sec * BOUND_SAFETY
    }

    /// Paper B eq 7 made conservative: for each vertex (ring order) a box
    /// `[xmin, xmax] × [ymin, ymax]` containing its Mercator offset from the reference
    /// point over the whole leg. Paper defect: eq 7's hull of the rectangles at `t0` and
    /// `tf` assumes linear vertex motion; here the offsets change with `sec φ`. Each offset
    /// term is `h·M(u + e, h)`, monotone in `u` on either side of `u = −e − h/2`, so its
    /// range over `[u0, u1]` is reached at the ends or at that point (interval sums).
    pub fn offset_boxes(&self) -> [[f64; 4]; 4] {
        let (u0, u1) = if self.u[0] <= self.u[1] {
            (self.u[0], self.u[1])
        } else {
            (self.u[1], self.u[0])
        };
        let (e0, e1) = (self.offset_terms(u0), self.offset_terms(u1));
        let mut out = [[0.0; 4]; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let [a, b, s1, s2] = self.step_consts[k];
            // range of term `j` = c·M(u + e, h) over [u0, u1]: the ends, and the
            // critical point u = −e − h/2 when inside
            let range = |j: usize, c: f64, e: f64, h: f64| -> (f64, f64) {
                let (mut lo, mut hi) = (e0[k][j].min(e1[k][j]), e0[k][j].max(e1[k][j]));
                let crit = -e - 0.5 * h;
                if crit > u0 && crit < u1 {
                    let v = c * self.geo.mean_g(crit + e, h);
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
                (lo, hi)
            };
            let (x1l, x1h) = range(0, s1, 0.0, a);
            let (x2l, x2h) = range(1, s2, a, b);
            let (yl, yh) = range(2, a + b, 0.0, a + b);
            let pad = |lo: f64, hi: f64| {
                let m = (hi - lo).abs().max(hi.abs().max(lo.abs())) * (BOUND_SAFETY - 1.0);
                (lo - m, hi + m)
            };
            let (xl, xh) = pad(x1l + x2l, x1h + x2h);
            let (yl, yh) = pad(yl, yh);
            *o = [xl, xh, yl, yh];
        }
        out
    }

    /// Paper B eqs 29–30: the three terms of each vertex's Mercator offset from a reference
    /// point at latitude `u`: `[s1·M(u, a), s2·M(u+a, b), ψ(u+a+b) − ψ(u)]` (as
    /// [`Leg::merc_vertices_at`] evaluates them).
    fn offset_terms(&self, u: f64) -> [[f64; 3]; 4] {
        let psi_u = self.geo.psi_of_u(u);
        let mean = |lat: f64, psi_lat: f64, h: f64, psi_end: f64| {
            let dphi = (lat + h) - lat;
            if dphi.abs() >= FAST_MEAN_SEC_MIN_H {
                (psi_end - psi_lat) / dphi
            } else {
                self.geo.mean_g(lat, h)
            }
        };
        let (af, ab) = (self.step_consts[0][0], self.step_consts[2][0]);
        let (psi_f, psi_b) = (self.geo.psi_of_u(u + af), self.geo.psi_of_u(u + ab));
        let front = mean(u, psi_u, af, psi_f);
        let back = mean(u, psi_u, ab, psi_b);
        let mut out = [[0.0; 3]; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let [a, b, s1, s2] = self.step_consts[k];
            let (m1, psi_mid) = if k < 2 { (front, psi_f) } else { (back, psi_b) };
            let mid = u + a;
            let y = self.geo.psi_of_u(mid + b);
            *o = [s1 * m1, s2 * mean(mid, psi_mid, b, y), y - psi_u];
        }
        out
    }

    /// Paper B Algorithm 4 with its defects fixed: the time at which the reference point is
    /// at fraction `rho` of the leg's Mercator segment. The printed algorithm drops `R`
    /// and `t0` (`t = d/s`); here `t = t0 + sign(ρ) · R·d/s` (`d` in radians of arc), so
    /// fractions before the start give times before `t0`.
    pub fn track_time(&self, rho: f64) -> f64 {
        let [c0, c1] = self.merc;
        let q = [c0[0] + rho * (c1[0] - c0[0]), c0[1] + rho * (c1[1] - c0[1])];
        let qs = self.geo.inverse_mercator(q);
        let d = self.geo.rhumb_distance(self.start, qs);
        self.t0 + rho.signum() * d / self.speed_kn
    }
}

/// Paper B Section III ("piece-wise straight line segments") and Section V: a track of
/// several waypoints split into legs, each a straight Mercator segment, back to back in
/// time from `t0`. Zero-length legs (repeated waypoints) are skipped.
pub fn track_legs(waypoints: &[LonLat], speed_kn: f64, t0: f64, dims: RectDims) -> Vec<Leg> {
    track_legs_in(Geodesy::Sphere, waypoints, speed_kn, t0, dims)
}

/// [`track_legs`] on the model `geo`.
pub fn track_legs_in(
    geo: Geodesy,
    waypoints: &[LonLat],
    speed_kn: f64,
    t0: f64,
    dims: RectDims,
) -> Vec<Leg> {
    let mut legs = Vec::with_capacity(waypoints.len().saturating_sub(1));
    let mut t = t0;
    for w in waypoints.windows(2) {
        if w[0] == w[1] {
            continue;
        }
        let leg = Leg::new_in(geo, w[0], w[1], speed_kn, t, dims);
        t = leg.t1;
        legs.push(leg);
    }
    legs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table2_ring_is_convex_and_ccw_free_of_bowtie() {
        let leg = Leg::new(
            LonLat::from_degrees(39.0, 29.0),
            LonLat::from_degrees(41.0, 31.0),
            15.0,
            0.0,
            RectDims {
                front: 10.0,
                back: 10.0,
                side: 10.0,
            },
        );
        let v = leg.merc_vertices_at(1.0);
        let mut signs = [0.0; 4];
        for i in 0..4 {
            let (a, b, c) = (v[i], v[(i + 1) % 4], v[(i + 2) % 4]);
            signs[i] = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        }
        assert!(signs.iter().all(|s| *s > 0.0) || signs.iter().all(|s| *s < 0.0));
    }

    #[test]
    fn fast_vertices_match_reference() {
        let dims = RectDims {
            front: 20.0,
            back: 12.0,
            side: 30.0,
        };
        let north = Leg::new(
            LonLat::from_degrees(-40.0, 2.0),
            LonLat::from_degrees(-39.0, 28.0),
            15.0,
            0.0,
            dims,
        );
        let east = Leg::new(
            LonLat::from_degrees(39.0, 30.0),
            LonLat::from_degrees(41.0, 30.0),
            15.0,
            0.0,
            dims,
        );
        let due_north = Leg::new(
            LonLat::from_degrees(39.0, 30.0),
            LonLat::from_degrees(39.0, 31.0),
            15.0,
            0.0,
            dims,
        );
        for leg in [north, east, due_north] {
            fast_vertices_case(&leg);
        }
    }

    fn fast_vertices_case(leg: &Leg) {
        for i in 0..=10 {
            let t = leg.t1 * i as f64 / 10.0;
            let a = leg.merc_vertices_at(t);
            let b = leg.vertices_at(t).map(mercator);
            for k in 0..4 {
                // FAST_MEAN_SEC_MIN_H's bound (1e-14 rad) plus a few roundings
                assert!((a[k][0] - b[k][0]).abs() < 4e-14 && (a[k][1] - b[k][1]).abs() < 4e-14);
            }
        }
    }

    #[test]
    fn speed_bound_holds_on_samples() {
        let leg = Leg::new(
            LonLat::from_degrees(-40.0, 2.0),
            LonLat::from_degrees(-39.0, 28.0),
            15.0,
            0.0,
            RectDims {
                front: 20.0,
                back: 20.0,
                side: 20.0,
            },
        );
        let v = leg.merc_speed_bound();
        let n = 200;
        let h = (leg.t1 - leg.t0) / n as f64;
        for i in 0..n {
            let a = leg.merc_vertices_at(leg.t0 + i as f64 * h);
            let b = leg.merc_vertices_at(leg.t0 + (i + 1) as f64 * h);
            for k in 0..4 {
                let d = (b[k][0] - a[k][0]).hypot(b[k][1] - a[k][1]);
                assert!(d <= v * h, "vertex {k} moved {d} > {}", v * h);
            }
        }
    }

    #[test]
    fn offset_boxes_contain_sampled_offsets() {
        let leg = Leg::new(
            LonLat::from_degrees(-40.0, -1.0),
            LonLat::from_degrees(-39.0, 1.5),
            15.0,
            0.0,
            RectDims {
                front: 20.0,
                back: 15.0,
                side: 30.0,
            },
        );
        let boxes = leg.offset_boxes();
        for i in 0..=100 {
            let t = leg.t0 + (leg.t1 - leg.t0) * i as f64 / 100.0;
            let c = leg.reference_merc_at(t);
            for (k, v) in leg.merc_vertices_at(t).iter().enumerate() {
                let (dx, dy) = (v[0] - c[0], v[1] - c[1]);
                let b = boxes[k];
                let slack = 1e-15;
                assert!(dx >= b[0] - slack && dx <= b[1] + slack, "x {k} {dx} {b:?}");
                assert!(dy >= b[2] - slack && dy <= b[3] + slack, "y {k} {dy} {b:?}");
            }
        }
    }
}
