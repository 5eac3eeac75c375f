//! The fast path for rigidly translating obstacles (the parent module's "Fast path for
//! translating polygons"; paper A §II's polygon, §II.G's proximity, §II–§III's motion
//! with every vertex velocity equal): the point's path in the polygon's frame is one
//! segment σ, and its distance to the fixed polygon P(0) decides the cell.

use std::vec::Vec;

use crate::ball::{nonnegative, positive, round_down, round_up, Ball, BallV, Tri};
use crate::offset::{at_least, segments_at_least, winding_number, within};
use crate::vect2::Vect2;

/// How many points of each stretch of σ̃ between crossings the deepest-point search
/// tries (interior points at k/SAMPLES of the stretch).
const SAMPLES: usize = 8;

/// The relative path of the point in a translating polygon's frame: σ̃ = [s, ẽ], the
/// float image of σ = {s + t·(w − V) : t ∈ [0, T]} (parent module: within `rho2` of σ
/// at every t).
pub(super) struct Rigid<'a> {
    /// P at t = 0 (exact f64 vertices, counterclockwise).
    p: &'a [Vect2],
    /// The point at t = 0.
    s: Vect2,
    /// σ̃'s float end.
    e: Vect2,
    /// 2ρ ≥ √2·ρ: bounds |σ(t) − σ̃(t)| (ρ bounds each coordinate of e's error).
    rho2: f64,
    /// T.
    t: f64,
    /// The relative velocity w − V, each coordinate as a ball.
    u: [Ball; 2],
    /// s certainly outside P (exact location, not on ∂P).
    s_out: bool,
}

/// σ̃'s float geometry against P (guides the choice of witnesses, decides nothing).
struct Shape {
    /// The nearest approach to ∂P: (the parameter λ ∈ [0, 1], the edge).
    near: (f64, usize),
    /// The float parameters 0, the crossings of σ̃ with ∂P, 1, sorted.
    events: Vec<f64>,
}

