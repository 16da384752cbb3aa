//! Mesa's lavapipe (Vulkan on the CPU, through wgpu) against the exact
//! reference, on the triangle cases it can express. Needs the `lavapipe`
//! feature and the system packages `mesa-vulkan-drivers libvulkan1`; without
//! an adapter each test says it skipped, and never passes by drawing nothing.
#![cfg(feature = "lavapipe")]

use std::path::Path;

use rastercheck::adapters::lavapipe::{self, Lavapipe};
use rastercheck::scene::Scene;
use rastercheck::suite::{self, CandidateRun, Verdict};

/// Whether lavapipe is here; prints why not once per test.
fn available() -> bool {
    match lavapipe::adapter_description() {
        Ok(description) => {
            eprintln!("lavapipe adapter: {description}");
            true
        }
        Err(why) => {
            eprintln!("skipped: no Vulkan adapter (install mesa-vulkan-drivers libvulkan1): {why}");
            false
        }
    }
}

mod common;
use common::{case, inline, report};

fn run(scene: &Scene) -> (suite::ReferenceRun, CandidateRun) {
    common::run(scene, &Lavapipe)
}

/// Top-left cases with samples exactly on edges, shared edges and fan
/// centres: lavapipe's own rule is top-left, so it must match exactly.
const TOP_LEFT_TIES: &[&str] = &[
    "triangles/fill_rule_top_left",
    "triangles/fan_16_center",
    "triangles/fan_16_center_ccw",
    "triangles/fan_16_center_snap_tie",
    "triangles/fan_16_square_ring",
    "triangles/fan_64_center",
    "triangles/shared_edge_diagonal",
    "triangles/shared_edge_antidiagonal",
    "triangles/shared_edge_horizontal",
    "triangles/shared_edge_vertical",
    "triangles/shared_edge_steep",
    "triangles/shared_edge_mixed_windings",
    "triangles/shared_edge_fractions_offgrid",
    "triangles/quad_grid_rot30",
    "triangles/pinwheel_axis_shift1_b8",
    "triangles/snap_tie_half_subpixel_b8",
    "triangles/mesh_full_canvas_odd",
];

