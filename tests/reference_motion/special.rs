//! Hand-computed special cases: exact translation, double roots, riding
//! samples, winding flips under each cull, irrational crossings, static
//! primitives, and a timing.

use std::time::Instant as Clock;

use crate::brute::{
    brute_pixels, brute_samples, coverage, disagreements, instants, mutated, offsets,
};
use crate::random::{random_setup, turned, Rng};
use crate::scenes::{line, moving, r, still, triangle, Move, Setup};
use dashu_ratio::RBig;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::reference::motion::{self, Certified, Mutation};
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{Cull, FillRule, Scene};

/// `point_coverage` of primitive 0 at a pixel's centre.
fn at_centre(scene: &Scene, x: i64, y: i64, shutter: [&RBig; 2]) -> Certified {
    motion::point_coverage(scene, 0, [&r(2 * x + 1, 2), &r(2 * y + 1, 2)], shutter)
}

fn exact(value: RBig) -> Certified {
    Certified {
        value,
        bound: RBig::ZERO,
    }
}

pub fn p(x: i64, y: i64) -> [RBig; 2] {
    [r(x, 1), r(y, 1)]
}

/// A point of pixel coordinates given in halves.
pub fn h(x: i64, y: i64) -> [RBig; 2] {
    [r(x, 2), r(y, 2)]
}

/// Every pixel of a scene against brute force (a check of the hand values
/// below as much as of the oracle).
fn assert_brute(scene: &Scene, k: usize) {
    let certified = coverage(scene);
    let brute = brute_pixels(
        &brute_samples(scene, &instants(scene, k)),
        offsets(scene).len(),
    );
    let wrong = disagreements(scene, &certified, &brute, k);
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn translation_is_exact_with_bound_zero() {
    // A vertical edge x = 4τ sweeps right across row 0; the triangle lies
    // right of it, so the centre x + ½ is covered while 4τ < x + ½.
    let setup = Setup::new(8);
    let tri = [
        moving(p(0, -10), p(4, -10)),
        moving(p(0, 30), p(4, 30)),
        moving(p(40, 10), p(44, 10)),
    ];
    let scene = setup.scene(&[triangle(&tri)]);
    let time = coverage(&scene);
    for x in 0..8 {
        let expected = r(2 * x + 1, 8).min(RBig::ONE);
        assert_eq!(time[x as usize], exact(expected), "pixel ({x}, 0)");
    }
    // The reference's frame is the time layer, rounded.
    let frame = reference::render(&scene, &Plan::for_scene(&scene));
    let rounded: Vec<f64> = time.iter().map(|c| c.value.to_f64().value()).collect();
    assert_eq!(frame.time.as_ref(), Some(&rounded));
    let [zero, one] = [RBig::ZERO, RBig::ONE];
    assert_eq!(at_centre(&scene, 1, 0, [&zero, &one]), exact(r(3, 8)));
    // Over [¼, ½] it is covered during [¼, ⅜): half of it.
    assert_eq!(
        at_centre(&scene, 1, 0, [&r(1, 4), &r(1, 2)]),
        exact(r(1, 2))
    );
    // Random translations, antialiased too: every bound is exactly 0. The
    // move is by whole pixels, so that both ends snap alike (ties to even
    // included: subpixel_bits ≥ 1 here) and the snapped motion is still a
    // translation.
    let mut rng = Rng(SplitMix64::new(3));
    for round in 0..40 {
        let mut setup = random_setup(&mut rng);
        setup.size = 6;
        let lines = round % 3 == 0;
        let n = if lines { 2 } else { 3 };
        let v = [0, 1].map(|_| r(rng.below(11) as i64 - 5, 1));
        let moves: Vec<Move> = (0..n)
            .map(|_| {
                let a = rng.point(-2, 8);
                let b = [&a[0] + &v[0], &a[1] + &v[1]];
                moving(a, b)
            })
            .collect();
        let prim = if lines {
            line(&moves, &r(3, 2))
        } else {
            triangle(&moves)
        };
        let scene = setup.scene(&[prim]);
        assert!(
            coverage(&scene).iter().all(|c| c.bound == RBig::ZERO),
            "round {round}"
        );
    }
}

#[test]
fn a_double_root_grazes_the_sample_exactly() {
    // Edge a→b at sample q = (8.5, 8.5) has E(τ) = 3(2τ − 1)²: it touches q
    // at τ = ½ only (a top edge then), a double root, rational.
    let q = h(17, 17);
    let a = moving(
        [&q[0] - r(2, 1), &q[1] + r(1, 1)],
        [q[0].clone(), &q[1] - r(1, 1)],
    );
    let b = moving(
        [&q[0] + r(1, 1), &q[1] - r(2, 1)],
        [&q[0] + r(3, 1), &q[1] + r(2, 1)],
    );
    let shutter = [&RBig::ZERO, &RBig::ONE];
    for (third, expected) in [(r(20, 1), RBig::ONE), (r(-20, 1), RBig::ZERO)] {
        let c = still([&q[0] - r(3, 1), &q[1] + &third]);
        for fill in FillRule::ALL {
            let scene = Setup {
                fill,
                ..Setup::new(16)
            }
            .scene(&[triangle(&[a.clone(), b.clone(), c.clone()])]);
            assert_eq!(at_centre(&scene, 8, 8, shutter), exact(expected.clone()));
        }
    }
}

#[test]
fn parallel_velocities_make_every_edge_linear() {
    // a and b slide along x at different speeds, c stands still: no
    // velocity cross product is non-zero, yet the shape changes. The edge
    // a→b reaches (10.5, 6.5) at τ = 10/23.
    let tri = [
        moving(p(8, 2), p(16, 2)),
        moving(p(8, 10), p(12, 10)),
        still(p(0, 6)),
    ];
    let scene = Setup::new(16).scene(&[triangle(&tri)]);
    assert_eq!(
        at_centre(&scene, 10, 6, [&RBig::ZERO, &RBig::ONE]),
        exact(r(13, 23))
    );
    assert_brute(&scene, 256);
}

#[test]
fn a_vertex_through_the_sample_at_one_half() {
    // An apex pointing right crosses (8.5, 8.5) at τ = ½; the triangle
    // covers the sample once the apex has passed it.
    let apex = h(17, 17);
    let shifted = |dx: i64, dy: i64| {
        moving(
            [&apex[0] + r(dx - 2, 1), &apex[1] + r(dy, 1)],
            [&apex[0] + r(dx + 2, 1), &apex[1] + r(dy, 1)],
        )
    };
    let tri = [shifted(0, 0), shifted(-4, -2), shifted(-4, 2)];
    for fill in FillRule::ALL {
        let scene = Setup {
            fill,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        assert_eq!(
            at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]),
            exact(r(1, 2))
        );
    }
}

