//! The verdict on one moving scenario: the engine's certified spans of inside and
//! near_{D,H} (`polyguard_earth::moving::plane::plane_spans`, segment by segment) against
//! the oracle's exact truth (`polyguard_oracle::moving`), with the contract's checks
//! (docs/moving-features.md, "The contract"):
//! - `moving_missed`: a true component (or isolated time) not inside the union of the
//!   spans' hulls [start.lo, end.hi] (G1);
//! - `end_outside`: an end of a true component in no span's start or end enclosure (G3);
//! - `false_certain`: a certain span whose stretch [start.hi, end.lo] is not inside one
//!   true component, or any certain span where the vertical condition is unknown (G2);
//! - `span_malformed`: spans out of order, not finite, outside the segment's domain, or
//!   the engine's segments differ from the exact split at max_gap;
//! - `undefined`: the truth is undefined (a ring not simple on a piece): counted, not a
//!   failure.
//!
//! Every check is an exact comparison of algebraic numbers with the spans' floats.

use std::cmp::Ordering;
use std::ops::Range;
use std::time::Instant;

use polyguard_earth::moving::plane::{PlaneArea, PlaneFix, PlaneRelation, TimeSpan};
use polyguard_oracle::algebraic::RealAlg;
use polyguard_oracle::moving as truth;
use polyguard_oracle::moving::MovingTruth;

use super::gen::MovingScenario;
use crate::intervals::judge::{cmp_f64, within};

/// The class of one relation's spans, or of a whole scenario (its worst).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum MovingClass {
    /// Every check passes.
    Agree,
    /// The truth is undefined (a ring not simple on a piece): not judged.
    Undefined,
    /// Spans out of order, not finite, outside the domain, or segments split wrongly.
    SpanMalformed,
    /// A certain span where the relation does not hold throughout. A failure.
    FalseCertain,
    /// An exact end outside every enclosure. A failure.
    EndOutside,
    /// A true component outside the spans' hulls. The worst failure.
    MovingMissed,
}

impl MovingClass {
    /// Every class, in report order.
    pub const ALL: [MovingClass; 6] = [
        MovingClass::Agree,
        MovingClass::Undefined,
        MovingClass::MovingMissed,
        MovingClass::EndOutside,
        MovingClass::FalseCertain,
        MovingClass::SpanMalformed,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            MovingClass::Agree => "agree",
            MovingClass::Undefined => "undefined",
            MovingClass::MovingMissed => "moving_missed",
            MovingClass::EndOutside => "end_outside",
            MovingClass::FalseCertain => "false_certain",
            MovingClass::SpanMalformed => "span_malformed",
        }
    }

    /// One line on what the class means (the summary's legend).
    pub fn meaning(self) -> &'static str {
        match self {
            MovingClass::Agree => "every span agrees with the exact truth",
            MovingClass::Undefined => "the truth is undefined (a ring not simple): not judged",
            MovingClass::MovingMissed => {
                "a time the relation holds outside every span: THE failure (G1)"
            }
            MovingClass::EndOutside => "an exact end outside every enclosure: a failure (G3)",
            MovingClass::FalseCertain => {
                "a certain span where the relation does not hold throughout: a failure (G2)"
            }
            MovingClass::SpanMalformed => {
                "spans out of order or outside the domain, or segments split wrongly: a failure"
            }
        }
    }

    /// A failure that a campaign must report with a non-zero exit status.
    pub fn is_failure(self) -> bool {
        !matches!(self, MovingClass::Agree | MovingClass::Undefined)
    }
}

/// Which engine a campaign judges: the certified one, or the canary the checks must
/// catch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MovingEngine {
    /// The certified planar engine: the product.
    #[default]
    Certified,
    /// The canary: the relation decided at the fix times only; its spans are the fix
    /// times where it holds, joined between consecutive holding fixes. It misses a cell
    /// that sweeps over the mover between fixes, and a leg cutting a corner.
    FixesOnly,
}

impl MovingEngine {
    /// The command line's name.
    pub fn name(self) -> &'static str {
        match self {
            MovingEngine::Certified => "plane",
            MovingEngine::FixesOnly => "fixes-only",
        }
    }
}

