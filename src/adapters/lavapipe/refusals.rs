//! What lavapipe can draw through wgpu, and why it refuses the rest: no
//! points, Vulkan's standard 4× samples only, the first provoking vertex,
//! no line rule.

use crate::adapters::gpu;
use crate::plan::{Plan, SamplePlan};
use crate::rasterizer::{refuse_last_provoking, RasterError};
use crate::scene::Scene;

/// The subpixel bits lavapipe snaps to (`subPixelPrecisionBits`; wgpu does
/// not report it, and lavapipe's is 8).
pub const DRIVER_BITS: u32 = 8;

/// The subpixel bits the scene is snapped to (an unsnapped scene to
/// [`DRIVER_BITS`]), or why lavapipe cannot draw it: samples other than
/// Vulkan's standard 4×, a line or too many attributes.
pub(super) fn accepted(scene: &Scene, plan: &Plan) -> Result<u32, RasterError> {
    if scene.has_points() {
        return Err(RasterError::Unsupported(
            "the wgpu adapter draws no points (wgpu has only 1-pixel points, no size)".to_owned(),
        ));
    }
    if let Some(aa) = &plan.antialias {
        // Its 4 samples lie at the standard positions whatever the case
        // states, and it declares them (`fixed_sample_pattern`): a case at
        // other positions is judged at those (SPEC.md §14.2.1).
        if aa.offsets.len() != 4 {
            return Err(RasterError::Unsupported(format!(
                "{} samples per pixel: wgpu exposes 4x MSAA only, at Vulkan's standard positions",
                aa.offsets.len()
            )));
        }
    } else if plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(format!(
            "{} samples per pixel without a sample pattern",
            plan.samples_per_pixel
        )));
    }
    refuse_last_provoking(
        scene,
        "the wgpu adapter (wgpu has no choice of provoking vertex)",
    )?;
    gpu::snapping_bits(
        scene,
        plan,
        |_| {
            Some("wgpu draws only 1-pixel lines, with no choice of the case's line rule".to_owned())
        },
        DRIVER_BITS,
    )
}

/// Vulkan's standard 4× sample locations (`standardSampleLocations`), in
/// 1/16 pixel from the pixel's top-left corner, y down, in Vulkan's sample
/// order: sample index i of the driver is slot i of the frame.
pub const STANDARD_4X: [[u32; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];

/// Why these samples are not the ones lavapipe draws, if they are not:
/// wgpu asks the driver for 4× MSAA at its standard locations and nothing
/// else, so only offsets exactly [`STANDARD_4X`] at their position bits
/// are drawn as stated (the offsets are checked, not the pattern's name);
/// others of 4 samples are judged at these (the adapter declares them,
/// SPEC.md §14.2.1).
pub fn standard_4x_refusal(aa: &SamplePlan) -> Option<String> {
    let standard = aa.position_bits.checked_sub(4).map(|shift| {
        STANDARD_4X
            .iter()
            .map(|p| p.map(|c| c << shift))
            .collect::<Vec<_>>()
    });
    if standard.as_deref() == Some(aa.offsets.as_slice()) {
        return None;
    }
    Some(format!(
        "{} samples per pixel, not at Vulkan's standard 4x locations: \
         wgpu exposes 4x MSAA at the standard positions only",
        aa.offsets.len()
    ))
}
