//! Properties of the reference's clip space (SPEC.md §16), on random
//! triangles: where SPEC §16.7 says the conventions agree they agree with
//! the screen-space scene of the projected vertices, bit for bit; a
//! triangle cut in two by a plane covers exactly what it covers whole; a
//! mesh whose shared edges cross the near plane stays watertight.

mod common;

use common::Rng;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::reference::{self, coverage_under, mesh_interior};
use rastercheck::scene::{
    ClipRules, ClipXy, ClipZ, DepthMode, FillRule, Interpolation, Number, Primitive, Scene,
    Triangle, Vertex,
};

const SIDE: u32 = 12;

/// A clip-space scene of `triangles`, each vertex (x, y, z, w) with one
/// attribute.
fn clip_scene(triangles: Vec<[[Number; 5]; 3]>, bits: Option<u32>, clip: ClipRules) -> Scene {
    let mut scene = common::inline(
        r#"{"name": "clip", "canvas": {"width": 12, "height": 12},
            "primitives": [{"triangle": [{"clip": [0, 0, 0, 1], "attributes": [0]},
                                          {"clip": [1, 0, 0, 1], "attributes": [0]},
                                          {"clip": [0, 1, 0, 1], "attributes": [0]}]}]}"#,
    );
    scene.rules.subpixel_bits = bits;
    scene.rules.clip = clip;
    scene.primitives = triangles
        .into_iter()
        .map(|t| {
            Primitive::Triangle(Triangle {
                vertices: t.map(|[x, y, z, w, a]| Vertex {
                    z,
                    w,
                    attributes: vec![a],
                    ..Vertex::at(x, y)
                }),
                interpolation: Interpolation::Perspective,
            })
        })
        .collect();
    scene
}

/// Every combination of the clip-space conventions.
fn conventions() -> Vec<ClipRules> {
    let mut all = Vec::new();
    for xy in ClipXy::ALL {
        for z in ClipZ::ALL {
            all.push(ClipRules {
                xy,
                z,
                depth: DepthMode::Clip,
                ..ClipRules::default()
            });
        }
        all.push(ClipRules {
            xy,
            z: ClipZ::ClipThenSnap,
            depth: DepthMode::Clamp,
            ..ClipRules::default()
        });
    }
    all
}

fn small(rng: &mut Rng, denominator: i64) -> Number {
    Number::ratio(rng.range(-3 * denominator, 3 * denominator), denominator)
}

fn render(scene: &Scene) -> Frame {
    reference::render(scene, &Plan::for_scene(scene))
}

/// The screen-space scene SPEC §16.7 says a clip-space scene drawn whole
/// equals: each vertex at (x_f, y_f) (snapped by the scene's own rule),
/// depth z/w, the same w and attributes.
fn on_screen(scene: &Scene) -> Scene {
    let mut screen = scene.clone();
    let half = Number::ratio(SIDE as i64, 2);
    screen.viewport = None;
    for v in screen.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        let w = v.w.as_rbig().clone();
        let land = |c: &Number| {
            Number::from_rbig(half.as_rbig() * (c.as_rbig() / &w + dashu_ratio::RBig::ONE))
        };
        let (x, y) = (land(&v.x), land(&v.y));
        v.z = Number::from_rbig(v.z.as_rbig() / &w);
        v.x = x;
        v.y = y;
    }
    screen
}

