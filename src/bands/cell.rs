//! One cell's certificate (the parent module's "certificate between samples" and
//! "prefilter and early exit"; paper A §II–§III's motion through the scan of
//! `crate::intervals`), refined into bands by [`super::refine`].

use std::boxed::Box;
use std::vec::Vec;

use super::refine::{refine, CellTest};
use super::rigid::Rigid;
use super::{BandKind, Bands, Traffic, Tri};
use crate::ball::{round_down, round_up};
use crate::intervals::{Class, Heights, Pieces, Relation, Scan, Separation, Workspace};
use crate::vect2::Vect2;

/// 2⁻⁴⁹: the velocity slack per unit of speed (twice the 2⁻⁵⁰ that the f64 velocities
/// of the sample and of a course need, parent module's rounding analysis).
const SLACK: f64 = 1.0 / 562_949_953_421_312.0;

/// 2⁻⁵¹ ≥ 2π − fl(2π): half an ulp of 2π, added to the last course cell's half width.
const TAU_GAP: f64 = 1.0 / 2_251_799_813_685_248.0;

/// Which parameter the cells vary.
#[derive(Clone, Copy, Debug)]
pub(super) enum Family {
    /// One fixed velocity (no cell: r = 0).
    Fixed { v: Vect2 },
    /// The course at this speed.
    Course { speed: f64 },
    /// The speed at this course.
    Speed { course: f64 },
    /// The vertical speed with this horizontal velocity.
    Vertical { v: Vect2 },
}

/// A cell's sample and radii: the velocity at the midpoint, its vertical speed (3D),
/// and the horizontal and vertical displacement bounds r and r_z over [0, T].
#[derive(Clone, Copy, Debug)]
struct Probe {
    v: Vect2,
    vz: Option<f64>,
    r: f64,
    rz: f64,
}

/// How many time slices the prefilter boxes cut [0, T] into.
const SLICES: usize = 8;

/// The ends of the prefilter's time slices: 0, T/8, ..., T (float times; consecutive
/// slices share their float end, so together they cover [0, T]).
fn slice_ends(t: f64) -> [f64; SLICES + 1] {
    let mut ends = [t; SLICES + 1];
    for (k, e) in ends.iter_mut().enumerate().take(SLICES) {
        *e = t * (k as f64 / SLICES as f64);
    }
    ends
}

/// The most cells a band answer starts with (see [`Tester::first_cells`]).
const FIRST_CELLS_MAX: usize = 256;

/// A box [lo.x, hi.x] × [lo.y, hi.y].
#[derive(Clone, Copy, Debug)]
struct Box2 {
    lo: Vect2,
    hi: Vect2,
}

impl Box2 {
    /// The box of the points a + τ·w for τ ∈ [t0, t1] (the segment between its ends),
    /// each end rounded outward.
    fn between(a: Vect2, w: Vect2, t0: f64, t1: f64) -> Box2 {
        let lo = |x: f64, y: f64, t: f64| round_down(x + round_down(t * y));
        let hi = |x: f64, y: f64, t: f64| round_up(x + round_up(t * y));
        Box2 {
            lo: Vect2::new(
                lo(a.x, w.x, t0).min(lo(a.x, w.x, t1)),
                lo(a.y, w.y, t0).min(lo(a.y, w.y, t1)),
            ),
            hi: Vect2::new(
                hi(a.x, w.x, t0).max(hi(a.x, w.x, t1)),
                hi(a.y, w.y, t0).max(hi(a.y, w.y, t1)),
            ),
        }
    }

    /// The box of a moving polygon over [t0, t1]: each vertex moves along a segment.
    fn polygon(p: &[Vect2], vels: &[Vect2], t0: f64, t1: f64) -> Box2 {
        let mut b = Box2::between(p[0], vels[0], t0, t1);
        for (&a, &w) in p.iter().zip(vels).skip(1) {
            b = b.join(Box2::between(a, w, t0, t1));
        }
        b
    }

