//! Paper A, function by function: each function of the f64 engine against the exact
//! oracle's function of the same name (`polyguard_oracle::{quad, contain, proximity,
//! detect, well_formed}`), on dyadic grids where the engine's arithmetic is exact.
//!
//! Why the grids make the comparison exact. Every input is k·h for a small integer k and a
//! power of two h (BUFF and F are small dyadics too), and lookaheads T are powers of two
//! with velocities D/T for grid displacements D, so that T·v = D and p + T·v stay on the
//! grid. A sum, difference or product of such numbers is again an integer multiple of a
//! power of two; as long as that integer stays below 2⁵³ the f64 operation is exact. The
//! bounds, per function (K: largest |integer| of a coordinate difference or coefficient):
//! - §I quad_min_le_D: b² − 4a(c − D) is degree 2 in the coefficients (≤ 9K²).
//! - §I quad_min_box_le_D: the interior test is degree 5 in the coefficients: with
//!   |coefficient| ≤ M units, disc ≤ 5M², mx, my ≤ 3M², and each term of
//!   quad2D(a, b, c, d·disc, e·disc, f·disc²)(mx, my) and D·disc² is ≤ 25M⁵, their partial
//!   sums ≤ 82M⁵ < 2⁵³ for M ≤ 512.
//! - §II.G segments_close (and everything that calls it: §II.H, §II.J): the box
//!   coefficients come from q = c − e, u = d − c, w = f − e. With L² ≥ q², u², w² (in grid
//!   units), disc = −4(u×w)², mx = 4(w×q)(w×u), my = −4(u×q)(u×w), so |disc|, |mx|, |my| ≤ 4L⁴
//!   and the partial sums of the interior test are ≤ 144·L¹⁰ grid units¹⁰. All points within
//!   |k| ≤ 7 of the origin give L² ≤ 2·14² = 392 and 144·392⁵ ≈ 1.3·10¹⁵ < 2⁵³ ≈ 9·10¹⁵;
//!   BUFF is a multiple of h/4 no larger than L, so BUFF²·disc² ≤ 256·L¹⁰ (h/4)²h⁸ units.
//!   The suites check this precondition on every case ([`box_exact`]).
//! - §II.C near_edge, §II.D, §II.E: degree ≤ 4 in coordinates, far below 2⁵³ on any grid
//!   used here.
//! - §II.J step 3 compares g·h with −cos κ·√(g²h²) (a rounded square root): with cos κ = k/64
//!   and g, h integer grid vectors (|g|, |h| ≤ √392), (g·h)² and cos²κ·g²h² differ by
//!   ≥ 1/4096 grid units⁴ when they differ at all, so |g·h| and cos κ·|g||h| differ by a
//!   relative 7·10⁻¹⁰ or more, far above the 2⁻⁵² rounding; when they are equal, g²h² is a
//!   perfect square, whose square root is exact.
//!
//! So for §I, §II.B–§II.H and §II.J the engine must equal the oracle exactly, boundary ties
//! included (distance exactly BUFF, a vertex exactly on the ray, disc exactly 0, parallel
//! and collinear segments), and the small grids hit those ties often.
//!
//! §II.I and §III take square roots and divide. The engine's dot_nn_lin returns an outer
//! enclosure of the exact interval (the certified engine rounds every end outward), so
//! the suites check that the engine's pair of intervals contains the exact pair, and that
//! each end is within 10⁻¹² (relative, plus 10⁻¹²·max(1, T) absolute) of the exact
//! algebraic end ([`Alg`]), or within 10⁻⁶ where a root is double or nearly so (there the
//! discriminant, 0 or nearly, is known to ±u·B² and its square root to ±√u·|B|). The
//! boolean detectors are checked where the exact answer is robust: the engine must equal
//! the oracle whenever the oracle gives the same answer with F (and, for §III, BUFF)
//! scaled by 1 − 2⁻²⁰ and by 1 + 2⁻²⁰.
//!
//! On an edge that collapses to a point at some t ∈ [0, T] (a repeated vertex, or
//! p_j − p_i + t·(v_j − v_i) = 0), inequalities (1) hold trivially at that t and the
//! paper's edge_detect is true wherever the point is. The engine's swept-box filter only
//! rejects edges that provably never collapse, so it says true there too
//! (`edge_detect_on_collapsing_edges_never_misses`).
//!
//! dot_nn_lin's sign σ only labels which of the two intervals is which: the paper specifies
//! their union. The engine and the oracle label the one-interval cases differently (the
//! engine gives it to σ = +1 except for A = 0, B < 0; the oracle always to σ = −1), so the
//! interval suites compare the pair of intervals up to that swap.

mod common;
use common::{dist2_point_segment, dist2_segments, q, qpoly, qv};
use std::cmp::Ordering;
use std::f64::consts::TAU;

use polyguard::contain::Perturbed;
use polyguard::{
    definitely_outside, detect_3d, detect_diff_2d, detect_same_2d, dot_nn, dot_nn_lin, edge_detect,
    edge_detect_simp, near_edge, num_cross, perturb, quad_min_box_le_d, quad_min_le_d,
    segments_close, well_formed, Interval, Sign, Vect2,
};
use polyguard_oracle::convert::to_float;
use polyguard_oracle::detect::Interval as ExactInterval;
use polyguard_oracle::qfield::Alg;
use polyguard_oracle::{
    contain as oc, detect as od, proximity as op, quad as oq, well_formed as ow, Arith, Decided,
    Exact, ExactField, Q, V2,
};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(512)
}

// ------------------------------------------------------------------ exact conversions

/// The relative step of the robustness check of the §II.I/§III detectors.
const DELTA: f64 = 1.0 / 1_048_576.0;

/// x·(1 − 2⁻²⁰) (`up` false) or x·(1 + 2⁻²⁰), exactly (x has few significant bits).
fn nudged(x: f64, up: bool) -> Q {
    q(x * if up { 1.0 + DELTA } else { 1.0 - DELTA })
}

