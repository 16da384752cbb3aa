//! A scene placed in production's fixed point, ready to be drawn: the
//! format, every kept primitive's vertices in it, and the samples' offsets.
//! Placing (snapping exact rationals onto the grid) is production's
//! conversion of its input, as building paths is a path filler's; drawing
//! is everything after. [`draw_frame`] does both at once;
//! [`PreparedFrame`] places once and draws again and again into one frame,
//! which is how `rastercheck bench` times production's own draw.

use super::antialias::sampling::{Samples, Sampling};
use super::fixed::{EdgeInt, Fixed, Format};
use super::line::{self, Geometry};
use super::primitive::{draw_primitive, Target};
use super::scene_format::{format_for, place};
use super::sweep::{Rows, Swept};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Prepared, RasterError};
use crate::scene::{LastPixel, LineRule, Primitive, Scene};

/// Production's frame of the primitives `keep` selects (by index in the
/// scene), drawn as a plan without motion says: the whole scene, or the
/// static primitives of a moving one, drawn once ([`motion`](super::motion)).
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

/// A static scene (or the static primitives of a moving one) in fixed
/// point.
pub(crate) struct Placed<'a> {
    scene: &'a Scene,
    plan: &'a Plan,
    samples: Option<Samples<'a>>,
    format: Format,
    /// The samples' offsets in `format`, when the scene antialiases.
    offsets: Option<Vec<[i64; 2]>>,
    what: Kept,
}

/// What is drawn.
enum Kept {
    /// Coverage-only `midpoint` lines, drawn together band by band
    /// ([`line::midpoint_lines`]).
    MidpointLines(Vec<(usize, Geometry, LastPixel)>),
    /// Coverage-only triangles, one sample per pixel: swept band by band
    /// ([`sweep`]; one band of the whole frame for small triangles). The
    /// vertices as in `Primitives`.
    Triangles(Swept),
    /// Primitives by index, with their vertices (a line's two ends, the
    /// second repeated; nothing for a polygon, which places its own).
    Primitives(Vec<(usize, [[Fixed; 2]; 3])>),
}

impl<'a> Placed<'a> {
    /// Places the primitives `keep` selects (by index in the scene), for a
    /// plan without motion.
    pub(crate) fn new(
        scene: &'a Scene,
        plan: &'a Plan,
        sampling: Sampling,
        keep: impl Fn(usize) -> bool,
    ) -> Result<Placed<'a>, RasterError> {
        debug_assert!(plan.motion.is_none());
        let samples = plan
            .antialias
            .as_ref()
            .map(|plan| Samples { plan, sampling });
        let format = format_for(scene, samples.as_ref())?;
        let at =
            |v: &crate::scene::Vertex| [place(scene, format, &v.x), place(scene, format, &v.y)];
        let kept = || {
            scene
                .primitives
                .iter()
                .enumerate()
                .filter(|&(index, _)| keep(index))
        };
        let coverage_only = samples.is_none() && !plan.interpolates();
        let midpoint =
            |p: &Primitive| matches!(p, Primitive::Line(l) if l.rule == LineRule::Midpoint);
        let what = if coverage_only && kept().all(|(_, p)| midpoint(p)) {
            Kept::MidpointLines(
                kept()
                    .map(|(index, p)| {
                        let Primitive::Line(l) = p else {
                            unreachable!("every kept primitive is a line")
                        };
                        let ends = l.vertices.each_ref().map(at);
                        (index, Geometry::new(ends), l.last_pixel)
                    })
                    .collect(),
            )
        } else {
            let placed: Vec<(usize, [[Fixed; 2]; 3])> = kept()
                .map(|(index, p)| {
                    let points = match p {
                        Primitive::Triangle(t) => t.vertices.each_ref().map(at),
                        Primitive::Line(l) => {
                            let [a, b] = l.vertices.each_ref().map(at);
                            [a, b, b]
                        }
                        Primitive::Polygon(_) => [[Fixed(0); 2]; 3],
                        Primitive::Point(p) => [at(&p.vertices[0]); 3],
                    };
                    (index, points)
                })
                .collect();
            let triangle = |p: &Primitive| matches!(p, Primitive::Triangle(_));
            if coverage_only && kept().all(|(_, p)| triangle(p)) {
                Kept::Triangles(Swept::new(format, placed))
            } else {
                Kept::Primitives(placed)
            }
        };
        let offsets = samples.as_ref().map(|s| s.offsets_in(format));
        Ok(Placed {
            scene,
            plan,
            samples,
            format,
            offsets,
            what,
        })
    }

    /// Draws the primitives, in scene order, into `frame` as it stands (a
    /// frame of the plan's shape), and resolves it when antialiased.
    pub(crate) fn draw(&self, frame: &mut Frame) -> Result<(), RasterError> {
        match &self.what {
            Kept::MidpointLines(lines) => {
                line::midpoint_lines(lines, self.format, self.scene.canvas, frame);
                return Ok(());
            }
            Kept::Triangles(swept) => {
                let rows = Rows {
                    coverage: &mut frame.coverage,
                    last: &mut frame.last,
                    width: self.scene.canvas.width as usize,
                    rows_from: 0,
                };
                swept.draw(self.scene, rows);
                return Ok(());
            }
            Kept::Primitives(primitives) => {
                if self.format.fits_i64() {
                    self.draw_all::<i64>(primitives, frame)?;
                } else {
                    self.draw_all::<i128>(primitives, frame)?;
                }
            }
        }
        if self.samples.is_some() {
            frame.resolve();
        }
        Ok(())
    }

    fn draw_all<E: EdgeInt>(
        &self,
        primitives: &[(usize, [[Fixed; 2]; 3])],
        frame: &mut Frame,
    ) -> Result<(), RasterError> {
        let target = Target {
            canvas: self.scene.canvas,
            rows_from: 0,
        };
        for (k, &(index, points)) in primitives.iter().enumerate() {
            if k % 64 == 0 {
                // The per-case time limit, polled every few primitives.
                crate::deadline::check();
            }
            draw_primitive::<E>(
                self.scene,
                self.plan,
                self.format,
                self.samples.as_ref(),
                self.offsets.as_deref(),
                index,
                points,
                target,
                frame,
            )?;
        }
        Ok(())
    }

    /// An empty frame of the plan's shape, for the scene's canvas.
    pub(crate) fn empty_frame(&self) -> Frame {
        Frame::for_plan(self.scene.canvas.width, self.scene.canvas.height, self.plan)
    }
}

/// Production's draw with the scene placed once and one frame reused:
/// [`Prepared::draw`] is [`Placed::draw`] alone, with nothing allocated.
pub(crate) struct PreparedFrame<'a> {
    pub(crate) placed: Placed<'a>,
    pub(crate) frame: Frame,
}

impl Prepared for PreparedFrame<'_> {
    fn clear(&mut self) -> Result<(), RasterError> {
        self.frame.clear();
        Ok(())
    }

    fn draw(&mut self) -> Result<(), RasterError> {
        self.placed.draw(&mut self.frame)
    }

    fn read_back(&mut self) -> Result<Frame, RasterError> {
        Ok(self.frame.clone())
    }
}
