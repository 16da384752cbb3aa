//! Random polygons (stars, concave, self-intersecting, with holes) on the
//! 1/16 grid, their scenes, and the brute force that decides each sample
//! from scratch as SPEC.md words it; the helpers every test here shares.

use dashu_int::ops::BitTest;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::fixed::Format;
use rastercheck::production::polygon;
use rastercheck::rasterizer::RasterError;
use rastercheck::reference;
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Number, Polygon, PolygonFill, Primitive,
    Rules, Scene, Vertex,
};

pub const SIZE: u32 = 24;

/// Subpixel bits of the random scenes: vertices on the 1/16 grid.
pub const BITS: u32 = 4;

/// A polygon's contours, in units of 2^-BITS pixel.
type Contours = Vec<Vec<[i64; 2]>>;

pub struct Rng(pub SplitMix64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(SplitMix64::new(seed))
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.0.next_u64() % (hi - lo) as u64) as i64
    }

    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.range(0, items.len() as i64) as usize]
    }
}

/// A coordinate in 1/16 pixel, from −4 to SIZE + 4 px: on the half-pixel
/// grid (pixel centres and edges: ties), or anywhere on the 1/16 grid.
pub fn coordinate(rng: &mut Rng, halves: bool) -> i64 {
    let lo = -4 * 16;
    let hi = (i64::from(SIZE) + 4) * 16;
    if halves {
        rng.range(lo / 8, hi / 8) * 8
    } else {
        rng.range(lo, hi)
    }
}

/// Rounds to the half-pixel grid when `halves`.
fn grid(v: i64, halves: bool) -> i64 {
    if halves {
        (v as f64 / 8.0).round() as i64 * 8
    } else {
        v
    }
}

/// A star: 2k points alternating between two radii around a centre.
pub fn star(rng: &mut Rng, halves: bool) -> Contours {
    let k = rng.range(3, 12);
    let c = [rng.range(4, 20) * 16, rng.range(4, 20) * 16];
    let outer = rng.range(4 * 16, 16 * 16) as f64;
    let inner = outer * rng.range(15, 70) as f64 / 100.0;
    let turn = rng.range(0, 1000) as f64 / 1000.0;
    let contour = (0..2 * k)
        .map(|i| {
            let r = if i % 2 == 0 { outer } else { inner };
            let a = (i as f64 / (2 * k) as f64 + turn) * std::f64::consts::TAU;
            [
                grid(c[0] + (r * a.cos()) as i64, halves),
                grid(c[1] + (r * a.sin()) as i64, halves),
            ]
        })
        .collect();
    vec![contour]
}

/// A concave polygon: random radii at sorted random angles (star-shaped).
pub fn concave(rng: &mut Rng, halves: bool) -> Contours {
    let n = rng.range(4, 16);
    let c = [rng.range(6, 18) * 16, rng.range(6, 18) * 16];
    let mut angles: Vec<f64> = (0..n)
        .map(|_| rng.range(0, 10000) as f64 / 10000.0 * std::f64::consts::TAU)
        .collect();
    angles.sort_by(f64::total_cmp);
    let contour = angles
        .iter()
        .map(|a| {
            let r = rng.range(16, 14 * 16) as f64;
            [
                grid(c[0] + (r * a.cos()) as i64, halves),
                grid(c[1] + (r * a.sin()) as i64, halves),
            ]
        })
        .collect();
    vec![contour]
}

/// Any vertices at all: self-intersecting.
pub fn tangle(rng: &mut Rng, halves: bool) -> Contours {
    let n = rng.range(3, 12);
    vec![(0..n)
        .map(|_| [coordinate(rng, halves), coordinate(rng, halves)])
        .collect()]
}

/// Several contours: an outer one with holes, either direction, some
/// crossing each other.
fn holes(rng: &mut Rng, halves: bool) -> Contours {
    let mut contours = concave(rng, halves);
    for _ in 0..rng.range(1, 4) {
        let mut inner = match rng.range(0, 3) {
            0 => star(rng, halves),
            1 => concave(rng, halves),
            _ => tangle(rng, halves),
        }
        .remove(0);
        if rng.range(0, 2) == 0 {
            inner.reverse();
        }
        contours.push(inner);
    }
    contours
}

fn number(units: i64, bits: u32) -> Number {
    Number::ratio(units, 1 << bits)
}

pub fn polygon_of(contours: &Contours, bits: u32, fill: PolygonFill) -> Polygon {
    let mut vertices = Vec::new();
    let mut contour_ends = Vec::new();
    for c in contours {
        vertices.extend(
            c.iter()
                .map(|p| Vertex::at(number(p[0], bits), number(p[1], bits))),
        );
        contour_ends.push(vertices.len());
    }
    Polygon {
        vertices,
        contour_ends,
        fill,
    }
}

pub fn scene_of(
    polygons: Vec<Polygon>,
    rule: FillRule,
    antialias: Option<Antialias>,
    subpixel_bits: Option<u32>,
) -> Scene {
    Scene {
        name: "random polygons".to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: SIZE,
            height: SIZE,
        },
        rules: Rules {
            subpixel_bits,
            fill_rule: rule,
            cull: Cull::None,
            ..Rules::default()
        },
        primitives: polygons.into_iter().map(Primitive::Polygon).collect(),
        effects: Effects {
            antialias,
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    }
}

