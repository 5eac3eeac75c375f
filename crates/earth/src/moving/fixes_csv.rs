//! A CSV of fixes (RFC 4180) with the columns the `traffic` library and OpenSky exports
//! use, grouped into trajectories (docs/moving-features.md, "Formats").
//!
//! Columns: `timestamp` (RFC 3339, or epoch seconds), `icao24`, `latitude`, `longitude`
//! are required; `callsign`, `altitude` (feet; an empty cell is no altitude at that fix)
//! and `flight_id` are read when present; any other column is named in one warning.
//!
//! Grouping and ids: with a `flight_id` column, the rows of one (non-empty) flight_id
//! make one trajectory whose id is that flight_id. Otherwise (and for rows whose
//! flight_id cell is empty) the rows of one (`icao24`, `callsign`) make one trajectory,
//! whose id is the icao24 when that icao24 has one group only, else `icao24/callsign`
//! (the group without a callsign keeping the bare icao24). Trajectories come in the order
//! of their first row.
//!
//! Rows: within a trajectory the times must strictly increase in file order. A row that
//! breaks this, or has a bad cell, is an error naming its line and column and is skipped;
//! the rest is still read. Rows whose latitude and longitude are both empty (ADS-B
//! messages without a position) are skipped and counted in one warning, not an error
//! each. A trajectory left with fewer than 2 fixes is an error.

use super::error::{ErrorKind, Location, MovingError, MovingWarning, WarningKind};
use super::geojson::MAX_LAT;
use super::model::{Fix, Trajectory};
use super::time;
use std::collections::HashMap;

/// The columns read, required first.
const REQUIRED: [&str; 4] = ["timestamp", "icao24", "latitude", "longitude"];
/// The optional columns read.
const OPTIONAL: [&str; 3] = ["callsign", "altitude", "flight_id"];

/// What a CSV gave: the trajectories, the errors of skipped rows and short trajectories,
/// and the warnings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CsvRead {
    /// The trajectories, in the order of their first row.
    pub trajectories: Vec<Trajectory>,
    /// Rows skipped and trajectories dropped, each with its line and column.
    pub errors: Vec<MovingError>,
    /// Unknown columns, rows without a position, times without offset.
    pub warnings: Vec<MovingWarning>,
}

/// One record of the text: its first line (1-based) and its fields, unquoted.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The line the record starts on.
    pub line: usize,
    /// The fields, with RFC 4180 quoting removed.
    pub fields: Vec<String>,
}

/// Splits a text into RFC 4180 records: fields separated by commas, records by LF or
/// CRLF; a field in double quotes may hold commas, line breaks and `""` for a quote.
/// Blank lines are skipped. The error is an unclosed quote, at its record's line.
pub fn records(text: &str) -> Result<Vec<Record>, MovingError> {
    RecordReader::new(text.as_bytes()).collect()
}

/// The records of a reader, one at a time ([`records`] without holding the text): a
/// day of fixes need not be in memory at once.
pub struct RecordReader<R> {
    reader: R,
    /// The next record's first line.
    line: usize,
    /// The text of the record being read.
    buf: String,
    /// Whether the first line (which may start with a byte order mark) has been read.
    started: bool,
}

impl<R: std::io::BufRead> RecordReader<R> {
    /// Records of `reader`.
    pub fn new(reader: R) -> Self {
        RecordReader {
            reader,
            line: 1,
            buf: String::new(),
            started: false,
        }
    }

    /// Appends the next line (with its LF) to `buf`: false at the end of the input.
    fn next_line(&mut self) -> Result<bool, MovingError> {
        let n = self.reader.read_line(&mut self.buf).map_err(|e| {
            MovingError::new(
                Location {
                    line: Some(self.line),
                    ..Location::default()
                },
                ErrorKind::Syntax,
                format!("cannot read: {e}"),
            )
        })?;
        Ok(n > 0)
    }
}

impl<R: std::io::BufRead> Iterator for RecordReader<R> {
    type Item = Result<Record, MovingError>;

