//! Line conventions a driver cannot choose (SPEC.md §4.3.1, §5.1), end to
//! end: a rasterizer that declares its line parameter (`projected` or
//! `major`, clamped or not) is judged against the reference computing the
//! values with it, and one that declares no tie rule on rectangle lines'
//! borders has those samples judged off the ties. Each foil is production
//! drawing one thing: declaring what it draws, it passes; declaring
//! something else, it is caught.

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, CandidateRun, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::registry;
use rastercheck::scene::{
    parse_case, FillRule, Limits, LineClamp, LineParameter, LineRule, LineT, Number, Primitive,
    Scene,
};

/// What a foil does to the case before production draws it.
#[derive(Clone, Copy)]
enum Draws {
    /// Every line's values at this parameter (production clamps).
    Parameter(LineParameter),
    /// Rectangle lines under `all-edges`: every border sample covered.
    BorderGreedy,
    /// Rectangle lines 1/64 pixel wider than stated.
    Wider,
}

/// Production drawing `draws`, declaring `parameter` for every line rule
/// and, if `no_border_rule`, no tie rule on rectangle lines' borders.
struct Foil {
    draws: Draws,
    parameter: Option<LineT>,
    no_border_rule: bool,
}

impl Rasterizer for Foil {
    fn name(&self) -> &str {
        "line-convention-foil"
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn is_foil(&self) -> bool {
        true
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut drawn = scene.clone();
        for p in &mut drawn.primitives {
            let Primitive::Line(line) = p else { continue };
            match self.draws {
                Draws::Parameter(parameter) => line.parameter = parameter,
                Draws::Wider => line.width = &line.width + &Number::ratio(1, 64),
                Draws::BorderGreedy => {}
            }
        }
        if let Draws::BorderGreedy = self.draws {
            drawn.rules.fill_rule = FillRule::AllEdges;
        }
        registry::by_name("production")
            .expect("production")
            .rasterize(&drawn, plan)
    }
    fn fixed_line_parameter(&self, _rule: LineRule) -> Option<LineT> {
        self.parameter
    }
    fn rectangle_border_no_tie_rule(&self) -> bool {
        self.no_border_rule
    }
}

fn case(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("cases/lines/{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap();
    parse_case(&text, &path.display().to_string(), &Limits::default()).unwrap()
}

fn judged(scene: &Scene, foil: &Foil) -> CandidateRun {
    let reference = run_reference(scene);
    run_candidate(scene, &reference, foil)
}

fn reasons(run: &CandidateRun) -> Vec<String> {
    match &run.verdict {
        Verdict::Pass => Vec::new(),
        Verdict::Fail(reasons) => reasons.clone(),
        other => panic!("{other:?}"),
    }
}

fn clamped(parameter: LineParameter) -> Option<LineT> {
    Some(LineT {
        parameter,
        clamp: LineClamp::Clamped,
    })
}

/// Two lines state `major` and two `projected`, with depth and three
/// attributes; the parameters differ at most of their pixels.
const COLOURS: &str = "diamond_colour_interpolation";

#[test]
fn a_declared_line_parameter_drawn_is_judged_under_it_and_passes() {
    for parameter in [LineParameter::Major, LineParameter::Projected] {
        let run = judged(
            &case(COLOURS),
            &Foil {
                draws: Draws::Parameter(parameter),
                parameter: clamped(parameter),
                no_border_rule: false,
            },
        );
        assert!(reasons(&run).is_empty(), "{:?}", reasons(&run));
        let own = run.judged.line_parameter.expect("judged under its own");
        assert_eq!(own.single(), clamped(parameter));
        // The lines stating the other parameter are the ones restated,
        // named as the case's.
        let other = match parameter {
            LineParameter::Major => "projected, clamped",
            LineParameter::Projected => "major, clamped",
        };
        assert_eq!(own.stated(), other);
    }
}

#[test]
fn foil_declaring_one_parameter_while_drawing_the_other_is_caught() {
    // Declaring projected while drawing major, and the reverse.
    for (draws, declares) in [
        (LineParameter::Major, LineParameter::Projected),
        (LineParameter::Projected, LineParameter::Major),
    ] {
        let run = judged(
            &case(COLOURS),
            &Foil {
                draws: Draws::Parameter(draws),
                parameter: clamped(declares),
                no_border_rule: false,
            },
        );
        let reasons = reasons(&run);
        assert!(
            reasons.iter().any(|r| r.contains("attribute")),
            "drawing {draws:?}, declaring {declares:?}: {reasons:?}"
        );
    }
}

#[test]
fn foil_declaring_no_clamp_while_clamping_is_caught() {
    // Line 1 starts a quarter pixel right of the centre of (2, 3), which
    // it lights: there t is −0.25/26.75, extrapolated when unclamped.
    let run = judged(
        &case(COLOURS),
        &Foil {
            draws: Draws::Parameter(LineParameter::Major),
            parameter: Some(LineT {
                parameter: LineParameter::Major,
                clamp: LineClamp::Unclamped,
            }),
            no_border_rule: false,
        },
    );
    let reasons = reasons(&run);
    assert!(!reasons.is_empty(), "the clamped pixel is caught");
    assert_eq!(
        run.judged.line_parameter.map(|p| p.name()),
        Some("major-unclamped")
    );
}

#[test]
fn a_case_of_lines_without_values_restates_nothing() {
    // The worked rectangle carries no depth and no attributes.
    let run = judged(
        &case("rectangle_worked_example"),
        &Foil {
            draws: Draws::Parameter(LineParameter::Projected),
            parameter: clamped(LineParameter::Projected),
            no_border_rule: false,
        },
    );
    assert!(run.judged.line_parameter.is_none());
    assert!(reasons(&run).is_empty());
}

#[test]
fn border_samples_given_to_the_line_pass_only_where_no_tie_rule_is_declared() {
    let scene = case("rectangle_worked_example");
    let undeclared = judged(
        &scene,
        &Foil {
            draws: Draws::BorderGreedy,
            parameter: None,
            no_border_rule: false,
        },
    );
    assert!(
        !reasons(&undeclared).is_empty(),
        "under top-left its right edges' samples are extra"
    );
    let declared = judged(
        &scene,
        &Foil {
            draws: Draws::BorderGreedy,
            parameter: None,
            no_border_rule: true,
        },
    );
    assert!(reasons(&declared).is_empty(), "{:?}", reasons(&declared));
    assert!(declared.judged.rectangle_border_ties);
    let ties = declared
        .metrics
        .and_then(|m| m.ties)
        .expect("its border samples counted apart");
    assert!(ties.tie_samples > 0 && ties.other_side > 0, "{ties:?}");
}

#[test]
fn foil_a_wider_rectangle_covering_samples_just_off_the_border_is_caught() {
    // A width-2 line at y = 2.5 + 1/256: its long sides lie at
    // y = 1.5 + 1/256 and 3.5 + 1/256, so no sample is on them, and the
    // centres of row 1 lie 1/256 outside; 1/64 wider covers row 1, whose
    // samples are off the border (not ties).
    let text = r#"{"name": "t", "canvas": {"width": 10, "height": 6},
        "rules": {"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none"},
        "primitives": [{"line": [[1, "641/256"], [9, "641/256"]], "rule": "rectangle", "width": 2}]}"#;
    let scene = parse_case(text, "t.json", &Limits::default()).unwrap();
    let run = judged(
        &scene,
        &Foil {
            draws: Draws::Wider,
            parameter: None,
            no_border_rule: true,
        },
    );
    assert!(run.judged.rectangle_border_ties);
    let reasons = reasons(&run);
    assert!(reasons.iter().any(|r| r.contains("extra")), "{reasons:?}");
}
