//! Polygons and antialiasing (SPEC.md §14): exact areas, translation,
//! contour order, and production's masks against the reference's.

use crate::config;
use crate::strategies::{map_vertices, production};
use dashu_ratio::RBig;
use proptest::prelude::*;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{Antialias, Pattern, Polygon, PolygonFill};
use rastercheck::scene::{
    Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line, LineParameter,
    LineRule, Number, Primitive, Rules, Scene, Triangle, Vertex,
};

// --- Polygons and antialiasing (SPEC.md §14) --------------------------------

const ASIZE: u32 = 16;

/// A coordinate inside [0, size]: on the half-pixel grid (ties at pixel
/// centres and borders), on a 1/16 grid (the standard patterns' lattice:
/// ties at samples), on a 1/4096 grid, or a free rational.
pub fn inside(size: u32) -> impl Strategy<Value = Number> {
    let s = i64::from(size);
    prop_oneof![
        3 => (0..=2 * s).prop_map(|h| Number::ratio(h, 2)),
        3 => (0..=16 * s).prop_map(|k| Number::ratio(k, 16)),
        2 => (0..=4096 * s).prop_map(|k| Number::ratio(k, 4096)),
        2 => (1i64..1 << 20).prop_flat_map(move |d| (0..=s * d).prop_map(move |n| Number::ratio(n, d))),
    ]
}

fn point_in(size: u32) -> impl Strategy<Value = Vertex> {
    (inside(size), inside(size)).prop_map(|(x, y)| Vertex::at(x, y))
}

/// A vertex anywhere in the coordinate range: tie-forcing half-pixels and
/// 1/16ths near the canvas, free rationals, or integers to ±32768.
fn point_anywhere() -> impl Strategy<Value = Vertex> {
    let near = prop_oneof![
        (-8i64..2 * (i64::from(ASIZE) + 8)).prop_map(|h| Number::ratio(h, 2)),
        (-128i64..16 * (i64::from(ASIZE) + 8)).prop_map(|k| Number::ratio(k, 16)),
        (-8i64 << 20..(i64::from(ASIZE) + 8) << 20, 1i64..1 << 20)
            .prop_map(|(n, d)| Number::ratio(n, d)),
    ];
    let any = prop_oneof![
        6 => near,
        1 => (-COORD_LIMIT..=COORD_LIMIT).prop_map(Number::from_int),
    ];
    (any.clone(), any).prop_map(|(x, y)| Vertex::at(x, y))
}

fn fill() -> impl Strategy<Value = PolygonFill> {
    prop::sample::select(vec![PolygonFill::NonZero, PolygonFill::EvenOdd])
}

/// A polygon of 1 to 3 contours of 3 to 8 vertices (random vertices: most
/// contours cross themselves and each other), or a rectangle with a hole
/// whose contour runs either way.
fn polygon_of(point: BoxedStrategy<Vertex>, size: u32) -> impl Strategy<Value = Polygon> {
    let contours = prop::collection::vec(prop::collection::vec(point.clone(), 3..9), 1..4);
    let random = (contours, fill()).prop_map(|(cs, fill)| {
        let mut vertices = Vec::new();
        let mut contour_ends = Vec::new();
        for c in cs {
            vertices.extend(c);
            contour_ends.push(vertices.len());
        }
        Polygon {
            vertices,
            contour_ends,
            fill,
        }
    });
    let s = i64::from(size);
    let holed = (
        prop::collection::vec(point, 3..7),
        fill(),
        any::<bool>(),
        1..s / 4,
    )
        .prop_map(move |(hole, fill, reverse, m)| {
            let corner = |x: i64, y: i64| Vertex::at(Number::from_int(x), Number::from_int(y));
            let mut outer = vec![
                corner(m, m),
                corner(s - m, m),
                corner(s - m, s - m),
                corner(m, s - m),
            ];
            if reverse {
                outer.reverse();
            }
            let mut vertices = outer;
            vertices.extend(hole);
            Polygon {
                contour_ends: vec![4, vertices.len()],
                vertices,
                fill,
            }
        });
    prop_oneof![3 => random, 1 => holed]
}

fn parallelogram(a: Vertex, b: Vertex, width: Number) -> Primitive {
    Primitive::Line(Line {
        vertices: [a, b],
        rule: LineRule::Parallelogram,
        width,
        last_pixel: LastPixel::Include,
        parameter: LineParameter::Major,
        interpolation: Interpolation::Perspective,
    })
}

/// Triangles, polygons and parallelogram lines with every vertex in the
/// canvas (a parallelogram's ends 2 px in from the sides, its width at
/// most 2, so its sides stay in too).
fn inside_primitive() -> impl Strategy<Value = Primitive> {
    let triangle = [point_in(ASIZE), point_in(ASIZE), point_in(ASIZE)].prop_map(|vertices| {
        Primitive::Triangle(Triangle {
            vertices,
            interpolation: Interpolation::Perspective,
        })
    });
    let end = (inside(ASIZE - 4), inside(ASIZE - 4))
        .prop_map(|(x, y)| {
            let two = Number::from_int(2);
            Vertex::at(&x + &two, &y + &two)
        })
        .boxed();
    let width = prop::sample::select(vec![
        Number::ratio(1, 16),
        Number::ratio(1, 3),
        Number::ONE,
        Number::from_int(2),
    ]);
    let line = (end.clone(), end, width).prop_map(|(a, b, w)| parallelogram(a, b, w));
    let polygon = polygon_of(point_in(ASIZE).boxed(), ASIZE).prop_map(Primitive::Polygon);
    prop_oneof![2 => triangle, 1 => line, 2 => polygon]
}

