//! The legend: a sample of each thing drawn and what it is, and the notes a reader needs
//! (labels left out for want of room, bands left out between panels, rings around
//! features too small to see).

use super::PALETTE;
use std::fmt::Write as _;

/// The legend's width (pixels).
pub(super) const WIDTH: f64 = 250.0;
/// Notes wrap at this many characters (11-pixel text in [`WIDTH`]).
const NOTE_CHARS: usize = 38;

/// `text` in lines of at most [`NOTE_CHARS`] characters, broken between words.
fn wrap(text: &str) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= NOTE_CHARS => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    lines
}

/// A legend entry's sample: a box or a line, in an SVG style.
pub(super) enum Sample {
    Boxed(String),
    Lined(String),
}

/// The legend's entries: a sample and what it stands for (stage 1's boxes and stage 3's
/// projections too with `detail`).
pub(super) fn entries(detail: bool) -> Vec<(Sample, &'static str)> {
    let c0 = PALETTE[0];
    let mut out = vec![
        (
            Sample::Boxed(format!(
                "fill=\"{c0}\" fill-opacity=\"0.08\" stroke=\"{c0}\" stroke-width=\"1.5\""
            )),
            "area (holes unfilled)",
        ),
        (
            Sample::Lined(format!(
                "stroke=\"{c0}\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\""
            )),
            "track, direction of travel",
        ),
        (
            Sample::Boxed(format!(
                "fill=\"{c0}\" fill-opacity=\"0.15\" stroke=\"{c0}\""
            )),
            "rectangle at a leg's start, end",
        ),
        (
            Sample::Boxed(format!(
                "fill=\"none\" stroke=\"{c0}\" stroke-dasharray=\"5 3\""
            )),
            "swept hull of a leg (eq 7)",
        ),
        (
            Sample::Boxed(
                "fill=\"red\" fill-opacity=\"0.35\" stroke=\"red\" stroke-dasharray=\"2 2\""
                    .to_owned(),
            ),
            "conflict region, window (h)",
        ),
    ];
    if detail {
        out.push((
            Sample::Boxed("fill=\"none\" stroke=\"#999\" stroke-dasharray=\"1 3\"".to_owned()),
            "bounding box (eqs 3–6)",
        ));
        out.push((
            Sample::Lined("stroke=\"red\" stroke-width=\"0.5\"".to_owned()),
            "projection on a track (eq 10)",
        ));
    }
    out
}

/// The legend at (`x`, `y`) (its top-left corner): the samples `entries` (each with what
/// it stands for), then `notes`. Its height (pixels).
pub(super) fn legend(
    out: &mut String,
    (x, y): (f64, f64),
    entries: &[(Sample, String)],
    notes: &[String],
) -> f64 {
    let lines: Vec<String> = notes.iter().flat_map(|n| wrap(n)).collect();
    let height = 22.0 + 30.0 * entries.len() as f64 + 15.0 * lines.len() as f64 + 4.0;
    let _ = writeln!(
        out,
        "<rect x=\"{x:.2}\" y=\"{y:.2}\" width=\"{:.2}\" height=\"{height:.0}\" fill=\"white\" \
         stroke=\"#888\"/>",
        WIDTH - 10.0
    );
    let sx = x + 10.0;
    let mut ly = y + 22.0;
    for (sample, text) in entries {
        let _ = match sample {
            Sample::Boxed(style) => write!(
                out,
                "<rect x=\"{sx:.2}\" y=\"{:.2}\" width=\"28\" height=\"14\" {style}/>",
                ly - 7.0
            ),
            Sample::Lined(style) => write!(
                out,
                "<line x1=\"{sx:.2}\" y1=\"{ly:.2}\" x2=\"{:.2}\" y2=\"{ly:.2}\" {style}/>",
                sx + 28.0
            ),
        };
        let _ = writeln!(
            out,
            "<text x=\"{:.2}\" y=\"{:.2}\">{}</text>",
            x + 48.0,
            ly + 4.0,
            super::esc(text)
        );
        ly += 30.0;
    }
    for line in &lines {
        let _ = writeln!(
            out,
            "<text x=\"{sx:.2}\" y=\"{:.2}\" fill=\"#555\" font-size=\"11\">{}</text>",
            ly - 4.0,
            super::esc(line)
        );
        ly += 15.0;
    }
    height
}
