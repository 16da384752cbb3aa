//! The reference's frame of a scene in which something moves: each
//! pixel's certified time coverage rounded once.

use super::certified::Certified;
use super::coverage::time_coverage;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::reference::area::to_f64_nearest;
use crate::scene::Scene;

/// The reference's frame of a scene in which something moves: each
/// pixel's certified time coverage rounded to the nearest f64.
pub fn frame(scene: &Scene, plan: &Plan) -> Frame {
    frame_of(scene, &time_coverage(scene, plan))
}

/// The time-only frame of certified per-pixel values (one per pixel),
/// each rounded to the nearest f64: the one rounding of `frame` and of the
/// suite, which keeps the certified values for its checks. For values from
/// [`time_coverage`] this is the exact value's correctly rounded f64
/// wherever 1024-bit isolation decides it (SPEC.md §15.4).
pub fn frame_of(scene: &Scene, certified: &[Certified]) -> Frame {
    let time = certified.iter().map(|c| to_f64_nearest(&c.value)).collect();
    Frame::time_only(scene.canvas.width, scene.canvas.height, time)
}