#[test]
fn conventions_agree_with_the_screen_where_nothing_is_clipped() {
    let mut rng = Rng(0x5EC7_1067);
    let mut drawn = 0;
    for round in 0..120 {
        // Inside the clip volume: |x|, |y| ≤ w, 0 ≤ z ≤ w, w > 0.
        let triangle = [0, 1, 2].map(|_| {
            let w = Number::ratio(rng.range(1, 40), 8);
            let inside = |rng: &mut Rng, low: i64| {
                Number::from_rbig(w.as_rbig() * Number::ratio(rng.range(low, 64), 64).as_rbig())
            };
            [
                inside(&mut rng, -64),
                inside(&mut rng, -64),
                inside(&mut rng, 0),
                w.clone(),
                small(&mut rng, 4),
            ]
        });
        let bits = [Some(0), Some(4), Some(8), None][round % 4];
        let base = clip_scene(vec![triangle], bits, ClipRules::default());
        let expected = render(&on_screen(&base));
        drawn += usize::from(expected.covered_samples() > 0);
        for clip in conventions() {
            let mut scene = base.clone();
            scene.rules.clip = clip;
            let frame = render(&scene);
            assert_eq!(frame.coverage, expected.coverage, "round {round}, {clip:?}");
            assert_eq!(frame.depth, expected.depth, "round {round}, {clip:?}");
            assert_eq!(
                frame.attributes, expected.attributes,
                "round {round}, {clip:?}"
            );
        }
    }
    assert!(drawn > 80, "only {drawn} of 120 triangles drew anything");
}

/// A triangle ABC and its two halves cut along M on AB and N on AC: AMN,
/// MBC and MCN, in ABC's winding.
fn halves(t: &[[Number; 5]; 3], along_b: &Number, along_c: &Number) -> Vec<[[Number; 5]; 3]> {
    let mix = |p: &[Number; 5], q: &[Number; 5], s: &Number| {
        [0, 1, 2, 3, 4].map(|i| {
            Number::from_rbig(p[i].as_rbig() + s.as_rbig() * (q[i].as_rbig() - p[i].as_rbig()))
        })
    };
    let [a, b, c] = t;
    let m = mix(a, b, along_b);
    let n = mix(a, c, along_c);
    vec![
        [a.clone(), m.clone(), n.clone()],
        [m.clone(), b.clone(), c.clone()],
        [m, c.clone(), n],
    ]
}

/// Coverage counts summed over a scene's primitives, per pixel.
fn total(scene: &Scene, rule: FillRule) -> Vec<u16> {
    coverage_under(scene, &Plan::for_scene(scene), rule)
}

#[test]
fn a_triangle_cut_in_two_covers_what_it_covers_whole() {
    let mut rng = Rng(0xC0_7713);
    let mut crossing = 0;
    for round in 0..150 {
        // Any w, including behind the eye: the homogeneous test, unsnapped.
        let triangle = [0, 1, 2].map(|_| {
            [
                small(&mut rng, 4),
                small(&mut rng, 4),
                small(&mut rng, 4),
                Number::ratio(rng.range(-8, 24), 8),
                small(&mut rng, 4),
            ]
        });
        crossing += usize::from(triangle.iter().any(|v| !v[3].is_positive()));
        let cut = halves(
            &triangle,
            &Number::ratio(rng.range(1, 15), 16),
            &Number::ratio(rng.range(1, 15), 16),
        );
        let per_sample = ClipRules {
            xy: ClipXy::GuardBand,
            z: ClipZ::PerSample,
            depth: DepthMode::Clip,
            ..ClipRules::default()
        };
        let clamp = ClipRules {
            depth: DepthMode::Clamp,
            ..per_sample
        };
        for clip in [per_sample, clamp] {
            let whole = clip_scene(vec![triangle.clone()], None, clip);
            let parts = clip_scene(cut.clone(), None, clip);
            for rule in FillRule::CONSISTENT {
                assert_eq!(
                    total(&parts, rule),
                    total(&whole, rule),
                    "round {round}, {rule}, {clip:?}"
                );
            }
            // Depth and attributes: the halves lie in the whole's plane.
            let (w, p) = (render(&whole), render(&parts));
            for i in 0..w.coverage.len() {
                if w.coverage[i] > 0 {
                    assert_eq!(w.depth.as_ref().unwrap()[i], p.depth.as_ref().unwrap()[i]);
                    assert_eq!(
                        w.attributes[0][i], p.attributes[0][i],
                        "round {round}, sample {i}"
                    );
                }
            }
        }
        // The check can fail: under all-edges the cut is covered twice.
        let whole = clip_scene(vec![triangle.clone()], None, ClipRules::default());
        let parts = clip_scene(cut, None, ClipRules::default());
        let (w, p) = (
            total(&whole, FillRule::AllEdges),
            total(&parts, FillRule::AllEdges),
        );
        assert!(p.iter().zip(&w).all(|(p, w)| p >= w));
    }
    assert!(
        crossing > 50,
        "only {crossing} triangles had a vertex behind the eye"
    );
}

