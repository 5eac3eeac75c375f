//! `polyguard generate`: random scenarios as in Paper B Section VI.D.
//!
//! The paper: areas of 3–10 vertices at radius 50–100 nm from a random centre, in the box
//! latitude 0–30°, longitude −45…−15°; tracks from a random first waypoint to a second
//! 50–100 nm away, rectangles 20–40 nm a side. Where the paper is silent (issue 5):
//! angles are sorted and redrawn when a gap exceeds π (else the ring crosses itself
//! around its centre), vertices are rhumb destinations at the drawn bearing and distance,
//! rectangle length = front + back and width = 2·side each uniform in 20–40 nm with
//! front = back, 15 kn, t0 = 0, `mixed` alternates area and track, the second waypoint
//! lies at a uniform bearing.
//!
//! `--density-box`: the box keeps the paper's latitudes and stretches in longitude to
//! `30° · N / 800` wide, so that 10× the objects cover 10× the area at the paper's density
//! (800 objects per paper box). Past 10⁴ objects the box runs beyond ±180°: the engine's
//! Mercator plane is the unrolled strip (longitudes are not wrapped), which keeps the
//! density and the Mercator distortion of every object exactly as in the paper's box.

use crate::earth::{rhumb_destination, LonLat, RectDims};
use crate::scenario::{Area, Feature, Kind, Scenario, Track};
use std::path::PathBuf;
use std::process::ExitCode;

/// Paper B §VI.D: the generation box, degrees.
pub const BOX_LAT_DEG: (f64, f64) = (0.0, 30.0);
/// Paper B §VI.D: the generation box, degrees.
pub const BOX_LON_DEG: (f64, f64) = (-45.0, -15.0);
/// `--density-box`: objects per paper box (the paper's runs had 500–800 objects).
pub const DENSITY_BOX_OBJECTS: f64 = 800.0;
/// Issue 5: speed of generated tracks (kn).
pub const TRACK_SPEED_KN: f64 = 15.0;

/// Which objects to generate.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mix {
    /// Static areas only.
    Static,
    /// Half areas, half tracks (alternating).
    Mixed,
    /// Tracks only.
    Tracks,
}

/// Arguments of `polyguard generate`.
#[derive(clap::Args, Debug, Clone)]
pub struct GenerateArgs {
    /// Number of objects.
    #[arg(long)]
    pub objects: usize,
    /// Areas, tracks or both.
    #[arg(long, value_enum, default_value_t = Mix::Mixed)]
    pub mix: Mix,
    /// Random seed.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Stretch the box with the number of objects (constant density).
    #[arg(long)]
    pub density_box: bool,
    /// Output file (standard output when absent).
    #[arg(long, short)]
    pub output: Option<PathBuf>,
}

/// SplitMix64 (Steele, Lea, Flood 2014): a small, seedable, well-mixed generator.
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[lo, hi)`, from the top 53 bits.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        lo + (hi - lo) * u
    }
    /// Uniform integer in `lo..=hi`.
    pub fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }
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

fn random_point(rng: &mut Rng, bx: ((f64, f64), (f64, f64))) -> LonLat {
    let lon = rng.uniform(bx.0 .0, bx.0 .1);
    let lat = rng.uniform(bx.1 .0, bx.1 .1);
    LonLat::from_degrees(lon, lat)
}

/// Paper B §VI.D: one random area.
pub fn random_area(rng: &mut Rng, bx: ((f64, f64), (f64, f64))) -> Area {
    let c = random_point(rng, bx);
    let n = rng.int(3, 10);
    let tau = core::f64::consts::TAU;
    let angles = loop {
        let mut a: Vec<f64> = (0..n).map(|_| rng.uniform(0.0, tau)).collect();
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
        .map(|&b| rhumb_destination(c, b, rng.uniform(50.0, 100.0)))
        .collect();
    ring.reverse();
    Area {
        ring,
        t0: None,
        tf: None,
    }
}

/// Paper B §VI.D: one random track.
pub fn random_track(rng: &mut Rng, bx: ((f64, f64), (f64, f64))) -> Track {
    let p = random_point(rng, bx);
    let bearing = rng.uniform(0.0, core::f64::consts::TAU);
    let q = rhumb_destination(p, bearing, rng.uniform(50.0, 100.0));
    let length = rng.uniform(20.0, 40.0);
    let width = rng.uniform(20.0, 40.0);
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
pub fn generate(n: usize, mix: Mix, seed: u64, density_box: bool) -> Scenario {
    let mut rng = Rng::new(seed);
    let bx = generation_box(n, density_box);
    let features = (0..n)
        .map(|i| {
            let area = match mix {
                Mix::Static => true,
                Mix::Tracks => false,
                Mix::Mixed => i % 2 == 0,
            };
            if area {
                Feature {
                    id: format!("a{i}"),
                    kind: Kind::Area(random_area(&mut rng, bx)),
                    extra: Default::default(),
                }
            } else {
                Feature {
                    id: format!("t{i}"),
                    kind: Kind::Track(random_track(&mut rng, bx)),
                    extra: Default::default(),
                }
            }
        })
        .collect();
    Scenario { features }
}

/// Runs `polyguard generate`.
pub fn run(args: &GenerateArgs) -> ExitCode {
    let sc = generate(args.objects, args.mix, args.seed, args.density_box);
    let text = crate::scenario::to_geojson(&sc).to_string();
    let res = match &args.output {
        Some(p) => std::fs::write(p, text + "\n"),
        None => {
            println!("{text}");
            Ok(())
        }
    };
    match res {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polyguard generate: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deterministic_and_in_box() {
        let a = generate(50, Mix::Mixed, 7, false);
        let b = generate(50, Mix::Mixed, 7, false);
        assert_eq!(a, b);
        let tracks = a
            .features
            .iter()
            .filter(|f| matches!(f.kind, Kind::Track(_)))
            .count();
        assert_eq!(tracks, 25);
        for f in &a.features {
            if let Kind::Area(ar) = &f.kind {
                assert!((3..=10).contains(&ar.ring.len()));
                let o = crate::scenario::objects(&Scenario {
                    features: vec![f.clone()],
                });
                // sorted angles with gaps ≤ π: a simple (star-shaped) ring
                assert!(crate::conflict::geom::signed_area(&o[0].sweep) > 0.0);
            }
        }
    }
}
