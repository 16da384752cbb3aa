//! The `motion` family (SPEC.md §15): moving triangles and parallelogram
//! lines on the paths that make time coverage hard (translations, rotations,
//! collapses through a point, vertices through sample centres, winding flips,
//! double roots, vanishing τ² coefficients), under every time pattern and
//! part of the shutter, sometimes antialiased, sometimes beside a static
//! primitive.

use dashu_ratio::RBig;

use super::common::{plain_triangle, position, scene_of, Values};
use super::polygons::polygon;
use crate::explore::fuzz::geometry::{minus, num, plus, ratio, times, Point};
use crate::explore::fuzz::rng::{sin_cos, Rng};
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    Antialias, Canvas, Cull, FillRule, Interpolation, LastPixel, Line, LineParameter, LineRule,
    MotionBlur, Number, Pattern, Primitive, Rules, Scene, TimePattern, Triangle, Vertex,
};

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
pub(super) fn step(rng: &mut Rng, reach: i64) -> Point {
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
pub(super) fn paths(rng: &mut Rng, canvas: Canvas, n: usize) -> Vec<[Point; 2]> {
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
pub(super) fn motion_scene(rng: &mut Rng) -> Scene {
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
        ..Rules::default()
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
