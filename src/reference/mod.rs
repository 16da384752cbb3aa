//! The exact oracle.
//!
//! It imports the scene model and the output types, and nothing from the
//! production rasterizer: an oracle that shared code with what it judges
//! would inherit its bugs. Every coverage decision is the sign of an exact
//! integer; every interpolated value is an exact rational, rounded only when
//! it is written out.
//!
//! Triangles (`triangle.rs`), lines (`line.rs`) and polygons (`polygon.rs`)
//! are visited at pixel centres on one integer grid (`grid.rs`); points
//! (`point.rs`) compare pixel centres with their square's exact sides; an
//! antialiased scene is visited once per sample, moved so that the sample
//! sits on the centre. Exact area coverage (`area.rs`) is computed only
//! when the plan antialiases.

pub mod area;
pub mod clip;
pub mod depth;
pub mod exact;
pub mod grid;
pub mod line;
pub mod motion;
pub mod point;
pub mod polygon;
pub mod triangle;

use dashu_int::IBig;
use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::{Plan, SamplePlan};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, LineRule, Primitive, Scene};
use grid::{to_i128, OnGrid};

pub use area::{exact_areas, primitive_area, primitive_pixel_areas};

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
    /// Exact depth and attributes at the sample: a clip-space triangle's
    /// (SPEC.md §16.5), or a point's, the same at every sample (§17).
    Values(Box<clip::Values>),
}

/// Visits every covered sample of every primitive under `rule`, in scene
/// order: `visit(primitive, slot, exact values)`. Without antialiasing a
/// pixel's one slot is its centre; with it, slot `pixel · N + s` is sample
/// s, decided as the pixel centre of the scene moved by (½ − offset_s)
/// (`OnGrid::translated`), sample by sample.
fn visit_samples<F>(
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

/// How many primitives cover each sample under `rule` (coverage only): one
/// slot per pixel, or N per pixel when the scene antialiases (sample s of
/// pixel p at p · N + s, as in a frame). `plan` is the scene's: only its
/// samples are read.
pub fn coverage_under(scene: &Scene, plan: &Plan, rule: FillRule) -> Vec<u16> {
    let slots = scene.canvas.pixel_count() * plan.samples_per_pixel as usize;
    let mut counts = vec![0u16; slots];
    visit_samples(
        scene,
        plan.antialias.as_ref(),
        rule,
        Arithmetic::Auto,
        false,
        |_, slot, _| counts[slot] = counts[slot].saturating_add(1),
    );
    counts
}

/// The exact frame: coverage under the scene's rule, and exact depth and
/// attributes rounded to odd (see `exact::to_f64_round_odd`). When the plan
/// antialiases, N slots per pixel at the plan's offsets, and `resolved`
/// holds each pixel's exact area coverage ([`exact_areas`]) rounded to the
/// nearest f64; without antialiasing no area is computed.
pub fn render(scene: &Scene, plan: &Plan) -> Frame {
    render_with(scene, plan, Arithmetic::Auto)
}

/// [`render`] with a choice of integer arithmetic.
pub fn render_with(scene: &Scene, plan: &Plan, arithmetic: Arithmetic) -> Frame {
    render_judged(scene, plan, arithmetic).0
}

/// The exact frame and, for a scene with a depth format (SPEC.md §18),
/// the depths a candidate may read back at each slot ([`depth::Stored`];
/// `None` for `exact` depth, judged by §6.3 against the frame): what the
/// metrics judge a candidate's depth against. The frame's depth is then
/// each slot's stored midpoint, the golden file's value.
pub fn render_judged(
    scene: &Scene,
    plan: &Plan,
    arithmetic: Arithmetic,
) -> (Frame, Option<Vec<[f64; 2]>>) {
    if plan.motion.is_some() {
        return (motion::frame(scene, plan), None);
    }
    // One slot per offset, whatever a hand-made plan says.
    let consistent;
    let plan = match &plan.antialias {
        Some(samples) if samples.offsets.len() as u32 != plan.samples_per_pixel => {
            consistent = Plan {
                samples_per_pixel: samples.offsets.len() as u32,
                ..plan.clone()
            };
            &consistent
        }
        _ => plan,
    };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    let provoking_line = scene.rules.provoking_vertex.index(2);
    let values: Vec<Option<triangle::VertexValues>> = scene
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Triangle(t) if plan.interpolates() && !scene.in_clip_space() => Some(
                triangle::VertexValues::new(t, scene.rules.provoking_vertex.index(3)),
            ),
            _ => None,
        })
        .collect();
    let depth_rules = depth::DepthRules::new(scene).filter(|_| plan.depth);
    let mut allowed = depth_rules
        .as_ref()
        .map(|_| vec![[0.0; 2]; frame.sample_count()]);
    visit_samples(
        scene,
        plan.antialias.as_ref(),
        scene.rules.fill_rule,
        arithmetic,
        plan.interpolates(),
        |index, slot, exact| {
            frame.hit(slot, index);
            match (exact, &scene.primitives[index]) {
                (Exact::Triangle(e, area), _) => {
                    let values = values[index].as_ref().expect("prepared for triangles");
                    values.write(&mut frame, slot, plan, &e, &area);
                    if let Some(rules) = &depth_rules {
                        let z = values.depth(&e, &area);
                        let stored = match rules.offset(index) {
                            Some([lo, hi]) => rules.store([&(&z + lo), &(&z + hi)]),
                            None => rules.store([&z, &z]),
                        };
                        store(&mut frame, allowed.as_mut(), slot, stored);
                    }
                }
                (Exact::Values(values), _) => {
                    if let Some(depth) = frame.depth.as_mut() {
                        depth[slot] = exact::to_f64_round_odd(&values.depth);
                    }
                    for (channel, value) in frame.attributes.iter_mut().zip(&values.attributes) {
                        channel[slot] = exact::to_f64_round_odd(value);
                    }
                    // The stored depth replaces the exact one (SPEC.md §18).
                    if let Some(rules) = &depth_rules {
                        let [lo, hi] = &values.depth_interval;
                        store(&mut frame, allowed.as_mut(), slot, rules.store([lo, hi]));
                    }
                }
                (Exact::Line(t), Primitive::Line(line)) => {
                    line::write(line, provoking_line, &mut frame, slot, plan, &t);
                    // Lines are never offset (SPEC.md §18.2).
                    if let Some(rules) = &depth_rules {
                        let z = line::depth(line, &t);
                        store(&mut frame, allowed.as_mut(), slot, rules.store([&z, &z]));
                    }
                }
                // A polygon's vertices carry z = 0 and no attributes.
                (_, Primitive::Polygon(_)) => {
                    if let Some(depth) = frame.depth.as_mut() {
                        depth[slot] = 0.0;
                    }
                    for channel in &mut frame.attributes {
                        channel[slot] = 0.0;
                    }
                    if let Some(rules) = &depth_rules {
                        let zero = dashu_ratio::RBig::ZERO;
                        store(
                            &mut frame,
                            allowed.as_mut(),
                            slot,
                            rules.store([&zero, &zero]),
                        );
                    }
                }
                _ => {}
            }
        },
    );
    if plan.antialias.is_some() {
        let areas = exact_areas(scene);
        frame.resolved = Some(areas.iter().map(area::to_f64_nearest).collect());
    }
    (frame, allowed)
}

