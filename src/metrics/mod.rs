//! Metrics: how a candidate's frame differs from the reference's, and the
//! verdict against a case's expectations.
//!
//! `measure.rs` measures a candidate with every metric that applies
//! (`coverage.rs`, `watertight.rs`, `line.rs`, `interpolation.rs` and
//! `depth.rs`, `latitude.rs` (diamond-exit lines under their API's latitude),
//! `antialias.rs` and `parts.rs` (an area method judged as one:
//! `area.rs`), `time.rs`, `ties.rs` (a candidate with no tie rule judged off
//! the ties); `conservative.rs` judges a conservative scene (SPEC.md §19)
//! against the reference's three classes, apart, and
//! `conservative_depth.rs` its depth (§19.9); the per-pixel ones
//! start from `difference.rs`, and antialiasing and time share
//! `error_bounds.rs`); `failures.rs` turns the metrics into the reasons a
//! candidate fails, counting in words with `counted.rs`.

pub mod antialias;
pub mod area;
pub mod conservative;
pub mod conservative_depth;
pub mod counted;
pub mod coverage;
pub mod depth;
pub(crate) mod difference;
pub mod error_bounds;
pub mod failures;
pub mod interpolation;
pub mod latitude;
pub mod line;
pub mod measure;
pub mod parts;
pub mod ties;
pub mod time;
pub mod watertight;

pub use antialias::{AntialiasMetrics, AreaClass};
pub use conservative::ConservativeMetrics;
pub use coverage::{CoverageMetrics, SampleDiff};
pub use failures::failures;
pub use interpolation::ChannelError;
pub use latitude::LatitudeMetrics;
pub use line::LineMetrics;
pub use measure::{
    measure, measure_known, measure_with_areas, Known, Metrics, DEFAULT_RELATIVE_BOUND,
};
pub use ties::TieMetrics;
pub use time::TimeMetrics;
pub use watertight::WatertightMetrics;
