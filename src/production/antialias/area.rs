//! `area-f32`: analytic area coverage in f32 by signed-area accumulation,
//! the method of font and vector rasterizers (font-rs, ab_glyph).
//!
//! Each edge, walked row by row, deposits into an accumulation buffer the
//! signed area it sweeps in each pixel (the part of the pixel's row strip
//! to its right, signed by its vertical direction) and the rest of its
//! cover into the next pixel; a prefix sum along each row then gives every
//! pixel its signed coverage. Per primitive the buffer spans its bounding
//! box clipped to the canvas, and min(1, |acc|) is added to the pixel's
//! resolved value. Edge parts left of the box stand on its left side (they
//! cover the whole row), parts right of it on its right side (they cover
//! nothing inside it).
//!
//! Measured, not exact: f32 rounds, and a pixel where the winding number
//! changes inside it gets |Σ signed areas|, which is the covered area only
//! where the winding is locally constant (even-odd fold it into [0, 1]).
//! It has no samples, so it returns resolved coverage only, and refuses
//! depth and attributes.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::{Fixed, Format, MAX_FRAC_BITS};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{LineRule, Number, PolygonFill, Primitive, Scene};

/// The `area-f32` method.
#[derive(Clone, Copy, Debug, Default)]
pub struct AreaF32;

impl Rasterizer for AreaF32 {
    fn name(&self) -> &str {
        "area-f32"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            attributes: false,
            depth: false,
            motion_blur: false,
            clip_space: false,
            points: false,
            ..Capabilities::everything()
        }
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
        if plan.antialias.is_none() {
            return unsupported("area-f32 draws antialiased scenes only");
        }
        if plan.interpolates() {
            return unsupported("area-f32 computes coverage only, not depth or attributes");
        }
        let shapes = shapes(scene)?;
        let canvas = scene.canvas;
        let mut resolved = vec![0.0f64; canvas.pixel_count()];
        let mut scratch = Vec::new();
        for shape in &shapes {
            accumulate(
                shape,
                canvas.width,
                canvas.height,
                &mut scratch,
                &mut resolved,
            );
        }
        let mut frame = Frame::resolved_only(canvas.width, canvas.height, resolved);
        // An area method: each pixel's total claims its exact area within
        // the default step (SPEC.md §14.4).
        frame.area_step = Some(0.0);
        Ok(frame)
    }
}

/// A primitive as closed contours in pixel coordinates, with its fill.
#[derive(Clone, Debug)]
struct Shape {
    contours: Vec<Vec<[f64; 2]>>,
    fill: PolygonFill,
    /// The primitive's index in the scene.
    index: usize,
}

/// Every drawn primitive as a shape, its vertices snapped as production
/// snaps them.
fn shapes(scene: &Scene) -> Result<Vec<Shape>, RasterError> {
    let format = match scene.rules.subpixel_bits {
        Some(bits) => Format::snapped(bits),
        None => {
            Format::for_exact(scene.vertices().flat_map(|v| [&v.x, &v.y])).ok_or_else(|| {
                RasterError::Unsupported(format!(
                    "unsnapped coordinates must be multiples of 2^-{}",
                    MAX_FRAC_BITS - 1
                ))
            })?
        }
    };
    let place = |n: &Number| match scene.rules.subpixel_bits {
        Some(bits) => format.snap(n, bits),
        None => format.exact(n).expect("Format::for_exact checked it"),
    };
    let point = |v: &crate::scene::Vertex| [place(&v.x), place(&v.y)];
    let to_f64 = |p: [Fixed; 2]| p.map(|c| c.0 as f64 / format.one() as f64);
    let mut shapes = Vec::new();
    for (index, primitive) in scene.primitives.iter().enumerate() {
        match primitive {
            Primitive::Triangle(t) => {
                let [a, b, c] = t.vertices.each_ref().map(point);
                // Twice the signed area, exact in i128 (coordinates below 2^34
                // units).
                let d = |u: Fixed, v: Fixed| i128::from(u.0) - i128::from(v.0);
                let area = d(b[0], a[0]) * d(c[1], a[1]) - d(b[1], a[1]) * d(c[0], a[0]);
                if area != 0 && !scene.rules.cull.discards(area.cmp(&0)) {
                    shapes.push(Shape {
                        contours: vec![[a, b, c].map(to_f64).to_vec()],
                        fill: PolygonFill::NonZero,
                        index,
                    });
                }
            }
            Primitive::Line(line) => {
                if line.rule != LineRule::Parallelogram {
                    return Err(RasterError::Unsupported(format!(
                        "area-f32 draws parallelogram lines, not {}",
                        line.rule.name()
                    )));
                }
                let [v0, v1] = line.vertices.each_ref().map(|v| to_f64(point(v)));
                if v0 == v1 {
                    continue;
                }
                let major = usize::from((v1[0] - v0[0]).abs() < (v1[1] - v0[1]).abs());
                let half = line.width.to_f64_lossy() / 2.0;
                let corner = |p: [f64; 2], sign: f64| {
                    let mut q = p;
                    q[1 - major] += sign * half;
                    q
                };
                shapes.push(Shape {
                    contours: vec![vec![
                        corner(v0, -1.0),
                        corner(v1, -1.0),
                        corner(v1, 1.0),
                        corner(v0, 1.0),
                    ]],
                    fill: PolygonFill::NonZero,
                    index,
                });
            }
            Primitive::Polygon(polygon) => shapes.push(Shape {
                contours: polygon
                    .contours()
                    .map(|c| c.iter().map(|v| to_f64(point(v))).collect())
                    .collect(),
                fill: polygon.fill,
                index,
            }),
            Primitive::Point(_) => {
                return Err(RasterError::Unsupported(
                    "points are not defined with antialiasing (SPEC.md §17)".to_owned(),
                ))
            }
        }
    }
    Ok(shapes)
}

