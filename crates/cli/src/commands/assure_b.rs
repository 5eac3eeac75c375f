//! `polyguard assure --paper b`: a seeded, sharded hunt of paper B's pipeline against the
//! ground truth ([`polyguard_harness::paper_b`]), and `assure merge` of its reports.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use super::assure_common::{keep_lowest, write_report, CampaignProgress};
use polyguard_earth::conflict::{geom, pipeline, Object};
use polyguard_earth::reference::truth::Outcome;
use polyguard_earth::scenario::{self, Scenario};
use polyguard_harness::gen::{Source, SplitMix};
use polyguard_harness::paper_b::{self, CaseB, ClassB, KeptB, ReportB, VerdictB};

/// Kept cases per class (failures and undecided ones), those of the lowest indices.
pub const KEEP_PER_CLASS: usize = 5;

/// Which pipeline `assure --paper b` judges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EngineB {
    /// The four stages as shipped.
    Pipeline,
    /// The canary: meetings sampled once a minute of the pair's common life, the way a
    /// sampling check (or the paper's local search) sees them. A hunt that sees must
    /// catch it cutting windows short and missing brief meetings.
    Sampled,
}

impl EngineB {
    /// The name in reports.
    pub fn name(self) -> &'static str {
        match self {
            EngineB::Pipeline => "pipeline",
            EngineB::Sampled => "sampled",
        }
    }
}

/// The generator's seed for case k (the same rule as paper A's campaigns).
fn case_seed(seed: u64, k: u64) -> u64 {
    let mut m = SplitMix(seed ^ k.wrapping_mul(0xD1B5_4A32_D192_ED03) ^ 0xB);
    m.next_u64()
}

/// Case k of a paper-B campaign.
pub fn campaign_case(seed: u64, k: u64) -> CaseB {
    paper_b::draw(&mut SplitMix(case_seed(seed, k)))
}

/// The canary's answer: the pair meets where one of its object pairs meets at a sample
/// (every minute of the common life, f64 ring test); the window spans those samples.
fn sampled(sc: &Scenario) -> Option<(f64, f64)> {
    let objs = scenario::objects(sc);
    let (a, b): (Vec<&Object>, Vec<&Object>) = objs.iter().partition(|o| o.owner == 0);
    let step = 1.0 / 60.0;
    let mut win: Option<(f64, f64)> = None;
    let (mut va, mut vb) = (Vec::new(), Vec::new());
    for x in &a {
        for y in &b {
            let lo = x.t0.max(y.t0).max(-1e3);
            let hi = x.t1.min(y.t1).min(1e3);
            if lo > hi {
                continue;
            }
            let n = ((hi - lo) / step).ceil().min(1e5) as usize;
            for k in 0..=n {
                let t = (lo + k as f64 * step).min(hi);
                x.vertices_at(t, &mut va);
                y.vertices_at(t, &mut vb);
                if geom::rings_intersect(&va, &vb) {
                    let (s, e) = if !x.is_moving() && !y.is_moving() {
                        (x.t0.max(y.t0), x.t1.min(y.t1))
                    } else {
                        (t, t)
                    };
                    win = Some(win.map_or((s, e), |(p, q)| (p.min(s), q.max(e))));
                }
            }
        }
    }
    win
}

/// Judges case `c` with `engine`; `(verdict, scenario read, its text, pipeline ns, truth ns)`.
fn judge(c: &CaseB, engine: EngineB) -> Result<(VerdictB, Scenario, String, u64, u64), String> {
    let t = Instant::now();
    let text = scenario::to_geojson(&c.scenario).to_string();
    let read = scenario::parse(&text).map_err(|e| e.to_string())?;
    if let Some(e) = read.errors.first() {
        return Err(e.to_string());
    }
    let sc = read.scenario;
    let eng = match engine {
        EngineB::Pipeline => paper_b::engine(&text)?,
        EngineB::Sampled => sampled(&sc),
    };
    let t_engine = t.elapsed().as_nanos() as u64;
    let t = Instant::now();
    let v = paper_b::judge_read(&sc, eng).ok_or("a feature the truth does not model")?;
    Ok((v, sc, text, t_engine, t.elapsed().as_nanos() as u64))
}

