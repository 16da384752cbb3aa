//! The documented range: anywhere in it, the reference and production never
//! panic and agree.

use crate::strategies::{
    any_bits, any_cull, coord, fill_rule, production, scene_of, triangle_or_line, valued_vertex,
};
use proptest::prelude::*;
use rastercheck::metrics;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{Number, Primitive, Rules, Scene};

// --- The documented range --------------------------------------------------

/// A coordinate anywhere in range, its very limits included.
fn extreme_coord() -> impl Strategy<Value = Number> {
    let l = COORD_LIMIT;
    prop_oneof![
        1 => prop::sample::select(vec![
            Number::from_int(l),
            Number::from_int(-l),
            Number::ratio(2 * l - 1, 2),
            Number::ratio(-(l << 40) + 1, 1 << 40),
            Number::ratio((l << 40) - 1, 1 << 40),
        ]),
        4 => coord(-4, 20, l),
    ]
}

/// A line width in (0, 1024], with denominators up to 2^40.
fn line_width() -> impl Strategy<Value = Number> {
    prop_oneof![
        prop::sample::select(vec![
            Number::from_int(1024),
            Number::ratio(1, 1 << 40),
            Number::ONE,
            Number::ratio(1, 3),
            Number::ratio(1023, 1),
        ]),
        (1i64..1 << 40).prop_flat_map(|d| (1..=1024 * d).prop_map(move |n| Number::ratio(n, d))),
    ]
}

fn extreme_primitive(attributes: usize) -> impl Strategy<Value = Primitive> {
    let v = move || valued_vertex((extreme_coord(), extreme_coord()), attributes);
    triangle_or_line(v, line_width(), 2)
}

fn extreme_scene() -> impl Strategy<Value = Scene> {
    prop::sample::select(vec![0usize, 1, 3, 16]).prop_flat_map(|attributes| {
        (
            any_bits(),
            fill_rule(),
            any_cull(),
            1u32..=16,
            1u32..=16,
            any::<bool>(),
            prop::collection::vec(extreme_primitive(attributes), 1..4),
        )
            .prop_map(
                |(subpixel_bits, fill_rule, cull, width, height, has_depth, primitives)| {
                    let rules = Rules {
                        subpixel_bits,
                        fill_rule,
                        cull,
                        ..Rules::default()
                    };
                    let mut scene = scene_of(width, height, rules, primitives);
                    scene.has_depth = has_depth;
                    scene
                },
            )
    })
}

proptest! {
    /// Anywhere in the documented range (coordinates to ±32768, w in
    /// [10^-6, 10^6], values to ±10^12, rationals with 40-bit denominators,
    /// every subpixel setting) the reference and production never panic,
    /// and production, where it accepts the scene, agrees with the reference.
    #[test]
    fn nothing_panics_anywhere_in_the_documented_range(scene in extreme_scene()) {
        use std::panic::{catch_unwind, AssertUnwindSafe};
        let plan = Plan::for_scene(&scene);
        let reference = catch_unwind(AssertUnwindSafe(|| reference::render(&scene, &plan)));
        prop_assert!(reference.is_ok(), "the reference panicked");
        let reference = reference.unwrap();
        let candidate = catch_unwind(AssertUnwindSafe(|| production(&scene, &plan)));
        prop_assert!(candidate.is_ok(), "production panicked");
        if let Some(candidate) = candidate.unwrap()? {
            let m = metrics::measure(&scene, &reference, &candidate, None);
            prop_assert_eq!(m.coverage.mismatched(), 0, "{} missing, {} extra, {} wrong owner", m.coverage.missing, m.coverage.extra, m.coverage.wrong_owner);
            for ch in &m.channels {
                prop_assert!(ch.within_bounds(), "{}: {:e} > {:e}", ch.channel, ch.max_abs, ch.allowed_abs);
            }
        }
    }
}
