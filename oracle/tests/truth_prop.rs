//! The ground truth against direct sampling: at sampled rational times, the
//! point is in the closed polygon (exact point-in-polygon) exactly as the truth
//! says — never before the entry time, at the entry time when it is rational,
//! and never at all for a miss.

mod common;

use core::cmp::Ordering;

use proptest::prelude::*;

use common::{cases, gen_case};
use polyguard_oracle::truth::in_closed_polygon;
use polyguard_oracle::{truth, Arith, Decided, Exact, ExactCase, ExactField, Truth, Q, V2};

fn inside_at(c: &ExactCase<Q>, t: &Q) -> bool {
    if let Some(z) = &c.vertical {
        let h = z.sz.plus(&z.vz.times(t));
        if h < z.bottom.plus(&z.vsp.times(t)) || h > z.top.plus(&z.vsp.times(t)) {
            return false;
        }
    }
    let poly: Vec<V2<Q>> = c
        .vertices
        .iter()
        .zip(&c.velocities)
        .map(|(p, w)| p.at(w, t))
        .collect();
    in_closed_polygon(&Exact, &poly, &c.s.at(&c.v, t)).decided()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(256)))]

    #[test]
    fn truth_agrees_with_sampling(seed in any::<u64>()) {
        let g = gen_case(seed);
        let Ok(c) = g.exact::<Q>() else { return Ok(()) };
        let t = truth(&c);
        let steps = 32i64;
        let samples: Vec<Q> = (0..=steps)
            .filter_map(|k| c.lookahead.times(&Q::from_i64(k)).quotient(&Q::from_i64(steps)))
            .collect();
        match &t {
            Truth::Undefined { .. } => {}
            Truth::Misses => {
                for s in &samples {
                    prop_assert!(!inside_at(&c, s), "miss, but inside at {s}: {g:?}");
                }
            }
            Truth::Enters { entry_time } => {
                prop_assert!(entry_time.cmp_rational(&c.lookahead.to_big()) != Ordering::Greater);
                prop_assert!(entry_time.cmp_rational(&Q::from_i64(0)) != Ordering::Less);
                for s in &samples {
                    if entry_time.cmp_rational(s) == Ordering::Greater {
                        prop_assert!(!inside_at(&c, s), "inside at {s} before the entry {entry_time}: {g:?}");
                    }
                }
                if entry_time.is_rational() {
                    prop_assert!(inside_at(&c, entry_time.rational_part()), "not inside at the entry {entry_time}: {g:?}");
                }
            }
        }
    }
}
