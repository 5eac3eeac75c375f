//! Writes the benchmark workload (`polyguard_harness::workload`) as case lines, so that
//! `polyguard detect --repeat R --timing` times it and counts its answers' `kind`:
//!
//! ```text
//! cargo run --release -p polyguard-harness --example uniform_workload -- 256 > workload.jsonl
//! polyguard detect workload.jsonl --repeat 200 --timing > answers.jsonl
//! ```
//!
//! The argument is the number of cases per group (2D static and warping at n = 4, 8,
//! 16, 32, 64; 3D static and warping at n = 8), 256 by default; each group has its own
//! seeds, as in the criterion bench; the few clockwise polygons of the random workload
//! are left out (the case format requires counterclockwise ones).
//!
//! With `--plain` the same cases, in the same order, are written as whitespace-separated
//! text that a few lines of C++ or Java read (benches/polycarp/, docs/performance.md's
//! "Against PolyCARP"): one case a line,
//!
//! ```text
//! GROUP n T BUFF FAC sx sy vx vy sz vz pmin pmax vsp x_0 y_0 … x_n−1 y_n−1 vx_0 vy_0 … vx_n−1 vy_n−1
//! ```
//!
//! GROUP is `static`, `warping`, `3d-static` or `3d-warping`; the 3D fields (sz vz pmin
//! pmax vsp) are 0 in the 2D groups; every number is printed shortest round-trip, so
//! reading it back gives the same f64. Lines starting with `#` are comments.

use std::io::{self, BufWriter, Write};

use polyguard::Vect2;
use polyguard_harness::workload::{workload, BUFF, FAC, T};

/// The 3D groups' slab: bottom, top and vertical speed.
const SLAB: (f64, f64, f64) = (0.0, 1000.0, 0.0);

/// One case of a group, as the paper's detectors take it.
struct Case<'a> {
    s: Vect2,
    v: Vect2,
    z: Option<(f64, f64)>,
    verts: &'a [Vect2],
    vels: &'a [Vect2],
}

fn pairs(v: &[Vect2]) -> String {
    let items: Vec<String> = v.iter().map(|p| format!("[{:?},{:?}]", p.x, p.y)).collect();
    format!("[{}]", items.join(","))
}

/// The case as a JSON case line (the case format of docs/cases.md).
fn json_line(out: &mut impl Write, id: &str, c: &Case) -> io::Result<()> {
    let (s, v) = (c.s, c.v);
    let (pos, vel, slab) = match c.z {
        Some((sz, vz)) => (
            format!("[{:?},{:?},{:?}]", s.x, s.y, sz),
            format!("[{:?},{:?},{:?}]", v.x, v.y, vz),
            format!(
                ",\"bottom\":{:?},\"top\":{:?},\"vz\":{:?}",
                SLAB.0, SLAB.1, SLAB.2
            ),
        ),
        None => (
            format!("[{:?},{:?}]", s.x, s.y),
            format!("[{:?},{:?}]", v.x, v.y),
            String::new(),
        ),
    };
    writeln!(
        out,
        "{{\"id\":\"{id}\",\"lookahead\":{T:?},\"buff\":{BUFF:?},\"fac\":{FAC:?},\"point\":{{\"pos\":{pos},\"vel\":{vel}}},\"polygon\":{{\"vertices\":{},\"velocities\":{}{slab}}}}}",
        pairs(c.verts),
        pairs(c.vels),
    )
}

/// The case as a plain line (the module doc's format).
fn plain_line(out: &mut impl Write, group: &str, c: &Case) -> io::Result<()> {
    let (sz, vz) = c.z.unwrap_or((0.0, 0.0));
    let (pmin, pmax, vsp) = if c.z.is_some() { SLAB } else { (0.0, 0.0, 0.0) };
    write!(
        out,
        "{group} {} {T:?} {BUFF:?} {FAC:?} {:?} {:?} {:?} {:?} {sz:?} {vz:?} {pmin:?} {pmax:?} {vsp:?}",
        c.verts.len(),
        c.s.x,
        c.s.y,
        c.v.x,
        c.v.y,
    )?;
    for p in c.verts.iter().chain(c.vels) {
        write!(out, " {:?} {:?}", p.x, p.y)?;
    }
    writeln!(out)
}

fn usage() -> ! {
    eprintln!("usage: uniform_workload [--plain] [CASES_PER_GROUP]");
    std::process::exit(2);
}

fn main() -> io::Result<()> {
    let mut per_group: usize = 256;
    let mut plain = false;
    for a in std::env::args().skip(1) {
        if a == "--plain" {
            plain = true;
        } else {
            match a.parse() {
                Ok(n) => per_group = n,
                Err(_) => {
                    eprintln!("uniform_workload: {a:?} is not a number of cases");
                    usage();
                }
            }
        }
    }
    let out = io::stdout();
    let mut out = BufWriter::new(out.lock());
    if plain {
        writeln!(out, "# GROUP n T BUFF FAC sx sy vx vy sz vz pmin pmax vsp vertices(x y)*n velocities(x y)*n")?;
    }
    let mut groups: Vec<(usize, bool, bool, u64)> = Vec::new();
    for warping in [false, true] {
        for n in [4usize, 8, 16, 32, 64] {
            groups.push((n, warping, false, 42 + n as u64));
        }
        groups.push((8, warping, true, 7));
    }
    for (n, warping, three, seed) in groups {
        let group = format!(
            "{}{}",
            if three { "3d-" } else { "" },
            if warping { "warping" } else { "static" }
        );
        let mut done = 0;
        let mut round = 0u64;
        while done < per_group {
            let w = workload(n, warping, seed + 1000 * round);
            for i in 0..w.s.len() {
                if done == per_group {
                    break;
                }
                // The case format takes simple counterclockwise rings only (the bench's
                // raw workload also has clockwise and self-crossing ones): those are
                // left out here.
                if !polyguard::ring::simple_ccw(&w.verts[i]) {
                    continue;
                }
                let case = Case {
                    s: w.s[i],
                    v: w.v[i],
                    z: three.then_some(w.z[i]),
                    verts: &w.verts[i],
                    vels: &w.vels[i],
                };
                if plain {
                    plain_line(&mut out, &group, &case)?;
                } else {
                    json_line(&mut out, &format!("{group}-n{n}-{done}"), &case)?;
                }
                done += 1;
            }
            round += 1;
        }
    }
    out.flush()
}
