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
//! close by production's own snapping ([`place`](crate::production::scene_format::place)), so 2^32 times it,
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
//! static path at the same spatial samples ([`draw_frame`]), and a
//! sample one covers counts as covered at all N instants: the frame's
//! [`SampleTests`] counts the tests of moving primitives alone. A moving
//! primitive is tested only at samples inside its swept bounding box, the
//! box of its positions at shutter open and close, which holds it at every
//! instant between (each vertex moves on a segment).
//!
//! What this does not do: moving polygons and moving lines of the
//! other rules (the case reader refuses them, SPEC.md §15.1), and values
//! (a moving scene has no depth or attributes).

use rayon::prelude::*;

use super::exact::TIME_BITS;
use super::mover::Mover;
use crate::frame::{Frame, SampleTests};
use crate::plan::Plan;
use crate::production::antialias::sampling::{Samples, Sampling};
use crate::production::fixed::Format;
use crate::production::placed::draw_frame;
use crate::production::scene_format::format_for;
use crate::rasterizer::RasterError;
use crate::scene::{Canvas, FillRule, MotionBlur, Scene};

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
