//! `vulkan`: any installed Vulkan driver, through raw Vulkan (ash), not
//! wgpu's portable subset (cargo feature `vulkan`; system package
//! `libvulkan1` and a driver: `mesa-vulkan-drivers` for lavapipe, which is
//! what CI has; a GPU's own driver where one is installed).
//!
//! # Which device
//!
//! The one whose name contains `RASTERCHECK_VULKAN_DEVICE`
//! (case-insensitive) if that is set; else the first device that is not a
//! CPU; else the first (lavapipe, where Mesa is all there is). Reports
//! name it, with its driver and version ([`Rasterizer::declared`]).
//!
//! # What is drawn, and how it is read back
//!
//! As in the `lavapipe` (wgpu) adapter: every primitive in scene order,
//! with no depth test, into float targets of the canvas's power-of-two
//! size, in one render pass with one subpass:
//!
//! - **count** (`R32_SFLOAT`, additive blending): covers per sample;
//! - **channel groups** (`R32G32B32A32_SFLOAT`, no blending, so the last
//!   primitive in submission order wins): `[primitive + 1, depth,
//!   attribute 0, …]` four at a time, all of them in the same pass
//!   (multiple render targets);
//! - **stencil**, for polygons (below).
//!
//! Positions are the shared stream's (`gpu/stream.rs`): snapped to the
//! case's grid exactly and rounded once to f32, exact for 8 subpixel bits.
//! The device then snaps to its own `subPixelPrecisionBits`; a case at
//! more bits is snapped twice and shows it, and a case with
//! `subpixel_bits: null` is unsupported. Depth is the case's `z` as a
//! `noperspective` varying; attributes are varyings with the case's
//! interpolation; flat ones take the first vertex (Vulkan's default
//! provoking vertex), or the last with VK_EXT_provoking_vertex where the
//! case says `last` (a device without it refuses such cases).
//!
//! # Clip space (SPEC.md §16)
//!
//! A clip-space case's clip coordinates go to the device unchanged (y
//! negated in the stream, which naga's flip undoes), with the case's
//! viewport and depth range: the device clips, divides, applies the
//! viewport and snaps, and that is what is judged. Depth is the device's
//! fragment depth, clamped to the depth range. `depth: clamp` is
//! depthClampEnable with VK_EXT_depth_clip_enable's depthClipEnable off.
//! lavapipe clips then snaps on all six planes (`fixed_clip_rules`, SPEC
//! §16.10). Refused: what `gpu::clip_space_refusal` says, and a viewport
//! outside the device's bounds.
//!
//! # Depth formats and polygon offset (SPEC.md §18)
//!
//! A scene with a `depth_format` or a `depth_bias` is drawn with a real
//! depth attachment (`gpu/depth.rs`): `D16_UNORM`, `X8_D24_UNORM_PACK32`
//! or `D32_SFLOAT`, the depth test always passing with writes on (the last
//! primitive's depth stays, as its channels do), the offset as the
//! pipeline's depth bias (constant, slope and clamp factors, the clamp
//! needing `depthBiasClamp`). A screen-space scene's z is the position's z
//! under depth clamp without depth clip, so the device clamps to [0, 1]
//! after the offset and never clips. After each pass the attachment's
//! depth aspect is copied out and its stored integers (or f32s) decoded:
//! the frame's depth is the device's stored depth, judged on the format's
//! grid. An antialiased one is multisampled natively (below) only in
//! `unorm16` or `float32`, its depth loaded by the read-back pass as a
//! depth texture, sample by sample, and the stored value recovered from
//! the float (`gpu::depth::sampled_value`); `unorm24` cannot be recovered
//! from a float near 1 and goes by shifted passes, each copied out.
//!
//! # Rules
//!
//! - **Fill rule**: the device's own (top-left); a case under another rule
//!   reports the device's departures from it. **Culling**: front face
//!   counter-clockwise in framebuffer coordinates (y down, as the case's),
//!   `cull: ccw` culls front faces and `cull: cw` back faces.
//! - **Lines** (VK_EXT_line_rasterization / VK_KHR_line_rasterization):
//!   `diamond-exit` is `BRESENHAM` (Vulkan's Bresenham lines are the
//!   diamond-exit rule); `rectangle` is `RECTANGULAR`; `parallelogram` is
//!   `DEFAULT` on a device without `strictLines` (whose non-strict lines
//!   are parallelograms swept along the minor axis), unsupported on one
//!   with it. A width other than 1 needs `wideLines`, inside
//!   `lineWidthRange`, on a multiple of `lineWidthGranularity`. No mode
//!   draws `midpoint`: such cases are unsupported, and say so.
//! - **Polygons**: stencil then cover (`gpu/stream.rs` explains why the fan
//!   is exact under the device's tie rule), even-odd and nonzero.
//!
//! # Antialiasing: native MSAA, or shifted passes
//!
//! - **Native MSAA** where the plan's offsets are exactly the standard
//!   locations of a count the device multisamples (with
//!   `standardSampleLocations`, and `sampleRateShading` when depth or
//!   attributes are interpolated, at each sample), for scenes without
//!   lines (Vulkan draws multisampled lines as rectangles, whatever the
//!   rule): one pass into multisampled targets, read back sample by sample
//!   through a pass that spreads sample s of pixel (x, y) to texel
//!   (n·x + s, y) of a target n times wider (`unpack.rs`). Vulkan's sample
//!   index s is standard location s, which is the frame's slot s; a probe
//!   on each location checks it (`tests/vulkan.rs`).
//! - **Shifted passes** for every other pattern (`gpu/passes.rs`): one
//!   single-sample pass per sample slot, the scene shifted by the pixel
//!   centre minus the slot's offset, so that pass s's pixel centres decide
//!   slot s. Exact when every offset lies on the device's subpixel grid;
//!   unsupported otherwise, with that reason.
//!
//! `vulkan-passes` is the same adapter drawing every pattern by shifted
//! passes, so that the device's multisampling and its single-sample
//! rasterization can be compared on the same cases. The declared
//! description in reports says which counts are native.
//!
//! # Motion: time passes
//!
//! A moving scene is drawn once per time test of every pixel
//! (`gpu/time.rs`): the scene placed at the test's instant and shifted for
//! its spatial sample, scissored to that pixel, every test adding to the
//! pixel's count in one render pass. The count over M·N tests is the
//! pixel's time coverage. At most 2^20 tests a scene; more is
//! unsupported. A vertex placed at an instant lies between the device's
//! grid points in general, and the device snaps it, as it would for any
//! renderer drawing that instant: the time-coverage verdict's bound judges
//! the result.
//!
//! # The rooms
//!
//! - this file: the [`Rasterizer`] impl, what a device can draw and why it
//!   refuses the rest, and the shared device;
//! - `device.rs`: the loader, the instance, choosing and creating the
//!   device, what it offers;
//! - `shaders.rs`: WGSL compiled to SPIR-V by naga;
//! - `pipelines.rs`: render passes and pipelines (lines, stencil, cover);
//! - `draw.rs`: one scene's passes recorded, submitted, read back, decoded;
//! - `unpack.rs`: the pass that reads a multisampled target back sample by
//!   sample.

