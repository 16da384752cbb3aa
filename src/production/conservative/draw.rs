//! A conservative scene drawn (SPEC.md §19): every triangle placed in
//! fixed point as production places any, set up (`triangle.rs`), and each
//! pixel of its box tested. Overestimation draws every pixel whose square,
//! grown by the case's uncertainty, meets the triangle: the most the case
//! allows. Underestimation draws every pixel whose square, so grown, lies
//! inside it: the least the case requires. The fully-covered flag, where
//! asked for, is true where the grown square lies inside the triangle (a
//! flag it is sure of), and the last triangle to draw a pixel leaves its
//! flag there.
//!
//! Points and lines (SPEC.md §19.8) are their own shapes (`lines.rs`),
//! tested pixel by pixel the same way; a line of zero length after placing
//! is culled, or, with `degenerate_lines`, drawn as the point it is.
//!
//! Depth, where the scene has it, is the triangle's plane at the pixel's
//! centre (`depth.rs`, SPEC.md §19.9).
//!
//! Multisampled (SPEC.md §19.10), a drawn pixel covers every sample of it.
//!
//! What it does not do: motion, clip space, polygons, attributes, and the
//! depth of points and lines or of multisampled scenes under conservative
//! rasterization (the
//! scene says why, `Scene::conservative_unjudged`); coordinates that are
//! not snapped whose common denominator exceeds 2^24.
//!
//! Coordinates are placed as production places any (snapped, or exact in
//! fixed point); unsnapped ones that are not dyadic are held exactly in
//! units of a half of their common denominator's reciprocal instead.

use dashu_int::IBig;

use super::depth::DepthPlane;
use super::growth::Growth;
use super::lines::{Frac, LineShape};
use super::triangle::{Setup, Shape};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::scene_format::{format_for, place};
use crate::rasterizer::RasterError;
use crate::scene::{ConservativeMode, ConservativeSupport, LineRule, Number, Primitive, Scene};

/// The largest common denominator of unsnapped coordinates that are not
/// dyadic this path holds: coordinates below 2^15 px times twice it stay
/// below 2^41 units, edge functions below 2^85.
const MAX_DENOMINATOR: u64 = 1 << 24;

/// What production draws conservatively: both modes and the flag, each
/// under the case's own uncertainty and properties.
pub fn support() -> ConservativeSupport {
    ConservativeSupport {
        overestimate: true,
        underestimate: true,
        fully_covered: true,
        depth: true,
        ..ConservativeSupport::default()
    }
}

/// Production's frame of a conservative scene.
pub fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let Some(case) = scene.effects.conservative.as_ref() else {
        return Err(RasterError::Failed(
            "production's conservative path was given a scene that is not conservative".to_owned(),
        ));
    };
    if let Some(why) = scene.conservative_unjudged() {
        return Err(RasterError::Unsupported(why));
    }
    let placed = placed(scene)?;
    let half = Growth::half_side(&case.uncertainty, placed.one);
    let margin = Growth::margin(&case.uncertainty, placed.one);
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::for_plan(w, h, plan);
    let mut flags = case.fully_covered.then(|| vec![false; frame.pixel_count()]);
    // Multisampled (SPEC.md §19.10): a drawn pixel covers all its samples.
    let samples = frame.samples.max(1) as usize;
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let v = &placed.vertices[index];
        let mut mark = |x: i64, y: i64, full: bool, plane: Option<&DepthPlane>| {
            let i = frame.index(x as u32, y as u32);
            frame.hit_run(i, i + samples, index);
            if let (Some(depth), Some(plane)) = (frame.depth.as_mut(), plane) {
                // Depth is judged single-sampled only (SPEC.md §19.7).
                depth[i] = plane.at(x, y);
            }
            if let Some(flags) = &mut flags {
                flags[i / samples] = full;
            }
        };
        match primitive {
            Primitive::Triangle(_) => {
                let (setup, orientation) = Setup::new([v[0], v[1], v[2]], placed.one);
                if setup.shape != Shape::Area && !case.degenerate_triangles {
                    continue;
                }
                if scene.rules.cull.discards(orientation) {
                    continue;
                }
                let triangle = [v[0], v[1], v[2]];
                let plane = scene
                    .has_depth
                    .then(|| DepthPlane::new(scene, index, triangle, placed.one))
                    .flatten();
                for y in setup.range(1, h) {
                    for x in setup.range(0, w) {
                        let drawn = match case.mode {
                            ConservativeMode::Overestimate => setup.meets(x, y, &half, &margin),
                            ConservativeMode::Underestimate => setup.holds(x, y, &half),
                        };
                        if drawn {
                            mark(x, y, setup.holds(x, y, &half), plane.as_ref());
                        }
                    }
                }
            }
            Primitive::Line(_) | Primitive::Point(_) => {
                let Some(shape) = line_shape(primitive, v, placed.one, case.degenerate_lines)
                else {
                    continue;
                };
                let (num, den) = half.fraction();
                let bounds = shape.bounds();
                let range = |axis: usize, size: u32| {
                    let first = bounds[axis].div_euclid(placed.one) - 2;
                    let last = bounds[axis + 2].div_euclid(placed.one) + 2;
                    let clip = |v: i128| v.clamp(0, i128::from(size)) as i64;
                    clip(first)..clip(last)
                };
                let centre = |p: i64| i128::from(p) * placed.one + placed.one / 2;
                for y in range(1, h) {
                    for x in range(0, w) {
                        let c = [centre(x), centre(y)];
                        let full = shape.holds(c, num, den);
                        let drawn = match case.mode {
                            ConservativeMode::Overestimate => shape.meets(c, num, den),
                            ConservativeMode::Underestimate => full,
                        };
                        if drawn {
                            mark(x, y, full, None);
                        }
                    }
                }
            }
            Primitive::Polygon(_) => {
                return Err(RasterError::Unsupported(
                    "production draws no polygons under conservative rasterization".to_owned(),
                ))
            }
        }
    }
    frame.fully_covered = flags;
    if frame.resolved.is_some() {
        frame.resolved = Some(frame.box_resolve());
    }
    // With depth it gives depth (SPEC.md §19.9); attributes are refused.
    frame.coverage_only = !scene.has_depth;
    Ok(frame)
}

