//! `polyguard assure`: a seeded safety-assurance run of the f64 engine against paper A
//! in exact arithmetic and the exact ground truth, on boundary-biased cases.

use std::collections::BTreeMap;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use polyguard_harness::case::RawCase;
use polyguard_harness::classify::{check_contract, compare_as, Class, Hunted, Verdict};
use polyguard_harness::gen::{any_case_in, bucket, Ends, Space, SplitMix};
use polyguard_harness::minimise::minimise;
use polyguard_harness::report::{Kept, Report};
use polyguard_harness::svg::{picture, Picture};

use polyguard_harness::intervals::report::IntervalReport;
use polyguard_harness::moving::report::MovingReport;

use super::assure_common::{keep_lowest, merge_reports, write_report, CampaignProgress};

pub use polyguard_harness::report::KEEP_PER_CLASS;

/// Arguments of `polyguard assure`.
#[derive(Debug, clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct AssureArgs {
    /// `assure merge`: add shard reports instead of running cases.
    #[command(subcommand)]
    pub merge: Option<MergeCommand>,
    /// How many cases (the default takes about a minute on 2 cores).
    #[arg(long, default_value_t = 60_000)]
    pub cases: u64,
    /// The campaign's seed: case k is the same for every thread count and shard.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Where report.json and the counterexamples go.
    #[arg(long, default_value = "assure-out")]
    pub out: PathBuf,
    /// Run only shard i of N ("i/N", 0-based): case k belongs to shard k mod N.
    #[arg(long, value_parser = parse_shard)]
    pub shard: Option<(u64, u64)>,
    /// No progress on standard error: without it, a bar on a terminal, else a line at
    /// every tenth of the cases and at least every 30 s.
    #[arg(long)]
    pub quiet: bool,
    /// Check only the engine's contract (paper A without rounding says yes ⇒ the engine
    /// says yes), for long campaigns: no truth, no classes, and paper A in exact
    /// arithmetic only where the engine does not certify a yes.
    #[arg(long)]
    pub contract: bool,
    /// The engine to judge. Paper A's: `f64` (the certified engine, the product), `plain`
    /// (the uncertified transcription: the canary, whose missed entries the hunt must
    /// catch) or `shifted-time` (the entry-time check's canary); paper B's (`--paper b`):
    /// `pipeline` or `sampled` (its canary).
    #[arg(long, value_enum, default_value_t = EngineArg::F64)]
    pub engine: EngineArg,
    /// Aim the campaign at part of the scale space: `path=1e3..1e7,buff=1e-12..1e-9`
    /// (relative path and BUFF per polygon size, as powers of ten; either may be left
    /// out), and `ends=all` (or `tiny`, `huge`) to move every case that can be moved to an
    /// end of the float range (BUFF subnormal, or the largest length near 2^900..2^1000)
    /// instead of one in eight, or `ends=none` to keep every case in the normal range.
    /// `--contract --aim ends=none` and `--contract --aim ends=all` give the rate of
    /// conservative answers in each. The default is the whole space (path 1e-3..1e7,
    /// buff 1e-12..1e0, ends=eighth).
    #[arg(long, value_parser = parse_aim)]
    pub aim: Option<Space>,
    /// The paper to hunt in: `a` (point vs polygon, the default) or `b` (interference of
    /// areas and tracks on the Earth: docs/assurance.md, "Paper B"). With `b`, `--engine`
    /// is `pipeline` (the default) or `sampled` (the canary), and `--contract` and `--aim`
    /// are refused (paper A's). With `moving` (flights against static and keyframed areas:
    /// docs/assurance.md, "Moving features"), `--canary fixes-only` judges the canary.
    /// With `wayout` (bands, recovery points, offsets: docs/assurance.md, "The way
    /// out"), `--canary sampled-bands` or `bisector-offset` judges a canary.
    #[arg(long, value_enum, default_value_t = PaperArg::A)]
    pub paper: PaperArg,
    /// Hunt the certified intervals (inside, near_D, breach_D: docs/cases.md) and keep-in
    /// exit detection against the oracle's exact algebraic truth instead of paper A's
    /// detection (docs/assurance.md, "Intervals"). `--engine` is then `f64` or one of the
    /// canaries `shifted-end`, `drop-second`, `flat-exit`.
    #[arg(long, conflicts_with = "contract")]
    pub intervals: bool,
    /// A canary of `--paper moving`: `fixes-only` decides the relations at the fix
    /// times alone (class `moving_missed` on cells sweeping over the mover and legs
    /// cutting a corner between fixes). Of `--paper wayout`: `sampled-bands`
    /// (`wrong_clear`) or `bisector-offset` (`offset_misses_buffer`).
    #[arg(long, value_enum)]
    pub canary: Option<CanaryArg>,
}

