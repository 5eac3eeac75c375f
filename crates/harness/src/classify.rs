//! The verdict on one case: the f64 engine against paper A in exact arithmetic and the
//! exact ground truth.

use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

use crate::case::RawCase;
use polyguard::api;
use polyguard::detect::Method;

/// The oracle's number type: GMP rationals with the `rug` feature, else num-rational.
#[cfg(feature = "rug")]
pub type Exact = polyguard_oracle::field::R;
/// The oracle's number type: GMP rationals with the `rug` feature, else num-rational.
#[cfg(not(feature = "rug"))]
pub type Exact = polyguard_oracle::Q;

/// How far BUFF and F are widened to tell a false alarm "in the band" from one "far"
/// outside it: an engine alarm that paper A's own exact algorithm would not raise even
/// with 4× the slack (and [`ROUNDING_BAND`]) is far from anything the paper flags by
/// design.
pub const WIDE_BAND: f64 = 4.0;

/// The rounding allowance of the wide band, relative to the scene's largest magnitude
/// ([`rounding_allowance`]): 2⁻⁴⁰, about 8,000 ulps. The f64 engine cannot tell
/// distances apart below a few ulps of the coordinates it is given (at an offset of
/// 10⁹, an ulp is 1.2·10⁻⁷, whatever BUFF is), and resolves what it cannot decide
/// towards detection; an alarm within this allowance of paper A's thresholds is the
/// price of f64 inputs, one beyond it is a bug.
pub const ROUNDING_BAND: f64 = 1.0 / (1u64 << 40) as f64;

/// [`ROUNDING_BAND`] times the largest magnitude of the scene over the lookahead: the
/// positions of the point and the vertices at 0 and their displacements over T (and
/// in 3D the heights of the point and the slab's ends, and their displacements).
pub fn rounding_allowance(raw: &RawCase) -> f64 {
    let t = raw.lookahead.abs();
    let mut m = 0f64;
    let mut see = |x: f64| m = m.max(x.abs());
    for (&p, &v) in raw.pos.iter().zip(&raw.vel) {
        see(p);
        see(v * t);
    }
    for (p, v) in raw.vertices.iter().zip(&raw.velocities) {
        for a in 0..2 {
            see(p[a]);
            see(v[a] * t);
        }
    }
    if let Some([bottom, top, vsp]) = raw.slab {
        see(bottom);
        see(top);
        see(vsp * t);
    }
    ROUNDING_BAND * m
}

/// The wide band's case: BUFF and F times [`WIDE_BAND`], BUFF plus the
/// [`rounding_allowance`], and in 3D the slab grown by the allowance at both ends.
pub fn wide_case(raw: &RawCase) -> RawCase {
    let r = rounding_allowance(raw);
    let mut wide = raw.widened(WIDE_BAND);
    wide.buff += r;
    if let Some(slab) = wide.slab.as_mut() {
        slab[0] -= r;
        slab[1] += r;
    }
    wide
}

/// The class of a compared case: what the engine, paper A in exact arithmetic and the
/// truth say together.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Class {
    /// Engine, paper-exact and truth tell the same story.
    Agree,
    /// Engine ≠ paper-exact, and neither a miss nor a false alarm (e.g. the engine
    /// does not raise a band alarm that the exact paper raises).
    FloatDivergence,
    /// Truth: the point enters; the engine says no. The one unforgivable bug.
    MissedDetection,
    /// Engine yes, truth no, within the BUFF/F band (paper-exact with 4× slack and the
    /// rounding allowance agrees).
    FalseAlarmInBand,
    /// Engine yes, truth no, and not even paper-exact with 4× slack and the rounding
    /// allowance ([`wide_case`]) flags it: a bug.
    FalseAlarmFar,
    /// Engine yes taken on a comparison it could not decide in f64 (`kind:
    /// conservative`), truth no, and beyond the wide band: the price of deciding in f64
    /// where the engine's rounding bound is wider than the band (near-tangent quadratics
    /// at large magnitudes). Safe, reported and kept, not a failure.
    ConservativeFar,
    /// Truth enters, paper-exact says no: a finding about the paper itself.
    PaperGap,
    /// The truth is undefined (the polygon stops being simple): not judged.
    Undefined,
    /// The f64 time of first entry (`api::detect_time`) contradicts the truth: the exact
    /// entry time lies outside the enclosure, a certified "never" for a point that enters,
    /// or a certified entry for one that does not. A failure.
    TimeOutside,
}