// ------------------------------------------------------------------ grid strategies

/// k·step for k in −r..=r.
fn grid(r: i32, step: f64) -> impl Strategy<Value = f64> + Clone {
    (-r..=r).prop_map(move |k| f64::from(k) * step)
}

/// k·step for k in lo..=hi.
fn grid_in(lo: i32, hi: i32, step: f64) -> impl Strategy<Value = f64> + Clone {
    (lo..=hi).prop_map(move |k| f64::from(k) * step)
}

/// A grid point with both coordinates k·step, |k| ≤ r.
fn gpt(r: i32, step: f64) -> impl Strategy<Value = Vect2> + Clone {
    (grid(r, step), grid(r, step)).prop_map(|(x, y)| Vect2::new(x, y))
}

/// Two grid points, equal one time in eight (a degenerate segment).
fn gseg(r: i32, step: f64) -> impl Strategy<Value = (Vect2, Vect2)> + Clone {
    (gpt(r, step), gpt(r, step), 0u8..8).prop_map(|(a, b, k)| (a, if k == 0 { a } else { b }))
}

/// Any polygon (possibly self-intersecting, with repeated vertices) on the grid.
fn any_poly(nmax: usize, r: i32, step: f64) -> impl Strategy<Value = Vec<Vect2>> + Clone {
    prop::collection::vec(gpt(r, step), 3..=nmax)
}

/// A star-shaped polygon around the origin (counterclockwise, or clockwise one time in
/// four), its vertices rounded to the grid (so collinear or repeated ones are possible).
fn star_poly(nmax: usize, r: i32, step: f64) -> impl Strategy<Value = Vec<Vect2>> + Clone {
    (
        3..=nmax,
        prop::collection::vec((0.0f64..0.7, ((r + 1) / 2)..=r), nmax),
        0u8..4,
        0.0f64..0.3,
    )
        .prop_map(move |(n, spokes, dir, phase)| {
            let mut ps: Vec<Vect2> = Vec::with_capacity(n);
            for (i, &(jitter, rad)) in spokes.iter().take(n).enumerate() {
                let ang = TAU * (i as f64 + phase + jitter) / n as f64;
                let rad = f64::from(rad);
                let p = Vect2::new(
                    (rad * ang.cos()).round() * step,
                    (rad * ang.sin()).round() * step,
                );
                if ps.last() != Some(&p) {
                    ps.push(p);
                }
            }
            if dir == 0 {
                ps.reverse();
            }
            ps
        })
}

/// A rectilinear polygon: a rectangle or an L (right-angle corners, §II.J ties at cos κ =
/// 0), sometimes with an extra vertex inside its first edge (a straight corner);
/// counterclockwise, or clockwise one time in four.
fn rect_poly(r: i32, step: f64) -> impl Strategy<Value = Vec<Vect2>> + Clone {
    (
        prop::collection::btree_set(-r..=r, 3),
        prop::collection::btree_set(-r..=r, 3),
        0u8..4,
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(move |(xs, ys, dir, ell, mid)| {
            let xs: Vec<f64> = xs.into_iter().map(|k| f64::from(k) * step).collect();
            let ys: Vec<f64> = ys.into_iter().map(|k| f64::from(k) * step).collect();
            let (x0, xm, x1) = (xs[0], xs[1], xs[2]);
            let (y0, ym, y1) = (ys[0], ys[1], ys[2]);
            let v = Vect2::new;
            let mut ps = if ell {
                vec![
                    v(x0, y0),
                    v(x1, y0),
                    v(x1, ym),
                    v(xm, ym),
                    v(xm, y1),
                    v(x0, y1),
                ]
            } else {
                vec![v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y1)]
            };
            if mid {
                ps.insert(1, v(xm, y0));
            }
            if dir == 0 {
                ps.reverse();
            }
            ps
        })
}

/// A polygon: arbitrary or star-shaped.
fn poly(nmax: usize, r: i32, step: f64) -> impl Strategy<Value = Vec<Vect2>> + Clone {
    prop_oneof![any_poly(nmax, r, step), star_poly(nmax, r, step)]
}

/// A power of two 2^k, k in lo..=hi (a lookahead T with T·(D/T) = D exactly).
fn pow2(lo: i32, hi: i32) -> impl Strategy<Value = f64> + Clone {
    (lo..=hi).prop_map(|k| 2f64.powi(k))
}

/// F, the small fraction of §II.I.
fn fac() -> impl Strategy<Value = f64> + Clone {
    prop::sample::select(vec![1.0 / 8.0, 1.0 / 16.0, 1.0 / 64.0, 1.0 / 1024.0])
}

/// |x/unit| is an integer ≤ max.
fn on_grid(x: f64, unit: f64, max: f64) -> bool {
    let k = x / unit;
    k == k.round() && k.abs() <= max
}

/// The precondition of the exactness of quad_min_box_le_D on segments between these
/// points (module doc): every coordinate is k·step with |k| ≤ 7.
fn box_exact(pts: &[Vect2], step: f64) -> bool {
    pts.iter()
        .all(|p| on_grid(p.x, step, 7.0) && on_grid(p.y, step, 7.0))
}

// ------------------------------------------------------------------ ties

/// √d2 when it is k·unit with 1 ≤ k ≤ max (a BUFF that makes the distance √d2 a tie).
fn grid_sqrt(d2: &Q, unit: f64, max: f64) -> Option<f64> {
    let b = to_float(d2).sqrt();
    (b > 0.0 && on_grid(b, unit, max) && q(b).sq() == *d2).then_some(b)
}

