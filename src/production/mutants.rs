//! Deliberately wrong rasterizers: the production rasterizer with one
//! realistic bug each. They exist to prove that every check can fail: each
//! is caught by a different metric (see tests/mutants/).
//!
//! A bug is applied by rewriting what production sees (the scene, or the
//! plan's sample offsets) or what it returns (the resolved coverage of an
//! antialiased frame); production itself is never changed.
//!
//! The motion mutants draw a moving scene as static scenes at chosen
//! instants ([`accumulate`]), with production's static path at the scene's
//! own spatial samples; the other mutants do not claim motion blur, since
//! a rewritten scene says nothing about the time loop.

use crate::frame::Frame;
use crate::plan::{MotionPlan, Plan};
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, Interpolation, LastPixel, LineRule, Number, Primitive, Scene};

/// A bug, applied by rewriting the scene the production rasterizer sees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mutation {
    /// The mirror-image tie rule (bottom-right for top-left): shared-edge
    /// samples go to the other triangle. Caught by coverage (wrong owner).
    FlippedTies,
    /// Every edge owns its samples: shared edges are drawn twice. Caught by
    /// watertightness (overdraw) and coverage.
    ClosedEdges,
    /// The first vertex of each triangle moved one subpixel right, as an
    /// off-by-one in snapping would. Caught by coverage on tie cases.
    VertexNudge,
    /// Every vertex pulled one subpixel toward its triangle's centroid, as an
    /// inward-rounding bug would: cracks open between neighbours. Caught by
    /// watertightness (holes).
    Shrunk,
    /// Perspective-correct interpolation done linearly in screen space.
    /// Caught by the interpolation error bound.
    NoPerspective,
    /// Midpoint lines drawn as one-pixel-wide rectangles: the "thin
    /// rectangle" mistaken for Bresenham. Caught by the one-pixel-per-step
    /// line metric and by coverage.
    ThickLines,
    /// Diamond-exit lines drawn by the half-open midpoint rule, as a driver
    /// that serves D3D-style lines with Bresenham would. Caught by coverage
    /// where the two rules part: corners, borders and ends.
    MidpointForDiamond,
    /// Every sample offset moved one lattice unit right (left from the last
    /// column), as a driver with an off-by-one sample table would. Caught
    /// by coverage at sample granularity where an edge passes between the
    /// two positions.
    ShiftedSamples,
    /// Resolved coverage rounded down to quarters, as a 2-bit coverage
    /// buffer would. Caught by the coverage error bounds and by the
    /// resolve check (the value is not the mask's box resolve).
    CoarseResolve,
    /// Fully covered pixels resolve to 1 − 2^-20, as an accumulation with a
    /// bias would. Caught by piglit's rule (full pixels are exactly 1).
    LeakyFull,
    /// Every moving primitive drawn where it is at shutter open, as a
    /// renderer that ignores the velocity would: time coverage 0 or 1 per
    /// spatial sample. Caught by the time-coverage RMS (and by
    /// `max_time_error` where a case gives one); not by the bias, since a
    /// primitive keeps its area at every instant and the errors cancel.
    MotionAtOpen,
    /// An accumulation buffer over the first half of the shutter only: the
    /// scene drawn at N instants, the midpoints of N equal strata of
    /// [open, (open + close)/2], the same at every pixel, as an off-by-two
    /// in the shutter's length would. Moving primitives cover only the
    /// first half of their path, twice as long; caught by the time-coverage
    /// RMS. (The same buffer over the whole shutter is not a bug these
    /// metrics catch: midpoints shared by every pixel err by at most about
    /// 1/N per edge, below the RMS bound, tests/mutants/ shows it. It
    /// strobes, but strobing is no error in any one pixel's mean.)
    MotionHalfShutter,
}

