//! The report of an assurance run: counts per paper function, generator mode and class,
//! timings, and the counterexamples kept. Reports of shards merge exactly.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::classify::{Class, ContractVerdict, Hunted, Verdict};

/// Counterexamples kept (minimised, written with a picture) per class: those of the
/// lowest case indices, so that the shards of a campaign merge into exactly the kept
/// cases of the whole.
pub const KEEP_PER_CLASS: usize = 5;

/// A kept counterexample (its case is written beside the report).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Kept {
    /// The case's index in the run (with the seed, it regenerates the case).
    pub index: u64,
    /// Its class.
    pub class: Class,
    /// The paper-A function that decided.
    pub method: String,
    /// The generator mode that drew it.
    pub mode: String,
    /// File names (relative to the run's directory) of the minimised case and its picture.
    pub case_file: String,
    /// See `case_file`.
    pub svg_file: String,
}

/// The contract check of an assurance run: paper A without rounding says yes ⇒ the
/// engine says yes. Its canary is the plain f64 transcription, which breaks it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Contract {
    /// Cases where paper-exact says yes.
    pub paper_yes: u64,
    /// Paper-exact yes, engine no: must be 0.
    pub violations: u64,
    /// Engine answers taken on an undecided comparison (`kind: conservative`).
    pub conservative: u64,
    /// Of those, the ones where paper-exact says no (the price of certainty).
    pub conservative_paper_no: u64,
    /// Paper-exact yes, plain f64 transcription no: the canary, expected above 0 on
    /// campaigns that reach long relative paths.
    pub plain_violations: u64,
    /// Of `paper_yes`, the ones known from the engine's certificate (a certified yes),
    /// without asking paper A (`assure --contract`); 0 in full campaigns.
    #[serde(default)]
    pub certified_yes: u64,
    /// Certified answers (yes or no, not conservative) that paper A in exact arithmetic
    /// contradicts: must be 0. Counted in classifying runs, which ask paper A on every
    /// case (a `--contract` run trusts a certified yes and counts only `violations`).
    #[serde(default)]
    pub certificate_breaches: u64,
}

impl Contract {
    fn add(&mut self, v: &Verdict) {
        self.paper_yes += u64::from(v.paper);
        self.violations += u64::from(v.paper && !v.engine);
        self.conservative += u64::from(v.conservative);
        self.conservative_paper_no += u64::from(v.conservative && !v.paper);
        self.plain_violations += u64::from(v.paper && !v.plain);
        self.certificate_breaches += u64::from(v.certificate_breach);
    }

    fn absorb(&mut self, o: &Contract) {
        self.paper_yes += o.paper_yes;
        self.violations += o.violations;
        self.conservative += o.conservative;
        self.conservative_paper_no += o.conservative_paper_no;
        self.plain_violations += o.plain_violations;
        self.certified_yes += o.certified_yes;
        self.certificate_breaches += o.certificate_breaches;
    }

    fn add_check(&mut self, v: &ContractVerdict) {
        use polyguard::Tri;
        let paper_yes = v.paper_yes();
        self.paper_yes += u64::from(paper_yes);
        self.certified_yes += u64::from(v.engine == Tri::Yes);
        self.violations += u64::from(v.is_breach());
        self.conservative += u64::from(v.engine == Tri::Unsure);
        self.conservative_paper_no += u64::from(v.engine == Tri::Unsure && v.paper == Some(false));
        self.plain_violations += u64::from(paper_yes && !v.plain);
    }
}

/// An assurance run's report (`report.json`). Read strictly (`assure merge`): an
/// unknown field is an error, so is a key given twice ([`Report::from_json`]).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Report {
    /// The run's seed.
    pub seed: u64,
    /// Shards included, as "i/N".
    pub shards: Vec<String>,
    /// The campaign's size (`--cases`): all shards together draw cases 0 … campaign_cases − 1.
    /// 0 in reports written before it was recorded, which `merge` refuses.
    #[serde(default)]
    pub campaign_cases: u64,
    /// Whether the run checked the contract alone (`--contract`): its counts cannot be
    /// merged with a classifying run's.
    #[serde(default)]
    pub contract_only: bool,
    /// The f64 engine judged: "f64" (the certified engine) or "plain" (the canary).
    #[serde(default = "certified_name")]
    pub engine: String,
    /// Shards of the campaign absent from a merge made with `--partial` (empty otherwise).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub missing_shards: Vec<String>,
    /// Cases generated.
    pub cases: u64,
    /// Cases the engine or oracle rejected (should be 0: the generator makes valid cases).
    pub rejected: u64,
    /// method → class → count.
    pub by_method: BTreeMap<String, BTreeMap<Class, u64>>,
    /// generator mode → class → count.
    pub by_mode: BTreeMap<String, BTreeMap<Class, u64>>,
    /// Coverage: generator mode → scale bucket → class → count. A bucket is named
    /// `path=1eP,buff=1eB`: the relative path is 10^P … 10^(P+1) polygon sizes and BUFF
    /// 10^B … 10^(B+1) of the polygon (`harness::gen::bucket`; the ends clamp). Empty in
    /// `--contract` runs and in reports written before coverage was recorded.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub by_bucket: BTreeMap<String, BTreeMap<String, BTreeMap<Class, u64>>>,
    /// The scale space the cases were drawn from (`assure --aim`), e.g.
    /// `path=1e-3..1e7,buff=1e-12..1e0` (the whole space).
    #[serde(default = "full_space")]
    pub space: String,
    /// Total ns in the engine, paper-exact and truth.
    pub nanos: [u64; 3],
    /// Wall-clock seconds of the run (summed over shards when merged).
    pub wall_seconds: f64,
    /// The contract check (absent from reports written before it existed).
    #[serde(default)]
    pub contract: Contract,
    /// The counterexamples kept (minimised, with pictures).
    pub kept: Vec<Kept>,
    /// The f64 entry times (`api::detect_time`) of the judged cases (absent from reports
    /// written before they were checked).
    #[serde(default)]
    pub entry: EntryStats,
}

