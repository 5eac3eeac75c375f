//! The graticule: meridians and parallels at a round step on each panel's Mercator
//! plot, labelled in degrees on the frame, and the bands left out between panels.

use super::frame::Frame;
use super::layout::Break;
use crate::geodesy::Geodesy;
use crate::sphere::LonLat;
use std::fmt::Write as _;

/// Round steps of the graticule (degrees).
const STEPS: [f64; 16] = [
    0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0,
];
/// Graticule lines are at least this far apart (pixels, along the equator).
const LINE_SPACING_PX: f64 = 100.0;

/// The round step (degrees) that draws lines at least [`LINE_SPACING_PX`] apart at `k`
/// pixels a radian: one step for every panel, which share the scale.
pub(super) fn step(k: f64) -> f64 {
    let least = (LINE_SPACING_PX / k).to_degrees();
    STEPS.iter().copied().find(|&s| s >= least).unwrap_or(90.0)
}

/// A longitude label, wrapped into (−180, 180].
fn lon_label(deg: f64) -> String {
    let l = crate::scenario::normal_lon(deg);
    let a = (l.abs() * 100.0).round() / 100.0;
    if a == 0.0 || a == 180.0 {
        format!("{a}°")
    } else if l > 0.0 {
        format!("{a}°E")
    } else {
        format!("{a}°W")
    }
}

/// A latitude label.
fn lat_label(deg: f64) -> String {
    let a = (deg.abs() * 100.0).round() / 100.0;
    if a == 0.0 {
        "0°".to_owned()
    } else if deg > 0.0 {
        format!("{a}°N")
    } else {
        format!("{a}°S")
    }
}

/// One panel's frame and graticule at `step` degrees on the model `geo`: meridians
/// labelled below the plot, parallels to its left.
pub(super) fn graticule(out: &mut String, f: &Frame, geo: Geodesy, step: f64) {
    let [x0, y0, x1, y1] = f.rect();
    let _ = writeln!(
        out,
        "<rect x=\"{x0:.2}\" y=\"{y0:.2}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"none\" \
         stroke=\"#888\"/>",
        x1 - x0,
        y1 - y0
    );
    let (lon0, lon1) = (f.b[0].to_degrees(), f.b[2].to_degrees());
    let mut g = (lon0 / step).ceil() * step;
    while g <= lon1 {
        let (x, _) = f.pt([g.to_radians(), 0.0], 0.0);
        let _ = writeln!(
            out,
            "<line x1=\"{x:.2}\" y1=\"{y0:.2}\" x2=\"{x:.2}\" y2=\"{y1:.2}\" stroke=\"#ddd\"/>\
             <text x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#555\">{}</text>",
            y1 + 16.0,
            lon_label(g)
        );
        g += step;
    }
    let lat0 = geo.inverse_mercator([0.0, f.b[1]]).lat.to_degrees();
    let lat1 = geo.inverse_mercator([0.0, f.b[3]]).lat.to_degrees();
    let mut g = (lat0 / step).ceil() * step;
    while g <= lat1 {
        let y = geo.mercator(LonLat::from_degrees(0.0, g))[1];
        let (_, py) = f.pt([0.0, y], 0.0);
        let _ = writeln!(
            out,
            "<line x1=\"{x0:.2}\" y1=\"{py:.2}\" x2=\"{x1:.2}\" y2=\"{py:.2}\" stroke=\"#ddd\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#555\">{}</text>",
            x0 - 6.0,
            py + 4.0,
            lat_label(g)
        );
        g += step;
    }
}

/// How wide a band left out is, in degrees of longitude or latitude on `geo`.
pub(super) fn band_deg(b: &Break, geo: Geodesy) -> f64 {
    if b.across_x {
        (b.to - b.from).to_degrees()
    } else {
        let lat = |y: f64| geo.inverse_mercator([0.0, y]).lat.to_degrees();
        lat(b.to) - lat(b.from)
    }
}

/// A band left out between two panels, named where it is: "≈ 146° of longitude" written
/// up the gap between panels side by side, or across the gap between stacked ones.
pub(super) fn band(out: &mut String, b: &Break, geo: Geodesy) {
    let (x, y) = b.at;
    let what = if b.across_x { "longitude" } else { "latitude" };
    let text = format!("≈ {:.0}° of {what} left out", band_deg(b, geo));
    let turn = if b.across_x {
        format!(" transform=\"rotate(-90 {x:.2} {y:.2})\"")
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "<text x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#777\" font-size=\"11\" \
         font-style=\"italic\"{turn}>{text}</text>",
        y + 4.0
    );
}
