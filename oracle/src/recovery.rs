//! Recovery points, exactly: the minimum distance from s to the points that satisfy a
//! recovery condition, and the exact check of a given point (paper A §II's polygons,
//! §II.G's proximity as the distance to a segment, §II–§III's motion for `_at`).
//!
//! # Definitions
//! P is a simple counterclockwise polygon (closed), D ≥ 0, dist Euclidean (0 inside P).
//! - out: x is feasible when **dist(x, P) ≥ D**;
//! - in: x is feasible when **x ∈ P and dist(x, ∂P) ≥ D**.
//!
//! m = min {|x − s| : x feasible}. The minimiser lies on the boundary of the feasible set,
//! on a *feature*: an edge shifted by D along its normal (outward for out, inward for in)
//! or a circle of radius D about a vertex; it is either the nearest point to s of one
//! feature (the clamped projection on a shifted edge; the point of a circle on the ray from
//! its centre through s) or a point where two features meet. Every such candidate is built
//! exactly in a [`Tower`] of square roots (√|e|² for a shifted edge, one more root for a
//! line–circle or circle–circle meeting) and kept when it is feasible, decided exactly.
//! Every feasible candidate is at distance ≥ m from s, and the minimiser is one of them, so
//! m is the least of their distances: [`ExactMin`] holds their squared distances and
//! compares m with a rational exactly, without choosing among them.
//!
//! # The interval front
//! The exact decisions are the same with or without an interval filter in front of them
//! ([`recovery_with`]'s `filter`, on in the named functions):
//! - every tower sign is first read off a rigorous enclosure ([`Tower`]);
//! - feasibility first encloses the candidate and tests each edge's gap in intervals,
//!   deciding exactly only the edges whose enclosure holds 0;
//! - candidates are tested in the order of the lower ends of their enclosed squared
//!   distances, and once a feasible one is known to be at most U, those whose lower end
//!   exceeds U are dropped untested: each is farther than that feasible one, so it is not
//!   the minimum, and [`ExactMin::cmp_rational`] answers the same without it.

use core::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::kernel::interval::{enclose, Iv};
use crate::tower::{sign_q, Elem, Tower};

/// The exact minimum distance m, as the least of finitely many tower numbers.
#[derive(Clone, Debug)]
pub struct ExactMin {
    /// s itself is feasible (m = 0).
    pub zero: bool,
    /// The squared distances to s of the feasible candidates, each in its own tower.
    pub cands: Vec<(Tower, Elem)>,
}

/// The exact answer of a recovery query.
#[derive(Clone, Debug)]
pub enum ExactRecovery {
    /// The feasible set is not empty; its distance from s is m.
    Min(ExactMin),
    /// No point is feasible (recovery_in on a polygon thinner than 2D).
    Impossible,
}

impl ExactMin {
    /// The exact order of m and a rational r ≥ 0 (m² against r²: both are ≥ 0).
    pub fn cmp_rational(&self, r: &BigRational) -> Ordering {
        if self.zero {
            return sign_q(&-r.clone());
        }
        let r2 = r * r;
        let mut best = Ordering::Greater;
        for (t, d2) in &self.cands {
            match t.sign(&t.sub(d2, &t.rat(&r2))) {
                Ordering::Less => return Ordering::Less,
                Ordering::Equal => best = Ordering::Equal,
                Ordering::Greater => {}
            }
        }
        best
    }
}

/// Which condition.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Side {
    Out,
    In,
}

/// An exact point (x, y).
pub type Point = [BigRational; 2];
type Pt = Point;

/// The exact inputs: vertices (at time t), s, D; and whether the interval front runs.
struct Scene {
    v: Vec<Pt>,
    s: Pt,
    d: BigRational,
    filter: bool,
}

/// A candidate point, in its own tower.
type Cand = (Tower, [Elem; 2]);

/// The exact minimum for the out condition (module doc); `None` for D < 0 or fewer than
/// 3 vertices.
pub fn recovery_out(p: &[Point], s: &Point, d: &BigRational) -> Option<ExactRecovery> {
    recovery_with(p, None, s, d, false, true)
}

