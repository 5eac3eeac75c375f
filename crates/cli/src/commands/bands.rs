//! `polyguard bands FILE`: conflict-free course bands (and speed, vertical speed bands)
//! for the point of each case line among its moving polygons (docs/way-out.md).

use std::path::PathBuf;
use std::process::ExitCode;

use polyguard_harness::wayout::answer::{Ask, Command, DEFAULT_UNKNOWN_MAX_DEG};

use super::wayout_common::{parse_positive, parse_separation, run as run_lines};

/// Arguments of `polyguard bands`.
#[derive(Debug, clap::Args)]
#[command(
    long_about = "Conflict-free bands for the point of each case line (docs/cases.md, extended by \
`polygons` and `bands`: docs/way-out.md) among its moving polygons over [0, lookahead]. \
A course band is clear (certified: no course in it comes within D, and H in 3D, of any \
polygon), conflict (certified: every course in it does) or unknown. Courses are degrees \
clockwise from +y (north), at the point's current speed |vel|. `current` is the verdict \
of the point's own velocity. With `bands.speeds` the speed bands at the current course; \
with `bands.vertical_speeds` (3D) the vertical speed bands. One JSON answer line per \
case line; errors as {\"id\", \"error\": {\"field\", \"line\", \"message\"}}; exit 0, 1 when \
some line gave an error, 2 when the run could not start."
)]
pub struct BandsArgs {
    /// The case file (JSON Lines); standard input when absent or "-".
    pub file: Option<PathBuf>,
    /// D ≥ 0, the horizontal separation, for cases without `sep`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep: f64,
    /// H ≥ 0, the vertical separation (3D), for cases without `sep_v`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep_v: f64,
    /// The total width of unknown course bands aimed at, in degrees, for cases without
    /// `bands.unknown_max_deg` (speed bands aim at the same share of their range).
    #[arg(long, default_value_t = DEFAULT_UNKNOWN_MAX_DEG, value_parser = parse_positive)]
    pub unknown_max_deg: f64,
    /// Also draw one case's course bands as a compass rose into this SVG file (the first
    /// valid case, or `--svg-case`); needs FILE, not standard input.
    #[arg(long, value_name = "OUT.svg")]
    pub svg: Option<PathBuf>,
    /// The id of the case to draw with `--svg`.
    #[arg(long, value_name = "ID", requires = "svg")]
    pub svg_case: Option<String>,
}

/// Runs `polyguard bands`.
pub fn run(args: &BandsArgs) -> ExitCode {
    let ask = Ask {
        sep: args.sep,
        sep_v: args.sep_v,
        unknown_max_deg: args.unknown_max_deg,
        ..Ask::default()
    };
    let file = args
        .file
        .as_deref()
        .filter(|f| *f != std::path::Path::new("-"));
    if args.svg.is_some() && file.is_none() {
        eprintln!("polyguard bands: --svg needs a case FILE (standard input is read once)");
        return ExitCode::from(2);
    }
    let status = run_lines("bands", Command::Bands, &args.file, &ask);
    if let (Some(out), Some(file)) = (&args.svg, file) {
        if let Err(e) = super::wayout_svg::write_bands(file, args.svg_case.as_deref(), &ask, out) {
            eprintln!("polyguard bands: --svg: {e}");
            return ExitCode::from(2);
        }
    }
    status
}
