//! The `conservative` family (SPEC.md §19): one to four triangles drawn
//! conservatively, in either mode, under an uncertainty of 0, a device's
//! (2^-9, 1/256 px), D3D12 tier 1's ½ px, Vulkan's largest extra ¾ px, a
//! whole pixel, a third or any 64th, with the fully-covered flag asked for
//! or not and degenerate triangles drawn or culled, with depth in half of
//! them (any format, an offset in some: SPEC.md §19.9), and multisampled
//! in half of those without depth (any pattern and count of the
//! `antialias` family's: SPEC.md §19.10, a pixel's samples all drawn or
//! none; a multisampled scene's depth is not judged, §19.7). The triangles are
//! what conservative tests get wrong: slivers thinner than a pixel,
//! needles, vertices on pixel corners and edges along pixel borders (a
//! touch of measure zero), degenerate triangles (collinear or coincident
//! vertices, on the snapping grid so that they stay degenerate), vertices
//! far outside the canvas, and neighbours sharing an edge. Coordinates are
//! dyadic when the scene is unsnapped, so that fixed point holds them.
//! One scene in three is of points and lines instead
//! (`conservative_lines.rs`, SPEC.md §19.8; `generate.rs` picks).

use super::antialias::antialias;
use super::common::{any_bits, any_rules, scene_of, Values};
use crate::explore::fuzz::rng::Rng;
use crate::scene::depth::{DepthBias, DepthFormat};
use crate::scene::rules::limits::{COORD_LIMIT, MAX_SUBPIXEL_BITS};
use crate::scene::rules::Rules;
use crate::scene::{
    Canvas, Conservative, ConservativeMode, Interpolation, Number, Primitive, Scene, Triangle,
    Vertex,
};

/// A conservative scene's canvas (3 to 16 px a side), its rules, any
/// subpixel bits, and whether they snap: what both the triangles' scenes
/// and the points' and lines' (`conservative_lines.rs`) start from.
pub(super) fn canvas_and_rules(rng: &mut Rng) -> (Canvas, Rules, bool) {
    let side = |rng: &mut Rng| *rng.pick(&[3, 4, 6, 8, 12, 16]);
    let canvas = Canvas {
        width: side(rng),
        height: side(rng),
    };
    let mut rules = any_rules(rng);
    rules.subpixel_bits = any_bits(rng);
    let snapped = rules.subpixel_bits.is_some();
    (canvas, rules, snapped)
}

pub(super) fn conservative_scene(rng: &mut Rng) -> Scene {
    let (canvas, mut rules, snapped) = canvas_and_rules(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 5) {
        let vertices = match primitives.last() {
            // The other side of an edge of the previous triangle: both may
            // draw the pixels along it (SPEC.md §19.5).
            Some(Primitive::Triangle(t)) if rng.chance(1, 4) => {
                let k = rng.below(3) as usize;
                let (a, b) = (&t.vertices[k], &t.vertices[(k + 1) % 3]);
                [b.clone(), a.clone(), point(rng, canvas, snapped)]
            }
            _ => shape(rng, canvas, snapped),
        };
        primitives.push(Primitive::Triangle(Triangle {
            vertices,
            interpolation: Interpolation::Perspective,
        }));
    }
    // Depth in half the scenes (SPEC.md §19.9): depths from −1/4 to 5/4,
    // so that extrapolated and clamped values come up, in any format, with
    // a polygon offset in some of those with a format.
    let depth = rng.chance(1, 2);
    if depth {
        for v in primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
            v.z = Number::ratio(rng.range(-16, 81), 64);
        }
        rules.depth_format = *rng.pick(&[
            DepthFormat::Exact,
            DepthFormat::Exact,
            DepthFormat::Unorm16,
            DepthFormat::Unorm24,
            DepthFormat::Float32,
        ]);
        if rules.depth_format != DepthFormat::Exact && rng.chance(1, 3) {
            rules.depth_bias = Some(DepthBias {
                constant: Number::from_int(rng.range(-8, 9)),
                slope: Number::ratio(rng.range(-4, 5), 2),
                clamp: Number::ZERO,
            });
        }
    }
    let values = Values {
        attributes: 0,
        depth,
        w: false,
    };
    if !snapped {
        // Midpoints and small steps can leave the 2^-16 grid: put every
        // coordinate back on it, so that fixed point holds it.
        for p in &mut primitives {
            for v in p.vertices_mut() {
                v.x = v.x.snapped(MAX_SUBPIXEL_BITS);
                v.y = v.y.snapped(MAX_SUBPIXEL_BITS);
            }
        }
    }
    let mut scene = scene_of(canvas, rules, primitives, &values);
    scene.effects.conservative = Some(any_conservative(rng));
    if !depth && rng.chance(1, 2) {
        scene.effects.antialias = Some(antialias(rng, canvas));
    }
    scene
}

/// A mode, an uncertainty, the flag asked for or not, degenerate
/// triangles drawn or culled.
pub(super) fn any_conservative(rng: &mut Rng) -> Conservative {
    let uncertainty = match rng.below(12) {
        0..=3 => Number::ZERO,
        4 => Number::ratio(1, 512),
        5 => Number::ratio(1, 256),
        6 => Number::ratio(1, 2),
        7 => Number::ratio(3, 4),
        8 => Number::ONE,
        9 => Number::ratio(1, 3),
        _ => Number::ratio(rng.range(0, 65), 64),
    };
    Conservative {
        mode: *rng.pick(&[
            ConservativeMode::Overestimate,
            ConservativeMode::Underestimate,
        ]),
        uncertainty,
        fully_covered: rng.chance(1, 2),
        degenerate_triangles: rng.chance(1, 2),
        ..Conservative::overestimate()
    }
}

