//! The `vulkan` and `vulkan-passes` adapters: the [`Rasterizer`] over the
//! shared device, what each declares of the device's conventions, and how
//! a scene is handed to `draw.rs` (natively multisampled, by shifted
//! passes, or by time passes; see `docs/drivers/vulkan.md`).

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{ApiRecord, Capabilities, RasterError, Rasterizer, ScreenViewport};
use crate::scene::{
    ClipXy, ClipZ, ConservativeSupport, FillRule, InterpolateFrom, LineClamp, LineParameter,
    LineRule, LineT, PointBounds, PointClip, Scene,
};

use super::device::Offers;
use super::draw;
use super::native::{native_offered, native_samples};
use super::refusals::accepted;
use super::shared::{lock, shared, Shared};
use crate::adapters::gpu::{self, Placement, View};

/// The name on the command line and in reports.
pub const NAME: &str = "vulkan";

/// The name of the adapter that draws every sample pattern by shifted
/// passes, never natively: the same device, to compare the two.
pub const PASSES_NAME: &str = "vulkan-passes";

/// Any Vulkan driver, through ash.
pub struct Vulkan {
    /// Shifted passes even where the device multisamples the pattern.
    pub passes_only: bool,
    /// The whole name `vulkan@DEVICE` (or `vulkan-passes@DEVICE`) when a
    /// device was named: the device whose name contains DEVICE
    /// (case-insensitive). `None`: the default device.
    pub on: Option<&'static str>,
}

impl Vulkan {
    /// The device asked for: DEVICE of `vulkan@DEVICE`.
    fn wanted(&self) -> Option<&str> {
        self.on
            .and_then(|name| name.split_once('@'))
            .map(|(_, device)| device)
    }

    /// The shared device this adapter draws on.
    fn shared(&self) -> Result<&'static std::sync::Mutex<Shared>, &'static String> {
        shared(self.wanted())
    }
}

impl Rasterizer for Vulkan {
    fn name(&self) -> &str {
        match self.on {
            Some(name) => name,
            None if self.passes_only => PASSES_NAME,
            None => NAME,
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

    /// Vulkan's Bresenham lines, which draw `diamond-exit`, may depart from
    /// the diamond-exit rule within the latitude the spec allows
    /// ("Bresenham Line Segment Rasterization"): judged under it (SPEC.md
    /// §4.2.1).
    fn diamond_exit_latitude(&self) -> bool {
        true
    }

    /// Vulkan's formula for a line's t ("Basic Line Segment
    /// Rasterization", `primsrast-lines-basic`) has no clamp, so every
    /// line is unclamped (SPEC.md §5.1). RECTANGULAR lines "must" use
    /// that formula, the projection: declared for `rectangle` whatever
    /// the device, a device doing otherwise stays a departure. For
    /// Bresenham and DEFAULT lines the device's own
    /// ([`super::device::line_parameter`], by its driver). `None` where
    /// the device cannot be made (nothing is drawn then).
    fn fixed_line_parameter(&self, rule: LineRule) -> Option<LineT> {
        let shared = self.shared().ok()?;
        let own = lock(shared).device.offers.line_parameter;
        let parameter = match rule {
            LineRule::Rectangle => LineParameter::Projected,
            _ => own,
        };
        Some(LineT {
            parameter,
            clamp: LineClamp::Unclamped,
        })
    }

    /// Vulkan's RECTANGULAR lines give no tie rule: "Coverage bits that
    /// correspond to sample points that intersect the rectangle are 1,
    /// other coverage bits are 0" (`primsrast-lines-basic`), where
    /// DEFAULT (parallelogram) lines say "Samples that fall exactly on the
    /// edge of the parallelogram follow the polygon rasterization rules".
    /// A rectangle's border samples are judged off the ties (SPEC.md
    /// §4.3.1).
    fn rectangle_border_no_tie_rule(&self) -> bool {
        true
    }

    /// Vulkan lets the device choose. lavapipe clips against all six planes
    /// before the divide and snaps the new vertices (measured on scenes
    /// that separate the conventions, `tests/vulkan.rs`: 6 samples depart
    /// from per-sample near clipping, 3 from a guard band, none from clip
    /// then snap). Another device is judged under these and shows it.
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }

    /// The device's own ([`super::device::interpolate_from`], by its
    /// driver): lavapipe sets its planes up in floating point from the
    /// divided, unsnapped vertices, and snaps only the edges (SPEC.md
    /// §16.10: on the bundled clip-space cases its depth and attributes
    /// depart from the snapped positions' values by up to 1.3e-3, and from
    /// the unsnapped positions' by at most 2.3e-6); SwiftShader sets them
    /// up from its snapped fixed-point vertices. `None` where the device
    /// cannot be made (nothing is drawn then).
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        let shared = self.shared().ok()?;
        let from = lock(shared).device.offers.interpolate_from;
        Some(from)
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

    /// The device's `subPixelPrecisionBits` (SPEC.md §3.2): a case at more
    /// bits, or unsnapped, is judged at the device's. `None` where the
    /// device cannot be made (nothing is drawn then).
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        let shared = self.shared().ok()?;
        let bits = lock(shared).device.offers.subpixel_bits;
        Some(bits)
    }

