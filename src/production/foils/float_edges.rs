//! The textbook floating-point triangle rasterizer, in f32 (`float-f32`)
//! and f64 (`float-f64`). **These are foils**, deliberately inexact, kept to
//! show what the exact reference catches in a careful-but-float
//! implementation; they are not candidates for correctness.
//!
//! Each vertex is converted to the float type (from the exact number via
//! `to_f64_lossy`, then narrowed) and snapped in float as
//! `(x · 2^bits).round() / 2^bits` when `subpixel_bits` is set. Each edge
//! function `(bx − ax)(py − ay) − (by − ay)(px − ax)` is evaluated in that
//! type at every pixel centre of the bounding box; the triangle is oriented
//! by the sign of its float area, a sample is inside when all three edge
//! values are ≥ 0, and a value of exactly 0 counts only on an edge the fill
//! rule owns, the edge classified from its float direction as production
//! does. Barycentrics are `Eᵢ / area` in the same type, and depth and
//! attributes are blended from them (perspective as Σ λᵢaᵢ/wᵢ / Σ λᵢ/wᵢ).
//! Lines are production's: only triangles are foiled.
//!
//! What breaks them, each shown by a case in `cases/hard/`:
//!
//! - **Large coordinates, near ties.** An edge function is a difference of
//!   two products; once a product needs more than 24 bits (f32) or 53 bits
//!   (f64) of mantissa it is rounded. At a sample exactly on an edge the two
//!   products are the same real number, so when the coordinate differences
//!   are exact the float still gets 0; but a sample that misses an edge by
//!   the least the grid allows (an exact edge value of 2^-16 px² against
//!   products of 2^31 px²) comes out as 0 or with the wrong sign, and goes
//!   to the tie rule's choice, to both neighbours or to neither. With 8
//!   subpixel bits and vertices near ±32768 px f32 fails and f64 is exact;
//!   with 16 bits f64 fails too (`hard/far_b8_near_tie_fan`,
//!   `hard/far_b16_near_tie_fan`).
//! - **Coordinates the type cannot hold.** A vertex with more significant
//!   bits than the mantissa (a 16-bit fraction on a coordinate near 32768 in
//!   f32, or a 25-bit difference of two 8-bit ones) is rounded before any
//!   edge is evaluated: shared edges then crack or overdraw.
//! - **Near-collinear triangles.** The float area of a sliver can round to 0
//!   (the triangle is dropped), or an exactly collinear one to a nonzero
//!   value (a zero-area triangle draws samples on its line). At 16 bits
//!   f32 cannot even hold the third vertex's offset and loses every sliver
//!   of `hard/sliver_far_b16`.
//! - **Snapping ties.** `round` sends halves away from zero, SPEC.md §2
//!   sends them to even: a vertex exactly half a subpixel off the grid (say
//!   x = 4.5 + 2^-9 at 8 bits) lands one subpixel away from where the
//!   reference puts it, in f32 and f64 alike, and the samples its edges pass
//!   through change sides.

use std::ops::{Add, Div, Mul, Sub};

use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Cull, FillRule, Interpolation, Primitive, Scene, Triangle};

foil!(
    /// The float triangle foil in f32.
    FloatF32,
    "float-f32",
    rasterize::<f32>
);

foil!(
    /// The float triangle foil in f64.
    FloatF64,
    "float-f64",
    rasterize::<f64>
);

/// The float type the foil computes in.
trait Float:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
{
    const ZERO: Self;
    const ONE: Self;
    const HALF: Self;
    /// Narrowed from f64 (round to nearest).
    fn from_f64(v: f64) -> Self;
    fn to_f64(self) -> f64;
    /// Rounds half away from zero, as `f32::round` and `f64::round` do.
    fn round(self) -> Self;
    fn floor(self) -> Self;
    fn ceil(self) -> Self;
}

impl Float for f32 {
    const ZERO: f32 = 0.0;
    const ONE: f32 = 1.0;
    const HALF: f32 = 0.5;
    fn from_f64(v: f64) -> f32 {
        v as f32
    }
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    fn round(self) -> f32 {
        f32::round(self)
    }
    fn floor(self) -> f32 {
        f32::floor(self)
    }
    fn ceil(self) -> f32 {
        f32::ceil(self)
    }
}

