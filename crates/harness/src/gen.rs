//! Boundary-biased case generators over the whole scale space: where floating point breaks.
//!
//! Every case puts the point at a threshold of one of paper A's decisions, moved by a
//! relative ε that is 0, a few ulps, or 10⁻¹⁵ … 10⁻³ either way ([`Mode`]):
//! a distance BUFF·(1 ± ε) from an edge or a vertex (near_edge), a vertex at
//! |p_x − s_x| = BUFF·(1 ± ε) or p_y = s_y − BUFF·(1 ± ε) (the perturbation of §II.B),
//! a trajectory through a vertex or tangent to / along an edge, first contact at
//! t = T·(1 ± ε) or at t = 0, the end of an extended edge (1 + F)·(1 ± ε) (edge_detect),
//! an edge whose ends move alike (dot_nn_lin's vanishing leading coefficient), and a
//! slab boundary reached at the contact time (detect_3d).
//!
//! On top of the threshold, every mode draws its scales independently and log-uniformly
//! ([`Space`]):
//! - the relative path (the point's path relative to the polygon over the lookahead)
//!   from 10⁻³ to 10⁷ polygon sizes; paths beyond 3 sizes are made by [`stretch`]ing a
//!   short case back in time, so that the threshold configuration lies far along a
//!   long path;
//! - BUFF from 10⁻¹² to 1 polygon size;
//! - the offset of the polygon from the origin up to 10⁹, with size / |offset| from
//!   10⁻¹² to 1 (a fifth of the cases sit at the origin, sizes 10⁻⁶ … 10⁶);
//! - the lookahead T from 10⁻⁶ to 10⁹, speeds to match;
//! - the outline ([`Outline`]): star-shaped polygons of 3 … 12 vertices, of up to 256,
//!   needles of aspect down to 10⁻⁸, near-collinear vertices, short edges beside long
//!   ones;
//! - in 3D, slabs from 10⁻⁶ to 10³ polygon sizes thick;
//! - the absolute scale: one case in eight is moved whole by a power of two to an end
//!   of the float range, BUFF subnormal (2⁻¹⁰⁷² … 2⁻¹⁰⁴⁰, where coordinates round to
//!   the subnormal grid and thresholds become exact ties) or the largest length near
//!   2⁹⁰⁰ … 2¹⁰⁰⁰ ([`absolute_scale`]). A subnormal BUFF is how a skip margin that
//!   rounded back to BUFF was found (tests/regressions/subnormal.jsonl).
//!
//! Warping polygons are drawn as an affine warp plus a jitter scaled to the outline's
//! finest feature, with one edge whose ends move alike; the polygon's simplicity over
//! [0, T] is decided exactly ([`polyguard_oracle::truth::simple_on_window`]) and a case
//! that fails is redrawn with a gentler warp (the last resort is none). Polygons at
//! time 0 are checked simple and counterclockwise exactly ([`polyguard::ring::simple_ccw`]).
//!
//! The choices are drawn from a [`Source`]: [`SplitMix`] for seeded runs, [`Bytes`] for
//! fuzzers (the fuzzer's input bytes steer every choice).

use crate::case::RawCase;
use polyguard::vect2::Vect2;

/// Where the generator's choices come from.
pub trait Source {
    /// 64 fresh bits.
    fn next_u64(&mut self) -> u64;

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform in 0..n (n > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
    /// One of the items.
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }
    /// A fair coin.
    fn coin(&mut self) -> bool {
        self.next_u64() & 1 == 1
    }
}

/// SplitMix64: seeded, tiny, the same on every machine.
#[derive(Clone, Debug)]
pub struct SplitMix(pub u64);

impl Source for SplitMix {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// A fuzzer's input as a source: 8 bytes per draw, zeros once exhausted.
#[derive(Clone, Debug)]
pub struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Bytes<'a> {
    /// Draws from `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Bytes { data, pos: 0 }
    }
}

impl Source for Bytes<'_> {
    fn next_u64(&mut self) -> u64 {
        let mut buf = [0u8; 8];
        for b in buf.iter_mut() {
            if let Some(&x) = self.data.get(self.pos) {
                *b = x;
            }
            self.pos += 1;
        }
        u64::from_le_bytes(buf)
    }
}

/// The threshold a case is built on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mode {
    /// s at BUFF·(1 + ε) outside an edge.
    EdgeBuff,
    /// s at BUFF·(1 + ε) from a vertex.
    VertexBuff,
    /// A vertex at |p_x − s_x| = BUFF·(1 + ε), above s (perturbation's x threshold).
    PerturbX,
    /// A vertex at p_y = s_y − BUFF·(1 + ε) (perturbation's y threshold).
    PerturbY,
    /// The trajectory passes through a vertex at t = T·(1/2 + ε).
    ThroughVertex,
    /// Moving along an edge's line, BUFF·ε outside it (tangent, collinear, disc = 0).
    AlongEdge,
    /// Coming straight in, first contact at t = T·(1 + ε).
    ContactAtT,
    /// On an edge at t = 0, moved by BUFF·ε.
    ContactAtZero,
    /// Crossing an edge's line just beyond its end: (1 + F)·(1 + ε) half-edges from the
    /// midpoint (edge_detect's F boundary).
    ExtendedEnd,
    /// Random trajectory near the polygon (no threshold): the background rate.
    Free,
}

