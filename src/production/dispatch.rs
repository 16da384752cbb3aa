//! The production rasterizer and its dispatcher: a clip-space scene to
//! `clip/`, a moving one to the time loop (`motion/`), any other placed and
//! drawn once (`placed.rs`), then its depth stored.

use super::antialias::sampling::Sampling;
use super::placed::{draw_frame, Placed, PreparedFrame};
use super::{clip, conservative, depth, motion};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{ConservativeSupport, Scene};

/// The production rasterizer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Production;

impl Rasterizer for Production {
    fn name(&self) -> &str {
        "production"
    }

    fn capabilities(&self) -> Capabilities {
        // Ideal geometry only when its coordinates are dyadic: checked per scene.
        Capabilities {
            polygons: true,
            antialias: true,
            motion_blur: true,
            ..Capabilities::everything()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if scene.in_clip_space() {
            return clip::rasterize(scene, plan);
        }
        if scene.is_conservative() {
            return conservative::rasterize(scene, plan);
        }
        rasterize_with(scene, plan, Sampling::for_plan(plan))
    }

    fn conservative(&self) -> Option<ConservativeSupport> {
        Some(conservative::support())
    }

    /// Any scene without motion: placed once, drawn into one frame.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        if plan.motion.is_some()
            || scene.in_clip_space()
            || scene.depth_rules_need_attachment()
            || scene.is_conservative()
        {
            return None;
        }
        Some(
            Placed::new(scene, plan, Sampling::for_plan(plan), |_| true).map(|placed| {
                let frame = placed.empty_frame();
                Box::new(PreparedFrame { placed, frame }) as Box<dyn Prepared>
            }),
        )
    }
}

/// Production's rasterizer with the antialiased scenes' samples decided by
/// `sampling` (ignored without antialiasing). A plan with motion goes to
/// the time loop ([`motion`]).
pub(crate) fn rasterize_with(
    scene: &Scene,
    plan: &Plan,
    sampling: Sampling,
) -> Result<Frame, RasterError> {
    if plan.motion.is_some() {
        return motion::rasterize(scene, plan, sampling);
    }
    let mut frame = draw_frame(scene, plan, sampling, |_| true)?;
    depth::apply(scene, &mut frame);
    Ok(frame)
}
