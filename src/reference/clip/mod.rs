//! Clip space (SPEC.md §16): a point is kept or discarded by its centre
//! and drawn by `../point.rs` (§17.2); each triangle is culled by its winding,
//! clipped against the planes the case clips (`clipper.rs`), fanned, and
//! each piece rasterized by homogeneous edge functions (`homogeneous.rs`),
//! with the planes the case does not clip tested at each sample.
//!
//! Every step is exact: new vertices are rationals, snapping is the scene
//! model's, and every sample decision the sign of a big integer. Speed is
//! not the point; clip-space cases are small.
//!
//! `visit.rs` walks the scene in that order; `point.rs` places a point.
//! `window.rs` clips a screen-space contour at a viewport rectangle, for a
//! screen-space case restated under a driver's own clipping (§16.9).
//! The exact values at a covered sample are `../values.rs`'s.

pub mod clipper;
pub mod homogeneous;
pub mod point;
mod visit;
pub mod window;

pub use super::values::Values;
pub use visit::visit;
pub use window::{clip_to_window, Window};
