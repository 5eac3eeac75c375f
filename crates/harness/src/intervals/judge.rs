//! The verdict on one interval case: the engine's certified spans of inside, near_D and
//! breach_D, and its keep-in exit answer, against the oracle's exact components
//! (docs/cases.md, "Separation and fences", gives the definitions and what a span
//! certifies).
//!
//! With S the exact set of a relation (a finite union of closed components [a, b], ends
//! real algebraic numbers) and the engine's spans, each with a start and an end
//! enclosure, the checks are exact comparisons of algebraic numbers with the spans'
//! floats (every f64 is a rational):
//! - `interval_missed`: a component not inside the union of the spans' hulls
//!   [start.lo, end.hi] (G1: the engine said "certainly not" at a time where the
//!   relation holds);
//! - `end_outside`: an end a or b in no enclosure of any span (G3);
//! - `interval_false`: a certain span whose stretch [start.hi, end.lo] is not inside one
//!   component (G2: "certainly holds" where it does not);
//! - `span_malformed`: spans out of order, not finite, or outside [0, T];
//! - `exit_missed`: the fence is breached (S of breach_D is not empty) and the exit
//!   detector says a certified no: the contract of exit detection;
//! - `exit_false`: a certified exit where the fence holds throughout.

use std::cmp::Ordering;
use std::time::Instant;

use polyguard::api;
use polyguard::intervals::{Relation, Separation, Span};
use polyguard::Tri;
use polyguard_oracle::algebraic::RealAlg;

use super::gen::IntervalCase;
use crate::classify::{CompareError, Exact};

/// The three relations, in report order.
pub const RELATIONS: [Relation; 3] = [Relation::Inside, Relation::Near, Relation::Breach];

/// The class of one relation's spans, or of a whole case (its worst).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum IntervalClass {
    /// Every check passes.
    Agree,
    /// The truth is undefined (the polygon is not simple where it matters): not judged.
    Undefined,
    /// A certified exit where the fence holds throughout. A failure.
    ExitFalse,
    /// Spans out of order, not finite or outside [0, T]. A failure.
    SpanMalformed,
    /// A certain span's stretch where the relation does not hold throughout. A failure.
    IntervalFalse,
    /// An exact end outside every enclosure. A failure.
    EndOutside,
    /// The fence is breached and the exit detector says a certified no. A failure.
    ExitMissed,
    /// A true component outside the spans' hulls. The worst failure.
    IntervalMissed,
}

impl IntervalClass {
    /// Every class, in report order.
    pub const ALL: [IntervalClass; 8] = [
        IntervalClass::Agree,
        IntervalClass::Undefined,
        IntervalClass::IntervalMissed,
        IntervalClass::EndOutside,
        IntervalClass::IntervalFalse,
        IntervalClass::SpanMalformed,
        IntervalClass::ExitMissed,
        IntervalClass::ExitFalse,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            IntervalClass::Agree => "agree",
            IntervalClass::Undefined => "undefined",
            IntervalClass::IntervalMissed => "interval_missed",
            IntervalClass::EndOutside => "end_outside",
            IntervalClass::IntervalFalse => "interval_false",
            IntervalClass::SpanMalformed => "span_malformed",
            IntervalClass::ExitMissed => "exit_missed",
            IntervalClass::ExitFalse => "exit_false",
        }
    }

    /// One line on what the class means (the summary's legend).
    pub fn meaning(self) -> &'static str {
        match self {
            IntervalClass::Agree => "every span and the exit answer agree with the exact truth",
            IntervalClass::Undefined => "the truth is undefined (fill rule): not judged",
            IntervalClass::IntervalMissed => {
                "a true interval outside every span: THE failure of intervals"
            }
            IntervalClass::EndOutside => "an exact end outside every enclosure: a failure",
            IntervalClass::IntervalFalse => {
                "a certain span where the relation does not hold throughout: a failure"
            }
            IntervalClass::SpanMalformed => "spans out of order or outside [0, T]: a failure",
            IntervalClass::ExitMissed => {
                "the fence is left, the exit detector says no: THE failure of exits"
            }
            IntervalClass::ExitFalse => "a certified exit from a fence that holds: a failure",
        }
    }

    /// A failure that a campaign must report with a non-zero exit status.
    pub fn is_failure(self) -> bool {
        !matches!(self, IntervalClass::Agree | IntervalClass::Undefined)
    }
}

