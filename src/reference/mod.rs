//! The exact oracle.
//!
//! It imports the scene model and the output types, and nothing from the
//! production rasterizer: an oracle that shared code with what it judges
//! would inherit its bugs. Every coverage decision is the sign of an exact
//! integer; every interpolated value is an exact rational, rounded only when
//! it is written out.

pub mod exact;
pub mod grid;
pub mod line;
pub mod triangle;

use dashu_int::IBig;
use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, Primitive, Scene};
use grid::to_i128;

/// The reference rasterizer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Reference;

impl Rasterizer for Reference {
    fn name(&self) -> &str {
        "reference"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Ok(render(scene, plan))
    }
}

/// Which integers the oracle computes triangle coverage with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// i128 where `exact::I128_COORD_BOUND` proves it safe, big integers
    /// otherwise.
    Auto,
    /// Big integers throughout: slower, and the differential check of the
    /// fast path.
    BigOnly,
}

/// What the oracle knows exactly at a covered sample.
enum Exact {
    /// Coverage only was asked for.
    Nothing,
    /// A triangle's edge values and twice its area.
    Triangle([IBig; 3], IBig),
    /// A line's interpolation parameter.
    Line(RBig),
}

/// Visits every covered sample of every primitive under `rule`, in scene
/// order: `visit(primitive, pixel, exact values)`.
fn visit_scene<F>(
    scene: &Scene,
    rule: FillRule,
    arithmetic: Arithmetic,
    with_values: bool,
    mut visit: F,
) where
    F: FnMut(usize, usize, Exact),
{
    let on = grid::on_grid(scene);
    let fast = on.fits_i128 && arithmetic == Arithmetic::Auto;
    let (grid, canvas, cull) = (&on.grid, scene.canvas, scene.rules.cull);
    for (index, (primitive, points)) in scene.primitives.iter().zip(&on.points).enumerate() {
        match primitive {
            Primitive::Triangle(_) if fast => {
                triangle::visit(grid, canvas, points, to_i128, rule, cull, |p, e, a| {
                    let exact = if with_values {
                        Exact::Triangle(e.map(IBig::from), IBig::from(*a))
                    } else {
                        Exact::Nothing
                    };
                    visit(index, p, exact)
                })
            }
            Primitive::Triangle(_) => {
                triangle::visit(grid, canvas, points, IBig::clone, rule, cull, |p, e, a| {
                    let exact = if with_values {
                        Exact::Triangle(e.clone(), a.clone())
                    } else {
                        Exact::Nothing
                    };
                    visit(index, p, exact)
                })
            }
            // Polygons arrive with their own module.
            Primitive::Polygon(_) => {}
            Primitive::Line(line) => line::visit(grid, canvas, line, points, rule, |p, t| {
                visit(
                    index,
                    p,
                    if with_values {
                        Exact::Line(t)
                    } else {
                        Exact::Nothing
                    },
                )
            }),
        }
    }
}

/// How many primitives cover each sample under `rule` (coverage only).
pub fn coverage_under(scene: &Scene, rule: FillRule) -> Vec<u16> {
    let mut counts = vec![0u16; scene.canvas.pixel_count()];
    visit_scene(scene, rule, Arithmetic::Auto, false, |_, pixel, _| {
        counts[pixel] = counts[pixel].saturating_add(1)
    });
    counts
}

/// The exact frame: coverage under the scene's rule, and exact depth and
/// attributes rounded to odd (see `exact::to_f64_round_odd`).
pub fn render(scene: &Scene, plan: &Plan) -> Frame {
    render_with(scene, plan, Arithmetic::Auto)
}

/// [`render`] with a choice of integer arithmetic.
pub fn render_with(scene: &Scene, plan: &Plan, arithmetic: Arithmetic) -> Frame {
    let mut frame = Frame::new(
        scene.canvas.width,
        scene.canvas.height,
        plan.depth,
        plan.attributes,
    );
    let values: Vec<Option<triangle::VertexValues>> = scene
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Triangle(t) if plan.interpolates() => Some(triangle::VertexValues::new(t)),
            _ => None,
        })
        .collect();
    visit_scene(
        scene,
        scene.rules.fill_rule,
        arithmetic,
        plan.interpolates(),
        |index, pixel, exact| {
            frame.hit(pixel, index);
            match (exact, &scene.primitives[index]) {
                (Exact::Triangle(e, area), _) => values[index]
                    .as_ref()
                    .expect("prepared for triangles")
                    .write(&mut frame, pixel, plan, &e, &area),
                (Exact::Line(t), Primitive::Line(line)) => {
                    line::write(line, &mut frame, pixel, plan, &t)
                }
                _ => {}
            }
        },
    );
    frame
}

/// Samples in the interior of the union of the scene's primitives: those
/// that each of the four consistent fill rules covers (SPEC.md §6.2).
pub fn mesh_interior(scene: &Scene) -> Vec<bool> {
    let mut interior = vec![true; scene.canvas.pixel_count()];
    for rule in FillRule::CONSISTENT {
        let counts = coverage_under(scene, rule);
        for (inside, count) in interior.iter_mut().zip(counts) {
            *inside &= count > 0;
        }
    }
    interior
}
