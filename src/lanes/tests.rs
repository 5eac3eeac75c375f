//! The masks give the scalar comparisons' bits: every kernel agrees with them bit for
//! bit, on random and adversarial vertices (ties at the margin, NaN, ±∞, subnormals, huge
//! values) and sizes that leave partial registers and partial chunks. The cases serve the
//! detectors' own comparisons of their masked and scalar loops (`contain`'s tests and
//! `detect::same`'s), which this module does not import.

use super::*;
use crate::ball::{Ball, BallV, ETA, U};
use proptest::prelude::*;

/// BUFF values: ordinary, tiny, subnormal.
fn buff() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1.0),
        Just(0.5),
        0.01f64..3.0,
        Just(1e-300),
        Just(f64::MIN_POSITIVE / 1024.0),
    ]
}

/// A coordinate: mostly ordinary, often exactly at the margin of `AtTime` at t = 0 with
/// s = 0 (and one ulp either side), sometimes non-finite, subnormal or huge.
fn coord(buff: f64) -> impl Strategy<Value = f64> {
    let m = buff * (1.0 + 4.0 * U) + ETA;
    prop_oneof![
        6 => -6.0f64..6.0,
        2 => prop_oneof![
            Just(m), Just(-m), Just(buff), Just(-buff),
            Just(m.next_up()), Just(m.next_down()), Just(-m.next_up()), Just(-m.next_down()),
        ],
        1 => prop_oneof![
            Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY), Just(0.0), Just(-0.0),
            Just(f64::MIN_POSITIVE / 3.0), Just(-5e-324), Just(1e300), Just(-1e300),
        ],
    ]
}

fn point(buff: f64) -> impl Strategy<Value = Vect2> {
    (coord(buff), coord(buff)).prop_map(|(x, y)| Vect2::new(x, y))
}

/// A case: BUFF, the vertices (3 to 70), the point, its velocity, the common vertex
/// velocity, T; the point is often the origin, so that the margin ties above are exact.
/// Vertices not stored as a slice (`as_slice` is `None`): a detector given them runs its
/// one-edge-at-a-time loops, the reference its masked loops are compared with.
pub(crate) struct NotSlice<'a>(pub(crate) &'a [Vect2]);

impl crate::polygon::VertexSeq for NotSlice<'_> {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn vertex(&self, i: usize) -> Vect2 {
        self.0[i]
    }
}

pub(crate) type Case = (f64, Vec<Vect2>, Vect2, Vect2, Vect2, f64);

pub(crate) fn case() -> impl Strategy<Value = Case> {
    buff().prop_flat_map(|b| {
        (
            Just(b),
            proptest::collection::vec(point(b), 3..=70),
            prop_oneof![Just(Vect2::ZERO), point(b)],
            point(b),
            prop_oneof![Just(Vect2::ZERO), point(b)],
            prop_oneof![Just(0.0), Just(1.0), 0.0f64..10.0],
        )
    })
}

/// Runs the property `check` on 2,000 cases on a thread with a 64 MiB stack: the
/// exact fall-backs of the engine on huge and non-finite inputs, and the case strategy
/// itself, nest deeper than a test thread's 2 MiB allow in an unoptimised build.
pub(crate) fn check_cases<S>(strategy: S, check: fn(S::Value) -> Result<(), TestCaseError>)
where
    S: Strategy + Send + 'static,
{
    let run = move || {
        let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(2000));
        if let Err(e) = runner.run(&strategy, check) {
            panic!("{e}");
        }
    };
    let thread = std::thread::Builder::new().stack_size(64 << 20).spawn(run);
    if let Err(p) = thread.expect("a test thread").join() {
        std::panic::resume_unwind(p);
    }
}

/// The kernels' bits are the scalar comparisons, for every sub-range of a chunk.
#[test]
fn the_kernels_give_the_scalar_bits() {
    check_cases((case(), 0usize..70, any::<bool>()), kernel_bits);
}

fn kernel_bits(
    ((b, verts, s, sh, _, t), lo, shifted): (Case, usize, bool),
) -> Result<(), TestCaseError> {
    let n = verts.len();
    let lo = lo % n;
    let f = Frame {
        verts: &verts,
        s,
        shift: if shifted { Some(sh) } else { None },
    };
    let m = b * (1.0 + 4.0 * U) + ETA;
    let hi = (lo + MARGIN_CHUNK).min(n);
    let portable = Portable.margin_bits(&f, lo, hi, m);
    let (mut ge, mut le) = (0u64, 0u64);
    for k in lo..hi {
        let (g, l) = vertex_margin_bits(f.at(k), m);
        ge |= g << (2 * (k - lo));
        le |= l << (2 * (k - lo));
    }
    prop_assert_eq!(portable, (ge, le));
    let d = BallV::diff(sh, s).scale(Ball::exact(t));
    let line = PathLine::new(d, b);
    let hi = (lo + SIDE_CHUNK).min(n);
    let sides = Portable.side_bits(&line, &verts, s, lo, hi);
    for (k, &p) in verts[lo..hi].iter().enumerate() {
        let side = line.side(p - s);
        prop_assert_eq!((sides.0 >> k) & 1 == 1, side > 0);
        prop_assert_eq!((sides.1 >> k) & 1 == 1, side < 0);
    }
    #[cfg(target_arch = "x86_64")]
    if let Some(avx) = Avx::new() {
        let hi = (lo + MARGIN_CHUNK).min(n);
        prop_assert_eq!(avx.margin_bits(&f, lo, hi, m), portable);
        let hi = (lo + SIDE_CHUNK).min(n);
        prop_assert_eq!(avx.side_bits(&line, &verts, s, lo, hi), sides);
    }
    Ok(())
}