impl Mutation {
    pub const ALL: [Mutation; 12] = [
        Mutation::FlippedTies,
        Mutation::ClosedEdges,
        Mutation::VertexNudge,
        Mutation::Shrunk,
        Mutation::NoPerspective,
        Mutation::ThickLines,
        Mutation::MidpointForDiamond,
        Mutation::ShiftedSamples,
        Mutation::CoarseResolve,
        Mutation::LeakyFull,
        Mutation::MotionAtOpen,
        Mutation::MotionHalfShutter,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Mutation::FlippedTies => "mutant:flipped-ties",
            Mutation::ClosedEdges => "mutant:closed-edges",
            Mutation::VertexNudge => "mutant:vertex-nudge",
            Mutation::Shrunk => "mutant:shrunk",
            Mutation::NoPerspective => "mutant:no-perspective",
            Mutation::ThickLines => "mutant:thick-lines",
            Mutation::MidpointForDiamond => "mutant:midpoint-for-diamond",
            Mutation::ShiftedSamples => "mutant:shifted-samples",
            Mutation::CoarseResolve => "mutant:coarse-resolve",
            Mutation::LeakyFull => "mutant:leaky-full",
            Mutation::MotionAtOpen => "mutant:motion-at-open",
            Mutation::MotionHalfShutter => "mutant:motion-half-shutter",
        }
    }

    /// Whether the bug is in the time loop: only these mutants draw
    /// moving scenes.
    pub fn is_motion(self) -> bool {
        matches!(self, Mutation::MotionAtOpen | Mutation::MotionHalfShutter)
    }

    /// The instants (in [0, 1]) a motion mutant draws a moving scene at.
    fn instants(self, motion: &MotionPlan) -> Vec<Number> {
        let one = i64::from(crate::scene::time::limits::TIME_ONE);
        let [open, close] = motion.blur.shutter.map(i64::from);
        match self {
            Mutation::MotionHalfShutter => {
                // open + (close − open)·(2k + 1)/(4N): the midpoints of N
                // strata of the first half.
                let n = i64::from(motion.blur.samples.max(1));
                (0..n)
                    .map(|k| {
                        Number::ratio(4 * n * open + (close - open) * (2 * k + 1), 4 * n * one)
                    })
                    .collect()
            }
            _ => vec![Number::ratio(open, one)],
        }
    }

    /// The plan production is given: with its sample offsets moved, for
    /// [`Mutation::ShiftedSamples`].
    fn plan(self, plan: &Plan) -> Plan {
        let mut plan = plan.clone();
        if let (Mutation::ShiftedSamples, Some(samples)) = (self, plan.antialias.as_mut()) {
            let last = (1u32 << samples.position_bits) - 1;
            for [x, _] in &mut samples.offsets {
                *x = if *x < last { *x + 1 } else { *x - 1 };
            }
        }
        plan
    }

    /// What production's frame is turned into.
    fn frame(self, mut frame: Frame) -> Frame {
        if let Some(resolved) = frame.resolved.as_mut() {
            match self {
                Mutation::CoarseResolve => {
                    for v in resolved.iter_mut() {
                        *v = (*v * 4.0).floor() / 4.0;
                    }
                }
                Mutation::LeakyFull => {
                    for v in resolved.iter_mut().filter(|v| **v == 1.0) {
                        *v = 1.0 - 1.0 / 1048576.0;
                    }
                }
                _ => {}
            }
        }
        frame
    }

    fn apply(self, scene: &Scene) -> Scene {
        let mut scene = scene.clone();
        let step = Number::ratio(1, 1 << scene.rules.subpixel_bits.unwrap_or(8));
        match self {
            Mutation::FlippedTies => scene.rules.fill_rule = scene.rules.fill_rule.flipped(),
            Mutation::ClosedEdges => scene.rules.fill_rule = FillRule::AllEdges,
            Mutation::VertexNudge => {
                for primitive in &mut scene.primitives {
                    let first = &mut primitive.vertices_mut()[0];
                    first.x = &first.x + &step;
                }
            }
            Mutation::Shrunk => {
                for t in scene.primitives.iter_mut().filter_map(|p| match p {
                    Primitive::Triangle(t) => Some(t),
                    _ => None,
                }) {
                    let sum = |f: fn(&crate::scene::Vertex) -> &Number| {
                        t.vertices.iter().fold(Number::ZERO, |acc, v| &acc + f(v))
                    };
                    let (cx, cy) = (sum(|v| &v.x), sum(|v| &v.y));
                    for v in &mut t.vertices {
                        // Compare 3·v with the vertex sum instead of v with the centroid.
                        let toward = |c: &Number, p: &Number| {
                            let thrice = &(p + p) + p;
                            match c.cmp(&thrice) {
                                std::cmp::Ordering::Greater => step.clone(),
                                std::cmp::Ordering::Less => -step.clone(),
                                std::cmp::Ordering::Equal => Number::ZERO,
                            }
                        };
                        v.x = &v.x + &toward(&cx, &v.x);
                        v.y = &v.y + &toward(&cy, &v.y);
                    }
                }
            }
            Mutation::NoPerspective => {
                for primitive in &mut scene.primitives {
                    let interpolation = match primitive {
                        Primitive::Triangle(t) => &mut t.interpolation,
                        Primitive::Line(l) => &mut l.interpolation,
                        Primitive::Polygon(_) | Primitive::Point(_) => continue,
                    };
                    if *interpolation == Interpolation::Perspective {
                        *interpolation = Interpolation::Linear;
                    }
                }
            }
            Mutation::ThickLines => swap_line_rule(
                &mut scene,
                LineRule::Midpoint,
                LineRule::Rectangle,
                LastPixel::Include,
            ),
            Mutation::MidpointForDiamond => swap_line_rule(
                &mut scene,
                LineRule::DiamondExit,
                LineRule::Midpoint,
                LastPixel::Exclude,
            ),
            Mutation::ShiftedSamples
            | Mutation::CoarseResolve
            | Mutation::LeakyFull
            | Mutation::MotionAtOpen
            | Mutation::MotionHalfShutter => {}
        }
        scene
    }
}

