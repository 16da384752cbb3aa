//! Polygons (SPEC.md §14.1 and §14.2): production's scanline fill against
//! the reference, sample for sample (counts and owners), on random stars, concave, self-intersecting and multi-contour
//! polygons with vertices on pixel centres and half-integers, under all four
//! tie rules and both fills, with and without antialiasing; the convex and
//! tessellating methods where they apply; the flood-fill foil departing on a
//! sliver; and a wrong tie caught.
//!
//! The reference is itself checked against a brute force written here,
//! which decides each sample from scratch as SPEC.md words it (the nudged
//! ray to +x, one exact i128 sign per edge), sharing no code with either.

use dashu_int::ops::BitTest;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::fixed::Format;
use rastercheck::production::polygon::{self, scanline};
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, Number, Pattern, Polygon,
    PolygonFill, Primitive, Rules, Scene, Triangle, Vertex,
};

const SIZE: u32 = 24;

/// Subpixel bits of the random scenes: vertices on the 1/16 grid.
const BITS: u32 = 4;

/// A polygon's contours, in units of 2^-BITS pixel.
type Contours = Vec<Vec<[i64; 2]>>;

struct Rng(SplitMix64);

impl Rng {
    fn new(seed: u64) -> Rng {
        Rng(SplitMix64::new(seed))
    }

    /// Uniform in [lo, hi).
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.0.next_u64() % (hi - lo) as u64) as i64
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.range(0, items.len() as i64) as usize]
    }
}

/// A coordinate in 1/16 pixel, from −4 to SIZE + 4 px: on the half-pixel
/// grid (pixel centres and edges: ties), or anywhere on the 1/16 grid.
fn coordinate(rng: &mut Rng, halves: bool) -> i64 {
    let lo = -4 * 16;
    let hi = (i64::from(SIZE) + 4) * 16;
    if halves {
        rng.range(lo / 8, hi / 8) * 8
    } else {
        rng.range(lo, hi)
    }
}

/// Rounds to the half-pixel grid when `halves`.
fn grid(v: i64, halves: bool) -> i64 {
    if halves {
        (v as f64 / 8.0).round() as i64 * 8
    } else {
        v
    }
}

/// A star: 2k points alternating between two radii around a centre.
fn star(rng: &mut Rng, halves: bool) -> Contours {
    let k = rng.range(3, 12);
    let c = [rng.range(4, 20) * 16, rng.range(4, 20) * 16];
    let outer = rng.range(4 * 16, 16 * 16) as f64;
    let inner = outer * rng.range(15, 70) as f64 / 100.0;
    let turn = rng.range(0, 1000) as f64 / 1000.0;
    let contour = (0..2 * k)
        .map(|i| {
            let r = if i % 2 == 0 { outer } else { inner };
            let a = (i as f64 / (2 * k) as f64 + turn) * std::f64::consts::TAU;
            [
                grid(c[0] + (r * a.cos()) as i64, halves),
                grid(c[1] + (r * a.sin()) as i64, halves),
            ]
        })
        .collect();
    vec![contour]
}

/// A concave polygon: random radii at sorted random angles (star-shaped).
fn concave(rng: &mut Rng, halves: bool) -> Contours {
    let n = rng.range(4, 16);
    let c = [rng.range(6, 18) * 16, rng.range(6, 18) * 16];
    let mut angles: Vec<f64> = (0..n)
        .map(|_| rng.range(0, 10000) as f64 / 10000.0 * std::f64::consts::TAU)
        .collect();
    angles.sort_by(f64::total_cmp);
    let contour = angles
        .iter()
        .map(|a| {
            let r = rng.range(16, 14 * 16) as f64;
            [
                grid(c[0] + (r * a.cos()) as i64, halves),
                grid(c[1] + (r * a.sin()) as i64, halves),
            ]
        })
        .collect();
    vec![contour]
}

