//! Paper A §II.I: the tests of dot_nn_lin, edge_detect_simp (with the exact contract of
//! its error bounds), edge_detect and detect_diff_2D.

use super::*;
use crate::detect::tests::v;

/// The interval encloses [lb, ub] from outside, tightly (a few ulps).
fn assert_encl(i: Interval, lb: f64, ub: f64) {
    let tight = |a: f64, b: f64| (a - b).abs() <= 1e-14 * (1.0 + b.abs());
    assert!(
        i.lb <= lb && i.ub >= ub && tight(i.lb, lb) && tight(i.ub, ub),
        "{i:?} does not tightly enclose [{lb}, {ub}]"
    );
}

/// The union of the two dot_nn_lin intervals, sampled, equals {t : f(t) ≥ 0}.
fn check_union(t: f64, ww: Vect2, vv: Vect2, aa: Vect2, bb: Vect2) {
    let lo = dot_nn_lin(t, ww, vv, aa, bb, Sign::Neg);
    let hi = dot_nn_lin(t, ww, vv, aa, bb, Sign::Pos);
    for k in 0..=64 {
        let tk = t * k as f64 / 64.0;
        let fk = (ww + vv.scale(tk)).dot(aa + bb.scale(tk));
        let inside = |i: &Interval| i.lb <= tk && tk <= i.ub;
        // Skip samples within rounding of a root.
        if fk.abs() < 1e-9 {
            continue;
        }
        assert_eq!(
            fk >= 0.0,
            inside(&lo) || inside(&hi),
            "t = {tk}, f = {fk}, {lo:?} {hi:?}"
        );
    }
}

/// Paper A §II.I at a window of one instant (T = 0): edge_detect accepts a point on
/// the bottom edge's line up to (1 + F)·‖aa‖ = 1.5 from its midpoint (aa the half
/// edge): x = 2.5, on the boundary, included; far outside the polygon's BUFF, so
/// detect_diff_2D says yes there (or leaves the boundary to exact arithmetic) and no
/// beyond. Every set the edge test forms is the single time 0, or empty.
#[test]
fn a_window_of_one_instant_is_walked() {
    // A thin bar (its short sides reach 0.05 beyond the corners), warping slowly.
    let p = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 0.2), v(0.0, 0.2)];
    let vels = [
        v(0.0, 0.0),
        v(0.0, 0.0),
        v(0.0, 1.0 / 64.0),
        v(0.0, 1.0 / 64.0),
    ];
    let at = |x: f64| detect_diff_2d_tri(0.0, v(x, 0.0), v(0.0, 2.0), &p[..], &vels[..], 0.5, 0.01);
    assert_eq!(at(2.4), Tri::Yes);
    // on the boundary: a yes, or undecided (then the exact fallback decides), never a no
    assert_ne!(at(2.5), Tri::No);
    assert_eq!(at(2.6), Tri::No);
    assert_eq!(at(3.5), Tri::No);
}

/// §II.I dot_nn_lin when vv = 0: (ww)·(aa + t·bb) is a line, its t² coefficient an
/// exact 0 (not a ball of radius ETA, which would make it a parabola with a second
/// root near |b|/ETA). Here the line is 2⁻⁷⁰·(5 − t), over a window reaching 2¹⁰⁰⁰:
/// the set where it is ≥ 0 is [0, 5], and no time near 2⁹⁹⁵, where the line is about
/// −2⁹²⁵, may be in either interval.
#[test]
fn a_line_stays_a_line_over_a_long_window() {
    let k = 2f64.powi(-35);
    let (ww, vv, aa, bb) = (v(k, 0.0), v(0.0, 0.0), v(5.0 * k, 0.0), v(-k, 0.0));
    let t = 2f64.powi(1000);
    let neg = dot_nn_lin(t, ww, vv, aa, bb, Sign::Neg);
    let pos = dot_nn_lin(t, ww, vv, aa, bb, Sign::Pos);
    assert!(
        neg.lb <= 0.0 && neg.ub >= 5.0 && neg.ub < 5.0 + 1e-9,
        "{neg:?}"
    );
    assert!(pos.is_empty(), "{pos:?}");
}