/// `--canary` of `polyguard assure --paper moving` and `--paper wayout`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum CanaryArg {
    /// The relations decided at the fix times alone (`--paper moving`).
    FixesOnly,
    /// Course bands sampled every 10° and painted between samples without the margin
    /// (`--paper wayout`: must report `wrong_clear`).
    SampledBands,
    /// Offsets by a PolyCARP-style bisector expansion (`--paper wayout`: must report
    /// `offset_misses_buffer`).
    BisectorOffset,
}

/// `--paper` of `polyguard assure`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PaperArg {
    /// Paper A (Narkawicz & Hagen).
    A,
    /// Paper B (Bienkowski et al.).
    B,
    /// Moving features: whole flights against static and keyframed areas, the planar
    /// engine's certified spans against the exact truth (docs/assurance.md, "Moving
    /// features").
    Moving,
    /// The way out: bands, recovery points, offsets and insets against the exact truth
    /// (docs/assurance.md, "The way out").
    Wayout,
}

/// `--aim path=1eA..1eB,buff=1eC..1eD,ends=E` → the narrowed scale space.
fn parse_aim(s: &str) -> Result<Space, String> {
    let (mut path, mut buff) = (Space::FULL.path, Space::FULL.buff);
    let mut ends = Ends::Eighth;
    for part in s.split(',') {
        let (key, range) = part.split_once('=').ok_or_else(|| {
            format!(
                "{part:?}: expected path=1eA..1eB, buff=1eC..1eD or ends=all|tiny|huge|none|eighth"
            )
        })?;
        if key.trim() == "ends" {
            ends = Ends::from_name(range.trim()).ok_or_else(|| {
                format!("ends: {range:?} is not one of eighth, all, tiny, huge, none")
            })?;
            continue;
        }
        let (lo, hi) = range
            .split_once("..")
            .ok_or_else(|| format!("{part:?}: expected a range lo..hi, e.g. 1e3..1e5"))?;
        let exp = |x: &str| -> Result<f64, String> {
            let v: f64 = x
                .trim()
                .parse()
                .map_err(|_| format!("{key}: {x:?} is not a number"))?;
            if v > 0.0 && v.is_finite() {
                Ok(v.log10())
            } else {
                Err(format!("{key}: {x:?} must be a positive number"))
            }
        };
        let r = (exp(lo)?, exp(hi)?);
        match key.trim() {
            "path" => path = r,
            "buff" => buff = r,
            other => return Err(format!("unknown scale {other:?}: use path, buff or ends")),
        }
    }
    Ok(Space::aimed(path, buff)?.with_ends(ends))
}

/// `--engine` of `polyguard assure`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// The certified engine.
    F64,
    /// The plain f64 transcription of paper A.
    Plain,
    /// Paper B's four stages as shipped (`--paper b`; the default there).
    Pipeline,
    /// Paper B's canary: meetings sampled once a minute (`--paper b`).
    Sampled,
    /// The canary of the entry-time check: the certified engine with every entry-time
    /// enclosure moved right by two resolution steps (T·2⁻³⁶ each), so that a crossing's
    /// exact entry time falls before it (class `time_outside`).
    ShiftedTime,
    /// The canary of `--intervals`' end check: every span's end enclosure moved right
    /// past itself (class `end_outside`).
    ShiftedEnd,
    /// The canary of `--intervals`' coverage check: the second span of every relation
    /// dropped (class `interval_missed`).
    DropSecond,
    /// The canary of `--intervals`' exit check: exit detection blind to the slab (class
    /// `exit_missed` on fences left through the floor or ceiling).
    FlatExit,
}

impl From<EngineArg> for Hunted {
    fn from(e: EngineArg) -> Hunted {
        match e {
            EngineArg::F64
            | EngineArg::Pipeline
            | EngineArg::Sampled
            | EngineArg::ShiftedEnd
            | EngineArg::DropSecond
            | EngineArg::FlatExit => Hunted::Certified,
            EngineArg::Plain => Hunted::Plain,
            EngineArg::ShiftedTime => Hunted::ShiftedTime,
        }
    }
}

/// `polyguard assure merge`.
#[derive(Debug, clap::Subcommand)]
pub enum MergeCommand {
    /// Join the report.json files of the shards of one campaign exactly, with their
    /// counterexample files. Reports of different seeds, campaign sizes, shard counts or
    /// engines (for paper A also scale spaces, and `--contract` runs beside classifying
    /// ones), a shard given twice, or a missing shard (without --partial) are refused
    /// (exit 2).
    Merge {
        /// The shards' report.json files.
        #[arg(required = true)]
        reports: Vec<PathBuf>,
        /// Where the merged report.json and the counterexamples go.
        #[arg(long, default_value = "assure-merged")]
        out: PathBuf,
        /// Merge even though shards of the campaign are missing; the report lists them
        /// and the summary says PARTIAL.
        #[arg(long)]
        partial: bool,
    },
    /// Print a report's coverage grid for some generator modes, as counts or as the
    /// rate of one class per scale bucket.
    Coverage {
        /// A report.json (of a run or a merge).
        report: PathBuf,
        /// Only the modes whose name starts with this (e.g. `edge_buff`, `free+long`).
        #[arg(long)]
        mode: Option<String>,
        /// Show the percentage of this class per bucket instead of the case counts
        /// (e.g. `false_alarm_in_band`).
        #[arg(long, value_parser = parse_class)]
        class: Option<Class>,
    },
}

