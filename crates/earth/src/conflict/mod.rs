//! Paper B, Sections III–IV: the four-stage interference identification.
//!
//! Stages are separate functions with typed inputs and outputs, composed by
//! [`pipeline::run`]:
//!
//! | stage | paper | input → output |
//! | --- | --- | --- |
//! | [`stage1`] | Algorithm 2, eqs 3–6 | objects → [`stage1::Candidates`] |
//! | [`stage2`] | eqs 7–10 | candidates → [`stage2::Region`]s |
//! | [`stage3`] | eqs 11–13, Algorithm 3 | regions → [`stage3::Window`]s |
//! | [`stage4`] | eqs 14–20 (replaced) | windows → [`stage4::Interval`]s |
//!
//! Everything happens in the Mercator plane of [`crate::sphere`] (radians). A track of
//! several waypoints becomes one [`Object`] per leg; legs of one track never conflict
//! with each other, and the pipeline merges the legs' answers per feature pair.

pub mod geom;
pub mod pipeline;
pub mod stage1;
pub mod stage2;
pub mod stage3;
pub mod stage4;

use crate::sphere::{Leg, Merc};

/// Paper B stage 4 tolerance: the default time tolerance of first/last conflict times,
/// one second in hours.
pub const DEFAULT_TIME_TOLERANCE_H: f64 = 1.0 / 3600.0;

/// How an object moves (Paper B eq 1: static polygons have constant vertices).
#[derive(Clone, Debug)]
pub enum Motion {
    /// A static area: a simple ring in the Mercator plane, counter-clockwise, not closed
    /// (the last vertex differs from the first), possibly non-convex.
    Static {
        /// The ring.
        ring: Vec<Merc>,
        /// The holes (clockwise, not closed): inside `ring`, not part of the area (their
        /// boundaries are).
        holes: Vec<Vec<Merc>>,
        /// Whether the ring is convex and has no holes (enables the fast convex paths).
        convex: bool,
    },
    /// One leg of a track: a Table 2 rectangle on a rhumb line (boxed: a leg is 400
    /// bytes, and an area's object would carry that much unused; 200 MB on 10⁶ objects).
    Moving(Box<Leg>),
}

/// Paper B eq 1: one polygon `i` with its life `[t0, tf]`, its motion, the conservative
/// region `Γ` it can occupy (eq 7/8) and the AABB of that region (eqs 3–6).
#[derive(Clone, Debug)]
pub struct Object {
    /// Index of the scenario feature the object belongs to.
    pub owner: u32,
    /// `t0^i` (h); `-∞` for an area without a start.
    pub t0: f64,
    /// `tf^i` (h); `+∞` for an area without an end.
    pub t1: f64,
    /// The motion.
    pub motion: Motion,
    /// `Γ^i`: the static ring itself, or the conservative swept hull of a leg (ccw).
    pub sweep: Vec<Merc>,
    /// AABB `[L, B, R, T]` of `sweep` (eqs 3–6).
    pub aabb: [f64; 4],
    /// Paper B eq 7 as printed, for legs: the hull of the rectangle at `t0` and `tf`
    /// (reporting the paper's stage 3 windows only; empty for areas).
    pub paper_sweep: Vec<Merc>,
    /// For legs, stage 3's per-object constants (eqs 11–13), computed once.
    pub projection: Option<stage3::Projection>,
    /// On the Earth ([`Object::on_earth`]): which of the object's copies this is, 0 for
    /// the first (the one drawn); always 0 on a plane that does not wrap.
    pub copy: u16,
    /// Whether the plane wraps (x is longitude on the Earth, 2π one turn): stage 1 then
    /// keeps each pair in one copy only ([`stage1::wanted`]). True for the constructors'
    /// objects; [`Object::on_plane`] clears it.
    pub earth: bool,
}

