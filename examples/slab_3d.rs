//! An airspace with a floor and a ceiling (paper A §III: a polygon extruded into a slab),
//! and two climbing aircraft.
//!
//! The airspace is the square [0, 4] × [0, 4] between heights 3 and 5. Both aircraft
//! start at (−2, 2, 0) and fly east at 1.
//! - The first climbs at 1: it is over the square from t = 2 (x = 0) to t = 6, and
//!   reaches the floor at t = 3, at x = 1: it enters at t = 3.
//! - The second climbs at 0.2: it reaches the floor at t = 15, long after it has left the
//!   square at t = 6, and passes under the airspace: no entry within T = 20.
//!
//! `cargo run --example slab_3d`

use polyguard::api::{detect, detect_time, Case, MovingPoint, MovingPolygon, Params};
use polyguard::entry::EntryTime;
use polyguard::Vect2;

fn airspace() -> Result<MovingPolygon, polyguard::error::CaseError> {
    let square = vec![
        Vect2::new(0.0, 0.0),
        Vect2::new(4.0, 0.0),
        Vect2::new(4.0, 4.0),
        Vect2::new(0.0, 4.0),
    ];
    // at rest (no velocities), floor 3, ceiling 5, not moving vertically
    MovingPolygon::new(square, None)?.with_slab(3.0, 5.0, 0.0)
}

fn main() -> Result<(), polyguard::error::CaseError> {
    let params = Params::new(0.01)?;

    let steep = MovingPoint::new_3d([-2.0, 2.0, 0.0], [1.0, 0.0, 1.0])?;
    let case = Case::new(20.0, steep, airspace()?, params)?;
    let answer = detect(&case);
    println!(
        "steep climb: detected {} by {}",
        answer.detected,
        answer.method.name()
    );
    assert!(answer.detected);
    assert_eq!(answer.method.name(), "detect_3d");
    match detect_time(&case) {
        EntryTime::Enters { lo, hi } => {
            println!("  enters in [{lo}, {hi}] (by hand: 3)");
            assert!(lo <= 3.0 && 3.0 <= hi);
        }
        other => panic!("a certified entry was expected, got {other:?}"),
    }

    let shallow = MovingPoint::new_3d([-2.0, 2.0, 0.0], [1.0, 0.0, 0.2])?;
    let case = Case::new(20.0, shallow, airspace()?, params)?;
    let answer = detect(&case);
    println!("shallow climb: detected {}", answer.detected);
    assert!(!answer.detected, "it passes under the floor");
    assert_eq!(detect_time(&case), EntryTime::Never);
    Ok(())
}
