//! Coverage, watertightness, interpolation, the empty result, crashes,
//! golden files and the line metric: each check failing a wrong
//! rasterizer, on inline and bundled cases.

use crate::{reasons, run, scene};
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{discover, judge, load, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::registry;
use rastercheck::scene::{Limits, Scene};

/// An 8×8 square split along its diagonal: the samples (i+½, i+½) lie
/// exactly on the shared edge, so the tie rule alone decides their owner.
pub const DIAGONAL_PAIR: &str = r#"{
  "name": "diagonal_pair", "canvas": {"width": 8, "height": 8},
  "primitives": [
    {"triangle": [[0, 0], [8, 0], [8, 8]]},
    {"triangle": [[0, 0], [8, 8], [0, 8]]}
  ],
  "expect": {"watertight": true, "samples_covered": 64}
}"#;

#[test]
fn production_passes_the_tie_cases_used_below() {
    for json in [DIAGONAL_PAIR, FAN, PERSPECTIVE] {
        let s = scene(json);
        let r = run(&s, &Production);
        assert_eq!(
            r.verdict,
            Verdict::Pass,
            "{}: {}",
            s.name,
            judge::describe(&r)
        );
    }
}

#[test]
fn coverage_check_catches_a_flipped_tie_rule() {
    let s = scene(DIAGONAL_PAIR);
    let r = run(&s, &Mutant(Mutation::FlippedTies));
    let m = r.metrics.as_ref().unwrap();
    // The 8 diagonal samples change hands; none goes missing or doubles.
    assert_eq!(
        (m.coverage.wrong_owner, m.coverage.missing, m.coverage.extra),
        (8, 0, 0)
    );
    assert!(
        reasons(&r)[0].contains("8 samples differ"),
        "{:?}",
        reasons(&r)
    );
}

#[test]
fn coverage_check_catches_a_one_subpixel_vertex_offset() {
    // A vertical left edge through the sample column x = 2.5: moving its top
    // vertex one subpixel right tilts the edge off the samples below it.
    let s = scene(
        r#"{"name": "column", "canvas": {"width": 8, "height": 8},
            "primitives": [{"triangle": [[2.5, 0], [8, 8], [2.5, 8]]}]}"#,
    );
    assert_eq!(run(&s, &Production).verdict, Verdict::Pass);
    let r = run(&s, &Mutant(Mutation::VertexNudge));
    assert!(r.metrics.as_ref().unwrap().coverage.missing > 0);
    assert!(reasons(&r)[0].starts_with("coverage:"), "{:?}", reasons(&r));
}

/// 16 triangles around the sample centre (4.5, 4.5); each outer vertex is
/// shared exactly by two neighbours.
const FAN: &str = r#"{
  "name": "fan", "canvas": {"width": 9, "height": 9},
  "primitives": [
    {"triangle": [[4.5, 4.5], [0.5, 0.5], [2.5, 0.5]]}, {"triangle": [[4.5, 4.5], [2.5, 0.5], [4.5, 0.5]]},
    {"triangle": [[4.5, 4.5], [4.5, 0.5], [6.5, 0.5]]}, {"triangle": [[4.5, 4.5], [6.5, 0.5], [8.5, 0.5]]},
    {"triangle": [[4.5, 4.5], [8.5, 0.5], [8.5, 2.5]]}, {"triangle": [[4.5, 4.5], [8.5, 2.5], [8.5, 4.5]]},
    {"triangle": [[4.5, 4.5], [8.5, 4.5], [8.5, 6.5]]}, {"triangle": [[4.5, 4.5], [8.5, 6.5], [8.5, 8.5]]},
    {"triangle": [[4.5, 4.5], [8.5, 8.5], [6.5, 8.5]]}, {"triangle": [[4.5, 4.5], [6.5, 8.5], [4.5, 8.5]]},
    {"triangle": [[4.5, 4.5], [4.5, 8.5], [2.5, 8.5]]}, {"triangle": [[4.5, 4.5], [2.5, 8.5], [0.5, 8.5]]},
    {"triangle": [[4.5, 4.5], [0.5, 8.5], [0.5, 6.5]]}, {"triangle": [[4.5, 4.5], [0.5, 6.5], [0.5, 4.5]]},
    {"triangle": [[4.5, 4.5], [0.5, 4.5], [0.5, 2.5]]}, {"triangle": [[4.5, 4.5], [0.5, 2.5], [0.5, 0.5]]}
  ],
  "expect": {"watertight": true}
}"#;

#[test]
fn watertightness_catches_closed_edges_as_overdraw() {
    let s = scene(FAN);
    let r = run(&s, &Mutant(Mutation::ClosedEdges));
    let w = r.metrics.as_ref().unwrap().watertight.clone().unwrap();
    assert_eq!(w.holes, 0);
    // Every interior sample on a spoke, and the centre, is drawn more than once.
    assert!(w.overdraw >= 9, "{w:?}");
    assert!(
        reasons(&r).iter().any(|m| m.starts_with("watertight:")),
        "{:?}",
        reasons(&r)
    );
}

