//! `polyguard assure --paper wayout`: a seeded hunt of the way out (certified course,
//! speed and vertical-speed bands, recovery points, offsets and insets) against the
//! oracle's exact truth (docs/assurance.md, "The way out"), in the shared report shape
//! of [`super::assure_common::run_hunt`].

use std::path::Path;
use std::process::ExitCode;

use polyguard_harness::gen::{Source, SplitMix};
use polyguard_harness::hunt::Judged;
use polyguard_harness::wayout::gen::{band_case, offset_case, wayout_case, WayoutCase};
use polyguard_harness::wayout::judge::{judge, WayoutClass, WayoutEngine};

use super::assure_common::{run_hunt, Hunt, HuntRun};

/// The way-out hunt with the engine it judges.
pub struct WayoutHunt {
    /// The seed.
    pub seed: u64,
    /// The engine (the certified one or a canary).
    pub engine: WayoutEngine,
}

/// Case k of a way-out campaign of `seed`, and its mode. A canary replaces one engine
/// module, so its run draws only the cases that module answers (band cases for
/// `sampled-bands`, offset and inset cases for `bisector-offset`); the certified run
/// draws all three kinds.
pub fn campaign_wayout_case(seed: u64, k: u64, engine: WayoutEngine) -> (WayoutCase, String) {
    let mut m = SplitMix(seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x3A70_0B7E);
    let s = m.next_u64();
    let src = &mut SplitMix(s);
    let d = match engine {
        WayoutEngine::Certified => wayout_case(src),
        WayoutEngine::SampledBands => band_case(src),
        WayoutEngine::BisectorOffset => offset_case(src),
    };
    (d.case, d.mode)
}

impl Hunt for WayoutHunt {
    type Case = WayoutCase;
    type Class = WayoutClass;

    fn name(&self) -> &'static str {
        "wayout"
    }

    fn engine(&self) -> &'static str {
        self.engine.name()
    }

    fn case(&self, k: u64) -> (WayoutCase, String) {
        campaign_wayout_case(self.seed, k, self.engine)
    }

    fn judge(&self, case: &WayoutCase) -> Judged<WayoutClass> {
        judge(case, self.engine)
    }

    fn line(&self, case: &WayoutCase, meta: serde_json::Value) -> String {
        let mut doc = case.to_json();
        if let (Some(d), serde_json::Value::Object(m)) = (doc.as_object_mut(), meta) {
            d.insert("meta".into(), serde_json::Value::Object(m));
        }
        doc.to_string()
    }
}

/// Runs the hunt's shard into `out`.
pub fn run(hunt: &WayoutHunt, run: &HuntRun, out: &Path) -> ExitCode {
    run_hunt(hunt, run, out)
}
