//! Production antialiasing (SPEC.md §14.2) against the exact reference,
//! sample by sample; adaptive sampling against full supersampling; the
//! measured methods (`adaptive-refine`, `area-f32`) against what they
//! approximate.
//!
//! The oracle is the reference's antialiased frame (`reference::render`):
//! its exact mask at every pattern's offsets, and its exact per-pixel
//! areas. A second check needs no antialiasing in the reference at all:
//! sample s of pixel (x, y) sits at (x, y) + o_s, and it is covered exactly
//! when the pixel centre (x, y) + ½ is covered in the scene translated by
//! ½ − o_s; the translation is exact for unsnapped scenes and for snapped
//! scenes whose vertices and offsets lie on the snapping grid.

mod common;

use common::Rng;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::{self, Production};
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line,
    LineParameter, LineRule, Number, Pattern, Primitive, Rules, Scene, Triangle, Vertex,
};

const CANVAS: Canvas = Canvas {
    width: 9,
    height: 7,
};

/// A sample count the pattern allows, up to 64.
fn sample_count(rng: &mut Rng, pattern: Pattern) -> u32 {
    match pattern {
        Pattern::Standard => rng.pick(&[1, 2, 4, 8, 16]),
        Pattern::Grid | Pattern::Stratified => rng.range(1, 8).pow(2) as u32,
        Pattern::Random | Pattern::NRooks => rng.range(1, 64) as u32,
    }
}

fn antialias(rng: &mut Rng, position_bits: u32, adaptive: bool) -> Antialias {
    let pattern = rng.pick(&Pattern::ALL);
    Antialias {
        samples: sample_count(rng, pattern),
        pattern,
        seed: rng.next() % 1000,
        adaptive,
        position_bits,
    }
}

/// A vertex at multiples of 2^-bits px, coarse often enough that edges pass
/// through samples and pixel corners; with values when `valued`.
fn vertex(rng: &mut Rng, bits: u32, valued: bool) -> Vertex {
    let bits = if rng.next() & 1 == 0 {
        bits.min(rng.range(0, 4) as u32)
    } else {
        bits
    };
    let unit = 1i64 << bits;
    let coordinate = |rng: &mut Rng, size: u32| {
        Number::ratio(rng.range(-2 * unit, (i64::from(size) + 2) * unit), unit)
    };
    let mut v = Vertex::at(
        coordinate(rng, CANVAS.width),
        coordinate(rng, CANVAS.height),
    );
    if valued {
        v.z = Number::ratio(rng.range(0, 64), 64);
        v.w = Number::ratio(rng.range(16, 64), 32);
        v.attributes = vec![Number::ratio(rng.range(-64, 64), 16)];
    }
    v
}

/// A random antialiased scene of triangles and, when `lines`, a
/// parallelogram line. Snapped scenes keep their vertices and offsets on
/// the snapping grid (position_bits ≤ subpixel_bits), so that translating
/// by an offset commutes with snapping; `anywhere` lifts that, for the
/// oracles that do not translate.
fn random_scene(rng: &mut Rng, adaptive: bool, valued: bool, lines: bool) -> Scene {
    random_scene_of(rng, adaptive, valued, lines, false)
}

