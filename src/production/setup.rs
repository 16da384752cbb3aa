//! Triangle setup: fixed-point vertices to edge equations with the tie-rule
//! bias folded in, a pixel bounding box, and f32 plane equations for depth
//! and attributes.

use super::fixed::{EdgeInt, Fixed, Format};
use crate::plan::Plan;
use crate::scene::{Canvas, Cull, FillRule, Interpolation, Triangle};

/// One edge as an incremental function of the pixel position:
/// `value(x, y) = at_origin + x·step_x + y·step_y` at the centre of pixel
/// (x, y). The tie bias is folded in, so a sample is inside the edge exactly
/// when the value is ≥ 0.
#[derive(Clone, Copy, Debug)]
pub struct EdgeEquation<E> {
    pub at_origin: E,
    pub step_x: E,
    pub step_y: E,
}

impl<E: EdgeInt> EdgeEquation<E> {
    #[inline]
    pub fn at(&self, x: i64, y: i64) -> E {
        self.at_origin + E::from(x) * self.step_x + E::from(y) * self.step_y
    }
}

/// Pixels whose centres may be covered, clipped to the canvas; half-open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelBox {
    pub x0: i64,
    pub y0: i64,
    pub x1: i64,
    pub y1: i64,
}

impl PixelBox {
    pub fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }
}

/// A plane `value = origin + dx·(px - x0) + dy·(py - y0)` in f32, anchored
/// at the first vertex (x0, y0), in pixels.
#[derive(Clone, Copy, Debug, Default)]
pub struct Plane {
    pub origin: f32,
    pub dx: f32,
    pub dy: f32,
}

impl Plane {
    #[inline]
    pub fn at(&self, rx: f32, ry: f32) -> f32 {
        self.origin + self.dx * rx + self.dy * ry
    }
}

/// How a triangle's attributes are evaluated at a sample.
#[derive(Clone, Debug)]
pub enum Shading {
    /// Coverage only.
    None,
    Values {
        interpolation: Interpolation,
        /// The anchor vertex in pixels, f32 relative offsets are taken from it.
        anchor: [Fixed; 2],
        depth: Option<Plane>,
        /// Linear and flat: the value planes. Perspective: the planes of a/w.
        attributes: Vec<Plane>,
        /// Perspective only: the plane of 1/w.
        inv_w: Plane,
    },
}

/// Everything traversal needs for one triangle.
#[derive(Clone, Debug)]
pub struct TriangleSetup<E> {
    pub edges: [EdgeEquation<E>; 3],
    pub bounds: PixelBox,
    pub shading: Shading,
}

/// Sets up a triangle whose vertices are already in `format`. Returns
/// `None` when it is culled, has zero area, or covers no pixel centre.
pub fn setup<E: EdgeInt>(
    positions: [[Fixed; 2]; 3],
    triangle: &Triangle,
    format: Format,
    rule: FillRule,
    cull: Cull,
    canvas: Canvas,
    plan: &Plan,
) -> Option<TriangleSetup<E>> {
    let [p0, p1, p2] = positions;
    let area = cross::<E>(p0, p1, p2);
    if area == E::default() {
        return None;
    }
    let clockwise = area > E::default();
    match cull {
        Cull::Clockwise if clockwise => return None,
        Cull::CounterClockwise if !clockwise => return None,
        _ => {}
    }
    // Traverse clockwise (on screen, y down), so that every edge function
    // is positive inside.
    let order = if clockwise {
        [p0, p1, p2]
    } else {
        [p0, p2, p1]
    };

    let bounds = pixel_box(&order, format, canvas);
    if bounds.is_empty() {
        return None;
    }
    let edges = [0, 1, 2].map(|i| edge_equation(order[i], order[(i + 1) % 3], format, rule));
    let shading = if plan.interpolates() {
        shading(positions, triangle, format, plan, area.to_f64())
    } else {
        Shading::None
    };
    Some(TriangleSetup {
        edges,
        bounds,
        shading,
    })
}

/// Twice the signed area; positive when a, b, c run clockwise on screen.
fn cross<E: EdgeInt>(a: [Fixed; 2], b: [Fixed; 2], c: [Fixed; 2]) -> E {
    let d = |u: Fixed, v: Fixed| E::from(u.0) - E::from(v.0);
    d(b[0], a[0]) * d(c[1], a[1]) - d(b[1], a[1]) * d(c[0], a[0])
}

