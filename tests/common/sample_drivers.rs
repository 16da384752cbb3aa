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
    probe_scene_at(pattern, n, 8)
}

/// [`probe_scene`] for a driver that snaps to `bits` subpixel bits: below
/// 5 the square's ±1/32 would snap away (SwiftShader snaps to 4), so each
/// sample gets instead the smallest triangle of the driver's grid that
/// holds it strictly inside, with no other point of the grid inside or on
/// its edges but its corners (Pick: area 3/2 steps², 3 boundary points,
/// 1 inside), turned so that its one corner off the sample's row and
/// column is no other sample's position.
pub fn probe_scene_at(pattern: &str, n: u32, bits: u32) -> Scene {
    let probe = inline(&format!(
        r#"{{"name": "offsets", "canvas": {{"width": {n}, "height": 1}},
            "effects": {{"antialias": {pattern}}},
            "primitives": [{{"triangle": [[0, 0], [1, 0], [0, 1]]}}]}}"#
    ));
    let offsets = Plan::for_scene(&probe).antialias.unwrap().offsets;
    let unit = if pattern.contains("position_bits") {
        16.0
    } else {
        256.0
    };
    let at: Vec<(f64, f64)> = offsets
        .iter()
        .map(|[sx, sy]| (f64::from(*sx) / unit, f64::from(*sy) / unit))
        .collect();
    let squares: Vec<String> = at
        .iter()
        .enumerate()
        .flat_map(|(i, &(sx, sy))| {
            let (cx, cy) = (i as f64 + sx, sy);
            if bits >= 5 {
                let (l, r, t, b) = (cx - 0.03125, cx + 0.03125, cy - 0.03125, cy + 0.03125);
                return vec![
                    format!(r#"{{"triangle": [[{l}, {t}], [{r}, {t}], [{r}, {b}]]}}"#),
                    format!(r#"{{"triangle": [[{l}, {t}], [{r}, {b}], [{l}, {b}]]}}"#),
                ];
            }
            let g = f64::from(bits).exp2().recip();
            let taken = |dx: f64, dy: f64| {
                at.iter().any(|&(x, y)| {
                    (x - (sx + dx * g)).abs() < 1e-9 && (y - (sy + dy * g)).abs() < 1e-9
                })
            };
            // (-1, -1), (1, 0), (0, 1), turned by quarter turns.
            let turn = |(x, y): (f64, f64)| (-y, x);
            let mut corners = [(-1.0, -1.0), (1.0, 0.0), (0.0, 1.0)];
            for _ in 0..4 {
                if !taken(corners[0].0, corners[0].1) {
                    break;
                }
                corners = corners.map(turn);
            }
            let [a, b, c] = corners.map(|(dx, dy)| format!("[{}, {}]", cx + dx * g, cy + dy * g));
            vec![format!(r#"{{"triangle": [{a}, {b}, {c}]}}"#)]
        })
        .collect();
    inline(&format!(
        r#"{{"name": "probe", "canvas": {{"width": {n}, "height": 1}},
            "rules": {{"subpixel_bits": {}}}, "effects": {{"antialias": {pattern}}},
            "primitives": [{}],
            "expect": {{"max_coverage_error": 0.25, "max_coverage_rms": 0.25}}}}"#,
        bits.min(8),
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
    let bits = candidate.fixed_subpixel_bits().unwrap_or(8);
    let scene = probe_scene_at(pattern, n, bits);
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
