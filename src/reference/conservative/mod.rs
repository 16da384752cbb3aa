//! Conservative rasterization, exact (SPEC.md §19): each pixel's class
//! (required, allowed, forbidden) for whether it is drawn and for its
//! fully-covered flag, decided in rationals.
//!
//! `classes.rs` holds the answer's types; `classify.rs` computes them for
//! a scene.

mod classes;
mod classify;

pub use classes::{ConservativeClasses, PixelClass};
pub use classify::{classify, frame_of, render};
