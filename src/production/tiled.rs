//! `production-tiled`: production drawn band by band in parallel.
//!
//! The canvas is cut into tiles of [`BAND`] pixel rows across its whole
//! width (a band's samples are one contiguous run of every frame buffer, so
//! the bands are disjoint slices). Each primitive is binned to the bands its
//! vertical extent meets, and each band draws its primitives in scene order
//! into a frame of its own with production's code, the vertices moved up by
//! the band's first row: edge functions and tie rules are exact integers,
//! unchanged by a move of whole pixels, so the band holds exactly the
//! samples, last primitives and values of its rows that production writes.
//! The bands are drawn on the current rayon pool and copied into the frame.
//!
//! Coverage-only triangles, the commonest scene, take the sweep instead
//! (`sweep.rs`, production's own road for them): the frame is cut into a
//! few regions per thread of whole sweep bands, and each region is swept
//! on its own straight into its rows of the frame ([`Tiled::prepare`]
//! places the scene once for that road).
//!
//! What this module does not do: polygons (a scene with one is drawn by
//! production alone, on one thread), scenes in which something moves
//! (production's time loop draws them, its rows in parallel), and coordinates or canvases beyond
//! 2^14 px (drawn by production alone too: moving a vertex by up to a
//! canvas's height must stay within the bounds production's integers were
//! sized for).

use rayon::prelude::*;

use super::antialias::sampling::{Samples, Sampling};
use super::dispatch::Production;
use super::fixed::{EdgeInt, Fixed, Format};
use super::primitive::{draw_primitive, Target};
use super::scene_format::{format_for, place};
use super::sweep::{band_rows, Rows, Swept};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{Canvas, Primitive, Scene};

/// Pixel rows per band: small enough that two threads share even a small
/// canvas in many pieces (a thread the scheduler puts off leaves few rows
/// behind), large enough that most small triangles are set up once.
pub const BAND: u32 = 16;

/// Coordinates (in pixels) and canvas sides up to which bands are drawn.
const SAFE: i64 = 1 << 14;

/// Production, drawn in bands on the current rayon pool; its frame is
/// production's.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tiled;

impl Rasterizer for Tiled {
    fn name(&self) -> &str {
        "production-tiled"
    }

    /// Production's, but screen space only: clip-space scenes are not tiled.
    fn capabilities(&self) -> Capabilities {
        Capabilities {
            clip_space: false,
            depth_attachment: false,
            ..Production.capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.motion.is_some() {
            // Production's time loop, whose rows run on the current pool.
            return Production.rasterize(scene, plan);
        }
        let Some((samples, format, points)) = placed(scene, plan)? else {
            return Production.rasterize(scene, plan);
        };
        if swept(scene, plan) {
            let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
            draw_swept(scene, &for_sweep(format, &points), &mut frame);
            return Ok(frame);
        }
        // One bit of integer range more than production's: a band moves
        // vertices by up to the canvas's height.
        if format.frac_bits < super::fixed::I64_MAX_FRAC_BITS {
            draw::<i64>(scene, plan, format, samples.as_ref(), &points)
        } else {
            draw::<i128>(scene, plan, format, samples.as_ref(), &points)
        }
    }

    /// Coverage-only triangle scenes, the sweep's: placed once, drawn into
    /// one frame.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        if plan.motion.is_some() || !swept(scene, plan) {
            return None;
        }
        let (_, format, points) = match placed(scene, plan) {
            Ok(Some(placed)) => placed,
            Ok(None) => return None,
            Err(e) => return Some(Err(e)),
        };
        let frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
        Some(Ok(Box::new(PreparedSweep {
            scene,
            swept: for_sweep(format, &points),
            frame,
        })))
    }
}

/// Whether a scene is drawn by the sweep: triangles only, coverage only,
/// one sample per pixel.
fn swept(scene: &Scene, plan: &Plan) -> bool {
    plan.antialias.is_none()
        && !plan.interpolates()
        && scene
            .primitives
            .iter()
            .all(|p| matches!(p, Primitive::Triangle(_)))
}