#[test]
fn matches_the_reference_on_top_left_tie_cases() {
    if !available() {
        return;
    }
    let mut failures = Vec::new();
    for id in TOP_LEFT_TIES {
        let scene = case(id);
        let (reference, run) = run(&scene);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        let m = run.metrics.as_ref().expect("lavapipe drew a frame");
        assert!(
            m.coverage.candidate_covered > 0,
            "{id}: lavapipe drew nothing"
        );
        if run.verdict != Verdict::Pass {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Interpolation cases: depth, linear, flat, perspective with a wide range
/// of w; errors within the default bound (2^-16 of the largest value).
const INTERPOLATION: &[&str] = &[
    "triangles/interp_depth_z",
    "triangles/interp_depth_perspective_w",
    "triangles/interp_flat",
    "triangles/interp_linear",
    "triangles/interp_mixed_modes",
    "triangles/interp_perspective_extreme",
    "triangles/interp_perspective_fan",
    "triangles/interp_perspective_w_range",
];

#[test]
fn interpolation_is_within_the_bound() {
    if !available() {
        return;
    }
    let mut failures = Vec::new();
    for id in INTERPOLATION {
        let scene = case(id);
        let (reference, run) = run(&scene);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        let m = run.metrics.as_ref().expect("lavapipe drew a frame");
        assert!(!m.channels.is_empty(), "{id}: no channel was compared");
        for c in &m.channels {
            assert!(c.samples > 0, "{id}: {} compared on no sample", c.channel);
            eprintln!(
                "        {}: max {:.3e} ({:.1} ulp), rms {:.3e}, bound {:.3e}",
                c.channel, c.max_abs, c.max_ulp, c.rms, c.allowed_abs
            );
            if !c.within_bounds() {
                failures.push(format!("{id}: {} max {:e}", c.channel, c.max_abs));
            }
        }
        if run.verdict != Verdict::Pass {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// lavapipe is top-left whatever the case says: under bottom-right it gives
/// the diagonal's samples to the other triangle, and the check sees it.
#[test]
fn its_tie_rule_is_top_left_not_the_cases() {
    if !available() {
        return;
    }
    let pair = |rule: &str| {
        inline(&format!(
            r#"{{"name": "pair", "canvas": {{"width": 8, "height": 8}},
                "rules": {{"fill_rule": "{rule}"}},
                "primitives": [
                  {{"triangle": [[0, 0], [8, 0], [8, 8]]}},
                  {{"triangle": [[0, 0], [8, 8], [0, 8]]}}],
                "expect": {{"watertight": true, "samples_covered": 64}}}}"#
        ))
    };
    let (_, top_left) = run(&pair("top-left"));
    assert_eq!(
        top_left.verdict,
        Verdict::Pass,
        "{}",
        suite::describe(&top_left)
    );
    let (_, bottom_right) = run(&pair("bottom-right"));
    let m = bottom_right.metrics.as_ref().unwrap();
    assert_eq!(
        (m.coverage.wrong_owner, m.coverage.missing, m.coverage.extra),
        (8, 0, 0),
        "{}",
        suite::describe(&bottom_right)
    );
}

/// Culling follows the case's on-screen winding (y down), through the y
/// flip of NDC: each winding case passes.
#[test]
fn culling_follows_the_on_screen_winding() {
    if !available() {
        return;
    }
    for id in [
        "triangles/winding_cw_cull_cw",
        "triangles/winding_cw_cull_ccw",
        "triangles/winding_ccw_cull_cw",
        "triangles/winding_ccw_cull_ccw",
        "triangles/cull_cw_mixed_windings",
        "triangles/cull_ccw_mixed_windings",
    ] {
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
    assert_eq!(m.coverage.extra, 0, "{}", suite::describe(&r));
    // Either the on-edge samples are lost (Mesa 22.3 here) or, on a driver
    // with a guard band, none is; nothing off the edge may differ.
    assert!(
        m.coverage.missing == 0 || m.coverage.missing == 6,
        "{}",
        suite::describe(&r)
    );
    let (reference, r) = run(&case("triangles/shared_edge_shallow"));
    eprintln!("finding: {}", report("shared_edge_shallow", &reference, &r));
    let w = r.metrics.as_ref().unwrap().watertight.clone().unwrap();
    assert!(w.is_watertight(), "{}", suite::describe(&r));
}

/// Lines and unsnapped geometry are reported unsupported, never passed.
#[test]
fn refuses_what_it_cannot_express() {
    if !available() {
        return;
    }
    let line = inline(
        r#"{"name": "l", "canvas": {"width": 8, "height": 8},
            "primitives": [{"line": [[0.5, 0.5], [7.5, 3.5]]}]}"#,
    );
    assert!(matches!(run(&line).1.verdict, Verdict::Unsupported(_)));
    let scene = case("triangles/unsnapped_dyadic_edges");
    assert!(matches!(run(&scene).1.verdict, Verdict::Unsupported(_)));
}

/// Every triangle case once, for the record: the verdicts, with the
/// departures lavapipe is known for listed rather than hidden.
#[test]
fn every_triangle_case_for_the_record() {
    if !available() {
        return;
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles");
    let mut ids: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            Some(format!("triangles/{}", name.strip_suffix(".json")?))
        })
        .collect();
    ids.sort();
    let mut errors = Vec::new();
    for id in &ids {
        let scene = case(id);
        let (reference, run) = run(&scene);
        eprintln!("{}", report(id, &reference, &run));
        if let Verdict::Error(why) = &run.verdict {
            errors.push(format!("{id}: {why}"));
        }
    }
    assert!(errors.is_empty(), "lavapipe broke: {}", errors.join("\n"));
}

#[test]
fn is_listed_by_name() {
    assert!(rastercheck::adapters::names().contains(&"lavapipe"));
    let r = rastercheck::adapters::by_name("lavapipe").expect("registered");
    assert_eq!(r.name(), "lavapipe");
}
