//! When does the point first enter? An f64 enclosure of the exact first-entry time.
//!
//! Paper A decides *whether* the point s + t·v comes within BUFF of the polygon
//! P + t·V during [0, T] (§II), inside the slab in 3D (§III). Its users also ask *when*.
//! [`first_entry`] answers with an enclosure [lo, hi] of the first time t* ∈ [0, T] at
//! which the point lies in the closed polygon P(t) (and in 3D in the closed slab): the
//! time the oracle's exact truth (`polyguard_oracle::truth`) computes. No BUFF is
//! involved; the question is the one paper A's correctness theorem is about.
//!
//! # Method: certified branch and bound on time
//! For each edge a(t) b(t) the point x(t) is on the edge exactly when
//! g(t) = (x − a) × (b − a) = 0, h₁(t) = (x − a)·(b − a) ≥ 0 and
//! h₂(t) = (b − x)·(b − a) ≥ 0 (paper A §II.C's quadratics without the BUFF band). The
//! three are quadratics in t; on a time interval [m − h, m + h] each lies within
//! f(m) ± (|f′(m)|·h + |f″/2|·h²), evaluated at the float m on `Ball`s, so the range
//! is rigorous (the module doc of `crate::ball` gives the rounding model). An edge
//! whose g range excludes 0, or whose h₁ or h₂ range is negative, certainly has no
//! contact on the interval.
//!
//! While the point is on no edge its winding number about P(t) is constant. The scan
//! visits [0, T] from left to right, halving each interval on which some edge may
//! touch, down to width ε = T·2⁻³⁶. It carries the point's state (outside, inside, or
//! unknown); where no edge may touch and the state is unknown, a certified winding
//! number at the interval's midpoint settles it (0: outside, odd: inside; even and
//! non-zero, possible only when P is not simple, stays unknown, as it is undefined in
//! the truth).
//!
//! Two shortcuts keep the scan short. Where one edge alone may touch, the point is
//! outside before, and on the interval that edge's h₁ and h₂ are certainly positive and
//! g is certainly monotone, the crossing is bracketed at once: Newton's method on the
//! float centres gives an estimate r, and floats r − δ and r + δ at which g has certain,
//! opposite signs bound it (`Edge::lone_crossing`). And once lo is known, hi need not be
//! finer than a 64th of the distance from lo.
//!
//! - **lo**: the start of the first interval on which an entry could not be excluded
//!   (an edge may touch there, or the state is inside or unknown, and the slab may
//!   hold). Every earlier time is certified: no entry.
//! - **hi**: the first time at which the point is certainly in the closed polygon and
//!   slab: the start of an interval that is certainly inside and in the slab, or the end
//!   of an interval on which g certainly changes sign while h₁ > 0 and h₂ > 0 throughout
//!   (then by continuity the point crosses the edge's interior there).
//!
//! So t* ∈ [lo, hi] whenever the truth says the point enters, and a certified `Never`
//! means it never does. Without a certificate for hi the answer is
//! [`EntryTime::Possible`] with hi = T: if the point enters at all (tangent contacts
//! and undefined fill rules are the usual reasons f64 cannot tell), it is in [lo, T].
//!
//! # Cost
//! A crossing costs about 2·36 interval visits, each over the edges still possible on its
//! parent. A visit budget ([`VISIT_BUDGET`]) stops pathological scans (a point sliding
//! along an edge touches it on a whole interval): the answer is then `Possible` from the
//! first time not excluded, which is still a true statement.

use crate::ball::mx;
use crate::motion::{centre, winding, Edge, Frame, SlabLine, State};
pub use crate::motion::{Heights, RESOLUTION, VISIT_BUDGET};
use crate::vect2::Vect2;

/// The answer of [`first_entry`]: where the exact first-entry time t* lies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EntryTime {
    /// Certified: the point is never in the closed polygon (and slab) during [0, T].
    Never,
    /// Certified: the point enters, and t* ∈ [lo, hi].
    Enters {
        /// No entry before lo.
        lo: f64,
        /// In the closed polygon (and slab) at some time ≤ hi.
        hi: f64,
    },
    /// Not certified either way: no entry before lo; if the point enters, t* ∈ [lo, hi]
    /// (hi is then T).
    Possible {
        /// No entry before lo.
        lo: f64,
        /// T.
        hi: f64,
    },
}