/// BUFF for a case: with `tie` (half the cases), one of the squared distances `d2s`
/// whose square root is on the BUFF grid (distance exactly BUFF); else `fallback`.
fn pick_buff(
    tie: Option<prop::sample::Index>,
    d2s: &[Q],
    unit: f64,
    max: f64,
    fallback: f64,
) -> f64 {
    let Some(i) = tie else { return fallback };
    let ties: Vec<f64> = d2s
        .iter()
        .filter_map(|d2| grid_sqrt(d2, unit, max))
        .collect();
    if ties.is_empty() {
        fallback
    } else {
        ties[i.index(ties.len())]
    }
}

/// The squared horizontal and vertical offsets at which §II.B's perturbation of vertex p
/// flips (|p_x − s_x| = BUFF, p_y = s_y − BUFF).
fn perturb_ties(p: &V2<Q>, s: &V2<Q>) -> [Q; 2] {
    [p.x.minus(&s.x).sq(), s.y.minus(&p.y).sq()]
}

/// Half the cases carry a tie index (see [`pick_buff`]).
fn tie() -> impl Strategy<Value = Option<prop::sample::Index>> {
    prop::option::weighted(0.5, any::<prop::sample::Index>())
}

// ------------------------------------------------------------------ §II.I intervals

/// Tolerance for an interval end x computed by the engine with lookahead T.
fn tol(x: f64, t: f64) -> f64 {
    1e-12 * x.abs() + 1e-12 * t.max(1.0)
}

/// The exact number a lies within tol(x, T) of the engine's x (decided exactly).
fn alg_near(a: &Alg<Q>, x: f64, t: f64) -> bool {
    if !x.is_finite() {
        return false;
    }
    let e = tol(x, t);
    let (lo, hi) = (x - e, x + e);
    if !(lo.is_finite() && hi.is_finite()) {
        return false;
    }
    a.cmp_rat(&q(lo)) != Ordering::Less && a.cmp_rat(&q(hi)) != Ordering::Greater
}

/// An exact interval end, rounded, for messages only.
fn approx(a: &Alg<Q>) -> f64 {
    (to_float(&a.p) + to_float(&a.q) * to_float(&a.d).sqrt()) / to_float(&a.r)
}

fn show(e: &ExactInterval<Alg<Q>>) -> String {
    match e {
        ExactInterval::Empty => "empty".to_string(),
        ExactInterval::Closed { lb, ub } => format!("[{:e}, {:e}]", approx(lb), approx(ub)),
    }
}

/// The engine's interval agrees with the exact one: both ends within tolerance; an
/// engine interval that is empty (lb > ub) or not agrees with the exact emptiness unless
/// it is within tolerance of degenerate. The engine's empty sentinel (+∞, −∞) comes only
/// from exact sign decisions and must match an exactly empty interval.
fn interval_matches(g: &Interval, e: &ExactInterval<Alg<Q>>, t: f64) -> bool {
    let sentinel = *g == Interval::EMPTY;
    match e {
        ExactInterval::Empty => sentinel || g.lb > g.ub || g.ub - g.lb <= tol(g.ub, t),
        ExactInterval::Closed { lb, ub } => {
            !sentinel && alg_near(lb, g.lb, t) && alg_near(ub, g.ub, t)
        }
    }
}

/// The engine's pair (σ = −1, σ = +1) against the oracle's, up to the σ labels.
fn pair_matches(g: &[Interval; 2], e: &[ExactInterval<Alg<Q>>; 2], t: f64) -> bool {
    let m = |i: usize, j: usize| interval_matches(&g[i], &e[j], t);
    (m(0, 0) && m(1, 1)) || (m(0, 1) && m(1, 0))
}

/// Every exact interval lies inside one of the engine's (decided exactly): the engine's
/// pair is an outer enclosure, so it never loses a time paper A accepts.
fn pair_contains(g: &[Interval; 2], e: &[ExactInterval<Alg<Q>>; 2]) -> bool {
    e.iter().all(|x| match x {
        ExactInterval::Empty => true,
        ExactInterval::Closed { lb, ub } => g.iter().any(|i| {
            i.lb.is_finite()
                && i.ub.is_finite()
                && lb.cmp_rat(&q(i.lb)) != Ordering::Less
                && ub.cmp_rat(&q(i.ub)) != Ordering::Greater
        }),
    })
}

/// The engine's pair is an outer enclosure of the exact one, tight to 10⁻¹² (or to 10⁻⁶
/// in total width beyond the exact pair, near a double root).
fn pair_encloses(g: &[Interval; 2], e: &[ExactInterval<Alg<Q>>; 2], t: f64) -> bool {
    if !pair_contains(g, e) {
        return false;
    }
    if pair_matches(g, e, t) {
        return true;
    }
    let width = |i: &Interval| if i.lb > i.ub { 0.0 } else { i.ub - i.lb };
    let exact_width: f64 = e
        .iter()
        .map(|x| match x {
            ExactInterval::Empty => 0.0,
            ExactInterval::Closed { lb, ub } => approx(ub) - approx(lb),
        })
        .sum();
    width(&g[0]) + width(&g[1]) - exact_width <= 1e-6 * t.max(1.0)
}

/// Does the moving edge vector aa + t·bb vanish at some t ∈ [0, T] (decided exactly)?
/// Then inequalities (1) of §II.I hold trivially at that t (both sides are 0), and the
/// paper's edge_detect_simp is true whatever ww and vv are.
fn collapses(t: &Q, aa: &V2<Q>, bb: &V2<Q>) -> bool {
    if !aa.cross(bb).is_zero_() {
        return false;
    }
    if bb.is_zero() {
        return aa.is_zero();
    }
    // aa ∥ bb, bb ≠ 0: aa + t·bb = 0 exactly at t* = −(aa·bb)/(bb·bb).
    let ts = aa.dot(bb).negated().quotient(&bb.sq()).expect("bb ≠ 0");
    !ts.is_neg() && ts <= *t
}

/// Does edge i → i + 1 of P + t·V collapse to a point at some t ∈ [0, T]?
fn edge_collapses(t: &Q, pi: &V2<Q>, pj: &V2<Q>, vi: &V2<Q>, vj: &V2<Q>) -> bool {
    collapses(t, &pj.minus(pi), &vj.minus(vi))
}

