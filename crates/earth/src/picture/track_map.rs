//! The map of an encounters picture on the Mercator plane (docs/moving-features.md, "The
//! model"): a mover's track (straight on the plane between fixes, its position there the
//! linear interpolation in time, as the planar model), and an area's rings (static, or a
//! keyframed area's vertices moving linearly between keyframes).

use super::frame::Frame;
use crate::geodesy::Geodesy;
use crate::moving::encounter::unwrap_near;
use crate::moving::model::{Area, Rings, Shape, Trajectory};
use std::fmt::Write as _;

/// A point on the Mercator plane, radians.
type P = [f64; 2];

/// A mover on the plane: its fixes' times and points (longitudes unwrapped each the
/// shorter way from the one before, so the track is drawn without a jump at ±180°), and
/// where its gaps are.
pub(super) struct Track {
    /// The fixes' times.
    pub t: Vec<f64>,
    /// The fixes on the plane.
    pub p: Vec<P>,
    /// The segments, as index ranges into the fixes (split where fixes are more than
    /// `max_gap_s` apart).
    pub segments: Vec<std::ops::Range<usize>>,
}

/// `lon`, `lat` (degrees; longitude unwrapped) on the Mercator plane of `geo`.
fn project(geo: Geodesy, lon: f64, lat: f64) -> P {
    [lon.to_radians(), geo.mercator_y(lat.to_radians())]
}

impl Track {
    /// `traj` on the plane of `geo`, its first longitude taken the shorter way from
    /// `reference` (degrees), split into segments at gaps over `max_gap_s`.
    pub fn new(traj: &Trajectory, geo: Geodesy, max_gap_s: f64, reference: f64) -> Track {
        let mut t = Vec::with_capacity(traj.fixes.len());
        let mut p = Vec::with_capacity(traj.fixes.len());
        let mut segments = Vec::new();
        let mut lon = reference;
        for (i, f) in traj.fixes.iter().enumerate() {
            lon = unwrap_near(f.lon, lon);
            if i == 0 || f.t - traj.fixes[i - 1].t > max_gap_s {
                segments.push(i..i + 1);
            } else if let Some(s) = segments.last_mut() {
                s.end = i + 1;
            }
            t.push(f.t);
            p.push(project(geo, lon, f.lat));
        }
        Track { t, p, segments }
    }

    /// The points of the track over the times [a, b] (the ends interpolated), one
    /// polyline per segment that meets [a, b].
    pub fn stretch(&self, a: f64, b: f64) -> Vec<Vec<P>> {
        let mut out = Vec::new();
        for s in &self.segments {
            let (t0, t1) = (self.t[s.start], self.t[s.end - 1]);
            let (a, b) = (a.max(t0), b.min(t1));
            if a > b {
                continue;
            }
            let mut pts = vec![self.at(s.clone(), a)];
            let first = s.start + self.t[s.clone()].partition_point(|&t| t <= a);
            let last = s.start + self.t[s.clone()].partition_point(|&t| t < b);
            pts.extend_from_slice(&self.p[first..last.max(first)]);
            pts.push(self.at(s.clone(), b));
            out.push(pts);
        }
        out
    }

    /// The point at time `t` on segment `s` (its ends when `t` is outside it).
    fn at(&self, s: std::ops::Range<usize>, t: f64) -> P {
        let ts = &self.t[s.clone()];
        let k = ts.partition_point(|&u| u <= t);
        if k == 0 {
            return self.p[s.start];
        }
        if k >= ts.len() {
            return self.p[s.end - 1];
        }
        let (i, j) = (s.start + k - 1, s.start + k);
        let w = (t - self.t[i]) / (self.t[j] - self.t[i]);
        [
            self.p[i][0] + w * (self.p[j][0] - self.p[i][0]),
            self.p[i][1] + w * (self.p[j][1] - self.p[i][1]),
        ]
    }

    /// The point at time `t`, when a segment holds it.
    pub fn point(&self, t: f64) -> Option<P> {
        self.segments
            .iter()
            .find(|s| self.t[s.start] <= t && t <= self.t[s.end - 1])
            .map(|s| self.at(s.clone(), t))
    }

