//! The way-out case: a detection case line (docs/cases.md) read for `polyguard bands`,
//! `recover` and `offset` (docs/way-out.md): the point, one polygon or several
//! (`polygons`), the lookahead T, and the way-out fields `time`, `bands` and `eps`
//! beside `sep`, `sep_v` and `fence`. Paper A §II's point and polygons, §II–§III's
//! motion (vertices p_i + t·V_i, slabs in 3D), read strictly as every case line is.

use serde_json::{Map, Value};

use polyguard::bands::{Height, Slab};
use polyguard::error::CaseError;
use polyguard::Vect2;

use super::bands::Polygon;
use crate::case::{
    array, case_options, get, moving_point, moving_polygon, number, object, only_known,
    point_fields, polygon_fields, read_case_object, Fence, TOP_KEYS,
};

/// What is wrong with a line: the field (a path into the case, `line` for the line as a
/// whole, `case` for the answer's computation) and what, in words.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    /// The field, as `polygons[1].vertices` or `bands.speeds`.
    pub field: String,
    /// What is wrong with it.
    pub message: String,
}

impl FieldError {
    /// An error of `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> FieldError {
        FieldError {
            field: field.into(),
            message: message.into(),
        }
    }

    /// A reader's error, its `polygon.` fields renamed to `prefix` (`polygons[2].`).
    fn of_case(e: &CaseError, prefix: &str) -> FieldError {
        let field = e.field();
        let text = e.to_string();
        let message = text
            .strip_prefix(&format!("{field}: "))
            .unwrap_or(&text)
            .to_owned();
        let field = match field.strip_prefix("polygon.") {
            Some(rest) => format!("{prefix}{rest}"),
            None => field,
        };
        FieldError { field, message }
    }
}

impl std::fmt::Display for FieldError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.message)
    }
}

/// The `bands` object's options (docs/way-out.md), `None` where the line gives none.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BandsOptions {
    /// The Unknown total aimed at, in degrees of course (> 0).
    pub unknown_max_deg: Option<f64>,
    /// Speed bands over [min, max] at the current course (0 ≤ min ≤ max).
    pub speeds: Option<[f64; 2]>,
    /// Vertical speed bands over [min, max] (3D; min ≤ max).
    pub vertical_speeds: Option<[f64; 2]>,
}

/// One way-out case, validated: the point s + t·v (height sz + t·vz in 3D), the moving
/// polygons, T, and the options the line gives.
#[derive(Clone, Debug, PartialEq)]
pub struct WayCase {
    /// T > 0.
    pub lookahead: f64,
    /// s.
    pub s: Vect2,
    /// v, horizontal.
    pub v: Vect2,
    /// sz and vz (3D).
    pub height: Option<Height>,
    /// The polygons (`polygon`, or each of `polygons`), velocities filled with zeros when
    /// absent.
    pub polygons: Vec<Polygon>,
    /// `sep` (D).
    pub sep: Option<f64>,
    /// `sep_v` (H).
    pub sep_v: Option<f64>,
    /// `fence`.
    pub fence: Option<Fence>,
    /// `time`, in [0, T].
    pub time: Option<f64>,
    /// `eps`, in (0, 1).
    pub eps: Option<f64>,
    /// `bands`.
    pub bands: BandsOptions,
}

/// One line read: the id to echo and the case, or the first thing wrong with it.
pub struct WayLine {
    /// The case's `id`, or the 1-based line number.
    pub id: Value,
    /// The case or the error.
    pub case: Result<WayCase, FieldError>,
}

/// Reads one non-blank line of the case format as a way-out case (docs/way-out.md).
pub fn parse_way_line(line: &str, line_no: usize) -> WayLine {
    let (id, obj) = read_case_object(line, line_no);
    let case = obj
        .map_err(|e| FieldError::of_case(&e, "polygon."))
        .and_then(|obj| way_case(&obj));
    WayLine { id, case }
}

