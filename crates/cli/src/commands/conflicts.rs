//! `polyguard conflicts SCENARIO`: Paper B Algorithm 1 on a scenario GeoJSON
//! (docs/scenario.md), writing the answer JSON of that spec.

use polyguard_earth::analysis::{analyse_into, analyse_with, Analysis, Progress};
use polyguard_earth::geodesy::Geodesy;
use polyguard_earth::picture;
use serde_json::Value;
use std::path::PathBuf;
use std::process::ExitCode;

/// Inputs with at least this many objects get a progress display (on a terminal).
const PROGRESS_MIN_OBJECTS: usize = 10_000;

/// Exit code when some features were rejected (the answer is still written).
const EXIT_BAD_FEATURES: u8 = 1;
/// Exit code when the scenario cannot be read at all.
const EXIT_FATAL: u8 = 2;

/// `--geodesy` of `polyguard conflicts`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum GeodesyArg {
    /// The paper's sphere.
    Sphere,
    /// The WGS84 ellipsoid.
    Wgs84,
}

impl From<GeodesyArg> for Geodesy {
    fn from(g: GeodesyArg) -> Geodesy {
        match g {
            GeodesyArg::Sphere => Geodesy::Sphere,
            GeodesyArg::Wgs84 => Geodesy::Wgs84,
        }
    }
}

/// Arguments of `polyguard conflicts`.
#[derive(clap::Args, Debug, Clone)]
pub struct ConflictsArgs {
    /// Scenario GeoJSON (docs/scenario.md); `-` reads standard input.
    pub scenario: PathBuf,
    /// Write the answer here instead of standard output.
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    /// Draw areas, tracks, swept hulls and conflict regions with their windows, on a
    /// longitude–latitude graticule with a legend (like the paper's Figs 2–5); groups far
    /// apart are drawn in panels of their own, at one scale.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// In the --svg picture, also stage 1's bounding boxes and stage 3's projections of
    /// the regions onto the tracks.
    #[arg(long, requires = "svg")]
    pub svg_detail: bool,
    /// Stage 4 time tolerance in seconds.
    #[arg(long, default_value_t = 1.0)]
    pub tolerance_s: f64,
    /// Pretty-print the answer.
    #[arg(long)]
    pub pretty: bool,
    /// The model of the Earth: `sphere` (the paper's, radius 3440.065 nm; the default) or
    /// `wgs84` (rhumb lines, Mercator and distances on the WGS84 ellipsoid, which
    /// reproduces the paper's printed Example 3 times). docs/scenario.md, "Geodesy".
    #[arg(long, value_enum, default_value_t = GeodesyArg::Sphere)]
    pub geodesy: GeodesyArg,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
    /// Leave out the conflict regions (no `region` key) and the paper's projection windows
    /// (`"projection_windows": null`): the answer of a 10⁶-object scenario is otherwise
    /// gigabytes of coordinates.
    #[arg(long)]
    pub no_regions: bool,
}

/// The spinner shown while the four stages run on a large scenario.
struct Spinner {
    show: bool,
    bar: Option<indicatif::ProgressBar>,
}

impl Progress for Spinner {
    fn stages_start(&mut self, objects: usize) {
        if self.show && objects >= PROGRESS_MIN_OBJECTS {
            let b = indicatif::ProgressBar::new_spinner();
            b.set_message(format!("four stages over {objects} objects"));
            b.enable_steady_tick(std::time::Duration::from_millis(200));
            self.bar = Some(b);
        }
    }
    fn stages_end(&mut self) {
        if let Some(b) = self.bar.take() {
            b.finish_and_clear();
        }
    }
}