/// The two relations of a scenario, by name.
pub const RELATIONS: [&str; 2] = ["inside", "near"];

/// The verdict on one relation over every segment of a scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct RelationVerdict {
    /// "inside" or "near".
    pub relation: &'static str,
    /// The worst class over the segments.
    pub class: MovingClass,
    /// The engine's spans, all segments in order.
    pub spans: Vec<TimeSpan>,
    /// The exact components, all segments.
    pub components: usize,
    /// Segments judged (the truth defined).
    pub pairs: u64,
    /// Segments whose truth is undefined.
    pub undefined: u64,
    /// Segments where the vertical condition is unknown.
    pub vertical_unknown: u64,
    /// Why the class is a failure, when it is.
    pub why: Option<String>,
}

/// The verdict on one scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingVerdict {
    /// The worst class of the relations.
    pub class: MovingClass,
    /// Inside and near.
    pub relations: Vec<RelationVerdict>,
    /// The trajectory's segments.
    pub segments: usize,
    /// Time in the engine and in the truth (ns).
    pub nanos: [u64; 2],
}

/// The engine's relation of a scenario's: inside, or near within D and H (the planar
/// sandwich's two distances are both D).
fn engine_relation(name: &str, s: &MovingScenario) -> PlaneRelation {
    match name {
        "inside" => PlaneRelation::Inside,
        _ => PlaneRelation::Near {
            d_lo: s.d,
            d_hi: s.d,
            h: s.h,
        },
    }
}

/// The oracle's relation of a scenario's.
fn truth_relation(name: &str, s: &MovingScenario) -> truth::PlaneRelation {
    match name {
        "inside" => truth::PlaneRelation::Inside,
        _ => truth::PlaneRelation::Near { d: s.d, h: s.h },
    }
}

/// The oracle's copy of the fixes.
fn truth_fixes(fixes: &[PlaneFix]) -> Vec<truth::PlaneFix> {
    fixes
        .iter()
        .map(|f| truth::PlaneFix {
            t: f.t,
            x: f.x,
            y: f.y,
            z: f.z,
        })
        .collect()
}

/// The oracle's copy of the area.
fn truth_area(a: &PlaneArea) -> truth::PlaneArea {
    truth::PlaneArea {
        frames: a
            .frames
            .iter()
            .map(|f| truth::PlaneFrame {
                t: f.t,
                parts: f
                    .parts
                    .iter()
                    .map(|p| truth::PlaneRings {
                        outer: p.outer.clone(),
                        holes: p.holes.clone(),
                    })
                    .collect(),
            })
            .collect(),
        is_static: a.is_static,
        floor: a.floor,
        ceiling: a.ceiling,
    }
}

/// The certified engine's spans of one segment.
fn certified_spans(
    fixes: &[PlaneFix],
    area: &PlaneArea,
    relation: PlaneRelation,
) -> Result<Vec<TimeSpan>, String> {
    polyguard_earth::moving::plane::plane_spans(fixes, area, relation).map_err(|e| e.to_string())
}

/// The canary's spans of one segment: the relation decided exactly at each fix time
/// (in the domain), possible spans over the runs of holding fixes.
fn fixes_only_spans(
    fixes: &[truth::PlaneFix],
    area: &truth::PlaneArea,
    relation: truth::PlaneRelation,
) -> Vec<TimeSpan> {
    let mut out: Vec<TimeSpan> = Vec::new();
    let mut run_open = false;
    for f in fixes {
        let holds = truth::plane_truth(std::slice::from_ref(f), area, relation)
            .is_ok_and(|t| !t.components.is_empty());
        match (holds, run_open, out.last_mut()) {
            (true, true, Some(last)) => last.end = [f.t, f.t],
            (true, _, _) => out.push(TimeSpan {
                start: [f.t, f.t],
                end: [f.t, f.t],
                certain: false,
            }),
            (false, _, _) => {}
        }
        run_open = holds;
    }
    out
}

