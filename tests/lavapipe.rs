//! Mesa's lavapipe (Vulkan on the CPU, through wgpu) against the exact
//! reference, on the triangle cases it can express. Needs the `lavapipe`
//! feature and the system packages `mesa-vulkan-drivers libvulkan1`; without
//! an adapter each test says it skipped, and never passes by drawing nothing.
#![cfg(feature = "lavapipe")]

use std::path::Path;

use rastercheck::adapters::lavapipe::{self, Lavapipe, STANDARD_4X};
use rastercheck::harness::judge::{CandidateRun, Verdict};
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::{Plan, SamplePlan};
use rastercheck::scene::Scene;

/// Whether lavapipe is here; prints why not once per test.
fn available() -> bool {
    common::adapters::driver_here(
        "lavapipe",
        lavapipe::adapter_description(),
        "Vulkan adapter",
        "mesa-vulkan-drivers libvulkan1",
    )
}

mod common;
use common::adapters::{
    assert_each, assert_eight_ties_change_hands, assert_interpolation_within_the_bound,
    assert_prepared_draws_as_rasterize, assert_probe_diagnosis,
    assert_refuses_lines_and_judges_unsnapped, bundled_ids, record_every_triangle_case, square_of,
    INTERPOLATION, TIE_CASES, WINDING_CASES,
};
use common::sample_drivers::{
    assert_each_probe_lights_its_slot, assert_reversed_slots_fail, probe_scene, STANDARD_4,
};
use common::{case, inline, mismatched_samples, report, sample_name};

fn run(scene: &Scene) -> (oracle::ReferenceRun, CandidateRun) {
    common::run(scene, &Lavapipe)
}

/// Top-left cases beyond `TIE_CASES`, with samples exactly on edges, shared
/// edges and fan centres: lavapipe's own rule is top-left, so it must match
/// all of them exactly.
const MORE_TIE_CASES: &[&str] = &[
    "triangles/quad_grid_rot30",
    "triangles/pinwheel_axis_shift1_b8",
    "triangles/snap_tie_half_subpixel_b8",
    "triangles/mesh_full_canvas_odd",
];

/// probe finds lavapipe point-sampled at the centre with top-left ties
/// (its 8 subpixel bits: `tests/probe.rs`).
#[test]
fn probe_finds_a_point_sampler_with_top_left_ties() {
    if !available() {
        return;
    }
    assert_probe_diagnosis(&Lavapipe, "top-left");
}

#[test]
fn matches_the_reference_on_top_left_tie_cases() {
    if !available() {
        return;
    }
    assert_each(
        &[TIE_CASES, MORE_TIE_CASES].concat(),
        &Lavapipe,
        |_| {},
        |id, run, line, failures| {
            let m = run.metrics.as_ref().expect("lavapipe drew a frame");
            assert!(
                m.coverage.candidate_covered > 0,
                "{id}: lavapipe drew nothing"
            );
            if run.verdict != Verdict::Pass {
                failures.push(line.to_owned());
            }
        },
    );
}

/// The interpolation cases (depth, linear, flat, perspective with a wide
/// range of w): errors within the default bound (2^-16 of the largest value).
#[test]
fn interpolation_is_within_the_bound() {
    if !available() {
        return;
    }
    assert_interpolation_within_the_bound(INTERPOLATION, &Lavapipe, "lavapipe", |_| {});
}

/// lavapipe is top-left whatever the case says: under bottom-right it gives
/// the diagonal's samples to the other triangle, and the check sees it.
#[test]
fn its_tie_rule_is_top_left_not_the_cases() {
    if !available() {
        return;
    }
    let pair = |rule: &str| {
        square_of(
            rule,
            r#"{"triangle": [[0, 0], [8, 0], [8, 8]]},
               {"triangle": [[0, 0], [8, 8], [0, 8]]}"#,
        )
    };
    assert_eight_ties_change_hands(&Lavapipe, pair, "top-left", "bottom-right");
}

/// Culling follows the case's on-screen winding (y down), through the y
/// flip of NDC: each winding case passes.
#[test]
fn culling_follows_the_on_screen_winding() {
    if !available() {
        return;
    }
    for id in WINDING_CASES {
        let scene = case(id);
        let (reference, run) = run(&scene);
        assert_eq!(
            run.verdict,
            Verdict::Pass,
            "{}",
            report(id, &reference, &run)
        );
    }
}