fn parse_class(s: &str) -> Result<Class, String> {
    Class::ALL
        .into_iter()
        .find(|c| c.name() == s)
        .ok_or_else(|| {
            let names: Vec<&str> = Class::ALL.iter().map(|c| c.name()).collect();
            format!("unknown class {s:?}; one of {}", names.join(", "))
        })
}

/// `polyguard assure coverage`.
fn coverage(path: &Path, mode: Option<&str>, class: Option<Class>) -> ExitCode {
    let report = match fs::read_to_string(path)
        .map_err(|e| e.to_string())
        .and_then(|t| Report::from_json(&t))
    {
        Ok(r) => r,
        Err(e) => {
            eprintln!("polyguard assure coverage: {}: {e}", path.display());
            return ExitCode::from(2);
        }
    };
    match report.coverage_view(mode, class) {
        Some(grid) => {
            let mut stdout = std::io::stdout().lock();
            let _ = stdout.write_all(grid.as_bytes());
            ExitCode::SUCCESS
        }
        None => {
            eprintln!(
                "polyguard assure coverage: no mode starts with {:?}; the report has: {}",
                mode.unwrap_or(""),
                report.coverage_modes().join(", ")
            );
            ExitCode::from(2)
        }
    }
}

fn parse_shard(s: &str) -> Result<(u64, u64), String> {
    let (i, n) = s.split_once('/').ok_or("expected i/N, e.g. 0/4")?;
    let i: u64 = i
        .trim()
        .parse()
        .map_err(|_| format!("shard index {i:?} is not a number"))?;
    let n: u64 = n
        .trim()
        .parse()
        .map_err(|_| format!("shard count {n:?} is not a number"))?;
    if n == 0 || i >= n {
        return Err(format!("shard {i}/{n}: need 0 ≤ i < N"));
    }
    Ok((i, n))
}

/// The generator's seed for case k of a campaign.
fn case_seed(seed: u64, k: u64) -> u64 {
    let mut m = SplitMix(seed ^ k.wrapping_mul(0xD1B5_4A32_D192_ED03));
    polyguard_harness::gen::Source::next_u64(&mut m)
}

/// Case k of a campaign drawn from `space`, with its generator mode.
pub fn campaign_case(seed: u64, k: u64, space: &Space) -> (RawCase, &'static str) {
    let mut src = SplitMix(case_seed(seed, k));
    let drawn = any_case_in(&mut src, space);
    let name = drawn.name();
    (drawn.raw, name)
}

/// Every class but agreement keeps its first [`KEEP_PER_CLASS`] cases.
fn is_kept_class(c: Class) -> bool {
    c != Class::Agree
}

fn write_counterexample(
    dir: &Path,
    k: u64,
    v: &Verdict,
    raw: &RawCase,
    mode: &str,
    hunted: Hunted,
) -> std::io::Result<Kept> {
    let small = minimise(raw, v.class, hunted);
    // The minimised case keeps the class; its own answers go in the file and the picture.
    let w = compare_as(&small, hunted).unwrap_or_else(|_| v.clone());
    let stem = format!("{}-{k}", v.class.name());
    let case_file = format!("counterexamples/{stem}.jsonl");
    let svg_file = format!("counterexamples/{stem}.svg");
    fs::create_dir_all(dir.join("counterexamples"))?;
    let extra = [
        ("class", serde_json::Value::from(w.class.name())),
        ("function", w.method.name().into()),
        ("mode", mode.into()),
        ("engine", w.engine.into()),
        ("paper_exact", w.paper.into()),
        (
            "truth",
            w.truth
                .map(serde_json::Value::from)
                .unwrap_or(serde_json::Value::Null),
        ),
    ];
    fs::write(
        dir.join(&case_file),
        small.to_json_line(&stem, &extra) + "\n",
    )?;
    fs::write(dir.join(&svg_file), draw(&small, &w, mode, hunted))?;
    Ok(Kept {
        index: k,
        class: v.class,
        method: v.method.name().into(),
        mode: mode.into(),
        case_file,
        svg_file,
    })
}

