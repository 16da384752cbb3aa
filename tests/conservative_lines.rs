//! Conservative points and lines (issue 38, SPEC.md §19.8): the bundled
//! line and point cases pass on production; `foil-conservative-open-ends`
//! (each line's end caps open) is caught as a required pixel missing; a
//! case whose points and lines are not drawn conservatively
//! (`points_and_lines: false`), and one with a `midpoint` line, are
//! `unsupported` with the reason; a candidate declaring `points_and_lines:
//! false` is refused unsent, and one declaring `degenerate_lines` is
//! judged under its own value and reported so; the exact Python example
//! draws points and lines, and its `--open` variant is caught on them.

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::plan::Plan;
use rastercheck::production::foils::ConservativeOpenEnds;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{parse_case, ConservativeSupport, Limits, Scene};

fn case_file(name: &str) -> Scene {
    let path = format!(
        "{}/cases/conservative/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    parse_case(&text, &path, &Limits::default()).unwrap()
}

fn scene(primitive: &str, conservative: &str) -> Scene {
    let json = format!(
        r#"{{ "name": "t", "canvas": {{ "width": 8, "height": 6 }},
        "rules": {{ "subpixel_bits": 8 }},
        "effects": {{ "conservative": {{ {conservative} }} }},
        "primitives": [ {primitive} ] }}"#
    );
    parse_case(&json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
}

fn verdict(scene: &Scene, candidate: &dyn Rasterizer) -> Verdict {
    let reference = run_reference(scene);
    run_candidate(scene, &reference, candidate).verdict
}

const LINE_CASES: [&str; 12] = [
    "line_over_diagonal",
    "line_over_band",
    "line_over_caps_exact",
    "line_parallelogram_over",
    "point_over_flag",
    "point_under",
    "line_under_wide",
    "line_degenerate_drawn",
    "line_degenerate_culled",
    "line_degenerate_corner_band",
    "mixed_triangle_line_point",
    "line_steep_parallelogram_under",
];

#[test]
fn production_passes_every_line_and_point_case() {
    for name in LINE_CASES {
        let v = verdict(&case_file(name), &Production);
        assert!(matches!(v, Verdict::Pass), "{name}: {v:?}");
    }
}

#[test]
fn open_end_caps_are_a_required_pixel_missing() {
    let scene = case_file("line_over_diagonal");
    match verdict(&scene, &ConservativeOpenEnds) {
        Verdict::Fail(reasons) => {
            let why = reasons.join("; ");
            assert!(why.contains("required pixel(s) not drawn"), "{why}");
        }
        other => panic!("foil-conservative-open-ends was not caught: {other:?}"),
    }
    // Its points and triangles are production's: a point case passes.
    let point = case_file("point_over_flag");
    assert!(matches!(
        verdict(&point, &ConservativeOpenEnds),
        Verdict::Pass
    ));
}

#[test]
fn lines_not_drawn_conservatively_and_midpoint_lines_are_unsupported() {
    let line = r#"{ "line": [[1, 1], [5, 3]], "rule": "rectangle", "width": 1 }"#;
    let off = scene(line, r#""mode": "overestimate""#);
    match verdict(&off, &Production) {
        Verdict::Unsupported(why) => assert!(why.contains("points_and_lines false"), "{why}"),
        other => panic!("{other:?}"),
    }
    let midpoint = scene(
        r#"{ "line": [[1, 1], [5, 3]], "rule": "midpoint" }"#,
        r#""mode": "overestimate", "points_and_lines": true"#,
    );
    match verdict(&midpoint, &Production) {
        Verdict::Unsupported(why) => assert!(why.contains("no conservative shape"), "{why}"),
        other => panic!("{other:?}"),
    }
    let point = scene(
        r#"{ "point": [2, 2], "size": 2 }"#,
        r#""mode": "overestimate""#,
    );
    assert!(matches!(
        verdict(&point, &Production),
        Verdict::Unsupported(_)
    ));
}

/// Production under fixed properties of its own (SPEC.md §19.6).
struct Declaring(ConservativeSupport);

impl Rasterizer for Declaring {
    fn name(&self) -> &str {
        "declaring"
    }

    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }

    fn conservative(&self) -> Option<ConservativeSupport> {
        Some(self.0.clone())
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut own = scene.clone();
        if let Some(c) = &mut own.effects.conservative {
            *c = self.0.restate(c);
        }
        Production.rasterize(&own, plan)
    }
}