#[test]
fn dot_nn_lin_cases() {
    // A = 0, B = 0: f = C.
    check_union(2.0, v(1.0, 0.0), v(0.0, 0.0), v(1.0, 0.0), v(0.0, 0.0)); // C = 1
    assert!(dot_nn_lin(
        2.0,
        v(-1.0, 0.0),
        v(0.0, 0.0),
        v(1.0, 0.0),
        v(0.0, 0.0),
        Sign::Pos
    )
    .is_empty());
    // A = 0, B > 0: f = t − 1 ≥ 0 on [1, 2].
    let i = dot_nn_lin(
        2.0,
        v(-1.0, 0.0),
        v(1.0, 0.0),
        v(1.0, 0.0),
        v(0.0, 0.0),
        Sign::Pos,
    );
    assert_encl(i, 1.0, 2.0);
    // A = 0, B < 0: f = 1 − t ≥ 0 on [0, 1].
    let i = dot_nn_lin(
        2.0,
        v(1.0, 0.0),
        v(-1.0, 0.0),
        v(1.0, 0.0),
        v(0.0, 0.0),
        Sign::Neg,
    );
    assert_encl(i, 0.0, 1.0);
    // A > 0, two roots: (t − 1)(t − 3) = t² − 4t + 3 with ww = (−1,0), vv = (1,0),
    // aa = (−3,0), bb = (1,0): f = (t − 1)(t − 3).
    let (ww, vv, aa, bb) = (v(-1.0, 0.0), v(1.0, 0.0), v(-3.0, 0.0), v(1.0, 0.0));
    assert_encl(dot_nn_lin(4.0, ww, vv, aa, bb, Sign::Neg), 0.0, 1.0);
    assert_encl(dot_nn_lin(4.0, ww, vv, aa, bb, Sign::Pos), 3.0, 4.0);
    check_union(4.0, ww, vv, aa, bb);
    // A < 0: −(t − 1)(t − 3) ≥ 0 between the roots.
    let aa2 = v(3.0, 0.0);
    let bb2 = v(-1.0, 0.0);
    assert_encl(dot_nn_lin(4.0, ww, vv, aa2, bb2, Sign::Pos), 1.0, 3.0);
    assert!(dot_nn_lin(4.0, ww, vv, aa2, bb2, Sign::Neg).is_empty());
    // A < 0, double root: −(t − 2)², ww = (−2,0), vv = (1,0), aa = (2,0), bb = (−1,0).
    let i = dot_nn_lin(
        4.0,
        v(-2.0, 0.0),
        v(1.0, 0.0),
        v(2.0, 0.0),
        v(-1.0, 0.0),
        Sign::Pos,
    );
    // A double root: its enclosure widens to about √u of the coefficients' scale
    // (the discriminant, 0, is known to ±u·B²), around the exact time 2.
    assert!(i.lb <= 2.0 && i.ub >= 2.0 && i.ub - i.lb < 1e-6, "{i:?}");
    // A > 0, double root: (t − 2)² ≥ 0 everywhere.
    let i = dot_nn_lin(
        4.0,
        v(-2.0, 0.0),
        v(1.0, 0.0),
        v(-2.0, 0.0),
        v(1.0, 0.0),
        Sign::Pos,
    );
    assert_encl(i, 0.0, 4.0);
}

/// Found by paper_a_functions_vs_oracle: (ww + t·vv)·(aa + t·bb) = −1/16 for all t (ww·bb = 0
/// exactly, but its ball has a tiny radius, so the line's slope is a tiny float and
/// −c/b overflows). Rounding +∞ down gave NaN, and the set became everything.
#[test]
fn overflowing_linear_root_is_clamped() {
    let (ww, vv, aa, bb) = (v(0.25, 0.0), v(0.0, 0.0), v(-0.25, 0.0), v(0.0, -0.25));
    for s in Sign::BOTH {
        assert!(dot_nn_lin(0.125, ww, vv, aa, bb, s).is_empty(), "{s:?}");
    }
}

#[test]
fn tiny_leading_coefficient_is_not_zero() {
    // f(t) = 1e-9·(t − 1)(t − 1000): A = 1e-9 (PolyCARP would call it a line,
    // B·t + C = −1.001e-6·t + 1e-6, losing the root at 1000). Over T = 2000, f ≥ 0 on
    // [0, 1] ∪ [1000, 2000].
    let (ww, vv, aa, bb) = (v(-1.0, 0.0), v(1.0, 0.0), v(-1000e-9, 0.0), v(1e-9, 0.0));
    let lo = dot_nn_lin(2000.0, ww, vv, aa, bb, Sign::Neg);
    let hi = dot_nn_lin(2000.0, ww, vv, aa, bb, Sign::Pos);
    assert!((lo.ub - 1.0).abs() < 1e-12 && lo.lb == 0.0);
    assert!((hi.lb - 1000.0).abs() < 1e-9 && hi.ub == 2000.0);
}

