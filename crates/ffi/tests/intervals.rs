//! `pg_intervals` and `pg_detect_exit` on cases worked out by hand (docs/cases.md,
//! "Separation and fences": inside, near_D, breach_D; keep-in exits), their buffer
//! protocol, and their errors: the status, the message naming the C field, the
//! conservative answer written on an error.

use std::ffi::CStr;
use std::ptr;

use polyguard_ffi::*;

mod common;
use common::{message, polygon, v};

/// Parameters T and BUFF with the defaults of F and κ.
fn params(lookahead: f64, buff: f64) -> PgParams {
    let mut p = PgParams::default();
    // SAFETY: a valid out-pointer.
    assert_eq!(unsafe { pg_params_default(&mut p) }, PG_OK);
    p.lookahead = lookahead;
    p.buff = buff;
    p
}

/// A 2D point s + t·v.
fn point2(s: PgVec2, vel: PgVec2) -> PgPoint {
    PgPoint {
        pos: s,
        vel,
        ..PgPoint::default()
    }
}

/// The spans of one relation: the count asked for first (cap 0), then the answer into a
/// buffer of exactly that size.
fn spans(
    p: &PgParams,
    pt: &PgPoint,
    poly: &PgPolygon,
    relation: i32,
    sep: PgSeparation,
) -> Vec<PgSpan> {
    let mut n = usize::MAX;
    // SAFETY: valid pointers; cap 0 with out NULL asks for the count.
    let rc = unsafe { pg_intervals(p, pt, poly, relation, &sep, ptr::null_mut(), 0, &mut n) };
    assert!(
        rc == PG_OK && n == 0 || rc == PG_ERR_CAPACITY && n > 0,
        "count: status {rc}, {n} spans: {}",
        message()
    );
    let mut out = vec![PgSpan::default(); n];
    let mut m = 0;
    // SAFETY: out holds n spans.
    let rc = unsafe { pg_intervals(p, pt, poly, relation, &sep, out.as_mut_ptr(), n, &mut m) };
    assert_eq!(rc, PG_OK, "{}", message());
    assert_eq!(m, n);
    for s in &out {
        assert!(s.start_lo <= s.start_hi && s.start_hi <= s.end_lo && s.end_lo <= s.end_hi);
        assert!(0.0 <= s.start_lo && s.end_hi <= p.lookahead);
    }
    for w in out.windows(2) {
        assert!(w[0].end_hi <= w[1].start_lo, "{w:?}");
    }
    out
}

/// The span encloses [a, b], certain, each end within `tol` of its exact value.
fn assert_span(s: &PgSpan, a: f64, b: f64, tol: f64) {
    assert_eq!(s.certain, 1, "{s:?}");
    assert!(s.start_lo <= a && a <= s.start_hi, "start {a} not in {s:?}");
    assert!(s.end_lo <= b && b <= s.end_hi, "end {b} not in {s:?}");
    assert!(
        s.start_hi - s.start_lo <= tol && s.end_hi - s.end_lo <= tol,
        "{s:?}"
    );
}

const NONE: PgSeparation = PgSeparation { d: 0.0, h: 0.0 };

const SQUARE: [PgVec2; 4] = [
    PgVec2 { x: 0.0, y: 0.0 },
    PgVec2 { x: 2.0, y: 0.0 },
    PgVec2 { x: 2.0, y: 2.0 },
    PgVec2 { x: 0.0, y: 2.0 },
];

/// (1, −2) moving north at 1 across the 2×2 square at rest: inside on [2, 4]; within
/// D = 0.5 on [1.5, 4.5] (loss of separation at 1.5); breach_0.5 (not deeper than 0.5
/// inside) on [0, 2.5] and [3.5, 10], where the point is 0.5 from the bottom and top
/// edges (its x = 1 is 1 from the sides).
#[test]
fn the_square_crossing() {
    let p = params(10.0, 0.01);
    let pt = point2(v(1.0, -2.0), v(0.0, 1.0));
    let sq = polygon(&SQUARE, None);
    let tol = 1e-9;
    let inside = spans(&p, &pt, &sq, PG_RELATION_INSIDE, NONE);
    assert_eq!(inside.len(), 1);
    assert_span(&inside[0], 2.0, 4.0, tol);
    let half = PgSeparation { d: 0.5, h: 0.0 };
    let near = spans(&p, &pt, &sq, PG_RELATION_NEAR, half);
    assert_eq!(near.len(), 1);
    assert_span(&near[0], 1.5, 4.5, tol);
    let breach = spans(&p, &pt, &sq, PG_RELATION_BREACH, half);
    assert_eq!(breach.len(), 2);
    assert_span(&breach[0], 0.0, 2.5, tol);
    assert_eq!((breach[0].start_lo, breach[0].start_hi), (0.0, 0.0));
    assert_span(&breach[1], 3.5, 10.0, tol);
    assert_eq!((breach[1].end_lo, breach[1].end_hi), (10.0, 10.0));
    // near_0 is inside: the same set.
    let near0 = spans(&p, &pt, &sq, PG_RELATION_NEAR, NONE);
    assert_eq!(near0.len(), 1);
    assert_span(&near0[0], 2.0, 4.0, tol);
}