mod device;
mod draw;
mod pipelines;
mod shaders;
mod unpack;

use std::sync::{Mutex, MutexGuard, OnceLock};

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{
    Antialias, ClipXy, ClipZ, DepthMode, FillRule, InterpolateFrom, LineRule, Pattern, PointBounds,
    PointClip, Primitive, Scene,
};

use super::gpu::{self, Placement};
use device::{Device, Offers};
use pipelines::Pipelines;
use unpack::Unpack;

/// The name on the command line and in reports.
pub const NAME: &str = "vulkan";

/// The name of the adapter that draws every sample pattern by shifted
/// passes, never natively: the same device, to compare the two.
pub const PASSES_NAME: &str = "vulkan-passes";

/// Any Vulkan driver, through ash.
pub struct Vulkan {
    /// Shifted passes even where the device multisamples the pattern.
    pub passes_only: bool,
}

/// Whether the device multisamples `n` samples natively at the standard
/// locations, read back sample by sample.
fn native_offered(offers: &Offers, n: u32) -> bool {
    offers.standard_locations
        && offers
            .msaa_counts
            .contains(ash::vk::SampleCountFlags::from_raw(n))
}

/// The sample count to multisample the scene with natively, if any: its
/// offsets are exactly the standard locations of a count the device
/// offers (checked offset by offset, not by the pattern's name), it has no
/// lines (multisampled Vulkan lines are rectangles, whatever their rule),
/// per-sample interpolation is there if the plan interpolates, and the
/// read-back target (n times the canvas's width) fits.
fn native_samples(scene: &Scene, plan: &Plan, offers: &Offers, passes_only: bool) -> Option<u32> {
    let aa = plan.antialias.as_ref()?;
    let n = aa.offsets.len() as u32;
    let standard = Antialias {
        samples: n,
        pattern: Pattern::Standard,
        seed: 0,
        adaptive: false,
        position_bits: aa.position_bits,
    };
    let fits = u64::from(scene.canvas.width) * u64::from(n) <= u64::from(offers.max_side);
    let lines = scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Line(_)));
    (!passes_only
        && matches!(n, 2 | 4 | 8 | 16)
        && native_offered(offers, n)
        && standard.offsets() == aa.offsets
        && !lines
        && (offers.sample_rate_shading || !plan.interpolates())
        && plan.motion.is_none()
        && depth_natively(scene, offers, n)
        && fits)
        .then_some(n)
}

