//! Hand-worked band cases: each conflict band's ends are computed on paper from the
//! definitions of the module doc and must lie in the Unknown slivers between a
//! Conflict band and a Clear band.

use super::*;
use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

fn v(x: f64, y: f64) -> Vect2 {
    Vect2::new(x, y)
}

/// The square [cx − a, cx + a] × [cy − a, cy + a], counterclockwise.
fn square(cx: f64, cy: f64, a: f64) -> Vec<Vect2> {
    vec![
        v(cx - a, cy - a),
        v(cx + a, cy - a),
        v(cx + a, cy + a),
        v(cx - a, cy + a),
    ]
}

fn sep(d: f64, h: f64) -> Separation {
    Separation { d, h }
}

/// 0.1° in radians.
const TENTH_DEGREE: f64 = PI / 1800.0;

/// The bands tile [lo, hi] in order, without gaps, adjacent kinds differ, and the
/// Unknown total is the sum of the Unknown widths.
fn assert_tiling(b: &Bands, lo: f64, hi: f64) {
    assert_eq!(b.bands.first().map(|x| x.lo), Some(lo));
    assert_eq!(b.bands.last().map(|x| x.hi), Some(hi));
    for w in b.bands.windows(2) {
        assert_eq!(w[0].hi, w[1].lo);
        assert_ne!(w[0].kind, w[1].kind);
    }
    for x in &b.bands {
        assert!(x.lo <= x.hi);
    }
    let u: f64 = b
        .bands
        .iter()
        .filter(|x| x.kind == BandKind::Unknown)
        .map(|x| x.hi - x.lo)
        .sum();
    assert!((u - b.unknown_total).abs() <= 1e-12 * (1.0 + u));
}

/// The kind of the band holding x (the first one, at a shared end).
fn kind_at(b: &Bands, x: f64) -> BandKind {
    b.bands
        .iter()
        .find(|band| band.lo <= x && x <= band.hi)
        .map(|band| band.kind)
        .unwrap_or(BandKind::Unknown)
}

/// The exact end x is between a Conflict band and a Clear band: the bands holding
/// x are Unknown only, x is strictly inside no Clear or Conflict band.
fn assert_enclosed(b: &Bands, x: f64) {
    for band in &b.bands {
        if band.lo < x && x < band.hi {
            assert_eq!(band.kind, BandKind::Unknown, "{x} inside {band:?}");
        }
    }
}

/// The tangent course from the origin to the disc of radius d around (cx, cy), on the
/// clockwise side: atan2(cx, cy) + asin(d / |c|).
fn tangent(cx: f64, cy: f64, d: f64) -> f64 {
    cx.atan2(cy) + (d / cx.hypot(cy)).asin()
}

#[test]
fn a_static_square_ahead() {
    // The square of half side 10 centred 100 north; D = 5; the point reaches 200.
    // The course is in conflict when the ray passes within 5 of the square: the
    // widest course is tangent to the disc of radius 5 around the near corner (10, 90)
    // (its far corner (10, 110) is seen at a smaller angle), θ* = atan(10/90) +
    // asin(5/√8200) ≈ 0.16590; the band is [−θ*, θ*].
    let p = square(0.0, 100.0, 10.0);
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 20.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: sep(5.0, 0.0),
    };
    let b = course_bands(&traffic, 10.0, TENTH_DEGREE).unwrap();
    assert_tiling(&b, 0.0, TAU);
    assert!(b.met && b.unknown_total <= TENTH_DEGREE, "{b:?}");
    let theta = tangent(10.0, 90.0, 5.0);
    assert!((theta - 0.16590).abs() < 1e-4);
    assert_eq!(b.bands[0].kind, BandKind::Conflict);
    assert_eq!(b.bands.last().unwrap().kind, BandKind::Conflict);
    assert_enclosed(&b, theta);
    assert_enclosed(&b, TAU - theta);
    assert_eq!(kind_at(&b, theta * 0.99), BandKind::Conflict);
    assert_eq!(kind_at(&b, theta * 1.01), BandKind::Clear);
    assert_eq!(kind_at(&b, PI), BandKind::Clear);
    // Exactly: Conflict, Unknown, Clear, Unknown, Conflict.
    let kinds: Vec<BandKind> = b.bands.iter().map(|x| x.kind).collect();
    assert_eq!(
        kinds,
        [
            BandKind::Conflict,
            BandKind::Unknown,
            BandKind::Clear,
            BandKind::Unknown,
            BandKind::Conflict
        ]
    );
}

