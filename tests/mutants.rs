//! Every check can fail: for each one, a wrong rasterizer that it catches,
//! next to the production rasterizer passing the same case.

use rastercheck::frame::Frame;
use rastercheck::harness::suite::{self, CandidateRun, Verdict};
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{parse_case, Limits, Number, Scene};

fn scene(json: &str) -> Scene {
    parse_case(json, "inline.json", &Limits::default()).expect("valid inline case")
}

fn run(scene: &Scene, candidate: &dyn Rasterizer) -> CandidateRun {
    let reference = suite::run_reference(scene);
    suite::run_candidate(scene, &reference, candidate)
}

fn reasons(run: &CandidateRun) -> Vec<String> {
    match &run.verdict {
        Verdict::Fail(reasons) => reasons.clone(),
        other => panic!("{} should have failed, got {other:?}", run.rasterizer),
    }
}

/// An 8×8 square split along its diagonal: the samples (i+½, i+½) lie
/// exactly on the shared edge, so the tie rule alone decides their owner.
const DIAGONAL_PAIR: &str = r#"{
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
            suite::describe(&r)
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
    let reference = suite::run_reference(&s);
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
        err.contains("channel attribute.0: 1 samples differ"),
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
    let found = suite::discover(&[cases]);
    assert!(
        found.cases.len() >= 40,
        "expected the bundled triangle cases"
    );
    found
        .cases
        .iter()
        .map(|file| {
            let s = suite::load(file, &Limits::default()).unwrap();
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
    suite::load(&suite::case_file(&path), &Limits::default()).unwrap()
}

fn departures(id: &str, name: &str) -> u64 {
    let s = bundled(id);
    let foil = suite::rasterizer(name).unwrap();
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

// Antialiasing (SPEC.md §14.3): each check next to a candidate that passes.

/// A 16-sample triangle with interior, edge and empty pixels: its slanted
/// edges cross pixels at many heights, so a sample moved one lattice unit
/// (1/16 pixel with `position_bits` 4) changes sides.
const AA_TRIANGLE: &str = r#"{
  "name": "aa_triangle", "canvas": {"width": 10, "height": 10},
  "primitives": [{"triangle": [[0.5, 0.25], [9.75, 1.5], [2.25, 9.5]]}],
  "effects": {"antialias": {"samples": 16, "position_bits": 4}},
  "expect": {"max_coverage_error": 0.25, "max_coverage_rms": 0.1}
}"#;

/// The reference's own answer for an antialiased scene, changed by `edit`:
/// a sample method with exactly the oracle's mask (resolved by the box
/// filter), or an area method (`samples` 0) with the exact areas.
struct Edited {
    name: &'static str,
    area_only: bool,
    edit: fn(&mut Frame),
}

impl Rasterizer for Edited {
    fn name(&self) -> &str {
        self.name
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let exact = rastercheck::reference::render(scene, plan);
        let mut frame = if self.area_only {
            Frame::resolved_only(exact.width, exact.height, exact.resolved.unwrap())
        } else {
            let mut samples = exact;
            samples.resolve();
            samples
        };
        (self.edit)(&mut frame);
        Ok(frame)
    }
}

fn unchanged(_: &mut Frame) {}

#[test]
fn the_oracles_own_mask_and_areas_pass_an_antialiased_case() {
    let s = scene(AA_TRIANGLE);
    for area_only in [false, true] {
        let c = Edited {
            name: "exact",
            area_only,
            edit: unchanged,
        };
        let r = run(&s, &c);
        assert_eq!(r.verdict, Verdict::Pass, "{}", suite::describe(&r));
        let m = r.metrics.unwrap();
        let aa = m.antialias.expect("antialias metrics");
        assert_eq!((aa.piglit_violations, aa.resolve_mismatches), (0, 0));
        // The exact areas have no error; 16 samples have some.
        assert_eq!(aa.max_error == 0.0, area_only, "{aa:?}");
        assert!(aa.edge_pixels > 0 && aa.full_pixels > 0 && aa.empty_pixels > 0);
        // An area method has no mask to compare; the other one is exact.
        assert_eq!(m.coverage.has_mask(), !area_only);
        assert_eq!(aa.samples, if area_only { 0 } else { 16 });
    }
}

#[test]
fn the_mask_is_compared_sample_by_sample() {
    let s = scene(AA_TRIANGLE);
    // One sample of one edge pixel flipped, its resolve kept consistent.
    fn flip_one(frame: &mut Frame) {
        let n = frame.samples as usize;
        let p = frame
            .resolved
            .as_ref()
            .unwrap()
            .iter()
            .position(|&v| v > 0.0 && v < 1.0)
            .unwrap();
        let slot = (p * n..(p + 1) * n)
            .find(|&i| frame.coverage[i] == 0)
            .unwrap();
        frame.hit(slot, 0);
        frame.resolve();
    }
    let c = Edited {
        name: "one-sample-off",
        area_only: false,
        edit: flip_one,
    };
    let r = run(&s, &c);
    let why = reasons(&r);
    assert!(
        why.iter()
            .any(|m| m.starts_with("coverage: 1 samples differ") && m.contains("1 extra")),
        "{why:?}"
    );
    // Its own resolve is right, so only the mask fails.
    assert_eq!(why.len(), 1, "{why:?}");
}

#[test]
fn an_area_method_is_held_to_piglits_rule_and_the_error_bound() {
    let s = scene(AA_TRIANGLE);
    fn leaky(frame: &mut Frame) {
        for v in frame.resolved.as_mut().unwrap() {
            if *v == 1.0 {
                *v = 1.0 - 1.0 / 1048576.0;
            } else if *v > 0.0 {
                *v = (*v + 0.3).min(0.999);
            }
        }
    }
    let c = Edited {
        name: "leaky-area",
        area_only: true,
        edit: leaky,
    };
    let r = run(&s, &c);
    let why = reasons(&r);
    assert!(why.iter().any(|m| m.contains("piglit's rule")), "{why:?}");
    assert!(
        why.iter()
            .any(|m| m.starts_with("antialias: max coverage error")),
        "{why:?}"
    );
    // No default RMS bound for an area method; this case gives one.
    assert!(
        why.iter().any(|m| m.starts_with("antialias: coverage RMS")),
        "{why:?}"
    );
    let aa = r.metrics.unwrap().antialias.unwrap();
    assert!(aa.bias_edge > 0.0, "{aa:?}");
}

#[test]
fn a_resolve_that_is_not_the_masks_box_resolve_fails() {
    let s = scene(AA_TRIANGLE);
    fn halve_partial(frame: &mut Frame) {
        for v in frame.resolved.as_mut().unwrap() {
            if *v > 0.0 && *v < 1.0 {
                *v /= 2.0;
            }
        }
    }
    let c = Edited {
        name: "half-resolve",
        area_only: false,
        edit: halve_partial,
    };
    let why = reasons(&run(&s, &c));
    assert!(
        why.iter()
            .any(|m| m.contains("box resolve of their own samples")),
        "{why:?}"
    );
}

#[test]
fn expect_area_pins_the_oracles_areas() {
    let mut s = scene(AA_TRIANGLE);
    // Twice the signed area: (9.25·9.25 − 1.25·1.75) = 83.375, so 41.6875.
    s.expect.area = Some(rastercheck::scene::Number::ratio(416875, 10000));
    let exact = Edited {
        name: "exact",
        area_only: false,
        edit: unchanged,
    };
    let r = run(&s, &exact);
    assert_eq!(r.verdict, Verdict::Pass, "{}", suite::describe(&r));
    s.expect.area = Some(rastercheck::scene::Number::ratio(41, 1));
    let why = reasons(&run(&s, &exact));
    assert!(
        why.iter()
            .any(|m| m.starts_with("reference: its pixel areas sum to 667/16")),
        "{why:?}"
    );
}

#[test]
fn production_passes_the_antialiased_case_its_mutants_fail() {
    let s = scene(AA_TRIANGLE);
    let r = run(&s, &Production);
    assert_eq!(r.verdict, Verdict::Pass, "{}", suite::describe(&r));

    let shifted = run(&s, &Mutant(Mutation::ShiftedSamples));
    let why = reasons(&shifted);
    assert!(why.iter().any(|m| m.starts_with("coverage:")), "{why:?}");
    assert!(shifted.metrics.unwrap().coverage.mismatched() > 0);

    let coarse = run(&s, &Mutant(Mutation::CoarseResolve));
    let why = reasons(&coarse);
    assert!(
        why.iter()
            .any(|m| m.contains("box resolve of their own samples")),
        "{why:?}"
    );
    let (good, bad) = (
        r.metrics.unwrap().antialias.unwrap(),
        coarse.metrics.unwrap().antialias.unwrap(),
    );
    assert!(bad.rms_edge > good.rms_edge && bad.bias_edge < good.bias_edge);

    let leaky = run(&s, &Mutant(Mutation::LeakyFull));
    let why = reasons(&leaky);
    assert!(why.iter().any(|m| m.contains("piglit's rule")), "{why:?}");
    let aa = leaky.metrics.unwrap().antialias.unwrap();
    assert_eq!(aa.piglit_violations, good.full_pixels);
}

/// The diagonal pair with 16 standard samples: sample 0 of every pixel on
/// the diagonal, at (9/16, 9/16), lies exactly on the shared edge.
const AA_DIAGONAL_PAIR: &str = r#"{
  "name": "aa_diagonal_pair", "canvas": {"width": 8, "height": 8},
  "primitives": [
    {"triangle": [[0, 0], [8, 0], [8, 8]]},
    {"triangle": [[0, 0], [8, 8], [0, 8]]}
  ],
  "effects": {"antialias": {"samples": 16}},
  "expect": {"watertight": true, "samples_covered": 1024, "area": 64}
}"#;

