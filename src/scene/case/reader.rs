//! The walk over one case file's JSON, under the run's limits: one type
//! whose methods `schema.rs`, `validate.rs`, `clip.rs`, `point.rs` and
//! `depth.rs` each add.

use std::cell::Cell;

use super::json::{Path, Result};
use super::limits::Limits;

/// The walk over one case file's JSON, under the run's limits.
pub(super) struct Reader<'a> {
    pub(super) limits: &'a Limits,
    /// Set when the walk stopped at a configurable limit of the run
    /// (`--max-canvas-pixels`, `--max-primitives`, `--max-samples`), not at
    /// bad input: the case is then `limit-exceeded` (SPEC.md §8).
    pub(super) over_limit: Cell<bool>,
}

impl<'a> Reader<'a> {
    pub(super) fn new(limits: &'a Limits) -> Reader<'a> {
        Reader {
            limits,
            over_limit: Cell::new(false),
        }
    }

    /// Stops the walk at a configurable limit of the run.
    pub(super) fn over<T>(&self, path: &Path, message: String) -> Result<T> {
        self.over_limit.set(true);
        Err((path.clone(), message))
    }
}