impl EntryTime {
    /// "never", "enters" or "possible".
    pub fn name(self) -> &'static str {
        match self {
            EntryTime::Never => "never",
            EntryTime::Enters { .. } => "enters",
            EntryTime::Possible { .. } => "possible",
        }
    }

    /// The enclosure [lo, hi], unless the answer is `Never`.
    pub fn enclosure(self) -> Option<(f64, f64)> {
        match self {
            EntryTime::Never => None,
            EntryTime::Enters { lo, hi } | EntryTime::Possible { lo, hi } => Some((lo, hi)),
        }
    }
}

/// Where the point is against the slab over an interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum InSlab {
    Never,
    Always,
    Maybe,
}

/// The scan's state (see the module doc).
struct Scan<'a> {
    s: Vect2,
    v: Vect2,
    p: &'a [Vect2],
    vels: &'a [Vect2],
    edges: Vec<Edge>,
    /// (sz − bottom, vz − vsp) and (top − sz, vsp − vz): the slab holds when both
    /// lines are ≥ 0.
    slab: Option<[SlabLine; 2]>,
    eps: f64,
    state: State,
    lo: Option<f64>,
    hi: Option<f64>,
    /// The candidate edges of every open interval, as a stack of segments.
    cands: Vec<u32>,
    visits: usize,
    /// Where the scan stood when the budget ran out.
    gave_up_at: Option<f64>,
}

impl Scan<'_> {
    /// The slab over |t − m| ≤ h (paper A §III's window, as ranges).
    fn in_slab(&self, m: f64, h: f64) -> InSlab {
        let Some(lines) = self.slab else {
            return InSlab::Always;
        };
        let mut always = true;
        for line in lines {
            let r = line.range(m, h);
            if r.hi() < 0.0 {
                return InSlab::Never;
            }
            // NaN: neither, so "maybe".
            always &= r.lo() >= 0.0;
        }
        if always {
            InSlab::Always
        } else {
            InSlab::Maybe
        }
    }

    /// The point's winding number about P(τ) (paper A §II.B's crossing count, on
    /// balls): see [`winding`]. An even, non-zero winding number is unknown here (no
    /// entry can be certified there).
    fn winding(&self, tau: f64) -> State {
        match winding(
            self.p.len(),
            |i| (self.p[i], self.vels[i]),
            self.s,
            self.v,
            tau,
        ) {
            State::Undefined => State::Unknown,
            w => w,
        }
    }

    /// Visits [a, b] whose candidate edges are `cands[from..to]`; `true` stops the scan
    /// (hi is found, or the budget is spent).
    fn visit(&mut self, a: f64, b: f64, from: usize, to: usize) -> bool {
        self.visits += 1;
        if self.visits > VISIT_BUDGET {
            self.gave_up_at = Some(a);
            return true;
        }
        let (m, h) = centre(a, b);
        let slab = self.in_slab(m, h);
        let start = self.cands.len();
        for k in from..to {
            let i = self.cands[k];
            if self.edges[i as usize].may_touch(m, h) {
                self.cands.push(i);
            }
        }
        let end = self.cands.len();
        let touching = end > start;
        // Once lo is known the enclosure is at least a − lo wide: hi need not be finer
        // than a 64th of that, which keeps a long stretch of contacts to a few hundred
        // visits per octave.
        let fine = match self.lo {
            Some(lo) => mx(self.eps, (a - lo) * (1.0 / 64.0)),
            None => self.eps,
        };
        let small = b - a <= fine || m <= a || m >= b;
        let stop = if slab == InSlab::Never {
            // No entry here; contacts may change the state without our knowing.
            if touching {
                self.state = State::Unknown;
            }
            false
        } else if !touching {
            if self.state == State::Unknown {
                self.state = self.winding(m);
            }
            match (self.state, slab) {
                (State::Outside, _) => false,
                (State::Inside, InSlab::Always) => {
                    self.lo.get_or_insert(a);
                    self.hi = Some(a);
                    true
                }
                (State::Inside, _) if !small => {
                    // Inside throughout; find where the slab surely holds.
                    self.visit(a, m, start, end) || self.visit(m, b, start, end)
                }
                _ => {
                    self.lo.get_or_insert(a);
                    false
                }
            }
        } else if let Some(lone) = (end - start == 1 && self.state == State::Outside)
            .then(|| self.edges[self.cands[start] as usize].lone_crossing(a, b, m, h, self.eps))
            .flatten()
        {
            // One edge may touch, and the point is outside before: its crossing settles
            // [a, b] at once (see `Edge::lone_crossing`).
            match lone {
                None => false,
                Some((t1, t2)) => {
                    self.lo.get_or_insert(t1);
                    if slab == InSlab::Always {
                        self.hi = Some(t2);
                        true
                    } else {
                        self.state = State::Unknown;
                        false
                    }
                }
            }
        } else if small {
            self.lo.get_or_insert(a);
            let crossed = slab == InSlab::Always
                && self.cands[start..end]
                    .iter()
                    .any(|&i| self.edges[i as usize].surely_crossed(a, b, m, h));
            if crossed {
                self.hi = Some(b);
                true
            } else {
                self.state = State::Unknown;
                false
            }
        } else {
            self.visit(a, m, start, end) || self.visit(m, b, start, end)
        };
        self.cands.truncate(start);
        stop
    }
}