/// The picture of a kept case from its own verdict `w`.
fn draw(small: &RawCase, w: &Verdict, mode: &str, hunted: Hunted) -> String {
    let title = format!("{} in {} ({mode})", w.class.name(), w.method.name());
    let pic = Picture {
        title: &title,
        engine: w.engine,
        engine_name: hunted.name(),
        paper: w.paper,
        truth: w.truth,
        entry_time: w.entry_time.as_deref().and_then(|t| t.parse::<f64>().ok()),
        entry: match w.entry.enclosure() {
            None => vec![format!("entry ({}): never", hunted.name())],
            Some((lo, hi)) => vec![
                format!("entry ({}): {}", hunted.name(), w.entry.name()),
                format!("in [{lo:.10e}, {hi:.10e}]"),
            ],
        },
    };
    picture(small, &pic)
}

/// Draws again the picture of a kept case from its case file (a long campaign filed in
/// a repository keeps its shards' case files but not their pictures: see
/// evidence/README.md). The case is answered again by the same engine.
fn redraw(case_file: &Path, mode: &str, hunted: Hunted) -> Result<String, String> {
    let text = fs::read_to_string(case_file).map_err(|e| e.to_string())?;
    let line = text.lines().next().unwrap_or_default();
    let case = polyguard_harness::case::parse_line(line, 1)
        .case
        .map_err(|e| e.to_string())?;
    let small = RawCase::from_api(&case);
    let w = compare_as(&small, hunted).map_err(|e| format!("{e:?}"))?;
    Ok(draw(&small, &w, mode, hunted))
}

/// Runs `polyguard assure`.
pub fn run(args: &AssureArgs) -> ExitCode {
    match &args.merge {
        Some(MergeCommand::Merge {
            reports,
            out,
            partial,
        }) => return merge(reports, out, *partial),
        Some(MergeCommand::Coverage {
            report,
            mode,
            class,
        }) => return coverage(report, mode.as_deref(), *class),
        None => {}
    }
    if args.paper == PaperArg::Moving {
        return run_moving(args);
    }
    if args.paper == PaperArg::Wayout {
        return run_wayout(args);
    }
    if args.canary.is_some() {
        eprintln!(
            "polyguard assure: --canary is a canary of --paper moving or --paper wayout: add one"
        );
        return ExitCode::from(2);
    }
    if args.paper == PaperArg::B {
        return run_paper_b(args);
    }
    if args.intervals {
        return run_intervals(args);
    }
    let hunted = match paper_a_engine(args) {
        Ok(h) => h,
        Err(code) => return code,
    };
    if let Err(e) = fs::create_dir_all(&args.out) {
        eprintln!(
            "polyguard assure: cannot create {}: {e}",
            args.out.display()
        );
        return ExitCode::from(2);
    }
    let (shard_i, shard_n) = args.shard.unwrap_or((0, 1));
    let campaign = Campaign {
        seed: args.seed,
        shard_i,
        shard_n,
        space: args.aim.unwrap_or_default(),
        contract: args.contract,
        hunted,
    };
    let mine = polyguard_harness::report::shard_size(args.cases, shard_i, shard_n);
    let progress = CampaignProgress::new(mine, args.quiet);
    let start = Instant::now();
    let (mut report, found) = run_cases(&campaign, mine, threads(args), &progress);
    progress.finish();
    report.shards = vec![format!("{shard_i}/{shard_n}")];
    report.campaign_cases = args.cases;
    report.contract_only = args.contract;
    report.engine = hunted.name().into();
    report.space = campaign.space.label();
    report.wall_seconds = start.elapsed().as_secs_f64();
    for (k, v, raw, mode) in &found {
        match write_counterexample(&args.out, *k, v, raw, mode, hunted) {
            Ok(kept) => report.kept.push(kept),
            Err(e) => eprintln!("polyguard assure: cannot write counterexample {k}: {e}"),
        }
    }
    finish(&report, &args.out)
}

/// The engine a paper-A campaign judges, or exit 2 when `--engine` (or `--contract`
/// with it) is not one of paper A's.
fn paper_a_engine(args: &AssureArgs) -> Result<Hunted, ExitCode> {
    if matches!(args.engine, EngineArg::Pipeline | EngineArg::Sampled) {
        eprintln!(
            "polyguard assure: --engine {} is paper B's: add --paper b (paper A's engines are f64, plain and shifted-time)",
            if args.engine == EngineArg::Pipeline { "pipeline" } else { "sampled" }
        );
        return Err(ExitCode::from(2));
    }
    if matches!(
        args.engine,
        EngineArg::ShiftedEnd | EngineArg::DropSecond | EngineArg::FlatExit
    ) {
        eprintln!("polyguard assure: --engine shifted-end, drop-second and flat-exit are canaries of --intervals: add --intervals");
        return Err(ExitCode::from(2));
    }
    let hunted = Hunted::from(args.engine);
    if args.contract && hunted != Hunted::Certified {
        eprintln!(
            "polyguard assure: --contract judges the certified engine (and counts the plain one's breaches as its canary); drop --engine {}",
            hunted.name()
        );
        return Err(ExitCode::from(2));
    }
    Ok(hunted)
}

