//! `vello-cpu`: vello_cpu 0.3's antialiased path fill, judged on
//! antialiased cases.
//!
//! vello_cpu computes coverage from the exact area of a path inside each
//! pixel (u8 alpha in the default pipeline). It has no single-sample mode:
//! its `set_aliasing_threshold(t)` lights a pixel whose covered *area*
//! reaches t/255, which is not the pixel-centre sample of SPEC.md §2 (a thin
//! sliver through a centre covers little area; a corner cut can cover half
//! a pixel and miss its centre). Thresholding its area would fake an aliased
//! rasterizer and blame vello for the adapter's choice, so single-sample
//! cases are `Unsupported`. Antialiased cases (SPEC.md §14) are what it is
//! for: each primitive is drawn alone on a cleared pixmap and its alpha,
//! divided by 255, is added to the pixel's resolved value. The frame holds
//! no sample mask, so vello is judged on its coverage error alone.
//!
//! As for the other adapters: vertices are snapped exactly to the case's
//! grid, then rounded once to f64 (kurbo's coordinate type, which holds
//! every snapped coordinate exactly); culling is applied by the adapter;
//! polygons keep their fill rule; lines, depth and attributes are
//! unsupported.

use vello_cpu::color::palette::css;
use vello_cpu::color::PremulRgba8;
use vello_cpu::kurbo::BezPath;
use vello_cpu::peniko::Fill;
use vello_cpu::{Pixmap, RenderContext, Resources};

use super::float_input::{coverage_only, fill_paths, path_fill_capabilities, to_f64};
use crate::frame::{Frame, Parts};
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

/// vello_cpu 0.3's exact-area antialiased fill.
pub struct VelloCpu;

impl Rasterizer for VelloCpu {
    fn name(&self) -> &str {
        "vello-cpu"
    }

    fn capabilities(&self) -> Capabilities {
        path_fill_capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        coverage_only(plan, "vello_cpu")?;
        if plan.antialias.is_none() {
            return Err(RasterError::Unsupported(
                "vello_cpu computes antialiased area coverage only; it has no pixel-centre \
                 (single-sample) mode, and thresholding its area would not be one"
                    .to_owned(),
            ));
        }
        let mut resolved = vec![0.0; scene.canvas.pixel_count()];
        let mut parts = Vec::new();
        for coverage in area_coverage(scene)? {
            for (sum, c) in resolved.iter_mut().zip(&coverage) {
                *sum += f64::from(*c);
            }
            parts.push(
                (0u32..)
                    .zip(coverage)
                    .filter(|&(_, c)| c != 0.0)
                    .map(|(p, c)| (p, f64::from(c)))
                    .collect(),
            );
        }
        let mut frame = Frame::resolved_only(scene.canvas.width, scene.canvas.height, resolved);
        // An area method, judged as one per primitive (SPEC.md §14.4):
        // its fractions are multiples of 1/255.
        frame.parts = Some(Parts {
            coverage: parts,
            step: 1.0 / 255.0,
        });
        Ok(frame)
    }
}

/// For each primitive in scene order, the fraction of every pixel (row-major)
/// that vello_cpu covers, in steps of 1/255; all zero for a culled triangle.
pub fn area_coverage(scene: &Scene) -> Result<Vec<Vec<f32>>, RasterError> {
    let paths = fill_paths(scene, "vello_cpu")?;
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let (Ok(w16), Ok(h16)) = (u16::try_from(width), u16::try_from(height)) else {
        return Err(RasterError::Unsupported(format!(
            "vello_cpu canvases are at most 65535 pixels a side, not {width}×{height}"
        )));
    };
    let mut context = RenderContext::new(w16, h16);
    let mut resources = Resources::new();
    let mut pixmap = Pixmap::new(w16, h16);
    let mut out = Vec::with_capacity(scene.primitives.len());
    for fill in &paths {
        let Some(fill) = fill else {
            out.push(vec![0.0; scene.canvas.pixel_count()]);
            continue;
        };
        let mut path = BezPath::new();
        for contour in &fill.contours {
            let p: Vec<(f64, f64)> = contour
                .iter()
                .map(|v| (to_f64(&v[0]), to_f64(&v[1])))
                .collect();
            path.move_to(p[0]);
            for &q in &p[1..] {
                path.line_to(q);
            }
            path.close_path();
        }
        context.reset();
        context.set_fill_rule(if fill.even_odd {
            Fill::EvenOdd
        } else {
            Fill::NonZero
        });
        context.set_paint(css::WHITE);
        context.fill_path(&path);
        context.flush();
        pixmap.data_mut().fill(PremulRgba8 {
            r: 0,
            g: 0,
            b: 0,
            a: 0,
        });
        context.render(&mut pixmap, &mut resources);
        out.push(
            pixmap
                .data()
                .iter()
                .map(|px| f32::from(px.a) / 255.0)
                .collect(),
        );
    }
    Ok(out)
}
