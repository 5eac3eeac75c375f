//! The exact ground truth: does s + t·v lie in the closed polygon P + t·V (and,
//! in 3D, in the closed slab) for some t ∈ [0, T], and when first?
//!
//! Method. Restrict time to the window W = [t0, t1] (the slab window of paper A
//! §III in 3D, [0, T] in 2D) and shift the clock to t0. The point's winding number
//! around P(t) is constant while the point lies on no edge (it is continuous in t
//! away from the boundary), so the point enters the closed polygon first either at
//! t0 (it is on an edge or inside then) or at the earliest time it lies on an edge.
//! The point x(t) lies on the edge a(t) b(t) exactly when
//! g(t) = (x − a) × (b − a) = 0 (a quadratic in t) and
//! h1(t) = (x − a)·(b − a) ≥ 0 and h2(t) = (b − x)·(b − a) ≥ 0. The roots of g
//! are algebraic numbers (p + q√d)/r, the signs of h1, h2 at them are decided
//! exactly ([`crate::qfield`]); when g ≡ 0 (motion collinear with the edge's
//! line), the solution sets of h1 ≥ 0 and h2 ≥ 0 are exact unions of intervals
//! ([`crate::detect::dot_nn_lin`], which covers every degenerate case).
//!
//! Polygons that are not simple. Paper A assumes P(t) simple; the truth does not
//! need it. Where no fill rule can matter it answers anyway: a point on an edge of
//! P(t) is in the closed polygon (it touches the boundary), a point of odd winding
//! number is inside by the nonzero and the even-odd rule alike, a point of winding
//! number 0 is outside by both. So the answer is defined unless the point starts
//! the window with an even, non-zero winding number, which only a polygon that is
//! not simple at t0 allows (a simple polygon winds 0 or ±1 times around a point off
//! its edges): then it is `Undefined`, naming two crossing edges. Whether the
//! polygon stays simple on W (the paper's premise) is a separate exact question,
//! [`simple_on_window`], which the generators ask: a simple polygon stops being
//! simple only through a vertex lying on a non-incident edge (two non-adjacent
//! edges first touch at an end point; folding adjacent edges put an end point on
//! the other edge; a collapsing edge puts its vertex on the next edge), the same
//! contact test as for the point.

use core::cmp::Ordering;

use crate::case::ExactCase;
use crate::detect::{dot_nn_lin, slab_window, Interval, Sign as Side};
use crate::field::{Arith, ExactField, V2};
use crate::kernel::interval::{self, edge_boxes, enclose, meeting_pairs, Iv, VertexBox};
use crate::kernel::run::{Filtered, FirstKernel, Resolve, Scene, Single, Unit};
use crate::kernel::{
    all, all_of, and, any_of, certainly, not, or, Decided, Exact, Intervals, Kernel,
};
use crate::qfield::Alg;
use crate::quad::quad;
pub use crate::time::ExactTime;

/// The ground truth for a case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Truth {
    /// The point is in the closed polygon (and slab) at some time in [0, T];
    /// `entry_time` is the first such time.
    Enters {
        /// The first time in [0, T] at which the point is in the closed polygon.
        entry_time: ExactTime,
    },
    /// It never is.
    Misses,
    /// The question has no answer: at the window's start the polygon is not simple and
    /// the point winds around it an even, non-zero number of times, inside by the
    /// nonzero rule and outside by the even-odd rule (see the module doc).
    Undefined {
        /// Why.
        reason: String,
    },
}

