//! The oracle mirrors the engine's names, module by module. For each of paper A's
//! modules (quad, contain, proximity, detect with every file of its folder, well_formed,
//! ring) and of the modules built on them (intervals, fence, offset, recovery and bands: the
//! times inside, near and breaching, keep-in exits, certified offsets, the nearest point out
//! of P's D-neighbourhood or into its D-core, and conflict-free courses and speeds), walked as files in both crates and paired by module path (`detect::same` is
//! src/detect/same.rs), every `pub fn` of the engine's module has a `pub fn` of the same
//! name in the oracle's module of the same path, with the same parameter names in the
//! same order. The oracle's paper functions are generic over a kernel and take it first,
//! as `k`: that one leading parameter is skipped. A module of one crate without its
//! counterpart in the other is a fault unless listed below with its reason. And every
//! one of these files, in both crates, cites its paper section in its module doc (a `§`
//! reference: ring cites §II, whose polygon is simple and counterclockwise).
//!
//! A simple text parse: top-level `pub fn` items (column 0), the generic parameter
//! list skipped, the parameters split at top-level commas, the name of each taken
//! before its `:`. Test modules (files named `tests.rs`) are not paper modules.

use std::collections::BTreeMap;
use std::path::Path;

/// Paper A's modules, by their names in both crates: a file `<name>.rs`, or a folder
/// `<name>/` whose files are its submodules.
const MODULES: [&str; 11] = [
    "quad",
    "contain",
    "proximity",
    "detect",
    "well_formed",
    "ring",
    "intervals",
    "fence",
    "offset",
    "recovery",
    "bands",
];

/// The name of a test module, skipped by the walk.
const TEST_MODULE: &str = "tests";

/// The oracle's kernel parameter, first of every kernel-generic paper function.
const KERNEL_PARAM: &str = "k";

/// Engine modules with no oracle counterpart, each for its reason. Each must exist in
/// the engine and not in the oracle (a stale entry fails the test).
const ENGINE_ONLY_MODULES: [(&str, &str); 12] = [
    (
        "offset::raw",
        "the f64 construction region (strips and circumscribed fans); the oracle checks a \
         result against the true sets and builds none",
    ),
    (
        "offset::arrange",
        "the f64 arrangement that extracts the construction's boundary; the oracle builds \
         no polygon",
    ),
    (
        "offset::certify",
        "the engine's certificate on balls; the oracle decides the same properties exactly \
         (Buffer::check)",
    ),
    (
        "bands::cell",
        "the f64 certificate of a cell between samples; the oracle decides single \
         velocities exactly (bands::conflict)",
    ),
    (
        "bands::refine",
        "the halving of cells into bands, for any cell certificate; the oracle decides \
         single velocities and has no cells to refine",
    ),
    (
        "bands::rigid",
        "the f64 fast path for translating obstacles, certified on balls; the oracle decides \
         single velocities exactly for every motion (bands::conflict)",
    ),
    (
        "detect::filter::lanes",
        "the sweep filter's f64 tests four edges at a time, the same bits as the scalar \
         filter; the oracle decides edge_detect exactly and needs no filter",
    ),
    (
        "detect::warping::crossing",
        "edge_detect_simp's certain yes at float crossing times, checked on balls; the \
         oracle decides the four conditions exactly and needs no witness",
    ),
    (
        "detect::roots",
        "float enclosures of the roots of dot_nn_lin's quadratics; the oracle's roots are \
         exact algebraic numbers (qfield, Kernel::two_roots), with no rounding to bound",
    ),
    (
        "intervals::scan",
        "the f64 branch and bound over time that certifies each piece; the oracle finds \
         every end exactly (intervals::set) and needs no search",
    ),
    (
        "intervals::scan::shortcut",
        "the scan's bracketing of a few sign changes at once: a float speed-up",
    ),
    (
        "intervals::scan::within",
        "the scan's halving of one edge at a time for keep-in exits: a float speed-up",
    ),
];