/// What is malformed in a segment's spans (finiteness, order, the domain), if anything.
fn malformed(spans: &[TimeSpan], truth: &MovingTruth) -> Option<String> {
    let Some((lo, hi)) = &truth.domain else {
        return (!spans.is_empty()).then(|| {
            format!(
                "{} spans where the segment and the area never coexist",
                spans.len()
            )
        });
    };
    let mut last = f64::NEG_INFINITY;
    let mut previous: Option<&TimeSpan> = None;
    for (k, s) in spans.iter().enumerate() {
        // two spans may share one cluster: the end of one is the start of the next
        if previous.is_some_and(|p| p.end == s.start) {
            last = s.start[0];
        }
        previous = Some(s);
        let e = [s.start[0], s.start[1], s.end[0], s.end[1]];
        if e.iter().any(|x| !x.is_finite()) {
            return Some(format!("span {k}: an end is not finite"));
        }
        let ordered = last <= e[0]
            && e[0] <= e[1]
            && e[2] <= e[3]
            && e[0] <= e[2]
            && e[1] <= e[3]
            && (!s.certain || e[1] <= e[2]);
        if !ordered {
            return Some(format!(
                "span {k}: [{:e}, {:e}]..[{:e}, {:e}] is out of order",
                e[0], e[1], e[2], e[3]
            ));
        }
        let below = polyguard_oracle::convert::q(e[0]).map_or(true, |q| &q < lo);
        let above = polyguard_oracle::convert::q(e[3]).map_or(true, |q| &q > hi);
        if below || above {
            return Some(format!(
                "span {k}: [{:e}, {:e}] is outside the domain [{}, {}]",
                e[0], e[3], lo, hi
            ));
        }
        last = e[3];
    }
    None
}

/// The spans' hulls [start.lo, end.hi], merged where they touch.
fn hulls(spans: &[TimeSpan]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for s in spans {
        match out.last_mut() {
            Some(h) if s.start[0] <= h.1 => h.1 = h.1.max(s.end[1]),
            _ => out.push((s.start[0], s.end[1])),
        }
    }
    out
}

/// The decimal text of an exact time (17 digits).
fn text(x: &RealAlg) -> String {
    x.to_decimal_string(17)
}

/// The contract's checks on one segment (see the module doc): `None` when they pass,
/// else the class and why.
pub fn check_segment(spans: &[TimeSpan], truth: &MovingTruth) -> Option<(MovingClass, String)> {
    if let Some(why) = malformed(spans, truth) {
        return Some((MovingClass::SpanMalformed, why));
    }
    let hull = hulls(spans);
    for (k, (a, b)) in truth.components.iter().enumerate() {
        let covered = hull.iter().any(|&(lo, hi)| {
            cmp_f64(a, lo) != Ordering::Less && cmp_f64(b, hi) != Ordering::Greater
        });
        if !covered {
            return Some((
                MovingClass::MovingMissed,
                format!(
                    "component {k} [{}, {}] is outside every span",
                    text(a),
                    text(b)
                ),
            ));
        }
    }
    let enclosures: Vec<[f64; 2]> = spans.iter().flat_map(|s| [s.start, s.end]).collect();
    for (k, (a, b)) in truth.components.iter().enumerate() {
        for (which, x) in [("start", a), ("end", b)] {
            if !enclosures.iter().any(|e| within(x, e[0], e[1])) {
                return Some((
                    MovingClass::EndOutside,
                    format!(
                        "the {which} of component {k}, {}, is in no enclosure",
                        text(x)
                    ),
                ));
            }
        }
    }
    for (k, s) in spans.iter().enumerate().filter(|(_, s)| s.certain) {
        if truth.vertical_unknown {
            return Some((
                MovingClass::FalseCertain,
                format!("span {k} is certain though the mover's height is unknown"),
            ));
        }
        let held = truth.components.iter().any(|(a, b)| {
            cmp_f64(a, s.start[1]) != Ordering::Greater && cmp_f64(b, s.end[0]) != Ordering::Less
        });
        if !held {
            return Some((
                MovingClass::FalseCertain,
                format!(
                    "span {k} is certain on [{:e}, {:e}], which no component covers",
                    s.start[1], s.end[0]
                ),
            ));
        }
    }
    None
}