/// Exact early "no contact": over [0, T] the point stays in the box spanned by
/// its two end positions and the moving segment in the box spanned by the four
/// end positions of its ends (each coordinate is linear in t); disjoint boxes
/// mean no contact.
/// (Paper A §II.C's bounding-box filter, exact.)
fn boxes_apart<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    x0: &V2<N>,
    xv: &V2<N>,
    a0: &V2<N>,
    av: &V2<N>,
    b0: &V2<N>,
    bv: &V2<N>,
) -> Result<bool, K::Abstain> {
    let x1 = x0.at(xv, t);
    let a1 = a0.at(av, t);
    let b1 = b0.at(bv, t);
    let apart = |px: [&N; 2], ex: [&N; 4]| {
        let (plo, phi) = k.hull(&px);
        let (elo, ehi) = k.hull(&ex);
        or(k.lt(&phi, &elo), || k.lt(&ehi, &plo))
    };
    or(apart([&x0.x, &x1.x], [&a0.x, &a1.x, &b0.x, &b1.x]), || {
        apart([&x0.y, &x1.y], [&a0.y, &a1.y, &b0.y, &b1.y])
    })
}

/// g(t) = (q0 + t·q1) × (e0 + t·e1) = g2·t² + g1·t + g0, as [g2, g1, g0]
/// (q = x − a, the point relative to the edge's start; e = b − a, the edge).
/// (Paper A §II.C's quadratic, for a point on an edge's line rather than within BUFF.)
fn contact_coeffs<N: Arith>(q0: &V2<N>, q1: &V2<N>, e0: &V2<N>, e1: &V2<N>) -> [N; 3] {
    let g2 = q1.cross(e1);
    let g1 = q0.cross(e1).plus(&q1.cross(e0));
    let g0 = q0.cross(e0);
    [g2, g1, g0]
}

/// The real roots of g2·t² + g1·t + g0, not identically zero, in increasing
/// order (the candidates of [`earliest_contact`], which names them by index).
/// (Paper A §II.A (quad_min_le_D's roots), without the BUFF band.)
fn contact_roots<N: Arith, K: Kernel<N>>(
    k: &K,
    g2: &N,
    g1: &N,
    g0: &N,
) -> Result<Vec<K::Root>, K::Abstain> {
    if k.is_zero(g2)? {
        if k.is_zero(g1)? {
            return Ok(Vec::new());
        }
        return Ok(k
            .linear_root(g0.negated(), g1.clone())
            .into_iter()
            .collect());
    }
    let disc = g1.sq().minus(&g2.twice().twice().times(g0));
    Ok(match k.sign(&disc)? {
        Ordering::Less => Vec::new(),
        Ordering::Equal => k
            .linear_root(g1.negated(), g2.twice())
            .into_iter()
            .collect(),
        Ordering::Greater => k.two_roots(g2, g1, disc).into_iter().flatten().collect(),
    })
}

/// Which root a contact time is: how the exact kernel rebuilds a contact that
/// another kernel found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RootId {
    /// The k-th real root (from 0, in increasing order) of the contact quadratic
    /// g(t) = (x − a) × (b − a).
    Index(usize),
    /// The start of a stretch where the point slides along the edge (g ≡ 0).
    Sliding,
}

/// The earliest time a moving point lies on a moving segment, and which root it is.
#[derive(Clone, Debug)]
pub struct Contact<R> {
    /// The time, in the kernel's root type.
    pub time: R,
    /// Which root it is.
    pub root: RootId,
}

