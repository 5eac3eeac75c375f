//! Paper B's ground truth for one pair of features: do they ever meet, and at which
//! instants? Built from the scenario's features alone, independent of stages 1–4 (no
//! bounding boxes, hulls, projections, windows or copies across the antimeridian), for
//! `polyguard assure --paper b` to judge the pipeline by.
//!
//! **The model.** A polygon at time `t` is its Mercator ring: an area's ring as written,
//! a track leg's Table 2 rectangle from [`Leg::merc_vertices_at`] (eqs 23–30 evaluated
//! in f64: the positions the engine itself computes). Two features meet at `t` when the
//! closed polygons share a point on the Earth's Mercator cylinder (x modulo 2π). This
//! module unwraps each ring and track itself (consecutive longitudes joined the shorter
//! way round) and tries every whole-turn shift that brings the two x-ranges together.
//!
//! **How it decides.**
//! - A *meeting* at an instant `t` is decided exactly: the ring intersection with exact
//!   arithmetic on the f64 vertices ([`meets_exact`], adaptive-precision orientation).
//! - *No meeting* over an interval `[t1, t2]` is certified from the distance at its
//!   midpoint: every vertex moves at most `V` per hour ([`Leg::merc_speed_bound`], checked
//!   on samples by `sphere::tests::speed_bound_holds_on_samples` and here on every pair of
//!   evaluations, see [`Outcome::BoundBroken`]), so the distance changes by at most
//!   `(V_a + V_b)·|Δt|`. The interval is apart when `d(t_m) > (V_a + V_b)(t2 − t1)/2 +
//!   slack`, where `slack` ([`slack`]) covers the f64 distance's rounding and the
//!   rounding of the vertices themselves.
//! - Bisection, leftmost first, finds the first meeting within `resolution` hours (and,
//!   rightmost first, the last). Where neither a meeting nor a certificate is reached at
//!   the resolution (a tangency closer than `slack`), the pair is *undecided*: the truth
//!   does not judge it.

use crate::scenario::{Feature, Kind};
use crate::sphere::{self, Leg, LonLat, Merc};
use std::f64::consts::TAU;

/// Evaluations allowed per search (first or last meeting) of one pair of bodies; beyond
/// it the pair is undecided (a long, close approach: about `V·T/d` evaluations).
pub const MAX_EVALUATIONS: usize = 20_000;

/// The distance slack, in Mercator radians, for coordinates of magnitude at most `c`:
/// [`sphere::position_slack`], `2⁻⁴⁰·max(c, 4)` (≈ 3.6e-12 rad, 2 cm on the Earth, for
/// |x| ≤ 4).
///
/// It bounds (a) the rounding of the f64 vertex–edge distance, a dozen operations on
/// differences of coordinates ≤ 2c, each off by ≤ 2⁻⁵³ relative, so ≤ 2⁻⁴⁸·c in all; and
/// (b) twice the rounding of a vertex by [`Leg::merc_vertices_at`], a chain of about 20
/// operations whose error is amplified at most by `sec φ ≤ 57` (latitudes ≤ 89°, the
/// rectangles' limit), ≤ 2⁻⁴⁴·c. The sum is below `2⁻⁴³·c`; the slack leaves 8× over it.
pub fn slack(c: f64) -> f64 {
    sphere::position_slack(c)
}

/// One body of a feature: a static ring alive over `[t0, t1]`, or one leg of a track.
#[derive(Clone, Debug)]
pub enum Body {
    /// An area's shape (holes are not modelled: the hunt's areas have none).
    Static {
        /// Mercator ring, unwrapped.
        ring: Vec<Merc>,
        /// Life (h), infinite when unbounded.
        t0: f64,
        /// See `t0`.
        t1: f64,
    },
    /// A track leg.
    Leg(Box<Leg>),
}

impl Body {
    fn life(&self) -> (f64, f64) {
        match self {
            Body::Static { t0, t1, .. } => (*t0, *t1),
            Body::Leg(l) => (l.t0, l.t1),
        }
    }
    fn speed(&self) -> f64 {
        match self {
            Body::Static { .. } => 0.0,
            Body::Leg(l) => l.merc_speed_bound(),
        }
    }
    fn at(&self, t: f64, out: &mut Vec<Merc>) {
        out.clear();
        match self {
            Body::Static { ring, .. } => out.extend_from_slice(ring),
            Body::Leg(l) => out.extend_from_slice(&l.merc_vertices_at(t)),
        }
    }
}

