//! Visiting every covered sample of a scene: the one traversal the exact
//! frame, coverage counts and the mesh interior share. Triangles, lines and
//! polygons are visited at pixel centres on one integer grid; an
//! antialiased scene once per sample, moved so that the sample sits on the
//! centre; a clip-space scene through `clip/`.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::clip;
use super::grid::{self, to_i128, OnGrid};
use super::line;
use super::point;
use super::polygon;
use super::triangle;
use super::values::Values;
use crate::plan::SamplePlan;
use crate::scene::{FillRule, LineRule, Primitive, Scene};

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
pub(super) enum Exact {
    /// Coverage only was asked for.
    Nothing,
    /// A triangle's edge values and twice its area.
    Triangle([IBig; 3], IBig),
    /// A line's interpolation parameter.
    Line(RBig),
    /// Exact depth and attributes at the sample: a clip-space triangle's
    /// (SPEC.md §16.5), or a point's, the same at every sample (§17).
    Values(Box<Values>),
}

/// Visits every covered sample of every primitive under `rule`, in scene
/// order: `visit(primitive, slot, exact values)`. Without antialiasing a
/// pixel's one slot is its centre; with it, slot `pixel · N + s` is sample
/// s, decided as the pixel centre of the scene moved by (½ − offset_s)
/// (`OnGrid::translated`), sample by sample.
pub(super) fn visit_samples<F>(
    scene: &Scene,
    antialias: Option<&SamplePlan>,
    rule: FillRule,
    arithmetic: Arithmetic,
    with_values: bool,
    mut visit: F,
) where
    F: FnMut(usize, usize, Exact),
{
    if scene.in_clip_space() {
        // The reader refuses antialiasing in clip space.
        return clip::visit(scene, rule, with_values, |index, pixel, values| {
            visit(
                index,
                pixel,
                values.map_or(Exact::Nothing, |v| Exact::Values(Box::new(v))),
            )
        });
    }
    let Some(samples) = antialias else {
        let on = grid::on_grid(scene);
        return visit_scene(scene, &on, rule, arithmetic, with_values, false, visit);
    };
    let on = grid::on_grid_sampled(scene, Some(samples.position_bits));
    let n = samples.offsets.len();
    for (s, &offset) in samples.offsets.iter().enumerate() {
        let moved = on.translated(scene, &on.sample_shift(offset, samples.position_bits));
        visit_scene(
            scene,
            &moved,
            rule,
            arithmetic,
            with_values,
            true,
            |index, pixel, exact| visit(index, pixel * n + s, exact),
        );
    }
}

/// Visits every covered pixel centre of every primitive of `on` under
/// `rule`, in scene order: `visit(primitive, pixel, exact values)`.
/// `antialiased` leaves out the lines that choose whole pixels
/// (`midpoint`, `diamond-exit`) and `rectangle` lines, which the reader
/// refuses in antialiased scenes (SPEC.md §14.2).
fn visit_scene<F>(
    scene: &Scene,
    on: &OnGrid,
    rule: FillRule,
    arithmetic: Arithmetic,
    with_values: bool,
    antialiased: bool,
    mut visit: F,
) where
    F: FnMut(usize, usize, Exact),
{
    let fast = on.fits_i128 && arithmetic == Arithmetic::Auto;
    let (grid, canvas, cull) = (&on.grid, scene.canvas, scene.rules.cull);
    let clamp = scene.rules.line_clamp;
    for (index, (primitive, points)) in scene.primitives.iter().zip(&on.points).enumerate() {
        crate::deadline::check();
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
            Primitive::Polygon(polygon) if fast => {
                polygon::visit(grid, canvas, polygon, points, to_i128, rule, |p| {
                    visit(index, p, Exact::Nothing)
                })
            }
            Primitive::Polygon(polygon) => {
                polygon::visit(grid, canvas, polygon, points, IBig::clone, rule, |p| {
                    visit(index, p, Exact::Nothing)
                })
            }
            // The reader refuses points in antialiased scenes.
            Primitive::Point(_) if antialiased => {}
            Primitive::Point(p) => {
                let values = with_values.then(|| point::screen_values(p));
                point::visit(&point::screen_square(scene, p), rule, canvas, |pixel| {
                    let exact = values
                        .as_ref()
                        .map_or(Exact::Nothing, |v| Exact::Values(Box::new(v.clone())));
                    visit(index, pixel, exact)
                })
            }
            Primitive::Line(line) if antialiased && line.rule != LineRule::Parallelogram => {}
            Primitive::Line(line) => {
                line::visit(grid, canvas, line, points, rule, clamp, |p, t| {
                    visit(
                        index,
                        p,
                        if with_values {
                            Exact::Line(t)
                        } else {
                            Exact::Nothing
                        },
                    )
                })
            }
        }
    }
}
