//! The interval kernel in front of the exact one never changes an answer: on the
//! same cases, interval-then-exact ([`paper_detect`], [`truth`]) and exact-only
//! ([`paper_detect_unfiltered`], [`truth_unfiltered`]) agree exactly — detected and
//! method, the truth's variant, its exact entry time (same representation) and its
//! reason text — and every decision the interval kernel takes on its own in a paper
//! function is the exact kernel's. Both backends when the `rug` feature is on.
//!
//! The cases are built to defeat the interval kernel: rational grid cases aimed
//! exactly at vertices and edges (tests/common), f64 cases on the boundaries (points
//! at exactly BUFF from an edge or a vertex and a few ulps off it, |p_x − s_x| =
//! BUFF, trajectories through vertices and tangent to edges, far offsets with small
//! polygons, tiny BUFF), and per-function cases with tiny integers, where zero
//! leading coefficients, double roots, parallel and collinear motions are common.
//!
//! Canaries: the comparison catches a first kernel that lies (one whose
//! certified decisions are flipped), and the interval kernel is seen to decide
//! easy cases on its own and to abstain on exact ties.

mod common;

use core::cell::Cell;
use core::cmp::Ordering;
use std::borrow::Cow;

use proptest::prelude::*;

use common::{cases, gen_case};
use polyguard_oracle::contain::{definitely_outside, near_edge};
use polyguard_oracle::detect::edge_detect;
use polyguard_oracle::kernel::interval::{enclose, enclose2, next_down, next_up};
use polyguard_oracle::kernel::{Abstain, Intervals, Iv};
use polyguard_oracle::proximity::segments_close;
use polyguard_oracle::truth::{earliest_contact, segments_intersect};
use polyguard_oracle::{
    paper_detect, paper_detect_unfiltered, paper_detect_with, truth, truth_unfiltered, truth_with,
    CaseInput, Decided, Exact, ExactCase, ExactField, Kernel, Q, V2,
};

/// Interval-then-exact and exact-only answers for one case, in one backend.
fn check<F: ExactField>(c: &ExactCase<F>) -> Result<(), TestCaseError> {
    prop_assert_eq!(paper_detect(c), paper_detect_unfiltered(c));
    prop_assert_eq!(truth(c), truth_unfiltered(c));
    Ok(())
}

/// A small deterministic generator for the f64 cases.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn uni(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

/// x moved by k ulps (k may be negative).
fn ulps(x: f64, k: i64) -> f64 {
    let mut y = x;
    for _ in 0..k.unsigned_abs() {
        y = if k > 0 { next_up(y) } else { next_down(y) };
    }
    y
}

/// An owned f64 case.
#[derive(Clone, Debug)]
struct F64Case {
    lookahead: f64,
    buff: f64,
    fac: f64,
    pos: Vec<f64>,
    vel: Vec<f64>,
    verts: Vec<[f64; 2]>,
    vels: Vec<[f64; 2]>,
    slab: Option<[f64; 3]>,
}

impl F64Case {
    fn exact<F: ExactField>(&self) -> Result<ExactCase<F>, polyguard_oracle::OracleError> {
        ExactCase::new(&CaseInput {
            lookahead: self.lookahead,
            buff: self.buff,
            fac: self.fac,
            pos: &self.pos,
            vel: &self.vel,
            vertices: &self.verts,
            velocities: &self.vels,
            slab: self.slab,
        })
    }
}

/// A boundary-biased f64 case (see the module doc).
fn gen_f64(seed: u64) -> F64Case {
    let mut g = Rng(seed | 1);
    let (verts, (cx, cy)) = gen_polygon(&mut g);
    let n = verts.len();
    let vels = gen_vertex_vels(&mut g, n);
    let buff = g.pick(&[1.0 / 64.0, 0.01, 2f64.powi(-20), 1e-9]);
    let fac = g.pick(&[1e-4, 1.0 / 64.0]);
    let lookahead = g.pick(&[0.5, 1.0, 4.0, 10.0]);
    let eps = g.pick(&[0i64, 0, 1, -1, 3, -3]);
    let k = (g.next() % n as u64) as usize;
    let mut vel = [g.uni(-3.0, 3.0), g.uni(-3.0, 3.0)];
    let near = Near {
        centre: [cx, cy],
        buff,
        lookahead,
        eps,
    };
    let pos = gen_pos(&mut g, &verts, &vels, k, &near, &mut vel);
    let slab = if g.next() % 5 == 0 {
        let bottom = g.uni(-5.0, 0.0);
        Some([bottom, bottom + g.uni(0.0, 5.0), g.uni(-1.0, 1.0)])
    } else {
        None
    };
    let (pos, vel) = match slab {
        Some(_) => (
            vec![pos[0], pos[1], g.uni(-6.0, 6.0)],
            vec![vel[0], vel[1], g.pick(&[0.0, 1.0, -0.5])],
        ),
        None => (pos.to_vec(), vel.to_vec()),
    };
    F64Case {
        lookahead,
        buff,
        fac,
        pos,
        vel,
        verts,
        vels,
        slab,
    }
}

