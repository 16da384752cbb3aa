//! The classic floating-point DDA line, in f32 (`dda-f32`) and f64
//! (`dda-f64`). **These are foils**, deliberately inexact, kept to show that
//! the suite catches the rounding of a float line walker.
//!
//! For an x-major `midpoint` line they walk the columns from the v0 end, start
//! at y(c) computed in float at the first column drawn, and add the float
//! slope m = dy/dx once per column; the row is `round(y − ½)`, the textbook
//! DDA's rounding of the pixel-centre coordinate, halves away from zero
//! (y-major lines are the same with the axes swapped). Which columns are
//! drawn is decided exactly, as production does, so the foils depart from
//! the rule through rounding (the f32 walker visibly on long lines) and at
//! exact ties, where `round` goes down the screen and SPEC.md §4.1 goes up.
//! Triangles and wide lines are production's.

use std::ops::{Add, Div, Mul, Sub};

use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::production::fixed::Format;
use crate::production::line::{self, Geometry, LineShading};
use crate::production::scene_format::{format_for, place};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Canvas, LastPixel, LineRule, Primitive, Scene};

foil!(
    /// The DDA foil stepping in f32.
    DdaF32,
    "dda-f32",
    rasterize::<f32>
);

foil!(
    /// The DDA foil stepping in f64.
    DdaF64,
    "dda-f64",
    rasterize::<f64>
);

/// The float a DDA steps in.
pub(crate) trait Float:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    fn from_i64(v: i64) -> Self;
    /// The textbook DDA's pixel: round(self − ½), halves away from zero.
    fn nearest_pixel(self) -> i64;
}

impl Float for f32 {
    fn from_i64(v: i64) -> f32 {
        v as f32
    }
    fn nearest_pixel(self) -> i64 {
        (self - 0.5).round() as i64
    }
}

impl Float for f64 {
    fn from_i64(v: i64) -> f64 {
        v as f64
    }
    fn nearest_pixel(self) -> i64 {
        (self - 0.5).round() as i64
    }
}

fn is_midpoint_line(p: &Primitive) -> bool {
    matches!(p, Primitive::Line(l) if l.rule == LineRule::Midpoint)
}

fn rasterize<F: Float>(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    if !scene.primitives.iter().any(is_midpoint_line) {
        return Production.rasterize(scene, plan);
    }
    // Production draws everything else, with each midpoint line collapsed to
    // a point (which draws nothing) so that indices stay put.
    let mut others = scene.clone();
    for p in &mut others.primitives {
        if let Primitive::Line(l) = p {
            if l.rule == LineRule::Midpoint {
                l.vertices[1] = l.vertices[0].clone();
            }
        }
    }
    let mut frame = Production.rasterize(&others, plan)?;

    // Production's own format (the foil has no samples) and placing.
    let format = format_for(scene, None)?;
    // The frame's last primitive is the largest index covering a sample, so
    // the midpoint lines can be merged in afterwards: each takes a sample
    // (and writes its values) only from earlier primitives.
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Line(l) = primitive else {
            continue;
        };
        if l.rule != LineRule::Midpoint {
            continue;
        }
        let g = Geometry::new(
            l.vertices
                .each_ref()
                .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]),
        );
        if g.is_point() {
            continue;
        }
        let shading = plan
            .interpolates()
            .then(|| LineShading::new(l, &g, plan, scene.rules.provoking_vertex.index(2)));
        let owner = index as u32 + 1;
        dda::<F>(&g, format, l.last_pixel, scene.canvas, |x, y| {
            let i = y as usize * frame.width as usize + x as usize;
            frame.coverage[i] = frame.coverage[i].saturating_add(1);
            if owner > frame.last[i] {
                frame.last[i] = owner;
                if let Some(s) = &shading {
                    let p = [format.centre(x).0, format.centre(y).0];
                    s.write(&mut frame, i, s.weights(p));
                }
            }
        });
    }
    Ok(frame)
}

