//! The `triangles` family: one to four random triangles, some sharing an
//! edge with the one before.

use super::common::{any_interpolation, any_rules, canvas, scene_of, Values};
use crate::explore::fuzz::rng::Rng;
use crate::scene::{Primitive, Scene, Triangle};

pub(super) fn triangle_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let values = Values::any(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 5) {
        let point = |rng: &mut Rng| values.random_vertex(rng, canvas);
        let vertices = match primitives.last() {
            // The other side of an edge of the previous triangle: every
            // sample on it must go to exactly one of the two.
            Some(Primitive::Triangle(t)) if rng.chance(1, 3) => {
                let k = rng.below(3) as usize;
                let (a, b) = (&t.vertices[k], &t.vertices[(k + 1) % 3]);
                let a = values.vertex(rng, a.x.clone(), a.y.clone());
                let b = values.vertex(rng, b.x.clone(), b.y.clone());
                [b, a, point(rng)]
            }
            _ => [point(rng), point(rng), point(rng)],
        };
        primitives.push(Primitive::Triangle(Triangle {
            vertices,
            interpolation: any_interpolation(rng),
        }));
    }
    scene_of(canvas, any_rules(rng), primitives, &values)
}
