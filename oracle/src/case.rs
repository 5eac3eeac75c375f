//! A detection case in exact numbers (docs/cases.md), its validation, and the
//! paper's choice of detection function (paper A §II.F and §III).

pub use crate::convert::Input;
use crate::detect::{detect_2d, dispatch, slab_scene, Method};
pub use crate::error::OracleError;
use crate::field::{ExactField, V2};
use crate::kernel::run::{Filtered, Scene, Single};
use crate::kernel::{Decided, Exact, Intervals, Iv, Kernel};

/// The vertical part of a 3D case (paper A §III).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Vertical<F> {
    /// s_z, the point's height at time 0.
    pub sz: F,
    /// v_z, the point's vertical speed.
    pub vz: F,
    /// pmin, the slab's bottom at time 0.
    pub bottom: F,
    /// pmax, the slab's top at time 0.
    pub top: F,
    /// vsp, the slab's vertical speed.
    pub vsp: F,
}

/// A validated case in exact numbers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactCase<F> {
    /// T > 0.
    pub lookahead: F,
    /// BUFF > 0.
    pub buff: F,
    /// F ∈ (0, 1).
    pub fac: F,
    /// s (horizontal).
    pub s: V2<F>,
    /// v (horizontal).
    pub v: V2<F>,
    /// P, at least 3 vertices.
    pub vertices: Vec<V2<F>>,
    /// V, one per vertex.
    pub velocities: Vec<V2<F>>,
    /// The vertical data when the case is 3D.
    pub vertical: Option<Vertical<F>>,
}

/// A case as written, field for field as docs/cases.md names them, in any number type
/// the oracle reads exactly ([`Input`]): the engine's binary floats, or text ("p/q", an
/// integer or a decimal). [`ExactCase::new`] checks it and makes it exact.
#[derive(Clone, Copy, Debug)]
pub struct CaseInput<'a, N> {
    /// T.
    pub lookahead: N,
    /// BUFF.
    pub buff: N,
    /// F.
    pub fac: N,
    /// s, 2 or 3 numbers.
    pub pos: &'a [N],
    /// v, same length as `pos`.
    pub vel: &'a [N],
    /// P.
    pub vertices: &'a [[N; 2]],
    /// V (empty means all zero).
    pub velocities: &'a [[N; 2]],
    /// bottom, top, vz when 3D.
    pub slab: Option<[N; 3]>,
}

/// Raw exact components before the rules are checked.
struct Raw<F> {
    lookahead: F,
    buff: F,
    fac: F,
    pos: Vec<F>,
    vel: Vec<F>,
    vertices: Vec<V2<F>>,
    velocities: Vec<V2<F>>,
    slab: Option<[F; 3]>,
}

impl<F: ExactField> ExactCase<F> {
    /// The exact case a written case denotes, checked against docs/cases.md's rules.
    pub fn new<N: Input>(c: &CaseInput<'_, N>) -> Result<Self, OracleError> {
        fn list<F: ExactField, N: Input>(
            field: &'static str,
            xs: &[N],
        ) -> Result<Vec<F>, OracleError> {
            xs.iter().map(|x| x.exact(field)).collect()
        }
        fn pts<F: ExactField, N: Input>(
            field: &'static str,
            xs: &[[N; 2]],
        ) -> Result<Vec<V2<F>>, OracleError> {
            xs.iter()
                .map(|p| Ok(V2::new(p[0].exact(field)?, p[1].exact(field)?)))
                .collect()
        }
        let slab = match c.slab {
            None => None,
            Some([b, t, z]) => Some([
                b.exact("polygon.bottom")?,
                t.exact("polygon.top")?,
                z.exact("polygon.vz")?,
            ]),
        };
        Self::from_raw(Raw {
            lookahead: c.lookahead.exact("lookahead")?,
            buff: c.buff.exact("buff")?,
            fac: c.fac.exact("fac")?,
            pos: list("point.pos", c.pos)?,
            vel: list("point.vel", c.vel)?,
            vertices: pts("polygon.vertices", c.vertices)?,
            velocities: pts("polygon.velocities", c.velocities)?,
            slab,
        })
    }