/// Whether the scene's depth attachment, if it needs one, can be drawn
/// with `n` samples and read back sample by sample: `unorm16` and
/// `float32`, read by a shader as floats from which the stored value is
/// recovered exactly (the integer nearest f·(2^16 − 1): the read is off by
/// far less than half a step; the f32 itself). Not `unorm24`, whose values
/// near 1 lie within an f32 ulp of each other: such a scene is drawn by
/// shifted passes, each copied out.
fn depth_natively(scene: &Scene, offers: &Offers, n: u32) -> bool {
    if !scene.depth_rules_need_attachment() {
        return true;
    }
    match device::depth_attachment(scene.rules.depth_format) {
        Some((_, i)) => {
            scene.rules.depth_format != crate::scene::DepthFormat::Unorm24
                && offers.depth_sampled[i]
                && offers
                    .depth_msaa_counts
                    .contains(ash::vk::SampleCountFlags::from_raw(n))
        }
        None => false,
    }
}

impl Rasterizer for Vulkan {
    fn name(&self) -> &str {
        if self.passes_only {
            PASSES_NAME
        } else {
            NAME
        }
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            ideal_geometry: false,
            ..Capabilities::everything()
        }
    }

    /// Vulkan lets the device choose; devices follow D3D's top-left rule
    /// (lavapipe and NVIDIA, measured). A device that does not is caught:
    /// its cases are judged under top-left.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        Some(FillRule::TopLeft)
    }

    /// Vulkan lets the device choose. lavapipe clips against all six planes
    /// before the divide and snaps the new vertices (measured on scenes
    /// that separate the conventions, `tests/vulkan.rs`: 6 samples depart
    /// from per-sample near clipping, 3 from a guard band, none from clip
    /// then snap). Another device is judged under these and shows it.
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }

    /// lavapipe sets its planes up in floating point from the divided,
    /// unsnapped vertices, and snaps only the edges (SPEC.md §16.10: on
    /// the bundled clip-space cases its depth and attributes depart from
    /// the snapped positions' values by up to 1.3e-3, and from the
    /// unsnapped positions' by at most 2.3e-6).
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        Some(InterpolateFrom::Unsnapped)
    }

    /// Vulkan lets the device choose. lavapipe pops no point: it draws one
    /// whose centre is outside the side planes (measured,
    /// `tests/vulkan.rs`), and limits its square to the viewport rectangle
    /// ([`Rasterizer::fixed_point_bounds`]).
    fn fixed_point_clip(&self) -> Option<PointClip> {
        Some(PointClip::GuardBand)
    }

    /// Mesa limits a point's square to the viewport rectangle (measured on
    /// the bundled point cases, SPEC.md §17.4).
    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        Some(PointBounds::Viewport)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let shared = shared().map_err(|why| RasterError::Failed(format!("vulkan: {why}")))?;
        let mut shared = lock(shared);
        let Shared {
            device,
            pipelines,
            unpack,
        } = &mut *shared;
        let bits = accepted(scene, plan, &device.offers)?;
        let target = gpu::target_size(scene, device.offers.max_side, "this Vulkan device")?;
        let centres = Placement::at_centres(bits, target);
        if let Some(n) = native_samples(scene, plan, &device.offers, self.passes_only) {
            let job = draw::Job {
                samples: n,
                ..draw::Job::per_placement(scene, &[centres])
            };
            let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
            return draw::slots(&bytes, scene, plan, &job);
        }
        let shifts = match &plan.antialias {
            Some(aa) => gpu::shifts(aa, device.offers.subpixel_bits)
                .map_err(|why| RasterError::Unsupported(format!("shifted passes: {why}")))?,
            None => vec![centres.shift.clone()],
        };
        let Some(motion) = &plan.motion else {
            let placements: Vec<Placement> = shifts
                .into_iter()
                .map(|shift| Placement {
                    shift,
                    ..Placement::at_centres(bits, target)
                })
                .collect();
            let job = draw::Job::per_placement(scene, &placements);
            let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
            return draw::slots(&bytes, scene, plan, &job);
        };
        let canvas = (scene.canvas.width, scene.canvas.height);
        let time = gpu::time_draws(motion, canvas, bits, target, &shifts)
            .map_err(|why| RasterError::Unsupported(format!("time passes: {why}")))?;
        let job = draw::Job {
            streams: time
                .placements
                .iter()
                .map(|p| {
                    crate::deadline::check();
                    gpu::Stream::new(scene, p)
                })
                .collect(),
            passes: vec![time
                .draws
                .iter()
                .map(|&(p, stream)| (draw::rect(p % canvas.0, p / canvas.0, 1, 1), stream))
                .collect()],
            samples: 1,
        };
        let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
        draw::time(&bytes, scene, shifts.len() as u32 * motion.blur.samples)
    }

    /// The device, its driver and version, once the device is made, and
    /// how samples and instants are drawn.
    fn declared(&self) -> Option<String> {
        let shared = shared().ok()?;
        let shared = lock(shared);
        let offers = &shared.device.offers;
        let sampling = if self.passes_only {
            "antialiasing by shifted passes only".to_owned()
        } else {
            let counts: Vec<String> = [2u32, 4, 8, 16]
                .into_iter()
                .filter(|&n| native_offered(offers, n))
                .map(|n| format!("{n}x"))
                .collect();
            format!(
                "antialiasing by native MSAA at the standard locations ({}), \
                 by shifted passes otherwise",
                if counts.is_empty() {
                    "none offered".to_owned()
                } else {
                    counts.join(", ")
                }
            )
        };
        Some(format!(
            "{}; {sampling}; motion by time passes",
            shared.device.description
        ))
    }
}