impl Object {
    /// A static area alive over `[t0, t1]`; `ring` in the Mercator plane, any orientation.
    pub fn area(owner: u32, ring: Vec<Merc>, t0: f64, t1: f64) -> Object {
        Object::area_with_holes(owner, ring, Vec::new(), t0, t1)
    }

    /// A static area with holes (GeoJSON interior rings), alive over `[t0, t1]`; any
    /// orientation. The holes must lie inside `ring` without touching it or each other
    /// (as the scenario reader checks). `Γ` is the exterior ring; the holes take part in
    /// stage 2's decision and region and in stage 4's distances.
    pub fn area_with_holes(
        owner: u32,
        ring: Vec<Merc>,
        holes: Vec<Vec<Merc>>,
        t0: f64,
        t1: f64,
    ) -> Object {
        let ring = geom::ccw(ring);
        let holes: Vec<Vec<Merc>> = holes
            .into_iter()
            .map(|h| {
                let mut h = geom::ccw(h);
                h.reverse();
                h
            })
            .collect();
        let convex = holes.is_empty() && geom::is_convex(&ring);
        let aabb = geom::bbox(&ring);
        Object {
            owner,
            t0,
            t1,
            sweep: ring.clone(),
            motion: Motion::Static {
                ring,
                holes,
                convex,
            },
            aabb,
            paper_sweep: Vec::new(),
            projection: None,
            copy: 0,
            earth: true,
        }
    }

    /// A leg of a track. Its `Γ` is eq 7 made conservative: the hull of the two
    /// reference-point ends each shifted by every corner of the per-vertex offset boxes of
    /// [`Leg::offset_boxes`] (the paper's hull of the rectangles at `t0` and `tf` assumes
    /// linear vertex motion, which rhumb rectangles do not have).
    pub fn leg(owner: u32, leg: Leg) -> Object {
        let [c0, c1] = leg.merc;
        let boxes = leg.offset_boxes();
        let mut pts = Vec::with_capacity(32);
        for c in [c0, c1] {
            for b in boxes.iter() {
                for (x, y) in [(b[0], b[2]), (b[1], b[2]), (b[1], b[3]), (b[0], b[3])] {
                    pts.push([c[0] + x, c[1] + y]);
                }
            }
        }
        // the hulls' buffers are made for twice their input (64 and 16 points): a leg
        // held 1.3 kB of them, 650 MB on 10⁶ objects
        let mut sweep = geom::convex_hull(&pts);
        sweep.shrink_to_fit();
        let aabb = geom::bbox(&sweep);
        let mut ends = leg.merc_vertices_at(leg.t0).to_vec();
        ends.extend_from_slice(&leg.merc_vertices_at(leg.t1));
        let mut paper_sweep = geom::convex_hull(&ends);
        paper_sweep.shrink_to_fit();
        let projection = Some(stage3::Projection::with_boxes(&leg, &boxes));
        Object {
            owner,
            t0: leg.t0,
            t1: leg.t1,
            motion: Motion::Moving(Box::new(leg)),
            sweep,
            aabb,
            paper_sweep,
            projection,
            copy: 0,
            earth: true,
        }
    }

    /// The object on a plane that does not wrap (the unrolled strip of
    /// `generate --density-box`): x is a coordinate like any other.
    pub fn on_plane(mut self) -> Object {
        self.earth = false;
        self
    }

