//! The format's rules on values already read (docs/scenario.md, "Geometry rules"): ranges,
//! longitudes laid out on the Earth or the unrolled plane, rings (closed, simple, wound),
//! the rings of one polygon, an area's times and a track's speed and rectangle.

use super::errors::{Ctx, Problem, ScenarioError};
use crate::scenario::model::{
    normal_lon, Area, Longitudes, Shape, Track, MAX_ABS_LAT_DEG, MAX_RECT_LAT_DEG,
};
use crate::sphere::{self, LonLat, RectDims};

/// A position checked for range: `[lon, lat]` degrees, |lat| ≤ [`MAX_ABS_LAT_DEG`].
pub(super) fn checked(
    ctx: &Ctx,
    field: &str,
    k: usize,
    lon: f64,
    lat: f64,
) -> Result<LonLat, ScenarioError> {
    if !(lon.is_finite() && lat.is_finite()) {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::BadNumber));
    }
    if lat.abs() > MAX_ABS_LAT_DEG {
        return Err(ctx.err(format!("{field}[{k}]"), Problem::LatitudeOutOfRange(lat)));
    }
    Ok(LonLat::from_degrees(lon, lat))
}

/// One line of positions (degrees as written: a ring, closing repeat included, or a
/// track's waypoints) laid out on the plane of `mode`; also the index of the first
/// position whose longitude lies beyond ±180° (it was wrapped, for a warning).
///
/// On the Earth the first longitude is taken modulo 360° into (−180, 180] and each next
/// one is the value of its own longitude (mod 360°) nearest the previous one, so every
/// step runs the shorter way round, across the antimeridian when that is shorter. The
/// way is decided on the steps between the exact values in (−180, 180] (one rounding,
/// which keeps the comparison with ±180 right except at a tie); a step of exactly 180°
/// could run either way and is an error. The longitude written is then ℓ + 360°·m for
/// the exact ℓ ∈ (−180, 180] and a whole m counted along the line: one rounding, none
/// accumulated. A ring must come back to its first position with m = 0 (else it
/// circles a pole) and span less than a turn. On the unrolled plane the longitudes are
/// kept as written, and a step longer than 180° is an error.
///
/// `start` (whole turns, 0 but for a hole) starts the count m there: a hole is laid out
/// in the same copy as its exterior ring.
pub(super) fn lay_out(
    ctx: &Ctx,
    field: &str,
    pts: &[[f64; 2]],
    mode: Longitudes,
    ring: bool,
    start: f64,
) -> Result<(Vec<[f64; 2]>, Option<usize>), ScenarioError> {
    let at = |k: usize, p: Problem| ctx.err(format!("{field}[{k}]"), p);
    if mode == Longitudes::Unrolled {
        return match (1..pts.len()).find(|&k| (pts[k][0] - pts[k - 1][0]).abs() > 180.0) {
            Some(k) => Err(at(k, Problem::CrossesAntimeridian(k))),
            None => Ok((pts.to_vec(), None)),
        };
    }
    let mut out = Vec::with_capacity(pts.len());
    let mut wrapped = None;
    let (mut prev, mut turns) = (0.0, start);
    for (k, q) in pts.iter().enumerate() {
        let l = normal_lon(q[0]);
        if wrapped.is_none() && q[0].abs() > 180.0 {
            wrapped = Some(k);
        }
        if k > 0 {
            let step = l - prev;
            if step.abs() == 180.0 {
                return Err(at(k, Problem::HalfTurnStep(k)));
            }
            if step > 180.0 {
                turns -= 1.0;
            } else if step < -180.0 {
                turns += 1.0;
            }
        }
        prev = l;
        out.push([if turns == 0.0 { l } else { l + 360.0 * turns }, q[1]]);
    }
    if ring && pts.len() > 1 {
        let (first, last) = (pts[0], pts[pts.len() - 1]);
        let closed = normal_lon(first[0]) == normal_lon(last[0]) && first[1] == last[1];
        if closed && turns != start {
            return Err(ctx.err(field, Problem::CirclesPole));
        }
        let (lo, hi) = out
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[0]), hi.max(p[0]))
            });
        if hi - lo >= 360.0 {
            return Err(ctx.err(field, Problem::SpansWholeTurn(hi - lo)));
        }
    }
    Ok((out, wrapped))
}

