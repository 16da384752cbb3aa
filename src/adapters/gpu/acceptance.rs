//! What a GPU API adapter draws, and the shared reasons it refuses a
//! scene: its capabilities, the subpixel bits it snaps to, and the
//! power-of-two target a canvas needs.

use super::channels::MAX_ATTRIBUTES;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError};
use crate::scene::{Line, Primitive, Scene};

/// What a GPU API adapter draws: triangles snapped to the case's grid,
/// with depth and attributes; antialiased scenes where its multisampling
/// is wired (`antialias`). No polygons, no motion.
#[cfg_attr(not(any(feature = "lavapipe", feature = "gl")), allow(dead_code))]
pub(crate) fn capabilities(antialias: bool) -> Capabilities {
    Capabilities {
        triangles: true,
        attributes: true,
        depth: true,
        antialias,
        ..Capabilities::none()
    }
}

/// The subpixel bits a GPU API adapter snaps the scene to, or why it cannot
/// draw the scene: a line the adapter refuses (`lines` says why, in the
/// adapter's words, or `None` for a line it draws), or more attributes
/// than the pipelines carry.
///
/// Unsnapped geometry (`subpixel_bits: null`) is snapped to the driver's
/// own `driver_bits`, ties to even (SPEC.md §2): the harness judges such
/// a case against the reference restated at the driver's bits (SPEC.md
/// §3.2), and those are exactly the vertices it is handed.
#[cfg_attr(not(any(feature = "lavapipe", feature = "gl")), allow(dead_code))]
pub(crate) fn snapping_bits(
    scene: &Scene,
    plan: &Plan,
    lines: impl Fn(&Line) -> Option<String>,
    driver_bits: u32,
) -> Result<u32, RasterError> {
    for primitive in &scene.primitives {
        if let Primitive::Line(line) = primitive {
            if let Some(why) = lines(line) {
                return Err(RasterError::Unsupported(format!("lines: {why}")));
            }
        }
    }
    let bits = scene.rules.subpixel_bits.unwrap_or(driver_bits);
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
