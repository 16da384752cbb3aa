//! The error statistics a per-pixel value is judged by against its exact
//! value, shared by antialiasing (resolved coverage, SPEC.md §14.3) and
//! time coverage (§15.4): the largest error and where, the RMS and bias over
//! the pixels that matter, their bounds, and the reasons a candidate fails
//! them, worded once.

use super::counted::counted;

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
                "{family}: {quantity} RMS {:.3e} over {} exceeds {:.3e} (bias {:+.3e}{worst})",
                self.rms,
                counted(
                    self.pixels,
                    &format!("{} pixel", self.kind),
                    &format!("{} pixels", self.kind)
                ),
                self.allowed_rms.unwrap_or(0.0),
                self.bias
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rms_reason_takes_the_number_of_its_pixels() {
        let over = |pixels| {
            ErrorBounds {
                family: "time",
                quantity: "time-coverage",
                max_error: 0.5,
                worst: "pixel (1, 2)".into(),
                allowed_error: None,
                rms: 0.5,
                bias: 0.5,
                pixels,
                kind: "moving",
                allowed_rms: Some(0.25),
                worst_in_rms: false,
            }
            .failures()
        };
        assert_eq!(
            over(1),
            ["time: time-coverage RMS 5.000e-1 over 1 moving pixel exceeds 2.500e-1 (bias +5.000e-1)"]
        );
        assert_eq!(
            over(3),
            ["time: time-coverage RMS 5.000e-1 over 3 moving pixels exceeds 2.500e-1 (bias +5.000e-1)"]
        );
    }
}
