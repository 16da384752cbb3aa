//! The production rasterizer: fixed point, integer coverage decisions,
//! f32 interpolation. It imports the scene model and the output types, and
//! never the reference.
//!
//! This file is the dispatcher, a scene to each primitive's path. A scene
//! flows through the files in this order:
//!
//! 1. [`Production::rasterize`]: a plan with motion goes to the time loop
//!    (`motion/`), which tests the moving primitives itself and draws the
//!    static ones from step 2 on ([`draw_frame`]).
//! 2. [`draw_frame`]: the fixed-point format (`fixed.rs`, [`format_for`]),
//!    every coordinate placed in it ([`place`]).
//! 3. A coverage-only scene of `midpoint` lines goes whole to
//!    `line/bands.rs`. Any other goes primitive by primitive, in scene
//!    order, through [`draw_primitive`] to its path:
//!    - a triangle: `triangle.rs`, then `setup.rs` (edge equations, tie
//!      bias, bounding box, interpolation set-up), then `traverse.rs` (8×8
//!      blocks, pixel centres) or `antialias/` (samples at the plan's
//!      offsets);
//!    - a line: `line/` (one file per rule; a parallelogram's two triangles
//!      go through `setup.rs` and `traverse.rs` or `antialias/` too);
//!    - a polygon: `polygon/` (scanline fill).
//! 4. An antialiased frame is resolved (`Frame::resolve`).
//!
//! The methods measured on their own reuse that path: `tiled.rs` (bands
//! drawn in parallel through [`draw_primitive`]), `antialias/`
//! (`adaptive-refine`, `adaptive-resolve`, `area-f32`), `polygon/`'s other
//! fills, `foils/` (float DDA and float edge functions) and `mutants.rs`
//! (one deliberate bug each).

pub mod antialias;
pub mod fixed;
pub mod foils;
pub mod line;
pub mod motion;
pub mod mutants;
pub mod polygon;
pub mod setup;
pub mod tiled;
pub mod traverse;
mod triangle;

use antialias::{Samples, Sampling};
use fixed::{EdgeInt, Fixed, Format};

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{LastPixel, LineRule, Number, Primitive, Scene};

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
    all.push(Method {
        name: "production-tiled",
        make: || Box::new(tiled::Tiled),
    });
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
            motion_blur: true,
            ..Capabilities::everything()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize_with(scene, plan, Sampling::for_plan(plan))
    }
}

/// Production's rasterizer with the antialiased scenes' samples decided by
/// `sampling` (ignored without antialiasing). A plan with motion goes to
/// the time loop ([`motion`]).
pub(crate) fn rasterize_with(
    scene: &Scene,
    plan: &Plan,
    sampling: Sampling,
) -> Result<Frame, RasterError> {
    if plan.motion.is_some() {
        return motion::rasterize(scene, plan, sampling);
    }
    draw_frame(scene, plan, sampling, |_| true)
}

/// Production's frame of the primitives `keep` selects (by index in the
/// scene), drawn as a plan without motion says: the whole scene, or the
/// static primitives of a moving one, drawn once ([`motion`]).
pub(crate) fn draw_frame(
    scene: &Scene,
    plan: &Plan,
    sampling: Sampling,
    keep: impl Fn(usize) -> bool,
) -> Result<Frame, RasterError> {
    debug_assert!(plan.motion.is_none());
    let samples = plan
        .antialias
        .as_ref()
        .map(|plan| Samples { plan, sampling });
    let format = format_for(scene, samples.as_ref())?;
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    if samples.is_none() && !plan.interpolates() {
        if let Some(lines) = coverage_midpoint_lines(scene, format, &keep) {
            line::midpoint_lines(&lines, format, scene.canvas, &mut frame);
            return Ok(frame);
        }
    }
    if format.fits_i64() {
        draw::<i64>(scene, plan, format, samples.as_ref(), &keep, &mut frame)?;
    } else {
        draw::<i128>(scene, plan, format, samples.as_ref(), &keep, &mut frame)?;
    }
    if samples.is_some() {
        frame.resolve();
    }
    Ok(frame)
}

