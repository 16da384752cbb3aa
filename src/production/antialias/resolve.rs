//! `adaptive-resolve`: production's adaptive sampling computing only the
//! resolved coverage, with no sample mask.
//!
//! Each pixel keeps the number of covered samples summed over the
//! primitives that cover it: a pixel wholly inside a triangle (judged
//! strictly from its closed square, or its 8 × 8 block's, as
//! [`Sampling::Adaptive`] does) adds N without a sample being tested, one
//! wholly outside adds nothing, and an edge pixel adds the samples it
//! covers, each decided by the same exact integer test as production's.
//! The sum is a small integer (exact in an f64), divided by N once at the
//! end: the box resolve of production's full supersampling, bit for bit,
//! as long as no sample is covered more than 65535 times (production's
//! per-sample counts saturate there).
//!
//! What this module does not do: depth, attributes, lines or polygons
//! (production draws those; this method says it cannot).

use super::{cover, At, SampleSink, Samples, Sampling};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::{EdgeInt, Fixed};
use crate::production::setup::{self, Footprint};
use crate::production::{format_for, place, Production};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Primitive, Scene};

/// The `adaptive-resolve` method.
#[derive(Clone, Copy, Debug, Default)]
pub struct AdaptiveResolve;

impl Rasterizer for AdaptiveResolve {
    fn name(&self) -> &str {
        "adaptive-resolve"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            attributes: false,
            depth: false,
            polygons: false,
            antialias: true,
            ..Production.capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
        let Some(sample_plan) = plan.antialias.as_ref() else {
            return unsupported("adaptive-resolve draws antialiased scenes only");
        };
        if plan.interpolates() {
            return unsupported("adaptive-resolve computes coverage only, not depth or attributes");
        }
        if scene
            .primitives
            .iter()
            .any(|p| !matches!(p, Primitive::Triangle(_)))
        {
            return unsupported("adaptive-resolve draws triangles only");
        }
        let samples = Samples {
            plan: sample_plan,
            sampling: Sampling::Adaptive,
        };
        let format = format_for(scene, Some(&samples))?;
        let canvas = scene.canvas;
        let mut counts = vec![0.0f64; canvas.pixel_count()];
        if format.fits_i64() {
            draw::<i64>(scene, plan, &samples, format, &mut counts);
        } else {
            draw::<i128>(scene, plan, &samples, format, &mut counts);
        }
        let n = samples.count() as f64;
        for c in &mut counts {
            if *c != 0.0 {
                *c /= n;
            }
        }
        Ok(Frame::resolved_only(canvas.width, canvas.height, counts))
    }
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    samples: &Samples,
    format: crate::production::fixed::Format,
    counts: &mut [f64],
) {
    let offsets = samples.offsets_in(format);
    let mut sink = Counts {
        counts,
        width: scene.canvas.width as usize,
    };
    for primitive in &scene.primitives {
        let Primitive::Triangle(triangle) = primitive else {
            continue;
        };
        let positions: [[Fixed; 2]; 3] = triangle
            .vertices
            .each_ref()
            .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]);
        let Some(setup) = setup::setup_in::<E>(
            positions,
            triangle,
            format,
            scene.rules.fill_rule,
            scene.rules.cull,
            scene.canvas,
            plan,
            |_, _| None,
            Footprint::Squares,
        ) else {
            continue;
        };
        cover(&setup, format, &offsets, Sampling::Adaptive, &mut sink);
    }
}

/// Covered samples per pixel.
struct Counts<'a> {
    counts: &'a mut [f64],
    width: usize,
}

impl<E: EdgeInt> SampleSink<E> for Counts<'_> {
    #[inline]
    fn sample(&mut self, x: i64, y: i64, _s: usize, _at: At<E>) {
        self.counts[y as usize * self.width + x as usize] += 1.0;
    }

    #[inline]
    fn whole(&mut self, x: i64, y: i64, samples: usize, _at: impl Fn(usize) -> At<E>) {
        self.counts[y as usize * self.width + x as usize] += samples as f64;
    }
}
