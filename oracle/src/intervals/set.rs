//! Closed sets of times with real algebraic ends, and the sets where one of the scene's
//! polynomials has a sign (paper A §II.C's edge quadratics, §II.I's warping edges,
//! §III's slab lines): sorted lists of disjoint closed components.
//!
//! Every end carries a rigorous float enclosure next to its exact value, which is built
//! only when needed: comparisons whose enclosures are apart are decided in floats, the
//! others exactly ([`RealAlg`]'s order). A root isolated in floats
//! ([`isolate_roots`]) becomes a [`RealAlg`] without further work: the exact polynomial
//! and the float bracket, whose certified opposite signs prove it isolating.

use core::cell::OnceCell;
use core::cmp::Ordering;
use std::rc::Rc;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::scene::{Kind, Scene};
use crate::algebraic::{Poly, RealAlg};
use crate::field::ExactField;
use crate::kernel::interval::{
    enclose, enclose_poly, isolate_roots, narrow_alg, poly_eval, tighten_alg, Iv, RootPiece,
};

/// A polynomial of the scene: its float enclosure now, in s = t − origin (the start
/// of the window it is worked on), its exact form in t on demand.
#[derive(Debug)]
pub(crate) struct Lazy {
    kind: Kind,
    /// Enclosures of the coefficients of a positive multiple, in s (lowest degree
    /// first).
    pub fl: Vec<Iv>,
    /// The origin of s, exactly and enclosed.
    origin: BigRational,
    origin_iv: Iv,
    exact: OnceCell<Poly>,
}

impl Lazy {
    /// The polynomial `kind` of the scene, to be worked on over the window w.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn new<F: ExactField>(sc: &Scene<'_, F>, kind: Kind, w: &Window) -> Rc<Self> {
        Rc::new(Lazy {
            kind,
            fl: sc.fl_poly(kind, w.lo_end.iv),
            origin: w.lo.clone(),
            origin_iv: w.lo_end.iv,
            exact: OnceCell::new(),
        })
    }

    /// The exact polynomial in t (a positive multiple of the same one).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn exact<F: ExactField>(&self, sc: &Scene<'_, F>) -> &Poly {
        self.exact.get_or_init(|| sc.exact_poly(self.kind))
    }

    /// The float value at the time t (enclosed).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    fn eval(&self, t: Iv) -> Iv {
        poly_eval(&self.fl, t.sub(self.origin_iv))
    }
}

/// How an end's exact value is known.
#[derive(Clone, Debug)]
enum Value {
    /// Exactly.
    Known(RealAlg),
    /// As the one root of `poly` at t = origin + s with s in (at.lo, at.hi), certified
    /// in floats (negative at at.lo when `rising`); the exact number is built on first
    /// use.
    Float {
        poly: Rc<Lazy>,
        at: Iv,
        rising: bool,
        alg: OnceCell<RealAlg>,
    },
}

/// An end of a component: a real algebraic time, with a rigorous float enclosure.
#[derive(Clone, Debug)]
pub(crate) struct End {
    /// Encloses the exact value (a point only when the value is that float).
    pub iv: Iv,
    value: Value,
    /// The exact value with its isolating interval narrowed below float resolution
    /// ([`narrow_alg`]), made when a comparison first needs it.
    narrow: OnceCell<RealAlg>,
}

