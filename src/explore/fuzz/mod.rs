//! Counterexample search and shrinking: `rastercheck fuzz`.
//!
//! The fuzzer draws random and adversarial scenes from a seed, runs each
//! through the reference and a candidate rasterizer, and judges the
//! candidate with the same metrics and verdicts as `run`
//! ([`crate::metrics::failures`]). The first failure (or the first K) is shrunk to a
//! minimal scene that still fails the **same check** and written out as a
//! case file (SPEC.md §1) that `rastercheck run` reproduces.
//!
//! - **Generation** is deterministic from the seed: case `i` of seed `s`
//!   comes from its own [`Rng`] stream, so a case can be regenerated without
//!   the ones before it. Six families, taken in turn unless one is named:
//!   random triangles (tie-forcing half-pixel vertices, subpixel-grid and
//!   free rationals, vertices anywhere in the coordinate range, pairs sharing
//!   an edge), lines of every rule (strips, wide lines, both `last_pixel`s),
//!   and watertight meshes (fans around sample centres, jittered grids with
//!   shared vertices, convex fans and ear-clipped star polygons) with
//!   `expect.watertight: true`, polygons (one to three contours with
//!   repeated, collinear and doubled vertices, both fills), antialiased
//!   scenes (every pattern, 1 to 256 samples) and moving scenes (SPEC.md
//!   §15: translations, rotations, collapses through a point, vertices
//!   through sample centres, winding flips, double roots, vanishing τ²
//!   coefficients, under every time pattern and part of the shutter). No
//!   float function whose result may differ between machines is used (the
//!   sines are a fixed polynomial).
//! - **Failure kinds** ([`Kind`]): a candidate that breaks (error), holes and
//!   overdraw in a mesh, crowded midpoint-line steps, coverage, antialiased
//!   coverage, time coverage, and interpolation. A scene failing several
//!   checks is shrunk for the first in that order (or the one `--check`
//!   asks for).
//! - **Fair scenes only**: a scene the exact method with the case's own
//!   samples fails is no test of a candidate, and is skipped: the exact
//!   N-sample mask under antialiasing, and for a moving scene the sample
//!   method of §15.3 with the case's own instants, each test decided by the
//!   static reference (`sampled_time`), whose RMS can exceed the
//!   statistical bound where few pixels move.
//! - **Shrinking** is a greedy delta-debugging loop. Each pass proposes
//!   simpler scenes and keeps the first that still fails the same kind; the
//!   loop stops when a whole round of passes makes no progress (or after
//!   [`SHRINK_BUDGET`] evaluations). Passes: remove primitives (halves, then
//!   quarters, ... then one at a time); crop the canvas to the failing
//!   samples' neighbourhood and trim its sides, translating everything by
//!   whole pixels (a moving vertex's `from` and `to` together); drop depth,
//!   attributes, w, and non-default rules, line options and expectations
//!   that do not matter; fewer samples and time samples, the whole shutter,
//!   the simplest patterns and seeds; make moving vertices static; move
//!   vertices and the ends of their paths to simpler values (shared
//!   vertices together, then each on its own: integers near
//!   the canvas, coarser dyadic grids, halfway in from far away); simplify
//!   depth, w and attribute values; lower `subpixel_bits` when the snapping
//!   still matters. Every accepted step makes a well-founded measure
//!   smaller, so the loop ends; there is no randomness and no clock in it,
//!   so the same seed always writes the same file.
//! - **Mesh validity** is kept while shrinking: a scene that expects
//!   watertightness must stay a mesh (no zero-area triangle, and no sample
//!   covered twice under any of the four consistent fill rules), so a
//!   shrunk mesh case says what every correct rasterizer does.

use std::cmp::Ordering;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use dashu_int::UBig;
use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::harness::suite::{self, ReferenceRun, Verdict};
use crate::metrics::{Metrics, SampleDiff};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference::{self, exact::snap};
use crate::scene::rules::limits::{COORD_LIMIT, MAX_SUBPIXEL_BITS, W_LIMIT};
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    parse_case, Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel,
    Limits, Line, LineParameter, LineRule, MotionBlur, Number, Pattern, Polygon, PolygonFill,
    Primitive, Rules, Scene, TimePattern, TimePin, Triangle, Vertex,
};

/// Most candidate evaluations one shrink may spend.
pub const SHRINK_BUDGET: u64 = 20_000;

// --- Random numbers --------------------------------------------------------

/// SplitMix64 (Steele, Lea and Flood, OOPSLA 2014): a small, fast,
/// well-mixed generator whose stream depends only on its seed.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The stream of case `index` of a run with `seed`.
    pub fn for_case(seed: u64, index: u64) -> Rng {
        let mut mix = Rng(seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03));
        Rng(mix.next_u64())
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, n), n > 0.
    pub fn below(&mut self, n: u64) -> u64 {
        ((u128::from(self.next_u64()) * u128::from(n)) >> 64) as u64
    }

    /// Uniform in [lo, hi), lo < hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo) as u64) as i64
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// True with probability `num / den`.
    pub fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len() as u64) as usize]
    }
}

/// sin and cos by a fixed Taylor polynomial: the same bits on every machine
/// (only IEEE +, −, ×, ÷ and remainder), unlike the platform's libm.
fn sin_cos(angle: f64) -> (f64, f64) {
    let pi = std::f64::consts::PI;
    let mut x = angle % std::f64::consts::TAU;
    if x > pi {
        x -= std::f64::consts::TAU;
    } else if x < -pi {
        x += std::f64::consts::TAU;
    }
    let (mut s, mut c) = (0.0, 0.0);
    let (mut ts, mut tc) = (x, 1.0);
    for k in 0..16 {
        s += ts;
        c += tc;
        let k = f64::from(k);
        ts *= -x * x / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        tc *= -x * x / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
    }
    (s, c)
}

// --- Families and generation -----------------------------------------------

/// What the fuzzer generates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Random triangles, some sharing edges.
    Triangles,
    /// Lines of every rule, some in strips.
    Lines,
    /// Watertight meshes, with `expect.watertight: true`.
    Meshes,
    /// Polygons of one to three contours (self-intersecting, holes, doubled
    /// and repeated vertices) under both fills, with a triangle or two.
    Polygons,
    /// Triangles, polygons and parallelogram lines under
    /// `effects.antialias` (every pattern, 1 to 256 samples, adaptive or
    /// not, position bits 4 to 16).
    Antialias,
    /// Moving triangles and parallelogram lines under
    /// `effects.motion_blur` (SPEC.md §15): translations, rotations,
    /// collapses through a point, vertices through sample centres, winding
    /// flips, double roots, vanishing τ² coefficients; every time pattern,
    /// 1 to 64 time samples, parts of the shutter, sometimes antialiased.
    Motion,
}

impl Family {
    pub const ALL: [Family; 6] = [
        Family::Triangles,
        Family::Meshes,
        Family::Lines,
        Family::Polygons,
        Family::Antialias,
        Family::Motion,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Family::Triangles => "triangles",
            Family::Lines => "lines",
            Family::Meshes => "meshes",
            Family::Polygons => "polygons",
            Family::Antialias => "antialias",
            Family::Motion => "motion",
        }
    }

    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }
}

/// Case `index` of a run with `seed`: its family (the one asked for, or the
/// families in turn) and its scene.
pub fn generate(seed: u64, index: u64, family: Option<Family>) -> (Family, Scene) {
    let family = family.unwrap_or(Family::ALL[(index % Family::ALL.len() as u64) as usize]);
    let mut rng = Rng::for_case(seed, index);
    loop {
        let scene = match family {
            Family::Triangles => Some(triangle_scene(&mut rng)),
            Family::Lines => Some(line_scene(&mut rng)),
            Family::Meshes => mesh_scene(&mut rng),
            Family::Polygons => Some(polygon_scene(&mut rng)),
            Family::Antialias => Some(antialias_scene(&mut rng)),
            Family::Motion => Some(motion_scene(&mut rng)),
        };
        if let Some(mut scene) = scene.filter(|s| valid(s).is_ok()) {
            scene.name = format!("fuzz_{}_{seed}_{index}", family.name());
            return (family, scene);
        }
    }
}

fn num(r: &RBig) -> Number {
    Number::from_string(&format!("{}/{}", r.numerator(), r.denominator()))
        .expect("a ratio of integers is a number")
}

fn canvas(rng: &mut Rng) -> Canvas {
    Canvas {
        width: *rng.pick(&[8, 16, 24, 32]),
        height: *rng.pick(&[8, 16, 24, 32]),
    }
}

fn any_bits(rng: &mut Rng) -> Option<u32> {
    match rng.below(10) {
        0 => None,
        1..=3 => Some(8),
        _ => Some(rng.below(u64::from(MAX_SUBPIXEL_BITS) + 1) as u32),
    }
}

fn any_rules(rng: &mut Rng) -> Rules {
    Rules {
        subpixel_bits: any_bits(rng),
        fill_rule: *rng.pick(&FillRule::ALL),
        cull: if rng.chance(3, 4) {
            Cull::None
        } else {
            *rng.pick(&[Cull::Clockwise, Cull::CounterClockwise])
        },
    }
}

/// A coordinate over a canvas side of `size`: on the half-pixel grid (ties
/// at sample centres and pixel edges), on a 1/4096 grid, a free rational,
/// or an integer anywhere in the coordinate range.
/// A random point for `canvas`, each coordinate from [`coordinate`].
fn xy(rng: &mut Rng, canvas: Canvas) -> (Number, Number) {
    (
        coordinate(rng, canvas.width),
        coordinate(rng, canvas.height),
    )
}

