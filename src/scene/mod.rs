//! The scene model: what a case asks to be drawn, and under which rules.
//!
//! This is the only code the reference and the production rasterizer share.
//! It holds exact numbers and names of conventions; it draws nothing and
//! decides nothing about coverage.

/// The words a case file uses for a closed set of conventions, from one
/// list: `ALL` in the order given, `name`, and its inverse `from_name`.
macro_rules! case_names {
    ($ty:ident { $($variant:ident => $name:literal),+ $(,)? }) => {
        impl $ty {
            /// Every value, in the documented order.
            pub const ALL: [$ty; [$($name),+].len()] = [$($ty::$variant),+];

            /// Every value's word, in the same order (for error messages).
            pub const NAMES: [&'static str; [$($name),+].len()] = [$($name),+];

            /// The word a case file uses for this value.
            pub fn name(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),+
                }
            }

            /// The value a case file's word names, if any.
            pub fn from_name(name: &str) -> Option<$ty> {
                $ty::ALL.into_iter().find(|v| v.name() == name)
            }
        }
    };
}

pub mod case;
pub mod clip;
pub mod depth;
pub mod number;
pub mod rules;
pub mod samples;
pub mod time;

pub use case::{parse_case, CaseError, Limits};
pub use clip::{
    ClipRules, ClipXy, ClipZ, DepthMode, InterpolateFrom, PointBounds, PointClip, Viewport,
};
pub use depth::{DepthBias, DepthFormat};
pub use number::Number;
pub use rules::{
    Cull, FillRule, Interpolation, LastPixel, LineParameter, LineRule, PolygonFill,
    ProvokingVertex, Rules,
};
pub use samples::{Antialias, Pattern};
pub use time::{MotionBlur, TimePattern};

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
    /// Whether any vertex gives `z`, or the scene is in clip space; only
    /// then is depth interpolated.
    pub has_depth: bool,
    /// `Some` when every vertex is in clip space (SPEC.md §16): its x, y,
    /// z and w are homogeneous clip coordinates, mapped onto the canvas by
    /// this viewport after clipping. `None`: screen space, as in §2.
    pub viewport: Option<Viewport>,
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
    Polygon(Polygon),
    Point(Point),
}

impl Primitive {
    pub fn vertices(&self) -> &[Vertex] {
        match self {
            Primitive::Triangle(t) => &t.vertices,
            Primitive::Line(l) => &l.vertices,
            Primitive::Polygon(p) => &p.vertices,
            Primitive::Point(p) => &p.vertices,
        }
    }

    pub fn vertices_mut(&mut self) -> &mut [Vertex] {
        match self {
            Primitive::Triangle(t) => &mut t.vertices,
            Primitive::Line(l) => &mut l.vertices,
            Primitive::Polygon(p) => &mut p.vertices,
            Primitive::Point(p) => &mut p.vertices,
        }
    }

    pub fn interpolation(&self) -> Interpolation {
        match self {
            Primitive::Triangle(t) => t.interpolation,
            Primitive::Line(l) => l.interpolation,
            Primitive::Polygon(_) => Interpolation::Linear,
            Primitive::Point(_) => Interpolation::Flat,
        }
    }

    /// Whether any vertex moves during the shutter (SPEC.md §15.1).
    pub fn moves(&self) -> bool {
        self.vertices().iter().any(Vertex::moves)
    }