impl Class {
    /// Every class, in report order.
    pub const ALL: [Class; 9] = [
        Class::Agree,
        Class::FloatDivergence,
        Class::MissedDetection,
        Class::FalseAlarmInBand,
        Class::FalseAlarmFar,
        Class::ConservativeFar,
        Class::PaperGap,
        Class::Undefined,
        Class::TimeOutside,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Class::Agree => "agree",
            Class::FloatDivergence => "float_divergence",
            Class::MissedDetection => "missed_detection",
            Class::FalseAlarmInBand => "false_alarm_in_band",
            Class::FalseAlarmFar => "false_alarm_far",
            Class::ConservativeFar => "conservative_far",
            Class::PaperGap => "paper_gap",
            Class::Undefined => "undefined",
            Class::TimeOutside => "time_outside",
        }
    }

    /// The table's column head (at most 8 characters).
    pub fn short(self) -> &'static str {
        match self {
            Class::Agree => "agree",
            Class::FloatDivergence => "float_dv",
            Class::MissedDetection => "MISSED",
            Class::FalseAlarmInBand => "in_band",
            Class::FalseAlarmFar => "FAR",
            Class::ConservativeFar => "cons_far",
            Class::PaperGap => "pap_gap",
            Class::Undefined => "undef",
            Class::TimeOutside => "TIME",
        }
    }

    /// One line on what the class means (the summary's legend).
    pub fn meaning(self) -> &'static str {
        match self {
            Class::Agree => "engine, paper-exact and truth tell the same story",
            Class::FloatDivergence => "engine differs from paper-exact; no miss, no false alarm",
            Class::MissedDetection => "the point enters, the engine says no: THE failure",
            Class::FalseAlarmInBand => "engine yes, truth no, within the BUFF/F band: by design",
            Class::FalseAlarmFar => "engine yes, truth no, beyond the wide band: a failure",
            Class::ConservativeFar => {
                "like FAR, on a comparison undecidable in f64: safe, reported"
            }
            Class::PaperGap => "the point enters, paper-exact says no: about the paper",
            Class::Undefined => "the fill rule decides (polygon not simple at the start)",
            Class::TimeOutside => "the exact entry time is outside the f64 enclosure: a failure",
        }
    }

    /// A failure that a campaign must report with a non-zero exit status.
    pub fn is_failure(self) -> bool {
        matches!(
            self,
            Class::MissedDetection | Class::FalseAlarmFar | Class::TimeOutside
        )
    }
}

/// The three answers on one case and its class.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// What the three answers say together.
    pub class: Class,
    /// The paper-A function that decided (§II.H, §II.I or §III).
    pub method: Method,
    /// The engine's answer.
    pub engine: bool,
    /// The engine's "yes" was taken on an undecided comparison (`api::Kind::Conservative`).
    pub conservative: bool,
    /// The certified engine decided (a certified yes or no) against paper A in exact
    /// arithmetic: a breach of its certificate, whichever engine the campaign judges.
    pub certificate_breach: bool,
    /// The plain f64 transcription's answer (the canary of the contract check).
    pub plain: bool,
    /// Paper A's answer without rounding (the oracle).
    pub paper: bool,
    /// Some(true) enters, Some(false) misses, None undefined.
    pub truth: Option<bool>,
    /// The exact first entry time when the point enters, as its nearest f64 in Rust's
    /// shortest round-trip notation.
    pub entry_time: Option<String>,
    /// The case's lookahead T.
    pub lookahead: f64,
    /// The f64 enclosure of the entry time (`api::detect_time`, of the certified engine,
    /// moved by the canary's shift with `Hunted::ShiftedTime`).
    pub entry: polyguard::entry::EntryTime,
    /// Why the enclosure contradicts the truth, when it does.
    pub time_failure: Option<String>,
    /// Time spent in the engine, paper-exact, truth and the f64 entry time (ns).
    pub nanos: [u64; 4],
}

