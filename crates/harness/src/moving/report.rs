//! The counts of a moving hunt (`polyguard assure --paper moving`): classes per scenario,
//! per relation and per generator mode, the pairs (segment × relation) judged, the spans
//! and their certain share, the widths of the end enclosures, and the time in the engine
//! and in the truth. Shards of one campaign merge exactly
//! ([`MovingReport::merge_campaign`]).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::judge::{MovingClass, MovingVerdict};

/// A kept scenario: its index (with the seed it regenerates the scenario), class, mode
/// and file.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeptMoving {
    /// The scenario's index in the campaign.
    pub index: u64,
    /// Its class.
    pub class: MovingClass,
    /// The generator mode that drew it.
    pub mode: String,
    /// The scenario file (relative to the report's directory).
    pub case_file: String,
}

/// The widths of end enclosures, in seconds.
pub use crate::hunt::Widths;

/// One relation over a campaign.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RelationCounts {
    /// Scenarios per class.
    pub classes: BTreeMap<MovingClass, u64>,
    /// Segment × relation pairs judged.
    pub pairs: u64,
    /// Pairs whose truth is undefined.
    pub undefined_pairs: u64,
    /// Pairs whose vertical condition is unknown (no heights).
    pub vertical_unknown: u64,
    /// Spans reported.
    pub spans: u64,
    /// Of them certain.
    pub certain: u64,
    /// Exact components of the truth.
    pub components: u64,
    /// The widths of the start and end enclosures (s).
    pub widths: Widths,
}

/// The report of a moving hunt (its JSON is the campaign's report.json).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MovingReport {
    /// Always "moving": what `assure merge` tells the hunts apart by.
    pub hunt: String,
    /// The campaign's seed.
    pub seed: u64,
    /// The campaign's size (all shards).
    pub campaign_cases: u64,
    /// The shards in this report, as "i/N".
    pub shards: Vec<String>,
    /// The engine judged (`plane` or the canary's name).
    pub engine: String,
    /// Scenarios judged.
    pub cases: u64,
    /// Scenarios the engine refused (none expected).
    pub rejected: u64,
    /// Segments over the scenarios.
    pub segments: u64,
    /// Scenarios per class (the worst of their relations).
    pub classes: BTreeMap<MovingClass, u64>,
    /// Per relation ("inside", "near").
    pub relations: BTreeMap<String, RelationCounts>,
    /// Per generator mode, scenarios per class.
    pub modes: BTreeMap<String, BTreeMap<MovingClass, u64>>,
    /// Time in the engine and in the truth (ns, summed over the scenarios).
    pub nanos: [u64; 2],
    /// Seconds of the run (shards: summed).
    pub wall_seconds: f64,
    /// The first scenarios of each failing class.
    pub kept: Vec<KeptMoving>,
}

impl MovingReport {
    /// An empty report of this campaign.
    pub fn new(seed: u64, engine: &str) -> MovingReport {
        MovingReport {
            hunt: "moving".into(),
            seed,
            engine: engine.into(),
            ..Default::default()
        }
    }

    /// Reads a report.json.
    pub fn from_json(text: &str) -> Result<MovingReport, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// Counts one verdict of a scenario drawn by `mode`.
    pub fn add(&mut self, v: &MovingVerdict, mode: &str) {
        self.cases += 1;
        self.segments += v.segments as u64;
        *self.classes.entry(v.class).or_default() += 1;
        *self
            .modes
            .entry(mode.into())
            .or_default()
            .entry(v.class)
            .or_default() += 1;
        for r in &v.relations {
            let c = self.relations.entry(r.relation.into()).or_default();
            *c.classes.entry(r.class).or_default() += 1;
            c.pairs += r.pairs;
            c.undefined_pairs += r.undefined;
            c.vertical_unknown += r.vertical_unknown;
            c.spans += r.spans.len() as u64;
            c.certain += r.spans.iter().filter(|s| s.certain).count() as u64;
            c.components += r.components as u64;
            for s in &r.spans {
                for e in [s.start, s.end] {
                    c.widths.add(e[1] - e[0], 1.0);
                }
            }
        }
        for (a, b) in self.nanos.iter_mut().zip(v.nanos) {
            *a += b;
        }
    }

    /// Adds another report's counts (threads of one run, or shards of one campaign).
    pub fn absorb(&mut self, o: &MovingReport) {
        self.cases += o.cases;
        self.rejected += o.rejected;
        self.segments += o.segments;
        for (k, n) in &o.classes {
            *self.classes.entry(*k).or_default() += n;
        }
        for (name, rc) in &o.relations {
            let c = self.relations.entry(name.clone()).or_default();
            for (k, n) in &rc.classes {
                *c.classes.entry(*k).or_default() += n;
            }
            c.pairs += rc.pairs;
            c.undefined_pairs += rc.undefined_pairs;
            c.vertical_unknown += rc.vertical_unknown;
            c.spans += rc.spans;
            c.certain += rc.certain;
            c.components += rc.components;
            c.widths.absorb(&rc.widths);
        }
        for (m, classes) in &o.modes {
            let mine = self.modes.entry(m.clone()).or_default();
            for (k, n) in classes {
                *mine.entry(*k).or_default() += n;
            }
        }
        for (a, b) in self.nanos.iter_mut().zip(o.nanos) {
            *a += b;
        }
        self.wall_seconds += o.wall_seconds;
        self.kept.extend(o.kept.iter().cloned());
        self.kept.sort_by_key(|k| k.index);
    }

