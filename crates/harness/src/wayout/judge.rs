//! The verdict on one case of the way-out hunt (`polyguard assure --paper wayout`):
//! the engine's answer against the oracle's exact truth, through the checks of
//! [`super::bands`], [`super::recovery`] and [`super::offset`].
//!
//! - Bands (the engine's `bands` contract, paper A §II–§III's motion): values drawn in
//!   each Clear band must be exactly free of conflict (else `wrong_clear`), values drawn
//!   in each Conflict band exactly in conflict (else `wrong_conflict`); the bands must
//!   tile the range in order (else `bands_malformed`). The values: each decided band's
//!   ends and midpoint, the courses aimed at each polygon's centre (at 0, T/2 and T)
//!   and vertices, the course 0 (the tangency's), and random values, at most
//!   [`MAX_DRAWS`] per case, aimed values first.
//! - Recovery (the `recovery` contract, §II.G's distance): the point exactly meets its
//!   condition (`recovery_breaks_condition`), min_lo ≤ m ≤ |x − s| ≤ dist_hi
//!   (`recovery_min_outside`), "clear" only when s meets it (a certified flag:
//!   `recovery_clear_wrong`), impossible exactly when nothing meets it
//!   (`recovery_impossible_wrong`, `recovery_point_where_none`).
//! - Offsets (the `offset` contract, §II's polygon): the oracle's exact verdict on the
//!   rings (`offset_rings_bad`), on P ⊕ disc(D) ⊆ Q (`offset_misses_buffer`) and on
//!   ∂Q within D(1 + ε) (`offset_too_far`), and an exact sampling of a grid for what
//!   the boundary cannot show; insets alike (`inset_outside_core`, `inset_misses_core`).
//!
//! A refusal the contract allows (an offset it cannot certify, a band input it
//! rejects) is `refused`, a case whose exact truth is undefined (a warping polygon
//! not simple) `undefined`; neither is a failure. A recovery gap above the engine's
//! stated tolerance (`gap_wide`) and an unknown total above the request
//! (`unknown_over`) are counted, not failures: the contracts allow both on
//! near-degenerate inputs.

use std::time::Instant;

use polyguard::bands::{course_bands, speed_bands, vertical_speed_bands, BandKind, Bands};
use polyguard::offset::{inset, inset_at, offset, offset_at, Offset, OffsetError, Region};
use polyguard::recovery::Recovery;
use polyguard::Vect2;
use polyguard_oracle::offset::Side as OffsetSide;
use serde::{Deserialize, Serialize};

use super::bands::{sampled_course_bands, BandCase, Param};
use super::gen::{OffsetCase, WayoutCase};
use super::offset::{problem, problem_at, regions_of, sample};
use super::recovery::{check_answer, engine as recovery_engine, margin, Query, Verdict};
use crate::canary_offset::bisector_expansion;
use crate::hunt::{HuntClass, Judged};

/// The most values a band case draws and decides exactly.
pub const MAX_DRAWS: usize = 24;

/// The sampling step of the `sampled-bands` canary (radians).
pub const CANARY_STEP: f64 = 10.0 * core::f64::consts::PI / 180.0;

/// The grid of the offsets' exact sampling (n × n points).
pub const SAMPLE_GRID: usize = 6;

/// The class of a case, or of one fault in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum WayoutClass {
    /// Every check passes.
    Agree,
    /// The exact truth is undefined somewhere (a polygon not simple): not judged there.
    Undefined,
    /// The engine refused as its contract allows (uncertified offset, rejected input).
    Refused,
    /// A recovery gap dist_hi − min_lo above the engine's stated tolerance.
    GapWide,
    /// Bands whose unknown total stayed above the request.
    UnknownOver,
    /// A value in a Clear band in conflict.
    WrongClear,
    /// A value in a Conflict band free of conflict.
    WrongConflict,
    /// Bands not tiling their range in order.
    BandsMalformed,
    /// A recovery point that does not meet its condition.
    RecoveryBreaksCondition,
    /// The exact minimum outside [min_lo, dist_hi], or |x − s| above dist_hi.
    RecoveryMinOutside,
    /// "s is clear" said where s does not meet the condition.
    RecoveryClearWrong,
    /// "Impossible" where a point meets the condition.
    RecoveryImpossibleWrong,
    /// A point where nothing meets the condition.
    RecoveryPointWhereNone,
    /// Offset rings not simple, oriented, nested and disjoint.
    OffsetRingsBad,
    /// A point of P ⊕ disc(D) outside the offset.
    OffsetMissesBuffer,
    /// A point of the offset farther than D(1 + ε) from P.
    OffsetTooFar,
    /// A point of the inset nearer than D to ∂P, or outside P.
    InsetOutsideCore,
    /// A point D(1 + ε) deep in P outside the inset.
    InsetMissesCore,
}

