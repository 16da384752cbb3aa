//! What every rasterizer returns: per-sample coverage counts, the primitive
//! that wrote each sample last, and the interpolated depth and attributes.
//!
//! One sample per pixel, at its centre, until antialiasing arrives. Values
//! are stored as f64 so that one type holds both a candidate's f32 output
//! (widened exactly) and the reference's exact values (rounded to odd, see
//! `reference::exact`).

/// A rasterizer's output for one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// How many primitives cover each sample, row-major from the top-left.
    pub coverage: Vec<u16>,
    /// Index + 1 of the last primitive (in scene order) that covered each
    /// sample; 0 where none did.
    pub last: Vec<u32>,
    /// Depth of the last primitive at each sample, when the plan asks for it;
    /// 0 where uncovered.
    pub depth: Option<Vec<f64>>,
    /// One channel per attribute, each holding the last primitive's value at
    /// every sample; 0 where uncovered.
    pub attributes: Vec<Vec<f64>>,
}

impl Frame {
    /// An empty frame with room for what the plan asks for.
    pub fn new(width: u32, height: u32, depth: bool, attributes: usize) -> Frame {
        let n = width as usize * height as usize;
        Frame {
            width,
            height,
            coverage: vec![0; n],
            last: vec![0; n],
            depth: depth.then(|| vec![0.0; n]),
            attributes: vec![vec![0.0; n]; attributes],
        }
    }

    pub fn sample_count(&self) -> usize {
        self.coverage.len()
    }

    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// Samples covered at least once.
    pub fn covered_samples(&self) -> u64 {
        self.coverage.iter().filter(|&&c| c > 0).count() as u64
    }

    /// Records that primitive `primitive` (0-based) covers sample `i`.
    /// Returns the slot's index so the caller can write values.
    #[inline]
    pub fn hit(&mut self, i: usize, primitive: usize) {
        self.coverage[i] = self.coverage[i].saturating_add(1);
        self.last[i] = primitive as u32 + 1;
    }
}