/// A vertex of plain position at a random point (polygon scenes carry no
/// depth and no attributes).
fn position(rng: &mut Rng, canvas: Canvas) -> Vertex {
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

fn value(rng: &mut Rng) -> Number {
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
struct Values {
    attributes: usize,
    depth: bool,
    w: bool,
}

impl Values {
    fn any(rng: &mut Rng) -> Values {
        Values {
            attributes: *rng.pick(&[0, 0, 1, 2]),
            depth: rng.chance(1, 3),
            w: rng.chance(1, 2),
        }
    }

    fn vertex(&self, rng: &mut Rng, x: Number, y: Number) -> Vertex {
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
}

fn any_interpolation(rng: &mut Rng) -> Interpolation {
    *rng.pick(&[
        Interpolation::Perspective,
        Interpolation::Perspective,
        Interpolation::Linear,
        Interpolation::Flat,
    ])
}

fn scene_of(canvas: Canvas, rules: Rules, primitives: Vec<Primitive>, values: &Values) -> Scene {
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
    }
}

fn triangle_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let values = Values::any(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 5) {
        let point = |rng: &mut Rng| {
            let (x, y) = xy(rng, canvas);
            values.vertex(rng, x, y)
        };
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

fn line_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let values = Values::any(rng);
    let mut primitives: Vec<Primitive> = Vec::new();
    for _ in 0..rng.range(1, 4) {
        let point = |rng: &mut Rng| {
            let (x, y) = xy(rng, canvas);
            values.vertex(rng, x, y)
        };
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

// Polygons and antialiasing (SPEC.md §14).

/// One contour of 3 to 8 vertices; sometimes with a vertex repeated, a
/// vertex inserted halfway along an edge (collinear), or the whole contour
/// run twice (winding twice, every edge doubled).
fn contour(rng: &mut Rng, canvas: Canvas) -> Vec<Vertex> {
    let n = rng.range(3, 9) as usize;
    let mut vs: Vec<Vertex> = (0..n).map(|_| position(rng, canvas)).collect();
    if rng.chance(1, 5) {
        let k = rng.below(vs.len() as u64) as usize;
        let copy = vs[k].clone();
        vs.insert(k, copy);
    }
    if rng.chance(1, 5) {
        let k = rng.below(vs.len() as u64) as usize;
        let (a, b) = (&vs[k], &vs[(k + 1) % vs.len()]);
        let half = |p: &Number, q: &Number| num(&((p.as_rbig() + q.as_rbig()) / RBig::from(2u8)));
        let mid = Vertex::at(half(&a.x, &b.x), half(&a.y, &b.y));
        vs.insert(k + 1, mid);
    }
    if rng.chance(1, 10) {
        vs.extend(vs.clone());
    }
    vs
}

fn polygon(rng: &mut Rng, canvas: Canvas) -> Polygon {
    let mut vertices = Vec::new();
    let mut contour_ends = Vec::new();
    for _ in 0..*rng.pick(&[1, 1, 1, 2, 2, 3]) {
        vertices.extend(contour(rng, canvas));
        contour_ends.push(vertices.len());
    }
    let fill = *rng.pick(&[PolygonFill::NonZero, PolygonFill::EvenOdd]);
    Polygon {
        vertices,
        contour_ends,
        fill,
    }
}

/// A triangle of plain positions (scenes with polygons carry no depth and
/// no attributes).
fn plain_triangle(rng: &mut Rng, canvas: Canvas) -> Primitive {
    let mut point = || position(rng, canvas);
    let vertices = [point(), point(), point()];
    Primitive::Triangle(Triangle {
        vertices,
        interpolation: Interpolation::Perspective,
    })
}

/// Rules for polygons: every consistent fill rule (`all-edges` is an input
/// error there), no culling (it does not apply to polygons).
fn polygon_rules(rng: &mut Rng) -> Rules {
    Rules {
        subpixel_bits: any_bits(rng),
        fill_rule: *rng.pick(&FillRule::CONSISTENT),
        cull: Cull::None,
    }
}

fn polygon_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let mut primitives = Vec::new();
    for _ in 0..rng.range(1, 3) {
        primitives.push(Primitive::Polygon(polygon(rng, canvas)));
    }
    for _ in 0..*rng.pick(&[0, 0, 1, 2]) {
        let at = rng.below(primitives.len() as u64 + 1) as usize;
        let t = plain_triangle(rng, canvas);
        primitives.insert(at, t);
    }
    let none = Values {
        attributes: 0,
        depth: false,
        w: false,
    };
    scene_of(canvas, polygon_rules(rng), primitives, &none)
}

/// `effects.antialias` with a sample count valid for its pattern; more
/// samples on smaller canvases.
fn antialias(rng: &mut Rng, canvas: Canvas) -> Antialias {
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

fn antialias_scene(rng: &mut Rng) -> Scene {
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

// Motion blur (SPEC.md §15).

type Point = [RBig; 2];

fn ratio(n: i64, d: i64) -> RBig {
    Number::ratio(n, d).as_rbig().clone()
}

fn plus(a: &Point, b: &Point) -> Point {
    [&a[0] + &b[0], &a[1] + &b[1]]
}

fn minus(a: &Point, b: &Point) -> Point {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

fn times(k: &RBig, a: &Point) -> Point {
    [k * &a[0], k * &a[1]]
}

/// A coordinate within 4 px of a canvas side of `size`: on the half-pixel
/// grid (vertices on sample centres and pixel edges: ties), on the 1/256
/// and 1/4096 grids, or a free rational.
fn near(rng: &mut Rng, size: u32) -> RBig {
    let span = i64::from(size) + 4;
    match rng.below(10) {
        0..=4 => ratio(rng.range(-8, 2 * span), 2),
        5..=6 => ratio(rng.range(-4 * 256, span * 256), 256),
        7..=8 => ratio(rng.range(-4 * 4096, span * 4096), 4096),
        _ => ratio(rng.range(-4 << 20, span << 20), rng.range(1, 1 << 20)),
    }
}

fn near_point(rng: &mut Rng, canvas: Canvas) -> Point {
    [near(rng, canvas.width), near(rng, canvas.height)]
}

/// The centre of a random pixel of the canvas: the sample without
/// antialiasing.
fn pixel_centre(rng: &mut Rng, canvas: Canvas) -> Point {
    [
        ratio(2 * rng.range(0, canvas.width.into()) + 1, 2),
        ratio(2 * rng.range(0, canvas.height.into()) + 1, 2),
    ]
}

/// A sample centre or any point near the canvas.
fn pivot(rng: &mut Rng, canvas: Canvas) -> Point {
    if rng.chance(1, 2) {
        pixel_centre(rng, canvas)
    } else {
        near_point(rng, canvas)
    }
}

/// A displacement of at most `reach` px per axis: whole and half pixels
/// (a vertex on a sample centre stays on one), 1/256 steps, none, or free.
fn step(rng: &mut Rng, reach: i64) -> Point {
    let mut axis = || match rng.below(8) {
        0..=3 => ratio(rng.range(-2 * reach, 2 * reach + 1), 2),
        4..=5 => ratio(rng.range(-256 * reach, 256 * reach + 1), 256),
        6 => RBig::ZERO,
        _ => ratio(
            rng.range(-(reach << 20), (reach << 20) + 1),
            rng.range(1, 1 << 20),
        ),
    };
    [axis(), axis()]
}

/// Paths `[from, to]` of `n` vertices (2 or 3) under one of the motions
/// that make time coverage hard to get right (SPEC.md §15.2): a
/// translation (linear edge functions), a rotation and a free motion
/// (quadratics with irrational roots), a scaling through a point (the
/// primitive collapses to it at a rational instant, and turns inside out
/// for a negative factor), a vertex through a sample centre at a rational
/// instant, a vertex through the opposite edge (the winding flips), an
/// edge touching a sample centre without crossing it (a double root),
/// parallel velocities (the τ² coefficient vanishes, exactly or nearly),
/// and for lines a direction turning through 45° (the major axis changes
/// at τ = ½).
fn paths(rng: &mut Rng, canvas: Canvas, n: usize) -> Vec<[Point; 2]> {
    let reach = i64::from(canvas.width.max(canvas.height)) / 2 + 1;
    let starts =
        |rng: &mut Rng| -> Vec<Point> { (0..n).map(|_| near_point(rng, canvas)).collect() };
    let still = |points: Vec<Point>| -> Vec<[Point; 2]> {
        points.into_iter().map(|p| [p.clone(), p]).collect()
    };
    match rng.below(10) {
        0 => {
            let d = step(rng, reach);
            starts(rng)
                .into_iter()
                .map(|p| {
                    let to = plus(&p, &d);
                    [p, to]
                })
                .collect()
        }
        1 => {
            // The rotation's sine and cosine rounded to 1/4096: the path
            // of each vertex is a chord, not an arc, as every renderer's is.
            let c = pivot(rng, canvas);
            let (s, co) = sin_cos(rng.uniform(-std::f64::consts::PI, std::f64::consts::PI));
            let (s, co) = (
                ratio((s * 4096.0).round() as i64, 4096),
                ratio((co * 4096.0).round() as i64, 4096),
            );
            starts(rng)
                .into_iter()
                .map(|p| {
                    let r = minus(&p, &c);
                    let to = [
                        &c[0] + &co * &r[0] - &s * &r[1],
                        &c[1] + &s * &r[0] + &co * &r[1],
                    ];
                    [p, to]
                })
                .collect()
        }
        2 => {
            // Through c with factor k: every vertex is at c when
            // (1 − τ) + τ·k = 0, at τ = 1/(1 − k): ½ for −1, ¼ for −3,
            // ¾ for −1/3, at shutter close for 0.
            let c = pivot(rng, canvas);
            let (num_k, den_k) =
                *rng.pick(&[(-1, 1), (-3, 1), (-1, 3), (0, 1), (2, 1), (-2, 1), (1, 2)]);
            let k = ratio(num_k, den_k);
            starts(rng)
                .into_iter()
                .map(|p| {
                    let to = plus(&c, &times(&k, &minus(&p, &c)));
                    [p, to]
                })
                .collect()
        }
        3 => {
            // Vertex k from c − a·d to c + b·d: on the sample centre c at
            // τ = a/(a + b); the others still, or all translated.
            let mut out = still(starts(rng));
            if rng.chance(1, 2) {
                let d = step(rng, 2);
                for path in &mut out {
                    path[1] = plus(&path[1], &d);
                }
            }
            let k = rng.below(n as u64) as usize;
            let c = pixel_centre(rng, canvas);
            let (a, b) = (rng.range(1, 8), rng.range(1, 8));
            let d = [ratio(rng.range(-8, 9), 4), ratio(rng.range(-8, 9), 4)];
            out[k] = [
                minus(&c, &times(&ratio(a, 1), &d)),
                plus(&c, &times(&ratio(b, 1), &d)),
            ];
            out
        }
        4 if n == 3 => {
            // Vertex k to its mirror image through the midpoint of the
            // opposite edge: zero area at τ = ½ and the winding flipped
            // after; with another vertex moving too, the flip is at an
            // irrational instant.
            let p = starts(rng);
            let mut out = still(p.clone());
            let k = rng.below(3) as usize;
            out[k][1] = minus(&plus(&p[(k + 1) % 3], &p[(k + 2) % 3]), &p[k]);
            if rng.chance(1, 3) {
                let j = (k + 1) % 3;
                out[j][1] = plus(&out[j][1], &step(rng, 2));
            } else if rng.chance(1, 2) {
                let d = step(rng, reach);
                for path in &mut out {
                    path[1] = plus(&path[1], &d);
                }
            }
            out
        }
        5 => double_root(rng, canvas, n),
        6 => {
            // Velocities k·d: cross(v_a, v_b) = 0, so every edge
            // function and the area are linear in τ; nearly so when one
            // velocity is nudged by 2^-8 to 2^-16 (a root far away).
            let d = step(rng, 3);
            let nudge = rng.chance(1, 3);
            starts(rng)
                .into_iter()
                .map(|p| {
                    let k = ratio(rng.range(-4, 5), *rng.pick(&[1, 2]));
                    let mut to = plus(&p, &times(&k, &d));
                    if nudge && rng.chance(1, 2) {
                        let axis = rng.below(2) as usize;
                        to[axis] += ratio(*rng.pick(&[1, -1]), *rng.pick(&[256, 4096, 65536]));
                    }
                    [p, to]
                })
                .collect()
        }
        7 if n == 2 => {
            // Direction (l, l − k) at open, (l, l + k) at close: exactly
            // diagonal at τ = ½, where the major axis changes.
            let a = near_point(rng, canvas);
            let l = ratio(rng.range(2, 2 * reach + 1), 2);
            let k = ratio(rng.range(1, 2 * reach), 4);
            let (sx, sy) = (ratio(*rng.pick(&[1, -1]), 1), ratio(*rng.pick(&[1, -1]), 1));
            let mut d0 = [&sx * &l, &sy * (&l - &k)];
            let mut d1 = [&sx * &l, &sy * (&l + &k)];
            if rng.chance(1, 2) {
                d0.swap(0, 1);
                d1.swap(0, 1);
            }
            let t = step(rng, 2);
            let a1 = plus(&a, &t);
            let b0 = plus(&a, &d0);
            let b1 = plus(&a1, &d1);
            vec![[a, a1], [b0, b1]]
        }
        _ => starts(rng)
            .into_iter()
            .map(|p| {
                let to = near_point(rng, canvas);
                [p, to]
            })
            .collect(),
    }
}

/// Paths whose first two vertices a, b make an edge that touches a sample
/// centre c at τ0 without crossing it: with a(τ0) = c + u,
/// b(τ0) = c + λu and v_b = λ·v_a + μ·u, the edge function at c is
/// cross(a − c, b − c) = μ·cross(v_a, u)·(τ − τ0)², a double root (and
/// identically zero when v_a ∥ u: the sample rides the edge's line).
fn double_root(rng: &mut Rng, canvas: Canvas, n: usize) -> Vec<[Point; 2]> {
    let c = pixel_centre(rng, canvas);
    let (t_num, t_den) = *rng.pick(&[(1, 2), (1, 4), (3, 4), (3, 8)]);
    let tau0 = ratio(t_num, t_den);
    let mut u = [ratio(rng.range(-6, 7), 2), ratio(rng.range(-6, 7), 2)];
    if u[0] == RBig::ZERO && u[1] == RBig::ZERO {
        u[0] = RBig::ONE;
    }
    let (l_num, l_den) = *rng.pick(&[(-1, 1), (-2, 1), (-1, 2), (-3, 1), (2, 1)]);
    let lambda = ratio(l_num, l_den);
    let va = [ratio(rng.range(-6, 7), 1), ratio(rng.range(-6, 7), 1)];
    let mu = ratio(*rng.pick(&[1, -1, 2, -2]), 1);
    let vb = plus(&times(&lambda, &va), &times(&mu, &u));
    let a0 = minus(&plus(&c, &u), &times(&tau0, &va));
    let b0 = minus(&plus(&c, &times(&lambda, &u)), &times(&tau0, &vb));
    let (a1, b1) = (plus(&a0, &va), plus(&b0, &vb));
    let mut out = vec![[a0, a1], [b0, b1]];
    if n == 3 {
        let p = near_point(rng, canvas);
        let to = if rng.chance(1, 2) {
            p.clone()
        } else {
            plus(&p, &step(rng, 2))
        };
        out.push([p, to]);
    }
    out
}

fn path_vertex(rng: &mut Rng, [from, to]: [Point; 2]) -> Vertex {
    let mut v = Vertex::at(num(&from[0]), num(&from[1]));
    // A vertex that stays put is sometimes written with from = to.
    if to != from || rng.chance(1, 4) {
        v.to = Some(Box::new([num(&to[0]), num(&to[1])]));
    }
    v
}

/// A moving triangle (two in three) or parallelogram line, in any winding.
fn moving_primitive(rng: &mut Rng, canvas: Canvas) -> Primitive {
    if rng.chance(1, 3) {
        let [a, b]: [Vertex; 2] = paths(rng, canvas, 2)
            .into_iter()
            .map(|p| path_vertex(rng, p))
            .collect::<Vec<_>>()
            .try_into()
            .expect("two paths");
        let width = match rng.below(6) {
            0 => Number::ratio(1, 2),
            1 => Number::from_int(2),
            2 => Number::ratio(3, 2),
            3 => Number::ratio(1, 4),
            _ => Number::ONE,
        };
        return Primitive::Line(Line {
            vertices: [a, b],
            rule: LineRule::Parallelogram,
            width,
            last_pixel: LastPixel::Include,
            parameter: LineParameter::Major,
            interpolation: Interpolation::Perspective,
        });
    }
    let mut vertices: [Vertex; 3] = paths(rng, canvas, 3)
        .into_iter()
        .map(|p| path_vertex(rng, p))
        .collect::<Vec<_>>()
        .try_into()
        .expect("three paths");
    if rng.chance(1, 2) {
        vertices.swap(1, 2);
    }
    vertices.rotate_left(rng.below(3) as usize);
    Primitive::Triangle(Triangle {
        vertices,
        interpolation: Interpolation::Perspective,
    })
}

/// `effects.motion_blur`: every pattern, N from 1 to 64 (M·N at most 64
/// with M spatial samples, which keeps the instant-by-instant check of a
/// failure cheap), the whole shutter or a part of it in 2^-16 steps.
fn motion_blur(rng: &mut Rng, spatial: u32) -> MotionBlur {
    let one = TIME_ONE;
    let samples = (*rng.pick(&[1, 2, 3, 4, 5, 8, 16, 16, 32, 64]))
        .min(64 / spatial.max(1))
        .max(1);
    let shutter = match rng.below(8) {
        0..=3 => [0, one],
        4 => {
            let a = rng.below(4) as u32;
            let b = rng.range(i64::from(a) + 1, 5) as u32;
            [a * one / 4, b * one / 4]
        }
        5 => *rng.pick(&[[0, one / 2], [one / 2, one]]),
        _ => {
            let open = rng.below(u64::from(one)) as u32;
            let close = rng.range(i64::from(open) + 1, i64::from(one) + 1) as u32;
            [open, close]
        }
    };
    let seed = match rng.below(4) {
        0 => 0,
        1 => rng.next_u64() >> 1,
        _ => rng.below(1000),
    };
    MotionBlur {
        shutter,
        samples,
        pattern: *rng.pick(&TimePattern::ALL),
        seed,
    }
}

/// `effects.antialias` for a moving scene: every pattern, 1 to 4 samples.
fn motion_antialias(rng: &mut Rng) -> Antialias {
    let pattern = *rng.pick(&Pattern::ALL);
    let counts: &[u32] = match pattern {
        Pattern::Standard => &[1, 2, 4],
        Pattern::Grid | Pattern::Stratified => &[1, 4],
        Pattern::Random | Pattern::NRooks => &[1, 2, 3, 4],
    };
    let samples = *rng.pick(counts);
    debug_assert!(pattern.check_count(samples).is_ok());
    Antialias {
        samples,
        pattern,
        seed: if pattern.is_seeded() {
            rng.below(1000)
        } else {
            0
        },
        adaptive: rng.chance(1, 3),
        position_bits: if rng.chance(2, 3) {
            8
        } else {
            rng.range(4, 17) as u32
        },
    }
}

/// One to three moving primitives (sometimes a triangle moving with the
/// first across a shared edge), sometimes a static one of any kind, on a
/// small canvas: the oracle certifies each spatial sample of each moving
/// primitive (about 10 µs each), so a case stays within a few
/// milliseconds.
fn motion_scene(rng: &mut Rng) -> Scene {
    let antialias = rng.chance(1, 4);
    let sides: &[u32] = if antialias {
        &[2, 4, 6, 8]
    } else {
        &[3, 4, 6, 8, 12, 16]
    };
    let canvas = Canvas {
        width: *rng.pick(sides),
        height: *rng.pick(sides),
    };
    let mut primitives: Vec<Primitive> = (0..rng.range(1, 4))
        .map(|_| moving_primitive(rng, canvas))
        .collect();
    if let Some(Primitive::Triangle(t)) = primitives.first() {
        if rng.chance(1, 4) {
            // The other side of a moving edge, the same paths: each sample
            // on it belongs to one of the two at every instant.
            let k = rng.below(3) as usize;
            let (a, b) = (t.vertices[k].clone(), t.vertices[(k + 1) % 3].clone());
            let path = paths(rng, canvas, 1).remove(0);
            let c = path_vertex(rng, path);
            primitives.push(Primitive::Triangle(Triangle {
                vertices: [b, a, c],
                interpolation: Interpolation::Perspective,
            }));
        }
    }
    let mut polygons = false;
    if rng.chance(1, 3) {
        let still = match rng.below(4) {
            0 if !antialias => {
                polygons = true;
                Primitive::Polygon(polygon(rng, canvas))
            }
            1 => {
                let mut point = || position(rng, canvas);
                let vertices = [point(), point()];
                let rule = if antialias {
                    LineRule::Parallelogram
                } else {
                    *rng.pick(&LineRule::ALL)
                };
                Primitive::Line(Line {
                    vertices,
                    rule,
                    width: if rule.is_wide() {
                        Number::from_int(2)
                    } else {
                        Number::ONE
                    },
                    last_pixel: LastPixel::Include,
                    parameter: LineParameter::Major,
                    interpolation: Interpolation::Perspective,
                })
            }
            _ => plain_triangle(rng, canvas),
        };
        let at = rng.below(primitives.len() as u64 + 1) as usize;
        primitives.insert(at, still);
    }
    let bits = match rng.below(6) {
        0..=2 => 8,
        3 => 4,
        _ => rng.below(u64::from(MAX_SUBPIXEL_BITS) + 1) as u32,
    };
    let rules = Rules {
        subpixel_bits: Some(bits),
        fill_rule: if polygons {
            *rng.pick(&FillRule::CONSISTENT)
        } else {
            *rng.pick(&FillRule::ALL)
        },
        cull: *rng.pick(&[Cull::None, Cull::Clockwise, Cull::CounterClockwise]),
    };
    let none = Values {
        attributes: 0,
        depth: false,
        w: false,
    };
    let mut scene = scene_of(canvas, rules, primitives, &none);
    let spatial = if antialias {
        let a = motion_antialias(rng);
        let m = a.samples;
        scene.effects.antialias = Some(a);
        m
    } else {
        1
    };
    scene.effects.motion_blur = Some(motion_blur(rng, spatial));
    scene
}

// Meshes, after the strategies of tests/properties.rs.

type Exact2 = [RBig; 2];

fn placed(n: &Number, bits: Option<u32>) -> RBig {
    match bits {
        Some(b) => snap(n, b),
        None => n.as_rbig().clone(),
    }
}

fn orient(a: &Exact2, b: &Exact2, c: &Exact2) -> Ordering {
    let v = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
    v.cmp(&RBig::ZERO)
}

/// A planar shape to triangulate into a mesh.
enum Shape {
    /// Points and triangles whose interiors do not overlap.
    Triangles(Vec<[Number; 2]>, Vec<[usize; 3]>),
    /// A polygon, star-shaped around `centre`, to ear-clip after snapping.
    Star {
        centre: [f64; 2],
        points: Vec<[Number; 2]>,
    },
}

/// A dyadic denominator (grid-aligned vertices force ties), or a free odd
/// one up to 2^40.
fn denominator(rng: &mut Rng) -> i64 {
    if rng.chance(3, 4) {
        1 << rng.below(17)
    } else {
        rng.range(1, 1 << 40) | 1
    }
}

fn to_number(v: f64, den: i64) -> Number {
    Number::ratio((v * den as f64).round() as i64, den)
}

/// A sample centre, or a dyadic or free point on the canvas.
fn mesh_centre(rng: &mut Rng, canvas: Canvas) -> [f64; 2] {
    let (w, h) = (i64::from(canvas.width), i64::from(canvas.height));
    if rng.chance(1, 2) {
        [rng.range(0, w) as f64 + 0.5, rng.range(0, h) as f64 + 0.5]
    } else {
        [rng.uniform(0.0, w as f64), rng.uniform(0.0, h as f64)]
    }
}

fn radius_scale(rng: &mut Rng) -> f64 {
    *rng.pick(&[1.5, 4.0, 12.0, 40.0, 20000.0])
}

/// `n` increasing angles around a circle, each gap below π.
fn angles(rng: &mut Rng, n: usize) -> Vec<f64> {
    let gaps: Vec<f64> = (0..n).map(|_| rng.uniform(1.0, 1.9)).collect();
    let total: f64 = gaps.iter().sum();
    let mut a = rng.uniform(0.0, std::f64::consts::TAU);
    gaps.iter()
        .map(|g| {
            a += std::f64::consts::TAU * g / total;
            a
        })
        .collect()
}

fn exact_centre(c: [f64; 2], den: i64) -> [Number; 2] {
    // A sample centre stays exact whatever the denominator.
    c.map(|v| {
        if (v * 2.0).fract() == 0.0 {
            Number::ratio((v * 2.0) as i64, 2)
        } else {
            to_number(v, den)
        }
    })
}

fn fan(rng: &mut Rng, canvas: Canvas) -> Shape {
    let n = rng.range(3, 16) as usize;
    let c = mesh_centre(rng, canvas);
    let angles = angles(rng, n);
    let scale = radius_scale(rng);
    let den = denominator(rng);
    let mut points = vec![exact_centre(c, den)];
    for a in angles {
        let r = rng.uniform(0.5, 1.5) * scale;
        let (s, co) = sin_cos(a);
        points.push([to_number(c[0] + r * co, den), to_number(c[1] + r * s, den)]);
    }
    let triangles = (1..=n).map(|k| [0, k, k % n + 1]).collect();
    Shape::Triangles(points, triangles)
}

fn convex_polygon(rng: &mut Rng, canvas: Canvas) -> Shape {
    let n = rng.range(3, 14) as usize;
    let c = mesh_centre(rng, canvas);
    let angles = angles(rng, n);
    let scale = radius_scale(rng);
    let den = denominator(rng);
    let points = angles
        .iter()
        .map(|&a| {
            let (s, co) = sin_cos(a);
            [
                to_number(c[0] + scale * co, den),
                to_number(c[1] + scale * s, den),
            ]
        })
        .collect();
    let triangles = (1..n - 1).map(|k| [0, k, k + 1]).collect();
    Shape::Triangles(points, triangles)
}

fn star_polygon(rng: &mut Rng, canvas: Canvas) -> Shape {
    let n = rng.range(4, 14) as usize;
    let centre = mesh_centre(rng, canvas);
    let angles = angles(rng, n);
    let scale = radius_scale(rng);
    let den = denominator(rng);
    let points = angles
        .iter()
        .map(|&a| {
            let r = rng.uniform(0.3, 1.5) * scale;
            let (s, co) = sin_cos(a);
            [
                to_number(centre[0] + r * co, den),
                to_number(centre[1] + r * s, den),
            ]
        })
        .collect();
    Shape::Star { centre, points }
}

/// A jittered lattice (jitter below a quarter of the spacing keeps every
/// triangle's orientation), each quad split along a random diagonal.
fn jittered_grid(rng: &mut Rng) -> Shape {
    let (n, m) = (rng.range(1, 9) as usize, rng.range(1, 9) as usize);
    let (ox, oy) = (
        rng.range(-16, 2) as f64 / 2.0,
        rng.range(-16, 2) as f64 / 2.0,
    );
    let s = *rng.pick(&[0.5, 1.0, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 4000.0]);
    let jitter = *rng.pick(&[0.0, 0.0, 0.24]);
    let den = denominator(rng);
    let at = |i: usize, j: usize| j * (n + 1) + i;
    let mut points = Vec::new();
    for j in 0..=m {
        for i in 0..=n {
            let (jx, jy) = (
                rng.uniform(-jitter, jitter + f64::MIN_POSITIVE),
                rng.uniform(-jitter, jitter + f64::MIN_POSITIVE),
            );
            let (x, y) = (ox + s * (i as f64 + jx), oy + s * (j as f64 + jy));
            points.push([to_number(x, den), to_number(y, den)]);
        }
    }
    let mut triangles = Vec::new();
    for j in 0..m {
        for i in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if rng.chance(1, 2) {
                triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    Shape::Triangles(points, triangles)
}

/// Ear clipping of a simple polygon given in `sign` winding. Vertices where
/// the boundary runs straight on are dropped (they become T-junctions on a
/// later triangle's edge, which keeps the tiling exact).
pub fn ear_clip(points: &[[RBig; 2]], sign: Ordering) -> Option<Vec<[usize; 3]>> {
    let mut left: Vec<usize> = (0..points.len()).collect();
    let mut triangles = Vec::new();
    let corner = |left: &[usize], k: usize| {
        let m = left.len();
        (left[(k + m - 1) % m], left[k], left[(k + 1) % m])
    };
    while left.len() > 3 {
        let m = left.len();
        if let Some(k) = (0..m).find(|&k| {
            let (a, b, c) = corner(&left, k);
            orient(&points[a], &points[b], &points[c]) == Ordering::Equal
        }) {
            left.remove(k);
            continue;
        }
        let ear = (0..m).find(|&k| {
            let (a, b, c) = corner(&left, k);
            let (pa, pb, pc) = (&points[a], &points[b], &points[c]);
            orient(pa, pb, pc) == sign
                && left.iter().all(|&q| {
                    q == a
                        || q == b
                        || q == c
                        || [
                            orient(pa, pb, &points[q]),
                            orient(pb, pc, &points[q]),
                            orient(pc, pa, &points[q]),
                        ]
                        .contains(&sign.reverse())
                })
        })?;
        let (a, b, c) = corner(&left, ear);
        triangles.push([a, b, c]);
        left.remove(ear);
    }
    if orient(&points[left[0]], &points[left[1]], &points[left[2]]) == sign {
        triangles.push([left[0], left[1], left[2]]);
    }
    Some(triangles)
}

/// A mesh scene, or `None` when snapping folded a triangle over (the shape
/// is then no longer a mesh).
fn mesh_scene(rng: &mut Rng) -> Option<Scene> {
    let canvas = canvas(rng);
    let shape = match rng.below(4) {
        0 => fan(rng, canvas),
        1 => jittered_grid(rng),
        2 => convex_polygon(rng, canvas),
        _ => star_polygon(rng, canvas),
    };
    let bits = any_bits(rng);
    let at = |p: &[Number; 2]| p.each_ref().map(|c| placed(c, bits));
    let (points, triangles) = match shape {
        Shape::Triangles(points, triangles) => (points, triangles),
        Shape::Star { centre, points } => {
            let placed_points: Vec<Exact2> = points.iter().map(at).collect();
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
            let triangles = ear_clip(&placed_points, signs[0])?;
            (points, triangles)
        }
    };
    let placed_points: Vec<Exact2> = points.iter().map(at).collect();
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
    if signs.is_empty() || signs.iter().any(|s| *s != signs[0] || s.is_eq()) {
        return None;
    }
    // Values belong to points, so that shared vertices agree.
    let values = Values {
        attributes: usize::from(rng.chance(1, 4)),
        depth: rng.chance(1, 6),
        w: false,
    };
    let vertices: Vec<Vertex> = points
        .iter()
        .map(|p| values.vertex(rng, p[0].clone(), p[1].clone()))
        .collect();
    let primitives = triangles
        .iter()
        .map(|t| {
            let mut vertices = t.map(|i| vertices[i].clone());
            if rng.chance(1, 2) {
                vertices.swap(1, 2);
            }
            vertices.rotate_left(rng.below(3) as usize);
            Primitive::Triangle(Triangle {
                vertices,
                interpolation: Interpolation::Perspective,
            })
        })
        .collect();
    let rules = Rules {
        subpixel_bits: bits,
        fill_rule: *rng.pick(&FillRule::CONSISTENT),
        cull: Cull::None,
    };
    let mut scene = scene_of(canvas, rules, primitives, &values);
    scene.expect.watertight = true;
    Some(scene)
}

/// Whether a scene is within SPEC.md's limits (§8), as a case file must be.
fn valid(scene: &Scene) -> Result<(), String> {
    let side = 1..=crate::scene::rules::limits::MAX_CANVAS_SIDE;
    if !side.contains(&scene.canvas.width) || !side.contains(&scene.canvas.height) {
        return Err("canvas side out of range".to_owned());
    }
    if scene.primitives.is_empty() {
        return Err("no primitives".to_owned());
    }
    let limit = Number::from_int(COORD_LIMIT);
    let (w_lo, w_hi) = (Number::ratio(1, W_LIMIT), Number::from_int(W_LIMIT));
    for v in scene.vertices() {
        if v.x.abs() > limit || v.y.abs() > limit {
            return Err("coordinate out of range".to_owned());
        }
        if v.w < w_lo || v.w > w_hi {
            return Err("w out of range".to_owned());
        }
        if v.attributes.len() != scene.attribute_count {
            return Err("attribute count".to_owned());
        }
    }
    // Polygons, antialiasing and motion have rules of their own (contours
    // of at least 3 vertices, sample counts per pattern, no `all-edges` for
    // polygons, no midpoint lines under antialiasing, only triangles and
    // parallelogram lines move, no values and no sample expectations in a
    // moving scene): the scene must read back from its case file, so that
    // a shrunk counterexample is a case.
    let motion = scene.effects.motion_blur.is_some() || scene.vertices().any(|v| v.to.is_some());
    if scene.has_polygons() || scene.effects.antialias.is_some() || motion {
        let mut named = scene.clone();
        named.name = "fuzz".to_owned();
        named.description = "fuzz".to_owned();
        parse_case(&case_json(&named), "fuzz", &Limits::default())
            .map_err(|e| format!("not a valid case: {}", e.message))?;
    }
    Ok(())
}

// --- Judging ---------------------------------------------------------------

/// Which check a candidate fails, in the order a scene failing several is
/// shrunk for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// The rasterizer broke: an error or a panic.
    Error,
    /// Interior samples of a mesh left uncovered (SPEC.md §6.2).
    Holes,
    /// Samples of a mesh covered twice (SPEC.md §6.2).
    Overdraw,
    /// A midpoint line with two pixels in one major-axis step (§6.4).
    Lines,
    /// Coverage differs from the reference's (§6.1).
    Coverage,
    /// Resolved coverage against the exact areas: piglit's rule, the
    /// coverage error bounds, a resolve that is not the box resolve of the
    /// candidate's own mask (§14.3).
    Antialias,
    /// Time coverage of a moving scene against the exact values: the RMS
    /// over moving pixels, the largest error, values that are not numbers
    /// (§15.4).
    Time,
    /// Depth or an attribute beyond its bound (§6.3).
    Interpolation,
}

impl Kind {
    pub const ALL: [Kind; 8] = [
        Kind::Error,
        Kind::Holes,
        Kind::Overdraw,
        Kind::Lines,
        Kind::Coverage,
        Kind::Antialias,
        Kind::Time,
        Kind::Interpolation,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Error => "error",
            Kind::Holes => "holes",
            Kind::Overdraw => "overdraw",
            Kind::Lines => "lines",
            Kind::Coverage => "coverage",
            Kind::Antialias => "antialias",
            Kind::Time => "time",
            Kind::Interpolation => "interpolation",
        }
    }

    /// What every correct rasterizer does on a case that fails this way.
    fn promise(self) -> &'static str {
        match self {
            Kind::Error => "draws the scene without breaking",
            Kind::Holes | Kind::Overdraw => {
                "covers every interior sample of the mesh exactly once and no sample twice"
            }
            Kind::Lines => "lights one pixel of a midpoint line per major-axis step",
            Kind::Coverage => "covers exactly the reference's samples, with the same owners",
            Kind::Antialias => {
                "resolves full pixels to exactly 1, empty ones to 0, within the coverage bounds"
            }
            Kind::Time => {
                "estimates each pixel's time coverage within the time-coverage bounds, as the sample method with the case's own instants does"
            }
            Kind::Interpolation => "interpolates depth and attributes within the bound",
        }
    }
}

/// The kinds a `--check` names: a kind, or `watertight` (holes or overdraw).
pub fn kinds_named(name: &str) -> Option<Vec<Kind>> {
    if name == "watertight" {
        return Some(vec![Kind::Holes, Kind::Overdraw]);
    }
    Kind::ALL
        .into_iter()
        .find(|k| k.name() == name)
        .map(|k| vec![k])
}

/// How a candidate fails a scene.
#[derive(Clone, Debug)]
pub struct Failure {
    /// Every check it fails, in [`Kind`] order.
    pub kinds: Vec<Kind>,
    /// The reasons `run` prints ([`crate::metrics::failures`]), or the error.
    pub reasons: Vec<String>,
    /// Per kind, the samples (sample `s` of pixel `p` at `p * N + s`, N the
    /// scene's samples per pixel) that show it.
    focus: Vec<(Kind, Vec<usize>)>,
}

impl Failure {
    /// The reasons that belong to `kind`.
    pub fn reasons_for(&self, kind: Kind) -> Vec<String> {
        let prefix: &[&str] = match kind {
            Kind::Error => &[],
            Kind::Holes | Kind::Overdraw => &["watertight:"],
            Kind::Lines => &["lines:"],
            Kind::Coverage => &["coverage:"],
            Kind::Antialias => &["antialias:"],
            Kind::Time => &["time:"],
            Kind::Interpolation => &["depth:", "attribute "],
        };
        let found: Vec<String> = self
            .reasons
            .iter()
            .filter(|r| prefix.is_empty() || prefix.iter().any(|p| r.starts_with(p)))
            .cloned()
            .collect();
        if found.is_empty() {
            self.reasons.clone()
        } else {
            found
        }
    }

    fn focus(&self, kind: Kind) -> &[usize] {
        self.focus
            .iter()
            .find(|(k, _)| *k == kind)
            .map_or(&[], |(_, f)| f.as_slice())
    }
}

/// A candidate's result on one scene.
#[derive(Clone, Debug)]
pub enum Outcome {
    Pass,
    Unsupported(String),
    /// The scene is not a case worth keeping: outside the limits, or a
    /// "mesh" whose triangles overlap or have no area.
    Invalid(String),
    Fail(Failure),
}

/// Runs the reference and `candidate` on `scene` and judges the candidate
/// as `run` does.
pub fn evaluate(scene: &Scene, candidate: &dyn Rasterizer) -> Outcome {
    if let Err(why) = valid(scene) {
        return Outcome::Invalid(why);
    }
    let reference = std::panic::catch_unwind(|| reference_run(scene));
    let reference = match reference {
        Ok(Ok(r)) => r,
        Ok(Err(why)) => return Outcome::Invalid(why),
        Err(panic) => {
            return Outcome::Invalid(format!(
                "the reference panicked: {}",
                suite::panic_message(&*panic)
            ))
        }
    };
    // The exact N-sample method (the reference's mask, box-resolved) must
    // meet the case's coverage bounds: with few samples no sampler meets
    // piglit's RMS bound on some scenes, and such a scene says nothing
    // about the candidate. (A moving scene is judged on time coverage
    // only; its fairness is checked below, when a candidate fails it.)
    if scene.effects.antialias.is_some() && reference.time.is_none() {
        let mut exact = reference.frame.clone();
        exact.resolve();
        let m = crate::metrics::measure_with_areas(
            scene,
            &reference.frame,
            &exact,
            reference.interior.as_deref(),
            reference
                .areas
                .as_ref()
                .and_then(|a| a.as_ref().ok())
                .map(|a| a.classes.as_slice()),
        );
        if let Some(aa) = &m.antialias {
            let broken = crate::metrics::antialias::failures(aa);
            if !broken.is_empty() {
                return Outcome::Invalid(format!(
                    "the exact {}-sample method breaks the coverage bounds: {}",
                    scene.effects.antialias.as_ref().map_or(1, |a| a.samples),
                    broken.join("; ")
                ));
            }
        }
    }
    let run = suite::run_candidate(scene, &reference, candidate);
    match (run.verdict, run.metrics, run.frame) {
        (Verdict::Pass, ..) => Outcome::Pass,
        (Verdict::Unsupported(why), ..) => Outcome::Unsupported(why),
        (Verdict::Error(why), ..) => Outcome::Fail(Failure {
            kinds: vec![Kind::Error],
            reasons: vec![why],
            focus: Vec::new(),
        }),
        (Verdict::Fail(reasons), Some(m), Some(frame)) => {
            let failure = classify(scene, &reference, &frame, &m, reasons);
            let broken_values = m.time.as_ref().is_some_and(|t| t.invalid_values > 0);
            if failure.kinds.contains(&Kind::Time) && !broken_values {
                if let Err(why) = fair_time(scene, &reference) {
                    return Outcome::Invalid(why);
                }
            }
            Outcome::Fail(failure)
        }
        (Verdict::Fail(reasons), ..) => Outcome::Fail(Failure {
            kinds: vec![Kind::Error],
            reasons,
            focus: Vec::new(),
        }),
    }
}

/// The reference's frame, and the mesh interior for a mesh case (refused
/// when the scene is no longer a mesh); for a scene in which something
/// moves, the certified time coverage as `run` computes it (refused when
/// the oracle fails or breaks a pin of the case).
fn reference_run(scene: &Scene) -> Result<ReferenceRun, String> {
    let started = Instant::now();
    let plan = Plan::for_scene(scene);
    if plan.motion.is_some() {
        let run = suite::run_reference(scene);
        match &run.time {
            Some(Err(why)) => return Err(why.clone()),
            Some(Ok(check)) if !check.broken_promises.is_empty() => {
                return Err(check.broken_promises.join("; "))
            }
            _ => return Ok(run),
        }
    }
    let frame = reference::render(scene, &plan);
    let interior = if scene.expect.watertight {
        mesh_geometry(scene)?;
        let mut interior = vec![true; scene.canvas.pixel_count()];
        for rule in FillRule::CONSISTENT {
            let counts = reference::coverage_under(scene, rule);
            if counts.iter().any(|&c| c > 1) {
                return Err(format!("mesh triangles overlap under {rule}"));
            }
            for (inside, count) in interior.iter_mut().zip(counts) {
                *inside &= count > 0;
            }
        }
        Some(interior)
    } else {
        None
    };
    let areas = suite::area_check(scene);
    Ok(ReferenceRun {
        plan,
        frame,
        interior,
        areas,
        time: None,
        elapsed: started.elapsed(),
    })
}

/// Refuses a "mesh" with a zero-area triangle or two triangles whose
/// interiors overlap (after snapping, exactly): such a scene no longer says
/// what a watertight rasterizer must do.
fn mesh_geometry(scene: &Scene) -> Result<(), String> {
    let bits = scene.rules.subpixel_bits;
    let triangles: Vec<[Exact2; 3]> = scene
        .triangles()
        .map(|(_, t)| {
            t.vertices
                .each_ref()
                .map(|v| [placed(&v.x, bits), placed(&v.y, bits)])
        })
        .collect();
    if triangles
        .iter()
        .any(|p| orient(&p[0], &p[1], &p[2]).is_eq())
    {
        return Err("a mesh triangle has no area".to_owned());
    }
    // Bounding boxes in f64, widened so that rounding can only make two
    // boxes meet that do not: a sweep over x finds the pairs to test.
    let boxes: Vec<[f64; 4]> = triangles
        .iter()
        .map(|t| {
            let xs = t.each_ref().map(|p| p[0].to_f64().value());
            let ys = t.each_ref().map(|p| p[1].to_f64().value());
            let lo = |v: [f64; 3]| v.into_iter().fold(f64::INFINITY, f64::min);
            let hi = |v: [f64; 3]| v.into_iter().fold(f64::NEG_INFINITY, f64::max);
            let pad = |v: f64| v.abs() * 1e-12 + 1e-12;
            let (x0, x1, y0, y1) = (lo(xs), hi(xs), lo(ys), hi(ys));
            [x0 - pad(x0), x1 + pad(x1), y0 - pad(y0), y1 + pad(y1)]
        })
        .collect();
    let mut order: Vec<usize> = (0..triangles.len()).collect();
    order.sort_by(|&a, &b| boxes[a][0].total_cmp(&boxes[b][0]));
    for (k, &a) in order.iter().enumerate() {
        for &b in &order[k + 1..] {
            if boxes[b][0] >= boxes[a][1] {
                break;
            }
            if boxes[b][2] >= boxes[a][3] || boxes[a][2] >= boxes[b][3] {
                continue;
            }
            if !separated(&triangles[a], &triangles[b]) {
                return Err("mesh triangles overlap".to_owned());
            }
        }
    }
    Ok(())
}

/// Whether two triangles' interiors are disjoint: some edge line of one
/// has the other on its far side, touching allowed (the separating axis
/// theorem; for convex polygons an edge normal always serves).
fn separated(t: &[Exact2; 3], u: &[Exact2; 3]) -> bool {
    let axes = (0..3)
        .map(|k| (&t[k], &t[(k + 1) % 3]))
        .chain((0..3).map(|k| (&u[k], &u[(k + 1) % 3])));
    for (a, b) in axes {
        let n = [&a[1] - &b[1], &b[0] - &a[0]];
        let project = |p: &Exact2| &n[0] * &p[0] + &n[1] * &p[1];
        let pt = t.each_ref().map(project);
        let pu = u.each_ref().map(project);
        let (t_lo, t_hi) = (pt.iter().min().unwrap(), pt.iter().max().unwrap());
        let (u_lo, u_hi) = (pu.iter().min().unwrap(), pu.iter().max().unwrap());
        if t_hi <= u_lo || u_hi <= t_lo {
            return true;
        }
    }
    false
}

fn classify(
    scene: &Scene,
    reference: &ReferenceRun,
    candidate: &Frame,
    m: &Metrics,
    reasons: Vec<String>,
) -> Failure {
    let r = &reference.frame;
    let n = r.sample_count();
    let mut focus: Vec<(Kind, Vec<usize>)> = Vec::new();
    if let (Some(w), Some(interior)) = (&m.watertight, &reference.interior) {
        if w.holes > 0 {
            let holes = (0..n)
                .filter(|&i| interior[i] && candidate.coverage[i] == 0)
                .collect();
            focus.push((Kind::Holes, holes));
        }
        if w.overdraw > 0 {
            let over = (0..n)
                .filter(|&i| candidate.coverage[i] > 1 && r.coverage[i] <= 1)
                .collect();
            focus.push((Kind::Overdraw, over));
        }
    }
    if m.lines.as_ref().is_some_and(|l| l.crowded_steps > 0) {
        focus.push((Kind::Lines, crowded_pixels(scene, candidate)));
    }
    let c = &m.coverage;
    if c.mismatched() > scene.expect.max_mismatched_samples
        || (c.reference_covered > 0 && c.candidate_covered == 0)
    {
        let differ = (0..n).filter(|&i| c.mask[i] != SampleDiff::Same).collect();
        focus.push((Kind::Coverage, differ));
    }
    if let Some(aa) = &m.antialias {
        if !crate::metrics::antialias::failures(aa).is_empty() {
            let per_pixel = r.samples.max(1) as usize;
            let w = r.width as usize;
            let pixels: Vec<usize> = aa
                .first_violation
                .into_iter()
                .chain([aa.worst_pixel])
                .map(|[x, y]| (y as usize * w + x as usize) * per_pixel)
                .collect();
            focus.push((Kind::Antialias, pixels));
        }
    }
    if let Some(t) = &m.time {
        if !crate::metrics::time::failures(t).is_empty() {
            focus.push((Kind::Time, time_focus(scene, r, candidate, t)));
        }
    }
    if m.channels.iter().any(|ch| !ch.within_bounds()) {
        let mut pixels = Vec::new();
        let exact = r.depth.iter().chain(&r.attributes);
        let values = candidate.depth.iter().chain(&candidate.attributes);
        for ((exact, values), ch) in exact.zip(values).zip(&m.channels) {
            if ch.within_bounds() {
                continue;
            }
            for i in 0..n {
                let compared = r.last[i] != 0 && r.last[i] == candidate.last[i];
                let error = (values[i] - exact[i]).abs();
                if compared && (error.is_nan() || error > ch.allowed_abs) {
                    pixels.push(i);
                }
            }
        }
        pixels.sort_unstable();
        pixels.dedup();
        focus.push((Kind::Interpolation, pixels));
    }
    focus.sort_by_key(|(k, _)| *k);
    Failure {
        kinds: focus.iter().map(|(k, _)| *k).collect(),
        reasons,
        focus,
    }
}

/// The pixels whose time coverage is off by more than a bound allows
/// (more than the RMS bound, or than the largest error allowed), the
/// worst first; the worst pixel alone when no single one is. Each as its
/// first sample slot (p · M for M spatial samples), as the shrinker crops.
fn time_focus(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    t: &crate::metrics::TimeMetrics,
) -> Vec<usize> {
    // A value that is not a number has an infinite error here.
    let errors = crate::metrics::time::signed_errors(reference, candidate);
    let allowed = [t.allowed_rms, t.allowed_error]
        .into_iter()
        .flatten()
        .fold(f64::INFINITY, f64::min);
    let mut pixels: Vec<usize> = (0..errors.len())
        .filter(|&p| errors[p].abs() > allowed)
        .collect();
    // Largest error first; equal ones in pixel order.
    pixels.sort_by(|&a, &b| errors[b].abs().total_cmp(&errors[a].abs()).then(a.cmp(&b)));
    if pixels.is_empty() {
        let [x, y] = t.worst_pixel;
        pixels.push((y * reference.width + x) as usize);
    }
    let per_pixel = samples_per_pixel(scene);
    pixels.into_iter().map(|p| p * per_pixel).collect()
}

/// Whether a moving scene is a fair test of its time bounds: the sample
/// method of SPEC.md §15.3 with the case's own instants
/// ([`sampled_time`]) meets them. The default RMS bound is statistical
/// (about twice what independent instants give on average), so on a
/// scene with few moving pixels an honest sampler can break it, and such
/// a scene says nothing about a candidate; `Err` says why it is refused.
/// Like the antialiasing check in [`evaluate`], which refuses a scene the
/// exact N-sample method fails.
fn fair_time(scene: &Scene, reference: &ReferenceRun) -> Result<(), String> {
    use crate::metrics::time;
    let whole = match &reference.time {
        Some(Ok(check)) => Some(check.whole.as_slice()),
        _ => None,
    };
    let Canvas { width, height } = scene.canvas;
    let sampled = Frame::time_only(width, height, sampled_time(scene, &reference.plan));
    let m = time::measure(&reference.frame, &sampled, whole, time::bounds(scene))
        .ok_or("the reference has no time coverage for a moving scene")?;
    let broken = time::failures(&m);
    if broken.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "the sample method with the case's own instants breaks the time bounds: {}",
            broken.join("; ")
        ))
    }
}

/// Each pixel's time coverage as SPEC.md §15.3's sample method estimates
/// it with the case's own instants (each pixel's u from its seed), every
/// test decided by the static reference at its exact instant: what every
/// conforming sampler returns (production does, test by test:
/// tests/motion_production.rs). Static primitives cover a sample at every
/// instant or at none. Moving ones are tested only at the pixels of their
/// swept box (elsewhere they cover nothing at any instant), each test a
/// one-pixel scene whose centre is the sample: the primitives at the
/// instant, moved there exactly (a translation keeps every decision).
///
/// # Panics
/// When the plan has no `motion` or the scene no `subpixel_bits`.
fn sampled_time(scene: &Scene, plan: &Plan) -> Vec<f64> {
    let blur = &plan.motion.as_ref().expect("a moving scene").blur;
    let bits = scene
        .rules
        .subpixel_bits
        .expect("a moving scene has subpixel_bits");
    let Canvas { width, height } = scene.canvas;
    let half = ratio(1, 2);
    let offsets: Vec<Point> = match &plan.antialias {
        Some(a) => {
            let unit = RBig::from(UBig::ONE << a.position_bits as usize);
            a.offsets
                .iter()
                .map(|o| o.map(|c| RBig::from(c) / &unit))
                .collect()
        }
        None => vec![[half.clone(), half.clone()]],
    };
    let (m, n) = (offsets.len(), blur.samples as usize);
    let mut still = scene.clone();
    still.primitives.retain(|p| !p.moves());
    still.effects.motion_blur = None;
    let fixed = if still.primitives.is_empty() {
        vec![0u16; scene.canvas.pixel_count() * m]
    } else {
        reference::coverage_under(&still, scene.rules.fill_rule)
    };
    let mut totals: Vec<u64> = fixed
        .chunks(m)
        .map(|c| c.iter().map(|&k| u64::from(k)).sum::<u64>() * n as u64)
        .collect();
    // The moving primitives alone on one pixel; each vertex's snapped
    // position at open and its displacement to close.
    let mut one = scene.clone();
    one.primitives.retain(Primitive::moves);
    one.canvas = Canvas {
        width: 1,
        height: 1,
    };
    one.rules.subpixel_bits = None;
    one.effects = Effects::default();
    one.expect = Expect::default();
    let ends: Vec<[Point; 2]> = one
        .vertices()
        .map(|v| {
            let open = [&v.x, &v.y].map(|c| c.snapped(bits).as_rbig().clone());
            let close = v.end().map(|c| c.snapped(bits).as_rbig().clone());
            let d = minus(&close, &open);
            [open, d]
        })
        .collect();
    // The swept box, widened by a line's width and a pixel: a sample
    // outside it is never covered.
    let margin = one
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Line(l) => l.width.to_f64_lossy(),
            _ => 0.0,
        })
        .fold(0.0, f64::max)
        + 1.0;
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for [open, d] in &ends {
        for axis in 0..2 {
            for c in [open[axis].clone(), &open[axis] + &d[axis]] {
                let f = c.to_f64().value();
                lo[axis] = lo[axis].min(f);
                hi[axis] = hi[axis].max(f);
            }
        }
    }
    let span = |axis: usize, size: u32| {
        let clamp = |v: f64| v.clamp(0.0, f64::from(size)) as u32;
        clamp((lo[axis] - margin).floor())..clamp((hi[axis] + margin).ceil())
    };
    let unit_time = RBig::from(UBig::ONE << 32);
    for y in span(1, height) {
        for x in span(0, width) {
            let p = (y * width + x) as usize;
            let us = blur.pixel_times(p as u64, m as u32);
            for (j, &u) in us.iter().enumerate() {
                let tau = RBig::from(blur.instant(u)) / &unit_time;
                let o = &offsets[j / n];
                let shift = [&half - RBig::from(x) - &o[0], &half - RBig::from(y) - &o[1]];
                let vertices = one.primitives.iter_mut().flat_map(|q| q.vertices_mut());
                for (v, [open, d]) in vertices.zip(&ends) {
                    v.x = Number::from_rbig(&open[0] + &tau * &d[0] + &shift[0]);
                    v.y = Number::from_rbig(&open[1] + &tau * &d[1] + &shift[1]);
                    v.to = None;
                }
                totals[p] += u64::from(reference::coverage_under(&one, scene.rules.fill_rule)[0]);
            }
        }
    }
    let tests = (m * n) as f64;
    totals.into_iter().map(|t| t as f64 / tests).collect()
}

