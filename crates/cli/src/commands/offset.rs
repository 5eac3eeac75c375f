//! `polyguard offset FILE`: the certified offset (buffer) or inset of the polygon of each
//! case line (docs/way-out.md).

use std::path::PathBuf;
use std::process::ExitCode;

use polyguard_harness::wayout::answer::{Ask, Command, DEFAULT_EPS};

use super::wayout_common::{parse_eps, parse_separation};

/// Arguments of `polyguard offset`.
#[derive(Debug, clap::Args)]
#[command(
    long_about = "The offset of the polygon of each case line (docs/cases.md; docs/way-out.md) \
by D, at `time` (default 0): polygons Q with P ⊕ disc(D) ⊆ Q ⊆ P ⊕ disc(D·(1 + ε)), \
certified; with --inset, pieces inside {x ∈ P : dist(x, ∂P) ≥ D} that contain \
{x ∈ P : dist(x, ∂P) ≥ D·(1 + ε)} (none when P is too thin). Each region is an outer \
ring (counterclockwise) with holes (clockwise). One polygon per case line. Exit 0, 1 \
when some line gave an error, 2 when the run could not start."
)]
pub struct OffsetArgs {
    /// The case file (JSON Lines); standard input when absent or "-".
    pub file: Option<PathBuf>,
    /// D ≥ 0, for cases without `sep`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep: f64,
    /// ε in (0, 1), the relative tolerance, for cases without `eps`.
    #[arg(long, default_value_t = DEFAULT_EPS, value_parser = parse_eps)]
    pub eps: f64,
    /// The inset (the polygon shrunk by D) instead of the offset.
    #[arg(long)]
    pub inset: bool,
    /// The picture (`--svg`, `--svg-case`).
    #[command(flatten)]
    pub svg: super::wayout_svg::SvgArgs,
}

/// Runs `polyguard offset`.
pub fn run(args: &OffsetArgs) -> ExitCode {
    let ask = Ask {
        sep: args.sep,
        eps: args.eps,
        inset: args.inset,
        ..Ask::default()
    };
    super::wayout_svg::run_and_draw("offset", Command::Offset, &args.file, &ask, &args.svg)
}
