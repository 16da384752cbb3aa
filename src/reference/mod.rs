//! The exact oracle.
//!
//! It imports the scene model and the output types, and nothing from the
//! production rasterizer: an oracle that shared code with what it judges
//! would inherit its bugs. Every coverage decision is the sign of an exact
//! integer; every interpolated value is an exact rational, rounded only when
//! it is written out.

pub mod exact;
pub mod triangle;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

pub use triangle::{coverage_under, mesh_interior};

/// The reference rasterizer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Reference;

impl Rasterizer for Reference {
    fn name(&self) -> &str {
        "reference"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Ok(triangle::render(scene, plan))
    }
}
