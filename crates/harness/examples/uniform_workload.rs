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

use polyguard_harness::workload::write_cases;

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
    write_cases(&mut out, per_group, plain)?;
    out.flush()
}