/// The float squared distance from q to the segment [a, b] and where its projection
/// falls (μ ∈ [0, 1]).
fn seg_dist2(q: Vect2, a: Vect2, b: Vect2) -> (f64, f64) {
    let e = b - a;
    let ee = e.sq();
    let mu = if ee > 0.0 {
        ((q - a).dot(e) / ee).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((q - (a + e.scale(mu))).sq(), mu)
}

/// The float cross product a × b.
fn cross(a: Vect2, b: Vect2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The edges of P as (index, a, b).
fn edges(p: &[Vect2]) -> impl Iterator<Item = (usize, Vect2, Vect2)> + '_ {
    (0..p.len()).map(move |j| (j, p[j], p[(j + 1) % p.len()]))
}

/// The gap between the boxes of [a, b] and [c, d] along x or y, rounded down, is at
/// least th: every pair of their points is at least th apart.
fn boxes_apart(a: Vect2, b: Vect2, c: Vect2, d: Vect2, th: f64) -> bool {
    let gx = (c.x.min(d.x) - a.x.max(b.x)).max(a.x.min(b.x) - c.x.max(d.x));
    let gy = (c.y.min(d.y) - a.y.max(b.y)).max(a.y.min(b.y) - c.y.max(d.y));
    round_down(gx.max(gy)) >= th
}

/// q is certainly inside P: not on ∂P, and an odd crossing count (exact).
fn inside(p: &[Vect2], q: Vect2) -> bool {
    matches!(winding_number(p, q), Some((w, false)) if w % 2 != 0)
}

impl<'a> Rigid<'a> {
    /// The relative path of the point s + t·w against the polygon with vertices
    /// p_i + t·vel over [0, T] (parent module's definition of σ); `None` when a
    /// coordinate or a bound is not finite.
    pub(super) fn new(p: &'a [Vect2], vel: Vect2, s: Vect2, w: Vect2, t: f64) -> Option<Self> {
        let u = [
            Ball::exact(w.x).sub(Ball::exact(vel.x)),
            Ball::exact(w.y).sub(Ball::exact(vel.y)),
        ];
        let tb = Ball::exact(t);
        let ex = Ball::exact(s.x).add(tb.mul(u[0]));
        let ey = Ball::exact(s.y).add(tb.mul(u[1]));
        let e = Vect2::new(ex.z, ey.z);
        let rho2 = 2.0 * ex.r.max(ey.r);
        if !(e.is_finite() && rho2.is_finite()) {
            return None;
        }
        let s_out = matches!(winding_number(p, s), Some((w, false)) if w % 2 == 0);
        Some(Rigid {
            p,
            s,
            e,
            rho2,
            t,
            u,
            s_out,
        })
    }

    /// σ̃'s float geometry against P: its nearest approach to ∂P (ends against edges,
    /// vertices against σ̃, crossings) and its crossings.
    fn shape(&self) -> Shape {
        let (p, s, e) = (self.p, self.s, self.e);
        let d = e - s;
        let mut events = Vec::with_capacity(8);
        events.push(0.0);
        events.push(1.0);
        let mut best = (f64::INFINITY, 0.0, 0usize);
        let mut keep = |d2: f64, lam: f64, j: usize| {
            if d2 < best.0 {
                best = (d2, lam, j);
            }
        };
        for (j, a, b) in edges(p) {
            let ab = b - a;
            let den = cross(d, ab);
            if den != 0.0 {
                let lam = cross(a - s, ab) / den;
                let mu = cross(a - s, d) / den;
                if (0.0..=1.0).contains(&lam) && (0.0..=1.0).contains(&mu) {
                    events.push(lam);
                    keep(0.0, lam, j);
                }
            }
            keep(seg_dist2(s, a, b).0, 0.0, j);
            keep(seg_dist2(e, a, b).0, 1.0, j);
            for q in [a, b] {
                let (d2, lam) = seg_dist2(q, s, e);
                keep(d2, lam, j);
            }
        }
        events.sort_by(f64::total_cmp);
        Shape {
            near: (best.1, best.2),
            events,
        }
    }

    /// s outside P and every edge at least `th` (a ball) from σ̃, certified; then
    /// every point of σ is outside P and at least th − √2·ρ from ∂P (parent module).
    fn apart(&self, th: Ball) -> bool {
        if !self.s_out {
            return false;
        }
        let hi = th.hi();
        let dv = BallV::diff(self.e, self.s);
        let lim = th.sq().mul(dv.sq());
        // The side of σ̃'s line each vertex certainly lies on at least th away (0: not
        // certain): an edge with both ends on one side is at least th from the line.
        let side = |a: Vect2| {
            let c = dv.cross(BallV::diff(a, self.s));
            if nonnegative(c.sq().sub(lim)) != Tri::Yes {
                0
            } else if positive(c) == Tri::Yes {
                1
            } else if positive(c.neg()) == Tri::Yes {
                -1
            } else {
                0
            }
        };
        let n = self.p.len();
        let first = side(self.p[0]);
        let mut here = first;
        (0..n).all(|j| {
            let (a, b) = (self.p[j], self.p[(j + 1) % n]);
            let next = if j + 1 == n { first } else { side(b) };
            let far = here != 0 && here == next;
            here = next;
            far || boxes_apart(self.s, self.e, a, b, hi)
                || segments_at_least(self.s, self.e, a, b, th)
        })
    }

    /// σ's box and P's box are more than `reach` apart along x or y (rounded toward
    /// the safe side): every coordinate of a point of σ lies between s's and e's, and
    /// e's is within ρ ≤ 2ρ of ẽ's.
    fn boxes_apart(&self, reach: f64) -> bool {
        let (mut lo, mut hi) = (self.p[0], self.p[0]);
        for a in &self.p[1..] {
            lo = Vect2::new(lo.x.min(a.x), lo.y.min(a.y));
            hi = Vect2::new(hi.x.max(a.x), hi.y.max(a.y));
        }
        let (s, e, r) = (self.s, self.e, self.rho2);
        let slo = Vect2::new(round_down(s.x.min(e.x) - r), round_down(s.y.min(e.y) - r));
        let shi = Vect2::new(round_up(s.x.max(e.x) + r), round_up(s.y.max(e.y) + r));
        round_down(lo.x - shi.x) > reach
            || round_down(slo.x - hi.x) > reach
            || round_down(lo.y - shi.y) > reach
            || round_down(slo.y - hi.y) > reach
    }

    /// The point y(t*) for λ (t* = fl(λ·T) ∈ [0, T]): its float value and 2ρ_y, twice
    /// the bound of each coordinate's error.
    fn point(&self, lam: f64) -> (Vect2, f64) {
        let ts = Ball::exact((lam.clamp(0.0, 1.0) * self.t).min(self.t));
        let yx = Ball::exact(self.s.x).add(ts.mul(self.u[0]));
        let yy = Ball::exact(self.s.y).add(ts.mul(self.u[1]));
        (Vect2::new(yx.z, yy.z), 2.0 * yx.r.max(yy.r))
    }

    /// y(fl(λ·T)) is certainly within `th` of edge j (so of P).
    fn within_at(&self, lam: f64, j: usize, th: f64) -> bool {
        let (y, r2) = self.point(lam);
        let th = Ball::exact(th).sub(Ball::exact(r2));
        let (a, b) = (self.p[j], self.p[(j + 1) % self.p.len()]);
        y.is_finite() && positive(th) == Tri::Yes && within(y, a, b, th)
    }

    /// y(fl(λ·T)) is certainly inside P and at least `depth` from ∂P.
    fn deep_at(&self, lam: f64, depth: f64) -> bool {
        let (y, r2) = self.point(lam);
        let th = Ball::exact(depth).add(Ball::exact(r2));
        y.is_finite() && inside(self.p, y) && edges(self.p).all(|(_, a, b)| at_least(y, a, b, th))
    }

    /// The float point of σ̃ deepest inside P among the sampled ones: its λ (`None`
    /// when no sampled point is inside).
    fn deepest(&self, shape: &Shape) -> Option<f64> {
        let mut best: Option<(f64, f64)> = None;
        for w in shape.events.windows(2) {
            let (l0, l1) = (w[0], w[1]);
            if l1 <= l0 {
                continue;
            }
            for k in 1..SAMPLES {
                let lam = l0 + (l1 - l0) * (k as f64 / SAMPLES as f64);
                let y = self.s + (self.e - self.s).scale(lam);
                if !inside(self.p, y) {
                    continue;
                }
                let depth = edges(self.p)
                    .map(|(_, a, b)| seg_dist2(y, a, b).0)
                    .fold(f64::INFINITY, f64::min);
                if best.map_or(true, |(d, _)| depth > d) {
                    best = Some((depth, lam));
                }
            }
        }
        best.map(|(_, lam)| lam)
    }

    /// Some t ∈ [0, T] with dist(y(t), P) ≤ th, certified: at σ̃'s nearest approach to
    /// ∂P, or inside P at its deepest sampled point.
    fn touches(&self, shape: &Shape, th: f64) -> bool {
        let (lam, j) = shape.near;
        if self.within_at(lam, j, th) {
            return true;
        }
        let crosses = shape.events.len() > 2 || !self.s_out;
        crosses
            && self
                .deepest(shape)
                .is_some_and(|lam| self.deep_at(lam, 0.0))
    }

    /// The fast path's verdict for one cell (parent module): `No` Clear (every point of
    /// σ farther than `reach` from P), `Yes` Conflict (a witness within `near` of P when
    /// `near` is given, that is r ≤ D; else a witness deeper than `deep` inside P),
    /// `Unsure` otherwise, with whether each scan could still decide: the Clear scan
    /// cannot when some point of σ is certainly within `reach`, the near_{D−r} scan
    /// cannot when σ is certainly farther than `near` from P.
    pub(super) fn judge(&self, reach: f64, near: Option<f64>, deep: f64) -> Judged {
        if self.boxes_apart(reach) {
            return Judged::decided(Tri::No);
        }
        let reach_b = Ball::exact(reach).add(Ball::exact(self.rho2));
        if self.apart(reach_b) {
            return Judged::decided(Tri::No);
        }
        let shape = self.shape();
        let conflict = match near {
            Some(nd) => self.touches(&shape, nd),
            None => self
                .deepest(&shape)
                .is_some_and(|lam| self.deep_at(lam, deep)),
        };
        if conflict {
            return Judged::decided(Tri::Yes);
        }
        let scan_clear = !self.touches(&shape, reach);
        let scan_conflict = match near {
            Some(nd) => !self.apart(Ball::exact(round_up(nd + self.rho2))),
            None => true,
        };
        Judged {
            tri: Tri::Unsure,
            scan_clear,
            scan_conflict,
        }
    }
}

/// The fast path's answer: its verdict, and (when `Unsure`) which scans may still
/// decide.
pub(super) struct Judged {
    pub tri: Tri,
    pub scan_clear: bool,
    pub scan_conflict: bool,
}

impl Judged {
    /// A certified verdict: no scan needed.
    fn decided(tri: Tri) -> Judged {
        Judged {
            tri,
            scan_clear: false,
            scan_conflict: false,
        }
    }
}

#[cfg(test)]
mod tests;
