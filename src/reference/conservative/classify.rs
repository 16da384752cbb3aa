//! The classes of every pixel of a conservative scene, and the frame the
//! reference draws from them (its required pixels).

use super::classes::{ConservativeClasses, PixelClass};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// Each pixel's class for a conservative scene (SPEC.md §19), or why this
/// version does not judge it.
pub fn classify(scene: &Scene) -> Result<ConservativeClasses, RasterError> {
    if let Some(why) = scene.conservative_unjudged() {
        return Err(RasterError::Unsupported(why));
    }
    Err(RasterError::Unsupported(
        "the exact conservative reference is not built yet".to_owned(),
    ))
}

/// The reference's own frame of a conservative scene: its required pixels
/// drawn, each by the last primitive required there.
pub fn render(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let classes = classify(scene)?;
    Ok(frame_of(scene, plan, &classes))
}

/// The frame of `classes`: every required pixel drawn once, its flag true
/// where it must be (a frame that passes).
pub fn frame_of(scene: &Scene, plan: &Plan, classes: &ConservativeClasses) -> Frame {
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (i, class) in classes.drawn.iter().enumerate() {
        if *class == PixelClass::Required {
            frame.hit(i, 0);
        }
    }
    frame.fully_covered = classes.fully_covered.as_ref().map(|flags| {
        flags
            .iter()
            .zip(&classes.drawn)
            .map(|(f, d)| *f == PixelClass::Required && *d == PixelClass::Required)
            .collect()
    });
    frame
}