/// Pixels of midpoint lines in steps where the line has more than one.
fn crowded_pixels(scene: &Scene, candidate: &Frame) -> Vec<usize> {
    let (w, h) = (candidate.width as usize, candidate.height as usize);
    let mut out = Vec::new();
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Line(line) = primitive else {
            continue;
        };
        if line.rule != LineRule::Midpoint {
            continue;
        }
        let bits = scene.rules.subpixel_bits;
        let [a, b] = &line.vertices;
        let dx = placed(&b.x, bits) - placed(&a.x, bits);
        let dy = placed(&b.y, bits) - placed(&a.y, bits);
        let abs = |r: RBig| if r < RBig::ZERO { -r } else { r };
        let x_major = abs(dx) >= abs(dy);
        let id = index as u32 + 1;
        let (steps, across) = if x_major { (w, h) } else { (h, w) };
        for step in 0..steps {
            let drawn: Vec<usize> = (0..across)
                .map(|k| if x_major { k * w + step } else { step * w + k })
                .filter(|&i| candidate.last[i] == id)
                .collect();
            if drawn.len() > 1 {
                out.extend(drawn);
            }
        }
    }
    out.sort_unstable();
    out
}

// --- Shrinking -------------------------------------------------------------

/// A shrunk counterexample.
#[derive(Clone, Debug)]
pub struct Shrunk {
    pub scene: Scene,
    pub failure: Failure,
    /// Candidate evaluations spent.
    pub evaluations: u64,
    /// Rounds of passes, the last of which made no progress.
    pub rounds: u32,
    pub elapsed: Duration,
}

