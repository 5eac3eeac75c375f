//! Shared code of polyguard's fuzz targets (see README.md).
//!
//! - [`differential`]: decode the fuzzer's bytes into a boundary-biased case through the
//!   harness's generators (the same ones `polyguard assure` and the proptest suites use),
//!   compare the f64 engine with paper A in exact arithmetic and the exact truth, and
//!   abort on the three failures (`missed_detection`, `false_alarm_far`, `time_outside`) with the case as a
//!   line of the case format, ready for `tests/regressions/`.
//! - [`Num`]: an `arbitrary` f64 that favours the values that break float code (NaN, ±∞,
//!   ±0, subnormals, the overflow and underflow thresholds of a square).

use arbitrary::{Arbitrary, Unstructured};
use polyguard_harness::case::parse_line;
use polyguard_harness::classify::{self, Class};
use polyguard_harness::gen::{self, Bytes, Mode, Shape, Source};
use polyguard_harness::case::RawCase;

/// The snake_case name of a shape, as the target names use it.
pub fn shape_name(shape: Shape) -> &'static str {
    match shape {
        Shape::Static => "same_2d",
        Shape::Warping => "diff_2d",
        Shape::ThreeD => "3d",
    }
}

/// The body of the differential targets: one case of `shape` decoded from `data`.
///
/// The first draw picks the generator mode, the rest steer the case (polygon, scale,
/// offset, ε, trajectory). Cases the engine or the oracle reject, and cases whose truth
/// is undefined, are skipped. Panics (which libFuzzer reports as a crash and saves the
/// input for) on [`Class::MissedDetection`] and [`Class::FalseAlarmFar`].
pub fn differential(data: &[u8], shape: Shape) {
    // An input that starts with '{' is one case line of the case format: the seed corpus
    // is tests/regressions/*.jsonl, one line a file (see ci.sh), and libFuzzer mutates it.
    let (raw, origin) = if data.first() == Some(&b'{') {
        let Ok(text) = std::str::from_utf8(data) else {
            return;
        };
        let Ok(case) = parse_line(text.lines().next().unwrap_or(""), 1).case else {
            return;
        };
        (RawCase::from_api(&case), "a case line".to_string())
    } else {
        // The same scale space as assure: paths of 10⁻³ … 10⁷ polygon sizes, BUFF of
        // 10⁻¹² … 1, offsets to 10⁹, T of 10⁻⁶ … 10⁹, every outline.
        let mut src = Bytes::new(data);
        let mode = src.pick(&Mode::ALL);
        let d = gen::case(&mut src, shape, mode, &gen::Space::FULL);
        let why = format!(
            "generator mode {}, outline {}, eps {:e}, stretch {:e}",
            mode.name(),
            d.outline.name(),
            d.eps,
            d.stretch
        );
        (d.raw, why)
    };
    let Ok(verdict) = classify::compare(&raw) else {
        return;
    };
    // A failure: a missed detection, a far false alarm, a breach of the engine's
    // contract (paper A without rounding says yes, the engine says no), or a certified
    // answer paper A contradicts.
    let breach = (verdict.paper && !verdict.engine) || verdict.certificate_breach;
    if !verdict.class.is_failure() && !breach {
        return;
    }
    let class = verdict.class;
    let why = format!(
        "cargo-fuzz diff_{}, {}: engine {}, paper-exact {}, truth {}{}",
        shape_name(shape),
        origin,
        verdict.engine,
        verdict.paper,
        match verdict.truth {
            Some(true) => "enters",
            Some(false) => "misses",
            None => "undefined",
        },
        verdict
            .entry_time
            .as_deref()
            .map(|t| format!(" at t = {t}"))
            .unwrap_or_default(),
    ) + &verdict
        .time_failure
        .as_deref()
        .map(|f| format!("; entry time: {f}"))
        .unwrap_or_default();
    let id = format!("fuzz-{}", shape_name(shape));
    let line = raw.to_json_line(
        &id,
        &[
            ("class", class.name().into()),
            ("why", why.into()),
            ("method", verdict.method.name().into()),
        ],
    );
    match class {
        Class::MissedDetection => panic!("missed_detection (truth enters, engine no):\n{line}"),
        _ => panic!("{} (engine alarm far from any band):\n{line}", class.name()),
    }
}

/// An f64 for `arbitrary` that is often one of the values float code gets wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num(pub f64);

/// The values [`Num`] picks a quarter of the time.
pub const SPECIAL: [f64; 24] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::MIN_POSITIVE,
    f64::MIN_POSITIVE / 2.0, // subnormal
    -f64::MIN_POSITIVE / 4.0,
    5e-324, // the smallest subnormal
    f64::MAX,
    f64::MIN,
    f64::EPSILON,
    1.0 + f64::EPSILON,
    1e154, // its square is near the overflow threshold
    1.5e154,
    1e-162, // its square is subnormal
    1e300,
    -1e300,
    1e7,
    1e-7,
];

impl<'a> Arbitrary<'a> for Num {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let tag: u8 = u.arbitrary()?;
        let x = match tag % 4 {
            0 => SPECIAL[usize::from(tag / 4) % SPECIAL.len()],
            // Small dyadic numbers: exact arithmetic, many ties and zeros.
            1 => f64::from(u.arbitrary::<i16>()?) / 8.0,
            // Any bit pattern (NaN payloads, subnormals, huge exponents).
            2 => f64::from_bits(u.arbitrary::<u64>()?),
            // A moderate mantissa at any decimal scale.
            _ => {
                let m = f64::from(u.arbitrary::<i32>()?);
                let k = i32::from(u.arbitrary::<i16>()? % 330);
                m * 10f64.powi(k)
            }
        };
        Ok(Num(x))
    }

    fn size_hint(_depth: usize) -> (usize, Option<usize>) {
        (1, Some(9))
    }
}

/// Paper B's pipeline against its ground truth on a two-feature scenario drawn by
/// `assure --paper b`'s generator (`polyguard_harness::paper_b`), steered by the
/// input's bytes. Panics on a failure class (missed conflict, short window, far end,
/// broken speed bound) or on a generated scenario the reader refuses.
pub fn paper_b(data: &[u8]) {
    use polyguard_harness::paper_b as pb;
    let mut src = Bytes::new(data);
    let case = pb::draw(&mut src);
    match pb::judge(&case) {
        Ok((v, _, text)) => {
            if v.class.is_failure() {
                panic!(
                    "cargo-fuzz paper_b: {} ({}): pipeline window {:?}, truth {:?}\n{text}",
                    v.class.name(),
                    case.mode,
                    v.engine,
                    v.truth
                );
            }
        }
        Err(e) => panic!("cargo-fuzz paper_b: generated scenario refused ({}): {e}", case.mode),
    }
}