/// A finding, not a bug of the adapter: lavapipe clips a triangle at the
/// viewport instead of rasterizing off-screen vertices in a guard band, and
/// the vertices clipping makes are re-snapped to 1/256. An edge from an
/// off-screen vertex through on-screen samples then moves by up to a
/// subpixel, and the samples exactly on it change hands
/// (`triangles/shared_edge_shallow`, `shared_edge_long_shallow`). The same
/// edge with its vertex on screen is exact; the mesh stays watertight.
#[test]
fn clipping_at_the_viewport_moves_ties_on_clipped_edges() {
    if !available() {
        return;
    }
    // Edges of slope 1/3 through the samples (0.5, 31.5), (3.5, 32.5), ...
    // From an on-screen vertex the ties are exact.
    let on_screen = inline(
        r#"{"name": "on", "canvas": {"width": 32, "height": 64},
            "primitives": [{"triangle": [[2, 32], [20, 38], [20, 0]]}]}"#,
    );
    let (reference, r) = run(&on_screen);
    assert_eq!(r.verdict, Verdict::Pass, "{}", report("on", &reference, &r));
    // From (-1, 31), clipping at x = 0 makes (0, 31 + 1/3), which snaps to
    // 31 + 85/256: the edge rises off its six samples.
    let off_screen = inline(
        r#"{"name": "off", "canvas": {"width": 32, "height": 64},
            "primitives": [{"triangle": [[-1, 31], [17, 37], [17, 0]]}]}"#,
    );
    let (reference, r) = run(&off_screen);
    eprintln!("finding: {}", report("off-screen vertex", &reference, &r));
    let m = r.metrics.as_ref().expect("lavapipe drew a frame");
    assert_eq!(m.coverage.extra, 0, "{}", judge::describe(&r));
    // Either the on-edge samples are lost (Mesa 22.3 here) or, on a driver
    // with a guard band, none is; nothing off the edge may differ.
    assert!(
        m.coverage.missing == 0 || m.coverage.missing == 6,
        "{}",
        judge::describe(&r)
    );
    let (reference, r) = run(&case("triangles/shared_edge_shallow"));
    eprintln!("finding: {}", report("shared_edge_shallow", &reference, &r));
    let w = r.metrics.as_ref().unwrap().watertight.clone().unwrap();
    assert!(w.is_watertight(), "{}", judge::describe(&r));
}

/// Far triangles with attributes, clipped at the target (the viewport
/// wgpu allows), pass under the restatement whose pieces take their
/// values from the whole triangles (SPEC.md §16.9;
/// `tests/data/far_values_clipped.json`, found by `fuzz -r gl`); the frame
/// fails the case judged unclipped and the pieces judged without values.
#[test]
fn far_values_clipped_at_the_viewport_pass() {
    if !available() {
        return;
    }
    common::viewport_drivers::assert_far_values_judged_clipped(&Lavapipe);
}

/// Lines are reported unsupported, never passed; unsnapped geometry is
/// judged at the driver's own bits (SPEC.md §3.2).
#[test]
fn refuses_what_it_cannot_express() {
    if !available() {
        return;
    }
    assert_refuses_lines_and_judges_unsnapped(&Lavapipe);
}

/// Every triangle case once, for the record: the verdicts, with the
/// departures lavapipe is known for listed rather than hidden.
#[test]
fn every_triangle_case_for_the_record() {
    if !available() {
        return;
    }
    record_every_triangle_case(&Lavapipe, "lavapipe");
}

/// The prepared path the bench times draws what `rasterize` draws, and
/// its draw draws into the targets as they stand: on overlapping triangles
/// with depth and attributes in three interpolation modes (three draw
/// calls), a fan, a culling case, two standard 4× cases, and the bench's
/// own kind of scene.
#[test]
fn the_prepared_path_draws_what_rasterize_draws() {
    if !available() {
        return;
    }
    assert_prepared_draws_as_rasterize(
        &Lavapipe,
        &[
            "triangles/interp_mixed_modes",
            "triangles/fan_16_center",
            "triangles/cull_cw_mixed_windings",
            "antialias/probe_standard4",
            "antialias/edge_slope_1_3_standard4",
        ],
    );
}

#[test]
fn is_listed_by_name() {
    assert!(rastercheck::registry::names().contains(&"lavapipe"));
    let r = rastercheck::registry::by_name("lavapipe").expect("registered");
    assert_eq!(r.name(), "lavapipe");
}