/// The earliest t ∈ [0, T] at which the point x0 + t·xv lies on the closed
/// segment from a0 + t·av to b0 + t·bv, if any (see the module doc).
/// (Paper A §II.C with BUFF = 0: the exact first touch of a moving point and edge.)
pub fn earliest_contact<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    x0: &V2<N>,
    xv: &V2<N>,
    a0: &V2<N>,
    av: &V2<N>,
    b0: &V2<N>,
    bv: &V2<N>,
) -> Result<Option<Contact<K::Root>>, K::Abstain> {
    if certainly(boxes_apart(k, t, x0, xv, a0, av, b0, bv)) {
        return Ok(None);
    }
    let q0 = x0.minus(a0);
    let q1 = xv.minus(av);
    let e0 = b0.minus(a0);
    let e1 = bv.minus(av);
    let [g2, g1, g0] = contact_coeffs(&q0, &q1, &e0, &e1);
    // g keeps one strict sign on [0, T] when its Bernstein coefficients there,
    // g(0), g(0) + g'(0)·T/2 and g(T), share it: no root, no contact.
    let bern = [
        g0.clone(),
        g0.plus(&g1.times(t).half()),
        quad(&g2, &g1, &g0, t),
    ];
    let one_sign = or(all(bern.iter().map(|x| k.is_pos(x))), || {
        all(bern.iter().map(|x| k.is_neg(x)))
    });
    if certainly(one_sign) {
        return Ok(None);
    }
    let r0 = e0.minus(&q0);
    let r1 = e1.minus(&q1);
    if all_of!(k.is_zero(&g2), k.is_zero(&g1), k.is_zero(&g0))? {
        return sliding(k, t, [&q0, &q1], [&r0, &r1], &e0, &e1);
    }
    let roots = contact_roots(k, &g2, &g1, &g0)?;
    // h1 = (q0 + t q1)·(e0 + t e1) and h2 = (r0 + t r1)·(e0 + t e1) as quadratics.
    let h = |w: &V2<N>, v: &V2<N>| [v.dot(&e1), w.dot(&e1).plus(&v.dot(&e0)), w.dot(&e0)];
    let [a1, b1, c1] = h(&q0, &q1);
    let [a2, b2, c2] = h(&r0, &r1);
    let (zero, end) = (k.root(&N::zero()), k.root(t));
    for (i, r) in roots.into_iter().enumerate() {
        let on = all_of!(
            not(k.root_lt(&r, &zero)),
            not(k.root_lt(&end, &r)),
            not(k.quad_neg_at(&r, &a1, &b1, &c1)),
            not(k.quad_neg_at(&r, &a2, &b2, &c2)),
        )?;
        if on {
            return Ok(Some(Contact {
                time: r,
                root: RootId::Index(i),
            }));
        }
    }
    Ok(None)
}

/// The earliest contact when the point always is on the edge's line (g ≡ 0):
/// {h1 ≥ 0} ∩ {h2 ≥ 0}, each an exact union of two intervals of [0, T]
/// (paper A §II.I's dot_nn_lin); the answer is their least common point.
fn sliding<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    [q0, q1]: [&V2<N>; 2],
    [r0, r1]: [&V2<N>; 2],
    e0: &V2<N>,
    e1: &V2<N>,
) -> Result<Option<Contact<K::Root>>, K::Abstain> {
    let mut s1 = Vec::with_capacity(2);
    let mut s2 = Vec::with_capacity(2);
    for side in Side::BOTH {
        s1.push(dot_nn_lin(k, t, q0, q1, e0, e1, side)?);
        s2.push(dot_nn_lin(k, t, r0, r1, e0, e1, side)?);
    }
    let mut best: Option<K::Root> = None;
    for i in &s1 {
        for j in &s2 {
            if let (Interval::Closed { lb: l1, ub: u1 }, Interval::Closed { lb: l2, ub: u2 }) =
                (i, j)
            {
                let lb = if k.root_lt(l1, l2)? { l2 } else { l1 };
                let ub = if k.root_lt(u1, u2)? { u1 } else { u2 };
                if !k.root_lt(ub, lb)? {
                    let better = match &best {
                        None => true,
                        Some(b) => k.root_lt(lb, b)?,
                    };
                    if better {
                        best = Some(lb.clone());
                    }
                }
            }
        }
    }
    Ok(best.map(|time| Contact {
        time,
        root: RootId::Sliding,
    }))
}

