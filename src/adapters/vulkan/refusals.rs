//! What a Vulkan device can draw of a scene, and why it refuses the rest:
//! line modes and widths, stencil, points, clip space, depth attachments,
//! the provoking vertex, attributes and conservative rasterization.

use super::device::{self, Offers};
use crate::adapters::float_input::f32_of;
use crate::adapters::gpu;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{DepthMode, LineRule, Primitive, Scene};

/// The subpixel bits the scene is snapped to (an unsnapped one to the
/// device's own), or why the device cannot draw it: too many attributes, a line rule or width
/// it has no mode for, a polygon without a stencil format.
pub(super) fn accepted(scene: &Scene, plan: &Plan, offers: &Offers) -> Result<u32, RasterError> {
    let unsupported = |why: String| Err(RasterError::Unsupported(why));
    for primitive in &scene.primitives {
        match primitive {
            Primitive::Line(line) => {
                if let Some(why) = line_refusal(line.rule, &line.width, offers) {
                    return unsupported(format!("{} line: {why}", line.rule.name()));
                }
            }
            Primitive::Polygon(_) if offers.stencil_format == ash::vk::Format::UNDEFINED => {
                return unsupported("polygons: the device has no stencil attachment format".into());
            }
            _ => {}
        }
    }
    let point_offers = gpu::points::PointOffers {
        large: offers.large_points,
        range: offers.point_size_range,
        granularity: offers.point_size_granularity,
        subpixel_bits: offers.subpixel_bits,
        pops: false,
    };
    for point in gpu::points::points(scene) {
        if let Some(why) = gpu::points::refusal(scene, point, &point_offers) {
            return unsupported(why);
        }
    }
    if let Err(why) = super::conservative::ask(scene, offers.conservative.as_ref()) {
        return unsupported(why);
    }
    if let Some(why) = clip_space_refusal(scene, offers) {
        return unsupported(why);
    }
    if let Some(why) = depth_refusal(scene, offers) {
        return unsupported(why);
    }
    if scene.needs_last_provoking_vertex() && !offers.provoking_last {
        return unsupported(
            "provoking_vertex: last on a flat primitive with attributes: the device has no \
             VK_EXT_provoking_vertex with provokingVertexLast"
                .into(),
        );
    }
    // Unsnapped geometry, and geometry at more bits than the device's, is
    // snapped to the device's own grid, ties to even: the case restated at
    // the device's bits (SPEC.md §3.2), which is what it is judged against.
    // Left to the device, an 8-bit vertex half a step off its 4-bit grid
    // would be rounded after the shift of a shifted pass, and ties to even
    // do not commute with a shift by an odd number of steps: SwiftShader
    // drew nothing of `antialias/probe_standard8`, whose squares are that.
    let bits = device_bits(scene.rules.subpixel_bits, offers.subpixel_bits);
    if plan.attributes > gpu::MAX_ATTRIBUTES {
        return unsupported(format!(
            "{} attributes (this adapter carries at most {})",
            plan.attributes,
            gpu::MAX_ATTRIBUTES
        ));
    }
    Ok(bits)
}

/// The bits a scene is snapped to before the device sees it: the case's,
/// at most the device's own (unsnapped: the device's).
fn device_bits(case: Option<u32>, device: u32) -> u32 {
    case.map_or(device, |bits| bits.min(device))
}