    /// The next record that is not blank: a line, or as many lines as a quoted field
    /// that holds line breaks needs.
    fn next(&mut self) -> Option<Self::Item> {
        loop {
            self.buf.clear();
            match self.next_line() {
                Ok(true) => {}
                Ok(false) => return None,
                Err(e) => return Some(Err(e)),
            }
            if !self.started {
                self.started = true;
                if let Some(rest) = self.buf.strip_prefix('\u{feff}') {
                    self.buf = rest.to_owned();
                }
            }
            let start = self.line;
            let (fields, lines) = if self.buf.contains('"') {
                // A quoted field may hold line breaks: take lines while a quote is open.
                while self.buf.matches('"').count() % 2 == 1 {
                    match self.next_line() {
                        Ok(true) => {}
                        Ok(false) => break,
                        Err(e) => return Some(Err(e)),
                    }
                }
                match quoted_record(&self.buf, start) {
                    Ok((f, _, lines)) => (f, lines),
                    Err(e) => return Some(Err(e)),
                }
            } else {
                // The common row: no quotes, so the fields are the pieces between commas
                // (a CR just before the LF ends the line, as in CRLF text).
                let row = match self.buf.strip_suffix('\n') {
                    Some(r) => r.strip_suffix('\r').unwrap_or(r),
                    None => &self.buf,
                };
                (row.split(',').map(String::from).collect::<Vec<_>>(), 1)
            };
            self.line += lines;
            let blank = fields.len() == 1 && fields[0].trim().is_empty() && !self.buf.contains('"');
            if !blank {
                return Some(Ok(Record {
                    line: start,
                    fields,
                }));
            }
        }
    }
}

/// One record read char by char from the start of `text` (RFC 4180 quoting), starting
/// on line `start`: its fields, the bytes it used (through its LF) and the lines it
/// spans.
fn quoted_record(text: &str, start: usize) -> Result<(Vec<String>, usize, usize), MovingError> {
    let mut chars = text.char_indices().peekable();
    let mut fields = Vec::new();
    let mut field = String::new();
    let mut lines = 1;
    loop {
        match chars.next() {
            None => {
                fields.push(field);
                return Ok((fields, text.len(), lines));
            }
            Some((_, '"')) if field.is_empty() => loop {
                match chars.next() {
                    None => {
                        return Err(MovingError::new(
                            Location {
                                line: Some(start),
                                ..Location::default()
                            },
                            ErrorKind::Syntax,
                            "a quoted field is not closed",
                        ))
                    }
                    Some((_, '"')) if chars.peek().map(|c| c.1) == Some('"') => {
                        chars.next();
                        field.push('"');
                    }
                    Some((_, '"')) => break,
                    Some((_, c)) => {
                        if c == '\n' {
                            lines += 1;
                        }
                        field.push(c);
                    }
                }
            },
            Some((_, ',')) => fields.push(std::mem::take(&mut field)),
            Some((_, '\r')) if chars.peek().map(|c| c.1) == Some('\n') => {}
            Some((i, '\n')) => {
                fields.push(field);
                return Ok((fields, i + 1, lines));
            }
            Some((_, c)) => field.push(c),
        }
    }
}

/// Which rows make one trajectory.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Group {
    /// A flight_id.
    Flight(String),
    /// An icao24 and a callsign (maybe none).
    Aircraft(String, Option<String>),
}

/// Column indices of the header.
struct Columns {
    required: [usize; 4],
    callsign: Option<usize>,
    altitude: Option<usize>,
    flight_id: Option<usize>,
}