/// Does some edge of the scene's polygon collapse to a point within [0, T]?
fn any_edge_collapses(t: &Q, p: &[V2<Q>], vels: &[V2<Q>]) -> bool {
    let n = p.len();
    (0..n).any(|i| {
        let j = (i + 1) % n;
        edge_collapses(t, &p[i], &p[j], &vels[i], &vels[j])
    })
}

// ------------------------------------------------------------------ scenes

/// A moving point and a moving polygon on the grid of step `H`.
#[derive(Clone, Debug)]
struct Scene {
    poly: Vec<Vect2>,
    vels: Vec<Vect2>,
    s: Vect2,
    v: Vect2,
    t: f64,
    buff: f64,
    f: f64,
}

const H: f64 = 0.25;

/// Polygon vertices and s within 5 steps of the origin; the end of the relative path
/// s + T(v − v_i) within 7 (the box exactness bound); the polygon moves by D_p + δ_i over
/// T (δ_i = 0 for all i when `warp` is false), T = 2^k.
fn scene(warp: prop::sample::Select<bool>) -> impl Strategy<Value = Scene> {
    (
        poly(6, 5, H),
        gpt(5, H),
        gpt(5, H),
        gpt(3, H),
        prop::collection::vec(gpt(2, H), 6),
        warp,
        pow2(-2, 2),
        grid_in(1, 8, H / 4.0),
        fac(),
    )
        .prop_map(|(poly, s, rel_end, dp, deltas, warp, t, buff, f)| {
            let n = poly.len();
            let vels: Vec<Vect2> = (0..n)
                .map(|i| {
                    let d = if warp { dp + deltas[i] } else { dp };
                    d.scale(1.0 / t)
                })
                .collect();
            let s_t = rel_end + dp;
            let v = (s_t - s).scale(1.0 / t);
            Scene {
                poly,
                vels,
                s,
                v,
                t,
                buff,
                f,
            }
        })
}

/// A scene in exact numbers: T, s, v, P, V.
type ExactScene = (Q, V2<Q>, V2<Q>, Vec<V2<Q>>, Vec<V2<Q>>);

impl Scene {
    fn exact(&self) -> ExactScene {
        (
            q(self.t),
            qv(self.s),
            qv(self.v),
            qpoly(&self.poly),
            qpoly(&self.vels),
        )
    }
}

/// The vertical part of a §III case: heights on the grid of step 1/4, relative vertical
/// speed w = v_z − v_sp a power of two (or 0), so the slab window ends are dyadic.
#[derive(Clone, Debug)]
struct Slab {
    sz: f64,
    vz: f64,
    pmin: f64,
    pmax: f64,
    vsp: f64,
}

fn slab() -> impl Strategy<Value = Slab> {
    (
        grid(12, 0.25),
        prop::sample::select(vec![0.0, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0]),
        grid(8, 0.25),
        grid_in(0, 8, 0.25),
        grid(4, 0.25),
    )
        .prop_map(|(sz, w, pmin, thick, vsp)| Slab {
            sz,
            vz: vsp + w,
            pmin,
            pmax: pmin + thick,
            vsp,
        })
}

// ------------------------------------------------------------------ §I strategies

/// (a, b, c, D): random coefficients (multiples of 1/16, |k| ≤ 256) with D sometimes
/// exactly quad(0) or quad(1), or a parabola a(t − t0)² + m, mostly upwards with its vertex
/// in [0, 1], with D = m half the time (vertex value exactly D) and m + δ otherwise.
fn quad1() -> impl Strategy<Value = (f64, f64, f64, f64)> {
    let unit = 1.0 / 16.0;
    let random = (
        grid(256, unit),
        grid(256, unit),
        grid(256, unit),
        grid(256, unit),
        0u8..4,
    )
        .prop_map(|(a, b, c, d, end)| match end {
            0 => (a, b, c, c),
            1 => (a, b, c, a + b + c),
            _ => (a, b, c, d),
        });
    let vertex = (
        prop_oneof![1..=16i32, -16..=16i32],
        prop_oneof![0..=8i32, -8..=16i32],
        -32..=32i32,
        prop_oneof![Just(0i32), -2..=2i32],
    )
        .prop_map(|(ka, kt, km, kd)| {
            let a = f64::from(ka) / 4.0;
            let t0 = f64::from(kt) / 8.0;
            let m = f64::from(km) / 16.0;
            (a, -2.0 * a * t0, a * t0 * t0 + m, m + f64::from(kd) / 64.0)
        });
    prop_oneof![random, vertex]
}

/// (a, b, c, d, e, f, D): random coefficients (multiples of 1/8, |k| ≤ 64), or
/// a(r − r0)² + b(t − t0)² + c(r − r0)(t − t0) + m with D = m + δ: critical points on
/// the box's sides and corners, disc = 0 when c² = 4ab, minimum value exactly D.
fn quad2() -> impl Strategy<Value = [f64; 7]> {
    let random = prop::collection::vec(grid(64, 0.125), 7).prop_map(|v| {
        let mut a = [0.0; 7];
        a.copy_from_slice(&v);
        a
    });
    // a, b ≥ 1 and |c| ≤ 2 (a convex form, c² ≤ 4ab) with (r0, t0) in the box, or
    // anything in a wider range; D = m (minimum exactly D) half the time.
    let critical = (
        prop_oneof![1..=2i32, -2..=2i32],
        prop_oneof![1..=2i32, -2..=2i32],
        prop_oneof![-2..=2i32, -4..=4i32],
        prop_oneof![0..=4i32, -2..=6i32],
        prop_oneof![0..=4i32, -2..=6i32],
        -8..=8i32,
        prop_oneof![Just(0i32), -1..=1i32],
    )
        .prop_map(|(a, b, c, kr, kt, km, kd)| {
            let (a, b, c) = (f64::from(a), f64::from(b), f64::from(c));
            let (r0, t0) = (f64::from(kr) / 4.0, f64::from(kt) / 4.0);
            let m = f64::from(km) / 16.0;
            let d = -2.0 * a * r0 - c * t0;
            let e = -2.0 * b * t0 - c * r0;
            let f = a * r0 * r0 + b * t0 * t0 + c * r0 * t0 + m;
            [a, b, c, d, e, f, m + f64::from(kd) / 16.0]
        });
    prop_oneof![random, critical]
}

