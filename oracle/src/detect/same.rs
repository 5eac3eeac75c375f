//! Paper A §II.H: detection for statically shaped polygons, detect_same_2D.

use super::Step;
use crate::field::{Arith, V2};
use crate::kernel::run::{Runner, Scene, Single};
use crate::kernel::{any, any_of, Kernel};

/// Paper A §II.H: detect_same_2D's steps, each run by `r`.
pub(super) fn same_2d<R: Runner>(r: &R) -> Result<bool, R::Abstain> {
    let n = r.count();
    if n == 0 {
        return Ok(false);
    }
    any_of!(
        r.run(&Step::Inside0),
        r.run(&Step::InsideT),
        any((0..n).map(|i| r.run(&Step::PathClose(i)))),
    )
}

/// Paper A §II.H: detect_same_2D for a statically shaped polygon (v_i of each edge used).
pub fn detect_same_2d<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    p: &[V2<N>],
    vels: &[V2<N>],
    buff: &N,
) -> Result<bool, K::Abstain> {
    // detect_same_2D has no F: the scene's F (here BUFF) is never read.
    same_2d(&Single::new(k, Scene::new(t, s, v, p, vels, buff, buff)))
}