/// Longitudes made continuous: each one moved by whole turns to within a half turn of
/// the one before (the scenario format's rule for consecutive positions). The move is
/// one addition of `2π·k` to the longitude as written.
fn unwrap(points: &[LonLat]) -> Vec<LonLat> {
    let mut out: Vec<LonLat> = Vec::with_capacity(points.len());
    for &p in points {
        let lon = match out.last() {
            None => p.lon,
            Some(q) => {
                let k = ((q.lon - p.lon) / TAU).round();
                if k == 0.0 {
                    p.lon
                } else {
                    p.lon + TAU * k
                }
            }
        };
        out.push(LonLat { lon, lat: p.lat });
    }
    out
}

/// The sign of the orientation of `abc`, exact for f64 inputs (adaptive precision).
fn orient(a: Merc, b: Merc, c: Merc) -> i8 {
    let o = robust::orient2d(
        robust::Coord { x: a[0], y: a[1] },
        robust::Coord { x: b[0], y: b[1] },
        robust::Coord { x: c[0], y: c[1] },
    );
    if o > 0.0 {
        1
    } else if o < 0.0 {
        -1
    } else {
        0
    }
}

/// Is `p`, collinear with `ab`, within the closed segment's box?
fn within(a: Merc, b: Merc, p: Merc) -> bool {
    p[0] >= a[0].min(b[0])
        && p[0] <= a[0].max(b[0])
        && p[1] >= a[1].min(b[1])
        && p[1] <= a[1].max(b[1])
}

/// Do the closed segments meet? (exact)
fn segments_meet(a: Merc, b: Merc, c: Merc, d: Merc) -> bool {
    let (o1, o2, o3, o4) = (
        orient(a, b, c),
        orient(a, b, d),
        orient(c, d, a),
        orient(c, d, b),
    );
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && within(a, b, c))
        || (o2 == 0 && within(a, b, d))
        || (o3 == 0 && within(c, d, a))
        || (o4 == 0 && within(c, d, b))
}

/// Is `p` inside or on the simple ring? (exact crossing number)
fn inside(p: Merc, ring: &[Merc]) -> bool {
    let n = ring.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let o = orient(a, b, p);
        if o == 0 && within(a, b, p) {
            return true;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            // p left of the upward edge ⇔ the ray to +x crosses it
            if (b[1] > a[1]) == (o > 0) {
                odd = !odd;
            }
        }
    }
    odd
}

/// Do the closed polygons bounded by two simple rings meet? Exact on the f64 vertices
/// (the same decision as [`super::rational::rings_intersect`], tested against it).
pub fn meets_exact(a: &[Merc], b: &[Merc]) -> bool {
    let (n, m) = (a.len(), b.len());
    (0..n).any(|i| (0..m).any(|j| segments_meet(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m])))
        || (n > 0 && inside(a[0], b))
        || (m > 0 && inside(b[0], a))
}

/// A feature's bodies. `None` for an area with holes (not modelled).
pub fn bodies(f: &Feature) -> Option<Vec<Body>> {
    match &f.kind {
        Kind::Area(a) => a
            .shapes
            .iter()
            .map(|s| {
                s.holes.is_empty().then(|| Body::Static {
                    ring: unwrap(&s.ring).into_iter().map(sphere::mercator).collect(),
                    t0: a.t0.unwrap_or(f64::NEG_INFINITY),
                    t1: a.tf.unwrap_or(f64::INFINITY),
                })
            })
            .collect(),
        Kind::Track(t) => Some(
            sphere::track_legs(&unwrap(&t.waypoints), t.speed_kn, t.t0, t.dims)
                .into_iter()
                .map(|l| Body::Leg(Box::new(l)))
                .collect(),
        ),
    }
}

/// The truth about a pair of features.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// They meet. `first` and `last` are instants at which they meet exactly; no meeting
    /// happens before `first_apart_until` or after `last_apart_from` (certified), and
    /// `first − first_apart_until ≤ resolution` (likewise at the end). Infinite for areas
    /// that are always there.
    Meets {
        /// The earliest meeting found.
        first: f64,
        /// Certified apart before this instant.
        first_apart_until: f64,
        /// The latest meeting found.
        last: f64,
        /// Certified apart after this instant.
        last_apart_from: f64,
    },
    /// They never meet: certified apart at every instant of their common life, at least
    /// `min_distance` apart (Mercator radians); `f64::INFINITY` without a common life.
    Apart {
        /// A lower bound on their distance over the common life.
        min_distance: f64,
    },
    /// Tangent within the slack (or the evaluation budget ran out): not judged.
    Undecided,
    /// Two evaluations of one body moved farther than its speed bound allows: the truth
    /// (and stage 4, which relies on the same bound) cannot be trusted. A failure.
    BoundBroken {
        /// The instant of the later evaluation.
        t: f64,
    },
}

