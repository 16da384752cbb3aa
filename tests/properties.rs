//! Property tests: the production rasterizer against the exact reference,
//! and the reference's i128 fast path against its big-integer path, on
//! random triangles over the whole supported range; polygons and
//! antialiasing; and time coverage under motion blur.
//!
//! Case counts: proptest's default (256; 96 for the polygon and antialiasing
//! properties, whose exact areas cost more; 64 for motion blur's certified
//! oracle), or `PROPTEST_CASES` for long runs, which sets every property's
//! count (`PROPTEST_CASES=25600 cargo test --release --test properties`:
//! 100× the default and more). Failures
//! are shrunk to a minimal scene and saved in
//! `tests/properties.proptest-regressions`, which is committed.

use proptest::prelude::*;
use rastercheck::metrics;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference::{self, Arithmetic};
use rastercheck::scene::rules::limits::COORD_LIMIT;
use rastercheck::scene::{
    Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line, LineParameter,
    LineRule, Number, Primitive, Rules, Scene, Triangle, Vertex,
};

const SIZE: u32 = 24;

/// A coordinate: on the half-pixel grid (forcing ties at sample centres),
/// on the subpixel grid, free (snapping decides), or anywhere in the
/// coordinate range.
fn coordinate() -> impl Strategy<Value = Number> {
    let span = i64::from(SIZE) + 8;
    prop_oneof![
        4 => (-8..2 * span).prop_map(|h| Number::ratio(h, 2)),
        4 => (-8 * 4096..span * 4096).prop_map(|k| Number::ratio(k, 4096)),
        2 => (-8i64 << 20..span << 20, 1i64..1 << 20).prop_map(|(n, d)| Number::ratio(n, d)),
        1 => (-COORD_LIMIT..=COORD_LIMIT).prop_map(Number::from_int),
    ]
}

fn fill_rule() -> impl Strategy<Value = FillRule> {
    prop::sample::select(FillRule::ALL.to_vec())
}

fn rules() -> impl Strategy<Value = Rules> {
    (
        prop::sample::select(vec![
            Some(0u32),
            Some(1),
            Some(4),
            Some(8),
            Some(13),
            Some(14),
            Some(16),
        ]),
        fill_rule(),
        prop::sample::select(vec![Cull::None, Cull::Clockwise, Cull::CounterClockwise]),
    )
        .prop_map(|(subpixel_bits, fill_rule, cull)| Rules {
            subpixel_bits,
            fill_rule,
            cull,
        })
}

fn vertex() -> impl Strategy<Value = Vertex> {
    (coordinate(), coordinate(), -1000i64..1000, 1i64..400).prop_map(|(x, y, a, w)| {
        let mut v = Vertex::at(x, y);
        v.attributes = vec![Number::ratio(a, 10)];
        v.w = Number::ratio(w, 100);
        v
    })
}

fn scene() -> impl Strategy<Value = Scene> {
    (
        rules(),
        prop::collection::vec([vertex(), vertex(), vertex()], 1..4),
    )
        .prop_map(|(rules, triangles)| Scene {
            name: "property".to_owned(),
            description: String::new(),
            canvas: Canvas {
                width: SIZE,
                height: SIZE,
            },
            rules,
            primitives: triangles
                .into_iter()
                .map(|vertices| {
                    Primitive::Triangle(Triangle {
                        vertices,
                        interpolation: Interpolation::Perspective,
                    })
                })
                .collect(),
            effects: Effects::default(),
            expect: Expect::default(),
            attribute_count: 1,
            has_depth: false,
        })
}

/// A scene of one line, under any rule and width.
fn line_scene() -> impl Strategy<Value = Scene> {
    line_scene_of(LineRule::ALL.to_vec())
}

/// A scene of one line under one of `line_rules`.
fn line_scene_of(line_rules: Vec<LineRule>) -> impl Strategy<Value = Scene> {
    (
        rules(),
        vertex(),
        vertex(),
        prop::sample::select(line_rules),
        prop::sample::select(vec![
            Number::ONE,
            Number::from_int(2),
            Number::ratio(5, 2),
            Number::ratio(1, 3),
        ]),
        prop::sample::select(vec![LineParameter::Major, LineParameter::Projected]),
    )
        .prop_map(|(rules, a, b, rule, width, parameter)| {
            let width = if rule.is_wide() { width } else { Number::ONE };
            let line = Line {
                vertices: [a, b],
                rule,
                width,
                last_pixel: LastPixel::Include,
                parameter,
                interpolation: Interpolation::Perspective,
            };
            Scene {
                name: "property".to_owned(),
                description: String::new(),
                canvas: Canvas {
                    width: SIZE,
                    height: SIZE,
                },
                rules,
                primitives: vec![Primitive::Line(line)],
                effects: Effects::default(),
                expect: Expect::default(),
                attribute_count: 1,
                has_depth: false,
            }
        })
}

fn reversed(scene: &Scene) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        p.vertices_mut().reverse();
    }
    scene
}

proptest! {
    #[test]
    fn production_lines_equal_the_reference(scene in line_scene()) {
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        match Production.rasterize(&scene, &plan) {
            Ok(candidate) => {
                let m = metrics::measure(&scene, &reference, &candidate, None);
                prop_assert_eq!(m.coverage.mismatched(), 0, "{} missing, {} extra", m.coverage.missing, m.coverage.extra);
                for ch in &m.channels {
                    prop_assert!(ch.within_bounds(), "{}: {:e} > {:e}", ch.channel, ch.max_abs, ch.allowed_abs);
                }
            }
            // Only non-dyadic widths (1/3 here) are beyond production's fixed point.
            Err(e) => prop_assert!(format!("{e}").contains("width"), "{e}"),
        }
    }

    #[test]
    // Diamond-exit depends on direction by definition (SPEC.md §4.2).
    fn reference_lines_are_the_same_drawn_either_way(
        scene in line_scene_of(vec![LineRule::Midpoint, LineRule::Rectangle, LineRule::Parallelogram])
    ) {
        let plan = Plan::for_scene(&scene);
        let forward = reference::render(&scene, &plan);
        let backward = reference::render(&reversed(&scene), &plan);
        prop_assert_eq!(forward.coverage, backward.coverage);
    }


    #[test]
    fn production_coverage_equals_the_reference(scene in scene()) {
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        let candidate = Production.rasterize(&scene, &plan).unwrap();
        let m = metrics::coverage::compare(&reference, &candidate);
        prop_assert_eq!(m.mismatched(), 0, "{} missing, {} extra, {} wrong owner", m.missing, m.extra, m.wrong_owner);
    }

    #[test]
    fn production_interpolation_stays_within_the_documented_bound(scene in scene()) {
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        let candidate = Production.rasterize(&scene, &plan).unwrap();
        let m = metrics::measure(&scene, &reference, &candidate, None);
        for ch in &m.channels {
            prop_assert!(ch.within_bounds(), "{}: {:e} > {:e}", ch.channel, ch.max_abs, ch.allowed_abs);
        }
    }

    #[test]
    fn the_i128_fast_path_equals_big_integers(scene in scene()) {
        let plan = Plan::for_scene(&scene);
        let fast = reference::render_with(&scene, &plan, Arithmetic::Auto);
        let big = reference::render_with(&scene, &plan, Arithmetic::BigOnly);
        prop_assert_eq!(fast, big);
    }
}

// ---------------------------------------------------------------------------
// Invariances, watertight meshes, exact values at vertices, and the range.
// ---------------------------------------------------------------------------

use dashu_ratio::RBig;
use rastercheck::frame::Frame;
use rastercheck::rasterizer::RasterError;
use rastercheck::reference::exact;
use rastercheck::scene::rules::limits::{VALUE_LIMIT, W_LIMIT};
use rastercheck::scene::{parse_case, Limits};

/// Subpixel bits: every value 0..=16, and `null` (exact coordinates).
fn any_bits() -> impl Strategy<Value = Option<u32>> {
    prop_oneof![6 => (0u32..=16).prop_map(Some), 1 => Just(None)]
}

