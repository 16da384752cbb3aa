//! The effects planner: the plan chosen for representative scenes
//! (SPEC.md §15.1, ARCHITECTURE.md "The plan"). A scene pays only for what
//! it asks for: no antialiasing → one sample; nothing moves → no time loop,
//! even with `motion_blur` declared; no attributes → no interpolation; no
//! `z` → no depth.

mod common;

use common::inline;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{Scene, TimePattern};

/// A case around `primitives` and `effects` (JSON text).
fn scene(primitives: &str, effects: &str) -> Scene {
    inline(&format!(
        r#"{{"name": "plan", "canvas": {{"width": 16, "height": 16}},
            "primitives": [{primitives}], "effects": {{{effects}}}}}"#
    ))
}

const STATIC: &str = r#"{"triangle": [[1, 1], [14, 2], [3, 13]]}"#;
const MOVING: &str = r#"{"triangle": [{"from": [1, 1], "to": [6, 2]}, [14, 2], [3, 13]]}"#;
const BLUR: &str = r#""motion_blur": {"samples": 8, "pattern": "random", "seed": 5}"#;
const AA: &str = r#""antialias": {"samples": 4}"#;

#[test]
fn a_plain_scene_plans_one_sample_and_nothing_else() {
    let plan = Plan::for_scene(&scene(STATIC, ""));
    assert_eq!(plan.samples_per_pixel, 1);
    assert_eq!(plan.antialias, None);
    assert!(!plan.depth);
    assert_eq!(plan.attributes, 0);
    assert_eq!(plan.motion, None);
    assert!(!plan.interpolates());
}

#[test]
fn depth_and_attributes_are_planned_only_when_vertices_carry_them() {
    let with_z = r#"{"triangle": [{"position": [1, 1], "z": 0.5}, {"position": [14, 2]}, {"position": [3, 13]}]}"#;
    let plan = Plan::for_scene(&scene(with_z, ""));
    assert!(plan.depth);
    assert_eq!(plan.attributes, 0);
    let with_attributes = r#"{"triangle": [
        {"position": [1, 1], "attributes": [1, 2]},
        {"position": [14, 2], "attributes": [3, 4]},
        {"position": [3, 13], "attributes": [5, 6]}]}"#;
    let plan = Plan::for_scene(&scene(with_attributes, ""));
    assert!(!plan.depth);
    assert_eq!(plan.attributes, 2);
    assert!(plan.interpolates());
}

#[test]
fn antialiasing_plans_its_offsets_and_no_time_loop() {
    let plan = Plan::for_scene(&scene(STATIC, AA));
    assert_eq!(plan.samples_per_pixel, 4);
    let samples = plan.antialias.expect("antialiased");
    assert_eq!(
        samples.offsets,
        [[96, 32], [224, 96], [32, 160], [160, 224]]
    );
    assert_eq!(plan.motion, None);
}

#[test]
fn declared_motion_blur_without_motion_plans_no_time_loop() {
    let declared = scene(STATIC, BLUR);
    let plain = scene(STATIC, "");
    assert_eq!(Plan::for_scene(&declared), Plan::for_scene(&plain));
    // A vertex whose `to` is its `from` does not move.
    let still = r#"{"triangle": [{"from": [1, 1], "to": [1, 1]}, [14, 2], [3, 13]]}"#;
    let still = scene(still, BLUR);
    assert!(!still.moves());
    assert_eq!(Plan::for_scene(&still), Plan::for_scene(&plain));
    // And production draws exactly the static frame: sample slots, no time
    // coverage, no sample tests.
    let drawn = Production
        .rasterize(&declared, &Plan::for_scene(&declared))
        .expect("drawn");
    let reference = Production
        .rasterize(&plain, &Plan::for_scene(&plain))
        .expect("drawn");
    assert_eq!(drawn, reference);
    assert_eq!(drawn.time, None);
    assert_eq!(drawn.sample_tests, None);
}

#[test]
fn motion_plans_a_time_loop_for_the_moving_primitives_only() {
    let plan = Plan::for_scene(&scene(&format!("{STATIC}, {MOVING}, {STATIC}"), BLUR));
    assert_eq!(plan.samples_per_pixel, 1);
    assert_eq!(plan.antialias, None);
    let motion = plan.motion.expect("something moves");
    assert_eq!(motion.moving, [false, true, false]);
    assert_eq!(motion.blur.samples, 8);
    assert_eq!(motion.blur.pattern, TimePattern::Random);
    assert_eq!(motion.blur.seed, 5);
    assert_eq!(motion.blur.shutter, [0, 1 << 16]);
    assert!(!plan.depth);
    assert_eq!(plan.attributes, 0);
}

#[test]
fn motion_with_antialiasing_plans_time_samples_at_every_spatial_sample() {
    let plan = Plan::for_scene(&scene(MOVING, &format!("{AA}, {BLUR}")));
    assert_eq!(plan.samples_per_pixel, 4);
    assert_eq!(plan.antialias.expect("antialiased").offsets.len(), 4);
    let motion = plan.motion.expect("something moves");
    assert_eq!(motion.moving, [true]);
    // The frame of a moving scene holds time coverage only.
    let frame = rastercheck::frame::Frame::for_plan(16, 16, &Plan::for_scene(&scene(MOVING, BLUR)));
    assert_eq!(frame.samples, 0);
    assert_eq!(frame.time.as_ref().map(Vec::len), Some(256));
    assert_eq!(frame.resolved, None);
}

#[test]
fn a_moving_line_plans_motion_too() {
    let line = r#"{"line": [{"from": [1, 1], "to": [1, 9]}, [14, 3]], "rule": "parallelogram"}"#;
    let plan = Plan::for_scene(&scene(line, BLUR));
    assert_eq!(plan.motion.expect("the line moves").moving, [true]);
}
