//! Keep-in exits worked out by hand, and the closed form against the breach scan.

use super::*;
use crate::intervals::intervals;
use proptest::prelude::*;

/// breach_D somewhere in [0, T], from the spans of the interval scan: `Yes` when a span
/// is certain, `No` when there is none.
fn scan_exit(
    t: f64,
    s: Vect2,
    v: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    z: Option<Heights>,
    sep: Separation,
) -> Tri {
    let spans = intervals(t, s, v, p, vels, z, Relation::Breach, sep);
    if spans.iter().any(|sp| sp.certain) {
        Tri::Yes
    } else if spans.is_empty() {
        Tri::No
    } else {
        Tri::Unsure
    }
}

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}

fn square(d: f64) -> Vec<Vect2> {
    vec![v(0.0, 0.0), v(d, 0.0), v(d, d), v(0.0, d)]
}

fn sep(d: f64) -> Separation {
    Separation { d, h: 0.0 }
}

/// Both ways of answering for a statically shaped polygon must agree where certain.
fn both(
    t: f64,
    s: Vect2,
    vel: Vect2,
    p: &[Vect2],
    vels: &[Vect2],
    z: Option<Heights>,
    d: Separation,
) -> Tri {
    let closed = exit(t, s, vel, p, vels, z, d, true);
    let halving = exit(t, s, vel, p, vels, z, d, false);
    let scan = scan_exit(t, s, vel, p, vels, z, d);
    let clash = |x: Tri, y: Tri| matches!((x, y), (Tri::Yes, Tri::No) | (Tri::No, Tri::Yes));
    assert!(
        !clash(closed, scan) && !clash(closed, halving) && !clash(halving, scan),
        "closed form {closed:?}, edge halving {halving:?}, interval scan {scan:?}"
    );
    closed
}

#[test]
fn deep_inside_stays_and_heading_out_exits() {
    let p = square(4.0);
    let still = [Vect2::ZERO; 4];
    // From the centre east at 0.5: x = 2 + t/2, within D = 1 of the east edge from t = 2.
    let (s, east) = (v(2.0, 2.0), v(0.5, 0.0));
    assert_eq!(both(1.5, s, east, &p, &still, None, sep(1.0)), Tri::No);
    assert_eq!(both(10.0, s, east, &p, &still, None, sep(1.0)), Tri::Yes);
    // Exactly at D at t = T = 2: a distance equal to D is an exit (closed); f64 may not
    // certify the tie, but it must not deny it.
    assert_ne!(both(2.0, s, east, &p, &still, None, sep(1.0)), Tri::No);
    assert!(detect_exit(2.0, s, east, &p, &still, None, sep(1.0)));
    // At rest, or with D = 0 and never reaching the boundary: stays.
    assert_eq!(
        both(10.0, s, Vect2::ZERO, &p, &still, None, sep(1.0)),
        Tri::No
    );
    assert_eq!(both(3.9, s, east, &p, &still, None, sep(0.0)), Tri::No);
    // Outside at t = 0: out of the fence from the start.
    assert_eq!(
        both(1.0, v(5.0, 2.0), Vect2::ZERO, &p, &still, None, sep(0.0)),
        Tri::Yes
    );
}

#[test]
fn a_drifting_fence_leaves_a_point_at_rest() {
    // The fence drifts east at 0.5; the point rests at its centre: the west edge, at
    // x = t/2, is within D = 1 of x = 2 from t = 2.
    let p = square(4.0);
    let drift = [v(0.5, 0.0); 4];
    let s = v(2.0, 2.0);
    assert_eq!(
        both(1.5, s, Vect2::ZERO, &p, &drift, None, sep(1.0)),
        Tri::No
    );
    assert_eq!(
        both(2.5, s, Vect2::ZERO, &p, &drift, None, sep(1.0)),
        Tri::Yes
    );
    // Moving with it: stays.
    assert_eq!(
        both(100.0, s, v(0.5, 0.0), &p, &drift, None, sep(1.0)),
        Tri::No
    );
}

#[test]
fn a_warping_fence_closes_in() {
    // The east edge moves west at 0.5 (x = 4 − t/2): within D = 1 of the centre from
    // t = 2.
    let p = square(4.0);
    let vels = [Vect2::ZERO, v(-0.5, 0.0), v(-0.5, 0.0), Vect2::ZERO];
    let s = v(2.0, 2.0);
    assert_eq!(
        detect_exit_tri(1.5, s, Vect2::ZERO, &p, &vels, None, sep(1.0)),
        Tri::No
    );
    assert_eq!(
        detect_exit_tri(2.5, s, Vect2::ZERO, &p, &vels, None, sep(1.0)),
        Tri::Yes
    );
}