/// Any vertices at all: self-intersecting.
fn tangle(rng: &mut Rng, halves: bool) -> Contours {
    let n = rng.range(3, 12);
    vec![(0..n)
        .map(|_| [coordinate(rng, halves), coordinate(rng, halves)])
        .collect()]
}

/// Several contours: an outer one with holes, either direction, some
/// crossing each other.
fn holes(rng: &mut Rng, halves: bool) -> Contours {
    let mut contours = concave(rng, halves);
    for _ in 0..rng.range(1, 4) {
        let mut inner = match rng.range(0, 3) {
            0 => star(rng, halves),
            1 => concave(rng, halves),
            _ => tangle(rng, halves),
        }
        .remove(0);
        if rng.range(0, 2) == 0 {
            inner.reverse();
        }
        contours.push(inner);
    }
    contours
}

fn number(units: i64, bits: u32) -> Number {
    Number::ratio(units, 1 << bits)
}

fn polygon_of(contours: &Contours, bits: u32, fill: PolygonFill) -> Polygon {
    let mut vertices = Vec::new();
    let mut contour_ends = Vec::new();
    for c in contours {
        vertices.extend(
            c.iter()
                .map(|p| Vertex::at(number(p[0], bits), number(p[1], bits))),
        );
        contour_ends.push(vertices.len());
    }
    Polygon {
        vertices,
        contour_ends,
        fill,
    }
}

fn scene_of(
    polygons: Vec<Polygon>,
    rule: FillRule,
    antialias: Option<Antialias>,
    subpixel_bits: Option<u32>,
) -> Scene {
    Scene {
        name: "random polygons".to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: SIZE,
            height: SIZE,
        },
        rules: Rules {
            subpixel_bits,
            fill_rule: rule,
            cull: Cull::None,
        },
        primitives: polygons.into_iter().map(Primitive::Polygon).collect(),
        effects: Effects {
            antialias,
            motion_blur: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
    }
}

/// The exact frame, from scratch: each sample's winding number along the
/// ray to +x from the sample nudged as the rule says (SPEC.md §14.1).
/// Vertices are exact multiples of 2^-bits and sample offsets multiples of
/// 2^-position_bits; both go to one integer grid of 2^-k pixel.
fn brute_force(scene: &Scene, plan: &Plan) -> Frame {
    let (offsets, position_bits) = match &plan.antialias {
        Some(s) => (s.offsets.clone(), s.position_bits),
        None => (vec![[1, 1]], 1),
    };
    let polygons: Vec<(&Polygon, usize)> = scene
        .primitives
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match p {
            Primitive::Polygon(p) => Some((p, i)),
            _ => None,
        })
        .collect();
    // Every vertex is an exact dyadic; k fraction bits hold them all.
    let k = scene
        .vertices()
        .flat_map(|v| [&v.x, &v.y])
        .map(|n| n.denominator().bit_len() as u32 - 1)
        .chain([position_bits])
        .max()
        .unwrap();
    let units = |n: &Number| -> i128 {
        let scaled = n.numerator() << k as usize;
        (&(scaled / dashu_int::IBig::from(n.denominator().clone())))
            .try_into()
            .unwrap()
    };
    let (right, down) = match scene.rules.fill_rule {
        FillRule::TopLeft => (true, true),
        FillRule::TopRight => (false, true),
        FillRule::BottomLeft => (true, false),
        FillRule::BottomRight => (false, false),
        FillRule::AllEdges => unreachable!(),
    };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (polygon, index) in polygons {
        let edges: Vec<([i128; 2], [i128; 2])> = polygon
            .edges()
            .map(|(a, b)| ([units(&a.x), units(&a.y)], [units(&b.x), units(&b.y)]))
            .collect();
        for y in 0..scene.canvas.height {
            for x in 0..scene.canvas.width {
                for (s, o) in offsets.iter().enumerate() {
                    let shift = k - position_bits;
                    let px = (i128::from(x) << k) + (i128::from(o[0]) << shift);
                    let py = (i128::from(y) << k) + (i128::from(o[1]) << shift);
                    let mut winding = 0;
                    for &(a, b) in &edges {
                        if a[1] == b[1] {
                            continue;
                        }
                        let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
                        let active = if down {
                            lo <= py && py < hi
                        } else {
                            lo < py && py <= hi
                        };
                        if !active {
                            continue;
                        }
                        // sign(x_c − px) = sign(num) · sign(dy).
                        let dy = b[1] - a[1];
                        let num = (a[0] - px) * dy + (py - a[1]) * (b[0] - a[0]);
                        let sign = num.signum() * dy.signum();
                        let counts = if right { sign > 0 } else { sign >= 0 };
                        if counts {
                            winding += dy.signum();
                        }
                    }
                    let inside = match polygon.fill {
                        PolygonFill::EvenOdd => winding % 2 != 0,
                        PolygonFill::NonZero => winding != 0,
                    };
                    if inside {
                        let i = frame.index(x, y) + s;
                        frame.hit(i, index);
                    }
                }
            }
        }
    }
    frame
}

