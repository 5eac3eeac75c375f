//! Errors and warnings of the moving-features readers (docs/moving-features.md,
//! "Formats"): each names where it is (line, feature, member or column) and what kind of
//! problem it is, in words a user understands.

use std::fmt;

/// Where in the input a problem is. Every field is optional: a reader fills what it knows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Location {
    /// The 1-based line (JSON Lines and CSV: the record's line; a JSON document: the line
    /// of the offending value).
    pub line: Option<usize>,
    /// The feature's index in the input, counting from 0 (a CSV: none).
    pub feature: Option<usize>,
    /// The feature's or trajectory's id, when known.
    pub id: Option<String>,
    /// The member path (`temporalGeometry.datetimes[3]`, `properties.floor_ft`) or the
    /// CSV column (`column latitude`).
    pub member: Option<String>,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts: Vec<String> = Vec::new();
        if let Some(l) = self.line {
            parts.push(format!("line {l}"));
        }
        match (self.feature, &self.id) {
            (Some(k), Some(id)) => parts.push(format!("feature {k} (id {id:?})")),
            (Some(k), None) => parts.push(format!("feature {k}")),
            (None, Some(id)) => parts.push(format!("id {id:?}")),
            (None, None) => {}
        }
        if let Some(m) = &self.member {
            parts.push(m.clone());
        }
        f.write_str(&parts.join(", "))
    }
}

/// What kind of problem an error is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// The text is not JSON (or not a CSV record).
    Syntax,
    /// A number that is NaN or infinite (or a JSON `NaN`/`Infinity`).
    NotFinite,
    /// A number outside its range (longitude, latitude, time).
    OutOfRange,
    /// Times that do not strictly increase.
    TimesNotIncreasing,
    /// A keyframe whose rings or vertex counts differ from the first keyframe's.
    VertexCountChanges,
    /// A member this format does not define where it defines all members
    /// (`temporalGeometry`), or a property that misspells one of ours.
    UnknownMember,
    /// A member given twice in one object.
    DuplicateMember,
    /// A required member or column that is absent.
    Missing,
    /// A value of the wrong JSON type (a string for a number, …).
    WrongType,
    /// A date-time that is not RFC 3339 (or a leap second).
    BadTime,
    /// A ring with fewer than 3 distinct vertices.
    TooFewVertices,
    /// A mover with fewer than 2 fixes.
    TooFewFixes,
    /// Two arrays that must have one element per instant have different lengths.
    LengthMismatch,
    /// `floor_ft` above `ceiling_ft`.
    FloorAboveCeiling,
    /// A form this reader does not take (MovingGeometryCollection, Step interpolation, a
    /// CRS other than WGS 84 longitude/latitude).
    Unsupported,
}

impl ErrorKind {
    /// The kind in a few words, the start of every message.
    pub fn describe(self) -> &'static str {
        match self {
            ErrorKind::Syntax => "not readable",
            ErrorKind::NotFinite => "not a finite number",
            ErrorKind::OutOfRange => "out of range",
            ErrorKind::TimesNotIncreasing => "times do not strictly increase",
            ErrorKind::VertexCountChanges => "the polygon's structure changes between instants",
            ErrorKind::UnknownMember => "unknown member",
            ErrorKind::DuplicateMember => "member given twice",
            ErrorKind::Missing => "missing",
            ErrorKind::WrongType => "wrong type",
            ErrorKind::BadTime => "not a date-time",
            ErrorKind::TooFewVertices => "too few vertices",
            ErrorKind::TooFewFixes => "too few fixes",
            ErrorKind::LengthMismatch => "lengths differ",
            ErrorKind::FloorAboveCeiling => "floor above ceiling",
            ErrorKind::Unsupported => "not supported",
        }
    }
}

/// An input problem that makes one feature (MF-JSON) or one row (CSV) unusable; the
/// reader goes on with the others.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingError {
    /// Where.
    pub at: Location,
    /// What kind.
    pub kind: ErrorKind,
    /// The particulars, in words (the value found, what was expected).
    pub detail: String,
}

impl MovingError {
    /// An error of `kind` at `at`.
    pub fn new(at: Location, kind: ErrorKind, detail: impl Into<String>) -> Self {
        MovingError {
            at,
            kind,
            detail: detail.into(),
        }
    }
}

impl fmt::Display for MovingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let at = self.at.to_string();
        if !at.is_empty() {
            write!(f, "{at}: ")?;
        }
        write!(f, "{}", self.kind.describe())?;
        if !self.detail.is_empty() {
            write!(f, ": {}", self.detail)?;
        }
        Ok(())
    }
}

impl std::error::Error for MovingError {}

/// What kind of remark a warning is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WarningKind {
    /// A member this format does not define, where RFC 7946 §6.1 permits foreign members
    /// (Feature, FeatureCollection, geometry): kept out of the model, named.
    ForeignMember,
    /// CSV columns this reader does not use.
    UnknownColumns,
    /// CSV rows without a position (ADS-B messages that carry none), skipped and counted.
    NoPosition,
    /// Date-times without a UTC offset, read as UTC.
    NoOffset,
    /// An altitude without a unit, read as feet.
    UnitAssumed,
}

/// A remark about the input that does not stop it being read.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingWarning {
    /// Where.
    pub at: Location,
    /// What kind.
    pub kind: WarningKind,
    /// The particulars, in words.
    pub detail: String,
}

impl MovingWarning {
    /// A warning of `kind` at `at`.
    pub fn new(at: Location, kind: WarningKind, detail: impl Into<String>) -> Self {
        MovingWarning {
            at,
            kind,
            detail: detail.into(),
        }
    }
}

impl fmt::Display for MovingWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let at = self.at.to_string();
        if !at.is_empty() {
            write!(f, "{at}: ")?;
        }
        f.write_str(&self.detail)
    }
}
