//! Conservative rasterization in production (SPEC.md §19): the classic
//! integer method, each edge function moved out (overestimation) or in
//! (underestimation) by the square's half extent along its normal,
//! (|a| + |b|)·(½ + u) for a pixel grown by the uncertainty u, decided
//! exactly. It shares nothing with the reference's rational classes but
//! the scene model.
//!
//! `growth.rs` (the grown square's half side as an exact fraction, and the
//! one comparison made with it) → `triangle.rs` (one triangle's edges and
//! box, and the per-pixel tests), `lines.rs` (a point's square and a
//! line's band or rectangle, and theirs), `depth.rs` (the depth a drawn
//! pixel gets: the plane at its centre) → `draw.rs` (a scene to a frame,
//! and what production declares it draws).

mod depth;
mod draw;
mod growth;
mod lines;
mod triangle;

pub use draw::{rasterize, support};