/// The keys of the `bands` object.
const BANDS_KEYS: [&str; 3] = ["unknown_max_deg", "speeds", "vertical_speeds"];

/// A way-out case from its JSON object: the detection case's rules (docs/cases.md) for
/// the fields it shares, `buff` optional, `polygon` or `polygons` (not both).
pub fn way_case(obj: &Map<String, Value>) -> Result<WayCase, FieldError> {
    let plain = |e: CaseError| FieldError::of_case(&e, "polygon.");
    only_known(obj, &TOP_KEYS, "").map_err(plain)?;
    if let Some(m) = obj.get("meta") {
        object(m, "meta").map_err(plain)?;
    }
    let present = |k: &str| obj.get(k).filter(|v| !v.is_null());
    let lookahead = number(
        get(obj, "lookahead", "lookahead").map_err(plain)?,
        "lookahead",
    )
    .map_err(plain)?;
    if lookahead <= 0.0 {
        return Err(FieldError::new(
            "lookahead",
            format!("{lookahead} is not > 0"),
        ));
    }
    if let Some(b) = present("buff") {
        let b = number(b, "buff").map_err(plain)?;
        if b <= 0.0 {
            return Err(FieldError::new("buff", format!("{b} is not > 0")));
        }
    }
    for k in ["fac", "kappa"] {
        if let Some(x) = present(k) {
            number(x, k).map_err(plain)?;
        }
    }
    let point = object(get(obj, "point", "point").map_err(plain)?, "point").map_err(plain)?;
    let (pos, vel) = point_fields(point).map_err(plain)?;
    let pt = moving_point(&pos, &vel).map_err(plain)?;
    let height = pt.z.map(|(sz, vz)| Height { sz, vz });
    let polygons = polygons_of(obj, height.is_some())?;
    let options = case_options(obj).map_err(plain)?;
    let time = present("time")
        .map(|v| number(v, "time").map_err(plain))
        .transpose()?;
    if let Some(t) = time {
        if !(0.0..=lookahead).contains(&t) {
            return Err(FieldError::new(
                "time",
                format!("{t} is outside [0, lookahead] = [0, {lookahead}]"),
            ));
        }
    }
    let eps = present("eps")
        .map(|v| number(v, "eps").map_err(plain))
        .transpose()?;
    if let Some(e) = eps {
        if !(e > 0.0 && e < 1.0) {
            return Err(FieldError::new("eps", format!("{e} is outside (0, 1)")));
        }
    }
    let bands = match present("bands") {
        None => BandsOptions::default(),
        Some(b) => bands_options(object(b, "bands").map_err(plain)?, height.is_some())?,
    };
    Ok(WayCase {
        lookahead,
        s: pt.pos,
        v: pt.vel,
        height,
        polygons,
        sep: options.sep,
        sep_v: options.sep_v,
        fence: options.fence,
        time,
        eps,
        bands,
    })
}

