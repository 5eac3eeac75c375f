//! Cases for the hunt of intervals and keep-in exits (docs/cases.md, "Separation and
//! fences"): where the sets inside, near_D and breach_D have several components, ends
//! that touch, or ends that f64 finds hard to place.
//!
//! Half of the cases are paper A's boundary-biased cases ([`crate::gen::any_case_in`],
//! the whole scale space) with D = BUFF and H = BUFF: a distance BUFF·(1 ± ε) from an
//! edge or a vertex becomes a graze at D·(1 ± ε), a trajectory through a vertex or along
//! an edge a touch of the inside set. The other half are drawn here ([`Kind`]):
//! - comb and star polygons crossed by a straight path: the point enters and leaves
//!   several times, and passes a comb's tooth tips at D·(1 ± ε);
//! - warping polygons whose edges sweep over the point twice (a rotating edge makes the
//!   cross product g(t) a quadratic with two roots);
//! - keep-in fences left through a corner, through an edge, through the slab's floor or
//!   ceiling, by a fence that shrinks over the point, or only grazed at D·(1 ± ε).
//!
//! Each is drawn at a random size (10⁻³ … 10³), offset and lookahead, with D from 10⁻¹²
//! to 1 sizes (0 in one case in eight), and one case in eight moved whole to an end of
//! the float range ([`crate::gen::absolute_scale`]).

use crate::case::RawCase;
use crate::gen::{absolute_scale, any_case_in, epsilon, Source, Space};
use polyguard::vect2::Vect2;

/// A case of the interval hunt: the case, its separations, how it was drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct IntervalCase {
    /// The case (its BUFF is paper A's, unused by the intervals).
    pub raw: RawCase,
    /// D ≥ 0.
    pub sep: f64,
    /// H ≥ 0 (used by 3D cases).
    pub sep_v: f64,
    /// The generator's name ([`Kind::name`], or `threshold:` and paper A's mode).
    pub mode: &'static str,
}

/// The shapes drawn here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A comb crossed along its teeth: one entry per tooth.
    Comb,
    /// A comb passed above its teeth at D·(1 ± ε): near_D touches each tooth tip.
    CombGraze,
    /// A star crossed off centre: several arms.
    Star,
    /// A warping quadrilateral whose rotating edge sweeps over the point twice.
    WarpTwice,
    /// A keep-in fence left through a corner.
    FenceCorner,
    /// A keep-in fence left through an edge's interior.
    FenceEdge,
    /// Sliding along an edge at D·(1 ± ε) inside a keep-in fence.
    FenceGraze,
    /// A 3D keep-in volume left through its ceiling or floor (within H·(1 ± ε)).
    FenceSlab,
    /// A keep-in fence that shrinks over a still point.
    FenceShrink,
}

impl Kind {
    /// Every kind.
    pub const ALL: [Kind; 9] = [
        Kind::Comb,
        Kind::CombGraze,
        Kind::Star,
        Kind::WarpTwice,
        Kind::FenceCorner,
        Kind::FenceEdge,
        Kind::FenceGraze,
        Kind::FenceSlab,
        Kind::FenceShrink,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Comb => "comb",
            Kind::CombGraze => "comb_graze",
            Kind::Star => "star",
            Kind::WarpTwice => "warp_twice",
            Kind::FenceCorner => "fence_corner",
            Kind::FenceEdge => "fence_edge",
            Kind::FenceGraze => "fence_graze",
            Kind::FenceSlab => "fence_slab",
            Kind::FenceShrink => "fence_shrink",
        }
    }
}

/// The threshold modes' names in this hunt ("threshold:" and paper A's mode).
fn threshold_name(mode: &str) -> &'static str {
    const NAMES: [(&str, &str); 10] = [
        ("edge_buff", "threshold:edge_buff"),
        ("vertex_buff", "threshold:vertex_buff"),
        ("perturb_x", "threshold:perturb_x"),
        ("perturb_y", "threshold:perturb_y"),
        ("through_vertex", "threshold:through_vertex"),
        ("along_edge", "threshold:along_edge"),
        ("contact_at_t", "threshold:contact_at_t"),
        ("contact_at_zero", "threshold:contact_at_zero"),
        ("extended_end", "threshold:extended_end"),
        ("free", "threshold:free"),
    ];
    let base = mode.trim_end_matches("+long");
    NAMES
        .iter()
        .find(|(m, _)| *m == base)
        .map_or("threshold:other", |(_, n)| n)
}

