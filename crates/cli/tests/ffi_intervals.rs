//! `pg_intervals` and `pg_detect_exit` give the command-line tool's answers bit for bit
//! (docs/cases.md, "Separation and fences"): `polyguard detect --intervals --fence
//! keep-in` on examples/intervals.jsonl (each line with its own `sep`, `sep_v`) and on
//! the uniform workload of the benches (`polyguard_harness::workload::write_cases`), with
//! no separation and with --sep 25 --sep-v 20. Each case line is read here into the
//! C structs, so the numbers go the C caller's way: every span's four floats are
//! compared by their bits, and `certain`, `loss_of_separation`, `exits`, `exit_kind`.
//!
//! The CLI is the binary this package builds for its tests, the C interface the
//! polyguard-ffi library linked in: both as the workspace builds them, with nothing built
//! again inside the test.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::ptr;

use polyguard_ffi::*;
use serde_json::Value;

/// The repository's root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Where this test writes its files: target/ffi-intervals, beside the test binary's
/// target/<profile>.
fn scratch() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let target = exe
        .ancestors()
        .nth(3)
        .expect("target/<profile>/deps/<test>")
        .to_path_buf();
    let dir = target.join("ffi-intervals");
    std::fs::create_dir_all(&dir).expect("target/ffi-intervals is writable");
    dir
}