/// What the f64 entry-time enclosures said on the cases the truth judged (class
/// `time_outside` counts the contradictions).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EntryStats {
    /// Certified "never".
    pub never: u64,
    /// Certified entries.
    pub enters: u64,
    /// Not certified either way.
    pub possible: u64,
    /// Certified entries per decade of the width (hi − lo)/T: "-11" counts widths in
    /// [10⁻¹¹, 10⁻¹⁰); "0" for a zero width.
    pub width_decades: BTreeMap<String, u64>,
    /// Total ns in `detect_time`.
    pub nanos: u64,
}

impl EntryStats {
    /// Counts one answer of a case with lookahead `t`.
    pub fn add(&mut self, e: polyguard::entry::EntryTime, t: f64, ns: u64) {
        use polyguard::entry::EntryTime;
        self.nanos = self.nanos.saturating_add(ns);
        match e {
            EntryTime::Never => self.never += 1,
            EntryTime::Possible { .. } => self.possible += 1,
            EntryTime::Enters { lo, hi } => {
                self.enters += 1;
                let w = (hi - lo) / t;
                let key = if w > 0.0 {
                    w.log10().floor().to_string()
                } else {
                    "0".into()
                };
                *self.width_decades.entry(key).or_default() += 1;
            }
        }
    }

    /// Adds another's counts.
    pub fn absorb(&mut self, o: &EntryStats) {
        self.never += o.never;
        self.enters += o.enters;
        self.possible += o.possible;
        self.nanos = self.nanos.saturating_add(o.nanos);
        for (k, n) in &o.width_decades {
            *self.width_decades.entry(k.clone()).or_default() += n;
        }
    }

    /// The summary line: the outcomes, the median and largest width decade, the time.
    pub fn line(&self) -> String {
        let judged = self.never + self.enters + self.possible;
        if judged == 0 {
            return String::new();
        }
        let mut decades: Vec<(i32, u64)> = self
            .width_decades
            .iter()
            .map(|(k, n)| {
                (
                    if k == "0" {
                        i32::MIN
                    } else {
                        k.parse().unwrap_or(0)
                    },
                    *n,
                )
            })
            .collect();
        decades.sort();
        let mut acc = 0;
        let mut median = None;
        for (d, n) in &decades {
            acc += n;
            if median.is_none() && 2 * acc >= self.enters {
                median = Some(*d);
            }
        }
        let show = |d: Option<i32>| match d {
            None => "-".to_string(),
            Some(i32::MIN) => "0".into(),
            Some(d) => format!("1e{d}"),
        };
        format!(
            "entry time (f64 enclosure): {} enters, {} possible, {} never; width/T of the certified: median below {}, largest below {}; {:.1} µs per case\n",
            self.enters,
            self.possible,
            self.never,
            show(median.map(|d| if d == i32::MIN { d } else { d + 1 })),
            show(decades.last().map(|&(d, _)| if d == i32::MIN { d } else { d + 1 })),
            self.nanos as f64 / judged as f64 / 1e3,
        )
    }
}

/// The whole scale space's label, for reports written before `space`.
fn full_space() -> String {
    crate::gen::Space::FULL.label()
}

/// A coverage bucket's name: `path=1eP,buff=1eB`.
pub fn bucket_name((path, buff): (i32, i32)) -> String {
    format!("path=1e{path},buff=1e{buff}")
}

/// The certified engine's name in reports ("f64"), for reports written before `engine`.
fn certified_name() -> String {
    Hunted::Certified.name().into()
}