/// A coordinate near [lo, hi) (in pixels), or anywhere within ±`far`:
/// on the half-pixel grid (ties at sample centres and pixel edges), on a
/// dyadic grid of 2^-k for k in 0..=16 (snapping ties for coarser bits),
/// a free rational with a denominator of up to 2^40, or an integer or a free
/// rational anywhere in ±`far`.
fn coord(lo: i64, hi: i64, far: i64) -> impl Strategy<Value = Number> {
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

fn any_interpolation() -> impl Strategy<Value = Interpolation> {
    prop::sample::select(vec![
        Interpolation::Perspective,
        Interpolation::Linear,
        Interpolation::Flat,
    ])
}

fn any_cull() -> impl Strategy<Value = Cull> {
    prop::sample::select(vec![Cull::None, Cull::Clockwise, Cull::CounterClockwise])
}

/// A vertex at (x, y) with depth, w and `attributes` values in range.
fn valued_vertex(
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

fn scene_of(width: u32, height: u32, rules: Rules, primitives: Vec<Primitive>) -> Scene {
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
    }
}

/// Production's frame, or `None` where it declines the scene: unsnapped
/// coordinates that are not multiples of 2^-16, or line widths it cannot
/// hold in fixed point (SPEC.md §8). Anything else is a failure.
fn production(scene: &Scene, plan: &Plan) -> Result<Option<Frame>, TestCaseError> {
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

/// Asserts production's interpolated values are within SPEC.md §6.3's bound.
fn assert_values_within_bound(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
) -> Result<(), TestCaseError> {
    let m = metrics::measure(scene, reference, candidate, None);
    for ch in &m.channels {
        prop_assert!(
            ch.within_bounds(),
            "{}: {:e} > {:e}",
            ch.channel,
            ch.max_abs,
            ch.allowed_abs
        );
    }
    Ok(())
}

/// Asserts that sample (x, y) of `a` equals sample (x + dx, y + dy) of `b`
/// wherever both are on the canvas: coverage, last primitive, depth and
/// every attribute, bit for bit.
fn assert_shifted(a: &Frame, b: &Frame, dx: i64, dy: i64, who: &str) -> Result<(), TestCaseError> {
    let (w, h) = (i64::from(a.width), i64::from(a.height));
    let mut compared = 0;
    for y in 0..h {
        for x in 0..w {
            let (u, v) = (x + dx, y + dy);
            if !(0..w).contains(&u) || !(0..h).contains(&v) {
                continue;
            }
            let (i, j) = ((y * w + x) as usize, (v * w + u) as usize);
            compared += 1;
            prop_assert_eq!(
                a.coverage[i],
                b.coverage[j],
                "{} coverage at ({}, {})",
                who,
                x,
                y
            );
            prop_assert_eq!(a.last[i], b.last[j], "{} owner at ({}, {})", who, x, y);
            if let (Some(da), Some(db)) = (&a.depth, &b.depth) {
                prop_assert_eq!(
                    da[i].to_bits(),
                    db[j].to_bits(),
                    "{} depth at ({}, {})",
                    who,
                    x,
                    y
                );
            }
            for (k, (ca, cb)) in a.attributes.iter().zip(&b.attributes).enumerate() {
                prop_assert_eq!(
                    ca[i].to_bits(),
                    cb[j].to_bits(),
                    "{} attribute {} at ({}, {}): {} vs {}",
                    who,
                    k,
                    x,
                    y,
                    ca[i],
                    cb[j]
                );
            }
        }
    }
    prop_assert!(compared > 0);
    Ok(())
}

const TSIZE: u32 = 32;

/// A primitive near the canvas (or reaching anywhere in range, kept 64 px
/// inside it so that a translation by up to 32 px stays in range).
fn near_primitive() -> impl Strategy<Value = Primitive> {
    let c = || coord(-8, i64::from(TSIZE) + 8, COORD_LIMIT - 64);
    let v = move || valued_vertex((c(), c()), 1);
    prop_oneof![
        3 => ([v(), v(), v()], any_interpolation()).prop_map(|(vertices, interpolation)| {
            Primitive::Triangle(Triangle { vertices, interpolation })
        }),
        1 => (
            [v(), v()],
            prop::sample::select(LineRule::ALL.to_vec()),
            prop::sample::select(vec![Number::ONE, Number::from_int(3), Number::ratio(5, 2), Number::ratio(3, 4)]),
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

fn near_scene(triangles_only: bool) -> impl Strategy<Value = Scene> {
    (
        any_bits(),
        fill_rule(),
        any_cull(),
        prop::collection::vec(near_primitive(), 1..4),
    )
        .prop_map(move |(subpixel_bits, fill_rule, cull, mut primitives)| {
            if triangles_only {
                primitives.retain(|p| matches!(p, Primitive::Triangle(_)));
            }
            let rules = Rules {
                subpixel_bits,
                fill_rule,
                cull,
            };
            scene_of(TSIZE, TSIZE, rules, primitives)
        })
        .prop_filter("at least one triangle", |s| !s.primitives.is_empty())
}

fn map_vertices(scene: &Scene, f: impl Fn(&mut Vertex)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        p.vertices_mut().iter_mut().for_each(&f);
    }
    scene
}

fn map_triangles(scene: &Scene, f: impl Fn(&mut Triangle)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        if let Primitive::Triangle(t) = p {
            f(t);
        }
    }
    scene
}

proptest! {
    /// Moving every vertex by whole pixels moves the frame: exactly, for
    /// coverage, owners and every value, in the reference and in production.
    /// (With 0 subpixel bits a shift must be even: snapping's ties go to
    /// even integers, so an odd shift moves a tie the other way.)
    #[test]
    fn whole_pixel_translation_shifts_the_frame_exactly(
        scene in near_scene(false),
        dx in -(TSIZE as i64 - 1)..TSIZE as i64,
        dy in -(TSIZE as i64 - 1)..TSIZE as i64,
    ) {
        let (dx, dy) = if scene.rules.subpixel_bits == Some(0) { (dx / 2 * 2, dy / 2 * 2) } else { (dx, dy) };
        let moved = map_vertices(&scene, |v| {
            v.x = &v.x + &Number::from_int(dx);
            v.y = &v.y + &Number::from_int(dy);
        });
        let plan = Plan::for_scene(&scene);
        assert_shifted(&reference::render(&scene, &plan), &reference::render(&moved, &plan), dx, dy, "reference")?;
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&moved, &plan)?) {
            assert_shifted(&a, &b, dx, dy, "production")?;
        }
    }

    /// (v0, v1, v2) → (v1, v2, v0) changes no coverage, and no value of a
    /// linear or perspective triangle (flat takes the first vertex's).
    #[test]
    fn rotating_the_vertex_order_changes_nothing(scene in near_scene(true)) {
        let scene = map_triangles(&scene, |t| {
            if t.interpolation == Interpolation::Flat {
                t.interpolation = Interpolation::Linear;
            }
        });
        let rotated = map_triangles(&scene, |t| t.vertices.rotate_left(1));
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        prop_assert_eq!(&reference, &reference::render(&rotated, &plan));
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&rotated, &plan)?) {
            prop_assert_eq!(&a.coverage, &b.coverage);
            prop_assert_eq!(&a.last, &b.last);
            assert_values_within_bound(&rotated, &reference, &b)?;
        }
    }

    /// (v0, v1, v2) → (v0, v2, v1) reverses the winding: with cull none it
    /// changes nothing (flat included: v0 stays first); with culling, it
    /// changes nothing when the culled winding is swapped too.
    #[test]
    fn reversing_the_winding_changes_nothing_but_culling(scene in near_scene(true)) {
        let reversed = map_triangles(&scene, |t| t.vertices.swap(1, 2));
        let mut reversed = reversed;
        reversed.rules.cull = match scene.rules.cull {
            Cull::None => Cull::None,
            Cull::Clockwise => Cull::CounterClockwise,
            Cull::CounterClockwise => Cull::Clockwise,
        };
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        prop_assert_eq!(&reference, &reference::render(&reversed, &plan));
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&reversed, &plan)?) {
            prop_assert_eq!(&a.coverage, &b.coverage);
            prop_assert_eq!(&a.last, &b.last);
            assert_values_within_bound(&reversed, &reference, &b)?;
        }
    }
}

// --- Watertight meshes -----------------------------------------------------

const MSIZE: u32 = 24;

type Exact2 = [RBig; 2];

/// Where a rasterizer puts a coordinate: snapped, or exact under `null`.
fn placed(n: &Number, bits: Option<u32>) -> RBig {
    match bits {
        Some(b) => exact::snap(n, b),
        None => n.as_rbig().clone(),
    }
}

