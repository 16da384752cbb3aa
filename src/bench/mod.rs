//! `rastercheck bench`: time and error of each method, measured in one run on
//! the same seeded workloads, written as BENCH.md and a hand-drawn SVG chart.
//!
//! Timings are medians over interleaved repetitions (every method runs once
//! per round, so drift in the machine's speed hits all methods alike), and
//! the conclusions drawn from them are ratios between methods measured side
//! by side. Errors are counted against the exact reference.
//!
//! One file a stage, in the order a run crosses them: `output.rs` (where
//! it writes), `run.rs` (the run), `sizes.rs` (how big a run is), `workloads.rs` (the seeded scenes), `foils.rs` and `methods.rs`
//! (what is measured), `timing.rs` (medians, pools, the parallel ceiling),
//! `draw_call.rs` (a method's own draw call, timed apart from its adapter),
//! one file per workload family (`triangles.rs` with `declared.rs`,
//! `lines.rs`, `antialias.rs`, `conservative.rs`, `motion.rs` with
//! `translation.rs`), scored by
//! `score.rs`; `llvmpipe.rs` and `machine.rs` (the drivers and the machine),
//! `suite.rs` (the bundled cases through production), `targets.rs`
//! (judging), then the writers `markdown.rs` and `chart.rs`
//! (with `text.rs`), all from the result model in `model.rs`. Peak heap is
//! `memory.rs`'s counting allocator.

mod antialias;
mod chart;
mod conservative;
mod declared;
mod draw_call;
mod foils;
mod lines;
mod llvmpipe;
mod machine;
mod markdown;
pub mod memory;
mod methods;
mod model;
mod motion;
pub mod output;
mod run;
mod score;
mod sizes;
mod suite;
mod targets;
mod text;
mod timing;
mod translation;
mod triangles;
mod workloads;

pub use declared::{DECLARED, PAIRED};
pub use foils::{NaiveBbox, PlainMidpoint};
pub use llvmpipe::{lp_num_threads, DRIVERS, LLVMPIPE_COMMAND};
pub use methods::{triangle_methods, MOTION_BASELINE};
pub use model::{Measured, Report, Target, Workload};
pub use output::{check_out_path, prepare_report_path, report_path, QUICK_DIR};
pub use run::run;
pub use score::time_error;
pub use sizes::Options;
pub use timing::{OnPool, ParallelCeiling, TILED_THREADS};
pub use translation::translation_time_coverage;
pub use workloads::{line_scene, motion_scene, triangle_scene, SEED};
