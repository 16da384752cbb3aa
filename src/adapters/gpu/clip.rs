//! What a driver adapter cannot hand a driver of a clip-space scene
//! (SPEC.md §16.10): the `vulkan` and `gl` adapters' shared refusal.

use dashu_ratio::RBig;

use super::super::float_input::to_f32;
use crate::scene::{Number, Scene};

/// Why a driver that snaps to `driver_bits` subpixel bits cannot draw a
/// clip-space scene (SPEC.md §16) as the case asks, if it cannot.
///
/// The driver clips, divides, applies the viewport and snaps: that is what
/// is judged, so the adapter hands it the case's numbers as they are and
/// cannot snap for it. Hence:
///
/// - **subpixel bits**: as in screen space, unsnapped geometry (`null`) and
///   a case at more bits than the driver's are drawn on the driver's grid,
///   and judged at its bits (SPEC.md §3.2). A case at fewer bits is
///   refused: in screen
///   space the adapter snaps to the coarser grid itself before the driver
///   sees the vertex (exact on the driver's finer grid), but here the
///   vertices are the driver's own (divided, and new ones from clipping).
/// - **f32**: the viewport's rectangle must be f32s, the type the driver
///   takes, as it places every vertex (coverage). Its depth range is
///   rounded once to f32 like any value (a relative error of 2^-24, far
///   inside depth's tolerance, SPEC.md §6.3). Clip coordinates are rounded once to
///   f32, as z, w and attributes are in screen space: a relative error of
///   2^-24, which moves a snapped position only where the exact one lies
///   that close to a rounding tie of the driver's grid (the bundled cases
///   give decimals such as 0.9, and refusing them would lose most of
///   `cases/clip`).
pub(crate) fn clip_space_refusal(scene: &Scene, driver: &str, driver_bits: u32) -> Option<String> {
    let viewport = scene.viewport.as_ref()?;
    if let Some(bits) = scene.rules.subpixel_bits.filter(|&bits| bits < driver_bits) {
        return Some(format!(
            "subpixel_bits {bits}: {driver} snaps clip-space vertices (divided, and those \
             clipping makes) to its own {driver_bits} bits, and the adapter cannot snap them coarser"
        ));
    }
    let not_f32 = |n: &Number| {
        let q = n.as_rbig();
        !RBig::try_from(to_f32(q)).is_ok_and(|back| &back == q)
    };
    let v = viewport;
    for (name, n) in [
        ("x", &v.x),
        ("y", &v.y),
        ("width", &v.width),
        ("height", &v.height),
    ] {
        if not_f32(n) {
            return Some(format!(
                "viewport.{name} {} is not an f32, the type {driver} takes",
                n.to_exact_string()
            ));
        }
    }
    None
}
