//! Arbitrary f64 (NaN, ±∞, subnormals, huge) into the public API and into the raw paper
//! functions on slices: neither may panic. The API must reject every non-finite input
//! with a typed error; the raw functions take anything and answer something.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use polyguard::api::{self, Case, MovingPoint, MovingPolygon, Params};
use polyguard::detect::{dot_nn, slab_window, statically_shaped};
use polyguard_harness::case::RawCase;
use polyguard::{
    definitely_outside, detect_3d, detect_diff_2d, detect_same_2d, dot_nn_lin, edge_detect,
    edge_detect_simp, near_edge, num_cross, perturb, quad_min_box_le_d, quad_min_le_d,
    segments_close, well_formed, Sign, Vect2,
};
use polyguard_fuzz::Num;

/// Vertices used at most (well_formed is quadratic in them).
const MAX_VERTICES: usize = 24;

#[derive(Arbitrary, Debug)]
struct Input {
    lookahead: Num,
    buff: Num,
    fac: Option<Num>,
    kappa: Option<Num>,
    pos: (Num, Num),
    vel: (Num, Num),
    z: Option<(Num, Num)>,
    slab: Option<(Num, Num, Num)>,
    vertices: Vec<(Num, Num)>,
    velocities: Option<Vec<(Num, Num)>>,
    /// Operands of the raw scalar functions.
    k: [Num; 16],
    sigma: bool,
}

fn v2(p: (Num, Num)) -> Vect2 {
    Vect2::new(p.0 .0, p.1 .0)
}

fn api_case(inp: &Input) -> Option<Case> {
    let verts: Vec<Vect2> = inp
        .vertices
        .iter()
        .take(MAX_VERTICES)
        .map(|&p| v2(p))
        .collect();
    let vels = inp
        .velocities
        .as_ref()
        .map(|vs| vs.iter().take(MAX_VERTICES).map(|&p| v2(p)).collect());
    let mut poly = MovingPolygon::new(verts, vels).ok()?;
    if let Some((b, t, z)) = inp.slab {
        poly = poly.with_slab(b.0, t.0, z.0).ok()?;
    }
    let point = match inp.z {
        None => MovingPoint::new_2d(v2(inp.pos), v2(inp.vel)).ok()?,
        Some((sz, vz)) => MovingPoint::new_3d(
            [inp.pos.0 .0, inp.pos.1 .0, sz.0],
            [inp.vel.0 .0, inp.vel.1 .0, vz.0],
        )
        .ok()?,
    };
    let mut params = Params::new(inp.buff.0).ok()?;
    if let Some(f) = inp.fac {
        params = params.with_fac(f.0).ok()?;
    }
    if let Some(k) = inp.kappa {
        params = params.with_kappa(k.0).ok()?;
    }
    Case::new(inp.lookahead.0, point, poly, params).ok()
}

fn raw_functions(inp: &Input) {
    let k: Vec<f64> = inp.k.iter().map(|n| n.0).collect();
    let p = |i: usize| Vect2::new(k[i % 16], k[(i + 1) % 16]);
    let sigma = if inp.sigma { Sign::Pos } else { Sign::Neg };
    let _ = quad_min_le_d(k[0], k[1], k[2], k[3]);
    let _ = quad_min_box_le_d(k[0], k[1], k[2], k[3], k[4], k[5], k[6]);
    let _ = near_edge(p(0), p(2), p(4), k[6]);
    let _ = segments_close(p(0), p(2), p(4), p(6), k[8]);
    let _ = perturb(p(0), p(2), k[4]);
    let i = dot_nn_lin(k[0], p(1), p(3), p(5), p(7), sigma);
    let _ = i.is_empty();
    let _ = dot_nn(k[0], p(1), p(3), p(5), p(7), sigma, sigma.flip(), k[9]);
    let _ = edge_detect_simp(k[0], p(1), p(3), p(5), p(7), k[9]);
    let _ = edge_detect(k[0], p(1), p(3), p(5), p(7), p(9), p(11), k[13]);
    let _ = slab_window(k[0], k[1], k[2], k[3], k[4], k[5]);

    // Polygon functions on raw slices of equal length (the documented precondition).
    let verts: Vec<Vect2> = inp
        .vertices
        .iter()
        .take(MAX_VERTICES)
        .map(|&q| v2(q))
        .collect();
    let vels: Vec<Vect2> = match &inp.velocities {
        Some(vs) => (0..verts.len())
            .map(|i| vs.get(i).map_or(Vect2::ZERO, |&q| v2(q)))
            .collect(),
        None => vec![Vect2::ZERO; verts.len()],
    };
    let (s, v) = (v2(inp.pos), v2(inp.vel));
    let (t, buff, fac) = (inp.lookahead.0, inp.buff.0, inp.fac.map_or(1e-4, |f| f.0));
    let _ = num_cross(&verts[..], s);
    let _ = definitely_outside(&verts[..], s, buff);
    let _ = well_formed(&verts[..], buff, k[10]);
    let _ = statically_shaped(&vels[..]);
    let _ = detect_same_2d(t, s, v, &verts[..], &vels[..], buff);
    let _ = detect_diff_2d(t, s, v, &verts[..], &vels[..], fac, buff);
    let _ = detect_3d(
        t,
        s,
        v,
        k[11],
        k[12],
        &verts[..],
        &vels[..],
        k[13],
        k[14],
        k[15],
        buff,
        fac,
    );
}

fuzz_target!(|inp: Input| {
    if let Some(case) = api_case(&inp) {
        let d = api::detect(&case);
        assert_eq!(
            d.detected,
            api::detected(&case),
            "detect and detected disagree"
        );
        assert_eq!(d.method, case.method());
        // A validated case survives the case format's fields bit for bit (κ is not one
        // of them: RawCase always uses the default).
        if inp.kappa.is_none() {
            let back = RawCase::from_api(&case).to_api();
            assert_eq!(
                back.as_ref().ok(),
                Some(&case),
                "RawCase round trip: {back:?}"
            );
        }
    }
    raw_functions(&inp);
});
