//! Engine against the exact oracle on boundary-biased cases: the safety property
//! "truth enters ⇒ the engine detects" (a failure is a missed detection), and the paper's
//! own theorem in exact arithmetic "truth enters ⇒ paper-exact detects".
//!
//! Cases put the point exactly at, or a few ulps / a relative 10⁻¹⁵…10⁻³ inside or
//! outside of, the BUFF band around an edge or a vertex, send it through vertices and
//! along edges, and make first contact happen at t = 0 or t = T. Coordinates are offset
//! by up to 10⁶ with small polygons.

use polyguard::api::{detected, Case, MovingPoint, MovingPolygon, Params};
use polyguard::Vect2;
use polyguard_oracle::{paper_detect, truth, CaseF64, ExactCase, Truth, Q};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("POLYGUARD_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(128)
}

#[derive(Clone, Debug)]
struct Raw {
    verts: Vec<[f64; 2]>,
    vels: Vec<[f64; 2]>,
    s: [f64; 2],
    v: [f64; 2],
    t: f64,
    buff: f64,
}

/// ε: zero, a few ulps (as a relative step), or 10⁻¹⁵ … 10⁻³, either sign.
fn eps() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        (-4i32..=4).prop_map(|k| k as f64 * f64::EPSILON),
        (-15i32..=-3, any::<bool>()).prop_map(|(e, neg)| if neg {
            -(10f64.powi(e))
        } else {
            10f64.powi(e)
        }),
    ]
}

prop_compose! {
    fn raw()(
        n in 3usize..9,
        radii in prop::collection::vec(0.5f64..1.0, 9),
        jitter in prop::collection::vec(0.0f64..1.0, 9),
        scale in prop::sample::select(vec![1.0, 10.0, 1000.0]),
        offset in prop::sample::select(vec![0.0, 1e3, 1e6]),
        warp in any::<bool>(),
        wv in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 9),
        drift in (-1.0f64..1.0, -1.0f64..1.0),
        edge_pick in 0usize..9,
        along in 0.0f64..1.0,
        mode in 0u8..5,
        e in eps(),
        buff_rel in prop::sample::select(vec![1e-2, 1e-4, 1e-7]),
        t in 1.0f64..300.0,
        dir in 0.0f64..std::f64::consts::TAU,
        speed in 0.0f64..3.0,
    ) -> Raw {
        let tau = std::f64::consts::TAU;
        let verts: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let a = tau * (i as f64 + 0.4 * jitter[i]) / n as f64;
                [offset + scale * radii[i] * a.cos(), offset + scale * radii[i] * a.sin()]
            })
            .collect();
        let buff = scale * buff_rel;
        let vels: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let w = if warp { 0.1 * scale / t } else { 0.0 };
                [drift.0 * scale / t + w * wv[i].0, drift.1 * scale / t + w * wv[i].1]
            })
            .collect();
        let i = edge_pick % n;
        let j = (i + 1) % n;
        let (pi, pj) = (Vect2::from(verts[i]), Vect2::from(verts[j]));
        let d = pj - pi;
        let out = d.perp().scale(1.0 / d.sq().sqrt()); // outward normal (CCW polygon)
        let v = Vect2::new(dir.cos(), dir.sin()).scale(speed * scale / t);
        let (s, v) = match mode {
            // At BUFF·(1 + ε) outside an edge, moving anywhere.
            0 => (pi + d.scale(along) + out.scale(buff * (1.0 + e)), v),
            // At BUFF·(1 + ε) from a vertex, along the bisector-ish outward direction.
            1 => (pi + (out - d.scale(1.0 / d.sq().sqrt())).scale(buff * (1.0 + e) / 2f64.sqrt()), v),
            // Through a vertex at t = T·(0.5 + ε) in the polygon's frame.
            2 => {
                let tc = t * (0.5 + e);
                let vi = Vect2::from(vels[i]);
                let target = pi + vi.scale(tc);
                (target - v.scale(tc), v)
            }
            // Moving along an edge's line, BUFF·ε outside it.
            3 => {
                let vi = Vect2::from(vels[i]);
                let start = pi - d.scale(0.5) + out.scale(buff * e.abs());
                (start, vi + d.scale(2.0 / t))
            }
            // First contact with an edge at t = T·(1 + ε), coming straight in.
            _ => {
                let vi = Vect2::from(vels[i]);
                let vin = out.scale(-speed.max(0.1) * scale / t);
                let hit = pi + d.scale(along);
                (hit - vin.scale(t * (1.0 + e)), vi + vin)
            }
        };
        Raw { verts, vels, s: [s.x, s.y], v: [v.x, v.y], t, buff }
    }
}

fn engine(r: &Raw) -> Option<bool> {
    let poly = MovingPolygon::new(
        r.verts.iter().map(|&p| p.into()).collect(),
        Some(r.vels.iter().map(|&p| p.into()).collect()),
    )
    .ok()?;
    let pt = MovingPoint::new_2d(r.s.into(), r.v.into()).ok()?;
    let case = Case::new(r.t, pt, poly, Params::new(r.buff).ok()?).ok()?;
    Some(detected(&case))
}

fn exact(r: &Raw) -> Option<(bool, Truth)> {
    let c = CaseF64 {
        lookahead: r.t,
        buff: r.buff,
        fac: 1e-4,
        pos: &r.s,
        vel: &r.v,
        vertices: &r.verts,
        velocities: &r.vels,
        slab: None,
    };
    let e = ExactCase::<Q>::from_f64(&c).ok()?;
    Some((paper_detect(&e).detected, truth(&e)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn truth_enters_implies_engine_and_paper_detect(r in raw()) {
        let Some(got) = engine(&r) else { return Ok(()) };
        let Some((paper, tr)) = exact(&r) else { return Ok(()) };
        if let Truth::Enters { entry_time } = tr {
            prop_assert!(paper, "paper gap: truth enters at {} but paper-exact says no", entry_time.to_decimal_string(20));
            prop_assert!(got, "missed detection: truth enters at {} but the engine says no", entry_time.to_decimal_string(20));
        }
    }
}