/// The spec's rules for one ring already read (`field` names it): closed, ≥ 3 distinct
/// vertices, simple (on the Mercator plane, where paper B's rhumb-line edges are
/// straight; exact orientation tests on the f64 Mercator vertices the stages use).
/// Either winding is accepted (RFC 7946 §3.1.6); the ring is kept counterclockwise, or
/// clockwise for a `hole`.
pub(super) fn ring_from(
    ctx: &Ctx,
    ring: Vec<LonLat>,
    field: &str,
    hole: bool,
) -> Result<Vec<LonLat>, ScenarioError> {
    ring_indexed(ctx, ring, field, hole).map(|(r, _)| r)
}

/// [`ring_from`], with the index as written of each vertex kept.
pub(super) fn ring_indexed(
    ctx: &Ctx,
    mut ring: Vec<LonLat>,
    field: &str,
    hole: bool,
) -> Result<(Vec<LonLat>, Vec<usize>), ScenarioError> {
    use polyguard::ring::{check, collinear, RingFault, Winding};
    if ring.len() < 2 || ring.first() != ring.last() {
        if ring.len() < 3 {
            return Err(ctx.err(field, Problem::TooFewVertices(ring.len())));
        }
        return Err(ctx.err(field, Problem::UnclosedRing));
    }
    ring.pop();
    let distinct = {
        let mut d = ring.clone();
        d.dedup();
        d.len() - usize::from(d.len() > 1 && d.first() == d.last())
    };
    if distinct < 3 {
        return Err(ctx.err(field, Problem::TooFewVertices(distinct)));
    }
    let plane = merc_ring(&ring);
    let want = if hole {
        Winding::Clockwise
    } else {
        Winding::Counterclockwise
    };
    let mut index: Vec<usize> = (0..ring.len()).collect();
    match check(&plane) {
        Ok(w) if w == want => {}
        Ok(_) => {
            ring.reverse();
            index.reverse();
        }
        Err(RingFault::Crossing { .. }) if collinear(&plane) => {
            return Err(ctx.err(field, Problem::ZeroArea))
        }
        Err(RingFault::Crossing { a, b }) => {
            return Err(ctx.err(field, Problem::SelfIntersecting(a, b)))
        }
        Err(RingFault::ZeroArea) => return Err(ctx.err(field, Problem::ZeroArea)),
        // beyond the exact check's range (no real position gets there): kept as given
        Err(RingFault::NotCheckable) => {}
    }
    let mut kept: Vec<(LonLat, usize)> = ring.into_iter().zip(index).collect();
    kept.dedup_by(|b, a| a.0 == b.0);
    if kept.len() > 1 && kept.first().map(|p| p.0) == kept.last().map(|p| p.0) {
        kept.pop();
    }
    Ok(kept.into_iter().unzip())
}

/// A ring's vertices on the Mercator plane, as the stages see them.
fn merc_ring(ring: &[LonLat]) -> Vec<polyguard::vect2::Vect2> {
    ring.iter()
        .map(|&p| {
            let [x, y] = sphere::mercator(p);
            polyguard::vect2::Vect2::new(x, y)
        })
        .collect()
}

/// Is `p` strictly inside the ring? Exact crossing number (the orientation of each edge
/// that straddles p's height); `p` must not lie on the ring. `None` when an exact
/// product would over- or underflow.
fn strictly_inside(p: polyguard::vect2::Vect2, ring: &[polyguard::vect2::Vect2]) -> Option<bool> {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            // the edge crosses the horizontal line through p right of p exactly when p
            // is left of the edge taken upward
            let o = polyguard::ring::orient(a, b, p)?;
            if (o > 0) == (b.y > a.y) {
                inside = !inside;
            }
        }
    }
    Some(inside)
}

