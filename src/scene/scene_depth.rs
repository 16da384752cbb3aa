//! What a scene's depth rules (SPEC.md §18) and depth values ask: whether
//! they need a real attachment, the magnitude and tolerance of its depths,
//! where polygon offset applies.

use super::depth::{DepthFormat, RELATIVE_BOUND};
use super::model::Scene;
use super::number::Number;
use super::primitive::Primitive;

impl Scene {
    /// Whether the scene states a depth rule of §18 (a format other than
    /// `exact`, or a polygon offset): only a rasterizer with a real depth
    /// attachment of that format can follow it. Every adapter that reads
    /// the fragment shader's depth refuses these scenes
    /// (`rasterizer::refuse_depth_rules`).
    pub fn depth_rules_need_attachment(&self) -> bool {
        self.rules.depth_format != DepthFormat::Exact || self.rules.depth_bias.is_some()
    }

    /// M of SPEC.md §6.3 for depth: the largest |z| of a vertex, or, in
    /// clip space, of the viewport's depth range (every depth written lies
    /// in [0, 1], whatever the clip z).
    pub fn depth_magnitude(&self) -> f64 {
        let largest = |values: &mut dyn Iterator<Item = &Number>| {
            values.map(|v| v.abs().to_f64_lossy()).fold(0.0, f64::max)
        };
        match &self.viewport {
            Some(v) => largest(&mut [&v.min_depth, &v.max_depth].into_iter()),
            None => largest(&mut self.vertices().map(|v| &v.z)),
        }
    }

    /// ε of SPEC.md §6.3 for depth: `expect.max_abs_error` when given,
    /// 2^-16 · max(1, M) otherwise.
    pub fn depth_tolerance(&self) -> f64 {
        self.expect
            .max_abs_error
            .unwrap_or(RELATIVE_BOUND * self.depth_magnitude().max(1.0))
    }

    /// Whether polygon offset applies to primitive `index`: triangles
    /// only (SPEC.md §18.2).
    pub fn offset_applies(&self, index: usize) -> bool {
        self.rules.depth_bias.is_some() && matches!(self.primitives[index], Primitive::Triangle(_))
    }
}
