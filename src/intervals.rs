//! Every time the relation holds: certified intervals of inside, near_D and breach_D over
//! [0, T] (paper A §II–§III's motion, timed; `entry::first_entry` gives the first entry).
//!
//! # Definitions
//! A case: T > 0, the point x(t) = s + t·v (3D: height z(t) = sz + t·vz), the polygon
//! P(t) with vertices p_i + t·V_i (static, translating or warping), in 3D the slab
//! bottom(t) = bottom + t·vsp ≤ z ≤ top(t) = top + t·vsp; separations D ≥ 0, H ≥ 0
//! ([`Separation`]).
//! - inside(t): x(t) in the closed polygon P(t) (and bottom(t) ≤ z(t) ≤ top(t) in 3D).
//! - near_D(t): the horizontal distance from x(t) to the closed P(t) is ≤ D (0 when
//!   inside), and in 3D bottom(t) − H ≤ z(t) ≤ top(t) + H.
//! - fence_D(t): x(t) in P(t) at distance > D from its boundary ∂P(t), and in 3D
//!   bottom(t) + H < z(t) < top(t) − H.
//! - breach_D(t) := not fence_D(t) (the keep-in fence is breached; a closed set of t).
//!
//! Each set S of times is closed, a finite union of closed intervals. For a polygon
//! that is not simple, inside is undefined where the point's winding number is even and
//! non-zero (as in the exact truth); the scan reports such a stretch as uncertain.
//!
//! # What the spans certify
//! [`intervals_into`] (and `intervals`, its `Vec` form with `std`) returns spans sorted in time: start.lo ≤ start.hi ≤ end.lo ≤ end.hi,
//! all in [0, T], and span\[k\].end.hi ≤ span\[k+1\].start.lo (equal enclosures mean that
//! both spans share one uncertain cluster).
//! - **G1** (nothing missed): S ⊆ ∪ₖ [startₖ.lo, endₖ.hi].
//! - **G2** (certain means certain): when `certain`, S ⊇ [start.hi, end.lo].
//! - **G3** (every end enclosed): each end a or b of a component [a, b] of S, 0 and T
//!   included, lies in some span's start or end enclosure.
//!
//! # Method
//! A certified branch and bound over time (module `scan`), the method of
//! `entry::first_entry`: on a piece [a, b] (centre m, half width h) every edge's quadratics
//! g = (x − a)×(b − a), h₁ = (x − a)·(b − a), h₂ = (b − x)·(b − a) (§II.C without the
//! BUFF band), the band's sides g ∓ D·|b − a| (the range of |b − a| is the square root
//! of the range of the quadratic |b − a|², its ends rounded outward) and the vertex
//! terms |x − p_k|² − D² are enclosed by their Taylor ranges; the slab lines by theirs.
//! From them, sufficient conditions over the whole closed piece:
//! - no contact: g ≠ 0, or h₁ < 0, or h₂ < 0 throughout, for every edge. Then the
//!   winding number is constant on the piece, and a certified crossing count at m
//!   (§II.B on balls) gives it: 0 outside, odd inside, even and not 0 undefined (a
//!   polygon that is not simple), or unknown.
//! - farther than D from an edge: g − D|e| > 0 or g + D|e| < 0 (the line is farther;
//!   for D = 0: g ≠ 0), or h₁ < 0 and |x − a| > D, or h₂ < 0 and |x − b| > D,
//!   throughout (the nearest point of the segment is then on its line, at a, or at b).
//! - within D of an edge: |x − a|² − D² ≤ 0, or |x − b|² − D² ≤ 0, or h₁ ≥ 0, h₂ ≥ 0
//!   and g − D|e| ≤ 0 ≤ g + D|e| throughout.
//!
//! inside **holds** on the piece when there is no contact, the point is inside and the
//! slab's lines are ≥ 0; it **fails** when the slab's lines exclude it or there is no
//! contact and the point is outside. near_D holds when the grown slab holds and the
//! point is inside or within D of an edge; it fails when the grown slab excludes it, or
//! the point is outside and farther than D from every edge. breach_D holds when the point
//! is outside, or within D of an edge, or a shrunk slab line is ≤ 0; it fails when the
//! point is inside, farther than D from every edge and strictly inside the shrunk slab.
//! (Every edge that is farther than D, or certainly not touched, on a piece stays so on
//! its halves, so the halves test only the others.) A piece that is neither is halved,
//! down to width ε = T·2⁻³⁶ (inside a cluster already L long, L/64: its end cannot be
//! enclosed more finely than that); there it is **undecided**. So is, at once, a piece
//! without contact on which the winding number is certainly even and not 0 and no edge
//! is undecided: there the relation is undefined, and halving cannot change that.
//!
//! A shortcut settles the common piece at once (module `scan::shortcut`): when at most
//! three of those functions may change sign on the piece (and matter there), each
//! certainly monotone with certain signs at a and b, each root is bracketed in
//! (t1, t2), t2 − t1 ≤ 2ε, by Newton's method and certified signs; the sub-pieces
//! between the brackets are decided with each function's range taken as the hull of its
//! values at their ends (exact for a monotone function), and the brackets are undecided
//! (unless both sides are decided alike and the bracket is too).
//!
//! The pieces tile [0, T] from left to right. Runs of pieces that hold are *true
//! stretches*, runs that fail *false stretches*, runs of undecided pieces *clusters*.
//! Each true stretch [α, β] becomes a certain span: its start is the cluster just before
//! it ([0, 0] at t = 0, or [α, α] after a false stretch), its end the cluster just after
//! it ([T, T] at t = T, or [β, β] before a false stretch); two true stretches around one
//! cluster give two spans sharing it. A cluster between false stretches (or [0, T]'s
//! ends) is a possible span with start = end = the cluster.
//!
//! # Proof of G1–G3
//! Each decision is a certified statement about every t of a closed piece (the ranges
//! enclose the exact functions there, the error analysis below). G1: S misses every false
//! stretch; every true stretch and every cluster lies within a span's [start.lo, end.hi].
//! G2: a certain span's [start.hi, end.lo] is its true stretch. G3: an end of a component
//! of S is where S changes, or 0 or T. It is not inside a stretch (S is constant there,
//! and a stretch's closed pieces both hold or both fail at the point they share), so it
//! is in a cluster, or at a stretch's end where the stretch meets [0, T]'s end or a
//! stretch of the other kind, each an enclosure of the span that stretch or cluster
//! gives. Sortedness: the pieces come in time order.
//!
//! When the visit budget (`VISIT_BUDGET` intervals) runs out, the rest of
//! [0, T] is one cluster: the statements stay true, only coarser.
//!
//! # Error analysis
//! That of `entry::first_entry`: every value is a `Ball` at an exact float time, each
//! operation adding 2u·|result| to the radius (`crate::ball`'s rounding model), and a
//! quadratic's Taylor form f(m) ± (|f′(m)|·h + |f″/2|·h²) is exact over |t − m| ≤ h,
//! so its range is rigorous; the square root of a range rounds its ends outward; every
//! decision compares an end of a range with 0. A case whose magnitudes are beyond
//! 2^±300 is first scaled by an exact power of two, so that no product overflows or
//! underflows. No absolute epsilon enters;
//! an enclosure's width is the resolution ε, or the rounding noise of the function whose
//! root it holds when that is larger.
//!
//! # Allocation
//! [`intervals_into`] allocates nothing: the scan keeps its edges and candidate lists in
//! fixed arrays on the stack (past their size it tests every edge, more slowly).