/// Which intervals engine a campaign judges: the certified one, or a canary that the
/// checks must catch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum IntervalEngine {
    /// The certified engine: the product.
    #[default]
    Certified,
    /// Every span's end enclosure moved right past itself by [`END_CANARY_STEPS`]
    /// resolution steps: an exact end then lies before it (`end_outside`).
    ShiftedEnd,
    /// The second span of every relation dropped (`interval_missed`).
    DropSecond,
    /// Exit detection blind to the slab: the horizontal breach alone (`exit_missed` on
    /// fences left through the floor or the ceiling).
    FlatExit,
}

impl IntervalEngine {
    /// The command line's name.
    pub fn name(self) -> &'static str {
        match self {
            IntervalEngine::Certified => "f64",
            IntervalEngine::ShiftedEnd => "shifted-end",
            IntervalEngine::DropSecond => "drop-second",
            IntervalEngine::FlatExit => "flat-exit",
        }
    }
}

/// How far the end canary moves an end enclosure beyond its own width, in resolution
/// steps of T (2⁻³⁶·T each, the engine's finest).
pub const END_CANARY_STEPS: f64 = 4.0;

/// The verdict on one relation.
#[derive(Clone, Debug, PartialEq)]
pub struct RelationVerdict {
    /// Which relation.
    pub relation: Relation,
    /// Its class.
    pub class: IntervalClass,
    /// The engine's spans.
    pub spans: Vec<Span>,
    /// How many exact components the truth has.
    pub components: usize,
    /// Why the class is a failure, when it is.
    pub why: Option<String>,
}

/// The verdict on one case.
#[derive(Clone, Debug, PartialEq)]
pub struct IntervalVerdict {
    /// The worst class of the relations and the exit.
    pub class: IntervalClass,
    /// Inside, near_D, breach_D.
    pub relations: Vec<RelationVerdict>,
    /// The exact answer to "is the fence left?" (`None`: undefined).
    pub exit_truth: Option<bool>,
    /// The engine's exit answer.
    pub exit_engine: Tri,
    /// The case's lookahead T.
    pub lookahead: f64,
    /// Time in the engine's intervals (three relations), the oracle's (three), the
    /// engine's exit detection, and `api::detect_time` (ns).
    pub nanos: [u64; 4],
}

/// The exact comparison of an algebraic end with a float (every f64 is a rational).
pub(crate) fn cmp_f64(a: &RealAlg, x: f64) -> Ordering {
    match polyguard_oracle::convert::q(x) {
        Some(r) => a.cmp_rational(&r),
        None if x > 0.0 => Ordering::Less,
        None => Ordering::Greater,
    }
}

/// lo ≤ a ≤ hi, exactly.
pub(crate) fn within(a: &RealAlg, lo: f64, hi: f64) -> bool {
    cmp_f64(a, lo) != Ordering::Less && cmp_f64(a, hi) != Ordering::Greater
}

/// What is malformed in `spans` (order, finiteness, [0, T]), if anything.
fn malformed(spans: &[Span], t: f64) -> Option<String> {
    let mut last = 0.0f64;
    let mut previous: Option<&Span> = None;
    for (k, s) in spans.iter().enumerate() {
        // two spans may share one cluster: the end of one is the start of the next
        let shared = previous.is_some_and(|p| p.end == s.start);
        previous = Some(s);
        if shared {
            last = s.start.lo;
        }
        let ends = [s.start.lo, s.start.hi, s.end.lo, s.end.hi];
        if ends.iter().any(|x| !x.is_finite()) {
            return Some(format!("span {k}: an end is not finite"));
        }
        // A possible span may be one cluster (start == end); a certain one has its
        // stretch between the enclosures.
        let ordered = last <= ends[0]
            && ends[0] <= ends[1]
            && ends[2] <= ends[3]
            && ends[0] <= ends[2]
            && ends[1] <= ends[3]
            && (!s.certain || ends[1] <= ends[2])
            && ends[3] <= t;
        if !ordered {
            return Some(format!(
                "span {k}: [{:e}, {:e}]..[{:e}, {:e}] is out of order or outside [0, {t:e}]",
                ends[0], ends[1], ends[2], ends[3]
            ));
        }
        last = ends[3];
    }
    None
}

