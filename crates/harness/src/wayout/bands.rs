//! The check of a band answer against the exact truth, for the `assure` hunt: values
//! drawn inside each Clear band must be exactly free of conflict, values drawn inside
//! each Conflict band must exactly lose separation (the engine's `bands` contract; the
//! oracle's `bands::conflict` decides each drawn value's f64 velocity exactly). And the
//! canary: a band builder that samples every `step` and paints between samples
//! without the certificate's margin, which the check must catch on a thin conflict.

use polyguard::bands::{
    conflict, velocity, Band, BandKind, Bands, Height, Obstacle, Slab, Traffic,
};
use polyguard::{Separation, Tri, Vect2};
use polyguard_oracle::bands as exact;
use polyguard_oracle::convert::f64_to_exact;
use polyguard_oracle::intervals::Separation as ExactSeparation;
use polyguard_oracle::{Q, V2};

/// One moving polygon of a band case, owned.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// The vertices at t = 0.
    pub p: Vec<Vect2>,
    /// Their velocities.
    pub vels: Vec<Vect2>,
    /// The slab (3D).
    pub slab: Option<Slab>,
}

/// A band case, owned: the engine's `bands::Traffic` without the borrows.
#[derive(Clone, Debug, PartialEq)]
pub struct BandCase {
    /// T.
    pub t: f64,
    /// The point at t = 0.
    pub s: Vect2,
    /// Its height and vertical speed (3D).
    pub height: Option<Height>,
    /// The moving polygons.
    pub polygons: Vec<Polygon>,
    /// D and H.
    pub sep: Separation,
}

/// Which parameter the bands vary, with the others fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Param {
    /// Courses at this speed.
    Course {
        /// The speed.
        speed: f64,
    },
    /// Speeds at this course.
    Speed {
        /// The course (radians clockwise from +y).
        course: f64,
    },
    /// Vertical speeds with this horizontal velocity.
    Vertical {
        /// The horizontal velocity.
        v: Vect2,
    },
}

impl Param {
    /// The f64 horizontal velocity and vertical speed of the value x (the engine's
    /// `bands::velocity` for courses and speeds).
    pub fn motion(self, x: f64, height: Option<Height>) -> (Vect2, Option<f64>) {
        let vz = height.map(|z| z.vz);
        match self {
            Param::Course { speed } => (velocity(speed, x), vz),
            Param::Speed { course } => (velocity(x, course), vz),
            Param::Vertical { v } => (v, Some(x)),
        }
    }
}

/// A value the exact truth contradicts (or cannot decide).
#[derive(Clone, Debug, PartialEq)]
pub struct Fault {
    /// The drawn value.
    pub value: f64,
    /// The band it was drawn from.
    pub band: Band,
    /// The exact truth: in conflict or not; `None` when the oracle found the case
    /// undefined (not counted as a contradiction by [`contradictions`]).
    pub conflict: Option<bool>,
}

/// The faults that are real contradictions (the exact truth decided against the band).
pub fn contradictions(faults: &[Fault]) -> usize {
    faults.iter().filter(|f| f.conflict.is_some()).count()
}

impl BandCase {
    /// Runs `f` on the engine's view of the case.
    pub fn with_traffic<R>(&self, f: impl FnOnce(&Traffic) -> R) -> R {
        let obstacles: Vec<Obstacle> = self
            .polygons
            .iter()
            .map(|o| Obstacle {
                p: &o.p,
                vels: &o.vels,
                slab: o.slab,
            })
            .collect();
        f(&Traffic {
            t: self.t,
            s: self.s,
            height: self.height,
            obstacles: &obstacles,
            sep: self.sep,
        })
    }

    /// The case in exact numbers, with the point's vertical speed `vz` (3D), or `None`
    /// for a number that is not finite.
    pub fn exact(&self, vz: Option<f64>) -> Option<exact::Traffic<Q>> {
        let q = |x: f64| f64_to_exact::<Q>(x);
        let pt = |a: Vect2| Some(V2::new(q(a.x)?, q(a.y)?));
        let height = match self.height {
            Some(z) => Some(exact::Height {
                sz: q(z.sz)?,
                vz: q(vz.unwrap_or(z.vz))?,
            }),
            None => None,
        };
        let mut obstacles = Vec::with_capacity(self.polygons.len());
        for o in &self.polygons {
            let slab = match o.slab {
                Some(z) => Some(exact::Slab {
                    bottom: q(z.bottom)?,
                    top: q(z.top)?,
                    vsp: q(z.vsp)?,
                }),
                None => None,
            };
            obstacles.push(exact::Obstacle {
                p: o.p.iter().map(|&a| pt(a)).collect::<Option<_>>()?,
                vels: o.vels.iter().map(|&a| pt(a)).collect::<Option<_>>()?,
                slab,
            });
        }
        Some(exact::Traffic {
            t: q(self.t)?,
            s: pt(self.s)?,
            height,
            obstacles,
            sep: ExactSeparation {
                d: q(self.sep.d)?,
                h: q(self.sep.h)?,
            },
        })
    }

    /// The exact truth at the value x of `param`: is its f64 velocity in conflict?
    /// `None` when the oracle finds the case undefined or a number is not finite.
    pub fn truth(&self, param: Param, x: f64) -> Option<bool> {
        let (v, vz) = param.motion(x, self.height);
        let traffic = self.exact(vz)?;
        let w = V2::new(f64_to_exact::<Q>(v.x)?, f64_to_exact::<Q>(v.y)?);
        exact::conflict(&traffic, &w).ok()
    }
}