/// The scene's samples, format and every primitive's vertices in it (a
/// line's second end repeated), placed in parallel (the costly part for
/// small triangles); `None` for a scene production draws alone.
#[allow(clippy::type_complexity)]
fn placed<'a>(
    scene: &'a Scene,
    plan: &'a Plan,
) -> Result<Option<(Option<Samples<'a>>, Format, Vec<[[Fixed; 2]; 3]>)>, RasterError> {
    if scene.has_polygons() || i64::from(scene.canvas.height) > SAFE {
        return Ok(None);
    }
    let sampling = Sampling::for_plan(plan);
    let samples = plan
        .antialias
        .as_ref()
        .map(|plan| Samples { plan, sampling });
    let format = format_for(scene, samples.as_ref())?;
    let points: Vec<[[Fixed; 2]; 3]> = scene
        .primitives
        .par_iter()
        .map(|p| {
            let at =
                |v: &crate::scene::Vertex| [place(scene, format, &v.x), place(scene, format, &v.y)];
            match p {
                Primitive::Triangle(t) => t.vertices.each_ref().map(at),
                Primitive::Line(l) => {
                    let [a, b] = l.vertices.each_ref().map(at);
                    [a, b, b]
                }
                Primitive::Polygon(_) => unreachable!("polygons are drawn by production"),
                Primitive::Point(p) => [at(&p.vertices[0]); 3],
            }
        })
        .collect();
    let limit = SAFE * format.one();
    if points.iter().flatten().flatten().any(|c| c.0.abs() > limit) {
        return Ok(None);
    }
    Ok(Some((samples, format, points)))
}

/// The sweep's draw with the scene placed once and one frame reused.
struct PreparedSweep<'a> {
    scene: &'a Scene,
    swept: Swept,
    frame: Frame,
}

impl Prepared for PreparedSweep<'_> {
    fn clear(&mut self) -> Result<(), RasterError> {
        self.frame.clear();
        Ok(())
    }

    fn draw(&mut self) -> Result<(), RasterError> {
        draw_swept(self.scene, &self.swept, &mut self.frame);
        Ok(())
    }

    fn read_back(&mut self) -> Result<Frame, RasterError> {
        Ok(self.frame.clone())
    }
}

/// The bands (first, last inclusive) primitive `p` may draw in.
fn bands_of(scene: &Scene, format: Format, p: usize, points: &[[Fixed; 2]; 3]) -> (i64, i64) {
    let one = format.one();
    let lo = points.iter().map(|q| q[1].0).min().unwrap().div_euclid(one);
    let hi = points.iter().map(|q| q[1].0).max().unwrap().div_euclid(one);
    // A pixel row whose centre or square meets the extent lies within one
    // row of it; a wide line reaches its half width (and a rectangle's
    // caps as much again) beyond its ends, a point half its size (at most
    // 512 pixels) beyond its centre.
    let margin = match &scene.primitives[p] {
        Primitive::Point(point) => point.size.to_f64_lossy().ceil() as i64 / 2 + 2,
        Primitive::Line(l) => {
            let w = l.width.to_f64_lossy();
            if w.is_finite() && w < SAFE as f64 {
                w.ceil() as i64 + 2
            } else {
                2 * SAFE
            }
        }
        _ => 1,
    };
    let band = i64::from(BAND);
    (
        (lo - margin).div_euclid(band),
        (hi + margin).div_euclid(band),
    )
}