/// Whether the closed segments a b and c d meet (orientation tests).
/// (Paper A §II's premise (P simple), checked exactly.)
pub fn segments_intersect<N: Arith, K: Kernel<N>>(
    k: &K,
    a: &V2<N>,
    b: &V2<N>,
    c: &V2<N>,
    d: &V2<N>,
) -> Result<bool, K::Abstain> {
    // Disjoint bounding boxes: certainly apart (a consequence of the tests below).
    let apart = |p: &N, q: &N, r: &N, s: &N| {
        let (plo, phi) = k.hull(&[p, q]);
        let (rlo, rhi) = k.hull(&[r, s]);
        or(k.lt(&phi, &rlo), || k.lt(&rhi, &plo))
    };
    if certainly(or(apart(&a.x, &b.x, &c.x, &d.x), || {
        apart(&a.y, &b.y, &c.y, &d.y)
    })) {
        return Ok(false);
    }
    let on = |p: &V2<N>, q: &V2<N>, x: &V2<N>| {
        let e = q.minus(p);
        all_of!(
            k.is_zero(&e.cross(&x.minus(p))),
            not(k.is_neg(&x.minus(p).dot(&e))),
            not(k.is_neg(&q.minus(x).dot(&e))),
        )
    };
    let side = |p: &V2<N>, q: &V2<N>, x: &V2<N>| k.sign(&q.minus(p).cross(&x.minus(p)));
    // x and y strictly on opposite sides.
    let proper = |x: Result<Ordering, K::Abstain>, y: Result<Ordering, K::Abstain>| match (x, y) {
        (Ok(Ordering::Equal), _) | (_, Ok(Ordering::Equal)) => Ok(false),
        (Ok(x), Ok(y)) => Ok(x != y),
        (Err(e), _) | (_, Err(e)) => Err(e),
    };
    any_of!(
        and(proper(side(a, b, c), side(a, b, d)), || {
            proper(side(c, d, a), side(c, d, b))
        }),
        on(a, b, c),
        on(a, b, d),
        on(c, d, a),
        on(c, d, b),
    )
}

/// The winding number of P around s, `None` when s lies on an edge of P (closed
/// segments; P need not be simple).
/// (Paper A §II.D (the ray's crossings), exact and signed.)
pub fn winding_number<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &[V2<N>],
    s: &V2<N>,
) -> Result<Option<i64>, K::Abstain> {
    let n = p.len();
    let mut winding: i64 = 0;
    for i in 0..n {
        let a = &p[i];
        let b = &p[(i + 1) % n];
        let e = b.minus(a);
        let q = s.minus(a);
        if and(k.is_zero(&e.x), || k.is_zero(&e.y))? {
            // A repeated vertex: the edge is the point a, and winds nothing.
            if and(k.is_zero(&q.x), || k.is_zero(&q.y))? {
                return Ok(None);
            }
            continue;
        }
        let o = e.cross(&q);
        let on_edge = all_of!(
            k.is_zero(&o),
            not(k.is_neg(&q.dot(&e))),
            not(k.is_neg(&b.minus(s).dot(&e))),
        )?;
        if on_edge {
            return Ok(None);
        }
        if k.le(&a.y, &s.y)? {
            if and(k.lt(&s.y, &b.y), || k.is_pos(&o))? {
                winding += 1;
            }
        } else if and(k.le(&b.y, &s.y), || k.is_neg(&o))? {
            winding -= 1;
        }
    }
    Ok(Some(winding))
}

/// Whether s lies in the closed polygon P (on an edge, or winding number ≠ 0).
/// (Paper A §II.D–E without the BUFF band: exact containment.)
pub fn in_closed_polygon<N: Arith, K: Kernel<N>>(
    k: &K,
    p: &[V2<N>],
    s: &V2<N>,
) -> Result<bool, K::Abstain> {
    Ok(winding_number(k, p, s)? != Some(0))
}

/// One sign test of the truth on its scene (the grain of the fallback).
#[derive(Clone, Copy, Debug)]
enum Check {
    /// The edges from vertices i and m meet.
    Cross(usize, usize),
}

impl Unit for Check {
    type Out<R> = bool;

    fn run<N: Arith, K: Kernel<N>>(&self, k: &K, sc: &Scene<'_, N>) -> Result<bool, K::Abstain> {
        let p = &sc.p;
        let next = |i: usize| (i + 1) % p.len();
        match *self {
            Check::Cross(i, m) => segments_intersect(k, &p[i], &p[next(i)], &p[m], &p[next(m)]),
        }
    }

    fn map_root<A, B>(out: bool, _: impl FnMut(A) -> B) -> bool {
        out
    }
}

/// Where s is at the scene's start: on an edge (`None`) or its winding number.
#[derive(Clone, Copy, Debug)]
struct Place;