impl HuntClass for WayoutClass {
    const ALL: &'static [WayoutClass] = &[
        WayoutClass::Agree,
        WayoutClass::Undefined,
        WayoutClass::Refused,
        WayoutClass::GapWide,
        WayoutClass::UnknownOver,
        WayoutClass::WrongClear,
        WayoutClass::WrongConflict,
        WayoutClass::BandsMalformed,
        WayoutClass::RecoveryBreaksCondition,
        WayoutClass::RecoveryMinOutside,
        WayoutClass::RecoveryClearWrong,
        WayoutClass::RecoveryImpossibleWrong,
        WayoutClass::RecoveryPointWhereNone,
        WayoutClass::OffsetRingsBad,
        WayoutClass::OffsetMissesBuffer,
        WayoutClass::OffsetTooFar,
        WayoutClass::InsetOutsideCore,
        WayoutClass::InsetMissesCore,
    ];

    fn name(self) -> &'static str {
        match self {
            WayoutClass::Agree => "agree",
            WayoutClass::Undefined => "undefined",
            WayoutClass::Refused => "refused",
            WayoutClass::GapWide => "gap_wide",
            WayoutClass::UnknownOver => "unknown_over",
            WayoutClass::WrongClear => "wrong_clear",
            WayoutClass::WrongConflict => "wrong_conflict",
            WayoutClass::BandsMalformed => "bands_malformed",
            WayoutClass::RecoveryBreaksCondition => "recovery_breaks_condition",
            WayoutClass::RecoveryMinOutside => "recovery_min_outside",
            WayoutClass::RecoveryClearWrong => "recovery_clear_wrong",
            WayoutClass::RecoveryImpossibleWrong => "recovery_impossible_wrong",
            WayoutClass::RecoveryPointWhereNone => "recovery_point_where_none",
            WayoutClass::OffsetRingsBad => "offset_rings_bad",
            WayoutClass::OffsetMissesBuffer => "offset_misses_buffer",
            WayoutClass::OffsetTooFar => "offset_too_far",
            WayoutClass::InsetOutsideCore => "inset_outside_core",
            WayoutClass::InsetMissesCore => "inset_misses_core",
        }
    }

    fn meaning(self) -> &'static str {
        match self {
            WayoutClass::Agree => "every check agrees with the exact truth",
            WayoutClass::Undefined => "the exact truth is undefined (a polygon not simple)",
            WayoutClass::Refused => "the engine refused as its contract allows",
            WayoutClass::GapWide => "recovery dist_hi − min_lo above the stated tolerance",
            WayoutClass::UnknownOver => "the unknown total stayed above the request",
            WayoutClass::WrongClear => "a course in a Clear band loses separation: THE failure",
            WayoutClass::WrongConflict => "a value in a Conflict band keeps separation",
            WayoutClass::BandsMalformed => "bands not tiling their range in order",
            WayoutClass::RecoveryBreaksCondition => "a recovery point breaks its condition",
            WayoutClass::RecoveryMinOutside => "the exact minimum outside [min_lo, dist_hi]",
            WayoutClass::RecoveryClearWrong => "\"s is clear\" where s is not",
            WayoutClass::RecoveryImpossibleWrong => "\"impossible\" where a point is feasible",
            WayoutClass::RecoveryPointWhereNone => "a point where none is feasible",
            WayoutClass::OffsetRingsBad => "rings not simple, oriented, nested, disjoint",
            WayoutClass::OffsetMissesBuffer => "a point within D of P outside the offset",
            WayoutClass::OffsetTooFar => "a point of the offset beyond D(1 + ε) of P",
            WayoutClass::InsetOutsideCore => "a point of the inset nearer than D to ∂P",
            WayoutClass::InsetMissesCore => "a point D(1 + ε) deep outside the inset",
        }
    }

    fn is_failure(self) -> bool {
        !matches!(
            self,
            WayoutClass::Agree
                | WayoutClass::Undefined
                | WayoutClass::Refused
                | WayoutClass::GapWide
                | WayoutClass::UnknownOver
        )
    }
}

/// Which engine the hunt judges: the certified one, or a canary the checks must catch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WayoutEngine {
    /// The certified engine: the product.
    #[default]
    Certified,
    /// Course bands sampled every [`CANARY_STEP`] and painted between samples without
    /// the certificate's margin (must give `wrong_clear`).
    SampledBands,
    /// Offsets by a PolyCARP-style bisector expansion (must give
    /// `offset_misses_buffer`).
    BisectorOffset,
}

