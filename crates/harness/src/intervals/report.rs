//! The counts of an interval hunt (`polyguard assure --intervals`): classes per case,
//! per relation and per generator mode, the widths of the end enclosures, the share of
//! possible spans, the exit answers against the truth, and the time spent. Shards of one
//! campaign merge exactly ([`IntervalReport::merge_campaign`]).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::judge::{IntervalClass, IntervalVerdict};
use polyguard::Tri;

/// A kept case: its index (with the seed it regenerates the case), class, mode and file.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeptInterval {
    /// The case's index in the campaign.
    pub index: u64,
    /// Its class.
    pub class: IntervalClass,
    /// The generator mode that drew it.
    pub mode: String,
    /// The case file (relative to the report's directory), with the engine's spans and the
    /// truth in its `meta`.
    pub case_file: String,
}

/// The widths of end enclosures, in units of the case's lookahead T.
pub use crate::hunt::Widths;

/// The spans of one relation over a campaign.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RelationCounts {
    /// Cases per class.
    pub classes: BTreeMap<IntervalClass, u64>,
    /// Spans reported.
    pub spans: u64,
    /// Of them certain.
    pub certain: u64,
    /// Exact components of the truth.
    pub components: u64,
    /// Cases with at least two components.
    pub multi: u64,
    /// The widths of the start and end enclosures (of ends inside (0, T)).
    pub widths: Widths,
}

/// The report of an interval hunt (its JSON is the campaign's report.json).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IntervalReport {
    /// Always "intervals": what `assure merge` tells the hunts apart by.
    pub hunt: String,
    /// The campaign's seed.
    pub seed: u64,
    /// The campaign's size (all shards).
    pub campaign_cases: u64,
    /// The shards in this report, as "i/N".
    pub shards: Vec<String>,
    /// The engine judged (`f64` or a canary's name).
    pub engine: String,
    /// The scale space of the threshold half.
    pub space: String,
    /// Cases judged.
    pub cases: u64,
    /// Cases the engine or the oracle refused (none expected).
    pub rejected: u64,
    /// Cases per class (the worst of a case's relations and exit).
    pub classes: BTreeMap<IntervalClass, u64>,
    /// Per relation ("inside", "near", "breach").
    pub relations: BTreeMap<String, RelationCounts>,
    /// Per generator mode, cases per class.
    pub modes: BTreeMap<String, BTreeMap<IntervalClass, u64>>,
    /// Per generator mode, the time in the engine's intervals and in the truth (ns).
    pub mode_nanos: BTreeMap<String, [u64; 2]>,
    /// Exit answers: "truth/engine" (truth yes|no|undefined, engine yes|no|unsure) → count.
    pub exits: BTreeMap<String, u64>,
    /// Time in the engine's intervals, the oracle's, the exit detection and detect_time
    /// (ns, summed over the cases).
    pub nanos: [u64; 4],
    /// Seconds of the run (shards: summed).
    pub wall_seconds: f64,
    /// The first cases of each failing class.
    pub kept: Vec<KeptInterval>,
}

/// A three-valued answer's name.
fn tri_name(t: Tri) -> &'static str {
    match t {
        Tri::Yes => "yes",
        Tri::No => "no",
        Tri::Unsure => "unsure",
    }
}

impl IntervalReport {
    /// An empty report of this campaign.
    pub fn new(seed: u64, engine: &str, space: String) -> IntervalReport {
        IntervalReport {
            hunt: "intervals".into(),
            seed,
            engine: engine.into(),
            space,
            ..Default::default()
        }
    }

