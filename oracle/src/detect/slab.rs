//! Paper A §III: detection for 3D polygons, detect_3D: the window in which the point is
//! in the polygon's slab, then the 2D detector over that window.

use core::cmp::Ordering;

use super::{detect_2d, dispatch};
use crate::field::{Arith, V2};
use crate::kernel::run::{Scene, Single};
use crate::kernel::{and, Kernel};

/// Paper A §III step 1: the window [a, b] ⊆ [0, T] where
/// pmin + t·vsp ≤ s_z + t·v_z ≤ pmax + t·vsp, or `None` when there is no such t.
pub fn slab_window<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    sz: &N,
    vz: &N,
    pmin: &N,
    pmax: &N,
    vsp: &N,
) -> Result<Option<(N, N)>, K::Abstain> {
    if k.lt(pmax, pmin)? {
        return Ok(None);
    }
    let w = vz.minus(vsp);
    let zero = N::zero();
    if k.sign(&w)? == Ordering::Equal {
        let inside = and(k.le(pmin, sz), || k.le(sz, pmax))?;
        return Ok(inside.then(|| (zero, t.clone())));
    }
    let (Some(t1), Some(t2)) = (pmin.minus(sz).quotient(&w), pmax.minus(sz).quotient(&w)) else {
        return Ok(None);
    };
    let (lo, hi) = if k.le(&t1, &t2)? { (t1, t2) } else { (t2, t1) };
    let a = if k.lt(&zero, &lo)? { lo } else { zero };
    let b = if k.lt(&hi, t)? { hi } else { t.clone() };
    Ok(if k.le(&a, &b)? { Some((a, b)) } else { None })
}

/// Paper A §III steps 1–2: the scene restarted at the slab window [a, b] (the point
/// at s + a·v, the polygon at P + a·V, lookahead b − a), `None` when the window is
/// empty.
pub(crate) fn slab_scene<'a, N: Arith, K: Kernel<N>>(
    k: &K,
    sc: &Scene<'a, N>,
    sz: &N,
    vz: &N,
    pmin: &N,
    pmax: &N,
    vsp: &N,
) -> Result<Option<Scene<'a, N>>, K::Abstain> {
    let window = slab_window(k, &sc.t, sz, vz, pmin, pmax, vsp)?;
    Ok(window.map(|(a, b)| sc.shifted(&a, b.minus(&a))))
}

/// Paper A §III: detect_3D — the slab window [a, b], then 2D detection from
/// s + a·v and P + a·V over lookahead b − a (detect_same_2D when all vertex
/// velocities are equal, detect_diff_2D otherwise). An empty window returns
/// false (the paper's text would run the 2D function with lookahead 0 − T).
pub fn detect_3d<N: Arith, K: Kernel<N>>(
    k: &K,
    t: &N,
    s: &V2<N>,
    v: &V2<N>,
    sz: &N,
    vz: &N,
    p: &[V2<N>],
    vels: &[V2<N>],
    pmin: &N,
    pmax: &N,
    vsp: &N,
    buff: &N,
    f: &N,
) -> Result<bool, K::Abstain> {
    let sc = Scene::new(t, s, v, p, vels, buff, f);
    match slab_scene(k, &sc, sz, vz, pmin, pmax, vsp)? {
        None => Ok(false),
        Some(window) => detect_2d(&Single::new(k, window), dispatch(k, false, vels)?),
    }
}
