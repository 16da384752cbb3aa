//! Property tests: the production rasterizer against the exact reference,
//! and the reference's i128 fast path against its big-integer path, on
//! random triangles over the whole supported range; polygons and
//! antialiasing; and time coverage under motion blur.
//!
//! Case counts: proptest's default (256; 96 for the polygon and antialiasing
//! properties, whose exact areas cost more; 64 for motion blur's certified
//! oracle), or `PROPTEST_CASES` for long runs, which sets every property's
//! count (`PROPTEST_CASES=25600 cargo test --release --test properties`:
//! 100× the default and more). Failures
//! are shrunk to a minimal scene and saved where proptest's default
//! `SourceParallel` puts them for a test target with a `main.rs`:
//! `tests/proptest-regressions/<module>.txt` (committed), one file per module
//! here, replayed by that module's properties.

mod antialias;
mod invariance;
mod line_bands;
mod meshes;
mod motion;
mod range;
mod reader;
mod strategies;
mod triangles_lines;
mod vertex_values;

use proptest::prelude::*;

/// `PROPTEST_CASES` when set (long runs), else `default`: the exact areas
/// of polygons cost more than a triangle's frame, so these properties run
/// fewer cases by default.
fn config(default: u32) -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    ProptestConfig {
        cases,
        ..ProptestConfig::default()
    }
}
