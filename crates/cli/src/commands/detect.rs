//! `polyguard detect [FILE]`: answers the case JSON Lines of docs/cases.md.

use std::collections::BTreeMap;
use std::fs::File;
use std::hint::black_box;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::{json, Map, Value};

use polyguard::api::{self, Case};
use polyguard_harness::answer::{answer, Ask, Engine};
use polyguard_harness::case::{parse_line_with, Fence};

/// Which implementation answers (the command line's names for [`Engine`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// The certified f64 engine (paper A in floating point): the product.
    F64,
    /// The plain f64 transcription of paper A, without certificate: for comparison only
    /// (it misses true entries on long relative paths).
    Plain,
    /// Paper A's functions in exact rational arithmetic (the oracle).
    Exact,
    /// The exact ground truth: does the point really enter the closed polygon, and when?
    Truth,
}

impl From<EngineArg> for Engine {
    fn from(e: EngineArg) -> Engine {
        match e {
            EngineArg::F64 => Engine::F64,
            EngineArg::Plain => Engine::Plain,
            EngineArg::Exact => Engine::Exact,
            EngineArg::Truth => Engine::Truth,
        }
    }
}

/// Arguments of `polyguard detect`.
#[derive(Debug, clap::Args)]
pub struct DetectArgs {
    /// The case file (JSON Lines); standard input when absent or "-".
    pub file: Option<PathBuf>,
    /// Which implementation answers.
    #[arg(long, value_enum, default_value = "f64")]
    pub engine: EngineArg,
    /// Run each case this many times (for --timing); the answer is printed once.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub repeat: u32,
    /// Print the engine's time per call (I/O and parsing excluded) per group to stderr.
    #[arg(long)]
    pub timing: bool,
    /// κ, the corner angle of the well-formedness report (§II.J), in degrees, for cases
    /// that give no `kappa` of their own.
    #[arg(long, default_value_t = polyguard_harness::case::DEFAULT_KAPPA_DEG)]
    pub kappa: f64,
    /// Answer a case that takes longer than this many seconds with an error line and go on
    /// with the next (the case's computation is abandoned). Without it every case is
    /// answered however long it takes.
    #[arg(long, value_parser = parse_timeout, conflicts_with = "timing")]
    pub case_timeout: Option<f64>,
    /// Also answer when the point first enters the closed polygon (and slab): an f64
    /// enclosure of the exact first-entry time (`entry`, `entry_lo`, `entry_hi`; the f64
    /// engine only: the truth engine gives `entry_time` exactly without it).
    #[arg(long)]
    pub time: bool,
    /// Also answer every interval of [0, T] in which the point is inside the polygon, near
    /// it (within --sep, and --sep-v of the slab), and breaching it as a keep-in fence, each
    /// end as a certified enclosure (f64) or exactly (truth): `intervals` (docs/cases.md,
    /// "Separation and fences").
    #[arg(long)]
    pub intervals: bool,
    /// D ≥ 0, the horizontal separation of near and breach, for cases without `sep`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep: f64,
    /// H ≥ 0, the vertical separation (3D), for cases without `sep_v`.
    #[arg(long, default_value_t = 0.0, value_parser = parse_separation)]
    pub sep_v: f64,
    /// keep-in: also answer whether the point leaves the polygon as a keep-in fence (comes
    /// within --sep of its edges, or --sep-v of its floor or ceiling): `fence`, `exits`,
    /// `exit_kind`. For cases without `fence`.
    #[arg(long, value_parser = parse_fence)]
    pub fence: Option<Fence>,
}

/// `--sep`, `--sep-v`: a finite distance ≥ 0.
fn parse_separation(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x >= 0.0 => Ok(x),
        Ok(x) => Err(format!("{x} is not a distance ≥ 0")),
        Err(e) => Err(format!("{s}: {e}")),
    }
}

/// `--fence keep-in | keep-out`.
fn parse_fence(s: &str) -> Result<Fence, String> {
    Fence::from_name(s).ok_or_else(|| format!("{s:?}: expected keep-in or keep-out"))
}

/// `--case-timeout`: a positive, finite number of seconds.
fn parse_timeout(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 && x < 1e9 => Ok(x),
        Ok(x) => Err(format!("{x} is not a number of seconds > 0")),
        Err(e) => Err(format!("{s}: {e}")),
    }
}

/// What a worker is asked: answer this case with this engine (and `--time`), `repeat`
/// times.
type Job = (Case, Ask, u32);

/// Its answer: the fields after `id`, or the error.
type Reply = Result<Map<String, Value>, String>;

