//! `foil-grid-samples`: production drawing every antialiased case with its
//! samples on a regular k × k grid (SPEC.md §14.2's `grid`), or, for a
//! count that is no square, at the `n-rooks` positions of seed 0, whatever
//! pattern the case states, while it **declares** the standard positions
//! (`fixed_sample_pattern`: Vulkan's `standardSampleLocations`). **A
//! foil** that lies about its sample positions: judged at the standard
//! positions it declares (SPEC.md §14.2.1), its masks differ wherever an
//! edge passes between a grid sample and the standard one. With one sample
//! both patterns are the centre, so it departs only from 2 samples up.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Pattern, Scene};

/// Samples on a grid, declaring the standard positions.
#[derive(Clone, Copy, Debug, Default)]
pub struct GridSamples;

impl Rasterizer for GridSamples {
    fn name(&self) -> &str {
        "foil-grid-samples"
    }
    fn is_foil(&self) -> bool {
        true
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities {
            motion_blur: false,
            ..Production.capabilities()
        }
    }
    fn rasterize(&self, scene: &Scene, _case_plan: &Plan) -> Result<Frame, RasterError> {
        let mut moved = scene.clone();
        if let Some(aa) = moved.effects.antialias.as_mut() {
            aa.pattern = if Pattern::Grid.check_count(aa.samples).is_ok() {
                Pattern::Grid
            } else {
                aa.seed = 0;
                Pattern::NRooks
            };
        }
        // The case's plan holds the case's offsets; the foil draws its own.
        Production.rasterize(&moved, &Plan::for_scene(&moved))
    }
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        Some(Pattern::Standard)
    }
}