/// Paper A Figure 2: a warping edge met twice. A(t) = (−2, 0) fixed, B(t) = (2, 2 − 2t),
/// s(t) = (t, 7/4 − 7t/4). cross(B − A, s − A) = 2t² − 5t + 3 = 2(t − 1)(t − 3/2):
/// the point is on the segment at t = 1 (s = (1, 0), B = (2, 0)) and at t = 3/2
/// (s = (3/2, −7/8) on the segment to B = (2, −1)), on the other side in between.
#[test]
fn warping_edge_met_twice() {
    let (a, va) = (v(-2.0, 0.0), v(0.0, 0.0));
    let (b, vb) = (v(2.0, 2.0), v(0.0, -2.0));
    let (s, vs) = (v(0.0, 1.75), v(1.0, -1.75));
    let f = 1e-4;
    assert!(edge_detect(1.2, s, vs, a, b, va, vb, f));
    assert!(!edge_detect(0.9, s, vs, a, b, va, vb, f));
    // From t0 = 1.1 (between the crossings) only the second crossing can be found.
    let t0 = 1.1;
    let (s1, a1, b1) = (s.at(vs, t0), a.at(va, t0), b.at(vb, t0));
    assert!(!edge_detect(0.3, s1, vs, a1, b1, va, vb, f));
    assert!(edge_detect(0.5, s1, vs, a1, b1, va, vb, f));
    // Either crossing alone is found in a window around it.
    assert!(edge_detect(
        0.2,
        s.at(vs, 0.9),
        vs,
        a.at(va, 0.9),
        b.at(vb, 0.9),
        va,
        vb,
        f
    ));
}

/// A window of one instant (t = 1) at which the point lies exactly on the boundary
/// of edge_detect_simp's perpendicular condition (|w × a| = F·‖a‖², the along one
/// holding with room): paper A says yes, so the engine must not certify "no". The
/// outer sets of the four quadratics then all shrink to the point [1, 1], and a
/// meeting of one point is still a meeting (first_meeting's `lb > ub` is strict).
#[test]
fn a_one_instant_window_on_the_boundary_is_not_missed() {
    let e = BallV::exact;
    for side in [0.5, -0.5] {
        let tri = edge_detect_simp_tri(
            Ball::exact(1.0),
            Ball::exact(1.0),
            e(v(-0.5, side)),
            e(v(1.0, 0.0)),
            e(v(1.0, 0.0)),
            e(v(0.0, 0.0)),
            true,
            0.5,
        );
        assert_ne!(tri, Tri::No, "w(1) = (0.5, {side})");
    }
}

/// §II.I over a window whose ends are balls that overlap (ta, tb ∈ [0.75, 1.25]):
/// for ta = 1.25 and tb = 0.75 the window is empty, so no answer may be a certain
/// yes, even for a point sitting on the edge's midpoint all the time (every t meets
/// inequalities (1)). Looking for a certain time in an empty inner window (a mutation
/// survivor: `ilo <= ihi` → `>`) certified it.
#[test]
fn an_empty_inner_window_certifies_nothing() {
    let (zero, a) = (BallV::exact(v(0.0, 0.0)), BallV::exact(v(1.0, 0.0)));
    let over = |ta: Ball, tb: Ball| edge_detect_simp_tri(ta, tb, zero, zero, a, zero, true, 0.5);
    let end = Ball { z: 1.0, r: 0.25 };
    assert_ne!(over(end, end), Tri::Yes);
    // the same scene over a window that is certainly not empty: a certain yes
    assert_eq!(over(Ball::exact(0.5), Ball::exact(1.5)), Tri::Yes);
}

/// §II.I with F = 0: the perpendicular conditions |w × a| ≤ 0 hold only at the one
/// instant t = 1 when the point crosses the edge's line (w = (−1 + t)·(0, 1) against
/// a = (2, 0)), inside the edge (w·a = 0), so paper A says yes, and the engine must
/// not settle the crossing's short meeting J as a certain no.
#[test]
fn a_one_point_crossing_is_not_settled_as_no() {
    let e = BallV::exact;
    let tri = edge_detect_simp_tri(
        Ball::exact(0.0),
        Ball::exact(2.0),
        e(v(0.0, -1.0)),
        e(v(0.0, 1.0)),
        e(v(2.0, 0.0)),
        e(v(0.0, 0.0)),
        true,
        0.0,
    );
    assert_ne!(tri, Tri::No);
    assert!(edge_detect_simp(
        2.0,
        v(0.0, -1.0),
        v(0.0, 1.0),
        v(2.0, 0.0),
        v(0.0, 0.0),
        0.0
    ));
}