/// The depths a candidate may read back at each slot of a scene with a
/// depth format (SPEC.md §18), `None` for `exact` depth: the second half
/// of [`render_judged`].
pub fn depth_allowed(scene: &Scene, plan: &Plan) -> Option<Vec<[f64; 2]>> {
    if scene.rules.depth_format == crate::scene::DepthFormat::Exact {
        return None;
    }
    render_judged(scene, plan, Arithmetic::Auto).1
}

/// Writes a slot's stored depth and what it allows.
fn store(
    frame: &mut Frame,
    allowed: Option<&mut Vec<[f64; 2]>>,
    slot: usize,
    stored: depth::Stored,
) {
    if let Some(depth) = frame.depth.as_mut() {
        depth[slot] = stored.value;
    }
    if let Some(allowed) = allowed {
        allowed[slot] = stored.allowed;
    }
}

/// Samples in the interior of the union of the scene's primitives: those
/// that each of the four consistent fill rules covers (SPEC.md §6.2). One
/// slot per sample, as [`coverage_under`].
pub fn mesh_interior(scene: &Scene, plan: &Plan) -> Vec<bool> {
    let slots = scene.canvas.pixel_count() * plan.samples_per_pixel as usize;
    let mut interior = vec![true; slots];
    for rule in FillRule::CONSISTENT {
        let counts = coverage_under(scene, plan, rule);
        for (inside, count) in interior.iter_mut().zip(counts) {
            *inside &= count > 0;
        }
    }
    interior
}
