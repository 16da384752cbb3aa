//! Time passes: a moving scene drawn once for every time test of every
//! pixel (`gpu::time_draws`, as the `vulkan` adapter draws it).
//!
//! Each distinct (spatial sample, instant) is one placement of the scene:
//! every moving vertex at its exact position at that instant, the whole
//! scene shifted for the spatial sample as a shifted pass is
//! (`passes.rs`), static primitives included, so that they count at every
//! instant. Each test is one pass: its placement's stream drawn in the one
//! tile with the scissor on its pixel alone (window row `Q − 1 − y` for
//! canvas row y), every primitive covering the pixel's centre adding 1 to
//! the pixel's count. The count read back over the M·N tests is the
//! pixel's time coverage ([`Frame::time_only`](crate::frame::Frame::time_only)).
//!
//! The spatial shifts are the shifted passes' own, refused where those are
//! (offsets off llvmpipe's 1/256 grid, or `subpixel_bits` > 8 with
//! antialiasing). A vertex placed at an instant lies between the driver's
//! grid points in general, and llvmpipe snaps it, as it snaps any vertex
//! it is given: the time-coverage verdict's bound (SPEC §15.4) judges the
//! result.

use super::passes::{self, Layout, Pass, Reading};
use crate::adapters::gpu;
use crate::plan::{MotionPlan, Plan};
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// The time passes of a moving scene in one `tile`, or why they cannot be
/// drawn: shifts the driver's grid does not hold, or too many tests.
pub(super) fn layout(
    scene: &Scene,
    plan: &Plan,
    motion: &MotionPlan,
    bits: u32,
    (tile, view): ((u32, u32), gpu::View),
) -> Result<Layout, RasterError> {
    let shifts = passes::shifts(plan, bits)?;
    let canvas = (scene.canvas.width, scene.canvas.height);
    let tests = shifts.len() as u32 * motion.blur.samples;
    let time = gpu::time_draws(motion, canvas, bits, view, &shifts)
        .map_err(|why| RasterError::Unsupported(format!("time passes: {why}")))?;
    let mut layout = Layout::new(tile, Reading::Time { tests });
    for placement in &time.placements {
        layout.push(gpu::Stream::new(scene, placement));
    }
    layout.passes = time
        .draws
        .into_iter()
        .map(|(p, stream)| Pass {
            origin: (0, 0),
            stream,
            pixel: Some((p % canvas.0, p / canvas.0)),
        })
        .collect();
    Ok(layout)
}
