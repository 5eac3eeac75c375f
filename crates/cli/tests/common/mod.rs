//! What the CLI tests share: running the built `polyguard` binary.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// The repository's root (this crate is `crates/cli`): the tests run the binary there, so
/// paths such as `examples/cases.jsonl` read as in the README.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs the built binary with `input` on standard input: (stdout, stderr, exit code).
/// Output that is not UTF-8 is read lossily (a test of it says so itself).
pub fn run(args: &[&str], input: &[u8]) -> (String, String, i32) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_polyguard"))
        .args(args)
        .current_dir(root())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn polyguard");
    let mut stdin = child.stdin.take().expect("stdin");
    // a closed pipe (the binary exited early) is the test's to judge from the output
    let _ = stdin.write_all(input);
    drop(stdin);
    let out = child.wait_with_output().expect("wait");
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code().unwrap_or(-1),
    )
}
