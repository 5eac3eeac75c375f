//! Paper A §I: does a quadratic dip below a threshold D on the unit interval / unit box?

use crate::ball::{Ball, Tri};
use crate::predicates as pr;

/// Paper A §I: quad(a, b, c)(t) = a·t² + b·t + c.
#[inline(always)]
pub fn quad(a: f64, b: f64, c: f64, t: f64) -> f64 {
    (a * t + b) * t + c
}

/// Paper A §I: quad2D(a, b, c, d, e, f)(r, t) = a·r² + b·t² + c·r·t + d·r + e·t + f.
#[inline(always)]
pub fn quad2d(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, r: f64, t: f64) -> f64 {
    a * r * r + b * t * t + c * r * t + d * r + e * t + f
}

/// Paper A §I quad_min_le_D: is there a t ∈ [0, 1] with a·t² + b·t + c < D?
///
/// Step 1 tests the ends (quad(0) = c, quad(1) = a + b + c); step 2 the vertex
/// t* = −b/(2a) when a > 0 and t* ∈ [0, 1], whose value c − b²/(4a) is below D exactly
/// when b² − 4a(c − D) > 0 (the printed "b² 4a(c D) > 0" lost its minus signs).
///
/// Decided exactly for the given floats (sums and products as expansions,
/// `pr::quad_min_below_exact`); `true` when an intermediate overflows or underflows.
#[inline]
///
/// ```
/// use polyguard::quad_min_le_d;
/// // t² − t + 1 has its least value 3/4 at t = 1/2 (the vertex, step 2)
/// assert!(quad_min_le_d(1.0, -1.0, 1.0, 0.8));
/// assert!(!quad_min_le_d(1.0, -1.0, 1.0, 0.75)); // strict: never below 3/4
/// ```
pub fn quad_min_le_d(a: f64, b: f64, c: f64, d: f64) -> bool {
    let e = Ball::exact;
    match pr::quad_min_below(e(a), e(b), e(c), e(d)) {
        Tri::Unsure => pr::quad_min_below_exact(a, b, c, d).unwrap_or(true),
        t => t == Tri::Yes,
    }
}

/// Paper A §I quad_min_box_le_D: are there r, t ∈ [0, 1] with quad2D(a,…,f)(r, t) < D?
///
/// Steps 1–4 restrict to the four sides of the box (t = 1, t = 0, r = 1, r = 0); steps
/// 5–6 test the critical point r = mx/disc, t = my/disc with disc = c² − 4ab,
/// mx = 2bd − ce, my = 2ae − cd (solving ∂/∂r = 2ar + ct + d = 0 and
/// ∂/∂t = 2bt + cr + e = 0). The printed "0 < my·disc < disc²" is read as the closed
/// test, as for mx: the box is closed.
///
/// Decided on balls, and exactly (expansions) where they cannot tell: `false` only when
/// the exact answer for these floats is false, `true` beyond it only on overflow or
/// underflow. (The detectors do not call it: segments_close decides its step 4 in the
/// geometric form of `pr::segments_cross`.)
#[inline]
///
/// ```
/// use polyguard::quad_min_box_le_d;
/// // (r − t)² + 1 on [0, 1]²: its least value is 1, on the diagonal r = t
/// assert!(quad_min_box_le_d(1.0, 1.0, -2.0, 0.0, 0.0, 1.0, 1.5));
/// assert!(!quad_min_box_le_d(1.0, 1.0, -2.0, 0.0, 0.0, 1.0, 0.5));
/// ```
pub fn quad_min_box_le_d(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, dd: f64) -> bool {
    quad_min_box_le_d_tri(a, b, c, d, e, f, dd).or_true()
}

/// Paper A §I quad_min_box_le_D, three-valued (see [`quad_min_box_le_d`]).
pub fn quad_min_box_le_d_tri(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, dd: f64) -> Tri {
    let x = Ball::exact;
    let (a, b, c, d, e, f, dd) = (x(a), x(b), x(c), x(d), x(e), x(f), x(dd));
    let one = |p: Ball, q: Ball, r: Ball| p.add(q).add(r); // quad(p, q, r)(1)
    let sides = pr::quad_min_below(a, c.add(d), one(b, e, f), dd)
        .or(pr::quad_min_below(a, d, f, dd))
        .or(pr::quad_min_below(b, c.add(e), one(a, d, f), dd))
        .or(pr::quad_min_below(b, e, f, dd));
    if sides == Tri::Yes {
        return Tri::Yes;
    }
    match sides.or(pr::box_interior_min_below(a, b, c, d, e, f, dd)) {
        Tri::Unsure => box_exact(a.z, b.z, c.z, d.z, e.z, f.z, dd.z),
        t => t,
    }
}

