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

use super::assure_common::{finish_report, run_shard, HuntRun, ShardJudge};

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
    finish_report(&report, out)
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