/// The case's polygons: `polygon`, or each of `polygons` (at least one), each with a
/// slab exactly when the point is 3D.
fn polygons_of(obj: &Map<String, Value>, three_d: bool) -> Result<Vec<Polygon>, FieldError> {
    let plain = |e: CaseError| FieldError::of_case(&e, "polygon.");
    let one = obj.get("polygon").filter(|v| !v.is_null());
    let many = obj.get("polygons").filter(|v| !v.is_null());
    let list: Vec<(&Value, String)> = match (one, many) {
        (Some(_), Some(_)) => {
            return Err(FieldError::new(
                "polygons",
                "a case has `polygon` or `polygons`, not both",
            ))
        }
        (None, None) => return Err(FieldError::new("polygon", "missing (or give `polygons`)")),
        (Some(p), None) => vec![(p, "polygon.".to_owned())],
        (None, Some(ps)) => {
            let ps = array(ps, "polygons").map_err(plain)?;
            if ps.is_empty() {
                return Err(FieldError::new("polygons", "empty: at least one polygon"));
            }
            ps.iter()
                .enumerate()
                .map(|(i, p)| (p, format!("polygons[{i}].")))
                .collect()
        }
    };
    let mut out = Vec::with_capacity(list.len());
    for (value, prefix) in list {
        let named = |e: CaseError| FieldError::of_case(&e, &prefix);
        let map = object(value, "polygon")
            .map_err(|_| FieldError::new(prefix.trim_end_matches('.'), "must be an object"))?;
        let (vertices, velocities, slab) = polygon_fields(map).map_err(named)?;
        // the case format's ring rules (simple, counterclockwise at time 0)
        moving_polygon(&vertices, &velocities, slab).map_err(named)?;
        match (three_d, slab.is_some()) {
            (true, false) => {
                return Err(FieldError::new(
                    format!("{prefix}bottom"),
                    "2D and 3D mixed: the point has a height but the polygon has no \
                     bottom/top/vz",
                ))
            }
            (false, true) => {
                return Err(FieldError::new(
                    "point.pos",
                    format!(
                        "2D and 3D mixed: {}has bottom/top/vz but the point has no height",
                        prefix
                    ),
                ))
            }
            _ => {}
        }
        let p: Vec<Vect2> = vertices.iter().map(|&a| a.into()).collect();
        let vels = if velocities.is_empty() {
            vec![Vect2::new(0.0, 0.0); p.len()]
        } else {
            velocities.iter().map(|&a| a.into()).collect()
        };
        out.push(Polygon {
            p,
            vels,
            slab: slab.map(|[bottom, top, vsp]| Slab { bottom, top, vsp }),
        });
    }
    Ok(out)
}

/// A `[min, max]` pair of finite numbers, min ≤ max (and min ≥ 0 when `nonnegative`).
fn range(v: &Value, field: &str, nonnegative: bool) -> Result<[f64; 2], FieldError> {
    let plain = |e: CaseError| FieldError::of_case(&e, "polygon.");
    let a = array(v, field).map_err(plain)?;
    if a.len() != 2 {
        return Err(FieldError::new(
            field,
            format!("{} numbers, 2 expected ([min, max])", a.len()),
        ));
    }
    let lo = number(&a[0], &format!("{field}[0]")).map_err(plain)?;
    let hi = number(&a[1], &format!("{field}[1]")).map_err(plain)?;
    if nonnegative && lo < 0.0 {
        return Err(FieldError::new(
            format!("{field}[0]"),
            format!("{lo} is below 0 (a speed)"),
        ));
    }
    if hi < lo {
        return Err(FieldError::new(
            format!("{field}[1]"),
            format!("{hi} is below min {lo}"),
        ));
    }
    Ok([lo, hi])
}