/// The edge a→b of a clockwise triangle. Its function,
/// `(bx - ax)(py - ay) - (by - ay)(px - ax)`, is positive inside; the bias
/// makes a sample on the edge count as inside only when the rule gives the
/// edge its samples.
fn edge_equation<E: EdgeInt>(
    a: [Fixed; 2],
    b: [Fixed; 2],
    format: Format,
    rule: FillRule,
) -> EdgeEquation<E> {
    let dx = b[0].0 - a[0].0;
    let dy = b[1].0 - a[1].0;
    // Walking clockwise with y down, the triangle is on the right-hand side:
    // an edge heading east (dy = 0, dx > 0) has it below, so it is a top
    // edge; one heading north (dy < 0) has it to the east, a left edge.
    let owned = if dy == 0 {
        if dx > 0 {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        }
    } else if dy < 0 {
        rule.owns_left()
    } else {
        rule.owns_right()
    };
    let centre = format.centre(0);
    let value = E::from(dx) * (E::from(centre.0) - E::from(a[1].0))
        - E::from(dy) * (E::from(centre.0) - E::from(a[0].0));
    // Inside: value > 0, or value = 0 on an owned edge. As integers that is
    // value + owned - 1 ≥ 0.
    let bias = if owned { E::from(0) } else { E::from(-1) };
    let one = format.one();
    EdgeEquation {
        at_origin: value + bias,
        step_x: E::from(-dy) * E::from(one),
        step_y: E::from(dx) * E::from(one),
    }
}

/// Pixels whose centres lie inside the triangle's bounding box, clipped to
/// the canvas.
fn pixel_box(v: &[[Fixed; 2]; 3], format: Format, canvas: Canvas) -> PixelBox {
    let half = format.one() / 2;
    let one = format.one();
    let axis = |k: usize, size: u32| {
        let lo = v.iter().map(|p| p[k].0).min().unwrap();
        let hi = v.iter().map(|p| p[k].0).max().unwrap();
        // First centre ≥ lo: i·one + half ≥ lo. Last centre ≤ hi.
        let first = (lo - half + one - 1).div_euclid(one);
        let last = (hi - half).div_euclid(one);
        (first.max(0), (last + 1).min(i64::from(size)))
    };
    let (x0, x1) = axis(0, canvas.width);
    let (y0, y1) = axis(1, canvas.height);
    PixelBox { x0, y0, x1, y1 }
}

/// f32 plane equations for depth and attributes, set up in f64 from the
/// vertices in their original order (the first vertex is the flat one).
fn shading(
    positions: [[Fixed; 2]; 3],
    triangle: &Triangle,
    format: Format,
    plan: &Plan,
    area: f64,
) -> Shading {
    let scale = 1.0 / format.one() as f64;
    let px = |p: Fixed| p.0 as f64 * scale;
    let [p0, p1, p2] = positions;
    let (dx1, dy1) = (px(p1[0]) - px(p0[0]), px(p1[1]) - px(p0[1]));
    let (dx2, dy2) = (px(p2[0]) - px(p0[0]), px(p2[1]) - px(p0[1]));
    let det = area * scale * scale;
    let plane = |v: [f64; 3]| -> Plane {
        let (d1, d2) = (v[1] - v[0], v[2] - v[0]);
        Plane {
            origin: v[0] as f32,
            dx: ((d1 * dy2 - d2 * dy1) / det) as f32,
            dy: ((d2 * dx1 - d1 * dx2) / det) as f32,
        }
    };
    let vs = &triangle.vertices;
    let depth = plan
        .depth
        .then(|| plane([0, 1, 2].map(|i| vs[i].z.to_f64_lossy())));
    let inv_w = [0, 1, 2].map(|i| 1.0 / vs[i].w.to_f64_lossy());
    let interpolation = triangle.interpolation;
    let attributes = (0..plan.attributes)
        .map(|k| {
            let a = [0, 1, 2].map(|i| vs[i].attributes[k].to_f64_lossy());
            match interpolation {
                Interpolation::Flat => Plane {
                    origin: a[0] as f32,
                    dx: 0.0,
                    dy: 0.0,
                },
                Interpolation::Linear => plane(a),
                Interpolation::Perspective => plane([0, 1, 2].map(|i| a[i] * inv_w[i])),
            }
        })
        .collect();
    Shading::Values {
        interpolation,
        anchor: p0,
        depth,
        attributes,
        inv_w: plane(inv_w),
    }
}
