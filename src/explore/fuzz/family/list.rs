//! The eight [`Family`]s the fuzzer generates, by name.

/// What the fuzzer generates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Random triangles, some sharing edges.
    Triangles,
    /// Lines of every rule, some in strips.
    Lines,
    /// Watertight meshes, with `expect.watertight: true`.
    Meshes,
    /// Polygons of one to three contours (self-intersecting, holes, doubled
    /// and repeated vertices) under both fills, with a triangle or two.
    Polygons,
    /// Triangles, polygons and parallelogram lines under
    /// `effects.antialias` (every pattern, 1 to 256 samples, adaptive or
    /// not, position bits 4 to 16).
    Antialias,
    /// Moving triangles and parallelogram lines under
    /// `effects.motion_blur` (SPEC.md §15): translations, rotations,
    /// collapses through a point, vertices through sample centres, winding
    /// flips, double roots, vanishing τ² coefficients; every time pattern,
    /// 1 to 64 time samples, parts of the shutter, sometimes antialiased.
    Motion,
    /// Triangles in clip space (SPEC.md §16): vertices behind the eye, on
    /// w = 0, across the near and far planes, extreme ratios of w; every
    /// clip convention, depth clip or clamp, either provoking vertex.
    Clip,
    /// Triangles drawn conservatively (SPEC.md §19): slivers, needles,
    /// corner and border touches, degenerate and far-away triangles, both
    /// modes, several uncertainties, the fully-covered flag on and off.
    Conservative,
}

impl Family {
    pub const ALL: [Family; 8] = [
        Family::Triangles,
        Family::Meshes,
        Family::Lines,
        Family::Polygons,
        Family::Antialias,
        Family::Motion,
        Family::Clip,
        Family::Conservative,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Family::Triangles => "triangles",
            Family::Lines => "lines",
            Family::Meshes => "meshes",
            Family::Polygons => "polygons",
            Family::Antialias => "antialias",
            Family::Motion => "motion",
            Family::Clip => "clip",
            Family::Conservative => "conservative",
        }
    }

    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }
}