    fn from_raw(r: Raw<F>) -> Result<Self, OracleError> {
        let zero = F::zero();
        if r.lookahead <= zero {
            return Err(OracleError::new("lookahead", "must be > 0"));
        }
        if r.buff <= zero {
            return Err(OracleError::new("buff", "must be > 0"));
        }
        if r.fac <= zero || r.fac >= F::one() {
            return Err(OracleError::new("fac", "must satisfy 0 < fac < 1"));
        }
        if r.pos.len() != 2 && r.pos.len() != 3 {
            return Err(OracleError::new(
                "point.pos",
                format!("{} numbers, 2 or 3 are needed", r.pos.len()),
            ));
        }
        if r.vel.len() != r.pos.len() {
            return Err(OracleError::new(
                "point.vel",
                format!(
                    "{} numbers, the same as point.pos ({}) are needed",
                    r.vel.len(),
                    r.pos.len()
                ),
            ));
        }
        let n = r.vertices.len();
        if n < 3 {
            return Err(OracleError::new(
                "polygon.vertices",
                format!("{n} points, at least 3 are needed"),
            ));
        }
        let velocities = if r.velocities.is_empty() {
            vec![V2::zero(); n]
        } else if r.velocities.len() != n {
            return Err(OracleError::new(
                "polygon.velocities",
                format!("{} velocities for {n} vertices", r.velocities.len()),
            ));
        } else {
            r.velocities
        };
        let vertical = match (r.pos.len(), r.slab) {
            (2, None) => None,
            (3, Some([bottom, top, vsp])) => Some(Vertical {
                sz: r.pos[2].clone(),
                vz: r.vel[2].clone(),
                bottom,
                top,
                vsp,
            }),
            (3, None) => {
                return Err(OracleError::new(
                    "polygon.bottom",
                    "the point is 3D but the polygon has no bottom/top/vz (2D/3D mixed)",
                ))
            }
            _ => {
                return Err(OracleError::new(
                    "point.pos",
                    "the polygon has bottom/top/vz but the point is 2D (2D/3D mixed)",
                ))
            }
        };
        let s = V2::new(r.pos[0].clone(), r.pos[1].clone());
        let v = V2::new(r.vel[0].clone(), r.vel[1].clone());
        Ok(ExactCase {
            lookahead: r.lookahead,
            buff: r.buff,
            fac: r.fac,
            s,
            v,
            vertices: r.vertices,
            velocities,
            vertical,
        })
    }

    /// Paper A §II.F and §III: the detector that decides the case ([`dispatch`]).
    pub fn method(&self) -> Method {
        dispatch(&Exact, self.vertical.is_some(), &self.velocities).decided()
    }

    /// The inputs of the 2D detectors: T, s, v, P, V, BUFF, F.
    fn scene(&self) -> Scene<'_, F> {
        Scene::new(
            &self.lookahead,
            &self.s,
            &self.v,
            &self.vertices,
            &self.velocities,
            &self.buff,
            &self.fac,
        )
    }
}

/// What paper A's algorithm, evaluated exactly, answers for a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PaperAnswer {
    /// The paper's answer.
    pub detected: bool,
    /// The detector that gave it ([`Method::name`] prints it).
    pub method: Method,
}

/// Paper A §II.F and §III: the case's detector, its 2D part run by `run` on the
/// scene it applies to (the case's, or in 3D the one restarted at the slab window)
/// with the 2D method.
fn answer<F: ExactField>(
    c: &ExactCase<F>,
    run: impl FnOnce(Scene<'_, F>, Method) -> bool,
) -> PaperAnswer {
    let method = c.method();
    let detected = match &c.vertical {
        None => run(c.scene(), method),
        Some(z) => {
            let window = slab_scene(&Exact, &c.scene(), &z.sz, &z.vz, &z.bottom, &z.top, &z.vsp);
            match window.decided() {
                None => false,
                Some(sc) => run(sc, dispatch(&Exact, false, &c.velocities).decided()),
            }
        }
    };
    PaperAnswer { detected, method }
}

/// Paper A §II.F and §III: detect_same_2D for equal vertex velocities,
/// detect_diff_2D otherwise, detect_3D for a 3D case — all evaluated exactly.
///
/// Each paper-function call (one step of a detector, one edge_detect) runs in the
/// interval kernel first ([`Intervals`]) and, when it abstains, in the exact kernel;
/// the answer is identical to [`paper_detect_unfiltered`]'s.
pub fn paper_detect<F: ExactField>(c: &ExactCase<F>) -> PaperAnswer {
    paper_detect_with(&Intervals, c)
}

/// Paper A §II.F and §III: [`paper_detect`] with `first` in front of the exact kernel instead of
/// [`Intervals`]: the answer is the exact one as long as `first`'s decisions are right.
pub fn paper_detect_with<F: ExactField, K: Kernel<Iv>>(first: &K, c: &ExactCase<F>) -> PaperAnswer {
    answer(c, |sc, method| {
        detect_2d(&Filtered::new(first, sc), method).decided()
    })
}

/// Paper A §II.F and §III: [`paper_detect`] computed by the exact kernel alone.
pub fn paper_detect_unfiltered<F: ExactField>(c: &ExactCase<F>) -> PaperAnswer {
    answer(c, |sc, method| {
        detect_2d(&Single::new(&Exact, sc), method).decided()
    })
}
