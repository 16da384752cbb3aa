//! `tiny-skia`: tiny-skia 0.12's aliased path fill, one triangle at a time.
//!
//! Each triangle becomes a closed three-point path, filled with the winding
//! rule and `anti_alias: false` into an 8-bit [`Mask`]; every non-zero mask
//! pixel is a covered sample. The mask is read back and cleared after each
//! triangle, so coverage counts and the last primitive per sample are exact.
//!
//! What the adapter decides, and what it leaves to the library:
//!
//! - **Snapping** is the adapter's: vertices are snapped exactly to the
//!   case's grid and then rounded once to f32 (see `float_input`). tiny-skia
//!   then converts every coordinate to 26.6 fixed point by *truncation*
//!   (`(x * 64.0) as i32`, `edge.rs`), so it works on a 1/64 grid and rounds
//!   toward zero: vertices finer than 6 subpixel bits move, and cases at 8
//!   bits can differ for that reason. That is the library's behaviour and is
//!   reported as found.
//! - **Fill rule** is the library's own: Skia's scan converter includes a
//!   sample that lies on a bottom or right edge and excludes one on a top or
//!   left edge (`bottom-right`). The adapter never imitates a case's rule, so
//!   a `top-left` case with samples on edges fails, which is the finding.
//! - **Culling** is pipeline state, applied by the adapter on the exact
//!   snapped positions before the library sees the triangle.
//! - **Zero-area paths**: tiny-skia refuses paths whose bounds are nearly zero
//!   wide or high, and draws nothing for them.
//!
//! Polygons are paths with their own fill rule (`EvenOdd` or `Winding`).
//! Antialiased cases use the library's antialiased fill (4× vertical
//! supersampling with horizontal area, per its `scan/path_aa.rs`): each
//! primitive's 8-bit coverage, divided by 255, is added to the pixel's
//! resolved value, and the frame holds no sample mask (the library's samples
//! are not the case's pattern), so it is judged on its coverage error alone.
//!
//! Unsupported: lines (tiny-skia strokes hairlines with its own antialiased
//! or Bresenham-like walk, none of SPEC.md §4's rules), depth and attributes
//! (a path fill interpolates nothing), and aliased fills with more than one
//! sample per pixel.

use tiny_skia::{BlendMode, Color, FillRule, Mask, Paint, Path, PathBuilder, Pixmap, Transform};

use super::float_input::{
    coverage_only, fill_paths, path_fill_capabilities, single_sample, to_f32, FillPath,
};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{owners_frame, Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::Scene;

/// tiny-skia's path fill: aliased for single-sample cases, antialiased for
/// antialiased ones.
pub struct TinySkia;

impl Rasterizer for TinySkia {
    fn name(&self) -> &str {
        "tiny-skia"
    }

    fn capabilities(&self) -> Capabilities {
        path_fill_capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        coverage_only(plan, "tiny-skia")?;
        let antialias = plan.antialias.is_some();
        if !antialias {
            single_sample(plan, "tiny-skia")?;
        }
        let paths = fill_paths(scene, "tiny-skia")?;
        let (width, height) = (scene.canvas.width, scene.canvas.height);
        let mut mask = Mask::new(width, height).ok_or_else(|| {
            RasterError::Failed(format!("tiny-skia refused a {width}×{height} mask"))
        })?;
        let mut frame = if antialias {
            Frame::resolved_only(width, height, vec![0.0; scene.canvas.pixel_count()])
        } else {
            Frame::new(width, height, false, 0)
        };
        for (index, fill) in paths.iter().enumerate() {
            let Some(fill) = fill else { continue };
            // `None`: no area the library can describe (e.g. non-finite bounds).
            let Some(path) = path(fill) else { continue };
            let rule = if fill.even_odd {
                FillRule::EvenOdd
            } else {
                FillRule::Winding
            };
            mask.fill_path(&path, rule, antialias, Transform::identity());
            // The fill writes only inside the path's bounds; read and clear
            // them, one pixel wider for safety.
            let b = path.bounds();
            let clamp = |v: f32, max: u32| (v.max(0.0) as u64).min(u64::from(max)) as usize;
            let (x0, x1) = (
                clamp(b.left().floor() - 1.0, width),
                clamp(b.right().ceil() + 1.0, width),
            );
            let (y0, y1) = (
                clamp(b.top().floor() - 1.0, height),
                clamp(b.bottom().ceil() + 1.0, height),
            );
            let data = mask.data_mut();
            for y in y0..y1 {
                let row = y * width as usize;
                for (i, value) in data[row + x0..row + x1].iter_mut().enumerate() {
                    if *value == 0 {
                        continue;
                    }
                    let pixel = row + x0 + i;
                    match &mut frame.resolved {
                        Some(resolved) if antialias => resolved[pixel] += f64::from(*value) / 255.0,
                        _ => frame.hit(pixel, index),
                    }
                    *value = 0;
                }
            }
        }
        if mask.data().iter().any(|&v| v != 0) {
            return Err(RasterError::Failed(
                "tiny-skia wrote outside a primitive's bounds; coverage would be misattributed"
                    .to_owned(),
            ));
        }
        Ok(frame)
    }

    /// Aliased, coverage-only scenes: [`PreparedFill`].
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        if plan.antialias.is_some() || plan.interpolates() {
            return None;
        }
        Some(prepare_fill(scene, plan).map(|p| Box::new(p) as Box<dyn Prepared>))
    }
}

