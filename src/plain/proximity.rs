//! Paper A §II.G: do two segments come within BUFF of each other?

use super::contain::near_edge;
use super::predicates as pr;
use super::quad::quad_min_box_le_d;
use crate::vect2::Vect2;

/// Paper A §II.G segments_close: is segment c d closer than BUFF to segment e f?
///
/// Steps 1–2 test the four ends with near_edge; step 4 asks quad_min_box_le_D whether
/// ‖(c + r·u) − (e + t·w)‖² = u²r² + w²t² − 2(u·w)rt + 2(q·u)r − 2(q·w)t + q² is below
/// BUFF² for some r, t ∈ [0, 1], with q = c − e, u = d − c, w = f − e.
#[inline]
pub fn segments_close(c: Vect2, d: Vect2, e: Vect2, f: Vect2, buff: f64) -> bool {
    // Filter: bounding boxes more than BUFF apart in x or y (see predicates::ranges_apart).
    let twice = 2.0 * buff;
    if pr::ranges_apart(
        c.x.min(d.x),
        c.x.max(d.x),
        e.x.min(f.x),
        e.x.max(f.x),
        twice,
    ) || pr::ranges_apart(
        c.y.min(d.y),
        c.y.max(d.y),
        e.y.min(f.y),
        e.y.max(f.y),
        twice,
    ) {
        return false;
    }
    // Filter: both ends of one segment beyond BUFF on one side of the other's line.
    if lines_separate(c, d, e, f, buff) || lines_separate(e, f, c, d, buff) {
        return false;
    }
    if near_edge(e, f, c, buff) || near_edge(e, f, d, buff) {
        return true;
    }
    if near_edge(c, d, e, buff) || near_edge(c, d, f, buff) {
        return true;
    }
    let q = c - e;
    let u = d - c;
    let w = f - e;
    quad_min_box_le_d(
        u.sq(),
        w.sq(),
        -2.0 * u.dot(w),
        2.0 * q.dot(u),
        -2.0 * q.dot(w),
        q.sq(),
        buff * buff,
    )
}

/// Are e and f both farther than `dist` from the line through c and d, on the same side?
/// Then no point of segment e f is within `dist` of segment c d.
#[inline(always)]
fn lines_separate(c: Vect2, d: Vect2, e: Vect2, f: Vect2, dist: f64) -> bool {
    let side = pr::line_side(c, d, e, dist);
    side != 0 && side == pr::line_side(c, d, f, dist)
}
