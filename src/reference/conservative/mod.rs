//! Conservative rasterization, exact (SPEC.md §19): each pixel's class
//! (required, allowed, forbidden) for whether it is drawn and for its
//! fully-covered flag, decided in rationals.
//!
//! `classes.rs` holds the answer's types; `geometry.rs` the exact tests of
//! a pixel's square against a convex polygon; `outline.rs` each
//! primitive's closed shape on the grid (triangles, points, lines) and the
//! rectangle line's own tests; `classify.rs` the classes of a scene,
//! primitive by primitive, and the reference's frame from them;
//! `depth.rs` the depths a drawn pixel may hold (SPEC.md §19.9) and the
//! reference's frame with its depth.

mod classes;
mod classify;
mod depth;
mod geometry;
mod outline;

pub use classes::{ConservativeClasses, PixelClass};
pub use classify::{classify, classify_under, frame_of};
pub use depth::{depth_allowed, frame_with_depth, render, ConservativeDepth};
