//! The other polygon methods: convex fill and tessellation where they
//! apply and refuse elsewhere, the flood-fill foil departing on a sliver,
//! and a wrong tie caught.

use crate::scanline::antialias;
use crate::shapes::{
    assert_same, concave, coordinate, differences, exact, polygon_of, scene_of, star, tangle, Rng,
    BITS, SIZE,
};
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::polygon::{self, scanline};
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::scene::{FillRule, Number, Pattern, PolygonFill, Primitive, Vertex};

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
