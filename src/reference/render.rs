//! The exact frame: coverage under the scene's rule, exact depth and
//! attributes rounded once, the depths a format allows (SPEC.md §18), and
//! an antialiased scene's exact areas.

use dashu_int::IBig;

use super::area::{self, exact_areas};
use super::depth;
use super::exact;
use super::line;
use super::motion;
use super::triangle;
use super::visit::{visit_samples, Arithmetic, Exact};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{DepthFormat, Primitive, Scene};

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
                        let stored = triangle_stored(rules, index, values, &e, &area);
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
    if scene.rules.depth_format == DepthFormat::Exact {
        return None;
    }
    render_judged(scene, plan, Arithmetic::Auto).1
}

/// What a screen-space triangle's sample stores under the depth rules:
/// its exact depth (`e`, `area` its edge values and twice its area there),
/// widened by primitive `index`'s offset interval when it is offset.
pub(super) fn triangle_stored(
    rules: &depth::DepthRules,
    index: usize,
    values: &triangle::VertexValues,
    e: &[IBig; 3],
    area: &IBig,
) -> depth::Stored {
    let z = values.depth(e, area);
    match rules.offset(index) {
        Some([lo, hi]) => rules.store([&(&z + lo), &(&z + hi)]),
        None => rules.store([&z, &z]),
    }
}

/// Writes a slot's stored depth and what it allows.
pub(super) fn store(
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