/// The reference's frame, checked against the brute force: two exact
/// deciders that share no code must agree before either judges production.
fn exact(scene: &Scene, plan: &Plan) -> Frame {
    let frame = reference::render(scene, plan);
    let wrong = differences(&brute_force(scene, plan), &frame);
    assert_eq!(wrong, 0, "the reference and the brute force disagree");
    frame
}

/// Samples whose count or owner differs.
fn differences(expected: &Frame, actual: &Frame) -> usize {
    assert_eq!(expected.coverage.len(), actual.coverage.len());
    (0..expected.coverage.len())
        .filter(|&i| {
            expected.coverage[i] != actual.coverage[i] || expected.last[i] != actual.last[i]
        })
        .count()
}

fn assert_same(expected: &Frame, actual: &Frame, what: &str) {
    let wrong = differences(expected, actual);
    assert!(
        wrong == 0,
        "{what}: {wrong} samples differ from the reference"
    );
}

/// Production's polygon fill called directly into a frame of the plan's
/// samples, in a format `extra_bits` finer than the samples need.
fn draw_direct(scene: &Scene, plan: &Plan, extra_bits: u32) -> Result<Frame, RasterError> {
    let bits = scene.rules.subpixel_bits.unwrap_or(BITS);
    let frac_bits = plan
        .antialias
        .as_ref()
        .map_or(bits + 1, |s| s.position_bits.max(bits + 1))
        + extra_bits;
    let format = Format { frac_bits };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (index, p) in scene.primitives.iter().enumerate() {
        if let Primitive::Polygon(p) = p {
            if format.fits_i64() {
                polygon::draw::<i64>(scene, plan, format, index, p, &mut frame)?;
            } else {
                polygon::draw::<i128>(scene, plan, format, index, p, &mut frame)?;
            }
        }
    }
    Ok(frame)
}

type Generator = fn(&mut Rng, bool) -> Contours;

const SHAPES: [(&str, Generator); 4] = [
    ("star", star),
    ("concave", concave),
    ("self-intersecting", tangle),
    ("holes", holes),
];

fn random_scene(rng: &mut Rng, antialias: Option<Antialias>) -> Scene {
    let halves = rng.range(0, 2) == 0;
    let count = rng.range(1, 3);
    let polygons = (0..count)
        .map(|_| {
            let (_, shape) = rng.pick(&SHAPES);
            let fill = rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]);
            polygon_of(&shape(rng, halves), BITS, fill)
        })
        .collect();
    let rule = rng.pick(&FillRule::CONSISTENT);
    scene_of(polygons, rule, antialias, Some(BITS))
}

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

