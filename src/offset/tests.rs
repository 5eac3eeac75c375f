//! Hand cases of the offset and the inset (paper A §II's polygon grown and shrunk).

use super::*;

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}

fn area(ring: &[Vect2]) -> f64 {
    let n = ring.len();
    0.5 * (0..n)
        .map(|i| ring[i].x * ring[(i + 1) % n].y - ring[i].y * ring[(i + 1) % n].x)
        .sum::<f64>()
}

fn total_area(o: &Offset) -> f64 {
    o.regions
        .iter()
        .map(|r| area(&r.outer) + r.holes.iter().map(|h| area(h)).sum::<f64>())
        .sum()
}

fn square(s: f64) -> Vec<Vect2> {
    std::vec![v(0.0, 0.0), v(s, 0.0), v(s, s), v(0.0, s)]
}

#[test]
fn a_squares_offset_lies_between_the_buffer_and_its_grown_copy() {
    let (s, d, eps) = (2.0, 0.5, 0.01);
    let o = offset(&square(s), d, eps).expect("certified");
    assert_eq!(o.regions.len(), 1);
    assert!(o.regions[0].holes.is_empty());
    let a = total_area(&o);
    let pi = core::f64::consts::PI;
    let buffer = s * s + 4.0 * s * d + pi * d * d;
    let de = d * (1.0 + eps);
    let grown = s * s + 4.0 * s * de + pi * de * de;
    assert!(buffer <= a && a <= grown, "{buffer} ≤ {a} ≤ {grown}");
}

#[test]
fn a_squares_inset_is_the_smaller_square() {
    let o = inset(&square(4.0), 1.0, 0.01).expect("certified");
    assert_eq!(o.regions.len(), 1);
    let a = total_area(&o);
    // Between the inset at D(1 + ε) and at D: (4 − 2·1.01)² ≤ a ≤ (4 − 2)².
    assert!((4.0 - 2.02f64).powi(2) <= a && a <= 4.0, "{a}");
}

#[test]
fn an_inset_deeper_than_the_inradius_is_empty() {
    let o = inset(&square(2.0), 1.5, 0.01).expect("an answer");
    assert!(o.regions.is_empty());
}

#[test]
fn a_dumbbells_inset_splits_in_two() {
    // Two 4 × 4 squares joined by a 4 × 1 corridor: inset by 1 leaves two squares.
    let p = std::vec![
        v(0.0, 0.0),
        v(4.0, 0.0),
        v(4.0, 1.5),
        v(8.0, 1.5),
        v(8.0, 0.0),
        v(12.0, 0.0),
        v(12.0, 4.0),
        v(8.0, 4.0),
        v(8.0, 2.5),
        v(4.0, 2.5),
        v(4.0, 4.0),
        v(0.0, 4.0),
    ];
    let o = inset(&p, 1.0, 0.01).expect("certified");
    assert_eq!(o.regions.len(), 2, "{o:?}");
}

/// A C whose mouth (width 1) closes when grown by 1: the offset has a hole.
fn c_shape() -> Vec<Vect2> {
    std::vec![
        v(0.0, 0.0),
        v(10.0, 0.0),
        v(10.0, 4.5),
        v(9.0, 4.5),
        v(9.0, 1.0),
        v(1.0, 1.0),
        v(1.0, 9.0),
        v(9.0, 9.0),
        v(9.0, 5.5),
        v(10.0, 5.5),
        v(10.0, 10.0),
        v(0.0, 10.0),
    ]
}

#[test]
fn a_closing_c_has_a_hole() {
    let o = offset(&c_shape(), 1.0, 0.01).expect("certified");
    assert_eq!(o.regions.len(), 1);
    assert_eq!(o.regions[0].holes.len(), 1, "{o:?}");
    // Grown by 0.3 the mouth stays open: no hole.
    let open = offset(&c_shape(), 0.3, 0.01).expect("certified");
    assert!(open.regions.iter().all(|r| r.holes.is_empty()));
}

#[test]
fn a_sharp_spike_is_rounded_not_cut() {
    // A thin spike: its tip's buffer reaches D beyond the tip along the spike's axis.
    let p = std::vec![v(0.0, 0.0), v(10.0, 0.5), v(0.0, 1.0)];
    let d = 1.0;
    let o = offset(&p, d, 0.01).expect("certified");
    let tip = v(10.0 + d, 0.5);
    let outer = &o.regions[0].outer;
    let reach = outer.iter().map(|q| q.x).fold(f64::MIN, f64::max);
    assert!(reach >= tip.x, "{reach}");
    assert!(reach <= 10.0 + d * 1.01 + 1e-9 * 10.0, "{reach}");
}