impl WayoutEngine {
    /// The name in reports.
    pub fn name(self) -> &'static str {
        match self {
            WayoutEngine::Certified => "f64",
            WayoutEngine::SampledBands => "sampled-bands",
            WayoutEngine::BisectorOffset => "bisector-offset",
        }
    }
}

/// Nanoseconds since `t0`.
fn ns(t0: Instant) -> u64 {
    t0.elapsed().as_nanos() as u64
}

/// Judges one case with `engine`.
pub fn judge(case: &WayoutCase, engine: WayoutEngine) -> Judged<WayoutClass> {
    let mut j = match case {
        WayoutCase::Bands {
            case,
            param,
            range,
            unknown_max,
        } => judge_bands(case, *param, *range, *unknown_max, engine),
        WayoutCase::Recovery(q) => judge_recovery(q),
        WayoutCase::Offset(o) => judge_offset(o, engine),
    };
    j.classes.sort();
    j.classes.dedup();
    if j.classes.is_empty() {
        j.classes.push(WayoutClass::Agree);
    }
    j
}

/// The engine's bands of the case (the canary's for courses under `SampledBands`).
fn bands_of(
    case: &BandCase,
    param: Param,
    range: (f64, f64),
    unknown_max: f64,
    engine: WayoutEngine,
) -> Option<Bands> {
    case.with_traffic(|t| match (param, engine) {
        (Param::Course { speed }, WayoutEngine::SampledBands) => {
            Some(sampled_course_bands(t, speed, CANARY_STEP))
        }
        (Param::Course { speed }, _) => course_bands(t, speed, unknown_max).ok(),
        (Param::Speed { course }, _) => speed_bands(t, course, range.0, range.1, unknown_max).ok(),
        (Param::Vertical { v }, _) => {
            vertical_speed_bands(t, v, range.0, range.1, unknown_max).ok()
        }
    })
}

/// The bands tile [range.0, end] in order, where end is range.1 (fl(2π) for courses).
fn well_tiled(bands: &Bands, range: (f64, f64)) -> bool {
    let (Some(first), Some(last)) = (bands.bands.first(), bands.bands.last()) else {
        return false;
    };
    first.lo == range.0
        && last.hi == range.1
        && bands.bands.iter().all(|b| b.lo <= b.hi)
        && bands.bands.windows(2).all(|w| w[0].hi == w[1].lo)
}

/// The course from the origin s toward `x`: clockwise from +y, in [0, 2π).
fn bearing(s: Vect2, x: Vect2) -> f64 {
    let a = (x.x - s.x).atan2(x.y - s.y);
    if a < 0.0 {
        a + core::f64::consts::TAU
    } else {
        a
    }
}

/// The values a band case decides exactly (module doc), aimed values first.
fn draws(case: &BandCase, param: Param, range: (f64, f64), bands: &Bands) -> Vec<f64> {
    let mut xs = Vec::new();
    if let Param::Course { .. } = param {
        xs.push(0.0);
        for o in &case.polygons {
            let n = o.p.len() as f64;
            for tau in [0.0, 0.5 * case.t, case.t] {
                let c =
                    o.p.iter()
                        .zip(&o.vels)
                        .fold(Vect2::ZERO, |a, (p, v)| a + p.at(*v, tau))
                        .scale(1.0 / n);
                xs.push(bearing(case.s, c));
            }
            xs.extend(o.p.iter().map(|&p| bearing(case.s, p)));
        }
    }
    // random values from a generator seeded by the case's own numbers
    let mut seed = case.t.to_bits() ^ case.sep.d.to_bits().rotate_left(17);
    for k in 0..4u64 {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407 + k);
        let u = (seed >> 11) as f64 / (1u64 << 53) as f64;
        xs.push(range.0 + (range.1 - range.0) * u);
    }
    for b in bands.bands.iter().filter(|b| b.kind != BandKind::Unknown) {
        xs.extend([b.lo, b.hi, b.lo + 0.5 * (b.hi - b.lo)]);
    }
    xs.retain(|x| {
        bands
            .bands
            .iter()
            .any(|b| b.kind != BandKind::Unknown && b.lo <= *x && *x <= b.hi)
    });
    let mut out: Vec<f64> = Vec::with_capacity(MAX_DRAWS);
    for x in xs {
        if out.len() == MAX_DRAWS {
            break;
        }
        if !out.contains(&x) {
            out.push(x);
        }
    }
    out
}

