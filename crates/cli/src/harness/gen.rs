//! Boundary-biased case generators: where floating point breaks.
//!
//! Every case is built around a star-shaped counterclockwise polygon and then puts the
//! point at a threshold of one of paper A's decisions, moved by a relative ε that is
//! 0, a few ulps, or 10⁻¹⁵ … 10⁻³ either way:
//! a distance BUFF·(1 ± ε) from an edge or a vertex (near_edge), a vertex at
//! |p_x − s_x| = BUFF·(1 ± ε) or p_y = s_y − BUFF·(1 ± ε) (the perturbation of §II.B),
//! a trajectory through a vertex or tangent to / along an edge, first contact at
//! t = T·(1 ± ε) or at t = 0, the end of an extended edge (1 + F)·(1 ± ε) (edge_detect),
//! an edge whose ends move alike (dot_nn_lin's vanishing leading coefficient), and a
//! slab boundary reached at the contact time (detect_3d). Scales: coordinates offset by
//! 0 or 10³ … 10⁷, polygons from 10⁻² to 10³ across, BUFF relative 10⁻² … 10⁻⁷.
//!
//! Half the cases of [`any_case`] are then stretched into long relative paths
//! ([`stretch`]): the whole scene is moved back in time by τ = (K − 1)·T with K
//! log-uniform in 10 … 10⁶, the polygon's warping slowed by K, so that at τ the scene is
//! the threshold configuration above and the relative path over the lookahead K·T is K
//! times longer (up to ~3·10⁶ polygon sizes, BUFF down to ~10⁻¹³ of the path): where
//! squared distances cancel, the region the plain f64 transcription misses.
//!
//! The choices are drawn from a [`Source`]: [`SplitMix`] for seeded runs, [`Bytes`] for
//! fuzzers (the fuzzer's input bytes steer every choice).

use crate::case::RawCase;
use polyguard::vect2::Vect2;

/// Where the generator's choices come from.
pub trait Source {
    /// 64 fresh bits.
    fn next_u64(&mut self) -> u64;

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform in 0..n (n > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
    /// One of the items.
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }
    /// A fair coin.
    fn coin(&mut self) -> bool {
        self.next_u64() & 1 == 1
    }
}

/// SplitMix64: seeded, tiny, the same on every machine.
#[derive(Clone, Debug)]
pub struct SplitMix(pub u64);

impl Source for SplitMix {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// A fuzzer's input as a source: 8 bytes per draw, zeros once exhausted.
#[derive(Clone, Debug)]
pub struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Bytes<'a> {
    /// Draws from `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Bytes { data, pos: 0 }
    }
}

impl Source for Bytes<'_> {
    fn next_u64(&mut self) -> u64 {
        let mut buf = [0u8; 8];
        for b in buf.iter_mut() {
            if let Some(&x) = self.data.get(self.pos) {
                *b = x;
            }
            self.pos += 1;
        }
        u64::from_le_bytes(buf)
    }
}

/// The threshold a case is built on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mode {
    /// s at BUFF·(1 + ε) outside an edge.
    EdgeBuff,
    /// s at BUFF·(1 + ε) from a vertex.
    VertexBuff,
    /// A vertex at |p_x − s_x| = BUFF·(1 + ε), above s (perturbation's x threshold).
    PerturbX,
    /// A vertex at p_y = s_y − BUFF·(1 + ε) (perturbation's y threshold).
    PerturbY,
    /// The trajectory passes through a vertex at t = T·(1/2 + ε).
    ThroughVertex,
    /// Moving along an edge's line, BUFF·ε outside it (tangent, collinear, disc = 0).
    AlongEdge,
    /// Coming straight in, first contact at t = T·(1 + ε).
    ContactAtT,
    /// On an edge at t = 0, moved by BUFF·ε.
    ContactAtZero,
    /// Crossing an edge's line just beyond its end: (1 + F)·(1 + ε) half-edges from the
    /// midpoint (edge_detect's F boundary).
    ExtendedEnd,
    /// Random trajectory near the polygon (no threshold): the background rate.
    Free,
}