fn orient(a: &Exact2, b: &Exact2, c: &Exact2) -> std::cmp::Ordering {
    let v = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
    v.cmp(&RBig::ZERO)
}

/// A planar shape to triangulate into a mesh.
#[derive(Clone, Debug)]
enum Shape {
    /// Points and triangles whose interiors do not overlap (before snapping).
    Triangles(Vec<[Number; 2]>, Vec<[usize; 3]>),
    /// A polygon, star-shaped around `centre`, to be ear-clipped after
    /// snapping.
    Star {
        centre: [f64; 2],
        points: Vec<[Number; 2]>,
    },
}

/// Denominators of mesh vertices: a dyadic grid of 2^-k (grid-aligned,
/// forcing ties), or a free odd denominator up to 2^40.
fn denominator() -> impl Strategy<Value = i64> {
    prop_oneof![
        3 => (0u32..=16).prop_map(|k| 1i64 << k),
        1 => (1i64..1 << 40).prop_map(|d| d | 1),
    ]
}

fn to_number(v: f64, den: i64) -> Number {
    Number::ratio((v * den as f64).round() as i64, den)
}

/// A mesh centre: a sample centre, or any coordinate on the canvas.
fn mesh_centre() -> impl Strategy<Value = [Number; 2]> {
    let m = i64::from(MSIZE);
    prop_oneof![
        (0..m, 0..m).prop_map(|(i, j)| [Number::ratio(2 * i + 1, 2), Number::ratio(2 * j + 1, 2)]),
        (coord(0, m, m), coord(0, m, m)).prop_map(|(x, y)| [x, y]),
    ]
}

/// Radii: a few pixels, the canvas, or far out in the guard band.
fn radius_scale() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![1.5, 4.0, 12.0, 40.0, 20000.0])
}

/// `n` angles in order around a circle, each gap below π.
fn angles(n: usize) -> impl Strategy<Value = Vec<f64>> {
    (
        prop::collection::vec(1.0f64..1.9, n),
        0.0f64..std::f64::consts::TAU,
    )
        .prop_map(|(gaps, phase)| {
            let total: f64 = gaps.iter().sum();
            let mut a = phase;
            gaps.iter()
                .map(|g| {
                    a += std::f64::consts::TAU * g / total;
                    a
                })
                .collect()
        })
}

/// A fan around a centre: around a sample centre, a free point, or a vertex
/// of the snapping grid.
fn fan() -> impl Strategy<Value = Shape> {
    (3usize..16).prop_flat_map(|n| {
        (
            mesh_centre(),
            angles(n),
            prop::collection::vec(0.5f64..1.5, n),
            radius_scale(),
            denominator(),
        )
            .prop_map(move |(c, angles, radii, scale, den)| {
                let (cx, cy) = (c[0].to_f64_lossy(), c[1].to_f64_lossy());
                let mut points = vec![c];
                for (a, r) in angles.iter().zip(&radii) {
                    let r = r * scale;
                    points.push([
                        to_number(cx + r * a.cos(), den),
                        to_number(cy + r * a.sin(), den),
                    ]);
                }
                let triangles = (1..=n).map(|k| [0, k, k % n + 1]).collect();
                Shape::Triangles(points, triangles)
            })
    })
}

/// A convex polygon (points on a circle), triangulated as a fan from its
/// first vertex.
fn convex_polygon() -> impl Strategy<Value = Shape> {
    (3usize..14).prop_flat_map(|n| {
        (mesh_centre(), angles(n), radius_scale(), denominator()).prop_map(
            move |(c, angles, scale, den)| {
                let (cx, cy) = (c[0].to_f64_lossy(), c[1].to_f64_lossy());
                let points = angles
                    .iter()
                    .map(|a| {
                        [
                            to_number(cx + scale * a.cos(), den),
                            to_number(cy + scale * a.sin(), den),
                        ]
                    })
                    .collect();
                let triangles = (1..n - 1).map(|k| [0, k, k + 1]).collect();
                Shape::Triangles(points, triangles)
            },
        )
    })
}

/// A simple polygon: star-shaped around a centre, with random radii.
fn star_polygon() -> impl Strategy<Value = Shape> {
    (4usize..14).prop_flat_map(|n| {
        (
            mesh_centre(),
            angles(n),
            prop::collection::vec(0.3f64..1.5, n),
            radius_scale(),
            denominator(),
        )
            .prop_map(move |(c, angles, radii, scale, den)| {
                let centre = [c[0].to_f64_lossy(), c[1].to_f64_lossy()];
                let points = angles
                    .iter()
                    .zip(&radii)
                    .map(|(a, r)| {
                        let r = r * scale;
                        [
                            to_number(centre[0] + r * a.cos(), den),
                            to_number(centre[1] + r * a.sin(), den),
                        ]
                    })
                    .collect();
                Shape::Star { centre, points }
            })
    })
}

/// A jittered lattice (jitter below a quarter of the spacing keeps every
/// triangle's orientation), each quad split along a random diagonal.
fn jittered_grid() -> impl Strategy<Value = Shape> {
    (1usize..=8, 1usize..=8).prop_flat_map(|(n, m)| {
        (
            (coord(-8, 1, 8), coord(-8, 1, 8)),
            prop::sample::select(vec![0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 4000.0]),
            prop::collection::vec((-0.24f64..0.24, -0.24f64..0.24), (n + 1) * (m + 1)),
            prop::collection::vec(any::<bool>(), n * m),
            denominator(),
        )
            .prop_map(move |((ox, oy), s, jitter, diagonals, den)| {
                let (ox, oy) = (ox.to_f64_lossy(), oy.to_f64_lossy());
                let at = |i: usize, j: usize| j * (n + 1) + i;
                let points = (0..=m)
                    .flat_map(|j| (0..=n).map(move |i| (i, j)))
                    .map(|(i, j)| {
                        let (jx, jy) = jitter[at(i, j)];
                        let (x, y) = (ox + s * (i as f64 + jx), oy + s * (j as f64 + jy));
                        [to_number(x, den), to_number(y, den)]
                    })
                    .collect();
                let mut triangles = Vec::new();
                for j in 0..m {
                    for i in 0..n {
                        let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                        if diagonals[j * n + i] {
                            triangles.extend([[a, b, c], [a, c, d]]);
                        } else {
                            triangles.extend([[a, b, d], [b, c, d]]);
                        }
                    }
                }
                Shape::Triangles(points, triangles)
            })
    })
}

/// A mesh scene: the shape snapped under `bits`, each triangle's winding
/// reversed or its vertices rotated at random. `None` when snapping folded
/// a triangle over (the shape is then no longer a mesh).
fn mesh_scene_of(shape: Shape, bits: Option<u32>, shuffles: &[u8]) -> Option<Scene> {
    let (points, triangles) = match shape {
        Shape::Triangles(points, triangles) => (points, triangles),
        Shape::Star { centre, points } => {
            let placed_points: Vec<Exact2> = points
                .iter()
                .map(|p| p.each_ref().map(|c| placed(c, bits)))
                .collect();
            let c = centre.map(|v| {
                Number::ratio((v * 65536.0).round() as i64, 65536)
                    .as_rbig()
                    .clone()
            });
            let n = placed_points.len();
            let signs: Vec<_> = (0..n)
                .map(|k| orient(&c, &placed_points[k], &placed_points[(k + 1) % n]))
                .collect();
            if signs.iter().any(|s| *s != signs[0] || s.is_eq()) {
                return None;
            }
            let triangles = rastercheck::explore::fuzz::ear_clip(&placed_points, signs[0])?;
            (points, triangles)
        }
    };
    let placed_points: Vec<Exact2> = points
        .iter()
        .map(|p| p.each_ref().map(|c| placed(c, bits)))
        .collect();
    let signs: Vec<_> = triangles
        .iter()
        .map(|t| {
            orient(
                &placed_points[t[0]],
                &placed_points[t[1]],
                &placed_points[t[2]],
            )
        })
        .collect();
    if signs.iter().any(|s| *s != signs[0] || s.is_eq()) {
        return None;
    }
    let primitives = triangles
        .iter()
        .zip(shuffles.iter().cycle())
        .map(|(t, shuffle)| {
            let mut vertices = t.map(|i| Vertex::at(points[i][0].clone(), points[i][1].clone()));
            if shuffle & 1 != 0 {
                vertices.swap(1, 2);
            }
            vertices.rotate_left(usize::from(shuffle >> 1) % 3);
            Primitive::Triangle(Triangle {
                vertices,
                interpolation: Interpolation::Perspective,
            })
        })
        .collect();
    let rules = Rules {
        subpixel_bits: bits,
        fill_rule: FillRule::TopLeft,
        cull: Cull::None,
    };
    let mut scene = scene_of(MSIZE, MSIZE, rules, primitives);
    scene.has_depth = false;
    Some(scene)
}