/// One proposed change to a scene; `false` when it would change nothing.
type Edit = Box<dyn Fn(&mut Scene) -> bool>;

struct Shrinker<'a> {
    candidate: &'a dyn Rasterizer,
    kind: Kind,
    best: Scene,
    failure: Failure,
    evaluations: u64,
}

/// Shrinks `scene`, on which `candidate` fails with `failure`, to a small
/// scene that still fails the check `kind`.
pub fn shrink(scene: &Scene, failure: Failure, kind: Kind, candidate: &dyn Rasterizer) -> Shrunk {
    let started = Instant::now();
    let mut s = Shrinker {
        candidate,
        kind,
        best: scene.clone(),
        failure,
        evaluations: 0,
    };
    let mut rounds = 0;
    loop {
        rounds += 1;
        let mut progress = false;
        progress |= s.remove_primitives();
        progress |= s.crop();
        progress |= s.trim();
        progress |= s.simplify_state();
        progress |= s.simplify_antialias();
        progress |= s.simplify_motion();
        progress |= s.freeze_vertices();
        progress |= s.remove_contours_and_vertices();
        progress |= s.move_shared_vertices();
        progress |= s.move_vertices();
        progress |= s.move_ends();
        progress |= s.simplify_values();
        // Coarser snapping is tried once nothing else helps: by then the
        // vertices are as simple as they get, and often on the grid already.
        if !progress {
            progress = s.reduce_bits();
        }
        if !progress || s.exhausted() {
            break;
        }
    }
    s.restore_default_bits();
    Shrunk {
        scene: s.best,
        failure: s.failure,
        evaluations: s.evaluations,
        rounds,
        elapsed: started.elapsed(),
    }
}

