//! Many coverage-only midpoint lines on a 1024² canvas: production's banded
//! path against the reference.

use crate::config;
use crate::strategies::any_bits;
use proptest::prelude::*;
use rastercheck::metrics;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference;
use rastercheck::scene::{
    Canvas, Effects, Expect, Interpolation, LastPixel, Line, LineParameter, LineRule, Number,
    Primitive, Rules, Scene, Vertex,
};

// --- Many coverage-only midpoint lines: production's banded path ------------

/// 1 to 40 coverage-only midpoint lines with ends anywhere around a 1024²
/// canvas (6 MiB of frame: production draws them band by band with
/// resumable walkers, `production/line/bands.rs` `midpoint_lines`): half-pixel
/// ends force ties, 1/256 ends the general case, both `last_pixel`s.
fn many_lines_scene() -> impl Strategy<Value = Scene> {
    let end = prop_oneof![
        (-64i64..2 * 1100).prop_map(|h| Number::ratio(h, 2)),
        (-64i64 * 256..1100 * 256).prop_map(|k| Number::ratio(k, 256)),
    ];
    let line = (
        end.clone(),
        end.clone(),
        end.clone(),
        end,
        prop::sample::select(vec![LastPixel::Include, LastPixel::Exclude]),
    )
        .prop_map(|(x0, y0, x1, y1, last_pixel)| {
            Primitive::Line(Line {
                vertices: [Vertex::at(x0, y0), Vertex::at(x1, y1)],
                rule: LineRule::Midpoint,
                width: Number::ONE,
                last_pixel,
                parameter: LineParameter::Major,
                interpolation: Interpolation::Perspective,
            })
        });
    (prop::collection::vec(line, 1..41), any_bits()).prop_map(|(primitives, bits)| Scene {
        name: "lines".to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: 1024,
            height: 1024,
        },
        rules: Rules {
            subpixel_bits: bits,
            ..Rules::default()
        },
        primitives,
        effects: Effects::default(),
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    })
}

proptest! {
    #![proptest_config(config(48))]

    /// Production's banded midpoint path equals the reference: every
    /// pixel's count and last line.
    #[test]
    fn production_midpoint_line_bands_equal_the_reference(scene in many_lines_scene()) {
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        let candidate = Production.rasterize(&scene, &plan).unwrap();
        let m = metrics::coverage::compare(&reference, &candidate);
        prop_assert_eq!(m.mismatched(), 0, "{} missing, {} extra, {} wrong owner", m.missing, m.extra, m.wrong_owner);
    }
}