/// [`gen_f64`]'s polygon and its centre: 3 to 8 vertices around a centre near the
/// origin or far off (up to 10⁷), or one time in four an axis-aligned rectangle with
/// dyadic corners, whose distances are exact.
fn gen_polygon(g: &mut Rng) -> (Vec<[f64; 2]>, (f64, f64)) {
    let n = 3 + (g.next() % 6) as usize;
    let off = g.pick(&[0.0, 1e3, 1e5, 1e7]) * g.pick(&[1.0, -1.0]);
    let (cx, cy) = (off + g.uni(-1.0, 1.0), -off + g.uni(-1.0, 1.0));
    let dyadic_rect = g.next() % 4 == 0;
    let verts: Vec<[f64; 2]> = if dyadic_rect {
        let (w, h) = (g.pick(&[1.0, 2.5, 8.0]), g.pick(&[0.75, 3.0]));
        let (x0, y0) = (cx.round(), cy.round());
        vec![[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]]
    } else {
        (0..n)
            .map(|k| {
                let a = (k as f64 + g.uni(0.1, 0.9)) * std::f64::consts::TAU / n as f64;
                let r = g.uni(1.0, 10.0);
                [cx + r * a.cos(), cy + r * a.sin()]
            })
            .collect()
    };
    (verts, (cx, cy))
}

/// [`gen_f64`]'s vertex velocities: still, one common velocity (a statically shaped
/// polygon), a common one with small differences, or each vertex its own from a few
/// exact values (warping).
fn gen_vertex_vels(g: &mut Rng, n: usize) -> Vec<[f64; 2]> {
    let base = [g.uni(-1.0, 1.0), g.uni(-1.0, 1.0)];
    match g.next() % 4 {
        0 => vec![[0.0, 0.0]; n],
        1 => vec![base; n],
        2 => (0..n)
            .map(|_| [base[0] + g.uni(-0.3, 0.3), base[1] + g.uni(-0.3, 0.3)])
            .collect(),
        _ => (0..n)
            .map(|_| [g.pick(&[-1.0, 0.0, 0.5, 1.0]), g.pick(&[-0.5, 0.0, 1.0])])
            .collect(),
    }
}

/// What [`gen_pos`] places the point against: the polygon's centre, BUFF, the
/// lookahead, and the ulps `eps` by which a boundary position is moved.
struct Near {
    centre: [f64; 2],
    buff: f64,
    lookahead: f64,
    eps: i64,
}

/// [`gen_f64`]'s point, at or near a boundary of paper A's decisions about edge k of
/// `verts` (from vertex k to the next): far and random, at a vertex, at BUFF from the
/// edge's middle, through a vertex inside the window, at the perturbation's thresholds,
/// tangent to the edge (which also sets its velocity `vel`), or at BUFF from an edge of
/// the dyadic rectangle, each a few ulps off.
fn gen_pos(
    g: &mut Rng,
    verts: &[[f64; 2]],
    vels: &[[f64; 2]],
    k: usize,
    near: &Near,
    vel: &mut [f64; 2],
) -> [f64; 2] {
    let Near {
        centre: [cx, cy],
        buff,
        lookahead,
        eps,
    } = *near;
    let l = (k + 1) % verts.len();
    let (p, q) = (verts[k], verts[l]);
    match g.next() % 7 {
        // Far, random.
        0 => [cx + g.uni(-30.0, 30.0), cy + g.uni(-30.0, 30.0)],
        // At a vertex, a few ulps off.
        1 => [ulps(p[0], eps), ulps(p[1], -eps)],
        // At BUFF·(1 ± ulps) from the middle of an edge, outward (approximate normal).
        2 => {
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let len = (dx * dx + dy * dy).sqrt().max(1e-300);
            let d = ulps(buff, eps);
            [
                0.5 * (p[0] + q[0]) + d * dy / len,
                0.5 * (p[1] + q[1]) - d * dx / len,
            ]
        }
        // Through a vertex at a time inside the window.
        3 => {
            let h = lookahead * g.pick(&[0.0, 0.5, 1.0]);
            let w = vels[k];
            [p[0] + h * (w[0] - vel[0]), p[1] + h * (w[1] - vel[1])]
        }
        // |p_x − s_x| = BUFF and p_y = s_y − BUFF (the perturbation's thresholds).
        4 => [ulps(p[0] + buff, eps), ulps(p[1] + buff, eps)],
        // Tangent: along the edge's direction, at BUFF (or 0) from its line.
        5 => {
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let len = (dx * dx + dy * dy).sqrt().max(1e-300);
            let d = g.pick(&[0.0, buff]);
            let start = g.uni(-2.0, -0.5);
            *vel = [dx / len + vels[k][0], dy / len + vels[k][1]];
            [
                p[0] + start * dx + d * dy / len,
                p[1] + start * dy - d * dx / len,
            ]
        }
        // At exactly BUFF from an edge of the dyadic rectangle (or a vertex).
        _ => [ulps(p[0], eps), p[1] - ulps(buff, eps)],
    }
}

