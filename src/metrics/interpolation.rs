//! Interpolation error against the exact values.

use crate::frame::Frame;

/// Error of one channel (depth or an attribute) over the samples where the
/// candidate and the reference agree on which primitive was drawn last.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelError {
    pub channel: String,
    pub samples: u64,
    pub max_abs: f64,
    /// Largest error in units in the last place of the exact value's f32,
    /// over samples whose exact value is at least `ulp_floor` in magnitude.
    pub max_ulp: f64,
    pub rms: f64,
    /// The bound this channel is held to.
    pub allowed_abs: f64,
    pub allowed_ulp: Option<f64>,
    /// Depth under a depth format (SPEC.md §18): the samples outside the
    /// allowed set. `max_abs`, `max_ulp` and `rms` then measure the
    /// distance from the allowed interval (0 inside), and `allowed_abs` is
    /// 0: the set already holds §6.3's tolerance.
    pub depth_set: Option<DepthSetMiss>,
}

/// How a candidate's depths miss the set a depth format allows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DepthSetMiss {
    /// `rules.depth_format`.
    pub format: &'static str,
    /// Samples whose depth is not on the unorm grid (0 for float32).
    pub off_grid: u64,
    /// Samples whose depth lies outside the allowed interval.
    pub outside: u64,
}

impl ChannelError {
    pub fn within_bounds(&self) -> bool {
        if let Some(miss) = &self.depth_set {
            return miss.off_grid == 0 && miss.outside == 0;
        }
        self.max_abs <= self.allowed_abs && self.allowed_ulp.is_none_or(|u| self.max_ulp <= u)
    }
}

/// What a channel is held to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub allowed_abs: f64,
    pub allowed_ulp: Option<f64>,
    /// Ulps are counted only where |exact| is at least this.
    pub ulp_floor: f64,
}

/// The spacing of f32 values at `x` (the f32 ulp of x's magnitude).
pub fn f32_ulp(x: f64) -> f64 {
    let m = (x as f32).abs();
    if m < f32::MIN_POSITIVE {
        return f64::from(f32::from_bits(1));
    }
    let next = f32::from_bits(m.to_bits() + 1);
    f64::from(next) - f64::from(m)
}

pub fn channel_error(
    channel: &str,
    reference: &Frame,
    candidate: &Frame,
    exact: &[f64],
    values: &[f64],
    bounds: Bounds,
) -> ChannelError {
    let Bounds {
        allowed_abs,
        allowed_ulp,
        ulp_floor,
    } = bounds;
    let (mut samples, mut max_abs, mut max_ulp, mut sum_sq) = (0u64, 0f64, 0f64, 0f64);
    for i in 0..reference.sample_count() {
        if reference.last[i] == 0 || reference.last[i] != candidate.last[i] {
            continue;
        }
        let error = (values[i] - exact[i]).abs();
        let error = if error.is_nan() { f64::INFINITY } else { error };
        samples += 1;
        max_abs = max_abs.max(error);
        // An error of 1e-9 where the exact value is 0 is infinitely many
        // ulps; near zero the absolute error is the measure.
        if exact[i].abs() >= ulp_floor {
            max_ulp = max_ulp.max(error / f32_ulp(exact[i]));
        }
        sum_sq += error * error;
    }
    let rms = if samples == 0 {
        0.0
    } else {
        (sum_sq / samples as f64).sqrt()
    };
    ChannelError {
        channel: channel.to_owned(),
        samples,
        max_abs,
        max_ulp,
        rms,
        allowed_abs,
        allowed_ulp,
        depth_set: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulps_follow_f32_spacing() {
        assert_eq!(f32_ulp(1.0), f64::from(f32::EPSILON));
        assert_eq!(f32_ulp(-1.0), f64::from(f32::EPSILON));
        assert_eq!(f32_ulp(1024.0), 1024.0 * f64::from(f32::EPSILON));
        assert_eq!(f32_ulp(0.0), f64::from(f32::from_bits(1)));
    }
}