/// Any primitive with vertices anywhere in the coordinate range.
fn anywhere_primitive() -> impl Strategy<Value = Primitive> {
    let triangle = [point_anywhere(), point_anywhere(), point_anywhere()].prop_map(|vertices| {
        Primitive::Triangle(Triangle {
            vertices,
            interpolation: Interpolation::Perspective,
        })
    });
    let width = prop::sample::select(vec![Number::ratio(1, 2), Number::ONE, Number::from_int(3)]);
    let line =
        (point_anywhere(), point_anywhere(), width).prop_map(|(a, b, w)| parallelogram(a, b, w));
    let polygon = polygon_of(point_anywhere().boxed(), ASIZE).prop_map(Primitive::Polygon);
    prop_oneof![2 => triangle, 1 => line, 2 => polygon]
}

/// `effects.antialias`: any pattern at a count it allows, any seed,
/// adaptive or not, position bits 4 to 16.
pub fn antialias() -> impl Strategy<Value = Antialias> {
    let patterned = prop_oneof![
        prop::sample::select(vec![1u32, 2, 4, 8, 16]).prop_map(|n| (Pattern::Standard, n)),
        prop::sample::select(vec![1u32, 4, 16, 64]).prop_map(|n| (Pattern::Grid, n)),
        prop::sample::select(vec![1u32, 4, 16, 64]).prop_map(|n| (Pattern::Stratified, n)),
        prop::sample::select(vec![1u32, 3, 16, 32]).prop_map(|n| (Pattern::Random, n)),
        prop::sample::select(vec![1u32, 5, 16, 32]).prop_map(|n| (Pattern::NRooks, n)),
    ];
    (
        patterned,
        0u64..1000,
        any::<bool>(),
        prop_oneof![3 => Just(8u32), 1 => 4u32..=16],
    )
        .prop_map(
            |((pattern, samples), seed, adaptive, position_bits)| Antialias {
                samples,
                pattern,
                seed: if pattern.is_seeded() { seed } else { 0 },
                adaptive,
                position_bits,
            },
        )
}

/// Rules for scenes with polygons: the four consistent fill rules (SPEC.md
/// §14.1), no culling, any snapping.
fn polygon_rules() -> impl Strategy<Value = Rules> {
    (
        prop::sample::select(vec![None, Some(0u32), Some(4), Some(8), Some(16)]),
        prop::sample::select(FillRule::CONSISTENT.to_vec()),
    )
        .prop_map(|(subpixel_bits, fill_rule)| Rules {
            subpixel_bits,
            fill_rule,
            cull: Cull::None,
            ..Rules::default()
        })
}

fn aa_scene_of(primitives: Vec<Primitive>, rules: Rules, antialias: Option<Antialias>) -> Scene {
    Scene {
        name: "property".to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: ASIZE,
            height: ASIZE,
        },
        rules,
        primitives,
        effects: Effects {
            antialias,
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    }
}

fn inside_scene() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(inside_primitive(), 1..4),
        polygon_rules(),
        antialias(),
    )
        .prop_map(|(p, r, a)| aa_scene_of(p, r, Some(a)))
}

fn anywhere_scene() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(anywhere_primitive(), 1..4),
        polygon_rules(),
        prop::option::weighted(0.7, antialias()),
    )
        .prop_map(|(p, r, a)| aa_scene_of(p, r, a))
}

pub fn total(areas: &[RBig]) -> RBig {
    areas.iter().fold(RBig::ZERO, |sum, a| sum + a)
}

fn map_polygons(scene: &Scene, f: impl Fn(&mut Polygon)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        if let Primitive::Polygon(q) = p {
            f(q);
        }
    }
    scene
}

/// Each contour of `p` rotated left by `k` (mod its length), or reversed.
fn per_contour(p: &mut Polygon, f: impl Fn(&mut [Vertex])) {
    let mut start = 0;
    for &end in &p.contour_ends {
        f(&mut p.vertices[start..end]);
        start = end;
    }
}

/// Asserts sample (x, y, s) of `a` equals sample (x + dx, y + dy, s) of `b`
/// (coverage and owner) wherever both are on the canvas.
fn assert_mask_shifted(
    a: &Frame,
    b: &Frame,
    dx: i64,
    dy: i64,
    who: &str,
) -> Result<(), TestCaseError> {
    let (w, h, n) = (i64::from(a.width), i64::from(a.height), a.samples as usize);
    for y in 0..h {
        for x in 0..w {
            let (u, v) = (x + dx, y + dy);
            if !(0..w).contains(&u) || !(0..h).contains(&v) {
                continue;
            }
            let (i, j) = ((y * w + x) as usize * n, (v * w + u) as usize * n);
            prop_assert_eq!(
                &a.coverage[i..i + n],
                &b.coverage[j..j + n],
                "{} mask at ({}, {})",
                who,
                x,
                y
            );
            prop_assert_eq!(
                &a.last[i..i + n],
                &b.last[j..j + n],
                "{} owners at ({}, {})",
                who,
                x,
                y
            );
        }
    }
    Ok(())
}