/// The values drawn in a band: its ends, `draws` values evenly inside, and enough more
/// that consecutive values are at most `spacing` apart (`spacing` ≤ 0: no more).
pub fn draws_in(band: &Band, draws: usize, spacing: f64) -> Vec<f64> {
    let width = band.hi - band.lo;
    let grid = if spacing > 0.0 && width > 0.0 {
        ((width / spacing).ceil() as usize).min(1 << 16)
    } else {
        0
    };
    let n = draws.max(grid);
    let mut xs = vec![band.lo, band.hi];
    xs.extend((0..n).map(|k| band.lo + width * ((k as f64 + 0.5) / n as f64)));
    xs
}

/// Checks a band answer: every value drawn in a Clear band must be exactly free of
/// conflict, every value drawn in a Conflict band exactly in conflict (see
/// [`draws_in`] for the values). Returns the faults (the exact truth against the band,
/// or undecided).
pub fn check(
    case: &BandCase,
    param: Param,
    bands: &Bands,
    draws: usize,
    spacing: f64,
) -> Vec<Fault> {
    let mut faults = Vec::new();
    for band in &bands.bands {
        let want = match band.kind {
            BandKind::Clear => false,
            BandKind::Conflict => true,
            BandKind::Unknown => continue,
        };
        for x in draws_in(band, draws, spacing) {
            let truth = case.truth(param, x);
            if truth != Some(want) {
                faults.push(Fault {
                    value: x,
                    band: *band,
                    conflict: truth,
                });
            }
        }
    }
    faults
}

/// The canary: course bands from samples every `step` radians, each sample's verdict
/// (the engine's certified `conflict` at that course: Yes Conflict, No Clear, else
/// Unknown) painted over the half steps on either side, **without** the certificate's
/// margin. A conflict thinner than a step between two samples is painted Clear: the
/// check must catch it.
pub fn sampled_course_bands(traffic: &Traffic, speed: f64, step: f64) -> Bands {
    let tau = core::f64::consts::TAU;
    let n = ((tau / step).ceil() as usize).max(1);
    let mut bands: Vec<Band> = Vec::new();
    for k in 0..n {
        let theta = k as f64 * step;
        let kind = match conflict(traffic, velocity(speed, theta)) {
            Ok(Tri::Yes) => BandKind::Conflict,
            Ok(Tri::No) => BandKind::Clear,
            _ => BandKind::Unknown,
        };
        let lo = if k == 0 { 0.0 } else { theta - step * 0.5 };
        let hi = if k + 1 == n { tau } else { theta + step * 0.5 };
        match bands.last_mut() {
            Some(b) if b.kind == kind => b.hi = hi,
            _ => bands.push(Band { lo, hi, kind }),
        }
    }
    let unknown_total = bands
        .iter()
        .filter(|b| b.kind == BandKind::Unknown)
        .fold(0.0, |u, b| u + (b.hi - b.lo));
    Bands {
        bands,
        unknown_total,
        met: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polyguard::bands::course_bands;

    /// The square [cx ± a] × [cy ± a], counterclockwise, at rest.
    fn square(cx: f64, cy: f64, a: f64) -> Polygon {
        let v = Vect2::new;
        Polygon {
            p: vec![
                v(cx - a, cy - a),
                v(cx + a, cy - a),
                v(cx + a, cy + a),
                v(cx - a, cy + a),
            ],
            vels: vec![Vect2::ZERO; 4],
            slab: None,
        }
    }

    /// A square of half side 1 at 100 on the bearing 5°, D = 0.5: its conflict band is
    /// about 5° ± 0.86°, between the samples 0° and 10° of a 10° grid.
    fn thin() -> BandCase {
        let b = 5f64.to_radians();
        BandCase {
            t: 20.0,
            s: Vect2::ZERO,
            height: None,
            polygons: vec![square(100.0 * b.sin(), 100.0 * b.cos(), 1.0)],
            sep: Separation { d: 0.5, h: 0.0 },
        }
    }

    #[test]
    fn the_canary_paints_a_thin_conflict_clear_and_is_caught() {
        let case = thin();
        let param = Param::Course { speed: 10.0 };
        let canary = case.with_traffic(|t| sampled_course_bands(t, 10.0, 10f64.to_radians()));
        assert!(canary.bands.iter().all(|b| b.kind == BandKind::Clear));
        let faults = check(&case, param, &canary, 8, 0.5f64.to_radians());
        assert!(contradictions(&faults) > 0, "{faults:?}");
        for f in &faults {
            assert_eq!(f.conflict, Some(true));
            assert!((f.value.to_degrees() - 5.0).abs() < 1.0, "{f:?}");
        }
    }

    #[test]
    fn the_certified_bands_of_the_same_case_pass() {
        let case = thin();
        let param = Param::Course { speed: 10.0 };
        let bands = case
            .with_traffic(|t| course_bands(t, 10.0, 0.1f64.to_radians()))
            .expect("valid");
        assert!(bands
            .bands
            .iter()
            .any(|b| b.kind == BandKind::Conflict && b.lo < 0.09 && b.hi > 0.085));
        let faults = check(&case, param, &bands, 8, 0.5f64.to_radians());
        assert!(faults.is_empty(), "{faults:?}");
    }
}
