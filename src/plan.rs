//! The effects planner: from a scene to the stages a frame needs.
//!
//! A scene pays only for what it asks for. Depth is interpolated only when a
//! vertex gives `z`; attributes only when vertices carry them; several
//! samples per pixel and a resolved coverage only with `effects.antialias`.

use crate::scene::Scene;

/// The work a rasterizer has to do for one scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// Samples per pixel; 1 means the pixel centre.
    pub samples_per_pixel: u32,
    /// Where the samples lie, when the scene antialiases.
    pub antialias: Option<SamplePlan>,
    /// Interpolate depth.
    pub depth: bool,
    /// Attribute channels to interpolate.
    pub attributes: usize,
}

/// The samples of an antialiased scene (SPEC.md §14.2).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SamplePlan {
    /// Each sample's offset from its pixel's top-left corner, in units of
    /// 2^-position_bits pixel; sample s of a pixel is slot s of its run in
    /// the frame.
    pub offsets: Vec<[u32; 2]>,
    pub position_bits: u32,
    /// Sample only the pixels an edge touches (production's choice of
    /// method; the result is the same).
    pub adaptive: bool,
}

impl Plan {
    pub fn for_scene(scene: &Scene) -> Plan {
        let antialias = scene.effects.antialias.as_ref().map(|aa| SamplePlan {
            offsets: aa.offsets(),
            position_bits: aa.position_bits,
            adaptive: aa.adaptive,
        });
        Plan {
            samples_per_pixel: antialias.as_ref().map_or(1, |s| s.offsets.len() as u32),
            antialias,
            depth: scene.has_depth,
            attributes: scene.attribute_count,
        }
    }

    /// Whether any value beyond coverage is interpolated.
    pub fn interpolates(&self) -> bool {
        self.depth || self.attributes > 0
    }
}
