//! The reference as a rasterizer: the one trait's face of [`render`].

use super::render::render;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{ConservativeSupport, Scene};

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
        if scene.is_conservative() {
            return super::conservative::render(scene, plan);
        }
        Ok(render(scene, plan))
    }

    fn conservative(&self) -> Option<ConservativeSupport> {
        Some(ConservativeSupport {
            overestimate: true,
            underestimate: true,
            fully_covered: true,
            depth: true,
            ..ConservativeSupport::default()
        })
    }
}