/// Exact checks of [`simp_quadratics`]' contract (§II.I): for every exact w, v, a, b
/// within the balls ww, vv, aa, bb (each coordinate within its radius of the centre)
/// and every k within k1, the exact coefficients of F·‖a‖² ± w × a and
/// k·‖a‖² ± w·a (a = aa + t·bb, w = ww + t·vv) lie in the balls it returns. The
/// inputs are taken at corners of their boxes, where a product's deviation reaches the
/// bound's input terms exactly (n_x·r_y + n_y·r_x + 2·r_x·r_y), the corner chosen to
/// push each coefficient up and down in turn, and on exact inputs whose roundings are
/// as large as they get (mantissas just above a power of two, vectors on one axis, so
/// that ‖·‖₁² is no looser than the product it bounds).
mod simp_quadratics_contract {
    use super::*;
    use crate::detect::tests::{exact, float};
    use polyguard_oracle::{Arith, ExactField, Q};
    use proptest::prelude::*;

    /// One call's arguments.
    #[derive(Clone, Copy, Debug)]
    pub(super) struct Args {
        /// ww, vv, aa, bb.
        pub(super) vecs: [BallV; 4],
        pub(super) k1: Ball,
        pub(super) f: f64,
    }

    impl Args {
        /// The four centres as one array (w.x, w.y, v.x, v.y, a.x, a.y, b.x, b.y).
        fn centres(&self) -> [f64; 8] {
            core::array::from_fn(|m| {
                let v = self.vecs[m / 2].v;
                if m % 2 == 0 {
                    v.x
                } else {
                    v.y
                }
            })
        }

        /// bb is exactly zero: the caller's `bb0`.
        fn bb0(&self) -> bool {
            self.vecs[3].v == Vect2::ZERO && self.vecs[3].r == 0.0
        }
    }

    const W: usize = 0;
    const V: usize = 2;
    const A: usize = 4;
    const B: usize = 6;

    fn dot(c: &[Q; 8], p: usize, q: usize) -> Q {
        c[p].times(&c[q]).plus(&c[p + 1].times(&c[q + 1]))
    }

    fn cross(c: &[Q; 8], p: usize, q: usize) -> Q {
        c[p].times(&c[q + 1]).minus(&c[p + 1].times(&c[q]))
    }

    /// The exact coefficients (t², t, 1) of the four quadratics, in simp_quadratics'
    /// order (F·g + y, F·g − y, k·g + x, k·g − x), at the exact inputs `c` and `k`.
    pub(super) fn exact_coefficients(c: &[Q; 8], k: &Q, f: &Q) -> [[Q; 3]; 4] {
        let g = [dot(c, B, B), dot(c, A, B).twice(), dot(c, A, A)];
        let x = [dot(c, V, B), dot(c, W, B).plus(&dot(c, V, A)), dot(c, W, A)];
        let y = [
            cross(c, V, B),
            cross(c, W, B).plus(&cross(c, V, A)),
            cross(c, W, A),
        ];
        let quad = |kk: &Q, h: &[Q; 3], plus: bool| -> [Q; 3] {
            core::array::from_fn(|i| {
                let kg = kk.times(&g[i]);
                if plus {
                    kg.plus(&h[i])
                } else {
                    kg.minus(&h[i])
                }
            })
        };
        [
            quad(f, &y, true),
            quad(f, &y, false),
            quad(k, &x, true),
            quad(k, &x, false),
        ]
    }

    /// Adds α·∇(p·q) (or α·∇(p × q)) at the centres `c` to `g`.
    fn add_grad(g: &mut [f64; 9], c: &[f64; 8], alpha: f64, p: usize, q: usize, cross: bool) {
        if cross {
            g[p] += alpha * c[q + 1];
            g[p + 1] -= alpha * c[q];
            g[q] -= alpha * c[p + 1];
            g[q + 1] += alpha * c[p];
        } else {
            g[p] += alpha * c[q];
            g[p + 1] += alpha * c[q + 1];
            g[q] += alpha * c[p];
            g[q + 1] += alpha * c[p + 1];
        }
    }

