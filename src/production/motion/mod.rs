//! Motion blur in production (SPEC.md §15.3): every spatial sample of a
//! pixel tested at its N instants against each moving primitive, each test
//! decided exactly in fixed point.
//!
//! This file is the time loop: which samples and instants each moving
//! primitive is tested at, and the frame they add up to. One test at one
//! instant is `exact.rs`'s; the fast road for coarse triangles is
//! `fast.rs`.
//!
//! Every instant of §15.3 is τ = t/2^32 for an integer t ≤ 2^32. A vertex at
//! τ is (1 − τ)·A + τ·B, A and B its positions snapped at shutter open and
//! close by production's own snapping ([`super::place`]), so 2^32 times it,
//! (2^32 − t)·A + t·B = 2^32·A + t·(B − A), is an integer in units of
//! 2^-(f+32) px at the fixed-point format of f fraction bits: the primitive
//! at τ exactly, snapped at its ends only. A test then decides the sample
//! as the static path decides one (`setup::setup_in`, SPEC.md §3): nothing
//! at zero area, the cull applied to the winding at τ, each edge's cross
//! product with the sample positive, or zero on an edge that owns it by
//! production's [`setup::edge_owned`] on the edge's direction at τ. A moving
//! `parallelogram` line is its two triangles at τ with the minor axis of
//! its direction at τ, as `line::parallelogram` builds them (SPEC.md §4.4).
//!
//! Triangles in formats of up to [`FAST_MAX_FRAC_BITS`] fraction bits (12
//! subpixel bits) take a faster road to the same integers: each edge
//! function at a sample, and twice the area, is a quadratic in τ
//! ([`Quadratic`]), set up once per sample and evaluated exactly at each of
//! its instants, about 3× faster than placing the vertices at every
//! instant. Finer triangles, and parallelograms, place their vertices at
//! each instant and compare products in 256 bits where i128 does not hold
//! them.
//!
//! Static primitives of a moving scene are drawn once, by production's
//! static path at the same spatial samples ([`super::draw_frame`]), and a
//! sample one covers counts as covered at all N instants: the frame's
//! [`SampleTests`] counts the tests of moving primitives alone. A moving
//! primitive is tested only at samples inside its swept bounding box, the
//! box of its positions at shutter open and close, which holds it at every
//! instant between (each vertex moves on a segment).
//!
//! What this module does not do: moving polygons and moving lines of the
//! other rules (the case reader refuses them, SPEC.md §15.1), and values
//! (a moving scene has no depth or attributes).

mod exact;
mod fast;

use std::ops::Range;

use rayon::prelude::*;

use exact::{edge_owned, sub, triangle_covers, Point, TIME_BITS};
use fast::{Fast, Quadratic, FAST_MAX_FRAC_BITS};

use super::antialias::sampling::{Samples, Sampling};
use super::fixed::{Format, MAX_FRAC_BITS};
use super::placed::draw_frame;
use super::scene_format::{format_for, place};
use crate::frame::{Frame, SampleTests};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Canvas, Cull, FillRule, LineRule, MotionBlur, Primitive, Scene, Vertex};

/// A moving primitive's vertices: 2^32 times each at shutter open of the
/// case (τ = 0), and its motion to τ = 1, B − A; at instant t the vertex is
/// `from + t·velocity`.
#[derive(Clone, Debug)]
struct Path<const K: usize> {
    from: [Point; K],
    velocity: [Point; K],
}

impl<const K: usize> Path<K> {
    /// `ends[i]` holds vertex i snapped at τ = 0 and τ = 1.
    fn new(ends: [[[i64; 2]; 2]; K]) -> Path<K> {
        Path {
            from: ends.map(|[a, _]| a.map(|c| i128::from(c) << TIME_BITS)),
            velocity: ends.map(|[a, b]| [0, 1].map(|k| i128::from(b[k]) - i128::from(a[k]))),
        }
    }

    #[inline]
    fn at(&self, t: i128) -> [Point; K] {
        std::array::from_fn(|i| [0, 1].map(|k| self.from[i][k] + t * self.velocity[i][k]))
    }
}

