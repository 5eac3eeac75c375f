//! Random scenarios as in Paper B Section VI.D (`polyguard generate`).
//!
//! The paper: areas of 3–10 vertices at radius 50–100 nm from a random centre, in the box
//! latitude 0–30°, longitude −45…−15°; tracks from a random first waypoint to a second
//! 50–100 nm away, rectangles 20–40 nm a side. Where the paper is silent:
//! angles are sorted and redrawn when a gap exceeds π (else the ring crosses itself
//! around its centre), vertices are rhumb destinations at the drawn bearing and distance,
//! rectangle length = front + back and width = 2·side each uniform in 20–40 nm with
//! front = back, 15 kn, t0 = 0, `mixed` alternates area and track, the second waypoint
//! lies at a uniform bearing.
//!
//! `--density-box`: the box keeps the paper's latitudes and stretches in longitude to
//! `30° · N / 800` wide, so that 10× the objects cover 10× the area at the paper's density
//! (800 objects per paper box). Past 6,000 objects the box runs beyond 180° east, more
//! than the Earth holds at that density: the scenario is then one of the unrolled strip
//! (`"longitudes": "unrolled"`, [`Longitudes::Unrolled`]: longitudes are not wrapped),
//! which keeps the density and the Mercator distortion of every object exactly as in the
//! paper's box.

use crate::scenario::{Area, Feature, Kind, Longitudes, Scenario, Track};
use crate::sphere::{rhumb_destination, LonLat, RectDims};

/// Paper B §VI.D: the generation box, degrees.
pub const BOX_LAT_DEG: (f64, f64) = (0.0, 30.0);
/// Paper B §VI.D: the generation box, degrees.
pub const BOX_LON_DEG: (f64, f64) = (-45.0, -15.0);
/// `--density-box`: objects per paper box (the paper's runs had 500–800 objects).
pub const DENSITY_BOX_OBJECTS: f64 = 800.0;
/// Speed of generated tracks (kn); the paper gives none.
pub const TRACK_SPEED_KN: f64 = 15.0;

/// Which objects to generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mix {
    /// Static areas only.
    Static,
    /// Half areas, half tracks (alternating).
    Mixed,
    /// Tracks only.
    Tracks,
}

/// 64 random bits a call: the generator's only source of randomness (the command-line tool
/// passes its seeded SplitMix64).
pub type Bits<'a> = dyn FnMut() -> u64 + 'a;

/// Uniform in `[lo, hi)`, from the top 53 bits.
fn uniform(rng: &mut Bits<'_>, lo: f64, hi: f64) -> f64 {
    let u = (rng() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
    lo + (hi - lo) * u
}

/// Uniform integer in `lo..=hi`.
fn int(rng: &mut Bits<'_>, lo: usize, hi: usize) -> usize {
    lo + (rng() % (hi - lo + 1) as u64) as usize
}

/// Paper B §VI.D: the box for `n` objects (degrees: lon range, lat range).
pub fn generation_box(n: usize, density_box: bool) -> ((f64, f64), (f64, f64)) {
    if density_box {
        let width = (BOX_LON_DEG.1 - BOX_LON_DEG.0) * n as f64 / DENSITY_BOX_OBJECTS;
        ((BOX_LON_DEG.0, BOX_LON_DEG.0 + width), BOX_LAT_DEG)
    } else {
        (BOX_LON_DEG, BOX_LAT_DEG)
    }
}

fn random_point(rng: &mut Bits<'_>, bx: ((f64, f64), (f64, f64))) -> LonLat {
    let lon = uniform(rng, bx.0 .0, bx.0 .1);
    let lat = uniform(rng, bx.1 .0, bx.1 .1);
    LonLat::from_degrees(lon, lat)
}

/// Paper B §VI.D: one random area.
pub fn random_area(rng: &mut Bits<'_>, bx: ((f64, f64), (f64, f64))) -> Area {
    let c = random_point(rng, bx);
    let n = int(rng, 3, 10);
    let tau = core::f64::consts::TAU;
    let angles = loop {
        let mut a: Vec<f64> = (0..n).map(|_| uniform(rng, 0.0, tau)).collect();
        a.sort_by(f64::total_cmp);
        let mut gap = a[0] + tau - a[n - 1];
        for w in a.windows(2) {
            gap = gap.max(w[1] - w[0]);
        }
        if gap <= core::f64::consts::PI {
            break a;
        }
    };
    // Bearings grow clockwise; GeoJSON (RFC 7946 §3.1.6) wants exterior rings
    // counterclockwise, so the vertices go in decreasing bearing.
    let mut ring: Vec<LonLat> = angles
        .iter()
        .map(|&b| rhumb_destination(c, b, uniform(rng, 50.0, 100.0)))
        .collect();
    ring.reverse();
    Area {
        shapes: vec![crate::scenario::Shape::plain(ring)],
        multi: false,
        t0: None,
        tf: None,
    }
}

/// Paper B §VI.D: one random track.
pub fn random_track(rng: &mut Bits<'_>, bx: ((f64, f64), (f64, f64))) -> Track {
    let p = random_point(rng, bx);
    let bearing = uniform(rng, 0.0, core::f64::consts::TAU);
    let q = rhumb_destination(p, bearing, uniform(rng, 50.0, 100.0));
    let length = uniform(rng, 20.0, 40.0);
    let width = uniform(rng, 20.0, 40.0);
    Track {
        waypoints: vec![p, q],
        speed_kn: TRACK_SPEED_KN,
        dims: RectDims {
            front: 0.5 * length,
            back: 0.5 * length,
            side: 0.5 * width,
        },
        t0: 0.0,
    }
}

/// Paper B §VI.D: a random scenario of `n` objects.
pub fn generate(n: usize, mix: Mix, density_box: bool, rng: &mut Bits<'_>) -> Scenario {
    let mut features = Vec::with_capacity(n);
    let longitudes = generate_each(n, mix, density_box, rng, &mut |f| features.push(f));
    Scenario {
        features,
        longitudes,
        geodesy: Default::default(),
    }
}

/// [`generate`], each feature handed to `each` as it is drawn (`generate --objects` writes
/// them so, in memory that does not grow with `n`); returns the scenario's plane.
pub fn generate_each(
    n: usize,
    mix: Mix,
    density_box: bool,
    rng: &mut Bits<'_>,
    each: &mut dyn FnMut(Feature),
) -> Longitudes {
    let bx = generation_box(n, density_box);
    for i in 0..n {
        let area = match mix {
            Mix::Static => true,
            Mix::Tracks => false,
            Mix::Mixed => i % 2 == 0,
        };
        each(if area {
            Feature {
                id: format!("a{i}"),
                kind: Kind::Area(random_area(rng, bx)),
                extra: Default::default(),
            }
        } else {
            Feature {
                id: format!("t{i}"),
                kind: Kind::Track(random_track(rng, bx)),
                extra: Default::default(),
            }
        });
    }
    // past ±180° the box is the unrolled strip (see the module's documentation)
    if bx.0 .1 > 180.0 {
        Longitudes::Unrolled
    } else {
        Longitudes::Earth
    }
}
