//! Clip-space checks every driver adapter that claims `clip_space` runs
//! (`vulkan.rs`, `gl/`): the provoking vertex's exact flat values, depth
//! written from the driver's own depth and clamped under `depth: clamp`,
//! refusals, and the scenes that tell the clipping conventions apart
//! (SPEC.md §16). Which conventions a driver follows stays in its test.

use rastercheck::frame::Frame;
use rastercheck::harness::profile::OwnConventions;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::scene::{ClipRules, ClipXy, ClipZ, DepthMode, FillRule, InterpolateFrom, Scene};

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
/// its reason: fewer subpixel bits than the driver's, a
/// viewport rectangle that is no f32 (a depth range off the f32s is drawn).
pub fn assert_clip_refusals(candidate: &dyn Rasterizer) {
    let refused =
        |scene: &Scene, why: &str| match candidate.rasterize(scene, &Plan::for_scene(scene)) {
            Err(RasterError::Unsupported(reason)) => assert!(
                reason.contains(why),
                "{}: refused for {reason:?}, want {why:?}",
                candidate.name()
            ),
            other => panic!(
                "{}: want unsupported ({why}), got {other:?}",
                candidate.name()
            ),
        };
    // Unsnapped is drawn on the driver's grid, and judged at its bits
    // (SPEC.md §3.2).
    let unsnapped = whole_viewport(r#""subpixel_bits": null"#, "flat", (0.0, 1.0), 1.0);
    let drawn = candidate.rasterize(&unsnapped, &Plan::for_scene(&unsnapped));
    assert!(drawn.is_ok(), "{}: unsnapped: {drawn:?}", candidate.name());
    // Fewer bits than the driver's: 4 on an 8-bit driver (lavapipe), 3 on
    // a 4-bit one (SwiftShader).
    let fewer = candidate
        .fixed_subpixel_bits()
        .map_or(4, |bits| bits.saturating_sub(1).min(4));
    refused(
        &whole_viewport(
            &format!(r#""subpixel_bits": {fewer}"#),
            "flat",
            (0.0, 1.0),
            1.0,
        ),
        &format!("subpixel_bits {fewer}"),
    );
    // The viewport's rectangle places vertices, so it must be an f32; its
    // depth range is a value, rounded once.
    let mut off_f32 = whole_viewport("", "flat", (0.0, 1.0), 1.0);
    off_f32.viewport.as_mut().expect("clip space").x = rastercheck::scene::Number::ratio(1, 10);
    refused(&off_f32, "is not an f32");
    let depth = whole_viewport("", "flat", (0.0, 0.1), 1.0);
    assert!(
        candidate
            .rasterize(&depth, &Plan::for_scene(&depth))
            .is_ok(),
        "{}: a depth range off the f32s is drawn",
        candidate.name()
    );
}

/// A 16×16 clip-space case (viewport = canvas, w = 1 everywhere, so that
/// x_f = 8(x + 1) and y_f = 8(y + 1)) of `triangles`, each vertex (x, y,
/// z) in clip coordinates, all f32.
fn clip_case(name: &str, triangles: &[[[f64; 3]; 3]]) -> Scene {
    let primitives: Vec<String> = triangles
        .iter()
        .map(|t| {
            let vertices: Vec<String> = t
                .iter()
                .map(|[x, y, z]| format!(r#"{{"clip": [{x}, {y}, {z}, 1]}}"#))
                .collect();
            format!(r#"{{"triangle": [{}]}}"#, vertices.join(", "))
        })
        .collect();
    inline(&format!(
        r#"{{"name": "{name}", "canvas": {{"width": 16, "height": 16}},
            "viewport": {{"x": 0, "y": 0, "width": 16, "height": 16}},
            "primitives": [{}]}}"#,
        primitives.join(", ")
    ))
}

/// A triangle across the near plane whose new vertices land off the
/// 8-bit grid: z = x − x0, x0 = 1/16 + 1/8192, so z = 0 on the line
/// x_f = 8.5 + 1/1024. Clipped then snapped, its new vertices (8.5 + 1/1024,
/// 0) and (≈ 8.50098, ≈ 6.00130) snap to (8.5, 0) and (8.5, 6): a left edge
/// through the samples x = 8.5, y = 0.5 … 5.5, which top-left and
/// bottom-left both own; per sample, those six samples have z_ndc < 0 and
/// are not covered. Guard band or not changes nothing: the triangle lies
/// inside x, y ∈ [−w, w].
pub fn across_the_near_plane() -> Scene {
    let x0 = 1.0 / 16.0 + 1.0 / 8192.0;
    clip_case(
        "separates_clip_z",
        &[[
            [-0.5, -1.0, -0.5 - x0],
            [1.0, -1.0, 1.0 - x0],
            [1.0, 1.0, 1.0 - x0],
        ]],
    )
}

/// Triangles cut by the viewport's right side whose cut lands off the
/// grid. On screen: V0 = (3.5, 3.5 + k), V1 = (27.5, 13.5 + k), V2 =
/// (3.5, 15.5 + k) for k = 0, −1, −2, each on the grid; V0V1 is a right
/// edge through the sample (15.5, 8.5 + k). Under a guard band that
/// sample lies on the edge, which top-left and bottom-left leave
/// uncovered. Clipped at x_f = 16 the new vertex (16, 8.70833… + k)
/// snaps to y = 8.70703125 + k, and the clipped edge passes above the
/// sample (y = 8.49875 + k at x = 15.5): covered. One sample each.
pub fn cut_by_the_viewport_side() -> Scene {
    let clip = |x: f64, y: f64| [x / 8.0 - 1.0, y / 8.0 - 1.0, 0.5];
    let triangles: Vec<[[f64; 3]; 3]> = [0.0, -1.0, -2.0]
        .into_iter()
        .map(|k| {
            [
                clip(3.5, 3.5 + k),
                clip(27.5, 13.5 + k),
                clip(3.5, 15.5 + k),
            ]
        })
        .collect();
    clip_case("separates_clip_xy", &triangles)
}

/// Samples whose coverage count differs between `candidate`'s frame of
/// `scene` and the reference's under `xy`, `z` (depth clip) and `rule`.
pub fn departures(
    candidate: &dyn Rasterizer,
    scene: &Scene,
    rule: FillRule,
    xy: ClipXy,
    z: ClipZ,
) -> usize {
    let mut scene = scene.with_fill_rule(rule);
    scene.rules.clip = ClipRules {
        xy,
        z,
        depth: DepthMode::Clip,
        ..ClipRules::default()
    };
    let plan = Plan::for_scene(&scene);
    let reference = rastercheck::reference::render(&scene, &plan);
    let got = drawn(candidate, &scene);
    assert!(
        reference.coverage.iter().any(|&c| c > 0),
        "{}: the reference draws something",
        scene.name
    );
    super::mismatched_samples(&reference, &got).len()
}

/// The driver matches the reference sample for sample under its own
/// clipping conventions (`fixed_clip_rules`) on the scenes that separate
/// them, and departs from it under the other convention on each: the
/// scenes tell the conventions apart, and the claim can fail. Returns the
/// departures under the other conventions, (clip_z, clip_xy), for the
/// record.
pub fn assert_clip_conventions(candidate: &dyn Rasterizer) -> (usize, usize) {
    let rule = candidate
        .fixed_fill_rule()
        .expect("a driver's own tie rule");
    let (xy, z) = candidate
        .fixed_clip_rules()
        .expect("a driver declares its clipping conventions");
    let other_z = ClipZ::ALL.into_iter().find(|&c| c != z).unwrap();
    let other_xy = ClipXy::ALL.into_iter().find(|&c| c != xy).unwrap();
    let near = across_the_near_plane();
    let side = cut_by_the_viewport_side();
    let name = candidate.name();
    let own = [
        departures(candidate, &near, rule, xy, z),
        departures(candidate, &side, rule, xy, z),
    ];
    let z_departs = departures(candidate, &near, rule, xy, other_z);
    let xy_departs = departures(candidate, &side, rule, other_xy, z);
    eprintln!(
        "{name}: clip_xy {} clip_z {}: departures {own:?}; under clip_z {}: {z_departs}, \
         under clip_xy {}: {xy_departs}",
        xy.name(),
        z.name(),
        other_z.name(),
        other_xy.name()
    );
    assert_eq!(own, [0, 0], "{name} under its own clip conventions");
    assert!(
        z_departs > 0,
        "{name}: the near-plane scene does not separate clip_z"
    );
    assert!(
        xy_departs > 0,
        "{name}: the viewport-side scene does not separate clip_xy"
    );
    (z_departs, xy_departs)
}

/// The viewport places the scene where SPEC §16.1 says, y down: on a
/// 16×8 canvas, a triangle over all of NDC [−1, 1]² drawn in viewports at
/// an offset, smaller than the canvas, one of them off the integers
/// (x = 2.5, height 4.5) and one hanging off the canvas, matches the
/// reference sample for sample under the driver's conventions. A driver
/// adapter that flipped y, or dropped the offset, would cover other rows.
pub fn assert_viewport_placement(candidate: &dyn Rasterizer) {
    let rule = candidate
        .fixed_fill_rule()
        .expect("a driver's own tie rule");
    let (xy, z) = candidate.fixed_clip_rules().expect("declared conventions");
    for (x, y, w, h) in [
        (2.0, 1.0, 8.0, 4.0),
        (2.5, 0.0, 9.0, 4.5),
        (-3.0, 5.0, 12.0, 6.0),
    ] {
        let scene = inline(&format!(
            r#"{{"name": "viewport", "canvas": {{"width": 16, "height": 8}},
                "viewport": {{"x": {x}, "y": {y}, "width": {w}, "height": {h}}},
                "primitives": [{{"triangle": [
                    {{"clip": [-1, -1, 0.5, 1]}}, {{"clip": [1, -1, 0.5, 1]}},
                    {{"clip": [-1, 0.5, 0.5, 1]}}]}}]}}"#
        ));
        let departed = departures(candidate, &scene, rule, xy, z);
        assert_eq!(
            departed,
            0,
            "{}: viewport ({x}, {y}) {w}×{h}",
            candidate.name()
        );
    }
}

/// Inside the clip volume, where every convention agrees (SPEC §16.7), a
/// clip-space scene with w from 0.5 to 4, perspective and flat attributes
/// and depth passes the suite's judgement: coverage exact, depth and
/// attributes within the bound.
pub fn assert_inside_the_volume_passes(candidate: &dyn Rasterizer) {
    let scene = inline(
        r#"{"name": "inside", "canvas": {"width": 16, "height": 16},
            "viewport": {"x": 0, "y": 0, "width": 16, "height": 16, "min_depth": 0.25, "max_depth": 1},
            "rules": {"provoking_vertex": "last"},
            "primitives": [
              {"triangle": [{"clip": [-0.4375, -0.46875, 0.25, 0.5], "attributes": [0, 1]},
                            {"clip": [3.5, -1.5, 1, 4], "attributes": [1, 0]},
                            {"clip": [-0.75, 0.875, 0.5, 1], "attributes": [2, 5]}]},
              {"interpolation": "flat",
               "triangle": [{"clip": [1, 1, 0.5, 2], "attributes": [7, 8]},
                            {"clip": [-1.5, 1.75, 1.5, 2], "attributes": [9, 10]},
                            {"clip": [1.5, -1.5, 1.75, 2], "attributes": [11, 12]}]}]}"#,
    );
    let (reference, run) = super::run(&scene, candidate);
    assert_eq!(
        run.verdict,
        rastercheck::harness::judge::Verdict::Pass,
        "{}",
        super::report("inside", &reference, &run)
    );
}

