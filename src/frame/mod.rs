//! What every rasterizer returns: per-sample coverage counts, the primitive
//! that wrote each sample last, and the interpolated depth and attributes;
//! for antialiased scenes, also a resolved coverage per pixel; for scenes in
//! which something moves, only a time coverage per pixel (SPEC.md §15).
//!
//! Without antialiasing there is one sample per pixel, at its centre. With
//! it, each pixel holds a run of `samples` slots, sample s of pixel p at
//! `p · samples + s`, in the order of the plan's offsets. Values are stored
//! as f64 so that one type holds both a candidate's f32 output (widened
//! exactly) and the reference's exact values (rounded to odd, see
//! `reference::exact`).
//!
//! `exr.rs` stores a frame as EXR channels (golden files, external answers).
//!
//! `model.rs` holds [`Frame`]; `parts.rs` an area method's coverage per
//! primitive; `sample_tests.rs` a time loop's cost; `cover.rs` the run
//! filling the rasterizers' spans go through.

mod cover;
pub mod exr;
mod model;
mod parts;
mod sample_tests;

pub use cover::cover_run;
pub use model::Frame;
pub use parts::Parts;
pub use sample_tests::SampleTests;
