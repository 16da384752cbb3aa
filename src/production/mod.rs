//! The production rasterizer: fixed point, integer coverage decisions,
//! f32 interpolation. It imports the scene model and the output types, and
//! never the reference.
//!
//! A scene flows through the files in this order:
//!
//! 1. `dispatch.rs` ([`Production`]): a clip-space scene (SPEC.md §16) goes
//!    whole to `clip/`, whose `mod.rs` gives its own order; a conservative
//!    one (§19) whole to `conservative/`; a plan with
//!    motion goes to the time loop (`motion/`), which tests the moving
//!    primitives itself and draws the static ones from step 2 on.
//! 2. `placed.rs` (`draw_frame`): the fixed-point format (`fixed.rs`,
//!    `scene_format.rs`), every coordinate placed in it.
//! 3. A coverage-only scene of `midpoint` lines goes whole to
//!    `line/bands.rs`, coverage-only triangles to `sweep.rs`. Any other
//!    goes primitive by primitive, in scene order, through `primitive.rs`
//!    to its path:
//!    - a triangle: `triangle.rs`, then `setup.rs` (edge equations, tie
//!      bias, bounding box, interpolation set-up), then `traverse.rs` (8×8
//!      blocks, pixel centres) or `antialias/` (samples at the plan's
//!      offsets);
//!    - a line: `line/` (one file per rule; a parallelogram's two triangles
//!      go through `setup.rs` and `traverse.rs` or `antialias/` too);
//!    - a polygon: `polygon/` (scanline fill);
//!    - a point: `point.rs` (a rectangle of whole pixels, SPEC.md §17).
//! 4. An antialiased frame is resolved (`Frame::resolve`); depth is stored
//!    (`depth.rs`).
//!
//! The methods measured on their own (`method.rs`, listed by
//! `catalog.rs`) reuse that path: `tiled.rs` (bands drawn in parallel
//! through `primitive.rs`), `adaptive/` (`adaptive-refine`,
//! `adaptive-resolve`), `antialias/area.rs` (`area-f32`), `polygon/`'s other fills, `foils/`
//! (float DDA, float edge functions, and three that do not sample at the
//! centre: at (1, 1), by area, by any coverage) and `mutants.rs` (one
//! deliberate bug each).

pub mod adaptive;
pub mod antialias;
pub mod catalog;
pub mod clip;
pub mod conservative;
pub mod depth;
pub mod dispatch;
pub mod fixed;
pub mod foils;
pub mod line;
pub mod method;
pub mod motion;
pub mod mutants;
mod placed;
mod point;
pub mod polygon;
pub(crate) mod primitive;
pub(crate) mod scene_format;
pub mod setup;
mod sweep;
pub mod tiled;
pub mod traverse;
mod triangle;

pub use catalog::methods;
pub use dispatch::Production;
pub use method::Method;
