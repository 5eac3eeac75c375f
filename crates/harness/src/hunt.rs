//! The report shape a hunt can share (`polyguard assure --paper wayout` uses it): the
//! counts of fault classes per case and per generator mode, the time in the engine and
//! in the exact checks, and per failing class the worst case found, kept as a
//! regression line. Shards of one campaign merge exactly ([`HuntReport::merge_campaign`]):
//! every count is a sum, and the worst case of a class is the one of greatest severity,
//! ties going to the lowest case index, whatever the order of the shards.

use std::collections::BTreeMap;
use std::fmt::Debug;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

/// A hunt's classes: names, the legend, and which are failures.
pub trait HuntClass: Copy + Ord + Debug + Serialize + DeserializeOwned + 'static {
    /// Every class, in report order.
    const ALL: &'static [Self];
    /// snake_case name.
    fn name(self) -> &'static str;
    /// One line on what the class means (the summary's legend).
    fn meaning(self) -> &'static str;
    /// A failure that a campaign must report with a non-zero exit status.
    fn is_failure(self) -> bool;
}

/// The judgement of one case: its classes (each fault found once, or the non-fault
/// class), how bad its worst fault is (for choosing the worst case of a class; larger
/// is worse), and the time in the engine and in the exact checks (ns).
#[derive(Clone, Debug, PartialEq)]
pub struct Judged<C> {
    /// The classes of the case (at least one).
    pub classes: Vec<C>,
    /// The severity of its faults (0 when the hunt has no measure for them).
    pub severity: f64,
    /// ns in the engine, ns in the exact checks.
    pub nanos: [u64; 2],
}

impl<C: HuntClass> Judged<C> {
    /// Some class of the case is a failure.
    pub fn failed(&self) -> bool {
        self.classes.iter().any(|c| c.is_failure())
    }
}

/// A kept case: the worst of its class in the run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
#[serde(bound(serialize = "C: Serialize", deserialize = "C: DeserializeOwned"))]
pub struct Kept<C> {
    /// The case's index in the campaign (with the seed it regenerates the case).
    pub index: u64,
    /// The failing class it is the worst case of.
    pub class: C,
    /// The generator mode that drew it.
    pub mode: String,
    /// Its severity (see [`Judged::severity`]).
    pub severity: f64,
    /// The regression line's file, relative to the report's directory.
    pub case_file: String,
}

impl<C> Kept<C> {
    /// Is `self` worse than `o` (greater severity, else the lower index)?
    pub fn worse_than(&self, o: &Kept<C>) -> bool {
        self.severity > o.severity || (self.severity == o.severity && self.index < o.index)
    }
}

/// A hunt's report (its JSON is the campaign's report.json).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
#[serde(bound(serialize = "C: Serialize", deserialize = "C: DeserializeOwned"))]
pub struct HuntReport<C: Ord> {
    /// The hunt's name: what `assure merge` tells the hunts apart by.
    pub hunt: String,
    /// The campaign's seed.
    pub seed: u64,
    /// The campaign's size (all shards).
    pub campaign_cases: u64,
    /// The shards in this report, as "i/N".
    pub shards: Vec<String>,
    /// The engine judged (the product's name or a canary's).
    pub engine: String,
    /// Cases judged.
    pub cases: u64,
    /// Cases the generator, the engine or the oracle refused (none expected).
    pub rejected: u64,
    /// Cases with at least one failing class.
    pub failed_cases: u64,
    /// Cases per class (a case with several faults counts in each).
    pub classes: BTreeMap<C, u64>,
    /// Per generator mode, the cases drawn.
    pub mode_cases: BTreeMap<String, u64>,
    /// Per generator mode, cases per class.
    pub modes: BTreeMap<String, BTreeMap<C, u64>>,
    /// Per generator mode, ns in the engine and in the exact checks.
    pub mode_nanos: BTreeMap<String, [u64; 2]>,
    /// ns in the engine and in the exact checks, summed over the cases.
    pub nanos: [u64; 2],
    /// Seconds of the run (shards: summed).
    pub wall_seconds: f64,
    /// The worst case of each failing class.
    pub kept: Vec<Kept<C>>,
}

impl<C: HuntClass> HuntReport<C> {
    /// An empty report of the hunt `hunt`.
    pub fn new(hunt: &str, seed: u64, engine: &str) -> HuntReport<C> {
        HuntReport {
            hunt: hunt.into(),
            seed,
            campaign_cases: 0,
            shards: Vec::new(),
            engine: engine.into(),
            cases: 0,
            rejected: 0,
            failed_cases: 0,
            classes: BTreeMap::new(),
            mode_cases: BTreeMap::new(),
            modes: BTreeMap::new(),
            mode_nanos: BTreeMap::new(),
            nanos: [0; 2],
            wall_seconds: 0.0,
            kept: Vec::new(),
        }
    }

