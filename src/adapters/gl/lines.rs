//! Lines: which of the case's line rules Mesa's GL draws, and why it
//! draws no other.
//!
//! llvmpipe rasterizes a line itself (`lp_setup_line.c`, `try_setup_line`)
//! as a quad of four edge planes:
//!
//! - into a single-sample target (our case) it takes GL's aliased rule: a
//!   quad `round(width)` pixels tall (x-major; wide, y-major) whose ends
//!   are at the endpoints, moved by up to half a pixel where its float
//!   test of the diamond-exit rule (GL 4.6 §14.5.1) says the end pixel is
//!   drawn or not. Width 1 is GL's diamond-exit line, which the case's
//!   `diamond-exit` rule is, up to GL's own tie convention (endpoints
//!   perturbed by −(ε, ε²) in window coordinates, y up), which a case
//!   under D3D11's conventions reports as found;
//! - wider, it is GL's wide aliased line (§14.5.2.1): the diamond-exit
//!   line's fragments replicated in columns (rows) of the rounded width.
//!   Its ends follow diamond exit, not the vertical (horizontal) ends of
//!   the case's `parallelogram` rule, and its width is an integer, so
//!   `parallelogram` is refused;
//! - into a multisampled target (with `GL_MULTISAMPLE`, on by default) it
//!   draws every line as GL's multisample line (§14.5.4): a rectangle of
//!   the line's width centred on the segment, corners snapped to its grid.
//!   So `rectangle` lines are drawn into a multisampled target, the scene
//!   shifted onto one driver sample (`msaa.rs`); a scene that has them
//!   and `diamond-exit` lines too is refused (the target draws one or the
//!   other), as is a moving one (time passes are single-sample);
//! - no GL mode draws the `midpoint` (Bresenham) rule: refused.

use crate::plan::Plan;
use crate::scene::{Line, LineRule, Primitive, Scene};

/// Why the adapter does not draw `line`, or `None` where GL's lines are
/// the case's rule (`diamond-exit`, width 1; `rectangle`, in a
/// multisampled target).
pub(super) fn refusal(line: &Line) -> Option<String> {
    match line.rule {
        LineRule::DiamondExit | LineRule::Rectangle => None,
        LineRule::Midpoint => Some("no GL mode draws the midpoint (Bresenham) rule".to_owned()),
        LineRule::Parallelogram => Some(
            "GL's wide aliased lines replicate the diamond-exit line's fragments over a \
             rounded width (GL 4.6 §14.5.2.1): their ends are not the parallelogram's"
                .to_owned(),
        ),
    }
}

/// Why the adapter does not draw the scene's lines together, or `None`:
/// rectangle lines beside diamond-exit ones, or in a moving scene.
pub(super) fn scene_refusal(scene: &Scene, plan: &Plan) -> Option<String> {
    if !has_rectangles(scene) {
        return None;
    }
    let rule = |r| lines(scene).any(|l| l.rule == r);
    if rule(LineRule::DiamondExit) {
        return Some(
            "rectangle and diamond-exit lines in one scene: llvmpipe draws every line of a \
             multisampled target as a rectangle, and rectangles only there"
                .to_owned(),
        );
    }
    if plan.motion.is_some() {
        return Some(
            "rectangle lines in a moving scene: time passes draw single-sample targets, \
             where llvmpipe draws no rectangles"
                .to_owned(),
        );
    }
    None
}

fn lines(scene: &Scene) -> impl Iterator<Item = &Line> {
    scene.primitives.iter().filter_map(|p| match p {
        Primitive::Line(l) => Some(l),
        _ => None,
    })
}

/// Whether the scene has any line.
pub(super) fn has_lines(scene: &Scene) -> bool {
    lines(scene).next().is_some()
}

/// Whether the scene has a `rectangle` line.
pub(super) fn has_rectangles(scene: &Scene) -> bool {
    lines(scene).any(|l| l.rule == LineRule::Rectangle)
}
