//! Three-valued timelines: what is known of a closed set of times S over a window
//! [t_0, t_n] (docs/moving-features.md, "How the answer is built"), and the operations
//! that compose the engine's certified spans into the answer of a whole flight.
//!
//! A [`Timeline`] has boundary times t_0 < t_1 < … < t_n; for each boundary a value
//! (`at`) and for each open interval (t_i, t_{i+1}) a value (`between`), each
//! [`Holds::Yes`] (S holds at every time of it), [`Holds::No`] (S holds at none) or
//! [`Holds::Maybe`] (unknown). The engine's spans (G1–G3 of `polyguard::intervals`)
//! become a timeline ([`Timeline::from_spans`]); timelines combine pointwise by Kleene's
//! logic ([`Timeline::and`], [`Timeline::or`], [`Timeline::complement`], [`Timeline::sandwich`]),
//! which keeps every value a true statement; and a timeline becomes spans again
//! ([`Timeline::to_spans`]) that keep G1–G3:
//! - G1: S misses every `No`; every other value lies in a span.
//! - G2: a certain span's [start.hi, end.lo] is a run of `Yes`.
//! - G3: S changes value only where the timeline is `Maybe` or at a boundary between a
//!   `Yes` and a `No`, and both are in a span's enclosure.

use super::planar::TimeSpan;
use super::{next_down, next_up};
use polyguard::Span;

/// What is known of S at a time or over an open interval of times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Holds {
    /// S holds at every time.
    Yes,
    /// Unknown.
    Maybe,
    /// S holds at none.
    No,
}

impl Holds {
    /// Kleene's negation.
    pub fn negated(self) -> Holds {
        match self {
            Holds::Yes => Holds::No,
            Holds::No => Holds::Yes,
            Holds::Maybe => Holds::Maybe,
        }
    }

    /// Kleene's conjunction.
    pub fn and(self, o: Holds) -> Holds {
        match (self, o) {
            (Holds::No, _) | (_, Holds::No) => Holds::No,
            (Holds::Yes, Holds::Yes) => Holds::Yes,
            _ => Holds::Maybe,
        }
    }

    /// Kleene's disjunction.
    pub fn or(self, o: Holds) -> Holds {
        self.negated().and(o.negated()).negated()
    }

    /// Two certified statements about one truth: `Yes` or `No` when either says so (and
    /// the other does not contradict it), else `Maybe`.
    pub fn meet(self, o: Holds) -> Holds {
        match (self, o) {
            (Holds::Yes, Holds::No) | (Holds::No, Holds::Yes) => Holds::Maybe,
            (Holds::Maybe, x) | (x, Holds::Maybe) => x,
            (x, _) => x,
        }
    }
}

/// What is known of a set of times over a window (the module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Timeline {
    /// The boundary times, strictly increasing (at least one).
    pub t: Vec<f64>,
    /// The value at each boundary time.
    pub at: Vec<Holds>,
    /// The value over each open interval between consecutive boundaries.
    pub between: Vec<Holds>,
}

/// The next f64 below `x` (finite).
fn down(x: f64) -> f64 {
    next_down(x)
}

/// The next f64 above `x` (finite).
fn up(x: f64) -> f64 {
    next_up(x)
}

impl Timeline {
    /// One value over the whole window [a, b] (a ≤ b).
    pub fn constant(a: f64, b: f64, v: Holds) -> Timeline {
        if a < b {
            Timeline {
                t: vec![a, b],
                at: vec![v, v],
                between: vec![v],
            }
        } else {
            Timeline {
                t: vec![a],
                at: vec![v],
                between: vec![],
            }
        }
    }

    /// The window's start.
    pub fn start(&self) -> f64 {
        self.t[0]
    }

    /// The window's end.
    pub fn end(&self) -> f64 {
        self.t[self.t.len() - 1]
    }

    /// The value at time `x` of the window.
    pub fn value_at(&self, x: f64) -> Holds {
        match self.t.binary_search_by(|b| b.total_cmp(&x)) {
            Ok(i) => self.at[i],
            Err(0) => self.at[0],
            Err(i) if i >= self.t.len() => self.at[self.t.len() - 1],
            Err(i) => self.between[i - 1],
        }
    }