/// A simplicity key for a number: smaller denominator first, then closer to
/// `[lo, hi]`, then closer to `centre`. Every accepted move makes some key
/// smaller, and keys of bounded denominator are well-ordered, so shrinking
/// ends.
fn key(v: &Number, lo: &Number, hi: &Number, centre: &Number) -> (UBig, Number, Number) {
    let outside = if v < lo {
        lo - v
    } else if v > hi {
        v - hi
    } else {
        Number::ZERO
    };
    (v.denominator().clone(), outside, (v - centre).abs())
}

/// Simpler values to try for `v`, in order: integers in `[lo, hi]` nearest
/// `v` first, coarser dyadic roundings of `v`, and `v` pulled halfway in
/// from far outside `[lo, hi]`.
fn simpler(v: &Number, lo: i64, hi: i64, finest: u32) -> Vec<Number> {
    let mut out: Vec<Number> = Vec::new();
    let f = v.to_f64_lossy();
    let mut ints: Vec<i64> = (lo..=hi).collect();
    ints.sort_by(|a, b| {
        ((*a as f64) - f)
            .abs()
            .total_cmp(&((*b as f64) - f).abs())
            .then(a.cmp(b))
    });
    out.extend(ints.into_iter().take(12).map(Number::from_int));
    for k in 0..=finest.min(MAX_SUBPIXEL_BITS) {
        out.push(num(&snap(v, k)));
    }
    let (lo_n, hi_n) = (Number::from_int(lo), Number::from_int(hi));
    let edge = if *v < lo_n {
        Some(lo_n)
    } else if *v > hi_n {
        Some(hi_n)
    } else {
        None
    };
    if let Some(edge) = edge {
        let half = num(&((v.as_rbig() + edge.as_rbig()) / RBig::from(2u8)));
        out.push(num(&snap(&half, 0)));
    }
    let mut seen: Vec<Number> = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
}

/// Sample slots per pixel of a scene's frames.
fn samples_per_pixel(scene: &Scene) -> usize {
    scene
        .effects
        .antialias
        .as_ref()
        .map_or(1, |a| a.samples.max(1) as usize)
}

