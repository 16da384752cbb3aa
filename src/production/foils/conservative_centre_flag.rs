//! `foil-conservative-centre-flag`: conservative rasterization whose
//! fully-covered flag is the ordinary coverage test, the pixel's centre
//! inside the triangle, as a driver that reuses its sample test for
//! `FullyCoveredEXT` would. **A foil**, wrong in that one way: a pixel
//! whose centre is covered but whose square is not wholly inside reports
//! itself fully covered. Caught by the flag's check (SPEC.md §19.4). It
//! draws the pixels production draws, in both modes.

use super::conservative_parts::{capabilities, drawn_with, Snapped};
use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::conservative;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;
use dashu_ratio::RBig;

foil!(
    /// Conservative rasterization with the centre's coverage as its flag.
    ConservativeCentreFlag,
    "foil-conservative-centre-flag",
    capabilities: capabilities(),
    conservative: conservative::support(),
    draw
);

/// Production's conservative pixels, each flagged fully covered when its
/// centre is inside.
fn draw(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    drawn_with(scene, plan, |v, x, y, _| Some(centre_inside(v, x, y)))
}

/// Whether the centre of pixel (x, y) lies in the closed triangle `v` of
/// positive area: on the inner side of (or on) every edge.
fn centre_inside(v: &Snapped, x: u32, y: u32) -> bool {
    let half = RBig::from(1) / RBig::from(2);
    let c = [RBig::from(x) + &half, RBig::from(y) + half];
    let cross = |a: &[RBig; 2], b: &[RBig; 2], p: &[RBig; 2]| {
        (&b[0] - &a[0]) * (&p[1] - &a[1]) - (&b[1] - &a[1]) * (&p[0] - &a[0])
    };
    let area = cross(&v[0], &v[1], &v[2]);
    if area == RBig::ZERO {
        return false;
    }
    let sides = [0, 1, 2].map(|i| cross(&v[i], &v[(i + 1) % 3], &c));
    if area > RBig::ZERO {
        sides.iter().all(|s| *s >= RBig::ZERO)
    } else {
        sides.iter().all(|s| *s <= RBig::ZERO)
    }
}