#[test]
fn the_slab_ends_are_fences_too() {
    // Climbing at 1 from z = 5 in the slab [0, 10] with H = 1: out of the fence at z = 9.
    let p = square(4.0);
    let still = [Vect2::ZERO; 4];
    let z = Heights {
        sz: 5.0,
        vz: 1.0,
        bottom: 0.0,
        top: 10.0,
        vsp: 0.0,
    };
    let sep = Separation { d: 1.0, h: 1.0 };
    let s = v(2.0, 2.0);
    assert_eq!(both(3.5, s, Vect2::ZERO, &p, &still, Some(z), sep), Tri::No);
    assert_eq!(
        both(4.5, s, Vect2::ZERO, &p, &still, Some(z), sep),
        Tri::Yes
    );
    // Exactly at the shrunk ceiling at T = 4: not denied.
    assert_ne!(both(4.0, s, Vect2::ZERO, &p, &still, Some(z), sep), Tri::No);
}

#[test]
fn a_graze_of_the_fence_from_inside_is_not_denied() {
    // Inside an L of arms 6 wide, the path (4.75, 5.375) + t·(0.5, −0.375) is tangent at
    // t = 1 to the circle of radius 1.25 about the reflex corner (6, 6): at distance
    // exactly D from the boundary there, farther before and after.
    let l = vec![
        v(0.0, 0.0),
        v(12.0, 0.0),
        v(12.0, 6.0),
        v(6.0, 6.0),
        v(6.0, 12.0),
        v(0.0, 12.0),
    ];
    let still = [Vect2::ZERO; 6];
    let (s, vel) = (v(4.75, 5.375), v(0.5, -0.375));
    assert_ne!(both(2.0, s, vel, &l, &still, None, sep(1.25)), Tri::No);
    assert_eq!(both(2.0, s, vel, &l, &still, None, sep(1.2)), Tri::No);
    assert_eq!(both(2.0, s, vel, &l, &still, None, sep(1.3)), Tri::Yes);
}

#[test]
fn out_of_domain_is_unsure() {
    let p = square(4.0);
    let still = [Vect2::ZERO; 4];
    let s = v(2.0, 2.0);
    for d in [-1.0, f64::NAN] {
        assert_eq!(
            detect_exit_tri(1.0, s, Vect2::ZERO, &p, &still, None, sep(d)),
            Tri::Unsure
        );
    }
    assert_eq!(
        detect_exit_tri(f64::NAN, s, Vect2::ZERO, &p, &still, None, sep(1.0)),
        Tri::Unsure
    );
    assert_eq!(
        detect_exit_tri(1.0, s, Vect2::ZERO, &p[..2], &still, None, sep(1.0)),
        Tri::Unsure
    );
}

proptest! {
    /// For statically shaped polygons the closed form, the edges' halving and the
    /// interval scan of breach_D are three certified answers to one question: they never
    /// contradict each other. For warping ones (radially, so they stay simple), the
    /// halving and the scan.
    #[test]
    fn the_closed_form_never_contradicts_the_scan(
        radii in proptest::collection::vec(1.0f64..4.0, 3..9),
        sx in -3.0f64..3.0, sy in -3.0f64..3.0,
        vx in -1.0f64..1.0, vy in -1.0f64..1.0,
        dx in -1.0f64..1.0, dy in -1.0f64..1.0,
        t in 0.0f64..5.0, d in 0.0f64..1.5,
    ) {
        let n = radii.len();
        let p: Vec<Vect2> = radii
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let a = k as f64 / n as f64 * core::f64::consts::TAU;
                v(r * a.cos(), r * a.sin())
            })
            .collect();
        let vels = vec![v(dx, dy); n];
        both(t, v(sx, sy), v(vx, vy), &p, &vels, None, sep(d));
        let warp: Vec<Vect2> = p.iter().map(|q| v(dx, dy) + q.scale(0.05)).collect();
        let halving = detect_exit_tri(t, v(sx, sy), v(vx, vy), &p, &warp, None, sep(d));
        let scan = scan_exit(t, v(sx, sy), v(vx, vy), &p, &warp, None, sep(d));
        prop_assert!(
            !matches!((halving, scan), (Tri::Yes, Tri::No) | (Tri::No, Tri::Yes)),
            "warping: edge halving {halving:?}, interval scan {scan:?}"
        );
    }
}