fn v<F: ExactField>(c: &[i64], i: usize) -> V2<F> {
    V2::new(F::from_i64(c[i]), F::from_i64(c[i + 1]))
}

/// An interval decision, when taken, is the exact one.
fn agrees<T: PartialEq + core::fmt::Debug>(
    interval: Result<T, Abstain>,
    exact: T,
) -> Result<(), TestCaseError> {
    if let Ok(x) = interval {
        prop_assert_eq!(x, exact);
    }
    Ok(())
}

/// The per-function checks on tiny integer data, in one backend: whatever the
/// interval kernel decides on the enclosures, the exact kernel decides the same.
fn check_functions<F: ExactField>(c: &[i64], k: i64) -> Result<(), TestCaseError> {
    let t = F::from_i64(c[16].abs() + 1);
    let fac = F::one().quotient(&F::from_i64(k)).unwrap_or_else(F::one);
    let buff = F::one()
        .quotient(&F::from_i64(k / 2 + 1))
        .unwrap_or_else(F::one);
    let p: Vec<V2<F>> = (0..8).map(|i| v(c, 2 * i)).collect();
    let (ti, fi, bi) = (enclose(&t), enclose(&fac), enclose(&buff));
    let pi: Vec<V2<Iv>> = p.iter().map(enclose2).collect();
    let (x, e) = (&Intervals, &Exact);
    agrees(
        edge_detect(x, &ti, &pi[0], &pi[1], &pi[2], &pi[3], &pi[4], &pi[5], &fi),
        edge_detect(e, &t, &p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &fac).decided(),
    )?;
    agrees(
        segments_close(x, &pi[0], &pi[1], &pi[2], &pi[3], &bi),
        segments_close(e, &p[0], &p[1], &p[2], &p[3], &buff).decided(),
    )?;
    agrees(
        definitely_outside(x, &pi[1..5], &pi[0], &bi),
        definitely_outside(e, &p[1..5], &p[0], &buff).decided(),
    )?;
    agrees(
        segments_intersect(x, &pi[0], &pi[1], &pi[2], &pi[3]),
        segments_intersect(e, &p[0], &p[1], &p[2], &p[3]).decided(),
    )?;
    // A contact the interval kernel certifies is the exact one: the same root of
    // the same quadratic, inside the enclosure.
    let exact = earliest_contact(e, &t, &p[0], &p[1], &p[2], &p[3], &p[4], &p[5]).decided();
    if let Ok(found) = earliest_contact(x, &ti, &pi[0], &pi[1], &pi[2], &pi[3], &pi[4], &pi[5]) {
        prop_assert_eq!(
            found.is_some(),
            exact.is_some(),
            "{:?} vs {:?}",
            found,
            exact
        );
        if let (Some(a), Some(b)) = (found, exact) {
            prop_assert_eq!(a.root, b.root);
            let inside = |end: f64, o: Ordering| {
                polyguard_oracle::convert::f64_to_exact::<F>(end)
                    .is_some_and(|end| b.time.cmp_rat(&end) != o)
            };
            prop_assert!(inside(a.time.lo, Ordering::Less) && inside(a.time.hi, Ordering::Greater));
        }
    }
    Ok(())
}

/// A generated case that the oracle can make exact in any backend.
trait Exactable {
    fn exact_in<F: ExactField>(&self) -> Result<ExactCase<F>, polyguard_oracle::OracleError>;
}

impl Exactable for common::GenCase {
    fn exact_in<F: ExactField>(&self) -> Result<ExactCase<F>, polyguard_oracle::OracleError> {
        self.exact()
    }
}

impl Exactable for F64Case {
    fn exact_in<F: ExactField>(&self) -> Result<ExactCase<F>, polyguard_oracle::OracleError> {
        self.exact()
    }
}