    /// The word a case file uses for this kind of primitive.
    pub fn kind(&self) -> &'static str {
        match self {
            Primitive::Triangle(_) => "triangle",
            Primitive::Line(_) => "line",
            Primitive::Polygon(_) => "polygon",
            Primitive::Point(_) => "point",
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

/// A polygon of one or more closed contours (holes are contours too),
/// filled under the even-odd or nonzero winding rule (SPEC.md §14.1).
/// Its vertices carry positions only.
#[derive(Clone, Debug)]
pub struct Polygon {
    /// Every contour's vertices, one contour after another.
    pub vertices: Vec<Vertex>,
    /// Where each contour ends in `vertices` (exclusive), in order.
    pub contour_ends: Vec<usize>,
    pub fill: PolygonFill,
}

impl Polygon {
    /// Each contour's vertices; the last vertex joins the first.
    pub fn contours(&self) -> impl Iterator<Item = &[Vertex]> {
        let starts = std::iter::once(0).chain(self.contour_ends.iter().copied());
        starts
            .zip(&self.contour_ends)
            .map(|(start, &end)| &self.vertices[start..end])
    }

    /// Every directed edge, contour by contour: (from, to).
    pub fn edges(&self) -> impl Iterator<Item = (&Vertex, &Vertex)> {
        self.contours()
            .flat_map(|c| c.iter().zip(c.iter().cycle().skip(1)).take(c.len()))
    }
}

#[derive(Clone, Debug)]
pub struct Triangle {
    pub vertices: [Vertex; 3],
    pub interpolation: Interpolation,
}

/// A point: the square of side `size` centred on its snapped position,
/// with the vertex's depth and attributes everywhere (SPEC.md §17).
#[derive(Clone, Debug)]
pub struct Point {
    pub vertices: [Vertex; 1],
    /// The square's side in pixels, exact, in (0, 1024].
    pub size: Number,
}

/// A vertex as written in the case, before any snapping. In a clip-space
/// scene (`Scene::viewport` is `Some`), x, y, z and w are its clip
/// coordinates.
#[derive(Clone, Debug)]
pub struct Vertex {
    pub x: Number,
    pub y: Number,
    /// Depth; 0 when the case gives none.
    pub z: Number,
    /// Clip-space w, used by perspective interpolation; 1 when not given.
    pub w: Number,
    pub attributes: Vec<Number>,
    /// A moving vertex's position at shutter close, τ = 1 (SPEC.md §15.1);
    /// `x` and `y` are then its position at τ = 0 (`from`).
    pub to: Option<Box<[Number; 2]>>,
}

impl Vertex {
    pub fn at(x: Number, y: Number) -> Vertex {
        Vertex {
            x,
            y,
            z: Number::ZERO,
            w: Number::ONE,
            attributes: Vec::new(),
            to: None,
        }
    }

    /// Whether the vertex is somewhere else at shutter close than at open.
    pub fn moves(&self) -> bool {
        self.to
            .as_deref()
            .is_some_and(|[x, y]| *x != self.x || *y != self.y)
    }

    /// The position at τ = 1: `to` for a moving vertex, the position
    /// otherwise.
    pub fn end(&self) -> [&Number; 2] {
        match self.to.as_deref() {
            Some([x, y]) => [x, y],
            None => [&self.x, &self.y],
        }
    }
}

/// Effects a case turns on; a scene pays only for those it names.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Effects {
    /// Several samples per pixel and a resolved coverage per pixel.
    pub antialias: Option<Antialias>,
    /// A shutter interval and time samples (SPEC.md §15); it changes
    /// nothing unless some primitive moves.
    pub motion_blur: Option<MotionBlur>,
}

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
    /// Antialiased cases: the largest |resolved coverage − exact area| of
    /// any pixel.
    pub max_coverage_error: Option<f64>,
    /// Antialiased cases: the largest RMS coverage error over edge pixels
    /// (default: piglit's 0.333 · 0.62^log2(N) for sample patterns).
    pub max_coverage_rms: Option<f64>,
    /// Antialiased cases: the exact total area of the primitives, which the
    /// reference's per-pixel areas must sum to.
    pub area: Option<Number>,
    /// Moving scenes: the largest |time coverage − exact| of any pixel.
    pub max_time_error: Option<f64>,
    /// Moving scenes: the largest RMS time-coverage error over moving
    /// pixels (default 0.75·(M·N)^-1/2, SPEC.md §15.4).
    pub max_time_rms: Option<f64>,
    /// Moving scenes: exact time coverages of chosen pixels, which the
    /// reference must reproduce within its certified bound + 10^-12.
    pub time_coverage: Vec<TimePin>,
}

impl Expect {
    /// The expectations a scene in which something moves cannot be judged
    /// on (it is judged on time coverage only, SPEC.md §15.1), by their key
    /// in the case file: the reader refuses a case that gives one.
    pub fn sample_expectations(&self) -> Vec<&'static str> {
        [
            ("samples_covered", self.samples_covered.is_some()),
            ("watertight", self.watertight),
            ("max_mismatched_samples", self.max_mismatched_samples > 0),
            ("max_abs_error", self.max_abs_error.is_some()),
            ("max_ulp_error", self.max_ulp_error.is_some()),
            ("max_coverage_error", self.max_coverage_error.is_some()),
            ("max_coverage_rms", self.max_coverage_rms.is_some()),
            ("area", self.area.is_some()),
        ]
        .into_iter()
        .filter_map(|(key, given)| given.then_some(key))
        .collect()
    }
}