#[test]
fn a_square_behind_conflicts_only_around_south() {
    // The same square 100 south: the band is [π − θ*, π + θ*].
    let p = square(0.0, -100.0, 10.0);
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 20.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: sep(5.0, 0.0),
    };
    let b = course_bands(&traffic, 10.0, TENTH_DEGREE).unwrap();
    assert_tiling(&b, 0.0, TAU);
    let theta = tangent(10.0, 90.0, 5.0);
    let kinds: Vec<BandKind> = b.bands.iter().map(|x| x.kind).collect();
    assert_eq!(
        kinds,
        [
            BandKind::Clear,
            BandKind::Unknown,
            BandKind::Conflict,
            BandKind::Unknown,
            BandKind::Clear
        ]
    );
    assert_enclosed(&b, PI - theta);
    assert_enclosed(&b, PI + theta);
    assert!(b.bands[2].lo <= PI - theta + 1e-3 && b.bands[2].hi >= PI + theta - 1e-3);
    // Too slow to reach it: all clear, at once (the prefilter).
    let slow = course_bands(&traffic, 4.0, TENTH_DEGREE).unwrap();
    assert_eq!(slow.bands.len(), 1);
    assert_eq!(slow.bands[0].kind, BandKind::Clear);
}

#[test]
fn a_moving_cell_changes_which_courses_conflict() {
    // The square of half side 10 centred (100, 100), at rest or drifting west at 10;
    // the point flies at 10 for T = 20, D = 5. At rest, north passes 80 west of it
    // (clear) and north-east heads at its centre (conflict). Drifting west, north
    // closes at (10, 10) relative: straight at the centre (conflict), and north-east
    // moves relative along (17.07, 7.07), 41 south of the centre at x = 100 and
    // never nearer than the square's bottom allows (clear).
    let p = square(100.0, 100.0, 10.0);
    let still = vec![Vect2::ZERO; 4];
    let west = vec![v(-10.0, 0.0); 4];
    for (vels, north, north_east) in [
        (&still, BandKind::Clear, BandKind::Conflict),
        (&west, BandKind::Conflict, BandKind::Clear),
    ] {
        let obstacles = [Obstacle {
            p: &p,
            vels,
            slab: None,
        }];
        let traffic = Traffic {
            t: 20.0,
            s: Vect2::ZERO,
            height: None,
            obstacles: &obstacles,
            sep: sep(5.0, 0.0),
        };
        let b = course_bands(&traffic, 10.0, TENTH_DEGREE).unwrap();
        assert_tiling(&b, 0.0, TAU);
        assert!(b.met);
        assert_eq!(kind_at(&b, 0.0), north);
        assert_eq!(kind_at(&b, FRAC_PI_4), north_east);
        assert_eq!(conflict(&traffic, velocity(10.0, 0.0)).unwrap(), {
            if north == BandKind::Conflict {
                Tri::Yes
            } else {
                Tri::No
            }
        });
    }
}

#[test]
fn speed_bands_of_a_square_ahead() {
    // North at speed σ for T = 5 reaches 5σ; the square's side grown by D = 5 is at
    // y = 85: conflict exactly when σ ≥ 17.
    let p = square(0.0, 100.0, 10.0);
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 5.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: sep(5.0, 0.0),
    };
    let b = speed_bands(&traffic, 0.0, 0.0, 20.0, 0.01).unwrap();
    assert_tiling(&b, 0.0, 20.0);
    assert!(b.met);
    let kinds: Vec<BandKind> = b.bands.iter().map(|x| x.kind).collect();
    assert_eq!(
        kinds,
        [BandKind::Clear, BandKind::Unknown, BandKind::Conflict]
    );
    assert_enclosed(&b, 17.0);
    assert!(b.bands[1].hi - b.bands[1].lo <= 0.01);
}

#[test]
fn vertical_speed_bands_under_a_slab() {
    // A large cell overhead with a slab from 100 to 200; the point at height 0 for
    // T = 20, H = 10: it comes within H of the bottom when 20·vz ≥ 90, vz ≥ 4.5.
    let p = square(0.0, 0.0, 1000.0);
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: Some(Slab {
            bottom: 100.0,
            top: 200.0,
            vsp: 0.0,
        }),
    }];
    let low = Traffic {
        t: 20.0,
        s: Vect2::ZERO,
        height: Some(Height { sz: 0.0, vz: 0.0 }),
        obstacles: &obstacles,
        sep: sep(5.0, 10.0),
    };
    let b = vertical_speed_bands(&low, v(0.0, 10.0), -10.0, 10.0, 0.01).unwrap();
    assert_tiling(&b, -10.0, 10.0);
    assert!(b.met);
    let kinds: Vec<BandKind> = b.bands.iter().map(|x| x.kind).collect();
    assert_eq!(
        kinds,
        [BandKind::Clear, BandKind::Unknown, BandKind::Conflict]
    );
    assert_enclosed(&b, 4.5);
    // Level flight below: every course clear, although the polygon covers them all.
    let courses = course_bands(&low, 10.0, TENTH_DEGREE).unwrap();
    assert_eq!(courses.bands.len(), 1);
    assert_eq!(courses.bands[0].kind, BandKind::Clear);
    // Inside the slab: every course in conflict (at t = 0 already).
    let inside = Traffic {
        height: Some(Height { sz: 150.0, vz: 0.0 }),
        ..low
    };
    let courses = course_bands(&inside, 10.0, TENTH_DEGREE).unwrap();
    assert_eq!(courses.bands.len(), 1);
    assert_eq!(courses.bands[0].kind, BandKind::Conflict);
    // Without D the horizontal part needs the point inside: still all in conflict.
    let inside_no_d = Traffic {
        sep: sep(0.0, 0.0),
        ..inside
    };
    let courses = course_bands(&inside_no_d, 10.0, TENTH_DEGREE).unwrap();
    assert_eq!(courses.bands[0].kind, BandKind::Conflict);
    assert_eq!(courses.bands.len(), 1);
}

