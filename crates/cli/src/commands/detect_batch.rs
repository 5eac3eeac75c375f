//! `polyguard detect-batch POINTS POLYGONS`: every point of one JSON Lines file against
//! every polygon of another (docs/batch.md), through `polyguard::batch::detect_batch`.

use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use serde_json::{json, Value};

use polyguard::api::{Kind, MovingPoint, MovingPolygon, Params};
use polyguard::batch::{detect_batch_counted, Options};
use polyguard_harness::batch::{batch_workload, Mix, BUFF, FAC, T};
use polyguard_harness::case::{point_from_line, polygon_from_line, DEFAULT_KAPPA_DEG};

/// Arguments of `polyguard detect-batch`.
#[derive(Debug, clap::Args)]
pub struct DetectBatchArgs {
    /// The points, one JSON object per line (`pos`, `vel`): written with --generate.
    pub points: PathBuf,
    /// The polygons, one JSON object per line (`vertices`, `velocities`, and `bottom`,
    /// `top`, `vz` in 3D): written with --generate.
    pub polygons: PathBuf,
    /// T, the lookahead (the case format's `lookahead`), > 0.
    #[arg(
        long,
        required_unless_present = "generate",
        allow_negative_numbers = true
    )]
    pub lookahead: Option<f64>,
    /// BUFF (the case format's `buff`), > 0.
    #[arg(
        long,
        required_unless_present = "generate",
        allow_negative_numbers = true
    )]
    pub buff: Option<f64>,
    /// F (the case format's `fac`), in (0, 1).
    #[arg(long, default_value_t = polyguard::api::Params::DEFAULT_FAC, allow_negative_numbers = true)]
    pub fac: f64,
    /// κ in degrees (the case format's `kappa`), in (0, 180): checked, as in a case; the
    /// batch answer reports no well-formedness.
    #[arg(long, default_value_t = DEFAULT_KAPPA_DEG, allow_negative_numbers = true)]
    pub kappa: f64,
    /// Instead of answering: write the seeded bench workload of N points and M polygons
    /// (8 vertices, docs/batch.md) to POINTS and POLYGONS, and say on standard error the
    /// --lookahead, --buff and --fac it is meant for.
    #[arg(long, num_args = 2, value_names = ["N", "M"])]
    pub generate: Option<Vec<usize>>,
    /// The seed of --generate.
    #[arg(long, default_value_t = 1, requires = "generate")]
    pub seed: u64,
    /// With --generate: 3D points (with a height) and polygons (with a slab).
    #[arg(long, requires = "generate")]
    pub three_d: bool,
    /// No summary on standard error (with --generate: no note of the options to answer
    /// with).
    #[arg(long)]
    pub quiet: bool,
}

/// Runs `polyguard detect-batch`.
pub fn run(args: &DetectBatchArgs) -> ExitCode {
    if let Some(nm) = &args.generate {
        return generate(args, nm[0], nm[1]);
    }
    let (Some(lookahead), Some(buff)) = (args.lookahead, args.buff) else {
        eprintln!("polyguard detect-batch: --lookahead and --buff are required");
        return ExitCode::from(2);
    };
    let params = match Params::new(buff)
        .map_err(|e| ("--buff", e))
        .and_then(|p| p.with_fac(args.fac).map_err(|e| ("--fac", e)))
        .and_then(|p| p.with_kappa_degrees(args.kappa).map_err(|e| ("--kappa", e)))
    {
        Ok(p) => p,
        Err((opt, e)) => {
            eprintln!("polyguard detect-batch: {opt}: {e}");
            return ExitCode::from(2);
        }
    };
    if !(lookahead.is_finite() && lookahead > 0.0) {
        eprintln!("polyguard detect-batch: --lookahead: {lookahead} is not a finite number > 0");
        return ExitCode::from(2);
    }
    let start = Instant::now();
    let (points, polygons) = match (read_lines(&args.points), read_lines(&args.polygons)) {
        (Ok(p), Ok(q)) => (p, q),
        (Err((path, e)), _) | (_, Err((path, e))) => {
            eprintln!(
                "polyguard detect-batch: cannot read {}: {e}",
                path.display()
            );
            return ExitCode::from(2);
        }
    };
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    let result = answer(
        args, lookahead, &params, &points, &polygons, &mut out, start,
    )
    .and_then(|bad| out.flush().map(|()| bad));
    match result {
        Ok(0) => ExitCode::SUCCESS,
        Ok(bad) => {
            eprintln!("polyguard detect-batch: {bad} line(s) could not be read (skipped)");
            ExitCode::from(1)
        }
        Err(e) => {
            eprintln!("polyguard detect-batch: cannot write: {e}");
            ExitCode::from(2)
        }
    }
}