impl Verdict {
    /// A failure of the campaign on this case (what makes `polyguard assure` exit 1): a
    /// failing class ([`Class::is_failure`]), a breach of the contract (paper A without
    /// rounding says yes, the engine no) or of the certificate.
    pub fn is_failure(&self) -> bool {
        self.class.is_failure() || (self.paper && !self.engine) || self.certificate_breach
    }
}

/// Why a case could not be compared.
#[derive(Clone, Debug, PartialEq)]
pub enum CompareError {
    /// The engine rejects the case.
    Engine(String),
    /// The oracle rejects the case.
    Oracle(String),
}

/// The class from the three answers (`wide` is paper-exact on [`wide_case`], asked only
/// when needed; `conservative`: the engine's yes was taken on an undecided comparison;
/// `time_ok`: the f64 entry time agrees with the truth, [`time_failure`]).
pub fn classify(
    engine: bool,
    conservative: bool,
    paper: bool,
    truth: Option<bool>,
    time_ok: bool,
    wide: impl FnOnce() -> bool,
) -> Class {
    match truth {
        None => Class::Undefined,
        Some(true) if !engine => Class::MissedDetection,
        _ if !time_ok => Class::TimeOutside,
        Some(true) if !paper => Class::PaperGap,
        Some(false) if engine => {
            if paper || wide() {
                Class::FalseAlarmInBand
            } else if conservative {
                Class::ConservativeFar
            } else {
                Class::FalseAlarmFar
            }
        }
        _ if engine != paper => Class::FloatDivergence,
        _ => Class::Agree,
    }
}

/// Which f64 engine a campaign judges.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Hunted {
    /// The certified engine: the product.
    #[default]
    Certified,
    /// The plain f64 transcription of paper A (no certificate): the hunt's canary, which
    /// misses true entries that a hunt able to see must find.
    Plain,
    /// The certified engine whose entry-time enclosures are moved right by
    /// [`TIME_CANARY_STEPS`] resolution steps: the canary of the `time_outside` class.
    ShiftedTime,
}

/// How far the time canary moves each enclosure, in resolution steps (T·2⁻³⁶): the exact
/// entry time of a crossing then lies before lo.
pub const TIME_CANARY_STEPS: f64 = 2.0;

/// Why the f64 entry time `answer` contradicts the exact truth, or `None` when it agrees:
/// a certified "never" for a point that enters, a certified entry for one that never does,
/// or an exact entry time outside [lo, hi] (compared exactly). An undefined truth judges
/// nothing. (Paper A §II–III's "the point enters", timed.)
pub fn time_failure(
    answer: polyguard::entry::EntryTime,
    truth: &polyguard_oracle::Truth,
) -> Option<String> {
    use polyguard::entry::EntryTime;
    use polyguard_oracle::convert::q;
    use polyguard_oracle::Truth;
    use std::cmp::Ordering;
    match (answer, truth) {
        (_, Truth::Undefined { .. }) => None,
        (EntryTime::Never, Truth::Enters { entry_time }) => Some(format!(
            "certified never, but the point enters at {}",
            entry_time.to_decimal_string(20)
        )),
        (EntryTime::Enters { .. }, Truth::Misses) => {
            Some("a certified entry, but the point never enters".into())
        }
        (
            EntryTime::Enters { lo, hi } | EntryTime::Possible { lo, hi },
            Truth::Enters { entry_time },
        ) => {
            let inside = match (q(lo), q(hi)) {
                (Some(l), Some(h)) => {
                    entry_time.cmp_rational(&l) != Ordering::Less
                        && entry_time.cmp_rational(&h) != Ordering::Greater
                }
                _ => false,
            };
            (!inside).then(|| {
                format!(
                    "the point enters at {}, outside [{lo:e}, {hi:e}]",
                    entry_time.to_decimal_string(20)
                )
            })
        }
        _ => None,
    }
}

