//! Production's scanline fill against the exact winding number: random
//! shapes, ties, antialiasing, unsnapped and free coordinates, extremes.

use crate::shapes::{
    assert_same, draw_direct, exact, polygon_of, random_scene, scene_of, Rng, BITS, SHAPES, SIZE,
};
use rastercheck::plan::Plan;
use rastercheck::production::polygon;
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{
    Antialias, FillRule, Interpolation, Number, Pattern, Polygon, PolygonFill, Primitive, Triangle,
    Vertex,
};

#[test]
fn scanline_equals_the_exact_winding_number() {
    let mut rng = Rng::new(1);
    for case in 0..300 {
        let scene = random_scene(&mut rng, None);
        let plan = Plan::for_scene(&scene);
        let expected = exact(&scene, &plan);
        let actual = Production.rasterize(&scene, &plan).unwrap();
        assert_same(&expected, &actual, &format!("case {case}"));
    }
}

#[test]
fn every_shape_rule_and_fill_on_ties() {
    // Each shape under each rule and fill, on the half-pixel grid, so that
    // vertices and edges fall on sample centres.
    let mut rng = Rng::new(2);
    let mut covered = 0;
    for (name, shape) in SHAPES {
        for rule in FillRule::CONSISTENT {
            for fill in [PolygonFill::EvenOdd, PolygonFill::NonZero] {
                for _ in 0..4 {
                    let p = polygon_of(&shape(&mut rng, true), BITS, fill);
                    let scene = scene_of(vec![p], rule, None, Some(BITS));
                    let plan = Plan::for_scene(&scene);
                    let expected = exact(&scene, &plan);
                    covered += expected.covered_samples();
                    let actual = Production.rasterize(&scene, &plan).unwrap();
                    assert_same(&expected, &actual, &format!("{name}, {rule}, {fill:?}"));
                }
            }
        }
    }
    assert!(covered > 1000, "the shapes cover samples: {covered}");
}

pub fn antialias(samples: u32, pattern: Pattern, seed: u64, position_bits: u32) -> Antialias {
    Antialias {
        samples,
        pattern,
        seed,
        adaptive: false,
        position_bits,
    }
}

#[test]
fn antialiased_samples_equal_the_exact_winding_number() {
    let mut rng = Rng::new(3);
    let patterns = [
        antialias(4, Pattern::Standard, 0, 8),
        antialias(16, Pattern::Standard, 0, 8),
        antialias(16, Pattern::Random, 5, 8),
        antialias(16, Pattern::Random, 9, 12),
        Antialias {
            adaptive: true,
            ..antialias(16, Pattern::Standard, 0, 8)
        },
    ];
    for case in 0..60 {
        let aa = patterns[case % patterns.len()].clone();
        let scene = random_scene(&mut rng, Some(aa));
        let plan = Plan::for_scene(&scene);
        let expected = exact(&scene, &plan);
        let actual = Production.rasterize(&scene, &plan).unwrap();
        assert_same(&expected, &actual, &format!("antialiased case {case}"));
        assert_eq!(actual.resolved, Some(actual.box_resolve()));
        // Called directly in a format finer than the samples need.
        let direct = draw_direct(&scene, &plan, 3).unwrap();
        assert_same(
            &expected,
            &direct,
            &format!("antialiased case {case}, finer"),
        );
    }
}

#[test]
fn sixteen_samples_on_the_border_are_ties() {
    // Standard 16× puts samples at x = 0 and y = 0 of the pixel: a square
    // on whole pixels has every such sample on its edges.
    let square = vec![vec![
        [2 * 16, 2 * 16],
        [9 * 16, 2 * 16],
        [9 * 16, 9 * 16],
        [2 * 16, 9 * 16],
    ]];
    for rule in FillRule::CONSISTENT {
        for reverse in [false, true] {
            let mut contours = square.clone();
            if reverse {
                contours[0].reverse();
            }
            let p = polygon_of(&contours, BITS, PolygonFill::NonZero);
            let scene = scene_of(
                vec![p],
                rule,
                Some(antialias(16, Pattern::Standard, 0, 8)),
                Some(BITS),
            );
            let plan = Plan::for_scene(&scene);
            let expected = exact(&scene, &plan);
            // 7 × 7 pixels of 16 samples: the border samples go to one side.
            assert_eq!(expected.covered_samples(), 49 * 16, "{rule}");
            assert_same(
                &expected,
                &Production.rasterize(&scene, &plan).unwrap(),
                &format!("{rule}"),
            );
        }
    }
}

#[test]
fn unsnapped_and_finely_snapped_coordinates() {
    // Exact dyadic coordinates (subpixel_bits null) and 16-bit snapping,
    // which takes production's i128 edge path for triangles.
    let mut rng = Rng::new(4);
    for case in 0..40 {
        let halves = case % 2 == 0;
        let (_, shape) = SHAPES[case % SHAPES.len()];
        let contours = shape(&mut rng, halves);
        let bits = if case % 4 < 2 { None } else { Some(16) };
        let p = polygon_of(&contours, BITS, PolygonFill::NonZero);
        let rule = FillRule::CONSISTENT[case % 4];
        let scene = scene_of(vec![p], rule, None, bits);
        let plan = Plan::for_scene(&scene);
        let expected = exact(&scene, &plan);
        let actual = Production.rasterize(&scene, &plan).unwrap();
        assert_same(&expected, &actual, &format!("case {case}"));
    }
}

