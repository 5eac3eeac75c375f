//! The picture of a band answer, drawn as a pilot reads a compass rose (the bands of
//! `polyguard::bands` over paper A §II–§III's motion): north up, the point and its
//! velocity, the polygons now and at the end of the lookahead, each polygon's certified
//! offset by D, the course bands as a ring of coloured wedges at the distance the point
//! covers in T, and the recovery point when there is one.
//!
//! Every coordinate is a pixel computed here: world coordinates are taken relative to the
//! point first (in f64), then scaled, so large coordinates still draw sensibly.

use std::fmt::Write as _;

use polyguard::bands::{BandKind, Bands};
use polyguard::offset::Offset;
use polyguard::vect2::Vect2;

/// What the compass picture shows (world coordinates in the case's length unit).
#[derive(Clone, Debug)]
pub struct Compass<'a> {
    /// The title, e.g. the case id.
    pub title: &'a str,
    /// The point at t = 0.
    pub s: Vect2,
    /// Its current velocity.
    pub v: Vect2,
    /// The lookahead T.
    pub t: f64,
    /// The separation D.
    pub sep: f64,
    /// Each polygon at t = 0 and at t = T.
    pub polygons: &'a [(Vec<Vect2>, Vec<Vect2>)],
    /// The certified offsets by D of the polygons at t = 0 (those that could be made).
    pub offsets: &'a [Offset],
    /// The course bands at the current speed.
    pub bands: &'a Bands,
    /// The recovery point at t = 0, when the point is within D of a polygon.
    pub recovery: Option<Vect2>,
    /// The units, for the legend (e.g. "nm, h").
    pub units: &'a str,
}

/// The canvas: width, height, and the map square.
const W: f64 = 760.0;
const H: f64 = 900.0;
const MAP: (f64, f64, f64) = (40.0, 70.0, 680.0);

/// The band colours: clear, conflict, unknown.
const CLEAR: &str = "#2e9d46";
const CONFLICT: &str = "#d7301f";
const UNKNOWN: &str = "#f0a020";

/// How thick the ring of wedges is, as a share of its radius.
const RING: f64 = 0.16;

/// The colour of a band kind.
fn colour(kind: BandKind) -> &'static str {
    match kind {
        BandKind::Clear => CLEAR,
        BandKind::Conflict => CONFLICT,
        BandKind::Unknown => UNKNOWN,
    }
}

/// World to pixels: the point s at the map's centre, north up, `k` pixels per unit.
struct Map {
    s: Vect2,
    k: f64,
    cx: f64,
    cy: f64,
}

impl Map {
    /// The pixel of a world point.
    fn px(&self, p: Vect2) -> (f64, f64) {
        (
            self.cx + (p.x - self.s.x) * self.k,
            self.cy - (p.y - self.s.y) * self.k,
        )
    }

    /// The pixel at course θ (clockwise from north), `r` pixels from the centre.
    fn polar(&self, theta: f64, r: f64) -> (f64, f64) {
        (self.cx + r * theta.sin(), self.cy - r * theta.cos())
    }
}

/// An SVG path through the points, closed.
fn ring_path(m: &Map, pts: &[Vect2]) -> String {
    let mut d = String::new();
    for (i, &p) in pts.iter().enumerate() {
        let (x, y) = m.px(p);
        let _ = write!(d, "{}{x:.2},{y:.2} ", if i == 0 { "M" } else { "L" });
    }
    d.push('Z');
    d
}