#[derive(Clone, Debug)]
enum Shape {
    /// A triangle in a format of at most [`FAST_MAX_FRAC_BITS`].
    Fast(Box<Fast>),
    /// Any triangle, its positions at each instant compared in 256 bits
    /// where i128 does not hold the products.
    Triangle { path: Path<3>, cull: Cull },
    /// A `parallelogram` line: its two ends, and 2^32 times half its width.
    Parallelogram { path: Path<2>, half: i128 },
}

/// A moving primitive ready to be tested.
#[derive(Clone, Debug)]
struct Mover {
    shape: Shape,
    /// Fraction bits of its format above the scene's (a parallelogram may
    /// need a finer one for half its width): what a sample is shifted by.
    shift: u32,
    /// Its swept bounding box, closed, in its own units of 2^-(f+32) px.
    lo: Point,
    hi: Point,
    /// The pixels that may hold a sample in the box, clipped to the canvas.
    columns: Range<i64>,
    rows: Range<i64>,
}

impl Mover {
    fn new(
        scene: &Scene,
        primitive: &Primitive,
        format: Format,
        blur: &MotionBlur,
    ) -> Result<Mover, RasterError> {
        let ends = |v: &Vertex, shift: u32| -> [[i64; 2]; 2] {
            let [ex, ey] = v.end();
            [[&v.x, &v.y], [ex, ey]].map(|p| p.map(|c| place(scene, format, c).0 << shift))
        };
        // The shape; its vertices at τ = 0 and 1 and how far beyond them
        // it reaches, for the swept box.
        let (shape, shift, vertices, margin) = match primitive {
            Primitive::Triangle(t) => {
                let vertices = t.vertices.each_ref().map(|v| ends(v, 0));
                let shape = if format.frac_bits <= FAST_MAX_FRAC_BITS {
                    Shape::Fast(Box::new(Fast::new(vertices, scene.rules.cull)))
                } else {
                    Shape::Triangle {
                        path: Path::new(vertices),
                        cull: scene.rules.cull,
                    }
                };
                (shape, 0, vertices.to_vec(), 0)
            }
            Primitive::Line(line) if line.rule == LineRule::Parallelogram => {
                // As `line::parallelogram`: the first format, from the
                // scene's on, in which half the width is exact (width/2 in
                // units of 2^-f is width in units of 2^-(f − 1)).
                let (fine, half) = (format.frac_bits..=MAX_FRAC_BITS)
                    .find_map(|frac_bits| {
                        let half = Format {
                            frac_bits: frac_bits - 1,
                        }
                        .exact(&line.width)?;
                        Some((frac_bits, half.0))
                    })
                    .ok_or_else(|| {
                        RasterError::Unsupported(format!(
                            "a parallelogram line's corners need half its width in fixed \
                             point, and width {} is not a multiple of 2^-{}",
                            line.width.to_exact_string(),
                            MAX_FRAC_BITS - 1
                        ))
                    })?;
                let shift = fine - format.frac_bits;
                let vertices = line.vertices.each_ref().map(|v| ends(v, shift));
                let half = i128::from(half) << TIME_BITS;
                (
                    Shape::Parallelogram {
                        path: Path::new(vertices),
                        half,
                    },
                    shift,
                    vertices.to_vec(),
                    // The corners lie half the width from the ends along
                    // one axis or the other.
                    half,
                )
            }
            Primitive::Line(line) => {
                return Err(RasterError::Unsupported(format!(
                    "only parallelogram lines can move (SPEC.md §15.1); this is a {} line",
                    line.rule.name()
                )))
            }
            Primitive::Polygon(_) => {
                return Err(RasterError::Unsupported(
                    "polygons cannot move (SPEC.md §15.1)".to_owned(),
                ))
            }
            Primitive::Point(_) => {
                return Err(RasterError::Unsupported(
                    "points cannot move (SPEC.md §17)".to_owned(),
                ))
            }
        };
        // The box of every vertex at the shutter's two ends.
        let [open, close] =
            [0, crate::scene::time::limits::TIME_ONE].map(|u| i128::from(blur.instant(u)));
        let points: Vec<Point> = vertices
            .iter()
            .flat_map(|&[a, b]| {
                [open, close].map(|t| {
                    [0, 1].map(|k| {
                        (i128::from(a[k]) << TIME_BITS) + t * (i128::from(b[k]) - i128::from(a[k]))
                    })
                })
            })
            .collect();
        let lo = [0, 1].map(|k| points.iter().map(|p| p[k]).min().unwrap() - margin);
        let hi = [0, 1].map(|k| points.iter().map(|p| p[k]).max().unwrap() + margin);
        // A sample i·one + o with o in [0, one) lies in [lo, hi] only in
        // pixels ⌊lo/one⌋ to ⌊hi/one⌋.
        let one = 1i128 << (format.frac_bits + shift + TIME_BITS);
        let pixels = |k: usize, size: u32| {
            let first = lo[k].div_euclid(one).max(0);
            let last = hi[k].div_euclid(one).min(i128::from(size) - 1);
            (first as i64)..(last as i64 + 1).max(first as i64)
        };
        Ok(Mover {
            shape,
            shift,
            lo,
            hi,
            columns: pixels(0, scene.canvas.width),
            rows: pixels(1, scene.canvas.height),
        })
    }

