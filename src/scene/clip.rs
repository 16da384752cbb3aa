//! Clip space (SPEC.md §16): vertices given as homogeneous (x, y, z, w),
//! the viewport that maps them onto the canvas, and the names of the
//! conventions a vertex post-processing stage chooses between.
//!
//! Names and numbers only, as everywhere in `scene/`: the reference and the
//! production rasterizer each clip, divide, snap and rasterize on their own.

use super::number::Number;

/// Where a clip-space scene lands on the canvas: the rectangle
/// [x, x + width] × [y, y + height] that normalized device coordinates
/// [−1, 1]² map onto (x_ndc = −1 at the left, y_ndc = −1 at the top, as in
/// Vulkan), and the depth range z_ndc ∈ [0, 1] maps onto.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub x: Number,
    pub y: Number,
    pub width: Number,
    pub height: Number,
    pub min_depth: Number,
    pub max_depth: Number,
}

impl Viewport {
    /// The whole canvas, depth range [0, 1].
    pub fn canvas(width: u32, height: u32) -> Viewport {
        Viewport {
            x: Number::ZERO,
            y: Number::ZERO,
            width: Number::from_int(i64::from(width)),
            height: Number::from_int(i64::from(height)),
            min_depth: Number::ZERO,
            max_depth: Number::ONE,
        }
    }
}

/// How the planes x = ±w and y = ±w are applied (SPEC.md §16.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClipXy {
    /// Not clipped: the primitive is rasterized whole, with homogeneous
    /// edge functions (Olano and Greer), and a sample outside the viewport
    /// rectangle is not covered.
    GuardBand,
    /// Clipped before the divide; the new vertices are divided, put through
    /// the viewport and snapped like any vertex.
    ClipThenSnap,
}

case_names!(ClipXy {
    GuardBand => "guard-band",
    ClipThenSnap => "clip-then-snap",
});

/// How the near and far planes (0 ≤ z ≤ w) are applied when depth clips
/// (SPEC.md §16.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClipZ {
    /// Clipped before the divide; the new vertices are snapped.
    ClipThenSnap,
    /// Not clipped: a sample whose exact depth is outside [0, 1] is not
    /// covered.
    PerSample,
}

case_names!(ClipZ {
    ClipThenSnap => "clip-then-snap",
    PerSample => "per-sample",
});

/// Depth clip or depth clamp (VK_EXT_depth_clip_enable, SPEC.md §16.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthMode {
    /// Primitives are clipped to 0 ≤ z ≤ w.
    Clip,
    /// Nothing is clipped by depth; each sample's depth is clamped to the
    /// viewport's depth range.
    Clamp,
}

case_names!(DepthMode {
    Clip => "clip",
    Clamp => "clamp",
});

/// Which positions depth and attributes are interpolated from
/// (SPEC.md §16.5): coverage always uses the snapped ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InterpolateFrom {
    /// The snapped screen positions, the ones coverage uses (D3D11's
    /// fixed-point set-up).
    Snapped,
    /// The exact projected positions before snapping, as a driver that
    /// sets its planes up in floating point from the divided vertices
    /// does (Mesa's llvmpipe and lavapipe, SPEC.md §16.10).
    Unsnapped,
}

case_names!(InterpolateFrom {
    Snapped => "snapped",
    Unsnapped => "unsnapped",
});

/// What the planes x = ±w and y = ±w do to a point (SPEC.md §17.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointClip {
    /// A point whose centre lies outside them is discarded whole
    /// ("popping"), as the Vulkan and OpenGL specifications clip points.
    Pop,
    /// They discard nothing: the square is drawn whatever its centre.
    GuardBand,
}

case_names!(PointClip {
    Pop => "pop",
    GuardBand => "guard-band",
});

/// What limits a kept point's square in clip space (SPEC.md §17.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointBounds {
    /// The canvas only: a square near the viewport's side reaches
    /// outside the viewport rectangle, as the specifications draw it.
    Canvas,
    /// The viewport rectangle too: only pixels whose centre lies in it
    /// (closed at its left and top, open at its right and bottom) are
    /// covered, as Mesa's llvmpipe and lavapipe draw (measured).
    Viewport,
}

case_names!(PointBounds {
    Canvas => "canvas",
    Viewport => "viewport",
});

/// The clip-space conventions of a case, with their defaults.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ClipRules {
    pub xy: ClipXy,
    pub z: ClipZ,
    pub depth: DepthMode,
    /// The positions values are interpolated from.
    pub values: InterpolateFrom,
    /// What the side planes do to a point.
    pub points: PointClip,
    /// What limits a kept point's square.
    pub bounds: PointBounds,
}

impl Default for ClipRules {
    fn default() -> Self {
        ClipRules {
            xy: ClipXy::GuardBand,
            z: ClipZ::ClipThenSnap,
            depth: DepthMode::Clip,
            values: InterpolateFrom::Snapped,
            points: PointClip::Pop,
            bounds: PointBounds::Canvas,
        }
    }
}

impl ClipRules {
    /// The conventions a clipping stage fixes, in words: `clip_xy`,
    /// `clip_z`, `interpolate_from`, `clip_points` and `point_bounds`
    /// (`depth` is always the case's).
    pub fn words(&self) -> String {
        format!(
            "clip_xy {}, clip_z {}, interpolate_from {}, clip_points {}, point_bounds {}",
            self.xy.name(),
            self.z.name(),
            self.values.name(),
            self.points.name(),
            self.bounds.name()
        )
    }

    /// Which of the six planes are clipped before the divide, in the order
    /// SPEC.md §16.3 clips them: near, far, left, right, top, bottom.
    pub fn clipped_planes(&self) -> [bool; 6] {
        let z = self.depth == DepthMode::Clip && self.z == ClipZ::ClipThenSnap;
        let xy = self.xy == ClipXy::ClipThenSnap;
        [z, z, xy, xy, xy, xy]
    }
}
