//! Paper A §II.G: do two segments come within BUFF of each other?

use crate::ball::{mx, BallV, Tri};
use crate::contain::near_edge_rel;
use crate::predicates::{self as pr, Terms};
use crate::vect2::Vect2;

/// Paper A §II.G segments_close: is segment c d closer than BUFF to segment e f?
///
/// Certified: `false` only when the exact answer is false (see [`segments_close_rel`]).
#[inline]
///
/// ```
/// use polyguard::{segments_close, Vect2};
/// let v = Vect2::new;
/// // two crossing segments are at distance 0
/// assert!(segments_close(v(0.0, 0.0), v(2.0, 2.0), v(0.0, 2.0), v(2.0, 0.0), 0.01));
/// // parallel segments 1 apart
/// assert!(segments_close(v(0.0, 0.0), v(2.0, 0.0), v(0.0, 1.0), v(2.0, 1.0), 1.5));
/// assert!(!segments_close(v(0.0, 0.0), v(2.0, 0.0), v(0.0, 1.0), v(2.0, 1.0), 0.5));
/// ```
pub fn segments_close(c: Vect2, d: Vect2, e: Vect2, f: Vect2, buff: f64) -> bool {
    segments_close_tri(c, d, e, f, buff).or_true()
}

/// Paper A §II.G segments_close, three-valued, for exact float ends.
#[inline]
pub fn segments_close_tri(c: Vect2, d: Vect2, e: Vect2, f: Vect2, buff: f64) -> Tri {
    // The frame of c: every difference is rounded once, on the segments' own scale.
    segments_close_rel(
        BallV::ZERO,
        BallV::diff(d, c),
        BallV::diff(e, c),
        BallV::diff(f, c),
        buff,
        || {
            Some([
                Terms::ZERO,
                Terms::diff(d, c),
                Terms::diff(e, c),
                Terms::diff(f, c),
            ])
        },
    )
}

/// Paper A §II.G segments_close on balls: steps 1–2 test the four ends with near_edge;
/// step 4 (quad_min_box_le_D on ‖(c + r·u) − (e + t·w)‖², whose four sides are steps
/// 1–2 again) adds the segments that cross ([`pr::segments_cross`]).
///
/// Two filters go first, each certain: bounding boxes more than BUFF apart (enlarged by
/// the radii), and both ends of one segment beyond BUFF on one side of the other's line.
/// `terms` gives the four points' exact terms, for the comparisons balls cannot settle.
#[inline]
#[doc(hidden)]
pub fn segments_close_rel(
    c: BallV,
    d: BallV,
    e: BallV,
    f: BallV,
    buff: f64,
    terms: impl Fn() -> Option<[Terms; 4]>,
) -> Tri {
    segments_close_ordered(c, d, e, f, buff, terms, false)
}

