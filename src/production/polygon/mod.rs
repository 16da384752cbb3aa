//! Polygons in production (SPEC.md §14.1): scanline fill with an edge table
//! and an active edge table (`scanline.rs`), and the other polygon methods
//! measured beside it (`method.rs`): convex span fill (`convex.rs`),
//! ear-clipping into production's triangles (`tessellate.rs`), and the
//! outline-and-flood-fill foil (`flood.rs`).
//!
//! A polygon of a production scene: `draw.rs` (one fill per sample) takes
//! its contours from `contour.rs` (nudge, snapping) and fills them with
//! `scanline.rs`.
//!
//! What this does not do: interpolate (polygons carry positions only), or
//! fill under `all-edges`, which SPEC.md leaves undefined for polygons.

pub mod contour;
pub mod convex;
pub mod draw;
pub mod flood;
pub mod method;
pub mod scanline;
pub mod tessellate;

pub use draw::draw;
pub use method::methods;