/// The exact minimum for the in condition (module doc), or `Impossible`.
pub fn recovery_in(p: &[Point], s: &Point, d: &BigRational) -> Option<ExactRecovery> {
    recovery_with(p, None, s, d, true, true)
}

/// [`recovery_out`] for the exact polygon (p_i + t·V_i) at time t.
pub fn recovery_out_at(
    p: &[Point],
    vels: &[Point],
    t: &BigRational,
    s: &Point,
    d: &BigRational,
) -> Option<ExactRecovery> {
    recovery_with(p, Some((vels, t)), s, d, false, true)
}

/// [`recovery_in`] for the exact polygon (p_i + t·V_i) at time t.
pub fn recovery_in_at(
    p: &[Point],
    vels: &[Point],
    t: &BigRational,
    s: &Point,
    d: &BigRational,
) -> Option<ExactRecovery> {
    recovery_with(p, Some((vels, t)), s, d, true, true)
}

/// The general form (module doc): the polygon at rest or at time t (`vels`), the in
/// condition when `keep_in`, the interval front when `filter` (the answer is the same
/// either way; without it every decision is the exact analysis alone).
pub fn recovery_with(
    p: &[Point],
    vels: Option<(&[Point], &BigRational)>,
    s: &Point,
    d: &BigRational,
    keep_in: bool,
    filter: bool,
) -> Option<ExactRecovery> {
    let mut sc = scene(p, vels, s, d)?;
    sc.filter = filter;
    Some(sc.solve(if keep_in { Side::In } else { Side::Out }))
}

/// Does x satisfy the out condition dist(x, P(t)) ≥ D exactly? (`vels` empty: static.)
pub fn satisfies_out(
    p: &[Point],
    vels: &[Point],
    t: &BigRational,
    x: &Point,
    d: &BigRational,
) -> bool {
    satisfies(p, vels, t, x, d, Side::Out)
}

/// Does x satisfy the in condition x ∈ P(t), dist(x, ∂P(t)) ≥ D exactly?
pub fn satisfies_in(
    p: &[Point],
    vels: &[Point],
    t: &BigRational,
    x: &Point,
    d: &BigRational,
) -> bool {
    satisfies(p, vels, t, x, d, Side::In)
}

fn satisfies(
    p: &[Point],
    vels: &[Point],
    t: &BigRational,
    x: &Point,
    d: &BigRational,
    side: Side,
) -> bool {
    let mv = if vels.is_empty() {
        None
    } else {
        Some((vels, t))
    };
    let Some(sc) = scene(p, mv, x, d) else {
        return false;
    };
    let tw = sc.tower();
    let x = [Elem::rat(sc.s[0].clone()), Elem::rat(sc.s[1].clone())];
    sc.feasible(side, &tw, &x)
}

/// The exact scene at time t, or `None` for D < 0, fewer than 3 vertices or a velocity
/// list of another length.
fn scene(
    p: &[Point],
    vels: Option<(&[Point], &BigRational)>,
    s: &Point,
    d: &BigRational,
) -> Option<Scene> {
    if d < &BigRational::zero() || p.len() < 3 {
        return None;
    }
    let v = match vels {
        None => p.to_vec(),
        Some((vs, t)) => {
            if vs.len() != p.len() {
                return None;
            }
            p.iter()
                .zip(vs)
                .map(|(a, w)| [&a[0] + t * &w[0], &a[1] + t * &w[1]])
                .collect()
        }
    };
    Some(Scene {
        v,
        s: s.clone(),
        d: d.clone(),
        filter: true,
    })
}