/// The time canary's answer: `answer` moved right by `steps` resolution steps of T.
pub fn shifted(
    answer: polyguard::entry::EntryTime,
    lookahead: f64,
    steps: f64,
) -> polyguard::entry::EntryTime {
    use polyguard::entry::EntryTime;
    let d = steps * lookahead * polyguard::entry::RESOLUTION;
    match answer {
        EntryTime::Never => EntryTime::Never,
        EntryTime::Enters { lo, hi } => EntryTime::Enters {
            lo: lo + d,
            hi: hi + d,
        },
        EntryTime::Possible { lo, hi } => EntryTime::Possible {
            lo: lo + d,
            hi: hi + d,
        },
    }
}

impl Hunted {
    /// The name `--engine` takes and reports carry: "f64" or "plain".
    pub fn name(self) -> &'static str {
        match self {
            Hunted::Certified => "f64",
            Hunted::Plain => "plain",
            Hunted::ShiftedTime => "shifted-time",
        }
    }
}

/// Runs the engine, paper-exact and the truth on one case.
pub fn compare(raw: &RawCase) -> Result<Verdict, CompareError> {
    compare_as(raw, Hunted::Certified)
}

/// [`compare`] judging the `hunted` engine: the class, and `engine` in the verdict, are
/// that engine's.
pub fn compare_as(raw: &RawCase, hunted: Hunted) -> Result<Verdict, CompareError> {
    let case = raw
        .to_api()
        .map_err(|e| CompareError::Engine(e.to_string()))?;
    let clock = Instant::now();
    let tri = api::decide(&case);
    let t_engine = clock.elapsed();
    let engine = tri.or_true();
    let conservative = tri == polyguard::Tri::Unsure;
    let plain = api::detected_plain(&case);
    let clock = Instant::now();
    let exact = raw
        .exact::<Exact>()
        .map_err(|e| CompareError::Oracle(e.to_string()))?;
    let paper = polyguard_oracle::paper_detect(&exact).detected;
    let t_paper = clock.elapsed();
    let clock = Instant::now();
    let answer = polyguard_oracle::truth(&exact);
    let t_truth = clock.elapsed();
    let clock = Instant::now();
    let entry = api::detect_time(&case);
    let t_time = clock.elapsed();
    let entry = match hunted {
        Hunted::ShiftedTime => shifted(entry, raw.lookahead, TIME_CANARY_STEPS),
        _ => entry,
    };
    let failure = time_failure(entry, &answer);
    let (truth, entry_time) = match answer {
        polyguard_oracle::Truth::Enters { entry_time } => (
            Some(true),
            Some(format!(
                "{:e}",
                polyguard_oracle::convert::time_to_f64(&entry_time)
            )),
        ),
        polyguard_oracle::Truth::Misses => (Some(false), None),
        polyguard_oracle::Truth::Undefined { .. } => (None, None),
    };
    let wide = || {
        wide_case(raw)
            .exact::<Exact>()
            .map(|c| polyguard_oracle::paper_detect(&c).detected)
            .unwrap_or(true)
    };
    let engine = match hunted {
        Hunted::Certified | Hunted::ShiftedTime => engine,
        Hunted::Plain => plain,
    };
    let class = classify(
        engine,
        conservative && hunted != Hunted::Plain,
        paper,
        truth,
        failure.is_none(),
        wide,
    );
    let ns = |d: Duration| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX);
    Ok(Verdict {
        class,
        method: case.method(),
        engine,
        conservative,
        certificate_breach: match tri {
            polyguard::Tri::Yes => !paper,
            polyguard::Tri::No => paper,
            polyguard::Tri::Unsure => false,
        },
        plain,
        paper,
        truth,
        entry_time,
        lookahead: raw.lookahead,
        entry,
        time_failure: failure,
        nanos: [ns(t_engine), ns(t_paper), ns(t_truth), ns(t_time)],
    })
}

