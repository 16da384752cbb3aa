//! The `lines` family: one to three lines of every rule, widths for the
//! wide rules, both `last_pixel`s, some in strips.

use super::common::{any_interpolation, any_rules, canvas, scene_of, Values};
use crate::explore::fuzz::rng::Rng;
use crate::scene::{LastPixel, Line, LineParameter, LineRule, Number, Primitive, Scene};

pub(super) fn line_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let values = Values::any(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 4) {
        let point = |rng: &mut Rng| values.random_vertex(rng, canvas);
        let start = match primitives.last() {
            // A strip: this line starts where the last one ended.
            Some(Primitive::Line(l)) if rng.chance(1, 2) => {
                let end = &l.vertices[1];
                values.vertex(rng, end.x.clone(), end.y.clone())
            }
            _ => point(rng),
        };
        let rule = *rng.pick(&LineRule::ALL);
        let width = if rule.is_wide() {
            match rng.below(12) {
                0 => Number::ratio(1, 3),
                1..=3 => Number::from_int(2),
                4..=5 => Number::ratio(5, 2),
                6..=7 => Number::ratio(1, 2),
                8 => Number::from_int(3),
                _ => Number::ONE,
            }
        } else {
            Number::ONE
        };
        let last_pixel = if rule == LineRule::Midpoint && rng.chance(1, 2) {
            LastPixel::Exclude
        } else {
            LastPixel::Include
        };
        primitives.push(Primitive::Line(Line {
            vertices: [start, point(rng)],
            rule,
            width,
            last_pixel,
            parameter: *rng.pick(&[LineParameter::Major, LineParameter::Projected]),
            interpolation: any_interpolation(rng),
        }));
    }
    scene_of(canvas, any_rules(rng), primitives, &values)
}