/// The spans' hulls [start.lo, end.hi], merged where they touch.
fn hulls(spans: &[Span]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for s in spans {
        match out.last_mut() {
            Some(h) if s.start.lo <= h.1 => h.1 = h.1.max(s.end.hi),
            _ => out.push((s.start.lo, s.end.hi)),
        }
    }
    out
}

/// The checks of the module doc for one relation: `None` when they pass, else the class
/// and why.
pub fn check_spans(
    spans: &[Span],
    truth: &[(RealAlg, RealAlg)],
    t: f64,
) -> Option<(IntervalClass, String)> {
    if let Some(why) = malformed(spans, t) {
        return Some((IntervalClass::SpanMalformed, why));
    }
    let hull = hulls(spans);
    for (k, (a, b)) in truth.iter().enumerate() {
        let covered = hull.iter().any(|&(lo, hi)| {
            cmp_f64(a, lo) != Ordering::Less && cmp_f64(b, hi) != Ordering::Greater
        });
        if !covered {
            return Some((
                IntervalClass::IntervalMissed,
                format!(
                    "component {k} [{}, {}] is outside every span",
                    a.to_decimal_string(17),
                    b.to_decimal_string(17)
                ),
            ));
        }
    }
    let enclosures: Vec<(f64, f64)> = spans
        .iter()
        .flat_map(|s| [(s.start.lo, s.start.hi), (s.end.lo, s.end.hi)])
        .collect();
    for (k, (a, b)) in truth.iter().enumerate() {
        for (which, x) in [("start", a), ("end", b)] {
            if !enclosures.iter().any(|&(lo, hi)| within(x, lo, hi)) {
                return Some((
                    IntervalClass::EndOutside,
                    format!(
                        "the {which} of component {k}, {}, is in no enclosure",
                        x.to_decimal_string(17)
                    ),
                ));
            }
        }
    }
    for (k, s) in spans.iter().enumerate().filter(|(_, s)| s.certain) {
        let held = truth.iter().any(|(a, b)| {
            cmp_f64(a, s.start.hi) != Ordering::Greater && cmp_f64(b, s.end.lo) != Ordering::Less
        });
        if !held {
            return Some((
                IntervalClass::IntervalFalse,
                format!(
                    "span {k} is certain on [{:e}, {:e}], which no component covers",
                    s.start.hi, s.end.lo
                ),
            ));
        }
    }
    None
}

/// The canary's spans: `spans` as the chosen engine reports them.
fn as_engine(mut spans: Vec<Span>, engine: IntervalEngine, t: f64) -> Vec<Span> {
    match engine {
        IntervalEngine::ShiftedEnd => {
            let step = END_CANARY_STEPS * t * polyguard::entry::RESOLUTION;
            for s in spans.iter_mut() {
                let w = s.end.hi - s.end.lo;
                s.end.lo += w + step;
                s.end.hi += w + step;
            }
            spans
        }
        IntervalEngine::DropSecond => {
            if spans.len() > 1 {
                spans.remove(1);
            }
            spans
        }
        IntervalEngine::Certified | IntervalEngine::FlatExit => spans,
    }
}

/// The relation's name in the oracle.
fn oracle_relation(r: Relation) -> polyguard_oracle::intervals::Relation {
    use polyguard_oracle::intervals::Relation as O;
    match r {
        Relation::Inside => O::Inside,
        Relation::Near => O::Near,
        Relation::Breach => O::Breach,
    }
}

