//! Conservative rasterization with multisampling (issue 38, SPEC.md
//! §19.10): a sample's class is its pixel's, so a conservatively drawn
//! pixel covers all its samples and an undrawn one none. The reference and
//! production pass the multisampled cases; worked example 16
//! (`msaa_over_corner_touch`) is pinned sample by sample; and a foil that
//! covers, at each conservatively drawn pixel, only the samples inside the
//! triangle (as a driver that kept its sample test would) is caught: a
//! corner pixel with no sample inside missing, and pixels covered partly.

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::reference::Reference;
use rastercheck::scene::ConservativeSupport;
use rastercheck::{parse_case, Limits, Scene};

const CASES: [&str; 5] = [
    "msaa_over_corner_touch",
    "msaa_over_sliver_band",
    "msaa_under_quarter_band",
    "msaa_flag_overestimate",
    "msaa_mesh_quad_split",
];

fn case(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("cases/conservative")
        .join(format!("{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap();
    parse_case(&text, &path.display().to_string(), &Limits::default()).unwrap()
}

fn verdict(scene: &Scene, candidate: &dyn Rasterizer) -> Verdict {
    let reference = run_reference(scene);
    run_candidate(scene, &reference, candidate).verdict
}

/// Production's conservative pixels, each keeping only the samples that
/// production's ordinary multisampled fill covers (the samples inside the
/// triangle): wrong at every pixel the triangle touches without covering
/// all its sample positions.
struct SamplesInside;

impl Rasterizer for SamplesInside {
    fn name(&self) -> &str {
        "foil-conservative-samples-inside"
    }
    fn is_foil(&self) -> bool {
        true
    }
    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }
    fn conservative(&self) -> Option<ConservativeSupport> {
        Production.conservative()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut frame = Production.rasterize(scene, plan)?;
        let ordinary = Scene {
            effects: rastercheck::scene::Effects {
                conservative: None,
                ..scene.effects.clone()
            },
            ..scene.clone()
        };
        let inside = Production.rasterize(&ordinary, &Plan::for_scene(&ordinary))?;
        for (slot, covered) in frame.coverage.iter_mut().enumerate() {
            if inside.coverage[slot] == 0 {
                *covered = 0;
                frame.last[slot] = 0;
            }
        }
        Ok(frame)
    }
}

#[test]
fn the_reference_and_production_pass_every_multisampled_case() {
    for name in CASES {
        let scene = case(name);
        assert!(scene.effects.antialias.is_some(), "{name}");
        assert_eq!(scene.conservative_unjudged(), None, "{name}");
        for candidate in [&Reference as &dyn Rasterizer, &Production] {
            let v = verdict(&scene, candidate);
            assert!(
                matches!(v, Verdict::Pass),
                "{name}: {}: {v:?}",
                candidate.name()
            );
        }
    }
}

/// Worked example 16: the 13 required pixels cover all 4 samples each,
/// pixel (0, 0) too, though none of its sample positions lies in the
/// triangle; every other pixel none.
#[test]
fn worked_example_9_every_sample_of_a_drawn_pixel() {
    let scene = case("msaa_over_corner_touch");
    let frame = Reference
        .rasterize(&scene, &Plan::for_scene(&scene))
        .unwrap();
    assert_eq!(frame.samples, 4);
    for y in 0..4 {
        for x in 0..4 {
            let i = frame.index(x, y);
            let covered = frame.coverage[i..i + 4].iter().filter(|&&c| c > 0).count();
            let expected = if x + y <= 4 { 4 } else { 0 };
            assert_eq!(covered, expected, "({x}, {y})");
        }
    }
    let production = Production
        .rasterize(&scene, &Plan::for_scene(&scene))
        .unwrap();
    assert_eq!(production.coverage, frame.coverage);
}

/// The foil: pixel (0, 0) has no sample inside, so the required pixel is
/// missing; (2, 1) has some, so it is partly covered. Both named.
#[test]
fn covering_only_the_samples_inside_is_caught() {
    let scene = case("msaa_over_corner_touch");
    let Verdict::Fail(reasons) = verdict(&scene, &SamplesInside) else {
        panic!("the samples-inside foil was not caught");
    };
    let text = reasons.join("; ");
    assert!(text.contains("required pixel(s) not drawn"), "{text}");
    assert!(text.contains("first (0, 0)"), "{text}");
    assert!(
        text.contains("with only some of their samples covered"),
        "{text}"
    );
    // Caught on the other single-triangle overestimation cases. (On
    // msaa_mesh_quad_split its ordinary fill covers every sample of the
    // watertight square: right there, and it passes.)
    for name in ["msaa_over_sliver_band", "msaa_flag_overestimate"] {
        let v = verdict(&case(name), &SamplesInside);
        assert!(matches!(v, Verdict::Fail(_)), "{name}: {v:?}");
    }
}

/// The fuzzer's conservative family multisamples some of its scenes
/// (SPEC.md §19.10): production passes each, and the samples-inside foil
/// is caught on some, so the family's multisampled scenes can fail.
#[test]
fn the_fuzz_familys_multisampled_scenes_catch_the_samples_inside_foil() {
    use rastercheck::explore::fuzz::{generate, Family};
    let (mut multisampled, mut caught) = (0, 0);
    for index in 0..400 {
        let (_, scene) = generate(38, index, Some(Family::Conservative));
        if scene.effects.antialias.is_none() {
            continue;
        }
        multisampled += 1;
        let v = verdict(&scene, &Production);
        assert!(matches!(v, Verdict::Pass), "scene {index}: {v:?}");
        if let Verdict::Fail(reasons) = verdict(&scene, &SamplesInside) {
            let text = reasons.join("; ");
            assert!(
                text.contains("required pixel(s) not drawn")
                    || text.contains("with only some of their samples covered"),
                "scene {index}: {text}"
            );
            caught += 1;
        }
    }
    eprintln!("{multisampled} multisampled scenes, the foil caught on {caught}");
    assert!(multisampled >= 40, "{multisampled}");
    assert!(caught * 4 >= multisampled, "{caught} of {multisampled}");
}

/// A frame with one sample per pixel for a multisampled case cannot be
/// judged: an error naming the counts, never a pass.
#[test]
fn a_frame_with_the_wrong_sample_count_is_an_error() {
    struct OneSample;
    impl Rasterizer for OneSample {
        fn name(&self) -> &str {
            "one-sample"
        }
        fn capabilities(&self) -> Capabilities {
            Production.capabilities()
        }
        fn conservative(&self) -> Option<ConservativeSupport> {
            Production.conservative()
        }
        fn rasterize(&self, scene: &Scene, _: &Plan) -> Result<Frame, RasterError> {
            let single = Scene {
                effects: rastercheck::scene::Effects {
                    antialias: None,
                    ..scene.effects.clone()
                },
                ..scene.clone()
            };
            Production.rasterize(&single, &Plan::for_scene(&single))
        }
    }
    match verdict(&case("msaa_over_corner_touch"), &OneSample) {
        Verdict::Error(why) => assert!(why.contains("drawn with 4 per pixel"), "{why}"),
        other => panic!("{other:?}"),
    }
}