mod scan;

#[cfg(feature = "std")]
use std::vec::Vec;

#[cfg(feature = "std")]
use crate::error::CaseError;
pub use crate::motion::Heights;
use crate::vect2::Vect2;
pub(crate) use scan::{Class, Parts, Pieces, Scan, Workspace};

/// Which set of times a scan encloses (the module doc's definitions).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Relation {
    /// inside(t): in the closed polygon (and slab).
    Inside,
    /// near_D(t): within D of the closed polygon (and within H of the slab): the first
    /// span's start is the loss of separation.
    Near,
    /// breach_D(t): not deep inside the keep-in fence (not inside at distance > D from
    /// its boundary, or not more than H inside the slab's ends).
    Breach,
}

impl Relation {
    /// The three relations.
    pub const ALL: [Relation; 3] = [Relation::Inside, Relation::Near, Relation::Breach];

    /// "inside", "near" or "breach".
    pub fn name(self) -> &'static str {
        match self {
            Relation::Inside => "inside",
            Relation::Near => "near",
            Relation::Breach => "breach",
        }
    }
}

/// The separations of near_D and breach_D: D horizontally, H vertically (3D).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation {
    /// D ≥ 0, the horizontal separation (a length).
    pub d: f64,
    /// H ≥ 0, the vertical separation (a height; unused in 2D).
    pub h: f64,
}