impl End {
    /// The exact number x with an enclosure of it (a rational is enclosed anew).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    fn with_enclosure(x: RealAlg, iv: Iv) -> End {
        if let Some(q) = x.as_rational() {
            return End::rational(q.clone());
        }
        End {
            iv,
            value: Value::Known(x),
            narrow: OnceCell::new(),
        }
    }

    /// The rational x.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn rational(x: BigRational) -> End {
        End {
            iv: enclose(&x),
            value: Value::Known(RealAlg::rational(x)),
            narrow: OnceCell::new(),
        }
    }

    /// The root of `poly` certified in floats at s in (at.lo, at.hi).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    fn float(poly: &Rc<Lazy>, at: Iv, rising: bool) -> End {
        End {
            iv: poly.origin_iv.add(at),
            value: Value::Float {
                poly: Rc::clone(poly),
                at,
                rising,
                alg: OnceCell::new(),
            },
            narrow: OnceCell::new(),
        }
    }

    /// The exact value (built on first use).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn alg<F: ExactField>(&self, sc: &Scene<'_, F>) -> &RealAlg {
        match &self.value {
            Value::Known(x) => x,
            Value::Float {
                poly,
                at,
                rising,
                alg,
            } => alg.get_or_init(|| {
                let p = poly.exact(sc).clone();
                // A root bracket's ends are finite floats (isolate_roots works in a
                // finite window only).
                let lo = &poly.origin
                    + at.lo_exact::<BigRational>()
                        .expect("a root bracket has finite ends");
                let hi = &poly.origin
                    + at.hi_exact::<BigRational>()
                        .expect("a root bracket has finite ends");
                let s = if *rising {
                    Ordering::Less
                } else {
                    Ordering::Greater
                };
                RealAlg::certified(p, lo, hi, s)
            }),
        }
    }

    /// The exact value, owned.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn into_alg<F: ExactField>(self, sc: &Scene<'_, F>) -> RealAlg {
        match self.value {
            Value::Known(x) => x,
            Value::Float { .. } => self.alg(sc).clone(),
        }
    }

    /// The exact value, its isolating interval narrowed below float resolution.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    fn narrowed<F: ExactField>(&self, sc: &Scene<'_, F>) -> &RealAlg {
        self.narrow.get_or_init(|| {
            let mut x = self.alg(sc).clone();
            narrow_alg(&mut x);
            x
        })
    }

    /// Whether both are the same root of the same polynomial (then equal).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    fn same_root(&self, o: &End) -> bool {
        match (&self.value, &o.value) {
            (Value::Float { poly: a, at: x, .. }, Value::Float { poly: b, at: y, .. }) => {
                Rc::ptr_eq(a, b) && x == y
            }
            _ => false,
        }
    }
}

/// The exact order of two ends: by their enclosures when they are apart, else exactly.
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
pub(crate) fn cmp_end<F: ExactField>(sc: &Scene<'_, F>, a: &End, b: &End) -> Ordering {
    if a.iv.hi < b.iv.lo {
        return Ordering::Less;
    }
    if b.iv.hi < a.iv.lo {
        return Ordering::Greater;
    }
    if (a.iv.is_point() && a.iv == b.iv) || a.same_root(b) {
        return Ordering::Equal;
    }
    a.narrowed(sc).cmp(b.narrowed(sc))
}

/// A time window [lo, hi] with rational ends (lo ≤ hi).
#[derive(Clone, Debug)]
pub(crate) struct Window {
    /// Its start, exactly.
    pub lo: BigRational,
    /// Its end, exactly.
    pub hi: BigRational,
    /// Its start as an end.
    pub lo_end: End,
    /// Its end as an end.
    pub hi_end: End,
}

impl Window {
    /// [lo, hi] (lo ≤ hi).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn new(lo: BigRational, hi: BigRational) -> Self {
        Window {
            lo_end: End::rational(lo.clone()),
            hi_end: End::rational(hi.clone()),
            lo,
            hi,
        }
    }

    /// The float hull of the window.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn iv(&self) -> Iv {
        self.lo_end.iv.hull(self.hi_end.iv)
    }

    /// Whether the window is a single time.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn is_point(&self) -> bool {
        self.lo == self.hi
    }
}

/// A point of time where a sign is taken: a float (as a point enclosure) or, when no
/// float fits, a rational.
pub(crate) struct Sample {
    /// Its enclosure.
    pub iv: Iv,
    /// Its exact value (built on first use for a float).
    exact: OnceCell<BigRational>,
}

impl Sample {
    /// The exact value.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn exact(&self) -> &BigRational {
        self.exact
            .get_or_init(|| self.iv.lo_exact().expect("a float sample is finite"))
    }

    /// A time strictly between the ends a < b: a float between their enclosures, or the
    /// midpoint of their isolating intervals refined apart.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn between<F: ExactField>(sc: &Scene<'_, F>, a: &End, b: &End) -> Sample {
        if let Some(m) = Iv::point_between(a.iv, b.iv) {
            return Sample {
                iv: m,
                exact: OnceCell::new(),
            };
        }
        let (mut x, mut y) = (a.alg(sc).clone(), b.alg(sc).clone());
        while x.bounds().1 >= y.bounds().0 {
            x.refine();
            y.refine();
        }
        let m = (x.bounds().1 + y.bounds().0) / BigRational::from_integer(BigInt::from(2));
        Sample::rational(m)
    }

    /// The time in decimal (9 digits, toward −∞), for messages.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn exact_text(&self) -> String {
        RealAlg::rational(self.exact().clone()).to_decimal_string(9)
    }

    /// The rational time m.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn rational(m: BigRational) -> Sample {
        Sample {
            iv: enclose(&m),
            exact: OnceCell::from(m),
        }
    }
}

