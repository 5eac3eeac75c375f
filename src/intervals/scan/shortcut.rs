//! The scan's shortcut of a few sign changes (the definitions and method of
//! [`crate::intervals`]; paper A §II.C's quadratics): on a piece [a, b] where at most
//! [`FEW`] functions that matter may change sign, their roots are bracketed at once
//! instead of by halving.
//!
//! Each function must be certainly monotone on [a, b] (its derivative's range excludes
//! 0) with certain signs at a and b: opposite signs give one root, bracketed in
//! (t1, t2) with t2 − t1 ≤ 2ε ([`bracket`]); the same sign gives none.
//!
//! The brackets cut [a, b] into sub-pieces on which every one of the functions is
//! monotone, so its range there is the hull of its values at the sub-piece's ends (exact,
//! up to rounding): each sub-piece is assessed with those ranges put in. A bracket is
//! undecided, unless the sub-pieces on both sides are decided alike and the bracket,
//! assessed in the same way, is too (a change of reason, as from "within D" to
//! "inside", or a crossing where the slab excludes the point anyway). When any
//! sub-piece stays undecided the shortcut gives up and the caller halves [a, b].

use super::{
    bracket, centre, hull, sign, signed, Ball, Cands, Class, Fun, Pieces, Scan, State, Summary, FEW,
};

/// The most pieces: the sub-pieces around at most one bracket per function.
const PIECES: usize = 2 * FEW + 1;

/// The cut points of [a, b]: a, each bracket's ends, b (pieces alternate: sub-piece,
/// bracket, sub-piece, …), and every function's value at each.
struct Plan {
    at: [f64; PIECES + 1],
    vals: [[Ball; FEW]; PIECES + 1],
    /// How many points.
    np: usize,
    /// The function of each bracket's root, in order.
    roots: [Fun; FEW],
}