/// [`check`] on a case in each exact backend (Q, and R with the rug feature); a case a
/// backend refuses has nothing to check.
fn check_backends(g: &impl Exactable) -> Result<(), TestCaseError> {
    if let Ok(c) = g.exact_in::<Q>() {
        check(&c)?;
    }
    #[cfg(feature = "rug")]
    if let Ok(c) = g.exact_in::<polyguard_oracle::R>() {
        check(&c)?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(192)))]

    /// Rational grid cases aimed exactly at vertices and edges (2D, 3D, static, warping).
    #[test]
    fn grid_cases_agree(seed in any::<u64>()) {
        check_backends(&gen_case(seed))?;
    }

    /// f64 cases on the boundaries (BUFF, vertices, tangents, far offsets).
    #[test]
    fn f64_boundary_cases_agree(seed in any::<u64>()) {
        check_backends(&gen_f64(seed))?;
    }

    /// Tiny integers: zero leading coefficients, double roots, parallel and
    /// collinear motion, points exactly on edges.
    #[test]
    fn functions_agree_on_tiny_integers(
        c in proptest::collection::vec(-3i64..=3, 17),
        k in 2i64..=6,
    ) {
        check_functions::<Q>(&c, k)?;
        #[cfg(feature = "rug")]
        check_functions::<polyguard_oracle::R>(&c, k)?;
    }
}

/// The interval kernel with its decisions counted and, when `lie` is set, the
/// certified ones turned round (a deliberately wrong first kernel).
#[derive(Default)]
struct Probe {
    lie: bool,
    decided: Cell<usize>,
    abstained: Cell<usize>,
}

impl Probe {
    fn tally<T>(&self, r: Result<T, Abstain>, flip: impl FnOnce(T) -> T) -> Result<T, Abstain> {
        let cell = if r.is_ok() {
            &self.decided
        } else {
            &self.abstained
        };
        cell.set(cell.get() + 1);
        match r {
            Ok(x) if self.lie => Ok(flip(x)),
            r => r,
        }
    }
    fn bool(&self, r: Result<bool, Abstain>) -> Result<bool, Abstain> {
        self.tally(r, |x| !x)
    }
}

impl Kernel<Iv> for Probe {
    type Root = Iv;
    type Abstain = Abstain;
    fn lt(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.lt(a, b))
    }
    fn le(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.le(a, b))
    }
    fn eq(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.eq(a, b))
    }
    fn sign(&self, x: &Iv) -> Result<Ordering, Abstain> {
        self.tally(Intervals.sign(x), Ordering::reverse)
    }
    fn abs(&self, x: &Iv) -> Iv {
        Intervals.abs(x)
    }
    fn hull<'a>(&self, xs: &[&'a Iv]) -> (Cow<'a, Iv>, Cow<'a, Iv>) {
        Intervals.hull(xs)
    }
    fn root(&self, x: &Iv) -> Iv {
        *x
    }
    fn linear_root(&self, n: Iv, d: Iv) -> Option<Iv> {
        Intervals.linear_root(n, d)
    }
    fn two_roots(&self, a: &Iv, b: &Iv, disc: Iv) -> Option<[Iv; 2]> {
        Intervals.two_roots(a, b, disc)
    }
    fn root_max(&self, r: Iv, x: &Iv) -> Iv {
        Intervals.root_max(r, x)
    }
    fn root_min(&self, r: Iv, x: &Iv) -> Iv {
        Intervals.root_min(r, x)
    }
    fn root_lt(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.root_lt(a, b))
    }
    fn root_le(&self, a: &Iv, b: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.root_le(a, b))
    }
    fn quad_neg_at(&self, r: &Iv, a: &Iv, b: &Iv, c: &Iv) -> Result<bool, Abstain> {
        self.bool(Intervals.quad_neg_at(r, a, b, c))
    }
}

/// Canary: the comparison can fail. With a first kernel whose certified
/// decisions are flipped, interval-then-exact answers differ from exact-only ones
/// on the grid cases (for the detector and for the truth).
#[test]
fn a_lying_first_kernel_is_caught() {
    let liar = Probe {
        lie: true,
        ..Probe::default()
    };
    let (mut detect_wrong, mut truth_wrong) = (0, 0);
    for seed in 1..200u64 {
        let Ok(c) = gen_case(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15)).exact::<Q>() else {
            continue;
        };
        if paper_detect_with(&liar, &c) != paper_detect_unfiltered(&c) {
            detect_wrong += 1;
        }
        if truth_with(&liar, &c) != truth_unfiltered(&c) {
            truth_wrong += 1;
        }
    }
    assert!(
        detect_wrong > 10 && truth_wrong > 10,
        "wrong answers: paper_detect {detect_wrong}, truth {truth_wrong}"
    );
}

