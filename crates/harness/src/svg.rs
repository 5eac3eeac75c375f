//! One picture per counterexample, for a person to read: the scene with axes and a legend,
//! an inset zoomed to where the decision is made (the nearest edge and its BUFF band),
//! the three verdicts written in, and for 3D cases the heights against time.
//!
//! Every coordinate in the SVG is a pixel computed here: world coordinates are first
//! taken relative to a centre (in f64), then scaled, so that offsets of 10⁹ and polygons
//! of 10⁻³ still give strokes and text of sensible sizes.

use std::fmt::Write as _;

use crate::case::RawCase;
use polyguard::vect2::Vect2;

/// What a counterexample picture says besides the case.
#[derive(Clone, Debug)]
pub struct Picture<'a> {
    /// The title, e.g. "missed_detection in detect_same_2d (edge_buff+long)".
    pub title: &'a str,
    /// The judged f64 engine's verdict (true: detection).
    pub engine: bool,
    /// The judged engine's name: "f64" or "plain".
    pub engine_name: &'a str,
    /// Paper A in exact arithmetic.
    pub paper: bool,
    /// The exact truth: Some(true) enters, Some(false) misses, None undefined.
    pub truth: Option<bool>,
    /// The truth's first-entry time, when it enters.
    pub entry_time: Option<f64>,
    /// The judged engine's entry-time answer (`api::detect_time`), as caption lines:
    /// e.g. "entry (f64): enters", "in [2.99, 3.01]".
    pub entry: Vec<String>,
}

const W: f64 = 960.0;
const MAIN: Rect = Rect {
    x: 70.0,
    y: 60.0,
    w: 540.0,
    h: 520.0,
};
const INSET: Rect = Rect {
    x: 660.0,
    y: 60.0,
    w: 270.0,
    h: 270.0,
};
const HEIGHTS: Rect = Rect {
    x: 70.0,
    y: 680.0,
    w: 860.0,
    h: 190.0,
};

#[derive(Clone, Copy, Debug)]
struct Rect {
    x: f64,
    y: f64,
    w: f64,
    h: f64,
}

/// A world-to-pixel map: x_px = ox + (x − cx)·kx, y_px = oy − (y − cy)·ky.
#[derive(Clone, Copy, Debug)]
struct Map {
    c: Vect2,
    kx: f64,
    ky: f64,
    o: Vect2,
}

impl Map {
    /// The map that fits the box [lo, hi] into `r` with a margin (equal scales when
    /// `equal`).
    fn fit(lo: Vect2, hi: Vect2, r: Rect, equal: bool) -> Map {
        let span = |a: f64, b: f64| {
            let s = b - a;
            if s > 0.0 && s.is_finite() {
                s
            } else {
                // a point, or a span f64 cannot hold: a unit (or relative) window
                (a.abs().max(b.abs()) * 1e-12).max(f64::MIN_POSITIVE * 1e20)
            }
        };
        let (sx, sy) = (span(lo.x, hi.x), span(lo.y, hi.y));
        let (mut kx, mut ky) = (0.9 * r.w / sx, 0.9 * r.h / sy);
        if equal {
            let k = kx.min(ky);
            (kx, ky) = (k, k);
        }
        Map {
            c: Vect2::new(lo.x + 0.5 * (hi.x - lo.x), lo.y + 0.5 * (hi.y - lo.y)),
            kx,
            ky,
            o: Vect2::new(r.x + 0.5 * r.w, r.y + 0.5 * r.h),
        }
    }

    fn px(&self, p: Vect2) -> (f64, f64) {
        let clamp = |v: f64| {
            if v.is_finite() {
                v.clamp(-1e5, 1e5)
            } else {
                0.0
            }
        };
        (
            clamp(self.o.x + (p.x - self.c.x) * self.kx),
            clamp(self.o.y - (p.y - self.c.y) * self.ky),
        )
    }