    /// Is the box narrower than 2·depth along x or y (rounded down)? Then no point of
    /// a polygon inside it is farther than `depth` from the polygon's boundary.
    fn narrower_than(self, depth: f64) -> bool {
        let twice = 2.0 * depth;
        round_down(self.hi.x - self.lo.x) < twice || round_down(self.hi.y - self.lo.y) < twice
    }

    /// The smallest box holding both.
    fn join(self, o: Box2) -> Box2 {
        Box2 {
            lo: Vect2::new(self.lo.x.min(o.lo.x), self.lo.y.min(o.lo.y)),
            hi: Vect2::new(self.hi.x.max(o.hi.x), self.hi.y.max(o.hi.y)),
        }
    }

    /// Is the gap between the boxes along x or along y (rounded down) larger than
    /// `reach`? Then every pair of their points is farther apart than `reach`.
    fn apart(self, o: Box2, reach: f64) -> bool {
        round_down(o.lo.x - self.hi.x) > reach
            || round_down(self.lo.x - o.hi.x) > reach
            || round_down(o.lo.y - self.hi.y) > reach
            || round_down(self.lo.y - o.hi.y) > reach
    }
}

/// The scan's pieces until the first one that does not fail: did all fail?
struct AllFail {
    all: bool,
}

impl Pieces for AllFail {
    /// Stops at the first piece that is not certainly false.
    fn piece(&mut self, _a: f64, _b: f64, class: Class) -> bool {
        if class != Class::Fails {
            self.all = false;
        }
        !self.all
    }
}

/// The scan's pieces until the first of class `want`: was there one?
struct Find {
    want: Class,
    found: bool,
}

impl Pieces for Find {
    /// Stops at the first piece of the wanted class.
    fn piece(&mut self, _a: f64, _b: f64, class: Class) -> bool {
        self.found = class == self.want;
        self.found
    }
}

/// The certificate's machinery for one traffic situation and one parameter family.
pub(super) struct Tester<'a> {
    traffic: &'a Traffic<'a>,
    family: Family,
    /// Each obstacle's swept boxes over the [`SLICES`] slices of [0, T].
    boxes: Vec<[Box2; SLICES]>,
    /// Each obstacle's common vertex velocity when it translates rigidly without a
    /// slab (the parent module's fast path), else `None`.
    rigid: Vec<Option<Vect2>>,
    ws: Box<Workspace>,
}