/// `path=1eP,buff=1eB` → (P, B).
fn parse_bucket(name: &str) -> Option<(i32, i32)> {
    let (p, b) = name.split_once(',')?;
    let p = p.strip_prefix("path=1e")?.parse().ok()?;
    let b = b.strip_prefix("buff=1e")?.parse().ok()?;
    Some((p, b))
}

/// "i/N" → (i, N), with i < N.
fn parse_shard_name(s: &str) -> Option<(u64, u64)> {
    let (i, n) = s.split_once('/')?;
    let (i, n) = (i.parse().ok()?, n.parse().ok()?);
    (i < n).then_some((i, n))
}

/// How many of the cases 0 … cases − 1 shard i of n draws (those k with k mod n = i).
pub fn shard_size(cases: u64, i: u64, n: u64) -> u64 {
    if i >= cases {
        0
    } else {
        (cases - 1 - i) / n + 1
    }
}

impl Report {
    /// Reads a report strictly: a byte-order mark is skipped; a key given twice (which
    /// serde would resolve silently, the last count winning) and an unknown field are
    /// errors naming the line.
    pub fn from_json(text: &str) -> Result<Report, String> {
        let lines = polyguard_earth::json::Lines::new(text);
        let tree = polyguard_earth::json::parse(text).map_err(|e| {
            let (l, c) = lines.line_col(e.at);
            format!("line {l} column {c}: {}", e.message)
        })?;
        if let Some((path, at)) = polyguard_earth::json::repeated_key(&tree) {
            return Err(format!("line {}: {path}: given twice", lines.line(at)));
        }
        let body = text.strip_prefix('\u{feff}').unwrap_or(text);
        serde_json::from_str(body).map_err(|e| e.to_string())
    }

    /// Counts one verdict of a case in coverage bucket `bucket` (`harness::gen::bucket`).
    pub fn add(&mut self, v: &Verdict, mode: &str, bucket: (i32, i32)) {
        self.cases += 1;
        *self
            .by_bucket
            .entry(mode.into())
            .or_default()
            .entry(bucket_name(bucket))
            .or_default()
            .entry(v.class)
            .or_default() += 1;
        *self
            .by_method
            .entry(v.method.name().into())
            .or_default()
            .entry(v.class)
            .or_default() += 1;
        *self
            .by_mode
            .entry(mode.into())
            .or_default()
            .entry(v.class)
            .or_default() += 1;
        for k in 0..3 {
            self.nanos[k] = self.nanos[k].saturating_add(v.nanos[k]);
        }
        if v.truth.is_some() {
            self.entry.add(v.entry, v.lookahead, v.nanos[3]);
        }
        self.contract.add(v);
    }

    /// Counts one contract check (`assure --contract`: no classes).
    pub fn add_contract(&mut self, v: &ContractVerdict) {
        self.cases += 1;
        self.contract.add_check(v);
    }

    /// Totals per class.
    pub fn totals(&self) -> BTreeMap<Class, u64> {
        let mut t = BTreeMap::new();
        for m in self.by_method.values() {
            for (c, n) in m {
                *t.entry(*c).or_default() += n;
            }
        }
        t
    }

    /// Any missed detection, far false alarm, or breach of the contract?
    pub fn has_failures(&self) -> bool {
        self.contract.violations > 0
            || self.contract.certificate_breaches > 0
            || self.totals().iter().any(|(c, n)| c.is_failure() && *n > 0)
    }

    /// Adds another report's counts, times and kept cases (no seed or shard checks: for
    /// the per-thread parts of one run).
    pub fn absorb(&mut self, other: &Report) {
        self.cases += other.cases;
        self.rejected += other.rejected;
        for (dst, src) in [
            (&mut self.by_method, &other.by_method),
            (&mut self.by_mode, &other.by_mode),
        ] {
            for (k, m) in src {
                let d = dst.entry(k.clone()).or_default();
                for (c, n) in m {
                    *d.entry(*c).or_default() += n;
                }
            }
        }
        for (mode, buckets) in &other.by_bucket {
            let d = self.by_bucket.entry(mode.clone()).or_default();
            for (b, m) in buckets {
                let e = d.entry(b.clone()).or_default();
                for (c, n) in m {
                    *e.entry(*c).or_default() += n;
                }
            }
        }
        for k in 0..3 {
            self.nanos[k] = self.nanos[k].saturating_add(other.nanos[k]);
        }
        self.wall_seconds += other.wall_seconds;
        self.entry.absorb(&other.entry);
        self.contract.absorb(&other.contract);
        self.kept.extend(other.kept.iter().cloned());
    }