/// Runs a command from the repository's root; its standard output (it must succeed).
fn stdout_of(cmd: &mut Command) -> String {
    let out = cmd
        .current_dir(root())
        .output()
        .unwrap_or_else(|e| panic!("{cmd:?} does not start: {e}"));
    assert!(
        out.status.success(),
        "{cmd:?} failed ({}):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// The polyguard binary of this package.
fn cli() -> Command {
    Command::new(env!("CARGO_BIN_EXE_polyguard"))
}

fn lines(text: &str) -> Vec<Value> {
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect()
}

/// A number of a case line.
fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

/// A list of [x, y] pairs of a case line.
fn pairs(v: &Value) -> Vec<PgVec2> {
    v.as_array()
        .expect("a list of points")
        .iter()
        .map(|p| PgVec2 {
            x: num(&p[0]),
            y: num(&p[1]),
        })
        .collect()
}

/// One case line (docs/cases.md) as the C structs a caller fills, and its own `sep`,
/// `sep_v` when it has them.
struct CCase {
    params: PgParams,
    point: PgPoint,
    vertices: Vec<PgVec2>,
    velocities: Option<Vec<PgVec2>>,
    slab: Option<PgSlab>,
    sep: Option<f64>,
    sep_v: Option<f64>,
}

impl CCase {
    /// The case format's fields, with its defaults (F = 10⁻⁴, κ = 5°).
    fn of(line: &Value) -> CCase {
        let get = |k: &str| line.get(k).filter(|v| !v.is_null());
        let pos = line["point"]["pos"].as_array().expect("point.pos");
        let vel = line["point"]["vel"].as_array().expect("point.vel");
        let poly = &line["polygon"];
        CCase {
            params: PgParams {
                lookahead: num(&line["lookahead"]),
                buff: num(&line["buff"]),
                fac: get("fac").map_or(1e-4, num),
                kappa_deg: get("kappa").map_or(5.0, num),
            },
            point: PgPoint {
                pos: PgVec2 {
                    x: num(&pos[0]),
                    y: num(&pos[1]),
                },
                vel: PgVec2 {
                    x: num(&vel[0]),
                    y: num(&vel[1]),
                },
                has_z: i32::from(pos.len() == 3),
                z: pos.get(2).map_or(0.0, num),
                vz: vel.get(2).map_or(0.0, num),
            },
            vertices: pairs(&poly["vertices"]),
            velocities: poly.get("velocities").map(pairs),
            slab: poly.get("bottom").map(|b| PgSlab {
                bottom: num(b),
                top: num(&poly["top"]),
                vz: num(&poly["vz"]),
            }),
            sep: get("sep").map(num),
            sep_v: get("sep_v").map(num),
        }
    }

    /// The polygon over this case's arrays.
    fn polygon(&self) -> PgPolygon {
        PgPolygon {
            vertices: self.vertices.as_ptr(),
            velocities: self.velocities.as_ref().map_or(ptr::null(), |v| v.as_ptr()),
            n: self.vertices.len(),
            has_slab: i32::from(self.slab.is_some()),
            slab: self.slab.unwrap_or_default(),
        }
    }

    /// `pg_intervals`' whole answer: the count first (cap 0), then exactly that many.
    fn intervals(&self, relation: i32, sep: &PgSeparation) -> Vec<PgSpan> {
        let poly = self.polygon();
        let mut n = 0;
        // SAFETY: valid pointers; cap 0 asks for the count.
        let rc = unsafe {
            pg_intervals(
                &self.params,
                &self.point,
                &poly,
                relation,
                sep,
                ptr::null_mut(),
                0,
                &mut n,
            )
        };
        assert!(rc == PG_OK || rc == PG_ERR_CAPACITY, "status {rc}");
        let mut out = vec![PgSpan::default(); n];
        let mut m = 0;
        // SAFETY: `out` holds n spans.
        let rc = unsafe {
            pg_intervals(
                &self.params,
                &self.point,
                &poly,
                relation,
                sep,
                out.as_mut_ptr(),
                n,
                &mut m,
            )
        };
        assert_eq!((rc, m), (PG_OK, n));
        out
    }

    /// `pg_detect_exit`'s answer.
    fn exit(&self, sep: &PgSeparation) -> PgDetection {
        let poly = self.polygon();
        let mut d = PgDetection::default();
        // SAFETY: valid pointers.
        let rc = unsafe { pg_detect_exit(&self.params, &self.point, &poly, sep, &mut d) };
        assert_eq!(rc, PG_OK);
        d
    }
}

/// An enclosure [lo, hi] of the CLI's answer, bit for bit equal to (lo, hi).
fn same_pair(cli: &Value, lo: f64, hi: f64) -> bool {
    let (a, b) = (num(&cli[0]), num(&cli[1]));
    cli.as_array().map(Vec::len) == Some(2)
        && a.to_bits() == lo.to_bits()
        && b.to_bits() == hi.to_bits()
}

/// What a comparison went through, so that a test can say it was not a dull one.
#[derive(Debug, Default, PartialEq)]
struct Seen {
    /// Case lines.
    cases: usize,
    /// Spans of the three relations.
    spans: usize,
    /// Of them, possible (not certain) ones.
    possible: usize,
    /// Cases whose near_D set is not empty (a loss of separation).
    losses: usize,
    /// Cases that leave the keep-in fence.
    exits: usize,
}

/// Runs `polyguard detect --intervals --fence keep-in FLAGS FILE` and compares every
/// line with the C interface's answers (`sep`, `sep_v`: the flags' values, for lines
/// without their own).
fn compare_with_cli(file: &Path, flags: &[&str], sep: f64, sep_v: f64) -> Seen {
    let cases = lines(&std::fs::read_to_string(file).expect("the case file reads"));
    let answers = lines(&stdout_of(
        cli()
            .args(["detect", "--intervals", "--fence", "keep-in"])
            .args(flags)
            .arg(file),
    ));
    assert_eq!(cases.len(), answers.len(), "one answer per case");
    let mut seen = Seen {
        cases: cases.len(),
        ..Seen::default()
    };
    for (line, cli) in cases.iter().zip(&answers) {
        let id = &cli["id"];
        assert_eq!(&line["id"], id);
        let c = CCase::of(line);
        let iv = &cli["intervals"];
        let s = PgSeparation {
            d: c.sep.unwrap_or(sep),
            h: c.sep_v.unwrap_or(sep_v),
        };
        assert_eq!((num(&iv["sep"]), num(&iv["sep_v"])), (s.d, s.h), "{id}");
        for (name, relation) in [
            ("inside", PG_RELATION_INSIDE),
            ("near", PG_RELATION_NEAR),
            ("breach", PG_RELATION_BREACH),
        ] {
            let mine = c.intervals(relation, &s);
            let theirs = iv[name].as_array().expect("a list of spans");
            assert_eq!(
                mine.len(),
                theirs.len(),
                "{id} {name}: {mine:?} vs {theirs:?}"
            );
            for (m, t) in mine.iter().zip(theirs) {
                assert!(
                    same_pair(&t["start"], m.start_lo, m.start_hi)
                        && same_pair(&t["end"], m.end_lo, m.end_hi)
                        && t["certain"].as_bool() == Some(m.certain == 1),
                    "{id} {name}: {m:?} vs the CLI's {t}"
                );
            }
            seen.spans += mine.len();
            seen.possible += mine.iter().filter(|m| m.certain == 0).count();
            if relation == PG_RELATION_NEAR {
                seen.losses += usize::from(!mine.is_empty());
                let loss = &iv["loss_of_separation"];
                match mine.first() {
                    None => assert!(loss.is_null(), "{id}: loss {loss}"),
                    Some(f) => assert!(same_pair(loss, f.start_lo, f.start_hi), "{id}"),
                }
            }
        }
        let d = c.exit(&s);
        assert_eq!(cli["fence"], "keep_in", "{id}");
        assert_eq!(cli["exits"].as_bool(), Some(d.detected == 1), "{id}");
        let kind = if d.kind == PG_KIND_EXACT {
            "exact"
        } else {
            "conservative"
        };
        assert_eq!(cli["exit_kind"], kind, "{id}");
        assert_eq!(
            cli["well_formed"].as_bool(),
            Some(d.well_formed == 1),
            "{id}"
        );
        seen.exits += usize::from(d.detected == 1);
    }
    seen
}

/// examples/intervals.jsonl: each line's own D and H.
#[test]
fn the_examples_match_the_cli() {
    let file = root().join("examples/intervals.jsonl");
    let seen = compare_with_cli(&file, &[], 0.0, 0.0);
    let expected = Seen {
        cases: 2,
        spans: 10,
        possible: 0,
        losses: 2,
        exits: 2,
    };
    assert_eq!(seen, expected);
}

/// The uniform workload (12 groups of 16 cases: 2D static and warping n-gons of 4 to 64
/// vertices, 3D at n = 8), without and with a separation. Its points all start outside
/// their polygon, so every case leaves the polygon as a keep-in fence at t = 0.
#[test]
fn the_uniform_workload_matches_the_cli() {
    let file = scratch().join("uniform.jsonl");
    let mut text = Vec::new();
    polyguard_harness::workload::write_cases(&mut text, 16, false).expect("the workload writes");
    std::fs::write(&file, text).expect("the workload writes");
    let none = compare_with_cli(&file, &[], 0.0, 0.0);
    let sep = compare_with_cli(&file, &["--sep", "25", "--sep-v", "20"], 25.0, 20.0);
    // Not a dull workload: about half the points meet their polygon, a separation of 25
    // adds near misses, and f64 leaves some tangency unsettled (possible spans).
    assert_eq!((none.cases, none.exits, sep.exits), (192, 192, 192));
    assert!(
        none.losses >= 50 && sep.losses > none.losses,
        "{none:?} {sep:?}"
    );
    assert!(none.spans >= 3 * 192 && none.possible > 0, "{none:?}");
}
