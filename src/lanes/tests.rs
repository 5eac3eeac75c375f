//! The masks give the scalar loops' decisions: the kernels agree bit for bit with the
//! scalar comparisons, and definitely_outside (§II.E) and detect_same_2D (§II.H) answer
//! the same on masks as one edge at a time, on random and adversarial vertices (ties at
//! the margin, NaN, ±∞, subnormals, huge values) and sizes that leave partial registers
//! and partial chunks.

use super::*;
use crate::ball::{Ball, BallV, Tri, ETA, U};
use crate::contain::{definitely_outside_rel, outside_masked, AtTime, RelPoly, Shifted};
use crate::detect::detect_same_2d_tri;
use crate::polygon::VertexSeq;
use crate::predicates::Terms;
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
type Case = (f64, Vec<Vect2>, Vect2, Vect2, Vect2, f64);

fn case() -> impl Strategy<Value = Case> {
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

/// A frame without [`RelPoly::frame`]: definitely_outside_rel runs its scalar loop.
struct NoFrame<'a, R>(&'a R);

impl<R: RelPoly> RelPoly for NoFrame<'_, R> {
    fn count(&self) -> usize {
        self.0.count()
    }
    fn rel(&self, i: usize) -> BallV {
        self.0.rel(i)
    }
    fn terms(&self, i: usize) -> Option<Terms> {
        self.0.terms(i)
    }
    fn at(&self, i: usize) -> Vect2 {
        self.0.at(i)
    }
    fn skip_margin(&self, buff: f64) -> Option<f64> {
        self.0.skip_margin(buff)
    }
}

/// Vertices not stored as a slice: detect_same_2D runs its scalar loops.
struct NotSlice<'a>(&'a [Vect2]);

impl VertexSeq for NotSlice<'_> {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn vertex(&self, i: usize) -> Vect2 {
        self.0[i]
    }
}

/// definitely_outside_rel on masks with kernel `k`, as the masked path calls it.
fn masked<R: RelPoly, K: Kernel>(p: &R, buff: f64, k: K) -> Option<Tri> {
    let (m, f) = (p.skip_margin(buff)?, p.frame()?);
    Some(outside_masked(p, &f, m, buff, k))
}

/// Runs the property `check` on 2,000 cases on a thread with a 64 MiB stack: the
/// exact fall-backs of the engine on huge and non-finite inputs, and the case strategy
/// itself, nest deeper than a test thread's 2 MiB allow in an unoptimised build.
fn check_cases<S>(strategy: S, check: fn(S::Value) -> Result<(), TestCaseError>)
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

/// definitely_outside (§II.E) on masks, with each kernel, answers as the scalar loop,
/// at t = 0 and in the shifted frame at T.
#[test]
fn definitely_outside_on_masks_is_the_scalar_answer() {
    check_cases(case(), outside_same);
}

fn outside_same((b, verts, s, v, v0, t): Case) -> Result<(), TestCaseError> {
    let at0 = AtTime {
        p: &verts[..],
        vels: &verts[..],
        s,
        v,
        t: Ball::exact(0.0),
    };
    let shifted = Shifted::new(&verts[..], s, v, v0, Ball::exact(t));
    for (scalar, dispatched, portable, k) in [
        (
            definitely_outside_rel(&NoFrame(&at0), b),
            definitely_outside_rel(&at0, b),
            masked(&at0, b, Portable),
            0,
        ),
        (
            definitely_outside_rel(&NoFrame(&shifted), b),
            definitely_outside_rel(&shifted, b),
            masked(&shifted, b, Portable),
            1,
        ),
    ] {
        prop_assert_eq!(dispatched, scalar, "frame {}", k);
        prop_assert_eq!(portable, Some(scalar), "frame {}", k);
    }
    #[cfg(target_arch = "x86_64")]
    if let Some(avx) = Avx::new() {
        prop_assert_eq!(
            masked(&at0, b, avx),
            Some(definitely_outside_rel(&NoFrame(&at0), b))
        );
        prop_assert_eq!(
            masked(&shifted, b, avx),
            Some(definitely_outside_rel(&NoFrame(&shifted), b))
        );
    }
    Ok(())
}

/// detect_same_2D (§II.H) on slices (masks from 16 vertices on) answers as on
/// vertices that are not a slice (one edge at a time).
#[test]
fn detect_same_on_masks_is_the_scalar_answer() {
    check_cases(case(), detect_same);
}

fn detect_same((b, verts, s, v, v0, t): Case) -> Result<(), TestCaseError> {
    let vels = vec![v0; verts.len()];
    prop_assert_eq!(
        detect_same_2d_tri(t, s, v, &verts[..], &vels[..], b),
        detect_same_2d_tri(t, s, v, &NotSlice(&verts), &vels[..], b)
    );
    Ok(())
}

/// The frames' [`RelPoly::frame`] computes what their [`RelPoly::at`] does, bit for bit.
#[test]
fn a_frame_is_its_at() {
    let verts = [
        Vect2::new(0.1, 0.7),
        Vect2::new(3.3, -1e-310),
        Vect2::new(-2.9, 1e300),
    ];
    let (s, v, v0) = (
        Vect2::new(0.3, 0.2),
        Vect2::new(0.7, -0.1),
        Vect2::new(-0.3, 1.1),
    );
    let at0 = AtTime {
        p: &verts[..],
        vels: &verts[..],
        s,
        v,
        t: Ball::exact(0.0),
    };
    let shifted = Shifted::new(&verts[..], s, v, v0, Ball::exact(0.7));
    for k in 0..3 {
        let f = at0.frame().map(|f| f.at(k));
        assert_eq!(
            f.map(|q| (q.x.to_bits(), q.y.to_bits())),
            Some((at0.at(k).x.to_bits(), at0.at(k).y.to_bits()))
        );
        let f = shifted.frame().map(|f| f.at(k));
        let a = shifted.at(k);
        assert_eq!(
            f.map(|q| (q.x.to_bits(), q.y.to_bits())),
            Some((a.x.to_bits(), a.y.to_bits()))
        );
    }
    // At a time other than 0 each vertex moves by its own velocity: no frame.
    let at1 = AtTime {
        p: &verts[..],
        vels: &verts[..],
        s,
        v,
        t: Ball::exact(1.0),
    };
    assert!(at1.frame().is_none());
}