/// What a paper-A campaign draws and judges: case k of `seed` from `space`, for the k of
/// shard i of N (k mod N = i), with the full classification or the contract alone.
struct Campaign {
    seed: u64,
    shard_i: u64,
    shard_n: u64,
    space: Space,
    contract: bool,
    hunted: Hunted,
}

/// A case kept for its class: its index, verdict, the case and its generator mode.
type Found = (u64, Verdict, RawCase, &'static str);

/// Runs the shard's `mine` cases on `threads` threads: the counts (seed and shard not
/// yet filled in), and the cases kept per class, by index.
fn run_cases(
    c: &Campaign,
    mine: u64,
    threads: usize,
    progress: &CampaignProgress,
) -> (Report, Vec<Found>) {
    let next = AtomicU64::new(0);
    let report = Mutex::new(Report {
        seed: c.seed,
        ..Default::default()
    });
    let interesting: Mutex<Vec<Found>> = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                let mut local = Report::default();
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    if j >= mine {
                        break;
                    }
                    let failed = one_case(c, j * c.shard_n + c.shard_i, &mut local, &interesting);
                    progress.inc(failed);
                }
                if let Ok(mut r) = report.lock() {
                    r.absorb(&local);
                }
            });
        }
    });
    let report = report.into_inner().unwrap_or_default();
    let mut found = interesting.into_inner().unwrap_or_default();
    found.sort_by_key(|(k, _, _, _)| *k);
    (report, found)
}

/// Draws and judges case `k` into `local` (a rejected case is said and counted), keeping
/// it in `interesting` when its class is kept; whether it is a failure of the campaign.
fn one_case(c: &Campaign, k: u64, local: &mut Report, interesting: &Mutex<Vec<Found>>) -> bool {
    let (raw, mode) = campaign_case(c.seed, k, &c.space);
    let judged = if c.contract {
        check_contract(&raw).map(|v| {
            local.add_contract(&v);
            v.is_breach()
        })
    } else {
        compare_as(&raw, c.hunted).map(|v| {
            local.add(&v, mode, bucket(&raw));
            let failed = v.is_failure();
            if is_kept_class(v.class) {
                if let Ok(mut g) = interesting.lock() {
                    keep_lowest(
                        &mut g,
                        (k, v, raw, mode),
                        KEEP_PER_CLASS,
                        |f| f.0,
                        |f| f.1.class,
                    );
                }
            }
            failed
        })
    };
    judged.unwrap_or_else(|e| {
        // The generator's cases are valid by construction: say which one was not, so
        // that it can be reproduced.
        eprintln!("polyguard assure: case {k} rejected: {e:?}");
        local.rejected += 1;
        false
    })
}

/// `assure --intervals`.
fn run_intervals(args: &AssureArgs) -> ExitCode {
    use polyguard_harness::intervals::judge::IntervalEngine;
    let engine = match args.engine {
        EngineArg::F64 => IntervalEngine::Certified,
        EngineArg::ShiftedEnd => IntervalEngine::ShiftedEnd,
        EngineArg::DropSecond => IntervalEngine::DropSecond,
        EngineArg::FlatExit => IntervalEngine::FlatExit,
        other => {
            eprintln!(
                "polyguard assure: --intervals judges --engine f64, shifted-end, drop-second or flat-exit, not {other:?}"
            );
            return ExitCode::from(2);
        }
    };
    let campaign = super::assure_intervals::IntervalCampaign {
        run: hunt_run(args),
        space: args.aim.unwrap_or_default(),
        engine,
    };
    super::assure_intervals::run(&campaign, &args.out)
}

/// `assure --paper moving`.
fn run_moving(args: &AssureArgs) -> ExitCode {
    use polyguard_harness::moving::judge::MovingEngine;
    if args.contract || args.aim.is_some() || args.intervals || args.engine != EngineArg::F64 {
        eprintln!("polyguard assure: --paper moving takes --cases, --seed, --shard, --threads, --out, --quiet and --canary fixes-only; drop --contract, --aim, --intervals and --engine");
        return ExitCode::from(2);
    }
    let campaign = super::assure_moving::MovingCampaign {
        run: hunt_run(args),
        engine: match args.canary {
            None => MovingEngine::Certified,
            Some(CanaryArg::FixesOnly) => MovingEngine::FixesOnly,
            Some(other) => {
                eprintln!("polyguard assure: --canary {other:?} is --paper wayout's; --paper moving's is fixes-only");
                return ExitCode::from(2);
            }
        },
    };
    super::assure_moving::run(&campaign, &args.out)
}

