//! The scene model: what a case asks to be drawn, and under which rules.
//!
//! This is the only code the reference and the production rasterizer share.
//! It holds exact numbers and names of conventions; it draws nothing and
//! decides nothing about coverage.

pub mod case;
pub mod number;
pub mod rules;

pub use case::{parse_case, CaseError, Limits};
pub use number::Number;
pub use rules::{Cull, FillRule, Interpolation, Rules};

/// One case: a canvas, rules, primitives, effects and expectations.
#[derive(Clone, Debug)]
pub struct Scene {
    pub name: String,
    pub description: String,
    pub canvas: Canvas,
    pub rules: Rules,
    pub primitives: Vec<Primitive>,
    pub effects: Effects,
    pub expect: Expect,
    /// Attributes every vertex carries (the same count for all vertices).
    pub attribute_count: usize,
    /// Whether any vertex gives `z`; only then is depth interpolated.
    pub has_depth: bool,
}

/// The pixel grid. Pixel (x, y) covers [x, x+1) × [y, y+1), y pointing down.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Canvas {
    pub width: u32,
    pub height: u32,
}

impl Canvas {
    pub fn pixel_count(&self) -> usize {
        self.width as usize * self.height as usize
    }
}

#[derive(Clone, Debug)]
pub enum Primitive {
    Triangle(Triangle),
}

#[derive(Clone, Debug)]
pub struct Triangle {
    pub vertices: [Vertex; 3],
    pub interpolation: Interpolation,
}

/// A vertex as written in the case, before any snapping.
#[derive(Clone, Debug)]
pub struct Vertex {
    pub x: Number,
    pub y: Number,
    /// Depth; 0 when the case gives none.
    pub z: Number,
    /// Clip-space w, used by perspective interpolation; 1 when not given.
    pub w: Number,
    pub attributes: Vec<Number>,
}

impl Vertex {
    pub fn at(x: Number, y: Number) -> Vertex {
        Vertex {
            x,
            y,
            z: Number::ZERO,
            w: Number::ONE,
            attributes: Vec::new(),
        }
    }
}

/// Effects a case turns on. Antialiasing and motion blur arrive with their
/// own issues; until then the object must be empty.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Effects {}

/// What a case expects of a rasterizer under test.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expect {
    /// Samples whose coverage count may differ from the reference (default 0).
    pub max_mismatched_samples: u64,
    /// The primitives form a mesh: no hole inside it, no sample covered twice.
    pub watertight: bool,
    /// How many samples the reference covers, when the case pins it down.
    pub samples_covered: Option<u64>,
    /// Largest absolute interpolation error allowed, per attribute and depth.
    /// `None`: the default bound of SPEC.md, "Interpolation tolerance".
    pub max_abs_error: Option<f64>,
    /// Largest error in units in the last place of the exact value's f32.
    pub max_ulp_error: Option<f64>,
}

impl Scene {
    pub fn triangles(&self) -> impl Iterator<Item = &Triangle> {
        self.primitives.iter().map(|p| match p {
            Primitive::Triangle(t) => t,
        })
    }
}