/// examples/intervals.jsonl, "cell-entered-twice": a U-shaped cell drifting west at 60
/// while the point flies east at 480 along y = 30, so the relative x is 540·t. At y = 30
/// the cell's walls are x ∈ [40, 55] and [85, 100]: inside on [40, 55]/540 and
/// [85, 100]/540; within D = 5 on [35, 60]/540 and [80, 105]/540; deeper than 5 inside
/// (fence_5) only for x ∈ (45, 50) and (90, 95) (the slot's floor y = 20 is 10 away), so
/// breach_5 is [0, 45/540], [50/540, 90/540], [95/540, T = 0.25].
#[test]
fn the_cell_entered_twice() {
    let p = params(0.25, 0.5);
    let cell = [
        v(40.0, 0.0),
        v(100.0, 0.0),
        v(100.0, 50.0),
        v(85.0, 50.0),
        v(85.0, 20.0),
        v(55.0, 20.0),
        v(55.0, 50.0),
        v(40.0, 50.0),
    ];
    let west = [v(-60.0, 0.0); 8];
    let poly = polygon(&cell, Some(&west));
    let pt = point2(v(0.0, 30.0), v(480.0, 0.0));
    let sep = PgSeparation { d: 5.0, h: 0.0 };
    let tol = 1e-9;
    let k = |x: f64| x / 540.0;
    let inside = spans(&p, &pt, &poly, PG_RELATION_INSIDE, sep);
    assert_eq!(inside.len(), 2);
    assert_span(&inside[0], k(40.0), k(55.0), tol);
    assert_span(&inside[1], k(85.0), k(100.0), tol);
    let near = spans(&p, &pt, &poly, PG_RELATION_NEAR, sep);
    assert_eq!(near.len(), 2);
    assert_span(&near[0], k(35.0), k(60.0), tol);
    assert_span(&near[1], k(80.0), k(105.0), tol);
    let breach = spans(&p, &pt, &poly, PG_RELATION_BREACH, sep);
    assert_eq!(breach.len(), 3);
    assert_span(&breach[0], 0.0, k(45.0), tol);
    assert_span(&breach[1], k(50.0), k(90.0), tol);
    assert_span(&breach[2], k(95.0), 0.25, tol);
    // It breaches the fence at t = 0: an exit, certified.
    let mut d = PgDetection::default();
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { pg_detect_exit(&p, &pt, &poly, &sep, &mut d) },
        PG_OK
    );
    assert_eq!((d.detected, d.kind), (1, PG_KIND_EXACT));
    assert_eq!(d.method, PG_METHOD_SAME_2D);
}

/// The 100×100 box from z = 0 to 120 and the drone at (50, 50, 100) moving (1, 0, 2):
/// its height reaches the ceiling 120 at t = 10 (inside [0, 10]), 130 = ceiling + H at
/// t = 15 (near [0, 15] with D = H = 10), and 110 = ceiling − H at t = 5, while x = 50 + t
/// stays more than 10 from the walls until t = 40: breach [5, 60].
fn drone() -> (PgParams, PgPoint, [PgVec2; 4]) {
    let p = params(60.0, 1.0);
    let pt = PgPoint {
        pos: v(50.0, 50.0),
        vel: v(1.0, 0.0),
        has_z: 1,
        z: 100.0,
        vz: 2.0,
    };
    let box_ = [v(0.0, 0.0), v(100.0, 0.0), v(100.0, 100.0), v(0.0, 100.0)];
    (p, pt, box_)
}

/// The drone's polygon with its slab [0, 120] at rest (paper A §III).
fn drone_polygon(box_: &[PgVec2; 4]) -> PgPolygon {
    PgPolygon {
        has_slab: 1,
        slab: PgSlab {
            bottom: 0.0,
            top: 120.0,
            vz: 0.0,
        },
        ..polygon(box_, None)
    }
}