    /// Reads a report.json.
    pub fn from_json(text: &str) -> Result<HuntReport<C>, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// Counts one judged case drawn by `mode`.
    pub fn add(&mut self, j: &Judged<C>, mode: &str) {
        self.cases += 1;
        self.failed_cases += u64::from(j.failed());
        *self.mode_cases.entry(mode.into()).or_default() += 1;
        let per_mode = self.modes.entry(mode.into()).or_default();
        for &c in &j.classes {
            *self.classes.entry(c).or_default() += 1;
            *per_mode.entry(c).or_default() += 1;
        }
        let mn = self.mode_nanos.entry(mode.into()).or_default();
        for (k, &n) in j.nanos.iter().enumerate() {
            mn[k] += n;
            self.nanos[k] += n;
        }
    }

    /// Keeps `k` when it is worse than the kept case of its class (or the first).
    pub fn keep(&mut self, k: Kept<C>) {
        match self.kept.iter_mut().find(|o| o.class == k.class) {
            Some(o) if k.worse_than(o) => *o = k,
            Some(_) => {}
            None => self.kept.push(k),
        }
        self.kept.sort_by_key(|k| k.class);
    }

    /// Adds another report's counts (threads of one run, or shards of one campaign).
    pub fn absorb(&mut self, o: &HuntReport<C>) {
        self.cases += o.cases;
        self.rejected += o.rejected;
        self.failed_cases += o.failed_cases;
        for (k, n) in &o.classes {
            *self.classes.entry(*k).or_default() += n;
        }
        for (m, n) in &o.mode_cases {
            *self.mode_cases.entry(m.clone()).or_default() += n;
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
        self.nanos[0] += o.nanos[0];
        self.nanos[1] += o.nanos[1];
        self.wall_seconds += o.wall_seconds;
        for k in &o.kept {
            self.keep(k.clone());
        }
    }

    /// The shards of one campaign joined: same hunt, seed, size and engine, each shard
    /// once; a missing shard is refused unless `partial`.
    pub fn merge_campaign(
        reports: &[HuntReport<C>],
        partial: bool,
    ) -> Result<HuntReport<C>, String> {
        let first = reports.first().ok_or("no reports")?;
        let mut out = HuntReport::new(&first.hunt, first.seed, &first.engine);
        out.campaign_cases = first.campaign_cases;
        let mut seen = Vec::new();
        let mut total = None;
        for (k, r) in reports.iter().enumerate() {
            if r.hunt != first.hunt
                || r.seed != first.seed
                || r.campaign_cases != first.campaign_cases
                || r.engine != first.engine
            {
                return Err(format!(
                    "report {} is of another campaign (hunt, seed, size or engine differ)",
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

    /// Cases with a failing class.
    pub fn failures(&self) -> u64 {
        self.failed_cases
    }

    /// N of the shards' "i/N" (1 when there are none).
    fn shard_total(&self) -> u64 {
        self.shards
            .first()
            .and_then(|s| s.split_once('/'))
            .and_then(|(_, n)| n.parse().ok())
            .unwrap_or(1)
    }

    /// The verdict line: PASS or FAIL with the count of every failing class.
    pub fn verdict_line(&self) -> String {
        let verdict = if self.failures() == 0 { "PASS" } else { "FAIL" };
        let partial = if self.campaign_cases > 0 && self.shards.len() as u64 != self.shard_total() {
            " (PARTIAL)"
        } else {
            ""
        };
        let counts: Vec<String> = C::ALL
            .iter()
            .filter(|c| c.is_failure())
            .map(|c| format!("{} {}", self.classes.get(c).copied().unwrap_or(0), c.name()))
            .collect();
        format!(
            "{verdict}{partial}: {} cases (seed {}, engine {}): {}",
            self.cases,
            self.seed,
            self.engine,
            counts.join(", ")
        )
    }

    /// The human summary: the verdict, the cost per mode and the classes' legend.
    pub fn summary(&self) -> String {
        let mut s = self.verdict_line();
        s.push('\n');
        if self.cases > 0 {
            let per = |k: usize| self.nanos[k] as f64 / self.cases as f64 / 1e3;
            s.push_str(&format!(
                "time per case: engine {:.1} µs, exact checks {:.1} µs\n",
                per(0),
                per(1)
            ));
        }
        s.push_str("\nper mode: cases, engine µs and checks µs per case, failing classes\n");
        for (m, classes) in &self.modes {
            let cases = self.mode_cases.get(m).copied().unwrap_or(0);
            let f: u64 = classes
                .iter()
                .filter(|(c, _)| c.is_failure())
                .map(|(_, k)| k)
                .sum();
            let ns = self.mode_nanos.get(m).copied().unwrap_or_default();
            let per = |x: u64| x as f64 / cases.max(1) as f64 / 1e3;
            s.push_str(&format!(
                "  {m:<32} {cases:>9} {:>10.1} {:>10.1} {f:>6}\n",
                per(ns[0]),
                per(ns[1])
            ));
        }
        s.push_str("\nclasses:\n");
        for &c in C::ALL {
            let n = self.classes.get(&c).copied().unwrap_or(0);
            s.push_str(&format!("  {:<28} {:>10}  {}\n", c.name(), n, c.meaning()));
        }
        s
    }
}

/// The widths of end enclosures, in a unit of the hunt's choosing (the lookahead T for
/// the interval hunt, a second for the moving hunt), as log₂(width / unit) rounded up,
/// counted: bucket k holds the widths in (2^(k−1), 2^k] units; a width of 0 is bucket
/// −1075 (an exact end).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Widths {
    /// Count per bucket.
    pub buckets: BTreeMap<i32, u64>,
    /// The widest enclosure seen, in units.
    pub widest: f64,
}

impl Widths {
    /// Counts one enclosure of width `w`, in units of `unit`.
    pub fn add(&mut self, w: f64, unit: f64) {
        let r = w / unit;
        let k = if r > 0.0 && r.is_finite() {
            r.log2().ceil() as i32
        } else {
            -1075
        };
        *self.buckets.entry(k).or_default() += 1;
        if r.is_finite() && r > self.widest {
            self.widest = r;
        }
    }

    /// The total count.
    pub fn count(&self) -> u64 {
        self.buckets.values().sum()
    }

    /// The smallest bucket below which at least `q` of the counts lie (q in (0, 1]).
    pub fn quantile(&self, q: f64) -> Option<i32> {
        let total = self.count();
        let mut seen = 0;
        for (&k, &n) in &self.buckets {
            seen += n;
            if seen as f64 >= q * total as f64 {
                return Some(k);
            }
        }
        None
    }

    /// Adds another shard's or thread's counts.
    pub fn absorb(&mut self, o: &Widths) {
        for (&k, &n) in &o.buckets {
            *self.buckets.entry(k).or_default() += n;
        }
        self.widest = self.widest.max(o.widest);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(
        Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
    )]
    enum C {
        Fine,
        Bad,
    }

    impl HuntClass for C {
        const ALL: &'static [C] = &[C::Fine, C::Bad];
        fn name(self) -> &'static str {
            ["fine", "bad"][self as usize]
        }
        fn meaning(self) -> &'static str {
            self.name()
        }
        fn is_failure(self) -> bool {
            self == C::Bad
        }
    }

    fn kept(index: u64, severity: f64) -> Kept<C> {
        Kept {
            index,
            class: C::Bad,
            mode: "m".into(),
            severity,
            case_file: format!("counterexamples/bad-{index}.jsonl"),
        }
    }

    /// Two shards merge, in either order, into the same counts and the same worst case
    /// (greatest severity, ties to the lowest index); a missing shard is refused.
    #[test]
    fn shards_merge_in_any_order_to_the_worst_case() {
        let mut a = HuntReport::new("h", 1, "e");
        let mut b = HuntReport::new("h", 1, "e");
        let bad = |sev| Judged {
            classes: vec![C::Bad],
            severity: sev,
            nanos: [1, 2],
        };
        a.add(&bad(0.5), "m");
        a.keep(kept(0, 0.5));
        b.add(&bad(0.5), "m");
        b.keep(kept(1, 0.5));
        b.add(
            &Judged {
                classes: vec![C::Fine],
                severity: 0.0,
                nanos: [1, 2],
            },
            "n",
        );
        a.shards = vec!["0/2".into()];
        b.shards = vec!["1/2".into()];
        let ab = HuntReport::merge_campaign(&[a.clone(), b.clone()], false).expect("merge");
        let ba = HuntReport::merge_campaign(&[b.clone(), a.clone()], false).expect("merge");
        assert_eq!(ab, ba);
        assert_eq!((ab.cases, ab.failures()), (3, 2));
        assert_eq!(ab.kept, vec![kept(0, 0.5)]);
        assert!(ab.verdict_line().starts_with("FAIL: 3 cases"));
        assert!(HuntReport::merge_campaign(&[a], false).is_err());
    }
}