fn antialias(samples: u32, pattern: Pattern, seed: u64, position_bits: u32) -> Antialias {
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

fn method(name: &str) -> Box<dyn Rasterizer> {
    let m = polygon::methods()
        .into_iter()
        .find(|m| m.name == name)
        .unwrap_or_else(|| panic!("no method {name}"));
    (m.make)()
}

/// The convex hull of points (Andrew's monotone chain), exact.
fn hull(mut points: Vec<[i64; 2]>) -> Vec<[i64; 2]> {
    points.sort();
    points.dedup();
    let cross = |o: [i64; 2], a: [i64; 2], b: [i64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut lower: Vec<[i64; 2]> = Vec::new();
    for &p in &points {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<[i64; 2]> = Vec::new();
    for &p in points.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

#[test]
fn convex_fill_agrees_where_it_applies() {
    let convex = method("polygon-convex");
    assert!(convex.capabilities().polygons && !convex.is_foil());
    let mut rng = Rng::new(5);
    let mut drawn = 0;
    for case in 0..200 {
        let halves = case % 2 == 0;
        let points = (0..rng.range(3, 12))
            .map(|_| [coordinate(&mut rng, halves), coordinate(&mut rng, halves)])
            .collect();
        let mut contour = hull(points);
        if contour.len() < 3 {
            continue;
        }
        // Either direction, any starting vertex, and a straight vertex
        // (an edge's midpoint) now and then.
        let start = rng.range(0, contour.len() as i64) as usize;
        contour.rotate_left(start);
        if rng.range(0, 2) == 0 {
            contour.reverse();
        }
        let (a, b) = (contour[0], contour[1]);
        if (a[0] + b[0]) % 2 == 0 && (a[1] + b[1]) % 2 == 0 && case % 3 == 0 {
            contour.insert(1, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]);
        }
        let fill = rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]);
        let rule = rng.pick(&FillRule::CONSISTENT);
        let scene = scene_of(
            vec![polygon_of(&vec![contour], BITS, fill)],
            rule,
            None,
            Some(BITS),
        );
        let plan = Plan::for_scene(&scene);
        let expected = exact(&scene, &plan);
        let actual = convex.rasterize(&scene, &plan).unwrap();
        assert_same(&expected, &actual, &format!("convex case {case}"));
        drawn += 1;
    }
    assert!(drawn > 150);
}

#[test]
fn convex_fill_refuses_what_is_not_convex() {
    let convex = method("polygon-convex");
    let at = |p: &[[i64; 2]]| p.iter().map(|q| q.map(|v| v * 16)).collect::<Vec<_>>();
    let refused = [
        // A pentagram turns the same way at every vertex, twice around.
        vec![at(&[[10, 1], [16, 19], [1, 8], [19, 8], [4, 19]])],
        // Concave: an arrowhead.
        vec![at(&[[2, 2], [20, 10], [2, 18], [8, 10]])],
        // A spike back along an edge.
        vec![at(&[[2, 2], [12, 2], [6, 2], [6, 12]])],
        // Two contours, each convex.
        vec![
            at(&[[1, 1], [5, 1], [5, 5]]),
            at(&[[10, 10], [15, 10], [15, 15]]),
        ],
    ];
    for contours in refused {
        let scene = scene_of(
            vec![polygon_of(&contours, BITS, PolygonFill::NonZero)],
            FillRule::TopLeft,
            None,
            Some(BITS),
        );
        let plan = Plan::for_scene(&scene);
        assert!(
            matches!(
                convex.rasterize(&scene, &plan),
                Err(RasterError::Unsupported(_))
            ),
            "{contours:?}"
        );
    }
}

/// Whether a closed contour is simple, decided here by brute force: no two
/// non-adjacent edges share a point, and adjacent ones only their vertex.
fn simple(points: &[[i64; 2]]) -> bool {
    let n = points.len();
    let orient = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum()
    };
    let on = |a: [i64; 2], b: [i64; 2], p: [i64; 2]| {
        orient(a, b, p) == 0
            && a[0].min(b[0]) <= p[0]
            && p[0] <= a[0].max(b[0])
            && a[1].min(b[1]) <= p[1]
            && p[1] <= a[1].max(b[1])
    };
    let meet = |a, b, c, d| {
        let (o1, o2, o3, o4) = (
            orient(a, b, c),
            orient(a, b, d),
            orient(c, d, a),
            orient(c, d, b),
        );
        (o1 * o2 < 0 && o3 * o4 < 0) || on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b)
    };
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = (points[i], points[(i + 1) % n]);
            let (c, d) = (points[j], points[(j + 1) % n]);
            if a == b || c == d {
                return false;
            }
            if j == i + 1 || (i == 0 && j == n - 1) {
                // Sharing one vertex: only a fold back along the line overlaps.
                let (shared, p, q) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                if orient(shared, p, q) == 0 && on(shared, p, q) || on(shared, q, p) {
                    return false;
                }
            } else if meet(a, b, c, d) {
                return false;
            }
        }
    }
    true
}