    /// A sample given in the scene's format, in this primitive's format.
    #[inline]
    fn sample(&self, q: [i64; 2]) -> Point {
        q.map(|c| i128::from(c) << self.shift)
    }

    /// Whether the sample (this primitive's format) lies in the swept
    /// bounding box: elsewhere the primitive covers it at no instant of the
    /// shutter.
    #[inline]
    fn sweeps(&self, q: Point) -> bool {
        (0..2).all(|k| self.lo[k] <= q[k] << TIME_BITS && q[k] << TIME_BITS <= self.hi[k])
    }

    /// The sample `q` (this primitive's format) set up for its tests.
    fn probe(&self, q: Point) -> Probe<'_> {
        match &self.shape {
            Shape::Fast(fast) => Probe::Fast(fast, fast.edges_at(q)),
            _ => Probe::Exact(self, q.map(|c| c << TIME_BITS)),
        }
    }

    /// Whether the primitive covers the sample `q` (units of 2^-(f+32)) at
    /// instant t/2^32, from its positions at t.
    fn covers(&self, q: Point, t: i128, rule: FillRule) -> bool {
        match &self.shape {
            Shape::Fast(_) => unreachable!("fast triangles are probed"),
            Shape::Triangle { path, cull } => {
                triangle_covers(path.at(t), q, *cull, |a, b| edge_owned(a, b, rule))
            }
            Shape::Parallelogram { path, half } => {
                let [v0, v1] = path.at(t);
                let d = sub(v1, v0);
                if d == [0, 0] {
                    return false;
                }
                // x-major when |dx| ≥ |dy|: the corners lie along y.
                let minor = usize::from(d[0].abs() >= d[1].abs());
                let corner = |p: Point, sign: i128| {
                    let mut c = p;
                    c[minor] += sign * half;
                    c
                };
                let (a, b, c, e) = (corner(v0, -1), corner(v1, -1), corner(v1, 1), corner(v0, 1));
                // ABC or ACE. They share only the diagonal AC, and a sample
                // is covered once whichever covers it, so the static path's
                // care to give the diagonal to one of them (it counts
                // coverage per triangle) changes nothing here.
                let owned = |p: Point, q: Point| edge_owned(p, q, rule);
                triangle_covers([a, b, c], q, Cull::None, owned)
                    || triangle_covers([a, c, e], q, Cull::None, owned)
            }
        }
    }
}

/// One sample of one moving primitive, ready for its N tests.
enum Probe<'a> {
    Fast(&'a Fast, [Quadratic; 3]),
    /// The sample in units of 2^-(f+32).
    Exact(&'a Mover, Point),
}

impl Probe<'_> {
    /// Whether the primitive covers the sample at instant t/2^32: one test.
    #[inline]
    fn covers(&self, t: i128, rule: FillRule) -> bool {
        match self {
            Probe::Fast(fast, edges) => fast.covers(edges, t, rule),
            Probe::Exact(mover, q) => mover.covers(*q, t, rule),
        }
    }
}

