//! Deliberately wrong rasterizers: the production rasterizer with one
//! realistic bug each. They exist to prove that every check can fail: each
//! is caught by a different metric (see tests/mutants.rs).
//!
//! A bug is applied by rewriting what production sees (the scene, or the
//! plan's sample offsets) or what it returns (the resolved coverage of an
//! antialiased frame); production itself is never changed.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::Production;
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
}

impl Mutation {
    pub const ALL: [Mutation; 10] = [
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
                        Primitive::Polygon(_) => continue,
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
            Mutation::ShiftedSamples | Mutation::CoarseResolve | Mutation::LeakyFull => {}
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

    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let frame = Production.rasterize(&self.0.apply(scene), &self.0.plan(plan))?;
        Ok(self.0.frame(frame))
    }
}
