//! The sample-slot probes the Vulkan driver tests share (`tests/vulkan.rs`,
//! `tests/lavapipe.rs`): a tiny square on each sample of a pattern must
//! light exactly that sample's slot, and the same frames with each
//! pixel's slots reversed must fail.

use rastercheck::harness::judge::{self, CandidateRun, Verdict};
use rastercheck::harness::oracle::{self, ReferenceRun};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::Scene;

use super::adapters::SlotsReversed;
use super::{inline, report, run, sample_name};

/// Vulkan's standard 4× pattern, at the default position bits.
pub const STANDARD_4: &str = r#"{"samples": 4, "pattern": "standard"}"#;

/// A tiny square around each sample of `pattern` (n samples), in pixel
/// (i, 0) for sample i: the adapter must light exactly slot i of pixel i.
pub fn probe_scene(pattern: &str, n: u32) -> Scene {
    let probe = inline(&format!(
        r#"{{"name": "offsets", "canvas": {{"width": {n}, "height": 1}},
            "effects": {{"antialias": {pattern}}},
            "primitives": [{{"triangle": [[0, 0], [1, 0], [0, 1]]}}]}}"#
    ));
    let offsets = Plan::for_scene(&probe).antialias.unwrap().offsets;
    let squares: Vec<String> = offsets
        .iter()
        .enumerate()
        .flat_map(|(i, [sx, sy])| {
            let unit = if pattern.contains("position_bits") {
                16.0
            } else {
                256.0
            };
            let (cx, cy) = (i as f64 + f64::from(*sx) / unit, f64::from(*sy) / unit);
            let (l, r, t, b) = (cx - 0.03125, cx + 0.03125, cy - 0.03125, cy + 0.03125);
            [
                format!(r#"{{"triangle": [[{l}, {t}], [{r}, {t}], [{r}, {b}]]}}"#),
                format!(r#"{{"triangle": [[{l}, {t}], [{r}, {b}], [{l}, {b}]]}}"#),
            ]
        })
        .collect();
    inline(&format!(
        r#"{{"name": "probe", "canvas": {{"width": {n}, "height": 1}},
            "rules": {{"subpixel_bits": 8}}, "effects": {{"antialias": {pattern}}},
            "primitives": [{}],
            "expect": {{"max_coverage_error": 0.25, "max_coverage_rms": 0.25}}}}"#,
        squares.join(", ")
    ))
}

/// Draws `pattern`'s probe (n samples) with `candidate`, and asserts that
/// exactly slot i of pixel i is lit, for every i, and that the probe
/// passes. The runs are returned for the adapter's own further checks.
pub fn assert_each_probe_lights_its_slot(
    candidate: &dyn Rasterizer,
    pattern: &str,
    n: u32,
) -> (ReferenceRun, CandidateRun) {
    let scene = probe_scene(pattern, n);
    let (reference, run) = run(&scene, candidate);
    let frame = run
        .frame
        .as_ref()
        .unwrap_or_else(|| panic!("{} drew a frame", candidate.name()));
    let lit: Vec<String> = (0..frame.sample_count())
        .filter(|&i| frame.coverage[i] > 0)
        .map(|i| sample_name(frame, i))
        .collect();
    let expected: Vec<String> = (0..n).map(|i| format!("({i},0)#{i}")).collect();
    assert_eq!(lit, expected, "{} {pattern}", candidate.name());
    assert_eq!(
        run.verdict,
        Verdict::Pass,
        "{}",
        report("probe", &reference, &run)
    );
    (reference, run)
}

/// `candidate` with each pixel's slots read back in reverse fails `scene`
/// (`id` names it), so the slot order is checked, not assumed. The runs
/// are returned for the adapter's own further checks.
pub fn assert_reversed_slots_fail(
    candidate: &dyn Rasterizer,
    id: &str,
    scene: &Scene,
) -> (ReferenceRun, CandidateRun) {
    let reference = oracle::run_reference(scene);
    let wrong = judge::run_candidate(scene, &reference, &SlotsReversed(candidate));
    eprintln!("{}", report(id, &reference, &wrong));
    let verdict = &wrong.verdict;
    assert!(matches!(verdict, Verdict::Fail(_)), "{id}: {verdict:?}");
    (reference, wrong)
}
