//! The `antialias` family (SPEC.md §14): triangles, polygons and
//! parallelogram lines under `effects.antialias`, every pattern with a sample
//! count valid for it.

use super::common::{any_rules, plain_triangle, position, scene_of, Values};
use super::polygons::{polygon, polygon_rules};
use crate::explore::fuzz::rng::Rng;
use crate::scene::{
    Antialias, Canvas, Interpolation, LastPixel, Line, LineParameter, LineRule, Number, Pattern,
    Primitive, Scene, Triangle,
};

/// `effects.antialias` with a sample count valid for its pattern; more
/// samples on smaller canvases.
pub(super) fn antialias(rng: &mut Rng, canvas: Canvas) -> Antialias {
    let pattern = *rng.pick(&Pattern::ALL);
    let small = canvas.width * canvas.height <= 256;
    let counts: &[u32] = match pattern {
        Pattern::Standard => &[1, 2, 4, 8, 16, 16],
        Pattern::Grid | Pattern::Stratified if small => &[1, 4, 16, 16, 64, 256],
        Pattern::Grid | Pattern::Stratified => &[1, 4, 9, 16, 16],
        Pattern::Random | Pattern::NRooks if small => &[1, 3, 8, 16, 16, 64, 256],
        Pattern::Random | Pattern::NRooks => &[1, 3, 8, 16, 16],
    };
    let samples = *rng.pick(counts);
    debug_assert!(pattern.check_count(samples).is_ok());
    let position_bits = if rng.chance(2, 3) {
        8
    } else {
        rng.range(4, 17) as u32
    };
    Antialias {
        samples,
        pattern,
        seed: if pattern.is_seeded() {
            rng.below(1000)
        } else {
            0
        },
        adaptive: rng.chance(1, 3),
        position_bits,
    }
}

pub(super) fn antialias_scene(rng: &mut Rng) -> Scene {
    let canvas = Canvas {
        width: *rng.pick(&[8, 12, 16, 24]),
        height: *rng.pick(&[8, 12, 16, 24]),
    };
    let mut primitives = Vec::new();
    let with_polygons = rng.chance(1, 2);
    for _ in 0..rng.range(1, 4) {
        let p = match rng.below(4) {
            0 | 1 if with_polygons => Primitive::Polygon(polygon(rng, canvas)),
            0 => {
                // The other side of an edge of the last triangle: its
                // samples go to exactly one, and the coverages add up.
                match primitives.last() {
                    Some(Primitive::Triangle(t)) => {
                        let k = rng.below(3) as usize;
                        let (a, b) = (t.vertices[k].clone(), t.vertices[(k + 1) % 3].clone());
                        let c = position(rng, canvas);
                        Primitive::Triangle(Triangle {
                            vertices: [b, a, c],
                            interpolation: Interpolation::Perspective,
                        })
                    }
                    _ => plain_triangle(rng, canvas),
                }
            }
            1 | 2 => plain_triangle(rng, canvas),
            _ => {
                let mut point = || position(rng, canvas);
                let vertices = [point(), point()];
                let width = match rng.below(4) {
                    0 => Number::ratio(1, 3),
                    1 => Number::from_int(2),
                    2 => Number::ratio(1, 16),
                    _ => Number::ONE,
                };
                Primitive::Line(Line {
                    vertices,
                    rule: LineRule::Parallelogram,
                    width,
                    last_pixel: LastPixel::Include,
                    parameter: LineParameter::Major,
                    interpolation: Interpolation::Perspective,
                })
            }
        };
        primitives.push(p);
    }
    let none = Values {
        attributes: 0,
        depth: false,
        w: false,
    };
    let rules = if with_polygons {
        polygon_rules(rng)
    } else {
        any_rules(rng)
    };
    let mut scene = scene_of(canvas, rules, primitives, &none);
    scene.effects.antialias = Some(antialias(rng, canvas));
    scene
}
