//! Lines: an incremental integer midpoint rasterizer, and wide lines.
//!
//! (Being written: see SPEC.md §4.)

use super::fixed::{EdgeInt, Fixed, Format};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Canvas, FillRule, Line};

/// Draws one line into the frame as primitive `index`.
#[allow(clippy::too_many_arguments)]
pub fn draw<E: EdgeInt>(
    line: &Line,
    ends: [[Fixed; 2]; 2],
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    plan: &Plan,
    index: usize,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let _ = (line, ends, format, rule, canvas, plan, index, frame);
    Err(RasterError::Unsupported(
        "lines are not drawn by the production rasterizer yet".to_owned(),
    ))
}