/// Oracle modules with no engine counterpart, each for its reason.
const ORACLE_ONLY_MODULES: [(&str, &str); 3] = [
    (
        "intervals::scene",
        "the case's polynomials in t with exact coefficients, which the engine evaluates \
         on balls instead",
    ),
    (
        "intervals::boundary",
        "the exact candidate ends (real roots of the scene's polynomials); the engine \
         encloses ends by halving",
    ),
    (
        "intervals::set",
        "the exact evaluation between and at the candidate ends, and the components",
    ),
];

/// Engine functions with no oracle counterpart, each for its reason. Every name
/// must exist in the engine's module and not in the oracle's (a stale entry fails
/// the test).
const ENGINE_ONLY: [(&str, &str, &str); 19] = [
    (
        "bands",
        "velocity",
        "the f64 velocity of a course (libm's sin and cos); the oracle takes an f64 \
         velocity exactly",
    ),
    // The band constructions: a band's ends are transcendental in the course, so the
    // oracle decides single velocities exactly (bands::conflict) and the harness's
    // wayout::bands check draws values inside each band and asks it.
    (
        "bands",
        "course_bands",
        "certified f64 construction; checked by sampling",
    ),
    (
        "bands",
        "speed_bands",
        "certified f64 construction; checked by sampling",
    ),
    (
        "bands",
        "vertical_speed_bands",
        "certified f64 construction; checked by sampling",
    ),
    ("fence", "detect_exit_tri", "three-valued float form"),
    (
        "intervals",
        "intervals_into",
        "the allocation-free slice form; the oracle returns its components",
    ),
    // Three-valued (Tri: Yes, No, Unsure) forms of the float engine's functions:
    // in the oracle every paper function already is kernel-generic and returns
    // Result<_, Abstain>, and the exact kernel never abstains.
    ("quad", "quad_min_box_le_d_tri", "three-valued float form"),
    ("contain", "near_edge_tri", "three-valued float form"),
    ("proximity", "segments_close_tri", "three-valued float form"),
    (
        "detect::same",
        "detect_same_2d_tri",
        "three-valued float form",
    ),
    (
        "detect::warping",
        "edge_detect_simp_tri",
        "three-valued float form",
    ),
    (
        "detect::warping",
        "detect_diff_2d_tri",
        "three-valued float form",
    ),
    ("detect::slab", "detect_3d_tri", "three-valued float form"),
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
        "detect::slab",
        "slab_window_balls",
        "float certification: the window as balls",
    ),
    // The ring checks: the engine's check_simple sweeps large rings, and keeps the
    // pairwise form as the sweep's reference; the oracle's check_simple is pairwise.
    // The engine's check rescales a ring whose exact products over- or underflow;
    // rationals never do, so the oracle's check_simple and winding are the whole check.
    (
        "ring",
        "check_simple_pairwise",
        "the sweep's pairwise reference; the oracle's check_simple is pairwise",
    ),
    (
        "ring",
        "check",
        "rescues rings whose exact float products over- or underflow",
    ),
];

/// The exemptions a comparison honours (the lists above, or a canary's own).
struct Exemptions<'a> {
    engine_only_modules: &'a [(&'a str, &'a str)],
    oracle_only_modules: &'a [(&'a str, &'a str)],
    engine_only_fns: &'a [(&'a str, &'a str, &'a str)],
}

/// The exemptions of the real comparison.
const EXEMPTIONS: Exemptions<'static> = Exemptions {
    engine_only_modules: &ENGINE_ONLY_MODULES,
    oracle_only_modules: &ORACLE_ONLY_MODULES,
    engine_only_fns: &ENGINE_ONLY,
};