/// quad_min_box_le_D decided exactly on expansions (steps 1–4 on the coefficient sums).
#[cold]
#[inline(never)]
fn box_exact(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, dd: f64) -> Tri {
    use crate::ball::exact::Sum;
    let (sa, sb, sdd) = (Sum::of(&[a]), Sum::of(&[b]), Sum::of(&[dd]));
    let sides = [
        (&sa, Sum::of(&[c, d]), Sum::of(&[b, e, f])),
        (&sa, Sum::of(&[d]), Sum::of(&[f])),
        (&sb, Sum::of(&[c, e]), Sum::of(&[a, d, f])),
        (&sb, Sum::of(&[e]), Sum::of(&[f])),
    ];
    let mut unsure = false;
    for (p, q, r) in &sides {
        match pr::quad_min_below_sums(p, q, r, &sdd) {
            Some(true) => return Tri::Yes,
            Some(false) => {}
            None => unsure = true,
        }
    }
    match pr::box_interior_min_below_exact(a, b, c, d, e, f, dd) {
        Some(true) => Tri::Yes,
        Some(false) if !unsure => Tri::No,
        _ => Tri::Unsure,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// §I quad_min_box_le_D on a box whose side t = 0, quad(1e200, −1e200, 0), dips to
    /// −¼·1e200 < D = 0 at r = ½, while its exact test overflows (b² = 1e400) and the
    /// interior has no critical point (disc = c² − 4ab = 0): an undecided side must keep
    /// the exact path from answering "no".
    #[test]
    fn an_overflowing_side_is_never_read_as_no() {
        let k = (1e200, 0.0, 0.0, -1e200, 0.0, 0.0, 0.0);
        assert!(quad_min_box_le_d(k.0, k.1, k.2, k.3, k.4, k.5, k.6));
        assert_ne!(
            quad_min_box_le_d_tri(k.0, k.1, k.2, k.3, k.4, k.5, k.6),
            Tri::No
        );
    }

    /// §I quad_min_box_le_D where only the exact path can tell: (r − ½)² + (t − ½)² +
    /// f − ½ with f the float just below ½ dips to −2⁻⁵⁴ < 0 at the box's centre, within
    /// the balls' rounding. The exact interior test must answer a certain yes.
    #[test]
    fn a_minimum_below_the_rounding_is_a_certain_yes() {
        let f = 0.5 - 2f64.powi(-54);
        assert_eq!(
            quad_min_box_le_d_tri(1.0, 1.0, 0.0, -1.0, -1.0, f, 0.0),
            Tri::Yes
        );
        // and just above: f = ½ puts the minimum at D, not below it
        assert_eq!(
            quad_min_box_le_d_tri(1.0, 1.0, 0.0, -1.0, -1.0, 0.5, 0.0),
            Tri::No
        );
    }

    #[test]
    fn parabola_with_known_minimum() {
        // (t − 1/2)² + 1 = t² − t + 5/4: minimum 1 at t = 1/2, ends 5/4.
        assert!(!quad_min_le_d(1.0, -1.0, 1.25, 1.0)); // min is 1, not < 1
        assert!(quad_min_le_d(1.0, -1.0, 1.25, 1.0 + 1.0 / 1024.0));
        assert!(!quad_min_le_d(1.0, -1.0, 1.25, 0.5));
        // Ends decide: the line 2 − t dips below 1.5 only near t = 1.
        assert!(quad_min_le_d(0.0, -1.0, 2.0, 1.5));
        assert!(!quad_min_le_d(0.0, -1.0, 2.0, 1.0)); // value 1 at t = 1, not < 1
    }

    #[test]
    fn vertex_outside_unit_interval_is_ignored() {
        // (t − 2)² = t² − 4t + 4: vertex at t = 2; on [0, 1] the minimum is 1 at t = 1.
        assert!(!quad_min_le_d(1.0, -4.0, 4.0, 1.0));
        assert!(quad_min_le_d(1.0, -4.0, 4.0, 1.0 + 1.0 / 64.0));
        // (t + 1)²: vertex at −1, minimum on [0,1] is 1 at t = 0.
        assert!(!quad_min_le_d(1.0, 2.0, 1.0, 1.0));
    }

    #[test]
    fn discriminant_exactly_zero_is_not_below() {
        // 4t² − 4t + 1 = (2t − 1)²: b² − 4a(c − 0) = 16 − 16 = 0, minimum exactly 0.
        assert!(!quad_min_le_d(4.0, -4.0, 1.0, 0.0));
        assert!(quad_min_le_d(4.0, -4.0, 1.0, 1.0 / 256.0));
    }

    #[test]
    fn downward_parabola_only_ends_matter() {
        // −t² + t + 1: max 1.25 at 1/2, ends 1.
        assert!(!quad_min_le_d(-1.0, 1.0, 1.0, 1.0));
        assert!(quad_min_le_d(-1.0, 1.0, 1.0, 1.0 + 1.0 / 128.0));
    }

    #[test]
    fn box_interior_minimum() {
        // (r − 1/2)² + (t − 1/2)² = r² + t² − r − t + 1/2: minimum 0 at the centre,
        // 1/4 on the sides' midpoints. D = 1/8 is reached only in the interior.
        let (a, b, c, d, e, f) = (1.0, 1.0, 0.0, -1.0, -1.0, 0.5);
        assert!(quad_min_box_le_d(a, b, c, d, e, f, 0.125));
        assert!(!quad_min_le_d(a, c + d, quad(b, e, f, 1.0), 0.125));
        assert!(!quad_min_le_d(a, d, f, 0.125));
        // Minimum exactly 0, not below 0: a threshold the balls cannot certify; the
        // exact fallback can.
        assert_eq!(quad_min_box_le_d_tri(a, b, c, d, e, f, 0.0), Tri::No);
        assert_eq!(quad_min_box_le_d_tri(a, b, c, d, e, f, -1e-9), Tri::No);
    }

    #[test]
    fn box_parallel_direction_disc_zero() {
        // (r − t)² = r² + t² − 2rt: disc = 4 − 4 = 0 (parallel segments); minimum 0 on
        // the diagonal, reached on the sides (r = t = 0).
        assert!(quad_min_box_le_d(1.0, 1.0, -2.0, 0.0, 0.0, 0.0, 1e-300));
        // (r − t)² + 1: never below 1 (exactly 1 on the diagonal), nor below 1 − 2⁻³⁰.
        assert_eq!(
            quad_min_box_le_d_tri(1.0, 1.0, -2.0, 0.0, 0.0, 1.0, 1.0),
            Tri::No
        );
        assert_eq!(
            quad_min_box_le_d_tri(1.0, 1.0, -2.0, 0.0, 0.0, 1.0, 1.0 - 2f64.powi(-30)),
            Tri::No
        );
    }
}
