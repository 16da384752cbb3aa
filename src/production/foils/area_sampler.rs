//! `foil-area-sampler`: a pixel is drawn by a primitive that covers at
//! least half of its area, instead of by the primitive that covers its
//! centre. **A foil**, wrong in that one way: the area of each primitive in
//! each pixel is `area-f32`'s (signed-area accumulation in f32, as font and
//! vector rasterizers compute it). It is what a 2D antialiasing library
//! gives when its coverage is thresholded to draw aliased shapes, and what
//! `probe` must call an area sampler rather than invent a tie rule and
//! subpixel bits for: a thin sliver through a pixel centre is not drawn,
//! and a primitive covering a pixel's centre with little of its area is
//! not either.
//!
//! Single-sample scenes get a mask (each pixel's count and last primitive,
//! from the primitives covering half of it or more); antialiased scenes
//! get `area-f32`'s resolved coverage only, as an area method answers them.
//! Depth and attributes are unsupported, as for `area-f32`.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::antialias::area::{self, AreaF32};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

/// The area threshold foil.
#[derive(Clone, Copy, Debug, Default)]
pub struct AreaSampler;

/// The share of a pixel a primitive must cover to draw it.
pub const THRESHOLD: f64 = 0.5;

impl Rasterizer for AreaSampler {
    fn name(&self) -> &str {
        "foil-area-sampler"
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn capabilities(&self) -> Capabilities {
        AreaF32.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.antialias.is_some() {
            return AreaF32.rasterize(scene, plan);
        }
        if plan.interpolates() {
            return Err(RasterError::Unsupported(
                "foil-area-sampler computes coverage only, not depth or attributes".to_owned(),
            ));
        }
        let mut frame = Frame::new(scene.canvas.width, scene.canvas.height, false, 0);
        area::each_primitive(scene, |index, coverage| {
            for (p, &c) in coverage.iter().enumerate() {
                if c >= THRESHOLD {
                    frame.coverage[p] = frame.coverage[p].saturating_add(1);
                    frame.last[p] = index as u32 + 1;
                }
            }
        })?;
        Ok(frame)
    }
}