/// The header: required columns found, unknown ones named in one warning.
fn columns(header: &Record, warnings: &mut Vec<MovingWarning>) -> Result<Columns, MovingError> {
    let names: Vec<&str> = header.fields.iter().map(|f| f.trim()).collect();
    let find = |c: &str| names.iter().position(|&n| n == c);
    let mut required = [0; 4];
    for (k, c) in REQUIRED.iter().enumerate() {
        required[k] = find(c).ok_or_else(|| {
            MovingError::new(
                Location {
                    line: Some(header.line),
                    member: Some(format!("column {c}")),
                    ..Location::default()
                },
                ErrorKind::Missing,
                format!(
                    "the header has no {c:?} column (required: {})",
                    REQUIRED.join(", ")
                ),
            )
        })?;
    }
    let unknown: Vec<&str> = names
        .iter()
        .copied()
        .filter(|n| !REQUIRED.contains(n) && !OPTIONAL.contains(n))
        .collect();
    if !unknown.is_empty() {
        warnings.push(MovingWarning::new(
            Location {
                line: Some(header.line),
                ..Location::default()
            },
            WarningKind::UnknownColumns,
            format!("columns not read: {}", unknown.join(", ")),
        ));
    }
    Ok(Columns {
        required,
        callsign: find("callsign"),
        altitude: find("altitude"),
        flight_id: find("flight_id"),
    })
}

/// The error of a cell: its line and column.
fn cell_err(line: usize, column: &str, kind: ErrorKind, detail: String) -> MovingError {
    MovingError::new(
        Location {
            line: Some(line),
            member: Some(format!("column {column}")),
            ..Location::default()
        },
        kind,
        detail,
    )
}

/// A number cell: finite, within `range` when given.
fn number(
    line: usize,
    column: &str,
    cell: &str,
    range: Option<(f64, f64)>,
) -> Result<f64, MovingError> {
    let x: f64 = cell.trim().parse().map_err(|_| {
        cell_err(
            line,
            column,
            ErrorKind::WrongType,
            format!("{cell:?} is not a number"),
        )
    })?;
    if !x.is_finite() {
        return Err(cell_err(
            line,
            column,
            ErrorKind::NotFinite,
            format!("{cell:?}"),
        ));
    }
    if let Some((lo, hi)) = range {
        if !(lo..=hi).contains(&x) {
            return Err(cell_err(
                line,
                column,
                ErrorKind::OutOfRange,
                format!("{x} is not in [{lo}, {hi}]"),
            ));
        }
    }
    Ok(x)
}

/// A timestamp cell: epoch seconds when it reads as a number, else RFC 3339 (without an
/// offset: UTC, noted in `no_offset`).
fn timestamp(line: usize, cell: &str, no_offset: &mut usize) -> Result<f64, MovingError> {
    let c = cell.trim();
    if let Ok(x) = c.parse::<f64>() {
        return time::epoch_seconds(x)
            .map_err(|why| cell_err(line, "timestamp", ErrorKind::OutOfRange, why));
    }
    let p = time::parse(c).map_err(|why| {
        cell_err(
            line,
            "timestamp",
            ErrorKind::BadTime,
            format!("{c:?}: {why}"),
        )
    })?;
    if !p.has_offset {
        *no_offset += 1;
    }
    Ok(p.t)
}

/// A non-empty trimmed cell, or none.
fn text(cell: Option<&String>) -> Option<String> {
    cell.map(|c| c.trim())
        .filter(|c| !c.is_empty())
        .map(str::to_owned)
}

/// One row: its group and its fix, or `Ok(None)` for a row without a position.
fn row(
    cols: &Columns,
    r: &Record,
    no_offset: &mut usize,
) -> Result<Option<(Keys, Fix)>, MovingError> {
    let [ti, ii, lai, loi] = cols.required;
    let cell = |k: usize| r.fields[k].as_str();
    if cell(lai).trim().is_empty() && cell(loi).trim().is_empty() {
        return Ok(None);
    }
    let t = timestamp(r.line, cell(ti), no_offset)?;
    let icao24 = text(r.fields.get(ii))
        .ok_or_else(|| cell_err(r.line, "icao24", ErrorKind::Missing, "empty icao24".into()))?;
    let lat = number(r.line, "latitude", cell(lai), Some((-MAX_LAT, MAX_LAT)))?;
    let lon = number(r.line, "longitude", cell(loi), Some((-180.0, 180.0)))?;
    let alt_ft = match cols.altitude.map(cell).filter(|c| !c.trim().is_empty()) {
        Some(c) => Some(number(r.line, "altitude", c, None)?),
        None => None,
    };
    let callsign = cols.callsign.and_then(|k| text(r.fields.get(k)));
    let keys = Keys {
        icao24,
        callsign,
        flight_id: cols.flight_id.and_then(|k| text(r.fields.get(k))),
    };
    Ok(Some((
        keys,
        Fix {
            t,
            lon,
            lat,
            alt_ft,
        },
    )))
}