fn mesh_scene() -> impl Strategy<Value = Scene> {
    (
        prop_oneof![fan(), jittered_grid(), convex_polygon(), star_polygon()],
        any_bits(),
        prop::collection::vec(any::<u8>(), 1..32),
    )
        .prop_filter_map("snapping folded a triangle", |(shape, bits, shuffles)| {
            mesh_scene_of(shape, bits, &shuffles)
        })
}

/// Every interior sample covered once, and no sample covered twice.
fn assert_mesh_coverage(frame: &Frame, interior: &[bool], who: &str) -> Result<(), TestCaseError> {
    for (i, (&count, &inside)) in frame.coverage.iter().zip(interior).enumerate() {
        let (x, y) = (i % MSIZE as usize, i / MSIZE as usize);
        prop_assert!(
            count <= 1,
            "{}: sample ({}, {}) covered {} times",
            who,
            x,
            y,
            count
        );
        prop_assert!(
            !inside || count == 1,
            "{}: interior sample ({}, {}) is a hole",
            who,
            x,
            y
        );
    }
    Ok(())
}

proptest! {
    /// Fans, jittered grids, convex fans and ear-clipped simple polygons,
    /// with random windings: under each consistent rule, each interior
    /// sample is covered exactly once and no sample twice (SPEC.md §3, §6.2).
    #[test]
    fn meshes_are_covered_exactly_once_under_every_consistent_rule(scene in mesh_scene()) {
        let interior = reference::mesh_interior(&scene);
        let plan = Plan::for_scene(&scene);
        for rule in FillRule::CONSISTENT {
            let mut scene = scene.clone();
            scene.rules.fill_rule = rule;
            assert_mesh_coverage(&reference::render(&scene, &plan), &interior, &format!("reference, {rule}"))?;
            if let Some(frame) = production(&scene, &plan)? {
                assert_mesh_coverage(&frame, &interior, &format!("production, {rule}"))?;
            }
        }
    }
}

// --- Exact values at vertices ---------------------------------------------

const VSIZE: u32 = 16;

/// The pixel whose sample centre a placed position is, if on the canvas.
fn centre_pixel(p: &[RBig; 2], size: u32) -> Option<usize> {
    let half = RBig::from_parts(1.into(), 2u8.into());
    let mut at = [0usize; 2];
    for axis in 0..2 {
        let t = &p[axis] - &half;
        if t.denominator() != &dashu_int::UBig::ONE {
            return None;
        }
        let i: i64 = t.numerator().try_into().ok()?;
        if !(0..i64::from(size)).contains(&i) {
            return None;
        }
        at[axis] = i as usize;
    }
    Some(at[1] * size as usize + at[0])
}

/// A vertex position: a sample centre on the canvas, a sample centre
/// anywhere in range, or any coordinate.
fn vertex_position() -> impl Strategy<Value = (Number, Number)> {
    let near = || (0..i64::from(VSIZE)).prop_map(|i| Number::ratio(2 * i + 1, 2));
    let anywhere = || (-COORD_LIMIT..COORD_LIMIT).prop_map(|i| Number::ratio(2 * i + 1, 2));
    let free = || coord(-4, i64::from(VSIZE) + 4, COORD_LIMIT);
    prop_oneof![
        4 => (near(), near()),
        1 => (anywhere(), anywhere()),
        1 => (near(), anywhere()),
        1 => (free(), free()),
    ]
}

fn vertex_scene() -> impl Strategy<Value = Scene> {
    (1usize..=3).prop_flat_map(|attributes| {
        (
            prop_oneof![4 => (1u32..=16).prop_map(Some), 1 => Just(None)],
            fill_rule(),
            any_interpolation(),
            [
                valued_vertex((near_centre(), near_centre()), attributes).boxed(),
                valued_vertex(vertex_position(), attributes).boxed(),
                valued_vertex(vertex_position(), attributes).boxed(),
            ],
        )
            .prop_map(|(subpixel_bits, fill_rule, interpolation, vertices)| {
                let rules = Rules {
                    subpixel_bits,
                    fill_rule,
                    cull: Cull::None,
                };
                scene_of(
                    VSIZE,
                    VSIZE,
                    rules,
                    vec![Primitive::Triangle(Triangle {
                        vertices,
                        interpolation,
                    })],
                )
            })
    })
}

fn near_centre() -> impl Strategy<Value = Number> {
    (0..i64::from(VSIZE)).prop_map(|i| Number::ratio(2 * i + 1, 2))
}

