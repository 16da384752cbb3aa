//! Screen-space scenes reaching past the adapter's target, as every GPU
//! API adapter draws them (`adapters/gpu/view.rs`): through a viewport
//! that encloses them, so that the driver clips nothing the case does not
//! clip, and a shared edge crossing the target's border stays where the
//! snapped vertices put it (SPEC.md §2).
//!
//! The foil is what the adapters did before: the same triangles drawn
//! through a viewport the size of the target, written as the clip-space
//! case the driver then saw (viewport `0, 0, P, Q`; vertex `(x, y)` at clip
//! `(2x/P − 1, 2y/Q − 1, ½, 1)`, exact). The driver clips them at the
//! target's side planes and snaps the new vertices, which moves the
//! shared edge: its frame differs from the screen-space reference.
#![allow(dead_code)]

use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{judge, oracle};
use rastercheck::rasterizer::Rasterizer;

use super::{case, differences, inline, mismatched_samples};

/// Bundled cases whose triangles reach past their power-of-two target
/// (their canvas) and share an edge that crosses its border; each failed
/// on SwiftShader, lavapipe and llvmpipe while the viewport was the
/// target (`git show 4c8628d~1:docs/drivers/departures/*/clips-screen-space-at-the-viewport.md`).
pub const PAST_THE_TARGET: &[&str] = &[
    "triangles/shared_edge_shallow",
    "triangles/shared_edge_long_shallow",
];

/// Each of [`PAST_THE_TARGET`] reaches past its target, is judged `pass`,
/// and matches the reference sample for sample; and the same triangles
/// drawn through the target's viewport (the foil) do not.
pub fn assert_drawn_unclipped(candidate: &dyn Rasterizer) {
    let mut failures = Vec::new();
    let mut foils_missed = Vec::new();
    for id in PAST_THE_TARGET {
        let scene = case(id);
        let (p, q) = (
            scene.canvas.width.next_power_of_two(),
            scene.canvas.height.next_power_of_two(),
        );
        let triangles = triangles(&scene);
        let outside = triangles.iter().flatten().any(|&[x, y]| {
            !(0.0..=f64::from(p)).contains(&x) || !(0.0..=f64::from(q)).contains(&y)
        });
        assert!(outside, "{id}: no vertex past the {p}×{q} target");

        let reference = oracle::run_reference(&scene);
        let run = judge::run_candidate(&scene, &reference, candidate);
        let frame = candidate
            .rasterize(&scene, &reference.plan)
            .unwrap_or_else(|e| panic!("{id}: {e}"));
        let wrong = differences(&reference.frame, &frame, candidate.name());
        if run.verdict != Verdict::Pass || !wrong.is_empty() {
            failures.push(format!("{id}: {:?}, {}", run.verdict, wrong.join("; ")));
        }

        let foil = inline(&through_the_target(&scene, &triangles, (p, q)));
        let foil_plan = oracle::run_reference(&foil).plan;
        let foil_frame = candidate
            .rasterize(&foil, &foil_plan)
            .unwrap_or_else(|e| panic!("{id} through the target: {e}"));
        let moved = mismatched_samples(&reference.frame, &foil_frame).len();
        eprintln!("{id}: through the {p}×{q} target, {moved} samples move");
        if moved == 0 {
            foils_missed.push(*id);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        foils_missed.is_empty(),
        "drawn through the target's viewport, {foils_missed:?} move no sample: \
         the check would not have caught the clipping"
    );
}

/// The scene's triangles' vertices, as f64 (the bundled cases' vertices
/// are dyadic with few bits: exact).
fn triangles(scene: &rastercheck::scene::Scene) -> Vec<[[f64; 2]; 3]> {
    scene
        .primitives
        .iter()
        .filter_map(|p| match p {
            rastercheck::scene::Primitive::Triangle(t) => Some(
                t.vertices
                    .each_ref()
                    .map(|v| [v.x.to_f64_lossy(), v.y.to_f64_lossy()]),
            ),
            _ => None,
        })
        .collect()
}

/// The clip-space case a driver saw of `scene` when the viewport was the
/// `(p, q)` target.
fn through_the_target(
    scene: &rastercheck::scene::Scene,
    triangles: &[[[f64; 2]; 3]],
    (p, q): (u32, u32),
) -> String {
    let clip = |[x, y]: [f64; 2]| {
        let (cx, cy) = (2.0 * x / f64::from(p) - 1.0, 2.0 * y / f64::from(q) - 1.0);
        format!("{{\"clip\": [{cx}, {cy}, 0.5, 1]}}")
    };
    let primitives: Vec<String> = triangles
        .iter()
        .map(|t| format!("{{\"triangle\": [{}]}}", t.map(clip).join(", ")))
        .collect();
    format!(
        r#"{{"name": "through_the_target", "canvas": {{"width": {w}, "height": {h}}},
  "rules": {{"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none",
    "clip_xy": "clip-then-snap", "clip_z": "clip-then-snap", "depth": "clip",
    "provoking_vertex": "first"}},
  "viewport": {{"x": 0, "y": 0, "width": {p}, "height": {q}, "min_depth": 0, "max_depth": 1}},
  "primitives": [{}]}}"#,
        primitives.join(",\n"),
        w = scene.canvas.width,
        h = scene.canvas.height,
    )
}