/// The bundled standard 4× antialiasing cases (`cases/antialias/*standard4*`,
/// the probe among them, and `count_standard_4`), sorted.
fn standard_4x_cases() -> Vec<String> {
    let ids = bundled_ids("antialias", |stem| {
        stem.contains("standard4") || stem.ends_with("standard_4")
    });
    assert!(ids.contains(&"antialias/probe_standard4".to_owned()));
    ids
}

/// lavapipe's 4× MSAA mask, read back sample by sample, against the exact
/// reference's on every bundled standard 4× case: every sample's count and
/// last primitive equal. The polygon sweeps are refused (lavapipe draws
/// triangles only), never passed.
#[test]
fn standard_4x_masks_equal_the_references_sample_by_sample() {
    if !available() {
        return;
    }
    eprintln!("msaa formats: {}", lavapipe::msaa_formats().unwrap());
    let (mut passed, mut refused) = (0, 0);
    let mut failures = Vec::new();
    for id in standard_4x_cases() {
        let scene = case(&id);
        let (reference, run) = run(&scene);
        eprintln!("{}", report(&id, &reference, &run));
        if scene.has_polygons() {
            assert!(
                matches!(run.verdict, Verdict::Unsupported(_)),
                "{id}: {}",
                run.verdict.label()
            );
            refused += 1;
            continue;
        }
        let frame = run.frame.as_ref().expect("lavapipe drew a frame");
        assert_eq!(frame.samples, 4, "{id}");
        assert!(
            frame.covered_samples() > 0 || reference.frame.covered_samples() == 0,
            "{id}: lavapipe drew nothing"
        );
        let wrong = mismatched_samples(&reference.frame, frame);
        if !wrong.is_empty() || run.verdict != Verdict::Pass {
            let names: Vec<String> = wrong.iter().map(|&i| sample_name(frame, i)).collect();
            failures.push(format!(
                "{id}: {} ({})",
                run.verdict.label(),
                names.join(" ")
            ));
        } else {
            passed += 1;
        }
    }
    eprintln!("standard 4x: {passed} exact, {refused} refused (polygons)");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(passed >= 10, "only {passed} cases drawn");
}

/// A 1/16-px square (two triangles, half-size 1/32) centred on the
/// standard location of sample i, in pixel (i, 0), for each i: the centre
/// is on the squares' shared diagonal, which the top-left rule gives to one
/// of them, and the square reaches no other sample.
/// The readback's slot order and lavapipe's sample positions: a tiny square
/// on standard location i lights exactly slot i of its pixel and nothing
/// else, so sample index i of the driver is standard location i, slot i.
#[test]
fn a_probe_on_each_standard_location_lights_exactly_that_slot() {
    if !available() {
        return;
    }
    // The probe's squares sit on Vulkan's standard 4× table.
    let offsets = Plan::for_scene(&probe_scene(STANDARD_4, 4))
        .antialias
        .unwrap()
        .offsets;
    assert_eq!(offsets, STANDARD_4X.map(|p| p.map(|c| c << 4)));
    let (_, run) = assert_each_probe_lights_its_slot(&Lavapipe, STANDARD_4, 4);
    let frame = run.frame.as_ref().expect("lavapipe drew a frame");
    for i in 0..4 {
        assert_eq!(frame.coverage[i * 4 + i], 1, "sample {i}");
    }
    assert_eq!(frame.resolved, Some(vec![0.25; 4]));
}

/// The comparison has teeth: the same frames with each pixel's slots
/// reversed fail the probe (every probe lands on the wrong slot) and the
/// bundled probe case, though the box resolve is unchanged.
#[test]
fn a_readback_in_the_wrong_slot_order_fails() {
    if !available() {
        return;
    }
    for (id, scene) in [
        ("probe", probe_scene(STANDARD_4, 4)),
        (
            "antialias/probe_standard4",
            case("antialias/probe_standard4"),
        ),
    ] {
        let reference = oracle::run_reference(&scene);
        let right = judge::run_candidate(&scene, &reference, &Lavapipe);
        assert_eq!(
            right.verdict,
            Verdict::Pass,
            "{}",
            report(id, &reference, &right)
        );
        let (reference, wrong) = assert_reversed_slots_fail(&Lavapipe, id, &scene);
        let frame = wrong.frame.as_ref().unwrap();
        // Slots 0 and 3, 1 and 2 trade places: every covered sample moves.
        let moved = mismatched_samples(&reference.frame, frame).len();
        assert_eq!(moved as u64, 2 * reference.frame.covered_samples(), "{id}");
        assert_eq!(
            frame.resolved,
            right.frame.as_ref().unwrap().resolved,
            "{id}"
        );
    }
}