impl Unit for Place {
    type Out<R> = Option<i64>;

    fn run<N: Arith, K: Kernel<N>>(
        &self,
        k: &K,
        sc: &Scene<'_, N>,
    ) -> Result<Option<i64>, K::Abstain> {
        winding_number(k, &sc.p, &sc.s)
    }

    fn map_root<A, B>(out: Option<i64>, _: impl FnMut(A) -> B) -> Option<i64> {
        out
    }
}

/// What meets the edge in a contact test.
#[derive(Clone, Copy, Debug)]
enum Mover {
    /// The point s.
    Point,
    /// The vertex of this index.
    Vertex(usize),
}

/// One contact test: the earliest time the mover lies on the edge from vertex
/// `edge` to the next (the grain of the fallback).
#[derive(Clone, Copy, Debug)]
struct Touch {
    mover: Mover,
    edge: usize,
}

impl Touch {
    /// x0, xv, a0, av, b0, bv of [`earliest_contact`] in the scene.
    fn parts<'s, N: Clone>(&self, sc: &'s Scene<'_, N>) -> [&'s V2<N>; 6] {
        let (i, j) = (self.edge, (self.edge + 1) % sc.p.len());
        let (x0, xv) = match self.mover {
            Mover::Point => (&*sc.s, &*sc.v),
            Mover::Vertex(m) => (&sc.p[m], &sc.vels[m]),
        };
        [x0, xv, &sc.p[i], &sc.vels[i], &sc.p[j], &sc.vels[j]]
    }

    /// The exact root `root` of this test's contact quadratic in the exact scene
    /// (the root another kernel found); the exact test's own answer if that root
    /// does not exist.
    fn exact_root<F: ExactField>(&self, sc: &Scene<'_, F>, root: RootId) -> Option<Alg<F>> {
        let [x0, xv, a0, av, b0, bv] = self.parts(sc);
        if let RootId::Index(i) = root {
            let [g2, g1, g0] =
                contact_coeffs(&x0.minus(a0), &xv.minus(av), &b0.minus(a0), &bv.minus(av));
            if let Some(r) = contact_roots(&Exact, &g2, &g1, &g0)
                .decided()
                .into_iter()
                .nth(i)
            {
                return Some(r);
            }
        }
        let found = earliest_contact(&Exact, &*sc.t, x0, xv, a0, av, b0, bv).decided();
        found.map(|c| c.time)
    }
}

impl Unit for Touch {
    type Out<R> = Option<Contact<R>>;

    fn run<N: Arith, K: Kernel<N>>(
        &self,
        k: &K,
        sc: &Scene<'_, N>,
    ) -> Result<Option<Contact<K::Root>>, K::Abstain> {
        let [x0, xv, a0, av, b0, bv] = self.parts(sc);
        earliest_contact(k, &sc.t, x0, xv, a0, av, b0, bv)
    }

    fn map_root<A, B>(out: Option<Contact<A>>, mut f: impl FnMut(A) -> B) -> Option<Contact<B>> {
        out.map(|c| Contact {
            time: f(c.time),
            root: c.root,
        })
    }
}

/// The exact time of a contact found by the runner.
/// (Paper A §II: the exact entry time of a contact.)
fn exact_time<F: ExactField, R: Resolve<F>>(
    r: &R,
    u: &Touch,
    c: &Contact<R::Root>,
) -> Option<Alg<F>> {
    match r.as_exact(&c.time) {
        Some(a) => Some(a.clone()),
        None => u.exact_root(r.exact_scene(), c.root),
    }
}

/// The earlier of two exact times (paper A §II: the first entry).
pub(crate) fn min_alg<F: ExactField>(best: Option<Alg<F>>, x: Alg<F>) -> Option<Alg<F>> {
    match best {
        Some(b) if b.cmp_alg(&x) != Ordering::Greater => Some(b),
        _ => Some(x),
    }
}

