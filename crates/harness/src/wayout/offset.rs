//! One engine offset or inset (paper A §II's polygon grown or shrunk by D) checked
//! against the oracle's exact verdict: the call a hunt (`assure`) makes for each drawn
//! case.

use polyguard::offset::Offset;
use polyguard::Vect2;
use polyguard_oracle::offset::{self as exact, Buffer, Region, Side, Verdict};
use polyguard_oracle::OracleError;

/// The engine's regions as the oracle's (f64 points, unchanged).
pub fn regions_of(result: &Offset) -> Vec<Region<f64>> {
    let pts = |r: &[Vect2]| r.iter().map(|v| [v.x, v.y]).collect::<Vec<_>>();
    result
        .regions
        .iter()
        .map(|r| Region {
            outer: pts(&r.outer),
            holes: r.holes.iter().map(|h| pts(h)).collect(),
        })
        .collect()
}

fn ring(p: &[Vect2]) -> Vec<[f64; 2]> {
    p.iter().map(|v| [v.x, v.y]).collect()
}

/// The exact problem of `side` (offset or inset) of P by D with ε, for a static P.
pub fn problem(p: &[Vect2], d: f64, eps: f64, side: Side) -> Result<Buffer, OracleError> {
    match side {
        Side::Out => exact::offset(&ring(p), d, eps),
        Side::In => exact::inset(&ring(p), d, eps),
    }
}

/// The exact problem at time t of the moving polygon p_i + t·V_i.
pub fn problem_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    d: f64,
    eps: f64,
    side: Side,
) -> Result<Buffer, OracleError> {
    let (p, vels) = (ring(p), ring(vels));
    match side {
        Side::Out => exact::offset_at(&p, &vels, t, d, eps),
        Side::In => exact::inset_at(&p, &vels, t, d, eps),
    }
}

/// The oracle's exact verdict on one engine result for a static P (see
/// `polyguard_oracle::offset` for what each part decides).
pub fn check(
    p: &[Vect2],
    d: f64,
    eps: f64,
    side: Side,
    result: &Offset,
) -> Result<Verdict, OracleError> {
    problem(p, d, eps, side)?.check(&regions_of(result))
}

/// [`check`] at time t of the moving polygon p_i + t·V_i (the engine's `offset_at` or
/// `inset_at` result).
pub fn check_at(
    p: &[Vect2],
    vels: &[Vect2],
    t: f64,
    d: f64,
    eps: f64,
    side: Side,
    result: &Offset,
) -> Result<Verdict, OracleError> {
    problem_at(p, vels, t, d, eps, side)?.check(&regions_of(result))
}

/// Exact sampling of what the boundary cannot show (a filled hole, a missed piece): on
/// an n × n grid over the box of P grown by 2·D(1 + ε), every point of the true set at D
/// (offset) or at D(1 + ε) (inset) must be in the result, and every point of the result
/// in the true set at D(1 + ε) (offset) or at D (inset). The first point that fails.
pub fn sample(
    problem: &Buffer,
    result: &Offset,
    n: usize,
) -> Result<Option<[f64; 2]>, OracleError> {
    let rings = exact::exact_rings(&regions_of(result))?;
    let p: Vec<[f64; 2]> = problem
        .p
        .iter()
        .map(|v| {
            [
                polyguard_oracle::convert::to_float(&v.x),
                polyguard_oracle::convert::to_float(&v.y),
            ]
        })
        .collect();
    let reach = 2.0 * polyguard_oracle::convert::to_float(&problem.limit());
    let lo = p
        .iter()
        .fold([f64::MAX; 2], |m, v| [m[0].min(v[0]), m[1].min(v[1])]);
    let hi = p
        .iter()
        .fold([f64::MIN; 2], |m, v| [m[0].max(v[0]), m[1].max(v[1])]);
    let steps = n.max(2) - 1;
    for i in 0..=steps {
        for j in 0..=steps {
            let f = |k: usize, a: f64, b: f64| {
                a - reach + (b - a + 2.0 * reach) * k as f64 / steps as f64
            };
            let x = [f(i, lo[0], hi[0]), f(j, lo[1], hi[1])];
            let xq = exact::exact_point(x)?;
            let inside = exact::locate_in(&rings, &xq);
            let (must_in, may_in) = match problem.side {
                Side::Out => (problem.inside_truth(&xq), problem.inside_limit(&xq)),
                Side::In => (problem.inside_limit(&xq), problem.inside_truth(&xq)),
            };
            if (must_in && !inside) || (inside && !may_in) {
                return Ok(Some(x));
            }
        }
    }
    Ok(None)
}
