//! polyguard's paper A detectors timed on a plain workload file
//! (`uniform_workload --plain`), the same way as the PolyCARP drivers in
//! benches/polycarp/ time PolyCARP on the same file, so that scripts/polycarp-speed
//! puts the three side by side (docs/performance.md, "Against PolyCARP"):
//!
//! ```text
//! cargo run --release -p polyguard-harness --example uniform_workload -- --plain 256 > work.txt
//! cargo run --release -p polyguard-harness --example workload_speed -- work.txt
//! ```
//!
//! Each group calls its paper function: `static` detect_same_2D (§II.H), `warping`
//! detect_diff_2D (§II.I), `3d-static` and `3d-warping` detect_3D (§III). The method:
//! WARMUP untimed passes over every group; then, per group, ROUNDS timed rounds, each
//! REPEAT passes over the group's cases; the figure is the median round's time per call
//! (the upper middle of the sorted rounds), by the thread's CPU clock and by the wall
//! clock. On a shared machine the wall clock of a round also counts the time other work
//! took the core, which long rounds suffer more than short ones; the CPU clock does not.
//! One line per group:
//!
//! ```text
//! GROUP n CASES CPU_NS_PER_CALL WALL_NS_PER_CALL ANSWERS
//! ```
//!
//! ANSWERS has one `1` (conflict) or `0` per case, in the file's order.
//! Options: `--rounds N` (30), `--repeat R` (10), `--warmup W` (5).

use std::hint::black_box;
use std::process::exit;
use std::time::Instant;

use polyguard::detect::{detect_3d, detect_diff_2d, detect_same_2d};
use polyguard::Vect2;

/// One case of the plain format (see uniform_workload's doc).
struct Case {
    t: f64,
    buff: f64,
    fac: f64,
    s: Vect2,
    v: Vect2,
    sz: f64,
    vz: f64,
    pmin: f64,
    pmax: f64,
    vsp: f64,
    verts: Vec<Vect2>,
    vels: Vec<Vect2>,
}

/// Which paper function a group calls.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Same,
    Diff,
    Slab,
}

/// The cases of one group, in the file's order.
struct Group {
    name: String,
    n: usize,
    kind: Kind,
    cases: Vec<Case>,
}

/// Paper A's answer for one case: true when the point may enter the polygon within T.
#[inline(always)]
fn detect(kind: Kind, c: &Case) -> bool {
    match kind {
        Kind::Same => detect_same_2d(c.t, c.s, c.v, &c.verts[..], &c.vels[..], c.buff),
        Kind::Diff => detect_diff_2d(c.t, c.s, c.v, &c.verts[..], &c.vels[..], c.fac, c.buff),
        Kind::Slab => detect_3d(
            c.t,
            c.s,
            c.v,
            c.sz,
            c.vz,
            &c.verts[..],
            &c.vels[..],
            c.pmin,
            c.pmax,
            c.vsp,
            c.buff,
            c.fac,
        ),
    }
}

/// This thread's CPU time in nanoseconds (`CLOCK_THREAD_CPUTIME_ID`).
fn thread_cpu_ns() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec, all that clock_gettime needs.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        eprintln!("workload_speed: the thread CPU clock cannot be read");
        exit(2);
    }
    ts.tv_sec as f64 * 1e9 + ts.tv_nsec as f64
}

/// The median (upper middle) of `x`.
fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

/// `reps` passes over the group; the number of hits, through a black box. Each kind's
/// loop is a function of its own ([`pass_kind`]), so that the code the compiler makes
/// for one paper function does not depend on the others (inlined into one loop, a change
/// to one detector moved another's time by a few per cent).
#[inline(never)]
fn pass(g: &Group, reps: usize) -> usize {
    match g.kind {
        Kind::Same => pass_kind::<0>(&g.cases, reps),
        Kind::Diff => pass_kind::<1>(&g.cases, reps),
        Kind::Slab => pass_kind::<2>(&g.cases, reps),
    }
}

/// [`pass`] for one kind (0 same, 1 diff, 2 slab), the paper function inlined.
#[inline(never)]
fn pass_kind<const K: u8>(cases: &[Case], reps: usize) -> usize {
    let kind = match K {
        0 => Kind::Same,
        1 => Kind::Diff,
        _ => Kind::Slab,
    };
    let mut hits = 0;
    for _ in 0..reps {
        for c in cases {
            if black_box(detect(kind, black_box(c))) {
                hits += 1;
            }
        }
    }
    hits
}