/// A free coordinate: any rational (snapping decides), on the 1/4096 grid,
/// or far out in the coordinate range.
fn free(rng: &mut Rng) -> Number {
    let span = i64::from(SIZE) + 8;
    match rng.range(0, 8) {
        0..=3 => Number::ratio(rng.range(-8 << 20, span << 20), rng.range(1, 1 << 20)),
        4..=6 => Number::ratio(rng.range(-8 * 4096, span * 4096), 4096),
        _ => Number::from_int(rng.range(-COORD_LIMIT, COORD_LIMIT + 1)),
    }
}

#[test]
fn free_coordinates_snap_like_the_reference() {
    // Any rational, snapped at 0 to 16 bits, or kept exact when dyadic; and
    // polygons drawn between triangles, so owners are checked across kinds.
    let mut rng = Rng::new(9);
    for case in 0..200 {
        let subpixel_bits =
            rng.pick(&[Some(0), Some(1), Some(4), Some(8), Some(14), Some(16), None]);
        let mut primitives = Vec::new();
        for _ in 0..rng.range(1, 4) {
            let n = rng.range(3, 10);
            let contours = rng.range(1, 3);
            let mut vertices = Vec::new();
            let mut contour_ends = Vec::new();
            for _ in 0..contours {
                for _ in 0..n {
                    let (x, y) = if subpixel_bits.is_none() {
                        let mut dyadic = || Number::ratio(rng.range(-8 * 64, 40 * 64), 64);
                        (dyadic(), dyadic())
                    } else {
                        (free(&mut rng), free(&mut rng))
                    };
                    vertices.push(Vertex::at(x, y));
                }
                contour_ends.push(vertices.len());
            }
            let fill = rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]);
            primitives.push(Primitive::Polygon(Polygon {
                vertices,
                contour_ends,
                fill,
            }));
            if rng.range(0, 2) == 0 {
                let mut corner = || {
                    Vertex::at(
                        Number::ratio(rng.range(-64, 28 * 64), 64),
                        Number::ratio(rng.range(-64, 28 * 64), 64),
                    )
                };
                primitives.push(Primitive::Triangle(Triangle {
                    vertices: [corner(), corner(), corner()],
                    interpolation: Interpolation::Linear,
                }));
            }
        }
        let mut scene = scene_of(
            Vec::new(),
            rng.pick(&FillRule::CONSISTENT),
            None,
            subpixel_bits,
        );
        scene.primitives = primitives;
        let plan = Plan::for_scene(&scene);
        let expected = reference::render(&scene, &plan);
        let actual = Production.rasterize(&scene, &plan).unwrap();
        assert_same(
            &expected,
            &actual,
            &format!("case {case}, bits {subpixel_bits:?}"),
        );
    }
}

#[test]
fn extreme_polygons_never_panic() {
    // Vertices at the ends of the coordinate range, at 16 subpixel bits (the
    // i128 formats), 4096 of them in one polygon, crossing the canvas.
    let mut rng = Rng::new(10);
    let far = |rng: &mut Rng| {
        let v = rng.pick(&[-COORD_LIMIT, COORD_LIMIT, 0, 12, i64::from(SIZE)]);
        Number::ratio(v * 65536 + rng.range(-3, 4), 65536)
    };
    let mut cases: Vec<Vec<Vertex>> = (0..20)
        .map(|_| {
            (0..rng.range(3, 9))
                .map(|_| Vertex::at(far(&mut rng), far(&mut rng)))
                .collect()
        })
        .collect();
    cases.push(
        (0..4096)
            .map(|i| {
                let a = f64::from(i) / 4096.0 * std::f64::consts::TAU;
                let r = if i % 2 == 0 { 30000.0 } else { 5.0 };
                let at = |v: f64| Number::ratio((v * 256.0) as i64, 256);
                Vertex::at(at(12.0 + r * a.cos()), at(12.0 + r * a.sin()))
            })
            .collect(),
    );
    let methods: Vec<Box<dyn Rasterizer>> =
        polygon::methods().into_iter().map(|m| (m.make)()).collect();
    for (case, vertices) in cases.into_iter().enumerate() {
        let n = vertices.len();
        let p = Polygon {
            vertices,
            contour_ends: vec![n],
            fill: PolygonFill::NonZero,
        };
        for bits in [Some(16), Some(8)] {
            let scene = scene_of(vec![p.clone()], FillRule::TopLeft, None, bits);
            let plan = Plan::for_scene(&scene);
            let expected = reference::render(&scene, &plan);
            let actual = Production.rasterize(&scene, &plan).unwrap();
            assert_same(&expected, &actual, &format!("extreme case {case}"));
            for m in &methods {
                match m.rasterize(&scene, &plan) {
                    Ok(frame) if !m.is_foil() => assert_same(
                        &expected,
                        &frame,
                        &format!("{} on extreme case {case}", m.name()),
                    ),
                    Ok(_) | Err(RasterError::Unsupported(_)) => {}
                    Err(e) => panic!("{} on extreme case {case}: {e}", m.name()),
                }
            }
        }
    }
}