/// Runs `polyguard conflicts`.
pub fn run(args: &ConflictsArgs) -> ExitCode {
    let text = if args.scenario.as_os_str() == "-" {
        let mut s = String::new();
        match std::io::Read::read_to_string(&mut std::io::stdin(), &mut s) {
            Ok(_) => s,
            Err(e) => {
                eprintln!("polyguard conflicts: reading standard input: {e}");
                return ExitCode::from(EXIT_FATAL);
            }
        }
    } else {
        match std::fs::read_to_string(&args.scenario) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("polyguard conflicts: {}: {e}", args.scenario.display());
                return ExitCode::from(EXIT_FATAL);
            }
        }
    };
    if !(args.tolerance_s.is_finite() && args.tolerance_s > 0.0) {
        eprintln!("polyguard conflicts: --tolerance-s must be a positive number");
        return ExitCode::from(EXIT_FATAL);
    }
    if args.svg.is_none() && !args.pretty {
        return streamed(args, text);
    }
    let Analysis {
        answer,
        errors,
        warnings,
        scenario: sc,
        objects,
        conflicts,
    } = match analyse_with(
        &text,
        args.tolerance_s / 3600.0,
        !args.no_regions,
        args.geodesy.into(),
        &mut Spinner {
            show: !args.quiet,
            bar: None,
        },
    ) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("polyguard conflicts: {}: {e}", args.scenario.display());
            return ExitCode::from(EXIT_FATAL);
        }
    };
    for w in &warnings {
        eprintln!("polyguard conflicts: warning: {w}");
    }
    for e in &errors {
        eprintln!("polyguard conflicts: {e}");
    }
    let text = if args.pretty {
        serde_json::from_str::<Value>(&answer)
            .and_then(|v| serde_json::to_string_pretty(&v))
            .unwrap_or(answer)
    } else {
        answer
    };
    let mut text = text;
    text.push('\n');
    let written = match &args.output {
        Some(p) => std::fs::write(p, &text),
        // one write: stdout is line-buffered and the answer has a line per conflict
        None => std::io::Write::write_all(&mut std::io::stdout().lock(), text.as_bytes()),
    };
    if let Err(e) = written {
        eprintln!("polyguard conflicts: writing the answer: {e}");
        return ExitCode::from(EXIT_FATAL);
    }
    if let Some(p) = &args.svg {
        if let Err(e) = std::fs::write(
            p,
            picture::svg(
                &sc,
                &objects,
                &conflicts,
                picture::Options {
                    detail: args.svg_detail,
                },
            ),
        ) {
            eprintln!("polyguard conflicts: writing {}: {e}", p.display());
            return ExitCode::from(EXIT_FATAL);
        }
    }
    let code = if errors.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(EXIT_BAD_FEATURES)
    };
    // The process ends right after: freeing millions of small allocations one by one would
    // cost more than the four stages on large inputs, and the OS reclaims them at once.
    std::mem::forget((sc, objects, conflicts));
    code
}

/// The answer written as the pipeline goes, a block of features at a time: memory holds
/// one block's conflicts, not the answer (which may be gigabytes).
fn streamed(args: &ConflictsArgs, text: String) -> ExitCode {
    let mut sink: Box<dyn std::io::Write> = match &args.output {
        Some(p) => match std::fs::File::create(p) {
            Ok(f) => Box::new(std::io::BufWriter::with_capacity(1 << 20, f)),
            Err(e) => {
                eprintln!("polyguard conflicts: {}: {e}", p.display());
                return ExitCode::from(EXIT_FATAL);
            }
        },
        None => Box::new(std::io::BufWriter::with_capacity(
            1 << 20,
            std::io::stdout().lock(),
        )),
    };
    let summary = match analyse_into(
        text,
        args.tolerance_s / 3600.0,
        !args.no_regions,
        args.geodesy.into(),
        &mut sink,
        &mut Spinner {
            show: !args.quiet,
            bar: None,
        },
    ) {
        Ok(Ok(s)) => s,
        Ok(Err(e)) => {
            eprintln!("polyguard conflicts: writing the answer: {e}");
            return ExitCode::from(EXIT_FATAL);
        }
        Err(e) => {
            eprintln!("polyguard conflicts: {}: {e}", args.scenario.display());
            return ExitCode::from(EXIT_FATAL);
        }
    };
    for w in &summary.warnings {
        eprintln!("polyguard conflicts: warning: {w}");
    }
    for e in &summary.errors {
        eprintln!("polyguard conflicts: {e}");
    }
    if summary.errors.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(EXIT_BAD_FEATURES)
    }
}
