//! Mesa's OpenGL on the CPU (llvmpipe, through EGL surfaceless) against the
//! exact reference, on the triangle cases it can express; and softpipe, in a
//! process of its own (Mesa picks one gallium driver per process). Needs the
//! `gl` feature and the system packages `libegl1 libegl-mesa0
//! libgl1-mesa-dri`; without a display each test says it skipped, and never
//! passes by drawing nothing.
#![cfg(feature = "gl")]

use std::path::Path;
use std::process::Command;

use rastercheck::adapters::gl::{self, Gl};
use rastercheck::harness::suite::{self, CandidateRun, Verdict};
use rastercheck::scene::{FillRule, Scene};

/// Whether llvmpipe is here; prints why not once per test.
fn available() -> bool {
    match gl::renderer_description() {
        Ok(description) if description.contains("llvmpipe") => {
            eprintln!("gl renderer: {description}");
            true
        }
        Ok(description) => {
            eprintln!("skipped: the GL renderer is {description}, not llvmpipe (GALLIUM_DRIVER?)");
            false
        }
        Err(why) => {
            eprintln!(
                "skipped: no EGL/GL driver (install libegl1 libegl-mesa0 libgl1-mesa-dri): {why}"
            );
            false
        }
    }
}

mod common;
use common::{case, inline, report};

fn run(scene: &Scene) -> (suite::ReferenceRun, CandidateRun) {
    common::run(scene, &Gl)
}

/// Tie cases (samples exactly on edges, shared edges, fan centres) written
/// for top-left. Mesa's GL, read back y down, is bottom-left: held to that
/// rule, llvmpipe must match the reference exactly, sample for sample.
const TIE_CASES: &[&str] = &[
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
    "triangles/quad_grid_rot0",
    "triangles/quad_grid_rot30",
    "triangles/quad_grid_rot45",
    "triangles/pinwheel_axis_shift1_b8",
    "triangles/snap_tie_half_subpixel_b8",
    "triangles/mesh_full_canvas_odd",
    "triangles/subpixel_no_sample",
];

#[test]
fn matches_the_reference_under_bottom_left() {
    if !available() {
        return;
    }
    let mut failures = Vec::new();
    for id in TIE_CASES {
        let mut scene = case(id);
        scene.rules.fill_rule = FillRule::BottomLeft;
        let (reference, run) = run(&scene);
        let m = run.metrics.as_ref().expect("gl drew a frame");
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        let c = &m.coverage;
        if (c.missing, c.extra, c.wrong_owner) != (0, 0, 0) {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The bundled fill-rule cases: bottom-left passes; top-left fails with
/// samples given to the other triangle, but no hole and no overdraw.
#[test]
fn its_tie_rule_is_bottom_left() {
    if !available() {
        return;
    }
    let (reference, bottom_left) = run(&case("triangles/fill_rule_bottom_left"));
    assert_eq!(
        bottom_left.verdict,
        Verdict::Pass,
        "{}",
        report("fill_rule_bottom_left", &reference, &bottom_left)
    );
    let (reference, top_left) = run(&case("triangles/fill_rule_top_left"));
    eprintln!("{}", report("fill_rule_top_left", &reference, &top_left));
    assert!(matches!(top_left.verdict, Verdict::Fail(_)));
    let m = top_left.metrics.as_ref().unwrap();
    assert!(m.coverage.wrong_owner > 0, "{}", suite::describe(&top_left));
    let w = m.watertight.clone().expect("a mesh case");
    assert!(w.is_watertight(), "{}", suite::describe(&top_left));
    // Two quads sharing a horizontal edge through the sample row y = 4.5:
    // top-left and bottom-left agree on every slanted edge and differ on
    // that row's 8 samples, which change hands.
    let pair = |rule: &str| {
        inline(&format!(
            r#"{{"name": "pair", "canvas": {{"width": 8, "height": 8}},
                "rules": {{"fill_rule": "{rule}"}},
                "primitives": [
                  {{"triangle": [[0, 0], [8, 0], [8, 4.5]]}},
                  {{"triangle": [[0, 0], [8, 4.5], [0, 4.5]]}},
                  {{"triangle": [[0, 4.5], [8, 4.5], [8, 8]]}},
                  {{"triangle": [[0, 4.5], [8, 8], [0, 8]]}}],
                "expect": {{"watertight": true, "samples_covered": 64}}}}"#
        ))
    };
    let (_, r) = run(&pair("bottom-left"));
    assert_eq!(r.verdict, Verdict::Pass, "{}", suite::describe(&r));
    let (_, r) = run(&pair("top-left"));
    let m = r.metrics.as_ref().unwrap();
    assert_eq!(
        (m.coverage.wrong_owner, m.coverage.missing, m.coverage.extra),
        (8, 0, 0),
        "{}",
        suite::describe(&r)
    );
}

/// Interpolation cases (depth, linear, flat, perspective with a wide range
/// of w), held to bottom-left: coverage exact, errors within the default
/// bound.
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
        let mut scene = case(id);
        scene.rules.fill_rule = FillRule::BottomLeft;
        let (reference, run) = run(&scene);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        let m = run.metrics.as_ref().expect("gl drew a frame");
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

/// Culling follows the case's on-screen winding through GL's y-up window
/// and the read-back flip: each winding case, held to bottom-left, passes
/// (culled triangles draw nothing, kept ones match).
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
        "triangles/sliver_cull_cw",
        "triangles/sliver_cull_ccw",
    ] {
        let mut scene = case(id);
        scene.rules.fill_rule = FillRule::BottomLeft;
        let (reference, run) = run(&scene);
        let m = run.metrics.as_ref().expect("gl drew a frame");
        let c = &m.coverage;
        assert_eq!(
            (c.missing, c.extra, c.wrong_owner),
            (0, 0, 0),
            "{}",
            report(id, &reference, &run)
        );
    }
}