/// The `bands` object (docs/way-out.md).
fn bands_options(b: &Map<String, Value>, three_d: bool) -> Result<BandsOptions, FieldError> {
    let plain = |e: CaseError| FieldError::of_case(&e, "polygon.");
    only_known(b, &BANDS_KEYS, "bands.").map_err(plain)?;
    let present = |k: &str| b.get(k).filter(|v| !v.is_null());
    let unknown_max_deg = present("unknown_max_deg")
        .map(|v| number(v, "bands.unknown_max_deg").map_err(plain))
        .transpose()?;
    if let Some(u) = unknown_max_deg {
        if u <= 0.0 {
            return Err(FieldError::new(
                "bands.unknown_max_deg",
                format!("{u} is not > 0"),
            ));
        }
    }
    let speeds = present("speeds")
        .map(|v| range(v, "bands.speeds", true))
        .transpose()?;
    let vertical_speeds = present("vertical_speeds")
        .map(|v| range(v, "bands.vertical_speeds", false))
        .transpose()?;
    if vertical_speeds.is_some() && !three_d {
        return Err(FieldError::new(
            "bands.vertical_speeds",
            "a 3D case only (point.pos of 3 numbers, polygons with bottom/top/vz)",
        ));
    }
    Ok(BandsOptions {
        unknown_max_deg,
        speeds,
        vertical_speeds,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = r#"{"id":"w","lookahead":2,"sep":0.5,"time":1,"bands":{"speeds":[0,3]},"point":{"pos":[5,-3],"vel":[0,1]},"polygons":[{"vertices":[[0,0],[2,0],[2,2],[0,2]]},{"vertices":[[4,0],[6,0],[5,1]],"velocities":[[1,0],[1,0],[1,0]]}]}"#;

    fn err(line: &str) -> String {
        match parse_way_line(line, 4).case {
            Ok(_) => "ok".into(),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn polygons_and_the_way_out_fields_read() {
        let c = parse_way_line(GOOD, 1).case.expect("valid");
        assert_eq!(c.polygons.len(), 2);
        assert_eq!(c.polygons[0].vels, vec![Vect2::new(0.0, 0.0); 4]);
        assert_eq!(c.polygons[1].vels[2], Vect2::new(1.0, 0.0));
        assert_eq!((c.time, c.sep, c.eps), (Some(1.0), Some(0.5), None));
        assert_eq!(c.bands.speeds, Some([0.0, 3.0]));
        assert!(c.height.is_none());
    }

    /// Each error names its field in the case's terms, polygons by their index.
    #[test]
    fn errors_name_their_field() {
        let cases = [
            (r#""velocities""#, r#""velocity""#, "polygons[1].velocity: unknown field; did you mean velocities?"),
            (r#"[[4,0],[6,0],[5,1]]"#, r#"[[4,0],[5,1],[6,0]]"#, "polygons[1].vertices: clockwise order (signed area -1); list the vertices counterclockwise"),
            (r#""time":1"#, r#""time":3"#, "time: 3 is outside [0, lookahead] = [0, 2]"),
            (r#""speeds":[0,3]"#, r#""speedz":[0,3]"#, "bands.speedz: unknown field; did you mean speeds?"),
            (r#""speeds":[0,3]"#, r#""vertical_speeds":[0,3]"#, "bands.vertical_speeds: a 3D case only (point.pos of 3 numbers, polygons with bottom/top/vz)"),
            (r#""sep":0.5"#, r#""sep":0.5,"eps":0"#, "eps: 0 is outside (0, 1)"),
            (r#""polygons":["#, r#""polygon":{"vertices":[[0,0],[1,0],[0,1]]},"polygons":["#, "polygons: a case has `polygon` or `polygons`, not both"),
        ];
        for (from, to, want) in cases {
            let line = GOOD.replacen(from, to, 1);
            assert_ne!(line, GOOD, "{from}");
            assert_eq!(err(&line), want);
        }
        let slab = GOOD.replacen(r#"[0,2]]}"#, r#"[0,2]],"bottom":0,"top":1,"vz":0}"#, 1);
        assert!(
            err(&slab).starts_with("point.pos: 2D and 3D mixed: polygons[0]."),
            "{}",
            err(&slab)
        );
        let nobuff = GOOD.replace(r#""sep":0.5,"#, r#""sep":0.5,"buff":0,"#);
        assert_eq!(err(&nobuff), "buff: 0 is not > 0");
    }

    /// `detect` keeps taking one polygon: `polygons` there is an error naming it.
    #[test]
    fn detect_refuses_polygons() {
        let line = GOOD.replace(r#""sep":0.5,"#, r#""sep":0.5,"buff":0.1,"#);
        let e = crate::case::parse_line(&line, 1)
            .case
            .err()
            .map(|e| e.to_string());
        assert_eq!(
            e.as_deref(),
            Some(
                "polygons: must be absent for detect: detect takes one polygon (`polygon`); \
                 `bands` takes several"
            )
        );
    }
}
