//! Pairs of nearby boxes by a sweep along one axis (sort, then scan forward while the next
//! box starts within reach): what makes §II.J's rules 1 and 2 ([`crate::well_formed`])
//! and §II's simplicity check ([`crate::ring`]) O(n log n + k) for k nearby pairs instead
//! of comparing every pair. Comparisons of the inputs only, so exact: no pair whose boxes
//! come within `reach` of each other on both axes is left out.

extern crate std;
use std::vec::Vec;

/// A box: its interval on the sweep axis (`lo`, `hi`) and on the other (`olo`, `ohi`),
/// and the index of what it bounds.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Item {
    pub lo: f64,
    pub hi: f64,
    pub olo: f64,
    pub ohi: f64,
    pub i: usize,
}

impl Item {
    /// The box of the points `a`, `b`, swept along x or (when `along_x` is false) y.
    pub fn of(a: crate::vect2::Vect2, b: crate::vect2::Vect2, i: usize, along_x: bool) -> Item {
        let (a0, a1, b0, b1) = if along_x {
            (a.x, a.y, b.x, b.y)
        } else {
            (a.y, a.x, b.y, b.x)
        };
        Item {
            lo: a0.min(b0),
            hi: a0.max(b0),
            olo: a1.min(b1),
            ohi: a1.max(b1),
            i,
        }
    }
}

/// Calls `visit(i, j)`, `i < j`, once for every pair of items whose intervals come within
/// `reach` of each other on both axes (`reach` ≥ 0; all inputs finite).
pub(crate) fn near_pairs(mut items: Vec<Item>, reach: f64, mut visit: impl FnMut(usize, usize)) {
    items.sort_unstable_by(|a, b| a.lo.total_cmp(&b.lo));
    for (k, a) in items.iter().enumerate() {
        for b in &items[k + 1..] {
            if b.lo > a.hi + reach {
                break;
            }
            if b.olo <= a.ohi + reach && a.olo <= b.ohi + reach {
                visit(a.i.min(b.i), a.i.max(b.i));
            }
        }
    }
}

/// Whether to sweep along x: the points' extent along x is at least that along y (a
/// needle along y would make an x sweep quadratic).
pub(crate) fn along_x(points: impl Iterator<Item = crate::vect2::Vect2>) -> bool {
    let (mut xlo, mut xhi, mut ylo, mut yhi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for v in points {
        xlo = xlo.min(v.x);
        xhi = xhi.max(v.x);
        ylo = ylo.min(v.y);
        yhi = yhi.max(v.y);
    }
    xhi - xlo >= yhi - ylo
}