/// The first time t ∈ [0, T] at which s + t·v lies in the closed polygon P + t·V (and,
/// with `heights`, in the closed slab), enclosed in f64 (see the module doc).
///
/// `p` and `vels` have equal lengths (the shorter is used); at least 3 vertices are
/// expected, like paper A's functions. Non-finite inputs give `Possible` from 0.
/// (Paper A §II–III's "the point enters", the question of its §IV theorem, timed.)
pub fn first_entry(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
) -> EntryTime {
    let n = p.len().min(vels.len());
    let (p, vels) = (&p[..n], &vels[..n]);
    if !(t >= 0.0 && t.is_finite()) || n < 3 {
        return EntryTime::Possible {
            lo: 0.0,
            hi: if t.is_finite() { t.max(0.0) } else { f64::MAX },
        };
    }
    // Scale space by a power of two so that the largest magnitude is about 1: the
    // question is the same (every position and velocity times 2^k, exactly), and the
    // products of the scan neither overflow nor underflow. Only an exact scaling is used.
    let frame = Frame::new(t, s, v, p, vels, heights, &[], false);
    let (s, v, heights) = (frame.pt(s), frame.pt(v), heights.map(|z| frame.heights(z)));
    let p: Vec<Vect2> = p.iter().map(|&a| frame.pt(a)).collect();
    let vels: Vec<Vect2> = vels.iter().map(|&a| frame.pt(a)).collect();
    let (p, vels) = (&p[..], &vels[..]);
    let edges: Vec<Edge> = (0..n)
        .map(|i| {
            let j = if i + 1 == n { 0 } else { i + 1 };
            Edge::new(s, v, p[i], vels[i], p[j], vels[j])
        })
        .collect();
    let slab = heights.map(|z| SlabLine::pair(z, 0.0));
    // An edge that is one repeated vertex throughout (the same float position and
    // velocity at both ends) is that vertex, which its neighbours' edges cover, as in the
    // truth; the scan skips it. A polygon of one point has no defined inside.
    let live: Vec<u32> = (0..n)
        .filter(|&i| {
            let j = if i + 1 == n { 0 } else { i + 1 };
            p[i] != p[j] || vels[i] != vels[j]
        })
        .map(|i| i as u32)
        .collect();
    if live.is_empty() {
        return EntryTime::Possible { lo: 0.0, hi: t };
    }
    let n_live = live.len();
    let mut scan = Scan {
        s,
        v,
        p,
        vels,
        edges,
        slab,
        eps: t * RESOLUTION,
        state: State::Unknown,
        lo: None,
        hi: None,
        cands: live,
        visits: 0,
        gave_up_at: None,
    };
    scan.visit(0.0, t, 0, n_live);
    match (scan.lo, scan.hi, scan.gave_up_at) {
        (Some(lo), Some(hi), _) => EntryTime::Enters { lo, hi },
        (lo, None, Some(at)) => EntryTime::Possible {
            lo: lo.unwrap_or(at),
            hi: t,
        },
        (Some(lo), None, None) => EntryTime::Possible { lo, hi: t },
        (None, _, _) => EntryTime::Never,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(d: f64) -> Vec<Vect2> {
        vec![
            Vect2::new(0.0, 0.0),
            Vect2::new(d, 0.0),
            Vect2::new(d, d),
            Vect2::new(0.0, d),
        ]
    }

    /// The point (x, y) moving at (vx, vy) against the polygon p at rest, in 2D.
    fn at_rest(t: f64, s: [f64; 2], v: [f64; 2], p: &[Vect2]) -> EntryTime {
        let still = vec![Vect2::ZERO; p.len()];
        first_entry(
            t,
            Vect2::new(s[0], s[1]),
            Vect2::new(v[0], v[1]),
            p,
            &still,
            None,
        )
    }

    fn encloses(e: EntryTime, t: f64, width: f64) -> bool {
        matches!(e, EntryTime::Enters { lo, hi } if lo <= t && t <= hi && hi - lo <= width)
    }

    #[test]
    fn names_and_enclosures_are_the_answers_own() {
        let enters = EntryTime::Enters { lo: 2.5, hi: 3.0 };
        let possible = EntryTime::Possible { lo: 1.0, hi: 10.0 };
        assert_eq!(
            [EntryTime::Never.name(), enters.name(), possible.name()],
            ["never", "enters", "possible"]
        );
        assert_eq!(EntryTime::Never.enclosure(), None);
        assert_eq!(enters.enclosure(), Some((2.5, 3.0)));
        assert_eq!(possible.enclosure(), Some((1.0, 10.0)));
    }

    #[test]
    fn a_crossing_is_enclosed_tightly() {
        // The point (1, −3) moving up at 1 meets the square's bottom edge at t = 3.
        let p = square(2.0);
        let e = at_rest(10.0, [1.0, -3.0], [0.0, 1.0], &p);
        assert!(encloses(e, 3.0, 1e-9 * 10.0), "{e:?}");
        // Missing it by 0.5 to the right: certified never.
        let e = at_rest(10.0, [2.5, -3.0], [0.0, 1.0], &p);
        assert_eq!(e, EntryTime::Never);
        // Inside from the start.
        let e = at_rest(10.0, [1.0, 1.0], [5.0, 0.0], &p);
        assert_eq!(e, EntryTime::Enters { lo: 0.0, hi: 0.0 });
    }

    #[test]
    fn a_warping_polygon_that_grows_over_the_point() {
        // The point rests at (1, 3); the square's top edge rises at 1 from y = 2: the
        // point is on it at t = 1.
        let p = square(2.0);
        let v = [
            Vect2::ZERO,
            Vect2::ZERO,
            Vect2::new(0.0, 1.0),
            Vect2::new(0.0, 1.0),
        ];
        let e = first_entry(4.0, Vect2::new(1.0, 3.0), Vect2::ZERO, &p, &v, None);
        assert!(encloses(e, 1.0, 1e-9 * 4.0), "{e:?}");
    }

    #[test]
    fn the_slab_starts_the_window() {
        // Inside the square all along, descending at 2 from 20 into a slab topped at 10:
        // in the slab from t = 5.
        let p = square(2.0);
        let z = Heights {
            sz: 20.0,
            vz: -2.0,
            bottom: 0.0,
            top: 10.0,
            vsp: 0.0,
        };
        let hover = |z: Heights| {
            let centre = Vect2::new(1.0, 1.0);
            first_entry(10.0, centre, Vect2::ZERO, &p, &[Vect2::ZERO; 4], Some(z))
        };
        let e = hover(z);
        assert!(encloses(e, 5.0, 1e-9 * 10.0), "{e:?}");
        // Passing over it: never.
        let high = Heights {
            sz: 30.0,
            vz: 0.0,
            ..z
        };
        assert_eq!(hover(high), EntryTime::Never);
    }

    #[test]
    fn every_scale_gives_the_same_time() {
        // The same crossing at t = 3 with every length times 2^k: exact, so the same
        // question; the products would overflow at 2^600 without the scan's rescaling.
        for k in [-1000, -600, -300, 0, 300, 600, 1000] {
            let c = libm::scalbn(1.0, k);
            let p: Vec<Vect2> = square(2.0).iter().map(|q| q.scale(c)).collect();
            let e = at_rest(10.0, [c, -3.0 * c], [0.0, c], &p);
            assert!(encloses(e, 3.0, 1e-9 * 10.0), "2^{k}: {e:?}");
        }
    }

    #[test]
    fn a_tangent_touch_is_possible_not_certain() {
        // Sliding along the bottom edge's line y = 0 from the left: on the boundary from
        // t = 1 (at the corner), which f64 cannot certify.
        let p = square(2.0);
        let e = at_rest(4.0, [-1.0, 0.0], [1.0, 0.0], &p);
        match e {
            EntryTime::Possible { lo, hi } => assert!(lo <= 1.0 && hi == 4.0, "{e:?}"),
            EntryTime::Enters { lo, hi } => assert!(lo <= 1.0 && 1.0 <= hi, "{e:?}"),
            EntryTime::Never => panic!("never, but it touches at t = 1"),
        }
    }

    #[test]
    fn a_repeated_vertex_is_skipped_not_a_contact() {
        // The square with vertex 1 given twice: the zero edge is no contact.
        let mut p = square(2.0);
        p.insert(1, p[1]);
        let e = at_rest(10.0, [5.0, -3.0], [0.0, 1.0], &p);
        assert_eq!(e, EntryTime::Never);
        let e = at_rest(10.0, [1.0, -3.0], [0.0, 1.0], &p);
        assert!(encloses(e, 3.0, 1e-9 * 10.0), "{e:?}");
    }
}
