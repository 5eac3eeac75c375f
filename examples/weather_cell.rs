//! A weather cell that drifts east and grows, and an aircraft flying north under it
//! (paper A §II.I: a warping polygon, every vertex with its own velocity).
//!
//! The cell is the square [0, 2] × [0, 2] at t = 0, drifting east at 1 unit per time
//! unit while each side moves out at 0.1. The aircraft starts at (5, −4) and flies north
//! at 1. By hand: its x is inside the cell's span from t = 3/1.1 (the east side
//! 2 + 1.1·t reaches 5), and its y meets the south side −0.1·t at t = 4/1.1 ≈ 3.636, so it
//! enters through the south side at 40/11, within the lookahead T = 10.
//!
//! `cargo run --example weather_cell`

use polyguard::api::{detect, detect_time, Case, Kind, MovingPoint, MovingPolygon, Params};
use polyguard::entry::EntryTime;
use polyguard::Vect2;

fn main() -> Result<(), polyguard::error::CaseError> {
    let square = vec![
        Vect2::new(0.0, 0.0),
        Vect2::new(2.0, 0.0),
        Vect2::new(2.0, 2.0),
        Vect2::new(0.0, 2.0),
    ];
    // east drift (1, 0) plus each corner's outward growth (±0.1, ±0.1)
    let growth = vec![
        Vect2::new(0.9, -0.1),
        Vect2::new(1.1, -0.1),
        Vect2::new(1.1, 0.1),
        Vect2::new(0.9, 0.1),
    ];
    let cell = MovingPolygon::new(square, Some(growth))?;
    let aircraft = MovingPoint::new_2d(Vect2::new(5.0, -4.0), Vect2::new(0.0, 1.0))?;
    let case = Case::new(10.0, aircraft, cell, Params::new(0.01)?)?;

    let answer = detect(&case);
    println!(
        "detected: {} ({:?}, by {})",
        answer.detected,
        answer.kind,
        answer.method.name()
    );
    assert!(answer.detected && answer.kind == Kind::Exact);
    assert_eq!(answer.method.name(), "detect_diff_2d");

    let entry = 40.0 / 11.0;
    match detect_time(&case) {
        EntryTime::Enters { lo, hi } => {
            println!("enters in [{lo}, {hi}] (by hand: 40/11 = {entry})");
            assert!(
                lo <= entry && entry <= hi,
                "the hand-computed entry is enclosed"
            );
        }
        other => panic!("a certified entry was expected, got {other:?}"),
    }
    Ok(())
}