/// One case of the hunt, over `space` (its path and BUFF ranges apply to the threshold
/// half; the shapes drawn here span their own scales).
pub fn interval_case<S: Source>(src: &mut S, space: &Space) -> IntervalCase {
    if src.coin() {
        let drawn = any_case_in(src, space);
        let d = drawn.raw.buff;
        let mode = threshold_name(drawn.name());
        return IntervalCase {
            raw: drawn.raw,
            sep: d,
            sep_v: d,
            mode,
        };
    }
    let kind = src.pick(&Kind::ALL);
    shaped_case(src, kind, space)
}

/// A case of the given kind at a random scale (see the module doc).
pub fn shaped_case<S: Source>(src: &mut S, kind: Kind, space: &Space) -> IntervalCase {
    let size = 10f64.powf(src.range(-3.0, 3.0));
    let t = 10f64.powf(src.range(-3.0, 4.0));
    let d = if src.below(8) == 0 {
        0.0
    } else {
        size * 10f64.powf(src.range(-12.0, 0.0))
    };
    let h = if src.below(8) == 0 {
        0.0
    } else {
        size * 10f64.powf(src.range(-12.0, 0.0))
    };
    let mut g = Shaper {
        size,
        t,
        d,
        h,
        eps: epsilon(src),
    };
    let mut raw = match kind {
        Kind::Comb => g.comb(src, false),
        Kind::CombGraze => g.comb(src, true),
        Kind::Star => g.star(src),
        Kind::WarpTwice => g.warp_twice(src),
        Kind::FenceCorner => g.fence_cross(src, true),
        Kind::FenceEdge => g.fence_cross(src, false),
        Kind::FenceGraze => g.fence_graze(src),
        Kind::FenceSlab => g.fence_slab(src),
        Kind::FenceShrink => g.fence_shrink(src),
    };
    g.place(src, &mut raw);
    // BUFF is paper A's (unused here); D rides in it through the move to an end of the
    // float range, which scales lengths only.
    raw.buff = if g.d > 0.0 { g.d } else { g.size * 1e-6 };
    let warping = raw.velocities.windows(2).any(|w| w[0] != w[1]);
    let (mut raw, j) = absolute_scale(src, raw, warping, space.ends);
    let scale = |x: f64| x * 2f64.powi(j / 2) * 2f64.powi(j - j / 2);
    let sep = if g.d > 0.0 { raw.buff } else { 0.0 };
    let sep_v = scale(g.h);
    if g.d <= 0.0 {
        raw.buff = scale(g.size * 1e-6).max(f64::MIN_POSITIVE);
    }
    IntervalCase {
        raw,
        sep,
        sep_v,
        mode: kind.name(),
    }
}

/// The scales of one shaped case, and the shapes.
struct Shaper {
    size: f64,
    t: f64,
    d: f64,
    h: f64,
    eps: f64,
}

/// The 2D case of these parts, still polygon (velocities empty).
fn still(t: f64, s: Vect2, v: Vect2, vertices: Vec<Vect2>) -> RawCase {
    RawCase {
        lookahead: t,
        buff: 1.0,
        fac: polyguard::api::Params::DEFAULT_FAC,
        pos: vec![s.x, s.y],
        vel: vec![v.x, v.y],
        vertices: vertices.iter().map(|p| [p.x, p.y]).collect(),
        velocities: vec![],
        slab: None,
    }
}