    /// The gradient of coefficient i of quadratic j at the centres, over the eight
    /// coordinates and k (a guide to the corner that pushes it furthest).
    pub(super) fn gradient(args: &Args, j: usize, i: usize) -> [f64; 9] {
        let c = args.centres();
        let mut g = [0.0; 9];
        let (kappa, sigma, is_cross) = match j {
            0 => (args.f, 1.0, true),
            1 => (args.f, -1.0, true),
            2 => (args.k1.z, 1.0, false),
            _ => (args.k1.z, -1.0, false),
        };
        match i {
            0 => add_grad(&mut g, &c, kappa, B, B, false),
            1 => add_grad(&mut g, &c, 2.0 * kappa, A, B, false),
            _ => add_grad(&mut g, &c, kappa, A, A, false),
        }
        match i {
            0 => add_grad(&mut g, &c, sigma, V, B, is_cross),
            1 => {
                add_grad(&mut g, &c, sigma, W, B, is_cross);
                add_grad(&mut g, &c, sigma, V, A, is_cross);
            }
            _ => add_grad(&mut g, &c, sigma, W, A, is_cross),
        }
        if j >= 2 {
            let d = |p: usize, q: usize| c[p] * c[q] + c[p + 1] * c[q + 1];
            g[8] = [d(B, B), 2.0 * d(A, B), d(A, A)][i];
        }
        g
    }

    /// The exact input at a corner: each coordinate (and k) at its centre minus, at,
    /// or plus its radius (sign −1, 0, 1).
    pub(super) fn corner(args: &Args, s: &[i8; 9]) -> ([Q; 8], Q) {
        let shift = |z: f64, r: f64, s: i8| match s {
            1 => exact(z).plus(&exact(r)),
            -1 => exact(z).minus(&exact(r)),
            _ => exact(z),
        };
        let c = args.centres();
        let coords = core::array::from_fn(|m| shift(c[m], args.vecs[m / 2].r, s[m]));
        (coords, shift(args.k1.z, args.k1.r, s[8]))
    }

    /// The corners tried: the centre, each coefficient pushed up and down along its
    /// gradient's signs (a zero component taking either sign), and all coordinates
    /// at +r or −r together.
    fn corners(args: &Args) -> Vec<[i8; 9]> {
        let mut all = vec![[0; 9], [1; 9], [-1; 9]];
        for j in 0..4 {
            for i in 0..3 {
                let g = gradient(args, j, i);
                for dir in [1.0, -1.0] {
                    for zero in [1, -1] {
                        all.push(core::array::from_fn(|m| {
                            let d = dir * g[m];
                            if d > 0.0 {
                                1
                            } else if d < 0.0 {
                                -1
                            } else {
                                zero
                            }
                        }));
                    }
                }
            }
        }
        all.sort_unstable();
        all.dedup();
        all
    }

    /// Some(reason) when an exact coefficient at some corner lies outside its ball.
    fn breach(args: &Args) -> Option<String> {
        let [ww, vv, aa, bb] = args.vecs;
        let got = simp_quadratics(ww, vv, aa, bb, args.bb0(), args.k1, args.f);
        let f = exact(args.f);
        for s in corners(args) {
            let (c, k) = corner(args, &s);
            let want = exact_coefficients(&c, &k, &f);
            for (j, (balls, exact_c)) in got.iter().zip(&want).enumerate() {
                for (i, (ball, e)) in balls.iter().zip(exact_c).enumerate() {
                    if !(ball.z.is_finite() && ball.r >= 0.0 && ball.r.is_finite()) {
                        return Some(format!("quadratic {j} coefficient {i}: {ball:?}"));
                    }
                    let d = e.minus(&exact(ball.z));
                    let d = if d.is_neg() { d.negated() } else { d };
                    if d > exact(ball.r) {
                        return Some(format!(
                            "quadratic {j} coefficient {i} at corner {s:?}: {:e} off the \
                             centre {:e}, radius {:e}",
                            polyguard_oracle::convert::to_float(&d),
                            ball.z,
                            ball.r
                        ));
                    }
                }
            }
        }
        None
    }

    /// A coordinate: zero one time in four, else ±m·2^e.
    pub(super) fn coordinate(e: core::ops::Range<i32>) -> impl Strategy<Value = f64> {
        prop_oneof![
            1 => Just(0.0),
            3 => (any::<bool>(), 1.0..2.0f64, e).prop_map(|(n, m, e)| float(n, m, e)),
        ]
    }

    /// A ball vector: its radius exact zero one time in three, else 2^e from far below
    /// the centre to above it.
    fn ball_vector() -> impl Strategy<Value = BallV> {
        (
            coordinate(-20..20),
            coordinate(-20..20),
            prop_oneof![1 => Just(0.0), 2 => (-70..24i32).prop_map(|e| 2f64.powi(e))],
        )
            .prop_map(|(x, y, r)| BallV { v: v(x, y), r })
    }