/// examples/intervals.jsonl, "drone-leaves-through-ceiling" (the numbers at `drone`).
#[test]
fn the_drone_leaves_through_its_ceiling() {
    let (p, pt, box_) = drone();
    let poly = drone_polygon(&box_);
    let sep = PgSeparation { d: 10.0, h: 10.0 };
    let tol = 1e-9 * 60.0;
    let inside = spans(&p, &pt, &poly, PG_RELATION_INSIDE, sep);
    assert_eq!(inside.len(), 1);
    assert_span(&inside[0], 0.0, 10.0, tol);
    assert_eq!((inside[0].start_lo, inside[0].start_hi), (0.0, 0.0));
    let near = spans(&p, &pt, &poly, PG_RELATION_NEAR, sep);
    assert_eq!(near.len(), 1);
    assert_span(&near[0], 0.0, 15.0, tol);
    let breach = spans(&p, &pt, &poly, PG_RELATION_BREACH, sep);
    assert_eq!(breach.len(), 1);
    assert_span(&breach[0], 5.0, 60.0, tol);
    assert_eq!((breach[0].end_lo, breach[0].end_hi), (60.0, 60.0));

    let mut d = PgDetection::default();
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { pg_detect_exit(&p, &pt, &poly, &sep, &mut d) },
        PG_OK
    );
    assert_eq!(
        (d.detected, d.kind, d.method),
        (1, PG_KIND_EXACT, PG_METHOD_3D)
    );
    // Until T = 4 the drone stays more than H below the ceiling: no exit, certified.
    let short = params(4.0, 1.0);
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { pg_detect_exit(&short, &pt, &poly, &sep, &mut d) },
        PG_OK
    );
    assert_eq!((d.detected, d.kind), (0, PG_KIND_EXACT));
    assert!(spans(&short, &pt, &poly, PG_RELATION_BREACH, sep).is_empty());
}

/// The buffer protocol: a buffer too small gets the first spans, the count and
/// PG_ERR_CAPACITY; an exact one PG_OK; the spans written are the same either way.
#[test]
fn a_buffer_too_small_gets_the_count_and_a_prefix() {
    let p = params(10.0, 0.01);
    let pt = point2(v(1.0, -2.0), v(0.0, 1.0));
    let sq = polygon(&SQUARE, None);
    let sep = PgSeparation { d: 0.5, h: 0.0 };
    let all = spans(&p, &pt, &sq, PG_RELATION_BREACH, sep);
    assert_eq!(all.len(), 2);
    let mut one = [PgSpan::default(); 1];
    let mut n = 0;
    // SAFETY: `one` holds 1 span.
    let rc = unsafe {
        pg_intervals(
            &p,
            &pt,
            &sq,
            PG_RELATION_BREACH,
            &sep,
            one.as_mut_ptr(),
            1,
            &mut n,
        )
    };
    assert_eq!(rc, PG_ERR_CAPACITY);
    assert_eq!(n, 2);
    assert_eq!(one[0], all[0]);
    assert!(
        message().starts_with("out: 2 spans, room for 1"),
        "{}",
        message()
    );
    // SAFETY: a static string.
    let name = unsafe { CStr::from_ptr(pg_status_name(PG_ERR_CAPACITY)) };
    assert_eq!(name.to_str(), Ok("PG_ERR_CAPACITY"));
    // A larger buffer than needed: PG_OK, the rest untouched.
    let mut big = [PgSpan::default(); 4];
    // SAFETY: `big` holds 4 spans.
    let rc = unsafe {
        pg_intervals(
            &p,
            &pt,
            &sq,
            PG_RELATION_BREACH,
            &sep,
            big.as_mut_ptr(),
            4,
            &mut n,
        )
    };
    assert_eq!((rc, n), (PG_OK, 2));
    assert_eq!(&big[..2], &all[..]);
    assert_eq!(big[2], PgSpan::default());
    // No spans at all: PG_OK with a NULL buffer.
    let far = point2(v(10.0, 10.0), v(1.0, 0.0));
    // SAFETY: cap 0, out NULL.
    let rc = unsafe {
        pg_intervals(
            &p,
            &far,
            &sq,
            PG_RELATION_INSIDE,
            &NONE,
            ptr::null_mut(),
            0,
            &mut n,
        )
    };
    assert_eq!((rc, n), (PG_OK, 0));
}