/// The sign of edge (a, e)'s gap dist²(x, segment) − D² (in the form
/// [`Scene::feasible`] computes exactly) from enclosures of x and D², when they settle
/// it and the branch it is computed by; `None` when an enclosure holds 0.
fn edge_gap_sign(x: &[Iv; 2], a: &Pt, e: &Pt, big_e: &BigRational, d2: Iv) -> Option<Ordering> {
    let (ex, ey, ee) = (enclose(&e[0]), enclose(&e[1]), enclose(big_e));
    let dx = x[0].sub(enclose(&a[0]));
    let dy = x[1].sub(enclose(&a[1]));
    let t = dx.mul(ex).add(dy.mul(ey));
    let gap = match t.sign().ok()? {
        Ordering::Less | Ordering::Equal => dx.sq().add(dy.sq()).sub(d2),
        Ordering::Greater => match t.sub(ee).sign().ok()? {
            Ordering::Greater | Ordering::Equal => {
                let (bx, by) = (dx.sub(ex), dy.sub(ey));
                bx.sq().add(by.sq()).sub(d2)
            }
            Ordering::Less => {
                let cr = dy.mul(ex).sub(dx.mul(ey));
                cr.sq().sub(d2.mul(ee))
            }
        },
    };
    gap.sign().ok()
}