fn fmt_time(t: f64) -> serde_json::Value {
    if t.is_finite() {
        t.into()
    } else {
        serde_json::Value::Null
    }
}

/// The truth as written into a kept case.
fn truth_json(t: &Outcome) -> serde_json::Value {
    match t {
        Outcome::Meets {
            first,
            first_apart_until,
            last,
            last_apart_from,
        } => serde_json::json!({"meets": true, "first": fmt_time(*first),
            "apart_before": fmt_time(*first_apart_until), "last": fmt_time(*last),
            "apart_after": fmt_time(*last_apart_from)}),
        Outcome::Apart { min_distance } => {
            serde_json::json!({"meets": false, "min_distance_rad": fmt_time(*min_distance)})
        }
        Outcome::Undecided => serde_json::json!({"meets": null}),
        Outcome::BoundBroken { t } => serde_json::json!({"bound_broken_at": fmt_time(*t)}),
    }
}

fn write_kept(
    dir: &Path,
    k: u64,
    c: &CaseB,
    v: &VerdictB,
    sc: &Scenario,
    engine: EngineB,
) -> std::io::Result<KeptB> {
    let stem = format!("b-{}-{k}", v.class.name());
    let case_file = format!("counterexamples/{stem}.geojson");
    let svg_file = format!("counterexamples/{stem}.svg");
    fs::create_dir_all(dir.join("counterexamples"))?;
    let mut sc2 = sc.clone();
    sc2.features[0].extra.insert(
        "assure".into(),
        serde_json::json!({
            "class": v.class.name(),
            "mode": c.mode,
            "engine": engine.name(),
            "window": v.engine.map(|(s, e)| vec![fmt_time(s), fmt_time(e)]),
            "truth": truth_json(&v.truth),
        }),
    );
    let text = serde_json::to_string_pretty(&scenario::to_geojson(&sc2)).unwrap_or_default();
    fs::write(dir.join(&case_file), text + "\n")?;
    let objs = scenario::objects(sc);
    let (conflicts, _) = pipeline::run(
        &objs,
        pipeline::Options {
            details: true,
            ..Default::default()
        },
    );
    let svg = polyguard_earth::picture::svg(
        sc,
        &objs,
        &conflicts,
        polyguard_earth::picture::Options { detail: false },
    );
    fs::write(
        dir.join(&svg_file),
        with_verdicts(&svg, c, v, engine, &conflicts),
    )?;
    Ok(KeptB {
        index: k,
        class: v.class,
        mode: c.mode.clone(),
        case_file,
        svg_file,
    })
}

