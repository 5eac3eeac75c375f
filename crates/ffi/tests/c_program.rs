//! The C test program (tests/c/test_polyguard.c) built with `cc` against this build's
//! static and shared libraries and run, through tests/run_c_tests.sh (extends the C
//! interface's tests; paper A §II.H, §II.I, §III on the example cases). Skipped, with a
//! message, where there is no `cc`. The comparison with the CLI's answers needs the
//! `polyguard` binary and runs in CI (.ci/run calls the script directly).

use std::path::Path;
use std::process::Command;

#[test]
fn the_c_test_program_passes() {
    if Command::new("cc").arg("--version").output().is_err() {
        eprintln!("skipped: no `cc` on this machine");
        return;
    }
    // The test binary sits in target/<profile>/deps, beside the libraries cargo built
    // for it from the same source (every crate type of the lib; `cargo test` does not
    // copy them up to target/<profile>, where they may be stale).
    let exe = std::env::current_exe().expect("the test binary's path");
    let lib_dir = exe.parent().expect("target/<profile>/deps");
    assert!(
        lib_dir.join("libpolyguard_ffi.a").exists(),
        "no libpolyguard_ffi.a in {}",
        lib_dir.display()
    );
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/run_c_tests.sh");
    let out = Command::new("bash")
        .arg(&script)
        .env("PG_LIB_DIR", lib_dir)
        .env("PG_CLI", "")
        .env(
            "CARGO_TARGET_DIR",
            lib_dir.parent().and_then(Path::parent).expect("target"),
        )
        .output()
        .expect("bash runs tests/run_c_tests.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "run_c_tests.sh failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
    assert!(
        stdout.contains("C interface: all checks passed"),
        "{stdout}"
    );
    assert_eq!(stdout.matches(" checks, 0 failed").count(), 2, "{stdout}");
}
