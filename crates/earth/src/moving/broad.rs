//! Many movers against many areas (docs/moving-features.md, "Many flights, many areas"):
//! a broad phase over the areas' boxes that never drops a pair that can meet, and the
//! encounters of each mover with the areas it reaches.
//!
//! The areas' boxes on the Mercator plane (every keyframe's vertices: a moving vertex
//! stays within them) go into an R-tree once. For each segment of a mover, its fixes'
//! box (the legs between fixes are straight on the plane, so they stay in it) grown by
//! the largest reach of near_D (D·sec 89°/R, more than any `d_hi`) and of the margins
//! (below 10⁻⁹ of a turn), and shifted by whole turns to meet every copy of the areas'
//! longitudes, is queried; an area whose box it misses is farther than D from the
//! segment at every time, so the pair has no span.

use super::{next_down, next_up};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

use super::encounter::{
    check_mover, encounter, reach, unwrap_near, Encounter, EncounterError, Options, PreparedArea,
};
use super::model::{Area, Trajectory};
use crate::geodesy::Geodesy;

/// A whole turn of longitude, radians.
const TURN: f64 = 2.0 * core::f64::consts::PI;

/// An area's box and its index.
type AreaBox = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The areas, laid on the plane, and the tree of their boxes.
pub struct Areas {
    /// The areas that could be laid out, in input order of those.
    pub prepared: Vec<PreparedArea>,
    tree: RTree<AreaBox>,
    geodesy: Geodesy,
}

