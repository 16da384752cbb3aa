//! Production's clip-space path (SPEC.md §16): a scene whose vertices are
//! homogeneous clip coordinates. A point is kept or discarded by its
//! centre (`point.rs`) and drawn as `../point.rs` draws one (§17.2); a
//! triangle flows through these files in order:
//!
//! 1. `draw.rs`: culling by the original triangle's D (§16.4),
//!    whatever its pieces;
//! 2. `clipper.rs`: Sutherland–Hodgman against the planes the rules clip
//!    before the divide, exact rationals, then the fan (§16.3);
//! 3. `project.rs`: each piece's vertices divided, put through the viewport
//!    and snapped (w > 0), or kept homogeneous (w ≤ 0) (§16.1, §16.4);
//! 4. `homogeneous.rs`: the piece's integer edge functions, their
//!    ownership under the fill rule, the samples to visit (§16.4);
//! 5. `shade.rs`: the per-sample depth test and the values written
//!    (§16.2, §16.5).
//!
//! Per-primitive set-up is exact (rationals and big integers); per-sample
//! work is integer dot products, in i128 when the coefficients fit
//! (`homogeneous.rs` states the bound) and in big integers otherwise. One
//! sample per pixel, at its centre: a clip-space case neither antialiases
//! nor moves (§16.1).

pub mod clipper;
pub mod draw;
mod homogeneous;
mod point;
pub(crate) mod project;
mod shade;

pub use draw::{rasterize, rasterize_with};