    /// F ≥ 0, and k1 either as edge_detect_simp_tri makes it (1 + F and its rounding
    /// error) or any ball of positive centre, whose radius may be as large as half
    /// of it (the contract holds for every ball).
    pub(super) fn k_and_f() -> impl Strategy<Value = (Ball, f64)> {
        (
            prop_oneof![
                Just(0.0),
                (1.0..2.0f64, -60..4i32).prop_map(|(m, e)| float(false, m, e))
            ],
            prop_oneof![
                Just(None),
                (1.0..4.0f64, 1..60i32).prop_map(|(z, e)| Some(Ball {
                    z,
                    r: z * 2f64.powi(-e)
                })),
            ],
        )
            .prop_map(|(f, k)| {
                let k1 = k.unwrap_or_else(|| {
                    let (z, err) = crate::ball::exact::two_sum(1.0, f);
                    Ball { z, r: err.abs() }
                });
                (k1, f)
            })
    }

    /// A coordinate whose products round by nearly half an ulp: ±2^e·(1 + m·2⁻²⁷),
    /// so that the product of two is 2^e'·(1 + … + m·m'·2⁻⁵⁴) with the last term
    /// anywhere in an ulp.
    fn rounding_coordinate() -> impl Strategy<Value = f64> {
        (any::<bool>(), 1.0..2.0f64, -8..8i32)
            .prop_map(|(n, m, e)| float(n, 1.0 + m * 2f64.powi(-27), e))
    }

    /// An exact vector on one axis (‖·‖₁ is then its length, the bound's tightest case).
    fn rounding_vector() -> impl Strategy<Value = BallV> {
        (any::<bool>(), rounding_coordinate())
            .prop_map(|(on_x, z)| BallV::exact(if on_x { v(z, 0.0) } else { v(0.0, z) }))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        #[test]
        fn the_balls_hold_the_exact_coefficients(
            vecs in [ball_vector(), ball_vector(), ball_vector(), ball_vector()],
            (k1, f) in k_and_f(),
        ) {
            let args = Args { vecs, k1, f };
            if let Some(why) = breach(&args) {
                prop_assert!(false, "{:?}: {}", args, why);
            }
        }

        #[test]
        fn the_balls_hold_the_exact_coefficients_of_exact_inputs(
            vecs in [rounding_vector(), rounding_vector(), rounding_vector(), rounding_vector()],
            f in prop_oneof![Just(0.0), rounding_coordinate().prop_map(f64::abs)],
        ) {
            let (z, err) = crate::ball::exact::two_sum(1.0, f);
            let args = Args { vecs, k1: Ball { z, r: err.abs() }, f };
            if let Some(why) = breach(&args) {
                prop_assert!(false, "{:?}: {}", args, why);
            }
        }
    }
}

/// [`crossing_witness`]'s contract: a time it returns lies in the inner window, and there
/// each of the four exact quadratics of edge_detect_simp (§II.I) is ≥ 0 for every exact
/// input within the balls, checked in rationals at the centre and at the corners that
/// push each quadratic's value down (by the signs of its gradient, as the coefficient
/// contract above does). The candidates must also find most crossings, or the fast path
/// would be dead weight; and a check that ignores the radii, on crossings at the edge's
/// ends and at the F slack's rim, must be caught by the same exact test (the canary).
mod crossing_witness_contract {
    use super::simp_quadratics_contract::{
        coordinate, corner, exact_coefficients, gradient, k_and_f, Args,
    };
    use super::*;
    use crate::detect::tests::exact;
    use polyguard_oracle::{Arith, ExactField, Q};
    use proptest::prelude::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    /// The window [0, T] of the crossings generated.
    const T: f64 = 8.0;

    /// The exact value at t of each of the four quadratics at the corner `s`.
    fn values_at(args: &Args, s: &[i8; 9], t: &Q) -> [Q; 4] {
        let (c, k) = corner(args, s);
        let want = exact_coefficients(&c, &k, &exact(args.f));
        want.map(|[c2, c1, c0]| c2.times(t).plus(&c1).times(t).plus(&c0))
    }

    /// Some(reason) when some quadratic is negative at t at the centre or at a corner
    /// that pushes its value down.
    fn breach_at(args: &Args, t: f64) -> Option<String> {
        let tq = exact(t);
        let mut corners = vec![[0i8; 9], [1; 9], [-1; 9]];
        for j in 0..4 {
            // the gradient of the value c₂t² + c₁t + c₀ over the inputs
            let g: [f64; 9] = {
                let gs = [0, 1, 2].map(|i| gradient(args, j, i));
                core::array::from_fn(|m| (gs[0][m] * t + gs[1][m]) * t + gs[2][m])
            };
            for zero in [1, -1] {
                corners.push(core::array::from_fn(|m| {
                    if g[m] > 0.0 {
                        -1
                    } else if g[m] < 0.0 {
                        1
                    } else {
                        zero
                    }
                }));
            }
        }
        for s in corners {
            for (j, val) in values_at(args, &s, &tq).iter().enumerate() {
                if val.is_neg() {
                    return Some(format!("quadratic {j} negative at t = {t:e}, corner {s:?}"));
                }
            }
        }
        None
    }

