//! `polyguard assure --intervals`: a seeded hunt of the engine's certified intervals
//! (inside, near_D, breach_D) and keep-in exit detection against the oracle's exact
//! algebraic truth (docs/assurance.md, "Intervals").

use std::fs;
use std::path::Path;
use std::process::ExitCode;

use polyguard_harness::gen::{Space, SplitMix};
use polyguard_harness::intervals::gen::{interval_case, IntervalCase};
use polyguard_harness::intervals::judge::{judge, IntervalEngine, IntervalVerdict};
use polyguard_harness::intervals::report::{IntervalReport, KeptInterval};

use super::assure_common::{finish_report, run_shard, HuntRun, ShardJudge};

/// How many cases of each failing class a run keeps.
pub const KEEP_PER_CLASS: usize = 5;

/// What one interval hunt draws and judges.
pub struct IntervalCampaign {
    /// Seed, shard, size, threads and progress.
    pub run: HuntRun,
    /// The threshold half's scale space.
    pub space: Space,
    /// The engine judged.
    pub engine: IntervalEngine,
}

/// Case k of an interval campaign.
pub fn campaign_interval_case(seed: u64, k: u64, space: &Space) -> IntervalCase {
    let mut m = SplitMix(seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x1A7E_5EED);
    let s = polyguard_harness::gen::Source::next_u64(&mut m);
    interval_case(&mut SplitMix(s), space)
}

/// A failing case as kept: its verdict and the case.
type Found = (IntervalVerdict, IntervalCase);

/// Runs the campaign into `out` (report.json, summary.txt, counterexamples/).
pub fn run(c: &IntervalCampaign, out: &Path) -> ExitCode {
    if let Err(e) = fs::create_dir_all(out) {
        eprintln!("polyguard assure: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let how = ShardJudge {
        judge: |k, local: &mut IntervalReport| {
            let ic = campaign_interval_case(c.run.seed, k, &c.space);
            let v = judge(&ic, c.engine).map_err(|e| format!("case {k} rejected: {e:?}"))?;
            local.add(&v, ic.mode);
            Ok(v.class.is_failure().then_some((v, ic)))
        },
        class: |(v, _): &Found| v.class,
        write: |k, (v, ic): &Found| write_kept(out, k, v, ic),
    };
    let report = run_shard(
        IntervalReport::new(c.run.seed, c.engine.name(), c.space.label()),
        &c.run,
        KEEP_PER_CLASS,
        how,
    );
    finish_report(&report, out)
}

/// The spans of a verdict as JSON (the meta of a kept case).
fn spans_json(v: &IntervalVerdict) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for r in &v.relations {
        let spans: Vec<serde_json::Value> = r
            .spans
            .iter()
            .map(|s| {
                serde_json::json!({
                    "start": [s.start.lo, s.start.hi],
                    "end": [s.end.lo, s.end.hi],
                    "certain": s.certain,
                })
            })
            .collect();
        m.insert(r.relation.name().into(), spans.into());
        if let Some(why) = &r.why {
            m.insert(format!("{}_why", r.relation.name()), why.clone().into());
        }
    }
    serde_json::Value::Object(m)
}

/// Writes a kept case's file (the case, its separations, and in `meta` its class, mode,
/// the engine's spans and why it failed).
fn write_kept(
    out: &Path,
    k: u64,
    v: &IntervalVerdict,
    ic: &IntervalCase,
) -> std::io::Result<KeptInterval> {
    let stem = format!("{}-{k}", v.class.name());
    let case_file = format!("counterexamples/{stem}.jsonl");
    fs::create_dir_all(out.join("counterexamples"))?;
    let extra = [
        ("class", serde_json::Value::from(v.class.name())),
        ("mode", ic.mode.into()),
        ("spans", spans_json(v)),
        (
            "exit",
            serde_json::json!({
                "truth": v.exit_truth,
                "engine": format!("{:?}", v.exit_engine),
            }),
        ),
    ];
    fs::write(out.join(&case_file), ic.to_json_line(&stem, &extra) + "\n")?;
    Ok(KeptInterval {
        index: k,
        class: v.class,
        mode: ic.mode.into(),
        case_file,
    })
}
