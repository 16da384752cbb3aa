//! The resource limits a run may tighten or relax (SPEC.md, "Limits").

use crate::scene::rules::limits;

/// Resource limits that a run may tighten or relax (SPEC.md, "Limits").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub max_canvas_pixels: u64,
    pub max_primitives: usize,
    /// Sample points per case: pixels × spatial samples × time samples
    /// (the last only when something moves). It bounds the frames'
    /// memory and the work of each primitive.
    pub max_samples: u64,
    /// Bytes of one case file, checked before it is read (`--max-case-bytes`).
    pub max_case_bytes: u64,
    /// Bytes one case may take, estimated before anything is allocated
    /// (`--max-case-memory`): its frames and each external program's
    /// answer line, the one budget of SPEC.md §8; enforced by the runner,
    /// not the reader.
    pub max_case_memory: u64,
    /// Wall time each rasterizer (the reference, then each candidate) may
    /// spend on one case; `None` for no limit. Not a property of the file:
    /// the reader ignores it, the runner enforces it ([`crate::deadline`]).
    pub case_timeout: Option<std::time::Duration>,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_canvas_pixels: limits::DEFAULT_MAX_CANVAS_PIXELS,
            max_primitives: limits::DEFAULT_MAX_PRIMITIVES,
            max_samples: limits::DEFAULT_MAX_SAMPLES,
            max_case_bytes: limits::DEFAULT_MAX_CASE_BYTES,
            max_case_memory: limits::DEFAULT_MAX_CASE_MEMORY,
            case_timeout: Some(limits::DEFAULT_CASE_TIMEOUT),
        }
    }
}