    /// Reads a report.json.
    pub fn from_json(text: &str) -> Result<IntervalReport, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// Counts one verdict of a case drawn by `mode`.
    pub fn add(&mut self, v: &IntervalVerdict, mode: &str) {
        self.cases += 1;
        *self.classes.entry(v.class).or_default() += 1;
        *self
            .modes
            .entry(mode.into())
            .or_default()
            .entry(v.class)
            .or_default() += 1;
        let mn = self.mode_nanos.entry(mode.into()).or_default();
        mn[0] += v.nanos[0];
        mn[1] += v.nanos[1];
        let t = v.lookahead;
        for r in &v.relations {
            let c = self.relations.entry(r.relation.name().into()).or_default();
            *c.classes.entry(r.class).or_default() += 1;
            c.spans += r.spans.len() as u64;
            c.certain += r.spans.iter().filter(|s| s.certain).count() as u64;
            c.components += r.components as u64;
            c.multi += u64::from(r.components >= 2);
            for s in &r.spans {
                for e in [s.start, s.end] {
                    // the ends at 0 and T are not ends the engine had to find
                    if e.hi > 0.0 && e.lo < t {
                        c.widths.add(e.hi - e.lo, t);
                    }
                }
            }
        }
        let truth = match v.exit_truth {
            Some(true) => "yes",
            Some(false) => "no",
            None => "undefined",
        };
        *self
            .exits
            .entry(format!("{truth}/{}", tri_name(v.exit_engine)))
            .or_default() += 1;
        for (a, b) in self.nanos.iter_mut().zip(v.nanos) {
            *a += b;
        }
    }

    /// Adds another report's counts (threads of one run, or shards of one campaign).
    pub fn absorb(&mut self, o: &IntervalReport) {
        self.cases += o.cases;
        self.rejected += o.rejected;
        for (k, n) in &o.classes {
            *self.classes.entry(*k).or_default() += n;
        }
        for (name, rc) in &o.relations {
            let c = self.relations.entry(name.clone()).or_default();
            for (k, n) in &rc.classes {
                *c.classes.entry(*k).or_default() += n;
            }
            c.spans += rc.spans;
            c.certain += rc.certain;
            c.components += rc.components;
            c.multi += rc.multi;
            c.widths.absorb(&rc.widths);
        }
        for (m, classes) in &o.modes {
            let mine = self.modes.entry(m.clone()).or_default();
            for (k, n) in classes {
                *mine.entry(*k).or_default() += n;
            }
        }
        for (m, ns) in &o.mode_nanos {
            let mine = self.mode_nanos.entry(m.clone()).or_default();
            mine[0] += ns[0];
            mine[1] += ns[1];
        }
        for (k, n) in &o.exits {
            *self.exits.entry(k.clone()).or_default() += n;
        }
        for (a, b) in self.nanos.iter_mut().zip(o.nanos) {
            *a += b;
        }
        self.wall_seconds += o.wall_seconds;
        self.kept.extend(o.kept.iter().cloned());
        self.kept.sort_by_key(|k| k.index);
    }

