//! The rules a case states: snapping, fill rule, culling, interpolation, and
//! the documented limits on every input.
//!
//! These are names for conventions, not code that applies them: each
//! rasterizer implements the rules on its own (see SPEC.md for their meaning).

use std::fmt;

use super::clip::ClipRules;
use super::depth::{DepthBias, DepthFormat};

/// Which edges own the samples that lie exactly on them.
///
/// Named after the D3D11 top-left rule (D3D11.3 functional spec §3.4.2.1)
/// and its mirror images, so that third-party conventions can be stated and
/// checked. In every rule but [`FillRule::AllEdges`], a horizontal edge is
/// either "top" (the triangle lies below it, y pointing down) or "bottom",
/// and any other edge is either "left" (the triangle lies to its right) or
/// "right".
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// D3D11 and Vulkan implementations: top and left edges own their samples.
    TopLeft,
    BottomRight,
    TopRight,
    BottomLeft,
    /// Every edge owns its samples: closed triangles, not watertight.
    AllEdges,
}

case_names!(FillRule {
    TopLeft => "top-left",
    BottomRight => "bottom-right",
    TopRight => "top-right",
    BottomLeft => "bottom-left",
    AllEdges => "all-edges",
});

impl FillRule {
    /// The four rules that each assign every shared-edge sample to exactly
    /// one triangle. A sample every one of them puts inside a mesh lies in
    /// the mesh's interior (SPEC.md, "Watertightness").
    pub const CONSISTENT: [FillRule; 4] = [
        FillRule::TopLeft,
        FillRule::BottomRight,
        FillRule::TopRight,
        FillRule::BottomLeft,
    ];

    /// Whether horizontal edges with the triangle below them own their samples.
    pub fn owns_top(self) -> bool {
        matches!(
            self,
            FillRule::TopLeft | FillRule::TopRight | FillRule::AllEdges
        )
    }

    /// Whether horizontal edges with the triangle above them own their samples.
    pub fn owns_bottom(self) -> bool {
        matches!(
            self,
            FillRule::BottomRight | FillRule::BottomLeft | FillRule::AllEdges
        )
    }

    /// Whether non-horizontal edges with the triangle to their right own their samples.
    pub fn owns_left(self) -> bool {
        matches!(
            self,
            FillRule::TopLeft | FillRule::BottomLeft | FillRule::AllEdges
        )
    }

    /// Whether non-horizontal edges with the triangle to their left own their samples.
    pub fn owns_right(self) -> bool {
        matches!(
            self,
            FillRule::BottomRight | FillRule::TopRight | FillRule::AllEdges
        )
    }

    /// The rule that gives every shared sample to the other triangle.
    pub fn flipped(self) -> FillRule {
        match self {
            FillRule::TopLeft => FillRule::BottomRight,
            FillRule::BottomRight => FillRule::TopLeft,
            FillRule::TopRight => FillRule::BottomLeft,
            FillRule::BottomLeft => FillRule::TopRight,
            FillRule::AllEdges => FillRule::AllEdges,
        }
    }
}

/// The tie rule a rasterizer declares it follows whatever a case states
/// (a program's `conventions.fill_rule`, a profile's `fill_rule`): one of
/// the fill rules, or `none`, no consistent rule at all (SPEC.md §3.1.1).
///
/// `none` is a declaration, not a rule a case can state: a sample exactly
/// on an edge may go to either side, so the reference decides no tie for
/// such a rasterizer; it is judged exactly everywhere else, and its ties
/// are counted apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeclaredRule {
    Fill(FillRule),
    /// No consistent tie rule (libraries whose ties go by slope, or by
    /// float rounding of an exact zero).
    NoTieRule,
}

impl DeclaredRule {
    /// The word for [`DeclaredRule::NoTieRule`].
    pub const NONE: &'static str = "none";

    /// Every word a declaration may use: the fill rules', then `none`.
    pub const NAMES: [&'static str; FillRule::NAMES.len() + 1] = [
        "top-left",
        "bottom-right",
        "top-right",
        "bottom-left",
        "all-edges",
        DeclaredRule::NONE,
    ];