/// Time since `clock` in ns.
fn ns(clock: Instant) -> u64 {
    u64::try_from(clock.elapsed().as_nanos()).unwrap_or(u64::MAX)
}

/// The verdict on one relation over the segments.
fn judge_relation(
    s: &MovingScenario,
    name: &'static str,
    segments: &[Range<usize>],
    engine: MovingEngine,
    nanos: &mut [u64; 2],
) -> Result<RelationVerdict, String> {
    let area = truth_area(&s.area);
    let all = truth_fixes(&s.fixes);
    let mut v = RelationVerdict {
        relation: name,
        class: MovingClass::Agree,
        spans: Vec::new(),
        components: 0,
        pairs: 0,
        undefined: 0,
        vertical_unknown: 0,
        why: None,
    };
    for seg in segments {
        let clock = Instant::now();
        let spans = match engine {
            MovingEngine::Certified => {
                certified_spans(&s.fixes[seg.clone()], &s.area, engine_relation(name, s))?
            }
            MovingEngine::FixesOnly => {
                fixes_only_spans(&all[seg.clone()], &area, truth_relation(name, s))
            }
        };
        nanos[0] += ns(clock);
        let clock = Instant::now();
        let exact = truth::plane_truth(&all[seg.clone()], &area, truth_relation(name, s));
        nanos[1] += ns(clock);
        let class = match exact {
            Err(_) => {
                v.undefined += 1;
                (MovingClass::Undefined, None)
            }
            Ok(t) => {
                v.pairs += 1;
                v.components += t.components.len();
                v.vertical_unknown += u64::from(t.vertical_unknown);
                match check_segment(&spans, &t) {
                    None => (MovingClass::Agree, None),
                    Some((c, why)) => (c, Some(format!("segment {seg:?}: {why}"))),
                }
            }
        };
        if class.0 > v.class {
            v.class = class.0;
            v.why = class.1;
        }
        v.spans.extend(spans);
    }
    Ok(v)
}