/// The window [t0, t1] of a case (the slab window of paper A §III in 3D,
/// [0, T] in 2D), `None` when the point never is in the slab.
fn window<F: ExactField>(c: &ExactCase<F>) -> Option<(F, F)> {
    match &c.vertical {
        None => Some((F::zero(), c.lookahead.clone())),
        Some(z) => slab_window(
            &Exact,
            &c.lookahead,
            &z.sz,
            &z.vz,
            &z.bottom,
            &z.top,
            &z.vsp,
        )
        .decided(),
    }
}

/// Rigorous boxes of the exact scene's vertices (paper A §II's premise, P(t) simple: the
/// broad phase's boxes): where each is at the scene's start, or anywhere in [0, T]
/// (`swept`), in the frame of vertex 0 ([`interval::vertex_boxes`]).
fn vertex_boxes<F: ExactField>(sc: &Scene<'_, F>, swept: bool) -> Vec<VertexBox> {
    interval::vertex_boxes(&sc.p, &sc.vels, &sc.t, swept)
}

/// The first pair of non-adjacent edges that meet at the scene's start, as vertex
/// indices (i, m) of their first ends (in the order i, then m). Only edges whose
/// boxes meet are tested.
/// (Paper A §II's premise (P simple) at the window's start.)
fn first_crossing<F: ExactField, R: Resolve<F>>(r: &R) -> Option<(usize, usize)> {
    let n = r.count();
    let edges = edge_boxes(&vertex_boxes(r.exact_scene(), false));
    meeting_pairs(&edges, &edges)
        .into_iter()
        .filter(|&(i, m)| m >= i + 2 && !(i == 0 && m == n - 1))
        .find(|&(i, m)| r.run(&Check::Cross(i, m)).decided())
}

/// Why the polygon is not simple on the window: two edges cross at its start, or
/// a vertex meets a non-incident edge at a time of the window (see the module doc);
/// `None` when it is simple throughout.
/// (Paper A §II's premise (P(t) simple on the window).)
fn not_simple<F: ExactField, R: Resolve<F>>(r: &R, t0: &F) -> Option<String> {
    let n = r.count();
    if let Some((i, m)) = first_crossing(r) {
        return Some(format!(
            "edges {i}-{} and {m}-{} cross at the window's start",
            (i + 1) % n,
            (m + 1) % n
        ));
    }
    // Vertex m can meet edge i only if its swept box meets the edge's (the edge is in
    // the hull of its ends' boxes at every time of the window).
    let vertices = vertex_boxes(r.exact_scene(), true);
    let edges = edge_boxes(&vertices);
    for (i, m) in meeting_pairs(&edges, &vertices) {
        let j = (i + 1) % n;
        if m == i || m == j {
            continue;
        }
        let u = Touch {
            mover: Mover::Vertex(m),
            edge: i,
        };
        if let Some(c) = r.run(&u).decided() {
            if let Some(tc) = exact_time(r, &u, &c) {
                let when = ExactTime::from_alg(&tc.shifted(t0));
                return Some(format!(
                    "vertex {m} meets edge {i}-{j} at t = {}",
                    when.to_decimal_string(9)
                ));
            }
        }
    }
    None
}

/// Whether an edge of the scene is a single point: never in the window, throughout it,
/// or at one time of it.
enum Collapse<F> {
    Never,
    Always,
    At(F),
}

/// Edge i's ends b − a = d0 + t·dv: when, in [0, T] of the scene, are they equal?
/// (Paper A §II's premise: an edge of positive length.)
fn collapse<F: ExactField>(sc: &Scene<'_, F>, i: usize) -> Collapse<F> {
    let j = (i + 1) % sc.p.len();
    let d0 = sc.p[j].minus(&sc.p[i]);
    let dv = sc.vels[j].minus(&sc.vels[i]);
    let zero = |v: &V2<F>| v.x.is_zero_() && v.y.is_zero_();
    if zero(&dv) {
        return if zero(&d0) {
            Collapse::Always
        } else {
            Collapse::Never
        };
    }
    // d0 + t·dv = 0 at t = −d0_k / dv_k for a component k with dv_k ≠ 0.
    let tc = if dv.x.is_zero_() {
        d0.y.negated().quotient(&dv.y)
    } else {
        d0.x.negated().quotient(&dv.x)
    };
    match tc {
        Some(tc)
            if !tc.is_neg()
                && tc.minus(&sc.t).sign() != Ordering::Greater
                && zero(&d0.at(&dv, &tc)) =>
        {
            Collapse::At(tc)
        }
        _ => Collapse::Never,
    }
}

