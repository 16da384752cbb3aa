//! Which antialiased scenes the device multisamples natively: the sample
//! counts it offers at the standard locations, and the scenes drawn so
//! (the rest are drawn by shifted passes).

use super::device::{self, Offers};
use crate::plan::Plan;
use crate::scene::{Antialias, Pattern, Primitive, Scene};

/// Whether the device multisamples `n` samples natively at the standard
/// locations, read back sample by sample.
pub(super) fn native_offered(offers: &Offers, n: u32) -> bool {
    offers.standard_locations
        && offers
            .msaa_counts
            .contains(ash::vk::SampleCountFlags::from_raw(n))
}

/// The sample count to multisample the scene with natively, if any: its
/// offsets are exactly the standard locations of a count the device
/// offers (checked offset by offset, not by the pattern's name), it has no
/// lines (multisampled Vulkan lines are rectangles, whatever their rule),
/// per-sample interpolation is there if the plan interpolates, and the
/// read-back target (n times the canvas's width) fits.
pub(super) fn native_samples(
    scene: &Scene,
    plan: &Plan,
    offers: &Offers,
    passes_only: bool,
) -> Option<u32> {
    let aa = plan.antialias.as_ref()?;
    let n = aa.offsets.len() as u32;
    let standard = Antialias {
        samples: n,
        pattern: Pattern::Standard,
        seed: 0,
        adaptive: false,
        position_bits: aa.position_bits,
    };
    let fits = u64::from(scene.canvas.width) * u64::from(n) <= u64::from(offers.max_side);
    let lines = scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Line(_)));
    (!passes_only
        && matches!(n, 2 | 4 | 8 | 16)
        && native_offered(offers, n)
        && standard.offsets() == aa.offsets
        && !lines
        && (offers.sample_rate_shading || !plan.interpolates())
        && plan.motion.is_none()
        && depth_natively(scene, offers, n)
        && fits)
        .then_some(n)
}

/// Whether the scene's depth attachment, if it needs one, can be drawn
/// with `n` samples and read back sample by sample: `unorm16` and
/// `float32`, read by a shader as floats from which the stored value is
/// recovered exactly (the integer nearest f·(2^16 − 1): the read is off by
/// far less than half a step; the f32 itself). Not `unorm24`, whose values
/// near 1 lie within an f32 ulp of each other: such a scene is drawn by
/// shifted passes, each copied out.
fn depth_natively(scene: &Scene, offers: &Offers, n: u32) -> bool {
    if !scene.depth_rules_need_attachment() {
        return true;
    }
    match device::depth_attachment(scene.rules.depth_format) {
        Some((_, i)) => {
            scene.rules.depth_format != crate::scene::DepthFormat::Unorm24
                && offers.depth_sampled[i]
                && offers
                    .depth_msaa_counts
                    .contains(ash::vk::SampleCountFlags::from_raw(n))
        }
        None => false,
    }
}