    /// The gaps: the last fix before and the first after each one.
    pub fn gaps(&self) -> Vec<[P; 2]> {
        self.segments
            .windows(2)
            .map(|w| [self.p[w[0].end - 1], self.p[w[1].start]])
            .collect()
    }
}

/// An area on the plane: its keyframes' times and rings (every part's outer ring and
/// holes in one list; a static area has one frame at time 0), each vertex unwrapped the
/// shorter way from the same vertex of the keyframe before (the first keyframe's from
/// the vertex before it, the first from `reference`).
pub(super) struct Outline {
    /// The keyframes: time and rings.
    pub frames: Vec<(f64, Vec<Vec<P>>)>,
    /// Whether the area is the same at every time.
    pub is_static: bool,
}

/// The rings of `parts`, unwrapped as [`Outline`] says.
fn rings(geo: Geodesy, parts: &[Rings], before: Option<&[Vec<P>]>, reference: f64) -> Vec<Vec<P>> {
    let all = parts
        .iter()
        .flat_map(|r| std::iter::once(&r.outer).chain(r.holes.iter()));
    all.enumerate()
        .map(|(k, ring)| {
            let mut lon = reference;
            ring.iter()
                .enumerate()
                .map(|(i, v)| {
                    let r = before
                        .and_then(|b| b.get(k))
                        .and_then(|b| b.get(i))
                        .map_or(lon, |q| q[0].to_degrees());
                    lon = unwrap_near(v[0], r);
                    project(geo, lon, v[1])
                })
                .collect()
        })
        .collect()
}

impl Outline {
    /// `area` on the plane of `geo`, unwrapped near `reference` (degrees).
    pub fn new(area: &Area, geo: Geodesy, reference: f64) -> Outline {
        match &area.shape {
            Shape::Static(parts) => Outline {
                frames: vec![(0.0, rings(geo, parts, None, reference))],
                is_static: true,
            },
            Shape::Keyframed(kf) => {
                let mut frames: Vec<(f64, Vec<Vec<P>>)> = Vec::with_capacity(kf.len());
                for k in kf {
                    let before = frames.last().map(|f| f.1.as_slice());
                    let r = rings(geo, &k.parts, before, reference);
                    frames.push((k.t, r));
                }
                Outline {
                    frames,
                    is_static: false,
                }
            }
        }
    }

    /// The rings at time `t`: each vertex interpolated linearly between the keyframes
    /// around `t`; `None` outside the area's existence.
    pub fn at(&self, t: f64) -> Option<Vec<Vec<P>>> {
        if self.is_static {
            return self.frames.first().map(|f| f.1.clone());
        }
        let k = self.frames.partition_point(|f| f.0 <= t);
        if k == 0 {
            return None;
        }
        let (t0, r0) = &self.frames[k - 1];
        if k == self.frames.len() {
            return (*t0 == t).then(|| r0.clone());
        }
        let (t1, r1) = &self.frames[k];
        let w = (t - t0) / (t1 - t0);
        Some(
            r0.iter()
                .zip(r1)
                .map(|(a, b)| {
                    a.iter()
                        .zip(b)
                        .map(|(p, q)| [p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])])
                        .collect()
                })
                .collect(),
        )
    }

    /// The box of every keyframe's vertices, `[x0, y0, x1, y1]`.
    pub fn bbox(&self) -> [f64; 4] {
        let pts = self.frames.iter().flat_map(|f| f.1.iter().flatten());
        bbox_of(pts)
    }
}

/// The box of `pts`, `[x0, y0, x1, y1]` (empty: inverted infinities).
pub(super) fn bbox_of<'a>(pts: impl Iterator<Item = &'a P>) -> [f64; 4] {
    pts.fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        },
    )
}

/// `rings` as one path (holes unfilled by the even-odd rule) in the SVG style `style`.
pub(super) fn rings_path(out: &mut String, f: &Frame, rings: &[Vec<P>], style: &str) {
    let d: String = rings.iter().map(|r| f.path(r, 0.0, true)).collect();
    let _ = writeln!(out, "<path d=\"{d}\" fill-rule=\"evenodd\" {style}/>");
}