impl Separation {
    /// No separation: D = H = 0 (near_0 is inside; breach_0 is "not in the open
    /// interior").
    pub const NONE: Separation = Separation { d: 0.0, h: 0.0 };

    /// D and H, each finite and ≥ 0: the typed error names `sep` (D) or `sep_v` (H), as
    /// the case format does.
    #[cfg(feature = "std")]
    pub fn new(d: f64, h: f64) -> Result<Separation, CaseError> {
        for (field, x) in [("sep", d), ("sep_v", h)] {
            if !x.is_finite() {
                return Err(CaseError::NotFinite {
                    field: field.into(),
                });
            }
            if x < 0.0 {
                return Err(CaseError::OutOfRange {
                    field,
                    value: x,
                    range: "[0, ∞)",
                });
            }
        }
        Ok(Separation { d, h })
    }
}

/// An enclosure [lo, hi] of one exact end of a component of the relation's set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct End {
    /// The enclosure's lower end.
    pub lo: f64,
    /// The enclosure's upper end.
    pub hi: f64,
}

impl End {
    /// The enclosure [t, t] of an end known exactly (0, T, or where stretches meet).
    pub const fn at(t: f64) -> End {
        End { lo: t, hi: t }
    }
}

/// One span of the answer (see the module doc's G1–G3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span {
    /// Encloses where the relation starts to hold (or may).
    pub start: End,
    /// Encloses where it stops.
    pub end: End,
    /// Certain: the relation holds on all of [start.hi, end.lo]. Possible (false): it
    /// may hold nowhere in the span.
    pub certain: bool,
}

/// The output slice of [`intervals_into`] was too small: the answer has this many spans
/// (the ones that fit were written).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Overflow {
    /// How many spans the answer has.
    pub needed_at_least: usize,
}

/// Where spans go.
trait Sink {
    /// One more span, in order.
    fn push(&mut self, span: Span);
}

/// A slice of spans, and how many the answer has (past its length they are counted).
struct SliceSink<'o> {
    out: &'o mut [Span],
    n: usize,
}

impl Sink for SliceSink<'_> {
    /// Writes the span if there is room, and counts it.
    fn push(&mut self, span: Span) {
        if let Some(slot) = self.out.get_mut(self.n) {
            *slot = span;
        }
        self.n += 1;
    }
}

#[cfg(feature = "std")]
impl Sink for Vec<Span> {
    /// Appends the span.
    fn push(&mut self, span: Span) {
        Vec::push(self, span);
    }
}

/// Pieces → spans: stretches and clusters as the module doc's "Method" turns them into
/// spans, streamed (nothing is kept but the open span and the open cluster).
struct Spans<'k, K: Sink> {
    sink: &'k mut K,
    t: f64,
    /// The start of the span of the true stretch in progress, if one is.
    open: Option<End>,
    /// The cluster in progress, if one is.
    cluster: Option<End>,
}

impl<K: Sink> Spans<'_, K> {
    /// The cluster in progress ends: it ends the open span (certain), or is a possible
    /// span of its own.
    fn close_cluster(&mut self) -> Option<End> {
        let c = self.cluster.take()?;
        match self.open.take() {
            Some(start) => self.sink.push(Span {
                start,
                end: c,
                certain: true,
            }),
            None => self.sink.push(Span {
                start: c,
                end: c,
                certain: false,
            }),
        }
        Some(c)
    }

    /// [0, T] is tiled: the last span closes at its cluster or at T.
    fn finish(&mut self) {
        if self.close_cluster().is_none() {
            if let Some(start) = self.open.take() {
                self.sink.push(Span {
                    start,
                    end: End::at(self.t),
                    certain: true,
                });
            }
        }
    }
}

impl<K: Sink> Pieces for Spans<'_, K> {
    /// One more piece (the module doc's "Method": stretches and clusters to spans).
    fn piece(&mut self, a: f64, b: f64, class: Class) -> bool {
        match class {
            Class::Unsure => {
                let lo = self.cluster.map_or(a, |c| c.lo);
                self.cluster = Some(End { lo, hi: b });
            }
            Class::Holds => {
                if let Some(c) = self.cluster.take() {
                    // The cluster ends the span before (if one is open) and starts this.
                    if let Some(start) = self.open.take() {
                        self.sink.push(Span {
                            start,
                            end: c,
                            certain: true,
                        });
                    }
                    self.open = Some(c);
                } else if self.open.is_none() {
                    self.open = Some(End::at(a));
                }
            }
            Class::Fails => {
                if self.close_cluster().is_none() {
                    if let Some(start) = self.open.take() {
                        self.sink.push(Span {
                            start,
                            end: End::at(a),
                            certain: true,
                        });
                    }
                }
            }
        }
        false
    }
}

