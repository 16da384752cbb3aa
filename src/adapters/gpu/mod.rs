//! What the GPU-API adapters (`vulkan`, `lavapipe`, `gl`) share: the
//! vertex stream they upload (`stream.rs`), the shifts of shifted passes
//! (`passes.rs`), the draws of time passes (`time.rs`), a real depth
//! attachment's state and read-back (`depth.rs`), the WGSL of the two
//! Vulkan adapters (`wgsl.rs`), what a driver cannot be handed of a
//! clip-space scene (`clip.rs`), and the size of the target they draw into.
//!
//! Positions are snapped exactly to the case's grid, rounded once to f32,
//! and mapped to clip space over a power-of-two target, on which the
//! mapping and the viewport transform back are exact in f32:
//! `x_ndc = 2x/P − 1`, `y_ndc = 1 − 2y/Q` (y down on screen), sent as
//! `(x_ndc·w, y_ndc·w, w/2, w)` so the driver's perspective division sees
//! the vertex's w.

#[cfg(any(feature = "vulkan", feature = "gl"))]
mod clip;
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) mod depth;
mod passes;
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) mod points;
mod stream;
#[cfg(any(feature = "vulkan", feature = "gl"))]
mod time;
#[cfg(any(feature = "lavapipe", feature = "vulkan"))]
pub(crate) mod wgsl;

#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) use clip::clip_space_refusal;
#[cfg_attr(not(feature = "vulkan"), allow(unused_imports))]
pub(crate) use passes::shifts;
#[allow(unused_imports)] // `Run` is the gl adapter's
pub(crate) use stream::{Draw, Placement, Run, Stream, VERTEX_FLOATS};
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) use time::time_draws;

use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError};
use crate::scene::{Line, Primitive, Scene};

/// Attributes a vertex can carry through the pipelines.
pub(crate) const MAX_ATTRIBUTES: usize = 16;
/// Channels written per sample: primitive + 1, depth, and the attributes.
pub(crate) const CHANNELS: usize = 2 + MAX_ATTRIBUTES;
/// Four-channel targets needed for every channel.
pub(crate) const GROUPS: usize = CHANNELS.div_ceil(4);

/// What a GPU API adapter draws: triangles snapped to the case's grid,
/// with depth and attributes; antialiased scenes where its multisampling
/// is wired (`antialias`). No polygons, no motion.
#[cfg_attr(not(any(feature = "lavapipe", feature = "gl")), allow(dead_code))]
pub(crate) fn capabilities(antialias: bool) -> Capabilities {
    Capabilities {
        ideal_geometry: false,
        polygons: false,
        antialias,
        motion_blur: false,
        clip_space: false,
        depth_attachment: false,
        points: false,
        ..Capabilities::everything()
    }
}

/// The subpixel bits a GPU API adapter snaps the scene to, or why it cannot
/// draw the scene: a line the adapter refuses (`lines` says why, in the
/// adapter's words, or `None` for a line it draws), unsnapped geometry
/// (the `driver` snaps to 8 bits), or more attributes than the pipelines
/// carry.
#[cfg_attr(not(any(feature = "lavapipe", feature = "gl")), allow(dead_code))]
pub(crate) fn snapping_bits(
    scene: &Scene,
    plan: &Plan,
    lines: impl Fn(&Line) -> Option<String>,
    driver: &str,
) -> Result<u32, RasterError> {
    for primitive in &scene.primitives {
        if let Primitive::Line(line) = primitive {
            if let Some(why) = lines(line) {
                return Err(RasterError::Unsupported(format!("lines: {why}")));
            }
        }
    }
    let Some(bits) = scene.rules.subpixel_bits else {
        return Err(RasterError::Unsupported(format!(
            "unsnapped geometry (subpixel_bits: null): {driver} snaps to 8 subpixel bits"
        )));
    };
    if plan.attributes > MAX_ATTRIBUTES {
        return Err(RasterError::Unsupported(format!(
            "{} attributes (this adapter carries at most {MAX_ATTRIBUTES})",
            plan.attributes
        )));
    }
    Ok(bits)
}

/// The power-of-two target a canvas is drawn in, or why it cannot be.
pub(crate) fn target_size(
    scene: &Scene,
    max_side: u32,
    device: &str,
) -> Result<(u32, u32), RasterError> {
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let (tw, th) = (w.next_power_of_two(), h.next_power_of_two());
    if tw.max(th) > max_side {
        return Err(RasterError::Unsupported(format!(
            "canvas {w}×{h} needs a {tw}×{th} target; {device} draws at most {max_side}"
        )));
    }
    Ok((tw, th))
}

/// Four-channel targets the plan needs.
pub(crate) fn groups(plan: &Plan) -> usize {
    let groups = if plan.interpolates() {
        (2 + plan.attributes).div_ceil(4)
    } else {
        1
    };
    debug_assert!(groups <= GROUPS);
    groups
}