    /// The shards of one campaign joined: same seed, size and engine, each shard once; a
    /// missing shard is refused unless `partial`.
    pub fn merge_campaign(reports: &[MovingReport], partial: bool) -> Result<MovingReport, String> {
        let first = reports.first().ok_or("no reports")?;
        let mut out = MovingReport::new(first.seed, &first.engine);
        out.campaign_cases = first.campaign_cases;
        let mut seen = Vec::new();
        let mut total = None;
        for (k, r) in reports.iter().enumerate() {
            if r.seed != first.seed
                || r.campaign_cases != first.campaign_cases
                || r.engine != first.engine
            {
                return Err(format!(
                    "report {} is of another campaign (seed, size or engine differ)",
                    k + 1
                ));
            }
            for s in &r.shards {
                let (i, n) = s
                    .split_once('/')
                    .and_then(|(i, n)| Some((i.parse::<u64>().ok()?, n.parse::<u64>().ok()?)))
                    .ok_or_else(|| format!("report {}: shard {s:?} is not i/N", k + 1))?;
                if *total.get_or_insert(n) != n {
                    return Err(format!("report {}: shard counts differ", k + 1));
                }
                if seen.contains(&i) {
                    return Err(format!("report {}: shard {s} given twice", k + 1));
                }
                seen.push(i);
            }
            out.absorb(r);
        }
        seen.sort_unstable();
        let n = total.unwrap_or(1);
        out.shards = seen.iter().map(|i| format!("{i}/{n}")).collect();
        if seen.len() as u64 != n && !partial {
            return Err(format!(
                "{} of {n} shards given (use --partial)",
                seen.len()
            ));
        }
        Ok(out)
    }

    /// Scenarios in a failing class.
    pub fn failures(&self) -> u64 {
        self.classes
            .iter()
            .filter(|(c, _)| c.is_failure())
            .map(|(_, n)| n)
            .sum()
    }

    /// N of the shards' "i/N" (1 when there are none).
    fn shard_total(&self) -> u64 {
        self.shards
            .first()
            .and_then(|s| s.split_once('/'))
            .and_then(|(_, n)| n.parse().ok())
            .unwrap_or(1)
    }

    /// The verdict line: PASS or FAIL with the counts of the failing classes.
    pub fn verdict_line(&self) -> String {
        let count = |c: MovingClass| self.classes.get(&c).copied().unwrap_or(0);
        let verdict = if self.failures() == 0 { "PASS" } else { "FAIL" };
        let partial = if self.campaign_cases > 0 && self.shards.len() as u64 != self.shard_total() {
            " (PARTIAL)"
        } else {
            ""
        };
        format!(
            "{verdict}{partial}: {} scenarios (seed {}, engine {}): {} moving_missed, {} end_outside, {} false_certain, {} span_malformed; {} undefined",
            self.cases,
            self.seed,
            self.engine,
            count(MovingClass::MovingMissed),
            count(MovingClass::EndOutside),
            count(MovingClass::FalseCertain),
            count(MovingClass::SpanMalformed),
            count(MovingClass::Undefined),
        )
    }

    /// The human summary: the verdict, per relation the pairs, spans, certain share and
    /// enclosure widths, the costs, the modes and the legend.
    pub fn summary(&self) -> String {
        let mut s = self.verdict_line();
        s.push('\n');
        s.push_str(&format!(
            "\n{} scenarios, {} segments\n{:<8} {:>9} {:>9} {:>10} {:>9} {:>10} {:>10} {:>10}\n",
            self.cases,
            self.segments,
            "relation",
            "pairs",
            "undefined",
            "spans",
            "certain",
            "components",
            "median_w",
            "widest_w"
        ));
        for (name, c) in &self.relations {
            let share = if c.spans > 0 {
                format!("{:.1}%", 100.0 * c.certain as f64 / c.spans as f64)
            } else {
                "-".into()
            };
            let median = c.widths.quantile(0.5).map_or("-".into(), |k| {
                if k == -1075 {
                    "0 s".into()
                } else {
                    format!("2^{k} s")
                }
            });
            s.push_str(&format!(
                "{:<8} {:>9} {:>9} {:>10} {:>9} {:>10} {:>10} {:>10.1e}\n",
                name,
                c.pairs,
                c.undefined_pairs,
                c.spans,
                share,
                c.components,
                median,
                c.widths.widest
            ));
        }
        if self.cases > 0 {
            let per = |k: usize| self.nanos[k] as f64 / self.cases as f64 / 1e3;
            s.push_str(&format!(
                "time per scenario: engine {:.1} µs, exact truth {:.1} µs\n",
                per(0),
                per(1)
            ));
        }
        s.push_str("\nper mode: scenarios, failures\n");
        for (m, classes) in &self.modes {
            let n: u64 = classes.values().sum();
            let f: u64 = classes
                .iter()
                .filter(|(c, _)| c.is_failure())
                .map(|(_, k)| k)
                .sum();
            s.push_str(&format!("  {m:<16} {n:>9} {f:>6}\n"));
        }
        s.push_str("\nclasses:\n");
        for c in MovingClass::ALL {
            let n = self.classes.get(&c).copied().unwrap_or(0);
            s.push_str(&format!("  {:<16} {:>10}  {}\n", c.name(), n, c.meaning()));
        }
        s
    }
}
