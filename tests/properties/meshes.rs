//! Watertight meshes: random fans, polygons and jittered grids, each
//! interior sample covered exactly once under every consistent rule.

use crate::strategies::{any_bits, coord, placed, production, scene_of, Exact2};
use proptest::prelude::*;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::scene::{
    Cull, FillRule, Interpolation, Number, Primitive, Rules, Scene, Triangle, Vertex,
};

// --- Watertight meshes -----------------------------------------------------

const MSIZE: u32 = 24;

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
pub fn denominator() -> impl Strategy<Value = i64> {
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
    let place = |p: &[Number; 2]| p.each_ref().map(|c| placed(c, bits));
    let (points, placed_points, triangles) = match shape {
        Shape::Triangles(points, triangles) => {
            let placed_points: Vec<Exact2> = points.iter().map(place).collect();
            (points, placed_points, triangles)
        }
        Shape::Star { centre, points } => {
            let placed_points: Vec<Exact2> = points.iter().map(place).collect();
            let triangles = rastercheck::explore::fuzz::ear_clip_star(centre, &placed_points)?;
            (points, placed_points, triangles)
        }
    };
    if !rastercheck::explore::fuzz::winds_one_way(&placed_points, &triangles) {
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
        ..Rules::default()
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
        let interior = reference::mesh_interior(&scene, &Plan::for_scene(&scene));
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