impl Shrinker<'_> {
    fn exhausted(&self) -> bool {
        self.evaluations >= SHRINK_BUDGET
    }

    /// Keeps `scene` when it still fails the same check.
    fn try_scene(&mut self, scene: Scene) -> bool {
        if self.exhausted() {
            return false;
        }
        self.evaluations += 1;
        match evaluate(&scene, self.candidate) {
            Outcome::Fail(f) if f.kinds.contains(&self.kind) => {
                self.best = scene;
                self.failure = f;
                true
            }
            _ => false,
        }
    }

    /// Tries each of `edits` on the current best scene in turn, keeping
    /// each that still fails.
    fn try_each(&mut self, edits: Vec<Edit>) -> bool {
        let mut progress = false;
        for edit in edits {
            let mut scene = self.best.clone();
            if edit(&mut scene) {
                progress |= self.try_scene(scene);
            }
        }
        progress
    }

    /// Removes chunks of primitives, halves first, then one at a time.
    fn remove_primitives(&mut self) -> bool {
        let mut progress = false;
        let mut chunk = self.best.primitives.len() / 2;
        while chunk >= 1 {
            let mut start = 0;
            while start < self.best.primitives.len() && self.best.primitives.len() > 1 {
                let end = (start + chunk).min(self.best.primitives.len());
                if end - start == self.best.primitives.len() {
                    break;
                }
                let mut scene = self.best.clone();
                scene.primitives.drain(start..end);
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    start += chunk;
                }
            }
            chunk /= 2;
        }
        progress
    }

    /// The canvas `[x0, x0 + w) × [y0, y0 + h)` of the current scene, with
    /// everything translated by (−x0, −y0): a moving vertex's `from` and
    /// `to` together, so that its path keeps its shape (and, moved by whole
    /// pixels, its snapping).
    fn cropped(&self, x0: u32, y0: u32, w: u32, h: u32) -> Scene {
        let mut scene = self.best.clone();
        let (dx, dy) = (Number::from_int(x0.into()), Number::from_int(y0.into()));
        for p in &mut scene.primitives {
            for v in p.vertices_mut() {
                v.x = &v.x - &dx;
                v.y = &v.y - &dy;
                if let Some(to) = v.to.as_deref_mut() {
                    to[0] = &to[0] - &dx;
                    to[1] = &to[1] - &dy;
                }
            }
        }
        scene.canvas = Canvas {
            width: w,
            height: h,
        };
        scene
    }

    /// Crops to the failing samples and a margin around them. A time
    /// failure is a mean over the moving pixels, spread over the primitives'
    /// paths: when the box of all the pixels it names does not do, the
    /// worst pixel's neighbourhood is tried alone.
    fn crop(&mut self) -> bool {
        let focus = self.failure.focus(self.kind).to_vec();
        if focus.is_empty() {
            return false;
        }
        if self.crop_to(&focus) {
            return true;
        }
        self.kind == Kind::Time && focus.len() > 1 && self.crop_to(&focus[..1])
    }

    /// Crops to the box of `focus` (sample slots) and a margin around it.
    fn crop_to(&mut self, focus: &[usize]) -> bool {
        let Canvas { width, height } = self.best.canvas;
        let w = width as usize;
        let n = samples_per_pixel(&self.best);
        let xs = focus.iter().map(|i| (i / n % w) as u32);
        let ys = focus.iter().map(|i| (i / n / w) as u32);
        let (x0, x1) = (xs.clone().min().unwrap(), xs.max().unwrap());
        let (y0, y1) = (ys.clone().min().unwrap(), ys.max().unwrap());
        for margin in [0, 1, 2, 4] {
            let (ax, ay) = (x0.saturating_sub(margin), y0.saturating_sub(margin));
            let (bx, by) = ((x1 + margin).min(width - 1), (y1 + margin).min(height - 1));
            let (cw, ch) = (bx - ax + 1, by - ay + 1);
            if (cw, ch) == (width, height) {
                break;
            }
            let scene = self.cropped(ax, ay, cw, ch);
            if self.try_scene(scene) {
                return true;
            }
        }
        false
    }

    /// Trims each side of the canvas: half of it, then a quarter, ... then
    /// one row or column at a time.
    fn trim(&mut self) -> bool {
        let mut progress = false;
        for side in 0..4 {
            let extent = |c: Canvas| if side % 2 == 0 { c.width } else { c.height };
            let mut cut = extent(self.best.canvas) / 2;
            while cut >= 1 {
                let Canvas { width, height } = self.best.canvas;
                if extent(self.best.canvas) <= cut {
                    cut /= 2;
                    continue;
                }
                let scene = match side {
                    0 => self.cropped(cut, 0, width - cut, height),
                    1 => self.cropped(0, cut, width, height - cut),
                    2 => self.cropped(0, 0, width - cut, height),
                    _ => self.cropped(0, 0, width, height - cut),
                };
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    cut /= 2;
                }
            }
        }
        progress
    }

    /// Drops depth, attributes, w, and every rule, line option and
    /// expectation that is not needed for the failure.
    fn simplify_state(&mut self) -> bool {
        let mut edits: Vec<Edit> = Vec::new();
        edits.push(Box::new(|s| {
            let changed = s.has_depth;
            s.has_depth = false;
            for p in &mut s.primitives {
                for v in p.vertices_mut() {
                    v.z = Number::ZERO;
                }
            }
            changed
        }));
        for k in (0..self.best.attribute_count).rev() {
            edits.push(Box::new(move |s| {
                s.attribute_count -= 1;
                for p in &mut s.primitives {
                    for v in p.vertices_mut() {
                        v.attributes.remove(k);
                    }
                }
                true
            }));
        }
        edits.push(Box::new(|s| {
            let mut changed = false;
            for p in &mut s.primitives {
                for v in p.vertices_mut() {
                    changed |= v.w != Number::ONE;
                    v.w = Number::ONE;
                }
            }
            changed
        }));
        for i in 0..self.best.primitives.len() {
            edits.push(Box::new(move |s| {
                let p = &mut s.primitives[i];
                let changed = p.interpolation() != Interpolation::Perspective;
                match p {
                    Primitive::Triangle(t) => t.interpolation = Interpolation::Perspective,
                    Primitive::Line(l) => l.interpolation = Interpolation::Perspective,
                    Primitive::Polygon(_) => {}
                }
                changed
            }));
            edits.push(Box::new(move |s| match &mut s.primitives[i] {
                Primitive::Line(l) => {
                    let before = (l.width.clone(), l.last_pixel, l.parameter);
                    l.width = Number::ONE;
                    l.last_pixel = LastPixel::Include;
                    l.parameter = LineParameter::Major;
                    before != (l.width.clone(), l.last_pixel, l.parameter)
                }
                Primitive::Triangle(_) | Primitive::Polygon(_) => false,
            }));
            for option in 0..3 {
                edits.push(Box::new(move |s| match &mut s.primitives[i] {
                    Primitive::Line(l) => match option {
                        0 => std::mem::replace(&mut l.width, Number::ONE) != Number::ONE,
                        1 => {
                            std::mem::replace(&mut l.last_pixel, LastPixel::Include)
                                != LastPixel::Include
                        }
                        _ => {
                            std::mem::replace(&mut l.parameter, LineParameter::Major)
                                != LineParameter::Major
                        }
                    },
                    Primitive::Triangle(_) | Primitive::Polygon(_) => false,
                }));
            }
        }
        edits.push(Box::new(|s| {
            std::mem::replace(&mut s.rules.fill_rule, FillRule::TopLeft) != FillRule::TopLeft
        }));
        edits.push(Box::new(|s| {
            std::mem::replace(&mut s.rules.cull, Cull::None) != Cull::None
        }));
        if !matches!(self.kind, Kind::Holes | Kind::Overdraw) {
            edits.push(Box::new(|s| std::mem::take(&mut s.expect.watertight)));
        }
        edits.push(Box::new(|s| {
            std::mem::take(&mut s.expect.max_mismatched_samples) != 0
        }));
        self.try_each(edits)
    }

    /// Drops `effects.antialias`, or else makes it simpler: fewer samples
    /// (each smaller count the pattern allows, smallest first), the
    /// standard or grid pattern, seed 0, not adaptive, 8 position bits.
    fn simplify_antialias(&mut self) -> bool {
        let Some(aa) = self.best.effects.antialias.clone() else {
            return false;
        };
        let mut edits: Vec<Edit> = vec![Box::new(|s| s.effects.antialias.take().is_some())];
        // Each edit changes the current best only toward the simplest
        // (fewer samples; standard, else grid), so no two undo each other.
        for n in [1, 2, 3, 4, 8, 9, 16, 64] {
            if n < aa.samples && aa.pattern.check_count(n).is_ok() {
                edits.push(Box::new(move |s| {
                    s.effects.antialias.as_mut().is_some_and(|a| {
                        let fewer = n < a.samples && a.pattern.check_count(n).is_ok();
                        if fewer {
                            a.samples = n;
                        }
                        fewer
                    })
                }));
            }
        }
        for pattern in [Pattern::Standard, Pattern::Grid] {
            if aa.pattern != pattern && pattern.check_count(aa.samples).is_ok() {
                edits.push(Box::new(move |s| {
                    s.effects.antialias.as_mut().is_some_and(|a| {
                        let simpler = a.pattern != pattern
                            && a.pattern != Pattern::Standard
                            && pattern.check_count(a.samples).is_ok();
                        if simpler {
                            a.pattern = pattern;
                            a.seed = 0;
                        }
                        simpler
                    })
                }));
            }
        }
        edits.push(Box::new(|s| {
            s.effects.antialias.as_mut().is_some_and(|a| {
                let before = (a.seed, a.adaptive, a.position_bits);
                if !a.pattern.is_seeded() {
                    a.seed = 0;
                }
                a.adaptive = false;
                a.position_bits = 8;
                before != (a.seed, a.adaptive, a.position_bits)
            })
        }));
        edits.push(Box::new(|s| {
            s.effects
                .antialias
                .as_mut()
                .is_some_and(|a| std::mem::replace(&mut a.seed, 0) != 0)
        }));
        self.try_each(edits)
    }

    /// Makes `effects.motion_blur` simpler: fewer time samples (smallest
    /// first), the whole shutter, the `stratified` pattern, seed 0. Each
    /// edit moves the current best only toward those, so the measure
    /// (N, then how far each field is from its simplest) falls.
    fn simplify_motion(&mut self) -> bool {
        let Some(blur) = self.best.effects.motion_blur.clone() else {
            return false;
        };
        let mut edits: Vec<Edit> = Vec::new();
        for n in [1, 2, 4, 8, 16, 32] {
            if n < blur.samples {
                edits.push(Box::new(move |s| {
                    s.effects.motion_blur.as_mut().is_some_and(|b| {
                        let fewer = n < b.samples;
                        if fewer {
                            b.samples = n;
                        }
                        fewer
                    })
                }));
            }
        }
        edits.push(Box::new(|s| {
            s.effects
                .motion_blur
                .as_mut()
                .is_some_and(|b| std::mem::replace(&mut b.shutter, [0, TIME_ONE]) != [0, TIME_ONE])
        }));
        edits.push(Box::new(|s| {
            s.effects.motion_blur.as_mut().is_some_and(|b| {
                std::mem::replace(&mut b.pattern, TimePattern::Stratified)
                    != TimePattern::Stratified
            })
        }));
        edits.push(Box::new(|s| {
            s.effects
                .motion_blur
                .as_mut()
                .is_some_and(|b| std::mem::replace(&mut b.seed, 0) != 0)
        }));
        self.try_each(edits)
    }

    /// Makes moving vertices static, keeping `from` as the position: each
    /// primitive's all at once, then one at a time. Fewer paths each time.
    fn freeze_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            let paths = |s: &Scene| {
                s.primitives[i]
                    .vertices()
                    .iter()
                    .filter(|v| v.to.is_some())
                    .count()
            };
            if paths(&self.best) > 1 {
                let mut scene = self.best.clone();
                for v in scene.primitives[i].vertices_mut() {
                    v.to = None;
                }
                progress |= self.try_scene(scene);
            }
            for j in 0..self.best.primitives[i].vertices().len() {
                if self.best.primitives[i].vertices()[j].to.is_some() {
                    let mut scene = self.best.clone();
                    scene.primitives[i].vertices_mut()[j].to = None;
                    progress |= self.try_scene(scene);
                }
            }
        }
        progress
    }

    /// Removes whole contours of polygons, then single vertices of contours
    /// longer than 3, and sets the fill to nonzero; a polygon of one
    /// triangular contour becomes a triangle when that still fails.
    fn remove_contours_and_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            let mut c = 0;
            while let Primitive::Polygon(p) = &self.best.primitives[i] {
                if c >= p.contour_ends.len() || p.contour_ends.len() == 1 {
                    break;
                }
                let mut scene = self.best.clone();
                if let Primitive::Polygon(q) = &mut scene.primitives[i] {
                    remove_contour(q, c);
                }
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    c += 1;
                }
            }
            let mut k = 0;
            while let Primitive::Polygon(p) = &self.best.primitives[i] {
                if k >= p.vertices.len() {
                    break;
                }
                let mut scene = self.best.clone();
                let removed = match &mut scene.primitives[i] {
                    Primitive::Polygon(q) => remove_vertex(q, k),
                    _ => false,
                };
                if removed && self.try_scene(scene) {
                    progress = true;
                } else {
                    k += 1;
                }
            }
            let mut scene = self.best.clone();
            if let Primitive::Polygon(q) = &mut scene.primitives[i] {
                if q.fill != PolygonFill::NonZero {
                    q.fill = PolygonFill::NonZero;
                    progress |= self.try_scene(scene);
                }
            }
            if let Primitive::Polygon(q) = &self.best.primitives[i] {
                if q.contour_ends == [3] {
                    let mut scene = self.best.clone();
                    let vertices = [
                        q.vertices[0].clone(),
                        q.vertices[1].clone(),
                        q.vertices[2].clone(),
                    ];
                    scene.primitives[i] = Primitive::Triangle(Triangle {
                        vertices,
                        interpolation: Interpolation::Perspective,
                    });
                    progress |= self.try_scene(scene);
                }
            }
        }
        progress
    }

    /// How simple a vertex position is: its larger denominator, then how
    /// far it lies outside the canvas, then its distance from the origin
    /// (L1). Every coordinate move makes one vertex's key smaller.
    fn position_key(&self, x: &Number, y: &Number) -> (UBig, Number, Number) {
        let canvas = self.best.canvas;
        let outside = |v: &Number, side: u32| {
            let hi = Number::from_int(side.into());
            if *v < Number::ZERO {
                v.abs()
            } else if *v > hi {
                v - &hi
            } else {
                Number::ZERO
            }
        };
        (
            x.denominator().max(y.denominator()).clone(),
            &outside(x, canvas.width) + &outside(y, canvas.height),
            &x.abs() + &y.abs(),
        )
    }

    /// The centre of the first sample that shows the failure (the canvas's
    /// middle when none does).
    fn focus_sample(&self) -> [Number; 2] {
        let Canvas { width, height } = self.best.canvas;
        let n = samples_per_pixel(&self.best);
        let (px, py) = match self.failure.focus(self.kind).first() {
            Some(&i) => (
                (i / n % width as usize) as i64,
                (i / n / width as usize) as i64,
            ),
            None => (i64::from(width / 2), i64::from(height / 2)),
        };
        [Number::ratio(2 * px + 1, 2), Number::ratio(2 * py + 1, 2)]
    }

    /// Simpler positions for a vertex at `p`, simplest first: one axis at a
    /// time (integers on the canvas nearest it, coarser dyadic grids,
    /// halfway in from far away), then both axes rounded together, then
    /// pulled halfway toward the failing sample (which keeps a vertex on a
    /// line through that sample) and halfway along each edge to a
    /// `partner` (which keeps the edge's line: a line keeps its slope), each
    /// on coarser grids.
    fn position_candidates(&self, p: &[Number; 2], partners: &[[Number; 2]]) -> Vec<[Number; 2]> {
        let finest = self
            .best
            .rules
            .subpixel_bits
            .unwrap_or(MAX_SUBPIXEL_BITS)
            .min(MAX_SUBPIXEL_BITS);
        let Canvas { width, height } = self.best.canvas;
        let [x, y] = p;
        let mut out: Vec<[Number; 2]> = Vec::new();
        out.extend(
            simpler(x, 0, width.into(), finest)
                .into_iter()
                .map(|c| [c, y.clone()]),
        );
        out.extend(
            simpler(y, 0, height.into(), finest)
                .into_iter()
                .map(|c| [x.clone(), c]),
        );
        let [fx, fy] = self.focus_sample();
        let half = |a: &Number, b: &Number| num(&((a.as_rbig() + b.as_rbig()) / RBig::from(2u8)));
        let mut targets = vec![p.clone(), [half(x, &fx), half(y, &fy)]];
        targets.extend(partners.iter().map(|q| [half(x, &q[0]), half(y, &q[1])]));
        for target in &targets {
            for k in 0..=finest {
                out.push(target.each_ref().map(|c| num(&snap(c, k))));
            }
        }
        let current = self.position_key(x, y);
        let mut seen: Vec<[Number; 2]> = Vec::new();
        out.retain(|c| {
            let keep = !seen.contains(c) && self.position_key(&c[0], &c[1]) < current;
            seen.push(c.clone());
            keep
        });
        out
    }

    /// Moves every vertex at one position together (a mesh stays a mesh).
    fn move_shared_vertices(&mut self) -> bool {
        let mut progress = false;
        let mut positions: Vec<[Number; 2]> = Vec::new();
        for v in self.best.vertices() {
            let p = [v.x.clone(), v.y.clone()];
            if !positions.contains(&p) {
                positions.push(p);
            }
        }
        for position in positions {
            let at = |v: &Vertex| v.x == position[0] && v.y == position[1];
            let mut partners: Vec<[Number; 2]> = Vec::new();
            for p in &self.best.primitives {
                if p.vertices().iter().any(at) {
                    for v in p.vertices().iter().filter(|v| !at(v)) {
                        let q = [v.x.clone(), v.y.clone()];
                        if !partners.contains(&q) {
                            partners.push(q);
                        }
                    }
                }
            }
            for c in self.position_candidates(&position, &partners) {
                let mut scene = self.best.clone();
                for p in &mut scene.primitives {
                    for v in p.vertices_mut() {
                        if v.x == position[0] && v.y == position[1] {
                            [v.x, v.y] = c.clone();
                        }
                    }
                }
                if self.try_scene(scene) {
                    progress = true;
                    break;
                }
            }
        }
        progress
    }

    /// Moves each vertex on its own. A moving vertex's whole path is
    /// moved first (its `to` by as much as its `from`, which keeps the
    /// velocity) when that makes `to` no less simple, then its `from` alone.
    fn move_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            for j in 0..self.best.primitives[i].vertices().len() {
                let vertices = self.best.primitives[i].vertices();
                let position = [vertices[j].x.clone(), vertices[j].y.clone()];
                let end = vertices[j].to.as_deref().cloned();
                let partners: Vec<[Number; 2]> = (0..vertices.len())
                    .filter(|&k| k != j)
                    .map(|k| [vertices[k].x.clone(), vertices[k].y.clone()])
                    .collect();
                for c in self.position_candidates(&position, &partners) {
                    let mut tries = Vec::new();
                    if let Some([tx, ty]) = &end {
                        let to = [tx + &(&c[0] - &position[0]), ty + &(&c[1] - &position[1])];
                        if self.position_key(&to[0], &to[1]) <= self.position_key(tx, ty) {
                            tries.push(Some(to));
                        }
                    }
                    tries.push(None);
                    let mut moved = false;
                    for to in tries {
                        let mut scene = self.best.clone();
                        let v = &mut scene.primitives[i].vertices_mut()[j];
                        [v.x, v.y] = c.clone();
                        if let (Some(to), Some(end)) = (to, v.to.as_deref_mut()) {
                            *end = to;
                        }
                        if self.try_scene(scene) {
                            moved = true;
                            break;
                        }
                    }
                    if moved {
                        progress = true;
                        break;
                    }
                }
            }
        }
        progress
    }

    /// Moves the ends of paths (`to`) to simpler values: every vertex with
    /// the same path together (a moving edge shared by two triangles stays
    /// shared), the candidates as for positions, with the path's start
    /// among the partners (halfway to it is a shorter path).
    fn move_ends(&mut self) -> bool {
        let mut progress = false;
        let mut paths: Vec<[[Number; 2]; 2]> = Vec::new();
        for v in self.best.vertices() {
            if let Some(to) = v.to.as_deref() {
                let path = [[v.x.clone(), v.y.clone()], to.clone()];
                if !paths.contains(&path) {
                    paths.push(path);
                }
            }
        }
        for [from, to] in paths {
            let on = |v: &Vertex| v.x == from[0] && v.y == from[1] && v.to.as_deref() == Some(&to);
            let mut partners = vec![from.clone()];
            for p in &self.best.primitives {
                if p.vertices().iter().any(on) {
                    for v in p.vertices().iter().filter(|v| !on(v)) {
                        let [x, y] = v.end();
                        let q = [x.clone(), y.clone()];
                        if !partners.contains(&q) {
                            partners.push(q);
                        }
                    }
                }
            }
            for c in self.position_candidates(&to, &partners) {
                let mut scene = self.best.clone();
                for p in &mut scene.primitives {
                    for v in p.vertices_mut() {
                        if on(v) {
                            v.to = Some(Box::new(c.clone()));
                        }
                    }
                }
                if self.try_scene(scene) {
                    progress = true;
                    break;
                }
            }
        }
        progress
    }

    /// Simpler depth, w and attribute values, vertex by vertex.
    fn simplify_values(&mut self) -> bool {
        let mut progress = false;
        let (zero, one) = (Number::ZERO, Number::ONE);
        for i in 0..self.best.primitives.len() {
            for j in 0..self.best.primitives[i].vertices().len() {
                // Slot 0: z, 1: w, 2..: attributes.
                for slot in 0..2 + self.best.attribute_count {
                    if slot == 0 && !self.best.has_depth {
                        continue;
                    }
                    let get = |s: &Scene| {
                        let v = &s.primitives[i].vertices()[j];
                        match slot {
                            0 => v.z.clone(),
                            1 => v.w.clone(),
                            k => v.attributes[k - 2].clone(),
                        }
                    };
                    let current = get(&self.best);
                    let centre = if slot == 1 { &one } else { &zero };
                    let current_key = key(&current, centre, centre, centre);
                    let candidates = simpler(&current, -4, 4, 0)
                        .into_iter()
                        .filter(|c| key(c, centre, centre, centre) < current_key)
                        .filter(|c| slot != 1 || c.is_positive());
                    for c in candidates.collect::<Vec<_>>() {
                        let mut scene = self.best.clone();
                        let v = &mut scene.primitives[i].vertices_mut()[j];
                        match slot {
                            0 => v.z = c,
                            1 => v.w = c,
                            k => v.attributes[k - 2] = c,
                        }
                        if self.try_scene(scene) {
                            progress = true;
                            break;
                        }
                    }
                }
            }
        }
        progress
    }

    /// Fewer subpixel bits, when snapping still moves a vertex (otherwise
    /// the case keeps its grid, which then does not matter).
    fn reduce_bits(&mut self) -> bool {
        let bits = self.best.rules.subpixel_bits;
        let on_grid = |b: Option<u32>| {
            coordinates(&self.best).all(|c| b.is_none_or(|b| &snap(c, b) == c.as_rbig()))
        };
        if bits.is_some() && on_grid(bits) {
            return false;
        }
        let top = bits.map_or(MAX_SUBPIXEL_BITS + 1, |b| b);
        for b in 0..top {
            let mut scene = self.best.clone();
            scene.rules.subpixel_bits = Some(b);
            if self.try_scene(scene) {
                return true;
            }
        }
        false
    }
}

