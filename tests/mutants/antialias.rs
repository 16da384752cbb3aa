//! Antialiasing: the mask sample by sample, area methods, resolves and
//! exact areas, each failing a wrong rasterizer that production's
//! antialiasing passes.

use crate::{reasons, run, scene};
use rastercheck::frame::Frame;
use rastercheck::harness::judge;
use rastercheck::harness::judge::Verdict;
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::Scene;

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
        assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
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
            .any(|m| m.starts_with("coverage: 1 sample differs") && m.contains("1 extra")),
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
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
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
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));

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
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
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
        judge::describe(&closed)
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
