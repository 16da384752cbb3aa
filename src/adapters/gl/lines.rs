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
//! - it draws `rectangle` lines (GL's multisample line, corners snapped to
//!   its grid) only into multisampled targets, which this adapter does not
//!   use: refused;
//! - no GL mode draws the `midpoint` (Bresenham) rule: refused.

use crate::scene::{Line, LineRule};

/// Why the adapter does not draw `line`, or `None` where GL's lines are
/// the case's rule (`diamond-exit`, width 1).
pub(super) fn refusal(line: &Line) -> Option<String> {
    match line.rule {
        LineRule::DiamondExit => None,
        LineRule::Midpoint => Some("no GL mode draws the midpoint (Bresenham) rule".to_owned()),
        LineRule::Parallelogram => Some(
            "GL's wide aliased lines replicate the diamond-exit line's fragments over a \
             rounded width (GL 4.6 §14.5.2.1): their ends are not the parallelogram's"
                .to_owned(),
        ),
        LineRule::Rectangle => Some(
            "llvmpipe draws rectangular lines only into multisampled targets, which this \
             adapter does not draw into"
                .to_owned(),
        ),
    }
}
