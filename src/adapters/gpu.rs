//! What the GPU-API adapters (`lavapipe`, `gl`) share: the vertex stream
//! they upload, and the size of the target they draw into.
//!
//! Positions are snapped exactly to the case's grid, rounded once to f32,
//! and mapped to clip space over a power-of-two target, on which the
//! mapping and the viewport transform back are exact in f32:
//! `x_ndc = 2x/P − 1`, `y_ndc = 1 − 2y/Q` (y down on screen), sent as
//! `(x_ndc·w, y_ndc·w, w/2, w)` so the driver's perspective division sees
//! the vertex's w.

use super::float_input::{f32_of, snapped, to_f32};
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError};
use crate::scene::{Interpolation, Primitive, Scene};

/// Attributes a vertex can carry through the pipelines.
pub(crate) const MAX_ATTRIBUTES: usize = 16;
/// Channels written per sample: primitive + 1, depth, and the attributes.
pub(crate) const CHANNELS: usize = 2 + MAX_ATTRIBUTES;
/// Four-channel targets needed for every channel.
pub(crate) const GROUPS: usize = CHANNELS.div_ceil(4);
/// Floats per vertex: clip position (4), `[primitive + 1, depth, 0, 0]` (4),
/// attributes (16).
pub(crate) const VERTEX_FLOATS: usize = 8 + MAX_ATTRIBUTES;

/// What a GPU API adapter draws: triangles snapped to the case's grid,
/// with depth and attributes; antialiased scenes where its multisampling
/// is wired (`antialias`). No polygons, no motion.
pub(crate) fn capabilities(antialias: bool) -> Capabilities {
    Capabilities {
        ideal_geometry: false,
        polygons: false,
        antialias,
        motion_blur: false,
        ..Capabilities::everything()
    }
}

/// The subpixel bits a GPU API adapter snaps the scene to, or why it cannot
/// draw the scene: a line (`lines` says why, in the adapter's words),
/// unsnapped geometry (the `driver` snaps to 8 bits), or more attributes
/// than the pipelines carry.
pub(crate) fn snapping_bits(
    scene: &Scene,
    plan: &Plan,
    lines: &str,
    driver: &str,
) -> Result<u32, RasterError> {
    if scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Line(_)))
    {
        return Err(RasterError::Unsupported(format!("lines: {lines}")));
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

/// Every triangle's vertices as `VERTEX_FLOATS` floats each, and the runs of
/// consecutive vertices (first, end) whose triangles share an
/// interpolation mode, so each run is one draw call.
pub(crate) fn vertex_stream(
    scene: &Scene,
    bits: u32,
    target: (u32, u32),
) -> (Vec<f32>, Vec<(Interpolation, u32, u32)>) {
    let mut vertices: Vec<f32> = Vec::with_capacity(scene.primitives.len() * 3 * VERTEX_FLOATS);
    let mut runs: Vec<(Interpolation, u32, u32)> = Vec::new();
    let (sx, sy) = (2.0 / target.0 as f32, 2.0 / target.1 as f32);
    for (i, t) in scene.triangles() {
        for v in &t.vertices {
            let x = to_f32(&snapped(&v.x, Some(bits)));
            let y = to_f32(&snapped(&v.y, Some(bits)));
            let wv = f32_of(&v.w);
            let (xn, yn) = (x * sx - 1.0, 1.0 - y * sy);
            vertices.extend([xn * wv, yn * wv, 0.5 * wv, wv]);
            vertices.extend([(i + 1) as f32, f32_of(&v.z), 0.0, 0.0]);
            let mut attrs = [0f32; MAX_ATTRIBUTES];
            for (slot, a) in attrs.iter_mut().zip(&v.attributes) {
                *slot = f32_of(a);
            }
            vertices.extend(attrs);
        }
        let first = (vertices.len() / VERTEX_FLOATS) as u32 - 3;
        match runs.last_mut() {
            Some((mode, _, end)) if *mode == t.interpolation => *end = first + 3,
            _ => runs.push((t.interpolation, first, first + 3)),
        }
    }
    (vertices, runs)
}