/// The rules between the rings of one polygon (each already checked by [`ring_from`]):
/// no two share a point, every hole lies inside the exterior ring and outside the other
/// holes. `Err((k, problem))` names the ring k at fault (a hole); the checks are exact on
/// the Mercator vertices. O(n²) edge pairs, pruned by bounding boxes. `written` gives
/// each ring's vertex indices as written (for the edges an error names).
pub(super) fn check_rings(
    ring: &[LonLat],
    holes: &[Vec<LonLat>],
    written: &[Vec<usize>],
) -> Result<(), (usize, Problem)> {
    use polyguard::ring::segments_meet;
    use polyguard::vect2::Vect2;
    let rings: Vec<Vec<Vect2>> = std::iter::once(ring)
        .chain(holes.iter().map(|h| h.as_slice()))
        .map(merc_ring)
        .collect();
    let boxes: Vec<[f64; 4]> = rings
        .iter()
        .map(|r| {
            r.iter().fold(
                [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ],
                |b, p| [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)],
            )
        })
        .collect();
    let apart = |a: [f64; 4], b: [f64; 4]| a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1];
    for k in 1..rings.len() {
        for j in 0..k {
            if apart(boxes[j], boxes[k]) {
                continue;
            }
            let (r, q) = (&rings[k], &rings[j]);
            for a in 0..r.len() {
                let (a0, a1) = (r[a], r[(a + 1) % r.len()]);
                for b in 0..q.len() {
                    let (b0, b1) = (q[b], q[(b + 1) % q.len()]);
                    // beyond the exact range (no real position gets there): not a meeting
                    if segments_meet(a0, a1, b0, b1) == Some(true) {
                        // each edge named in the direction it is written
                        let edge = |w: &[usize], i: usize| {
                            let (x, y) = (w[i], w[(i + 1) % w.len()]);
                            if w.len() > 1 && w[0] > w[1] {
                                (y, x)
                            } else {
                                (x, y)
                            }
                        };
                        let (a, b) = (edge(&written[k], a), edge(&written[j], b));
                        let n = |x: usize| u32::try_from(x).unwrap_or(u32::MAX);
                        return Err((
                            k,
                            Problem::RingsMeet {
                                ring: n(j),
                                a: (n(a.0), n(a.1)),
                                b: (n(b.0), n(b.1)),
                            },
                        ));
                    }
                }
            }
        }
        // No ring meets another: a ring's first vertex tells on which side of another
        // ring the whole of it lies.
        if strictly_inside(rings[k][0], &rings[0]) == Some(false) {
            return Err((k, Problem::HoleOutside));
        }
        for j in 1..k {
            if strictly_inside(rings[k][0], &rings[j]) == Some(true)
                || strictly_inside(rings[j][0], &rings[k]) == Some(true)
            {
                return Err((k, Problem::HoleInHole(j)));
            }
        }
    }
    Ok(())
}

/// The spec's area rules for a Polygon of one ring (the fast path's areas): the ring's
/// rules ([`ring_from`]) and `tf ≥ t0`.
pub(super) fn area_from(
    ctx: &Ctx,
    ring: Vec<LonLat>,
    t0: Option<f64>,
    tf: Option<f64>,
) -> Result<Area, ScenarioError> {
    let ring = ring_from(ctx, ring, "geometry.coordinates[0]", false)?;
    times_ok(ctx, t0, tf)?;
    Ok(Area {
        shapes: vec![Shape::plain(ring)],
        multi: false,
        t0,
        tf,
    })
}

/// An area's `tf ≥ t0`.
pub(super) fn times_ok(ctx: &Ctx, t0: Option<f64>, tf: Option<f64>) -> Result<(), ScenarioError> {
    if let (Some(a), Some(b)) = (t0, tf) {
        if b < a {
            return Err(ctx.err("properties.tf", Problem::EndBeforeStart));
        }
    }
    Ok(())
}

