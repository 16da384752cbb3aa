//! `foil-truncate` and `foil-truncate-undeclared`: production drawing every
//! vertex at ⌊x⌋, ⌊y⌋ (truncation to whole pixels, as two real 2D
//! libraries do, issue 40) whatever a case states. **Foils** that differ
//! only in what they declare (SPEC.md §3.2):
//!
//! - `foil-truncate` declares its truncation (`fixed_snapping`), so every
//!   case is judged against the reference drawn at truncated vertices: it
//!   passes every case production passes, a convention and not a failure;
//! - `foil-truncate-undeclared` draws the same frames and declares
//!   nothing, as a library whose adapter forgets to say so: judged at the
//!   case's own bits it fails wherever truncation moves a sample across an
//!   edge.
//!
//! Screen-space triangles, lines and polygons only: a clip-space vertex
//! is not in pixels, a point's square is not a vertex walk, and a moving
//! vertex's snapping is not what these foils are about.

use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer, Snapping};
use crate::scene::{Number, Scene};

/// Truncates to whole pixels; declares it or not.
#[derive(Clone, Copy, Debug)]
pub struct Truncate {
    declares: bool,
}

impl Truncate {
    /// `foil-truncate`: truncates and says so.
    pub const HONEST: Truncate = Truncate { declares: true };
    /// `foil-truncate-undeclared`: truncates and declares nothing.
    pub const UNDECLARED: Truncate = Truncate { declares: false };
}

impl Rasterizer for Truncate {
    fn name(&self) -> &str {
        if self.declares {
            "foil-truncate"
        } else {
            "foil-truncate-undeclared"
        }
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            motion_blur: false,
            clip_space: false,
            points: false,
            ..Production.capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Production.rasterize(&truncated(scene), plan)
    }

    fn fixed_snapping(&self) -> Option<Snapping> {
        self.declares.then_some(Snapping::Truncate)
    }
}

/// The scene with every vertex at ⌊x⌋, ⌊y⌋, exactly, and no further
/// snapping (whole pixels lie on every grid).
pub fn truncated(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        for c in [&mut v.x, &mut v.y] {
            *c = Number::from_rbig(RBig::from(c.as_rbig().floor()));
        }
    }
    s.rules.subpixel_bits = None;
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    #[test]
    fn a_vertex_at_two_point_nine_is_drawn_at_two() {
        let s = parse_case(
            r#"{"name": "t", "canvas": {"width": 8, "height": 8},
                "primitives": [{"triangle": [[2.9, 1.1], [6.5, -0.5], [0.99, 5]]}]}"#,
            "t",
            &Limits::default(),
        )
        .unwrap();
        let t = truncated(&s);
        let v = t.primitives[0].vertices();
        let got: Vec<String> = v
            .iter()
            .flat_map(|v| [v.x.to_exact_string(), v.y.to_exact_string()])
            .collect();
        assert_eq!(got, ["2", "1", "6", "-1", "0", "5"]);
        assert_eq!(t.rules.subpixel_bits, None);
    }
}