/// Runs the scan and streams its spans into `sink`; a case outside the scan's domain
/// gives one possible span over [0, T] (see [`intervals_into`]).
#[allow(clippy::too_many_arguments)]
fn scan_into(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    relation: Relation,
    sep: Separation,
    sink: &mut impl Sink,
) {
    let mut ws = Workspace::new();
    match Scan::new(t, s, v, p, vels, heights, relation, sep, ws.parts()) {
        Some(mut scan) => {
            let mut spans = Spans {
                sink,
                t,
                open: None,
                cluster: None,
            };
            scan.run(&mut spans);
            spans.finish();
        }
        None => {
            let whole = End {
                lo: 0.0,
                hi: if t.is_finite() { t.max(0.0) } else { f64::MAX },
            };
            sink.push(Span {
                start: whole,
                end: whole,
                certain: false,
            });
        }
    }
}

/// The spans of `relation` over [0, T] (module doc: definitions, G1–G3), written to
/// `out`; returns how many. Allocates nothing.
///
/// `p` and `vels` have equal lengths (the shorter is used). A case the scan cannot
/// certify anything about (T negative or not finite, fewer than 3 vertices, a
/// coordinate that is not finite, a separation the relation uses that is negative or
/// not finite) gives one possible span over [0, T]. (Paper A §II–§III's motion; the
/// definitions of the module doc.)
///
/// ```
/// use polyguard::intervals::{intervals_into, Relation, Separation};
/// use polyguard::{Span, Vect2};
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// let still = [Vect2::ZERO; 4];
/// // (1, −2) moving up at 1: inside the square from t = 2 to t = 4.
/// let (s, v) = (Vect2::new(1.0, -2.0), Vect2::new(0.0, 1.0));
/// let mut out = [Span { start: polyguard::End::at(0.0), end: polyguard::End::at(0.0), certain: false }; 4];
/// let n = intervals_into(10.0, s, v, &square, &still, None, Relation::Inside, Separation::NONE, &mut out).unwrap();
/// assert_eq!(n, 1);
/// let span = out[0];
/// assert!(span.certain && span.start.lo <= 2.0 && 2.0 <= span.start.hi && span.end.lo <= 4.0 && 4.0 <= span.end.hi);
/// assert!(span.end.hi - span.start.lo < 2.0 + 1e-8);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn intervals_into(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    relation: Relation,
    sep: Separation,
    out: &mut [Span],
) -> Result<usize, Overflow> {
    let mut sink = SliceSink { out, n: 0 };
    scan_into(t, s, v, p, vels, heights, relation, sep, &mut sink);
    if sink.n > sink.out.len() {
        Err(Overflow {
            needed_at_least: sink.n,
        })
    } else {
        Ok(sink.n)
    }
}

/// The spans of `relation` over [0, T], as a `Vec` (see [`intervals_into`] and the
/// module doc's G1–G3; paper A §II–§III's motion).
///
/// ```
/// use polyguard::intervals::{intervals, Relation, Separation};
/// use polyguard::Vect2;
/// let square = [Vect2::new(0.0, 0.0), Vect2::new(2.0, 0.0), Vect2::new(2.0, 2.0), Vect2::new(0.0, 2.0)];
/// // Passing 1 below the square: within D = 1.5 of it from t = 3 − √1.25 to t = 5 + √1.25.
/// let spans = intervals(10.0, Vect2::new(-3.0, -1.0), Vect2::new(1.0, 0.0), &square, &[Vect2::ZERO; 4],
///     None, Relation::Near, Separation { d: 1.5, h: 0.0 });
/// assert_eq!(spans.len(), 1);
/// let (a, b) = (3.0 - 1.25f64.sqrt(), 5.0 + 1.25f64.sqrt());
/// assert!(spans[0].start.lo <= a && a <= spans[0].start.hi);
/// assert!(spans[0].end.lo <= b && b <= spans[0].end.hi);
/// ```
#[cfg(feature = "std")]
#[allow(clippy::too_many_arguments)]
pub fn intervals(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    heights: Option<Heights>,
    relation: Relation,
    sep: Separation,
) -> Vec<Span> {
    let mut spans = Vec::new();
    scan_into(t, s, v, p, vels, heights, relation, sep, &mut spans);
    spans
}

#[cfg(test)]
mod tests;