/// [`segments_close_rel`], with step 4's crossing test before the two filters when
/// `cross_first`. A certain crossing and a certain filter cannot both hold, and the
/// answer is the same disjunction in either order. The crossing goes first where the
/// filters seldom fire and crossings are common: detect_same_2D's edges (§II.H step 3)
/// come here only past the side test of the path's line. Elsewhere (well_formed's pairs
/// of edges, mostly far apart) the filters go first.
#[inline]
pub(crate) fn segments_close_ordered(
    c: BallV,
    d: BallV,
    e: BallV,
    f: BallV,
    buff: f64,
    terms: impl Fn() -> Option<[Terms; 4]>,
    cross_first: bool,
) -> Tri {
    if pr::buff_outside_domain(buff) {
        return Tri::Unsure;
    }
    let early = if cross_first {
        match pr::segments_cross(c, d, e, f, &terms) {
            Tri::Yes => return Tri::Yes,
            other => Some(other),
        }
    } else {
        None
    };
    let r = mx(mx(c.r, d.r), mx(e.r, f.r));
    let gap = crate::ball::up(2.0 * (buff + 2.0 * r));
    let apart = |a1: f64, a2: f64, b1: f64, b2: f64| {
        // Ends are compared pairwise (no min/max): a non-finite end has an infinite
        // radius, so gap is then +∞ and nothing is filtered.
        (a1 - b1 > gap && a1 - b2 > gap && a2 - b1 > gap && a2 - b2 > gap)
            || (b1 - a1 > gap && b1 - a2 > gap && b2 - a1 > gap && b2 - a2 > gap)
    };
    // fl(x − y) > gap implies x − y > gap·(1 − u) > BUFF + 4r, and the exact ends are
    // within r of the computed ones: the exact gap exceeds BUFF.
    if apart(c.v.x, d.v.x, e.v.x, f.v.x) || apart(c.v.y, d.v.y, e.v.y, f.v.y) {
        return Tri::No;
    }
    if lines_separate(c, d, e, f, buff) || lines_separate(e, f, c, d, buff) {
        return Tri::No;
    }
    // Step 4's crossing before steps 1–2: the disjunction is the same, and a path through
    // an edge (the common hit) is settled by four orientations instead of four near_edge
    // tests.
    let cross = match early {
        Some(cross) => cross,
        None => pr::segments_cross(c, d, e, f, &terms),
    };
    if cross == Tri::Yes {
        return Tri::Yes;
    }
    let mut acc = cross;
    for (a, b, s) in [(2, 3, 0), (2, 3, 1), (0, 1, 2), (0, 1, 3)] {
        let pts = [c, d, e, f];
        let rel = || {
            let t = terms()?;
            Some((t[a].minus(&t[s])?, t[b].minus(&t[s])?))
        };
        match near_edge_rel(pts[a].sub(pts[s]), pts[b].sub(pts[s]), buff, rel) {
            Tri::Yes => return Tri::Yes,
            Tri::Unsure => acc = Tri::Unsure,
            Tri::No => {}
        }
    }
    acc
}

