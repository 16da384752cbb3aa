//! The exact oracle.
//!
//! It imports the scene model and the output types, and nothing from the
//! production rasterizer: an oracle that shared code with what it judges
//! would inherit its bugs. Every coverage decision is the sign of an exact
//! integer; every interpolated value is an exact rational, rounded only when
//! it is written out.
//!
//! Triangles (`triangle.rs`), lines (`line.rs`) and polygons (`polygon.rs`)
//! are visited at pixel centres on one integer grid (`grid.rs`); points
//! (`point.rs`) compare pixel centres with their square's exact sides; an
//! antialiased scene is visited once per sample, moved so that the sample
//! sits on the centre. Exact area coverage (`area.rs`) is computed only
//! when the plan antialiases.
//!
//! `visit.rs` is that traversal; `render.rs` writes the exact frame from
//! it, `coverage.rs` counts coverage under any rule and the mesh interior,
//! `ties.rs` the samples exactly on an edge (for a rasterizer with no tie rule),
//! `latitude.rs` each diamond-exit line's own fragments (for one that draws
//! them with its API's latitude);
//! `pieces.rs` writes the whole triangle's values at the samples its
//! pieces cover, for a case restated clipped at a driver's viewport;
//! `conservative/` classes every pixel of a conservative scene (SPEC.md §19):
//! required, allowed or forbidden;
//! `rasterizer.rs` is the reference behind the one trait.

pub mod area;
pub mod clip;
pub mod conservative;
pub mod coverage;
pub mod depth;
pub mod exact;
pub mod grid;
pub mod latitude;
pub mod line;
pub mod motion;
pub mod pieces;
pub mod point;
pub mod polygon;
pub mod rasterizer;
pub mod render;
pub mod ties;
pub mod triangle;
pub mod values;
mod visit;

pub use area::{exact_areas, primitive_area, primitive_pixel_areas};
pub use coverage::{coverage_under, mesh_interior};
pub use latitude::{diamond_lines, DiamondLine};
pub use pieces::take_whole_values;
pub use rasterizer::Reference;
pub use render::{depth_allowed, render, render_judged, render_with};
pub use ties::{tie_set, TieOutcome, TieSample, TieSet};
pub use visit::Arithmetic;