fn swap_line_rule(scene: &mut Scene, from: LineRule, to: LineRule, last_pixel: LastPixel) {
    for primitive in &mut scene.primitives {
        if let Primitive::Line(line) = primitive {
            if line.rule == from {
                line.rule = to;
                line.last_pixel = last_pixel;
            }
        }
    }
}

/// The production rasterizer with a [`Mutation`].
#[derive(Clone, Copy, Debug)]
pub struct Mutant(pub Mutation);

impl Rasterizer for Mutant {
    fn name(&self) -> &str {
        self.0.name()
    }

    /// Production's, except motion blur: only the motion mutants draw
    /// moving scenes (they do it their own way, [`accumulate`]), whatever
    /// production can do.
    fn capabilities(&self) -> Capabilities {
        Capabilities {
            motion_blur: self.0.is_motion(),
            ..Production.capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if let (true, Some(motion)) = (self.0.is_motion(), &plan.motion) {
            return accumulate(scene, &self.0.instants(motion));
        }
        let frame = Production.rasterize(&self.0.apply(scene), &self.0.plan(plan))?;
        Ok(self.0.frame(frame))
    }
}

/// A moving scene drawn as an accumulation buffer: the static scene at
/// each of `instants` (in [0, 1]) drawn by production at the scene's own
/// spatial samples, and each pixel's time coverage the covered
/// (instant, sample) tests over all of them, counting every primitive
/// that covers a sample (SPEC.md §15.3's estimate with the same instants
/// at every pixel). Each static scene is snapped again to the case's grid,
/// as such a renderer would snap every frame; positions at an instant on
/// that grid (every instant of a shutter open at 0, say) do not move.
///
/// # Errors
/// What production reports for a static scene; `Failed` for a scene
/// without `subpixel_bits` (every moving scene has them) or no instants.
pub fn accumulate(scene: &Scene, instants: &[Number]) -> Result<Frame, RasterError> {
    let bits = scene
        .rules
        .subpixel_bits
        .ok_or_else(|| RasterError::Failed("a moving scene without subpixel_bits".to_owned()))?;
    if instants.is_empty() {
        return Err(RasterError::Failed("no instants to draw".to_owned()));
    }
    let mut covered = vec![0u64; scene.canvas.pixel_count()];
    let mut tests = 0u64;
    for instant in instants {
        let mut still = scene.at_instant(instant);
        still.rules.subpixel_bits = Some(bits);
        let plan = Plan::for_scene(&still);
        let frame = Production.rasterize(&still, &plan)?;
        let n = frame.samples.max(1) as usize;
        for (sum, run) in covered.iter_mut().zip(frame.coverage.chunks(n)) {
            *sum += run.iter().map(|&c| u64::from(c)).sum::<u64>();
        }
        tests += n as u64;
    }
    let time = covered.iter().map(|&c| c as f64 / tests as f64).collect();
    Ok(Frame::time_only(
        scene.canvas.width,
        scene.canvas.height,
        time,
    ))
}
