//! The primitives a scene draws (triangles, lines, polygons, points) and
//! their vertices, as written in the case, before any snapping.

use super::number::Number;
use super::rules::{Interpolation, LastPixel, LineParameter, LineRule, PolygonFill};

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
