//! The `clip` family (SPEC.md §16): one to four triangles in clip space,
//! and in a third of the scenes one to three points after them (§17), the
//! triangles some sharing an edge, with vertices behind the eye, on the w = 0 plane,
//! across the near and far planes, at extreme ratios of w; a viewport that
//! is the canvas, smaller, offset or fractional; every clip convention,
//! depth clip or clamp, either provoking vertex.

use super::common::{any_rules, scene_of, Values};
use crate::explore::fuzz::rng::Rng;
use crate::scene::clip::{
    ClipRules, ClipXy, ClipZ, DepthMode, InterpolateFrom, PointBounds, PointClip, Viewport,
};
use crate::scene::rules::{limits::CLIP_LIMIT, ProvokingVertex};
use crate::scene::{Canvas, Interpolation, Number, Point, Primitive, Scene, Triangle, Vertex};

pub(super) fn clip_scene(rng: &mut Rng) -> Scene {
    let side = |rng: &mut Rng| rng.range(4, 33) as u32;
    let canvas = Canvas {
        width: side(rng),
        height: side(rng),
    };
    let values = Values {
        attributes: *rng.pick(&[0, 1, 1, 2]),
        depth: true,
        w: true,
    };
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 5) {
        let vertices = match primitives.last() {
            // The other side of an edge of the previous triangle: the
            // edge's clipped end must be the same for both.
            Some(Primitive::Triangle(t)) if rng.chance(1, 2) => {
                let k = rng.below(3) as usize;
                let (a, b) = (t.vertices[k].clone(), t.vertices[(k + 1) % 3].clone());
                [b, a, clip_vertex(rng, &values)]
            }
            _ => [0, 1, 2].map(|_| clip_vertex(rng, &values)),
        };
        primitives.push(Primitive::Triangle(Triangle {
            vertices,
            interpolation: *rng.pick(&[Interpolation::Perspective, Interpolation::Flat]),
        }));
    }
    let mut rules = any_rules(rng);
    rules.clip = ClipRules {
        xy: *rng.pick(&ClipXy::ALL),
        z: *rng.pick(&ClipZ::ALL),
        depth: *rng.pick(&[DepthMode::Clip, DepthMode::Clip, DepthMode::Clamp]),
        values: *rng.pick(&InterpolateFrom::ALL),
        points: PointClip::Pop,
        bounds: PointBounds::Canvas,
    };
    if rules.clip.depth == DepthMode::Clamp {
        rules.clip.z = ClipZ::ClipThenSnap;
    }
    rules.provoking_vertex = *rng.pick(&ProvokingVertex::ALL);
    let mut scene = scene_of(canvas, rules, primitives, &values);
    scene.viewport = Some(viewport(rng, canvas));
    // Points (SPEC.md §17) in a third of the scenes, drawn after the
    // triangles, under either rule for the side planes. Drawn from the
    // generator last, so that a seed's triangles are those it drew before
    // points were added.
    if rng.chance(1, 3) {
        for _ in 0..rng.range(1, 4) {
            let size = *rng.pick(&[(1, 1), (2, 1), (3, 1), (1, 2), (19, 4), (1, 3), (8, 1)]);
            scene.primitives.push(Primitive::Point(Point {
                vertices: [clip_vertex(rng, &values)],
                size: Number::ratio(size.0, size.1),
            }));
        }
        scene.rules.clip.points = *rng.pick(&PointClip::ALL);
        scene.rules.clip.bounds = *rng.pick(&PointBounds::ALL);
    }
    scene
}

/// The canvas, or a rectangle inside or across it, on whole, half or
/// 1/256 pixels; depth [0, 1] or a random range, sometimes reversed.
fn viewport(rng: &mut Rng, canvas: Canvas) -> Viewport {
    let mut v = Viewport::canvas(canvas.width, canvas.height);
    if rng.chance(1, 2) {
        let den = *rng.pick(&[1, 2, 256]);
        let (w, h) = (i64::from(canvas.width), i64::from(canvas.height));
        v.x = Number::ratio(rng.range(-2 * den, w * den / 2), den);
        v.y = Number::ratio(rng.range(-2 * den, h * den / 2), den);
        v.width = Number::ratio(rng.range(den, (w + 2) * den), den);
        v.height = Number::ratio(rng.range(den, (h + 2) * den), den);
    }
    if rng.chance(1, 3) {
        v.min_depth = Number::ratio(rng.range(0, 16), 16);
        v.max_depth = Number::ratio(rng.range(0, 16), 16);
    }
    v
}

/// A clip-space vertex: mostly near the view volume, with w positive,
/// negative, zero, tiny or huge, and z across the near and far planes.
fn clip_vertex(rng: &mut Rng, values: &Values) -> Vertex {
    let w = match rng.below(10) {
        0 => Number::ZERO,
        1 => Number::ratio(-rng.range(1, 64), 16),
        2 => Number::ratio(1, rng.range(1, 1_000_000)),
        3 => Number::from_int(rng.range(1, CLIP_LIMIT / 1000) * 1000),
        _ => Number::ratio(rng.range(1, 64), 16),
    };
    // x, y, z as multiples of w (inside the volume up to 2: outside it),
    // plus a small free term so that w = 0 still places the vertex.
    let coordinate = |rng: &mut Rng, low: i64| {
        let scale = Number::ratio(rng.range(low, 32), 16);
        let free = Number::ratio(rng.range(-16, 16), *rng.pick(&[4, 16, 1 << 12]));
        let c = Number::from_rbig(w.as_rbig() * scale.as_rbig() + free.as_rbig());
        let limit = Number::from_int(CLIP_LIMIT);
        if c.abs() > limit {
            free
        } else {
            c
        }
    };
    let mut v = Vertex::at(coordinate(rng, -32), coordinate(rng, -32));
    v.z = coordinate(rng, -16);
    v.w = w;
    v.attributes = (0..values.attributes)
        .map(|_| Number::ratio(rng.range(-1000, 1001), 8))
        .collect();
    v
}