impl Float for f64 {
    const ZERO: f64 = 0.0;
    const ONE: f64 = 1.0;
    const HALF: f64 = 0.5;
    fn from_f64(v: f64) -> f64 {
        v
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn round(self) -> f64 {
        f64::round(self)
    }
    fn floor(self) -> f64 {
        f64::floor(self)
    }
    fn ceil(self) -> f64 {
        f64::ceil(self)
    }
}

fn rasterize<F: Float>(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let has_lines = scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Line(_)));
    // Production draws the lines, with every triangle collapsed to a point
    // (zero area, nothing drawn) so that indices stay put.
    let mut frame = if has_lines {
        let mut lines_only = scene.clone();
        for p in &mut lines_only.primitives {
            if let Primitive::Triangle(t) = p {
                let first = t.vertices[0].clone();
                t.vertices = [first.clone(), first.clone(), first];
            }
        }
        Production.rasterize(&lines_only, plan)?
    } else {
        Frame::new(
            scene.canvas.width,
            scene.canvas.height,
            plan.depth,
            plan.attributes,
        )
    };
    let scale = scene
        .rules
        .subpixel_bits
        .map(|bits| F::from_f64((bits as f64).exp2()));
    let place = |n: &crate::scene::Number| {
        let x = F::from_f64(n.to_f64_lossy());
        match scale {
            Some(s) => (x * s).round() / s,
            None => x,
        }
    };
    // The frame's last primitive is the largest index covering a sample, so
    // the triangles can be merged in after the lines: each takes a sample
    // (and writes its values) only from earlier primitives.
    for (index, triangle) in scene.triangles() {
        let p = triangle
            .vertices
            .each_ref()
            .map(|v| [place(&v.x), place(&v.y)]);
        draw_triangle(scene, plan, index, triangle, p, &mut frame);
    }
    Ok(frame)
}

