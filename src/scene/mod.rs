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
pub use rules::{Cull, FillRule, Interpolation, LastPixel, LineParameter, LineRule, Rules};

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
    Line(Line),
}

impl Primitive {
    pub fn vertices(&self) -> &[Vertex] {
        match self {
            Primitive::Triangle(t) => &t.vertices,
            Primitive::Line(l) => &l.vertices,
        }
    }

    pub fn vertices_mut(&mut self) -> &mut [Vertex] {
        match self {
            Primitive::Triangle(t) => &mut t.vertices,
            Primitive::Line(l) => &mut l.vertices,
        }
    }

    pub fn interpolation(&self) -> Interpolation {
        match self {
            Primitive::Triangle(t) => t.interpolation,
            Primitive::Line(l) => l.interpolation,
        }
    }
}

/// A line segment between two vertices, drawn under one of the line rules
/// of SPEC.md §4.
#[derive(Clone, Debug)]
pub struct Line {
    pub vertices: [Vertex; 2],
    pub rule: LineRule,
    /// Width in pixels for `rectangle` and `parallelogram` lines; 1 otherwise.
    pub width: Number,
    /// Whether a `midpoint` line draws the pixel at its second endpoint.
    pub last_pixel: LastPixel,
    /// How the interpolation parameter of a sample is found.
    pub parameter: LineParameter,
    pub interpolation: Interpolation,
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
    /// The triangles, each with its index among all primitives.
    pub fn triangles(&self) -> impl Iterator<Item = (usize, &Triangle)> {
        self.primitives
            .iter()
            .enumerate()
            .filter_map(|(i, p)| match p {
                Primitive::Triangle(t) => Some((i, t)),
                Primitive::Line(_) => None,
            })
    }

    /// Every vertex of every primitive.
    pub fn vertices(&self) -> impl Iterator<Item = &Vertex> {
        self.primitives.iter().flat_map(|p| p.vertices())
    }
}
