//! The `meshes` family, after the strategies of tests/properties/meshes.rs: fans
//! around sample centres, jittered grids with shared vertices, convex fans
//! and ear-clipped star polygons, kept only when snapping folds no triangle
//! over, each with `expect.watertight: true`.

use std::cmp::Ordering;

use dashu_ratio::RBig;

use super::common::{any_bits, canvas, scene_of, Values};
use crate::explore::fuzz::geometry::{orient, placed, Point};
use crate::explore::fuzz::rng::{sin_cos, Rng};
use crate::scene::{
    Canvas, Cull, FillRule, Interpolation, Number, Primitive, Rules, Scene, Triangle, Vertex,
};

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

/// The points at `angles` around `c`, each at the distance `radius` draws,
/// on the 1/`den` grid.
fn around(
    rng: &mut Rng,
    c: [f64; 2],
    angles: &[f64],
    den: i64,
    radius: impl Fn(&mut Rng) -> f64,
) -> Vec<[Number; 2]> {
    angles
        .iter()
        .map(|&a| {
            let r = radius(rng);
            let (s, co) = sin_cos(a);
            [to_number(c[0] + r * co, den), to_number(c[1] + r * s, den)]
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
    points.extend(around(rng, c, &angles, den, |rng| {
        rng.uniform(0.5, 1.5) * scale
    }));
    let triangles = (1..=n).map(|k| [0, k, k % n + 1]).collect();
    Shape::Triangles(points, triangles)
}

fn convex_polygon(rng: &mut Rng, canvas: Canvas) -> Shape {
    let n = rng.range(3, 14) as usize;
    let c = mesh_centre(rng, canvas);
    let angles = angles(rng, n);
    let scale = radius_scale(rng);
    let den = denominator(rng);
    let points = around(rng, c, &angles, den, |_| scale);
    let triangles = (1..n - 1).map(|k| [0, k, k + 1]).collect();
    Shape::Triangles(points, triangles)
}

fn star_polygon(rng: &mut Rng, canvas: Canvas) -> Shape {
    let n = rng.range(4, 14) as usize;
    let centre = mesh_centre(rng, canvas);
    let angles = angles(rng, n);
    let scale = radius_scale(rng);
    let den = denominator(rng);
    let points = around(rng, centre, &angles, den, |rng| {
        rng.uniform(0.3, 1.5) * scale
    });
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

/// Ear clipping of a polygon star-shaped around `centre`, its `points`
/// already placed on the case's grid: `None` when the placed polygon no
/// longer turns one way around the centre (rounded to 1/65536), seen edge by
/// edge (snapping folded it over), else [`ear_clip`] in that winding.
pub fn ear_clip_star(centre: [f64; 2], points: &[[RBig; 2]]) -> Option<Vec<[usize; 3]>> {
    let c = centre.map(|v| {
        Number::ratio((v * 65536.0).round() as i64, 65536)
            .as_rbig()
            .clone()
    });
    let n = points.len();
    let signs: Vec<_> = (0..n)
        .map(|k| orient(&c, &points[k], &points[(k + 1) % n]))
        .collect();
    if signs.iter().any(|s| *s != signs[0] || s.is_eq()) {
        return None;
    }
    ear_clip(points, signs[0])
}

/// Whether every triangle of a mesh has the same, nonzero orientation on
/// its placed points: no triangle folded over or collapsed by snapping.
/// An empty mesh is no mesh.
pub fn winds_one_way(points: &[Point], triangles: &[[usize; 3]]) -> bool {
    let signs: Vec<_> = triangles
        .iter()
        .map(|t| orient(&points[t[0]], &points[t[1]], &points[t[2]]))
        .collect();
    !signs.is_empty() && signs.iter().all(|s| *s == signs[0] && !s.is_eq())
}

/// A mesh scene, or `None` when snapping folded a triangle over (the shape
/// is then no longer a mesh).
pub(super) fn mesh_scene(rng: &mut Rng) -> Option<Scene> {
    let canvas = canvas(rng);
    let shape = match rng.below(4) {
        0 => fan(rng, canvas),
        1 => jittered_grid(rng),
        2 => convex_polygon(rng, canvas),
        _ => star_polygon(rng, canvas),
    };
    let bits = any_bits(rng);
    let at = |p: &[Number; 2]| p.each_ref().map(|c| placed(c, bits));
    let (points, placed_points, triangles) = match shape {
        Shape::Triangles(points, triangles) => {
            let placed_points: Vec<Point> = points.iter().map(at).collect();
            (points, placed_points, triangles)
        }
        Shape::Star { centre, points } => {
            let placed_points: Vec<Point> = points.iter().map(at).collect();
            let triangles = ear_clip_star(centre, &placed_points)?;
            (points, placed_points, triangles)
        }
    };
    if !winds_one_way(&placed_points, &triangles) {
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
        ..Rules::default()
    };
    let mut scene = scene_of(canvas, rules, primitives, &values);
    scene.expect.watertight = true;
    Some(scene)
}
