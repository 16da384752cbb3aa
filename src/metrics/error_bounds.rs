//! The error statistics a per-pixel value is judged by against its exact
//! value, shared by antialiasing (resolved coverage, SPEC.md §14.3) and
//! time coverage (§15.4): the largest error and where, the RMS and bias over
//! the pixels that matter, their bounds, and the reasons a candidate fails
//! them, worded once.

/// One family's error statistics and bounds, in the words its reasons use.
pub struct ErrorBounds<'a> {
    /// The family the reasons start with: `antialias`, `time`.
    pub family: &'a str,
    /// What is measured: `coverage`, `time-coverage`.
    pub quantity: &'a str,
    /// Largest |candidate − exact|, and where (`pixel (x, y)`, with the
    /// values there when the family shows them).
    pub max_error: f64,
    pub worst: String,
    pub allowed_error: Option<f64>,
    /// RMS and bias (mean signed error) over `pixels` pixels of a `kind`
    /// (`edge`, `moving`).
    pub rms: f64,
    pub bias: f64,
    pub pixels: u64,
    pub kind: &'a str,
    pub allowed_rms: Option<f64>,
    /// Whether the RMS reason names the worst pixel too.
    pub worst_in_rms: bool,
}

/// Whether `value` is within `bound` (no bound: always).
pub fn within(value: f64, bound: Option<f64>) -> bool {
    bound.is_none_or(|b| value <= b)
}

impl ErrorBounds<'_> {
    /// Why the statistics break their bounds; empty when they hold.
    pub fn failures(&self) -> Vec<String> {
        let (family, quantity, worst) = (self.family, self.quantity, &self.worst);
        let mut out = Vec::new();
        if !within(self.max_error, self.allowed_error) {
            out.push(format!(
                "{family}: max {quantity} error {:.3e} at {worst} exceeds {:.3e}",
                self.max_error,
                self.allowed_error.unwrap_or(0.0)
            ));
        }
        if !within(self.rms, self.allowed_rms) {
            let worst = if self.worst_in_rms {
                format!("; worst {worst}")
            } else {
                String::new()
            };
            out.push(format!(
                "{family}: {quantity} RMS {:.3e} over {} {} pixels exceeds {:.3e} (bias {:+.3e}{worst})",
                self.rms,
                self.pixels,
                self.kind,
                self.allowed_rms.unwrap_or(0.0),
                self.bias
            ));
        }
        out
    }
}