#[test]
fn watertightness_and_ties_are_judged_sample_by_sample() {
    let s = scene(AA_DIAGONAL_PAIR);
    let r = run(&s, &Production);
    assert_eq!(r.verdict, Verdict::Pass, "{}", suite::describe(&r));
    let w = r.metrics.unwrap().watertight.expect("a mesh case");
    // Samples 12 at (0, 8/16) and 15 at (1/16, 0) of the left column and
    // top row lie on the mesh's rim; the diagonal's samples are interior.
    assert_eq!((w.interior, w.holes, w.overdraw), (1024 - 16, 0, 0));

    let closed = run(&s, &Mutant(Mutation::ClosedEdges));
    let w = closed.metrics.as_ref().unwrap().watertight.clone().unwrap();
    assert_eq!(
        (w.holes, w.overdraw),
        (0, 8),
        "{}",
        suite::describe(&closed)
    );
    // Each overdrawn sample also makes its pixel resolve above 1.
    let why = reasons(&closed);
    assert!(
        why.iter()
            .any(|m| m.starts_with("watertight: 0 holes and 8")),
        "{why:?}"
    );

    let flipped = run(&s, &Mutant(Mutation::FlippedTies));
    let c = flipped.metrics.as_ref().unwrap().coverage.clone();
    // The diagonal's samples change hands (the resolve cannot show that);
    // the rim samples on the canvas's left and top edges go missing.
    assert_eq!((c.wrong_owner, c.missing, c.extra), (8, 16, 0));
}