/// Why the device cannot draw a clip-space scene, if it cannot: the case's
/// numbers are not the device's (`gpu::clip_space_refusal`), depth clamp
/// without depth clip is not offered, or the viewport is outside the
/// device's bounds.
fn clip_space_refusal(scene: &Scene, offers: &Offers) -> Option<String> {
    let v = scene.viewport.as_ref()?;
    if let Some(why) = gpu::clip_space_refusal(scene, "the Vulkan device", offers.subpixel_bits) {
        return Some(why);
    }
    if scene.rules.clip.depth == DepthMode::Clamp && !offers.depth_clamp {
        return Some(
            "depth: clamp: the device lacks depthClamp or VK_EXT_depth_clip_enable \
             (depthClampEnable alone would still clip)"
                .into(),
        );
    }
    let [lo, hi] = offers.viewport_bounds;
    let [x, y, w, h] = [&v.x, &v.y, &v.width, &v.height].map(f32_of);
    let inside = x >= lo
        && y >= lo
        && x + w <= hi
        && y + h <= hi
        && w <= offers.max_viewport[0] as f32
        && h <= offers.max_viewport[1] as f32;
    (!inside).then(|| {
        format!(
            "viewport ({x}, {y}) {w}×{h}: the device's viewports lie in [{lo}, {hi}], \
             at most {}×{}",
            offers.max_viewport[0], offers.max_viewport[1]
        )
    })
}

/// Why the device cannot set up the depth attachment the scene needs
/// (`gpu::depth`), if it cannot: what `gpu::depth::target` refuses, a
/// format it cannot attach and copy out, a clamped offset without
/// `depthBiasClamp`.
fn depth_refusal(scene: &Scene, offers: &Offers) -> Option<String> {
    let target = match gpu::depth::target(scene, offers.depth_clamp, "the Vulkan device") {
        Ok(target) => target?,
        Err(why) => return Some(why),
    };
    let (_, i) = device::depth_attachment(target.format)?;
    if !offers.depth_formats[i] {
        let format = ["D16_UNORM", "X8_D24_UNORM_PACK32", "D32_SFLOAT"][i];
        return Some(format!(
            "depth_format {}: the device cannot attach {format} and copy it out",
            target.format.name()
        ));
    }
    if target.bias.is_some_and(|[_, _, clamp]| clamp != 0.0) && !offers.depth_bias_clamp {
        return Some("depth_bias.clamp: the device lacks depthBiasClamp".into());
    }
    None
}

/// Why the device has no line mode for this rule and width, if it has none.
fn line_refusal(rule: LineRule, width: &crate::scene::Number, offers: &Offers) -> Option<String> {
    let mode_missing = match rule {
        LineRule::Midpoint => {
            return Some("no Vulkan line mode draws the midpoint rule".to_owned());
        }
        LineRule::DiamondExit => (!offers.bresenham_lines)
            .then_some("the device offers no Bresenham (diamond-exit) lines"),
        LineRule::Rectangle => {
            (!offers.rectangular_lines).then_some("the device offers no rectangular lines")
        }
        LineRule::Parallelogram => offers.strict_lines.then_some(
            "the device has strictLines: its DEFAULT lines are rectangles, not parallelograms",
        ),
    };
    if let Some(why) = mode_missing {
        return Some(why.to_owned());
    }
    let w = f32_of(width);
    if w == 1.0 {
        return None;
    }
    let [lo, hi] = offers.line_width_range;
    let steps = (w - lo) / offers.line_width_granularity.max(f32::MIN_POSITIVE);
    let exact = dashu_ratio::RBig::try_from(w).is_ok_and(|back| &back == width.as_rbig());
    if !offers.wide_lines || w < lo || w > hi || steps.fract() != 0.0 || !exact {
        return Some(format!(
            "width {}: the device draws widths {lo} to {hi} in steps of {}{}",
            width.to_exact_string(),
            offers.line_width_granularity,
            if offers.wide_lines {
                ""
            } else {
                " (no wideLines)"
            }
        ));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::device_bits;

    #[test]
    fn a_scene_is_snapped_to_at_most_the_device_bits() {
        assert_eq!(device_bits(Some(8), 4), 4, "an 8-bit case on SwiftShader");
        assert_eq!(device_bits(Some(16), 8), 8, "a 16-bit case on lavapipe");
        assert_eq!(device_bits(Some(2), 8), 2, "a coarser case keeps its own");
        assert_eq!(device_bits(None, 4), 4, "unsnapped: the device's");
    }
}
