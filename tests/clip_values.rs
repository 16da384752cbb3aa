//! `interpolate_from` (SPEC.md §16.5): coverage from the snapped vertices,
//! values from the snapped or the exact projected positions. Under
//! `unsnapped` the reference covers what it covers under `snapped`, and
//! its values are those of the same scene drawn unsnapped; production
//! agrees; a rasterizer that takes its values from the other positions
//! fails the worked examples; a driver that fixes the rule is judged
//! under it and named.

mod common;

use common::Rng;
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::{
    ClipRules, ClipXy, ClipZ, DepthMode, InterpolateFrom, Interpolation, Number, Primitive, Scene,
    Triangle, Vertex,
};

/// A 12×12 clip-space scene of random triangles, some across the near
/// plane or behind the eye, under `clip`.
fn random_scene(rng: &mut Rng, clip: ClipRules) -> Scene {
    let mut scene = common::inline(
        r#"{"name": "values", "canvas": {"width": 12, "height": 12},
            "primitives": [{"triangle": [{"clip": [0, 0, 0, 1], "attributes": [0]},
                                          {"clip": [1, 0, 0, 1], "attributes": [0]},
                                          {"clip": [0, 1, 0, 1], "attributes": [0]}]}]}"#,
    );
    scene.rules.clip = clip;
    let coordinate = |rng: &mut Rng| Number::ratio(rng.range(-300, 300), 97);
    scene.primitives = (0..3)
        .map(|_| {
            let vertex = |rng: &mut Rng| Vertex {
                z: Number::ratio(rng.range(-20, 120), 97),
                w: Number::ratio(rng.range(-30, 200), 97),
                attributes: vec![Number::ratio(rng.range(-500, 500), 7)],
                ..Vertex::at(coordinate(rng), coordinate(rng))
            };
            Primitive::Triangle(Triangle {
                vertices: [vertex(rng), vertex(rng), vertex(rng)],
                interpolation: rng.pick(&[Interpolation::Perspective, Interpolation::Flat]),
            })
        })
        .collect();
    scene
}

fn render(scene: &Scene) -> Frame {
    reference::render(scene, &Plan::for_scene(scene))
}

fn with_values(scene: &Scene, values: InterpolateFrom) -> Scene {
    let mut s = scene.clone();
    s.rules.clip.values = values;
    s
}

#[test]
fn unsnapped_values_are_those_of_the_scene_drawn_unsnapped() {
    let mut rng = Rng(0x5eed_0016_0005);
    let (mut compared, mut apart) = (0usize, 0usize);
    for round in 0..120 {
        let clip = ClipRules {
            xy: ClipXy::ALL[round % 2],
            z: ClipZ::ALL[(round / 2) % 2],
            depth: [DepthMode::Clip, DepthMode::Clamp][(round / 4) % 2],
            values: InterpolateFrom::Unsnapped,
            ..ClipRules::default()
        };
        let scene = random_scene(&mut rng, clip);
        let unsnapped = render(&scene);
        let snapped = render(&with_values(&scene, InterpolateFrom::Snapped));
        let mut ideal_scene = scene.clone();
        ideal_scene.rules.subpixel_bits = None;
        let ideal = render(&ideal_scene);
        // Coverage is the snapped vertices' under either rule, except
        // that a per-sample depth test reads the values' depth.
        if clip.z == ClipZ::ClipThenSnap || clip.depth == DepthMode::Clamp {
            assert_eq!(unsnapped.coverage, snapped.coverage, "round {round}");
            assert_eq!(unsnapped.last, snapped.last, "round {round}");
        }
        let depth = unsnapped.depth.as_ref().expect("clip space writes depth");
        let ideal_depth = ideal.depth.as_ref().expect("clip space writes depth");
        let snapped_depth = snapped.depth.as_ref().expect("clip space writes depth");
        for i in 0..unsnapped.coverage.len() {
            if unsnapped.coverage[i] == 0 || ideal.coverage[i] == 0 {
                continue;
            }
            if unsnapped.last[i] != ideal.last[i] {
                continue;
            }
            compared += 1;
            assert_eq!(depth[i], ideal_depth[i], "round {round} sample {i}");
            assert_eq!(
                unsnapped.attributes[0][i], ideal.attributes[0][i],
                "round {round} sample {i}"
            );
            apart += usize::from(depth[i] != snapped_depth[i]);
        }
    }
    // Enough samples compared, and the rule changes values: a reference
    // that ignored it would fail the check above on these.
    assert!(compared > 2000, "{compared} samples compared");
    assert!(apart > 500, "{apart} samples where the rules part");
}

#[test]
fn production_follows_interpolate_from() {
    let mut rng = Rng(0x5eed_0016_0006);
    for round in 0..150 {
        let clip = ClipRules {
            xy: ClipXy::ALL[round % 2],
            z: ClipZ::ALL[(round / 2) % 2],
            depth: DepthMode::Clip,
            values: InterpolateFrom::ALL[(round / 4) % 2],
            ..ClipRules::default()
        };
        let scene = random_scene(&mut rng, clip);
        let (_, run) = common::run(&scene, &rastercheck::production::Production);
        assert!(
            matches!(run.verdict, Verdict::Pass),
            "round {round} {clip:?}: {:?}",
            run.verdict
        );
    }
}

/// The reference with its values taken from the given positions,
/// whatever a case states; declared as its own rule only when `declares`.
struct ValuesFrom {
    values: InterpolateFrom,
    declares: bool,
}

impl Rasterizer for ValuesFrom {
    fn name(&self) -> &str {
        "values-from"
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Ok(reference::render(&with_values(scene, self.values), plan))
    }
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        self.declares.then_some(self.values)
    }
}

#[test]
fn values_from_the_other_positions_fail_the_worked_examples() {
    for (case, wrong) in [
        ("clip/spec_interpolate_unsnapped", InterpolateFrom::Snapped),
        ("clip/spec_interpolate_snapped", InterpolateFrom::Unsnapped),
        (
            "clip/interp_unsnapped_clipped_gb_cts",
            InterpolateFrom::Snapped,
        ),
    ] {
        let scene = common::case(case);
        let right = ValuesFrom {
            values: scene.rules.clip.values,
            declares: false,
        };
        let (_, run) = common::run(&scene, &right);
        assert!(
            matches!(run.verdict, Verdict::Pass),
            "{case}: {:?}",
            run.verdict
        );
        let wrong = ValuesFrom {
            values: wrong,
            declares: false,
        };
        let (_, run) = common::run(&scene, &wrong);
        let Verdict::Fail(reasons) = &run.verdict else {
            panic!("{case}: {:?}", run.verdict)
        };
        assert!(
            reasons.iter().any(|r| r.contains("depth")),
            "{case}: {reasons:?}"
        );
    }
}

#[test]
fn a_rasterizers_own_interpolate_from_is_judged_and_named() {
    let scene = common::case("clip/spec_interpolate_snapped");
    let own = ValuesFrom {
        values: InterpolateFrom::Unsnapped,
        declares: true,
    };
    let (_, run) = common::run(&scene, &own);
    assert_eq!(
        run.judged.clip.map(|c| c.values),
        Some(InterpolateFrom::Unsnapped)
    );
    assert!(matches!(run.verdict, Verdict::Pass), "{:?}", run.verdict);
    // Held to the case's rule instead, it fails: the check can fail.
    let (_, run) = common::run(&scene, &common::AsStated(&own));
    assert!(matches!(run.verdict, Verdict::Fail(_)), "{:?}", run.verdict);
}