/// The exact sign of a scene polynomial at a sample (floats first).
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
pub(crate) fn sign_at_sample<F: ExactField>(
    sc: &Scene<'_, F>,
    poly: &Lazy,
    at: &Sample,
) -> Ordering {
    match poly.eval(at.iv).sign() {
        Ok(s) => s,
        Err(_) => poly.exact(sc).sign_at(at.exact()),
    }
}

/// The exact sign of a scene polynomial at an end (floats first, over the enclosure).
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
pub(crate) fn sign_at_end<F: ExactField>(sc: &Scene<'_, F>, poly: &Lazy, at: &End) -> Ordering {
    match poly.eval(at.iv).sign() {
        Ok(s) => s,
        Err(_) => at.alg(sc).sign_of(poly.exact(sc)),
    }
}

/// A root of a scene polynomial, with the polynomial's sign just after it when floats
/// certified it (the sign just before is the other one: a certified root is simple).
pub(crate) type Root = (End, Option<Ordering>);

/// The distinct roots of a scene polynomial in the closed window, increasing; `None`
/// when the polynomial is identically 0. Roots certified in floats strictly inside the
/// window cost no exact work; the rest (a root bracket over a window end, a stretch the
/// floats could not settle) is done exactly.
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
pub(crate) fn roots_in<F: ExactField>(
    sc: &Scene<'_, F>,
    poly: &Rc<Lazy>,
    w: &Window,
) -> Option<Vec<Root>> {
    let mut out = Vec::new();
    // The window in s = t − w.lo (poly's origin is w.lo).
    let width = w.hi_end.iv.sub(w.lo_end.iv);
    let ws = Iv::ZERO.hull(Iv::point(width.hi));
    for piece in isolate_roots(&poly.fl, ws) {
        match piece {
            RootPiece::Root { at, rising } => {
                let e = End::float(poly, at, rising);
                let inside = at.lo >= 0.0 && at.hi <= width.lo;
                if inside
                    || (cmp_end(sc, &e, &w.lo_end) != Ordering::Less
                        && cmp_end(sc, &e, &w.hi_end) != Ordering::Greater)
                {
                    let after = if rising {
                        Ordering::Greater
                    } else {
                        Ordering::Less
                    };
                    out.push((e, Some(after)));
                }
            }
            RootPiece::Unsure(at) => {
                let p = poly.exact(sc);
                if p.is_zero() {
                    return None;
                }
                let lo = match at.lo_exact::<BigRational>() {
                    Some(l) if l > BigRational::zero() => &w.lo + l,
                    _ => w.lo.clone(),
                };
                let hi = match at.hi_exact::<BigRational>() {
                    Some(h) if &w.lo + &h < w.hi => &w.lo + h,
                    _ => w.hi.clone(),
                };
                if lo <= hi {
                    out.extend(shifted_roots(p, &lo, &hi).into_iter().map(|e| (e, None)));
                }
            }
        }
    }
    Some(out)
}

/// How many times an unsure stretch is moved to the origin and tried in floats again
/// before exact isolation.
const SHIFTS: u32 = 3;

/// The roots of p in [lo, hi] (lo ≤ hi), increasing: in floats again with the origin
/// of time moved to lo exactly ([`Poly::shifted`]: exact coefficients, so a stretch
/// that floats could not settle far from t = 0 for cancellation often settles now; each
/// move gains about half the float precision around a near-double root), then in
/// floats on p's squarefree part (where an exact double root is a simple one), and
/// exactly (Sturm) where they still cannot tell.
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
fn shifted_roots(p: &Poly, lo: &BigRational, hi: &BigRational) -> Vec<End> {
    let mut out: Vec<(RealAlg, Iv)> = Vec::new();
    let mut stack = vec![(lo.clone(), hi.clone(), 0u32)];
    let mut squarefree: Option<Poly> = None;
    while let Some((a, b, depth)) = stack.pop() {
        let q = if depth < SHIFTS {
            p
        } else {
            squarefree.get_or_insert_with(|| p.squarefree())
        };
        let mut unsure = Vec::new();
        for piece in float_roots(q, &a, &b) {
            match piece {
                Ok(e) => out.push(e),
                Err((l, h)) => unsure.push((l, h)),
            }
        }
        for (l, h) in unsure.into_iter().rev() {
            if depth < SHIFTS {
                stack.push((l, h, depth + 1));
            } else {
                out.extend(q.roots_in(&l, &h).into_iter().map(|mut x| {
                    let iv = tighten_alg(&mut x);
                    (x, iv)
                }));
            }
        }
    }
    // Distinct roots, ordered by their enclosures where these are apart, else exactly.
    out.sort_by(|(x, a), (y, b)| {
        if a.hi < b.lo {
            Ordering::Less
        } else if b.hi < a.lo {
            Ordering::Greater
        } else {
            x.cmp(y)
        }
    });
    out.into_iter()
        .map(|(x, iv)| End::with_enclosure(x, iv))
        .collect()
}