/// `assure --paper wayout`.
fn run_wayout(args: &AssureArgs) -> ExitCode {
    use polyguard_harness::wayout::judge::WayoutEngine;
    if args.contract || args.aim.is_some() || args.intervals || args.engine != EngineArg::F64 {
        eprintln!("polyguard assure: --paper wayout takes --cases, --seed, --shard, --threads, --out, --quiet and --canary sampled-bands|bisector-offset; drop --contract, --aim, --intervals and --engine");
        return ExitCode::from(2);
    }
    let engine = match args.canary {
        None => WayoutEngine::Certified,
        Some(CanaryArg::SampledBands) => WayoutEngine::SampledBands,
        Some(CanaryArg::BisectorOffset) => WayoutEngine::BisectorOffset,
        Some(CanaryArg::FixesOnly) => {
            eprintln!("polyguard assure: --canary fixes-only is --paper moving's; --paper wayout's are sampled-bands and bisector-offset");
            return ExitCode::from(2);
        }
    };
    let hunt = super::assure_wayout::WayoutHunt {
        seed: args.seed,
        engine,
    };
    super::assure_wayout::run(&hunt, &hunt_run(args), &args.out)
}

/// The seed, shard, size, threads and progress of a hunt, from the command line.
fn hunt_run(args: &AssureArgs) -> super::assure_common::HuntRun {
    super::assure_common::HuntRun {
        seed: args.seed,
        shard: args.shard.unwrap_or((0, 1)),
        cases: args.cases,
        threads: threads(args),
        quiet: args.quiet,
    }
}

/// `assure --paper b`.
fn run_paper_b(args: &AssureArgs) -> ExitCode {
    use super::assure_b::{self, EngineB};
    let engine = match args.engine {
        EngineArg::F64 | EngineArg::Pipeline => EngineB::Pipeline,
        EngineArg::Sampled => EngineB::Sampled,
        EngineArg::Plain
        | EngineArg::ShiftedTime
        | EngineArg::ShiftedEnd
        | EngineArg::DropSecond
        | EngineArg::FlatExit => {
            eprintln!("polyguard assure: --engine plain, shifted-time, shifted-end, drop-second and flat-exit are paper A's canaries; paper B's is --engine sampled");
            return ExitCode::from(2);
        }
    };
    if args.contract || args.aim.is_some() {
        eprintln!("polyguard assure: --contract and --aim are paper A's; drop them with --paper b");
        return ExitCode::from(2);
    }
    assure_b::run(
        args.cases,
        args.seed,
        threads(args),
        &args.out,
        args.shard.unwrap_or((0, 1)),
        args.quiet,
        engine,
    )
}

/// `--threads`, or one per core.
fn threads(args: &AssureArgs) -> usize {
    args.threads
        .unwrap_or_else(|| {
            std::thread::available_parallelism()
                .map(|n| n.get())
                .unwrap_or(1)
        })
        .max(1)
}

