//! Many aircraft against many cells at once (`batch::detect_batch`), and the same answer
//! pair by pair (`api::detect`): the batch's broad phase only spares pairs whose boxes
//! prove paper A's "no".
//!
//! A row of 50 aircraft flying north, one unit apart, against 20 drifting cells in a row.
//!
//! `cargo run --example batch` (add `--features parallel` for all cores)

use polyguard::api::{detect, Case, MovingPoint, MovingPolygon, Params};
use polyguard::batch::detect_batch;
use polyguard::Vect2;

fn cell(x: f64) -> Result<MovingPolygon, polyguard::error::CaseError> {
    let square = vec![
        Vect2::new(x, 0.0),
        Vect2::new(x + 1.5, 0.0),
        Vect2::new(x + 1.5, 1.5),
        Vect2::new(x, 1.5),
    ];
    MovingPolygon::new(square, Some(vec![Vect2::new(0.3, 0.0); 4]))
}

fn main() -> Result<(), polyguard::error::CaseError> {
    let lookahead = 8.0;
    let params = Params::new(0.05)?;
    let points = (0..50)
        .map(|k| MovingPoint::new_2d(Vect2::new(k as f64, -5.0), Vect2::new(0.0, 1.0)))
        .collect::<Result<Vec<_>, _>>()?;
    let polygons = (0..20)
        .map(|k| cell(2.5 * k as f64))
        .collect::<Result<Vec<_>, _>>()?;

    let hits = detect_batch(lookahead, &points, &polygons, &params)?;
    println!(
        "{} of {} pairs detected",
        hits.len(),
        points.len() * polygons.len()
    );

    // every pair, one at a time
    let mut pairwise = Vec::new();
    for (i, p) in points.iter().enumerate() {
        for (j, q) in polygons.iter().enumerate() {
            if detect(&Case::new(lookahead, *p, q.clone(), params)?).detected {
                pairwise.push((i, j));
            }
        }
    }
    let batch: Vec<_> = hits.iter().map(|h| (h.point, h.polygon)).collect();
    assert_eq!(
        batch, pairwise,
        "the batch and the pairwise engine agree here"
    );
    assert!(!batch.is_empty());
    println!(
        "the batch agrees with api::detect on all {} pairs",
        points.len() * polygons.len()
    );
    Ok(())
}
