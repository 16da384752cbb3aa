//! `rectangle` lines, drawn into llvmpipe's multisampled target (where it
//! draws GL's multisample lines, rectangles, GL 4.6 §14.5.4) with the
//! scene shifted so that one driver sample lies on each pixel centre, that
//! sample read.

use super::GL;
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{LineRule, Primitive, Scene};

use super::common::adapters::bundled_ids;
use super::common::{case, inline, report};
use super::{available, run};

/// How far (pixels, f64: for the record, not a verdict) a sample centre
/// lies from the nearest border of the nearest rectangle line of `scene`.
fn distance_to_a_border(scene: &Scene, (px, py): (f64, f64)) -> f64 {
    let mut best = f64::INFINITY;
    for p in &scene.primitives {
        let Primitive::Line(l) = p else { continue };
        if l.rule != LineRule::Rectangle {
            continue;
        }
        let [a, b] = &l.vertices;
        let (x0, y0) = (a.x.to_f64_lossy(), a.y.to_f64_lossy());
        let (dx, dy) = (b.x.to_f64_lossy() - x0, b.y.to_f64_lossy() - y0);
        let len = dx.hypot(dy);
        let (qx, qy) = (px - x0, py - y0);
        let along = (qx * dx + qy * dy) / len;
        let across = (qx * dy - qy * dx).abs() / len;
        let half = l.width.to_f64_lossy() / 2.0;
        let inside_ends = (-1e-9..=len + 1e-9).contains(&along);
        let near_side = (across - half).abs();
        let near_end = along.abs().min((along - len).abs());
        let d = match (inside_ends, across <= half + 1e-9) {
            (true, _) => near_side.min(if across <= half {
                near_end
            } else {
                f64::INFINITY
            }),
            (false, true) => near_end,
            (false, false) => near_side.max(near_end),
        };
        best = best.min(d);
    }
    best
}

/// The samples (pixel x, y) whose coverage differs.
fn differing(reference: &Frame, candidate: &Frame) -> Vec<(u32, u32)> {
    (0..reference.height)
        .flat_map(|y| (0..reference.width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let k = reference.index(x, y);
            reference.coverage[k] != candidate.coverage[k]
        })
        .collect()
}

/// Every bundled `rectangle` case is judged (passed or failed, never
/// unsupported), its verdict printed with each differing sample's
/// distance to the nearest border; every departure lies within 1/64 pixel
/// of a border (llvmpipe snaps the rectangle's irrational corners to its
/// 1/256 grid and computes them in float: samples on or next to a border
/// go either way), none deep inside or far outside a rectangle.
#[test]
fn every_bundled_rectangle_case_is_judged() {
    let Some(_record) = available() else {
        return;
    };
    let ids = bundled_ids("lines", |stem| stem.starts_with("rectangle_"));
    assert!(ids.len() >= 11, "{ids:?}");
    let mut failures = Vec::new();
    for id in &ids {
        let scene = case(id);
        let (reference, r) = run(&scene);
        eprintln!("{}", report(id, &reference, &r));
        match &r.verdict {
            Verdict::Pass => {}
            Verdict::Fail(_) => {
                let frame = r.frame.as_ref().expect("a frame");
                for (x, y) in differing(&reference.frame, frame) {
                    let d = distance_to_a_border(&scene, (f64::from(x) + 0.5, f64::from(y) + 0.5));
                    let k = reference.frame.index(x, y);
                    eprintln!(
                        "  ({x}, {y}): reference {} gl {}, {d:.6} px from a border",
                        reference.frame.coverage[k], frame.coverage[k]
                    );
                    if d > 1.0 / 64.0 {
                        failures.push(format!("{id}: ({x}, {y}) is {d} px from a border"));
                    }
                }
            }
            other => failures.push(format!("{id}: {other:?}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Rectangles with no sample on or near a border match the reference:
/// the bundled wide ones, and thin ones at several slopes with their ends
/// and sides between samples.
#[test]
fn rectangles_clear_of_the_samples_pass() {
    let Some(_record) = available() else {
        return;
    };
    for id in ["lines/rectangle_width_5", "lines/rectangle_width_10"] {
        let (reference, r) = run(&case(id));
        assert_eq!(r.verdict, Verdict::Pass, "{}", report(id, &reference, &r));
    }
    let scene = inline(
        r#"{"name": "rects", "canvas": {"width": 32, "height": 32},
            "primitives": [
              {"line": [[1.25, 1.125], [29.75, 9.125]], "rule": "rectangle", "width": 1},
              {"line": [[30.25, 2.375], [3.125, 28.75]], "rule": "rectangle", "width": 3},
              {"line": [[5.25, 30.125], [9.875, 12.3125]], "rule": "rectangle", "width": 2.25},
              {"line": [[12.125, 20.25], [28.25, 26.875]], "rule": "rectangle", "width": 1.5}]}"#,
    );
    let (reference, r) = run(&scene);
    eprintln!("{}", report("rects", &reference, &r));
    let frame = r.frame.as_ref().expect("a frame");
    for (x, y) in differing(&reference.frame, frame) {
        let d = distance_to_a_border(&scene, (f64::from(x) + 0.5, f64::from(y) + 0.5));
        eprintln!("  ({x}, {y}): {d:.6} px from a border");
    }
    assert_eq!(
        r.verdict,
        Verdict::Pass,
        "{}",
        report("rects", &reference, &r)
    );
    assert!(reference.frame.covered_samples() > 100);
}

/// What the multisampled target cannot draw exactly is refused with the
/// reason: rectangle lines beside diamond-exit ones (llvmpipe draws every
/// line of a multisampled target as a rectangle), and vertices finer than
/// the driver's grid (the shift onto a driver sample would not commute
/// with its rounding). (Moving rectangles are refused too, but no case can
/// ask for one: the reader refuses them.)
#[test]
fn refuses_rectangles_it_cannot_draw_exactly() {
    let Some(_record) = available() else {
        return;
    };
    for (primitives, bits, why) in [
        (
            r#"{"line": [[0.5, 0.5], [7.5, 3.5]], "rule": "rectangle", "width": 2},
               {"line": [[0.5, 6.5], [7.5, 1.5]], "rule": "diamond-exit"}"#,
            8,
            "diamond-exit",
        ),
        (
            r#"{"line": [[0.5, 0.5], [7.5, 3.5]], "rule": "rectangle", "width": 2}"#,
            10,
            "ties to even",
        ),
    ] {
        let scene = inline(&format!(
            r#"{{"name": "l", "canvas": {{"width": 8, "height": 8}},
                "rules": {{"subpixel_bits": {bits}}}, "primitives": [{primitives}]}}"#
        ));
        match GL.rasterize(&scene, &Plan::for_scene(&scene)) {
            Err(e) => assert!(e.to_string().contains(why), "{why}: {e}"),
            Ok(_) => panic!("{why}: drawn"),
        }
    }
}