/// A case under `tests/data/` by name.
fn data(name: &str) -> rastercheck::scene::Scene {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/data/{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    rastercheck::scene::parse_case(
        &text,
        &path.display().to_string(),
        &rastercheck::scene::Limits::default(),
    )
    .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Why `frame` fails `scene` as the reference draws it, restated as
/// given; empty when it passes.
fn failures_against(
    scene: &rastercheck::scene::Scene,
    frame: &rastercheck::frame::Frame,
) -> Vec<String> {
    let reference = oracle::run_reference(scene);
    let m = rastercheck::metrics::measure(scene, &reference.frame, frame, None);
    rastercheck::metrics::failures(scene, &reference.frame, &m)
}

/// Far triangles with attributes that the driver clips at its viewport
/// (`tests/data/far_values_clipped.json`, found by `fuzz -r gl`, SPEC.md
/// §16.9): judged `pass`, restated clipped with the pieces' values taken
/// from the whole triangles' planes, and said so. The same frame fails
/// both restatements that fall short: the case judged unclipped (under
/// the candidate's other conventions: how it was judged before, coverage
/// departing on the clipped edges), and the pieces judged without their
/// values (a polygon carries none).
pub fn assert_far_values_judged_clipped(candidate: &dyn Rasterizer) {
    use rastercheck::harness::profile::OwnConventions;
    let scene = data("far_values_clipped");
    let reference = oracle::run_reference(&scene);
    let run = judge::run_candidate(&scene, &reference, candidate);
    assert_eq!(run.verdict, Verdict::Pass, "{}", judge::describe(&run));
    assert!(run.judged.viewport.is_some(), "not restated clipped");
    assert!(run.judged.viewport_values, "its values not restated");
    let frame = run.frame.as_ref().expect("a frame");

    let own = OwnConventions::of(candidate, &scene);
    let unclipped = failures_against(&own.restate(&scene), frame);
    eprintln!("judged unclipped: {unclipped:?}");
    assert!(
        unclipped.iter().any(|f| f.contains("sample")),
        "judged unclipped, its coverage does not depart: {unclipped:?}"
    );
    let own = own.with_viewport(candidate, &scene, &reference.plan);
    let without_values = failures_against(&own.restate(&scene), frame);
    eprintln!("judged without the pieces' values: {without_values:?}");
    assert!(
        without_values.iter().any(|f| f.contains("attribute 0")),
        "the pieces judged without values pass: {without_values:?}"
    );
}