/// The device's description, or why there is none. Creates the shared
/// device on first use.
pub fn device_description() -> Result<String, String> {
    Ok(lock(shared()?).device.description.clone())
}

/// The subpixel bits the scene is snapped to, or why the device cannot
/// draw it: unsnapped geometry, too many attributes, a line rule or width
/// it has no mode for, a polygon without a stencil format.
fn accepted(scene: &Scene, plan: &Plan, offers: &Offers) -> Result<u32, RasterError> {
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
    let Some(bits) = scene.rules.subpixel_bits else {
        return unsupported(format!(
            "unsnapped geometry (subpixel_bits: null): the device snaps to {} subpixel bits",
            offers.subpixel_bits
        ));
    };
    if plan.attributes > gpu::MAX_ATTRIBUTES {
        return unsupported(format!(
            "{} attributes (this adapter carries at most {})",
            plan.attributes,
            gpu::MAX_ATTRIBUTES
        ));
    }
    Ok(bits)
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
    let [x, y, w, h] = [&v.x, &v.y, &v.width, &v.height].map(super::float_input::f32_of);
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
    let w = super::float_input::f32_of(width);
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

/// The device and its kept pipelines, made once and shared by every case.
struct Shared {
    // Dropped in this order: the pipelines before their device.
    pipelines: Pipelines,
    unpack: Unpack,
    device: Device,
}

fn shared() -> Result<&'static Mutex<Shared>, &'static String> {
    static SHARED: OnceLock<Result<Mutex<Shared>, String>> = OnceLock::new();
    SHARED
        .get_or_init(|| {
            let device = Device::new()?;
            if !device.blends(pipelines::COUNT_FORMAT) {
                return Err(format!(
                    "{}: R32_SFLOAT does not blend, and the coverage count needs it",
                    device.description
                ));
            }
            let pipelines = Pipelines::new(&device)?;
            let unpack = Unpack::new(&device.device)?;
            Ok(Mutex::new(Shared {
                pipelines,
                unpack,
                device,
            }))
        })
        .as_ref()
}

/// The shared device, for one case at a time; a case that panicked
/// holding it leaves it usable.
fn lock(shared: &'static Mutex<Shared>) -> MutexGuard<'static, Shared> {
    shared
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}
