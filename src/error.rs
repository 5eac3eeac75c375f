//! Typed errors for bad cases: every rule of docs/cases.md, each naming its field.

#[cfg(feature = "std")]
use core::fmt;

#[cfg(feature = "std")]
use std::string::String;

/// What is wrong with a detection case, and in which field (a path such as
/// `polygon.vertices[2][1]`, as in the case format of docs/cases.md).
#[cfg(feature = "std")]
#[derive(Clone, Debug, PartialEq)]
pub enum CaseError {
    /// The line is not JSON, or not a JSON object.
    Syntax {
        /// What the parser said, with the column.
        message: String,
    },
    /// A required field is absent.
    Missing {
        /// The field, as `polygon.vertices`.
        field: String,
    },
    /// A field has the wrong JSON type (a string where a number belongs, …).
    WrongType {
        /// The field.
        field: String,
        /// The type it must have.
        expected: &'static str,
    },
    /// NaN or ±∞ (or a number too large for an f64).
    NotFinite {
        /// The field, down to the coordinate (`polygon.vertices[2][1]`).
        field: String,
    },
    /// Fewer than 3 vertices.
    TooFewVertices {
        /// How many there are.
        found: usize,
    },
    /// A list of the wrong length (a point of 4 numbers, 3 velocities for 4 vertices…).
    WrongLength {
        /// The list.
        field: String,
        /// The length it must have.
        expected: usize,
        /// The length it has.
        found: usize,
        /// What the items are, for the message.
        what: &'static str,
    },
    /// A number that must be > 0 (lookahead T, buff BUFF) is not.
    NotPositive {
        /// The field.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A number outside its open range (fac F in (0, 1), κ in (0, π)).
    OutOfRange {
        /// The field.
        field: &'static str,
        /// Its value.
        value: f64,
        /// The range it must lie in, for the message.
        range: &'static str,
    },
    /// 2D and 3D mixed: z in the point without a slab in the polygon, or the reverse.
    DimensionMismatch {
        /// The field that has (or lacks) the third dimension.
        field: &'static str,
        /// What is missing where, for the message.
        detail: &'static str,
    },
    /// The slab's bottom lies above its top.
    SlabInverted {
        /// The slab's bottom.
        bottom: f64,
        /// The slab's top.
        top: f64,
    },
    /// The vertices run clockwise (negative signed area); the format wants counterclockwise.
    Clockwise {
        /// The ring's signed area (shoelace), negative.
        signed_area: f64,
    },
    /// Two edges of the ring meet although they are not neighbours (or neighbours fold
    /// back over each other): a polygon that crosses itself has no inside for paper A's
    /// containment test. Edges are named by their vertices' indices, from 0.
    SelfIntersecting {
        /// One edge, as (first vertex, second vertex).
        a: (usize, usize),
        /// The edge it meets.
        b: (usize, usize),
    },
    /// All vertices on one line: the polygon encloses nothing.
    ZeroArea,
    /// NaN, Infinity or -Infinity written where a number belongs (Python's `json`
    /// writes them; JSON has no such literal).
    NotJsonNumber {
        /// The field.
        field: String,
        /// The literal as written (`NaN`, `Infinity`, `-Infinity`).
        literal: String,
    },
    /// `point.pos` holds neither 2 nor 3 numbers.
    PointLength {
        /// How many numbers it holds.
        found: usize,
    },
    /// A key the format does not define (a typo must not be read as an absent field),
    /// with the nearest defined name when one is close.
    UnknownField {
        /// The key as written.
        field: String,
        /// The nearest defined name, when one is close.
        suggestion: Option<&'static str>,
    },
}

#[cfg(feature = "std")]
impl CaseError {
    /// The field the error is about, as a path into the case.
    pub fn field(&self) -> String {
        match self {
            CaseError::Syntax { .. } => String::from("line"),
            CaseError::Missing { field }
            | CaseError::WrongType { field, .. }
            | CaseError::NotFinite { field }
            | CaseError::WrongLength { field, .. }
            | CaseError::UnknownField { field, .. }
            | CaseError::NotJsonNumber { field, .. } => field.clone(),
            CaseError::TooFewVertices { .. }
            | CaseError::Clockwise { .. }
            | CaseError::SelfIntersecting { .. }
            | CaseError::ZeroArea => String::from("polygon.vertices"),
            CaseError::PointLength { .. } => String::from("point.pos"),
            CaseError::NotPositive { field, .. }
            | CaseError::OutOfRange { field, .. }
            | CaseError::DimensionMismatch { field, .. } => String::from(*field),
            CaseError::SlabInverted { .. } => String::from("polygon.top"),
        }
    }
}

#[cfg(feature = "std")]
impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.field())?;
        match self {
            CaseError::Syntax { message } => write!(f, "not a JSON object: {message}"),
            CaseError::Missing { .. } => write!(f, "missing"),
            CaseError::WrongType { expected, .. } => write!(f, "must be {expected}"),
            CaseError::NotFinite { .. } => write!(f, "not a finite number"),
            CaseError::TooFewVertices { found } => {
                let s = if *found == 1 { "point" } else { "points" };
                write!(f, "{found} {s}, at least 3 are needed")
            }
            CaseError::WrongLength {
                expected,
                found,
                what,
                ..
            } => {
                // "1 numbers (…)" reads badly: the singular for one
                let what = if *found == 1 {
                    what.replacen("numbers", "number", 1)
                        .replacen("velocities", "velocity", 1)
                        .replacen("points", "point", 1)
                } else {
                    String::from(*what)
                };
                write!(f, "{found} {what}, {expected} expected")
            }
            CaseError::NotPositive { value, .. } => write!(f, "{value} is not > 0"),
            CaseError::OutOfRange { value, range, .. } => write!(f, "{value} is outside {range}"),
            CaseError::DimensionMismatch { detail, .. } => write!(f, "2D and 3D mixed: {detail}"),
            CaseError::SlabInverted { bottom, top } => {
                write!(f, "top {top} is below bottom {bottom}")
            }
            CaseError::Clockwise { signed_area } => write!(
                f,
                "clockwise order (signed area {signed_area}); list the vertices counterclockwise"
            ),
            CaseError::SelfIntersecting { a, b } => write!(
                f,
                "edges {}–{} and {}–{} cross (vertices numbered from 0); \
                 the polygon must not intersect itself",
                a.0, a.1, b.0, b.1
            ),
            CaseError::ZeroArea => write!(
                f,
                "the vertices lie on one line; the polygon encloses nothing"
            ),
            CaseError::NotJsonNumber { literal, .. } => write!(
                f,
                "{literal} is not a JSON number; a case needs finite numbers"
            ),
            CaseError::PointLength { found } => {
                let s = if *found == 1 { "number" } else { "numbers" };
                write!(f, "{found} {s}, 2 (x, y) or 3 (x, y, z) expected")
            }
            CaseError::UnknownField { suggestion, .. } => {
                write!(f, "unknown field")?;
                match suggestion {
                    Some(s) => write!(f, "; did you mean {s}?"),
                    None => Ok(()),
                }
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for CaseError {}