// ------------------------------------------------------------------ §II.I strategies

/// (ww, vv, aa, bb) on the grid of step 1/4: components |k| ≤ 8 (or ≤ 2, where zero
/// leading coefficients and double roots are common). With F = 2⁻¹⁰, F·aa + σ2·ww is at
/// most 2¹⁴ units of 2⁻¹²; A, C ≤ 2¹⁸ and B ≤ 2¹⁹ units of 2⁻¹⁴, B² and 4AC ≤ 2³⁸ and the
/// discriminant ≤ 2³⁹ units of 2⁻²⁸: all exact.
fn lin_vectors() -> impl Strategy<Value = [Vect2; 4]> {
    let wide = (gpt(8, H), gpt(8, H), gpt(8, H), gpt(8, H));
    let narrow = (gpt(2, H), gpt(2, H), gpt(2, H), gpt(2, H));
    prop_oneof![wide, narrow].prop_map(|(a, b, c, d)| [a, b, c, d])
}

/// T = k/8, k in 0..=32 (T = 0 is the one-instant slab window of §III).
fn lookahead() -> impl Strategy<Value = f64> {
    grid_in(0, 32, 0.125)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Paper A §I quad_min_le_D: engine and oracle agree exactly on the dyadic grid
    /// (ends exactly at D, vertex value exactly D, vertex exactly at 0 or 1).
    #[test]
    fn quad_min_le_d_matches_oracle((a, b, c, d) in quad1()) {
        let want = oq::quad_min_le_d(&Exact, &q(a), &q(b), &q(c), &q(d)).decided();
        prop_assert_eq!(quad_min_le_d(a, b, c, d), want);
    }

    /// Paper A §I quad_min_box_le_D: engine and oracle agree exactly (critical point on
    /// the box boundary, disc = 0, minimum exactly D).
    #[test]
    fn quad_min_box_le_d_matches_oracle(k in quad2()) {
        prop_assert!(k.iter().all(|&x| on_grid(x, 1.0 / 16.0, 512.0)), "outside the exact grid");
        let [a, b, c, d, e, f, dd] = k;
        let want = oq::quad_min_box_le_d(&Exact, &q(a), &q(b), &q(c), &q(d), &q(e), &q(f), &q(dd)).decided();
        prop_assert_eq!(quad_min_box_le_d(a, b, c, d, e, f, dd), want);
    }

    /// Paper A §II.B perturb: the perturbed vertex is exactly the oracle's (half the cases
    /// put it exactly at |p_x − s_x| = BUFF or p_y = s_y − BUFF).
    #[test]
    fn perturb_matches_oracle(
        p in gpt(8, 0.125),
        s in gpt(8, 0.125),
        buff in grid_in(1, 6, 0.125),
        tie in tie(),
    ) {
        let (ep, es) = (qv(p), qv(s));
        let buff = pick_buff(tie, &perturb_ties(&ep, &es), 0.125, 64.0, buff);
        let want = oc::perturb(&Exact, &ep, &es, &q(buff)).decided();
        prop_assert_eq!(qv(perturb(p, s, buff)), want);
    }

    /// Paper A §II.C near_edge: engine and oracle agree exactly, on a dense grid and on a
    /// wide one with s near the segment (half the cases at distance exactly BUFF; degenerate
    /// segments one time in eight).
    #[test]
    fn near_edge_matches_oracle(
        dense in (gseg(8, 0.125), gpt(8, 0.125), grid_in(1, 8, 0.125)),
        wide in (gseg(64, 0.125), gpt(24, 0.125), grid_in(1, 64, 0.125)),
        tie in tie(),
    ) {
        for (name, ((pi, pj), s, buff)) in [("dense", dense), ("wide", wide)] {
            let s = if name == "wide" { pi + s } else { s };
            let (epi, epj, es) = (qv(pi), qv(pj), qv(s));
            let d2 = dist2_point_segment(&es, &epi, &epj);
            let buff = pick_buff(tie, &[d2], 1.0 / 32.0, 4096.0, buff);
            let want = oc::near_edge(&Exact, &epi, &epj, &es, &q(buff)).decided();
            prop_assert_eq!(near_edge(pi, pj, s, buff), want, "{} grid, BUFF = {}", name, buff);
        }
    }

    /// Paper A §II.D num_cross: the same crossing count as the oracle on the perturbed
    /// polygon P*_BUFF (as §II.E uses it; half the cases with a vertex exactly at a
    /// perturbation threshold), and on P itself (vertices on the ray).
    #[test]
    fn num_cross_matches_oracle(
        p in any_poly(8, 6, H),
        s in gpt(6, H),
        buff in grid_in(1, 4, H / 2.0),
        tie in tie(),
    ) {
        let (ep, es) = (qpoly(&p), qv(s));
        prop_assert_eq!(num_cross(&p[..], s), oc::num_cross(&Exact, &ep, &es).decided(), "P");
        let ties: Vec<Q> = ep.iter().flat_map(|v| perturb_ties(v, &es)).collect();
        let buff = pick_buff(tie, &ties, H / 4.0, 256.0, buff);
        let star = Perturbed { poly: &p[..], s, buff };
        let estar: Vec<V2<Q>> = ep
            .iter()
            .map(|v| oc::perturb(&Exact, v, &es, &q(buff)).decided())
            .collect();
        prop_assert_eq!(num_cross(&star, s), oc::num_cross(&Exact, &estar, &es).decided(), "P*_BUFF, BUFF = {}", buff);
    }

    /// Paper A §II.E definitely_outside: engine and oracle agree exactly, on a small and an
    /// 8× wider grid (s on an edge, on the ray through a vertex; half the cases with s
    /// exactly BUFF from an edge or a vertex exactly at a perturbation threshold).
    #[test]
    fn definitely_outside_matches_oracle(
        p in prop_oneof![poly(7, 6, H), rect_poly(6, H)],
        s in gpt(8, H),
        buff in grid_in(1, 8, H / 4.0),
        scale in prop::sample::select(vec![1.0, 8.0]),
        tie in tie(),
    ) {
        let p: Vec<Vect2> = p.iter().map(|v| v.scale(scale)).collect();
        let s = s.scale(scale);
        let (ep, es) = (qpoly(&p), qv(s));
        let n = ep.len();
        let mut ties: Vec<Q> = (0..n).map(|i| dist2_point_segment(&es, &ep[i], &ep[(i + 1) % n])).collect();
        ties.extend(ep.iter().flat_map(|v| perturb_ties(v, &es)));
        let buff = pick_buff(tie, &ties, H / 4.0, 1024.0, buff);
        let want = oc::definitely_outside(&Exact, &ep, &es, &q(buff)).decided();
        prop_assert_eq!(definitely_outside(&p[..], s, buff), want, "BUFF = {}", buff);
    }

    /// Paper A §II.G segments_close: engine and oracle agree exactly (crossing, parallel,
    /// collinear and degenerate segments; half the cases exactly BUFF apart).
    #[test]
    fn segments_close_matches_oracle(
        cd in gseg(7, H),
        ef in gseg(7, H),
        buff in grid_in(1, 8, H / 4.0),
        tie in tie(),
    ) {
        let ((c, d), (e, f)) = (cd, ef);
        prop_assert!(box_exact(&[c, d, e, f], H));
        let (ec, ed, ee, ef) = (qv(c), qv(d), qv(e), qv(f));
        let buff = pick_buff(tie, &[dist2_segments(&ec, &ed, &ee, &ef)], H / 4.0, 80.0, buff);
        let want = op::segments_close(&Exact, &ec, &ed, &ee, &ef, &q(buff)).decided();
        prop_assert_eq!(segments_close(c, d, e, f, buff), want, "BUFF = {}", buff);
    }

    /// Paper A §II.H detect_same_2D: engine and oracle agree exactly (statically shaped
    /// polygons, and warping ones, which both treat edge by edge with v_i; half the cases
    /// with BUFF exactly the distance from s to an edge at 0 or at T, or from the relative
    /// path to an edge).
    #[test]
    fn detect_same_2d_matches_oracle(
        sc in scene(prop::sample::select(vec![false, false, false, true])),
        tie in tie(),
    ) {
        let rel_ends: Vec<Vect2> = sc.vels.iter().map(|&vi| sc.s.at(sc.v - vi, sc.t)).collect();
        let mut pts = sc.poly.clone();
        pts.push(sc.s);
        pts.extend(rel_ends.iter().copied());
        prop_assert!(box_exact(&pts, H));
        let (t, s, v, p, vels) = sc.exact();
        let n = p.len();
        let moved: Vec<V2<Q>> = p.iter().zip(&vels).map(|(pi, vi)| pi.at(vi, &t)).collect();
        let s_t = s.at(&v, &t);
        let mut ties = Vec::with_capacity(3 * n);
        for i in 0..n {
            let j = (i + 1) % n;
            ties.push(dist2_point_segment(&s, &p[i], &p[j]));
            ties.push(dist2_point_segment(&s_t, &moved[i], &moved[j]));
            ties.push(dist2_segments(&s, &qv(rel_ends[i]), &p[i], &p[j]));
        }
        let buff = pick_buff(tie, &ties, H / 4.0, 80.0, sc.buff);
        let want = od::detect_same_2d(&Exact, &t, &s, &v, &p, &vels, &q(buff)).decided();
        let got = detect_same_2d(sc.t, sc.s, sc.v, &sc.poly[..], &sc.vels[..], buff);
        prop_assert_eq!(got, want, "BUFF = {}", buff);
    }

    /// Paper A §II.J well_formed: engine and oracle agree exactly, with dyadic cos κ (exact
    /// in both). Ties: right-angle corners at cos κ = 0 (rectilinear polygons), straight
    /// corners and turns, and half the cases with two vertices exactly 2·BUFF apart or two
    /// non-adjacent edges exactly BUFF apart.
    #[test]
    fn well_formed_matches_oracle(
        p in prop_oneof![poly(7, 7, H), rect_poly(7, H)],
        buff in grid_in(1, 4, H / 4.0),
        cos_kappa in prop::sample::select(vec![-0.5, 0.0, 0.0, 0.5, 0.75, 0.9375, 63.0 / 64.0, 1.0]),
        tie in tie(),
    ) {
        prop_assert!(box_exact(&p, H));
        let ep = qpoly(&p);
        let n = ep.len();
        let four = Q::from_i64(4);
        let mut ties = Vec::new();
        for i in 0..n {
            for k in (i + 1)..n {
                ties.push(ep[i].minus(&ep[k]).sq().quotient(&four).expect("4 ≠ 0"));
                if k != i + 1 && !(i == 0 && k == n - 1) {
                    ties.push(dist2_segments(&ep[i], &ep[(i + 1) % n], &ep[k], &ep[(k + 1) % n]));
                }
            }
        }
        let buff = pick_buff(tie, &ties, H / 4.0, 80.0, buff);
        let want = ow::well_formed(&ep, &q(buff), &q(cos_kappa));
        prop_assert_eq!(well_formed(&p[..], buff, cos_kappa), want, "BUFF = {}", buff);
    }

    /// Paper A §II.I dot_nn_lin: the same case split as the oracle, and each interval end
    /// within 10⁻¹² (relative, plus 10⁻¹²·max(1, T)) of the exact end (σ labels up to a swap).
    #[test]
    fn dot_nn_lin_matches_oracle(vs in lin_vectors(), t in lookahead()) {
        let [ww, vv, aa, bb] = vs;
        let (et, eww, evv, eaa, ebb) = (q(t), qv(ww), qv(vv), qv(aa), qv(bb));
        let g = Sign::BOTH.map(|s| dot_nn_lin(t, ww, vv, aa, bb, s));
        let e = od::Sign::BOTH.map(|s| od::dot_nn_lin(&Exact, &et, &eww, &evv, &eaa, &ebb, s).decided());
        prop_assert!(
            pair_encloses(&g, &e, t),
            "engine {:?} exact [{}, {}]", g, show(&e[0]), show(&e[1])
        );
    }

    /// Paper A §II.I dot_nn: for each σ2, the engine's pair (σ1 = ∓1) matches the oracle's as
    /// in dot_nn_lin (F·aa + σ2·ww and F·bb + σ2·vv are exact on the grid).
    #[test]
    fn dot_nn_matches_oracle(vs in lin_vectors(), t in lookahead(), f in fac()) {
        let [ww, vv, aa, bb] = vs;
        let (et, eww, evv, eaa, ebb, ef) = (q(t), qv(ww), qv(vv), qv(aa), qv(bb), q(f));
        for (s2, es2) in Sign::BOTH.into_iter().zip(od::Sign::BOTH) {
            let g = Sign::BOTH.map(|s1| dot_nn(t, ww, vv, aa, bb, s1, s2, f));
            let e = od::Sign::BOTH.map(|s1| od::dot_nn(&Exact, &et, &eww, &evv, &eaa, &ebb, s1, es2, &ef).decided());
            prop_assert!(
                pair_encloses(&g, &e, t),
                "σ2 = {:?}: engine {:?} exact [{}, {}]", s2, g, show(&e[0]), show(&e[1])
            );
        }
    }

    /// Paper A §II.I edge_detect_simp (inequalities (1)): the engine equals the oracle
    /// whenever the exact answer is the same for F·(1 ± 2⁻²⁰). Edge vectors aa + t·bb that
    /// vanish within [0, T] are left out: (1) then holds at that one instant whatever F is,
    /// a tie the robustness test cannot see.
    #[test]
    fn edge_detect_simp_matches_oracle_when_robust(
        vs in (gpt(8, H), gpt(4, H), gpt(6, H), gpt(2, H)),
        t in pow2(-2, 2),
        f in fac(),
    ) {
        let (ww, vv, aa, bb) = vs;
        let (et, eww, evv, eaa, ebb) = (q(t), qv(ww), qv(vv), qv(aa), qv(bb));
        prop_assume!(!collapses(&et, &eaa, &ebb));
        let exact = |k: &Q| od::edge_detect_simp(&Exact, &et, &eww, &evv, &eaa, &ebb, k).decided();
        let want = exact(&q(f));
        if exact(&nudged(f, false)) == want && exact(&nudged(f, true)) == want {
            prop_assert_eq!(edge_detect_simp(t, ww, vv, aa, bb, f), want);
        }
    }

    /// Paper A §II.I edge_detect (equation (2)): the engine (with its swept-box filter)
    /// equals the oracle whenever the exact answer is the same for F·(1 ± 2⁻²⁰). Edges that
    /// collapse to a point within [0, T] are left to
    /// `edge_detect_on_collapsing_edges_differs_only_by_the_filter` (a known disagreement).
    #[test]
    fn edge_detect_matches_oracle_when_robust(
        seg in (gpt(6, H), gpt(6, H)).prop_filter("an edge, not a point", |(a, b)| a != b),
        dij in (gpt(4, H), gpt(4, H)),
        s in gpt(8, H),
        d in gpt(10, H),
        t in pow2(-2, 2),
        f in fac(),
    ) {
        let ((pi, pj), (di, dj)) = (seg, dij);
        let (vi, vj, v) = (di.scale(1.0 / t), dj.scale(1.0 / t), d.scale(1.0 / t));
        let (et, es, ev, epi, epj, evi, evj) = (q(t), qv(s), qv(v), qv(pi), qv(pj), qv(vi), qv(vj));
        prop_assume!(!edge_collapses(&et, &epi, &epj, &evi, &evj));
        let exact = |k: &Q| od::edge_detect(&Exact, &et, &es, &ev, &epi, &epj, &evi, &evj, k).decided();
        let want = exact(&q(f));
        if exact(&nudged(f, false)) == want && exact(&nudged(f, true)) == want {
            prop_assert_eq!(edge_detect(t, s, v, pi, pj, vi, vj, f), want);
        }
    }

    /// Paper A §II.I detect_diff_2D: the engine equals the oracle whenever the exact answer
    /// is the same for F·(1 ± 2⁻²⁰) (its definitely_outside step is exact on the grid, so
    /// half the cases put s exactly BUFF from an edge). Polygons with an edge that collapses
    /// to a point within [0, T] are left out, as for edge_detect.
    #[test]
    fn detect_diff_2d_matches_oracle_when_robust(
        sc in scene(prop::sample::select(vec![true, true, true, false])),
        tie in tie(),
    ) {
        let (t, s, v, p, vels) = sc.exact();
        prop_assume!(!any_edge_collapses(&t, &p, &vels));
        let n = p.len();
        let ties: Vec<Q> = (0..n).map(|i| dist2_point_segment(&s, &p[i], &p[(i + 1) % n])).collect();
        let buff = pick_buff(tie, &ties, H / 4.0, 80.0, sc.buff);
        let eb = q(buff);
        let exact = |k: &Q| od::detect_diff_2d(&Exact, &t, &s, &v, &p, &vels, k, &eb).decided();
        let want = exact(&q(sc.f));
        if exact(&nudged(sc.f, false)) == want && exact(&nudged(sc.f, true)) == want {
            let got = detect_diff_2d(sc.t, sc.s, sc.v, &sc.poly[..], &sc.vels[..], sc.f, buff);
            prop_assert_eq!(got, want);
        }
    }

    /// Paper A §III detect_3D: the engine equals the oracle whenever the exact answer is the
    /// same with BUFF and F both scaled by 1 − 2⁻²⁰ and both by 1 + 2⁻²⁰ (the slab window
    /// ends are dyadic, but s + a·v and P + a·V leave the small grid). Warping polygons with
    /// an edge that collapses to a point within [0, T] are left out, as for edge_detect.
    #[test]
    fn detect_3d_matches_oracle_when_robust(
        sc in scene(prop::sample::select(vec![false, true])),
        z in slab(),
    ) {
        let (t, s, v, p, vels) = sc.exact();
        // Statically shaped polygons go to detect_same_2D, which has no edge_detect.
        prop_assume!(od::statically_shaped(&Exact, &vels).decided() || !any_edge_collapses(&t, &p, &vels));
        let (sz, vz, pmin, pmax, vsp) = (q(z.sz), q(z.vz), q(z.pmin), q(z.pmax), q(z.vsp));
        let exact = |b: &Q, k: &Q| od::detect_3d(&Exact, &t, &s, &v, &sz, &vz, &p, &vels, &pmin, &pmax, &vsp, b, k).decided();
        let want = exact(&q(sc.buff), &q(sc.f));
        if exact(&nudged(sc.buff, false), &nudged(sc.f, false)) == want
            && exact(&nudged(sc.buff, true), &nudged(sc.f, true)) == want
        {
            let got = detect_3d(
                sc.t, sc.s, sc.v, z.sz, z.vz, &sc.poly[..], &sc.vels[..],
                z.pmin, z.pmax, z.vsp, sc.buff, sc.f,
            );
            prop_assert_eq!(got, want);
        }
    }

    /// Paper A §II.I edge_detect on edges that collapse to a point at some t ∈ [0, T]
    /// (p_i = p_j with v_i = v_j, or p_j − p_i + t·(v_j − v_i) = 0 at t = T/4, T/2, T).
    /// At the collapse inequalities (1) read 0 ≤ 0, so the paper's edge_detect is true
    /// wherever the point is: a false alarm of the paper on such degenerate (not well
    /// formed) edges, which the engine must reproduce (its contract: paper-exact true ⇒
    /// engine true). The swept-box filter, whose proof assumes ‖aa + t·bb‖ > 0, rejects
    /// only edges that provably never collapse. Before that guard the shrunk input
    /// p_i = p_j = v_i = v_j = (0, 0), s = (0, −1/4), v = (−1/4, 0), T = 1, F = 1/8 gave
    /// engine false, paper-exact true.
    #[test]
    fn edge_detect_on_collapsing_edges_never_misses(
        pi in gpt(6, H),
        dvec in gpt(4, H),
        vi in gpt(4, H),
        collapse in prop::sample::select(vec![0.0, 0.25, 0.5, 1.0]),
        s in gpt(8, H),
        d in gpt(10, H),
        t in pow2(-2, 2),
        f in fac(),
    ) {
        // Collapse at tc = collapse·T: p_j − p_i = dvec, v_j − v_i = −dvec/tc (or p_j = p_i
        // and any v_j − v_i when tc = 0, here v_j = v_i).
        let vi = vi.scale(1.0 / t);
        let tc = collapse * t;
        let (pj, vj) = if tc == 0.0 { (pi, vi) } else { (pi + dvec, vi - dvec.scale(1.0 / tc)) };
        let v = d.scale(1.0 / t);
        let (et, es, ev, epi, epj, evi, evj) = (q(t), qv(s), qv(v), qv(pi), qv(pj), qv(vi), qv(vj));
        prop_assert!(edge_collapses(&et, &epi, &epj, &evi, &evj));
        let exact = |k: &Q| od::edge_detect(&Exact, &et, &es, &ev, &epi, &epj, &evi, &evj, k).decided();
        let want = exact(&q(f));
        let engine = edge_detect(t, s, v, pi, pj, vi, vj, f);
        prop_assert!(engine || !want, "paper-exact true, engine false");
        if exact(&nudged(f, false)) == want && exact(&nudged(f, true)) == want {
            let ww = s - (pj.scale(0.5) + pi.scale(0.5));
            let vv = v - (vj.scale(0.5) + vi.scale(0.5));
            let aa = pj.scale(0.5) - pi.scale(0.5);
            let bb = vj.scale(0.5) - vi.scale(0.5);
            prop_assert_eq!(edge_detect_simp(t, ww, vv, aa, bb, f), want);
        }
    }
}

/// Paper A §I quad and quad2D: the engine's polynomials equal the oracle's where f64 is
/// exact (integers in −20…20: every product and sum is an integer far below 2⁵³).
#[test]
fn quad_and_quad2d_equal_the_oracle_on_exact_inputs() {
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((s >> 33) % 41) as f64 - 20.0
    };
    for _ in 0..500 {
        let f: Vec<f64> = (0..8).map(|_| next()).collect();
        let e: Vec<Q> = f.iter().map(|&x| q(x)).collect();
        assert_eq!(
            q(polyguard::quad::quad(f[0], f[1], f[2], f[3])),
            oq::quad(&e[0], &e[1], &e[2], &e[3]),
            "quad{:?}",
            &f[..4]
        );
        assert_eq!(
            q(polyguard::quad::quad2d(
                f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7]
            )),
            oq::quad2d(&e[0], &e[1], &e[2], &e[3], &e[4], &e[5], &e[6], &e[7]),
            "quad2d{f:?}"
        );
    }
}
