//! The planar model's data (docs/moving-features.md, "The planar model"): fixes and
//! keyframed polygons already on a plane, the relations asked, the spans answered and
//! the errors; [`super::plane`] computes with them.

/// One fix on the plane: at time `t` the mover is at `(x, y)`, height `z` when known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneFix {
    /// Time (seconds).
    pub t: f64,
    /// Abscissa.
    pub x: f64,
    /// Ordinate.
    pub y: f64,
    /// Height (feet), absent when unknown.
    pub z: Option<f64>,
}

/// One polygon on the plane: an outer ring and holes, not closed, either winding.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneRings {
    /// The outer ring.
    pub outer: Vec<[f64; 2]>,
    /// The holes.
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// An area's polygons at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneFrame {
    /// Time (seconds).
    pub t: f64,
    /// The parts (their union is the region).
    pub parts: Vec<PlaneRings>,
}

/// An area on the plane: static (one frame, its `t` ignored, existing at all times) or
/// keyframed (frames strictly increasing in time, the same structure in each, vertices
/// linear in time between them; existing from the first frame to the last).
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneArea {
    /// The frames.
    pub frames: Vec<PlaneFrame>,
    /// One frame valid at all times.
    pub is_static: bool,
    /// The floor (absent: unbounded below).
    pub floor: Option<f64>,
    /// The ceiling (absent: unbounded above).
    pub ceiling: Option<f64>,
}

/// Which set of times: inside, or near within D (plane units) and H (feet).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlaneRelation {
    /// inside(t): in the region, between floor and ceiling.
    Inside,
    /// near(t): horizontal distance to the region within `[d_lo, d_hi]`'s sandwich (on
    /// the plane both are D; the Earth layer makes them differ), vertically within `h` of
    /// the floor–ceiling slab.
    Near {
        /// A distance certainly within D on the Earth (plane units).
        d_lo: f64,
        /// A distance beyond which the Earth's distance certainly exceeds D.
        d_hi: f64,
        /// H, feet.
        h: f64,
    },
}

/// One span of the answer, in global time: each end an enclosure [lo, hi] of an exact
/// end; `certain` means the relation holds on all of [start\[1\], end\[0\]].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeSpan {
    /// Encloses where the relation starts to hold (or may).
    pub start: [f64; 2],
    /// Encloses where it stops.
    pub end: [f64; 2],
    /// The relation holds on all of [start\[1\], end\[0\]].
    pub certain: bool,
}

/// Why the planar spans cannot be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum PlaneError {
    /// A value is NaN or infinite (`what` names it).
    NotFinite {
        /// The value's name.
        what: String,
    },
    /// Times that do not strictly increase (`what` names them).
    NotIncreasing {
        /// The list's name.
        what: String,
    },
    /// The keyframes do not all have the same parts, holes and vertex counts.
    StructureChanges {
        /// The frame that differs from the first.
        frame: usize,
    },
    /// A ring with fewer than 3 vertices, or no frame at all.
    Degenerate {
        /// What is degenerate.
        what: String,
    },
}

impl core::fmt::Display for PlaneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            PlaneError::NotFinite { what } => write!(f, "{what}: not a finite number"),
            PlaneError::NotIncreasing { what } => write!(f, "{what}: times do not increase"),
            PlaneError::StructureChanges { frame } => write!(
                f,
                "frame {frame}: its parts, holes or vertex counts differ from frame 0 \
                 (linear interpolation needs the same structure at every instant)"
            ),
            PlaneError::Degenerate { what } => write!(f, "{what}: degenerate"),
        }
    }
}

impl std::error::Error for PlaneError {}