/// Reads a CSV of fixes into trajectories. The error is for a text without a usable
/// header (not CSV, or a required column missing); row problems are in
/// [`CsvRead::errors`].
pub fn read(input: &str) -> Result<CsvRead, MovingError> {
    read_from(input.as_bytes())
}

/// [`read`] from a reader, one record at a time: the memory it holds is the
/// trajectories', not the text's.
pub fn read_from(input: impl std::io::BufRead) -> Result<CsvRead, MovingError> {
    let mut recs = RecordReader::new(input);
    let mut out = CsvRead::default();
    let header = match recs.next() {
        Some(h) => h?,
        None => {
            return Err(MovingError::new(
                Location::default(),
                ErrorKind::Missing,
                "no header line (timestamp, icao24, latitude, longitude, …)",
            ))
        }
    };
    let cols = columns(&header, &mut out.warnings)?;
    let (mut no_position, mut first_no_position, mut no_offset) = (0usize, None, 0usize);
    let mut grouping = Grouping::default();
    for r in recs {
        let r = match r {
            Ok(r) => r,
            Err(e) => {
                // An unclosed quote runs to the end of the input; a read error stops it.
                out.errors.push(e);
                break;
            }
        };
        let r = &r;
        if r.fields.len() != header.fields.len() {
            out.errors.push(MovingError::new(
                Location {
                    line: Some(r.line),
                    ..Location::default()
                },
                ErrorKind::Syntax,
                format!(
                    "{} fields, the header has {}",
                    r.fields.len(),
                    header.fields.len()
                ),
            ));
            continue;
        }
        let (keys, fix) = match row(&cols, r, &mut no_offset) {
            Ok(Some(g)) => g,
            Ok(None) => {
                no_position += 1;
                first_no_position.get_or_insert(r.line);
                continue;
            }
            Err(e) => {
                out.errors.push(e);
                continue;
            }
        };
        let at = Location {
            line: Some(r.line),
            ..Location::default()
        };
        if let Err(e) = grouping.push(at, keys, fix) {
            out.errors.push(e);
        }
    }
    let (trajectories, errors) = grouping.finish();
    out.trajectories = trajectories;
    out.errors.extend(errors);
    if no_position > 0 {
        out.warnings.push(MovingWarning::new(
            Location {
                line: first_no_position,
                ..Location::default()
            },
            WarningKind::NoPosition,
            format!("{no_position} rows without latitude and longitude skipped (the first here)"),
        ));
    }
    if no_offset > 0 {
        out.warnings.push(MovingWarning::new(
            Location::default(),
            WarningKind::NoOffset,
            format!("{no_offset} timestamps without a UTC offset read as UTC"),
        ));
    }
    Ok(out)
}

/// An instant for a message.
fn shown(t: f64) -> String {
    time::format(t, time::Round::Floor).unwrap_or_else(|| format!("{t} s"))
}

/// What groups a fix: its aircraft, callsign and flight (the module's grouping rule).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Keys {
    /// The aircraft's ICAO 24-bit address (non-empty).
    pub icao24: String,
    /// The callsign, when known (non-empty).
    pub callsign: Option<String>,
    /// The flight's id, when known (non-empty).
    pub flight_id: Option<String>,
}

/// One trajectory being built: its group, callsign, fixes and the location of its first
/// row.
struct Building {
    group: Group,
    callsign: Option<String>,
    fixes: Vec<Fix>,
    first: Location,
}

