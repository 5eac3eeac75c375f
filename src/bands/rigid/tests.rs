//! The fast path on hand-worked segments, and against the scan: a decision of the fast
//! path never contradicts one of the scan, and a scan it skips could not have decided.

use super::*;
use crate::ball::round_down;
use crate::intervals::{Class, Pieces, Relation, Scan, Separation, Workspace};
use proptest::prelude::*;

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}

/// The square [−a, a]², counterclockwise.
fn square(a: f64) -> Vec<Vect2> {
    vec![v(-a, -a), v(a, -a), v(a, a), v(-a, a)]
}

#[test]
fn a_path_passing_four_from_a_square() {
    // y = 5 passes the square [−1, 1]² at distance 4.
    let p = square(1.0);
    let g = Rigid::new(&p, Vect2::ZERO, v(-10.0, 5.0), v(1.0, 0.0), 20.0).expect("finite");
    assert_eq!(g.judge(3.9, Some(3.0), 0.0).tri, Tri::No);
    assert_eq!(g.judge(4.5, Some(4.1), 0.0).tri, Tri::Yes);
    // Between: within 4.5 somewhere (the Clear scan cannot decide), never within 3.5
    // (nor can the near scan).
    let j = g.judge(4.5, Some(3.5), 0.0);
    assert_eq!(j.tri, Tri::Unsure);
    assert!(!j.scan_clear && !j.scan_conflict);
}

#[test]
fn a_path_through_a_square_is_deep_inside() {
    let p = square(1.0);
    let g = Rigid::new(&p, Vect2::ZERO, v(-10.0, 0.0), v(1.0, 0.0), 20.0).expect("finite");
    // r > D: deeper than 0.3 at the square's centre.
    assert_eq!(g.judge(0.7, None, 0.3).tri, Tri::Yes);
    // Never deeper than 1: no witness, and the scans stay available.
    let j = g.judge(1.5, None, 1.0);
    assert_eq!(j.tri, Tri::Unsure);
    assert!(!j.scan_clear && j.scan_conflict);
}

#[test]
fn a_square_moving_with_the_point_keeps_its_distance() {
    // V = w: the relative path is the point (5, 0), 4 from the square.
    let p = square(1.0);
    let w = v(0.3, -0.7);
    let g = Rigid::new(&p, w, v(5.0, 0.0), w, 10.0).expect("finite");
    assert_eq!(g.judge(3.0, Some(2.0), 0.0).tri, Tri::No);
    assert_eq!(g.judge(4.5, Some(4.25), 0.0).tri, Tri::Yes);
}

/// Did every piece fail (stopping at the first that does not)?
struct AllFail(bool);

impl Pieces for AllFail {
    fn piece(&mut self, _a: f64, _b: f64, class: Class) -> bool {
        if class != Class::Fails {
            self.0 = false;
        }
        !self.0
    }
}

/// Was there a piece of this class?
struct Find(Class, bool);

impl Pieces for Find {
    fn piece(&mut self, _a: f64, _b: f64, class: Class) -> bool {
        self.1 = class == self.0;
        self.1
    }
}

/// The scan's run with `out` (false when the scan refuses the case).
fn scan(c: &Case, relation: Relation, d: f64, ws: &mut Workspace, out: &mut impl Pieces) -> bool {
    let vels = vec![c.vel; c.p.len()];
    match Scan::new(
        c.t,
        c.s,
        c.w,
        &c.p,
        &vels,
        None,
        relation,
        Separation { d, h: 0.0 },
        ws.parts(),
    ) {
        Some(mut s) => {
            s.run(out);
            true
        }
        None => false,
    }
}

#[derive(Debug)]
struct Case {
    p: Vec<Vect2>,
    vel: Vect2,
    s: Vect2,
    w: Vect2,
    t: f64,
    d: f64,
    r: f64,
}

prop_compose! {
    fn case()(
        radii in prop::collection::vec(0.0..1.0f64, 3..9),
        size in 1.0..10.0f64,
        vel in (-2.0..2.0f64, -2.0..2.0f64),
        s in (-15.0..15.0f64, -15.0..15.0f64),
        w in (-8.0..8.0f64, -8.0..8.0f64),
        t in 0.5..12.0f64,
        d in prop_oneof![Just(0.0), 0.0..6.0f64],
        r in prop_oneof![Just(0.0), 0.0..8.0f64],
    ) -> Case {
        let n = radii.len();
        let p = radii.iter().enumerate().map(|(i, f)| {
            let a = core::f64::consts::TAU * i as f64 / n as f64;
            let rr = size * (0.4 + 0.6 * f);
            v(rr * a.cos(), rr * a.sin())
        }).collect();
        Case { p, vel: v(vel.0, vel.1), s: v(s.0, s.1), w: v(w.0, w.1), t, d, r }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    /// Fast Clear ⇒ the scan finds no conflict; fast Conflict ⇒ the scan is not Clear;
    /// a scan the fast path skips does not decide.
    #[test]
    fn the_fast_path_never_contradicts_the_scan(c in case()) {
        agree(&c)?;
    }

    /// The same at the boundary: D within a relative 10⁻¹³ of σ̃'s float distance to P
    /// (r = 0), where the rounding bounds decide.
    #[test]
    fn the_fast_path_agrees_at_the_boundary(c in case(), f in -1e-13..1e-13f64) {
        let g = Rigid::new(&c.p, c.vel, c.s, c.w, c.t).expect("finite");
        let (lam, j) = g.shape().near;
        let y = g.s + (g.e - g.s).scale(lam);
        let md = seg_dist2(y, c.p[j], c.p[(j + 1) % c.p.len()]).0.sqrt();
        agree(&Case { d: md * (1.0 + f), r: 0.0, ..c })?;
    }
}

/// The property of both tests for one case.
fn agree(c: &Case) -> Result<(), TestCaseError> {
    {
        let g = Rigid::new(&c.p, c.vel, c.s, c.w, c.t).expect("finite");
        let reach = round_up(c.d + c.r);
        let near = (c.r <= c.d).then(|| round_down(c.d - c.r).max(0.0));
        let deep = round_up(c.r - c.d);
        let j = g.judge(reach, near, deep);
        let mut ws = Workspace::new();
        let mut all = AllFail(true);
        let scan_clear = scan(c, Relation::Near, reach, &mut ws, &mut all) && all.0;
        let scan_conflict = match near {
            Some(nd) => {
                let mut f = Find(Class::Holds, false);
                scan(c, Relation::Near, nd, &mut ws, &mut f) && f.1
            }
            None => {
                let mut f = Find(Class::Fails, false);
                scan(c, Relation::Breach, deep, &mut ws, &mut f) && f.1
            }
        };
        match j.tri {
            Tri::No => prop_assert!(!scan_conflict, "fast Clear, scan Conflict"),
            Tri::Yes => prop_assert!(!scan_clear, "fast Conflict, scan Clear"),
            Tri::Unsure => {
                prop_assert!(j.scan_clear || !scan_clear, "skipped a deciding Clear scan");
                prop_assert!(
                    j.scan_conflict || !scan_conflict,
                    "skipped a deciding Conflict scan"
                );
            }
        }
    }
    Ok(())
}
