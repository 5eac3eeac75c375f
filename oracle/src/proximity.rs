//! Paper A §II.G: are two segments within BUFF of each other?

use crate::contain::near_edge;
use crate::field::{ExactField, V2};
use crate::quad::quad_min_box_le_d;

/// Paper A §II.G: segments_close — is segment c d within BUFF of segment e f?
pub fn segments_close<F: ExactField>(c: &V2<F>, d: &V2<F>, e: &V2<F>, f: &V2<F>, buff: &F) -> bool {
    // Steps 1–2: an end point near the other segment.
    if near_edge(e, f, c, buff)
        || near_edge(e, f, d, buff)
        || near_edge(c, d, e, buff)
        || near_edge(c, d, f, buff)
    {
        return true;
    }
    // Steps 3–4: ‖q + r·u − t·w‖² on the unit box, q = c − e, u = d − c, w = f − e.
    let q = c.minus(e);
    let u = d.minus(c);
    let w = f.minus(e);
    let uw = u.dot(&w);
    let qu = q.dot(&u);
    let qw = q.dot(&w);
    quad_min_box_le_d(
        &u.sq(),
        &w.sq(),
        &uw.plus(&uw).negated(),
        &qu.plus(&qu),
        &qw.plus(&qw).negated(),
        &q.sq(),
        &buff.sq(),
    )
}