#[test]
fn coverage_starting_or_ending_at_the_shutter_ends() {
    // Shutter [¼, ¾]. A vertical edge meets (1.5, 0.5) exactly at open
    // (x = −½ + 8τ) or exactly at close (x = −9/2 + 8τ).
    let setup = Setup {
        shutter: [r(1, 4), r(3, 4)],
        ..Setup::new(4)
    };
    let wall = |x0: RBig, side: i64| {
        let at = |x: &RBig, y: i64| [x.clone(), r(y, 1)];
        let x1 = &x0 + r(8, 1);
        triangle(&[
            moving(at(&x0, -20), at(&x1, -20)),
            moving(at(&x0, 40), at(&x1, 40)),
            moving(at(&(&x0 + r(side, 1)), 10), at(&(&x1 + r(side, 1)), 10)),
        ])
    };
    let cases = [
        // Right of the edge, which passes the sample at open: never.
        (wall(r(-1, 2), 60), RBig::ZERO),
        // Left of it: covered from open on.
        (wall(r(-1, 2), -60), RBig::ONE),
        // Right of it, reaching the sample at close: covered until then.
        (wall(r(-9, 2), 60), RBig::ONE),
        (wall(r(-9, 2), -60), RBig::ZERO),
    ];
    for (prim, expected) in cases {
        let scene = setup.scene(&[prim]);
        assert_eq!(coverage(&scene)[1], exact(expected));
    }
}

