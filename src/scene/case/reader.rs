//! The walk over one case file's JSON, under the run's limits: one type
//! whose methods `schema.rs`, `validate.rs`, `clip.rs`, `point.rs` and
//! `depth.rs` each add.

use super::limits::Limits;

/// The walk over one case file's JSON, under the run's limits.
pub(super) struct Reader<'a> {
    pub(super) limits: &'a Limits,
}