    /// A point that crosses the edge's line at about t0, at u along the half-edge from
    /// its midpoint and e·F off it (both in units of the half-edge), rounded to floats:
    /// (ww, vv, aa, bb) as exact balls, or with the radius 2^−k·‖·‖∞ (k from `rad`).
    fn crossing(
        (a, b, vel): (Vect2, Vect2, Vect2),
        (t0, u, e, f): (f64, f64, f64, f64),
        rad: Option<i32>,
    ) -> [BallV; 4] {
        let at = a + b.scale(t0);
        let w = at.scale(u) + at.perp().scale(e * f) - vel.scale(t0);
        [w, vel, a, b].map(|x| BallV {
            v: x,
            r: rad.map_or(0.0, |k| x.x.abs().max(x.y.abs()) * 2f64.powi(-k)),
        })
    }

    /// Edges, velocities and the point's velocity: coordinates of 2^−10 … 2^10, the
    /// edge's velocity zero one time in four (a translating edge: bb = 0).
    fn motion() -> impl Strategy<Value = (Vect2, Vect2, Vect2)> {
        let c = || coordinate(-10..10);
        (
            (c(), c()).prop_filter("an edge", |&(x, y)| x != 0.0 || y != 0.0),
            prop_oneof![1 => Just((0.0, 0.0)), 3 => (c(), c())],
            (c(), c()),
        )
            .prop_map(|((ax, ay), (bx, by), (vx, vy))| (v(ax, ay), v(bx, by), v(vx, vy)))
    }

    /// A point that certainly crosses the edge's inside well within the slack.
    fn inside_crossing() -> impl Strategy<Value = [BallV; 4]> {
        (motion(), 0.0..T, -0.9..0.9f64, -0.01..0.01f64)
            .prop_map(|(m, t0, u, e)| crossing(m, (t0, u, e, 1e-4), None))
    }

    /// [`crossing_times`]' candidates that [`conditions_hold_at`] accepts with `sure`.
    fn witnesses(args: &Args, sure: impl Fn(Ball) -> bool + Copy) -> Vec<f64> {
        let [ww, vv, aa, bb] = args.vecs;
        crossing_times(ww.v, vv.v, aa.v, bb.v, 0.0)
            .into_iter()
            .filter(|&t| {
                (0.0..=T).contains(&t)
                    && conditions_hold_at(t, ww, vv, aa, bb, args.k1, args.f, sure)
            })
            .collect()
    }

    /// Draws `n` values of `s` from a fixed seed.
    fn draw<S: Strategy>(s: S, n: usize) -> Vec<S::Value> {
        let mut runner = TestRunner::deterministic();
        (0..n)
            .map(|_| s.new_tree(&mut runner).expect("a value").current())
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        #[test]
        fn a_witness_holds_at_every_corner(
            m in motion(),
            (t0, u, e) in (0.0..T, -1.2..1.2f64, -3.0..3.0f64),
            rad in prop_oneof![1 => Just(None), 2 => (20..60i32).prop_map(Some)],
            (k1, f) in k_and_f(),
        ) {
            let vecs = crossing(m, (t0, u, e, f.max(1e-6)), rad);
            let args = Args { vecs, k1, f };
            let [ww, vv, aa, bb] = vecs;
            if let Some(t) = crossing_witness(0.0, T, ww, vv, aa, bb, k1, f) {
                prop_assert!((0.0..=T).contains(&t), "{t}");
                if let Some(why) = breach_at(&args, t) {
                    prop_assert!(false, "{:?}: {}", args, why);
                }
            }
        }
    }

    /// Nine crossings in ten of an edge's inside, exact inputs and F = 10⁻⁴, get a
    /// witness: the fast path answers the common hit.
    #[test]
    fn most_inside_crossings_are_witnessed() {
        let cases = draw(inside_crossing(), 2000);
        let (z, err) = crate::ball::exact::two_sum(1.0, 1e-4);
        let k1 = Ball { z, r: err.abs() };
        let found = cases
            .iter()
            .filter(|&&[ww, vv, aa, bb]| {
                crossing_witness(0.0, T, ww, vv, aa, bb, k1, 1e-4).is_some()
            })
            .count();
        assert!(found >= 1800, "{found} of 2000");
    }