/// Lines and unsnapped geometry are reported unsupported, never passed; in
/// a process holding llvmpipe, `softpipe` fails and says how to get it.
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
    let scene = case("triangles/fill_rule_top_left");
    let reference = suite::run_reference(&scene);
    let r = suite::run_candidate(&scene, &reference, &gl::Softpipe);
    match &r.verdict {
        Verdict::Error(why) => assert!(why.contains("GALLIUM_DRIVER=softpipe"), "{why}"),
        other => panic!("softpipe in an llvmpipe process: {other:?}"),
    }
}

/// Every triangle case once, for the record: the verdicts under the cases'
/// own rules, with llvmpipe's departures listed rather than hidden.
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
    assert!(errors.is_empty(), "gl broke: {}", errors.join("\n"));
}

/// softpipe, in a process of its own (the CLI, `GALLIUM_DRIVER` unset so
/// that the adapter sets it): its rule is bottom-right.
#[test]
fn softpipe_is_bottom_right_in_its_own_process() {
    if !available() {
        return;
    }
    let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles");
    let output = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .env_remove("GALLIUM_DRIVER")
        .args(["run", "-r", "softpipe"])
        .arg(cases.join("fill_rule_bottom_right.json"))
        .arg(cases.join("fill_rule_top_left.json"))
        .output()
        .expect("the rastercheck binary runs");
    let text = String::from_utf8_lossy(&output.stdout);
    eprintln!("{text}{}", String::from_utf8_lossy(&output.stderr));
    if text.contains("ERROR") || !text.contains("softpipe") {
        eprintln!("skipped: softpipe did not draw (not built into this Mesa?)");
        return;
    }
    let verdict = |id: &str| {
        text.lines()
            .find(|l| l.contains(id))
            .and_then(|l| l.split_whitespace().next())
            .unwrap_or("?")
            .to_owned()
    };
    assert_eq!(verdict("fill_rule_bottom_right"), "PASS", "{text}");
    assert_eq!(verdict("fill_rule_top_left"), "FAIL", "{text}");
}

#[test]
fn is_listed_by_name() {
    let names = rastercheck::adapters::names();
    assert!(names.contains(&"gl") && names.contains(&"softpipe"));
    let r = rastercheck::adapters::by_name("gl").expect("registered");
    assert_eq!(r.name(), "gl");
    let r = rastercheck::adapters::by_name("softpipe").expect("registered");
    assert_eq!(r.name(), "softpipe");
}
