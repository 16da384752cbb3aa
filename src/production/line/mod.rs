//! Lines (SPEC.md §4): a line's rule to the file that draws it. An
//! incremental integer midpoint rasterizer, the diamond-exit walk, the
//! parallelogram (non-strict wide) line through the triangle path, and the
//! rectangle line tested exactly sample by sample on tight row spans.
//!
//! Every coverage decision is an integer comparison in the production
//! fixed-point format, one bit finer than the snapping grid so that pixel
//! centres are integers. Floats appear only in interpolation and, for the
//! rectangle, in choosing which candidate samples to test (with a margin
//! far wider than their error; every candidate is then decided exactly).
//! Values along a line are interpolated in f32 from the line parameter of
//! SPEC.md §5, never from triangle barycentrics. Antialiased, a
//! parallelogram line's two triangles are sampled like any triangle's
//! (`antialias::cover`), and its values are taken at each sample.
//!
//! One file per rule, the stepping they share in one place, in the order a
//! line goes through them:
//!
//! - `mod.rs` (here): [`draw`], one line to its rule;
//! - `step.rs`: the fixed-point [`Geometry`], the major axis's pixel range,
//!   and the exact stepping of the minor coordinate;
//! - `midpoint.rs`, `diamond.rs`, `parallelogram.rs`, `rectangle.rs`: the
//!   four rules;
//! - `shading.rs`: values along the line, and the sink every rule writes
//!   into;
//! - `bands.rs`: a whole coverage-only scene of midpoint lines on a large
//!   canvas, band by band ([`midpoint_lines`], called by the scene's
//!   dispatcher before any line reaches [`draw`]).

mod bands;
mod diamond;
mod midpoint;
mod parallelogram;
mod rectangle;
mod shading;
mod step;
#[cfg(test)]
mod test_support;

pub(crate) use bands::midpoint_lines;
pub(crate) use midpoint::midpoint;
pub use rectangle::MAX_WIDTH_DENOMINATOR_BITS;
pub(crate) use shading::LineShading;
pub(crate) use step::{major_range, Geometry};

use diamond::diamond_exit;
use midpoint::midpoint_coverage;
use parallelogram::parallelogram;
use rectangle::rectangle;
use shading::LineSink;

use super::antialias::Samples;
use super::fixed::{EdgeInt, Fixed, Format};
use crate::frame::Frame;
use crate::plan::Plan;
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
