//! The certified branch and bound over time behind [`super::intervals_into`]: on each
//! time piece, decide whether the relation (inside, near_D or breach_D of the definitions
//! in the parent module, paper A §II.C's edge quadratics, §II.B's crossing count and
//! §III's slab) certainly holds throughout, certainly fails throughout, or neither; halve
//! the undecided pieces down to the resolution. The pieces go, left to right, to a
//! [`Pieces`] consumer. The same machinery halves one edge at a time for the keep-in
//! exits of `crate::fence` ([`Scan::comes_within`]).
//!
//! No heap: the first [`EDGE_CAP`] edges are kept in a stack array (later ones are formed
//! when needed), and the candidate edges of the open pieces in a stack of
//! [`CAND_CAP`] indices; when it is full, a piece's children test every edge.

use super::{Relation, Separation};
use crate::ball::{mx, round_down, round_up, up, Ball, BallV, Tri};
use crate::motion::{
    bracket, centre, sign, touch_possible, winding, Edge, Frame, Heights, SlabLine, State, Taylor,
    RESOLUTION, VISIT_BUDGET,
};
use crate::vect2::Vect2;

mod shortcut;
mod within;

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
/// of the parent module: an edge's g, h₁, h₂, the two sides g − D|e| and g + D|e| of its
/// band (within D of its line exactly when g − D|e| ≤ 0 ≤ g + D|e|), a vertex's
/// |x − p_k|² − D², a slab line).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Fun {
    Cross(u32),
    Along(u32),
    Back(u32),
    Minus(u32),
    Plus(u32),
    Vertex(u32),
    Slab(u8),
}

/// How many functions that may change sign on a piece the shortcut takes on at once.
const FEW: usize = 3;

/// The functions that may change sign on a piece and matter there: up to [`FEW`] of
/// them, or more (`many`).
#[derive(Clone, Copy, Debug)]
struct Few {
    funs: [Fun; FEW],
    n: usize,
    many: bool,
}

impl Few {
    /// None yet.
    const NONE: Few = Few {
        funs: [Fun::Slab(0); FEW],
        n: 0,
        many: false,
    };

    /// Counts `f`, which may change sign (the same function twice counts once).
    #[inline]
    fn add(&mut self, f: Fun) {
        if self.many || self.funs[..self.n].contains(&f) {
            return;
        }
        if self.n == FEW {
            self.many = true;
        } else {
            self.funs[self.n] = f;
            self.n += 1;
        }
    }

