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

use fixed::{EdgeInt, Fixed, Format};
use glam::Vec3;
use setup::{Shading, TriangleSetup};
use traverse::Sink;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Interpolation, Number, Primitive, Scene, Triangle};

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
            polygons: false,
            antialias: false,
            ..Capabilities::everything()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
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
        let mut frame = Frame::new(
            scene.canvas.width,
            scene.canvas.height,
            plan.depth,
            plan.attributes,
        );
        if format.fits_i64() {
            draw::<i64>(scene, plan, format, &mut frame)?;
        } else {
            draw::<i128>(scene, plan, format, &mut frame)?;
        }
        Ok(frame)
    }
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let place = |n: &Number| match scene.rules.subpixel_bits {
        Some(bits) => format.snap(n, bits),
        None => format
            .exact(n)
            .expect("Format::for_exact checked every coordinate"),
    };
    for (index, primitive) in scene.primitives.iter().enumerate() {
        match primitive {
            Primitive::Triangle(triangle) => {
                let positions = triangle
                    .vertices
                    .each_ref()
                    .map(|v| [place(&v.x), place(&v.y)]);
                draw_triangle::<E>(scene, plan, format, index, triangle, positions, frame);
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

fn draw_triangle<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    index: usize,
    triangle: &Triangle,
    positions: [[Fixed; 2]; 3],
    frame: &mut Frame,
) {
    let Some(setup) = setup::setup::<E>(
        positions,
        triangle,
        format,
        scene.rules.fill_rule,
        scene.rules.cull,
        scene.canvas,
        plan,
    ) else {
        return;
    };
    let mut sink = FrameSink {
        frame,
        index,
        setup: &setup,
    };
    traverse::traverse(&setup, &mut sink);
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
        let Shading::Values {
            interpolation,
            inv_area,
            opposite,
            depth,
            attributes,
            inv_w,
        } = &self.setup.shading
        else {
            return;
        };
        // The exact edge values at the span's first pixel, bias removed,
        // then stepped pixel by pixel.
        let mut e = self.setup.edges.map(|edge| edge.at(x0, y) - edge.bias);
        for x in x0..x1 {
            let i = row + x as usize;
            // λ for each vertex in the case's order.
            let mut weight = Vec3::ZERO;
            for k in 0..3 {
                weight[opposite[k]] = (e[k].to_f64() * inv_area) as f32;
                e[k] = e[k] + self.setup.edges[k].step_x;
            }
            let blend = |v: &Vec3| weight.dot(*v);
            if let (Some(z), Some(out)) = (depth, self.frame.depth.as_mut()) {
                out[i] = f64::from(blend(z));
            }
            let perspective_w = match interpolation {
                Interpolation::Perspective => blend(inv_w),
                _ => 1.0,
            };
            for (channel, values) in self.frame.attributes.iter_mut().zip(attributes) {
                let value = match interpolation {
                    Interpolation::Flat => values.x,
                    Interpolation::Linear => blend(values),
                    Interpolation::Perspective => blend(values) / perspective_w,
                };
                channel[i] = f64::from(value);
            }
        }
    }
}
