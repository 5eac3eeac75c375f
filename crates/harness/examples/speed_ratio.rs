//! The certified engine against the plain f64 transcription (`polyguard::plain`, paper
//! A without error bounds) on the criterion workload (`polyguard_harness::workload`),
//! interleaved in one process: 30 rounds of `REPS` passes over the 256 cases per engine,
//! the fastest round of each reported, and their ratio. A quick look between criterion
//! runs on a noisy machine; callgrind gives instruction counts that the load does not
//! move:
//!
//! ```text
//! cargo run --release -p polyguard-harness --example speed_ratio              # every group
//! cargo run --release -p polyguard-harness --example speed_ratio -- diff 4    # one group
//! valgrind --tool=callgrind --toggle-collect='speed_ratio::run' \
//!     target/release/examples/speed_ratio diff 4 certified 10
//! ```
//!
//! Groups: `same` (2D statically shaped), `diff` (2D warping), `3s` and `3w` (3D static
//! and warping, n = 8). With an engine (`certified` or `plain`) and a count, the example
//! runs that engine alone that many passes (for profilers).

use std::hint::black_box;
use std::process::exit;
use std::time::Instant;

use polyguard::detect::{detect_3d, detect_diff_2d, detect_same_2d};
use polyguard::plain::detect as plain;
use polyguard_harness::workload::{workload, Workload, BUFF, CASES, FAC, T};

/// How many cases of `w` the engine finds, over `reps` passes.
#[inline(never)]
fn run(w: &Workload, group: &str, certified: bool, reps: usize) -> usize {
    let mut hits = 0;
    for _ in 0..reps {
        for i in 0..CASES {
            let (s, v, p, vels) = (w.s[i], w.v[i], &w.verts[i][..], &w.vels[i][..]);
            let (sz, vz) = w.z[i];
            let hit = match (group, certified) {
                ("same", true) => detect_same_2d(T, s, v, p, vels, BUFF),
                ("same", false) => plain::detect_same_2d(T, s, v, p, vels, BUFF),
                ("diff", true) => detect_diff_2d(T, s, v, p, vels, FAC, BUFF),
                ("diff", false) => plain::detect_diff_2d(T, s, v, p, vels, FAC, BUFF),
                (_, true) => detect_3d(T, s, v, sz, vz, p, vels, 0.0, 1000.0, 0.0, BUFF, FAC),
                (_, false) => {
                    plain::detect_3d(T, s, v, sz, vz, p, vels, 0.0, 1000.0, 0.0, BUFF, FAC)
                }
            };
            if black_box(hit) {
                hits += 1;
            }
        }
    }
    hits
}

/// The group's workload, with the criterion bench's seeds.
fn group_workload(group: &str, n: usize) -> Workload {
    let warping = matches!(group, "diff" | "3w");
    let seed = if group.starts_with('3') {
        7
    } else {
        42 + n as u64
    };
    workload(n, warping, seed)
}

/// Both engines on one group, interleaved: the fastest of 30 rounds each.
fn compare(group: &str, n: usize, reps: usize) {
    let w = group_workload(group, n);
    let (mut best_c, mut best_p) = (f64::MAX, f64::MAX);
    for _ in 0..30 {
        let t0 = Instant::now();
        black_box(run(&w, group, true, reps));
        best_c = best_c.min(t0.elapsed().as_secs_f64());
        let t0 = Instant::now();
        black_box(run(&w, group, false, reps));
        best_p = best_p.min(t0.elapsed().as_secs_f64());
    }
    let per = |x: f64| x * 1e6 / reps as f64;
    println!(
        "{group:>4} n = {n:<2}  certified {:7.1} µs  plain {:7.1} µs  (per {CASES} cases)  ratio {:.2}",
        per(best_c),
        per(best_p),
        best_c / best_p
    );
}

fn usage() -> ! {
    eprintln!("usage: speed_ratio [same|diff|3s|3w N [certified|plain PASSES]]");
    exit(2);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let group = |g: &str| matches!(g, "same" | "diff" | "3s" | "3w");
    match args.as_slice() {
        [] => {
            for g in ["same", "diff"] {
                for n in [4, 8, 16, 32, 64] {
                    compare(g, n, 100);
                }
            }
            compare("3s", 8, 100);
            compare("3w", 8, 100);
        }
        [g, n] if group(g) => match n.parse() {
            Ok(n) if n >= 3 => compare(g, n, 100),
            _ => usage(),
        },
        [g, n, engine, reps] if group(g) => {
            let (Ok(n), Ok(reps)) = (n.parse::<usize>(), reps.parse::<usize>()) else {
                usage()
            };
            let certified = match engine.as_str() {
                "certified" => true,
                "plain" => false,
                _ => usage(),
            };
            if n < 3 {
                usage();
            }
            let hits = run(&group_workload(g, n), g, certified, reps);
            println!(
                "{g} n = {n} {engine}: {} of {CASES} cases hit",
                hits / reps.max(1)
            );
        }
        _ => usage(),
    }
}
