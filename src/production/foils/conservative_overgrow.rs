//! `foil-conservative-overgrow`: conservative overestimation that grows
//! every triangle by ⅛ px more than the uncertainty it declares (the
//! case's), as a driver whose reported `primitiveOverestimationSize` is
//! smaller than what its hardware does. **A foil**, wrong in that one way:
//! a pixel whose square lies more than u but at most u + ⅛ px from a
//! triangle is drawn. Caught as a forbidden pixel drawn (SPEC.md §19.1).
//! It draws overestimation only.

use super::conservative_parts::{capabilities, overestimation_only};
use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::conservative;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Scene};

/// How much more it grows than it declares: ⅛ px.
const EXCESS: (i64, i64) = (1, 8);

foil!(
    /// Conservative overestimation grown ⅛ px past its declaration.
    ConservativeOvergrow,
    "foil-conservative-overgrow",
    capabilities: capabilities(),
    conservative: overestimation_only(),
    draw
);

/// Production's conservative frame of the scene with its uncertainty grown
/// by [`EXCESS`].
fn draw(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let mut grown = scene.clone();
    if let Some(c) = &mut grown.effects.conservative {
        let excess = Number::ratio(EXCESS.0, EXCESS.1);
        c.uncertainty = Number::from_rbig(c.uncertainty.as_rbig() + excess.as_rbig());
    }
    conservative::rasterize(&grown, plan)
}