    /// The value over the open interval (x, y) of the window that lies between two
    /// consecutive boundaries of a finer partition.
    fn value_over(&self, x: f64, y: f64) -> Holds {
        let mid = x + (y - x) / 2.0;
        match self.t.binary_search_by(|b| b.total_cmp(&mid)) {
            // A boundary strictly between x and y cannot be, as they are consecutive in
            // a partition that contains every boundary; mid may round onto x or y.
            Ok(i) if self.t[i] == x => self.between.get(i).copied().unwrap_or(self.at[i]),
            Ok(i) => self.between[i.saturating_sub(1)],
            Err(0) => self.at[0],
            Err(i) if i >= self.t.len() => self.at[self.t.len() - 1],
            Err(i) => self.between[i - 1],
        }
    }

    /// The engine's spans over [0, T] (G1–G3 of `polyguard::intervals`) as a timeline:
    /// a certain span's [start.hi, end.lo] is `Yes`, every enclosure `Maybe`, a possible
    /// span `Maybe`, and the times outside every span `No` (G1).
    pub fn from_spans(lookahead: f64, spans: &[Span]) -> Timeline {
        let at0 = match spans.first() {
            Some(s) if s.certain && s.start.hi == 0.0 => Holds::Yes,
            Some(s) if s.start.lo == 0.0 => Holds::Maybe,
            _ => Holds::No,
        };
        let mut b = Builder::new_at(0.0, at0);
        for s in spans {
            b.reach(s.start.lo, Holds::No, Holds::Maybe);
            if s.certain {
                b.reach(s.start.hi, Holds::Maybe, Holds::Yes);
                b.reach(s.end.lo, Holds::Yes, Holds::Yes);
                b.reach(s.end.hi, Holds::Maybe, Holds::Maybe);
            } else {
                b.reach(s.end.hi, Holds::Maybe, Holds::Maybe);
            }
        }
        b.reach(lookahead, Holds::No, Holds::No);
        b.finish()
    }

    /// Pointwise `f` of two timelines over the same window.
    fn zip(&self, o: &Timeline, f: impl Fn(Holds, Holds) -> Holds) -> Timeline {
        let mut t: Vec<f64> = self.t.iter().chain(o.t.iter()).copied().collect();
        t.sort_by(f64::total_cmp);
        t.dedup();
        let at = t
            .iter()
            .map(|&x| f(self.value_at(x), o.value_at(x)))
            .collect();
        let between = t
            .windows(2)
            .map(|w| f(self.value_over(w[0], w[1]), o.value_over(w[0], w[1])))
            .collect();
        Timeline { t, at, between }.simplified()
    }

    /// Kleene's conjunction, pointwise.
    pub fn and(&self, o: &Timeline) -> Timeline {
        self.zip(o, Holds::and)
    }

    /// Kleene's disjunction, pointwise.
    pub fn or(&self, o: &Timeline) -> Timeline {
        self.zip(o, Holds::or)
    }

    /// Kleene's negation, pointwise (the complement of S).
    pub fn complement(&self) -> Timeline {
        Timeline {
            t: self.t.clone(),
            at: self.at.iter().map(|h| h.negated()).collect(),
            between: self.between.iter().map(|h| h.negated()).collect(),
        }
    }

    /// S between two known sets, `lower` ⊆ S ⊆ `upper`: `Yes` where `lower` is, `No`
    /// where `upper` is not, else `Maybe`.
    pub fn sandwich(lower: &Timeline, upper: &Timeline) -> Timeline {
        lower.zip(upper, |l, u| match (l, u) {
            (Holds::Yes, Holds::No) => Holds::Maybe,
            (Holds::Yes, _) => Holds::Yes,
            (_, Holds::No) => Holds::No,
            _ => Holds::Maybe,
        })
    }

