//! The oracle's exact offset and inset checks (paper A §II's polygon grown and shrunk)
//! on hand-made results: a mitred square (contains the buffer, reaches too far), a
//! square with cut corners (misses the buffer), an inset square, and the arguments.

use polyguard_oracle::offset::{exact_point, inset, offset, offset_at, Region};

fn region(outer: &[[f64; 2]]) -> Region<f64> {
    Region {
        outer: outer.to_vec(),
        holes: Vec::new(),
    }
}

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];

#[test]
fn offset_the_mitred_square_contains_the_buffer_but_reaches_too_far() {
    let b = offset(&SQUARE, 1.0, 0.01).expect("valid");
    let mitred = region(&[[-1.0, -1.0], [3.0, -1.0], [3.0, 3.0], [-1.0, 3.0]]);
    let v = b.check(&[mitred]).expect("finite");
    assert!(v.rings && v.clear && !v.close, "{v:?}");
    // With ε = 1, L = 2 reaches the mitred corners (√2 from the square's).
    let wide = offset(&SQUARE, 1.0, 1.0).expect("valid");
    let mitred = region(&[[-1.0, -1.0], [3.0, -1.0], [3.0, 3.0], [-1.0, 3.0]]);
    assert!(wide.check(&[mitred]).expect("finite").holds());
}

#[test]
fn offset_a_square_cut_at_its_corners_misses_the_buffer() {
    let b = offset(&SQUARE, 1.0, 0.01).expect("valid");
    // The octagon through the edges' shifted copies, its corners cut at distance
    // 1/√2 < 1 from the square's corners.
    let cut = region(&[
        [0.0, -1.0],
        [2.0, -1.0],
        [3.0, 0.0],
        [3.0, 2.0],
        [2.0, 3.0],
        [0.0, 3.0],
        [-1.0, 2.0],
        [-1.0, 0.0],
    ]);
    let v = b.check(&[cut]).expect("finite");
    assert!(v.rings && !v.clear && v.close, "{v:?}");
}

#[test]
fn offset_the_inset_square_is_exact_and_the_wrong_way_round_is_not_a_ring() {
    let b = inset(&SQUARE, 0.5, 0.01).expect("valid");
    let inner = region(&[[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]);
    assert!(b
        .check(std::slice::from_ref(&inner))
        .expect("finite")
        .holds());
    let mut cw = inner.clone();
    cw.outer.reverse();
    assert!(!b.check(&[cw]).expect("finite").rings);
    // Too deep: closer than D to the boundary.
    let fat = region(&[[0.4, 0.4], [1.6, 0.4], [1.6, 1.6], [0.4, 1.6]]);
    assert!(!b.check(&[fat]).expect("finite").clear);
    // Points: the centre is in I_D, a point 0.3 from the boundary is not.
    let centre = exact_point([1.0, 1.0]).expect("finite");
    assert!(b.inside_truth(&centre) && b.inside_limit(&centre));
    assert!(!b.inside_truth(&exact_point([0.3, 1.0]).expect("finite")));
}

#[test]
fn offset_arguments_name_their_field() {
    assert_eq!(offset(&SQUARE, -1.0, 0.1).unwrap_err().field, "d");
    assert_eq!(inset(&SQUARE, 1.0, 0.0).unwrap_err().field, "eps");
    let mut cw = SQUARE;
    cw.reverse();
    assert_eq!(offset(&cw, 1.0, 0.1).unwrap_err().field, "p");
    assert_eq!(
        offset_at(&SQUARE, &[[0.0, 0.0]; 3], 1.0, 1.0, 0.1)
            .unwrap_err()
            .field,
        "vels"
    );
    let moved = offset_at(&SQUARE, &[[1.0, 0.0]; 4], 2.0, 1.0, 0.1).expect("valid");
    assert_eq!(moved.p[0], exact_point([2.0, 0.0]).expect("finite"));
}

/// The interval front of the point–segment test decides as the rationals do, at ties
/// too: points exactly at distance r from a segment (3-4-5 offsets from its ends and
/// its line), just inside and just outside, and random points, strict and not.
#[test]
fn segment_near_filtered_matches_exact_at_ties_and_elsewhere() {
    use polyguard_oracle::offset::segment_near;
    use polyguard_oracle::Q;
    let mut seed = 0x5851_f42d_4c95_7f2du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let p = |x: f64, y: f64| exact_point([x, y]).expect("finite");
    let (a, b) = (p(1.0, 1.0), p(9.0, 1.0));
    let r2 = Q::from_integer(25.into());
    let mut xs = vec![
        p(-2.0, 5.0),
        p(12.0, 5.0),
        p(5.0, 6.0),
        p(5.0, -4.0),
        p(1.0, 1.0),
    ];
    for x in [p(-2.0, 5.0), p(5.0, 6.0)] {
        for dy in [1e-12, -1e-12] {
            xs.push(V::new(
                x.x.clone(),
                &x.y + Q::from_float(dy).expect("finite"),
            ));
        }
    }
    for _ in 0..2000 {
        xs.push(p(20.0 * next() - 5.0, 14.0 * next() - 6.0));
    }
    let mut ties = 0;
    for x in &xs {
        for strict in [false, true] {
            let fast = segment_near(x, &a, &b, &r2, strict, true);
            let slow = segment_near(x, &a, &b, &r2, strict, false);
            assert_eq!(fast, slow, "x = {x:?} strict {strict}");
        }
        if segment_near(x, &a, &b, &r2, false, false) != segment_near(x, &a, &b, &r2, true, false) {
            ties += 1;
        }
    }
    assert_eq!(ties, 4, "the four points at distance exactly 5");
}

type V = polyguard_oracle::V2<polyguard_oracle::Q>;
