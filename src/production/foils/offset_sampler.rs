//! `foil-offset-sampler`: production with its sample at the pixel's
//! bottom-right corner, offset (1, 1), instead of its centre (½, ½).
//! **A foil**, wrong in that one way: every triangle, line and value is
//! production's, drawn as if the scene had moved half a pixel up and left
//! (pixel Q is drawn where Q + (1, 1) is covered, that is where
//! Q + ½ is covered once the scene moves by −½), so the whole raster is
//! shifted by half a pixel down and right. It is the point sampler whose
//! sample lies outside [0, 1)², which `probe` must find ("(1, 1) of the
//! pixel") rather than read as a wrong tie rule or precision.
//!
//! Vertices snap to the case's grid first and move after, so that snapping
//! is the case's; the moved scene is drawn unsnapped (its coordinates are
//! dyadic, production holds them exactly).

use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Scene};

foil!(
    /// The sample at (1, 1) of the pixel.
    OffsetSampler,
    "foil-offset-sampler",
    rasterize
);

/// The foil's sample offset from the pixel's top-left corner.
pub const SAMPLE: (i64, i64) = (1, 1);

fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    // Sampling pixel Q at Q + s is sampling Q + ½ of the scene moved by
    // ½ − s.
    let by = [SAMPLE.0, SAMPLE.1].map(|s| &Number::ratio(1, 2) - &Number::from_int(s));
    let mut moved = scene.clone();
    let bits = scene.rules.subpixel_bits;
    for v in moved.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        for (c, t) in [&mut v.x, &mut v.y].into_iter().zip(&by) {
            let snapped = bits.map_or_else(|| c.clone(), |b| c.snapped(b));
            *c = &snapped + t;
        }
    }
    moved.rules.subpixel_bits = None;
    Production.rasterize(&moved, plan)
}
