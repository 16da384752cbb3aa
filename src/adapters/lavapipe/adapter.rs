//! The `lavapipe` adapter: the [`Rasterizer`] over Mesa's lavapipe through
//! wgpu, drawing on the shared device (see `docs/drivers/lavapipe.md`).

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer, ScreenViewport};
use crate::scene::{ClipXy, ClipZ, FillRule, Pattern, Scene};

use super::prepared;
use super::refusals::{accepted, DRIVER_BITS};
use super::shared::{gpu, lock};
use crate::adapters::gpu;

/// The name on the command line and in reports.
pub const NAME: &str = "lavapipe";

/// Mesa's lavapipe, through wgpu's Vulkan backend.
pub struct Lavapipe;

impl Rasterizer for Lavapipe {
    fn name(&self) -> &str {
        NAME
    }

    fn capabilities(&self) -> Capabilities {
        gpu::capabilities(true)
    }

    /// Vulkan's, as the `vulkan` adapter says: the driver chooses, and
    /// lavapipe follows top-left.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        Some(FillRule::TopLeft)
    }

    /// lavapipe's 8 bits (SPEC.md §3.2): a case at more, or unsnapped, is
    /// judged at 8.
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        Some(DRIVER_BITS)
    }

    /// wgpu's 4× MSAA, at Vulkan's standard positions and no others
    /// (SPEC.md §14.2.1): a 4-sample case at other positions is judged at
    /// these.
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        Some(Pattern::Standard)
    }

    /// lavapipe's, as the `vulkan` adapter declares it (SPEC.md §16.10):
    /// no guard band at the side planes, the new vertices snapped. This
    /// adapter draws no clip-space case; what the declaration decides is a
    /// screen-space case past its viewport ([`Lavapipe::screen_viewport`]).
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }

    /// The target: wgpu sets no viewport beyond its render target, so a
    /// screen-space scene whose vertices reach past the target (rounded up
    /// to the device's sizes, `gpu::target_size`) is clipped there by the
    /// driver (SPEC.md §16.9).
    fn screen_viewport(&self, scene: &Scene, plan: &Plan) -> Option<ScreenViewport> {
        let bits = accepted(scene, plan).ok()?;
        let max_side = lock(gpu().ok()?).max_side;
        let target = gpu::target_size(scene, max_side, "the lavapipe adapter").ok()?;
        gpu::clipped_at(scene, bits, &gpu::View::target(target))
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let bits = accepted(scene, plan)?;
        let gpu = gpu().map_err(|why| RasterError::Failed(why.clone()))?;
        lock(gpu).render(scene, plan, bits)
    }

    /// Everything `rasterize` draws, set up once: see `prepared.rs`.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepared::prepare(scene, plan).map(|p| Box::new(p) as Box<dyn Prepared + 'a>))
    }
}