/// A file's lines (the newline removed; `None` for a line that is not UTF-8), or the
/// path and the error.
fn read_lines(path: &Path) -> Result<Vec<Option<String>>, (PathBuf, io::Error)> {
    let bytes = fs::read(path).map_err(|e| (path.to_path_buf(), e))?;
    Ok(bytes
        .split(|&b| b == b'\n')
        .map(|l| String::from_utf8(l.to_vec()).ok())
        .collect())
}

/// Items read from one file: the good ones with their 0-based line index.
struct Read<T> {
    items: Vec<T>,
    lines: Vec<usize>,
}

/// Reads every non-blank line with `parse`; each bad line is written to `out` as an
/// error line naming the file, the line (1-based, as `polyguard detect` does) and the
/// field. `dim` says whether an item is 3D; `want`, when set, the batch's dimension.
fn read_items<T, W: Write>(
    lines: &[Option<String>],
    file: &Path,
    parse: impl Fn(&str) -> Result<T, String>,
    dim: impl Fn(&T) -> bool,
    want: &mut Option<(bool, String)>,
    out: &mut W,
    bad: &mut u64,
) -> io::Result<Read<T>> {
    let mut read = Read {
        items: Vec::new(),
        lines: Vec::new(),
    };
    let name = file.display().to_string();
    for (k, text) in lines.iter().enumerate() {
        let item = match text {
            Some(t) if t.trim().is_empty() => continue,
            Some(t) => parse(t),
            None => Err("line: not UTF-8".to_string()),
        };
        let item = item.and_then(|it| match want {
            None => {
                *want = Some((dim(&it), format!("{name} line {}", k + 1)));
                Ok(it)
            }
            Some((d, _)) if *d == dim(&it) => Ok(it),
            Some((d, first)) => Err(if *d {
                format!("2D and 3D mixed: this item is 2D, the batch 3D (from {first})")
            } else {
                format!("2D and 3D mixed: this item is 3D, the batch 2D (from {first})")
            }),
        });
        match item {
            Ok(it) => {
                read.items.push(it);
                read.lines.push(k);
            }
            Err(e) => {
                *bad += 1;
                let line = json!({"file": name, "line": k + 1, "error": e});
                writeln!(out, "{line}")?;
            }
        }
    }
    Ok(read)
}

