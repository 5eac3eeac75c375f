//! Tests of the three-valued logic, the balls and the exact signs: each bound against
//! exact sums of floats.
use super::exact::*;
use super::*;

#[test]
fn tri_logic() {
    use Tri::*;
    assert_eq!(Yes.or(Unsure), Yes);
    assert_eq!(No.or(Unsure), Unsure);
    assert_eq!(No.and(Unsure), No);
    assert_eq!(Yes.and(Unsure), Unsure);
    assert_eq!(Unsure.not(), Unsure);
    assert!(Unsure.or_true() && Yes.or_true() && !No.or_true());
}

#[test]
fn exact_signs_see_below_the_rounding() {
    // 1 + 2⁻⁶⁰ − 1 rounds to 0 in f64; the exact sum is 2⁻⁶⁰ > 0.
    let tiny = 2f64.powi(-60);
    assert_eq!(1.0 + tiny - 1.0, 0.0);
    assert_eq!(sign_sum(&[1.0, tiny, -1.0]), Some(1));
    assert_eq!(sign_sum(&[1.0, -tiny, -1.0]), Some(-1));
    assert_eq!(sign_sum(&[1.0, -1.0]), Some(0));
    // (1 + 2⁻³⁰)² − (1 + 2⁻²⁹) = 2⁻⁶⁰ exactly.
    let a = 1.0 + 2f64.powi(-30);
    let mut s = Sum::default();
    s.add_prod(a, a);
    s.add(-(1.0 + 2f64.powi(-29)));
    assert_eq!(s.sign(), Some(1));
    // Overflowing inputs are not decided.
    assert_eq!(sign_sum(&[f64::MAX, f64::MAX]), None);
    assert_eq!(two_prod(1e-200, 1e-200), None);
}

#[test]
fn balls_contain_the_exact_value() {
    // 0.1 + 0.2 in f64 is 0.30000000000000004; the exact sum of the two floats is
    // within the radius of the computed ball.
    let b = Ball::exact(0.1).add(Ball::exact(0.2));
    assert!(b.r > 0.0 && b.r < 1e-15);
    // (1 + 2⁻³⁰)² − (1 + 2⁻²⁹) = 2⁻⁶⁰: the ball cannot decide the sign (it is 0 in
    // f64) and says so.
    let a = Ball::exact(1.0 + 2f64.powi(-30));
    let d = a.sq().sub(Ball::exact(1.0 + 2f64.powi(-29)));
    assert_eq!(positive(d), Tri::Unsure);
    assert_eq!(positive(Ball::exact(f64::NAN)), Tri::Unsure);
    assert_eq!(positive(Ball::exact(3.0).sub(Ball::exact(1.0))), Tri::Yes);
}

/// Floats of every magnitude, signs and near-cancelling pairs (deterministic).
fn spread_floats(n: usize) -> Vec<[f64; 3]> {
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let float = |r: u64| {
        let mant = 1.0 + (r >> 12) as f64 / (1u64 << 52) as f64;
        let exp = ((r >> 3) % 80) as i32 - 40;
        let sign = if r & 1 == 0 { 1.0 } else { -1.0 };
        match r % 11 {
            0 => sign * f64::MIN_POSITIVE * mant / 1024.0, // subnormal
            _ => sign * mant * 2f64.powi(exp),
        }
    };
    (0..n)
        .map(|_| {
            let (a, b) = (float(next()), float(next()));
            // every third triple has a third value within rounding of the first
            let c = if next() % 3 == 0 {
                a * (1.0 + 2f64.powi(-50))
            } else {
                float(next())
            };
            [a, b, c]
        })
        .collect()
}

/// Is the exact `(Σ terms)/2` within `r` of `c`? Doubled to stay in exact sums:
/// `2c − 2r ≤ Σ terms ≤ 2c + 2r`.
fn half_sum_within(c: f64, r: f64, terms: &[f64]) -> bool {
    let signed = |k: f64| {
        let mut t = vec![2.0 * c, k * 2.0 * r];
        t.extend(terms.iter().map(|x| -x));
        sign_sum(&t)
    };
    signed(1.0).is_some_and(|s| s >= 0) && signed(-1.0).is_some_and(|s| s <= 0)
}

/// mid_offset and half_diff hold the exact `s − (p + q)/2` and `(p − q)/2`, checked by
/// exact sums on 20,000 triples of floats of every magnitude; with a quarter of the
/// radius (the canary) they do not.
#[test]
fn static_bounds_of_the_edge_quantities_hold_the_exact_values() {
    let cases = spread_floats(20_000);
    let (mut missed, mut missed_quarter) = (0, 0);
    for w in cases.windows(2) {
        let ([p0, q0, s0], [p1, q1, s1]) = (w[0], w[1]);
        let (p, q, s) = (Vect2::new(p0, p1), Vect2::new(q0, q1), Vect2::new(s0, s1));
        let m = BallV::mid_offset(p, q, s);
        let h = BallV::half_diff(p, q);
        for (c, r, terms) in [
            (m.v.x, m.r, [2.0 * s0, -p0, -q0]),
            (m.v.y, m.r, [2.0 * s1, -p1, -q1]),
            (h.v.x, h.r, [p0, -q0, 0.0]),
            (h.v.y, h.r, [p1, -q1, 0.0]),
        ] {
            if terms.iter().any(|t| !t.is_finite()) {
                continue;
            }
            missed += usize::from(!half_sum_within(c, r, &terms));
            missed_quarter += usize::from(!half_sum_within(c, 0.25 * r, &terms));
        }
    }
    assert_eq!(missed, 0);
    assert!(missed_quarter > 100, "the canary found {missed_quarter}");
}
