//! The timeline under an encounters map: one row per pair met, a UTC time axis, bars for
//! the certified spans of inside and near (docs/moving-features.md, "The contract"):
//! certain spans solid, possible ones hatched or dashed, the first loss of separation
//! marked, the mover's gaps shaded.

use super::esc;
use crate::moving::plane::TimeSpan;
use crate::moving::time::{format, Round};
use std::fmt::Write as _;

/// Round steps of the time axis (seconds).
const STEPS_S: [f64; 17] = [
    1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 60.0, 120.0, 300.0, 600.0, 900.0, 1800.0, 3600.0, 7200.0,
    10800.0, 21600.0, 43200.0,
];
/// Ticks of the time axis are at least this far apart (pixels).
const TICK_SPACING_PX: f64 = 64.0;
/// A row's height (pixels).
pub(super) const ROW_H: f64 = 20.0;
/// The label column's width (pixels), left of the axis.
pub(super) const LABEL_W: f64 = 180.0;
/// A row's label is cut to this many characters.
const LABEL_CHARS: usize = 26;
/// Spans narrower than this are drawn this wide, to be seen (pixels).
const MIN_BAR_PX: f64 = 1.5;

/// One row: a pair met, named and coloured, with its spans and the mover's gaps.
pub(super) struct Row<'a> {
    /// What the row names (the area, or the mover).
    pub label: String,
    /// The pair's colour, and its index in the palette (for its hatch pattern).
    pub colour: (&'static str, usize),
    /// When the mover is inside.
    pub inside: &'a [TimeSpan],
    /// When it is near.
    pub near: &'a [TimeSpan],
    /// The mover's gaps, `[last fix before, first fix after]`.
    pub gaps: &'a [[f64; 2]],
}

/// Where the timeline lies: its top-left corner, the axis's width, and the times shown.
pub(super) struct Axis {
    /// The timeline's left edge (the label column starts here).
    pub left: f64,
    /// The top of the first row.
    pub top: f64,
    /// The time axis's width (pixels), right of the label column.
    pub width: f64,
    /// The times at the axis's ends (seconds since 1970-01-01T00:00:00Z).
    pub t: [f64; 2],
}

impl Axis {
    /// The pixel `x` of time `t`.
    fn x(&self, t: f64) -> f64 {
        let span = (self.t[1] - self.t[0]).max(1.0);
        self.left + LABEL_W + (t - self.t[0]) / span * self.width
    }

    /// The pixel span of [a, b], cut to the axis and at least [`MIN_BAR_PX`] wide.
    fn bar(&self, a: f64, b: f64) -> Option<(f64, f64)> {
        if b < self.t[0] || a > self.t[1] {
            return None;
        }
        let (x0, x1) = (self.x(a.max(self.t[0])), self.x(b.min(self.t[1])));
        if x1 - x0 >= MIN_BAR_PX {
            Some((x0, x1 - x0))
        } else {
            Some(((x0 + x1 - MIN_BAR_PX) / 2.0, MIN_BAR_PX))
        }
    }
}

/// `t` as UTC `HH:MM`, or `HH:MM:SS` when the axis's step is under a minute.
fn clock(t: f64, seconds: bool) -> String {
    let s = format(t, Round::Nearest).unwrap_or_default();
    let hms = s.get(11..19).unwrap_or("");
    if seconds {
        hms.to_owned()
    } else {
        hms.get(..5).unwrap_or("").to_owned()
    }
}

/// The round tick step (seconds) that keeps ticks [`TICK_SPACING_PX`] apart on `axis`.
fn step(axis: &Axis) -> f64 {
    let least = TICK_SPACING_PX / axis.width * (axis.t[1] - axis.t[0]).max(1.0);
    STEPS_S
        .iter()
        .copied()
        .find(|&s| s >= least)
        .unwrap_or(86400.0)
}