/// Production's mask equals the reference's, sample for sample.
fn assert_production_equals_reference(scene: &Scene) -> Result<(), TestCaseError> {
    let plan = Plan::for_scene(scene);
    let reference = reference::render(scene, &plan);
    if let Some(frame) = production(scene, &plan)? {
        prop_assert_eq!(frame.samples, reference.samples);
        prop_assert!(frame.coverage == reference.coverage, "coverage differs");
        prop_assert!(frame.last == reference.last, "owners differ");
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(96))]

    /// The exact per-pixel areas of primitives inside the canvas sum to
    /// their whole areas, computed without pixels (a rational equality):
    /// triangles, parallelogram lines, and polygons simple,
    /// self-intersecting and with holes, under both fills.
    #[test]
    fn exact_areas_sum_to_the_primitive_areas(scene in inside_scene()) {
        let whole = (0..scene.primitives.len())
            .fold(RBig::ZERO, |sum, i| sum + reference::primitive_area(&scene, i));
        prop_assert_eq!(total(&reference::exact_areas(&scene)), whole);
    }

    /// Moving every vertex by whole pixels moves the antialiased mask and
    /// the exact areas exactly, in the reference and in production. (With
    /// 0 subpixel bits the shift is even: snapping ties go to even.)
    #[test]
    fn whole_pixel_translation_shifts_masks_and_areas_exactly(
        scene in inside_scene(),
        dx in -6i64..7,
        dy in -6i64..7,
    ) {
        let (dx, dy) = if scene.rules.subpixel_bits == Some(0) { (dx / 2 * 2, dy / 2 * 2) } else { (dx, dy) };
        let moved = map_vertices(&scene, |v| {
            v.x = &v.x + &Number::from_int(dx);
            v.y = &v.y + &Number::from_int(dy);
        });
        let plan = Plan::for_scene(&scene);
        assert_mask_shifted(&reference::render(&scene, &plan), &reference::render(&moved, &plan), dx, dy, "reference")?;
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&moved, &plan)?) {
            assert_mask_shifted(&a, &b, dx, dy, "production")?;
        }
        let (a, b) = (reference::exact_areas(&scene), reference::exact_areas(&moved));
        let w = i64::from(ASIZE);
        for y in 0..w {
            for x in 0..w {
                let (u, v) = (x + dx, y + dy);
                if (0..w).contains(&u) && (0..w).contains(&v) {
                    prop_assert_eq!(&a[(y * w + x) as usize], &b[(v * w + u) as usize], "area at ({}, {})", x, y);
                }
            }
        }
    }

    /// Rotating each contour's vertex order changes nothing; reversing every
    /// contour changes nothing under either fill (the winding number only
    /// changes sign); reversing one contour changes nothing under even-odd
    /// (its parity is unchanged). Masks, owners and exact areas, in the
    /// reference and in production.
    #[test]
    fn contour_order_and_direction_change_nothing(
        scene in inside_scene(),
        k in 1usize..8,
        which in 0usize..3,
    ) {
        let rotated = map_polygons(&scene, |p| per_contour(p, |c| { let n = c.len(); c.rotate_left(k % n) }));
        let reversed = map_polygons(&scene, |p| per_contour(p, |c| c.reverse()));
        let one_reversed = map_polygons(&scene, |p| {
            if p.fill == PolygonFill::EvenOdd {
                let c = which % p.contour_ends.len();
                let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
                p.vertices[start..p.contour_ends[c]].reverse();
            }
        });
        let plan = Plan::for_scene(&scene);
        let frame = reference::render(&scene, &plan);
        let areas = reference::exact_areas(&scene);
        let produced = production(&scene, &plan)?;
        for (what, other) in [("rotated", &rotated), ("reversed", &reversed), ("one contour reversed", &one_reversed)] {
            let f = reference::render(other, &plan);
            prop_assert!(f.coverage == frame.coverage && f.last == frame.last, "reference mask, {}", what);
            prop_assert!(reference::exact_areas(other) == areas, "exact areas, {}", what);
            if let (Some(a), Some(b)) = (&produced, production(other, &plan)?) {
                prop_assert!(a.coverage == b.coverage && a.last == b.last, "production mask, {}", what);
            }
        }
    }

    /// Production equals the reference sample for sample on polygons (and
    /// triangles and parallelogram lines beside them) with tie-forcing and
    /// free vertices anywhere in the coordinate range, with and without
    /// antialiasing (every pattern, adaptive or not).
    #[test]
    fn production_equals_the_reference_on_polygons_and_antialiasing(scene in anywhere_scene()) {
        assert_production_equals_reference(&scene)?;
    }
}