    /// For a closed S: a boundary next to a `Yes` interval is `Yes` (S contains the
    /// closure of that interval).
    pub fn closed(mut self) -> Timeline {
        for i in 0..self.between.len() {
            if self.between[i] == Holds::Yes {
                for j in [i, i + 1] {
                    if self.at[j] == Holds::Maybe {
                        self.at[j] = Holds::Yes;
                    }
                }
            }
        }
        self.simplified()
    }

    /// Boundaries that separate nothing removed (equal values on both sides and at it).
    fn simplified(self) -> Timeline {
        let n = self.t.len();
        if n <= 2 {
            return self;
        }
        let mut t = vec![self.t[0]];
        let mut at = vec![self.at[0]];
        let mut between = Vec::new();
        for i in 1..n - 1 {
            let (l, r) = (self.between[i - 1], self.between[i]);
            if l == r && self.at[i] == l {
                continue;
            }
            between.push(l);
            t.push(self.t[i]);
            at.push(self.at[i]);
        }
        between.push(self.between[n - 2]);
        t.push(self.t[n - 1]);
        at.push(self.at[n - 1]);
        Timeline { t, at, between }
    }

    /// The timeline moved by `shift` (local time τ to global time shift + τ), each
    /// boundary rounded outward: a boundary whose sum is not exact becomes a `Maybe`
    /// interval [down, up] around the exact sum; boundaries that meet merge.
    pub fn shifted(&self, shift: f64) -> Timeline {
        let mut b: Option<Builder> = None;
        for i in 0..self.t.len() {
            let (s, exact) = two_sum_exact(shift, self.t[i]);
            let (lo, hi) = if exact { (s, s) } else { (down(s), up(s)) };
            let v = if exact { self.at[i] } else { Holds::Maybe };
            match b.as_mut() {
                None => b = Some(Builder::new_at(lo, v)),
                Some(b) => {
                    if lo > b.last() {
                        b.reach(lo, self.between[i - 1], v);
                    } else {
                        b.weaken_last();
                    }
                }
            }
            if let Some(b) = b.as_mut() {
                if hi > b.last() {
                    b.weaken_last();
                    b.reach(hi, Holds::Maybe, Holds::Maybe);
                }
            }
        }
        match b {
            Some(b) => b.finish(),
            None => Timeline::constant(shift, shift, Holds::Maybe),
        }
    }

    /// The part over [a, b] (within the window).
    pub fn clipped(&self, a: f64, b: f64) -> Timeline {
        let mut t = vec![a];
        let mut at = vec![self.value_at(a)];
        let mut between = Vec::new();
        for (i, &x) in self.t.iter().enumerate() {
            if x > a && x < b {
                between.push(self.value_over(t[t.len() - 1], x));
                t.push(x);
                at.push(self.at[i]);
            }
        }
        if b > a {
            between.push(self.value_over(t[t.len() - 1], b));
            t.push(b);
            at.push(self.value_at(b));
        }
        Timeline { t, at, between }.simplified()
    }

    /// `self` then `next`, whose window starts where this one ends; the shared time's
    /// two statements meet ([`Holds::meet`]).
    pub fn then(mut self, next: &Timeline) -> Timeline {
        let last = self.at.len() - 1;
        self.at[last] = self.at[last].meet(next.at[0]);
        self.t.extend_from_slice(&next.t[1..]);
        self.at.extend_from_slice(&next.at[1..]);
        self.between.extend_from_slice(&next.between);
        // Both parts are simplified; only the shared boundary may separate nothing.
        if last > 0 && last + 1 < self.t.len() {
            let (l, r) = (self.between[last - 1], self.between[last]);
            if l == r && self.at[last] == l {
                self.t.remove(last);
                self.at.remove(last);
                self.between.remove(last);
            }
        }
        self
    }

    /// The one value of a timeline that has no other, if so.
    pub fn as_constant(&self) -> Option<Holds> {
        let v = self.at[0];
        (self.at.iter().chain(&self.between).all(|&x| x == v)).then_some(v)
    }

