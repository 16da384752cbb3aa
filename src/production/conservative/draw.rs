//! A conservative scene drawn (SPEC.md §19): every triangle placed in
//! fixed point as production places any, set up (`triangle.rs`), and each
//! pixel of its box tested. Overestimation draws every pixel whose square,
//! grown by the case's uncertainty, meets the triangle: the most the case
//! allows. Underestimation draws every pixel whose square, so grown, lies
//! inside it: the least the case requires. The fully-covered flag, where
//! asked for, is true where the grown square lies inside the triangle (a
//! flag it is sure of), and the last triangle to draw a pixel leaves its
//! flag there.
//!
//! What it does not do: multisampling, motion, clip space, polygons, lines,
//! points, depth and attributes under conservative rasterization (the
//! scene says why, `Scene::conservative_unjudged`); coordinates that are
//! neither snapped nor dyadic (fixed point cannot hold them).

use super::growth::Growth;
use super::triangle::{Setup, Shape};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::Fixed;
use crate::production::scene_format::{format_for, place};
use crate::rasterizer::RasterError;
use crate::scene::{ConservativeMode, ConservativeSupport, Primitive, Scene};

/// What production draws conservatively: both modes and the flag, each
/// under the case's own uncertainty and properties.
pub fn support() -> ConservativeSupport {
    ConservativeSupport {
        overestimate: true,
        underestimate: true,
        fully_covered: true,
        ..ConservativeSupport::default()
    }
}

/// Production's frame of a conservative scene.
pub fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let Some(case) = scene.effects.conservative.as_ref() else {
        return Err(RasterError::Failed(
            "production's conservative path was given a scene that is not conservative".to_owned(),
        ));
    };
    if let Some(why) = scene.conservative_unjudged() {
        return Err(RasterError::Unsupported(why));
    }
    let format = format_for(scene, None)?;
    let f = format.frac_bits;
    let half = Growth::half_side(&case.uncertainty, f);
    let margin = Growth::margin(&case.uncertainty, f);
    // The flag's square: the pixel grown by u, whichever the mode.
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::for_plan(w, h, plan);
    let mut flags = case
        .fully_covered
        .then(|| vec![false; frame.coverage.len()]);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Triangle(t) = primitive else {
            return Err(RasterError::Unsupported(
                "production draws triangles only under conservative rasterization".to_owned(),
            ));
        };
        let vertices: [[Fixed; 2]; 3] = t
            .vertices
            .each_ref()
            .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]);
        let (setup, orientation) = Setup::new(vertices, f);
        if setup.shape != Shape::Area && !case.degenerate_triangles {
            continue;
        }
        if scene.rules.cull.discards(orientation) {
            continue;
        }
        for y in setup.range(1, h) {
            for x in setup.range(0, w) {
                let drawn = match case.mode {
                    ConservativeMode::Overestimate => setup.meets(x, y, &half, &margin),
                    ConservativeMode::Underestimate => setup.holds(x, y, &half),
                };
                if !drawn {
                    continue;
                }
                let i = frame.index(x as u32, y as u32);
                frame.hit(i, index);
                if let Some(flags) = &mut flags {
                    flags[i] = setup.holds(x, y, &half);
                }
            }
        }
    }
    frame.fully_covered = flags;
    frame.coverage_only = true;
    Ok(frame)
}
