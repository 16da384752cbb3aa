//! Numbers and pixels as the protocol's JSON carries them: a number
//! written twice (its nearest f64 and its exact spelling), a pixel and a
//! whole number read back, and a depth as its format stores it.

use serde_json::{json, Value};

use crate::scene::depth::unorm_value;
use crate::scene::{DepthFormat, Number};

/// A number twice: its nearest f64, and (in the sibling `exact` object) its
/// exact spelling.
pub(super) fn float(n: &Number) -> Value {
    json!(n.to_f64_lossy())
}

pub(super) fn exact(n: &Number) -> Value {
    Value::String(n.to_exact_string())
}

/// A number as a request gives it: (its nearest f64, its exact spelling).
pub(super) fn float_exact(n: &Number) -> (Value, Value) {
    (float(n), exact(n))
}

/// The pixel (x, y) an answer's item starts with, or why it is none of
/// the canvas (`at` names the item's JSON path).
pub(super) fn pixel_of(
    item: &[Value],
    (width, height): (u32, u32),
    at: &dyn Fn() -> String,
) -> Result<(u32, u32), String> {
    match (whole_below(&item[0], width), whole_below(&item[1], height)) {
        (Some(x), Some(y)) => Ok((x, y)),
        _ => Err(format!(
            "{}: ({}, {}) is not a pixel of the {width}×{height} canvas",
            at(),
            item[0],
            item[1]
        )),
    }
}

/// A whole number in [0, limit), as JSON gives it.
pub(super) fn whole_below(v: &Value, limit: u32) -> Option<u32> {
    v.as_f64()
        .filter(|c| c.fract() == 0.0 && *c >= 0.0 && *c < f64::from(limit))
        .map(|c| c as u32)
}

/// A depth an answer gives, as the case's format stores it (SPEC.md
/// §12.10): under unorm n the stored integer k in [0, 2^n − 1], read back
/// as k/(2^n − 1) rounded once to an f32, as a driver's readback is;
/// under float32 any number, stored as its nearest f32; under `exact` the
/// number itself. `None`: not a depth of the format.
pub(super) fn stored_depth(value: f64, format: DepthFormat) -> Option<f64> {
    match format {
        DepthFormat::Exact => Some(value),
        DepthFormat::Float32 => Some(f64::from(value as f32)),
        DepthFormat::Unorm16 | DepthFormat::Unorm24 => {
            let bits = format.unorm_bits()?;
            let k = whole_below(&Value::from(value), 1 << bits)?;
            Some(f64::from(unorm_value(k, bits)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_depth_is_read_back_as_its_format_stores_it() {
        let half = stored_depth(32768.0, DepthFormat::Unorm16).unwrap();
        assert_eq!(half, f64::from(unorm_value(32768, 16)));
        assert_eq!(stored_depth(65535.0, DepthFormat::Unorm16), Some(1.0));
        // Not a stored integer of the format: refused.
        assert_eq!(stored_depth(0.5, DepthFormat::Unorm16), None);
        assert_eq!(stored_depth(65536.0, DepthFormat::Unorm16), None);
        assert_eq!(stored_depth(-1.0, DepthFormat::Unorm24), None);
        assert!(stored_depth(16_777_215.0, DepthFormat::Unorm24).is_some());
        // float32: the nearest f32; exact: the number itself.
        assert_eq!(
            stored_depth(0.1, DepthFormat::Float32),
            Some(f64::from(0.1f32))
        );
        assert_eq!(stored_depth(0.1, DepthFormat::Exact), Some(0.1));
    }
}