impl Scan<'_> {
    /// The brackets of the functions' roots on [a, b] (centre m, half width h) and the
    /// functions' values at their ends; `None` when a function is not certainly
    /// monotone, its signs at a or b are not certain, or the brackets are not narrow and
    /// apart (module doc).
    fn plan(&self, funs: &[Fun], a: f64, b: f64, m: f64, h: f64) -> Option<Plan> {
        // Each function's values at a and b, and its root's bracket, if any: (t1, t2,
        // which function, its values at t1 and t2).
        let (mut at_a, mut at_b) = ([Ball::exact(0.0); FEW], [Ball::exact(0.0); FEW]);
        let mut cuts = [(0.0, 0.0, 0usize, Ball::exact(0.0), Ball::exact(0.0)); FEW];
        let mut nc = 0;
        for (j, &f) in funs.iter().enumerate() {
            if !signed(self.slope(f, m, h)) {
                return None;
            }
            (at_a[j], at_b[j]) = (self.eval(f, a).0, self.eval(f, b).0);
            let (sa, sb) = (sign(at_a[j])?, sign(at_b[j])?);
            if sa != sb {
                let tol = self.eps * (1.0 / 64.0);
                let (t1, t2, f1, f2) =
                    bracket(|t| self.eval(f, t), a, b, m, self.eps, tol, sa, sb)?;
                if t2 - t1 > 2.0 * self.eps {
                    return None;
                }
                cuts[nc] = (t1, t2, j, f1, f2);
                nc += 1;
            }
        }
        let cuts = &mut cuts[..nc];
        cuts.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        if cuts.windows(2).any(|w| w[0].1 >= w[1].0) {
            return None;
        }
        let np = 2 * nc + 2;
        let mut plan = Plan {
            at: [0.0; PIECES + 1],
            vals: [[Ball::exact(0.0); FEW]; PIECES + 1],
            np,
            roots: [Fun::Slab(0); FEW],
        };
        (plan.at[0], plan.vals[0]) = (a, at_a);
        (plan.at[np - 1], plan.vals[np - 1]) = (b, at_b);
        for (c, &(t1, t2, own, f1, f2)) in cuts.iter().enumerate() {
            plan.roots[c] = funs[own];
            for (p, t, v) in [(2 * c + 1, t1, f1), (2 * c + 2, t2, f2)] {
                plan.at[p] = t;
                for (j, &f) in funs.iter().enumerate() {
                    plan.vals[p][j] = if j == own { v } else { self.eval(f, t).0 };
                }
            }
        }
        Some(plan)
    }

    /// The shortcut (module doc) on [a, b] (centre m, half width h) whose summary is
    /// `sum` and whose remaining candidates are `child`. `None` when it does not decide
    /// every sub-piece: the caller then halves [a, b].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn few(
        &mut self,
        a: f64,
        b: f64,
        m: f64,
        h: f64,
        sum: &Summary,
        child: Cands,
        out: &mut impl Pieces,
    ) -> Option<bool> {
        let funs = sum.few.list()?;
        let k = funs.len();
        let Plan {
            at,
            vals,
            np,
            roots,
        } = self.plan(funs, a, b, m, h)?;
        // The functions' ranges on [at[p], at[p + 1]].
        let over = |p: usize| {
            let mut o = [(Fun::Slab(0), Ball::exact(0.0)); FEW];
            for (j, &f) in funs.iter().enumerate() {
                o[j] = (f, hull(vals[p][j], vals[p + 1][j]));
            }
            o
        };
        let state_a = self.state;
        let mut class = [Class::Unsure; PIECES];
        let mut touched = [false; PIECES];
        let mut states = [State::Unknown; PIECES];
        for s in (0..np - 1).step_by(2) {
            if s > 0 && (touched[s - 2] || (sum.touching && !slab(roots[s / 2 - 1]))) {
                // Contacts before, or (where some edge may be touched on [a, b]) a
                // bracket before, in which a crossing may hide: the winding number may
                // have changed.
                self.state = State::Unknown;
            }
            let (mid, half) = centre(at[s], at[s + 1]);
            let (piece, _) = self.assess(mid, half, child, &over(s)[..k], false);
            class[s] = self.settle(&piece, mid);
            touched[s] = piece.touching;
            states[s] = self.state;
            if class[s] == Class::Unsure {
                self.state = state_a;
                return None;
            }
        }
        // A bracket joins its sides when both are decided alike and it is itself (as a
        // change of reason, from "within D" to "inside", or a crossing above the slab).
        // Without a contact on the bracket, the state found on a neighbouring sub-piece
        // without one is the bracket's (no winding number changes between them).
        for s in (1..np - 1).step_by(2) {
            if class[s - 1] == class[s + 1] {
                let (mid, half) = centre(at[s], at[s + 1]);
                let (piece, _) = self.assess(mid, half, child, &over(s)[..k], false);
                // A side decided without the winding number (within D of an edge, say)
                // leaves it unknown: take the other side's, or compute it on the
                // bracket itself, constant there as no edge may be touched.
                let known =
                    |j: usize| (!touched[j] && states[j] != State::Unknown).then_some(states[j]);
                let state = if piece.touching {
                    State::Unknown
                } else {
                    known(s + 1)
                        .or_else(|| known(s - 1))
                        .unwrap_or_else(|| self.winding(mid))
                };
                if self.classify(&piece, state) == class[s + 1] {
                    class[s] = class[s + 1];
                }
            }
        }
        if touched[np - 2] {
            self.state = State::Unknown;
        }
        // Send the pieces, runs of one class as one.
        let mut from = a;
        for s in 0..np - 1 {
            if s + 1 < np - 1 && class[s + 1] == class[s] {
                continue;
            }
            if self.emit(out, from, at[s + 1], class[s]) {
                return Some(true);
            }
            from = at[s + 1];
        }
        Some(false)
    }
}

/// A slab line (whose root changes no winding number).
fn slab(f: Fun) -> bool {
    matches!(f, Fun::Slab(_))
}
