//! What the campaigns share (`polyguard assure`, `assure --paper b`, the other hunts):
//! the progress shown on standard error while the cases run, the report file, and for
//! a hunt reporting in the shared shape ([`polyguard_harness::hunt::HuntReport`]) the
//! whole run over threads and shards ([`run_hunt`]) and its merge ([`merge_hunt`]).

use std::collections::BTreeMap;
use std::fs;
use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use polyguard_harness::hunt::{HuntClass, HuntReport, Judged, Kept};

/// When standard error is not a terminal, a progress line is printed at least this often
/// (and at every tenth of the cases).
const LINE_EVERY: Duration = Duration::from_secs(30);

/// A campaign's progress over its cases, on standard error: a bar on a terminal, plain
/// lines when standard error is a pipe or a file (a bar would leave nothing to read for
/// minutes), nothing with `--quiet`. Shared by the worker threads.
pub struct CampaignProgress {
    bar: indicatif::ProgressBar,
    lines: Option<Lines>,
}

/// The plain progress lines: one at every tenth of the cases and at least one every
/// [`LINE_EVERY`], each `polyguard assure: 300/600 cases (50 %), 31 s, 0 failures so far`.
struct Lines {
    total: u64,
    start: Instant,
    done: AtomicU64,
    failures: AtomicU64,
    /// The count of cases at which the next tenth is reached.
    next_mark: AtomicU64,
    /// Milliseconds from `start` to the last line printed.
    last_ms: AtomicU64,
    /// Held while a line is printed, so that two threads do not print the same mark.
    printing: Mutex<()>,
}

impl CampaignProgress {
    /// The progress of `cases` cases: a bar when standard error is a terminal, lines
    /// otherwise, nothing when `quiet`.
    pub fn new(cases: u64, quiet: bool) -> CampaignProgress {
        let terminal = std::io::stderr().is_terminal();
        let bar = if quiet || !terminal {
            indicatif::ProgressBar::hidden()
        } else {
            indicatif::ProgressBar::new(cases)
        };
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} {per_sec} eta {eta} {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let lines = (!quiet && !terminal && cases > 0).then(|| Lines {
            total: cases,
            start: Instant::now(),
            done: AtomicU64::new(0),
            failures: AtomicU64::new(0),
            next_mark: AtomicU64::new(tenth_mark(cases, 0)),
            last_ms: AtomicU64::new(0),
            printing: Mutex::new(()),
        });
        CampaignProgress { bar, lines }
    }

    /// One more case done; `failed` when it is a failure of the campaign (a missed
    /// detection, a far false alarm, a contract breach, …).
    pub fn inc(&self, failed: bool) {
        self.bar.inc(1);
        if let Some(l) = &self.lines {
            l.inc(failed);
        }
    }

