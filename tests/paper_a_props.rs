//! Properties of the f64 engine on well-separated cases: the answer is known by
//! construction and must not change under exact rigid motions of the whole case.
//!
//! Construction: a star-shaped counterclockwise polygon around a centre c, vertex radii in
//! [r_in, r_out], angular gaps below 2π/3 (so it contains the disc of radius 0.28·r_in), all
//! vertices drifting with a common velocity u plus a warp δ_i with |δ_i|·T ≤ r_in/8 (so
//! within [0, T] it keeps containing the disc of radius 0.15·r_in around c + t·u and stays
//! within r_out + r_in/8 of it). A "hit" point passes through c + t0·u at t0 ∈ (0, T);
//! a "miss" point keeps a distance ≥ 3·r_out from it at all times. Coordinates are
//! multiples of 2⁻¹⁰ below 2²⁰, so translating by integers and rotating by 90° are exact.

use polyguard::api::{detect, Case, MovingPoint, MovingPolygon, Params};
use polyguard::detect::Method;
use polyguard::Vect2;
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(256)
}

fn dyadic(x: f64) -> f64 {
    (x * 1024.0).round() / 1024.0
}

#[derive(Clone, Debug)]
struct Built {
    verts: Vec<Vect2>,
    vels: Vec<Vect2>,
    s: Vect2,
    v: Vect2,
    t: f64,
    hit: bool,
}

prop_compose! {
    fn built()(
        n in 3usize..12,
        seed_angles in prop::collection::vec(0.2f64..1.0, 12),
        radii in prop::collection::vec(0.0f64..1.0, 12),
        warp in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 12),
        warping in any::<bool>(),
        c in (-500.0f64..500.0, -500.0f64..500.0),
        u in (-2.0f64..2.0, -2.0f64..2.0),
        r_in in 1.0f64..50.0,
        spread in 1.0f64..3.0,
        t in 1.0f64..300.0,
        t0_frac in 0.1f64..0.9,
        dir in 0.0f64..std::f64::consts::TAU,
        speed in 0.5f64..5.0,
        hit in any::<bool>(),
        side in prop::bool::ANY,
    ) -> Built {
        let r_out = r_in * spread;
        // Angles: random gaps mixed with the uniform gap, so each gap γ is at most
        // 0.2·(1/1.4) + 0.8/3 < 0.41 of a turn. The triangle (c, p_i, p_i+1) then contains
        // the sector of the disc of radius r_in·cos(γ/2) ≥ 0.28·r_in.
        let gaps: Vec<f64> = seed_angles[..n].to_vec();
        let total: f64 = gaps.iter().sum();
        let mut theta: f64 = 0.0;
        let mut verts = Vec::with_capacity(n);
        let c = Vect2::new(dyadic(c.0), dyadic(c.1));
        for i in 0..n {
            let g = 0.2 * gaps[i] / total + 0.8 / n as f64;
            let r = r_in + (r_out - r_in) * radii[i];
            verts.push(Vect2::new(dyadic(c.x + r * theta.cos()), dyadic(c.y + r * theta.sin())));
            theta += g * std::f64::consts::TAU;
        }
        let u = Vect2::new(dyadic(u.0), dyadic(u.1));
        let max_warp = r_in / 8.0 / t;
        let vels = (0..n)
            .map(|i| {
                if warping {
                    // |δ| ≤ max_warp/√2·√2 after rounding down to the dyadic grid.
                    let d = Vect2::new(warp[i].0, warp[i].1).scale(max_warp / 2.0);
                    Vect2::new(u.x + (d.x * 1024.0).trunc() / 1024.0, u.y + (d.y * 1024.0).trunc() / 1024.0)
                } else {
                    u
                }
            })
            .collect();
        let v = Vect2::new(dyadic(speed * dir.cos()), dyadic(speed * dir.sin()));
        let t = dyadic(t).max(1.0);
        let t0 = t * t0_frac;
        let rel = v - u;
        // Hit: s + t0·v = c + t0·u. Miss: shift that path sideways by 4·r_out·(1 + ‖rel‖)
        // perpendicular to the relative velocity (or anywhere if it is zero).
        let mut s = c - rel.scale(t0);
        if !hit {
            let nrm = rel.sq().sqrt();
            let perp = if nrm > 0.0 { rel.perp().scale(1.0 / nrm) } else { Vect2::new(1.0, 0.0) };
            let k = if side { 1.0 } else { -1.0 };
            s = s + perp.scale(k * 4.0 * r_out);
        }
        Built { verts, vels, s: Vect2::new(dyadic(s.x), dyadic(s.y)), v, t, hit }
    }
}

fn answer(b: &Built) -> (bool, Method) {
    let poly = MovingPolygon::new(b.verts.clone(), Some(b.vels.clone())).expect("valid polygon");
    let pt = MovingPoint::new_2d(b.s, b.v).expect("valid point");
    let case = Case::new(b.t, pt, poly, Params::new(0.01).expect("buff")).expect("valid case");
    let d = detect(&case);
    (d.detected, d.method)
}

fn map(b: &Built, f: impl Fn(Vect2) -> Vect2, g: impl Fn(Vect2) -> Vect2) -> Built {
    Built {
        verts: b.verts.iter().map(|&p| f(p)).collect(),
        vels: b.vels.iter().map(|&p| g(p)).collect(),
        s: f(b.s),
        v: g(b.v),
        t: b.t,
        hit: b.hit,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn separated_answers_are_right_and_invariant(b in built(), dx in -1000i32..1000, dy in -1000i32..1000, shift in 0usize..12) {
        let (got, method) = answer(&b);
        prop_assert_eq!(got, b.hit, "original ({:?})", method);
        let rot = |p: Vect2| Vect2::new(-p.y, p.x);
        prop_assert_eq!(answer(&map(&b, rot, rot)).0, b.hit, "rotated by 90°");
        let half = |p: Vect2| Vect2::new(-p.x, -p.y);
        prop_assert_eq!(answer(&map(&b, half, half)).0, b.hit, "rotated by 180°");
        let tr = |p: Vect2| Vect2::new(p.x + dx as f64, p.y + dy as f64);
        prop_assert_eq!(answer(&map(&b, tr, |v| v)).0, b.hit, "translated by ({}, {})", dx, dy);
        let k = shift % b.verts.len();
        let mut rolled = b.clone();
        rolled.verts.rotate_left(k);
        rolled.vels.rotate_left(k);
        prop_assert_eq!(answer(&rolled).0, b.hit, "vertices renumbered from {}", k);
    }
}