    /// The functions, when there are at most [`FEW`] and at least one.
    fn list(&self) -> Option<&[Fun]> {
        (!self.many && self.n > 0).then(|| &self.funs[..self.n])
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
    few: Few,
}

/// The candidate edges of a piece: every live edge, or a segment of the stack.
#[derive(Clone, Copy, Debug)]
pub(super) enum Cands {
    All,
    Stack(usize, usize),
}

/// The ranges of one edge's functions over a piece.
struct Ranges {
    g: Ball,
    h1: Ball,
    h2: Ball,
    minus: Ball,
    plus: Ball,
    head: Ball,
    tail: Ball,
}

/// A range that says nothing: (−∞, ∞).
const UNKNOWN: Ball = Ball {
    z: 0.0,
    r: f64::INFINITY,
};

/// x ≤ 0, or NaN: not certainly positive.
#[inline]
fn not_positive(x: f64) -> bool {
    x <= 0.0 || x.is_nan()
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

/// The range of √x from the range of x (negative values cut off; each end rounded
/// outward).
#[inline]
fn root(x: Ball) -> Ball {
    let (lo, hi) = (x.lo().max(0.0), x.hi());
    Ball::from_interval(
        round_down(libm::sqrt(lo)).max(0.0),
        round_up(libm::sqrt(hi)),
    )
}

/// The scan's fixed storage, which the caller keeps on its stack: the first
/// [`EDGE_CAP`] edges, and the stack of candidate edges of the open pieces.
pub(crate) struct Workspace {
    edges: [Edge; EDGE_CAP],
    /// D·|e| of the stored edges that are rigid (e1 = 0).
    reach: [Ball; EDGE_CAP],
    cands: [u32; CAND_CAP],
}

impl Workspace {
    /// Empty storage.
    pub(crate) fn new() -> Workspace {
        let o = Vect2::ZERO;
        Workspace {
            edges: [Edge::new(o, o, o, o, o, o); EDGE_CAP],
            reach: [Ball::exact(0.0); EDGE_CAP],
            cands: [0; CAND_CAP],
        }
    }

    /// All of it, for a scan.
    pub(crate) fn parts(&mut self) -> Parts<'_> {
        Parts {
            edges: &mut self.edges,
            reach: &mut self.reach,
            cands: &mut self.cands,
        }
    }
}

/// The storage a scan works in: stored edges (and their D·|e| when rigid), and the
/// stack of candidates. Any lengths will do (none: every edge is formed when used, and
/// every piece tests every edge), so a caller that halves one edge at a time
/// ([`Scan::comes_within`]) need not set up a [`Workspace`].
pub(crate) struct Parts<'a> {
    pub edges: &'a mut [Edge],
    pub reach: &'a mut [Ball],
    pub cands: &'a mut [u32],
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
    /// The edges formed once (the first [`EDGE_CAP`]) and the candidates' stack.
    ws: Parts<'a>,
    /// D and D², in the frame, and whether D = 0.
    d: Ball,
    d2: Ball,
    d_zero: bool,
    slab: Option<[SlabLine; 2]>,
    t: f64,
    eps: f64,
    state: State,
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
        ws: Parts<'a>,
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
        let frame = Frame::new(t, s, v, p, vels, heights, &[d, h], true);
        let (s, v) = (frame.pt(s), frame.pt(v));
        let (d, h) = (frame.len(d), frame.len(h));
        let off = match relation {
            Relation::Inside => 0.0,
            Relation::Near => h,
            Relation::Breach => -h,
        };
        let slab = heights.map(|z| SlabLine::pair(frame.heights(z), off));
        let scan = Scan {
            relation,
            frame,
            s,
            v,
            p,
            vels,
            ws,
            d: Ball::exact(d),
            d2: Ball::exact(d).sq(),
            d_zero: d == 0.0,
            slab,
            t,
            eps: t * RESOLUTION,
            state: State::Unknown,
            len: 0,
            visits: 0,
            cluster_from: None,
        };
        for i in 0..n.min(scan.ws.edges.len()).min(scan.ws.reach.len()) {
            let e = scan.make_edge(i);
            if e.rigid() {
                scan.ws.reach[i] = scan.d.mul(root(e.length(1, e.e0).range(0.0)));
            }
            scan.ws.edges[i] = e;
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
        Edge::lean(
            self.s,
            self.v,
            f.pt(self.p[i]),
            f.pt(self.vels[i]),
            f.pt(self.p[j]),
            f.pt(self.vels[j]),
        )
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

    /// Edge i: the stored one, or formed into `slot` past [`EDGE_CAP`].
    #[inline]
    fn edge<'s>(&'s self, i: u32, slot: &'s mut Option<Edge>) -> &'s Edge {
        match self.ws.edges.get(i as usize) {
            Some(e) => e,
            None => slot.insert(self.make_edge(i as usize)),
        }
    }

    /// D·|e| over |t − m| ≤ h (e = e(m)), from the range of |e|²; a rigid edge's is
    /// constant and stored.
    #[inline]
    fn reach(&self, i: u32, e: &Edge, ev: BallV, h: f64) -> Ball {
        match self.ws.reach.get(i as usize) {
            Some(&r) if e.rigid() => r,
            _ => self.d.mul(root(e.length(1, ev).range(h))),
        }
    }

    /// A cheap certificate that the edge is farther than D throughout |t − m| ≤ h: both
    /// of its ends, a − x = −q and b − x = w, stay beyond D on one side along x or along
    /// y (each end's box: its value at m, widened by its radius and by its velocity
    /// times h, all rounded up; §II.G's bounding-box filter, over time).
    #[inline]
    fn boxes_apart(&self, e: &Edge, q: BallV, w: BallV, h: f64) -> bool {
        let d = self.d.z;
        let reach = |x: BallV, x1: BallV, c1: f64| up(d + x.r + (c1.abs() + x1.r) * h);
        let (qx, qy) = (reach(q, e.q1, e.q1.v.x), reach(q, e.q1, e.q1.v.y));
        let (wx, wy) = (reach(w, e.w1, e.w1.v.x), reach(w, e.w1, e.w1.v.y));
        // a − x = −q: beyond D to the right when −q.x > D + its widening, and so on.
        (-q.v.x > qx && w.v.x > wx)
            || (q.v.x > qx && -w.v.x > wx)
            || (-q.v.y > qy && w.v.y > wy)
            || (q.v.y > qy && -w.v.y > wy)
    }

    /// The ranges of edge i's functions over |t − m| ≤ h, with `over`'s range put in for
    /// its function when it is one of this edge's (the monotone hull of a shortcut).
    /// `None` when the edge is out of play on the piece: it cannot be touched (inside),
    /// or its line is farther than D (near_D, breach_D). Only what is needed is formed.
    #[inline]
    fn ranges(&self, i: u32, m: f64, h: f64, over: &[(Fun, Ball)]) -> Option<Ranges> {
        let mut slot = None;
        let e = self.edge(i, &mut slot);
        self.ranges_of(i, e, m, h, over)
    }

    /// [`Scan::ranges`] of edge i, given as `e`.
    #[inline]
    fn ranges_of(&self, i: u32, e: &Edge, m: f64, h: f64, over: &[(Fun, Ball)]) -> Option<Ranges> {
        let (q, ev, w) = e.at(m);
        if over.is_empty() && self.boxes_apart(e, q, w, h) {
            return None;
        }
        let pick = |f: Fun, r: Ball| match over.iter().find(|(o, _)| *o == f) {
            Some(&(_, x)) => x,
            None => r,
        };
        let g = pick(Fun::Cross(i), e.g(q, ev).range(h));
        let (minus, plus) = if self.d_zero {
            (g, g)
        } else {
            let reach = self.reach(i, e, ev, h);
            (
                pick(Fun::Minus(i), g.sub(reach)),
                pick(Fun::Plus(i), g.add(reach)),
            )
        };
        // Off the line (inside), or farther than D from it: out of play.
        if minus.lo() > 0.0 || plus.hi() < 0.0 {
            return None;
        }
        let h1 = pick(Fun::Along(i), e.h1(q, ev).range(h));
        let h2 = pick(Fun::Back(i), e.h2(w, ev).range(h));
        if !self.distances() {
            return if h1.hi() < 0.0 || h2.hi() < 0.0 {
                None
            } else {
                Some(Ranges {
                    g,
                    h1,
                    h2,
                    minus,
                    plus,
                    head: UNKNOWN,
                    tail: UNKNOWN,
                })
            };
        }
        // A vertex's distance matters where the foot of the perpendicular may leave the
        // segment at that end (h₁ ≤ 0 for a, h₂ ≤ 0 for b); elsewhere the line decides,
        // and the vertex term is left unknown (never far, never close).
        let vertex = |k: usize, x: BallV, at_end: bool| {
            if at_end {
                e.length(k, x).range(h).sub(self.d2)
            } else {
                UNKNOWN
            }
        };
        let j = next(self.p.len(), i as usize) as u32;
        let head = pick(Fun::Vertex(i), vertex(0, q, not_positive(h1.lo())));
        let tail = pick(Fun::Vertex(j), vertex(2, w, not_positive(h2.lo())));
        Some(Ranges {
            g,
            h1,
            h2,
            minus,
            plus,
            head,
            tail,
        })
    }

    /// One pass over the candidates on |t − m| ≤ h: what is certain there, and (when
    /// `push`) the candidates that remain for the piece's halves, pushed on the stack.
    /// Returns the summary and the halves' candidates.
    fn assess(
        &mut self,
        m: f64,
        h: f64,
        cands: Cands,
        over: &[(Fun, Ball)],
        push: bool,
    ) -> (Summary, Cands) {
        let start = self.len;
        let mut full = false;
        let mut sum = Summary {
            touching: false,
            all_far: true,
            any_close: false,
            slab: None,
            few: Few::NONE,
        };
        let (from, to) = match cands {
            Cands::All => (0, self.p.len()),
            Cands::Stack(from, to) => (from, to),
        };
        for k in from..to {
            let i = match cands {
                Cands::All if !live(self.p, self.vels, k) => continue,
                Cands::All => k as u32,
                Cands::Stack(..) => self.ws.cands[k],
            };
            let keep = self.edge_assess(i, m, h, over, &mut sum);
            if keep && push {
                if self.len < self.ws.cands.len() {
                    self.ws.cands[self.len] = i;
                    self.len += 1;
                } else {
                    full = true;
                }
            }
        }
        if let Some(lines) = self.slab {
            let mut r = [Ball::exact(0.0); 2];
            for (k, line) in lines.iter().enumerate() {
                r[k] = match over.iter().find(|(o, _)| *o == Fun::Slab(k as u8)) {
                    Some(&(_, x)) => x,
                    None => line.range(m, h),
                };
                if !signed(r[k]) {
                    sum.few.add(Fun::Slab(k as u8));
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
    fn edge_assess(&self, i: u32, m: f64, h: f64, over: &[(Fun, Ball)], sum: &mut Summary) -> bool {
        let Some(r) = self.ranges(i, m, h, over) else {
            return false;
        };
        let touch = touch_possible(r.g, r.h1, r.h2);
        if !self.distances() {
            sum.touching = true;
            sum.all_far = false;
            for (f, x) in [
                (Fun::Cross(i), r.g),
                (Fun::Along(i), r.h1),
                (Fun::Back(i), r.h2),
            ] {
                if !signed(x) {
                    sum.few.add(f);
                }
            }
            return true;
        }
        // Farther than D from the segment: beyond an end (h₁ < 0 or h₂ < 0) and farther
        // than D from that end (farther than D from the line: out of play already).
        let far = (r.h1.hi() < 0.0 && r.head.lo() > 0.0) || (r.h2.hi() < 0.0 && r.tail.lo() > 0.0);
        if far {
            return false;
        }
        sum.all_far = false;
        // Within D of an end, or of the segment's interior (the foot of the perpendicular
        // on the segment: h₁ ≥ 0, h₂ ≥ 0, and g² ≤ D²|e|²).
        sum.any_close |= close(&r);
        sum.touching |= touch;
        let j = next(self.p.len(), i as usize) as u32;
        // With D > 0 the point meets the edge only where it is within D of it, where the
        // relation is decided whatever the winding number: g's sign change is no event.
        let inner = r.h1.hi() >= 0.0 && r.h2.hi() >= 0.0;
        for (f, x, matters) in [
            (Fun::Along(i), r.h1, true),
            (Fun::Back(i), r.h2, true),
            (Fun::Cross(i), r.g, inner && self.d_zero),
            (Fun::Minus(i), r.minus, inner && !self.d_zero),
            (Fun::Plus(i), r.plus, inner && !self.d_zero),
            (Fun::Vertex(i), r.head, r.h1.lo() <= 0.0),
            (Fun::Vertex(j), r.tail, r.h2.lo() <= 0.0),
        ] {
            if matters && !signed(x) {
                sum.few.add(f);
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
        let (sum, child) = self.assess(m, h, cands, &[], true);
        let class = self.settle(&sum, m);
        // Inside a cluster already L long its end is enclosed to L/64 at best: pieces
        // need not be finer (as first_entry's hi), which keeps a stretch of contacts (a
        // point sliding along an edge) to a few hundred visits per octave.
        let fine = match self.cluster_from {
            Some(c) => mx(self.eps, (a - c) * (1.0 / 64.0)),
            None => self.eps,
        };
        // Where the winding number is certainly even and not 0 (a polygon that is not
        // simple), inside is undefined: halving cannot decide what no edge can change.
        let undefined = class == Class::Unsure
            && !sum.touching
            && self.state == State::Undefined
            && (self.relation == Relation::Inside || sum.all_far);
        let small = b - a <= fine || m <= a || m >= b || undefined;
        let stop = if class != Class::Unsure || small {
            if sum.touching {
                self.state = State::Unknown;
            }
            self.emit(out, a, b, class)
        } else if let Some(stop) = self.few(a, b, m, h, &sum, child, out) {
            stop
        } else {
            self.visit(a, m, child, out) || self.visit(m, b, child, out)
        };
        self.len = start;
        stop
    }

    /// Sends the piece [a, b] to `out`, keeping track of the cluster in progress.
    fn emit(&mut self, out: &mut impl Pieces, a: f64, b: f64, class: Class) -> bool {
        self.cluster_from = match class {
            Class::Unsure => Some(self.cluster_from.unwrap_or(a)),
            _ => None,
        };
        out.piece(a, b, class)
    }

    /// f's Taylor form at the float time m (a band side's as g's and |e|²'s).
    fn taylor_of(&self, f: Fun, m: f64) -> (Taylor, Option<Taylor>) {
        let i = match f {
            Fun::Cross(i)
            | Fun::Along(i)
            | Fun::Back(i)
            | Fun::Minus(i)
            | Fun::Plus(i)
            | Fun::Vertex(i) => i,
            Fun::Slab(_) => 0,
        };
        let mut slot = None;
        let e = self.edge(i, &mut slot);
        let (q, ev, w) = e.at(m);
        match f {
            Fun::Along(_) => (e.h1(q, ev), None),
            Fun::Back(_) => (e.h2(w, ev), None),
            Fun::Vertex(_) => (e.length(0, q), None),
            Fun::Minus(_) | Fun::Plus(_) => (e.g(q, ev), Some(e.length(1, ev))),
            _ => (e.g(q, ev), None),
        }
    }

    /// f(t) as a ball and f′(t) as a float estimate, at the float time t.
    fn eval(&self, f: Fun, t: f64) -> (Ball, f64) {
        if let Fun::Slab(k) = f {
            return match self.slab {
                Some(lines) => lines[k as usize].at(t),
                None => (Ball::exact(f64::NAN), f64::NAN),
            };
        }
        match self.taylor_of(f, t) {
            (x, None) if matches!(f, Fun::Vertex(_)) => (x.f0.sub(self.d2), x.f1.z),
            (x, None) => (x.f0, x.f1.z),
            (g, Some(el)) => {
                let reach = self.d.mul(root(el.f0));
                let minus = matches!(f, Fun::Minus(_));
                let value = if minus {
                    g.f0.sub(reach)
                } else {
                    g.f0.add(reach)
                };
                // (D|e|)′ = D·(|e|²)′ / (2|e|).
                let turn = self.d.z * el.f1.z / (2.0 * libm::sqrt(el.f0.z));
                (value, if minus { g.f1.z - turn } else { g.f1.z + turn })
            }
        }
    }

    /// An enclosure of f′ over |t − m| ≤ h (a band side's g′ ∓ D·(|e|²)′/(2|e|) from
    /// bounds of its factors: |(|e|²)′| at most its range's largest magnitude, |e| at
    /// least the least value of its range).
    fn slope(&self, f: Fun, m: f64, h: f64) -> Ball {
        if let Fun::Slab(k) = f {
            return match self.slab {
                Some(lines) => lines[k as usize].c1,
                None => Ball::exact(f64::NAN),
            };
        }
        match self.taylor_of(f, m) {
            (x, None) => x.slope(h),
            (g, Some(el)) => {
                if el.f1.is_exact_zero() && el.f2.is_exact_zero() {
                    // A rigid edge: |e| is constant.
                    return g.slope(h);
                }
                let rate = el.slope(h);
                let least = root(el.range(h)).lo();
                let most = rate.lo().abs().max(rate.hi().abs());
                // |D·(|e|²)′/(2|e|)| ≤ D·most/(2·least), each step rounded up.
                let bound = if least > 0.0 {
                    round_up(self.d.z * round_up(most / (2.0 * least)))
                } else {
                    f64::INFINITY
                };
                g.slope(h).add(Ball { z: 0.0, r: bound })
            }
        }
    }
}

/// Within D of the edge throughout the piece of these ranges: within D of an end, or of
/// the segment's interior (the foot of the perpendicular on it, and the line within D).
#[inline]
fn close(r: &Ranges) -> bool {
    r.head.hi() <= 0.0
        || r.tail.hi() <= 0.0
        || (r.h1.lo() >= 0.0 && r.h2.lo() >= 0.0 && r.minus.hi() <= 0.0 && r.plus.lo() >= 0.0)
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
