//! `rastercheck merge`: reports read back and put together into one
//! (SPEC.md §10.3): shards of a run into the run, runs on other
//! rasterizers or machines beside it. The merged folder is then written by
//! the same writers a run uses (`report/write.rs`), from the same model.
//!
//! ```text
//! read.rs      a report.json (or its folder) into the model: Input
//!   lenient.rs   the model read as written (null where a number was not finite)
//! combine.rs   the inputs grouped into runs, shards interleaved, runs side by
//!              side; every disagreement an error naming its case: Merged
//! ```

pub mod combine;
pub mod lenient;
pub mod read;

pub use combine::{merge, Merged};
pub use read::{read_input, Input};
