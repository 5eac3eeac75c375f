//! What the oracle refuses: a case that breaks a rule of docs/cases.md (paper A's
//! premises, §II and §III: T > 0, BUFF > 0, 0 < F < 1, a polygon of at least three
//! vertices), named by its field.

use core::fmt;

/// A case that breaks a rule of docs/cases.md; `field` is the spec's field name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OracleError {
    /// The offending field, as the spec names it (e.g. "polygon.vertices").
    pub field: &'static str,
    /// What is wrong with it.
    pub message: String,
}

impl OracleError {
    pub(crate) fn new(field: &'static str, message: impl Into<String>) -> Self {
        OracleError {
            field,
            message: message.into(),
        }
    }
}

impl fmt::Display for OracleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.message)
    }
}

impl std::error::Error for OracleError {}
