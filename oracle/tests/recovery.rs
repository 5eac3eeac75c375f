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