#[test]
fn arguments_outside_their_domain_name_their_field() {
    let sq = square(1.0);
    let field = |r: Result<Offset, OffsetError>| match r {
        Err(OffsetError::Invalid { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(field(offset(&sq, -1.0, 0.1)), "d");
    assert_eq!(field(offset(&sq, f64::NAN, 0.1)), "d");
    assert_eq!(field(inset(&sq, 1.0, 0.0)), "eps");
    assert_eq!(
        field(offset_at(&sq, &[Vect2::ZERO; 3], 0.0, 1.0, 0.1)),
        "vels"
    );
    assert_eq!(
        field(offset_at(&sq, &[Vect2::ZERO; 4], f64::INFINITY, 1.0, 0.1)),
        "t"
    );
    let mut cw = sq.clone();
    cw.reverse();
    assert_eq!(field(offset(&cw, 1.0, 0.1)), "p");
    assert!(matches!(
        offset(&sq, 1.0, 1e-30),
        Err(OffsetError::TooFine { .. })
    ));
}

#[test]
fn a_moving_square_is_offset_where_it_is_at_t() {
    let vels = [v(1.0, 0.5); 4];
    let o = offset_at(&square(2.0), &vels, 3.0, 0.5, 0.01).expect("certified");
    let outer = &o.regions[0].outer;
    let min_x = outer.iter().map(|q| q.x).fold(f64::MAX, f64::min);
    assert!((3.0 - 0.5 * 1.01..=3.0 - 0.5).contains(&min_x), "{min_x}");
    let i = inset_at(&square(2.0), &vels, 3.0, 0.5, 0.01).expect("certified");
    assert_eq!(i.regions.len(), 1);
}

#[test]
fn straight_and_repeated_vertices_are_one_polygon() {
    let p = std::vec![
        v(0.0, 0.0),
        v(1.0, 0.0),
        v(2.0, 0.0),
        v(2.0, 0.0),
        v(2.0, 2.0),
        v(0.0, 2.0),
        v(0.0, 1.3),
    ];
    let o = offset(&p, 0.5, 0.01).expect("certified");
    let s = offset(&square(2.0), 0.5, 0.01).expect("certified");
    assert!((total_area(&o) - total_area(&s)).abs() <= 1e-9 * total_area(&s));
    let i = inset(&p, 0.5, 0.01).expect("certified");
    assert_eq!(i.regions.len(), 1);
}

/// The certificate itself: a mitred square (corners √2·D out) is not close, a square
/// with cut corners (1/√2·D from the corners) is not clear, the true offset's
/// construction is both. (The mitred square stands 1.001·D off: edges exactly at D
/// are within rounding of the bound and not certified, by design.)
#[test]
fn the_certificate_rejects_mitred_and_cut_corners() {
    let sq = square(2.0);
    let bounds = certify::Bounds::new(1.0, 0.01, 0.0);
    let one = |outer: Vec<Vect2>| {
        std::vec![Region {
            outer,
            holes: Vec::new(),
        }]
    };
    let (lo, hi) = (-1.001, 3.001);
    let mitred = one(std::vec![v(lo, lo), v(hi, lo), v(hi, hi), v(lo, hi)]);
    assert_eq!(
        certify::certify(&sq, &mitred, &bounds, Side::Out),
        Err(OffsetError::Uncertified {
            reason: "an edge of the result is farther than D·(1 + ε) from P"
        })
    );
    let cut = one(std::vec![
        v(0.0, -1.0),
        v(2.0, -1.0),
        v(3.0, 0.0),
        v(3.0, 2.0),
        v(2.0, 3.0),
        v(0.0, 3.0),
        v(-1.0, 2.0),
        v(-1.0, 0.0),
    ]);
    assert_eq!(
        certify::certify(&sq, &cut, &bounds, Side::Out),
        Err(OffsetError::Uncertified {
            reason: "an edge of the result is closer than D to P"
        })
    );
    // The inset of a square as a hand-made square: certified; shifted outside P, not.
    let (a, b) = (0.501, 1.499);
    let inner = one(std::vec![v(a, a), v(b, a), v(b, b), v(a, b)]);
    let half = certify::Bounds::new(0.5, 0.01, 0.0);
    assert_eq!(certify::certify(&sq, &inner, &half, Side::In), Ok(()));
    let outside = one(std::vec![
        v(3.0, 0.5),
        v(4.0, 0.5),
        v(4.0, 1.5),
        v(3.0, 1.5)
    ]);
    assert!(certify::certify(&sq, &outside, &half, Side::In).is_err());
    let ok = offset(&sq, 1.0, 0.01).expect("certified");
    assert_eq!(
        certify::certify(&sq, &ok.regions, &bounds, Side::Out),
        Ok(())
    );
}

/// A ring of the result inside P is refused even where every distance test passes: P
/// is a strip 2.005·D wide, and a thin clockwise ring along its middle line is at least D
/// from both long edges and within D·(1 + ε) of one of them. Added to the true offset as
/// a hole, it would cut points of P out of Q.
#[test]
fn the_certificate_rejects_a_ring_inside_p() {
    let strip = std::vec![v(0.0, 0.0), v(20.0, 0.0), v(20.0, 2.005), v(0.0, 2.005)];
    let bounds = certify::Bounds::new(1.0, 0.01, 0.0);
    let mut q = offset(&strip, 1.0, 0.01).expect("certified").regions;
    assert_eq!(certify::certify(&strip, &q, &bounds, Side::Out), Ok(()));
    let (y0, y1) = (1.0005, 1.0045);
    q[0].holes
        .push(std::vec![v(1.5, y0), v(1.5, y1), v(18.0, y1), v(18.0, y0)]);
    assert_eq!(
        certify::certify(&strip, &q, &bounds, Side::Out),
        Err(OffsetError::Uncertified {
            reason: "a ring of the offset lies inside P"
        })
    );
}