    pub fn from_name(name: &str) -> Option<DeclaredRule> {
        if name == DeclaredRule::NONE {
            return Some(DeclaredRule::NoTieRule);
        }
        FillRule::from_name(name).map(DeclaredRule::Fill)
    }

    pub fn name(self) -> &'static str {
        match self {
            DeclaredRule::Fill(rule) => rule.name(),
            DeclaredRule::NoTieRule => DeclaredRule::NONE,
        }
    }

    /// The fill rule it names; `None` for `none`.
    pub fn fill_rule(self) -> Option<FillRule> {
        match self {
            DeclaredRule::Fill(rule) => Some(rule),
            DeclaredRule::NoTieRule => None,
        }
    }
}

impl fmt::Display for DeclaredRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for FillRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Which triangles are discarded by their winding as seen on screen (y down).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cull {
    None,
    /// Discard triangles whose vertices run clockwise on screen.
    Clockwise,
    /// Discard triangles whose vertices run counter-clockwise on screen.
    CounterClockwise,
}

case_names!(Cull {
    None => "none",
    Clockwise => "cw",
    CounterClockwise => "ccw",
});

impl Cull {
    /// Whether a triangle is discarded, from the sign of
    /// (b − a) × (c − a) in screen coordinates (y down): positive is
    /// clockwise on screen. A zero-area triangle is never culled here (it
    /// draws nothing anyway).
    pub fn discards(self, cross: std::cmp::Ordering) -> bool {
        use std::cmp::Ordering::{Greater, Less};
        match self {
            Cull::None => false,
            Cull::Clockwise => cross == Greater,
            Cull::CounterClockwise => cross == Less,
        }
    }
}

/// Which points a polygon fills, from their winding number: the number of
/// times the contours wind around the point, counting direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolygonFill {
    /// Odd winding numbers are inside (SVG `evenodd`).
    EvenOdd,
    /// Non-zero winding numbers are inside (SVG `nonzero`, the default).
    NonZero,
}

case_names!(PolygonFill {
    EvenOdd => "even-odd",
    NonZero => "nonzero",
});

impl PolygonFill {
    /// Whether a point of winding number `winding` is filled.
    pub fn fills(self, winding: i64) -> bool {
        match self {
            PolygonFill::EvenOdd => winding % 2 != 0,
            PolygonFill::NonZero => winding != 0,
        }
    }
}

/// How a primitive's attributes vary across it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// Barycentric weights divided by each vertex's w (perspective-correct).
    Perspective,
    /// Screen-space barycentric weights.
    Linear,
    /// The provoking vertex's values everywhere (the first vertex unless
    /// the case's `provoking_vertex` is `last`).
    Flat,
}

case_names!(Interpolation {
    Perspective => "perspective",
    Linear => "linear",
    Flat => "flat",
});

/// How a line decides which pixels it lights (SPEC.md §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LineRule {
    /// The pixel nearest the line in each column (x-major) or row
    /// (y-major): the midpoint/Bresenham algorithm.
    Midpoint,
    /// D3D11's and OpenGL's aliased line: a pixel is lit when the segment
    /// leaves its diamond.
    DiamondExit,
    /// A rectangle of the given width centred on the segment, sampled at
    /// pixel centres under the fill rule.
    Rectangle,
    /// The segment swept along the minor axis by the given width (the
    /// non-strict wide line), sampled under the fill rule.
    Parallelogram,
}

case_names!(LineRule {
    Midpoint => "midpoint",
    DiamondExit => "diamond-exit",
    Rectangle => "rectangle",
    Parallelogram => "parallelogram",
});

impl LineRule {
    /// Whether the rule takes a `width`.
    pub fn is_wide(self) -> bool {
        matches!(self, LineRule::Rectangle | LineRule::Parallelogram)
    }
}

/// Whether a midpoint line includes the pixel at its second endpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LastPixel {
    Include,
    /// Half-open, as Vulkan's Bresenham lines: strips join without doubles.
    Exclude,
}

impl LastPixel {
    pub fn from_name(name: &str) -> Option<LastPixel> {
        match name {
            "include" => Some(LastPixel::Include),
            "exclude" => Some(LastPixel::Exclude),
            _ => None,
        }
    }
}

