//! Arbitrary bytes into the moving-features readers (docs/moving-features.md, "Formats"):
//! MF-JSON / GeoJSON / JSON Lines and the CSV of fixes never panic, every error's line is
//! inside the text, and whatever they accept satisfies the model's rules (finite
//! positions in range, times strictly increasing, at least 2 fixes, rings of at least 3
//! vertices, floor ≤ ceiling).
#![no_main]

use libfuzzer_sys::fuzz_target;
use polyguard_earth::moving::error::MovingError;
use polyguard_earth::moving::fixes_csv;
use polyguard_earth::moving::mfjson::{self, Item};
use polyguard_earth::moving::model::{Area, Fix, Rings, Shape};

fn fix_ok(f: &Fix) {
    assert!(
        f.t.is_finite() && (-180.0..=180.0).contains(&f.lon) && (-85.0..=85.0).contains(&f.lat)
    );
    assert!(f.alt_ft.is_none_or(f64::is_finite));
}

fn movers_ok(fixes: &[Fix]) {
    assert!(fixes.len() >= 2);
    fixes.iter().for_each(fix_ok);
    assert!(fixes.windows(2).all(|w| w[0].t < w[1].t));
}

fn rings_ok(r: &Rings) {
    for ring in std::iter::once(&r.outer).chain(&r.holes) {
        assert!(ring.len() >= 3);
    }
}

fn area_ok(a: &Area) {
    if let (Some(f), Some(c)) = (a.floor_ft, a.ceiling_ft) {
        assert!(f <= c);
    }
    match &a.shape {
        Shape::Static(parts) => parts.iter().for_each(rings_ok),
        Shape::Keyframed(k) => {
            assert!(k.len() >= 2 && k.windows(2).all(|w| w[0].t < w[1].t));
            k.iter().flat_map(|f| &f.parts).for_each(rings_ok);
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    // a text of k newlines has k + 1 lines
    let lines = text.matches('\n').count() + 1;
    let line_ok = |e: &MovingError| {
        if let Some(l) = e.at.line {
            assert!((1..=lines).contains(&l), "line {l} of {lines}: {e}");
        }
        let _ = e.to_string();
    };
    match mfjson::read(text) {
        Ok(r) => {
            for item in &r.items {
                match item {
                    Ok(Item::Mover(t)) => movers_ok(&t.fixes),
                    Ok(Item::Area(a)) => area_ok(a),
                    Err(e) => line_ok(e),
                }
            }
        }
        Err(e) => line_ok(&e),
    }
    match fixes_csv::read(text) {
        Ok(r) => {
            r.errors.iter().for_each(line_ok);
            r.trajectories.iter().for_each(|t| movers_ok(&t.fixes));
        }
        Err(e) => line_ok(&e),
    }
});
