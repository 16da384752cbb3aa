//! One primitive drawn by its kind's path (`triangle.rs`, `line/`,
//! `polygon/`, `point.rs`), into the whole canvas or a band of its rows.

use super::antialias::sampling::Samples;
use super::fixed::{EdgeInt, Fixed, Format};
use super::{line, point, polygon, triangle};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Primitive, Scene};

/// Where a primitive is drawn: into a frame of `canvas`'s size holding the
/// scene's pixel rows from `rows_from` on (a band of the scene's canvas
/// for [`tiled`], all of it otherwise).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Target {
    pub canvas: crate::scene::Canvas,
    pub rows_from: i64,
}

/// Draws primitive `index`, whose vertices (a line's two ends first) are
/// `points` in `format`, into `frame` as `target` says. Moving the
/// vertices up by whole pixel rows moves every edge function's value with
/// them exactly, so a band draws the very samples of its rows that the
/// whole canvas would.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_primitive<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    samples: Option<&Samples>,
    offsets: Option<&[[i64; 2]]>,
    index: usize,
    points: [[Fixed; 2]; 3],
    target: Target,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let shift = target.rows_from * format.one();
    let points = points.map(|[x, y]| [x, Fixed(y.0 - shift)]);
    match &scene.primitives[index] {
        Primitive::Triangle(triangle) => {
            let sampled = samples.zip(offsets);
            triangle::draw::<E>(
                scene,
                plan,
                format,
                sampled,
                index,
                triangle,
                points,
                target.canvas,
                frame,
            );
        }
        Primitive::Line(line) => {
            line::draw::<E>(
                line,
                [points[0], points[1]],
                format,
                scene.rules.fill_rule,
                target.canvas,
                plan,
                samples,
                index,
                scene.rules.provoking_vertex,
                frame,
            )?;
        }
        Primitive::Polygon(polygon) => {
            assert_eq!(
                target.rows_from, 0,
                "polygons are drawn on the whole canvas"
            );
            polygon::draw::<E>(scene, plan, format, index, polygon, frame)?;
        }
        Primitive::Point(p) => point::draw(
            p,
            points[0],
            format,
            scene.rules.fill_rule,
            plan,
            target.canvas,
            index,
            frame,
        ),
    }
    Ok(())
}
