//! Shared generators and checks: coordinates, values, vertices and scenes
//! over the documented range, production's frame where it accepts a scene,
//! and exact placement of coordinates. The properties live in the modules
//! beside this one.

use dashu_ratio::RBig;
use proptest::prelude::*;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference::exact;
use rastercheck::scene::rules::limits::{VALUE_LIMIT, W_LIMIT};
use rastercheck::scene::{
    Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line, LineParameter,
    LineRule, Number, Primitive, Rules, Scene, Triangle, Vertex,
};

pub fn fill_rule() -> impl Strategy<Value = FillRule> {
    prop::sample::select(FillRule::ALL.to_vec())
}

/// Subpixel bits: every value 0..=16, and `null` (exact coordinates).
pub fn any_bits() -> impl Strategy<Value = Option<u32>> {
    prop_oneof![6 => (0u32..=16).prop_map(Some), 1 => Just(None)]
}

/// A coordinate near [lo, hi) (in pixels), or anywhere within ±`far`:
/// on the half-pixel grid (ties at sample centres and pixel edges), on a
/// dyadic grid of 2^-k for k in 0..=16 (snapping ties for coarser bits),
/// a free rational with a denominator of up to 2^40, or an integer or a free
/// rational anywhere in ±`far`.
pub fn coord(lo: i64, hi: i64, far: i64) -> impl Strategy<Value = Number> {
    prop_oneof![
        4 => (2 * lo..2 * hi).prop_map(|h| Number::ratio(h, 2)),
        3 => (0u32..=16, any::<u64>()).prop_map(move |(k, r)| {
            let span = ((hi - lo) << k) as u64;
            Number::ratio((lo << k) + (r % span) as i64, 1 << k)
        }),
        2 => (1i64..1 << 40, any::<u64>()).prop_map(move |(d, r)| {
            let span = ((hi - lo) as u64) * d as u64;
            Number::ratio(lo * d + (r % span) as i64, d)
        }),
        1 => (-far..=far).prop_map(Number::from_int),
        1 => (1i64..1 << 40, any::<u64>()).prop_map(move |(d, r)| {
            let span = (2 * far as u64) * d as u64 + 1;
            Number::ratio(-far * d + (r % span) as i64, d)
        }),
    ]
}

/// A rational in [-limit, limit] (limit ≤ 10^12) with a denominator of up to
/// 2^40, the limits themselves included.
fn value_in(limit: i64) -> impl Strategy<Value = Number> {
    prop_oneof![
        3 => (-1000i64..=1000).prop_map(|n| Number::ratio(n, 8)),
        2 => (-(limit - 1)..limit, 1i64..1 << 40, any::<u64>())
            .prop_map(|(int, d, r)| &Number::from_int(int) + &Number::ratio((r % d as u64) as i64, d)),
        1 => (1i64..1 << 40, -(1i64 << 22)..(1 << 22)).prop_map(|(d, n)| Number::ratio(n, d)),
        1 => prop::sample::select(vec![-limit, limit, 0, -1, 1]).prop_map(Number::from_int),
    ]
}

/// w in [10^-6, 10^6]: the limits themselves, simple values, and rationals
/// with denominators up to 2^40.
fn w_value() -> impl Strategy<Value = Number> {
    prop_oneof![
        1 => Just(Number::ratio(1, W_LIMIT)),
        1 => Just(Number::from_int(W_LIMIT)),
        3 => (1i64..400).prop_map(|w| Number::ratio(w, 100)),
        // [10^-6, 10^6] as n / d with d ≤ 2^40.
        2 => (1i64..1 << 40, any::<u64>()).prop_map(|(d, r)| {
            let lo = (d + W_LIMIT - 1) / W_LIMIT; // ⌈d / 10^6⌉
            let hi = (W_LIMIT as i128 * d as i128).min(i64::MAX as i128) as i64;
            Number::ratio(lo.max(1) + (r % (hi - lo.max(1) + 1) as u64) as i64, d)
        }),
    ]
}

pub fn any_interpolation() -> impl Strategy<Value = Interpolation> {
    prop::sample::select(vec![
        Interpolation::Perspective,
        Interpolation::Linear,
        Interpolation::Flat,
    ])
}

