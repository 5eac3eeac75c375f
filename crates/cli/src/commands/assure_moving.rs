//! `polyguard assure --paper moving`: a seeded hunt of the planar moving engine's certified
//! spans (inside, near_{D,H}: whole flights against static and keyframed areas) against
//! the oracle's exact truth (docs/assurance.md, "Moving features").

use std::fs;
use std::path::Path;
use std::process::ExitCode;

use polyguard_earth::moving::plane::{PlaneArea, PlaneFix, TimeSpan};
use polyguard_harness::gen::SplitMix;
use polyguard_harness::moving::gen::{moving_scenario, MovingScenario};
use polyguard_harness::moving::judge::{judge, MovingEngine, MovingVerdict};
use polyguard_harness::moving::report::{KeptMoving, MovingReport};
use serde_json::{json, Value};

use super::assure_common::{run_shard, write_report, HuntRun, ShardJudge};

/// How many scenarios of each failing class a run keeps.
pub const KEEP_PER_CLASS: usize = 5;

/// What one moving hunt draws and judges.
pub struct MovingCampaign {
    /// Seed, shard, size, threads and progress.
    pub run: HuntRun,
    /// The engine judged.
    pub engine: MovingEngine,
}

/// Scenario k of a moving campaign.
pub fn campaign_scenario(seed: u64, k: u64) -> MovingScenario {
    let mut m = SplitMix(seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x3071_4E5E);
    let s = polyguard_harness::gen::Source::next_u64(&mut m);
    moving_scenario(&mut SplitMix(s))
}

/// A failing scenario as kept: its verdict and the scenario.
type Found = (MovingVerdict, MovingScenario);

/// Runs the campaign into `out` (report.json, summary.txt, counterexamples/).
pub fn run(c: &MovingCampaign, out: &Path) -> ExitCode {
    if let Err(e) = fs::create_dir_all(out) {
        eprintln!("polyguard assure: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let how = ShardJudge {
        judge: |k, local: &mut MovingReport| {
            let s = campaign_scenario(c.run.seed, k);
            let v = judge(&s, c.engine).map_err(|e| format!("scenario {k} rejected: {e}"))?;
            local.add(&v, s.mode);
            Ok(v.class.is_failure().then_some((v, s)))
        },
        class: |(v, _): &Found| v.class,
        write: |k, (v, s): &Found| write_kept(out, k, v, s),
    };
    let report = run_shard(
        MovingReport::new(c.run.seed, c.engine.name()),
        &c.run,
        KEEP_PER_CLASS,
        how,
    );
    finish(&report, out)
}

/// Spans as JSON.
fn spans_json(spans: &[TimeSpan]) -> Value {
    spans
        .iter()
        .map(|s| json!({"start": s.start, "end": s.end, "certain": s.certain}))
        .collect()
}

/// Fixes as JSON ([t, x, y, z or null] each).
fn fixes_json(fixes: &[PlaneFix]) -> Value {
    fixes.iter().map(|f| json!([f.t, f.x, f.y, f.z])).collect()
}

/// An area as JSON (its frames' parts as rings of [x, y]).
fn area_json(a: &PlaneArea) -> Value {
    let frames: Vec<Value> = a
        .frames
        .iter()
        .map(|f| {
            let parts: Vec<Value> = f
                .parts
                .iter()
                .map(|p| json!({"outer": p.outer, "holes": p.holes}))
                .collect();
            json!({"t": f.t, "parts": parts})
        })
        .collect();
    json!({
        "frames": frames,
        "is_static": a.is_static,
        "floor": a.floor,
        "ceiling": a.ceiling,
    })
}

/// Writes a kept scenario's file: the scenario (fixes, area, max_gap, D, H), its class
/// and mode, and per relation the engine's spans and why it failed.
fn write_kept(
    out: &Path,
    k: u64,
    v: &MovingVerdict,
    s: &MovingScenario,
) -> std::io::Result<KeptMoving> {
    let case_file = format!("counterexamples/{}-{k}.json", v.class.name());
    fs::create_dir_all(out.join("counterexamples"))?;
    let relations: serde_json::Map<String, Value> = v
        .relations
        .iter()
        .map(|r| {
            (
                r.relation.to_string(),
                json!({"class": r.class.name(), "spans": spans_json(&r.spans), "why": r.why}),
            )
        })
        .collect();
    let doc = json!({
        "index": k,
        "class": v.class.name(),
        "mode": s.mode,
        "max_gap": s.max_gap,
        "d": s.d,
        "h": s.h,
        "fixes": fixes_json(&s.fixes),
        "area": area_json(&s.area),
        "relations": relations,
    });
    let text = serde_json::to_string_pretty(&doc).unwrap_or_default();
    fs::write(out.join(&case_file), text + "\n")?;
    Ok(KeptMoving {
        index: k,
        class: v.class,
        mode: s.mode.into(),
        case_file,
    })
}

/// Writes report.json and summary.txt and prints the summary; exit 1 on a failure.
pub fn finish(report: &MovingReport, out: &Path) -> ExitCode {
    if let Err(code) = write_report(report, out) {
        return code;
    }
    let mut text = report.summary();
    if report.rejected > 0 {
        text += &format!(
            "{} generated scenarios were rejected by the engine\n",
            report.rejected
        );
    }
    for k in &report.kept {
        text += &format!("kept {} ({}): {}\n", k.class.name(), k.mode, k.case_file);
    }
    text += &format!("report: {}\n", out.join("report.json").display());
    let _ = fs::write(out.join("summary.txt"), &text);
    print!("{text}");
    if report.failures() > 0 || report.rejected > 0 {
        eprintln!(
            "polyguard assure: the moving engine ({}) failed the exact truth in {} scenarios",
            report.engine,
            report.failures()
        );
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `assure merge` of moving reports: joins the shards and copies their kept scenarios.
pub fn merge(
    paths: &[std::path::PathBuf],
    texts: &[String],
    out: &Path,
    partial: bool,
) -> ExitCode {
    let fail = |msg: String| {
        eprintln!("polyguard assure merge: {msg}");
        ExitCode::from(2)
    };
    let mut reports = Vec::with_capacity(texts.len());
    for (p, t) in paths.iter().zip(texts) {
        match MovingReport::from_json(t) {
            Ok(r) => reports.push(r),
            Err(e) => return fail(format!("{} is not a moving report: {e}", p.display())),
        }
    }
    let merged = match MovingReport::merge_campaign(&reports, partial) {
        Ok(m) => m,
        Err(e) => return fail(e),
    };
    if let Err(e) = fs::create_dir_all(out.join("counterexamples")) {
        return fail(format!("cannot create {}: {e}", out.display()));
    }
    for (p, r) in paths.iter().zip(&reports) {
        let dir = p.parent().unwrap_or_else(|| Path::new("."));
        for k in &r.kept {
            if let Err(e) = fs::copy(dir.join(&k.case_file), out.join(&k.case_file)) {
                return fail(format!("cannot copy {}: {e}", k.case_file));
            }
        }
    }
    finish(&merged, out)
}