#[test]
fn a_thin_conflict_between_coarse_samples_is_found() {
    // A small square of half side 1 at 150 on the bearing 30°, D = 0.5: its conflict
    // band is about 30° ± 0.57° wide, found between samples by halving.
    let c = (150.0 * 0.5, 150.0 * (3f64.sqrt() / 2.0));
    let p = square(c.0, c.1, 1.0);
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 20.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: sep(0.5, 0.0),
    };
    let b = course_bands(&traffic, 10.0, TENTH_DEGREE).unwrap();
    assert!(b.met);
    assert_eq!(kind_at(&b, PI / 6.0), BandKind::Conflict);
    assert_eq!(kind_at(&b, PI / 6.0 + 0.03), BandKind::Clear);
    assert_eq!(kind_at(&b, FRAC_PI_2), BandKind::Clear);
}

#[test]
fn inputs_are_checked_by_field() {
    let p = square(0.0, 100.0, 10.0);
    let vels = vec![Vect2::ZERO; 4];
    let short = vec![Vect2::ZERO; 3];
    let good = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 20.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &good,
        sep: sep(5.0, 0.0),
    };
    let field = |e: BandsError| match e {
        BandsError::NotFinite { field }
        | BandsError::OutOfRange { field, .. }
        | BandsError::WrongLength { field, .. }
        | BandsError::DimensionMismatch { field } => field,
    };
    let err = |r: Result<Bands, BandsError>| field(r.unwrap_err());
    assert_eq!(err(course_bands(&traffic, -1.0, 0.1)), "speed");
    assert_eq!(err(course_bands(&traffic, f64::NAN, 0.1)), "speed");
    assert_eq!(err(course_bands(&traffic, 1.0, 0.0)), "unknown_max");
    let bad_t = Traffic { t: 0.0, ..traffic };
    assert_eq!(err(course_bands(&bad_t, 1.0, 0.1)), "t");
    let bad_d = Traffic {
        sep: sep(-1.0, 0.0),
        ..traffic
    };
    assert_eq!(err(course_bands(&bad_d, 1.0, 0.1)), "sep");
    let bad = [Obstacle {
        p: &p,
        vels: &short,
        slab: None,
    }];
    let bad_v = Traffic {
        obstacles: &bad,
        ..traffic
    };
    assert_eq!(err(course_bands(&bad_v, 1.0, 0.1)), "obstacles[0].vels");
    assert_eq!(err(speed_bands(&traffic, 0.0, 2.0, 1.0, 0.1)), "max");
    assert_eq!(
        err(vertical_speed_bands(&traffic, Vect2::ZERO, 0.0, 1.0, 0.1)),
        "height"
    );
    let slab = [Obstacle {
        p: &p,
        vels: &vels,
        slab: Some(Slab {
            bottom: 0.0,
            top: 1.0,
            vsp: 0.0,
        }),
    }];
    let flat = Traffic {
        obstacles: &slab,
        ..traffic
    };
    assert_eq!(err(course_bands(&flat, 1.0, 0.1)), "obstacles[0].slab");
}

#[test]
fn a_bound_that_cannot_be_met_is_reported() {
    // The point starts on the bottom edge of the square [−10, 10] × [0, 20], D = 0:
    // every course is in conflict at t = 0 (exactly on the boundary). Courses into the
    // square go deeper than any r: certified Conflict. Courses out of it never have a
    // point deeper than r inside nor a margin for Clear: Unknown at every width.
    let p = vec![v(-10.0, 0.0), v(10.0, 0.0), v(10.0, 20.0), v(-10.0, 20.0)];
    let vels = vec![Vect2::ZERO; 4];
    let obstacles = [Obstacle {
        p: &p,
        vels: &vels,
        slab: None,
    }];
    let traffic = Traffic {
        t: 10.0,
        s: Vect2::ZERO,
        height: None,
        obstacles: &obstacles,
        sep: sep(0.0, 0.0),
    };
    let b = course_bands(&traffic, 1.0, TENTH_DEGREE).unwrap();
    assert_tiling(&b, 0.0, TAU);
    assert!(!b.met && b.unknown_total > TENTH_DEGREE);
    assert!(b.bands.iter().all(|x| x.kind != BandKind::Clear));
    assert_eq!(kind_at(&b, 0.0), BandKind::Conflict);
    assert_eq!(kind_at(&b, PI), BandKind::Unknown);
    assert!(b.unknown_total >= PI * 0.9, "{b:?}");
}