/// The distance between two features' bodies at `t`, on the cylinder.
struct Pair<'a> {
    a: &'a Body,
    b: &'a Body,
    va: Vec<Merc>,
    vb: Vec<Merc>,
    shifted: Vec<Merc>,
    speed: f64,
    evaluations: usize,
    /// The last evaluation (time and vertices), for the speed-bound check.
    last: Option<(f64, Vec<Merc>, Vec<Merc>)>,
    broken: Option<f64>,
}

/// What one evaluation at an instant found.
enum At {
    /// They meet (decided exactly).
    Meet,
    /// A certain lower bound on the distance (> 0).
    Apart(f64),
    /// Closer than the slack, and not meeting on the f64 vertices.
    Close,
}

fn bounds(v: &[Merc]) -> (f64, f64, f64) {
    let (mut lo, mut hi, mut c) = (f64::INFINITY, f64::NEG_INFINITY, 0f64);
    for p in v {
        lo = lo.min(p[0]);
        hi = hi.max(p[0]);
        c = c.max(p[0].abs()).max(p[1].abs());
    }
    (lo, hi, c)
}

/// Distance from `p` to the closed segment `ab` (f64).
fn seg_dist(p: Merc, a: Merc, b: Merc) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let s = if l2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - s * dx).hypot(p[1] - a[1] - s * dy)
}

/// Distance between the boundaries of two rings (f64): the least vertex–edge distance.
fn boundary_distance(a: &[Merc], b: &[Merc]) -> f64 {
    let one = |p: &[Merc], q: &[Merc]| {
        let m = q.len();
        p.iter()
            .flat_map(|&x| (0..m).map(move |j| (x, j)))
            .map(|(x, j)| seg_dist(x, q[j], q[(j + 1) % m]))
            .fold(f64::INFINITY, f64::min)
    };
    one(a, b).min(one(b, a))
}

impl<'a> Pair<'a> {
    fn new(a: &'a Body, b: &'a Body) -> Pair<'a> {
        Pair {
            a,
            b,
            va: Vec::new(),
            vb: Vec::new(),
            shifted: Vec::new(),
            speed: a.speed() + b.speed(),
            evaluations: 0,
            last: None,
            broken: None,
        }
    }

    /// The state at `t` and the slack of its coordinates.
    fn eval(&mut self, t: f64) -> (At, f64) {
        self.evaluations += 1;
        self.a.at(t, &mut self.va);
        self.b.at(t, &mut self.vb);
        let (alo, ahi, ca) = bounds(&self.va);
        let (blo, bhi, cb) = bounds(&self.vb);
        let sl = slack(ca.max(cb) + TAU);
        self.check_speed(t, sl);
        // every whole-turn shift of b that can bring it within reach of a
        let k_lo = ((alo - bhi - 1.0) / TAU).floor() as i64;
        let k_hi = ((ahi - blo + 1.0) / TAU).ceil() as i64;
        let mut best = f64::INFINITY;
        let mut close = false;
        for k in k_lo..=k_hi {
            let dx = TAU * k as f64;
            self.shifted.clear();
            self.shifted
                .extend(self.vb.iter().map(|p| [p[0] + dx, p[1]]));
            let (blo2, bhi2) = (blo + dx, bhi + dx);
            if blo2 > ahi + best || bhi2 < alo - best {
                continue;
            }
            if meets_exact(&self.va, &self.shifted) {
                return (At::Meet, sl);
            }
            // disjoint: their distance is a vertex–edge one
            let d = boundary_distance(&self.va, &self.shifted);
            if d > 2.0 * sl {
                best = best.min(d - sl);
            } else {
                close = true;
            }
        }
        if close {
            (At::Close, sl)
        } else {
            (At::Apart(best), sl)
        }
    }

    /// Every vertex moved at most `speed·|Δt|` (plus the rounding of both positions)
    /// since the previous evaluation.
    fn check_speed(&mut self, t: f64, sl: f64) {
        if let Some((t_prev, pa, pb)) = &self.last {
            let dt = (t - t_prev).abs();
            let moved = |p: &[Merc], q: &[Merc]| {
                p.iter()
                    .zip(q)
                    .map(|(x, y)| (x[0] - y[0]).hypot(x[1] - y[1]))
                    .fold(0f64, f64::max)
            };
            let (sa, sb) = (self.a.speed(), self.b.speed());
            if moved(&self.va, pa) > sa * dt + sl || moved(&self.vb, pb) > sb * dt + sl {
                self.broken.get_or_insert(t);
            }
        }
        match &mut self.last {
            Some((tl, pa, pb)) => {
                *tl = t;
                pa.clone_from(&self.va);
                pb.clone_from(&self.vb);
            }
            None => self.last = Some((t, self.va.clone(), self.vb.clone())),
        }
    }
}