/// A regular n-gon of radius r about the origin, counterclockwise, turned by `phase`.
fn regular(n: usize, r: f64, phase: f64) -> Vec<Vect2> {
    (0..n)
        .map(|k| {
            let a = phase + std::f64::consts::TAU * k as f64 / n as f64;
            Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

impl Shaper {
    /// A comb of k teeth (base [0, W] × [0, 1], teeth of height L), in units of `size`,
    /// crossed left to right at a height inside the teeth, or (graze) at D·(1 + ε) above
    /// the tips.
    fn comb<S: Source>(&mut self, src: &mut S, graze: bool) -> RawCase {
        let k = 2 + src.below(5);
        let u = self.size;
        let (w, l) = (u, u * src.range(0.5, 3.0));
        let tooth = w / (2.0 * k as f64);
        let mut p = vec![Vect2::new(0.0, 0.0), Vect2::new(w, 0.0), Vect2::new(w, u)];
        for i in (0..k).rev() {
            let c = (i as f64 + 0.5) * w / k as f64;
            p.push(Vect2::new(c + tooth / 2.0, u));
            p.push(Vect2::new(c + tooth / 2.0, u + l));
            p.push(Vect2::new(c - tooth / 2.0, u + l));
            p.push(Vect2::new(c - tooth / 2.0, u));
        }
        p.push(Vect2::new(0.0, u));
        let y = if graze {
            u + l + self.d * (1.0 + self.eps)
        } else {
            u + l * src.range(0.05, 0.95)
        };
        let (x0, x1) = (-0.2 * w, 1.2 * w);
        still(
            self.t,
            Vect2::new(x0, y),
            Vect2::new((x1 - x0) / self.t, 0.0),
            p,
        )
    }

    /// A star of m arms (radii r and R alternating) crossed along a line at an offset
    /// below the inner radius.
    fn star<S: Source>(&mut self, src: &mut S) -> RawCase {
        let m = 3 + src.below(6);
        let (r_out, r_in) = (self.size, self.size * src.range(0.2, 0.6));
        let phase = src.range(0.0, std::f64::consts::TAU);
        let p: Vec<Vect2> = (0..2 * m)
            .map(|k| {
                let a = phase + std::f64::consts::PI * k as f64 / m as f64;
                let r = if k % 2 == 0 { r_out } else { r_in };
                Vect2::new(r * a.cos(), r * a.sin())
            })
            .collect();
        let dir = src.range(0.0, std::f64::consts::TAU);
        let off = r_in * src.range(0.3, 1.2);
        let (c, n) = (
            Vect2::new(dir.cos(), dir.sin()),
            Vect2::new(-dir.sin(), dir.cos()),
        );
        let s = Vect2::new(
            -1.5 * r_out * c.x + off * n.x,
            -1.5 * r_out * c.y + off * n.y,
        );
        let v = Vect2::new(3.0 * r_out * c.x / self.t, 3.0 * r_out * c.y / self.t);
        let mut raw = still(self.t, s, v, p);
        if src.coin() {
            // the whole star drifts: a translating polygon
            let drift = [self.size * src.range(-1.0, 1.0) / self.t, 0.0];
            raw.velocities = vec![drift; raw.vertices.len()];
        }
        raw
    }

    /// A quadrilateral whose edge a b rotates about its midpoint while it shortens, so
    /// that g(t) = (b − a) × (x − a) has two roots in (0, T): the edge sweeps over the
    /// point and back. Drawn until an f64 look finds two sweeps and the polygon stays
    /// simple (exactly, [`crate::gen::simple_throughout`]); else the last draw.
    fn warp_twice<S: Source>(&mut self, src: &mut S) -> RawCase {
        let (u, t) = (self.size, self.t);
        let mut last = None;
        for _ in 0..24 {
            let (r1, r2) = (t * src.range(0.1, 0.45), t * src.range(0.55, 0.9));
            // The midpoint of a b at the origin: g(t) = 2·(b × x). With b(t) = (u − w·t,
            // −c·t) and x(t) = (x0 + vx·t, y0): b × x = u·y0 + (c·x0 − w·y0)·t + c·vx·t².
            let c = u / t * src.range(0.2, 1.0);
            let vx = u / t * src.range(0.05, 0.3) * if src.coin() { 1.0 } else { -1.0 };
            let lead = c * vx;
            let y0 = lead * r1 * r2 / u;
            let x0 = u * src.range(-0.3, 0.3);
            let w = (c * x0 + lead * (r1 + r2)) / y0;
            let a0 = Vect2::new(-u, 0.0);
            let b0 = Vect2::new(u, 0.0);
            let (va, vb) = (Vect2::new(w, c), Vect2::new(-w, -c));
            // the other two corners, far on the side the point starts
            let side = if y0 > 0.0 { 1.0 } else { -1.0 };
            let (c0, d0) = (
                Vect2::new(u, 3.0 * u * side),
                Vect2::new(-u, 3.0 * u * side),
            );
            let mut verts = vec![a0, b0, c0, d0];
            let mut vels = [va, vb, Vect2::default(), Vect2::default()];
            if side < 0.0 {
                verts.reverse();
                vels.reverse();
            }
            let mut raw = still(t, Vect2::new(x0, y0), Vect2::new(vx, 0.0), verts);
            raw.velocities = vels.iter().map(|q| [q.x, q.y]).collect();
            let ok = polyguard::ring::simple_ccw(
                &raw.vertices
                    .iter()
                    .map(|&q| q.into())
                    .collect::<Vec<Vect2>>(),
            ) && crate::gen::simple_throughout(&raw);
            if ok && sweeps(&raw) >= 2 {
                return raw;
            }
            if ok {
                last = Some(raw);
            }
        }
        last.unwrap_or_else(|| self.fence_cross_plain(src))
    }

    /// The point inside a regular n-gon (a keep-in fence), heading for a corner (or an
    /// edge's interior) that it reaches at a random time in (0, T).
    fn fence_cross<S: Source>(&mut self, src: &mut S, corner: bool) -> RawCase {
        let n = 3 + src.below(6);
        let p = regular(n, self.size, src.range(0.0, 1.0));
        let k = src.below(n);
        let target = if corner {
            p[k]
        } else {
            let f = src.range(0.1, 0.9);
            let q = p[(k + 1) % n];
            Vect2::new(p[k].x + f * (q.x - p[k].x), p[k].y + f * (q.y - p[k].y))
        };
        let s = Vect2::new(
            target.x * src.range(-0.3, 0.3),
            target.y * src.range(-0.3, 0.3),
        );
        let when = self.t * src.range(0.1, 0.9) * (1.0 + self.eps);
        let v = Vect2::new((target.x - s.x) / when, (target.y - s.y) / when);
        still(self.t, s, v, p)
    }

    /// [`Self::fence_cross`] through an edge: the fallback of the warping draw.
    fn fence_cross_plain<S: Source>(&mut self, src: &mut S) -> RawCase {
        self.fence_cross(src, false)
    }

    /// Sliding along an edge of a regular n-gon at D·(1 + ε) inside it, from near one end
    /// to near the other: breach_D touches (ε ≤ 0) or just holds off (ε > 0).
    fn fence_graze<S: Source>(&mut self, src: &mut S) -> RawCase {
        let n = 3 + src.below(6);
        let p = regular(n, self.size, src.range(0.0, 1.0));
        let k = src.below(n);
        let (a, b) = (p[k], p[(k + 1) % n]);
        let e = Vect2::new(b.x - a.x, b.y - a.y);
        let len = e.x.hypot(e.y);
        // inward normal of a counterclockwise polygon: e turned left
        let nrm = Vect2::new(-e.y / len, e.x / len);
        let off = self.d.min(0.2 * len) * (1.0 + self.eps);
        let at = |f: f64| Vect2::new(a.x + f * e.x + off * nrm.x, a.y + f * e.y + off * nrm.y);
        let (s, s1) = (at(0.4), at(0.6));
        let v = Vect2::new((s1.x - s.x) / self.t, (s1.y - s.y) / self.t);
        still(self.t, s, v, p)
    }

    /// A 3D keep-in volume (a regular n-gon between a floor and a ceiling that may move),
    /// the point deep inside horizontally, reaching the ceiling (or floor) less H·(1 + ε)
    /// at a random time.
    fn fence_slab<S: Source>(&mut self, src: &mut S) -> RawCase {
        let n = 3 + src.below(6);
        let p = regular(n, self.size, src.range(0.0, 1.0));
        let thick = self.size * 10f64.powf(src.range(-2.0, 1.0));
        self.h = self.h.min(0.25 * thick);
        let (bottom, top) = (0.0, thick);
        let vsp = thick * src.range(-0.5, 0.5) / self.t;
        let when = self.t * src.range(0.1, 1.2);
        let up = src.coin();
        let z_then = if up {
            top + vsp * when - self.h * (1.0 + self.eps)
        } else {
            bottom + vsp * when + self.h * (1.0 + self.eps)
        };
        let z0 = 0.5 * thick;
        let mut raw = still(
            self.t,
            Vect2::new(0.1 * self.size, 0.0),
            Vect2::new(0.0, 0.1 * self.size / self.t),
            p,
        );
        raw.pos.push(z0);
        raw.vel.push((z_then - z0) / when);
        raw.slab = Some([bottom, top, vsp]);
        raw
    }

    /// A regular n-gon whose corners move towards its centre so that it shrinks to a
    /// fraction of its size over T, around a point that it passes.
    fn fence_shrink<S: Source>(&mut self, src: &mut S) -> RawCase {
        let n = 3 + src.below(6);
        let p = regular(n, self.size, src.range(0.0, 1.0));
        let keep = src.range(0.05, 0.5);
        let vels: Vec<[f64; 2]> = p
            .iter()
            .map(|q| [-q.x * (1.0 - keep) / self.t, -q.y * (1.0 - keep) / self.t])
            .collect();
        let r = self.size * src.range(0.1, 0.8);
        let a = src.range(0.0, std::f64::consts::TAU);
        let mut raw = still(
            self.t,
            Vect2::new(r * a.cos(), r * a.sin()),
            Vect2::default(),
            p,
        );
        raw.velocities = vels;
        raw
    }

    /// Moves the whole case by a random offset (up to 10³ sizes; none in one case in
    /// four), exactly as drawn: the offset is added to every position.
    fn place<S: Source>(&self, src: &mut S, raw: &mut RawCase) {
        if src.below(4) == 0 {
            return;
        }
        let o = [
            self.size * 10f64.powf(src.range(-1.0, 3.0)) * if src.coin() { 1.0 } else { -1.0 },
            self.size * 10f64.powf(src.range(-1.0, 3.0)) * if src.coin() { 1.0 } else { -1.0 },
        ];
        raw.pos[0] += o[0];
        raw.pos[1] += o[1];
        for q in raw.vertices.iter_mut() {
            q[0] += o[0];
            q[1] += o[1];
        }
    }
}

/// How many separate stretches of time a look at 256 f64 instants finds the point
/// inside the polygon (crossing parity in f64: a generator's look, never a decision).
fn sweeps(raw: &RawCase) -> usize {
    let n = raw.vertices.len();
    let at = |k: usize, t: f64| -> [f64; 2] {
        let v = raw.velocities.get(k).copied().unwrap_or([0.0, 0.0]);
        [raw.vertices[k][0] + t * v[0], raw.vertices[k][1] + t * v[1]]
    };
    let mut runs = 0;
    let mut was_in = false;
    for i in 0..=256 {
        let t = raw.lookahead * i as f64 / 256.0;
        let (x, y) = (raw.pos[0] + t * raw.vel[0], raw.pos[1] + t * raw.vel[1]);
        let mut inside = false;
        for k in 0..n {
            let (a, b) = (at(k, t), at((k + 1) % n, t));
            if (a[1] > y) != (b[1] > y) {
                let xc = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                if x < xc {
                    inside = !inside;
                }
            }
        }
        if inside && !was_in {
            runs += 1;
        }
        was_in = inside;
    }
    runs
}

impl IntervalCase {
    /// The case as a line of the case format, with `sep` and `sep_v` (docs/cases.md) and
    /// `extra` in its `meta`.
    pub fn to_json_line(&self, id: &str, extra: &[(&str, serde_json::Value)]) -> String {
        let line = self.raw.to_json_line(id, extra);
        match serde_json::from_str::<serde_json::Value>(&line) {
            Ok(serde_json::Value::Object(mut obj)) => {
                obj.insert("sep".into(), self.sep.into());
                obj.insert("sep_v".into(), self.sep_v.into());
                serde_json::Value::Object(obj).to_string()
            }
            _ => line,
        }
    }
}
