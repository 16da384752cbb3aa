//! The three conservative foils (issue 38), each caught by a named check
//! of the conservative verdict (SPEC.md §19.5) on a scene built to show
//! its one fault, with the reason in the failure text; and production,
//! on the same scenes, passing.
//!
//! - `foil-conservative-overgrow` grows ⅛ px past the uncertainty it
//!   declares: the pixels 1/16 px from the triangle (column 0, row 0)
//!   are forbidden at u = 0, and it draws them.
//! - `foil-conservative-centre-box` tests only the pixels whose centres
//!   lie in the triangle's box: the vertices at x = 2.75 and x = 6 poke
//!   into pixel columns 2 and 5 to 6 beyond their centres, required
//!   pixels it never draws.
//! - `foil-conservative-centre-flag` flags a pixel fully covered when its
//!   centre is covered: pixel (3, 2)'s centre lies on the hypotenuse of
//!   x + y ≤ 6, its square does not lie inside.

use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::production::foils::{
    ConservativeCentreBox, ConservativeCentreFlag, ConservativeOvergrow,
};
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{parse_case, Limits, Scene};

fn case(vertices: &str, conservative: &str) -> Scene {
    let json = format!(
        r#"{{ "name": "t", "canvas": {{ "width": 8, "height": 8 }},
        "rules": {{ "subpixel_bits": 8 }},
        "effects": {{ "conservative": {{ {conservative} }} }},
        "primitives": [ {{ "triangle": {vertices} }} ] }}"#
    );
    parse_case(&json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
}

fn verdict(scene: &Scene, candidate: &dyn Rasterizer) -> Verdict {
    let reference = run_reference(scene);
    run_candidate(scene, &reference, candidate).verdict
}

/// The reasons `candidate` fails `scene` for; panics when it passes.
fn reasons(scene: &Scene, candidate: &dyn Rasterizer) -> String {
    match verdict(scene, candidate) {
        Verdict::Fail(reasons) => reasons.join("; "),
        other => panic!("{} was not caught: {other:?}", candidate.name()),
    }
}

fn passes(scene: &Scene, candidate: &dyn Rasterizer) {
    let v = verdict(scene, candidate);
    assert!(matches!(v, Verdict::Pass), "{}: {v:?}", candidate.name());
}

#[test]
fn overgrowth_is_a_forbidden_pixel_drawn() {
    // x ≥ 17/16, y ≥ 17/16, x + y ≤ 6: pixel (0, 2)'s square ends 1/16 px
    // left of it.
    let scene = case(
        r#"[ { "position": ["17/16", "17/16"] }, { "position": ["79/16", "17/16"] }, { "position": ["17/16", "79/16"] } ]"#,
        r#""mode": "overestimate""#,
    );
    passes(&scene, &Production);
    let why = reasons(&scene, &ConservativeOvergrow);
    assert!(why.contains(FORBIDDEN), "{why}");
}

#[test]
fn a_touched_corner_pixel_missed_is_a_required_pixel_missing() {
    let scene = case(
        r#"[ { "position": [2.75, 3] }, { "position": [6, 1] }, { "position": [6, 5] } ]"#,
        r#""mode": "overestimate", "uncertainty": "1/256""#,
    );
    passes(&scene, &Production);
    let why = reasons(&scene, &ConservativeCentreBox);
    assert!(why.contains(MISSING), "{why}");
}

#[test]
fn a_partly_covered_pixel_flagged_fully_covered_is_a_wrong_flag() {
    let scene = case(
        r#"[ { "position": [2, 2] }, { "position": [4, 2] }, { "position": [2, 4] } ]"#,
        r#""mode": "overestimate", "fully_covered": true"#,
    );
    passes(&scene, &Production);
    let why = reasons(&scene, &ConservativeCentreFlag);
    assert!(why.contains(FLAG), "{why}");
}

#[test]
fn the_foils_draw_what_they_declare_and_refuse_the_rest() {
    let under = case(
        r#"[ { "position": [2, 2] }, { "position": [4, 2] }, { "position": [2, 4] } ]"#,
        r#""mode": "underestimate""#,
    );
    for foil in [
        &ConservativeOvergrow as &dyn Rasterizer,
        &ConservativeCentreBox,
    ] {
        assert!(
            matches!(verdict(&under, foil), Verdict::Unsupported(_)),
            "{}",
            foil.name()
        );
    }
    // The flag foil draws production's pixels: underestimation's are
    // wholly covered, so its flag is right there.
    passes(&under, &ConservativeCentreFlag);
}

// The verdict's words for its three checks (SPEC.md §19.5), each with
// its reason.
const FORBIDDEN: &str = "forbidden pixel(s) drawn, first";
const MISSING: &str = "required pixel(s) not drawn";
const FLAG: &str = "fully-covered flag wrong";