/// The aliased fill as an application calls it: every path built once, each
/// filled with `Pixmap::fill_path` in an opaque colour that numbers its
/// primitive (index + 1 in red, green and blue), into one reused pixmap.
/// An opaque solid paint takes tiny-skia's fastest road, a span fill.
struct PreparedFill {
    fills: Vec<(Path, FillRule, Paint<'static>)>,
    pixmap: Pixmap,
}

impl Prepared for PreparedFill {
    fn clear(&mut self) -> Result<(), RasterError> {
        self.pixmap.fill(Color::TRANSPARENT);
        Ok(())
    }

    fn draw(&mut self) -> Result<(), RasterError> {
        for (path, rule, paint) in &self.fills {
            self.pixmap
                .fill_path(path, paint, *rule, Transform::identity(), None);
        }
        Ok(())
    }

    fn read_back(&mut self) -> Result<Frame, RasterError> {
        let owners: Vec<u32> = self
            .pixmap
            .pixels()
            .iter()
            .map(|p| u32::from(p.red()) | u32::from(p.green()) << 8 | u32::from(p.blue()) << 16)
            .collect();
        Ok(owners_frame(
            self.pixmap.width(),
            self.pixmap.height(),
            &owners,
        ))
    }
}

/// The prepared aliased fill of a single-sample, coverage-only scene.
fn prepare_fill(scene: &Scene, plan: &Plan) -> Result<PreparedFill, RasterError> {
    coverage_only(plan, "tiny-skia")?;
    single_sample(plan, "tiny-skia")?;
    if scene.primitives.len() >= 1 << 24 {
        return Err(RasterError::Unsupported(
            "more primitives than 24 bits of colour can number".to_owned(),
        ));
    }
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let pixmap = Pixmap::new(width, height).ok_or_else(|| {
        RasterError::Failed(format!("tiny-skia refused a {width}×{height} pixmap"))
    })?;
    let mut fills = Vec::new();
    for (index, fill) in fill_paths(scene, "tiny-skia")?.iter().enumerate() {
        let Some(path) = fill.as_ref().and_then(path) else {
            continue;
        };
        let number = index as u32 + 1;
        let byte = |shift: u32| (number >> shift) as u8;
        let mut paint = Paint::default();
        paint.set_color_rgba8(byte(0), byte(8), byte(16), 255);
        paint.anti_alias = false;
        paint.blend_mode = BlendMode::Source;
        let rule = if fill.as_ref().is_some_and(|f| f.even_odd) {
            FillRule::EvenOdd
        } else {
            FillRule::Winding
        };
        fills.push((path, rule, paint));
    }
    Ok(PreparedFill { fills, pixmap })
}

/// The library's path for a fill, every contour closed.
fn path(fill: &FillPath) -> Option<Path> {
    let mut builder = PathBuilder::new();
    for contour in &fill.contours {
        let p: Vec<[f32; 2]> = contour
            .iter()
            .map(|v| [to_f32(&v[0]), to_f32(&v[1])])
            .collect();
        builder.move_to(p[0][0], p[0][1]);
        for q in &p[1..] {
            builder.line_to(q[0], q[1]);
        }
        builder.close();
    }
    builder.finish()
}