/// Are e and f both certainly farther than `dist` from the line through c and d, on the
/// same side? Then no point of segment e f is within `dist` of segment c d.
#[inline(always)]
fn lines_separate(c: BallV, d: BallV, e: BallV, f: BallV, dist: f64) -> bool {
    let m = d.sub(c);
    let side = pr::side_beyond(c, m, e, dist);
    side != 0 && side == pr::side_beyond(c, m, f, dist)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    fn v(x: f64, y: f64) -> Vect2 {
        Vect2::new(x, y)
    }

    /// Ends on a coarse grid (crossings, shared ends, touching and collinear segments)
    /// or anywhere in a small square, with BUFF from 0 to 1.
    fn pieces() -> impl Strategy<Value = ([Vect2; 4], f64)> {
        let coord = prop_oneof![(-4i8..=4).prop_map(|k| 0.5 * f64::from(k)), -2.0..2.0f64];
        let pt = (coord.clone(), coord).prop_map(|(x, y)| v(x, y));
        (
            prop::array::uniform4(pt),
            prop_oneof![Just(0.0), 0.0..1.0f64],
        )
    }

    /// segments_close with the crossing test first answers as with the filters first
    /// (a certain crossing and a certain filter cannot both hold). Liveness: the cases
    /// reach certain crossings and both certain answers, so the comparison compares
    /// something. Canary: a crossing-first that answered every certain non-crossing with
    /// no (skipping the ends' near_edge tests) would differ on more than 100 cases.
    #[test]
    fn the_crossing_first_changes_no_answer() {
        let mut runner = TestRunner::deterministic();
        let (mut crossings, mut yes, mut no, mut caught) = (0, 0, 0, 0);
        for _ in 0..20_000 {
            let ([c, d, e, f], buff) = pieces().new_tree(&mut runner).expect("a case").current();
            let (dc, ec, fc) = (BallV::diff(d, c), BallV::diff(e, c), BallV::diff(f, c));
            let terms = || {
                Some([
                    Terms::ZERO,
                    Terms::diff(d, c),
                    Terms::diff(e, c),
                    Terms::diff(f, c),
                ])
            };
            let first = segments_close_ordered(BallV::ZERO, dc, ec, fc, buff, terms, true);
            let last = segments_close_ordered(BallV::ZERO, dc, ec, fc, buff, terms, false);
            assert_eq!(first, last, "{c:?} {d:?} {e:?} {f:?} BUFF {buff}");
            let cross = pr::segments_cross(BallV::ZERO, dc, ec, fc, terms);
            crossings += usize::from(cross == Tri::Yes);
            // Canary: a crossing-first that answered a certain non-crossing with no,
            // skipping steps 1–2, differs from the filters-first answer here.
            caught += usize::from(cross == Tri::No && last != Tri::No);
            yes += usize::from(first == Tri::Yes);
            no += usize::from(first == Tri::No);
        }
        assert!(
            crossings > 1_000 && yes > 2_000 && no > 2_000,
            "{crossings} {yes} {no}"
        );
        assert!(caught > 100, "the canary was caught {caught} times");
    }

    #[test]
    fn crossing_segments_are_close() {
        // The diagonals of the square [0,2]²: they cross at (1,1); no end is near the
        // other segment (distance √2 > 0.5), so only step 4's interior minimum (0) decides.
        assert!(segments_close(
            v(0.0, 0.0),
            v(2.0, 2.0),
            v(0.0, 2.0),
            v(2.0, 0.0),
            0.5
        ));
    }

    #[test]
    fn parallel_segments_at_exactly_buff_are_not_close() {
        // y = 0 and y = 1 over x ∈ [0, 4]: distance exactly 1 = BUFF (strict test: false);
        // disc = c² − 4ab = 64 − 64 = 0 here.
        assert!(!segments_close(
            v(0.0, 0.0),
            v(4.0, 0.0),
            v(0.0, 1.0),
            v(4.0, 1.0),
            1.0
        ));
        assert!(segments_close(
            v(0.0, 0.0),
            v(4.0, 0.0),
            v(0.0, 1.0),
            v(4.0, 1.0),
            1.0 + 1.0 / 1024.0
        ));
    }

    #[test]
    fn the_box_filter_compares_every_pair_of_ends() {
        // Two segments on the x axis 0.05 apart (BUFF 0.1), in frames where the first
        // end is not the origin (as edge_detect passes them): whichever ends are the
        // near ones, the bounding-box filter must not call them apart.
        let b = |x: f64| BallV::exact(v(x, 0.0));
        for (c, d, e, f) in [
            (5.0, 6.0, 4.95, 0.0),
            (5.0, 6.0, 0.0, 4.95),
            (6.0, 5.0, 4.95, 0.0),
            (6.0, 5.0, 0.0, 4.95),
        ] {
            // and mirrored (the other half of the filter), and with the segments swapped
            for (c, d, e, f) in [
                (c, d, e, f),
                (-c, -d, -e, -f),
                (e, f, c, d),
                (-e, -f, -c, -d),
            ] {
                assert_eq!(
                    segments_close_rel(b(c), b(d), b(e), b(f), 0.1, || None),
                    Tri::Yes,
                    "{c} {d} / {e} {f}"
                );
            }
        }
    }

    #[test]
    fn far_segments_are_not_close() {
        assert!(!segments_close(
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(3.0, 3.0),
            v(4.0, 5.0),
            1.0
        ));
        // A T-junction gap of 0.25: close for BUFF 0.5, not for BUFF 0.25.
        assert!(segments_close(
            v(0.0, 0.0),
            v(4.0, 0.0),
            v(2.0, 0.25),
            v(2.0, 3.0),
            0.5
        ));
        assert!(!segments_close(
            v(0.0, 0.0),
            v(4.0, 0.0),
            v(2.0, 0.25),
            v(2.0, 3.0),
            0.25
        ));
    }
}