/// Bands: tiling, then each drawn value's exact truth against every decided band
/// holding it. Severity: the depth of a wrong value inside its band, over the range.
fn judge_bands(
    case: &BandCase,
    param: Param,
    range: (f64, f64),
    unknown_max: f64,
    engine: WayoutEngine,
) -> Judged<WayoutClass> {
    let t0 = Instant::now();
    let got = bands_of(case, param, range, unknown_max, engine);
    let engine_ns = ns(t0);
    let t1 = Instant::now();
    let mut j = Judged {
        classes: Vec::new(),
        severity: 0.0,
        nanos: [engine_ns, 0],
    };
    let Some(bands) = got else {
        j.classes.push(WayoutClass::Refused);
        return j;
    };
    let end = match param {
        Param::Course { .. } => core::f64::consts::TAU,
        _ => range.1,
    };
    if !well_tiled(&bands, (range.0, end)) {
        j.classes.push(WayoutClass::BandsMalformed);
    }
    if !bands.met {
        j.classes.push(WayoutClass::UnknownOver);
    }
    let width = (range.1 - range.0).max(f64::MIN_POSITIVE);
    for x in draws(case, param, range, &bands) {
        let truth = case.truth(param, x);
        for b in &bands.bands {
            if b.kind == BandKind::Unknown || x < b.lo || x > b.hi {
                continue;
            }
            let want = b.kind == BandKind::Conflict;
            match truth {
                None => j.classes.push(WayoutClass::Undefined),
                Some(c) if c == want => {}
                Some(_) => {
                    j.classes.push(if want {
                        WayoutClass::WrongConflict
                    } else {
                        WayoutClass::WrongClear
                    });
                    let depth = (x - b.lo).min(b.hi - x) / width;
                    j.severity = j.severity.max(depth);
                }
            }
        }
    }
    j.nanos[1] = ns(t1);
    j
}

/// Recovery: the engine's answer, then the oracle's verdict. Severity: how far (in
/// floats, over D) a point breaking its condition falls short.
fn judge_recovery(q: &Query) -> Judged<WayoutClass> {
    let t0 = Instant::now();
    let got = recovery_engine(q);
    let engine_ns = ns(t0);
    let t1 = Instant::now();
    let verdict = check_answer(q, got);
    let mut classes = Vec::new();
    let mut severity = 0.0;
    match verdict {
        Verdict::Point {
            condition,
            min_lo_below,
            dist_hi_above,
            gap_within,
            clear_agrees,
        } => {
            if !condition {
                classes.push(WayoutClass::RecoveryBreaksCondition);
                if let Ok(Recovery::Point { x, .. }) = got {
                    let at_t = Query {
                        p: q.p
                            .iter()
                            .enumerate()
                            .map(|(i, p)| q.vels.get(i).map_or(*p, |v| p.at(*v, q.t)))
                            .collect(),
                        vels: Vec::new(),
                        ..q.clone()
                    };
                    severity = (-margin(&at_t, x) / q.d.max(f64::MIN_POSITIVE)).max(0.0);
                }
            }
            if !(min_lo_below && dist_hi_above) {
                classes.push(WayoutClass::RecoveryMinOutside);
            }
            if !clear_agrees {
                classes.push(WayoutClass::RecoveryClearWrong);
            }
            if !gap_within {
                classes.push(WayoutClass::GapWide);
            }
        }
        Verdict::ImpossibleAgreed => {}
        Verdict::ImpossibleWrong => classes.push(WayoutClass::RecoveryImpossibleWrong),
        Verdict::PointWhereNone => classes.push(WayoutClass::RecoveryPointWhereNone),
        Verdict::Refused(_) => classes.push(WayoutClass::Refused),
    }
    Judged {
        classes,
        severity,
        nanos: [engine_ns, ns(t1)],
    }
}

/// The polygon of an offset case at its time, in f64 (for the canary, which has no
/// `_at` form).
fn p_at(o: &OffsetCase) -> Vec<Vect2> {
    o.p.iter()
        .enumerate()
        .map(|(i, p)| o.vels.get(i).map_or(*p, |v| p.at(*v, o.t)))
        .collect()
}

/// The engine's offset or inset of the case (the bisector expansion for offsets under
/// `BisectorOffset`, with PolyCARP's BUFF = D/100).
fn offset_of(o: &OffsetCase, engine: WayoutEngine) -> Result<Offset, OffsetError> {
    let moving = !o.vels.is_empty();
    match (o.side, engine) {
        (OffsetSide::Out, WayoutEngine::BisectorOffset) => Ok(Offset {
            regions: vec![Region {
                outer: bisector_expansion(&p_at(o), o.d / 100.0, o.d),
                holes: Vec::new(),
            }],
        }),
        (OffsetSide::Out, _) if moving => offset_at(&o.p, &o.vels, o.t, o.d, o.eps),
        (OffsetSide::Out, _) => offset(&o.p, o.d, o.eps),
        (OffsetSide::In, _) if moving => inset_at(&o.p, &o.vels, o.t, o.d, o.eps),
        (OffsetSide::In, _) => inset(&o.p, o.d, o.eps),
    }
}