#[test]
fn tessellation_agrees_where_it_applies() {
    let tessellate = method("polygon-tessellate");
    let mut rng = Rng::new(6);
    let (mut drawn, mut refused) = (0, 0);
    for case in 0..300 {
        let halves = case % 2 == 0;
        let contours = match case % 3 {
            0 => star(&mut rng, halves),
            1 => concave(&mut rng, halves),
            _ => tangle(&mut rng, halves),
        };
        let fill = rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]);
        let rule = rng.pick(&FillRule::CONSISTENT);
        let scene = scene_of(
            vec![polygon_of(&contours, BITS, fill)],
            rule,
            None,
            Some(BITS),
        );
        let plan = Plan::for_scene(&scene);
        match tessellate.rasterize(&scene, &plan) {
            Ok(actual) => {
                assert!(simple(&contours[0]), "case {case} is drawn, yet not simple");
                let expected = exact(&scene, &plan);
                assert_same(&expected, &actual, &format!("tessellated case {case}"));
                drawn += 1;
            }
            Err(RasterError::Unsupported(_)) => {
                assert!(!simple(&contours[0]), "case {case} is simple, yet refused");
                refused += 1;
            }
            Err(e) => panic!("case {case}: {e}"),
        }
    }
    assert!(
        drawn > 150 && refused > 30,
        "drawn {drawn}, refused {refused}"
    );
}

#[test]
fn methods_refuse_other_primitives_and_antialiasing() {
    let mut scene = scene_of(
        vec![polygon_of(
            &star(&mut Rng::new(7), true),
            BITS,
            PolygonFill::NonZero,
        )],
        FillRule::TopLeft,
        None,
        Some(BITS),
    );
    let triangle = rastercheck::scene::Triangle {
        vertices: [[0, 0], [16, 0], [0, 16]]
            .map(|p| Vertex::at(Number::from_int(p[0]), Number::from_int(p[1]))),
        interpolation: rastercheck::scene::Interpolation::Linear,
    };
    let aa = scene_of(
        scene
            .primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Polygon(p) => Some(p.clone()),
                _ => None,
            })
            .collect(),
        FillRule::TopLeft,
        Some(antialias(4, Pattern::Standard, 0, 8)),
        Some(BITS),
    );
    scene.primitives.push(Primitive::Triangle(triangle));
    for m in polygon::methods() {
        let r = (m.make)();
        assert!(
            !r.capabilities().antialias && r.capabilities().polygons,
            "{}",
            m.name
        );
        let plan = Plan::for_scene(&scene);
        assert!(
            matches!(r.rasterize(&scene, &plan), Err(RasterError::Unsupported(_))),
            "{}",
            m.name
        );
        assert!(r.capabilities().refuses(&aa).is_some(), "{}", m.name);
    }
}