/// Writes `DIR/report.json`, then prints the summary. The report is written first and a
/// closed standard output (`polyguard assure | head`) is not an error: the campaign's
/// result must not depend on who reads the summary.
fn finish(report: &Report, out: &Path) -> ExitCode {
    if let Err(code) = write_report(report, out) {
        return code;
    }
    let path = out.join("report.json");
    let mut text = report.table();
    if !report.missing_shards.is_empty() {
        text += &format!(
            "PARTIAL: {} of this {}-case campaign are missing; the counts cover {} cases\n",
            polyguard_harness::report::shard_ranges(&report.missing_shards),
            report.campaign_cases,
            report.cases
        );
    }
    if report.rejected > 0 {
        text += &format!(
            "{} generated cases were rejected by the engine or the oracle\n",
            report.rejected
        );
    }
    for k in &report.kept {
        text += &format!(
            "kept {} ({}, {}): {} {}\n",
            k.class.name(),
            k.method,
            k.mode,
            k.case_file,
            k.svg_file
        );
    }
    text += &format!("report: {}\n", path.display());
    if !report.contract_only {
        text += &report.coverage_grid();
        text += &format!(
            "per mode, or a class's rate per bucket: polyguard assure coverage {} --mode MODE --class CLASS\n",
            path.display()
        );
        text += &Report::legend();
    }
    text += &report.verdict_line();
    let mut stdout = std::io::stdout().lock();
    let _ = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush());
    if report.has_failures() {
        let mut by_mode: BTreeMap<&str, u64> = BTreeMap::new();
        for (mode, counts) in &report.by_mode {
            let bad: u64 = counts
                .iter()
                .filter(|(c, _)| c.is_failure())
                .map(|(_, n)| n)
                .sum();
            by_mode.insert(mode, bad);
        }
        let modes: Vec<String> = by_mode
            .iter()
            .filter(|(_, n)| **n > 0)
            .map(|(m, n)| format!("{m}: {n}"))
            .collect();
        eprintln!(
            "polyguard assure: missed detections or far false alarms found ({})",
            modes.join(", ")
        );
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Which hunt a set of reports is of.
enum Hunt {
    PaperA,
    PaperB,
    Intervals,
    Moving,
    Wayout,
}

/// The hunt of every report in `texts`: paper B's say so (`"paper": "b"`), interval
/// moving and way-out hunts too (`"hunt": "intervals"`, `"moving"`, `"wayout"`); reports of
/// different hunts are refused.
fn hunt_of(texts: &[String]) -> Result<Hunt, String> {
    let member = |t: &str, key: &str| -> Option<String> {
        serde_json::from_str::<serde_json::Value>(t)
            .ok()?
            .get(key)?
            .as_str()
            .map(str::to_owned)
    };
    let n = texts.len();
    let iv = texts
        .iter()
        .filter(|t| member(t, "hunt").as_deref() == Some("intervals"))
        .count();
    let b = texts
        .iter()
        .filter(|t| member(t, "paper").as_deref() == Some("b"))
        .count();
    let mv = texts
        .iter()
        .filter(|t| member(t, "hunt").as_deref() == Some("moving"))
        .count();
    let wo = texts
        .iter()
        .filter(|t| member(t, "hunt").as_deref() == Some("wayout"))
        .count();
    if wo > 0 {
        return if wo == n {
            Ok(Hunt::Wayout)
        } else {
            Err(format!(
                "{wo} of the {n} reports are way-out hunts and the rest are not: merge each hunt apart"
            ))
        };
    }
    if mv > 0 {
        return if mv == n {
            Ok(Hunt::Moving)
        } else {
            Err(format!(
                "{mv} of the {n} reports are moving hunts and the rest are not: merge each hunt apart"
            ))
        };
    }
    match (iv, b) {
        (iv, 0) if iv == n => Ok(Hunt::Intervals),
        (0, b) if b == n => Ok(Hunt::PaperB),
        (0, 0) => Ok(Hunt::PaperA),
        (iv, 0) => Err(format!(
            "{iv} of the {n} reports are interval hunts and the rest are not: merge each hunt apart"
        )),
        (_, b) => Err(format!(
            "{b} of the {n} reports are paper B's and the rest paper A's: merge each paper's apart"
        )),
    }
}

fn merge(paths: &[PathBuf], out: &Path, partial: bool) -> ExitCode {
    let fail = |msg: String| {
        eprintln!("polyguard assure merge: {msg}");
        ExitCode::from(2)
    };
    let mut texts = Vec::with_capacity(paths.len());
    for p in paths {
        match fs::read_to_string(p) {
            Ok(t) => texts.push(t),
            Err(e) => return fail(format!("cannot read {}: {e}", p.display())),
        }
    }
    match hunt_of(&texts) {
        Err(e) => return fail(e),
        Ok(Hunt::Intervals) => return merge_reports::<IntervalReport>(paths, &texts, out, partial),
        Ok(Hunt::Moving) => return merge_reports::<MovingReport>(paths, &texts, out, partial),
        Ok(Hunt::Wayout) => {
            return super::assure_common::merge_hunt::<polyguard_harness::wayout::judge::WayoutClass>(
                paths, &texts, out, partial,
            )
        }
        Ok(Hunt::PaperB) => return super::assure_b::merge(paths, &texts, out, partial),
        Ok(Hunt::PaperA) => {}
    }
    let mut reports = Vec::with_capacity(paths.len());
    for (p, text) in paths.iter().zip(&texts) {
        match Report::from_json(text) {
            Ok(r) => reports.push(r),
            Err(e) => return fail(format!("{} is not a report: {e}", p.display())),
        }
    }
    let merged = match Report::merge_campaign(&reports, partial) {
        Ok(m) => m,
        // name the files: the message counts reports from 1, in the order given
        Err(e) => {
            let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
            return fail(format!("{e} (reports: {})", names.join(", ")));
        }
    };
    if let Err(e) = fs::create_dir_all(out.join("counterexamples")) {
        return fail(format!("cannot create {}: {e}", out.display()));
    }
    // The kept counterexamples' files travel with the merge: a merged report never lists
    // a case file that is not beside it.
    for (p, r) in paths.iter().zip(&reports) {
        let dir = p.parent().unwrap_or_else(|| Path::new("."));
        let hunted = if r.engine == Hunted::Plain.name() {
            Hunted::Plain
        } else if r.engine == Hunted::ShiftedTime.name() {
            Hunted::ShiftedTime
        } else {
            Hunted::Certified
        };
        for k in r.kept.iter().filter(|k| merged.kept.contains(k)) {
            for f in [&k.case_file, &k.svg_file] {
                let (from, to) = (dir.join(f), out.join(f));
                // a picture left behind is drawn again from its case file
                if f == &k.svg_file && !from.exists() && dir.join(&k.case_file).exists() {
                    let drawn = redraw(&dir.join(&k.case_file), &k.mode, hunted)
                        .and_then(|svg| fs::write(&to, svg).map_err(|e| e.to_string()));
                    if let Err(e) = drawn {
                        return fail(format!(
                            "{} lists {}, which is missing and cannot be drawn again from {}: {e}",
                            p.display(),
                            from.display(),
                            k.case_file
                        ));
                    }
                    continue;
                }
                if from != to {
                    if let Err(e) = fs::copy(&from, &to) {
                        return fail(format!(
                            "{} lists {}, which cannot be copied: {e}",
                            p.display(),
                            from.display()
                        ));
                    }
                }
            }
        }
    }
    finish(&merged, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An aimed campaign's cases land in (or next to, as the polygon's measured size
    /// differs from the drawn one) the buckets it aims at.
    #[test]
    fn aimed_campaigns_hit_their_buckets() {
        let space = parse_aim("path=1e4..1e5,buff=1e-9..1e-8").expect("a valid aim");
        for k in 0..300 {
            let (raw, mode) = campaign_case(5, k, &space);
            let (p, b) = bucket(&raw);
            assert!((3..=5).contains(&p), "case {k} ({mode}): path bucket 1e{p}");
            assert!(
                (-10..=-8).contains(&b),
                "case {k} ({mode}): buff bucket 1e{b}"
            );
        }
    }

    /// `--aim ends=…` moves every case that can be moved to the chosen end of the float
    /// range (a move that would break the case is not made), and says so in its label.
    #[test]
    fn aimed_at_the_ends_cases_go_there() {
        assert_eq!(parse_aim("ends=all"), Ok(Space::FULL.with_ends(Ends::All)));
        assert_eq!(
            parse_aim("ends=none"),
            Ok(Space::FULL.with_ends(Ends::None))
        );
        assert!(parse_aim("ends=middle").is_err());
        assert_eq!(Space::FULL.label(), "path=1e-3..1e7,buff=1e-12..1e0");
        for (name, want_tiny) in [("tiny", Some(true)), ("huge", Some(false)), ("all", None)] {
            let space = parse_aim(&format!("path=1e-1..1e2,ends={name}")).expect("a valid aim");
            assert!(space.label().ends_with(&format!(",ends={name}")));
            let n = 200;
            let (mut tiny, mut huge) = (0, 0);
            for k in 0..n {
                let (raw, _) = campaign_case(3, k, &space);
                let largest = raw
                    .vertices
                    .iter()
                    .flatten()
                    .chain(&raw.pos)
                    .fold(raw.buff, |m, x| m.max(x.abs()));
                tiny += usize::from(raw.buff < f64::MIN_POSITIVE);
                huge += usize::from(largest > 2f64.powi(890));
            }
            match want_tiny {
                Some(true) => assert!(tiny >= 180 && huge == 0, "{name}: {tiny} tiny, {huge} huge"),
                Some(false) => {
                    assert!(huge >= 180 && tiny == 0, "{name}: {tiny} tiny, {huge} huge")
                }
                None => assert!(
                    tiny >= 60 && huge >= 60 && tiny + huge >= 180,
                    "{name}: {tiny} tiny, {huge} huge"
                ),
            }
        }
        // the default: about one case in eight
        let (mut moved, n) = (0, 800);
        for k in 0..n {
            let (raw, _) = campaign_case(3, k, &Space::FULL);
            let largest = raw
                .vertices
                .iter()
                .flatten()
                .fold(raw.buff, |m, x| m.max(x.abs()));
            moved += usize::from(raw.buff < f64::MIN_POSITIVE || largest > 2f64.powi(890));
        }
        assert!(
            (50..=150).contains(&moved),
            "{moved} of {n} moved by default"
        );
        // ends=none moves none, and its cases are the default's wherever the default
        // left a case at its scale
        let none = parse_aim("ends=none").expect("a valid aim");
        assert!(none.label().ends_with(",ends=none"));
        for k in 0..n {
            let kept = any_case_in(&mut SplitMix(case_seed(3, k)), &none);
            assert_eq!(kept.scale_exp, 0, "case {k} moved with ends=none");
            let default = any_case_in(&mut SplitMix(case_seed(3, k)), &Space::FULL);
            if default.scale_exp == 0 {
                assert_eq!(kept.raw, default.raw, "case {k}");
            }
        }
    }

    #[test]
    fn shards_parse_and_cases_are_reproducible() {
        assert_eq!(parse_shard("1/4"), Ok((1, 4)));
        assert!(parse_shard("4/4").is_err());
        assert!(parse_shard("x").is_err());
        let full = Space::FULL;
        assert_eq!(
            parse_aim("path=1e3..1e5"),
            Space::aimed((3.0, 5.0), full.buff)
        );
        assert!(parse_aim("path=1e5..1e3").is_err());
        assert!(parse_aim("buff=1e-13..1e-9").is_err(), "outside the space");
        assert!(parse_aim("speed=1..2").is_err());
        assert!(parse_aim("path=0..1e3").is_err());
        assert_eq!(
            campaign_case(9, 123, &full).0,
            campaign_case(9, 123, &full).0
        );
        assert_ne!(
            campaign_case(9, 123, &full).0,
            campaign_case(9, 124, &full).0
        );
    }
}