/// The result of one directed search.
enum Found {
    /// A meeting at `t`; certified apart from the search's start up to `apart` (on the
    /// start's side of `t`, within the resolution of it unless a tangency came first).
    Meeting { t: f64, apart: f64 },
    /// Certified apart all the way, with the least distance bound seen.
    Apart(f64),
    /// No meeting found, and not certified apart everywhere.
    Undecided,
}

/// Pushes the halves `[t1, tm]` and `[tm, t2]` so that the one nearest the search's
/// start (the left one going forward) is popped first.
fn push_halves(stack: &mut Vec<(f64, f64)>, (t1, tm, t2): (f64, f64, f64), forward: bool) {
    if forward {
        stack.push((tm, t2));
        stack.push((t1, tm));
    } else {
        stack.push((t1, tm));
        stack.push((tm, t2));
    }
}

/// The first (`forward`) or last meeting of the pair over `[lo, hi]` (finite).
fn search(p: &mut Pair<'_>, lo: f64, hi: f64, forward: bool, resolution: f64) -> Found {
    let start = if forward { lo } else { hi };
    // a meeting at the very start (a window that opens at a life's end) is found exactly
    if let (At::Meet, _) = p.eval(start) {
        return Found::Meeting {
            t: start,
            apart: start,
        };
    }
    // a stack of intervals, the one nearest the search's start on top
    let mut stack = vec![(lo, hi)];
    let mut min_d = f64::INFINITY;
    let mut undecided = false;
    // the far end of the prefix certified apart so far
    let mut apart_to = start;
    while let Some((t1, t2)) = stack.pop() {
        if p.evaluations > MAX_EVALUATIONS {
            return Found::Undecided;
        }
        let tm = 0.5 * (t1 + t2);
        let far = if forward { t2 } else { t1 };
        let (at, sl) = p.eval(tm);
        if let At::Meet = at {
            if t2 - t1 <= resolution || tm <= t1 || tm >= t2 {
                return Found::Meeting {
                    t: tm,
                    apart: apart_to,
                };
            }
            // an earlier meeting may lie in the near half: look there first, keeping
            // this one as the answer if none is found
            let near_half = if forward { (t1, tm) } else { (tm, t2) };
            return match search_in(
                p,
                near_half,
                forward,
                resolution,
                &mut apart_to,
                &mut undecided,
            ) {
                Some(t) => Found::Meeting { t, apart: apart_to },
                None => Found::Meeting {
                    t: tm,
                    apart: apart_to,
                },
            };
        }
        let half = 0.5 * (t2 - t1);
        if let At::Apart(d) = at {
            if d > p.speed * half + sl {
                min_d = min_d.min(d - p.speed * half);
                if !undecided {
                    apart_to = far;
                }
                continue;
            }
        }
        if t2 - t1 <= resolution || tm <= t1 || tm >= t2 {
            // close at the resolution without meeting: a tangency the slack hides
            undecided = true;
            continue;
        }
        push_halves(&mut stack, (t1, tm, t2), forward);
    }
    if undecided {
        Found::Undecided
    } else {
        Found::Apart(min_d)
    }
}

/// [`search`] within one interval whose far end is known to meet: the nearest meeting in
/// it, if one is found before the resolution.
fn search_in(
    p: &mut Pair<'_>,
    iv: (f64, f64),
    forward: bool,
    resolution: f64,
    apart_to: &mut f64,
    undecided: &mut bool,
) -> Option<f64> {
    let mut stack = vec![iv];
    let mut found: Option<f64> = None;
    while let Some((t1, t2)) = stack.pop() {
        if p.evaluations > MAX_EVALUATIONS {
            break;
        }
        let tm = 0.5 * (t1 + t2);
        let far = if forward { t2 } else { t1 };
        let (at, sl) = p.eval(tm);
        let small = t2 - t1 <= resolution || tm <= t1 || tm >= t2;
        match at {
            At::Meet => {
                found = Some(tm);
                if small {
                    break;
                }
                // nearer still?
                stack.clear();
                stack.push(if forward { (t1, tm) } else { (tm, t2) });
            }
            At::Apart(d) if d > p.speed * 0.5 * (t2 - t1) + sl => {
                if !*undecided {
                    *apart_to = far;
                }
            }
            _ if small => *undecided = true,
            _ => {
                push_halves(&mut stack, (t1, tm, t2), forward);
            }
        }
    }
    found
}

