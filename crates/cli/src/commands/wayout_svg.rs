//! `polyguard bands --svg FILE` and `polyguard offset --svg FILE`: the compass rose of one
//! case's course bands, and one case's certified offset beside a bisector expansion
//! (docs/way-out.md), drawn by the harness's `wayout::picture`.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use serde_json::Value;

use polyguard::bands::course_bands;
use polyguard::offset::{inset_at, offset, offset_at};
use polyguard::recovery::{recovery_out, Recovery};
use polyguard::Vect2;
use polyguard_harness::canary_offset::bisector_expansion;
use polyguard_harness::wayout::answer::{band_case, Ask, Command};
use polyguard_harness::wayout::case::{parse_way_line, WayCase};
use polyguard_harness::wayout::picture::{compass_svg, offset_svg, Compass, OffsetPicture};

/// `--svg OUT` and `--svg-case ID`, shared by `bands` and `offset`.
#[derive(Debug, clap::Args)]
pub struct SvgArgs {
    /// Also draw one case into this SVG file (the first valid case, or `--svg-case`):
    /// `bands` draws the compass rose of its course bands, `offset` its result beside a
    /// PolyCARP-style bisector expansion and the points of the buffer that one leaves
    /// out. Needs FILE, not standard input.
    #[arg(long, value_name = "OUT.svg")]
    pub svg: Option<PathBuf>,
    /// The id of the case to draw with `--svg`.
    #[arg(long, value_name = "ID", requires = "svg")]
    pub svg_case: Option<String>,
}

/// Answers every line of `file` with `cmd` (`wayout_common::run`), then draws the picture
/// `--svg` asks for: `write_bands` for `bands`, `write_offset` for `offset`. Exit 2
/// when `--svg` is given without a FILE or the picture cannot be drawn.
pub fn run_and_draw(
    name: &str,
    cmd: Command,
    file: &Option<PathBuf>,
    ask: &Ask,
    svg: &SvgArgs,
) -> ExitCode {
    let path = file.as_deref().filter(|f| *f != Path::new("-"));
    if svg.svg.is_some() && path.is_none() {
        eprintln!("polyguard {name}: --svg needs a case FILE (standard input is read once)");
        return ExitCode::from(2);
    }
    let status = super::wayout_common::run(name, cmd, file, ask);
    if let (Some(out), Some(path)) = (&svg.svg, path) {
        let want = svg.svg_case.as_deref();
        let drawn = match cmd {
            Command::Offset => write_offset(path, want, ask, out),
            _ => write_bands(path, want, ask, out),
        };
        if let Err(e) = drawn {
            eprintln!("polyguard {name}: --svg: {e}");
            return ExitCode::from(2);
        }
    }
    status
}

/// The relative tolerance of the offsets drawn (a picture needs no finer).
const PICTURE_EPS: f64 = 0.01;

/// Does the line's id match the one asked for (a string id as written, any other id as
/// its JSON text)?
fn id_matches(id: &Value, want: &str) -> bool {
    match id {
        Value::String(s) => s == want,
        other => serde_json::to_string(other).is_ok_and(|text| text == want),
    }
}

/// The case to draw: the first valid one, or the one whose id is `want`.
fn pick(text: &str, want: Option<&str>) -> Result<(String, WayCase), String> {
    let lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    for (i, line) in lines {
        let parsed = parse_way_line(line, i + 1);
        if want.is_some_and(|w| !id_matches(&parsed.id, w)) {
            continue;
        }
        let title = match &parsed.id {
            Value::String(s) => s.clone(),
            other => other.to_string(),
        };
        match parsed.case {
            Ok(case) => return Ok((title, case)),
            Err(e) if want.is_some() => return Err(format!("line {}: {e}", i + 1)),
            Err(_) => {}
        }
    }
    Err(match want {
        Some(w) => format!("no case with id {w:?}"),
        None => "no valid case to draw".into(),
    })
}

/// The recovery point out of the nearest polygon's D-neighbourhood at t = 0, when the
/// point is within D of some polygon.
fn recovery(case: &WayCase, d: f64) -> Option<Vect2> {
    let mut best: Option<(f64, Vect2)> = None;
    for poly in &case.polygons {
        if let Ok(Recovery::Point {
            x,
            dist_hi,
            clear: false,
            ..
        }) = recovery_out(&poly.p, case.s, d)
        {
            if best.map_or(true, |(b, _)| dist_hi < b) {
                best = Some((dist_hi, x));
            }
        }
    }
    best.map(|(_, x)| x)
}

