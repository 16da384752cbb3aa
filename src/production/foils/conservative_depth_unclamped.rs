//! `foil-conservative-depth-unclamped`: production's conservative
//! rasterization whose depth skips the format's clamp to [0, 1], as a
//! driver that stores the extrapolated plane value as it comes would.
//! **A foil**, wrong in that one way: where the plane at a drawn pixel's
//! centre, extrapolated past the triangle, lies beyond [0, 1], it writes
//! that value; everywhere else it writes what production writes. Caught
//! as a depth outside the interval SPEC.md §19.9 allows (the format
//! clamps, §18.1). Under `exact` depth, which has no clamp, it is
//! production.

use super::conservative_parts::capabilities;
use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::conservative;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::depth::DepthFormat;
use crate::scene::Scene;

foil!(
    /// Conservative rasterization whose depth is not clamped to [0, 1].
    ConservativeDepthUnclamped,
    "foil-conservative-depth-unclamped",
    // The conservative foils' triangles, with depth into an attachment of
    // the case's format (the clamp it skips is the format's).
    capabilities: Capabilities {
        depth: true,
        depth_attachment: true,
        ..capabilities()
    },
    conservative: conservative::support(),
    draw
);

/// Production's conservative frame, with the plane's unclamped value
/// written wherever it lies outside [0, 1].
fn draw(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let mut frame = conservative::rasterize(scene, plan)?;
    if scene.rules.depth_format == DepthFormat::Exact {
        return Ok(frame);
    }
    // The same scene with `exact` depth: the plane's values as they
    // come, before any format.
    let mut raw_scene = scene.clone();
    raw_scene.rules.depth_format = DepthFormat::Exact;
    let raw = conservative::rasterize(&raw_scene, plan)?;
    if let (Some(depth), Some(raw)) = (frame.depth.as_mut(), raw.depth.as_ref()) {
        for (i, z) in depth.iter_mut().enumerate() {
            if frame.last[i] > 0 && !(0.0..=1.0).contains(&raw[i]) {
                *z = f64::from(raw[i] as f32);
            }
        }
    }
    Ok(frame)
}