/// The roots of q in [lo, hi] isolated in floats after moving the origin to lo: each a
/// root with its enclosure (`Ok`), or a stretch [l, h] ⊆ [lo, hi] that floats could
/// not settle.
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
fn float_roots(
    q: &Poly,
    lo: &BigRational,
    hi: &BigRational,
) -> Vec<Result<(RealAlg, Iv), (BigRational, BigRational)>> {
    let shifted = q.shifted(lo);
    let window = Iv::ZERO.hull(enclose(&(hi - lo)));
    let mut out = Vec::new();
    for piece in isolate_roots(&enclose_poly(&shifted), window) {
        match piece {
            RootPiece::Root { at, rising } => {
                let (Some(sl), Some(sh)) =
                    (at.lo_exact::<BigRational>(), at.hi_exact::<BigRational>())
                else {
                    out.push(Err((lo.clone(), hi.clone())));
                    continue;
                };
                let (tl, th) = (lo + sl, lo + sh);
                let iv = Iv {
                    lo: enclose(&tl).lo,
                    hi: enclose(&th).hi,
                };
                let inside = &tl >= lo && &th <= hi;
                let s = if rising {
                    Ordering::Less
                } else {
                    Ordering::Greater
                };
                let x = RealAlg::certified(q.clone(), tl, th, s);
                if inside
                    || (x.cmp_rational(lo) != Ordering::Less
                        && x.cmp_rational(hi) != Ordering::Greater)
                {
                    out.push(Ok((x, iv)));
                }
            }
            RootPiece::Unsure(at) => {
                let a = match at.lo_exact::<BigRational>() {
                    Some(l) if l > BigRational::zero() => lo + l,
                    _ => lo.clone(),
                };
                let b = match at.hi_exact::<BigRational>() {
                    Some(h) if &(lo + &h) < hi => lo + h,
                    _ => hi.clone(),
                };
                if a <= b {
                    out.push(Err((a, b)));
                }
            }
        }
    }
    out
}

/// A closed set of times: sorted, disjoint closed components [a, b] (a ≤ b).
#[derive(Clone, Debug, Default)]
pub(crate) struct Set {
    /// The components.
    pub comps: Vec<(End, End)>,
}