/// Where along a line a sample's attributes are taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LineParameter {
    /// From the sample's position along the major axis, as the incremental
    /// midpoint algorithm steps it.
    Major,
    /// From the exact projection of the sample onto the segment.
    Projected,
}

impl LineParameter {
    pub fn from_name(name: &str) -> Option<LineParameter> {
        match name {
            "major" => Some(LineParameter::Major),
            "projected" => Some(LineParameter::Projected),
            _ => None,
        }
    }
}

/// Whether a line's parameter t is clamped to [0, 1] (SPEC.md §5.1). A
/// case states no clamp of its own: its lines are `Clamped`. `Unclamped`
/// is a convention a rasterizer declares (the formula of Vulkan's "Basic
/// Line Segment Rasterization" and of GL 4.6 §14.5.1 has no clamp, so a
/// fragment whose centre lies before the first end or past the last one
/// extrapolates), judged by restating the case under it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LineClamp {
    #[default]
    Clamped,
    Unclamped,
}

impl LineClamp {
    pub fn name(self) -> &'static str {
        match self {
            LineClamp::Clamped => "clamped",
            LineClamp::Unclamped => "unclamped",
        }
    }
}

impl LineParameter {
    pub fn name(self) -> &'static str {
        match self {
            LineParameter::Major => "major",
            LineParameter::Projected => "projected",
        }
    }
}

/// A line parameter a rasterizer follows whatever a case states, for the
/// lines of one rule (SPEC.md §5.1): where along the line t is taken, and
/// whether it is clamped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LineT {
    pub parameter: LineParameter,
    pub clamp: LineClamp,
}

impl LineT {
    /// In words: "projected" or "major", with ", unclamped" where it is.
    pub fn words(self) -> String {
        match self.clamp {
            LineClamp::Clamped => self.parameter.name().to_owned(),
            LineClamp::Unclamped => format!("{}, unclamped", self.parameter.name()),
        }
    }

    /// Its name in a report: `major`, `projected`, `major-unclamped`,
    /// `projected-unclamped`.
    pub fn name(self) -> &'static str {
        match (self.parameter, self.clamp) {
            (LineParameter::Major, LineClamp::Clamped) => "major",
            (LineParameter::Projected, LineClamp::Clamped) => "projected",
            (LineParameter::Major, LineClamp::Unclamped) => "major-unclamped",
            (LineParameter::Projected, LineClamp::Unclamped) => "projected-unclamped",
        }
    }
}

/// Which vertex of a primitive gives a `flat` primitive its values
/// (SPEC.md §5): Vulkan's default and `VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT`,
/// OpenGL's `glProvokingVertex`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ProvokingVertex {
    First,
    Last,
}

case_names!(ProvokingVertex {
    First => "first",
    Last => "last",
});

impl ProvokingVertex {
    /// The index of the provoking vertex among `count` vertices.
    pub fn index(self, count: usize) -> usize {
        match self {
            ProvokingVertex::First => 0,
            ProvokingVertex::Last => count - 1,
        }
    }
}

/// Snapping, fill rule, culling, the provoking vertex and the clip-space
/// conventions for a whole case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rules {
    /// Vertices snap to multiples of 2^-bits, ties to even; `None` keeps the
    /// exact coordinates ("ideal geometry").
    pub subpixel_bits: Option<u32>,
    pub fill_rule: FillRule,
    pub cull: Cull,
    pub provoking_vertex: ProvokingVertex,
    /// How a clip-space scene is clipped (SPEC.md §16); screen-space
    /// scenes keep the defaults.
    pub clip: ClipRules,
    /// How depth is stored (SPEC.md §18.1); `exact` unless the case says.
    pub depth_format: DepthFormat,
    /// Polygon offset (SPEC.md §18.2), when the case gives one.
    pub depth_bias: Option<DepthBias>,
    /// Whether lines clamp t to [0, 1] (SPEC.md §5.1): always `Clamped` in
    /// a case; `Unclamped` only in a case restated under a rasterizer's
    /// declared line parameter.
    pub line_clamp: LineClamp,
}

