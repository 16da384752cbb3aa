//! Depth under a depth format (SPEC.md §18): a candidate's depth at a
//! sample must lie in the interval the reference allows there
//! (`reference::render_judged`), and for a unorm format on its grid.
//!
//! Every comparison is exact: the candidate's depth is an f32 widened to
//! f64, the interval's ends are the tightest f64 bounds of exact values
//! (or grid values), and "on the grid" is decided by
//! [`crate::scene::depth::unorm_index`] in exact arithmetic.

use super::interpolation::{f32_ulp, ChannelError, DepthSetMiss};
use crate::frame::Frame;
use crate::scene::depth::{unorm_index, DepthFormat};

/// A depth's signed distance from its allowed interval [lo, hi]: below
/// it negative, above it positive, inside it 0; NaN for a NaN depth.
pub fn signed_distance(c: f64, [lo, hi]: [f64; 2]) -> f64 {
    if c.is_nan() || c < lo {
        c - lo
    } else if c > hi {
        c - hi
    } else {
        0.0
    }
}

/// The depth channel's error against the allowed set `allowed` (one
/// [lo, hi] per slot), over the samples where the candidate and the
/// reference agree on the last primitive. The distance reported is from
/// the interval (0 inside); a NaN depth is outside at infinite distance.
pub fn measure(
    format: DepthFormat,
    reference: &Frame,
    candidate: &Frame,
    allowed: &[[f64; 2]],
    values: &[f64],
) -> ChannelError {
    let mut miss = DepthSetMiss {
        format: format.name(),
        ..DepthSetMiss::default()
    };
    let (mut samples, mut max_abs, mut max_ulp, mut sum_sq) = (0u64, 0f64, 0f64, 0f64);
    for i in 0..reference.sample_count() {
        if reference.last[i] == 0 || reference.last[i] != candidate.last[i] {
            continue;
        }
        samples += 1;
        let (c, [lo, hi]) = (values[i], allowed[i]);
        let distance = if c.is_nan() {
            f64::INFINITY
        } else {
            signed_distance(c, [lo, hi]).abs()
        };
        if distance > 0.0 {
            miss.outside += 1;
        }
        if let Some(bits) = format.unorm_bits() {
            if unorm_index(c, bits).is_none() {
                miss.off_grid += 1;
            }
        }
        max_abs = max_abs.max(distance);
        if distance > 0.0 {
            max_ulp = max_ulp.max(distance / f32_ulp(if c < lo { lo } else { hi }));
        }
        sum_sq += distance * distance;
    }
    let rms = if samples == 0 {
        0.0
    } else {
        (sum_sq / samples as f64).sqrt()
    };
    ChannelError {
        channel: "depth".to_owned(),
        samples,
        max_abs,
        max_ulp,
        rms,
        allowed_abs: 0.0,
        allowed_ulp: None,
        depth_set: Some(miss),
    }
}