impl Set {
    /// The empty set.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn empty() -> Set {
        Set { comps: Vec::new() }
    }

    /// The whole window.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn all(w: &Window) -> Set {
        Set {
            comps: vec![(w.lo_end.clone(), w.hi_end.clone())],
        }
    }

    /// Whether it has no point.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn is_empty(&self) -> bool {
        self.comps.is_empty()
    }

    /// The union of closed intervals, in any order: sorted by start, and merged where
    /// one starts at or before the other's end (closed sets that touch are one
    /// component).
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn union_of<F: ExactField>(sc: &Scene<'_, F>, mut parts: Vec<(End, End)>) -> Set {
        parts.sort_by(|a, b| cmp_end(sc, &a.0, &b.0));
        let mut comps: Vec<(End, End)> = Vec::with_capacity(parts.len());
        for (a, b) in parts {
            if let Some(last) = comps.last_mut() {
                if cmp_end(sc, &a, &last.1) != Ordering::Greater {
                    if cmp_end(sc, &b, &last.1) == Ordering::Greater {
                        last.1 = b;
                    }
                    continue;
                }
            }
            comps.push((a, b));
        }
        Set { comps }
    }

    /// self ∩ o.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn intersect<F: ExactField>(&self, sc: &Scene<'_, F>, o: &Set) -> Set {
        let mut comps = Vec::new();
        let (mut i, mut j) = (0, 0);
        while i < self.comps.len() && j < o.comps.len() {
            let (a, b) = (&self.comps[i], &o.comps[j]);
            let lo = if cmp_end(sc, &a.0, &b.0) == Ordering::Less {
                &b.0
            } else {
                &a.0
            };
            let a_first = cmp_end(sc, &a.1, &b.1) == Ordering::Less;
            let hi = if a_first { &a.1 } else { &b.1 };
            if cmp_end(sc, lo, hi) != Ordering::Greater {
                comps.push((lo.clone(), hi.clone()));
            }
            if a_first {
                i += 1;
            } else {
                j += 1;
            }
        }
        Set { comps }
    }

    /// The stretches of the window outside the set, each with a time strictly inside it
    /// (or the window's one time): the relatively open gaps [w0, a1), (b_k, a_k+1),
    /// (b_m, w1] around the components.
    /// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
    pub fn gaps<F: ExactField>(&self, sc: &Scene<'_, F>, w: &Window) -> Vec<(End, End, Sample)> {
        let mut out = Vec::new();
        let (Some(first), Some(last)) = (self.comps.first(), self.comps.last()) else {
            let s = if w.is_point() {
                Sample::rational(w.lo.clone())
            } else {
                Sample::between(sc, &w.lo_end, &w.hi_end)
            };
            out.push((w.lo_end.clone(), w.hi_end.clone(), s));
            return out;
        };
        if cmp_end(sc, &w.lo_end, &first.0) == Ordering::Less {
            let s = Sample::between(sc, &w.lo_end, &first.0);
            out.push((w.lo_end.clone(), first.0.clone(), s));
        }
        for k in 1..self.comps.len() {
            let (a, b) = (&self.comps[k - 1].1, &self.comps[k].0);
            out.push((a.clone(), b.clone(), Sample::between(sc, a, b)));
        }
        if cmp_end(sc, &last.1, &w.hi_end) == Ordering::Less {
            let s = Sample::between(sc, &last.1, &w.hi_end);
            out.push((last.1.clone(), w.hi_end.clone(), s));
        }
        out
    }
}

/// {t ∈ W : P(t) ≤ 0} (`want` Less) or {P(t) ≥ 0} (`want` Greater) for a scene
/// polynomial P: its roots in W, and P's sign on each stretch between them taken at a
/// sample (a root always belongs to the set; a stretch when P has the wanted sign).
/// (The contract's components: ends at roots of paper A §II.C/§II.I's polynomials.)
pub(crate) fn sign_set<F: ExactField>(
    sc: &Scene<'_, F>,
    poly: &Rc<Lazy>,
    w: &Window,
    want: Ordering,
) -> Set {
    if w.is_point() {
        let s = sign_at_sample(sc, poly, &Sample::rational(w.lo.clone()));
        return if s == want || s == Ordering::Equal {
            Set::all(w)
        } else {
            Set::empty()
        };
    }
    let Some(roots) = roots_in(sc, poly, w) else {
        return Set::all(w);
    };
    // The stretches between the window's ends and the roots, in order, each with its
    // ends; a root at a window end leaves no stretch there. A stretch's sign is known
    // from a float-certified root at either end, else taken at a sample.
    let mut pieces: Vec<(End, End, bool)> = Vec::with_capacity(2 * roots.len() + 1);
    let mut from = w.lo_end.clone();
    let mut after: Option<Ordering> = None;
    for (r, r_after) in roots {
        if cmp_end(sc, &from, &r) == Ordering::Less {
            let sign = match (after, r_after) {
                (Some(s), _) => s,
                (None, Some(s)) => s.reverse(),
                (None, None) => sign_at_sample(sc, poly, &Sample::between(sc, &from, &r)),
            };
            pieces.push((from, r.clone(), sign == want));
        }
        pieces.push((r.clone(), r.clone(), true));
        from = r;
        after = r_after;
    }
    if cmp_end(sc, &from, &w.hi_end) == Ordering::Less {
        let sign = match after {
            Some(s) => s,
            None => sign_at_sample(sc, poly, &Sample::between(sc, &from, &w.hi_end)),
        };
        pieces.push((from, w.hi_end.clone(), sign == want));
    }
    // Runs of kept pieces are components (a kept stretch's ends are roots or window
    // ends, which belong to the closed set).
    let mut comps: Vec<(End, End)> = Vec::new();
    let mut open = false;
    for (a, b, keep) in pieces {
        if !keep {
            open = false;
            continue;
        }
        if open {
            if let Some(last) = comps.last_mut() {
                last.1 = b;
            }
        } else {
            comps.push((a, b));
            open = true;
        }
    }
    Set { comps }
}