// Motion blur. The oracle is not needed here: the sliding square's exact
// time coverage is computed by hand (tests/sliding), and the reference's
// run is built from it as from the oracle.

mod sliding;

use rastercheck::metrics::TimeMetrics;
use sliding::{Given, Slide};

/// The reference's run of a sliding square, from its exact values.
fn slide_reference(slide: &Slide) -> (Scene, suite::ReferenceRun) {
    let s = slide.scene();
    let reference = suite::run_reference_with(&s, |_, plan| slide.exact(plan));
    (s, reference)
}

fn time_metrics(run: &CandidateRun) -> TimeMetrics {
    run.metrics
        .as_ref()
        .and_then(|m| m.time.clone())
        .unwrap_or_else(|| panic!("{}: no time metrics: {:?}", run.rasterizer, run.verdict))
}

/// The sliding square with and without 4× antialiasing.
fn slides() -> Vec<Slide> {
    let aa = Slide {
        antialias: Some(4),
        ..Slide::new("slide_aa4")
    };
    vec![Slide::new("slide"), aa]
}

#[test]
fn only_the_motion_mutants_claim_motion_blur() {
    for mutation in Mutation::ALL {
        assert_eq!(
            Mutant(mutation).capabilities().motion_blur,
            mutation.is_motion(),
            "{}",
            mutation.name()
        );
        let others = Capabilities {
            motion_blur: false,
            ..Mutant(mutation).capabilities()
        };
        let production = Capabilities {
            motion_blur: false,
            ..Production.capabilities()
        };
        assert_eq!(others, production, "{}", mutation.name());
    }
    let s = Slide::new("slide").scene();
    let r = suite::run_candidate(
        &s,
        &slide_reference(&Slide::new("slide")).1,
        &Mutant(Mutation::FlippedTies),
    );
    assert!(
        matches!(r.verdict, Verdict::Unsupported(_)),
        "{:?}",
        r.verdict
    );
}