/// Offsets and insets: the oracle's exact verdict on the rings, then the exact
/// sampling of an n × n grid.
fn judge_offset(o: &OffsetCase, engine: WayoutEngine) -> Judged<WayoutClass> {
    let t0 = Instant::now();
    let got = offset_of(o, engine);
    let engine_ns = ns(t0);
    let t1 = Instant::now();
    let mut classes = Vec::new();
    let buffer = if o.vels.is_empty() {
        problem(&o.p, o.d, o.eps, o.side)
    } else {
        problem_at(&o.p, &o.vels, o.t, o.d, o.eps, o.side)
    };
    match (got, buffer) {
        (Err(_), _) => classes.push(WayoutClass::Refused),
        (Ok(_), Err(_)) => classes.push(WayoutClass::Undefined),
        (Ok(result), Ok(buffer)) => {
            let out = o.side == OffsetSide::Out;
            match buffer.check(&regions_of(&result)) {
                Err(_) => classes.push(WayoutClass::OffsetRingsBad),
                Ok(v) => {
                    if !v.rings {
                        classes.push(WayoutClass::OffsetRingsBad);
                    }
                    if !v.clear {
                        classes.push(if out {
                            WayoutClass::OffsetMissesBuffer
                        } else {
                            WayoutClass::InsetOutsideCore
                        });
                    }
                    if !v.close {
                        classes.push(if out {
                            WayoutClass::OffsetTooFar
                        } else {
                            WayoutClass::InsetMissesCore
                        });
                    }
                    if v.rings {
                        classes.extend(sampled(&buffer, &result, out));
                    }
                }
            }
        }
    }
    Judged {
        classes,
        severity: 0.0,
        nanos: [engine_ns, ns(t1)],
    }
}

/// The class of the first grid point where the result and the true sets disagree.
fn sampled(
    buffer: &polyguard_oracle::offset::Buffer,
    result: &Offset,
    out: bool,
) -> Option<WayoutClass> {
    let x = sample(buffer, result, SAMPLE_GRID).ok()??;
    let xq = polyguard_oracle::offset::exact_point(x).ok()?;
    let inside = polyguard_oracle::offset::locate(&regions_of(result), &xq).ok()?;
    Some(match (out, inside) {
        (true, false) => WayoutClass::OffsetMissesBuffer,
        (true, true) => WayoutClass::OffsetTooFar,
        (false, true) => WayoutClass::InsetOutsideCore,
        (false, false) => WayoutClass::InsetMissesCore,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::SplitMix;
    use crate::wayout::gen::{band_case, offset_case, recovery_case, Drawn};

    /// The certified engine passes every check on a few cases of each kind.
    #[test]
    fn the_certified_engine_passes() {
        let mut src = SplitMix(7);
        let kinds: [fn(&mut SplitMix) -> Drawn; 3] = [band_case, recovery_case, offset_case];
        for k in 0..9 {
            let d = kinds[k % 3](&mut src);
            let j = judge(&d.case, WayoutEngine::Certified);
            assert!(
                !j.failed(),
                "{} {:?}: {}",
                d.mode,
                j.classes,
                d.case.to_json()
            );
        }
    }

    /// The sampled-bands canary paints a thin conflict Clear: caught as `wrong_clear`
    /// on some of a few band cases.
    #[test]
    fn the_sampled_bands_canary_is_caught() {
        let mut src = SplitMix(3);
        let caught = (0..10)
            .filter(|_| {
                let d = band_case(&mut src);
                let j = judge(&d.case, WayoutEngine::SampledBands);
                j.classes.contains(&WayoutClass::WrongClear)
            })
            .count();
        assert!(caught > 0);
    }

    /// The bisector-offset canary misses buffer on some of a few offset cases.
    #[test]
    fn the_bisector_offset_canary_is_caught() {
        let mut src = SplitMix(3);
        let caught = (0..6)
            .filter(|_| {
                let d = offset_case(&mut src);
                let j = judge(&d.case, WayoutEngine::BisectorOffset);
                j.classes.contains(&WayoutClass::OffsetMissesBuffer)
            })
            .count();
        assert!(caught > 0);
    }
}
