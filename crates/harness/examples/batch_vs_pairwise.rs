//! The batch contract at the bench's scale (batch detection): on the seeded
//! batch workload (`polyguard_harness::batch`), `detect_batch` against
//! `api::detected` on every one of the N·M pairs, 2D and 3D, and on the dense workload
//! (`dense_workload`: every pair a candidate). Too slow for a unit test at
//! 10⁴ × 10³ in debug; in release it takes seconds:
//!
//! ```text
//! cargo run --release -p polyguard-harness --features parallel --example batch_vs_pairwise -- 10000 1000 1
//! ```
//!
//! Arguments: N points, M polygons, the seed (10000, 1000, 1 by default). Prints the
//! counts and exits 1 on any difference.

use std::process::ExitCode;
use std::time::Instant;

use polyguard::api::{decide, Case, Kind, Params};
use polyguard::batch::{detect_batch_counted, Hit, Options};
use polyguard::Tri;
use polyguard_harness::batch::{batch_workload, dense_workload, Mix, BUFF, FAC, T};

fn main() -> ExitCode {
    let arg = |k: usize, d: u64| {
        std::env::args()
            .nth(k)
            .and_then(|a| a.parse().ok())
            .unwrap_or(d)
    };
    let (n, m, seed) = (arg(1, 10_000) as usize, arg(2, 1_000) as usize, arg(3, 1));
    let params = match Params::new(BUFF).and_then(|p| p.with_fac(FAC)) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("batch_vs_pairwise: {e}");
            return ExitCode::from(2);
        }
    };
    let mut failed = false;
    for name in ["2D", "3D", "dense"] {
        let w = match name {
            "dense" => dense_workload(n, m, seed),
            _ => batch_workload(
                n,
                m,
                seed,
                Mix {
                    three_d: name == "3D",
                    ..Mix::BENCH
                },
            ),
        };
        let start = Instant::now();
        let (batch, decided) =
            match detect_batch_counted(T, &w.points, &w.polygons, &params, &Options::default()) {
                Ok(b) => b,
                Err(e) => {
                    eprintln!("batch_vs_pairwise: {e}");
                    return ExitCode::from(2);
                }
            };
        let batch_time = start.elapsed();
        let start = Instant::now();
        let mut pairwise = Vec::new();
        for (i, p) in w.points.iter().enumerate() {
            for (j, q) in w.polygons.iter().enumerate() {
                let Ok(case) = Case::new(T, *p, q.clone(), params) else {
                    eprintln!("batch_vs_pairwise: pair ({i}, {j}) is not a case");
                    return ExitCode::from(2);
                };
                let kind = match decide(&case) {
                    Tri::No => continue,
                    Tri::Yes => Kind::Exact,
                    Tri::Unsure => Kind::Conservative,
                };
                pairwise.push(Hit {
                    point: i,
                    polygon: j,
                    kind,
                    method: case.method(),
                });
            }
        }
        let same = pairwise == batch.hits;
        failed |= !same;
        println!(
            "{} {n} x {m} seed {seed}: {} hits ({} conservative), {} candidates, {} decided; batch {:.1} ms, \
             pairwise {:.0} ms; {}",
            name,
            batch.hits.len(),
            batch
                .hits
                .iter()
                .filter(|h| h.kind == Kind::Conservative)
                .count(),
            batch.candidates,
            decided,
            batch_time.as_secs_f64() * 1e3,
            start.elapsed().as_secs_f64() * 1e3,
            if same { "the same" } else { "DIFFERENT" }
        );
    }
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