impl Mode {
    /// Every mode.
    pub const ALL: [Mode; 10] = [
        Mode::EdgeBuff,
        Mode::VertexBuff,
        Mode::PerturbX,
        Mode::PerturbY,
        Mode::ThroughVertex,
        Mode::AlongEdge,
        Mode::ContactAtT,
        Mode::ContactAtZero,
        Mode::ExtendedEnd,
        Mode::Free,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Mode::EdgeBuff => "edge_buff",
            Mode::VertexBuff => "vertex_buff",
            Mode::PerturbX => "perturb_x",
            Mode::PerturbY => "perturb_y",
            Mode::ThroughVertex => "through_vertex",
            Mode::AlongEdge => "along_edge",
            Mode::ContactAtT => "contact_at_t",
            Mode::ContactAtZero => "contact_at_zero",
            Mode::ExtendedEnd => "extended_end",
            Mode::Free => "free",
        }
    }

    /// snake_case name of the mode stretched into a long path ([`stretch`]).
    pub fn long_name(self) -> &'static str {
        match self {
            Mode::EdgeBuff => "edge_buff+long",
            Mode::VertexBuff => "vertex_buff+long",
            Mode::PerturbX => "perturb_x+long",
            Mode::PerturbY => "perturb_y+long",
            Mode::ThroughVertex => "through_vertex+long",
            Mode::AlongEdge => "along_edge+long",
            Mode::ContactAtT => "contact_at_t+long",
            Mode::ContactAtZero => "contact_at_zero+long",
            Mode::ExtendedEnd => "extended_end+long",
            Mode::Free => "free+long",
        }
    }
}

/// Options of a generated case's shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// All vertex velocities equal (detect_same_2d).
    Static,
    /// Vertex velocities differ (detect_diff_2d); one edge keeps equal end velocities.
    Warping,
    /// With a height and a slab (detect_3d), static or warping at random.
    ThreeD,
}

/// A relative perturbation ε: 0, ±1…4 ulps, or ±10⁻¹⁵ … 10⁻³.
pub fn epsilon<S: Source>(src: &mut S) -> f64 {
    match src.below(3) {
        0 => 0.0,
        1 => (src.below(9) as f64 - 4.0) * f64::EPSILON,
        _ => {
            let e = 10f64.powi(-(3 + src.below(13) as i32));
            if src.coin() {
                e
            } else {
                -e
            }
        }
    }
}

