//! The oracle mirrors the engine's names: for each of paper A's modules (quad,
//! contain, proximity, detect, well_formed), every `pub fn` of the engine's module
//! (../src/<module>.rs) has a `pub fn` of the same name in the oracle's module of
//! the same name, with the same parameter names in the same order. The oracle's
//! paper functions are generic over a kernel and take it first, as `k`: that one
//! leading parameter is skipped.
//!
//! A simple text parse: top-level `pub fn` items (column 0), the generic parameter
//! list skipped, the parameters split at top-level commas, the name of each taken
//! before its `:`.

use std::path::Path;

/// Paper A's modules, by their file names in both crates.
const MODULES: [&str; 5] = ["quad", "contain", "proximity", "detect", "well_formed"];

/// The oracle's kernel parameter, first of every kernel-generic paper function.
const KERNEL_PARAM: &str = "k";

/// Engine functions with no oracle counterpart, each for its reason. Every name
/// must exist in the engine (a stale entry fails the test).
const ENGINE_ONLY: [(&str, &str, &str); 11] = [
    // Three-valued (Tri: Yes, No, Unsure) forms of the float engine's functions:
    // in the oracle every paper function already is kernel-generic and returns
    // Result<_, Abstain>, and the exact kernel never abstains.
    ("quad", "quad_min_box_le_d_tri", "three-valued float form"),
    ("contain", "near_edge_tri", "three-valued float form"),
    ("proximity", "segments_close_tri", "three-valued float form"),
    ("detect", "detect_same_2d_tri", "three-valued float form"),
    ("detect", "edge_detect_simp_tri", "three-valued float form"),
    ("detect", "detect_diff_2d_tri", "three-valued float form"),
    ("detect", "detect_3d_tri", "three-valued float form"),
    // Float certification: the same decisions on balls around point-relative
    // coordinates, with error terms; the oracle has no rounding to bound.
    (
        "contain",
        "near_edge_rel",
        "float certification on relative balls",
    ),
    (
        "contain",
        "definitely_outside_rel",
        "float certification on relative balls",
    ),
    (
        "proximity",
        "segments_close_rel",
        "float certification on relative balls",
    ),
    (
        "detect",
        "slab_window_balls",
        "float certification: the window as balls",
    ),
];

/// A top-level `pub fn`: its name and parameter names.
#[derive(Debug, PartialEq)]
struct Sig {
    name: String,
    params: Vec<String>,
}

/// The index just past the bracketed group opening at `open` (`(`, `[` or `<`),
/// where "->" is not a bracket.
fn close(s: &[u8], open: usize) -> usize {
    let mut depth = 0i32;
    let mut i = open;
    while i < s.len() {
        match s[i] {
            b'(' | b'[' | b'<' => depth += 1,
            b'>' if i > 0 && s[i - 1] == b'-' => {}
            b')' | b']' | b'>' => depth -= 1,
            _ => {}
        }
        i += 1;
        if depth == 0 {
            break;
        }
    }
    i
}

/// The names of a parameter list's parameters (`self` forms skipped).
fn param_names(list: &str) -> Vec<String> {
    let b = list.as_bytes();
    let mut parts = Vec::new();
    let (mut start, mut i) = (0, 0);
    while i < b.len() {
        match b[i] {
            b'(' | b'[' | b'<' => {
                i = close(b, i);
                continue;
            }
            b',' => {
                parts.push(&list[start..i]);
                start = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    parts.push(&list[start..]);
    parts
        .iter()
        .filter_map(|p| p.split_once(':').map(|(name, _)| name.trim()))
        .map(|name| name.trim_start_matches("mut ").trim().to_string())
        .filter(|name| !name.is_empty() && !name.ends_with("self"))
        .collect()
}

/// Every top-level `pub fn` of a source file.
fn pub_fns(src: &str) -> Vec<Sig> {
    let src = &format!("\n{src}");
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(found) = src[at..].find("\npub fn ") {
        let start = at + found + "\npub fn ".len();
        let b = src.as_bytes();
        let mut i = start;
        while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
            i += 1;
        }
        let name = src[start..i].to_string();
        if b.get(i) == Some(&b'<') {
            i = close(b, i);
        }
        if b.get(i) == Some(&b'(') {
            let end = close(b, i);
            out.push(Sig {
                name,
                params: param_names(&src[i + 1..end - 1]),
            });
            at = end;
        } else {
            at = i;
        }
    }
    out
}

/// The mismatches of the oracle's module against the engine's (empty: mirrored).
fn mirror_faults(module: &str, engine: &str, oracle: &str) -> Vec<String> {
    let oracle = pub_fns(oracle);
    let mut faults = Vec::new();
    for e in pub_fns(engine) {
        if ENGINE_ONLY
            .iter()
            .any(|&(m, name, _)| m == module && name == e.name)
        {
            continue;
        }
        let Some(o) = oracle.iter().find(|o| o.name == e.name) else {
            faults.push(format!("{module}::{} is missing from the oracle", e.name));
            continue;
        };
        let mut params = o.params.as_slice();
        if params.first().map(String::as_str) == Some(KERNEL_PARAM)
            && e.params.first().map(String::as_str) != Some(KERNEL_PARAM)
        {
            params = &params[1..];
        }
        if params != e.params.as_slice() {
            faults.push(format!(
                "{module}::{}: the engine's parameters are {:?}, the oracle's {:?}",
                e.name, e.params, params
            ));
        }
    }
    faults
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn oracle_mirrors_the_engines_paper_a_functions() {
    let oracle_src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let engine_src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../src");
    let mut faults = Vec::new();
    let mut mirrored = 0;
    for module in MODULES {
        let engine = read(&engine_src.join(format!("{module}.rs")));
        let oracle = read(&oracle_src.join(format!("{module}.rs")));
        let engine_fns = pub_fns(&engine);
        for &(m, name, _) in ENGINE_ONLY.iter().filter(|(m, ..)| *m == module) {
            if !engine_fns.iter().any(|f| f.name == name) {
                faults.push(format!("exemption {m}::{name} names no engine function"));
            }
        }
        mirrored += engine_fns.len();
        faults.extend(mirror_faults(module, &engine, &oracle));
    }
    assert!(mirrored >= 25, "only {mirrored} engine functions read");
    assert!(faults.is_empty(), "{faults:#?}");
}

/// Canaries: a function the oracle lacks and a renamed parameter are reported;
/// the parse copes with generics, `->` inside parameter types and methods.
#[test]
fn the_check_catches_a_missing_function_and_a_renamed_parameter() {
    let engine = "\
//! m
pub fn no_such_paper_function(t: f64, s: Vect2) -> bool {
    true
}

pub fn near_edge<P: VertexSeq + ?Sized>(pi: Vect2, pj: &P, terms: impl Fn() -> Option<(A, B)>, buff: f64) -> bool {
    true
}

impl X {
    pub fn method(&self) {}
}
";
    let oracle = "\
pub fn near_edge<N: Arith, K: Kernel<N>>(
    k: &K,
    pi: &V2<N>,
    pj: &[V2<N>],
    terms: &N,
    buf: &N,
) -> Result<bool, K::Abstain> {
    todo!()
}
";
    assert_eq!(
        pub_fns(engine)[1],
        Sig {
            name: "near_edge".into(),
            params: vec!["pi".into(), "pj".into(), "terms".into(), "buff".into()],
        }
    );
    let faults = mirror_faults("contain", engine, oracle);
    assert_eq!(faults.len(), 2, "{faults:#?}");
    assert!(faults[0].contains("no_such_paper_function is missing"));
    assert!(faults[1].contains("\"buf\""));
}