#[test]
fn an_honest_sampler_passes_the_sliding_square_under_every_pattern() {
    // The scene the motion mutants fail is fair: the spec's instants,
    // tested exactly, meet the default RMS bound 0.75·(M·N)^-1/2. Moving
    // 8 pixels, every centre's interval ends on a multiple of 1/16, so
    // 16 strata are exact there; moving 7, no pattern is.
    for base in slides() {
        for dx in [8, 7] {
            for pattern in [
                "random",
                "stratified",
                "jittered-xy-t",
                "stratified-shuffled",
            ] {
                let slide = Slide {
                    pattern,
                    dx,
                    ..base.clone()
                };
                let (s, reference) = slide_reference(&slide);
                let sampler = Given("sampler", |s: &Scene, p: &Plan| slide.sampled(s, p));
                let r = suite::run_candidate(&s, &reference, &sampler);
                let t = time_metrics(&r);
                let what = format!("{} dx {dx} {pattern}", slide.name);
                assert_eq!(r.verdict, Verdict::Pass, "{what}: {}", suite::describe(&r));
                assert!(t.moving_pixels > 0, "{what}: {t:?}");
                assert!(
                    t.max_error > 0.0 || dx == 8 && pattern != "random",
                    "{what}: {t:?}"
                );
                let m = slide.antialias.unwrap_or(1);
                let bound = 0.75 / f64::from(m * slide.samples).sqrt();
                assert_eq!(t.allowed_rms, Some(bound));
                // Random instants come to about half the bound, stratified
                // ones less (jittered-xy-t least well of them with 4×
                // antialiasing: each spatial sample sees one quarter of
                // the shutter).
                let share = if pattern == "random" { 0.75 } else { 0.5 };
                assert!(t.rms_moving < share * bound, "{what}: {t:?}");
                let tests = t.sample_tests.unwrap();
                assert_eq!(tests.tests, 16 * 6 * u64::from(m) * 16);
                eprintln!(
                    "{what}: rms {:.4} (bound {bound:.4}), max {:.4}, efficiency {:.3}",
                    t.rms_moving,
                    t.max_error,
                    tests.efficiency()
                );
            }
        }
    }
}

#[test]
fn time_metrics_catch_primitives_drawn_at_shutter_open() {
    for slide in slides() {
        let (s, reference) = slide_reference(&slide);
        let plan = Plan::for_scene(&s);
        let mutant = Mutant(Mutation::MotionAtOpen);
        let frame = mutant.rasterize(&s, &plan).unwrap();
        // The square where it starts: 1 inside x = 2..6, y = 1..5, else 0.
        let at_open: Vec<f64> = (0..6)
            .flat_map(|y| {
                (0..16)
                    .map(move |x| f64::from(u8::from((2..6).contains(&x) && (1..5).contains(&y))))
            })
            .collect();
        assert_eq!(frame.time.as_deref(), Some(at_open.as_slice()));
        let r = suite::run_candidate(&s, &reference, &mutant);
        let t = time_metrics(&r);
        // The expected metrics, from the exact values.
        let exact = slide.exact_f64(&plan);
        let (worst, max) = exact
            .iter()
            .zip(&at_open)
            .map(|(e, c)| (c - e).abs())
            .enumerate()
            .fold(
                (0, 0.0),
                |(wi, w), (i, e)| if e > w { (i, e) } else { (wi, w) },
            );
        assert_eq!(t.max_error, max, "{}", slide.name);
        assert_eq!(t.worst_pixel, [worst as u32 % 16, worst as u32 / 16]);
        if slide.antialias.is_none() {
            // Pixel (2, 1): its centre is inside for τ ≤ 1/16 only.
            assert_eq!(
                (t.worst_pixel, t.max_error, t.worst_exact),
                ([2, 1], 0.9375, 0.0625)
            );
        }
        let failures = reasons(&r);
        assert!(
            failures
                .iter()
                .any(|f| f.starts_with("time: time-coverage RMS")),
            "{failures:?}"
        );
        // Any primitive keeps its area at every instant: the errors cancel
        // over each row, and only the RMS sees them.
        assert!(t.bias_moving.abs() < 1e-12, "{t:?}");
        let [x, y] = t.worst_pixel;
        assert!(
            failures[0].contains(&format!("worst pixel ({x}, {y})")),
            "{failures:?}"
        );
    }
    // With a bound on the largest error, that fails too, naming the pixel.
    let slide = Slide {
        expect: "\"max_time_error\": 0.5".to_owned(),
        ..Slide::new("slide_max")
    };
    let (s, reference) = slide_reference(&slide);
    let failures = reasons(&suite::run_candidate(
        &s,
        &reference,
        &Mutant(Mutation::MotionAtOpen),
    ));
    assert!(
        failures[0].starts_with("time: max time-coverage error 9.375e-1 at pixel (2, 1): candidate 1.000000, exact 0.062500 exceeds 5.000e-1"),
        "{failures:?}"
    );
}

