//! The adaptive classification's corner tests: strict, as it must be, and
//! the non-strict one caught; refine's first samples.

use super::sampling::Sampling;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::rasterize_with;
use crate::scene::FillRule;
use crate::scene::Scene;

/// A scene of one triangle with integer vertices under 16× standard
/// sampling, whose sample 12 lies on its pixel's left border.
fn scene(rule: FillRule, xs: [i64; 3], ys: [i64; 3]) -> Scene {
    let [a, b, c] = [0, 1, 2].map(|i| format!("[{}, {}]", xs[i], ys[i]));
    let text = format!(
        r#"{{"name": "tie", "canvas": {{"width": 10, "height": 8}},
            "rules": {{"fill_rule": "{}"}},
            "primitives": [{{"triangle": [{a}, {b}, {c}]}}],
            "effects": {{"antialias": {{"samples": 16, "pattern": "standard"}}}}}}"#,
        rule.name()
    );
    crate::scene::parse_case(&text, "tie.json", &crate::scene::Limits::default()).unwrap()
}

fn frame(scene: &Scene, sampling: Sampling) -> Frame {
    rasterize_with(scene, &Plan::for_scene(scene), sampling).unwrap()
}

#[test]
fn non_strict_corners_are_caught() {
    // The left edge x = 2 of (2,0) (8,0) (2,6) runs along the left
    // border of pixel column 2, through sample 12 at (0, 8/16) in every
    // row. Bottom-right does not own left edges, so those samples are
    // empty; a classification that takes corners on the edge as inside
    // fills the pixel whole.
    let scene = scene(FillRule::BottomRight, [2, 8, 2], [0, 0, 6]);
    let full = frame(&scene, Sampling::Full);
    let on_edge = full.index(2, 1) + 12;
    assert_eq!(full.coverage[on_edge], 0);
    assert_eq!(frame(&scene, Sampling::Adaptive), full);
    let wrong = frame(&scene, Sampling::NonStrictCorners);
    assert_eq!(wrong.coverage[on_edge], 1);
    assert_ne!(wrong, full);
}

#[test]
fn corners_on_an_owned_edge_are_not_outside() {
    // The right edge x = 2 of (0,0) (2,0) (2,6) under bottom-right: the
    // samples at (2, y + 1/2) are covered. Pixel column 2 is wholly
    // outside but for its left border; a non-strict "outside" empties it.
    let scene = scene(FillRule::BottomRight, [0, 2, 2], [0, 0, 6]);
    let full = frame(&scene, Sampling::Full);
    let on_edge = full.index(2, 1) + 12;
    assert_eq!(full.coverage[on_edge], 1);
    assert_eq!(frame(&scene, Sampling::Adaptive), full);
    assert_eq!(
        frame(&scene, Sampling::NonStrictCorners).coverage[on_edge],
        0
    );
}

#[test]
fn refine_tests_a_quarter_spread_through_the_pattern() {
    // Whole pixels far inside or outside come out the same as full
    // sampling; refine differs only where its first samples agree
    // wrongly.
    let scene = scene(FillRule::TopLeft, [-4, 30, -4], [-4, -4, 30]);
    assert_eq!(
        frame(&scene, Sampling::Refine).coverage,
        frame(&scene, Sampling::Full).coverage
    );
}