/// det[(x, y, w)] of a triangle's vertices: its winding on the screen when
/// every w > 0.
fn winding(t: &[[Number; 5]; 3]) -> dashu_ratio::RBig {
    let r = |v: &[Number; 5]| [&v[0], &v[1], &v[3]].map(|c| c.as_rbig().clone());
    let [a, b, c] = [r(&t[0]), r(&t[1]), r(&t[2])];
    &a[0] * (&b[1] * &c[2] - &b[2] * &c[1]) - &a[1] * (&b[0] * &c[2] - &b[2] * &c[0])
        + &a[2] * (&b[0] * &c[1] - &b[1] * &c[0])
}

#[test]
fn a_mesh_across_the_near_plane_stays_watertight() {
    let mut rng = Rng(0x4EA2);
    let mut cut = 0;
    for round in 0..200 {
        // A fan around a centre, every spoke an edge two triangles share.
        let centre = [
            small(&mut rng, 8),
            small(&mut rng, 8),
            Number::ratio(rng.range(-4, 8), 8),
            Number::ONE,
            Number::ZERO,
        ];
        let n = rng.range(4, 7) as usize;
        let ring: Vec<[Number; 5]> = (0..n)
            .map(|i| {
                let angle = std::f64::consts::TAU * i as f64 / n as f64;
                let r = rng.range(8, 20) as f64 / 8.0;
                let q = |v: f64| Number::ratio((v * 64.0).round() as i64, 64);
                [
                    q(r * angle.cos()),
                    q(r * angle.sin()),
                    Number::ratio(rng.range(-8, 8), 8),
                    Number::ratio(rng.range(6, 10), 8),
                    Number::ONE,
                ]
            })
            .collect();
        let triangles: Vec<_> = (0..n)
            .map(|i| [centre.clone(), ring[i].clone(), ring[(i + 1) % n].clone()])
            .collect();
        // Every w > 0 here: keep the fans that do not fold on the screen,
        // every triangle wound the same way.
        let windings: Vec<bool> = triangles
            .iter()
            .map(|t| winding(t) > dashu_ratio::RBig::ZERO)
            .collect();
        if windings.iter().any(|w| *w != windings[0]) {
            continue;
        }
        cut += usize::from(
            triangles
                .iter()
                .flatten()
                .any(|v| !v[2].as_rbig().ge(&dashu_ratio::RBig::ZERO)),
        );
        for clip in conventions() {
            let mut scene = clip_scene(triangles.clone(), Some([0, 4, 8][round % 3]), clip);
            scene.expect.watertight = true;
            let interior = mesh_interior(&scene, &Plan::for_scene(&scene));
            for rule in FillRule::CONSISTENT {
                let counts = coverage_under(&scene, &Plan::for_scene(&scene), rule);
                for (i, (&count, &inside)) in counts.iter().zip(&interior).enumerate() {
                    assert!(
                        count <= 1,
                        "round {round}, {clip:?}, {rule}: sample {i} covered {count} times"
                    );
                    assert!(
                        !inside || count == 1,
                        "round {round}, {clip:?}, {rule}: hole at {i}"
                    );
                }
            }
        }
    }
    assert!(cut > 30, "only {cut} meshes crossed the near plane");
}

