//! The certified branch and bound over time behind [`super::intervals_into`] and the
//! keep-in scan of `crate::fence`: on each time piece, decide whether the relation
//! (inside, near_D or breach_D of the definitions in the parent module, paper A §II.C's
//! edge quadratics, §II.B's crossing count and §III's slab) certainly holds throughout,
//! certainly fails throughout, or neither; halve the undecided pieces down to the
//! resolution. The pieces go, left to right, to a [`Pieces`] consumer.
//!
//! No heap: the first [`EDGE_CAP`] edges are kept in a stack array (later ones are formed
//! when needed), and the candidate edges of the open pieces in a stack of
//! [`CAND_CAP`] indices; when it is full, a piece's children test every edge.

use super::{Relation, Separation};
use crate::ball::{mx, round_down, round_up, Ball};
use crate::motion::{
    bracket, centre, sign, touch_possible, winding, Edge, Frame, Heights, SlabLine, State, Taylor,
    RESOLUTION, VISIT_BUDGET,
};
use crate::vect2::Vect2;

/// How many edges are formed once and kept (on the stack) for the whole scan.
pub(crate) const EDGE_CAP: usize = 64;

/// How many candidate indices the stack of open pieces holds.
pub(crate) const CAND_CAP: usize = 1024;

/// What the scan certifies of the relation on a closed piece [a, b].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Class {
    /// The relation holds at every t ∈ [a, b].
    Holds,
    /// The relation fails at every t ∈ [a, b].
    Fails,
    /// Not decided (f64 could not tell at the resolution, or the visit budget ran out).
    Unsure,
}

/// The consumer of the scan's pieces, which arrive in order and tile [0, T].
pub(crate) trait Pieces {
    /// The piece [a, b] and what is certain on it; `true` stops the scan.
    fn piece(&mut self, a: f64, b: f64, class: Class) -> bool;
}

/// One of the functions of t whose signs decide the relation on a piece (definitions
/// of the parent module: an edge's g, h₁, h₂, its band g² − D²|e|², a vertex's
/// |x − p_k|² − D², a slab line).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Fun {
    Cross(u32),
    Along(u32),
    Back(u32),
    Band(u32),
    Vertex(u32),
    Slab(u8),
}

/// The functions that may change sign on a piece and matter there: none, one, or more.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Lone {
    None,
    One(Fun),
    Many,
}

impl Lone {
    /// Counts `f`, which may change sign (the same function twice counts once).
    #[inline]
    fn add(&mut self, f: Fun) {
        *self = match *self {
            Lone::None => Lone::One(f),
            Lone::One(g) if g == f => Lone::One(g),
            _ => Lone::Many,
        };
    }
}

/// What one pass over the candidate edges (and the slab) certifies on a piece.
#[derive(Clone, Copy, Debug)]
struct Summary {
    /// Some edge may be touched (the winding number may change).
    touching: bool,
    /// Every edge is certainly farther than D throughout (near_D, breach_D).
    all_far: bool,
    /// Some edge is certainly within D throughout (near_D, breach_D).
    any_close: bool,
    /// The slab lines' ranges (3D).
    slab: Option<[Ball; 2]>,
    lone: Lone,
}

/// The candidate edges of a piece: every live edge, or a segment of the stack.
#[derive(Clone, Copy, Debug)]
enum Cands {
    All,
    Stack(usize, usize),
}

/// The ranges of one edge's functions over a piece.
struct Ranges {
    g: Ball,
    h1: Ball,
    h2: Ball,
    band: Ball,
    head: Ball,
    tail: Ball,
}

/// Does the range certainly exclude 0? (NaN: no.)
#[inline]
fn signed(x: Ball) -> bool {
    x.lo() > 0.0 || x.hi() < 0.0
}

/// The smallest ball holding both balls (the range of a monotone function over a piece
/// from its values at the ends).
#[inline]
fn hull(x: Ball, y: Ball) -> Ball {
    let (lo, hi) = (x.lo().min(y.lo()), x.hi().max(y.hi()));
    Ball::from_interval(lo, hi)
}