#[test]
fn winding_flips_mid_shutter_under_each_cull() {
    // a and b swap places: clockwise before τ = ½, zero area at ½,
    // counter-clockwise after. (6.5, 8.5) is covered while |τ − ½| > ⅓.
    let tri = [
        moving(p(2, 2), p(10, 2)),
        moving(p(10, 2), p(2, 2)),
        still(p(6, 10)),
    ];
    let shutter = [&RBig::ZERO, &RBig::ONE];
    for (cull, expected, wrong) in [
        (Cull::None, r(1, 3), r(1, 3)),
        (Cull::Clockwise, r(1, 6), RBig::ZERO),
        (Cull::CounterClockwise, r(1, 6), r(1, 3)),
    ] {
        let scene = Setup {
            cull,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        assert_eq!(at_centre(&scene, 6, 8, shutter), exact(expected));
        assert_brute(&scene, 192);
        // Culling by the winding at open is caught.
        let open = motion::point_coverage_with(
            &scene,
            0,
            [&r(13, 2), &r(17, 2)],
            shutter,
            Mutation::WindingAtOpen,
        );
        assert_eq!(open, exact(wrong));
    }
}

#[test]
fn collapse_at_one_half_on_an_edge_the_sample_rides() {
    // (4.5, 4.5) lies on edge a→b at every instant. c crosses that edge at
    // τ = ½: before, the triangle lies below it (a top edge, clockwise);
    // after, above it (a bottom edge, counter-clockwise); at ½ it has no
    // area and covers nothing.
    let tri = [still(h(0, 9)), still(h(16, 9)), moving(p(4, 12), p(4, -3))];
    let half = r(1, 2);
    let expect = |fill: FillRule, cull: Cull| -> RBig {
        let before = (fill.owns_top() && cull != Cull::Clockwise) as i64;
        let after = (fill.owns_bottom() && cull != Cull::CounterClockwise) as i64;
        &half * RBig::from(before + after)
    };
    for fill in FillRule::ALL {
        for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
            let scene = Setup {
                fill,
                cull,
                ..Setup::new(8)
            }
            .scene(&[triangle(&tri)]);
            let c = at_centre(&scene, 4, 4, [&RBig::ZERO, &RBig::ONE]);
            assert_eq!(c, exact(expect(fill, cull)), "{fill:?} {cull:?}");
        }
    }
}

#[test]
fn an_edge_the_sample_rides_turns_horizontal() {
    // (8.5, 8.5) is the midpoint of a→b at every instant; the edge turns
    // about it, horizontal at τ = ½. With c below, it is a left edge
    // before ½ and a right edge after.
    let q = h(17, 17);
    let end = |sign: i64| {
        let e = |tau: i64| [r(4 * sign, 1), r(sign * (-4 + 8 * tau), 1)];
        let (e0, e1) = (e(0), e(1));
        moving(
            [&q[0] + &e0[0], &q[1] + &e0[1]],
            [&q[0] + &e1[0], &q[1] + &e1[1]],
        )
    };
    let tri = [end(-1), end(1), still([q[0].clone(), &q[1] + r(10, 1)])];
    for fill in FillRule::ALL {
        let scene = Setup {
            fill,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        let expected = r(1, 2) * RBig::from(fill.owns_left() as i64 + fill.owns_right() as i64);
        assert_eq!(
            at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]),
            exact(expected),
            "{fill:?}"
        );
    }
}

#[test]
fn an_irrational_crossing_is_within_its_bound() {
    // E(τ) = −8(2τ² − 1) at (8.5, 8.5): covered until τ = 1/√2.
    let q = h(17, 17);
    let tri = [
        moving(
            [q[0].clone(), &q[1] + r(1, 1)],
            [&q[0] + r(2, 1), &q[1] + r(1, 1)],
        ),
        moving(
            [&q[0] - r(8, 1), &q[1] + r(1, 1)],
            [&q[0] - r(6, 1), &q[1] - r(7, 1)],
        ),
        still(p(20, 0)),
    ];
    let scene = Setup::new(16).scene(&[triangle(&tri)]);
    let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
    assert!(
        c.bound > RBig::ZERO && c.bound <= motion::max_bound(),
        "{c:?}"
    );
    // value − bound ≤ 1/√2 ≤ value + bound, squared.
    let two = RBig::from(2);
    let low = &c.value - &c.bound;
    let high = &c.value + &c.bound;
    assert!(
        &low * &low * &two <= RBig::ONE && &high * &high * &two >= RBig::ONE,
        "{c:?}"
    );
    assert_brute(&scene, 256);
    // Without the τ² term the edge function is the constant 8: covered
    // throughout, which the brute force refutes.
    let wrong = mutated(&scene, Mutation::LinearEdges);
    assert_eq!(wrong[8 * 16 + 8], exact(RBig::ONE));
    let brute = brute_pixels(&brute_samples(&scene, &instants(&scene, 256)), 1);
    assert!(!disagreements(&scene, &wrong, &brute, 256).is_empty());
}

/// Whether q ≤ b/√2, exactly.
fn at_most_root_half(q: &RBig, b: &RBig) -> bool {
    let (q2, b2) = (q * q * RBig::from(2), b * b);
    match (*q <= RBig::ZERO, *b >= RBig::ZERO) {
        (true, true) => true,
        (false, true) => q2 <= b2,
        (true, false) => q2 >= b2,
        (false, false) => false,
    }
}