/// The axis: ticks and light lines down through `n` rows, clock labels above, and the
/// day (UTC) at the label column.
fn ticks(out: &mut String, axis: &Axis, n: usize) {
    let s = step(axis);
    let bottom = axis.top + ROW_H * n as f64;
    let mut t = (axis.t[0] / s).ceil() * s;
    while t <= axis.t[1] {
        let x = axis.x(t);
        let _ = writeln!(
            out,
            "<line x1=\"{x:.2}\" y1=\"{:.2}\" x2=\"{x:.2}\" y2=\"{bottom:.2}\" stroke=\"#ddd\"/>\
             <text x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#555\" \
             font-size=\"11\">{}</text>",
            axis.top - 4.0,
            axis.top - 8.0,
            clock(t, s < 60.0)
        );
        t += s;
    }
    let day = format(axis.t[0], Round::Nearest)
        .and_then(|d| d.get(..10).map(str::to_owned))
        .unwrap_or_default();
    let _ = writeln!(
        out,
        "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#555\" font-size=\"11\">time, UTC ({day})</text>\
         <rect x=\"{:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"none\" \
         stroke=\"#888\"/>",
        axis.left,
        axis.top - 8.0,
        axis.left + LABEL_W,
        axis.top,
        axis.width,
        bottom - axis.top
    );
}

/// One span's bar in a row whose top is `y`: `near` a tall pale bar (hatched when
/// possible), inside a narrow dark one (dashed outline when possible); the tooltip gives
/// the span's outer ends.
fn span_bar(out: &mut String, axis: &Axis, y: f64, s: &TimeSpan, near: bool, c: (&str, usize)) {
    let Some((x, w)) = axis.bar(s.start[0], s.end[1]) else {
        return;
    };
    let (h, dy) = if near { (14.0, 3.0) } else { (6.0, 7.0) };
    let style = match (near, s.certain) {
        (true, true) => format!("fill=\"{}\" fill-opacity=\"0.3\"", c.0),
        (true, false) => format!(
            "fill=\"url(#hatch{})\" stroke=\"{}\" stroke-width=\"0.5\"",
            c.1, c.0
        ),
        (false, true) => format!("fill=\"{}\"", c.0),
        (false, false) => format!(
            "fill=\"white\" stroke=\"{}\" stroke-width=\"1.5\" stroke-dasharray=\"3 2\"",
            c.0
        ),
    };
    let what = match (near, s.certain) {
        (true, true) => "near",
        (true, false) => "possibly near",
        (false, true) => "inside",
        (false, false) => "possibly inside",
    };
    let _ = writeln!(
        out,
        "<rect x=\"{x:.2}\" y=\"{:.2}\" width=\"{w:.2}\" height=\"{h:.0}\" {style}><title>{what} \
         {} – {}</title></rect>",
        y + dy,
        format(s.start[0], Round::Floor).unwrap_or_default(),
        format(s.end[1], Round::Ceil).unwrap_or_default(),
    );
}

