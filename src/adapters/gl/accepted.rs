//! What Mesa's GL can draw of a scene, and why it refuses the rest: the
//! subpixel bits it snaps to and the depth attachment it needs.

use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

use super::context::{ask_for_softpipe, context};
use super::lines;
use crate::adapters::gpu;
use crate::adapters::gpu::depth::DepthTarget;

/// The subpixel bits Mesa's GL snaps the scene to and the depth
/// attachment it needs (`depth.rs`), or why it cannot draw it: several
/// samples per pixel, a line rule GL does not draw (`lines.rs`), too
/// many attributes, or a depth attachment
/// `gpu::depth::target` refuses. For `softpipe`, asks for it if no display
/// exists yet.
pub(super) fn accepted(
    scene: &Scene,
    plan: &Plan,
    softpipe: bool,
) -> Result<(u32, Option<DepthTarget>), RasterError> {
    if plan.antialias.is_none() && plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(format!(
            "{} samples per pixel without a sample pattern",
            plan.samples_per_pixel
        )));
    }
    let bits = gpu::snapping_bits(scene, plan, lines::refusal, super::passes::DRIVER_BITS)?;
    if let Some(why) = lines::scene_refusal(scene, plan) {
        return Err(RasterError::Unsupported(format!("lines: {why}")));
    }
    if softpipe {
        ask_for_softpipe();
    }
    if let Some(why) = point_refusal(scene) {
        return Err(RasterError::Unsupported(why));
    }
    // GL_DEPTH_CLAMP (core since 3.2) clamps depth without clipping it.
    let depth = gpu::depth::target(scene, true, "Mesa's GL").map_err(RasterError::Unsupported)?;
    Ok((bits, depth))
}

/// Why Mesa's GL cannot draw a point of the scene as the rule's square
/// (`gpu::points`), if it cannot: the context's point sizes, on llvmpipe's
/// grid of 8 subpixel bits.
fn point_refusal(scene: &Scene) -> Option<String> {
    let mut points = gpu::points::points(scene).peekable();
    points.peek()?;
    let gl = match context() {
        Ok(gl) => gl,
        Err(why) => return Some(format!("no context to ask for point sizes: {why}")),
    };
    let offers = {
        let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        gpu::points::PointOffers {
            large: true,
            range: gl.point_range,
            granularity: gl.point_granularity,
            subpixel_bits: 8,
            pops: true,
        }
    };
    points.find_map(|p| gpu::points::refusal(scene, p, &offers))
}