#[test]
fn declared_points_and_lines_and_degenerate_lines_are_what_a_candidate_is_judged_under() {
    let support = Production.conservative().unwrap();
    let no_lines = Declaring(ConservativeSupport {
        points_and_lines: Some(false),
        ..support.clone()
    });
    match verdict(&case_file("line_over_diagonal"), &no_lines) {
        Verdict::Unsupported(why) => {
            assert!(
                why.contains("this rasterizer declares points_and_lines false"),
                "{why}"
            )
        }
        other => panic!("{other:?}"),
    }
    // The case culls its degenerate line; a candidate that draws them is
    // judged under its own property, and passes drawing the point.
    let draws = Declaring(ConservativeSupport {
        degenerate_lines: Some(true),
        ..support
    });
    let scene = case_file("line_degenerate_culled");
    let reference = run_reference(&scene);
    let run = run_candidate(&scene, &reference, &draws);
    assert!(matches!(run.verdict, Verdict::Pass), "{:?}", run.verdict);
    let frame = run.frame.unwrap();
    assert_eq!(frame.coverage.iter().filter(|&&c| c > 0).count(), 1);
}

#[test]
fn the_python_example_draws_points_and_lines_and_its_open_variant_is_caught() {
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/conservative_rasterizer.py"
    );
    let program = |flags: &str| {
        let spec = format!("external-persistent:python3 {script} {flags}");
        rastercheck::adapters::external::preflight(&spec).unwrap();
        rastercheck::registry::by_name(&spec).unwrap()
    };
    let exact = program("");
    for name in LINE_CASES {
        let v = verdict(&case_file(name), exact.as_ref());
        assert!(matches!(v, Verdict::Pass), "{name}: {v:?}");
    }
    let open = program("--open");
    match verdict(&case_file("line_over_diagonal"), open.as_ref()) {
        Verdict::Fail(reasons) => {
            assert!(reasons.join("; ").contains("required pixel(s) not drawn"))
        }
        other => panic!("--open was not caught: {other:?}"),
    }
}

/// Production's sets are the reference's exactly on the fuzz family's
/// point and line scenes: overestimation draws every required and allowed
/// pixel and no other, underestimation every required one, and the flag
/// is true exactly where it must be. (The fuzzer's verdict only checks
/// that production keeps within the classes; this checks the band too.)
#[test]
fn production_draws_exactly_the_reference_classes_on_fuzzed_points_and_lines() {
    use rastercheck::explore::fuzz::{generate, Family};
    use rastercheck::reference::conservative::{classify, PixelClass};
    use rastercheck::scene::{ConservativeMode, Primitive};
    let mut lines = 0;
    for index in 0..3000 {
        let (_, scene) = generate(38, index, Some(Family::Conservative));
        if !scene
            .primitives
            .iter()
            .any(|p| matches!(p, Primitive::Line(_) | Primitive::Point(_)))
        {
            continue;
        }
        lines += 1;
        let case = scene.effects.conservative.clone().unwrap();
        let classes = classify(&scene).unwrap();
        let frame = Production
            .rasterize(&scene, &Plan::for_scene(&scene))
            .unwrap();
        for (i, class) in classes.drawn.iter().enumerate() {
            let want = match case.mode {
                ConservativeMode::Overestimate => *class != PixelClass::Forbidden,
                ConservativeMode::Underestimate => *class == PixelClass::Required,
            };
            assert_eq!(frame.coverage[i] > 0, want, "{} pixel {i}", scene.name);
        }
        if let (Some(flags), Some(given)) = (&classes.fully_covered, &frame.fully_covered) {
            for (i, f) in flags.iter().enumerate() {
                if frame.coverage[i] > 0 && scene.primitives.len() == 1 {
                    assert_eq!(
                        given[i],
                        *f == PixelClass::Required,
                        "{} flag {i}",
                        scene.name
                    );
                }
            }
        }
    }
    assert!(lines > 500, "{lines} point and line scenes");
}
