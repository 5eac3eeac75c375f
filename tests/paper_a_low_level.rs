//! The contract at the `no_std` entry points: `polyguard::detect_same_2d`,
//! `detect_diff_2d` and `detect_3d` called on slices, in the case's own (absolute)
//! coordinates, as a user of the `no_std` path calls them.
//!
//! Once only `api::Case::new` translated the case to the point, so the slice
//! functions missed what `api::detect` found: `polyguard::detect_3d` answered false on
//! `missed_detection-2486702` (tests/regressions/assure-seed7.jsonl), where paper A in
//! exact arithmetic answers true. The certified engine takes every decision on
//! differences from the point itself; these tests check, on every recorded regression
//! case and on long-path boundary cases of the assure generator, that the slice
//! functions give `api::decide`'s three-valued answer and never say no where paper-exact
//! says yes.

use std::fs;
use std::path::Path;

use polyguard::detect::Method;
use polyguard::{api, detect, Tri, Vect2};
use polyguard_harness::case::parse_line;
use polyguard_harness::case::RawCase;
use polyguard_harness::classify::Exact;
use polyguard_harness::gen::{self, SplitMix};

/// The slice function paper A's dispatch picks, on the raw case's own numbers.
fn slice_answer(raw: &RawCase) -> Tri {
    let p: Vec<Vect2> = raw.vertices.iter().map(|&q| q.into()).collect();
    let vels: Vec<Vect2> = if raw.velocities.is_empty() {
        vec![Vect2::ZERO; p.len()]
    } else {
        raw.velocities.iter().map(|&q| q.into()).collect()
    };
    let s = Vect2::new(raw.pos[0], raw.pos[1]);
    let v = Vect2::new(raw.vel[0], raw.vel[1]);
    let (t, buff, f) = (raw.lookahead, raw.buff, raw.fac);
    match (detect::dispatch(raw.slab.is_some(), &vels[..]), raw.slab) {
        (Method::Detect3d, Some([bottom, top, vsp])) => detect::detect_3d_tri(
            t,
            s,
            v,
            raw.pos[2],
            raw.vel[2],
            &p[..],
            &vels[..],
            bottom,
            top,
            vsp,
            buff,
            f,
        ),
        (Method::DetectSame2d, _) => detect::detect_same_2d_tri(t, s, v, &p[..], &vels[..], buff),
        _ => detect::detect_diff_2d_tri(t, s, v, &p[..], &vels[..], f, buff),
    }
}

/// Slice answer = api answer, and paper-exact yes ⇒ slice yes; returns paper-exact.
fn check(raw: &RawCase, what: &str) -> bool {
    let case = raw
        .to_api()
        .unwrap_or_else(|e| panic!("{what}: not a valid case: {e}"));
    let slice = slice_answer(raw);
    assert_eq!(slice, api::decide(&case), "{what}: slice and api disagree");
    let exact = raw
        .exact::<Exact>()
        .unwrap_or_else(|e| panic!("{what}: the oracle rejects it: {e}"));
    let paper = polyguard_oracle::paper_detect(&exact).detected;
    assert!(
        !paper || slice.or_true(),
        "{what}: paper-exact yes, slice function no"
    );
    if slice == Tri::Yes {
        assert!(paper, "{what}: a certified yes where paper-exact says no");
    }
    if slice == Tri::No {
        assert!(!paper, "{what}: a certified no where paper-exact says yes");
    }
    paper
}

/// The case: `polyguard::detect_3d` on slices, absolute coordinates.
#[test]
fn detect_3d_on_slices_finds_missed_detection_2486702() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions/assure-seed7.jsonl");
    let text = fs::read_to_string(&path).expect("the regression corpus is readable");
    let (n, line) = text
        .lines()
        .enumerate()
        .find(|(_, l)| l.contains("\"missed_detection-2486702\""))
        .expect("the case is in the corpus");
    let case = parse_line(line, n + 1).case.expect("the case parses");
    let raw = RawCase::from_api(&case);
    assert!(raw.slab.is_some(), "a 3D case");
    assert!(
        check(&raw, "missed_detection-2486702"),
        "paper-exact detects it"
    );
    assert!(slice_answer(&raw).or_true());
    // The canary: the plain transcription (paper A without error bounds) on the same slices
    // still misses it, so this test would have caught that engine.
    let p: Vec<Vect2> = raw.vertices.iter().map(|&q| q.into()).collect();
    let vels: Vec<Vect2> = raw.velocities.iter().map(|&q| q.into()).collect();
    let [bottom, top, vsp] = raw.slab.expect("3D");
    let plain = polyguard::plain::detect::detect_3d(
        raw.lookahead,
        Vect2::new(raw.pos[0], raw.pos[1]),
        Vect2::new(raw.vel[0], raw.vel[1]),
        raw.pos[2],
        raw.vel[2],
        &p[..],
        &vels[..],
        bottom,
        top,
        vsp,
        raw.buff,
        raw.fac,
    );
    assert!(!plain, "the plain transcription misses it on slices");
}

/// Every recorded regression case, through the slice functions.
#[test]
fn every_regression_case_through_the_slice_functions() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions");
    let mut seen = 0;
    for entry in fs::read_dir(&dir).expect("tests/regressions exists") {
        let path = entry.expect("a directory entry").path();
        if path.extension().is_none_or(|x| x != "jsonl") {
            continue;
        }
        let text = fs::read_to_string(&path).expect("readable");
        for (n, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let case = parse_line(line, n + 1).case.expect("the corpus parses");
            check(
                &RawCase::from_api(&case),
                &format!("{}:{}", path.display(), n + 1),
            );
            seen += 1;
        }
    }
    assert!(seen >= 20, "the corpus has its cases ({seen})");
}

/// Long-path boundary cases of the assure generator (every mode and shape, relative
/// paths of 10 … 10⁷ polygon sizes, the rest of the scale space drawn as in assure),
/// through the slice functions.
#[test]
fn long_path_cases_through_the_slice_functions() {
    let mut src = SplitMix(0x5EED_0008);
    let long = gen::Space::aimed((1.0, 7.0), gen::Space::FULL.buff).expect("within the space");
    let mut stretched = 0;
    for k in 0..600 {
        let shape = [gen::Shape::Static, gen::Shape::Warping, gen::Shape::ThreeD][k % 3];
        let mode = gen::Mode::ALL[(k / 3) % gen::Mode::ALL.len()];
        let d = gen::case(&mut src, shape, mode, &long);
        if d.stretch > 1.0 {
            stretched += 1;
        }
        check(&d.raw, &format!("case {k} ({mode:?}, {shape:?})"));
    }
    assert!(
        stretched > 500,
        "the cases are long paths ({stretched} of 600)"
    );
}
