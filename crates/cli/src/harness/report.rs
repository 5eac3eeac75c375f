//! The report of an assurance run: counts per paper function, generator mode and class,
//! timings, and the counterexamples kept. Reports of shards merge exactly.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::classify::{Class, ContractVerdict, Verdict};

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
}

impl Contract {
    fn add(&mut self, v: &Verdict) {
        self.paper_yes += u64::from(v.paper);
        self.violations += u64::from(v.paper && !v.engine);
        self.conservative += u64::from(v.conservative);
        self.conservative_paper_no += u64::from(v.conservative && !v.paper);
        self.plain_violations += u64::from(v.paper && !v.plain);
    }

    fn absorb(&mut self, o: &Contract) {
        self.paper_yes += o.paper_yes;
        self.violations += o.violations;
        self.conservative += o.conservative;
        self.conservative_paper_no += o.conservative_paper_no;
        self.plain_violations += o.plain_violations;
        self.certified_yes += o.certified_yes;
    }

    fn add_check(&mut self, v: &ContractVerdict) {
        use polyguard::ball::Tri;
        let paper_yes = v.engine == Tri::Yes || v.paper == Some(true);
        self.paper_yes += u64::from(paper_yes);
        self.certified_yes += u64::from(v.engine == Tri::Yes);
        self.violations += u64::from(paper_yes && v.engine == Tri::No);
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
    /// Cases generated.
    pub cases: u64,
    /// Cases the engine or oracle rejected (should be 0: the generator makes valid cases).
    pub rejected: u64,
    /// method → class → count.
    pub by_method: BTreeMap<String, BTreeMap<Class, u64>>,
    /// generator mode → class → count.
    pub by_mode: BTreeMap<String, BTreeMap<Class, u64>>,
    /// Total ns in the engine, paper-exact and truth.
    pub nanos: [u64; 3],
    /// Wall-clock seconds of the run (summed over shards when merged).
    pub wall_seconds: f64,
    /// The contract check (absent from reports written before it existed).
    #[serde(default)]
    pub contract: Contract,
    /// The counterexamples kept (minimised, with pictures).
    pub kept: Vec<Kept>,
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

    /// Counts one verdict.
    pub fn add(&mut self, v: &Verdict, mode: &str) {
        self.cases += 1;
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
        self.contract.violations > 0 || self.totals().iter().any(|(c, n)| c.is_failure() && *n > 0)
    }

    /// Joins another shard's report of the same seed: every count adds exactly.
    pub fn merge(&mut self, other: &Report) -> Result<(), String> {
        if self.cases > 0 && other.seed != self.seed {
            return Err(format!("seeds differ: {} and {}", self.seed, other.seed));
        }
        if let Some(s) = other.shards.iter().find(|s| self.shards.contains(s)) {
            return Err(format!("shard {s} is in both reports"));
        }
        self.seed = other.seed;
        self.shards.extend(other.shards.iter().cloned());
        self.absorb(other);
        Ok(())
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
        for k in 0..3 {
            self.nanos[k] = self.nanos[k].saturating_add(other.nanos[k]);
        }
        self.wall_seconds += other.wall_seconds;
        self.contract.absorb(&other.contract);
        self.kept.extend(other.kept.iter().cloned());
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
        let classes = Class::ALL;
        out.push_str(&format!("{:<16}", "function"));
        for c in classes {
            out.push_str(&format!(" {:>20}", c.name()));
        }
        out.push('\n');
        let mut rows: Vec<(String, BTreeMap<Class, u64>)> = self
            .by_method
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        rows.push(("all".into(), self.totals()));
        for (name, counts) in rows {
            let total: u64 = counts.values().sum();
            out.push_str(&format!("{name:<16}"));
            for c in classes {
                let n = counts.get(&c).copied().unwrap_or(0);
                let rate = if total == 0 {
                    0.0
                } else {
                    n as f64 / total as f64
                };
                out.push_str(&format!(" {:>9} ({:>7.3}%)", n, 100.0 * rate));
            }
            out.push('\n');
        }
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
        out.push_str(&self.contract_lines());
        out
    }

    /// The contract's lines of the summary.
    fn contract_lines(&self) -> String {
        let mut out = String::new();
        let c = &self.contract;
        let pct = |n: u64| {
            if self.cases == 0 {
                0.0
            } else {
                100.0 * n as f64 / self.cases as f64
            }
        };
        out.push_str(&format!(
            "contract paper-exact => engine: {} violations in {} paper-exact yes (canary, plain f64 transcription: {} violations)\n",
            c.violations, c.paper_yes, c.plain_violations
        ));
        out.push_str(&format!(
            "conservative answers (an undecided comparison): {} ({:.4}%), {} of them where paper-exact says no ({:.4}%)\n",
            c.conservative,
            pct(c.conservative),
            c.conservative_paper_no,
            pct(c.conservative_paper_no)
        ));
        out
    }
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
            plain: true,
            paper: true,
            truth: Some(true),
            entry_time: None,
            nanos: [1, 2, 3],
        }
    }

    #[test]
    fn merge_adds_exactly_and_refuses_overlaps() {
        let mut a = Report {
            seed: 1,
            shards: vec!["0/2".into()],
            ..Default::default()
        };
        let mut b = Report {
            seed: 1,
            shards: vec!["1/2".into()],
            ..Default::default()
        };
        a.add(&verdict(Class::Agree, Method::DetectSame2d), "free");
        a.add(
            &verdict(Class::MissedDetection, Method::DetectDiff2d),
            "edge_buff",
        );
        b.add(&verdict(Class::Agree, Method::DetectSame2d), "free");
        let mut m = a.clone();
        m.merge(&b).expect("disjoint shards");
        assert_eq!(m.cases, 3);
        assert_eq!(m.totals()[&Class::Agree], 2);
        assert_eq!(m.by_mode["free"][&Class::Agree], 2);
        assert_eq!(m.nanos, [3, 6, 9]);
        assert!(m.has_failures());
        assert!(m.merge(&b).is_err(), "the same shard twice");
        let other_seed = Report {
            seed: 2,
            shards: vec!["0/1".into()],
            ..Default::default()
        };
        assert!(a.clone().merge(&other_seed).is_err());
        // JSON round trip.
        let json = serde_json::to_string(&m).expect("serialise");
        let back = Report::from_json(&json).expect("parse");
        assert_eq!(back, m);
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
        r.add(&verdict(Class::Agree, Method::DetectSame2d), "free");
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