/// Time since `clock` in ns.
fn ns(clock: Instant) -> u64 {
    u64::try_from(clock.elapsed().as_nanos()).unwrap_or(u64::MAX)
}

/// The verdict on one case, judged as `engine` answers it.
pub fn judge(ic: &IntervalCase, engine: IntervalEngine) -> Result<IntervalVerdict, CompareError> {
    let raw = &ic.raw;
    let case = raw
        .to_api()
        .map_err(|e| CompareError::Engine(e.to_string()))?;
    let sep = Separation {
        d: ic.sep,
        h: ic.sep_v,
    };
    let (exact, lengths) = raw
        .exact_with_lengths::<Exact>(&[ic.sep, ic.sep_v])
        .map_err(|e| CompareError::Oracle(e.to_string()))?;
    let osep = match lengths.as_slice() {
        [d, h] => polyguard_oracle::intervals::Separation {
            d: d.clone(),
            h: h.clone(),
        },
        _ => return Err(CompareError::Oracle("sep: two lengths expected".into())),
    };
    let t = raw.lookahead;
    let mut nanos = [0u64; 4];
    let mut relations = Vec::with_capacity(3);
    let mut undefined = false;
    let mut breach_nonempty = None;
    for r in RELATIONS {
        let clock = Instant::now();
        let spans = api::intervals(&case, r, sep);
        nanos[0] += ns(clock);
        let spans = as_engine(spans, engine, t);
        let clock = Instant::now();
        let truth = polyguard_oracle::intervals::intervals_of(&exact, oracle_relation(r), &osep);
        nanos[1] += ns(clock);
        let (class, why, components) = match truth {
            Err(_) => {
                undefined = true;
                (IntervalClass::Undefined, None, 0)
            }
            Ok(truth) => {
                if r == Relation::Breach {
                    breach_nonempty = Some(!truth.is_empty());
                }
                match check_spans(&spans, &truth, t) {
                    None => (IntervalClass::Agree, None, truth.len()),
                    Some((c, why)) => (c, Some(why), truth.len()),
                }
            }
        };
        relations.push(RelationVerdict {
            relation: r,
            class,
            spans,
            components,
            why,
        });
    }
    let clock = Instant::now();
    let exit_engine = match engine {
        IntervalEngine::FlatExit => {
            // the canary: the same case seen from above, its heights dropped
            let mut flat = raw.clone();
            flat.pos.truncate(2);
            flat.vel.truncate(2);
            flat.slab = None;
            let flat = flat
                .to_api()
                .map_err(|e| CompareError::Engine(e.to_string()))?;
            exit_tri(&flat, sep)
        }
        _ => exit_tri(&case, sep),
    };
    nanos[2] = ns(clock);
    let clock = Instant::now();
    let _ = std::hint::black_box(api::detect_time(&case));
    nanos[3] = ns(clock);
    let exit_class = match (breach_nonempty, exit_engine) {
        (Some(true), Tri::No) => IntervalClass::ExitMissed,
        (Some(false), Tri::Yes) => IntervalClass::ExitFalse,
        _ => IntervalClass::Agree,
    };
    let worst = relations
        .iter()
        .map(|v| v.class)
        .chain([exit_class])
        .max()
        .unwrap_or(IntervalClass::Agree);
    let class = if undefined && !worst.is_failure() {
        IntervalClass::Undefined
    } else {
        worst
    };
    Ok(IntervalVerdict {
        class,
        relations,
        exit_truth: breach_nonempty,
        exit_engine,
        lookahead: t,
        nanos,
    })
}

/// The engine's three-valued exit answer (api::detect_exit's kind and answer).
fn exit_tri(case: &api::Case, sep: Separation) -> Tri {
    let d = api::detect_exit(case, sep);
    match (d.detected, d.kind) {
        (_, api::Kind::Conservative) => Tri::Unsure,
        (true, _) => Tri::Yes,
        (false, _) => Tri::No,
    }
}
