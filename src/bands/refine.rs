//! The refinement of cells into bands (the parent module's "refinement"), for any cell
//! certificate: the planar tester of paper A §II–§III's motion, and the Earth's in
//! `polyguard-earth` (paper B §V's rhumb lines).

use std::vec::Vec;

use super::{Band, BandKind, Bands, MAX_CELLS};

/// A refinement pass that leaves more than this fraction of the Unknown total has
/// stalled.
const STALL: f64 = 0.9;

/// After this many stalled passes in a row the refinement stops (`met` is false).
const STALLS: usize = 4;

/// A cell certificate: what [`refine`] asks of one cell [lo, hi] of the parameter.
pub trait CellTest {
    /// What a cell's verdict leaves for its children to test (the planar tester: the
    /// obstacles still open; a certificate with nothing to pass down: `()`).
    type Open: Clone;
    /// What the first cells test (everything).
    fn everything(&self) -> Self::Open;
    /// The verdict on [lo, hi], testing what `open` holds, and what an `Unknown` verdict
    /// leaves open for the halves. The verdict must hold for every value of the closed
    /// cell: `Clear` and `Conflict` are certificates.
    fn test(&mut self, lo: f64, hi: f64, open: &Self::Open) -> (BandKind, Self::Open);
    /// Whether an `Unknown` cell is worth halving (false: halves would be Unknown too,
    /// for a reason the width does not change).
    fn splittable(&self, _open: &Self::Open) -> bool {
        true
    }
}

/// A cell of the refinement: its range, its verdict, and what it left open.
struct Cell<O> {
    lo: f64,
    hi: f64,
    kind: BandKind,
    open: O,
}

/// The refinement's state: the certificate and the cell tests made so far.
struct Refiner<'t, T: CellTest> {
    tester: &'t mut T,
    cells: usize,
}

impl<T: CellTest> Refiner<'_, T> {
    /// Tests [lo, hi] and halves it while Unknown and wider than `w_min`, pushing the
    /// leaves in order.
    fn settle(
        &mut self,
        lo: f64,
        hi: f64,
        open: &T::Open,
        w_min: f64,
        out: &mut Vec<Cell<T::Open>>,
    ) {
        self.cells += 1;
        let (kind, open) = self.tester.test(lo, hi, open);
        self.split(Cell { lo, hi, kind, open }, w_min, out);
    }

    /// Halves an Unknown cell wider than `w_min` (while its midpoint is strictly inside
    /// and the budget lasts), else keeps it.
    fn split(&mut self, cell: Cell<T::Open>, w_min: f64, out: &mut Vec<Cell<T::Open>>) {
        let m = cell.lo + (cell.hi - cell.lo) * 0.5;
        let can = cell.kind == BandKind::Unknown
            && cell.hi - cell.lo > w_min
            && cell.lo < m
            && m < cell.hi
            && self.cells + 2 <= MAX_CELLS
            && self.tester.splittable(&cell.open);
        if can {
            self.settle(cell.lo, m, &cell.open, w_min, out);
            self.settle(m, cell.hi, &cell.open, w_min, out);
        } else {
            out.push(cell);
        }
    }
}

/// The band answer over [lo, hi] from `first` equal cells (parent module's refinement):
/// the first cells as they are, then every Unknown cell halved once per pass while the
/// Unknown total is above `unknown_max`, some cell can still be split, the budget of
/// [`MAX_CELLS`] cell tests lasts, and fewer than four passes in a row stalled.
pub fn refine<T: CellTest>(
    tester: &mut T,
    lo: f64,
    hi: f64,
    first: usize,
    unknown_max: f64,
) -> Bands {
    let n = first.max(1);
    let all = tester.everything();
    let mut r = Refiner { tester, cells: 0 };
    let mut cells = Vec::new();
    let mut w_min = (hi - lo) / n as f64;
    let mut a = lo;
    for k in 1..=n {
        let b = if k == n {
            hi
        } else {
            lo + (hi - lo) * (k as f64 / n as f64)
        };
        r.settle(a, b, &all, f64::INFINITY, &mut cells);
        a = b;
    }
    let mut stalls = 0;
    loop {
        let unknown = unknown_width(&cells);
        if unknown <= unknown_max {
            break;
        }
        w_min *= 0.5;
        let before = r.cells;
        let mut next = Vec::with_capacity(cells.len());
        for cell in cells {
            r.split(cell, w_min, &mut next);
        }
        cells = next;
        let split = r.cells > before;
        if split {
            // Halving every Unknown cell roughly halves a sliver around a boundary; an
            // Unknown stretch that does not shrink is one the certificate cannot decide
            // at any width.
            if unknown_width(&cells) > STALL * unknown {
                stalls += 1;
            } else {
                stalls = 0;
            }
        }
        let stuck = !split && w_min < unknown_max * f64::EPSILON;
        if stuck || stalls >= STALLS || r.cells + 2 > MAX_CELLS {
            break;
        }
    }
    merge(cells, unknown_max)
}

/// The total width of the Unknown cells.
fn unknown_width<O>(cells: &[Cell<O>]) -> f64 {
    cells
        .iter()
        .filter(|c| c.kind == BandKind::Unknown)
        .fold(0.0, |u, c| u + (c.hi - c.lo))
}

/// Adjacent cells of one kind merged into bands, with the Unknown total.
fn merge<O>(cells: Vec<Cell<O>>, unknown_max: f64) -> Bands {
    let unknown_total = unknown_width(&cells);
    let mut bands: Vec<Band> = Vec::new();
    for c in cells {
        match bands.last_mut() {
            Some(b) if b.kind == c.kind => b.hi = c.hi,
            _ => bands.push(Band {
                lo: c.lo,
                hi: c.hi,
                kind: c.kind,
            }),
        }
    }
    Bands {
        bands,
        unknown_total,
        met: unknown_total <= unknown_max,
    }
}
