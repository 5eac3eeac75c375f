//! `polyguard recover FILE`: the nearest way out of a polygon's D-neighbourhood (or into
//! its D-core, keep-in) for the point of each case line (docs/way-out.md).

use std::path::PathBuf;
use std::process::ExitCode;

use polyguard_harness::case::Fence;
use polyguard_harness::wayout::answer::{Ask, Command};

use super::wayout_common::{parse_fence, parse_separation, run as run_lines};

/// Which implementation answers `recover`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RecoverEngine {
    /// The certified f64 engine: a point certified to meet its condition, with
    /// certified bounds on the minimum distance.
    F64,
    /// The f64 engine's answer plus the exact minimum distance from the oracle (nearest
    /// f64 and exact text) and the exact check of the point.
    Truth,
}

/// Arguments of `polyguard recover`.
#[derive(Debug, clap::Args)]
#[command(
    long_about = "The recovery point of each case line (docs/cases.md; docs/way-out.md): for a \
keep-out polygon the nearest point x to the point's position s with dist(x, P) ≥ D; for \
a keep-in polygon (--fence keep-in or `fence`) the nearest x inside P with \
dist(x, ∂P) ≥ D, or `impossible` when P has no such point. The polygon is taken at \
`time` (default 0). x is certified to meet its condition; `distance` is a certified \
upper bound of |x − s| and the exact minimum lies in [min_lo, distance]. One polygon per \
case line. Exit 0, 1 when some line gave an error, 2 when the run could not start."
)]
pub struct RecoverArgs {
    /// The case file (JSON Lines); standard input when absent or "-".
    pub file: Option<PathBuf>,
    /// D ≥ 0, the separation, for cases without `sep`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep: f64,
    /// keep-out (the default): out of the D-neighbourhood; keep-in: into the D-core.
    /// For cases without `fence`.
    #[arg(long, value_parser = parse_fence)]
    pub fence: Option<Fence>,
    /// Which implementation answers.
    #[arg(long, value_enum, default_value = "f64")]
    pub engine: RecoverEngine,
    /// Also answer with NASA PolyCARP's recovery point (its algorithm, ported; BUFF =
    /// D/100), judged exactly: does it meet the condition, how much farther than the
    /// exact minimum is it.
    #[arg(long)]
    pub polycarp: bool,
}

/// Runs `polyguard recover`.
pub fn run(args: &RecoverArgs) -> ExitCode {
    let ask = Ask {
        sep: args.sep,
        fence: args.fence.unwrap_or_default(),
        truth: args.engine == RecoverEngine::Truth,
        polycarp: args.polycarp,
        ..Ask::default()
    };
    run_lines("recover", Command::Recover, &args.file, &ask)
}
