//! What a case expects of a rasterizer under test, and the pixels whose
//! time coverage it pins.

use super::conservative::ConservativePromise;
use super::number::Number;

/// What a case expects of a rasterizer under test.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expect {
    /// Samples whose coverage count may differ from the reference (default 0).
    pub max_mismatched_samples: u64,
    /// The primitives form a mesh: no hole inside it, no sample covered twice.
    pub watertight: bool,
    /// How many samples the reference covers, when the case pins it down.
    pub samples_covered: Option<u64>,
    /// Largest absolute interpolation error allowed, per attribute and depth.
    /// `None`: the default bound of SPEC.md, "Interpolation tolerance".
    pub max_abs_error: Option<f64>,
    /// Largest error in units in the last place of the exact value's f32.
    pub max_ulp_error: Option<f64>,
    /// Antialiased cases: the largest |resolved coverage − exact area| of
    /// any pixel.
    pub max_coverage_error: Option<f64>,
    /// Antialiased cases: the largest RMS coverage error over edge pixels
    /// (default: piglit's 0.333 · 0.62^log2(N) for sample patterns).
    pub max_coverage_rms: Option<f64>,
    /// Antialiased cases: the exact total area of the primitives, which the
    /// reference's per-pixel areas must sum to.
    pub area: Option<Number>,
    /// Moving scenes: the largest |time coverage − exact| of any pixel.
    pub max_time_error: Option<f64>,
    /// Moving scenes: the largest RMS time-coverage error over moving
    /// pixels (default 0.75·(M·N)^-1/2, SPEC.md §15.4).
    pub max_time_rms: Option<f64>,
    /// Moving scenes: exact time coverages of chosen pixels, which the
    /// reference must reproduce within its certified bound + 10^-12.
    pub time_coverage: Vec<TimePin>,
    /// Conservative scenes: the reference's classes, pinned (SPEC.md
    /// §19).
    pub conservative: Option<ConservativePromise>,
}

impl Expect {
    /// The expectations a scene in which something moves cannot be judged
    /// on (it is judged on time coverage only, SPEC.md §15.1), by their key
    /// in the case file: the reader refuses a case that gives one.
    pub fn sample_expectations(&self) -> Vec<&'static str> {
        [
            ("samples_covered", self.samples_covered.is_some()),
            ("watertight", self.watertight),
            ("max_mismatched_samples", self.max_mismatched_samples > 0),
            ("max_abs_error", self.max_abs_error.is_some()),
            ("max_ulp_error", self.max_ulp_error.is_some()),
            ("max_coverage_error", self.max_coverage_error.is_some()),
            ("max_coverage_rms", self.max_coverage_rms.is_some()),
            ("area", self.area.is_some()),
        ]
        .into_iter()
        .filter_map(|(key, given)| given.then_some(key))
        .collect()
    }
}

/// One pixel's time coverage as the case author computed it.
#[derive(Clone, Debug, PartialEq)]
pub struct TimePin {
    pub pixel: [u32; 2],
    pub value: Number,
}