impl Mode {
    /// Every mode.
    pub const ALL: [Mode; 10] = [
        Mode::EdgeBuff,
        Mode::VertexBuff,
        Mode::PerturbX,
        Mode::PerturbY,
        Mode::ThroughVertex,
        Mode::AlongEdge,
        Mode::ContactAtT,
        Mode::ContactAtZero,
        Mode::ExtendedEnd,
        Mode::Free,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Mode::EdgeBuff => "edge_buff",
            Mode::VertexBuff => "vertex_buff",
            Mode::PerturbX => "perturb_x",
            Mode::PerturbY => "perturb_y",
            Mode::ThroughVertex => "through_vertex",
            Mode::AlongEdge => "along_edge",
            Mode::ContactAtT => "contact_at_t",
            Mode::ContactAtZero => "contact_at_zero",
            Mode::ExtendedEnd => "extended_end",
            Mode::Free => "free",
        }
    }

    /// snake_case name of the mode stretched into a long path ([`stretch`]).
    pub fn long_name(self) -> &'static str {
        match self {
            Mode::EdgeBuff => "edge_buff+long",
            Mode::VertexBuff => "vertex_buff+long",
            Mode::PerturbX => "perturb_x+long",
            Mode::PerturbY => "perturb_y+long",
            Mode::ThroughVertex => "through_vertex+long",
            Mode::AlongEdge => "along_edge+long",
            Mode::ContactAtT => "contact_at_t+long",
            Mode::ContactAtZero => "contact_at_zero+long",
            Mode::ExtendedEnd => "extended_end+long",
            Mode::Free => "free+long",
        }
    }
}

/// Options of a generated case's shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// All vertex velocities equal (detect_same_2d).
    Static,
    /// Vertex velocities differ (detect_diff_2d); one edge keeps equal end velocities.
    Warping,
    /// With a height and a slab (detect_3d), static or warping at random.
    ThreeD,
}

/// A relative perturbation ε: 0, ±1…4 ulps, or ±10⁻¹⁵ … 10⁻³.
pub fn epsilon<S: Source>(src: &mut S) -> f64 {
    match src.below(3) {
        0 => 0.0,
        1 => (src.below(9) as f64 - 4.0) * f64::EPSILON,
        _ => {
            let e = 10f64.powi(-(3 + src.below(13) as i32));
            if src.coin() {
                e
            } else {
                -e
            }
        }
    }
}

/// The polygon's outline, drawn independently of the mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Outline {
    /// Star-shaped around its centre, 3 … 12 vertices.
    Star,
    /// Star-shaped, 13 … 256 vertices.
    Many,
    /// A star squeezed to an aspect ratio of 1 … 10⁻⁸ and turned: a thin needle.
    Needle,
    /// A star with vertices inserted 10⁻⁴ … 10⁻¹⁴ edge lengths off their edges' midpoints.
    NearCollinear,
    /// A star with a vertex inserted 10⁻³ … 10⁻¹² edge lengths from another: a short
    /// edge beside a long one.
    ShortEdge,
}

impl Outline {
    /// Every outline.
    pub const ALL: [Outline; 5] = [
        Outline::Star,
        Outline::Many,
        Outline::Needle,
        Outline::NearCollinear,
        Outline::ShortEdge,
    ];

    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            Outline::Star => "star",
            Outline::Many => "many",
            Outline::Needle => "needle",
            Outline::NearCollinear => "near_collinear",
            Outline::ShortEdge => "short_edge",
        }
    }
}

/// Where in scale space cases are drawn: decimal exponents of the relative path per
/// polygon size and of BUFF per polygon size, each drawn uniformly in its range (so the
/// ratio is log-uniform). [`Space::FULL`] is the whole space; `assure --aim` narrows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Space {
    /// log₁₀ of (relative path over [0, T]) / (polygon size): within −3 … 7.
    pub path: (f64, f64),
    /// log₁₀ of BUFF / (polygon size): within −12 … 0.
    pub buff: (f64, f64),
    /// Which cases are moved to an end of the float range ([`absolute_scale`]).
    pub ends: Ends,
}

/// How many cases [`absolute_scale`] moves to an end of the float range, and to which.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Ends {
    /// One case in eight, to either end (the default campaign).
    #[default]
    Eighth,
    /// Every case that can be moved, to either end.
    All,
    /// Every case that can be moved, BUFF subnormal.
    Tiny,
    /// Every case that can be moved, the largest length near 2⁹⁰⁰ … 2¹⁰⁰⁰.
    Huge,
    /// No case: every case stays at the scale it is drawn at (the normal range).
    None,
}

impl Ends {
    /// The name `--aim ends=…` takes (`eighth`, `all`, `tiny`, `huge`, `none`).
    pub fn name(self) -> &'static str {
        match self {
            Ends::Eighth => "eighth",
            Ends::All => "all",
            Ends::Tiny => "tiny",
            Ends::Huge => "huge",
            Ends::None => "none",
        }
    }

    /// The one of that name.
    pub fn from_name(name: &str) -> Option<Ends> {
        [Ends::Eighth, Ends::All, Ends::Tiny, Ends::Huge, Ends::None]
            .into_iter()
            .find(|e| e.name() == name)
    }
}

impl Space {
    /// The whole space: relative paths 10⁻³ … 10⁷ and BUFF 10⁻¹² … 1 polygon sizes.
    pub const FULL: Space = Space {
        path: (-3.0, 7.0),
        buff: (-12.0, 0.0),
        ends: Ends::Eighth,
    };

