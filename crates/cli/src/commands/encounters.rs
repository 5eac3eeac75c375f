//! `polyguard encounters MOVERS AREAS`: every mover (timed fixes: CSV, or MF-JSON
//! trajectories) against every area (GeoJSON polygons, MF-JSON moving polygons), one JSON
//! line per pair that meets, with the certified spans of inside and near
//! (docs/moving-features.md).

use polyguard_earth::moving::answer::encounter_json;
use polyguard_earth::moving::broad::{encounters_of, Areas};
use polyguard_earth::moving::encounter::Options;
use polyguard_earth::moving::model::{Area, Trajectory};
use polyguard_earth::moving::{fixes_csv, mfjson};
use rayon::prelude::*;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use super::conflicts::GeodesyArg;
use super::encounters_svg;

/// Exit code when some features or rows were rejected (the others are answered).
const EXIT_BAD_INPUT: u8 = 1;
/// Exit code when an input cannot be read at all.
const EXIT_FATAL: u8 = 2;
/// Movers answered together (in parallel) before their lines are written: bounds the
/// memory held by answers waiting to be written.
const CHUNK: usize = 256;

/// Arguments of `polyguard encounters`.
#[derive(clap::Args, Debug, Clone)]
pub struct EncountersArgs {
    /// The movers: a CSV of fixes (`.csv`: timestamp, icao24, latitude, longitude, and
    /// optionally callsign, altitude, flight_id) or MF-JSON trajectories / MovingPoints
    /// (docs/moving-features.md, "Formats"); `-` reads standard input (MF-JSON).
    pub movers: PathBuf,
    /// The areas: GeoJSON Polygons / MultiPolygons (optional `floor_ft`, `ceiling_ft`) or
    /// MF-JSON MovingPolygons, as a FeatureCollection or JSON Lines.
    pub areas: PathBuf,
    /// D, nautical miles: "near" means within D horizontally (0: near is inside).
    #[arg(long, default_value_t = 0.0)]
    pub sep: f64,
    /// H, feet: "near" also means within H of the area's floor–ceiling slab.
    #[arg(long = "sep-v", default_value_t = 0.0)]
    pub sep_v: f64,
    /// Fixes more than this many seconds apart are not joined: the flight splits there
    /// and the gap is reported.
    #[arg(long = "max-gap", default_value_t = 60.0)]
    pub max_gap: f64,
    /// The model of the Earth: `sphere` (radius 3440.065 nm) or `wgs84`.
    #[arg(long, value_enum, default_value_t = GeodesyArg::Sphere)]
    pub geodesy: GeodesyArg,
    /// Write the answer here instead of standard output.
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    /// No summary on standard error.
    #[arg(long)]
    pub quiet: bool,
    /// Also draw a picture to FILE (SVG) of one mover (`--svg-mover`), one area
    /// (`--svg-area`), or without either the first mover that meets an area: a map on
    /// the Mercator plane (tracks, areas, the stretches inside drawn thick and near as a
    /// halo, possible ones dashed, gaps dotted, each first loss of separation ringed in
    /// red) and a timeline in UTC, one row per pair met in the order of their first loss
    /// of separation. The answer is still written (standard output or --output).
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// With --svg: draw the mover of this id (or, when no id matches, this callsign) and
    /// every area it meets, one timeline row per area. An unknown ID is refused (exit 2)
    /// before any answer, naming some ids there are.
    #[arg(long = "svg-mover", value_name = "ID", requires = "svg")]
    pub svg_mover: Option<String>,
    /// With --svg: draw the area of this id and every mover that meets it, one timeline
    /// row per mover (the first 40; the rest are counted). An unknown ID is refused
    /// (exit 2) before any answer, naming some ids there are.
    #[arg(
        long = "svg-area",
        value_name = "ID",
        requires = "svg",
        conflicts_with = "svg_mover"
    )]
    pub svg_area: Option<String>,
}

impl EncountersArgs {
    /// What the picture flags ask for.
    fn svg_ask(&self) -> encounters_svg::Ask<'_> {
        encounters_svg::Ask {
            file: self.svg.as_deref(),
            mover: self.svg_mover.as_deref(),
            area: self.svg_area.as_deref(),
        }
    }
}

/// The text of `path` (`-`: standard input), or a message.
fn read_text(path: &Path) -> Result<String, String> {
    if path == Path::new("-") {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut std::io::stdin(), &mut s)
            .map_err(|e| format!("standard input: {e}"))?;
        Ok(s)
    } else {
        std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
    }
}

/// What the inputs gave: movers, areas, and the messages of what was rejected.
#[derive(Default)]
struct Inputs {
    movers: Vec<Trajectory>,
    areas: Vec<Area>,
    errors: Vec<String>,
    warnings: Vec<String>,
}

