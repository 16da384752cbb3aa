//! Exact values at vertices: a vertex on a sample centre writes its own
//! depth and attributes, correctly rounded.

use crate::strategies::{
    any_interpolation, coord, fill_rule, orient, placed, production, scene_of, valued_vertex,
};
use dashu_ratio::RBig;
use proptest::prelude::*;
use rastercheck::metrics;
use rastercheck::plan::Plan;
use rastercheck::reference::{self, exact};
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{
    Cull, FillRule, Interpolation, Number, Primitive, Rules, Scene, Triangle,
};

// --- Exact values at vertices ---------------------------------------------

const VSIZE: u32 = 16;

/// The pixel whose sample centre a placed position is, if on the canvas.
fn centre_pixel(p: &[RBig; 2], size: u32) -> Option<usize> {
    let half = RBig::from_parts(1.into(), 2u8.into());
    let mut at = [0usize; 2];
    for axis in 0..2 {
        let t = &p[axis] - &half;
        if t.denominator() != &dashu_int::UBig::ONE {
            return None;
        }
        let i: i64 = t.numerator().try_into().ok()?;
        if !(0..i64::from(size)).contains(&i) {
            return None;
        }
        at[axis] = i as usize;
    }
    Some(at[1] * size as usize + at[0])
}

/// A vertex position: a sample centre on the canvas, a sample centre
/// anywhere in range, or any coordinate.
fn vertex_position() -> impl Strategy<Value = (Number, Number)> {
    let near = || (0..i64::from(VSIZE)).prop_map(|i| Number::ratio(2 * i + 1, 2));
    let anywhere = || (-COORD_LIMIT..COORD_LIMIT).prop_map(|i| Number::ratio(2 * i + 1, 2));
    let free = || coord(-4, i64::from(VSIZE) + 4, COORD_LIMIT);
    prop_oneof![
        4 => (near(), near()),
        1 => (anywhere(), anywhere()),
        1 => (near(), anywhere()),
        1 => (free(), free()),
    ]
}

fn vertex_scene() -> impl Strategy<Value = Scene> {
    (1usize..=3).prop_flat_map(|attributes| {
        (
            prop_oneof![4 => (1u32..=16).prop_map(Some), 1 => Just(None)],
            fill_rule(),
            any_interpolation(),
            [
                valued_vertex((near_centre(), near_centre()), attributes).boxed(),
                valued_vertex(vertex_position(), attributes).boxed(),
                valued_vertex(vertex_position(), attributes).boxed(),
            ],
        )
            .prop_map(|(subpixel_bits, fill_rule, interpolation, vertices)| {
                let rules = Rules {
                    subpixel_bits,
                    fill_rule,
                    cull: Cull::None,
                    ..Rules::default()
                };
                scene_of(
                    VSIZE,
                    VSIZE,
                    rules,
                    vec![Primitive::Triangle(Triangle {
                        vertices,
                        interpolation,
                    })],
                )
            })
    })
}

fn near_centre() -> impl Strategy<Value = Number> {
    (0..i64::from(VSIZE)).prop_map(|i| Number::ratio(2 * i + 1, 2))
}

proptest! {
    /// At a vertex that lies on a sample centre, the reference writes the
    /// vertex's own depth and attributes (the first vertex's for flat), as
    /// the correctly rounded f32 (checked against dashu's conversion), and
    /// production is within SPEC.md §6.3's bound of them. Under `all-edges`
    /// a triangle with area covers its vertices' samples.
    #[test]
    fn interpolation_reproduces_vertex_values_at_sample_centres(scene in vertex_scene()) {
        let Primitive::Triangle(t) = &scene.primitives[0] else { unreachable!() };
        let bits = scene.rules.subpixel_bits;
        let positions: Vec<[RBig; 2]> = t.vertices.iter().map(|v| [placed(&v.x, bits), placed(&v.y, bits)]).collect();
        let area = orient(&positions[0], &positions[1], &positions[2]);
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        let candidate = production(&scene, &plan)?;
        let bound = |values: Vec<&Number>| {
            metrics::DEFAULT_RELATIVE_BOUND
                * values.iter().map(|v| v.abs().to_f64_lossy()).fold(1.0, f64::max)
        };
        for (i, p) in positions.iter().enumerate() {
            let Some(pixel) = centre_pixel(p, VSIZE) else { continue };
            if scene.rules.fill_rule == FillRule::AllEdges && !area.is_eq() {
                prop_assert_eq!(reference.last[pixel], 1, "vertex {} not covered under all-edges", i);
            }
            let mut expected = vec![(
                "depth",
                &t.vertices[i].z,
                reference.depth.as_ref().unwrap()[pixel],
                candidate.as_ref().map(|c| c.depth.as_ref().unwrap()[pixel]),
                bound(t.vertices.iter().map(|v| &v.z).collect()),
            )];
            let source = if t.interpolation == Interpolation::Flat { 0 } else { i };
            for k in 0..scene.attribute_count {
                expected.push((
                    "attribute",
                    &t.vertices[source].attributes[k],
                    reference.attributes[k][pixel],
                    candidate.as_ref().map(|c| c.attributes[k][pixel]),
                    bound(t.vertices.iter().map(|v| &v.attributes[k]).collect()),
                ));
            }
            if reference.last[pixel] != 1 {
                continue;
            }
            for (what, value, exact_out, candidate_out, allowed) in expected {
                let q = value.as_rbig();
                prop_assert_eq!(exact_out.to_bits(), exact::to_f64_round_odd(q).to_bits(), "{} at vertex {}", what, i);
                prop_assert_eq!((exact_out as f32).to_bits(), q.to_f32().value().to_bits(), "{} at vertex {}: f32", what, i);
                if let (Some(out), Some(c)) = (candidate_out, &candidate) {
                    if c.last[pixel] == 1 {
                        prop_assert!((out - exact_out).abs() <= allowed, "production {} at vertex {}: {} vs {} (bound {:e})", what, i, out, exact_out, allowed);
                    }
                }
            }
        }
    }
}
