//! Clip-space checks every driver adapter that claims `clip_space` runs
//! (`vulkan.rs`, `gl/`): the provoking vertex's exact flat values, depth
//! written from the driver's own depth and clamped under `depth: clamp`,
//! refusals, and the scenes that tell the clipping conventions apart
//! (SPEC.md §16). Which conventions a driver follows stays in its test.

use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::scene::Scene;

use super::inline;

/// A 4×4 clip-space case of one triangle over the whole viewport (w = 2
/// everywhere, so every x, y in [−2, 2] lands inside), with `rules` and
/// the triangle's `interpolation`, each vertex carrying attribute
/// 10, 20, 30 in order.
pub fn whole_viewport(rules: &str, interpolation: &str, depth_range: (f64, f64), z: f64) -> Scene {
    inline(&format!(
        r#"{{"name": "clip_whole", "canvas": {{"width": 4, "height": 4}},
            "viewport": {{"x": 0, "y": 0, "width": 4, "height": 4,
                          "min_depth": {}, "max_depth": {}}},
            "rules": {{{rules}}},
            "primitives": [{{"interpolation": "{interpolation}", "triangle": [
                {{"clip": [-2, -2, {z}, 2], "attributes": [10]}},
                {{"clip": [6, -2, {z}, 2], "attributes": [20]}},
                {{"clip": [-2, 6, {z}, 2], "attributes": [30]}}]}}]}}"#,
        depth_range.0, depth_range.1
    ))
}

/// The frame the candidate draws of `scene`, or the test fails.
pub fn drawn(candidate: &dyn Rasterizer, scene: &Scene) -> Frame {
    candidate
        .rasterize(scene, &Plan::for_scene(scene))
        .unwrap_or_else(|e| panic!("{}: {e}", candidate.name()))
}

/// Attribute 0 of every covered sample, and how many are covered.
pub fn flat_values(frame: &Frame) -> (Vec<f64>, usize) {
    let covered: Vec<usize> = (0..frame.coverage.len())
        .filter(|&i| frame.coverage[i] > 0)
        .collect();
    let values = covered.iter().map(|&i| frame.attributes[0][i]).collect();
    (values, covered.len())
}

/// Flat values come from the vertex the case names, exactly, in clip
/// space and in screen space: 30 (the last) under `last`, 10 under
/// `first`. A driver that ignored the rule gives the other on every
/// sample.
pub fn assert_provoking_vertex(candidate: &dyn Rasterizer) {
    for (rule, want) in [("first", 10.0), ("last", 30.0)] {
        let rules = format!(r#""provoking_vertex": "{rule}""#);
        let clip = whole_viewport(&rules, "flat", (0.0, 1.0), 1.0);
        let screen = inline(&format!(
            r#"{{"name": "screen_flat", "canvas": {{"width": 4, "height": 4}},
                "rules": {{{rules}}},
                "primitives": [{{"interpolation": "flat", "triangle": [
                    {{"position": [0, 0], "attributes": [10]}},
                    {{"position": [8, 0], "attributes": [20]}},
                    {{"position": [0, 8], "attributes": [30]}}]}}]}}"#
        ));
        for (space, scene) in [("clip", clip), ("screen", screen)] {
            let (values, covered) = flat_values(&drawn(candidate, &scene));
            assert_eq!(covered, 16, "{space} space, {rule}: every sample covered");
            assert!(
                values.iter().all(|&v| v == want),
                "{} {space} space, provoking_vertex {rule}: flat values {values:?}, want {want}",
                candidate.name()
            );
        }
    }
}

/// `depth: clamp` against `depth: clip` on a triangle wholly beyond the far
/// plane (z_ndc = 1.5): clipped away under `clip`; under `clamp` drawn
/// everywhere, its depth min + (max − min)·1.5 = 0 clamped to the range
/// [0.25, 0.75] of the viewport's reversed min 0.75, max 0.25: 0.25. And
/// inside the volume (z_ndc = 0.5) depth is 0.75 − 0.5·0.5 = 0.5 under
/// both.
pub fn assert_depth_clip_and_clamp(candidate: &dyn Rasterizer) {
    let range = (0.75, 0.25);
    for (depth, z, covered, want) in [
        ("clip", 3.0, 0, None),
        ("clamp", 3.0, 16, Some(0.25)),
        ("clip", 1.0, 16, Some(0.5)),
        ("clamp", 1.0, 16, Some(0.5)),
    ] {
        let rules = format!(r#""depth": "{depth}""#);
        let scene = whole_viewport(&rules, "perspective", range, z);
        let frame = drawn(candidate, &scene);
        let (_, got) = flat_values(&frame);
        assert_eq!(got, covered, "depth {depth}, z = {z}: samples covered");
        if let Some(want) = want {
            let depths = frame.depth.as_ref().expect("clip space writes depth");
            for (i, &d) in depths.iter().enumerate() {
                assert!(
                    (d - want).abs() < 1e-6,
                    "{} depth {depth}, z = {z}: sample {i} has depth {d}, want {want}",
                    candidate.name()
                );
            }
        }
    }
}

/// Clip-space cases the driver cannot draw as asked are refused, each with
/// its reason: unsnapped, fewer subpixel bits than the driver's, a clip
/// coordinate that is no f32.
pub fn assert_clip_refusals(candidate: &dyn Rasterizer) {
    let refused = |scene: &Scene, why: &str| match candidate
        .rasterize(scene, &Plan::for_scene(scene))
    {
        Err(RasterError::Unsupported(reason)) => assert!(
            reason.contains(why),
            "{}: refused for {reason:?}, want {why:?}",
            candidate.name()
        ),
        other => panic!("{}: want unsupported ({why}), got {other:?}", candidate.name()),
    };
    refused(
        &whole_viewport(r#""subpixel_bits": null"#, "flat", (0.0, 1.0), 1.0),
        "unsnapped",
    );
    refused(
        &whole_viewport(r#""subpixel_bits": 4"#, "flat", (0.0, 1.0), 1.0),
        "subpixel_bits 4",
    );
    refused(
        &whole_viewport("", "flat", (0.0, 1.0), 0.1),
        "not an f32",
    );
}