pub fn any_cull() -> impl Strategy<Value = Cull> {
    prop::sample::select(vec![Cull::None, Cull::Clockwise, Cull::CounterClockwise])
}

/// A vertex at (x, y) with depth, w and `attributes` values in range.
pub fn valued_vertex(
    xy: impl Strategy<Value = (Number, Number)>,
    attributes: usize,
) -> impl Strategy<Value = Vertex> {
    (
        xy,
        value_in(VALUE_LIMIT),
        w_value(),
        prop::collection::vec(value_in(VALUE_LIMIT), attributes),
    )
        .prop_map(|((x, y), z, w, attributes)| Vertex {
            x,
            y,
            z,
            w,
            attributes,
            to: None,
        })
}

pub fn scene_of(width: u32, height: u32, rules: Rules, primitives: Vec<Primitive>) -> Scene {
    let attribute_count = primitives
        .first()
        .map_or(0, |p| p.vertices()[0].attributes.len());
    Scene {
        name: "property".to_owned(),
        description: String::new(),
        canvas: Canvas { width, height },
        rules,
        primitives,
        effects: Effects::default(),
        expect: Expect::default(),
        attribute_count,
        has_depth: true,
        viewport: None,
    }
}

/// Production's frame, or `None` where it declines the scene: unsnapped
/// coordinates that are not multiples of 2^-16, or line widths it cannot
/// hold in fixed point (SPEC.md §8). Anything else is a failure.
pub fn production(scene: &Scene, plan: &Plan) -> Result<Option<Frame>, TestCaseError> {
    match Production.rasterize(scene, plan) {
        Ok(frame) => Ok(Some(frame)),
        Err(RasterError::Unsupported(why)) => {
            prop_assert!(
                scene.rules.subpixel_bits.is_none() || why.contains("width"),
                "production declined a snapped scene: {why}"
            );
            Ok(None)
        }
        Err(e) => Err(TestCaseError::fail(format!("production broke: {e}"))),
    }
}

pub fn map_vertices(scene: &Scene, f: impl Fn(&mut Vertex)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        p.vertices_mut().iter_mut().for_each(&f);
    }
    scene
}

pub type Exact2 = [RBig; 2];

/// Where a rasterizer puts a coordinate: snapped, or exact under `null`.
pub fn placed(n: &Number, bits: Option<u32>) -> RBig {
    match bits {
        Some(b) => exact::snap(n, b),
        None => n.as_rbig().clone(),
    }
}

pub fn orient(a: &Exact2, b: &Exact2, c: &Exact2) -> std::cmp::Ordering {
    let v = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
    v.cmp(&RBig::ZERO)
}

/// A triangle (weight `triangles`) or a line (weight 1) of any rule, last
/// pixel and parameter, with vertices from `v` and, if the rule is wide, a
/// width from `width`.
pub fn triangle_or_line<V, W>(
    v: impl Fn() -> V,
    width: W,
    triangles: u32,
) -> impl Strategy<Value = Primitive>
where
    V: Strategy<Value = Vertex> + 'static,
    W: Strategy<Value = Number> + 'static,
{
    prop_oneof![
        triangles => ([v(), v(), v()], any_interpolation()).prop_map(|(vertices, interpolation)| {
            Primitive::Triangle(Triangle { vertices, interpolation })
        }),
        1 => (
            [v(), v()],
            prop::sample::select(LineRule::ALL.to_vec()),
            width,
            prop::sample::select(vec![LastPixel::Include, LastPixel::Exclude]),
            prop::sample::select(vec![LineParameter::Major, LineParameter::Projected]),
            any_interpolation(),
        )
            .prop_map(|(vertices, rule, width, last_pixel, parameter, interpolation)| {
                Primitive::Line(Line {
                    vertices,
                    rule,
                    width: if rule.is_wide() { width } else { Number::ONE },
                    last_pixel: if rule == LineRule::Midpoint { last_pixel } else { LastPixel::Include },
                    parameter,
                    interpolation,
                })
            }),
    ]
}