#[test]
fn time_metrics_catch_a_shutter_sampled_only_in_its_first_half() {
    for slide in slides() {
        let (s, reference) = slide_reference(&slide);
        let plan = Plan::for_scene(&s);
        let mutant = Mutant(Mutation::MotionHalfShutter);
        let frame = mutant.rasterize(&s, &plan).unwrap();
        if slide.antialias.is_none() {
            // Instants (2k + 1)/64, k < 16: the square's left edge at
            // 2 + (2k + 1)/8 in odd eighths, so the centre x + ½ is inside
            // when 8x − 44 < 2k + 1 < 8x − 12, never on an edge.
            let expected: Vec<f64> = (0..6)
                .flat_map(|y| {
                    (0..16i64).map(move |x| {
                        let k =
                            (0..16i64).filter(|k| 8 * x - 44 < 2 * k + 1 && 2 * k + 1 < 8 * x - 12);
                        if (1..5).contains(&y) {
                            k.count() as f64 / 16.0
                        } else {
                            0.0
                        }
                    })
                })
                .collect();
            assert_eq!(frame.time.as_deref(), Some(expected.as_slice()));
        }
        let r = suite::run_candidate(&s, &reference, &mutant);
        let t = time_metrics(&r);
        assert!(t.rms_moving > 1.25 * t.allowed_rms.unwrap(), "{t:?}");
        let failures = reasons(&r);
        assert!(
            failures
                .iter()
                .any(|f| f.starts_with("time: time-coverage RMS")),
            "{failures:?}"
        );
        if slide.antialias.is_none() {
            assert_eq!((t.max_error, t.worst_pixel), (0.4375, [5, 1]));
        }
    }
    // A shutter of [1/4, 3/4]: the mutant draws [1/4, 1/2] only.
    let slide = Slide {
        shutter: [sliding::ONE / 4, 3 * sliding::ONE / 4],
        ..Slide::new("slide_part")
    };
    let (s, reference) = slide_reference(&slide);
    let r = suite::run_candidate(&s, &reference, &Mutant(Mutation::MotionHalfShutter));
    assert!(
        reasons(&r)[0].starts_with("time: time-coverage RMS"),
        "{:?}",
        reasons(&r)
    );
    let honest = Given("sampler", |s: &Scene, p: &Plan| slide.sampled(s, p));
    assert_eq!(
        suite::run_candidate(&s, &reference, &honest).verdict,
        Verdict::Pass
    );
}

#[test]
fn motion_mutants_draw_static_scenes_as_production_does() {
    let s = scene(DIAGONAL_PAIR);
    for mutation in [Mutation::MotionAtOpen, Mutation::MotionHalfShutter] {
        assert_eq!(run(&s, &Mutant(mutation)).verdict, Verdict::Pass);
    }
}

#[test]
fn an_accumulation_buffer_over_the_whole_shutter_is_not_caught() {
    // The limit of what time metrics see: N strata midpoints shared by
    // every pixel (an accumulation buffer, which strobes) estimate each
    // pixel's mean within about 1/N per edge, well inside the RMS bound.
    // Only the half-shutter variant above is a bug they catch.
    for base in slides() {
        for dx in [8, 7] {
            let slide = Slide { dx, ..base.clone() };
            let (s, reference) = slide_reference(&slide);
            let midpoints = |_: &Scene, _: &Plan| {
                let instants: Vec<Number> = (0..16).map(|k| Number::ratio(2 * k + 1, 32)).collect();
                rastercheck::production::mutants::accumulate(&s, &instants).unwrap()
            };
            let r = suite::run_candidate(&s, &reference, &Given("accumulation", midpoints));
            let t = time_metrics(&r);
            assert_eq!(r.verdict, Verdict::Pass, "{}: {t:?}", slide.name);
            assert!(t.max_error <= 1.0 / 16.0 + 1e-12, "{}: {t:?}", slide.name);
            eprintln!(
                "{} dx {dx}: accumulation over the whole shutter: rms {:.4} (bound {:.4}), max {:.4}",
                slide.name,
                t.rms_moving,
                t.allowed_rms.unwrap(),
                t.max_error
            );
        }
    }
}