impl Areas {
    /// Lays out `areas` on the plane of `geo`; an area that cannot be (out of range,
    /// keyframes that change structure, …) is left out and its error returned.
    pub fn new(areas: &[Area], geo: Geodesy) -> (Areas, Vec<EncounterError>) {
        let mut prepared = Vec::with_capacity(areas.len());
        let mut errors = Vec::new();
        for a in areas {
            match PreparedArea::new(a, geo) {
                Ok(p) => prepared.push(p),
                Err(e) => errors.push(e),
            }
        }
        let boxes = prepared
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let b = p.bbox;
                GeomWithData::new(Rectangle::from_corners([b[0], b[1]], [b[2], b[3]]), i)
            })
            .collect();
        let tree = RTree::bulk_load(boxes);
        (
            Areas {
                prepared,
                tree,
                geodesy: geo,
            },
            errors,
        )
    }

    /// How many areas were laid out.
    pub fn len(&self) -> usize {
        self.prepared.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.prepared.is_empty()
    }

    /// The indices of the areas that the box [x0, y0, x1, y1] (radians, longitudes
    /// unwrapped) may reach within `sep_nm`, every copy a whole turn away included;
    /// sorted, without repeats.
    fn candidates(&self, b: [f64; 4], max_lat: f64, sep_nm: f64) -> Vec<usize> {
        let reach = reach(self.geodesy, sep_nm, max_lat);
        let (x0, x1) = (b[0] - reach, b[2] + reach);
        let (y0, y1) = (b[1] - reach, b[3] + reach);
        let mut out = Vec::new();
        // Shifts that bring the box's longitudes onto the areas' branch, [−π − ε, π + ε]
        // widened by the largest area's own reach past ±π (rings are unwrapped there).
        let k_lo = ((x0 - core::f64::consts::PI) / TURN).floor() as i64 - 1;
        let k_hi = ((x1 + core::f64::consts::PI) / TURN).ceil() as i64 + 1;
        for k in k_lo..=k_hi {
            let s = k as f64 * TURN;
            let env = AABB::from_corners(
                [next_down(x0 - s), next_down(y0)],
                [next_up(x1 - s), next_up(y1)],
            );
            out.extend(
                self.tree
                    .locate_in_envelope_intersecting(&env)
                    .map(|g| g.data),
            );
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// The fixes' box of each segment of `traj` on the plane of `geo` (longitudes unwrapped
/// each the shorter way from the one before, as the encounter does), [x0, y0, x1, y1],
/// and its largest |latitude| (radians).
fn segment_boxes(traj: &Trajectory, opts: &Options) -> Vec<([f64; 4], f64)> {
    let mut out = Vec::new();
    let mut cur: Option<([f64; 4], f64)> = None;
    let mut prev: Option<(f64, f64)> = None;
    for f in &traj.fixes {
        let lon = match prev {
            Some((t, l)) if f.t - t <= opts.max_gap_s => unwrap_near(f.lon, l),
            _ => {
                if let Some(b) = cur.take() {
                    out.push(b);
                }
                f.lon
            }
        };
        prev = Some((f.t, lon));
        let x = lon.to_radians();
        let y = opts.geodesy.mercator_y(f.lat.to_radians());
        if !x.is_finite() || !y.is_finite() {
            continue;
        }
        let lat = f.lat.to_radians().abs();
        cur = Some(match cur {
            None => ([x, y, x, y], lat),
            Some((b, l)) => (
                [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)],
                l.max(lat),
            ),
        });
    }
    out.extend(cur);
    out
}

/// Every area that `traj` meets, as an [`Encounter`] (in the areas' order), or the
/// mover's error (which stops this mover only).
pub fn encounters_of(
    traj: &Trajectory,
    areas: &Areas,
    opts: &Options,
) -> Result<Vec<Encounter>, EncounterError> {
    check_mover(traj, opts)?;
    let mut cand: Vec<usize> = segment_boxes(traj, opts)
        .into_iter()
        .flat_map(|(b, lat)| areas.candidates(b, lat, opts.sep_nm))
        .collect();
    cand.sort_unstable();
    cand.dedup();
    let mut out = Vec::new();
    for i in cand {
        if let Some(e) = encounter(traj, &areas.prepared[i], opts)? {
            out.push(e);
        }
    }
    Ok(out)
}

/// Every encounter of `movers` with `areas` (docs/moving-features.md, the answer of
/// `polyguard encounters`): the areas are laid out once, then each mover meets the areas
/// its segments reach. Items come in the CLI's order: first the error of each area that
/// cannot be laid out, then, mover by mover, its encounters in the areas' order or the
/// one error that stops that mover. An error's `id` names its area or mover.
///
/// ```
/// use polyguard_earth::moving::broad::encounters;
/// use polyguard_earth::moving::encounter::Options;
/// use polyguard_earth::moving::model::{Area, Fix, Rings, Shape, Trajectory};
///
/// // Eastbound along 0.5° N at 1° per 10 minutes, through the box 0°–1° E, 0°–1° N.
/// let fix = |t: f64, lon: f64| Fix { t, lon, lat: 0.5, alt_ft: None };
/// let flight = Trajectory {
///     id: "f1".into(),
///     callsign: None,
///     fixes: (0..=12).map(|k| fix(50.0 * k as f64, -0.5 + k as f64 / 12.0)).collect(),
/// };
/// let square = Area {
///     id: "box".into(),
///     name: None,
///     shape: Shape::Static(vec![Rings {
///         outer: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
///         holes: vec![],
///     }]),
///     floor_ft: None,
///     ceiling_ft: None,
/// };
/// let found: Vec<_> = encounters([flight], &[square], &Options::default())
///     .collect::<Result<_, _>>()
///     .expect("a good flight and a good box");
/// assert_eq!(found.len(), 1);
/// // It crosses 0° E at t = 300 s and flies on to its last fix (600 s, 0.5° E) inside.
/// let inside = &found[0].inside;
/// assert_eq!(inside.len(), 1);
/// assert!(inside[0].start[0] <= 300.0 && 300.0 <= inside[0].start[1]);
/// assert!(inside[0].end[0] <= 600.0 && 600.0 <= inside[0].end[1]);
/// assert!(inside[0].certain);
/// ```
pub fn encounters<I>(
    movers: I,
    areas: &[Area],
    opts: &Options,
) -> impl Iterator<Item = Result<Encounter, EncounterError>>
where
    I: IntoIterator<Item = Trajectory>,
{
    let opts = *opts;
    let (laid, errors) = Areas::new(areas, opts.geodesy);
    errors
        .into_iter()
        .map(Err)
        .chain(
            movers
                .into_iter()
                .flat_map(move |t| match encounters_of(&t, &laid, &opts) {
                    Ok(list) => list.into_iter().map(Ok).collect::<Vec<_>>(),
                    Err(e) => vec![Err(e)],
                }),
        )
}