#[test]
fn watertightness_catches_cracks_as_holes() {
    let s = scene(FAN);
    let r = run(&s, &Mutant(Mutation::Shrunk));
    let w = r.metrics.as_ref().unwrap().watertight.clone().unwrap();
    assert!(w.holes > 0, "{w:?}");
    assert!(
        reasons(&r).iter().any(|m| m.contains("holes")),
        "{:?}",
        reasons(&r)
    );
}

const PERSPECTIVE: &str = r#"{
  "name": "perspective", "canvas": {"width": 16, "height": 16},
  "primitives": [{"triangle": [
    {"position": [0, 0], "w": 0.1, "attributes": [0, 1]},
    {"position": [16, 0], "w": 4, "attributes": [1, 0]},
    {"position": [0, 16], "w": 1, "attributes": [0, 0]}
  ]}]
}"#;

#[test]
fn interpolation_bound_catches_screen_space_interpolation() {
    let s = scene(PERSPECTIVE);
    let r = run(&s, &Mutant(Mutation::NoPerspective));
    let failures = reasons(&r);
    assert!(
        failures
            .iter()
            .any(|m| m.starts_with("attribute 0: max error")),
        "{failures:?}"
    );
    // Coverage is untouched by this bug.
    assert_eq!(r.metrics.as_ref().unwrap().coverage.mismatched(), 0);
}

/// Draws nothing at all.
struct Blank;

impl Rasterizer for Blank {
    fn name(&self) -> &str {
        "blank"
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Ok(Frame::new(
            scene.canvas.width,
            scene.canvas.height,
            plan.depth,
            plan.attributes,
        ))
    }
}

#[test]
fn an_empty_result_never_passes() {
    let mut s = scene(DIAGONAL_PAIR);
    // Even when the case tolerates every sample differing.
    s.expect.max_mismatched_samples = 64;
    let r = run(&s, &Blank);
    assert!(
        reasons(&r).iter().any(|m| m.contains("drew nothing")),
        "{:?}",
        reasons(&r)
    );
}

#[test]
fn a_case_pins_the_oracle_with_samples_covered() {
    let mut s = scene(DIAGONAL_PAIR);
    s.expect.samples_covered = Some(63);
    let r = run(&s, &Production);
    assert!(
        reasons(&r)
            .iter()
            .any(|m| m.starts_with("reference: covers 64")),
        "{:?}",
        reasons(&r)
    );
}

/// Panics, as a buggy adapter might.
struct Panicking;

impl Rasterizer for Panicking {
    fn name(&self) -> &str {
        "panicking"
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, _: &Scene, _: &Plan) -> Result<Frame, RasterError> {
        panic!("index out of bounds")
    }
}

#[test]
fn a_crashing_rasterizer_is_an_error_not_a_crash_of_the_suite() {
    let s = scene(DIAGONAL_PAIR);
    let r = run(&s, &Panicking);
    assert!(
        matches!(&r.verdict, Verdict::Error(why) if why.contains("index out of bounds")),
        "{:?}",
        r.verdict
    );
}