/// One pixel's time coverage as the case author computed it.
#[derive(Clone, Debug, PartialEq)]
pub struct TimePin {
    pub pixel: [u32; 2],
    pub value: Number,
}

impl Scene {
    /// The same scene under another fill rule.
    pub fn with_fill_rule(&self, rule: FillRule) -> Scene {
        let mut s = self.clone();
        s.rules.fill_rule = rule;
        s
    }

    /// The triangles, each with its index among all primitives.
    pub fn triangles(&self) -> impl Iterator<Item = (usize, &Triangle)> {
        self.primitives
            .iter()
            .enumerate()
            .filter_map(|(i, p)| match p {
                Primitive::Triangle(t) => Some((i, t)),
                _ => None,
            })
    }

    /// Whether any primitive is a polygon.
    pub fn has_polygons(&self) -> bool {
        self.primitives
            .iter()
            .any(|p| matches!(p, Primitive::Polygon(_)))
    }

    /// Whether any primitive is a point (SPEC.md §17).
    pub fn has_points(&self) -> bool {
        self.primitives
            .iter()
            .any(|p| matches!(p, Primitive::Point(_)))
    }

    /// Whether any primitive moves: only then is there a time loop.
    pub fn moves(&self) -> bool {
        self.primitives.iter().any(Primitive::moves)
    }

    /// The static scene this one is at instant τ ∈ [0, 1] (SPEC.md §15.1):
    /// every vertex at (1 − τ)·snap(from) + τ·snap(to), exactly. Its
    /// positions are already snapped, so its `subpixel_bits` is null; motion
    /// blur and expectations are dropped. Brute force for tests: the static
    /// rules at one instant.
    ///
    /// # Panics
    /// When the scene has no `subpixel_bits` (a moving scene always has).
    pub fn at_instant(&self, instant: &Number) -> Scene {
        let bits = self
            .rules
            .subpixel_bits
            .expect("a moving scene has subpixel_bits");
        let mut scene = self.clone();
        let tau = instant.as_rbig();
        let one_minus = &dashu_ratio::RBig::ONE - tau;
        for vertex in scene.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
            let [x1, y1] = vertex.end().map(|c| c.snapped(bits).as_rbig().clone());
            let [x0, y0] = [&vertex.x, &vertex.y].map(|c| c.snapped(bits).as_rbig().clone());
            vertex.x = Number::from_rbig(&one_minus * x0 + tau * x1);
            vertex.y = Number::from_rbig(&one_minus * y0 + tau * y1);
            vertex.to = None;
        }
        scene.rules.subpixel_bits = None;
        scene.effects.motion_blur = None;
        scene.expect = Expect::default();
        scene
    }

    /// Whether the vertices are in clip space (SPEC.md §16).
    pub fn in_clip_space(&self) -> bool {
        self.viewport.is_some()
    }

    /// Whether the scene's flat values come from the last vertex
    /// (`provoking_vertex: last`, SPEC.md §16.6) on some primitive where
    /// that shows: a `flat` triangle or line carrying attributes. A
    /// rasterizer that can only take the first vertex's values must refuse
    /// exactly these scenes (`rasterizer::refuse_last_provoking`); every
    /// other scene draws the same under either rule.
    pub fn needs_last_provoking_vertex(&self) -> bool {
        self.rules.provoking_vertex == ProvokingVertex::Last
            && self.attribute_count > 0
            && self.primitives.iter().any(|p| match p {
                Primitive::Triangle(t) => t.interpolation == Interpolation::Flat,
                Primitive::Line(l) => l.interpolation == Interpolation::Flat,
                Primitive::Polygon(_) | Primitive::Point(_) => false,
            })
    }

    /// Every vertex of every primitive.
    pub fn vertices(&self) -> impl Iterator<Item = &Vertex> {
        self.primitives.iter().flat_map(|p| p.vertices())
    }
}
