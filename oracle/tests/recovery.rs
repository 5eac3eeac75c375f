//! The exact minimum of `recovery` is not above the distance of any feasible point:
//! points drawn about s (half of them just beyond the float value of m, where a missed
//! candidate would show) that meet the condition, exactly, are all at least m away
//! (m ≤ an upper bound of |x − s|).

use std::cmp::Ordering;

use polyguard_oracle::convert::{q, tower_to_f64};
use polyguard_oracle::recovery::{
    recovery_in, recovery_out, satisfies_in, satisfies_out, ExactMin, ExactRecovery, Point,
};
use polyguard_oracle::Q;

fn pts(p: &[[f64; 2]]) -> Vec<Point> {
    p.iter().map(|a| pt(*a)).collect()
}

fn pt(a: [f64; 2]) -> Point {
    [q(a[0]).expect("finite"), q(a[1]).expect("finite")]
}

fn approx(m: &ExactMin) -> f64 {
    m.cands
        .iter()
        .map(|(t, d2)| tower_to_f64(t, d2).max(0.0).sqrt())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn no_feasible_point_is_nearer_than_the_minimum() {
    let polys: [&[[f64; 2]]; 3] = [
        &[
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 3.0],
            [2.3, 3.0],
            [2.0, 1.0],
            [1.7, 3.0],
            [0.0, 3.0],
        ],
        &[[0.0, 0.0], [3.0, 0.5], [2.5, 2.0], [0.2, 1.5]],
        &[[0.0, 0.0], [4.0, 0.0], [0.5, 1.0]],
    ];
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let zero = Q::from_integer(0.into());
    for p in polys {
        let pe = pts(p);
        for (s, d) in [([2.0, 1.5], 0.4), ([1.0, 0.4], 0.3), ([3.5, 0.2], 0.2)] {
            let (se, de) = (pt(s), q(d).expect("finite"));
            for out in [true, false] {
                let ex = if out {
                    recovery_out(&pe, &se, &de)
                } else {
                    recovery_in(&pe, &se, &de)
                };
                let Some(ExactRecovery::Min(m)) = ex else {
                    continue;
                };
                if m.zero {
                    continue;
                }
                let near = approx(&m);
                for k in 0..600 {
                    let rad = if k % 2 == 0 {
                        3.0 * next()
                    } else {
                        near * (1.0 + 0.1 * next())
                    };
                    let ang = std::f64::consts::TAU * next();
                    let x = [s[0] + rad * ang.cos(), s[1] + rad * ang.sin()];
                    let meets = if out {
                        satisfies_out(&pe, &[], &zero, &pt(x), &de)
                    } else {
                        satisfies_in(&pe, &[], &zero, &pt(x), &de)
                    };
                    if !meets {
                        continue;
                    }
                    let dist = ((x[0] - s[0]).powi(2) + (x[1] - s[1]).powi(2)).sqrt();
                    // An upper bound of the exact |x − s|: a few roundings, 2⁻⁵⁰ covers them.
                    let hi = q(dist * (1.0 + 2f64.powi(-50))).expect("finite");
                    assert_ne!(
                        m.cmp_rational(&hi),
                        Ordering::Greater,
                        "{p:?} {s:?} {d} {out}"
                    );
                }
            }
        }
    }
}

/// The exact order of m against r, from an answer (`None` for impossible).
fn order(ex: &ExactRecovery, r: &Q) -> Option<Ordering> {
    match ex {
        ExactRecovery::Min(m) => Some(m.cmp_rational(r)),
        ExactRecovery::Impossible => None,
    }
}

/// The interval front (enclosed signs, the per-edge gaps, the candidates dropped once a
/// feasible one is nearer) changes no answer: on star-shaped polygons (spikes, thin
/// parts, moving), impossible agrees, and m compares the same with rationals at and a
/// hair about every candidate distance of the exact-only run, where a dropped minimum or
/// a wrongly kept candidate would show.
#[test]
fn the_interval_front_gives_the_exact_answers() {
    use polyguard_oracle::recovery::recovery_with;
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut compared = 0;
    for case in 0..16 {
        let n = 3 + case % 5;
        let spiky = case % 3 == 0;
        let p: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * (k as f64 + 0.4 * next()) / n as f64;
                let r = if spiky && k % 2 == 1 {
                    0.3 + 0.2 * next()
                } else {
                    1.0 + 2.0 * next()
                };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let vels: Vec<Point> = (0..n).map(|_| pt([next() - 0.5, next() - 0.5])).collect();
        let t = q(0.5 * next()).expect("finite");
        let s = pt([4.0 * next() - 2.0, 4.0 * next() - 2.0]);
        let d = q(0.05 + 0.6 * next()).expect("finite");
        let pe = pts(&p);
        let moving = case % 2 == 1;
        let mv = moving.then_some((vels.as_slice(), &t));
        for keep_in in [false, true] {
            let slow = recovery_with(&pe, mv, &s, &d, keep_in, false);
            let fast = recovery_with(&pe, mv, &s, &d, keep_in, true);
            let (Some(slow), Some(fast)) = (slow, fast) else {
                panic!("case {case}: a scene refused");
            };
            let mut probes = vec![Q::from_integer(0.into())];
            match &slow {
                ExactRecovery::Min(m) if !m.zero => {
                    for (tw, d2) in &m.cands {
                        let v = tower_to_f64(tw, d2).max(0.0).sqrt();
                        for f in [1.0 - 1e-12, 1.0, 1.0 + 1e-12] {
                            probes.push(q(v * f).expect("finite"));
                        }
                    }
                }
                ExactRecovery::Min(_) => {}
                ExactRecovery::Impossible => {
                    assert!(
                        matches!(fast, ExactRecovery::Impossible),
                        "case {case}: impossible only without the front"
                    );
                }
            }
            if let (ExactRecovery::Min(a), ExactRecovery::Min(b)) = (&slow, &fast) {
                assert_eq!(a.zero, b.zero, "case {case}: s feasible differs");
                assert!(b.cands.len() <= a.cands.len());
            }
            for r in &probes {
                assert_eq!(
                    order(&slow, r),
                    order(&fast, r),
                    "case {case} keep_in {keep_in}: m against {r}"
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 150, "only {compared} comparisons");
}