/// The primitives `keep` selects, when every one is a `midpoint` line:
/// drawn coverage only, they go band by band ([`line::midpoint_lines`]).
fn coverage_midpoint_lines(
    scene: &Scene,
    format: Format,
    keep: &impl Fn(usize) -> bool,
) -> Option<Vec<(usize, line::Geometry, LastPixel)>> {
    let mut lines = Vec::new();
    for (index, primitive) in scene.primitives.iter().enumerate() {
        if !keep(index) {
            continue;
        }
        let Primitive::Line(l) = primitive else {
            return None;
        };
        if l.rule != LineRule::Midpoint {
            return None;
        }
        let ends = l
            .vertices
            .each_ref()
            .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]);
        lines.push((index, line::Geometry::new(ends), l.last_pixel));
    }
    Some(lines)
}

/// The fixed-point format production draws `scene` in: the snapping grid
/// one bit finer, or the exact coordinates' own, at least as fine as the
/// sample offsets.
pub(crate) fn format_for(scene: &Scene, samples: Option<&Samples>) -> Result<Format, RasterError> {
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
    // Sample offsets are integers in a format at least position_bits fine.
    Ok(match samples {
        Some(samples) => format.with_samples(samples.plan.position_bits),
        None => format,
    })
}

/// A coordinate in `format`, snapped or exact as the scene's rules say.
pub(crate) fn place(scene: &Scene, format: Format, n: &Number) -> Fixed {
    match scene.rules.subpixel_bits {
        Some(bits) => format.snap(n, bits),
        None => format
            .exact(n)
            .expect("format_for checked every coordinate"),
    }
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    samples: Option<&Samples>,
    keep: &impl Fn(usize) -> bool,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let offsets = samples.map(|s| s.offsets_in(format));
    let target = Target {
        canvas: scene.canvas,
        rows_from: 0,
    };
    for (index, primitive) in scene.primitives.iter().enumerate() {
        if index % 64 == 0 {
            // The per-case time limit, polled every few primitives.
            crate::deadline::check();
        }
        if !keep(index) {
            continue;
        }
        let points = match primitive {
            Primitive::Triangle(t) => t
                .vertices
                .each_ref()
                .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]),
            Primitive::Line(l) => {
                let [a, b] = l
                    .vertices
                    .each_ref()
                    .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]);
                [a, b, b]
            }
            Primitive::Polygon(_) => [[Fixed(0); 2]; 3],
        };
        draw_primitive::<E>(
            scene,
            plan,
            format,
            samples,
            offsets.as_deref(),
            index,
            points,
            target,
            frame,
        )?;
    }
    Ok(())
}

/// Where a primitive is drawn: into a frame of `canvas`'s size holding the
/// scene's pixel rows from `rows_from` on (a band of the scene's canvas
/// for [`tiled`], all of it otherwise).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Target {
    pub canvas: crate::scene::Canvas,
    pub rows_from: i64,
}

/// Draws primitive `index`, whose vertices (a line's two ends first) are
/// `points` in `format`, into `frame` as `target` says. Moving the
/// vertices up by whole pixel rows moves every edge function's value with
/// them exactly, so a band draws the very samples of its rows that the
/// whole canvas would.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_primitive<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    samples: Option<&Samples>,
    offsets: Option<&[[i64; 2]]>,
    index: usize,
    points: [[Fixed; 2]; 3],
    target: Target,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let shift = target.rows_from * format.one();
    let points = points.map(|[x, y]| [x, Fixed(y.0 - shift)]);
    match &scene.primitives[index] {
        Primitive::Triangle(triangle) => {
            let sampled = samples.zip(offsets);
            triangle::draw::<E>(
                scene,
                plan,
                format,
                sampled,
                index,
                triangle,
                points,
                target.canvas,
                frame,
            );
        }
        Primitive::Line(line) => {
            line::draw::<E>(
                line,
                [points[0], points[1]],
                format,
                scene.rules.fill_rule,
                target.canvas,
                plan,
                samples,
                index,
                frame,
            )?;
        }
        Primitive::Polygon(polygon) => {
            assert_eq!(
                target.rows_from, 0,
                "polygons are drawn on the whole canvas"
            );
            polygon::draw::<E>(scene, plan, format, index, polygon, frame)?;
        }
    }
    Ok(())
}