/// The picture with the three answers written under its legend: the judged pipeline's
/// window, the truth, and the shipped pipeline's window (the one drawn).
fn with_verdicts(
    svg: &str,
    c: &CaseB,
    v: &VerdictB,
    engine: EngineB,
    drawn: &[pipeline::Conflict],
) -> String {
    let width: f64 = svg
        .split("width=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .and_then(|w| w.parse().ok())
        .unwrap_or(1200.0);
    let win = |w: Option<(f64, f64)>| match w {
        Some((s, e)) => format!("{s:.5} to {e:.5} h"),
        None => "no conflict".into(),
    };
    let truth = match &v.truth {
        Outcome::Meets { first, last, .. } => format!("meets, {first:.5} to {last:.5} h"),
        Outcome::Apart { min_distance } => {
            format!(
                "apart, ≥ {:.3} m",
                min_distance * polyguard_earth::sphere::EARTH_RADIUS_NM * 1852.0
            )
        }
        Outcome::Undecided => "undecided (tangent)".into(),
        Outcome::BoundBroken { t } => format!("speed bound broken at {t:.5} h"),
    };
    let lines = [
        format!("verdict: {}", v.class.name()),
        format!("mode: {}", c.mode),
        format!("{}: {}", engine.name(), win(v.engine)),
        format!("truth: {truth}"),
        format!(
            "drawn (pipeline): {}",
            win(drawn.first().map(|c| (c.t_start, c.t_end)))
        ),
    ];
    let x = width - 250.0;
    let mut text = String::new();
    for (i, l) in lines.iter().enumerate() {
        let weight = if i == 0 { " font-weight=\"bold\"" } else { "" };
        text += &format!(
            "<text x=\"{x:.1}\" y=\"{:.1}\"{weight}>{}</text>\n",
            262.0 + 17.0 * i as f64,
            l.replace('&', "&amp;").replace('<', "&lt;")
        );
    }
    match svg.rfind("</svg>") {
        Some(k) => format!("{}{text}{}", &svg[..k], &svg[k..]),
        None => svg.to_string(),
    }
}

/// Runs a paper-B campaign: cases `k ≡ shard_i (mod shard_n)` of `0..cases`.
#[allow(clippy::too_many_arguments)]
pub fn run(
    cases: u64,
    seed: u64,
    threads: usize,
    out: &Path,
    shard: (u64, u64),
    quiet: bool,
    engine: EngineB,
) -> ExitCode {
    let (shard_i, shard_n) = shard;
    if let Err(e) = fs::create_dir_all(out) {
        eprintln!("polyguard assure: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let mine: u64 = (0..cases).filter(|k| k % shard_n == shard_i).count() as u64;
    let progress = CampaignProgress::new(mine, quiet);
    let next = AtomicU64::new(0);
    let report = Mutex::new(ReportB {
        paper: "b".into(),
        seed,
        shards: vec![format!("{shard_i}/{shard_n}")],
        campaign_cases: cases,
        engine: engine.name().into(),
        ..Default::default()
    });
    type Found = (u64, CaseB, VerdictB, Scenario);
    let kept: Mutex<Vec<Found>> = Mutex::new(Vec::new());
    let start = Instant::now();
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1) {
            scope.spawn(|| {
                let mut local = ReportB::default();
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    if j >= mine {
                        break;
                    }
                    let k = j * shard_n + shard_i;
                    let c = campaign_case(seed, k);
                    let mut failed = false;
                    match judge(&c, engine) {
                        Ok((v, sc, _, ne, nt)) => {
                            local.cases += 1;
                            local.see_model(&v);
                            local.nanos[0] += ne;
                            local.nanos[1] += nt;
                            *local
                                .by_mode
                                .entry(c.mode.clone())
                                .or_default()
                                .entry(v.class)
                                .or_insert(0) += 1;
                            failed = v.class.is_failure();
                            if !matches!(v.class, ClassB::Agree | ClassB::NearAlarm) {
                                if let Ok(mut g) = kept.lock() {
                                    let f = (k, c, v, sc);
                                    keep_lowest(&mut g, f, KEEP_PER_CLASS, |f| f.0, |f| f.2.class);
                                }
                            }
                        }
                        Err(e) => {
                            eprintln!(
                                "polyguard assure: paper B case {k} ({}) rejected: {e}",
                                c.mode
                            );
                            local.rejected += 1;
                        }
                    }
                    progress.inc(failed);
                }
                if let Ok(mut r) = report.lock() {
                    r.absorb(&local);
                }
            });
        }
    });
    progress.finish();
    let mut report = report.into_inner().unwrap_or_default();
    report.wall_seconds = start.elapsed().as_secs_f64();
    let mut found = kept.into_inner().unwrap_or_default();
    found.sort_by_key(|f| f.0);
    for (k, c, v, sc) in &found {
        match write_kept(out, *k, c, v, sc, engine) {
            Ok(x) => report.kept.push(x),
            Err(e) => eprintln!("polyguard assure: cannot write case {k}: {e}"),
        }
    }
    finish(&report, out)
}