    /// Whether this report, the `at`-th (from 0) of a merge whose first report is
    /// `first`, is a shard of the same campaign: same seed, size, mode, space and engine,
    /// itself whole, split as the others (`n_shards`, set by the first), no shard already
    /// `seen` (shard index → report), and holding exactly its shards' cases.
    fn check_joins(
        &self,
        first: &Report,
        at: usize,
        n_shards: &mut Option<u64>,
        seen: &mut BTreeMap<u64, usize>,
    ) -> Result<(), String> {
        let which = format!("report {}", at + 1);
        if self.campaign_cases == 0 {
            return Err(format!(
                "{which} does not say its campaign's size (written before reports recorded it): run it again"
            ));
        }
        if self.seed != first.seed {
            return Err(format!(
                "{which}: seed {} where report 1 has {}",
                self.seed, first.seed
            ));
        }
        if self.campaign_cases != first.campaign_cases {
            return Err(format!(
                "{which}: a campaign of {} cases where report 1's has {}",
                self.campaign_cases, first.campaign_cases
            ));
        }
        if self.contract_only != first.contract_only {
            return Err(format!(
                "{which}: a --contract run and a classifying run cannot be merged"
            ));
        }
        if self.space != first.space {
            return Err(format!(
                "{which} draws from the scale space {}, report 1 from {}",
                self.space, first.space
            ));
        }
        if self.engine != first.engine {
            return Err(format!(
                "{which} judges the {} engine, report 1 the {} engine",
                self.engine, first.engine
            ));
        }
        if !self.missing_shards.is_empty() {
            return Err(format!("{which} is itself a partial merge"));
        }
        for s in &self.shards {
            let (i, n) =
                parse_shard_name(s).ok_or_else(|| format!("{which}: shard {s:?} is not i/N"))?;
            match *n_shards {
                None => *n_shards = Some(n),
                Some(m) if m != n => {
                    return Err(format!(
                        "{which}: shard {s} of a campaign split {n} ways, the others are split {m} ways"
                    ))
                }
                Some(_) => {}
            }
            if let Some(prev) = seen.insert(i, at) {
                return Err(format!(
                    "{which}: shard {s} is also in report {} (its cases would count twice)",
                    prev + 1
                ));
            }
        }
        let want: u64 = self
            .shards
            .iter()
            .filter_map(|s| parse_shard_name(s))
            .map(|(i, n)| shard_size(self.campaign_cases, i, n))
            .sum();
        if self.cases != want {
            return Err(format!(
                "{which}: {} cases where its shards {:?} of a {}-case campaign draw {want}",
                self.cases, self.shards, self.campaign_cases
            ));
        }
        Ok(())
    }

    /// `assure merge`: the shards of one campaign joined exactly, or an error saying why
    /// they are not one campaign. Every report must give the same seed, campaign size and
    /// mode (classifying or `--contract`) and the same shard count N; no shard may come
    /// twice; each must hold exactly the cases its shard draws. A shard of the campaign
    /// that is absent is an error unless `partial`, and is then listed in
    /// `missing_shards`.
    pub fn merge_campaign(reports: &[Report], partial: bool) -> Result<Report, String> {
        let Some(first) = reports.first() else {
            return Err("no reports to merge".into());
        };
        let mut n_shards = None;
        let mut seen: BTreeMap<u64, usize> = BTreeMap::new();
        for (at, r) in reports.iter().enumerate() {
            r.check_joins(first, at, &mut n_shards, &mut seen)?;
        }
        let n = n_shards.unwrap_or(1);
        let missing: Vec<String> = (0..n)
            .filter(|i| !seen.contains_key(i))
            .map(|i| format!("{i}/{n}"))
            .collect();
        if !missing.is_empty() && !partial {
            return Err(format!(
                "{} of the campaign are missing (merge them too, or pass --partial)",
                shard_ranges(&missing)
            ));
        }
        let mut merged = Report {
            seed: first.seed,
            campaign_cases: first.campaign_cases,
            contract_only: first.contract_only,
            engine: first.engine.clone(),
            space: first.space.clone(),
            ..Default::default()
        };
        for r in reports {
            merged.shards.extend(r.shards.iter().cloned());
            merged.absorb(r);
        }
        // The campaign keeps the lowest indices of each class: so does its merge.
        merged.kept.sort_by_key(|k| k.index);
        let mut per_class: BTreeMap<Class, usize> = BTreeMap::new();
        merged.kept.retain(|k| {
            let n = per_class.entry(k.class).or_default();
            *n += 1;
            *n <= KEEP_PER_CLASS
        });
        merged.missing_shards = missing;
        Ok(merged)
    }

