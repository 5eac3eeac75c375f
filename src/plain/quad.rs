//! Paper A §I: does a quadratic dip below a threshold D on the unit interval / unit box?

use super::predicates as pr;

pub use crate::quad::{quad, quad2d};

/// Paper A §I quad_min_le_D: is there a t ∈ [0, 1] with a·t² + b·t + c < D?
///
/// Step 1 tests the ends (quad(0) = c, quad(1) = a + b + c); step 2 the vertex
/// t* = −b/(2a) when a > 0 and t* ∈ [0, 1], whose value c − b²/(4a) is below D exactly
/// when b² − 4a(c − D) > 0 (the printed "b² 4a(c D) > 0" lost its minus signs).
#[inline]
pub fn quad_min_le_d(a: f64, b: f64, c: f64, d: f64) -> bool {
    pr::value_below(c, d) || pr::value_below(a + b + c, d) || pr::interior_min_below(a, b, c, d)
}

/// Paper A §I quad_min_box_le_D: are there r, t ∈ [0, 1] with quad2D(a,…,f)(r, t) < D?
///
/// Steps 1–4 restrict to the four sides of the box (t = 1, t = 0, r = 1, r = 0); steps
/// 5–6 test the critical point r = mx/disc, t = my/disc with disc = c² − 4ab,
/// mx = 2bd − ce, my = 2ae − cd (solving ∂/∂r = 2ar + ct + d = 0 and
/// ∂/∂t = 2bt + cr + e = 0). The printed "0 < my·disc < disc²" is read as the closed
/// test, as for mx: the box is closed.
#[inline]
pub fn quad_min_box_le_d(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, dd: f64) -> bool {
    quad_min_le_d(a, c + d, quad(b, e, f, 1.0), dd)
        || quad_min_le_d(a, d, f, dd)
        || quad_min_le_d(b, c + e, quad(a, d, f, 1.0), dd)
        || quad_min_le_d(b, e, f, dd)
        || pr::box_interior_min_below(a, b, c, d, e, f, dd)
}
