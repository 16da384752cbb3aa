//! The `conservative` family's points and lines (SPEC.md §19.8): one to
//! four points, `rectangle` and `parallelogram` lines, now and then with a
//! triangle, drawn conservatively with `points_and_lines` true and
//! degenerate lines drawn or culled. The shapes are what conservative
//! lines get wrong: diagonals whose rectangles have irrational corners,
//! lines along pixel borders and ends on pixel corners (touches of measure
//! zero), ends a small step apart that snapping makes one point, lines of
//! zero length, points on pixel corners and of sizes that end on pixel
//! borders, and thin and wide widths.

use super::common::{scene_of, Values};
use super::conservative::{any_conservative, canvas_and_rules, grid, point, small, whole};
use crate::explore::fuzz::rng::Rng;
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::{
    Canvas, Conservative, Interpolation, LastPixel, Line, LineParameter, LineRule, Number, Point,
    Primitive, Scene, Triangle, Vertex,
};

/// A conservative scene of points and lines: any mode, uncertainty and
/// flag, `points_and_lines` true, degenerate lines drawn or culled.
pub(super) fn points_and_lines_scene(rng: &mut Rng) -> Scene {
    let (canvas, rules, snapped) = canvas_and_rules(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 5) {
        primitives.push(match rng.below(8) {
            0..=3 => line(rng, canvas, snapped),
            4..=6 => Primitive::Point(Point {
                vertices: [if rng.chance(1, 2) {
                    Vertex::at(whole(rng, canvas.width), whole(rng, canvas.height))
                } else {
                    point(rng, canvas, snapped)
                }],
                size: size(rng),
            }),
            _ => Primitive::Triangle(Triangle {
                vertices: [0, 1, 2].map(|_| point(rng, canvas, snapped)),
                interpolation: Interpolation::Perspective,
            }),
        });
    }
    if !snapped {
        for p in &mut primitives {
            for v in p.vertices_mut() {
                v.x = v.x.snapped(MAX_SUBPIXEL_BITS);
                v.y = v.y.snapped(MAX_SUBPIXEL_BITS);
            }
        }
    }
    let values = Values {
        attributes: 0,
        depth: false,
        w: false,
    };
    let mut scene = scene_of(canvas, rules, primitives, &values);
    scene.effects.conservative = Some(Conservative {
        points_and_lines: true,
        degenerate_lines: rng.chance(1, 2),
        ..any_conservative(rng)
    });
    scene
}

/// A `rectangle` or `parallelogram` line of one of the shapes above.
fn line(rng: &mut Rng, canvas: Canvas, snapped: bool) -> Primitive {
    let add = |p: &Vertex, dx: &Number, dy: &Number| {
        Vertex::at(
            Number::from_rbig(p.x.as_rbig() + dx.as_rbig()),
            Number::from_rbig(p.y.as_rbig() + dy.as_rbig()),
        )
    };
    let a = match rng.below(3) {
        0 => Vertex::at(whole(rng, canvas.width), whole(rng, canvas.height)),
        1 => Vertex::at(grid(rng, canvas.width, 2), grid(rng, canvas.height, 2)),
        _ => point(rng, canvas, snapped),
    };
    let b = match rng.below(6) {
        // A diagonal: irrational corners.
        0 => {
            let k = Number::from_int(rng.range(-6, 7));
            let j = Number::from_int(*rng.pick(&[-1, 1]) * rng.range(-6, 7));
            add(&a, &k, &j)
        }
        // Along a pixel border or centre line: one coordinate kept.
        1 => {
            let d = grid(rng, canvas.width, 4);
            if rng.chance(1, 2) {
                Vertex::at(d, a.y.clone())
            } else {
                Vertex::at(a.x.clone(), d)
            }
        }
        // A small step: often one point after snapping.
        2 => add(&a, &small(rng), &small(rng)),
        // Zero length.
        3 => a.clone(),
        _ => point(rng, canvas, snapped),
    };
    Primitive::Line(Line {
        vertices: [a, b],
        rule: *rng.pick(&[LineRule::Rectangle, LineRule::Parallelogram]),
        width: size(rng),
        last_pixel: LastPixel::Include,
        parameter: LineParameter::Major,
        interpolation: Interpolation::Linear,
    })
}

/// A point size or line width: thin, whole, or a multiple of ⅛ or ⅓ up
/// to 4 px.
fn size(rng: &mut Rng) -> Number {
    match rng.below(5) {
        0 => Number::ratio(rng.range(1, 9), 16),
        1 => Number::from_int(rng.range(1, 4)),
        2 => Number::ratio(rng.range(1, 10), 3),
        _ => Number::ratio(rng.range(1, 33), 8),
    }
}