    /// The world coordinate of pixel column x (row y).
    fn world_x(&self, x: f64) -> f64 {
        self.c.x + (x - self.o.x) / self.kx
    }
    fn world_y(&self, y: f64) -> f64 {
        self.c.y - (y - self.o.y) / self.ky
    }
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number for a label: few digits, exponent when large or small.
fn num(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if (1e-3..1e5).contains(&x.abs()) {
        let s = format!("{x:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_string()
    } else {
        format!("{x:.3e}")
    }
}

/// A 1-2-5 step giving about `n` ticks over `span`.
fn tick_step(span: f64, n: f64) -> f64 {
    let raw = span / n;
    if raw <= 0.0 || !raw.is_finite() {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    let m = raw / p;
    p * if m < 1.5 {
        1.0
    } else if m < 3.5 {
        2.0
    } else if m < 7.5 {
        5.0
    } else {
        10.0
    }
}

fn poly_at(raw: &RawCase, t: f64) -> Vec<Vect2> {
    raw.vertices
        .iter()
        .zip(&raw.velocities)
        .map(|(&p, &v)| Vect2::from(p).at(Vect2::from(v), t))
        .collect()
}

/// The nearest point of segment ab to s, and its distance. Computed on the vectors
/// moved by a power of two to unit scale, so that squares neither overflow (cases near
/// 2¹⁰⁰⁰) nor underflow (subnormal ones).
fn nearest_on(a: Vect2, b: Vect2, s: Vect2) -> (Vect2, f64) {
    let (d, w) = (b - a, s - a);
    let m = d.x.abs().max(d.y.abs()).max(w.x.abs()).max(w.y.abs());
    if !(m > 0.0 && m.is_finite()) {
        return (a, w.x.hypot(w.y));
    }
    let e = m.log2().floor() as i32;
    let unit = |v: Vect2| v.scale(2f64.powi(-e / 2)).scale(2f64.powi(-e + e / 2));
    let (du, wu) = (unit(d), unit(w));
    let len2 = du.sq();
    let r = if len2 > 0.0 {
        (wu.dot(du) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = a + d.scale(r);
    let gap = unit(s - q);
    (
        q,
        gap.x.hypot(gap.y) * 2f64.powi(e / 2) * 2f64.powi(e - e / 2),
    )
}

/// The nearest edge of P to s: (index, nearest point, distance).
fn nearest_edge(p: &[Vect2], s: Vect2) -> (usize, Vect2, f64) {
    let n = p.len();
    (0..n)
        .map(|i| {
            let (q, d) = nearest_on(p[i], p[(i + 1) % n], s);
            (i, q, d)
        })
        .fold(
            (0, s, f64::INFINITY),
            |best, x| if x.2 < best.2 { x } else { best },
        )
}

/// The time of interest: the truth's entry time, else the sampled closest approach of
/// the point to the polygon's boundary over [0, T].
fn event_time(raw: &RawCase, entry: Option<f64>) -> f64 {
    let t = raw.lookahead;
    if let Some(e) = entry.filter(|e| e.is_finite()) {
        return e;
    }
    let (s, v) = point(raw);
    (0..=200)
        .map(|k| t * k as f64 / 200.0)
        .map(|tk| (tk, nearest_edge(&poly_at(raw, tk), s.at(v, tk)).2))
        .fold((0.0, f64::INFINITY), |b, x| if x.1 < b.1 { x } else { b })
        .0
}

fn point(raw: &RawCase) -> (Vect2, Vect2) {
    let g = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0);
    (
        Vect2::new(g(&raw.pos, 0), g(&raw.pos, 1)),
        Vect2::new(g(&raw.vel, 0), g(&raw.vel, 1)),
    )
}

fn path_d(m: &Map, pts: &[Vect2], close: bool) -> String {
    let mut d = String::new();
    for (k, p) in pts.iter().enumerate() {
        let (x, y) = m.px(*p);
        let _ = write!(d, "{}{x:.2} {y:.2} ", if k == 0 { 'M' } else { 'L' });
    }
    if close {
        d.push('Z');
    }
    d
}

fn text(out: &mut String, x: f64, y: f64, size: f64, anchor: &str, s: &str) {
    let _ = writeln!(
        out,
        r#"<text x="{x:.1}" y="{y:.1}" font-size="{size}" font-family="sans-serif" text-anchor="{anchor}">{}</text>"#,
        esc(s)
    );
}

/// Axes with 1-2-5 ticks around `r`; labels relative to `origin` when the coordinates
/// are far larger than the span shown (named in the axis title).
fn axes(out: &mut String, m: &Map, r: Rect, xname: &str, yname: &str) {
    let _ = writeln!(
        out,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#888"/>"##,
        r.x, r.y, r.w, r.h
    );
    let (x0, x1) = (m.world_x(r.x), m.world_x(r.x + r.w));
    let (y0, y1) = (m.world_y(r.y + r.h), m.world_y(r.y));
    for (lo, hi, horizontal) in [(x0, x1, true), (y0, y1, false)] {
        let span = hi - lo;
        let step = tick_step(span, 5.0);
        let mid = lo + 0.5 * span;
        let origin = if mid.abs() > 1e3 * span.abs() {
            (mid / step).round() * step
        } else {
            0.0
        };
        let first = ((lo - origin) / step).ceil();
        for k in 0..=12 {
            let v = origin + (first + k as f64) * step;
            if v > hi || !v.is_finite() {
                break;
            }
            let label = num(v - origin);
            if horizontal {
                let (x, _) = m.px(Vect2::new(v, m.c.y));
                let yb = r.y + r.h;
                let _ = writeln!(
                    out,
                    r##"<line x1="{x:.1}" y1="{yb}" x2="{x:.1}" y2="{}" stroke="#888"/>"##,
                    yb + 5.0
                );
                text(out, x, yb + 18.0, 11.0, "middle", &label);
            } else {
                let (_, y) = m.px(Vect2::new(m.c.x, v));
                let _ = writeln!(
                    out,
                    r##"<line x1="{}" y1="{y:.1}" x2="{}" y2="{y:.1}" stroke="#888"/>"##,
                    r.x - 5.0,
                    r.x
                );
                text(out, r.x - 8.0, y + 4.0, 11.0, "end", &label);
            }
        }
        let name = if horizontal { xname } else { yname };
        let title = if origin != 0.0 {
            format!("{name} − {}", num(origin))
        } else {
            name.to_string()
        };
        if horizontal {
            text(
                out,
                r.x + 0.5 * r.w,
                r.y + r.h + 36.0,
                12.0,
                "middle",
                &title,
            );
        } else {
            let (x, y) = (r.x - 52.0, r.y + 0.5 * r.h);
            let _ = writeln!(
                out,
                r#"<text x="{x}" y="{y}" font-size="12" font-family="sans-serif" text-anchor="middle" transform="rotate(-90 {x} {y})">{}</text>"#,
                esc(&title)
            );
        }
    }
}

/// A horizontal scale bar of a round world length in the lower left of `r`, labelled
/// with that length in the case's own units (`back`, see [`picture`]).
fn scale_bar(out: &mut String, m: &Map, r: Rect, back: &dyn Fn(f64) -> f64) {
    let world = tick_step(0.3 * r.w / m.kx, 1.0);
    let px = world * m.kx;
    let (x, y) = (r.x + 10.0, r.y + r.h - 12.0);
    let _ = writeln!(
        out,
        r##"<line x1="{x}" y1="{y}" x2="{:.1}" y2="{y}" stroke="#000" stroke-width="2"/>"##,
        x + px
    );
    text(out, x, y - 5.0, 11.0, "start", &num(back(world)));
}

/// The polygon (at t = 0 or at the event), its BUFF band, in map `m`.
fn polygon(out: &mut String, m: &Map, p: &[Vect2], buff: f64, event: bool) {
    let d = path_d(m, p, true);
    if event {
        let _ = writeln!(
            out,
            r##"<path d="{d}" fill="#e76f51" fill-opacity="0.12" stroke="#e76f51" stroke-width="1.5" stroke-dasharray="6 4"/>"##
        );
    } else {
        let band = (2.0 * buff * m.kx).max(0.0);
        if band >= 0.5 {
            let _ = writeln!(
                out,
                r##"<path d="{d}" fill="none" stroke="#f4a261" stroke-opacity="0.5" stroke-width="{band:.2}" stroke-linejoin="round"/>"##
            );
        }
        let _ = writeln!(
            out,
            r##"<path d="{d}" fill="#2a9d8f" fill-opacity="0.25" stroke="#2a9d8f" stroke-width="1.5"/>"##
        );
    }
}

/// The point's path from s(t0) to s(t1) with an arrowhead, in map `m`.
fn path(out: &mut String, m: &Map, a: Vect2, b: Vect2) {
    let ((x0, y0), (x1, y1)) = (m.px(a), m.px(b));
    let _ = writeln!(
        out,
        r##"<line x1="{x0:.2}" y1="{y0:.2}" x2="{x1:.2}" y2="{y1:.2}" stroke="#264653" stroke-width="1.5" marker-end="url(#arrow)" marker-mid="url(#arrow)"/>"##
    );
    // a second arrowhead half way, so the direction shows even when the end is off view
    let (mx, my) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let _ = writeln!(
        out,
        r##"<line x1="{x0:.2}" y1="{y0:.2}" x2="{mx:.2}" y2="{my:.2}" stroke="#264653" stroke-width="1.5" marker-end="url(#arrow)"/>"##
    );
}

/// The part of segment ab inside the box centre ± half (Liang–Barsky), computed relative
/// to the centre so that far-away ends do not distort the part that is drawn.
fn clip(a: Vect2, b: Vect2, centre: Vect2, half: f64) -> Option<(Vect2, Vect2)> {
    let (ra, rb) = (a - centre, b - centre);
    let d = rb - ra;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, ra.x + half),
        (d.x, half - ra.x),
        (-d.y, ra.y + half),
        (d.y, half - ra.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1 && t0.is_finite() && t1.is_finite())
        .then(|| (centre + ra + d.scale(t0), centre + ra + d.scale(t1)))
}

/// A dot of `colour` at `p`, without a label.
fn dot(out: &mut String, m: &Map, p: Vect2, colour: &str) {
    let (x, y) = m.px(p);
    let _ = writeln!(
        out,
        r#"<circle cx="{x:.2}" cy="{y:.2}" r="4" fill="{colour}"/>"#
    );
}

/// Font size of a dot's label.
const LABEL_SIZE: f64 = 12.0;

/// Where a dot's label goes so that it stays inside `frame` (which clips the panel):
/// beside the dot at pixel (x, y), above it (or below when `below`), to its right unless
/// that runs past the frame's right side, and on the other side vertically when the
/// chosen one runs past the top or bottom. The width is estimated at 0.62 of the font
/// size per character (sans-serif digits and letters are narrower). Returns the text's
/// x, baseline y and anchor.
fn label_place(frame: Rect, (x, y): (f64, f64), label: &str, below: bool) -> (f64, f64, &str) {
    let (gap, margin) = (7.0, 3.0);
    let width = 0.62 * LABEL_SIZE * label.chars().count() as f64;
    let (right, bottom) = (frame.x + frame.w - margin, frame.y + frame.h - margin);
    let (lx, anchor) = if x + gap + width <= right {
        (x + gap, "start")
    } else if x - gap - width >= frame.x + margin {
        (x - gap, "end")
    } else {
        (right, "end")
    };
    let above = y - gap;
    let under = y + gap + LABEL_SIZE;
    let fits_above = above - LABEL_SIZE >= frame.y + margin;
    let fits_under = under <= bottom;
    let ly = match (below, fits_above, fits_under) {
        (false, true, _) | (true, true, false) => above,
        _ => under.min(bottom),
    };
    (lx, ly, anchor)
}

/// Writes a dot's label, placed by [`label_place`].
fn dot_label(out: &mut String, frame: Rect, at: (f64, f64), label: &str, below: bool) {
    let (x, y, anchor) = label_place(frame, at, label, below);
    text(out, x, y, LABEL_SIZE, anchor, label);
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// The SVG document for a counterexample.
pub fn picture(raw: &RawCase, pic: &Picture) -> String {
    let original = raw;
    // A case near an end of the float range is drawn moved by a power of two to unit
    // scale: lengths, heights and speeds scale, T and F do not, so it is the same case,
    // and the world-to-pixel map neither overflows nor underflows. The axes say by how
    // much; the numbers written out are the case's own.
    let j = drawing_scale(raw);
    let moved;
    let raw: &RawCase = if j == 0 {
        raw
    } else {
        moved = raw.times_pow2(j);
        &moved
    };
    let back = move |x: f64| x * 2f64.powi(-j / 2) * 2f64.powi(-(j - j / 2));
    let named = |name: &str| {
        if j == 0 {
            name.to_string()
        } else {
            format!("{name} · 2^{j}")
        }
    };
    let t = raw.lookahead;
    let three_d = raw.pos.len() == 3 && raw.slab.is_some();
    let height = if three_d { 920.0 } else { 660.0 };
    let event = event_time(raw, pic.entry_time);
    let (s, v) = point(raw);
    let (p0, pe) = (poly_at(raw, 0.0), poly_at(raw, event));
    let (s_e, s_t) = (s.at(v, event), s.at(v, t));
    let mut out = String::new();
    let _ = writeln!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {W} {height}" width="{W}" height="{height}">
<title>{}</title>
<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse"><path d="M0 0 L10 5 L0 10 z" fill="#264653"/></marker>
<clipPath id="main"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>
<clipPath id="inset"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath></defs>
<rect width="100%" height="100%" fill="white"/>"##,
        esc(pic.title),
        MAIN.x,
        MAIN.y,
        MAIN.w,
        MAIN.h,
        INSET.x,
        INSET.y,
        INSET.w,
        INSET.h
    );
    text(&mut out, 20.0, 32.0, 18.0, "start", pic.title);

    // Main panel: everything over [0, T].
    let all: Vec<Vect2> = p0.iter().chain(&pe).copied().chain([s, s_t, s_e]).collect();
    let (lo, hi) = bounds(&all);
    let m = Map::fit(lo, hi, MAIN, true);
    axes(&mut out, &m, MAIN, &named("x"), &named("y"));
    out.push_str("<g clip-path=\"url(#main)\">\n");
    polygon(&mut out, &m, &p0, raw.buff, false);
    polygon(&mut out, &m, &pe, raw.buff, true);
    path(&mut out, &m, s, s_t);
    dot(&mut out, &m, s, "#264653");
    dot(&mut out, &m, s_t, "#264653");
    dot(&mut out, &m, s_e, "#e76f51");
    out.push_str("</g>\n");
    // The labels inside the frame. Those of the ends only where they do not pile up on a
    // short path; the end's label below its dot when the event's label sits near it.
    let (a, b, e) = (m.px(s), m.px(s_t), m.px(s_e));
    let apart = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1);
    if apart(a, b) > 60.0 {
        dot_label(&mut out, MAIN, a, "t = 0", apart(a, e) < 20.0);
        dot_label(&mut out, MAIN, b, "t = T", apart(b, e) < 20.0);
    }
    dot_label(&mut out, MAIN, e, &format!("t = {}", num(event)), false);
    scale_bar(&mut out, &m, MAIN, &back);

    // Inset: the point at the event and the nearest edge of P(event), BUFF visible.
    inset(&mut out, raw, &pe, s_e, v, event, &back);

    // Legend and verdicts, in the case's own numbers.
    legend(&mut out, original, pic, event);

    if three_d {
        heights(&mut out, raw, event, &named("z"));
    }
    out.push_str("</svg>\n");
    out
}

/// The power of two j that brings a case near an end of the float range to unit scale
/// for drawing: its largest length (a coordinate, BUFF, a height, a distance moved over
/// T) is then about 1. 0 for a case whose largest length lies within 2^±200, which f64
/// draws as it is.
fn drawing_scale(raw: &RawCase) -> i32 {
    let t = raw.lookahead;
    let lengths = raw
        .pos
        .iter()
        .chain(raw.vertices.iter().flatten())
        .chain(raw.slab.iter().flatten())
        .map(|x| x.abs())
        .chain(
            raw.vel
                .iter()
                .chain(raw.velocities.iter().flatten())
                .map(|x| (x * t).abs()),
        );
    let largest = lengths
        .filter(|x| x.is_finite())
        .fold(raw.buff.abs(), f64::max);
    if !(largest > 0.0 && largest.is_finite()) {
        return 0;
    }
    let e = largest.log2();
    if (-200.0..=200.0).contains(&e) {
        0
    } else {
        -(e.round() as i32)
    }
}

fn bounds(pts: &[Vect2]) -> (Vect2, Vect2) {
    let finite: Vec<&Vect2> = pts
        .iter()
        .filter(|p| p.x.is_finite() && p.y.is_finite())
        .collect();
    let Some(first) = finite.first() else {
        return (Vect2::new(-1.0, -1.0), Vect2::new(1.0, 1.0));
    };
    finite.iter().fold((**first, **first), |(lo, hi), q| {
        (
            Vect2::new(lo.x.min(q.x), lo.y.min(q.y)),
            Vect2::new(hi.x.max(q.x), hi.y.max(q.y)),
        )
    })
}

/// `back` turns a drawn length into the case's own (see [`picture`]).
fn inset(
    out: &mut String,
    raw: &RawCase,
    pe: &[Vect2],
    s_e: Vect2,
    v: Vect2,
    event: f64,
    back: &dyn Fn(f64) -> f64,
) {
    let (edge, q, dist) = nearest_edge(pe, s_e);
    let magnitude = pe
        .iter()
        .chain([&s_e])
        .fold(0f64, |a, p| a.max(p.x.abs()).max(p.y.abs()));
    // Below ~64 ulps of the coordinates, f64 cannot draw what is there.
    let resolution = 64.0 * f64::EPSILON * magnitude;
    let wanted = (10.0 * raw.buff).max(1.3 * dist);
    let half = wanted.max(resolution);
    let centre = if dist <= half {
        s_e + (q - s_e).scale(0.5)
    } else {
        s_e
    };
    let m = Map::fit(
        centre - Vect2::new(half, half),
        centre + Vect2::new(half, half),
        INSET,
        true,
    );
    let _ = writeln!(
        out,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#fbfbfb" stroke="#444"/>"##,
        INSET.x, INSET.y, INSET.w, INSET.h
    );
    out.push_str("<g clip-path=\"url(#inset)\">\n");
    let n = pe.len();
    let band = 2.0 * raw.buff * m.kx;
    let view = 1.5 * half; // the inset's box and a margin, for clipping
    for i in 0..n {
        let Some((a, b)) = clip(pe[i], pe[(i + 1) % n], centre, view) else {
            continue;
        };
        let (a, b) = (m.px(a), m.px(b));
        if band >= 0.5 {
            let _ = writeln!(
                out,
                r##"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="#f4a261" stroke-opacity="0.5" stroke-width="{band:.2}" stroke-linecap="round"/>"##,
                a.0, a.1, b.0, b.1
            );
        }
        let colour = if i == edge { "#e76f51" } else { "#2a9d8f" };
        let _ = writeln!(
            out,
            r##"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="{colour}" stroke-width="2"/>"##,
            a.0, a.1, b.0, b.1
        );
    }
    // The path through the inset.
    let (lo, hi) = (s_e.at(v, -event), s_e.at(v, raw.lookahead - event));
    if let Some((lo, hi)) = clip(lo, hi, centre, view) {
        path(out, &m, lo, hi);
    }
    dot(out, &m, s_e, "#e76f51");
    dot(out, &m, q, "#2a9d8f");
    out.push_str("</g>\n");
    scale_bar(out, &m, INSET, back);
    let mut y = INSET.y + INSET.h + 16.0;
    let mut line = |s: &str| {
        text(out, INSET.x, y, 11.0, "start", s);
        y += 15.0;
    };
    line(&format!("inset: the point at t = {}", num(event)));
    line(&format!(
        "and edge {edge}-{} (red), {} apart",
        (edge + 1) % n.max(1),
        num(back(dist))
    ));
    line(&format!(
        "BUFF = {} ({:.1} px)",
        num(back(raw.buff)),
        band / 2.0
    ));
    line(&format!("distance/BUFF = {}", num(dist / raw.buff)));
    if half > wanted {
        line("BUFF is below f64 resolution at this offset:");
        line(&format!("the inset shows {} across", num(back(2.0 * half))));
    }
}

fn legend(out: &mut String, raw: &RawCase, pic: &Picture, event: f64) {
    let (x, mut y) = (INSET.x, INSET.y + INSET.h + 100.0);
    let items: [(&str, &str); 5] = [
        (
            r##"<rect width="18" height="10" fill="#2a9d8f" fill-opacity="0.25" stroke="#2a9d8f"/>"##,
            "polygon at t = 0",
        ),
        (
            r##"<rect width="18" height="10" fill="#f4a261" fill-opacity="0.5"/>"##,
            "BUFF band (where visible)",
        ),
        (
            r##"<rect width="18" height="10" fill="#e76f51" fill-opacity="0.12" stroke="#e76f51" stroke-dasharray="4 2"/>"##,
            "polygon at the event time",
        ),
        (
            r##"<line x1="0" y1="5" x2="18" y2="5" stroke="#264653" stroke-width="1.5" marker-end="url(#arrow)"/>"##,
            "point's path over [0, T]",
        ),
        (
            r##"<circle cx="9" cy="5" r="4" fill="#e76f51"/>"##,
            "point at the event time",
        ),
    ];
    for (shape, label) in items {
        let _ = writeln!(
            out,
            r#"<g transform="translate({x} {:.1})">{shape}</g>"#,
            y - 9.0
        );
        text(out, x + 26.0, y, 12.0, "start", label);
        y += 17.0;
    }
    y += 8.0;
    let truth = match pic.truth {
        Some(true) => match pic.entry_time {
            // Beside an f64 enclosure, enough digits to compare with it.
            Some(e) if !pic.entry.is_empty() => format!("truth: enters at t = {e:.10e}"),
            Some(e) => format!("truth: enters at t = {}", num(e)),
            None => "truth: enters".into(),
        },
        Some(false) => "truth: misses".into(),
        None => "truth: undefined (the fill rule decides)".into(),
    };
    let mut lines = vec![
        (
            format!("engine ({}): {}", pic.engine_name, yes(pic.engine)),
            true,
        ),
        (format!("paper A exact: {}", yes(pic.paper)), true),
        (truth, true),
    ];
    lines.extend(pic.entry.iter().map(|l| (l.clone(), false)));
    lines.extend([
        (
            format!("T = {}, F = {}", num(raw.lookahead), num(raw.fac)),
            false,
        ),
        (format!("BUFF = {}", num(raw.buff)), false),
        (
            format!(
                "{} vertices; event at t = {}",
                raw.vertices.len(),
                num(event)
            ),
            false,
        ),
    ]);
    // Two more lines with an entry-time answer: closer together, to stay above the
    // heights panel.
    let step = if lines.len() > 6 { 16.0 } else { 18.0 };
    for (s, bold) in lines {
        let weight = if bold { "bold" } else { "normal" };
        let _ = writeln!(
            out,
            r#"<text x="{x}" y="{y:.1}" font-size="13" font-weight="{weight}" font-family="sans-serif">{}</text>"#,
            esc(&s)
        );
        y += step;
    }
}

/// The heights panel of a 3D case: the point's height, the slab's ends, the window
/// where the point is in the slab, the event time.
fn heights(out: &mut String, raw: &RawCase, event: f64, zname: &str) {
    let t = raw.lookahead;
    let (Some([bottom, top, vsp]), Some(&z0), Some(&vz)) =
        (raw.slab, raw.pos.get(2), raw.vel.get(2))
    else {
        return;
    };
    let z = |tk: f64| z0 + vz * tk;
    let (b, tp) = (|tk: f64| bottom + vsp * tk, |tk: f64| top + vsp * tk);
    let pts = [
        Vect2::new(0.0, z(0.0)),
        Vect2::new(t, z(t)),
        Vect2::new(0.0, b(0.0)),
        Vect2::new(t, b(t)),
        Vect2::new(0.0, tp(0.0)),
        Vect2::new(t, tp(t)),
    ];
    let (lo, hi) = bounds(&pts);
    let m = Map::fit(lo, hi, HEIGHTS, false);
    text(
        out,
        HEIGHTS.x,
        HEIGHTS.y - 14.0,
        14.0,
        "start",
        "heights against time (3D)",
    );
    axes(out, &m, HEIGHTS, "t", zname);
    // The point is in the slab where bottom(t) ≤ z(t) ≤ top(t): sampled for the shading.
    let inside: Vec<f64> = (0..=400)
        .map(|k| t * k as f64 / 400.0)
        .filter(|&tk| b(tk) <= z(tk) && z(tk) <= tp(tk))
        .collect();
    if let (Some(&w0), Some(&w1)) = (inside.first(), inside.last()) {
        let (x0, _) = m.px(Vect2::new(w0, m.c.y));
        let (x1, _) = m.px(Vect2::new(w1, m.c.y));
        let _ = writeln!(
            out,
            r##"<rect x="{x0:.1}" y="{}" width="{:.1}" height="{}" fill="#e9c46a" fill-opacity="0.35"/>"##,
            HEIGHTS.y,
            (x1 - x0).max(1.0),
            HEIGHTS.h
        );
    }
    let slab = [
        Vect2::new(0.0, b(0.0)),
        Vect2::new(t, b(t)),
        Vect2::new(t, tp(t)),
        Vect2::new(0.0, tp(0.0)),
    ];
    let _ = writeln!(
        out,
        r##"<path d="{}" fill="#2a9d8f" fill-opacity="0.2" stroke="#2a9d8f"/>"##,
        path_d(&m, &slab, true)
    );
    path(out, &m, Vect2::new(0.0, z(0.0)), Vect2::new(t, z(t)));
    let (ex, _) = m.px(Vect2::new(event, m.c.y));
    let _ = writeln!(
        out,
        r##"<line x1="{ex:.1}" y1="{}" x2="{ex:.1}" y2="{}" stroke="#e76f51" stroke-dasharray="5 3"/>"##,
        HEIGHTS.y,
        HEIGHTS.y + HEIGHTS.h
    );
    text(
        out,
        HEIGHTS.x + HEIGHTS.w,
        HEIGHTS.y - 14.0,
        11.0,
        "end",
        "slab (green), point's height (arrow), point in the slab (yellow), event (red)",
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dot's label stays inside the main panel's frame (which clips it) wherever the dot
    /// is: at a corner, on an edge, in the middle; below the dot when asked and it fits.
    #[test]
    fn dot_labels_stay_inside_the_frame() {
        let f = MAIN;
        let inside = |at: (f64, f64), label: &str, below: bool| {
            let (x, y, anchor) = label_place(f, at, label, below);
            let width = 0.62 * LABEL_SIZE * label.chars().count() as f64;
            let (left, right) = match anchor {
                "start" => (x, x + width),
                _ => (x - width, x),
            };
            assert!(
                left >= f.x && right <= f.x + f.w && y - LABEL_SIZE >= f.y && y <= f.y + f.h,
                "{label:?} at {at:?}: x {left}..{right}, baseline {y}"
            );
            (x, y)
        };
        for at in [
            (f.x, f.y),
            (f.x + f.w, f.y),
            (f.x, f.y + f.h),
            (f.x + f.w, f.y + f.h),
            (f.x + f.w - 20.0, f.y + 200.0),
            (f.x + 200.0, f.y + 2.0),
            (f.x + 200.0, f.y + 200.0),
        ] {
            for label in ["t = T", "t = 0", "t = 1.000e-5", "t = 41638.6363"] {
                inside(at, label, false);
                inside(at, label, true);
            }
        }
        let mid = (f.x + 200.0, f.y + 200.0);
        assert!(inside(mid, "t = T", true).1 > mid.1, "below when asked");
        assert!(inside(mid, "t = T", false).1 < mid.1, "above by default");
    }

    /// The distance the inset reports is right at both ends of the float range: a
    /// point 3 units from an edge 8 long, moved whole by 2^±1000 (exactly), is 3·2^±1000
    /// from it, the nearest point in the middle of the edge's span.
    #[test]
    fn the_inset_distance_holds_at_every_scale() {
        for e in [-1000, 0, 1000] {
            let k = |x: f64| x * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
            let (a, b, s) = (
                Vect2::new(k(-4.0), k(1.0)),
                Vect2::new(k(4.0), k(1.0)),
                Vect2::new(k(2.0), k(4.0)),
            );
            let (q, d) = nearest_on(a, b, s);
            assert_eq!(d, k(3.0), "at 2^{e}");
            assert_eq!(q, Vect2::new(k(2.0), k(1.0)), "at 2^{e}");
        }
    }

    fn square(offset: f64, size: f64, buff: f64) -> RawCase {
        RawCase {
            lookahead: 10.0,
            buff,
            fac: 1e-4,
            pos: vec![offset - 3.0 * size, offset + size],
            vel: vec![size, 0.0],
            vertices: vec![
                [offset, offset],
                [offset + 2.0 * size, offset],
                [offset + 2.0 * size, offset + 2.0 * size],
                [offset, offset + 2.0 * size],
            ],
            velocities: vec![[0.5 * size, 0.0]; 4],
            slab: None,
        }
    }

    fn pic(title: &str) -> Picture<'_> {
        Picture {
            title,
            engine: false,
            engine_name: "f64",
            paper: true,
            truth: Some(true),
            entry_time: Some(3.0),
            entry: vec!["entry (f64): enters".into(), "in [2.9, 3.1]".into()],
        }
    }

    /// Every number in an attribute of the document, with the attribute's name.
    fn attributes(svg: &str) -> Vec<(String, f64)> {
        let mut out = Vec::new();
        for part in svg.split([' ', '<', '>']) {
            let Some((name, value)) = part.split_once("=\"") else {
                continue;
            };
            let value = value.trim_end_matches(['"', '/']);
            for tok in
                value.split(|c: char| c == ' ' || c == ',' || c.is_ascii_alphabetic() && c != 'e')
            {
                if let Ok(x) = tok.parse::<f64>() {
                    out.push((name.to_string(), x));
                }
            }
        }
        out
    }

    #[test]
    fn a_picture_says_the_verdicts_and_has_its_parts() {
        let svg = picture(&square(0.0, 1.0, 0.1), &pic("a <test> & more"));
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("a &lt;test&gt; &amp; more"));
        assert!(!svg.contains("<test>"));
        for s in [
            "engine (f64): no",
            "paper A exact: yes",
            "truth: enters at t = 3",
        ] {
            assert!(svg.contains(s), "{s}");
        }
        assert!(
            svg.contains("marker-end=\"url(#arrow)\""),
            "the path shows its direction"
        );
        assert!(svg.contains("clip-path=\"url(#inset)\""), "an inset");
        assert!(
            !svg.contains("heights against time"),
            "2D: no heights panel"
        );
    }

    /// A case at an end of the float range (a subnormal BUFF, or lengths near 2¹⁰⁰⁰) is
    /// drawn as the same case at unit scale: the polygons, the path and the points land
    /// on the same pixels as at scale 1 (the moves are exact for this case; the axes'
    /// ticks differ, being round numbers), the axes say the power of two, and the
    /// numbers written out are the case's own. Before, a subnormal case's map overflowed
    /// and the main panel was empty.
    #[test]
    fn a_case_at_an_end_of_the_float_range_is_drawn() {
        let case = square(0.0, 1.0, 0.25);
        let picture_of = |raw: &RawCase| picture(raw, &pic("ends"));
        let shapes = |svg: &str| -> Vec<String> {
            svg.lines()
                .filter(|l| l.starts_with("<path d=") || l.starts_with("<circle"))
                .map(String::from)
                .collect()
        };
        let unit = picture_of(&case);
        assert!(unit.contains(">x</text>"), "unit scale: plain axes");
        for e in [-1062, -1040, 1000] {
            let moved = case.times_pow2(e);
            let svg = picture_of(&moved);
            assert_eq!(shapes(&svg), shapes(&unit), "at 2^{e}");
            let j = drawing_scale(&moved);
            assert!(
                svg.contains(&format!("x · 2^{j}")),
                "at 2^{e}: axes name the scale"
            );
            assert!((j + e).abs() <= 4, "at 2^{e}: drawn at 2^{j}");
            assert!(
                svg.contains(&format!("BUFF = {}", num(moved.buff))),
                "at 2^{e}: BUFF in the case's own units"
            );
            for (name, x) in attributes(&svg) {
                assert!(x.is_finite() && x.abs() <= 1e5, "at 2^{e}: {name} = {x}");
            }
        }
    }

    #[test]
    fn far_offsets_and_tiny_polygons_give_sensible_pixels() {
        let raw = square(1e9, 1e-3, 1e-15);
        // the point (1e9 − 3e-3 + 1e-3·t) meets the edge (1e9 + 0.5e-3·t) at t = 6
        let svg = picture(
            &raw,
            &Picture {
                entry_time: Some(6.0),
                ..pic("far")
            },
        );
        for (name, x) in attributes(&svg) {
            assert!(x.abs() <= 1e5, "{name} = {x}");
            if name == "font-size" {
                assert!(x >= 8.0, "font-size {x}");
            }
        }
        assert!(
            svg.contains("below f64 resolution"),
            "says BUFF cannot be drawn"
        );
        assert!(svg.contains("x − "), "ticks relative to a stated origin");
    }

    #[test]
    fn a_3d_case_has_its_heights_panel() {
        let mut raw = square(0.0, 1.0, 0.1);
        raw.pos.push(-1.0);
        raw.vel.push(0.5);
        raw.slab = Some([0.0, 2.0, 0.0]);
        let svg = picture(&raw, &pic("3d"));
        assert!(svg.contains("heights against time"));
        assert!(svg.contains("#e9c46a"), "the window in the slab is shaded");
    }

    #[test]
    fn degenerate_cases_still_draw() {
        let mut raw = square(0.0, 1.0, 0.1);
        raw.vel = vec![0.0, 0.0];
        raw.velocities = vec![[0.0, 0.0]; 4];
        let svg = picture(
            &raw,
            &Picture {
                truth: None,
                entry_time: None,
                ..pic("still")
            },
        );
        assert!(svg.contains("truth: undefined"));
        assert!(svg.trim_end().ends_with("</svg>"));
    }
}