/// The verdict on one scenario, judged as `engine` answers it (`Err`: the engine
/// refused the scenario, which the generator never draws).
pub fn judge(s: &MovingScenario, engine: MovingEngine) -> Result<MovingVerdict, String> {
    let segments = truth::split_segments(&truth_fixes(&s.fixes), s.max_gap);
    let engine_segments = polyguard_earth::moving::plane::split_segments(&s.fixes, s.max_gap);
    let mut nanos = [0u64; 2];
    let mut relations = Vec::with_capacity(RELATIONS.len());
    for name in RELATIONS {
        relations.push(judge_relation(s, name, &segments, engine, &mut nanos)?);
    }
    if engine_segments != segments {
        if let Some(r) = relations.first_mut() {
            r.class = MovingClass::SpanMalformed;
            r.why = Some(format!(
                "the engine's segments {engine_segments:?} differ from the exact split {segments:?}"
            ));
        }
    }
    let class = relations
        .iter()
        .map(|r| r.class)
        .max()
        .unwrap_or(MovingClass::Agree);
    Ok(MovingVerdict {
        class,
        relations,
        segments: segments.len(),
        nanos,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::SplitMix;
    use crate::moving::gen::{moving_scenario, scenario_of, Kind};

    /// The exact truth rounded outward to floats: spans every check must accept.
    fn outward(t: &MovingTruth) -> Vec<TimeSpan> {
        t.components
            .iter()
            .map(|(a, b)| {
                let (a0, a1) = a.to_f64_bounds();
                let (b0, b1) = b.to_f64_bounds();
                TimeSpan {
                    start: [a0, a1],
                    end: [b0, b1],
                    certain: !t.vertical_unknown && a1 <= b0,
                }
            })
            .collect()
    }

    #[test]
    fn moving_the_exact_truth_rounded_outward_passes_every_check() {
        let mut judged = 0;
        for seed in 0..60u64 {
            let s = moving_scenario(&mut SplitMix(seed));
            let fixes = truth_fixes(&s.fixes);
            let area = truth_area(&s.area);
            for seg in truth::split_segments(&fixes, s.max_gap) {
                for name in RELATIONS {
                    let Ok(t) =
                        truth::plane_truth(&fixes[seg.clone()], &area, truth_relation(name, &s))
                    else {
                        continue;
                    };
                    judged += 1;
                    assert_eq!(check_segment(&outward(&t), &t), None, "seed {seed} {name}");
                }
            }
        }
        assert!(judged > 60);
    }

    #[test]
    fn moving_the_checks_catch_a_dropped_span_a_moved_end_and_a_false_certainty() {
        for seed in 0..200u64 {
            let s = scenario_of(&mut SplitMix(seed), Kind::Exact);
            let fixes = truth_fixes(&s.fixes);
            let area = truth_area(&s.area);
            let Ok(t) = truth::plane_truth(&fixes, &area, truth::PlaneRelation::Inside) else {
                continue;
            };
            let Some((a, b)) = t.components.first() else {
                continue;
            };
            let good = outward(&t);
            let mut dropped = good.clone();
            dropped.remove(0);
            assert_eq!(
                check_segment(&dropped, &t).map(|c| c.0),
                Some(MovingClass::MovingMissed)
            );
            if a < b {
                let mut moved = good.clone();
                moved[0].end = [moved[0].end[0] - 0.5, moved[0].end[1] - 0.5];
                moved[0].start = [moved[0].start[0] - 0.5, moved[0].start[1] - 0.5];
                let c = check_segment(&moved, &t).map(|c| c.0);
                assert!(
                    matches!(
                        c,
                        Some(
                            MovingClass::MovingMissed
                                | MovingClass::EndOutside
                                | MovingClass::SpanMalformed
                        )
                    ),
                    "{seed}: {c:?}"
                );
                let mut widened = good.clone();
                widened[0].end = [moved[0].end[0] + 1.0, moved[0].end[1] + 1.0];
                widened[0].certain = true;
                let c = check_segment(&widened, &t).map(|c| c.0);
                assert!(c.is_some(), "{seed}");
            }
            return;
        }
        panic!("no exact scenario with an inside component");
    }

    #[test]
    fn moving_the_fixes_only_canary_is_caught() {
        let mut caught = 0;
        for seed in 0..40u64 {
            let s = scenario_of(&mut SplitMix(seed), Kind::Sweep);
            let v = judge_canary(&s);
            caught += u64::from(v.is_failure());
            let s = scenario_of(&mut SplitMix(seed), Kind::CornerCut);
            caught += u64::from(judge_canary(&s).is_failure());
        }
        assert!(caught >= 40, "the canary was caught {caught} times in 80");
    }

    /// The canary's class on a scenario.
    fn judge_canary(s: &MovingScenario) -> MovingClass {
        let segments = truth::split_segments(&truth_fixes(&s.fixes), s.max_gap);
        let mut nanos = [0; 2];
        RELATIONS
            .iter()
            .map(|name| {
                judge_relation(s, name, &segments, MovingEngine::FixesOnly, &mut nanos)
                    .map_or(MovingClass::Agree, |v| v.class)
            })
            .max()
            .unwrap_or(MovingClass::Agree)
    }
}

#[cfg(test)]
mod engine_tests {
    use super::*;
    use crate::gen::SplitMix;
    use crate::moving::gen::moving_scenario;

    /// The failing classes of `engine` on the scenarios of seeds 0..n.
    fn failures(engine: MovingEngine, n: u64) -> Vec<(u64, MovingClass)> {
        (0..n)
            .filter_map(|seed| {
                let s = moving_scenario(&mut SplitMix(seed));
                match judge(&s, engine) {
                    Ok(v) if v.class.is_failure() => Some((seed, v.class)),
                    Ok(_) => None,
                    Err(e) => panic!("seed {seed}: the engine refused a scenario: {e}"),
                }
            })
            .collect()
    }

    #[test]
    fn moving_the_canary_is_caught_where_the_certified_engine_passes() {
        let canary = failures(MovingEngine::FixesOnly, 80);
        assert!(
            canary.iter().any(|(_, c)| *c == MovingClass::MovingMissed),
            "the fixes-only canary was not caught: {canary:?}"
        );
        assert_eq!(failures(MovingEngine::Certified, 80), Vec::new());
    }
}
