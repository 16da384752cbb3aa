//! Baselines: the accuracy metrics of a run, recorded per case and
//! rasterizer, so that a later run can be held to them. A rasterizer that is
//! not exact (an antialiasing method, a GPU driver, a float foil) may be
//! imperfect, but it must not get worse.
//!
//! A run's outcomes become entries (`observe.rs`, `entry.rs`), saved as a
//! `rastercheck-baseline/1` file (`file.rs`, which documents the format);
//! a later run is held to it within its tolerances (`tolerance.rs`) and
//! what moved is worded (`compare.rs`).

mod compare;
mod entry;
mod file;
mod observe;
mod tolerance;

pub use compare::{Change, Comparison, Finding};
pub use entry::{Entry, Value};
pub use file::{Baseline, SelectionInfo, Tool, SCHEMA};
pub use observe::{metrics_of, MetricParts, Observed};
pub use tolerance::{is_error_metric, Tolerance, Tolerances};

#[cfg(test)]
mod tests;
