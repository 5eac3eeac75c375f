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

use std::io::{self, BufWriter, Write};

use polyguard::Vect2;
use polyguard_harness::workload::{workload, BUFF, FAC, T};

fn pairs(v: &[Vect2]) -> String {
    let items: Vec<String> = v.iter().map(|p| format!("[{:?},{:?}]", p.x, p.y)).collect();
    format!("[{}]", items.join(","))
}

fn main() -> io::Result<()> {
    let per_group: usize = match std::env::args().nth(1) {
        None => 256,
        Some(a) => match a.parse() {
            Ok(n) => n,
            Err(_) => {
                eprintln!("uniform_workload: {a:?} is not a number of cases");
                std::process::exit(2);
            }
        },
    };
    let out = io::stdout();
    let mut out = BufWriter::new(out.lock());
    let mut groups: Vec<(usize, bool, bool, u64)> = Vec::new();
    for warping in [false, true] {
        for n in [4usize, 8, 16, 32, 64] {
            groups.push((n, warping, false, 42 + n as u64));
        }
        groups.push((8, warping, true, 7));
    }
    for (n, warping, three, seed) in groups {
        let mut done = 0;
        let mut round = 0u64;
        while done < per_group {
            let w = workload(n, warping, seed + 1000 * round);
            for i in 0..w.s.len() {
                if done == per_group {
                    break;
                }
                // A random star polygon with an angular gap over half a turn can be
                // clockwise: the case format rejects it, so it is left out here.
                // the case format takes simple counterclockwise rings only (the bench's
                // raw workload also has clockwise and self-crossing ones)
                if !polyguard::ring::simple_ccw(&w.verts[i]) {
                    continue;
                }
                let (s, v) = (w.s[i], w.v[i]);
                let (pos, vel, slab) = if three {
                    let (sz, vz) = w.z[i];
                    (
                        format!("[{:?},{:?},{:?}]", s.x, s.y, sz),
                        format!("[{:?},{:?},{:?}]", v.x, v.y, vz),
                        ",\"bottom\":0.0,\"top\":1000.0,\"vz\":0.0".to_string(),
                    )
                } else {
                    (
                        format!("[{:?},{:?}]", s.x, s.y),
                        format!("[{:?},{:?}]", v.x, v.y),
                        String::new(),
                    )
                };
                writeln!(
                    out,
                    "{{\"id\":\"{}{}-n{n}-{done}\",\"lookahead\":{T:?},\"buff\":{BUFF:?},\"fac\":{FAC:?},\"point\":{{\"pos\":{pos},\"vel\":{vel}}},\"polygon\":{{\"vertices\":{},\"velocities\":{}{slab}}}}}",
                    if three { "3d-" } else { "" },
                    if warping { "warping" } else { "static" },
                    pairs(&w.verts[i]),
                    pairs(&w.vels[i]),
                )?;
                done += 1;
            }
            round += 1;
        }
    }
    out.flush()
}
