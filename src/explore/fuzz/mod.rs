//! Counterexample search and shrinking: `rastercheck fuzz`.
//!
//! The fuzzer draws random and adversarial scenes from a seed, runs each
//! through the reference and a candidate rasterizer, and judges the
//! candidate with the same metrics and verdicts as `run`
//! ([`crate::metrics::failures`]). The first failure (or the first K) is shrunk to a
//! minimal scene that still fails the **same check** and written out as a
//! case file (SPEC.md §1) that `rastercheck run` reproduces.
//!
//! - **Generation** is deterministic from the seed: case `i` of seed `s`
//!   comes from its own [`Rng`] stream, so a case can be regenerated without
//!   the ones before it. Six families, taken in turn unless one is named:
//!   random triangles (tie-forcing half-pixel vertices, subpixel-grid and
//!   free rationals, vertices anywhere in the coordinate range, pairs sharing
//!   an edge), lines of every rule (strips, wide lines, both `last_pixel`s),
//!   and watertight meshes (fans around sample centres, jittered grids with
//!   shared vertices, convex fans and ear-clipped star polygons) with
//!   `expect.watertight: true`, polygons (one to three contours with
//!   repeated, collinear and doubled vertices, both fills), antialiased
//!   scenes (every pattern, 1 to 256 samples) and moving scenes (SPEC.md
//!   §15: translations, rotations, collapses through a point, vertices
//!   through sample centres, winding flips, double roots, vanishing τ²
//!   coefficients, under every time pattern and part of the shutter). No
//!   float function whose result may differ between machines is used (the
//!   sines are a fixed polynomial).
//! - **Failure kinds** ([`Kind`]): a candidate that breaks (error), holes and
//!   overdraw in a mesh, crowded midpoint-line steps, coverage, antialiased
//!   coverage, time coverage, and interpolation. A scene failing several
//!   checks is shrunk for the first in that order (or the one `--check`
//!   asks for).
//! - **Fair scenes only**: a scene the exact method with the case's own
//!   samples fails is no test of a candidate, and is skipped: the exact
//!   N-sample mask under antialiasing, and for a moving scene the sample
//!   method of §15.3 with the case's own instants, each test decided by the
//!   static reference (`sampled_time`), whose RMS can exceed the
//!   statistical bound where few pixels move.
//! - **Shrinking** is a greedy delta-debugging loop. Each pass proposes
//!   simpler scenes and keeps the first that still fails the same kind; the
//!   loop stops when a whole round of passes makes no progress (or after
//!   [`SHRINK_BUDGET`] evaluations). Passes: remove primitives (halves, then
//!   quarters, ... then one at a time); crop the canvas to the failing
//!   samples' neighbourhood and trim its sides, translating everything by
//!   whole pixels (a moving vertex's `from` and `to` together); drop depth,
//!   attributes, w, and non-default rules, line options and expectations
//!   that do not matter; fewer samples and time samples, the whole shutter,
//!   the simplest patterns and seeds; make moving vertices static; move
//!   vertices and the ends of their paths to simpler values (shared
//!   vertices together, then each on its own: integers near
//!   the canvas, coarser dyadic grids, halfway in from far away); simplify
//!   depth, w and attribute values; lower `subpixel_bits` when the snapping
//!   still matters. Every accepted step makes a well-founded measure
//!   smaller, so the loop ends; there is no randomness and no clock in it,
//!   so the same seed always writes the same file.
//! - **Mesh validity** is kept while shrinking: a scene that expects
//!   watertightness must stay a mesh (no zero-area triangle, and no sample
//!   covered twice under any of the four consistent fill rules), so a
//!   shrunk mesh case says what every correct rasterizer does.
//!
//! One file per stage, each using only the ones before it: `rng.rs`
//! (SplitMix64, machine-independent sines) → `geometry.rs` (exact points) →
//! `case_json.rs` (a scene as a case file, and whether it is one) →
//! `family/` (one generator per family) → `fair.rs` (moving scenes no
//! honest sampler passes) → `judge.rs` (evaluation and failure kinds) →
//! `shrink/` → `search.rs` (the loop `rastercheck fuzz` runs, and the files
//! it writes).

mod case_json;
mod fair;
mod family;
mod geometry;
mod judge;
mod rng;
mod search;
mod shrink;
pub mod targets;

pub use case_json::case_json;
pub use family::{
    ear_clip, ear_clip_star, generate, scene_from_tape, tape_of_case, winds_one_way, Family,
};
pub use judge::{evaluate, kinds_named, Failure, Kind, Outcome};
pub use rng::Rng;
pub use search::{clock_seed, default_out, from_tape, search, Found, Options, Summary};
pub use shrink::{shrink, Shrunk, SHRINK_BUDGET};