impl<'a> Tester<'a> {
    /// The boxes of a validated situation.
    pub(super) fn new(traffic: &'a Traffic<'a>, family: Family) -> Tester<'a> {
        let ends = slice_ends(traffic.t);
        let boxes = traffic
            .obstacles
            .iter()
            .map(|o| {
                let mut slices = [Box2::polygon(o.p, o.vels, 0.0, 0.0); SLICES];
                for (k, b) in slices.iter_mut().enumerate() {
                    *b = Box2::polygon(o.p, o.vels, ends[k], ends[k + 1]);
                }
                slices
            })
            .collect();
        let rigid = traffic
            .obstacles
            .iter()
            .map(|o| {
                let v = o.vels[0];
                (o.slab.is_none() && o.vels.iter().all(|&w| w == v)).then_some(v)
            })
            .collect();
        Tester {
            traffic,
            family,
            boxes,
            rigid,
            ws: Box::new(Workspace::new()),
        }
    }

    /// The sample and radii of the cell [lo, hi] (parent module: r of each family).
    fn probe(&self, lo: f64, hi: f64) -> Probe {
        let t = self.traffic.t;
        let vz = self.traffic.height.map(|z| z.vz);
        let m = lo + (hi - lo) * 0.5;
        let half = round_up((m - lo).max(hi - m));
        match self.family {
            Family::Fixed { v } => Probe {
                v,
                vz,
                r: 0.0,
                rz: 0.0,
            },
            Family::Course { speed } => {
                let mut delta = half;
                if hi >= core::f64::consts::TAU {
                    delta = round_up(delta + TAU_GAP);
                }
                let delta = delta.min(core::f64::consts::PI);
                let chord = round_up(2.0 * libm::sin(delta * 0.5));
                Probe {
                    v: super::velocity(speed, m),
                    vz,
                    r: round_up(round_up(t * speed) * round_up(chord + SLACK)),
                    rz: 0.0,
                }
            }
            Family::Speed { course } => Probe {
                v: super::velocity(m, course),
                vz,
                r: round_up(t * round_up(half + round_up(hi * SLACK))),
                rz: 0.0,
            },
            Family::Vertical { v } => Probe {
                v,
                vz: Some(m),
                r: 0.0,
                rz: round_up(t * half),
            },
        }
    }

    /// Runs one scan of obstacle i with `consumer` (a case the scan refuses gives
    /// nothing: the consumer's initial answer stands).
    fn scan(
        &mut self,
        i: usize,
        pr: &Probe,
        heights: Option<Heights>,
        relation: Relation,
        sep: Separation,
        consumer: &mut impl Pieces,
    ) -> bool {
        let o = &self.traffic.obstacles[i];
        let tr = self.traffic;
        match Scan::new(
            tr.t,
            tr.s,
            pr.v,
            o.p,
            o.vels,
            heights,
            relation,
            sep,
            self.ws.parts(),
        ) {
            Some(mut scan) => {
                scan.run(consumer);
                true
            }
            None => false,
        }
    }

    /// The slab of obstacle i for the sample, its ends moved by `grow` (outward when
    /// positive), rounded toward the inside when `inward` and outward otherwise; `None`
    /// in 2D or for an obstacle without a slab.
    fn heights(&self, i: usize, pr: &Probe, grow: f64, inward: bool) -> Option<Heights> {
        let z = self.traffic.height?;
        let slab = self.traffic.obstacles[i].slab?;
        let (bottom, top) = if inward {
            (round_up(slab.bottom - grow), round_down(slab.top + grow))
        } else {
            (round_down(slab.bottom - grow), round_up(slab.top + grow))
        };
        Some(Heights {
            sz: z.sz,
            vz: pr.vz.unwrap_or(z.vz),
            bottom,
            top,
            vsp: slab.vsp,
        })
    }

    /// Is the point moving at `v` farther than `reach` from obstacle i throughout
    /// [0, T]? In each time slice their boxes are apart by more than `reach` along x
    /// or y (the parent module's prefilter).
    fn apart(&self, i: usize, v: Vect2, reach: f64) -> bool {
        let ends = slice_ends(self.traffic.t);
        self.boxes[i].iter().enumerate().all(|(k, b)| {
            b.apart(
                Box2::between(self.traffic.s, v, ends[k], ends[k + 1]),
                reach,
            )
        })
    }

    /// The certificate for obstacle i on a cell (parent module): `No` Clear, `Yes`
    /// Conflict, `Unsure` neither.
    fn verdict(&mut self, i: usize, pr: &Probe) -> Tri {
        let Separation { d, h } = self.traffic.sep;
        // Clear: near_{D+r} (and H + r_z) is empty at the sample.
        let reach = round_up(d + pr.r);
        // The fast path for a rigidly translating obstacle (its own box test replaces
        // the sliced prefilter), then the scans it left able to decide.
        let (mut scan_clear, mut scan_conflict) = (true, true);
        let tr = self.traffic;
        let rigid =
            self.rigid[i].and_then(|vel| Rigid::new(tr.obstacles[i].p, vel, tr.s, pr.v, tr.t));
        if let Some(g) = rigid {
            let near = (pr.r <= d).then(|| round_down(d - pr.r).max(0.0));
            let deep = round_up(pr.r - d);
            let judged = g.judge(reach, near, deep);
            if judged.tri != Tri::Unsure {
                return judged.tri;
            }
            (scan_clear, scan_conflict) = (judged.scan_clear, judged.scan_conflict);
        } else if self.apart(i, pr.v, reach) {
            return Tri::No;
        }
        let grown = round_up(h + pr.rz);
        let z = self.heights(i, pr, grown, false);
        let mut all = AllFail { all: true };
        let ran = scan_clear
            && self.scan(
                i,
                pr,
                z,
                Relation::Near,
                Separation { d: reach, h: 0.0 },
                &mut all,
            );
        if ran && all.all {
            return Tri::No;
        }
        // Conflict: the slab moved inward by r_z − H (outward by H − r_z).
        let grow = if pr.rz <= h {
            round_down(h - pr.rz).max(0.0)
        } else {
            -round_up(pr.rz - h)
        };
        let z = self.heights(i, pr, grow, true);
        let found = if !scan_conflict {
            false
        } else if pr.r <= d {
            let near = Separation {
                d: round_down(d - pr.r).max(0.0),
                h: 0.0,
            };
            let mut f = Find {
                want: Class::Holds,
                found: false,
            };
            self.scan(i, pr, z, Relation::Near, near, &mut f) && f.found
        } else if self.boxes[i]
            .iter()
            .all(|b| b.narrower_than(round_up(pr.r - d)))
        {
            // No point of the obstacle is r − D deep inside: its swept box is narrower.
            false
        } else {
            let deep = Separation {
                d: round_up(pr.r - d),
                h: 0.0,
            };
            let mut f = Find {
                want: Class::Fails,
                found: false,
            };
            self.scan(i, pr, z, Relation::Breach, deep, &mut f) && f.found
        };
        if found {
            Tri::Yes
        } else {
            Tri::Unsure
        }
    }

    /// Conflict at one velocity (r = 0): `Yes`, `No` or `Unsure` over all obstacles.
    pub(super) fn at_velocity(&mut self, v: Vect2) -> Tri {
        let pr = Probe {
            v,
            vz: self.traffic.height.map(|z| z.vz),
            r: 0.0,
            rz: 0.0,
        };
        let mut all_clear = true;
        for i in 0..self.traffic.obstacles.len() {
            match self.verdict(i, &pr) {
                Tri::Yes => return Tri::Yes,
                Tri::No => {}
                Tri::Unsure => all_clear = false,
            }
        }
        if all_clear {
            Tri::No
        } else {
            Tri::Unsure
        }
    }

    /// Tests the cell [lo, hi] against the obstacles `open` (the parent's open ones):
    /// Conflict when one is, Clear when all are, else Unknown with the ones left open.
    fn test_cell(&mut self, lo: f64, hi: f64, open: &[u32]) -> (BandKind, Vec<u32>) {
        let pr = self.probe(lo, hi);
        let mut left = Vec::new();
        for &i in open {
            match self.verdict(i as usize, &pr) {
                Tri::Yes => return (BandKind::Conflict, Vec::new()),
                Tri::No => {}
                Tri::Unsure => left.push(i),
            }
        }
        let kind = if left.is_empty() {
            BandKind::Clear
        } else {
            BandKind::Unknown
        };
        (kind, left)
    }

    /// How many equal cells to start with: the fewest (a power of two, at most
    /// [`FIRST_CELLS_MAX`]) whose radius is at most the separation it is added to (D,
    /// or H for vertical speeds): coarser cells could not be decided but where no
    /// obstacle is near.
    fn first_cells(&self, lo: f64, hi: f64) -> usize {
        let Separation { d, h } = self.traffic.sep;
        let mut n = 1;
        while n < FIRST_CELLS_MAX {
            let pr = self.probe(lo, lo + (hi - lo) / n as f64);
            if pr.r <= d && pr.rz <= h {
                break;
            }
            n *= 2;
        }
        n
    }

    /// The band answer over [lo, hi] (parent module's refinement).
    pub(super) fn bands(mut self, lo: f64, hi: f64, unknown_max: f64) -> Bands {
        let n = self.first_cells(lo, hi);
        refine(&mut self, lo, hi, n, unknown_max)
    }
}

impl CellTest for Tester<'_> {
    type Open = Vec<u32>;

    fn everything(&self) -> Vec<u32> {
        (0..self.traffic.obstacles.len() as u32).collect()
    }

    fn test(&mut self, lo: f64, hi: f64, open: &Vec<u32>) -> (BandKind, Vec<u32>) {
        self.test_cell(lo, hi, open)
    }
}