/// |value − (a + b/√2)| ≤ bound, exactly; the bound is not 0 when b is not.
fn assert_near_root_half(c: &Certified, a: &RBig, b: &RBig, what: &str) {
    let x = &c.value - a;
    let low = &x - &c.bound;
    let high = &x + &c.bound;
    let minus_high = -&high;
    let minus_b = -b;
    // low ≤ b/√2 and −high ≤ −b/√2.
    assert!(
        at_most_root_half(&low, b) && at_most_root_half(&minus_high, &minus_b),
        "{what}: {c:?} is not {a} + {b}/√2"
    );
    assert!(c.bound <= motion::max_bound(), "{what}: {c:?}");
}

#[test]
fn a_sample_riding_an_edge_sees_the_winding_flip_at_an_irrational_instant() {
    // (8.5, 8.5) is the midpoint of a→b = (2, 2τ) at every instant, and c
    // = q + (2τ, 1) crosses that edge's line when 1 − 2τ² = 0: the
    // winding flips at 1/√2, so the edge's ownership changes there. Before,
    // clockwise with the triangle left of a downward edge (a right edge);
    // after, a left edge. (Contrary to SPEC.md §15.2's last sentence, such
    // an instant need not be rational: it is a root of A(τ), isolated like
    // any other.)
    let q = h(17, 17);
    let tri = [
        moving(
            [&q[0] - r(1, 1), q[1].clone()],
            [&q[0] - r(1, 1), &q[1] - r(1, 1)],
        ),
        moving(
            [&q[0] + r(1, 1), q[1].clone()],
            [&q[0] + r(1, 1), &q[1] + r(1, 1)],
        ),
        moving(
            [q[0].clone(), &q[1] + r(1, 1)],
            [&q[0] + r(2, 1), &q[1] + r(1, 1)],
        ),
    ];
    let root = r(1, 1);
    for fill in FillRule::ALL {
        for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
            let scene = Setup {
                fill,
                cull,
                ..Setup::new(16)
            }
            .scene(&[triangle(&tri)]);
            let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
            // Covered for τ < 1/√2 (b/√2 with b = 1) when the right edge
            // owns it and clockwise is drawn, and for τ > 1/√2 (1 − 1/√2)
            // when the left edge does and counter-clockwise is drawn.
            let before = fill.owns_right() && cull != Cull::Clockwise;
            let after = fill.owns_left() && cull != Cull::CounterClockwise;
            let a = if after { RBig::ONE } else { RBig::ZERO };
            let b = RBig::from(before as i64 - after as i64) * &root;
            assert_near_root_half(&c, &a, &b, &format!("{fill:?} {cull:?}"));
            assert!(c.bound > RBig::ZERO, "an irrational root in the shutter");
            assert_brute(&scene, 256);
        }
    }
}

