//! The exact reference on polygons and antialiased scenes (SPEC.md §14):
//! the area self-check as an equality of rationals, polygon coverage
//! against triangulations under every consistent rule, the standard sample
//! positions, and the i128 path against the big-integer path. Each check is
//! also shown failing on a deliberately wrong variant.

use dashu_ratio::RBig;
use rastercheck::plan::Plan;
use rastercheck::reference::exact::snap;
use rastercheck::reference::{self, Arithmetic};
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{parse_case, FillRule, Limits, Number, Scene};

fn number(q: &RBig) -> Number {
    Number::from_string(&format!("{}/{}", q.numerator(), q.denominator())).unwrap()
}

/// A scene from its parts, as a case file would give them.
fn scene(size: u32, rules: &str, primitives: &[String], effects: &str) -> Scene {
    let json = format!(
        r#"{{"name": "t", "canvas": {{"width": {size}, "height": {size}}},
            "rules": {rules}, "primitives": [{}], "effects": {effects}}}"#,
        primitives.join(", ")
    );
    parse_case(&json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
}

fn rule(name: &str, bits: &str) -> String {
    format!(r#"{{"subpixel_bits": {bits}, "fill_rule": "{name}"}}"#)
}

fn antialias(samples: u32, pattern: &str) -> String {
    format!(r#"{{"antialias": {{"samples": {samples}, "pattern": "{pattern}"}}}}"#)
}

fn points(ps: &[(String, String)]) -> String {
    let items: Vec<String> = ps
        .iter()
        .map(|(x, y)| format!(r#"["{x}", "{y}"]"#))
        .collect();
    format!("[{}]", items.join(", "))
}

fn triangle(ps: &[(String, String)]) -> String {
    format!(r#"{{"triangle": {}}}"#, points(ps))
}

fn polygon(contours: &[&[(String, String)]], fill: &str) -> String {
    let cs: Vec<String> = contours.iter().map(|c| points(c)).collect();
    format!(r#"{{"contours": [{}], "fill": "{fill}"}}"#, cs.join(", "))
}

/// A vertex as exact strings.
type At = (String, String);

fn p(x: &str, y: &str) -> (String, String) {
    (x.to_owned(), y.to_owned())
}

/// Points written "x y, x y, …", each as `p` makes it.
fn parse_points(text: &str) -> Vec<At> {
    text.split(',')
        .map(|xy| {
            let (x, y) = xy.trim().split_once(' ').expect("x y");
            p(x, y)
        })
        .collect()
}

fn pi(x: i64, y: i64) -> (String, String) {
    (x.to_string(), y.to_string())
}

fn total(areas: &[RBig]) -> RBig {
    areas.iter().fold(RBig::ZERO, |sum, a| sum + a)
}

/// The self-check: the per-pixel areas sum to the primitives' whole areas.
fn assert_self_check(s: &Scene) -> RBig {
    let whole =
        (0..s.primitives.len()).fold(RBig::ZERO, |sum, i| sum + reference::primitive_area(s, i));
    assert_eq!(total(&reference::exact_areas(s)), whole);
    whole
}

/// A random coordinate in [lo, hi): a multiple of 1/den.
fn coordinate(rng: &mut SplitMix64, lo: i64, hi: i64, den: i64) -> String {
    let span = ((hi - lo) * den) as u64;
    format!("{}/{den}", lo * den + (rng.next_u64() % span) as i64)
}

#[test]
fn random_triangles_and_parallelograms_pass_the_self_check() {
    let mut rng = SplitMix64::new(11);
    for round in 0..40 {
        let bits = ["8", "null", "2", "null"][round % 4];
        let den = [1000, 7, 3, 4096][round % 4];
        let mut prims = Vec::new();
        for _ in 0..3 {
            let v: Vec<(String, String)> = (0..3)
                .map(|_| {
                    (
                        coordinate(&mut rng, 0, 12, den),
                        coordinate(&mut rng, 0, 12, den),
                    )
                })
                .collect();
            prims.push(triangle(&v));
        }
        // A parallelogram inside the canvas: ends at least width/2 from it.
        let (x0, y0, x1, y1) = (
            coordinate(&mut rng, 2, 10, den),
            coordinate(&mut rng, 2, 10, den),
            coordinate(&mut rng, 2, 10, den),
            coordinate(&mut rng, 2, 10, den),
        );
        prims.push(format!(
            r#"{{"line": [["{x0}", "{y0}"], ["{x1}", "{y1}"]], "rule": "parallelogram", "width": "{}"}}"#,
            coordinate(&mut rng, 1, 4, den)
        ));
        let s = scene(
            12,
            &rule("top-left", bits),
            &prims,
            &antialias(4, "standard"),
        );
        let whole = assert_self_check(&s);
        assert!(whole > RBig::ZERO || round % 4 == 2);
    }
}

#[test]
fn areas_are_clipped_to_the_canvas_and_culling_removes_area() {
    let s = scene(
        4,
        &rule("top-left", "8"),
        &[triangle(&[pi(-2, 0), pi(2, 0), pi(-2, 4)])],
        &antialias(1, "standard"),
    );
    // The triangle is x + y ≤ 2 over x ≥ −2, y ≥ 0: inside x ≥ 0 it is the
    // triangle (0,0), (2,0), (0,2), of area 2.
    assert_eq!(total(&reference::exact_areas(&s)), RBig::from(2u8));
    assert_eq!(reference::primitive_area(&s, 0), RBig::from(8u8));
    // Culled (clockwise on screen: (−2,0)→(2,0)→(−2,4) turns right).
    let culled = scene(
        4,
        r#"{"cull": "cw"}"#,
        &[triangle(&[pi(-2, 0), pi(2, 0), pi(-2, 4)])],
        &antialias(1, "standard"),
    );
    assert_eq!(total(&reference::exact_areas(&culled)), RBig::ZERO);
    assert_eq!(reference::primitive_area(&culled, 0), RBig::ZERO);
}

/// Sutherland–Hodgman: a convex polygon clipped to the half-plane where
/// `inside` holds, `cut(a, b)` giving where an edge crosses its border.
fn clip(
    poly: &[[RBig; 2]],
    inside: impl Fn(&[RBig; 2]) -> bool,
    cut: impl Fn(&[RBig; 2], &[RBig; 2]) -> [RBig; 2],
) -> Vec<[RBig; 2]> {
    let mut out = Vec::new();
    for (i, a) in poly.iter().enumerate() {
        let b = &poly[(i + 1) % poly.len()];
        match (inside(a), inside(b)) {
            (true, true) => out.push(b.clone()),
            (true, false) => out.push(cut(a, b)),
            (false, true) => {
                out.push(cut(a, b));
                out.push(b.clone());
            }
            (false, false) => {}
        }
    }
    out
}

/// The area of a convex polygon inside the pixel square at (x, y), by
/// clipping it to the square's four sides and the shoelace formula.
fn clipped_area(poly: &[[RBig; 2]], x: i64, y: i64) -> RBig {
    let mut p = poly.to_vec();
    for (axis, bound, keep_below) in [
        (0, x, false),
        (0, x + 1, true),
        (1, y, false),
        (1, y + 1, true),
    ] {
        let c = RBig::from(bound);
        let inside = |q: &[RBig; 2]| {
            if keep_below {
                q[axis] <= c
            } else {
                q[axis] >= c
            }
        };
        let cut = |a: &[RBig; 2], b: &[RBig; 2]| {
            let t = (&c - &a[axis]) / (&b[axis] - &a[axis]);
            [&a[0] + &t * (&b[0] - &a[0]), &a[1] + &t * (&b[1] - &a[1])]
        };
        p = clip(&p, inside, cut);
        if p.is_empty() {
            return RBig::ZERO;
        }
    }
    let twice = (0..p.len()).fold(RBig::ZERO, |sum, i| {
        let (a, b) = (&p[i], &p[(i + 1) % p.len()]);
        sum + &a[0] * &b[1] - &a[1] * &b[0]
    });
    let area = twice / RBig::from(2u8);
    if area < RBig::ZERO {
        -area
    } else {
        area
    }
}

#[test]
fn per_pixel_areas_equal_convex_clipping() {
    // Triangles and parallelograms are convex: clipping each to each pixel
    // square is an independent per-pixel computation of the same areas,
    // canvas clipping included (primitives reach past every side).
    let mut rng = SplitMix64::new(29);
    let size = 7;
    for round in 0..30 {
        let den = [3, 16, 5][round % 3];
        let exact = |n: &str| Number::from_string(n).unwrap().as_rbig().clone();
        let (shape, corners): (String, Vec<[RBig; 2]>) = if round % 2 == 0 {
            let v: Vec<At> = (0..3)
                .map(|_| {
                    (
                        coordinate(&mut rng, -2, 9, den),
                        coordinate(&mut rng, -2, 9, den),
                    )
                })
                .collect();
            let corners = v.iter().map(|(x, y)| [exact(x), exact(y)]).collect();
            (triangle(&v), corners)
        } else {
            let (x0, y0, x1, y1) = (
                coordinate(&mut rng, -1, 8, den),
                coordinate(&mut rng, -1, 8, den),
                coordinate(&mut rng, -1, 8, den),
                coordinate(&mut rng, -1, 8, den),
            );
            let width = coordinate(&mut rng, 1, 3, den);
            let (a, b) = ([exact(&x0), exact(&y0)], [exact(&x1), exact(&y1)]);
            let h = exact(&width) / RBig::from(2u8);
            let abs = |q: RBig| if q < RBig::ZERO { -q } else { q };
            // SPEC §4.4: swept along the minor axis.
            let minor = usize::from(abs(&b[0] - &a[0]) >= abs(&b[1] - &a[1]));
            let moved = |p: &[RBig; 2], by: &RBig| {
                let mut q = p.clone();
                q[minor] = &q[minor] + by;
                q
            };
            let corners = vec![
                moved(&a, &-h.clone()),
                moved(&b, &-h.clone()),
                moved(&b, &h),
                moved(&a, &h),
            ];
            let line = format!(
                r#"{{"line": [["{x0}", "{y0}"], ["{x1}", "{y1}"]], "rule": "parallelogram", "width": "{width}"}}"#
            );
            (line, corners)
        };
        let s = scene(
            size,
            &rule("top-left", "null"),
            &[shape],
            &antialias(4, "standard"),
        );
        let areas = reference::exact_areas(&s);
        for (i, area) in areas.iter().enumerate() {
            let (x, y) = ((i % size as usize) as i64, (i / size as usize) as i64);
            assert_eq!(
                *area,
                clipped_area(&corners, x, y),
                "round {round}, pixel ({x}, {y})"
            );
        }
    }
}

fn rq(text: &str) -> RBig {
    Number::from_string(text).unwrap().as_rbig().clone()
}

/// Asserts that every pixel's exact area is `expected(x, y)`.
fn assert_pixels(s: &Scene, size: u32, expected: impl Fn(i64, i64) -> RBig, what: &str) {
    for (i, area) in reference::exact_areas(s).iter().enumerate() {
        let (x, y) = ((i % size as usize) as i64, (i / size as usize) as i64);
        assert_eq!(*area, expected(x, y), "{what}, pixel ({x}, {y})");
    }
}

#[test]
fn per_pixel_areas_of_holes_and_bow_ties_equal_their_convex_pieces() {
    let size = 7;
    let outer = parse_points("0.5 0.25, 6.75 0.5, 6.25 6.5, 0.25 6");
    let inner_cw = parse_points("2.25 2, 4.5 2.25, 4 4.75, 2 4.5");
    let inner_ccw: Vec<At> = inner_cw.iter().rev().cloned().collect();
    let corners =
        |ps: &[At]| -> Vec<[RBig; 2]> { ps.iter().map(|(x, y)| [rq(x), rq(y)]).collect() };
    let (o, i) = (corners(&outer), corners(&inner_cw));
    let cases: [(&[At], &str, bool); 4] = [
        (&inner_ccw, "nonzero", true),
        (&inner_ccw, "even-odd", true),
        (&inner_cw, "nonzero", false),
        (&inner_cw, "even-odd", true),
    ];
    for (hole, fill, is_hole) in cases {
        let s = scene(
            size,
            &rule("top-left", "null"),
            &[polygon(&[&outer, hole], fill)],
            &antialias(4, "standard"),
        );
        let expected = |x, y| {
            let area = clipped_area(&o, x, y);
            if is_hole {
                area - clipped_area(&i, x, y)
            } else {
                area
            }
        };
        assert_pixels(&s, size, expected, fill);
    }
    // A bow-tie A→B→C→D whose edges BC and DA cross at X: the filled
    // region is the triangles ABX and CDX under either fill.
    let bow = parse_points("0.25 0.5, 6.5 1, 0.75 6.25, 6 5.75");
    let v = corners(&bow);
    let (a, b, c, d) = (&v[0], &v[1], &v[2], &v[3]);
    let cross = |u: [RBig; 2], w: [RBig; 2]| &u[0] * &w[1] - &u[1] * &w[0];
    let sub = |u: &[RBig; 2], w: &[RBig; 2]| [&u[0] - &w[0], &u[1] - &w[1]];
    // X = b + t (c − b) on the line through d and a.
    let t = cross(sub(d, b), sub(a, d)) / cross(sub(c, b), sub(a, d));
    let x = [&b[0] + &t * (&c[0] - &b[0]), &b[1] + &t * (&c[1] - &b[1])];
    let halves = [
        vec![a.clone(), b.clone(), x.clone()],
        vec![c.clone(), d.clone(), x],
    ];
    for fill in ["nonzero", "even-odd"] {
        let s = scene(
            size,
            &rule("top-left", "null"),
            &[polygon(&[&bow], fill)],
            &antialias(4, "standard"),
        );
        let expected = |x, y| clipped_area(&halves[0], x, y) + clipped_area(&halves[1], x, y);
        assert_pixels(&s, size, expected, fill);
    }
}

/// A pentagram: the star through every second vertex of a convex pentagon
/// with integer corners.
fn pentagram(fill: &str) -> String {
    let corners = [pi(8, 1), pi(15, 6), pi(12, 15), pi(4, 15), pi(1, 6)];
    let star: Vec<(String, String)> = (0..5).map(|i| corners[(2 * i) % 5].clone()).collect();
    polygon(&[&star], fill)
}

#[test]
fn pentagram_even_odd_leaves_the_centre_empty_and_nonzero_fills_it() {
    let size = 16;
    let area = |fill: &str| {
        let s = scene(
            size,
            &rule("top-left", "8"),
            &[pentagram(fill)],
            &antialias(4, "standard"),
        );
        let whole = assert_self_check(&s);
        let centre = (8 * size + 8) as usize;
        let frame = reference::render(&s, &Plan::for_scene(&s));
        let covered = frame.coverage[centre * 4..centre * 4 + 4].to_vec();
        (whole, covered)
    };
    let (even_odd, centre_eo) = area("even-odd");
    let (nonzero, centre_nz) = area("nonzero");
    assert_eq!(centre_eo, [0, 0, 0, 0]);
    assert_eq!(centre_nz, [1, 1, 1, 1]);
    // The winding number is 1 in the star's points and 2 in its inner
    // pentagon, so the signed (shoelace) area is points + 2·inner, while
    // even-odd is points and nonzero points + inner.
    let star: [(i64, i64); 5] = [(8, 1), (12, 15), (1, 6), (15, 6), (4, 15)];
    let twice: i64 = (0..5)
        .map(|i| {
            let (a, b) = (star[i], star[(i + 1) % 5]);
            a.0 * b.1 - a.1 * b.0
        })
        .sum();
    assert_eq!(
        RBig::from(twice.abs()) / RBig::from(2u8),
        nonzero.clone() * RBig::from(2u8) - even_odd.clone()
    );
    assert!(nonzero > even_odd);
}

#[test]
fn holes_bow_ties_and_orientation() {
    let outer = [pi(0, 0), pi(9, 0), pi(9, 9), pi(0, 9)];
    let hole_opposite = [pi(3, 3), pi(3, 6), pi(6, 6), pi(6, 3)];
    let hole_same = [pi(3, 3), pi(6, 3), pi(6, 6), pi(3, 6)];
    let bow_tie = [pi(0, 0), pi(4, 0), pi(0, 4), pi(4, 4)];
    let cases: [(&[&[At]], &str, i64); 6] = [
        (&[&outer, &hole_opposite], "nonzero", 72),
        (&[&outer, &hole_opposite], "even-odd", 72),
        (&[&outer, &hole_same], "nonzero", 81),
        (&[&outer, &hole_same], "even-odd", 72),
        (&[&bow_tie], "nonzero", 8),
        (&[&bow_tie], "even-odd", 8),
    ];
    for (contours, fill, expected) in cases {
        let s = scene(
            10,
            &rule("top-left", "8"),
            &[polygon(contours, fill)],
            &antialias(4, "standard"),
        );
        assert_eq!(assert_self_check(&s), RBig::from(expected), "{fill}");
    }
    // A bow-tie off the pixel grid, self-intersecting at a rational point.
    let tilted = parse_points("0.25 0.5, 5.5 1, 0.75 4.25, 4 5.75");
    for fill in ["nonzero", "even-odd"] {
        let s = scene(
            6,
            &rule("top-left", "null"),
            &[polygon(&[&tilted], fill)],
            &antialias(4, "standard"),
        );
        assert_self_check(&s);
    }
}

#[test]
fn random_self_intersecting_polygons_pass_the_self_check() {
    let mut rng = SplitMix64::new(5);
    for round in 0..12 {
        let n = 3 + (rng.next_u64() % 7) as usize;
        let v: Vec<(String, String)> = (0..n)
            .map(|_| {
                (
                    coordinate(&mut rng, 0, 10, 8),
                    coordinate(&mut rng, 0, 10, 8),
                )
            })
            .collect();
        let fill = ["nonzero", "even-odd"][round % 2];
        let s = scene(
            10,
            &rule("top-left", "null"),
            &[polygon(&[&v], fill)],
            &antialias(4, "standard"),
        );
        assert_self_check(&s);
    }
}

/// Coverage of the scene under `rule`, one entry per sample.
fn coverage(size: u32, r: FillRule, prims: &[String], effects: &str) -> Vec<u16> {
    let s = scene(size, &rule(r.name(), "8"), prims, effects);
    reference::coverage_under(&s, &Plan::for_scene(&s), r)
}

#[test]
fn polygons_cover_what_their_triangulations_cover() {
    // Convex: a fan; simple but not convex: an arrow cut into triangles.
    // Vertices on pixel centres and half-integers, so many samples tie.
    let hexagon = [
        p("1.5", "0.5"),
        p("4.5", "0.5"),
        p("6", "3"),
        p("4.5", "5.5"),
        p("1.5", "5.5"),
        p("0.5", "3"),
    ];
    let fan: Vec<String> = (1..5)
        .map(|i| {
            triangle(&[
                hexagon[0].clone(),
                hexagon[i].clone(),
                hexagon[i + 1].clone(),
            ])
        })
        .collect();
    let arrow = [pi(1, 1), p("3.5", "3.5"), pi(6, 1), p("3.5", "6.5")];
    let arrow_triangles = vec![
        triangle(&[arrow[0].clone(), arrow[1].clone(), arrow[3].clone()]),
        triangle(&[arrow[1].clone(), arrow[2].clone(), arrow[3].clone()]),
    ];
    let shapes = [(&hexagon[..], fan), (&arrow[..], arrow_triangles)];
    // caught[i][k]: whether polygons decided with rule k's nudge differ from
    // the triangulations under rule i somewhere.
    let mut caught = [[false; 4]; 4];
    for (outline, triangles) in &shapes {
        for fill in ["nonzero", "even-odd"] {
            for (i, r) in FillRule::CONSISTENT.into_iter().enumerate() {
                for effects in [
                    "{}".to_owned(),
                    antialias(16, "standard"),
                    antialias(9, "grid"),
                ] {
                    let whole = coverage(8, r, &[polygon(&[outline], fill)], &effects);
                    let parts = coverage(8, r, triangles, &effects);
                    assert_eq!(whole, parts, "{fill}, {r:?}, {effects}");
                    assert!(parts.iter().any(|&c| c > 0));
                    // A polygon nudged the wrong way (another rule's nudge).
                    let s = scene(
                        8,
                        &rule(r.name(), "8"),
                        &[polygon(&[outline], fill)],
                        &effects,
                    );
                    for (k, wrong) in FillRule::CONSISTENT.into_iter().enumerate() {
                        caught[i][k] |=
                            reference::coverage_under(&s, &Plan::for_scene(&s), wrong) != parts;
                    }
                }
            }
        }
    }
    for (i, row) in caught.iter().enumerate() {
        for (k, &differs) in row.iter().enumerate() {
            assert_eq!(differs, i != k, "rule {i} against nudge {k}");
        }
    }
}

#[test]
fn polygons_sharing_an_edge_cover_each_sample_once() {
    // Two quadrilaterals share the slanted edge from (3.5, 0.5) to
    // (2.5, 6.5) and meet a third along y = 6.5; the union is the square
    // [0.5, 6.5]², so every sample inside it is covered exactly once.
    let left = parse_points("0.5 0.5, 3.5 0.5, 2.5 6.5, 0.5 6.5");
    let right = parse_points("3.5 0.5, 6.5 0.5, 6.5 6.5, 2.5 6.5");
    let below = parse_points("0.5 6.5, 6.5 6.5, 6.5 7.5, 0.5 7.5");
    let union = parse_points("0.5 0.5, 6.5 0.5, 6.5 7.5, 0.5 7.5");
    for r in FillRule::CONSISTENT {
        for effects in ["{}".to_owned(), antialias(16, "standard")] {
            let parts = coverage(
                8,
                r,
                &[
                    polygon(&[&left], "nonzero"),
                    polygon(&[&right], "even-odd"),
                    polygon(&[&below], "nonzero"),
                ],
                &effects,
            );
            let whole = coverage(8, r, &[polygon(&[&union], "nonzero")], &effects);
            assert_eq!(parts, whole, "{r:?} {effects}");
            assert!(parts.iter().all(|&c| c <= 1));
        }
    }
}

/// The standard 4× positions, in 1/16 pixel (Vulkan's table).
const STANDARD_4: [[i64; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];

#[test]
fn a_tiny_quad_on_a_standard_sample_covers_that_sample_only() {
    for (s, [ox, oy]) in STANDARD_4.iter().enumerate() {
        // A quad 1/32 wide centred on sample s of pixel (2, 1), as two
        // triangles sharing the diagonal through the sample.
        let (cx, cy) = (2 * 16 + ox, 16 + oy);
        let at = |dx: i64, dy: i64| (format!("{}/32", 2 * cx + dx), format!("{}/32", 2 * cy + dy));
        let quad = [
            triangle(&[at(-1, -1), at(1, -1), at(-1, 1)]),
            triangle(&[at(1, -1), at(1, 1), at(-1, 1)]),
        ];
        let sc = scene(4, &rule("top-left", "8"), &quad, &antialias(4, "standard"));
        let frame = reference::render(&sc, &Plan::for_scene(&sc));
        let pixel = 4 + 2;
        for (slot, &count) in frame.coverage.iter().enumerate() {
            let expected = u16::from(slot == pixel * 4 + s);
            assert_eq!(count, expected, "sample {s}, slot {slot}");
        }
        // A sampler with the offsets mirrored (1 − offset) misses it: the
        // same quad moved to the mirrored position is a different sample.
        let (mx, my) = (2 * 16 + 16 - ox, 16 + 16 - oy);
        let mirrored =
            |dx: i64, dy: i64| (format!("{}/32", 2 * mx + dx), format!("{}/32", 2 * my + dy));
        let moved = [
            triangle(&[mirrored(-1, -1), mirrored(1, -1), mirrored(-1, 1)]),
            triangle(&[mirrored(1, -1), mirrored(1, 1), mirrored(-1, 1)]),
        ];
        let sc = scene(4, &rule("top-left", "8"), &moved, &antialias(4, "standard"));
        let frame = reference::render(&sc, &Plan::for_scene(&sc));
        assert_eq!(frame.coverage[pixel * 4 + s], 0, "sample {s} mirrored");
    }
}

#[test]
fn antialiased_frames_hold_n_slots_and_the_rounded_exact_area() {
    let s = scene(
        6,
        &rule("top-left", "8"),
        &[
            r#"{"triangle": [{"position": [0.3, 0.2], "z": 0.5, "attributes": [1]},
                              {"position": [5.7, 1.1], "z": 0.25, "attributes": [0]},
                              {"position": [2.2, 5.9], "z": 1, "attributes": [3]}]}"#
                .to_owned(),
        ],
        &antialias(8, "standard"),
    );
    let plan = Plan::for_scene(&s);
    let frame = reference::render(&s, &plan);
    assert_eq!(frame.samples, 8);
    assert_eq!(frame.coverage.len(), 36 * 8);
    assert_eq!(
        reference::coverage_under(&s, &Plan::for_scene(&s), FillRule::TopLeft),
        frame.coverage
    );
    assert_eq!(
        reference::mesh_interior(&s, &Plan::for_scene(&s)).len(),
        36 * 8
    );
    let areas = reference::exact_areas(&s);
    let resolved = frame.resolved.as_ref().unwrap();
    for (area, &r) in areas.iter().zip(resolved) {
        assert_eq!(r, area.to_f64().value());
    }
    // Each slot's values are the pixel-centre values of the scene moved by
    // (½ − offset): checked against an unsampled render of moved vertices.
    let offsets = &plan.antialias.as_ref().unwrap().offsets;
    for (k, offset) in offsets.iter().enumerate() {
        let dx = RBig::from_parts_signed((128 - i64::from(offset[0])).into(), 256u16.into());
        let dy = RBig::from_parts_signed((128 - i64::from(offset[1])).into(), 256u16.into());
        let mut moved = s.clone();
        moved.effects.antialias = None;
        for v in moved.primitives[0].vertices_mut() {
            // Snapped positions plus a multiple of 1/256 stay on the grid.
            v.x = number(&(snap(&v.x, 8) + &dx));
            v.y = number(&(snap(&v.y, 8) + &dy));
        }
        let one = reference::render(&moved, &Plan::for_scene(&moved));
        for pixel in 0..36 {
            let slot = pixel * 8 + k;
            assert_eq!(frame.coverage[slot], one.coverage[pixel]);
            assert_eq!(frame.attributes[0][slot], one.attributes[0][pixel]);
            assert_eq!(
                frame.depth.as_ref().unwrap()[slot],
                one.depth.as_ref().unwrap()[pixel]
            );
        }
    }
}

#[test]
fn the_i128_path_equals_the_big_integer_path() {
    let mut rng = SplitMix64::new(3);
    for round in 0..8 {
        let v: Vec<(String, String)> = (0..6)
            .map(|_| {
                (
                    coordinate(&mut rng, -2, 12, 16),
                    coordinate(&mut rng, -2, 12, 16),
                )
            })
            .collect();
        let t: Vec<(String, String)> = (0..3)
            .map(|_| {
                (
                    coordinate(&mut rng, -2, 12, 3),
                    coordinate(&mut rng, -2, 12, 3),
                )
            })
            .collect();
        let bits = if round % 2 == 0 { "8" } else { "null" };
        let effects = if round % 4 < 2 {
            antialias(16, "random")
        } else {
            "{}".to_owned()
        };
        let s = scene(
            10,
            &rule(FillRule::CONSISTENT[round % 4].name(), bits),
            &[polygon(&[&v], "even-odd"), triangle(&t)],
            &effects,
        );
        let plan = Plan::for_scene(&s);
        let fast = reference::render_with(&s, &plan, Arithmetic::Auto);
        let big = reference::render_with(&s, &plan, Arithmetic::BigOnly);
        assert_eq!(fast, big);
        assert!(fast.covered_samples() > 0);
    }
}

#[test]
fn coordinates_too_big_for_i128_still_decide_polygons() {
    // Unsnapped coordinates with a huge denominator push the grid past
    // 2^60: the big-integer path runs, and agrees with a snapped twin.
    let tiny = "1/1152921504606846977"; // 1/(2^60 + 1)
    let shape = |extra: &str| {
        polygon(
            &[&[
                p("0.5", "0.5"),
                p("4.5", "0.5"),
                (extra.to_owned(), "4.5".to_owned()),
                p("0.5", "4.5"),
            ]],
            "nonzero",
        )
    };
    let exact = scene(
        6,
        &rule("top-left", "null"),
        &[shape(tiny)],
        &antialias(4, "standard"),
    );
    let near = scene(
        6,
        &rule("top-left", "null"),
        &[shape("0")],
        &antialias(4, "standard"),
    );
    let plan = Plan::for_scene(&exact);
    let big = reference::render_with(&exact, &plan, Arithmetic::Auto);
    assert_eq!(
        big,
        reference::render_with(&exact, &plan, Arithmetic::BigOnly)
    );
    // Moving one vertex by 2^-60 changes no sample here.
    let near_frame = reference::render(&near, &Plan::for_scene(&near));
    assert_eq!(big.coverage, near_frame.coverage);
}

#[test]
fn production_polygons_agree_with_the_reference_sample_by_sample() {
    // Two implementations that share no code: production's scanline fill
    // and the oracle's nudged winding numbers. Half-integer vertices put
    // many samples on edges, at vertices and at crossings.
    use rastercheck::production::Production;
    use rastercheck::rasterizer::Rasterizer;
    let mut rng = SplitMix64::new(17);
    let mut covered = 0;
    for round in 0..48 {
        let n = 3 + (rng.next_u64() % 8) as usize;
        let den = [2, 4, 256][round % 3];
        let v: Vec<At> = (0..n)
            .map(|_| {
                (
                    coordinate(&mut rng, -1, 9, den),
                    coordinate(&mut rng, -1, 9, den),
                )
            })
            .collect();
        let r = FillRule::CONSISTENT[round % 4];
        let fill = ["nonzero", "even-odd"][(round / 4) % 2];
        let effects = if round % 3 == 0 {
            "{}".to_owned()
        } else {
            antialias(16, "standard")
        };
        let s = scene(8, &rule(r.name(), "8"), &[polygon(&[&v], fill)], &effects);
        let plan = Plan::for_scene(&s);
        let want = reference::render(&s, &plan);
        let got = Production.rasterize(&s, &plan).unwrap();
        assert_eq!(
            got.coverage, want.coverage,
            "round {round}: {v:?} {fill} {r:?}"
        );
        covered += want.covered_samples();
    }
    assert!(covered > 1000, "{covered}");
}

/// Timing (release): `cargo test --release --test reference_aa timing -- --ignored --nocapture`.
#[test]
#[ignore]
fn timing_ten_triangles_on_64_by_64_with_256_samples() {
    let mut rng = SplitMix64::new(1);
    let prims: Vec<String> = (0..10)
        .map(|_| {
            let v: Vec<(String, String)> = (0..3)
                .map(|_| {
                    (
                        coordinate(&mut rng, 0, 64, 256),
                        coordinate(&mut rng, 0, 64, 256),
                    )
                })
                .collect();
            triangle(&v)
        })
        .collect();
    let with_values: Vec<String> = (0..10)
        .map(|_| {
            let v: Vec<String> = (0..3)
                .map(|k| {
                    format!(
                        r#"{{"position": ["{}", "{}"], "z": "{k}/3", "w": "{}", "attributes": [{k}]}}"#,
                        coordinate(&mut rng, 0, 64, 256),
                        coordinate(&mut rng, 0, 64, 256),
                        k + 1
                    )
                })
                .collect();
            format!(r#"{{"triangle": [{}]}}"#, v.join(", "))
        })
        .collect();
    for (pattern, prims) in [
        ("random", &prims),
        ("n-rooks", &prims),
        ("random, depth + attribute", &with_values),
    ] {
        let name = pattern.split(',').next().unwrap();
        let s = scene(64, &rule("top-left", "8"), prims, &antialias(256, name));
        let plan = Plan::for_scene(&s);
        let start = std::time::Instant::now();
        let frame = reference::render(&s, &plan);
        let render = start.elapsed();
        let start = std::time::Instant::now();
        let areas = reference::exact_areas(&s);
        let area = start.elapsed();
        eprintln!(
            "{pattern}: render (mask + areas) {render:?}, areas alone {area:?}, {} samples covered, total area {}",
            frame.covered_samples(),
            total(&areas).to_f64().value()
        );
    }
}

/// Timing (release) of polygons: a star-shaped 1000-gon (no crossings) and
/// a random 60-gon (many crossings), 64 × 64, 256 samples.
#[test]
#[ignore]
fn timing_polygons_on_64_by_64_with_256_samples() {
    let mut rng = SplitMix64::new(2);
    // Radii alternate on rays at rational angles' lattice points.
    let star: Vec<At> = (0..1000)
        .map(|i| {
            let t = i as f64 / 1000.0 * std::f64::consts::TAU;
            let r = if i % 2 == 0 {
                30.0
            } else {
                12.0 + (i % 7) as f64
            };
            let at = |c: f64| format!("{}/256", (c * 256.0).round() as i64);
            (at(32.0 + r * t.cos()), at(32.0 + r * t.sin()))
        })
        .collect();
    let random: Vec<At> = (0..60)
        .map(|_| {
            (
                coordinate(&mut rng, 0, 64, 256),
                coordinate(&mut rng, 0, 64, 256),
            )
        })
        .collect();
    for (name, outline) in [("star 1000-gon", &star), ("random 60-gon", &random)] {
        for fill in ["nonzero", "even-odd"] {
            let s = scene(
                64,
                &rule("top-left", "8"),
                &[polygon(&[outline], fill)],
                &antialias(256, "random"),
            );
            let start = std::time::Instant::now();
            let frame = reference::render(&s, &Plan::for_scene(&s));
            let render = start.elapsed();
            let start = std::time::Instant::now();
            let areas = reference::exact_areas(&s);
            let area = start.elapsed();
            assert_self_check(&s);
            eprintln!(
                "{name} {fill}: render {render:?}, areas alone {area:?}, {} samples, area {}",
                frame.covered_samples(),
                total(&areas).to_f64().value()
            );
        }
    }
}