/// Three vertices of one of the shapes conservative tests get wrong.
fn shape(rng: &mut Rng, canvas: Canvas, snapped: bool) -> [Vertex; 3] {
    let at = |x: Number, y: Number| Vertex::at(x, y);
    let add = |p: &Vertex, dx: &Number, dy: &Number| {
        at(
            Number::from_rbig(p.x.as_rbig() + dx.as_rbig()),
            Number::from_rbig(p.y.as_rbig() + dy.as_rbig()),
        )
    };
    match rng.below(8) {
        // A sliver: a third vertex a small step off the midpoint of two.
        0 => {
            let (a, b) = (point(rng, canvas, snapped), point(rng, canvas, snapped));
            let mid = at(
                Number::from_rbig((a.x.as_rbig() + b.x.as_rbig()) / dashu_ratio::RBig::from(2)),
                Number::from_rbig((a.y.as_rbig() + b.y.as_rbig()) / dashu_ratio::RBig::from(2)),
            );
            let c = add(&mid, &small(rng), &small(rng));
            [a, b, c]
        }
        // A needle: two vertices a small step apart, the third far off.
        1 => {
            let a = point(rng, canvas, snapped);
            let b = add(&a, &small(rng), &small(rng));
            [a, b, point(rng, canvas, snapped)]
        }
        // A vertex on a pixel corner, the triangle opening away from it:
        // the pixels on the corner's other sides are touched at one point.
        2 => {
            let (x, y) = (whole(rng, canvas.width), whole(rng, canvas.height));
            let a = at(x, y);
            let (sx, sy) = (*rng.pick(&[-1, 1]), *rng.pick(&[-1, 1]));
            let away = |rng: &mut Rng| {
                let d = Number::ratio(rng.range(0, 33), 8);
                let e = Number::ratio(rng.range(0, 33), 8);
                (
                    Number::from_rbig(d.as_rbig() * dashu_ratio::RBig::from(sx)),
                    Number::from_rbig(e.as_rbig() * dashu_ratio::RBig::from(sy)),
                )
            };
            let (dx, dy) = away(rng);
            let (ex, ey) = away(rng);
            [a.clone(), add(&a, &dx, &dy), add(&a, &ex, &ey)]
        }
        // An edge along a pixel border: two vertices on one whole x (or y).
        3 => {
            let c = whole(rng, canvas.width);
            let (p, q) = (grid(rng, canvas.height, 2), grid(rng, canvas.height, 2));
            let third = point(rng, canvas, snapped);
            if rng.chance(1, 2) {
                [at(c.clone(), p), at(c, q), third]
            } else {
                [at(p, c.clone()), at(q, c), Vertex::at(third.y, third.x)]
            }
        }
        // Degenerate: collinear on the half-pixel grid, two vertices the
        // same, or all three.
        4 => {
            let a = at(grid(rng, canvas.width, 2), grid(rng, canvas.height, 2));
            let step = (
                Number::ratio(rng.range(-8, 9), 2),
                Number::ratio(rng.range(-8, 9), 2),
            );
            let b = add(&a, &step.0, &step.1);
            let k = Number::from_int(rng.range(-2, 3));
            let c = add(
                &a,
                &Number::from_rbig(step.0.as_rbig() * k.as_rbig()),
                &Number::from_rbig(step.1.as_rbig() * k.as_rbig()),
            );
            match rng.below(3) {
                0 => [a.clone(), a.clone(), a],
                1 => [a.clone(), a, b],
                _ => [a, b, c],
            }
        }
        // Far away: vertices anywhere in the coordinate range.
        5 => {
            let far = |rng: &mut Rng| {
                Vertex::at(
                    Number::from_int(rng.range(-COORD_LIMIT, COORD_LIMIT + 1)),
                    Number::from_int(rng.range(-COORD_LIMIT, COORD_LIMIT + 1)),
                )
            };
            [far(rng), point(rng, canvas, snapped), far(rng)]
        }
        _ => [0, 1, 2].map(|_| point(rng, canvas, snapped)),
    }
}

/// A random point near the canvas: on whole or half pixels, a fine dyadic
/// grid, or (snapped scenes only) a free rational.
pub(super) fn point(rng: &mut Rng, canvas: Canvas, snapped: bool) -> Vertex {
    let coordinate = |rng: &mut Rng, size: u32| match rng.below(if snapped { 6 } else { 5 }) {
        0 => whole(rng, size),
        1 => grid(rng, size, 2),
        2 => grid(rng, size, 256),
        3 | 4 => grid(rng, size, 1 << 16),
        _ => {
            let den = rng.range(1, 1 << 20);
            Number::ratio(rng.range(-2 * den, (i64::from(size) + 2) * den), den)
        }
    };
    Vertex::at(
        coordinate(rng, canvas.width),
        coordinate(rng, canvas.height),
    )
}

/// A whole pixel coordinate within a pixel of a side of `size`.
pub(super) fn whole(rng: &mut Rng, size: u32) -> Number {
    Number::from_int(rng.range(-1, i64::from(size) + 2))
}

/// A multiple of 1/`den` within two pixels of a side of `size`.
pub(super) fn grid(rng: &mut Rng, size: u32, den: i64) -> Number {
    Number::ratio(rng.range(-2 * den, (i64::from(size) + 2) * den), den)
}

/// A small step, positive or negative, from 2^-16 to ¼ px: dyadic, so
/// that unsnapped scenes stay in fixed point.
pub(super) fn small(rng: &mut Rng) -> Number {
    let den = 1i64 << rng.range(2, 17);
    Number::ratio(rng.range(-1, 2) * rng.range(0, 5), den)
}
