//! `polyguard bands FILE`: conflict-free course bands (and speed, vertical speed bands)
//! for the point of each case line among its moving polygons (docs/way-out.md).

use std::path::PathBuf;
use std::process::ExitCode;

use polyguard_harness::wayout::answer::{Ask, Command, DEFAULT_UNKNOWN_MAX_DEG};

use super::wayout_common::{parse_positive, parse_separation};

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
some line gave an error, 2 when the run could not start. \
With --earth: encounters of detect-earth (docs/earth-cases.md) with an optional `bands` \
object; course bands in degrees true at the aircraft's speed (the sphere), speed bands in \
knots with `bands.speeds_kn`, each band certified on the Earth against BUFF; answers and \
errors as docs/earth-cases.md, \"Bands\", shows."
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
    /// The picture (`--svg`, `--svg-case`; not with `--earth`).
    #[command(flatten)]
    pub svg: super::wayout_svg::SvgArgs,
    /// Read encounters on the Earth (docs/earth-cases.md, "Bands"): degrees true, knots,
    /// BUFF in nautical miles.
    #[arg(long)]
    pub earth: bool,
    /// With --earth, the model of the Earth: `sphere` (the default; course bands need it)
    /// or `wgs84` (speed bands only).
    #[arg(long, value_enum, default_value_t = super::conflicts::GeodesyArg::Sphere)]
    pub geodesy: super::conflicts::GeodesyArg,
    /// With --earth, the total width of unknown speed bands aimed at, in knots, for
    /// encounters without `bands.unknown_max_kn` (default: the share of the speed range
    /// that --unknown-max-deg is of 360°).
    #[arg(long, value_parser = parse_positive)]
    pub unknown_max_kn: Option<f64>,
}

/// Runs `polyguard bands`.
pub fn run(args: &BandsArgs) -> ExitCode {
    if args.earth {
        if args.svg.svg.is_some() {
            eprintln!("polyguard bands: --svg draws plane cases; it does not take --earth");
            return ExitCode::from(2);
        }
        let ask = super::bands_earth::EarthAsk {
            unknown_max_deg: args.unknown_max_deg,
            speeds_kn: None,
            unknown_max_kn: args.unknown_max_kn,
        };
        return super::bands_earth::run(&args.file, ask, args.geodesy.into());
    }
    let ask = Ask {
        sep: args.sep,
        sep_v: args.sep_v,
        unknown_max_deg: args.unknown_max_deg,
        ..Ask::default()
    };
    super::wayout_svg::run_and_draw("bands", Command::Bands, &args.file, &ask, &args.svg)
}
