//! Motion blur in production (SPEC.md §15.3): every spatial sample of a
//! pixel tested at its N instants against each moving primitive, each test
//! decided exactly in fixed point.
//!
//! `sampler.rs` is the time loop (which samples and instants each moving
//! primitive is tested at, the static ones drawn once, the frame they add
//! up to); `mover.rs` a moving primitive set up for its tests; one test at
//! one instant is `exact.rs`'s, and the fast road for coarse triangles is
//! `fast.rs`.

mod exact;
mod fast;
mod mover;
pub mod sampler;

pub use sampler::{rasterize, Sampler};