/// One band's share of the frame's buffers.
struct BandSlices<'a> {
    coverage: &'a mut [u16],
    last: &'a mut [u32],
    depth: Option<&'a mut [f64]>,
    attributes: Vec<&'a mut [f64]>,
    resolved: Option<&'a mut [f64]>,
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    samples: Option<&Samples>,
    points: &[[[Fixed; 2]; 3]],
) -> Result<Frame, RasterError> {
    let canvas = scene.canvas;
    let bands = canvas.height.div_ceil(BAND) as usize;
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands.max(1)];
    for (p, pts) in points.iter().enumerate() {
        let (first, last) = bands_of(scene, format, p, pts);
        let first = first.max(0) as usize;
        let last = last.min(bands as i64 - 1);
        if last < first as i64 {
            // Off the canvas: drawn in band 0 anyway, so that its errors
            // are production's.
            bins[0].push(p as u32);
            continue;
        }
        for bin in &mut bins[first..=last as usize] {
            bin.push(p as u32);
        }
    }
    let mut frame = Frame::for_plan(canvas.width, canvas.height, plan);
    let offsets = samples.map(|s| s.offsets_in(format));
    let width = canvas.width as usize;
    let slots = width * BAND as usize * frame.samples as usize;
    let pixels = width * BAND as usize;
    let mut slices: Vec<BandSlices> = frame
        .coverage
        .chunks_mut(slots.max(1))
        .zip(frame.last.chunks_mut(slots.max(1)))
        .map(|(coverage, last)| BandSlices {
            coverage,
            last,
            depth: None,
            attributes: Vec::new(),
            resolved: None,
        })
        .collect();
    if let Some(depth) = frame.depth.as_mut() {
        for (s, d) in slices.iter_mut().zip(depth.chunks_mut(slots.max(1))) {
            s.depth = Some(d);
        }
    }
    for channel in &mut frame.attributes {
        for (s, a) in slices.iter_mut().zip(channel.chunks_mut(slots.max(1))) {
            s.attributes.push(a);
        }
    }
    if let Some(resolved) = frame.resolved.as_mut() {
        for (s, r) in slices.iter_mut().zip(resolved.chunks_mut(pixels.max(1))) {
            s.resolved = Some(r);
        }
    }
    // Each band's first error, with its primitive, to report production's
    // (the lowest primitive's).
    let errors: Vec<(usize, RasterError)> = slices
        .into_par_iter()
        .enumerate()
        .filter_map(|(b, out)| {
            let rows_from = b as u32 * BAND;
            let rows = BAND.min(canvas.height - rows_from);
            let band_canvas = Canvas {
                width: canvas.width,
                height: rows,
            };
            let mut band = Frame::for_plan(canvas.width, rows, plan);
            let target = Target {
                canvas: band_canvas,
                rows_from: i64::from(rows_from),
            };
            for &p in &bins[b] {
                let p = p as usize;
                if let Err(e) = draw_primitive::<E>(
                    scene,
                    plan,
                    format,
                    samples,
                    offsets.as_deref(),
                    p,
                    points[p],
                    target,
                    &mut band,
                ) {
                    return Some((p, e));
                }
            }
            if samples.is_some() {
                band.resolve();
            }
            out.coverage.copy_from_slice(&band.coverage);
            out.last.copy_from_slice(&band.last);
            if let (Some(d), Some(from)) = (out.depth, &band.depth) {
                d.copy_from_slice(from);
            }
            for (a, from) in out.attributes.into_iter().zip(&band.attributes) {
                a.copy_from_slice(from);
            }
            if let (Some(r), Some(from)) = (out.resolved, &band.resolved) {
                r.copy_from_slice(from);
            }
            None
        })
        .collect();
    if let Some((_, e)) = errors.into_iter().min_by_key(|(p, _)| *p) {
        return Err(e);
    }
    Ok(frame)
}

/// Coverage-only triangles, the common case: the frame cut into regions of
/// whole sweep bands, each swept on its own ([`sweep`]) straight into its
/// rows of the frame. A triangle is set up once in every region it
/// reaches; more regions than threads keep both threads busy to the end.
fn draw_swept(scene: &Scene, swept: &Swept, frame: &mut Frame) {
    let canvas = scene.canvas;
    let width = canvas.width as usize;
    let band = band_rows(canvas.width) as usize;
    let threads = rayon::current_num_threads().max(1);
    let bands = (canvas.height as usize).div_ceil(band);
    let region = band * bands.div_ceil(REGIONS_PER_THREAD * threads).max(1);
    let slots = (width * region).max(1);
    frame
        .coverage
        .par_chunks_mut(slots)
        .zip(frame.last.par_chunks_mut(slots))
        .enumerate()
        .with_max_len(1)
        .for_each(|(r, (coverage, last))| {
            let rows = Rows {
                coverage,
                last,
                width,
                rows_from: (r * region) as i64,
            };
            swept.draw(scene, rows);
        });
}

/// Every primitive (all triangles) with its index, ready to be swept.
fn for_sweep(format: Format, points: &[[[Fixed; 2]; 3]]) -> Swept {
    Swept::new(format, points.iter().copied().enumerate().collect())
}

/// Regions per thread of the coverage-only sweep.
const REGIONS_PER_THREAD: usize = 8;