/// The truth about features `fa` and `fb`: first and last meetings to within
/// `resolution` hours. `None` when a feature is not modelled (an area with holes).
pub fn pair(fa: &Feature, fb: &Feature, resolution: f64) -> Option<Outcome> {
    let (ba, bb) = (bodies(fa)?, bodies(fb)?);
    // (instant, certified-apart bound) of the earliest and the latest meeting found
    let mut first: Option<(f64, f64)> = None;
    let mut last: Option<(f64, f64)> = None;
    let mut min_d = f64::INFINITY;
    let mut undecided = false;
    for a in &ba {
        for b in &bb {
            let ((a0, a1), (b0, b1)) = (a.life(), b.life());
            let (lo, hi) = (a0.max(b0), a1.min(b1));
            if lo > hi {
                continue;
            }
            let mut p = Pair::new(a, b);
            if p.speed == 0.0 {
                // two areas: one exact decision holds for the whole common life
                match p.eval(0.0).0 {
                    At::Meet => {
                        if first.map_or(true, |f| lo < f.0) {
                            first = Some((lo, lo));
                        }
                        if last.map_or(true, |l| hi > l.0) {
                            last = Some((hi, hi));
                        }
                    }
                    At::Apart(d) => min_d = min_d.min(d),
                    // static rings have no rounded positions: the exact test on their
                    // vertices is the whole truth, and they are apart (by less than
                    // the slack)
                    At::Close => min_d = 0.0,
                }
                continue;
            }
            let f = search(&mut p, lo, hi, true, resolution);
            if let Some(t) = p.broken {
                return Some(Outcome::BoundBroken { t });
            }
            match f {
                Found::Meeting { t, apart } => {
                    if first.map_or(true, |f| t < f.0) {
                        first = Some((t, apart));
                    }
                    let l = search(&mut p, lo, hi, false, resolution);
                    if let Some(t) = p.broken {
                        return Some(Outcome::BoundBroken { t });
                    }
                    match l {
                        Found::Meeting { t, apart } => {
                            if last.map_or(true, |l| t > l.0) {
                                last = Some((t, apart));
                            }
                        }
                        // the backward search meets too unless a tangency or the
                        // budget stops it: the forward meeting stands for the last
                        _ => {
                            undecided = true;
                            if last.map_or(true, |l| t > l.0) {
                                last = Some((t, t));
                            }
                        }
                    }
                }
                Found::Apart(d) => min_d = min_d.min(d),
                Found::Undecided => undecided = true,
            }
        }
    }
    Some(match (first, last) {
        // meetings found are certain; their certified-apart bounds stand only when no
        // other body pair was left undecided
        (Some((f, fa)), Some((l, la))) => Outcome::Meets {
            first: f,
            first_apart_until: if undecided { f } else { fa },
            last: l,
            last_apart_from: if undecided { l } else { la },
        },
        _ if undecided => Outcome::Undecided,
        _ => Outcome::Apart {
            min_distance: min_d,
        },
    })
}

/// The two features' distance at `t` (a lower bound, Mercator radians; 0 when they
/// meet, `None` when one is absent at `t` or not modelled), and the slack of the
/// coordinates: to judge the engine's claim that its window's ends are near contact.
pub fn distance_at(fa: &Feature, fb: &Feature, t: f64) -> Option<(f64, f64)> {
    let (ba, bb) = (bodies(fa)?, bodies(fb)?);
    let mut best: Option<(f64, f64)> = None;
    for a in &ba {
        for b in &bb {
            let ((a0, a1), (b0, b1)) = (a.life(), b.life());
            if t < a0.max(b0) || t > a1.min(b1) {
                continue;
            }
            let mut p = Pair::new(a, b);
            let (at, sl) = p.eval(t);
            let d = match at {
                At::Meet | At::Close => 0.0,
                At::Apart(d) => d,
            };
            if best.map_or(true, |(x, _)| d < x) {
                best = Some((d, sl));
            }
        }
    }
    best
}

/// The speed bound of a feature's fastest body (Mercator radians per hour; 0 for areas).
pub fn speed_bound(f: &Feature) -> f64 {
    bodies(f)
        .map(|b| b.iter().map(Body::speed).fold(0f64, f64::max))
        .unwrap_or(0.0)
}
