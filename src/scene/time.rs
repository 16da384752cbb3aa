//! Motion blur as a case asks for it: the shutter and the instants a
//! sample method tests (SPEC.md §15).
//!
//! Like the antialiasing patterns, the instants are part of the case, so
//! they live in the scene model: production and any external program read
//! the same instants, and the reference, which integrates over the whole
//! shutter, needs none. Every instant is open + (close − open)·u/2^16 for an
//! integer u, and the shutter's ends are multiples of 2^-16, so every
//! instant is a multiple of 2^-32: exact in fixed point.

use super::samples::SplitMix64;

/// How the instants of a pixel's samples are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimePattern {
    /// Independent uniform instants.
    Random,
    /// Each spatial sample's N instants jittered in N equal strata.
    Stratified,
    /// The pixel's M·N instants jittered in M·N strata, taken in order by
    /// the spatial samples: x, y and t stratified together, and correlated.
    JitteredXyT,
    /// The pixel's M·N strata dealt to the spatial samples by a shuffle:
    /// t stratified independently of x and y.
    StratifiedShuffled,
}

case_names!(TimePattern {
    Random => "random",
    Stratified => "stratified",
    JitteredXyT => "jittered-xy-t",
    StratifiedShuffled => "stratified-shuffled",
});

/// Bounds on `effects.motion_blur`.
pub mod limits {
    /// Instants are multiples of 2^-TIME_BITS of the shutter, and the
    /// shutter's ends multiples of 2^-TIME_BITS.
    pub const TIME_BITS: u32 = 16;
    /// 2^TIME_BITS: the shutter [0, 1] in time units.
    pub const TIME_ONE: u32 = 1 << TIME_BITS;
    /// Largest count of time samples per spatial sample.
    pub const MAX_SAMPLES: u32 = 1024;
}

/// `effects.motion_blur`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MotionBlur {
    /// [open, close] in units of 2^-16, 0 ≤ open < close ≤ 2^16.
    pub shutter: [u32; 2],
    /// N: time samples per spatial sample.
    pub samples: u32,
    pub pattern: TimePattern,
    pub seed: u64,
}

impl MotionBlur {
    /// The u (in 2^-16 of the shutter, in [0, 2^16)) of every test of pixel
    /// `pixel` (y·width + x) with `spatial` spatial samples: slot
    /// s·N + k is instant k of spatial sample s (SPEC.md §15.3).
    pub fn pixel_times(&self, pixel: u64, spatial: u32) -> Vec<u32> {
        let n = u64::from(self.samples);
        let total = u64::from(spatial) * n;
        let one = u64::from(limits::TIME_ONE);
        let mut rng =
            SplitMix64::new(self.seed ^ pixel.wrapping_add(1).wrapping_mul(0xD6E8_FEB8_6659_FD93));
        let mut draw = || rng.below_power_of_two(limits::TIME_BITS);
        match self.pattern {
            TimePattern::Random => (0..total).map(|_| draw() as u32).collect(),
            TimePattern::Stratified => (0..total)
                .map(|j| (((j % n) * one + draw()) / n) as u32)
                .collect(),
            TimePattern::JitteredXyT | TimePattern::StratifiedShuffled => {
                let mut strata: Vec<u32> = (0..total)
                    .map(|i| ((i * one + draw()) / total) as u32)
                    .collect();
                if self.pattern == TimePattern::StratifiedShuffled {
                    // Fisher–Yates from the top, as SPEC.md writes it:
                    // u_j = v_{π[j]} with π shuffled in place.
                    let mut order: Vec<u64> = (0..total).collect();
                    for i in (1..total).rev() {
                        let j = rng.next_u64() % (i + 1);
                        order.swap(i as usize, j as usize);
                    }
                    strata = order.iter().map(|&i| strata[i as usize]).collect();
                }
                strata
            }
        }
    }

    /// The instant of `u`, in units of 2^-32 of [0, 1]:
    /// open + (close − open)·u/2^16.
    pub fn instant(&self, u: u32) -> u64 {
        let [open, close] = self.shutter.map(u64::from);
        (open << limits::TIME_BITS) + (close - open) * u64::from(u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blur(samples: u32, pattern: TimePattern) -> MotionBlur {
        MotionBlur {
            shutter: [0, limits::TIME_ONE],
            samples,
            pattern,
            seed: 3,
        }
    }

    #[test]
    fn stratified_instants_keep_to_their_strata() {
        let times = blur(8, TimePattern::Stratified).pixel_times(5, 2);
        assert_eq!(times.len(), 16);
        for (j, &u) in times.iter().enumerate() {
            assert_eq!(u / (limits::TIME_ONE / 8), j as u32 % 8);
        }
    }

    #[test]
    fn shuffled_strata_cover_every_stratum_once() {
        let times = blur(4, TimePattern::StratifiedShuffled).pixel_times(9, 4);
        let mut strata: Vec<u32> = times.iter().map(|u| u / (limits::TIME_ONE / 16)).collect();
        assert_ne!(strata, (0..16).collect::<Vec<_>>(), "shuffled");
        strata.sort();
        assert_eq!(strata, (0..16).collect::<Vec<_>>());
        let jittered = blur(4, TimePattern::JitteredXyT).pixel_times(9, 4);
        for (j, &u) in jittered.iter().enumerate() {
            assert_eq!(u / (limits::TIME_ONE / 16), j as u32);
        }
    }

    #[test]
    fn pixels_and_seeds_draw_different_instants() {
        let b = blur(16, TimePattern::Random);
        assert_eq!(b.pixel_times(1, 1), b.pixel_times(1, 1));
        assert_ne!(b.pixel_times(1, 1), b.pixel_times(2, 1));
        let mut other = b.clone();
        other.seed = 4;
        assert_ne!(b.pixel_times(1, 1), other.pixel_times(1, 1));
    }

    #[test]
    fn instants_span_the_shutter() {
        let mut b = blur(1, TimePattern::Random);
        b.shutter = [limits::TIME_ONE / 4, limits::TIME_ONE / 2];
        assert_eq!(b.instant(0), 1 << 30);
        assert_eq!(b.instant(limits::TIME_ONE), 1 << 31);
    }
}