/// Bad input to `pg_intervals`: each error's status, the message naming the C field,
/// and the conservative answer written anyway (one possible span over all time).
#[test]
fn errors_name_the_field_and_leave_one_possible_span() {
    let p = params(10.0, 0.01);
    let pt = point2(v(1.0, -2.0), v(0.0, 1.0));
    let sq = polygon(&SQUARE, None);
    let sep = PgSeparation { d: 0.5, h: 0.0 };
    let always = PgSpan {
        start_lo: 0.0,
        start_hi: f64::INFINITY,
        end_lo: 0.0,
        end_hi: f64::INFINITY,
        certain: 0,
    };
    // One bad call: its status, its message's start, and the answer it leaves.
    let check = |p: &PgParams,
                 pt: *const PgPoint,
                 relation: i32,
                 sep: *const PgSeparation,
                 code: i32,
                 prefix: &str| {
        let mut out = [PgSpan::default(); 2];
        let mut n = 0;
        // SAFETY: valid pointers or NULL; `out` holds 2 spans.
        let rc = unsafe { pg_intervals(p, pt, &sq, relation, sep, out.as_mut_ptr(), 2, &mut n) };
        let m = message();
        assert_eq!(rc, code, "{m}");
        assert!(
            m.starts_with(prefix),
            "{m:?} does not start with {prefix:?}"
        );
        assert_eq!((n, out[0]), (1, always), "{m}");
    };
    let near = PG_RELATION_NEAR;
    let (null, bad) = (PG_ERR_NULL_POINTER, PG_ERR_BAD_PARAMETER);
    check(&p, &pt, near, ptr::null(), null, "sep: NULL pointer");
    let negative = PgSeparation { d: -1.0, h: 0.0 };
    check(&p, &pt, near, &negative, bad, "sep.d: -1 ");
    let nan = PgSeparation {
        d: 1.0,
        h: f64::NAN,
    };
    check(
        &p,
        &pt,
        near,
        &nan,
        PG_ERR_NOT_FINITE,
        "sep.h: not a finite number",
    );
    check(
        &p,
        &pt,
        7,
        &sep,
        bad,
        "relation: 7 is not PG_RELATION_INSIDE (0)",
    );
    check(&p, ptr::null(), near, &sep, null, "point: NULL pointer");
    check(&params(0.0, 0.01), &pt, near, &sep, bad, "lookahead: ");
    check(&params(10.0, 0.0), &pt, near, &sep, bad, "buff: ");
}

/// `pg_detect_exit` checks `sep` as `pg_intervals` does and answers "exits" on an error;
/// `pg_intervals`' own pointers (`n_out`, and `out` when cap > 0) are checked before
/// anything is written through them.
#[test]
fn the_exit_and_the_out_pointers_are_checked() {
    let p = params(10.0, 0.01);
    let pt = point2(v(1.0, -2.0), v(0.0, 1.0));
    let sq = polygon(&SQUARE, None);
    let sep = PgSeparation { d: 0.5, h: 0.0 };
    let mut d = PgDetection::default();
    let bad = PgSeparation { d: 0.0, h: -2.0 };
    // SAFETY: valid pointers.
    let rc = unsafe { pg_detect_exit(&p, &pt, &sq, &bad, &mut d) };
    assert_eq!(rc, PG_ERR_BAD_PARAMETER);
    assert!(message().starts_with("sep.h: "), "{}", message());
    assert_eq!(
        (d.detected, d.kind, d.method),
        (1, PG_KIND_CONSERVATIVE, PG_METHOD_NONE)
    );
    // SAFETY: NULL sep and NULL out are refused before any read.
    unsafe {
        assert_eq!(
            pg_detect_exit(&p, &pt, &sq, ptr::null(), &mut d),
            PG_ERR_NULL_POINTER
        );
        assert_eq!(message(), "sep: NULL pointer");
        assert_eq!(
            pg_detect_exit(&p, &pt, &sq, &sep, ptr::null_mut()),
            PG_ERR_NULL_POINTER
        );
        assert_eq!(message(), "out: NULL pointer");
    }
    // pg_intervals' own pointers: n_out, and out when cap > 0.
    let mut n = 5;
    // SAFETY: NULL and misaligned pointers are refused before any write.
    unsafe {
        let rc = pg_intervals(&p, &pt, &sq, 0, &sep, ptr::null_mut(), 0, ptr::null_mut());
        assert_eq!(
            (rc, message().as_str()),
            (PG_ERR_NULL_POINTER, "n_out: NULL pointer")
        );
        let rc = pg_intervals(&p, &pt, &sq, 0, &sep, ptr::null_mut(), 3, &mut n);
        assert_eq!(
            (rc, message().as_str(), n),
            (PG_ERR_NULL_POINTER, "out: NULL pointer", 1)
        );
        let mut bytes = [0u8; 2 * std::mem::size_of::<PgSpan>()];
        let skew = bytes.as_mut_ptr().wrapping_add(1).cast::<PgSpan>();
        let rc = pg_intervals(&p, &pt, &sq, 0, &sep, skew, 1, &mut n);
        assert_eq!(rc, PG_ERR_INVALID);
        assert!(
            message().starts_with("out: misaligned pointer"),
            "{}",
            message()
        );
        assert!(
            bytes.iter().all(|&b| b == 0),
            "nothing is written through it"
        );
    }
    // A successful call clears the message.
    let mut out = [PgSpan::default(); 2];
    // SAFETY: valid pointers.
    let rc = unsafe { pg_intervals(&p, &pt, &sq, 0, &sep, out.as_mut_ptr(), 2, &mut n) };
    assert_eq!((rc, n, message().as_str()), (PG_OK, 1, ""));
}