/// Draws the bands of the case `want` (or the first valid one) of `file` into `out`.
pub fn write_bands(file: &Path, want: Option<&str>, ask: &Ask, out: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let (title, case) = pick(&text, want)?;
    let bc = band_case(&case, ask);
    let deg = case.bands.unknown_max_deg.unwrap_or(ask.unknown_max_deg);
    let speed = case.v.x.hypot(case.v.y);
    let bands = bc
        .with_traffic(|traffic| course_bands(traffic, speed, deg.to_radians()))
        .map_err(|e| e.to_string())?;
    let t = case.lookahead;
    let polygons: Vec<(Vec<Vect2>, Vec<Vect2>)> = case
        .polygons
        .iter()
        .map(|p| {
            let at_t = p.p.iter().zip(&p.vels).map(|(a, v)| a.at(*v, t)).collect();
            (p.p.clone(), at_t)
        })
        .collect();
    let d = bc.sep.d;
    let offsets: Vec<_> = if d > 0.0 {
        case.polygons
            .iter()
            .filter_map(|p| offset(&p.p, d, PICTURE_EPS).ok())
            .collect()
    } else {
        Vec::new()
    };
    let picture = Compass {
        title: &title,
        s: case.s,
        v: case.v,
        t,
        sep: d,
        polygons: &polygons,
        offsets: &offsets,
        bands: &bands,
        recovery: recovery(&case, d),
        units: "case units",
    };
    std::fs::write(out, compass_svg(&picture)).map_err(|e| format!("{}: {e}", out.display()))
}

/// The bisector expansion's tolerance BUFF, as a share of D (PolyCARP's examples use a
/// BUFF far below the resolution distance).
const BISECTOR_BUFF_SHARE: f64 = 0.01;

/// Is q inside the closed ring (crossing parity in f64: for the picture only; the exact
/// verdict on a bisector expansion is the oracle's, `assure --canary bisector-offset`)?
fn inside(ring: &[Vect2], q: Vect2) -> bool {
    let n = ring.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a.y > q.y) != (b.y > q.y) {
            let x = a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if q.x < x {
                odd = !odd;
            }
        }
    }
    odd
}

/// The share of D at which the buffer is sampled: just inside its edge, so that a point
/// of an expansion's edge that runs exactly at D is not drawn as missed.
const SAMPLE_DEPTH: f64 = 1.0 - 1.0 / 1_048_576.0;

/// Points within D of P, just inside the buffer's edge: along each edge shifted outward
/// by D·[`SAMPLE_DEPTH`], and around each convex vertex every degree of its arc.
fn buffer_edge_points(p: &[Vect2], d: f64) -> Vec<Vect2> {
    let d = d * SAMPLE_DEPTH;
    let n = p.len();
    let normal = |a: Vect2, b: Vect2| {
        let e = b - a;
        let len = e.x.hypot(e.y);
        Vect2::new(e.y / len, -e.x / len)
    };
    let mut out = Vec::new();
    for i in 0..n {
        let (u, v, w) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
        let (n0, n1) = (normal(u, v), normal(v, w));
        for k in 0..=20 {
            let f = f64::from(k) / 20.0;
            out.push(v + (w - v).scale(f) + n1.scale(d));
        }
        let (a0, mut a1) = (n0.y.atan2(n0.x), n1.y.atan2(n1.x));
        if a1 > a0 {
            a1 -= core::f64::consts::TAU;
        }
        let steps = ((a0 - a1).to_degrees().ceil() as i64).max(1);
        if (v - u).x * (w - v).y - (v - u).y * (w - v).x > 0.0 {
            for k in 0..=steps {
                let a = a0 + (a1 - a0) * (k as f64 / steps as f64);
                out.push(v + Vect2::new(a.cos(), a.sin()).scale(d));
            }
        }
    }
    out
}

/// Draws the certified offset (or inset) of the case `want` (or the first valid one) of
/// `file` into `out`; an offset is drawn beside a bisector expansion and the points of
/// the buffer it leaves out.
pub fn write_offset(file: &Path, want: Option<&str>, ask: &Ask, out: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let (title, case) = pick(&text, want)?;
    let poly = case.polygons.first().ok_or("the case has no polygon")?;
    let t = case.time.unwrap_or(0.0);
    let d = case.sep.unwrap_or(ask.sep);
    let eps = case.eps.unwrap_or(ask.eps);
    let result = if ask.inset {
        inset_at(&poly.p, &poly.vels, t, d, eps)
    } else {
        offset_at(&poly.p, &poly.vels, t, d, eps)
    }
    .map_err(|e| e.to_string())?;
    let p: Vec<Vect2> = poly
        .p
        .iter()
        .zip(&poly.vels)
        .map(|(a, v)| a.at(*v, t))
        .collect();
    let bisector = (!ask.inset).then(|| bisector_expansion(&p, BISECTOR_BUFF_SHARE * d, d));
    let missed: Vec<Vect2> = match &bisector {
        Some(b) => buffer_edge_points(&p, d)
            .into_iter()
            .filter(|&q| !inside(b, q))
            .collect(),
        None => Vec::new(),
    };
    let picture = OffsetPicture {
        title: &title,
        p: &p,
        d,
        offset: &result,
        inset: ask.inset,
        bisector: bisector.as_deref(),
        missed: &missed,
    };
    std::fs::write(out, offset_svg(&picture)).map_err(|e| format!("{}: {e}", out.display()))
}
