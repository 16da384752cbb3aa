//! One line to the file of its rule: a coverage-only midpoint line to its
//! counting walk, any other through the sink that shades it.

use super::diamond::diamond_exit;
use super::midpoint::{midpoint, midpoint_coverage};
use super::parallelogram::parallelogram;
use super::rectangle::rectangle;
use super::shading::{LineShading, LineSink};
use super::step::Geometry;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::antialias::sampling::Samples;
use crate::production::fixed::{EdgeInt, Fixed, Format};
use crate::rasterizer::RasterError;
use crate::scene::{Canvas, FillRule, Line, LineRule, ProvokingVertex};

/// Draws one line into the frame as primitive `index`.
///
/// `E` is production's integer for the case's format; lines choose their own
/// (the midpoint walk steps in i64 at every format, a parallelogram may be
/// drawn in a finer format than the case's).
#[allow(clippy::too_many_arguments, clippy::extra_unused_type_parameters)]
pub fn draw<E: EdgeInt>(
    line: &Line,
    ends: [[Fixed; 2]; 2],
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    plan: &Plan,
    samples: Option<&Samples>,
    index: usize,
    provoking: ProvokingVertex,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    if samples.is_some() && line.rule != LineRule::Parallelogram {
        // SPEC.md §14.2: the case reader refuses these.
        return Err(RasterError::Unsupported(format!(
            "a {} line has no samples to antialias",
            line.rule.name()
        )));
    }
    let g = Geometry::new(ends);
    if g.is_point() {
        return Ok(());
    }
    let shading = plan
        .interpolates()
        .then(|| LineShading::new(line, &g, plan, provoking.index(2)));
    if line.rule == LineRule::Midpoint && shading.is_none() {
        midpoint_coverage(&g, format, line.last_pixel, canvas, index, frame);
        return Ok(());
    }
    let mut sink = LineSink {
        frame,
        index,
        shading: shading.as_ref(),
        format,
        offsets: samples.map(|s| s.offsets_in(format)).unwrap_or_default(),
        samples,
    };
    match line.rule {
        LineRule::Midpoint => {
            midpoint(&g, format, line.last_pixel, canvas, |x, y| sink.pixel(x, y));
            Ok(())
        }
        LineRule::DiamondExit => {
            diamond_exit(&g, format, canvas, |x, y| sink.pixel(x, y));
            Ok(())
        }
        LineRule::Parallelogram => parallelogram(line, &g, format, rule, canvas, &mut sink),
        LineRule::Rectangle => rectangle(line, &g, format, rule, canvas, &mut sink),
    }
}