    /// The object on the Earth, whose Mercator plane wraps every 2π of x (one turn of
    /// longitude): its copies moved by whole turns, one for each k whose copy, moved by
    /// −2π·k, reaches into the strip [−π, π] (with a margin of [`stage1::WRAP_MARGIN`]).
    /// Every place the object covers lies in that strip in one of its copies; so when two
    /// objects meet somewhere on the Earth, the two copies that put the place in the
    /// strip meet there on the plane, and stage 1 finds them. An object inside (−π, π)
    /// is its only copy, unchanged.
    pub fn on_earth(self) -> Vec<Object> {
        use std::f64::consts::{PI, TAU};
        let reach = PI + stage1::WRAP_MARGIN;
        let (lo, hi) = (self.aabb[0], self.aabb[2]);
        if !(lo.is_finite() && hi.is_finite()) || (lo >= -PI && hi <= PI) {
            return vec![self];
        }
        // k with lo − 2πk ≤ reach and hi − 2πk ≥ −reach
        let k_lo = ((lo - reach) / TAU).ceil() as i64;
        let k_hi = ((hi + reach) / TAU).floor() as i64;
        let mut out = Vec::with_capacity((k_hi - k_lo + 1).max(0) as usize);
        for k in k_lo..=k_hi {
            let dx = -TAU * k as f64;
            let mut o = if k == 0 {
                self.clone()
            } else {
                self.shifted(dx)
            };
            o.copy = out.len() as u16;
            out.push(o);
        }
        out
    }

    /// The object moved `dx` east on the plane (rebuilt from its moved geometry).
    fn shifted(&self, dx: f64) -> Object {
        let mut o = match &self.motion {
            Motion::Static { ring, holes, .. } => {
                let mv = |r: &[Merc]| r.iter().map(|p| [p[0] + dx, p[1]]).collect();
                Object::area_with_holes(
                    self.owner,
                    mv(ring),
                    holes.iter().map(|h| mv(h)).collect(),
                    self.t0,
                    self.t1,
                )
            }
            Motion::Moving(leg) => Object::leg(self.owner, leg.shifted(dx)),
        };
        o.earth = self.earth;
        o
    }

    /// The holes of a static area (clockwise); none for a leg.
    pub fn holes(&self) -> &[Vec<Merc>] {
        match &self.motion {
            Motion::Static { holes, .. } => holes,
            Motion::Moving(_) => &[],
        }
    }

    /// Is the object moving?
    pub fn is_moving(&self) -> bool {
        matches!(self.motion, Motion::Moving(_))
    }

    /// Is the object's polygon convex at all times (legs' rectangles are)?
    pub fn is_convex(&self) -> bool {
        match &self.motion {
            Motion::Static { convex, .. } => *convex,
            Motion::Moving(_) => true,
        }
    }

    /// Paper B eq 1: the polygon's vertices at time `t`, written into `out`.
    pub fn vertices_at(&self, t: f64, out: &mut Vec<Merc>) {
        out.clear();
        match &self.motion {
            Motion::Static { ring, .. } => out.extend_from_slice(ring),
            Motion::Moving(leg) => out.extend_from_slice(&leg.merc_vertices_at(t)),
        }
    }

    /// Upper bound on the Mercator speed of every vertex (0 for a static area).
    pub fn speed_bound(&self) -> f64 {
        match &self.motion {
            Motion::Static { .. } => 0.0,
            Motion::Moving(leg) => leg.merc_speed_bound(),
        }
    }

    /// Velocity envelope for stage 4: every vertex velocity is `σ e + w` with
    /// `σ ∈ [σ_lo, σ_hi]` and `|w| ≤ deform` (see
    /// [`Leg::reference_velocity_envelope`], [`Leg::deformation_speed_bound`]).
    /// Returns `(e, σ_lo, σ_hi, deform)`; all zero for a static area.
    pub fn velocity_envelope(&self) -> (Merc, f64, f64, f64) {
        match &self.motion {
            Motion::Static { .. } => ([0.0, 0.0], 0.0, 0.0, 0.0),
            Motion::Moving(leg) => {
                let (e, lo, hi) = leg.reference_velocity_envelope();
                (e, lo, hi, leg.deformation_speed_bound())
            }
        }
    }

    /// Paper B eq 20: `Some(v)` when every vertex moves with the constant velocity `v`.
    pub fn linear_velocity(&self) -> Option<Merc> {
        match &self.motion {
            Motion::Static { .. } => Some([0.0, 0.0]),
            Motion::Moving(leg) => leg.linear_velocity(),
        }
    }
}