/// Whether edge i of the scene certainly keeps a positive length throughout [0, T]: one
/// coordinate of b − a = d0 + t·dv (linear in t) has one strict sign at both ends of the
/// window, so at every time of it. Decided by the runner's first kernel on the
/// enclosures (an O(n) pass of float work in front of [`collapse`]'s exact one); false
/// when not certain. (Paper A §II's premise: an edge of positive length.)
fn never_collapses(k: &dyn FirstKernel, sc: &Scene<'_, Iv>, i: usize) -> bool {
    let j = (i + 1) % sc.p.len();
    let d0 = sc.p[j].minus(&sc.p[i]);
    let dv = sc.vels[j].minus(&sc.vels[i]);
    let d1 = d0.at(&dv, &sc.t);
    let one_sign = |a: &Iv, b: &Iv| (k.pos(a) && k.pos(b)) || (k.neg(a) && k.neg(b));
    one_sign(&d0.x, &d1.x) || one_sign(&d0.y, &d1.y)
}

/// The truth on the scene restarted at the window's start t0 (see the module
/// doc), each sign test and contact test run by `r`.
/// (Paper A §II's question (and §III's in the slab window), answered exactly.)
fn ground_truth<F: ExactField, R: Resolve<F>>(r: &R, t0: &F) -> Truth {
    let n = r.count();
    if n < 3 {
        return Truth::Undefined {
            reason: "fewer than 3 vertices or velocities of the wrong length".to_string(),
        };
    }
    let start = Truth::Enters {
        entry_time: ExactTime::rational(t0.to_big()),
    };
    match r.run(&Place).decided() {
        // On the boundary, or inside by every fill rule.
        None => return start,
        Some(w) if w % 2 != 0 => return start,
        Some(0) => {}
        Some(w) => {
            let edges = first_crossing(r)
                .map(|(i, m)| format!("edges {i}-{} and {m}-{} cross", (i + 1) % n, (m + 1) % n))
                .unwrap_or_else(|| "it is not simple".into());
            return Truth::Undefined {
                reason: format!(
                    "at the window's start {edges} and the point's winding number is {w}: inside by the nonzero rule, outside by the even-odd rule"
                ),
            };
        }
    }
    // Outside by every rule at the start: the first entry is the first contact. An edge
    // that is a repeated vertex throughout is that vertex, which its neighbours' edges
    // cover; one that shrinks to a point during the window is answered as undefined
    // (the contact test takes a point edge for a line through it).
    let sc = r.exact_scene();
    let mut point_edges = vec![false; n];
    for (i, is_point) in point_edges.iter_mut().enumerate() {
        if r.certainly_first(|k, e| never_collapses(k, e, i)) {
            continue;
        }
        match collapse(sc, i) {
            Collapse::Never => {}
            Collapse::Always => *is_point = true,
            Collapse::At(tc) => {
                let j = (i + 1) % n;
                return Truth::Undefined {
                    reason: format!(
                        "edge {i}-{j} shrinks to a point at t = {} (the polygon is not simple then)",
                        ExactTime::rational(tc.plus(t0).to_big()).to_decimal_string(9)
                    ),
                };
            }
        }
    }
    if point_edges.iter().all(|&p| p) {
        return Truth::Undefined {
            reason: "every vertex is the same point".into(),
        };
    }
    let found: Vec<(Touch, Contact<R::Root>)> = (0..n)
        .filter(|&edge| !point_edges[edge])
        .filter_map(|edge| {
            let u = Touch {
                mover: Mover::Point,
                edge,
            };
            r.run(&u).decided().map(|c| (u, c))
        })
        .collect();
    let mut best: Option<Alg<F>> = None;
    for (i, (u, c)) in found.iter().enumerate() {
        // A contact certainly later than another cannot be the earliest, nor tie with it.
        let mut others = found.iter().enumerate().filter(|&(m, _)| m != i);
        if others.any(|(_, (_, d))| r.certainly_before(&d.time, &c.time)) {
            continue;
        }
        if let Some(tc) = exact_time(r, u, c) {
            best = min_alg(best, tc);
        }
    }
    match best {
        Some(tc) => Truth::Enters {
            entry_time: ExactTime::from_alg(&tc.shifted(t0)),
        },
        None => Truth::Misses,
    }
}