/// Paper modules by module path ("detect::same"), each with its source text.
type Tree = BTreeMap<String, String>;

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
fn mirror_faults(module: &str, engine: &str, oracle: &str, ex: &Exemptions) -> Vec<String> {
    let oracle = pub_fns(oracle);
    let mut faults = Vec::new();
    for e in pub_fns(engine) {
        if ex
            .engine_only_fns
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

/// The module doc of a source file: its leading `//!` lines.
fn module_doc(src: &str) -> String {
    src.lines()
        .take_while(|l| l.starts_with("//!"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Does the module doc cite a section of the paper?
fn cites_section(src: &str) -> bool {
    module_doc(src).contains('§')
}

/// Every mismatch between the two trees of paper modules: a module without its
/// counterpart, a function the oracle lacks or names differently, a module doc without
/// a section, and an exemption that no longer applies.
fn mirror_tree(engine: &Tree, oracle: &Tree, ex: &Exemptions) -> Vec<String> {
    let mut faults = Vec::new();
    for (crate_name, tree) in [("engine", engine), ("oracle", oracle)] {
        for (module, src) in tree {
            if !cites_section(src) {
                faults.push(format!(
                    "{crate_name} {module}: its module doc cites no paper section (§)"
                ));
            }
        }
    }
    for (module, src) in engine {
        match oracle.get(module) {
            Some(o) => faults.extend(mirror_faults(module, src, o, ex)),
            None if ex.engine_only_modules.iter().any(|(m, _)| m == module) => {}
            None => faults.push(format!("{module} has no oracle module")),
        }
    }
    for module in oracle.keys() {
        if !engine.contains_key(module) && !ex.oracle_only_modules.iter().any(|(m, _)| m == module)
        {
            faults.push(format!("{module} has no engine module"));
        }
    }
    for &(m, _) in ex.engine_only_modules {
        if !engine.contains_key(m) || oracle.contains_key(m) {
            faults.push(format!("exemption {m}: not an engine-only module"));
        }
    }
    for &(m, _) in ex.oracle_only_modules {
        if !oracle.contains_key(m) || engine.contains_key(m) {
            faults.push(format!("exemption {m}: not an oracle-only module"));
        }
    }
    let has = |tree: &Tree, m: &str, name: &str| {
        tree.get(m)
            .is_some_and(|src| pub_fns(src).iter().any(|f| f.name == name))
    };
    for &(m, name, _) in ex.engine_only_fns {
        if !has(engine, m, name) {
            faults.push(format!("exemption {m}::{name} names no engine function"));
        } else if has(oracle, m, name) {
            faults.push(format!(
                "exemption {m}::{name}: the oracle has it, so compare it"
            ));
        }
    }
    faults
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The `.rs` files below `dir` as module paths under `prefix` (`mod.rs` is the folder's
/// own module), test modules left out.
fn walk(dir: &Path, prefix: &str, tree: &mut Tree) {
    let entries = std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in entries {
        let path = entry
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
            continue;
        };
        if stem == TEST_MODULE {
            continue;
        }
        let module = format!("{prefix}::{stem}");
        if path.is_dir() {
            walk(&path, &module, tree);
        } else if path.extension().is_some_and(|x| x == "rs") {
            let module = if stem == "mod" { prefix } else { &module };
            tree.insert(module.to_string(), read(&path));
        }
    }
}

/// Paper A's modules of one crate's src/, as files.
fn paper_tree(src: &Path) -> Tree {
    let mut tree = Tree::new();
    for module in MODULES {
        let file = src.join(format!("{module}.rs"));
        if file.is_file() {
            tree.insert(module.to_string(), read(&file));
        }
        let folder = src.join(module);
        if folder.is_dir() {
            walk(&folder, module, &mut tree);
        }
    }
    tree
}

/// Both crates' trees: the engine's (../src) and the oracle's (src).
fn trees() -> (Tree, Tree) {
    let oracle_src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let engine_src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../src");
    (paper_tree(&engine_src), paper_tree(&oracle_src))
}

#[test]
fn oracle_mirrors_the_engines_paper_a_modules() {
    let (engine, oracle) = trees();
    let mut faults = Vec::new();
    for module in MODULES {
        for (crate_name, tree) in [("engine", &engine), ("oracle", &oracle)] {
            if !tree.contains_key(module) {
                faults.push(format!("{crate_name} has no module {module}"));
            }
        }
    }
    faults.extend(mirror_tree(&engine, &oracle, &EXEMPTIONS));
    // The walk went into the folders, and read the functions.
    for sub in ["detect::same", "detect::warping", "detect::slab"] {
        assert!(
            engine.contains_key(sub) && oracle.contains_key(sub),
            "{sub} not read"
        );
    }
    let mirrored: usize = engine.values().map(|src| pub_fns(src).len()).sum();
    assert!(mirrored >= 30, "only {mirrored} engine functions read");
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
    let faults = mirror_faults("contain", engine, oracle, &EXEMPTIONS);
    assert_eq!(faults.len(), 2, "{faults:#?}");
    assert!(faults[0].contains("no_such_paper_function is missing"));
    assert!(faults[1].contains("\"buf\""));
}

/// Canaries on the real trees: an extra `pub fn` planted in one engine file, a renamed
/// parameter in another, and an oracle file whose module doc lost its section are each
/// reported, and nothing else.
#[test]
fn the_check_catches_faults_planted_in_the_real_modules() {
    let (mut engine, mut oracle) = trees();
    let before = mirror_tree(&engine, &oracle, &EXEMPTIONS);
    assert!(before.is_empty(), "{before:#?}");
    let slab = engine.get_mut("detect::slab").expect("detect::slab");
    slab.push_str("\npub fn planted_canary(t: f64) -> bool {\n    true\n}\n");
    let same = oracle.get_mut("detect::same").expect("detect::same");
    *same = same.replacen('§', "section ", 1);
    let warping = engine.get_mut("detect::warping").expect("detect::warping");
    *warping = warping.replacen(
        "pub fn edge_detect(\n    t: f64,",
        "pub fn edge_detect(\n    tt: f64,",
        1,
    );
    let faults = mirror_tree(&engine, &oracle, &EXEMPTIONS);
    assert_eq!(faults.len(), 3, "{faults:#?}");
    for want in [
        "oracle detect::same: its module doc cites no paper section",
        "detect::slab::planted_canary is missing from the oracle",
        "detect::warping::edge_detect: the engine's parameters are [\"tt\"",
    ] {
        assert!(
            faults.iter().any(|f| f.contains(want)),
            "{want}: {faults:#?}"
        );
    }
}

/// Canaries on in-memory trees: modules without a counterpart either way, a module doc
/// without a section, and stale exemptions (a function or module that is not there, a
/// function the oracle has after all) are each reported.
#[test]
fn the_check_catches_missing_modules_citations_and_stale_exemptions() {
    let tree = |files: &[(&str, &str)]| -> Tree {
        files
            .iter()
            .map(|&(m, src)| (m.to_string(), src.to_string()))
            .collect()
    };
    let engine = tree(&[
        (
            "detect",
            "//! Paper A §II.F.\npub fn dispatch(vertical: bool) {}\n",
        ),
        ("detect::only_here", "//! Paper A §II.I.\n"),
        ("detect::uncited", "//! No section.\npub fn f(t: f64) {}\n"),
    ]);
    let oracle = tree(&[
        (
            "detect",
            "//! Paper A §II.F.\npub fn dispatch(k: &K, vertical: bool) {}\n",
        ),
        (
            "detect::uncited",
            "//! Paper A §III.\npub fn f(k: &K, t: &N) {}\n",
        ),
        ("detect::orphan", "//! Paper A §III.\n"),
    ]);
    let ex = Exemptions {
        engine_only_modules: &[("detect::gone", "stale")],
        oracle_only_modules: &[("detect::uncited", "in both")],
        engine_only_fns: &[
            ("detect", "dispatch", "the oracle has it"),
            ("detect", "gone", "stale"),
        ],
    };
    let faults = mirror_tree(&engine, &oracle, &ex);
    let want = [
        "engine detect::uncited: its module doc cites no paper section",
        "detect::only_here has no oracle module",
        "detect::orphan has no engine module",
        "exemption detect::gone: not an engine-only module",
        "exemption detect::uncited: not an oracle-only module",
        "exemption detect::dispatch: the oracle has it",
        "exemption detect::gone names no engine function",
    ];
    for w in want {
        assert!(faults.iter().any(|f| f.contains(w)), "{w}: {faults:#?}");
    }
    assert_eq!(faults.len(), want.len(), "{faults:#?}");
}
