//! One picture per counterexample: the polygon at t = 0 with its BUFF band, the polygon
//! at the event time, the trajectory over [0, T], and the times.

use crate::case::RawCase;
use polyguard::vect2::Vect2;

fn poly_at(raw: &RawCase, t: f64) -> Vec<Vect2> {
    raw.vertices
        .iter()
        .zip(&raw.velocities)
        .map(|(&p, &v)| Vect2::from(p).at(Vect2::from(v), t))
        .collect()
}

fn path(points: &[Vect2]) -> String {
    let mut d = String::new();
    for (k, p) in points.iter().enumerate() {
        d.push_str(&format!(
            "{}{} {} ",
            if k == 0 { "M" } else { "L" },
            p.x,
            -p.y
        ));
    }
    d.push('Z');
    d
}

/// The SVG document for a case; `event` is the time of interest (entry time, or T).
pub fn picture(raw: &RawCase, event: f64, title: &str) -> String {
    let t = raw.lookahead;
    let p0 = poly_at(raw, 0.0);
    let pe = poly_at(raw, event);
    let s = Vect2::new(raw.pos[0], raw.pos[1]);
    let v = Vect2::new(raw.vel[0], raw.vel[1]);
    let (s_e, s_t) = (s.at(v, event), s.at(v, t));
    let all: Vec<Vect2> = p0.iter().chain(&pe).copied().chain([s, s_t]).collect();
    let (mut lo, mut hi) = (all[0], all[0]);
    for q in &all {
        lo = Vect2::new(lo.x.min(q.x), lo.y.min(q.y));
        hi = Vect2::new(hi.x.max(q.x), hi.y.max(q.y));
    }
    let span = (hi.x - lo.x).max(hi.y - lo.y).max(raw.buff * 8.0);
    let m = 0.08 * span;
    let (x0, y0, w, h) = (
        lo.x - m,
        -hi.y - m,
        hi.x - lo.x + 2.0 * m,
        hi.y - lo.y + 2.0 * m,
    );
    let sw = span / 400.0;
    let esc = |s: &str| {
        s.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="{x0} {y0} {w} {h}" width="640" height="640">
<title>{title}</title>
<path d="{band}" fill="none" stroke="#f4a261" stroke-opacity="0.45" stroke-width="{bw}" stroke-linejoin="round"/>
<path d="{band}" fill="#2a9d8f" fill-opacity="0.25" stroke="#2a9d8f" stroke-width="{sw}"/>
<path d="{ev}" fill="#e76f51" fill-opacity="0.15" stroke="#e76f51" stroke-width="{sw}" stroke-dasharray="{dash}"/>
<line x1="{sx}" y1="{sy}" x2="{tx}" y2="{ty}" stroke="#264653" stroke-width="{sw}"/>
<circle cx="{sx}" cy="{sy}" r="{r}" fill="#264653"/>
<circle cx="{ex}" cy="{ey}" r="{r}" fill="#e76f51"/>
<text x="{x0}" y="{ty0}" font-size="{fs}" font-family="monospace">{text}</text>
</svg>
"##,
        band = path(&p0),
        ev = path(&pe),
        bw = 2.0 * raw.buff,
        dash = 4.0 * sw,
        sx = s.x,
        sy = -s.y,
        tx = s_t.x,
        ty = -s_t.y,
        ex = s_e.x,
        ey = -s_e.y,
        r = 3.0 * sw,
        ty0 = y0 + 0.04 * h,
        fs = 0.03 * h,
        text = esc(&format!(
            "{title}  t=0 (green, BUFF band orange), t={event} (red), T={t}"
        )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn picture_is_an_svg_with_the_shapes() {
        let raw = RawCase {
            lookahead: 10.0,
            buff: 0.1,
            fac: 1e-4,
            pos: vec![-3.0, 1.0],
            vel: vec![1.0, 0.0],
            vertices: vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            velocities: vec![[0.5, 0.0]; 4],
            slab: None,
        };
        let svg = picture(&raw, 3.0, "a <test>");
        assert!(svg.starts_with("<svg"));
        assert_eq!(svg.matches("<path").count(), 3);
        assert!(svg.contains("a &lt;test&gt;"));
        // The event polygon is the square moved by 1.5 in x.
        assert!(svg.contains("M1.5 -0 L3.5 -0"), "{svg}");
    }
}
