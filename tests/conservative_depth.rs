//! The depth at conservatively drawn pixels (SPEC.md §19.9): the worked
//! examples' intervals, exactly, on their case files; production and the
//! reference passing every depth case; `foil-conservative-depth-unclamped`
//! caught by the depth check with its reason, and passing where nothing
//! is clamped; a value between two possible last writers' depths caught;
//! a rasterizer that gives no depth refused unsent.

use rastercheck::frame::Frame;
use rastercheck::harness::conservative::refusal;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::metrics::conservative_depth::{failures, measure};
use rastercheck::plan::Plan;
use rastercheck::production::conservative;
use rastercheck::production::foils::ConservativeDepthUnclamped;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::reference::conservative::depth_allowed;
use rastercheck::reference::Reference;
use rastercheck::scene::depth::unorm_value;
use rastercheck::scene::{parse_case, ConservativeSupport, Limits, Scene};

const CASES: [&str; 9] = [
    "depth_inside",
    "depth_touch_extrapolated",
    "depth_clamp_unorm16",
    "depth_clamp_float32_below",
    "depth_band_grown",
    "depth_last_writer",
    "depth_degenerate_provoking",
    "depth_offset_unorm16",
    "depth_under",
];

fn load(name: &str) -> Scene {
    let path = format!(
        "{}/cases/conservative/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the case file");
    parse_case(&text, &path, &Limits::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// The allowed intervals at pixel (x, y) of a case, under its own state.
fn allowed_at(scene: &Scene, x: u32, y: u32) -> Vec<[f64; 2]> {
    let case = scene.effects.conservative.as_ref().expect("conservative");
    let allowed = depth_allowed(scene, case).expect("a case with depth");
    allowed.allowed[(y * scene.canvas.width + x) as usize].clone()
}

/// [lo, hi] widened by the cases' 2^-24 (dyadic: exact in f64).
fn widened(lo: f64, hi: f64) -> [f64; 2] {
    let e = 2f64.powi(-24);
    [lo - e, hi + e]
}

fn verdict(scene: &Scene, candidate: &dyn Rasterizer) -> Verdict {
    let reference = run_reference(scene);
    run_candidate(scene, &reference, candidate).verdict
}

#[test]
fn the_worked_examples_intervals_are_exact() {
    // Depth example 1: inside, z over the square x ∈ [1, 2] of z = x/8.
    let s = load("depth_inside");
    assert_eq!(allowed_at(&s, 1, 1), vec![widened(0.125, 0.25)]);
    // Depth example 2: touched at (3, 1), the centre extrapolated to 7/8.
    let s = load("depth_touch_extrapolated");
    assert_eq!(allowed_at(&s, 3, 1), vec![widened(0.75, 0.875)]);
    assert_eq!(allowed_at(&s, 3, 0), vec![widened(0.75, 1.0)]);
    // Depth example 3: [1, 9/8] clamped by unorm16 to exactly 1; below 0
    // in float32, exactly 0.
    let s = load("depth_clamp_unorm16");
    assert_eq!(allowed_at(&s, 4, 0), vec![[1.0, 1.0]]);
    let s = load("depth_clamp_float32_below");
    assert_eq!(allowed_at(&s, 0, 0), vec![[0.0, 0.0]]);
    // Depth example 4: the band, through the grown square.
    let s = load("depth_band_grown");
    assert_eq!(allowed_at(&s, 7, 2), vec![widened(0.6875, 0.78125)]);
    assert_eq!(allowed_at(&s, 0, 2), vec![widened(-0.09375, 0.0)]);
    // Depth example 5: either possible last writer, not between them.
    let s = load("depth_last_writer");
    assert_eq!(
        allowed_at(&s, 3, 0),
        vec![widened(0.25, 0.25), widened(0.75, 0.75)]
    );
    assert_eq!(allowed_at(&s, 0, 0), vec![widened(0.75, 0.75)]);
    assert_eq!(allowed_at(&s, 5, 3), vec![widened(0.25, 0.25)]);
    // The provoking vertex, the offset, underestimation.
    let s = load("depth_degenerate_provoking");
    for x in 1..4 {
        assert_eq!(allowed_at(&s, x, 1), vec![widened(0.25, 0.25)]);
    }
    let s = load("depth_offset_unorm16");
    let grid = |k: u32| f64::from(unorm_value(k, 16));
    assert_eq!(allowed_at(&s, 0, 0), vec![[grid(32771), grid(32776)]]);
    let s = load("depth_under");
    assert_eq!(allowed_at(&s, 1, 1), vec![widened(0.125, 0.25)]);
}

#[test]
fn production_and_the_reference_pass_every_depth_case() {
    for name in CASES {
        let scene = load(name);
        for candidate in [&Production as &dyn Rasterizer, &Reference] {
            let v = verdict(&scene, candidate);
            assert!(
                matches!(v, Verdict::Pass),
                "{name} {}: {v:?}",
                candidate.name()
            );
        }
    }
}

#[test]
fn an_unclamped_extrapolated_depth_is_caught_with_its_pixel_and_interval() {
    let why = |name: &str| match verdict(&load(name), &ConservativeDepthUnclamped) {
        Verdict::Fail(reasons) => reasons.join("; "),
        other => panic!("{name}: the foil was not caught: {other:?}"),
    };
    let above = why("depth_clamp_unorm16");
    assert!(
        above.contains(
            "conservative depth: 1 of 15 drawn pixel(s) outside the depths unorm16 allows"
        ) && above.contains("largest excursion 0.125; first (4, 0): 1.125 not in [1, 1]"),
        "{above}"
    );
    let below = why("depth_clamp_float32_below");
    assert!(
        below.contains("first (0, 0): -0.125 not in [0, 0]"),
        "{below}"
    );
    // Where nothing is clamped (exact depth) it is production.
    for name in ["depth_inside", "depth_band_grown", "depth_last_writer"] {
        let v = verdict(&load(name), &ConservativeDepthUnclamped);
        assert!(matches!(v, Verdict::Pass), "{name}: {v:?}");
    }
}

#[test]
fn a_depth_between_two_possible_last_writers_fails() {
    let scene = load("depth_last_writer");
    let plan = Plan::for_scene(&scene);
    let mut frame = conservative::rasterize(&scene, &plan).expect("production draws it");
    let case = scene.effects.conservative.as_ref().expect("conservative");
    let allowed = depth_allowed(&scene, case).expect("depth");
    assert!(failures(&measure(&allowed, &frame)).is_empty());
    let i = frame.index(3, 0);
    frame.depth.as_mut().expect("depth")[i] = 0.5;
    let m = measure(&allowed, &frame);
    assert_eq!((m.outside, m.largest_excursion), (1, 0.25 - 2f64.powi(-24)));
    assert!(failures(&m)[0].contains("first (3, 0): 0.5 not in"));
}

/// Production's conservative rasterization, declaring no depth.
struct NoDepth;

impl Rasterizer for NoDepth {
    fn name(&self) -> &str {
        "no-depth"
    }

    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }

    fn conservative(&self) -> Option<ConservativeSupport> {
        Some(ConservativeSupport {
            depth: false,
            ..conservative::support()
        })
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        conservative::rasterize(scene, plan)
    }
}

#[test]
fn a_rasterizer_that_gives_no_depth_is_refused_unsent() {
    let why = refusal(&load("depth_inside"), &NoDepth).expect("refused");
    assert!(why.contains("gives no depth under conservative rasterization (SPEC.md §19.9)"));
    let without = load("depth_inside");
    let flat = Scene {
        has_depth: false,
        ..without
    };
    assert_eq!(refusal(&flat, &NoDepth), None);
}