/// A scene's primitives in integer units of 1/`one` px.
struct PlacedScene {
    one: i128,
    /// Per primitive, its vertices.
    vertices: Vec<Vec<[i128; 2]>>,
}

/// A point's square or a line's shape in units (SPEC.md §19.8); `None`
/// for a line of zero length after placing when `degenerate_lines` is
/// false (culled). A degenerate line drawn is its point.
fn line_shape(
    primitive: &Primitive,
    v: &[[i128; 2]],
    one: i128,
    degenerate_lines: bool,
) -> Option<LineShape> {
    // n·one/2 as an exact fraction of units.
    let half = |n: &Number| Frac {
        n: n.numerator() * IBig::from(one),
        d: IBig::from(n.denominator().clone()) * IBig::from(2u8),
    };
    match primitive {
        Primitive::Point(p) => Some(LineShape::Square {
            c: v[0],
            h: half(&p.size),
        }),
        Primitive::Line(l) => {
            let (a, b) = (v[0], v[1]);
            if a == b {
                return degenerate_lines.then(|| LineShape::Square {
                    c: a,
                    h: half(&Number::ZERO),
                });
            }
            let h = half(&l.width);
            Some(if l.rule == LineRule::Rectangle {
                LineShape::Rectangle { a, b, h }
            } else {
                let k = usize::from((b[0] - a[0]).abs() < (b[1] - a[1]).abs());
                LineShape::Band { a, b, k, h }
            })
        }
        _ => None,
    }
}

/// Every triangle's vertices in integers: production's fixed point where
/// it holds them, else units of 1/(2D) px for D the coordinates' common
/// denominator.
fn placed(scene: &Scene) -> Result<PlacedScene, RasterError> {
    // Each primitive's vertices, each coordinate through `units`.
    let each = |units: &dyn Fn(&Number) -> i128| -> Vec<Vec<[i128; 2]>> {
        scene
            .primitives
            .iter()
            .map(|p| {
                p.vertices()
                    .iter()
                    .map(|v| [units(&v.x), units(&v.y)])
                    .collect()
            })
            .collect()
    };
    if let Ok(format) = format_for(scene, None) {
        return Ok(PlacedScene {
            one: 1 << format.frac_bits,
            vertices: each(&|n| i128::from(place(scene, format, n).0)),
        });
    }
    let mut d: u64 = 1;
    for n in scene.vertices().flat_map(|v| [&v.x, &v.y]) {
        let q = u64::try_from(n.denominator()).ok();
        d = q
            .and_then(|q| {
                let lcm = d / gcd(d, q) * q;
                (lcm <= MAX_DENOMINATOR).then_some(lcm)
            })
            .ok_or_else(|| {
                RasterError::Unsupported(format!(
                    "unsnapped coordinates whose common denominator exceeds 2^24 are not held by production's conservative path ({})",
                    n.to_exact_string()
                ))
            })?;
    }
    let one = 2 * i128::from(d);
    let units = |n: &Number| {
        let p = i128::try_from(n.numerator()).expect("coordinates are bounded by COORD_LIMIT");
        let q = i128::try_from(n.denominator()).expect("q divides d");
        p * (one / q)
    };
    Ok(PlacedScene {
        one,
        vertices: each(&units),
    })
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}
