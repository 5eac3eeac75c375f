//! A detection case as raw f64 fields, exactly as the case format carries them.

use serde::{Deserialize, Serialize};

use polyguard::api::{Case, MovingPoint, MovingPolygon, Params};
use polyguard::error::CaseError;
use polyguard::vect2::Vect2;

/// A case of docs/cases.md, unvalidated.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RawCase {
    /// T, the lookahead time.
    pub lookahead: f64,
    /// BUFF, the distance threshold.
    pub buff: f64,
    /// F, the fraction of BUFF for warping polygons.
    pub fac: f64,
    /// 2 numbers, or 3 with the height.
    pub pos: Vec<f64>,
    /// As many as `pos`.
    pub vel: Vec<f64>,
    /// The polygon, counterclockwise.
    pub vertices: Vec<[f64; 2]>,
    /// One velocity per vertex (empty: all still).
    pub velocities: Vec<[f64; 2]>,
    /// bottom, top, vz for a 3D case.
    pub slab: Option<[f64; 3]>,
}

impl RawCase {
    /// The engine's validated case.
    pub fn to_api(&self) -> Result<Case, CaseError> {
        let mut params = Params::new(self.buff)?.with_fac(self.fac)?;
        params = params.with_kappa(Params::DEFAULT_KAPPA)?;
        let pt = match (self.pos.as_slice(), self.vel.as_slice()) {
            ([x, y], [vx, vy]) => MovingPoint::new_2d(Vect2::new(*x, *y), Vect2::new(*vx, *vy))?,
            ([x, y, z], [vx, vy, vz]) => MovingPoint::new_3d([*x, *y, *z], [*vx, *vy, *vz])?,
            _ => {
                return Err(CaseError::WrongLength {
                    field: "point.vel".into(),
                    expected: self.pos.len(),
                    found: self.vel.len(),
                    what: "numbers (as many as point.pos)",
                })
            }
        };
        let mut poly = MovingPolygon::new(
            self.vertices.iter().map(|&p| p.into()).collect(),
            Some(self.velocities.iter().map(|&p| p.into()).collect()),
        )?;
        if let Some([b, t, z]) = self.slab {
            poly = poly.with_slab(b, t, z)?;
        }
        Case::new(self.lookahead, pt, poly, params)
    }

    /// The raw fields of a validated case.
    pub fn from_api(case: &Case) -> RawCase {
        let pt = case.point();
        let (pos, vel) = match pt.z {
            Some((sz, vz)) => (vec![pt.pos.x, pt.pos.y, sz], vec![pt.vel.x, pt.vel.y, vz]),
            None => (vec![pt.pos.x, pt.pos.y], vec![pt.vel.x, pt.vel.y]),
        };
        RawCase {
            lookahead: case.lookahead(),
            buff: case.params().buff(),
            fac: case.params().fac(),
            pos,
            vel,
            vertices: case
                .polygon()
                .vertices()
                .iter()
                .map(|&p| p.into())
                .collect(),
            velocities: case
                .polygon()
                .velocities()
                .iter()
                .map(|&p| p.into())
                .collect(),
            slab: case.polygon().slab().map(|s| [s.bottom, s.top, s.vz]),
        }
    }

    /// The oracle's exact case: the rationals these f64 denote.
    pub fn exact<F: polyguard_oracle::ExactField>(
        &self,
    ) -> Result<polyguard_oracle::ExactCase<F>, polyguard_oracle::OracleError> {
        polyguard_oracle::ExactCase::from_f64(&polyguard_oracle::CaseF64 {
            lookahead: self.lookahead,
            buff: self.buff,
            fac: self.fac,
            pos: &self.pos,
            vel: &self.vel,
            vertices: &self.vertices,
            velocities: &self.velocities,
            slab: self.slab,
        })
    }

    /// The same case with BUFF and F multiplied by k (the "wide band" of classify).
    pub fn widened(&self, k: f64) -> RawCase {
        RawCase {
            buff: self.buff * k,
            fac: (self.fac * k).min(0.5),
            ..self.clone()
        }
    }

    /// One line of the case format (shortest round-trip numbers), with an `id` and any
    /// annotations (a kept counterexample's class, …) in its `meta` object.
    pub fn to_json_line(&self, id: &str, extra: &[(&str, serde_json::Value)]) -> String {
        let mut point = serde_json::Map::new();
        point.insert("pos".into(), serde_json::json!(self.pos));
        point.insert("vel".into(), serde_json::json!(self.vel));
        let mut poly = serde_json::Map::new();
        poly.insert("vertices".into(), serde_json::json!(self.vertices));
        poly.insert("velocities".into(), serde_json::json!(self.velocities));
        if let Some([b, t, z]) = self.slab {
            poly.insert("bottom".into(), b.into());
            poly.insert("top".into(), t.into());
            poly.insert("vz".into(), z.into());
        }
        let mut obj = serde_json::Map::new();
        obj.insert("id".into(), id.into());
        obj.insert("lookahead".into(), self.lookahead.into());
        obj.insert("buff".into(), self.buff.into());
        obj.insert("fac".into(), self.fac.into());
        obj.insert("point".into(), serde_json::Value::Object(point));
        obj.insert("polygon".into(), serde_json::Value::Object(poly));
        if !extra.is_empty() {
            let meta: serde_json::Map<String, serde_json::Value> = extra
                .iter()
                .map(|(k, v)| ((*k).to_string(), v.clone()))
                .collect();
            obj.insert("meta".into(), serde_json::Value::Object(meta));
        }
        serde_json::Value::Object(obj).to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::case::parse_line;

    #[test]
    fn json_round_trip_is_bit_exact() {
        let raw = RawCase {
            lookahead: 300.0,
            buff: 0.1 + 0.2,
            fac: 1e-4,
            pos: vec![1.0 / 3.0, -2.5e-300, 7.0],
            vel: vec![0.1, f64::MIN_POSITIVE, -1.0],
            vertices: vec![[0.0, 0.0], [1e7 + 0.1, 0.0], [0.5, 1.0]],
            velocities: vec![[0.0, 0.0]; 3],
            slab: Some([0.0, 10.0, -0.25]),
        };
        let line = raw.to_json_line("x", &[]);
        let back = parse_line(&line, 1).case.expect("valid");
        assert_eq!(RawCase::from_api(&back), raw);
    }
}
