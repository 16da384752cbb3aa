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

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::exact::{ceil_div, fits_fast_path, floor_div, snap, to_f64_round_odd, ExactInt};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{Canvas, Cull, FillRule, Interpolation, Scene, Triangle};

/// The common integer grid: every snapped vertex and every sample point is
/// an integer multiple of 1/`scale` pixel.
struct Grid {
    scale: IBig,
}

impl Grid {
    /// `2^(bits+1)` for snapped scenes (pixel centres lie on odd multiples of
    /// 2^-(bits+1)); otherwise the least common multiple of 2 and every
    /// coordinate's denominator.
    fn for_scene(scene: &Scene, positions: &[[[RBig; 2]; 3]]) -> Grid {
        if let Some(bits) = scene.rules.subpixel_bits {
            return Grid {
                scale: IBig::ONE << (bits as usize + 1),
            };
        }
        let mut scale = UBig::from(2u8);
        for p in positions.iter().flatten().flatten() {
            let d = p.denominator();
            let g = gcd(&scale, d);
            scale = &scale / &g * d;
        }
        Grid {
            scale: scale.into(),
        }
    }

    fn to_grid(&self, q: &RBig) -> IBig {
        let den = IBig::from(q.denominator().clone());
        q.numerator() * (&self.scale / den)
    }

    /// Grid coordinate of the centre of pixel column (or row) `i`.
    fn centre(&self, i: i64) -> IBig {
        IBig::from(i) * &self.scale + (&self.scale >> 1)
    }
}

fn gcd(a: &UBig, b: &UBig) -> UBig {
    let (mut a, mut b) = (a.clone(), b.clone());
    while b != UBig::ZERO {
        let r = &a % &b;
        a = b;
        b = r;
    }
    a
}

/// The snapped position of every vertex, as exact rationals.
fn snapped_positions(scene: &Scene) -> Vec<[[RBig; 2]; 3]> {
    let place = |n: &crate::scene::Number| match scene.rules.subpixel_bits {
        Some(bits) => snap(n, bits),
        None => n.as_rbig().clone(),
    };
    scene
        .triangles()
        .map(|t| t.vertices.clone().map(|v| [place(&v.x), place(&v.y)]))
        .collect()
}

type Point<T> = [T; 2];

/// (bx - ax)(py - ay) - (by - ay)(px - ax): positive when p lies clockwise
/// of a→b on screen (y down).
fn orient<T: ExactInt>(a: &Point<T>, b: &Point<T>, p: &Point<T>) -> T {
    let left = b[0].sub(&a[0]).mul(&p[1].sub(&a[1]));
    let right = b[1].sub(&a[1]).mul(&p[0].sub(&a[0]));
    left.sub(&right)
}

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

/// Pixel columns (or rows) whose centre lies within [lo, hi] on the grid,
/// clipped to [0, size).
fn centre_range(grid: &Grid, lo: &IBig, hi: &IBig, size: u32) -> std::ops::Range<u32> {
    let half = &grid.scale >> 1;
    let first = ceil_div(&(lo - &half), &grid.scale).max(IBig::ZERO);
    let last = floor_div(&(hi - &half), &grid.scale).min(IBig::from(size) - IBig::ONE);
    if first > last {
        return 0..0;
    }
    let first: u32 = (&first).try_into().unwrap();
    let last: u32 = (&last).try_into().unwrap();
    first..last + 1
}

/// Visits every covered sample of every triangle under `rule`, in scene
/// order. `visit(primitive, pixel, edge values, twice the area)`.
fn for_each_covered<T, F>(
    grid: &Grid,
    canvas: Canvas,
    triangles: &[[Point<IBig>; 3]],
    to_t: fn(&IBig) -> T,
    rule: FillRule,
    cull: Cull,
    mut visit: F,
) where
    T: ExactInt,
    F: FnMut(usize, usize, &[T; 3], &T),
{
    let columns: Vec<T> = (0..canvas.width)
        .map(|i| to_t(&grid.centre(i64::from(i))))
        .collect();
    let rows: Vec<T> = (0..canvas.height)
        .map(|j| to_t(&grid.centre(i64::from(j))))
        .collect();
    for (index, tri) in triangles.iter().enumerate() {
        let v = tri.clone().map(|p| p.map(|c| to_t(&c)));
        let Some(setup) = Setup::new(v, rule, cull) else {
            continue;
        };
        let xs = centre_range(grid, min3(tri, 0), max3(tri, 0), canvas.width);
        let ys = centre_range(grid, min3(tri, 1), max3(tri, 1), canvas.height);
        for y in ys {
            for x in xs.clone() {
                let p = [columns[x as usize].clone(), rows[y as usize].clone()];
                if let Some(values) = setup.covers(&p) {
                    let pixel = y as usize * canvas.width as usize + x as usize;
                    visit(index, pixel, &values, &setup.area);
                }
            }
        }
    }
}

