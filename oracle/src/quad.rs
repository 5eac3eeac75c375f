//! Paper A §I: does a quadratic in one or two variables go below a threshold
//! on the unit interval / unit box?

use crate::field::Arith;
use crate::kernel::{all_of, and, any_of, certainly, not, or, Kernel};

/// Paper A §I: quad(a, b, c)(t) = a·t² + b·t + c.
pub fn quad<N: Arith>(a: &N, b: &N, c: &N, t: &N) -> N {
    a.times(t).plus(b).times(t).plus(c)
}

/// Paper A §I: quad2D(a, b, c, d, e, f)(r, t) = a·r² + b·t² + c·r·t + d·r + e·t + f.
pub fn quad2d<N: Arith>(a: &N, b: &N, c: &N, d: &N, e: &N, f: &N, r: &N, t: &N) -> N {
    a.times(&r.sq())
        .plus(&b.times(&t.sq()))
        .plus(&c.times(r).times(t))
        .plus(&d.times(r))
        .plus(&e.times(t))
        .plus(f)
}

/// Paper A §I: quad_min_le_D — is a·t² + b·t + c < D for some t ∈ [0, 1]?
pub fn quad_min_le_d<N: Arith, K: Kernel<N>>(
    k: &K,
    a: &N,
    b: &N,
    c: &N,
    d: &N,
) -> Result<bool, K::Abstain> {
    // Step 1: the ends t = 0 and t = 1.
    let ends = or(k.lt(c, d), || k.lt(&a.plus(b).plus(c), d));
    if certainly(ends) {
        return ends;
    }
    // Step 2: an interior minimum at t = −b/(2a) ∈ [0, 1] with value c − b²/(4a) < D,
    // i.e. b² − 4a(c − D) > 0 (the OCR'd text lost this minus sign).
    or(ends, || {
        all_of!(
            k.is_pos(a),
            not(k.is_pos(b)),
            k.le(&b.negated(), &a.twice()),
            k.is_pos(&b.sq().minus(&a.twice().twice().times(&c.minus(d))))
        )
    })
}

/// Paper A §I: quad_min_box_le_D — is quad2D(a..f)(r, t) < D for some (r, t) ∈ [0, 1]²?
pub fn quad_min_box_le_d<N: Arith, K: Kernel<N>>(
    k: &K,
    a: &N,
    b: &N,
    c: &N,
    d: &N,
    e: &N,
    f: &N,
    dd: &N,
) -> Result<bool, K::Abstain> {
    // Steps 1–4: the four sides of the box t = 1, t = 0, r = 1, r = 0.
    let one = N::one();
    let sides = any_of!(
        quad_min_le_d(k, a, &c.plus(d), &quad(b, e, f, &one), dd),
        quad_min_le_d(k, a, d, f, dd),
        quad_min_le_d(k, b, &c.plus(e), &quad(a, d, f, &one), dd),
        quad_min_le_d(k, b, e, f, dd),
    );
    if certainly(sides) {
        return sides;
    }
    // Step 5: the critical point is (mx, my)/disc with disc = c² − 4ab,
    // mx = 2bd − ce, my = 2ae − cd (the OCR'd text lost the minus signs).
    let disc = c.sq().minus(&a.twice().twice().times(b));
    let mx = b.twice().times(d).minus(&c.times(e));
    let my = a.twice().times(e).minus(&c.times(d));
    // Step 6: (mx, my)/disc inside the box and the value there below D, all
    // multiplied by disc² (when disc = 0, (mx, my) lies in the kernel of the
    // Hessian and the last test reads 0 < 0: false, as it must be).
    let disc2 = disc.sq();
    let mxd = mx.times(&disc);
    let myd = my.times(&disc);
    let zero = N::zero();
    let inside = all_of!(
        k.le(&zero, &mxd),
        k.le(&mxd, &disc2),
        k.le(&zero, &myd),
        k.le(&myd, &disc2),
    );
    or(sides, || {
        and(inside, || {
            let (dx, ex, fx) = (d.times(&disc), e.times(&disc), f.times(&disc2));
            let v = quad2d(a, b, c, &dx, &ex, &fx, &mx, &my);
            k.lt(&v, &dd.times(&disc2))
        })
    })
}