/// One boundary-biased case of the given shape and mode, and the ε it used.
pub fn case<S: Source>(src: &mut S, shape: Shape, mode: Mode) -> (RawCase, f64) {
    let tau = core::f64::consts::TAU;
    let n = 3 + src.below(10);
    let scale = src.pick(&[1e-2, 1.0, 10.0, 1e3]);
    let offset = src.pick(&[0.0, 0.0, 1e3, 1e5, 1e7]);
    let o = Vect2::new(offset * src.range(-1.0, 1.0), offset * src.range(-1.0, 1.0));
    // Star-shaped around o: angular gaps below (1 + 0.45)/3 < half a turn, radii in [0.4, 1]·scale.
    let verts: Vec<Vect2> = (0..n)
        .map(|i| {
            let a = tau * (i as f64 + 0.45 * src.unit()) / n as f64;
            let r = scale * src.range(0.4, 1.0);
            o + Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect();
    let t = src.pick(&[1.0, 10.0, 300.0]) * src.range(0.5, 1.0);
    let buff = scale * src.pick(&[1e-2, 1e-4, 1e-7]);
    let fac = src.pick(&[1e-4, 1e-4, 1e-2, 1e-6]);
    let warping = match shape {
        Shape::Static => false,
        Shape::Warping => true,
        Shape::ThreeD => src.coin(),
    };
    let drift = Vect2::new(src.range(-1.0, 1.0), src.range(-1.0, 1.0)).scale(scale / t);
    let keep = src.below(n); // an edge whose ends move alike: dot_nn_lin's A = 0
    let mut vels: Vec<Vect2> = (0..n)
        .map(|_| {
            if warping {
                drift
                    + Vect2::new(src.range(-1.0, 1.0), src.range(-1.0, 1.0)).scale(0.3 * scale / t)
            } else {
                drift
            }
        })
        .collect();
    if warping {
        vels[(keep + 1) % n] = vels[keep];
    }
    let e = epsilon(src);
    let i = src.below(n);
    let j = (i + 1) % n;
    let (pi, pj) = (verts[i], verts[j]);
    let d = pj - pi;
    let len = d.sq().sqrt();
    let (u, out) = (d.scale(1.0 / len), d.perp().scale(1.0 / len)); // outward: CCW
    let speed = src.range(0.0, 3.0) * scale / t;
    let dir = src.range(0.0, tau);
    let free_v = Vect2::new(dir.cos(), dir.sin()).scale(speed);
    let along = src.unit();
    let (s, v) = match mode {
        Mode::EdgeBuff => (pi + d.scale(along) + out.scale(buff * (1.0 + e)), free_v),
        Mode::VertexBuff => {
            let w = (out - u).scale(1.0 / 2f64.sqrt());
            (pi + w.scale(buff * (1.0 + e)), free_v)
        }
        Mode::PerturbX => {
            let side = if src.coin() { 1.0 } else { -1.0 };
            let below = scale * src.range(0.0, 2.0);
            (
                Vect2::new(pi.x + side * buff * (1.0 + e), pi.y - below),
                free_v,
            )
        }
        Mode::PerturbY => {
            let dx = buff * src.range(-1.0, 1.0);
            (Vect2::new(pi.x + dx, pi.y + buff * (1.0 + e)), free_v)
        }
        Mode::ThroughVertex => {
            let tc = t * (0.5 + e);
            (pi.at(vels[i], tc) - free_v.scale(tc), free_v)
        }
        Mode::AlongEdge => {
            let start = pi - d.scale(0.5) + out.scale(buff * e);
            (start, vels[i] + d.scale(2.0 / t))
        }
        Mode::ContactAtT => {
            let vin = out.scale(-speed.max(0.1 * scale / t));
            let hit = pi + d.scale(along);
            (hit - vin.scale(t * (1.0 + e)), vels[i] + vin)
        }
        Mode::ContactAtZero => (pi + d.scale(along) + out.scale(buff * e), free_v),
        Mode::ExtendedEnd => {
            // Crosses the edge's line (moving with vertex i) at (1 + F)(1 + ε) half-edges
            // beyond the midpoint, i.e. just past p_j, at time T/2.
            let mid = pi + d.scale(0.5);
            let cross = mid + d.scale(0.5 * (1.0 + fac) * (1.0 + e));
            let vin = out.scale(-speed.max(0.1 * scale / t));
            let tc = 0.5 * t;
            (
                cross.at(vels[i], tc) - vin.scale(tc) - vels[i].scale(tc),
                vels[i] + vin,
            )
        }
        Mode::Free => {
            let start = o + Vect2::new(src.range(-3.0, 3.0), src.range(-3.0, 3.0)).scale(scale);
            (start, free_v)
        }
    };
    let mut raw = RawCase {
        lookahead: t,
        buff,
        fac,
        pos: vec![s.x, s.y],
        vel: vec![v.x, v.y],
        vertices: verts.iter().map(|&p| p.into()).collect(),
        velocities: vels.iter().map(|&p| p.into()).collect(),
        slab: None,
    };
    if shape == Shape::ThreeD {
        // The point reaches the slab's bottom (or top) at a time near the middle, ± ε.
        let vz = src.range(-2.0, 2.0) * scale / t;
        let vsp = if src.coin() {
            0.0
        } else {
            src.range(-0.5, 0.5) * scale / t
        };
        let tz = t * src.range(0.2, 0.8) * (1.0 + e);
        let z0 = src.range(-1.0, 1.0) * scale;
        let height = scale * src.range(0.01, 2.0);
        let z_at = z0 + vz * tz;
        let (bottom, top) = if src.coin() {
            let b = z_at - vsp * tz;
            (b, b + height)
        } else {
            let tp = z_at - vsp * tz;
            (tp - height, tp)
        };
        raw.pos.push(z0);
        raw.vel.push(vz);
        raw.slab = Some([bottom, top, vsp]);
    }
    (raw, e)
}

/// Stretches a case into a long relative path: K = 10^u, u uniform in [1, 6].
///
/// With τ = (K − 1)·T, vertex velocities v_i = v_0 + δ_i and a slab moving at vsp, the
/// new case has lookahead K·T, start s − τ·v, vertices p_i − τ·v_0 − (τ/K)·δ_i and
/// velocities v_0 + δ_i/K, heights z − τ·v_z and slab ends − τ·vsp. At time τ it is the
/// original case at time 0 (up to the rounding of the far-away starts), and over its
/// lookahead the polygon warps exactly as much as the original did over T, while the
/// point travels K times as far relative to it. Returns K; 1 (the case unchanged) when
/// the polygon at time 0, the original one warped backwards, is no longer simple and
/// counterclockwise.
pub fn stretch<S: Source>(src: &mut S, raw: &mut RawCase) -> f64 {
    let original = raw.clone();
    let k = stretch_by(src, raw);
    let verts: Vec<Vect2> = raw.vertices.iter().map(|&p| p.into()).collect();
    if polyguard::ring::simple_ccw(&verts) {
        k
    } else {
        *raw = original;
        1.0
    }
}

fn stretch_by<S: Source>(src: &mut S, raw: &mut RawCase) -> f64 {
    let k = 10f64.powf(src.range(1.0, 6.0));
    let t = raw.lookahead;
    let tau = (k - 1.0) * t;
    let v = Vect2::new(raw.vel[0], raw.vel[1]);
    let v0: Vect2 = raw
        .velocities
        .first()
        .map(|&w| w.into())
        .unwrap_or_default();
    raw.lookahead = k * t;
    raw.pos[0] -= tau * v.x;
    raw.pos[1] -= tau * v.y;
    for (p, w) in raw.vertices.iter_mut().zip(raw.velocities.iter_mut()) {
        let d = Vect2::from(*w) - v0;
        let np = Vect2::from(*p) - v0.scale(tau) - d.scale(tau / k);
        *p = np.into();
        *w = (v0 + d.scale(1.0 / k)).into();
    }
    if raw.pos.len() == 3 {
        raw.pos[2] -= tau * raw.vel[2];
        if let Some(slab) = raw.slab.as_mut() {
            slab[0] -= tau * slab[2];
            slab[1] -= tau * slab[2];
        }
    }
    k
}

/// A case of random shape and mode; half of them stretched into long relative paths
/// ([`stretch`]). The name is the mode's, with "+long" for a stretched one.
pub fn any_case<S: Source>(src: &mut S) -> (RawCase, Shape, Mode, &'static str) {
    let shape = src.pick(&[Shape::Static, Shape::Warping, Shape::ThreeD]);
    let mode = src.pick(&Mode::ALL);
    let (mut raw, _) = case(src, shape, mode);
    if src.coin() {
        stretch(src, &mut raw);
        (raw, shape, mode, mode.long_name())
    } else {
        (raw, shape, mode, mode.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_cases_are_valid_and_seeded() {
        let mut a = SplitMix(7);
        let mut b = SplitMix(7);
        for _ in 0..500 {
            let (ca, _, _, _) = any_case(&mut a);
            let (cb, _, _, _) = any_case(&mut b);
            assert_eq!(ca, cb);
            ca.to_api().expect("generated cases are valid");
        }
    }

    #[test]
    fn edge_buff_mode_is_at_buff_from_the_edge() {
        let mut src = SplitMix(3);
        for _ in 0..200 {
            let (raw, e) = case(&mut src, Shape::Static, Mode::EdgeBuff);
            let s = Vect2::new(raw.pos[0], raw.pos[1]);
            // Distance to the nearest edge, relative to BUFF, is about 1 + ε.
            let n = raw.vertices.len();
            let dist = (0..n)
                .map(|k| {
                    let a = Vect2::from(raw.vertices[k]);
                    let b = Vect2::from(raw.vertices[(k + 1) % n]);
                    let d = b - a;
                    let r = ((s - a).dot(d) / d.sq()).clamp(0.0, 1.0);
                    (a + d.scale(r) - s).sq().sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            let scale_err = 1e-6 + 1e-9 * raw.vertices[0][0].abs() / raw.buff;
            assert!(
                (dist / raw.buff) <= 1.0 + e.abs() + scale_err,
                "{dist} vs {}",
                raw.buff
            );
        }
    }

    #[test]
    fn bytes_source_is_total() {
        for data in [&[][..], &[1, 2, 3][..], &[255; 100][..]] {
            let mut src = Bytes::new(data);
            let (raw, _, _, _) = any_case(&mut src);
            assert!(raw.to_api().is_ok() || raw.vertices.len() >= 3);
        }
    }
}
