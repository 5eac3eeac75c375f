//! The benchmark workload, shared by benches/detect.rs (criterion),
//! crates/harness/examples/speed_ratio.rs and [`write_cases`] (the same cases as case lines, for
//! `polyguard detect`, written by crates/harness/examples/uniform_workload.rs):
//! random star-shaped counterclockwise polygons of size ~1000, lookahead 300, BUFF 0.01,
//! F 1e-4, a point starting 1500 from the centre aimed within 800 of it, about half the
//! cases hitting. No threshold is sought: the uniform workload.

use super::gen::{Source, SplitMix};
use polyguard::Vect2;
use std::io::{self, Write};

/// `CASES` cases of one shape, as the engine's paper functions take them.
pub struct Workload {
    /// Each case's polygon, counterclockwise (a few raw polygons cross themselves; the
    /// case format refuses those, the paper functions take them).
    pub verts: Vec<Vec<Vect2>>,
    /// Each case's vertex velocities.
    pub vels: Vec<Vec<Vect2>>,
    /// Each case's point.
    pub s: Vec<Vect2>,
    /// Each case's point velocity.
    pub v: Vec<Vect2>,
    /// Each case's point height and vertical speed, for the 3D benches (slab 0 to 1000).
    pub z: Vec<(f64, f64)>,
}

/// T, the lookahead time.
pub const T: f64 = 300.0;
/// BUFF.
pub const BUFF: f64 = 0.01;
/// F.
pub const FAC: f64 = 1e-4;
/// Cases per workload.
pub const CASES: usize = 256;

/// The workload of `CASES` cases with `n`-gons, warping or not, from `seed`.
pub fn workload(n: usize, warping: bool, seed: u64) -> Workload {
    let mut rng = SplitMix(seed);
    let mut w = Workload {
        verts: vec![],
        vels: vec![],
        s: vec![],
        v: vec![],
        z: vec![],
    };
    for _ in 0..CASES {
        // Star-shaped around the origin: sorted angles, radii 250…500 (size ~1000).
        let mut angles: Vec<f64> = (0..n)
            .map(|_| rng.range(0.0, std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        let verts: Vec<Vect2> = angles
            .iter()
            .map(|&a| {
                let r = rng.range(250.0, 500.0);
                Vect2::new(r * a.cos(), r * a.sin())
            })
            .collect();
        let drift = Vect2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let vels = (0..n)
            .map(|_| {
                if warping {
                    drift + Vect2::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5))
                } else {
                    drift
                }
            })
            .collect();
        // Start 1500 from the centre, aim within 800 of it, cover ~2000 in T.
        let a = rng.range(0.0, std::f64::consts::TAU);
        let s = Vect2::new(1500.0 * a.cos(), 1500.0 * a.sin());
        let target = Vect2::new(rng.range(-800.0, 800.0), rng.range(-800.0, 800.0));
        let d = target - s;
        let v = d.scale(rng.range(5.0, 8.0) / d.sq().sqrt());
        w.verts.push(verts);
        w.vels.push(vels);
        w.s.push(s);
        w.v.push(v);
        w.z.push((rng.range(100.0, 1000.0), rng.range(-1.0, 1.0)));
    }
    w
}

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
fn json_line(out: &mut dyn Write, id: &str, c: &Case) -> io::Result<()> {
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
fn plain_line(out: &mut dyn Write, group: &str, c: &Case) -> io::Result<()> {
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

/// The workload as case lines, `per_group` cases in each of twelve groups (2D static and
/// warping at n = 4, 8, 16, 32, 64; 3D static and warping at n = 8), each group from its
/// own seeds as in the criterion bench: JSON case lines (docs/cases.md) with ids
/// `GROUP-nN-K`, or with `plain` the whitespace-separated lines that the PolyCARP drivers
/// read (crates/harness/examples/uniform_workload.rs gives both formats). The few
/// clockwise or self-crossing polygons of the random workload are left out: the case
/// format takes simple counterclockwise rings only.
pub fn write_cases(out: &mut dyn Write, per_group: usize, plain: bool) -> io::Result<()> {
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
                    plain_line(out, &group, &case)?;
                } else {
                    json_line(out, &format!("{group}-n{n}-{done}"), &case)?;
                }
                done += 1;
            }
            round += 1;
        }
    }
    Ok(())
}