    /// The summary table: per paper function and per class, counts and rates.
    pub fn table(&self) -> String {
        let mut out = String::new();
        if self.by_method.is_empty() && self.cases > 0 {
            // A contract-only campaign (`assure --contract`): no classes, no timings.
            out.push_str(&format!(
                "contract check: {} cases in {:.1} s wall ({:.0} cases/s); paper A asked on {} of them, {} certified yes\n",
                self.cases,
                self.wall_seconds,
                if self.wall_seconds > 0.0 { self.cases as f64 / self.wall_seconds } else { 0.0 },
                self.cases - self.contract.certified_yes,
                self.contract.certified_yes,
            ));
            out.push_str(&self.contract_lines());
            return out;
        }
        // Counts per paper function and class, then the rates of the whole: at most
        // 105 columns ([`Class::short`] heads the columns; the legend explains them).
        let classes = Class::ALL;
        out.push_str(&format!("{:<15}{:>9}", "function", "cases"));
        for c in classes {
            out.push_str(&format!("{:>9}", c.short()));
        }
        out.push('\n');
        let mut rows: Vec<(String, BTreeMap<Class, u64>)> = self
            .by_method
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        let totals = self.totals();
        rows.push(("all".into(), totals.clone()));
        for (name, counts) in rows {
            let total: u64 = counts.values().sum();
            out.push_str(&format!("{name:<15}{total:>9}"));
            for c in classes {
                out.push_str(&format!("{:>9}", counts.get(&c).copied().unwrap_or(0)));
            }
            out.push('\n');
        }
        let all: u64 = totals.values().sum();
        out.push_str(&format!("{:<15}{:>9}", "all, % ", ""));
        for c in classes {
            let n = totals.get(&c).copied().unwrap_or(0);
            let pct = if all == 0 {
                0.0
            } else {
                100.0 * n as f64 / all as f64
            };
            out.push_str(&format!("{:>9}", format!("{pct:.3}")));
        }
        out.push('\n');
        let per = |ns: u64| {
            if self.cases == 0 {
                0.0
            } else {
                ns as f64 / self.cases as f64
            }
        };
        out.push_str(&format!(
            "time per case: engine {:.0} ns, paper-exact {:.0} ns, truth {:.0} ns; {} cases in {:.1} s wall ({:.0} cases/s)\n",
            per(self.nanos[0]),
            per(self.nanos[1]),
            per(self.nanos[2]),
            self.cases,
            self.wall_seconds,
            if self.wall_seconds > 0.0 { self.cases as f64 / self.wall_seconds } else { 0.0 },
        ));
        out.push_str(&self.entry.line());
        out.push_str(&self.contract_lines());
        out
    }

    /// The legend of the table's columns, one line a class.
    pub fn legend() -> String {
        let mut out = String::from("classes:\n");
        for c in Class::ALL {
            out.push_str(&format!(
                "  {:<9} {:<20} {}\n",
                c.short(),
                c.name(),
                c.meaning()
            ));
        }
        out
    }

    /// The coverage grid: cases per scale bucket, all modes together (rows: BUFF per
    /// polygon size, columns: relative path per polygon size, decades), `.` for an empty
    /// bucket, `!` after a count that includes a failure. The report holds the grid per
    /// mode and class; [`Report::coverage_view`] shows any of it.
    pub fn coverage_grid(&self) -> String {
        self.coverage_view(None, None).unwrap_or_default()
    }

    /// The generator modes the coverage holds.
    pub fn coverage_modes(&self) -> Vec<String> {
        self.by_bucket.keys().cloned().collect()
    }

    /// A coverage grid of the modes whose name starts with `mode` (all when `None`):
    /// the count of cases per bucket, or with `class` the percentage of that class among
    /// the bucket's cases. `None` when no mode matches.
    pub fn coverage_view(&self, mode: Option<&str>, class: Option<Class>) -> Option<String> {
        // per bucket: (cases, of the class, any failure)
        let mut grid: BTreeMap<(i32, i32), (u64, u64, bool)> = BTreeMap::new();
        let mut matched = false;
        for (m, buckets) in &self.by_bucket {
            if mode.is_some_and(|want| !m.starts_with(want)) {
                continue;
            }
            matched = true;
            for (name, counts) in buckets {
                let Some(key) = parse_bucket(name) else {
                    continue;
                };
                let e = grid.entry(key).or_default();
                e.0 += counts.values().sum::<u64>();
                e.1 += class.and_then(|c| counts.get(&c)).copied().unwrap_or(0);
                e.2 |= counts.iter().any(|(c, n)| c.is_failure() && *n > 0);
            }
        }
        if !matched {
            return None;
        }
        let compact = |n: u64| match n {
            0..=9_999 => n.to_string(),
            10_000..=999_999 => format!("{}k", n / 1000),
            _ => format!("{}M", n / 1_000_000),
        };
        let what = match class {
            None => "cases".to_string(),
            Some(c) => format!("% {}", c.name()),
        };
        let modes = mode.map_or("all modes".to_string(), |m| format!("modes {m}*"));
        let mut out = format!(
            "coverage ({modes}): {what} per bucket (rows BUFF/size, columns relative path/size, decades)\n"
        );
        out.push_str(&format!("{:>10}", "buff\\path"));
        for p in -3..=7 {
            out.push_str(&format!("{:>7}", format!("1e{p}")));
        }
        out.push('\n');
        for b in (-12..=0).rev() {
            out.push_str(&format!("{:>10}", format!("1e{b}")));
            for p in -3..=7 {
                let cell = match grid.get(&(p, b)) {
                    None | Some((0, _, _)) => ".".to_string(),
                    Some((n, k, bad)) => {
                        let v = match class {
                            None => compact(*n),
                            Some(_) => format!("{:.2}", 100.0 * *k as f64 / *n as f64),
                        };
                        format!("{v}{}", if *bad { "!" } else { "" })
                    }
                };
                out.push_str(&format!("{cell:>7}"));
            }
            out.push('\n');
        }
        Some(out)
    }