    /// The canary: on crossings at the rim (at an end of the edge, u = ±(1 + F), or at
    /// the slack's edge, e = ±1, each moved by a few ulps), a check that ignores the
    /// radii accepts times where an exact quadratic is negative, and the exact test
    /// above finds them; the engine's check accepts none of those.
    #[test]
    fn a_check_without_radii_is_caught() {
        let f = 1e-4;
        let (z, err) = crate::ball::exact::two_sum(1.0, f);
        let k1 = Ball { z, r: err.abs() };
        let rim = prop_oneof![
            (any::<bool>(), -4..4i32).prop_map(move |(n, k)| {
                let u = (1.0 + f) * (1.0 + f64::from(k) * 2f64.powi(-52));
                (if n { -u } else { u }, 0.0)
            }),
            (any::<bool>(), -4..4i32).prop_map(|(n, k)| {
                let e = 1.0 + f64::from(k) * 2f64.powi(-52);
                (0.0, if n { -e } else { e })
            }),
        ];
        let cases = draw((motion(), 0.0..T, rim), 3000);
        let (mut caught, mut engine_breaches) = (0, 0);
        for (m, t0, (u, e)) in cases {
            let args = Args {
                vecs: crossing(m, (t0, u, e, f), None),
                k1,
                f,
            };
            let loose = |b: Ball| b.z >= 0.0;
            caught += witnesses(&args, loose)
                .iter()
                .filter(|&&t| breach_at(&args, t).is_some())
                .count();
            let sure = |b: Ball| nonnegative(b) == Tri::Yes;
            engine_breaches += witnesses(&args, sure)
                .iter()
                .filter(|&&t| breach_at(&args, t).is_some())
                .count();
        }
        assert!(caught > 0, "the canary was not caught");
        assert_eq!(engine_breaches, 0);
    }
}

mod masks {
    //! detect_diff_2D (§II.I) answers with its filter four edges at a time
    //! ([`crate::detect::filter::lanes`]) as with the filter one edge at a time.
    use super::*;
    use crate::detect::filter::lanes::tests::{case, Case};
    use crate::detect::{detect_3d_tri, slab_window_balls};
    use crate::lanes::tests::{check_cases, NotSlice};
    use proptest::prelude::*;

    /// detect_diff_2D on slices (the masked loop) answers as on vertices that are not a
    /// slice (the scalar loop), from 0 over [0, T].
    #[test]
    fn detect_diff_on_masks_is_the_scalar_answer() {
        check_cases(case(), detect_diff);
    }

    fn detect_diff((p, vels, s, v, (_, t), f, b): Case) -> Result<(), TestCaseError> {
        prop_assert_eq!(
            detect_diff_2d_tri(t, s, v, &p[..], &vels[..], f, b),
            detect_diff_2d_tri(t, s, v, &NotSlice(&p), &vels[..], f, b)
        );
        Ok(())
    }

    /// detect_3D (§III), whose 2D part is detect_diff_2D over the slab window (from a
    /// time after 0 when the point enters the slab later), answers on slices as on
    /// vertices that are not a slice.
    #[test]
    fn detect_3d_on_masks_is_the_scalar_answer() {
        check_cases((case(), -3.0f64..3.0, -2.0f64..2.0), detect_3d);
    }

    fn detect_3d(
        ((p, vels, s, v, (_, t), f, b), sz, vz): (Case, f64, f64),
    ) -> Result<(), TestCaseError> {
        let (pmin, pmax) = (0.0, 1.0);
        let masked = detect_3d_tri(t, s, v, sz, vz, &p[..], &vels[..], pmin, pmax, 0.0, b, f);
        let scalar = detect_3d_tri(
            t,
            s,
            v,
            sz,
            vz,
            &NotSlice(&p),
            &vels[..],
            pmin,
            pmax,
            0.0,
            b,
            f,
        );
        prop_assert_eq!(masked, scalar);
        Ok(())
    }

    /// The slab windows above do start after 0 (or the test above would repeat the one
    /// before it): from 2 below the slab rising at 1, the point enters it at t = 2.
    #[test]
    fn the_slab_window_starts_later() {
        let (a, b) = slab_window_balls(10.0, -2.0, 1.0, 0.0, 1.0, 0.0).expect("a window");
        assert!(a.lo() > 1.9 && b.hi() < 3.1);
    }
}
