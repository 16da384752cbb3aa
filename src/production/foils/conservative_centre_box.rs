//! `foil-conservative-centre-box`: conservative overestimation whose
//! pixel box is the ordinary rasterizer's, the pixels whose centres lie in
//! the triangle's bounding box, as a driver that reuses its normal
//! triangle set-up would. **A foil**, wrong in that one way: a pixel that
//! a triangle's vertex pokes into without reaching its centre's row or
//! column (a touched corner pixel) is never tested, so never drawn. Caught
//! as a required pixel missing (SPEC.md §19.1). It draws overestimation
//! only, under the case's uncertainty.

use super::conservative_parts::{capabilities, drawn_with, overestimation_only};
use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;
use dashu_ratio::RBig;

foil!(
    /// Conservative overestimation within the centres' box.
    ConservativeCentreBox,
    "foil-conservative-centre-box",
    capabilities: capabilities(),
    conservative: overestimation_only(),
    draw
);

/// Production's conservative frame less the pixels whose centres lie
/// outside the triangle's bounding box.
fn draw(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    drawn_with(scene, plan, |v, x, y, flag| {
        // The centre (x + ½, y + ½) inside [min, max] on both axes.
        let half = RBig::from(1) / RBig::from(2);
        let inside = |c: u32, k: usize| {
            let centre = RBig::from(c) + &half;
            let lo = v.iter().map(|p| &p[k]).min().expect("three vertices");
            let hi = v.iter().map(|p| &p[k]).max().expect("three vertices");
            *lo <= centre && centre <= *hi
        };
        (inside(x, 0) && inside(y, 1)).then_some(flag)
    })
}