#[test]
fn golden_check_catches_a_changed_oracle() {
    let s = scene(PERSPECTIVE);
    let reference = oracle::run_reference(&s);
    let dir = std::env::temp_dir().join(format!("rastercheck-golden-{}", std::process::id()));
    let path = dir.join("case.exr");
    rastercheck::harness::golden::write(&reference.frame, &path).unwrap();
    assert_eq!(
        rastercheck::harness::golden::check(&reference.frame, &path),
        Ok(())
    );

    // One attribute value one f32 ulp off, as a changed rounding would give.
    let mut changed = reference.frame.clone();
    let i = changed.last.iter().position(|&p| p != 0).unwrap();
    let v = changed.attributes[0][i] as f32;
    changed.attributes[0][i] = f64::from(f32::from_bits(v.to_bits() + 1));
    let err = rastercheck::harness::golden::check(&changed, &path).unwrap_err();
    assert!(
        err.contains("channel attribute.0: 1 sample differs"),
        "{err}"
    );

    // One sample handed to no primitive.
    let mut changed = reference.frame.clone();
    changed.coverage[i] = 0;
    let err = rastercheck::harness::golden::check(&changed, &path).unwrap_err();
    assert!(err.contains("channel coverage"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

/// Runs a rasterizer over every bundled triangle case; returns each case id
/// with its failure reasons (empty when it passed).
fn sweep(candidate: &dyn Rasterizer) -> Vec<(String, Vec<String>)> {
    let cases = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/triangles");
    let found = discover::discover(&[cases]);
    assert!(
        found.cases.len() >= 40,
        "expected the bundled triangle cases"
    );
    found
        .cases
        .iter()
        .map(|file| {
            let s = load::load(file, &Limits::default()).unwrap();
            let r = run(&s, candidate);
            let reasons = match r.verdict {
                Verdict::Pass => Vec::new(),
                Verdict::Fail(reasons) => reasons,
                other => panic!("{}: {other:?}", file.id),
            };
            (file.id.clone(), reasons)
        })
        .collect()
}

fn is_tie_case(id: &str) -> bool {
    let name = id.trim_start_matches("triangles/");
    [
        "fan_",
        "pinwheel_",
        "snap_tie_",
        "quad_grid_rot",
        "shared_edge_",
    ]
    .iter()
    .any(|p| name.starts_with(p))
        && name != "shared_edge_fractions_offgrid"
        || ["top_left", "bottom_right", "top_right", "bottom_left"]
            .iter()
            .any(|r| name == format!("fill_rule_{r}"))
}

#[test]
fn the_bundled_tie_cases_catch_a_flipped_tie_rule() {
    let results = sweep(&Mutant(Mutation::FlippedTies));
    let tie_cases: Vec<_> = results.iter().filter(|(id, _)| is_tie_case(id)).collect();
    assert!(tie_cases.len() >= 30, "{} tie cases", tie_cases.len());
    for (id, reasons) in tie_cases {
        assert!(
            reasons.iter().any(|r| r.starts_with("coverage:")),
            "{id}: the flipped tie rule went unnoticed"
        );
    }
}

#[test]
fn the_bundled_meshes_catch_closed_edges_as_overdraw() {
    for (id, reasons) in sweep(&Mutant(Mutation::ClosedEdges)) {
        let name = id.trim_start_matches("triangles/");
        if name.starts_with("fan_")
            || name.starts_with("quad_grid_rot")
            || (name.starts_with("fill_rule_") && name != "fill_rule_all_edges")
        {
            assert!(
                reasons
                    .iter()
                    .any(|r| r.starts_with("watertight:") && !r.contains(" 0 overdrawn")),
                "{id}: {reasons:?}"
            );
        }
    }
}

#[test]
fn the_bundled_perspective_cases_catch_screen_space_interpolation() {
    let caught: Vec<_> = sweep(&Mutant(Mutation::NoPerspective))
        .into_iter()
        .filter(|(id, _)| {
            id.contains("interp_perspective_w_range")
                || id.contains("interp_mixed_modes")
                || id.contains("interp_perspective_fan")
        })
        .collect();
    assert_eq!(caught.len(), 3);
    for (id, reasons) in caught {
        assert!(
            reasons.iter().any(|r| r.contains("max error")),
            "{id}: {reasons:?}"
        );
    }
}

fn bundled(id: &str) -> Scene {
    let path =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("cases/{id}.json"));
    load::load(&discover::case_file(&path), &Limits::default()).unwrap()
}

fn departures(id: &str, name: &str) -> u64 {
    let s = bundled(id);
    let foil = registry::by_name(name).unwrap();
    assert!(foil.is_foil());
    let r = run(&s, foil.as_ref());
    assert_eq!(run(&s, &Production).verdict, Verdict::Pass, "{id}");
    r.metrics.unwrap().coverage.mismatched()
}

#[test]
fn the_suite_catches_the_float_dda_on_long_and_tie_lines() {
    // f32 drifts over 2048 columns; both round exact ties down the screen
    // where the midpoint rule goes up.
    assert!(departures("lines/midpoint_long_shallow_2048", "dda-f32") > 0);
    assert!(departures("lines/midpoint_long_steep_2048", "dda-f32") > 0);
    for foil in ["dda-f32", "dda-f64"] {
        assert!(
            departures("lines/midpoint_tie_slope_half", foil) > 0,
            "{foil}"
        );
        assert!(
            departures("lines/midpoint_tie_slope_two", foil) > 0,
            "{foil}"
        );
    }
}

#[test]
fn the_line_metric_catches_thin_rectangles_drawn_for_midpoint_lines() {
    let s = bundled("lines/midpoint_star_16");
    let r = run(&s, &Mutant(Mutation::ThickLines));
    let crowded = r
        .metrics
        .as_ref()
        .unwrap()
        .lines
        .as_ref()
        .unwrap()
        .crowded_steps;
    assert!(crowded > 0);
    assert!(
        reasons(&r).iter().any(|m| m.starts_with("lines:")),
        "{:?}",
        reasons(&r)
    );
}

#[test]
fn coverage_catches_bresenham_served_for_diamond_exit_lines() {
    // Half-open midpoint lines agree with diamond-exit on most lines; these
    // cases hold the endpoints and borders where the two rules part.
    for id in [
        "lines/diamond_endpoints_edges",
        "lines/diamond_subpixel_4bits",
        "lines/diamond_subpixel_8bits",
        "lines/diamond_strip",
        "lines/diamond_colour_interpolation",
    ] {
        let s = bundled(id);
        assert_eq!(run(&s, &Production).verdict, Verdict::Pass, "{id}");
        let r = run(&s, &Mutant(Mutation::MidpointForDiamond));
        assert!(
            reasons(&r)[0].starts_with("coverage:"),
            "{id}: {:?}",
            reasons(&r)
        );
    }
}