    /// The one verdict line that ends a campaign's summary: PASS or FAIL, with the counts
    /// of missed detections, far false alarms and contract breaches.
    pub fn verdict_line(&self) -> String {
        let t = self.totals();
        let n = |c: Class| t.get(&c).copied().unwrap_or(0);
        let (missed, far) = (n(Class::MissedDetection), n(Class::FalseAlarmFar));
        let word = if self.has_failures() { "FAIL" } else { "PASS" };
        let partial = if self.missing_shards.is_empty() {
            ""
        } else {
            " (PARTIAL)"
        };
        if self.contract_only {
            return format!(
                "{word}{partial}: {} contract breaches in {} cases ({} engine)\n",
                self.contract.violations, self.cases, self.engine
            );
        }
        format!(
            "{word}{partial}: {missed} missed detections, {far} far false alarms, {} entry times outside their enclosure, {} contract breaches in {} cases ({} engine); {} conservative far alarms, {} undefined\n",
            n(Class::TimeOutside),
            self.contract.violations + self.contract.certificate_breaches,
            self.cases,
            self.engine,
            n(Class::ConservativeFar),
            n(Class::Undefined)
        )
    }

    /// The contract's lines of the summary.
    fn contract_lines(&self) -> String {
        let mut out = String::new();
        let c = &self.contract;
        out.push_str(&format!(
            "contract paper-exact => engine: {} violations in {} paper-exact yes (canary, plain f64 transcription: {} violations)\n",
            c.violations, c.paper_yes, c.plain_violations
        ));
        if !self.contract_only {
            out.push_str(&format!(
                "certificate: {} certified answers contradicted by paper-exact\n",
                c.certificate_breaches
            ));
        }
        out.push_str(&self.conservative_line());
        out
    }

    /// The rate of conservative answers as one line a document can quote: the counts,
    /// the rates, and where the cases were drawn (the seed, and the scale space with how
    /// many cases sit at the ends of the float range, which is where most conservative
    /// answers are: `--aim ends=none` and `ends=all` measure the two apart).
    pub fn conservative_line(&self) -> String {
        let c = &self.contract;
        let pct = |n: u64| {
            if self.cases == 0 {
                0.0
            } else {
                100.0 * n as f64 / self.cases as f64
            }
        };
        // the space's label leaves out the default ends (one case in eight): say it
        let space = if self.space.contains("ends=") {
            self.space.clone()
        } else {
            format!("{},ends={}", self.space, crate::gen::Ends::Eighth.name())
        };
        format!(
            "conservative answers (an undecided comparison): {} of {} cases ({:.4} %), {} of them where paper-exact says no ({:.4} %); seed {}, space {space}\n",
            c.conservative,
            self.cases,
            pct(c.conservative),
            c.conservative_paper_no,
            pct(c.conservative_paper_no),
            self.seed,
        )
    }
}