/// The range of g² from the range of g: [(|g| − r)², (|g| + r)²], or from 0 when the
/// range holds 0 (the interval square, each end rounded outward).
#[inline]
fn square(g: Ball) -> Ball {
    let (lo, hi) = (g.lo(), g.hi());
    let top = round_up(mx_abs(lo, hi) * mx_abs(lo, hi));
    let bottom = if lo > 0.0 {
        round_down(lo * lo)
    } else if hi < 0.0 {
        round_down(hi * hi)
    } else {
        0.0
    };
    Ball::from_interval(bottom.max(0.0), top)
}

/// max(|a|, |b|).
#[inline]
fn mx_abs(a: f64, b: f64) -> f64 {
    a.abs().max(b.abs())
}

/// The scan over [0, T] of one relation (see the module doc).
pub(crate) struct Scan<'a> {
    relation: Relation,
    frame: Frame,
    /// The point, in the frame.
    s: Vect2,
    v: Vect2,
    /// The polygon as given (each vertex is put in the frame when used).
    p: &'a [Vect2],
    vels: &'a [Vect2],
    cache: [Edge; EDGE_CAP],
    /// D², in the frame, and whether D = 0.
    d2: Ball,
    d_zero: bool,
    slab: Option<[SlabLine; 2]>,
    t: f64,
    eps: f64,
    state: State,
    cands: [u32; CAND_CAP],
    len: usize,
    visits: usize,
    /// Where the undecided pieces sent last began, while the last piece sent was one.
    cluster_from: Option<f64>,
}