/// The contract check of one case (`polyguard assure --contract`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContractVerdict {
    /// The paper-A function that decided.
    pub method: Method,
    /// The engine's three-valued answer.
    pub engine: polyguard::Tri,
    /// The plain f64 transcription's answer (the canary).
    pub plain: bool,
    /// Paper A in exact arithmetic, asked only when the engine does not certify a yes
    /// (a certified yes is paper A's yes by the engine's certificate).
    pub paper: Option<bool>,
}

impl ContractVerdict {
    /// Paper A without rounding says yes (known from the engine's certified yes, or asked).
    pub fn paper_yes(&self) -> bool {
        self.engine == polyguard::Tri::Yes || self.paper == Some(true)
    }

    /// A breach of the contract: paper A without rounding says yes, the engine no.
    pub fn is_breach(&self) -> bool {
        self.paper_yes() && self.engine == polyguard::Tri::No
    }
}

/// The engine's contract on one case: the engine, the plain transcription, and paper A
/// in exact arithmetic where needed. No truth.
pub fn check_contract(raw: &RawCase) -> Result<ContractVerdict, CompareError> {
    let case = raw
        .to_api()
        .map_err(|e| CompareError::Engine(e.to_string()))?;
    let engine = api::decide(&case);
    let plain = api::detected_plain(&case);
    let paper = if engine == polyguard::Tri::Yes {
        None
    } else {
        let exact = raw
            .exact::<Exact>()
            .map_err(|e| CompareError::Oracle(e.to_string()))?;
        Some(polyguard_oracle::paper_detect(&exact).detected)
    };
    Ok(ContractVerdict {
        method: case.method(),
        engine,
        plain,
        paper,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_follow_the_definitions() {
        let never = || panic!("not needed");
        assert_eq!(
            classify(true, false, true, Some(true), true, never),
            Class::Agree
        );
        assert_eq!(
            classify(false, false, false, Some(false), true, never),
            Class::Agree
        );
        assert_eq!(
            classify(false, false, true, Some(true), true, never),
            Class::MissedDetection
        );
        assert_eq!(
            classify(false, false, false, Some(true), true, never),
            Class::MissedDetection
        );
        assert_eq!(
            classify(true, false, false, Some(true), true, never),
            Class::PaperGap
        );
        assert_eq!(
            classify(true, false, true, Some(false), true, never),
            Class::FalseAlarmInBand
        );
        assert_eq!(
            classify(true, false, false, Some(false), true, || true),
            Class::FalseAlarmInBand
        );
        assert_eq!(
            classify(true, false, false, Some(false), true, || false),
            Class::FalseAlarmFar
        );
        assert_eq!(
            classify(true, true, false, Some(false), true, || false),
            Class::ConservativeFar
        );
        assert_eq!(
            classify(true, true, false, Some(false), true, || true),
            Class::FalseAlarmInBand
        );
        assert_eq!(
            classify(false, false, true, Some(false), true, never),
            Class::FloatDivergence
        );
        assert_eq!(
            classify(true, false, true, None, true, never),
            Class::Undefined
        );
    }

    #[test]
    fn compare_runs_all_three() {
        let raw = RawCase {
            lookahead: 10.0,
            buff: 0.01,
            fac: 1e-4,
            pos: vec![5.0, -3.0],
            vel: vec![0.0, 1.0],
            vertices: vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            velocities: vec![[1.0, 0.0]; 4],
            slab: None,
        };
        let v = compare(&raw).expect("comparable");
        assert_eq!(
            (v.engine, v.paper, v.truth, v.class),
            (true, true, Some(true), Class::Agree)
        );
        // Far away and moving away: every answer no.
        let far = RawCase {
            pos: vec![50.0, -3.0],
            vel: vec![1.0, 0.0],
            ..raw
        };
        let v = compare(&far).expect("comparable");
        assert_eq!(v.class, Class::Agree);
        assert!(!v.engine && v.truth == Some(false));
    }
}