/// `pts` as an open line in the SVG style `style`, with a tooltip `title`.
pub(super) fn line(out: &mut String, f: &Frame, pts: &[P], style: &str, title: &str) {
    if pts.len() < 2 {
        return;
    }
    let _ = writeln!(
        out,
        "<path d=\"{}\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\" \
         {style}><title>{}</title></path>",
        f.path(pts, 0.0, false),
        super::esc(title)
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::moving::model::{Fix, Keyframe};

    /// A fix at `t` s on the equator at `lon` degrees.
    fn fix(t: f64, lon: f64) -> Fix {
        Fix {
            t,
            lon,
            lat: 0.0,
            alt_ft: None,
        }
    }

    /// A square of side 1° whose west edge is at `lon`, on the equator.
    fn square(lon: f64) -> Vec<Rings> {
        vec![Rings {
            outer: vec![[lon, 0.0], [lon + 1.0, 0.0], [lon + 1.0, 1.0], [lon, 1.0]],
            holes: vec![],
        }]
    }

    /// A stretch starts and ends at the positions interpolated in time, holds the fixes
    /// between, and is cut at a gap into one line per segment.
    #[test]
    fn a_stretch_is_interpolated_and_cut_at_gaps() {
        let traj = Trajectory {
            id: "m".into(),
            callsign: None,
            fixes: vec![
                fix(0.0, 0.0),
                fix(10.0, 1.0),
                fix(20.0, 2.0),
                fix(200.0, 3.0),
                fix(210.0, 4.0),
            ],
        };
        let tr = Track::new(&traj, Geodesy::Sphere, 60.0, 0.0);
        assert_eq!(tr.segments, vec![0..3, 3..5]);
        let one = tr.stretch(5.0, 15.0);
        assert_eq!(one.len(), 1);
        let lons: Vec<f64> = one[0].iter().map(|p| p[0].to_degrees()).collect();
        assert_eq!(lons.len(), 3);
        for (got, want) in lons.iter().zip([0.5, 1.0, 1.5]) {
            assert!((got - want).abs() < 1e-12, "{lons:?}");
        }
        assert_eq!(
            tr.stretch(15.0, 205.0).len(),
            2,
            "one line each side of the gap"
        );
        assert!(tr.point(100.0).is_none(), "nowhere in a gap");
        assert_eq!(tr.gaps().len(), 1);
    }

    /// Across the antimeridian a track goes on eastward rather than jumping back.
    #[test]
    fn a_track_is_unwrapped_across_the_antimeridian() {
        let traj = Trajectory {
            id: "m".into(),
            callsign: None,
            fixes: vec![fix(0.0, 179.5), fix(10.0, -179.5)],
        };
        let tr = Track::new(&traj, Geodesy::Sphere, 60.0, 179.5);
        assert!((tr.p[1][0].to_degrees() - 180.5).abs() < 1e-9);
    }

    /// A keyframed area halfway between two keyframes is halfway between their
    /// vertices, and exists only from its first keyframe to its last.
    #[test]
    fn a_keyframed_outline_moves_linearly_between_keyframes() {
        let area = Area {
            id: "a".into(),
            name: None,
            shape: Shape::Keyframed(vec![
                Keyframe {
                    t: 0.0,
                    parts: square(0.0),
                },
                Keyframe {
                    t: 100.0,
                    parts: square(2.0),
                },
            ]),
            floor_ft: None,
            ceiling_ft: None,
        };
        let o = Outline::new(&area, Geodesy::Sphere, 0.0);
        let mid = o.at(50.0).expect("exists at 50 s");
        assert!((mid[0][0][0].to_degrees() - 1.0).abs() < 1e-12);
        assert!(o.at(-1.0).is_none() && o.at(101.0).is_none());
        assert!(o.at(100.0).is_some());
        let b = o.bbox();
        assert!((b[2].to_degrees() - 3.0).abs() < 1e-12, "{b:?}");
    }
}