#[test]
fn flood_fill_departs_on_a_sliver() {
    let flood = method("flood-fill");
    assert!(flood.is_foil());
    // A sliver 1/4 px high along row 3, between the sample rows: the exact
    // rule covers no sample, the outline covers every pixel it runs through.
    let sliver = vec![vec![
        [16, 3 * 16 + 2],
        [20 * 16, 3 * 16 + 4],
        [16, 3 * 16 + 6],
    ]];
    let scene = scene_of(
        vec![polygon_of(&sliver, BITS, PolygonFill::NonZero)],
        FillRule::TopLeft,
        None,
        Some(BITS),
    );
    let plan = Plan::for_scene(&scene);
    let expected = exact(&scene, &plan);
    let actual = flood.rasterize(&scene, &plan).unwrap();
    assert_eq!(expected.covered_samples(), 0);
    assert!(
        differences(&expected, &actual) >= 19,
        "{}",
        differences(&expected, &actual)
    );
    // On a large square it is right away from the edges: it is a fill, not
    // noise.
    let square = vec![vec![
        [2 * 16 + 8, 2 * 16 + 8],
        [20 * 16, 2 * 16 + 8],
        [20 * 16, 20 * 16],
        [2 * 16 + 8, 20 * 16],
    ]];
    let scene = scene_of(
        vec![polygon_of(&square, BITS, PolygonFill::NonZero)],
        FillRule::TopLeft,
        None,
        Some(BITS),
    );
    let expected = exact(&scene, &plan);
    let actual = flood.rasterize(&scene, &plan).unwrap();
    assert_eq!(expected.covered_samples(), 18 * 18);
    let wrong = differences(&expected, &actual);
    assert!(wrong > 0 && wrong < 4 * 19, "{wrong}");
    // Concave stars: seeds only deep inside, so the fill stays within the
    // outline and departs along it, never over the whole canvas.
    let mut rng = Rng::new(8);
    for case in 0..20 {
        let scene = scene_of(
            vec![polygon_of(
                &star(&mut rng, false),
                BITS,
                PolygonFill::NonZero,
            )],
            FillRule::TopLeft,
            None,
            Some(BITS),
        );
        let expected = exact(&scene, &plan);
        let actual = flood.rasterize(&scene, &plan).unwrap();
        let wrong = differences(&expected, &actual);
        assert!(
            wrong > 0 && wrong < (SIZE * SIZE / 3) as usize,
            "star {case}: {wrong} of {} samples",
            expected.covered_samples()
        );
    }
}

#[test]
fn a_wrong_tie_is_caught() {
    // A square with its left and top edges through sample centres (x = 2.5,
    // y = 2.5): the tie rule decides a whole column and a whole row.
    let square = vec![vec![[40, 40], [200, 40], [200, 200], [40, 200]]];
    let scene = scene_of(
        vec![polygon_of(&square, BITS, PolygonFill::NonZero)],
        FillRule::TopLeft,
        None,
        Some(BITS),
    );
    let plan = Plan::for_scene(&scene);
    let expected = exact(&scene, &plan);
    assert_same(
        &expected,
        &Production.rasterize(&scene, &plan).unwrap(),
        "production",
    );
    // The scanline with x_c < x in place of x_c ≤ x (the nudge left), and
    // with the rows half-open the other way (the nudge up).
    let contours: Vec<Vec<[i64; 2]>> = square
        .iter()
        .map(|c| c.iter().map(|p| p.map(|v| v * 2)).collect())
        .collect();
    for (right, down) in [(false, true), (true, false)] {
        let mut frame = Frame::for_plan(SIZE, SIZE, &plan);
        let samples = scanline::Samples {
            one: 32,
            offset: [16, 16],
            slot: 0,
            nudge: scanline::Nudge { right, down },
        };
        scanline::fill(
            &contours,
            PolygonFill::NonZero,
            &samples,
            scene.canvas,
            &mut frame,
            0,
        );
        // A column (or row) of 10 samples lost, and one of 10 gained.
        assert_eq!(
            differences(&expected, &frame),
            20,
            "right {right}, down {down}"
        );
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