    /// VK_EXT_conservative_rasterization where the device offers it, with
    /// its `primitiveOverestimationSize` as its uncertainty and its
    /// degenerate-primitive properties (`conservative.rs`); where it does
    /// not, both modes are claimed and each case is refused in
    /// [`Rasterizer::rasterize`] with the device's reason. `None` where
    /// the device cannot be made (nothing is drawn then).
    fn conservative(&self) -> Option<ConservativeSupport> {
        let shared = self.shared().ok()?;
        let support =
            super::conservative::support(lock(shared).device.offers.conservative.as_ref());
        Some(support)
    }

    /// [`Rasterizer::conservative`] for `scene`: its overestimation
    /// uncertainty is the device's base size plus the extra size the case
    /// asks for (SPEC.md §19.6, `conservative.rs`).
    fn conservative_for(&self, scene: &Scene) -> Option<ConservativeSupport> {
        let shared = self.shared().ok()?;
        let support = super::conservative::support_for(
            scene,
            lock(shared).device.offers.conservative.as_ref(),
        );
        Some(support)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let shared = self
            .shared()
            .map_err(|why| RasterError::Failed(format!("vulkan: {why}")))?;
        let mut shared = lock(shared);
        let Shared {
            device,
            pipelines,
            unpack,
        } = &mut *shared;
        let (bits, view) = placed(scene, plan, &device.offers)?;
        let centres = Placement::at_centres(bits, view);
        if let Some(n) = native_samples(scene, plan, &device.offers, self.passes_only) {
            let job = draw::Job {
                samples: n,
                ..draw::Job::per_placement(scene, &[centres], view)
            };
            let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
            return draw::slots(&bytes, scene, plan, &job);
        }
        if scene.is_conservative() && plan.antialias.is_some() {
            return Err(RasterError::Unsupported(
                "conservative and multisampled, not natively: each shifted single-sample pass \
                 would draw every pixel its shifted triangle touches, not the case's pixels with \
                 all their samples (SPEC.md §19.10)"
                    .to_owned(),
            ));
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
                    ..Placement::at_centres(bits, view)
                })
                .collect();
            let job = draw::Job::per_placement(scene, &placements, view);
            let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
            return draw::slots(&bytes, scene, plan, &job);
        };
        let canvas = (scene.canvas.width, scene.canvas.height);
        let time = gpu::time_draws(motion, canvas, bits, view, &shifts)
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
            view,
        };
        let bytes = draw::render(device, pipelines, unpack, scene, plan, &job)?;
        draw::time(&bytes, scene, shifts.len() as u32 * motion.blur.samples)
    }

    /// The viewport [`placed`] draws a screen-space scene through, where it
    /// cannot hold the scene's vertices: the device's largest viewport
    /// (`maxViewportDimensions`, `viewportBoundsRange`) is too small, and
    /// the driver, which has no guard band, clips there (SPEC.md §16.9).
    fn screen_viewport(&self, scene: &Scene, plan: &Plan) -> Option<ScreenViewport> {
        let shared = self.shared().ok()?;
        let shared = lock(shared);
        let (bits, view) = placed(scene, plan, &shared.device.offers).ok()?;
        gpu::clipped_at(scene, bits, &view)
    }

    /// What the instance's messenger heard of this process's calls
    /// (`messenger.rs`): every case's, of both adapters on the shared
    /// device.
    fn api_record(&self) -> Option<ApiRecord> {
        let shared = self.shared().ok()?;
        let record = lock(shared).device.api_record();
        Some(record)
    }

    /// The device, its driver and version, once the device is made, and
    /// how samples and instants are drawn.
    fn declared(&self) -> Option<String> {
        let shared = self.shared().ok()?;
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
        let conservative = match &offers.conservative {
            Some(c) => c.words(),
            None => format!("no {}", super::conservative::EXTENSION),
        };
        Some(format!(
            "{}; {sampling}; motion by time passes; {conservative}",
            shared.device.description
        ))
    }
}

/// The case's snapping bits (what the device draws of it, `refusals.rs`)
/// and the viewport its screen-space positions are placed on
/// (`gpu/view.rs`): what [`Vulkan::rasterize`] draws through and
/// [`Vulkan::screen_viewport`] reports.
fn placed(scene: &Scene, plan: &Plan, offers: &Offers) -> Result<(u32, View), RasterError> {
    let bits = accepted(scene, plan, offers)?;
    let target = gpu::target_size(scene, offers.max_side, "this Vulkan device")?;
    let limits = gpu::ViewLimits::vulkan(offers.max_viewport, offers.viewport_bounds);
    let fine = bits.max(offers.subpixel_bits);
    Ok((bits, gpu::screen_view(scene, bits, fine, target, &limits)))
}
