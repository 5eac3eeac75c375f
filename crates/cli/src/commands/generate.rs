//! `polyguard generate`: random scenarios as in Paper B Section VI.D
//! ([`polyguard_earth::generate`]), seeded with the harness's SplitMix64.

use polyguard_earth::generate::Mix;
use polyguard_harness::gen::{Source, SplitMix};
use std::path::PathBuf;
use std::process::ExitCode;

/// Which objects to generate (the command line's names for [`Mix`]).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum MixArg {
    /// Static areas only.
    Static,
    /// Half areas, half tracks (alternating).
    Mixed,
    /// Tracks only.
    Tracks,
}

impl From<MixArg> for Mix {
    fn from(m: MixArg) -> Mix {
        match m {
            MixArg::Static => Mix::Static,
            MixArg::Mixed => Mix::Mixed,
            MixArg::Tracks => Mix::Tracks,
        }
    }
}

/// Arguments of `polyguard generate`.
#[derive(clap::Args, Debug, Clone)]
pub struct GenerateArgs {
    /// Number of objects.
    #[arg(long)]
    pub objects: usize,
    /// Areas, tracks or both.
    #[arg(long, value_enum, default_value_t = MixArg::Mixed)]
    pub mix: MixArg,
    /// Random seed.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Stretch the box with the number of objects (constant density).
    #[arg(long)]
    pub density_box: bool,
    /// Output file (standard output when absent).
    #[arg(long, short)]
    pub output: Option<PathBuf>,
}

/// Above this many objects in the paper's box (without `--density-box`), `generate` warns:
/// ten times the paper's largest runs (800 objects), the density of no scenario the paper
/// measured, with conflicts growing as the square of the count.
pub const DENSE_OBJECTS: usize = 8_000;

/// Runs `polyguard generate`: each feature is written as it is drawn (memory does not
/// grow with `--objects`); the text is what [`polyguard_earth::scenario::to_geojson`]
/// writes for the whole scenario.
pub fn run(args: &GenerateArgs) -> ExitCode {
    use std::io::Write;
    if !args.density_box && args.objects > DENSE_OBJECTS {
        eprintln!(
            "polyguard generate: warning: {} objects in the paper's 30° × 30° box is {:.0} times \
             the density of its largest runs (800 objects); conflicts grow as the square of \
             the count. --density-box keeps the paper's density.",
            args.objects,
            args.objects as f64 / polyguard_earth::generate::DENSITY_BOX_OBJECTS
        );
    }
    let mut out: Box<dyn Write> = match &args.output {
        Some(p) => match std::fs::File::create(p) {
            Ok(f) => Box::new(std::io::BufWriter::with_capacity(1 << 20, f)),
            Err(e) => {
                eprintln!("polyguard generate: {}: {e}", p.display());
                return ExitCode::FAILURE;
            }
        },
        None => Box::new(std::io::BufWriter::with_capacity(
            1 << 20,
            std::io::stdout().lock(),
        )),
    };
    let (_, bx_lon) = (
        0,
        polyguard_earth::generate::generation_box(args.objects, args.density_box).0,
    );
    // the collection's members in to_geojson's order: type, longitudes (unrolled only),
    // features
    let head = if bx_lon.1 > 180.0 {
        "{\"type\":\"FeatureCollection\",\"longitudes\":\"unrolled\",\"features\":["
    } else {
        "{\"type\":\"FeatureCollection\",\"features\":["
    };
    let mut failed: Option<std::io::Error> = out.write_all(head.as_bytes()).err();
    let mut first = true;
    let mut rng = SplitMix(args.seed);
    let longitudes = polyguard_earth::generate::generate_each(
        args.objects,
        args.mix.into(),
        args.density_box,
        &mut || rng.next_u64(),
        &mut |f| {
            if failed.is_some() {
                return;
            }
            let mut text = if first { String::new() } else { ",".to_owned() };
            first = false;
            text.push_str(
                &polyguard_earth::scenario::feature_geojson(&f, lon_mode(bx_lon)).to_string(),
            );
            failed = out.write_all(text.as_bytes()).err();
        },
    );
    debug_assert_eq!(longitudes, lon_mode(bx_lon));
    let res = match failed {
        Some(e) => Err(e),
        None => out.write_all(b"]}\n").and_then(|()| out.flush()),
    };
    match res {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polyguard generate: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The plane of a scenario generated in a box of these longitudes (past 180° east the
/// unrolled strip, as [`polyguard_earth::generate::generate`] says).
fn lon_mode(bx_lon: (f64, f64)) -> polyguard_earth::scenario::Longitudes {
    if bx_lon.1 > 180.0 {
        polyguard_earth::scenario::Longitudes::Unrolled
    } else {
        polyguard_earth::scenario::Longitudes::Earth
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polyguard_earth::scenario::{Kind, Scenario};
    use polyguard_harness::paper_b::seeded;

    /// The file written feature by feature is the whole scenario's GeoJSON, on the Earth
    /// and on the unrolled strip.
    #[test]
    fn written_as_drawn_is_the_whole_scenario() {
        for (n, density_box) in [(300, false), (6_500, true)] {
            let path = std::env::temp_dir().join(format!(
                "polyguard-generate-{}-{n}.geojson",
                std::process::id()
            ));
            let args = GenerateArgs {
                objects: n,
                mix: MixArg::Mixed,
                seed: 5,
                density_box,
                output: Some(path.clone()),
            };
            assert_eq!(run(&args), ExitCode::SUCCESS);
            let got = std::fs::read_to_string(&path).expect("written");
            let _ = std::fs::remove_file(&path);
            let want =
                polyguard_earth::scenario::to_geojson(&seeded(n, Mix::Mixed, 5, density_box))
                    .to_string()
                    + "\n";
            assert!(got == want, "{n} objects: the streamed file differs");
        }
    }

    #[test]
    fn deterministic_and_in_box() {
        let a = seeded(50, Mix::Mixed, 7, false);
        let b = seeded(50, Mix::Mixed, 7, false);
        assert_eq!(a, b);
        let tracks = a
            .features
            .iter()
            .filter(|f| matches!(f.kind, Kind::Track(_)))
            .count();
        assert_eq!(tracks, 25);
        for f in &a.features {
            if let Kind::Area(ar) = &f.kind {
                assert!((3..=10).contains(&ar.shapes[0].ring.len()));
                let o = polyguard_earth::scenario::objects(&Scenario {
                    features: vec![f.clone()],
                    longitudes: a.longitudes,
                    geodesy: Default::default(),
                });
                // sorted angles with gaps ≤ π: a simple (star-shaped) ring
                assert!(polyguard_earth::conflict::geom::signed_area(&o[0].sweep) > 0.0);
            }
        }
    }
}
