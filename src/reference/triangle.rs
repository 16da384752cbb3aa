//! Exact triangle coverage and interpolation.
//!
//! Every decision is the sign of an exact integer: vertices are snapped
//! exactly, moved onto one integer grid that also holds every sample point,
//! and tested against each edge with an orientation determinant. The fill
//! rule is applied as D3D11 words it (§3.4.2.1), edge by edge, from where the
//! third vertex lies, not from the winding.
//!
//! What this module does not do: incremental stepping, bounding-box
//! blocking, or any float arithmetic. It visits each candidate sample and
//! evaluates it from scratch; speed is the production rasterizer's job.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::exact::{to_f64_round_odd, ExactInt};
use super::grid::{orient, Grid, Point};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{Canvas, Cull, FillRule, Interpolation, Triangle};

/// Whether the edge a→b of a triangle whose third vertex is c owns the
/// samples on it, by D3D11's definitions: a top edge is horizontal with the
/// triangle below it; a left edge is not horizontal and has the triangle to
/// its right.
fn edge_owns<T: ExactInt>(rule: FillRule, a: &Point<T>, b: &Point<T>, c: &Point<T>) -> bool {
    if a[1] == b[1] {
        let triangle_below = c[1] > a[1];
        return if triangle_below {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        };
    }
    // c lies right of the line through a and b when c.x exceeds the line's x
    // at c.y:  (cx - ax) > (cy - ay)(bx - ax)/(by - ay). Multiplying by
    // (by - ay) keeps the comparison exact and flips it when by < ay.
    let s = c[0]
        .sub(&a[0])
        .mul(&b[1].sub(&a[1]))
        .sub(&c[1].sub(&a[1]).mul(&b[0].sub(&a[0])));
    let triangle_right = s.signum() == b[1].sub(&a[1]).signum();
    if triangle_right {
        rule.owns_left()
    } else {
        rule.owns_right()
    }
}

/// A triangle ready for exact sample tests.
struct Setup<T> {
    v: [Point<T>; 3],
    /// Twice the signed area; positive for clockwise on screen.
    area: T,
    /// Edge i runs from v[i] to v[(i+1)%3]; whether it owns its samples.
    owns: [bool; 3],
}

impl<T: ExactInt> Setup<T> {
    /// `None` for zero-area and culled triangles.
    fn new(v: [Point<T>; 3], rule: FillRule, cull: Cull) -> Option<Setup<T>> {
        let area = orient(&v[0], &v[1], &v[2]);
        let clockwise = match area.signum() {
            0 => return None,
            s => s > 0,
        };
        match cull {
            Cull::Clockwise if clockwise => return None,
            Cull::CounterClockwise if !clockwise => return None,
            _ => {}
        }
        let owns = [0, 1, 2].map(|i| edge_owns(rule, &v[i], &v[(i + 1) % 3], &v[(i + 2) % 3]));
        Some(Setup { v, area, owns })
    }

    /// The three orientations of `p` against the edges when `p` is
    /// covered; `None` otherwise. Value i, for edge v[i]→v[i+1], carries the
    /// area's sign and equals the area times the barycentric weight of the
    /// opposite vertex v[i+2].
    fn covers(&self, p: &Point<T>) -> Option<[T; 3]> {
        let sign = self.area.signum();
        let mut values = [T::zero(), T::zero(), T::zero()];
        for (i, value) in values.iter_mut().enumerate() {
            let e = orient(&self.v[i], &self.v[(i + 1) % 3], p);
            let inward = e.signum() * sign;
            if inward < 0 || (inward == 0 && !self.owns[i]) {
                return None;
            }
            *value = e;
        }
        Some(values)
    }
}

/// Visits every covered sample of one triangle under `rule`:
/// `visit(pixel, edge values, twice the area)`. `to_t` moves grid
/// coordinates into the integer type the proof allows.
pub fn visit<T, F>(
    grid: &Grid,
    canvas: Canvas,
    tri: &[Point<IBig>],
    to_t: fn(&IBig) -> T,
    rule: FillRule,
    cull: Cull,
    mut visit: F,
) where
    T: ExactInt,
    F: FnMut(usize, &[T; 3], &T),
{
    let v = [0, 1, 2].map(|i| tri[i].clone().map(|c| to_t(&c)));
    let Some(setup) = Setup::new(v, rule, cull) else {
        return;
    };
    let lo = |axis: usize| tri.iter().map(|p| &p[axis]).min().unwrap();
    let hi = |axis: usize| tri.iter().map(|p| &p[axis]).max().unwrap();
    let xs = grid.centre_range(lo(0), hi(0), canvas.width);
    let ys = grid.centre_range(lo(1), hi(1), canvas.height);
    let columns: Vec<T> = xs
        .clone()
        .map(|x| to_t(&grid.centre(i64::from(x))))
        .collect();
    for y in ys {
        let py = to_t(&grid.centre(i64::from(y)));
        for (x, px) in xs.clone().zip(&columns) {
            let p = [px.clone(), py.clone()];
            if let Some(values) = setup.covers(&p) {
                visit(
                    y as usize * canvas.width as usize + x as usize,
                    &values,
                    &setup.area,
                );
            }
        }
    }
}

/// A triangle's exact per-vertex values, prepared for interpolation.
pub struct VertexValues {
    interpolation: Interpolation,
    z: [RBig; 3],
    /// attributes[k][i]: attribute k at vertex i.
    attributes: Vec<[RBig; 3]>,
    /// 1/w at each vertex.
    inv_w: [RBig; 3],
}

impl VertexValues {
    pub fn new(t: &Triangle) -> VertexValues {
        let v = &t.vertices;
        let count = v[0].attributes.len();
        VertexValues {
            interpolation: t.interpolation,
            z: [0, 1, 2].map(|i| v[i].z.as_rbig().clone()),
            attributes: (0..count)
                .map(|k| [0, 1, 2].map(|i| v[i].attributes[k].as_rbig().clone()))
                .collect(),
            inv_w: [0, 1, 2].map(|i| RBig::ONE / v[i].w.as_rbig()),
        }
    }

    /// Writes exact depth and attributes at a covered sample. `e[i]` is the
    /// edge value of edge v[i]→v[i+1], which is the area-weighted barycentric
    /// weight of the opposite vertex v[i+2].
    pub fn write(&self, frame: &mut Frame, pixel: usize, plan: &Plan, e: &[IBig; 3], area: &IBig) {
        // Barycentric weight of vertex i: b[i] = e[(i+1)%3] / area.
        let b: [RBig; 3] =
            [0, 1, 2].map(|i| RBig::from_parts_signed(e[(i + 1) % 3].clone(), area.clone()));
        let linear = |values: &[RBig; 3]| -> RBig {
            &b[0] * &values[0] + &b[1] * &values[1] + &b[2] * &values[2]
        };
        if let Some(depth) = frame.depth.as_mut() {
            depth[pixel] = to_f64_round_odd(&linear(&self.z));
        }
        if plan.attributes == 0 {
            return;
        }
        // Perspective: (Σ b_i a_i / w_i) / (Σ b_i / w_i).
        let inv_w_sum = linear(&self.inv_w);
        for (k, values) in self.attributes.iter().enumerate() {
            let exact = match self.interpolation {
                Interpolation::Flat => values[0].clone(),
                Interpolation::Linear => linear(values),
                Interpolation::Perspective => {
                    let over_w = [0, 1, 2].map(|i| &values[i] * &self.inv_w[i]);
                    linear(&over_w) / &inv_w_sum
                }
            };
            frame.attributes[k][pixel] = to_f64_round_odd(&exact);
        }
    }
}
