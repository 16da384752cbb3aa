//! What the three conservative foils share: production's conservative
//! frame drawn one triangle at a time, each triangle's pixels passed
//! through the foil's own change (a pixel dropped, a flag set otherwise),
//! then laid down in scene order as production lays them; the
//! triangle's snapped vertices in rationals, for the foil's own tests; and
//! what they declare.

use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::conservative;
use crate::rasterizer::{Capabilities, RasterError};
use crate::scene::{ConservativeSupport, Number, Primitive, Scene};

/// A triangle's vertices after snapping, exact.
pub(super) type Snapped = [[RBig; 2]; 3];

/// What the conservative foils draw: triangles, snapped or not.
pub(super) fn capabilities() -> Capabilities {
    Capabilities {
        triangles: true,
        ideal_geometry: true,
        ..Capabilities::none()
    }
}

/// What the overestimating foils declare: production's conservative
/// support, overestimation only.
pub(super) fn overestimation_only() -> ConservativeSupport {
    ConservativeSupport {
        underestimate: false,
        ..conservative::support()
    }
}

/// Production's conservative frame of `scene`, each triangle drawn on its
/// own and each of its pixels (x, y) with the flag production gives it
/// passed through `change`: `None` drops the pixel, `Some(flag)` draws it
/// with that flag.
pub(super) fn drawn_with(
    scene: &Scene,
    plan: &Plan,
    change: impl Fn(&Snapped, u32, u32, bool) -> Option<bool>,
) -> Result<Frame, RasterError> {
    let mut frame = conservative::rasterize(
        &Scene {
            primitives: Vec::new(),
            ..scene.clone()
        },
        plan,
    )?;
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Triangle(t) = primitive else {
            return Err(RasterError::Unsupported(
                "the conservative foils draw triangles only".to_owned(),
            ));
        };
        let alone = Scene {
            primitives: vec![primitive.clone()],
            ..scene.clone()
        };
        let own = conservative::rasterize(&alone, plan)?;
        let snapped: Snapped = t
            .vertices
            .each_ref()
            .map(|v| [&v.x, &v.y].map(|n| snap(n, scene.rules.subpixel_bits).as_rbig().clone()));
        for y in 0..frame.height {
            for x in 0..frame.width {
                let i = frame.index(x, y);
                if own.coverage[i] == 0 {
                    continue;
                }
                let flag = own.fully_covered.as_ref().is_some_and(|f| f[i]);
                if let Some(flag) = change(&snapped, x, y, flag) {
                    frame.hit(i, index);
                    if let (Some(depth), Some(own)) = (frame.depth.as_mut(), own.depth.as_ref()) {
                        depth[i] = own[i];
                    }
                    if let Some(flags) = &mut frame.fully_covered {
                        flags[i] = flag;
                    }
                }
            }
        }
    }
    Ok(frame)
}

fn snap(n: &Number, bits: Option<u32>) -> Number {
    bits.map_or_else(|| n.clone(), |b| n.snapped(b))
}