/// Calls `each` with every drawn primitive's index and its coverage of
/// every pixel (row-major), as `area-f32` computes it, one primitive at a
/// time: what `foil-area-sampler` thresholds.
pub(crate) fn each_primitive(
    scene: &Scene,
    mut each: impl FnMut(usize, &[f64]),
) -> Result<(), RasterError> {
    let canvas = scene.canvas;
    let mut coverage = vec![0.0f64; canvas.pixel_count()];
    let mut scratch = Vec::new();
    for shape in shapes(scene)? {
        accumulate(
            &shape,
            canvas.width,
            canvas.height,
            &mut scratch,
            &mut coverage,
        );
        each(shape.index, &coverage);
        coverage.fill(0.0);
    }
    Ok(())
}

/// Accumulates one shape over its bounding box and adds its coverage into
/// `resolved` (row-major, `width` × `height`).
fn accumulate(
    shape: &Shape,
    width: u32,
    height: u32,
    scratch: &mut Vec<f32>,
    resolved: &mut [f64],
) {
    let points = shape.contours.iter().flatten();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let x0 = (lo[0].floor().max(0.0) as i64).min(i64::from(width));
    let x1 = (hi[0].ceil().max(0.0) as i64).min(i64::from(width));
    let y0 = (lo[1].floor().max(0.0) as i64).min(i64::from(height));
    let y1 = (hi[1].ceil().max(0.0) as i64).min(i64::from(height));
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let (w, h) = ((x1 - x0) as usize, (y1 - y0) as usize);
    // Two spare columns: deposits at the right side land in column w, and
    // the cover after a deposit in the column after that.
    let stride = w + 2;
    scratch.clear();
    scratch.resize(stride * h, 0.0);
    let mut buffer = Accumulator {
        acc: scratch,
        stride,
        width: w as f32,
        height: h,
    };
    let origin = [x0 as f64, y0 as f64];
    for contour in &shape.contours {
        // Coordinates relative to the box, where f32 keeps them fine.
        let local = |p: &[f64; 2]| [(p[0] - origin[0]) as f32, (p[1] - origin[1]) as f32];
        for (a, b) in contour.iter().zip(contour.iter().cycle().skip(1)) {
            buffer.edge(local(a), local(b));
        }
    }
    for row in 0..h {
        let mut sum = 0.0f32;
        let out = (y0 as usize + row) * width as usize + x0 as usize;
        for col in 0..w {
            sum += buffer.acc[row * stride + col];
            let winding = sum.abs();
            let coverage = match shape.fill {
                PolygonFill::NonZero => winding.min(1.0),
                PolygonFill::EvenOdd => {
                    let folded = winding % 2.0;
                    if folded > 1.0 {
                        2.0 - folded
                    } else {
                        folded
                    }
                }
            };
            resolved[out + col] += f64::from(coverage);
        }
    }
}

/// The accumulation buffer of one shape's bounding box.
struct Accumulator<'a> {
    acc: &'a mut [f32],
    stride: usize,
    width: f32,
    height: usize,
}

