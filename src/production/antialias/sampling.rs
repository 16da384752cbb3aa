//! How an antialiased scene's samples are decided ([`Sampling`]: full,
//! adaptive or refined), and the samples as the primitives are drawn.

use crate::plan::{Plan, SamplePlan};
use crate::production::fixed::Format;

/// How the samples of a primitive's pixels are decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    /// Every sample of every pixel in the primitive's footprint is tested.
    Full,
    /// Pixels wholly inside or outside, judged strictly from their corners,
    /// take every sample or none untested; the others are tested sample by
    /// sample. The same mask as [`Sampling::Full`].
    Adaptive,
    /// A quarter of the samples first (at least one, spread through the
    /// pattern); when they agree the pixel takes their answer for every
    /// sample, otherwise every sample is tested. Inexact: a feature thinner
    /// than the spacing of the first samples can be missed.
    Refine,
    /// A deliberately wrong [`Sampling::Adaptive`] that classifies corners
    /// non-strictly, for the test that shows the comparison catches it.
    #[cfg(test)]
    NonStrictCorners,
}

impl Sampling {
    /// Production's exact method for a plan: adaptive when it asks.
    pub fn for_plan(plan: &Plan) -> Sampling {
        match &plan.antialias {
            Some(samples) if samples.adaptive => Sampling::Adaptive,
            _ => Sampling::Full,
        }
    }
}

/// An antialiased scene's samples as the primitives are drawn.
#[derive(Clone, Debug)]
pub struct Samples<'a> {
    pub plan: &'a SamplePlan,
    pub sampling: Sampling,
}

impl Samples<'_> {
    /// Samples per pixel.
    pub fn count(&self) -> usize {
        self.plan.offsets.len()
    }

    /// The offsets from the pixel's top-left corner in units of `format`,
    /// which has at least `position_bits` fraction bits.
    pub fn offsets_in(&self, format: Format) -> Vec<[i64; 2]> {
        assert!(format.frac_bits >= self.plan.position_bits);
        let shift = format.frac_bits - self.plan.position_bits;
        self.plan
            .offsets
            .iter()
            .map(|o| [i64::from(o[0]) << shift, i64::from(o[1]) << shift])
            .collect()
    }
}