impl Shrinker<'_> {
    /// Puts `subpixel_bits` back to the default 8 when every vertex lies on
    /// both grids (so snapping moves nothing either way) and the failure
    /// stays: a case is easier to read on the usual grid.
    fn restore_default_bits(&mut self) {
        let default = Rules::default().subpixel_bits;
        let bits = self.best.rules.subpixel_bits;
        let on = |b: Option<u32>, v: &Number| b.is_none_or(|b| &snap(v, b) == v.as_rbig());
        if bits == default || !coordinates(&self.best).all(|c| on(bits, c) && on(default, c)) {
            return;
        }
        let mut scene = self.best.clone();
        scene.rules.subpixel_bits = default;
        self.try_scene(scene);
    }
}

/// Every coordinate of every vertex: its position (`from`) and, for a
/// moving vertex, its `to`.
fn coordinates(scene: &Scene) -> impl Iterator<Item = &Number> {
    scene.vertices().flat_map(|v| {
        [&v.x, &v.y]
            .into_iter()
            .chain(v.to.iter().flat_map(|to| to.iter()))
    })
}

/// Removes contour `c` of a polygon of several contours.
fn remove_contour(p: &mut Polygon, c: usize) {
    let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
    let end = p.contour_ends[c];
    p.vertices.drain(start..end);
    p.contour_ends.remove(c);
    for e in &mut p.contour_ends[c..] {
        *e -= end - start;
    }
}

/// Removes vertex `k` of a polygon when its contour keeps 3 or more;
/// `false` when it would not.
fn remove_vertex(p: &mut Polygon, k: usize) -> bool {
    let c = p.contour_ends.partition_point(|&e| e <= k);
    let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
    if p.contour_ends[c] - start <= 3 {
        return false;
    }
    p.vertices.remove(k);
    for e in &mut p.contour_ends[c..] {
        *e -= 1;
    }
    true
}

// --- Case files ------------------------------------------------------------

fn json_number(n: &Number) -> String {
    let s = n.to_exact_string();
    if s.contains('/') {
        format!("\"{s}\"")
    } else {
        s
    }
}

fn json_string(s: &str) -> String {
    serde_json::to_string(s).expect("a string serializes")
}

fn position_json(x: &Number, y: &Number) -> String {
    format!("[{}, {}]", json_number(x), json_number(y))
}

fn vertex_json(scene: &Scene, v: &Vertex) -> String {
    let position = position_json(&v.x, &v.y);
    if !scene.has_depth && v.w == Number::ONE && v.attributes.is_empty() && v.to.is_none() {
        return position;
    }
    let mut fields = match v.to.as_deref() {
        // A moving vertex (or one written with from = to, which is static).
        Some([x, y]) => vec![
            format!("\"from\": {position}"),
            format!("\"to\": {}", position_json(x, y)),
        ],
        None => vec![format!("\"position\": {position}")],
    };
    if scene.has_depth {
        fields.push(format!("\"z\": {}", json_number(&v.z)));
    }
    if v.w != Number::ONE {
        fields.push(format!("\"w\": {}", json_number(&v.w)));
    }
    if !v.attributes.is_empty() {
        let values: Vec<String> = v.attributes.iter().map(json_number).collect();
        fields.push(format!("\"attributes\": [{}]", values.join(", ")));
    }
    format!("{{ {} }}", fields.join(", "))
}

fn primitive_json(scene: &Scene, p: &Primitive) -> String {
    let vertices: Vec<String> = p.vertices().iter().map(|v| vertex_json(scene, v)).collect();
    let mut fields = match p {
        Primitive::Triangle(_) => vec![format!("\"triangle\": [{}]", vertices.join(", "))],
        Primitive::Polygon(polygon) => {
            let contours: Vec<String> = polygon
                .contours()
                .map(|c| {
                    let vs: Vec<String> = c.iter().map(|v| vertex_json(scene, v)).collect();
                    format!("[{}]", vs.join(", "))
                })
                .collect();
            vec![
                format!("\"contours\": [{}]", contours.join(", ")),
                format!("\"fill\": \"{}\"", polygon.fill.name()),
            ]
        }
        Primitive::Line(l) => {
            let mut f = vec![
                format!("\"line\": [{}]", vertices.join(", ")),
                format!("\"rule\": \"{}\"", l.rule.name()),
            ];
            if l.rule.is_wide() && l.width != Number::ONE {
                f.push(format!("\"width\": {}", json_number(&l.width)));
            }
            if l.rule == LineRule::Midpoint && l.last_pixel == LastPixel::Exclude {
                f.push("\"last_pixel\": \"exclude\"".to_owned());
            }
            if l.parameter == LineParameter::Projected {
                f.push("\"parameter\": \"projected\"".to_owned());
            }
            f
        }
    };
    if !matches!(p, Primitive::Polygon(_)) && p.interpolation() != Interpolation::Perspective {
        fields.push(format!(
            "\"interpolation\": \"{}\"",
            p.interpolation().name()
        ));
    }
    format!("{{ {} }}", fields.join(", "))
}

/// A scene as a case file (SPEC.md §1), every number exact.
pub fn case_json(scene: &Scene) -> String {
    let bits = scene
        .rules
        .subpixel_bits
        .map_or("null".to_owned(), |b| b.to_string());
    let primitives: Vec<String> = scene
        .primitives
        .iter()
        .map(|p| format!("    {}", primitive_json(scene, p)))
        .collect();
    let e = &scene.expect;
    let mut expect = Vec::new();
    if e.max_mismatched_samples != 0 {
        expect.push(format!(
            "\"max_mismatched_samples\": {}",
            e.max_mismatched_samples
        ));
    }
    if e.watertight {
        expect.push("\"watertight\": true".to_owned());
    }
    if let Some(n) = e.samples_covered {
        expect.push(format!("\"samples_covered\": {n}"));
    }
    if let Some(x) = e.max_abs_error {
        expect.push(format!("\"max_abs_error\": {x:e}"));
    }
    if let Some(x) = e.max_ulp_error {
        expect.push(format!("\"max_ulp_error\": {x:e}"));
    }
    if let Some(x) = e.max_coverage_error {
        expect.push(format!("\"max_coverage_error\": {x:e}"));
    }
    if let Some(x) = e.max_coverage_rms {
        expect.push(format!("\"max_coverage_rms\": {x:e}"));
    }
    if let Some(a) = &e.area {
        expect.push(format!("\"area\": \"{}\"", a.to_exact_string()));
    }
    if let Some(x) = e.max_time_error {
        expect.push(format!("\"max_time_error\": {x:e}"));
    }
    if let Some(x) = e.max_time_rms {
        expect.push(format!("\"max_time_rms\": {x:e}"));
    }
    if !e.time_coverage.is_empty() {
        let pins: Vec<String> = e
            .time_coverage
            .iter()
            .map(|pin| {
                format!(
                    "{{ \"pixel\": [{}, {}], \"value\": {} }}",
                    pin.pixel[0],
                    pin.pixel[1],
                    json_number(&pin.value)
                )
            })
            .collect();
        expect.push(format!("\"time_coverage\": [{}]", pins.join(", ")));
    }
    let mut effects = Vec::new();
    if let Some(a) = &scene.effects.antialias {
        effects.push(format!(
            "\"antialias\": {{ \"samples\": {}, \"pattern\": \"{}\", \"seed\": {}, \"adaptive\": {}, \"position_bits\": {} }}",
            a.samples,
            a.pattern.name(),
            a.seed,
            a.adaptive,
            a.position_bits
        ));
    }
    if let Some(b) = &scene.effects.motion_blur {
        let [open, close] = b
            .shutter
            .map(|t| json_number(&Number::ratio(t.into(), TIME_ONE.into())));
        effects.push(format!(
            "\"motion_blur\": {{ \"shutter\": [{open}, {close}], \"samples\": {}, \"pattern\": \"{}\", \"seed\": {} }}",
            b.samples,
            b.pattern.name(),
            b.seed
        ));
    }
    let effects = if effects.is_empty() {
        String::new()
    } else {
        format!("  \"effects\": {{ {} }},\n", effects.join(", "))
    };
    format!(
        "{{\n  \"name\": {},\n  \"description\": {},\n  \"canvas\": {{ \"width\": {}, \"height\": {} }},\n  \"rules\": {{ \"subpixel_bits\": {bits}, \"fill_rule\": \"{}\", \"cull\": \"{}\" }},\n{effects}  \"primitives\": [\n{}\n  ],\n  \"expect\": {{ {} }}\n}}\n",
        json_string(&scene.name),
        json_string(&scene.description),
        scene.canvas.width,
        scene.canvas.height,
        scene.rules.fill_rule.name(),
        scene.rules.cull.name(),
        primitives.join(",\n"),
        expect.join(", "),
    )
}

// --- The search ------------------------------------------------------------

/// What `rastercheck fuzz` was asked to do.
#[derive(Clone, Debug)]
pub struct Options {
    pub seed: u64,
    /// Scenes to try.
    pub cases: u64,
    /// One family, or all of them in turn.
    pub family: Option<Family>,
    /// Only failures of these kinds count (all when empty).
    pub check: Vec<Kind>,
    /// Stop after this many failures.
    pub max_failures: usize,
    /// Folder for the case files.
    pub out: PathBuf,
    /// The command line that reproduces the search, for descriptions.
    pub command: String,
}

/// One failure found, shrunk and written.
#[derive(Clone, Debug)]
pub struct Found {
    pub index: u64,
    pub family: Family,
    pub kind: Kind,
    pub path: PathBuf,
    pub original: Scene,
    pub shrunk: Shrunk,
}

/// What a search did.
#[derive(Clone, Debug, Default)]
pub struct Summary {
    pub cases: u64,
    pub passed: u64,
    pub unsupported: u64,
    /// Failures of kinds `--check` did not ask for.
    pub ignored: u64,
    pub found: Vec<Found>,
}

fn sanitize(text: &str) -> String {
    let s: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    let s = s.trim_matches('_').to_owned();
    s.chars().take(40).collect()
}