fn sub(a: &Pt, b: &Pt) -> Pt {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

fn dot(a: &Pt, b: &Pt) -> BigRational {
    &a[0] * &b[0] + &a[1] * &b[1]
}

impl Scene {
    fn n(&self) -> usize {
        self.v.len()
    }

    fn edge(&self, i: usize) -> (Pt, Pt) {
        let a = self.v[i].clone();
        let b = self.v[(i + 1) % self.n()].clone();
        let e = sub(&b, &a);
        (a, e)
    }

    /// Is the tower point x feasible? Every edge at least D away (the squared distance
    /// to the segment, by the foot of the perpendicular), and the side of ∂P by the
    /// crossing parity of the upward ray (exact, as x is off ∂P when D > 0).
    fn feasible(&self, side: Side, tw: &Tower, x: &[Elem; 2]) -> bool {
        let d2 = &self.d * &self.d;
        let mut on_boundary = false;
        let front = self
            .filter
            .then(|| ([tw.enclose(&x[0]), tw.enclose(&x[1])], enclose(&d2)));
        for i in 0..self.n() {
            let (a, e) = self.edge(i);
            let big_e = dot(&e, &e);
            if let Some((xi, d2i)) = &front {
                match edge_gap_sign(xi, &a, &e, &big_e, *d2i) {
                    Some(Ordering::Less) => return false,
                    Some(Ordering::Greater) => continue,
                    _ => {}
                }
            }
            let dx = tw.sub(&x[0], &tw.rat(&a[0]));
            let dy = tw.sub(&x[1], &tw.rat(&a[1]));
            let t = tw.add(&dx.scale(&e[0]), &dy.scale(&e[1]));
            let gap = if tw.sign(&t) != Ordering::Greater {
                tw.sub(&tw.add(&tw.sq(&dx), &tw.sq(&dy)), &tw.rat(&d2))
            } else if tw.sign(&tw.sub(&t, &tw.rat(&big_e))) != Ordering::Less {
                let bx = tw.sub(&dx, &tw.rat(&e[0]));
                let by = tw.sub(&dy, &tw.rat(&e[1]));
                tw.sub(&tw.add(&tw.sq(&bx), &tw.sq(&by)), &tw.rat(&d2))
            } else {
                let cr = tw.sub(&dy.scale(&e[0]), &dx.scale(&e[1]));
                tw.sub(&tw.sq(&cr), &tw.rat(&(&d2 * &big_e)))
            };
            match tw.sign(&gap) {
                Ordering::Less => return false,
                Ordering::Equal if self.d.is_zero() => on_boundary = true,
                _ => {}
            }
        }
        match side {
            Side::Out if self.d.is_zero() => true,
            Side::Out => !self.inside(tw, x),
            Side::In => on_boundary || self.inside(tw, x),
        }
    }

    /// The crossing parity of the rightward ray from x (x off ∂P).
    fn inside(&self, tw: &Tower, x: &[Elem; 2]) -> bool {
        let mut odd = false;
        for i in 0..self.n() {
            let (a, e) = self.edge(i);
            let b = [&a[0] + &e[0], &a[1] + &e[1]];
            let above = |y: &BigRational| tw.sign(&tw.sub(&tw.rat(y), &x[1])) == Ordering::Greater;
            if above(&a[1]) == above(&b[1]) {
                continue;
            }
            // x_cross − x > 0 ⟺ (a_x − x)·e_y − (a_y − y)·e_x has the sign of e_y.
            let ax = tw.sub(&tw.rat(&a[0]), &x[0]);
            let ay = tw.sub(&tw.rat(&a[1]), &x[1]);
            let num = tw.sub(&ax.scale(&e[1]), &ay.scale(&e[0]));
            if tw.sign(&num) == sign_q(&e[1]) {
                odd = !odd;
            }
        }
        odd
    }

    /// A tower for a new candidate, filtered as the scene is.
    fn tower(&self) -> Tower {
        if self.filter {
            Tower::new()
        } else {
            Tower::unfiltered()
        }
    }

    /// |x − s|², in x's tower.
    fn dist2(&self, tw: &Tower, x: &[Elem; 2]) -> Elem {
        let dx = tw.sub(&x[0], &tw.rat(&self.s[0]));
        let dy = tw.sub(&x[1], &tw.rat(&self.s[1]));
        tw.add(&tw.sq(&dx), &tw.sq(&dy))
    }

    /// The exact minimum over the feasible candidates (module doc): every candidate
    /// without the filter; with it, in the order of their enclosed distances, the ones
    /// farther than a feasible one dropped untested.
    fn solve(&self, side: Side) -> ExactRecovery {
        let tw0 = self.tower();
        let s = [Elem::rat(self.s[0].clone()), Elem::rat(self.s[1].clone())];
        if self.feasible(side, &tw0, &s) {
            return ExactRecovery::Min(ExactMin {
                zero: true,
                cands: Vec::new(),
            });
        }
        let sig = if side == Side::Out {
            BigRational::one()
        } else {
            -BigRational::one()
        };
        let sd = &sig * &self.d;
        let mut all = Vec::new();
        let n = self.n();
        for i in 0..n {
            self.projection(&sd, i, &mut all);
            self.circle_nearest(i, &mut all);
            for j in 0..n {
                if j > i {
                    self.line_line(&sd, i, j, &mut all);
                    self.circle_circle(i, j, &mut all);
                }
                self.line_circle(&sd, i, j, &mut all);
            }
        }
        let (s0, s1) = (enclose(&self.s[0]), enclose(&self.s[1]));
        let mut ranked: Vec<(Iv, Tower, [Elem; 2])> = all
            .into_iter()
            .map(|(tw, x)| {
                let iv = if self.filter {
                    let dx = tw.enclose(&x[0]).sub(s0);
                    let dy = tw.enclose(&x[1]).sub(s1);
                    dx.sq().add(dy.sq())
                } else {
                    Iv::ENTIRE
                };
                (iv, tw, x)
            })
            .collect();
        ranked.sort_by(|a, b| a.0.lo.total_cmp(&b.0.lo));
        let mut out = Vec::new();
        let mut bound = Iv::ENTIRE;
        for (iv, tw, x) in ranked {
            if iv.lo > bound.hi {
                break;
            }
            if self.feasible(side, &tw, &x) {
                if iv.hi < bound.hi {
                    bound = iv;
                }
                let d2 = self.dist2(&tw, &x);
                out.push((tw, d2));
            }
        }
        if out.is_empty() {
            ExactRecovery::Impossible
        } else {
            ExactRecovery::Min(ExactMin {
                zero: false,
                cands: out,
            })
        }
    }

    /// The shifted edge i's start p0 = a + σD·N/√E (N = e⊥ = (e_y, −e_x)) in a tower
    /// holding √E as its first root; `None` for an edge of length 0 (a repeated vertex,
    /// whose features are its circle's).
    fn shifted_start(
        &self,
        sd: &BigRational,
        i: usize,
    ) -> Option<(Tower, [Elem; 2], Pt, BigRational)> {
        let (a, e) = self.edge(i);
        let big_e = dot(&e, &e);
        if big_e.is_zero() {
            return None;
        }
        let mut tw = self.tower();
        let root = tw.adjoin(&Elem::rat(big_e.clone()))?;
        let k = sd / &big_e;
        let p0 = [
            tw.add(&tw.rat(&a[0]), &root.scale(&(&k * &e[1]))),
            tw.add(&tw.rat(&a[1]), &root.scale(&(-&k * &e[0]))),
        ];
        Some((tw, p0, e, big_e))
    }

    /// The clamped projection of s on shifted edge i (the parameter along e is rational).
    fn projection(&self, sd: &BigRational, i: usize, out: &mut Vec<Cand>) {
        let Some((tw, p0, e, big_e)) = self.shifted_start(sd, i) else {
            return;
        };
        let tau = dot(&sub(&self.s, &self.v[i]), &e) / &big_e;
        let tau = tau.clamp(BigRational::zero(), BigRational::one());
        let x = [
            tw.add(&p0[0], &tw.rat(&(&tau * &e[0]))),
            tw.add(&p0[1], &tw.rat(&(&tau * &e[1]))),
        ];
        out.push((tw, x));
    }

    /// The point of the circle about vertex i on the ray from it through s.
    fn circle_nearest(&self, i: usize, out: &mut Vec<Cand>) {
        let w = sub(&self.s, &self.v[i]);
        let l2 = dot(&w, &w);
        if l2.is_zero() {
            return;
        }
        let mut tw = self.tower();
        let Some(root) = tw.adjoin(&Elem::rat(l2.clone())) else {
            return;
        };
        let k = &self.d / &l2;
        let x = [
            tw.add(&tw.rat(&self.v[i][0]), &root.scale(&(&k * &w[0]))),
            tw.add(&tw.rat(&self.v[i][1]), &root.scale(&(&k * &w[1]))),
        ];
        out.push((tw, x));
    }

    /// Where shifted edges i and j meet: N_i·x = N_i·a_i + σD√E_i, likewise j (Cramer).
    fn line_line(&self, sd: &BigRational, i: usize, j: usize, out: &mut Vec<Cand>) {
        let (ai, ei) = self.edge(i);
        let (aj, ej) = self.edge(j);
        let ni = [ei[1].clone(), -&ei[0]];
        let nj = [ej[1].clone(), -&ej[0]];
        let det = &ni[0] * &nj[1] - &ni[1] * &nj[0];
        if det.is_zero() {
            return;
        }
        let mut tw = self.tower();
        let (Some(ri), Some(rj)) = (
            tw.adjoin(&Elem::rat(dot(&ei, &ei))),
            tw.adjoin(&Elem::rat(dot(&ej, &ej))),
        ) else {
            return;
        };
        let ci = tw.add(&tw.rat(&dot(&ni, &ai)), &ri.scale(sd));
        let cj = tw.add(&tw.rat(&dot(&nj, &aj)), &rj.scale(sd));
        let inv = BigRational::one() / det;
        let x = tw.sub(&ci.scale(&nj[1]), &cj.scale(&ni[1])).scale(&inv);
        let y = tw.sub(&cj.scale(&ni[0]), &ci.scale(&nj[0])).scale(&inv);
        out.push((tw, [x, y]));
    }

    /// Where shifted edge i (p0 + τe) meets the circle about vertex j:
    /// E τ² + 2Bτ + C = 0, B = e·(p0 − v_j), C = |p0 − v_j|² − D².
    fn line_circle(&self, sd: &BigRational, i: usize, j: usize, out: &mut Vec<Cand>) {
        let Some((mut tw, p0, e, big_e)) = self.shifted_start(sd, i) else {
            return;
        };
        let wx = tw.sub(&p0[0], &tw.rat(&self.v[j][0]));
        let wy = tw.sub(&p0[1], &tw.rat(&self.v[j][1]));
        let b = tw.add(&wx.scale(&e[0]), &wy.scale(&e[1]));
        let c = tw.sub(
            &tw.add(&tw.sq(&wx), &tw.sq(&wy)),
            &tw.rat(&(&self.d * &self.d)),
        );
        let disc = tw.sub(&tw.sq(&b), &c.scale(&big_e));
        let Some(root) = tw.adjoin(&disc) else {
            return;
        };
        let inv_e = BigRational::one() / &big_e;
        for sgn in [BigRational::one(), -BigRational::one()] {
            let tau = tw.add(&b.scale(&-&inv_e), &root.scale(&(&sgn * &inv_e)));
            let x = [
                tw.add(&p0[0], &tau.scale(&e[0])),
                tw.add(&p0[1], &tau.scale(&e[1])),
            ];
            out.push((tw.clone(), x));
        }
    }

    /// Where the circles about vertices i and j meet: m ± (v_j − v_i)⊥·h,
    /// h² = (D² − L/4)/L, L = |v_j − v_i|².
    fn circle_circle(&self, i: usize, j: usize, out: &mut Vec<Cand>) {
        let w = sub(&self.v[j], &self.v[i]);
        let l = dot(&w, &w);
        if l.is_zero() {
            return;
        }
        let quarter = BigRational::new(1.into(), 4.into());
        let h2 = (&self.d * &self.d - &l * &quarter) / &l;
        let mut tw = self.tower();
        let Some(h) = tw.adjoin(&Elem::rat(h2)) else {
            return;
        };
        let half = BigRational::new(1.into(), 2.into());
        let m = [
            (&self.v[i][0] + &self.v[j][0]) * &half,
            (&self.v[i][1] + &self.v[j][1]) * &half,
        ];
        for sgn in [BigRational::one(), -BigRational::one()] {
            let x = [
                tw.add(&tw.rat(&m[0]), &h.scale(&(&sgn * &w[1]))),
                tw.add(&tw.rat(&m[1]), &h.scale(&(-&sgn * &w[0]))),
            ];
            out.push((tw.clone(), x));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn pt(x: i64, y: i64) -> Point {
        [r(x, 1), r(y, 1)]
    }

    fn sq2() -> Vec<Point> {
        vec![pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)]
    }

    fn min_of(e: Option<ExactRecovery>) -> ExactMin {
        match e {
            Some(ExactRecovery::Min(m)) => m,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn square_out_and_in() {
        let zero = r(0, 1);
        let half = r(1, 2);
        // From the centre, out of the 1/2-neighbourhood: 3/2 exactly.
        let m = min_of(recovery_out(&sq2(), &pt(1, 1), &half));
        assert_eq!(m.cmp_rational(&r(3, 2)), Ordering::Equal);
        // From (−1, −1) into the 1/2-core: to (1/2, 1/2), √(9/2), between 2.121 and 2.122.
        let m = min_of(recovery_in(&sq2(), &pt(-1, -1), &half));
        assert_eq!(m.cmp_rational(&r(2121, 1000)), Ordering::Greater);
        assert_eq!(m.cmp_rational(&r(2122, 1000)), Ordering::Less);
        let at = |x: BigRational, y: BigRational| [x, y];
        assert!(satisfies_in(
            &sq2(),
            &[],
            &zero,
            &at(half.clone(), half.clone()),
            &half
        ));
        assert!(!satisfies_in(
            &sq2(),
            &[],
            &zero,
            &at(half.clone(), r(49, 100)),
            &half
        ));
        assert!(satisfies_out(
            &sq2(),
            &[],
            &zero,
            &at(r(5, 2), r(1, 1)),
            &half
        ));
        assert!(!satisfies_out(
            &sq2(),
            &[],
            &zero,
            &at(r(23, 10), r(23, 10)),
            &half
        ));
    }

    #[test]
    fn thin_rectangle_has_no_core() {
        let p = [pt(0, 0), pt(10, 0), [r(10, 1), r(1, 2)], [r(0, 1), r(1, 2)]];
        assert!(matches!(
            recovery_in(&p, &[r(5, 1), r(1, 4)], &r(3, 10)),
            Some(ExactRecovery::Impossible)
        ));
    }
}
