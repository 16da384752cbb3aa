//! Antialiasing in production (SPEC.md §14.2): supersampling at the plan's
//! offsets, adaptive sampling of edge pixels only, and the methods measured
//! beside it.
//!
//! A triangle's samples: `sampling.rs` (how they are decided), `cover.rs`
//! (which the triangle covers, pixels and blocks settled from their corners
//! when adaptive), `writer.rs` (into the frame). `area.rs` is `area-f32`, a
//! method measured on its own; `../adaptive/` holds the two built on this
//! sampling.

pub mod area;
pub mod cover;
pub mod sampling;
pub mod writer;

pub use cover::{cover, At, SampleSink, BLOCK};
pub use sampling::{Samples, Sampling};
pub use writer::write_triangle;

#[cfg(test)]
mod tests;
