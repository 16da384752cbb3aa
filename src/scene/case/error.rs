//! The error a case that cannot be read gives: the file, the JSON path
//! of the offending value, and why.

use std::fmt;

/// A case that cannot be read: where, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaseError {
    /// The case file, as given to the loader.
    pub file: String,
    /// JSON path of the offending value (`$.primitives[2].triangle[0]`), or
    /// `line L column C` for a syntax error.
    pub location: String,
    pub message: String,
    /// The case is over a configurable limit of the run (`--max-…`), not
    /// bad: reported `limit-exceeded`, not unreadable (SPEC.md §8).
    pub over_limit: bool,
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.file, self.location, self.message)
    }
}

impl std::error::Error for CaseError {}