fn min3(t: &[Point<IBig>; 3], axis: usize) -> &IBig {
    t.iter().map(|p| &p[axis]).min().unwrap()
}

fn max3(t: &[Point<IBig>; 3], axis: usize) -> &IBig {
    t.iter().map(|p| &p[axis]).max().unwrap()
}

/// Triangles on the grid, and whether the i128 path is proven safe for them.
fn on_grid(scene: &Scene) -> (Grid, Vec<[Point<IBig>; 3]>, bool) {
    let positions = snapped_positions(scene);
    let grid = Grid::for_scene(scene, &positions);
    let triangles: Vec<[Point<IBig>; 3]> = positions
        .iter()
        .map(|t| t.clone().map(|p| p.map(|c| grid.to_grid(&c))))
        .collect();
    let far_corner = grid.centre(i64::from(scene.canvas.width.max(scene.canvas.height)));
    let fast =
        fits_fast_path(&far_corner) && triangles.iter().flatten().flatten().all(fits_fast_path);
    (grid, triangles, fast)
}

fn to_i128(v: &IBig) -> i128 {
    v.try_into().expect("checked by fits_fast_path")
}

/// Which integers the oracle computes coverage with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// i128 where `exact::I128_COORD_BOUND` proves it safe, big integers
    /// otherwise.
    Auto,
    /// Big integers throughout: slower, and the differential check of the
    /// fast path.
    BigOnly,
}

/// Visits every covered sample of the scene under `rule`, converting the
/// edge values and area to big integers only when `with_values` asks.
fn visit_scene<F>(
    scene: &Scene,
    rule: FillRule,
    arithmetic: Arithmetic,
    with_values: bool,
    mut visit: F,
) where
    F: FnMut(usize, usize, Option<([IBig; 3], IBig)>),
{
    let (grid, triangles, fast) = on_grid(scene);
    let cull = scene.rules.cull;
    if fast && arithmetic == Arithmetic::Auto {
        for_each_covered(
            &grid,
            scene.canvas,
            &triangles,
            to_i128,
            rule,
            cull,
            |i, p, e, a| {
                visit(
                    i,
                    p,
                    with_values.then(|| ((*e).map(IBig::from), IBig::from(*a))),
                )
            },
        );
    } else {
        for_each_covered(
            &grid,
            scene.canvas,
            &triangles,
            IBig::clone,
            rule,
            cull,
            |i, p, e, a| visit(i, p, with_values.then(|| (e.clone(), a.clone()))),
        );
    }
}

/// How many triangles cover each sample under `rule` (coverage only).
pub fn coverage_under(scene: &Scene, rule: FillRule) -> Vec<u16> {
    let mut counts = vec![0u16; scene.canvas.pixel_count()];
    visit_scene(scene, rule, Arithmetic::Auto, false, |_, pixel, _| {
        counts[pixel] = counts[pixel].saturating_add(1)
    });
    counts
}

/// The exact frame: coverage under the scene's rule, and exact depth and
/// attributes rounded to odd (see `exact::to_f64_round_odd`).
pub fn render(scene: &Scene, plan: &Plan) -> Frame {
    render_with(scene, plan, Arithmetic::Auto)
}

/// [`render`] with a choice of integer arithmetic.
pub fn render_with(scene: &Scene, plan: &Plan, arithmetic: Arithmetic) -> Frame {
    let mut frame = Frame::new(
        scene.canvas.width,
        scene.canvas.height,
        plan.depth,
        plan.attributes,
    );
    let values: Vec<VertexValues> = scene.triangles().map(VertexValues::new).collect();
    visit_scene(
        scene,
        scene.rules.fill_rule,
        arithmetic,
        plan.interpolates(),
        |index, pixel, exact| {
            frame.hit(pixel, index);
            if let Some((e, area)) = exact {
                values[index].write(&mut frame, pixel, plan, &e, &area);
            }
        },
    );
    frame
}

/// A triangle's exact per-vertex values, prepared for interpolation.
struct VertexValues {
    interpolation: Interpolation,
    z: [RBig; 3],
    /// attributes[k][i]: attribute k at vertex i.
    attributes: Vec<[RBig; 3]>,
    /// 1/w at each vertex.
    inv_w: [RBig; 3],
}

impl VertexValues {
    fn new(t: &Triangle) -> VertexValues {
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
    fn write(&self, frame: &mut Frame, pixel: usize, plan: &Plan, e: &[IBig; 3], area: &IBig) {
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

/// Samples in the interior of the union of the scene's triangles: those that
/// each of the four consistent fill rules covers (SPEC.md, "Watertightness").
pub fn mesh_interior(scene: &Scene) -> Vec<bool> {
    let mut interior = vec![true; scene.canvas.pixel_count()];
    for rule in FillRule::CONSISTENT {
        let counts = coverage_under(scene, rule);
        for (inside, count) in interior.iter_mut().zip(counts) {
            *inside &= count > 0;
        }
    }
    interior
}
