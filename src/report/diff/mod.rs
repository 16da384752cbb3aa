//! `rastercheck diff OLD NEW`: what changed between two runs, from their
//! `report.json` files (SPEC.md §10.2). The model here is `diff.json`
//! (schema `rastercheck-diff/1`); `diff.md` and `diff.html` are written
//! from it (`render.rs`), so they cannot disagree.
//!
//! `read.rs` reads one report; `pair.rs` pairs the rasterizers;
//! [`compare`] (`compare.rs`) pairs the cases, classifies each result that
//! changed (`class.rs`), and measures each metric's move, into the model
//! (`model.rs`) that `render.rs` writes.

pub mod class;
pub mod compare;
pub mod model;
pub mod pair;
pub mod read;
pub mod render;

pub use class::{kind, Class, Kind};
pub use compare::compare;
pub use model::{CaseOnly, Change, Counts, Diff, MetricDelta, Pair, SideInfo, SCHEMA};
pub use pair::pair;
pub use read::{read, Side};