    /// The shards of one campaign joined: same seed, size, engine and space, each shard
    /// once; a missing shard is refused unless `partial`.
    pub fn merge_campaign(
        reports: &[IntervalReport],
        partial: bool,
    ) -> Result<IntervalReport, String> {
        let first = reports.first().ok_or("no reports")?;
        let mut out = IntervalReport::new(first.seed, &first.engine, first.space.clone());
        out.campaign_cases = first.campaign_cases;
        let mut seen = Vec::new();
        let mut total = None;
        for (k, r) in reports.iter().enumerate() {
            let same = r.seed == first.seed
                && r.campaign_cases == first.campaign_cases
                && r.engine == first.engine
                && r.space == first.space;
            if !same {
                return Err(format!(
                    "report {} is of another campaign (seed, size, engine or space differ)",
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
        out.shards = seen
            .iter()
            .map(|i| format!("{i}/{}", total.unwrap_or(1)))
            .collect();
        let n = total.unwrap_or(1);
        if seen.len() as u64 != n && !partial {
            return Err(format!(
                "{} of {n} shards given (use --partial)",
                seen.len()
            ));
        }
        Ok(out)
    }

    /// Cases in a failing class.
    pub fn failures(&self) -> u64 {
        self.classes
            .iter()
            .filter(|(c, _)| c.is_failure())
            .map(|(_, n)| n)
            .sum()
    }

    /// The verdict line: PASS or FAIL with the counts of the failing classes.
    pub fn verdict_line(&self) -> String {
        let count = |c: IntervalClass| self.classes.get(&c).copied().unwrap_or(0);
        let verdict = if self.failures() == 0 { "PASS" } else { "FAIL" };
        let partial = if self.campaign_cases > 0 && self.shards.len() as u64 != self.shard_total() {
            " (PARTIAL)"
        } else {
            ""
        };
        format!(
            "{verdict}{partial}: {} cases (seed {}, engine {}): {} interval_missed, {} end_outside, {} interval_false, {} span_malformed, {} exit_missed, {} exit_false; {} undefined",
            self.cases,
            self.seed,
            self.engine,
            count(IntervalClass::IntervalMissed),
            count(IntervalClass::EndOutside),
            count(IntervalClass::IntervalFalse),
            count(IntervalClass::SpanMalformed),
            count(IntervalClass::ExitMissed),
            count(IntervalClass::ExitFalse),
            count(IntervalClass::Undefined),
        )
    }

    /// N of the shards' "i/N" (1 when there are none).
    fn shard_total(&self) -> u64 {
        self.shards
            .first()
            .and_then(|s| s.split_once('/'))
            .and_then(|(_, n)| n.parse().ok())
            .unwrap_or(1)
    }

    /// The human summary: the verdict, the classes per relation, the widths, the share
    /// of possible spans, the exits and the costs.
    pub fn summary(&self) -> String {
        let mut s = String::new();
        s.push_str(&self.verdict_line());
        s.push('\n');
        s.push_str(&format!(
            "\n{:<8} {:>10} {:>10} {:>10} {:>9} {:>10} {:>10} {:>10}\n",
            "relation", "cases", "spans", "possible", "multi", "median_w", "p99_w", "widest_w"
        ));
        for (name, c) in &self.relations {
            let cases: u64 = c.classes.values().sum();
            let q = |p: f64| {
                c.widths
                    .quantile(p)
                    .map_or("-".into(), |k| format!("2^{k}·T"))
            };
            s.push_str(&format!(
                "{:<8} {:>10} {:>10} {:>10} {:>9} {:>10} {:>10} {:>10.1e}\n",
                name,
                cases,
                c.spans,
                c.spans - c.certain,
                c.multi,
                q(0.5),
                q(0.99),
                c.widths.widest
            ));
        }
        s.push_str("\nexit answers (truth/engine):");
        for (k, n) in &self.exits {
            s.push_str(&format!(" {k} {n};"));
        }
        s.push('\n');
        if self.cases > 0 {
            let per = |k: usize| self.nanos[k] as f64 / self.cases as f64 / 1e3;
            s.push_str(&format!(
                "time per case: engine intervals (3 relations) {:.1} µs, exact truth {:.1} µs, exit {:.2} µs, detect_time {:.2} µs\n",
                per(0),
                per(1),
                per(2),
                per(3)
            ));
        }
        s.push_str("\nper mode: cases, engine µs and truth µs per case, failures\n");
        for (m, classes) in &self.modes {
            let n: u64 = classes.values().sum();
            let f: u64 = classes
                .iter()
                .filter(|(c, _)| c.is_failure())
                .map(|(_, k)| k)
                .sum();
            let ns = self.mode_nanos.get(m).copied().unwrap_or_default();
            let per = |x: u64| x as f64 / n.max(1) as f64 / 1e3;
            s.push_str(&format!(
                "  {m:<28} {n:>9} {:>10.1} {:>10.1} {f:>6}\n",
                per(ns[0]),
                per(ns[1])
            ));
        }
        s.push_str("\nclasses:\n");
        for c in IntervalClass::ALL {
            let n = self.classes.get(&c).copied().unwrap_or(0);
            s.push_str(&format!("  {:<16} {:>10}  {}\n", c.name(), n, c.meaning()));
        }
        s
    }
}