    /// A space narrowed to `path` and `buff` (decimal exponents), or why it cannot be:
    /// each range must lie within [`Space::FULL`]'s and not be empty. One case in eight
    /// goes to an end of the float range, as in the full space ([`Space::with_ends`]
    /// changes that).
    pub fn aimed(path: (f64, f64), buff: (f64, f64)) -> Result<Space, String> {
        for (name, (lo, hi), (flo, fhi)) in [
            ("path", path, Space::FULL.path),
            ("buff", buff, Space::FULL.buff),
        ] {
            if !(lo.is_finite() && hi.is_finite() && lo <= hi && lo >= flo && hi <= fhi) {
                return Err(format!(
                    "{name}: 1e{lo}..1e{hi} is not a range within 1e{flo}..1e{fhi}"
                ));
            }
        }
        Ok(Space {
            path,
            buff,
            ends: Ends::Eighth,
        })
    }

    /// The same space with `ends` cases moved to the ends of the float range.
    pub fn with_ends(self, ends: Ends) -> Space {
        Space { ends, ..self }
    }

    /// The space as `assure --aim` writes it and reports record it:
    /// `path=1e-3..1e7,buff=1e-12..1e0`, followed by `,ends=all` (or `tiny`, `huge`)
    /// when the cases at the ends of the float range are not the default eighth.
    pub fn label(&self) -> String {
        let ends = match self.ends {
            Ends::Eighth => String::new(),
            e => format!(",ends={}", e.name()),
        };
        format!(
            "path=1e{}..1e{},buff=1e{}..1e{}{ends}",
            self.path.0, self.path.1, self.buff.0, self.buff.1
        )
    }
}

impl Default for Space {
    fn default() -> Self {
        Space::FULL
    }
}

/// A generated case and how it was drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawn {
    /// The case.
    pub raw: RawCase,
    /// Static, warping or 3D.
    pub shape: Shape,
    /// The threshold it is built on.
    pub mode: Mode,
    /// The polygon's outline.
    pub outline: Outline,
    /// The relative perturbation of the threshold.
    pub eps: f64,
    /// The factor K the case was stretched by ([`stretch`]); 1 when it was not.
    pub stretch: f64,
    /// The power of two the whole case was moved by to an end of the float range
    /// (see [`absolute_scale`]); 0 when it was not.
    pub scale_exp: i32,
}

impl Drawn {
    /// The mode's name, with "+long" when the case was stretched into a long path.
    pub fn name(&self) -> &'static str {
        if self.stretch > 1.0 {
            self.mode.long_name()
        } else {
            self.mode.name()
        }
    }
}

/// 10^u with u uniform in [lo, hi).
fn decade<S: Source>(src: &mut S, (lo, hi): (f64, f64)) -> f64 {
    10f64.powf(src.range(lo, hi))
}

