//! `polyguard generate`: random scenarios as in Paper B Section VI.D
//! ([`polyguard_earth::generate`]), seeded with the harness's SplitMix64.

use crate::harness::gen::{Source, SplitMix};
use polyguard_earth::generate::{generate, Mix};
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

/// Paper B §VI.D: a random scenario of `n` objects from `seed` (the same scenario for the
/// same arguments on every machine).
pub fn seeded(
    n: usize,
    mix: Mix,
    seed: u64,
    density_box: bool,
) -> polyguard_earth::scenario::Scenario {
    let mut rng = SplitMix(seed);
    generate(n, mix, density_box, &mut || rng.next_u64())
}

/// Runs `polyguard generate`.
pub fn run(args: &GenerateArgs) -> ExitCode {
    let sc = seeded(args.objects, args.mix.into(), args.seed, args.density_box);
    let text = polyguard_earth::scenario::to_geojson(&sc).to_string();
    let res = match &args.output {
        Some(p) => std::fs::write(p, text + "\n"),
        None => {
            println!("{text}");
            Ok(())
        }
    };
    match res {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polyguard generate: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polyguard_earth::scenario::{Kind, Scenario};

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
                });
                // sorted angles with gaps ≤ π: a simple (star-shaped) ring
                assert!(polyguard_earth::conflict::geom::signed_area(&o[0].sweep) > 0.0);
            }
        }
    }
}
