//! The production rasterizer: fixed point, integer coverage decisions,
//! f32 interpolation. It imports the scene model and the output types, and
//! never the reference.

pub mod antialias;
pub mod fixed;
pub mod foils;
pub mod line;
pub mod polygon;
pub mod setup;
pub mod traverse;

use antialias::{Samples, Sampling};
use fixed::{EdgeInt, Fixed, Format};
use setup::{Footprint, Shading, TriangleSetup};
use traverse::Sink;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Primitive, Scene, Triangle};

/// A production method that is a rasterizer of its own (a polygon fill, an
/// antialiasing method), by its command-line name.
pub struct Method {
    pub name: &'static str,
    pub make: fn() -> Box<dyn Rasterizer>,
}

/// Production's other methods, each measured against the reference on its
/// own.
pub fn methods() -> Vec<Method> {
    let mut all = polygon::methods();
    all.extend(antialias::methods());
    all
}

/// The production rasterizer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Production;

impl Rasterizer for Production {
    fn name(&self) -> &str {
        "production"
    }

    fn capabilities(&self) -> Capabilities {
        // Ideal geometry only when its coordinates are dyadic: checked per scene.
        Capabilities {
            polygons: true,
            antialias: true,
            ..Capabilities::everything()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize_with(scene, plan, Sampling::for_plan(plan))
    }
}

/// Production's rasterizer with the antialiased scenes' samples decided by
/// `sampling` (ignored without antialiasing).
pub(crate) fn rasterize_with(
    scene: &Scene,
    plan: &Plan,
    sampling: Sampling,
) -> Result<Frame, RasterError> {
    let format = match scene.rules.subpixel_bits {
        Some(bits) => Format::snapped(bits),
        None => {
            Format::for_exact(scene.vertices().flat_map(|v| [&v.x, &v.y])).ok_or_else(|| {
                RasterError::Unsupported(format!(
                    "unsnapped coordinates must be multiples of 2^-{} to be held in fixed point",
                    fixed::MAX_FRAC_BITS - 1
                ))
            })?
        }
    };
    let samples = plan
        .antialias
        .as_ref()
        .map(|plan| Samples { plan, sampling });
    // Sample offsets are integers in a format at least position_bits fine.
    let format = match &samples {
        Some(samples) => format.with_samples(samples.plan.position_bits),
        None => format,
    };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    if format.fits_i64() {
        draw::<i64>(scene, plan, format, samples.as_ref(), &mut frame)?;
    } else {
        draw::<i128>(scene, plan, format, samples.as_ref(), &mut frame)?;
    }
    if samples.is_some() {
        frame.resolve();
    }
    Ok(frame)
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    samples: Option<&Samples>,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let place = |n: &Number| match scene.rules.subpixel_bits {
        Some(bits) => format.snap(n, bits),
        None => format
            .exact(n)
            .expect("Format::for_exact checked every coordinate"),
    };
    let offsets = samples.map(|s| s.offsets_in(format));
    for (index, primitive) in scene.primitives.iter().enumerate() {
        match primitive {
            Primitive::Triangle(triangle) => {
                let positions = triangle
                    .vertices
                    .each_ref()
                    .map(|v| [place(&v.x), place(&v.y)]);
                let offsets = offsets.as_deref();
                let sampled = samples.zip(offsets);
                draw_triangle::<E>(
                    scene, plan, format, sampled, index, triangle, positions, frame,
                );
            }
            Primitive::Line(line) => {
                let ends = line.vertices.each_ref().map(|v| [place(&v.x), place(&v.y)]);
                line::draw::<E>(
                    line,
                    ends,
                    format,
                    scene.rules.fill_rule,
                    scene.canvas,
                    plan,
                    samples,
                    index,
                    frame,
                )?;
            }
            Primitive::Polygon(polygon) => {
                polygon::draw::<E>(scene, plan, format, index, polygon, frame)?;
            }
        }
    }
    Ok(())
}

/// Draws one triangle whose vertices are already in `format` as primitive
/// `index`: its pixel centres, or, `sampled`, its samples at the offsets
/// given in `format`.
#[allow(clippy::too_many_arguments)]
fn draw_triangle<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    sampled: Option<(&Samples, &[[i64; 2]])>,
    index: usize,
    triangle: &Triangle,
    positions: [[Fixed; 2]; 3],
    frame: &mut Frame,
) {
    let footprint = match sampled {
        Some(_) => Footprint::Squares,
        None => Footprint::Centres,
    };
    let Some(setup) = setup::setup_in::<E>(
        positions,
        triangle,
        format,
        scene.rules.fill_rule,
        scene.rules.cull,
        scene.canvas,
        plan,
        |_, _| None,
        footprint,
    ) else {
        return;
    };
    match sampled {
        Some((samples, offsets)) => {
            antialias::write_triangle(&setup, format, offsets, samples.sampling, index, frame)
        }
        None => {
            let mut sink = FrameSink {
                frame,
                index,
                setup: &setup,
            };
            traverse::traverse(&setup, &mut sink);
        }
    }
}

/// Writes covered pixels, and their interpolated values, into a frame.
struct FrameSink<'a, E> {
    frame: &'a mut Frame,
    index: usize,
    setup: &'a TriangleSetup<E>,
}

impl<E: EdgeInt> Sink for FrameSink<'_, E> {
    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        let width = self.frame.width as usize;
        let row = y as usize * width;
        for x in x0..x1 {
            self.frame.hit(row + x as usize, self.index);
        }
        if matches!(self.setup.shading, Shading::None) {
            return;
        }
        // The exact edge values at the span's first pixel, bias removed,
        // then stepped pixel by pixel.
        let mut e = self.setup.edges.map(|edge| edge.at(x0, y) - edge.bias);
        for x in x0..x1 {
            self.setup.shading.write(self.frame, row + x as usize, e);
            for (value, edge) in e.iter_mut().zip(&self.setup.edges) {
                *value = *value + edge.step_x;
            }
        }
    }
}
