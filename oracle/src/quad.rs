//! Paper A §I: does a quadratic in one or two variables go below a threshold
//! on the unit interval / unit box?

use crate::field::ExactField;

/// Paper A §I: quad(a, b, c)(t) = a·t² + b·t + c.
pub fn quad<F: ExactField>(a: &F, b: &F, c: &F, t: &F) -> F {
    a.times(t).plus(b).times(t).plus(c)
}

/// Paper A §I: quad2D(a, b, c, d, e, f)(r, t) = a·r² + b·t² + c·r·t + d·r + e·t + f.
#[allow(clippy::too_many_arguments)]
pub fn quad2d<F: ExactField>(a: &F, b: &F, c: &F, d: &F, e: &F, f: &F, r: &F, t: &F) -> F {
    a.times(&r.sq())
        .plus(&b.times(&t.sq()))
        .plus(&c.times(r).times(t))
        .plus(&d.times(r))
        .plus(&e.times(t))
        .plus(f)
}

/// Paper A §I: quad_min_le_D — is a·t² + b·t + c < D for some t ∈ [0, 1]?
pub fn quad_min_le_d<F: ExactField>(a: &F, b: &F, c: &F, d: &F) -> bool {
    // Step 1: the ends t = 0 and t = 1.
    if c < d || a.plus(b).plus(c) < *d {
        return true;
    }
    // Step 2: an interior minimum at t = −b/(2a) ∈ [0, 1] with value c − b²/(4a) < D,
    // i.e. b² − 4a(c − D) > 0 (the OCR'd text lost this minus sign).
    if a.is_pos() && !b.is_pos() && b.negated() <= a.plus(a) {
        let four_a = F::from_i64(4).times(a);
        if b.sq().minus(&four_a.times(&c.minus(d))).is_pos() {
            return true;
        }
    }
    false
}

/// Paper A §I: quad_min_box_le_D — is quad2D(a..f)(r, t) < D for some (r, t) ∈ [0, 1]²?
#[allow(clippy::too_many_arguments)]
pub fn quad_min_box_le_d<F: ExactField>(a: &F, b: &F, c: &F, d: &F, e: &F, f: &F, dd: &F) -> bool {
    // Steps 1–4: the four sides of the box t = 1, t = 0, r = 1, r = 0.
    let one = F::one();
    if quad_min_le_d(a, &c.plus(d), &quad(b, e, f, &one), dd)
        || quad_min_le_d(a, d, f, dd)
        || quad_min_le_d(b, &c.plus(e), &quad(a, d, f, &one), dd)
        || quad_min_le_d(b, e, f, dd)
    {
        return true;
    }
    // Step 5: the critical point is (mx, my)/disc with disc = c² − 4ab,
    // mx = 2bd − ce, my = 2ae − cd (the OCR'd text lost the minus signs).
    let two = F::from_i64(2);
    let disc = c.sq().minus(&F::from_i64(4).times(a).times(b));
    let mx = two.times(b).times(d).minus(&c.times(e));
    let my = two.times(a).times(e).minus(&c.times(d));
    // Step 6: (mx, my)/disc inside the box and the value there below D, all
    // multiplied by disc² (when disc = 0, (mx, my) lies in the kernel of the
    // Hessian and the last test reads 0 < 0: false, as it must be).
    let disc2 = disc.sq();
    let mxd = mx.times(&disc);
    let myd = my.times(&disc);
    let zero = F::zero();
    if zero <= mxd && mxd <= disc2 && zero <= myd && myd <= disc2 {
        let v = quad2d(
            a,
            b,
            c,
            &d.times(&disc),
            &e.times(&disc),
            &f.times(&disc2),
            &mx,
            &my,
        );
        if v < dd.times(&disc2) {
            return true;
        }
    }
    false
}
