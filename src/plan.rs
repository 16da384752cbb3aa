//! The effects planner: from a scene to the stages a frame needs.
//!
//! A scene pays only for what it asks for. Depth is interpolated only when a
//! vertex gives `z`; attributes only when vertices carry them; several
//! samples per pixel and a resolved coverage only with `effects.antialias`;
//! a time loop only when `effects.motion_blur` is declared *and* some
//! primitive moves, and then only for the primitives that move.

use crate::scene::{MotionBlur, Scene};

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
    /// The time loop, when something moves.
    pub motion: Option<MotionPlan>,
}

/// The time samples of a scene in which something moves (SPEC.md §15).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MotionPlan {
    pub blur: MotionBlur,
    /// Which primitives move, in scene order; the others are drawn once,
    /// with no time loop.
    pub moving: Vec<bool>,
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
        let motion = scene
            .effects
            .motion_blur
            .as_ref()
            .filter(|_| scene.moves())
            .map(|blur| MotionPlan {
                blur: blur.clone(),
                moving: scene.primitives.iter().map(|p| p.moves()).collect(),
            });
        Plan {
            samples_per_pixel: antialias.as_ref().map_or(1, |s| s.offsets.len() as u32),
            antialias,
            depth: scene.has_depth,
            attributes: scene.attribute_count,
            motion,
        }
    }

    /// Coverage only: one sample at the pixel centre, no depth, no
    /// attributes, no effects.
    pub fn coverage_only() -> Plan {
        Plan {
            samples_per_pixel: 1,
            antialias: None,
            depth: false,
            attributes: 0,
            motion: None,
        }
    }

    /// Whether any value beyond coverage is interpolated.
    pub fn interpolates(&self) -> bool {
        self.depth || self.attributes > 0
    }
}
