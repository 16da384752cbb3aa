//! Invariances: whole-pixel translation, vertex order and winding change
//! nothing but what they must, in the reference and in production.

use crate::strategies::{
    any_bits, any_cull, coord, fill_rule, map_vertices, production, scene_of, triangle_or_line,
    valued_vertex,
};
use proptest::prelude::*;
use rastercheck::frame::Frame;
use rastercheck::metrics;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{Cull, Interpolation, Number, Primitive, Rules, Scene, Triangle};

/// Asserts production's interpolated values are within SPEC.md §6.3's bound.
fn assert_values_within_bound(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
) -> Result<(), TestCaseError> {
    let m = metrics::measure(scene, reference, candidate, None);
    for ch in &m.channels {
        prop_assert!(
            ch.within_bounds(),
            "{}: {:e} > {:e}",
            ch.channel,
            ch.max_abs,
            ch.allowed_abs
        );
    }
    Ok(())
}

/// Asserts that sample (x, y) of `a` equals sample (x + dx, y + dy) of `b`
/// wherever both are on the canvas: coverage, last primitive, depth and
/// every attribute, bit for bit.
fn assert_shifted(a: &Frame, b: &Frame, dx: i64, dy: i64, who: &str) -> Result<(), TestCaseError> {
    let (w, h) = (i64::from(a.width), i64::from(a.height));
    let mut compared = 0;
    for y in 0..h {
        for x in 0..w {
            let (u, v) = (x + dx, y + dy);
            if !(0..w).contains(&u) || !(0..h).contains(&v) {
                continue;
            }
            let (i, j) = ((y * w + x) as usize, (v * w + u) as usize);
            compared += 1;
            prop_assert_eq!(
                a.coverage[i],
                b.coverage[j],
                "{} coverage at ({}, {})",
                who,
                x,
                y
            );
            prop_assert_eq!(a.last[i], b.last[j], "{} owner at ({}, {})", who, x, y);
            if let (Some(da), Some(db)) = (&a.depth, &b.depth) {
                prop_assert_eq!(
                    da[i].to_bits(),
                    db[j].to_bits(),
                    "{} depth at ({}, {})",
                    who,
                    x,
                    y
                );
            }
            for (k, (ca, cb)) in a.attributes.iter().zip(&b.attributes).enumerate() {
                prop_assert_eq!(
                    ca[i].to_bits(),
                    cb[j].to_bits(),
                    "{} attribute {} at ({}, {}): {} vs {}",
                    who,
                    k,
                    x,
                    y,
                    ca[i],
                    cb[j]
                );
            }
        }
    }
    prop_assert!(compared > 0);
    Ok(())
}

const TSIZE: u32 = 32;

/// A primitive near the canvas (or reaching anywhere in range, kept 64 px
/// inside it so that a translation by up to 32 px stays in range).
fn near_primitive() -> impl Strategy<Value = Primitive> {
    let c = || coord(-8, i64::from(TSIZE) + 8, COORD_LIMIT - 64);
    let v = move || valued_vertex((c(), c()), 1);
    triangle_or_line(
        v,
        prop::sample::select(vec![
            Number::ONE,
            Number::from_int(3),
            Number::ratio(5, 2),
            Number::ratio(3, 4),
        ]),
        3,
    )
}

fn near_scene(triangles_only: bool) -> impl Strategy<Value = Scene> {
    (
        any_bits(),
        fill_rule(),
        any_cull(),
        prop::collection::vec(near_primitive(), 1..4),
    )
        .prop_map(move |(subpixel_bits, fill_rule, cull, mut primitives)| {
            if triangles_only {
                primitives.retain(|p| matches!(p, Primitive::Triangle(_)));
            }
            let rules = Rules {
                subpixel_bits,
                fill_rule,
                cull,
                ..Rules::default()
            };
            scene_of(TSIZE, TSIZE, rules, primitives)
        })
        .prop_filter("at least one triangle", |s| !s.primitives.is_empty())
}

fn map_triangles(scene: &Scene, f: impl Fn(&mut Triangle)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        if let Primitive::Triangle(t) = p {
            f(t);
        }
    }
    scene
}

proptest! {
    /// Moving every vertex by whole pixels moves the frame: exactly, for
    /// coverage, owners and every value, in the reference and in production.
    /// (With 0 subpixel bits a shift must be even: snapping's ties go to
    /// even integers, so an odd shift moves a tie the other way.)
    #[test]
    fn whole_pixel_translation_shifts_the_frame_exactly(
        scene in near_scene(false),
        dx in -(TSIZE as i64 - 1)..TSIZE as i64,
        dy in -(TSIZE as i64 - 1)..TSIZE as i64,
    ) {
        let (dx, dy) = if scene.rules.subpixel_bits == Some(0) { (dx / 2 * 2, dy / 2 * 2) } else { (dx, dy) };
        let moved = map_vertices(&scene, |v| {
            v.x = &v.x + &Number::from_int(dx);
            v.y = &v.y + &Number::from_int(dy);
        });
        let plan = Plan::for_scene(&scene);
        assert_shifted(&reference::render(&scene, &plan), &reference::render(&moved, &plan), dx, dy, "reference")?;
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&moved, &plan)?) {
            assert_shifted(&a, &b, dx, dy, "production")?;
        }
    }

    /// (v0, v1, v2) → (v1, v2, v0) changes no coverage, and no value of a
    /// linear or perspective triangle (flat takes the first vertex's).
    #[test]
    fn rotating_the_vertex_order_changes_nothing(scene in near_scene(true)) {
        let scene = map_triangles(&scene, |t| {
            if t.interpolation == Interpolation::Flat {
                t.interpolation = Interpolation::Linear;
            }
        });
        let rotated = map_triangles(&scene, |t| t.vertices.rotate_left(1));
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        prop_assert_eq!(&reference, &reference::render(&rotated, &plan));
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&rotated, &plan)?) {
            prop_assert_eq!(&a.coverage, &b.coverage);
            prop_assert_eq!(&a.last, &b.last);
            assert_values_within_bound(&rotated, &reference, &b)?;
        }
    }

    /// (v0, v1, v2) → (v0, v2, v1) reverses the winding: with cull none it
    /// changes nothing (flat included: v0 stays first); with culling, it
    /// changes nothing when the culled winding is swapped too.
    #[test]
    fn reversing_the_winding_changes_nothing_but_culling(scene in near_scene(true)) {
        let reversed = map_triangles(&scene, |t| t.vertices.swap(1, 2));
        let mut reversed = reversed;
        reversed.rules.cull = match scene.rules.cull {
            Cull::None => Cull::None,
            Cull::Clockwise => Cull::CounterClockwise,
            Cull::CounterClockwise => Cull::Clockwise,
        };
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        prop_assert_eq!(&reference, &reference::render(&reversed, &plan));
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&reversed, &plan)?) {
            prop_assert_eq!(&a.coverage, &b.coverage);
            prop_assert_eq!(&a.last, &b.last);
            assert_values_within_bound(&reversed, &reference, &b)?;
        }
    }
}