#[test]
fn the_fuzz_clip_family_draws_what_clipping_is_for() {
    use rastercheck::explore::fuzz::{generate, Family};
    let (mut drawn, mut behind, mut clamped) = (0, 0, 0);
    for index in 0..200 {
        let (_, scene) = generate(11, index, Some(Family::Clip));
        assert!(scene.in_clip_space());
        let frame = render(&scene);
        let covered = frame.covered_samples() > 0;
        drawn += usize::from(covered);
        behind += usize::from(covered && scene.vertices().any(|v| !v.w.is_positive()));
        clamped += usize::from(covered && scene.rules.clip.depth == DepthMode::Clamp);
    }
    assert!(drawn > 100, "{drawn} of 200 scenes drew something");
    assert!(
        behind > 30,
        "{behind} scenes drew a triangle with a vertex behind the eye"
    );
    assert!(clamped > 20, "{clamped} scenes drew under depth clamp");
}

/// The reference, clipping one way whatever a case states: what a driver
/// does (SPEC.md §16.9).
struct FixedClip(ClipRules);

impl rastercheck::rasterizer::Rasterizer for FixedClip {
    fn name(&self) -> &str {
        "fixed-clip"
    }
    fn capabilities(&self) -> rastercheck::rasterizer::Capabilities {
        rastercheck::rasterizer::Capabilities::everything()
    }
    fn rasterize(
        &self,
        scene: &Scene,
        plan: &Plan,
    ) -> Result<Frame, rastercheck::rasterizer::RasterError> {
        let mut s = scene.clone();
        s.rules.clip.xy = self.0.xy;
        if s.rules.clip.depth == DepthMode::Clip {
            s.rules.clip.z = self.0.z;
        }
        Ok(reference::render(&s, plan))
    }
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((self.0.xy, self.0.z))
    }
}

#[test]
fn probe_finds_a_rasterizers_own_clipping() {
    use rastercheck::explore::probe::probe_clip;
    let found = probe_clip(&rastercheck::reference::Reference).expect("takes clip space");
    assert!(found.follows_case && found.consistent, "{found:?}");
    assert!(found.scenes >= 12, "{found:?}");
    for clip in conventions()
        .into_iter()
        .filter(|c| c.depth == DepthMode::Clip)
    {
        let found = probe_clip(&FixedClip(clip)).expect("takes clip space");
        assert!(
            !found.follows_case && found.consistent,
            "{clip:?}: {found:?}"
        );
        assert_eq!(found.clip_xy(), Some(clip.xy.name()), "{found:?}");
        assert_eq!(found.clip_z(), Some(clip.z.name()), "{found:?}");
    }
    // Production follows each case; a screen-space rasterizer is not probed.
    let found = probe_clip(&rastercheck::production::Production).expect("takes clip space");
    assert!(found.follows_case, "{found:?}");
    assert!(probe_clip(&rastercheck::production::foils::FloatF32).is_none());
}

#[test]
fn a_rasterizers_own_clipping_is_judged_and_named() {
    // Guard band, near and far clipped per sample: a triangle across the
    // near plane whose cut is off the snapping grid.
    let own = ClipRules {
        xy: ClipXy::GuardBand,
        z: ClipZ::PerSample,
        depth: DepthMode::Clip,
        ..ClipRules::default()
    };
    let scene = common::case("clip/spec_near_clip_then_snap");
    assert_eq!(scene.rules.clip.z, ClipZ::ClipThenSnap);
    let (_, run) = common::run(&scene, &FixedClip(own));
    assert_eq!(run.judged.clip, Some(own));
    assert!(
        matches!(run.verdict, rastercheck::harness::judge::Verdict::Pass),
        "{:?}",
        run.verdict
    );
    // Held to the case's clipping instead, it fails: the check can fail.
    let (_, run) = common::run(&scene, &common::AsStated(&FixedClip(own)));
    assert!(
        matches!(run.verdict, rastercheck::harness::judge::Verdict::Fail(_)),
        "{:?}",
        run.verdict
    );
}
