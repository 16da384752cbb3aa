//! The bodies of the coverage-guided fuzz targets in `fuzz/` (cargo-fuzz,
//! libFuzzer). Each takes libFuzzer's bytes and panics on a finding; the
//! target files in `fuzz/fuzz_targets/` only call these, so that the same
//! code runs in unit tests, in `rastercheck fuzz --from-crash`, and under
//! any engine (libFuzzer, AFL++, OSS-Fuzz's).
//!
//! - [`case_json`] (`case_file.rs`): bytes into the case reader. No input
//!   panics; a case it accepts writes back and reads back as itself, and
//!   runs through the reference.
//! - [`scene_reference_vs_production`] (`scene.rs`): bytes as the tape of
//!   choices of `rastercheck fuzz`'s six families ([`super::scene_from_tape`]):
//!   ties, far coordinates, every rule, lines, polygons, antialiasing and
//!   motion, within SPEC.md's limits. Production must equal the reference
//!   exactly, and a mesh must stay watertight, under the same judge as
//!   `rastercheck fuzz` ([`super::evaluate`]).
//! - [`protocol_response`] (`response.rs`): bytes as an external
//!   rasterizer's answer (a JSON line, an EXR file, or a hello). An answer
//!   is read into a frame or refused with a reason, never a panic, and its
//!   memory is bounded by the canvas (libFuzzer's `-rss_limit_mb` and
//!   `-malloc_limit_mb` catch the rest).
//! - [`exact_arithmetic`] (`arithmetic.rs`): the reference's i128 fast
//!   paths against big integers and rationals, its roundings against
//!   their definitions, and production's fixed-point snapping (an i128
//!   path and a big-integer one) against the reference's.
//!
//! [`seeds`] writes each target's seed corpus: the bundled case files, the
//! tapes of generated cases, and answers built from real frames.
//!
//! `by_name.rs` lists the targets and runs one by name.

mod arithmetic;
mod by_name;
mod case_file;
mod response;
mod scene;
mod seeds;

pub use arithmetic::exact_arithmetic;
pub use by_name::{run, TARGETS};
pub use case_file::case_json;
pub use response::protocol_response;
pub use scene::{scene_reference_vs_production, FOUND_BY_SCENE_TARGET};
pub use seeds::{seeds, write_corpus};