/// The timeline at `axis` for `rows` (the first `shown` drawn, the rest
/// counted in a line below); `shared_gaps`: the one mover's gaps shaded
/// across every row (else each row shades its own). Its height (pixels).
pub(super) fn timeline(
    out: &mut String,
    axis: &Axis,
    rows: &[Row],
    shown: usize,
    shared_gaps: bool,
) -> f64 {
    if rows.is_empty() {
        let _ = writeln!(
            out,
            "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#555\">nothing met: no timeline</text>",
            axis.left, axis.top
        );
        return 8.0;
    }
    let n = rows.len().min(shown);
    ticks(out, axis, n);
    let shade = |out: &mut String, g: &[f64; 2], y: f64, h: f64| {
        if let Some((x, w)) = axis.bar(g[0], g[1]) {
            let _ = writeln!(
                out,
                "<rect x=\"{x:.2}\" y=\"{y:.2}\" width=\"{w:.2}\" height=\"{h:.2}\" \
                 fill=\"#888\" fill-opacity=\"0.25\"><title>gap: no fixes</title></rect>"
            );
        }
    };
    if shared_gaps {
        for g in rows.first().map_or(&[][..], |r| r.gaps) {
            shade(out, g, axis.top, ROW_H * n as f64);
        }
    }
    for (i, r) in rows.iter().take(n).enumerate() {
        let y = axis.top + ROW_H * i as f64;
        if i % 2 == 1 {
            let _ = writeln!(
                out,
                "<rect x=\"{:.2}\" y=\"{y:.2}\" width=\"{:.2}\" height=\"{ROW_H}\" fill=\"#000\" \
                 fill-opacity=\"0.03\"/>",
                axis.left,
                LABEL_W + axis.width
            );
        }
        if !shared_gaps {
            for g in r.gaps {
                shade(out, g, y, ROW_H);
            }
        }
        let label: String = if r.label.chars().count() > LABEL_CHARS {
            r.label.chars().take(LABEL_CHARS - 1).chain(['…']).collect()
        } else {
            r.label.clone()
        };
        let _ = writeln!(
            out,
            "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"10\" height=\"10\" fill=\"{}\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" font-size=\"11\">{}<title>{}</title></text>",
            axis.left,
            y + 5.0,
            r.colour.0,
            axis.left + 14.0,
            y + 14.0,
            esc(&label),
            esc(&r.label)
        );
        for s in r.near {
            span_bar(out, axis, y, s, true, r.colour);
        }
        for s in r.inside {
            span_bar(out, axis, y, s, false, r.colour);
        }
        if let Some(s) = r.near.first() {
            los_mark(out, axis, y, s.start[0]);
        }
    }
    let mut h = ROW_H * n as f64;
    if rows.len() > n {
        let _ = writeln!(
            out,
            "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#555\" font-size=\"11\">and {} more</text>",
            axis.left,
            axis.top + h + 14.0,
            rows.len() - n
        );
        h += 20.0;
    }
    h
}

/// The first loss of separation at `t` in the row whose top is `y`: a red line through
/// the row and a triangle above it.
fn los_mark(out: &mut String, axis: &Axis, y: f64, t: f64) {
    if t < axis.t[0] || t > axis.t[1] {
        return;
    }
    let x = axis.x(t);
    let _ = writeln!(
        out,
        "<path d=\"M{x:.2},{:.2} L{x:.2},{:.2} M{:.2},{:.2} L{:.2},{:.2} L{x:.2},{:.2} Z\" \
         stroke=\"red\" stroke-width=\"1.5\" fill=\"red\"><title>first loss of separation \
         {}</title></path>",
        y + 1.0,
        y + ROW_H - 1.0,
        x - 3.5,
        y + 1.0,
        x + 3.5,
        y + 1.0,
        y + 5.0,
        format(t, Round::Floor).unwrap_or_default()
    );
}

/// Hatch patterns, one per palette colour (`hatch{i}`), for possible spans.
pub(super) fn hatches(out: &mut String, palette: &[&str]) {
    out.push_str("<defs>");
    for (i, c) in palette.iter().enumerate() {
        let _ = write!(
            out,
            "<pattern id=\"hatch{i}\" width=\"5\" height=\"5\" patternUnits=\"userSpaceOnUse\" \
             patternTransform=\"rotate(45)\"><rect width=\"5\" height=\"5\" fill=\"{c}\" \
             fill-opacity=\"0.1\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"5\" stroke=\"{c}\" \
             stroke-width=\"2\"/></pattern>"
        );
    }
    out.push_str("</defs>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The axis's step is the first round step that keeps ticks apart, and clock labels
    /// are UTC hours and minutes (seconds too under a minute's step).
    #[test]
    fn ticks_are_round_and_clocks_are_utc() {
        let axis = Axis {
            left: 0.0,
            top: 0.0,
            width: 640.0,
            t: [0.0, 3600.0],
        };
        // 10 ticks at most in 640 pixels: a step of at least 360 s, so 600 s
        assert_eq!(step(&axis), 600.0);
        assert_eq!(clock(1_633_613_562.0, false), "13:32");
        assert_eq!(clock(1_633_613_562.0, true), "13:32:42");
        // a span too short to see is drawn MIN_BAR_PX wide about its place
        let (x, w) = axis.bar(1800.0, 1800.0).expect("on the axis");
        assert_eq!(w, MIN_BAR_PX);
        assert!((x + w / 2.0 - axis.x(1800.0)).abs() < 1e-9);
        assert!(axis.bar(4000.0, 5000.0).is_none());
    }
}
