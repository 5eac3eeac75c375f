//! What `polyguard bands`, `recover` and `offset` share (docs/way-out.md): the case file
//! read line by line, each line answered by the harness's way-out answer builder
//! (`polyguard_harness::wayout::answer`), errors as error lines, the exit status of
//! docs/cases.md.

use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use serde_json::json;

use polyguard_harness::case::Fence;
use polyguard_harness::wayout::answer::{answer_line, Ask, Command};

/// `--sep`, `--sep-v`: a finite distance ≥ 0.
pub fn parse_separation(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x >= 0.0 => Ok(x),
        Ok(x) => Err(format!("{x} is not a distance ≥ 0")),
        Err(e) => Err(format!("{s}: {e}")),
    }
}

/// `--unknown-max-deg`: finite and > 0.
pub fn parse_positive(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        Ok(x) => Err(format!("{x} is not > 0")),
        Err(e) => Err(format!("{s}: {e}")),
    }
}

/// `--eps`: in (0, 1).
pub fn parse_eps(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x > 0.0 && x < 1.0 => Ok(x),
        Ok(x) => Err(format!("{x} is outside (0, 1)")),
        Err(e) => Err(format!("{s}: {e}")),
    }
}

/// `--fence keep-in | keep-out`.
pub fn parse_fence(s: &str) -> Result<Fence, String> {
    Fence::from_name(s).ok_or_else(|| format!("{s:?}: expected keep-in or keep-out"))
}

fn open(file: &Option<PathBuf>) -> io::Result<Box<dyn BufRead>> {
    match file {
        // a directory opens on Unix and fails only at the first read: say so up front
        Some(p) if p.is_dir() => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "is a directory, not a case file",
        )),
        Some(p) if p.as_os_str() != "-" => Ok(Box::new(BufReader::new(File::open(p)?))),
        _ => Ok(Box::new(BufReader::new(io::stdin().lock()))),
    }
}

fn name_of(file: &Option<PathBuf>) -> String {
    file.as_deref()
        .filter(|p| *p != Path::new("-"))
        .map_or_else(|| "standard input".into(), |p| p.display().to_string())
}

/// Runs one way-out command over a case file (standard input when absent or "-"): one
/// answer line per non-blank line, in order. Exit 0 when every line was answered, 1 when
/// some line gave an error line, 2 when the run could not start or finish.
pub fn run(name: &str, cmd: Command, file: &Option<PathBuf>, ask: &Ask) -> ExitCode {
    let reader = match open(file) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("polyguard {name}: cannot read {}: {e}", name_of(file));
            return ExitCode::from(2);
        }
    };
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    match process(reader, &mut out, cmd, ask).and_then(|f| out.flush().map(|()| f)) {
        Ok(0) => ExitCode::SUCCESS,
        Ok(failed) => {
            eprintln!("polyguard {name}: {failed} line(s) could not be answered");
            ExitCode::from(1)
        }
        Err(e) => {
            eprintln!("polyguard {name}: {}: {e}", name_of(file));
            ExitCode::from(2)
        }
    }
}

/// Streams case lines from `reader` to `out`; returns the number of error lines.
pub fn process<R: BufRead, W: Write>(
    mut reader: R,
    out: &mut W,
    cmd: Command,
    ask: &Ask,
) -> io::Result<u64> {
    let mut buf = Vec::new();
    let mut line_no = 0usize;
    let mut failed = 0u64;
    loop {
        buf.clear();
        if reader.read_until(b'\n', &mut buf)? == 0 {
            break;
        }
        line_no += 1;
        let Ok(text) = std::str::from_utf8(&buf) else {
            failed += 1;
            let line = json!({"id": line_no, "error": {"field": "line", "line": line_no, "message": "not UTF-8"}});
            writeln!(out, "{line}")?;
            continue;
        };
        if text.trim().is_empty() {
            continue;
        }
        let (answer, ok) = answer_line(cmd, text, line_no, ask);
        if !ok {
            failed += 1;
        }
        writeln!(out, "{answer}")?;
    }
    Ok(failed)
}