proptest! {
    /// At a vertex that lies on a sample centre, the reference writes the
    /// vertex's own depth and attributes (the first vertex's for flat), as
    /// the correctly rounded f32 (checked against dashu's conversion), and
    /// production is within SPEC.md §6.3's bound of them. Under `all-edges`
    /// a triangle with area covers its vertices' samples.
    #[test]
    fn interpolation_reproduces_vertex_values_at_sample_centres(scene in vertex_scene()) {
        let Primitive::Triangle(t) = &scene.primitives[0] else { unreachable!() };
        let bits = scene.rules.subpixel_bits;
        let positions: Vec<[RBig; 2]> = t.vertices.iter().map(|v| [placed(&v.x, bits), placed(&v.y, bits)]).collect();
        let area = orient(&positions[0], &positions[1], &positions[2]);
        let plan = Plan::for_scene(&scene);
        let reference = reference::render(&scene, &plan);
        let candidate = production(&scene, &plan)?;
        let bound = |values: Vec<&Number>| {
            metrics::DEFAULT_RELATIVE_BOUND
                * values.iter().map(|v| v.abs().to_f64_lossy()).fold(1.0, f64::max)
        };
        for (i, p) in positions.iter().enumerate() {
            let Some(pixel) = centre_pixel(p, VSIZE) else { continue };
            if scene.rules.fill_rule == FillRule::AllEdges && !area.is_eq() {
                prop_assert_eq!(reference.last[pixel], 1, "vertex {} not covered under all-edges", i);
            }
            let mut expected = vec![(
                "depth",
                &t.vertices[i].z,
                reference.depth.as_ref().unwrap()[pixel],
                candidate.as_ref().map(|c| c.depth.as_ref().unwrap()[pixel]),
                bound(t.vertices.iter().map(|v| &v.z).collect()),
            )];
            let source = if t.interpolation == Interpolation::Flat { 0 } else { i };
            for k in 0..scene.attribute_count {
                expected.push((
                    "attribute",
                    &t.vertices[source].attributes[k],
                    reference.attributes[k][pixel],
                    candidate.as_ref().map(|c| c.attributes[k][pixel]),
                    bound(t.vertices.iter().map(|v| &v.attributes[k]).collect()),
                ));
            }
            if reference.last[pixel] != 1 {
                continue;
            }
            for (what, value, exact_out, candidate_out, allowed) in expected {
                let q = value.as_rbig();
                prop_assert_eq!(exact_out.to_bits(), exact::to_f64_round_odd(q).to_bits(), "{} at vertex {}", what, i);
                prop_assert_eq!((exact_out as f32).to_bits(), q.to_f32().value().to_bits(), "{} at vertex {}: f32", what, i);
                if let (Some(out), Some(c)) = (candidate_out, &candidate) {
                    if c.last[pixel] == 1 {
                        prop_assert!((out - exact_out).abs() <= allowed, "production {} at vertex {}: {} vs {} (bound {:e})", what, i, out, exact_out, allowed);
                    }
                }
            }
        }
    }
}

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
    prop_oneof![
        2 => ([v(), v(), v()], any_interpolation()).prop_map(|(vertices, interpolation)| {
            Primitive::Triangle(Triangle { vertices, interpolation })
        }),
        1 => (
            [v(), v()],
            prop::sample::select(LineRule::ALL.to_vec()),
            line_width(),
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

// --- The reader at the edges of the range ---------------------------------

/// What a slot of the template case holds, which decides its range.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slot {
    Side,
    Bits,
    Coord,
    Value,
    W,
    Width,
    Tolerance,
}

/// The template's slots: JSON path, kind, and in-range default.
fn slots() -> Vec<(String, Slot, &'static str)> {
    let mut s = vec![
        ("$.canvas.width".to_owned(), Slot::Side, "8"),
        ("$.canvas.height".to_owned(), Slot::Side, "8"),
        ("$.rules.subpixel_bits".to_owned(), Slot::Bits, "8"),
    ];
    let defaults = [["0", "0"], ["8", "0"], ["0", "8"]];
    for (i, d) in defaults.iter().enumerate() {
        let v = format!("$.primitives[0].triangle[{i}]");
        s.push((format!("{v}.position[0]"), Slot::Coord, d[0]));
        s.push((format!("{v}.position[1]"), Slot::Coord, d[1]));
        s.push((format!("{v}.z"), Slot::Value, "0.5"));
        s.push((format!("{v}.w"), Slot::W, "1"));
        s.push((format!("{v}.attributes[0]"), Slot::Value, "-3"));
    }
    for i in 0..2 {
        s.push((
            format!("$.primitives[1].line[{i}].position[0]"),
            Slot::Coord,
            "1",
        ));
        s.push((
            format!("$.primitives[1].line[{i}].position[1]"),
            Slot::Coord,
            "2",
        ));
    }
    s.push(("$.primitives[1].width".to_owned(), Slot::Width, "2"));
    s.push((
        "$.expect.max_abs_error".to_owned(),
        Slot::Tolerance,
        "0.001",
    ));
    s
}

/// The template case with `texts` in its slots (in `slots()` order).
fn template(texts: &[String]) -> String {
    let mut t = texts.iter();
    let mut n = || t.next().unwrap().clone();
    let canvas = format!(r#"{{"width": {}, "height": {}}}"#, n(), n());
    let rules = format!(r#"{{"subpixel_bits": {}, "fill_rule": "top-left"}}"#, n());
    let vertices: Vec<String> = (0..3)
        .map(|_| {
            format!(
                r#"{{"position": [{}, {}], "z": {}, "w": {}, "attributes": [{}, 1]}}"#,
                n(),
                n(),
                n(),
                n(),
                n()
            )
        })
        .collect();
    let ends: Vec<String> = (0..2)
        .map(|_| {
            format!(
                r#"{{"position": [{}, {}], "attributes": [0, 0]}}"#,
                n(),
                n()
            )
        })
        .collect();
    let line = format!("[{}]", ends.join(", "));
    format!(
        r#"{{"name": "range", "canvas": {canvas}, "rules": {rules},
  "primitives": [{{"triangle": [{}]}},
    {{"line": {line}, "rule": "rectangle", "width": {}, "interpolation": "linear"}}],
  "expect": {{"max_abs_error": {}}}}}"#,
        vertices.join(", "),
        n(),
        n()
    )
}

/// Exact text for `base + sign · step/den`, as a JSON number or fraction
/// string.
fn offset_text(base: i128, step: i128, den: i128, as_fraction: bool) -> String {
    let n = base * den + step;
    if as_fraction {
        format!("\"{n}/{den}\"")
    } else if den == 1 {
        format!("{n}")
    } else {
        // den is a power of ten here.
        let digits = den.to_string().len() - 1;
        let (sign, m) = if n < 0 { ("-", -n) } else { ("", n) };
        let int = m / den;
        let frac = m % den;
        format!("{sign}{int}.{frac:0digits$}")
    }
}

/// A value for a slot of kind `slot` and whether it is in range: the limits
/// themselves, a hair inside or outside them, far outside, the wrong sign,
/// non-finite strings, and numbers too long to read.
fn slot_value(slot: Slot) -> impl Strategy<Value = (String, bool)> {
    let (lo, hi, lo_open): (i128, i128, bool) = match slot {
        Slot::Side => (1, 16384, false),
        Slot::Bits => (0, 16, false),
        Slot::Coord => (-32768, 32768, false),
        Slot::Value => (-1_000_000_000_000, 1_000_000_000_000, false),
        // w ≥ 10^-6: scaled by the denominator below.
        Slot::W => (0, 1_000_000, false),
        Slot::Width => (0, 1024, true),
        Slot::Tolerance => (0, 1_000_000_000_000, false),
    };
    let integral = matches!(slot, Slot::Side | Slot::Bits);
    let dens: Vec<i128> = if integral {
        vec![1]
    } else {
        vec![1, 10, 1_000_000, 1 << 40, 3, 1_000_000_000_000]
    };
    (
        prop::sample::select(dens),
        0u8..8,
        any::<bool>(),
        1i128..1000,
    )
        .prop_map(move |(den, pick, as_fraction, far)| {
            let frac = as_fraction || ![1, 10, 1_000_000, 1_000_000_000_000].contains(&den);
            match pick {
                // The limits themselves (open at 0 for widths, at 10^-6 for w).
                0 => match slot {
                    Slot::W => (
                        offset_text(0, den / 1_000_000, den, frac),
                        den % 1_000_000 == 0,
                    ),
                    _ => (offset_text(lo, 0, den, frac), !lo_open),
                },
                1 => (offset_text(hi, 0, den, frac), true),
                // A hair outside.
                2 => match slot {
                    Slot::W => (offset_text(0, den / 1_000_000 - 1, den, frac), false),
                    _ => (offset_text(lo, -1, den, frac), false),
                },
                3 => (offset_text(hi, 1, den, frac), false),
                // Far outside.
                4 => (offset_text(hi * far, 1, den, frac), false),
                5 => (offset_text(-hi * far - 1, 0, 1, false), false),
                6 => (prop_oneof_text(far as usize, slot), false),
                // A hair inside.
                _ => match slot {
                    Slot::W | Slot::Side | Slot::Bits => (
                        offset_text(hi, -1, den, frac),
                        hi * den > lo * den + if slot == Slot::W { den / 1_000_000 } else { 0 },
                    ),
                    _ => (offset_text(lo, 1, den, frac), true),
                },
            }
        })
}

/// Texts that are never numbers in range: non-finite strings, zero
/// denominators, too many digits, too large exponents; for integer slots,
/// fractions.
fn prop_oneof_text(k: usize, slot: Slot) -> String {
    let texts = [
        "\"NaN\"".to_owned(),
        "\"-Infinity\"".to_owned(),
        "\"inf\"".to_owned(),
        "\"1/0\"".to_owned(),
        format!("1{}", "0".repeat(1000)),
        "1e1001".to_owned(),
        "1e-1001".to_owned(),
        "\"1e999999999\"".to_owned(),
        "true".to_owned(),
        "[1]".to_owned(),
    ];
    match slot {
        Slot::Side | Slot::Bits if k % 3 < 1 => "\"3/2\"".to_owned(),
        _ => texts[k % texts.len()].clone(),
    }
}

proptest! {
    /// Every number slot of a case, at its documented limits, a hair either
    /// side and far beyond: in range it reads, out of range the reader
    /// returns an error naming that slot's JSON path (never a panic).
    #[test]
    fn the_reader_accepts_the_range_and_names_the_path_beyond_it(
        (index, (text, valid)) in (0..slots().len()).prop_flat_map(|i| (Just(i), slot_value(slots()[i].1)))
    ) {
        let slots = slots();
        let mut texts: Vec<String> = slots.iter().map(|s| s.2.to_owned()).collect();
        texts[index] = text.clone();
        let case = template(&texts);
        let result = std::panic::catch_unwind(|| parse_case(&case, "range.json", &Limits::default()));
        prop_assert!(result.is_ok(), "the reader panicked on {}", case);
        match result.unwrap() {
            Ok(_) => prop_assert!(valid, "{} = {} was accepted", slots[index].0, text),
            Err(e) => {
                prop_assert!(!valid, "{} = {} was refused: {}", slots[index].0, text, e);
                prop_assert_eq!(&e.location, &slots[index].0, "{} = {}: {}", slots[index].0, text, e);
            }
        }
    }
}

/// The limits that belong to a whole object rather than one number.
#[test]
fn the_reader_names_the_object_that_breaks_a_count_limit() {
    let parse = |text: &str| parse_case(text, "limits.json", &Limits::default());
    let triangle = r#"{"triangle": [[0, 0], [1, 0], [0, 1]]}"#;
    let case = |canvas: &str, primitives: &str| {
        format!(r#"{{"name": "n", "canvas": {canvas}, "primitives": [{primitives}]}}"#)
    };
    let e = parse(&case(r#"{"width": 16384, "height": 1025}"#, triangle)).unwrap_err();
    assert_eq!(e.location, "$.canvas", "{e}");
    assert!(parse(&case(r#"{"width": 16384, "height": 1024}"#, triangle)).is_ok());
    let vertex = |n: usize| {
        format!(
            r#"{{"position": [0, 0], "attributes": [{}]}}"#,
            vec!["1"; n].join(", ")
        )
    };
    let with_attributes = |n: usize| format!(r#"{{"triangle": [{v}, {v}, {v}]}}"#, v = vertex(n));
    assert!(parse(&case(r#"{"width": 4, "height": 4}"#, &with_attributes(16))).is_ok());
    let e = parse(&case(r#"{"width": 4, "height": 4}"#, &with_attributes(17))).unwrap_err();
    assert_eq!(e.location, "$.primitives[0].triangle[0].attributes", "{e}");
    let many = vec![triangle; 100_001].join(",");
    let e = parse(&case(r#"{"width": 4, "height": 4}"#, &many)).unwrap_err();
    assert_eq!(e.location, "$.primitives", "{e}");
}

// --- Polygons and antialiasing (SPEC.md §14) --------------------------------

use rastercheck::scene::{Antialias, Pattern, Polygon, PolygonFill};

/// `PROPTEST_CASES` when set (long runs), else `default`: the exact areas
/// of polygons cost more than a triangle's frame, so these properties run
/// fewer cases by default.
fn config(default: u32) -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    ProptestConfig {
        cases,
        ..ProptestConfig::default()
    }
}

const ASIZE: u32 = 16;

/// A coordinate inside [0, size]: on the half-pixel grid (ties at pixel
/// centres and borders), on a 1/16 grid (the standard patterns' lattice:
/// ties at samples), on a 1/4096 grid, or a free rational.
fn inside(size: u32) -> impl Strategy<Value = Number> {
    let s = i64::from(size);
    prop_oneof![
        3 => (0..=2 * s).prop_map(|h| Number::ratio(h, 2)),
        3 => (0..=16 * s).prop_map(|k| Number::ratio(k, 16)),
        2 => (0..=4096 * s).prop_map(|k| Number::ratio(k, 4096)),
        2 => (1i64..1 << 20).prop_flat_map(move |d| (0..=s * d).prop_map(move |n| Number::ratio(n, d))),
    ]
}

fn point_in(size: u32) -> impl Strategy<Value = Vertex> {
    (inside(size), inside(size)).prop_map(|(x, y)| Vertex::at(x, y))
}

/// A vertex anywhere in the coordinate range: tie-forcing half-pixels and
/// 1/16ths near the canvas, free rationals, or integers to ±32768.
fn point_anywhere() -> impl Strategy<Value = Vertex> {
    let near = prop_oneof![
        (-8i64..2 * (i64::from(ASIZE) + 8)).prop_map(|h| Number::ratio(h, 2)),
        (-128i64..16 * (i64::from(ASIZE) + 8)).prop_map(|k| Number::ratio(k, 16)),
        (-8i64 << 20..(i64::from(ASIZE) + 8) << 20, 1i64..1 << 20)
            .prop_map(|(n, d)| Number::ratio(n, d)),
    ];
    let any = prop_oneof![
        6 => near,
        1 => (-COORD_LIMIT..=COORD_LIMIT).prop_map(Number::from_int),
    ];
    (any.clone(), any).prop_map(|(x, y)| Vertex::at(x, y))
}

fn fill() -> impl Strategy<Value = PolygonFill> {
    prop::sample::select(vec![PolygonFill::NonZero, PolygonFill::EvenOdd])
}

/// A polygon of 1 to 3 contours of 3 to 8 vertices (random vertices: most
/// contours cross themselves and each other), or a rectangle with a hole
/// whose contour runs either way.
fn polygon_of(point: BoxedStrategy<Vertex>, size: u32) -> impl Strategy<Value = Polygon> {
    let contours = prop::collection::vec(prop::collection::vec(point.clone(), 3..9), 1..4);
    let random = (contours, fill()).prop_map(|(cs, fill)| {
        let mut vertices = Vec::new();
        let mut contour_ends = Vec::new();
        for c in cs {
            vertices.extend(c);
            contour_ends.push(vertices.len());
        }
        Polygon {
            vertices,
            contour_ends,
            fill,
        }
    });
    let s = i64::from(size);
    let holed = (
        prop::collection::vec(point, 3..7),
        fill(),
        any::<bool>(),
        1..s / 4,
    )
        .prop_map(move |(hole, fill, reverse, m)| {
            let corner = |x: i64, y: i64| Vertex::at(Number::from_int(x), Number::from_int(y));
            let mut outer = vec![
                corner(m, m),
                corner(s - m, m),
                corner(s - m, s - m),
                corner(m, s - m),
            ];
            if reverse {
                outer.reverse();
            }
            let mut vertices = outer;
            vertices.extend(hole);
            Polygon {
                contour_ends: vec![4, vertices.len()],
                vertices,
                fill,
            }
        });
    prop_oneof![3 => random, 1 => holed]
}

fn parallelogram(a: Vertex, b: Vertex, width: Number) -> Primitive {
    Primitive::Line(Line {
        vertices: [a, b],
        rule: LineRule::Parallelogram,
        width,
        last_pixel: LastPixel::Include,
        parameter: LineParameter::Major,
        interpolation: Interpolation::Perspective,
    })
}

/// Triangles, polygons and parallelogram lines with every vertex in the
/// canvas (a parallelogram's ends 2 px in from the sides, its width at
/// most 2, so its sides stay in too).
fn inside_primitive() -> impl Strategy<Value = Primitive> {
    let triangle = [point_in(ASIZE), point_in(ASIZE), point_in(ASIZE)].prop_map(|vertices| {
        Primitive::Triangle(Triangle {
            vertices,
            interpolation: Interpolation::Perspective,
        })
    });
    let end = (inside(ASIZE - 4), inside(ASIZE - 4))
        .prop_map(|(x, y)| {
            let two = Number::from_int(2);
            Vertex::at(&x + &two, &y + &two)
        })
        .boxed();
    let width = prop::sample::select(vec![
        Number::ratio(1, 16),
        Number::ratio(1, 3),
        Number::ONE,
        Number::from_int(2),
    ]);
    let line = (end.clone(), end, width).prop_map(|(a, b, w)| parallelogram(a, b, w));
    let polygon = polygon_of(point_in(ASIZE).boxed(), ASIZE).prop_map(Primitive::Polygon);
    prop_oneof![2 => triangle, 1 => line, 2 => polygon]
}

/// Any primitive with vertices anywhere in the coordinate range.
fn anywhere_primitive() -> impl Strategy<Value = Primitive> {
    let triangle = [point_anywhere(), point_anywhere(), point_anywhere()].prop_map(|vertices| {
        Primitive::Triangle(Triangle {
            vertices,
            interpolation: Interpolation::Perspective,
        })
    });
    let width = prop::sample::select(vec![Number::ratio(1, 2), Number::ONE, Number::from_int(3)]);
    let line =
        (point_anywhere(), point_anywhere(), width).prop_map(|(a, b, w)| parallelogram(a, b, w));
    let polygon = polygon_of(point_anywhere().boxed(), ASIZE).prop_map(Primitive::Polygon);
    prop_oneof![2 => triangle, 1 => line, 2 => polygon]
}

/// `effects.antialias`: any pattern at a count it allows, any seed,
/// adaptive or not, position bits 4 to 16.
fn antialias() -> impl Strategy<Value = Antialias> {
    let patterned = prop_oneof![
        prop::sample::select(vec![1u32, 2, 4, 8, 16]).prop_map(|n| (Pattern::Standard, n)),
        prop::sample::select(vec![1u32, 4, 16, 64]).prop_map(|n| (Pattern::Grid, n)),
        prop::sample::select(vec![1u32, 4, 16, 64]).prop_map(|n| (Pattern::Stratified, n)),
        prop::sample::select(vec![1u32, 3, 16, 32]).prop_map(|n| (Pattern::Random, n)),
        prop::sample::select(vec![1u32, 5, 16, 32]).prop_map(|n| (Pattern::NRooks, n)),
    ];
    (
        patterned,
        0u64..1000,
        any::<bool>(),
        prop_oneof![3 => Just(8u32), 1 => 4u32..=16],
    )
        .prop_map(
            |((pattern, samples), seed, adaptive, position_bits)| Antialias {
                samples,
                pattern,
                seed: if pattern.is_seeded() { seed } else { 0 },
                adaptive,
                position_bits,
            },
        )
}

/// Rules for scenes with polygons: the four consistent fill rules (SPEC.md
/// §14.1), no culling, any snapping.
fn polygon_rules() -> impl Strategy<Value = Rules> {
    (
        prop::sample::select(vec![None, Some(0u32), Some(4), Some(8), Some(16)]),
        prop::sample::select(FillRule::CONSISTENT.to_vec()),
    )
        .prop_map(|(subpixel_bits, fill_rule)| Rules {
            subpixel_bits,
            fill_rule,
            cull: Cull::None,
        })
}

fn aa_scene_of(primitives: Vec<Primitive>, rules: Rules, antialias: Option<Antialias>) -> Scene {
    Scene {
        name: "property".to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: ASIZE,
            height: ASIZE,
        },
        rules,
        primitives,
        effects: Effects {
            antialias,
            motion_blur: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
    }
}

fn inside_scene() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(inside_primitive(), 1..4),
        polygon_rules(),
        antialias(),
    )
        .prop_map(|(p, r, a)| aa_scene_of(p, r, Some(a)))
}

fn anywhere_scene() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(anywhere_primitive(), 1..4),
        polygon_rules(),
        prop::option::weighted(0.7, antialias()),
    )
        .prop_map(|(p, r, a)| aa_scene_of(p, r, a))
}

fn total(areas: &[RBig]) -> RBig {
    areas.iter().fold(RBig::ZERO, |sum, a| sum + a)
}

fn map_polygons(scene: &Scene, f: impl Fn(&mut Polygon)) -> Scene {
    let mut scene = scene.clone();
    for p in &mut scene.primitives {
        if let Primitive::Polygon(q) = p {
            f(q);
        }
    }
    scene
}

/// Each contour of `p` rotated left by `k` (mod its length), or reversed.
fn per_contour(p: &mut Polygon, f: impl Fn(&mut [Vertex])) {
    let mut start = 0;
    for &end in &p.contour_ends {
        f(&mut p.vertices[start..end]);
        start = end;
    }
}

/// Asserts sample (x, y, s) of `a` equals sample (x + dx, y + dy, s) of `b`
/// (coverage and owner) wherever both are on the canvas.
fn assert_mask_shifted(
    a: &Frame,
    b: &Frame,
    dx: i64,
    dy: i64,
    who: &str,
) -> Result<(), TestCaseError> {
    let (w, h, n) = (i64::from(a.width), i64::from(a.height), a.samples as usize);
    for y in 0..h {
        for x in 0..w {
            let (u, v) = (x + dx, y + dy);
            if !(0..w).contains(&u) || !(0..h).contains(&v) {
                continue;
            }
            let (i, j) = ((y * w + x) as usize * n, (v * w + u) as usize * n);
            prop_assert_eq!(
                &a.coverage[i..i + n],
                &b.coverage[j..j + n],
                "{} mask at ({}, {})",
                who,
                x,
                y
            );
            prop_assert_eq!(
                &a.last[i..i + n],
                &b.last[j..j + n],
                "{} owners at ({}, {})",
                who,
                x,
                y
            );
        }
    }
    Ok(())
}

/// Production's mask equals the reference's, sample for sample.
fn assert_production_equals_reference(scene: &Scene) -> Result<(), TestCaseError> {
    let plan = Plan::for_scene(scene);
    let reference = reference::render(scene, &plan);
    if let Some(frame) = production(scene, &plan)? {
        prop_assert_eq!(frame.samples, reference.samples);
        prop_assert!(frame.coverage == reference.coverage, "coverage differs");
        prop_assert!(frame.last == reference.last, "owners differ");
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(96))]

    /// The exact per-pixel areas of primitives inside the canvas sum to
    /// their whole areas, computed without pixels (a rational equality):
    /// triangles, parallelogram lines, and polygons simple,
    /// self-intersecting and with holes, under both fills.
    #[test]
    fn exact_areas_sum_to_the_primitive_areas(scene in inside_scene()) {
        let whole = (0..scene.primitives.len())
            .fold(RBig::ZERO, |sum, i| sum + reference::primitive_area(&scene, i));
        prop_assert_eq!(total(&reference::exact_areas(&scene)), whole);
    }

    /// Moving every vertex by whole pixels moves the antialiased mask and
    /// the exact areas exactly, in the reference and in production. (With
    /// 0 subpixel bits the shift is even: snapping ties go to even.)
    #[test]
    fn whole_pixel_translation_shifts_masks_and_areas_exactly(
        scene in inside_scene(),
        dx in -6i64..7,
        dy in -6i64..7,
    ) {
        let (dx, dy) = if scene.rules.subpixel_bits == Some(0) { (dx / 2 * 2, dy / 2 * 2) } else { (dx, dy) };
        let moved = map_vertices(&scene, |v| {
            v.x = &v.x + &Number::from_int(dx);
            v.y = &v.y + &Number::from_int(dy);
        });
        let plan = Plan::for_scene(&scene);
        assert_mask_shifted(&reference::render(&scene, &plan), &reference::render(&moved, &plan), dx, dy, "reference")?;
        if let (Some(a), Some(b)) = (production(&scene, &plan)?, production(&moved, &plan)?) {
            assert_mask_shifted(&a, &b, dx, dy, "production")?;
        }
        let (a, b) = (reference::exact_areas(&scene), reference::exact_areas(&moved));
        let w = i64::from(ASIZE);
        for y in 0..w {
            for x in 0..w {
                let (u, v) = (x + dx, y + dy);
                if (0..w).contains(&u) && (0..w).contains(&v) {
                    prop_assert_eq!(&a[(y * w + x) as usize], &b[(v * w + u) as usize], "area at ({}, {})", x, y);
                }
            }
        }
    }

    /// Rotating each contour's vertex order changes nothing; reversing every
    /// contour changes nothing under either fill (the winding number only
    /// changes sign); reversing one contour changes nothing under even-odd
    /// (its parity is unchanged). Masks, owners and exact areas, in the
    /// reference and in production.
    #[test]
    fn contour_order_and_direction_change_nothing(
        scene in inside_scene(),
        k in 1usize..8,
        which in 0usize..3,
    ) {
        let rotated = map_polygons(&scene, |p| per_contour(p, |c| { let n = c.len(); c.rotate_left(k % n) }));
        let reversed = map_polygons(&scene, |p| per_contour(p, |c| c.reverse()));
        let one_reversed = map_polygons(&scene, |p| {
            if p.fill == PolygonFill::EvenOdd {
                let c = which % p.contour_ends.len();
                let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
                p.vertices[start..p.contour_ends[c]].reverse();
            }
        });
        let plan = Plan::for_scene(&scene);
        let frame = reference::render(&scene, &plan);
        let areas = reference::exact_areas(&scene);
        let produced = production(&scene, &plan)?;
        for (what, other) in [("rotated", &rotated), ("reversed", &reversed), ("one contour reversed", &one_reversed)] {
            let f = reference::render(other, &plan);
            prop_assert!(f.coverage == frame.coverage && f.last == frame.last, "reference mask, {}", what);
            prop_assert!(reference::exact_areas(other) == areas, "exact areas, {}", what);
            if let (Some(a), Some(b)) = (&produced, production(other, &plan)?) {
                prop_assert!(a.coverage == b.coverage && a.last == b.last, "production mask, {}", what);
            }
        }
    }

    /// Production equals the reference sample for sample on polygons (and
    /// triangles and parallelogram lines beside them) with tie-forcing and
    /// free vertices anywhere in the coordinate range, with and without
    /// antialiasing (every pattern, adaptive or not).
    #[test]
    fn production_equals_the_reference_on_polygons_and_antialiasing(scene in anywhere_scene()) {
        assert_production_equals_reference(&scene)?;
    }
}

// --- Motion blur (SPEC.md §15) ----------------------------------------------

/// How one vertex of a moving scene moves.
#[derive(Clone, Debug)]
enum Motion {
    /// A position.
    Still,
    /// `from` and `to` that differ by less than half a subpixel step:
    /// both ends snap to the same point, so the vertex moves in the case
    /// file (the scene goes through the time loop) but not on the grid.
    Within(i64),
    /// A real move, by up to 4 px in 1/256 steps.
    By(i64, i64),
}

const BLUR_SIZE: i64 = 8;

/// n / 2^bits as the exact decimal a case file spells.
fn dyadic(n: i64, bits: u32) -> String {
    let scaled = i128::from(n.unsigned_abs()) * 5i128.pow(bits);
    let ten = 10i128.pow(bits);
    let fraction = format!("{:0width$}", scaled % ten, width = bits as usize);
    let fraction = fraction.trim_end_matches('0');
    let sign = if n < 0 { "-" } else { "" };
    if fraction.is_empty() {
        format!("{sign}{}", scaled / ten)
    } else {
        format!("{sign}{}.{fraction}", scaled / ten)
    }
}

fn motion() -> impl Strategy<Value = Motion> {
    prop_oneof![
        1 => Just(Motion::Still),
        2 => (1i64..1 << 11).prop_map(Motion::Within),
        3 => (-1024i64..1025, -1024i64..1025).prop_map(|(x, y)| Motion::By(x, y)),
    ]
}

/// 1 or 2 triangles on an 8² canvas, 8 subpixel bits, vertices on the
/// 1/256 grid (ties at centres, edges through samples), each still,
/// moving within a snap step, or moving; under `effects.motion_blur` with
/// every pattern, 1 to 16 time samples, a full or partial shutter, and
/// sometimes 4× antialiasing. `real` = false keeps every vertex from
/// moving on the grid.
fn moving_case(real: bool) -> impl Strategy<Value = (String, String)> {
    let vertex = (
        (-256i64..(BLUR_SIZE + 1) * 256),
        (-256i64..(BLUR_SIZE + 1) * 256),
        motion(),
    );
    let triangle = prop::collection::vec(vertex, 3);
    (
        prop::collection::vec(triangle, 1..3),
        prop::sample::select(vec![
            "random",
            "stratified",
            "jittered-xy-t",
            "stratified-shuffled",
        ]),
        1u32..17,
        any::<bool>(),
        any::<bool>(),
        prop::sample::select(vec!["none", "cw", "ccw"]),
        any::<u16>(),
    )
        .prop_map(move |(triangles, pattern, n, partial, aa, cull, seed)| {
            let d = |n: i64| dyadic(n, 8);
            let still = |x: i64, y: i64| format!("[{}, {}]", d(x), d(y));
            let mut moving = Vec::new();
            let mut fixed = Vec::new();
            for t in &triangles {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                for (x, y, m) in t {
                    let m = match m {
                        Motion::By(..) if !real => &Motion::Within(1),
                        m => m,
                    };
                    b.push(still(*x, *y));
                    a.push(match m {
                        Motion::Still => still(*x, *y),
                        Motion::Within(k) => format!(
                            r#"{{"from": [{}, {}], "to": [{}, {}]}}"#,
                            d(*x),
                            d(*y),
                            dyadic(x * 4096 + k, 20),
                            d(*y)
                        ),
                        Motion::By(dx, dy) => format!(
                            r#"{{"from": [{}, {}], "to": [{}, {}]}}"#,
                            d(*x),
                            d(*y),
                            d(x + dx),
                            d(y + dy)
                        ),
                    });
                }
                moving.push(format!(r#"{{"triangle": [{}]}}"#, a.join(", ")));
                fixed.push(format!(r#"{{"triangle": [{}]}}"#, b.join(", ")));
            }
            let shutter = if partial { "[0.25, 0.75]" } else { "[0, 1]" };
            let antialias = if aa {
                r#", "antialias": {"samples": 4, "pattern": "standard"}"#
            } else {
                ""
            };
            let case = |primitives: &[String], effects: &str| {
                format!(
                    r#"{{"name": "p", "canvas": {{"width": {BLUR_SIZE}, "height": {BLUR_SIZE}}},
                    "rules": {{"subpixel_bits": 8, "cull": "{cull}"}},
                    "effects": {{{effects}}},
                    "primitives": [{}]}}"#,
                    primitives.join(", ")
                )
            };
            let blur = format!(
                r#""motion_blur": {{"shutter": {shutter}, "samples": {n}, "pattern": "{pattern}", "seed": {seed}}}"#
            );
            (
                case(&moving, &format!("{blur}{antialias}")),
                case(&fixed, antialias.trim_start_matches(", ")),
            )
        })
}

fn parse(text: &str) -> Result<Scene, rastercheck::scene::CaseError> {
    parse_case(text, "motion.json", &Limits::default())
}

/// Production's time coverage, or `None` when it does not draw the scene.
fn production_time(scene: &Scene, plan: &Plan) -> Option<Vec<f64>> {
    Production.rasterize(scene, plan).ok()?.time
}

proptest! {
    #![proptest_config(config(64))]

    /// Time coverage lies in [0, k] for k primitives (in [0, 1] for one),
    /// within the certified bound, in the reference and in production.
    #[test]
    fn time_coverage_lies_between_0_and_the_primitive_count(case in moving_case(true)) {
        let scene = parse(&case.0).expect("a valid moving case");
        let plan = Plan::for_scene(&scene);
        let k = RBig::from(scene.primitives.len() as u64);
        if plan.motion.is_none() {
            // Every vertex snapped still: nothing to measure over time.
            return Ok(());
        }
        for (p, c) in reference::motion::time_coverage(&scene, &plan).iter().enumerate() {
            prop_assert!(&c.value + &c.bound >= RBig::ZERO && &c.value - &c.bound <= k, "pixel {}: {} ± {}", p, c.value, c.bound);
        }
        if let Some(time) = production_time(&scene, &plan) {
            let k = scene.primitives.len() as f64;
            prop_assert!(time.iter().all(|t| (0.0..=k).contains(t)), "production: {:?}", time);
        }
    }

    /// When no vertex moves on the grid (each `to` snaps onto its `from`),
    /// the time loop still runs, and every pixel's time coverage equals
    /// its static coverage: covered spatial samples (counted per
    /// primitive) over M, exactly, with a bound of 0. The same in
    /// production.
    #[test]
    fn time_coverage_equals_the_static_coverage_when_nothing_moves(case in moving_case(false)) {
        let scene = parse(&case.0).expect("a valid moving case");
        let still = parse(&case.1).expect("the same case without motion");
        let plan = Plan::for_scene(&scene);
        let still_plan = Plan::for_scene(&still);
        prop_assert!(still_plan.motion.is_none());
        if !scene.moves() {
            return Ok(());
        }
        prop_assert!(plan.motion.is_some(), "a vertex with from ≠ to takes the time loop");
        let frame = reference::render(&still, &still_plan);
        let m = frame.samples as usize;
        let exact: Vec<RBig> = frame
            .coverage
            .chunks(m)
            .map(|s| RBig::from_parts(s.iter().map(|&c| u64::from(c)).sum::<u64>().into(), (m as u64).into()))
            .collect();
        let certified = reference::motion::time_coverage(&scene, &plan);
        for (p, (c, e)) in certified.iter().zip(&exact).enumerate() {
            prop_assert!(c.bound == RBig::ZERO && &c.value == e, "pixel {}: time {} ± {}, static {}", p, c.value, c.bound, e);
        }
        if let Some(time) = production_time(&scene, &plan) {
            for (p, (t, e)) in time.iter().zip(&exact).enumerate() {
                prop_assert_eq!(*t, e.to_f64().value(), "production, pixel {}", p);
            }
        }
    }
}

// --- Many coverage-only midpoint lines: production's banded path ------------

/// 1 to 40 coverage-only midpoint lines with ends anywhere around a 1024²
/// canvas (6 MiB of frame: production draws them band by band with
/// resumable walkers, `production/line.rs` `midpoint_lines`): half-pixel
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