fn random_scene_of(
    rng: &mut Rng,
    adaptive: bool,
    valued: bool,
    lines: bool,
    anywhere: bool,
) -> Scene {
    let subpixel_bits = rng.pick(&[None, Some(4), Some(8), Some(12)]);
    let (bits, position_bits) = match subpixel_bits {
        Some(b) if anywhere => (b + 3, rng.range(4, 16) as u32),
        Some(b) => (b, rng.range(4, i64::from(b)) as u32),
        None => (rng.range(0, 12) as u32, rng.pick(&[4, 6, 8, 12, 16])),
    };
    let rules = Rules {
        subpixel_bits,
        fill_rule: rng.pick(&FillRule::ALL),
        cull: rng.pick(&[
            Cull::None,
            Cull::None,
            Cull::Clockwise,
            Cull::CounterClockwise,
        ]),
        ..Rules::default()
    };
    let interpolation = rng.pick(&[
        Interpolation::Perspective,
        Interpolation::Linear,
        Interpolation::Flat,
    ]);
    let mut primitives: Vec<Primitive> = (0..rng.range(1, 3))
        .map(|_| {
            Primitive::Triangle(Triangle {
                vertices: [0, 1, 2].map(|_| vertex(rng, bits, valued)),
                interpolation,
            })
        })
        .collect();
    if lines && rng.next() & 1 == 0 {
        // Widths on the grid too, so that the corners are.
        let width_bits = bits.min(4) as i64;
        primitives.push(Primitive::Line(Line {
            vertices: [0, 1].map(|_| vertex(rng, bits, valued)),
            rule: LineRule::Parallelogram,
            width: Number::ratio(rng.range(1, 4 << width_bits), 1 << width_bits),
            last_pixel: LastPixel::Include,
            parameter: rng.pick(&[LineParameter::Major, LineParameter::Projected]),
            interpolation,
        }));
    }
    Scene {
        name: "antialias-production".to_owned(),
        description: String::new(),
        canvas: CANVAS,
        rules,
        primitives,
        effects: Effects {
            antialias: Some(antialias(rng, position_bits, adaptive)),
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: usize::from(valued),
        has_depth: valued,
        viewport: None,
    }
}

fn production_frame(scene: &Scene) -> Frame {
    let plan = Plan::for_scene(scene);
    match Production.rasterize(scene, &plan) {
        Ok(frame) => frame,
        Err(e) => panic!("production refused {scene:#?}: {e}"),
    }
}

/// The exact mask (and values) at every sample slot, from the reference's
/// one-sample rasterizer on the translated scenes.
fn reference_per_sample(scene: &Scene) -> Frame {
    let aa = scene.effects.antialias.as_ref().unwrap();
    let offsets = aa.offsets();
    let n = offsets.len();
    let plan = Plan::for_scene(scene);
    let mut out = Frame::for_plan(scene.canvas.width, scene.canvas.height, &plan);
    let denominator = 1i64 << aa.position_bits;
    for (s, o) in offsets.iter().enumerate() {
        let shift = o.map(|c| Number::ratio(denominator / 2 - i64::from(c), denominator));
        let mut moved = scene.clone();
        moved.effects.antialias = None;
        for primitive in &mut moved.primitives {
            for v in primitive.vertices_mut() {
                v.x = &v.x + &shift[0];
                v.y = &v.y + &shift[1];
            }
        }
        let frame = reference::render(&moved, &Plan::for_scene(&moved));
        for p in 0..frame.pixel_count() {
            let slot = p * n + s;
            out.coverage[slot] = frame.coverage[p];
            out.last[slot] = frame.last[p];
            if let (Some(to), Some(from)) = (out.depth.as_mut(), frame.depth.as_ref()) {
                to[slot] = from[p];
            }
            for (to, from) in out.attributes.iter_mut().zip(&frame.attributes) {
                to[slot] = from[p];
            }
        }
    }
    out.resolve();
    out
}

fn assert_same_mask(got: &Frame, want: &Frame, scene: &Scene) {
    assert_eq!(got.samples, want.samples);
    for slot in 0..want.sample_count() {
        let n = want.samples as usize;
        let (p, s) = (slot / n, slot % n);
        let (x, y) = (p % want.width as usize, p / want.width as usize);
        assert!(
            got.coverage[slot] == want.coverage[slot] && got.last[slot] == want.last[slot],
            "pixel ({x}, {y}) sample {s}: production {}×#{}, reference {}×#{} in {scene:#?}",
            got.coverage[slot],
            got.last[slot],
            want.coverage[slot],
            want.last[slot],
        );
    }
}

/// Values at covered samples within 1e-4 of the exact ones (f32
/// barycentrics; the values here are at most 4 in magnitude).
fn assert_values_close(got: &Frame, want: &Frame, scene: &Scene) {
    let channels = got.depth.iter().zip(want.depth.iter());
    let channels = channels.chain(got.attributes.iter().zip(&want.attributes));
    for (g, w) in channels {
        for slot in 0..want.sample_count() {
            if want.coverage[slot] > 0 {
                assert!(
                    (g[slot] - w[slot]).abs() <= 1e-4,
                    "slot {slot}: {} against {} in {scene:#?}",
                    g[slot],
                    w[slot]
                );
            }
        }
    }
}

#[test]
fn production_masks_equal_the_reference_at_every_pattern() {
    let mut rng = Rng(142);
    let mut patterns_seen = std::collections::HashSet::new();
    let mut covered = 0;
    for trial in 0..300 {
        let scene = random_scene_of(&mut rng, trial % 2 == 1, trial % 3 == 0, true, true);
        let aa = scene.effects.antialias.as_ref().unwrap();
        patterns_seen.insert(aa.pattern.name());
        let got = production_frame(&scene);
        let want = reference::render(&scene, &Plan::for_scene(&scene));
        assert_same_mask(&got, &want, &scene);
        assert_values_close(&got, &want, &scene);
        assert_eq!(got.resolved, Some(got.box_resolve()), "box resolve");
        covered += got.covered_samples();
    }
    assert_eq!(patterns_seen.len(), Pattern::ALL.len());
    assert!(covered > 10_000, "the scenes cover too little: {covered}");
}

#[test]
fn production_masks_equal_the_translated_one_sample_reference() {
    let mut rng = Rng(143);
    for trial in 0..100 {
        let scene = random_scene(&mut rng, trial % 2 == 1, trial % 3 == 0, true);
        let got = production_frame(&scene);
        let want = reference_per_sample(&scene);
        assert_same_mask(&got, &want, &scene);
        assert_values_close(&got, &want, &scene);
    }
}

#[test]
fn an_edge_on_samples_follows_the_fill_rule() {
    // Standard 16× has a sample at (0, 1/2) of every pixel: the vertical
    // edge x = 2 passes through it in every row. As a left edge it is owned
    // by top-left and bottom-left, not by top-right or bottom-right.
    for rule in FillRule::ALL {
        let triangle = |xs: [i64; 3], ys: [i64; 3]| Triangle {
            vertices: [0, 1, 2]
                .map(|i| Vertex::at(Number::from_int(xs[i]), Number::from_int(ys[i]))),
            interpolation: Interpolation::Linear,
        };
        let scene = Scene {
            name: "edge".to_owned(),
            description: String::new(),
            canvas: CANVAS,
            rules: Rules {
                fill_rule: rule,
                ..Rules::default()
            },
            primitives: vec![Primitive::Triangle(triangle([2, 9, 2], [0, 0, 7]))],
            effects: Effects {
                antialias: Some(Antialias {
                    samples: 16,
                    pattern: Pattern::Standard,
                    seed: 0,
                    adaptive: false,
                    position_bits: 8,
                }),
                motion_blur: None,
                conservative: None,
            },
            expect: Expect::default(),
            attribute_count: 0,
            has_depth: false,
            viewport: None,
        };
        let frame = production_frame(&scene);
        let on_edge = frame.index(2, 1) + 12; // sample 12 is (0, 8/16)
        let owned = u16::from(rule.owns_left());
        assert_eq!(frame.coverage[on_edge], owned, "{rule:?}");
        assert_same_mask(&frame, &reference_per_sample(&scene), &scene);
        let mut adaptive = scene.clone();
        adaptive.effects.antialias.as_mut().unwrap().adaptive = true;
        assert_eq!(production_frame(&adaptive), frame, "{rule:?}");
    }
}

#[test]
fn adaptive_sampling_equals_full_supersampling() {
    let mut rng = Rng(2);
    let mut skipped_pixels = 0;
    let mut seen = std::collections::HashSet::new();
    for trial in 0..400 {
        let mut scene = random_scene(&mut rng, false, trial % 4 == 0, true);
        let aa = scene.effects.antialias.as_ref().unwrap();
        seen.insert(format!("{:?}", scene.rules.fill_rule));
        seen.insert(aa.pattern.name().to_owned());
        seen.insert(format!("N > 48: {}", aa.samples > 48));
        if trial % 5 == 0 {
            // Larger triangles, where whole pixels are skipped.
            scene.canvas = Canvas {
                width: 40,
                height: 30,
            };
            for primitive in &mut scene.primitives {
                for v in primitive.vertices_mut() {
                    v.x = &(&v.x + &v.x) + &(&v.x + &v.x);
                    v.y = &(&v.y + &v.y) + &(&v.y + &v.y);
                }
            }
        }
        let full = production_frame(&scene);
        scene.effects.antialias.as_mut().unwrap().adaptive = true;
        let adaptive = production_frame(&scene);
        assert!(adaptive == full, "adaptive differs in {scene:#?}");
        let n = full.samples as usize;
        skipped_pixels += full
            .coverage
            .chunks(n)
            .filter(|run| n > 1 && run.iter().all(|&c| c == run[0]))
            .count();
    }
    assert!(
        skipped_pixels > 1000,
        "too few uniform pixels: {skipped_pixels}"
    );
}

#[test]
fn adaptive_refine_misses_a_thin_sliver_and_resolves_its_own_mask() {
    // 4× standard: refine tests sample 0, at (6/16, 2/16), first. A sliver
    // between x = 61/16 and 63/16 holds sample 1, at (14/16, 6/16), in
    // column 3 of the rows its left edge allows, and never sample 0: refine
    // sees four agreeing "uncovered" samples in every pixel and skips it.
    let methods = production::methods();
    let refine = methods
        .iter()
        .find(|m| m.name == "adaptive-refine")
        .unwrap();
    let refine = (refine.make)();
    assert!(refine.is_foil());
    let v = |x: Number, y: i64| Vertex::at(x, Number::from_int(y));
    let sliver = Triangle {
        vertices: [
            v(Number::ratio(61, 16), 0),
            v(Number::ratio(63, 16), 0),
            v(Number::ratio(63, 16), 7),
        ],
        interpolation: Interpolation::Linear,
    };
    let mut scene = Scene {
        name: "sliver".to_owned(),
        description: String::new(),
        canvas: CANVAS,
        rules: Rules::default(),
        primitives: vec![Primitive::Triangle(sliver)],
        effects: Effects {
            antialias: Some(Antialias {
                samples: 4,
                pattern: Pattern::Standard,
                seed: 0,
                adaptive: false,
                position_bits: 8,
            }),
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    };
    let plan = Plan::for_scene(&scene);
    let exact = production_frame(&scene);
    let refined = refine.rasterize(&scene, &plan).unwrap();
    assert!(exact.covered_samples() > 0);
    assert_eq!(refined.covered_samples(), 0);
    assert_eq!(refined.resolved, Some(refined.box_resolve()));
    // A triangle over the whole canvas: every first sample agrees, rightly.
    scene.primitives = vec![Primitive::Triangle(Triangle {
        vertices: [
            v(Number::from_int(-1), -1),
            v(Number::from_int(30), -1),
            v(Number::from_int(-1), 30),
        ],
        interpolation: Interpolation::Linear,
    })];
    scene.effects.antialias.as_mut().unwrap().samples = 16;
    let plan = Plan::for_scene(&scene);
    assert_eq!(
        refine.rasterize(&scene, &plan).unwrap().coverage,
        production_frame(&scene).coverage
    );
}

#[test]
fn the_same_seed_gives_the_same_frame() {
    let mut a = Rng(77);
    let mut b = Rng(77);
    for _ in 0..20 {
        let scene_a = random_scene(&mut a, false, true, true);
        let scene_b = random_scene(&mut b, false, true, true);
        assert_eq!(production_frame(&scene_a), production_frame(&scene_b));
        assert_eq!(production_frame(&scene_a), production_frame(&scene_a));
    }
}

#[test]
fn area_f32_is_within_1e4_of_the_exact_area() {
    let methods = production::methods();
    let area = methods.iter().find(|m| m.name == "area-f32").unwrap();
    let area = (area.make)();
    assert!(area.is_foil());
    let mut rng = Rng(5);
    let mut worst = 0.0f64;
    for trial in 0..300 {
        // Simple scenes: one triangle, or one parallelogram line.
        let mut scene = random_scene_of(&mut rng, false, false, trial % 2 == 0, true);
        let keep = if trial % 2 == 0 {
            scene.primitives.len() - 1
        } else {
            0
        };
        scene.primitives = vec![scene.primitives.swap_remove(keep)];
        let plan = Plan::for_scene(&scene);
        let frame = area.rasterize(&scene, &plan).unwrap();
        assert_eq!(frame.samples, 0);
        let got = frame.resolved.as_ref().unwrap();
        let want = reference::render(&scene, &plan).resolved.unwrap();
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            worst = worst.max((g - w).abs());
            assert!(
                (g - w).abs() <= 1e-4,
                "pixel {i}: {g} against {w} in {scene:#?}"
            );
        }
    }
    assert!(worst > 0.0, "f32 should round somewhere");
    println!("area-f32: largest error {worst:e}");
}

#[test]
fn area_f32_refuses_values_and_respects_culling() {
    let area = (production::methods()
        .into_iter()
        .find(|m| m.name == "area-f32")
        .unwrap()
        .make)();
    let mut rng = Rng(9);
    let scene = random_scene(&mut rng, false, true, false);
    assert!(matches!(
        area.rasterize(&scene, &Plan::for_scene(&scene)),
        Err(RasterError::Unsupported(_))
    ));
    // (0,0) (4,0) (0,4) is clockwise: culled under cw, drawn under ccw.
    let v = |x: i64, y: i64| Vertex::at(Number::from_int(x), Number::from_int(y));
    let mut scene = random_scene(&mut rng, false, false, false);
    scene.primitives = vec![Primitive::Triangle(Triangle {
        vertices: [v(0, 0), v(4, 0), v(0, 4)],
        interpolation: Interpolation::Linear,
    })];
    let total = |scene: &Scene| -> f64 {
        let frame = area.rasterize(scene, &Plan::for_scene(scene)).unwrap();
        frame.resolved.unwrap().iter().sum()
    };
    scene.rules.cull = Cull::Clockwise;
    assert_eq!(total(&scene), 0.0);
    scene.rules.cull = Cull::CounterClockwise;
    assert!((total(&scene) - 8.0).abs() < 1e-5);
}

#[test]
fn area_f32_is_exact_to_1e4_on_polygons_of_locally_constant_winding() {
    let area = (production::methods()
        .into_iter()
        .find(|m| m.name == "area-f32")
        .unwrap()
        .make)();
    // A frame with a hole, its contours both clockwise (even-odd) or
    // opposite (nonzero), corners off the pixel grid; and a concave
    // arrow. Wherever a pixel meets the outline the winding on either side
    // is constant, so |Σ signed areas| is the exact area.
    let outer = "[[0.75, 0.5], [8.25, 1.25], [7.5, 6.5], [1.25, 6]]";
    let hole_cw = "[[3, 2.5], [5.5, 2.25], [5.25, 4.5], [2.75, 4]]";
    let hole_ccw = "[[2.75, 4], [5.25, 4.5], [5.5, 2.25], [3, 2.5]]";
    let arrow = "[[0.5, 0.5], [8.5, 3.5], [0.5, 6.5], [3.25, 3.5]]";
    let cases = [
        format!(r#"{{"contours": [{outer}, {hole_cw}], "fill": "even-odd"}}"#),
        format!(r#"{{"contours": [{outer}, {hole_ccw}], "fill": "nonzero"}}"#),
        format!(r#"{{"polygon": {arrow}, "fill": "nonzero"}}"#),
        format!(r#"{{"polygon": {arrow}, "fill": "even-odd"}}"#),
    ];
    for polygon in cases {
        let text = format!(
            r#"{{"name": "p", "canvas": {{"width": 9, "height": 7}},
                "effects": {{"antialias": {{"samples": 16}}}},
                "primitives": [{polygon}]}}"#
        );
        let scene = rastercheck::parse_case(&text, "p.json", &Default::default()).unwrap();
        let plan = Plan::for_scene(&scene);
        let got = area.rasterize(&scene, &plan).unwrap().resolved.unwrap();
        let want = reference::render(&scene, &plan).resolved.unwrap();
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            assert!(
                (g - w).abs() <= 1e-4,
                "{polygon}: pixel {i}: {g} against {w}"
            );
        }
        assert!(want.iter().any(|&w| w > 0.0 && w < 1.0));
    }
}