/// `(b − a) × (p − a)`, in float: positive when a, b, p run clockwise on
/// screen.
fn edge<F: Float>(a: [F; 2], b: [F; 2], p: [F; 2]) -> F {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// Whether the edge a→b of a clockwise triangle owns its samples, from its
/// float direction (as production classifies edges).
fn owned<F: Float>(a: [F; 2], b: [F; 2], rule: FillRule) -> bool {
    let dx = b[0] - a[0];
    let dy = b[1] - a[1];
    if dy == F::ZERO {
        if dx > F::ZERO {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        }
    } else if dy < F::ZERO {
        rule.owns_left()
    } else {
        rule.owns_right()
    }
}

fn draw_triangle<F: Float>(
    scene: &Scene,
    plan: &Plan,
    index: usize,
    triangle: &Triangle,
    p: [[F; 2]; 3],
    frame: &mut Frame,
) {
    let area = edge(p[0], p[1], p[2]);
    if area == F::ZERO {
        return;
    }
    let clockwise = area > F::ZERO;
    match scene.rules.cull {
        Cull::Clockwise if clockwise => return,
        Cull::CounterClockwise if !clockwise => return,
        _ => {}
    }
    let (order, opposite, area) = if clockwise {
        ([p[0], p[1], p[2]], [2, 0, 1], area)
    } else {
        ([p[0], p[2], p[1]], [1, 0, 2], F::ZERO - area)
    };
    let rule = scene.rules.fill_rule;
    let edges = [0, 1, 2].map(|i| (order[i], order[(i + 1) % 3]));
    let owns = edges.map(|(a, b)| owned(a, b, rule));

    // Pixel centres inside the bounding box, clipped to the canvas.
    let axis = |k: usize, size: u32| -> (i64, i64) {
        let lo = p
            .iter()
            .map(|v| v[k])
            .fold(p[0][k], |m, v| if v < m { v } else { m });
        let hi = p
            .iter()
            .map(|v| v[k])
            .fold(p[0][k], |m, v| if v > m { v } else { m });
        let first = (lo - F::HALF).ceil().to_f64().max(0.0) as i64;
        let last = (hi - F::HALF).floor().to_f64().min(f64::from(size) - 1.0) as i64;
        (first, last)
    };
    let (x0, x1) = axis(0, scene.canvas.width);
    let (y0, y1) = axis(1, scene.canvas.height);
    if x0 > x1 || y0 > y1 {
        return;
    }

    let vs = &triangle.vertices;
    let f = |n: &crate::scene::Number| F::from_f64(n.to_f64_lossy());
    let inv_w = [0, 1, 2].map(|i| F::ONE / f(&vs[i].w));
    let owner = index as u32 + 1;
    let width = frame.width as usize;
    for y in y0..=y1 {
        let py = F::from_f64(y as f64) + F::HALF;
        for x in x0..=x1 {
            let px = F::from_f64(x as f64) + F::HALF;
            let e = edges.map(|(a, b)| edge(a, b, [px, py]));
            let inside = (0..3).all(|k| e[k] > F::ZERO || (e[k] == F::ZERO && owns[k]));
            if !inside {
                continue;
            }
            let i = y as usize * width + x as usize;
            frame.coverage[i] = frame.coverage[i].saturating_add(1);
            if owner <= frame.last[i] {
                continue;
            }
            frame.last[i] = owner;
            if !plan.interpolates() {
                continue;
            }
            let mut weight = [F::ZERO; 3];
            for k in 0..3 {
                weight[opposite[k]] = e[k] / area;
            }
            let blend =
                |v: &dyn Fn(usize) -> F| weight[0] * v(0) + weight[1] * v(1) + weight[2] * v(2);
            if let Some(depth) = frame.depth.as_mut() {
                depth[i] = blend(&|j| f(&vs[j].z)).to_f64();
            }
            for (k, channel) in frame.attributes.iter_mut().enumerate() {
                let a = |j: usize| f(&vs[j].attributes[k]);
                let value = match triangle.interpolation {
                    Interpolation::Flat => a(scene.rules.provoking_vertex.index(3)),
                    Interpolation::Linear => blend(&a),
                    Interpolation::Perspective => {
                        blend(&|j| a(j) * inv_w[j]) / blend(&|j| inv_w[j])
                    }
                };
                channel[i] = value.to_f64();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::Reference;
    use crate::scene::{parse_case, Limits};

    #[test]
    fn both_match_the_reference_on_a_small_mesh_with_ties() {
        // Two triangles share the diagonal through the 8 samples (k+½, k+½),
        // a third has a horizontal edge through row 5, every vertex is on
        // the grid and every product is small: no rounding anywhere.
        let text = r#"{"name": "t", "canvas": {"width": 8, "height": 8},
            "rules": {"subpixel_bits": 8, "fill_rule": "top-left"},
            "primitives": [
              {"triangle": [
                {"position": [0, 0], "z": 0.5, "w": 1, "attributes": [1, 0]},
                {"position": [8, 0], "z": 0.25, "w": 2, "attributes": [0, 1]},
                {"position": [8, 8], "z": 0, "w": 4, "attributes": [0, 0]}]},
              {"triangle": [
                {"position": [0, 0], "z": 0.5, "w": 1, "attributes": [1, 0]},
                {"position": [0, 8], "z": 1, "w": 0.5, "attributes": [0.5, 0.5]},
                {"position": [8, 8], "z": 0, "w": 4, "attributes": [0, 0]}],
               "interpolation": "linear"},
              {"triangle": [
                {"position": [1, 5.5], "z": 0, "w": 1, "attributes": [2, 2]},
                {"position": [7, 5.5], "z": 0, "w": 1, "attributes": [3, 3]},
                {"position": [4, 7.5], "z": 0, "w": 1, "attributes": [4, 4]}],
               "interpolation": "flat"}
            ]}"#;
        let scene = parse_case(text, "t.json", &Limits::default()).unwrap();
        let plan = Plan::for_scene(&scene);
        let want = Reference.rasterize(&scene, &plan).unwrap();
        for foil in [&FloatF32 as &dyn Rasterizer, &FloatF64] {
            assert!(foil.is_foil());
            let got = foil.rasterize(&scene, &plan).unwrap();
            assert_eq!(got.coverage, want.coverage, "{}", foil.name());
            assert_eq!(got.last, want.last, "{}", foil.name());
            let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-5);
            assert!(close(
                got.depth.as_ref().unwrap(),
                want.depth.as_ref().unwrap()
            ));
            for (g, w) in got.attributes.iter().zip(&want.attributes) {
                assert!(close(g, w), "{}", foil.name());
            }
        }
    }

    #[test]
    fn float_snapping_rounds_ties_away_from_zero() {
        // x = 4.5 + 2^-9 is half a subpixel off the 8-bit grid: the exact
        // rule snaps it to 4.5 (even), `round` to 4.5 + 2^-8. The right
        // edge then passes through column 4's samples (unowned) or beyond.
        let text = r#"{"name": "t", "canvas": {"width": 8, "height": 4},
            "primitives": [{"triangle": [[0, 0], [4.501953125, 0], [4.501953125, 4]]}]}"#;
        let scene = parse_case(text, "t.json", &Limits::default()).unwrap();
        let plan = Plan::for_scene(&scene);
        let want = Reference.rasterize(&scene, &plan).unwrap();
        for foil in [&FloatF32 as &dyn Rasterizer, &FloatF64] {
            let got = foil.rasterize(&scene, &plan).unwrap();
            assert_ne!(got.coverage, want.coverage, "{}", foil.name());
        }
    }
}
