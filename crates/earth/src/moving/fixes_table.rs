//! A table of fixes held in columns (a pandas data frame of the `traffic` library or of
//! MovingPandas, handed over as arrays), read as the CSV of fixes is
//! (docs/moving-features.md, "CSV of fixes"): the same columns, the same checks of each
//! cell and the same grouping into trajectories ([`super::fixes_csv::Grouping`]).
//!
//! Rows are named by their position, counting from 0 (`row 7, column latitude`). A row
//! whose latitude and longitude are both NaN (a message without a position) is skipped
//! and counted in one warning; a NaN altitude is no altitude at that fix.

use super::error::{ErrorKind, Location, MovingError, MovingWarning, WarningKind};
use super::fixes_csv::{CsvRead, Grouping, Keys};
use super::geojson::MAX_LAT;
use super::model::Fix;
use super::time;

/// The columns of a table of fixes, one entry per row (every column as long as `t`).
#[derive(Clone, Copy, Debug)]
pub struct FixColumns<'a> {
    /// Seconds since 1970-01-01T00:00:00Z.
    pub t: &'a [f64],
    /// Longitude, degrees.
    pub lon: &'a [f64],
    /// Latitude, degrees.
    pub lat: &'a [f64],
    /// Altitude, feet (NaN: none at that row); `None`: no altitude column.
    pub alt_ft: Option<&'a [f64]>,
    /// The aircraft's ICAO 24-bit address (`None` or empty: an error at that row).
    pub icao24: &'a [Option<String>],
    /// The callsign column, when there is one (`None` or empty: none at that row).
    pub callsign: Option<&'a [Option<String>]>,
    /// The flight_id column, when there is one (`None` or empty: grouped by aircraft).
    pub flight_id: Option<&'a [Option<String>]>,
}

/// The error of a cell: its row and column.
fn cell_err(row: usize, column: &str, kind: ErrorKind, detail: String) -> MovingError {
    MovingError::new(
        Location {
            member: Some(format!("row {row}, column {column}")),
            ..Location::default()
        },
        kind,
        detail,
    )
}

/// A non-empty trimmed text, or none.
fn text(cell: Option<&Option<String>>) -> Option<String> {
    cell.and_then(|c| c.as_deref())
        .map(str::trim)
        .filter(|c| !c.is_empty())
        .map(str::to_owned)
}

/// A coordinate: finite and within `[-lim, lim]` degrees.
fn coordinate(row: usize, column: &str, x: f64, lim: f64) -> Result<f64, MovingError> {
    if !x.is_finite() {
        return Err(cell_err(row, column, ErrorKind::NotFinite, format!("{x}")));
    }
    if !(-lim..=lim).contains(&x) {
        return Err(cell_err(
            row,
            column,
            ErrorKind::OutOfRange,
            format!("{x} is not in [{}, {lim}]", -lim),
        ));
    }
    Ok(x)
}