/// Calls `visit(x, y)` for each pixel the float DDA draws on the canvas.
pub(crate) fn dda<F: Float>(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
    mut visit: impl FnMut(i64, i64),
) {
    let (u, v) = (g.major, 1 - g.major);
    let (first, end) = line::major_range(g, format, last_pixel, canvas);
    if first >= end {
        return;
    }
    let minor_size = i64::from(if v == 0 { canvas.width } else { canvas.height });
    let one = F::from_i64(format.one());
    let pixels = |units: i64| F::from_i64(units) / one;
    let (u0, v0) = (pixels(g.v0[u]), pixels(g.v0[v]));
    let slope = pixels(g.d[v]) / pixels(g.d[u]);
    // Walk from the v0 end, as the classic DDA does.
    let forward = g.d[u] > 0;
    let start = if forward { first } else { end - 1 };
    let centre = pixels(format.centre(start).0);
    let mut minor = v0 + (centre - u0) * slope;
    let zero = F::from_i64(0);
    let step = if forward { slope } else { zero - slope };
    for k in 0..end - first {
        let major = if forward { first + k } else { end - 1 - k };
        let m = minor.nearest_pixel();
        if (0..minor_size).contains(&m) {
            if u == 0 {
                visit(major, m);
            } else {
                visit(m, major);
            }
        }
        minor = minor + step;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::production::fixed::Fixed;
    use crate::scene::{parse_case, Limits};

    fn pixels(
        g: &Geometry,
        format: Format,
        canvas: Canvas,
        walk: impl Fn(&Geometry, Format, LastPixel, Canvas, &mut Vec<(i64, i64)>),
    ) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        walk(g, format, LastPixel::Include, canvas, &mut out);
        out.sort();
        out
    }

    fn exact(g: &Geometry, f: Format, l: LastPixel, c: Canvas, out: &mut Vec<(i64, i64)>) {
        line::midpoint(g, f, l, c, |x, y| out.push((x, y)));
    }
    fn dda32(g: &Geometry, f: Format, l: LastPixel, c: Canvas, out: &mut Vec<(i64, i64)>) {
        dda::<f32>(g, f, l, c, |x, y| out.push((x, y)));
    }
    fn dda64(g: &Geometry, f: Format, l: LastPixel, c: Canvas, out: &mut Vec<(i64, i64)>) {
        dda::<f64>(g, f, l, c, |x, y| out.push((x, y)));
    }

    fn at(format: Format, x: f64, y: f64) -> [Fixed; 2] {
        let one = format.one() as f64;
        [Fixed((x * one) as i64), Fixed((y * one) as i64)]
    }

    #[test]
    fn both_agree_with_the_rule_on_a_short_line_without_ties() {
        let format = Format { frac_bits: 9 };
        let canvas = Canvas {
            width: 16,
            height: 16,
        };
        // y(c) = 0.25 + 0.3·i: never within 0.05 of an integer.
        for ends in [
            [at(format, 0.5, 0.25), at(format, 10.5, 3.25)],
            [at(format, 10.5, 3.25), at(format, 0.5, 0.25)],
            [at(format, 0.25, 0.5), at(format, 3.25, 10.5)],
        ] {
            let g = Geometry::new(ends);
            let want = pixels(&g, format, canvas, exact);
            assert_eq!(pixels(&g, format, canvas, dda32), want);
            assert_eq!(pixels(&g, format, canvas, dda64), want);
        }
    }

    #[test]
    fn f32_departs_from_the_rule_on_a_long_shallow_line() {
        let format = Format { frac_bits: 9 };
        let canvas = Canvas {
            width: 4096,
            height: 1100,
        };
        // y(c) = i/3: an exact tie every third column, and m = 1/3 is
        // inexact in float.
        let g = Geometry::new([at(format, 0.5, 0.0), at(format, 3000.5, 1000.0)]);
        let want = pixels(&g, format, canvas, exact);
        let got = pixels(&g, format, canvas, dda32);
        assert_eq!(got.len(), want.len());
        let wrong = got.iter().zip(&want).filter(|(a, b)| a != b).count();
        assert!(wrong > 0, "the f32 DDA matched the exact rule");
    }

    #[test]
    fn the_foils_keep_primitive_order() {
        // A triangle, then a midpoint line over it, then another triangle:
        // coverage counts and the last primitive follow scene order.
        let text = r#"{"name": "t", "canvas": {"width": 8, "height": 8},
            "primitives": [
              {"triangle": [[0, 0], [8, 0], [0, 8]]},
              {"line": [[0, 4.5], [8, 4.5]]},
              {"triangle": [[0, 4], [8, 4], [0, 5]]}
            ]}"#;
        let scene = parse_case(text, "t.json", &Limits::default()).unwrap();
        let plan = Plan::for_scene(&scene);
        let reference = Production.rasterize(&scene, &plan).unwrap();
        for foil in [&DdaF32 as &dyn Rasterizer, &DdaF64] {
            let frame = foil.rasterize(&scene, &plan).unwrap();
            assert_eq!(frame, reference, "{}", foil.name());
        }
    }
}