/// The largest |driver − reference| over depth and attributes where both
/// cover a sample with the same primitive, the reference drawn under
/// `values`.
fn value_departure(candidate: &dyn Rasterizer, scene: &Scene, values: InterpolateFrom) -> f64 {
    // At the driver's own subpixel bits and clipping (SwiftShader snaps to
    // 4), as a run judges it.
    let mut scene = OwnConventions::of(candidate, scene).restate(scene);
    scene.rules.clip.values = values;
    let reference = rastercheck::reference::render(&scene, &Plan::for_scene(&scene));
    let got = drawn(candidate, &scene);
    let mut worst: f64 = 0.0;
    for i in 0..got.coverage.len() {
        if got.coverage[i] == 0 || reference.coverage[i] == 0 || got.last[i] != reference.last[i] {
            continue;
        }
        if let (Some(a), Some(b)) = (&got.depth, &reference.depth) {
            worst = worst.max((a[i] - b[i]).abs());
        }
        for (a, b) in got.attributes.iter().zip(&reference.attributes) {
            worst = worst.max((a[i] - b[i]).abs());
        }
    }
    worst
}

/// The driver's depth and attributes are those of the positions it
/// declares it interpolates from (`fixed_interpolate_from`), within §6.3's
/// 2^-16, on the worked examples whose vertices land off the grid, and
/// depart from the other positions' beyond it: the claim can fail.
/// Returns the departures (own, other), for the record.
pub fn assert_values_from_declared_positions(candidate: &dyn Rasterizer) -> (f64, f64) {
    let own = candidate
        .fixed_interpolate_from()
        .expect("a driver declares the positions it interpolates from");
    let other = InterpolateFrom::ALL
        .into_iter()
        .find(|&v| v != own)
        .unwrap();
    let bound = 2f64.powi(-16);
    let (mut worst_own, mut worst_other) = (0f64, 0f64);
    for id in [
        "clip/spec_interpolate_snapped",
        "clip/interp_perspective_clipped_gb_cts",
    ] {
        let scene = super::case(id);
        let (d_own, d_other) = (
            value_departure(candidate, &scene, own),
            value_departure(candidate, &scene, other),
        );
        assert!(
            d_own <= bound,
            "{} {id}: departs {d_own:e} from the {} positions' values it declares",
            candidate.name(),
            own.name()
        );
        assert!(
            d_other > bound,
            "{} {id}: departs only {d_other:e} from the {} positions' values: the scene does not tell them apart",
            candidate.name(),
            other.name()
        );
        worst_own = worst_own.max(d_own);
        worst_other = worst_other.max(d_other);
    }
    (worst_own, worst_other)
}
