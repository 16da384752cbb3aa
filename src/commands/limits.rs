//! The resource-limit flags every command that reads cases shares
//! (SPEC.md §8), and their conversion to [`Limits`].

use clap::Args;

use crate::scene::Limits;

#[derive(Args)]
pub struct LimitArgs {
    /// Largest canvas, in pixels.
    #[arg(long, default_value_t = Limits::default().max_canvas_pixels)]
    pub max_canvas_pixels: u64,
    /// Largest number of primitives in one case.
    #[arg(long, default_value_t = Limits::default().max_primitives)]
    pub max_primitives: usize,
    /// Largest number of sample points in one case: pixels × samples per
    /// pixel × time samples (these only when something moves).
    #[arg(long, default_value_t = Limits::default().max_samples)]
    pub max_samples: u64,
    /// Largest case file, in bytes, checked before it is read.
    #[arg(long, value_name = "BYTES", default_value_t = Limits::default().max_case_bytes)]
    pub max_case_bytes: u64,
    /// Memory one case may take, in bytes, estimated from the scene
    /// before anything is allocated: the reference's frame, a working
    /// copy, one frame per candidate, and each external program's answer
    /// line (its output limit).
    #[arg(long, value_name = "BYTES", default_value_t = Limits::default().max_case_memory)]
    pub max_case_memory: u64,
    /// Seconds each rasterizer (the reference, then each candidate) may
    /// spend on one case; 0 for no limit. A case over it is an error.
    #[arg(long, value_name = "SECONDS", default_value_t = default_case_timeout(), value_parser = seconds)]
    pub case_timeout: f64,
}

/// A number of seconds: finite and not negative.
fn seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if (0.0..1e9).contains(&s) => Ok(s),
        _ => Err(format!(
            "expected a number of seconds (0 for no limit), got {text:?}"
        )),
    }
}

fn default_case_timeout() -> f64 {
    Limits::default()
        .case_timeout
        .map_or(0.0, |d| d.as_secs_f64())
}

impl LimitArgs {
    /// The limits these flags set.
    pub fn limits(&self) -> Limits {
        let seconds = self.case_timeout;
        Limits {
            max_canvas_pixels: self.max_canvas_pixels,
            max_primitives: self.max_primitives,
            max_samples: self.max_samples,
            max_case_bytes: self.max_case_bytes,
            max_case_memory: self.max_case_memory,
            case_timeout: (seconds > 0.0).then(|| std::time::Duration::from_secs_f64(seconds)),
        }
    }
}
