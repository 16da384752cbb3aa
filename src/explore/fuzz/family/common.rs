//! What the families share: canvases, rules, coordinates (ties, fine grids,
//! free rationals, far away), depth, w and attribute values, plain
//! triangles, and a scene from its parts. Nothing here decides a family's
//! mix of primitives.

use crate::explore::fuzz::rng::Rng;
use crate::scene::rules::limits::{COORD_LIMIT, MAX_SUBPIXEL_BITS, W_LIMIT};
use crate::scene::{
    Canvas, Cull, Effects, Expect, FillRule, Interpolation, Number, Primitive, Rules, Scene,
    Triangle, Vertex,
};

pub(super) fn canvas(rng: &mut Rng) -> Canvas {
    Canvas {
        width: *rng.pick(&[8, 16, 24, 32]),
        height: *rng.pick(&[8, 16, 24, 32]),
    }
}

pub(super) fn any_bits(rng: &mut Rng) -> Option<u32> {
    match rng.below(10) {
        0 => None,
        1..=3 => Some(8),
        _ => Some(rng.below(u64::from(MAX_SUBPIXEL_BITS) + 1) as u32),
    }
}

pub(super) fn any_rules(rng: &mut Rng) -> Rules {
    Rules {
        subpixel_bits: any_bits(rng),
        fill_rule: *rng.pick(&FillRule::ALL),
        cull: if rng.chance(3, 4) {
            Cull::None
        } else {
            *rng.pick(&[Cull::Clockwise, Cull::CounterClockwise])
        },
        ..Rules::default()
    }
}

/// A coordinate over a canvas side of `size`: on the half-pixel grid (ties
/// at sample centres and pixel edges), on a 1/4096 grid, a free rational,
/// or an integer anywhere in the coordinate range.
/// A random point for `canvas`, each coordinate from [`coordinate`].
pub(super) fn xy(rng: &mut Rng, canvas: Canvas) -> (Number, Number) {
    (
        coordinate(rng, canvas.width),
        coordinate(rng, canvas.height),
    )
}

/// A vertex of plain position at a random point (polygon scenes carry no
/// depth and no attributes).
pub(super) fn position(rng: &mut Rng, canvas: Canvas) -> Vertex {
    let (x, y) = xy(rng, canvas);
    Vertex::at(x, y)
}

fn coordinate(rng: &mut Rng, size: u32) -> Number {
    let span = i64::from(size) + 8;
    match rng.below(11) {
        0..=3 => Number::ratio(rng.range(-8, 2 * span), 2),
        4..=7 => Number::ratio(rng.range(-8 * 4096, span * 4096), 4096),
        8..=9 => Number::ratio(rng.range(-8 << 20, span << 20), rng.range(1, 1 << 20)),
        _ => Number::from_int(rng.range(-COORD_LIMIT, COORD_LIMIT + 1)),
    }
}

pub(super) fn value(rng: &mut Rng) -> Number {
    match rng.below(8) {
        0 => Number::from_int(rng.range(-1_000_000_000_000, 1_000_000_000_001)),
        1 => Number::ratio(rng.range(-(1 << 30), 1 << 30), rng.range(1, 1 << 30)),
        _ => Number::ratio(rng.range(-1000, 1001), 8),
    }
}

fn w_value(rng: &mut Rng) -> Number {
    match rng.below(12) {
        0 => Number::ratio(1, W_LIMIT),
        1 => Number::from_int(W_LIMIT),
        2..=5 => Number::ratio(rng.range(1, 400), 100),
        _ => Number::ONE,
    }
}

/// What the vertices of one scene carry besides their position.
pub(super) struct Values {
    pub(super) attributes: usize,
    pub(super) depth: bool,
    pub(super) w: bool,
}

impl Values {
    pub(super) fn any(rng: &mut Rng) -> Values {
        Values {
            attributes: *rng.pick(&[0, 0, 1, 2]),
            depth: rng.chance(1, 3),
            w: rng.chance(1, 2),
        }
    }

    pub(super) fn vertex(&self, rng: &mut Rng, x: Number, y: Number) -> Vertex {
        let mut v = Vertex::at(x, y);
        if self.depth {
            v.z = value(rng);
        }
        if self.w {
            v.w = w_value(rng);
        }
        v.attributes = (0..self.attributes).map(|_| value(rng)).collect();
        v
    }

    /// A vertex at a random point of `canvas` ([`xy`]), with its values.
    pub(super) fn random_vertex(&self, rng: &mut Rng, canvas: Canvas) -> Vertex {
        let (x, y) = xy(rng, canvas);
        self.vertex(rng, x, y)
    }
}

pub(super) fn any_interpolation(rng: &mut Rng) -> Interpolation {
    *rng.pick(&[
        Interpolation::Perspective,
        Interpolation::Perspective,
        Interpolation::Linear,
        Interpolation::Flat,
    ])
}

pub(super) fn scene_of(
    canvas: Canvas,
    rules: Rules,
    primitives: Vec<Primitive>,
    values: &Values,
) -> Scene {
    Scene {
        name: String::new(),
        description: String::new(),
        canvas,
        rules,
        primitives,
        effects: Effects::default(),
        expect: Expect::default(),
        attribute_count: values.attributes,
        has_depth: values.depth,
        viewport: None,
    }
}

/// A triangle of plain positions (scenes with polygons carry no depth and
/// no attributes).
pub(super) fn plain_triangle(rng: &mut Rng, canvas: Canvas) -> Primitive {
    let mut point = || position(rng, canvas);
    let vertices = [point(), point(), point()];
    Primitive::Triangle(Triangle {
        vertices,
        interpolation: Interpolation::Perspective,
    })
}