/// Only Vulkan's standard 4× offsets are drawn, checked offset by offset
/// (the standard table in the wrong order is refused though its positions
/// are the same). lavapipe cannot choose its positions, so a 4-sample case
/// at other positions is judged at its own standard ones (SPEC §14.2.1),
/// named so; other counts are refused with the reason.
#[test]
fn other_sample_patterns_are_judged_at_its_own_positions_or_refused() {
    let plan = |offsets: Vec<[u32; 2]>, position_bits| SamplePlan {
        offsets,
        position_bits,
        adaptive: false,
    };
    assert_eq!(
        lavapipe::standard_4x_refusal(&plan(STANDARD_4X.to_vec(), 4)),
        None
    );
    let at_8: Vec<[u32; 2]> = STANDARD_4X.iter().map(|p| p.map(|c| c << 4)).collect();
    assert_eq!(lavapipe::standard_4x_refusal(&plan(at_8.clone(), 8)), None);
    assert!(lavapipe::standard_4x_refusal(&plan(at_8, 9)).is_some());
    let mut reversed = STANDARD_4X.to_vec();
    reversed.reverse();
    assert!(lavapipe::standard_4x_refusal(&plan(reversed, 4)).is_some());
    if !available() {
        return;
    }
    let scene = |aa: &str| {
        inline(&format!(
            r#"{{"name": "aa", "canvas": {{"width": 8, "height": 8}},
                "effects": {{"antialias": {aa}}},
                "primitives": [{{"triangle": [[0, 0], [8, 1], [1, 7]]}}]}}"#
        ))
    };
    for aa in [
        r#"{"samples": 8, "pattern": "standard"}"#,
        r#"{"samples": 16, "pattern": "standard"}"#,
    ] {
        let (_, r) = run(&scene(aa));
        match &r.verdict {
            Verdict::Unsupported(why) => assert!(why.contains("4x MSAA only"), "{why}"),
            other => panic!("{aa}: {}", other.label()),
        }
    }
    for aa in [
        r#"{"samples": 4, "pattern": "grid"}"#,
        r#"{"samples": 4, "pattern": "random", "seed": 3}"#,
    ] {
        let (reference, r) = run(&scene(aa));
        assert_eq!(r.verdict, Verdict::Pass, "{}", report(aa, &reference, &r));
        assert_eq!(
            r.judged.sample_pattern,
            Some(rastercheck::scene::Pattern::Standard),
            "{aa}"
        );
    }
    for bits in [4, 8, 16] {
        let aa = format!(r#"{{"samples": 4, "pattern": "standard", "position_bits": {bits}}}"#);
        let (reference, r) = run(&scene(&aa));
        assert_eq!(r.verdict, Verdict::Pass, "{}", report(&aa, &reference, &r));
    }
}

/// Depth and linear and flat attributes under 4× MSAA, interpolated at
/// each sample's own position (`@interpolate(linear, sample)`), within the
/// default bound, the mask exact: the linear and flat triangles of
/// `triangles/interp_mixed_modes`.
#[test]
fn depth_and_linear_attributes_per_sample_are_within_the_bound() {
    if !available() {
        return;
    }
    let scene = inline(
        r#"{"name": "modes4x", "canvas": {"width": 16, "height": 16},
            "rules": {"subpixel_bits": 8},
            "effects": {"antialias": {"samples": 4, "pattern": "standard"}},
            "primitives": [
              {"triangle": [{"position": [16, 0], "z": 2, "w": 3, "attributes": [-100, 100]},
                            {"position": [16, 16], "z": 4, "w": 0.5, "attributes": [0, 0]},
                            {"position": [0, 16], "z": 3, "w": 1, "attributes": ["1/3", 50]}],
               "interpolation": "linear"},
              {"triangle": [{"position": [16, 16], "z": 4, "w": 0.5, "attributes": [0, 0]},
                            {"position": [0, 0], "z": 1, "w": 0.2, "attributes": [100, -100]},
                            {"position": [8, -4], "z": 0, "w": 2, "attributes": [-7, 7]}],
               "interpolation": "flat"}],
            "expect": {"max_coverage_error": 1, "max_coverage_rms": 1}}"#,
    );
    let (reference, r) = run(&scene);
    eprintln!("{}", report("linear and flat at 4x", &reference, &r));
    let frame = r.frame.as_ref().expect("lavapipe drew a frame");
    assert!(mismatched_samples(&reference.frame, frame).is_empty());
    let m = r.metrics.as_ref().unwrap();
    assert_eq!(m.channels.len(), 3, "depth and two attributes compared");
    for c in &m.channels {
        eprintln!(
            "        {}: max {:.3e} ({:.1} ulp), bound {:.3e} over {} samples",
            c.channel, c.max_abs, c.max_ulp, c.allowed_abs, c.samples
        );
        assert!(c.within_bounds(), "{}", c.channel);
        assert_eq!(
            c.samples,
            reference.frame.covered_samples(),
            "{}",
            c.channel
        );
    }
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
}