/// A moving scene ready to be sampled in time: its frame, and each test's
/// decision on its own for tests of production.
#[derive(Clone, Debug)]
pub struct Sampler {
    canvas: Canvas,
    blur: MotionBlur,
    format: Format,
    rule: FillRule,
    /// Each spatial sample's offset from its pixel's top-left corner in
    /// `format`: the plan's antialiasing offsets, or the pixel centre.
    offsets: Vec<[i64; 2]>,
    movers: Vec<Mover>,
    /// How many static primitives cover each spatial sample (sample s of
    /// pixel p at p·M + s), drawn once; `None` when every primitive moves.
    statics: Option<Vec<u16>>,
}

/// Production's frame of a scene in which something moves (`plan.motion`):
/// each pixel's time coverage, and the sample tests spent on moving
/// primitives.
pub fn rasterize(scene: &Scene, plan: &Plan, sampling: Sampling) -> Result<Frame, RasterError> {
    Ok(Sampler::new(scene, plan, sampling)?.frame())
}

impl Sampler {
    /// Sets up every moving primitive and draws the static ones. `sampling`
    /// decides the static primitives' antialiased samples, as in production's
    /// static path.
    pub fn new(scene: &Scene, plan: &Plan, sampling: Sampling) -> Result<Sampler, RasterError> {
        let motion = plan.motion.as_ref().ok_or_else(|| {
            RasterError::Failed("the time loop needs a plan with motion".to_owned())
        })?;
        if motion.moving.len() != scene.primitives.len() {
            return Err(RasterError::Failed(
                "the plan's moving primitives are not the scene's".to_owned(),
            ));
        }
        if scene.rules.subpixel_bits.is_none() {
            return Err(RasterError::Unsupported(
                "moving vertices snap at shutter open and close: a moving scene needs \
                 subpixel_bits"
                    .to_owned(),
            ));
        }
        let samples = plan
            .antialias
            .as_ref()
            .map(|plan| Samples { plan, sampling });
        let format = format_for(scene, samples.as_ref())?;
        let offsets = match &samples {
            Some(samples) => samples.offsets_in(format),
            None => vec![[format.one() / 2; 2]],
        };
        let movers = scene
            .primitives
            .iter()
            .zip(&motion.moving)
            .filter(|(_, &moving)| moving)
            .map(|(p, _)| Mover::new(scene, p, format, &motion.blur))
            .collect::<Result<Vec<_>, _>>()?;
        let statics = if motion.moving.iter().all(|&m| m) {
            None
        } else {
            let once = Plan {
                motion: None,
                ..plan.clone()
            };
            let frame = draw_frame(scene, &once, sampling, |i| !motion.moving[i])?;
            debug_assert_eq!(frame.samples as usize, offsets.len());
            Some(frame.coverage)
        };
        Ok(Sampler {
            canvas: scene.canvas,
            blur: motion.blur.clone(),
            format,
            rule: scene.rules.fill_rule,
            offsets,
            movers,
            statics,
        })
    }

    /// M: spatial samples per pixel.
    pub fn spatial_samples(&self) -> usize {
        self.offsets.len()
    }

    /// N: time samples per spatial sample.
    pub fn time_samples(&self) -> usize {
        self.blur.samples as usize
    }

    fn pixel_index(&self, x: i64, y: i64) -> usize {
        y as usize * self.canvas.width as usize + x as usize
    }

    /// Static primitives covering spatial sample `s` of pixel `p`.
    fn statics(&self, p: usize, s: usize) -> u32 {
        self.statics
            .as_ref()
            .map_or(0, |c| u32::from(c[p * self.offsets.len() + s]))
    }

    /// Spatial sample `s` of pixel (x, y) in the scene's format.
    fn sample_at(&self, x: i64, y: i64, s: usize) -> [i64; 2] {
        let one = self.format.one();
        let [ox, oy] = self.offsets[s];
        [x * one + ox, y * one + oy]
    }

    /// The pixel's u (SPEC.md §15.3), slot s·N + k for instant k of
    /// spatial sample s; its instant is `blur.instant(u)`/2^32.
    fn times(&self, x: i64, y: i64) -> Vec<u32> {
        let p = self.pixel_index(x, y) as u64;
        self.blur.pixel_times(p, self.offsets.len() as u32)
    }