/// Shards written "i/N" (as `missing_shards` lists them), said briefly: consecutive
/// indices as ranges, "shards 3-5, 9 of 10 (4 shards)"; a list that is not of that form
/// is said as it is.
pub fn shard_ranges(shards: &[String]) -> String {
    let parsed: Option<Vec<(u64, u64)>> = shards
        .iter()
        .map(|s| {
            let (i, n) = s.split_once('/')?;
            Some((i.parse().ok()?, n.parse().ok()?))
        })
        .collect();
    let Some(parsed) = parsed.filter(|p| !p.is_empty() && p.iter().all(|q| q.1 == p[0].1)) else {
        return format!("shards {}", shards.join(", "));
    };
    let mut idx: Vec<u64> = parsed.iter().map(|q| q.0).collect();
    idx.sort_unstable();
    idx.dedup();
    let mut parts: Vec<String> = Vec::new();
    let mut k = 0;
    while k < idx.len() {
        let start = idx[k];
        while k + 1 < idx.len() && idx[k + 1] == idx[k] + 1 {
            k += 1;
        }
        parts.push(if idx[k] == start {
            start.to_string()
        } else {
            format!("{start}-{}", idx[k])
        });
        k += 1;
    }
    let count = idx.len();
    let noun = if count == 1 { "shard" } else { "shards" };
    format!(
        "{noun} {} of {} ({count} {noun})",
        parts.join(", "),
        parsed[0].1
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use polyguard::detect::Method;

    fn verdict(class: Class, method: Method) -> Verdict {
        Verdict {
            class,
            method,
            engine: true,
            conservative: false,
            certificate_breach: false,
            plain: true,
            paper: true,
            truth: Some(true),
            entry_time: None,
            lookahead: 1.0,
            entry: polyguard::entry::EntryTime::Enters { lo: 0.5, hi: 0.5 },
            time_failure: None,
            nanos: [1, 2, 3, 4],
        }
    }

    /// A shard of `cases` cases with `n` verdicts drawn (`missed` of them misses).
    fn shard(seed: u64, cases: u64, i: u64, n: u64, missed: u64) -> Report {
        let mut r = Report {
            seed,
            campaign_cases: cases,
            shards: vec![format!("{i}/{n}")],
            ..Default::default()
        };
        for j in 0..shard_size(cases, i, n) {
            let class = if j < missed {
                Class::MissedDetection
            } else {
                Class::Agree
            };
            r.add(&verdict(class, Method::DetectSame2d), "free", (1, -3));
        }
        r
    }

    /// The conservative answers' line says its counts, rates, seed and space, the ends of
    /// the float range included when the label leaves the default out.
    #[test]
    fn the_conservative_line_says_where_its_cases_were_drawn() {
        let mut r = Report {
            seed: 2,
            space: crate::gen::Space::FULL.label(),
            ..Default::default()
        };
        for k in 0..8 {
            let mut v = verdict(Class::Agree, Method::DetectSame2d);
            v.conservative = k < 2;
            v.paper = k != 0;
            r.add(&v, "free", (1, -3));
        }
        assert_eq!(
            r.conservative_line(),
            "conservative answers (an undecided comparison): 2 of 8 cases (25.0000 %), 1 of \
             them where paper-exact says no (12.5000 %); seed 2, space \
             path=1e-3..1e7,buff=1e-12..1e0,ends=eighth\n"
        );
        r.space = crate::gen::Space::FULL
            .with_ends(crate::gen::Ends::None)
            .label();
        assert!(r
            .conservative_line()
            .ends_with(",buff=1e-12..1e0,ends=none\n"));
    }

    /// The coverage views count cases per bucket and mode, and give a class's rate.
    #[test]
    fn coverage_views_count_and_rate() {
        let mut r = Report::default();
        r.add(
            &verdict(Class::Agree, Method::DetectSame2d),
            "free",
            (2, -5),
        );
        r.add(
            &verdict(Class::FalseAlarmInBand, Method::DetectSame2d),
            "free",
            (2, -5),
        );
        r.add(
            &verdict(Class::Agree, Method::DetectSame2d),
            "free",
            (2, -5),
        );
        r.add(
            &verdict(Class::MissedDetection, Method::DetectSame2d),
            "edge_buff",
            (-3, 0),
        );
        let row = |grid: &str, label: &str| -> Vec<String> {
            grid.lines()
                .find(|l| l.split_whitespace().next() == Some(label))
                .map(|l| l.split_whitespace().skip(1).map(String::from).collect())
                .unwrap_or_default()
        };
        let all = r.coverage_grid();
        // columns 1e-3 … 1e7: path 1e2 is the 6th
        assert_eq!(row(&all, "1e-5")[5], "3");
        assert_eq!(row(&all, "1e0")[0], "1!", "a failure is marked");
        assert_eq!(row(&all, "1e-6")[5], ".", "an empty bucket");
        let rate = r
            .coverage_view(Some("free"), Some(Class::FalseAlarmInBand))
            .expect("the mode exists");
        assert_eq!(row(&rate, "1e-5")[5], "33.33");
        assert_eq!(row(&rate, "1e0")[0], ".", "edge_buff is not shown");
        assert!(r.coverage_view(Some("vertex"), None).is_none());
    }

    #[test]
    fn shard_sizes_cover_the_campaign() {
        for cases in [0, 1, 2, 5, 7, 100] {
            for n in 1..6 {
                let total: u64 = (0..n).map(|i| shard_size(cases, i, n)).sum();
                assert_eq!(total, cases, "{cases} cases in {n} shards");
                for i in 0..n {
                    let direct = (0..cases).filter(|k| k % n == i).count() as u64;
                    assert_eq!(shard_size(cases, i, n), direct);
                }
            }
        }
    }

    #[test]
    fn merge_adds_exactly() {
        let (a, b) = (shard(1, 5, 0, 2, 1), shard(1, 5, 1, 2, 0));
        let m = Report::merge_campaign(&[a, b], false).expect("one campaign");
        assert_eq!(m.cases, 5);
        assert_eq!(m.campaign_cases, 5);
        assert_eq!(m.totals()[&Class::Agree], 4);
        assert_eq!(m.by_mode["free"][&Class::MissedDetection], 1);
        assert_eq!(m.nanos, [5, 10, 15]);
        assert!(m.has_failures());
        assert!(m.missing_shards.is_empty());
        // JSON round trip.
        let json = serde_json::to_string(&m).expect("serialise");
        let back = Report::from_json(&json).expect("parse");
        assert_eq!(back, m);
    }

    /// Each way a merge could lie (counting cases twice, mixing campaigns) is refused,
    /// and says why.
    #[test]
    fn merges_that_would_lie_are_refused() {
        let err = |rs: &[Report], partial: bool| {
            Report::merge_campaign(rs, partial)
                .err()
                .unwrap_or_default()
        };
        // one shard alone is not the campaign
        assert!(err(&[shard(1, 5000, 0, 2, 0)], false)
            .contains("shard 1 of 2 (1 shard) of the campaign are missing"));
        // shards of a 5,000- and a 6,000-case campaign
        assert!(
            err(&[shard(1, 5000, 0, 2, 0), shard(1, 6000, 1, 2, 0)], false).contains("6000 cases")
        );
        // a full run plus a shard: split 1 way and 2 ways
        assert!(
            err(&[shard(1, 50, 0, 1, 0), shard(1, 50, 1, 2, 0)], false).contains("split 2 ways")
        );
        // the same shard twice
        assert!(err(&[shard(1, 50, 0, 2, 0), shard(1, 50, 0, 2, 0)], false).contains("count twice"));
        // different seeds
        assert!(err(&[shard(1, 50, 0, 2, 0), shard(2, 50, 1, 2, 0)], false).contains("seed 2"));
        // a shard whose counts do not match its size
        let mut short = shard(1, 50, 1, 2, 0);
        short.cases -= 1;
        assert!(err(&[shard(1, 50, 0, 2, 0), short], false).contains("draw 25"));
        // a report from before campaign sizes were recorded
        let mut old = shard(1, 50, 0, 1, 0);
        old.campaign_cases = 0;
        assert!(err(&[old], false).contains("run it again"));
        // contract-only and classifying runs
        let mut contract = shard(1, 50, 1, 2, 0);
        contract.contract_only = true;
        assert!(err(&[shard(1, 50, 0, 2, 0), contract], false).contains("--contract"));
    }

    #[test]
    fn a_partial_merge_says_what_is_missing() {
        // Said briefly: 97 missing shards of 100 make one range, not 97 names.
        let many: Vec<String> = (3..100).map(|i| format!("{i}/100")).collect();
        assert_eq!(shard_ranges(&many), "shards 3-99 of 100 (97 shards)");
        let gaps: Vec<String> = ["9/10", "3/10", "4/10", "5/10"].map(String::from).to_vec();
        assert_eq!(shard_ranges(&gaps), "shards 3-5, 9 of 10 (4 shards)");
        let m = Report::merge_campaign(&[shard(1, 90, 2, 3, 0)], true).expect("partial");
        assert_eq!(m.missing_shards, vec!["0/3".to_owned(), "1/3".to_owned()]);
        assert_eq!(
            shard_ranges(&m.missing_shards),
            "shards 0-1 of 3 (2 shards)"
        );
        assert_eq!(m.cases, 30);
        // and a partial merge is not merged again as if it were whole
        assert!(Report::merge_campaign(&[m], true).is_err());
    }

    /// A merge reads reports strictly: a misspelt field, or a count given twice (serde
    /// would keep the last), is an error naming it; a byte-order mark is fine.
    #[test]
    fn merges_read_reports_strictly() {
        let mut r = Report {
            seed: 1,
            shards: vec!["0/1".into()],
            ..Default::default()
        };
        r.add(
            &verdict(Class::Agree, Method::DetectSame2d),
            "free",
            (0, -2),
        );
        let json = serde_json::to_string_pretty(&r).expect("serialise");
        assert_eq!(Report::from_json(&format!("\u{feff}{json}")), Ok(r.clone()));
        let typo = json.replacen("\"rejected\"", "\"rejectd\"", 1);
        let e = Report::from_json(&typo).expect_err("unknown field");
        assert!(e.contains("unknown field `rejectd`"), "{e}");
        let twice = json.replacen("\"agree\": 1", "\"agree\": 1, \"agree\": 5", 1);
        assert_ne!(twice, json);
        let e = Report::from_json(&twice).expect_err("repeated key");
        assert!(
            e.ends_with("by_method.detect_same_2d.agree: given twice"),
            "{e}"
        );
        assert!(e.starts_with("line "), "{e}");
    }
}