/// Canary: the interval kernel does the work on easy cases (no abstention at all)
/// and abstains on exact ties, where the exact kernel must decide.
#[test]
fn intervals_decide_easy_cases_and_abstain_on_ties() {
    let square = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
    let case = |pos: &[f64], vel: &[f64], vels: &[[f64; 2]]| {
        ExactCase::<Q>::new(&CaseInput {
            lookahead: 10.0,
            buff: 0.125,
            fac: 1e-4,
            pos,
            vel,
            vertices: &square,
            velocities: vels,
            slab: None,
        })
        .expect("valid case")
    };
    // A warping square, the point far away or straight through it: every decision
    // of both paper_detect and the truth is taken by the interval kernel.
    let warp = [[0.3, 0.1], [0.7, -0.2], [0.55, 0.45], [0.2, 0.05]];
    for (pos, vel) in [([-50.0, 5.0], [0.1, 1.3]), ([-5.0, 5.0], [1.1, 0.3])] {
        let c = case(&pos, &vel, &warp);
        let probe = Probe::default();
        assert_eq!(paper_detect_with(&probe, &c), paper_detect_unfiltered(&c));
        assert_eq!(truth_with(&probe, &c), truth_unfiltered(&c));
        assert_eq!(probe.abstained.get(), 0, "{pos:?} {vel:?}");
        // (the truth no longer asks the n² simplicity questions: 50 decisions here)
        assert!(probe.decided.get() >= 30, "{}", probe.decided.get());
    }
    // Exactly BUFF from an edge's end (a 3-4-5 triangle of dyadic sides): a tie
    // only the exact kernel can break; nearer and farther are certain.
    let (a, b) = (
        V2::new(Iv::point(0.0), Iv::point(0.0)),
        V2::new(Iv::point(10.0), Iv::point(0.0)),
    );
    let at = |x: f64, y: f64| V2::new(Iv::point(x), Iv::point(y));
    let buff = Iv::point(0.625);
    let near = |s: V2<Iv>| near_edge(&Intervals, &a, &b, &s, &buff);
    assert_eq!(near(at(-0.375, 0.5)), Err(Abstain));
    assert_eq!(near(at(-0.375, 0.25)), Ok(true));
    assert_eq!(near(at(-0.375, 0.75)), Ok(false));
    // Straight through a vertex of a square at rest: the contact there is a tie.
    let c = case(&[-2.0, -2.0], &[1.0, 1.0], &[]);
    let probe = Probe::default();
    assert_eq!(truth_with(&probe, &c), truth_unfiltered(&c));
    assert!(probe.abstained.get() > 0);
}

/// Hand-made degenerate cases: a double root (the point grazes a warping edge),
/// a point exactly at BUFF from an edge, a ray exactly through a vertex.
#[test]
fn degenerate_cases_agree() {
    let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    let buff = 1.0 / 64.0;
    type Shape<'a> = (&'a [f64], &'a [f64], &'a [[f64; 2]]);
    let shapes: [Shape<'_>; 5] = [
        // Exactly BUFF below the bottom edge, moving along it.
        (&[1.0, -buff], &[1.0, 0.0], &[]),
        // Straight through the vertex (4, 4).
        (&[8.0, 8.0], &[-1.0, -1.0], &[]),
        // Grazing the corner: touches (0, 0) exactly at t = 1.
        (&[-1.0, 1.0], &[1.0, -1.0], &[]),
        // A warping square whose top edge rises and falls back: point on its path.
        (
            &[2.0, 5.0],
            &[0.0, 0.0],
            &[[0.0, 0.0], [0.0, 0.0], [0.0, 1.0], [0.0, 1.0]],
        ),
        // A static square moving right, the point exactly on its left edge's path.
        (
            &[-2.0, 2.0],
            &[0.0, 0.0],
            &[[1.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 0.0]],
        ),
    ];
    for (pos, vel, vels) in shapes {
        for lookahead in [1.0, 2.0, 10.0] {
            let c = F64Case {
                lookahead,
                buff,
                fac: 1e-4,
                pos: pos.to_vec(),
                vel: vel.to_vec(),
                verts: square.to_vec(),
                vels: vels.to_vec(),
                slab: None,
            };
            let q = c.exact::<Q>().expect("valid case");
            assert_eq!(paper_detect(&q), paper_detect_unfiltered(&q), "{c:?}");
            assert_eq!(truth(&q), truth_unfiltered(&q), "{c:?}");
        }
    }
}
