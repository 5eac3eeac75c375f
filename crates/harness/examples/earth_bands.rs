//! Course bands on the Earth (`polyguard_earth::bands`), measured: for random encounters
//! at several latitudes (the generator of tests/paper_a_earth.rs, BUFF 5 nm, lookahead
//! at most 30 min), the unknown total of the course bands (unknown_max 0.1°), how often
//! it was met, the time per answer, and the bands against the ground truth
//! (reference::approach): 8 courses drawn in each band; a clear course whose closest
//! approach is within BUFF, or a conflict course whose closest approach is beyond it,
//! is counted wrong.
//!
//! `cargo run --release -p polyguard-harness --example earth_bands [N per latitude]`

use std::time::Instant;

use polyguard_earth::bands::{course_bands, Kind};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::paper_a::{EarthCase, Motion};
use polyguard_earth::reference::approach::{closest_approach, encounter, Mix};

fn quantile(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(((v.len() as f64 - 1.0) * q).round() as usize)
        .copied()
        .unwrap_or(f64::NAN)
}

fn main() {
    let n: u64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    println!("| latitude | encounters | unknown total: median | p90 | max | met | ms per answer: median | max | courses drawn | wrong |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let mut rng = Mix(5);
    for lat in [0.0, 30.0, 45.0, 60.0, 75.0] {
        let (mut unknown, mut ms) = (Vec::new(), Vec::new());
        let (mut met, mut drawn, mut wrong, mut answered) = (0, 0, 0, 0);
        for seed in 0..n {
            let mut case = encounter(7000 + seed, lat);
            case.buff_nm = 5.0;
            case.lookahead_h = case.lookahead_h.min(0.5);
            let t0 = Instant::now();
            let Ok(bands) = course_bands(&case, Geodesy::Sphere, 0.1) else {
                continue;
            };
            ms.push(t0.elapsed().as_secs_f64() * 1e3);
            answered += 1;
            unknown.push(bands.unknown_total);
            met += usize::from(bands.met);
            for b in &bands.bands {
                if b.kind == Kind::Unknown {
                    continue;
                }
                for _ in 0..8 {
                    let x = rng.uniform(b.lo, b.hi);
                    let flown = EarthCase {
                        aircraft: Motion {
                            course_deg: x,
                            ..case.aircraft
                        },
                        ..case.clone()
                    };
                    let (d, _) = closest_approach(&flown, Geodesy::Sphere, 400);
                    drawn += 1;
                    let bad = match b.kind {
                        Kind::Clear => d <= case.buff_nm,
                        _ => d > case.buff_nm,
                    };
                    if bad {
                        wrong += 1;
                        eprintln!("wrong: seed {seed} lat {lat} course {x} {:?} d {d}", b.kind);
                    }
                }
            }
        }
        let max = unknown.iter().copied().fold(0.0, f64::max);
        let ms_max = ms.iter().copied().fold(0.0, f64::max);
        println!(
            "| {lat}° | {answered} | {:.3}° | {:.3}° | {:.3}° | {met} of {answered} | {:.1} | {:.1} | {drawn} | {wrong} |",
            quantile(&mut unknown, 0.5),
            quantile(&mut unknown, 0.9),
            max,
            quantile(&mut ms, 0.5),
            ms_max,
        );
    }
}
