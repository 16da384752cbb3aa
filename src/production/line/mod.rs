//! Lines (SPEC.md §4): a line's rule to the file that draws it. An
//! incremental integer midpoint rasterizer, the diamond-exit walk, the
//! parallelogram (non-strict wide) line through the triangle path, and the
//! rectangle line tested exactly sample by sample on tight row spans.
//!
//! Every coverage decision is an integer comparison in the production
//! fixed-point format, one bit finer than the snapping grid so that pixel
//! centres are integers. Floats appear only in interpolation and, for the
//! rectangle, in choosing which candidate samples to test (with a margin
//! far wider than their error; every candidate is then decided exactly).
//! Values along a line are interpolated in f32 from the line parameter of
//! SPEC.md §5, never from triangle barycentrics. Antialiased, a
//! parallelogram line's two triangles are sampled like any triangle's
//! (`antialias::cover`), and its values are taken at each sample.
//!
//! One file per rule, the stepping they share in one place, in the order a
//! line goes through them:
//!
//! - `draw.rs`: [`draw`], one line to its rule;
//! - `step.rs`: the fixed-point [`Geometry`], the major axis's pixel range,
//!   and the exact stepping of the minor coordinate;
//! - `midpoint.rs`, `diamond.rs`, `parallelogram.rs`, `rectangle.rs`: the
//!   four rules;
//! - `shading.rs`: values along the line, and the sink every rule writes
//!   into;
//! - `bands.rs`: a whole coverage-only scene of midpoint lines on a large
//!   canvas, band by band ([`midpoint_lines`], called by the scene's
//!   placing (`../placed.rs`) before any line reaches [`draw`]).

mod bands;
mod diamond;
mod draw;
mod midpoint;
mod parallelogram;
mod rectangle;
mod shading;
mod step;
#[cfg(test)]
mod test_support;

pub(crate) use bands::midpoint_lines;
pub use draw::draw;
#[cfg(test)]
pub(crate) use midpoint::midpoint;
pub use rectangle::MAX_WIDTH_DENOMINATOR_BITS;
pub(crate) use shading::LineShading;
pub(crate) use step::{major_range, Geometry};
