//! The effects planner: from a scene to the stages a frame needs.
//!
//! A scene pays only for what it asks for. Depth is interpolated only when a
//! vertex gives `z`; attributes only when vertices carry them. Antialiasing
//! and motion blur will add their stages here.

use crate::scene::Scene;

/// The work a rasterizer has to do for one scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Plan {
    /// Samples per pixel; 1 means the pixel centre.
    pub samples_per_pixel: u32,
    /// Interpolate depth.
    pub depth: bool,
    /// Attribute channels to interpolate.
    pub attributes: usize,
}

impl Plan {
    pub fn for_scene(scene: &Scene) -> Plan {
        Plan {
            samples_per_pixel: 1,
            depth: scene.has_depth,
            attributes: scene.attribute_count,
        }
    }

    /// Whether any value beyond coverage is interpolated.
    pub fn interpolates(&self) -> bool {
        self.depth || self.attributes > 0
    }
}