/// One row: its keys and fix, `Ok(None)` for a row without a position.
fn row(c: &FixColumns, k: usize) -> Result<Option<(Keys, Fix)>, MovingError> {
    let (lat, lon) = (c.lat[k], c.lon[k]);
    if lat.is_nan() && lon.is_nan() {
        return Ok(None);
    }
    let t = time::epoch_seconds(c.t[k])
        .map_err(|why| cell_err(k, "timestamp", ErrorKind::OutOfRange, why))?;
    let icao24 = text(c.icao24.get(k))
        .ok_or_else(|| cell_err(k, "icao24", ErrorKind::Missing, "empty icao24".into()))?;
    let lat = coordinate(k, "latitude", lat, MAX_LAT)?;
    let lon = coordinate(k, "longitude", lon, 180.0)?;
    let alt_ft = match c.alt_ft.map(|a| a[k]).filter(|a| !a.is_nan()) {
        Some(a) if !a.is_finite() => {
            return Err(cell_err(
                k,
                "altitude",
                ErrorKind::NotFinite,
                format!("{a}"),
            ))
        }
        other => other,
    };
    let keys = Keys {
        icao24,
        callsign: c.callsign.and_then(|col| text(col.get(k))),
        flight_id: c.flight_id.and_then(|col| text(col.get(k))),
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

/// Reads the columns into trajectories, row by row as [`super::fixes_csv::read`] reads
/// records. The error is columns of different lengths; row problems are in
/// [`CsvRead::errors`].
pub fn read(c: &FixColumns) -> Result<CsvRead, MovingError> {
    let n = c.t.len();
    let lengths = [
        ("longitude", c.lon.len()),
        ("latitude", c.lat.len()),
        ("altitude", c.alt_ft.map_or(n, <[f64]>::len)),
        ("icao24", c.icao24.len()),
        ("callsign", c.callsign.map_or(n, <[Option<String>]>::len)),
        ("flight_id", c.flight_id.map_or(n, <[Option<String>]>::len)),
    ];
    if let Some((name, len)) = lengths.iter().find(|(_, len)| *len != n) {
        return Err(MovingError::new(
            Location {
                member: Some(format!("column {name}")),
                ..Location::default()
            },
            ErrorKind::Syntax,
            format!("{len} rows, the timestamp column has {n}"),
        ));
    }
    let mut out = CsvRead::default();
    let mut grouping = Grouping::default();
    let (mut no_position, mut first_no_position) = (0usize, None);
    for k in 0..n {
        match row(c, k) {
            Ok(Some((keys, fix))) => {
                let at = Location {
                    member: Some(format!("row {k}")),
                    ..Location::default()
                };
                if let Err(e) = grouping.push(at, keys, fix) {
                    out.errors.push(e);
                }
            }
            Ok(None) => {
                no_position += 1;
                first_no_position.get_or_insert(k);
            }
            Err(e) => out.errors.push(e),
        }
    }
    let (trajectories, errors) = grouping.finish();
    out.trajectories = trajectories;
    out.errors.extend(errors);
    if let Some(first) = first_no_position {
        out.warnings.push(MovingWarning::new(
            Location {
                member: Some(format!("row {first}")),
                ..Location::default()
            },
            WarningKind::NoPosition,
            format!("{no_position} rows without latitude and longitude skipped (the first here)"),
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::moving::fixes_csv;

    #[test]
    fn columns_group_as_the_csv_of_the_same_rows() {
        let csv = "timestamp,icao24,callsign,latitude,longitude,altitude\n\
                   10,abc,AF1,45,2,1000\n\
                   20,abc,AF1,45.1,2.1,\n\
                   5,def,,46,3,2000\n\
                   15,abc,AF1,45.2,2.2,1200\n\
                   30,abc,AF2,45.3,2.3,1300\n\
                   40,abc,AF2,45.4,2.4,1400\n\
                   6,def,,46.1,3.1,2100\n\
                   7,def,,,,\n\
                   8,def,,95,3,2100\n";
        let from_csv = fixes_csv::read(csv).expect("csv");
        let s = |v: &[&str]| -> Vec<Option<String>> {
            v.iter()
                .map(|x| Some(x.to_string()).filter(|x| !x.is_empty()))
                .collect()
        };
        let t = [10.0, 20.0, 5.0, 15.0, 30.0, 40.0, 6.0, 7.0, 8.0];
        let lat = [45.0, 45.1, 46.0, 45.2, 45.3, 45.4, 46.1, f64::NAN, 95.0];
        let lon = [2.0, 2.1, 3.0, 2.2, 2.3, 2.4, 3.1, f64::NAN, 3.0];
        let alt = [
            1e3,
            f64::NAN,
            2e3,
            1200.0,
            1300.0,
            1400.0,
            2100.0,
            f64::NAN,
            2100.0,
        ];
        let icao = s(&[
            "abc", "abc", "def", "abc", "abc", "abc", "def", "def", "def",
        ]);
        let cs = s(&["AF1", "AF1", "", "AF1", "AF2", "AF2", "", "", ""]);
        let cols = FixColumns {
            t: &t,
            lon: &lon,
            lat: &lat,
            alt_ft: Some(&alt),
            icao24: &icao,
            callsign: Some(&cs),
            flight_id: None,
        };
        let from_cols = read(&cols).expect("columns");
        assert_eq!(from_cols.trajectories, from_csv.trajectories);
        let ids: Vec<&str> = from_cols
            .trajectories
            .iter()
            .map(|t| t.id.as_str())
            .collect();
        assert_eq!(ids, ["abc/AF1", "def", "abc/AF2"]);
        // the out-of-order fix (15 after 20) and the latitude 95 are errors, in row order
        let kinds: Vec<ErrorKind> = from_cols.errors.iter().map(|e| e.kind).collect();
        assert_eq!(
            kinds,
            [ErrorKind::TimesNotIncreasing, ErrorKind::OutOfRange]
        );
        assert_eq!(
            from_cols.errors[0].at.member.as_deref(),
            Some("row 3, column timestamp")
        );
        assert_eq!(from_cols.warnings.len(), 1);
        let short = FixColumns {
            lat: &lat[..3],
            ..cols
        };
        assert!(read(&short).is_err());
    }
}
