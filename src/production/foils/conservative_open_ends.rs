//! `foil-conservative-open-ends`: conservative points and lines (SPEC.md
//! §19.8) drawn with each line's end caps open, as an implementation that
//! tests a pixel against the line's sides but compares strictly at its
//! ends. **A foil**, wrong in that one way: every line is drawn 1/1024 of
//! its length short at both ends, so a pixel whose square only touches an
//! end cap (the end pixels of `conservative/line_over_diagonal`, touching
//! the line at a corner) is missed. Caught as a required pixel not drawn
//! (SPEC.md §19.5). Its triangles and points are production's.

use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::conservative;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Primitive, Scene};

/// How much of its length each end loses: 1/1024.
const SHORT: i64 = 1024;

foil!(
    /// Conservative lines with open end caps.
    ConservativeOpenEnds,
    "foil-conservative-open-ends",
    capabilities: Capabilities {
        triangles: true,
        ideal_geometry: true,
        points: true,
        ..Capabilities::none()
    },
    conservative: conservative::support(),
    draw
);

/// Production's conservative frame of the scene with every line
/// shortened by 1/[`SHORT`] of its length at each end.
fn draw(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    // Snap first, as the rasterizer does, then pull each line's ends in
    // along the snapped segment: the result is dyadic, held unsnapped.
    let mut short = scene.clone();
    if let Some(bits) = scene.rules.subpixel_bits {
        for v in short.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
            v.x = v.x.snapped(bits);
            v.y = v.y.snapped(bits);
        }
        short.rules.subpixel_bits = None;
    }
    for primitive in &mut short.primitives {
        let Primitive::Line(line) = primitive else {
            continue;
        };
        let [a, b] = &line.vertices;
        let step = |from: &Number, to: &Number| {
            Number::from_rbig((to.as_rbig() - from.as_rbig()) / dashu_ratio::RBig::from(SHORT))
        };
        let (sx, sy) = (step(&a.x, &b.x), step(&a.y, &b.y));
        let moved = |n: &Number, by: &Number, sign: bool| {
            Number::from_rbig(if sign {
                n.as_rbig() + by.as_rbig()
            } else {
                n.as_rbig() - by.as_rbig()
            })
        };
        let [a, b] = &mut line.vertices;
        a.x = moved(&a.x, &sx, true);
        a.y = moved(&a.y, &sy, true);
        b.x = moved(&b.x, &sx, false);
        b.y = moved(&b.y, &sy, false);
    }
    conservative::rasterize(&short, plan)
}