/// Fixes grouped into trajectories by the rule of the module's documentation (flight_id,
/// else icao24 and callsign), row by row in input order: the CSV reader's grouping, shared
/// with readers of other tables of fixes (a data frame's columns).
#[derive(Default)]
pub struct Grouping {
    built: Vec<Building>,
    index: HashMap<Group, usize>,
}

impl Grouping {
    /// Adds the fix of one row located `at` (its line, or its row as `member`) to its
    /// trajectory. The error is a fix not after the trajectory's previous one: the row is
    /// skipped.
    pub fn push(&mut self, at: Location, keys: Keys, fix: Fix) -> Result<(), MovingError> {
        let Keys {
            icao24,
            callsign,
            flight_id,
        } = keys;
        let group = match flight_id {
            Some(f) => Group::Flight(f),
            None => Group::Aircraft(icao24, callsign.clone()),
        };
        let built = &mut self.built;
        let k = *self.index.entry(group.clone()).or_insert_with(|| {
            built.push(Building {
                group,
                callsign: callsign.clone(),
                fixes: Vec::new(),
                first: at.clone(),
            });
            built.len() - 1
        });
        let b = &mut self.built[k];
        if let Some(last) = b.fixes.last() {
            if fix.t <= last.t {
                let member = match &at.member {
                    Some(m) => format!("{m}, column timestamp"),
                    None => "column timestamp".into(),
                };
                return Err(MovingError::new(
                    Location {
                        member: Some(member),
                        ..at
                    },
                    ErrorKind::TimesNotIncreasing,
                    format!(
                        "{} is not after the trajectory's previous fix at {} (row skipped)",
                        shown(fix.t),
                        shown(last.t)
                    ),
                ));
            }
        }
        if b.callsign.is_none() {
            b.callsign = callsign;
        }
        b.fixes.push(fix);
        Ok(())
    }

    /// The trajectories with their ids (the rule of the module's documentation), in the
    /// order of their first row, and the errors of those with fewer than 2 fixes (left
    /// out).
    pub fn finish(self) -> (Vec<Trajectory>, Vec<MovingError>) {
        let mut groups_of: HashMap<String, usize> = HashMap::new();
        for b in &self.built {
            if let Group::Aircraft(icao, _) = &b.group {
                *groups_of.entry(icao.clone()).or_default() += 1;
            }
        }
        let (mut trajectories, mut errors) = (Vec::new(), Vec::new());
        for b in self.built {
            let id = match &b.group {
                Group::Flight(f) => f.clone(),
                Group::Aircraft(icao, Some(cs)) if groups_of.get(icao).is_some_and(|&n| n > 1) => {
                    format!("{icao}/{cs}")
                }
                Group::Aircraft(icao, _) => icao.clone(),
            };
            if b.fixes.len() < 2 {
                errors.push(MovingError::new(
                    Location {
                        id: Some(id),
                        ..b.first
                    },
                    ErrorKind::TooFewFixes,
                    format!("a mover needs at least 2 fixes, found {}", b.fixes.len()),
                ));
                continue;
            }
            trajectories.push(Trajectory {
                id,
                callsign: b.callsign,
                fixes: b.fixes,
            });
        }
        (trajectories, errors)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_fields_hold_commas_quotes_and_line_breaks() {
        let r = records("a,\"b,c\",\"d\"\"e\"\r\n\n\"x\ny\",2,\n3,,\"\"").expect("csv");
        assert_eq!(r.len(), 3);
        assert_eq!(r[0].fields, ["a", "b,c", "d\"e"]);
        assert_eq!(
            (r[1].line, r[1].fields.clone()),
            (3, vec!["x\ny".into(), "2".into(), String::new()])
        );
        assert_eq!(
            (r[2].line, r[2].fields.clone()),
            (5, vec!["3".into(), String::new(), String::new()])
        );
        let e = records("a\n\"b").expect_err("open quote");
        assert_eq!(e.at.line, Some(2));
    }
}