/// A finding in the driver (Mesa 22.3 llvmpipe): with per-sample
/// interpolation, a perspective attribute is Σ λ·a/w interpolated at the
/// sample divided by Σ λ/w interpolated at the pixel centre, not at the
/// sample. The check catches it (the case fails, errors up to ~12 on a
/// range of 200); in fully covered pixels every sample equals that mixed
/// quotient to f32 precision.
#[test]
fn perspective_attributes_per_sample_divide_by_w_at_the_pixel_centre() {
    if !available() {
        return;
    }
    // (0,0) w 0.2 a 100; (16,0) w 3 a −100; (0,16) w 1 a 1/3: λ1 = x/16,
    // λ2 = y/16 in screen space.
    let scene = inline(
        r#"{"name": "persp4x", "canvas": {"width": 16, "height": 16},
            "rules": {"subpixel_bits": 8},
            "effects": {"antialias": {"samples": 4, "pattern": "standard"}},
            "primitives": [
              {"triangle": [{"position": [0, 0], "w": 0.2, "attributes": [100]},
                            {"position": [16, 0], "w": 3, "attributes": [-100]},
                            {"position": [0, 16], "w": 1, "attributes": ["1/3"]}]}]}"#,
    );
    let (reference, r) = run(&scene);
    eprintln!("finding: {}", report("perspective at 4x", &reference, &r));
    assert!(
        matches!(r.verdict, Verdict::Fail(_)),
        "{}",
        judge::describe(&r)
    );
    let frame = r.frame.as_ref().expect("lavapipe drew a frame");
    assert!(mismatched_samples(&reference.frame, frame).is_empty());
    let (a, w) = ([100.0, -100.0, 1.0 / 3.0], [0.2f64, 3.0, 1.0]);
    let sums = |x: f64, y: f64| {
        let l = [1.0 - x / 16.0 - y / 16.0, x / 16.0, y / 16.0];
        let den: f64 = (0..3).map(|k| l[k] / w[k]).sum();
        let num: f64 = (0..3).map(|k| l[k] * a[k] / w[k]).sum();
        (num, den)
    };
    let (mut checked, mut worst_reference) = (0, 0.0f64);
    for p in 0..frame.pixel_count() {
        let slots = p * 4..p * 4 + 4;
        if !slots.clone().all(|i| frame.coverage[i] == 1) {
            continue;
        }
        let (px, py) = ((p % 16) as f64, (p / 16) as f64);
        let (_, den_centre) = sums(px + 0.5, py + 0.5);
        for (s, i) in slots.enumerate() {
            let [sx, sy] = STANDARD_4X[s].map(|c| f64::from(c) / 16.0);
            let (num, den) = sums(px + sx, py + sy);
            let got = frame.attributes[0][i];
            let mixed = num / den_centre;
            assert!(
                (got - mixed).abs() <= 1e-4 * mixed.abs().max(1.0),
                "{}: {got} is not {mixed} (exact {})",
                sample_name(frame, i),
                num / den
            );
            worst_reference = worst_reference.max((got - reference.frame.attributes[0][i]).abs());
            checked += 1;
        }
    }
    eprintln!("{checked} samples of fully covered pixels; worst error {worst_reference:.3}");
    assert!(checked > 100 && worst_reference > 1.0);
}

