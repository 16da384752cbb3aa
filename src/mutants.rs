//! Deliberately wrong rasterizers: the production rasterizer with one
//! realistic bug each. They exist to prove that every check can fail: each
//! is caught by a different metric (see tests/mutants.rs).

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
}

impl Mutation {
    pub const ALL: [Mutation; 7] = [
        Mutation::FlippedTies,
        Mutation::ClosedEdges,
        Mutation::VertexNudge,
        Mutation::Shrunk,
        Mutation::NoPerspective,
        Mutation::ThickLines,
        Mutation::MidpointForDiamond,
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
        }
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
        Production.rasterize(&self.0.apply(scene), plan)
    }
}
