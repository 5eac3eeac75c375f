//! The two exact backends (num-rational and rug/GMP) give identical answers.
#![cfg(feature = "rug")]

mod common;

use proptest::prelude::*;

use common::{cases, gen_case};
use polyguard_oracle::detect::{dot_nn_lin, Interval, Sign};
use polyguard_oracle::qfield::Alg;
use polyguard_oracle::truth::ExactTime;
use polyguard_oracle::well_formed::well_formed;
use polyguard_oracle::{
    detect_exit_of, intervals_of, paper_detect, truth, Arith, Decided, Exact, ExactField, Relation,
    Separation, Q, R, V2,
};

fn iv_key<F: ExactField>(i: &Interval<Alg<F>>) -> Option<(ExactTime, ExactTime)> {
    match i {
        Interval::Empty => None,
        Interval::Closed { lb, ub } => Some((ExactTime::from_alg(lb), ExactTime::from_alg(ub))),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(128)))]

    #[test]
    fn same_answers(seed in any::<u64>()) {
        let g = gen_case(seed);
        let a = g.exact::<Q>();
        let b = g.exact::<R>();
        prop_assert_eq!(a.is_ok(), b.is_ok());
        if let (Ok(a), Ok(b)) = (a, b) {
            prop_assert_eq!(paper_detect(&a), paper_detect(&b));
            prop_assert_eq!(truth(&a), truth(&b));
            let k = Q::from_i64(99).quotient(&Q::from_i64(100)).unwrap_or_else(<Q as Arith>::one);
            let kr = R::from_i64(99).quotient(&R::from_i64(100)).unwrap_or_else(<R as Arith>::one);
            prop_assert_eq!(well_formed(&a.vertices, &a.buff, &k), well_formed(&b.vertices, &b.buff, &kr));
        }
    }

    // The exact sets of times and exit detection: the same components, exactly.
    #[test]
    fn same_intervals(seed in any::<u64>(), which in 0u64..6) {
        let g = gen_case(seed);
        let (Ok(a), Ok(b)) = (g.exact::<Q>(), g.exact::<R>()) else { return Ok(()) };
        let d = [0i64, 1][(which % 2) as usize];
        let sq = Separation { d: Q::from_i64(d), h: Q::from_i64(1) };
        let sr = Separation { d: R::from_i64(d), h: R::from_i64(1) };
        let rel = [Relation::Inside, Relation::Near, Relation::Breach][(which / 2) as usize];
        prop_assert_eq!(intervals_of(&a, rel, &sq), intervals_of(&b, rel, &sr));
        prop_assert_eq!(detect_exit_of(&a, &sq), detect_exit_of(&b, &sr));
    }

    #[test]
    fn same_dot_nn_lin(c in proptest::collection::vec(-50i64..50, 9), sigma in prop_oneof![Just(Sign::Neg), Just(Sign::Pos)]) {
        let vq = |i: usize| V2::new(Q::from_i64(c[i]), Q::from_i64(c[i + 1]));
        let vr = |i: usize| V2::new(R::from_i64(c[i]), R::from_i64(c[i + 1]));
        let tq = Q::from_i64(c[8].abs());
        let tr = R::from_i64(c[8].abs());
        let a = dot_nn_lin(&Exact, &tq, &vq(0), &vq(2), &vq(4), &vq(6), sigma).decided();
        let b = dot_nn_lin(&Exact, &tr, &vr(0), &vr(2), &vr(4), &vr(6), sigma).decided();
        prop_assert_eq!(iv_key(&a), iv_key(&b));
    }
}

#[test]
fn conversions_agree() {
    use polyguard_oracle::convert::{f64_to_exact, parse_rational};
    for x in [
        0.1,
        -2.5,
        1e-300,
        -7.25e200,
        5e-324,
        0.0,
        -0.0,
        123456789.125,
    ] {
        let a: Option<Q> = f64_to_exact(x);
        let b: Option<R> = f64_to_exact(x);
        assert_eq!(a, b.map(|r| r.to_big()), "{x}");
    }
    for s in ["-3/4", "12345678901234567890123/7", "-1.25", "0"] {
        let a: Option<Q> = parse_rational(s);
        let b: Option<R> = parse_rational(s);
        assert_eq!(a, b.map(|r| r.to_big()), "{s}");
    }
}