/// Escapes text for SVG.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A short number for the legend.
fn short(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The wedge of courses [lo, hi] between radii `r0` < `r1` (pixels), as a path; a band
/// wider than half a turn is drawn as two wedges so that every arc is under π.
fn wedge(m: &Map, lo: f64, hi: f64, r0: f64, r1: f64) -> String {
    if hi - lo > core::f64::consts::PI {
        let mid = lo + (hi - lo) / 2.0;
        return format!(
            "{} {}",
            wedge(m, lo, mid, r0, r1),
            wedge(m, mid, hi, r0, r1)
        );
    }
    let (a, b) = (m.polar(lo, r1), m.polar(hi, r1));
    let (c, d) = (m.polar(hi, r0), m.polar(lo, r0));
    format!(
        "M{:.2},{:.2} A{r1:.2},{r1:.2} 0 0 1 {:.2},{:.2} L{:.2},{:.2} A{r0:.2},{r0:.2} 0 0 0 {:.2},{:.2} Z",
        a.0, a.1, b.0, b.1, c.0, c.1, d.0, d.1
    )
}

/// The pixels per world unit: the reach circle (speed·T + D around s) and every polygon
/// at t = 0 fit the map, the polygons' far parts capped at three reaches.
fn scale(c: &Compass) -> f64 {
    let reach = (c.v.sq().sqrt() * c.t + c.sep).max(f64::MIN_POSITIVE);
    let mut half = reach;
    for (p0, _) in c.polygons {
        for q in p0 {
            let d = (q.x - c.s.x).abs().max((q.y - c.s.y).abs());
            half = half.max(d.min(3.0 * reach));
        }
    }
    (MAP.2 / 2.0 - 10.0) / (half * 1.08)
}

/// Draws the polygons (now filled, at T dashed) and their offsets (dotted).
fn polygons(out: &mut String, m: &Map, c: &Compass) {
    for off in c.offsets {
        for region in &off.regions {
            let mut d = ring_path(m, &region.outer);
            for hole in &region.holes {
                d.push(' ');
                d.push_str(&ring_path(m, hole));
            }
            let _ = writeln!(
                out,
                r##"<path d="{d}" fill="#9ab" fill-opacity="0.12" stroke="#456" stroke-width="1.2" stroke-dasharray="2 3" fill-rule="evenodd"/>"##
            );
        }
    }
    for (p0, pt) in c.polygons {
        let _ = writeln!(
            out,
            r##"<path d="{}" fill="none" stroke="#678" stroke-width="1" stroke-dasharray="6 4"/>"##,
            ring_path(m, pt)
        );
        let _ = writeln!(
            out,
            r##"<path d="{}" fill="#5a6f86" fill-opacity="0.55" stroke="#2d3a48" stroke-width="1.5"/>"##,
            ring_path(m, p0)
        );
    }
}

/// Tints each band's sector from the point out to the ring, faintly, so that a clear
/// lane reads as a way between the polygons.
fn lanes(out: &mut String, m: &Map, c: &Compass, r: f64) {
    let r0 = r * (1.0 - RING);
    for b in &c.bands.bands {
        let _ = writeln!(
            out,
            r##"<path d="{}" fill="{}" fill-opacity="0.10" stroke="none"/>"##,
            wedge(m, b.lo, b.hi, 0.0, r0),
            colour(b.kind)
        );
    }
}

/// Draws the ring of course bands at the reach radius, with degree ticks.
fn rose(out: &mut String, m: &Map, c: &Compass, r: f64) {
    let r0 = r * (1.0 - RING);
    let _ = writeln!(
        out,
        r##"<circle cx="{:.2}" cy="{:.2}" r="{r0:.2}" fill="none" stroke="#bbb" stroke-width="0.8"/>"##,
        m.cx, m.cy
    );
    for b in &c.bands.bands {
        let _ = writeln!(
            out,
            r##"<path d="{}" fill="{}" fill-opacity="0.85" stroke="none"/>"##,
            wedge(m, b.lo, b.hi, r0, r),
            colour(b.kind)
        );
    }
    for deg in (0..360).step_by(10) {
        let th = (deg as f64).to_radians();
        let long = deg % 30 == 0;
        let (a, b) = (
            m.polar(th, r),
            m.polar(th, r + if long { 10.0 } else { 5.0 }),
        );
        let _ = writeln!(
            out,
            r##"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="#333" stroke-width="1"/>"##,
            a.0, a.1, b.0, b.1
        );
        if long {
            let (x, y) = m.polar(th, r + 22.0);
            let label = match deg {
                0 => "N".to_string(),
                90 => "E".to_string(),
                180 => "S".to_string(),
                270 => "W".to_string(),
                _ => format!("{deg:03}"),
            };
            let _ = writeln!(
                out,
                r##"<text x="{x:.2}" y="{:.2}" font-size="13" text-anchor="middle" font-family="sans-serif">{label}</text>"##,
                y + 4.5
            );
        }
    }
}

/// Draws the point, its velocity over T, and the recovery point.
fn point(out: &mut String, m: &Map, c: &Compass) {
    let (sx, sy) = m.px(c.s);
    let end = m.px(Vect2::new(c.s.x + c.v.x * c.t, c.s.y + c.v.y * c.t));
    let _ = writeln!(
        out,
        r##"<line x1="{sx:.2}" y1="{sy:.2}" x2="{:.2}" y2="{:.2}" stroke="#111" stroke-width="2.5" marker-end="url(#arrow)"/>"##,
        end.0, end.1
    );
    let _ = writeln!(
        out,
        r##"<circle cx="{sx:.2}" cy="{sy:.2}" r="5" fill="#111"/>"##
    );
    if let Some(x) = c.recovery {
        let (rx, ry) = m.px(x);
        let _ = writeln!(
            out,
            r##"<line x1="{sx:.2}" y1="{sy:.2}" x2="{rx:.2}" y2="{ry:.2}" stroke="#7b2cbf" stroke-width="1.5" stroke-dasharray="4 3"/>"##
        );
        let _ = writeln!(
            out,
            r##"<circle cx="{rx:.2}" cy="{ry:.2}" r="5" fill="none" stroke="#7b2cbf" stroke-width="2.5"/>"##
        );
    }
}

/// Draws the legend below the map.
fn legend(out: &mut String, c: &Compass) {
    let y = MAP.1 + MAP.2 + 30.0;
    let items = [
        (CLEAR, "clear: no course in it loses separation"),
        (CONFLICT, "conflict: every course in it loses separation"),
        (UNKNOWN, "unknown: not settled in f64"),
    ];
    for (i, (col, text)) in items.iter().enumerate() {
        let yy = y + 20.0 * i as f64;
        let _ = writeln!(
            out,
            r##"<rect x="50" y="{:.1}" width="14" height="14" fill="{col}"/><text x="72" y="{:.1}" font-size="13" font-family="sans-serif">{text}</text>"##,
            yy - 11.0,
            yy
        );
    }
    let speed = c.v.sq().sqrt();
    let lines = [
        format!(
            "D = {}, T = {}, speed = {} ({}); ring at speed·T",
            short(c.sep),
            short(c.t),
            short(speed),
            esc(c.units)
        ),
        format!(
            "unknown total {:.4}°; filled: polygons now, dashed: at T, dotted: offset by D",
            c.bands.unknown_total.to_degrees()
        ),
        if c.recovery.is_some() {
            "purple ring: the nearest point at distance ≥ D from the polygons".to_string()
        } else {
            "the point is at least D from every polygon now".to_string()
        },
    ];
    for (i, line) in lines.iter().enumerate() {
        let _ = writeln!(
            out,
            r##"<text x="50" y="{:.1}" font-size="13" font-family="sans-serif">{}</text>"##,
            y + 70.0 + 19.0 * i as f64,
            line
        );
    }
}

/// The SVG of a compass picture.
pub fn compass_svg(c: &Compass) -> String {
    let k = scale(c);
    let m = Map {
        s: c.s,
        k,
        cx: MAP.0 + MAP.2 / 2.0,
        cy: MAP.1 + MAP.2 / 2.0,
    };
    let mut out = String::new();
    let _ = writeln!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}">"##
    );
    out.push_str(
        r##"<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="#111"/></marker>"##,
    );
    let _ = writeln!(
        out,
        r##"<clipPath id="map"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath></defs>"##,
        MAP.0, MAP.1, MAP.2, MAP.2
    );
    let _ = writeln!(out, r##"<rect width="{W}" height="{H}" fill="white"/>"##);
    let _ = writeln!(
        out,
        r##"<text x="{}" y="40" font-size="18" text-anchor="middle" font-family="sans-serif">{}</text>"##,
        W / 2.0,
        esc(c.title)
    );
    let reach = (c.v.sq().sqrt() * c.t * k).max(60.0);
    lanes(&mut out, &m, c, reach);
    rose(&mut out, &m, c, reach);
    out.push_str(r##"<g clip-path="url(#map)">"##);
    polygons(&mut out, &m, c);
    out.push_str("</g>\n");
    point(&mut out, &m, c);
    legend(&mut out, c);
    out.push_str("</svg>\n");
    out
}

/// What the offset picture shows: P, its certified offset (or inset), and for an offset
/// a bisector expansion beside it with the points of the true buffer it leaves out.
#[derive(Clone, Debug)]
pub struct OffsetPicture<'a> {
    /// The title, e.g. the case id.
    pub title: &'a str,
    /// The polygon P (at the case's time).
    pub p: &'a [Vect2],
    /// D.
    pub d: f64,
    /// The certified result.
    pub offset: &'a Offset,
    /// An inset rather than an offset.
    pub inset: bool,
    /// A PolyCARP-style bisector expansion of P by D, for comparison.
    pub bisector: Option<&'a [Vect2]>,
    /// Points at distance D from P that the bisector expansion leaves outside.
    pub missed: &'a [Vect2],
}

