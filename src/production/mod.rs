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
//! A clip-space scene (SPEC.md §16) goes whole to `clip/` instead, whose
//! `mod.rs` gives its own order (clip, project, rasterize, shade).
//!
//! The methods measured on their own reuse that path: `tiled.rs` (bands
//! drawn in parallel through [`draw_primitive`]), `antialias/`
//! (`adaptive-refine`, `adaptive-resolve`, `area-f32`), `polygon/`'s other
//! fills, `foils/` (float DDA, float edge functions, and three that do not
//! sample at the centre: at (1, 1), by area, by any coverage) and
//! `mutants.rs` (one deliberate bug each).

pub mod antialias;
pub mod clip;
pub mod fixed;
pub mod foils;
pub mod line;
pub mod motion;
pub mod mutants;
mod placed;
pub mod polygon;
pub mod setup;
mod sweep;
pub mod tiled;
pub mod traverse;
mod triangle;

use antialias::{Samples, Sampling};
use fixed::{EdgeInt, Fixed, Format};

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{Number, Primitive, Scene};
use placed::{Placed, PreparedFrame};

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
        if scene.in_clip_space() {
            return clip::rasterize(scene, plan);
        }
        rasterize_with(scene, plan, Sampling::for_plan(plan))
    }

    /// Any scene without motion: placed once, drawn into one frame.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        if plan.motion.is_some() || scene.in_clip_space() {
            return None;
        }
        Some(
            Placed::new(scene, plan, Sampling::for_plan(plan), |_| true).map(|placed| {
                let frame = placed.empty_frame();
                Box::new(PreparedFrame { placed, frame }) as Box<dyn Prepared>
            }),
        )
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
    let placed = Placed::new(scene, plan, sampling, keep)?;
    let mut frame = placed.empty_frame();
    placed.draw(&mut frame)?;
    Ok(frame)
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
                scene.rules.provoking_vertex,
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
        Primitive::Point(_) => {
            return Err(RasterError::Unsupported(
                "production draws no points".to_owned(),
            ))
        }
    }
    Ok(())
}