    /// How many primitives cover spatial sample `s` of pixel (x, y) at the
    /// instant `instant`/2^32 (at most 2^32, any instant, inside the shutter
    /// or not): each moving primitive tested there, with no bounding box,
    /// plus the static ones. One test of the time loop, open to tests of
    /// production against the static rules at that instant.
    pub fn coverage_at(&self, x: u32, y: u32, s: usize, instant: u64) -> u32 {
        assert!(instant <= 1 << TIME_BITS, "an instant in [0, 1]");
        let (x, y) = (i64::from(x), i64::from(y));
        let q = self.sample_at(x, y, s);
        let moving = self
            .movers
            .iter()
            .filter(|m| m.probe(m.sample(q)).covers(i128::from(instant), self.rule))
            .count();
        moving as u32 + self.statics(self.pixel_index(x, y), s)
    }

    /// Pixel (x, y)'s tests as the time loop makes them: slot j = s·N + k
    /// holds how many primitives cover spatial sample s at the pixel's j-th
    /// instant, static ones included. The frame's time coverage of the
    /// pixel is their sum over M·N.
    pub fn slot_counts(&self, x: u32, y: u32) -> Vec<u32> {
        let (x, y) = (i64::from(x), i64::from(y));
        let n = self.time_samples();
        let p = self.pixel_index(x, y);
        let mut slots: Vec<u32> = (0..self.offsets.len() * n)
            .map(|j| self.statics(p, j / n))
            .collect();
        let movers: Vec<&Mover> = self.movers.iter().collect();
        self.test_pixel(x, y, &movers, &mut SampleTests::default(), |j| {
            slots[j] += 1
        });
        slots
    }

    /// Runs the tests of pixel (x, y) against `movers` (those whose rows
    /// hold it), counting them in `tests`; `hit(j)` for each covered one,
    /// j its slot.
    fn test_pixel(
        &self,
        x: i64,
        y: i64,
        movers: &[&Mover],
        tests: &mut SampleTests,
        mut hit: impl FnMut(usize),
    ) {
        let n = self.time_samples();
        let mut times: Option<Vec<u32>> = None;
        for mover in movers.iter().filter(|m| m.columns.contains(&x)) {
            for s in 0..self.offsets.len() {
                let q = mover.sample(self.sample_at(x, y, s));
                if !mover.sweeps(q) {
                    continue;
                }
                let times = times.get_or_insert_with(|| self.times(x, y));
                let probe = mover.probe(q);
                for (k, &u) in times[s * n..(s + 1) * n].iter().enumerate() {
                    tests.tests += 1;
                    if probe.covers(i128::from(self.blur.instant(u)), self.rule) {
                        tests.covered += 1;
                        hit(s * n + k);
                    }
                }
            }
        }
    }

    /// The frame: each pixel's time coverage, (N·static hits + covered
    /// tests)/(M·N), one exact quotient of integers rounded once, rows in
    /// parallel on the current rayon pool.
    pub fn frame(&self) -> Frame {
        let (width, height) = (self.canvas.width, self.canvas.height);
        let (m, n) = (self.offsets.len() as u64, self.time_samples() as u64);
        let mut time = vec![0.0; self.canvas.pixel_count()];
        let tests = time
            .par_chunks_mut(width.max(1) as usize)
            .enumerate()
            .map(|(y, row)| {
                let y = y as i64;
                let movers: Vec<&Mover> =
                    self.movers.iter().filter(|m| m.rows.contains(&y)).collect();
                let mut tests = SampleTests::default();
                for (x, value) in row.iter_mut().enumerate() {
                    let x = x as i64;
                    let p = self.pixel_index(x, y);
                    let still: u64 = (0..m as usize).map(|s| u64::from(self.statics(p, s))).sum();
                    let mut covered = 0u64;
                    self.test_pixel(x, y, &movers, &mut tests, |_| covered += 1);
                    *value = (still * n + covered) as f64 / (m * n) as f64;
                }
                tests
            })
            .reduce(SampleTests::default, |a, b| SampleTests {
                tests: a.tests + b.tests,
                covered: a.covered + b.covered,
            });
        let mut frame = Frame::time_only(width, height, time);
        frame.sample_tests = Some(tests);
        frame
    }
}