/// A star-shaped counterclockwise ring around `o`: angular gaps below (1 + 0.45)/3 of a
/// turn (under half), radii in [0.2, 0.5]·size.
fn star<S: Source>(src: &mut S, n: usize, size: f64) -> Vec<Vect2> {
    let tau = core::f64::consts::TAU;
    (0..n)
        .map(|i| {
            let a = tau * (i as f64 + 0.45 * src.unit()) / n as f64;
            let r = size * src.range(0.2, 0.5);
            Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

/// The outline's ring around the origin (before the offset) and the size of its finest
/// feature (the needle's width, the short edge, the near-collinear vertex's distance),
/// which bounds how much a warp may jitter it.
fn outline_ring<S: Source>(src: &mut S, outline: Outline, size: f64) -> (Vec<Vect2>, f64) {
    match outline {
        Outline::Star => {
            let n = 3 + src.below(10);
            (star(src, n, size), size)
        }
        Outline::Many => {
            let n = 2f64.powf(src.range(3.7, 8.0)).round() as usize;
            (star(src, n.clamp(13, 256), size), size / n as f64)
        }
        Outline::Needle => {
            let aspect = decade(src, (-8.0, 0.0));
            let turn = src.range(0.0, core::f64::consts::TAU);
            let (c, s) = (turn.cos(), turn.sin());
            let n = 3 + src.below(6);
            let ring = star(src, n, size)
                .into_iter()
                .map(|p| {
                    let q = Vect2::new(p.x, aspect * p.y);
                    Vect2::new(c * q.x - s * q.y, s * q.x + c * q.y)
                })
                .collect();
            (ring, aspect * size)
        }
        Outline::NearCollinear | Outline::ShortEdge => {
            let n = 3 + src.below(6);
            let base = star(src, n, size);
            let n = base.len();
            let mut ring = Vec::with_capacity(2 * n);
            let mut finest = size;
            for i in 0..n {
                let (a, b) = (base[i], base[(i + 1) % n]);
                ring.push(a);
                if !src.coin() && i != 0 {
                    continue;
                }
                let d = b - a;
                let len = d.sq().sqrt();
                let out = d.perp().scale(1.0 / len);
                let (at, off) = if outline == Outline::NearCollinear {
                    let f = decade(src, (-14.0, -4.0));
                    let side = if src.coin() { 1.0 } else { -1.0 };
                    (0.5, side * f)
                } else {
                    let f = decade(src, (-12.0, -3.0));
                    (f, 0.5 * f)
                };
                finest = finest.min(off.abs() * len).min(at * len);
                ring.push(a + d.scale(at) + out.scale(off * len));
            }
            (ring, finest)
        }
    }
}

/// The polygon: an outline of nominal size `size` offset to `o`, simple and
/// counterclockwise exactly after rounding. Redrawn (as a star, then larger) when the
/// rounding at the offset breaks it.
fn polygon<S: Source>(
    src: &mut S,
    outline: Outline,
    size: f64,
    o: Vect2,
) -> (Vec<Vect2>, f64, Outline) {
    let (mut outline, mut size) = (outline, size);
    loop {
        for _ in 0..4 {
            let (ring, finest) = outline_ring(src, outline, size);
            let verts: Vec<Vect2> = ring.into_iter().map(|p| o + p).collect();
            let repeated = (0..verts.len()).any(|i| verts[i] == verts[(i + 1) % verts.len()]);
            if !repeated && polyguard::ring::simple_ccw(&verts) {
                return (verts, finest, outline);
            }
        }
        // The offset's grid is too coarse for this outline: a star, then a larger one.
        if outline == Outline::Star {
            size *= 16.0;
        }
        outline = Outline::Star;
    }
}

/// Is the case's polygon simple at every time of [0, T], decided exactly? (A case the
/// oracle cannot read counts as not.)
pub(crate) fn simple_throughout(raw: &RawCase) -> bool {
    raw.exact::<super::classify::Exact>()
        .is_ok_and(|c| polyguard_oracle::truth::simple_on_window(&c).is_ok())
}

/// The scales of a case and its polygon at time 0 (the first draws of [`case`]).
struct Scales {
    outline: Outline,
    /// The polygon's vertices, the finest feature's size, and its centre's offset `o`.
    verts: Vec<Vect2>,
    finest: f64,
    o: Vect2,
    size: f64,
    buff: f64,
    /// The time of the unstretched case, the point's speed relative to the polygon, and
    /// the stretch that makes the path as long as drawn (1: none).
    t: f64,
    spd: f64,
    k: f64,
}

/// Draws the scales of a case from `space`: size and offset, then BUFF, path and T, each
/// log-uniform, and the polygon.
fn draw_scales<S: Source>(src: &mut S, space: &Space) -> Scales {
    let tau = core::f64::consts::TAU;
    let outline = src.pick(&Outline::ALL);
    let (size, offset) = if src.below(5) == 0 {
        (decade(src, (-6.0, 6.0)), 0.0)
    } else {
        let offset = decade(src, (-3.0, 9.0));
        (offset * decade(src, (-12.0, 0.0)), offset)
    };
    let dir_o = src.range(0.0, tau);
    let o = Vect2::new(offset * dir_o.cos(), offset * dir_o.sin());
    let (verts, finest, outline) = polygon(src, outline, size, o);
    let buff = size * decade(src, space.buff);
    let path = decade(src, space.path);
    let t_final = decade(src, (-6.0, 9.0));
    // Paths beyond 3 sizes come from stretching a case whose path is 0.3 … 3 sizes.
    let (rel, k) = if path <= 3.0 {
        (path, 1.0)
    } else {
        let rel = src.range(0.3, 3.0);
        (rel, path / rel)
    };
    let t = t_final / k;
    Scales {
        outline,
        verts,
        finest,
        o,
        size,
        buff,
        t,
        spd: rel * size / t,
        k,
    }
}

/// How the polygon and the point move and where the threshold sits (the draws of
/// [`case`] after the scales).
struct Motion {
    fac: f64,
    warping: bool,
    drift: Vect2,
    /// An edge whose ends move alike: dot_nn_lin's A = 0.
    keep: usize,
    warp: [f64; 4],
    jitter: Vec<Vect2>,
    e: f64,
    i: usize,
    dir: f64,
    along: f64,
    side: f64,
    below: f64,
    dx: f64,
    start_off: Vect2,
    z: [f64; 5],
    z_still: bool,
    z_bottom: bool,
}

/// Draws the motion of a case of `shape` whose polygon has `n` vertices, at scales `sc`.
fn draw_motion<S: Source>(src: &mut S, shape: Shape, n: usize, sc: &Scales) -> Motion {
    let tau = core::f64::consts::TAU;
    let fac = src.pick(&[1e-4, 1e-4, 1e-2, 1e-6]);
    let warping = match shape {
        Shape::Static => false,
        Shape::Warping => true,
        Shape::ThreeD => src.coin(),
    };
    let drift_dir = src.range(0.0, tau);
    let drift = Vect2::new(drift_dir.cos(), drift_dir.sin())
        .scale(src.range(0.0, 1.0) * src.pick(&[1.0, 1.0, 1e3]) * sc.size / sc.t);
    let keep = src.below(n);
    let warp = [
        src.range(-0.3, 0.3),
        src.range(-0.3, 0.3),
        src.range(-0.3, 0.3),
        src.range(-0.3, 0.3),
    ];
    let jitter: Vec<Vect2> = (0..n)
        .map(|_| Vect2::new(src.range(-0.1, 0.1), src.range(-0.1, 0.1)))
        .collect();
    let e = epsilon(src);
    let i = src.below(n);
    let dir = src.range(0.0, tau);
    let along = src.unit();
    let side = if src.coin() { 1.0 } else { -1.0 };
    let below = sc.size * src.range(0.0, 1.0);
    let dx = src.range(-1.0, 1.0);
    let start_off = Vect2::new(src.range(-1.5, 1.5), src.range(-1.5, 1.5));
    let z = [
        src.range(-2.0, 2.0),
        src.range(-0.5, 0.5),
        src.range(0.2, 0.8),
        src.range(-0.5, 0.5),
        decade(src, (-6.0, 3.0)),
    ];
    let (z_still, z_bottom) = (src.coin(), src.coin());
    Motion {
        fac,
        warping,
        drift,
        keep,
        warp,
        jitter,
        e,
        i,
        dir,
        along,
        side,
        below,
        dx,
        start_off,
        z,
        z_still,
        z_bottom,
    }
}

/// The case of scales `sc` and motion `m` at the threshold of `mode`, its polygon warped
/// with strength `w` (0: it only translates) and drifting at `drift`, stretched to its
/// path when `sc.k` > 1; with the stretch made.
fn threshold_at(
    sc: &Scales,
    m: &Motion,
    shape: Shape,
    mode: Mode,
    w: f64,
    drift: Vect2,
) -> (RawCase, f64) {
    let (t, n) = (sc.t, sc.verts.len());
    let mut vels: Vec<Vect2> = sc
        .verts
        .iter()
        .zip(&m.jitter)
        .map(|(&p, &jit)| {
            let q = (p - sc.o).scale(w / t);
            let warp = m.warp;
            let affine = Vect2::new(warp[0] * q.x + warp[1] * q.y, warp[2] * q.x + warp[3] * q.y);
            drift + affine + jit.scale(w * sc.finest / t)
        })
        .collect();
    if w > 0.0 {
        vels[(m.keep + 1) % n] = vels[m.keep];
    }
    let mut raw = threshold_case(&Threshold {
        mode,
        verts: &sc.verts,
        vels: &vels,
        i: m.i,
        e: m.e,
        t,
        buff: sc.buff,
        fac: m.fac,
        spd: sc.spd,
        dir: m.dir,
        along: m.along,
        side: m.side,
        below: m.below,
        dx: m.dx,
        start_off: m.start_off,
        o: sc.o,
        size: sc.size,
    });
    if shape == Shape::ThreeD {
        add_slab(&mut raw, &m.z, m.z_still, m.z_bottom, m.e, sc.spd, sc.size);
    }
    let k_done = if sc.k > 1.0 {
        stretch_to(&mut raw, sc.k)
    } else {
        1.0
    };
    (raw, k_done)
}

/// One boundary-biased case of the given shape and mode, its scales drawn from `space`.
pub fn case<S: Source>(src: &mut S, shape: Shape, mode: Mode, space: &Space) -> Drawn {
    let sc = draw_scales(src, space);
    let m = draw_motion(src, shape, sc.verts.len(), &sc);
    // Warps from the full one down to none; the first whose polygon stays simple over
    // [0, T] exactly is taken (a static polygon only translates: always simple).
    let strengths: &[f64] = if m.warping {
        &[1.0, 1e-2, 1e-5, 0.0]
    } else {
        &[0.0]
    };
    // A stretch that the rounding of far-away vertices (p − τ·v₀) would break is
    // redrawn without the polygon's drift, where that rounding is gone.
    let drifts = [m.drift, Vect2::default()];
    let make = |w: f64, d: Vect2| threshold_at(&sc, &m, shape, mode, w, d);
    let (raw, stretch) = drifts
        .iter()
        .flat_map(|&d| strengths.iter().map(move |&w| (w, d)))
        .find_map(|(w, d)| {
            let (raw, k_done) = make(w, d);
            let stretched = sc.k <= 1.0 || k_done > 1.0 || d == Vect2::default();
            (stretched && (w == 0.0 || simple_throughout(&raw))).then_some((raw, k_done))
        })
        .unwrap_or_else(|| make(0.0, Vect2::default()));
    // Drawn last, so that the cases left at their scale are the same as before.
    let (raw, scale_exp) = absolute_scale(src, raw, m.warping, space.ends);
    Drawn {
        raw,
        shape,
        mode,
        outline: sc.outline,
        eps: m.e,
        stretch,
        scale_exp,
    }
}

/// One case in eight, moved whole by a power of two 2^j (exact, but for underflow) to
/// the ends of the float range: half of them so that BUFF lies in 2⁻¹⁰⁷² … 2⁻¹⁰⁴⁰
/// (subnormal: a few to 34 significant bits), where rounding has an absolute floor,
/// products underflow and a threshold ε below the grid becomes an exact tie; half so that the largest length (a coordinate, BUFF, or a distance
/// moved over T) lies in 2⁹⁰⁰ … 2¹⁰⁰⁰, where squares overflow. Lengths, heights and
/// velocities scale, T and F do not, so the case is the same case at another scale. A
/// move that breaks it (underflow collapsing the polygon, or a warping one no longer
/// simple over [0, T]) is not made. Returns the case and j (0: not moved).
pub fn absolute_scale<S: Source>(
    src: &mut S,
    raw: RawCase,
    warping: bool,
    ends: Ends,
) -> (RawCase, i32) {
    // The default draws exactly as before `ends` existed, so seeded campaigns keep
    // their cases. With none moved nothing is drawn: this is the case's last draw, so
    // case k is then the default campaign's case k wherever that one was not moved.
    if ends == Ends::None || (ends == Ends::Eighth && src.below(8) != 0) {
        return (raw, 0);
    }
    let tiny = match ends {
        Ends::Tiny => true,
        Ends::Huge => false,
        Ends::Eighth | Ends::All | Ends::None => src.coin(),
    };
    let u = if tiny {
        src.range(-1072.0, -1040.0)
    } else {
        src.range(900.0, 1000.0)
    };
    let t = raw.lookahead;
    let mut largest = raw.buff;
    let mut grow = |x: f64| largest = largest.max(x.abs());
    raw.pos.iter().for_each(|&x| grow(x));
    raw.vel.iter().for_each(|&x| grow(x * t));
    raw.vertices.iter().flatten().for_each(|&x| grow(x));
    raw.velocities.iter().flatten().for_each(|&x| grow(x * t));
    raw.slab.iter().flatten().for_each(|&x| grow(x));
    let anchor = if tiny { raw.buff } else { largest };
    if !(anchor > 0.0 && anchor.is_finite()) {
        return (raw, 0);
    }
    let j = (u - anchor.log2()).round() as i32;
    let moved = raw.times_pow2(j);
    let verts: Vec<Vect2> = moved.vertices.iter().map(|&p| p.into()).collect();
    let kept = moved.buff > 0.0
        && moved.to_api().is_ok()
        && polyguard::ring::simple_ccw(&verts)
        && (!warping || simple_throughout(&moved));
    if kept {
        (moved, j)
    } else {
        (raw, 0)
    }
}

/// What a threshold configuration is built from (all drawn before the warp is chosen,
/// so that a gentler warp redraws nothing else).
struct Threshold<'a> {
    mode: Mode,
    verts: &'a [Vect2],
    vels: &'a [Vect2],
    i: usize,
    e: f64,
    t: f64,
    buff: f64,
    fac: f64,
    spd: f64,
    dir: f64,
    along: f64,
    side: f64,
    below: f64,
    dx: f64,
    start_off: Vect2,
    o: Vect2,
    size: f64,
}

/// The 2D case at the threshold of `c.mode` (see [`Mode`]).
fn threshold_case(c: &Threshold) -> RawCase {
    let n = c.verts.len();
    let (i, j) = (c.i, (c.i + 1) % n);
    let (pi, pj) = (c.verts[i], c.verts[j]);
    let (t, buff, e) = (c.t, c.buff, c.e);
    let d = pj - pi;
    let len = d.sq().sqrt();
    let (u, out) = (d.scale(1.0 / len), d.perp().scale(1.0 / len)); // outward: CCW
    let vi = c.vels[i];
    let free_v = vi + Vect2::new(c.dir.cos(), c.dir.sin()).scale(c.spd);
    let vin = out.scale(-c.spd);
    let (s, v) = match c.mode {
        Mode::EdgeBuff => (pi + d.scale(c.along) + out.scale(buff * (1.0 + e)), free_v),
        Mode::VertexBuff => {
            let w = (out - u).scale(1.0 / 2f64.sqrt());
            (pi + w.scale(buff * (1.0 + e)), free_v)
        }
        Mode::PerturbX => (
            Vect2::new(pi.x + c.side * buff * (1.0 + e), pi.y - c.below),
            free_v,
        ),
        Mode::PerturbY => (
            Vect2::new(pi.x + buff * c.dx, pi.y + buff * (1.0 + e)),
            free_v,
        ),
        Mode::ThroughVertex => {
            let tc = t * (0.5 + e);
            (pi.at(vi, tc) - free_v.scale(tc), free_v)
        }
        Mode::AlongEdge => (pi - d.scale(0.5) + out.scale(buff * e), vi + u.scale(c.spd)),
        Mode::ContactAtT => {
            let hit = pi + d.scale(c.along);
            (hit - vin.scale(t * (1.0 + e)), vi + vin)
        }
        Mode::ContactAtZero => (pi + d.scale(c.along) + out.scale(buff * e), free_v),
        Mode::ExtendedEnd => {
            // Crosses the edge's line (moving with vertex i) at (1 + F)(1 + ε) half-edges
            // beyond the midpoint, i.e. just past p_j, at time T/2.
            let mid = pi + d.scale(0.5);
            let cross = mid + d.scale(0.5 * (1.0 + c.fac) * (1.0 + e));
            let tc = 0.5 * t;
            (cross.at(vi, tc) - vin.scale(tc) - vi.scale(tc), vi + vin)
        }
        Mode::Free => (c.o + c.start_off.scale(c.size), free_v),
    };
    RawCase {
        lookahead: t,
        buff,
        fac: c.fac,
        pos: vec![s.x, s.y],
        vel: vec![v.x, v.y],
        vertices: c.verts.iter().map(|&p| p.into()).collect(),
        velocities: c.vels.iter().map(|&p| p.into()).collect(),
        slab: None,
    }
}

/// Makes a 2D case 3D: the point reaches the slab's bottom (or top) at a time near the
/// middle, ± ε; the slab is `z[4]` polygon sizes thick (thin and thick), still or moving.
fn add_slab(
    raw: &mut RawCase,
    z: &[f64; 5],
    still: bool,
    bottom_first: bool,
    e: f64,
    spd: f64,
    size: f64,
) {
    let t = raw.lookahead;
    let vz = z[0] * spd;
    let vsp = if still { 0.0 } else { z[1] * spd };
    let tz = t * z[2] * (1.0 + e);
    let z0 = z[3] * size;
    let height = size * z[4];
    let z_at = z0 + vz * tz;
    let (bottom, top) = if bottom_first {
        let b = z_at - vsp * tz;
        (b, b + height)
    } else {
        let tp = z_at - vsp * tz;
        (tp - height, tp)
    };
    raw.pos.push(z0);
    raw.vel.push(vz);
    raw.slab = Some([bottom, top, vsp]);
}

/// Stretches a case into a long relative path: K = 10^u, u uniform in [1, 6]. Returns
/// K, or 1 (the case unchanged) when the polygon at time 0 is then no longer simple and
/// counterclockwise. See [`stretch_to`].
pub fn stretch<S: Source>(src: &mut S, raw: &mut RawCase) -> f64 {
    let k = 10f64.powf(src.range(1.0, 6.0));
    stretch_to(raw, k)
}

/// Stretches a case by K (> 1) into a long relative path.
///
/// With τ = (K − 1)·T, vertex velocities v_i = v_0 + δ_i and a slab moving at vsp, the
/// new case has lookahead K·T, start s − τ·v, vertices p_i − τ·v_0 − (τ/K)·δ_i and
/// velocities v_0 + δ_i/K, heights z − τ·v_z and slab ends − τ·vsp. At time τ it is the
/// original case at time 0 (up to the rounding of the far-away starts), and over its
/// lookahead the polygon warps exactly as much as the original did over T, while the
/// point travels K times as far relative to it. Returns K; 1 (the case unchanged) when
/// the polygon at time 0, the original one warped backwards, is no longer simple and
/// counterclockwise.
pub fn stretch_to(raw: &mut RawCase, k: f64) -> f64 {
    let original = raw.clone();
    stretch_by(raw, k);
    let verts: Vec<Vect2> = raw.vertices.iter().map(|&p| p.into()).collect();
    if polyguard::ring::simple_ccw(&verts) {
        k
    } else {
        *raw = original;
        1.0
    }
}

fn stretch_by(raw: &mut RawCase, k: f64) {
    let t = raw.lookahead;
    let tau = (k - 1.0) * t;
    let v = Vect2::new(raw.vel[0], raw.vel[1]);
    let v0: Vect2 = raw
        .velocities
        .first()
        .map(|&w| w.into())
        .unwrap_or_default();
    raw.lookahead = k * t;
    raw.pos[0] -= tau * v.x;
    raw.pos[1] -= tau * v.y;
    for (p, w) in raw.vertices.iter_mut().zip(raw.velocities.iter_mut()) {
        let d = Vect2::from(*w) - v0;
        let np = Vect2::from(*p) - v0.scale(tau) - d.scale(tau / k);
        *p = np.into();
        *w = (v0 + d.scale(1.0 / k)).into();
    }
    if raw.pos.len() == 3 {
        raw.pos[2] -= tau * raw.vel[2];
        if let Some(slab) = raw.slab.as_mut() {
            slab[0] -= tau * slab[2];
            slab[1] -= tau * slab[2];
        }
    }
}

/// A case of random shape and mode over the whole scale space.
pub fn any_case<S: Source>(src: &mut S) -> Drawn {
    any_case_in(src, &Space::FULL)
}

/// A case of random shape and mode, its scales drawn from `space`.
pub fn any_case_in<S: Source>(src: &mut S, space: &Space) -> Drawn {
    let shape = src.pick(&[Shape::Static, Shape::Warping, Shape::ThreeD]);
    let mode = src.pick(&Mode::ALL);
    case(src, shape, mode, space)
}

/// The coverage bucket of a case: the decimal exponents (floors) of its relative path
/// per polygon size, clamped to −3 … 7, and of its BUFF per polygon size, clamped to
/// −12 … 0. The size is the diagonal of the polygon's bounding box at time 0; the
/// relative path is |v − v̄|·T with v̄ the mean vertex velocity.
pub fn bucket(raw: &RawCase) -> (i32, i32) {
    let n = raw.vertices.len().max(1) as f64;
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &raw.vertices {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    let size = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    let mean = raw
        .velocities
        .iter()
        .fold([0.0, 0.0], |m, w| [m[0] + w[0] / n, m[1] + w[1] / n]);
    let rel = match raw.vel.as_slice() {
        [vx, vy, ..] => (vx - mean[0]).hypot(vy - mean[1]),
        _ => 0.0,
    };
    let exp = |x: f64, lo: i32, hi: i32| {
        if x > 0.0 && x.is_finite() {
            (x.log10().floor() as i32).clamp(lo, hi)
        } else {
            lo
        }
    };
    (
        exp(rel * raw.lookahead / size, -3, 7),
        exp(raw.buff / size, -12, 0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The homogeneity [`RawCase::exact`] relies on: generated cases moved by 2⁻¹⁰⁰⁰
    /// and by 2⁹⁰⁰ (exactly), handed to the oracle as they are, get paper A's answer,
    /// the truth and the entry time of the case at its own scale.
    #[test]
    fn the_oracle_answers_alike_at_every_scale() {
        use super::super::classify::Exact;
        use polyguard_oracle::{paper_detect, truth, ExactCase};
        // the entry time as a value (a + b·√d is written in more than one way)
        let answers = |c: &ExactCase<Exact>| {
            let t = match truth(c) {
                polyguard_oracle::Truth::Enters { entry_time } => {
                    Some(Some(entry_time.to_decimal_string(40)))
                }
                polyguard_oracle::Truth::Misses => Some(None),
                polyguard_oracle::Truth::Undefined { .. } => None,
            };
            (paper_detect(c).detected, t)
        };
        let mut src = SplitMix(5);
        let mut moved = 0;
        for _ in 0..40 {
            let raw = any_case(&mut src).raw;
            let want = answers(&raw.exact().expect("a generated case is valid"));
            for s in [-1000, 900] {
                let c = raw.times_pow2(s);
                if c.times_pow2(-s) != raw {
                    continue; // the move rounded: not the same case
                }
                moved += 1;
                let got = answers(&c.exact_as_is().expect("moved exactly"));
                assert_eq!(got, want, "moved by 2^{s}: {c:?}");
            }
        }
        assert!(moved >= 40, "only {moved} of 80 moves were exact");
    }

    #[test]
    fn generated_cases_are_valid_and_seeded() {
        let mut a = SplitMix(7);
        let mut b = SplitMix(7);
        for _ in 0..500 {
            let (ca, cb) = (any_case(&mut a), any_case(&mut b));
            assert_eq!(ca, cb);
            ca.raw.to_api().expect("generated cases are valid");
        }
    }

    #[test]
    fn edge_buff_mode_is_at_buff_from_the_edge() {
        let mut src = SplitMix(3);
        for _ in 0..200 {
            let Drawn {
                raw,
                eps: e,
                scale_exp,
                ..
            } = case(
                &mut src,
                Shape::Static,
                Mode::EdgeBuff,
                &Space {
                    path: (-3.0, 0.4),
                    buff: (-7.0, -2.0),
                    ends: Ends::Eighth,
                },
            );
            // A case moved to an end of the float range is measured moved back (by a
            // power of two: exactly), where its squares do not overflow.
            let back =
                |x: f64| x * 2f64.powi(-scale_exp / 2) * 2f64.powi(-(scale_exp - scale_exp / 2));
            let s = Vect2::new(back(raw.pos[0]), back(raw.pos[1]));
            let vertex = |k: usize| Vect2::new(back(raw.vertices[k][0]), back(raw.vertices[k][1]));
            let buff = back(raw.buff);
            // Distance to the nearest edge, relative to BUFF, is about 1 + ε.
            let n = raw.vertices.len();
            let dist = (0..n)
                .map(|k| {
                    let a = vertex(k);
                    let b = vertex((k + 1) % n);
                    let d = b - a;
                    let r = ((s - a).dot(d) / d.sq()).clamp(0.0, 1.0);
                    (a + d.scale(r) - s).sq().sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            // and, for a case moved to the subnormal range, the rounding of each
            // coordinate there (2⁻¹⁰⁷⁵ a number, absolute)
            let floor = if scale_exp < 0 {
                8.0 * f64::from_bits(1)
            } else {
                0.0
            };
            let scale_err = 1e-6 + (1e-9 * raw.vertices[0][0].abs() + floor) / raw.buff;
            assert!(
                (dist / buff) <= 1.0 + e.abs() + scale_err,
                "{dist} vs {buff} (moved by 2^{scale_exp})"
            );
        }
    }

    /// About one case in eight is moved to an end of the float range, both ends are
    /// reached, and a moved case is still valid: BUFF subnormal or just above at the
    /// small end, the largest length in 2⁸⁹⁹ … 2¹⁰⁰¹ at the large one.
    #[test]
    fn some_cases_move_to_the_ends_of_the_float_range() {
        let mut src = SplitMix(11);
        let (mut tiny, mut huge, total) = (0, 0, 2000);
        for _ in 0..total {
            let d = any_case(&mut src);
            let r = &d.raw;
            r.to_api().expect("a moved case is still valid");
            let t = r.lookahead;
            let largest = r
                .pos
                .iter()
                .chain(r.vertices.iter().flatten())
                .chain(r.slab.iter().flatten())
                .copied()
                .chain(
                    r.vel
                        .iter()
                        .chain(r.velocities.iter().flatten())
                        .map(|v| v * t),
                )
                .fold(r.buff, |m, x| m.max(x.abs()));
            if d.scale_exp < 0 {
                tiny += 1;
                assert!(
                    r.buff > 0.0 && r.buff < 2f64.powi(-520) * 2f64.powi(-519),
                    "BUFF {:e}",
                    r.buff
                );
            } else if d.scale_exp > 0 {
                huge += 1;
                let (lo, hi) = (2f64.powi(899), 2f64.powi(1001));
                assert!((lo..=hi).contains(&largest), "largest {largest:e}");
            }
        }
        let moved = tiny + huge;
        assert!(
            (total / 12..=total / 5).contains(&moved) && tiny > total / 40 && huge > total / 40,
            "{tiny} tiny and {huge} huge in {total}"
        );
    }

    #[test]
    fn bytes_source_is_total() {
        for data in [&[][..], &[1, 2, 3][..], &[255; 100][..]] {
            let mut src = Bytes::new(data);
            let raw = any_case(&mut src).raw;
            assert!(raw.to_api().is_ok() || raw.vertices.len() >= 3);
        }
    }
}
