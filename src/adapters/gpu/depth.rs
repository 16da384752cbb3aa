//! A real depth attachment for the scenes that need one (SPEC.md §18: a
//! depth format other than `exact`, or a polygon offset): what the Vulkan
//! and GL adapters set up, what they refuse, and how a stored depth reads
//! back as the value a frame reports.
//!
//! The depth written is the driver's own: interpolated by it from the
//! positions' z (screen space: the case's `z` as the position's z, so
//! that z_ndc is the case's depth; clip space: the clip z through the
//! viewport's depth range), offset by its polygon offset, clamped and
//! stored in the attachment's format. A depth test that always passes,
//! with writes on, keeps the last primitive's depth in submission order,
//! as the colour channels keep its values. The adapter reads the stored
//! integers (unorm) or floats (float32) back, never a conversion of them
//! to float: a unorm24 value near 1 is within an f32 ulp of its
//! neighbours. The one exception, a multisampled attachment, which no
//! copy reads, is loaded by a shader as floats: unorm16 and float32 only,
//! the stored value recovered exactly ([`sampled_value`]).

use dashu_ratio::RBig;

use super::super::float_input::f32_of;
use crate::scene::depth::unorm_value;
use crate::scene::{DepthFormat, Number, Scene};

/// The depth state of a scene that needs an attachment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DepthTarget {
    /// `unorm16`, `unorm24` or `float32` (never `exact`: the reader
    /// refuses a polygon offset without a format, and an `exact` scene
    /// needs no attachment).
    pub format: DepthFormat,
    /// Polygon offset `[constant, slope, clamp]` (Vulkan's
    /// depthBiasConstantFactor, depthBiasSlopeFactor, depthBiasClamp;
    /// GL's units, factor, clamp), each the case's number exactly.
    pub bias: Option<[f32; 3]>,
}

/// The attachment the scene asks for, as the API takes it (`None`: it
/// needs none: its depth is the fragment's, judged by SPEC.md §6.3): its
/// format, and its offset numbers rounded to f32 ([`target`] refuses them
/// where that rounds).
pub(crate) fn requested(scene: &Scene) -> Option<DepthTarget> {
    scene.depth_rules_need_attachment().then(|| DepthTarget {
        format: scene.rules.depth_format,
        bias: scene
            .rules
            .depth_bias
            .as_ref()
            .map(|b| [&b.constant, &b.slope, &b.clamp].map(f32_of)),
    })
}

/// The attachment the scene needs ([`requested`]), or why the adapter cannot
/// set it up: a polygon (§14 polygons carry no depth, and the adapters'
/// stencil attachment is theirs), an offset number that is not an f32
/// (the APIs take f32), or, in screen space, a depth outside [0, 1] when
/// the driver cannot clamp depth without clipping it (`clamps`: the
/// case's depth is the position's z, which the near and far planes would
/// otherwise cut).
pub(crate) fn target(
    scene: &Scene,
    clamps: bool,
    driver: &str,
) -> Result<Option<DepthTarget>, String> {
    let Some(requested) = requested(scene) else {
        return Ok(None);
    };
    if scene.has_polygons() {
        return Err(format!(
            "depth_format {} with polygons: polygons carry no depth, and {driver}'s \
             stencil attachment is the polygons'",
            scene.rules.depth_format.name()
        ));
    }
    let exact = |n: &Number| RBig::try_from(f32_of(n)).is_ok_and(|back| &back == n.as_rbig());
    if let Some(b) = &scene.rules.depth_bias {
        for (name, n) in [
            ("constant", &b.constant),
            ("slope", &b.slope),
            ("clamp", &b.clamp),
        ] {
            if !exact(n) {
                return Err(format!(
                    "depth_bias.{name} {} is not an f32, as {driver} takes it",
                    n.to_exact_string()
                ));
            }
        }
    }
    if scene.viewport.is_none() && !clamps {
        let unit = |z: &Number| *z.as_rbig() >= RBig::ZERO && *z.as_rbig() <= RBig::ONE;
        if !scene.vertices().all(|v| unit(&v.z)) {
            return Err(format!(
                "a depth outside [0, 1] in screen space: {driver} cannot clamp depth \
                 without clipping it"
            ));
        }
    }
    Ok(Some(requested))
}

/// The depth a stored value reads back as: a unorm integer `k` (the
/// attachment's low n bits) as the f32 nearest k/(2^n − 1), a float32's
/// bits as that f32.
pub(crate) fn stored_value(format: DepthFormat, word: u32) -> f64 {
    match format.unorm_bits() {
        Some(bits) => f64::from(unorm_value(word & ((1u32 << bits) - 1), bits)),
        None => f64::from(f32::from_bits(word)),
    }
}

/// The depth a multisampled attachment's sample reads back as, from the
/// float a shader loaded it as: a unorm16 sample as the f32 nearest
/// k/(2^16 − 1), k the integer nearest f·(2^16 − 1) (the load is off by far
/// less than half a step, so k is the stored one); a float32 sample as
/// itself. Not for unorm24 (its neighbours near 1 are within an f32 ulp:
/// the adapters copy it out instead).
#[cfg_attr(not(feature = "vulkan"), allow(dead_code))] // the gl adapter copies only
pub(crate) fn sampled_value(format: DepthFormat, f: f32) -> f64 {
    match format.unorm_bits() {
        Some(bits) => {
            debug_assert_eq!(bits, 16, "unorm24 is copied out, never sampled");
            let n = f64::from((1u32 << bits) - 1);
            let k = (f64::from(f) * n).round().clamp(0.0, n) as u32;
            f64::from(unorm_value(k, bits))
        }
        None => f64::from(f),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_values_decode_the_grid_and_the_float() {
        assert_eq!(stored_value(DepthFormat::Unorm16, 65535), 1.0);
        assert_eq!(stored_value(DepthFormat::Unorm16, 0), 0.0);
        // X8_D24: the upper byte is undefined and ignored.
        assert_eq!(stored_value(DepthFormat::Unorm24, 0xff00_0000), 0.0);
        assert_eq!(
            stored_value(DepthFormat::Unorm24, 0x00ff_ffff | 0x1200_0000),
            1.0
        );
        let half = stored_value(DepthFormat::Unorm16, 32768);
        assert_eq!(half, f64::from((32768.0f64 / 65535.0) as f32));
        assert_eq!(stored_value(DepthFormat::Float32, 0.25f32.to_bits()), 0.25);
    }

    #[test]
    fn sampled_values_recover_the_stored_integer() {
        // A load a few ulps off k/65535 still gives k's grid value.
        for k in [0u32, 1, 32767, 32768, 65534, 65535] {
            let exact = k as f32 / 65535.0;
            for off in [-3i32, 0, 3] {
                let f = f32::from_bits((exact.to_bits() as i32 + off).max(0) as u32);
                let want = f64::from(unorm_value(k, 16));
                assert_eq!(sampled_value(DepthFormat::Unorm16, f), want, "{k} {off}");
            }
        }
        assert_eq!(sampled_value(DepthFormat::Float32, 0.3), f64::from(0.3f32));
    }
}
