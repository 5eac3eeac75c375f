//! How conservative is paper A on the Earth (`polyguard_earth::paper_a`)? For random
//! encounters at several latitudes (the generator of tests/paper_a_earth.rs), the
//! truth's closest approach `d` (reference::approach) against the smallest BUFF at which
//! the engine alarms, `b*` (by bisection): the alarm reaches `d / b*` times BUFF (1 would
//! be no false alarm at all). The share of encounters whose reach exceeds 1.05 and 1.2 is
//! the false-alarm rate for aircraft passing 5 % and 20 % beyond BUFF. The same with one
//! piece, and how often the canary (unscaled BUFF) misses an approach within BUFF.
//!
//! `cargo run --release -p polyguard-harness --example earth_false_alarms [N per latitude]`

use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::{detect_earth_with, Buffer, EarthCase, Options, Pieces};
use polyguard_earth::reference::approach::{closest_approach, encounter};

fn alarms(case: &EarthCase, buff: f64, opts: Options) -> Option<bool> {
    let mut c = case.clone();
    c.buff_nm = buff;
    detect_earth_with(&c, opts).ok().map(|a| a.detected)
}

/// The smallest BUFF (nm) at which the engine alarms, within 0.1 %.
fn threshold(case: &EarthCase, d: f64, opts: Options) -> Option<f64> {
    let (mut lo, mut hi) = (d * 1e-3, d * 1.001);
    if !alarms(case, hi, opts)? {
        return None; // a miss: the tests would fail
    }
    if alarms(case, lo, opts)? {
        return Some(lo);
    }
    while hi / lo > 1.001 {
        let mid = (lo * hi).sqrt();
        if alarms(case, mid, opts)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

fn percentile(v: &mut [f64], p: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let n: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(200);
    let geo = Geodesy::Sphere;
    let certified = Options::default();
    let one_piece = Options {
        pieces: Pieces::Fixed(1),
        ..certified
    };
    let unscaled = Options {
        buffer: Buffer::Unscaled,
        pieces: Pieces::Fixed(1),
        ..certified
    };
    println!("lat  cases  reach d/b*: median  p90   max  | >1.05  >1.2 | 1 piece: median  p90 | unscaled misses");
    for lat in [0.0, 30.0, 45.0, 60.0, 75.0, 84.0] {
        let (mut reach, mut reach1) = (Vec::new(), Vec::new());
        let (mut canary_missed, mut near) = (0, 0);
        for seed in 0..n {
            let case = encounter(seed, lat);
            if detect_earth_with(&case, certified).is_err() {
                continue;
            }
            let (d, _) = closest_approach(&case, geo, 200);
            if d > 0.05 && d < 150.0 {
                near += 1;
                if let Some(b) = threshold(&case, d, certified) {
                    reach.push(d / b);
                }
                if let Some(b) = threshold(&case, d, one_piece) {
                    reach1.push(d / b);
                }
                if alarms(&case, d * 1.001, unscaled) == Some(false) {
                    canary_missed += 1;
                }
            }
        }
        if reach.is_empty() {
            continue;
        }
        let max = reach.iter().copied().fold(0.0, f64::max);
        let share =
            |k: f64| 100.0 * reach.iter().filter(|&&r| r > k).count() as f64 / reach.len() as f64;
        let (s5, s20) = (share(1.05), share(1.2));
        println!(
            "{lat:>4} {:>6}  {:>17.3} {:>5.3} {:>5.3} | {s5:>4.0}% {s20:>4.0}% | {:>15.3} {:>5.3} | {} of {}",
            reach.len(),
            percentile(&mut reach, 0.5),
            percentile(&mut reach, 0.9),
            max,
            percentile(&mut reach1, 0.5),
            percentile(&mut reach1, 0.9),
            canary_missed,
            near
        );
    }
}