/// Reads both files, answers, writes the hits; returns the number of bad lines.
fn answer<W: Write>(
    args: &DetectBatchArgs,
    lookahead: f64,
    params: &Params,
    point_lines: &[Option<String>],
    polygon_lines: &[Option<String>],
    out: &mut W,
    start: Instant,
) -> io::Result<u64> {
    let mut bad = 0;
    let mut dim = None;
    let points: Read<MovingPoint> = read_items(
        point_lines,
        &args.points,
        |l| point_from_line(l).map_err(|e| e.to_string()),
        |p| p.z.is_some(),
        &mut dim,
        out,
        &mut bad,
    )?;
    let polygons: Read<MovingPolygon> = read_items(
        polygon_lines,
        &args.polygons,
        |l| polygon_from_line(l).map_err(|e| e.to_string()),
        |q| q.slab().is_some(),
        &mut dim,
        out,
        &mut bad,
    )?;
    let read_time = start.elapsed();
    let t0 = Instant::now();
    let (batch, decided) = match detect_batch_counted(
        lookahead,
        &points.items,
        &polygons.items,
        params,
        &Options::default(),
    ) {
        Ok(b) => b,
        // the dimensions and T were checked above: not expected, but said, not hidden
        Err(e) => {
            writeln!(out, "{}", json!({ "error": e.to_string() }))?;
            return Ok(bad + 1);
        }
    };
    let detect_time = t0.elapsed();
    let mut conservative = 0;
    for h in &batch.hits {
        if h.kind == Kind::Conservative {
            conservative += 1;
        }
        let line = json!({
            "point": points.lines[h.point],
            "polygon": polygons.lines[h.polygon],
            "kind": h.kind.name(),
            "method": h.method.name(),
        });
        writeln!(out, "{line}")?;
    }
    if !args.quiet {
        let (n, m) = (points.items.len(), polygons.items.len());
        eprintln!(
            "polyguard detect-batch: {n} points × {m} polygons ({} pairs): {} kept by the broad \
             phase ({} unbounded polygons), {} by the mid phase, {} hits ({conservative} \
             conservative); \
             read {:.1} ms, detect {:.1} ms",
            n as u64 * m as u64,
            batch.candidates,
            batch.unbounded_polygons,
            decided,
            batch.hits.len(),
            read_time.as_secs_f64() * 1e3,
            detect_time.as_secs_f64() * 1e3,
        );
    }
    Ok(bad)
}

/// `--generate N M`: the seeded workload of `polyguard_harness::batch` as the two files.
fn generate(args: &DetectBatchArgs, n: usize, m: usize) -> ExitCode {
    let mix = Mix {
        three_d: args.three_d,
        ..Mix::BENCH
    };
    let w = batch_workload(n, m, args.seed, mix);
    let points = w.points.iter().map(point_json);
    let polygons = w.polygons.iter().map(polygon_json);
    for (path, lines) in [
        (&args.points, points.collect::<Vec<_>>()),
        (&args.polygons, polygons.collect()),
    ] {
        let write = || -> io::Result<()> {
            let mut f = BufWriter::new(fs::File::create(path)?);
            for l in lines {
                writeln!(f, "{l}")?;
            }
            f.flush()
        };
        if let Err(e) = write() {
            eprintln!(
                "polyguard detect-batch: cannot write {}: {e}",
                path.display()
            );
            return ExitCode::from(2);
        }
    }
    if !args.quiet {
        eprintln!(
            "polyguard detect-batch: wrote {n} points to {} and {m} polygons to {}; answer with \
             --lookahead {T} --buff {BUFF} --fac {FAC}",
            args.points.display(),
            args.polygons.display()
        );
    }
    ExitCode::SUCCESS
}

/// A point as its line (docs/batch.md).
pub fn point_json(p: &MovingPoint) -> Value {
    match p.z {
        Some((sz, vz)) => json!({"pos": [p.pos.x, p.pos.y, sz], "vel": [p.vel.x, p.vel.y, vz]}),
        None => json!({"pos": [p.pos.x, p.pos.y], "vel": [p.vel.x, p.vel.y]}),
    }
}

/// A polygon as its line (docs/batch.md); velocities only when it moves.
pub fn polygon_json(q: &MovingPolygon) -> Value {
    let pts = |v: &[polyguard::Vect2]| v.iter().map(|p| json!([p.x, p.y])).collect::<Vec<_>>();
    let mut obj = serde_json::Map::new();
    obj.insert("vertices".into(), pts(q.vertices()).into());
    if q.velocities().iter().any(|v| v.x != 0.0 || v.y != 0.0) {
        obj.insert("velocities".into(), pts(q.velocities()).into());
    }
    if let Some(s) = q.slab() {
        obj.insert("bottom".into(), s.bottom.into());
        obj.insert("top".into(), s.top.into());
        obj.insert("vz".into(), s.vz.into());
    }
    Value::Object(obj)
}
