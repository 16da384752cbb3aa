//! `foil-outline-over-fill`: production's fill of each triangle, then its
//! three edges stroked over it as one-pixel hairlines (production's
//! `midpoint` lines: the pixel nearest the edge in each column or row), as
//! a 2D library that draws an outline over an aliased fill does (issue
//! 40). **A foil**, wrong in that one way.
//!
//! It draws more than a point sampler (pixels whose centre lies outside
//! the triangle, where a hairline passes) and less than an any-coverage
//! (conservative) rasterizer: a pixel an edge grazes but whose column (or
//! row) the hairline lights elsewhere stays undrawn, however much of it
//! the triangle covers. `probe` must tell it from both.
//!
//! Each triangle is drawn on its own, on a canvas cropped to its bounds
//! and moved by whole pixels (on every grid, so snapping is unchanged):
//! a pixel its fill and its outline both light counts once. Triangles,
//! single-sample, coverage only.

use super::declare::coverage_foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{
    Canvas, Interpolation, LastPixel, Line, LineParameter, LineRule, Number, Primitive, Scene,
};

coverage_foil!(
    /// The outline-over-fill foil.
    OutlineOverFill,
    "foil-outline-over-fill",
    draw_outlined
);

/// Each triangle filled by production, its edges stroked over the fill.
fn draw_outlined(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
    if plan.antialias.is_some() {
        return unsupported(
            "foil-outline-over-fill draws single-sample coverage only, not antialiasing",
        );
    }
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::new(w, h, false, 0);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        if !matches!(primitive, Primitive::Triangle(_)) {
            return unsupported("foil-outline-over-fill draws triangles only");
        }
        let Some((origin, piece)) = cropped(scene, primitive) else {
            continue;
        };
        let drawn = Production.rasterize(&piece, &Plan::for_scene(&piece))?;
        for y in 0..piece.canvas.height {
            for x in 0..piece.canvas.width {
                if drawn.coverage[drawn.index(x, y)] == 0 {
                    continue;
                }
                let (cx, cy) = (i64::from(x) + origin.0, i64::from(y) + origin.1);
                let i = frame.index(cx as u32, cy as u32);
                frame.coverage[i] = frame.coverage[i].saturating_add(1);
                frame.last[i] = index as u32 + 1;
            }
        }
    }
    Ok(frame)
}

/// The triangle and its three edges as midpoint lines, on a canvas
/// cropped to its bounds (and the scene's), moved so that the crop's
/// corner is the origin; with that corner in the scene's pixels. `None`
/// when it lies off the canvas.
fn cropped(scene: &Scene, triangle: &Primitive) -> Option<((i64, i64), Scene)> {
    let v = triangle.vertices();
    let whole = |pick: &dyn Fn(&crate::scene::Vertex) -> &Number, up: bool| {
        let it = v.iter().map(|v| pick(v).to_f64_lossy());
        let e = if up {
            it.fold(f64::MIN, f64::max).ceil() + 1.0
        } else {
            it.fold(f64::MAX, f64::min).floor() - 1.0
        };
        e.clamp(-1e9, 1e9) as i64
    };
    let x0 = whole(&|v| &v.x, false).max(0);
    let y0 = whole(&|v| &v.y, false).max(0);
    let x1 = whole(&|v| &v.x, true).min(i64::from(scene.canvas.width));
    let y1 = whole(&|v| &v.y, true).min(i64::from(scene.canvas.height));
    if x1 <= x0 || y1 <= y0 {
        return None;
    }
    let mut piece = scene.clone();
    piece.canvas = Canvas {
        width: (x1 - x0) as u32,
        height: (y1 - y0) as u32,
    };
    let shift =
        |n: &Number, by: i64| Number::from_rbig(n.as_rbig() - Number::from_int(by).as_rbig());
    let mut t = triangle.clone();
    for p in t.vertices_mut() {
        p.x = shift(&p.x, x0);
        p.y = shift(&p.y, y0);
    }
    let corners = t.vertices().to_vec();
    piece.primitives = vec![t];
    for k in 0..3 {
        piece.primitives.push(Primitive::Line(Line {
            vertices: [corners[k].clone(), corners[(k + 1) % 3].clone()],
            rule: LineRule::Midpoint,
            width: Number::from_int(1),
            last_pixel: LastPixel::Include,
            parameter: LineParameter::Major,
            interpolation: Interpolation::Linear,
        }));
    }
    Some(((x0, y0), piece))
}