/// Every antialiasing case once, for the record: lavapipe draws the
/// standard 4× ones it can (triangles), refuses the rest with a reason, and
/// never errors.
#[test]
fn every_antialias_case_for_the_record() {
    if !available() {
        return;
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/antialias");
    let mut ids: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            Some(format!("antialias/{}", name.strip_suffix(".json")?))
        })
        .collect();
    ids.sort();
    let (mut drawn, mut refused) = (0, 0);
    let mut errors = Vec::new();
    for id in &ids {
        let scene = case(id);
        let (reference, run) = run(&scene);
        eprintln!("{}", report(id, &reference, &run));
        match &run.verdict {
            Verdict::Error(why) => errors.push(format!("{id}: {why}")),
            Verdict::Unsupported(_) => refused += 1,
            _ => {
                drawn += 1;
                assert_eq!(reference.plan.samples_per_pixel, 4, "{id}");
            }
        }
    }
    eprintln!("{drawn} drawn, {refused} refused of {}", ids.len());
    assert!(errors.is_empty(), "lavapipe broke: {}", errors.join("\n"));
    assert!(drawn >= 13, "{drawn} drawn");
}

/// The tie rule at the sample positions: two triangles share the vertical
/// edge x = 4 + 6/16, which runs through sample 0 of every pixel of column
/// 4. lavapipe gives those 8 samples to the right triangle (the edge is
/// its left edge: top-left), sample by sample as the reference does under
/// top-left and bottom-left; under top-right and bottom-right the reference
/// gives them to the left triangle and the check sees exactly those 8.
#[test]
fn ties_at_sample_positions_follow_the_top_left_rule() {
    if !available() {
        return;
    }
    let pair = |rule: &str| {
        inline(&format!(
            r#"{{"name": "tie4x", "canvas": {{"width": 8, "height": 8}},
                "rules": {{"subpixel_bits": 8, "fill_rule": "{rule}"}},
                "effects": {{"antialias": {{"samples": 4, "pattern": "standard"}}}},
                "primitives": [
                  {{"triangle": [[4.375, -8], [4.375, 16], [-20, 4]]}},
                  {{"triangle": [[4.375, -8], [30, 4], [4.375, 16]]}}],
                "expect": {{"max_coverage_error": 1, "max_coverage_rms": 1}}}}"#
        ))
    };
    for (rule, differing) in [
        ("top-left", 0),
        ("bottom-left", 0),
        ("top-right", 8),
        ("bottom-right", 8),
    ] {
        // Held to the case's rule (`run` judges it under its own).
        let (reference, r) = common::run_as_stated(&pair(rule), &Lavapipe);
        eprintln!("{}", report(rule, &reference, &r));
        let frame = r.frame.as_ref().expect("lavapipe drew a frame");
        assert_eq!(frame.covered_samples(), 256, "{rule}");
        let wrong: Vec<String> = mismatched_samples(&reference.frame, frame)
            .into_iter()
            .map(|i| sample_name(frame, i))
            .collect();
        let expected: Vec<String> = (0..differing).map(|y| format!("(4,{y})#0")).collect();
        assert_eq!(wrong, expected, "{rule}");
        for y in 0..8 {
            assert_eq!(frame.last[frame.index(4, y)], 2, "{rule}: (4,{y})#0");
        }
        let m = r.metrics.as_ref().unwrap();
        assert_eq!(
            (m.coverage.wrong_owner, m.coverage.missing, m.coverage.extra),
            (differing as u64, 0, 0),
            "{rule}"
        );
    }
}

/// wgpu has no choice of provoking vertex: a flat primitive with
/// attributes under `provoking_vertex: last` is unsupported, with the
/// reason, rather than drawn with the first vertex's values.
#[test]
fn provoking_last_is_unsupported() {
    use rastercheck::rasterizer::Rasterizer;
    if !available() {
        return;
    }
    let scene = inline(
        r#"{"name": "provoking_last", "canvas": {"width": 4, "height": 4},
            "rules": {"provoking_vertex": "last"},
            "primitives": [{"interpolation": "flat", "triangle": [
                {"position": [0, 0], "attributes": [10]},
                {"position": [8, 0], "attributes": [20]},
                {"position": [0, 8], "attributes": [30]}]}]}"#,
    );
    let plan = rastercheck::plan::Plan::for_scene(&scene);
    match Lavapipe.rasterize(&scene, &plan) {
        Err(rastercheck::rasterizer::RasterError::Unsupported(why)) => {
            assert!(why.contains("provoking_vertex: last"), "{why}")
        }
        other => panic!("want unsupported, got {other:?}"),
    }
}