/// The case's scene over its window, restarted at the window's start t0, handed to
/// `run` with t0 and the window's length (`None` when the point never is in the slab).
/// (Paper A §III's slab window (all of [0, T] in 2D).)
fn on_window<F: ExactField>(
    c: &ExactCase<F>,
    run: impl FnOnce(Scene<'_, F>, &F, &F) -> Truth,
) -> Truth {
    let Some((t0, t1)) = window(c) else {
        return Truth::Misses;
    };
    let tw = t1.minus(&t0);
    let sc = Scene::new(&tw, &c.s, &c.v, &c.vertices, &c.velocities, &c.buff, &c.fac);
    run(sc, &t0, &tw)
}

/// The ground truth of a case: `Enters` with the exact first entry time,
/// `Misses`, or `Undefined` when the fill rule decides (see the module doc).
///
/// Every sign test and contact test runs in the interval kernel first
/// ([`Intervals`]) and, when it abstains, in the exact kernel; the answer is
/// identical to [`truth_unfiltered`]'s, entry time representation included.
/// (Paper A §II–III's question, answered exactly.)
pub fn truth<F: ExactField>(c: &ExactCase<F>) -> Truth {
    truth_with(&Intervals, c)
}

/// [`truth`] with `first` in front of the exact kernel instead of [`Intervals`]:
/// the answer is the exact one as long as `first`'s decisions are right (paper A
/// §II–III's question).
pub fn truth_with<F: ExactField, K: Kernel<Iv>>(first: &K, c: &ExactCase<F>) -> Truth {
    on_window(c, |sc, t0, tw| {
        if t0.is_zero_() {
            return ground_truth(&Filtered::new(first, sc), t0);
        }
        // The restarted enclosures, computed from those of the case.
        let e = sc.enclosed();
        let iv = e.shifted(&enclose(t0), *e.t);
        ground_truth(
            &Filtered::with_enclosures(first, sc.shifted(t0, tw.clone()), iv),
            t0,
        )
    })
}

/// The ground truth computed by the exact kernel alone.
/// (Paper A §II–III's question, answered exactly.)
pub fn truth_unfiltered<F: ExactField>(c: &ExactCase<F>) -> Truth {
    on_window(c, |sc, t0, tw| {
        let sc = if t0.is_zero_() {
            sc
        } else {
            sc.shifted(t0, tw.clone())
        };
        ground_truth(&Single::new(&Exact, sc), t0)
    })
}

/// Paper A §II's premise, decided exactly: is the polygon simple at every time of
/// [0, T] (the whole lookahead, also in 3D)? `Err` says why not: two edges that cross
/// at t = 0, or a vertex meeting a non-incident edge and when. The generators ask it
/// of every warping polygon and redraw the ones that fail.
pub fn simple_on_window<F: ExactField>(c: &ExactCase<F>) -> Result<(), String> {
    if c.vertices.len() < 3 || c.vertices.len() != c.velocities.len() {
        return Err("fewer than 3 vertices or velocities of the wrong length".into());
    }
    let sc = Scene::new(
        &c.lookahead,
        &c.s,
        &c.v,
        &c.vertices,
        &c.velocities,
        &c.buff,
        &c.fac,
    );
    match not_simple(&Filtered::new(&Intervals, sc), &F::zero()) {
        Some(why) => Err(why),
        None => Ok(()),
    }
}