/// Writes `report.json`, prints the summary; exit 1 on failures (or rejected cases).
pub fn finish(report: &ReportB, out: &Path) -> ExitCode {
    if let Err(code) = write_report(report, out) {
        return code;
    }
    let path = out.join("report.json");
    let mut text = String::new();
    for k in &report.kept {
        text += &format!(
            "kept {} ({}): {} {}\n",
            k.class.name(),
            k.mode,
            k.case_file,
            k.svg_file
        );
    }
    text += &format!("report: {}\n", path.display());
    if !report.missing_shards.is_empty() {
        text += &format!(
            "PARTIAL: shards {} of this {}-case campaign are missing\n",
            report.missing_shards.join(", "),
            report.campaign_cases
        );
    }
    text += &report.summary();
    let mut stdout = std::io::stdout().lock();
    let _ = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush());
    if report.failures() > 0 || report.rejected > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `assure merge` of paper-B reports: one seed, one campaign size, one engine, shards
/// that do not overlap and (unless `partial`) cover the campaign.
pub fn merge(paths: &[PathBuf], texts: &[String], out: &Path, partial: bool) -> ExitCode {
    let fail = |msg: String| {
        eprintln!("polyguard assure merge: {msg}");
        ExitCode::from(2)
    };
    let mut reports = Vec::new();
    for (p, t) in paths.iter().zip(texts) {
        match serde_json::from_str::<ReportB>(t) {
            Ok(r) => reports.push(r),
            Err(e) => return fail(format!("{} is not a paper-B report: {e}", p.display())),
        }
    }
    let Some(first) = reports.first() else {
        return fail("no reports".into());
    };
    let mut m = ReportB {
        paper: "b".into(),
        seed: first.seed,
        campaign_cases: first.campaign_cases,
        engine: first.engine.clone(),
        ..Default::default()
    };
    let mut n_of: Option<u64> = None;
    let mut have = std::collections::BTreeSet::new();
    for (p, r) in paths.iter().zip(&reports) {
        if r.seed != m.seed || r.campaign_cases != m.campaign_cases || r.engine != m.engine {
            return fail(format!(
                "{}: seed {}, {} cases, engine {} differ from the first report's (seed {}, {} cases, engine {})",
                p.display(), r.seed, r.campaign_cases, r.engine, m.seed, m.campaign_cases, m.engine
            ));
        }
        for s in &r.shards {
            let (i, n) = match s
                .split_once('/')
                .and_then(|(i, n)| Some((i.parse::<u64>().ok()?, n.parse::<u64>().ok()?)))
            {
                Some(x) => x,
                None => return fail(format!("{}: shard {s:?} is not i/N", p.display())),
            };
            if *n_of.get_or_insert(n) != n {
                return fail(format!(
                    "{}: shard {s} is not of {} shards",
                    p.display(),
                    n_of.unwrap_or(n)
                ));
            }
            if !have.insert(i) {
                return fail(format!(
                    "{}: shard {s} is already in the merge",
                    p.display()
                ));
            }
            m.shards.push(s.clone());
        }
        m.absorb(r);
    }
    let n = n_of.unwrap_or(1);
    m.missing_shards = (0..n)
        .filter(|i| !have.contains(i))
        .map(|i| format!("{i}/{n}"))
        .collect();
    if !m.missing_shards.is_empty() && !partial {
        return fail(format!(
            "shards {} are missing (merge them too, or pass --partial)",
            m.missing_shards.join(", ")
        ));
    }
    // the kept cases of the whole: per class the lowest indices, files copied along
    let mut all: Vec<(KeptB, PathBuf)> = Vec::new();
    for (p, r) in paths.iter().zip(&reports) {
        let dir = p.parent().unwrap_or_else(|| Path::new(".")).to_path_buf();
        all.extend(r.kept.iter().map(|k| (k.clone(), dir.clone())));
    }
    all.sort_by_key(|(k, _)| k.index);
    if let Err(e) = fs::create_dir_all(out.join("counterexamples")) {
        return fail(format!("cannot create {}: {e}", out.display()));
    }
    for (k, dir) in all {
        if m.kept.iter().filter(|x| x.class == k.class).count() >= KEEP_PER_CLASS {
            continue;
        }
        for f in [&k.case_file, &k.svg_file] {
            let (from, to) = (dir.join(f), out.join(f));
            if from != to {
                if let Err(e) = fs::copy(&from, &to) {
                    return fail(format!("cannot copy {}: {e}", from.display()));
                }
            }
        }
        m.kept.push(k);
    }
    finish(&m, out)
}