/// The spec's track rules on values already read: ≥ 2 waypoints, speed > 0, distances
/// ≥ 0 (`None` = missing).
pub(super) fn track_from(
    ctx: &Ctx,
    waypoints: Vec<LonLat>,
    speed_kn: Option<f64>,
    dists: [Option<f64>; 3],
    t0: Option<f64>,
) -> Result<Track, ScenarioError> {
    if waypoints.len() < 2 {
        return Err(ctx.err(
            "geometry.coordinates",
            Problem::TooFewVertices(waypoints.len()),
        ));
    }
    let speed_kn = speed_kn.ok_or_else(|| ctx.err("properties.speed_kn", Problem::Missing))?;
    if speed_kn < 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::NegativeSpeed(speed_kn)));
    }
    if speed_kn == 0.0 {
        return Err(ctx.err("properties.speed_kn", Problem::ZeroSpeed));
    }
    let mut d = [0.0; 3];
    for (k, key) in ["front_nm", "back_nm", "side_nm"].iter().enumerate() {
        d[k] = dists[k].ok_or_else(|| ctx.err(format!("properties.{key}"), Problem::Missing))?;
        if d[k] < 0.0 {
            return Err(ctx.err(format!("properties.{key}"), Problem::NegativeDistance(d[k])));
        }
    }
    let reach = (d[0].max(d[1]) + d[2]) / sphere::EARTH_RADIUS_NM;
    let top = waypoints.iter().fold(0f64, |m, p| m.max(p.lat.abs())) + reach;
    if top.to_degrees() > MAX_RECT_LAT_DEG {
        return Err(ctx.err(
            "properties.front_nm",
            Problem::RectangleTooLarge(top.to_degrees()),
        ));
    }
    Ok(Track {
        waypoints,
        speed_kn,
        dims: RectDims {
            front: d[0],
            back: d[1],
            side: d[2],
        },
        t0: t0.unwrap_or(0.0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::model::Kind;
    use crate::scenario::read::testkit::{middle, problem};
    use crate::scenario::read::{fast_parse, parse, parse_general};
    use crate::scenario::testdata::{file, AREA, TRACK};

    #[test]
    fn rectangle_past_the_pole_is_rejected() {
        let e = problem(
            r#"{"type":"Feature","properties":{"id":"big","kind":"track","speed_kn":10,
            "front_nm":400,"back_nm":1,"side_nm":1},
            "geometry":{"type":"LineString","coordinates":[[0,84],[1,84]]}}"#,
        );
        assert!(matches!(e.problem, Problem::RectangleTooLarge(_)));
    }

    /// Either winding is read (RFC 7946) and kept counterclockwise, by both paths.
    #[test]
    fn either_winding_reads_counterclockwise() {
        let ccw = parse(&file(&[AREA])).expect("collection");
        let cw_text =
            file(&[&AREA.replace("[[0,0],[1,0],[1,1],[0,0]]", "[[0,0],[1,1],[1,0],[0,0]]")]);
        let cw = parse(&cw_text).expect("collection");
        assert!(cw.errors.is_empty() && ccw.errors.is_empty());
        let (Kind::Area(a), Kind::Area(b)) = (
            &ccw.scenario.features[0].kind,
            &cw.scenario.features[0].kind,
        ) else {
            panic!("areas");
        };
        let turn = |r: &[LonLat]| {
            let p: Vec<polyguard::vect2::Vect2> = r
                .iter()
                .map(|q| polyguard::vect2::Vect2::new(q.lon, q.lat))
                .collect();
            polyguard::ring::winding(&p)
        };
        assert_eq!(
            turn(&a.shapes[0].ring),
            Ok(polyguard::ring::Winding::Counterclockwise)
        );
        assert_eq!(
            turn(&b.shapes[0].ring),
            Ok(polyguard::ring::Winding::Counterclockwise)
        );
        assert_eq!(
            fast_parse(&cw_text),
            Some(parse_general(&cw_text).expect("collection"))
        );
    }

    /// What cannot be read one way only, or is not modelled, with the field and the words
    /// its error has (each case the middle feature of three): a step of exactly 180° of
    /// longitude (east or west?), a ring that circles a pole or spans a whole turn, holes
    /// that meet their polygon's rings or lie outside it or in another hole, a hole that
    /// crosses itself, an unclosed part of a MultiPolygon, a geometry of another type.
    fn refused() -> Vec<(String, &'static str, &'static str)> {
        vec![
            (
                TRACK.replace("[[0,0],[1,1]]", "[[179.5,0],[-0.5,1]]"),
                "geometry.coordinates[1]",
                "positions 0 and 1 are exactly 180° of longitude apart",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,60],[120,60],[-120,60],[0,60]]]",
                ),
                "geometry.coordinates[0]",
                "the ring circles a pole",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[170,0],[340,0],[20,1],[-150,2],[40,3],[0,3],[0,0]]]",
                ),
                "geometry.coordinates[0]",
                "spans 380° of longitude, a whole turn or more",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[1,1],[4,1],[4,2],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "meets ring 0 of the polygon: edge 0→1 of this ring and edge 1→2",
            ),
            (
                // a hole touching the exterior at one point is refused too
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[1,1],[3,2],[1,2],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "meets ring 0 of the polygon",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[3,0],[3,3],[0,3],[0,0]],[[4,1],[5,1],[5,2],[4,1]]]",
                ),
                "geometry.coordinates[1]",
                "does not lie inside the polygon's exterior ring",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[9,0],[9,9],[0,9],[0,0]],[[1,1],[1,8],[8,8],[8,1],[1,1]],\
                     [[2,2],[2,3],[3,3],[2,2]]]",
                ),
                "geometry.coordinates[2]",
                "this hole and hole 1 of the polygon lie one inside the other",
            ),
            (
                AREA.replace(
                    "[[[0,0],[1,0],[1,1],[0,0]]]",
                    "[[[0,0],[9,0],[9,9],[0,9],[0,0]],[[1,1],[3,3],[3,1],[1,3],[1,1]]]",
                ),
                "geometry.coordinates[1]",
                "edges 0–1 and 2–3 cross",
            ),
            (
                AREA.replace(r#""type":"Polygon""#, r#""type":"MultiPolygon""#)
                    .replace(
                        "[[[0,0],[1,0],[1,1],[0,0]]]",
                        "[[[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6]]]]",
                    ),
                "geometry.coordinates[1][0]",
                "ring not closed",
            ),
            (
                AREA.replace(r#""type":"Polygon""#, r#""type":"Point""#),
                "geometry.type",
                "expected Polygon or MultiPolygon",
            ),
        ]
    }

    /// What cannot be read one way only is an error, never a silent misreading, naming
    /// the feature's line and the field ([`refused`]).
    #[test]
    fn what_is_ambiguous_or_not_modelled_is_refused() {
        for (bad, field, message) in refused() {
            let bad = bad
                .replace(r#""id":"a""#, r#""id":"x""#)
                .replace(r#""id":"t""#, r#""id":"x""#);
            let e = middle(&bad);
            assert_eq!((e.line, e.field.as_str()), (Some(3), field), "{bad}");
            assert!(e.to_string().contains(message), "{e}");
        }
    }

    /// On the unrolled plane (where longitudes do not wrap) a step longer than 180° is an
    /// error for its feature, the file's others are read; a `longitudes` value other than
    /// `earth` or `unrolled` is a file error naming the member.
    #[test]
    fn the_unrolled_plane_refuses_long_steps() {
        let unrolled = |feats: &[&str]| {
            file(feats).replacen(
                "\"type\":\"FeatureCollection\",",
                "\"type\":\"FeatureCollection\",\"longitudes\":\"unrolled\",",
                1,
            )
        };
        let long = TRACK
            .replace("[[0,0],[1,1]]", "[[179.5,0],[-179.5,0]]")
            .replace(r#""id":"t""#, r#""id":"x""#);
        let r = parse(&unrolled(&[AREA, &long])).expect("a collection");
        assert_eq!(r.scenario.longitudes, Longitudes::Unrolled);
        assert_eq!(r.scenario.features.len(), 1);
        assert!(
            r.errors[0]
                .to_string()
                .contains("more than 180° of longitude apart"),
            "{}",
            r.errors[0]
        );
        // an unknown value is a file error naming the member
        let bad = file(&[AREA]).replacen(
            "\"type\":\"FeatureCollection\",",
            "\"type\":\"FeatureCollection\",\"longitudes\":\"flat\",",
            1,
        );
        let e = parse(&bad).expect_err("a file error");
        assert_eq!(e.field, "longitudes");
        assert!(
            e.to_string()
                .contains("\"earth\" (the default) or \"unrolled\""),
            "{e}"
        );
    }

    /// On the Earth a step across the antimeridian is read the shorter way (1°, not 359°),
    /// east-bound or west-bound; a longitude beyond ±180° names the same place as its
    /// value in (−180, 180], with a warning naming the position.
    #[test]
    fn longitudes_on_the_earth() {
        let track = |coords: &str| {
            TRACK
                .replace("[[0,0],[1,1]]", coords)
                .replace(r#""id":"t""#, r#""id":"x""#)
        };
        for (coords, lons) in [
            ("[[179.5,0],[-179.5,0]]", [179.5, 180.5]),
            ("[[-179.5,0],[179.5,0]]", [-179.5, -180.5]),
            ("[[-180,0],[179,0]]", [180.0, 179.0]),
            ("[[540.5,0],[-178.5,0]]", [-179.5, -178.5]),
        ] {
            let r = parse(&file(&[&track(coords)])).expect("a collection");
            assert!(r.errors.is_empty(), "{coords}: {:?}", r.errors);
            let Kind::Track(t) = &r.scenario.features[0].kind else {
                panic!("a track")
            };
            let got: Vec<f64> = t.waypoints.iter().map(|p| p.to_degrees().0).collect();
            assert_eq!(got, lons, "{coords}");
            // the leg is 1° of longitude long, on the equator
            let legs = sphere::track_legs(&t.waypoints, t.speed_kn, t.t0, t.dims);
            assert_eq!(legs.len(), 1, "{coords}: {:?}", t.waypoints);
            let nm = legs[0].length_nm;
            assert!((nm - 60.04).abs() < 0.01, "{coords}: {nm} nm");
        }
        let r = parse(&file(&[&track("[[190,0],[191,1]]")])).expect("a collection");
        assert_eq!(r.warnings.len(), 1, "{:?}", r.warnings);
        let w = r.warnings[0].to_string();
        assert!(
            w.contains("geometry.coordinates[0]: longitude 190 is beyond ±180°; read as -170"),
            "{w}"
        );
        let Kind::Track(t) = &r.scenario.features[0].kind else {
            panic!("a track")
        };
        assert_eq!(t.waypoints[0].to_degrees().0, -170.0);
    }
}