/// Reads one input (CSV by its extension, else MF-JSON) into `inp`; `want_movers` says
/// which kind of feature the argument is for (the other kind is an error naming it).
fn read_input(path: &Path, want_movers: bool, inp: &mut Inputs) -> Result<(), String> {
    let name = path.display().to_string();
    let is_csv = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
    if is_csv {
        if !want_movers {
            return Err(format!("{name}: a CSV holds fixes of movers, not areas"));
        }
        // Streamed: a day of fixes is read row by row, never held as text.
        let file = std::fs::File::open(path).map_err(|e| format!("{name}: {e}"))?;
        let r = fixes_csv::read_from(std::io::BufReader::with_capacity(1 << 20, file))
            .map_err(|e| format!("{name}: {e}"))?;
        inp.movers.extend(r.trajectories);
        inp.errors
            .extend(r.errors.iter().map(|e| format!("{name}: {e}")));
        inp.warnings
            .extend(r.warnings.iter().map(|w| format!("{name}: {w}")));
        return Ok(());
    }
    let text = read_text(path)?;
    let r = mfjson::read(&text).map_err(|e| format!("{name}: {e}"))?;
    inp.warnings
        .extend(r.warnings.iter().map(|w| format!("{name}: {w}")));
    for (i, item) in r.items.into_iter().enumerate() {
        match item {
            Ok(mfjson::Item::Mover(t)) if want_movers => inp.movers.push(t),
            Ok(mfjson::Item::Area(a)) if !want_movers => inp.areas.push(a),
            Ok(mfjson::Item::Mover(t)) => inp.errors.push(format!(
                "{name}: feature {i} ({}) is a mover; AREAS takes areas",
                t.id
            )),
            Ok(mfjson::Item::Area(a)) => inp.errors.push(format!(
                "{name}: feature {i} ({}) is an area; MOVERS takes movers",
                a.id
            )),
            Err(e) => inp.errors.push(format!("{name}: {e}")),
        }
    }
    Ok(())
}

/// Answers every mover in chunks (each chunk in parallel, its lines written in input
/// order): the counts of pairs met and of inside and near spans, or `None` when the
/// output cannot be written. A mover's error goes to `inp.errors`.
fn answer(
    inp: &mut Inputs,
    areas: &Areas,
    opts: &Options,
    out: &mut dyn Write,
) -> Option<(usize, usize, usize)> {
    let (mut pairs, mut spans_inside, mut spans_near) = (0usize, 0usize, 0usize);
    let mut errors = Vec::new();
    for chunk in inp.movers.chunks(CHUNK) {
        let answers: Vec<_> = chunk
            .par_iter()
            .map(|t| encounters_of(t, areas, opts))
            .collect();
        for (t, ans) in chunk.iter().zip(answers) {
            match ans {
                Ok(list) => {
                    for e in &list {
                        pairs += 1;
                        spans_inside += e.inside.len();
                        spans_near += e.near.len();
                        writeln!(out, "{}", encounter_json(e)).ok()?;
                    }
                }
                Err(e) => errors.push(format!("mover {} {e}", t.id)),
            }
        }
    }
    inp.errors.extend(errors);
    Some((pairs, spans_inside, spans_near))
}

/// Runs `polyguard encounters`.
pub fn run(a: &EncountersArgs) -> ExitCode {
    let started = Instant::now();
    for (name, x) in [
        ("--sep", a.sep),
        ("--sep-v", a.sep_v),
        ("--max-gap", a.max_gap),
    ] {
        if !x.is_finite() || x < 0.0 {
            eprintln!("polyguard encounters: {name} {x}: must be a finite number ≥ 0");
            return ExitCode::from(EXIT_FATAL);
        }
    }
    let mut inp = Inputs::default();
    for (path, movers) in [(&a.movers, true), (&a.areas, false)] {
        if let Err(e) = read_input(path, movers, &mut inp) {
            eprintln!("polyguard encounters: {e}");
            return ExitCode::from(EXIT_FATAL);
        }
    }
    let opts = Options {
        sep_nm: a.sep,
        sep_v_ft: a.sep_v,
        max_gap_s: a.max_gap,
        geodesy: a.geodesy.into(),
    };
    // an unknown id to draw stops before any answer
    if let Err(e) = encounters_svg::focus(a.svg_ask(), &inp.movers, &inp.areas) {
        eprintln!("polyguard encounters: {e}");
        return ExitCode::from(EXIT_FATAL);
    }
    let (areas, area_errors) = Areas::new(&inp.areas, opts.geodesy);
    inp.errors
        .extend(area_errors.iter().map(|e| format!("area {e}")));
    let read_s = started.elapsed().as_secs_f64();

    let mut out: Box<dyn Write> = match &a.output {
        Some(p) => match std::fs::File::create(p) {
            Ok(f) => Box::new(std::io::BufWriter::new(f)),
            Err(e) => {
                eprintln!("polyguard encounters: {}: {e}", p.display());
                return ExitCode::from(EXIT_FATAL);
            }
        },
        None => Box::new(std::io::BufWriter::new(std::io::stdout().lock())),
    };
    let Some((pairs, spans_inside, spans_near)) = answer(&mut inp, &areas, &opts, &mut out) else {
        return ExitCode::from(EXIT_FATAL);
    };
    if out.flush().is_err() {
        return ExitCode::from(EXIT_FATAL);
    }
    if let Err(e) = encounters_svg::write(a.svg_ask(), &inp.movers, &inp.areas, &areas, &opts) {
        eprintln!("polyguard encounters: --svg: {e}");
        return ExitCode::from(EXIT_FATAL);
    }
    for w in &inp.warnings {
        eprintln!("warning: {w}");
    }
    for e in &inp.errors {
        eprintln!("error: {e}");
    }
    if !a.quiet {
        let gaps = inp
            .movers
            .iter()
            .map(|t| {
                t.fixes
                    .windows(2)
                    .filter(|w| w[1].t - w[0].t > a.max_gap)
                    .count()
            })
            .sum::<usize>();
        let fixes: usize = inp.movers.iter().map(|t| t.fixes.len()).sum();
        eprintln!(
            "{} movers ({} fixes), {} areas: {} pairs met, {} inside and {} near spans, {} \
             gaps; {} errors, {} warnings; {:.3} s ({:.3} s reading)",
            inp.movers.len(),
            fixes,
            areas.len(),
            pairs,
            spans_inside,
            spans_near,
            gaps,
            inp.errors.len(),
            inp.warnings.len(),
            started.elapsed().as_secs_f64(),
            read_s,
        );
    }
    if inp.errors.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(EXIT_BAD_INPUT)
    }
}