impl Default for Rules {
    fn default() -> Self {
        Rules {
            subpixel_bits: Some(8),
            fill_rule: FillRule::TopLeft,
            cull: Cull::None,
            provoking_vertex: ProvokingVertex::First,
            clip: ClipRules::default(),
            depth_format: DepthFormat::Exact,
            depth_bias: None,
            line_clamp: LineClamp::Clamped,
        }
    }
}

/// Input limits. Every bound the rasterizers rely on for freedom from
/// overflow derives from these constants; see SPEC.md, "Limits".
pub mod limits {
    /// |x| and |y| of every vertex, in pixels, before and after snapping:
    /// D3D11's viewport range [-32768, 32767] plus one, so that a guard band
    /// reaching ±32768 can be written.
    pub const COORD_LIMIT: i64 = 1 << 15;
    /// Largest `subpixel_bits`.
    pub const MAX_SUBPIXEL_BITS: u32 = 16;
    /// Largest canvas side, in pixels.
    pub const MAX_CANVAS_SIDE: u32 = 1 << 14;
    /// Default largest canvas area, in pixels (a 4096 × 4096 canvas).
    pub const DEFAULT_MAX_CANVAS_PIXELS: u64 = 1 << 24;
    /// Default largest number of primitives in one case.
    pub const DEFAULT_MAX_PRIMITIVES: usize = 100_000;
    /// Default largest number of sample points in one case (pixels ×
    /// spatial samples × time samples): 2^26, a 4096² canvas at 4×, whose
    /// frame of coverage counts and owners takes 384 MiB.
    pub const DEFAULT_MAX_SAMPLES: u64 = 1 << 26;
    /// Default largest case file, in bytes: checked from the file's size
    /// before it is read (reading holds about 33 times the file in memory).
    /// The largest bundled case is under 20 KiB.
    pub const DEFAULT_MAX_CASE_BYTES: u64 = 16 << 20;
    /// Default memory one case's frames may take, in bytes: the
    /// reference's frame, a working copy, and each candidate's, estimated
    /// from the scene before any is allocated ([`crate::frame::Frame::estimated_bytes`]).
    /// 4 GiB holds a case at `DEFAULT_MAX_SAMPLES` with depth and a few
    /// attributes for one candidate; with 16 attributes such a case needs
    /// about 38 GiB, and gets a limit verdict instead of ending the run.
    pub const DEFAULT_MAX_CASE_MEMORY: u64 = 4 << 30;
    /// Default wall time per rasterizer and case.
    pub const DEFAULT_CASE_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(60);
    /// Largest number of attributes a vertex may carry.
    pub const MAX_ATTRIBUTES: usize = 16;
    /// |attribute| and |z| bound, so that every f32 pipeline stays finite.
    pub const VALUE_LIMIT: i64 = 1_000_000_000_000;
    /// |x|, |y|, |z| and |w| of a clip-space vertex (SPEC.md §16.1).
    pub const CLIP_LIMIT: i64 = 1_000_000;
    /// w lies in [1/W_LIMIT, W_LIMIT].
    pub const W_LIMIT: i64 = 1_000_000;
    /// Largest width of a wide line, in pixels.
    pub const MAX_LINE_WIDTH: i64 = 1024;
    /// Largest side of a point's square, in pixels (SPEC.md §17.1).
    pub const MAX_POINT_SIZE: i64 = 1024;
    /// Largest number of vertices of one polygon, all contours together.
    pub const MAX_POLYGON_VERTICES: usize = 4096;

    const _: () = assert!(MAX_CANVAS_SIDE as i64 <= COORD_LIMIT);
}

#[cfg(test)]
mod declared_rule_tests {
    use super::{DeclaredRule, FillRule};

    #[test]
    fn every_fill_rule_word_then_none() {
        assert_eq!(
            &DeclaredRule::NAMES[..FillRule::NAMES.len()],
            &FillRule::NAMES[..]
        );
        for name in DeclaredRule::NAMES {
            assert_eq!(
                DeclaredRule::from_name(name).map(DeclaredRule::name),
                Some(name)
            );
        }
        assert_eq!(
            DeclaredRule::from_name("none"),
            Some(DeclaredRule::NoTieRule)
        );
        assert_eq!(DeclaredRule::NoTieRule.fill_rule(), None);
    }
}
