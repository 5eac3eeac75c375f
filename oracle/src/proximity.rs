//! Paper A §II.G: are two segments within BUFF of each other?

use crate::contain::near_edge;
use crate::field::{Arith, V2};
use crate::kernel::{any_of, certainly, or, Kernel};
use crate::quad::quad_min_box_le_d;

/// Paper A §II.G: segments_close — is segment c d within BUFF of segment e f?
pub fn segments_close<N: Arith, K: Kernel<N>>(
    k: &K,
    c: &V2<N>,
    d: &V2<N>,
    e: &V2<N>,
    f: &V2<N>,
    buff: &N,
) -> Result<bool, K::Abstain> {
    // Steps 1–2: an end point near the other segment.
    let ends = any_of!(
        near_edge(k, e, f, c, buff),
        near_edge(k, e, f, d, buff),
        near_edge(k, c, d, e, buff),
        near_edge(k, c, d, f, buff),
    );
    if certainly(ends) {
        return ends;
    }
    // Steps 3–4: ‖q + r·u − t·w‖² on the unit box, q = c − e, u = d − c, w = f − e.
    or(ends, || {
        let q = c.minus(e);
        let u = d.minus(c);
        let w = f.minus(e);
        quad_min_box_le_d(
            k,
            &u.sq(),
            &w.sq(),
            &u.dot(&w).twice().negated(),
            &q.dot(&u).twice(),
            &q.dot(&w).twice().negated(),
            &q.sq(),
            &buff.sq(),
        )
    })
}