    /// The cases are done: the bar is cleared (the lines have said 100 % already).
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

impl Lines {
    /// Counts one case, and prints a line when it reaches the next tenth or when
    /// [`LINE_EVERY`] has passed since the last line (the 100 % line only once).
    fn inc(&self, failed: bool) {
        if failed {
            self.failures.fetch_add(1, Ordering::Relaxed);
        }
        let done = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        let now_ms = self.start.elapsed().as_millis() as u64;
        let due_by_time = now_ms.saturating_sub(self.last_ms.load(Ordering::Relaxed))
            >= LINE_EVERY.as_millis() as u64;
        if done < self.next_mark.load(Ordering::Relaxed) && !due_by_time {
            return;
        }
        let Ok(_guard) = self.printing.lock() else {
            return;
        };
        // another thread may have printed this mark while this one waited
        let now_ms = self.start.elapsed().as_millis() as u64;
        let done = self.done.load(Ordering::Relaxed);
        let mark = self.next_mark.load(Ordering::Relaxed);
        let last = self.last_ms.load(Ordering::Relaxed);
        let due_by_time = now_ms.saturating_sub(last) >= LINE_EVERY.as_millis() as u64;
        // the last line is the 100 % mark's, printed once
        if done < mark && !(due_by_time && done < self.total) {
            return;
        }
        // the count may be past the mark (threads run on while one prints): the line
        // says the count
        eprintln!(
            "polyguard assure: {done}/{} cases ({} %), {} s, {} failures so far",
            self.total,
            done * 100 / self.total,
            now_ms / 1000,
            self.failures.load(Ordering::Relaxed)
        );
        self.next_mark
            .store(tenth_mark(self.total, done), Ordering::Relaxed);
        self.last_ms.store(now_ms, Ordering::Relaxed);
    }
}

/// The first count above `done` that reaches a tenth of `total` (⌈total·i/10⌉ for the
/// least such i ≤ 10), or `u64::MAX` past the last.
fn tenth_mark(total: u64, done: u64) -> u64 {
    (1..=10u64)
        .map(|i| (total * i).div_ceil(10))
        .find(|&m| m > done)
        .unwrap_or(u64::MAX)
}

/// Keeps, of each class, the `per_class` items of the lowest case indices, whatever the
/// threads' order, so that the shards of a campaign merge into exactly the whole run's
/// kept cases. `index` is an item's case index, `class` its class.
pub fn keep_lowest<T, C: PartialEq>(
    kept: &mut Vec<T>,
    item: T,
    per_class: usize,
    index: impl Fn(&T) -> u64,
    class: impl Fn(&T) -> C,
) {
    let same: Vec<usize> = (0..kept.len())
        .filter(|&x| class(&kept[x]) == class(&item))
        .collect();
    if same.len() < per_class {
        kept.push(item);
    } else if let Some(&worst) = same.iter().max_by_key(|&&x| index(&kept[x])) {
        if index(&kept[worst]) > index(&item) {
            kept[worst] = item;
        }
    }
}

/// A campaign report with a shape of its own (the interval and moving hunts): what
/// [`run_shard`], [`finish_report`] and [`merge_reports`] need of it.
pub trait ShardReport: Default + Send + serde::Serialize + Sized {
    /// A kept failing case, as the report lists it.
    type Kept;
    /// What the report is, for errors ("an interval report").
    const WHAT: &'static str;
    /// What the summary says after the count of rejected cases.
    const REJECTED: &'static str;
    /// Adds another thread's counts.
    fn absorb(&mut self, other: &Self);
    /// Counts a case that the engine or the oracle rejected.
    fn reject(&mut self);
    /// The shard's label (`i/N`), the campaign's size, the wall time and the kept cases.
    fn stamp(
        &mut self,
        shard: String,
        campaign_cases: u64,
        wall_seconds: f64,
        kept: Vec<Self::Kept>,
    );
    /// The report read back from its JSON.
    fn from_json(text: &str) -> Result<Self, String>;
    /// The shards of one campaign joined (`partial`: some may be missing).
    fn merge(reports: &[Self], partial: bool) -> Result<Self, String>;
    /// The summary's text, the counts of failures and of rejected cases.
    fn counts(&self) -> (String, u64, u64);
    /// Per kept case: its class, mode and file.
    fn kept(&self) -> Vec<(&'static str, &str, &str)>;
    /// A line for standard error when the campaign failed.
    fn failure_note(&self) -> Option<String>;
}

/// [`ShardReport`] for a report type with the fields `rejected`, `shards`,
/// `campaign_cases`, `wall_seconds` and `kept` (of `$kept`), and the methods `absorb`,
/// `from_json`, `merge_campaign`, `summary` and `failures`.
macro_rules! shard_report {
    ($report:ty, $kept:ty, $what:expr, $rejected:expr, $note:expr) => {
        impl ShardReport for $report {
            type Kept = $kept;
            const WHAT: &'static str = $what;
            const REJECTED: &'static str = $rejected;
            fn absorb(&mut self, other: &Self) {
                <$report>::absorb(self, other);
            }
            fn reject(&mut self) {
                self.rejected += 1;
            }
            fn stamp(&mut self, shard: String, cases: u64, wall: f64, kept: Vec<$kept>) {
                (self.shards, self.campaign_cases) = (vec![shard], cases);
                (self.wall_seconds, self.kept) = (wall, kept);
            }
            fn from_json(text: &str) -> Result<Self, String> {
                <$report>::from_json(text)
            }
            fn merge(reports: &[Self], partial: bool) -> Result<Self, String> {
                <$report>::merge_campaign(reports, partial)
            }
            fn counts(&self) -> (String, u64, u64) {
                (self.summary(), self.failures(), self.rejected)
            }
            fn kept(&self) -> Vec<(&'static str, &str, &str)> {
                let k = self.kept.iter();
                k.map(|k| (k.class.name(), k.mode.as_str(), k.case_file.as_str()))
                    .collect()
            }
            fn failure_note(&self) -> Option<String> {
                let note: fn(&Self) -> Option<String> = $note;
                note(self)
            }
        }
    };
}

shard_report!(
    polyguard_harness::intervals::report::IntervalReport,
    polyguard_harness::intervals::report::KeptInterval,
    "an interval report",
    "generated cases were rejected by the engine or the oracle",
    |_| None
);
shard_report!(
    polyguard_harness::moving::report::MovingReport,
    polyguard_harness::moving::report::KeptMoving,
    "a moving report",
    "generated scenarios were rejected by the engine",
    |r| Some(format!(
        "polyguard assure: the moving engine ({}) failed the exact truth in {} scenarios",
        r.engine,
        r.failures()
    ))
);

/// Writes a [`ShardReport`]'s report.json and summary.txt and prints the summary; exit 1
/// on a failure or a rejected case.
pub fn finish_report<R: ShardReport>(report: &R, out: &Path) -> ExitCode {
    if let Err(code) = write_report(report, out) {
        return code;
    }
    let (mut text, failures, rejected) = report.counts();
    if rejected > 0 {
        text += &format!("{rejected} {}\n", R::REJECTED);
    }
    for (class, mode, file) in report.kept() {
        text += &format!("kept {class} ({mode}): {file}\n");
    }
    text += &format!("report: {}\n", out.join("report.json").display());
    let _ = fs::write(out.join("summary.txt"), &text);
    print!("{text}");
    if failures > 0 || rejected > 0 {
        if let Some(note) = report.failure_note() {
            eprintln!("{note}");
        }
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `assure merge` of [`ShardReport`]s: joins the shards and copies their kept cases.
pub fn merge_reports<R: ShardReport>(
    paths: &[std::path::PathBuf],
    texts: &[String],
    out: &Path,
    partial: bool,
) -> ExitCode {
    let merged = read_reports(paths, texts, R::from_json, R::WHAT).and_then(|reports| {
        let merged = R::merge(&reports, partial).map_err(merge_failed)?;
        copy_kept(paths, &reports, out, |r| {
            r.kept()
                .into_iter()
                .map(|(_, _, f)| f.to_string())
                .collect()
        })?;
        Ok(merged)
    });
    match merged {
        Ok(m) => finish_report(&m, out),
        Err(code) => code,
    }
}

/// `assure merge`'s failure: the message on standard error, exit 2.
fn merge_failed(msg: String) -> ExitCode {
    eprintln!("polyguard assure merge: {msg}");
    ExitCode::from(2)
}

/// The shards' reports read from their texts (`what`: "an interval report").
fn read_reports<R>(
    paths: &[std::path::PathBuf],
    texts: &[String],
    parse: impl Fn(&str) -> Result<R, String>,
    what: &str,
) -> Result<Vec<R>, ExitCode> {
    let read = |(p, t): (&std::path::PathBuf, &String)| {
        parse(t).map_err(|e| merge_failed(format!("{} is not {what}: {e}", p.display())))
    };
    paths.iter().zip(texts).map(read).collect()
}

/// Copies into `out` the files (`files`, relative to each report's directory) that the
/// merged report keeps.
fn copy_kept<R>(
    paths: &[std::path::PathBuf],
    reports: &[R],
    out: &Path,
    files: impl Fn(&R) -> Vec<String>,
) -> Result<(), ExitCode> {
    fs::create_dir_all(out.join("counterexamples"))
        .map_err(|e| merge_failed(format!("cannot create {}: {e}", out.display())))?;
    for (p, r) in paths.iter().zip(reports) {
        let dir = p.parent().unwrap_or_else(|| Path::new("."));
        for file in files(r) {
            fs::copy(dir.join(&file), out.join(&file))
                .map_err(|e| merge_failed(format!("cannot copy {file}: {e}")))?;
        }
    }
    Ok(())
}

/// How [`run_shard`] judges and keeps the cases of a campaign.
pub struct ShardJudge<J, C, W> {
    /// `judge(k, report)` draws and judges case k and adds it to the thread's report;
    /// it returns the failure to keep if the case failed, or why the case was rejected.
    pub judge: J,
    /// A failure's class.
    pub class: C,
    /// Writes a kept failure's file (case k) and returns the report's entry for it.
    pub write: W,
}

/// Runs a shard of a campaign whose report has a shape of its own ([`ShardReport`]) over
/// the shard's threads into `out`. The shard's j-th case is case k = j·N + i of the
/// campaign. Of each failing class, the `keep` failures of the lowest indices are kept
/// and written, whatever the threads' order (see [`keep_lowest`]); a rejected case is
/// reported on standard error and counted. Returns the stamped report.
pub fn run_shard<R, F, C>(
    report: R,
    s: &HuntRun,
    keep: usize,
    how: ShardJudge<
        impl Fn(u64, &mut R) -> Result<Option<F>, String> + Sync,
        impl Fn(&F) -> C + Sync,
        impl Fn(u64, &F) -> std::io::Result<R::Kept>,
    >,
) -> R
where
    R: ShardReport,
    F: Send,
    C: PartialEq,
{
    let (shard_i, shard_n) = s.shard;
    let mine = polyguard_harness::report::shard_size(s.cases, shard_i, shard_n);
    let progress = CampaignProgress::new(mine, s.quiet);
    let start = Instant::now();
    let next = AtomicU64::new(0);
    let report = Mutex::new(report);
    let found: Mutex<Vec<(u64, F)>> = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..s.threads.max(1) {
            scope.spawn(|| {
                let mut local = R::default();
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    if j >= mine {
                        break;
                    }
                    let k = j * shard_n + shard_i;
                    let failure = (how.judge)(k, &mut local).unwrap_or_else(|why| {
                        eprintln!("polyguard assure: {why}");
                        local.reject();
                        None
                    });
                    progress.inc(failure.is_some());
                    if let (Some(f), Ok(mut g)) = (failure, found.lock()) {
                        keep_lowest(&mut g, (k, f), keep, |x| x.0, |x| (how.class)(&x.1));
                    }
                }
                if let Ok(mut r) = report.lock() {
                    r.absorb(&local);
                }
            });
        }
    });
    progress.finish();
    let mut found = found.into_inner().unwrap_or_default();
    found.sort_by_key(|f| f.0);
    let mut kept = Vec::with_capacity(found.len());
    for (k, f) in &found {
        match (how.write)(*k, f) {
            Ok(entry) => kept.push(entry),
            Err(e) => eprintln!("polyguard assure: cannot write counterexample {k}: {e}"),
        }
    }
    let mut report = report.into_inner().unwrap_or_default();
    let wall = start.elapsed().as_secs_f64();
    report.stamp(format!("{shard_i}/{shard_n}"), s.cases, wall, kept);
    report
}

/// Writes `DIR/report.json` (either paper's report); exit 2 when it cannot.
pub fn write_report<T: serde::Serialize>(report: &T, out: &Path) -> Result<(), ExitCode> {
    let path = out.join("report.json");
    let json = serde_json::to_string_pretty(report).map_err(|e| {
        eprintln!("polyguard assure: cannot serialise the report: {e}");
        ExitCode::from(2)
    })?;
    fs::write(&path, json + "\n").map_err(|e| {
        eprintln!("polyguard assure: cannot write {}: {e}", path.display());
        ExitCode::from(2)
    })
}

/// A hunt in the shared report shape: how case k is drawn, judged and written.
pub trait Hunt: Sync {
    /// A drawn case.
    type Case;
    /// Its classes.
    type Class: HuntClass + Send;
    /// The hunt's name in reports (`"hunt"`).
    fn name(&self) -> &'static str;
    /// The engine's name in reports.
    fn engine(&self) -> &'static str;
    /// Case k of the campaign and its generator mode.
    fn case(&self, k: u64) -> (Self::Case, String);
    /// The judgement of a case.
    fn judge(&self, case: &Self::Case) -> Judged<Self::Class>;
    /// A case as its regression line (one JSON object), with `meta` merged in.
    fn line(&self, case: &Self::Case, meta: serde_json::Value) -> String;
}

/// Where a run of a hunt goes: seed, shard i of N, size, threads, progress.
pub struct HuntRun {
    /// The seed.
    pub seed: u64,
    /// Shard i of N.
    pub shard: (u64, u64),
    /// The campaign's size (all shards).
    pub cases: u64,
    /// Worker threads.
    pub threads: usize,
    /// No progress lines.
    pub quiet: bool,
}

/// Per failing class, the worst case kept so far and its regression line.
type Worst<C> = BTreeMap<C, (Kept<C>, String)>;

/// Runs a hunt's shard into `out` (report.json, summary.txt and, per failing class, the
/// worst case as a regression line in counterexamples/CLASS-K.jsonl); exit 1 on a
/// failure.
pub fn run_hunt<H: Hunt>(hunt: &H, run: &HuntRun, out: &Path) -> ExitCode {
    if let Err(e) = fs::create_dir_all(out.join("counterexamples")) {
        eprintln!("polyguard assure: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let (shard_i, shard_n) = run.shard;
    let mine = polyguard_harness::report::shard_size(run.cases, shard_i, shard_n);
    let progress = CampaignProgress::new(mine, run.quiet);
    let start = Instant::now();
    let next = AtomicU64::new(0);
    let report: Mutex<HuntReport<H::Class>> =
        Mutex::new(HuntReport::new(hunt.name(), run.seed, hunt.engine()));
    // per failing class, the worst case's severity, index and regression line
    let worst: Mutex<Worst<H::Class>> = Mutex::new(BTreeMap::new());
    std::thread::scope(|scope| {
        for _ in 0..run.threads.max(1) {
            scope.spawn(|| {
                let mut local = HuntReport::new(hunt.name(), run.seed, hunt.engine());
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    if j >= mine {
                        break;
                    }
                    let k = j * shard_n + shard_i;
                    let (case, mode) = hunt.case(k);
                    let v = hunt.judge(&case);
                    local.add(&v, &mode);
                    for &c in v.classes.iter().filter(|c| c.is_failure()) {
                        let kept = Kept {
                            index: k,
                            class: c,
                            mode: mode.clone(),
                            severity: v.severity,
                            case_file: format!("counterexamples/{}-{k}.jsonl", c.name()),
                        };
                        if let Ok(mut w) = worst.lock() {
                            let better = w.get(&c).map_or(true, |(o, _)| kept.worse_than(o));
                            if better {
                                let meta = serde_json::json!({
                                    "id": format!("{}-{k}", c.name()),
                                    "hunt": hunt.name(),
                                    "seed": run.seed,
                                    "index": k,
                                    "class": c.name(),
                                    "classes": v.classes.iter().map(|c| c.name()).collect::<Vec<_>>(),
                                    "mode": mode,
                                    "severity": v.severity,
                                    "engine": hunt.engine(),
                                });
                                w.insert(c, (kept, hunt.line(&case, meta)));
                            }
                        }
                    }
                    progress.inc(v.failed());
                }
                if let Ok(mut r) = report.lock() {
                    r.absorb(&local);
                }
            });
        }
    });
    progress.finish();
    let mut report = report
        .into_inner()
        .unwrap_or_else(|_| HuntReport::new(hunt.name(), run.seed, hunt.engine()));
    report.shards = vec![format!("{shard_i}/{shard_n}")];
    report.campaign_cases = run.cases;
    report.wall_seconds = start.elapsed().as_secs_f64();
    report.kept.clear();
    for (_, (kept, line)) in worst.into_inner().unwrap_or_default() {
        match fs::write(out.join(&kept.case_file), line + "\n") {
            Ok(()) => report.keep(kept),
            Err(e) => eprintln!("polyguard assure: cannot write {}: {e}", kept.case_file),
        }
    }
    finish_hunt(&report, out)
}

/// Writes report.json and summary.txt and prints the summary; exit 1 on a failure.
pub fn finish_hunt<C: HuntClass>(report: &HuntReport<C>, out: &Path) -> ExitCode {
    if let Err(code) = write_report(report, out) {
        return code;
    }
    let mut text = report.summary();
    if report.rejected > 0 {
        text += &format!("{} generated cases were rejected\n", report.rejected);
    }
    for k in &report.kept {
        text += &format!(
            "kept {} ({}, worst: severity {:e}): {}\n",
            k.class.name(),
            k.mode,
            k.severity,
            k.case_file
        );
    }
    text += &format!("report: {}\n", out.join("report.json").display());
    let _ = fs::write(out.join("summary.txt"), &text);
    print!("{text}");
    if report.failures() > 0 || report.rejected > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `assure merge` of reports in the shared shape: joins the shards (the worst case of
/// each class over all of them) and copies the kept cases' files.
pub fn merge_hunt<C: HuntClass>(
    paths: &[std::path::PathBuf],
    texts: &[String],
    out: &Path,
    partial: bool,
) -> ExitCode {
    let what = "a report of this hunt";
    let merged = read_reports(paths, texts, HuntReport::<C>::from_json, what).and_then(|reports| {
        let merged = HuntReport::merge_campaign(&reports, partial).map_err(merge_failed)?;
        copy_kept(paths, &reports, out, |r| {
            let kept = r.kept.iter().filter(|k| merged.kept.contains(k));
            kept.map(|k| k.case_file.clone()).collect()
        })?;
        Ok(merged)
    });
    match merged {
        Ok(m) => finish_hunt(&m, out),
        Err(code) => code,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The marks are the tenths of the campaign, rounded up, each once.
    #[test]
    fn progress_lines_fall_on_the_tenths() {
        let marks = |total: u64| {
            let mut out = vec![];
            let mut m = tenth_mark(total, 0);
            while m != u64::MAX {
                out.push(m);
                m = tenth_mark(total, m);
            }
            out
        };
        assert_eq!(marks(100), (1..=10).map(|i| 10 * i).collect::<Vec<_>>());
        assert_eq!(marks(25), vec![3, 5, 8, 10, 13, 15, 18, 20, 23, 25]);
        assert_eq!(marks(3), vec![1, 2, 3]);
        assert_eq!(tenth_mark(60_000, 30_000), 36_000);
    }

    /// Whatever the order the items come in, the lowest indices of each class stay.
    #[test]
    fn the_lowest_indices_of_each_class_are_kept() {
        let items = [
            (9, 'a'),
            (3, 'b'),
            (7, 'a'),
            (1, 'a'),
            (8, 'b'),
            (2, 'b'),
            (5, 'a'),
        ];
        let mut kept = vec![];
        for it in items {
            keep_lowest(&mut kept, it, 2, |x| x.0, |x| x.1);
        }
        kept.sort();
        assert_eq!(kept, vec![(1, 'a'), (2, 'b'), (3, 'b'), (5, 'a')]);
    }
}