impl<'a> Scan<'a> {
    /// The scan of `relation` for the case, or `None` when the case is outside the
    /// domain the scan certifies (T not finite or negative, fewer than 3 vertices, a
    /// coordinate or a separation used by the relation that is not finite, a negative
    /// separation, a polygon of one repeated point): then nothing is certain on [0, T].
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        t: f64,
        s: Vect2,
        v: Vect2,
        p: &'a [Vect2],
        vels: &'a [Vect2],
        heights: Option<Heights>,
        relation: Relation,
        sep: Separation,
    ) -> Option<Scan<'a>> {
        let n = p.len().min(vels.len());
        let (p, vels) = (&p[..n], &vels[..n]);
        let (d, h) = match relation {
            Relation::Inside => (0.0, 0.0),
            _ => (sep.d, if heights.is_some() { sep.h } else { 0.0 }),
        };
        let finite = |a: &Vect2| a.is_finite();
        let ok = t >= 0.0
            && t.is_finite()
            && n >= 3
            && finite(&s)
            && finite(&v)
            && p.iter().all(finite)
            && vels.iter().all(finite)
            && heights.map_or(true, |z| {
                [z.sz, z.vz, z.bottom, z.top, z.vsp]
                    .iter()
                    .all(|x| x.is_finite())
            })
            && d >= 0.0
            && d.is_finite()
            && h >= 0.0
            && h.is_finite()
            && (0..n).any(|i| live(p, vels, i));
        if !ok {
            return None;
        }
        let frame = Frame::new(t, s, v, p, vels, heights, &[d, h]);
        let (s, v) = (frame.pt(s), frame.pt(v));
        let (d, h) = (frame.len(d), frame.len(h));
        let off = match relation {
            Relation::Inside => 0.0,
            Relation::Near => h,
            Relation::Breach => -h,
        };
        let slab = heights.map(|z| SlabLine::pair(frame.heights(z), off));
        let o = Vect2::ZERO;
        let zero = Edge::new(o, o, o, o, o, o);
        let mut scan = Scan {
            relation,
            frame,
            s,
            v,
            p,
            vels,
            cache: [zero; EDGE_CAP],
            d2: Ball::exact(d).sq(),
            d_zero: d == 0.0,
            slab,
            t,
            eps: t * RESOLUTION,
            state: State::Unknown,
            cands: [0; CAND_CAP],
            len: 0,
            visits: 0,
            cluster_from: None,
        };
        for i in 0..n.min(EDGE_CAP) {
            scan.cache[i] = scan.make_edge(i);
        }
        Some(scan)
    }

    /// Scans [0, T], sending every piece to `out` (until it asks to stop).
    pub(crate) fn run(&mut self, out: &mut impl Pieces) {
        self.visit(0.0, self.t, Cands::All, out);
    }

    /// Edge i → i + 1 in the frame (paper A §II.C's relative motion).
    fn make_edge(&self, i: usize) -> Edge {
        let j = next(self.p.len(), i);
        let f = &self.frame;
        Edge::new(
            self.s,
            self.v,
            f.pt(self.p[i]),
            f.pt(self.vels[i]),
            f.pt(self.p[j]),
            f.pt(self.vels[j]),
        )
    }

    /// Edge i, from the cache when it is there.
    #[inline]
    fn edge(&self, i: u32) -> Edge {
        match self.cache.get(i as usize) {
            Some(e) => *e,
            None => self.make_edge(i as usize),
        }
    }

    /// The point's winding number about P(τ) (paper A §II.B on balls, see
    /// `motion::winding`).
    fn winding(&self, tau: f64) -> State {
        let f = &self.frame;
        winding(
            self.p.len(),
            |i| (f.pt(self.p[i]), f.pt(self.vels[i])),
            self.s,
            self.v,
            tau,
        )
    }

    /// Does the relation need the distance functions (band, vertices)?
    #[inline]
    fn distances(&self) -> bool {
        self.relation != Relation::Inside
    }

    /// The ranges of edge i's functions over |t − m| ≤ h, with `over`'s range put in for
    /// its function when it is one of this edge's (the monotone hull of a shortcut).
    #[inline]
    fn ranges(&self, i: u32, m: f64, h: f64, over: Option<(Fun, Ball)>) -> Ranges {
        let e = self.edge(i);
        let (q, ev, w) = e.at(m);
        let [g, h1, h2] = e.taylor3(q, ev, w);
        let pick = |f: Fun, r: Ball| match over {
            Some((o, x)) if o == f => x,
            _ => r,
        };
        let g = pick(Fun::Cross(i), g.range(h));
        let h1 = pick(Fun::Along(i), h1.range(h));
        let h2 = pick(Fun::Back(i), h2.range(h));
        if !self.distances() {
            let z = Ball::exact(0.0);
            return Ranges {
                g,
                h1,
                h2,
                band: z,
                head: z,
                tail: z,
            };
        }
        let [el, ql, wl] = e.lengths(q, ev, w);
        let band = pick(Fun::Band(i), square(g).sub(self.d2.mul(el.range(h))));
        let j = next(self.p.len(), i as usize) as u32;
        let head = pick(Fun::Vertex(i), ql.range(h).sub(self.d2));
        let tail = pick(Fun::Vertex(j), wl.range(h).sub(self.d2));
        Ranges {
            g,
            h1,
            h2,
            band,
            head,
            tail,
        }
    }

    /// One pass over the candidates on |t − m| ≤ h: what is certain there, and (when
    /// `push`) the candidates that remain for the piece's halves, pushed on the stack.
    /// Returns the summary and the halves' candidates.
    fn assess(
        &mut self,
        m: f64,
        h: f64,
        cands: Cands,
        over: Option<(Fun, Ball)>,
        push: bool,
    ) -> (Summary, Cands) {
        let start = self.len;
        let mut full = false;
        let mut sum = Summary {
            touching: false,
            all_far: true,
            any_close: false,
            slab: None,
            lone: Lone::None,
        };
        let (from, to) = match cands {
            Cands::All => (0, self.p.len()),
            Cands::Stack(from, to) => (from, to),
        };
        for k in from..to {
            let i = match cands {
                Cands::All if !live(self.p, self.vels, k) => continue,
                Cands::All => k as u32,
                Cands::Stack(..) => self.cands[k],
            };
            let keep = self.edge_assess(i, m, h, over, &mut sum);
            if keep && push {
                if self.len < CAND_CAP {
                    self.cands[self.len] = i;
                    self.len += 1;
                } else {
                    full = true;
                }
            }
        }
        if let Some(lines) = self.slab {
            let mut r = [Ball::exact(0.0); 2];
            for (k, line) in lines.iter().enumerate() {
                r[k] = match over {
                    Some((Fun::Slab(o), x)) if o as usize == k => x,
                    _ => line.range(m, h),
                };
                if !signed(r[k]) {
                    sum.lone.add(Fun::Slab(k as u8));
                }
            }
            sum.slab = Some(r);
        }
        let child = if full {
            self.len = start;
            Cands::All
        } else {
            Cands::Stack(start, self.len)
        };
        (sum, child)
    }

    /// Edge i's part of [`Scan::assess`]: folds its certainties into `sum`, and says
    /// whether it stays a candidate (it may be touched, for inside; it may come within D,
    /// for near_D and breach_D).
    #[inline]
    fn edge_assess(
        &self,
        i: u32,
        m: f64,
        h: f64,
        over: Option<(Fun, Ball)>,
        sum: &mut Summary,
    ) -> bool {
        let r = self.ranges(i, m, h, over);
        let touch = touch_possible(r.g, r.h1, r.h2);
        if !self.distances() {
            if touch {
                sum.touching = true;
                sum.all_far = false;
                for (f, x) in [
                    (Fun::Cross(i), r.g),
                    (Fun::Along(i), r.h1),
                    (Fun::Back(i), r.h2),
                ] {
                    if !signed(x) {
                        sum.lone.add(f);
                    }
                }
            }
            return touch;
        }
        // Farther than D from the segment: from its line (with D = 0: off the line), or
        // beyond an end (h₁ < 0 or h₂ < 0) and farther than D from that end.
        let line_far = if self.d_zero {
            signed(r.g)
        } else {
            r.band.lo() > 0.0
        };
        let far = line_far
            || (r.h1.hi() < 0.0 && r.head.lo() > 0.0)
            || (r.h2.hi() < 0.0 && r.tail.lo() > 0.0);
        if far {
            return false;
        }
        sum.all_far = false;
        // Within D of an end, or of the segment's interior (the foot of the perpendicular
        // on the segment: h₁ ≥ 0, h₂ ≥ 0, and g² ≤ D²|e|²).
        sum.any_close |= r.head.hi() <= 0.0
            || r.tail.hi() <= 0.0
            || (r.h1.lo() >= 0.0 && r.h2.lo() >= 0.0 && r.band.hi() <= 0.0);
        sum.touching |= touch;
        let j = next(self.p.len(), i as usize) as u32;
        let inner = r.h1.hi() >= 0.0 && r.h2.hi() >= 0.0;
        for (f, x, matters) in [
            (Fun::Along(i), r.h1, true),
            (Fun::Back(i), r.h2, true),
            (Fun::Cross(i), r.g, inner),
            (Fun::Band(i), r.band, inner && !self.d_zero),
            (Fun::Vertex(i), r.head, r.h1.lo() <= 0.0),
            (Fun::Vertex(j), r.tail, r.h2.lo() <= 0.0),
        ] {
            if matters && !signed(x) {
                sum.lone.add(f);
            }
        }
        true
    }

    /// The relation's certainty on a piece from its summary and the point's state there
    /// (the definitions of the parent module, condition by condition).
    fn classify(&self, sum: &Summary, state: State) -> Class {
        let (lo, hi) = match sum.slab {
            Some([a, b]) => (a.lo().min(b.lo()), [a.hi(), b.hi()]),
            None => (f64::INFINITY, [f64::INFINITY; 2]),
        };
        let inside = !sum.touching && state == State::Inside;
        let outside = !sum.touching && state == State::Outside;
        match self.relation {
            Relation::Inside | Relation::Near => {
                // The slab (grown by H for near_D) holds where both lines are ≥ 0.
                let never = hi[0] < 0.0 || hi[1] < 0.0;
                let always = lo >= 0.0;
                let far = if self.relation == Relation::Inside {
                    outside
                } else {
                    sum.all_far && outside
                };
                let near = if self.relation == Relation::Inside {
                    inside
                } else {
                    sum.any_close || inside
                };
                if never || far {
                    Class::Fails
                } else if always && near {
                    Class::Holds
                } else {
                    Class::Unsure
                }
            }
            Relation::Breach => {
                // The fence's slab (shrunk by H) holds where both lines are > 0.
                let z_breach = hi[0] <= 0.0 || hi[1] <= 0.0;
                let z_fence = lo > 0.0;
                if z_breach || sum.any_close || outside {
                    Class::Holds
                } else if z_fence && sum.all_far && inside {
                    Class::Fails
                } else {
                    Class::Unsure
                }
            }
        }
    }

    /// [`Scan::classify`] with the state the scan carries; when that is unknown and no
    /// edge may be touched on the piece, the certified winding number at m settles it
    /// (constant over the piece) and is kept for the pieces that follow.
    fn settle(&mut self, sum: &Summary, m: f64) -> Class {
        let c = self.classify(sum, self.state);
        if c == Class::Unsure && !sum.touching && self.state == State::Unknown {
            self.state = self.winding(m);
            return self.classify(sum, self.state);
        }
        c
    }

    /// Visits [a, b] with its candidate edges; `true` stops the scan (the consumer asked,
    /// or the budget is spent: then [a, T] goes out as one undecided piece).
    fn visit(&mut self, a: f64, b: f64, cands: Cands, out: &mut impl Pieces) -> bool {
        self.visits += 1;
        if self.visits > VISIT_BUDGET {
            out.piece(a, self.t, Class::Unsure);
            return true;
        }
        let (m, h) = centre(a, b);
        let start = self.len;
        let (sum, child) = self.assess(m, h, cands, None, true);
        let class = self.settle(&sum, m);
        // Inside a cluster already L long its end is enclosed to L/64 at best: pieces
        // need not be finer (as first_entry's hi), which keeps a stretch of contacts (a
        // point sliding along an edge) to a few hundred visits per octave.
        let fine = match self.cluster_from {
            Some(c) => mx(self.eps, (a - c) * (1.0 / 64.0)),
            None => self.eps,
        };
        let small = b - a <= fine || m <= a || m >= b;
        let stop = if class != Class::Unsure || small {
            if sum.touching {
                self.state = State::Unknown;
            }
            self.emit(out, a, b, class)
        } else if let Some(stop) = self.lone(a, b, m, h, &sum, child, out) {
            stop
        } else {
            self.visit(a, m, child, out) || self.visit(m, b, child, out)
        };
        self.len = start;
        stop
    }

    /// The shortcut of one sign change: on [a, b] exactly one function that matters may
    /// change sign, and it is certainly monotone there. With the same certain sign at a
    /// and b it keeps it throughout; with opposite signs its one root is bracketed
    /// ([`bracket`]) in (t1, t2), t2 − t1 ≤ 2ε, and [a, t1], [t2, b] are decided with that
    /// function's range replaced by the hull of its end values (exact for a monotone
    /// function, up to rounding). `None` when the shortcut does not decide the pieces;
    /// the caller then halves [a, b].
    #[allow(clippy::too_many_arguments)]
    fn lone(
        &mut self,
        a: f64,
        b: f64,
        m: f64,
        h: f64,
        sum: &Summary,
        child: Cands,
        out: &mut impl Pieces,
    ) -> Option<bool> {
        let Lone::One(f) = sum.lone else {
            return None;
        };
        if !signed(self.slope(f, m, h)) {
            return None;
        }
        let (fa, fb) = (self.eval(f, a).0, self.eval(f, b).0);
        let (sa, sb) = (sign(fa)?, sign(fb)?);
        let state_a = self.state;
        if sa == sb {
            let (whole, _) = self.assess(m, h, child, Some((f, hull(fa, fb))), false);
            let c = self.settle(&whole, m);
            if c == Class::Unsure || whole.touching {
                self.state = state_a;
                return None;
            }
            return Some(self.emit(out, a, b, c));
        }
        let (t1, t2) = bracket(|t| self.eval(f, t), a, b, m, self.eps, sa, sb)?;
        if t2 - t1 > 2.0 * self.eps {
            return None;
        }
        let (m1, r1) = centre(a, t1);
        let (m2, r2) = centre(t2, b);
        let f1 = self.eval(f, t1).0;
        let f2 = self.eval(f, t2).0;
        let (left, _) = self.assess(m1, r1, child, Some((f, hull(fa, f1))), false);
        let (right, _) = self.assess(m2, r2, child, Some((f, hull(f2, fb))), false);
        if left.touching || right.touching {
            return None;
        }
        let c1 = self.settle(&left, m1);
        let state_left = self.state;
        if matches!(f, Fun::Cross(_)) {
            // The point crossed an edge: its winding number changed.
            self.state = State::Unknown;
        }
        let c2 = self.settle(&right, m2);
        if c1 == Class::Unsure || c2 == Class::Unsure {
            self.state = state_left;
            return None;
        }
        Some(
            self.emit(out, a, t1, c1)
                || self.emit(out, t1, t2, Class::Unsure)
                || self.emit(out, t2, b, c2),
        )
    }

    /// Sends the piece [a, b] to `out`, keeping track of the cluster in progress.
    fn emit(&mut self, out: &mut impl Pieces, a: f64, b: f64, class: Class) -> bool {
        self.cluster_from = match class {
            Class::Unsure => Some(self.cluster_from.unwrap_or(a)),
            _ => None,
        };
        out.piece(a, b, class)
    }

    /// f(t) as a ball and f′(t) as a float estimate, at the float time t.
    fn eval(&self, f: Fun, t: f64) -> (Ball, f64) {
        let taylor = |i: u32| {
            let e = self.edge(i);
            let (q, ev, w) = e.at(t);
            (e.taylor3(q, ev, w), e.lengths(q, ev, w))
        };
        let pair = |x: Taylor| (x.f0, x.f1.z);
        match f {
            Fun::Cross(i) => self.edge(i).g_with_slope(t),
            Fun::Along(i) => pair(taylor(i).0[1]),
            Fun::Back(i) => pair(taylor(i).0[2]),
            Fun::Band(i) => {
                let ([g, ..], [el, ..]) = taylor(i);
                let value = g.f0.sq().sub(self.d2.mul(el.f0));
                (value, 2.0 * g.f0.z * g.f1.z - self.d2.z * el.f1.z)
            }
            Fun::Vertex(k) => {
                let (_, [_, ql, _]) = taylor(k);
                (ql.f0.sub(self.d2), ql.f1.z)
            }
            Fun::Slab(k) => match self.slab {
                Some(lines) => lines[k as usize].at(t),
                None => (Ball::exact(f64::NAN), f64::NAN),
            },
        }
    }

    /// An enclosure of f′ over |t − m| ≤ h (the band's from its factors' ranges:
    /// (g² − D²|e|²)′ = 2g·g′ − D²·(|e|²)′).
    fn slope(&self, f: Fun, m: f64, h: f64) -> Ball {
        let taylor = |i: u32| {
            let e = self.edge(i);
            let (q, ev, w) = e.at(m);
            (e.taylor3(q, ev, w), e.lengths(q, ev, w))
        };
        match f {
            Fun::Cross(i) => taylor(i).0[0].slope(h),
            Fun::Along(i) => taylor(i).0[1].slope(h),
            Fun::Back(i) => taylor(i).0[2].slope(h),
            Fun::Band(i) => {
                let ([g, ..], [el, ..]) = taylor(i);
                g.range(h)
                    .mul(g.slope(h))
                    .scale(2.0)
                    .sub(self.d2.mul(el.slope(h)))
            }
            Fun::Vertex(k) => taylor(k).1[1].slope(h),
            Fun::Slab(k) => match self.slab {
                Some(lines) => lines[k as usize].c1,
                None => Ball::exact(f64::NAN),
            },
        }
    }
}

/// The vertex after i, cyclically.
#[inline]
fn next(n: usize, i: usize) -> usize {
    if i + 1 == n {
        0
    } else {
        i + 1
    }
}

/// Edge i is not one repeated vertex throughout (the same float position and velocity
/// at both ends): such an edge is that vertex, which its neighbours' edges cover, as in
/// the truth; the scans skip it.
#[inline]
fn live(p: &[Vect2], vels: &[Vect2], i: usize) -> bool {
    let j = next(p.len(), i);
    p[i] != p[j] || vels[i] != vels[j]
}
