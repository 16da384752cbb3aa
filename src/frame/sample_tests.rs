//! What a method of moving primitives spent on its time loop.

/// Sample tests of moving primitives: every (instant, sample) a method
/// tested, and how many of them were covered.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SampleTests {
    pub tests: u64,
    pub covered: u64,
}

impl SampleTests {
    /// Covered tests over all tests: the cost measure of stochastic
    /// rasterization (1 when no test was wasted).
    pub fn efficiency(&self) -> f64 {
        if self.tests == 0 {
            1.0
        } else {
            self.covered as f64 / self.tests as f64
        }
    }
}