/// Answers cases on a thread of its own, so that `--case-timeout` can stop waiting for
/// one. A worker that timed out is abandoned (its case runs on, unread, until the
/// process ends) and the next case gets a new worker.
struct Worker {
    jobs: std::sync::mpsc::Sender<Job>,
    replies: std::sync::mpsc::Receiver<Reply>,
}

impl Worker {
    fn spawn() -> io::Result<Worker> {
        let (jobs, job_rx) = std::sync::mpsc::channel::<Job>();
        let (reply_tx, replies) = std::sync::mpsc::channel::<Reply>();
        std::thread::Builder::new()
            .name("polyguard-detect-case".into())
            .spawn(move || {
                for (case, engine, repeat) in job_rx {
                    for _ in 1..repeat {
                        let _ = black_box(answer(black_box(&case), engine, &mut Map::new()));
                    }
                    let mut out = Map::new();
                    let r = answer(&case, engine, &mut out).map(|()| out);
                    if reply_tx.send(r).is_err() {
                        break;
                    }
                }
            })?;
        Ok(Worker { jobs, replies })
    }

    /// The case's answer, or `None` when `limit` passed first (the worker is then spent).
    fn answer(&self, case: Case, engine: Ask, repeat: u32, limit: f64) -> Option<Reply> {
        if self.jobs.send((case, engine, repeat)).is_err() {
            return Some(Err("case: the worker thread stopped".into()));
        }
        match self
            .replies
            .recv_timeout(std::time::Duration::from_secs_f64(limit))
        {
            Ok(r) => Some(r),
            Err(std::sync::mpsc::RecvTimeoutError::Timeout) => None,
            Err(std::sync::mpsc::RecvTimeoutError::Disconnected) => {
                Some(Err("case: the worker thread stopped".into()))
            }
        }
    }
}

/// Timing totals of one group of cases.
#[derive(Default)]
struct Group {
    calls: u64,
    nanos: u128,
}

/// A timing group: dimension, static or warping, number of vertices.
type GroupKey = (&'static str, &'static str, usize);

/// The timing group of a case.
fn group_key(case: &Case) -> GroupKey {
    let dim = if case.point().z.is_some() { "3D" } else { "2D" };
    let shape = if case.polygon().statically_shaped() {
        "static"
    } else {
        "warping"
    };
    (dim, shape, case.polygon().vertices().len())
}

fn open(file: &Option<PathBuf>) -> io::Result<Box<dyn BufRead>> {
    match file {
        // a directory opens on Unix and fails only at the first read: say so up front
        Some(p) if p.is_dir() => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "is a directory, not a case file",
        )),
        Some(p) if p.as_os_str() != "-" => Ok(Box::new(BufReader::new(File::open(p)?))),
        _ => Ok(Box::new(BufReader::new(io::stdin().lock()))),
    }
}

/// Runs `polyguard detect`: one answer line per non-blank input line, in order.
pub fn run(args: &DetectArgs) -> ExitCode {
    if (args.intervals || args.fence == Some(Fence::KeepIn))
        && matches!(args.engine, EngineArg::Plain | EngineArg::Exact)
    {
        eprintln!("polyguard detect: --intervals and --fence keep-in are answered by the f64 and truth engines (paper A has neither)");
        return ExitCode::from(2);
    }
    if args.time && args.engine != EngineArg::F64 {
        eprintln!("polyguard detect: --time is answered by the f64 engine only (the truth engine gives entry_time without it)");
        return ExitCode::from(2);
    }
    if let Err(e) = api::Params::new(1.0).and_then(|p| p.with_kappa_degrees(args.kappa)) {
        eprintln!("polyguard detect: --kappa: {e}");
        return ExitCode::from(2);
    }
    let reader = match open(&args.file) {
        Ok(r) => r,
        Err(e) => {
            let name = args
                .file
                .as_ref()
                .map_or_else(|| "standard input".into(), |p| p.display().to_string());
            eprintln!("polyguard detect: cannot read {name}: {e}");
            return ExitCode::from(2);
        }
    };
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    match process(reader, &mut out, args) {
        Ok(failed) => {
            if let Err(e) = out.flush() {
                eprintln!("polyguard detect: cannot write: {e}");
                return ExitCode::from(2);
            }
            if failed > 0 {
                eprintln!("polyguard detect: {failed} line(s) could not be answered");
                ExitCode::from(1)
            } else {
                ExitCode::SUCCESS
            }
        }
        Err(e) => {
            let name = args
                .file
                .as_ref()
                .map_or_else(|| "standard input".into(), |p| p.display().to_string());
            eprintln!("polyguard detect: reading {name}: {e}");
            ExitCode::from(2)
        }
    }
}