    /// The spans that keep G1–G3 (the module doc): each maximal run of times that are not
    /// `No` gives its spans; in a run, each stretch of `Yes` is a certain span whose
    /// start encloses the run's `Maybe` times before it and whose end those after it
    /// (two neighbours share the `Maybe` times between them); a run without `Yes` is one
    /// possible span.
    pub fn to_spans(&self) -> Vec<TimeSpan> {
        let mut out = Vec::new();
        // Elements in time order: (lo, hi, value); a boundary is (t, t, at).
        let mut elems: Vec<(f64, f64, Holds)> = Vec::with_capacity(2 * self.t.len());
        for i in 0..self.t.len() {
            elems.push((self.t[i], self.t[i], self.at[i]));
            if i < self.between.len() {
                elems.push((self.t[i], self.t[i + 1], self.between[i]));
            }
        }
        let mut k = 0;
        while k < elems.len() {
            if elems[k].2 == Holds::No {
                k += 1;
                continue;
            }
            let mut run_end = k;
            while run_end + 1 < elems.len() && elems[run_end + 1].2 != Holds::No {
                run_end += 1;
            }
            spans_of_run(&elems[k..=run_end], &mut out);
            k = run_end + 1;
        }
        out
    }
}

/// The spans of one run of elements that are not `No` ([`Timeline::to_spans`]).
fn spans_of_run(run: &[(f64, f64, Holds)], out: &mut Vec<TimeSpan>) {
    let lo = run[0].0;
    let hi = run[run.len() - 1].1;
    // The stretches of Yes: [a, b] hulls of consecutive Yes elements.
    let mut yes: Vec<(f64, f64)> = Vec::new();
    let mut i = 0;
    while i < run.len() {
        if run[i].2 == Holds::Yes {
            let a = run[i].0;
            let mut j = i;
            while j + 1 < run.len() && run[j + 1].2 == Holds::Yes {
                j += 1;
            }
            yes.push((a, run[j].1));
            i = j + 1;
        } else {
            i += 1;
        }
    }
    if yes.is_empty() {
        out.push(TimeSpan {
            start: [lo, hi],
            end: [lo, hi],
            certain: false,
        });
        return;
    }
    for (k, &(a, b)) in yes.iter().enumerate() {
        let start_lo = if k == 0 { lo } else { yes[k - 1].1 };
        let end_hi = if k + 1 == yes.len() { hi } else { yes[k + 1].0 };
        out.push(TimeSpan {
            start: [start_lo, a],
            end: [b, end_hi],
            certain: true,
        });
    }
}

/// `a + b` rounded to nearest, and whether it is exact (Knuth's two-sum).
fn two_sum_exact(a: f64, b: f64) -> (f64, bool) {
    let s = a + b;
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    (s, err == 0.0)
}

/// Builds a timeline left to right.
struct Builder {
    t: Vec<f64>,
    at: Vec<Holds>,
    between: Vec<Holds>,
}

impl Builder {
    /// A timeline starting at `t0` with the value `v` there.
    fn new_at(t0: f64, v: Holds) -> Builder {
        Builder {
            t: vec![t0],
            at: vec![v],
            between: vec![],
        }
    }

    /// The last boundary.
    fn last(&self) -> f64 {
        self.t[self.t.len() - 1]
    }

    /// The last boundary's value made `Maybe`.
    fn weaken_last(&mut self) {
        let n = self.at.len();
        self.at[n - 1] = Holds::Maybe;
    }

    /// Extends the timeline to time `x`: `over` on (last, x), `at` at x. A time equal
    /// to the last boundary adds the statement `at` about it (two spans' shared
    /// enclosure; a `No` there is the gap's and says nothing of the point); an earlier
    /// time adds nothing.
    fn reach(&mut self, x: f64, over: Holds, at: Holds) {
        let n = self.t.len();
        let last = self.t[n - 1];
        if x > last {
            self.between.push(over);
            self.t.push(x);
            self.at.push(at);
        } else if x == last && at != Holds::No {
            self.at[n - 1] = self.at[n - 1].meet(at);
        }
    }

    /// The timeline, simplified.
    fn finish(self) -> Timeline {
        Timeline {
            t: self.t,
            at: self.at,
            between: self.between,
        }
        .simplified()
    }
}