impl Accumulator<'_> {
    /// Deposits the edge a→b, split where it leaves [0, width] in x and each
    /// part outside moved onto the side it left by.
    fn edge(&mut self, a: [f32; 2], b: [f32; 2]) {
        let mut cuts = vec![0.0f32, 1.0];
        for side in [0.0, self.width] {
            let t = (side - a[0]) / (b[0] - a[0]);
            if t > 0.0 && t < 1.0 {
                cuts.push(t);
            }
        }
        cuts.sort_by(f32::total_cmp);
        let width = self.width;
        let at = |t: f32| {
            let x = if t == 1.0 {
                b[0]
            } else {
                a[0] + t * (b[0] - a[0])
            };
            let y = if t == 1.0 {
                b[1]
            } else {
                a[1] + t * (b[1] - a[1])
            };
            [x.clamp(0.0, width), y]
        };
        for pair in cuts.windows(2) {
            self.line(at(pair[0]), at(pair[1]));
        }
    }

    /// font-rs's `draw_line`: a segment inside [0, width] in x, clipped
    /// here to the rows [0, height).
    fn line(&mut self, p: [f32; 2], q: [f32; 2]) {
        if p[1] == q[1] {
            return;
        }
        let (dir, p, q) = if p[1] < q[1] {
            (1.0f32, p, q)
        } else {
            (-1.0, q, p)
        };
        let dxdy = (q[0] - p[0]) / (q[1] - p[1]);
        let top = p[1].max(0.0);
        let bottom = q[1].min(self.height as f32);
        if top >= bottom {
            return;
        }
        let (lo_x, hi_x) = (p[0].min(q[0]), p[0].max(q[0]));
        let x_at = |y: f32| (p[0] + (y - p[1]) * dxdy).clamp(lo_x, hi_x);
        let mut y = top;
        let mut x = x_at(y);
        let mut row = y.floor() as usize;
        while y < bottom && row < self.height {
            let next = ((row + 1) as f32).min(bottom);
            let xnext = if next == q[1] { q[0] } else { x_at(next) };
            self.deposit(row, x, xnext, (next - y) * dir);
            x = xnext;
            y = next;
            row += 1;
        }
    }

    /// One row's part of a segment from x to xnext, of signed height d.
    fn deposit(&mut self, row: usize, x: f32, xnext: f32, d: f32) {
        let line = &mut self.acc[row * self.stride..(row + 1) * self.stride];
        let (x0, x1) = if x < xnext { (x, xnext) } else { (xnext, x) };
        let x0floor = x0.floor();
        let x0i = x0floor as usize;
        let x1ceil = x1.ceil();
        let x1i = x1ceil as usize;
        if x1i <= x0i + 1 {
            // Within one pixel: the area right of the segment's middle.
            let xmf = 0.5 * (x + xnext) - x0floor;
            line[x0i] += d - d * xmf;
            line[x0i + 1] += d * xmf;
        } else {
            let s = (x1 - x0).recip();
            let x0f = x0 - x0floor;
            let a0 = 0.5 * s * (1.0 - x0f) * (1.0 - x0f);
            let x1f = x1 - x1ceil + 1.0;
            let am = 0.5 * s * x1f * x1f;
            line[x0i] += d * a0;
            if x1i == x0i + 2 {
                line[x0i + 1] += d * (1.0 - a0 - am);
            } else {
                let a1 = s * (1.5 - x0f);
                line[x0i + 1] += d * (a1 - a0);
                for cell in &mut line[x0i + 2..x1i - 1] {
                    *cell += d * s;
                }
                let a2 = a1 + (x1i - x0i - 3) as f32 * s;
                line[x1i - 1] += d * (1.0 - a2 - am);
            }
            line[x1i] += d * am;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn coverage(contour: Vec<[f64; 2]>, fill: PolygonFill, w: u32, h: u32) -> Vec<f64> {
        let mut out = vec![0.0; (w * h) as usize];
        let shape = Shape {
            contours: vec![contour],
            fill,
            index: 0,
        };
        accumulate(&shape, w, h, &mut Vec::new(), &mut out);
        out
    }

    #[test]
    fn a_square_covers_whole_and_half_pixels() {
        // [0.5, 2.5] × [1, 3] on a 4 × 4 canvas.
        let square = vec![[0.5, 1.0], [2.5, 1.0], [2.5, 3.0], [0.5, 3.0]];
        let got = coverage(square, PolygonFill::NonZero, 4, 4);
        let want = [
            0.0, 0.0, 0.0, 0.0, //
            0.5, 1.0, 0.5, 0.0, //
            0.5, 1.0, 0.5, 0.0, //
            0.0, 0.0, 0.0, 0.0,
        ];
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-6, "{got:?}");
        }
    }

    #[test]
    fn parts_outside_the_canvas_are_clipped() {
        // A right triangle from far left to far right: the canvas row 0
        // lies under its hypotenuse y = 1 + (x + 8)/16 · ... checked by sum.
        let tri = vec![[-8.0, 0.0], [12.0, 0.0], [-8.0, 20.0]];
        let got = coverage(tri, PolygonFill::NonZero, 4, 4);
        // The hypotenuse is x + y = 12: every pixel of the 4 × 4 canvas is
        // inside.
        assert!(got.iter().all(|&c| (c - 1.0).abs() < 1e-6), "{got:?}");
    }

    #[test]
    fn even_odd_folds_double_winding_to_empty() {
        // The same square twice: winding 2.
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let shape = Shape {
            contours: vec![square.to_vec(), square.to_vec()],
            fill: PolygonFill::EvenOdd,
            index: 0,
        };
        let mut out = vec![0.0; 4];
        accumulate(&shape, 2, 2, &mut Vec::new(), &mut out);
        assert!(out.iter().all(|&c| c.abs() < 1e-6), "{out:?}");
        let nonzero = Shape {
            fill: PolygonFill::NonZero,
            ..shape
        };
        let mut out = vec![0.0; 4];
        accumulate(&nonzero, 2, 2, &mut Vec::new(), &mut out);
        assert!(out.iter().all(|&c| (c - 1.0).abs() < 1e-6), "{out:?}");
    }
}