/// Streams cases from `reader` to `out`; returns the number of lines that failed.
pub fn process<R: BufRead, W: Write>(
    mut reader: R,
    out: &mut W,
    args: &DetectArgs,
) -> io::Result<u64> {
    let mut buf = Vec::new();
    let mut line_no = 0usize;
    let mut failed = 0u64;
    let mut groups: BTreeMap<GroupKey, Group> = BTreeMap::new();
    let mut worker: Option<Worker> = None;
    let ask = Ask {
        time: args.time,
        intervals: args.intervals,
        sep: args.sep,
        sep_v: args.sep_v,
        fence: args.fence.unwrap_or_default(),
        ..Ask::of(args.engine.into())
    };
    loop {
        buf.clear();
        if reader.read_until(b'\n', &mut buf)? == 0 {
            break;
        }
        line_no += 1;
        let text = match std::str::from_utf8(&buf) {
            Ok(t) => t,
            Err(_) => {
                failed += 1;
                let line = json!({"id": line_no, "line": line_no, "error": "line: not UTF-8"});
                writeln!(out, "{line}")?;
                continue;
            }
        };
        if text.trim().is_empty() {
            continue;
        }
        let parsed = parse_line_with(text, line_no, args.kappa);
        let ask = ask.for_line(&parsed.options);
        let mut obj = Map::new();
        obj.insert("id".into(), parsed.id);
        let result = match (parsed.case, args.case_timeout) {
            (Err(e), _) => Err(e.to_string()),
            (Ok(case), Some(limit)) => answer_within(case, ask, args.repeat, limit, &mut worker)?,
            (Ok(case), None) => answer_here(&case, args, ask, &mut groups),
        };
        match result {
            Ok(fields) => obj.extend(fields),
            Err(e) => {
                failed += 1;
                obj.insert("line".into(), line_no.into());
                obj.insert("error".into(), e.into());
            }
        }
        writeln!(out, "{}", Value::Object(obj))?;
    }
    if args.timing {
        report_timing(&groups);
    }
    Ok(failed)
}

/// A valid case answered on the worker thread (`--case-timeout`): its fields, or an
/// error when no answer came within `limit` seconds (the worker is then abandoned and
/// the next case gets a new one).
fn answer_within(
    case: Case,
    ask: Ask,
    repeat: u32,
    limit: f64,
    worker: &mut Option<Worker>,
) -> io::Result<Reply> {
    let w = match worker.take() {
        Some(w) => w,
        None => Worker::spawn()?,
    };
    Ok(match w.answer(case, ask, repeat, limit) {
        Some(r) => {
            *worker = Some(w);
            r
        }
        None => Err(format!(
            "case: no answer within {limit} s (--case-timeout); the case was abandoned"
        )),
    })
}

/// A valid case answered on this thread, `--repeat` times, timed per group with
/// `--timing`: its fields (the answer is computed once more, untimed, to be written).
fn answer_here(
    case: &Case,
    args: &DetectArgs,
    ask: Ask,
    groups: &mut BTreeMap<GroupKey, Group>,
) -> Reply {
    // The engine asked for is the one timed: its decision alone for f64 and plain,
    // the whole answer (conversion to rationals included) for exact and truth.
    let once = |case: &Case| match ask.engine {
        Engine::F64 => {
            black_box(api::detected(black_box(case)));
        }
        Engine::Plain => {
            black_box(api::detected_plain(black_box(case)));
        }
        Engine::Exact | Engine::Truth => {
            let _ = black_box(answer(black_box(case), ask, &mut Map::new()));
        }
    };
    if args.timing {
        let start = Instant::now();
        for _ in 0..args.repeat {
            once(case);
        }
        let g = groups.entry(group_key(case)).or_default();
        g.calls += u64::from(args.repeat);
        g.nanos += start.elapsed().as_nanos();
    } else {
        for _ in 1..args.repeat {
            once(case);
        }
    }
    let mut fields = Map::new();
    answer(case, ask, &mut fields).map(|()| fields)
}

/// Prints `--timing`'s table: per group, the calls and the time per call.
fn report_timing(groups: &BTreeMap<GroupKey, Group>) {
    eprintln!(
        "{:<4} {:<8} {:>9} {:>12} {:>12}",
        "dim", "shape", "vertices", "calls", "ns/call"
    );
    for ((dim, shape, n), g) in groups {
        let per = if g.calls == 0 {
            0.0
        } else {
            g.nanos as f64 / g.calls as f64
        };
        eprintln!("{dim:<4} {shape:<8} {n:>9} {:>12} {per:>12.1}", g.calls);
    }
}