fn describe_size(scene: &Scene) -> String {
    let count = |f: fn(&Primitive) -> bool| scene.primitives.iter().filter(|p| f(p)).count();
    let triangles = count(|p| matches!(p, Primitive::Triangle(_)));
    let lines = count(|p| matches!(p, Primitive::Line(_)));
    let polygons = count(|p| matches!(p, Primitive::Polygon(_)));
    let mut parts = Vec::new();
    for (n, what) in [
        (triangles, "triangle"),
        (lines, "line"),
        (polygons, "polygon"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}{}", if n == 1 { "" } else { "s" }));
        }
    }
    let antialias = scene.effects.antialias.as_ref().map_or(String::new(), |a| {
        let s = if a.samples == 1 { "" } else { "s" };
        format!(" at {} {} sample{s} per pixel", a.samples, a.pattern.name())
    });
    let moving = scene.primitives.iter().filter(|p| p.moves()).count();
    let motion = match &scene.effects.motion_blur {
        Some(b) if moving > 0 => {
            let shutter = if b.shutter == [0, TIME_ONE] {
                String::new()
            } else {
                let [open, close] = b.shutter.map(|t| Number::ratio(t.into(), TIME_ONE.into()));
                format!(" over the shutter [{open}, {close}]")
            };
            let s = if b.samples == 1 { "" } else { "s" };
            format!(
                ", {moving} moving, with {} {} time sample{s}{shutter}",
                b.samples,
                b.pattern.name()
            )
        }
        _ => String::new(),
    };
    format!(
        "{} on a {}×{} canvas{antialias}{motion}",
        parts.join(" and "),
        scene.canvas.width,
        scene.canvas.height
    )
}

/// The shrunk scene as the case to write: named, described, with the
/// reference's sample count pinned.
fn finished_case(
    candidate: &dyn Rasterizer,
    options: &Options,
    index: u64,
    family: Family,
    original: &Scene,
    kind: Kind,
    shrunk: &Shrunk,
) -> Scene {
    let mut scene = shrunk.scene.clone();
    scene.name = format!(
        "fuzz_{}_{}_{}_{index}",
        sanitize(candidate.name()),
        kind.name(),
        options.seed
    );
    let reasons = shrunk.failure.reasons_for(kind).join("; ");
    scene.description = format!(
        "Found by `{}`: case {index} ({} family, seed {}), originally {}, shrunk to {} in {} evaluations. {} fails it: {reasons}. A correct rasterizer {}.",
        options.command,
        family.name(),
        options.seed,
        describe_size(original),
        describe_size(&shrunk.scene),
        shrunk.evaluations,
        candidate.name(),
        kind.promise(),
    );
    let plan = Plan::for_scene(&scene);
    if plan.motion.is_some() {
        // Judged on time coverage only: pin the reference's time coverage
        // of the first pixel the failure shows, exact when the oracle's
        // bound is 0 (the nearest f64 otherwise, well within the pin's
        // tolerance of bound + 10^-12).
        let per_pixel = samples_per_pixel(&scene);
        let p = shrunk
            .failure
            .focus(kind)
            .first()
            .map_or(0, |i| i / per_pixel);
        let certified = reference::motion::time_coverage(&scene, &plan);
        if let Some(c) = certified.get(p) {
            let value = if c.bound == RBig::ZERO {
                num(&c.value)
            } else {
                let nearest = reference::area::to_f64_nearest(&c.value);
                Number::from_decimal(&format!("{nearest}")).expect("an f64 is a decimal")
            };
            let width = scene.canvas.width as usize;
            scene.expect.time_coverage = vec![TimePin {
                pixel: [(p % width) as u32, (p / width) as u32],
                value,
            }];
        }
        return scene;
    }
    scene.expect.samples_covered = Some(reference::render(&scene, &plan).covered_samples());
    if scene.effects.antialias.is_some() {
        let total = reference::exact_areas(&scene)
            .iter()
            .fold(RBig::ZERO, |sum, a| sum + a);
        scene.expect.area = Some(num(&total));
    }
    scene
}

/// Searches `options.cases` scenes for failures of `candidate`, shrinks and
/// writes each (up to `max_failures`), and reports progress through `log`.
/// `Err` when a case file cannot be written.
pub fn search(
    candidate: &dyn Rasterizer,
    options: &Options,
    log: &mut dyn FnMut(&str),
) -> Result<Summary, String> {
    let mut summary = Summary::default();
    if candidate.is_foil() {
        log(&format!(
            "note: {} is a foil: `run` reports its departures as FOIL, never as failures",
            candidate.name()
        ));
    }
    for index in 0..options.cases {
        let (family, scene) = generate(options.seed, index, options.family);
        summary.cases += 1;
        let failure = match evaluate(&scene, candidate) {
            Outcome::Pass => {
                summary.passed += 1;
                continue;
            }
            Outcome::Unsupported(_) => {
                summary.unsupported += 1;
                continue;
            }
            Outcome::Invalid(why) => {
                log(&format!(
                    "note: case {index} ({}) skipped: {why}",
                    family.name()
                ));
                continue;
            }
            Outcome::Fail(f) => f,
        };
        let Some(kind) = failure
            .kinds
            .iter()
            .copied()
            .find(|k| options.check.is_empty() || options.check.contains(k))
        else {
            summary.ignored += 1;
            continue;
        };
        log(&format!(
            "FAIL  case {index} ({}, {}): {}",
            family.name(),
            describe_size(&scene),
            failure.reasons_for(kind).join("; ")
        ));
        let shrunk = shrink(&scene, failure, kind, candidate);
        let case = finished_case(candidate, options, index, family, &scene, kind, &shrunk);
        let text = case_json(&case);
        // The file must say what the shrinker saw: read it back and judge
        // it again.
        let reread = crate::scene::parse_case(&text, "the shrunk case", &Default::default())
            .map_err(|e| format!("internal error: the shrunk case does not read back: {e}"))?;
        match evaluate(&reread, candidate) {
            Outcome::Fail(f) if f.kinds.contains(&kind) => {}
            other => {
                return Err(format!(
                    "internal error: the shrunk case read back no longer fails {}: {other:?}",
                    kind.name()
                ))
            }
        }
        std::fs::create_dir_all(&options.out)
            .map_err(|e| format!("{}: {e}", options.out.display()))?;
        let path = options.out.join(format!("{}.json", case.name));
        std::fs::write(&path, &text).map_err(|e| format!("{}: {e}", path.display()))?;
        log(&format!(
            "      shrunk in {} evaluations, {} rounds, {:.0} ms: {}",
            shrunk.evaluations,
            shrunk.rounds,
            shrunk.elapsed.as_secs_f64() * 1000.0,
            describe_size(&shrunk.scene)
        ));
        log(&format!("      wrote {}", path.display()));
        for reason in shrunk.failure.reasons_for(kind) {
            log(&format!("        {reason}"));
        }
        summary.found.push(Found {
            index,
            family,
            kind,
            path,
            original: scene,
            shrunk,
        });
        if summary.found.len() >= options.max_failures {
            break;
        }
    }
    Ok(summary)
}

/// Where `rastercheck fuzz` writes by default.
pub fn default_out() -> &'static Path {
    Path::new("fuzz-cases")
}

/// A seed from the clock, for runs that name none (it is printed).
pub fn clock_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    Rng::new(nanos ^ u64::from(std::process::id())).next_u64() % 1_000_000_000
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generation_is_deterministic() {
        for i in 0..30 {
            let (_, a) = generate(7, i, None);
            let (_, b) = generate(7, i, None);
            assert_eq!(case_json(&a), case_json(&b));
        }
    }

    #[test]
    fn generated_scenes_read_back_as_written() {
        for i in 0..60 {
            let (_, scene) = generate(11, i, None);
            let text = case_json(&scene);
            let back = crate::scene::parse_case(&text, "t", &Default::default())
                .unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(case_json(&back), text);
        }
    }

    #[test]
    fn polygon_and_antialias_families_read_back_and_vary() {
        let (mut contours, mut fills, mut patterns) = (0, Vec::new(), Vec::new());
        let (mut adaptive, mut lines) = (false, false);
        for i in 0..150 {
            for family in [Family::Polygons, Family::Antialias] {
                let (_, scene) = generate(3, i, Some(family));
                let text = case_json(&scene);
                let back = crate::scene::parse_case(&text, "t", &Default::default())
                    .unwrap_or_else(|e| panic!("{e}\n{text}"));
                assert_eq!(case_json(&back), text);
                for p in &scene.primitives {
                    match p {
                        Primitive::Polygon(q) => {
                            contours = contours.max(q.contour_ends.len());
                            if !fills.contains(&q.fill) {
                                fills.push(q.fill);
                            }
                        }
                        Primitive::Line(l) => lines |= l.rule == LineRule::Parallelogram,
                        Primitive::Triangle(_) => {}
                    }
                }
                if let Some(a) = &scene.effects.antialias {
                    assert_eq!(family, Family::Antialias);
                    adaptive |= a.adaptive;
                    if !patterns.contains(&a.pattern) {
                        patterns.push(a.pattern);
                    }
                }
            }
        }
        assert_eq!(contours, 3);
        assert_eq!(fills.len(), 2);
        assert_eq!(patterns.len(), Pattern::ALL.len());
        assert!(adaptive && lines);
    }

    #[test]
    fn motion_family_reads_back_and_varies() {
        let (mut patterns, mut culls, mut shutters) = (Vec::new(), Vec::new(), 0);
        let (mut lines, mut antialiased, mut still, mut frozen_written) = (0, 0, 0, 0);
        let (mut counts, mut moving) = (Vec::new(), 0);
        for i in 0..300 {
            let (family, scene) = generate(5, i, Some(Family::Motion));
            assert_eq!(family, Family::Motion);
            let text = case_json(&scene);
            let back = crate::scene::parse_case(&text, "t", &Default::default())
                .unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(case_json(&back), text);
            let blur = scene.effects.motion_blur.as_ref().expect("motion blur");
            let spatial = scene.effects.antialias.as_ref().map_or(1, |a| a.samples);
            assert!(spatial * blur.samples <= 64, "{text}");
            assert!(
                scene.canvas.pixel_count() * spatial as usize <= 256,
                "{text}"
            );
            for (name, list) in [
                (blur.pattern.name(), &mut patterns),
                (scene.rules.cull.name(), &mut culls),
            ] {
                if !list.contains(&name) {
                    list.push(name);
                }
            }
            if !counts.contains(&blur.samples) {
                counts.push(blur.samples);
            }
            shutters += usize::from(blur.shutter != [0, TIME_ONE]);
            antialiased += usize::from(scene.effects.antialias.is_some());
            lines += scene
                .primitives
                .iter()
                .filter(|p| p.moves() && matches!(p, Primitive::Line(_)))
                .count();
            still += scene.primitives.iter().filter(|p| !p.moves()).count();
            frozen_written += scene
                .vertices()
                .filter(|v| v.to.is_some() && !v.moves())
                .count();
            moving += usize::from(scene.moves());
        }
        assert!(moving > 290, "{moving}");
        assert_eq!(patterns.len(), TimePattern::ALL.len());
        assert_eq!(culls.len(), 3);
        assert!(counts.contains(&1) && counts.contains(&64), "{counts:?}");
        assert!(
            shutters > 30 && antialiased > 30 && lines > 30,
            "{shutters} {antialiased} {lines}"
        );
        assert!(
            still > 30 && frozen_written > 10,
            "{still} {frozen_written}"
        );
    }

    /// The fairness check's sampler (the static reference at each of the
    /// case's own instants) is production's frame, value for value: two
    /// independent readings of SPEC.md §15.3. Other instants (another
    /// seed) give other values.
    #[test]
    fn sampled_time_is_productions_frame() {
        use crate::production::Production;
        let mut differ = 0;
        for i in 0..40 {
            let (_, scene) = generate(9, i, Some(Family::Motion));
            let plan = Plan::for_scene(&scene);
            if plan.motion.is_none() {
                continue;
            }
            let sampled = sampled_time(&scene, &plan);
            let frame = Production
                .rasterize(&scene, &plan)
                .expect("production draws it");
            assert_eq!(
                frame.time.as_deref(),
                Some(sampled.as_slice()),
                "{}",
                case_json(&scene)
            );
            // The same with every pixel's instants taken from its
            // neighbour's seed: a sampler with the wrong instants.
            let mut other = scene.clone();
            if let Some(b) = other.effects.motion_blur.as_mut() {
                b.seed ^= 1;
            }
            differ += usize::from(sampled_time(&other, &Plan::for_scene(&other)) != sampled);
        }
        assert!(differ > 10, "{differ}");
    }

    /// Where few pixels move, the default time RMS bound can fail an
    /// honest sampler: production fails `run` on such a scene, and without
    /// the fairness check the search would blame it. It is skipped instead.
    #[test]
    fn unfair_moving_scenes_are_skipped_not_blamed() {
        use crate::production::Production;
        let mut skipped = 0;
        for i in 0..100 {
            let (_, scene) = generate(1, i, Some(Family::Motion));
            let Outcome::Invalid(why) = evaluate(&scene, &Production) else {
                continue;
            };
            if !why.contains("the sample method with the case's own instants") {
                continue;
            }
            skipped += 1;
            let reference = suite::run_reference(&scene);
            let run = suite::run_candidate(&scene, &reference, &Production);
            let Verdict::Fail(reasons) = run.verdict else {
                panic!("production passes a scene refused as unfair: {why}");
            };
            assert!(
                reasons.iter().all(|r| r.starts_with("time: ")),
                "{reasons:?}"
            );
        }
        assert!(skipped > 0);
    }

    #[test]
    fn contours_and_vertices_are_removed_in_place() {
        let v = |k: i64| Vertex::at(Number::from_int(k), Number::from_int(-k));
        let mut p = Polygon {
            vertices: (0..10).map(v).collect(),
            contour_ends: vec![3, 7, 10],
            fill: PolygonFill::EvenOdd,
        };
        // A 3-vertex contour keeps its vertices.
        assert!(!remove_vertex(&mut p, 1));
        assert!(remove_vertex(&mut p, 4));
        assert_eq!(p.contour_ends, vec![3, 6, 9]);
        let xs = |p: &Polygon| p.vertices.iter().map(|v| v.x.clone()).collect::<Vec<_>>();
        let n = |ks: &[i64]| ks.iter().map(|&k| Number::from_int(k)).collect::<Vec<_>>();
        assert_eq!(xs(&p), n(&[0, 1, 2, 3, 5, 6, 7, 8, 9]));
        remove_contour(&mut p, 1);
        assert_eq!(p.contour_ends, vec![3, 6]);
        assert_eq!(xs(&p), n(&[0, 1, 2, 7, 8, 9]));
        remove_contour(&mut p, 0);
        assert_eq!(p.contour_ends, vec![3]);
        assert_eq!(xs(&p), n(&[7, 8, 9]));
    }

    #[test]
    fn sines_are_close_to_libm() {
        for k in -50..50 {
            let a = f64::from(k) * 0.37;
            let (s, c) = sin_cos(a);
            assert!((s - a.sin()).abs() < 1e-12 && (c - a.cos()).abs() < 1e-12);
        }
    }

    #[test]
    fn simpler_values_are_simpler() {
        let v = Number::ratio(12345, 4096);
        let c = simpler(&v, 0, 4, 8);
        assert_eq!(c[0], Number::from_int(3));
        assert!(c.contains(&Number::ratio(772, 256)));
        let far = simpler(&Number::from_int(20000), 0, 4, 8);
        assert!(far.contains(&Number::from_int(10002)));
    }
}