/// The exact frame, from scratch: each sample's winding number along the
/// ray to +x from the sample nudged as the rule says (SPEC.md §14.1).
/// Vertices are exact multiples of 2^-bits and sample offsets multiples of
/// 2^-position_bits; both go to one integer grid of 2^-k pixel.
fn brute_force(scene: &Scene, plan: &Plan) -> Frame {
    let (offsets, position_bits) = match &plan.antialias {
        Some(s) => (s.offsets.clone(), s.position_bits),
        None => (vec![[1, 1]], 1),
    };
    let polygons: Vec<(&Polygon, usize)> = scene
        .primitives
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match p {
            Primitive::Polygon(p) => Some((p, i)),
            _ => None,
        })
        .collect();
    // Every vertex is an exact dyadic; k fraction bits hold them all.
    let k = scene
        .vertices()
        .flat_map(|v| [&v.x, &v.y])
        .map(|n| n.denominator().bit_len() as u32 - 1)
        .chain([position_bits])
        .max()
        .unwrap();
    let units = |n: &Number| -> i128 {
        let scaled = n.numerator() << k as usize;
        (&(scaled / dashu_int::IBig::from(n.denominator().clone())))
            .try_into()
            .unwrap()
    };
    let (right, down) = match scene.rules.fill_rule {
        FillRule::TopLeft => (true, true),
        FillRule::TopRight => (false, true),
        FillRule::BottomLeft => (true, false),
        FillRule::BottomRight => (false, false),
        FillRule::AllEdges => unreachable!(),
    };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (polygon, index) in polygons {
        let edges: Vec<([i128; 2], [i128; 2])> = polygon
            .edges()
            .map(|(a, b)| ([units(&a.x), units(&a.y)], [units(&b.x), units(&b.y)]))
            .collect();
        for y in 0..scene.canvas.height {
            for x in 0..scene.canvas.width {
                for (s, o) in offsets.iter().enumerate() {
                    let shift = k - position_bits;
                    let px = (i128::from(x) << k) + (i128::from(o[0]) << shift);
                    let py = (i128::from(y) << k) + (i128::from(o[1]) << shift);
                    let mut winding = 0;
                    for &(a, b) in &edges {
                        if a[1] == b[1] {
                            continue;
                        }
                        let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
                        let active = if down {
                            lo <= py && py < hi
                        } else {
                            lo < py && py <= hi
                        };
                        if !active {
                            continue;
                        }
                        // sign(x_c − px) = sign(num) · sign(dy).
                        let dy = b[1] - a[1];
                        let num = (a[0] - px) * dy + (py - a[1]) * (b[0] - a[0]);
                        let sign = num.signum() * dy.signum();
                        let counts = if right { sign > 0 } else { sign >= 0 };
                        if counts {
                            winding += dy.signum();
                        }
                    }
                    let inside = match polygon.fill {
                        PolygonFill::EvenOdd => winding % 2 != 0,
                        PolygonFill::NonZero => winding != 0,
                    };
                    if inside {
                        let i = frame.index(x, y) + s;
                        frame.hit(i, index);
                    }
                }
            }
        }
    }
    frame
}

/// The reference's frame, checked against the brute force: two exact
/// deciders that share no code must agree before either judges production.
pub fn exact(scene: &Scene, plan: &Plan) -> Frame {
    let frame = reference::render(scene, plan);
    let wrong = differences(&brute_force(scene, plan), &frame);
    assert_eq!(wrong, 0, "the reference and the brute force disagree");
    frame
}

/// Samples whose count or owner differs.
pub fn differences(expected: &Frame, actual: &Frame) -> usize {
    assert_eq!(expected.coverage.len(), actual.coverage.len());
    (0..expected.coverage.len())
        .filter(|&i| {
            expected.coverage[i] != actual.coverage[i] || expected.last[i] != actual.last[i]
        })
        .count()
}

pub fn assert_same(expected: &Frame, actual: &Frame, what: &str) {
    let wrong = differences(expected, actual);
    assert!(
        wrong == 0,
        "{what}: {wrong} samples differ from the reference"
    );
}

/// Production's polygon fill called directly into a frame of the plan's
/// samples, in a format `extra_bits` finer than the samples need.
pub fn draw_direct(scene: &Scene, plan: &Plan, extra_bits: u32) -> Result<Frame, RasterError> {
    let bits = scene.rules.subpixel_bits.unwrap_or(BITS);
    let frac_bits = plan
        .antialias
        .as_ref()
        .map_or(bits + 1, |s| s.position_bits.max(bits + 1))
        + extra_bits;
    let format = Format { frac_bits };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (index, p) in scene.primitives.iter().enumerate() {
        if let Primitive::Polygon(p) = p {
            if format.fits_i64() {
                polygon::draw::<i64>(scene, plan, format, index, p, &mut frame)?;
            } else {
                polygon::draw::<i128>(scene, plan, format, index, p, &mut frame)?;
            }
        }
    }
    Ok(frame)
}

type Generator = fn(&mut Rng, bool) -> Contours;

pub const SHAPES: [(&str, Generator); 4] = [
    ("star", star),
    ("concave", concave),
    ("self-intersecting", tangle),
    ("holes", holes),
];

pub fn random_scene(rng: &mut Rng, antialias: Option<Antialias>) -> Scene {
    let halves = rng.range(0, 2) == 0;
    let count = rng.range(1, 3);
    let polygons = (0..count)
        .map(|_| {
            let (_, shape) = rng.pick(&SHAPES);
            let fill = rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]);
            polygon_of(&shape(rng, halves), BITS, fill)
        })
        .collect();
    let rule = rng.pick(&FillRule::CONSISTENT);
    scene_of(polygons, rule, antialias, Some(BITS))
}