/// One plain line as a case, or why it is not one.
fn parse_case(fields: &[&str]) -> Result<(String, usize, Case), String> {
    let num = |i: usize| -> Result<f64, String> {
        let f = fields.get(i).ok_or("short line")?;
        f.parse::<f64>()
            .map_err(|_| format!("{f:?} is not a number"))
    };
    let name = fields.first().ok_or("empty line")?.to_string();
    let n: usize = fields
        .get(1)
        .and_then(|f| f.parse().ok())
        .ok_or("no vertex count")?;
    if fields.len() != 14 + 4 * n {
        return Err(format!("{} fields, {} expected", fields.len(), 14 + 4 * n));
    }
    let pts = |from: usize| -> Result<Vec<Vect2>, String> {
        (0..n)
            .map(|i| Ok(Vect2::new(num(from + 2 * i)?, num(from + 2 * i + 1)?)))
            .collect()
    };
    let case = Case {
        t: num(2)?,
        buff: num(3)?,
        fac: num(4)?,
        s: Vect2::new(num(5)?, num(6)?),
        v: Vect2::new(num(7)?, num(8)?),
        sz: num(9)?,
        vz: num(10)?,
        pmin: num(11)?,
        pmax: num(12)?,
        vsp: num(13)?,
        verts: pts(14)?,
        vels: pts(14 + 2 * n)?,
    };
    Ok((name, n, case))
}

/// The file's groups, in the order they first appear.
fn read_groups(path: &str) -> Result<Vec<Group>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut groups: Vec<Group> = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        if fields.is_empty() || fields[0].starts_with('#') {
            continue;
        }
        let (name, n, case) = parse_case(&fields).map_err(|e| format!("{path}:{}: {e}", k + 1))?;
        let kind = match name.as_str() {
            "static" => Kind::Same,
            "warping" => Kind::Diff,
            "3d-static" | "3d-warping" => Kind::Slab,
            _ => return Err(format!("{path}:{}: unknown group {name:?}", k + 1)),
        };
        match groups.iter_mut().find(|g| g.name == name && g.n == n) {
            Some(g) => g.cases.push(case),
            None => groups.push(Group {
                name,
                n,
                kind,
                cases: vec![case],
            }),
        }
    }
    Ok(groups)
}

fn usage() -> ! {
    eprintln!("usage: workload_speed FILE [--rounds N] [--repeat R] [--warmup W]");
    exit(2);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut file, mut rounds, mut reps, mut warmup) = (None, 30usize, 10usize, 5usize);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || -> usize {
            match it.next().map(|v| v.parse()) {
                Some(Ok(v)) => v,
                _ => usage(),
            }
        };
        match a.as_str() {
            "--rounds" => rounds = value().max(1),
            "--repeat" => reps = value().max(1),
            "--warmup" => warmup = value(),
            _ if file.is_none() && !a.starts_with("--") => file = Some(a.clone()),
            _ => usage(),
        }
    }
    let Some(file) = file else { usage() };
    let groups = match read_groups(&file) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("workload_speed: {e}");
            exit(2);
        }
    };
    for _ in 0..warmup {
        for g in &groups {
            black_box(pass(g, reps));
        }
    }
    for g in &groups {
        let answers: String = g
            .cases
            .iter()
            .map(|c| if detect(g.kind, c) { '1' } else { '0' })
            .collect();
        let calls = (reps * g.cases.len()) as f64;
        let (mut cpu, mut wall) = (Vec::new(), Vec::new());
        for _ in 0..rounds {
            let (c0, t0) = (thread_cpu_ns(), Instant::now());
            black_box(pass(g, reps));
            let (c1, t1) = (thread_cpu_ns(), t0.elapsed());
            cpu.push((c1 - c0) / calls);
            wall.push(t1.as_secs_f64() * 1e9 / calls);
        }
        println!(
            "{} {} {} {:.1} {:.1} {answers}",
            g.name,
            g.n,
            g.cases.len(),
            median(cpu),
            median(wall)
        );
    }
}
