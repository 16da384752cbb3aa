//! `adaptive-refine`: an inexact antialiasing method measured beside
//! production's, a pixel decided from a quarter of its samples.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::antialias::sampling::Sampling;
use crate::production::dispatch::{rasterize_with, Production};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

/// `adaptive-refine`: production's sampling, but deciding a pixel from a
/// quarter of its samples when they agree ([`Sampling::Refine`]). Measured,
/// not exact: it misses features thinner than the first samples' spacing.
#[derive(Clone, Copy, Debug, Default)]
pub struct AdaptiveRefine;

impl Rasterizer for AdaptiveRefine {
    fn name(&self) -> &str {
        "adaptive-refine"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            polygons: false,
            antialias: true,
            // Its static samples are inexact, and it has no time loop.
            motion_blur: false,
            // Clip-space scenes neither antialias nor reach its sampler.
            clip_space: false,
            points: false,
            ..Production.capabilities()
        }
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if scene.has_polygons() {
            return Err(RasterError::Unsupported(
                "adaptive-refine does not draw polygons".to_owned(),
            ));
        }
        rasterize_with(scene, plan, Sampling::Refine)
    }
}