#[test]
fn a_vertex_riding_the_sample_flips_at_an_irrational_instant() {
    // Vertex a stays on (8.5, 8.5); b − a = 4(−1, 2τ), c − a = 4(τ, −1), so
    // A(τ) = 16(1 − 2τ²). Near τ = 1/√2 the corner at a opens to almost a
    // half-plane, on one side of the line before and on the other after.
    // Top-left nudges the sample towards (1, ε): inside the corner only
    // after 1/√2, when it is counter-clockwise.
    let q = h(17, 17);
    let tri = [
        still(q.clone()),
        moving(
            [&q[0] - r(4, 1), q[1].clone()],
            [&q[0] - r(4, 1), &q[1] + r(8, 1)],
        ),
        moving(
            [q[0].clone(), &q[1] - r(4, 1)],
            [&q[0] + r(4, 1), &q[1] - r(4, 1)],
        ),
    ];
    for (cull, after) in [
        (Cull::None, true),
        (Cull::Clockwise, true),
        (Cull::CounterClockwise, false),
    ] {
        let scene = Setup {
            cull,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
        let (a, b) = if after {
            (RBig::ONE, -RBig::ONE)
        } else {
            (RBig::ZERO, RBig::ZERO)
        };
        assert_near_root_half(&c, &a, &b, &format!("{cull:?}"));
        for fill in FillRule::ALL {
            assert_brute(
                &Setup {
                    fill,
                    cull,
                    ..Setup::new(16)
                }
                .scene(&[triangle(&tri)]),
                256,
            );
        }
    }
}

#[test]
fn static_primitives_keep_their_static_coverage() {
    // Static triangle, polygon and lines beside a moving triangle; pixels
    // the mover never reaches hold the static reference's counts exactly.
    let mover = triangle(&[
        moving(h(1, 1), h(9, 3)),
        moving(h(7, 1), h(13, 5)),
        moving(h(1, 7), h(5, 9)),
    ]);
    let statics = [
        triangle(&[still(h(3, 10)), still(h(29, 13)), still(h(9, 31))]),
        r#"{"polygon": [[16, 1], [31, 2], [20, 9], [30, 14]], "fill": "even-odd"}"#.to_owned(),
        line(&[still(h(2, 30)), still(h(30, 20))], &r(3, 2)),
    ];
    let midpoint = r#"{"line": [[0.5, 12.5], [15.5, 14]]}"#.to_owned();
    for antialias in [None, Some(r#"{"samples": 4}"#.to_owned())] {
        let setup = Setup {
            antialias: antialias.clone(),
            ..Setup::new(16)
        };
        let mut prims: Vec<String> = statics.to_vec();
        if antialias.is_none() {
            prims.push(midpoint.clone());
        }
        let alone = setup.scene(&prims);
        prims.push(mover.clone());
        let scene = setup.scene(&prims);
        let m = offsets(&scene).len();
        let counts =
            reference::coverage_under(&alone, &Plan::for_scene(&alone), alone.rules.fill_rule);
        let time = coverage(&scene);
        let mut untouched = 0;
        for (pixel, c) in time.iter().enumerate() {
            let (x, y) = (pixel % 16, pixel / 16);
            if x < 8 && y < 6 {
                continue; // the mover's swept box
            }
            let sum: u16 = counts[pixel * m..(pixel + 1) * m].iter().sum();
            assert_eq!(*c, exact(r(i64::from(sum), m as i64)), "({x}, {y})");
            untouched += usize::from(sum > 0);
        }
        assert!(untouched > 40);
        assert_brute(&scene, 128);
    }
}

#[test]
fn zero_velocity_agrees_with_the_static_reference() {
    // The oracle's own decision at an instant, on static triangles and
    // parallelograms on coarse coordinates (samples on edges and at
    // vertices), against the static reference, sample by sample.
    let mut rng = Rng(SplitMix64::new(5));
    let mut covered = 0;
    for round in 0..150 {
        let mut setup = random_setup(&mut rng);
        setup.size = 6;
        let lines = round % 3 == 0;
        let n = if lines { 2 } else { 3 };
        let v: Vec<Move> = (0..n)
            .map(|_| {
                let a = [
                    r(rng.below(13) as i64 - 1, 2),
                    r(rng.below(13) as i64 - 1, 2),
                ];
                still(a)
            })
            .collect();
        let prim = if lines {
            line(&v, &rng.pick(&[r(1, 1), r(2, 1), r(1, 2)]))
        } else {
            triangle(&v)
        };
        let scene = setup.scene(&[prim]);
        let counts =
            reference::coverage_under(&scene, &Plan::for_scene(&scene), scene.rules.fill_rule);
        let offsets = offsets(&scene);
        let m = offsets.len();
        let [open, close] = setup.shutter.clone();
        for (slot, &count) in counts.iter().enumerate() {
            let (pixel, s) = (slot / m, slot % m);
            let point = [
                r((pixel % 6) as i64, 1) + &offsets[s][0],
                r((pixel / 6) as i64, 1) + &offsets[s][1],
            ];
            let c = motion::point_coverage(&scene, 0, [&point[0], &point[1]], [&open, &close]);
            assert_eq!(c, exact(RBig::from(count)), "round {round} slot {slot}");
            covered += usize::from(count > 0);
        }
    }
    assert!(covered > 500, "{covered}");
}

#[test]
fn timing_a_triangle_moving_100_pixels() {
    // Rotating while it moves, so its edges are true quadratics.
    let from = [p(-30, 10), p(-6, 18), p(-22, 40)];
    let centre = p(-20, 22);
    let moves: Vec<Move> = from
        .iter()
        .map(|v| {
            let t = turned(v, &centre, (3, 4, 5));
            moving(v.clone(), [&t[0] + r(100, 1), &t[1] + r(10, 1)])
        })
        .collect();
    for antialias in [None, Some(r#"{"samples": 4}"#.to_owned())] {
        let scene = Setup {
            antialias: antialias.clone(),
            ..Setup::new(64)
        }
        .scene(&[triangle(&moves)]);
        let start = Clock::now();
        let time = coverage(&scene);
        let elapsed = start.elapsed();
        let worst = time
            .iter()
            .map(|c| c.bound.to_f64().value())
            .fold(0.0, f64::max);
        let moving = time.iter().filter(|c| c.value > RBig::ZERO).count();
        eprintln!(
            "64×64, one triangle moving 100 px, M = {}: {elapsed:?}, {moving} pixels covered at some instant, worst bound {worst:e}",
            offsets(&scene).len()
        );
        assert!(moving > 500);
    }
}