/// The SVG of an offset picture: north up, one scale, P filled, the certified result
/// outlined in blue, the bisector expansion dashed orange, its missed points red.
pub fn offset_svg(o: &OffsetPicture) -> String {
    let mut pts: Vec<Vect2> = o.p.to_vec();
    for r in &o.offset.regions {
        pts.extend(&r.outer);
    }
    if let Some(b) = o.bisector {
        pts.extend(b);
    }
    let (mut lo, mut hi) = (pts[0], pts[0]);
    for q in &pts {
        lo = Vect2::new(lo.x.min(q.x), lo.y.min(q.y));
        hi = Vect2::new(hi.x.max(q.x), hi.y.max(q.y));
    }
    let half = ((hi.x - lo.x).max(hi.y - lo.y) / 2.0).max(f64::MIN_POSITIVE);
    let k = (MAP.2 / 2.0 - 10.0) / (half * 1.05);
    // The map is as tall as the drawing needs (a wide polygon leaves no blank band).
    let map_h = ((hi.y - lo.y) * 1.05 * k + 20.0).clamp(MAP.2 / 3.0, MAP.2);
    let m = Map {
        s: Vect2::new((lo.x + hi.x) / 2.0, (lo.y + hi.y) / 2.0),
        k,
        cx: MAP.0 + MAP.2 / 2.0,
        cy: MAP.1 + map_h / 2.0,
    };
    let legend_y = MAP.1 + map_h + 30.0;
    let height = legend_y + 3.0 * 19.0 + 20.0;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{height:.0}" viewBox="0 0 {W} {height:.0}">"##
    );
    let _ = writeln!(
        out,
        r##"<rect width="{W}" height="{height:.0}" fill="white"/>"##
    );
    let _ = writeln!(
        out,
        r##"<text x="{}" y="40" font-size="18" text-anchor="middle" font-family="sans-serif">{}</text>"##,
        W / 2.0,
        esc(o.title)
    );
    for r in &o.offset.regions {
        let mut d = ring_path(&m, &r.outer);
        for h in &r.holes {
            d.push(' ');
            d.push_str(&ring_path(&m, h));
        }
        let _ = writeln!(
            out,
            r##"<path d="{d}" fill="#4a7fc1" fill-opacity="0.15" stroke="#1f4e8c" stroke-width="1.5" fill-rule="evenodd"/>"##
        );
    }
    let _ = writeln!(
        out,
        r##"<path d="{}" fill="#5a6f86" fill-opacity="0.6" stroke="#2d3a48" stroke-width="1.5"/>"##,
        ring_path(&m, o.p)
    );
    if let Some(b) = o.bisector {
        let _ = writeln!(
            out,
            r##"<path d="{}" fill="none" stroke="#e07b00" stroke-width="2" stroke-dasharray="7 4"/>"##,
            ring_path(&m, b)
        );
    }
    for &q in o.missed {
        let (x, y) = m.px(q);
        let _ = writeln!(
            out,
            r##"<circle cx="{x:.2}" cy="{y:.2}" r="2.5" fill="{CONFLICT}"/>"##
        );
    }
    let y = legend_y;
    let what = if o.inset { "inset" } else { "offset" };
    let mut lines = vec![format!(
        "filled: P; blue: the certified {what} by D = {}",
        short(o.d)
    )];
    if o.bisector.is_some() {
        lines.push("dashed orange: a PolyCARP-style bisector expansion by D".to_string());
        lines.push(format!(
            "red: {} sampled points within D of P that the bisector expansion leaves out",
            o.missed.len()
        ));
    }
    for (i, line) in lines.iter().enumerate() {
        let _ = writeln!(
            out,
            r##"<text x="50" y="{:.1}" font-size="13" font-family="sans-serif">{}</text>"##,
            y + 19.0 * i as f64,
            line
        );
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use polyguard::bands::Band;

    fn square(cx: f64, cy: f64, h: f64) -> Vec<Vect2> {
        vec![
            Vect2::new(cx - h, cy - h),
            Vect2::new(cx + h, cy - h),
            Vect2::new(cx + h, cy + h),
            Vect2::new(cx - h, cy + h),
        ]
    }

    /// The wedges of the bands are drawn in their colours, a band over half a turn as
    /// two arcs, and the ring's ticks carry the cardinal letters.
    #[test]
    fn draws_each_band_in_its_colour() {
        let tau = core::f64::consts::TAU;
        let bands = Bands {
            bands: vec![
                Band {
                    lo: 0.0,
                    hi: 0.5,
                    kind: BandKind::Conflict,
                },
                Band {
                    lo: 0.5,
                    hi: 0.52,
                    kind: BandKind::Unknown,
                },
                Band {
                    lo: 0.52,
                    hi: tau,
                    kind: BandKind::Clear,
                },
            ],
            unknown_total: 0.02,
            met: true,
        };
        let cell = square(0.0, 10.0, 2.0);
        let polys = vec![(cell.clone(), cell)];
        let c = Compass {
            title: "a <cell> ahead",
            s: Vect2::new(0.0, 0.0),
            v: Vect2::new(0.0, 40.0),
            t: 0.25,
            sep: 1.0,
            polygons: &polys,
            offsets: &[],
            bands: &bands,
            recovery: None,
            units: "nm, h",
        };
        let svg = compass_svg(&c);
        for col in [CLEAR, CONFLICT, UNKNOWN] {
            assert!(svg.contains(&format!("fill=\"{col}\"")), "{col} missing");
        }
        // The clear band spans more than half a turn: two arcs in one path.
        let clear_path = svg
            .lines()
            .find(|l| l.contains(&format!("fill=\"{CLEAR}\" fill-opacity=\"0.85\"")))
            .unwrap_or("");
        assert_eq!(clear_path.matches(" A").count(), 4, "{clear_path}");
        assert!(svg.contains(">N<") && svg.contains(">E<") && svg.contains(">030<"));
        assert!(svg.contains("a &lt;cell&gt; ahead"));
        assert!(!svg.contains("NaN"));
    }

    /// North is up: a course of 0 points to smaller pixel y, 90° to larger pixel x.
    #[test]
    fn north_is_up_and_east_is_right() {
        let m = Map {
            s: Vect2::new(5.0, 5.0),
            k: 2.0,
            cx: 100.0,
            cy: 100.0,
        };
        let n = m.polar(0.0, 10.0);
        let e = m.polar(core::f64::consts::FRAC_PI_2, 10.0);
        assert!(n.1 < 100.0 && (n.0 - 100.0).abs() < 1e-9);
        assert!(e.0 > 100.0 && (e.1 - 100.0).abs() < 1e-9);
        let p = m.px(Vect2::new(6.0, 6.0));
        assert!(p.0 > 100.0 && p.1 < 100.0);
    }
}
